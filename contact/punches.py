"""Rigid punch profiles: the paper's four (Zhou et al. 2014, eq. (2.6)) and any custom one.

A punch is described by what the integral equation and the contact search need: the slope
dv/dX of its face (Zhou et al. 2014, eqs. (4.5), (4.10): Lambda = dv/dX), its height where
known (the gap outside the contact), its extent (``extent``: the face ends at a sharp corner,
or goes on without bound), and where the slope or one of its derivatives jumps (``breaks``).
A contact end at an edge of the face is a corner: fixed, the pressure singular there.  Other
contact ends are free: the pressure vanishes there and the end is found from the load (and,
for two free ends, from the solvability condition of the index -1 equation, eq. (5.40)).

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

from sie.errors import SIEInputError

from .samples import MIN_SAMPLES, OutsideSamplesError, face_from_samples
from .errors import (ContactInputError, ProfileCallableError, PunchGeometryError, check_number,
                     real_array)

__all__ = ["Punch", "FlatPunch", "TriangularPunch", "ParabolicPunch", "CylindricalPunch",
           "ProfilePunch"]


def _positive(name: str, value) -> float:
    """A punch dimension: a number (:func:`contact.errors.check_number`), finite and > 0."""
    check_number(name, value, PunchGeometryError, "a positive finite number")
    try:
        v = float(value)
    except (TypeError, ValueError):         # e.g. an array of several numbers
        raise PunchGeometryError(f"{name} must be a positive finite number, got {value!r}") from None
    if not math.isfinite(v) or v <= 0.0:
        raise PunchGeometryError(f"{name} must be a positive finite number, got {v!r}")
    return v


def _called(fn, X, what):
    """fn(X) for the punch's ``what`` ("slope" | "height"); an exception of any kind raised
    inside it becomes a ProfileCallableError naming ``what`` and the X it was called at
    (chained), except the package's own errors (:class:`~contact.ContactInputError`, among
    them a sampled face's OutsideSamplesError, and :class:`sie.SIEInputError`), which say
    what went wrong themselves and pass through unchanged.  KeyboardInterrupt and SystemExit
    are not wrapped."""
    try:
        return fn(X)
    except (ContactInputError, SIEInputError):
        raise
    except Exception as exc:
        raise ProfileCallableError(
            f"the punch {what} raised {type(exc).__name__} when called at {_points(X)}: "
            f"{exc}") from exc


def _points(X) -> str:
    """Where a punch callable was called, for a message: X = x for one point, the range of
    X for several."""
    X = np.asarray(X, dtype=float).ravel()
    if X.size == 1:
        return f"X = {float(X[0])!r}"
    seen = X[np.isfinite(X)]                # scipy's derivative passes NaN for points done
    if seen.size == 0:
        return f"{X.size} points X, none finite"
    return (f"{X.size} points X in [{float(seen.min())!r}, {float(seen.max())!r}] (first "
            f"X = {float(X[0])!r})")


def _checked(fn, X, what):
    """fn(X) for the punch's ``what`` ("slope" | "height"), as a real array of X's shape with
    finite values, else ProfileCallableError naming what went wrong (:func:`_called`)."""
    X = np.asarray(X, dtype=float)
    out = np.asarray(_called(fn, X, what))
    # (the array methods, not numpy's functions: this runs on every call of the slope)
    if out.dtype.kind == "c":
        raise ProfileCallableError(f"the punch {what} must return real values, got complex")
    out = out.astype(float, copy=False)
    if out.shape != X.shape:
        raise ProfileCallableError(
            f"the punch {what} must be vectorised: called with an array of shape {X.shape} "
            f"it returned shape {out.shape}")
    if not np.isfinite(out).all():
        bad = float(X.ravel()[np.flatnonzero(~np.isfinite(out.ravel()))[0]])
        raise ProfileCallableError(f"the punch {what} returned a non-finite value at X = {bad!r}")
    return out


class Punch:
    """Base class of the rigid punches: what the contact solver needs of a face.

    Subclasses set ``corners`` (left, right: X of a sharp corner or None), ``breaks`` (tuple
    of X) and implement :meth:`_slope` (and :meth:`_height` where the height is known).
    :func:`contact.solve` accepts any instance; use :class:`ProfilePunch` for a face of
    your own rather than subclassing.

    Attributes
    ----------
    corners : (float or None, float or None)
        X of the sharp corner that ends the face on the left / right, or None.
    breaks : tuple of float
        X where the slope or one of its derivatives jumps.
    extent : (float, float)
        (X_min, X_max) of the face (-inf / +inf where it has no corner).
    ends : (str, str)
        "singular" (a corner: p unbounded there) or "bounded" at each end of a contact
        that reaches the corners.
    kappa : int
        The index of the equation for that contact: 1, 0 or -1.
    kind : str
        The registry name ("flat", "triangular", "parabolic", "cylindrical", "profile").
    has_height : bool
        Whether :meth:`height` is known.
    homogeneous, slope_degree, convex
        Properties of the slope that let the solver take short cuts (module docstring).

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eq. (2.6) (the four profiles) and eq. (4.10)
    (the slope is the right-hand side of the contact equation).

    Examples
    --------
    >>> import contact
    >>> p = contact.FlatPunch(1.0)
    >>> isinstance(p, contact.Punch), p.ends, p.kappa, p.extent
    (True, ('singular', 'singular'), 1, (-1.0, 1.0))
    >>> float(contact.CylindricalPunch(2.0).slope(1.0))           # X / R
    0.5
    """

    corners: tuple = (None, None)
    breaks: tuple = ()
    homogeneous: Optional[tuple] = None      # (x0, d): slope(x0 + lam xi) = lam^d slope(x0 + xi)
    slope_degree: Optional[int] = None       # the slope is a polynomial of this degree
    convex: bool = False                     # slope nondecreasing: the gap opens by itself
    kind: str = "profile"
    #: slope and height are the library's own elementwise formulas of a float array (the
    #: paper's four punches): they need no check of shape and finiteness on every call
    _own_formulas: bool = False

    def _slope(self, X):                      # pragma: no cover - abstract
        raise NotImplementedError

    def slope(self, X):
        """dv/dX of the punch face at X (vectorised), checked for shape and finiteness."""
        if self._own_formulas:
            return self._slope(np.asarray(X, dtype=float))
        return _checked(self._slope, X, "slope")

    def _height(self, X):
        """v(X), the height of the face, where known in closed form (see ``has_height``)."""
        raise NotImplementedError

    #: the slope is the height's derivative by finite differences (a face given by its height
    #: alone): the contact search explores the face through its height
    slope_from_height: bool = False

    @property
    def has_height(self) -> bool:
        """Whether the face's height is known (else the contact search integrates the slope)."""
        return type(self)._height is not Punch._height

    def height(self, X):
        """v(X) of the punch face (any additive constant; vectorised), checked for shape and
        finiteness; ProfileCallableError where the height is not known (``has_height``)."""
        if not self.has_height:
            raise ProfileCallableError(
                f"the height of this {type(self).__name__} is not known: give height= "
                "(the slope is integrated where a height difference is needed)")
        if self._own_formulas:
            return self._height(np.asarray(X, dtype=float))
        return _checked(self._height, X, "height")

    @property
    def extent(self) -> tuple:
        """(X_min, X_max) of the face: its sharp corners, -inf/+inf where it has none."""
        left, right = self.corners
        return (-math.inf if left is None else float(left),
                math.inf if right is None else float(right))

    def as_face(self):
        """The face as the multi-zone contact search sees it (:class:`contact.face.Face`),
        made once per punch (what it finds of itself, its valleys, is kept with it)."""
        face = getattr(self, "_face", None)
        if face is None:
            from .face import Face
            face = self._face = Face(self.slope, extent=self.extent, breaks=self.breaks,
                                     height=self.height if self.has_height else None,
                                     convex=self.convex, homogeneous=self.homogeneous,
                                     slope_from_height=self.slope_from_height)
        return face

    @property
    def ends(self) -> tuple:
        """("singular" | "bounded") at the left and right contact ends."""
        return tuple("singular" if c is not None else "bounded" for c in self.corners)

    @property
    def kappa(self) -> int:
        return {("singular", "singular"): 1, ("bounded", "bounded"): -1}.get(self.ends, 0)


class FlatPunch(Punch):
    """Flat-ended punch of half-width a: contact [-a, a], sharp corners at both ends
    (index 1; Zhou et al. 2014, Sec. 5.1).

    Parameters
    ----------
    half_width : float
        a > 0.

    Attributes
    ----------
    half_width : float
    corners : (float, float)
        (-a, a).

    Raises
    ------
    PunchGeometryError
        a not finite or not positive.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), Sec. 5.1, eqs. (5.1)-(5.13).  Without friction
    the classical rigid flat punch: p = P / (pi sqrt(a^2 - X^2)) (Sadowsky 1928; Johnson,
    Contact Mechanics (1985), ch. 2), SIFs P / (pi sqrt(a)) (eq. (5.13)).

    Examples
    --------
    >>> import math, contact
    >>> r = contact.solve(contact.Isotropic(1.0, 0.3), contact.FlatPunch(1.0), load=1.0,
    ...                   speed=0.0)
    >>> r.ends, r.zones[0].kinds
    ((-1.0, 1.0), ('corner', 'corner'))
    >>> round(float(r.pressure(0.6)) * math.pi * 0.8, 12)     # p = P / (pi sqrt(a^2 - X^2))
    1.0
    >>> round(r.sif["right"] * math.pi, 12)                   # K = P / (pi sqrt(a))
    1.0
    """
    kind = "flat"
    convex = True
    slope_degree = 0

    _own_formulas = True
    def __init__(self, half_width):
        self.half_width = _positive("half_width", half_width)
        self.corners = (-self.half_width, self.half_width)

    @property
    def dimension(self) -> float:
        """The one dimension of the closed form (Zhou et al. 2014, Sec. 5.1): a."""
        return self.half_width

    def _slope(self, X):
        return np.zeros_like(X)

    def _height(self, X):
        return np.zeros_like(np.asarray(X, dtype=float))

    def __repr__(self):
        return f"FlatPunch(half_width={self.half_width!r})"


class TriangularPunch(Punch):
    """Wedge face v = -v0 + m0 X, sharp corner at X = 0, contact [0, b] (index 0;
    Zhou et al. 2014, Sec. 5.2).  ``slope`` is m0 > 0.

    Parameters
    ----------
    slope : float
        m0 > 0.

    Attributes
    ----------
    m0 : float
    corners : (0.0, None)

    Raises
    ------
    PunchGeometryError
        m0 not finite or not positive.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), Sec. 5.2, eqs. (5.14)-(5.23); the contact
    length b = -N11 P / (m0 pi alpha), eq. (5.22).

    Examples
    --------
    Without friction alpha = 1/2, so b = -2 N11 P / (pi m0):

    >>> import math, contact
    >>> m = contact.Isotropic(1.0, 0.3)
    >>> r = contact.solve(m, contact.TriangularPunch(0.1), load=0.01, speed=0.0)
    >>> N11 = contact.surface_constants(m, 0.0).N11
    >>> r.ends[0], round(r.ends[1] / (-2 * N11 * 0.01 / (math.pi * 0.1)), 12)
    (0.0, 1.0)
    """
    kind = "triangular"
    convex = True
    slope_degree = 0
    corners = (0.0, None)
    homogeneous = (0.0, 0)

    _own_formulas = True
    def __init__(self, slope):
        self.m0 = _positive("slope", slope)

    @property
    def dimension(self) -> float:
        """The one dimension of the closed form (Zhou et al. 2014, Sec. 5.2): m0."""
        return self.m0

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

    _own_formulas = True
    def __init__(self, radius):
        self.radius = _positive("radius", radius)

    @property
    def dimension(self) -> float:
        """The one dimension of the closed form (Zhou et al. 2014, Secs. 5.3-5.4): R."""
        return self.radius

    def _slope(self, X):
        return X / self.radius

    def _height(self, X):
        X = np.asarray(X, dtype=float)
        return X * X / (2.0 * self.radius)

    def __repr__(self):
        return f"{type(self).__name__}(radius={self.radius!r})"


class ParabolicPunch(_ParabolicFace):
    """Face v = -v0 + X^2/(2R) on [0, b], sharp corner at X = 0 (index 0;
    Zhou et al. 2014, Sec. 5.3).

    Parameters
    ----------
    radius : float
        R > 0.

    Attributes
    ----------
    radius : float
    corners : (0.0, None)

    Raises
    ------
    PunchGeometryError
        R not finite or not positive.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), Sec. 5.3, eqs. (5.24)-(5.34); the contact
    length b^2 = -2 N11 P R / (pi alpha (1 + alpha)), eq. (5.32).

    Examples
    --------
    Without friction alpha = 1/2, so b^2 = -8 N11 P R / (3 pi):

    >>> import math, contact
    >>> m = contact.Isotropic(1.0, 0.3)
    >>> r = contact.solve(m, contact.ParabolicPunch(1.0), load=0.01, speed=0.0)
    >>> N11 = contact.surface_constants(m, 0.0).N11
    >>> r.ends[0], round(r.ends[1] / math.sqrt(-8 * N11 * 0.01 / (3 * math.pi)), 12)
    (0.0, 1.0)
    """
    kind = "parabolic"
    corners = (0.0, None)


class CylindricalPunch(_ParabolicFace):
    """Face v = -v0 + X^2/(2R) (a + b << R), both contact ends free (index -1;
    Zhou et al. 2014, Sec. 5.4).

    Parameters
    ----------
    radius : float
        R > 0.

    Attributes
    ----------
    radius : float
    corners : (None, None)

    Raises
    ------
    PunchGeometryError
        R not finite or not positive.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), Sec. 5.4, eqs. (5.35)-(5.47).  Without friction
    the Hertz line contact: half-width a^2 = -2 N11 P R / pi = 4 P R / (pi E*),
    E* = E / (1 - nu^2) (Johnson, Contact Mechanics (1985), ch. 4).

    Examples
    --------
    >>> import math, contact
    >>> E, nu, P, R = 1.0, 0.3, 0.01, 1.0
    >>> r = contact.solve(contact.Isotropic(E, nu), contact.CylindricalPunch(R), load=P,
    ...                   speed=0.0)
    >>> a = math.sqrt(4 * P * R / (math.pi * E / (1 - nu**2)))       # Hertz
    >>> round(r.ends[0] / a, 12), round(r.ends[1] / a, 12)
    (-1.0, 1.0)
    """
    kind = "cylindrical"
    corners = (None, None)


class ProfilePunch(Punch):
    """Any punch face, given by its slope dv/dX, its height v(X), or both.

    Parameters
    ----------
    slope : callable, optional
        Vectorised dv/dX(X): the right-hand side of the contact equation (Zhou et al. 2014,
        eq. (4.10)).
    breaks : sequence of float
        X where the slope or one of its derivatives jumps (rounded corners, joins): the
        solver splits its quadratures there (spectral instead of algebraic convergence).
        Breaks outside the face are dropped.
    corners : (left, right)
        X of a sharp corner that ends the face on that side, or None.  The same as giving
        that side of ``face``; when both are given they must agree.
    height : callable, optional
        Vectorised v(X) (any additive constant): the gap between zones and outside them is
        read from it instead of integrating the slope.  Given alone, the slope is its
        derivative by adaptive finite differences (:func:`scipy.differentiate.derivative`,
        order 8, one-sided next to breaks and edges; measured on sin(3X) e^X / 10 + X^2:
        within 1e-12 of the slope's scale centred and 6e-12 one-sided), at tens of height
        calls per slope point; pass ``slope`` as well for the full accuracy and speed.
    face : (X_min, X_max), optional
        The extent of the face (either side may be infinite).  Contact cannot go beyond it:
        a contact end that reaches an edge becomes a sharp corner there (singular pressure).
        Without it (and without corners) the face is unbounded, and its height must rise
        without bound on both sides (else :class:`PunchGeometryError` asks for ``face``).

    Attributes
    ----------
    extent : (float, float)
        (X_min, X_max) of the face.
    corners : (float or None, float or None)
        The finite edges of the face (sharp corners), None on an unbounded side.
    breaks : tuple of float
        The breaks inside the face, ascending.
    samples : object
        Only for :meth:`from_samples`: the spline through the samples.

    Raises
    ------
    ProfileCallableError
        ``slope`` / ``height`` not callable (or, when evaluated, not vectorised, not real or
        not finite).
    PunchGeometryError
        Neither ``slope`` nor ``height``; ``face`` not an increasing pair; a corner outside
        the face ("the face is narrower than the corner") or inside it; breaks not finite.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eq. (4.10) (the slope is the right-hand side
    of the contact equation); contact of several zones: see the documentation, Theory: the
    contact model and its conventions.

    Examples
    --------
    A W-shaped face touches first at its two lowest points, X = -1 and 1:

    >>> import numpy as np, contact
    >>> w = contact.ProfilePunch(lambda X: 0.2 * X**3 - 0.2 * X, face=(-2.0, 2.0))
    >>> w.extent, w.corners
    ((-2.0, 2.0), (-2.0, 2.0))
    >>> r = contact.solve(contact.zhou2014(), w, load=1e-3, speed=0.0)
    >>> [tuple(round(x, 2) for x in z.ends) for z in r.zones]
    [(-1.01, -0.99), (0.99, 1.01)]

    A face given by its height alone (the slope by finite differences):

    >>> cyl = contact.ProfilePunch(height=lambda X: X**2 / 2.0)          # R = 1
    >>> a = contact.solve(contact.Isotropic(1.0, 0.3), cyl, load=0.01, speed=0.0).half_width
    >>> round(a / (4 * 0.01 / (np.pi / (1 - 0.3**2)))**0.5, 8)          # Hertz
    1.0
    """
    kind = "profile"
    #: The fewest samples :meth:`from_samples` takes.
    MIN_SAMPLES = MIN_SAMPLES

    def __init__(self, slope: Optional[Callable] = None, breaks=(), corners=(None, None), *,
                 height: Optional[Callable] = None, face=None):
        if slope is None and height is None:
            raise PunchGeometryError(
                "a profile punch needs its slope dv/dX (slope=) or its height v(X) (height=), "
                "or both")
        for name, fn in (("slope", slope), ("height", height)):
            if fn is not None and not callable(fn):
                what = "dv/dX(X)" if name == "slope" else "v(X)"
                raise ProfileCallableError(
                    f"{name} must be a vectorised callable {what}, got {type(fn).__name__}")
        self._fn = slope
        self._h = height
        cs = _corners(corners)
        lo, hi = _face(face)
        for side, c, edge in (("left", cs[0], lo), ("right", cs[1], hi)):
            if c is None or face is None:
                continue
            if not lo <= c <= hi:
                raise PunchGeometryError(
                    f"the face ({lo:g}, {hi:g}) is narrower than the {side} corner at X = {c:g}: "
                    "a corner is an edge of the face, give it inside or at the face's extent")
            if c != edge:
                raise PunchGeometryError(
                    f"the {side} corner at X = {c:g} lies inside the face ({lo:g}, {hi:g}): a "
                    f"sharp corner is where the face ends; give face=({c if side == 'left' else lo:g}, "
                    f"{hi if side == 'left' else c:g}), or put a kink in breaks=")
        if face is None:
            lo = -math.inf if cs[0] is None else cs[0]
            hi = math.inf if cs[1] is None else cs[1]
        self._extent = (lo, hi)
        self.corners = tuple(x if math.isfinite(x) else None for x in self._extent)
        br = _breaks(breaks)
        if not all(math.isfinite(b) for b in br):
            raise PunchGeometryError(f"breaks must be finite, got {br}")
        self.breaks = tuple(b for b in br if lo < b < hi)
        self.homogeneous = None

    @classmethod
    def from_samples(cls, X, h, *, kind="quintic", breaks="auto", face=None, outside="raise"):
        """A measured face through samples (X_i, h_i) (:func:`contact.samples.face_from_samples`:
        the not-a-knot quintic spline by default, its slope C^3).

        ``face`` defaults to the samples' extent (X_0, X_{N-1}); a wider face needs
        ``outside="tangent"`` (the height continued by its end tangents).  The spline is
        kept as ``punch.samples``.

        Raises
        ------
        contact.SampleError
            Fewer than :attr:`MIN_SAMPLES` samples, NaN / inf, X unsorted or repeated,
            lengths that differ.
        contact.OutsideSamplesError
            ``face`` reaches beyond the samples with ``outside="raise"``.
        """
        sf = face_from_samples(X, h, kind=kind, breaks=breaks, outside=outside)
        ext = sf.extent if face is None else _face(face)
        if outside == "raise" and (ext[0] < sf.extent[0] or ext[1] > sf.extent[1]):
            raise OutsideSamplesError(
                f"face {ext} reaches beyond the samples, which cover [{sf.extent[0]:g}, "
                f"{sf.extent[1]:g}]: give a face inside them, or outside='tangent' to continue "
                "the height by its end tangents")
        punch = cls(sf.slope, breaks=sf.breaks, height=sf.height, face=ext)
        punch.samples = sf
        return punch

    @property
    def extent(self) -> tuple:
        return self._extent

    @property
    def has_height(self) -> bool:
        return self._h is not None

    @property
    def slope_from_height(self) -> bool:
        return self._fn is None

    def _height(self, X):
        return self._h(X)

    def _slope(self, X):
        if self._fn is not None:
            return self._fn(X)
        return self._slope_from_height(X)

    def _slope_from_height(self, X):
        """dv/dX by adaptive finite differences of the height (order 8): centred where the
        stencil fits between the neighbouring breaks / edges, else one-sided toward the
        larger room (scipy.differentiate.derivative picks the step by its error estimate)."""
        from scipy.differentiate import derivative
        X = np.asarray(X, dtype=float)
        if X.size == 0:
            return np.zeros_like(X)
        lo, hi = self._extent
        walls = np.array([lo, *self.breaks, hi])
        finite = walls[np.isfinite(walls)]
        # the face's own length (not the user's unit): its edges' and breaks' span, else
        # what the scan of its height finds (contact.face.Face.scale)
        scale = (finite[-1] - finite[0]) if finite.size >= 2 else self.as_face().scale
        s0 = 0.0625 * max(scale, np.finfo(float).tiny)
        kl = np.searchsorted(walls, X, side="left") - 1         # the last wall below X
        kr = np.searchsorted(walls, X, side="right")            # the first wall above X
        left = np.where(kl >= 0, X - walls[np.clip(kl, 0, None)], np.inf)
        right = np.where(kr < walls.size, walls[np.clip(kr, None, walls.size - 1)] - X, np.inf)
        room_c = np.minimum(left, right)
        # centred (rounding ~ eps |v| / step) while the step need not shrink below s0 / 16;
        # one-sided (truncation of a 9-point stencil) only closer to a wall than that
        central = room_c >= 4.5 * s0 / 16
        direction = np.where(central, 0, np.where(right >= left, 1, -1))
        room = np.where(central, room_c / 4.5, np.maximum(left, right) / 9.0)
        step = np.minimum(s0, room)
        # the raw height (scipy passes NaN for elements it has finished with), an error
        # inside it named as the height's (_called)
        res = derivative(lambda x: np.asarray(_called(self._h, x, "height"), dtype=float), X,
                         initial_step=step,
                         step_direction=direction, order=8, maxiter=6,
                         tolerances=dict(atol=0.0, rtol=1e-14))
        df = np.asarray(res.df, dtype=float).reshape(X.shape)
        if not np.all(np.isfinite(df)):
            bad = float(X.ravel()[np.flatnonzero(~np.isfinite(df.ravel()))[0]])
            raise ProfileCallableError(
                f"the slope from the punch height is not finite at X = {bad!r} (the height "
                "returned a non-finite value next to it)")
        return df

    def __repr__(self):
        parts = []
        if self._fn is not None:
            parts.append(f"slope={self._fn!r}")
        if self._h is not None:
            parts.append(f"height={self._h!r}")
        parts.append(f"breaks={self.breaks}")
        parts.append(f"face={self._extent}")
        return f"ProfilePunch({', '.join(parts)})"


def _breaks(breaks) -> tuple:
    """The break points as ascending floats; PunchGeometryError unless a flat sequence of
    numbers (:func:`contact.errors.real_array`: text and bools are not numbers)."""
    allowed = "a sequence of finite X values"
    try:
        if isinstance(breaks, (str, bytes)):
            raise TypeError
        items = breaks if isinstance(breaks, np.ndarray) else list(breaks)
    except TypeError:
        raise PunchGeometryError(f"breaks must be {allowed}, got {breaks!r}") from None
    br = real_array("breaks", items, PunchGeometryError, allowed)
    if br.ndim != 1:
        raise PunchGeometryError(f"breaks must be {allowed}, got {breaks!r}")
    return tuple(sorted(br.tolist()))


def _corners(corners):
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
        check_number(f"corners[{name}]", c, PunchGeometryError, "a finite X or None")
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
    return tuple(cs)


def _face(face):
    """(X_min, X_max) as floats (either may be infinite), or (-inf, inf) for None."""
    if face is None:
        return (-math.inf, math.inf)
    try:
        if isinstance(face, (str, bytes)):
            raise TypeError
        lo, hi = face
    except (TypeError, ValueError):
        raise PunchGeometryError(
            f"face must be a pair (X_min, X_max) of numbers (either may be infinite), got "
            f"{face!r}") from None
    for side, v in (("X_min", lo), ("X_max", hi)):
        check_number(f"face {side}", v, PunchGeometryError,
                     "a number (either side of the face may be infinite)")
    lo, hi = float(lo), float(hi)
    if math.isnan(lo) or math.isnan(hi):
        raise PunchGeometryError(f"face must not contain NaN, got {face!r}")
    if not lo < hi:
        raise PunchGeometryError(
            f"face must satisfy X_min < X_max (a face of positive width), got {face!r}")
    return (lo, hi)
