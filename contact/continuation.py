"""The contact zones along a load curve, from first touch.

The face first touches at its lowest point(s); the load then grows in steps, and after each
step the zones are checked and changed where the physics says so (each change is an
:class:`Event`):

* a free end that reaches an edge of the face becomes a corner there (the pressure turns
  singular; the end stops moving): "edge";
* two neighbouring zones whose gap closes merge into one: "merge";
* a point of the face outside the zones that the surface would cross (gap < 0) starts a new
  zone there: "new zone";
* a zone whose pressure turns negative inside (away from its ends) loses contact there and
  becomes two zones: "split".  (Under a growing load the zones of a rigid punch only grow --
  the increment is a flat punch on the current zones, with a positive pressure -- so this
  one is there for completeness.)

Steps.  Newton's method (:mod:`contact.zones`) follows the ends from a prediction:

* with earlier states of the same topology, each free end is extrapolated from the last two
  to four loads, as a polynomial in log(P - P0) of log|end - anchor| (a power law about the
  point the zone grows from, exact on a face homogeneous about it; P0 = 0 from first touch,
  the load of the last event after one);
* from first touch, each zone by the face's local power law (a slope like |X - x0|^d about
  the lowest point x0: load ~ size^(d + 1), d from ``Face.homogeneous`` or measured); a zone
  at an interior minimum of a face that is not homogeneous about it is also placed where the
  face is equally high at both ends and sized to carry its share of the load on its own;
* else the ends as they are (Newton's first step is then the tangent).

A step that fails (Newton does not converge within its budget, or the checks fail: p >= 0 in
every zone at 64 points, gap >= 0 at 400 samples of the face) means an event before it.

Events.  Each quantity that reaches zero at an event -- a free end's distance to an edge, the
squared gap between two zones (it closes like the square root of the load to go), the
lowest valley of the gap away from the zones (located to O(h^3) of the sample spacing h), the
smallest pressure inside a zone -- is extrapolated to zero from the last two valid loads,
and the old zones are followed 99 % of the way there until the load left to go is below 1e-6
of the load (or they fail within 1e-4 of it); where no quantity predicts the failure, the
step is halved instead.  The zones after the event are solved just past it (the candidate
topology the located quantity names first, then the others) and accepted only where they are
valid.  The event load is then refined from that side: on a second state of the new zones,
what vanishes there (the smallest pressure in the merged zone, the singular factor at the new
corner, the squared gap of a split) is extrapolated back to zero; a new zone, whose load does
not vanish linearly, keeps the load located from the old side.  Measured: within 1e-10 of
the closed forms for a merge, 1e-14 for an edge.
"""
from __future__ import annotations

import functools
import math
import weakref
from dataclasses import dataclass, field, replace

import numpy as np

import sie

from .errors import ContactLossError, LoadError, PunchGeometryError
from .face import outside
from .zones import CORNER, FREE, Zone, ZoneEquations, _ordered

__all__ = ["Event", "ZoneState", "first_touch", "follow_load", "EVENT_KINDS"]

EVENT_KINDS = ("new zone", "merge", "edge", "split")
_GROWTH = 4.0          # load ratio (from the origin) of a continuation step after a failed one
_GROWTH_MAX = 256.0    # ... squared after each step that works, up to this
_CHECK_U = np.cos(np.pi * (np.arange(64) + 0.5) / 64)     # where p >= 0 is checked
_INNER = np.abs(_CHECK_U) < 0.9                           # "inside a zone" for a split
_REFINE_U = np.cos(np.pi * (np.arange(33) + 0.5) / 33)    # where n and 2n are compared
_MIN_RATIO = 1e-9      # the finest load step (relative) before giving up
_TAIL = 1e-6           # n is doubled while the last coefficients exceed this (relative),
                       # up to ZoneEquations.n_max
_EVENT_RTOL = 1e-6     # an event is located once the load left to it is below this (relative)
_CLOSE = 1e-4          # ... or once the old zones fail this close to their last valid load
_AIM = 0.99            # fraction of the way to an extrapolated event load that a step goes
_PAST = (1e-6, 1e-4, 1e-2)   # relative distances past an event where the new zones are tried
_HISTORY = 4          # states (this one and earlier ones) the predictor extrapolates from
_NEAR_VALLEY = 1e-2    # a valley of the gap below this (relative) is located more closely
_BUDGET = 16           # residual evaluations a continuation step may spend, plus 2 per unknown
_GAP_N = 2.0           # n >= _GAP_N sqrt(w / g) next to a gap g between zones of width w
_GAP_SHARE = 1e-3      # of what the gap check forgives: the log potential's error allowed


@dataclass(frozen=True)
class Event:
    """A change of the contact zones along the load.

    Attributes
    ----------
    load : float
        The load where it happens (located as described in the module docstring).
    kind : str
        "new zone", "merge", "edge" (a free end became a corner at an edge of the face) or
        "split" (a zone lost contact inside and became two).
    zone : int
        Index of the affected zone among the zones just after the event (for a split, the
        left one of the two).
    side : {"left", "right"} or None
        For an "edge" event, which end of the zone reached the face's edge (both ends of a
        zone that reach them at once are two events); None for the other kinds.

    References
    ----------
    K. L. Johnson, Contact Mechanics, Cambridge University Press (1985), ch. 5 (non-Hertzian
    contacts, whose extent is found with the load).

    Examples
    --------
    A symmetric W-shaped face: its two zones merge, then both ends of the one zone reach
    the face's edges together.

    >>> import contact
    >>> w = contact.ProfilePunch(lambda X: 0.2 * X * (X * X - 1.0),
    ...                          height=lambda X: 0.05 * (X * X - 1.0) ** 2, face=(-2.0, 2.0))
    >>> curve = contact.load_curve(contact.Isotropic(1.0, 0.3), w, [0.01, 2.0], speed=0.0)
    >>> [(e.kind, e.zone, e.side) for e in curve.events]
    [('merge', 0, None), ('edge', 0, 'left'), ('edge', 0, 'right')]
    """
    load: float
    kind: str
    zone: int
    side: str | None = None


@dataclass(frozen=True)
class ZoneState:
    """The zones at one load, their index-1 loads, the solution of the equation on them, and
    the Jacobian of the side conditions (reused by the next step of the same topology).

    ``events`` holds the :class:`Event` s located between the previous state that
    :func:`follow_load` returned and this one (first touch is the start, not an event)."""
    load: float
    zones: tuple
    totals: tuple
    solution: object
    jacobian: object = field(default=None, repr=False)
    events: tuple = ()
    # what the predictor and the event search use: per zone the points its free ends grow
    # from and the exponent of load ~ size^e (first touch), the previous valid state of the
    # same topology (load, zones, totals, checks, and up to two earlier (load, zones,
    # totals)), the validity indicators of this one, the load the zones grow from (0 from
    # first touch, the load of the last event after one), and at first touch each zone's
    # share of the load
    _anchors: tuple = field(default=None, repr=False, compare=False)
    _growth: tuple = field(default=None, repr=False, compare=False)
    _previous: object = field(default=None, repr=False, compare=False)
    _checks: object = field(default=None, repr=False, compare=False)
    _origin: float = field(default=0.0, repr=False, compare=False)
    _shares: tuple = field(default=None, repr=False, compare=False)


def _with(state, **changes):
    """``state`` with some fields changed (dataclasses.replace without its introspection)."""
    kw = {"load": state.load, "zones": state.zones, "totals": state.totals,
          "solution": state.solution, "jacobian": state.jacobian, "events": state.events,
          "_anchors": state._anchors, "_growth": state._growth,
          "_previous": state._previous, "_checks": state._checks, "_origin": state._origin,
          "_shares": state._shares}
    kw.update(changes)
    return ZoneState(**kw)


@dataclass(frozen=True)
class _Checks:
    """Validity of a state and the quantities that reach zero at an event."""
    ok: bool
    p_inner: tuple          # per zone: min p / max p over the inner check points
    p_where: tuple          # per zone: X of that minimum
    valley: float | None    # the lowest valley of the gap away from the zones / rise scale
    valley_where: float | None


# ------------------------------------------------------------------------------------------
# first touch
# ------------------------------------------------------------------------------------------
def first_touch(face, eq: ZoneEquations, width=1e-3):
    """Zones of width ~``width`` * (face scale) at the lowest point(s) of the face, and the
    load they carry (each zone on its own): the start of the continuation."""
    seed = _touch(face, eq, width)
    return list(seed.zones), seed.load


def touch_zones(face, alpha, beta, width=1e-3):
    """The first-touch zone at each lowest point of the face, for cases whose exponents
    with both ends bounded are ``alpha``, ``beta`` (arrays, one entry per case): a list
    with one (c, d, kinds, anchors) per lowest point, c and d arrays over the cases.

    A zone ~``width`` times the face's scale wide: at an edge, a corner there and a free
    end; on a flat stretch, the stretch widened at its free ends; at an interior minimum
    x0, two free ends, the centre shifted to x0 + h (beta - alpha) (h the half-width), where
    the solvability condition holds for a linear slope."""
    lo, hi = face.extent
    w = width * face.scale
    ones = np.ones(np.shape(alpha))
    out = []
    for point in face.lowest_points():
        x0, kind = point
        kinds = touch_kinds(face, point)
        if kind == "left-edge":
            c, d, anc = lo, lo + w, (lo, lo)
        elif kind == "right-edge":
            c, d, anc = hi - w, hi, (hi, hi)
        elif kind == "flat":
            cf, df = (float(v) for v in x0)
            c, d, anc = (cf if cf == lo else cf - 0.5 * w), (df if df == hi else df + 0.5 * w), \
                (cf, df)
        else:
            x0 = float(x0)
            m = x0 + 0.5 * w * (np.asarray(beta) - np.asarray(alpha))
            c, d, anc = np.maximum(lo, m - 0.5 * w), np.minimum(hi, m + 0.5 * w), (x0, x0)
        out.append((c * ones, d * ones, kinds, anc))
    return out


def touch_kinds(face, point):
    """The kinds of the ends of the first-touch zone at a lowest point (x0, kind) of
    :meth:`contact.face.Face.lowest_points`: a corner at an edge of the face, free
    elsewhere."""
    lo, hi = face.extent
    x0, kind = point
    if kind == "left-edge":
        return CORNER, FREE
    if kind == "right-edge":
        return FREE, CORNER
    if kind == "flat":
        return CORNER if x0[0] == lo else FREE, CORNER if x0[1] == hi else FREE
    return FREE, FREE


def power_law_ends(c, d, kinds, anchors, g):
    """The ends of a zone grown from its anchors by the factor ``g`` (arrays over cases, or
    numbers): each free end moved away from its anchor g-fold, corners kept (the power law
    of a face homogeneous about the anchors, Ciavarella et al. 1998 at a flat's ends)."""
    if kinds[0] == FREE and anchors[0] is not None:
        c = anchors[0] + g * (c - anchors[0])
    if kinds[1] == FREE and anchors[1] is not None:
        d = anchors[1] + g * (d - anchors[1])
    return c, d


def _touch(face, eq, width=1e-3):
    """The first-touch zones (:func:`touch_zones`) as a (not yet solved) ZoneState with
    anchors and growth exponents."""
    w = width * face.scale
    e = sie.sie_exponents(eq.a, eq.b, "bounded", "bounded")
    zones, anchors = [], []
    for c, d, kinds, anc in touch_zones(face, np.array([e.alpha]), np.array([e.beta]), width):
        zones.append(Zone(float(c[0]), float(d[0]), *kinds))
        anchors.append(anc)
    growth = tuple(_growth_exponent(face, z, anc, w) for z, anc in zip(zones, anchors))
    loads = eq.zone_loads(zones)
    known = [P for P in loads if P is not None]
    fill = sum(known) / len(known) if known else 1.0
    loads = [fill if P is None else P for P in loads]
    load0 = float(sum(loads))
    if not load0 > 0:
        hint = "" if face.breaks else (
            "; if its slope kinks or jumps there (a flat that ends where the face starts to "
            "rise), pass that X as breaks=: the collocation nodes miss a slope that starts "
            "between them")
        raise ContactLossError(
            f"the face carries no compressive load at its lowest point(s) "
            f"{face.lowest_points()}{hint}")
    totals = tuple(P if z.kappa == 1 else None for z, P in zip(zones, loads))
    return ZoneState(load0, tuple(zones), totals, None, _anchors=tuple(anchors),
                     _growth=growth, _shares=tuple(P / load0 for P in loads))


def _growth_exponent(face, z, anchors, w):
    """e in load ~ size^e for a zone growing from ``anchors``: d + 1 for a slope that
    behaves like |X - x0|^d there (the face's ``homogeneous`` degree when it is stated about
    that point, else measured from the slope at distances w and 2 w), d + 1/2 for a zone
    that grows from the ends of a flat stretch (there the flat's square-root pressure must be
    cancelled: its factor, ~P, against the slope's, int_0^delta s^d / sqrt(delta - s) ds
    ~ delta^(d + 1/2); Ciavarella et al. 1998 for the rounded flat punch, P ~ delta^(3/2));
    None for a zone without free ends."""
    if z.left == CORNER and z.right == CORNER:
        return None
    h = face.homogeneous
    if h is not None and h[0] in anchors:
        return h[1] + 1.0
    lo, hi = face.extent
    ds = []
    for side, a in ((-1.0, anchors[0]), (1.0, anchors[1])):
        if (side < 0 and z.left == CORNER) or (side > 0 and z.right == CORNER):
            continue
        X = np.array([a + side * w, a + 2.0 * side * w])
        if not (lo <= X.min() and X.max() <= hi):
            continue
        s1, s2 = (abs(float(v)) for v in face.slope(X))
        if s1 > 0.0 and s2 > 0.0:
            ds.append(min(max(math.log2(s2 / s1), 0.0), 6.0))
    grow = 0.5 if anchors[0] != anchors[1] else 1.0       # from a flat stretch's ends
    return (sum(ds) / len(ds) + grow) if ds else 1.0 + grow


# ------------------------------------------------------------------------------------------
# the load curve
# ------------------------------------------------------------------------------------------
def follow_load(face, eq: ZoneEquations, loads, final_gap=True):
    """ZoneState at each load of ``loads`` (ascending), by continuation from first touch.

    Parameters
    ----------
    face : contact.face.Face
    eq : contact.zones.ZoneEquations
        The equations (its ``load`` is replaced by each load).
    loads : sequence of float
        Ascending loads.
    final_gap : bool
        False: a step that lands on the last load directly checks p >= 0 but not the gap,
        for a caller that checks the state it makes of it in full
        (:func:`inspect_state`), and follows the load again with every check where that
        fails (a gap check is most of the cost of a state on a face with breaks).

    Returns
    -------
    list of ZoneState
        One per load; each state's ``events`` are those between the previous load (first
        touch for the first) and its own.
    """
    seed = _touch(face, eq)
    loads = [float(P) for P in loads]
    last = loads[-1] if not final_gap else None
    state = _try_step(face, eq, seed, loads[0],         # straight to the first load
                      gap=loads[0] != last)
    if state is None:
        # from a solution at the first-touch load (below it, the zones of first touch
        # shrink about the same points: the topology of first touch holds at any smaller load)
        state = _solve_at(face, eq, list(seed.zones), list(seed.totals), seed.load,
                          like=seed)
        if loads[0] < seed.load:
            z, t = _predict(state, loads[0])
            _check_representable(z, loads[0])
            state = _solve_at(face, eq, z, t, loads[0], like=state)
        state = _advance(face, eq, state, loads[0], direct=False, last=last)
    out = [state]
    for P in loads[1:]:
        out.append(_advance(face, eq, out[-1], P, last=last))
    return out


def follow_last_again(face, eq, states, loads):
    """The state at the last load reached again with every check, gap included (from the
    state at the load before, or from first touch), with the events on the way: for a
    caller of ``follow_load(..., final_gap=False)`` whose own check of the last state
    failed."""
    if len(states) > 1:
        return _advance(face, eq, states[-2], loads[-1])
    return follow_load(face, eq, loads[-1:])[0]


def _check_representable(zones, P):
    """LoadError where a zone predicted at load P is narrower than 64 rounding units of its
    position: X cannot tell its ends apart (a load of 1e-100 on a face that touches at X = 1
    makes a zone ~1e-50 wide)."""
    for z in zones:
        ulp = 64.0 * np.finfo(float).eps * max(abs(z.c), abs(z.d))
        if not z.d - z.c > ulp:
            x = 0.5 * (z.c + z.d)
            raise LoadError(
                f"load {P!r} is too small to resolve: the contact zone at X = {x:.6g} would be "
                f"narrower than {ulp:.3g}, what floating point can tell apart there; raise "
                "the load, or write X from an origin nearer to where the face touches")


def _solve_at(face, eq, zones, totals, P, jacobian=None, like=None, previous=None,
              budget=None):
    """The zones at load P by Newton from ``zones``; anchors and growth from ``like``."""
    lo, hi = face.extent
    e = replace(eq, load=P, n=_n_for_gaps(eq, zones))
    zs, ts, sol, J = e.solve_ends(zones, totals, lo=lo, hi=hi, jacobian=jacobian,
                                  budget=budget)
    same = like is not None and len(like.zones) == len(zs)
    return ZoneState(P, tuple(zs), tuple(ts), sol, J, _anchors=like._anchors if same else None,
                     _growth=like._growth if same else None, _previous=previous,
                     _origin=like._origin if same else 0.0)


def _n_for_gaps(eq, zones):
    """eq.n, doubled (up to ``eq.n_max``) until it is at least _GAP_N sqrt(w / g) for the
    narrowest gap g between two zones and the wider w of the two: the pressure next to a
    free end across a gap varies on the scale of the gap, which a series of n terms resolves
    once n^2 g / w is large (a gap that closes like the square root of the load to go, as
    two zones merge, would otherwise leave Newton's method unresolved states to follow)."""
    n = eq.n
    n_max = eq.n_max if eq.n_max is not None else eq.n
    for z0, z1 in zip(zones[:-1], zones[1:]):
        g = z1.c - z0.d
        need = _GAP_N * math.sqrt(max(z0.width, z1.width) / g) if g > 0.0 else math.inf
        while n < need and 2 * n <= n_max:
            n *= 2
    return n


def _extrapolate(xs, loads, anchor, P, origin=0.0):
    """An end (or a load) at load P from its values ``xs`` at ``loads`` (the most recent
    first, two to four): the Lagrange polynomial in log(P - origin) of log|x - anchor| (a
    power law about the anchor, exact on a homogeneous face) when all lie on one side of the
    anchor, else of x itself; only the last two points for a step much longer than theirs."""
    tp = math.log(P - origin)
    t = [math.log(L - origin) for L in loads]
    if len(t) > 2 and abs(tp - t[0]) > 1.5 * abs(t[0] - t[1]):
        t, xs = t[:2], xs[:2]       # far beyond the points: a polynomial would run away
    y = list(xs)
    sign = 0.0
    if anchor is not None:
        r = [x - anchor for x in xs]
        if all(v > 0.0 for v in r) or all(v < 0.0 for v in r):
            sign = math.copysign(1.0, r[0])
            y = [math.log(abs(v)) for v in r]
    out = 0.0
    for i, (ti, yi) in enumerate(zip(t, y)):
        w = 1.0
        for k, tk in enumerate(t):
            if k != i:
                w *= (tp - tk) / (ti - tk)
        out += w * yi
    return anchor + sign * math.exp(min(out, 700.0)) if sign else out


def _predict(state, P, face=None, eq=None):
    """The zones and index-1 loads at load P predicted from ``state`` (module docstring):
    with previous states of the same topology, each free end extrapolated from the last
    two to four; from first touch (or an event), the power law of each zone that has one;
    else the ends unchanged (Newton's first step is then the tangent).  Loads count from
    the state's origin (0, or the last event's load)."""
    origin = state._origin
    r = (P - origin) / (state.load - origin)
    history = [(state.load, state.zones, state.totals)]
    prev = state._previous
    if prev is not None:
        history.append(prev[:3])
        history.extend(prev[4])
    loads = [h[0] for h in history]
    anchors = state._anchors or [(None, None)] * len(state.zones)
    growth = state._growth or [None] * len(state.zones)
    zones, totals = [], []
    for j, (z, t) in enumerate(zip(state.zones, state.totals)):
        a_l, a_r = anchors[j]
        c, d = z.c, z.d
        if len(history) > 1:
            if z.left == FREE:
                c = _extrapolate([h[1][j].c for h in history], loads, a_l, P, origin)
            if z.right == FREE:
                d = _extrapolate([h[1][j].d for h in history], loads, a_r, P, origin)
            if t is not None:
                t = _extrapolate([h[2][j] for h in history], loads, 0.0, P, origin)
        else:
            g = 1.0 if growth[j] is None else r ** (1.0 / growth[j])
            c, d = power_law_ends(z.c, z.d, (z.left, z.right), (a_l, a_r), g)
            if face is not None and state.solution is None and a_l == a_r is not None \
                    and z.left == z.right == FREE and growth[j] is not None and \
                    (face.homogeneous is None or face.homogeneous[0] != a_l):
                # from first touch at an interior minimum: the predicted width placed where
                # the face is equally high at both ends (exact for a symmetric valley; the
                # power law about the minimum does not see the valley's asymmetry), with the
                # seed's shift for friction
                c, d = _level_placement(face, a_l, z, c, d)
                if eq is not None:
                    # the width from the zone's own load (without the other zones), its
                    # share of P as at first touch, through the same power law
                    share = P * state._shares[j] if state._shares else None
                    lo, hi = face.extent
                    for _ in range(3 if share else 0):
                        if c < lo or d > hi:
                            break       # wider than the face: the caller clips it (an edge)
                        own = eq.zone_loads([Zone(c, d)])[0]
                        if not own > 0.0:
                            break
                        f = (share / own) ** (1.0 / growth[j])
                        if abs(f - 1.0) < 1e-3:
                            break
                        c, d = _level_placement(face, a_l, z, a_l + f * (c - a_l),
                                                a_l + f * (d - a_l))
            if t is not None:
                t = t * P / state.load
        zones.append(Zone(c, d, z.left, z.right))
        totals.append(t)
    return zones, totals


def _level_placement(face, x0, seed, c, d):
    """(c, d) of width d - c moved so that H(c) = H(d) around the minimum x0, plus the shift
    of the ``seed`` zone's centre from x0 scaled to the width (friction); (c, d) unchanged
    where the face does not rise on both sides within the width."""
    width = d - c
    lo, hi = face.extent
    a, b = max(x0 - width, lo), min(x0, hi - width)
    if not a < b:
        return c, d
    fa, fb = face.rise(a, a + width), face.rise(b, b + width)
    if not fa < 0.0 < fb:
        return c, d
    from scipy.optimize import brentq       # here: its import slows every start otherwise
    c0 = brentq(lambda u: face.rise(u, u + width), a, b, xtol=1e-6 * width)
    shift = (0.5 * (seed.c + seed.d) - x0) * width / seed.width
    c1, d1 = c0 + shift, c0 + width + shift
    return (c1, d1) if lo <= c1 and d1 <= hi else (c0, c0 + width)


def _basis_n(state):
    n = state.solution.n
    return int(n if np.ndim(n) == 0 else max(n))


def _resolved(face, eq, state):
    """(eq, state) with n doubled (up to ``eq.n_max``) while the last Jacobi coefficients
    of the solution exceed ``_TAIL`` of the largest: a face whose features are narrow
    against the contact (a dip, a protrusion under a wide zone) needs a larger n for the
    Newton steps and the checks to mean anything (the checks forgive the size of the
    unresolved tail)."""
    n_max = eq.n_max if eq.n_max is not None else eq.n
    if any(z.c < x < z.d for x in eq.breaks for z in state.zones):
        # with breaks inside, the series is the projection of a kinked slope (its tail does
        # not fall; the pointwise correction carries the kinks): n stays
        return eq, state
    while _resolution(state.solution) > _TAIL and 2 * eq.n <= n_max:
        eq = replace(eq, n=2 * eq.n)
        try:
            state = _with(_solve_at(face, eq, list(state.zones), list(state.totals),
                                    state.load, like=state), events=state.events,
                          _anchors=state._anchors, _growth=state._growth,
                          _origin=state._origin, _previous=state._previous)
        except ContactLossError:
            return eq, None
    return eq, state


def _checked_resolved(face, eq, state, gap=True):
    """``state`` with its checks when it is valid, after n is raised to resolve it
    (:func:`_resolved`; then checked again at that n), else None.  ``gap``: False checks
    p >= 0 only (:func:`follow_load`'s ``final_gap``)."""
    checks = _inspect(face, eq, state, gap)
    if not checks.ok:
        return None
    eq2, solved = _resolved(face, eq, state)
    if solved is None:
        return None
    if solved is not state:
        checks = _inspect(face, eq2, solved, gap)
        if not checks.ok:
            return None
    return _with(solved, _checks=checks)


def _advance(face, eq, state, P, direct=True, last=None):
    """From ``state`` to load P, stepping and handling events; the returned state carries
    the events located on the way.  ``direct``: try one step to P first.  n follows the
    states' needs (:func:`_resolved`).  A step that lands on the load ``last`` does not
    check the gap (:func:`follow_load`'s ``final_gap``)."""
    if state.load == P:
        return _with(state, events=())
    if state.solution is not None:
        eq = replace(eq, n=max(eq.n, _basis_n(state)))
    events = []
    tried = None
    if state.load < P and direct:
        new = _try_step(face, eq, state, P, gap=P != last)   # one step if the topology holds
        if new is not None:
            return _with(new, events=())
        tried = P
    growth = _GROWTH
    while state.load < P:
        target = min(P, state._origin + (state.load - state._origin) * growth)
        new = _try_step(face, eq, state, target, gap=target != last) \
            if target != tried else None
        tried = None
        if new is None:
            new, found = _cross_event(face, eq, state, target)
            events.extend(found)
            growth = _GROWTH
        else:
            growth = min(growth * growth, _GROWTH_MAX)     # the prediction holds: go further
        state = new
        eq = replace(eq, n=max(eq.n, _basis_n(state)))      # n as the states needed it
    return _with(state, events=tuple(events))


def _try_step(face, eq, state, P, retry=True, gap=True):
    """The state at load P from ``state`` if the zone topology holds there (Newton converges,
    no end beyond the face, gaps open, no penetration), else None.  Newton starts from the
    Jacobian of ``state``, and again from a fresh one if that fails (``retry``).  ``gap``:
    False leaves the gap unchecked (:func:`follow_load`'s ``final_gap``)."""
    zones, totals = _predict(state, P, face, eq)
    lo, hi = face.extent
    zones = _clip(zones, lo, hi)
    if zones is None:
        return None
    previous = None
    if state.solution is not None:        # a solved state (not the first-touch seed)
        older = ()
        if state._previous is not None:
            older = (state._previous[:3],) + state._previous[4][:_HISTORY - 3]
        previous = (state.load, state.zones, state.totals, state._checks, older)
    # the previous step's Jacobian first (Broyden keeps it current); a fresh one if that fails
    unknowns = sum((z.left == FREE) + (z.right == FREE) + (z.kappa == 1) for z in zones)
    budget = _BUDGET + 2 * unknowns
    for jac in ((state.jacobian, None) if state.jacobian is not None and retry
                else (state.jacobian,)):
        try:
            new = _solve_at(face, eq, zones, totals, P, jac, like=state, previous=previous,
                            budget=budget)
        except ContactLossError:
            continue
        checked = _checked_resolved(face, eq, new, gap)
        if checked is not None:
            return checked
    return None


def _clip(zones, lo, hi):
    """The zones cut to [lo, hi], or None when they no longer are ordered with gaps."""
    out = [z if lo <= z.c and z.d <= hi else Zone(max(z.c, lo), min(z.d, hi), z.left, z.right)
           for z in zones]
    return out if _ordered(out, lo, hi) else None


# ------------------------------------------------------------------------------------------
# validity
# ------------------------------------------------------------------------------------------
def _inspect(face, eq, state, gap=True):
    """The checks of a state: p >= 0 in every zone (at 64 Chebyshev points of each), the
    gap >= 0 outside the zones (400 samples of the face, and the bottom of each of its own
    valleys, :meth:`contact.face.Face.dips`; skipped for one zone on a convex face of a
    homogeneous half-space, where it opens by itself,
    :attr:`contact.face.Face.opens_by_itself`, and where ``gap`` is False),
    each to the resolution of the solution (:func:`_resolution`)."""
    sol = state.solution
    tol = _resolution(sol)
    ok = True
    p_inner, p_where = [], []
    for z, piece, (p, _) in zip(state.zones, sol.pieces,
                                zone_pressures(sol, refine=eq.n_max is not None)):
        X = z.points(_CHECK_U)
        top = pressure_top(p)
        if not pressure_holds(p, tol, top) or _lowest_dip(piece, p, top) < -tol * top:
            ok = False
        k = int(np.argmin(np.where(_INNER, p, np.inf)))
        p_inner.append(float(p[k]) / top)
        p_where.append(float(X[k]))
    valley = valley_where = None
    if gap and not (len(state.zones) == 1 and face.opens_by_itself and eq.kernel is None):
        rise = face.rise_scale(state)
        accuracy = _gap_accuracy(eq, state, tol * rise)
        g, X, gd, Xd = _gap_samples(face, eq, state, accuracy)
        if g.size:
            if np.min(g) < -tol * rise:
                ok = False
            k = _valley(face, state.zones, g, X)
            if k is not None:
                gv, xv = _vertex(g, X, k)
                if gv < _NEAR_VALLEY * rise and 0 < k < g.size - 1:
                    # close to touching: the vertex again from points 16 times closer; a
                    # valley below zero between the samples fails the state as one at them
                    h = (X[k + 1] - X[k - 1]) / 32.0
                    Xr = np.array([xv - h, xv, xv + h])
                    if np.all(outside(state.zones, Xr)):
                        gr = _gap_at(face, eq, state, Xr, tol=accuracy)
                        gv, xv = _vertex(gr, Xr, 1)
                        if np.min(gr) < -tol * rise:
                            ok = False
                valley, valley_where = gv / rise, xv
            # the face's own valleys, which a dip narrower than the samples' spacing hides
            # from them: a gap below zero there fails the state, and is its valley
            if gd.size:
                j = int(np.argmin(gd))
                if gd[j] < -tol * rise:
                    ok = False
                    if valley is None or gd[j] / rise < valley:
                        valley, valley_where = float(gd[j]) / rise, float(Xd[j])
    return _Checks(ok, tuple(p_inner), tuple(p_where), valley, valley_where)


def pressure_top(p):
    """The largest |p| of each zone's pressure at the check points (the last axis), and
    not zero."""
    return np.maximum(np.max(np.abs(p), axis=-1), np.finfo(float).tiny)


def pressure_holds(p, tol, top=None):
    """Whether p >= 0 at the check points (the last axis) to ``tol`` of its largest |p|
    (``top``, :func:`pressure_top`, when known): a zone's pressure at the check points
    (:data:`_CHECK_U`), or many zones' as rows."""
    return np.min(p, axis=-1) >= -tol * (pressure_top(p) if top is None else top)


def pressure_dips(p, top=None):
    """The interior local minima of p at the check points below 1e-2 of its largest |p|
    (``top``, :func:`pressure_top`, when known; a boolean array over the points 1 .. m - 2
    of the last axis): where the pressure may turn negative between the check points
    (:func:`_lowest_dip` polishes them)."""
    top = np.asarray(pressure_top(p) if top is None else top)[..., None]
    mid = p[..., 1:-1]
    return (mid <= p[..., :-2]) & (mid <= p[..., 2:]) & (mid < 1e-2 * top)


def _lowest_dip(piece, p, top):
    """The lowest pressure in the dips of one zone's pressure ``p`` at the check points
    (:func:`pressure_dips`), each polished by parabolas through three points, the spacing
    cut by 8 each time (a pressure that turns negative between the check points, as one
    zone just below the load where two merge, is found); inf where there is no such dip."""
    def pressure(u):                # p at local points u of the zone
        return (1.0 - u) ** piece.alpha * (1.0 + u) ** piece.beta * piece.phi_local(u)

    out = math.inf
    dips = np.flatnonzero(pressure_dips(p, top)) + 1
    for k in dips.tolist():
        u0 = float(_CHECK_U[k])
        h = 0.5 * min(_CHECK_U[k - 1] - u0, u0 - _CHECK_U[k + 1])
        u0, lowest = _parabola_minimum(pressure, u0, h, -1.0, 1.0, 6)
        out = min(out, lowest, float(pressure(np.array([u0]))[0]))
    return out


def inspect_state(face, eq, state):
    """Whether ``state`` passes :func:`_inspect` (p >= 0 in every zone, the gap >= 0 on the
    face, to the resolution of its solution)."""
    return _inspect(face, replace(eq, load=state.load, n=_basis_n(state)), state).ok


def _vertex(g, X, k):
    """The lowest gap near sample k and where it is: the vertex of the parabola through the
    samples k - 1, k, k + 1 when they are evenly spaced (the sampled minimum is high by up
    to g'' h^2 / 8 for a spacing h; the vertex, by O(h^3)), else sample k itself."""
    if 0 < k < g.size - 1:
        h0, h1 = X[k] - X[k - 1], X[k + 1] - X[k]
        curv = g[k + 1] - 2.0 * g[k] + g[k - 1]
        if abs(h1 - h0) <= 1e-9 * h1 and curv > 0.0:
            shift = 0.5 * (g[k - 1] - g[k + 1]) / curv
            if abs(shift) <= 1.0:
                return float(g[k] - 0.5 * curv * shift * shift), float(X[k] + shift * h1)
    return float(g[k]), float(X[k])


def _valley(face, zones, g, X):
    """Index of the lowest sample of the gap that is a local minimum inside a stretch of the
    face between zones, or at an edge of the face; None if there is none.  (Next to a free
    end the gap falls to zero toward the zone: that is not where a new zone starts.)"""
    stretch = np.searchsorted(np.array([z.d for z in zones]), X)
    m = g.size
    keep = np.zeros(m, dtype=bool)
    same_prev = np.concatenate([[False], stretch[1:] == stretch[:-1]])
    same_next = np.concatenate([stretch[:-1] == stretch[1:], [False]])
    inner = same_prev & same_next
    keep[1:-1] = inner[1:-1] & (g[1:-1] <= g[:-2]) & (g[1:-1] <= g[2:])
    lo, hi = face.extent
    if X[0] == lo and not (zones[0].c <= X[0]) and same_next[0] and g[0] <= g[1]:
        keep[0] = True
    if X[-1] == hi and same_prev[-1] and g[-1] <= g[-2]:
        keep[-1] = True
    if not keep.any():
        return None
    idx = np.flatnonzero(keep)
    return int(idx[np.argmin(g[idx])])


@functools.lru_cache(maxsize=64)
def _check_weight(alpha, beta, u_key="check"):
    """(1 - u)^alpha (1 + u)^beta at the check points (``u_key`` "check": _CHECK_U;
    "both": _CHECK_U and then _REFINE_U; read-only)."""
    u = _CHECK_U if u_key == "check" else _BOTH_U
    out = (1.0 - u) ** alpha * (1.0 + u) ** beta
    out.flags.writeable = False
    return out


_BOTH_U = np.concatenate([_CHECK_U, _REFINE_U])
_PRESSURES = weakref.WeakKeyDictionary()      # solution -> zone_pressures(solution)


def zone_pressures(sol, refine=False):
    """Per zone (piece) of the solution ``sol``: (p at the local check points _CHECK_U,
    p at the points _REFINE_U where :func:`contact.solver._refine` compares n and 2n, or
    None without ``refine``), read-only.  With ``refine`` phi is evaluated once at both
    sets (with breaks each evaluation sums the correction's rules: one call is cheaper than
    two); kept as long as the solution lives (a state is checked by the continuation, then
    compared with its refinement; the refinement compared, then checked)."""
    got = _PRESSURES.get(sol)
    if got is not None and (got[0][1] is not None or not refine):
        return got
    m = _CHECK_U.size
    out = []
    for k, piece in enumerate(sol.pieces):
        if got is not None:             # the check points known: the others alone
            q = _weight_at(piece.alpha, piece.beta, _REFINE_U) * piece.phi_local(_REFINE_U)
            p = got[k][0]
        elif refine:
            both = _check_weight(piece.alpha, piece.beta, "both") * piece.phi_local(_BOTH_U)
            p, q = both[:m], both[m:]
        else:
            p, q = _check_weight(piece.alpha, piece.beta) * piece.phi_local(_CHECK_U), None
        for v in (p, q):
            if v is not None:
                v.flags.writeable = False
        out.append((p, q))
    out = tuple(out)
    _PRESSURES[sol] = out
    return out


def _weight_at(alpha, beta, u):
    """(1 - u)^alpha (1 + u)^beta at points u."""
    return (1.0 - u) ** alpha * (1.0 + u) ** beta


@functools.lru_cache(maxsize=8)
def _resolution(sol):
    """What the checks forgive: 1e-9, or the size of the last two Jacobi coefficients
    relative to the largest (times 10) when n does not resolve p (a kink without breaks at a
    small n: wiggles of that size are truncation, not a lost contact).  A zone with breaks
    inside forgives only 1e-9: its series is the projection of a kinked slope, whose tail
    falls slowly at any n, and p is that series plus the pointwise correction that carries
    the kinks (:attr:`sie.solution.IntervalSolution.has_breaks`), exact to the quadrature.
    Kept for the last few solutions (immutable, hashed by identity): a state is checked,
    then tested for its resolution."""
    return max([1e-9] + [float(series_tail(piece.coefficients)) for piece in sol.pieces
                         if not piece.has_breaks])


def series_tail(C):
    """10 (|c_{n-1}| + |c_{n-2}|) / max |c| of each series along the last axis of C (0 for
    a series of two terms or fewer, or all zero): what :func:`_resolution` forgives."""
    c = np.abs(np.asarray(C))
    if c.shape[-1] <= 2:
        return np.zeros(c.shape[:-1])
    top = np.max(c, axis=-1)
    return np.where(top > 0.0, 10.0 * (c[..., -1] + c[..., -2])
                    / np.where(top > 0.0, top, 1.0), 0.0)


def _gap_samples(face, eq, state, tol=None, m=400):
    """The gap g = H - v - v0 at points of the face outside the zones, from g(c_1) = 0:
    v' = a p + b Hc[p] (a = N12 mu_f, b = N11 + M12 mu_f: ``eq.a``, ``eq.b``), so across
    the zones left of X the friction term adds a times their loads, and
        g(X) = H(X) - H(c_1) - a int_{c_1}^X p + b (V(X) - V(c_1)).
    (g, X, gd, Xd): at ``m`` samples X of the face, and at the bottom Xd of each of its own
    valleys outside the zones (:meth:`contact.face.Face.dips`), in one evaluation.  A
    layered material's kernel adds -int (K(X, t) - K(c_1, t)) p(t) dt (:mod:`contact.kernel`).
    ``tol``: the accuracy asked of V (:func:`_gap_accuracy`; None: to rounding)."""
    X = face.sample_points(state.zones, m)
    if X.size == 0:
        return X, X, X, X
    Xd = face.dips()
    Xd = Xd[outside(state.zones, Xd)]
    Xa = np.concatenate([X, Xd])
    rise = face.rise_from(state.zones[0].c, Xa)
    g = _gap_at(face, eq, state, Xa, rise, tol)
    _stays_open(face, X, g[:X.size], rise[:X.size])
    return g[:X.size], X, g[X.size:], Xd


def _stays_open(face, X, g, rise):
    """PunchGeometryError where the face, at the outermost gap sample on a side without an
    edge, has not risen above the first zone's end by twice the surface's displacement
    there (rise - g: the half-space's deflection, which grows like the logarithm of the
    distance): beyond it a face that rises on (:meth:`contact.face.Face.scan`) stays clear
    of the surface; a face that does not rise that far cannot be shown to."""
    lo, hi = face.extent
    for k, edge, name in ((0, lo, "-X"), (-1, hi, "+X")):
        if math.isfinite(edge) or not rise[k] > 0.0 or g[k] >= 0.5 * rise[k]:
            continue
        raise PunchGeometryError(
            f"the face rises only {rise[k]:.3g} above the contact toward {name} out to X = "
            f"{X[k]:.6g}, less than twice the half-space's deflection there "
            f"({rise[k] - g[k]:.3g}): contact cannot be shown to stay away from it beyond; "
            "give the face's extent (face=) where it ends")


def _gap_at(face, eq, state, X, rise=None, tol=None):
    """The gap at points X outside the zones (see :func:`_gap_samples`); ``rise``: H(X) -
    H(c_1) where known; ``tol``: the accuracy asked of V (:func:`_gap_accuracy`)."""
    zones, sol = state.zones, state.solution
    ref = zones[0].c
    V = sol.log_potential(np.concatenate([[ref], X]), tol=tol)
    g = (face.rise_from(ref, X) if rise is None else rise) + eq.b * (V[1:] - V[0])
    if eq.kernel is not None:
        K = sol.kernel_integral(eq.kernel.deflection, np.concatenate([[ref], X]))
        g = g - (K[1:] - K[0])
    if eq.a != 0.0:
        loads = [sol.integral(interval=j) for j in range(len(zones))] if len(zones) > 1 \
            else [sol.integral()]
        passed = np.zeros(X.shape)
        for z, load in zip(zones, loads):
            passed += np.where(X >= z.d, load, 0.0)
        g = g - eq.a * passed
    return g


def _gap_accuracy(eq, state, forgiven):
    """The accuracy asked of V[p] for the gap checks of ``state`` that forgive ``forgiven``
    (:func:`_resolution` times the face's rise over the contact):
    :meth:`sie.Solution.log_potential`'s tol, relative to (1/pi) int |p|, with int p over
    the zones for int |p| (p >= 0, as the pressure checks ask).  g carries b (V(X) - V(c_1)),
    off by at most 2 |b| tol (1/pi) int |p|, which is held to _GAP_SHARE of ``forgiven``:
    the check decides as with V to rounding but for gaps within 1e-3 of its threshold, and
    the valley it reports for the events (relative to the rise, extrapolated in the load)
    moves by ~1e-12, far below the tolerance to which events are located (_EVENT_RTOL).
    With breaks in the zones V is then summed on a rule graded less deeply toward them
    (:mod:`sie.remainder`).  None (to rounding) where that scale is zero."""
    scale = 2.0 * abs(eq.b) * sum(abs(p.integral()) for p in state.solution.pieces) / math.pi
    if not (scale > 0.0 and forgiven > 0.0):
        return None
    return _GAP_SHARE * forgiven / scale


# ------------------------------------------------------------------------------------------
# events
# ------------------------------------------------------------------------------------------
def _indicators(face, zones, checks):
    """{(kind, zone, side): value}: what reaches zero at each possible event (module
    docstring), in units where it is smooth in the load near the event."""
    lo, hi = face.extent
    scale = face.scale
    out = {}
    for j, z in enumerate(zones):
        if z.left == FREE and math.isfinite(lo):
            out[("edge", j, "left")] = (z.c - lo) / scale
        if z.right == FREE and math.isfinite(hi):
            out[("edge", j, "right")] = (hi - z.d) / scale
    for j in range(len(zones) - 1):
        out[("merge", j, None)] = ((zones[j + 1].c - zones[j].d) / scale) ** 2
    if checks is not None:
        if checks.valley is not None:
            out[("new zone", None, None)] = checks.valley
        for j, v in enumerate(checks.p_inner):
            out[("split", j, None)] = v
    return out


def _event_roots(face, older, newer):
    """[(load, key)]: the load where each indicator reaches zero, extrapolated linearly from
    two valid states of one topology (older, newer: (load, zones, checks)), for the
    indicators that decrease toward it; nearest first."""
    P0, z0, c0 = older
    P1, z1, c1 = newer
    i0, i1 = _indicators(face, z0, c0), _indicators(face, z1, c1)
    roots = []
    for key, v1 in i1.items():
        v0 = i0.get(key)
        if v0 is not None and v0 > v1:
            roots.append((P1 + max(v1, 0.0) * (P1 - P0) / (v0 - v1), key))
    return sorted(roots, key=lambda r: r[0])


def _cross_event(face, eq, state, P):
    """From ``state`` (valid) toward load P, where the zones of ``state`` fail: the state
    just past the event with its new zones, and the events.  See the module docstring."""
    older = state._previous
    lo_state, hi = state, P
    located = key = best = None
    for _ in range(200):
        roots = []
        if older is not None:
            roots = [r for r in _event_roots(face, older[0:2] + (older[3],),
                                              (lo_state.load, lo_state.zones,
                                               lo_state._checks))
                     if r[0] <= hi]
        located, key = roots[0] if roots else (None, None)
        if roots:
            best = roots[0]
        gap = hi / lo_state.load - 1.0
        if located is not None and located / lo_state.load - 1.0 <= _EVENT_RTOL:
            break
        if best is not None and gap <= _CLOSE:
            # the old zones fail this close to the last valid load (a merge that n does not
            # resolve): the event is in between; the new zones locate it (below)
            located, key = min(max(best[0], lo_state.load), hi), best[1]
            break
        if gap <= _MIN_RATIO:
            located, key = None, None
            break
        trial = lo_state.load + _AIM * (located - lo_state.load) if located is not None \
            else math.sqrt(lo_state.load * hi)
        new = _try_step(face, eq, lo_state, trial, retry=False)
        if new is None:
            hi = trial
        else:
            older = new._previous
            lo_state = new
    if located is None:
        located = math.sqrt(lo_state.load * hi)
    hint = key[0] if key is not None else None
    for rel in _PAST:
        P_new = min(located * (1.0 + rel), P)
        if P_new <= lo_state.load:
            continue
        for kind, zones, totals, where in _candidates(face, eq, lo_state, hint):
            new = _solve_candidate(face, eq, zones, totals, P_new, located,
                                   [j for j, _ in where] if kind == "new zone" else ())
            if new is not None:
                new, load = _refine_event(face, eq, lo_state, new, kind, where, located, P)
                return new, [Event(float(load), kind, j, side) for j, side in where]
        if rel == _PAST[0]:
            # an extrapolated zero that was not the failure: the old zones go on
            new = _try_step(face, eq, lo_state, P_new)
            if new is not None:
                return new, []
        if P_new == P:
            break
    return _bisect_event(face, eq, lo_state, P)


def _reverse_indicator(kind, where, state):
    """What vanishes at the event as the load falls back to it, on the zones after it, and is
    smooth in the load there: the smallest pressure inside the merged zone, the pressure
    factor phi at the new corner, the squared gap between the two halves of a split zone.
    (The load of a new zone also vanishes, but like (P - P_event) / log(...), as the 2-D
    contact of a curved face does: that event is located from the old zones only.)"""
    j, side = where[0]
    sol, zones = state.solution, state.zones
    multi = len(zones) > 1
    if kind == "merge":
        return _min_pressure(sol, zones[j])
    if kind == "edge":
        return sol.endpoint_value(-1 if side == "left" else 1, interval=j if multi else None)
    return (zones[j + 1].c - zones[j].d) ** 2


def _min_pressure(sol, z):
    """min p / max p inside zone z: the smallest of 64 Chebyshev points, polished by
    parabolas through three points with the spacing cut by 8 each time."""
    X = z.points(_CHECK_U)
    p = sol(X)
    top = max(float(np.max(np.abs(p))), np.finfo(float).tiny)
    k = int(np.argmin(np.where(_INNER, p, np.inf)))
    x0, _ = _parabola_minimum(sol, float(X[k]), 0.5 * z.width * math.pi / 64, z.c, z.d, 4)
    return float(sol(np.array([x0]))[0]) / top


def _parabola_minimum(f, x0, h, lo, hi, steps):
    """(x, lowest): a minimum of f near x0 polished by parabolas through f at x - h, x,
    x + h (the vertex, a step of at most h), the spacing cut by 8 each time, ``steps``
    times or until the three points leave (lo, hi); and the lowest value f took at them."""
    lowest = math.inf
    for _ in range(steps):
        pts = np.array([x0 - h, x0, x0 + h])
        if pts[0] <= lo or pts[-1] >= hi:
            break
        pm, p0, pp = f(pts)
        lowest = min(lowest, pm, p0, pp)
        curv = pp - 2.0 * p0 + pm
        if curv > 0.0:
            x0 += min(max(-0.5 * h * (pp - pm) / curv, -h), h)
        h *= 0.125
    return x0, lowest


def _refine_event(face, eq, lo_state, new, kind, where, located, P):
    """The event load from the side of the new zones: a second state of the new topology
    (twice as far from the last valid old load), and the indicator of
    :func:`_reverse_indicator` extrapolated linearly from the two to zero.  Returns that
    second state (or ``new``) and the load (``located`` where the extrapolation does not
    land between the last old and the second new load)."""
    P2 = new.load + (new.load - lo_state.load)
    if kind == "new zone":
        # (a new zone's load is not linear in the load: no extrapolation from this side)
        second = _try_step(face, eq, new, P2) if P2 <= P else None
        return (new if second is None else second), located
    # the second state may lie past P (where the load curve stops): it then serves the
    # extrapolation alone, and the state returned is ``new``
    second = _try_step(face, eq, new, P2)
    if second is None:
        return new, located
    keep = second if P2 <= P else new
    v1 = _reverse_indicator(kind, where, new)
    v2 = _reverse_indicator(kind, where, second)
    if not v2 > v1:
        return keep, located
    root = new.load - v1 * (second.load - new.load) / (v2 - v1)
    if not lo_state.load * (1.0 - 1e-12) <= root <= second.load * (1.0 + 1e-12):
        return keep, located
    return keep, min(max(root, lo_state.load), keep.load)


def _solve_candidate(face, eq, zones, totals, P, origin=0.0, young=()):
    """A candidate topology solved at load P, or None where it fails or is not valid.  The
    zones then grow from load ``origin`` (the event's), the new zones ``young`` like the
    square root of the load since (a zone on a smooth valley of the gap), each about its
    corner, or its centre if it has none."""
    if not _ordered(zones, *face.extent):
        return None
    try:
        new = _solve_at(face, eq, zones, totals, P)
    except ContactLossError:
        return None
    anchors = tuple((z.c,) * 2 if z.left == CORNER else (z.d,) * 2 if z.right == CORNER
                    else (0.5 * (z.c + z.d),) * 2 for z in new.zones)
    growth = tuple(2.0 if j in young else None for j in range(len(new.zones)))
    new = _with(new, _anchors=anchors, _growth=growth,
                _origin=origin if origin < P else 0.0)
    return _checked_resolved(face, eq, new)


def _bisect_event(face, eq, state, P):
    """The load in (state.load, P] where the topology must change, and the state just past
    it with the new topology: the step is halved (in log load) until one of the candidate
    topologies (:func:`_candidates`) solves without violations just past the last good load.
    A candidate is accepted only when it is valid there (p >= 0 in every zone, gap >= 0 on
    the face), so an event is never moved to where it does not belong."""
    lo_state, hi_load = state, P
    while True:
        for kind, zones, totals, where in _candidates(face, eq, lo_state, None):
            new = _solve_candidate(face, eq, zones, totals, hi_load)
            if new is not None:
                load = math.sqrt(lo_state.load * hi_load)
                return new, [Event(float(load), kind, j, side) for j, side in where]
        if hi_load / lo_state.load - 1.0 <= _MIN_RATIO:
            raise ContactLossError(
                f"the contact zones cannot be followed past load {lo_state.load:.6g} (zones "
                f"{[(z.c, z.d) for z in lo_state.zones]}): no change of the zones (an end at "
                "an edge of the face, two zones merging, a new zone, a zone splitting) gives "
                "a valid contact" + ("" if face.breaks else
                                     "; if the slope jumps or kinks (a wedge's apex, a rounded "
                                     "corner), pass its X positions as breaks="))
        mid = math.sqrt(lo_state.load * hi_load)
        new = _try_step(face, eq, lo_state, mid)
        if new is None:
            hi_load = mid
        else:
            lo_state = new


def _negative_stretch(sol, z, x):
    """Where a split of zone z at x (its smallest pressure) starts its gap: the stretch
    around x where p < 0 (between check points), at least 1e-3 of the zone's width."""
    X = z.points(_CHECK_U[::-1])
    p = sol(X)
    k = int(np.argmin(np.abs(X - x)))
    i0 = i1 = k
    while i0 > 0 and p[i0 - 1] < 0.0:
        i0 -= 1
    while i1 < X.size - 1 and p[i1 + 1] < 0.0:
        i1 += 1
    g0 = 0.5 * (X[i0] + X[i0 - 1]) if p[k] < 0.0 and i0 > 0 else x
    g1 = 0.5 * (X[i1] + X[i1 + 1]) if p[k] < 0.0 and i1 < X.size - 1 else x
    half = 0.5e-3 * z.width
    return min(g0, x - half), max(g1, x + half)


def _candidates(face, eq, state, hint):
    """(kind, zones, totals, where) to try just past ``state``, ``where`` listing (index of
    the affected zone among the new zones, "left" / "right" for the end that became a corner,
    else None): free ends next to an edge become corners (those that reach it together,
    then the nearest alone, then all within 1e-3 of their zone's width); the two zones with
    the narrowest gap merge; a new zone where the gap has its lowest valley; a zone splits
    where its pressure is smallest (the stretch where it is negative becomes the gap).  The
    kind ``hint`` comes first."""
    lo, hi = face.extent
    zones, totals = list(state.zones), list(state.totals)
    checks = state._checks if state._checks is not None else _inspect(face, eq, state)
    multi = len(zones) > 1

    def load_of(j):
        return state.solution.integral(interval=j) if multi else state.solution.integral()

    def edge():
        near = []
        for j, z in enumerate(zones):
            if z.left == FREE and z.c - lo <= 1e-3 * z.width:
                near.append(((z.c - lo) / z.width, j, "left"))
            if z.right == FREE and hi - z.d <= 1e-3 * z.width:
                near.append(((hi - z.d) / z.width, j, "right"))
        if not near:
            return
        near.sort()
        first = [e for e in near if e[0] <= 10.0 * near[0][0] + 1e-12]   # reached together
        tried = []
        for chosen in (first, near[:1], near):
            if chosen in tried:
                continue
            tried.append(chosen)
            cz, ct = list(zones), list(totals)
            for _, j, side in chosen:
                z = cz[j]
                cz[j] = replace(z, c=lo, left=CORNER) if side == "left" else \
                    replace(z, d=hi, right=CORNER)
            for j, z in enumerate(cz):
                if z.kappa == 1 and ct[j] is None:
                    ct[j] = load_of(j)
            yield "edge", cz, ct, [(j, side) for _, j, side in sorted(chosen, key=lambda e: e[1:])]

    def merge():
        if not multi:
            return
        gaps = [zones[j + 1].c - zones[j].d for j in range(len(zones) - 1)]
        j = int(np.argmin(gaps))
        a, b = zones[j], zones[j + 1]
        m = Zone(a.c, b.d, a.left, b.right)
        t = None if m.kappa != 1 else load_of(j) + load_of(j + 1)
        yield "merge", zones[:j] + [m] + zones[j + 2:], totals[:j] + [t] + totals[j + 2:], \
            [(j, None)]

    def new_zone():
        if checks.valley_where is None:
            return
        x0 = checks.valley_where
        w = 1e-3 * max(z.width for z in zones)
        pos = sum(1 for z in zones if z.d < x0)
        if x0 <= lo:                    # the edge of the face touches: a corner there
            nz = Zone(lo, lo + w, CORNER, FREE)
        elif x0 >= hi:
            nz = Zone(hi - w, hi, FREE, CORNER)
        else:
            nz = Zone(max(lo, x0 - 0.5 * w), min(hi, x0 + 0.5 * w))
        yield "new zone", zones[:pos] + [nz] + zones[pos:], \
            totals[:pos] + [None] + totals[pos:], [(pos, None)]

    def split():
        for j in np.argsort(checks.p_inner):
            j = int(j)
            if checks.p_inner[j] > 1e-3:
                break
            z, x = zones[j], checks.p_where[j]
            g0, g1 = _negative_stretch(state.solution, z, x)
            a = Zone(z.c, g0, z.left, FREE)
            b = Zone(g1, z.d, FREE, z.right)
            ta = None if a.kappa != 1 else 0.5 * load_of(j)
            tb = None if b.kappa != 1 else 0.5 * load_of(j)
            yield "split", zones[:j] + [a, b] + zones[j + 1:], \
                totals[:j] + [ta, tb] + totals[j + 1:], [(j, None)]
            break

    order = {"edge": edge, "merge": merge, "new zone": new_zone, "split": split}
    kinds = list(order)
    if hint in order:
        kinds.remove(hint)
        kinds.insert(0, hint)
    for kind in kinds:
        yield from order[kind]()
