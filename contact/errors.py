"""Exceptions and warnings raised by :mod:`contact`.

Every exception is a ``ValueError`` subclass whose message names the offending argument, the
value received and what is allowed.
"""
from __future__ import annotations

import math

import numpy as np

from sie.errors import check_finite_real, describe_value, is_number, real_array

__all__ = [
    "ContactInputError",
    "MaterialError",
    "SpeedError",
    "LoadError",
    "FrictionError",
    "DirectionError",
    "PunchGeometryError",
    "ProfileCallableError",
    "CauchyTransformError",
    "ContactLossError",
    "StressPointError",
    "UnboundedStressError",
    "NearRayleighWarning",
    "check_finite",
    "check_number",
    "real_array",
]


class ContactInputError(ValueError):
    """Base class: an argument of a :mod:`contact` function is not admissible.

    Every input error of :mod:`contact` derives from it (and from ``ValueError``); raised as
    such for arguments of the wrong type (a material without the methods of
    :class:`~contact.Material`, a punch that is not a :class:`~contact.Punch`), an
    unknown ``method``, ``n`` or ``tol`` out of range, a bad region or grid of
    :meth:`contact.ContactResult.stress_extrema`.

    Examples
    --------
    >>> import contact
    >>> contact.solve("steel", contact.FlatPunch(1.0), load=1.0, speed=0.0)
    Traceback (most recent call last):
        ...
    contact.errors.ContactInputError: material must have the methods surface_constants(c), ..., got str, which lacks surface_constants, rayleigh_speed, limiting_speed, relative_speed, half_space_modes
    """


class MaterialError(ContactInputError):
    """Stiffnesses not finite, or not positive definite; density not positive; a material's
    method returning what is not admissible.

    Raised by :class:`~contact.Orthotropic` and :func:`~contact.Isotropic` (C11, C22, C33 > 0,
    C11 C22 > C12^2, rho > 0; -1 < nu < 1/2), and where a density is needed but absent.
    Raised for a material of one's own (:class:`~contact.Material`) whose method returns
    what is not admissible (constants that are NaN or not real, N11 >= 0, a Rayleigh speed
    that is not > 0, modes without ``points`` and ``stresses``, points off the upper
    half-plane, stresses that are NaN) or raises an exception that is not a
    :class:`ContactInputError`: the message names the method.

    Examples
    --------
    >>> import contact
    >>> contact.Isotropic(1.0, 0.5)
    Traceback (most recent call last):
        ...
    contact.errors.MaterialError: Poisson's ratio nu must satisfy -1 < nu < 0.5, got 0.5
    """


class SpeedError(ContactInputError):
    """Relative speed negative, not finite, or not below the Rayleigh speed c_R.

    The admissible range is 0 <= c < c_R (:func:`~contact.rayleigh_speed`): the surface
    constants share the denominator Delta(c), which vanishes at c_R.  (Zhou, Lee & Jang 2014,
    Sec. 6.1, print [0, 1): see the documentation, Theory: errata of Zhou et al. 2014.)
    Raised by :func:`~contact.surface_constants`, :func:`~contact.solve` and
    :func:`~contact.load_curve`.

    Examples
    --------
    >>> import contact
    >>> contact.surface_constants(contact.zhou2014(), 1.0)
    Traceback (most recent call last):
        ...
    contact.errors.SpeedError: relative speed c must be below the Rayleigh speed c_R = 0.99361... of this material (allowed: 0 <= c < c_R), got c = 1.0
    """


class LoadError(ContactInputError):
    """Load not finite or not positive.

    Raised by :func:`~contact.solve` (``load``) and :func:`~contact.load_curve` (``loads``
    also empty or not strictly increasing).

    Examples
    --------
    >>> import contact
    >>> contact.solve(contact.zhou2014(), contact.FlatPunch(1.0), load=-1.0, speed=0.0)
    Traceback (most recent call last):
        ...
    contact.errors.LoadError: load must be positive (force per unit length pressing the punch in), got -1.0
    """


class FrictionError(ContactInputError):
    """Friction coefficient negative or not finite.

    The sense of sliding is ``direction``, not the sign of the friction coefficient.  Raised
    by :func:`~contact.solve` and :func:`~contact.load_curve`, and by
    :func:`~contact.half_space_stress` for a ``q_ratio`` (signed) that is not a finite number.

    Examples
    --------
    >>> import contact
    >>> contact.solve(contact.zhou2014(), contact.FlatPunch(1.0), load=1.0, speed=0.0,
    ...               friction=-0.1)
    Traceback (most recent call last):
        ...
    contact.errors.FrictionError: friction must be >= 0 (...), got -0.1
    """


class DirectionError(ContactInputError):
    """Direction of sliding not -1 or +1.

    Raised by :func:`~contact.solve` and :func:`~contact.load_curve`.

    Examples
    --------
    >>> import contact
    >>> contact.solve(contact.zhou2014(), contact.FlatPunch(1.0), load=1.0, speed=0.0,
    ...               direction=0)
    Traceback (most recent call last):
        ...
    contact.errors.DirectionError: direction must be -1 (punch slides toward -X) or +1 (toward +X), got 0
    """


class PunchGeometryError(ContactInputError):
    """Non-positive or non-finite punch dimension, or an inconsistent corner/break.

    Raised by the punch constructors (:class:`~contact.FlatPunch` etc.,
    :class:`~contact.ProfilePunch`), and by :func:`~contact.solve` for an unbounded face whose
    height does not rise on both sides (give ``face=``).

    Examples
    --------
    >>> import contact
    >>> contact.FlatPunch(-1.0)
    Traceback (most recent call last):
        ...
    contact.errors.PunchGeometryError: half_width must be a positive finite number, got -1.0
    """


class ProfileCallableError(ContactInputError):
    """A user slope callable returned the wrong shape or a non-finite value.

    Raised by :class:`~contact.ProfilePunch` (``slope`` / ``height`` not callable) and when
    its slope or height is evaluated (not vectorised, complex, raising or not finite).  An
    exception of any kind raised inside the user's slope or height (any ``Exception``:
    KeyError, ZeroDivisionError, ...) becomes this error, which names the callable and the X
    it was called at and has the exception as its cause; the package's own errors raised
    there (a :class:`ContactInputError` such as a sampled face's OutsideSamplesError, a
    :class:`sie.SIEInputError`) pass through unchanged.

    Examples
    --------
    >>> import contact
    >>> contact.ProfilePunch(slope="X")
    Traceback (most recent call last):
        ...
    contact.errors.ProfileCallableError: slope must be a vectorised callable dv/dX(X), got str
    """


class CauchyTransformError(ContactInputError):
    """A Cauchy transform given to :func:`~contact.half_space_stress` is not callable, raised,
    or returned values that are not those of a transform: not vectorised, not complex, not
    finite.

    At a point z with Im z > 0 the transform C(z) = (1/pi) int p(t) / (t - z) dt is complex
    (its imaginary part is the Poisson integral of p): a callable that returns a real array
    there has dropped (or never computed) the imaginary part, and is refused.  The message
    names the callable (``cauchy_p`` or ``cauchy_q``) and the points where it was called.

    Examples
    --------
    >>> import numpy as np, contact
    >>> contact.half_space_stress(contact.Isotropic(1.0, 0.3), 0.0, 1.0, -2.0,
    ...                           lambda z: -1.0 / (np.pi * z.real))
    Traceback (most recent call last):
        ...
    contact.errors.CauchyTransformError: cauchy_p must return complex values C(z) ...
    """


class ContactLossError(ContactInputError):
    """The profile and load admit no single contact zone with p >= 0 (contact lost inside,
    or two separate zones would be needed).

    Raised by :func:`~contact.solve` and :func:`~contact.load_curve` when the zones cannot be
    followed in load from first touch: no change of the zones (an end at an edge of the
    face, a merge, a new zone, a split) gives p >= 0 and an open gap, the face carries no
    compressive load where it first touches, or Newton's method for the ends fails.

    Examples
    --------
    A wedge, whose slope jumps at its apex, without ``breaks`` there: the ends cannot be
    found from the apex (the polynomial basis cannot follow the jump); with the break, they
    are.

    >>> import numpy as np, contact
    >>> wedge = lambda breaks: contact.ProfilePunch(lambda X: 0.01 * np.sign(X),
    ...                                             face=(-1.0, 1.0), breaks=breaks)
    >>> try:
    ...     contact.solve(contact.zhou2014(), wedge(()), load=0.01, speed=0.0)
    ... except contact.ContactLossError as e:
    ...     print(type(e).__name__, "- says to pass breaks=:", "breaks=" in str(e))
    ContactLossError - says to pass breaks=: True
    >>> r = contact.solve(contact.zhou2014(), wedge((0.0,)), load=0.01, speed=0.0)
    >>> round(r.ends[1], 6) == -round(r.ends[0], 6) > 0
    True
    """


class StressPointError(ContactInputError):
    """A point where the stress is asked for is not finite or lies outside the half-space
    Y <= 0.

    Raised by :meth:`contact.ContactResult.stress` and :func:`~contact.half_space_stress`
    (which also needs Y < 0).

    Examples
    --------
    >>> import contact
    >>> r = contact.solve(contact.zhou2014(), contact.FlatPunch(1.0), load=1.0, speed=0.0)
    >>> r.stress(0.0, 1.0)
    Traceback (most recent call last):
        ...
    contact.errors.StressPointError: the half-space is Y <= 0; got Y up to 1.0 (depth below the surface is -Y)
    """


class UnboundedStressError(ContactInputError):
    """A stress extremum asked for in a region that holds a singular contact end (where the
    stresses are infinite).

    Raised by :meth:`contact.ContactResult.stress_extrema` when the region reaches Y = 0 at
    a corner end (use the zones' SIFs there, or a region with Y_max < 0).

    Examples
    --------
    >>> import contact
    >>> r = contact.solve(contact.zhou2014(), contact.FlatPunch(1.0), load=1.0, speed=0.0)
    >>> r.stress_extrema(region=((-2.0, 2.0), (-1.0, 0.0)))
    Traceback (most recent call last):
        ...
    contact.errors.UnboundedStressError: the stresses are infinite at the singular contact end X = -1.0 ...
    """


class NearRayleighWarning(UserWarning):
    """Speed within 1% of the Rayleigh speed: results valid but extremely sensitive to c.

    Warned by :func:`~contact.surface_constants` (and so by :func:`~contact.solve`) for
    c > 0.99 c_R: N11 has a simple pole at c_R.

    Examples
    --------
    >>> import warnings, contact
    >>> m = contact.zhou2014()
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     sc = contact.surface_constants(m, 0.995 * contact.rayleigh_speed(m))
    >>> [w.category.__name__ for w in caught]
    ['NearRayleighWarning']
    """


def check_finite(name: str, value, error=ContactInputError) -> float:
    """Return ``value`` as a float, or raise ``error`` naming ``name`` if it is not a finite real
    number (:func:`check_number`, then :func:`sie.errors.check_finite_real`; the contact
    layer's base error by default)."""
    if type(value) is float and math.isfinite(value):
        return value                  # the common case, which the checks below accept
    check_number(name, value, error)
    return check_finite_real(name, value, error)


def check_number(name: str, value, error=ContactInputError,
                 allowed: str = "a finite real number") -> None:
    """Raise ``error`` naming ``name``, what was given and that ``allowed`` (a number) is
    required, unless ``value`` is a real number (:func:`is_number`).

    The one place where the contact layer tells a number from something ``float`` would
    also take: text (``float("0.5")`` parses it) and bools are refused, so that
    ``Orthotropic(C11="159")`` or ``load="0.01"`` fail where given, and numpy's numeric
    scalars (``np.float64``, ``np.int64``) are numbers."""
    if not is_number(value):
        raise error(f"{name} must be {allowed}, got {describe_value(value)}")


