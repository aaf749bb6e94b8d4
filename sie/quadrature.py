"""Gauss-Jacobi sums for projections: the end-mass-corrected rule and the composite rule
split at breaks."""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from ._jit import jit
from .gaussjacobi import gauss_jacobi_cached
from .jacobi import jacobi_project
from .special import jacobi_end_values, jacobi_moment_shifted

__all__ = ["WeightedRule", "composite_rule", "composite_weighted_rule"]


# --------------------------------------------------------------------------
# Gauss-Jacobi sums with the mass of a nearly non-integrable end taken out
# --------------------------------------------------------------------------
_NEAR_MINUS_ONE = 0.01   # e + 1 below this: the weight's end mass ~ 1/(e+1) is split off


@dataclass(frozen=True)
class WeightedRule:
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
def composite_rule(q, alpha, beta, breaks):
    """Nodes/weights for int (1-s)^alpha (1+s)^beta g(s) ds, g smooth on each piece.

    Pieces split at ``breaks`` (ascending); the end pieces carry the endpoint singularity
    in their own Gauss-Jacobi rule ((0, beta) on the left, (alpha, 0) on the right), the
    other factor is smooth there and multiplies the weights.
    """
    q, alpha, beta = int(q), float(alpha), float(beta)
    u, wu = _composite_table(q, alpha, beta)
    return _composite_nodes(np.ascontiguousarray(breaks, dtype=float), q, alpha, beta, u, wu)


def composite_weighted_rule(q, a, b, a_p1, b_p1, breaks):
    """:func:`composite_rule` as a :class:`WeightedRule`: with the mass of a nearly
    non-integrable end (a + 1 or b + 1 below 0.01) split off as :class:`WeightedRule` does,
    ``end`` and ``corr`` set; plain otherwise (``end`` = 0).

    The end piece then takes the Gauss-Jacobi rule of the exponent plus one (exact, from
    ``a_p1`` / ``b_p1``) with omega_j = w'_j / abs(end - x_j), the other pieces their plain
    weights, and corr = mu_0 - sum omega over all pieces: sum_j omega_j (g_j - g(end)) is
    int W (g - g(end)) piece by piece, and g(end) mu_0 is exact.  Without the split a Gauss
    sum loses eps times the end's mass ~ 1 / (e + 1): with an exponent 2e-8 from +-1 the
    projection g_0, and int psi with it, lost 1e-9 of itself."""
    x, w = composite_rule(q, a, b, breaks)
    if min(a_p1, b_p1) >= _NEAR_MINUS_ONE or len(breaks) == 0:
        return WeightedRule(x, w, 0, 0.0, a, b, a_p1, b_p1)
    q = int(q)
    x, omega = x.copy(), w.copy()
    if a_p1 < b_p1:                       # the mass sits at x = +1: the last piece
        lo, end, sl = float(breaks[-1]), 1, slice(x.size - q, x.size)
        u, wu = gauss_jacobi_cached(q, a_p1, 0.0)
        half = 0.5 * (1.0 - lo)
        t = lo + half * (u + 1.0)
        omega[sl] = wu * half ** (1.0 + a_p1) * (1.0 + t) ** b / (1.0 - t)
    else:                                 # at x = -1: the first piece
        hi, end, sl = float(breaks[0]), -1, slice(0, q)
        u, wu = gauss_jacobi_cached(q, 0.0, b_p1)
        half = 0.5 * (hi + 1.0)
        t = -1.0 + half * (u + 1.0)
        omega[sl] = wu * half ** (1.0 + b_p1) * (1.0 - t) ** a / (1.0 + t)
    x[sl] = t
    mu0 = jacobi_moment_shifted(a_p1, b_p1)
    return WeightedRule(x, omega, end, float(mu0 - omega.sum()), a, b, a_p1, b_p1)


@functools.lru_cache(maxsize=256)
def _composite_table(q, alpha, beta):
    """The rules :func:`composite_rule` takes its pieces from, one after the other (nodes,
    weights): Gauss-Legendre (inner pieces), Gauss-Jacobi (0, beta) (the left end piece),
    (alpha, 0) (the right one) and (alpha, beta) (one piece, no breaks), q nodes each."""
    rules = [gauss_jacobi_cached(q, ea, eb)
             for ea, eb in ((0.0, 0.0), (0.0, beta), (alpha, 0.0), (alpha, beta))]
    return np.concatenate([r[0] for r in rules]), np.concatenate([r[1] for r in rules])


@jit()
def _power(x, e):
    """x ** e as numpy forms it for an array x and a scalar e (its exact paths for
    e = 0.5, 2, 1, 0 and -1, pow elsewhere): the compiled rule's weights are numpy's."""
    if e == 0.5:
        return math.sqrt(x)
    if e == 2.0:
        return x * x
    if e == 1.0:
        return x
    if e == 0.0:
        return 1.0
    if e == -1.0:
        return 1.0 / x
    return x ** e


@jit()
def _composite_nodes(breaks, q, alpha, beta, tab_u, tab_w):
    """:func:`composite_rule` from the rules of :func:`_composite_table`."""
    pieces = breaks.shape[0] + 1
    x = np.empty(pieces * q)
    w = np.empty(pieces * q)
    for i in range(pieces):
        lo = -1.0 if i == 0 else breaks[i - 1]
        hi = 1.0 if i == pieces - 1 else breaks[i]
        half = 0.5 * (hi - lo)
        ea = alpha if i == pieces - 1 else 0.0
        eb = beta if i == 0 else 0.0
        # the rule (ea, eb): Legendre, left end, right end, or both
        o = q * ((1 if i == 0 else 0) + (2 if i == pieces - 1 else 0))
        scale = half ** (1.0 + ea + eb)
        for k in range(q):
            # s = lo + half (u + 1); (1-u)^ea (1+u)^eb carried by the rule
            s = lo + half * (tab_u[o + k] + 1.0)
            wk = tab_w[o + k] * scale
            if ea == 0.0:  # the right end is not in this piece: (1-s)^alpha is smooth here
                wk = wk * _power(1.0 - s, alpha)
            if eb == 0.0:
                wk = wk * _power(1.0 + s, beta)
            x[i * q + k] = s
            w[i * q + k] = wk
    return x, w
