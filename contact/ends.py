"""Finding the contact ends: the trial-interval problem and the free-end searches.

A sharp corner fixes its end; a free end is found from the load (one free end: the root of
load(L) = P) or, with two free ends, from the load and the solvability condition of the index -1
equation (Zhou et al. 2014, eq. (5.40)): center by continuation, half-width by bracketing, then a
2-D Newton polish.  Every trial uses :func:`sie.dominant_functionals` / :class:`sie.FunctionalsRule`
(one Gauss sum), not a full solve.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq

import sie
from sie.errors import CallableOutputError

from .errors import ContactInputError, ContactLossError
from .punches import Punch

_MAX_BRACKET_STEPS = 200


@dataclass
class _Problem:
    punch: Punch
    a: float            # N12 mu_f
    b: float            # N11
    load: float
    n: int
    _rule: object = field(default=None, repr=False)

    @property
    def left(self):
        return self.punch.ends[0]

    @property
    def right(self):
        return self.punch.ends[1]

    def _equation(self, xl, xr, checked=False):
        """Half-width, f(s) = slope(h s + m) and the breaks in s on the trial contact [xl, xr].

        ``checked=False`` uses the punch's raw slope: sie checks what f returns (shape,
        finiteness) anyway, and checking it twice per trial was a third of the cost of a
        free-end search.  :meth:`_run` re-runs a failed call with the checked slope so that
        the error names the punch and the X.
        """
        h = 0.5 * (xr - xl)
        m = 0.5 * (xr + xl)
        punch = self.punch
        # the raw slope only where it is safe: a subclass that overrides slope() itself keeps it
        raw = type(punch).slope is Punch.slope
        slope = punch._slope if raw and not checked else punch.slope
        br = [(x - m) / h for x in self.punch.breaks if xl < x < xr]
        br = [s for s in br if abs(s) < 1.0 - 1e-12]
        return h, (lambda s: slope(h * s + m)), br

    def _run(self, xl, xr, fn, raw=True):
        """``fn(h, f, breaks)`` for the trial contact [xl, xr] (see :meth:`_equation`).

        ``raw``: first with the raw slope; a failure is re-run with the checked slope so
        that the error names the punch and the X.  ``raw=False``: the checked slope only.
        """
        first = None
        if raw:
            try:
                return fn(*self._equation(xl, xr))
            except CallableOutputError as exc:
                first = exc
        try:
            out = fn(*self._equation(xl, xr, checked=True))
        except CallableOutputError as exc:
            if isinstance(exc.__cause__, ContactInputError):
                raise exc.__cause__ from None
            raise
        if first is not None:
            raise first
        return out

    def _sie_kw(self):
        return dict(a=self.a, b=self.b, left=self.left, right=self.right)

    def solve_on(self, xl, xr, n=None, check_residual=True):
        """The full solution on the trial contact [xl, xr].  ``check_residual=False`` silences
        sie's ResidualWarning (the adaptive loop judges convergence itself)."""
        n = self.n if n is None else n

        def run(h, f, br):
            total = self.load / h if self.punch.kappa == 1 else None
            with warnings.catch_warnings():
                if not check_residual:
                    warnings.simplefilter("ignore", sie.ResidualWarning)
                return sie.solve(f, n=n, total=total, breaks=br, **self._sie_kw())
        # the checked slope: the solution keeps f and calls it again later (the remainder of
        # a solution with breaks is built on first use), outside _run's error translation
        return self._run(xl, xr, run, raw=False)

    def functionals_on(self, xl, xr):
        """(load carried, solvability residual) on [xl, xr], without forming the solution
        (a prepared Gauss rule when no break falls inside the trial contact)."""
        def run(h, f, br):
            if br:
                return h, sie.dominant_functionals(f, n=self.n, breaks=br, **self._sie_kw())
            if self._rule is None:
                self._rule = sie.FunctionalsRule(n=self.n, **self._sie_kw())
            return h, self._rule(f)
        h, fun = self._run(xl, xr, run)
        return h * fun.integral, fun.consistency

    def load_on(self, xl, xr):
        return self.functionals_on(xl, xr)[0]

    def consistency_on(self, xl, xr):
        return self.functionals_on(xl, xr)[1]


def _bracket_positive(fun, x0, what, factor=2.0):
    """Find lo < hi with fun(lo) < 0 <= fun(hi) for an increasing fun on (0, inf), x0 > 0,
    stepping geometrically by ``factor`` from x0."""
    f0 = fun(x0)
    lo = hi = x0
    if f0 < 0:
        for _ in range(_MAX_BRACKET_STEPS):
            lo, hi = hi, hi * factor
            if fun(hi) >= 0:
                return lo, hi
    else:
        for _ in range(_MAX_BRACKET_STEPS):
            lo, hi = lo / factor, lo
            if fun(lo) < 0:
                return lo, hi
    raise ContactLossError(f"no {what} carries the load: the load stays on one side of the "
                           "target from 1e-60 to 1e60 times the starting size (does the profile "
                           "rise away from the contact?)")


def _bracket_around(fun, x0, what, rel=1e-3):
    """lo < x0 < hi with fun(lo) < 0 < fun(hi), searched outward from x0 (a good guess):
    avoids a bracket end that sits on the root itself, where rounding decides the sign."""
    lo, hi = x0 / (1.0 + rel), x0 * (1.0 + rel)
    for _ in range(_MAX_BRACKET_STEPS):
        if fun(lo) < 0:
            break
        lo /= 2.0
    else:
        raise ContactLossError(f"no {what} below {x0:.6g} leaves the load uncarried")
    for _ in range(_MAX_BRACKET_STEPS):
        if fun(hi) > 0:
            break
        hi *= 2.0
    else:
        raise ContactLossError(f"no {what} above {x0:.6g} carries the load")
    return lo, hi


def _one_free_end(prob: _Problem, hint=None):
    """Index 0: the corner end is fixed, the other end is the root of load = P.
    ``hint``: ends found at a lower n, to search next to."""
    punch = prob.punch
    xc = punch.corners[0] if punch.corners[0] is not None else punch.corners[1]
    sign = 1.0 if punch.corners[0] is not None else -1.0     # free end to the right / left

    def ends(L):
        return (xc, xc + L) if sign > 0 else (xc - L, xc)

    hom = punch.homogeneous
    if hom is not None and hom[0] == xc:
        # load(L) = L^(d+1) load(1): exact scaling of the equation (f(s) scales as L^d)
        load1 = prob.load_on(*ends(1.0))
        if not load1 > 0:
            raise ContactLossError(
                f"this profile carries no compressive load next to its corner at X = {xc} "
                f"(load on a unit contact = {load1:.3g}); the punch face must rise away from it")
        L = (prob.load / load1) ** (1.0 / (hom[1] + 1.0))
        return ends(L)
    excess = lambda L: prob.load_on(*ends(L)) - prob.load      # noqa: E731
    if hint is not None:
        lo, hi = _bracket_around(excess, hint[1] - hint[0], "contact length")
    else:
        lo, hi = _bracket_positive(excess, _length_scale(punch, xc), "contact length")
    L = brentq(lambda L: prob.load_on(*ends(L)) - prob.load, lo, hi, xtol=1e-15 * hi,
               rtol=4 * np.finfo(float).eps, maxiter=200)
    return ends(L)


def _length_scale(punch, x0):
    if punch.breaks:
        return max(1e-300, 2.0 * max(abs(b - x0) for b in punch.breaks))
    return 1.0


class _CenterTracker:
    """Center m(h) of a two-free-end contact of half-width h: the root of the solvability
    condition (weighted mean of the slope over the contact = 0), followed by continuation."""

    def __init__(self, prob: _Problem, m0: float):
        self.prob = prob
        self.m = m0
        self.window = 0.25
        self.xtol_rel = 1e-14       # loosened while only bracketing the half-width

    def restart(self, m0):
        self.m = m0
        self.window = 0.25

    def g(self, m, h):
        return self.prob.consistency_on(m - h, m + h)

    def __call__(self, h):
        m0 = self.m
        w = self.window * h          # small once the center is known from a nearby h
        lo, hi = m0 - w, m0 + w
        glo, ghi = self.g(lo, h), self.g(hi, h)
        for _ in range(_MAX_BRACKET_STEPS):
            if glo <= 0.0 <= ghi:
                break
            w *= 4.0
            if glo > 0.0:
                lo, glo = m0 - w, self.g(m0 - w, h)
            if ghi < 0.0:
                hi, ghi = m0 + w, self.g(m0 + w, h)
        else:
            raise ContactLossError(
                "no contact position satisfies the solvability condition of the index -1 "
                f"equation at half-width {h:.6g} (the weighted mean slope does not change sign "
                "from - to +): the profile has no contact zone with two free ends here")
        # one secant step first: exact when the slope is linear (g affine in m)
        m_sec = lo - glo * (hi - lo) / (ghi - glo) if ghi != glo else 0.5 * (lo + hi)
        g_sec = self.g(m_sec, h) if lo < m_sec < hi else math.inf
        if glo == 0.0:
            self.m = lo
        elif ghi == 0.0:
            self.m = hi
        elif abs(g_sec) <= 4 * np.finfo(float).eps * (abs(glo) + abs(ghi)):
            self.m = m_sec
        else:
            self.m = brentq(lambda m: self.g(m, h), lo, hi, xtol=self.xtol_rel * h,
                            rtol=4 * np.finfo(float).eps, maxiter=200)
        self.window = 0.01
        return self.m


def _two_free_ends(prob: _Problem, hint=None):
    """Index -1: center from the solvability condition, half-width from the load.

    Without a scaling law: start from a contact large enough to carry 4P (where the center
    is the unique root of the solvability condition for profiles that rise on both sides),
    then walk the half-width down by halves, continuing the center, until the load drops
    below P, and refine by Brent's method.  ``hint``: ends found at a lower n."""
    punch = prob.punch
    hom = punch.homogeneous
    if hom is not None:
        x0, d = hom
        # the unit contact's center does not scale with the hint: start from x0 (a distant
        # start widens the bracket and brentq's absolute tolerance with it)
        track = _CenterTracker(prob, x0)
        m1 = track(1.0)
        load1 = prob.load_on(m1 - 1.0, m1 + 1.0)
        if not load1 > 0:
            raise ContactLossError(f"this profile carries no compressive load (load on a unit "
                                   f"contact = {load1:.3g})")
        lam = (prob.load / load1) ** (1.0 / (d + 1.0))
        return (x0 + lam * (m1 - 1.0 - x0), x0 + lam * (m1 + 1.0 - x0))

    memo = {}

    def load_at(h):
        # memoised: brentq re-evaluates the bracket ends found while bracketing, and a
        # contact inside a flat seat makes the center root degenerate (slow to converge)
        if h not in memo:
            m = track(h)
            memo[h] = prob.load_on(m - h, m + h)
        return memo[h]

    if hint is not None:
        track = _CenterTracker(prob, 0.5 * (hint[0] + hint[1]))
        lo, hi = _bracket_around(lambda h: load_at(h) - prob.load, 0.5 * (hint[1] - hint[0]),
                                 "contact half-width")
    else:
        m0 = 0.5 * (min(punch.breaks) + max(punch.breaks)) if punch.breaks else 0.0
        track = _CenterTracker(prob, m0)
        track.xtol_rel = 1e-3       # bracketing needs the sign of load - P only
        h = 0.5 * _length_scale(punch, m0)
        for _ in range(_MAX_BRACKET_STEPS):          # up: a contact that carries 4P
            if load_at(h) >= 4.0 * prob.load:
                break
            track.restart(m0)
            h *= 2.0
        else:
            raise ContactLossError("no contact width carries the load (the load stays below it "
                                   "up to 1e60 times the starting width)")
        for _ in range(_MAX_BRACKET_STEPS):          # down, by continuation
            if load_at(0.5 * h) < prob.load:
                break
            h *= 0.5
        else:
            raise ContactLossError("the load is carried by every contact width down to 1e-60 "
                                   "of the starting one: the profile has a flat or concave seat")
        lo, hi = 0.5 * h, h
    # start of a 2-D Newton on (center, half-width): h from the power law load ~ h^p through
    # the bracket, the center from the solvability condition there; if Newton does not
    # converge, fall back to the nested Brent search at full tolerance
    l_lo, l_hi = load_at(lo), load_at(hi)
    if l_lo > 0 and l_hi > l_lo:
        p_exp = math.log(l_hi / l_lo) / math.log(hi / lo)
        h0 = lo * (prob.load / l_lo) ** (1.0 / p_exp)
    else:
        h0 = 0.5 * (lo + hi)
    track.xtol_rel = 1e-8
    track.m = track(hi)
    m0 = track(h0)
    polished = _newton_polish(prob, m0, h0)
    if polished is not None and lo <= 0.5 * (polished[1] - polished[0]) <= hi:
        return polished                  # (a root outside the bracket would be another branch)
    track.xtol_rel = 1e-14
    memo.clear()
    track.m = track(hi)
    h = brentq(lambda h: load_at(h) - prob.load, lo, hi, xtol=1e-15 * hi,
               rtol=4 * np.finfo(float).eps, maxiter=200)
    m = track(h)
    return (m - h, m + h)


def _newton_polish(prob, m, h, iterations=12):
    """Newton on F(m, h) = (load/P - 1, residual/slope scale) from a good start, with a
    forward-difference Jacobian (step 1e-7 h: the Jacobian is then good to ~1e-7, so each step
    gains ~7 digits).  Returns the ends, or None if the residual does not fall to rounding."""
    scale = np.max(np.abs(prob.punch.slope(m + h * np.linspace(-1.0, 1.0, 9))))
    if not scale > 0:
        return None

    def F(m, h):
        load, resid = prob.functionals_on(m - h, m + h)
        return np.array([load / prob.load - 1.0, resid / scale])

    f = F(m, h)
    for _ in range(iterations):
        if np.max(np.abs(f)) <= 8 * np.finfo(float).eps:
            return (m - h, m + h)
        d = 1e-7 * h
        J = np.column_stack([(F(m + d, h) - f) / d, (F(m, h + d) - f) / d])
        try:
            dm, dh = np.linalg.solve(J, -f)
        except np.linalg.LinAlgError:
            return None
        if not (np.isfinite(dm) and np.isfinite(dh)) or abs(dh) > 0.5 * h or abs(dm) > 0.5 * h:
            return None
        m, h = m + dm, h + dh
        f_new = F(m, h)
        if abs(dm) <= 1e-15 * h and abs(dh) <= 1e-15 * h:
            return (m - h, m + h)
        f = f_new
    return (m - h, m + h) if np.max(np.abs(f)) <= 64 * np.finfo(float).eps else None


def _ends_for(prob, hint=None):
    k = prob.punch.kappa
    if k == 1:
        return prob.punch.corners
    if k == 0:
        return _one_free_end(prob, hint)
    return _two_free_ends(prob, hint)


def _ends_hold(prob, ends, tol):
    """Do the ends found at a lower n satisfy this n's end conditions to tol?  (Load within
    tol P; for two free ends also the solvability residual within tol of the slope scale.)
    Then the search at this n would move them by ~tol of the width, and is skipped."""
    k = prob.punch.kappa
    if k == 1:
        return True
    load, resid = prob.functionals_on(*ends)
    if not abs(load - prob.load) <= tol * prob.load:
        return False
    if k == 0:
        return True
    h, m = 0.5 * (ends[1] - ends[0]), 0.5 * (ends[1] + ends[0])
    scale = np.max(np.abs(prob.punch.slope(m + h * np.linspace(-1.0, 1.0, 9))))
    return abs(resid) <= tol * scale
