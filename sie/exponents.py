"""Endpoint exponents of a Cauchy singular integral equation of the second kind."""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np

from .errors import InvalidCoefficientError, InvalidEndConditionError, check_finite_real

__all__ = ["Exponents", "sie_exponents", "exponents_of", "check_coefficients", "check_end",
           "is_explicit", "check_explicit_exponent", "END_CHOICES", "MIN_B_OVER_A"]

END_CHOICES = ("bounded", "singular")


# --------------------------------------------------------------------------
# exponents
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class Exponents:
    """Endpoint exponents of psi = (1-s)^alpha (1+s)^beta phi.

    Returned by :func:`sie_exponents`.  alpha0 in (0,1) solves cot(pi alpha0) = -a/b.
    The shifted exponents 1 + alpha, 1 + beta (those of the solution weight at its ends)
    and 1 - alpha, 1 - beta (those of the projection weight (1-s)^{-alpha}(1+s)^{-beta}) are
    carried separately, each computed without cancellation from alpha0 or 1 - alpha0: when
    an exponent is within 1e-8 of -1, recomputing e + 1 from a rounded e would lose 8
    digits, and moments ~ 1/(e+1) with it.

    Attributes
    ----------
    alpha, beta : float
        Exponents at the right (s = 1) and the left (s = -1) end, in (-1, 1).
    kappa : int
        Index -(alpha + beta): 1 (both ends singular), 0 or -1 (both bounded).
    alpha0 : float
        The root in (0, 1) of cot(pi alpha0) = -a/b.
    cot : float
        cot(pi alpha) = -a/b.
    sin : float
        sin(pi alpha).
    alpha_p1, beta_p1 : float
        1 + alpha, 1 + beta.
    alpha_m1, beta_m1 : float
        1 - alpha, 1 - beta.

    References
    ----------
    N. I. Muskhelishvili, Singular Integral Equations (1953), ch. 10; Erdogan, Gupta & Cook
    (1973), ch. 7.

    Examples
    --------
    >>> import sie
    >>> e = sie.sie_exponents(-1.0, 1.0, "bounded", "bounded")    # cot(pi alpha0) = 1
    >>> type(e).__name__, round(e.alpha, 12), round(e.beta, 12), e.kappa, round(e.sin, 12)
    ('Exponents', 0.25, 0.75, -1, 0.707106781187)
    """
    alpha: float
    beta: float
    kappa: int
    alpha0: float
    cot: float
    sin: float
    alpha_p1: float   # 1 + alpha
    beta_p1: float    # 1 + beta
    alpha_m1: float   # 1 - alpha
    beta_m1: float    # 1 - beta


def sie_exponents(a: float, b: float, left: str, right: str) -> Exponents:
    """Exponents and index from cot(pi alpha0) = -a/b and the end choices.

    Right end: alpha = alpha0 ("bounded") or alpha0 - 1 ("singular"); left end:
    beta = 1 - alpha0 ("bounded") or -alpha0 ("singular"); kappa = -(alpha+beta).
    alpha0 is the principal arccot in (0, 1), for every sign of a/b.

    Parameters
    ----------
    a, b : float
        Coefficients of a psi + (b/pi) PV int psi/(t - s) dt: finite, b != 0.
    left, right : {"bounded", "singular"}
        Behaviour of psi at s = -1 and s = +1.

    Returns
    -------
    Exponents

    Raises
    ------
    InvalidCoefficientError
        a or b not a finite real number, b = 0, or abs(b/a) below :data:`MIN_B_OVER_A` (an end
        exponent within rounding of -1 or 1).
    InvalidEndConditionError
        left or right not "bounded" or "singular".

    References
    ----------
    N. I. Muskhelishvili, Singular Integral Equations (1953), ch. 10; Erdogan, Gupta & Cook
    (1973), ch. 7.  The same rule with cot(pi alpha) = -mu_f N12 / N11 gives the exponents
    of the contact pressure (Zhou, Lee & Jang 2014, eqs. (4.14)-(4.18), with the branch of
    the arccot corrected: see the documentation, Theory: errata of Zhou et al. 2014).

    Examples
    --------
    a = 0 (the airfoil equation): the exponents are +-1/2.

    >>> import sie
    >>> e = sie.sie_exponents(0.0, 1.0, "singular", "bounded")
    >>> e.alpha, e.beta, e.kappa
    (0.5, -0.5, 0)
    >>> e = sie.sie_exponents(-1.0, 1.0, "singular", "singular")   # alpha0 = 1/4
    >>> round(e.alpha, 12), round(e.beta, 12), e.kappa
    (-0.75, -0.25, 1)
    """
    a, b = check_coefficients(a, b)
    return exponents_of(a, b, check_end("left", left), check_end("right", right))


#: About the smallest abs(b/a) that double precision resolves: below it alpha0 (cot(pi
#: alpha0) = -a/b, alpha0 ~ abs(b/a) / pi) or 1 - alpha0, as :func:`exponents_of` computes
#: it from atan2, rounds to 1, and an end exponent to -1 or 1 (the exact bound, ~3.4e-16,
#: is where that rounding happens; :func:`check_coefficients` tests the rounding itself).
MIN_B_OVER_A = math.pi * 2.0 ** -53


def check_coefficients(a, b) -> tuple[float, float]:
    """(a, b) as floats: finite reals with b != 0 and abs(b/a) resolved in double precision
    (:data:`MIN_B_OVER_A`), else InvalidCoefficientError."""
    a = check_finite_real("a", a, InvalidCoefficientError)
    b = check_finite_real("b", b, InvalidCoefficientError)
    if b == 0.0:
        raise InvalidCoefficientError(
            "b must be nonzero (b = 0 leaves no singular integral: the equation is not a Cauchy SIE)")
    y = -a / b                   # as exponents_of forms alpha0 and 1 - alpha0 from it
    if not (math.isfinite(y) and math.atan2(1.0, y) / math.pi < 1.0
            and math.atan2(1.0, -y) / math.pi < 1.0):
        raise InvalidCoefficientError(
            f"|b/a| = {abs(b) / abs(a):.3g} (a = {a!r}, b = {b!r}) is too small for double "
            f"precision: alpha0 (cot(pi alpha0) = -a/b) is within rounding of 0 or 1, so that "
            f"an end exponent rounds to -1 or 1 (allowed: |b/a| above about "
            f"{MIN_B_OVER_A:.2g})")
    return a, b


def is_explicit(v) -> bool:
    """Whether an end condition is an explicit exponent (a real number, not text or a
    bool) rather than "bounded" / "singular"."""
    return isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_))


def check_explicit_exponent(name: str, v) -> float:
    """``v`` as a float if it is a real number in (-1, 1), else InvalidEndConditionError."""
    if not is_explicit(v):
        raise InvalidEndConditionError(
            f'{name} must be "bounded", "singular" or an exponent in (-1, 1) (a float), '
            f"got {v!r}")
    e = float(v)
    if not (-1.0 < e < 1.0):
        raise InvalidEndConditionError(
            f"{name} = {e!r}: an explicit end exponent must lie in (-1, 1) (psi integrable, "
            "not vanishing to first order)")
    return e


def check_end(name: str, v, explicit: bool = False):
    """``v`` if it is "bounded" or "singular"; with ``explicit``, also a real number in
    (-1, 1) (an explicit end exponent, returned as a float: :mod:`sie.fixed_ends`); else
    InvalidEndConditionError."""
    if isinstance(v, str) and v in END_CHOICES:
        return v
    if explicit and not isinstance(v, (str, bytes)):
        return check_explicit_exponent(name, v)
    # text: a misspelt end choice (an exponent is given as a number, not as text)
    raise InvalidEndConditionError(f'{name} must be "bounded" or "singular", got {v!r}')


def exponents_of(a: float, b: float, left: str, right: str) -> Exponents:
    """:func:`sie_exponents` of inputs already checked (:func:`check_coefficients`,
    :func:`check_end`)."""
    y = -a / b                                   # cot(pi alpha0)
    alpha0 = math.atan2(1.0, y) / math.pi        # principal arccot, in (0, 1)
    alpha0c = math.atan2(1.0, -y) / math.pi      # 1 - alpha0, without cancellation
    sin0 = 1.0 / math.hypot(1.0, y)              # sin(pi alpha0) > 0
    if right == "bounded":
        alpha, alpha_p1, alpha_m1 = alpha0, 1.0 + alpha0, alpha0c
    else:
        alpha, alpha_p1, alpha_m1 = -alpha0c, alpha0, 1.0 + alpha0c
    if left == "bounded":
        beta, beta_p1, beta_m1 = alpha0c, 1.0 + alpha0c, alpha0
    else:
        beta, beta_p1, beta_m1 = -alpha0, alpha0c, 1.0 + alpha0
    kappa = {("singular", "singular"): 1, ("bounded", "bounded"): -1}.get((left, right), 0)
    sin_pa = sin0 if right == "bounded" else -sin0  # sin(pi(alpha0 - 1)) = -sin(pi alpha0)
    return Exponents(alpha, beta, kappa, alpha0, y, sin_pa, alpha_p1, beta_p1, alpha_m1, beta_m1)


