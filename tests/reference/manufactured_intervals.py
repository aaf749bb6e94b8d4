"""Independent reference builders for Cauchy singular integral equations on several
intervals, for complex Cauchy transforms and for log potentials.

Nothing in here imports ``sie``.  Everything is built from closed forms, mpmath
(high precision) and the one-interval machinery of ``tests/reference/manufactured.py``
(formulas (M1), (M2), (T) there), which this module extends.

Notation.  L = [c_1, d_1] U ... U [c_J, d_J] (disjoint, ascending); on interval j
the local coordinate is u = (s - m_j)/h_j, m_j = (c_j + d_j)/2, h_j = (d_j - c_j)/2,
and psi(s) = w_j(u) phi_j(u), w_j(u) = (1 - u)^alpha_j (1 + u)^beta_j, with the
exponents of ``manufactured.exponents(a, b, left_j, right_j)``.

The equation, for s in interval i,

    a psi(s) + (b/pi) PV int_L psi(t)/(t - s) dt + int_L k(s,t) psi(t) dt = f(s).

The Cauchy integral is scale invariant,

    (1/pi) int_{L_j} psi(t)/(t - z) dt = (1/pi) int_{-1}^{1} w_j(u) phi_j(u)/(u - zeta) du,
    zeta = (z - m_j)/h_j,                                                          (S)

so every piece is a transform on [-1, 1]:

* own interval (zeta = v in (-1, 1)): a psi + b H[w phi](v) = b R(v) with R the
  smooth function of (M2) in manufactured.py (``Problem.smooth_part``);

* other intervals (v real, |v| > 1, nearly singular when the gap is tiny):

      (1/pi) int w phi/(u - v) du = phi(v) T_w(v) + (1/pi) int w(u) (phi(u) - phi(v))/(u - v) du   (X)

  with the weight's transform T_w in closed form (below) and a regular Gauss-Jacobi sum
  with a cancellation-free divided difference (``Phi.divdiff``).  For |v| >= 1.5 the
  integrand itself is smooth and the Gauss-Jacobi sum of phi/(u - v) is used directly.

The weight's transform off [-1, 1] (alpha + beta = kappa' in {-1, 0, 1}, alpha not an
integer).  With F(z) = (z - 1)^alpha (z + 1)^beta (principal powers, cut on [-1, 1]:
F is single valued off [-1, 1] because alpha + beta is an integer), F(x + i0) - F(x - i0)
= 2 i sin(pi alpha) w(x) on (-1, 1), so by Plemelj / Liouville

    T_w(z) := (1/pi) int_{-1}^{1} w(t)/(t - z) dt = [F(z) - Pol(z)] / sin(pi alpha),   (W)

    Pol = 0 (kappa' = -1),  1 (kappa' = 0),  z + 1 - 2 alpha (kappa' = 1)

(the polynomial part of F at infinity).  For alpha = beta = 1/2 this is
sqrt(z^2 - 1) - z.  (W) is checked against mpmath.quad and against Szego's Jacobi
function of the second kind (Szego 1975, sec. 4.61)

    int w/(t - x) dt = -2^{alpha+beta+1} B(alpha+1, beta+1)/(x - 1)
                        * 2F1(1, alpha+1; alpha+beta+2; 2/(1 - x)),  x > 1        (Q0)

in tests/sie/test_sie_intervals.py and tests/sie/test_sie_cauchy.py.  For complex zeta near
[-1, 1] the same subtraction (X) with mpmath Gauss-Jacobi nodes gives the transform of
w times an entire function (or a polynomial) at any distance from the cut.

Other pieces: the classical two-collinear-cracks solution (``collinear_cracks``), a
log-potential quadrature (``log_potential_local_mp``), and the scale
S(z) = (1/pi) int |psi(t)|/|t - z| dt used as the yardstick of Cauchy-transform errors.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from typing import Optional

import numpy as np
from mpmath import mp

import manufactured as M

DPS = M.DPS           # 40 digits, as the one-interval references
DIRECT = 1.5          # |v| from which the plain Gauss-Jacobi sum of phi/(u - v) is used


# ----------------------------------------------------------------------------
# catalogue extensions (registered in manufactured.PHIS so that M.problem finds them)
# ----------------------------------------------------------------------------

POLYS = {
    "poly1": (1.0, -0.5),                     # 1 - s/2
    "poly2": (0.75, 0.5, -1.0),               # 3/4 + s/2 - s^2
    "poly3": (-0.25, 1.0, 0.5, 0.5),          # -1/4 + s + s^2/2 + s^3/2
}


def _register_poly(name, c):
    phi = M.Phi(name, lambda s, c=c: M.poly_eval(c, s), lambda s, c=c: M.poly_eval_mp(c, s),
                lambda t, s, c=c: M.poly_divdiff(c, t, s), c)
    have = M.PHIS.setdefault(name, phi)
    assert have.poly == c, f"manufactured.PHIS already has a different {name!r}"


for _name, _c in POLYS.items():
    _register_poly(_name, _c)

# kernels in REAL coordinates; intervals used in the tests lie in about [-3, 3], where
# these stay O(1) (0.3 exp(st) would reach 0.3 e^9 there)
KERNELS = {
    None: None,
    "0.3exp(st/4)": M.Kernel("0.3exp(st/4)", lambda s, t: 0.3 * np.exp(0.25 * s * t),
                             lambda s, t: mp.mpf("0.3") * mp.exp(s * t / 4)),
    "cos(s-t)/2": M.KERNELS["cos(s-t)/2"],
}


# ----------------------------------------------------------------------------
# the weight's transform (W) and Szego's (Q0)
# ----------------------------------------------------------------------------

def _sum_index(alpha, beta) -> int:
    s = alpha + beta
    k = int(mp.nint(s))
    if k not in (-1, 0, 1) or abs(s - k) > mp.mpf(10) ** (-mp.dps + 5):
        raise ValueError(f"alpha + beta = {s} is not in {{-1, 0, 1}}")
    return k


def weight_cauchy_mp(alpha, beta, z):
    """(W): (1/pi) int_{-1}^{1} (1-t)^alpha (1+t)^beta/(t - z) dt for complex z off [-1, 1]
    (an mpc); alpha + beta must be -1, 0 or 1 (to working precision)."""
    alpha, beta = mp.mpf(alpha), mp.mpf(beta)
    k = _sum_index(alpha, beta)
    z = mp.mpc(z)
    if z.imag == 0 and -1 <= z.real <= 1:
        raise ValueError("z on [-1, 1]")
    F = mp.power(z - 1, alpha) * mp.power(z + 1, beta)
    pol = (0, 1, z + 1 - 2 * alpha)[k + 1]
    return (F - pol) / mp.sin(mp.pi * alpha)


def weight_cauchy_outside_mp(alpha, beta, v, dist):
    """(W) for real v outside [-1, 1], with dist = |v| - 1 > 0 passed separately (exact
    when the caller has it: at a gap of 1e-6 recomputing v -+ 1 would cost 10 digits).
    v < -1 by the reflection t -> -t:  T^{(alpha,beta)}(v) = -T^{(beta,alpha)}(-v)."""
    alpha, beta, v, dist = mp.mpf(alpha), mp.mpf(beta), mp.mpf(v), mp.mpf(dist)
    if v < 0:
        return -weight_cauchy_outside_mp(beta, alpha, -v, dist)
    k = _sum_index(alpha, beta)
    F = dist ** alpha * (2 + dist) ** beta
    pol = (0, 1, v + 1 - 2 * alpha)[k + 1]
    return (F - pol) / mp.sin(mp.pi * alpha)


def weight_cauchy_szego_mp(alpha, beta, x):
    """(Q0): the same for real x > 1 through Szego's Q_0 (hypergeometric; no use of (W))."""
    alpha, beta, x = mp.mpf(alpha), mp.mpf(beta), mp.mpf(x)
    mu0 = 2 ** (alpha + beta + 1) * mp.beta(alpha + 1, beta + 1)
    return -mu0 / (x - 1) * mp.hyp2f1(1, alpha + 1, alpha + beta + 2, 2 / (1 - x)) / mp.pi


def jacobi_second_kind_cauchy_mp(n, alpha, beta, x):
    """(1/pi) int w P_n^{(alpha,beta)}/(t - x) dt for real x > 1, from Szego's Q_n
    (Szego 1975, sec. 4.61): = -(2/pi) (x-1)^alpha (x+1)^beta Q_n(x)."""
    alpha, beta, x = mp.mpf(alpha), mp.mpf(beta), mp.mpf(x)
    Q = (2 ** (n + alpha + beta) * mp.gamma(n + alpha + 1) * mp.gamma(n + beta + 1)
         / mp.gamma(2 * n + alpha + beta + 2) * (x - 1) ** (-n - alpha - 1) * (x + 1) ** (-beta)
         * mp.hyp2f1(n + 1, n + alpha + 1, 2 * n + alpha + beta + 2, 2 / (1 - x)))
    return -2 * (x - 1) ** alpha * (x + 1) ** beta * Q / mp.pi


# ----------------------------------------------------------------------------
# transforms of w * (entire function or polynomial), anywhere off [-1, 1] and the PV on it
# ----------------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def gauss_jacobi_exact(alpha_s: str, beta_s: str, n: int):
    """mpmath Gauss-Jacobi rule at DPS digits for exponents given as strings of mpf
    (so that alpha + beta = integer can be imposed exactly)."""
    with mp.workdps(DPS):
        X, W = mp.gauss_quadrature(n, "jacobi", mp.mpf(alpha_s), mp.mpf(beta_s))
        return tuple(X), tuple(W)


def bernstein_rho(zeta) -> float:
    """Bernstein-ellipse parameter of zeta w.r.t. [-1, 1]: |zeta + sqrt(zeta^2 - 1)| >= 1."""
    z = complex(zeta)
    r = z + np.sqrt(z - 1) * np.sqrt(z + 1)
    return max(abs(r), 1 / abs(r)) if r != 0 else 1.0


def cauchy_wphi_mp(alpha, beta, phi_mp, zeta, X, W, direct=True):
    """(1/pi) int w(u) phi(u)/(u - zeta) du for complex (or real outside) zeta, phi entire
    (or a polynomial), by (X) with the Gauss-Jacobi rule (X, W) of w.  With ``direct``
    (for a rule of ~40 nodes) and zeta far (Bernstein parameter >= 2.5: error ~ 2.5^-80),
    the plain Gauss-Jacobi sum of phi/(u - zeta) instead.  For a polynomial phi of degree
    < len(X) the subtraction is exact at any zeta (use direct=False).  It loses
    ~log10(1/|u - zeta|) of the DPS digits near a node and ~log10(|phi(zeta)/phi|) far away."""
    zeta = mp.mpc(zeta)
    if direct and bernstein_rho(complex(zeta)) >= 2.5:
        return mp.fsum(w * phi_mp(x) / (x - zeta) for x, w in zip(X, W)) / mp.pi
    p = phi_mp(zeta)
    reg = mp.fsum(w * (phi_mp(x) - p) / (x - zeta) for x, w in zip(X, W))
    return p * weight_cauchy_mp(alpha, beta, zeta) + reg / mp.pi


def hilbert_wphi_mp(alpha, beta, phi_mp, x, X, W):
    """(1/pi) PV int w phi/(u - x) du for real x in (-1, 1): (M1) with Tricomi's (T)."""
    x = mp.mpf(x)
    p = phi_mp(x)
    reg = mp.fsum(w * (phi_mp(t) - p) / (t - x) for t, w in zip(X, W))
    return p * M.hilbert_weight_mp(alpha, beta, x) + reg / mp.pi


def jacobi_series_mp(coeffs, alpha, beta):
    """u -> sum_k c_k P_k^{(alpha,beta)}(u) (real or complex u, mpmath) by the three-term
    recurrence of ``jacobi_series_np`` (mpmath.jacobi's hypergeometric form fails at
    u = -1 for some exponents; the recurrence is checked against it in the self-tests)."""
    c = [mp.mpf(ck) for ck in coeffs]
    return lambda u: jacobi_series_np(c, alpha, beta, u, one=mp.mpf(1))


@dataclass(frozen=True)
class JacobiDensity:
    """psi = (1-t)^alpha (1+t)^beta sum_k c_k P_k^{(alpha,beta)}(t) on [-1, 1] (the density of
    sie.jacobi_cauchy).  alpha, beta are the doubles passed to the library; in mpmath
    beta is taken as round(alpha + beta) - alpha (exact), which differs from the double
    by at most an ulp."""
    coeffs: tuple
    alpha: float
    beta: float

    @functools.cached_property
    def _mp(self):
        with mp.workdps(DPS):
            al = mp.mpf(self.alpha)
            be = int(round(self.alpha + self.beta)) - al
            assert abs(be - mp.mpf(self.beta)) <= mp.mpf(2) ** -50 * max(1, abs(be))
            X, W = gauss_jacobi_exact(str(al), str(be), len(self.coeffs) + 2)
            return al, be, jacobi_series_mp(self.coeffs, al, be), X, W

    def phi_mp(self, u):
        return self._mp[2](u)

    def psi(self, t):
        """numpy psi at real t in [-1, 1] (for scales only)."""
        t = np.asarray(t, float)
        ph = np.array([float(self.phi_mp(x)) for x in t.ravel()]).reshape(t.shape)
        return (1 - t) ** self.alpha * (1 + t) ** self.beta * ph

    def cauchy_mp(self, z):
        """(1/pi) int psi/(t - z) dt: complex z off [-1, 1] (mpc); real z: PV inside
        (-1, 1), ordinary integral outside (mpf)."""
        al, be, phi, X, W = self._mp
        with mp.workdps(DPS):
            if isinstance(z, complex) or isinstance(z, mp.mpc):
                return cauchy_wphi_mp(al, be, phi, z, X, W, direct=False)
            z = mp.mpf(z)
            if abs(z) < 1:
                return hilbert_wphi_mp(al, be, phi, z, X, W)
            return cauchy_wphi_mp(al, be, phi, z, X, W, direct=False).real

    def cauchy_quad_mp(self, z, dps=30):
        """Brute force: mpmath.quad of psi/(t - z) (moderate distance from [-1, 1] only)."""
        al, be, phi, _, _ = self._mp
        with mp.workdps(dps):
            z = mp.mpc(z)
            return M.int_w_mp(al, be, lambda t: phi(t) / (t - z)) / mp.pi

    def S(self, z):
        """S(z) = (1/pi) int |psi(t)|/|t - z| dt (numpy, ~1e-6 accurate)."""
        return scale_S_np(self.alpha, self.beta, lambda u: self._phi_np(u), z)

    def _phi_np(self, u):
        # numpy evaluation of the Jacobi series by the three-term recurrence (DLMF 18.9.1-2)
        return jacobi_series_np(self.coeffs, self.alpha, self.beta, u)


def jacobi_series_np(coeffs, alpha, beta, x, one=None):
    """sum c_k P_k^{(alpha,beta)}(x) by the three-term recurrence (DLMF 18.9.1-2),
    P_0 = 1, P_1 = (alpha+1) + (alpha+beta+2)(x-1)/2,
    P_{n+1} = (A_n x + B_n) P_n - C_n P_{n-1},
    A_n = (2n+s+1)(2n+s+2)/(2(n+1)(n+s+1)), B_n = (alpha^2-beta^2)(2n+s+1)/(2(n+1)(n+s+1)(2n+s)),
    C_n = (n+alpha)(n+beta)(2n+s+2)/((n+1)(n+s+1)(2n+s)),  s = alpha + beta.
    numpy arrays (one=None; for the scales S) or mpmath scalars (one=mpf(1))."""
    if one is None:
        x = np.asarray(x, float)
        p0 = np.ones_like(x)
    else:
        p0 = one
    out = coeffs[0] * p0
    if len(coeffs) == 1:
        return out
    p1 = (alpha + 1) + (alpha + beta + 2) * (x - 1) / 2
    out = out + coeffs[1] * p1
    ab = alpha + beta
    for n in range(1, len(coeffs) - 1):
        A = (2 * n + ab + 1) * (2 * n + ab + 2) / (2 * (n + 1) * (n + ab + 1))
        B = (alpha ** 2 - beta ** 2) * (2 * n + ab + 1) / (2 * (n + 1) * (n + ab + 1) * (2 * n + ab))
        C = (n + alpha) * (n + beta) * (2 * n + ab + 2) / ((n + 1) * (n + ab + 1) * (2 * n + ab))
        p0, p1 = p1, (A * x + B) * p1 - C * p0
        out = out + coeffs[n + 1] * p1
    return out


# ----------------------------------------------------------------------------
# the scale S(z) = (1/pi) int |w phi|/|u - zeta| du
# ----------------------------------------------------------------------------

_GLX, _GLW = np.polynomial.legendre.leggauss(12)


def _graded_points(zeta, ratio=2.0):
    z = complex(zeta)
    x0 = min(max(z.real, -1.0), 1.0)
    y = abs(z.imag) + max(0.0, abs(z.real) - 1.0)     # ~ distance to [-1, 1]
    pts = {-1.0, 0.0, 1.0, x0}
    for k in range(1, 17):
        pts.add(-1.0 + 10.0 ** -k)
        pts.add(1.0 - 10.0 ** -k)
    if y > 0:
        d = y
        while d < 4:
            pts.add(x0 - d)
            pts.add(x0 + d)
            d *= ratio
    return np.array(sorted(p for p in pts if -1.0 <= p <= 1.0))


def _graded_integral(alpha, beta, phi_np, zeta, g):
    """(1/pi) int_{-1}^{1} (1-u)^alpha (1+u)^beta |phi(u)| g(u) du, composite Gauss-Legendre
    on the mesh of _graded_points(zeta)."""
    p = _graded_points(zeta)
    a, b = p[:-1], p[1:]
    half, mid = (b - a) / 2, (b + a) / 2
    u = mid[:, None] + half[:, None] * _GLX[None, :]
    # distances to the ends from the panel ends (accurate near the ends)
    one_m = (1.0 - b)[:, None] + half[:, None] * (1 - _GLX[None, :])
    one_p = (1.0 + a)[:, None] + half[:, None] * (1 + _GLX[None, :])
    w = one_m ** float(alpha) * one_p ** float(beta)
    val = w * np.abs(phi_np(u)) * g(u)
    return float(np.sum(half[:, None] * _GLW[None, :] * val)) / math.pi


def scale_S_np(alpha, beta, phi_np, zeta):
    """S = (1/pi) int_{-1}^{1} (1-u)^alpha (1+u)^beta |phi(u)|/|u - zeta| du by composite
    Gauss-Legendre on a mesh graded towards the ends and towards Re zeta (a yardstick:
    ~1e-3 relative is plenty; checked against mpmath.quad in the self-tests)."""
    z = complex(zeta)
    return _graded_integral(alpha, beta, phi_np, z, lambda u: 1 / np.abs(u - z))


def scale_log_np(alpha, beta, phi_np, xi, h):
    """Yardstick of a log potential on one interval of half-width h:
    (h/pi) int w |phi| (1 + |log(h |xi - u|)|) du  (>= the size of every term of V)."""
    xi = float(xi)
    # graded towards xi down to 1e-12 (finer panels would put Gauss nodes onto xi in double)
    return h * _graded_integral(alpha, beta, phi_np, complex(xi, 1e-12 * max(1.0, abs(xi))),
                                lambda u: 1 + np.abs(np.log(h * np.maximum(np.abs(xi - u), 1e-18))))


def scale_S_mp(alpha, beta, phi_mp, zeta, dps=20):
    """The same by mpmath.quad on a coarser mesh (grading ratio 10, tanh-sinh copes with the
    rest), in the end distances p = 1 + u (u < 0) and q = 1 - u (u > 0) so that tanh-sinh
    nodes never round onto an end (for the self-test of scale_S_np)."""
    pts = _graded_points(zeta, ratio=10.0)
    with mp.workdps(dps):
        al, be, z = mp.mpf(alpha), mp.mpf(beta), mp.mpc(zeta)

        def gl(p):
            return p ** be * (2 - p) ** al * abs(phi_mp(p - 1)) / abs(p - 1 - z)

        def gr(q):
            return q ** al * (2 - q) ** be * abs(phi_mp(1 - q)) / abs(1 - q - z)
        P = sorted({mp.mpf(float(x)) + 1 for x in pts if x <= 0})
        Q = sorted({1 - mp.mpf(float(x)) for x in pts if x >= 0})
        return (mp.quad(gl, P) + mp.quad(gr, Q)) / mp.pi


# ----------------------------------------------------------------------------
# log potential on [-1, 1]
# ----------------------------------------------------------------------------

def log_potential_local_mp(alpha, beta, phi_mp, xi, dps=30):
    """int_{-1}^{1} w(u) phi(u) log|xi - u| du for real xi (inside, outside or at +-1), by
    mpmath.quad in the end distances p = 1 + u (left half) and q = 1 - u (right half), split
    at the logarithmic singularity, with the end-point singularity subtracted as in
    manufactured.int_w_mp:  int_0^1 p^beta H(p) dp = H(0)/(beta+1) + int_0^1 p^beta (H(p) - H(0)) dp,
    and where xi is that end (H = A(p) log p):  int_0^1 p^beta log p dp = -1/(beta+1)^2.
    (Plain tanh-sinh on p^-0.7 tails stalls at ~1e-11 at 30 digits.)"""
    with mp.workdps(dps):
        al, be, xi = mp.mpf(alpha), mp.mpf(beta), mp.mpf(xi)

        def half(e_near, e_far, A, star):
            # int_0^1 p^e_near A(p) log|star - p| dp,  A smooth on [0, 1]
            A0 = A(mp.zero)
            pts = [mp.zero, star, mp.one] if 0 < star < 1 else [mp.zero, mp.one]
            if star == 0:
                return (mp.quad(lambda p: p ** e_near * mp.log(p) * (A(p) - A0), pts)
                        - A0 / (e_near + 1) ** 2)
            H0 = A0 * mp.log(abs(star))
            return (mp.quad(lambda p: p ** e_near * (A(p) * mp.log(abs(star - p)) - H0), pts)
                    + H0 / (e_near + 1))

        left = half(be, al, lambda p: (2 - p) ** al * phi_mp(p - 1), xi + 1)
        right = half(al, be, lambda q: (2 - q) ** be * phi_mp(1 - q), 1 - xi)
        return left + right


# ----------------------------------------------------------------------------
# manufactured problems on several intervals
# ----------------------------------------------------------------------------

def dyadic(x: float) -> float:
    """x rounded to the nearest power of two (so that interval ends, midpoints and
    half-widths built from dyadic lengths are all exact doubles)."""
    return 2.0 ** round(math.log2(x))


def layout(lengths, gap_ratios, start=-1.25):
    """Intervals of the given (dyadic) lengths, left to right from ``start``; gap i (between
    intervals i and i+1) = dyadic(gap_ratios[i]) * min(lengths[i], lengths[i+1]).
    Everything is then an exact double with m_j - h_j == c_j and m_j + h_j == d_j, so the
    local coordinate (s - m_j)/h_j is unambiguous even at gap/width ~ 1e-6 (otherwise the
    rounding of m_j would move the distance to the near end by ~1e-11 relative)."""
    assert len(gap_ratios) == len(lengths) - 1
    out, c = [], float(start)
    for i, ln in enumerate(lengths):
        assert dyadic(ln) == ln or float(ln * 64).is_integer(), ln
        d = c + ln
        out.append((c, d))
        if i < len(gap_ratios):
            c = d + dyadic(gap_ratios[i]) * min(lengths[i], lengths[i + 1])
    for c, d in out:
        m, h = (c + d) / 2, (d - c) / 2
        assert m - h == c and m + h == d, (c, d)
    return tuple(out)


@functools.lru_cache(maxsize=None)
def _weight_outside_float(a, b, left, right, v, dist):
    e = M.exponents(a, b, left, right)
    with mp.workdps(DPS):
        return float(weight_cauchy_outside_mp(e.alpha, e.beta, v, dist))


@dataclass(eq=False)
class MultiProblem:
    """psi = w_j phi_j on interval j; f built by (M2) on the own interval, (X) for the others,
    and a 40-node Gauss-Jacobi sum for the kernel term."""
    a: float
    b: float
    intervals: tuple
    ends: tuple                   # ((left, right), ...)
    phi_names: tuple
    kernel: Optional[M.Kernel]
    parts: tuple = field(repr=False)     # manufactured.Problem per interval (no kernel)

    # -- geometry ------------------------------------------------------------
    @property
    def J(self):
        return len(self.intervals)

    def m(self, j):
        c, d = self.intervals[j]
        return (c + d) / 2

    def h(self, j):
        c, d = self.intervals[j]
        return (d - c) / 2

    def local(self, j, s):
        return (np.asarray(s, float) - self.m(j)) / self.h(j)

    def locate(self, s):
        """Index of the closed interval holding each s (a few ulps of slack); -1 elsewhere."""
        s = np.asarray(s, float)
        idx = np.full(s.shape, -1, dtype=int)
        for j, (c, d) in enumerate(self.intervals):
            tol = 8 * np.finfo(float).eps * max(abs(c), abs(d), d - c)
            idx[(s >= c - tol) & (s <= d + tol)] = j
        return idx

    # -- per-interval data ---------------------------------------------------
    @property
    def left(self):
        return tuple(l for l, _ in self.ends)

    @property
    def right(self):
        return tuple(r for _, r in self.ends)

    @property
    def kappa(self):
        return tuple(P.kappa for P in self.parts)

    @property
    def alpha(self):
        return tuple(P.alpha for P in self.parts)

    @property
    def beta(self):
        return tuple(P.beta for P in self.parts)

    def integral(self, j):
        """int_{c_j}^{d_j} psi(s) ds = h_j int w phi du (real coordinate)."""
        return self.h(j) * self.parts[j].integral

    def abs_integral(self, j):
        return self.h(j) * self.parts[j].abs_integral

    @property
    def total(self):
        """Per-interval side conditions: int psi for kappa_j = 1, None elsewhere."""
        return tuple(self.integral(j) if P.kappa == 1 else None for j, P in enumerate(self.parts))

    def mu0(self, j):
        """int_{-1}^{1} w_j du (how much the weight can amplify end values)."""
        return float(M.weight_integral_mp(self.parts[j].e))

    # -- the exact solution ----------------------------------------------------
    def phi_true(self, j, s):
        return self.parts[j].phi.f(self.local(j, s))

    def psi(self, s):
        s = np.asarray(s, float)
        out = np.zeros(s.shape)
        idx = self.locate(s)
        for j in range(self.J):
            sel = idx == j
            v = np.clip(self.local(j, s[sel]), -1.0, 1.0)
            out[sel] = self.parts[j].psi(v)
        return out

    # -- pieces of f -----------------------------------------------------------
    def _dist(self, j, s):
        """(v, dist) of real s outside interval j: v = local coordinate, dist = |v| - 1
        from the exact difference to the nearer end."""
        c, d = self.intervals[j]
        h = self.h(j)
        if s > d:
            dist = (s - d) / h
            return 1.0 + dist, dist
        if s < c:
            dist = (c - s) / h
            return -1.0 - dist, dist
        raise ValueError(f"s = {s!r} is inside interval {j}")

    def cross_local(self, j, v, dist):
        """(1/pi) int w_j phi_j/(u - v) du for real v outside [-1, 1], by (X) (double
        Gauss-Jacobi sums, (W) in mpmath)."""
        P = self.parts[j]
        if abs(v) >= DIRECT:
            return float(np.sum(P.Wq * P.phi.f(P.tq) / (P.tq - v))) / math.pi
        Tw = _weight_outside_float(P.a, P.b, P.left, P.right, float(v), float(dist))
        reg = float(np.sum(P.Wq * P.phi.divdiff(P.tq, np.full_like(P.tq, v)))) / math.pi
        return float(P.phi.f(np.array(v))) * Tw + reg

    def cross(self, j, s):
        """(1/pi) int_{L_j} psi(t)/(t - s) dt for real s outside interval j (scalar)."""
        v, dist = self._dist(j, float(s))
        return self.cross_local(j, v, dist)

    def cross_mp(self, j, s):
        """The same by brute force: mpmath.quad with geometric subdivision towards the
        near end (manufactured.Problem.cauchy_outside_mp), local coordinate in mpmath."""
        with mp.workdps(DPS):
            v = (mp.mpf(float(s)) - mp.mpf(self.m(j))) / mp.mpf(self.h(j))
            return self.parts[j].cauchy_outside_mp(v)

    def kernel_term(self, s):
        """int_L k(s,t) psi(t) dt (40-node Gauss-Jacobi per interval)."""
        s = np.asarray(s, float)
        out = np.zeros(s.shape)
        if self.kernel is None:
            return out
        flat = s.reshape(-1)
        acc = np.zeros(flat.shape)
        for j, P in enumerate(self.parts):
            t = self.m(j) + self.h(j) * P.tq
            k = self.kernel.f(flat[:, None], t[None, :])
            acc += self.h(j) * (k * (P.Wq * P.phi.f(P.tq))[None, :]).sum(axis=1)
        return acc.reshape(s.shape)

    def rhs(self, s):
        """f(s) for s in L (vectorised, shape in = shape out).  Raises for s outside L."""
        s = np.asarray(s, float)
        flat = s.reshape(-1)
        idx = self.locate(flat)
        if np.any(idx < 0):
            raise ValueError(f"f evaluated outside L at s = {flat[idx < 0][:3].tolist()}")
        out = np.zeros(flat.shape)
        for i in range(self.J):
            sel = idx == i
            if not sel.any():
                continue
            v = np.clip(self.local(i, flat[sel]), -1.0, 1.0)
            val = self.b * self.parts[i].smooth_part(v)          # a psi + b H_own psi, (M2)
            for j in range(self.J):
                if j != i:
                    val = val + self.b * np.array([self.cross(j, x) for x in flat[sel]])
            out[sel] = val
        out = out + self.kernel_term(flat)
        return out.reshape(s.shape)

    __call__ = rhs

    def rhs_mp(self, s):
        """f(s) by brute force: a psi + b PV (manufactured.hilbert_mp, no (T)) + b sum of
        mpmath.quad cross terms + mpmath.quad kernel term."""
        s = float(s)
        i = int(self.locate(np.array(s)))
        with mp.workdps(DPS):
            P = self.parts[i]
            e = P.e
            v = (mp.mpf(s) - mp.mpf(self.m(i))) / mp.mpf(self.h(i))
            psi = (1 - v) ** e.alpha * (1 + v) ** e.beta * P.phi.f_mp(v)
            val = mp.mpf(self.a) * psi + mp.mpf(self.b) * M.hilbert_mp(e.alpha, e.beta, P.phi.f_mp, v)
            for j in range(self.J):
                if j != i:
                    val += mp.mpf(self.b) * self.cross_mp(j, s)
            if self.kernel is not None:
                for j, Pj in enumerate(self.parts):
                    mj, hj = mp.mpf(self.m(j)), mp.mpf(self.h(j))
                    val += hj * M.int_w_mp(Pj.e.alpha, Pj.e.beta,
                                           lambda u: self.kernel.f_mp(mp.mpf(s), mj + hj * u) * Pj.phi.f_mp(u))
            return val

    # -- transforms of the exact psi ---------------------------------------------
    def hilbert(self, x):
        """H[psi](x) = (1/pi) PV int_L psi(t)/(t - x) dt for real x off the ends (double;
        own interval by (M1)+(T), others by (X))."""
        x = np.asarray(x, float)
        flat = x.reshape(-1)
        idx = self.locate(flat)
        out = np.zeros(flat.shape)
        for k, xv in enumerate(flat):
            val = 0.0
            for j in range(self.J):
                if j == idx[k]:
                    val += float(self.parts[j].hilbert(np.array(self.local(j, xv))))
                else:
                    val += self.cross(j, xv)
            out[k] = val
        return out.reshape(x.shape)

    def hilbert_mp(self, x):
        """The same by brute force (manufactured.hilbert_mp inside, mpmath.quad outside)."""
        x = float(x)
        i = int(self.locate(np.array(x)))
        with mp.workdps(DPS):
            val = mp.zero
            for j in range(self.J):
                if j == i:
                    e = self.parts[j].e
                    v = (mp.mpf(x) - mp.mpf(self.m(j))) / mp.mpf(self.h(j))
                    val += M.hilbert_mp(e.alpha, e.beta, self.parts[j].phi.f_mp, v)
                else:
                    val += self.cross_mp(j, x)
            return val

    def _rule(self, j):
        e = self.parts[j].e
        X, W, _, _ = M.gauss_jacobi_mp(self.a, self.b, *self.ends[j])
        return e, X, W

    def cauchy_mp(self, z):
        """(1/pi) int_L psi(t)/(t - z) dt for complex z off L (mpc), by (S) and (X)."""
        with mp.workdps(DPS):
            z = mp.mpc(z)
            tot = mp.mpc(0)
            for j in range(self.J):
                e, X, W = self._rule(j)
                zeta = (z - mp.mpf(self.m(j))) / mp.mpf(self.h(j))
                tot += cauchy_wphi_mp(e.alpha, e.beta, self.parts[j].phi.f_mp, zeta, X, W)
            return tot

    def cauchy_quad_mp(self, z, dps=30):
        """Brute force: mpmath.quad per interval (moderate distance from L only)."""
        with mp.workdps(dps):
            z = mp.mpc(z)
            tot = mp.mpc(0)
            for j, P in enumerate(self.parts):
                zeta = (z - mp.mpf(self.m(j))) / mp.mpf(self.h(j))
                tot += M.int_w_mp(P.e.alpha, P.e.beta, lambda u: P.phi.f_mp(u) / (u - zeta)) / mp.pi
            return tot

    def S(self, z):
        """S(z) = (1/pi) int_L |psi(t)|/|t - z| dt (numpy yardstick), by (S)."""
        tot = 0.0
        for j, P in enumerate(self.parts):
            zeta = (complex(z) - self.m(j)) / self.h(j)
            tot += scale_S_np(P.alpha, P.beta, P.phi.f, zeta)
        return tot

    def V_scale(self, x):
        """(1/pi) int_L |psi(t)| (1 + |log|x - t||) dt (numpy yardstick of the log potential)."""
        return sum(scale_log_np(P.alpha, P.beta, P.phi.f, (float(x) - self.m(j)) / self.h(j), self.h(j))
                   for j, P in enumerate(self.parts))

    def log_potential_mp(self, x, dps=30):
        """V(x) = (1/pi) int_L psi(t) log|x - t| dt: per interval t = m + h u gives
        (h/pi) [log(h) int w phi du + int w phi log|xi - u| du], xi = (x - m)/h."""
        with mp.workdps(dps):
            tot = mp.zero
            for j, P in enumerate(self.parts):
                m, h = mp.mpf(self.m(j)), mp.mpf(self.h(j))
                xi = (mp.mpf(float(x)) - m) / h
                I = mp.mpf(P.integral)      # exact to ~1e-16 relative, enough for a 1e-13 check
                tot += h / mp.pi * (mp.log(h) * I
                                    + log_potential_local_mp(P.e.alpha, P.e.beta, P.phi.f_mp, xi, dps))
            return tot

    def fscale(self):
        """max |f| over interior sample points of every interval."""
        S = M.sample_points(50)
        return float(max(np.max(np.abs(self.rhs(self.m(j) + self.h(j) * S))) for j in range(self.J)))


@functools.lru_cache(maxsize=None)
def multi_problem(a: float, b: float, intervals: tuple, ends: tuple, phis: tuple,
                  kernel: Optional[str] = None) -> MultiProblem:
    """Cached manufactured problem on several intervals.  ends: ((left, right), ...);
    phis: keys of manufactured.PHIS (incl. poly1..poly3 above); kernel: key of KERNELS."""
    assert len(intervals) == len(ends) == len(phis)
    for (c0, d0), (c1, d1) in zip(intervals, intervals[1:]):
        assert c0 < d0 < c1 < d1
    parts = tuple(M.problem(a, b, l, r, p, None) for (l, r), p in zip(ends, phis))
    return MultiProblem(float(a), float(b), tuple((float(c), float(d)) for c, d in intervals),
                        tuple(ends), tuple(phis), KERNELS[kernel], parts)


def jacobi_coefficients(P: MultiProblem, j: int):
    """Exact coefficients of a polynomial phi_j in P_k^{(alpha_j, beta_j)} (scipy normalisation)."""
    return P.parts[j].jacobi_coefficients()


# ----------------------------------------------------------------------------
# two equal collinear cracks b < |x| < c  (airfoil equation, both ends singular)
# ----------------------------------------------------------------------------

@dataclass(frozen=True)
class CollinearCracks:
    """(1/pi) PV int_L psi(t)/(t - x) dt = 1 on L = [-c, -b] U [b, c], psi ~ dist^(-1/2) at
    all four tips, int psi = 0 over each crack (a = 0, b_coef = 1, f = 1).

    Exact solution (Westergaard's stress function for a row of collinear cracks, Westergaard
    1939; the two-collinear-cracks entry of Tada, Paris & Irwin, The Stress Analysis of Cracks
    Handbook, 3rd ed. 2000, Part II, and Erdogan 1962 give the same SIFs -- its page is not
    quoted here: everything below is derived and then checked numerically in
    tests/sie/test_sie_intervals.py::test_reference_collinear_cracks*: the equation by brute-force
    PV, the zero net integrals, the SIFs as lim sqrt(2 pi r) sigma_yy from quadrature of the
    density, and the isolated-crack / single-crack limits): with
    X(z) = sqrt((z^2 - b^2)(z^2 - c^2)) ~ z^2 at infinity,

        C(z) := (1/pi) int_L psi/(t - z) dt = 1 - (z^2 - lambda^2)/X(z),
        lambda^2 = c^2 E(k)/K(k),  k^2 = 1 - b^2/c^2,

    C = O(z^-2) at infinity (so int_L psi = 0; lambda makes each crack's integral vanish:
    int_b^c dt/sqrt(..) = K(k)/c, int_b^c t^2 dt/sqrt(..) = c E(k)), C(x+i0) + C(x-i0) = 2
    on L, and X(x + i0) = +i sqrt((x^2-b^2)(c^2-x^2)) on (b, c), hence

        psi(t) = sgn(t) (t^2 - lambda^2)/sqrt((t^2 - b^2)(c^2 - t^2)).

    Mechanics: psi is the (stress-normalised) dislocation density of mode-I cracks opened by
    a unit face pressure (= unit remote tension by superposition); the normal stress on the
    crack line off L is sigma_yy(x) = 1 - H[psi](x) = (x^2 - lambda^2)/X(x), the
    Westergaard function Z, and K_I = lim sqrt(2 pi r) sigma_yy at distance r ahead of a tip:

        K_outer (x = +-c) = sqrt(pi c) (1 - E/K)/k,
        K_inner (x = +-b) = sqrt(pi c) sqrt(c/b) (E/K - b^2/c^2)/k

    (E, K of modulus k; mpmath.ellipk/ellipe take the parameter m = k^2).  Both -> sqrt(pi a),
    a = (c - b)/2, as b/c -> 1 (isolated cracks) and K_outer -> sqrt(pi c) as b/c -> 0.
    Relation to the density: psi ~ A r^(-1/2) at a tip gives H[psi] ~ -+A r^(-1/2) just
    ahead of it, so K = sqrt(2 pi) |A|.  In the local coordinate of the right crack
    (m = (b+c)/2, h = (c-b)/2, alpha = beta = -1/2), psi = (1-u^2)^(-1/2) phi(u) and
    1 - u = (c - t)/h, so A = phi(1) sqrt(h/2) and

        K_outer = sqrt(pi h) phi_right(+1),   K_inner = -sqrt(pi h) phi_right(-1),

    phi_right(u) = (t^2 - lambda^2)/(h sqrt((t + b)(t + c))), t = m + h u; by oddness
    phi_left(u) = -phi_right(-u), so K_inner = sqrt(pi h) phi_left(+1),
    K_outer = -sqrt(pi h) phi_left(-1)."""
    b: float
    c: float

    @functools.cached_property
    def _mp(self):
        with mp.workdps(DPS):
            b, c = mp.mpf(self.b), mp.mpf(self.c)
            m2 = 1 - (b / c) ** 2                  # parameter m = k^2
            K, E = mp.ellipk(m2), mp.ellipe(m2)
            k = mp.sqrt(m2)
            lam2 = c ** 2 * E / K
            K_outer = mp.sqrt(mp.pi * c) * (1 - E / K) / k
            K_inner = mp.sqrt(mp.pi * c) * mp.sqrt(c / b) * (E / K - (b / c) ** 2) / k
            return dict(b=b, c=c, k=k, K=K, E=E, lam2=lam2, K_outer=K_outer, K_inner=K_inner,
                        m=(b + c) / 2, h=(c - b) / 2)

    @property
    def lam2(self):
        return self._mp["lam2"]

    @property
    def K_outer(self):
        return self._mp["K_outer"]

    @property
    def K_inner(self):
        return self._mp["K_inner"]

    @property
    def intervals(self):
        return ((-self.c, -self.b), (self.b, self.c))

    def phi_right_mp(self, u):
        d = self._mp
        t = d["m"] + d["h"] * u
        return (t * t - d["lam2"]) / (d["h"] * mp.sqrt((t + d["b"]) * (t + d["c"])))

    def phi_left_mp(self, u):
        return -self.phi_right_mp(-u)

    def phi_right(self, u):
        with mp.workdps(DPS):
            return np.array([float(self.phi_right_mp(mp.mpf(float(x)))) for x in np.ravel(u)])

    def phi_left(self, u):
        return -self.phi_right(-np.asarray(u, float))

    def psi_mp(self, t):
        d = self._mp
        t = mp.mpf(t)
        return mp.sign(t) * (t * t - d["lam2"]) / mp.sqrt((t * t - d["b"] ** 2) * (d["c"] ** 2 - t * t))

    def westergaard_mp(self, x):
        """sigma_yy on the crack line off L: (x^2 - lambda^2)/X(x), X > 0 for |x| > c,
        X < 0 for |x| < b (X ~ z^2, and each of the two factors sqrt(z^2 - c^2),
        sqrt(z^2 - b^2) continued through the upper half plane)."""
        d = self._mp
        x = mp.mpf(x)
        X = mp.sqrt((x * x - d["b"] ** 2) * (x * x - d["c"] ** 2))
        if abs(x) < d["b"]:
            X = -X
        return (x * x - d["lam2"]) / X

    def hilbert_mp(self, x):
        """H[psi](x) by brute force: (1/pi)(PV) int over both cracks in local coordinates
        (manufactured.hilbert_mp on the crack holding x, mpmath.quad with geometric
        subdivision towards the near end for the other)."""
        d = self._mp
        half = mp.mpf(-1) / 2
        with mp.workdps(DPS):
            x = mp.mpf(x)
            tot = mp.zero
            for sign, phi in ((1, self.phi_right_mp), (-1, self.phi_left_mp)):
                v = (x - sign * d["m"]) / d["h"]
                if abs(v) < 1:
                    tot += M.hilbert_mp(half, half, phi, v)
                else:
                    dist = abs(v) - 1
                    splits = ([mp.mpf(10) ** k for k in range(-14, 0) if mp.mpf(10) ** k > dist / 10]
                              if dist < 0.5 else [])
                    tot += M.int_w_mp(half, half, lambda u: phi(u) / (u - v), splits) / mp.pi
            return tot


# ----------------------------------------------------------------------------
# solvability of the airfoil equation with bounded ends on two intervals
# ----------------------------------------------------------------------------

def airfoil_solvability_mp(intervals, f_mp, kmax=1):
    """int_L f(t) t^k / R+(t) dt, k = 0..kmax, R(z) = sqrt(prod (z - c_j)(z - d_j)) ~ z^J
    (Muskhelishvili 1953, ch. 11: the airfoil equation has a solution bounded at all 2J
    ends iff these J numbers vanish).  On interval j, R+ = +-i |R| with the sign alternating
    from one interval to the next (each gap flips the sign of R, each interval adds a
    factor i); the values returned use |R| with alternating signs, sign +1 on the last
    interval (a common factor does not matter for "is it zero")."""
    out = []
    with mp.workdps(30):
        ends = [mp.mpf(x) for cd in intervals for x in cd]
        for k in range(kmax + 1):
            tot = mp.zero
            for j, (c, d) in enumerate(intervals):
                c, d = mp.mpf(c), mp.mpf(d)
                sign = (-1) ** (len(intervals) - 1 - j)

                def g(t):
                    R = mp.sqrt(abs(mp.fprod(t - e for e in ends)))
                    return f_mp(t) * t ** k / R
                tot += sign * mp.quad(g, [c, (c + d) / 2, d])
            out.append(tot)
    return out
