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

import warnings
from dataclasses import replace

import numpy as np

from .constants import SurfaceConstants, surface_constants
from .continuation import ZoneState, follow_load
from .errors import (ContactInputError, DirectionError, FrictionError, LoadError,
                     check_finite)
from .material import Orthotropic
from .punches import Punch
from .result import ContactResult, ContactZone, _ClosedFormContactResult
from .zones import ZoneEquations

__all__ = ["solve", "ContactResult", "contact_length"]

_N_DEFAULT = 12
_N_MAX = 4096      # adaptive doubling stops here (n = 3072 from 12: ~0.07 s for a free-end profile)


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
    face = punch.as_face()
    eq = ZoneEquations(slope=punch.slope, rise=face.rise, breaks=tuple(punch.breaks), a=a,
                       b=const.N11, load=load, n=n_use)
    state = _solve_adaptive(face, eq, load, adaptive, tol, punch)
    sol = state.solution
    zones = tuple(_zone_info(z, j, sol) for j, z in enumerate(state.zones))
    integral = sum(z.load for z in zones)
    res = ContactResult(
        zones=zones, n=_basis_size(state), load_check=abs(integral - load) / load,
        constants=const, load=load, speed=float(speed),
        friction=friction, direction=direction, mu_f=mu_f, punch=punch, method="numeric",
        solution=sol)
    return res


def _basis_size(state):
    n = state.solution.n
    return int(n if np.ndim(n) == 0 else max(n))


def _zone_info(z, j, sol):
    multi = np.ndim(sol.alpha) > 0
    alpha = sol.alpha[j] if multi else sol.alpha
    beta = sol.beta[j] if multi else sol.beta
    kappa = sol.kappa[j] if multi else sol.kappa
    load = sol.integral(interval=j) if multi else sol.integral()
    return ContactZone((float(z.c), float(z.d)), (z.left, z.right), float(alpha), float(beta),
                       int(kappa), float(load))


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
    kinds = tuple("corner" if x is not None else "free" for x in punch.corners)
    zone = ContactZone(tuple(float(x) for x in c.ends), kinds, float(c.alpha), float(c.beta),
                       int(c.kappa), float(load))
    return _ClosedFormContactResult(
        zones=(zone,), n=2,
        load_check=c.load_check, constants=const, load=load,
        speed=speed, friction=friction, direction=direction, mu_f=mu_f, punch=punch,
        method="closed_form", solution=c, _sif=dict(c.sif))


def _solve_adaptive(face, eq, load, adaptive, tol, punch):
    """The zones at ``load`` from first touch (:func:`contact.continuation.follow_load`);
    with ``adaptive``, n is doubled (Newton from the previous zones) until the ends and the
    pressure at check points agree between n and 2n to ``tol``."""
    (state,) = follow_load(face, eq, [load])
    if not adaptive:
        return state
    u = np.cos(np.pi * (np.arange(33) + 0.5) / 33)
    lo, hi = face.extent
    while True:
        eq2 = replace(eq, n=2 * eq.n)
        zs, ts, sol2, J = eq2.solve_ends(list(state.zones), list(state.totals), lo=lo, hi=hi,
                                         jacobian=state.jacobian)
        width = zs[-1].d - zs[0].c
        d_ends = max(max(abs(a.c - b.c), abs(a.d - b.d)) for a, b in zip(zs, state.zones)) / width
        X = np.concatenate([z.points(u) for z in zs])
        Xo = np.concatenate([z.points(u) for z in state.zones])
        # compare phi-like values on each zone's own normalised points
        p1, p2 = state.solution(Xo), sol2(X)
        d_p = np.max(np.abs(p2 - p1)) / max(np.max(np.abs(p2)), np.finfo(float).tiny)
        new = ZoneState(load, tuple(zs), tuple(ts), sol2, J)
        if max(d_ends, d_p) <= tol or 2 * eq2.n > _N_MAX:
            if max(d_ends, d_p) > tol:
                hint = ("; if the slope varies on a length scale much shorter than the contact, "
                        "pass a larger n= (the error falls geometrically, at a rate set by that "
                        "scale)")
                if not punch.breaks:
                    hint += ("; if it has a kink or a jump in a derivative, pass its X positions "
                             "as breaks= (spectral instead of algebraic convergence)")
                warnings.warn(f"contact.solve: n = {eq2.n} reached with a change of "
                              f"{max(d_ends, d_p):.2g} (> tol = {tol:.2g}) between n and 2n{hint}",
                              RuntimeWarning, stacklevel=3)
            return new
        eq, state = eq2, new


def contact_length(material, punch, *, load, speed, friction=0.0, direction=-1):
    """x_right - x_left of the contact (numeric path)."""
    r = solve(material, punch, load=load, speed=speed, friction=friction, direction=direction)
    return r.ends[1] - r.ends[0]
