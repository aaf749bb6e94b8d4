"""Many one-interval dominant equations at once: the stages of :meth:`sie.Equation.solve`
along an equation's case axis.

    a_i psi_i(s) + (b_i/pi) PV int_{c_i}^{d_i} psi_i(t)/(t - s) dt = f(s),   i < B,

one interval each, no kernel, no breaks, the same end choices and the same n.  Each stage of
:func:`sie.solve` (exponents, the projection rule of (1-u)^{-alpha}(1+u)^{-beta}, the
projection of f, the diagonal solve lambda c_{m+kappa} = f_m) runs for all B equations in one
compiled loop, with f called once on all B sets of nodes.  Per equation the arithmetic is
that of :func:`sie.solve` (the same Gauss-Jacobi kernel, norms and recurrences; a sum may be
taken in another order, so results agree to rounding), and each equation's result does not
depend on the others in the batch.  For parameter sweeps, where the Python around a solve
of a few coefficients costs more than its arithmetic.  :class:`sie.Equation` validates the
cases and keeps one :class:`CaseRules` per n; the results are :class:`SolutionBatch` and
:class:`FunctionalsBatch`.

References: as for :func:`sie.solve` (Erdogan, Gupta & Cook 1973; Krenk 1975).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ._jit import jit
from .cauchy import _FORWARD_GROWTH, f0_parameter_row
from .cauchy_kernels import series_forward_limit, series_kernel
from .errors import EvaluationPointError, InvalidIntervalError, call_checked
from .gaussjacobi import N_BOUNDARY, _small_rule
from .intervals import Interval
from .jacobi import _jacobi_norms
from .quadrature import _NEAR_MINUS_ONE, WeightedRule
from .solution import IntervalSolution, Solution, equation_end_value
from .special import jacobi_moment_shifted

__all__ = ["CaseRules", "SolutionBatch", "FunctionalsBatch"]


# --------------------------------------------------------------------------
# compiled loops over the batch
# --------------------------------------------------------------------------
@jit()
def _rules(q, A, Bv, X, W, ok):
    """Gauss-Jacobi rules of (1-x)^A_i (1+x)^Bv_i with q nodes (the kernel of
    :func:`sie.gauss_jacobi` for small q); ok[i] False where it declines."""
    for i in range(A.shape[0]):
        x, w, good = _small_rule(q, A[i], Bv[i])
        ok[i] = good
        if good:
            X[i] = x
            W[i] = w


@jit()
def _norms(count, A, Bv, H):
    """h_m of P_m^{(A_i, Bv_i)}, m < count."""
    for i in range(A.shape[0]):
        H[i] = _jacobi_norms(count, A[i], Bv[i])


@jit(fastmath={"reassoc"})
def _dot(u, v):
    """sum_j u_j v_j, summed in vector lanes (``reassoc``: the order of the sum only)."""
    s = 0.0
    for j in range(u.shape[0]):
        s += u[j] * v[j]
    return s


@jit()
def _jacobi_start(a, b, x, p0, p1):
    """p0 <- P_0^{(a,b)}(x) = 1, p1 <- P_1^{(a,b)}(x), as :func:`sie.jacobi._vandermonde`
    (a + b + 2 as (a+1) + (b+1): no cancellation when both exponents are near -1)."""
    ap1 = a + 1.0
    abp2 = ap1 + (b + 1.0)
    for j in range(x.shape[0]):
        p0[j] = 1.0
        p1[j] = ap1 + 0.5 * abp2 * (x[j] - 1.0)


@jit()
def _jacobi_step(k, a, b, x, cur, prev):
    """prev <- P_{k+1}^{(a,b)}(x) from cur = P_k(x) and prev = P_{k-1}(x), k >= 1: the
    recurrence of :func:`sie.jacobi._vandermonde` (DLMF 18.9.1-2), the same arithmetic."""
    abp2 = (a + 1.0) + (b + 1.0)
    s = 2.0 * (k - 1) + abp2
    d = 2.0 * (k + 1) * ((k - 1) + abp2) * s
    A = (s + 1.0) * (s + 2.0) * s / d
    B = (s + 1.0) * (a * a - b * b) / d
    C = 2.0 * (k + a) * (k + b) * (s + 2.0) / d
    for j in range(x.shape[0]):
        prev[j] = (A * x[j] + B) * cur[j] - C * prev[j]


# The two kernels below run the recurrence over all points at once, one degree at a time:
# memory O(points) instead of a points x degrees Vandermonde matrix (at n = 20000 that was
# 3.2 GB per equation, and read down its columns: 20 s for one contact solve).
@jit()
def _project(count, A, Bv, X, OMEGA, F, out):
    """out[i, m] = sum_j OMEGA[i, j] F[i, j] P_m^{(A_i, Bv_i)}(X[i, j]), m < count."""
    q = X.shape[1]
    prev = np.empty(q)
    cur = np.empty(q)
    for i in range(A.shape[0]):
        x = X[i]
        wf = OMEGA[i] * F[i]
        _jacobi_start(A[i], Bv[i], x, prev, cur)
        if count > 0:
            out[i, 0] = _dot(wf, prev)
        if count > 1:
            out[i, 1] = _dot(wf, cur)
        for k in range(1, count - 1):
            _jacobi_step(k, A[i], Bv[i], x, cur, prev)
            prev, cur = cur, prev
            out[i, k + 1] = _dot(wf, cur)


@jit()
def _series(C, Al, Be, u, out):
    """out[i, j] = sum_k C[i, k] P_k^{(Al_i, Be_i)}(u_j) (summed in k, as written)."""
    n = C.shape[1]
    m = u.shape[0]
    prev = np.empty(m)
    cur = np.empty(m)
    for i in range(C.shape[0]):
        _jacobi_start(Al[i], Be[i], u, prev, cur)
        for j in range(m):
            out[i, j] = 0.0
            if n > 0:
                out[i, j] += C[i, 0] * prev[j]
            if n > 1:
                out[i, j] += C[i, 1] * cur[j]
        for k in range(1, n - 1):
            _jacobi_step(k, Al[i], Be[i], u, cur, prev)
            prev, cur = cur, prev
            for j in range(m):
                out[i, j] += C[i, k + 1] * cur[j]


@jit()
def _cauchy_limits(C, Al, Be, MU0, P, z, zm1, zp1, log_growth, cap, out):
    """out[i] = sum_k C[i, k] F_k(z) (the kernel of :func:`sie.cauchy.cauchy_series`; real z
    inside: H[psi] + i psi), each series cut after its last nonzero coefficient."""
    for i in range(C.shape[0]):
        last = 0
        for k in range(C.shape[1]):
            if C[i, k] != 0.0:
                last = k
        c = C[i, :last + 1].copy()
        lr = series_forward_limit(c, log_growth, cap)
        series_kernel(Al[i], Be[i], MU0[i], lr, z, zm1, zp1, P[i], c, out[i])


# --------------------------------------------------------------------------
# the stages
# --------------------------------------------------------------------------
class CaseRules:
    """The projection rules of B one-interval dominant equations
    a_i psi + (b_i/pi) PV int_{c_i}^{d_i} psi/(t - s) dt = f(s) with n coefficients each:
    stage 1 of the solve (exponents, Gauss-Jacobi rules of (1-u)^{-alpha}(1+u)^{-beta},
    their norms), which does not depend on the intervals, prepared once for all B.
    :meth:`functionals` and :meth:`solve` then take B intervals and f, as often as a search
    over the intervals needs.  Built by :class:`sie.Equation` (which validated a, b and the
    end choices) for each n it is solved with.

    Attributes
    ----------
    a, b : ndarray, shape (B,)
    alpha, beta : ndarray, shape (B,)
        Exponents of each psi_i at its right and left end.
    kappa : int
        The index, shared (the end choices are).
    n : int
    exponents : tuple of Exponents
    """

    def __init__(self, a, b, n, left, right, exps):
        from .solver import _check_n
        self._set(np.asarray(a, dtype=float), np.asarray(b, dtype=float),
                  _check_n(n, exps[0], ""), left, right, exps)

    def _set(self, a, b, n, left, right, exps, rule=None):
        B = a.size
        self.a, self.b, self.n, self.left, self.right, self.exponents = a, b, n, left, right, exps
        self.kappa = k = exps[0].kappa
        self.alpha = np.array([e.alpha for e in exps])
        self.beta = np.array([e.beta for e in exps])
        self.lam = -(2.0 ** (-k)) * b / np.array([e.sin for e in exps])   # dominant_lambda
        self.mu0 = np.array([jacobi_moment_shifted(e.alpha_p1, e.beta_p1) for e in exps])
        if rule is not None:
            self._x, self._omega, self._end, self._corr, self._norms = rule
            return
        q = n - k
        X, W = np.empty((B, q)), np.empty((B, q))
        end, corr = np.zeros(B, dtype=np.int64), np.zeros(B)
        ok = np.zeros(B, dtype=bool)
        plain = np.array([min(e.alpha_m1, e.beta_m1) >= _NEAR_MINUS_ONE for e in exps])
        A, Bv = np.ascontiguousarray(-self.alpha), np.ascontiguousarray(-self.beta)
        if 2 <= q <= 2 * N_BOUNDARY:
            _rules(q, A, Bv, X, W, ok)
            ok &= plain
        for i in np.flatnonzero(~ok).tolist():
            # a split-off end (an exponent within 0.01 of 1), or a size the kernel leaves
            # to the general rule
            e = exps[i]
            rule = WeightedRule.build(q, -e.alpha, -e.beta, e.alpha_m1, e.beta_m1)
            X[i], W[i], end[i], corr[i] = rule.x, rule.omega, rule.end, rule.corr
        H = np.empty((B, q))
        _norms(q, A, Bv, H)
        H[:, 0] = [jacobi_moment_shifted(e.alpha_m1, e.beta_m1) for e in exps]   # exact h_0
        self._x, self._omega, self._end, self._corr, self._norms = X, W, end, corr, H

    def __len__(self):
        return self.a.size

    def freeze(self) -> None:
        """Make every array read-only (rules shared between equations)."""
        for v in vars(self).values():
            if isinstance(v, np.ndarray):
                v.flags.writeable = False

    def take(self, indices) -> "CaseRules":
        """The equations at ``indices`` (in that order), their rules kept."""
        idx = np.asarray(indices, dtype=int).reshape(-1)
        out = CaseRules.__new__(CaseRules)
        out._set(self.a[idx], self.b[idx], self.n, self.left, self.right,
                 tuple(self.exponents[i] for i in idx.tolist()),
                 (self._x[idx], self._omega[idx], self._end[idx], self._corr[idx],
                  self._norms[idx]))
        return out

    # -- stage 2: the right-hand side ------------------------------------------------------
    def _sample(self, f, iv):
        """f at the real nodes of every equation (B, q), and at each split-off end."""
        c, d = iv[:, 0:1], iv[:, 1:2]
        X = 0.5 * (c + d) + 0.5 * (d - c) * self._x
        split = np.flatnonzero(self._end)
        pts = X.ravel()
        if split.size:
            pts = np.concatenate([pts, np.where(self._end[split] > 0, iv[split, 1],
                                                iv[split, 0])])
        v = call_checked(f, "f", (pts,), pts.shape)
        return v[:X.size].reshape(X.shape), v[X.size:]

    def _projections(self, f, iv, count):
        """<f, P_m^{(-alpha,-beta)}> / h_m, m < count, per equation, shape (B, count)."""
        F, f_end = self._sample(f, iv)
        out = np.empty((len(self), count))
        _project(count, np.ascontiguousarray(-self.alpha), np.ascontiguousarray(-self.beta),
                 self._x, self._omega, F, out)
        for k, i in enumerate(np.flatnonzero(self._end).tolist()):
            e = self.exponents[i]
            rule = WeightedRule(self._x[i], self._omega[i], int(self._end[i]),
                                float(self._corr[i]), -e.alpha, -e.beta, e.alpha_m1, e.beta_m1)
            out[i] += (f_end[k] * self._corr[i]) * rule.end_values(count)
        return out / self._norms[:, :count]

    # -- the functionals and the solution ----------------------------------------------------
    def functionals(self, f, iv) -> "FunctionalsBatch":
        """int psi_i and the solvability residual of each equation on its interval
        ``iv[i]`` (shape (B, 2)), from one Gauss sum each."""
        k = self.kappa
        if k == 1:
            return FunctionalsBatch(None, None, self.alpha, self.beta, 1)
        fhat = self._projections(f, iv, 1 if k == 0 else 2)
        scale = 0.5 * (iv[:, 1] - iv[:, 0]) * self.mu0 / self.lam
        if k == 0:
            return FunctionalsBatch(scale * fhat[:, 0], None, self.alpha, self.beta, 0)
        return FunctionalsBatch(scale * fhat[:, 1], fhat[:, 0].copy(), self.alpha, self.beta,
                                -1)

    def solve(self, f, iv, t=None) -> "SolutionBatch":
        """The solution of each equation on its interval ``iv[i]`` (shape (B, 2)); ``t``:
        int psi_i for index 1 (checked by the caller), else None."""
        B, k, n = len(self), self.kappa, self.n
        fhat = self._projections(f, iv, n - k)
        C = np.empty((B, n))
        cons = None
        if k == 1:
            C[:, 0] = t / (0.5 * (iv[:, 1] - iv[:, 0]) * self.mu0)
            C[:, 1:] = fhat / self.lam[:, None]
        elif k == 0:
            C[:] = fhat / self.lam[:, None]
        else:
            C[:] = fhat[:, 1:] / self.lam[:, None]
            cons = fhat[:, 0].copy()
        if n > 8:
            from .solver import _chop_noise
            for i, e in enumerate(self.exponents):
                C[i] = _chop_noise(C[i], e)
        C.setflags(write=False)
        return SolutionBatch(iv, self.a, self.b, self.alpha, self.beta, k, n, C, cons,
                             self.exponents, self.mu0, f)


# --------------------------------------------------------------------------
# functionals
# --------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class FunctionalsBatch:
    """int psi and the solvability residual of each equation of a case axis, without its
    solution (:meth:`sie.Equation.functionals`).

    Attributes
    ----------
    integral : ndarray, shape (B,)
        int_{c_i}^{d_i} psi_i for kappa <= 0; None for kappa = 1 (the side condition).
    consistency : ndarray, shape (B,) or None
        kappa = -1: the solvability residual of each (as ``Solution.consistency``).
    alpha, beta : ndarray, shape (B,)
        Exponents at the right and the left end.
    kappa : int
        The index (the same for all: the end choices are shared).

    References
    ----------
    As for :meth:`sie.Equation.functionals`.

    Examples
    --------
    >>> import sie
    >>> eq = sie.Equation(a=0.0, b=1.0, left="bounded", right="bounded",
    ...                   intervals=[[(-1.0, 1.0)]])
    >>> fb = eq.functionals(lambda s: 1.0 + 0.0 * s, n=4)
    >>> fb.kappa, round(float(fb.consistency[0]), 12)     # f = 1 is not solvable: residual 1
    (-1, 1.0)
    """
    integral: np.ndarray | None
    consistency: np.ndarray | None
    alpha: np.ndarray
    beta: np.ndarray
    kappa: int


# --------------------------------------------------------------------------
# solutions
# --------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class SolutionBatch:
    """The solutions of the B one-interval equations of a case axis
    (:meth:`sie.Equation.solve`); immutable.

    ``len(batch)`` is B; ``batch[i]`` is equation i's :class:`sie.Solution` (built on
    access, the same as :func:`sie.solve` with ``intervals=[(c_i, d_i)]`` returns, to
    rounding).  The array methods evaluate all B at once at the same local points.

    Attributes
    ----------
    intervals : ndarray, shape (B, 2)
    a, b : ndarray, shape (B,)
    alpha, beta : ndarray, shape (B,)
        Exponents at the right and the left end of each.
    kappa : int
        The shared index.
    n : int
        Jacobi coefficients per equation.
    coefficients : ndarray, shape (B, n)
        c_k of each phi_i = sum_k c_k P_k^{(alpha_i,beta_i)} (read-only).
    consistency : ndarray, shape (B,) or None
        kappa = -1: the solvability residual of each.
    exponents : tuple of Exponents
    mu0 : ndarray, shape (B,)
        int (1-u)^alpha_i (1+u)^beta_i du over [-1, 1] (exact).
    f : callable or None
        The right-hand side solved for (what :meth:`endpoint_values` evaluates at the
        singular ends); None for a batch built by :meth:`of`.

    References
    ----------
    As for :func:`sie.solve`.

    Examples
    --------
    >>> import numpy as np, sie
    >>> eq = sie.Equation(a=0.0, b=1.0, left="bounded", right="bounded",
    ...                   intervals=[[(-1.0, 1.0)], [(-2.0, 2.0)]])
    >>> sb = eq.solve(lambda s: -s, n=4)
    >>> np.round(sb.integral() / np.pi, 12).tolist()           # pi R^2 / 2
    [0.5, 2.0]
    >>> np.round(sb.phi_local(np.array([0.0])), 12).tolist()   # psi = sqrt(R^2 - s^2)
    [[1.0], [2.0]]
    """
    intervals: np.ndarray
    a: np.ndarray
    b: np.ndarray
    alpha: np.ndarray
    beta: np.ndarray
    kappa: int
    n: int
    coefficients: np.ndarray
    consistency: np.ndarray | None
    exponents: tuple
    mu0: np.ndarray
    f: object = field(default=None, repr=False)

    def __len__(self):
        return self.a.size

    def __getitem__(self, i) -> Solution:
        i = range(len(self))[i]
        c = self.coefficients[i]                    # a read-only view of the batch's array
        cons = None if self.consistency is None else float(self.consistency[i])
        c0, d0 = self.intervals[i].tolist()
        piece = IntervalSolution(Interval(c0, d0), self.exponents[i], self.n, c, cons, None,
                                 self._end_rhs(c0, d0))
        return Solution((piece,), float(self.a[i]), float(self.b[i]), True, None)

    def _end_rhs(self, c, d):
        """(f, abs(f)) at the ends c, d on call (None without f): the right-hand side at
        the ends, as :attr:`sie.IntervalSolution.end_rhs`."""
        f = self.f
        if f is None:
            return None

        def end_rhs():
            x = np.array([c, d])
            g = call_checked(f, "f", (x,), x.shape)
            return g, np.abs(g)
        return end_rhs

    @classmethod
    def of(cls, solutions) -> "SolutionBatch":
        """The batch of one-interval solutions without breaks (as :meth:`__getitem__` gives
        them), all with the same index and n."""
        pieces = [s.pieces[0] for s in solutions]
        if not pieces or any(len(s.pieces) != 1 or p.remainder is not None
                             for s, p in zip(solutions, pieces)):
            raise InvalidIntervalError("SolutionBatch.of takes solutions on one interval each, "
                                       "without breaks")
        exps = tuple(p.exp for p in pieces)
        if len({(e.kappa, p.n) for e, p in zip(exps, pieces)}) != 1:
            raise InvalidIntervalError("SolutionBatch.of takes solutions of one index and n")
        C = np.array([p.coefficients for p in pieces])
        C.setflags(write=False)
        cons = None if pieces[0].consistency is None else \
            np.array([p.consistency for p in pieces])
        return cls(np.array([(p.interval.c, p.interval.d) for p in pieces]),
                   np.array([s.a for s in solutions]), np.array([s.b for s in solutions]),
                   np.array([e.alpha for e in exps]), np.array([e.beta for e in exps]),
                   exps[0].kappa, pieces[0].n, C, cons, exps,
                   np.array([jacobi_moment_shifted(e.alpha_p1, e.beta_p1) for e in exps]))

    def take(self, indices) -> "SolutionBatch":
        """The batch of the equations at ``indices`` (in that order)."""
        idx = np.asarray(indices, dtype=int).reshape(-1)
        C = self.coefficients[idx]
        C.setflags(write=False)
        return SolutionBatch(self.intervals[idx], self.a[idx], self.b[idx], self.alpha[idx],
                             self.beta[idx], self.kappa, self.n, C,
                             None if self.consistency is None else self.consistency[idx],
                             tuple(self.exponents[i] for i in idx.tolist()), self.mu0[idx],
                             self.f)

    def integral(self) -> np.ndarray:
        """int psi_i over its interval, shape (B,): h_i mu_0 c_0."""
        h = 0.5 * (self.intervals[:, 1] - self.intervals[:, 0])
        return h * self.mu0 * self.coefficients[:, 0]

    def phi_local(self, u) -> np.ndarray:
        """phi_i at local points u of [-1, 1] (the same for all), shape (B, len(u))."""
        u = np.ascontiguousarray(u, dtype=float).ravel()
        out = np.empty((len(self), u.size))
        _series(self.coefficients, self.alpha, self.beta, u, out)
        return out

    def endpoint_values(self) -> np.ndarray:
        """phi_i at the local ends (-1, +1), shape (B, 2), as ``batch[i].endpoint_value``.

        For index 0, at the singular end from the equation there where that keeps more
        digits than the series (:func:`sie.solution.equation_end_value`: as the end's
        exponent tends to 0; f is called once more, at the B singular ends); elsewhere, and
        without ``f``, the series (:meth:`phi_local`)."""
        out = self.phi_local(np.array([-1.0, 1.0]))
        if self.kappa != 0 or self.f is None:
            return out
        left = self.beta < 0                      # the singular end of each equation
        x = np.where(left, self.intervals[:, 0], self.intervals[:, 1])
        g = call_checked(self.f, "f", (x,), x.shape)
        lam = -self.b / np.array([e.sin for e in self.exponents])      # dominant_lambda
        for end, sel in ((-1, left), (1, ~left)):
            if not np.any(sel):
                continue
            exps = [e for e, m in zip(self.exponents, sel) if m]
            eps = [e.beta if end < 0 else e.alpha for e in exps]
            eps_p1 = [e.beta_p1 if end < 0 else e.alpha_p1 for e in exps]
            value, better = equation_end_value(self.coefficients[sel], eps, eps_p1, end,
                                               g[sel], np.abs(g[sel]), lam[sel])
            rows = np.flatnonzero(sel)[better]
            out[rows, (end + 1) // 2] = value[better]
        return out

    def weight_local(self, u) -> np.ndarray:
        """(1 - u)^alpha_i (1 + u)^beta_i at local points u, shape (B, len(u))."""
        u = np.asarray(u, dtype=float).ravel()
        return (1.0 - u) ** self.alpha[:, None] * (1.0 + u) ** self.beta[:, None]

    def cauchy_limit_local(self, u) -> np.ndarray:
        """(1/pi) int_{-1}^{1} psi_i / (t - u - i0) dt at local points u strictly inside
        (-1, 1), shape (B, len(u)) complex: H[psi_i](u) + i psi_i(u) (Plemelj), each from
        its series' Cauchy transform (:func:`sie.jacobi_cauchy`), independent of the
        equation it solves."""
        u = np.ascontiguousarray(u, dtype=float).ravel()
        if not np.all(np.abs(u) < 1.0):
            raise EvaluationPointError("cauchy_limit_local needs points strictly inside (-1, 1)")
        z = u.astype(complex)
        P = np.array([f0_parameter_row(-self.kappa, e.alpha, e.alpha_m1, e.sin, e.alpha_p1,
                                       e.beta_p1, m0)
                      for e, m0 in zip(self.exponents, self.mu0.tolist())])
        out = np.empty((len(self), u.size), dtype=complex)
        _cauchy_limits(np.ascontiguousarray(self.coefficients), self.alpha, self.beta,
                       self.mu0, P, z, z - 1.0, z + 1.0, math.log(_FORWARD_GROWTH),
                       math.log(2.0), out)
        return out
