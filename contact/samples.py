"""A punch face from measured samples (X_i, h_i), i = 0..N-1: H, H' and breaks for the solver.

    face = face_from_samples(X, h, outside="tangent")
    res = contact.solve(material, contact.ProfilePunch(face.slope, breaks=face.breaks),
                        load=P, speed=c, friction=mu)

Interpolant
-----------
``kind="quintic"`` (default): the not-a-knot interpolating spline of degree 5
(:func:`scipy.interpolate.make_interp_spline`, k = 5; interior knots X[3:-3]).  The
equation's right-hand side is the slope H', and the Gauss-Jacobi solve converges spectrally
only where H' is smooth: H' of a quintic spline is a quartic on each knot interval and C^3
across knots (only its 4th derivative jumps), so even where the knots are *not* passed as
breaks the Jacobi coefficients of H' fall like k^-5, and the jumps themselves are O(h) (h the
spacing), the size of the interpolation error, not of H'.  Accuracy for smooth H (measured,
H = 1 - cos X on [-1, 1], N = 10 .. 160): H to O(h^6), H' to O(h^5) (observed orders 6.0-6.3
and 5.0-5.3); a parabola (the cylinder) is reproduced exactly up to rounding.

``kind="cubic"``: the not-a-knot cubic spline (H to O(h^4), H' to O(h^3)).  Its slope is only
C^1 (H''' jumps by O(h)): once a knot lies inside the contact and no breaks are passed,
contact.solve's adaptive n reaches its cap (n = 3072) and warns, for every N measured
(6 .. 1000), although the ends are those of the solve with breaks; prefer quintic unless the
data cannot bear a degree-5 fit.  Not offered: pchip / Akima (H only C^1, so H' has kinks at
every sample: first-order convergence in n without breaks, and third order at best in H).

Fewer samples than degree + 1 (N = 4, 5 for quintic) give the interpolating polynomial of
degree N - 1 (no knots).

Breaks policy (``breaks="auto"``)
---------------------------------
``face.knots`` always holds every interior knot (where a derivative of H' jumps);
``face.breaks`` is what to pass to the solver: all knots when there are at most
``MAX_AUTO_BREAKS`` = 8 of them (quintic: N <= 14; cubic: N <= 12), otherwise none.
``breaks="all"`` / ``"none"`` force either.  Why:

* Every break splits the solver's projection rule (n - kappa + 24 nodes per piece,
  ``sie.unknowns._EXTRA_PER_PIECE``) and adds a pointwise correction to the solution, and a
  contact search solves many trial contacts: with about 150 knots inside the contact
  (N = 1000 samples of a cylinder on [-2, 2], P = 0.01) one contact solve with all knots as
  breaks costs some hundred times the solve without (``make bench``).
* The ends do not change: without breaks they agree with the all-breaks solve to 1e-13 and
  with the exact face to the interpolation error (3.1e-6 / 1.7e-8 / 2.2e-10 / 3.8e-12 at
  N = 10 / 20 / 40 / 80 for H = 1 - cos X), because the unresolved jumps are of the size of
  that error.
* The one cost of "none": with few, widely spaced knots inside a wide contact the O(h) jumps
  are large and the adaptive n grows (n = 384 for 10 samples on [-2, 2] at P = 2.5, against
  24 with the 4 knots as breaks); 8 breaks are cheap, which is why the coarsest tables get
  them.

Outside the samples
-------------------
``outside="raise"`` (default): :meth:`SampledFace.height` / :meth:`SampledFace.slope` raise
:class:`OutsideSamplesError` at an X outside ``extent`` (beyond a rounding slack of
64 eps * max(|X_0|, |X_{N-1}|, X_{N-1} - X_0), which is clamped).  Give the face its extent
(``ProfilePunch(face.slope, breaks=face.breaks, corners=face.extent)``): the contact search
then stays on the measured face, and a contact that reaches an end of it turns that end into
a corner.  ``outside="tangent"`` continues H by its end tangents (H' constant beyond the
ends), for a face that is known to go on.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import ContactInputError, PunchGeometryError

__all__ = ["SampledFace", "face_from_samples", "SampleError", "OutsideSamplesError",
           "MAX_AUTO_BREAKS", "MIN_SAMPLES"]

MIN_SAMPLES = 4
MAX_AUTO_BREAKS = 8          # breaks="auto": all knots up to this many, none above
_DEGREE = {"quintic": 5, "cubic": 3}
_BREAKS = ("auto", "all", "none")
_OUTSIDE = ("raise", "tangent")
_SLACK = 64 * np.finfo(float).eps


class SampleError(PunchGeometryError):
    """The samples (X_i, h_i) cannot define a face: too few, not finite, X not strictly
    increasing, lengths differ, not 1-D.

    Raised by :meth:`contact.ProfilePunch.from_samples`.

    Examples
    --------
    >>> import contact
    >>> contact.ProfilePunch.from_samples([0.0, 1.0, 2.0], [0.0, 1.0, 4.0])
    Traceback (most recent call last):
        ...
    contact.samples.SampleError: at least 4 samples are needed to define a face, got 3
    """


class OutsideSamplesError(PunchGeometryError):
    """A sampled face (``outside="raise"``) asked for, or evaluated, outside its samples.

    Raised by :meth:`contact.ProfilePunch.from_samples` for a ``face`` wider than the
    samples, and by the face's slope and height beyond them.

    Examples
    --------
    >>> import numpy as np, contact
    >>> X = np.linspace(-1.0, 1.0, 9)
    >>> contact.ProfilePunch.from_samples(X, X ** 2, face=(-2.0, 1.0))
    Traceback (most recent call last):
        ...
    contact.samples.OutsideSamplesError: face (-2.0, 1.0) reaches beyond the samples, ...
    """


@dataclass(frozen=True, eq=False, repr=False)
class SampledFace:
    """A punch face interpolated from samples; see :func:`face_from_samples`.

    Attributes
    ----------
    extent : (float, float)
        (X_0, X_{N-1}): the face ends at its first and last sample.
    breaks : tuple of float
        Knots to pass as ``ProfilePunch(..., breaks=)`` (the policy of ``breaks=``).
    knots : tuple of float
        Every interior knot of the spline: where the 4th (quintic) / 2nd (cubic) derivative
        of the slope jumps.
    degree : int
        Spline degree (5, 3, or N - 1 for N <= degree).
    kind, outside : str
    X, h : ndarray
        The samples (read-only copies).
    """
    extent: tuple
    breaks: tuple
    knots: tuple
    degree: int
    kind: str
    outside: str
    X: np.ndarray
    h: np.ndarray
    _H: object
    _dH: object
    _ends: tuple      # (H(X_0), H(X_N-1), H'(X_0), H'(X_N-1))

    def __repr__(self):
        return (f"SampledFace(extent={self.extent}, samples={self.X.size}, kind={self.kind!r}, "
                f"degree={self.degree}, knots={len(self.knots)}, breaks={len(self.breaks)}, "
                f"outside={self.outside!r})")

    def height(self, X):
        """H(X), vectorised (same shape as X)."""
        return self._eval(X, self._H, "height")

    def slope(self, X):
        """H'(X) = dH/dX, vectorised (same shape as X)."""
        return self._eval(X, self._dH, "slope")

    def _eval(self, X, spline, what):
        X = np.asarray(X, dtype=float)
        lo, hi = self.extent
        slack = _SLACK * max(abs(lo), abs(hi), hi - lo)
        below, above = X < lo, X > hi
        if self.outside == "raise":
            bad = (X < lo - slack) | (X > hi + slack) | np.isnan(X)
            if bad.any():
                x = float(X[bad].ravel()[0])
                raise OutsideSamplesError(
                    f"the sampled face's {what} was asked at X = {x!r}, outside its extent "
                    f"[{lo!r}, {hi!r}] (first and last sample); build it with "
                    "face_from_samples(..., outside='tangent') to continue H by its end "
                    "tangents (contact.solve evaluates the slope up to 16 contact widths "
                    "beyond a free end to check the gap)")
        out = spline(np.clip(X, lo, hi))
        if what == "height" and self.outside == "tangent" and (below.any() or above.any()):
            h0, h1, s0, s1 = self._ends
            out = np.where(below, h0 + s0 * (X - lo), out)
            out = np.where(above, h1 + s1 * (X - hi), out)
        return out[()] if out.ndim == 0 else out


def _samples(name, value):
    if isinstance(value, (str, bytes)):
        raise SampleError(f"{name} must be a 1-D sequence of real numbers, got a string")
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError) as exc:
        raise SampleError(f"{name} must be a 1-D sequence of real numbers: {exc}") from None
    if arr.dtype.kind == "c":
        raise SampleError(f"{name} must be real, got complex values")
    if arr.dtype.kind not in "biuf":
        raise SampleError(f"{name} must be a 1-D sequence of real numbers, got dtype {arr.dtype}")
    if arr.ndim != 1:
        raise SampleError(f"{name} must be 1-D (one value per sample), got shape {arr.shape}")
    arr = arr.astype(float)
    bad = np.flatnonzero(~np.isfinite(arr))
    if bad.size:
        raise SampleError(f"{name} must be finite, got {name}[{bad[0]}] = {float(arr[bad[0]])!r} "
                          f"({bad.size} non-finite value{'s' if bad.size > 1 else ''})")
    return arr


def face_from_samples(X, h, *, kind="quintic", breaks="auto", outside="raise") -> SampledFace:
    """The punch face H(X) through measured samples (X_i, h_i).

    Parameters
    ----------
    X : 1-D sequence of float
        Strictly increasing sample positions (any spacing), at least ``MIN_SAMPLES`` = 4.
    h : 1-D sequence of float
        Face height at each X (same length; any additive constant).
    kind : {"quintic", "cubic"}
        Interpolating spline degree 5 (default; slope C^3) or 3 (slope C^1); see the module
        docstring for why quintic.
    breaks : {"auto", "all", "none"}
        Which knots ``face.breaks`` holds: all when there are at most ``MAX_AUTO_BREAKS``
        (auto), all, or none (see the module docstring for the measured trade-off).
    outside : {"raise", "tangent"}
        Evaluation outside ``extent``: :class:`OutsideSamplesError`, or H continued by its
        end tangents (needed by contact.solve unless the samples reach 16 contact widths
        beyond the contact).

    Returns
    -------
    SampledFace

    Raises
    ------
    SampleError
        (a :class:`contact.PunchGeometryError`) for fewer than 4 samples, NaN / inf, X not
        strictly increasing (unsorted or repeated), lengths that differ, non-1-D input.
    contact.ContactInputError
        ``kind``, ``breaks`` or ``outside`` not one of the allowed values.
    """
    if kind not in _DEGREE:
        raise ContactInputError(f"kind must be one of {sorted(_DEGREE)}, got {kind!r}")
    if breaks not in _BREAKS:
        raise ContactInputError(f"breaks must be one of {list(_BREAKS)}, got {breaks!r}")
    if outside not in _OUTSIDE:
        raise ContactInputError(f"outside must be one of {list(_OUTSIDE)}, got {outside!r}")
    Xa = _samples("X", X)
    ha = _samples("h", h)
    if Xa.size != ha.size:
        raise SampleError(f"X and h must have the same length, got {Xa.size} and {ha.size}")
    N = Xa.size
    if N < MIN_SAMPLES:
        raise SampleError(f"at least {MIN_SAMPLES} samples are needed to define a face, got {N}")
    dX = np.diff(Xa)
    bad = np.flatnonzero(dX <= 0.0)
    if bad.size:
        i = int(bad[0])
        what = "repeated" if dX[i] == 0.0 else "decreasing (unsorted)"
        raise SampleError(f"X must be strictly increasing (sorted, no repeated X), got "
                          f"X[{i}] = {float(Xa[i])!r} and X[{i + 1}] = {float(Xa[i + 1])!r}: {what}")
    deg = min(_DEGREE[kind], N - 1)
    # imported here: scipy.interpolate slows the start of every `contact run`, and only a
    # face given by samples needs it
    from scipy.interpolate import make_interp_spline
    H = make_interp_spline(Xa, ha, k=deg)          # not-a-knot for odd k; N = k + 1: polynomial
    dH = H.derivative()
    knots = tuple(float(t) for t in H.t[deg + 1:H.t.size - deg - 1])
    use = breaks == "all" or (breaks == "auto" and len(knots) <= MAX_AUTO_BREAKS)
    lo, hi = float(Xa[0]), float(Xa[-1])
    e = np.array([lo, hi])
    h01, s01 = H(e), dH(e)
    if not (np.all(np.isfinite(h01)) and np.all(np.isfinite(s01))):   # pragma: no cover
        raise SampleError("the interpolating spline is not finite (X spacing too uneven?)")
    Xa.flags.writeable = False
    ha.flags.writeable = False
    return SampledFace(extent=(lo, hi), breaks=knots if use else (), knots=knots, degree=deg,
                       kind=kind, outside=outside, X=Xa, h=ha, _H=H, _dH=dH,
                       _ends=(float(h01[0]), float(h01[1]), float(s01[0]), float(s01[1])))
