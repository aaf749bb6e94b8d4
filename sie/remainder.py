"""Pointwise correction for right-hand sides with breaks (kinks, jumps in a derivative).

The collocation solution phi_N = sum_{k<n} c_k P_k^{(alpha,beta)} has exact
coefficients when the projections are computed by the composite rule, but its
truncation error decays only algebraically when f has a kink.  What is missing
is the inverse of the dominant operator applied to the projection remainder

    r = g - sum_{m<M} g_m P_m^{(-alpha,-beta)},     g = f - (coupling + kernel) psi_N,

which the Muskhelishvili inversion formula gives pointwise (the dominant identity of
Erdogan, Gupta & Cook 1973 applied to the weight 1/w; checked in tests):

    R[r] = w delta_phi,
    delta_phi(x) = -b/(a^2+b^2) [ I(x) + 2^kappa P_kappa^{(alpha,beta)}(x) r(x)/sin(pi alpha) ] + C,
    I(x) = (1/pi) int (1-t)^{-alpha}(1+t)^{-beta} (r(t) - r(x))/(t - x) dt,

with P_{-1} = 0 and C fixing int w delta_phi = 0 when kappa = 1 (the total is
carried by c_0).  I(x) is a regular integral whose integrand is smooth on each
piece between breaks, so the composite Gauss-Jacobi rule converges spectrally.
Two interleaved rules (q and q+1 nodes per piece) are kept, and each x uses the
one whose nearest node is farther away, so r(t) - r(x) never cancels badly.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import call_checked
from .gaussjacobi import gauss_jacobi_cached
from .jacobi import jacobi_series
from .special import jacobi_moment_shifted

__all__ = ["InversionRemainder"]


_GRADING = 0.15       # ratio of successive sub-intervals toward a break
_LEVELS = 19          # 0.15^19 ~ 2e-16 of the piece length is left ungraded


def graded_points(breaks):
    """Breaks plus points b +- d 0.15^k (k = 1.._LEVELS), d = half the gap to the
    neighbouring break or end: a geometric mesh toward each break (Babuska-Guo hp)."""
    edges = np.concatenate([[-1.0], breaks, [1.0]])
    pts = list(breaks)
    for i, c in enumerate(breaks, start=1):
        for side, other in ((-1.0, edges[i - 1]), (1.0, edges[i + 1])):
            d = 0.5 * abs(other - c)
            steps = d * _GRADING ** np.arange(1, _LEVELS + 1)
            # r is Lipschitz across a break, so an ungraded innermost piece of length
            # 1e-12 d costs at most ~1e-12; deeper pieces would not be resolvable in floats
            steps = steps[steps > max(1e-12 * d, 1e4 * np.finfo(float).eps)]
            pts.extend(c + side * steps)
            pts.append(c + side * d)
    pts = np.unique(np.asarray(pts, dtype=float))
    return pts[(pts > -1.0) & (pts < 1.0)]


_Q_SMALL = 16         # Gauss nodes on a graded sub-interval (pole at >= 1.15 its length)


def _graded_rule(q, alpha, beta, breaks, pts, q_small=_Q_SMALL, shift=0):
    """Composite rule for int (1-x)^alpha (1+x)^beta g on the graded mesh ``pts``:
    q (+ shift) nodes on the pieces that span most of a gap between breaks, fewer (in
    proportion to the piece, at least q_small) on the geometric sub-intervals next to a
    break.  End pieces carry their end's Jacobi weight in the rule; elsewhere it is smooth
    and multiplies the Gauss-Legendre weights."""
    edges = np.concatenate([[-1.0], pts, [1.0]])
    gaps = np.concatenate([[-1.0], breaks, [1.0]])
    los, his = edges[:-1], edges[1:]
    j = np.searchsorted(gaps, 0.5 * (los + his))
    gap = gaps[j] - gaps[j - 1]
    big = ((his - los) > 0.2 * gap) | (los == -1.0) | (his == 1.0)
    counts = np.where(big, q, q_small + np.ceil(q * (his - los) / gap).astype(int)) + shift
    xs, ws = [], []
    for qq in np.unique(counts):                 # all pieces with the same node count at once
        sel = counts == qq
        lo, hi = los[sel], his[sel]
        half = 0.5 * (hi - lo)
        inner = (lo != -1.0) & (hi != 1.0)
        if inner.any():                          # Gauss-Legendre times the smooth weight
            u, wu = gauss_jacobi_cached(int(qq), 0.0, 0.0)
            x = lo[inner, None] + half[inner, None] * (u + 1.0)
            w = (half[inner, None] * wu) * (1.0 - x) ** alpha * (1.0 + x) ** beta
            xs.append(x.ravel())
            ws.append(w.ravel())
        for i in np.flatnonzero(~inner):         # an end piece: its end's Jacobi weight
            ea = alpha if hi[i] == 1.0 else 0.0
            eb = beta if lo[i] == -1.0 else 0.0
            u, wu = gauss_jacobi_cached(int(qq), ea, eb)
            x = lo[i] + half[i] * (u + 1.0)
            w = wu * half[i] ** (1.0 + ea + eb)
            if hi[i] != 1.0:
                w = w * (1.0 - x) ** alpha
            if lo[i] != -1.0:
                w = w * (1.0 + x) ** beta
            xs.append(x)
            ws.append(w)
    x, w = np.concatenate(xs), np.concatenate(ws)
    order = np.argsort(x, kind="stable")
    return x[order], w[order]


def _end_grading(breaks):
    """Points 1 - d 0.15^k and -1 + d 0.15^k, d = half the distance to the nearest break."""
    edges = np.concatenate([[-1.0], breaks, [1.0]])
    out = []
    for end, nb in ((1.0, edges[-2]), (-1.0, edges[1])):
        d = 0.5 * abs(end - nb)
        steps = d * _GRADING ** np.arange(0, _LEVELS + 1)
        steps = steps[steps > max(1e-12 * d, 1e4 * np.finfo(float).eps)]
        out.extend(end - np.sign(end) * steps)
    return np.asarray(out)


@dataclass(eq=False)
class InversionRemainder:
    """delta_phi, its integral and Cauchy transform (see module docstring)."""
    sol: object                 # the IntervalSolution (polynomial part)
    a: float
    b: float
    f: object
    other: object               # coupling + kernel terms at local points, or None
    rules: list                 # [(s, ws, r_s)] for weight 1/w
    g_coef: np.ndarray          # projections g_m of g = f - other
    const: float = 0.0
    w_rule: tuple = ()
    _wphi: np.ndarray | None = None     # w_rule weights times delta_phi at its nodes

    @classmethod
    def build(cls, piece, a, b, f, other, breaks, s, ws, fs, g_coef):
        """``piece``: the :class:`sie.solution.IntervalSolution` (polynomial part);
        ``f``, ``other``: f and the coupling + kernel terms of the polynomial solution as
        callables of the local coordinate (``other`` None when there are none); ``s, ws, fs``:
        the composite projection rule and f there; ``g_coef``: projections of f - other."""
        self = cls(piece, a, b, f, other, [], g_coef)
        q = s.size // (breaks.size + 1)
        # I(x) for x close to a break c: in the neighbouring piece the integrand has a pole
        # at distance |x - c|, so the pieces are graded toward the breaks (Gauss-Legendre on
        # a geometric mesh resolves a pole at any distance; without it phi(c + 1e-3) was
        # off by 1e-4 at n = 24)
        pts = graded_points(breaks)
        alpha, beta = piece.alpha, piece.beta
        for shift in (0, 1):    # two interleaved rules: counts differ by one on every piece,
            # so no x (e.g. a piece midpoint, a node of every odd-count rule) is a node of both
            nodes, weights = _graded_rule(q, -alpha, -beta, breaks, pts, _Q_SMALL, shift)
            fvals = call_checked(f, "f", (nodes,), nodes.shape)
            self.rules.append((nodes, weights, self._r(nodes, fvals)))
        # rule for integrals against w: delta_phi behaves like (x - c) log|x - c| at a break c,
        # so the pieces are graded geometrically toward each break (hp quadrature; without
        # grading int psi converged only like n^-3: 2e-8 at n = 192)
        # also graded toward +-1: cauchy_outside(x) for x just outside an end has its pole
        # next to that end (x = 1.001 lost 5e-8 at n = 48 without it)
        self.w_rule = _graded_rule(max(q, 24), alpha, beta, breaks,
                                   np.union1d(pts, _end_grading(breaks)), _Q_SMALL + 2)
        if piece.kappa == 1:
            tw, ww = self.w_rule
            self.const = -float(ww @ self._phi_no_const(tw)) / jacobi_moment_shifted(
                piece.exp.alpha_p1, piece.exp.beta_p1)
        return self

    # g - Pi g at points x, given f(x)
    def _r(self, x, fx):
        sol = self.sol
        out = fx - jacobi_series(self.g_coef, -sol.alpha, -sol.beta, x)
        if self.other is not None:
            out = out - self.other(x)
        return out

    def _phi_no_const(self, x):
        sol = self.sol
        x = np.asarray(x, dtype=float)
        fx = call_checked(self.f, "f", (x,), x.shape)
        rx = self._r(x, fx)
        # per point, the rule whose nearest node is farther from x
        dist = [np.min(np.abs(nodes[None, :] - x[:, None]), axis=1) for nodes, _, _ in self.rules]
        choice = (dist[1] > dist[0]).astype(int)
        integral = np.empty(x.shape)
        for idx, (nodes, weights, r_nodes) in enumerate(self.rules):
            sel = choice == idx
            if np.any(sel):
                xs = x[sel]
                den = nodes[None, :] - xs[:, None]
                num = r_nodes[None, :] - rx[sel][:, None]
                # a node within rounding of x (only on the innermost graded pieces, whose
                # weights are ~1e-13): drop that term instead of dividing 0 by 0
                diff = np.divide(num, den, out=np.zeros_like(num), where=den != 0.0)
                integral[sel] = diff @ weights / math.pi
        k = sol.kappa
        if k == 1:
            pk = (sol.alpha + 1.0) + 0.5 * (sol.alpha + sol.beta + 2.0) * (x - 1.0)
        elif k == 0:
            pk = np.ones(x.shape)
        else:
            pk = np.zeros(x.shape)
        a, b = self.a, self.b
        return -b / (a * a + b * b) * (integral + 2.0 ** k * pk * rx / sol.exp.sin)

    def phi(self, x):
        return self._phi_no_const(x) + self.const

    def cauchy_inside(self, x, psi_full):
        """H[psi](x) = (g(x) - a psi(x)) / b, the equation itself, with the accurate psi."""
        gx = call_checked(self.f, "f", (x,), x.shape)
        if self.other is not None:
            gx = gx - self.other(x)
        return (gx - self.a * psi_full) / self.b

    def cauchy_outside(self, x):
        """(1/pi) int w delta_phi/(t - x) dt by the graded composite rule (x off [-1, 1])."""
        tw, ww = self.w_rule
        if self._wphi is None:
            self._wphi = ww * self.phi(tw)
        return (self._wphi[None, :] / (tw[None, :] - x[:, None])).sum(axis=1) / math.pi
