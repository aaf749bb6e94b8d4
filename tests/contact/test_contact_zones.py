"""contact.zones: the equations of several contact zones and Newton's method for their ends.

References: the single-zone solver (contact.solve, itself checked against the paper's corrected
closed forms) for one zone of each index; mirror symmetry of a symmetric face at mu = 0; the
side conditions checked directly on the returned pressure (load by quadrature of p, the gap
between zones by quadrature of its slope H' - N11 Hc[p], which does not use the log potential
the equations use).
"""
from __future__ import annotations

import numpy as np
import pytest

import contact
from contact.zones import CORNER, FREE, Zone, ZoneEquations

MAT = contact.zhou2014()


def _equations(H, dH, speed, mu_f, load, n=16, breaks=()):
    k = contact.surface_constants(MAT, speed)
    return ZoneEquations(slope=dH, rise=lambda x0, x1: H(x1) - H(x0), breaks=breaks,
                         a=k.N12 * mu_f if mu_f else 0.0, b=k.N11, load=load, n=n), k


@pytest.mark.parametrize("speed", [0.0, 0.6])
@pytest.mark.parametrize("friction,direction", [(0.0, -1), (0.3, -1), (0.3, 1)])
def test_one_free_free_zone_is_the_cylinder(speed, friction, direction):
    R, P = 100.0, 0.01
    ref = contact.solve(MAT, contact.CylindricalPunch(radius=R), load=P, speed=speed,
                        friction=friction, direction=direction)
    eq, _ = _equations(lambda X: X * X / (2 * R), lambda X: X / R, speed,
                       -direction * friction, P, n=8)
    (z,), _, sol = eq.newton([Zone(-0.5, 0.5)])
    w = ref.ends[1] - ref.ends[0]
    assert abs(z.c - ref.ends[0]) <= 1e-12 * w and abs(z.d - ref.ends[1]) <= 1e-12 * w
    assert abs(sol.integral() - P) <= 1e-13 * P


@pytest.mark.parametrize("friction", [0.0, 0.3])
def test_corner_free_zone_is_the_triangular_punch(friction):
    m0, P = 0.1, 0.02
    ref = contact.solve(MAT, contact.TriangularPunch(slope=m0), load=P, speed=0.3,
                        friction=friction)
    eq, _ = _equations(lambda X: m0 * X, lambda X: np.full_like(X, m0), 0.3, friction, P, n=8)
    (z,), _, sol = eq.newton([Zone(0.0, 1.0, left=CORNER)], lo=0.0)
    assert z.c == 0.0
    assert abs(z.d - ref.ends[1]) <= 1e-12 * ref.ends[1]


def test_corner_corner_zone_is_the_flat_punch():
    a, P = 0.5, 0.03
    ref = contact.solve(MAT, contact.FlatPunch(half_width=a), load=P, speed=0.6, friction=0.3)
    eq, _ = _equations(lambda X: 0.0 * X, lambda X: np.zeros_like(X), 0.6, 0.3, P, n=8)
    (z,), (t,), sol = eq.newton([Zone(-a, a, CORNER, CORNER)], lo=-a, hi=a)
    assert abs(t - P) <= 1e-14 * P
    X = np.linspace(-0.45, 0.45, 7)
    assert np.allclose(sol(X), ref.pressure(X), rtol=1e-12, atol=0)


def _w_face():
    H = lambda X: 0.05 * (X * X - 1.0) ** 2          # noqa: E731  valleys at X = +-1
    dH = lambda X: 0.2 * X * (X * X - 1.0)           # noqa: E731
    return H, dH


def _gap_between(sol, k, dH, x0, x1, m=40):
    """g(x1) - g(x0) = int_{x0}^{x1} (H' - N11 Hc[p]) dX, by Gauss-Legendre on the two halves
    with X = end + (mid - end) t^2 (graded toward each end, where the integrand behaves like
    dist^alpha next to a free end)."""
    u, w = np.polynomial.legendre.leggauss(m)
    t, wt = 0.5 * (u + 1.0), 0.5 * w
    mid = 0.5 * (x0 + x1)
    total = 0.0
    for end in (x0, x1):
        X = end + (mid - end) * t * t
        dX = 2.0 * t * abs(mid - end)
        total += np.sum(wt * dX * (dH(X) - k.N11 * sol.cauchy(X)))
    return total


@pytest.mark.parametrize("load", [1e-4, 1e-3, 1e-2])
def test_w_face_two_zones_mirror_symmetric(load):
    H, dH = _w_face()
    eq, k = _equations(H, dH, 0.6, 0.0, load)
    zs, _, sol = eq.newton([Zone(-1.05, -0.95), Zone(0.95, 1.05)])
    (z0, z1) = zs
    w = z0.width
    assert abs(z0.c + z1.d) <= 1e-12 * w and abs(z0.d + z1.c) <= 1e-12 * w
    assert abs(sol.integral(interval=0) - 0.5 * load) <= 1e-12 * load
    # both zones touch the same face: the gap opens between them and closes again
    assert abs(_gap_between(sol, k, dH, z0.d, z1.c)) <= 1e-10 * (H(0.0) - H(1.0))
    # pressure positive inside each zone
    for z in zs:
        Xs = z.c + z.width * np.linspace(0.01, 0.99, 50)
        assert np.all(sol(Xs) > 0)


@pytest.mark.parametrize("direction", [-1, 1])
def test_w_face_with_friction_side_conditions(direction):
    H, dH = _w_face()
    load = 1e-2
    eq, k = _equations(H, dH, 0.6, -direction * 0.3, load)
    zs, _, sol = eq.newton([Zone(-1.05, -0.95), Zone(0.95, 1.05)])
    assert abs(sol.integral() - load) <= 1e-13 * load
    for cons in sol.consistency:
        assert abs(cons) <= 1e-12 * 0.2
    assert abs(_gap_between(sol, k, dH, zs[0].d, zs[1].c)) <= 1e-10 * (H(0.0) - H(1.0))
    # friction breaks the mirror symmetry: the zones shift the same way
    shift0 = 0.5 * (zs[0].c + zs[0].d) + 1.0
    shift1 = 0.5 * (zs[1].c + zs[1].d) - 1.0
    assert np.sign(shift0) == np.sign(shift1) != 0


# ----------------------------------------------------------------------------
# continuation from first touch (contact.continuation)
# ----------------------------------------------------------------------------
from contact.continuation import follow_load          # noqa: E402
from contact.face import Face                         # noqa: E402


def test_load_curve_w_face_two_zones_merge_then_reach_the_edges():
    """W face on [-2, 2]: two mirror-symmetric zones at light load, one zone after they merge,
    both ends at the face edges (corners, index 1) at a large load; the load carried at every
    step, the zones nested in the load (contact grows monotonically)."""
    H, dH = _w_face()
    k = contact.surface_constants(MAT, 0.6)
    face = Face(dH, extent=(-2.0, 2.0), height=H)
    eq = ZoneEquations(slope=dH, rise=face.rise, breaks=(), a=0.0, b=k.N11, load=1.0, n=16)
    loads = np.geomspace(1e-4, 100.0, 13)
    states = follow_load(face, eq, loads)
    counts = [len(s.zones) for s in states]
    assert counts[0] == 2 and counts[-1] == 1
    assert counts == sorted(counts, reverse=True)            # 2 ... 2, 1 ... 1: one merge
    for s in states:
        assert abs(s.solution.integral() - s.load) <= 1e-12 * s.load
        zs = s.zones
        assert abs(zs[0].c + zs[-1].d) <= 1e-10 * (zs[-1].d - zs[0].c)          # mirror
    last = states[-1].zones[0]
    assert (last.c, last.d, last.left, last.right) == (-2.0, 2.0, CORNER, CORNER)
    spans = [(s.zones[0].c, s.zones[-1].d) for s in states]
    assert all(a1 <= a0 and b1 >= b0 for (a0, b0), (a1, b1) in zip(spans, spans[1:]))


def test_load_curve_tilted_flat_punch_lifts_off_one_end():
    """A flat face tilted by a constant slope, edges at -1 and 1: first touch at the low edge
    (a corner, the other end free: index 0), the triangular punch translated, until the free
    end reaches the high edge (index 1)."""
    m0 = 0.05
    k = contact.surface_constants(MAT, 0.3)
    face = Face(lambda X: np.full_like(X, m0), extent=(-1.0, 1.0), height=lambda X: m0 * X)
    eq = ZoneEquations(slope=face.slope, rise=face.rise, breaks=(), a=k.N12 * 0.3, b=k.N11,
                       load=1.0, n=8)
    states = follow_load(face, eq, [1e-3, 1e-2, 1e-1, 1.0, 10.0])
    for s in states[:4]:
        (z,) = s.zones
        ref = contact.solve(MAT, contact.TriangularPunch(slope=m0), load=s.load, speed=0.3,
                            friction=0.3)
        assert (z.c, z.left, z.right) == (-1.0, CORNER, FREE)
        assert abs((z.d + 1.0) - ref.ends[1]) <= 1e-12 * ref.ends[1]
    (z,) = states[-1].zones
    assert (z.c, z.d, z.left, z.right) == (-1.0, 1.0, CORNER, CORNER)
    assert abs(states[-1].solution.integral() - 10.0) <= 1e-12 * 10.0


def test_load_curve_rounded_flat_punch_against_ciavarella_hills_monno():
    """Flat on |X| <= b, rounded with radius R beyond (static, isotropic, frictionless): the
    contact half-width against the closed form of Ciavarella, Hills & Monno (1998), from
    first touch on the flat stretch."""
    import rounded_flat_reference as RF
    k = contact.surface_constants(contact.Isotropic(1.0, 0.3), 0.0)
    b, R = 0.5, 3.0

    def dH(X):
        return np.where(np.abs(X) > b, np.sign(X) * (np.abs(X) - b) / R, 0.0)

    def H(X):
        return np.where(np.abs(X) > b, (np.abs(X) - b) ** 2 / (2 * R), 0.0)

    face = Face(dH, extent=(-3.0, 3.0), breaks=(-b, b), height=H)
    eq = ZoneEquations(slope=dH, rise=face.rise, breaks=(-b, b), a=0.0, b=k.N11, load=1.0, n=24)
    for s in follow_load(face, eq, [1e-3, 1e-2, 0.1, 1.0]):
        (z,) = s.zones
        a = RF.half_width_for_load(s.load, b, R, k.N11)
        assert abs(z.d - a) <= 1e-12 * a and abs(z.c + a) <= 1e-12 * a


def test_flat_face_of_finite_width_is_the_flat_punch():
    """A flat face on [-a, a] touches everywhere at once: one zone with two corners (index 1),
    the flat punch."""
    a, P = 0.5, 0.03
    ref = contact.solve(MAT, contact.FlatPunch(half_width=a), load=P, speed=0.6, friction=0.3)
    k = contact.surface_constants(MAT, 0.6)
    face = Face(lambda X: np.zeros_like(X), extent=(-a, a), height=lambda X: np.zeros_like(X))
    eq = ZoneEquations(slope=face.slope, rise=face.rise, breaks=(), a=k.N12 * 0.3, b=k.N11,
                       load=P, n=8)
    (s,) = follow_load(face, eq, [P])
    (z,) = s.zones
    assert (z.c, z.d, z.left, z.right) == (-a, a, CORNER, CORNER)
    X = np.linspace(-0.45, 0.45, 7)
    assert np.allclose(s.solution(X), ref.pressure(X), rtol=1e-12, atol=0)


def test_load_curve_w_face_against_closed_form_and_merge_load():
    """Frictionless W face: zones against the closed form (bem_reference.w_face_closed_form:
    two zones +-[c, b] with b^2 + c^2 = 2, (b^2 - c^2)^2 = 2 P |N11| / (pi A); one zone after
    the merge at P* |N11| = 2 pi A) to 1e-10, on both sides of the merge load (at 0.99 P* the
    inner ends sit at +-0.07 and move like sqrt(P* - P): a residual of eps moves them ~1/c
    times more than elsewhere; measured 1.1e-11 there, 1e-15 at light load)."""
    import bem_reference as B
    H, dH = _w_face()
    k = contact.surface_constants(MAT, 0.6)
    face = Face(dH, extent=(-2.0, 2.0), height=H)
    eq = ZoneEquations(slope=dH, rise=face.rise, breaks=(), a=0.0, b=k.N11, load=1.0, n=16)
    p_merge = 2.0 * np.pi * B.W_AMPLITUDE / abs(k.N11)
    loads = [1e-3 * p_merge, 0.3 * p_merge, 0.99 * p_merge, 1.01 * p_merge, 1.5 * p_merge]
    for s in follow_load(face, eq, loads):
        want = B.w_face_closed_form(k.N11, s.load)
        got = [(z.c, z.d) for z in s.zones]
        assert len(got) == len(want), (s.load / p_merge, got, want)
        assert np.allclose(got, want, rtol=0, atol=1e-10), (s.load / p_merge, got, want)


def test_w_face_with_friction_against_the_independent_bem():
    """With friction (mu = 0.3, c = 0.6) the two zones are asymmetric; the boundary-element
    solver of tests/reference/bem_reference.py (its own discretisation; refined edges good to ~1e-6)
    agrees to its accuracy."""
    import bem_reference as B
    H, dH = _w_face()
    k = contact.surface_constants(MAT, 0.6)
    mu_f = 0.3                       # direction -1
    P = 1.30011
    eq = ZoneEquations(slope=dH, rise=lambda x0, x1: H(x1) - H(x0), breaks=(),
                       a=k.N12 * mu_f, b=k.N11, load=P, n=24)
    zs, _, _ = eq.newton([Zone(-1.33, -0.44), Zone(0.46, 1.35)])
    ref = B.solve_bem(B.w_face, B.W_FACE, k.N11, k.N12 * mu_f, P, m=500, refine=32)
    assert len(ref.zones) == 2
    assert np.allclose([(z.c, z.d) for z in zs], ref.zones, rtol=0, atol=2e-5)


# Faces where a search for a single zone goes wrong: it returns a zone next to X = 0
# (penetrating elsewhere) or fails in its end search.
TRIAL_FACES = {
    # cylinder R = 100 with a protrusion 0.12 below the tip at X = 4: first touch there
    "protrusion": (lambda X: X / 100 + 0.8 * (X - 4) * np.exp(-(X - 4) ** 2 / 0.5),
                   lambda X: X * X / 200 - 0.2 * np.exp(-(X - 4) ** 2 / 0.5),
                   (-np.inf, np.inf), 0.01, (3.8, 4.1)),
    # the asymmetric bump X^2/200 + X^3/300 on the face [-1, 1]: one zone around X = 0
    "asymmetric bump": (lambda X: X / 100 + X * X / 100, lambda X: X * X / 200 + X ** 3 / 300,
                        (-1.0, 1.0), 1e-4, (-0.1, 0.1)),
    # a narrow dip at X = 0.8 on a wide cylinder: first touch in the dip
    "narrow dip": (lambda X: X / 100 + (X - 0.8) * np.exp(-(X - 0.8) ** 2 / 0.02),
                   lambda X: X * X / 200 - 0.01 * np.exp(-(X - 0.8) ** 2 / 0.02),
                   (-np.inf, np.inf), 0.01, (0.7, 0.9)),
}


@pytest.mark.parametrize("name", list(TRIAL_FACES))
def test_trial_faces_touch_where_the_face_is_lowest(name):
    """One zone where the face is lowest, p >= 0 in it, the gap >= 0 over the sampled face
    (checked by follow_load), the load carried."""
    dH, H, extent, P, where = TRIAL_FACES[name]
    k = contact.surface_constants(MAT, 0.6)
    face = Face(dH, extent=extent, height=H)
    eq = ZoneEquations(slope=dH, rise=face.rise, breaks=(), a=k.N12 * 0.3, b=k.N11, load=P,
                       n=24)
    (s,) = follow_load(face, eq, [P])
    (z,) = s.zones
    assert where[0] < z.c < z.d < where[1]
    assert abs(s.solution.integral() - P) <= 1e-12 * P


PAPER_PUNCHES = {
    "flat": contact.FlatPunch(half_width=0.5),
    "triangular": contact.TriangularPunch(slope=0.1),
    "parabolic": contact.ParabolicPunch(radius=10.0),
    "cylindrical": contact.CylindricalPunch(radius=100.0),
}


@pytest.mark.parametrize("name", list(PAPER_PUNCHES))
@pytest.mark.parametrize("friction,direction", [(0.0, -1), (0.3, -1), (0.3, 1)])
def test_paper_punches_from_first_touch(name, friction, direction):
    """Punch.as_face() and the load curve from first touch give the single-zone solver's
    contact (ends and pressure) for the four punches of the paper: the flat face touches
    everywhere at once (two corners), the wedge and the parabola first at their corner, the
    cylinder at its lowest point."""
    punch, P, speed = PAPER_PUNCHES[name], 0.02, 0.6
    ref = contact.solve(MAT, punch, load=P, speed=speed, friction=friction, direction=direction)
    k = contact.surface_constants(MAT, speed)
    face = punch.as_face()
    mu_f = -direction * friction
    eq = ZoneEquations(slope=face.slope, rise=face.rise, breaks=face.breaks,
                       a=k.N12 * mu_f if mu_f else 0.0, b=k.N11, load=P, n=8)
    (s,) = follow_load(face, eq, [P])
    (z,) = s.zones
    w = ref.ends[1] - ref.ends[0]
    assert abs(z.c - ref.ends[0]) <= 1e-12 * w and abs(z.d - ref.ends[1]) <= 1e-12 * w
    X = ref.ends[0] + w * np.linspace(0.05, 0.95, 7)
    assert np.allclose(s.solution(X), ref.pressure(X), rtol=1e-10, atol=0)
