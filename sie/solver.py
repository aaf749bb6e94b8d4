"""Gauss-Jacobi collocation for Cauchy singular integral equations of the second kind on
one or several intervals.

    a psi(s) + (b/pi) PV int_L psi(t)/(t - s) dt + int_L k(s,t) psi(t) dt = f(s),   s in L,
    L = [c_1, d_1] U ... U [c_J, d_J].

The solve of an :class:`sie.Equation` (its blocks validated there), in stages, each in its
own module:

1. **unknowns** (:mod:`sie.unknowns`): per interval, psi = w phi with the exponents of its
   end choices, phi = sum_{k<n} c_k P_k^{(alpha,beta)} in the local coordinate, and the
   projection rule of (1-u)^{-alpha}(1+u)^{-beta} (collocation at the roots of
   P_{n-kappa}^{(-alpha,-beta)}; Erdogan, Gupta & Cook 1973; Krenk 1975);
2. **right-hand side**: f projected onto P_m^{(-alpha,-beta)} per interval;
3. **assembly** (:mod:`sie.assembly`): the exact dominant operator on the diagonal blocks,
   the coupling between intervals (exact Cauchy transforms of the Jacobi basis off its
   interval, :mod:`sie.cauchy`) and the kernel off it, side conditions as rows, one solve;
4. **result** (:mod:`sie.solution`): an immutable :class:`Solution`, with the residual checks
   (solvability for index -1, the equation at points between the nodes).

Right-hand sides with kinks: with ``breaks`` the projections are computed by a composite rule
split at the breaks, and phi is evaluated pointwise by adding the exact inversion of the
truncation remainder (:mod:`sie.remainder`).

One-interval equations without a kernel also have their functionals (int psi, the
solvability residual) from one Gauss sum (:func:`block_functionals`); a case axis of them is
solved by :mod:`sie.batch`.
"""
from __future__ import annotations

import functools
import warnings
from dataclasses import dataclass

import numpy as np

from .assembly import assemble_and_solve, operator_images, probe_kernel
from .errors import (InconsistentEquationWarning, InvalidOrderError,
                     ResidualWarning, SideConditionError, call_checked, check_finite_real,
                     check_order)
from .block import Block
from .exponents import Exponents, exponents_of
from .intervals import Interval, per_interval, split_breaks
from .jacobi import jacobi_norms_cached, jacobi_vandermonde, plateau_start
from .solution import IntervalSolution, Solution
from .quadrature import composite_weighted_rule
from .unknowns import _EXTRA_PER_PIECE, IntervalUnknown

__all__ = ["solve_blocks", "block_functionals", "Solution", "Exponents", "Functionals", "N_MAX"]

#: Largest number of Jacobi coefficients per interval that :func:`solve`,
#: :meth:`sie.Equation.solve` and :meth:`sie.Equation.functionals` accept (a larger ``n`` raises
#: :class:`~sie.errors.InvalidOrderError`).  The projection is dense: O(n^2) work and memory
#: per interval, about 1 s at n = N_MAX.  A solution that needs more terms has a singularity
#: the basis does not carry (pass ``breaks=`` at kinks of f) or should be split into intervals.
N_MAX = 20_000
CONSISTENCY_TOL = 1e-8  # |consistency| above this times max|f| warns (index -1)
RESIDUAL_TOL = 1e-6     # equation residual above this times its scale warns
_CHECK_POINTS = np.cos(np.pi * (np.arange(7) + 0.5) / 7) * 0.999
_NO_POINTS = np.empty(0)


# --------------------------------------------------------------------------
# validation
# --------------------------------------------------------------------------

def _check_n(n, e, label):
    n = check_order(n, 2 if e.kappa == 1 else 1,
                    f"{label} for index 1 (both ends singular)" if e.kappa == 1 else label)
    if n > N_MAX:
        raise InvalidOrderError(
            f"n{label} = {n} is beyond the limit {N_MAX}: the projection is dense (O(n^2) "
            f"work and memory per interval: ~1 s at n = {N_MAX}); a solution that needs more "
            "terms has a singularity the basis does not carry (a kink: pass breaks=; a fixed "
            "singularity in the kernel) or should be split into intervals")
    return n


def _check_totals(total, exps, multi):
    """One total per interval with kappa = 1, None elsewhere."""
    J = len(exps)
    totals = per_interval("total", total, J)
    out = []
    for j, (t, e) in enumerate(zip(totals, exps)):
        where = f" on interval {j}" if multi else ""
        if e.kappa == 1:
            if t is None:
                raise SideConditionError(
                    f"total (= int psi{where}) is required when both ends{where} are singular "
                    "(index 1)")
            out.append(check_finite_real("total", t, SideConditionError))
        else:
            if t is not None:
                raise SideConditionError(
                    f"total must not be given{where}: the index there is {e.kappa} (a total "
                    "is only for both ends singular, index 1; pass None for that interval)")
            out.append(None)
    return out


# --------------------------------------------------------------------------
# residual checks
# --------------------------------------------------------------------------
def _dominant_image(piece):
    """sum_k c_k P_{k-kappa}^{(-alpha,-beta)} at the check points (the dominant operator
    without lambda and without the kappa = -1 constant)."""
    c, k = piece.coefficients, piece.kappa
    shifted = c[1:] if k == 1 else (c if k == 0 else np.concatenate([[0.0], c]))
    return _check_basis(shifted.size, -piece.alpha, -piece.beta) @ shifted


@functools.lru_cache(maxsize=64)
def _check_basis(n, a, b):
    """P_k^{(a,b)} at the residual check points, k < n (read-only)."""
    out = jacobi_vandermonde(n, a, b, _CHECK_POINTS)
    out.flags.writeable = False
    return out


def _check_residual(f_checks, unknowns, pieces, at_checks, fscale, stacklevel):
    """Warn when the equation, at points between the collocation nodes, is not satisfied to
    RESIDUAL_TOL of its scale: catches an unresolved f or kernel and kernels outside the
    method's class.  Only where the collocation is not exact by construction (a kernel or
    several intervals; alone, the dominant operator maps the basis exactly); costs f at 7
    points per interval (``f_checks``, sampled with the nodes), the rest comes with the
    assembly."""
    worst, where = 0.0, None
    for i, (ui, pi, other, fx) in enumerate(zip(unknowns, pieces, at_checks, f_checks)):
        lhs = ui.lam * _dominant_image(pi) + other
        if pi.consistency is not None:
            fx = fx - pi.consistency
        scale = max(fscale, float(np.max(np.abs(lhs))), np.finfo(float).tiny)
        r = float(np.max(np.abs(fx - lhs))) / scale
        if r > worst:
            worst, where = r, i
    if worst > RESIDUAL_TOL:
        on = f" on interval {where}" if len(unknowns) > 1 else ""
        warnings.warn(
            f"sie.solve: the solution leaves a residual of {worst:.2g} (relative to f) in the "
            f"equation between the collocation nodes{on}: n = {[u.n for u in unknowns]} does "
            "not resolve f or the kernel (increase n; pass breaks= at kinks of f), or the "
            "kernel is not smooth", ResidualWarning, stacklevel=stacklevel + 1)


# --------------------------------------------------------------------------
# the solver
# --------------------------------------------------------------------------
def solve_blocks(blocks, f, n, total, breaks, check_residual, multi, stacklevel=2):
    """:meth:`sie.Equation.solve` of one equation: its blocks (validated), f, n, the totals
    and breaks (checked here), in the four stages of the module docstring.  Warnings point
    ``stacklevel`` frames up (2: the caller of this function)."""
    J = len(blocks)
    ivs = tuple(blk.interval for blk in blocks)
    exps = [blk.exponents for blk in blocks]
    ns = [_check_n(v, e, f"[{j}]" if multi else "")
          for j, (v, e) in enumerate(zip(per_interval("n", n, J), exps))]
    totals = _check_totals(total, exps, multi)
    brs = split_breaks(breaks, ivs)
    has_kernel = any(blk.kernel is not None for blk in blocks)

    # 1. unknowns
    unknowns = [IntervalUnknown.build(blk, nj, br, t)
                for blk, nj, br, t in zip(blocks, ns, brs, totals)]
    if has_kernel:
        probe_kernel(unknowns)
    # 2. right-hand side (and f at the residual check points, where there is a check)
    checked = bool(check_residual) and (J > 1 or has_kernel) and \
        not any(br.size for br in brs)
    extra = _CHECK_POINTS if checked else _NO_POINTS
    fvals, f_checks = zip(*(u.sample(f, "f", extra) for u in unknowns))
    fhat = [u.project(v) for u, v in zip(unknowns, fvals)]
    # 3. assembly and solve
    sys_ = assemble_and_solve(unknowns, fhat, extra)
    # 4. result
    coeffs = []
    for u, c in zip(unknowns, sys_.coefficients):
        # with breaks the correction (sie.remainder) inverts g minus the image of exactly
        # these coefficients, projection noise included, so they stay as solved: a chopped
        # tail (a kink so small or so near an end that its coefficients lie below the
        # plateau) would be missing from phi, up to 6e-11 of it at n = 3072
        if u.breaks.size == 0:
            c = _chop_noise(c, u.exp)
        c.flags.writeable = False
        coeffs.append(c)
    pieces = [IntervalSolution(u.interval, u.exp, u.n, c, cons, None,
                               _end_rhs_factory(u, unknowns, coeffs, f))
              for u, c, cons in zip(unknowns, coeffs, sys_.consistency)]
    needs_scale = checked or any(p.consistency is not None for p in pieces)
    fscale = max(float(np.abs(v).max(initial=0.0)) for v in fvals) if needs_scale else 0.0
    for j, p in enumerate(pieces):
        if p.consistency is not None and abs(p.consistency) > CONSISTENCY_TOL * max(fscale, 1e-300):
            on = f" on interval {j}" if multi else ""
            warnings.warn(
                f"sie.solve: both ends are bounded{on} (index -1) and f violates the "
                f"solvability condition: consistency = {p.consistency:.3g} (max|f| = "
                f"{fscale:.3g}); the returned psi solves the equation with that weighted mean "
                "taken out of f", InconsistentEquationWarning, stacklevel=stacklevel)
    if any(br.size for br in brs):
        pieces = _with_remainders(pieces, unknowns, fvals, sys_, f)
    elif checked:
        _check_residual(f_checks, unknowns, pieces, sys_.at_checks, fscale, stacklevel)
    return Solution(tuple(pieces), _shared(blk.a for blk in blocks),
                    _shared(blk.b for blk in blocks), multi, sys_.matrix)


def _shared(values):
    """One value where all blocks share it, else the tuple of them."""
    vals = tuple(values)
    return vals[0] if len(set(vals)) == 1 else vals


def _with_remainders(pieces, unknowns, fvals, sys_, f):
    """Attach the breaks correction (built on first use) to every piece with breaks."""
    out = []
    for i, (p, u, fs, g) in enumerate(zip(pieces, unknowns, fvals, sys_.g_hat)):
        if u.breaks.size == 0:
            out.append(p)
            continue
        out.append(IntervalSolution(p.interval, p.exp, p.n, p.coefficients, p.consistency,
                                    _remainder_factory(p, u, fs, g, pieces, unknowns, f),
                                    p._end_rhs_factory))
    return out


def _end_rhs_factory(u, unknowns, coeffs, f):
    """(g, size) at the ends c, d of ``u``'s interval, on call: g = f - (coupling + kernel)
    psi and the sum of the sizes of its terms (what :meth:`IntervalSolution.endpoint_value`
    forms phi at a singular end from, and judges that form by); f at the ends themselves,
    not at m -+ h, which may round off them."""
    iv = u.interval

    def end_rhs():
        x = np.array([iv.c, iv.d])
        g = call_checked(f, "f", (x,), x.shape)
        size = np.abs(g)
        if len(unknowns) > 1 or u.kernel is not None:
            imgs = operator_images(x, u, unknowns)
            g = g - sum(img @ c for img, c in zip(imgs, coeffs))
            size = size + sum(np.abs(img) @ np.abs(c) for img, c in zip(imgs, coeffs))
        return g, size
    return end_rhs


def _remainder_factory(piece, u, fs, g_hat, pieces, unknowns, f):
    from .remainder import InversionRemainder
    iv = u.interval

    def f_local(x):
        return f(iv.real(x))

    def coupling_and_kernel(x):
        imgs = operator_images(iv.real(x), u, unknowns)
        return sum(img @ pj.coefficients for img, pj in zip(imgs, pieces))

    other = None if len(unknowns) == 1 and u.kernel is None else coupling_and_kernel
    return lambda: InversionRemainder.build(piece, u.a, u.b, f_local, other, u.breaks, u.s,
                                            u.ws, fs, g_hat)


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
    c = np.array(c, dtype=float)
    if c.size <= run:
        return c
    scale = _sqrt_norms(c.size, max(e.alpha, -0.5), max(e.beta, -0.5))
    c[plateau_start(c, scale, factor * np.finfo(float).eps, run):] = 0.0
    return c


@functools.lru_cache(maxsize=256)
def _sqrt_norms(n, a, b):
    return np.sqrt(jacobi_norms_cached(n, a, b))


# --------------------------------------------------------------------------
# functionals without the solution (searches over one interval)
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class Functionals:
    """What a search over the interval needs, without forming the solution.

    Returned by :meth:`sie.Equation.functionals`.

    Attributes
    ----------
    integral : float or None
        int psi for kappa <= 0 (h mu_0 c_0, h the half-width of the interval); None for
        kappa = 1 (it is the side condition).
    consistency : float or None
        kappa = -1: the solvability residual (as ``Solution.consistency``); None otherwise.
    alpha, beta : float
        Exponents of psi at the right and left end.
    kappa : int
        Index -(alpha + beta).

    References
    ----------
    As for :meth:`sie.Equation.functionals`.

    Examples
    --------
    >>> import sie
    >>> eq = sie.Equation(a=0.0, b=1.0, left="bounded", right="bounded")
    >>> fn = eq.functionals(lambda s: -s, n=4)
    >>> type(fn).__name__, fn.kappa, round(fn.integral, 12), abs(fn.consistency) < 1e-14
    ('Functionals', -1, 1.570796326795, True)
    """
    integral: float | None
    consistency: float | None
    alpha: float
    beta: float
    kappa: int


def block_functionals(block, f, n, breaks):
    """:meth:`sie.Equation.functionals` of one block without a kernel: the rule of its
    coefficients, ends and n (prepared once, :func:`_dominant_rule`) applied to f on its
    interval, int psi in real coordinates (h times the local integral)."""
    e = block.exponents
    rule = _dominant_rule(block.a, block.b, _check_n(n, e, ""), block.left, block.right)
    iv = block.interval
    local = f if (iv.c, iv.d) == (-1.0, 1.0) else (lambda u: f(iv.real(u)))
    some = len(breaks) if isinstance(breaks, (list, tuple)) else np.size(breaks)
    br = split_breaks(breaks, (iv,))[0] if some else ()
    fn = rule(local, br)
    if fn.integral is None or iv.h == 1.0:
        return fn
    return Functionals(iv.h * fn.integral, fn.consistency, fn.alpha, fn.beta, fn.kappa)


@functools.lru_cache(maxsize=64)
def _dominant_rule(a, b, n, left, right):
    """The functionals' rule of one block on [-1, 1], prepared once per equation and n."""
    return _DominantRule(a, b, n, left, right)


class _DominantRule:
    """int psi and the solvability residual of a psi + (b/pi) PV int psi/(t-s) dt = f on
    [-1, 1] from one Gauss sum (the projections f_0, f_1 of f on P_m^{(-alpha,-beta)}),
    exactly as the solve with the same n would form them: int psi = mu_0 c_0 with
    c_0 = f_0/lambda (kappa = 0) or f_1/lambda (kappa = -1), the residual f_0 (kappa = -1).

    The Gauss rule, the norms and the end correction are built once; each call costs one
    evaluation of f at the fixed nodes and two dot products.  With breaks, the composite
    rule of the pieces between them (which move with the interval in a search) is formed
    per call from cached Gauss-Jacobi rules, as the solve forms it.
    """

    def __init__(self, a, b, n, left, right):
        e = exponents_of(a, b, left, right)
        self.exponents, self.kappa = e, e.kappa
        if e.kappa == 1:
            return
        u = IntervalUnknown.build(Block(Interval(-1.0, 1.0), a, b, left, right, e), n,
                                  np.empty(0), None, count=2)
        rule, h = u.rule, u.norms
        self._h = h
        self._q_pieces = u.m_eq + _EXTRA_PER_PIECE        # nodes per piece, as solve's
        x = rule.x
        p1 = _p1(e, x)
        p_end = rule.end_values(2) if rule.end else np.zeros(2)
        self.nodes = x
        self.end = rule.end
        self._w = (rule.omega / h[0], rule.omega * p1 / h[1])
        self._w_end = (rule.corr * p_end[0] / h[0], rule.corr * p_end[1] / h[1])
        self._scale = u.mu0 / u.lam

    def __call__(self, f, br) -> Functionals:
        e = self.exponents
        if self.kappa == 1:
            return Functionals(None, None, e.alpha, e.beta, 1)
        if len(br):
            return self._with_breaks(f, br)
        fs = call_checked(f, "f", (self.nodes,), self.nodes.shape)
        f_end = 0.0
        if self.end:
            f_end = float(call_checked(f, "f", (np.array([float(self.end)]),), (1,))[0])
        f0 = float(self._w[0] @ fs + self._w_end[0] * f_end)
        if self.kappa == 0:
            return Functionals(self._scale * f0, None, e.alpha, e.beta, 0)
        f1 = float(self._w[1] @ fs + self._w_end[1] * f_end)
        return Functionals(self._scale * f1, f0, e.alpha, e.beta, -1)

    def _with_breaks(self, f, br):
        e = self.exponents
        rule = composite_weighted_rule(self._q_pieces, -e.alpha, -e.beta, e.alpha_m1,
                                       e.beta_m1, br)
        x = np.append(rule.x, float(rule.end)) if rule.end else rule.x
        fs = call_checked(f, "f", (x,), x.shape)
        q = rule.x.size
        wf = rule.omega * fs[:q]
        p_end = rule.corr * fs[q] * rule.end_values(2) if rule.end else (0.0, 0.0)
        f0 = (float(wf.sum()) + p_end[0]) / self._h[0]
        if self.kappa == 0:
            return Functionals(self._scale * f0, None, e.alpha, e.beta, 0)
        f1 = (float(wf @ _p1(e, rule.x)) + p_end[1]) / self._h[1]
        return Functionals(self._scale * f1, f0, e.alpha, e.beta, -1)


def _p1(e, x):
    """P_1^{(-alpha,-beta)}(x), the second function the projections are taken on."""
    return (1.0 - e.alpha) + 0.5 * (2.0 - e.alpha - e.beta) * (x - 1.0)
