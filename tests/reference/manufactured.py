"""Independent reference builders for Cauchy singular integral equations.

Nothing in here imports ``sie``: every reference value is computed from
closed forms, mpmath (high precision) or scipy, so that tests comparing the
solver against these values are genuinely independent checks.

The equation (on |s| < 1)

    a psi(s) + (b/pi) PV int_{-1}^{1} psi(t)/(t - s) dt + int k(s,t) psi(t) dt = f(s)

with psi = w phi, w(s) = (1 - s)^alpha (1 + s)^beta.  alpha0 in (0, 1) solves
cot(pi alpha0) = -a/b; right end "bounded": alpha = alpha0, "singular":
alpha = alpha0 - 1; left end "bounded": beta = 1 - alpha0, "singular":
beta = -alpha0; index kappa = -(alpha + beta).

Manufacturing f from a chosen smooth phi.  With H[g](s) := (1/pi) PV int g(t)/(t-s) dt,

    H[w phi](s) = phi(s) H[w](s) + (1/pi) int w(t) (phi(t) - phi(s))/(t - s) dt      (M1)

and the transform of the weight in closed form (Tricomi 1957, sec. 4.3;
Erdogan 1969, eq. (25); valid for alpha, beta > -1, alpha not an integer):

    H[w](s) = cot(pi alpha) w(s)
              - (2^{alpha+beta}/pi) Gamma(alpha) Gamma(beta+1)/Gamma(alpha+beta+1)
                * 2F1(1, -alpha-beta; 1-alpha; (1-s)/2)                               (T)

(verified against a singularity-subtracted mpmath quadrature of the principal
value in tests/sie/test_solve_manufactured.py::test_tricomi_formula).  Because
cot(pi alpha) = cot(pi alpha0) = -a/b, the terms a w phi + b cot(pi alpha) w phi
cancel *exactly*, and

    f(s) = b [ -C F(s) phi(s) + (1/pi) int w(t) (phi(t)-phi(s))/(t-s) dt ]
           + int k(s,t) w(t) phi(t) dt                                               (M2)

with C = 2^{alpha+beta} Gamma(alpha) Gamma(beta+1) / (pi Gamma(alpha+beta+1))
(= 0 when kappa = 1, since 1/Gamma(0) = 0) and F the (terminating, for
kappa <= 0) hypergeometric polynomial.  (M2) is smooth on [-1, 1] and free of
the a/b = 1e8 cancellation.

All exponent-dependent constants are computed in mpmath from alpha0, so that
e.g. alpha + 1 = alpha0 ~ 3e-9 (a/b = -1e8, singular right end) is known to
full relative precision; the regular integrals use a Gauss-Jacobi rule
computed by mpmath (Golub-Welsch at 40 digits) for the exact exponents, and
"divided differences" (phi(t)-phi(s))/(t-s) are evaluated in a
cancellation-free closed form for every phi in the catalogue, so the double
precision f is accurate to ~1e-15 relative at every s (including s close to a
quadrature node).  ``rhs_mp`` re-derives f(s) by brute force (mpmath.quad of
the principal value with the singularity subtracted, no use of (T)) for
cross-checking.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from typing import Callable, Optional

import numpy as np
from mpmath import mp

DPS = 40          # working precision of all mpmath computations here
NQUAD = 40        # Gauss-Jacobi nodes for the regular integrals (integrands are
                  # entire or have their nearest singularity at |t| = 3:
                  # error ~ (3 + sqrt 8)^(-2N) ~ 1e-61)

ENDS = ("bounded", "singular")


# ----------------------------------------------------------------------------
# catalogue of smooth densities phi
# ----------------------------------------------------------------------------

@dataclass(frozen=True)
class Phi:
    """A smooth phi with a numerically stable divided difference."""
    name: str
    f: Callable            # numpy, vectorised
    f_mp: Callable         # mpmath scalar
    divdiff: Callable      # (t, s) -> (phi(t) - phi(s))/(t - s), numpy, stable
    poly: Optional[tuple] = None   # monomial coefficients (low -> high) if polynomial

    def __repr__(self):
        return f"Phi({self.name})"


def _dd_exp(t, s):
    # (e^t - e^s)/(t - s) = e^s * expm1(d)/d,  d = t - s  (no cancellation)
    d = t - s
    with np.errstate(invalid="ignore", divide="ignore"):
        q = np.where(d == 0.0, 1.0, np.expm1(d) / np.where(d == 0.0, 1.0, d))
    return np.exp(s) * q


def _dd_inv3(t, s):
    # 1/(3-t) - 1/(3-s) = (t - s)/((3-t)(3-s))
    return 1.0 / ((3.0 - t) * (3.0 - s))


def _dd_cos2_cube(t, s):
    # cos 2t - cos 2s = -2 sin(t+s) sin(t-s);  t^3 - s^3 = (t-s)(t^2+ts+s^2)
    d = t - s
    return -2.0 * np.sin(t + s) * np.sinc(d / np.pi) + (t * t + t * s + s * s)


def poly_eval(c, x):
    y = np.zeros_like(np.asarray(x, dtype=float)) + c[-1]
    for ck in c[-2::-1]:
        y = y * x + ck
    return y


def poly_eval_mp(c, x):
    y = mp.mpf(c[-1])
    for ck in c[-2::-1]:
        y = y * x + ck
    return y


def poly_divdiff(c, t, s):
    """(p(t) - p(s))/(t - s) by the Horner recursion D_j = P_{j+1}(s) + t D_{j+1}."""
    t, s = np.broadcast_arrays(np.asarray(t, float), np.asarray(s, float))
    P = np.full(s.shape, float(c[-1]))      # P_n(s)
    D = np.zeros(s.shape)                   # D_n
    for ck in c[-2::-1]:
        D = P + t * D
        P = ck + s * P
    return D


POLY5 = (0.5, -1.0, 2.0, 0.25, 0.0, -0.75)      # 1/2 - s + 2 s^2 + s^3/4 - 3 s^5/4

PHIS = {
    "exp(s)": Phi("exp(s)", np.exp, mp.exp, _dd_exp),
    "1/(3-s)": Phi("1/(3-s)", lambda s: 1.0 / (3.0 - s), lambda s: 1 / (3 - s), _dd_inv3),
    "cos(2s)+s^3": Phi("cos(2s)+s^3", lambda s: np.cos(2 * s) + s ** 3,
                       lambda s: mp.cos(2 * s) + s ** 3, _dd_cos2_cube),
    "poly5": Phi("poly5", lambda s: poly_eval(POLY5, s),
                 lambda s: poly_eval_mp(POLY5, s),
                 lambda t, s: poly_divdiff(POLY5, t, s), POLY5),
}


# ----------------------------------------------------------------------------
# catalogue of regular kernels
# ----------------------------------------------------------------------------

@dataclass(frozen=True, eq=False)
class Kernel:
    name: str
    f: Callable                    # numpy, k(s, t) broadcasting
    f_mp: Optional[Callable] = None

    def __repr__(self):
        return f"Kernel({self.name})"


KERNELS = {
    None: None,
    "0.3exp(st)": Kernel("0.3exp(st)", lambda s, t: 0.3 * np.exp(s * t),
                         lambda s, t: mp.mpf("0.3") * mp.exp(s * t)),
    "cos(s-t)/2": Kernel("cos(s-t)/2", lambda s, t: 0.5 * np.cos(s - t),
                         lambda s, t: mp.cos(s - t) / 2),
}


# ----------------------------------------------------------------------------
# exponents
# ----------------------------------------------------------------------------

@dataclass(frozen=True)
class Exponents:
    a: float
    b: float
    left: str
    right: str
    alpha0: object      # mpf
    alpha: object       # mpf
    beta: object        # mpf
    kappa: int

    @property
    def alpha_f(self):
        return float(self.alpha)

    @property
    def beta_f(self):
        return float(self.beta)


@functools.lru_cache(maxsize=None)
def exponents(a: float, b: float, left: str, right: str) -> Exponents:
    """alpha0 = 1/2 + atan(a/b)/pi solves cot(pi alpha0) = -a/b in (0, 1)
    (cot(pi/2 + x) = -tan x).  Computed at DPS digits from the exact binary
    values of a and b, so 1 - alpha0 and alpha0 are both known to full relative
    precision even for |a/b| = 1e8."""
    if left not in ENDS or right not in ENDS:
        raise ValueError((left, right))
    with mp.workdps(DPS):
        r = mp.mpf(a) / mp.mpf(b)
        alpha0 = mp.mpf(1) / 2 + mp.atan(r) / mp.pi
        alpha = alpha0 if right == "bounded" else alpha0 - 1
        beta = 1 - alpha0 if left == "bounded" else -alpha0
        kappa = int(mp.nint(-(alpha + beta)))
        assert abs(mp.cot(mp.pi * alpha0) + r) <= mp.mpf(10) ** (-DPS + 12) * max(1, abs(r)) ** 2
    return Exponents(float(a), float(b), left, right, alpha0, alpha, beta, kappa)


def index_of(left: str, right: str) -> int:
    return {("singular", "singular"): 1, ("bounded", "singular"): 0,
            ("singular", "bounded"): 0, ("bounded", "bounded"): -1}[(left, right)]


# ----------------------------------------------------------------------------
# Tricomi's formula (T), in mpmath, general alpha, beta
# ----------------------------------------------------------------------------

def hilbert_weight_mp(alpha, beta, s):
    """(T): (1/pi) PV int (1-t)^alpha (1+t)^beta/(t-s) dt, |s| < 1."""
    alpha, beta, s = mp.mpf(alpha), mp.mpf(beta), mp.mpf(s)
    w = (1 - s) ** alpha * (1 + s) ** beta
    C = 2 ** (alpha + beta) / mp.pi * mp.gamma(alpha) * mp.gamma(beta + 1) * mp.rgamma(alpha + beta + 1)
    if C == 0:
        return mp.cot(mp.pi * alpha) * w
    return mp.cot(mp.pi * alpha) * w - C * mp.hyp2f1(1, -alpha - beta, 1 - alpha, (1 - s) / 2)


def hilbert_mp(alpha, beta, phi_mp, s):
    """Brute-force (1/pi) PV int w(t) phi(t)/(t - s) dt, independent of (T).

    PV int psi(t)/(t-s) dt = int (psi(t) - psi(s))/(t - s) dt + psi(s) log((1-s)/(1+s)).
    The remaining integral is split at t = s and written in the distances
    u = 1 + t, v = 1 - t to the end points (so that u^beta, v^alpha are exact);
    the end-point singularity u^beta g(-1) is subtracted and integrated in
    closed form (tanh-sinh cannot resolve u^(-1+eps) tails otherwise)."""
    alpha, beta, s = mp.mpf(alpha), mp.mpf(beta), mp.mpf(s)
    psi_s = (1 - s) ** alpha * (1 + s) ** beta * phi_mp(s)
    hl0 = 2 ** alpha * phi_mp(mp.mpf(-1)) / (-1 - s)
    hr0 = 2 ** beta * phi_mp(mp.mpf(1)) / (1 - s)

    cl, cr = 1 + s, 1 - s

    def gl(u):          # t = -1 + u,  u in (0, 1 + s);  t - s = u - cl
        d = u - cl
        if d == 0:      # a tanh-sinh node rounded onto t = s: zero weight anyway
            return mp.zero
        return ((2 - u) ** alpha * u ** beta * phi_mp(-1 + u) - psi_s) / d - hl0 * u ** beta

    def gr(v):          # t = 1 - v,   v in (0, 1 - s);  t - s = cr - v
        d = cr - v
        if d == 0:
            return mp.zero
        return (v ** alpha * (2 - v) ** beta * phi_mp(1 - v) - psi_s) / d - hr0 * v ** alpha

    total = (mp.quad(gl, [0, cl / 2, cl]) + hl0 * cl ** (beta + 1) / (beta + 1)
             + mp.quad(gr, [0, cr / 2, cr]) + hr0 * cr ** (alpha + 1) / (alpha + 1)
             + psi_s * mp.log(cr / cl))
    return total / mp.pi


def int_w_mp(alpha, beta, g, splits=()):
    """int_{-1}^{1} (1-t)^alpha (1+t)^beta g(t) dt for smooth g, by mpmath.quad in
    the end-point distances with the end-point values subtracted:
        int_0^1 u^beta h(u) du = h(0)/(beta+1) + int_0^1 u^beta (h(u) - h(0)) du.
    ``splits``: extra subdivision points in (0, 1) of u and v (for near poles)."""
    alpha, beta = mp.mpf(alpha), mp.mpf(beta)
    pts = [mp.mpf(0)] + sorted(mp.mpf(x) for x in splits) + [mp.mpf(1)]
    hl = lambda u: (2 - u) ** alpha * g(-1 + u)
    hr = lambda v: (2 - v) ** beta * g(1 - v)
    hl0, hr0 = hl(mp.mpf(0)), hr(mp.mpf(0))
    left = mp.quad(lambda u: u ** beta * (hl(u) - hl0), pts) + hl0 / (beta + 1)
    right = mp.quad(lambda v: v ** alpha * (hr(v) - hr0), pts) + hr0 / (alpha + 1)
    return left + right


# ----------------------------------------------------------------------------
# Gauss-Jacobi rule for the exact exponents
# ----------------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def gauss_jacobi_mp(a: float, b: float, left: str, right: str, n: int = NQUAD):
    """Nodes/weights for w(t) = (1-t)^alpha (1+t)^beta, computed by mpmath at DPS
    digits from the exact exponents.  Returns (t_mp, W_mp, t_float, W_float)."""
    e = exponents(a, b, left, right)
    with mp.workdps(DPS):
        X, W = mp.gauss_quadrature(n, "jacobi", e.alpha, e.beta)
        X, W = list(X), list(W)
        # sanity: zeroth moment = 2^{alpha+beta+1} B(alpha+1, beta+1)
        mu0 = 2 ** (e.alpha + e.beta + 1) * mp.beta(e.alpha + 1, e.beta + 1)
        assert abs(mp.fsum(W) - mu0) <= mp.mpf(10) ** (-DPS + 8) * mu0
    return (tuple(X), tuple(W), np.array([float(x) for x in X]), np.array([float(w) for w in W]))


def weight_integral_mp(e: Exponents):
    with mp.workdps(DPS):
        return 2 ** (e.alpha + e.beta + 1) * mp.beta(e.alpha + 1, e.beta + 1)


# ----------------------------------------------------------------------------
# the manufactured problem
# ----------------------------------------------------------------------------

@dataclass(eq=False)
class Problem:
    a: float
    b: float
    left: str
    right: str
    phi: Phi
    kernel: Optional[Kernel]
    e: Exponents = field(repr=False)
    C: float = field(repr=False)               # constant of (T)
    one_minus_alpha: float = field(repr=False)
    tq: np.ndarray = field(repr=False)
    Wq: np.ndarray = field(repr=False)
    integral: float = field(repr=False)        # int w phi (exact to ~1e-30, then rounded)
    abs_integral: float = field(repr=False)    # int w |phi|  (scale for integral errors)

    # -- exponents ----------------------------------------------------------
    @property
    def alpha(self):
        return self.e.alpha_f

    @property
    def beta(self):
        return self.e.beta_f

    @property
    def kappa(self):
        return self.e.kappa

    @property
    def total(self):
        """The side condition for kappa = 1 (None otherwise)."""
        return self.integral if self.kappa == 1 else None

    # -- reference functions (numpy, any shape) -------------------------------
    def w(self, s):
        s = np.asarray(s, float)
        return (1.0 - s) ** self.alpha * (1.0 + s) ** self.beta

    def psi(self, s):
        return self.w(s) * self.phi.f(np.asarray(s, float))

    def _CF(self, s):
        """C * 2F1(1, kappa; 1 - alpha; (1-s)/2) of (T); a polynomial for kappa <= 0,
        and C = 0 for kappa = 1."""
        if self.kappa == 1:
            return np.zeros_like(s)
        if self.kappa == 0:
            return np.full_like(s, self.C)
        # kappa = -1: 2F1(1, -1; c; z) = 1 - z/c
        return self.C * (1.0 - (1.0 - s) / (2.0 * self.one_minus_alpha))

    def _apply(self, s, fn):
        s = np.asarray(s, dtype=float)
        flat = s.reshape(-1)
        out = fn(flat[:, None])
        return np.asarray(out, float).reshape(s.shape)

    def regular(self, s):
        """(1/pi) int w(t)(phi(t) - phi(s))/(t - s) dt  (Gauss-Jacobi, stable divdiff)."""
        return self._apply(s, lambda S: (self.Wq * self.phi.divdiff(self.tq, S)).sum(axis=1) / np.pi)

    def kernel_term(self, s):
        """int k(s,t) w(t) phi(t) dt."""
        if self.kernel is None:
            return np.zeros_like(np.asarray(s, float))
        ph = self.phi.f(self.tq)
        return self._apply(s, lambda S: (self.Wq * ph * self.kernel.f(S, self.tq)).sum(axis=1))

    def smooth_part(self, s):
        """R(s) := H[w phi](s) - cot(pi alpha) w(s) phi(s)  (smooth on [-1, 1])."""
        s = np.asarray(s, float)
        return -self._CF(s) * self.phi.f(s) + self.regular(s)

    def hilbert(self, s):
        """H[w phi](s) = (1/pi) PV int w phi/(t - s) dt for |s| < 1, by (M1)+(T);
        cot(pi alpha) = -a/b exactly."""
        s = np.asarray(s, float)
        return (-self.a / self.b) * self.psi(s) + self.smooth_part(s)

    def rhs(self, s):
        """f(s) by (M2).  Vectorised, same shape out as in."""
        s = np.asarray(s, float)
        return self.b * self.smooth_part(s) + self.kernel_term(s)

    __call__ = rhs

    # -- brute-force mpmath versions for cross-checks -------------------------
    def rhs_mp(self, s):
        """f(s) = a psi(s) + b H[psi](s) + int k psi, all by mpmath.quad (no (T))."""
        e = self.e
        with mp.workdps(DPS):
            s = mp.mpf(s)
            psi_s = (1 - s) ** e.alpha * (1 + s) ** e.beta * self.phi.f_mp(s)
            val = mp.mpf(self.a) * psi_s + mp.mpf(self.b) * hilbert_mp(e.alpha, e.beta, self.phi.f_mp, s)
            if self.kernel is not None:
                val += int_w_mp(e.alpha, e.beta, lambda t: self.kernel.f_mp(s, t) * self.phi.f_mp(t))
            return val

    def integral_mp(self):
        with mp.workdps(DPS):
            return int_w_mp(self.e.alpha, self.e.beta, self.phi.f_mp)

    def cauchy_outside_mp(self, x, dps=DPS, splits=None):
        """(1/pi) int w(t) phi(t)/(t - x) dt for real |x| > 1, by mpmath.quad (with
        geometric subdivision towards the end point when x is close to it)."""
        e = self.e
        with mp.workdps(dps):
            x = mp.mpf(x)
            dist = abs(x) - 1
            if splits is None:
                splits = ([mp.mpf(10) ** k for k in range(-12, 0) if mp.mpf(10) ** k > dist / 10]
                          if dist < 0.5 else [])
            return int_w_mp(e.alpha, e.beta, lambda t: self.phi.f_mp(t) / (t - x), splits) / mp.pi

    def cauchy_outside_gauss(self, x):
        """The same by the DPS-digit Gauss-Jacobi rule (fine for x away from [-1, 1])."""
        X, W, _, _ = gauss_jacobi_mp(self.a, self.b, self.left, self.right)
        with mp.workdps(DPS):
            x = mp.mpf(x)
            return mp.fsum(w * self.phi.f_mp(t) / (t - x) for t, w in zip(X, W)) / mp.pi

    def jacobi_coefficients(self):
        """Exact coefficients c_k of a polynomial phi = sum c_k P_k^{(alpha,beta)}
        (scipy.special.eval_jacobi normalisation, = mpmath.jacobi), by
        interpolation at deg+1 Chebyshev points in DPS-digit arithmetic."""
        if self.phi.poly is None:
            raise ValueError("phi is not a polynomial")
        return _jacobi_coefficients(self.phi.poly, self.e)


@functools.lru_cache(maxsize=None)
def _jacobi_coefficients(poly, e: Exponents):
    d = len(poly) - 1
    with mp.workdps(DPS):
        xs = [mp.cos(mp.pi * (i + mp.mpf(1) / 2) / (d + 1)) for i in range(d + 1)]
        M = mp.matrix(d + 1, d + 1)
        rhs = mp.matrix(d + 1, 1)
        for i, x in enumerate(xs):
            for k in range(d + 1):
                M[i, k] = mp.jacobi(k, e.alpha, e.beta, x)
            rhs[i] = poly_eval_mp(poly, x)
        c = mp.lu_solve(M, rhs)
        return np.array([float(c[k]) for k in range(d + 1)])


@functools.lru_cache(maxsize=None)
def problem(a: float, b: float, left: str, right: str, phi: str, kernel=None) -> Problem:
    """Cached manufactured problem.  ``phi``: key of PHIS; ``kernel``: key of
    KERNELS or a Kernel instance."""
    ph = PHIS[phi]
    ker = KERNELS[kernel] if (kernel is None or isinstance(kernel, str)) else kernel
    e = exponents(a, b, left, right)
    X, W, tq, Wq = gauss_jacobi_mp(a, b, left, right)
    with mp.workdps(DPS):
        C = (2 ** (e.alpha + e.beta) / mp.pi * mp.gamma(e.alpha) * mp.gamma(e.beta + 1)
             * mp.rgamma(e.alpha + e.beta + 1))
        # exact Gauss-Jacobi sums at DPS digits (phi smooth; see NQUAD)
        integral = mp.fsum(w * ph.f_mp(x) for x, w in zip(X, W))
        abs_integral = mp.fsum(w * abs(ph.f_mp(x)) for x, w in zip(X, W))
        oma = 1 - e.alpha
    return Problem(float(a), float(b), left, right, ph, ker, e, float(C), float(oma), tq, Wq,
                   float(integral), float(abs_integral))


# ----------------------------------------------------------------------------
# small helpers for tests
# ----------------------------------------------------------------------------

def sample_points(m: int = 50, margin: float = 1e-3):
    """m points in (-1, 1): Chebyshev-like clustering towards the ends, plus
    irrational offsets so that they are not collocation nodes of anything."""
    k = np.arange(m)
    x = np.cos(np.pi * (k + 0.5 + 0.1234567) / (m + 0.2469134))
    return np.clip(x, -1 + margin, 1 - margin)


def digits(err: float, scale: float) -> float:
    """Number of correct significant digits, -log10(err/scale), capped at 17."""
    if err == 0:
        return 17.0
    return min(17.0, -math.log10(err / scale))
