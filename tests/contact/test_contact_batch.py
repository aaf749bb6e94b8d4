"""Tests of :func:`contact.solve_batch` and of its lockstep first step
(:mod:`contact.lockstep`).

References, and why each is independent of what it checks:

* ``contact.solver._numeric`` (the full load continuation: first touch, events, Newton on
  the ends, adaptive n; :mod:`contact.continuation`, :mod:`contact.zones`, ``sie.solve``)
  for one case: the path every case took before the batch existed.  The lockstep step
  (an ``sie.Equation`` with a case axis, the power-law prediction, batched side conditions,
  batched SIFs and residuals) is a separate implementation of that path's first step, so a case it
  finishes must agree with the continuation to rounding.  Cases it declines fall back to
  ``_numeric`` itself; for them the comparison checks the dispatch.
* The corrected closed forms of Zhou et al. 2014 (``method="closed_form"``,
  :mod:`contact.closed_form`): formulas in the exponents, no integral equation solved; and
  Hertz's half-width a^2 = -2 N11 P R / pi for the cylinder without friction.
* Exact equality between ``contact.solve`` of a case and ``solve_batch`` of a batch holding
  it (a single solve is a batch of one, and a case's result must not depend on the other
  cases).
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import contact
from contact.lockstep import first_steps
from contact.solver import _numeric, _Problem

ZHOU = contact.zhou2014()
ISO = contact.Isotropic(1.0, 0.3)
# isotropic with lambda = G = 1 (C11 = C22 = 3, C12 = C33 = 1), C11 moved by 1e-8: the two
# characteristic roots nearly coincide (the surface constants' repeated-root limit)
NEAR_ISO = contact.Orthotropic(3.0 * (1 + 1e-8), 1.0, 3.0, 1.0)
MATERIALS = {"zhou2014": ZHOU, "isotropic": ISO}


class BoundedCylinder(contact.ProfilePunch):
    """slope X / R on a face of finite extent, declared convex, homogeneous about 0 and of
    polynomial degree 1 (what the built-in cylinder declares), so that the lockstep step
    takes it up: at loads where the zone would pass the face's left edge the step must
    decline (the continuation turns that end into a corner)."""
    convex = True
    slope_degree = 1

    def __init__(self, radius, face):
        super().__init__(lambda X: X / radius, face=face)
        self.homogeneous = (0.0, 1)


# name: (punch, load).  The profiles have no slope_degree (adaptive n) and are not convex
# for the lockstep: they go through the full continuation.
PUNCHES = {
    "cylinder": (contact.CylindricalPunch(radius=100.0), 0.01),
    "parabola": (contact.ParabolicPunch(radius=100.0), 0.01),
    "flat": (contact.FlatPunch(1.0), 0.5),
    "triangle": (contact.TriangularPunch(0.1), 0.01),
    # height X^2/2 + 0.05 X^4: convex, one free-free zone about 0
    "profile": (contact.ProfilePunch(lambda X: X + 0.2 * X ** 3, face=(-2.0, 2.0)), 0.01),
    # the slope X^2/2 + 0.05 X^4 >= 0: lowest at the left edge, a corner there
    "profile-edge": (contact.ProfilePunch(lambda X: X ** 2 / 2 + 0.05 * X ** 4,
                                          face=(-2.0, 2.0)), 0.01),
    # W-shaped face: two zones at this load
    "W": (contact.ProfilePunch(lambda X: 0.2 * X ** 3 - 0.2 * X, face=(-2.0, 2.0)), 1e-3),
}
BUILTIN = ("cylinder", "parabola", "flat", "triangle")


def reference(material, punch, load, speed, friction, direction, n=None):
    """The full continuation of one case (``_numeric``), as ``contact.solve`` ran it before
    the batch path."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", contact.NearRayleighWarning)
        const = contact.surface_constants(material, speed)
    mu_f = -direction * friction if friction != 0.0 else 0.0
    problem = _Problem(material, punch, const, float(speed), friction, direction, mu_f)
    return _numeric(problem, [load], n, 1e-12).results[0]


def interior_points(zone, k=13):
    c, d = zone.ends
    return c + (d - c) * np.linspace(0.01, 0.99, k)


def assert_matches(r, q):
    """solve_batch's result r against the reference result q of the same case."""
    assert isinstance(r, contact.ContactResult)
    assert (r.load, r.speed, r.friction, r.direction, r.mu_f) == \
        (q.load, q.speed, q.friction, q.direction, q.mu_f)
    assert r.constants == q.constants
    assert r.n == q.n and r.method == q.method == "numeric"
    assert len(r.zones) == len(q.zones)
    width = max(z.ends[1] for z in q.zones) - min(z.ends[0] for z in q.zones)
    for zr, zq in zip(r.zones, q.zones):
        assert zr.kinds == zq.kinds and zr.kappa == zq.kappa
        assert max(abs(x - y) for x, y in zip(zr.ends, zq.ends)) <= 1e-13 * width, \
            (zr.ends, zq.ends)
        assert abs(zr.alpha - zq.alpha) <= 1e-14 and abs(zr.beta - zq.beta) <= 1e-14
        assert abs(zr.load - zq.load) <= 1e-12 * abs(zq.load)
        sr, sq = zr.sif, zq.sif
        assert sr.keys() == sq.keys()
        assert set(sq) == {side for side, kind in zip(("left", "right"), zq.kinds)
                           if kind == "corner"}
        for key in sq:
            assert abs(sr[key] - sq[key]) <= 1e-12 * abs(sq[key]), (key, sr[key], sq[key])
        X = interior_points(zq)
        pr, pq = r.pressure(X), q.pressure(X)
        assert np.max(np.abs(pr - pq)) <= 1e-12 * np.max(np.abs(pq))
        hr, hq = r.hilbert_pressure(X), q.hilbert_pressure(X)
        assert np.max(np.abs(hr - hq)) <= 1e-12 * max(np.max(np.abs(hq)), np.max(np.abs(pq)))
    if len(q.zones) == 1:
        assert r.ends == r.zones[0].ends and r.sif == r.zones[0].sif
    # int p = P to rounding: 1e-13 for the lockstep's cases; the continuation's Newton stops
    # at 32 eps in its scaled side conditions, and on the corner profile (zhou2014) its own
    # load_check reaches 1.3e-13 -- a fallback case carries the reference's value itself
    assert r.load_check < 1e-13 or r.load_check == q.load_check
    assert r.load_check < 1e-12
    # the residual (precomputed by residual=True for the lockstep cases, else on access)
    assert abs(r.residual - q.residual) <= 1e-13
    assert r.residual < 1e-12


def sweep(speeds, frictions):
    S, F, D = np.meshgrid(speeds, frictions, [-1, 1], indexing="ij")
    return S.ravel(), F.ravel(), D.ravel().astype(int)


# --------------------------------------------------------------------------
# every case against the full continuation
# --------------------------------------------------------------------------
@pytest.mark.parametrize("material", list(MATERIALS), ids=list(MATERIALS))
@pytest.mark.parametrize("name", list(PUNCHES))
def test_sweep_matches_continuation(name, material):
    punch, load = PUNCHES[name]
    mat = MATERIALS[material]
    speeds = [0.0, 0.3, 0.6, 0.9] if name in BUILTIN else [0.0, 0.9]
    S, F, D = sweep(speeds, [0.0, 0.2, 0.5])
    rs = contact.solve_batch(mat, punch, load=load, speed=S, friction=F, direction=D,
                             residual=True)
    assert len(rs) == S.size
    for r, s, f, d in zip(rs, S, F, D):
        assert_matches(r, reference(mat, punch, load, s, f, d))
    if name == "W":
        assert all(len(r.zones) == 2 for r in rs)
    if name == "profile-edge":
        assert all(r.zones[0].kinds == ("corner", "free") and r.ends[0] == -2.0 for r in rs)


@pytest.mark.parametrize("n", (3, 8, 24))
def test_explicit_n_matches_continuation(n):
    """n given (n > 8: the coefficients' noise chopping in both paths): the lockstep runs
    at that n for the built-in punches; a profile at fixed n goes to the continuation."""
    S, F, D = sweep([0.0, 0.8], [0.0, 0.4])
    for name in BUILTIN + ("profile",):
        punch, load = PUNCHES[name]
        rs = contact.solve_batch(ISO, punch, load=load, speed=S, friction=F, direction=D, n=n)
        for r, s, f, d in zip(rs, S, F, D):
            assert r.n == n
            assert_matches(r, reference(ISO, punch, load, s, f, d, n=n))


def hard_cases(material):
    """Near the Rayleigh speed; frictions that put an exponent within 0.01 of 0 or 1;
    zero friction and friction 1e-12, in both directions."""
    cR = contact.rayleigh_speed(material)
    return [(0.999 * cR, 0.3, -1), (0.999 * cR, 0.0, 1), (0.9, 60.0, -1), (0.9, 60.0, 1),
            (0.5, 300.0, 1), (0.5, 300.0, -1), (0.0, 0.0, -1), (0.2, 1e-12, 1)]


@pytest.mark.parametrize("material", [ZHOU, ISO, NEAR_ISO], ids=["zhou2014", "isotropic",
                                                                 "nearly-isotropic"])
@pytest.mark.parametrize("name", BUILTIN)
def test_hard_cases_match_continuation(name, material):
    punch, load = PUNCHES[name]
    S, F, D = (np.array(v) for v in zip(*hard_cases(material)))
    with pytest.warns(contact.NearRayleighWarning):
        rs = contact.solve_batch(material, punch, load=load, speed=S, friction=F, direction=D,
                                 residual=True)
    for r, s, f, d in zip(rs, S, F, D):
        assert_matches(r, reference(material, punch, load, s, f, d))
    # an exponent within 0.01 of 0 or 1 (the rule's split-off end in sie), both signs of mu_f
    near = [min(abs(e - round(e)) for e in (r.alpha, r.beta)) < 0.01 for r in rs]
    assert any(near)
    if name == "cylinder":
        # the lockstep step finished every case (none fell back): it is what was tested
        consts = [contact.surface_constants(material, s) for s in S[2:]]
        fs = first_steps(punch.as_face(), punch.slope, (),
                         [k.N12 * (-d * f) for k, f, d in zip(consts, F[2:], D[2:])],
                         [k.N11 for k in consts], [load] * len(consts), 5)
        assert fs.done.size == len(consts)


def test_nearly_isotropic_close_to_isotropic():
    """The nearly isotropic material gives the isotropic (lambda = G = 1) answer to ~1e-8:
    the batch is continuous through the repeated-root limit of the surface constants."""
    iso = contact.Orthotropic(3.0, 1.0, 3.0, 1.0)
    punch, load = PUNCHES["cylinder"]
    S, F, D = sweep([0.0, 0.5], [0.0, 0.4])
    for a, b in zip(contact.solve_batch(NEAR_ISO, punch, load=load, speed=S, friction=F,
                                        direction=D),
                    contact.solve_batch(iso, punch, load=load, speed=S, friction=F,
                                        direction=D)):
        assert max(abs(x - y) for x, y in zip(a.ends, b.ends)) <= 1e-7 * a.zones[0].width
        assert abs(a.alpha - b.alpha) <= 1e-7


speed_st = st.floats(0.0, 0.9, allow_nan=False)
friction_st = st.one_of(st.just(0.0), st.floats(0.0, 2.0, allow_nan=False))


@settings(max_examples=20, deadline=None)
@given(name=st.sampled_from(BUILTIN), material=st.sampled_from(list(MATERIALS)),
       speeds=st.lists(speed_st, min_size=1, max_size=3), friction=friction_st,
       direction=st.sampled_from((-1, 1)), log_load=st.floats(-6.0, 1.0))
def test_property_builtin_punches_match_continuation(name, material, speeds, friction,
                                                     direction, log_load):
    punch, _ = PUNCHES[name]
    mat = MATERIALS[material]
    load = 10.0 ** log_load
    rs = contact.solve_batch(mat, punch, load=load, speed=speeds, friction=friction,
                             direction=direction)
    for r, s in zip(rs, speeds):
        assert_matches(r, reference(mat, punch, load, s, friction, direction))


# --------------------------------------------------------------------------
# independent oracles: the closed forms and Hertz
# --------------------------------------------------------------------------
@pytest.mark.parametrize("name", BUILTIN)
def test_numeric_batch_matches_closed_forms(name):
    """The lockstep results against the corrected closed forms of Zhou et al. 2014
    (no integral equation solved there)."""
    punch, load = PUNCHES[name]
    S, F, D = sweep([0.0, 0.5, 0.9], [0.0, 0.3])
    rn = contact.solve_batch(ZHOU, punch, load=load, speed=S, friction=F, direction=D)
    rc = contact.solve_batch(ZHOU, punch, load=load, speed=S, friction=F, direction=D,
                             method="closed_form")
    for a, c in zip(rn, rc):
        assert c.method == "closed_form"
        w = c.ends[1] - c.ends[0]
        assert max(abs(x - y) for x, y in zip(a.ends, c.ends)) <= 1e-12 * w
        assert abs(a.alpha - c.alpha) <= 1e-13 and abs(a.beta - c.beta) <= 1e-13
        X = interior_points(c.zones[0], 9)
        assert np.max(np.abs(a.pressure(X) - c.pressure(X))) <= 1e-12 * np.max(c.pressure(X))
        assert a.sif.keys() == c.sif.keys()
        for k in c.sif:
            assert abs(a.sif[k] - c.sif[k]) <= 1e-12 * abs(c.sif[k])


def test_cylinder_without_friction_is_hertz():
    """a^2 = -2 N11 P R / pi, centred, for every speed and load of the batch."""
    R = 100.0
    P = np.array([1e-4, 0.01, 1.0])[:, None]
    speeds = np.array([0.0, 0.4, 0.8])
    rs = contact.solve_batch(ISO, contact.CylindricalPunch(R), load=P, speed=speeds)
    for k, r in enumerate(rs):
        N11 = contact.surface_constants(ISO, speeds[k % 3]).N11
        a = math.sqrt(-2.0 * N11 * P[k // 3, 0] * R / math.pi)
        assert abs(r.ends[0] + a) <= 1e-13 * a and abs(r.ends[1] - a) <= 1e-13 * a


# --------------------------------------------------------------------------
# solve is a batch of one; a case does not depend on the others
# --------------------------------------------------------------------------
def assert_identical(r, s):
    assert r.n == s.n and len(r.zones) == len(s.zones)
    for zr, zs in zip(r.zones, s.zones):
        assert zr.ends == zs.ends and zr.kinds == zs.kinds
        assert zr.alpha == zs.alpha and zr.beta == zs.beta and zr.load == zs.load
        assert zr.sif == zs.sif
    for pr, ps in zip(r.solution.pieces, s.solution.pieces):
        assert np.array_equal(pr.coefficients, ps.coefficients)
    assert r.load_check == s.load_check


@pytest.mark.parametrize("name", list(PUNCHES))
def test_solve_equals_batch_exactly(name):
    punch, load = PUNCHES[name]
    S, F, D = sweep([0.0, 0.7] if name not in BUILTIN else [0.0, 0.35, 0.7, 0.9], [0.0, 0.4])
    loads = load * np.linspace(0.5, 2.0, S.size)
    rs = contact.solve_batch(ZHOU, punch, load=loads, speed=S, friction=F, direction=D)
    rev = contact.solve_batch(ZHOU, punch, load=loads[::-1], speed=S[::-1],
                              friction=F[::-1], direction=D[::-1])[::-1]
    for k in range(S.size):
        one = contact.solve(ZHOU, punch, load=loads[k], speed=S[k], friction=F[k],
                            direction=int(D[k]))
        assert_identical(rs[k], one)
        assert_identical(rev[k], one)
    sub = [3, 0]
    part = contact.solve_batch(ZHOU, punch, load=loads[sub], speed=S[sub], friction=F[sub],
                               direction=D[sub])
    for r, k in zip(part, sub):
        assert_identical(r, rs[k])


# --------------------------------------------------------------------------
# which cases the lockstep step finishes
# --------------------------------------------------------------------------
def _coefficients(material, speeds, frictions, directions):
    consts = [contact.surface_constants(material, s) for s in speeds]
    a = [k.N12 * (-d * f) if f != 0.0 else 0.0 for k, f, d in zip(consts, frictions, directions)]
    return a, [k.N11 for k in consts]


@pytest.mark.parametrize("name, kinds", [("cylinder", ("free", "free")),
                                         ("parabola", ("corner", "free")),
                                         ("triangle", ("corner", "free")),
                                         ("flat", ("corner", "corner"))])
def test_lockstep_finishes_builtin_sweeps(name, kinds):
    punch, load = PUNCHES[name]
    S, F, D = sweep([0.0, 0.3, 0.6, 0.9], [0.0, 0.2, 0.5])
    loads = load * np.geomspace(1e-3, 1e3, S.size)
    a, b = _coefficients(ZHOU, S, F, D)
    n = punch.slope_degree + 4
    fs = first_steps(punch.as_face(), punch.slope, tuple(punch.breaks), a, b, loads, n)
    assert fs is not None and fs.kinds == kinds
    assert np.array_equal(fs.done, np.arange(S.size))
    assert fs.solutions.n == n and len(fs.solutions) == S.size
    # the step's zones are the answer
    rs = contact.solve_batch(ZHOU, punch, load=loads, speed=S, friction=F, direction=D)
    for k, r in enumerate(rs):
        assert r.ends == tuple(fs.solutions.intervals[k].tolist())
        assert_matches(r, reference(ZHOU, punch, loads[k], S[k], F[k], D[k]))


@pytest.mark.parametrize("name", ["profile", "profile-edge", "W"])
def test_lockstep_declines_non_convex_faces(name):
    punch, _ = PUNCHES[name]
    assert first_steps(punch.as_face(), punch.slope, tuple(punch.breaks), [0.0, 0.01],
                       [-0.1, -0.2], [0.01, 0.02], 16) is None


def test_lockstep_declines_zone_past_the_edge_and_fallback_solves_it():
    """A convex homogeneous face of finite extent: at small loads the step finishes, at
    larger ones the predicted zone passes the left edge and the case goes to the
    continuation, which turns that end into a corner; both kinds agree with the reference."""
    punch = BoundedCylinder(1.0, (-0.3, 3.0))
    loads = np.array([1e-3, 0.2, 1e-2, 0.1, 0.05, 0.3])
    speed, friction, direction = 0.3, np.array([0.0, 0.0, 0.1, 0.1, 0.3, 0.3]), -1
    a, b = _coefficients(ISO, [speed] * 6, friction, [direction] * 6)
    fs = first_steps(punch.as_face(), punch.slope, (), a, b, loads, 5)
    assert fs is not None and fs.kinds == ("free", "free")
    done = set(fs.done.tolist())
    assert done and done != set(range(6))
    rs = contact.solve_batch(ISO, punch, load=loads, speed=speed, friction=friction,
                             direction=direction, residual=True)
    for k, r in enumerate(rs):
        q = reference(ISO, punch, loads[k], speed, friction[k], direction)
        assert_matches(r, q)
        if k in done:
            assert r.zones[0].kinds == ("free", "free")
            assert r.ends == tuple(fs.solutions.intervals[sorted(done).index(k)].tolist())
        else:
            assert r.zones[0].kinds == ("corner", "free") and r.ends[0] == -0.3
    # every case past the edge: the step declines them all, the continuation solves each
    past = [1, 3, 5]
    fs = first_steps(punch.as_face(), punch.slope, (), np.asarray(a)[past],
                     np.asarray(b)[past], loads[past], 5)
    assert fs is not None and fs.done.size == 0
    rs = contact.solve_batch(ISO, punch, load=loads[past], speed=speed,
                             friction=friction[past], direction=direction)
    for r, k in zip(rs, (1, 3, 5)):
        assert_matches(r, reference(ISO, punch, loads[k], speed, friction[k], direction))


def test_residual_precomputed_equals_lazy():
    """residual=True fills the residual in one batched pass; without it the result computes
    it on access from its own solution (contact.result._residual_of)."""
    punch, load = PUNCHES["cylinder"]
    S, F, D = sweep([0.0, 0.5, 0.9], [0.0, 0.5])
    pre = contact.solve_batch(ZHOU, punch, load=load, speed=S, friction=F, direction=D,
                              residual=True)
    lazy = contact.solve_batch(ZHOU, punch, load=load, speed=S, friction=F, direction=D)
    for p, q in zip(pre, lazy):
        assert p._residual is not None and q._residual is None
        assert abs(p.residual - q.residual) <= 1e-13 and q.residual < 1e-12


# --------------------------------------------------------------------------
# errors
# --------------------------------------------------------------------------
def test_errors_return_in_place():
    punch, load = PUNCHES["cylinder"]
    rs = contact.solve_batch(ZHOU, punch, load=[load, -1.0, load, load, load],
                             speed=[0.3, 0.3, 0.5, 2.0, 0.3],
                             friction=[0.1, 0.1, np.nan, 0.1, 0.2], errors="return")
    assert isinstance(rs[1], contact.LoadError)
    assert isinstance(rs[2], contact.FrictionError)
    assert isinstance(rs[3], contact.SpeedError)
    assert "load" in str(rs[1]) and "friction" in str(rs[2])
    for k, f in ((0, 0.1), (4, 0.2)):
        assert_identical(rs[k], contact.solve(ZHOU, punch, load=load, speed=0.3, friction=f))


def test_errors_raise_the_first():
    punch, load = PUNCHES["cylinder"]
    with pytest.raises(contact.LoadError, match="load"):
        contact.solve_batch(ZHOU, punch, load=[load, -1.0, load], speed=0.3,
                            friction=[0.1, 0.1, np.nan])
    with pytest.raises(contact.FrictionError, match="friction"):
        contact.solve_batch(ZHOU, punch, load=[load, load, -1.0], speed=0.3,
                            friction=[0.1, np.nan, 0.1], errors="raise")
    with pytest.raises(contact.DirectionError, match="direction"):
        contact.solve_batch(ZHOU, punch, load=load, speed=0.3, direction=[1, 0])


def test_errors_bad_arguments():
    punch, load = PUNCHES["cylinder"]
    with pytest.raises(contact.ContactInputError, match="errors"):
        contact.solve_batch(ZHOU, punch, load=load, speed=0.3, errors="bogus")
    with pytest.raises(contact.ContactInputError, match="broadcast"):
        contact.solve_batch(ZHOU, punch, load=[load, load], speed=[0.1, 0.2, 0.3])
    with pytest.raises(contact.ContactInputError, match="broadcast"):
        contact.solve_batch(ZHOU, punch, load=load, speed=[[0.1, 0.2]], friction=[0.0] * 3)
    k = contact.surface_constants(ZHOU, 0.3)
    with pytest.raises(contact.ContactInputError, match="one SurfaceConstants per case"):
        contact.solve_batch(ZHOU, punch, load=load, speed=[0.3, 0.3], constants=[k])
    with pytest.raises(contact.ContactInputError, match="constants are for speed"):
        contact.solve_batch(ZHOU, punch, load=load, speed=[0.3, 0.4], constants=[k, k])
    rs = contact.solve_batch(ZHOU, punch, load=load, speed=[0.3, 0.4], constants=[k, k],
                             errors="return")
    assert isinstance(rs[1], contact.ContactInputError) and "speed" in str(rs[1])
    assert_identical(rs[0], contact.solve(ZHOU, punch, load=load, speed=0.3))
    with pytest.raises(contact.ContactInputError, match="closed_form"):
        contact.solve_batch(ZHOU, PUNCHES["W"][0], load=1e-3, speed=0.0,
                            method="closed_form")
    # ... and in place with errors="return", as every other error of a case
    (r,) = contact.solve_batch(ZHOU, PUNCHES["W"][0], load=1e-3, speed=0.0,
                               method="closed_form", errors="return")
    assert isinstance(r, contact.ContactInputError) and "closed_form" in str(r)
    # one SurfaceConstants where a sequence of them is expected (what solve takes)
    with pytest.raises(contact.ContactInputError, match="sequence of SurfaceConstants"):
        contact.solve_batch(ZHOU, punch, load=load, speed=0.3, constants=k)


def test_constants_given_match_computed():
    punch, load = PUNCHES["triangle"]
    speeds = [0.2, 0.6, 0.2]
    ks = [contact.surface_constants(ZHOU, s) for s in speeds]
    a = contact.solve_batch(ZHOU, punch, load=load, speed=speeds, friction=0.3, constants=ks)
    b = contact.solve_batch(ZHOU, punch, load=load, speed=speeds, friction=0.3)
    for x, y in zip(a, b):
        assert_identical(x, y)


# --------------------------------------------------------------------------
# broadcasting and the closed forms through solve_batch
# --------------------------------------------------------------------------
def test_broadcasting_c_order():
    punch, load = PUNCHES["cylinder"]
    speeds = np.array([[0.0], [0.4], [0.8]])
    frictions = np.array([0.0, 0.1, 0.3, 0.5])
    rs = contact.solve_batch(ZHOU, punch, load=load, speed=speeds, friction=frictions)
    assert len(rs) == 12
    for k, r in enumerate(rs):
        i, j = divmod(k, 4)
        assert r.speed == speeds[i, 0] and r.friction == frictions[j]
        assert r.load == load and r.direction == -1
    for k in (0, 5, 11):
        i, j = divmod(k, 4)
        assert_identical(rs[k], contact.solve(ZHOU, punch, load=load, speed=speeds[i, 0],
                                              friction=frictions[j]))
    # a scalar everything: one result
    (r,) = contact.solve_batch(ZHOU, punch, load=load, speed=0.4)
    assert_identical(r, contact.solve(ZHOU, punch, load=load, speed=0.4))
    # directions broadcast too
    rs = contact.solve_batch(ZHOU, punch, load=load, speed=0.4, friction=0.3,
                             direction=[[-1], [1]])
    assert [r.direction for r in rs] == [-1, 1] and rs[0].mu_f == -rs[1].mu_f == 0.3


@pytest.mark.parametrize("name", BUILTIN)
def test_closed_form_through_batch(name):
    punch, load = PUNCHES[name]
    S, F, D = sweep([0.0, 0.6], [0.0, 0.3])
    rs = contact.solve_batch(ISO, punch, load=load, speed=S, friction=F, direction=D,
                             method="closed_form")
    for r, s, f, d in zip(rs, S, F, D):
        c = contact.solve(ISO, punch, load=load, speed=s, friction=f, direction=int(d),
                          method="closed_form")
        assert r.method == c.method == "closed_form"
        assert r.ends == c.ends and r.alpha == c.alpha and r.beta == c.beta
        assert r.sif == c.sif
        X = interior_points(c.zones[0], 7)
        assert np.array_equal(r.pressure(X), c.pressure(X))


def test_a_batch_runs_the_collector_rarely_and_leaves_it_as_it_was():
    """solve_batch raises the collector's first threshold while its cases run (a batch keeps
    some hundred small objects a case: each pass would walk them) and leaves the collector
    as it was afterwards, its thresholds and whether it is on, also when a case raises."""
    import gc
    seen = []

    def slope(X):
        seen.append(gc.get_threshold()[0])
        return X / 100.0
    before = gc.get_threshold()
    assert gc.isenabled()
    contact.solve_batch(ZHOU, contact.ProfilePunch(slope), load=0.01, speed=[0.1, 0.2],
                        friction=0.1)
    assert seen and min(seen) >= 100_000 > before[0]
    assert gc.get_threshold() == before and gc.isenabled()
    punch, load = PUNCHES["cylinder"]
    with pytest.raises(contact.LoadError):
        contact.solve_batch(ZHOU, punch, load=[load, -1.0], speed=0.1)
    assert gc.get_threshold() == before and gc.isenabled()
    gc.disable()
    try:
        contact.solve_batch(ZHOU, punch, load=load, speed=[0.1, 0.2], friction=0.1)
        assert not gc.isenabled() and gc.get_threshold() == before
    finally:
        gc.enable()
