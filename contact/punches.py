"""Rigid punch profiles: the paper's four (Zhou et al. 2014, eq. (2.6)) and any custom one.

A punch is described by what the integral equation needs: the slope dv/dX of its face
(Zhou et al. 2014, eqs. (4.5), (4.10): Lambda = dv/dX), where its sharp corners are (a corner
fixes that contact end and makes the pressure singular there), and where the slope or one of
its derivatives jumps (``breaks``).  Contact ends without a corner are free: the pressure
vanishes there and the end is found from the load (and, for two free ends, from the
solvability condition of the index -1 equation, eq. (5.40)).

``slope_degree`` says the slope is a polynomial of that degree: then the right-hand side of
the equation is one too, its Jacobi projection is exact with a few terms, and the solver
uses a small fixed n instead of doubling n until two solutions agree.

``convex`` (a nondecreasing slope) means the gap outside a contact with p >= 0 opens by
itself, so the solver skips its numerical gap check.

``homogeneous`` records an exact scaling law when the slope has one,
slope(x0 + lam xi) = lam^d slope(x0 + xi): the solver then finds the contact size with one
solve instead of a root search (the load scales like size^(d+1)).  It is a statement about the
profile, not a closed-form solution.
"""
from __future__ import annotations

import math
from typing import Callable, Optional

import numpy as np

from .errors import ProfileCallableError, PunchGeometryError

__all__ = ["Punch", "FlatPunch", "TriangularPunch", "ParabolicPunch", "CylindricalPunch",
           "ProfilePunch"]


def _positive(name: str, value) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise PunchGeometryError(f"{name} must be a positive finite number, got {value!r}") from None
    if not math.isfinite(v) or v <= 0.0:
        raise PunchGeometryError(f"{name} must be a positive finite number, got {v!r}")
    return v


class Punch:
    """Base class.  Subclasses set ``corners`` (left, right: X of a sharp corner or None),
    ``breaks`` (tuple of X) and implement :meth:`_slope`."""

    corners: tuple = (None, None)
    breaks: tuple = ()
    homogeneous: Optional[tuple] = None      # (x0, d): slope(x0 + lam xi) = lam^d slope(x0 + xi)
    slope_degree: Optional[int] = None       # the slope is a polynomial of this degree
    convex: bool = False                     # slope nondecreasing: the gap opens by itself
    kind: str = "profile"

    def _slope(self, X):                      # pragma: no cover - abstract
        raise NotImplementedError

    def slope(self, X):
        """dv/dX of the punch face at X (vectorised), checked for shape and finiteness."""
        X = np.asarray(X, dtype=float)
        try:
            out = self._slope(X)
        except (TypeError, ValueError, ArithmeticError) as exc:
            raise ProfileCallableError(
                f"the punch slope raised {type(exc).__name__}: {exc}") from exc
        out = np.asarray(out)
        if np.iscomplexobj(out):
            raise ProfileCallableError("the punch slope must return real values, got complex")
        out = np.asarray(out, dtype=float)
        if out.shape != X.shape:
            raise ProfileCallableError(
                f"the punch slope must be vectorised: called with an array of shape {X.shape} "
                f"it returned shape {out.shape}")
        if not np.all(np.isfinite(out)):
            bad = float(X.ravel()[np.flatnonzero(~np.isfinite(out.ravel()))[0]])
            raise ProfileCallableError(f"the punch slope returned a non-finite value at X = {bad!r}")
        return out

    def _height(self, X):
        """H(X), the height of the face (None: not known in closed form; the contact search
        integrates the slope)."""
        return None

    @property
    def extent(self) -> tuple:
        """(X_min, X_max) of the face: its sharp corners, -inf/+inf where it has none."""
        left, right = self.corners
        return (-math.inf if left is None else float(left),
                math.inf if right is None else float(right))

    def as_face(self):
        """The face as the multi-zone contact search sees it (:class:`contact.face.Face`)."""
        from .face import Face
        has_height = type(self)._height is not Punch._height
        return Face(self.slope, extent=self.extent, breaks=self.breaks,
                    height=self._height if has_height else None, convex=self.convex)

    @property
    def ends(self) -> tuple:
        """("singular" | "bounded") at the left and right contact ends."""
        return tuple("singular" if c is not None else "bounded" for c in self.corners)

    @property
    def kappa(self) -> int:
        return {("singular", "singular"): 1, ("bounded", "bounded"): -1}.get(self.ends, 0)


class FlatPunch(Punch):
    """Flat-ended punch of half-width a: contact [-a, a], sharp corners at both ends
    (index 1; Zhou et al. 2014, Sec. 5.1)."""
    kind = "flat"
    convex = True
    slope_degree = 0

    def __init__(self, half_width):
        self.half_width = _positive("half_width", half_width)
        self.corners = (-self.half_width, self.half_width)

    def _slope(self, X):
        return np.zeros_like(X)

    def _height(self, X):
        return np.zeros_like(np.asarray(X, dtype=float))

    def __repr__(self):
        return f"FlatPunch(half_width={self.half_width!r})"


class TriangularPunch(Punch):
    """Wedge face v = -v0 + m0 X, sharp corner at X = 0, contact [0, b] (index 0;
    Zhou et al. 2014, Sec. 5.2).  ``slope`` is m0 > 0."""
    kind = "triangular"
    convex = True
    slope_degree = 0
    corners = (0.0, None)
    homogeneous = (0.0, 0)

    def __init__(self, slope):
        self.m0 = _positive("slope", slope)

    def _slope(self, X):
        return np.full_like(X, self.m0)

    def _height(self, X):
        return self.m0 * np.asarray(X, dtype=float)

    def __repr__(self):
        return f"TriangularPunch(slope={self.m0!r})"


class _ParabolicFace(Punch):
    """Face v = -v0 + X^2/(2R): slope X/R, convex, homogeneous of degree 1 about X = 0."""
    convex = True
    slope_degree = 1
    homogeneous = (0.0, 1)

    def __init__(self, radius):
        self.radius = _positive("radius", radius)

    def _slope(self, X):
        return X / self.radius

    def _height(self, X):
        X = np.asarray(X, dtype=float)
        return X * X / (2.0 * self.radius)

    def __repr__(self):
        return f"{type(self).__name__}(radius={self.radius!r})"


class ParabolicPunch(_ParabolicFace):
    """Face v = -v0 + X^2/(2R) on [0, b], sharp corner at X = 0 (index 0;
    Zhou et al. 2014, Sec. 5.3)."""
    kind = "parabolic"
    corners = (0.0, None)


class CylindricalPunch(_ParabolicFace):
    """Face v = -v0 + X^2/(2R) (a + b << R), both contact ends free (index -1;
    Zhou et al. 2014, Sec. 5.4)."""
    kind = "cylindrical"
    corners = (None, None)


class ProfilePunch(Punch):
    """Any punch face, given by its slope dv/dX.

    Parameters
    ----------
    slope : callable
        Vectorised dv/dX(X).
    breaks : sequence of float
        X where the slope or one of its derivatives jumps (rounded corners, joins): the
        solver splits its quadratures there (spectral instead of algebraic convergence).
    corners : (left, right)
        X of a sharp corner that bounds the contact on that side (pressure singular there),
        or None for a free end (pressure vanishes, end found from the load).  Both None by
        default (index -1); one corner gives index 0, two corners index 1.
    """
    kind = "profile"

    def __init__(self, slope: Callable, breaks=(), corners=(None, None)):
        if not callable(slope):
            raise ProfileCallableError(
                f"slope must be a vectorised callable dv/dX(X), got {type(slope).__name__}")
        self._fn = slope
        try:
            br = tuple(sorted(float(b) for b in breaks))
        except (TypeError, ValueError):
            raise PunchGeometryError(f"breaks must be a sequence of finite X values, got {breaks!r}") from None
        if not all(math.isfinite(b) for b in br):
            raise PunchGeometryError(f"breaks must be finite, got {br}")
        try:
            left, right = corners
        except (TypeError, ValueError):
            raise PunchGeometryError(
                f"corners must be a pair (left, right) of X values or None, got {corners!r}") from None
        cs = []
        for name, c in (("left", left), ("right", right)):
            if c is None:
                cs.append(None)
                continue
            try:
                c = float(c)
            except (TypeError, ValueError):
                raise PunchGeometryError(f"corners[{name}] must be a finite X or None, got {c!r}") from None
            if not math.isfinite(c):
                raise PunchGeometryError(f"corners[{name}] must be a finite X or None, got {c!r}")
            cs.append(c)
        if cs[0] is not None and cs[1] is not None and not cs[0] < cs[1]:
            raise PunchGeometryError(
                f"corners must satisfy left < right, got left = {cs[0]}, right = {cs[1]}")
        self.breaks = br
        self.corners = tuple(cs)
        self.homogeneous = None

    def _slope(self, X):
        return self._fn(X)

    def __repr__(self):
        return f"ProfilePunch(slope={self._fn!r}, breaks={self.breaks}, corners={self.corners})"
