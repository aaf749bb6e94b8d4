"""An elastic punch (contact.solve(..., punch_material=...)): the punch's compliance added to
the half-space's (contact.elastic_punch), against the classical two-body results.

References: K. L. Johnson, Contact Mechanics (1985): Hertz's two cylinders (a^2 =
4 P R / (pi E*), 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, p = (2P / (pi a^2)) sqrt(a^2 - x^2));
the flat punch sliding with friction (half-width 1: p = P cos(pi g) / pi (1 - x)^(-1/2 + g)
(1 + x)^(-1/2 - g), tan(pi g) = beta mu: the power is fixed by the local equation at each
corner, the factor by int p = P, int (1 - x)^(-1/2 + g) (1 + x)^(-1/2 - g) = pi / cos(pi g));
J. Dundurs, J. Appl. Mech. 36 (1969) 650 (beta, plane strain kappa = 3 - 4 nu)."""
import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import contact
from contact.elastic_punch import punch_constants, two_body_constants


def dundurs_beta(E1, nu1, E2, nu2):
    """Dundurs' beta of body 1 (the half-space) and body 2 (the punch), plane strain."""
    G1, G2 = E1 / (2 * (1 + nu1)), E2 / (2 * (1 + nu2))
    k1, k2 = 3 - 4 * nu1, 3 - 4 * nu2
    return (G1 * (k2 - 1) - G2 * (k1 - 1)) / (G1 * (k2 + 1) + G2 * (k1 + 1))


@pytest.mark.parametrize("friction", [0.0, 0.5])
def test_two_identical_cylinders_are_hertz_with_the_pair_modulus_and_friction_leaves_them(
        friction):
    """Identical materials: beta = 0, so sliding friction does not change the pressure; the
    half-width and the pressure are Hertz's with 1/E* = 2 (1 - nu^2) / E."""
    E, nu, R, P = 2.0, 0.3, 3.0, 0.02
    m = contact.Isotropic(E, nu)
    r = contact.solve(m, contact.CylindricalPunch(R), load=P, speed=0.0, friction=friction,
                      punch_material=m)
    a = math.sqrt(4 * P * R / (math.pi * E / (2 * (1 - nu ** 2))))
    np.testing.assert_allclose(r.ends, (-a, a), rtol=0, atol=1e-13 * a)
    x = a * np.linspace(-0.95, 0.95, 9)
    np.testing.assert_allclose(r.pressure(x), 2 * P / (math.pi * a * a) * np.sqrt(a * a - x * x),
                               rtol=1e-11)
    assert r.punch_material is m


@pytest.mark.parametrize("E2,nu2,friction,direction", [(3.0, 0.2, 0.5, -1), (0.4, 0.45, 0.8, 1),
                                                       (1e3, 0.3, 0.3, -1)])
def test_sliding_flat_punch_of_another_material_has_johnsons_exponents_and_pressure(
        E2, nu2, friction, direction):
    """A flat punch of half-width 1 sliding over a dissimilar half-space: p = P cos(pi g) / pi
    (1 - x)^(-1/2 + g) (1 + x)^(-1/2 - g), g = arctan(beta mu_f) / pi with mu_f =
    -direction mu (the friction on the half-space), Dundurs' beta of the pair."""
    E1, nu1, P = 1.0, 0.3, 0.1
    r = contact.solve(contact.Isotropic(E1, nu1), contact.FlatPunch(half_width=1.0), load=P,
                      speed=0.0, friction=friction, direction=direction,
                      punch_material=contact.Isotropic(E2, nu2))
    g = math.atan(dundurs_beta(E1, nu1, E2, nu2) * (-direction) * friction) / math.pi
    assert r.alpha == pytest.approx(-0.5 + g, abs=1e-14)
    assert r.beta == pytest.approx(-0.5 - g, abs=1e-14)
    x = np.linspace(-0.9, 0.9, 7)
    ref = P * math.cos(math.pi * g) / math.pi * (1 - x) ** (-0.5 + g) * (1 + x) ** (-0.5 - g)
    np.testing.assert_allclose(r.pressure(x), ref, rtol=1e-12)


@pytest.mark.parametrize("E2,nu2", [(1.0, 0.3), (3.0, 0.2), (0.05, 0.49), (200.0, 0.0)])
def test_the_pair_coupling_is_dundurs_beta_and_the_compliance_is_two_over_e_star(E2, nu2):
    """N12* / N11* = beta (the half-space body 1), N11* = -2 / E* (plane strain)."""
    E1, nu1 = 1.0, 0.3
    both = two_body_constants(contact.surface_constants(contact.Isotropic(E1, nu1), 0.0),
                              punch_constants(contact.Isotropic(E2, nu2)))
    e_star = 1.0 / ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)
    assert both.N11 == pytest.approx(-2.0 / e_star, rel=1e-14)
    assert both.N12 / both.N11 == pytest.approx(dundurs_beta(E1, nu1, E2, nu2), rel=1e-13,
                                                abs=1e-16)


def test_a_very_stiff_punch_is_the_rigid_punch():
    m = contact.Isotropic(1.0, 0.25)
    kw = dict(load=0.01, speed=0.5, friction=0.3)
    rigid = contact.solve(m, contact.CylindricalPunch(2.0), **kw)
    stiff = contact.solve(m, contact.CylindricalPunch(2.0), punch_material=contact.Isotropic(1e10, 0.3),
                          **kw)
    w = rigid.ends[1] - rigid.ends[0]
    np.testing.assert_allclose(stiff.ends, rigid.ends, rtol=0, atol=1e-9 * w)
    assert stiff.constants.N21 == rigid.constants.N21      # the half-space's stresses


def test_one_anisotropic_material_in_one_orientation_cancels_the_local_coupling():
    """Two bodies of one rotated ply: the local parts of the relative slope cancel
    (N12 - N12_p = 0, no coupling of friction into the pressure) and the Hilbert parts
    double (N11, and M12: the ply seen from below has the opposite M12).  A turned ply has
    M12 != 0, so this also checks the half-turn about X."""
    ortho = contact.Orthotropic(5.0, 1.0, 2.0, 0.7)
    ply = contact.Anisotropic.from_orthotropic(ortho, C13=1.0, C23=1.0, C33=2.0, C44=0.6,
                                               C55=0.6).rotated(Rotation.from_euler("z", 30, degrees=True))
    own = contact.surface_constants(ply, 0.0)
    assert abs(own.M12) > 0.1 * abs(own.N11)
    both = two_body_constants(own, punch_constants(ply))
    assert abs(both.N12) < 1e-14 * abs(own.N12)
    assert both.N11 == pytest.approx(2 * own.N11, rel=1e-14)
    assert both.M12 == pytest.approx(2 * own.M12, rel=1e-13)


def test_batch_and_load_curve_take_the_punch_material_as_solve_does():
    m, steel = contact.Isotropic(1.0, 0.3), contact.Isotropic(3.0, 0.25)
    punch = contact.CylindricalPunch(1.0)
    kw = dict(speed=0.4, friction=0.2, punch_material=steel)
    one = contact.solve(m, punch, load=0.02, **kw)
    (batch,) = contact.solve_batch(m, punch, load=[0.02], **kw)
    curve = contact.load_curve(m, punch, [0.01, 0.02], **kw)
    assert batch.ends == pytest.approx(one.ends, abs=1e-14)
    assert curve[1].ends == pytest.approx(one.ends, abs=1e-12)


class _OwnMaterial:
    """A material of one's own with the protocol's methods (delegated)."""

    def __init__(self):
        self._m = contact.Isotropic(1.0, 0.3)

    def __getattr__(self, name):
        return getattr(self._m, name)


@pytest.mark.parametrize("bad,match", [("steel", "Material protocol"),
                                       (_OwnMaterial(), "seen from below")])
def test_a_punch_material_that_cannot_be_turned_or_is_not_a_material_is_refused(bad, match):
    with pytest.raises(contact.ContactInputError, match=match):
        contact.solve(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0), load=0.01,
                      speed=0.0, punch_material=bad)
