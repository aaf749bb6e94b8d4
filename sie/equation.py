"""The equation object: a Cauchy singular integral equation of the second kind, validated once.

    a_j psi(s) + (b_j/pi) PV int_L psi(t)/(t - s) dt + int_L k_j(s, t) psi(t) dt = f(s),
    s in L_j,   L = L_1 U ... U L_J,

an immutable :class:`Equation` made of :class:`Block` s: block j is the pair (the unknown
psi_j = psi on L_j, the equation collocated on L_j), with its own coefficients a_j, b_j, its
own kernel row k_j and its end choices.  Everything the solver needs that does not depend on
the right-hand side or the number of coefficients is checked and computed here once (the
coefficients, the end exponents, the intervals); :meth:`Equation.solve` and
:meth:`Equation.functionals` then take f and n, and :meth:`Equation.on` moves the equation to
other intervals (a search over free ends) without checking the rest again.

A leading case axis: intervals of shape (B, 1, 2) make B independent one-interval equations
with their own a_i, b_i (shape (B,)) and shared end choices, solved stage by stage for all
B at once (:mod:`sie.batch`): a parameter sweep, where the Python around a solve of a few
coefficients costs more than its arithmetic.

References: Erdogan, Gupta & Cook (1973), ch. 7; Krenk, Quart. Appl. Math. 33 (1975) 225;
Muskhelishvili, Singular Integral Equations (1953), ch. 10.
"""
from __future__ import annotations

import functools
import math

import numpy as np

from .auto import check_tol, solve_auto
from .errors import (CallableOutputError, InvalidCoefficientError, InvalidEndConditionError,
                     InvalidIntervalError, InvalidOrderError, PerIntervalArgumentError,
                     SideConditionError, UnsupportedEquationError, real_array)
from .exponents import check_coefficients, check_end, exponents_of
from .fixed_ends import (_N_MAX as FIXED_N_MAX, check_further, explicit_exponents, is_explicit,
                         solve_fixed)
from .block import Block
from .intervals import Interval, check_intervals, per_interval, split_breaks
from .batch import CaseRules
from .solver import block_functionals, solve_blocks
from .systems import solve_system, solve_system_auto
from .junctions import solve_junctions

__all__ = ["Equation", "solve"]


def _check_callable(name, fn, what):
    if not callable(fn):
        raise CallableOutputError(f"{name} must be a {what}, got {type(fn).__name__}")


def _kernels(kernel, J):
    """One kernel row per block: a callable (or None) shared by all, or a sequence of J."""
    if kernel is None or callable(kernel):
        return [kernel] * J
    if isinstance(kernel, (str, bytes)) or np.ndim(kernel) == 0:
        _check_callable("kernel", kernel, "callable k(s, t), a sequence of them (one per "
                        "interval), or None")
    rows = per_interval("kernel", kernel, J)
    for j, k in enumerate(rows):
        if k is not None:
            _check_callable(f"kernel[{j}]", k, "callable k(s, t) or None")
    return rows


class Equation:
    """a_j psi + (b_j/pi) PV int_L psi/(t - s) dt + int_L k_j(s, t) psi dt = f on L_j,
    validated once (immutable).

    Parameters
    ----------
    a, b : float or sequence of float
        The coefficients, shared by all intervals or one per interval (b != 0 and abs(b/a)
        resolvable in double precision: see :func:`sie.sie_exponents`); with a case axis,
        one per case (shape (B,)) or shared.
    left, right : {"bounded", "singular"}, float, tuple, or a sequence of them
        psi's behaviour at the left and the right end of each interval (shared by the
        cases of a case axis), or an explicit exponent in (-1, 1) (one interval, no case
        axis: the end of a kernel with a fixed singularity there; :mod:`sie.fixed_ends`),
        or a tuple ``(e0, g1, g2, ...)`` of an explicit exponent and further exponents of
        psi's expansion at that end (real or complex, Re g > e0; one interval: the basis
        carries them, :func:`sie.end_exponents`).
    intervals : array_like, optional
        L as J disjoint ascending (c, d) pairs, shape (J, 2); default the single interval
        [-1, 1].  With it, the per-interval attributes of a :class:`sie.Solution` are
        tuples.  Shape (B, 1, 2): a case axis of B one-interval equations.
    kernel : callable, sequence of callables, or None
        k(s, t), vectorised over two arrays of equal shape and bounded on L x L; one per
        interval (the kernel of the rows collocated there; None for none) or one for all.

    Attributes
    ----------
    blocks : tuple of Block
        The (unknown, interval) pairs, left to right (one-interval cases: those of case 0).
    cases : int or None
        B with a case axis, else None.
    intervals : ndarray
        Shape (J, 2), or (B, 1, 2) with a case axis.
    a, b : ndarray
        Shape (J,), or (B,) with a case axis.
    kappa : tuple of int
        The index of each block (shared by the cases).

    Raises
    ------
    InvalidCoefficientError
        a or b not finite, b = 0, or abs(b/a) not resolvable; shapes that do not match.
    InvalidEndConditionError
        ``left`` or ``right`` not "bounded", "singular", an exponent in (-1, 1) or a tuple
        (e0, g1, ...) of one and valid further exponents (finite, Re g > e0, none repeated,
        a complex one implying its conjugate).
    InvalidIntervalError
        ``intervals`` not finite, ascending and disjoint (each case's interval: c < d).
    PerIntervalArgumentError
        A per-interval argument whose length does not match the intervals.
    CallableOutputError
        ``kernel`` not callable.
    UnsupportedEquationError
        A case axis with a kernel or several intervals per case.

    Notes
    -----
    Per interval, psi = w phi with w = (1-u)^alpha (1+u)^beta, the exponents from
    cot(pi alpha0) = -a_j/b_j and the end choices, phi a Jacobi series, and the equation
    collocated at the roots of P_{n-kappa}^{(-alpha,-beta)}, where the dominant operator
    maps the basis exactly (Erdogan, Gupta & Cook 1973; Krenk 1975).  The intervals couple
    through the exact Cauchy transforms of the Jacobi basis (:mod:`sie.cauchy`).

    References
    ----------
    F. Erdogan, G. D. Gupta and T. S. Cook, "Numerical solution of singular integral
    equations", in Methods of Analysis and Solutions of Crack Problems, G. C. Sih (ed.),
    Noordhoff (1973), ch. 7.  N. I. Muskhelishvili, Singular Integral Equations (1953).

    Examples
    --------
    (1/pi) PV int sqrt(1 - t^2) / (t - s) dt = -s on (-1, 1): with a = 0, b = 1 and both
    ends bounded (index -1) f = -s gives psi = sqrt(1 - s^2):

    >>> import numpy as np, sie
    >>> eq = sie.Equation(a=0.0, b=1.0, left="bounded", right="bounded")
    >>> sol = eq.solve(lambda s: -s, n=4)
    >>> [round(float(v), 12) for v in sol(np.array([0.0, 0.6]))]
    [1.0, 0.8]
    >>> fn = eq.functionals(lambda s: -s, n=4)        # int psi = pi/2, solvable
    >>> round(fn.integral / (np.pi / 2), 12), abs(fn.consistency) < 1e-14
    (1.0, True)

    The same f on the intervals [-R, R], R = 1, 2, as a case axis: psi = sqrt(R^2 - s^2):

    >>> cases = sie.Equation(a=0.0, b=1.0, left="bounded", right="bounded",
    ...                      intervals=[[(-1.0, 1.0)], [(-2.0, 2.0)]])
    >>> cases.cases, np.round(cases.solve(lambda s: -s, n=4).integral() / np.pi, 12).tolist()
    (2, [0.5, 2.0])
    """

    __slots__ = ("_blocks", "cases", "intervals", "a", "b", "kappa", "_multi", "_ends",
                 "_exps", "_prepared", "_further")

    def __init__(self, *, a, b, left, right, intervals=None, kernel=None):
        iv = None if intervals is None else _as_interval_array(intervals)
        if iv is not None:
            self._init_cases(a, b, left, right, iv, kernel)
            return
        ivs = check_intervals(intervals)
        J = len(ivs)
        A = [check_coefficients(ai, bi) for ai, bi in
             zip(per_interval("a", a, J), per_interval("b", b, J))]
        # (e0, g1, ...) at one interval: an explicit exponent and further ones
        further = [(), ()]
        if J == 1:
            if _is_expansion(left):
                left, further[0] = check_further("left", left)
            if _is_expansion(right):
                right, further[1] = check_further("right", right)
        lefts = [check_end("left", v, True) for v in per_interval("left", left, J)]
        rights = [check_end("right", v, True) for v in per_interval("right", right, J)]
        kernels = _kernels(kernel, J)
        explicit = any(is_explicit(v) for v in lefts + rights)
        if explicit and J != 1:
            raise UnsupportedEquationError(
                f"an explicit end exponent (left=/right= a float) is available on one "
                f"interval; got {J} intervals")
        exps = explicit_exponents if explicit else exponents_of
        blocks = tuple(Block(iv_j, aj, bj, l, r, exps(aj, bj, l, r), k)
                       for iv_j, (aj, bj), l, r, k in zip(ivs, A, lefts, rights, kernels))
        self._set(blocks, intervals is not None, tuple(further))

    def _set(self, blocks, multi, further=((), ())):
        """One equation (no case axis) of the given blocks; ``further``: the further
        exponents at the left and the right end of a one-interval explicit-exponent
        equation (:func:`sie.fixed_ends.check_further`)."""
        s = object.__setattr__
        s(self, "_blocks", blocks)
        s(self, "_further", further)
        s(self, "cases", None)
        s(self, "_multi", multi)
        s(self, "intervals", np.array([(b.interval.c, b.interval.d) for b in blocks]))
        s(self, "a", np.array([b.a for b in blocks]))
        s(self, "b", np.array([b.b for b in blocks]))
        s(self, "kappa", tuple(b.kappa for b in blocks))
        s(self, "_ends", tuple((b.left, b.right) for b in blocks))
        s(self, "_exps", tuple(b.exponents for b in blocks))
        s(self, "_prepared", {})           # a case axis' rules; one equation has none
        for name in ("intervals", "a", "b"):
            getattr(self, name).flags.writeable = False

    def _init_cases(self, a, b, left, right, iv, kernel):
        B, J = iv.shape[:2]
        if J != 1 or kernel is not None:
            raise UnsupportedEquationError(
                f"a case axis (intervals of shape (B, J, 2)) holds one-interval equations "
                f"without a kernel; got J = {J}{' and a kernel' if kernel is not None else ''} "
                f"(solve such equations one by one)")
        if B == 0:
            raise InvalidCoefficientError("a case axis must hold at least one equation, got none")
        _check_case_intervals(iv)
        A, Bv = _case_coefficients(a, b, B)
        if is_explicit(left) or is_explicit(right) or _is_expansion(left) or \
                _is_expansion(right):
            raise UnsupportedEquationError(
                "a case axis takes the end choices \"bounded\" / \"singular\"; an explicit end "
                "exponent is available for one equation (solve the cases one by one)")
        left, right = check_end("left", _one(left, "left")), check_end("right", _one(right, "right"))
        exps = tuple(exponents_of(ai, bi, left, right) for ai, bi in zip(A.tolist(), Bv.tolist()))
        A.flags.writeable = Bv.flags.writeable = False
        self._set_cases(iv, A, Bv, left, right, exps, None)

    def _set_cases(self, iv, A, Bv, left, right, exps, prepared):
        """A case axis: ``iv`` copied, A and Bv (read-only arrays) and the rest shared."""
        s = object.__setattr__
        iv = np.array(iv, dtype=float)
        iv.flags.writeable = False
        s(self, "_blocks", None)               # built when asked for (:attr:`blocks`)
        s(self, "cases", int(iv.shape[0]))
        s(self, "_multi", True)
        s(self, "intervals", iv)
        s(self, "a", A)
        s(self, "b", Bv)
        s(self, "kappa", (exps[0].kappa,))
        s(self, "_ends", ((left, right),))
        s(self, "_exps", exps)
        s(self, "_prepared", {} if prepared is None else prepared)
        s(self, "_further", ((), ()))

    @property
    def blocks(self) -> tuple:
        """The blocks, left to right (with a case axis: the one block of case 0)."""
        if self._blocks is None:
            (l, r), = self._ends
            iv = self.intervals[0, 0]
            object.__setattr__(self, "_blocks", (Block(
                Interval(float(iv[0]), float(iv[1])), float(self.a[0]), float(self.b[0]), l, r,
                self._exps[0]),))
        return self._blocks

    def __setattr__(self, name, value):
        raise AttributeError(f"sie.Equation is immutable (tried to set {name!r})")

    def __getstate__(self):
        """Its fields (the prepared rules are rebuilt where it is used): for pickle."""
        return {name: getattr(self, name) for name in self.__slots__ if name != "_prepared"}

    def __setstate__(self, state):
        for name, value in state.items():
            object.__setattr__(self, name, value)
        object.__setattr__(self, "_prepared", {})

    def __repr__(self):
        if self.cases is not None:
            l, r = self._ends[0]
            return f"Equation({self.cases} cases, left={l!r}, right={r!r})"
        parts = ", ".join(f"[{b.interval.c:g}, {b.interval.d:g}] a={b.a:g} b={b.b:g} "
                          f"{b.left}/{b.right}" for b in self.blocks)
        k = ", kernel" if any(b.kernel is not None for b in self.blocks) else ""
        return f"Equation({parts}{k})"

    # -- the same equation elsewhere ---------------------------------------------------------
    def on(self, intervals) -> "Equation":
        """The same coefficients, end choices and kernel on other intervals of the same
        count (or, with a case axis, one interval per case: shape (B, 1, 2)); only the
        intervals are checked.  For searches over the ends of the intervals."""
        out = object.__new__(Equation)
        if self.cases is not None:
            iv = _as_interval_array(intervals)
            if iv is None or iv.shape != (self.cases, 1, 2):
                raise InvalidIntervalError(f"intervals must have the case axis' shape "
                                           f"({self.cases}, 1, 2); got {np.shape(intervals)}")
            _check_case_intervals(iv)
            (l, r), = self._ends
            out._set_cases(iv, self.a, self.b, l, r, self._exps, self._prepared)
            return out
        ivs = check_intervals(intervals)
        if len(ivs) != len(self.blocks):
            raise PerIntervalArgumentError(f"intervals must hold {len(self.blocks)} intervals "
                                           f"(as the equation's blocks), got {len(ivs)}")
        blocks = tuple(Block(iv, b.a, b.b, b.left, b.right, b.exponents, b.kernel)
                       for iv, b in zip(ivs, self.blocks))
        out._set(blocks, True, self._further)
        return out

    def take(self, indices) -> "Equation":
        """The cases at ``indices`` (in that order) of an equation with a case axis, their
        prepared rules kept."""
        if self.cases is None:
            raise UnsupportedEquationError("take() selects cases: this equation has no case axis")
        idx = np.asarray(indices, dtype=int).reshape(-1)
        out = object.__new__(Equation)
        (l, r), = self._ends
        prepared = {n: rules.take(idx) for n, rules in self._prepared.items()}
        A, Bv = self.a[idx], self.b[idx]
        A.flags.writeable = Bv.flags.writeable = False
        out._set_cases(self.intervals[idx], A, Bv, l, r,
                       tuple(self._exps[i] for i in idx.tolist()), prepared)
        return out

    @property
    def _explicit(self) -> bool:
        """Whether an end has an explicit exponent (:mod:`sie.fixed_ends`)."""
        return any(is_explicit(v) for ends in self._ends for v in ends)

    @property
    def exponents(self) -> tuple:
        """The Exponents of each block (of each case, with a case axis)."""
        return self._exps

    # -- solving ------------------------------------------------------------------------------
    def solve(self, f, *, n, total=None, breaks=(), check_residual=True, tol=None):
        """psi for the right-hand side ``f`` with ``n`` Jacobi coefficients per interval.

        Parameters
        ----------
        f : callable
            Vectorised right-hand side f(s), s in real coordinates (with a case axis,
            called once with the nodes of all B equations).
        n : int, sequence of int, or "auto"
            Jacobi coefficients of phi per interval (>= 2 where kappa = 1), at most
            ``sie.N_MAX``; one shared n with a case axis.  "auto": grown per interval from
            16 by doubling until the series' tail is below ``tol`` (:mod:`sie.auto`; not
            with a case axis); the solution's ``n`` reports what was used.
        total : float or sequence, optional
            int psi over each interval of index 1 (both ends singular), None for the
            others; with a case axis, one per case (or shared).
        breaks : sequence of float, optional
            Points strictly inside L where f or one of its derivatives jumps (not with a
            case axis).
        check_residual : bool
            Check the equation between the collocation nodes and warn
            (``ResidualWarning``) where it is not met (several intervals or a kernel,
            without breaks: elsewhere the collocation is exact by construction).
        tol : float, optional
            With ``n="auto"``: the relative size of the series' tail that counts as
            resolved (default 1e-13; in [1e-15, 1e-2]).

        Returns
        -------
        Solution, or SolutionBatch with a case axis

        Raises
        ------
        InvalidOrderError, SideConditionError, InvalidBreakpointError,
        PerIntervalArgumentError, KernelSingularityError, CallableOutputError
            As for :func:`sie.solve`.
        UnsupportedEquationError
            ``breaks`` or ``n="auto"`` with a case axis.

        Warns
        -----
        ResolutionWarning
            ``n="auto"`` reached its largest n without resolving an interval.
        """
        if isinstance(n, str) or tol is not None:
            return self._solve_auto(f, n, total, breaks, check_residual, tol)
        return self._solve(f, n, total, breaks, check_residual, stacklevel=4)

    def _solve_auto(self, f, n, total, breaks, check_residual, tol, stacklevel=4):
        """:meth:`solve` with ``n="auto"`` (:func:`sie.auto.solve_auto`)."""
        if not (isinstance(n, str) and n == "auto"):
            if isinstance(n, str):
                raise InvalidOrderError(f'n must be an integer, one per interval, or "auto", '
                                        f"got {n!r}")
            raise InvalidOrderError(f'tol is for n="auto" only (the tolerance n is chosen '
                                    f"for), got n = {n!r} with tol = {tol!r}")
        if self.cases is not None:
            raise UnsupportedEquationError('n="auto" chooses n per equation: solve a case '
                                           "axis at a given n")
        tol = check_tol(tol)
        _check_callable("f", f, "vectorised callable f(s)")
        ivs = tuple(blk.interval for blk in self.blocks)
        brs = split_breaks(breaks, ivs)
        one = self._explicit or not self._multi       # the paths that take one int n
        return solve_auto(lambda ns: self._solve(f, ns[0] if one else ns, total, breaks,
                                                 check_residual, stacklevel + 3),
                          len(ivs), [br.size > 0 for br in brs], tol, stacklevel,
                          n_max=FIXED_N_MAX if self._explicit else None)

    def _solve(self, f, n, total, breaks, check_residual, stacklevel):
        """:meth:`solve`, its warnings ``stacklevel`` frames above solve_blocks' caller."""
        _check_callable("f", f, "vectorised callable f(s)")
        if self.cases is not None:
            if np.size(breaks):
                raise UnsupportedEquationError("a case axis takes no breaks (solve an equation "
                                               "with breaks on its own)")
            return self._rules(n).solve(f, self.intervals[:, 0, :], _case_total(total, self))
        if self._explicit:
            return solve_fixed(self.blocks[0], f, n, total, breaks, check_residual,
                               self._multi, stacklevel, self._further)
        return solve_blocks(self.blocks, f, n, total, breaks, check_residual, self._multi,
                            stacklevel)

    def functionals(self, f, *, n, breaks=()):
        """int psi and the solvability residual of the equation, without solving it.

        For one interval without a kernel, exactly as :meth:`solve` (same rule, same n)
        would return them, at the cost of one Gauss sum: int psi = h mu_0 c_0 with
        c_0 = f_0/lambda (kappa = 0) or f_1/lambda (kappa = -1), and the residual is f_0
        (kappa = -1), f_m the projections of f on P_m^{(-alpha,-beta)} (h the half-width).
        For searches over the interval (free contact ends), where the full solution is only
        needed at the end.

        Parameters
        ----------
        f : callable
            Vectorised right-hand side f(s), s in real coordinates.
        n : int
            Jacobi coefficients (as for :meth:`solve`).
        breaks : sequence of float, optional
            Points strictly inside the interval where f or a derivative jumps (not with a
            case axis).

        Returns
        -------
        Functionals, or FunctionalsBatch with a case axis
            ``integral`` and ``consistency`` are None for kappa = 1 (int psi is then the
            side condition).

        Raises
        ------
        UnsupportedEquationError
            Several intervals or a kernel; ``breaks`` with a case axis.
        InvalidOrderError, InvalidBreakpointError, CallableOutputError
            As for :meth:`solve`.

        References
        ----------
        N. I. Muskhelishvili, Singular Integral Equations (1953), ch. 10 (solvability for
        index -1); Zhou, Lee & Jang, Arch. Mech. 66 (2014), eq. (5.40) (the condition that
        fixes the free ends of a cylindrical punch).
        """
        _check_callable("f", f, "vectorised callable f(s)")
        if self.cases is not None:
            if np.size(breaks):
                raise UnsupportedEquationError("a case axis takes no breaks")
            return self._rules(n).functionals(f, self.intervals[:, 0, :])
        if self._explicit:
            raise UnsupportedEquationError("functionals need the end choices \"bounded\" / "
                                           "\"singular\" (the dominant equation's Gauss sum); "
                                           "with an explicit end exponent use solve()")
        if len(self.blocks) != 1 or self.blocks[0].kernel is not None:
            raise UnsupportedEquationError(
                f"functionals need one interval without a kernel (the dominant equation's "
                f"Gauss sum); this equation has {len(self.blocks)} interval(s)"
                f"{' and a kernel' if self.blocks[0].kernel is not None else ''}: use solve()")
        return block_functionals(self.blocks[0], f, n, breaks)

    def _rules(self, n):
        """The case axis' projection rules for n coefficients, prepared once per n."""
        rules = self._prepared.get(n)
        if rules is None:
            (l, r), = self._ends
            if self.cases == 1:
                # one case: the rules of its coefficients, ends and n, kept between
                # equations (as one block's functionals rule is): a solve repeated with the
                # same coefficients (a load sweep) prepares them once
                rules = _one_case_rules(float(self.a[0]), float(self.b[0]), n, l, r)
            else:
                rules = CaseRules(self.a, self.b, n, l, r, self._exps)
            self._prepared[int(n) if isinstance(n, (int, np.integer)) else n] = rules
        return rules


def _is_expansion(v) -> bool:
    """Whether an end condition is given as (e0, g1, ...): a tuple of two or more entries
    whose first is a real number (an explicit exponent and further ones; a one-interval
    equation: a per-interval sequence there has one entry)."""
    return isinstance(v, tuple) and len(v) >= 2 and is_explicit(v[0])


@functools.lru_cache(maxsize=64)
def _one_case_rules(a, b, n, left, right):
    """The CaseRules of one case (read-only arrays: shared by the equations that ask)."""
    rules = CaseRules(np.array([a]), np.array([b]), n, left, right,
                      (exponents_of(a, b, left, right),))
    rules.freeze()
    return rules


def _as_interval_array(intervals):
    """``intervals`` as a float array when it has a case axis (3-D: numbers only, not
    text), else None (one equation: :func:`sie.intervals.check_intervals` checks it)."""
    if isinstance(intervals, np.ndarray) and intervals.dtype == float:
        iv = intervals
        if iv.ndim != 3:
            return None
    else:
        try:
            ndim = np.ndim(intervals)
        except ValueError:               # ragged
            return None
        if ndim != 3:
            return None
        iv = real_array("intervals", intervals, InvalidIntervalError)
    if iv.shape[-1] != 2:
        raise InvalidIntervalError(f"intervals with a case axis must have shape (B, 1, 2); "
                                   f"got {iv.shape}")
    return iv


def _check_case_intervals(iv):
    """InvalidIntervalError unless every case's interval (c, d) of ``iv`` (shape (B, 1, 2))
    is finite with c < d."""
    if iv.shape[0] == 1:                 # one case (a single solve): Python floats
        c, d = iv[0, 0].tolist()
        if c < d and math.isfinite(c) and math.isfinite(d):
            return
    elif (iv[:, 0, 0] < iv[:, 0, 1]).all() and np.isfinite(iv).all():
        return
    good = np.isfinite(iv).all(axis=(1, 2)) & (iv[:, 0, 0] < iv[:, 0, 1])
    k = int(np.flatnonzero(~good)[0])
    raise InvalidIntervalError(f"intervals[{k}] must be a finite (c, d) with c < d, got "
                               f"{tuple(iv[k, 0].tolist())}")


def _one(v, name):
    if isinstance(v, str) or v is None:
        return v
    raise PerIntervalArgumentError(f"{name} must be one end choice shared by the cases of a "
                                   f"case axis, got {v!r}")


def _case_coefficients(a, b, B):
    """a and b of a case axis as float arrays of length B (a scalar is shared), each pair
    checked (:func:`sie.exponents.check_coefficients`; numbers of a float array with
    |a/b| < 1e12, far from what double precision cannot resolve, at once)."""
    if B == 1 and all(isinstance(v, np.ndarray) and v.dtype == float and v.size == 1
                      for v in (a, b)):
        av, bv = a.item(), b.item()      # one case (a single solve): Python floats
        if abs(av) < 1e12 * abs(bv) < math.inf and bv != 0.0:
            return np.array([av]), np.array([bv])
    if all(isinstance(v, float) or (isinstance(v, np.ndarray) and v.dtype == float
                                    and v.shape in ((B,), ())) for v in (a, b)):
        A, Bv = (np.full(B, v) if np.ndim(v) == 0 else np.array(v, dtype=float)
                 for v in (a, b))
        # comparisons only: no floating-point warning for inf or NaN, which fail them
        absB = np.abs(Bv)
        if ((np.abs(A) < 1e12 * absB) & (absB < np.inf) & (Bv != 0.0)).all():
            return A, Bv
    out = []
    for name, v in (("a", a), ("b", b)):
        if np.ndim(v) == 0:
            out.append([v] * B)
            continue
        vals = list(np.asarray(v, dtype=object).reshape(-1))
        if len(vals) != B:
            raise InvalidCoefficientError(
                f"{name} must be one number for all {B} cases or one per case, got shape "
                f"{np.shape(v)}")
        out.append(vals)
    pairs = [check_coefficients(ai, bi) for ai, bi in zip(*out)]
    return np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])


def _case_total(total, eq):
    """The totals of a case axis: one finite number per case for index 1 (or one shared),
    none otherwise."""
    k, B = eq.kappa[0], eq.cases
    if k != 1:
        if total is not None:
            raise SideConditionError(f"total must not be given: the index is {k} (a total is "
                                     "only for both ends singular, index 1)")
        return None
    if total is None:
        raise SideConditionError("total (= int psi) is required when both ends are singular "
                                 "(index 1)")
    t = real_array("total", total, SideConditionError).reshape(-1)
    if t.size == 1:
        t = np.full(B, t[0])
    if t.size != B or not np.all(np.isfinite(t)):
        raise SideConditionError(f"total must be one finite number per case ({B}) or one "
                                 f"for all, got {total!r}")
    return t


def _is_matrix(v):
    """An m x m coefficient (a system), as opposed to one per interval or per case."""
    if isinstance(v, np.ndarray):
        return v.ndim == 2 and v.shape[0] == v.shape[1]
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(
        isinstance(r, (list, tuple, np.ndarray)) and np.ndim(r) == 1 and len(r) == len(v)
        for r in v)


def _solve_system(f, a, b, n, left, right, kernel, total, breaks, intervals, tol):
    """:func:`solve` with m x m coefficients: :func:`sie.systems.solve_system` (one interval,
    no breaks; n given or "auto": :func:`sie.systems.solve_system_auto`)."""
    if np.size(breaks):
        raise UnsupportedEquationError(
            "a system (m x m a and b) takes no breaks yet: one interval, constant "
            "coefficients (sie.solve_system)")
    interval = (-1.0, 1.0)
    if intervals is not None:
        ivs = list(intervals)
        if len(ivs) != 1:
            raise UnsupportedEquationError(
                f"a system (m x m a and b) is solved on one interval, got {len(ivs)}")
        interval = tuple(ivs[0])
    a = np.zeros(np.shape(b)) if np.ndim(a) == 0 and a == 0 else a
    if isinstance(n, str) or tol is not None:
        if not (isinstance(n, str) and n == "auto"):
            if isinstance(n, str):
                raise InvalidOrderError(f'n must be an integer or "auto", got {n!r}')
            raise InvalidOrderError(f'tol is for n="auto" only (the tolerance n is chosen '
                                    f"for), got n = {n!r} with tol = {tol!r}")
        return solve_system_auto(f, a, b, left=left, right=right, total=total,
                                 interval=interval, kernel=kernel, tol=tol)
    return solve_system(f, a, b, n=n, left=left, right=right, total=total, interval=interval,
                        kernel=kernel)


def _touching(intervals):
    """Whether a list of intervals (c_i, d_i) has one that ends where the next begins."""
    if intervals is None or isinstance(intervals, np.ndarray) and intervals.ndim != 2:
        return False
    try:
        ivs = [tuple(iv) for iv in intervals]
    except TypeError:
        return False
    return any(len(p) == 2 and len(q) == 2 and p[1] == q[0] for p, q in zip(ivs, ivs[1:]))


def _solve_touching(f, a, b, n, left, right, kernel, total, breaks, intervals, tol,
                    check_residual):
    """:func:`solve` on intervals that touch: :func:`sie.junctions.solve_junctions`, the
    choice at each junction being the right end's of the interval before it, which must be
    the left end's of the one after it."""
    ivs = [tuple(iv) for iv in intervals]
    J = len(ivs)
    for name, given in (("kernel", kernel is not None), ("breaks", bool(np.size(breaks))),
                        ('n="auto"', isinstance(n, str) or tol is not None)):
        if given:
            raise UnsupportedEquationError(
                f"intervals that touch (coefficients that jump) take no {name} yet")
    if any(p[1] != q[0] for p, q in zip(ivs, ivs[1:])):
        raise UnsupportedEquationError(
            "intervals that touch and intervals with gaps between them in one equation are "
            "not supported yet: solve the touching ones as one equation")
    lefts, rights = (per_interval(name, v, J) for name, v in (("left", left), ("right", right)))
    junctions = []
    for i in range(J - 1):
        if rights[i] != lefts[i + 1]:
            raise InvalidEndConditionError(
                f"at the junction x = {ivs[i][1]!r} the end choices of the two intervals "
                f"must agree (one exponent on both sides): right[{i}] = {rights[i]!r}, "
                f"left[{i + 1}] = {lefts[i + 1]!r}")
        junctions.append(rights[i])
    av = a if np.ndim(a) else [a] * J
    bv = b if np.ndim(b) else [b] * J
    return solve_junctions(f, av, bv, ivs, n=n, left=lefts[0], right=rights[-1],
                           junctions=junctions, total=total, check_residual=check_residual)


def solve(f, *, a, b, n, left, right, kernel=None, total=None, breaks=(), intervals=None,
          check_residual=True, tol=None):
    """Solve a psi + (b/pi) PV int_L psi/(t-s) dt + int_L k(s,t) psi(t) dt = f(s) on L.

    The one-call form of ``sie.Equation(a=a, b=b, left=left, right=right,
    intervals=intervals, kernel=kernel).solve(f, n=n, total=total, breaks=breaks)``
    (:class:`sie.Equation`: build the equation once where it is solved for many f or n).

    Parameters
    ----------
    f : callable
        Vectorised right-hand side f(s) (s in real coordinates).
    a, b : float, sequence of float, or m x m arrays
        Coefficients, shared or one per interval; b != 0.  cot(pi alpha0) = -a/b fixes the
        exponents.  Square matrices A, B (B invertible; a scalar 0 for A = 0) make it a
        system of m equations in psi = (psi_1 .. psi_m), solved by
        :func:`sie.solve_system` (one interval, no breaks, n given or "auto"; f returns shape
        (m, len(s)), ``left``/``right`` per mode, ``total`` per mode of index 1; a kernel
        returns shape (m, m) + the shape of s).
    n : int, sequence of int, or "auto"
        Number of Jacobi coefficients of phi per interval (>= 2 where kappa = 1), at most
        ``N_MAX``.  "auto": chosen per interval, from 16 doubling until the series' tail
        (in the orthonormal scale) is at most ``tol`` times its largest term (with breaks:
        until phi stops changing by more than ``tol``), at most 4096 (:mod:`sie.auto`);
        the solution's ``n`` reports what was used.
    left, right : {"bounded", "singular"}, float, tuple, or a sequence of them
        Behaviour of psi at the left and right end of each interval, or an explicit
        exponent in (-1, 1) for an end where the kernel has a fixed singularity (one
        interval; the general collocation of :mod:`sie.fixed_ends`, which counts an
        explicit exponent below 0 as singular for the index, and returns a
        :class:`sie.fixed_ends.FixedEndSolution`; :func:`sie.end_exponent`), or a tuple
        ``(e0, g1, ...)``: that exponent and further exponents of psi's expansion there
        (the next roots of the kernel's symbol, :func:`sie.end_exponents`; complex ones
        imply their conjugates), which the basis then carries: e.g. the edge crack's
        ``left=(0.0, 1.7396 + 1.1190j)`` (to full digits) converges ~N^-10 instead of
        ~N^-4.5.
    kernel : callable or sequence of callables, optional
        Kernel k(s, t), vectorised over two arrays of equal shape, bounded on L x L (one
        per interval: the kernel of the equation collocated there).  For a system, one
        kernel returning the m x m matrix K(s, t), shape (m, m) + the shape of s.
    total : float or sequence, optional
        int psi over each interval with kappa = 1 (both ends singular); None (or absent)
        for the others.
    breaks : sequence of float, optional
        Points strictly inside L where f or one of its derivatives jumps.
    intervals : sequence of (c, d), optional
        L as disjoint ascending intervals; default the single interval [-1, 1].  Intervals
        that touch (d_i = c_(i+1)) with coefficients that jump there are solved by
        :func:`sie.solve_junctions` (the junction's exponent from both sides' a, b; its
        choice is ``right[i]``, which must equal ``left[i+1]``; no kernel or breaks yet).  With it,
        the per-interval attributes of the :class:`Solution` are tuples.  A case axis
        (shape (B, 1, 2)) returns a :class:`sie.SolutionBatch` (:class:`sie.Equation`).
    check_residual : bool
        Check the equation between the collocation nodes and warn (``ResidualWarning``)
        where it is not met (several intervals or a kernel, without breaks: elsewhere the
        collocation is exact by construction).  False skips the check and its cost (f at 7
        more points per interval), for a caller that solves many trial problems and ignores
        the warning.
    tol : float, optional
        With ``n="auto"``: the relative size of the series' tail that counts as resolved
        (default 1e-13, in [1e-15, 1e-2]).  Given with an integer n: InvalidOrderError.

    Returns
    -------
    Solution

    Raises
    ------
    InvalidCoefficientError
        a or b not finite, or b = 0.
    InvalidEndConditionError
        ``left`` or ``right`` not "bounded", "singular", a real number in (-1, 1) or a tuple
        (e0, g1, ...) of one and valid further exponents (:class:`sie.Equation`).
    InvalidOrderError
        n not an integer or "auto", n < 1 (n < 2 where kappa = 1), or n > ``N_MAX``;
        ``tol`` outside [1e-15, 1e-2] or given with an integer n.
    SideConditionError
        ``total`` missing where kappa = 1, given elsewhere, or not finite.
    InvalidBreakpointError
        A break not strictly inside an interval.
    InvalidIntervalError
        ``intervals`` not finite, ascending and disjoint.
    PerIntervalArgumentError
        A per-interval argument whose length does not match ``intervals``.
    KernelSingularityError
        ``kernel`` unbounded next to an end whose exponent was not given (the message
        names the end: give it, ``left=<float>`` / ``right=<float>``).
    CallableOutputError
        ``f`` or ``kernel`` not callable, not vectorised, complex or not finite.

    Warns
    -----
    InconsistentEquationWarning
        Index -1 on an interval and f violates its solvability condition.
    ResidualWarning
        The equation is not satisfied between the nodes (unresolved f or kernel).
    ResolutionWarning
        ``n="auto"`` reached n = 4096 on an interval without resolving it.

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
    if _is_matrix(a) or _is_matrix(b):
        return _solve_system(f, a, b, n, left, right, kernel, total, breaks, intervals, tol)
    if _touching(intervals):
        return _solve_touching(f, a, b, n, left, right, kernel, total, breaks, intervals, tol,
                               check_residual)
    eq = Equation(a=a, b=b, left=left, right=right, intervals=intervals, kernel=kernel)
    if isinstance(n, str) or tol is not None:
        return eq._solve_auto(f, n, total, breaks, check_residual, tol, stacklevel=4)
    return eq._solve(f, n, total, breaks, check_residual, stacklevel=4)   # at our caller
