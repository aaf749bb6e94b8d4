"""Contact on several zones: one integral equation on their union, its side conditions, and
Newton's method for the ends.

On L = [c_1, d_1] U ... U [c_J, d_J] the pressure solves (Zhou et al. 2014, eqs. (4.5)-(4.10);
conventions of the documentation, Theory: the contact model and its conventions: v the
Y-displacement, q = mu_f p)

    a p(X) + (b/pi) PV int_L p(t)/(t - X) dt [+ int_L k(X, t) p(t) dt] = H'(X),

a = N12 mu_f, b = N11 + M12 mu_f (:meth:`contact.SurfaceConstants.equation_coefficients`;
M12 = 0 for an orthotropic material aligned with the frame), X in L, H the height of the
punch face, k the regular kernel of a layered material
(:mod:`contact.kernel`; none for a homogeneous half-space).  Each zone end is **free** (p bounded, -> 0; its position is
unknown) or a **corner** (an edge of the face: p singular, the position fixed).  The unknowns
are the free ends and, for a zone with two corners (index 1), the load it carries; the
equations are

* per zone with two free ends (index -1): the solvability condition of the equation on that
  zone (``sie.Solution.consistency``: the weighted mean of the right-hand side left over),
* per gap between neighbouring zones: both touch the same rigid face.  The gap
  g = H - v - v_0 has g' = H' - b Hc[p] off L (p = q = 0 there: dv/dX = N11 Hc[p] +
  M12 Hc[q] = b Hc[p]), and with
  V(X) = (1/pi) int_L p(t) log|X - t| dt (dV/dX = -Hc[p], ``sie.Solution.log_potential``)
      g(c_{j+1}) - g(d_j) = H(c_{j+1}) - H(d_j) + b (V(c_{j+1}) - V(d_j))
                            [- int_L (K(c_{j+1}, t) - K(d_j, t)) p(t) dt] = 0,
  (K the antiderivative of k in X),
* the total load: int_L p = P.

Zone by zone the counts agree (two free ends: two unknowns and one equation; one corner: one
unknown; two corners: the zone's load), and the J - 1 gap conditions with the total load give
the remaining J equations.
"""
from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass

import numpy as np

import sie

from .errors import ContactLossError

__all__ = ["Zone", "ZoneEquations", "FREE", "CORNER", "slope_scale", "one_zone_conditions"]

FREE, CORNER = "free", "corner"
_FLOOR = 1e-9       # residuals below this that no step reduces are rounding: converged
_NEAR_FLOOR = 1e-12  # residuals below this that a step does not halve are rounding: converged
_STEP_TOL = 1e-13    # see solve_ends: the error left (relative to the width) to stop at
_F_TOL = 5e-14       # ... and the residuals
_CONVERGED = 32 * np.finfo(float).eps     # residuals at this need no step
_SIE_END = {FREE: "bounded", CORNER: "singular"}
_NINE = np.linspace(0.0, 1.0, 9)     # where the slope scale of a zone is sampled


def slope_scale(slope, c, d, b, load):
    """The size of H' on the zones [c_j, d_j] of each case: its largest magnitude at 9
    points of each zone; where H' vanishes there, |b| P over the widest zone.  ``c``, ``d``:
    arrays of shape (cases, zones); the result has one entry per case."""
    c, d = np.asarray(c, dtype=float), np.asarray(d, dtype=float)
    X = c[..., None] + (d - c)[..., None] * _NINE
    s = np.max(np.abs(slope(X.ravel()).reshape(X.shape)), axis=(-2, -1))
    return np.where(s > 0.0, s, np.abs(b) * load / np.max(d - c, axis=-1))


def one_zone_conditions(carried, consistency, load):
    """The raw side conditions of one zone with a free end (:meth:`ZoneEquations.residual`)
    from its functionals (arrays over cases, or numbers): the solvability residual (index
    -1; ``consistency`` None otherwise) and int p / P - 1, ``carried`` being int p."""
    load_condition = carried / load - 1.0
    return (load_condition,) if consistency is None else (consistency, load_condition)


@dataclass(frozen=True)
class Zone:
    """One contact zone [c, d] and the kind of each end ("free" or "corner")."""
    c: float
    d: float
    left: str = FREE
    right: str = FREE

    @property
    def kappa(self) -> int:
        return {(CORNER, CORNER): 1, (FREE, FREE): -1}.get((self.left, self.right), 0)

    @property
    def width(self) -> float:
        return self.d - self.c

    def points(self, u):
        """X = m + h u at local points u of [-1, 1] (m the centre, h the half-width)."""
        return 0.5 * (self.c + self.d) + 0.5 * self.width * np.asarray(u)

    def local(self, X):
        """u = (X - m) / h: the local point of X (the inverse of :meth:`points`)."""
        return (np.asarray(X) - 0.5 * (self.c + self.d)) / (0.5 * self.width)


@dataclass(frozen=True)
class ZoneEquations:
    """The equations of a set of zones for one face, material, friction and load.

    ``slope``: H'(X), vectorised; ``rise(x0, x1)``: H(x1) - H(x0); ``breaks``: X where H' or a
    derivative jumps; ``a`` = N12 mu_f, ``b`` = N11 + M12 mu_f; ``n``: Jacobi coefficients per zone;
    ``n_max``: how far the continuation may raise n to resolve its states (None: n is
    fixed, as the user gave it); ``kernel``: the regular kernel of a layered material
    (:class:`contact.kernel.ContactKernel`), None for a homogeneous half-space."""
    slope: object
    rise: object
    breaks: tuple
    a: float
    b: float
    load: float
    n: int = 32
    n_max: int | None = None
    kernel: object = None

    # -- the integral equation on the zones ---------------------------------------------
    def solve(self, zones, totals=None) -> sie.Solution:
        """p on the zones (``totals``: the load of each index-1 zone, None elsewhere)."""
        totals = totals if totals is not None else [None] * len(zones)
        br = [x for x in self.breaks if any(z.c < x < z.d for z in zones)]
        with warnings.catch_warnings():
            # a trial set of ends violates the solvability condition until Newton converges
            warnings.simplefilter("ignore", sie.InconsistentEquationWarning)
            warnings.simplefilter("ignore", sie.ResidualWarning)
            eq = _equation(self.a, self.b, tuple((z.left, z.right) for z in zones),
                           self.kernel)
            return eq.on([(z.c, z.d) for z in zones]).solve(
                self.slope, n=self.n, total=list(totals), breaks=br, check_residual=False)

    # -- unknowns <-> zones ----------------------------------------------------------------
    @staticmethod
    def pack(zones, totals):
        """The unknown vector: each zone's free ends, then its load if both ends are corners."""
        x = []
        for z, t in zip(zones, totals):
            if z.left == FREE:
                x.append(z.c)
            if z.right == FREE:
                x.append(z.d)
            if z.kappa == 1:
                x.append(t)
        return np.array(x, dtype=float)

    @staticmethod
    def unpack(x, zones):
        out, totals, i = [], [], 0
        for z in zones:
            c, d = z.c, z.d
            if z.left == FREE:
                c, i = float(x[i]), i + 1
            if z.right == FREE:
                d, i = float(x[i]), i + 1
            t = None
            if z.kappa == 1:
                t, i = float(x[i]), i + 1
            out.append(Zone(c, d, z.left, z.right))
            totals.append(t)
        return out, totals

    # -- residuals ----------------------------------------------------------------------------
    def residual(self, zones, totals, scale=None):
        """(F, solution): the scaled residuals of the side conditions (module docstring):
        each solvability residual divided by ``scale`` (default: the largest |H'| on the
        zones), each gap condition by ``scale`` times the wider zone of its pair, and the
        load as int p / P - 1.  One zone with a free end and no kernel needs only the load
        and the solvability residual, which :meth:`sie.Equation.functionals` gives from one
        Gauss sum, exactly as the full solve would; the solution is then None (formed once
        Newton has converged)."""
        scale = self._slope_scale(zones) if scale is None else scale
        R, sol = self._raw_residual(zones, totals)
        return R / self._norms(zones, scale), sol

    def _norms(self, zones, scale):
        """What each raw residual is divided by (see :meth:`residual`)."""
        out = [scale for z in zones if z.kappa == -1]
        out += [scale * max(z0.width, z1.width) for z0, z1 in zip(zones[:-1], zones[1:])]
        out.append(1.0)
        return np.array(out)

    def _raw_residual(self, zones, totals):
        """(R, solution): the side conditions in their own units (solvability residuals in
        units of H', gaps in units of H, the load relative)."""
        if len(zones) == 1 and zones[0].kappa != 1 and self.kernel is None:
            return self._raw_one_zone(zones[0]), None
        sol = self.solve(zones, totals)
        R = [cz for z, cz in zip(zones, sol.consistency) if z.kappa == -1]
        if len(zones) > 1:
            ends = np.array([x for z0, z1 in zip(zones[:-1], zones[1:]) for x in (z0.d, z1.c)])
            V = sol.log_potential(ends).reshape(-1, 2)
            K = None if self.kernel is None else \
                sol.kernel_integral(self.kernel.deflection, ends).reshape(-1, 2)
            for k, (z0, z1) in enumerate(zip(zones[:-1], zones[1:])):
                gap = self.rise(z0.d, z1.c) + self.b * (V[k, 1] - V[k, 0])
                R.append(gap if K is None else gap - (K[k, 1] - K[k, 0]))
        R.append(sol.integral() / self.load - 1.0)
        return np.array(R), sol

    def _functionals(self, z):
        """sie.Functionals of one zone on its own (no other zone)."""
        # Zone.local in Python floats (the same operations)
        m, h = 0.5 * (z.c + z.d), 0.5 * (z.d - z.c)
        br = [float((x - m) / h) for x in self.breaks if z.c < x < z.d]
        br = [u for u in br if abs(u) < 1.0 - 1e-12]
        f = lambda u: self.slope(z.points(u))      # noqa: E731
        # on [-1, 1]: the equation and its rule are prepared once, the zone maps onto it
        return _equation(self.a, self.b, ((z.left, z.right),)).functionals(f, n=self.n,
                                                                           breaks=br)

    def _raw_one_zone(self, z):
        fun = self._functionals(z)
        return np.array(one_zone_conditions(0.5 * z.width * fun.integral, fun.consistency,
                                            self.load))

    def zone_loads(self, zones):
        """The load each zone would carry on its own (no interaction between zones; exact
        for one zone), None for a zone with two corners (its load is an unknown)."""
        if self.kernel is not None:
            return [None if z.kappa == 1 else self.solve([z]).integral() for z in zones]
        return [None if z.kappa == 1 else 0.5 * z.width * self._functionals(z).integral
                for z in zones]

    def _slope_scale(self, zones):
        """The size of H' on the zones (:func:`slope_scale`)."""
        # slope_scale for one case, without its array bookkeeping (the same points and sums)
        X = np.concatenate([z.c + (z.d - z.c) * _NINE for z in zones])
        s = float(np.abs(self.slope(X)).max())
        return s if s > 0.0 else abs(self.b) * self.load / max(z.d - z.c for z in zones)

    # -- Newton ---------------------------------------------------------------------------------
    def newton(self, zones, totals=None, *, iterations=40, lo=-math.inf, hi=math.inf):
        """The ends (and index-1 loads) that satisfy the side conditions, from a start close
        enough.  Returns (zones, totals, solution); see :meth:`solve_ends`."""
        return self.solve_ends(zones, totals, iterations=iterations, lo=lo, hi=hi)[:3]

    def solve_ends(self, zones, totals=None, *, iterations=40, lo=-math.inf, hi=math.inf,
                   jacobian=None, budget=None):
        """Newton's method on the side conditions with Broyden's rank-one updates of the
        Jacobian (a finite-difference Jacobian to start, unless ``jacobian`` -- e.g. the
        previous load step's -- is given, and again whenever an updated one stops reducing the
        residual); steps damped to keep the zones ordered and inside [lo, hi].  Returns
        (zones, totals, solution, Jacobian); the Jacobian is that of the scaled residuals
        (:meth:`residual`) with respect to the unknowns in units of their zone's width (and
        the loads in units of the load), which does not change when the zones grow alike, so
        that another set of zones of the same topology can start from it.  ``budget``: the
        most residual evaluations to spend (ContactLossError beyond it; a continuation step
        that needs more is too long and is better halved).

        Converged when the residuals are at 32 eps; or at 5e-14 with the error left in the
        ends (the last step times the factor by which it cut the residuals) below 1e-13 of
        the widths; or at the rounding floor (no step reduces them below 1e-9, or halves
        them below 1e-12)."""
        totals = list(totals) if totals is not None else [
            self.load / len(zones) if z.kappa == 1 else None for z in zones]
        x = self.pack(zones, totals)
        norms = self._norms(zones, self._slope_scale(zones))   # fixed for the whole iteration
        raw = self._raw_residual if budget is None else _Budgeted(self._raw_residual, budget)
        R, sol = raw(zones, totals)
        F = R / norms
        size = _size(F)                 # max |F|, kept with F
        scale = self._fd_steps(zones, totals) * 1e7          # the zone widths (and loads)
        # the Jacobian is kept relative to the scales of the residuals and of the unknowns,
        # where it does not change when the zones grow alike (exactly so on a homogeneous
        # face): another set of zones of the same topology starts from it
        J = jacobian / scale[None, :] if jacobian is not None and \
            jacobian.shape == (F.size, x.size) else None
        fresh = False
        for _ in range(iterations):
            if size <= _CONVERGED:
                break
            if J is None:
                J, fresh = self._fd_jacobian(x, F, zones, totals, lo, hi, norms, raw), True
            try:
                dx = -np.linalg.solve(J, F)
            except np.linalg.LinAlgError:
                if fresh:
                    raise ContactLossError("the side conditions of the contact zones are "
                                           f"singular at ends {[(z.c, z.d) for z in zones]}") from None
                J = None
                continue
            step = self._damped_step(x, dx, size, zones, lo, hi, norms, raw)
            if step is None and size <= _FLOOR:
                if not fresh:               # an updated Jacobian: a fresh one may still step
                    J = None
                    continue
                break                       # at the rounding floor of the residuals
            size_n = None if step is None else step[5]
            if step is not None and size_n > 0.5 * size and size_n <= _NEAR_FLOOR:
                x, zones, totals, F, sol, size = step[0], step[1], step[4], step[2], step[3], \
                    size_n
                break                       # next to the floor: what is left is rounding
            if step is None or size_n > 0.5 * size:
                if not fresh:               # an updated Jacobian that stopped working
                    J = None
                    continue
                if step is None:
                    hint = "" if self.breaks else (
                        "; if the slope jumps or kinks (a wedge's apex, a rounded corner), "
                        "pass its X positions as breaks=")
                    raise ContactLossError(
                        "Newton's method for the contact ends made no progress at ends "
                        f"{[(z.c, z.d) for z in zones]} (residual {size:.3g})"
                        f"{hint}")
            xn, zn, Fn, soln, tn, _ = step
            s = xn - x
            if size > _NEAR_FLOOR:
                # Broyden's ("good") update; not from residuals at the rounding floor, whose
                # difference is noise along a step of the same size
                J = J + np.outer(Fn - F - J @ s, s) / (s @ s)
            fresh = False
            # converged once the residuals are at 5e-14 and the error left in the ends,
            # estimated as the step times the factor by which it cut the residual (the
            # iteration contracts at least that fast), is below 1e-13 of each zone's width
            cut = size_n / size
            small = size_n <= _F_TOL and cut * _size(s / scale) <= _STEP_TOL
            x, zones, totals, F, sol, size = xn, zn, tn, Fn, soln, size_n
            if small:
                break
        else:
            if size > 1e-10:
                raise ContactLossError(
                    f"Newton's method for the contact ends did not converge (residual "
                    f"{size:.3g} after {iterations} iterations)")
        if sol is None:
            sol = self.solve(zones, totals)
        return zones, totals, sol, (None if J is None else J * scale[None, :])

    @staticmethod
    def end_uncertainty(zones, totals, jacobian, noise=_CONVERGED):
        """About the largest error in an end (a length) that residuals at the rounding level
        ``noise`` leave, by the Jacobian of :meth:`solve_ends` (of the scaled residuals with
        respect to the unknowns): max over the ends of the row sums of abs(J^-1) times
        ``noise`` (an estimate: measured within 2-20x of the errors next to the W face's
        merge).  Small where the side conditions hold the ends firmly; large (abs(J^-1)
        ~ 1/gap^2) where two ends are about to meet, as when two zones merge, where no n
        fixes them better.  0 without free ends (nothing to fix)."""
        if jacobian is None or jacobian.size == 0:
            return 0.0
        try:
            inv = np.linalg.inv(jacobian)
        except np.linalg.LinAlgError:
            return math.inf
        err = np.abs(inv).sum(axis=1) * noise
        is_end = []
        for z, t in zip(zones, totals):
            is_end += [True] * ((z.left == FREE) + (z.right == FREE)) + [False] * (z.kappa == 1)
        err = err[np.array(is_end, dtype=bool)]
        return float(err.max()) if err.size else 0.0

    def _fd_jacobian(self, x, F, zones, totals, lo, hi, norms, raw):
        steps = self._fd_steps(zones, totals)
        J = np.empty((F.size, x.size))
        for k in range(x.size):
            xk = x.copy()
            xk[k] += steps[k]
            zk, tk = self.unpack(xk, zones)
            if not _ordered(zk, lo, hi):      # step the other way at a gap or an edge
                steps[k] = -steps[k]
                xk[k] = x[k] + steps[k]
                zk, tk = self.unpack(xk, zones)
                if not _ordered(zk, lo, hi):
                    raise ContactLossError(
                        f"the contact zones {[(z.c, z.d) for z in zones]} are too close to "
                        "each other or to an edge of the face to vary their ends")
            J[:, k] = (raw(zk, tk)[0] / norms - F) / steps[k]
        return J

    def _damped_step(self, x, dx, size, zones, lo, hi, norms, raw):
        """x + t dx for the largest t = 1, 1/2, ... that keeps the zones ordered and reduces
        max|F| (``size``; down to t = 1e-3; only t = 1 once max|F| is at the rounding floor,
        where a shorter step cannot help): (x, zones, F, solution, totals, max|F|) there;
        None if none does."""
        t, t_min = 1.0, (1e-3 if size > _FLOOR else 1.0)
        while t >= t_min:
            xn = x + t * dx
            zn, tn = self.unpack(xn, zones)
            if _ordered(zn, lo, hi):
                Rn, soln = raw(zn, tn)
                Fn = Rn / norms
                size_n = _size(Fn)
                if size_n < size:
                    return xn, zn, Fn, soln, tn, size_n
            t *= 0.5
        return None

    def _fd_steps(self, zones, totals):
        out = []
        for z, t in zip(zones, totals):
            for kind in (z.left, z.right):
                if kind == FREE:
                    out.append(1e-7 * z.width)
            if z.kappa == 1:
                out.append(1e-7 * max(abs(t), self.load))
        return np.array(out)


class _Budgeted:
    """A residual function that raises ContactLossError after ``budget`` calls."""

    def __init__(self, fn, budget):
        self.fn, self.left = fn, int(budget)

    def __call__(self, zones, totals):
        if self.left <= 0:
            raise ContactLossError("Newton's method for the contact ends did not converge "
                                   "within its budget of residual evaluations")
        self.left -= 1
        return self.fn(zones, totals)


@functools.lru_cache(maxsize=64)
def _equation(a, b, kinds, kernel=None):
    """The sie.Equation of zones with end kinds ``kinds`` ((left, right) per zone; on
    [-1, 1] and its neighbours until :meth:`sie.Equation.on` places it), validated once per
    coefficients, topology and kernel (``kernel``: a ContactKernel, whose ``slope`` is the
    equation's kernel k(X, t) in the face's coordinate, or None)."""
    J = len(kinds)
    intervals = None if J == 1 else [(4.0 * j - 1.0, 4.0 * j + 1.0) for j in range(J)]
    return sie.Equation(a=a, b=b, left=[_SIE_END[l] for l, _ in kinds],
                        right=[_SIE_END[r] for _, r in kinds], intervals=intervals,
                        kernel=None if kernel is None else kernel.slope)


def _size(v):
    """max |v| of a small array, as a float (the method, not numpy's function: Newton's
    loop takes it of every residual)."""
    return float(np.abs(v).max())


def _ordered(zones, lo, hi):
    """c_1 >= lo, d_J <= hi, each zone of positive width, gaps between zones."""
    if not (lo <= zones[0].c and zones[-1].d <= hi):
        return False
    prev = -math.inf
    for z in zones:
        if not (prev < z.c < z.d):
            return False
        prev = z.d
    return True
