"""Exceptions raised by :mod:`sie` (all subclasses of ``ValueError``).

Every message names the offending argument and says what is allowed.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = [
    "SIEInputError",
    "InvalidOrderError",
    "InvalidExponentError",
    "InvalidCoefficientError",
    "InvalidEndConditionError",
    "SideConditionError",
    "CallableOutputError",
    "InvalidBreakpointError",
    "EvaluationPointError",
    "InvalidIntervalError",
    "PerIntervalArgumentError",
    "KernelSingularityError",
    "UnsupportedEquationError",
    "SIEWarning",
    "InconsistentEquationWarning",
    "ResidualWarning",
    "ResolutionWarning",
]


class SIEInputError(ValueError):
    """Base class: an argument of an :mod:`sie` function is not admissible.

    Every input error of :mod:`sie` derives from it (and from ``ValueError``), so one
    ``except sie.SIEInputError`` catches them all; the message names the argument, the value
    received and what is allowed.  :func:`sie.jacobi_moment` and :func:`sie.jacobi_norms`
    raise a plain ``ValueError`` instead.

    Examples
    --------
    >>> import sie
    >>> try:
    ...     sie.gauss_jacobi(0, 0.0, 0.0)
    ... except sie.SIEInputError as e:
    ...     print(type(e).__name__, isinstance(e, ValueError))
    InvalidOrderError True
    """


class InvalidOrderError(SIEInputError):
    """``n`` (number of nodes / unknowns) is not an admissible integer.

    Raised by :func:`sie.gauss_jacobi` (n < 1, not an integer, or n > 20000 with an exponent
    above 5) and by :meth:`sie.Equation.solve`, :meth:`sie.Equation.functionals` and
    :func:`sie.solve` (n < 1, n < 2 on an interval of index 1, or n > ``N_MAX``).

    Examples
    --------
    >>> import sie
    >>> sie.gauss_jacobi(0, 0.0, 0.0)
    Traceback (most recent call last):
        ...
    sie.errors.InvalidOrderError: n must be an integer >= 1, got 0
    """


class InvalidExponentError(SIEInputError):
    """A Jacobi exponent is not > -1 (or not finite).

    The weight (1-x)^alpha (1+x)^beta is integrable on [-1, 1] only for alpha, beta > -1.
    Raised by :func:`sie.gauss_jacobi` and :func:`sie.jacobi_cauchy` (which also needs
    alpha + beta in {-1, 0, 1}).

    Examples
    --------
    >>> import sie
    >>> sie.gauss_jacobi(3, -1.0, 0.0)
    Traceback (most recent call last):
        ...
    sie.errors.InvalidExponentError: alpha must be > -1 (the weight ... must be integrable), got -1.0
    """


class InvalidCoefficientError(SIEInputError):
    """``a`` or ``b`` is not finite, or ``b == 0``.

    With b = 0 the equation has no Cauchy integral (it is not a singular integral equation).
    Raised by :class:`sie.Equation` and :func:`sie.solve`.

    Examples
    --------
    >>> import numpy as np, sie
    >>> sie.solve(np.cos, a=1.0, b=0.0, n=4, left="bounded", right="singular")
    Traceback (most recent call last):
        ...
    sie.errors.InvalidCoefficientError: b must be nonzero (b = 0 leaves no singular integral: ...)
    """


class InvalidEndConditionError(SIEInputError):
    """``left``/``right`` is not one of "bounded", "singular".

    Raised by :class:`sie.Equation` and :func:`sie.solve`.

    Examples
    --------
    >>> import numpy as np, sie
    >>> sie.solve(np.cos, a=1.0, b=1.0, n=4, left="free", right="singular")
    Traceback (most recent call last):
        ...
    sie.errors.InvalidEndConditionError: left must be "bounded" or "singular", got 'free'
    """


class SideConditionError(SIEInputError):
    """``total`` missing for index 1, given for another index, or not finite.

    With both ends singular (index 1) the dominant operator has a one-dimensional null space
    and int psi = ``total`` fixes the solution (Muskhelishvili 1953, ch. 10); with any other
    index the solution is unique and ``total`` must not be given.  Raised by
    :func:`sie.solve`.

    Examples
    --------
    >>> import numpy as np, sie
    >>> sie.solve(np.cos, a=1.0, b=1.0, n=4, left="singular", right="singular")
    Traceback (most recent call last):
        ...
    sie.errors.SideConditionError: total (= int psi) is required when both ends are singular (index 1)
    """


class CallableOutputError(SIEInputError):
    """A user callable returned the wrong shape or a non-finite value.

    Raised when ``f`` or ``kernel`` is not callable, raises, is not vectorised (called with an
    array it must return an array of that shape), or returns complex or non-finite values; the
    message names the callable and the point.  Raised by :func:`sie.solve`,
    :meth:`sie.Equation.solve` and :meth:`sie.Equation.functionals`.

    Examples
    --------
    >>> import sie
    >>> sie.solve(lambda s: 1.0, a=1.0, b=1.0, n=4, left="bounded", right="singular")
    Traceback (most recent call last):
        ...
    sie.errors.CallableOutputError: f must be vectorised: called with arrays of shape (4,) it must return that shape, got ()
    """


class InvalidBreakpointError(SIEInputError):
    """A break point is not a finite number strictly inside (-1, 1).

    (With ``intervals``: strictly inside one of them.)  Raised by :func:`sie.solve` and
    :meth:`sie.Equation.functionals`.

    Examples
    --------
    >>> import numpy as np, sie
    >>> sie.solve(np.cos, a=1.0, b=1.0, n=4, left="bounded", right="singular", breaks=(1.5,))
    Traceback (most recent call last):
        ...
    sie.errors.InvalidBreakpointError: breaks must lie strictly inside (-1.0, 1.0); got ...1.5...
    """


class EvaluationPointError(SIEInputError):
    """An evaluation point is not finite or lies where the quantity is infinite.

    Raised by the methods of :class:`sie.Solution` (a point outside L for ``phi`` and
    ``weight``, a singular end for ``psi``, an end for ``cauchy``, a complex point where a
    real one is needed) and by :func:`sie.jacobi_cauchy` (z = +-1, a complex z on [-1, 1]).

    Examples
    --------
    >>> import sie
    >>> sie.jacobi_cauchy([1.0], -0.5, -0.5, 1.0)
    Traceback (most recent call last):
        ...
    sie.errors.EvaluationPointError: z lies at an end of the interval [-1.0, 1.0], where the Cauchy transform is infinite or undefined
    """


class InvalidIntervalError(SIEInputError):
    """``intervals`` is not a sequence of finite, ascending, disjoint (c, d) pairs with c < d.

    Raised by :func:`sie.solve`.

    Examples
    --------
    >>> import numpy as np, sie
    >>> sie.solve(np.cos, a=1.0, b=1.0, n=4, left="bounded", right="singular",
    ...           intervals=[(0.0, -1.0)])
    Traceback (most recent call last):
        ...
    sie.errors.InvalidIntervalError: intervals[0] = (0.0, -1.0): need c < d
    """


class PerIntervalArgumentError(SIEInputError):
    """A per-interval argument (n, left, right, total, breaks) does not fit the intervals.

    Each of them is one value for all intervals or a sequence with one entry per interval.
    Raised by :func:`sie.solve`.

    Examples
    --------
    >>> import numpy as np, sie
    >>> sie.solve(np.cos, a=1.0, b=1.0, n=[4], left="bounded", right="singular",
    ...           intervals=[(-1.0, -0.5), (0.0, 1.0)])
    Traceback (most recent call last):
        ...
    sie.errors.PerIntervalArgumentError: n must be one value for all 2 intervals or a sequence of 2 (one per interval), got 1 entries
    """


class KernelSingularityError(SIEInputError):
    """The kernel k(s, t) is unbounded at an end whose exponent was not given (a fixed
    singularity, e.g. the edge crack's generalised Cauchy kernel): it sets the end exponent
    itself, which the end choices "bounded" / "singular" take from a and b instead.

    :func:`sie.solve` samples the kernel at distances 1e-3 and 1e-6 (relative to the
    half-widths) inside every pair of interval ends and raises when it grows more than
    100-fold there, or cannot be evaluated there.  The message names the end: give its
    exponent explicitly, ``left=<float>`` or ``right=<float>`` in (-1, 1)
    (:mod:`sie.fixed_ends`; the root of the kernel's characteristic function,
    :func:`sie.end_exponent`; 0 for the edge crack's kernel at the free surface), and the
    corners of such ends are not probed.

    References
    ----------
    F. Erdogan, G. D. Gupta and T. S. Cook, "Numerical solution of singular integral
    equations", in Methods of Analysis and Solutions of Crack Problems, G. C. Sih (ed.),
    Noordhoff (1973), ch. 7 (generalised Cauchy kernels of edge cracks).
    Kaya & Erdogan (1987), on treating such kernels analytically.

    Examples
    --------
    >>> import numpy as np, sie
    >>> sie.solve(np.cos, a=1.0, b=1.0, n=4, left="bounded", right="singular",
    ...           kernel=lambda s, t: 1.0 / (2.0 - s - t))
    Traceback (most recent call last):
        ...
    sie.errors.KernelSingularityError: the kernel grows without bound toward (s, t) = (1.0, 1.0) ...
    """


class UnsupportedEquationError(SIEInputError):
    """A method was asked for an equation it does not handle.

    :meth:`Equation.functionals` needs one interval without a kernel (the functionals of
    the dominant equation come from one Gauss sum only there), and a case axis holds
    one-interval equations without a kernel or breaks.

    Examples
    --------
    >>> import numpy as np, sie
    >>> eq = sie.Equation(a=0.0, b=1.0, left="bounded", right="bounded",
    ...                   kernel=lambda s, t: s * t)
    >>> eq.functionals(np.cos, n=4)
    Traceback (most recent call last):
        ...
    sie.errors.UnsupportedEquationError: functionals need one interval without a kernel ...
    """


class SIEWarning(UserWarning):
    """Base class of the warnings of :mod:`sie`: a result is returned but is suspect.

    Examples
    --------
    >>> import sie
    >>> [issubclass(w, sie.SIEWarning)
    ...  for w in (sie.InconsistentEquationWarning, sie.ResidualWarning)]
    [True, True]
    """


class InconsistentEquationWarning(SIEWarning):
    """Index -1 (both ends bounded) and f violates the solvability condition: the returned
    psi solves the equation with f minus its inconsistent part only.

    The condition is that the weighted mean of f against (1-s)^{-alpha} (1+s)^{-beta}
    vanish (Muskhelishvili 1953, ch. 10; for the cylindrical punch, Zhou, Lee & Jang 2014,
    eq. (5.40)); its value is ``Solution.consistency``.  Warned by :func:`sie.solve` when
    abs(consistency) exceeds 1e-8 max abs(f).

    References
    ----------
    N. I. Muskhelishvili, Singular Integral Equations, Noordhoff (1953), ch. 10.

    Examples
    --------
    f = 1 is not orthogonal to 1/sqrt(1 - s^2), so (1/pi) PV int psi/(t - s) dt = 1 has no
    solution bounded at both ends:

    >>> import warnings, numpy as np, sie
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     sol = sie.solve(np.ones_like, a=0.0, b=1.0, n=6, left="bounded", right="bounded")
    >>> [w.category.__name__ for w in caught], round(sol.consistency, 12)
    (['InconsistentEquationWarning'], 1.0)
    """


class ResidualWarning(SIEWarning):
    """The returned solution leaves a residual in the equation that is not small against f.

    :func:`sie.solve` checks the equation at 7 points of each interval between the
    collocation nodes when there is a kernel or several intervals (elsewhere the collocation
    is exact by construction) and warns when the residual exceeds 1e-6 of the scale of f:
    n does not resolve f or the kernel, or the kernel is not smooth.

    Examples
    --------
    >>> import warnings, numpy as np, sie
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     sol = sie.solve(np.cos, a=0.0, b=1.0, n=6, left="bounded", right="singular",
    ...                     kernel=lambda s, t: np.exp(30.0 * s * t))
    >>> [w.category.__name__ for w in caught]
    ['ResidualWarning']
    """


class ResolutionWarning(SIEWarning):
    """``n="auto"`` stopped at its largest n (:data:`sie.auto.N_AUTO_MAX`) on an interval
    whose series is not resolved to ``tol``: the solution returned is the last one, and its
    error is about the size of the series' tail (given in the message).  Usually a feature
    the Jacobi basis does not carry: a kink or jump in f (pass ``breaks=``), a fixed
    singularity at an end (give its exponent), or an interval that should be split.

    Examples
    --------
    >>> import warnings, numpy as np, sie
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     sol = sie.solve(lambda s: np.abs(s - 0.3), a=0.0, b=1.0, n="auto", tol=1e-13,
    ...                     left="bounded", right="singular")
    >>> [w.category.__name__ for w in caught], sol.n
    (['ResolutionWarning'], 4096)
    """


def check_finite_real(name: str, value, error=SIEInputError) -> float:
    """Return ``value`` as a float or raise ``error`` naming ``name``: a real number
    (:func:`is_number`: not text, which ``float`` would parse, nor a bool), finite."""
    if type(value) is float and math.isfinite(value):
        return value                  # the common case, which the checks below accept
    if not is_number(value):
        raise error(f"{name} must be a finite real number, got {describe_value(value)}")
    try:
        v = float(value)
    except (TypeError, ValueError, OverflowError):
        raise error(f"{name} must be a finite real number, got {value!r}") from None
    if not math.isfinite(v):
        raise error(f"{name} must be a finite real number, got {v!r}")
    return v


def check_order(n, minimum: int = 1, what: str = "") -> int:
    """Return ``n`` as an int >= ``minimum`` or raise :class:`InvalidOrderError`."""
    if isinstance(n, (bool, np.bool_)) or not isinstance(n, (int, np.integer, float, np.floating)):
        raise InvalidOrderError(f"n must be an integer >= {minimum}{what}, got {n!r}")
    if isinstance(n, (float, np.floating)):
        if not math.isfinite(n) or n != int(n):
            raise InvalidOrderError(f"n must be an integer >= {minimum}{what}, got {n!r}")
    n = int(n)
    if n < minimum:
        raise InvalidOrderError(f"n must be an integer >= {minimum}{what}, got {n}")
    return n


def check_exponent(name: str, value) -> float:
    """Return a Jacobi exponent as float, requiring finiteness and > -1."""
    v = check_finite_real(name, value, InvalidExponentError)
    if v <= -1.0:
        raise InvalidExponentError(
            f"{name} must be > -1 (the weight (1-x)^alpha (1+x)^beta must be integrable), got {v!r}")
    return v


_RETRY_MAX = 4096   # points re-tried one by one to name the point where a callable raised


def _failing_point(fn, args):
    """The first point at which ``fn`` raises when called on one point at a time (the
    arrays in ``args`` share a shape), or None."""
    flat = [np.ravel(a) for a in args]
    for i in range(min(flat[0].size, _RETRY_MAX)):
        try:
            fn(*(a[i:i + 1] for a in flat))
        except Exception:
            return tuple(float(a[i]) for a in flat)
    return None


def call_checked(fn, name, args, shape):
    """``fn(*args)`` as a float array of the given shape, or a :class:`CallableOutputError`
    naming ``name`` and the point (an exception inside fn -- any ``Exception``, chained as
    the cause --, complex or non-numeric output, a wrong shape, a non-finite value)."""
    try:
        out = fn(*args)
    except Exception as exc:
        where = _failing_point(fn, args)
        at = f" at {where}" if where is not None else (
            f" (called on {np.size(args[0])} points; no single one raises alone)")
        raise CallableOutputError(f"{name} raised {type(exc).__name__}{at}: {exc}") from exc
    out = np.asarray(out)
    if out.dtype.kind == "c":
        raise CallableOutputError(f"{name} must return real values, got complex")
    try:
        out = out.astype(float, copy=False)
    except (TypeError, ValueError) as exc:
        raise CallableOutputError(f"{name} must return real numbers, got {out.dtype}: {exc}") from exc
    if out.shape != shape:
        raise CallableOutputError(
            f"{name} must be vectorised: called with arrays of shape {shape} it must return "
            f"that shape, got {out.shape}")
    if not np.isfinite(out).all():
        bad = np.flatnonzero(~np.isfinite(out.ravel()))[0]
        where = tuple(float(np.ravel(a)[bad]) for a in args)
        raise CallableOutputError(f"{name} returned a non-finite value at {where}")
    return out


def is_number(value) -> bool:
    """Whether ``value`` is a real number: an int or a float (Python's or numpy's, a 0-d
    numeric array), or another object that converts itself to a float (``Fraction``,
    ``Decimal``).  Text is not, though ``float`` would parse it (``"0.5"``, numpy's ``str_``,
    an array of strings), nor a bool, nor a complex number."""
    if isinstance(value, (str, bytes, bool, np.bool_, complex, np.complexfloating)):
        return False
    if isinstance(value, (np.ndarray, np.generic)):
        return value.dtype.kind in "iuf"
    return hasattr(value, "__float__") or hasattr(value, "__index__")


def describe_value(value) -> str:
    """A value refused as a number and its type, for the message: ``'0.5' (a str, not a
    real number)``."""
    if isinstance(value, np.generic):
        value = value.item()                # np.str_('0.5') reads as '0.5'
    if isinstance(value, np.ndarray):
        kind = f"an array of {value.dtype}"
    else:
        kind = type(value).__name__
        kind = f"{'an' if kind[0] in 'aeiou' else 'a'} {kind}"
    return f"{value!r} ({kind}, not a real number)"


def real_array(name: str, values, error=SIEInputError,
               allowed: str = "real numbers") -> np.ndarray:
    """``values`` (a number or a sequence of them) as a float array, or ``error`` naming
    ``name`` and the first entry that is not a real number (:func:`is_number`: text, a bool,
    a complex number), or saying that ``values`` is ragged.  Finiteness is the caller's to
    check."""
    try:
        arr = np.asarray(values)
    except (TypeError, ValueError) as exc:          # ragged
        raise error(f"{name} must be {allowed} (an array of them), got {values!r}: {exc}") \
            from None
    if arr.dtype.kind in "iuf":
        return arr.astype(float, copy=False)
    entries = arr if isinstance(values, np.ndarray) else np.asarray(values, dtype=object)
    bad = next((v for v in entries.flat if not is_number(v)), None)
    if bad is not None:
        among = "" if arr.ndim == 0 else f" among {values!r}"
        raise error(f"{name} must be {allowed}, got {describe_value(bad)}{among}")
    try:
        return arr.astype(float)
    except (TypeError, ValueError) as exc:          # numbers nested in sequences
        raise error(f"{name} must be {allowed} (an array of them), got {values!r}: {exc}") \
            from None
