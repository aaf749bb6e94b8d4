"""The fretting cycle (contact.fretting_cycle): loading, unloading and reloading at constant P
for a pair that decouples, against Cattaneo-Mindlin-Deresiewicz for two cylinders of one
material in two dimensions.

Reference (Hertz: half-width a, p0 = 2P / (pi a); the contact at P' = x P has the half-width
a sqrt(x) and the pressure p0 (c/a) sqrt(1 - X^2/c^2)): with Phi_c = p0 [E_a - E_c],
E_r(X) = (r/a) sqrt(1 - X^2/r^2) (0 outside |X| < r), the traction on

    loading      q = mu Phi_c(Q),                  c(Q)  = a sqrt(1 - Q/(mu P)),
    unloading    q = mu Phi_c* - 2 mu Phi_c',      c'    = a sqrt(1 - (Q* - Q)/(2 mu P)),
    reloading    q(Q) = -q_unloading(-Q),

the sum of three semi-ellipses (Mindlin & Deresiewicz 1953; Johnson, Contact Mechanics
(1985), ch. 7; Hills & Nowell, Mechanics of Fretting Fatigue (1994)).  The slip of Phi_c,
from the transforms Hc[sqrt(r^2 - t^2)](X) = -X + sign(X) sqrt(X^2 - r^2) [abs(X) > r] and
d(u - u_p)/dX = T Hc[q], is -T (p0/a) G_c(abs(X)) beyond c, G_c(y) = int_c^y sqrt(t^2 - c^2)
dt; the energy per cycle, 4 mu int p s dX over the slip zones at Q*, is integrated here by
mpmath from these alone and compared with the closed form (11) of contact.fretting.
"""
import math

import mpmath
import numpy as np
import pytest

import contact

MAT = contact.Isotropic(1.0, 0.3)
P, MU, R = 0.01, 0.5, 1.0
QA = 0.5 * MU * P           # the amplitude of the cycle the tests share
STEPS = 16


def cycle(Qa=QA, steps=STEPS, **kw):
    return contact.fretting_cycle(MAT, contact.CylindricalPunch(R), load=P, friction=MU,
                                  tangential_amplitude=Qa, punch_material=MAT, steps=steps,
                                  **kw)


@pytest.fixture(scope="module")
def cyc():
    return cycle()


def ellipse(x, a, r):
    return (r / a) * np.sqrt(np.maximum(1 - (x / r) ** 2, 0.0))


def phi(x, a, c):
    """p(X; P) - p(X; P') of Hertz, P' = P c^2 / a^2."""
    return 2 * P / (math.pi * a) * (ellipse(x, a, a) - ellipse(x, a, c))


def unloading(x, a, Q):
    """The unloading traction: three semi-ellipses."""
    cs = a * math.sqrt(1 - QA / (MU * P))
    cr = a * math.sqrt(1 - (QA - Q) / (2 * MU * P))
    return MU * phi(x, a, cs) - 2 * MU * phi(x, a, cr)


def G(y, c):
    """int_c^y sqrt(t^2 - c^2) dt, y >= c."""
    return 0.5 * (y * np.sqrt(y * y - c * c) - c * c * np.arccosh(y / c))


def slip_of_phi(x, a, c, T):
    """The slip of Phi_c (weight 1): -T (p0/a) G_c(abs(X)) beyond c, 0 inside."""
    y = np.abs(x)
    out = np.zeros_like(y)
    out[y > c] = -T * 2 * P / (math.pi * a * a) * G(y[y > c], c)
    return out


def W_closed(Qa, T):
    """Eq. (11) of contact.fretting."""
    x = 1 - Qa / (MU * P)
    return abs(T) * (MU * P) ** 2 / math.pi * (1 - x * x + 2 * x * math.log(x))


def test_the_unloading_and_reloading_states_are_mindlin_deresiewicz(cyc):
    """At every Q of the unloading: the stick zone |X| < c', c'/a = sqrt(1 - (Q* - Q)/(2 mu
    P)), the reverse slip zones beyond it, q the sum of three semi-ellipses to 1e-12 mu p0;
    the reloading mirrored."""
    a = cyc.full.ends[1]
    p0 = 2 * P / (math.pi * a)
    x = a * np.linspace(-0.999, 0.999, 61)
    for st in cyc.unloading:
        Q = st.tangential_load
        cr = a * math.sqrt(1 - (QA - Q) / (2 * MU * P))
        ((c0, c1),) = [z.ends for z in st.stick_zones]
        assert (c0, c1) == pytest.approx((-cr, cr), abs=1e-13 * a)
        if Q < QA:
            np.testing.assert_allclose(st.slip_zones, ((-a, -cr), (cr, a)), rtol=0,
                                       atol=1e-13 * a)
            assert st.slip_sense == -1
        np.testing.assert_allclose(st.tangential_traction(x), unloading(x, a, Q), rtol=0,
                                   atol=1e-12 * MU * p0)
    for st in cyc.reloading:
        np.testing.assert_allclose(st.tangential_traction(x),
                                   -unloading(x, a, -st.tangential_load), rtol=0,
                                   atol=1e-12 * MU * p0)
        assert st.slip_sense == 1


def test_the_slip_is_the_closed_form_and_the_displacement_the_loading_curve(cyc):
    """s(X) of the peak and of an unloading state against -T (p0/a) G_c; delta on loading
    against (T mu P/pi) [(1 - x) log(1/2) - (x/2) log x - (1 - x)/2] (the datum l = a)."""
    a = cyc.full.ends[1]
    T = cyc.full.constants.tangential_compliance
    assert T == pytest.approx(-3.64, rel=1e-14)        # two bodies: 2 (-2 (1 - nu^2) / E)
    cs = a * math.sqrt(1 - QA / (MU * P))
    x = a * np.linspace(-0.999, 0.999, 41)
    peak = cyc.loading[-1]
    scale = MU * slip_of_phi(np.array([a]), a, cs, T)[0]
    np.testing.assert_allclose(peak.slip(x), MU * slip_of_phi(x, a, cs, T), rtol=0,
                               atol=1e-12 * scale)
    st = cyc.unloading[STEPS // 2 + 3]
    cr = a * math.sqrt(1 - (QA - st.tangential_load) / (2 * MU * P))
    np.testing.assert_allclose(st.slip(x), MU * slip_of_phi(x, a, cs, T)
                               - 2 * MU * slip_of_phi(x, a, cr, T), rtol=0, atol=1e-12 * scale)
    for st in cyc.loading:
        xx = 1 - st.tangential_load / (MU * P)
        ref = T * MU * P / math.pi * ((1 - xx) * math.log(0.5) - 0.5 * xx * math.log(xx)
                                      - 0.5 * (1 - xx))
        assert st.displacement == pytest.approx(ref, abs=1e-13 * cyc.loading[-1].displacement)


def test_the_energy_per_cycle_three_ways(cyc):
    """W from the frictional work (the module), from the loop's area oint Q d(delta)
    (Clenshaw-Curtis on the path's Chebyshev points) and from eq. (11), which mpmath
    confirms from the closed-form traction and slip alone."""
    a = cyc.full.ends[1]
    T = cyc.full.constants.tangential_compliance
    W = W_closed(QA, T)
    # eq. (11) against 8 mu int_c^a p s dX, the slip G_c itself by quadrature
    mpmath.mp.dps = 30
    try:
        cs = a * mpmath.sqrt(1 - mpmath.mpf(QA) / (MU * P))
        p0 = 2 * mpmath.mpf(P) / (mpmath.pi * a)

        def s(y):
            return -T * p0 / a * mpmath.quad(lambda t: mpmath.sqrt(t * t - cs * cs), [cs, y])
        assert abs(s(0.9 * a) / (MU * slip_of_phi(np.array([0.9 * a]), a, float(cs), T)[0])
                   * MU - 1) < 1e-13
        ref = 8 * MU * mpmath.quad(lambda y: p0 * mpmath.sqrt(1 - (y / a) ** 2) * MU
                                   * -T * p0 / a * (y * mpmath.sqrt(y * y - cs * cs)
                                                    - cs * cs * mpmath.acosh(y / cs)) / 2,
                                   [cs, a])
    finally:
        mpmath.mp.dps = 15
    assert float(ref) == pytest.approx(W, rel=1e-14)
    assert cyc.energy_per_cycle == pytest.approx(W, rel=1e-10)
    # the loop's area: at Q = Q* c_i the unloading state i and the reloading state m - i
    c = np.array([st.tangential_load for st in cyc.unloading]) / QA
    width = np.array([u.displacement - r.displacement
                      for u, r in zip(cyc.unloading, cyc.reloading[::-1])])
    area = QA * np.polynomial.Chebyshev.fit(c, width, STEPS, domain=[-1, 1]).integ(lbnd=-1)(1)
    assert area == pytest.approx(W, rel=1e-10)


def test_the_loop_is_point_symmetric_and_closes(cyc):
    """delta_reloading(-Q) = -delta_unloading(Q), q likewise; the reloading ends where the
    loading did; the unloading starts from it."""
    x = cyc.full.ends[1] * np.linspace(-0.99, 0.99, 21)
    for u, r in zip(cyc.unloading, cyc.reloading):
        assert r.tangential_load == -u.tangential_load
        assert r.displacement == -u.displacement
        np.testing.assert_allclose(r.tangential_traction(x), -u.tangential_traction(x),
                                   rtol=0, atol=1e-18)
    peak, start, end = cyc.loading[-1], cyc.unloading[0], cyc.reloading[-1]
    assert peak.tangential_load == start.tangential_load == end.tangential_load == QA
    assert peak.displacement == pytest.approx(end.displacement, rel=1e-14)
    assert start.displacement == pytest.approx(peak.displacement, rel=1e-14)
    np.testing.assert_allclose(end.tangential_traction(x), peak.tangential_traction(x),
                               rtol=0, atol=1e-15)
    Q, d = cyc.loop
    assert len(Q) == 2 * STEPS + 1 and Q[0] == Q[-1] == QA and d[0] == d[-1]
    assert np.all(np.diff([s.displacement for s in cyc.unloading]) < 0)


def test_the_datum_tilts_the_loop_and_leaves_its_area():
    """Another reference length l' adds -(T/pi) log(l'/l) Q to every displacement."""
    base = cycle(steps=8)
    other = cycle(steps=8, reference_length=2 * base.reference_length)
    T = base.full.constants.tangential_compliance
    np.testing.assert_allclose(other.displacements - base.displacements,
                               -T / math.pi * math.log(2) * base.tangential_loads, rtol=0,
                               atol=1e-15)
    assert other.energy_per_cycle == base.energy_per_cycle


def test_small_amplitudes_dissipate_like_the_cube():
    """W ~ abs(T) Q*^3 / (3 pi mu P): the order 3 from two amplitudes, and eq. (11)."""
    small = [cycle(Qa, steps=4) for Qa in (0.01 * MU * P, 0.02 * MU * P)]
    T = small[0].full.constants.tangential_compliance
    for c in small:
        assert c.energy_per_cycle == pytest.approx(W_closed(c.tangential_amplitude, T),
                                                   rel=1e-10)
    order = math.log2(small[1].energy_per_cycle / small[0].energy_per_cycle)
    assert order == pytest.approx(3.0, abs=0.01)
    lead = abs(T) * (0.01 * MU * P) ** 3 / (3 * math.pi * MU * P)
    assert small[0].energy_per_cycle / lead == pytest.approx(1.0, abs=0.01)


def test_near_full_sliding_the_stick_zone_vanishes_and_the_loop_opens():
    """Q* -> mu P: the stick zone at Q* shrinks like sqrt(1 - Q*/(mu P)) and W tends to
    abs(T) mu^2 P^2 / pi."""
    eps = 1e-6
    c = cycle(MU * P * (1 - eps), steps=4)
    T = c.full.constants.tangential_compliance
    a, cs = c.full.ends[1], c.loading[-1].stick_zones[0].ends[1]
    assert cs / a == pytest.approx(math.sqrt(eps), rel=1e-9)
    assert c.energy_per_cycle == pytest.approx(W_closed(c.tangential_amplitude, T), rel=1e-10)
    assert c.energy_per_cycle == pytest.approx(abs(T) * (MU * P) ** 2 / math.pi, rel=1e-4)


def test_the_loading_branch_is_solve_with_the_tangential_load(cyc):
    a = cyc.full.ends[1]
    x = a * np.linspace(-0.999, 0.999, 41)
    for st in cyc.loading[1::2]:
        r = contact.solve(MAT, contact.CylindricalPunch(R), load=P, speed=0.0, friction=MU,
                          punch_material=MAT, tangential_load=st.tangential_load)
        np.testing.assert_allclose([z.ends for z in st.stick_zones],
                                   [z.ends for z in r.stick_zones], rtol=0, atol=1e-14 * a)
        np.testing.assert_allclose(st.tangential_traction(x), r.tangential_traction(x),
                                   rtol=0, atol=1e-13 * MU * 2 * P / (math.pi * a))


@pytest.mark.parametrize("kw,error,match", [
    (dict(tangential_amplitude=MU * P), contact.FrictionError, "full sliding"),
    (dict(tangential_amplitude=2 * MU * P), contact.FrictionError, "full sliding"),
    (dict(tangential_amplitude=0.0), contact.LoadError, "positive"),
    (dict(tangential_amplitude=-1e-3), contact.LoadError, "positive"),
    (dict(tangential_amplitude=float("nan")), contact.LoadError, "tangential_amplitude"),
    (dict(friction=0.0), contact.FrictionError, "friction > 0"),
    (dict(punch_material=None), contact.CoupledPartialSlipError, "beta"),
    (dict(punch_material=contact.Isotropic(2.0, 0.3)), contact.CoupledPartialSlipError,
     "beta"),
    (dict(steps=1), contact.ContactInputError, "steps"),
    (dict(reference_length=-1.0), contact.ContactInputError, "reference_length")])
def test_what_a_fretting_cycle_cannot_do_is_said(kw, error, match):
    args = dict(load=P, friction=MU, tangential_amplitude=QA, punch_material=MAT)
    args.update(kw)
    with pytest.raises(error, match=match):
        contact.fretting_cycle(MAT, contact.CylindricalPunch(R), **args)
