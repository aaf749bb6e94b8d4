"""Surface constants N11, N12, N21, N22 of a moving orthotropic half-space, and its Rayleigh speed.

Conventions (see the documentation, Theory: the contact model and its conventions):
half-space Y < 0, surface tractions sigma_YY(X, 0) = -p(X), tau_XY(X, 0) = -q(X),
Hc[f](X) = (1/pi) PV int f(t) / (t - X) dt.  The surface response to (p, q) is (Zhou, Lee &
Jang 2014, eqs. (4.5)-(4.6), with N22 where the paper's eq. (4.3) prints N21 in L2; see the
documentation, Theory: errata of Zhou et al. 2014)::

    dv/dX (X, 0)   = N12 q(X) + N11 Hc[p](X),
    sigma_XX(X, 0) = N21 p(X) + N22 Hc[q](X).

Derivation (independent of the paper's eq. (4.4) and Appendix)
---------------------------------------------------------------
Take u, v ~ exp(i k X + |k| eta Y).  The equations of motion give eq. (3.1), the quadratic
a eta^4 + b eta^2 + d = 0 of :meth:`contact.material.Orthotropic.characteristic_coefficients`.
Decay as Y -> -inf keeps the two roots eta1, eta2 with Re eta > 0; with the eigenvectors
v_n = i sgn(k) h(eta_n) u_n, h(eta) = (C33 eta^2 - C11') / ((C12 + C33) eta), and
C11' = C11 - C33 c^2, the two traction conditions at Y = 0 fix the amplitudes.  Hc has the
Fourier multiplier +i sgn(k), so dv/dX and sigma_XX can be read off.  Every 2x2 determinant
carries a factor (eta1 - eta2), which cancels; the factor (C12 + C33) of the eigenvectors
cancels as well.  What is left depends on the roots only through

    P = eta1 eta2 = sqrt(d / a) = sqrt((1 - c^2) C11' / C22),
    S = eta1 + eta2 = sqrt(eta1^2 + eta2^2 + 2 P) = sqrt(2 P - b / a),

which are real and positive for real, complex-conjugate and repeated roots alike
(0 <= c < c_R).  With the Rayleigh function

    Delta(c) = P (C22 C11' - C12^2) - C33 c^2 C11'

the constants are

    N11 = -S C11' / Delta,
    N12 = (C11' - C12 P) / Delta,
    N21 = -[C11' (C11 C22 - C12^2 - C12 C33 c^2) - C12 C22 C33 c^2 P] / (C22 Delta),
    N22 = -P S (C11 C22 - C12^2) / Delta.

Static isotropic check (P = 1, S = 2): N11 = -(1 - nu)/G, N12 = (1 - 2 nu)/(2G), N21 = -1,
N22 = -2.  Evaluated at zeta > 0, the paper's eq. (4.4) with the Appendix (Case B) gives the
same numbers, but it divides by (eta1 - eta2) and by (C12 + C33): it is singular at isotropy
and loses digits near it.
"""
from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass

import numpy as np

from .errors import NearRayleighWarning, SpeedError
from .material import Orthotropic, check_speed

__all__ = [
    "SurfaceConstants",
    "surface_constants",
    "root_symmetric_functions",
    "rayleigh_function",
    "limiting_speed",
    "rayleigh_speed",
    "NEAR_RAYLEIGH_FRACTION",
]

#: A speed above this fraction of c_R triggers :class:`~contact.errors.NearRayleighWarning`.
NEAR_RAYLEIGH_FRACTION = 0.99


@dataclass(frozen=True)
class SurfaceConstants:
    """Surface constants of eqs. (4.5)-(4.6) of Zhou et al. 2014 at one relative speed.

    Returned by :func:`surface_constants`; :func:`contact.solve` accepts one as
    ``constants=`` (a sweep over friction at one speed shares it).

    Attributes
    ----------
    N11, N12 : float
        dv/dX (X, 0) = N12 q + N11 Hc[p]  (unit: 1 / stress unit of the material).
    N21, N22 : float
        sigma_XX(X, 0) = N21 p + N22 Hc[q]  (dimensionless).
    c : float
        Relative speed V / sqrt(C33 / rho).
    eta_product, eta_sum : float
        P = eta1 eta2 and S = eta1 + eta2 of the two decaying characteristic roots.
    rayleigh_denominator : float
        Delta(c) = P (C22 C11' - C12^2) - C33 c^2 C11' (> 0 below c_R).
    rayleigh_speed : float
        c_R of the material.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (4.4)-(4.6); the formulas in closed form
    through P and S: see :func:`surface_constants` and the module docstring.

    Examples
    --------
    An isotropic material at rest has a double root eta = 1 (P = 1, S = 2):

    >>> import contact
    >>> sc = contact.surface_constants(contact.Isotropic(2.5, 0.25), 0.0)
    >>> type(sc).__name__, sc.c, sc.eta_product, sc.eta_sum
    ('SurfaceConstants', 0.0, 1.0, 2.0)
    """

    N11: float
    N12: float
    N21: float
    N22: float
    c: float
    eta_product: float
    eta_sum: float
    rayleigh_denominator: float
    rayleigh_speed: float


def root_symmetric_functions(material: Orthotropic, c) -> tuple[float, float]:
    """P = eta1 eta2 and S = eta1 + eta2 of the decaying roots of eq. (3.1), Zhou et al. 2014.

    Computed from the coefficients of a eta^4 + b eta^2 + d = 0 only: P = sqrt(d/a),
    S = sqrt(2P - b/a).  Valid for 0 <= c below the limiting speed (see
    :func:`limiting_speed`), where d >= 0 and 2P - b/a >= 0; outside, NaN may result.
    """
    a, b, d = material.characteristic_coefficients(c)
    P = math.sqrt(d / a) if d > 0.0 else 0.0
    S2 = 2.0 * P - b / a
    S = math.sqrt(S2) if S2 >= 0.0 else math.nan
    return P, S


def rayleigh_function(material: Orthotropic, c) -> float:
    """The common denominator Delta(c) of the surface constants (a Rayleigh function).

    Delta(c) = P (C22 C11' - C12^2) - C33 c^2 C11', C11' = C11 - C33 c^2, P = eta1 eta2.
    Delta(0) = P (C11 C22 - C12^2) > 0; its first zero is the Rayleigh speed c_R.
    """
    P, _ = root_symmetric_functions(material, c)
    c2 = float(c) ** 2
    C11p = material.C11 - material.C33 * c2
    return P * (material.C22 * C11p - material.C12 ** 2) - material.C33 * c2 * C11p


def _scaled_rayleigh_function(material: Orthotropic, c: float) -> float:
    """Delta(c) / sqrt(C11'): same sign as Delta below the limiting speed, without the trivial
    zero of Delta at C11' = 0 (c^2 = C11/C33 < 1)."""
    c2 = c * c
    C11p = max(material.C11 - material.C33 * c2, 0.0)
    return (math.sqrt(max(1.0 - c2, 0.0) / material.C22) * (material.C22 * C11p - material.C12 ** 2)
            - material.C33 * c2 * math.sqrt(C11p))


def _eta_sum_squared(material: Orthotropic, c: float) -> float:
    a, b, d = material.characteristic_coefficients(c)
    return 2.0 * math.sqrt(max(d, 0.0) / a) - b / a


@functools.lru_cache(maxsize=256)
def limiting_speed(material: Orthotropic) -> float:
    """Lowest relative speed at which a decaying root reaches the imaginary axis.

    The smallest of 1 (shear wave, d = 0), sqrt(C11/C33) (longitudinal wave, d = 0) and the
    speed where eta1 + eta2 = 0 (a complex pair eta^2 becomes a negative double root).
    S^2 = 2P - b/a is positive at c = 0 for every positive definite stiffness and strictly
    decreasing in c, so that speed is found by bisection (:func:`_decreasing_root`).

    Parameters
    ----------
    material : Orthotropic

    Returns
    -------
    float
        The limiting relative speed c_L <= 1 (memoised per material).

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eq. (3.1) and Table 1 (the roots against c);
    a, b, d as in :meth:`contact.Orthotropic.characteristic_coefficients`.

    Examples
    --------
    For the paper's material the shear wave (c = 1) comes first.  For C11 = C22 = C33 = 1,
    C12 = 0.9: S^2 = 0.39 - 4 c^2, which vanishes at c^2 = 0.0975:

    >>> import math, contact
    >>> contact.limiting_speed(contact.zhou2014())
    1.0
    >>> m = contact.Orthotropic(1.0, 0.9, 1.0, 1.0)
    >>> round(contact.limiting_speed(m) / math.sqrt(0.0975), 12)
    1.0
    """
    c_max = min(1.0, math.sqrt(material.C11 / material.C33))
    if _eta_sum_squared(material, c_max) >= 0.0:
        return c_max
    return _decreasing_root(functools.partial(_eta_sum_squared, material), 0.0, c_max)


@functools.lru_cache(maxsize=256)
def rayleigh_speed(material: Orthotropic) -> float:
    """Relative Rayleigh speed c_R: the first zero of :func:`rayleigh_function`.

    Delta > 0 at c = 0 and Delta <= 0 at the limiting speed c_L <= 1 (a subsonic surface wave
    exists for an orthotropic half-space; also checked on 20000 random stiffnesses, each with
    a single sign change of Delta on (0, c_L)), so c_R is bracketed in (0, c_L] and found
    by bisection on Delta / sqrt(C11') to about one ulp (:func:`_decreasing_root`).
    Zhou et al. 2014 material: c_R = 0.9936147...; isotropic nu = 0.25: 0.9194017...
    The admissible speeds are 0 <= c < c_R (the paper, Sec. 6.1, gives [0, 1): see the
    documentation, Theory: errata of Zhou et al. 2014).

    Parameters
    ----------
    material : Orthotropic

    Returns
    -------
    float
        c_R, relative to the shear wave speed sqrt(C33 / rho) (memoised per material).

    References
    ----------
    Lord Rayleigh, "On waves propagated along the plane surface of an elastic solid",
    Proc. London Math. Soc. 17 (1885) 4-11 (isotropic: c_R^2 = 2 - 2/sqrt(3) at nu = 1/4).
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (4.4)-(4.6) (Delta is the common
    denominator of the surface constants).

    Examples
    --------
    >>> import math, contact
    >>> c_R = contact.rayleigh_speed(contact.Isotropic(1.0, 0.25))
    >>> round(c_R, 12), round(math.sqrt(2.0 - 2.0 / math.sqrt(3.0)), 12)
    (0.919401686762, 0.919401686762)
    >>> round(contact.rayleigh_speed(contact.zhou2014()), 6)
    0.993615
    """
    c_lim = limiting_speed(material)
    f = functools.partial(_scaled_rayleigh_function, material)
    if f(c_lim) >= 0.0:  # exceptional limiting wave that is itself traction free
        return c_lim
    return _decreasing_root(f, 0.0, c_lim)


def _decreasing_root(f, lo: float, hi: float) -> float:
    """Root of f with f(lo) > 0 >= f(hi), to about one ulp.

    Bisection down to two adjacent doubles (f > 0 at the left one, f <= 0 at the right
    one), returning the one with the smaller |f|; the rounding noise of f itself limits
    this to about one ulp.  Bisection rather than scipy.optimize.brentq: Brent's method
    stops a few ulp away and needs this bisection after it anyway, and importing
    scipy.optimize adds ~0.15 s to every start of the ``contact`` command (0.55 -> 0.40 s on
    a 2-core VM) and of every worker process that is not forked, for a root memoised per
    material that bisection finds in ~55 evaluations of f (~30 us).
    """
    a, b = float(lo), float(hi)
    while True:
        mid = 0.5 * (a + b)
        if not a < mid < b:
            break
        if f(mid) > 0.0:
            a = mid
        else:
            b = mid
    return float(a if abs(f(a)) < abs(f(b)) else b)


def _check_subrayleigh(material: Orthotropic, c) -> tuple[float, float]:
    c = check_speed(c)
    c_R = rayleigh_speed(material)
    if not c < c_R:
        raise SpeedError(
            f"relative speed c must be below the Rayleigh speed c_R = {c_R!r} of this material "
            f"(allowed: 0 <= c < c_R), got c = {c!r}")
    if c > NEAR_RAYLEIGH_FRACTION * c_R:
        warnings.warn(
            f"relative speed c = {c!r} is within 1% of the Rayleigh speed c_R = {c_R!r}: "
            f"the surface constants are valid but extremely sensitive to c",
            NearRayleighWarning, stacklevel=3)
    return c, c_R


def surface_constants(material: Orthotropic, c) -> SurfaceConstants:
    """Surface constants N11, N12, N21, N22 of Zhou et al. 2014, eqs. (4.4)-(4.6).

    Parameters
    ----------
    material : Orthotropic
    c : float
        Relative speed V / sqrt(C33 / rho), 0 <= c < c_R.

    Returns
    -------
    SurfaceConstants
        With C11' = C11 - C33 c^2, P = eta1 eta2 = sqrt((1 - c^2) C11' / C22),
        S = eta1 + eta2 = sqrt(2P - b/a) (see :func:`root_symmetric_functions`) and
        Delta = P (C22 C11' - C12^2) - C33 c^2 C11'::

            N11 = -S C11' / Delta
            N12 = (C11' - C12 P) / Delta
            N21 = -[C11' (C11 C22 - C12^2 - C12 C33 c^2) - C12 C22 C33 c^2 P] / (C22 Delta)
            N22 = -P S (C11 C22 - C12^2) / Delta

        for dv/dX = N12 q + N11 Hc[p] and sigma_XX = N21 p + N22 Hc[q].

    Raises
    ------
    SpeedError
        If c is not finite, negative, or not below the Rayleigh speed c_R.

    Warns
    -----
    NearRayleighWarning
        If c > 0.99 c_R.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (4.4)-(4.6), rewritten through
    P = eta1 eta2 and S = eta1 + eta2 (module docstring): the paper's form divides by
    eta1 - eta2 and by C12 + C33 and is singular at isotropy.

    Examples
    --------
    The isotropic static limit (plane strain, shear modulus G, Poisson's ratio nu):
    N11 = -(1 - nu)/G, N12 = (1 - 2 nu)/(2G), N21 = -1, N22 = -2; here G = 1, nu = 1/4:

    >>> import contact
    >>> sc = contact.surface_constants(contact.Isotropic(2.5, 0.25), 0.0)
    >>> [round(v, 12) for v in (sc.N11, sc.N12, sc.N21, sc.N22)]
    [-0.75, 0.25, -1.0, -2.0]
    """
    c, c_R = _check_subrayleigh(material, c)
    C11, C12, C22, C33 = material.C11, material.C12, material.C22, material.C33
    c2 = c * c
    C11p = C11 - C33 * c2
    P, S = root_symmetric_functions(material, c)
    det = C11 * C22 - C12 ** 2
    delta = P * (C22 * C11p - C12 ** 2) - C33 * c2 * C11p
    return SurfaceConstants(
        N11=-S * C11p / delta,
        N12=(C11p - C12 * P) / delta,
        N21=-(C11p * (det - C12 * C33 * c2) - C12 * C22 * C33 * c2 * P) / (C22 * delta),
        N22=-P * S * det / delta,
        c=c,
        eta_product=P,
        eta_sum=S,
        rayleigh_denominator=delta,
        rayleigh_speed=c_R,
    )
