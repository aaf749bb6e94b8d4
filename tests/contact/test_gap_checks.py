"""The validity checks of a contact state and what they may leave out.

* A face whose slope is nondecreasing (convex) opens its gap by itself around one zone: its
  gap is not sampled.  The library's punches say so; a ProfilePunch is read from its slope
  (``Face.opens_by_itself``), and any decrease of the slope at the samples makes it a face
  whose gap is checked.
* The step that lands on the load ``contact.solve`` asks for leaves its gap to the check of
  the refined state; where that check fails the load is followed again with every check, so
  the zones and the events are those of a continuation that checks every state.
* With breaks inside a zone, p is the series plus the pointwise correction that carries the
  kinks: the checks forgive rounding only, not the size of the series' tail.

References: the rounded flat punch (Ciavarella, Hills & Monno 1998,
tests/reference/rounded_flat_reference.py) for the growth law P ~ delta^(3/2) of a contact spreading
from the ends of a flat; the load curve through every check for the deferred step.
"""
import numpy as np
import pytest

import contact
import rounded_flat_reference as RF
from contact.continuation import _growth_exponent, _resolution
from contact.zones import FREE, Zone

MAT = contact.Isotropic(1.0, 0.3)
B, R = 1.0, 50.0


def _rounded_flat(X):
    X = np.asarray(X, dtype=float)
    return np.where(np.abs(X) < B, 0.0, (np.abs(X) - B) * np.sign(X) / R)


def _flanked_flat(X):
    """The rounded flat whose flanks flatten beyond |X| = 4: its slope falls there."""
    X = np.asarray(X, dtype=float)
    r = np.abs(X)
    s = np.where(r < 4.0, np.maximum(r - B, 0.0) / R, 3.0 / R * (0.8 + 0.2 * np.exp(4.0 - r)))
    return np.sign(X) * s


def _tilted_w(A=0.05, tilt=0.01):
    """A W face whose right valley is higher: it touches in the left one, and the right one
    closes at P ~ 0.11 (speed 0.6, Zhou's material)."""
    return contact.ProfilePunch(lambda X: 4 * A * X * (X * X - 1.0) + tilt,
                                height=lambda X: A * (X * X - 1.0) ** 2 + tilt * X,
                                face=(-2.0, 2.0))


@pytest.mark.parametrize("slope, breaks, convex", [
    (_rounded_flat, (-B, B), True),
    (lambda X: np.sinh(X), (), True),
    (lambda X: X / 50.0 + 0.1 * np.sign(X), (0.0,), True),          # a V with a rounded tip
    (_flanked_flat, (-4.0, -B, B, 4.0), False),
    (lambda X: 0.2 * X * (X * X - 1.0), (), False),                  # the W face
    (lambda X: X / 10.0 - 0.05 * (X > 1.0), (1.0,), False),          # the slope jumps down
    # a dip of the slope 0.05 wide at X = 2 (it stays positive: H rises on)
    (lambda X: X / 50.0 - 0.02 * np.exp(-((X - 2.0) / 0.05) ** 2), (), False),
])
def test_a_face_is_convex_when_its_slope_never_falls(slope, breaks, convex):
    face = contact.ProfilePunch(slope, breaks=breaks).as_face()
    assert face.opens_by_itself is convex


def test_a_convex_face_solves_the_same_with_and_without_its_gap_check():
    """The rounded flat (convex: its gap is not sampled) gives bit for bit the zones it gives
    when its gap is checked at every state."""
    skipped = contact.solve(MAT, contact.ProfilePunch(_rounded_flat, breaks=(-B, B)),
                            load=0.05, speed=0.3, friction=0.2)
    checked_punch = contact.ProfilePunch(_rounded_flat, breaks=(-B, B))
    checked_punch.as_face()._opens = False
    checked = contact.solve(MAT, checked_punch, load=0.05, speed=0.3, friction=0.2)
    assert skipped.ends == checked.ends
    X = np.linspace(*skipped.ends, 41)[1:-1]
    assert np.array_equal(skipped.pressure(X), checked.pressure(X))


def test_a_step_past_a_new_zone_is_followed_again_with_every_check(monkeypatch):
    """At P = 0.2 the tilted W face touches in both valleys; the step from first touch lands
    on one zone (its gap unchecked), whose refined check fails: the load is followed again
    with every check.  The zones and the "new zone" event are those of the load curve that
    checks each state on its way (0.01, then 0.2)."""
    import contact.solver as S
    again = []
    real = S.follow_last_again
    monkeypatch.setattr(S, "follow_last_again", lambda *a: again.append(1) or real(*a))
    w, mat = _tilted_w(), contact.zhou2014()
    direct = contact.load_curve(mat, w, [0.2], speed=0.6)
    assert again == [1]                 # the step from first touch landed on one zone
    stepped = contact.load_curve(mat, w, [0.01, 0.2], speed=0.6)
    assert len(direct.results[-1].zones) == len(stepped.results[-1].zones) == 2
    for a, b in zip(direct.results[-1].zones, stepped.results[-1].zones):
        assert a.ends == pytest.approx(b.ends, abs=1e-12)
    (e1,), (e2,) = direct.events, stepped.events
    assert (e1.kind, e1.zone) == (e2.kind, e2.zone) == ("new zone", 1)
    assert e1.load == pytest.approx(e2.load, rel=1e-9)
    solved = contact.solve(mat, w, load=0.2, speed=0.6)
    assert [z.ends for z in solved.zones] == [z.ends for z in direct.results[-1].zones]


def test_a_zone_spreading_from_a_flat_grows_like_the_rounded_flat_punch():
    """The continuation's first guess for a zone spreading from the ends of a flat stretch:
    P ~ delta^(d + 1/2) for a slope ~ (|X| - b)^d beyond them, d = 1 here.  Ciavarella's
    closed form, P = -a^2 g(eps) / (N11 R), eps = arccos(b / a), has that law as a -> b:
    its log-log slope at delta = 1e-6 b is 3/2 to 1e-5."""
    face = contact.ProfilePunch(_rounded_flat, breaks=(-B, B)).as_face()
    w = 1e-3 * face.scale
    seed = Zone(-B - 0.5 * w, B + 0.5 * w, FREE, FREE)
    assert _growth_exponent(face, seed, (-B, B), w) == pytest.approx(1.5, abs=1e-12)
    N11 = contact.surface_constants(MAT, 0.0).N11
    d = 1e-6 * B
    P1, P2 = (RF.load_for_half_width(B + x, B, R, N11) for x in (d, 1.01 * d))
    assert np.log(P2 / P1) / np.log(1.01) == pytest.approx(1.5, abs=1e-5)


def test_a_zone_with_breaks_forgives_rounding_only():
    """The rounded flat's series at n = 24 has a tail of ~6 % of its largest coefficient (the
    projection of a kinked slope); its pressure, series plus correction, is exact to the
    quadrature, and its checks forgive 1e-9, not that tail."""
    r = contact.solve(MAT, contact.ProfilePunch(_rounded_flat, breaks=(-B, B)), load=0.05,
                      speed=0.0)
    (piece,) = r.solution.pieces
    assert piece.has_breaks
    assert contact.continuation.series_tail(piece.coefficients) > 1e-3
    assert _resolution(r.solution) == 1e-9
    # the pressure itself: Ciavarella's closed form to 1e-10 of its peak
    a = RF.half_width_for_load(0.05, B, R, contact.surface_constants(MAT, 0.0).N11)
    X = np.linspace(-a, a, 81)[1:-1]
    want = RF.pressure(X, a, B, R, contact.surface_constants(MAT, 0.0).N11)
    assert np.max(np.abs(r.pressure(X) - want)) <= 1e-10 * np.max(want)
