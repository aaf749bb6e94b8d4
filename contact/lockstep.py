"""The first step of the load continuation for many cases at once.

Cases that share a punch face and differ in the coefficients of the equation (friction and
speed: a = N12 mu_f, b = N11) and in the load go through the first step of
:func:`contact.continuation.follow_load` together -- first touch, the power-law prediction to
the load, the side conditions there, the solution and its checks -- each stage one vectorised
call (an :class:`sie.Equation` with a case axis) instead of one per case.  It is the continuation's own step,
in the cases where that step is the whole answer:

* the face is convex and lowest at one point, edge or flat stretch (one zone, whose gap opens
  by itself: no gap check), and homogeneous about an interior lowest point (the power law from
  first touch is then exact);
* n is fixed (given, or a polynomial slope, whose projection is exact): no refinement;
* at the predicted ends the side conditions already hold to rounding (32 eps, Newton's own
  test: no Newton step), the zone stays on the face and holds no break, and p >= 0 at the check
  points (to the resolution of the solution).

A case that fails any of these is left to the full continuation, solved alone (events,
Newton, refinement); :func:`contact.solve` and :func:`contact.solve_batch` go this way for
every case, a single solve as a batch of one.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

import sie

from .continuation import _CHECK_U, _growth_exponent, series_tail
from .zones import _NINE, CORNER, FREE, Zone, _SIE_END

__all__ = ["FirstSteps", "first_steps"]

_TOUCH_WIDTH = 1e-3        # the first-touch zone, relative to the face scale (as _touch)
_CONVERGED = 32 * np.finfo(float).eps     # Newton's test of solve_ends: no step needed
_CHECK_WEIGHT_U = np.ascontiguousarray(_CHECK_U)


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
    None where the face is not one the step can finish (module docstring)."""
    if not face.convex:
        return None
    lowest = face.lowest_points()
    if len(lowest) != 1:
        return None
    a, b, P = (np.asarray(v, dtype=float) for v in (a, b, loads))
    kinds = _touch_kinds(face, lowest[0])
    if kinds is None:
        return None
    unit = np.ones(a.size)
    eqs = sie.Equation(a=a, b=b, left=_SIE_END[kinds[0]], right=_SIE_END[kinds[1]],
                       intervals=_cases(-unit, unit))
    c, d, anchors = _seed(face, lowest[0], np.array([e.alpha for e in eqs.exponents]),
                          np.array([e.beta for e in eqs.exponents]))
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
        if kinds[0] == FREE:
            c = anchors[0] + g * (c - anchors[0])
        if kinds[1] == FREE:
            d = anchors[1] + g * (d - anchors[1])
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


def _touch_kinds(face, lowest):
    """The kinds of the ends of the first-touch zone (as
    :func:`contact.continuation._touch`), or None for a lowest point the step cannot start
    from: an interior minimum the face is not homogeneous about, where the prediction
    places the zone by a search."""
    lo, hi = face.extent
    x0, kind = lowest
    if kind == "left-edge":
        return CORNER, FREE
    if kind == "right-edge":
        return FREE, CORNER
    if kind == "flat":
        return CORNER if x0[0] == lo else FREE, CORNER if x0[1] == hi else FREE
    if face.homogeneous is None or face.homogeneous[0] != float(x0):
        return None
    return FREE, FREE


def _cases(c, d):
    """The zones (c_i, d_i) as the intervals of an sie.Equation's case axis."""
    return np.column_stack([c, d])[:, None, :]


def _seed(face, lowest, alpha, beta):
    """(c, d, anchors) of the first-touch zone of every case, whose exponents with both
    ends bounded are ``alpha``, ``beta`` (as :func:`contact.continuation._touch`)."""
    lo, hi = face.extent
    w = _TOUCH_WIDTH * face.scale
    x0, kind = lowest
    B = alpha.size
    if kind == "left-edge":
        return np.full(B, lo), np.full(B, lo + w), (lo, lo)
    if kind == "right-edge":
        return np.full(B, hi - w), np.full(B, hi), (hi, hi)
    if kind == "flat":
        cf, df = (float(v) for v in x0)
        return (np.full(B, cf if cf == lo else cf - 0.5 * w),
                np.full(B, df if df == hi else df + 0.5 * w), (cf, df))
    # an interior minimum: the centre shifted so that the solvability condition holds for a
    # linear slope (both ends free: the bounded-bounded exponents)
    x0 = float(x0)
    m = x0 + 0.5 * w * (beta - alpha)
    return np.maximum(lo, m - 0.5 * w), np.minimum(hi, m + 0.5 * w), (x0, x0)


def _side_conditions(eqs, slope, P, n):
    """max |F| of each case: the scaled side conditions of one zone with a free end
    (:meth:`contact.zones.ZoneEquations.residual`): the solvability residual over the
    slope's scale (index -1) and int p / P - 1."""
    fb = eqs.functionals(slope, n=n)
    F = np.abs(fb.integral / P - 1.0)
    iv = eqs.intervals[:, 0, :]
    if fb.kappa == -1:
        width = iv[:, 1] - iv[:, 0]
        X = iv[:, :1] + width[:, None] * _NINE
        scale = np.max(np.abs(slope(X.ravel()).reshape(X.shape)), axis=1)
        scale = np.where(scale > 0.0, scale, np.abs(eqs.b) * P / width)
        F = np.maximum(F, np.abs(fb.consistency) / scale)
    return F


def _pressure_ok(sols):
    """Which solutions pass p >= 0 at the check points of their zone, to the resolution of
    their series (:func:`contact.continuation._inspect` on one zone)."""
    tol = np.maximum(1e-9, series_tail(sols.coefficients))
    u = _CHECK_WEIGHT_U
    p = sols.weight_local(u) * sols.phi_local(u)
    top = np.maximum(np.max(np.abs(p), axis=1), np.finfo(float).tiny)
    return np.flatnonzero(np.min(p, axis=1) >= -tol * top)

