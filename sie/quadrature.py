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

__all__ = ["WeightedRule", "composite_rule", "composite_weighted_rule", "stacked_rules"]


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

    A piece that ends at a break close to an end it does not contain (a break 1e-4 from +1:
    the piece [-1, 1 - 1e-4]) sees that end's factor, singular or with a singular
    derivative, at a small fraction of its length, where q nodes no longer resolve it; such
    a piece is graded geometrically toward the break (:func:`_composite_pieces`), as the
    rule of a pole at that distance would be.  Elsewhere every piece has q nodes.
    """
    return _composite(int(q), float(alpha), float(beta), breaks)[:2]


def _composite(q, alpha, beta, breaks):
    """:func:`composite_rule` with its pieces: (x, w, lo, hi, counts)."""
    breaks = np.ascontiguousarray(breaks, dtype=float)
    los, his, counts, graded = _composite_pieces(breaks, q, _END_Q, _END_RATIO, _END_EXPONENT,
                                                 _COUNT_LADDER)
    if not graded:
        u, wu = _composite_table(q, alpha, beta)
        x, w = _composite_nodes(breaks, q, alpha, beta, u, wu)
        return x, w, los, his, counts
    extra = tuple(sorted({int(c) for c in counts} - {q}))
    u, wu, legendre, ends = _graded_table(q, alpha, beta, extra)
    x, w = _composite_graded_nodes(los, his, counts, alpha, beta, u, wu, legendre, ends)
    return x, w, los, his, counts


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
    q = int(q)
    x, w, los, his, _ = _composite(q, float(a), float(b), breaks)
    if min(a_p1, b_p1) >= _NEAR_MINUS_ONE or len(breaks) == 0:
        return WeightedRule(x, w, 0, 0.0, a, b, a_p1, b_p1)
    x, omega = x.copy(), w.copy()
    if a_p1 < b_p1:                       # the mass sits at x = +1: the last piece
        lo, end, sl = float(los[-1]), 1, slice(x.size - q, x.size)
        u, wu = gauss_jacobi_cached(q, a_p1, 0.0)
        half = 0.5 * (1.0 - lo)
        t = lo + half * (u + 1.0)
        omega[sl] = wu * half ** (1.0 + a_p1) * (1.0 + t) ** b / (1.0 - t)
    else:                                 # at x = -1: the first piece
        hi, end, sl = float(his[0]), -1, slice(0, q)
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


_END_RATIO = 4.0      # grading toward a break next to an end: sub-pieces see the end at
#                       >= 1/3 of their length (Bernstein parameter rho >= 3)
_END_Q = 16           # ... with at least this many nodes (3^-32 ~ 5e-16), or more where the
_END_EXPONENT = 36.0  # end is nearer: 2 count log(rho) >= 36 (e^-36 ~ 2e-16)
_COUNT_LADDER = 8     # counts set by a piece's angle rise in steps of 1/8 of their size


@jit()
def _log_rho_end(end, lo, hi):
    """log of the Bernstein-ellipse parameter of the end ``end`` (outside [lo, hi])."""
    u = abs(2.0 * end - (lo + hi)) / (hi - lo)
    return math.log(u + math.sqrt((u - 1.0) * (u + 1.0)))


@jit()
def _composite_pieces(breaks, q, q_small, ratio, exponent, ladder):
    """The pieces of :func:`composite_rule` (lo, hi, counts) and whether any is graded.

    The gaps between -1, the breaks and +1 are the pieces, q nodes each, unless q Gauss
    nodes do not resolve an end outside a gap (2 q log(rho) < ``exponent``, rho the
    Bernstein parameter of the end for the gap).  Such a gap [lo, hi] with hi = 1 - delta
    is split at 1 - delta ratio^j, j = 1, 2, ..., until the part left, [lo, 1 - delta
    ratio^J], is resolved by q nodes (likewise toward -1).  Its sub-pieces then see the end
    at >= 1/(ratio - 1) of their length and take max(c_end, k + min(q_small, k)) nodes (at
    most q): c_end from 2 c_end log(rho) >= ``exponent``, at least q_small, and k =
    q dtheta / 2, dtheta the angle the piece spans in s = cos(theta), for the polynomial
    part of the integrand (P_m(s) ~ cos(m theta), m < q), which next to an end varies on
    a scale far finer than the piece's length (as :func:`sie.remainder._piece_counts`),
    rounded up to a ladder of ``ladder`` steps per doubling.  The part left and the end
    pieces keep q (the end pieces carry their end's Gauss-Jacobi rule)."""
    nb = breaks.shape[0]
    cap = (nb + 1) * 130 + 2
    los = np.empty(cap)
    his = np.empty(cap)
    counts = np.empty(cap, dtype=np.int64)
    pts = np.empty(130)
    graded = False
    m = 0
    for i in range(nb + 1):
        lo = -1.0 if i == 0 else breaks[i - 1]
        hi = 1.0 if i == nb else breaks[i]
        k = 0
        pts[k] = lo
        k += 1
        # toward +1 (hi < 1) and toward -1 (lo > -1): points until the rest is resolved
        for end in (1.0, -1.0):
            inner = hi if end > 0.0 else lo
            outer = lo if end > 0.0 else hi
            if inner == end:
                continue
            p = inner
            while 2.0 * q * _log_rho_end(end, min(p, outer), max(p, outer)) < exponent:
                p = end - (end - p) * ratio
                if (p - outer) * end <= 0.0 or k >= 127:
                    break
                pts[k] = p
                k += 1
        pts[k] = hi
        k += 1
        if k == 2:
            los[m] = lo
            his[m] = hi
            counts[m] = q
            m += 1
            continue
        graded = True
        srt = np.sort(pts[:k])
        for j in range(k - 1):
            a, b = srt[j], srt[j + 1]
            if b <= a:
                continue
            if a == -1.0 or b == 1.0:
                cnt = q
            else:
                # the nearer end, and the count that resolves it
                lr = min(_log_rho_end(1.0, a, b), _log_rho_end(-1.0, a, b))
                cnt = max(q_small, int(math.ceil(0.5 * exponent / lr)))
                dtheta = math.acos(a) - math.acos(b)
                kk = int(math.ceil(0.5 * q * dtheta))
                poly = kk + min(q_small, kk)
                if poly > cnt:
                    step = max(1, poly // ladder)
                    cnt = step * ((poly + step - 1) // step)
                cnt = min(q, cnt)
            los[m] = a
            his[m] = b
            counts[m] = cnt
            m += 1
    return los[:m].copy(), his[:m].copy(), counts[:m].copy(), graded


@functools.lru_cache(maxsize=256)
def _graded_table(q, alpha, beta, extra):
    """The rules of a graded :func:`composite_rule` (nodes, weights): Gauss-Legendre with q
    nodes and with each count of ``extra``, and Gauss-Jacobi (0, beta), (alpha, 0) and
    (alpha, beta) with q nodes; with the offset of the Legendre rule of each count (-1:
    none) and the offsets of the three end rules."""
    return stacked_rules(sorted(set(extra) | {q}), q, alpha, beta)


def stacked_rules(counts, q_end, alpha, beta):
    """Gauss-Legendre rules with each of ``counts`` (ascending) nodes and Gauss-Jacobi
    (0, beta), (alpha, 0), (alpha, beta) with ``q_end`` nodes, concatenated for a compiled
    composite rule to take its pieces from: (nodes, weights, offset of the Legendre rule of
    each count (-1: none), offsets of the end rules at -1, at +1 and of one piece spanning
    both)."""
    rules = [gauss_jacobi_cached(c, 0.0, 0.0) for c in counts]
    rules += [gauss_jacobi_cached(q_end, 0.0, beta), gauss_jacobi_cached(q_end, alpha, 0.0),
              gauss_jacobi_cached(q_end, alpha, beta)]
    sizes = [r[0].size for r in rules]
    starts = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)
    legendre = np.full(max(counts) + 1, -1, dtype=np.int64)
    legendre[counts] = starts[:len(counts)]
    return (np.concatenate([r[0] for r in rules]), np.concatenate([r[1] for r in rules]),
            legendre, starts[len(counts):].copy())


@jit()
def _composite_graded_nodes(los, his, counts, alpha, beta, tab_u, tab_w, legendre, ends):
    """:func:`composite_rule` on the pieces of :func:`_composite_pieces` from the rules of
    :func:`_graded_table`.  On an inner piece 1 -+ s are formed from the piece's own
    distance to the end (full relative precision next to it)."""
    total = 0
    for i in range(los.shape[0]):
        total += counts[i]
    x = np.empty(total)
    w = np.empty(total)
    at = 0
    for i in range(los.shape[0]):
        lo, hi, cnt = los[i], his[i], counts[i]
        half = 0.5 * (hi - lo)
        left, right = lo == -1.0, hi == 1.0
        if left or right:
            o = ends[2] if (left and right) else (ends[1] if right else ends[0])
            ea = alpha if right else 0.0
            eb = beta if left else 0.0
            scale = half ** (1.0 + ea + eb)
            for k in range(cnt):
                s = lo + half * (tab_u[o + k] + 1.0)
                wk = tab_w[o + k] * scale
                if not right:
                    wk = wk * _power(1.0 - s, alpha)
                if not left:
                    wk = wk * _power(1.0 + s, beta)
                x[at + k] = s
                w[at + k] = wk
        else:
            o = legendre[cnt]
            for k in range(cnt):
                uk = tab_u[o + k]
                one_minus = (1.0 - hi) + half * (1.0 - uk)
                one_plus = (1.0 + lo) + half * (1.0 + uk)
                x[at + k] = lo + half * (uk + 1.0)
                w[at + k] = (half * tab_w[o + k]) * _power(one_minus, alpha) * \
                    _power(one_plus, beta)
        at += cnt
    return x, w
