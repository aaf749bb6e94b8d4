"""Gauss-Jacobi quadrature nodes and weights in O(n) operations.

    int_{-1}^{1} (1-x)^alpha (1+x)^beta g(x) dx  ~  sum_k w_k g(x_k)

Why we write this ourselves: scipy's ``roots_jacobi`` is O(n^2) (a dense
eigenvalue problem) and its weights lose digits at large n (2e-5 relative at
n = 1e4).  Everything is computed in the angle theta (x = cos theta), measured
from the nearer end, so nodes next to x = +-1 keep full *relative* precision
in 1 - |x| and the weights never square a derivative taken in x near an end.

Dispatch ladder (read top to bottom)
------------------------------------
1. n == 1                              closed form.
2. max(alpha, beta) > 5                Newton in theta on the three-term
                                       recurrence (O(n^2)), started from
                                       Golub-Welsch eigenvalues (LAPACK dsterf,
                                       O(n^2)).
3. otherwise                           for n <= N_RECURRENCE_MAX first the
                                       small-n rule: Halley in theta on the
                                       three-term recurrence for every node,
                                       started from the Gatteschi-Pittaluga
                                       (1985) estimates, vectorised over the
                                       nodes and compiled whole
                                       (:func:`_recurrence_rule`; O(n^2), ~10 us
                                       at n = 100).  Where it reports a node it
                                       could not finish (an exponent very near
                                       -1 can need more passes), and for
                                       n > N_RECURRENCE_MAX: Hale & Townsend
                                       (2013), Newton in theta on Hahn's
                                       interior asymptotic expansion (O(1) per
                                       node) from the same estimates, compiled
                                       whole (:func:`_asymptotic_rule`); for
                                       n <= 2 N_BOUNDARY the Golub-Welsch rule
                                       described below (:func:`_small_rule`).
On rungs 2 and 3 the ``N_BOUNDARY`` nodes nearest each end (where the expansion
is not accurate, and where the recurrence loses relative accuracy in the weights
for exponents near -1 at large n) are finished by Newton on the terminating
hypergeometric series at that end, summed in double-double in t = 1 - x so that it
keeps relative precision (O(1) terms per node: O(n) overall); for n <= N_RECURRENCE_MAX
rung 3 finishes them on the recurrence instead (O(n) per node, a few microseconds in
all, as accurate there).  Where rung 3 cannot finish a boundary node, rung 2 takes
the rule (for n <= N_RECURRENCE_MAX) or rung 3 in its general form, which finishes it
on the recurrence.  For n <= 2 N_BOUNDARY
the Golub-Welsch angles go straight to that series (with an exponent > 5 at that end,
through the recurrence first).  Where the series cancels past
dd precision (exponents ~20 and up), or where with an exponent > 5 at that end it does
not confirm the recurrence's root, the recurrence is kept.

Large exponents (max(alpha, beta) > 5) take rung 2 for every n: O(n^2), ~1 s at n = 1e4,
as accurate as the other rungs (see _newton_recurrence for what that took).  What it
cannot deliver is refused before any work (_check_large_exponents): n > 20000 (time), and
weights outside the double range (they are ~(m/n)^(2m) next to an end with exponent m).

Nodes with x >= 0 are computed with (alpha, beta) and theta measured from
x = 1; nodes with x < 0 by the reflection P_n^{(a,b)}(-x) = (-1)^n P_n^{(b,a)}(x)
with theta measured from x = -1.

References
----------
N. Hale and A. Townsend, "Fast and accurate computation of Gauss-Legendre and
Gauss-Jacobi quadrature nodes and weights", SIAM J. Sci. Comput. 35 (2013)
A652-A674 (interior expansion, eq. 3.1, after E. Hahn, 1980).
L. Gatteschi and G. Pittaluga, "An asymptotic expansion for the zeros of
Jacobi polynomials", in Mathematical Analysis, Teubner (1985) 70-86.
G. H. Golub and J. H. Welsch, Math. Comp. 23 (1969) 221-230.
"""
from __future__ import annotations

import functools
import math
import sys

import numpy as np

from ._jit import jit
from .errors import InvalidOrderError, check_exponent, check_order
from ._dd import dd_add, dd_div, dd_mul, two_sum
from .special import _log_gamma_ratio, jacobi_moment, log_gamma_ratio

__all__ = ["gauss_jacobi", "N_RECURRENCE_MAX", "N_BOUNDARY"]

N_RECURRENCE_MAX = 100  # plain-double recurrence coefficients, and the small-n rule, up to here
N_BOUNDARY = 10         # nodes per end done by recurrence on rung 3
# ... for n <= N_RECURRENCE_MAX: Hahn's expansion is within 2e-14 (angle and weight,
# relative) from the sixth node off an end on (n = 21..100, exponents in (-1, 5]; 6e-13 at
# the fifth, 2e-8 at the fourth, at n = 100)
_N_BOUNDARY_SMALL = 6
_ASY_MAX_PARAM = 5.0    # Hahn's expansion coefficients grow with |alpha|, |beta|
_M_MAX = 40             # cap on the number of terms of the interior expansion
_X_INSIDE = float(np.nextafter(1.0, 0.0))   # the largest double below 1
_DD_CANCEL_MAX = 1e16   # dd boundary series: cancellation up to which Q' keeps ~16 digits
_NEWTON_MAX = 12
_TINY = sys.float_info.min      # smallest normal double
_LOG10_TINY = math.log10(_TINY)
_LOG10_HUGE = math.log10(sys.float_info.max)
_N_LARGE_EXPONENT_MAX = 20_000  # rung 2 for max(alpha, beta) > _ASY_MAX_PARAM: ~5 s here
_SECONDS_PER_N2 = 1.2e-8        # rung 2 time / n^2 (2-core CI machine; dsterf is 90% of it)


# --------------------------------------------------------------------------
# Three-term recurrence near x = 1, Reinsch-modified
#
# With Q_k = P_k(x)/P_k(1), P_k(1) = (a+1)_k/k!, and E_k = Q_k - Q_{k-1}, the
# recurrence DLMF 18.9.1 becomes (x = 1 - t)
#     E_{k+1} = Ct_k E_k - Bt_k t Q_k,     Q_{k+1} = Q_k + E_{k+1},
#     Bt_k = (s+1)(s+2) / (2 (k+a+b+1)(k+a+1)),
#     Ct_k = k (k+b)(s+2) / ((k+a+b+1) s (k+a+1)),     s = 2k+a+b,
# which carries the small differences E_k instead of subtracting nearly equal
# O(1) numbers: the plain recurrence loses ~n^1.5 eps relative accuracy next
# to x = 1 (measured: 4e-11 in the first root angle at n = 1000, alpha = -0.99),
# this form does not.  (Reinsch's modification, cf. Oliver, Numer. Math. 1977.)
# --------------------------------------------------------------------------
@jit()
def _dd_recurrence_coefficients(n, a, b):
    """Bt_k, Ct_k (k = 1..n-1) of the block comment above, in double-double and rounded once,
    for _newton_recurrence; E_1 / t in Bt[0].  (A kernel of its own: inlined there it cost
    0.5 s more compile time, and only large exponents with n > N_RECURRENCE_MAX need it.)"""
    Bt = np.empty(n)
    Ct = np.empty(n)
    ap1h, ap1l = two_sum(a, 1.0)
    bp1h, bp1l = two_sum(b, 1.0)
    abh, abl = dd_add(ap1h, ap1l, bp1h, bp1l)                       # a + b + 2
    for k in range(1, n):
        d1h, d1l = dd_add(abh, abl, k - 1.0, 0.0)                   # k + a + b + 1
        sh, sl = dd_add(abh, abl, 2.0 * (k - 1), 0.0)               # s = 2k + a + b
        s1h, s1l = dd_add(sh, sl, 1.0, 0.0)
        s2h, s2l = dd_add(sh, sl, 2.0, 0.0)
        a1h, a1l = dd_add(ap1h, ap1l, k + 0.0, 0.0)                 # k + a + 1
        b1h, b1l = dd_add(bp1h, bp1l, k - 1.0, 0.0)                 # k + b
        dah, dal = dd_mul(d1h, d1l, a1h, a1l)
        nh, nl = dd_mul(s1h, s1l, s2h, s2l)
        Bt[k] = dd_div(nh, nl, 2.0 * dah, 2.0 * dal)[0]
        nh, nl = dd_mul(b1h, b1l, s2h, s2l)
        nh, nl = dd_mul(nh, nl, k + 0.0, 0.0)
        dh, dl = dd_mul(dah, dal, sh, sl)
        Ct[k] = dd_div(nh, nl, dh, dl)[0]
    Bt[0] = -dd_div(abh, abl, 2.0 * ap1h, 2.0 * ap1l)[0]
    return Bt, Ct


_NO_COEFFICIENTS = np.empty(0)


def _newton_recurrence(n, a, b, theta):
    """_newton_recurrence_kernel with the recurrence coefficients in double-double for
    n > N_RECURRENCE_MAX; up to there the bias of plain double (<= n * 7e-17 in the weights)
    is below the rule's other errors, and dd would cost ~4 us at n = 50."""
    if n > N_RECURRENCE_MAX:
        return _newton_recurrence_kernel(n, a, b, theta, *_dd_recurrence_coefficients(n, a, b))
    return _newton_recurrence_kernel(n, a, b, theta, _NO_COEFFICIENTS, _NO_COEFFICIENTS)


@jit()
def _newton_recurrence_kernel(n, a, b, theta, Bt, Ct):
    """Newton in theta on P_n^{(a,b)}(cos theta) via the recurrence in t = 2 sin^2(theta/2).

    Returns the refined angles, dQ_n/dtheta at them (Q_n = P_n / P_n(1)), and whether
    Newton converged there; where it did not (a start far from a root next to an end, see
    below), the angle returned is the start.
    dP_n/dtheta = -sin(theta) P_n'(x) and, from DLMF 18.9.17,
    (2n+a+b)(1-x^2) P_n' = n[(a-b) - (2n+a+b)x] P_n + 2(n+a)(n+b) P_{n-1};
    divided by P_n(1), with P_{n-1}(1)/P_n(1) = n/(n+a):
    dQ_n/dtheta = -(n[(a-b) - (2n+a+b)x] Q_n + 2n(n+b) Q_{n-1}) / ((2n+a+b) sin theta).

    Each pass runs the recurrence of the block comment above for (Q_n, Q_{n-1}) at the
    angles still iterating.  Q is carried as an unevaluated sum q + lo (Knuth's TwoSum),
    renormalised at every step: next to x = 1 the O(1) partial sums Q_k absorb O(t)
    increments E_k, and without the compensation their rounding errors (eps per step)
    add up to n*eps.  The renormalisation matters for large exponents: Q_k then falls
    from 1 to ~n^{-a} a! in the interior, and a lo that kept the early O(eps) rounding
    errors would leave q + lo with an absolute error ~1e-33 against a value of ~1e-26
    (measured without it: nodes 1.5e-9 and weights 1e-6 off at n = 200,
    alpha = 20).  For n > N_RECURRENCE_MAX, Bt_k and Ct_k are formed in double-double and
    rounded once (_dd_recurrence_coefficients): rounded factor by factor they are biased
    (mean -7e-17 relative at alpha = -1 + 1e-6, beta = 20), and the bias adds up to
    ~n eps in every weight (measured at n = 1e4: 6e-13 rounded factor by factor, 2e-14 in dd).

    Newton stops for an angle once its step is below 1e-9 theta and |p step| < 1e-6,
    p = [(a-b) + (a+b+1) cos theta] / sin theta (so the step left after it is below
    ~|p| step^2 / 2): one more pass then takes the last step and moves dQ_n/dtheta to
    the new angle by the differential equation, Q_n'' = -p Q_n' at a root, i.e.
    dQ_n/dtheta(theta - s) = dQ_n/dtheta(theta) (1 + p s).  Computing the weight from
    the derivative there, instead of from (sin theta / Q_{n-1})^2, matters: the latter is
    ill-conditioned in theta (measured: 1.6e-16 relative in theta gave 3e-13 in the
    weight at n = 1000, alpha = 20).  Angles that have stopped leave the passes, so a
    slow start next to an end (Newton in theta only halves the error far from the first
    root) costs O(n) per pass, not O(n^2); such a node is one of the N_BOUNDARY nearest
    the end, which the dd series redoes from its start.  (One kernel with scalar loops, no array
    expressions: numba compiles it ~4x faster than a separate recurrence kernel written
    with array arithmetic.)
    """
    # Bt_k, Ct_k of the block comment above, k = 1..n-1 (and E_1 / t), unless given (from
    # _dd_recurrence_coefficients, E_1 / t in Bt[0]): formed from a+1 and b+1 (exact there):
    # with both exponents near -1, s = 2k + a + b at k = 1 is ~(a+1) + (b+1), and
    # (2 + a) + b would leave it (and every weight) 1e-8 off at a, b = -1 + 1e-8.
    if Bt.shape[0] == 0:
        Bt = np.empty(n)
        Ct = np.empty(n)
        ap1 = a + 1.0
        abp2 = ap1 + (b + 1.0)
        for k in range(1, n):
            s = 2.0 * (k - 1) + abp2
            Bt[k] = (s + 1.0) * (s + 2.0) / (2.0 * ((k - 1) + abp2) * (k + ap1))
            Ct[k] = k * ((k - 1) + (b + 1.0)) * (s + 2.0) / (((k - 1) + abp2) * s * (k + ap1))
        Bt[0] = -abp2 / (2.0 * ap1)
    e1 = Bt[0]                                                      # E_1 / t
    th = theta.copy()
    m = th.shape[0]
    dq_root = np.empty(m)
    converged = np.zeros(m, dtype=np.bool_)
    state = np.zeros(m, dtype=np.int8)     # 0: iterating, 1: last step next pass, 2: done
    act = np.empty(m, dtype=np.int64)      # the angles in this pass
    t = np.empty(m)
    q = np.empty(m)
    lo = np.empty(m)
    e = np.empty(m)
    q_prev = np.empty(m)
    lo_prev = np.empty(m)
    c2 = 2.0 * n + a + b
    for it in range(_NEWTON_MAX + 1):
        na = 0
        for i in range(m):
            if state[i] != 2:
                act[na] = i
                na += 1
        if na == 0:
            break
        for j in range(na):
            sh = math.sin(0.5 * th[act[j]])
            t[j] = 2.0 * sh * sh
            q_prev[j] = 1.0
            lo_prev[j] = 0.0
            e[j] = e1 * t[j]
            q[j] = 1.0 + e[j]
            lo[j] = (1.0 - q[j]) + e[j]
        for k in range(1, n):
            Bk = Bt[k]
            Ck = Ct[k]
            for j in range(na):
                ej = Ck * e[j] - Bk * t[j] * (q[j] + lo[j])
                e[j] = ej
                q_prev[j] = q[j]
                lo_prev[j] = lo[j]
                s = q[j] + ej                      # TwoSum(q, E), then renormalise
                bb = s - q[j]
                r = lo[j] + ((q[j] - (s - bb)) + (ej - bb))
                h = s + r
                bb = h - s
                lo[j] = (s - (h - bb)) + (r - bb)
                q[j] = h
        for j in range(na):
            i = act[j]
            x = 1.0 - t[j]
            sin_th = math.sqrt(t[j] * (2.0 - t[j]))
            qn = q[j] + lo[j]
            dq = -(n * ((a - b) - c2 * x) * qn
                   + 2.0 * n * (n + b) * (q_prev[j] + lo_prev[j])) / (c2 * sin_th)
            step = qn / dq
            p = ((a - b) + (a + b + 1.0) * x) / sin_th
            new = th[i] - step
            if not new > 0.0:       # overshot past the end (or NaN): halve towards it instead
                new = 0.5 * th[i]
            th[i] = new
            if state[i] == 1 or it == _NEWTON_MAX:
                dq_root[i] = dq * (1.0 + p * step)
                converged[i] = state[i] == 1
                state[i] = 2
            elif abs(step) < 1e-9 * th[i] and abs(p * step) < 1e-6:
                state[i] = 1
    for i in range(m):
        if not converged[i]:
            th[i] = theta[i]        # its start: a better guess for the dd series than where it went
    return th, dq_root, converged


# --------------------------------------------------------------------------
# Boundary nodes: the terminating hypergeometric (Frobenius) series at x = 1,
#     P_n(1-t)/P_n(1) = 2F1(-n, n+a+b+1; a+1; t/2) = sum_k T_k   (DLMF 18.5.7),
# summed in double-double.  Next to the end it behaves like the series of
# J_a(rho theta): terms peak near e^{rho theta}, so the tenth node (rho theta
# ~ 31 + a) cancels ~13 digits for a ~ 0, which dd arithmetic (~32 digits) absorbs;
# cost is O(1) per node (about 2 rho theta terms), independent of n.
# --------------------------------------------------------------------------
@jit()
def _newton_boundary(n, a, b, theta):
    """Newton in t = 1 - x on the dd series; returns the angles and dQ_n/dt at them.

    The term ratios rho_k = (k-n)(k+n+1+a+b) / ((k+1+a)(k+1)) do not depend on t:
    they are formed once (as far as the series reach), in dd, and each evaluation of the
    series costs two dd products per term for T_{k+1} = T_k rho_k (t/2) plus the sums
    S = sum T_k (= Q_n),  S1 = sum k T_k (= t Q_n'),  S2 = sum k(k-1) T_k (= t^2 Q_n''),
    all three in dd (S2 cancels like S).

    Newton runs in t, not theta: next to x = 1, Q_n is nearly linear in t, so a start far
    to the right of the first root (an exponent near -1 puts it ~sqrt(a+1) closer to the
    end than the asymptotic estimates) converges in a few steps, where Newton in theta
    only halves the error per step.  It stops within an ulp of the root, or when the steps
    stop shrinking at the series' noise floor (large exponents: e^{rho theta} cancels more
    than dd holds).  The derivative is then moved from the last iterate to the root,
    Q'(t*) = Q'(t) - Q''(t) Q(t)/Q'(t), without another evaluation.

    Third value: the cancellation in Q', the largest term over |S1|.  Below 1e16, dd leaves
    Q' ~16 digits; large exponents (a ~ 20 and up) exceed it at the outer boundary nodes,
    and the caller uses the recurrence there.
    """
    rh = np.empty(n)
    rl = np.empty(n)
    filled = 0      # rho_k is formed when a series first needs it (~100 terms of n = 1e5)
    abh, abl = two_sum(a, b)
    th = theta.copy()
    m = th.shape[0]
    dqt = np.empty(m)
    cancel = np.empty(m)
    for i in range(m):
        sh = math.sin(0.5 * th[i])
        t = 2.0 * sh * sh
        if t < 1e-300:      # t = 0 (a clipped start): Newton's first step is then the
            t = 1e-300      # linearisation of Q_n at the end
        q = 0.0
        dq = 1.0
        d2q = 0.0
        prev = math.inf
        for it in range(_NEWTON_MAX):
            u = 0.5 * t
            Th, Tl = 1.0, 0.0               # T_0
            Sh, Sl = 1.0, 0.0
            S1h, S1l = 0.0, 0.0
            S2h, S2l = 0.0, 0.0
            peak = 1.0
            for k in range(n):
                if k == filled:
                    c1h, c1l = dd_add(abh, abl, k + n + 1.0, 0.0)
                    numh, numl = dd_mul(c1h, c1l, k - n + 0.0, 0.0)
                    c2h, c2l = two_sum(a, k + 1.0)
                    denh, denl = dd_mul(c2h, c2l, k + 1.0, 0.0)
                    rh[k], rl[k] = dd_div(numh, numl, denh, denl)
                    filled += 1
                Th, Tl = dd_mul(Th, Tl, rh[k], rl[k])
                Th, Tl = dd_mul(Th, Tl, u, 0.0)
                kk = k + 1.0
                Sh, Sl = dd_add(Sh, Sl, Th, Tl)
                vh, vl = dd_mul(Th, Tl, kk, 0.0)
                S1h, S1l = dd_add(S1h, S1l, vh, vl)
                vh, vl = dd_mul(vh, vl, kk - 1.0, 0.0)
                S2h, S2l = dd_add(S2h, S2l, vh, vl)
                at = abs(Th)
                if at > peak:
                    peak = at
                if at < 1e-34 * peak and kk > 2.0:
                    break
            q = Sh + Sl
            dq = (S1h + S1l) / t
            d2q = (S2h + S2l) / (t * t)
            dt = q / dq
            t_new = t - dt
            if t_new <= 0.0:
                # overshot past the end (a start far right of the first root): the chord
                # through Q(0) = 1 and Q(t) < 0, exact when Q is linear in t there
                t_new = t / (1.0 - q) if q < 0.0 else 0.5 * t
                dt = t - t_new
            t = t_new
            step = abs(dt)
            if step <= 5e-16 * t:           # within an ulp of the root
                break
            if step < 1e-9 * t and step > 0.5 * prev:
                break                       # steps no longer shrink: the series' noise floor
            prev = step
        dqt[i] = dq - d2q * q / dq
        th[i] = 2.0 * math.asin(math.sqrt(0.5 * t))
        cancel[i] = peak / abs(S1h)
    return th, dqt, cancel


# --------------------------------------------------------------------------
# Hahn's interior expansion (Hale & Townsend 2013, eq. 3.1)
#   P_n(cos th) = K g(th) / (sin(th/2)^(a+1/2) cos(th/2)^(b+1/2)),
#   K = 2^(2 rho) B(n+a+1, n+b+1) / pi,  rho = n + (a+b+1)/2,
#   g = sum_m 1/(2rho+1)_m sum_l U_l V_{m-l} cos(rho th + m th/2 - (a+l+1/2) pi/2),
#   U_l = (1/2+a)_l (1/2-a)_l / (l! (2 sin(th/2))^l),
#   V_j = (1/2+b)_j (1/2-b)_j / (j! (2 cos(th/2))^j).
# --------------------------------------------------------------------------
@jit()
def _hahn_g(n, a, b, th, tol, U, V):
    """g(th) and g'(th) of the interior expansion; third value: terms used.

    U, V are scratch arrays of length _M_MAX (filled here as far as needed).
    """
    rho = n + 0.5 * (a + b + 1.0)
    s2 = math.sin(0.5 * th)
    c2 = math.cos(0.5 * th)
    cot2 = c2 / s2
    tan2 = s2 / c2
    U[0] = 1.0
    V[0] = 1.0
    # e^{i ph_m}, ph_m = psi0 + m th/2, by rotation
    psi0 = rho * th - (a + 0.5) * 0.5 * math.pi
    cp = math.cos(psi0)
    sp = math.sin(psi0)
    cr = c2                     # e^{i th/2} = cos(th/2) + i sin(th/2)
    sr = s2
    g = 0.0
    dg = 0.0
    e_m = 1.0
    used = 0
    small = 0
    for m in range(_M_MAX):
        if m > 0:
            e_m /= (2.0 * rho + m)
            U[m] = U[m - 1] * (m - 0.5 + a) * (m - 0.5 - a) / (m * 2.0 * s2)
            V[m] = V[m - 1] * (m - 0.5 + b) * (m - 0.5 - b) / (m * 2.0 * c2)
            cp, sp = cp * cr - sp * sr, sp * cr + cp * sr
        # W = sum_l U_l (-i)^l V_{m-l};  dW = sum_l U_l (-i)^l V_{m-l} [-(l/2)cot + ((m-l)/2)tan]
        wr = 0.0
        wi = 0.0
        dwr = 0.0
        dwi = 0.0
        bound = 0.0
        for l in range(m + 1):
            c = U[l] * V[m - l]
            bound += abs(c)
            dc = c * (-0.5 * l * cot2 + 0.5 * (m - l) * tan2)
            r = l & 3
            if r == 0:
                wr += c
                dwr += dc
            elif r == 1:
                wi -= c
                dwi -= dc
            elif r == 2:
                wr -= c
                dwr -= dc
            else:
                wi += c
                dwi += dc
        # Re[e^{i ph} W] and its derivative (d ph/d th = rho + m/2)
        g += e_m * (cp * wr - sp * wi)
        dg += e_m * ((cp * dwr - sp * dwi) - (rho + 0.5 * m) * (sp * wr + cp * wi))
        used = m + 1
        if e_m * bound < tol:
            small += 1
            if small >= 2:
                break
        else:
            small = 0
    return g, dg, used


@jit()
def _newton_interior(n, a, b, theta, const):
    """Newton in theta on Hahn's g: angles, weights, and the most terms used.

    g is (up to a constant) u = sin^{a+1/2}(th/2) cos^{b+1/2}(th/2) P_n(cos th),
    which solves u'' + Q(th) u = 0 with Q = rho^2 + (1/4-a^2)/(4 sin^2(th/2))
    + (1/4-b^2)/(4 cos^2(th/2)) (Szegő 1975, eq. 4.24.2).  So g'' = 0 at a
    root, Newton converges cubically, and after the last step s the derivative
    at the root is g'(1 + Q s^2/2) without another evaluation.
    Weights: w = const * sin^{2a+1}(th/2) cos^{2b+1}(th/2) / g'(th)^2.
    """
    rho = n + 0.5 * (a + b + 1.0)
    th = theta.copy()
    m = th.shape[0]
    w = np.empty(m)
    U = np.empty(_M_MAX)
    V = np.empty(_M_MAX)
    maxused = 0
    tol = 2.0 ** -56
    small_step = 1e-6 / rho
    for i in range(m):
        x = th[i]
        dg = 1.0
        for it in range(_NEWTON_MAX):
            g, dg, used = _hahn_g(n, a, b, x, tol, U, V)
            step = g / dg
            x -= step
            if used > maxused:
                maxused = used
            if abs(step) < small_step:
                s2 = math.sin(0.5 * x)
                c2 = math.cos(0.5 * x)
                q = rho * rho + (0.25 - a * a) / (4.0 * s2 * s2) + (0.25 - b * b) / (4.0 * c2 * c2)
                dg *= 1.0 + 0.5 * q * step * step
                break
        th[i] = x
        s2 = math.sin(0.5 * x)
        c2 = math.cos(0.5 * x)
        w[i] = const * s2 ** (2.0 * a + 1.0) * c2 ** (2.0 * b + 1.0) / (dg * dg)
    return th, w, maxused


@jit()
def _gatteschi_pittaluga(n, a, b, m):
    """First m angles (from x = 1) of P_n^{(a,b)}: Gatteschi & Pittaluga (1985)."""
    th = np.empty(m)
    r = 2.0 * n + a + b + 1.0
    for k in range(1, m + 1):
        K = (2.0 * k + a - 0.5) * math.pi / r
        th[k - 1] = K + ((0.25 - a * a) / math.tan(0.5 * K) - (0.25 - b * b) * math.tan(0.5 * K)) / (r * r)
    return th


@jit()
def _interior_constant(n, a, b):
    """:func:`_interior_weight_constant`, compiled (for :func:`_asymptotic_rule`)."""
    lg = (_log_gamma_ratio(n + a + 1.0, 0.5 * (b - a))
          + _log_gamma_ratio(n + b + 1.0, 0.5 * (a - b))
          + _log_gamma_ratio(n + a + b + 1.0, 0.5 * (1.0 - a - b))
          + _log_gamma_ratio(n + 1.0, 0.5 * (a + b + 1.0)))
    return math.pi * 2.0 ** (a + b + 1.0) * math.exp(lg)


@jit()
def _count_right(n, a, b):
    """:func:`_half_count`, compiled: the nodes at x >= 0, from the Gatteschi-Pittaluga
    angles around the leading-order crossing of pi/2."""
    k0 = int((0.5 * (2.0 * n + a + b + 1.0) - a + 0.5) / 2.0)
    lo = max(k0 - 3, 0)
    hi = min(k0 + 3, n)
    th = _gatteschi_pittaluga(n, a, b, hi)
    count = lo
    for k in range(lo, hi):
        if th[k] <= 0.5 * math.pi:
            count += 1
    return count


@jit()
def _asymptotic_half(n, a, b, m, const, scale):
    """Rung 3 for one half, compiled: the m angles nearest x = 1 and their weights, the
    _N_BOUNDARY_SMALL nearest the end by Newton on the recurrence (n <= N_RECURRENCE_MAX)
    or the N_BOUNDARY nearest on the dd series, and whether that converged (dd: sufficed)
    for all of them."""
    th0 = _gatteschi_pittaluga(n, a, b, m)
    nb = min(_N_BOUNDARY_SMALL if n <= N_RECURRENCE_MAX else N_BOUNDARY, m)
    th = np.empty(m)
    w = np.empty(m)
    ok = True
    if nb and n <= N_RECURRENCE_MAX:
        # Newton on the recurrence (Reinsch's form, plain-double coefficients: a bias
        # <= n 7e-17 in the weights): 4 times cheaper than the dd series at these n, and
        # within 1e-14 of it (weights) and 1.3e-15 (angles, relative) for exponents in
        # (-1, 5], n = 21..100
        tb, dq, conv = _newton_recurrence_kernel(n, a, b, th0[:nb].copy(), _NO_COEFFICIENTS,
                                                 _NO_COEFFICIENTS)
        for i in range(nb):
            ok = ok and conv[i]
            th[i] = tb[i]
            w[i] = (scale / dq[i]) ** 2
    elif nb:
        tb, wb, okb = _dd_boundary(n, a, b, th0[:nb].copy(), scale)
        for i in range(nb):
            ok = ok and okb[i]
            th[i] = tb[i]
            w[i] = wb[i]
    if m > nb:
        ti, wi, _ = _newton_interior(n, a, b, th0[nb:].copy(), const)
        th[nb:] = ti
        w[nb:] = wi
    return th, w, ok


@jit()
def _asymptotic_rule(n, a, b):
    """Rung 3 whole in one compiled call, for exponents <= _ASY_MAX_PARAM: (x, w, ok), ok
    False where a boundary node did not converge (the caller then takes the general path).
    One call instead of ~40 small numpy and Python steps.  For 20 < n <= N_RECURRENCE_MAX
    it is the fallback of the small-n rule (_recurrence_rule): Hahn's expansion agrees with
    the recurrence to 1e-14 in the weights from n = 21 on (exponents in (-1, 5])."""
    m_right = _count_right(n, a, b)
    th_r, w_r, ok_r = _asymptotic_half(n, a, b, m_right, _interior_constant(n, a, b),
                                       _end_scale(n, a, b))
    n_left = n - m_right
    th_l, w_l, ok_l = _asymptotic_half(n, b, a, n_left, _interior_constant(n, b, a),
                                       _end_scale(n, b, a))
    x = np.empty(n)
    w = np.empty(n)
    for i in range(n_left):
        x[i] = -math.cos(th_l[i])
        w[i] = w_l[i]
    for i in range(m_right):
        x[n - 1 - i] = math.cos(th_r[i])
        w[n - 1 - i] = w_r[i]
    x[0] = max(x[0], -_X_INSIDE)
    x[n - 1] = min(x[n - 1], _X_INSIDE)
    return x, w, ok_r and ok_l


# --------------------------------------------------------------------------
# The small-n rule: every node by Halley's method on the Reinsch-form recurrence
# (n <= N_RECURRENCE_MAX, exponents <= _ASY_MAX_PARAM)
#
# O(n^2) work, but ~10 flops of it per node and step of the recurrence, vectorised across
# the nodes, and most nodes need one pass: ~10 us at n = 100, where rung 3 (Hahn's
# expansion, ~0.3 us per node at these n) takes ~60 us, and ~5 us at n = 20, where
# Golub-Welsch and the dd series (_small_rule) take ~40 us.
# --------------------------------------------------------------------------
_RULE_PASSES = 8        # passes over the nodes still iterating; beyond: the next rung
_RULE_STOP = 1e-5       # a Halley step s with |s| (n + 1/sin theta) below this is the last one


@jit()
def _rule_coefficients(n, a, b, Bt, Ct):
    """Bt_k, Ct_k (k = 1..n-1) of the Reinsch form (block comment above
    _dd_recurrence_coefficients) into Bt, Ct, and E_1 / t into Bt[0].

    Ct_k = 1 - delta_k with delta_k = [2(2a+1) k (k+a+b+1) + (a+b)(a+1)(a+b+1)]
    / [(k+a+b+1)(2k+a+b)(k+a+1)] (where |delta_k| < 1/2): Ct_k is then rounded
    once, plus |delta_k| times the few rounding errors of delta_k.  Formed as a
    product of five rounded factors, Ct_k is biased (mean -5e-17 relative at
    a, b = -0.99, 0.99, n = 100) and the bias adds up over k: the weight next to
    x = 1 came out 1.2e-14 off there (2e-16 this way).  Bt_k enters only as Bt_k t Q_k,
    small where accuracy matters (next to the end), and is formed directly.  Everything
    from a+1 and b+1, as in _newton_recurrence_kernel."""
    ap1 = a + 1.0
    abp2 = ap1 + (b + 1.0)
    f1 = 2.0 * (2.0 * ap1 - 1.0)                    # 2 (2a + 1)
    f0 = (abp2 - 2.0) * ap1 * (abp2 - 1.0)          # (a + b)(a + 1)(a + b + 1)
    for k in range(1, n):
        d1 = (k - 1) + abp2                         # k + a + b + 1
        s = 2.0 * (k - 1) + abp2                    # 2k + a + b
        d3 = k + ap1                                # k + a + 1
        Bt[k] = (s + 1.0) * (s + 2.0) / (2.0 * d1 * d3)
        den = d1 * s * d3
        delta = (f1 * k * d1 + f0) / den
        if abs(delta) < 0.5:
            Ct[k] = 1.0 - delta
        else:
            Ct[k] = k * ((k - 1) + (b + 1.0)) * (s + 2.0) / den
    Bt[0] = -abp2 / (2.0 * ap1)


@jit()
def _rule_starts(n, a, b, m, t):
    """t = 2 sin^2(theta/2) of the first m Gatteschi-Pittaluga angles (from the end with
    exponent a) into t: theta = K + [(1/4-a^2) cot(K/2) - (1/4-b^2) tan(K/2)] / r^2,
    K = (2k + a - 1/2) pi / r, r = 2n + a + b + 1 (see _gatteschi_pittaluga).  e^{iK/2}
    by rotation, the correction by its Taylor series: no transcendental call, one division
    per node.  Only starts: rounding errors (~k eps) do not matter, the state of the
    iteration is t itself."""
    r = 2.0 * n + a + b + 1.0
    step = math.pi / r
    phi = (a + 1.5) * 0.5 * step                    # K_1 / 2
    c = math.cos(phi)
    s = math.sin(phi)
    cr = math.cos(step)
    sr = math.sin(step)
    fa = 0.5 * (0.25 - a * a) / (r * r)
    fb = 0.5 * (0.25 - b * b) / (r * r)
    for k in range(m):
        if k:
            c, s = c * cr - s * sr, s * cr + c * sr
        h = (fa * c * c - fb * s * s) / (s * c)     # half the correction
        h2 = h * h
        sin_h = h * (1.0 - h2 * (1.0 / 6.0) * (1.0 - h2 * (1.0 / 20.0)))
        cos_h = 1.0 - 0.5 * h2 * (1.0 - h2 * (1.0 / 12.0) * (1.0 - h2 * (1.0 / 30.0)))
        sh = s * cos_h + c * sin_h                  # sin(theta / 2)
        t[k] = 2.0 * sh * sh if sh > 0.0 else 2.0 * s * s


@jit()
def _rule_pass(n, Br, Cr, tr, er, qr, nr, Bl, Cl, tl, el, ql, nl):
    """(Q_n, E_n) of the Reinsch form at the nr angles tr (coefficients Br, Cr) and the nl
    angles tl (Bl, Cl) into (qr, er) and (ql, el).  Two steps of k per sweep over the
    angles (half the loads and stores), both halves in one loop over k: with few angles
    left the chains of the two halves overlap."""
    for j in range(nr):
        er[j] = Br[0] * tr[j]
        qr[j] = 1.0 + er[j]
    for j in range(nl):
        el[j] = Bl[0] * tl[j]
        ql[j] = 1.0 + el[j]
    k = 1
    while k + 1 < n:
        b1 = Br[k]
        c1 = Cr[k]
        b2 = Br[k + 1]
        c2 = Cr[k + 1]
        for j in range(nr):
            tj = tr[j]
            ej = c1 * er[j] - b1 * tj * qr[j]
            qj = qr[j] + ej
            ej = c2 * ej - b2 * tj * qj
            er[j] = ej
            qr[j] = qj + ej
        b1 = Bl[k]
        c1 = Cl[k]
        b2 = Bl[k + 1]
        c2 = Cl[k + 1]
        for j in range(nl):
            tj = tl[j]
            ej = c1 * el[j] - b1 * tj * ql[j]
            qj = ql[j] + ej
            ej = c2 * ej - b2 * tj * qj
            el[j] = ej
            ql[j] = qj + ej
        k += 2
    if k < n:
        for j in range(nr):
            ej = Cr[k] * er[j] - Br[k] * tr[j] * qr[j]
            er[j] = ej
            qr[j] += ej
        for j in range(nl):
            ej = Cl[k] * el[j] - Bl[k] * tl[j] * ql[j]
            el[j] = ej
            ql[j] += ej


@jit()
def _rule_gather(T, done, lo, hi, act, tt):
    """The nodes lo..hi-1 still iterating: their indices into act, their t into tt; count."""
    na = 0
    for i in range(lo, hi):
        if not done[i]:
            act[na] = i
            tt[na] = T[i]
            na += 1
    return na


@jit()
def _rule_update(n, a, b, act, tt, e, q, na, T, done, x, w, scale, first, sign):
    """One Halley step in theta for each of the na nodes of one half (exponent a at its
    end; see _recurrence_rule), from (Q_n, E_n) = (q, e) at t = tt.  A last step writes the
    node and its weight: node k of the half (k = act[j] - first) to x[i], w[i] with
    i = n - 1 - k (sign -1, nodes from x = 1) or i = k (sign +1, from x = -1)."""
    c2 = 2.0 * n + a + b
    lam = n * (n + a + b + 1.0)
    apb1 = a + b + 1.0
    kd = 2.0 * n * (n + b) / c2
    for j in range(na):
        i = act[j]
        tj = tt[j]
        sn = math.sqrt(tj * (2.0 - tj))             # sin theta
        r_sn = 1.0 / sn                             # 1/theta within pi/2 (theta <~ pi/2)
        cs = 1.0 - tj                               # cos theta
        qn = q[j]
        d1 = (kd * e[j] - n * tj * qn) * r_sn       # first derivative of Q_n in theta
        p = ((a - b) + apb1 * cs) * r_sn
        d2 = -p * d1 - lam * qn                     # second
        s = qn * d1 / (d1 * d1 - 0.5 * qn * d2)     # Halley's step in theta
        if abs(s) * (n + r_sn) < _RULE_STOP:
            s2 = s * s
            t_new = tj - sn * s * (1.0 - s2 * (1.0 / 6.0)) + cs * 0.5 * s2
            d3 = (apb1 + p * cs * r_sn) * d1 - p * d2 - lam * d1        # third
            dr = d1 - s * d2 + 0.5 * s2 * d3        # the first at the root
            k = i - first
            out = n - 1 - k if sign < 0 else k
            x[out] = sign * (t_new - 1.0)
            w[out] = (scale / dr) ** 2
            done[i] = True
        elif abs(s) < 0.25 * sn:
            T[i] = tj * math.cos(s) + 2.0 * math.sin(0.5 * s) ** 2 - sn * math.sin(s)
        else:
            # a start far right of the first root (an exponent near -1): Newton in t, where
            # Q_n is nearly linear; past the end, the chord through Q(0) = 1 and Q(t) < 0
            t_new = tj - qn * sn / d1
            if not t_new > 0.0:
                t_new = tj / (1.0 - qn) if qn < 0.0 else 0.5 * tj
            T[i] = t_new


@jit()
def _recurrence_rule(n, a, b):
    """Gauss-Jacobi rule by Halley's method on the recurrence for every node: (x, w, ok).

    Nodes at x >= 0 are found from x = 1 with (a, b), the others from x = -1 with (b, a),
    as on the other rungs, each in t = 1 - |x| = 2 sin^2(theta/2) (relative precision next
    to the end).  Each pass runs the recurrence of the block comment above
    _dd_recurrence_coefficients in plain double for all the nodes still iterating
    (_rule_pass) and takes one Halley step in theta (_rule_update), with
        Q_n' = dQ_n/dtheta = [2n(n+b)/(2n+a+b) E_n - n t Q_n] / sin theta
    (DLMF 18.9.17 with Q_{n-1} = Q_n - E_n: the O(1) partial sums Q_k enter only times t,
    so they need no compensation, unlike in _newton_recurrence_kernel, which uses Q_{n-1}),
        Q_n'' = -p Q_n' - lambda Q_n,  Q_n''' = -p' Q_n' - p Q_n'' - lambda Q_n',
    p = [(a-b) + (a+b+1) cos theta] / sin theta, p' = -(a+b+1) - p cot theta,
    lambda = n(n+a+b+1) (Szego's equation in theta).  A step s with |s|(n + 1/sin theta) <
    _RULE_STOP is the last: the node is then within ~(that)^3 / n of the root (Halley is
    cubic), t moves by the Taylor series of 1 - cos, and Q_n' moves to the root by its
    Taylor series to second order (error ~(that)^3 / 6 relative), which gives the weight
    w = (_end_scale / Q_n')^2 with no further pass.  Most nodes stop after one pass; those
    next to an end, where the starts are poorer, after two to five.  A step larger than a
    quarter of sin theta (a start far to the right of the first root: an exponent near -1) is
    replaced by Newton's step in t, where Q_n is nearly linear next to the end.

    ok is False when some node did not stop within _RULE_PASSES passes or the nodes do not
    come out ascending and apart (two starts drawn to one root); the caller then takes the
    rung it would take without this one.
    Measured against mpmath for n = 2..100 and exponents in (-1, 5] (down to -1 + 1e-12):
    nodes within 2.2e-16, weights 7.1e-15 (relative), sum of the weights within 3.4e-15 of
    mu_0; rung 3 at n = 21..100: weights 1.2e-14, sum 9.7e-15 (its boundary nodes'
    coefficients are formed factor by factor, see _rule_coefficients); the Golub-Welsch
    rule at n <= 20: 2.1e-15 and 1.6e-15."""
    # nodes at x >= 0: the Gatteschi-Pittaluga angles from x = 1 up to pi/2, counted as in
    # _count_right (t <= 1 is theta <= pi/2; a few starts beyond are computed and dropped)
    k0 = int((0.5 * (2.0 * n + a + b + 1.0) - a + 0.5) / 2.0)
    lo = max(k0 - 3, 0)
    hi = min(k0 + 3, n)
    T = np.empty(n)                 # the state: t of every node, right half first
    _rule_starts(n, a, b, hi, T)
    m = lo
    for k in range(lo, hi):
        if T[k] <= 1.0:
            m += 1
    _rule_starts(n, b, a, n - m, T[m:])
    work = np.empty(10 * n)
    Br, Cr, Bl, Cl = work[:n], work[n:2 * n], work[2 * n:3 * n], work[3 * n:4 * n]
    tr, er, qr = work[4 * n:5 * n], work[5 * n:6 * n], work[6 * n:7 * n]
    tl, el, ql = work[7 * n:8 * n], work[8 * n:9 * n], work[9 * n:]
    _rule_coefficients(n, a, b, Br, Cr)
    _rule_coefficients(n, b, a, Bl, Cl)
    scale_r = _end_scale(n, a, b)
    scale_l = _end_scale(n, b, a)
    x = np.empty(n)
    w = np.empty(n)
    done = np.zeros(n, dtype=np.bool_)
    act_r = np.empty(n, dtype=np.int64)
    act_l = np.empty(n, dtype=np.int64)
    for _ in range(_RULE_PASSES):
        nr = _rule_gather(T, done, 0, m, act_r, tr)
        nl = _rule_gather(T, done, m, n, act_l, tl)
        if nr + nl == 0:
            break
        _rule_pass(n, Br, Cr, tr, er, qr, nr, Bl, Cl, tl, el, ql, nl)
        _rule_update(n, a, b, act_r, tr, er, qr, nr, T, done, x, w, scale_r, 0, -1.0)
        _rule_update(n, b, a, act_l, tl, el, ql, nl, T, done, x, w, scale_l, m, 1.0)
    for i in range(n):
        if not done[i]:
            return x, w, False
    x[0] = max(x[0], -_X_INSIDE)
    x[n - 1] = min(x[n - 1], _X_INSIDE)
    # n converged roots, strictly ascending, are all the roots; a gap below 0.1 / n^2 is
    # one root reached from two starts (both halves can converge to the middle root and
    # land an ulp apart).  The true gaps are >= 2 / n^2 for exponents in (-1, 5] and
    # n = 2..100 (measured; the smallest are next to the ends, ~(j_2^2 - j_1^2) / (2 n^2)
    # with j the Bessel zeros of the exponent there).
    gap = 0.1 / (n * n)
    for i in range(n - 1):
        if not x[i + 1] - x[i] > gap:
            return x, w, False
    return x, w, True


# --------------------------------------------------------------------------
# Python layer: validation, dispatch, assembly
# --------------------------------------------------------------------------
def _half_count(n: int, a: float, b: float) -> int:
    """How many nodes lie at x >= 0 (theta <= pi/2), from the Gatteschi-Pittaluga estimates."""
    # leading order theta_k = (2k + a - 1/2) pi / (2n+a+b+1); refine around the crossing
    k0 = int((0.5 * (2.0 * n + a + b + 1.0) - a + 0.5) / 2.0)
    lo = max(k0 - 3, 0)
    hi = min(k0 + 3, n)
    th = _gatteschi_pittaluga(n, a, b, hi)
    return lo + int(np.count_nonzero(th[lo:] <= 0.5 * math.pi))


@jit()
def _split_exponent(c):
    """c = m + f with m = max(0, round(c)) (ties to even, as Python's round) and f in
    (-1, 1/2]."""
    r = math.floor(c)
    frac = c - r
    if frac > 0.5 or (frac == 0.5 and r % 2.0 != 0.0):
        r += 1.0
    m = max(0, int(r))
    return m, c - m          # exact: m <= 2c for m >= 1 (Sterbenz)


@jit()
def _scaled(h, l, e):
    """(h + l) 2^e with h renormalised to [0.5, 1) once it leaves [2^-500, 2^500)."""
    if 2.0 ** -500 <= abs(h) < 2.0 ** 500:
        return h, l, e
    hm, k = math.frexp(h)
    return hm, math.ldexp(l, -k), e + k


@jit()
def _shifted_ratio(z, c, d, with_d):
    """Gamma(z+c)/Gamma(z) / (Gamma(z+d+c)/Gamma(z+d)) for z >= 1 and c, d > -1
    (Gamma(z+c)/Gamma(z) when not ``with_d``), as (v, e) with value v 2^e: no
    under/overflow.

    The integer part of c is a product (in double-double), only the rest goes through
    the log-gamma ratio: exp(L) loses |L| ulps of L, and L ~ c ln z is ~140 for c = 20,
    n = 1000 (measured: through the log-gamma ratio alone C_n / P_n(1)^2 is 3e-14 off there,
    and so is every rung-2 weight)."""
    m, f = _split_exponent(c)
    ph, pl, pe = 1.0, 0.0, 0
    for j in range(m):
        nh, nl = two_sum(z + j, f)                                    # z + f + j
        if not with_d:
            ph, pl = dd_mul(ph, pl, nh, nl)
        else:
            sh, sl = two_sum(z + j, d)
            dh, dl = dd_add(sh, sl, f, 0.0)                           # z + d + f + j
            qh, ql = dd_div(nh, nl, dh, dl)
            ph, pl = dd_mul(ph, pl, qh, ql)
        ph, pl, pe = _scaled(ph, pl, pe)
    rest = _log_gamma_ratio(z, f)
    if with_d:
        rest -= _log_gamma_ratio(z + d, f)
    return (ph + pl) * math.exp(rest), pe


@jit()
def _end_scale(n, a, b):
    """sqrt(C_n) / P_n(1), C_n = 2^{a+b+1} Gamma(n+a+1) Gamma(n+b+1) / (Gamma(n+a+b+1) n!)
    (Szegő 15.3.5), so that w = (_end_scale / (dQ_n/dtheta))^2 with Q_n = P_n / P_n(1).

    = 2^{(a+b+1)/2} G sqrt(R) with G = 1/P_n(1) = Gamma(a+1) n! / Gamma(n+a+1) and
    R = Gamma(n+a+1) Gamma(n+b+1) / (Gamma(n+a+b+1) n!) = 1 + O(ab/n), both without
    exponentials of large logarithms (see _shifted_ratio; exp of a difference of
    log-gamma ratios leaves every rung-2 weight 3e-14 off at n = 1000, alpha = 20).
    Powers of two are carried apart until the end: G and R underflow long before the
    weights do (G ~ a! n^-a is ~1e-150 at n = 2e4, alpha = 50; R ~ 2^-2200 at n = 2,
    alpha = beta = 1100)."""
    m, f = _split_exponent(a)
    r, re = _shifted_ratio(n + 1.0, f, 0.0, False)
    gh, gl, ge = math.gamma(1.0 + f) / r, 0.0, -re                  # Gamma(f+1) n!/Gamma(n+f+1)
    for j in range(1, m + 1):                                         # * prod (f+j)/(n+f+j)
        nh, nl = two_sum(f, float(j))
        dh, dl = two_sum(f, float(n + j))
        qh, ql = dd_div(nh, nl, dh, dl)
        gh, gl = dd_mul(gh, gl, qh, ql)
        gh, gl, ge = _scaled(gh, gl, ge)
    lo, hi = (a, b) if a <= b else (b, a)
    r, re = _shifted_ratio(n + 1.0, lo, hi, True)
    if re % 2:
        r, re = 2.0 * r, re - 1
    e = 0.5 * (a + b + 1.0)
    ei = math.floor(e)          # 2^e by ldexp: exact
    return math.ldexp(2.0 ** (e - ei) * gh * math.sqrt(r), int(ei) + ge + re // 2)


def _weights_from_recurrence(scale, dq):
    """w = C_n / (dP_n/dtheta)^2 at the roots, from dQ_n/dtheta there (Q_n = P_n/P_n(1))
    and scale = _end_scale(n, a, b)."""
    with np.errstate(divide="ignore", over="ignore"):   # dq = 0: caught by _check_rung2
        return (scale / dq) ** 2


def _interior_weight_constant(n, a, b):
    """C_n / K^2 = pi 2^{a+b+1} Gamma(rho+1/2)^2 Gamma(rho+1)^2 / (Gamma(n+a+1) Gamma(n+b+1) Gamma(n+a+b+1) n!).

    (Legendre duplication of Gamma(2 rho + 1) removes the 2^{4 rho}.)
    """
    lg = (log_gamma_ratio(n + a + 1.0, 0.5 * (b - a))          # Gamma(rho+1/2)/Gamma(n+a+1)
          + log_gamma_ratio(n + b + 1.0, 0.5 * (a - b))        # Gamma(rho+1/2)/Gamma(n+b+1)
          + log_gamma_ratio(n + a + b + 1.0, 0.5 * (1.0 - a - b))  # Gamma(rho+1)/Gamma(n+a+b+1)
          + log_gamma_ratio(n + 1.0, 0.5 * (a + b + 1.0)))     # Gamma(rho+1)/n!
    return math.pi * 2.0 ** (a + b + 1.0) * math.exp(lg)


@jit()
def _dd_boundary(n, a, b, theta0, scale):
    """Nodes next to x = 1 by Newton on the dd hypergeometric series, with weights, and
    the mask of the nodes where dd sufficed (see _newton_boundary).

    w = C_n / (dP_n/dtheta)^2,  dP_n/dtheta = P_n(1) Q_n'(t) sin(theta).
    """
    th, dqt, cancel = _newton_boundary(n, a, b, theta0)
    w = np.empty(th.size)
    ok = np.empty(th.size, np.bool_)
    for i in range(th.size):
        w[i] = (scale / (dqt[i] * math.sin(th[i]))) ** 2     # dq = 0: inf, caught by the caller
        ok[i] = cancel[i] < _DD_CANCEL_MAX     # NaN cancellation counts as not enough
    return th, w, ok


def _boundary_nodes(n, a, b, theta0):
    """Boundary nodes with no recurrence values at hand (rung 3, or a rung-2 half that is
    all boundary): dd where it suffices, Newton on the recurrence elsewhere (large
    exponents; O(n) each, a few nodes at most).  Returns angles and weights."""
    scale = _end_scale(n, a, b)
    if a > _ASY_MAX_PARAM:      # rung 2 only: checked against the recurrence, see _polish_by_dd
        th, dq, conv = _newton_recurrence(n, a, b, theta0)
        return _polish_by_dd(n, a, b, th, _weights_from_recurrence(scale, dq), conv, scale)
    th, w, ok = _dd_boundary(n, a, b, theta0, scale)
    if not ok.all():
        bad = ~ok
        th[bad], dq, _ = _newton_recurrence(n, a, b, np.ascontiguousarray(theta0[bad]))
        w[bad] = _weights_from_recurrence(scale, dq)
    return th, w


def _polish_by_dd(n, a, b, th, w, conv, scale):
    """The N_BOUNDARY nodes nearest the end (angles th, weights w from the recurrence;
    conv: where it converged, elsewhere th is its start) redone by the dd series, in place.

    dd is kept where its cancellation allows and, with an exponent > 5 at this end, only
    where it lands within 1e-6 theta of a converged recurrence angle: there the dd Newton
    iteration can stop at a point of its own noise that is no root, while the recurrence
    is accurate (measured: n = 896, exponents 9.7 and 55.8, the ninth node from -1)."""
    nb = min(N_BOUNDARY, th.size)
    tb, wb, ok = _dd_boundary(n, a, b, th[:nb], scale)
    if a > _ASY_MAX_PARAM:
        ok &= ~conv[:nb] | (np.abs(tb - th[:nb]) <= 1e-6 * th[:nb])
    th[:nb][ok] = tb[ok]
    w[:nb][ok] = wb[ok]
    return th, w


def _half_small(n, a, b, theta0):
    """Rung 2 for one half: Newton on the recurrence from given starting angles,
    the N_BOUNDARY nodes nearest the end by the dd series (as on rung 3).  When every node
    of this half is a boundary node and the exponent at this end is <= 5, the recurrence
    pass is skipped: the Golub-Welsch angles are close enough for the dd Newton iteration."""
    if theta0.size <= N_BOUNDARY:
        return _boundary_nodes(n, a, b, np.array(theta0, dtype=float))
    scale = _end_scale(n, a, b)
    th, dq, conv = _newton_recurrence(n, a, b, theta0)
    return _polish_by_dd(n, a, b, th, _weights_from_recurrence(scale, dq), conv, scale)


def _half_asymptotic(n, a, b, m):
    """Rung 3 for one half: the m nodes nearest x = 1 of P_n^{(a,b)}, as angles."""
    th0 = _gatteschi_pittaluga(n, a, b, m)
    nb = min(N_BOUNDARY, m)
    th = np.empty(m)
    w = np.empty(m)
    if nb:
        th[:nb], w[:nb] = _boundary_nodes(n, a, b, th0[:nb])
    if m > nb:
        th[nb:], w[nb:], _ = _newton_interior(n, a, b, th0[nb:], _interior_weight_constant(n, a, b))
    return th, w


@jit()
def _jacobi_bands(n, a, b):
    """Diagonal and off-diagonal of the symmetric Jacobi matrix of P^{(a,b)} (Golub & Welsch
    1969): its eigenvalues are the roots of P_n."""
    diag = np.empty(n)
    off = np.empty(n - 1)
    diag[0] = (b - a) / (a + b + 2.0)
    for k in range(1, n):
        s = 2.0 * k + a + b
        diag[k] = (b * b - a * a) / (s * (s + 2.0))
    for k in range(1, n):                       # off-diagonal entries k = 1..n-1
        s1 = 2.0 * k + a + b
        # (k+a+b)/(2k+a+b-1) is 0/0 at k = 1, a+b = -1; its value there is exactly 1
        ratio = 1.0 if k == 1 else (k + a + b) / (s1 - 1.0)
        off[k - 1] = 2.0 / s1 * math.sqrt(k * (k + a) * (k + b) * ratio / (s1 + 1.0))
    return diag, off


def _golub_welsch_guess(n, a, b):
    """Eigenvalues of the Jacobi matrix (Golub & Welsch 1969), ascending."""
    diag, off = _jacobi_bands(n, a, b)
    # LAPACK dsterf (Pal-Walker-Kahan QL, eigenvalues only): 2x faster than numpy's dense
    # eigvalsh or scipy's eigh_tridiagonal at these sizes.  Lazy import: numba's first
    # call imports scipy.linalg anyway.
    from scipy.linalg.lapack import dsterf
    vals, info = dsterf(diag, off)
    if info != 0:  # pragma: no cover - LAPACK failure on a symmetric tridiagonal
        raise FloatingPointError(f"LAPACK dsterf failed (info = {info}) for n = {n}")
    return vals


def _log10_smallest_weight(n, c, d):
    """Estimate of log10 of the weight nearest the end with exponent c > 5 (d at the other).

    Mehler-Heine: P_n(cos theta) / P_n(1) ~ Gamma(c+1) (2/(rho theta))^c J_c(rho theta),
    rho = n + (c+d+1)/2, so the first node is theta_1 ~ j/rho, j = j_{c,1}, and
    w_1 = C_n / (dP_n/dtheta)^2 ~ C_n j^{2c} / (P_n(1)^2 Gamma(c+1)^2 4^c rho^2 J_c'(j)^2),
    with j ~ c + 1.8557571 c^{1/3} + 1.033150 c^{-1/3}, |J_c'(j)| ~ 1.113102 c^{-2/3}
    (DLMF 10.21.40, 10.21.41).  Measured: within 0.3 of the computed value for c in [6, 60],
    n in [60, 2e4]; too large (never too small) once c is comparable to n."""
    lg = math.lgamma
    log_c = ((c + d + 1.0) * math.log(2.0) + lg(n + c + 1.0) + lg(n + d + 1.0)
             - lg(n + c + d + 1.0) - lg(n + 1.0))
    log_end = lg(n + c + 1.0) - lg(c + 1.0) - lg(n + 1.0)                  # log P_n(1)
    j = c + 1.8557571 * c ** (1.0 / 3.0) + 1.033150 * c ** (-1.0 / 3.0)
    djc = 1.113102 * c ** (-2.0 / 3.0)
    rho = n + 0.5 * (c + d + 1.0)
    return (log_c - 2.0 * log_end + 2.0 * c * math.log(0.5 * j) - 2.0 * lg(c + 1.0)
            - 2.0 * math.log(rho * djc)) / math.log(10.0)


def _check_large_exponents(n, a, b):
    """Refuse, before any O(n^2) work, what rung 2 cannot deliver (max(a, b) > 5 only):

    * n > _N_LARGE_EXPONENT_MAX: the time (Golub-Welsch, LAPACK dsterf, ~1.1e-8 n^2 s on the
      2-core CI machine, plus Newton on the recurrence, ~1.2e-9 n^2 s) -- InvalidOrderError.
      Accuracy does not limit n any more (nodes 2e-16, weights 2.4e-14 at n = 1e4,
      alpha = -1 + 1e-6, beta = 20; see _newton_recurrence).
    * weights outside the double range (the ones next to an end with a large exponent
      underflow, see _log10_smallest_weight; or mu_0 / n overflows): FloatingPointError.
      The estimate only refuses clear cases (measured: it is never more than 0.37 too
      small); _check_rung2 catches the rest afterwards.
    Cost: ~3 us (a few lgamma calls), against ~0.15 ms for the smallest rung-2 call."""
    m = max(a, b)
    if n > _N_LARGE_EXPONENT_MAX:
        secs = _SECONDS_PER_N2 * n * n
        took = f"~{secs / 60:.0f} min" if secs >= 90 else f"~{secs:.0f} s"
        raise InvalidOrderError(
            f"gauss_jacobi(n={n}, alpha={a!r}, beta={b!r}): n must be <= "
            f"{_N_LARGE_EXPONENT_MAX} when max(alpha, beta) > {_ASY_MAX_PARAM:g} (any n when both "
            f"exponents are <= {_ASY_MAX_PARAM:g}). Exponents this large (here {m:g}) use the "
            f"O(n^2) rung (Golub-Welsch + Newton on the three-term recurrence), which would take "
            f"{took} at n = {n} (~{_SECONDS_PER_N2:.1e} n^2 s measured); refused before starting. "
            f"Accuracy is not the limit: the rung keeps nodes within ~2e-16 and weights within "
            f"~3e-14 (relative) of mpmath references (measured up to n = 10000), so nothing "
            f"would be lost but time")
    log_big = ((a + b + 1.0) * math.log(2.0) + math.lgamma(a + 1.0) + math.lgamma(b + 1.0)
               - math.lgamma(a + b + 2.0)) / math.log(10.0) - math.log10(n)     # mu_0 / n
    if log_big > _LOG10_HUGE:
        raise FloatingPointError(
            f"gauss_jacobi(n={n}, alpha={a!r}, beta={b!r}): the weights sum to mu_0 = "
            f"2^(alpha+beta+1) B(alpha+1, beta+1), so the largest is at least mu_0 / n ~ "
            f"1e{log_big:.0f}, beyond the largest double; refused before starting. Allowed: "
            f"mu_0 / n < 1.8e308, i.e. smaller exponents")
    log_min, c = min((_log10_smallest_weight(n, c, d), c) for c, d in ((a, b), (b, a))
                     if c > _ASY_MAX_PARAM)
    if log_min < _LOG10_TINY - 1.0:
        raise FloatingPointError(
            f"gauss_jacobi(n={n}, alpha={a!r}, beta={b!r}): the weights next to the end with "
            f"exponent {c:g} would be ~1e{log_min:.0f}, below the smallest normal double "
            f"({_TINY:.1e}); refused before starting. Allowed: every weight within the double "
            f"range, i.e. a smaller n or a smaller exponent (the smallest weight is roughly "
            f"(m / n)^(2m) for the exponent m at that end)")


def _check_rung2(n, a, b, x, w):
    """Large exponents, after the fact: the weights must be positive normal doubles (next to
    an end with a large exponent they can underflow; _check_large_exponents refuses the clear
    cases before any work) and the nodes strictly ascending (each Newton iteration found its
    own root).  FloatingPointError otherwise, rather than a rule that is silently wrong."""
    if not (np.isfinite(w).all() and w.min() >= _TINY):
        bad = w[~(np.isfinite(w) & (w >= _TINY))]
        raise FloatingPointError(
            f"gauss_jacobi(n={n}, alpha={a!r}, beta={b!r}): {bad.size} weight(s) outside the "
            f"range of normal doubles (e.g. {float(bad[0])!r}; smallest normal {_TINY:.1e}): the "
            f"weights next to an end with a large exponent m are roughly (m / n)^(2 m). "
            f"Allowed: every weight within the double range, i.e. a smaller n or smaller exponents")
    if not (np.diff(x) > 0.0).all():
        i = int(np.argmin(np.diff(x)))
        raise FloatingPointError(
            f"gauss_jacobi(n={n}, alpha={a!r}, beta={b!r}): Newton on the recurrence did not "
            f"separate the nodes (x[{i}] = {x[i]!r} >= x[{i + 1}] = {x[i + 1]!r}); please report")


@jit()
def _positive_angles(th0):
    """Starting angles (ascending) with no zeros.  An eigenvalue of the Jacobi matrix can
    land on or beyond x = +-1 (absolute error ~ n eps, while an exponent near -1 puts the
    first node ~1e-15 from the end); its angle is then 0, where Newton divides by
    sin(theta) = 0.  Such starts are spread over (0, first positive angle): distinct, and
    to the right of nothing but the roots they stand for."""
    th = th0.copy()
    m = th.size
    k = 0
    while k < m and th[k] <= 0.0:               # ascending: zeros come first
        k += 1
    if k:
        top = th[k] if k < m else 1.0 / (m * m)
        for i in range(k):
            th[i] = top * (i + 1) / (k + 1)
    return th


@jit()
def _angles_from_end(x_sorted):
    """Starting angles from the nearer end of nodes ``x_sorted`` (ascending, all on one side:
    x >= 0 measured from 1, else from -1 after reflection), no zeros (:func:`_positive_angles`)."""
    th = np.empty(x_sorted.size)
    for i in range(x_sorted.size):
        th[i] = math.acos(min(max(x_sorted[i], -1.0), 1.0))
    return _positive_angles(th)


@jit()
def _small_rule(n, a, b):
    """For n <= 2 N_BOUNDARY and exponents <= 5 where the small-n rule (_recurrence_rule)
    could not finish a node, compiled whole: Golub-Welsch
    starting angles (a dense symmetric eigenvalue problem: at these sizes LAPACK called
    from the kernel beats the Python round trip to dsterf), then every node by the dd
    series of its end (:func:`_dd_boundary`).  Returns (x, w, ok); ``ok`` False when a half
    has more than N_BOUNDARY nodes or the series cancelled past dd somewhere, and the
    caller takes the general path.  One kernel call instead of ~20 small numpy and Python
    steps: a new pair of exponents at n = 5 costs ~10 us instead of ~70 us."""
    diag, off = _jacobi_bands(n, a, b)
    J = np.diag(diag)
    for k in range(n - 1):
        J[k + 1, k] = off[k]
        J[k, k + 1] = off[k]
    guess = np.linalg.eigvalsh(J)               # ascending
    n_left = 0
    while n_left < n and guess[n_left] < 0.0:
        n_left += 1
    n_right = n - n_left
    x = np.empty(n)
    w = np.empty(n)
    if n_left > N_BOUNDARY or n_right > N_BOUNDARY:
        return x, w, False
    th_r, w_r, ok_r = _dd_boundary(n, a, b, _angles_from_end(guess[n_left:][::-1].copy()),
                                   _end_scale(n, a, b))
    for i in range(n_right):
        if not ok_r[i]:
            return x, w, False
        x[n - 1 - i] = math.cos(th_r[i])
        w[n - 1 - i] = w_r[i]
    if n_left:
        th_l, w_l, ok_l = _dd_boundary(n, b, a, _angles_from_end(-guess[:n_left]),
                                       _end_scale(n, b, a))
        for i in range(n_left):
            if not ok_l[i]:
                return x, w, False
            x[i] = -math.cos(th_l[i])
            w[i] = w_l[i]
    x[0] = max(x[0], -_X_INSIDE)
    x[n - 1] = min(x[n - 1], _X_INSIDE)
    return x, w, True


def gauss_jacobi(n, alpha, beta):
    """Gauss-Jacobi nodes and weights.

    Parameters
    ----------
    n : int
        Number of nodes, n >= 1.
    alpha, beta : float
        Exponents of the weight (1 - x)^alpha (1 + x)^beta, both > -1.

    Returns
    -------
    x : ndarray, shape (n,)
        Nodes, the roots of P_n^{(alpha, beta)}, ascending.
    w : ndarray, shape (n,)
        Weights: sum(w * g(x)) = int_{-1}^{1} (1-x)^alpha (1+x)^beta g(x) dx for
        every polynomial g of degree <= 2n - 1.

    Raises
    ------
    InvalidOrderError
        n not an integer >= 1, or n > 20000 with max(alpha, beta) > 5.
    InvalidExponentError
        alpha or beta not finite or <= -1.
    FloatingPointError
        Weights that would leave the range of normal doubles (large exponents).

    Notes
    -----
    O(n) for n > 100 (Hale & Townsend 2013 interior asymptotics, boundary
    nodes by Newton on the recurrence in 1 - x); up to n = 100, Halley's method on
    the recurrence for every node (O(n^2), vectorised: ~10 us at n = 100); see the
    module docstring for the dispatch ladder.  Accuracy: nodes ~1e-16 absolute, weights ~1e-14
    relative (tests/sie/test_gauss_jacobi.py checks against mpmath), also for exponents
    within 1e-12 of -1.  A node closer to an end than the spacing of doubles there is
    returned one ulp inside (-1, 1).

    Large exponents (max(alpha, beta) > 5) take rung 2 for every n, at O(n^2) cost
    (~1 s at n = 1e4), with the same accuracy (measured: nodes 2.5e-16, weights 2.4e-14
    up to n = 1e4 and exponents up to 430).  Refused before any work:
    n > 20000 with max(alpha, beta) > 5 (InvalidOrderError, a ValueError: it would take
    minutes), and weights that would leave the range of normal doubles (FloatingPointError;
    the weights next to an end with a large exponent m are roughly (m/n)^(2m)).  What the
    a-priori estimate lets through is checked afterwards (FloatingPointError).

    References
    ----------
    N. Hale and A. Townsend, "Fast and accurate computation of Gauss-Legendre and
    Gauss-Jacobi quadrature nodes and weights", SIAM J. Sci. Comput. 35 (2013) A652-A674.
    G. H. Golub and J. H. Welsch, Math. Comp. 23 (1969) 221-230.
    NIST DLMF, sec. 3.5(v) (Gauss quadrature) and 18.9 (the three-term recurrence).

    Examples
    --------
    Gauss-Legendre with two nodes: x = -+1/sqrt(3), w = 1, 1; Gauss-Chebyshev
    (alpha = beta = -1/2): x_k = cos((2k - 1) pi / (2n)), w_k = pi / n.

    >>> import numpy as np, sie
    >>> x, w = sie.gauss_jacobi(2, 0.0, 0.0)
    >>> np.round(x * np.sqrt(3.0), 12).tolist(), np.round(w, 12).tolist()
    ([-1.0, 1.0], [1.0, 1.0])
    >>> x, w = sie.gauss_jacobi(5, -0.5, -0.5)
    >>> k = np.arange(5, 0, -1)
    >>> bool(np.allclose(x, np.cos((2 * k - 1) * np.pi / 10), rtol=0, atol=1e-15))
    True
    >>> bool(np.allclose(w, np.pi / 5, rtol=1e-14, atol=0))
    True
    """
    n = check_order(n, 1)
    a = check_exponent("alpha", alpha)
    b = check_exponent("beta", beta)
    if max(a, b) > _ASY_MAX_PARAM:
        _check_large_exponents(n, a, b)
    if n == 1:
        x1 = (b - a) / ((a + 1.0) + (b + 1.0))       # a + b + 2 without cancellation
        return np.clip([x1], -_X_INSIDE, _X_INSIDE), np.array([jacobi_moment(a, b)])

    if max(a, b) <= _ASY_MAX_PARAM:
        if n <= N_RECURRENCE_MAX:
            x, w, ok = _recurrence_rule(n, a, b)
            if ok:
                return x, w
        x, w, ok = (_small_rule if n <= 2 * N_BOUNDARY else _asymptotic_rule)(n, a, b)
        if ok:
            return x, w
    if n <= N_RECURRENCE_MAX or max(a, b) > _ASY_MAX_PARAM:
        guess = _golub_welsch_guess(n, a, b)
        right = guess >= 0.0
        th_r0 = _angles_from_end(guess[right][::-1].copy())       # from x = 1
        th_l0 = _angles_from_end(-guess[~right])                   # from x = -1
        th_r, w_r = _half_small(n, a, b, th_r0)
        th_l, w_l = _half_small(n, b, a, th_l0) if th_l0.size else (th_l0, th_l0)
    else:
        m_right = _half_count(n, a, b)
        th_r, w_r = _half_asymptotic(n, a, b, m_right)
        th_l, w_l = _half_asymptotic(n, b, a, n - m_right)

    x = np.concatenate([-np.cos(th_l), np.cos(th_r[::-1])])
    w = np.concatenate([w_l, w_r[::-1]])
    # a node closer to an end than half the spacing of doubles there (an exponent within
    # ~1e-12 of -1) would round onto +-1, where the weight function is infinite: keep it
    # one ulp inside (an absolute error below 1.2e-16; the weight, from theta, is unaffected)
    x[0] = max(x[0], -_X_INSIDE)      # nodes ascend: only the outermost can round onto an end
    x[-1] = min(x[-1], _X_INSIDE)
    if max(a, b) > _ASY_MAX_PARAM:
        _check_rung2(n, a, b, x, w)
    return x, w


@functools.lru_cache(maxsize=256)
def gauss_jacobi_cached(q, a, b):
    """gauss_jacobi(q, a, b), memoised (read-only arrays): the contact layer solves
    the same-exponent equation many times while it searches for free contact ends."""
    x, w = gauss_jacobi(q, a, b)
    x.flags.writeable = False
    w.flags.writeable = False
    return x, w
