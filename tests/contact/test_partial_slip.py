"""Partial slip under a tangential load (contact.solve(..., tangential_load=Q)) for pairs whose
normal and tangential problems decouple, against Cattaneo-Mindlin.

Reference (two cylinders of one material, K. L. Johnson, Contact Mechanics (1985), the
Cattaneo-Mindlin problem in two dimensions; C. Cattaneo 1938, R. D. Mindlin 1949): Hertz's
half-width a and p0 = 2P / (pi a); the stick zone |x| < c, c/a = sqrt(1 - |Q| / (mu P)); the
tangential traction q = s mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)] in the stick zone,
s mu p0 sqrt(1 - x^2/a^2) in the slip zones, s = sign Q."""
import math

import numpy as np
import pytest
from scipy.integrate import quad

import contact

MAT = contact.Isotropic(1.0, 0.3)
P, MU, R = 0.01, 0.5, 1.0


def cattaneo(x, a, c, Q):
    p0 = 2 * P / (math.pi * a)
    stick = np.where(np.abs(x) < c, (c / a) * np.sqrt(np.maximum(1 - (x / c) ** 2, 0.0)), 0.0)
    return math.copysign(1.0, Q) * MU * p0 * (np.sqrt(1 - (x / a) ** 2) - stick)


def solve(Q, **kw):
    return contact.solve(MAT, contact.CylindricalPunch(R), load=P, speed=0.0, friction=MU,
                         punch_material=MAT, tangential_load=Q, **kw)


@pytest.mark.parametrize("Q", [1e-4, 0.002, -0.0035, 0.0049])
def test_cattaneo_mindlin_stick_zone_and_traction(Q):
    r = solve(Q)
    a = r.ends[1]
    c = a * math.sqrt(1 - abs(Q) / (MU * P))
    ((c0, c1),) = [z.ends for z in r.stick_zones]
    assert (c0, c1) == pytest.approx((-c, c), abs=1e-13 * a)
    np.testing.assert_allclose(r.slip_zones, ((-a, -c), (c, a)), rtol=0, atol=1e-13 * a)
    x = a * np.linspace(-0.999, 0.999, 61)
    p0 = 2 * P / (math.pi * a)
    np.testing.assert_allclose(r.tangential_traction(x), cattaneo(x, a, c, Q), rtol=0,
                               atol=1e-12 * MU * p0)


def test_coulomb_holds_and_the_traction_adds_up_to_the_load():
    """abs(q) <= mu p, equal on the slip zones; int q = Q (quadrature of the traction)."""
    Q = 0.003
    r = solve(Q)
    a = r.ends[1]
    x = a * np.linspace(-0.9999, 0.9999, 801)
    q, p = r.tangential_traction(x), r.pressure(x)
    assert np.all(np.abs(q) <= MU * p * (1 + 1e-12) + 1e-15)
    slip = np.abs(x) > r.stick_zones[0].ends[1]
    np.testing.assert_allclose(q[slip], MU * p[slip], rtol=1e-12)
    total, err = quad(lambda t: float(r.tangential_traction(t)), -a, a,
                      points=list(r.stick_zones[0].ends), epsabs=1e-15, limit=200)
    assert total == pytest.approx(Q, rel=1e-9)


def test_the_limits_no_tangential_load_and_full_sliding():
    """Q = 0: everything sticks, q = 0, the pressure the frictionless one; Q -> mu P: the stick
    zone shrinks to nothing and q tends to the sliding traction mu p."""
    none = solve(0.0)
    assert [z.ends for z in none.stick_zones] == [z.ends for z in none.zones]
    x = none.ends[1] * np.linspace(-0.9, 0.9, 7)
    assert np.all(none.tangential_traction(x) == 0.0)
    near = solve(MU * P * (1 - 1e-8))
    a, c = near.ends[1], near.stick_zones[0].ends[1]
    assert c / a == pytest.approx(1e-4, rel=1e-6)
    x = x[np.abs(x) > c]        # outside the stick zone q is mu p (inside, mu (p - p*))
    np.testing.assert_allclose(near.tangential_traction(x), MU * near.pressure(x), rtol=1e-13)


def test_the_surface_stress_carries_the_tangential_traction():
    """On the surface sigma_XY = -q and sigma_YY = -p (the field's superposition of the
    contacts at P and P*)."""
    r = solve(0.002)
    x = r.ends[1] * np.linspace(-0.95, 0.95, 9)
    f = r.stress(x, np.zeros_like(x))
    np.testing.assert_allclose(f.sigma_xy, -r.tangential_traction(x), rtol=0, atol=1e-15)
    np.testing.assert_allclose(f.sigma_yy, -r.pressure(x), rtol=0, atol=1e-15)
    below = r.stress(0.0, -0.5 * r.ends[1])
    assert np.isfinite(below.sigma_xx) and np.isfinite(below.sigma_xy)


def test_two_isotropic_bodies_with_equal_n12_decouple_too():
    """Dissimilar isotropic bodies with (1 - 2 nu1)/G1 = (1 - 2 nu2)/G2: beta = 0, Cattaneo's
    stick zone again."""
    E2, nu2 = 2.0, 0.3
    G1, G2 = 1.0 / 2.6, E2 / 2.6
    nu1 = 0.5 - 0.5 * (1 - 2 * nu2) * G1 / G2      # (1 - 2 nu1)/G1 = (1 - 2 nu2)/G2
    m1 = contact.Isotropic(2 * G1 * (1 + nu1), nu1)
    r = contact.solve(m1, contact.CylindricalPunch(R), load=P, speed=0.0, friction=MU,
                      punch_material=contact.Isotropic(E2, nu2), tangential_load=0.003)
    assert r.stick_zones[0].ends[1] / r.ends[1] == pytest.approx(math.sqrt(0.4), rel=1e-12)


@pytest.mark.parametrize("kw,error,match", [
    (dict(punch_material=None), contact.CoupledPartialSlipError, "beta"),
    (dict(punch_material=MAT, speed=0.5), contact.CoupledPartialSlipError, "speed 0.5"),
    (dict(punch_material=MAT, tangential_load=0.005), contact.FrictionError, "full sliding"),
    (dict(punch_material=MAT, friction=0.0), contact.FrictionError, "needs friction"),
    (dict(punch_material=MAT, tangential_load=float("nan")), contact.LoadError,
     "tangential_load")])
def test_what_partial_slip_cannot_do_is_said(kw, error, match):
    args = dict(load=P, speed=0.0, friction=MU, tangential_load=0.002)
    args.update(kw)
    with pytest.raises(error, match=match):
        contact.solve(MAT, contact.CylindricalPunch(R), **args)


# --------------------------------------------------------------------------
# steady rolling (Carter)
# --------------------------------------------------------------------------
def carter(x, a, c, Q, direction):
    """Carter's traction (Johnson 1985, rolling with traction): the stick zone of half-width c
    at the leading edge (x = -a rolling toward -X), centred at d = -+(a - c)."""
    d = -(a - c) if direction < 0 else a - c
    p0 = 2 * P / (math.pi * a)
    stick = np.where(np.abs(x - d) < c,
                     (c / a) * np.sqrt(np.maximum(1 - ((x - d) / c) ** 2, 0.0)), 0.0)
    return math.copysign(1.0, Q) * MU * p0 * (np.sqrt(1 - (x / a) ** 2) - stick)


def roll(direction=-1, **kw):
    return contact.solve(MAT, contact.CylindricalPunch(R), load=P, speed=0.0, friction=MU,
                         punch_material=MAT, rolling=True, direction=direction, **kw)


@pytest.mark.parametrize("Q,direction", [(0.003, -1), (0.003, 1), (-0.0045, -1)])
def test_carter_stick_zone_at_the_leading_edge_traction_and_creepage(Q, direction):
    """The stick zone [-a, -a + 2c] rolling toward -X (mirrored toward +X), c/a =
    sqrt(1 - |Q|/(mu P)); the traction to 1e-12; the creepage xi = s mu (c - a)/R toward
    -X (T = b for one isotropic material: Carter's |xi| = (mu a / R)(1 - c/a))."""
    r = roll(direction, tangential_load=Q)
    a = r.ends[1]
    c = a * math.sqrt(1 - abs(Q) / (MU * P))
    stick = (-a, -a + 2 * c) if direction < 0 else (a - 2 * c, a)
    np.testing.assert_allclose(r.stick_zones[0].ends, stick, rtol=0, atol=1e-13 * a)
    x = a * np.linspace(-0.999, 0.999, 61)
    np.testing.assert_allclose(r.tangential_traction(x), carter(x, a, c, Q, direction),
                               rtol=0, atol=1e-12 * MU * 2 * P / (math.pi * a))
    s = math.copysign(1.0, Q)
    assert r.creepage == pytest.approx(direction * s * MU * (a - c) / R, rel=1e-12)


@pytest.mark.parametrize("xi", [-0.01, 0.02, -0.035])
def test_the_traction_curve_from_the_creepage_is_carters(xi):
    """Given the creepage: Q / (mu P) = 1 - (1 - |xi| R / (mu a))^2 (Carter), and Q back
    from that creepage's solve gives the same creepage."""
    r = roll(creepage=xi)
    a = r.ends[1]
    ratio = 1 - (1 - abs(xi) * R / (MU * a)) ** 2
    assert abs(r.tangential_load) == pytest.approx(ratio * MU * P, rel=1e-11)
    assert roll(tangential_load=r.tangential_load).creepage == pytest.approx(xi, rel=1e-11)


def test_free_rolling_and_creepage_beyond_full_slip():
    free = roll(tangential_load=0.0)
    assert free.creepage == 0.0
    assert np.all(free.tangential_traction(np.linspace(-0.1, 0.1, 5)) == 0.0)
    a = free.ends[1]
    with pytest.raises(contact.FrictionError, match="full slip"):
        roll(creepage=1.01 * MU * a / R)


@pytest.mark.parametrize("kw,match", [(dict(rolling=True), "one of"),
                                      (dict(rolling=True, tangential_load=1e-3, creepage=1e-3),
                                       "one of"),
                                      (dict(creepage=1e-3), "rolling=True"),
                                      (dict(rolling=True, creepage=1e-3, method="closed_form"),
                                       "numeric"),
                                      (dict(rolling=1, creepage=1e-3), "True or False")])
def test_what_rolling_needs_is_said(kw, match):
    with pytest.raises(contact.ContactInputError, match=match):
        contact.solve(MAT, contact.CylindricalPunch(R), load=P, speed=0.0, friction=MU,
                      punch_material=MAT, **kw)


@pytest.mark.parametrize("C,c", [((5.0, 1.0, 2.0, 0.7), 0.0), ((5.0, 1.0, 2.0, 0.7), 0.5),
                                 ((159.7885, 5.2609, 15.4732, 5.52), 0.2),
                                 ((3.0, 1.0, 3.0, 1.0), 0.7)])
def test_the_orthotropic_tangential_compliance_is_the_stroh_response(C, c):
    """-P S C22 / Delta (contact.constants) against slope_hilbert[X, q] of the Stroh
    formalism (contact.Anisotropic, an independent route), moving and at rest."""
    o = contact.Orthotropic(*C, rho=1.0)
    A = contact.Anisotropic.from_orthotropic(o, C13=1.0, C23=1.0, C33=2 * max(C[0], C[2]),
                                             C44=0.6, C55=0.6, rho=1.0)
    T = contact.surface_constants(o, c).tangential_compliance
    assert T == pytest.approx(float(A.surface_response(c).slope_hilbert[0, 0]), rel=1e-12)


def test_the_extrema_under_the_surface_are_those_of_the_superposed_field():
    """PartialSlipResult.stress_extrema searches its own stress: the largest max_shear it
    reports is the field's value at the point it names, and the tangential load moves it
    toward the surface (Hertz's 0.300 p0 at 0.786 a without it)."""
    r = solve(0.004)
    ext = r.stress_extrema()
    peak = ext.max_shear
    f = r.stress(peak.X, peak.Y)
    assert float(f.max_shear) == pytest.approx(peak.value, rel=1e-9)
    a, p0 = r.ends[1], float(r.pressure(0.0))
    assert peak.value > 0.300 * p0 and abs(peak.Y) < 0.786 * a
