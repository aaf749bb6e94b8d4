"""Cauchy transforms and logarithmic potentials of Jacobi series, anywhere.

    F_k(z) = (1/pi) int_{-1}^{1} w(t) P_k^{(alpha,beta)}(t) / (t - z) dt,
    w(t) = (1-t)^alpha (1+t)^beta,   alpha + beta = m in {-1, 0, 1}.

Off [-1, 1] F_k is Szegő's Jacobi function of the second kind up to a factor
(Szegő 1975, sec. 4.61: F_k(z) = -(2/pi) (z-1)^alpha (z+1)^beta Q_k(z)).  For real x
in (-1, 1) the principal value is the mean of the one-sided limits, which Plemelj's
formulae give as F_k(x +- i0) = H[w P_k](x) +- i w(x) P_k(x).

Method (per point z):

* **three-term recurrence.**  Because int w P_k = 0 for k >= 1,
      F_1 = P_1(z) F_0 + A_0 mu_0 / pi,
      F_{k+1} = (A_k z + B_k) F_k - C_k F_{k-1}    (k >= 1),
  the recurrence of P_k (DLMF 18.9.1-2).  F_k is its *minimal* solution off the
  interval (|F_k| ~ |rho|^-k, |P_k| ~ |rho|^k, rho = z + sqrt(z^2 - 1) with |rho| > 1),
  so (Gautschi, SIAM Rev. 9 (1967) 24):
* **near the interval** (|rho|^n <= 30 and |rho| <= 2) the recurrence
  is run forward from F_0 in closed form: contamination by the dominant solution grows
  like |rho|^{2k}, which stays below the rounding of the result there, and inside the
  interval (|rho| = 1) both solutions oscillate and forward is stable;
* **away from it** Miller's backward recurrence from y_K = 0, y_{K-1} = 1, with K chosen
  so that |rho|^{-2(K-n)} < 1e-17, gives F_k up to one factor; F_0 itself follows from
  F_1 = P_1 F_0 + A_0 mu_0 / pi as F_0 = A_0 mu_0 y_0 / (pi (y_1 - P_1(z) y_0)), which
  involves no closed form and no cancellation far away.

F_0 in closed form.  With G(z) = (z-1)^alpha (z+1)^beta (principal powers, cut on
[-1, 1]) and its polynomial part at infinity 2^m P_m^{(-alpha,-beta)},
F_0 = [G(z) - 2^m P_m^{(-alpha,-beta)}(z)] / sin(pi alpha) (Tricomi 1957, sec. 4.3;
Erdogan, Gupta & Cook 1973).  Written in L = log((z-1)/(z+1)) with expm1 it loses no
digits when alpha is near an integer (sin(pi alpha) -> 0, |a/b| -> infinity):
    m = -1:  F_0 = e^{alpha L} / ((z+1) sin(pi alpha)),
    m =  0:  F_0 = expm1(alpha L) / sin(pi alpha),
    m =  1:  F_0 = [(z+1) expm1(alpha L) + 2 alpha] / sin(pi alpha)             (alpha <= 1/2)
               = [(z-1) expm1(-(1-alpha) L) - 2 (1-alpha)] / sin(pi alpha)   (alpha > 1/2).

Logarithmic potential.  d/du [(1-u)^{alpha+1} (1+u)^{beta+1} P_{k-1}^{(alpha+1,beta+1)}]
= -2k w P_k (DLMF 18.9.16), and that bracket vanishes at both ends, so integrating by
parts
    (1/pi) int w P_k log|x - u| du = (1/(2k)) (1/pi) int w (1-u^2) P_{k-1}^{(alpha+1,beta+1)}/(u - x) du,
the Cauchy transform (above) of P_{k-1}^{(alpha+1,beta+1)} against the weight with both
exponents raised by one, which is finite at the ends; its F_0 near the interval follows from
that of w (see :func:`_f0_shifted`).
The k = 0 term is L_0(x) = (1/pi) int w log|x - u| du:
    L_0(1) = (mu_0/pi) (log 2 + psi(alpha+1) - psi(alpha+beta+2))     (d mu_0 / d alpha),
    L_0(x) = L_0(1) + int_x^1 H[w],   |x| < 1,
    L_0(x) = L_0(1) - int_1^x F_0,     1 < x < 2,
    L_0(x) = (1/pi) [mu_0 log|x| - sum_{j>=1} M_j / (j x^j)],   |x| >= 2 (M_j = int w u^j),
and x < -1 by the reflection u -> -u (alpha and beta swap).
"""
from __future__ import annotations

import cmath
import functools
import math
from dataclasses import dataclass

import numpy as np
from scipy import special as sp

from ._jit import jit
from .gaussjacobi import gauss_jacobi_cached
from .special import jacobi_moment_shifted

__all__ = ["Weight", "cauchy_basis", "cauchy_series", "log_potential_series", "jacobi_cauchy"]



def _sinpi(x: float) -> float:
    """sin(pi x) to full relative precision near an integer: x - round(x) is exact
    (Sterbenz), while pi * x rounds with an absolute error that sin(pi x) ~ pi (x - r)
    would feel relatively."""
    r = round(x)
    return (-1.0) ** (r % 2) * math.sin(math.pi * (x - r))


@dataclass(frozen=True)
class Weight:
    """w(t) = (1-t)^alpha (1+t)^beta with alpha + beta = m in {-1, 0, 1}.

    ``alpha_p1``, ``beta_p1`` (= alpha + 1, beta + 1) and ``alpha_m1`` (= 1 - alpha) are
    carried exactly (an exponent within 1e-9 of an integer loses nothing), and
    ``sin`` = sin(pi alpha) to full relative precision.
    """
    alpha: float
    beta: float
    alpha_p1: float
    beta_p1: float
    alpha_m1: float
    sin: float

    @property
    def m(self) -> int:
        return int(round(self.alpha + self.beta))

    @property
    def mu0(self) -> float:
        return jacobi_moment_shifted(self.alpha_p1, self.beta_p1)

    @classmethod
    def from_exponents(cls, e) -> "Weight":
        """From :class:`sie.Exponents` (exact complements)."""
        return cls(e.alpha, e.beta, e.alpha_p1, e.beta_p1, e.alpha_m1, e.sin)

    @classmethod
    def plain(cls, alpha: float, beta: float) -> "Weight":
        """From two floats (complements formed in double)."""
        m = alpha + beta
        if abs(m - round(m)) > 1e-12 or round(m) not in (-1, 0, 1):
            raise ValueError(f"the Cauchy transform in closed form needs alpha + beta in "
                             f"{{-1, 0, 1}}, got alpha + beta = {m!r}")
        return cls(float(alpha), float(beta), 1.0 + alpha, 1.0 + beta, 1.0 - alpha,
                   _sinpi(float(alpha)))

    def reflected(self) -> "Weight":
        """The weight of u -> -u: (1+t)^alpha (1-t)^beta."""
        m = self.m
        # sin(pi beta) = sin(pi (m - alpha)) = -cos(pi m) sin(pi alpha)
        return Weight(self.beta, self.alpha, self.beta_p1, self.alpha_p1,
                      1.0 - self.beta, -((-1.0) ** m) * self.sin)


# --------------------------------------------------------------------------
# F_0 in closed form (near the interval)
# --------------------------------------------------------------------------
def _expm1c(w):
    """expm1 of complex w without cancellation: expm1(x) cos y - 2 sin^2(y/2) + i e^x sin y."""
    x, y = w.real, w.imag
    s = np.sin(0.5 * y)
    return (np.expm1(x) * np.cos(y) - 2.0 * s * s) + 1j * (np.exp(x) * np.sin(y))


def _log_ratio(zm1, zp1):
    """L = log((z-1)/(z+1)), principal branch (cut on [-1, 1]); for real z = x in
    (-1, 1) the upper limit log((1-x)/(1+x)) + i pi.  From z - 1 and z + 1 as given (the
    callers form them from the real coordinate, which keeps the distance to a nearby end
    to full relative precision)."""
    if zm1.dtype.kind != "c":
        out = np.empty(zm1.shape, dtype=complex)
        inside = (zm1 < 0.0) & (zp1 > 0.0)
        out[inside] = (np.log(-zm1[inside]) - np.log(zp1[inside])) + 1j * math.pi
        out[~inside] = np.log(zm1[~inside] / zp1[~inside])
        return out
    return np.log(zm1 / zp1)


def _end_offsets(z, ends):
    """(z - 1, z + 1): given, or formed from z."""
    if ends is not None:
        return ends
    return z - 1.0, z + 1.0


def f0_closed(wt: Weight, z, ends=None):
    """F_0(z) for complex z off [-1, 1] (or real x: the upper limit F_0(x + i0) inside).
    ``ends``: (z - 1, z + 1) computed more accurately than from z (see :func:`_log_ratio`)."""
    zm1, zp1 = _end_offsets(z, ends)
    L = _log_ratio(zm1, zp1)
    m, a = wt.m, wt.alpha
    if m == -1:
        num = np.exp(a * L) / zp1
    elif m == 0:
        num = _expm1c(a * L)
    elif a <= 0.5:
        num = zp1 * _expm1c(a * L) + 2.0 * a
    else:
        num = zm1 * _expm1c(-wt.alpha_m1 * L) - 2.0 * wt.alpha_m1
    return num / wt.sin


# --------------------------------------------------------------------------
# the recurrence (one kernel: forward near, backward Miller far)
# --------------------------------------------------------------------------
@jit()
def _cauchy_kernel(n, a, b, mu0, zr, zi, f0r, f0i, cand, c, V, out):
    """F_k(z_i), k < n (see module docstring), into V[i, k] when V has rows, else
    out[i] = sum_k c_k F_k(z_i).

    Near the interval (|rho|^n <= _NEAR_GROWTH and |rho| <= 2; ``cand[i]`` marks the points
    whose closed-form F_0 was supplied, a superset) the recurrence runs forward.  Elsewhere
    Miller's backward recurrence y_{k-1} = ((A_k z + B_k) y_k - y_{k+1}) / C_k from
    y_K = 0, y_{K-1} = 1, |rho|^{-2(K-n)} < 1e-17, rescaled against overflow, and normalised by
    F_0 = A_0 mu_0 y_0 / (pi (y_1 - P_1(z) y_0)) (from F_1 = P_1 F_0 + A_0 mu_0 / pi)."""
    m = zr.shape[0]
    store = V.shape[0] > 0
    ap1 = a + 1.0
    abp2 = ap1 + (b + 1.0)
    A0 = 0.5 * abp2
    B0 = ap1 - A0
    c0 = A0 * mu0 / math.pi
    lim_near = math.log(30.0)
    # first pass: the start of the backward recurrence per point (0: forward)
    K = np.zeros(m, dtype=np.int64)
    kmax = n
    for i in range(m):
        z = complex(zr[i], zi[i])
        rho = abs(z + cmath.sqrt(z - 1.0) * cmath.sqrt(z + 1.0))
        lr = math.log(max(rho, 1.0 / rho))
        if cand[i] and n * lr <= lim_near and lr <= math.log(2.0):
            K[i] = 0
        else:
            K[i] = n + int(math.ceil(39.2 / (2.0 * lr))) + 2
            if K[i] > kmax:
                kmax = K[i]
    # recurrence coefficients P_{k+1} = (A_k x + B_k) P_k - C_k P_{k-1}, k >= 1 (DLMF 18.9.2)
    Ak = np.zeros(kmax + 1)
    Bk = np.zeros(kmax + 1)
    Ck = np.zeros(kmax + 1)
    iC = np.zeros(kmax + 1)
    for k in range(1, kmax + 1):
        s = 2.0 * (k - 1) + abp2
        d = 2.0 * (k + 1) * ((k - 1) + abp2) * s
        Ak[k] = (s + 1.0) * (s + 2.0) * s / d
        Bk[k] = (s + 1.0) * (a * a - b * b) / d
        Ck[k] = 2.0 * (k + a) * (k + b) * (s + 2.0) / d
        iC[k] = 1.0 / Ck[k]
    for i in range(m):
        z = complex(zr[i], zi[i])
        if K[i] == 0:
            f_prev = complex(f0r[i], f0i[i])
            acc = c[0] * f_prev if not store else 0j
            if store:
                V[i, 0] = f_prev
            if n > 1:
                f = (A0 * z + B0) * f_prev + c0
                if store:
                    V[i, 1] = f
                else:
                    acc += c[1] * f
                for k in range(1, n - 1):
                    f_next = (Ak[k] * z + Bk[k]) * f - Ck[k] * f_prev
                    if store:
                        V[i, k + 1] = f_next
                    else:
                        acc += c[k + 1] * f_next
                    f_prev = f
                    f = f_next
            out[i] = acc
        else:
            y_next = 0j          # y_{k+1}
            y = 1.0 + 0j         # y_k, k = K - 1
            acc = 0j
            for k in range(K[i] - 1, 0, -1):
                if k < n:
                    if store:
                        V[i, k] = y
                    else:
                        acc += c[k] * y
                y_prev = ((Ak[k] * z + Bk[k]) * y - y_next) * iC[k]
                y_next = y
                y = y_prev
                if abs(y.real) + abs(y.imag) > 1e250:       # rescale: only ratios matter
                    y *= 1e-250
                    y_next *= 1e-250
                    acc *= 1e-250
                    if store:
                        for j in range(k, n):
                            V[i, j] *= 1e-250
            # now y = y_0, y_next = y_1
            if store:
                V[i, 0] = y
            else:
                acc += c[0] * y
            scale = c0 / (y_next - (A0 * z + B0) * y)     # F_0 / y_0
            if store:
                for k in range(n):
                    V[i, k] *= scale
            out[i] = acc * scale
    return out


_NEAR_BOX = (1.3, 0.8)    # |rho| <= 2 lies inside |Re z| < 1.25, |Im z| < 0.75


def _near_f0(wt, z, shifted, ends):
    """Candidates for the forward recurrence (a box around the interval) and F_0 there."""
    zc = z.astype(complex)
    cand = (np.abs(zc.real) < _NEAR_BOX[0]) & (np.abs(zc.imag) < _NEAR_BOX[1])
    f0 = np.zeros(z.shape, dtype=complex)
    if np.any(cand):
        e = None if ends is None else (ends[0][cand], ends[1][cand])
        f0[cand] = _f0_shifted(wt, z[cand], e) if shifted else f0_closed(wt, z[cand], e)
    return zc, cand, f0


def _kernel_args(wt, shifted):
    if shifted:
        return (float(wt.alpha_p1), float(wt.beta_p1),
                float(jacobi_moment_shifted(wt.alpha_p1 + 1.0, wt.beta_p1 + 1.0)))
    return float(wt.alpha), float(wt.beta), float(wt.mu0)


def _f0_shifted(wt: Weight, z, ends=None):
    """F~_0(z) = (1/pi) int (1-u)^{alpha+1} (1+u)^{beta+1} / (u - z) du near the interval:
    1 - u^2 = (1 - z^2) - (u - z)(u + z) gives F~_0 = (1 - z^2) F_0 - (M_1 + z mu_0)/pi,
    M_1 = int w u = mu_0 (beta - alpha)/(alpha + beta + 2); finite at the ends
    ((1 - z^2) F_0 -> 0 there since alpha, beta > -1)."""
    zc = z.astype(complex)
    zm1, zp1 = _end_offsets(z, ends)
    at_end = (zm1 == 0.0) | (zp1 == 0.0)
    f0 = np.zeros(z.shape, dtype=complex)
    if np.any(~at_end):
        f0[~at_end] = f0_closed(wt, z[~at_end], (zm1[~at_end], zp1[~at_end]))
    mu0 = wt.mu0
    m1 = mu0 * (wt.beta_p1 - wt.alpha_p1) / (wt.alpha_p1 + wt.beta_p1)
    return -(zm1 * zp1) * f0 - (m1 + zc * mu0) / math.pi


def cauchy_basis(n, wt: Weight, z, shifted=False, ends=None):
    """Matrix V[i, k] = F_k(z_i), k < n, complex (real x inside: the upper limit
    H[w P_k](x) + i w P_k(x)).  z: 1-d real or complex array off the ends +-1.

    ``shifted``: the same for the weight (1-u)^{alpha+1}(1+u)^{beta+1} and its Jacobi
    polynomials P_k^{(alpha+1,beta+1)} (finite at the ends too).  ``ends``: z - 1 and z + 1
    when the caller has them more accurately than z itself."""
    z = np.asarray(z)
    zc, cand, f0 = _near_f0(wt, z, shifted, ends)
    V = np.empty((z.size, n), dtype=complex)
    if z.size and n:
        _cauchy_kernel(int(n), *_kernel_args(wt, shifted), zc.real.copy(), zc.imag.copy(),
                       f0.real.copy(), f0.imag.copy(), cand, np.zeros(1), V,
                       np.empty(z.size, dtype=complex))
    return V


def cauchy_series(c, wt: Weight, z, shifted=False, ends=None):
    """sum_k c_k F_k(z) for a 1-d array z (memory O(1) per point)."""
    c = np.ascontiguousarray(c, dtype=float)
    z = np.asarray(z)
    out = np.zeros(z.shape, dtype=complex)
    if c.size == 0 or z.size == 0:
        return out
    zc, cand, f0 = _near_f0(wt, z, shifted, ends)
    return _cauchy_kernel(int(c.size), *_kernel_args(wt, shifted), zc.real.copy(),
                          zc.imag.copy(), f0.real.copy(), f0.imag.copy(), cand, c,
                          np.empty((0, c.size), dtype=complex), out)


def jacobi_cauchy(c, alpha, beta, z):
    """(1/pi) int_{-1}^{1} (1-t)^alpha (1+t)^beta sum_k c_k P_k^{(alpha,beta)}(t) / (t - z) dt.

    Parameters
    ----------
    c : array_like
        Coefficients in scipy's normalisation of P_k^{(alpha,beta)}.
    alpha, beta : float
        Exponents > -1 with alpha + beta in {-1, 0, 1} (the weights of Cauchy singular
        integral equations; Muskhelishvili 1953, ch. 10).
    z : array_like, real or complex
        Real z: the principal value inside (-1, 1), the ordinary integral outside; complex
        z: the integral, off [-1, 1].

    Returns
    -------
    ndarray, real for real z and complex for complex z.

    Raises
    ------
    EvaluationPointError
        z = +-1, a complex z on [-1, 1], a non-finite z.
    InvalidExponentError
        alpha or beta <= -1, or alpha + beta not in {-1, 0, 1}.
    """
    from .errors import InvalidExponentError, check_exponent
    alpha = check_exponent("alpha", alpha)
    beta = check_exponent("beta", beta)
    try:
        wt = Weight.plain(alpha, beta)
    except ValueError as exc:
        raise InvalidExponentError(str(exc)) from None
    z, cplx = evaluation_points(z, ((-1.0, 1.0),), "z")
    out = cauchy_series(np.asarray(c, dtype=float).ravel(), wt, z.ravel())
    return (out if cplx else out.real).reshape(z.shape)


def evaluation_points(z, intervals, name="z"):
    """z as a float or complex array, checked: finite, not at an end, and a complex z not
    on the intervals (the transform jumps across them: give the side by Im z != 0, or a
    real z for the principal value).  Returns (array, is_complex)."""
    from .errors import EvaluationPointError
    z = np.asarray(z)
    if z.dtype.kind not in "biufc":
        raise EvaluationPointError(f"{name} must be real or complex numbers, got dtype {z.dtype}")
    cplx = z.dtype.kind == "c"
    z = z.astype(complex if cplx else float)
    if not np.all(np.isfinite(z)):
        raise EvaluationPointError(f"{name} must be finite")
    x = z.real
    for c, d in intervals:
        if np.any(((x == c) | (x == d)) & (z.imag == 0 if cplx else True)):
            raise EvaluationPointError(
                f"{name} lies at an end of the interval [{c!r}, {d!r}], where the Cauchy "
                "transform is infinite or undefined")
        if cplx and np.any((z.imag == 0) & (x > c) & (x < d)):
            raise EvaluationPointError(
                f"a complex {name} with Im {name} == 0 lies on the interval [{c!r}, {d!r}], "
                "where the transform jumps: pass it as a real number for the principal value, "
                "or give it a nonzero imaginary part for the one-sided value")
    return z, cplx


# --------------------------------------------------------------------------
# logarithmic potential
# --------------------------------------------------------------------------
@functools.lru_cache(maxsize=64)
def _moments(wt: Weight, count: int):
    """M_j = int w u^j, j < count, exact (Gauss rule with end-mass correction)."""
    from .quadrature import WeightedRule
    rule = WeightedRule.build(count // 2 + 2, wt.alpha, wt.beta, wt.alpha_p1, wt.beta_p1)
    j = np.arange(count)
    M = (rule.x[None, :] ** j[:, None]) @ rule.omega
    if rule.end:
        M = M + rule.corr * float(rule.end) ** j
    M.flags.writeable = False
    return M


def _l0_at_one(wt: Weight):
    """L_0(1) = (1/pi) int w log(1 - u) du = (mu_0/pi)(log 2 + psi(alpha+1) - psi(alpha+beta+2))."""
    return wt.mu0 / math.pi * (math.log(2.0) + sp.digamma(wt.alpha_p1)
                               - sp.digamma(wt.alpha_p1 + wt.beta_p1))


def _poly_part_integral(wt: Weight, lo, hi):
    """int_lo^hi 2^m P_m^{(-alpha,-beta)}(x) dx (m = -1: 0; 0: 1; 1: (x+1) - 2 alpha)."""
    m = wt.m
    if m == -1:
        return np.zeros(np.shape(lo))
    if m == 0:
        return hi - lo
    return 0.5 * ((hi + 1.0) ** 2 - (lo + 1.0) ** 2) - 2.0 * wt.alpha * (hi - lo)


def _l0_right(wt: Weight, x):
    """L_0 at x > -1 (inside or right of the interval)."""
    out = np.empty(x.shape)
    l1 = _l0_at_one(wt)
    inside = x < 1.0
    if np.any(inside):
        xi = x[inside]
        # int_x^1 w = mu_0 I_{(1-x)/2}(alpha+1, beta+1)
        iw = wt.mu0 * sp.betainc(wt.alpha_p1, wt.beta_p1, 0.5 * (1.0 - xi))
        out[inside] = l1 + (math.cos(math.pi * wt.alpha) * iw
                            - _poly_part_integral(wt, xi, 1.0)) / wt.sin
    mid = (x >= 1.0) & (x < 2.0)
    if np.any(mid):
        xm = x[mid]
        # int_1^x (xi-1)^alpha (xi+1)^beta: xi = 1 + (x-1)(1+tau)/2, Gauss-Jacobi (0, alpha)
        tau, wtau = gauss_jacobi_cached(30, 0.0, wt.alpha)
        half = 0.5 * (xm - 1.0)
        xi = 1.0 + half[:, None] * (1.0 + tau[None, :])
        g = ((xi + 1.0) ** wt.beta) @ wtau
        ig = half ** wt.alpha_p1 * g
        out[mid] = l1 - (ig - _poly_part_integral(wt, 1.0, xm)) / wt.sin
    far = x >= 2.0
    if np.any(far):
        out[far] = _l0_far(wt, x[far])
    return out


def _l0_far(wt: Weight, x):
    """(1/pi) [mu_0 log|x| - sum_{j>=1} M_j / (j x^j)], |x| >= 2 (60 terms: 2^-60 < 1e-18)."""
    M = _moments(wt, 61)
    j = np.arange(1, 61)
    y = 1.0 / x
    series = (y[:, None] ** j[None, :]) @ (M[1:] / j)
    return (wt.mu0 * np.log(np.abs(x)) - series) / math.pi


def l0(wt: Weight, x):
    """L_0(x) = (1/pi) int w(u) log|x - u| du at real x (any x; finite at the ends)."""
    x = np.asarray(x, dtype=float)
    out = np.empty(x.shape)
    right = x >= -1.0
    if np.any(right):
        out[right] = _l0_right(wt, x[right])
    left = ~right
    if np.any(left):
        xl = x[left]
        far = xl <= -2.0
        vals = np.empty(xl.shape)
        if np.any(far):
            vals[far] = _l0_far(wt, xl[far])
        if np.any(~far):
            vals[~far] = _l0_right(wt.reflected(), -xl[~far])
        out[left] = vals
    return out


def log_potential_series(c, wt: Weight, x, ends=None):
    """(1/pi) int w(u) sum_k c_k P_k(u) log|x - u| du at real x (1-d array)."""
    c = np.asarray(c, dtype=float)
    out = c[0] * l0(wt, x) if c.size else np.zeros(x.shape)
    if c.size > 1:
        k = np.arange(1, c.size, dtype=float)
        out = out + cauchy_series(c[1:] / (2.0 * k), wt, x, shifted=True, ends=ends).real
    return out
