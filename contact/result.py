"""The result of a contact solve (:func:`contact.solve`): fields, SIFs, residual.

Zhou, Lee & Jang 2014, eqs. (4.5)-(4.6), (5.11)-(5.13), (5.23), (5.33); conventions of the
documentation, Theory: the contact model and its conventions (p > 0 compressive, q = mu_f p,
Hc[f](X) = (1/pi) PV int f(t)/(t - X) dt).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from .constants import SurfaceConstants
from .errors import ContactInputError, check_number, real_array
from .kernel import own_errors
from .punches import Punch
from .zones import Zone

__all__ = ["ContactResult", "ContactZone", "LoadCurve"]


@dataclass(frozen=True)
class ContactZone:
    """One contact zone: the zone the continuation found (its ends and their kinds, the
    ``zone``, as Newton's method and the checks saw it) and what the solution says of it.

    Attributes
    ----------
    zone : Zone
        ``contact.zones.Zone``: (c, d) and the kind of each end; ``ends``, ``kinds``,
        ``kappa``, ``width`` and :meth:`points` read it.
    ends : (float, float)
        (x_left, x_right).
    kinds : (str, str)
        Each end "free" (p -> 0 there, the end found from the load) or "corner" (an edge of
        the face: the end is fixed and p singular).
    alpha, beta : float
        Exponents of p ~ (x_right - X)^alpha and (X - x_left)^beta.
    kappa : int
        Index -(alpha + beta): 1 (two corners), 0 (one), -1 (two free ends).
    load : float
        The load the zone carries, its integral of p.
    sif : dict
        Stress intensity factors at its corner ends, keyed "left" / "right" (definitions:
        :class:`ContactResult`); empty for two free ends.  Computed on first access.
    width : float
        x_right - x_left.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (5.11)-(5.13), (5.23), (5.33) (the SIFs).

    Examples
    --------
    A flat punch without friction: K = P / (pi sqrt(a)) at both corners (eq. (5.13)):

    >>> import math, contact
    >>> r = contact.solve(contact.Isotropic(1.0, 0.3), contact.FlatPunch(2.0), load=1.0,
    ...                   speed=0.0)
    >>> z = r.zones[0]
    >>> z.kinds, z.width, z.kappa, round(z.load, 12)
    (('corner', 'corner'), 4.0, 1, 1.0)
    >>> round(z.sif["left"] * math.pi * math.sqrt(2.0), 12)
    1.0
    """
    zone: Zone
    alpha: float
    beta: float
    load: float
    _sif_source: object = field(default=None, repr=False, compare=False)

    @property
    def ends(self) -> tuple:
        return (self.zone.c, self.zone.d)

    @property
    def kinds(self) -> tuple:
        return (self.zone.left, self.zone.right)

    @property
    def kappa(self) -> int:
        return self.zone.kappa

    @property
    def width(self) -> float:
        return self.zone.width

    def points(self, u):
        """X at local points u of [-1, 1] (u = -1 the left end)."""
        return self.zone.points(u)

    @property
    def sif(self) -> dict:
        """SIFs at the corner ends, computed on first access (from phi at the ends)."""
        src = self._sif_source
        if src is None:
            return {}
        if isinstance(src, dict):
            return dict(src)
        cached = self.__dict__.get("_sif_cache")
        if cached is None:
            cached = _sif(src, self.ends, self.kinds, self.alpha, self.beta)
            object.__setattr__(self, "_sif_cache", cached)
        return dict(cached)


@dataclass(eq=False)
class ContactResult:
    """Solution of one contact problem.

    Returned by :func:`contact.solve` (and, one per load, by :func:`contact.load_curve`).
    Methods: :meth:`pressure`, :meth:`shear`, :meth:`hilbert_pressure`, :meth:`sigma_xx` (on
    the surface), :meth:`stress` and :meth:`stress_extrema` (under it).

    Attributes
    ----------
    zones : tuple of ContactZone
        The contact zones, left to right (one for the paper's punches).
    ends : (float, float)
        Contact ends (x_left, x_right) of the one zone (an error when there are several:
        use ``zones``).
    alpha, beta : float
        Exponents of p ~ (x_right - X)^alpha at the right end and (X - x_left)^beta at the left
        (tuples over the zones when there are several).
    kappa : int
        Index -(alpha + beta) (a tuple when there are several zones).
    n : int
        Jacobi coefficients used per zone.
    residual : float
        max abs((dominant operator applied to p) - v') at 64 check points per zone, relative
        to max abs(v') (or to the operator's size when v' = 0).
    load_check : float
        abs(int p dX - P) / P.
    sif : dict
        Stress intensity factors at singular (corner) ends, keyed "left"/"right" (one zone).
        Two corners (flat type, Zhou et al. 2014 eqs. (5.11)-(5.12)):
        K_right = lim (x_r - X)^(-alpha) p(X) / 2^beta, K_left = lim (X - x_l)^(-beta) p(X) / 2^alpha.
        One corner (eqs. (5.23), (5.33)): K = lim |X - x_corner|^(-e) p(X), e its exponent.
    constants : SurfaceConstants
    material : Material
        The material it was solved for (with ``constants``, what :meth:`stress` needs: its
        ``half_space_modes``, :class:`contact.Material`).
    punch_material : Material or None
        The elastic punch's material (None: a rigid punch); ``constants`` then hold the
        pair's N11, N12, M12 (:func:`contact.elastic_punch.two_body_constants`) and the
        half-space's stress constants.
    mu_f : float
        Signed friction coefficient -direction * friction.
    load, speed, friction, direction, punch
        The arguments of :func:`contact.solve`.
    method : {"numeric", "closed_form"}
    solution : sie.Solution or closed-form solution
        The solution of the integral equation (numeric path: ``p(X) = solution(X)``).
    half_width, center : float
        Of the one zone.
    zone_scale : float
        The largest half-width of the zones.
    singular_ends : tuple of (float, float)
        (X, exponent) of every end where p is unbounded.

    Raises
    ------
    ContactInputError
        ``ends``, ``sif``, ``half_width`` and ``center`` of a contact with several zones;
        fields asked for at non-finite points or at a singular end.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (4.5)-(4.6) (surface fields), (4.14)-(4.18)
    (exponents, with the arccot branch corrected: see the documentation, Theory: errata of
    Zhou et al. 2014), (5.11)-(5.13), (5.23), (5.33) (SIFs).

    Examples
    --------
    A flat punch sliding with friction 0.3: the exponents solve
    cot(pi alpha) = -a / b = -mu_f N12 / (N11 + M12 mu_f) (M12 = 0 here), with
    alpha + beta = -1 (index 1):

    >>> import math, contact
    >>> r = contact.solve(contact.Isotropic(1.0, 0.3), contact.FlatPunch(1.0), load=1.0,
    ...                   speed=0.0, friction=0.3)
    >>> type(r).__name__, r.ends, r.kappa, round(r.alpha + r.beta, 12)
    ('ContactResult', (-1.0, 1.0), 1, -1.0)
    >>> N = r.constants
    >>> abs(1.0 / math.tan(math.pi * r.alpha) + r.mu_f * N.N12 / N.N11) < 1e-12
    True
    >>> r.load_check < 1e-12, r.residual < 1e-12
    (True, True)
    """
    zones: tuple
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
    material: object = field(default=None, repr=False)
    punch_material: object = field(default=None, repr=False)
    _residual: float | None = field(default=None, repr=False)
    # computes the residual of this result where the solver has its own way (a batch)
    _residual_source: object = field(default=None, repr=False)
    # the material's regular kernel (contact.kernel.ContactKernel), None without one
    _kernel: object = field(default=None, repr=False)

    # -- the zones ---------------------------------------------------------------
    def _one(self, what):
        if len(self.zones) != 1:
            raise ContactInputError(
                f"{what} is defined for one contact zone; this contact has {len(self.zones)} "
                f"zones {[z.ends for z in self.zones]}: use result.zones")
        return self.zones[0]

    @property
    def ends(self):
        return self._one("ends").ends

    def _per_zone(self, name):
        vals = tuple(getattr(z, name) for z in self.zones)
        return vals[0] if len(vals) == 1 else vals

    @property
    def alpha(self):
        return self._per_zone("alpha")

    @property
    def beta(self):
        return self._per_zone("beta")

    @property
    def kappa(self):
        return self._per_zone("kappa")

    @property
    def residual(self) -> float:
        """max abs(a p + b Hc[p] [+ int k p] - v') at 64 Chebyshev points of each zone,
        a = N12 mu_f, b = N11 + M12 mu_f (:meth:`SurfaceConstants.equation_coefficients`),
        relative to max abs(v') (or to the size of b Hc[p] when v' = 0); computed on
        first access.  A layered material's kernel term (:class:`contact.SurfaceKernel`) by
        a finer rule than the solve's own (:meth:`sie.Solution.kernel_integral`): an
        unresolved kernel shows here."""
        if self._residual is None:
            src = self._residual_source
            self._residual = src(self) if src is not None else _residual_of(self)
        return self._residual

    @property
    def sif(self) -> dict:
        """Stress intensity factors of the one zone (see the class docstring; for several
        zones each ``zones[j].sif``)."""
        return self._one("sif").sif

    # geometry ------------------------------------------------------------
    @property
    def zone_scale(self) -> float:
        """The largest half-width of the zones: the length over which the field under the
        surface varies (the default maps and extrema regions are multiples of it; two narrow
        zones far apart have their stresses within about their own width of the surface)."""
        return max(z.width for z in self.zones) / 2.0

    @property
    def half_width(self):
        e = self.ends
        return 0.5 * (e[1] - e[0])

    @property
    def center(self):
        e = self.ends
        return 0.5 * (e[1] + e[0])

    def _X(self, X):
        X = real_array("X", X, ContactInputError, "finite real numbers")  # not text, complex
        if not np.all(np.isfinite(X)):
            raise ContactInputError("X must be finite real numbers")
        return X

    @property
    def singular_ends(self) -> tuple:
        """(X, exponent) of every contact end where p is unbounded (exponent < 0: a corner),
        left to right: the stresses are infinite there on the surface."""
        return tuple((end, e) for z in self.zones
                     for end, e in ((z.ends[0], z.beta), (z.ends[1], z.alpha)) if e < 0)

    def _check_not_singular_end(self, X, what):
        for end, expo in self.singular_ends:
            if np.any(X == end):
                raise ContactInputError(
                    f"{what} is infinite at the singular contact end X = {end!r} "
                    f"(exponent {expo:.6g}); evaluate at points off it")

    # fields --------------------------------------------------------------
    def pressure(self, X):
        """Contact pressure p(X) >= 0 (compressive), zero outside the contact."""
        X = self._X(X)
        self._check_not_singular_end(X, "the pressure")
        return self.solution(X)

    def shear(self, X):
        """Friction traction q(X) = mu_f p(X) (tau_XY(X, 0) = -q; the conventions of the
        documentation, Theory: the contact model and its conventions)."""
        return self.mu_f * self.pressure(X)

    def hilbert_pressure(self, X):
        """Hc[p](X) = (1/pi) PV int p(u)/(u - X) du at any real X (not at a singular end)."""
        X = np.array(self._X(X), dtype=float, copy=True)
        self._check_not_singular_end(X, "Hc[p]")
        # bounded ends: Hc[p] is continuous there; take the limit from inside
        for z in self.zones:
            X[X == z.ends[1]] = np.nextafter(z.ends[1], z.ends[0])
            X[X == z.ends[0]] = np.nextafter(z.ends[0], z.ends[1])
        return self.solution.cauchy(X)

    def sigma_xx(self, X):
        """Surface in-plane stress sigma_XX(X, 0) at any real X:
        (N21 + M22 mu_f) p + (N22 mu_f + M21) Hc[p] (:class:`SurfaceConstants`, eq. (2),
        with q = mu_f p; N22 multiplies the shear term, where the paper's eq. (4.3) prints
        N21: see the documentation, Theory: errata of Zhou et al. 2014).  For an
        orthotropic material aligned with the frame (M21 = M22 = 0) N21 p + N22 mu_f Hc[p],
        at mu_f = 0 only N21 p: Hc[p] is evaluated only where its coefficient is not 0.  A
        layered material adds int s(X, t) p(t) dt, s from its kernel's ``sigma_xx`` (and
        ``shear_sigma_xx``, :class:`contact.SurfaceKernel`); without them it is refused."""
        p = self.pressure(X)
        local, hilbert = self.constants.sigma_xx_coefficients(self.mu_f)
        out = local * p
        if hilbert != 0.0:
            out = out + hilbert * self.hilbert_pressure(X)
        if self._kernel is not None:
            with own_errors():
                out = out + self.solution.kernel_integral(self._kernel.sigma_xx, self._X(X))
        return out


    # the field under the surface ------------------------------------------
    def stress(self, X, Y):
        """The plane stresses at points (X, Y) of the half-space, Y <= 0 (moving frame).

        The material's modes (``material.half_space_modes(c)``, :class:`contact.Material`)
        combine the Cauchy transform C(z) of p at the complex points they name; for an
        orthotropic material sigma_c = Re{ KD_c D + KE_c E } at z_j = X - i eta_j Y over the
        two decaying roots eta_j of Zhou et al. 2014, eq. (3.1) (D, E their divided
        difference and mean; the coefficients and their derivation:
        :mod:`contact.subsurface`), smooth through repeated roots; q = mu_f p adds its
        column only when mu_f != 0.  On Y = 0 the stresses are the tractions
        (sigma_YY = -p, sigma_XY = -q) and :meth:`sigma_xx`.  Where the modes give the
        out-of-plane stresses (``out_of_plane``: :class:`contact.anisotropic.Anisotropic`,
        generalised plane strain) they are filled in as well, on Y = 0 as the limit from
        below (every point z of the modes tends to X, where the transform tends to
        Hc[p](X) + i p(X)).

        Parameters
        ----------
        X, Y : array_like
            Points (broadcast together), finite, Y <= 0.

        Returns
        -------
        contact.subsurface.StressField
            sigma_xx, sigma_yy, sigma_xy (tension positive) and the derived max_shear,
            principal stresses and max_tension; sigma_zz, sigma_yz, sigma_xz (and von_mises,
            tresca) where the material's modes give them, else None.

        Raises
        ------
        StressPointError
            NaN or infinite points, Y > 0.
        ContactInputError
            A point on Y = 0 at a singular contact end (the stress is infinite there).
        MaterialError
            The material's modes are not admissible (:func:`contact.subsurface.half_space_modes`,
            :func:`~contact.subsurface.modes_points`,
            :func:`~contact.subsurface.modes_stresses`).

        Examples
        --------
        >>> import contact
        >>> r = contact.solve(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0),
        ...                   load=0.01, speed=0.0)
        >>> a, p0 = r.half_width, r.pressure(0.0)
        >>> f = r.stress(0.0, -0.786 * a)               # Hertz: 0.300 p0 at 0.786 a
        >>> round(float(f.max_shear / p0), 3)
        0.3
        """
        from .subsurface import (StressField, modes_out_of_plane, modes_points, modes_stresses,
                                 stress_points)
        X, Y = stress_points(X, Y)
        below = Y < 0
        modes = self._modes if np.any(below) or self._has_out_of_plane else None
        out = [np.zeros(X.shape) for _ in range(6 if self._has_out_of_plane else 3)]
        if np.any(below):
            Xb, Yb = X[below], Y[below]
            Cp = [np.asarray(self.solution.cauchy(z), dtype=complex)
                  for z in modes_points(modes, Xb, Yb)]
            q_ratio = self.mu_f or None
            values = modes_stresses(modes, Cp, None, q_ratio, Xb, Yb)
            if len(out) == 6:
                values += modes_out_of_plane(modes, Cp, None, q_ratio, Xb, Yb)
            for o, v in zip(out, values):
                o[below] = v
        if not np.all(below):
            on = ~below
            p = self.pressure(X[on])
            out[0][on] = self.sigma_xx(X[on])
            out[1][on] = -p
            out[2][on] = -self.mu_f * p
            if len(out) == 6:
                # the limit from below: every point z = X + zeta Y of the modes tends to X,
                # where the transform tends to Hc[p](X) + i p(X) (Plemelj)
                Xo = X[on]
                C0 = self.hilbert_pressure(Xo) + 1j * p
                n = len(modes.points(Xo, np.zeros_like(Xo)))
                for o, v in zip(out[3:], modes_out_of_plane(modes, [C0] * n, None,
                                                            self.mu_f or None, Xo, Y[on])):
                    o[on] = v
        return StressField(X, Y, *out)

    @property
    def _has_out_of_plane(self) -> bool:
        """Whether the material's modes give the out-of-plane stresses (``out_of_plane``,
        :class:`contact.MaterialModes`); False without a material."""
        if self.material is None:
            return False
        return callable(getattr(self._modes, "out_of_plane", None))

    @functools.cached_property
    def _modes(self):
        """The half-space modes at this speed (computed on first use)."""
        if self.material is None:
            raise ContactInputError("this ContactResult carries no material: the field "
                                    "under the surface needs it (contact.solve sets it)")
        from .subsurface import half_space_modes
        return half_space_modes(self.material, self.constants.c)

    def stress_extrema(self, region=None, grid=(81, 61),
                       quantities=("max_shear", "max_tension")):
        """Where the in-plane maximum shear and the largest tension (sigma_1) peak (and the
        von Mises stress or the Tresca shear, where asked for).

        A grid search over ``region`` then a polish of the best grid points
        (:func:`contact.subsurface.field_extrema`).

        Parameters
        ----------
        region : ((X_min, X_max), (Y_min, Y_max)), optional
            Default: X within a of the contact's outer ends (x_left of the first zone,
            x_right of the last), 0 >= Y >= -3 a, with a = :attr:`zone_scale` (the largest
            zone's half-width; the half-width for one zone).  With several zones, each
            zone's own part of the region (X within h of its ends, 0 >= Y >= -3 h, h its
            half-width) is searched alike as well, so that a zone narrower than the grid's
            spacing over the whole region is not missed; the largest of all is returned.
        grid : (int, int)
            Grid points in X and Y (>= 3 each).
        quantities : sequence of str
            Which quantities of :class:`contact.subsurface.StressField` to search for:
            some of "max_shear", "max_tension", "von_mises", "tresca" (the last two need a
            material whose modes give the out-of-plane stresses, e.g.
            :class:`contact.anisotropic.Anisotropic`).

        Returns
        -------
        contact.subsurface.StressExtrema
            For each quantity asked for (``max_shear``, ``max_tension``, ``von_mises``,
            ``tresca``; None for those not asked for): value, X, Y, depth and depth / a with
            a the half-width of the zone nearest to X.

        Raises
        ------
        UnboundedStressError
            The region reaches Y = 0 at a singular (corner) end: the stresses are infinite
            there (use the zones' SIFs, or a region with Y_max < 0).
        ContactInputError
            A region that is empty, not finite or above Y = 0; a grid below 3 x 3;
            ``quantities`` empty or naming another quantity.
        MaterialError
            "von_mises" or "tresca" for a material whose modes give only the in-plane
            stresses (:class:`contact.Orthotropic`).
        """
        from .errors import MaterialError
        from .subsurface import (StressExtrema, UnboundedStressError, extremum_quantities,
                                 field_extrema)
        names = extremum_quantities(quantities)
        three_d = [name for name in names if name in ("von_mises", "tresca")]
        if three_d and not self._has_out_of_plane:
            raise MaterialError(
                f"{three_d[0]} needs the out-of-plane stresses sigma_zz, sigma_yz, sigma_xz, "
                f"which the modes of {type(self.material).__name__} do not give (allowed "
                f"there: quantities 'max_shear', 'max_tension'; von Mises and Tresca need a "
                f"material whose half_space_modes(c) has out_of_plane, e.g. "
                f"contact.anisotropic.Anisotropic)")
        xl, xr = self.zones[0].ends[0], self.zones[-1].ends[1]
        a = self.zone_scale
        if region is None:
            region = ((xl - a, xr + a), (-3.0 * a, 0.0))
        nx, ny = _grid(grid)
        x0, x1, y0, y1 = _region(region)
        if not all(np.isfinite([x0, x1, y0, y1])) or not (x0 < x1 and y0 < y1 <= 0.0):
            raise ContactInputError(f"region must be finite with X_min < X_max and "
                                    f"Y_min < Y_max <= 0, got {region!r}")
        if y1 == 0.0:
            for end, e in self.singular_ends:
                if x0 <= end <= x1:
                    raise UnboundedStressError(
                        f"the stresses are infinite at the singular contact end "
                        f"X = {end!r} (exponent {e:.6g}), inside the region {region!r}; "
                        f"use the zones' SIFs there, or a region with Y_max < 0")
        checked = [((x0, x1), (y0, y1))]
        for z in self.zones if len(self.zones) > 1 else ():
            h = z.width / 2
            part = ((max(x0, z.ends[0] - h), min(x1, z.ends[1] + h)),
                    (max(y0, -3.0 * h), y1))
            if part[0][0] < part[0][1] and part[1][0] < part[1][1]:
                checked.append(part)

        def half_width_at(X):
            return min(self.zones, key=lambda z: max(z.ends[0] - X, X - z.ends[1], 0.0)).width / 2

        found = [field_extrema(self.stress, reg, half_width_at, (nx, ny), names)
                 for reg in checked]
        if len(found) == 1:
            return found[0]
        best = {name: max((getattr(f, name) for f in found), key=lambda e: e.value)
                for name in names}
        return StressExtrema(best.get("max_shear"), best.get("max_tension"), checked[0],
                             von_mises=best.get("von_mises"), tresca=best.get("tresca"))


def _grid(grid) -> tuple:
    """(nx, ny) of a stress_extrema grid: integers (numbers of integral value, not text or
    bools: :func:`contact.errors.check_number`), at least 3 each."""
    try:
        nx, ny = grid
    except (TypeError, ValueError):
        raise ContactInputError(f"grid must be (nx, ny), got {grid!r}") from None
    for name, g in (("nx", nx), ("ny", ny)):
        check_number(f"grid {name}", g, ContactInputError, "an integer >= 3")
        if not (math.isfinite(float(g)) and float(g) == int(g)):
            raise ContactInputError(f"grid {name} must be an integer >= 3, got {g!r}")
    if int(nx) < 3 or int(ny) < 3:
        raise ContactInputError(f"grid must have at least 3 x 3 points, got {grid!r}")
    return int(nx), int(ny)


def _region(region) -> tuple:
    """x0, x1, y0, y1 of a region ((X_min, X_max), (Y_min, Y_max)) as floats: numbers, not
    text or bools (:func:`contact.errors.check_number`); their order is the caller's to
    check."""
    shape = "((X_min, X_max), (Y_min, Y_max))"
    try:
        (x0, x1), (y0, y1) = region
    except (TypeError, ValueError):
        raise ContactInputError(f"region must be {shape}, got {region!r}") from None
    for name, v in (("X_min", x0), ("X_max", x1), ("Y_min", y0), ("Y_max", y1)):
        check_number(f"region {name}", v, ContactInputError, f"a number (region = {shape})")
    try:
        return tuple(float(v) for v in (x0, x1, y0, y1))
    except (TypeError, ValueError):
        raise ContactInputError(f"region must be {shape}, got {region!r}") from None


class _ClosedFormContactResult(ContactResult):
    """ContactResult whose fields come from the corrected closed forms
    (:mod:`contact.closed_form`); same interface as the numeric result."""

    def pressure(self, X):
        X = self._X(X)
        self._check_not_singular_end(X, "the pressure")
        return self.solution.pressure(X)

    def hilbert_pressure(self, X):
        X = self._X(X)
        self._check_not_singular_end(X, "Hc[p]")
        return self.solution.hilbert_pressure(X)


#: Where the residual is evaluated: 64 Chebyshev points of each zone (local coordinate).
RESIDUAL_U = np.cos(np.pi * (np.arange(64) + 0.5) / 64)


def _residual_of(res):
    """Relative max residual of the dominant equation at 64 Chebyshev points per zone."""
    if res.method == "closed_form":
        return 0.0
    X = np.concatenate([z.points(RESIDUAL_U) for z in res.zones])
    F = res.solution.cauchy_limit(X)         # H[p] + i p on the zones (Plemelj), one pass
    f = res.punch.slope(X)
    if res._kernel is not None:              # int k p moved to the right-hand side
        with own_errors():
            f = f - res.solution.kernel_integral(res._kernel.slope, X)
    a, b = res.constants.equation_coefficients(res.mu_f)
    return float(relative_residual(f, F, b, a))


def relative_residual(f, F, b, a):
    """max abs(a p + b Hc[p] - f) / scale over the last axis, from F = Hc[p] + i p and
    f = v' at the same points (b, a: scalars, or columns for rows of points; b = N11 +
    M12 mu_f, a = N12 mu_f, :meth:`SurfaceConstants.equation_coefficients`).  The scale
    of the terms: Hc[p] can vanish by symmetry (flat punch, mu = 0) while its rounding is
    eps |b| max|p|."""
    psi, hc = F.imag, b * F.real
    scale = np.maximum.reduce([np.max(np.abs(f), axis=-1), np.max(np.abs(hc), axis=-1),
                               np.max(np.abs(b * psi), axis=-1),
                               np.full(np.shape(f)[:-1], np.finfo(float).tiny)])
    return np.max(np.abs(a * psi + hc - f), axis=-1) / scale


def _sif(phi_end, ends, kinds, alpha, beta):
    """SIFs of one zone from phi at its local ends, ``phi_end(e)`` for e = -1, +1 (h its
    half-width; Zhou et al. 2014, eqs. (5.11)-(5.12), (5.23), (5.33))."""
    h = 0.5 * (ends[1] - ends[0])
    out = {}
    if kinds == ("corner", "corner"):
        out["right"] = h ** (-alpha) * phi_end(1)
        out["left"] = h ** (-beta) * phi_end(-1)
    elif kinds == ("corner", "free"):
        out["left"] = 2.0 ** alpha * h ** (-beta) * phi_end(-1)
    elif kinds == ("free", "corner"):
        out["right"] = 2.0 ** beta * h ** (-alpha) * phi_end(1)
    return out


@dataclass(frozen=True, eq=False)
class LoadCurve:
    """The contact at each load of a load curve (:func:`contact.load_curve`).

    ``len(curve)``, ``curve[i]`` and iteration go over ``results``.

    Attributes
    ----------
    loads : ndarray
        The loads, ascending.
    results : tuple of ContactResult
        The contact at each load (zones, pressure, fields).
    events : tuple
        Where the zones changed between first touch and the last load, in load order
        (:class:`contact.Event`: load, kind "new zone" / "merge" / "edge" / "split", zone
        index, and for an edge which end).
    zone_count : ndarray of int
        Number of contact zones at each load.
    contact_length : ndarray
        The summed width of the zones at each load.
    span : ndarray, shape (m, 2)
        (x_left of the first zone, x_right of the last) at each load.

    References
    ----------
    As for :func:`contact.solve`.

    Examples
    --------
    A cylinder without friction: the Hertz half-width grows like sqrt(P):

    >>> import contact
    >>> curve = contact.load_curve(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0),
    ...                            [0.01, 0.04], speed=0.0)
    >>> len(curve), curve.zone_count.tolist(), curve.events
    (2, [1, 1], ())
    >>> round(float(curve.contact_length[1] / curve.contact_length[0]), 12)
    2.0
    """
    loads: np.ndarray
    results: tuple
    events: tuple = ()

    def __len__(self):
        return len(self.results)

    def __getitem__(self, i):
        return self.results[i]

    def __iter__(self):
        return iter(self.results)

    @property
    def zone_count(self) -> np.ndarray:
        """Number of contact zones at each load."""
        return np.array([len(r.zones) for r in self.results], dtype=int)

    @property
    def contact_length(self) -> np.ndarray:
        """The summed width of the zones at each load."""
        return np.array([sum(z.width for z in r.zones) for r in self.results])

    @property
    def span(self) -> np.ndarray:
        """(x_left of the first zone, x_right of the last) at each load, shape (m, 2)."""
        return np.array([(r.zones[0].ends[0], r.zones[-1].ends[1]) for r in self.results])
