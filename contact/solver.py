"""The moving frictional punch, solved numerically through :func:`sie.solve`.

Zhou, Lee & Jang 2014, eqs. (4.5)-(4.10), with the conventions of the project's errata notes:
on the contact [x_l, x_r], with X = h s + m (h = (x_r - x_l)/2, m = (x_r + x_l)/2),
p(X) = psi(s) solves

    N12 mu_f psi(s) + (N11/pi) PV int psi(t)/(t - s) dt = v'(h s + m),     |s| < 1,
    h int psi ds = P,

with mu_f = -direction * mu (direction -1: the punch slides toward -X, friction traction on
the half-space toward -X, trailing edge on the right).  A sharp corner makes its end singular
and fixes it; a free end is bounded and unknown.  Index 1 (two corners): ends known, the load
is the side condition.  Index 0 (one corner): the free end is the root of load(L) = P.  Index
-1 (two free ends): the solvability condition of the equation (eq. (5.40)) and the load.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq

import sie
from sie.errors import CallableOutputError

from .constants import SurfaceConstants, surface_constants
from .errors import (ContactInputError, ContactLossError, DirectionError, FrictionError,
                     LoadError, check_finite)
from .material import Orthotropic
from .punches import Punch

__all__ = ["solve", "ContactResult", "contact_length"]

_N_DEFAULT = 12
_N_MAX = 1024
_MAX_BRACKET_STEPS = 200


# --------------------------------------------------------------------------
# the result
# --------------------------------------------------------------------------
@dataclass(eq=False)
class ContactResult:
    """Solution of one contact problem.

    Attributes
    ----------
    ends : (float, float)
        Contact ends (x_left, x_right).
    alpha, beta : float
        Exponents of p ~ (x_right - X)^alpha at the right end and (X - x_left)^beta at the left.
    kappa : int
        Index -(alpha + beta).
    n : int
        Jacobi coefficients used.
    residual : float
        max |(dominant operator applied to p) - v'| at 64 check points inside the contact,
        relative to max |v'| (or to the operator's size when v' = 0).
    load_check : float
        |int p dX - P| / P.
    sif : dict
        Stress intensity factors at singular (corner) ends, keyed "left"/"right".  Two
        corners (flat type, Zhou et al. 2014 eqs. (5.11)-(5.12)):
        K_right = lim (x_r - X)^(-alpha) p(X) / 2^beta, K_left = lim (X - x_l)^(-beta) p(X) / 2^alpha.
        One corner (eqs. (5.23), (5.33)): K = lim |X - x_corner|^(-e) p(X), e its exponent.
    constants : SurfaceConstants
    mu_f : float
        Signed friction coefficient -direction * friction.
    """
    ends: tuple
    alpha: float
    beta: float
    kappa: int
    n: int
    load_check: float
    constants: SurfaceConstants
    load: float
    speed: float
    friction: float
    direction: int
    mu_f: float
    punch: Punch
    method: str = "numeric"
    solution: object = field(default=None, repr=False)
    _sif: dict | None = field(default=None, repr=False)
    _residual: float | None = field(default=None, repr=False)

    @property
    def residual(self) -> float:
        """max |N12 mu_f p + N11 Hc[p] - v'| at 64 Chebyshev points of the contact, relative
        to max |v'| (or to the size of N11 Hc[p] when v' = 0); computed on first access."""
        if self._residual is None:
            self._residual = _residual_of(self)
        return self._residual

    @property
    def sif(self) -> dict:
        """Stress intensity factors (see the class docstring), computed on first access."""
        if self._sif is None:
            self._sif = _sif(self.solution, self.punch, self.half_width)
        return self._sif

    # geometry ------------------------------------------------------------
    @property
    def half_width(self):
        return 0.5 * (self.ends[1] - self.ends[0])

    @property
    def center(self):
        return 0.5 * (self.ends[1] + self.ends[0])

    def _s(self, X):
        X = np.asarray(X, dtype=float)
        if not np.all(np.isfinite(X)):
            raise ContactInputError("X must be finite real numbers")
        return (X - self.center) / self.half_width

    def _check_not_singular_end(self, X, s, what):
        for end, expo in ((1.0, self.alpha), (-1.0, self.beta)):
            if expo < 0 and np.any(s == end):
                raise ContactInputError(
                    f"{what} is infinite at the singular contact end X = "
                    f"{self.ends[0] if end < 0 else self.ends[1]!r} (exponent {expo:.6g}); "
                    "evaluate at points off it")

    # fields --------------------------------------------------------------
    def pressure(self, X):
        """Contact pressure p(X) >= 0 (compressive), zero outside the contact."""
        s = self._s(X)
        self._check_not_singular_end(X, s, "the pressure")
        return self.solution(s)

    def shear(self, X):
        """Friction traction q(X) = mu_f p(X) (tau_XY(X, 0) = -q; errata conventions)."""
        return self.mu_f * self.pressure(X)

    def hilbert_pressure(self, X):
        """Hc[p](X) = (1/pi) PV int p(u)/(u - X) du at any real X (not at a singular end)."""
        s = self._s(X)
        self._check_not_singular_end(X, s, "Hc[p]")
        s = np.array(s, dtype=float, copy=True)
        # bounded ends: Hc[p] is continuous there; take the limit from inside
        s[s == 1.0] = np.nextafter(1.0, 0.0)
        s[s == -1.0] = np.nextafter(-1.0, 0.0)
        return self.solution.cauchy(s)

    def sigma_xx(self, X):
        """Surface in-plane stress sigma_XX(X, 0) = N21 p + N22 mu_f Hc[p] at any real X
        (errata item 1: N22 multiplies the shear term).  At mu_f = 0 only N21 p."""
        p = self.pressure(X)
        if self.mu_f == 0.0:
            return self.constants.N21 * p
        return self.constants.N21 * p + self.constants.N22 * self.mu_f * self.hilbert_pressure(X)


# --------------------------------------------------------------------------
# the numerical problem on a trial contact interval
# --------------------------------------------------------------------------
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

    def _equation(self, xl, xr):
        h = 0.5 * (xr - xl)
        m = 0.5 * (xr + xl)
        slope = self.punch.slope
        br = [(x - m) / h for x in self.punch.breaks if xl < x < xr]
        br = [s for s in br if abs(s) < 1.0 - 1e-12]
        return h, (lambda s: slope(h * s + m)), br

    def _call_sie(self, fn, **kw):
        try:
            return fn(a=self.a, b=self.b, left=self.left, right=self.right, **kw)
        except CallableOutputError as exc:
            if isinstance(exc.__cause__, ContactInputError):
                raise exc.__cause__ from None
            raise

    def solve_on(self, xl, xr, n=None):
        """The full solution on the trial contact [xl, xr]."""
        h, f, br = self._equation(xl, xr)
        total = self.load / h if self.punch.kappa == 1 else None
        return self._call_sie(lambda **kw: sie.solve(f, **kw), n=self.n if n is None else n,
                              total=total, breaks=br)

    def functionals_on(self, xl, xr):
        """(load carried, solvability residual) on [xl, xr], without forming the solution
        (a prepared Gauss rule when no break falls inside the trial contact)."""
        h, f, br = self._equation(xl, xr)
        if br:
            fun = self._call_sie(lambda **kw: sie.dominant_functionals(f, **kw), n=self.n,
                                 breaks=br)
        else:
            if self._rule is None:
                self._rule = self._call_sie(lambda **kw: sie.FunctionalsRule(**kw), n=self.n)
            try:
                fun = self._rule(f)
            except CallableOutputError as exc:
                if isinstance(exc.__cause__, ContactInputError):
                    raise exc.__cause__ from None
                raise
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
    if polished is not None:
        return polished
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


# --------------------------------------------------------------------------
# checks and derived quantities
# --------------------------------------------------------------------------
def _residual_of(res):
    """Relative max residual of the dominant equation at 64 Chebyshev points."""
    if res.method == "closed_form":
        return 0.0
    sol = res.solution
    s = np.cos(np.pi * (np.arange(64) + 0.5) / 64)
    f = res.punch.slope(res.half_width * s + res.center)
    hc = res.constants.N11 * sol.cauchy(s)
    lhs = res.constants.N12 * res.mu_f * sol(s) + hc
    scale = max(np.max(np.abs(f)), np.max(np.abs(hc)), np.finfo(float).tiny)
    return float(np.max(np.abs(lhs - f)) / scale)


def _sif(sol, punch, h):
    e = punch.ends
    out = {}
    if e == ("singular", "singular"):
        out["right"] = h ** (-sol.alpha) * sol.endpoint_value(1)
        out["left"] = h ** (-sol.beta) * sol.endpoint_value(-1)
    elif e == ("singular", "bounded"):
        out["left"] = 2.0 ** sol.alpha * h ** (-sol.beta) * sol.endpoint_value(-1)
    elif e == ("bounded", "singular"):
        out["right"] = 2.0 ** sol.beta * h ** (-sol.alpha) * sol.endpoint_value(1)
    return out


def _check_positive_pressure(sol, xl, xr, breaks=()):
    """p >= 0 inside the contact, sampled at Chebyshev points (401; 129 when the breaks
    correction makes each point cost O(n) more) plus both sides of every break."""
    m = 129 if len(breaks) else 401
    s = np.cos(np.pi * (np.arange(m) + 0.5) / m)
    if len(breaks):
        h, c = 0.5 * (xr - xl), 0.5 * (xr + xl)
        sb = np.array([(b - c) / h for b in breaks if xl < b < xr])
        s = np.concatenate([s, sb * (1 - 1e-6), sb * (1 + 1e-6)]) if sb.size else s
    phi = sol.phi(s)
    top = np.max(np.abs(phi))
    if np.min(phi) < -1e-9 * top:
        k = int(np.argmin(phi))
        X = 0.5 * (xr - xl) * s[k] + 0.5 * (xr + xl)
        raise ContactLossError(
            f"the contact pressure is negative inside the contact [{xl:.6g}, {xr:.6g}] "
            f"(at X = {X:.6g}): the punch would lose contact there; this profile and load need "
            "more than one contact zone, which this solver does not model")


def _slope_nondecreasing(punch, x0, x1, samples=2001):
    """Is the punch slope nondecreasing on [min(x0,x1), max(x0,x1)] (sampled)?"""
    X = np.linspace(min(x0, x1), max(x0, x1), samples)
    v = punch.slope(X)
    return bool(np.all(np.diff(v) >= -1e-14 * max(np.max(np.abs(v)), np.finfo(float).tiny)))


_GAP_RULE = tuple(0.5 * v for v in np.polynomial.legendre.leggauss(12))
_GAP_RULE = (_GAP_RULE[0] + 0.5, _GAP_RULE[1])          # Gauss-Legendre on [0, 1]


def _check_gap(res, prob):
    """The punch face must stay above the surface outside free ends (gap >= 0), checked at
    1/8 .. 16 contact widths beyond each free end.

    gap(x_end + side D) = side int_0^D (v'(X) - N11 Hc[p](X)) dxi, X = x_end + side xi
    (outside the contact q = 0, so the surface slope is N11 Hc[p]); xi = D u^2 grades the
    Gauss-Legendre nodes toward the end, where the integrand behaves like xi^alpha."""
    xl, xr = res.ends
    L = xr - xl
    u, wu = _GAP_RULE
    Ds = L * np.array([0.125, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0])
    N11 = res.constants.N11
    for k, (side, x_end) in enumerate(((-1.0, xl), (1.0, xr))):
        if prob.punch.corners[k] is not None:
            continue                       # a corner: the punch face ends there
        if _slope_nondecreasing(prob.punch, x_end, x_end + side * Ds[-1]):
            # gap' = v'(X) - N11 Hc[p](X) with N11 Hc[p] > 0 and decreasing away from the
            # contact (p >= 0), and gap' = 0 at a free end: a nondecreasing slope makes the
            # gap grow on this side, no quadrature needed
            continue
        X = x_end + side * (Ds[:, None] * (u * u)[None, :])          # (7, 24)
        slope = prob.punch.slope(X)
        n11hc = N11 * res.hilbert_pressure(X.ravel()).reshape(X.shape)
        gap = side * ((slope - n11hc) * (wu * 2.0 * u)[None, :]).sum(axis=1) * Ds
        scale = Ds * np.maximum(np.abs(slope).max(axis=1), np.abs(n11hc).max(axis=1))
        bad = np.flatnonzero(gap < -1e-9 * scale)
        if bad.size:
            j = bad[0]
            raise ContactLossError(
                f"the punch face penetrates the surface outside the contact (at X = "
                f"{x_end + side * Ds[j]:.6g}, gap {gap[j]:.3g}): a second contact zone would be "
                "needed, which this solver does not model")


# --------------------------------------------------------------------------
# public entry point
# --------------------------------------------------------------------------
def _check_inputs(material, punch, load, speed, friction, direction, method, n, tol):
    if not isinstance(material, Orthotropic):
        raise ContactInputError(
            f"material must be a contact.Orthotropic (or contact.Isotropic(...)), got {type(material).__name__}")
    if not isinstance(punch, Punch):
        raise ContactInputError(
            "punch must be one of FlatPunch, TriangularPunch, ParabolicPunch, CylindricalPunch, "
            f"ProfilePunch; got {type(punch).__name__}")
    load = check_finite("load", load, LoadError)
    if load <= 0:
        raise LoadError(f"load must be positive (force per unit length pressing the punch in), got {load!r}")
    friction = check_finite("friction", friction, FrictionError)
    if friction < 0:
        raise FrictionError(f"friction must be >= 0 (a coefficient; the sliding direction is "
                            f"set by `direction`), got {friction!r}")
    if isinstance(direction, bool) or direction not in (-1, 1):
        raise DirectionError(f"direction must be -1 (punch slides toward -X) or +1 (toward +X), "
                             f"got {direction!r}")
    if method not in ("numeric", "closed_form"):
        raise ContactInputError(f'method must be "numeric" or "closed_form", got {method!r}')
    if n is not None:
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 2 or n > 100_000:
            raise ContactInputError(f"n must be an integer in [2, 100000] or None, got {n!r}")
    tol = check_finite("tol", tol, ContactInputError)
    if not 0 < tol < 1:
        raise ContactInputError(f"tol must be in (0, 1), got {tol!r}")
    return load, friction, int(direction), tol


def solve(material, punch, *, load, speed, friction=0.0, direction=-1, method="numeric",
          n=None, tol=1e-12, constants=None):
    """Contact pressure, contact extent, SIFs and surface stress of a sliding punch.

    Parameters
    ----------
    material : Orthotropic
    punch : Punch
        FlatPunch, TriangularPunch, ParabolicPunch, CylindricalPunch or ProfilePunch.
    load : float
        P > 0, normal force per unit length.
    speed : float
        Relative speed c = V / sqrt(C33/rho), 0 <= c < c_R.
    friction : float
        Coulomb coefficient mu >= 0.
    direction : {-1, +1}
        -1: the punch slides toward -X (trailing edge on the right, the paper's figures).
    method : {"numeric", "closed_form"}
        "closed_form" evaluates the corrected closed forms (the four punches only).
    n : int, optional
        Jacobi coefficients; by default chosen adaptively until two successive n agree to tol.
    tol : float
        Target relative accuracy of the pressure (adaptive n).
    constants : SurfaceConstants, optional
        ``surface_constants(material, speed)`` computed beforehand (a sweep over friction
        at one speed shares them); must be for this speed.

    Returns
    -------
    ContactResult
    """
    load, friction, direction, tol = _check_inputs(material, punch, load, speed, friction,
                                                   direction, method, n, tol)
    if constants is None:
        const = surface_constants(material, speed)
    else:
        if not isinstance(constants, SurfaceConstants):
            raise ContactInputError(f"constants must be a contact.SurfaceConstants or None, got "
                                    f"{type(constants).__name__}")
        if constants.c != check_finite("speed", speed, ContactInputError):
            raise ContactInputError(f"constants are for speed {constants.c!r}, but speed = {speed!r}")
        const = constants
    mu_f = -direction * friction if friction != 0.0 else 0.0
    if method == "closed_form":
        return _closed_form_result(const, punch, load, float(speed), friction, direction, mu_f)
    a = const.N12 * mu_f if mu_f != 0.0 else 0.0        # no friction terms at mu = 0
    if n is None and punch.slope_degree is not None:
        # polynomial right-hand side of degree d: the projection with n - kappa > d terms is
        # exact, so phi (degree <= d + 1) is too; no doubling needed
        n_use, adaptive = punch.slope_degree + 4, False
    else:
        n_use, adaptive = (n if n is not None else _N_DEFAULT), n is None
    prob = _Problem(punch, a, const.N11, load, n_use)
    ends, sol = _solve_adaptive(prob, adaptive, tol)
    xl, xr = ends
    h = 0.5 * (xr - xl)
    _check_positive_pressure(sol, xl, xr, punch.breaks)
    res = ContactResult(
        ends=(float(xl), float(xr)), alpha=sol.alpha, beta=sol.beta, kappa=sol.kappa, n=sol.n,
        load_check=abs(h * sol.integral() - load) / load,
        constants=const, load=load, speed=float(speed),
        friction=friction, direction=direction, mu_f=mu_f, punch=punch, method="numeric",
        solution=sol)
    if punch.kappa < 1 and not punch.convex:
        _check_gap(res, prob)
    return res


class _ClosedFormContactResult(ContactResult):
    """ContactResult whose fields come from the corrected closed forms
    (:mod:`contact.closed_form`); same interface as the numeric result."""

    def pressure(self, X):
        s = self._s(X)
        self._check_not_singular_end(X, s, "the pressure")
        return self.solution.pressure(np.asarray(X, dtype=float))

    def hilbert_pressure(self, X):
        s = self._s(X)
        self._check_not_singular_end(X, s, "Hc[p]")
        return self.solution.hilbert_pressure(np.asarray(X, dtype=float))


def _closed_form_result(const, punch, load, speed, friction, direction, mu_f):
    from . import closed_form as cf
    from .punches import CylindricalPunch, FlatPunch, ParabolicPunch, TriangularPunch
    N = (const.N11, const.N12, const.N21, const.N22, mu_f)
    if type(punch) is FlatPunch:
        c = cf.flat_closed_form(*N, punch.half_width, load)
    elif type(punch) is TriangularPunch:
        c = cf.triangular_closed_form(*N, punch.m0, load)
    elif type(punch) is ParabolicPunch:
        c = cf.parabolic_closed_form(*N, punch.radius, load)
    elif type(punch) is CylindricalPunch:
        c = cf.cylindrical_closed_form(*N, punch.radius, load)
    else:
        raise ContactInputError(
            f'method="closed_form" exists only for FlatPunch, TriangularPunch, ParabolicPunch and '
            f'CylindricalPunch; use method="numeric" for {type(punch).__name__}')
    return _ClosedFormContactResult(
        ends=tuple(float(x) for x in c.ends), alpha=c.alpha, beta=c.beta, kappa=c.kappa, n=2,
        load_check=c.load_check, constants=const, load=load,
        speed=speed, friction=friction, direction=direction, mu_f=mu_f, punch=punch,
        method="closed_form", solution=c, _sif=dict(c.sif))


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


def _solve_adaptive(prob, adaptive, tol):
    """Find the ends and the solution; with ``adaptive``, double n until the pressure at
    check points and the ends agree between n and 2n to ``tol``."""
    ends = _ends_for(prob)
    sol = prob.solve_on(*ends)
    if not adaptive:
        return ends, sol
    s = np.cos(np.pi * (np.arange(33) + 0.5) / 33)
    while True:
        prob2 = _Problem(prob.punch, prob.a, prob.b, prob.load, 2 * prob.n)
        ends2 = ends if _ends_hold(prob2, ends, tol) else _ends_for(prob2, hint=ends)
        sol2 = prob2.solve_on(*ends2)
        width = ends2[1] - ends2[0]
        d_ends = max(abs(ends2[0] - ends[0]), abs(ends2[1] - ends[1])) / width
        # compare phi on the common normalised interval: p differs by the end shift anyway
        p1, p2 = sol.phi(s), sol2.phi(s)
        d_p = np.max(np.abs(p2 - p1)) / max(np.max(np.abs(p2)), np.finfo(float).tiny)
        if max(d_ends, d_p) <= tol or 2 * prob2.n > _N_MAX:
            if max(d_ends, d_p) > tol:
                hint = ("" if prob.punch.breaks else "; if the slope has a kink or a jump in a "
                        "derivative, pass its X positions as breaks= (spectral instead of "
                        "algebraic convergence)")
                warnings.warn(f"contact.solve: n = {prob2.n} reached with a change of "
                              f"{max(d_ends, d_p):.2g} (> tol = {tol:.2g}) between n and 2n{hint}",
                              RuntimeWarning, stacklevel=3)
            return ends2, sol2
        prob, ends, sol = prob2, ends2, sol2


def contact_length(material, punch, *, load, speed, friction=0.0, direction=-1):
    """x_right - x_left of the contact (numeric path)."""
    r = solve(material, punch, load=load, speed=speed, friction=friction, direction=direction)
    return r.ends[1] - r.ends[0]
