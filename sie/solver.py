"""Gauss-Jacobi collocation for Cauchy singular integral equations of the second kind on
one or several intervals.

    a psi(s) + (b/pi) PV int_L psi(t)/(t - s) dt + int_L k(s,t) psi(t) dt = f(s),   s in L,
    L = [c_1, d_1] U ... U [c_J, d_J].

The stages of :func:`solve`, each in its own module:

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
"""
from __future__ import annotations

import functools
import warnings
from dataclasses import dataclass

import numpy as np

from .assembly import assemble_and_solve, operator_images, probe_kernel
from .errors import (CallableOutputError, InconsistentEquationWarning, InvalidOrderError,
                     ResidualWarning, SideConditionError, call_checked, check_finite_real,
                     check_order)
from .exponents import Exponents, check_coefficients, check_end, exponents_of
from .intervals import UNIT, Interval, check_intervals, per_interval, split_breaks
from .jacobi import jacobi_norms_cached, jacobi_vandermonde, plateau_start
from .solution import IntervalSolution, Solution
from .quadrature import composite_rule
from .unknowns import _EXTRA_PER_PIECE, IntervalUnknown

__all__ = ["solve", "Solution", "Exponents", "dominant_functionals", "Functionals",
           "FunctionalsRule", "N_MAX"]

#: Largest number of Jacobi coefficients per interval that :func:`solve`,
#: :func:`dominant_functionals` and :class:`FunctionalsRule` accept (a larger ``n`` raises
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
def _check_callable(name, fn, what):
    if not callable(fn):
        raise CallableOutputError(f"{name} must be a {what}, got {type(fn).__name__}")


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


def _check_residual(f_checks, unknowns, pieces, at_checks, fscale):
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
            "kernel is not smooth", ResidualWarning, stacklevel=3)


# --------------------------------------------------------------------------
# the solver
# --------------------------------------------------------------------------
def solve(f, *, a, b, n, left, right, kernel=None, total=None, breaks=(), intervals=None,
          check_residual=True):
    """Solve a psi + (b/pi) PV int_L psi/(t-s) dt + int_L k(s,t) psi(t) dt = f(s) on L.

    Parameters
    ----------
    f : callable
        Vectorised right-hand side f(s) (s in real coordinates).
    a, b : float
        Coefficients; b != 0.  cot(pi alpha0) = -a/b fixes the exponents.
    n : int or sequence of int
        Number of Jacobi coefficients of phi per interval (>= 2 where kappa = 1), at most
        ``N_MAX``.
    left, right : {"bounded", "singular"} or a sequence of them
        Behaviour of psi at the left and right end of each interval.
    kernel : callable, optional
        Kernel k(s, t), vectorised over two arrays of equal shape, bounded on L x L.
    total : float or sequence, optional
        int psi over each interval with kappa = 1 (both ends singular); None (or absent)
        for the others.
    breaks : sequence of float, optional
        Points strictly inside L where f or one of its derivatives jumps.
    intervals : sequence of (c, d), optional
        L as disjoint ascending intervals; default the single interval [-1, 1].  With it,
        the per-interval attributes of the :class:`Solution` are tuples.
    check_residual : bool
        Check the equation between the collocation nodes and warn (``ResidualWarning``)
        where it is not met (several intervals or a kernel, without breaks: elsewhere the
        collocation is exact by construction).  False skips the check and its cost (f at 7
        more points per interval; ~15 % of a two-interval solve at n = 16), for a caller
        that solves many trial problems and ignores the warning.

    Returns
    -------
    Solution

    Raises
    ------
    InvalidCoefficientError
        a or b not finite, or b = 0.
    InvalidEndConditionError
        ``left`` or ``right`` not "bounded" or "singular".
    InvalidOrderError
        n not an integer, n < 1 (n < 2 where kappa = 1), or n > ``N_MAX``.
    SideConditionError
        ``total`` missing where kappa = 1, given elsewhere, or not finite.
    InvalidBreakpointError
        A break not strictly inside an interval.
    InvalidIntervalError
        ``intervals`` not finite, ascending and disjoint.
    PerIntervalArgumentError
        A per-interval argument whose length does not match ``intervals``.
    KernelSingularityError
        ``kernel`` unbounded next to an end.
    CallableOutputError
        ``f`` or ``kernel`` not callable, not vectorised, complex or not finite.

    Warns
    -----
    InconsistentEquationWarning
        Index -1 on an interval and f violates its solvability condition.
    ResidualWarning
        The equation is not satisfied between the nodes (unresolved f or kernel).

    Notes
    -----
    Per interval, psi = w phi with w = (1-u)^alpha (1+u)^beta, the exponents from
    cot(pi alpha0) = -a/b and the end choices (:func:`sie_exponents`), and phi a Jacobi
    series P_k^{(alpha,beta)}; the equation is collocated at the roots of
    P_{n-kappa}^{(-alpha,-beta)}, where the dominant operator maps the basis exactly
    (Erdogan, Gupta & Cook 1973; Krenk 1975).  Spectral convergence for analytic f and k.

    References
    ----------
    F. Erdogan, G. D. Gupta and T. S. Cook, "Numerical solution of singular integral
    equations", in Methods of Analysis and Solutions of Crack Problems, G. C. Sih (ed.),
    Noordhoff (1973), ch. 7.
    S. Krenk, "On quadrature formulas for singular integral equations of the first and the
    second kind", Quart. Appl. Math. 33 (1975) 225.
    N. I. Muskhelishvili, Singular Integral Equations, Noordhoff (1953), ch. 10 (index,
    side conditions and solvability).

    Examples
    --------
    (1/pi) PV int sqrt(1 - t^2) / (t - s) dt = -s on (-1, 1), so with a = 0, b = 1,
    f(s) = -s and both ends bounded (index -1) the solution is psi(s) = sqrt(1 - s^2):

    >>> import numpy as np, sie
    >>> sol = sie.solve(lambda s: -s, a=0.0, b=1.0, n=4, left="bounded", right="bounded")
    >>> sol.alpha, sol.beta, sol.kappa
    (0.5, 0.5, -1)
    >>> [round(float(v), 12) for v in sol(np.array([0.0, 0.6]))]      # sqrt(1 - s^2)
    [1.0, 0.8]
    >>> round(sol.integral() / (np.pi / 2), 12)                        # int psi = pi/2
    1.0
    """
    a, b = check_coefficients(a, b)
    _check_callable("f", f, "vectorised callable f(s)")
    if kernel is not None:
        _check_callable("kernel", kernel, "callable k(s, t) or None")
    multi = intervals is not None
    ivs = check_intervals(intervals)
    J = len(ivs)
    lefts = [check_end("left", v) for v in per_interval("left", left, J)]
    rights = [check_end("right", v) for v in per_interval("right", right, J)]
    exps = [exponents_of(a, b, l, r) for l, r in zip(lefts, rights)]
    ns = [_check_n(v, e, f"[{j}]" if multi else "")
          for j, (v, e) in enumerate(zip(per_interval("n", n, J), exps))]
    totals = _check_totals(total, exps, multi)
    brs = split_breaks(breaks, ivs)

    # 1. unknowns
    unknowns = [IntervalUnknown.build(iv, e, nj, br, t, b)
                for iv, e, nj, br, t in zip(ivs, exps, ns, brs, totals)]
    if kernel is not None:
        probe_kernel(kernel, unknowns)
    # 2. right-hand side (and f at the residual check points, where there is a check)
    checked = bool(check_residual) and (J > 1 or kernel is not None) and \
        not any(br.size for br in brs)
    extra = _CHECK_POINTS if checked else _NO_POINTS
    fvals, f_checks = zip(*(u.sample(f, "f", extra) for u in unknowns))
    fhat = [u.project(v) for u, v in zip(unknowns, fvals)]
    # 3. assembly and solve
    sys_ = assemble_and_solve(unknowns, fhat, b, kernel, extra)
    # 4. result
    coeffs = []
    for u, c in zip(unknowns, sys_.coefficients):
        c = _chop_noise(c, u.exp)
        c.flags.writeable = False
        coeffs.append(c)
    pieces = [IntervalSolution(u.interval, u.exp, u.n, c, cons, None,
                               _end_rhs_factory(u, unknowns, coeffs, f, b, kernel))
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
                "taken out of f", InconsistentEquationWarning, stacklevel=2)
    if any(br.size for br in brs):
        pieces = _with_remainders(pieces, unknowns, fvals, sys_, f, a, b, kernel)
    elif checked:
        _check_residual(f_checks, unknowns, pieces, sys_.at_checks, fscale)
    return Solution(tuple(pieces), a, b, multi, sys_.matrix)


def _with_remainders(pieces, unknowns, fvals, sys_, f, a, b, kernel):
    """Attach the breaks correction (built on first use) to every piece with breaks."""
    out = []
    for i, (p, u, fs, g) in enumerate(zip(pieces, unknowns, fvals, sys_.g_hat)):
        if u.breaks.size == 0:
            out.append(p)
            continue
        out.append(IntervalSolution(p.interval, p.exp, p.n, p.coefficients, p.consistency,
                                    _remainder_factory(p, u, fs, g, pieces, unknowns, f, a, b,
                                                       kernel), p._end_rhs_factory))
    return out


def _end_rhs_factory(u, unknowns, coeffs, f, b, kernel):
    """(g, size) at the ends c, d of ``u``'s interval, on call: g = f - (coupling + kernel)
    psi and the sum of the sizes of its terms (what :meth:`IntervalSolution.endpoint_value`
    forms phi at a singular end from, and judges that form by); f at the ends themselves,
    not at m -+ h, which may round off them."""
    iv = u.interval

    def end_rhs():
        x = np.array([iv.c, iv.d])
        g = call_checked(f, "f", (x,), x.shape)
        size = np.abs(g)
        if len(unknowns) > 1 or kernel is not None:
            imgs = operator_images(x, u, unknowns, b, kernel)
            g = g - sum(img @ c for img, c in zip(imgs, coeffs))
            size = size + sum(np.abs(img) @ np.abs(c) for img, c in zip(imgs, coeffs))
        return g, size
    return end_rhs


def _remainder_factory(piece, u, fs, g_hat, pieces, unknowns, f, a, b, kernel):
    from .remainder import InversionRemainder
    iv = u.interval

    def f_local(x):
        return f(iv.real(x))

    def coupling_and_kernel(x):
        imgs = operator_images(iv.real(x), u, unknowns, b, kernel)
        return sum(img @ pj.coefficients for img, pj in zip(imgs, pieces))

    other = None if len(unknowns) == 1 and kernel is None else coupling_and_kernel
    return lambda: InversionRemainder.build(piece, a, b, f_local, other, u.breaks, u.s, u.ws,
                                            fs, g_hat)


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

    Returned by :func:`dominant_functionals` and :class:`FunctionalsRule`.

    Attributes
    ----------
    integral : float or None
        int psi for kappa <= 0 (mu_0 c_0); None for kappa = 1 (it is the side condition).
    consistency : float or None
        kappa = -1: the solvability residual (as ``Solution.consistency``); None otherwise.
    alpha, beta : float
        Exponents of psi at the right and left end.
    kappa : int
        Index -(alpha + beta).

    References
    ----------
    As for :func:`dominant_functionals`.

    Examples
    --------
    >>> import sie
    >>> fn = sie.dominant_functionals(lambda s: -s, a=0.0, b=1.0, n=4,
    ...                               left="bounded", right="bounded")
    >>> type(fn).__name__, fn.kappa, round(fn.integral, 12), abs(fn.consistency) < 1e-14
    ('Functionals', -1, 1.570796326795, True)
    """
    integral: float | None
    consistency: float | None
    alpha: float
    beta: float
    kappa: int


def _unit_unknown(a, b, n, left, right, breaks, count=None):
    """Validated exponents and, for index <= 0, the one-interval unknown on [-1, 1] whose
    rule gives the projections on P_m, m < count (default: those the functionals need);
    None for index 1 (nothing to project)."""
    a, b = check_coefficients(a, b)
    e = exponents_of(a, b, check_end("left", left), check_end("right", right))
    n = _check_n(n, e, "")
    br = split_breaks(breaks, check_intervals(None))[0]
    if e.kappa == 1:
        return e, None
    count = (1 if e.kappa == 0 else 2) if count is None else count
    return e, IntervalUnknown.build(Interval(-1.0, 1.0), e, n, br, None, b, count=count)


def dominant_functionals(f, *, a, b, n, left, right, breaks=()):
    """int psi and the solvability residual of the dominant equation, without solving it.

    For a psi + (b/pi) PV int psi/(t-s) dt = f on [-1, 1] (no kernel), exactly as
    :func:`solve` (same rule, same n) would return them, at the cost of one Gauss sum:
    int psi = mu_0 c_0 with c_0 = f_0/lambda (kappa = 0) or f_1/lambda (kappa = -1), and
    the residual is f_0 (kappa = -1), f_m the projections of f on P_m^{(-alpha,-beta)}.
    For searches over the interval (free contact ends), where the full solution is only
    needed at the end.

    Parameters
    ----------
    f : callable
        Vectorised right-hand side f(s).
    a, b : float
        Coefficients; b != 0.
    n : int
        Number of Jacobi coefficients (as for :func:`solve`), at most ``N_MAX``.
    left, right : {"bounded", "singular"}
        Behaviour of psi at each end.
    breaks : sequence of float, optional
        Points strictly inside (-1, 1) where f or a derivative jumps.

    Returns
    -------
    Functionals
        ``integral`` is None and ``consistency`` None for kappa = 1 (both ends singular:
        int psi is then the side condition).

    Raises
    ------
    InvalidCoefficientError, InvalidEndConditionError, InvalidOrderError,
    InvalidBreakpointError, CallableOutputError
        As for :func:`solve`.

    References
    ----------
    N. I. Muskhelishvili, Singular Integral Equations (1953), ch. 10 (solvability for index
    -1); Zhou, Lee & Jang, Arch. Mech. 66 (2014), eq. (5.40) (the condition that fixes the
    free ends of a cylindrical punch).

    Examples
    --------
    psi = sqrt(1 - s^2) solves (1/pi) PV int psi/(t - s) dt = -s: int psi = pi/2, and the
    equation is solvable (residual 0); f = 1 is not (residual 1, the weighted mean of f):

    >>> import numpy as np, sie
    >>> fn = sie.dominant_functionals(lambda s: -s, a=0.0, b=1.0, n=4,
    ...                               left="bounded", right="bounded")
    >>> round(fn.integral / (np.pi / 2), 12), abs(fn.consistency) < 1e-14
    (1.0, True)
    >>> fn = sie.dominant_functionals(np.ones_like, a=0.0, b=1.0, n=4,
    ...                               left="bounded", right="bounded")
    >>> round(fn.consistency, 12)
    1.0
    """
    _check_callable("f", f, "vectorised callable f(s)")
    e, u = _unit_unknown(a, b, n, left, right, breaks)
    if u is None:
        return Functionals(None, None, e.alpha, e.beta, 1)
    fhat = u.project(u.sample(f, "f"))
    scale = u.mu0 / u.lam
    if e.kappa == 0:
        return Functionals(float(scale * fhat[0]), None, e.alpha, e.beta, 0)
    return Functionals(float(scale * fhat[1]), float(fhat[0]), e.alpha, e.beta, -1)


class FunctionalsRule:
    """:func:`dominant_functionals` prepared once for fixed a, b, n and ends.

    The Gauss rule, the norms and the end correction are built here; each call then costs
    one evaluation of f at the fixed nodes and two dot products.  For searches that try
    many right-hand sides of one equation (free contact ends).  ``rule(f)`` returns the same
    :class:`Functionals` as ``dominant_functionals(f, a=..., b=..., n=..., left=..., right=...)``
    and ``rule(f, breaks=br)`` those of ``dominant_functionals(..., breaks=br)`` (the
    composite rule of the pieces between the breaks, which move with the interval in a
    search, is formed per call from cached Gauss-Jacobi rules).

    Parameters
    ----------
    a, b : float
        Coefficients; b != 0.
    n : int
        Number of Jacobi coefficients, at most ``N_MAX``.
    left, right : {"bounded", "singular"}
        Behaviour of psi at each end.

    Attributes
    ----------
    a, b : float
    n : int
    exponents : Exponents
        The exponents of the end choices (:func:`sie_exponents`).
    kappa : int
        The index.

    Raises
    ------
    InvalidCoefficientError, InvalidEndConditionError, InvalidOrderError
        As for :func:`solve`; a call raises :class:`CallableOutputError` for an f that is
        not a vectorised real callable.

    References
    ----------
    As for :func:`dominant_functionals`.

    Examples
    --------
    >>> import numpy as np, sie
    >>> rule = sie.FunctionalsRule(a=0.0, b=1.0, n=4, left="bounded", right="bounded")
    >>> fn = rule(lambda s: -s)                      # psi = sqrt(1 - s^2)
    >>> round(fn.integral / (np.pi / 2), 12), abs(fn.consistency) < 1e-14
    (1.0, True)
    """

    def __init__(self, *, a, b, n, left, right):
        e, u = _unit_unknown(a, b, n, left, right, (), count=2)
        self.a, self.b, self.n, self.exponents = float(a), float(b), int(n), e
        self.kappa = e.kappa
        if u is None:
            return
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

    def __call__(self, f, breaks=()) -> Functionals:
        e = self.exponents
        if self.kappa == 1:
            return Functionals(None, None, e.alpha, e.beta, 1)
        _check_callable("f", f, "vectorised callable f(s)")
        if np.size(breaks):
            return self._with_breaks(f, split_breaks(breaks, UNIT)[0])
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
        x, w = composite_rule(self._q_pieces, -e.alpha, -e.beta, br)
        fs = call_checked(f, "f", (x,), x.shape)
        wf = w * fs
        f0 = float(np.sum(wf)) / self._h[0]
        if self.kappa == 0:
            return Functionals(self._scale * f0, None, e.alpha, e.beta, 0)
        f1 = float(wf @ _p1(e, x)) / self._h[1]
        return Functionals(self._scale * f1, f0, e.alpha, e.beta, -1)


def _p1(e, x):
    """P_1^{(-alpha,-beta)}(x), the second function the projections are taken on."""
    return (1.0 - e.alpha) + 0.5 * (2.0 - e.alpha - e.beta) * (x - 1.0)
