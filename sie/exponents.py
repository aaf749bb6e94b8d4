"""Endpoint exponents of a Cauchy singular integral equation of the second kind."""
from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["Exponents", "sie_exponents", "END_CHOICES"]

END_CHOICES = ("bounded", "singular")


# --------------------------------------------------------------------------
# exponents
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class Exponents:
    """Endpoint exponents of psi = (1-s)^alpha (1+s)^beta phi.

    alpha0 in (0,1) solves cot(pi alpha0) = -a/b.  ``cot`` = cot(pi alpha) = -a/b,
    ``sin`` = sin(pi alpha).  The shifted exponents 1 + alpha, 1 + beta (those of
    the solution weight at its ends) and 1 - alpha, 1 - beta (those of the
    projection weight (1-s)^{-alpha}(1+s)^{-beta}) are carried separately, each
    computed without cancellation from alpha0 or 1 - alpha0: when an exponent is
    within 1e-8 of -1, recomputing e + 1 from a rounded e would lose 8 digits,
    and moments ~ 1/(e+1) with it.
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
    (Muskhelishvili 1953, ch. 10; Erdogan, Gupta & Cook 1973.)
    """
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


