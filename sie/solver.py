"""Gauss-Jacobi collocation for Cauchy singular integral equations of the second kind.

    a psi(s) + (b/pi) PV int_{-1}^{1} psi(t)/(t - s) dt + int_{-1}^{1} k(s,t) psi(t) dt = f(s)

psi = w phi, w(s) = (1-s)^alpha (1+s)^beta, phi = sum_k c_k P_k^{(alpha,beta)}.

The dominant operator maps the basis exactly (sie-math.md item 1; Erdogan,
Gupta & Cook 1973):

    a w P_k + b H[w P_k] = lambda P_{k-kappa}^{(-alpha,-beta)},
    lambda = -2^{-kappa} b / sin(pi alpha),   H[g](x) = (1/pi) PV int g(t)/(t-x) dt,

so the equation is projected onto P_m^{(-alpha,-beta)}, m < n - kappa, with the
Gauss-Jacobi rule of the weight (1-s)^{-alpha}(1+s)^{-beta} at n - kappa nodes;
that is collocation at the roots of P_{n-kappa}^{(-alpha,-beta)} (Krenk 1975).
Without a kernel the system is diagonal.  kappa = 1: the side condition
int psi = mu_0 c_0 = total closes it.  kappa = -1: the projection on m = 0 is
the solvability condition (Muskhelishvili 1953, sec. 110), reported as
``Solution.consistency``.

Right-hand sides with kinks: with ``breaks`` the projections are computed by a
composite rule split at the breaks (so the coefficients are exact to rounding)
and phi is evaluated pointwise by adding the exact inversion of the truncation
remainder r = g - Pi g (Muskhelishvili inversion formula, see
:func:`_inversion_phi`), which converges spectrally in the number of nodes per
piece.  Without ``breaks`` a kink costs algebraic convergence (the Jacobi series
of phi then decays only like k^{-2}).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .errors import (CallableOutputError, EvaluationPointError, InvalidBreakpointError,
                     InvalidCoefficientError, InvalidEndConditionError, SideConditionError,
                     call_checked, check_finite_real, check_order)
from .gaussjacobi import gauss_jacobi_cached
from .jacobi import jacobi_norms, jacobi_project, jacobi_series, jacobi_vandermonde
from .special import jacobi_end_values, jacobi_moment_shifted

__all__ = ["solve", "Solution", "sie_exponents", "Exponents", "dominant_functionals", "Functionals", "FunctionalsRule"]

END_CHOICES = ("bounded", "singular")
_EXTRA_PER_PIECE = 24       # extra nodes per piece of the composite rule (breaks)
_KERNEL_EXTRA = 16          # t-nodes beyond n for int k(s,t) psi(t) dt


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


# --------------------------------------------------------------------------
# validation helpers
# --------------------------------------------------------------------------
def _check_breaks(breaks):
    if isinstance(breaks, (tuple, list)) and len(breaks) == 0:
        return np.empty(0)
    try:
        br = np.asarray(breaks, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InvalidBreakpointError(f"breaks must be real numbers in (-1, 1), got {breaks!r}") from None
    if not (np.abs(br) < 1.0).all():           # also False for NaN
        raise InvalidBreakpointError(
            f"breaks must be finite points strictly inside (-1, 1), got {br.tolist()}")
    br = np.sort(br)
    if br.size > 1:                              # drop repeats (np.unique is slower here)
        br = br[np.concatenate(([True], np.diff(br) > 0.0))]
    return br


# --------------------------------------------------------------------------
# Gauss-Jacobi sums with the mass of a nearly non-integrable end taken out
# --------------------------------------------------------------------------
_NEAR_MINUS_ONE = 0.01   # e + 1 below this: the weight's end mass ~ 1/(e+1) is split off


@dataclass(frozen=True)
class _WeightedRule:
    """int (1-x)^a (1+x)^b g(x) dx  ~  sum_j omega_j g(x_j) + g(end) * corr.

    Plain Gauss-Jacobi (``end`` = 0, corr = 0) unless an exponent e has
    e + 1 < 0.01.  Then the weight carries a mass ~ 1/(e+1) next to that end and a
    Gauss sum loses eps * mass absolute, which the integrals we need cannot
    afford: they are O(1) because the integrand nearly vanishes there
    (P_k^{(a,b)}(+1) ~ (a+1)/k).  We split g(x) = g(end) + (end - x) r(x):

        int W g = g(end) mu_0 + int W |end - x| r,

    the first term with the exact moment and end value (from the exact e + 1),
    the second by the Gauss rule of the regular weight with e + 1 in place of e,
    rewritten as sum_j omega_j (g(x_j) - g(end)), omega_j = w'_j/|end - x_j|.
    """
    x: np.ndarray
    omega: np.ndarray
    end: int
    corr: float
    a: float
    b: float
    a_p1: float
    b_p1: float

    @classmethod
    def build(cls, q, a, b, a_p1, b_p1):
        if min(a_p1, b_p1) >= _NEAR_MINUS_ONE:
            x, w = gauss_jacobi_cached(q, a, b)
            return cls(x, w, 0, 0.0, a, b, a_p1, b_p1)
        mu0 = jacobi_moment_shifted(a_p1, b_p1)
        if a_p1 < b_p1:                       # the mass sits at x = +1
            x, w = gauss_jacobi_cached(q, a_p1, b)
            omega = w / (1.0 - x)
            end = 1
        else:
            x, w = gauss_jacobi_cached(q, a, b_p1)
            omega = w / (1.0 + x)
            end = -1
        return cls(x, omega, end, float(mu0 - omega.sum()), a, b, a_p1, b_p1)

    def end_values(self, n):
        """P_k^{(a,b)}(end), k < n, to full relative precision."""
        return jacobi_end_values(n, self.a_p1 if self.end > 0 else self.b_p1, self.end)

    def project(self, g, g_end, n):
        """sum_j omega_j g_j P_k(x_j) + g_end P_k(end) corr, k < n: <g, P_k>_W."""
        out = jacobi_project(self.omega * g, self.a, self.b, self.x, n)
        if self.end:
            out = out + (g_end * self.corr) * self.end_values(n)
        return out


# --------------------------------------------------------------------------
# quadrature for projections onto P_m^{(-alpha,-beta)}
# --------------------------------------------------------------------------
def _composite_rule(q, alpha, beta, breaks):
    """Nodes/weights for int (1-s)^alpha (1+s)^beta g(s) ds, g smooth on each piece.

    Pieces split at ``breaks``; the end pieces carry the endpoint singularity in
    their own Gauss-Jacobi rule ((0, beta) on the left, (alpha, 0) on the right),
    the other factor is smooth there and multiplies the weights.
    """
    edges = np.concatenate([[-1.0], breaks, [1.0]])
    xs, ws = [], []
    for i in range(len(edges) - 1):
        lo, hi = edges[i], edges[i + 1]
        half = 0.5 * (hi - lo)
        ea = alpha if i == len(edges) - 2 else 0.0
        eb = beta if i == 0 else 0.0
        u, wu = gauss_jacobi_cached(q, ea, eb)
        # s = lo + half (u + 1); (1-u)^ea (1+u)^eb carried by the rule
        s = lo + half * (u + 1.0)
        w = wu * half ** (1.0 + ea + eb)
        if ea == 0.0:  # the right end is not in this piece: (1-s)^alpha is smooth here
            w = w * (1.0 - s) ** alpha
        if eb == 0.0:
            w = w * (1.0 + s) ** beta
        xs.append(s)
        ws.append(w)
    return np.concatenate(xs), np.concatenate(ws)


# --------------------------------------------------------------------------
# the solution object
# --------------------------------------------------------------------------
@dataclass(eq=False)
class Solution:
    """Solution psi = w phi of the SIE; call it to evaluate psi.

    Attributes
    ----------
    alpha, beta : float
        Exponents of w(s) = (1-s)^alpha (1+s)^beta.
    kappa : int
        Index -(alpha + beta).
    n : int
        Number of Jacobi coefficients of phi.
    coefficients : ndarray
        c_k with phi = sum_k c_k P_k^{(alpha,beta)} (scipy's normalisation).
    consistency : float or None
        kappa = -1: the weighted mean of g = f - int k psi against
        (1-s)^{-alpha}(1+s)^{-beta}, i.e. int g w^{-1} ds / int w^{-1} ds, in
        units of f; zero iff the equation is solvable.  None for kappa != -1.
    a, b : float
        The coefficients of the equation.
    """
    alpha: float
    beta: float
    kappa: int
    n: int
    coefficients: np.ndarray
    consistency: float | None
    a: float
    b: float
    _exp: Exponents = field(repr=False)
    _matrix: np.ndarray | None = field(default=None, repr=False)
    _remainder_factory: object = field(default=None, repr=False)
    _remainder_cache: object = field(default=None, repr=False)

    @property
    def _remainder(self):
        """The breaks correction (:mod:`sie.remainder`), built on first use: a solve whose
        caller only needs ``integral()`` or ``consistency`` (the contact layer's root
        searches) never pays for it."""
        if self._remainder_cache is None and self._remainder_factory is not None:
            self._remainder_cache = self._remainder_factory()
        return self._remainder_cache

    # -- psi and phi ------------------------------------------------------
    def _points(self, s, name="s"):
        s = np.asarray(s, dtype=float)
        if not np.all(np.isfinite(s)):
            raise EvaluationPointError(f"{name} must be finite real numbers")
        return s

    def phi(self, s):
        """phi(s) = psi(s)/w(s) for s in [-1, 1] (a polynomial of degree n-1,
        plus the pointwise remainder correction when ``breaks`` were given)."""
        s = self._points(s)
        if np.any(np.abs(s) > 1.0):
            raise EvaluationPointError("phi is defined on [-1, 1]; got points outside")
        out = jacobi_series(self.coefficients, self.alpha, self.beta, s)
        if self._remainder is not None:
            out = out + self._remainder.phi(s)
        return out

    def weight(self, s):
        """w(s) = (1-s)^alpha (1+s)^beta."""
        s = np.asarray(s, dtype=float)
        return (1.0 - s) ** self.alpha * (1.0 + s) ** self.beta

    def __call__(self, s):
        """psi(s); zero outside [-1, 1]; a singular end itself raises."""
        s = self._points(s)
        inside = np.abs(s) < 1.0
        for end, expo in ((1.0, self.alpha), (-1.0, self.beta)):
            if expo < 0 and np.any(s == end):
                raise EvaluationPointError(
                    f"psi is infinite at s = {end:+g} (singular end, exponent {expo:.6g})")
        out = np.zeros(s.shape)
        ends = (np.abs(s) == 1.0)
        if np.any(inside):
            si = s[inside]
            out[inside] = self.weight(si) * self.phi(si)
        if np.any(ends):  # bounded ends: psi = 0 there
            out[ends] = 0.0
        return out

    # -- functionals -----------------------------------------------------
    def integral(self):
        """int_{-1}^{1} psi = mu_0 c_0 (orthogonality of P_k, k >= 1, to 1).

        Exact also with ``breaks``: the remainder correction inverts components
        P_m^{(-alpha,-beta)}, m >= n - kappa, into P_k^{(alpha,beta)}, k >= n >= 1,
        all orthogonal to 1 (and kappa = 1 fixes its null-space part to integral 0)."""
        total = jacobi_moment_shifted(self._exp.alpha_p1, self._exp.beta_p1) * self.coefficients[0]
        return float(total)

    def endpoint_value(self, end):
        """phi(+1) or phi(-1): the factor that stress-intensity factors are built from."""
        if end not in (1, -1):
            raise EvaluationPointError(f"end must be +1 or -1, got {end!r}")
        return float(self.phi(np.array([float(end)]))[0])

    @property
    def condition(self):
        """2-norm condition number of the (row-scaled) collocation system."""
        if self._matrix is None:
            return 1.0
        return float(np.linalg.cond(self._matrix))

    # -- Cauchy transform -------------------------------------------------
    def _dominant_image(self, x):
        """sum_k c_k P_{k-kappa}^{(-alpha,-beta)}(x)."""
        c = self.coefficients
        k = self.kappa
        if k == 1:
            cs = c[1:]
        elif k == 0:
            cs = c
        else:
            cs = np.concatenate([[0.0], c])
        return jacobi_series(cs, -self.alpha, -self.beta, x)

    def cauchy(self, x):
        """(1/pi) PV int_{-1}^{1} psi(t)/(t - x) dt for any real x != +-1.

        Inside: H[w P_k] = cot(pi alpha) w P_k - 2^{-kappa}/sin(pi alpha) P_{k-kappa}^{(-alpha,-beta)}
        (sie-math.md item 1).  Outside, near the interval: the same functions
        continued analytically, H[psi](x) = [G(x) - 2^{-kappa} sum c_k P_{k-kappa}^{(-alpha,-beta)}(x)] / sin(pi alpha),
        G(x) = (x-1)^alpha (x+1)^beta phi(x) for x > 1 and (-1)^kappa |x-1|^alpha |x+1|^beta phi(x)
        for x < -1 (the polynomial part of G at infinity is the second term);
        far away (where that difference cancels) a Gauss-Jacobi rule on the
        smooth integrand w phi/(t - x), sized from the Bernstein ellipse.
        """
        x = self._points(x, "x")
        if np.any(np.abs(x) == 1.0):
            raise EvaluationPointError(
                "the Cauchy transform is evaluated at x = +-1, where it is infinite or "
                "undefined; use points inside (-1, 1) or outside [-1, 1]")
        out = np.empty(x.shape)
        e = self._exp
        scale = 2.0 ** (-self.kappa)
        inside = np.abs(x) < 1.0
        if np.any(inside):
            xi = x[inside]
            out[inside] = e.cot * self(xi) - scale / e.sin * self._dominant_image(xi)
            if self._remainder is not None:
                out[inside] = self._remainder.cauchy_inside(xi, self(xi))
        outside = ~inside
        if np.any(outside):
            out[outside] = self._cauchy_outside(x[outside])
        return out

    def _cauchy_outside(self, x):
        e = self._exp
        ax = np.abs(x)
        rho_b = ax + np.sqrt((ax - 1.0) * (ax + 1.0))       # Bernstein ellipse through x
        # closed form loses ~ rho_b^(n) digits to cancellation; use it only while that is < 1e2
        near = self.n * np.log(rho_b) <= math.log(1e2)
        out = np.empty(x.shape)
        if np.any(near):
            xn = x[near]
            base = np.abs(xn - 1.0) ** self.alpha * np.abs(xn + 1.0) ** self.beta
            sign = np.where(xn < 0, (-1.0) ** self.kappa, 1.0)
            g = sign * base * jacobi_series(self.coefficients, self.alpha, self.beta, xn)
            out[near] = (g - 2.0 ** (-self.kappa) * self._dominant_image(xn)) / e.sin
        far = ~near
        if np.any(far):
            xf = x[far]
            # Gauss: error ~ rho_b^(-2 m) for the analytic part; the polynomial needs m >= n/2
            need = int(np.ceil(self.n / 2 + 40.0 / (2.0 * np.log(rho_b[far]).min()))) + 8
            t, w = gauss_jacobi_cached(max(need, self.n), self.alpha, self.beta)
            wf = w * jacobi_series(self.coefficients, self.alpha, self.beta, t)
            out[far] = (wf[None, :] / (t[None, :] - xf[:, None])).sum(axis=1) / math.pi
        if self._remainder is not None:
            out = out + self._remainder.cauchy_outside(x)
        return out


def _chop_noise(c, e, factor=256.0, run=8):
    """Zero the rounding-noise tail of a Jacobi series (plateau chopping).

    Coefficients are compared in an orthonormal scale |c_k| sqrt(h_k), with h_k
    the norms of the weight whose exponents are max(alpha, -1/2), max(beta, -1/2):
    the true h_0 ~ 1/(alpha+1) is 3e8 at alpha = -1 + 3e-9, which made c_0 look
    huge and chopped real digits at 1e-9.  Once ``run`` consecutive sizes lie
    below factor * eps * max, the series has resolved phi to rounding; what
    follows is noise from the projection (it grows with k, ~1e-12 at k = 4600,
    and P_k(1) ~ k^alpha amplifies it at the ends: unchopped, phi(+1) moved by
    3e-5 at n = 5000).  Slowly decaying series (kinked f) never reach the
    threshold and are left alone.  Cf. Aurentz & Trefethen, "Chopping a
    Chebyshev series", ACM TOMS 43 (2017).
    """
    if c.size <= run:
        return c
    size = np.abs(c) * np.sqrt(jacobi_norms(c.size, max(e.alpha, -0.5), max(e.beta, -0.5)))
    top = size.max()
    if top == 0.0:
        return c
    small = size <= factor * np.finfo(float).eps * top
    # first k with small[k:k+run] all True
    window = np.convolve(small.astype(int), np.ones(run, dtype=int), mode="valid")
    hits = np.flatnonzero(window == run)
    if hits.size == 0:
        return c
    c = c.copy()
    c[hits[0]:] = 0.0
    return c


def _kernel_projection(kernel, n, m_eq, e, rule, s, ws, h):
    """khat[m, k] = <int k(., t) w(t) P_k^{(alpha,beta)}(t) dt, P_m^{(-alpha,-beta)}> / h_m.

    Inner integral over t by the (end-corrected) Gauss rule of w; outer
    projection by the same rule as f (``rule``; None means the composite rule
    ``s, ws`` used with breaks).  Corrected ends need the kernel on the end
    lines s = +-1 or t = +-1, so it is evaluated on the grid augmented by them.
    """
    alpha, beta = e.alpha, e.beta
    trule = _WeightedRule.build(n + _KERNEL_EXTRA, alpha, beta, e.alpha_p1, e.beta_p1)
    s_end = rule.end if rule is not None else 0
    s_aug = np.concatenate([s, [float(s_end)]]) if s_end else s
    t_aug = np.concatenate([trule.x, [float(trule.end)]]) if trule.end else trule.x
    S, T = np.meshgrid(s_aug, t_aug, indexing="ij")
    kst = call_checked(kernel, "kernel", (S, T), S.shape)
    nt = trule.x.size
    Pt = jacobi_vandermonde(n, alpha, beta, trule.x)               # (nt, n)
    G = (kst[:, :nt] * trule.omega) @ Pt                          # (q[+1], n)
    if trule.end:
        G += np.outer(kst[:, nt], trule.corr * trule.end_values(n))
    q = s.size
    Ps = jacobi_vandermonde(m_eq, -alpha, -beta, s)               # (q, m_eq)
    khat = (Ps.T * ws) @ G[:q]
    if s_end:
        khat += np.outer(rule.corr * rule.end_values(m_eq), G[q])
    return khat / h[:, None]


def _check_equation(f, a, b, left, right):
    """Validate a, b, the end choices and f; return (a, b, exponents)."""
    a = check_finite_real("a", a, InvalidCoefficientError)
    b = check_finite_real("b", b, InvalidCoefficientError)
    if b == 0.0:
        raise InvalidCoefficientError(
            "b must be nonzero (b = 0 leaves no singular integral: the equation is not a Cauchy SIE)")
    for name, v in (("left", left), ("right", right)):
        if v not in END_CHOICES:
            raise InvalidEndConditionError(f'{name} must be "bounded" or "singular", got {v!r}')
    if f is not None and not callable(f):
        raise CallableOutputError(f"f must be a vectorised callable f(s), got {type(f).__name__}")
    return a, b, sie_exponents(a, b, left, right)


def _lambda(e, b):
    """lambda = -2^{-kappa} b / sin(pi alpha): a w P_k + b H[w P_k] = lambda P_{k-kappa}^{(-alpha,-beta)}."""
    return -(2.0 ** (-e.kappa)) * b / e.sin


def _project_rhs(f, e, m_eq, br, count):
    """f_m = <f, P_m^{(-alpha,-beta)}> / h_m for m < count, by the Gauss rule of m_eq nodes
    (end-mass corrected) or, with breaks, the composite rule.

    Returns (rule or None, nodes, weights, f at nodes, f_m, h_m)."""
    alpha, beta = e.alpha, e.beta
    h = jacobi_norms(count, -alpha, -beta)
    h[0] = jacobi_moment_shifted(e.alpha_m1, e.beta_m1)
    if br.size == 0:
        rule = _WeightedRule.build(m_eq, -alpha, -beta, e.alpha_m1, e.beta_m1)
        s, ws = rule.x, rule.omega
    else:
        rule = None
        s, ws = _composite_rule(m_eq + _EXTRA_PER_PIECE, -alpha, -beta, br)
    fs = call_checked(f, "f", (s,), s.shape)
    if rule is not None and rule.end:
        f_end = float(call_checked(f, "f", (np.array([float(rule.end)]),), (1,))[0])
        fhat = rule.project(fs, f_end, count) / h
    else:
        fhat = jacobi_project(ws * fs, -alpha, -beta, s, count) / h
    return rule, s, ws, fs, fhat, h


@dataclass(frozen=True)
class Functionals:
    """What a search over the interval needs, without forming the solution.

    integral : float or None
        int psi for kappa <= 0 (mu_0 c_0); None for kappa = 1 (it is the side condition).
    consistency : float or None
        kappa = -1: the solvability residual (as ``Solution.consistency``); None otherwise.
    alpha, beta : float
    kappa : int
    """
    integral: float | None
    consistency: float | None
    alpha: float
    beta: float
    kappa: int


def dominant_functionals(f, *, a, b, n, left, right, breaks=()):
    """int psi and the solvability residual of a psi + (b/pi) PV int psi/(t-s) dt = f,
    exactly as :func:`solve` (same rule, same n) would return them, at the cost of one
    Gauss sum: int psi = mu_0 c_0 with c_0 = f_0/lambda (kappa = 0) or f_1/lambda
    (kappa = -1), and the residual is f_0 (kappa = -1).

    For searches over the interval (free contact ends), where the full solution is only
    needed at the end.  No kernel.
    """
    a, b, e = _check_equation(f, a, b, left, right)
    n = check_order(n, 2 if e.kappa == 1 else 1)
    br = _check_breaks(breaks)
    kappa = e.kappa
    if kappa == 1:
        return Functionals(None, None, e.alpha, e.beta, 1)
    m_eq = n - kappa
    count = 1 if kappa == 0 else 2
    _, _, _, _, fhat, _ = _project_rhs(f, e, m_eq, br, count)
    mu0 = jacobi_moment_shifted(e.alpha_p1, e.beta_p1)
    lam = _lambda(e, b)
    if kappa == 0:
        return Functionals(float(mu0 * fhat[0] / lam), None, e.alpha, e.beta, 0)
    return Functionals(float(mu0 * fhat[1] / lam), float(fhat[0]), e.alpha, e.beta, -1)


class FunctionalsRule:
    """:func:`dominant_functionals` prepared once for fixed a, b, n and ends (no breaks).

    The Gauss rule, the norms and the end correction are built here; each call then costs
    one evaluation of f at the fixed nodes and two dot products.  For searches that try
    many right-hand sides of one equation (free contact ends).  ``rule(f)`` returns the same
    :class:`Functionals` as ``dominant_functionals(f, a=..., b=..., n=..., left=..., right=...)``.
    """

    def __init__(self, *, a, b, n, left, right):
        a, b, e = _check_equation(None, a, b, left, right)
        n = check_order(n, 2 if e.kappa == 1 else 1)
        self.a, self.b, self.n, self.exponents = a, b, n, e
        self.kappa = e.kappa
        if self.kappa == 1:
            return
        m_eq = n - self.kappa
        rule = _WeightedRule.build(m_eq, -e.alpha, -e.beta, e.alpha_m1, e.beta_m1)
        h = jacobi_norms(2, -e.alpha, -e.beta)
        h[0] = jacobi_moment_shifted(e.alpha_m1, e.beta_m1)
        x = rule.x
        p1 = (1.0 - e.alpha) + 0.5 * (2.0 - e.alpha - e.beta) * (x - 1.0)   # P_1^{(-alpha,-beta)}
        p_end = rule.end_values(2) if rule.end else np.zeros(2)
        self.nodes = x
        self.end = rule.end
        self._w = (rule.omega / h[0], rule.omega * p1 / h[1])
        self._w_end = (rule.corr * p_end[0] / h[0], rule.corr * p_end[1] / h[1])
        self._scale = jacobi_moment_shifted(e.alpha_p1, e.beta_p1) / _lambda(e, b)

    def __call__(self, f) -> Functionals:
        e = self.exponents
        if self.kappa == 1:
            return Functionals(None, None, e.alpha, e.beta, 1)
        if not callable(f):
            raise CallableOutputError(f"f must be a vectorised callable f(s), got {type(f).__name__}")
        fs = call_checked(f, "f", (self.nodes,), self.nodes.shape)
        f_end = 0.0
        if self.end:
            f_end = float(call_checked(f, "f", (np.array([float(self.end)]),), (1,))[0])
        f0 = float(self._w[0] @ fs + self._w_end[0] * f_end)
        if self.kappa == 0:
            return Functionals(self._scale * f0, None, e.alpha, e.beta, 0)
        f1 = float(self._w[1] @ fs + self._w_end[1] * f_end)
        return Functionals(self._scale * f1, f0, e.alpha, e.beta, -1)


# --------------------------------------------------------------------------
# the solver
# --------------------------------------------------------------------------
def solve(f, *, a, b, n, left, right, kernel=None, total=None, breaks=()):
    """Solve a psi + (b/pi) PV int psi/(t-s) dt + int k(s,t) psi(t) dt = f on (-1, 1).

    Parameters
    ----------
    f : callable
        Vectorised right-hand side f(s).
    a, b : float
        Coefficients; b != 0.  cot(pi alpha0) = -a/b fixes the exponents.
    n : int
        Number of Jacobi coefficients of phi (n >= 2 when kappa = 1).
    left, right : {"bounded", "singular"}
        Behaviour of psi at s = -1 and s = +1.
    kernel : callable, optional
        Smooth kernel k(s, t), vectorised over two arrays of equal shape.
    total : float, optional
        int psi; required when kappa = 1, rejected otherwise.
    breaks : sequence of float, optional
        Points in (-1, 1) where f or one of its derivatives jumps.

    Returns
    -------
    Solution

    Notes
    -----
    Collocation at the roots of P_{n-kappa}^{(-alpha,-beta)} (Erdogan, Gupta &
    Cook 1973; Krenk 1975): spectral convergence for analytic f and k.
    """
    a, b, e = _check_equation(f, a, b, left, right)
    if kernel is not None and not callable(kernel):
        raise CallableOutputError(f"kernel must be a callable k(s, t) or None, got {type(kernel).__name__}")
    kappa = e.kappa
    n = check_order(n, 2 if kappa == 1 else 1,
                    " for index 1 (both ends singular)" if kappa == 1 else "")
    if kappa == 1:
        if total is None:
            raise SideConditionError(
                "total (= int psi) is required when both ends are singular (index 1)")
        total = check_finite_real("total", total, SideConditionError)
    elif total is not None:
        raise SideConditionError(
            f"total must not be given for index {kappa} (it is only for both ends singular, index 1)")
    br = _check_breaks(breaks)

    alpha, beta = e.alpha, e.beta
    lam = _lambda(e, b)
    mu0 = jacobi_moment_shifted(e.alpha_p1, e.beta_p1)          # int w, exact
    m_eq = n - kappa                           # projected equations, m = 0..m_eq-1
    rule, s, ws, fs, fhat, h = _project_rhs(f, e, m_eq, br, m_eq)

    matrix = None
    if kernel is None:
        c = np.empty(n)
        if kappa == 1:
            c[0] = total / mu0
            c[1:] = fhat / lam
        elif kappa == 0:
            c[:] = fhat / lam
        else:
            c[:] = fhat[1:] / lam
        kc = None
    else:
        khat = _kernel_projection(kernel, n, m_eq, e, rule, s, ws, h)
        A = khat.copy()
        for m in range(m_eq):
            k = m + kappa
            if 0 <= k < n:
                A[m, k] += lam
        rhs = fhat.copy()
        if kappa == 1:
            side = np.zeros(n)
            side[0] = abs(lam)                           # row scaled like the others
            A = np.vstack([side, A])
            rhs = np.concatenate([[abs(lam) * total / mu0], rhs])
        elif kappa == -1:
            A, rhs = A[1:], rhs[1:]
        c = np.linalg.solve(A, rhs)
        matrix = A
        kc = khat @ c
    c = _chop_noise(c, e)
    consistency = None
    if kappa == -1:
        consistency = float(fhat[0] - (kc[0] if kc is not None else 0.0))

    sol = Solution(alpha=alpha, beta=beta, kappa=kappa, n=n, coefficients=c,
                   consistency=consistency, a=a, b=b, _exp=e, _matrix=matrix)
    if br.size:
        from .remainder import InversionRemainder
        sol._remainder_factory = lambda: InversionRemainder.build(sol, f, kernel, br, s, ws, fs,
                                                                  fhat, kc, lam)
    return sol
