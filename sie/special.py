"""Gamma-function ratios and Jacobi normalisation constants, to full precision.

``math.lgamma`` differences lose digits for large arguments (lgamma(1e5) is
about 1e6, so its last bit is worth 1e-10 relative in the ratio); the
quantities needed by Gauss-Jacobi weights are ratios Gamma(z+a)/Gamma(z) with
|a| = O(1), which we compute from the difference of Stirling series with
``log1p`` (absolute error ~1e-16 in the logarithm for any z).
"""
from __future__ import annotations

import functools
import math

import numpy as np

from ._jit import jit

__all__ = ["log_gamma_ratio", "gamma_ratio", "jacobi_moment", "jacobi_norm",
           "gauss_jacobi_constant", "jacobi_moment_shifted", "jacobi_end_values"]

# B_{2k} / (2k (2k-1)), k = 1..8 (Stirling series of ln Gamma; DLMF 5.11.1)
_STIRLING = (1.0 / 12.0, -1.0 / 360.0, 1.0 / 1260.0, -1.0 / 1680.0, 1.0 / 1188.0,
             -691.0 / 360360.0, 1.0 / 156.0, -3617.0 / 122400.0)
_SHIFT_TO = 20.0  # the 8-term series is accurate to < 1e-17 for z >= 20


def log_gamma_ratio(z: float, a: float) -> float:
    """``ln Gamma(z + a) - ln Gamma(z)`` for z > 0, z + a > 0, without cancellation.

    Uses upward recurrence to z >= 20 then the difference of Stirling series
    (DLMF 5.11.1), written so that the leading term is ``(z-1/2) log1p(a/z) +
    a ln(z+a) - a``.  Compiled (:func:`_log_gamma_ratio`): the Gauss-Jacobi constants
    and the Jacobi norms call it a dozen times for every new pair of exponents.
    """
    if not (z > 0.0 and z + a > 0.0):
        raise ValueError(f"log_gamma_ratio needs z > 0 and z + a > 0, got z={z!r}, a={a!r}")
    return _log_gamma_ratio(float(z), float(a))


@jit()
def _log_gamma_ratio(z, a):
    if a == 0.0:
        return 0.0
    shift = 0.0
    while z < _SHIFT_TO:
        # Gamma(z+a)/Gamma(z) = [Gamma(z+1+a)/Gamma(z+1)] * z/(z+a)
        shift -= math.log1p(a / z)
        z += 1.0
    za = z + a
    s = (z - 0.5) * math.log1p(a / z) + a * math.log(za) - a
    zi, zai = 1.0 / z, 1.0 / za
    zi2, zai2 = zi * zi, zai * zai
    pz, pza = zi, zai
    for c in _STIRLING:
        s += c * (pza - pz)
        pz *= zi2
        pza *= zai2
    return s + shift


def gamma_ratio(z: float, a: float) -> float:
    """``Gamma(z + a) / Gamma(z)`` (see :func:`log_gamma_ratio`)."""
    return math.exp(log_gamma_ratio(z, a))


def jacobi_moment(alpha: float, beta: float) -> float:
    """mu_0 = int_{-1}^{1} (1-x)^alpha (1+x)^beta dx = 2^{alpha+beta+1} B(alpha+1, beta+1).

    Parameters
    ----------
    alpha, beta : float
        Exponents of the weight, both > -1.

    Returns
    -------
    float
        The zeroth moment of the Jacobi weight.

    Raises
    ------
    ValueError
        alpha or beta <= -1 (the weight is not integrable).

    References
    ----------
    NIST DLMF 5.12.1 (the Beta integral); also Zhou, Lee & Jang, Arch. Mech. 66 (2014),
    eq. (5.5).

    Examples
    --------
    int (1 - x^2)^{1/2} dx = pi/2 and int (1 - x^2)^{-1/2} dx = pi:

    >>> import math, sie
    >>> round(sie.jacobi_moment(0.5, 0.5) / (math.pi / 2), 12)
    1.0
    >>> round(sie.jacobi_moment(-0.5, -0.5) / math.pi, 12)
    1.0
    """
    if not (alpha > -1.0 and beta > -1.0):
        raise ValueError(f"jacobi_moment needs alpha, beta > -1, got {alpha!r}, {beta!r}")
    return _jacobi_moment(float(alpha), float(beta))


@jit()
def _jacobi_moment(alpha, beta):
    # B(a+1, b+1) = Gamma(a+1) Gamma(b+1) / Gamma(a+b+2); use the ratio form for accuracy
    return 2.0 ** (alpha + beta + 1.0) * math.gamma(alpha + 1.0) * math.exp(
        -_log_gamma_ratio(beta + 1.0, alpha + 1.0))


def jacobi_norm(k: int, alpha: float, beta: float) -> float:
    """h_k = int w P_k^{(alpha,beta)}^2 (DLMF 18.3, Table 18.3.1)."""
    if not (alpha > -1.0 and beta > -1.0) or k < 0:
        raise ValueError(f"jacobi_norm needs k >= 0 and alpha, beta > -1, got {k!r}, "
                         f"{alpha!r}, {beta!r}")
    return _jacobi_norm(int(k), float(alpha), float(beta))


@jit()
def _jacobi_norm(k, alpha, beta):
    if k == 0:
        return _jacobi_moment(alpha, beta)
    # h_k = 2^{a+b+1}/(2k+a+b+1) * Gamma(k+a+1)Gamma(k+b+1)/(Gamma(k+a+b+1) k!)
    return (2.0 ** (alpha + beta + 1.0) / (2 * k + alpha + beta + 1.0)
            * math.exp(_log_gamma_ratio(k + 1.0, alpha)
                       + _log_gamma_ratio(k + alpha + beta + 1.0, -alpha)))


def gauss_jacobi_constant(n: int, alpha: float, beta: float) -> float:
    """C_n with Gauss-Jacobi weights w_k = C_n / ((1-x_k^2) P_n'(x_k)^2).

    C_n = 2^{a+b+1} Gamma(n+a+1) Gamma(n+b+1) / (Gamma(n+a+b+1) n!)
    (Szegő 1975, eq. 15.3.5; DLMF 18.2).
    """
    return 2.0 ** (alpha + beta + 1.0) * math.exp(
        log_gamma_ratio(n + 1.0, alpha) + log_gamma_ratio(n + alpha + beta + 1.0, -alpha))


@functools.lru_cache(maxsize=1024)
def jacobi_moment_shifted(alpha_p1: float, beta_p1: float) -> float:
    """mu_0 = int (1-x)^alpha (1+x)^beta dx from the shifted exponents alpha+1, beta+1.

    Same as :func:`jacobi_moment`, but takes alpha+1 and beta+1 as given: when an
    exponent is within ~1e-8 of -1, alpha+1 recomputed from a rounded alpha has a
    relative error eps/(alpha+1) (3.5e-8 at alpha = -1 + 3e-9), and mu_0 ~ 1/(alpha+1)
    inherits it.  The SIE exponents carry alpha+1 exactly (:class:`sie.Exponents`).
    """
    s = alpha_p1 + beta_p1
    return 2.0 ** (s - 1.0) * math.gamma(alpha_p1) * math.exp(-log_gamma_ratio(beta_p1, alpha_p1))


def jacobi_end_values(n: int, e_p1: float, end: int):
    """P_k^{(a,b)}(end), k = 0..n-1, from the exact shifted exponent of that end.

    P_k(+1) = binom(k+a, k) = prod_{j=1}^{k} (j - 1 + (a+1))/j  (DLMF 18.6.1), with
    ``e_p1`` = a + 1; P_k(-1) = (-1)^k binom(k+b, k) with ``e_p1`` = b + 1.
    Relative accuracy stays ~k eps however small e_p1 is (P_k(+1) ~ (a+1)/k then).
    """
    j = np.arange(1, n, dtype=float)
    vals = np.concatenate([[1.0], np.cumprod((j - 1.0 + e_p1) / j)])
    if end < 0:
        vals[1::2] *= -1.0
    return vals
