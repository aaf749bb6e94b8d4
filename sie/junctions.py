"""Coefficients that jump at a junction: touching intervals with different (a, b).

    a_i psi(s) + (b_i/pi) PV int_L psi(t)/(t - s) dt = f(s),   s in L_i,

on L = L_1 U ... U L_J, L_i = [c_i, d_i] with d_i = c_{i+1} (the intervals touch), the
Cauchy integral over the whole of L.  At a junction e = d_i = c_{i+1} the coefficients jump
and psi has a power singularity of its own (Muskhelishvili 1953, the Riemann-Hilbert problem
with discontinuous coefficients): psi ~ A_1 (e - t)^gamma for t < e
and A_2 (t - e)^gamma for t > e, one exponent on both sides.  With the standard integrals

    (1/pi) PV int_0^inf u^g/(u - x) du = -cot(pi g) x^g,
    (1/pi) int_0^inf u^g/(u + x) du = -x^g / sin(pi g)        (0 < x, -1 < g < 0,
                                                                continued analytically)

the leading terms of the equation on the two sides are

    x > e:  A_2 (a_2 - b_2 cot(pi gamma)) + A_1 b_2 / sin(pi gamma) = 0,
    x < e:  A_1 (a_1 + b_1 cot(pi gamma)) - A_2 b_1 / sin(pi gamma) = 0,

a homogeneous pair with a nonzero solution iff (1/sin^2 = 1 + cot^2)

    cot(pi gamma) = -(a_1 a_2 + b_1 b_2) / (a_2 b_1 - a_1 b_2)            (JN)

(:func:`junction_exponent`: gamma0 in (0, 1), the principal arccot as
:func:`sie.sie_exponents`; "bounded" gamma = gamma0, "singular" gamma = gamma0 - 1), with
the amplitude ratio A_2 / A_1 = (a_1 + b_1 cot(pi gamma)) sin(pi gamma) / b_1
(:func:`junction_ratio`).  With z_i = a_i + i b_i = r_i exp(i pi t_i), (JN) reads gamma =
t_2 - t_1 (mod 1), and an outer end's exponent is t_1 (mod 1) at c, -t_J (mod 1) at d: the
sum of all the exponents telescopes to an integer, and the index is kappa = -(that sum), in
[-J, J].  No jump (a_1 b_2 = a_2 b_1) leaves an integer exponent: no junction at all.

Method (the general collocation of :mod:`sie.fixed_ends`, one block per interval):
psi_i = w_i phi_i, w_i the weight with the outer end's exponent at an outer end and the
junction's at a junction, phi_i = sum_{k<N_i} c_{ik} P_k^{(alpha_i, beta_i)}.  At a
collocation point x of L_i the image of w_j P_k is

    i = j:   a_i w_i P_k(x) + b_i H[w_i P_k](x)          (:func:`sie.fixed_ends.hilbert_images`)
    i != j:  b_i (1/pi) int_{L_j} w_j P_k / (t - x) dt

the latter by :func:`sie.fixed_ends.graded_weight_rule`, graded toward the end of L_j next
to x on the scale of x's distance to it (a collocation point 1e-4 from the junction sees a
near-singular integrand there), with the distance formed from local distances, never as a
difference of close coordinates.  Collocation points: the roots of
P_{m_i}^{(-alpha_i, -beta_i)} on each L_i, m_i = N_i - k_i, where the shares k_i of kappa
are the cumulative roundings of -(beta_i + alpha_i), a junction's exponent counted half on
either side (sum k_i = kappa).  kappa = 1: int_L psi = total closes the square system;
kappa = J (only when every end is singular): the J integrals over the intervals; kappa < 0:
least squares, the root-mean-square residual reported as ``consistency``.

The regular part.  The basis carries the junction's power abs(t - e)^gamma times a smooth
function on each side, but the solution for a smooth f also has a part that is smooth
across the junction: at order (x - e)^0 the equation on the two sides, a_i C + b_i H0 =
f(e -+ 0), gives psi(e) = C = (b_1 f(e+) - b_2 f(e-)) / (a_2 b_1 - a_1 b_2), nonzero for a
generic f (zero for f continuous with b_1 = b_2, and for the manufactured psi = abs(t -
e)^gamma g(t) of the tests).  On L_1, C = w_1 * C (e - t)^(-gamma): phi_1 is not smooth,
and the pieces' series alone converge like a power of n, or not at all (a bounded gamma
near 1: 0.3 at n = 48).  So psi carries a regular part besides, W r on the whole of [c, d],
W the outer ends' weight, r = sum_{k<K} r_k P_k^{(alpha_d, beta_c)} with K = ``regular``
(6) per junction and K more collocation points; its image is a_i W P_k + b_i H_L[W P_k], the
principal value over the whole of L (:func:`sie.fixed_ends.hilbert_images` on [c, d]).  The
pieces' series approximate W r algebraically well, so the columns are nearly dependent (a
frame; condition 1e9-1e16): the system is solved in least squares, oversampled (N_i
more collocation points on each interval; the square frame system stalls at ~1e-10, the
oversampled one reaches ~1e-13).  ``regular=0`` gives the plain collocation (square where
kappa >= 0), geometric to rounding where psi has no regular part.

Scope: without a kernel and without breaks.

References
----------
N. I. Muskhelishvili, Singular Integral Equations (1953) (discontinuous
coefficients; the exponents at the points of discontinuity and the index).  F. Erdogan, G.
D. Gupta and T. S. Cook, "Numerical solution of singular integral equations", in Methods of
Analysis and Solutions of Crack Problems, G. C. Sih (ed.), Noordhoff (1973), ch. 7.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from .errors import (InconsistentEquationWarning, InvalidCoefficientError,
                     InvalidEndConditionError, InvalidIntervalError, InvalidOrderError,
                     PerIntervalArgumentError,
                     ResidualWarning, SideConditionError, UnsupportedEquationError,
                     call_checked, check_finite_real, check_order, describe_value, is_number)
from .exponents import Exponents, check_coefficients, check_end, exponents_of
from .fixed_ends import (_CHECKS, _CONSISTENCY_TOL, _N_MAX, _Q_MIN, _RESIDUAL_TOL,
                         FixedEndSolution, graded_weight_rule, hilbert_images)
from .gaussjacobi import gauss_jacobi_cached
from .intervals import Interval
from .jacobi import jacobi_vandermonde
from .solution import IntervalSolution
from .special import jacobi_moment_shifted

_REGULAR = 6   # terms of the regular part per junction (the default of solve_junctions)
_OVER = 1.0     # with a regular part, N_i more collocation points per interval (the frame's
#                 least squares oversampled: the junction's value 2e-9 -> 4e-14 at n = 32)

__all__ = ["junction_exponent", "junction_ratio", "solve_junctions", "JunctionSolution"]


# --------------------------------------------------------------------------
# the local analysis
# --------------------------------------------------------------------------
def _jump(a1, b1, a2, b2):
    """(x, y) with cot(pi gamma) = x / y: x = -(a_1 a_2 + b_1 b_2), y = a_2 b_1 - a_1 b_2
    (x + i y = -z_1 conj(z_2), z_i = a_i + i b_i)."""
    return -(a1 * a2 + b1 * b2), a2 * b1 - a1 * b2


def _is_proportional(a1, b1, a2, b2) -> bool:
    """Whether a_1 b_2 = a_2 b_1 to rounding: no jump, no junction."""
    return abs(a2 * b1 - a1 * b2) <= 4.0 * np.finfo(float).eps * (abs(a2 * b1) + abs(a1 * b2))


def _gamma0_pair(a1, b1, a2, b2):
    """(gamma0, 1 - gamma0), each from atan2 without cancellation (as
    :func:`sie.exponents.exponents_of` forms alpha0): cot(pi gamma0) = x / y is
    atan2(abs(y), x sign(y)) / pi."""
    x, y = _jump(a1, b1, a2, b2)
    sx = x if y > 0 else -x
    return math.atan2(abs(y), sx) / math.pi, math.atan2(abs(y), -sx) / math.pi


def junction_exponent(a1, b1, a2, b2) -> float:
    """gamma0 in (0, 1) of a junction where (a, b) jumps from (a_1, b_1) to (a_2, b_2).

    psi ~ A_1 (e - t)^gamma (t < e), A_2 (t - e)^gamma (t > e) is a local solution of the
    homogeneous equation iff (Muskhelishvili 1953, discontinuous coefficients; the module
    docstring)

        cot(pi gamma) = -(a_1 a_2 + b_1 b_2) / (a_2 b_1 - a_1 b_2);

    gamma0 is its principal root in (0, 1); "bounded" takes gamma = gamma0, "singular"
    gamma = gamma0 - 1.

    Parameters
    ----------
    a1, b1, a2, b2 : float
        The coefficients on the left and the right of the junction: finite, b_i != 0, not
        proportional.

    Returns
    -------
    float

    Raises
    ------
    InvalidCoefficientError
        A coefficient not finite, b_i = 0, or (a_1, b_1) proportional to (a_2, b_2).

    References
    ----------
    N. I. Muskhelishvili, Singular Integral Equations, Noordhoff (1953) (the
    Riemann-Hilbert problem with discontinuous coefficients: the exponent at a point where
    the coefficient jumps).

    Examples
    --------
    The airfoil equation (a = 0) next to a = b = 1: cot(pi gamma) = -1, gamma0 = 3/4.

    >>> import sie
    >>> round(sie.junction_exponent(0.0, 1.0, 1.0, 1.0), 15)
    0.75
    """
    a1, b1 = check_coefficients(a1, b1)
    a2, b2 = check_coefficients(a2, b2)
    if _is_proportional(a1, b1, a2, b2):
        raise InvalidCoefficientError(
            f"(a, b) = ({a1!r}, {b1!r}) and ({a2!r}, {b2!r}) are proportional: a junction "
            "where nothing jumps; give one interval")
    return _gamma0_pair(a1, b1, a2, b2)[0]


def junction_ratio(a1, b1, a2, b2, gamma) -> float:
    """A_2 / A_1 of the junction's local solution with exponent ``gamma`` (gamma0 or
    gamma0 - 1): (a_1 + b_1 cot(pi gamma)) sin(pi gamma) / b_1 = (a_1 sin(pi gamma) + b_1
    cos(pi gamma)) / b_1, from the leading term on the left of the junction (module
    docstring).  Over a power gamma + k the ratio carries a factor (-1)^k: psi = |t -
    e|^gamma g(t) (times A_1, A_2) with g smooth across the junction leaves no power of
    |x - e| in the equation's image."""
    return (a1 * math.sin(math.pi * gamma) + b1 * math.cos(math.pi * gamma)) / b1


# --------------------------------------------------------------------------
# the input
# --------------------------------------------------------------------------
def _touching_intervals(intervals):
    """``intervals`` as a tuple of :class:`Interval`: at least two (c, d) pairs, finite,
    c < d, each starting exactly where the previous ends."""
    try:
        pairs = [tuple(p) for p in intervals]
    except TypeError:
        raise InvalidIntervalError(
            f"intervals must be a sequence of (c, d) pairs, got {intervals!r}") from None
    if len(pairs) < 2:
        raise InvalidIntervalError(
            f"intervals must hold at least two touching (c, d) pairs (one junction), got "
            f"{len(pairs)}: one interval is sie.solve's")
    out = []
    for j, p in enumerate(pairs):
        if len(p) != 2 or not (is_number(p[0]) and is_number(p[1])):
            raise InvalidIntervalError(f"intervals[{j}] must be a pair of real numbers "
                                       f"(c, d), got {describe_value(p)}")
        c, d = float(p[0]), float(p[1])
        if not (math.isfinite(c) and math.isfinite(d)):
            raise InvalidIntervalError(f"intervals[{j}] = {p!r}: the ends must be finite")
        if not c < d:
            raise InvalidIntervalError(f"intervals[{j}] = {p!r}: need c < d")
        if out and c != out[-1].d:
            prev = out[-1]
            what = "overlaps" if c < prev.d else "leaves a gap after"
            raise InvalidIntervalError(
                f"intervals[{j}] = ({c!r}, {d!r}) {what} intervals[{j - 1}] = ({prev.c!r}, "
                f"{prev.d!r}): at a junction d_i == c_(i+1) exactly (disjoint intervals with "
                "gaps are sie.solve's)")
        out.append(Interval(c, d))
    return tuple(out)


def _per_interval(name, values, J):
    """A sequence of exactly J entries, one per interval."""
    if isinstance(values, (str, bytes)) or np.ndim(values) == 0:
        raise PerIntervalArgumentError(
            f"{name} must be a sequence of {J} values (one per interval), got {values!r}")
    vals = list(values)
    if len(vals) != J:
        raise PerIntervalArgumentError(
            f"{name} must hold {J} values (one per interval), got {len(vals)}")
    return vals


def _orders(n, J):
    """N_i: one int for all intervals or a sequence of J."""
    if isinstance(n, (str, bytes)) or np.ndim(n) == 0:
        return [check_order(n, 1, "")] * J
    vals = list(n)
    if len(vals) != J:
        raise PerIntervalArgumentError(
            f"n must be one integer or a sequence of {J} (one per interval), got "
            f"{len(vals)} entries")
    return [check_order(v, 1, "") for v in vals]


def _check_regular(regular) -> int:
    if isinstance(regular, (bool, np.bool_)) or not isinstance(regular, (int, np.integer)) \
            or not 0 <= regular <= 32:
        raise InvalidOrderError(f"regular must be an integer in 0..32 (terms of the regular "
                                f"part per junction), got {regular!r}")
    return int(regular)


def _junction_choices(junctions, J):
    try:
        vals = list(junctions) if not isinstance(junctions, (str, bytes)) else None
    except TypeError:
        vals = None
    if vals is None:
        raise InvalidEndConditionError(
            f'junctions must be a sequence of {J - 1} "bounded" / "singular" (one per '
            f"junction), got {junctions!r}")
    if len(vals) != J - 1:
        raise PerIntervalArgumentError(
            f'junctions must hold {J - 1} choices "bounded" / "singular" (one per junction), '
            f"got {len(vals)}")
    return [check_end(f"junctions[{j}]", v) for j, v in enumerate(vals)]


# --------------------------------------------------------------------------
# the exponents and the index
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class _End:
    """An exponent e with 1 + e and 1 - e formed without cancellation."""
    e: float
    p1: float
    m1: float


def _junction_end(a1, b1, a2, b2, choice) -> _End:
    g0, g0c = _gamma0_pair(a1, b1, a2, b2)
    if choice == "bounded":
        return _End(g0, 1.0 + g0, g0c)
    return _End(-g0c, g0, 1.0 + g0c)


def _outer_ends(a, b, left, right):
    lo = exponents_of(a[0], b[0], left, "bounded")
    hi = exponents_of(a[-1], b[-1], "bounded", right)
    return _End(lo.beta, lo.beta_p1, lo.beta_m1), _End(hi.alpha, hi.alpha_p1, hi.alpha_m1)


def _index(ends) -> int:
    """kappa = -(sum of all the exponents): an integer (the sum telescopes, module
    docstring); the rounding of the sum is checked."""
    s = -sum(e.e for e in ends)
    k = round(s)
    assert abs(s - k) < 1e-9, f"the exponents' sum {s!r} is not an integer"
    return int(k)


def _shares(lefts, rights, kappa):
    """k_i with sum k_i = kappa: the cumulative roundings of -(beta_i + alpha_i), a
    junction's exponent counted half on either side (the difference between N_i and the
    number of collocation points on L_i)."""
    J = len(lefts)
    real = [-(lefts[i].e * (0.5 if i > 0 else 1.0) + rights[i].e * (0.5 if i < J - 1 else 1.0))
            for i in range(J)]
    cum = np.cumsum(real)
    K = [int(round(v)) for v in cum[:-1]] + [kappa]
    return [K[0]] + [K[i] - K[i - 1] for i in range(1, J)]


def _piece_exponents(a, b, left: _End, right: _End, share: int) -> Exponents:
    """The :class:`sie.Exponents` of one interval: its end exponents, kappa = its share of
    the index, alpha0 and cot from its own (a, b)."""
    named = exponents_of(a, b, "bounded", "bounded")
    return Exponents(right.e, left.e, share, named.alpha0, named.cot,
                     math.sin(math.pi * right.e), right.p1, left.p1, right.m1, left.m1)


# --------------------------------------------------------------------------
# the system
# --------------------------------------------------------------------------
def _cross_images(nj, ej: Exponents, delta, from_left: bool, q):
    """(1/pi) int_{-1}^{1} w_j P_k(v) / (v - x) dv, k < nj, for points x outside [-1, 1] at
    local distances ``delta`` > 0 from its left end (``from_left``: x = -1 - delta) or its
    right end: the rule graded toward that end on the scale of delta
    (:func:`sie.fixed_ends.graded_weight_rule`); v - x = (1 + v) + delta (or -((1 - v) +
    delta)) from the nodes' distances, without cancellation."""
    out = np.empty((delta.size, nj))
    for r, dlt in enumerate(delta):
        far = 2.0 + dlt
        dl, dr, wt = graded_weight_rule(dlt if from_left else far, far if from_left else dlt,
                                        q, ej.alpha, ej.beta, from_left, not from_left)
        v = np.where(dl <= dr, dl - 1.0, 1.0 - dr)
        denom = (dl + dlt) if from_left else -(dr + dlt)
        out[r] = (wt / denom) @ jacobi_vandermonde(nj, ej.alpha, ej.beta, v)
    return out / math.pi


def _points(iv: Interval, u):
    """Local distances (1 + u, 1 - u) of the points and the real coordinates, formed from
    the nearer end (next to a junction s keeps its distance to it)."""
    dl, dr = 1.0 + u, 1.0 - u
    s = np.where(dl <= dr, iv.c + iv.h * dl, iv.d - iv.h * dr)
    return dl, dr, s


def _rows(i, dl, dr, ivs, exps, ns, a, b, q):
    """The rows of the points (local distances dl, dr on L_i) against all the unknowns."""
    cols = []
    for j, (ivj, ej, nj) in enumerate(zip(ivs, exps, ns)):
        if j == i:
            u = np.where(dl <= dr, dl - 1.0, 1.0 - dr)
            blk = b[i] * hilbert_images(nj, ej.alpha, ej.beta, u)
            if a[i] != 0.0:
                w = dr ** ej.alpha * dl ** ej.beta
                blk += a[i] * w[:, None] * jacobi_vandermonde(nj, ej.alpha, ej.beta, u)
        elif j > i:
            # the real distance to c_j: the intervals between, then the point's own to d_i
            gap = ivs[j - 1].d - ivs[i].d
            blk = b[i] * _cross_images(nj, ej, (gap + ivs[i].h * dr) / ivj.h, True, q)
        else:
            gap = ivs[i].c - ivs[j + 1].c
            blk = b[i] * _cross_images(nj, ej, (gap + ivs[i].h * dl) / ivj.h, False, q)
        cols.append(blk)
    return np.hstack(cols)


def _regular_rows(i, dl, dr, ivs, reg: Exponents, K, a, b):
    """The images of the regular part's basis W P_k^{(alpha_d, beta_c)} on the whole of
    L = [c, d] (k < K) at the points of L_i (local distances dl, dr on L_i): a_i W P_k +
    b_i H_L[W P_k], the principal value over all of L (the regular part is smooth across the
    junctions)."""
    c, d = ivs[0].c, ivs[-1].d
    hL = 0.5 * (d - c)
    # distances to the outer ends: the intervals between, then the point's own
    dlL = ((ivs[i].c - c) + ivs[i].h * dl) / hL
    drL = ((d - ivs[i].d) + ivs[i].h * dr) / hL
    u = np.where(dlL <= drL, dlL - 1.0, 1.0 - drL)
    blk = b[i] * hilbert_images(K, reg.alpha, reg.beta, u)
    if a[i] != 0.0:
        w = drL ** reg.alpha * dlL ** reg.beta
        blk += a[i] * w[:, None] * jacobi_vandermonde(K, reg.alpha, reg.beta, u)
    return blk


def _regular_moments(ivs, reg: Exponents, K):
    """int_{L_i} W P_k dt, k < K, per interval (rows), W P_k the regular part's basis on L =
    [c, d]: Gauss-Jacobi on each L_i of the outer end's factor of W where L_i holds that
    end, the rest of W (smooth on L_i) evaluated."""
    c, d = ivs[0].c, ivs[-1].d
    hL = 0.5 * (d - c)
    J, out = len(ivs), np.zeros((len(ivs), K))
    for i, iv in enumerate(ivs):
        ea = reg.alpha if i == J - 1 else 0.0
        eb = reg.beta if i == 0 else 0.0
        v, om = gauss_jacobi_cached(K + 8, ea, eb)
        v, om = np.asarray(v), np.asarray(om)
        dlL = ((iv.c - c) + iv.h * (1.0 + v)) / hL
        drL = ((d - iv.d) + iv.h * (1.0 - v)) / hL
        rest = drL ** (reg.alpha - ea) * dlL ** (reg.beta - eb)
        # the factor of W that the rule carries, in L's local distances: (h_i / h_L)^e
        scale = (iv.h / hL) ** (ea + eb)
        u = np.where(dlL <= drL, dlL - 1.0, 1.0 - drL)
        out[i] = iv.h * scale * ((om * rest) @ jacobi_vandermonde(K, reg.alpha, reg.beta, u))
    return out


def _side_rows(kappa, ivs, exps, ns, reg, K, total):
    """The rows of the side conditions and their values: kappa = 1, int_L psi = total;
    kappa = J, int_{L_i} psi = total[i]."""
    J = len(ivs)
    moments = [iv.h * jacobi_moment_shifted(e.alpha_p1, e.beta_p1) for iv, e in zip(ivs, exps)]
    starts = np.concatenate([[0], np.cumsum(ns)[:-1]])
    regular = _regular_moments(ivs, reg, K) if K else np.zeros((J, 0))
    if kappa == 1:
        row = np.zeros(sum(ns))
        row[starts] = moments
        return np.concatenate([row, regular.sum(axis=0)])[None, :], np.array([total])
    if kappa == J:
        rows = np.zeros((J, sum(ns)))
        rows[np.arange(J), starts] = moments
        return np.hstack([rows, regular]), np.asarray(total, dtype=float)
    raise UnsupportedEquationError(
        f"index {kappa} on {J} intervals: side conditions are available for index 1 (int_L "
        f"psi = total) and index {J} (total = the {J} integrals over the intervals)")


def _check_total(total, kappa, J):
    if kappa <= 0:
        if total is not None:
            raise SideConditionError(f"total must not be given: the index is {kappa} (the "
                                     "solution is unique or over-determined)")
        return None
    if 2 <= kappa < J:
        raise UnsupportedEquationError(
            f"index {kappa} on {J} intervals: side conditions are available for index 1 "
            f"(int_L psi = total) and index {J} (total = the {J} integrals over the "
            "intervals)")
    if total is None:
        raise SideConditionError(
            f"total is required: the index is {kappa}" + (
                " (int_L psi = total)" if kappa == 1 else
                f" (a sequence of the {J} integrals over the intervals)"))
    if kappa == 1:
        return check_finite_real("total", total, SideConditionError)
    if isinstance(total, (str, bytes)) or np.ndim(total) != 1 or len(total) != J:
        raise SideConditionError(
            f"total must be a sequence of the {J} integrals over the intervals (index "
            f"{kappa}), got {total!r}")
    return [check_finite_real(f"total[{i}]", v, SideConditionError) for i, v in enumerate(total)]


# --------------------------------------------------------------------------
# the result
# --------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class JunctionSolution(FixedEndSolution):
    """psi on touching intervals with jumping coefficients: one piece per interval (w_i
    phi_i, :class:`sie.IntervalSolution`) and the regular part W r on the whole of L
    (``regular``, an IntervalSolution on [c, d], or None); ``sol(s)`` evaluates their sum on
    L (a singular junction itself raises :class:`sie.EvaluationPointError`), ``integral``
    and ``kernel_integral`` include the regular part; ``phi``, ``weight`` and
    ``endpoint_value`` are the pieces' own (psi = w_i phi_i + W r); ``cauchy``,
    ``cauchy_limit`` and ``log_potential`` are those of :class:`sie.FixedEndSolution`,
    summed over the pieces and the regular part (a junction is an end of two pieces: the
    transform is not evaluated there, the log potential is).

    Attributes
    ----------
    gamma : tuple of float
        The exponent at each junction.
    kappa : int
        The index, -(sum of all the exponents); a piece's ``exp.kappa`` is its share (the
        difference between its coefficients and its collocation points).
    consistency : float or None
        kappa < 0: the root-mean-square residual of the least-squares collocation (zero iff
        f meets the solvability conditions, to the truncation).
    alpha, beta, n, coefficients : tuple
        Per interval.
    """
    gammas: tuple = field(default=(), repr=False)
    index: int = field(default=0, repr=False)
    _consistency: float | None = field(default=None, repr=False)
    regular: IntervalSolution | None = field(default=None, repr=False)

    def __call__(self, s):
        out = super().__call__(s)
        r = self.regular
        if r is None:
            return out
        s = self._real_points(s)
        iv = r.interval
        sel = iv.contains(s)
        if np.any(sel):
            out = np.array(out, dtype=float)
            out[sel] += r.psi_local(iv.local(s[sel]))
        return out

    def integral(self, interval=None) -> float:
        """int psi over L (``interval=None``) or over interval j, the regular part's
        share included."""
        base = super().integral(interval)
        if self.regular is None:
            return base
        ivs = [p.interval for p in self.pieces]
        m = _regular_moments(ivs, self.regular.exp, self.regular.n) @ self.regular.coefficients
        return base + float(m.sum() if interval is None else m[self._piece_index(interval)])

    def _piece_index(self, interval):
        return self.pieces.index(self._piece(interval))

    def kernel_integral(self, kernel, s, nodes=None):
        out = super().kernel_integral(kernel, s, nodes)
        if self.regular is None:
            return out
        s = self._real_points(s)
        r = self.regular
        flat = np.ascontiguousarray(s.ravel(), dtype=float)
        extra = r.kernel_local(kernel, flat, 2 * r.n + 32 if nodes is None else int(nodes))
        return out + extra.reshape(s.shape)

    def _transform_pieces(self):
        """The pieces and the regular part: the Cauchy transform, its limits and the log
        potential sum over them (:class:`sie.FixedEndSolution`)."""
        return self.pieces if self.regular is None else self.pieces + (self.regular,)

    gamma = property(lambda self: self.gammas, doc="The exponent at each junction.")
    kappa = property(lambda self: self.index, doc="The index, -(sum of all the exponents).")
    consistency = property(lambda self: self._consistency,
                           doc="The least-squares residual for kappa < 0 (None elsewhere).")


# --------------------------------------------------------------------------
# the solver
# --------------------------------------------------------------------------
def solve_junctions(f, a, b, intervals, *, n, left, right, junctions, total=None,
                    regular=_REGULAR, check_residual=True):
    """Solve a_i psi + (b_i/pi) PV int_L psi/(t - s) dt = f(s), s in L_i, on touching
    intervals L_i whose coefficients jump at the junctions.

    The exponent at each junction from :func:`junction_exponent` and the choice there, the
    index from the sum of all the exponents, the general collocation of the module
    docstring (Muskhelishvili 1953, discontinuous coefficients; Erdogan, Gupta & Cook 1973,
    ch. 7).

    Parameters
    ----------
    f : callable
        f(s) on float arrays, vectorised, finite real values.
    a, b : sequence of float
        (a_i, b_i) on each interval: finite, b_i != 0, neighbours not proportional.
    intervals : sequence of (c, d)
        At least two, ascending, touching: d_i == c_(i+1) exactly.
    n : int or sequence of int
        Jacobi coefficients per interval (at most 400 each).
    left, right : {"bounded", "singular"}
        The outer ends c_1 and d_J.
    junctions : sequence of {"bounded", "singular"}
        One per junction: gamma0 or gamma0 - 1.
    total : float or sequence of float, optional
        Index 1: int_L psi.  Index J (every end singular and every gamma0 below the next):
        the J integrals over the intervals.  Otherwise not given.
    regular : int
        Terms of the regular part (smooth across the junctions) per junction, 0..32; 0: the
        pieces' series alone (module docstring).
    check_residual : bool
        Check the equation between the collocation points (:class:`sie.ResidualWarning`).

    Returns
    -------
    JunctionSolution

    Raises
    ------
    InvalidIntervalError
        Fewer than two intervals, c >= d, a gap or an overlap between neighbours.
    PerIntervalArgumentError
        a, b, n or junctions of the wrong length.
    InvalidCoefficientError
        A coefficient not finite, b_i = 0, or neighbours' (a, b) proportional.
    InvalidEndConditionError
        A choice not "bounded" / "singular".
    SideConditionError
        total missing where the index is positive, or given where it is not.
    UnsupportedEquationError
        An index in 2..J-1 (no side conditions defined), or n above 400.
    InvalidOrderError
        n not an integer >= 1, or ``regular`` not an integer in 0..32.

    Warns
    -----
    InconsistentEquationWarning
        kappa < 0 and the least-squares residual above 1e-8 max abs(f).
    ResidualWarning
        The equation's residual between the collocation points above 1e-6 (relative).

    References
    ----------
    N. I. Muskhelishvili, Singular Integral Equations, Noordhoff (1953) (discontinuous
    coefficients) and ch. 10 (the index); F. Erdogan, G. D. Gupta and T. S. Cook (1973),
    ch. 7 (the Gauss-Jacobi collocation).

    Examples
    --------
    The airfoil equation on [-1, 0] next to a = b = 1 on [0, 1]: gamma0 = 3/4, the outer
    exponents -1/2 (singular at -1) and -1/4 (singular at 1), index -(-1/2 + 3/4 - 1/4) = 0:

    >>> import numpy as np, sie
    >>> sol = sie.solve_junctions(np.cos, [0.0, 1.0], [1.0, 1.0], [(-1.0, 0.0), (0.0, 1.0)],
    ...                           n=16, left="singular", right="singular",
    ...                           junctions=["bounded"])
    >>> sol.gamma, sol.kappa, sol.beta[0], sol.alpha[1]
    ((0.75,), 0, -0.5, -0.25)
    """
    ivs = _touching_intervals(intervals)
    J = len(ivs)
    a = _per_interval("a", a, J)
    b = _per_interval("b", b, J)
    coef = [check_coefficients(ai, bi) for ai, bi in zip(a, b)]
    a = [c[0] for c in coef]
    b = [c[1] for c in coef]
    for i in range(J - 1):
        if _is_proportional(a[i], b[i], a[i + 1], b[i + 1]):
            raise InvalidCoefficientError(
                f"(a, b) on intervals[{i}] = ({a[i]!r}, {b[i]!r}) and on intervals[{i + 1}] = "
                f"({a[i + 1]!r}, {b[i + 1]!r}) are proportional: a junction where nothing "
                "jumps; give one interval")
    left, right = check_end("left", left), check_end("right", right)
    choices = _junction_choices(junctions, J)
    ns = _orders(n, J)
    if max(ns) > _N_MAX:
        raise UnsupportedEquationError(f"n = {max(ns)}: the general collocation takes at "
                                       f"most {_N_MAX} coefficients per interval")

    lo, hi = _outer_ends(a, b, left, right)
    juncs = [_junction_end(a[i], b[i], a[i + 1], b[i + 1], choices[i]) for i in range(J - 1)]
    lefts, rights = [lo] + juncs, juncs + [hi]
    kappa = _index([lo, hi] + juncs)
    total = _check_total(total, kappa, J)
    shares = _shares(lefts, rights, kappa)
    exps = [_piece_exponents(a[i], b[i], lefts[i], rights[i], shares[i]) for i in range(J)]
    K = _check_regular(regular) * (J - 1)
    # the regular part's K coefficients: as many more collocation points, half of each
    # junction's on either side of it, and N_i more on each interval (oversampled least
    # squares, module docstring)
    extra = [0] * J
    for j in range(J - 1):
        extra[j] += (K // (J - 1) + 1) // 2
        extra[j + 1] += K // (J - 1) // 2
    over = [int(_OVER * ni) if K else 0 for ni in ns]
    ms = [ni - k + x + o for ni, k, x, o in zip(ns, shares, extra, over)]
    if min(ms) < 1:
        raise UnsupportedEquationError(
            f"n = {ns}: each interval needs more coefficients than its share of the index "
            f"{shares}")
    reg = _piece_exponents(a[0], b[0], lo, hi, 0)
    sol_c, matrix, consistency = _collocate(f, a, b, ivs, exps, ns, ms, reg, K, kappa, total,
                                            check_residual)
    starts = np.concatenate([[0], np.cumsum(ns)])
    pieces = []
    for i in range(J):
        c = np.array(sol_c[starts[i]:starts[i + 1]])
        c.flags.writeable = False
        pieces.append(IntervalSolution(ivs[i], exps[i], ns[i], c, None, None, None))
    regular_piece = None
    if K:
        c = np.array(sol_c[starts[-1]:])
        c.flags.writeable = False
        regular_piece = IntervalSolution(Interval(ivs[0].c, ivs[-1].d), reg, K, c, None,
                                         None, None)
    return JunctionSolution(tuple(pieces), tuple(a), tuple(b), True, matrix,
                            tuple(e.e for e in juncs), kappa, consistency, regular_piece)


def _collocate(f, a, b, ivs, exps, ns, ms, reg, K, kappa, total, check_residual):
    """Assemble and solve: (coefficients, matrix, consistency); the regular part's K
    coefficients last."""
    q = max(_Q_MIN, max(ns) // 2 + 16)
    A, fx, Ac, fc = [], [], [], []
    for i, (iv, e, m) in enumerate(zip(ivs, exps, ms)):
        u = np.asarray(gauss_jacobi_cached(m, -e.alpha, -e.beta)[0])
        u = np.concatenate([u, _CHECKS if check_residual else np.empty(0)])
        dl, dr, s = _points(iv, u)
        rows = _rows(i, dl, dr, ivs, exps, ns, a, b, q)
        if K:
            rows = np.hstack([rows, _regular_rows(i, dl, dr, ivs, reg, K, a, b)])
        vals = call_checked(f, "f", (s,), s.shape)
        Ac.append(rows[:m])
        fc.append(vals[:m])
        A.append(rows[m:])
        fx.append(vals[m:])
    Ac, fc = np.vstack(Ac), np.concatenate(fc)
    fscale = max(float(np.max(np.abs(fc))), np.finfo(float).tiny)
    consistency = None
    matrix, rhs = Ac, fc
    if kappa > 0:
        rows, vals = _side_rows(kappa, ivs, exps, ns, reg, K, total)
        scale = float(np.max(np.abs(Ac))) / float(np.max(np.abs(rows)))
        matrix = np.vstack([scale * rows, Ac])
        rhs = np.concatenate([scale * vals, fc])
    if kappa >= 0 and K == 0:
        c = np.linalg.solve(matrix, rhs)
    else:
        # over-determined (kappa < 0), or the regular part's columns, which the pieces'
        # series approximate algebraically well: least squares
        norms = np.linalg.norm(matrix, axis=0)
        c, *_ = np.linalg.lstsq(matrix / norms, rhs, rcond=None)
        c = c / norms
    if kappa < 0:
        consistency = float(np.sqrt(np.mean((Ac @ c - fc) ** 2)))
        if consistency > _CONSISTENCY_TOL * fscale:
            warnings.warn(
                f"sie.solve_junctions: the collocation is over-determined (index {kappa}) and "
                f"its least-squares residual is {consistency:.3g} (max abs(f) = "
                f"{fscale:.3g}): f violates the solvability conditions, or n is too small",
                InconsistentEquationWarning, stacklevel=3)
    if check_residual:
        A, fx = np.vstack(A), np.concatenate(fx)
        lhs = A @ c
        r = float(np.max(np.abs(lhs - fx))) / max(fscale, float(np.max(np.abs(lhs))))
        if r > _RESIDUAL_TOL:
            warnings.warn(
                f"sie.solve_junctions: the solution leaves a residual of {r:.2g} (relative to "
                f"f) between the collocation points: n = {ns} does not resolve f or psi",
                ResidualWarning, stacklevel=3)
    return c, matrix, consistency
