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

Transforms of Psi = w delta_phi.  Psi solves a Psi + b H[Psi] = r on (-1, 1) (for
kappa = -1 too: the sum above includes m = 0, so r has weighted mean zero), and r is
orthogonal to P_m^{(-alpha,-beta)} for m < M = n - kappa, so the moments int Psi t^j
vanish for j < n (the polynomial part carries them) and the Cauchy transform of Psi decays
like z^-(n+1).  The sectionally holomorphic solution of the Riemann-Hilbert problem of the
equation (Muskhelishvili 1953, sec. 107-110) is then

    (1/pi) int Psi(t)/(t - z) dt = -(sin(pi alpha)/b) G(z) J(z),
    G(z) = (z-1)^alpha (z+1)^beta,   J(z) = (1/pi) int (1-t)^-alpha (1+t)^-beta r(t)/(t - z) dt

(principal powers, cut on [-1, 1]; G+/G- = e^{2 pi i alpha} = -(b + i a)/(b - i a) is the
jump the equation asks for, and a polynomial multiple of G cannot be added because of the
decay).  J involves r only, which is cheap and has no singularity but its kinks at the
breaks; next to the interval it is computed with r(x0) subtracted (x0 the point of
[-1, 1] nearest z) and r(x0) times the weight transform in closed form added back, on pieces
graded geometrically toward x0 down to |z - x0|.  Away from the interval the fixed rule
``w_rule`` summed over Psi at its nodes is used where it resolves 1/(t - z) (Bernstein
ellipses).  The logarithmic potential V(x) = (1/pi) int Psi log|x - t| dt: outside the
interval (and at its ends) by ``w_rule`` with delta_phi at the nearer end subtracted (the
closed form of the weight's potential adds it back), its nodes grouped in clusters whose
distances to that end span a factor 2, each summed by the expansion of log(D + d) about
its centre (one logarithm per cluster, :func:`_log_sums`); inside from V' = -H[Psi] =
(a Psi - r)/b integrated from the nearer end.  For a stated accuracy (the ``tol`` of
:meth:`sie.Solution.log_potential`) the rule for integrals against w is made for it
(:func:`_accuracy_rule`: graded less deeply toward the breaks, fewer nodes on the graded
pieces), which cuts the evaluations of delta_phi by more than half.
"""
from __future__ import annotations

import copy
import functools
import math
from dataclasses import dataclass, field

import numpy as np

from ._jit import jit
from .cauchy import _FAR_TERMS, Weight, _log_ratio, f0_closed, l0
from .errors import call_checked
from .gaussjacobi import gauss_jacobi_cached
from .jacobi import jacobi_series
from .quadrature import _COUNT_LADDER, _END_EXPONENT, _composite_pieces, _power, stacked_rules
from .special import jacobi_moment_shifted
from .unknowns import _EXTRA_PER_PIECE

__all__ = ["InversionRemainder", "log_far"]


_GRADING = 0.15       # ratio of successive sub-intervals toward a break
_BLOCK = 1 << 20      # entries of one points-by-nodes block (8 MiB)
_LEVELS = 19          # 0.15^19 ~ 2e-16 of the piece length is left ungraded


_POWERS = _GRADING ** np.arange(1, _LEVELS + 1)    # 0.15^k, k = 1.._LEVELS
_FLOOR = 1e4 * np.finfo(float).eps                # the shortest graded step
_DEPTH = 1e-12        # the grading stops at pieces this long relative to d (below)


def graded_points(breaks, depth=_DEPTH):
    """Breaks plus points b +- d 0.15^k (k = 1.._LEVELS, while d 0.15^k > depth d), d =
    half the gap to the neighbouring break or end: a geometric mesh toward each break
    (Babuska-Guo hp).  Ascending, inside (-1, 1)."""
    return _graded_points(np.ascontiguousarray(breaks, dtype=float), _POWERS, _FLOOR,
                          float(depth))


@jit()
def _graded_points(breaks, powers, floor, depth):
    """:func:`graded_points` (``powers``: 0.15^k; ``floor``: the shortest step; ``depth``:
    the shortest step relative to d)."""
    nb = breaks.shape[0]
    out = np.empty(nb * (2 * powers.shape[0] + 3))
    m = 0
    for i in range(nb):
        out[m] = breaks[i]
        m += 1
    for i in range(nb):
        c = breaks[i]
        for side in (-1.0, 1.0):
            if side < 0.0:
                other = breaks[i - 1] if i > 0 else -1.0
            else:
                other = breaks[i + 1] if i < nb - 1 else 1.0
            d = 0.5 * abs(other - c)
            # r is Lipschitz across a break, so an ungraded innermost piece of length
            # 1e-12 d (_DEPTH) costs at most ~1e-12; deeper pieces would not be resolvable
            # in floats
            least = max(depth * d, floor)
            for k in range(powers.shape[0]):
                step = d * powers[k]
                if step > least:
                    out[m] = c + side * step
                    m += 1
            out[m] = c + side * d
            m += 1
    pts = np.unique(out[:m])
    keep = (pts > -1.0) & (pts < 1.0)
    return pts[keep]


_Q_SMALL = 16         # Gauss nodes on a graded sub-interval (pole at >= 1.15 its length)
_HP_SLOPE = 1.0       # ... one node fewer per level of the grading deeper toward a break,
_HP_MIN = 4  # down to this many


def _panels(q, breaks, pts, q_small=_Q_SMALL, shift=0):
    """The pieces of the graded mesh ``pts`` and their node counts: q (+ shift) on the
    pieces that span most of a gap between breaks, fewer on the geometric sub-intervals next
    to a break or an end: q_small plus one per 1/q of the gap; next to a break one fewer
    (_HP_SLOPE) per level deeper than the outermost, at least _HP_MIN (+ shift), except on
    the innermost piece at the break itself.  Returns (lo, hi, counts).

    Toward a break the counts fall with depth as in hp refinement (Babuska & Guo): a piece
    k levels deep is 0.15^k as long as the outermost, the weight is smooth there and the
    integrands bounded, so what its rule misses scales with its length times rho^(-2 count),
    rho = 2.26 for a singularity at the break (0.15 of its length away); one node fewer per
    level (rho^2 = 5.1 < 1 / 0.15) keeps each level's error below that of the level before.
    The innermost piece is where the grading stops (at 1e-12 of the gap): a point inside
    it sees the other side's innermost piece within that piece's length, which then needs
    its full count.  Toward an end the weight (1 -+ x)^e may be singular (e < 0): a piece's share then falls
    only like its length^(1 + e), and the counts stay.  Checked against a rule with twice the nodes on every piece
    (tests/sie/test_remainder_rules.py): delta_phi and the log potential of w delta_phi
    agree to rounding with and without the hp counts.

    Whatever the depth, a piece also gets k + min(q_small, k) nodes (up to q), k = q dtheta / 2,
    dtheta the angle it spans in x = cos(theta): the integrands carry the projection's
    polynomial part, of degree ~q, which oscillates like cos(q theta) and needs about that
    many whatever the pole does.  Away from the ends this is below the counts above
    (dtheta ~ length); next to an end the angle falls only like the square root of the
    length, and without it a break 1e-2 to 1e-6 from an end left phi off by 1e-10 to 2e-8
    at n = 768 to 3072
    (tests/sie/test_breaks_near_ends.py)."""
    return _graded_rule(q, 0.0, 0.0, breaks, pts, q_small, shift, details=True)[5:]


@functools.lru_cache(maxsize=64)
def _rule_table(q, q_small, shift, alpha, beta, extra=()):
    """The Gauss rules that the pieces of :func:`_panels` may ask for, concatenated (nodes,
    weights): Gauss-Legendre with every count a graded piece of a mesh away from the ends
    may have (_HP_MIN + shift up to one more than q_small + shift + 0.2 q), with the counts
    ``extra`` (those of pieces near an end, :func:`_piece_counts`) and with q + shift
    nodes, and Gauss-Jacobi with q + shift nodes for an end piece (at -1, at +1, and one
    piece spanning both).  Returns (u, w, offset of the Legendre rule of each count (-1:
    none), offsets of the end rules at -1, at +1 and of both)."""
    qq = q + shift
    top = _table_top(q, q_small, shift)
    counts = sorted(set(range(min(_HP_MIN, q_small + 1) + shift, top)) | {qq} | set(extra))
    return stacked_rules(counts, qq, alpha, beta)


def _table_top(q, q_small, shift):
    """One more than the largest count of :func:`_rule_table`'s range of Legendre rules."""
    return q_small + shift + math.ceil(0.2 * q) + 2


def _graded_rule(q, alpha, beta, breaks, pts, q_small=_Q_SMALL, shift=0, details=False,
                 hp_slope=None, innermost=True, q_end=None):
    """Composite rule for int (1-x)^alpha (1+x)^beta g on the graded mesh ``pts``, with the
    node counts of :func:`_panels` (``hp_slope``: nodes fewer per level deeper toward a
    break, _HP_SLOPE where None; ``innermost`` False: the innermost piece at a break counted as the level it
    lies at, where no point is asked for inside it; ``q_end``: q_small of the pieces graded
    toward an end, and the nodes a piece gets beyond q dtheta / 2 for the projection's
    polynomial part, q_small where None).  End pieces carry their end's Jacobi
    weight in the rule; elsewhere it is smooth and multiplies the Gauss-Legendre weights.

    Returns the ascending nodes and their weights; with ``details`` also, per node, the
    index of its piece and 1 - x, 1 + x to full relative precision (a node of a piece
    1e-12 wide at an end can round onto the end itself), and per piece its ends and node
    count."""
    q, q_small, shift, alpha, beta = int(q), int(q_small), int(shift), float(alpha), float(beta)
    pts = np.ascontiguousarray(pts, dtype=float)
    gaps = np.concatenate([[-1.0], np.asarray(breaks, dtype=float), [1.0]])
    slope = _HP_SLOPE if hp_slope is None else float(hp_slope)
    los, his, counts = _piece_counts(pts, gaps, q, q_small, shift, slope, _HP_MIN,
                                     math.log(1.0 / _GRADING), bool(innermost),
                                     q_small if q_end is None else int(q_end))
    top = _table_top(q, q_small, shift)
    extra = tuple(sorted({int(c) for c in counts if c >= top and c != q + shift}))
    u, wu, legendre, ends = _rule_table(q, q_small, shift, alpha, beta, extra)
    out = _graded_nodes(los, his, counts, alpha, beta, u, wu, legendre, ends)
    return out if details else out[:2]


_LADDER = 8           # counts set by a piece's angle rise in steps of 1/8 of their size


@jit()
def _piece_counts(pts, gaps, q, q_small, shift, hp_slope, hp_min, log_ratio, keep_innermost,
                  q_end):
    """The pieces of the mesh ``pts`` (lo, hi) and their node counts (:func:`_panels`).
    ``gaps``: -1, the breaks, +1; ``hp_slope``, ``hp_min``: the counts' fall with depth;
    ``log_ratio``: log(1 / _GRADING); ``keep_innermost``: the innermost piece at a break
    keeps its count; ``q_end``: q_small of the pieces graded toward an end, and the nodes
    beyond k for the polynomial part (below)."""
    npc = pts.shape[0] + 1
    los = np.empty(npc)
    his = np.empty(npc)
    counts = np.empty(npc, dtype=np.int64)
    for i in range(npc):
        lo = -1.0 if i == 0 else pts[i - 1]
        hi = 1.0 if i == npc - 1 else pts[i]
        j = np.searchsorted(gaps, 0.5 * (lo + hi))
        gap = gaps[j] - gaps[j - 1]
        if (hi - lo) > 0.2 * gap or lo == -1.0 or hi == 1.0:
            cnt = q
        else:
            # graded toward a break (not toward an end, where the weight may be singular):
            # one node fewer per level below the outermost graded piece (~0.064 of the gap)
            mid = 0.5 * (lo + hi)
            toward_end = (j == 1 and mid - gaps[0] < gaps[1] - mid) or \
                (j == gaps.shape[0] - 1 and gaps[j] - mid < mid - gaps[j - 1])
            cnt = (q_end if toward_end else q_small) + int(math.ceil(q * (hi - lo) / gap))
            # the innermost piece, at the break itself, keeps its count: the grading stops
            # there, and a point inside it sees the other side's innermost piece within
            # its own length
            innermost = keep_innermost and (lo == gaps[j - 1] or hi == gaps[j])
            if not (toward_end or innermost):
                level = math.floor(math.log(0.2 * gap / (hi - lo)) / log_ratio)
                cnt = max(hp_min, cnt - int(math.floor(hp_slope * level)))
            # the projection's polynomial part, cos(q theta)-like: k = q dtheta / 2 nodes
            # and min(q_end, k) more at any depth (:func:`_panels`), rounded up to a
            # ladder of _LADDER steps per doubling (fewer distinct rules), at most q (which
            # integrates it exactly)
            dtheta = math.acos(max(lo, -1.0)) - math.acos(min(hi, 1.0))
            kappa = int(math.ceil(0.5 * q * dtheta))
            poly = kappa + min(q_end, kappa)
            if poly > cnt:
                step = max(1, poly // _LADDER)
                cnt = min(q, step * ((poly + step - 1) // step))
        los[i] = lo
        his[i] = hi
        counts[i] = cnt + shift
    return los, his, counts


@jit()
def _graded_nodes(los, his, counts, alpha, beta, tab_u, tab_w, legendre, ends):
    """:func:`_graded_rule` with its details: (x, w, piece, 1 - x, 1 + x, lo, hi, counts),
    on the pieces ``los``, ``his`` with ``counts`` (:func:`_piece_counts`); ``tab_u``,
    ``tab_w``, ``legendre``, ``ends``: the rules of :func:`_rule_table`."""
    npc = los.shape[0]
    total = 0
    for i in range(npc):
        total += counts[i]
    x = np.empty(total)
    w = np.empty(total)
    piece = np.empty(total, dtype=np.int64)
    om = np.empty(total)
    op = np.empty(total)
    at = 0
    for i in range(npc):
        lo, hi, cnt = los[i], his[i], counts[i]
        half = 0.5 * (hi - lo)
        left, right = lo == -1.0, hi == 1.0
        if left or right:                    # an end piece: its end's weight in the rule
            o = ends[2] if (left and right) else (ends[1] if right else ends[0])
            ea = alpha if right else 0.0
            eb = beta if left else 0.0
            for k in range(cnt):
                uk = tab_u[o + k]
                xe = lo + half * (uk + 1.0)
                we = tab_w[o + k] * half ** (1.0 + ea + eb)
                if not right:
                    we = we * _power(1.0 - xe, alpha)
                if not left:
                    we = we * _power(1.0 + xe, beta)
                x[at + k] = xe
                w[at + k] = we
                piece[at + k] = i
                om[at + k] = half * (1.0 - uk) if right else 1.0 - xe
                op[at + k] = half * (1.0 + uk) if left else 1.0 + xe
        else:
            # Gauss-Legendre times the smooth weight; 1 -+ x from the piece's own distance
            # to the end (exact next to it); formed from the rounded x, 1 + x at
            # x ~ -1 + 1e-12 keeps 4 digits and int w loses 4e-10
            o = legendre[cnt] if cnt < legendre.shape[0] else -1
            if o < 0:
                raise ValueError("graded rule: a node count outside the table")
            for k in range(cnt):
                uk = tab_u[o + k]
                one_minus = (1.0 - hi) + half * (1.0 - uk)
                one_plus = (1.0 + lo) + half * (1.0 + uk)
                x[at + k] = lo + half * (uk + 1.0)
                w[at + k] = ((half * tab_w[o + k]) * _power(one_minus, alpha)
                             * _power(one_plus, beta))
                piece[at + k] = i
                om[at + k] = one_minus
                op[at + k] = one_plus
        at += cnt
    return x, w, piece, om, op, los, his, counts


_END_POWERS = _GRADING ** np.arange(0, _LEVELS + 1)    # 0.15^k, k = 0.._LEVELS


def _end_grading(breaks):
    """Points 1 - d 0.15^k and -1 + d 0.15^k, d = half the distance to the nearest break."""
    breaks = np.asarray(breaks, dtype=float)
    parts = []
    for end, nb in ((1.0, breaks[-1] if breaks.size else -1.0),
                    (-1.0, breaks[0] if breaks.size else 1.0)):
        d = 0.5 * abs(end - nb)
        steps = d * _END_POWERS
        steps = steps[steps > max(_DEPTH * d, _FLOOR)]
        parts.append(end - steps if end > 0.0 else end + steps)
    return np.concatenate(parts)


@jit()
def _end_graded_mesh(mesh, breaks, powers, floor, depths):
    """The ascending mesh ``mesh`` joined with :func:`_end_grading`'s points (``powers``:
    0.15^k, k = 0.._LEVELS; ``floor``: the shortest graded step), duplicates dropped: the
    union of ``mesh`` and ``_end_grading(breaks)`` in one call; ``depths``: (at -1, at +1)
    the shortest step relative to d (_DEPTH in ``_end_grading``)."""
    nb = breaks.shape[0]
    out = np.empty(mesh.shape[0] + 2 * powers.shape[0])
    m = mesh.shape[0]
    out[:m] = mesh
    for end in (1.0, -1.0):
        if end > 0.0:
            nearest = breaks[nb - 1] if nb else -1.0
        else:
            nearest = breaks[0] if nb else 1.0
        d = 0.5 * abs(end - nearest)
        least = max((depths[1] if end > 0.0 else depths[0]) * d, floor)
        for k in range(powers.shape[0]):
            step = d * powers[k]
            if step > least:
                out[m] = end - step if end > 0.0 else end + step
                m += 1
    pts = np.sort(out[:m])
    keep = np.ones(m, dtype=np.bool_)
    for j in range(1, m):
        keep[j] = pts[j] != pts[j - 1]
    return pts[keep]


# transforms of w delta_phi off the interval and its log potential
_FAR_EXPONENT = 40.0  # w_rule is used for 1/(t - v) where 2 q log(rho) >= 40 on every piece
_NEAR_RATIO = 4.0     # geometric grading toward Re v (pieces see the pole at >= 1/3 length)
_NEAR_Q = 16          # Gauss nodes on the smallest graded pieces
_KEEP_END = 1.5       # grading point p kept while |end - p| >= |p - x0| / 2
_DELTA_FLOOR = 1e-15  # grading toward Re v stops at this |Im v|: closer, the integrand is
                      # bounded by |r'| on the remaining 1e-15, and nodes could not be placed
_CHUNK_FAR = 256      # points per block of the dense sums over w_rule
_CHUNK_NODES = 50_000  # quadrature nodes per block of the near-line transform (the kernel
                       # term of r makes an array of (nodes, n + 16) per interval)


def _log_rho(z, lo, hi):
    """log of the Bernstein-ellipse parameter of z for the piece [lo, hi]: the ellipse with
    foci lo, hi through z; sqrt(u - 1) sqrt(u + 1) ~ u has its cut on [-1, 1] only."""
    u = (2.0 * z - (lo + hi)) / (hi - lo)
    return np.log(np.abs(u + np.sqrt(u - 1.0) * np.sqrt(u + 1.0)))


def _panel_nodes(lo, hi, counts, at_left, at_right, lm, lp, ea, eb, ea1, eb1, eab1):
    """Gauss rules for int (1-t)^ea (1+t)^eb g(t) dt on pieces [lo, hi], all given as offsets
    d = t - x0 from a centre x0 with 1 - x0 = lm, 1 + x0 = lp (per piece), so that 1 - t =
    lm - d and 1 + t = lp + d keep full relative precision next to an end.

    A piece with ``at_right`` (``at_left``) ends at +1 (-1) and carries that end's factor in
    its Gauss-Jacobi rule; elsewhere the factor is smooth and multiplies the Gauss-Legendre
    weights.  ``ea1``, ``eb1``, ``eab1`` are 1 + ea, 1 + eb, 1 + ea + eb, exact.  Pieces
    with the same count and end flags are done together.  Returns (d, weights, piece index)."""
    key = 4 * counts.astype(np.int64) + 2 * at_left.astype(np.int64) + at_right.astype(np.int64)
    ds, ws, owners = [], [], []
    for k in np.unique(key):
        sel = np.flatnonzero(key == k)
        cnt, L, R = int(k // 4), bool(k & 2), bool(k & 1)
        u, wu = gauss_jacobi_cached(cnt, ea if R else 0.0, eb if L else 0.0)
        lo_s, hi_s = lo[sel, None], hi[sel, None]
        half = 0.5 * (hi_s - lo_s)
        if R:
            one_minus = half * (1.0 - u)            # 1 - t, exact next to +1
            d = hi_s - one_minus
        else:
            d = lo_s + half * (1.0 + u)
            one_minus = lm[sel, None] - d
        one_plus = half * (1.0 + u) if L else lp[sel, None] + d
        expo = eab1 if (L and R) else (ea1 if R else (eb1 if L else 1.0))
        w = wu * half ** expo
        if not R:
            w = w * one_minus ** ea
        if not L:
            w = w * one_plus ** eb
        ds.append(d.ravel())
        ws.append(w.ravel())
        owners.append(np.repeat(sel, cnt))
    return np.concatenate(ds), np.concatenate(ws), np.concatenate(owners)


# -- compiled sums over the rules ------------------------------------------------------------
@jit(fastmath={"reassoc"})
def _barycentric(u, s, lam, f, out):
    """out[i] = the interpolant through (s_k, f_k) at u_i, barycentric weights ``lam``
    (second form); f_k where u_i is s_k.  ``reassoc``: the sums in vector lanes (the order
    of the sums changes)."""
    for i in range(u.shape[0]):
        num = 0.0
        den = 0.0
        for k in range(s.shape[0]):
            c = lam[k] / (u[i] - s[k])
            num += c * f[k]
            den += c
        value = num / den
        if not math.isfinite(value):
            # u_i is one of the points, or so close to one that lam / (u_i - s_k)
            # overflows: the interpolant there is its value
            best = 0
            for k in range(s.shape[0]):
                if abs(u[i] - s[k]) < abs(u[i] - s[best]):
                    best = k
            value = f[best]
        out[i] = value


@jit()
def _nearest(nodes, x):
    """Distance from x to the nearest of the ascending ``nodes``."""
    i = np.searchsorted(nodes, x)
    below = abs(x - nodes[max(i - 1, 0)])
    above = abs(nodes[min(i, nodes.shape[0] - 1)] - x)
    return min(below, above)


@jit(fastmath={"reassoc"})
def _difference_quotient_sums(x, rx, nodes0, r0, weights0, nodes1, r1, weights1, out):
    """out[i] = sum_j weights[j] (r_nodes[j] - rx[i]) / (nodes[j] - x[i]) over the rule
    (nodes, weights, r at the nodes) of the two whose nearest node is farther from x[i],
    so that r_nodes[j] - rx[i] never cancels badly; the term of a node within rounding of
    x[i] (nodes[j] == x[i]) left out: its weight is ~1e-13 (only the innermost graded pieces
    come that close) and its quotient 0/0.

    ``reassoc`` lets the compiler sum in vector lanes (2.5 times faster than one chain):
    the order of the sum changes, so results agree to rounding.  This is delta_phi's cost:
    points x nodes (2000 x 1200 for the rule ``w_rule`` of a face with two breaks)."""
    for i in range(x.shape[0]):
        xi = x[i]
        ri = rx[i]
        if _nearest(nodes1, xi) > _nearest(nodes0, xi):
            nodes, r_nodes, weights = nodes1, r1, weights1
        else:
            nodes, r_nodes, weights = nodes0, r0, weights0
        s = 0.0
        for j in range(nodes.shape[0]):
            den = nodes[j] - xi
            term = (r_nodes[j] - ri) / den if den != 0.0 else 0.0
            s += weights[j] * term
        out[i] = s


_TREE_LEAF = 32       # nodes of a 1/w rule per leaf of its tree (at most)
_TREE_THETA = 0.5     # a tree node is summed from its moments where radius < theta distance
_TREE_GROUP = 64      # targets (consecutive, ascending) that walk the tree together
_TREE_MIN = 256       # targets from which the tree pays for itself (fewer: term by term)


def _series_limits(eps, theta):
    """limits[p], p >= 1: the largest t with t^p (1 + t) / (1 - t) <= eps (bisection), up to
    the first p whose limit reaches theta; limits[0] = 0."""
    top = math.ceil((math.log(eps) - math.log((1.0 + theta) / (1.0 - theta))) / math.log(theta))
    p = np.arange(1, top + 2, dtype=float)
    lo, hi = np.zeros(p.size), np.ones(p.size)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        ok = mid ** p * (1.0 + mid) / (1.0 - mid) <= eps
        lo, hi = np.where(ok, mid, lo), np.where(ok, hi, mid)
    top = int(np.argmax(lo >= theta)) + 1
    return np.concatenate([[0.0], lo[:top]])


# a node's series is cut where what is left is below eps/8 of the terms' size
_TREE_LIMITS = _series_limits(np.finfo(float).eps / 8.0, _TREE_THETA)


@jit(fastmath={"reassoc"})
def _rule_tree_sums(x, rx, order, nodes, r_nodes, weights, limits, out):
    """out[i] = sum_j weights[j] (r_nodes[j] - rx[i]) / (nodes[j] - x[i]) for the targets
    i = order[0], order[1], ... (ascending in x) over the ascending ``nodes`` of one rule,
    by a treecode (Barnes & Hut, Nature 324 (1986) 446) on the source side.

    The tree: index ranges of the nodes halved until a leaf holds at most _TREE_LEAF
    (tree node k has children 2k+1, 2k+2); per tree node its centre c and half-width rho.
    The targets walk it in groups of _TREE_GROUP consecutive ones.  A tree node with
    rho < _TREE_THETA D, D the distance from c to the group's span, is summed from its
    moments: with a_j = w_j r_j, b_j = w_j, s_j = (t_j - c) / rho and y = rho / (x - c),

        sum_j (a_j - r(x) b_j) / (t_j - x) = -1/(x - c) sum_p (A_p - r(x) B_p) y^p,
        A_p = sum_j a_j s_j^p,  B_p = sum_j b_j s_j^p,

    cut after the first p terms where t^p (1 + t) / (1 - t) <= eps/8 (``limits``; t = rho/D
    >= |y|): what is left is below eps/8 of sum_j (|a_j| + |r(x) b_j|) / |t_j - x|, the
    size of the rounding of r_j - r(x) in the terms one by one, which the split form loses
    no more than.  Such a node with no more nodes than terms, and every leaf nearer the
    group, is summed term by term as in :func:`_difference_quotient_sums` (a node that
    coincides with a target left out), over runs of adjacent leaves.  The moments are formed
    for the nodes summed from them, as many as any group asks for; a group's series are
    summed by Horner's rule across its targets (vector lanes).

    ``reassoc`` lets the compiler sum in vector lanes: the results agree with the sums term
    by term to rounding."""
    n = nodes.shape[0]
    nt = order.shape[0]
    if nt == 0:
        return
    depth = 0
    while (n + (1 << depth) - 1) >> depth > _TREE_LEAF:
        depth += 1
    count = (1 << (depth + 1)) - 1
    start = np.empty(count, dtype=np.int64)
    stop = np.empty(count, dtype=np.int64)
    start[0] = 0
    stop[0] = n
    for k in range((1 << depth) - 1):
        mid = (start[k] + stop[k]) // 2
        start[2 * k + 1] = start[k]
        stop[2 * k + 1] = mid
        start[2 * k + 2] = mid
        stop[2 * k + 2] = stop[k]
    centre = np.zeros(count)
    radius = np.zeros(count)
    for k in range(count):
        if stop[k] > start[k]:
            centre[k] = 0.5 * (nodes[start[k]] + nodes[stop[k] - 1])
            radius[k] = 0.5 * (nodes[stop[k] - 1] - nodes[start[k]])
    # the walk of each group: the tree nodes summed from moments (with their term counts)
    # and the runs of nodes summed term by term
    group = _TREE_GROUP
    ngroups = (nt + group - 1) // group
    pmax = limits.shape[0] - 1
    need = np.zeros(count, dtype=np.int64)
    exp_node = np.empty(64, dtype=np.int64)
    exp_p = np.empty(64, dtype=np.int64)
    run_lo = np.empty(64, dtype=np.int64)
    run_hi = np.empty(64, dtype=np.int64)
    exp_first = np.empty(ngroups + 1, dtype=np.int64)
    run_first = np.empty(ngroups + 1, dtype=np.int64)
    stack = np.empty(2 * depth + 2, dtype=np.int64)
    ne = 0
    nr = 0
    for gi in range(ngroups):
        xmin = x[order[gi * group]]
        xmax = x[order[min(nt, (gi + 1) * group) - 1]]
        exp_first[gi] = ne
        run_first[gi] = nr
        stack[0] = 0
        top = 1
        while top > 0:
            top -= 1
            k = stack[top]
            lo, hi = start[k], stop[k]
            if hi <= lo:
                continue
            dist = max(xmin - centre[k], centre[k] - xmax)
            if dist > 0.0 and radius[k] < _TREE_THETA * dist:
                t = radius[k] / dist
                last = min(pmax, hi - lo - 1)   # more terms than nodes: term by term
                if last >= 1 and limits[last] >= t:
                    a = 0
                    p = last                    # the fewest terms whose limit covers t
                    while p - a > 1:
                        m = (a + p) >> 1
                        if limits[m] >= t:
                            p = m
                        else:
                            a = m
                    if ne == exp_node.shape[0]:
                        exp_node = np.concatenate((exp_node, np.empty(ne, dtype=np.int64)))
                        exp_p = np.concatenate((exp_p, np.empty(ne, dtype=np.int64)))
                    exp_node[ne] = k
                    exp_p[ne] = p
                    ne += 1
                    need[k] = max(need[k], p)
                    continue
            elif 2 * k + 2 < count:
                stack[top] = 2 * k + 2          # the left child on top: runs ascend
                stack[top + 1] = 2 * k + 1
                top += 2
                continue
            if nr > run_first[gi] and run_hi[nr - 1] == lo:
                run_hi[nr - 1] = hi
            else:
                if nr == run_lo.shape[0]:
                    run_lo = np.concatenate((run_lo, np.empty(nr, dtype=np.int64)))
                    run_hi = np.concatenate((run_hi, np.empty(nr, dtype=np.int64)))
                run_lo[nr] = lo
                run_hi[nr] = hi
                nr += 1
    exp_first[ngroups] = ne
    run_first[ngroups] = nr
    # the moments (slices: loops from 0, which the compiler vectorizes)
    terms = 1
    for k in range(count):
        terms = max(terms, need[k])
    ma = np.empty((count, terms))
    mb = np.empty((count, terms))
    pw = np.empty(n)
    sv = np.empty(n)
    for k in range(count):
        if need[k] == 0:
            continue
        lo, hi = start[k], stop[k]
        c = centre[k]
        scale = 1.0 / radius[k] if radius[k] > 0.0 else 0.0
        pk, sk, tk, rk = pw[lo:hi], sv[lo:hi], nodes[lo:hi], r_nodes[lo:hi]
        pk[:] = weights[lo:hi]
        for j in range(sk.shape[0]):
            sk[j] = (tk[j] - c) * scale
        for p in range(need[k]):
            sa = 0.0
            sb = 0.0
            for j in range(pk.shape[0]):
                sa += pk[j] * rk[j]
                sb += pk[j]
                pk[j] *= sk[j]
            ma[k, p] = sa
            mb[k, p] = sb
    # the sums
    xs = np.empty(group)
    rs = np.empty(group)
    inv = np.empty(group)
    y = np.empty(group)
    acc = np.empty(group)
    tot = np.empty(group)
    for gi in range(ngroups):
        g0 = gi * group
        g = min(nt, g0 + group) - g0
        xg, rg, ig, yg, ag, tg = xs[:g], rs[:g], inv[:g], y[:g], acc[:g], tot[:g]
        for i in range(g):
            xg[i] = x[order[g0 + i]]
            rg[i] = rx[order[g0 + i]]
            tg[i] = 0.0
        for e in range(exp_first[gi], exp_first[gi + 1]):
            k = exp_node[e]
            p = exp_p[e]
            c = centre[k]
            rho = radius[k]
            a0 = ma[k, p - 1]
            b0 = mb[k, p - 1]
            for i in range(g):
                ig[i] = 1.0 / (xg[i] - c)
                yg[i] = rho * ig[i]
                ag[i] = a0 - rg[i] * b0
            for q in range(p - 2, -1, -1):
                aq = ma[k, q]
                bq = mb[k, q]
                for i in range(g):
                    ag[i] = ag[i] * yg[i] + (aq - rg[i] * bq)
            for i in range(g):
                tg[i] -= ig[i] * ag[i]
        for i in range(g):
            xi = xg[i]
            ri = rg[i]
            sm = 0.0
            for e in range(run_first[gi], run_first[gi + 1]):
                tk = nodes[run_lo[e]:run_hi[e]]
                rk = r_nodes[run_lo[e]:run_hi[e]]
                wk = weights[run_lo[e]:run_hi[e]]
                for j in range(tk.shape[0]):
                    den = tk[j] - xi
                    term = (rk[j] - ri) / den if den != 0.0 else 0.0
                    sm += wk[j] * term
            out[order[g0 + i]] = tg[i] + sm


@jit()
def _nearest_sorted(nodes, xs, out):
    """out[i] = the distance from xs[i] to the nearest of the ascending ``nodes``, for
    ascending xs (one merge-like pass)."""
    j = 0
    last = nodes.shape[0] - 1
    for i in range(xs.shape[0]):
        while j < last and nodes[j + 1] <= xs[i]:
            j += 1
        d = abs(xs[i] - nodes[j])
        if j < last:
            d = min(d, abs(nodes[j + 1] - xs[i]))
        out[i] = d


@jit()
def _tree_quotient_sums(x, rx, nodes0, r0, weights0, nodes1, r1, weights1, limits, out):
    """:func:`_difference_quotient_sums` by the treecode :func:`_rule_tree_sums`: each x[i]
    takes the rule whose nearest node is farther, and the targets of each rule are summed in
    ascending order."""
    n = x.shape[0]
    order = np.argsort(x, kind="mergesort")
    xs = x[order]
    d0 = np.empty(n)
    d1 = np.empty(n)
    _nearest_sorted(nodes0, xs, d0)
    _nearest_sorted(nodes1, xs, d1)
    n1 = 0
    for i in range(n):
        if d1[i] > d0[i]:
            n1 += 1
    order0 = np.empty(n - n1, dtype=np.int64)
    order1 = np.empty(n1, dtype=np.int64)
    a = 0
    b = 0
    for i in range(n):
        if d1[i] > d0[i]:
            order1[b] = order[i]
            b += 1
        else:
            order0[a] = order[i]
            a += 1
    _rule_tree_sums(x, rx, order0, nodes0, r0, weights0, limits, out)
    _rule_tree_sums(x, rx, order1, nodes1, r1, weights1, limits, out)


_LOG_SPAN = 2.0       # a cluster holds offsets e in [e0, 2 e0]: radius / centre <= 1/3
_LOG_TERMS = 40       # expansion terms at most: (1/3)^41 / 41 < 1e-21
_LOG_TOL = 1e-19      # truncation of the expansion, relative to sum |c_j| of the cluster
_LOG_DIRECT = 6       # clusters of at most this many nodes are summed term by term


@jit()
def _cluster_starts(e):
    """Start indices (and the end) of the clusters of the ascending offsets ``e`` > 0: each
    runs from its first offset e0 up to _LOG_SPAN e0."""
    starts = np.empty(e.shape[0] + 1, dtype=np.int64)
    k = 0
    i = 0
    while i < e.shape[0]:
        starts[k] = i
        k += 1
        top = _LOG_SPAN * e[i]
        i += 1
        while i < e.shape[0] and e[i] <= top:
            i += 1
    starts[k] = e.shape[0]
    return starts[:k + 1].copy()


_LOG_EXACT = 4        # moments p < _LOG_EXACT summed compensated (module below)


@jit(fastmath={"reassoc"})
def _power_sums(pw, s, first, out):
    """out[p] = sum_j pw_j s_j^(p - first) / p for p = first .. out.size - 1 (p >= 1);
    ``pw`` is overwritten.  ``reassoc`` lets the compiler sum in vector lanes (the order of
    the sums changes)."""
    for p in range(first, out.shape[0]):
        acc = 0.0
        for j in range(pw.shape[0]):
            acc += pw[j]
            pw[j] *= s[j]
        out[p] = acc / p


@jit()
def _log_moments(e, c, starts, centers, radii, terms, moments):
    """Per cluster k (offsets e[starts[k]:starts[k+1]]): centre m_k and radius rho_k of its
    offsets, moments[k, 0] = sum c_j and moments[k, p] = sum c_j s_j^p / p (p >= 1,
    s_j = (e_j - m_k) / rho_k in [-1, 1]: scaled, no underflow for a cluster 1e-14 wide).

    A cluster holds up to ~1000 nodes, whose plain sum loses ~sqrt(1000) ulps (4e-15 of
    M_0); the moments p < _LOG_EXACT are compensated (Neumaier: 1e-16).  The others enter
    the sums of :func:`_log_sums` times r^p <= 3^-p, which leaves their rounding below 0.1
    ulp of sum |c_j|: plain sums in vector lanes (:func:`_power_sums`)."""
    comp = np.empty(_LOG_EXACT)
    pws = np.empty(e.shape[0])
    ss = np.empty(e.shape[0])
    for k in range(starts.shape[0] - 1):
        lo, hi = starts[k], starts[k + 1]
        m = 0.5 * (e[lo] + e[hi - 1])
        rho = 0.5 * (e[hi - 1] - e[lo])
        centers[k] = m
        radii[k] = rho
        # the most terms any point z >= 0 asks for: those at z = 0, r = rho / m
        r = rho / m if m > 0.0 else 0.0
        p = 1
        pw = r
        while p < moments.shape[1] - 1 and pw * r > _LOG_TOL * (p + 1):
            pw *= r
            p += 1
        terms[k] = p
        scale = 1.0 / rho if rho > 0.0 else 0.0
        for p in range(moments.shape[1]):
            moments[k, p] = 0.0
        if hi - lo <= _LOG_DIRECT:
            continue                        # summed term by term
        top = min(terms[k] + 1, _LOG_EXACT)
        for p in range(top):
            comp[p] = 0.0
        for j in range(lo, hi):
            sj = (e[j] - m) * scale
            ss[j] = sj
            pw = c[j]
            for p in range(top):
                if p > 0:
                    pw *= sj
                x = pw / p if p > 0 else pw
                t = moments[k, p] + x
                if abs(moments[k, p]) >= abs(x):
                    comp[p] += (moments[k, p] - t) + x
                else:
                    comp[p] += (x - t) + moments[k, p]
                moments[k, p] = t
            pws[j] = pw * sj
        for p in range(top):
            moments[k, p] += comp[p]
        if terms[k] >= top:
            _power_sums(pws[lo:hi], ss[lo:hi], top, moments[k, :terms[k] + 1])


@jit()
def _log_sums(z, e, c, starts, centers, radii, terms, moments, out):
    """out[i] = sum_j c_j log(z_i + e_j) for z_i >= 0 and offsets e_j > 0 in the clusters of
    :func:`_log_moments`.

    A cluster of more than :data:`_LOG_DIRECT` nodes: with D = z_i + m_k, r = rho_k / D
    <= 1/3 (the cluster's offsets span at most a factor 2, and z_i >= 0),

        sum_j c_j log(D + rho_k s_j) = M_0 log D - sum_{p >= 1} M_p (-r)^p,

    cut after the terms the cluster needs at z = 0, where r is largest: the rest is below
    1.5 _LOG_TOL sum |c_j|, ~1e-3 of the rounding of the sum itself.  One logarithm per
    cluster and point (~50 clusters for the ~2000 nodes of a rule graded toward two breaks
    and both ends) instead of one per node; the series is summed for all points at once
    (Horner's rule across the points: independent lanes, not one chain per point)."""
    npts = z.shape[0]
    u = np.empty(npts)
    acc = np.empty(npts)
    for i in range(npts):
        out[i] = 0.0
    for k in range(starts.shape[0] - 1):
        lo, hi = starts[k], starts[k + 1]
        if hi - lo <= _LOG_DIRECT:
            for i in range(npts):
                for j in range(lo, hi):
                    out[i] += c[j] * math.log(z[i] + e[j])
            continue
        p = terms[k]
        for i in range(npts):
            u[i] = -radii[k] / (z[i] + centers[k])
            acc[i] = moments[k, p]
        for q in range(p - 1, 0, -1):
            mq = moments[k, q]
            for i in range(npts):
                acc[i] = acc[i] * u[i] + mq
        for i in range(npts):
            out[i] += moments[k, 0] * math.log(z[i] + centers[k]) - u[i] * acc[i]


@jit()
def _log_cluster_data(offsets, ww, phi_w, pe, nterms):
    """The clusters of :meth:`InversionRemainder._log_clusters` for one end: the offsets
    ``offsets`` of the nodes from it ascending (they descend or ascend with the nodes but
    where two pieces' nodes round alike: then sorted, stably), c_j = w_j (phi_j - pe) in
    the same order, and the clusters' starts, centres, radii, term counts and moments
    (:func:`_cluster_starts`, :func:`_log_moments`; ``nterms`` columns)."""
    n = offsets.shape[0]
    c = ww * (phi_w - pe)
    down = True
    up = True
    for j in range(1, n):
        if not offsets[j] < offsets[j - 1]:
            down = False
        if not offsets[j] > offsets[j - 1]:
            up = False
    if down:
        e = offsets[::-1].copy()
        c = c[::-1].copy()
    elif up:
        e = offsets.copy()
    else:
        order = np.argsort(offsets, kind="mergesort")
        e = offsets[order]
        c = c[order]
    starts = _cluster_starts(e)
    k = starts.shape[0] - 1
    centers = np.empty(k)
    radii = np.empty(k)
    terms = np.empty(k, dtype=np.int64)
    moments = np.empty((k, nterms))
    _log_moments(e, c, starts, centers, radii, terms, moments)
    return e, c, starts, centers, radii, terms, moments


@jit()
def _log_sums_where(z, take, e, c, starts, centers, radii, terms, moments, out):
    """:func:`_log_sums` at the points z[i] with take[i], into out[i] (the others left)."""
    idx = np.flatnonzero(take)
    part = np.empty(idx.shape[0])
    _log_sums(z[idx], e, c, starts, centers, radii, terms, moments, part)
    for k in range(idx.shape[0]):
        out[idx[k]] = part[k]


_LOG_FAR = 2.0        # |v| from which the log potential is summed from moments ...
_LOG_FAR_TERMS = _FAR_TERMS   # ... with at most this many terms (60: 2^-60 of
                              # int |w delta_phi| left), as the series' far sums


_FAR_DIVISORS = np.arange(1.0, _LOG_FAR_TERMS + 1.0)   # k in M_k / k, k >= 1


@jit(fastmath={"reassoc"})
def _power_moments(t, c, out):
    """out[k] = sum_j c_j t_j^k, k = 0 .. out.size - 1 (|t_j| <= 1).  ``reassoc`` lets the
    compiler sum in vector lanes: the sums agree with a plain loop to rounding."""
    pw = c.copy()
    for k in range(out.shape[0]):
        s = 0.0
        for j in range(t.shape[0]):
            s += pw[j]
            pw[j] *= t[j]
        out[k] = s


@jit()
def _log_far_sums(v, coef, out):
    """out[i] = coef[0] log|v_i| - sum_{k >= 1} coef[k] / v_i^k for |v_i| >= 2: with
    coef = (M_0, M_1 / 1, M_2 / 2, ...), M_k = sum_j c_j t_j^k the moments of c at points
    |t_j| <= 1, this is sum_j c_j log|v - t_j| (log|v - t| = log|v| - sum_k (t / v)^k / k).
    The terms are below sum |c_j| |v|^-k, so those with |v|^-k > 2^-(len(coef) - 1) are
    summed (all of them at |v| = 2, fewer farther out; Horner's rule)."""
    top = coef.shape[0] - 1
    for i in range(v.shape[0]):
        y = 1.0 / v[i]
        ay = abs(y)
        K = top
        if ay < 0.5:
            K = max(1, min(top, int(math.ceil(top * math.log(2.0) / -math.log(ay)))))
        acc = coef[K]
        for k in range(K - 1, 0, -1):
            acc = acc * y + coef[k]
        out[i] = coef[0] * math.log(abs(v[i])) - acc * y


def log_far(v, coef):
    """(1/pi) [coef[0] log|v| - sum_{k >= 1} coef[k] v^-k] at |v| >= 2 (:func:`_log_far_sums`):
    the log potential of a density on [-1, 1] from its moments M_k, coef = (M_0, M_k / k)."""
    out = np.empty(np.shape(v))
    _log_far_sums(np.ascontiguousarray(v, dtype=float), coef, out)
    return out / math.pi


@functools.lru_cache(maxsize=16)
def _chebyshev_offsets(m):
    """Chebyshev points of the second kind as offsets s = sin^2(theta/2) in [0, 1] from an
    end (theta = pi k / (m - 1): exact at the end itself, no cancellation next to it) and
    their barycentric weights (-1)^k, halved at both ends (read-only)."""
    s = np.sin(0.5 * np.pi * np.arange(m) / (m - 1)) ** 2
    lam = (-1.0) ** np.arange(m)
    lam[[0, -1]] *= 0.5
    s.flags.writeable = False
    lam.flags.writeable = False
    return s, lam


# the log potential of w delta_phi to a stated accuracy (InversionRemainder.log_potential's
# tol), by a rule for integrals against w graded less deeply toward the breaks and with
# fewer nodes on the graded pieces than ``w_rule``
_RULE_ROUNDING = 1e-16      # what the full w_rule leaves, relative to the correction's scale
_LEAST_ACCURACY = 6         # an accuracy coarser than 1e-6 gets the rule of 1e-6
_RULE_MARGIN = 10.0         # the rule for 10^-k is taken to leave this times 10^-k (it left
                            # up to 3 times in the cases of tests/sie/test_breaks.py)
# the Bernstein-ellipse parameter of a graded piece [c + g s, c + s] (g = _GRADING) for a
# break at c: delta_phi's singularity lies g / (1 - g) of the piece's length beyond its end
_RHO_GRADED = (1.0 + _GRADING) / (1.0 - _GRADING) + math.sqrt(
    ((1.0 + _GRADING) / (1.0 - _GRADING)) ** 2 - 1.0)


def _accuracy_level(tol):
    """k, 10^-k <= tol, of the rule that :meth:`InversionRemainder.log_potential` uses for
    the accuracy ``tol`` (at least _LEAST_ACCURACY); None where tol asks for what the full
    ``w_rule`` gives (tol None, or within 10 times _RULE_ROUNDING)."""
    if tol is None or not tol > 10.0 * _RULE_ROUNDING:
        return None
    return max(_LEAST_ACCURACY, math.ceil(-math.log10(tol) - 1e-9))


_HP_SLOPE_TOL = 2.0   # nodes fewer per level deeper toward a break in a rule for tol (below)


def _unresolved(tol, power):
    """The largest h < 1 with h^power log(1/h) <= tol (tol < 1/e)."""
    h = tol ** (1.0 / power)
    for _ in range(8):              # h = (tol / log(1/h))^(1/power), a contraction
        h = (tol / math.log(1.0 / h)) ** (1.0 / power)
    return h


@functools.lru_cache(maxsize=64)
def _accuracy_rule(k, alpha, beta, m_poly):
    """The rule for integrals against w that leaves ~10^-k of the correction's scale
    (1/pi) int w |delta_phi| in its log potential, for the end exponents alpha, beta and a
    projection whose polynomial part delta_phi carries has degree < m_poly: (depth toward
    the breaks, (depth toward -1, toward +1), q_small, hp_slope, m: the nodes of a piece that
    spans most of a gap and the Chebyshev points on the end pieces);
    :meth:`InversionRemainder._w_parts` and :meth:`~InversionRemainder._phi_at_w_nodes` read
    it.

    delta_phi ~ A (t - c) log|t - c| at a break c.  Where the grading stops, the innermost
    piece [c, c + h d] is left unresolved: its Gauss rule misses ~A (h d)^2 log(1/h) at most
    (the part A (h d)^2 log(h d) s, s = (t - c) / (h d), is a polynomial it integrates;
    s log s is what it misses, by 7e-4 with 4 nodes), so the grading stops once the innermost
    piece is no longer than the largest h with h^2 log(1/h) <= 10^-k (steps of 0.15 down to
    depth = 0.15 h), and the innermost piece needs no more nodes than its level's.  Toward
    an end e the sum is over w (delta_phi - delta_phi(e)) log|v - t|, v outside, ~(1 -+ t)^(1
    + exponent) log(1 -+ t) at most: an unresolved end piece of length h misses
    ~h^(2 + exponent) log(1/h).  A graded piece sees the break at rho = _RHO_GRADED
    (Bernstein ellipse), and each of its Gauss nodes cuts its error by rho^2: the full rule's
    counts, made for _RULE_ROUNDING, are lowered by as many nodes as rho^2 fits in 10^-k /
    _RULE_ROUNDING, and by _HP_SLOPE_TOL (not 1) per level deeper (hp refinement, Babuska &
    Guo): a piece's error ~A len^2 rho^(-2 count) still falls by 0.15^2 rho^4 = 0.59 a level.
    The pieces graded toward an end keep the full rule's counts: the sums beyond an end e
    take delta_phi(e) out, so next to the other end the integrand is ~delta_phi(e) w log|v -
    t|, with w's singularity there, and not small with A (there 8 nodes a piece left 5e-5
    of the correction's scale); their nodes cost no evaluation of delta_phi
    (:meth:`~InversionRemainder._phi_at_w_nodes`).  On the end pieces delta_phi is
    interpolated from m Chebyshev points (rho = 3 + sqrt(8) there): rho^-m <= 10^-k and
    m >= m_poly, which interpolates the polynomial part exactly; and m nodes (at least 24)
    on a piece that spans most of a gap, not the full rule's m_poly + 24: they integrate
    the polynomial part times the logarithm (analytic there) and the break's singularity
    (rho >= 2.2 from such a piece, 2.2^-48 < 1e-16)."""
    tol = 10.0 ** -k
    depth = max(_GRADING * _unresolved(tol, 2.0), _DEPTH)
    ends = tuple(max(_GRADING * _unresolved(tol, 2.0 + e), _DEPTH) for e in (beta, alpha))
    cut = math.floor(math.log(tol / _RULE_ROUNDING) / (2.0 * math.log(_RHO_GRADED)))
    m = max(int(m_poly), math.ceil(k * math.log(10.0) / math.log(3.0 + math.sqrt(8.0))))
    return depth, ends, max(_HP_MIN, _Q_SMALL + 2 - cut), _HP_SLOPE_TOL, m


@dataclass(eq=False)
class InversionRemainder:
    """delta_phi, its integral, Cauchy transform and logarithmic potential (module docstring).

    Costs per point (n basis functions, q ~ n + 24 nodes per piece between breaks, N ~ 10 q
    to 25 q the size of ``w_rule``): delta_phi ~N; the Cauchy transform where ``w_rule``
    resolves the pole ~N, next to the interval r at ~20 nodes on each of
    2 log_4(2/|Im z|) graded pieces plus ~n (900 nodes at |Im z| = 1e-12 for n = 32, 1000
    for n = 128; 500 to 600 at 1e-6), where the coupling and kernel terms of r dominate
    when present; the log potential outside ~50 clusters (once ~40 N to set them up),
    inside ~q^2 (one piece of ``w_rule`` interpolated) plus r at q nodes per piece between
    breaks."""
    sol: object                 # the IntervalSolution (polynomial part)
    a: float
    b: float
    f: object
    other: object               # coupling + kernel terms at local points, or None
    rules: list                 # [(s, ws, r_s)] for weight 1/w
    g_coef: np.ndarray          # projections g_m of g = f - other
    const: float = 0.0
    q: int = 0                          # nodes per piece between breaks of the 1/w rules
    _w_mesh: np.ndarray | None = None   # the graded mesh of w_rule (made on first use)
    _w: tuple | None = None             # (w_rule, w_panels, w_ends)
    breaks: np.ndarray = field(default_factory=lambda: np.empty(0))
    _wphi: np.ndarray | None = None     # w_rule weights times delta_phi at its nodes
    _phi_w: np.ndarray | None = None    # delta_phi at the nodes of w_rule
    _phi_ends: np.ndarray | None = None  # delta_phi at -1 and +1
    _log_data: dict = field(default_factory=dict)   # per end: _log_clusters(end)
    _log_ends: tuple | None = None      # the log potential of w delta_phi at -1 and +1
    _far_moments: np.ndarray | None = None  # far_coefficients()
    _interp: tuple | None = None        # barycentric data of delta_phi on the w_rule pieces
    _splits: np.ndarray | None = None   # _near_splits()
    _w_design: tuple | None = None      # w_rule made for an accuracy (_accuracy_rule), or
                                        # None: to rounding
    _accurate: dict = field(default_factory=dict)   # k -> _at_level(k)

    @classmethod
    def build(cls, piece, a, b, f, other, breaks, s, ws, fs, g_coef):
        """``piece``: the :class:`sie.solution.IntervalSolution` (polynomial part);
        ``f``, ``other``: f and the coupling + kernel terms of the polynomial solution as
        callables of the local coordinate (``other`` None when there are none); ``s, ws, fs``:
        the composite projection rule and f there; ``g_coef``: projections of f - other."""
        self = cls(piece, a, b, f, other, [], g_coef)
        q = piece.n - piece.kappa + _EXTRA_PER_PIECE     # the projection's nodes per piece
        # I(x) for x close to a break c: in the neighbouring piece the integrand has a pole
        # at distance |x - c|, so the pieces are graded toward the breaks (Gauss-Legendre on
        # a geometric mesh resolves a pole at any distance; without it phi(c + 1e-3) is
        # off by 1e-4 at n = 24)
        pts = graded_points(breaks)
        alpha, beta = piece.alpha, piece.beta
        # two interleaved rules: counts differ by one on every piece, so no x (e.g. a piece
        # midpoint, a node of every odd-count rule) is a node of both; f at both in one call
        rules = [_graded_rule(q, -alpha, -beta, breaks, pts, _Q_SMALL, shift)
                 for shift in (0, 1)]
        nodes = np.concatenate([r[0] for r in rules])
        r_all = self._r(nodes, call_checked(f, "f", (nodes,), nodes.shape))
        cut = rules[0][0].size
        for (x, w), r_x in zip(rules, (r_all[:cut], r_all[cut:])):
            self.rules.append((x, w, r_x))
        self._w_mesh = pts          # the rule for integrals against w: see w_rule
        self.q = q
        self.breaks = breaks
        if piece.kappa == 1:
            tw, ww = self.w_rule
            self.const = -float(ww @ self._phi_no_const(tw)) / jacobi_moment_shifted(
                piece.exp.alpha_p1, piece.exp.beta_p1)
        return self

    @property
    def w_rule(self):
        """(nodes, weights) of the rule for integrals against w, made on first use (phi at
        points needs only the 1/w rules): graded toward the breaks and toward +-1."""
        return self._w_parts()[0]

    @property
    def w_panels(self):
        """(lo, hi, counts) of the pieces of :attr:`w_rule`."""
        return self._w_parts()[1]

    @property
    def w_ends(self):
        """Per node of :attr:`w_rule`: its piece, 1 - t and 1 + t (exact)."""
        return self._w_parts()[2]

    def _w_parts(self):
        # delta_phi behaves like (x - c) log|x - c| at a break c, so the pieces are graded
        # geometrically toward each break (hp quadrature; without grading int psi converged
        # only like n^-3: 2e-8 at n = 192); also graded toward +-1: the Cauchy transform at x
        # just outside an end sums this rule where it resolves the pole (at x = 1.001 an
        # ungraded rule loses 5e-8 at n = 48), and so does the log potential outside
        if self._w is None:
            breaks, q = self.breaks, max(self.q, 24)
            design = self._w_design
            alpha, beta = self.sol.alpha, self.sol.beta
            if design is None:
                w_pts = _end_graded_mesh(self._w_mesh, breaks, _END_POWERS, _FLOOR,
                                         np.array([_DEPTH, _DEPTH]))
                rule = _graded_rule(q, alpha, beta, breaks, w_pts, _Q_SMALL + 2, details=True)
            else:                       # made for an accuracy (_accuracy_rule)
                _, ends, q_small, slope, m = design
                w_pts = _end_graded_mesh(self._w_mesh, breaks, _END_POWERS, _FLOOR,
                                         np.array(ends))
                rule = _graded_rule(max(m, 24), alpha, beta, breaks, w_pts, q_small,
                                    details=True, hp_slope=slope, innermost=False,
                                    q_end=_Q_SMALL + 2)
            tw, ww, piece_w, om_w, op_w, lo, hi, counts = rule
            self._w = ((tw, ww), (lo, hi, counts), (piece_w, om_w, op_w))
        return self._w

    # g - Pi g at points x, given f(x)
    def _r(self, x, fx):
        sol = self.sol
        out = fx - jacobi_series(self.g_coef, -sol.alpha, -sol.beta, x)
        if self.other is not None:
            out = out - self.other(x)
        return out

    def _quotient_integral(self, x):
        """(I(x), r(x)) at the points x (module docstring): the difference-quotient sums of
        the 1/w rules, by the treecode from _TREE_MIN points on, term by term below."""
        fx = call_checked(self.f, "f", (x,), x.shape)
        rx = self._r(x, fx)
        sums = np.empty(x.size)
        (n0, w0, r0), (n1, w1, r1) = self.rules
        args = (np.ascontiguousarray(x.ravel()), np.ascontiguousarray(rx.ravel()),
                n0, r0, w0, n1, r1, w1)
        if x.size >= _TREE_MIN:
            _tree_quotient_sums(*args, _TREE_LIMITS, sums)
        else:
            _difference_quotient_sums(*args, sums)
        return sums.reshape(x.shape) / math.pi, rx

    def _phi_no_const(self, x):
        sol = self.sol
        x = np.asarray(x, dtype=float)
        integral, rx = self._quotient_integral(x)
        k = sol.kappa
        if k == 1:
            pk = (sol.alpha + 1.0) + 0.5 * (sol.alpha + sol.beta + 2.0) * (x - 1.0)
        elif k == 0:
            pk = np.ones(x.shape)
        a, b = self.a, self.b
        if k == -1:                                     # P_{-1} = 0
            return -b / (a * a + b * b) * integral
        return -b / (a * a + b * b) * (integral + 2.0 ** k * pk * rx / sol.exp.sin)

    def phi(self, x):
        return self._phi_no_const(x) + self.const

    def quotient_part(self, x):
        """delta_phi without its term in r(x): -b/(a^2+b^2) I(x) + C at points x.  At an
        end of index 0 the term left out is r(end) / lambda (lambda = -b / sin(pi alpha),
        a^2 + b^2 = b^2 / sin^2(pi alpha)), which
        :meth:`sie.solution.IntervalSolution.endpoint_value` folds into g(end) / lambda:
        both grow like 1 / sin(pi alpha) as the exponent nears 0 and cancel."""
        integral, _ = self._quotient_integral(np.asarray(x, dtype=float))
        a, b = self.a, self.b
        return -b / (a * a + b * b) * integral + self.const

    def cauchy_inside(self, x, psi_full):
        """H[psi](x) = (g(x) - a psi(x)) / b, the equation itself, with the accurate psi.

        kappa = -1: psi solves the equation with g minus its weighted mean g_0 (the
        consistency; the basis has no image of P_0^{(-alpha,-beta)}), so g_0 is taken out."""
        gx = call_checked(self.f, "f", (x,), x.shape)
        if self.other is not None:
            gx = gx - self.other(x)
        if self.sol.kappa == -1:
            gx = gx - self.g_coef[0]
        return (gx - self.a * psi_full) / self.b

    # -- Cauchy transform off the open interval ---------------------------------------
    def _w_values(self):
        """w_rule weights times delta_phi at its nodes (computed once; with delta_phi at -1
        and +1, :meth:`_phi_at_w_nodes`)."""
        if self._wphi is None:
            tw, ww = self.w_rule
            self._phi_w, self._phi_ends = self._phi_at_w_nodes()
            self._wphi = ww * self._phi_w
        return self._wphi

    def _phi_at_w_nodes(self):
        """delta_phi at the nodes of ``w_rule`` and at -1, +1.

        ``w_rule`` is graded toward the ends for the transforms of w delta_phi just beyond
        them, not for delta_phi itself: on the end pieces of the mesh of the 1/w rules,
        [-1, p_1] and [p_K, 1] (p_1 the midpoint between -1 and the first break), delta_phi
        is analytic (its singularities are the breaks: I(x) is regular wherever r is
        analytic), in the Bernstein ellipse through the nearest break, rho = 3 + sqrt(8)
        (the break lies one piece length beyond).  There it is interpolated (barycentric
        form, Berrut & Trefethen, SIAM Rev. 46 (2004) 501) from m Chebyshev points with
        m log(rho) >= _FAR_EXPONENT and m >= q (the projection's polynomial part, of
        degree < q, is then interpolated exactly): ~rho^-m < 1e-17 of delta_phi there, at
        m points instead of the ~10 graded pieces' nodes.  The Chebyshev points include the
        end itself.  Elsewhere delta_phi at the nodes."""
        tw, _ = self.w_rule
        _, om, op = self.w_ends
        lo_w, hi_w, counts = self.w_panels
        pts = self._w_mesh
        m = max(int(self.q), math.ceil(_FAR_EXPONENT / math.log(3.0 + math.sqrt(8.0)))) \
            if self._w_design is None else self._w_design[4]
        s, lam = _chebyshev_offsets(m)
        # the nodes ascend piece by piece: those on the end pieces are a prefix and a suffix
        n = tw.size
        first, last = 0, n                  # delta_phi itself at tw[first:last]
        if pts.size:
            head = int(counts[:np.searchsorted(hi_w, pts[0], side="right")].sum())
            tail = int(counts[np.searchsorted(lo_w, pts[-1], side="left"):].sum())
            if head > m and 1.0 + pts[0] > 0.0:
                first = head
            if tail > m and 1.0 - pts[-1] > 0.0:
                last = n - tail
        parts = [tw[first:last], np.array([-1.0, 1.0])]
        if first:
            parts.insert(0, -1.0 + (1.0 + pts[0]) * s)
        if last < n:
            parts.insert(-1, 1.0 - (1.0 - pts[-1]) * s)
        values = self.phi(np.concatenate(parts))
        out = np.empty(n)
        k = m if first else 0
        out[first:last] = values[k:k + last - first]
        if first:
            _barycentric(op[:first] / (1.0 + pts[0]), s, lam, values[:m], out[:first])
        if last < n:
            k += last - first
            _barycentric(om[last:] / (1.0 - pts[-1]), s, lam, values[k:k + m], out[last:])
        return out, values[-2:]

    def _log_clusters(self, side):
        """What :func:`_log_sums` needs for points beyond the end ``side`` (+1 or -1), built
        once per side: the offsets e_j = |side - t_j| of the nodes of ``w_rule`` (exact,
        ascending), c_j = w_j (delta_phi(t_j) - delta_phi(side)), their clusters
        (:func:`_cluster_starts`), centres, radii, term counts and moments
        (:func:`_log_moments`), and delta_phi(side)."""
        data = self._log_data.get(side)
        if data is None:
            _, ww = self.w_rule
            _, om, op = self.w_ends
            self._w_values()
            pe = float(self._phi_ends[(side + 1) // 2])
            data = self._log_data[side] = (
                *_log_cluster_data(om if side == 1 else op, ww, self._phi_w, pe,
                                   _LOG_TERMS + 1), pe)
        return data

    def _resolved_by_w_rule(self, v):
        """True where the fixed rule ``w_rule`` integrates 1/(t - v) to rounding on every
        piece: Gauss with q nodes on a piece whose Bernstein ellipse through v has parameter
        rho errs by ~rho^(-2q) (Trefethen, ATAP ch. 19), so 2 q log(rho) >= _FAR_EXPONENT."""
        lo, hi, counts = self.w_panels
        ok = np.ones(v.shape, dtype=bool)
        for start in range(0, v.size, _CHUNK_FAR):
            vv = v[start:start + _CHUNK_FAR].astype(complex)
            ok[start:start + _CHUNK_FAR] = np.all(
                2.0 * counts[None, :] * _log_rho(vv[:, None], lo[None, :], hi[None, :])
                >= _FAR_EXPONENT, axis=1)
        return ok

    def cauchy_off(self, v, ends=None):
        """(1/pi) int_{-1}^{1} w delta_phi / (t - v) dt at v off the open interval (-1, 1):
        complex v with Im v != 0, or real v with |v| > 1 (complex result; real there).
        ``ends``: (v - 1, v + 1) from the real coordinate (full relative precision next to
        an end).

        Where the fixed rule ``w_rule`` resolves the pole (:meth:`_resolved_by_w_rule`),
        its sum; elsewhere, with Psi = w delta_phi solving a Psi + b H[Psi] = r on (-1, 1) and
        int Psi = 0, the Riemann-Hilbert solution (Muskhelishvili 1953, sec. 107-110)

            (1/pi) int Psi/(t - z) dt = -(sin(pi alpha)/b) G(z) J(z),
            G(z) = (z-1)^alpha (z+1)^beta,
            J(z) = (1/pi) int (1-t)^-alpha (1+t)^-beta r(t)/(t - z) dt

        (principal powers, cut on [-1, 1]): G+/G- = e^{2 pi i alpha} = -(b + i a)/(b - i a)
        is the jump the equation imposes, and no polynomial multiple of G may be added
        because the left side decays at infinity like z^-(n+1).  J needs only r, which is
        cheap and has no singularity but kinks at the breaks; see :meth:`_near_j`."""
        v = np.asarray(v)
        zm1, zp1 = (v - 1.0, v + 1.0) if ends is None else ends
        v, zm1, zp1 = (np.asarray(a, dtype=complex) for a in (v, zm1, zp1))
        out = np.empty(v.shape, dtype=complex)
        if v.size == 0:
            return out
        far = self._resolved_by_w_rule(v)
        if np.any(far):
            tw, _ = self.w_rule
            wphi = self._w_values()
            vf = v[far]
            res = np.empty(vf.shape, dtype=complex)
            rows = max(1, min(_CHUNK_FAR, _BLOCK // max(tw.size, 1)))
            for start in range(0, vf.size, rows):
                vv = vf[start:start + rows]
                res[start:start + rows] = (wphi[None, :] / (tw[None, :] - vv[:, None])).sum(axis=1)
            out[far] = res / math.pi
        near = ~far
        if np.any(near):
            out[near] = self._near_cauchy(v[near], zm1[near], zp1[near])
        return out

    def _near_cauchy(self, v, zm1, zp1):
        """-(sin(pi alpha)/b) G(v) J(v) (see :meth:`cauchy_off`)."""
        sol = self.sol
        e = sol.exp
        # the weight 1/w = (1-t)^-alpha (1+t)^-beta, its shifted exponents carried exactly
        inv = Weight(alpha=-e.alpha, beta=-e.beta, alpha_p1=e.alpha_m1, beta_p1=e.beta_m1,
                     alpha_m1=e.alpha_p1, sin=-e.sin)
        # the subtraction point x0: the point of [-1, 1] nearest to v, or the end nearer to it
        # when that end is closer to it than v is (otherwise the piece between x0 and the
        # graded pieces on the far side of it would see the end's singular weight at a
        # fraction of its length: at v = 0.997 + 2.05i, 16 nodes would be off by 1e-8)
        dist = np.abs(v.imag)
        right = (zm1.real >= 0.0) | ((-zm1.real < dist) & (-zm1.real <= zp1.real))
        left = ((zp1.real <= 0.0) | (zp1.real < dist)) & ~right
        x0 = np.where(right, 1.0, np.where(left, -1.0, v.real))
        lm = np.where(right, 0.0, np.where(left, 2.0, -zm1.real))          # 1 - x0
        lp = np.where(right, 2.0, np.where(left, 0.0, zp1.real))           # 1 + x0
        zeta = np.where(right, zm1, np.where(left, zp1, 1j * v.imag))      # v - x0
        r0 = self._r(x0, call_checked(self.f, "f", (x0,), x0.shape))
        J = self._near_j(x0, lm, lp, zeta, r0) + r0 * f0_closed(inv, v, (zm1, zp1))
        m = -sol.kappa                                   # alpha + beta
        G = np.exp(e.alpha * _log_ratio(zm1, zp1)) * (zp1 ** m if m else 1.0)
        return -(e.sin / self.b) * G * J

    def _near_j(self, x0, lm, lp, zeta, r0):
        """(1/pi) int (1-t)^-alpha (1+t)^-beta (r(t) - r0) / (t - v) dt, v = x0 + zeta,
        x0 in [-1, 1] with |zeta| <= its distance to the ends unless it is an end (lm =
        1 - x0, lp = 1 + x0, all exact), r0 = r(x0).

        The integrand is bounded (|r'| near x0) but varies on the scale |zeta| there, and r
        has kinks at the breaks: Gauss on pieces split at the breaks, at x0 and at
        x0 +- |zeta| 4^j (a geometric mesh toward x0, as for a pole at distance |zeta|:
        each piece sees the pole at >= 1/3 of its length, rho >= 3, so 16 nodes leave
        3^-32 ~ 5e-16); node counts grow with the piece ((M/2 + 8) sqrt(len/2) more, M the
        number of projections) so that the polynomial part of r stays resolved.  Offsets
        d = t - x0 are carried so that t - v = d - zeta keeps full relative precision at any
        |zeta|."""
        sol = self.sol
        e = sol.exp
        out = np.zeros(x0.shape, dtype=complex)
        delta = np.maximum(np.abs(zeta), _DELTA_FLOOR)
        levels = int(np.ceil(math.log(2.0 / delta.min()) / math.log(_NEAR_RATIO))) + 1
        splits = self._near_splits()
        per_point = 2 * levels + splits.size + 3
        # r is a polynomial of degree < M (the projection) plus f - other, analytic between
        # breaks; p(t)/(t - v) = (polynomial of degree < M - 1) + p(v)/(t - v), so M/2 nodes
        # more than the pole needs integrate the polynomial part exactly on any piece; fewer
        # on short pieces, where its higher derivatives are small (scaled by length^k)
        q_poly = 0.5 * self.g_coef.size + 8
        chunk = max(1, _CHUNK_NODES // (per_point * (_NEAR_Q + 4)))
        for start in range(0, x0.size, chunk):
            sl = slice(start, start + chunk)
            xc, lmc, lpc, zc, dc, r0c = x0[sl], lm[sl], lp[sl], zeta[sl], delta[sl], r0[sl]
            P = xc.size
            steps = dc[:, None] * _NEAR_RATIO ** np.arange(levels)[None, :]
            # a grading point p toward an end is kept only while |end - p| >= |p - x0| / 2:
            # the Gauss-Legendre piece before it then sees the end's singular weight at
            # >= 2/3 of its own length, and the end piece (Gauss-Jacobi) sees x0 at >= 1/7
            up = np.where(steps * _KEEP_END <= lmc[:, None], steps, 0.0)
            down = np.where(steps * _KEEP_END <= lpc[:, None], -steps, 0.0)
            brk = splits[None, :] - xc[:, None]
            edges = np.concatenate([-lpc[:, None], down, np.zeros((P, 1)), up, brk,
                                    lmc[:, None]], axis=1)
            edges.sort(axis=1)
            lo, hi = edges[:, :-1], edges[:, 1:]
            owner = np.broadcast_to(np.arange(P)[:, None], lo.shape)
            keep = hi > lo
            lo, hi, owner = lo[keep], hi[keep], owner[keep]
            at_left = lo == -lpc[owner]
            at_right = hi == lmc[owner]
            length = hi - lo
            counts = _NEAR_Q + 4 * np.ceil(q_poly * np.sqrt(0.5 * length) / 4.0).astype(int)
            d, w, own = _panel_nodes(lo, hi, counts, at_left, at_right, lmc[owner], lpc[owner],
                                     -e.alpha, -e.beta, e.alpha_m1, e.beta_m1, 1.0 + sol.kappa)
            pt = owner[own]
            t = xc[pt] + d
            rt = self._r(t, call_checked(self.f, "f", (t,), t.shape))
            terms = w * (rt - r0c[pt]) / (d - zc[pt])
            out[sl] = (np.bincount(pt, weights=terms.real, minlength=P)
                       + 1j * np.bincount(pt, weights=terms.imag, minlength=P)) / math.pi
        return out

    def _near_splits(self):
        """Where :meth:`_near_j` splits [-1, 1] whatever the point: the breaks, and points
        that grade the gap between a break and an end it lies close to toward the break,
        end -+ delta 4^j (delta the break's distance to the end), until _NEAR_Q nodes
        resolve that end's factor on the rest of the gap
        (:func:`sie.quadrature._composite_pieces`).  Without them the piece that ends at
        the break sees the end's branch point at a fraction of its length (a break 1e-4
        from +1 left the transform 1e-7 from -1 off by 1e-3 at n = 48).  Computed once."""
        if self._splits is None:
            lo, hi, _, graded = _composite_pieces(self.breaks, _NEAR_Q, _NEAR_Q,
                                                  _NEAR_RATIO, _END_EXPONENT, _COUNT_LADDER)
            self._splits = np.unique(np.concatenate([self.breaks, hi[:-1]])) if graded \
                else self.breaks
        return self._splits

    # -- logarithmic potential -------------------------------------------------------
    def _at_level(self, k):
        """This correction with ``w_rule`` made for 10^-k of its own scale
        (:func:`_accuracy_rule`: graded less deeply toward the breaks, fewer nodes on the
        graded pieces), and with its own values at that rule's nodes; made once per k (it
        shares everything else: the 1/w rules, f, the constant)."""
        view = self._accurate.get(k)
        if view is None:
            sol = self.sol
            design = _accuracy_rule(k, sol.alpha, sol.beta, self.g_coef.size + 1)
            view = copy.copy(self)          # the fields below replaced, the others shared
            view._w_mesh, view._w_design = graded_points(self.breaks, design[0]), design
            view._w = view._wphi = view._phi_w = view._phi_ends = view._log_ends = None
            view._far_moments = view._interp = None
            view._log_data, view._accurate = {}, {}
            self._accurate[k] = view
        return view

    def for_accuracy(self, tol):
        """The correction whose log potential (:meth:`log_potential`, :meth:`far_coefficients`)
        errs by at most tol times the piece's scale (1/pi) int w |phi|, phi the whole
        (the series plus delta_phi): self where tol is None or asks for rounding, else
        :meth:`_at_level` for tol.  That rule leaves ~10^-k (_RULE_MARGIN 10^-k taken) of
        delta_phi's own scale (1/pi) int w |delta_phi|, far below the piece's where the
        series resolves the smooth part of phi (1e-4 to 1e-3 of it in tests); where
        delta_phi's scale is not that small, k is raised by the ratio (the piece's scale
        from below by |c_0| mu_0 = |int w phi|, else summed on the rule)."""
        k = _accuracy_level(tol)
        if k is None:
            return self
        view = self._at_level(k)
        own = _RULE_MARGIN * 10.0 ** -k * float(np.sum(np.abs(view._w_values())))
        sol = self.sol
        if own <= tol * abs(sol.coefficients[0]) * sol.weight_data.mu0:
            return view
        tw, ww = view.w_rule
        whole = float(np.sum(ww * np.abs(
            jacobi_series(sol.coefficients, sol.alpha, sol.beta, tw) + view._phi_w)))
        if own <= tol * whole:
            return view
        return self.for_accuracy(10.0 ** -k * tol * whole / own if whole > 0.0 else None)

    def log_potential(self, v, ends=None, l0_values=None, tol=None):
        """(1/pi) int_{-1}^{1} w delta_phi log|v - t| dt at real v (any v); with ``tol``, to
        ~tol of the piece's scale (1/pi) int w |phi| (:meth:`for_accuracy`).

        |v| >= 1: the sum of ``w_rule`` with delta_phi(e) subtracted at the nearer end e and
        added back through the closed form of (1/pi) int w log|v - t| (:func:`sie.cauchy.l0`):
        the rest vanishes at e like (1 -+ t)^(1 + exponent), so the logarithm's singularity
        at or next to e costs nothing.  |v| < 1: from V' = -H[Psi] = (a Psi - r)/b (the
        equation on (-1, 1)) integrated from the nearer end e,

            V(v) = V(e) + (a int_e^v Psi - int_e^v r) / b,

        with int_e^v Psi from the piece sums of ``w_rule`` plus one Gauss rule on the part of
        the piece containing v, and int_e^v r by Gauss-Legendre split at the breaks.
        ``l0_values``: the weight's potential :func:`sie.cauchy.l0` at v where the caller
        has it."""
        if tol is not None:
            rem = self.for_accuracy(tol)
            if rem is not self:
                return rem.log_potential(v, ends, l0_values)
        v = np.asarray(v, dtype=float)
        zm1, zp1 = (v - 1.0, v + 1.0) if ends is None else (np.asarray(ends[0], dtype=float),
                                                            np.asarray(ends[1], dtype=float))
        out = np.empty(v.shape)
        inside = (zm1 < 0.0) & (zp1 > 0.0)
        if np.any(~inside):
            out[~inside] = self._log_outside(v[~inside], zm1[~inside], zp1[~inside],
                                             None if l0_values is None
                                             else l0_values[~inside])
        if np.any(inside):
            out[inside] = self._log_inside(v[inside], zm1[inside], zp1[inside])
        return out

    def far_coefficients(self, tol=None):
        """(M_0, M_1 / 1, ..., M_K / K), M_k = int w delta_phi t^k by ``w_rule``, K =
        _LOG_FAR_TERMS: what :func:`log_far` sums the log potential at |v| >= 2 from (read-only;
        computed once); with ``tol``, by the rule of :meth:`for_accuracy`."""
        if tol is not None:
            rem = self.for_accuracy(tol)
            if rem is not self:
                return rem.far_coefficients()
        if self._far_moments is None:
            tw, _ = self.w_rule
            moments = np.empty(_LOG_FAR_TERMS + 1)
            _power_moments(tw, self._w_values(), moments)
            moments[1:] /= _FAR_DIVISORS
            moments.flags.writeable = False
            self._far_moments = moments
        return self._far_moments

    def _log_outside(self, v, zm1, zp1, l0_values=None):
        """The |v| >= 1 branch of :meth:`log_potential`.  |v| < _LOG_FAR: the sum of
        ``w_rule`` over w (delta_phi - delta_phi(e)) log|v - t|, |v - t| from the offsets to
        the nearer end e (no cancellation next to it), by clusters of nodes
        (:func:`_log_sums`), plus delta_phi(e) times the weight's potential.  Beyond, the
        expansion of log|v - t| in t / v over the moments of w delta_phi (:func:`log_far`,
        :meth:`far_coefficients`)."""
        far = np.abs(v) >= _LOG_FAR
        count = int(np.count_nonzero(far))
        if count == v.size:
            return log_far(v, self.far_coefficients())
        out = np.empty(v.shape)
        if count:
            out[far] = log_far(v[far], self.far_coefficients())
            near = ~far
            v, zm1, zp1 = v[near], zm1[near], zp1[near]
            if l0_values is not None:
                l0_values = l0_values[near]
        weight_potential = l0(self.sol.weight_data, v) if l0_values is None else l0_values
        right = zm1 >= 0.0
        z = np.where(right, zm1, -zp1)            # the distance beyond the nearer end
        sums = np.empty(v.shape)
        pe = [0.0, 0.0]
        for i, (side, take) in enumerate(((1, right), (-1, ~right))):
            if take.any():
                *clusters, pe[i] = self._log_clusters(side)
                _log_sums_where(z, take, *clusters, sums)
        near_sums = sums / math.pi + np.where(right, pe[0], pe[1]) * weight_potential
        if not count:
            return near_sums
        out[~far] = near_sums
        return out

    def _phi_in_piece(self, t, k):
        """delta_phi at points t of the pieces k of ``w_rule``.  On a piece where delta_phi is
        analytic in the Bernstein ellipse rho with q_k log(rho) >= _FAR_EXPONENT (rho from
        the nearest break: the only singularities of delta_phi), the interpolant through
        its q_k nodes (barycentric form, Berrut & Trefethen, SIAM Rev. 46 (2004) 501) is
        exact to ~rho^(-q_k) < 4e-18 and costs O(q_k) instead of a full evaluation; the
        projection's polynomial part (degree < q_k) is interpolated exactly.  Elsewhere
        (the short pieces next to a break) delta_phi itself."""
        if self._interp is None:
            lo, hi, counts = self.w_panels
            tw, ww = self.w_rule
            starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
            brk = self.breaks.astype(complex)
            ok = np.ones(lo.size, dtype=bool)
            if brk.size:
                ok = np.all(counts[:, None] * _log_rho(brk[None, :], lo[:, None], hi[:, None])
                            >= _FAR_EXPONENT, axis=1)
            phi_w = self._w_values() / ww
            bary = {}
            for j in np.flatnonzero(ok):
                sl = slice(starts[j], starts[j] + counts[j])
                s = (2.0 * tw[sl] - (lo[j] + hi[j])) / (hi[j] - lo[j])
                if not np.all(np.diff(s) > 0.0):    # a piece within rounding of a point of
                    ok[j] = False                   # the mesh (two grading points that agree
                    continue                        # to 1 ulp): its nodes coincide
                diff = s[:, None] - s[None, :]
                np.fill_diagonal(diff, 1.0)
                logs = np.log(np.abs(diff)).sum(axis=1)       # scaled: no overflow at large q
                lam = np.prod(np.sign(diff), axis=1) * np.exp(logs.min() - logs)
                bary[j] = (s, lam, phi_w[sl])
            self._interp = (ok, bary)
        ok, bary = self._interp
        out = np.empty(t.shape)
        direct = ~ok[k]
        if np.any(direct):
            out[direct] = self.phi(t[direct])
        lo, hi, _ = self.w_panels
        for j in np.unique(k[~direct]):
            sel = np.flatnonzero(k == j)
            s, lam, fj = bary[j]
            x = (2.0 * t[sel] - (lo[j] + hi[j])) / (hi[j] - lo[j])
            diff = x[:, None] - s[None, :]
            hit = diff == 0.0
            diff[hit] = 1.0
            c = lam / diff
            val = (c @ fj) / c.sum(axis=1)
            rows, cols = np.nonzero(hit)
            val[rows] = fj[cols]
            out[sel] = val
        return out

    def _log_inside(self, v, zm1, zp1):
        sol = self.sol
        e = sol.exp
        if self._log_ends is None:
            ends = np.array([-1.0, 1.0])
            self._log_ends = tuple(self._log_outside(ends, ends - 1.0, ends + 1.0))
        lo_w, hi_w, counts_w = self.w_panels
        tw, _ = self.w_rule
        wphi = self._w_values()
        K = lo_w.size
        sums = np.bincount(self.w_ends[0], weights=wphi, minlength=K)
        before = np.concatenate([[0.0], np.cumsum(sums)])            # int_{-1}^{lo_k} Psi
        after = np.concatenate([np.cumsum(sums[::-1])[::-1], [0.0]])   # int_{lo_k}^{1} Psi
        k = np.clip(np.searchsorted(hi_w, v, side="right"), 0, K - 1)  # piece holding v
        left = v < 0.0
        lm, lp = -zm1, zp1
        # the part of piece k between v and the nearer end's side, as offsets from v
        lo = np.where(left, lo_w[k] - v, 0.0)
        hi = np.where(left, 0.0, hi_w[k] - v)
        at_left = left & (k == 0)
        at_right = ~left & (k == K - 1)
        lo = np.where(at_left, -lp, lo)
        hi = np.where(at_right, lm, hi)
        d, w, o = _panel_nodes(lo, hi, counts_w[k] + 2, at_left, at_right, lm, lp,
                               e.alpha, e.beta, e.alpha_p1, e.beta_p1, 1.0 - sol.kappa)
        part = np.bincount(o, weights=w * self._phi_in_piece(v[o] + d, k[o]), minlength=v.size)
        int_psi = np.where(left, before[k] + part, -(part + after[k + 1]))      # int_e^v Psi
        # int_e^v r: Gauss-Legendre on the pieces between breaks, clipped to [e, v]
        gaps = np.concatenate([[-1.0], self.breaks, [1.0]])
        glo = np.where(left[:, None], np.minimum(gaps[None, :-1], v[:, None]),
                       np.maximum(gaps[None, :-1], v[:, None]))
        ghi = np.where(left[:, None], np.minimum(gaps[None, 1:], v[:, None]),
                       np.maximum(gaps[None, 1:], v[:, None]))
        u, wu = gauss_jacobi_cached(int(self.q), 0.0, 0.0)
        half = 0.5 * (ghi - glo)
        t = glo[..., None] + half[..., None] * (1.0 + u)
        rt = self._r(t.ravel(), call_checked(self.f, "f", (t.ravel(),), (t.size,)))
        int_r = ((rt.reshape(t.shape) * wu).sum(axis=2) * half).sum(axis=1)
        int_r = np.where(left, int_r, -int_r)
        base = np.where(left, self._log_ends[0], self._log_ends[1])
        return base + (self.a * int_psi - int_r) / self.b
