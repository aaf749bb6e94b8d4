"""The contact zones along a load curve, from first touch.

The face first touches at its lowest point(s); the load then grows in steps, and after each
step the zones are checked and changed where the physics says so:

* a free end that reaches an edge of the face becomes a corner there (the pressure turns
  singular; the end stops moving);
* two neighbouring zones whose gap closes merge into one;
* a point of the face outside the zones that the surface would cross (gap < 0) starts a new
  zone there.

Each event is located in the load by bisection (to a relative 1e-9 of the load), so that the
topology changes where it should; in between, Newton's method (:mod:`contact.zones`) follows
the ends from the previous step's solution.  Nothing about the profile far away is assumed.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from .errors import ContactLossError
from .zones import CORNER, FREE, Zone, ZoneEquations, _ordered

__all__ = ["ZoneState", "first_touch", "follow_load"]

_GROWTH = 4.0          # largest load ratio of one continuation step
_CHECK_U = np.cos(np.pi * (np.arange(64) + 0.5) / 64)     # where p >= 0 is checked
_MIN_RATIO = 1e-9      # the finest load step (relative) before giving up


@dataclass(frozen=True)
class ZoneState:
    """The zones at one load, their index-1 loads, the solution of the equation on them, and
    the Jacobian of the side conditions (reused by the next step of the same topology)."""
    load: float
    zones: tuple
    totals: tuple
    solution: object
    jacobian: object = field(default=None, repr=False)


def first_touch(face, eq: ZoneEquations, width=1e-3):
    """Zones of width ~``width`` * (face scale) at the lowest point(s) of the face, and the
    load they carry: the start of the continuation."""
    lo, hi = face.extent
    zones = []
    for x0, kind in face.lowest_points():
        scale = face.scale
        w = width * scale
        if kind == "left-edge":
            zones.append(Zone(lo, lo + w, CORNER, FREE))
        elif kind == "right-edge":
            zones.append(Zone(hi - w, hi, FREE, CORNER))
        elif kind == "flat":
            c, d = x0
            zones.append(Zone(c if c == lo else c - 0.5 * w, d if d == hi else d + 0.5 * w,
                              CORNER if c == lo else FREE, CORNER if d == hi else FREE))
        else:
            zones.append(Zone(max(lo, x0 - 0.5 * w), min(hi, x0 + 0.5 * w)))
    sol = eq.solve(zones, [None if z.kappa != 1 else 1.0 for z in zones])
    load0 = sum(sol.integral(interval=j) if len(zones) > 1 else sol.integral()
                for j in range(len(zones)))
    if not load0 > 0:
        raise ContactLossError(
            f"the face carries no compressive load at its lowest point(s) {face.lowest_points()}")
    return zones, float(load0)


def follow_load(face, eq: ZoneEquations, loads):
    """ZoneState at each load of ``loads`` (ascending), by continuation from first touch."""
    zones, load0 = first_touch(face, eq)
    loads = [float(P) for P in loads]
    totals0 = tuple(None if z.kappa != 1 else load0 / len(zones) for z in zones)
    if loads[0] > load0:
        # straight to the first load when first touch's topology holds there (the common
        # case: one zone that grows), without solving at the first-touch load itself
        direct = _try_step(face, eq, ZoneState(load0, tuple(zones), totals0, None), loads[0])
        if direct is not None:
            out = [direct]
            for P in loads[1:]:
                out.append(_advance(face, eq, out[-1], P))
            return out
    state = _solve_at(face, eq, zones, None, load0)
    if loads[0] < load0:
        # below the first-touch load the zones shrink about the same points (the topology
        # of first touch holds at any smaller load)
        z, t = _predict(state, loads[0])
        state = _solve_at(face, eq, z, t, loads[0])
    out = []
    for P in loads:
        state = _advance(face, eq, state, P)
        out.append(state)
    return out


def _solve_at(face, eq, zones, totals, P, jacobian=None):
    lo, hi = face.extent
    e = replace(eq, load=P)
    zs, ts, sol, J = e.solve_ends(zones, totals, lo=lo, hi=hi, jacobian=jacobian)
    return ZoneState(P, tuple(zs), tuple(ts), sol, J)


def _predict(state, P):
    """Scale each zone about its centre (free ends only) like sqrt(load), index-1 loads like
    the load."""
    r = P / state.load
    g = math.sqrt(r)
    out = []
    for z in state.zones:
        m = 0.5 * (z.c + z.d)
        c = z.c if z.left == CORNER else (m - g * (m - z.c) if z.right == FREE else z.d - g * z.width)
        d = z.d if z.right == CORNER else (m + g * (z.d - m) if z.left == FREE else z.c + g * z.width)
        out.append(replace(z, c=c, d=d))
    totals = [None if t is None else t * r for t in state.totals]
    return out, totals


def _advance(face, eq, state, P):
    """From ``state`` to load P, stepping and handling events."""
    if state.load < P:
        new = _try_step(face, eq, state, P)         # one step when the topology holds
        if new is not None:
            return new
    while state.load < P:
        target = min(P, state.load * _GROWTH)
        new = _try_step(face, eq, state, target)
        if new is None:
            new = _bisect_event(face, eq, state, target)
        state = new
    return state


def _try_step(face, eq, state, P):
    """The state at load P from ``state`` if the zone topology holds there (Newton converges,
    no end beyond the face, gaps open, no penetration), else None."""
    zones, totals = _predict(state, P)
    lo, hi = face.extent
    zones = _clip(zones, lo, hi)
    if zones is None:
        return None
    # the previous step's Jacobian first (Broyden keeps it current); a fresh one if that fails
    for jac in ((state.jacobian, None) if state.jacobian is not None else (None,)):
        try:
            new = _solve_at(face, eq, zones, totals, P, jac)
        except ContactLossError:
            continue
        if not _violations(face, eq, new):
            return new
    return None


def _clip(zones, lo, hi):
    """The zones cut to [lo, hi], or None when they no longer are ordered with gaps."""
    out = [replace(z, c=max(z.c, lo), d=min(z.d, hi)) for z in zones]
    return out if _ordered(out, lo, hi) else None


def _violations(face, eq, state):
    """True when the state breaks a condition that needs another topology: p < 0 inside a
    zone, the gap negative outside the zones."""
    sol = state.solution
    tol = _resolution(sol)
    for j, z in enumerate(state.zones):
        X = z.points(_CHECK_U)
        if np.min(sol(X)) < -tol * np.max(np.abs(sol(X))):
            return True
    if face.convex and len(state.zones) == 1:
        return False                     # a nondecreasing slope: the gap opens by itself
    g, X = _gap_samples(face, eq, state)
    if g.size == 0:                      # the zones cover the face
        return False
    scale = face.rise_scale(state)
    return bool(np.min(g) < -tol * scale)


def _resolution(sol):
    """What the checks forgive: 1e-9, or the size of the last two Jacobi coefficients
    relative to the largest (times 10) when n does not resolve p (a kink without breaks at a
    small n: wiggles of that size are truncation, not a lost contact)."""
    tails = []
    for c in (sol.coefficients if np.ndim(sol.kappa) else (sol.coefficients,)):
        c = np.abs(np.asarray(c))
        if c.size > 2 and c.max() > 0:
            tails.append(10.0 * (c[-1] + c[-2]) / c.max())
    return max([1e-9] + tails)


def _gap_samples(face, eq, state, m=400):
    """The gap g = H - v - v0 at points of the face outside the zones, from g(c_1) = 0:
    v' = N12 mu_f p + N11 Hc[p], so across the zones left of X the friction term adds
    N12 mu_f times their loads, and
        g(X) = H(X) - H(c_1) - N12 mu_f int_{c_1}^X p + N11 (V(X) - V(c_1))."""
    X = face.sample_points(state.zones, m)
    if X.size == 0:
        return X, X
    zones, sol = state.zones, state.solution
    ref = zones[0].c
    V = sol.log_potential(np.concatenate([[ref], X]))
    g = face.rise_from(ref, X) + eq.b * (V[1:] - V[0])
    if eq.a != 0.0:
        loads = [sol.integral(interval=j) for j in range(len(zones))] if len(zones) > 1 \
            else [sol.integral()]
        passed = np.zeros(X.shape)
        for z, load in zip(zones, loads):
            passed += np.where(X >= z.d, load, 0.0)
        g = g - eq.a * passed
    return g, X


def _bisect_event(face, eq, state, P):
    """The load in (state.load, P] where the topology must change, and the state just past
    it with the new topology: the step is halved (in log load) until one of the candidate
    topologies (:func:`_candidates`) solves without violations just past the last good load.
    A candidate is accepted only when it is valid there (p >= 0 in every zone, gap >= 0 on
    the face), so an event is never moved to where it does not belong."""
    lo_state, hi_load = state, P
    while True:
        for zones, totals in _candidates(face, eq, lo_state):
            if not _ordered(zones, *face.extent):
                continue
            try:
                new = _solve_at(face, eq, zones, totals, hi_load)
            except ContactLossError:
                continue
            if not _violations(face, eq, new):
                return new
        if hi_load / lo_state.load - 1.0 <= _MIN_RATIO:
            raise ContactLossError(
                f"the contact zones cannot be followed past load {lo_state.load:.6g} (zones "
                f"{[(z.c, z.d) for z in lo_state.zones]}): no change of the zones (an end at "
                "an edge of the face, two zones merging, a new zone) gives a valid contact")
        mid = math.sqrt(lo_state.load * hi_load)
        new = _try_step(face, eq, lo_state, mid)
        if new is None:
            hi_load = mid
        else:
            lo_state = new


def _candidates(face, eq, state):
    """Topologies to try just past ``state``: free ends next to an edge become corners; the
    two zones with the narrowest gap merge; a new zone where the gap is smallest."""
    lo, hi = face.extent
    zones, totals = list(state.zones), list(state.totals)

    def load_of(j):
        return state.solution.integral(interval=j) if len(zones) > 1 else \
            state.solution.integral()

    # ends at an edge -> corners (within 1e-3 of the zone width)
    cz, ct, changed = list(zones), list(totals), False
    for j, z in enumerate(cz):
        if z.left == FREE and z.c - lo <= 1e-3 * z.width:
            cz[j] = z = replace(z, c=lo, left=CORNER)
            changed = True
        if z.right == FREE and hi - z.d <= 1e-3 * z.width:
            cz[j] = z = replace(z, d=hi, right=CORNER)
            changed = True
        if z.kappa == 1 and ct[j] is None:
            ct[j] = load_of(j)
    if changed:
        yield cz, ct
    # merge the pair with the narrowest gap
    if len(zones) > 1:
        gaps = [zones[j + 1].c - zones[j].d for j in range(len(zones) - 1)]
        j = int(np.argmin(gaps))
        a, b = zones[j], zones[j + 1]
        m = Zone(a.c, b.d, a.left, b.right)
        t = None if m.kappa != 1 else load_of(j) + load_of(j + 1)
        yield zones[:j] + [m] + zones[j + 2:], totals[:j] + [t] + totals[j + 2:]
    # a new zone where the gap is smallest
    g, X = _gap_samples(face, eq, state)
    if g.size == 0:
        return
    k = int(np.argmin(g))
    x0 = float(X[k])
    w = 1e-3 * max(z.width for z in zones)
    pos = sum(1 for z in zones if z.d < x0)
    nz = Zone(max(lo, x0 - 0.5 * w), min(hi, x0 + 0.5 * w))
    yield zones[:pos] + [nz] + zones[pos:], totals[:pos] + [None] + totals[pos:]
