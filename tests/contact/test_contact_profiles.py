"""contact.load_curve / contact.solve on custom faces, through the public API, over the matrix
of speeds, friction, directions and loads of the "contact 2" acceptance list.

Every result is checked against conditions computed here, independently of the solver's own
checks (which use the log potential of the pressure):

* the load: the zones' integrals of p sum to P (to 1e-12, or to what the rounding of the
  ends' absolute positions allows, eps |X| / l, l the zone's width or a free end's distance
  to the nearest break, when l is far below |X|);
* p >= 0 inside every zone;
* the gap g >= 0 on the face outside the zones, g obtained by integrating its slope
  g' = H' - N11 Hc[p] (p = 0 there) from the nearest zone end, where g = 0, by graded
  Gauss-Legendre;
* where the zones reach an edge of the face, that end is a corner.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import contact

MAT = contact.zhou2014()
SPEEDS = (0.0, 0.3, 0.6, 0.9)
FRICTION = ((0.0, -1), (0.3, -1), (0.3, 1))
LOADS = np.geomspace(1e-6, 1e2, 9)

_B, _R, _M0 = 0.5, 3.0, 0.05
_XS = np.linspace(-2.0, 2.0, 200)


def _faces():
    return {
        # an asymmetric bump on the face [-1, 1]
        "bump": contact.ProfilePunch(lambda X: X / 100 + X * X / 100,
                                     height=lambda X: X * X / 200 + X ** 3 / 300,
                                     face=(-1.0, 1.0)),
        # W face: two valleys at +-1, two zones that merge
        "W": contact.ProfilePunch(lambda X: 0.2 * X * (X * X - 1.0),
                                  height=lambda X: 0.05 * (X * X - 1.0) ** 2, face=(-2.0, 2.0)),
        # flat on |X| <= b, rounded with radius R beyond (slope continuous, kinks in H'')
        "rounded flat": contact.ProfilePunch(
            lambda X: np.where(np.abs(X) > _B, np.sign(X) * (np.abs(X) - _B) / _R, 0.0),
            height=lambda X: np.where(np.abs(X) > _B, (np.abs(X) - _B) ** 2 / (2 * _R), 0.0),
            breaks=(-_B, _B), face=(-3.0, 3.0)),
        # a flat face tilted by a constant slope: one end lifts off
        "tilted flat": contact.ProfilePunch(lambda X: np.full_like(X, _M0),
                                            height=lambda X: _M0 * X, face=(-1.0, 1.0)),
        # a cylinder R = 100 tabulated at 200 points on [-2, 2]
        "sampled cylinder": contact.ProfilePunch.from_samples(_XS, _XS ** 2 / 200.0),
        "flat": contact.FlatPunch(half_width=0.5),
        "triangular": contact.TriangularPunch(slope=0.1),
        "parabolic": contact.ParabolicPunch(radius=10.0),
        "cylindrical": contact.CylindricalPunch(radius=100.0),
    }


FACES = _faces()
#: the load curves of every face at rest, at a moderate speed and near the Rayleigh speed;
#: the bump (two zones that appear and merge, its slowest curves) at rest and near c_R
# every face at c = 0, 0.6 and 0.9 with every friction; the bump (the slowest face, 4 to
# 11 s a case) only at c = 0.9 with friction toward -X
LOAD_RANGE_CASES = [(name, speed, friction, direction)
                    for name in FACES for speed in (0.0, 0.6, 0.9)
                    for friction, direction in FRICTION
                    if name != "bump" or (speed == 0.9 and direction == -1 and friction > 0)]


def _gap(res, X, m=32):
    """g(X) at points X outside the zones: int_e^X (H' - N11 Hc[p]) dt from the nearest zone
    end e (no zone in between), t = e + (X - e) s^2 (graded toward e, where Hc[p] behaves like
    |t - e|^(1/2) next to a free end and |t - e|^(-alpha) next to a corner)."""
    ends = np.array([e for z in res.zones for e in z.ends])
    u, w = np.polynomial.legendre.leggauss(m)
    s, ws = 0.5 * (u + 1.0), 0.5 * w
    e = ends[np.argmin(np.abs(X[:, None] - ends[None, :]), axis=1)]
    T = e[:, None] + (X - e)[:, None] * s[None, :] ** 2
    J = 2.0 * s[None, :] * (X - e)[:, None]
    dg = res.punch.slope(T) - res.constants.N11 * res.hilbert_pressure(T)
    return np.sum(ws[None, :] * J * dg, axis=1)


def _outside_points(res, per_gap=12):
    """Points of the face outside the zones: Chebyshev points of each gap between zones and
    of the stretches from the outer ends to the face's edges (or 4 widths beyond them)."""
    lo, hi = res.punch.extent
    zs = res.zones
    span = zs[-1].ends[1] - zs[0].ends[0]
    left = lo if math.isfinite(lo) else zs[0].ends[0] - 4 * span
    right = hi if math.isfinite(hi) else zs[-1].ends[1] + 4 * span
    stretches = [(left, zs[0].ends[0])] + [(a.ends[1], b.ends[0]) for a, b in zip(zs, zs[1:])] \
        + [(zs[-1].ends[1], right)]
    u = 0.5 * (1 - np.cos(np.pi * (np.arange(per_gap) + 0.5) / per_gap))
    pts = [a + (b - a) * u for a, b in stretches if b - a > 1e-12 * span]
    return np.concatenate(pts) if pts else np.zeros(0)


def check_contact(res):
    """The independent checks of the module docstring."""
    P = res.load
    # the load moves with a free end on the scale of the zone's width or of its distance to
    # the nearest break (a flat stretch's edge: P ~ delta^(3/2)); the end itself is rounded
    # to eps |X|
    breaks = np.array(res.punch.breaks)
    lengths = [z.width for z in res.zones]
    for z in res.zones:
        for e, kind in zip(z.ends, z.kinds):
            if kind == "free" and breaks.size:
                lengths.append(np.min(np.abs(breaks - e)))
    reach = max(abs(e) for z in res.zones for e in z.ends)
    tol_load = max(1e-12, 4 * np.finfo(float).eps * reach / min(lengths))
    total = sum(z.load for z in res.zones)
    assert abs(total - P) <= tol_load * P, (P, total, tol_load)
    lo, hi = res.punch.extent
    for z in res.zones:
        assert lo <= z.ends[0] < z.ends[1] <= hi
        assert (z.ends[0] == lo) == (z.kinds[0] == "corner")
        assert (z.ends[1] == hi) == (z.kinds[1] == "corner")
        u = np.cos(np.pi * (np.arange(48) + 0.5) / 48)
        X = 0.5 * (z.ends[0] + z.ends[1]) + 0.5 * z.width * u
        p = res.pressure(X)
        assert np.min(p) >= -1e-9 * np.max(np.abs(p)), (z, np.min(p))
    X = _outside_points(res)
    if X.size:
        g = _gap(res, X)
        zs = res.zones
        span = zs[-1].ends[1] - zs[0].ends[0]
        Xz = np.linspace(zs[0].ends[0], zs[-1].ends[1], 33)
        scale = np.max(np.abs(res.punch.slope(Xz))) * span
        assert np.min(g) >= -1e-8 * scale, (np.min(g), X[np.argmin(g)], scale)


@pytest.mark.slow
@pytest.mark.parametrize("name,speed,friction,direction", LOAD_RANGE_CASES)
def test_faces_over_the_load_range(name, speed, friction, direction):
    """Loads 1e-6 .. 1e2 in one continuation from first touch: every result passes the
    independent checks."""
    curve = contact.load_curve(MAT, FACES[name], LOADS, speed=speed, friction=friction,
                               direction=direction)
    assert len(curve) == LOADS.size
    np.testing.assert_array_equal(curve.loads, LOADS)
    for res in curve:
        check_contact(res)


@pytest.mark.parametrize("name", ["flat", "triangular", "parabolic", "cylindrical"])
@pytest.mark.parametrize("speed", SPEEDS)
def test_paper_punches_along_a_load_curve_are_the_closed_forms(name, speed):
    """The four punches of the paper: each load of the curve is the corrected closed form
    (Zhou et al. 2014, Sec. 5) to 1e-12 in the ends and the pressure."""
    punch = FACES[name]
    curve = contact.load_curve(MAT, punch, LOADS, speed=speed, friction=0.3)
    for res in curve:
        ref = contact.solve(MAT, punch, load=res.load, speed=speed, friction=0.3,
                            method="closed_form")
        w = ref.ends[1] - ref.ends[0]
        np.testing.assert_allclose(res.ends, ref.ends, rtol=0, atol=1e-12 * w)
        X = ref.ends[0] + w * np.linspace(0.05, 0.95, 7)
        np.testing.assert_allclose(res.pressure(X), ref.pressure(X), rtol=1e-10)


# ----------------------------------------------------------------------------
# the asymmetric bump: contact grows from X = 0 to the whole face
# ----------------------------------------------------------------------------
@pytest.mark.slow
def test_bump_contact_reaches_both_edges_and_becomes_the_flat_punch():
    """At load 100 the bump's contact covers its face [-1, 1] with two corners (index 1): the
    flat punch of half-width 1 plus the bump's own shape, which at this load is small:
    the exponents are the flat punch's (they depend on the corners only)."""
    punch = FACES["bump"]
    res = contact.solve(MAT, punch, load=100.0, speed=0.6, friction=0.3)
    (z,) = res.zones
    assert z.ends == (-1.0, 1.0) and z.kinds == ("corner", "corner") and z.kappa == 1
    flat = contact.solve(MAT, contact.FlatPunch(half_width=1.0), load=100.0, speed=0.6,
                         friction=0.3, method="closed_form")
    assert abs(z.alpha - flat.alpha) <= 1e-14 and abs(z.beta - flat.beta) <= 1e-14
    assert set(z.sif) == {"left", "right"}


# ----------------------------------------------------------------------------
# ProfilePunch: face=, height=, from_samples
# ----------------------------------------------------------------------------
def test_height_alone_gives_the_slope_by_finite_differences():
    """height= alone: the slope by adaptive finite differences is within 1e-12 of the
    exact slope (centred) and next to the edges (one-sided), and the contact is that of the
    exact slope to 1e-12 of its width."""
    H = lambda X: np.sin(3 * X) * np.exp(X) / 10 + X * X          # noqa: E731
    dH = lambda X: (3 * np.cos(3 * X) + np.sin(3 * X)) * np.exp(X) / 10 + 2 * X  # noqa: E731
    by_h = contact.ProfilePunch(height=H, face=(-1.0, 1.0), breaks=(0.25,))
    X = np.concatenate([np.linspace(-1, 1, 41), [0.25, 0.25 - 1e-9, 0.25 + 1e-9]])
    scale = np.max(np.abs(dH(X)))
    assert np.max(np.abs(by_h.slope(X) - dH(X))) <= 1e-11 * scale
    exact = contact.ProfilePunch(dH, height=H, face=(-1.0, 1.0), breaks=(0.25,))
    a = contact.solve(MAT, by_h, load=0.05, speed=0.3, friction=0.3)
    b = contact.solve(MAT, exact, load=0.05, speed=0.3, friction=0.3)
    (za,), (zb,) = a.zones, b.zones
    assert np.allclose(za.ends, zb.ends, rtol=0, atol=1e-10 * zb.width)


def test_slope_alone_and_slope_with_height_agree():
    """Without height the gap is the integral of the slope: the same contact."""
    a = contact.ProfilePunch(lambda X: 0.2 * X * (X * X - 1.0), face=(-2.0, 2.0))
    b = FACES["W"]
    ra = contact.solve(MAT, a, load=0.01, speed=0.3, friction=0.3)
    rb = contact.solve(MAT, b, load=0.01, speed=0.3, friction=0.3)
    assert len(ra.zones) == len(rb.zones) == 2
    for za, zb in zip(ra.zones, rb.zones):
        assert np.allclose(za.ends, zb.ends, rtol=0, atol=1e-12)


def test_corners_are_the_edges_of_the_face():
    """corners=(l, r) is the face (l, r): the tilted flat face lifts off its high edge."""
    a = contact.ProfilePunch(lambda X: np.full_like(X, _M0), corners=(-1.0, 1.0))
    assert a.extent == (-1.0, 1.0)
    r = contact.solve(MAT, a, load=0.01, speed=0.3, friction=0.3)
    (z,) = r.zones
    assert z.kinds == ("corner", "free") and z.ends[0] == -1.0
    tri = contact.solve(MAT, contact.TriangularPunch(slope=_M0), load=0.01, speed=0.3,
                        friction=0.3, method="closed_form")
    assert abs((z.ends[1] + 1.0) - tri.ends[1]) <= 1e-12 * tri.ends[1]


def test_from_samples_face_is_the_samples_extent():
    p = FACES["sampled cylinder"]
    assert p.extent == (-2.0, 2.0) and p.has_height
    X = np.linspace(-2, 2, 9)
    np.testing.assert_allclose(p.height(X), X * X / 200, rtol=0, atol=1e-15)
    np.testing.assert_allclose(p.slope(X), X / 100, rtol=0, atol=1e-14)
    wide = contact.ProfilePunch.from_samples(_XS, _XS ** 2 / 200, face=(-3, 3), outside="tangent")
    assert wide.extent == (-3.0, 3.0)


@pytest.mark.parametrize("kwargs,error,match", [
    (dict(), contact.PunchGeometryError, "slope=.*height="),
    (dict(slope=1.0), contact.ProfileCallableError, "slope must be a vectorised callable"),
    (dict(height="x"), contact.ProfileCallableError, "height must be a vectorised callable"),
    (dict(slope=np.sin, face=(1.0, 1.0)), contact.PunchGeometryError, "X_min < X_max"),
    (dict(slope=np.sin, face=(0.0, float("nan"))), contact.PunchGeometryError, "NaN"),
    (dict(slope=np.sin, face=3.0), contact.PunchGeometryError, "pair"),
    (dict(slope=np.sin, face=(-1.0, 1.0), corners=(-2.0, None)), contact.PunchGeometryError,
     "narrower than the left corner"),
    (dict(slope=np.sin, face=(-1.0, 1.0), corners=(None, 0.5)), contact.PunchGeometryError,
     "inside the face"),
    (dict(slope=np.sin, breaks=(0.0, float("inf"))), contact.PunchGeometryError, "finite"),
])
def test_profile_punch_bad_input(kwargs, error, match):
    with pytest.raises(error, match=match):
        contact.ProfilePunch(**kwargs)


@pytest.mark.parametrize("X,h,error,match", [
    ([], [], "SampleError", "at least 4"),
    ([0, 1, 2, 3], [0, np.nan, 0, 0], "SampleError", "finite"),
    ([0, 2, 1, 3], [0, 1, 1, 0], "SampleError", "unsorted"),
    ([0, 1, 1, 3], [0, 1, 1, 0], "SampleError", "repeated"),
])
def test_from_samples_bad_input(X, h, error, match):
    from contact import samples
    with pytest.raises(getattr(samples, error), match=match):
        contact.ProfilePunch.from_samples(X, h)
    assert issubclass(getattr(samples, error), contact.ContactInputError)


def test_from_samples_face_beyond_the_samples():
    from contact.samples import OutsideSamplesError
    with pytest.raises(OutsideSamplesError, match="beyond the samples"):
        contact.ProfilePunch.from_samples(_XS, _XS ** 2, face=(-3.0, 2.0))


def test_height_with_nan_is_named():
    p = contact.ProfilePunch(height=lambda X: np.where(X > 0.5, np.nan, X * X), face=(-1, 1))
    with pytest.raises(contact.ProfileCallableError, match="not finite"):
        p.slope(np.linspace(-1, 1, 11))
    with pytest.raises(contact.ProfileCallableError, match="height returned a non-finite"):
        p.height(np.linspace(-1, 1, 11))


# ----------------------------------------------------------------------------
# load_curve
# ----------------------------------------------------------------------------
def test_load_curve_is_solve_at_each_load():
    """Each point of the curve is what contact.solve gives at that load (ends to 1e-12)."""
    k = contact.surface_constants(MAT, 0.6)
    p_merge = 2 * np.pi * 0.05 / abs(k.N11)       # frictionless merge load (bem_reference)
    loads = [1e-3 * p_merge, 1e-2 * p_merge, 0.3 * p_merge, 3.0 * p_merge]
    curve = contact.load_curve(MAT, FACES["W"], loads, speed=0.6, friction=0.3)
    assert curve.zone_count.tolist() == [2, 2, 2, 1]
    for res in curve:
        one = contact.solve(MAT, FACES["W"], load=res.load, speed=0.6, friction=0.3)
        assert len(one.zones) == len(res.zones)
        for a, b in zip(one.zones, res.zones):
            assert np.allclose(a.ends, b.ends, rtol=0, atol=1e-12)
    np.testing.assert_allclose(curve.contact_length,
                               [sum(z.width for z in r.zones) for r in curve])
    assert curve.span.shape == (4, 2)


@pytest.mark.parametrize("loads,match", [
    ([], "at least one"),
    ([1.0, float("nan")], "positive and finite"),
    ([-1.0, 1.0], "positive and finite"),
    ([1.0, 0.5], "strictly increasing"),
    ([1.0, 1.0], "strictly increasing"),
    ("abc", "sequence of positive numbers"),
])
def test_load_curve_bad_loads(loads, match):
    with pytest.raises(contact.LoadError, match=match):
        contact.load_curve(MAT, FACES["cylindrical"], loads, speed=0.3)


def test_several_zones_single_zone_attributes_raise():
    res = contact.solve(MAT, FACES["W"], load=1e-3, speed=0.0)
    assert len(res.zones) == 2
    for what in ("ends", "sif", "half_width"):
        with pytest.raises(contact.ContactInputError, match="2 zones"):
            getattr(res, what)
    # mirror symmetry at mu = 0 (the face is even)
    a, b = res.zones
    assert abs(a.ends[0] + b.ends[1]) <= 1e-12 and abs(a.ends[1] + b.ends[0]) <= 1e-12
    assert a.sif == {} and b.sif == {}


@pytest.mark.parametrize("face", [(-1.0, 1.0), (-1.0, 2.0), (-2.0, 1.0)])
def test_face_cut_at_its_valleys(face):
    """A W face whose edges sit at its valleys (H' = 0 there) first touches at the edge(s)
    (a corner there) and in the valley inside: two zones, left to right, valid."""
    punch = contact.ProfilePunch(lambda X: 0.2 * X * (X * X - 1.0),
                                 height=lambda X: 0.05 * (X * X - 1.0) ** 2, face=face)
    res = contact.solve(MAT, punch, load=0.01, speed=0.3, friction=0.3)
    assert len(res.zones) == 2
    check_contact(res)


NARROW = {
    # a cylinder R = 100 with a protrusion 0.12 below its tip at X = 4: first touch there
    "protrusion": contact.ProfilePunch(
        lambda X: X / 100 + 0.8 * (X - 4) * np.exp(-(X - 4) ** 2 / 0.5),
        height=lambda X: X * X / 200 - 0.2 * np.exp(-(X - 4) ** 2 / 0.5)),
    # a narrow dip at X = 0.8 on a wide cylinder (trial 3)
    "narrow dip": contact.ProfilePunch(
        lambda X: X / 100 + (X - 0.8) * np.exp(-(X - 0.8) ** 2 / 0.02),
        height=lambda X: X * X / 200 - 0.01 * np.exp(-(X - 0.8) ** 2 / 0.02)),
}


@pytest.mark.slow
@pytest.mark.filterwarnings("ignore:contact.solve. n = 3072 reached")
@pytest.mark.parametrize("name", list(NARROW))
@pytest.mark.parametrize("speed,friction,direction", [(0.0, 0.0, -1), (0.6, 0.3, -1)])
def test_narrow_features_under_wide_contacts(name, speed, friction, direction):
    """Unbounded faces whose feature (width ~0.1-0.7) ends up deep inside a contact 50 wide:
    first touch at the feature, a second zone, merges; the continuation raises n while
    its solutions are unresolved (at load 100 the dip needs more than n = 3072 and warns).
    Every result passes the independent checks."""
    curve = contact.load_curve(MAT, NARROW[name], LOADS, speed=speed, friction=friction,
                               direction=direction)
    assert max(curve.zone_count) >= 2 and curve.zone_count[-1] == 1
    for res in curve:
        check_contact(res)


@pytest.mark.slow
def test_protrusion_between_the_merges_is_two_zones():
    """At load 4.4 (c = 0.6, mu = 0.3) the protrusion face touches in two zones; a single
    zone over both (what an unresolved n = 12 step accepted, p down to -0.26 inside) is
    rejected once n resolves it.  No split event under a growing load."""
    res = contact.solve(MAT, NARROW["protrusion"], load=4.4, speed=0.6, friction=0.3)
    assert len(res.zones) == 2
    check_contact(res)
    curve = contact.load_curve(MAT, NARROW["protrusion"], [1.0, 4.4, 4.5, 20.0], speed=0.6,
                               friction=0.3)
    assert "split" not in [e.kind for e in curve.events]
    for r in curve:
        check_contact(r)


@pytest.mark.parametrize("slope, face, said", [
    (lambda X: 0.0 * X, None, "flat everywhere, with no edge"),
    (lambda X: 0.0 * X, (-1.0, math.inf), "flat toward \\+X from X = -1, a side without"),
    (lambda X: 0.0 * X, (-math.inf, 2.0), "flat toward -X from X = 2, a side without"),
    (lambda X: np.where(X > 0.0, X / 100.0, 0.0 * X), None, "flat toward -X from X = 0"),
])
def test_a_face_flat_toward_a_side_without_an_edge_asks_for_its_extent(slope, face, said):
    """A face whose height does not rise toward an unbounded side has no lowest point to
    touch first: the solve asks for the face's extent, naming where the face is flat (it
    reported a load it could not carry on the window searched, in numpy reprs)."""
    punch = contact.ProfilePunch(slope, face=face) if face else contact.ProfilePunch(slope)
    with pytest.raises(contact.PunchGeometryError, match=said) as exc:
        contact.solve(MAT, punch, load=0.01, speed=0.3)
    assert "face=" in str(exc.value) and "np.float64" not in str(exc.value)


def test_a_flat_face_with_its_extent_is_the_flat_punch():
    """The same face given its extent: the flat punch's contact, both ends at its corners."""
    r = contact.solve(MAT, contact.ProfilePunch(lambda X: 0.0 * X, face=(-1.0, 1.0)),
                      load=0.01, speed=0.3, friction=0.2)
    ref = contact.solve(MAT, contact.FlatPunch(1.0), load=0.01, speed=0.3, friction=0.2)
    assert r.ends == (-1.0, 1.0) and r.zones[0].kinds == ("corner", "corner")
    X = np.linspace(-0.9, 0.9, 7)
    assert np.allclose(r.pressure(X), ref.pressure(X), rtol=1e-12, atol=0)


def test_a_slope_jump_without_a_break_says_to_pass_breaks():
    """A wedge's apex (the slope jumps there) without breaks=: Newton's method for the ends
    cannot follow it from first touch, and the error says what to pass.  With the break,
    the isotropic static wedge of slope m (Johnson, Contact Mechanics, 1985, sec. 5.8):
    a = P / (E* m), p(x) = (E* m / pi) arccosh(a / |x|), E* = E / (1 - nu^2), to 1e-14."""
    m, P = 0.01, 0.01

    def wedge(breaks):
        return contact.ProfilePunch(lambda X: m * np.sign(X), face=(-1.0, 1.0), breaks=breaks)
    with pytest.raises(contact.ContactLossError, match="pass its X positions as breaks="):
        contact.solve(MAT, wedge(()), load=P, speed=0.0)
    E, nu = 1.0, 0.3
    r = contact.solve(contact.Isotropic(E, nu), wedge((0.0,)), load=P, speed=0.0)
    E_star = E / (1.0 - nu**2)
    a = P / (E_star * m)
    assert r.ends == pytest.approx((-a, a), rel=1e-14)
    X = a * np.array([-0.8, -0.2, 0.05, 0.4, 0.9])
    ref = E_star * m / math.pi * np.arccosh(a / np.abs(X))
    assert np.allclose(r.pressure(X), ref, rtol=1e-14, atol=0)


def test_a_flat_that_starts_to_rise_between_the_nodes_asks_for_a_break():
    """A face flat on [-1, 0] that rises beyond 0 (its slope kinks there): the first contact,
    [-1, 0.002], has no collocation node where the slope is not zero, carries no load, and
    the error says to pass the kink as a break; with it, the contact is that of the face's
    twin without the right edge (whose wider search finds the same zone), to 1e-12."""
    slope = lambda X: np.where(X < 0.0, 0.0 * X, X)          # noqa: E731
    with pytest.raises(contact.ContactLossError, match="pass that X as breaks="):
        contact.solve(MAT, contact.ProfilePunch(slope, face=(-1.0, 1.0)), load=1e-4, speed=0.3)
    r = contact.solve(MAT, contact.ProfilePunch(slope, face=(-1.0, 1.0), breaks=(0.0,)),
                      load=1e-4, speed=0.3)
    twin = contact.solve(MAT, contact.ProfilePunch(slope, face=(-1.0, math.inf),
                                                   breaks=(0.0,)), load=1e-4, speed=0.3)
    assert r.zones[0].kinds == ("corner", "free") and r.ends[0] == -1.0
    assert r.ends[1] == pytest.approx(twin.ends[1], rel=1e-12)
