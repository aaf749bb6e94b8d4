"""The first step of the load continuation for many cases at once.

Cases that share a punch face and differ in the coefficients of the equation (friction and
speed: a = N12 mu_f, b = N11 + M12 mu_f) and in the load go through the first step of
:func:`contact.continuation.follow_load` together -- first touch, the power-law prediction to
the load, the side conditions there, the solution and its checks -- each stage one vectorised
call (an :class:`sie.Equation` with a case axis) instead of one per case.  It is the
continuation's own step, made of the continuation's own pieces with a case axis (the
first-touch zone, the power law, the side conditions and their scale, the pressure check),
in the cases where that step is the whole answer:

* the face is convex and lowest at one point, edge or flat stretch (one zone, whose gap opens
  by itself: no gap check), and homogeneous about an interior lowest point (the power law from
  first touch is then exact);
* n is fixed (given, or a polynomial slope, whose projection is exact): no refinement;
* at the predicted ends the side conditions already hold to rounding (32 eps, Newton's own
  test: no Newton step), the zone stays on the face and holds no break, and p >= 0 at the check
  points (to the resolution of the solution) with no dip between them to polish.

A case that fails any of these is left to the full continuation, solved alone (events,
Newton, refinement); :func:`contact.solve` and :func:`contact.solve_batch` go this way for
every case, a single solve as a batch of one.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

import sie

from .continuation import (_CHECK_U, _growth_exponent, power_law_ends, pressure_dips,
                           pressure_holds, pressure_top, series_tail, touch_kinds, touch_zones)
from .zones import _SIE_END, Zone, one_zone_conditions, slope_scale

__all__ = ["FirstSteps", "first_steps"]

_TOUCH_WIDTH = 1e-3        # the first-touch zone, relative to the face scale (as _touch's)
_CONVERGED = 32 * np.finfo(float).eps     # Newton's test of solve_ends: no step needed


@dataclass(frozen=True, eq=False)
class FirstSteps:
    """The cases a lockstep first step solved.

    Attributes
    ----------
    done : ndarray of int
        Indices (into the batch) of the cases solved here; the others need the full
        continuation.
    kinds : (str, str)
        The kinds of the zone's ends (the same in every case).
    solutions : sie.SolutionBatch
        p on each solved case's zone (``solutions.intervals`` are the zones).
    """
    done: np.ndarray
    kinds: tuple
    solutions: object


def first_steps(face, slope, breaks, a, b, loads, n) -> FirstSteps | None:
    """The first continuation step of each case (a_i, b_i, P_i) on one face, at n fixed;
    None where the face is not one the step can finish (module docstring).  The step's
    pieces are the continuation's own, on a case axis: the first-touch zone
    (:func:`contact.continuation.touch_zones`), its growth by the power law
    (:func:`contact.continuation.power_law_ends`), the side conditions and their scale
    (:func:`contact.zones.one_zone_conditions`, :func:`contact.zones.slope_scale`) and the
    pressure check (:func:`contact.continuation.pressure_holds`)."""
    if not face.convex:
        return None
    lowest = face.lowest_points()
    if len(lowest) != 1:
        return None
    x0, kind = lowest[0]
    if kind == "interior" and (face.homogeneous is None or face.homogeneous[0] != float(x0)):
        return None     # the prediction places that zone by a search (continuation._predict)
    a, b, P = (np.asarray(v, dtype=float) for v in (a, b, loads))
    kinds = touch_kinds(face, lowest[0])
    unit = np.ones(a.size)
    eqs = sie.Equation(a=a, b=b, left=_SIE_END[kinds[0]], right=_SIE_END[kinds[1]],
                       intervals=_cases(-unit, unit))
    # the exponents with both ends bounded (those of a zone at an interior minimum, the only
    # one whose placement uses them)
    (c, d, _, anchors), = touch_zones(face, np.array([e.alpha for e in eqs.exponents]),
                                      np.array([e.beta for e in eqs.exponents]), _TOUCH_WIDTH)
    eqs = eqs.on(_cases(c, d))
    z0 = Zone(float(c[0]), float(d[0]), *kinds)
    kappa = z0.kappa
    ok = np.ones(a.size, dtype=bool)
    if kappa != 1:
        # the loads at first touch, then the power law about the anchors to P
        L = eqs.functionals(slope, n=n).integral
        ok &= L > 0.0
        growth = _growth_exponent(face, z0, anchors, _TOUCH_WIDTH * face.scale)
        g = (P / np.where(ok, L, 1.0)) ** (1.0 / growth) if growth is not None else 1.0
        c, d = power_law_ends(c, d, kinds, anchors, g)
    lo, hi = face.extent
    ok &= (lo <= c) & (c < d) & (d <= hi)
    for x in breaks:
        ok &= ~((c < x) & (x < d))
    done = np.flatnonzero(ok)
    if done.size == 0:
        return FirstSteps(done, kinds, None)
    if done.size < a.size:
        eqs, P, c, d = eqs.take(done), P[done], c[done], d[done]
    eqs = eqs.on(_cases(c, d))
    if kappa != 1:
        keep = np.flatnonzero(_side_conditions(eqs, slope, P, n) <= _CONVERGED)
        if keep.size == 0:
            return FirstSteps(keep, kinds, None)
        if keep.size < done.size:
            done, eqs, P = done[keep], eqs.take(keep), P[keep]
    sols = eqs.solve(slope, n=n, total=P if kappa == 1 else None)
    # index 1: the load is the side condition, int p = P by construction (the residual
    # of ZoneEquations at the predicted total P)
    keep = np.flatnonzero(np.abs(sols.integral() / P - 1.0) <= _CONVERGED) if kappa == 1 \
        else np.arange(done.size)
    keep = keep[_pressure_ok(sols.take(keep))]
    return FirstSteps(done[keep], kinds, sols if keep.size == done.size else sols.take(keep))


def _cases(c, d):
    """The zones (c_i, d_i) as the intervals of an sie.Equation's case axis."""
    out = np.empty((np.size(c), 1, 2))
    out[:, 0, 0], out[:, 0, 1] = c, d
    return out


def _side_conditions(eqs, slope, P, n):
    """max |F| of each case: the scaled side conditions of its one zone with a free end
    (:meth:`contact.zones.ZoneEquations.residual`, Newton's measure of convergence)."""
    fb = eqs.functionals(slope, n=n)
    R = one_zone_conditions(fb.integral, fb.consistency, P)
    if fb.consistency is None:
        return np.abs(R[0])
    iv = eqs.intervals[:, 0, :]
    scale = slope_scale(slope, iv[:, :1], iv[:, 1:], eqs.b, P)
    return np.maximum(np.abs(R[0]) / scale, np.abs(R[1]))


def _pressure_ok(sols):
    """Which solutions pass the continuation's check of p >= 0 at the check points of
    their zone, to the resolution of their series (:func:`contact.continuation._inspect`
    on one zone), and have no dip there that could hide a negative pressure between the
    check points (the continuation polishes those; such a case is left to it)."""
    tol = np.maximum(1e-9, series_tail(sols.coefficients))
    p = sols.weight_local(_CHECK_U) * sols.phi_local(_CHECK_U)
    top = pressure_top(p)
    good = pressure_holds(p, tol, top) & ~np.any(pressure_dips(p, top), axis=-1)
    return np.flatnonzero(good)


