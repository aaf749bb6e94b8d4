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
    "SIEWarning",
    "InconsistentEquationWarning",
    "ResidualWarning",
]


class SIEInputError(ValueError):
    """Base class: an argument of an :mod:`sie` function is not admissible."""


class InvalidOrderError(SIEInputError):
    """``n`` (number of nodes / unknowns) is not an admissible integer."""


class InvalidExponentError(SIEInputError):
    """A Jacobi exponent is not > -1 (or not finite)."""


class InvalidCoefficientError(SIEInputError):
    """``a`` or ``b`` is not finite, or ``b == 0``."""


class InvalidEndConditionError(SIEInputError):
    """``left``/``right`` is not one of "bounded", "singular"."""


class SideConditionError(SIEInputError):
    """``total`` missing for index 1, given for another index, or not finite."""


class CallableOutputError(SIEInputError):
    """A user callable returned the wrong shape or a non-finite value."""


class InvalidBreakpointError(SIEInputError):
    """A break point is not a finite number strictly inside (-1, 1)."""


class EvaluationPointError(SIEInputError):
    """An evaluation point is not finite or lies where the quantity is infinite."""


class InvalidIntervalError(SIEInputError):
    """``intervals`` is not a sequence of finite, ascending, disjoint (c, d) pairs with c < d."""


class PerIntervalArgumentError(SIEInputError):
    """A per-interval argument (n, left, right, total, breaks) does not fit the intervals."""


class KernelSingularityError(SIEInputError):
    """The kernel k(s, t) is unbounded at an end (a fixed singularity, e.g. the edge crack's
    generalised Cauchy kernel): it changes the end exponent, which the Jacobi basis fixes."""


class SIEWarning(UserWarning):
    """Base class of the warnings of :mod:`sie`: a result is returned but is suspect."""


class InconsistentEquationWarning(SIEWarning):
    """Index -1 (both ends bounded) and f violates the solvability condition: the returned
    psi solves the equation with f minus its inconsistent part only."""


class ResidualWarning(SIEWarning):
    """The returned solution leaves a residual in the equation that is not small against f."""


def check_finite_real(name: str, value, error=SIEInputError) -> float:
    """Return ``value`` as a float or raise ``error`` naming ``name``."""
    try:
        v = float(value)
    except (TypeError, ValueError):
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
