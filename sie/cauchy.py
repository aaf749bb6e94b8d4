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
* **near the interval** (|rho| <= 2, and |rho|^k |c_k| <= 30 max|c| for a series
  sum c_k F_k, |rho|^n <= 30 for the basis itself) the recurrence is run forward from F_0 in
  closed form: a rounding error in F_0 excites the dominant solution, which grows like
  |rho|^k and stays below 30 eps |F_0| there (30 eps max|c| |F_0| in a series; relative to a
  small F_k itself it can be larger); inside the interval (|rho| = 1) both solutions
  oscillate and forward is stable;
* **away from it** Miller's backward recurrence from y_K = 0, y_{K-1} = 1, with K chosen
  so that |rho|^{-2(K-n)} < 1e-17, gives F_k up to one factor; F_0 itself follows from
  F_1 = P_1 F_0 + A_0 mu_0 / pi as F_0 = A_0 mu_0 y_0 / (pi (y_1 - P_1(z) y_0)), which
  involves no closed form and no cancellation far away.

The compiled kernels are in :mod:`sie.cauchy_kernels` (a series runs eight points at a time,
lane-wise, so that their independent recurrences overlap).

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

import functools
import math
from dataclasses import dataclass

import numpy as np
from scipy import special as sp

from ._jit import jit
from .cauchy_kernels import basis_kernel, f0_points, series_forward_limit, series_kernel
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

    @functools.cached_property
    def mu0(self) -> float:
        """int w (exact; computed once per weight)."""
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


def f0_parameters(wt: Weight, shifted=False):
    """Parameters of the closed form of F_0 for the compiled kernels
    (:func:`sie.cauchy_kernels._f0`): m, alpha, 1 - alpha, sin(pi alpha), shifted, for
    the shifted weight M_1 = int w u = mu_0 (beta - alpha)/(alpha + beta + 2) and mu_0, and
    1 + alpha."""
    return np.array(f0_parameter_row(wt.m, wt.alpha, wt.alpha_m1, wt.sin, wt.alpha_p1,
                                     wt.beta_p1, wt.mu0, shifted))


def f0_parameter_row(m, alpha, alpha_m1, sin, alpha_p1, beta_p1, mu0, shifted=False):
    """:func:`f0_parameters` from the weight's numbers (a row per weight of a batch)."""
    m1 = mu0 * (beta_p1 - alpha_p1) / (alpha_p1 + beta_p1)
    return [float(m), alpha, alpha_m1, sin, float(shifted), m1, mu0, alpha_p1]


def _writeable(x, dtype=float):
    """C-contiguous and writeable: one numba specialisation per kernel (a read-only array is
    a different numba type and would compile again)."""
    x = np.ascontiguousarray(x, dtype=dtype)
    return x if x.flags.writeable else x.copy()


def _kernel_points(z, ends):
    """z, z - 1 and z + 1 as complex arrays for the kernels."""
    zm1, zp1 = _end_offsets(z, ends)
    return _writeable(z, complex), _writeable(zm1, complex), _writeable(zp1, complex)


def f0_closed(wt: Weight, z, ends=None, shifted=False):
    """F_0(z) for complex z off [-1, 1] (or real x: the upper limit F_0(x + i0) inside), in
    closed form (module docstring).  ``ends``: (z - 1, z + 1) computed more accurately than
    from z (see :func:`_log_ratio`).  ``shifted``: F~_0 of the weight with both exponents
    raised by one, (1 - z^2) F_0 - (M_1 + z mu_0)/pi, finite at the ends."""
    z = np.asarray(z)
    zc, zm1, zp1 = _kernel_points(z.ravel(), None if ends is None else
                                  (np.ravel(ends[0]), np.ravel(ends[1])))
    out = f0_points(zc, zm1, zp1, f0_parameters(wt, shifted), np.empty(zc.size, dtype=complex))
    return out.reshape(z.shape)


def _kernel_args(wt, shifted, lr_max):
    if shifted:
        return (float(wt.alpha_p1), float(wt.beta_p1),
                float(jacobi_moment_shifted(wt.alpha_p1 + 1.0, wt.beta_p1 + 1.0)), lr_max)
    return float(wt.alpha), float(wt.beta), float(wt.mu0), lr_max


_FORWARD_GROWTH = 30.0     # the most the forward recurrence may amplify rounding


def _forward_limit(n, c=None):
    """The largest log|rho| where the forward recurrence is used (capped at log 2).

    Forward from F_0, a rounding error eps |F_0| excites the dominant solution, ~|rho|^k in
    F_k.  For the basis (``c`` None) every F_k, k < n, must keep it below 30 eps |F_0|:
    |rho|^n <= 30.  For a series sum_k c_k F_k only the sum must:
    |c_k| |rho|^k <= 30 max|c| for every k, which for a resolved series (|c_k| decaying
    geometrically at the rate of phi's Bernstein ellipse) allows the whole box around the
    interval, where Miller's recurrence would need ~20/log|rho| extra steps per point."""
    cap = math.log(2.0)
    if c is None:
        return min(cap, math.log(_FORWARD_GROWTH) / max(n, 1))
    return float(series_forward_limit(c, math.log(_FORWARD_GROWTH), cap))


def cauchy_basis(n, wt: Weight, z, shifted=False, ends=None):
    """Matrix V[i, k] = F_k(z_i), k < n, complex (real x inside: the upper limit
    H[w P_k](x) + i w P_k(x)).  z: 1-d real or complex array off the ends +-1.

    ``shifted``: the same for the weight (1-u)^{alpha+1}(1+u)^{beta+1} and its Jacobi
    polynomials P_k^{(alpha+1,beta+1)} (finite at the ends too).  ``ends``: z - 1 and z + 1
    when the caller has them more accurately than z itself."""
    z = np.asarray(z)
    V = np.empty((z.size, n), dtype=complex)
    if z.size and n:
        basis_kernel(int(n), *_kernel_args(wt, shifted, _forward_limit(n)),
                     *_kernel_points(z, ends), f0_parameters(wt, shifted), V)
    return V


def cauchy_series(c, wt: Weight, z, shifted=False, ends=None):
    """sum_k c_k F_k(z) for a 1-d array z (memory O(1) per point)."""
    c = _writeable(c)
    z = np.asarray(z)
    out = np.zeros(z.shape, dtype=complex)
    if c.size == 0 or z.size == 0:
        return out
    nz = np.flatnonzero(c)
    c = c[:nz[-1] + 1] if nz.size else c[:1]     # trailing zeros (a chopped series) cost nothing
    return series_kernel(*_kernel_args(wt, shifted, _forward_limit(c.size, c)),
                         *_kernel_points(z, ends), f0_parameters(wt, shifted), c, out)


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

    Notes
    -----
    A three-term recurrence (DLMF 18.9.1-2) from F_0 in closed form near the interval, and
    Miller's backward recurrence away from it, where F_k is the minimal solution
    (Gautschi, SIAM Rev. 9 (1967) 24); see the module docstring.

    References
    ----------
    G. Szegő, Orthogonal Polynomials, 4th ed., AMS (1975), sec. 4.61 (Jacobi functions of
    the second kind).
    F. G. Tricomi, Integral Equations (1957), sec. 4.3; Erdogan, Gupta & Cook (1973), ch. 7
    (F_0 in closed form).
    N. I. Muskhelishvili, Singular Integral Equations (1953) (Plemelj formulae).

    Examples
    --------
    The Chebyshev weight (alpha = beta = -1/2): (1/pi) int (1 - t^2)^{-1/2} / (t - z) dt is
    0 (principal value) inside (-1, 1) and -1/sqrt(z^2 - 1) off it:

    >>> import numpy as np, sie
    >>> F = sie.jacobi_cauchy([1.0], -0.5, -0.5, [0.3, 2.0])
    >>> bool(abs(F[0]) < 1e-15), round(float(F[1]) * 3.0 ** 0.5, 12)
    (True, -1.0)
    >>> z = 2.0 + 1.0j
    >>> F = sie.jacobi_cauchy([1.0], -0.5, -0.5, z)
    >>> bool(abs(F + 1.0 / np.sqrt(z * z - 1.0)) < 1e-15)
    True
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


def limit_points(x, side, intervals):
    """x checked for the one-sided limits C(x + i0 side) of the Cauchy transform: ``side``
    +1 or -1, x real, finite and not at an end (:func:`evaluation_points`).  Returns the
    float array."""
    from .errors import EvaluationPointError
    if isinstance(side, bool) or side not in (1, -1):
        raise EvaluationPointError(f"side must be +1 (from above) or -1 (from below), "
                                   f"got {side!r}")
    if np.asarray(x).dtype.kind == "c":
        raise EvaluationPointError("x must be real (the limits are taken on the real "
                                   "line; use cauchy() at complex points); got complex")
    return evaluation_points(x, intervals, "x")[0]


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


@functools.lru_cache(maxsize=64)
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


def _l0_inside(wt: Weight, x):
    """L_0 at -1 < x < 1."""
    # int_x^1 w = mu_0 I_{(1-x)/2}(alpha+1, beta+1); for x < 0 from the complement
    # mu_0 (1 - I_{(1+x)/2}(beta+1, alpha+1)): next to -1 the argument (1-x)/2 would be
    # rounded next to 1, and I there is ~(1+x)^(beta+1) (2.7e-8 off at x = -1 + 1e-12)
    iw = np.where(x >= 0.0,
                  wt.mu0 * sp.betainc(wt.alpha_p1, wt.beta_p1, 0.5 * (1.0 - x)),
                  wt.mu0 * sp.betaincc(wt.beta_p1, wt.alpha_p1, 0.5 * (1.0 + x)))
    return _l0_at_one(wt) + (math.cos(math.pi * wt.alpha) * iw
                             - _poly_part_integral(wt, x, 1.0)) / wt.sin


@functools.lru_cache(maxsize=64)
def _l0_sides(wt: Weight):
    """What :func:`_l0_near_right` needs of a weight, for x > 1 and (by the reflection
    u -> -u) for x < -1: per side (Gauss-Jacobi (0, alpha) nodes and weights, 30 of them;
    alpha, beta, alpha + 1, sin(pi alpha), m, L_0 at the end).  Computed once per weight."""
    out = []
    for w in (wt, wt.reflected()):
        tau, wtau = gauss_jacobi_cached(30, 0.0, w.alpha)
        out.append((tau, wtau, w.alpha, w.beta, w.alpha_p1, w.sin, w.m, _l0_at_one(w)))
    return tuple(out)


def _l0_near_right(side, x):
    """L_0 at 1 < x < 2 for one side of :func:`_l0_sides` (x < -1: the reflected side at
    -x)."""
    tau, wtau, alpha, beta, alpha_p1, sin, m, at_one = side
    # int_1^x (xi-1)^alpha (xi+1)^beta: xi = 1 + (x-1)(1+tau)/2, Gauss-Jacobi (0, alpha)
    half = 0.5 * (x - 1.0)
    xi = 1.0 + half[:, None] * (1.0 + tau[None, :])
    g = ((xi + 1.0) ** beta) @ wtau
    ig = half ** alpha_p1 * g
    # int_1^x 2^m P_m^{(-alpha,-beta)}, as _poly_part_integral(wt, 1.0, x)
    if m == -1:
        poly = np.zeros(np.shape(x))
    elif m == 0:
        poly = x - 1.0
    else:
        poly = 0.5 * ((x + 1.0) ** 2 - (1.0 + 1.0) ** 2) - 2.0 * alpha * (x - 1.0)
    return at_one - (ig - poly) / sin


def l0_beside(wt: Weight, x):
    """:func:`l0` with the points beside the interval (1 <= |x| < 2) in one compiled pass
    (:func:`_l0_beside_points`: the same rule and closed forms, its sums in a loop instead
    of a matrix product, so the values agree with :func:`l0` to rounding); the others by
    :func:`l0`."""
    x = np.asarray(x, dtype=float)
    ax = np.abs(x)
    beside = (ax >= 1.0) & (ax < 2.0)
    if not beside.all():
        out = l0(wt, x)
        if beside.any():
            out[beside] = l0_beside(wt, x[beside])
        return out
    out = np.empty(x.shape)
    _l0_beside_points(np.ascontiguousarray(x).ravel(), *_l0_beside_data(wt), out.ravel())
    return out


@functools.lru_cache(maxsize=64)
def _l0_beside_data(wt: Weight):
    """:func:`_l0_sides` as :func:`_l0_beside_points` takes it (read-only)."""
    right, left = _l0_sides(wt)
    params = np.array([right[2:], left[2:]], dtype=float)
    params.flags.writeable = False
    return right[0], right[1], left[0], left[1], params


@jit()
def _l0_beside_points(x, tau_r, w_r, tau_l, w_l, params, out):
    """L_0 at 1 <= |x| < 2 (:func:`_l0_near_right`, x < 0 by the reflection u -> -u):
    with s = |x| and that side's weight (``params`` rows: alpha, beta, alpha + 1,
    sin(pi alpha), m, L_0 at the end),

        L_0(s) = L_0(1) - (int_1^s (xi - 1)^alpha (xi + 1)^beta dxi
                           - int_1^s 2^m P_m^{(-alpha,-beta)}) / sin(pi alpha),

    the first integral by Gauss-Jacobi (0, alpha) in xi = 1 + (s - 1)(1 + tau)/2, the
    second in closed form; both vanish at s = 1, which leaves L_0(1)."""
    for i in range(x.shape[0]):
        right = x[i] > 0.0
        s = x[i] if right else -x[i]
        row = 0 if right else 1
        tau = tau_r if right else tau_l
        w = w_r if right else w_l
        alpha, beta, alpha_p1 = params[row, 0], params[row, 1], params[row, 2]
        m = int(params[row, 4])
        half = 0.5 * (s - 1.0)
        g = 0.0
        for k in range(tau.shape[0]):
            xi = 1.0 + half * (1.0 + tau[k])
            g += (xi + 1.0) ** beta * w[k]
        if m == -1:
            poly = 0.0
        elif m == 0:
            poly = s - 1.0
        else:
            poly = 0.5 * ((s + 1.0) ** 2 - (1.0 + 1.0) ** 2) - 2.0 * alpha * (s - 1.0)
        out[i] = params[row, 5] - (half ** alpha_p1 * g - poly) / params[row, 3]


_FAR_TERMS = 60          # |x| >= 2: 2^-60 < 1e-18 relative to mu_0


@functools.lru_cache(maxsize=64)
def _far_coefficients(wt: Weight):
    """M_j / j, j = 1 .. 60 (read-only)."""
    M = _moments(wt, _FAR_TERMS + 1)
    out = M[1:] / np.arange(1, _FAR_TERMS + 1)
    out.flags.writeable = False
    return out


def _l0_far(wt: Weight, x):
    """(1/pi) [mu_0 log|x| - sum_{j>=1} M_j / (j x^j)], |x| >= 2: the terms are below
    mu_0 |x|^-j, so K terms with max|1/x|^K <= 2^-60 (at most 60, fewer farther out); the
    powers 1/x^j by a running product."""
    y = 1.0 / x
    top = float(np.max(np.abs(y))) if y.size else 0.5
    K = _FAR_TERMS if top >= 0.5 else max(1, min(_FAR_TERMS, math.ceil(
        _FAR_TERMS * math.log(2.0) / -math.log(top)))) if top > 0.0 else 1
    powers = np.cumprod(np.broadcast_to(y[:, None], (y.size, K)), axis=1)
    series = powers @ _far_coefficients(wt)[:K]
    return (wt.mu0 * np.log(np.abs(x)) - series) / math.pi


def l0(wt: Weight, x):
    """L_0(x) = (1/pi) int w(u) log|x - u| du at real x (any x; finite at the ends): in
    closed form inside and at the ends, by a Gauss-Jacobi rule for 1 < |x| < 2, by the
    series in 1/x beyond; x < -1 by the reflection u -> -u."""
    x = np.asarray(x, dtype=float)
    out = np.empty(x.shape)
    ax = np.abs(x)
    if ax.size and ax.min() >= 1.0 and ax.max() < 2.0:
        # beside the interval only (the gap checks' points): the branches below, fewer masks
        right, left = _l0_sides(wt)
        pos, neg = x > 1.0, x < -1.0
        if pos.any():
            out[pos] = _l0_near_right(right, x[pos])
        if neg.any():
            out[neg] = _l0_near_right(left, -x[neg])
        at = ax == 1.0
        if at.any():
            out[at] = np.where(x[at] > 0.0, right[-1], left[-1])
        return out
    kind = np.where(ax >= 2.0, 3, np.where(ax > 1.0, 2, np.where(ax == 1.0, 1, 0)))
    present = np.bincount(kind.ravel(), minlength=4)
    if present[3]:
        sel = kind == 3
        out[sel] = _l0_far(wt, x[sel])
    if present[0]:
        sel = kind == 0
        out[sel] = _l0_inside(wt, x[sel])
    if present[1] or present[2]:
        right, left = _l0_sides(wt)
    if present[1]:
        sel = kind == 1
        out[sel] = np.where(x[sel] > 0.0, right[-1], left[-1])
    if present[2]:
        sel = kind == 2
        xs = x[sel]
        vals = np.empty(xs.shape)
        pos = xs > 0.0
        if pos.any():
            vals[pos] = _l0_near_right(right, xs[pos])
        if not pos.all():
            vals[~pos] = _l0_near_right(left, -xs[~pos])
        out[sel] = vals
    return out


_FAR_SERIES_MAX_N = 256   # series longer than this take the far points the general way


@functools.lru_cache(maxsize=64)
def _far_series_table(wt: Weight, n: int):
    """T[j-1, k] = (1/j) int w u^j P_k du, j = 1 .. 60, k < n (read-only): the moments of a
    series sum_k c_k w P_k are T @ c.  From the Gauss rule of w (end-mass corrected) with
    enough nodes to integrate u^60 P_{n-1} exactly."""
    from .jacobi import jacobi_vandermonde
    from .quadrature import WeightedRule
    rule = WeightedRule.build((n + _FAR_TERMS) // 2 + 2, wt.alpha, wt.beta, wt.alpha_p1,
                              wt.beta_p1)
    x, omega = rule.x, rule.omega
    if rule.end:
        x, omega = np.append(x, float(rule.end)), np.append(omega, rule.corr)
    j = np.arange(1, _FAR_TERMS + 1)
    powers = x[None, :] ** j[:, None] / j[:, None]
    out = powers @ (omega[:, None] * jacobi_vandermonde(n, wt.alpha, wt.beta, x))
    out.flags.writeable = False
    return out


def _log_potential_far(c, wt: Weight, x):
    """(1/pi) int w(u) sum_k c_k P_k(u) log|x - u| du at |x| >= 2, from the moments of the
    series: (1/pi) [c_0 mu_0 log|x| - sum_{j>=1} M_j / (j x^j)], M_j = int w u^j sum c_k P_k
    (|M_j| <= int |w phi|, so 60 terms leave 2^-60 of it; fewer farther out)."""
    y = 1.0 / x
    top = float(np.max(np.abs(y)))
    K = _FAR_TERMS if top >= 0.5 else max(1, min(_FAR_TERMS, math.ceil(
        _FAR_TERMS * math.log(2.0) / -math.log(top)))) if top > 0.0 else 1
    moments = _far_series_table(wt, c.size)[:K] @ c
    powers = np.cumprod(np.broadcast_to(y[:, None], (y.size, K)), axis=1)
    return (c[0] * wt.mu0 * np.log(np.abs(x)) - powers @ moments) / math.pi


@functools.lru_cache(maxsize=128)
def _end_table(wt: Weight, n: int, end: float):
    """(L_0(end), Re F~_k(end), k < n - 1): the log potential's pieces at an end (+-1) of
    the interval, for a series of n terms (the values do not depend on the coefficients;
    read-only)."""
    v = np.array([end])
    ends = (v - 1.0, v + 1.0)
    row = cauchy_basis(n - 1, wt, v, shifted=True, ends=ends)[0].real if n > 1 else np.zeros(0)
    row.flags.writeable = False
    return float(l0(wt, v)[0]), row


def log_potential_series(c, wt: Weight, x, ends=None, l0_values=None):
    """(1/pi) int w(u) sum_k c_k P_k(u) log|x - u| du at real x (1-d array): near the
    interval (|x| < 2) from L_0 and the Cauchy transform of the shifted series (module
    docstring; at the ends x = +-1 from tables of both, which do not depend on c), beyond
    it from the moments of the series (:func:`_log_potential_far`).  ``l0_values``:
    :func:`l0` at x where the caller has it."""
    c = np.asarray(c, dtype=float)
    x = np.asarray(x, dtype=float)
    if c.size == 0:
        return np.zeros(x.shape)
    ax = np.abs(x)
    far = ax >= 2.0 if c.size <= _FAR_SERIES_MAX_N else np.zeros(x.shape, dtype=bool)
    at_end = ax == 1.0
    if not (far.any() or at_end.any()):
        return _log_potential_near(c, wt, x, ends, l0_values)
    out = np.empty(x.shape)
    if far.any():
        out[far] = _log_potential_far(c, wt, x[far])
    if at_end.any():
        scaled = c[1:] / (2.0 * np.arange(1, c.size))
        for end in (1.0, -1.0):
            sel = x == end
            if sel.any():
                L, row = _end_table(wt, c.size, end)
                out[sel] = c[0] * L + scaled @ row
    near = ~(far | at_end)
    if near.any():
        out[near] = _log_potential_near(c, wt, x[near], None if ends is None else
                                        (ends[0][near], ends[1][near]),
                                        None if l0_values is None else l0_values[near])
    return out


def _log_potential_near(c, wt: Weight, x, ends=None, l0_values=None):
    """log_potential_series through L_0 (``l0_values`` where given) and the shifted Cauchy
    transform (any x)."""
    out = c[0] * (l0(wt, x) if l0_values is None else l0_values)
    if c.size > 1:
        k = np.arange(1, c.size, dtype=float)
        out = out + cauchy_series(c[1:] / (2.0 * k), wt, x, shifted=True, ends=ends).real
    return out
