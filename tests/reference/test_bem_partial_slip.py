"""Validation of the independent partial-slip solver ``tests/reference/bem_partial_slip.py``
(coupled normal and tangential problems, Dundurs' beta != 0).

The solver uses neither ``sie`` nor ``contact``'s solver (``contact`` is imported here only
for its surface constants, to pin the sign conventions).  Checked:

* conventions: the single-body slopes and the pair's beta against ``contact.SurfaceConstants``
  and ``contact.elastic_punch.two_body_constants``; the panel matrices against quadrature;
  beta -> -beta flips the shear only; full sliding against ``bem_reference`` (to rounding)
  and ``bem_reference.PolynomialFaceOneZone`` (closed form);
* beta = 0: Cattaneo (closed form; first order in h for the zone ends, the discrete
  superposition of Ciavarella and Jager to rounding; path independence of a monotone Q);
* beta != 0 under normal load alone (Spence's problem): slip at the edges with the friction on
  a rigid punch pointing inward; c/a self-similar (the same at two loads); the growing Hertzian
  contact's c/a equal to the flat punch's (the increment of the one is the other); the limit
  beta -> 0 at fixed beta/mu against K'(c/a)/K(c/a) = abs(beta)/mu (derived in
  ``bem_partial_slip.goodman_stick_ratio``; Spence's own tables (J. Elasticity 5 (1975) 297)
  were not available, so no published digit is compared); the local exponent of the stick
  deficit;
* the flat punch for large mu (slip zones ~ exp(-arctan(mu)/eps), full stick on the grid) and
  the rounded flat (beta = 0 against ``rounded_flat_reference``);
* beta != 0 under Q at constant P: all the conditions of the model hold, the numbers approach
  the converged table, the path matters, and Q -> mu P tends to full sliding.

Coarse grids here (m <= 400); the converged numbers (m up to 800 and Richardson) are printed by
``python tests/reference/bem_partial_slip.py`` and quoted in the tests' comments.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import ellipk

import bem_partial_slip as B


A4 = 4.0                       # A = 4: (A/4) = 1 in eq. (3)
R = 1.0
P_HERTZ = math.pi / 2          # a = 1 for beta = 0 (a = sqrt(A R P / (2 pi)))
WINDOW = (-1.25, 1.25)
NU = 0.3
BETA_RIGID = -(1 - 2 * NU) / (2 * (1 - NU))          # rigid punch on nu = 0.3: -0.2857


def _check_conditions(sv, st, prev_s, tol=1e-9):
    """Every condition of the model on the discrete solution ``st``."""
    mu, h = sv.mu, sv.h
    C = st.state != B.OFF
    ps, ss = np.max(st.p), max(np.max(np.abs(st.ds)), 1e-300)
    assert np.all(st.p[C] >= -tol * ps) and np.all(st.p[~C] == 0) and np.all(st.q[~C] == 0)
    assert np.all(np.abs(st.g[C]) == 0) and np.all(st.g[~C] >= -tol * np.max(np.abs(st.g)))
    assert np.all(np.abs(st.q) <= mu * st.p * (1 + tol) + tol * ps)
    T = st.state == B.STICK
    assert np.all(np.abs(st.s[T] - prev_s[T]) <= tol * ss)
    for code, sgn in ((B.SLIP_POS, 1.0), (B.SLIP_NEG, -1.0)):
        k = st.state == code
        assert np.allclose(st.q[k], sgn * mu * st.p[k], rtol=1e-12, atol=1e-14 * ps)
        assert np.all(sgn * st.ds[k] <= tol * ss)             # q opposes the slip increment
    assert h * st.p.sum() == pytest.approx(st.P, rel=1e-12)
    assert h * st.q.sum() == pytest.approx(st.Q, abs=1e-12 * st.P)
    # the fields are those of the model
    k = sv.k
    g = sv.Hx - st.delta + k * (sv.L @ st.p + sv.beta * (sv.S @ st.q))
    s = st.D + k * (sv.L @ st.q - sv.beta * (sv.S @ st.p))
    assert np.allclose(g[~C], st.g[~C], atol=1e-12) and np.allclose(g[C], 0, atol=1e-12)
    assert np.allclose(s, st.s, atol=1e-12)


# converged numbers (``python tests/reference/bem_partial_slip.py``: m = 100, 200, 400, 800,
# Richardson from the last two; A = 4, R = 1, P = pi/2, rigid punch on nu = 0.3, beta =
# -0.2857, mu = 0.3).  Under P alone: a = 0.97650 (+-1e-4), c/a = 0.6891 (+-3e-4; the flat
# punch 0.68916), q/mu at X/a = 0.25, 0.5, 0.75: -0.53538, -0.73896, -0.6439 (+-1e-4).  After
# Q = 0.5 mu P (10 steps; 40 give the same digits): stick zone [-0.0329, 0.8061] aQ (+-3e-4),
# q/mu at X/aQ = -0.5, 0, 0.5: 0.82195, 0.67535, -0.27180 (+-6e-5).
SPENCE_CONVERGED = dict(c_a=0.6891, q=(-0.53538, -0.73896, -0.6439))
TANGENTIAL_CONVERGED = dict(c=(-0.0329, 0.8061), q=(0.82195, 0.67535, -0.27180))


# --------------------------------------------------------------------------
# conventions and kernels
# --------------------------------------------------------------------------
@pytest.mark.parametrize("nu", [0.0, 0.25, 0.3, 0.45])
def test_slopes_and_beta_match_library_constants(nu):
    """dv/dX = N12 q + N11 Hc[p], du/dX = -N12 p + N11 Hc[q]: N11, N12 and the tangential
    compliance equal the library's; the rigid punch's beta = N12/N11 (the library's
    equation: a p + b Hc[p] with a/b = mu_f beta); swapping the bodies flips beta."""
    import contact                      # its constants only: the conventions pinned here
    G = 1.0 / (2 * (1 + nu))
    sc = contact.surface_constants(contact.Isotropic(1.0, nu), 0.0)
    sl = B.single_body_slopes(G, nu)
    assert sl["dv_dHp"] == pytest.approx(sc.N11, rel=1e-14)
    assert sl["dv_dq"] == pytest.approx(sc.N12, rel=1e-14, abs=1e-15)
    assert sl["du_dHq"] == pytest.approx(sc.tangential_compliance, rel=1e-14)
    assert sl["du_dp"] == pytest.approx(-sc.N12, rel=1e-14, abs=1e-15)
    A, beta = B.rigid_punch_dundurs(G, nu)
    assert A == pytest.approx(-4 * sc.N11, rel=1e-14)
    assert beta == pytest.approx(sc.N12 / sc.N11, rel=1e-14, abs=1e-15)
    assert beta == pytest.approx(-(1 - 2 * nu) / (2 * (1 - nu)), abs=1e-15)
    A12, b12 = B.dundurs(G, nu, 3.0, 0.1)
    A21, b21 = B.dundurs(3.0, 0.1, G, nu)
    assert A12 == pytest.approx(A21) and b12 == pytest.approx(-b21)
    assert B.dundurs(G, nu, G, nu)[1] == 0.0                    # one material: decoupled


def test_two_body_beta_matches_library_pair_constants():
    """Body 1 the half-space, body 2 the punch: -A/4 and beta equal the library's two-body
    N11* and N12*/N11* (``contact.elastic_punch.two_body_constants``, N12 -> N12 - N12_p)."""
    import contact
    from contact.elastic_punch import punch_constants, two_body_constants
    for (E1, nu1), (E2, nu2) in (((1.0, 0.3), (3.0, 0.1)), ((2.0, 0.45), (0.5, 0.2))):
        m1, m2 = contact.Isotropic(E1, nu1), contact.Isotropic(E2, nu2)
        pair = two_body_constants(contact.surface_constants(m1, 0.0), punch_constants(m2))
        A, beta = B.dundurs(E1 / (2 * (1 + nu1)), nu1, E2 / (2 * (1 + nu2)), nu2)
        assert -A / 4 == pytest.approx(pair.N11, rel=1e-13)
        assert beta == pytest.approx(pair.N12 / pair.N11, rel=1e-12)


def test_panel_matrices_closed_form():
    m, h = 7, 0.3
    L, S = B.influence_matrices(m, h)
    x = (np.arange(m) + 0.5) * h
    for i in (0, 3, 6):
        for j in (0, 3, 5, 6):
            t0, t1 = j * h, (j + 1) * h
            pts = [x[i]] if t0 < x[i] < t1 else None
            lg = quad(lambda t: math.log(abs(x[i] - t)), t0, t1, points=pts, limit=200)[0]
            assert L[i, j] == pytest.approx(-lg / math.pi, rel=1e-12, abs=1e-14)
            assert S[i, j] == pytest.approx(0.5 * h * np.sign(i - j), abs=1e-15)
    assert np.allclose(L, L.T) and np.allclose(S, -S.T)


def test_goodman_relation_integral():
    """The integral behind goodman_stick_ratio:
    int_0^c artanh(b) / (b sqrt(c^2 - x^2)) dx = (pi/2) K'(c), b = sqrt(1 - x^2)."""
    for c in (0.2, 0.6, 0.9):
        f = lambda th: (math.atanh(math.sqrt(1 - (c * math.sin(th)) ** 2))          # noqa: E731
                        / math.sqrt(1 - (c * math.sin(th)) ** 2))
        assert quad(f, 0, math.pi / 2, limit=200)[0] == pytest.approx(
            0.5 * math.pi * ellipk(1 - c * c), rel=1e-10)
    assert B.goodman_stick_ratio(1.0) == pytest.approx(1 / math.sqrt(2), abs=1e-13)  # K' = K


# --------------------------------------------------------------------------
# beta = 0: Cattaneo
# --------------------------------------------------------------------------
def test_cattaneo_beta_zero():
    """beta = 0, mu = 0.5, Q = 0.6 mu P: c/a = sqrt(1 - Q/(mu P)) and Cattaneo's q.

    m = 100, 200, 400, 800 panels on [-1.25, 1.25] (h = 0.025 .. 0.003125): the contact ends
    within -0.022 h of a = 1 (first order, a clean constant); the stick ends from the slip
    accumulated since Q = 0 within +0.026, -0.017, +0.002, +0.010 h (first order, erratic
    constant; from the stick deficit instead: +0.037, +0.045, +0.023, +0.085 h); the pressure
    at second order (max error 2.3e-5, 7.2e-6, 2.1e-6, 5.7e-7 over |X| < 0.9); the traction
    away from the stick end (|X| < 0.5) 3.6e-4, 1.1e-5, 1.3e-5, 5.2e-6 (relative to mu p0),
    i.e. bounded by ~0.02 h: the discrete q is mu (p(P) - p(P*)) exactly (next test), and its
    error is the O(h), erratic, error of the discrete P* contact's ends.
    """
    mu, Q = 0.5, 0.6 * 0.5 * P_HERTZ
    a, c, qcf = B.cattaneo_closed_form(A4, R, P_HERTZ, Q, mu)
    _, pcf = B.hertz_closed_form(A4, R, P_HERTZ)
    assert a == pytest.approx(1.0) and c == pytest.approx(math.sqrt(0.4))
    perrs = []
    for m in (100, 200, 400):
        sv = B.Solver(B.parabolic(R), WINDOW, m, A4, 0.0, mu)
        states = B.load_path(sv, P_HERTZ, Q, normal_steps=10, tangential_steps=3, keep=True)
        st = states[-1]
        _check_conditions(sv, st, states[-2].s)
        ae = B.contact_edges(st, 0.0, mu)
        ce = B.stick_zone(st, 0.0, mu, slip_since=states[-4].s)
        assert np.allclose(ae, (-a, a), atol=0.03 * st.h, rtol=0)
        assert np.allclose(ce, (-c, c), atol=0.04 * st.h, rtol=0)
        assert np.allclose(B.stick_zone(st, 0.0, mu), (-c, c), atol=0.06 * st.h, rtol=0)
        inner = np.abs(st.x) < 0.5
        assert np.max(np.abs(st.q - qcf(st.x))[inner]) < 0.02 * st.h * mu * (4 * a / (A4 * R))
        perrs.append(np.max(np.abs(st.p - pcf(st.x))[np.abs(st.x) < 0.9]))
        assert np.all(st.q >= 0)                                  # Q > 0: q = +mu p in slip
        assert np.array_equal(st.stick, np.abs(st.x) < c) or m == 100
    orders = np.log2(np.array(perrs[:-1]) / np.array(perrs[1:]))
    assert np.all(orders > 1.6)


def test_cattaneo_discrete_superposition_and_path_independence():
    """beta = 0: the discrete q equals mu (p(P) - p(P*)) of the same grid's frictionless
    solutions (Ciavarella-Jager at the discrete level) to rounding, and 1 or 7 steps of Q give
    the same answer (monotone Q, decoupled: no path dependence)."""
    mu, m = 0.4, 120
    Q = 0.45 * mu * P_HERTZ
    sv = B.Solver(B.parabolic(R), WINDOW, m, A4, 0.0, mu)
    one = B.load_path(sv, P_HERTZ, Q, normal_steps=8, tangential_steps=1)
    seven = B.load_path(sv, P_HERTZ, Q, normal_steps=8, tangential_steps=7)
    assert np.allclose(one.q, seven.q, atol=1e-12) and np.array_equal(one.state, seven.state)
    star = B.load_path(sv, P_HERTZ - Q / mu, 0.0, normal_steps=8)
    assert np.allclose(one.q, mu * (one.p - star.p), atol=1e-11)
    assert np.array_equal(one.stick, star.contact)


# --------------------------------------------------------------------------
# beta != 0, normal load alone (Spence)
# --------------------------------------------------------------------------
@pytest.fixture(scope="module")
def spence_hertz():
    """Rigid cylinder on nu = 0.3 (beta = -0.2857), mu = 0.3, normal load from first touch;
    m = 160, 80 load steps P (k/80)^2 (a grows ~0.8 panel per step)."""
    mu = 0.3
    sv = B.Solver(B.parabolic(R), WINDOW, 160, A4, BETA_RIGID, mu)
    return sv, B.load_path(sv, P_HERTZ, 0.0, normal_steps=80, keep=True)


def test_spence_hertz_slip_at_edges_inward_friction(spence_hertz):
    """Under normal load alone the edges slip and the centre sticks; the friction on the rigid
    punch points inward (q < 0 on the right); p even and q odd; every condition holds."""
    sv, states = spence_hertz
    st = states[-1]
    _check_conditions(sv, st, states[-2].s)
    (i0, i1), = B._runs(st.contact)
    (j0, j1), = B._runs(st.stick)
    assert i0 < j0 and j1 < i1
    assert np.all(st.state[i0:j0] == B.SLIP_POS) and np.all(st.state[j1 + 1:i1 + 1] == B.SLIP_NEG)
    assert np.all(st.q[st.x > 0] <= 0) and np.all(st.q[st.x < 0] >= 0)
    assert np.allclose(st.p, st.p[::-1], atol=1e-12) and np.allclose(st.q, -st.q[::-1], atol=1e-12)
    assert st.Q == 0 and abs(st.h * st.q.sum()) < 1e-13
    # the coupling narrows the contact (beta = 0 would give a = 1): a = 0.9766 (m = 400, 800)
    a = B.contact_edges(st, BETA_RIGID, sv.mu)[1]
    assert 0.970 < a < 0.980


def test_spence_hertz_self_similar_and_equal_to_flat_punch(spence_hertz):
    """c/a does not change with the load (self-similarity), and equals the flat punch's (the
    load increment of the growing contact is a flat-punch problem).

    Grid values of c/a from the stick deficit (Hertz at P/4 and P; flat punch), m = 100:
    0.6913, 0.6890, 0.6909; m = 160: 0.6910, 0.6895, 0.6889; m = 200: 0.6898, 0.6884,
    0.6886; m = 400: 0.6888, 0.6885, 0.6887; m = 800: 0.6888, 0.6891, 0.6889 (the slip of
    the last step gives worse ends for the growing contact: 0.66-0.686 at m = 160-200).  beta = -0.2857, mu = 0.3: c/a = 0.6888 +- 0.0003; the Goodman limit
    (beta -> 0 at this beta/mu = 0.952) would give 0.7438.
    """
    sv, states = spence_hertz
    ratios = []
    for st in (states[39], states[-1]):
        a = B.contact_edges(st, BETA_RIGID, sv.mu)
        c = B.stick_zone(st, BETA_RIGID, sv.mu, growing=True)
        ratios.append(c[1] / a[1])
        assert c[0] / a[0] == pytest.approx(c[1] / a[1], abs=1e-12)
    assert ratios[0] == pytest.approx(ratios[1], abs=2.5e-3)
    assert ratios[1] == pytest.approx(SPENCE_CONVERGED["c_a"], abs=1.5e-3)
    a = B.contact_edges(states[-1], BETA_RIGID, sv.mu)[1]
    qs = [np.interp(xi * a, states[-1].x, states[-1].q) / sv.mu for xi in (0.25, 0.5, 0.75)]
    assert np.allclose(qs, SPENCE_CONVERGED["q"], atol=2e-3, rtol=0)
    fl = B.Solver(B.flat(1.0), (-1.0, 1.0), 200, A4, BETA_RIGID, sv.mu)
    st = B.load_path(fl, 1.0, 0.0, normal_steps=1)
    _check_conditions(fl, st, np.zeros(fl.m))
    cf = B.stick_zone(st, BETA_RIGID, sv.mu)[1]
    assert ratios[1] == pytest.approx(cf, abs=1.5e-3)
    assert cf == pytest.approx(0.6888, abs=1.5e-3)


@pytest.mark.parametrize("beta_over_mu", [0.8, 1.5])
def test_flat_punch_goodman_limit(beta_over_mu):
    """beta -> 0 at fixed beta/mu (beta mu = 1e-4): the flat punch's c/a tends to the root of
    K'(c/a)/K(c/a) = abs(beta)/mu (0.854102 at 0.8, 0.365915 at 1.5).

    Stick end from the slip, m = 200, 400, 800: 0.85178, 0.85308, 0.85366 (0.8) and 0.36506,
    0.36546, 0.36572 (1.5): monotone, first order; Richardson (order 1) from 400 and 800:
    0.85424 and 0.36598.  From the stick deficit (erratic): 0.85571, 0.85380, 0.85389 and
    0.36588, 0.36562, 0.36576.  At beta/mu = 0.8 and larger beta mu the coupling shrinks
    the stick zone: c/a = 0.8531 (beta = 0.04), 0.8485 (0.1), 0.8313 (0.2), 0.8000 (0.3),
    0.7508 (0.4) (m = 1600, deficit).
    """
    mu = math.sqrt(1e-4 / beta_over_mu)
    beta = -beta_over_mu * mu
    exact = B.goodman_stick_ratio(beta_over_mu)
    ends = []
    for m in (200, 400):
        fl = B.Solver(B.flat(1.0), (-1.0, 1.0), m, A4, beta, mu)
        st = B.load_path(fl, 1.0, 0.0, normal_steps=1)
        c = B.stick_zone(st, beta, mu, slip_since=np.zeros(m))
        assert c[0] == pytest.approx(-c[1], abs=1e-12)
        assert c[1] == pytest.approx(exact, abs=2.5e-3)
        assert B.stick_zone(st, beta, mu)[1] == pytest.approx(exact, abs=2e-3)
        ends.append(c[1])
    ext, _ = B.richardson(ends, [2 / 200, 2 / 400], 1)
    assert ext == pytest.approx(exact, abs=5e-4)


def test_flat_punch_stick_deficit_exponent():
    """Near the stick-slip end the stick deficit mu p - |q| vanishes like d^lam with lam of
    stick_deficit_exponent (here 0.4137 for beta = -0.6, mu = 0.5): a free three-parameter
    fit (c, C, lam) to panels 3..14 inside the stick zone, m = 400."""
    beta, mu = -0.6, 0.5
    fl = B.Solver(B.flat(1.0), (-1.0, 1.0), 400, A4, beta, mu)
    st = B.load_path(fl, 1.0, 0.0, normal_steps=1)
    (i0, i1), = B._runs(st.stick)
    lam = B.stick_deficit_exponent(beta, mu, B._eps(st.state, i1 + 1), 1)
    assert lam == pytest.approx(0.5 - math.atan(0.3) / math.pi)
    ii = i1 - np.arange(3, 15)
    d = mu * st.p[ii] - np.abs(st.q[ii])
    from scipy.optimize import curve_fit
    c0 = B.stick_zone(st, beta, mu)[1]
    (c, logC, e), _ = curve_fit(lambda x, c, logC, e: logC + e * np.log(np.maximum(c - x, 1e-300)),
                                st.x[ii], np.log(d), p0=[c0, 0.0, 0.5])
    assert e == pytest.approx(lam, abs=0.03)
    assert e == pytest.approx(lam, abs=abs(e - 0.5) + 0.03)     # not Cattaneo's 1/2 by chance
    assert abs(e - (0.5 + math.atan(0.3) / math.pi)) > 0.1       # nor the other sign's


def test_flat_punch_large_friction_tends_to_full_stick():
    """Rigid flat punch on nu = 0.3 (beta = -0.2857): the slip zones at the edges shrink like
    exp(-arctan(mu)/eps), eps = ln(3 - 4 nu)/(2 pi) = 0.0935 (Abramov's bonded punch:
    q/p = tan(eps ln((1 + x)/(1 - x))) reaches mu at 1 - x ~ 2 exp(-arctan(mu)/eps)); the
    width w = 1 - c/a is ~4 times that: m = 400 gives w = 0.3113, 0.1357, 0.0578, 0.0232 at
    mu = 0.3, 0.4, 0.5, 0.6 (d ln w / d(arctan(mu)/eps) = -0.87, -0.96, ...).  For mu >= 1
    the slip zones are thinner than a panel (m = 200): the grid sees full stick, p > 0."""
    beta = BETA_RIGID
    eps = math.log(3 - 4 * NU) / (2 * math.pi)
    assert eps == pytest.approx(math.log((1 - beta) / (1 + beta)) / (2 * math.pi))
    w = []
    for mu in (0.4, 0.5):
        fl = B.Solver(B.flat(1.0), (-1.0, 1.0), 400, A4, beta, mu)
        st = B.load_path(fl, 1.0, 0.0, normal_steps=1)
        w.append(1 - B.stick_zone(st, beta, mu)[1])
        assert 2.5 < w[-1] / (2 * math.exp(-math.atan(mu) / eps)) < 5.0
    slope = math.log(w[1] / w[0]) / ((math.atan(0.5) - math.atan(0.4)) / eps)
    assert -1.1 < slope < -0.85
    fl = B.Solver(B.flat(1.0), (-1.0, 1.0), 200, A4, beta, 2.0)
    st = B.load_path(fl, 1.0, 0.0, normal_steps=1)
    assert np.all(st.state == B.STICK) and np.all(st.p > 0)
    assert np.all(np.abs(st.q) < 2.0 * st.p)


def test_rounded_flat_normal_load():
    """Flat of half-width 0.5 with corners of radius 1: beta = 0, the contact half-width equals
    Ciavarella, Hills & Monno's (``rounded_flat_reference``, N11 = -A/4) within 0.05 h and q
    stays 0; beta = -0.2857, mu = 0.3, loaded from first touch in 30 steps: edges slip with the
    friction pointing inward, every condition holds, and the contact is narrower (the inward
    shear lifts the pressure near the centre)."""
    import rounded_flat_reference as RF
    b, Rc, P, m = 0.5, 1.0, 0.3, 128
    a_ex = float(RF.half_width_for_load(P, b, Rc, -A4 / 4))
    sv0 = B.Solver(B.rounded_flat(b, Rc), WINDOW, m, A4, 0.0, 0.3)
    st0 = B.load_path(sv0, P, 0.0, normal_steps=30, growing=False)
    assert np.allclose(B.contact_edges(st0, 0.0, 0.3), (-a_ex, a_ex), atol=0.05 * sv0.h, rtol=0)
    assert np.all(st0.q == 0.0)
    sv = B.Solver(B.rounded_flat(b, Rc), WINDOW, m, A4, BETA_RIGID, 0.3)
    states = B.load_path(sv, P, 0.0, normal_steps=30, growing=False, keep=True)
    st = states[-1]
    _check_conditions(sv, st, states[-2].s)
    a = B.contact_edges(st, BETA_RIGID, 0.3)
    assert a_ex - a[1] > 0.008 and a[0] == pytest.approx(-a[1], abs=1e-12)   # 0.0139 at m = 160
    (i0, i1), = B._runs(st.contact)
    assert st.state[i0] == B.SLIP_POS and st.state[i1] == B.SLIP_NEG and st.stick.any()
    assert np.all(st.q[st.x > 0] <= 0)


@pytest.mark.parametrize("eps", [1.0, -1.0])
def test_full_sliding_matches_bem_reference_and_closed_form(eps):
    """q = eps mu p everywhere (Q = eps mu P): the pressure equals ``bem_reference``'s
    (N11 = -A/4, N12 mu_f = -(A/4) beta eps mu: the library's equation) to rounding, and the
    ends equal the closed form of ``PolynomialFaceOneZone`` within 0.05 h (this pins the sign
    of the coupling term beta S q and the slip-zone edge exponents)."""
    import bem_reference as BR
    beta, mu, m = BETA_RIGID, 0.5, 200
    sv = B.Solver(B.parabolic(R), WINDOW, m, A4, beta, mu)
    st = sv.sliding(P_HERTZ, eps)
    ref = BR.solve_bem(B.parabolic(R), WINDOW, -A4 / 4, -A4 / 4 * beta * eps * mu, P_HERTZ, m,
                       refine=None)
    assert np.max(np.abs(st.p - ref.p)) < 1e-12 * np.max(st.p)
    with np.errstate(all="ignore"):
        ends = BR.PolynomialFaceOneZone([0.0, 1.0 / R], -A4 / 4, -A4 / 4 * beta * eps * mu).solve(
            P_HERTZ, (-1.0, 1.0))
    assert np.allclose(B.contact_edges(st, beta, mu), ends, atol=0.05 * sv.h, rtol=0)
    # beta < 0: the contact shifts toward the trailing side (+X for a punch dragged along -X,
    # eps = +1), and mirrors with the direction
    assert (ends[1] + ends[0] > 0) == (eps > 0)


# --------------------------------------------------------------------------
# beta != 0, Q at constant P
# --------------------------------------------------------------------------
def test_coupled_tangential_load_conditions_and_path():
    """After Spence's normal loading, Q = 0.5 mu P in 5 steps: every condition holds at every
    step, the stick zone is shifted (asymmetric), q > 0 near both edges at the end (the
    right-hand slip zone has reversed), and the answer depends on the path: the same (P, Q)
    reached proportionally differs."""
    beta, mu, m = BETA_RIGID, 0.3, 120
    Q = 0.5 * mu * P_HERTZ
    sv = B.Solver(B.parabolic(R), WINDOW, m, A4, beta, mu)
    states = B.load_path(sv, P_HERTZ, Q, normal_steps=50, tangential_steps=5, keep=True)
    for prev, st in zip(states[-6:-1], states[-5:]):
        _check_conditions(sv, st, prev.s)
    st = states[-1]
    (i0, i1), = B._runs(st.contact)
    assert st.q[i0] > 0 and st.q[i1] > 0
    c = B.stick_zone(st, beta, mu, slip_since=states[49].s)
    a = B.contact_edges(st, beta, mu)
    assert c[0] - a[0] > 0.05 and abs((c[0] - a[0]) - (a[1] - c[1])) > 2 * st.h
    # m = 120 against the converged numbers (m = 120: [-0.0315, 0.8106]; q/mu 0.82205,
    # 0.67801, -0.27211)
    assert np.allclose(np.array(c) / a[1], TANGENTIAL_CONVERGED["c"], atol=8e-3, rtol=0)
    qs = [np.interp(xi * a[1], st.x, st.q) / mu for xi in (-0.5, 0.0, 0.5)]
    assert np.allclose(qs, TANGENTIAL_CONVERGED["q"], atol=5e-3, rtol=0)
    # the right-hand end of Spence's stick zone (0.689 a) moved outward: the slip zone there
    # had q = -mu p and had to reverse, sticking on the way
    assert c[1] / a[1] > SPENCE_CONVERGED["c_a"] + 0.05
    # proportional path: P and Q together from the first touch
    prop = sv.initial()
    for t in np.arange(1, 51) / 50:
        prop = sv.step(prop, P_HERTZ * t * t, Q * t * t)
    assert np.max(np.abs(prop.q - st.q)) > 0.05 * mu * np.max(st.p)


def test_coupled_partial_slip_tends_to_sliding():
    """Q raised to 0.99 mu P: the stick zone shrinks at every step (to 6 panels of 120) and the
    pressure tends to the full-sliding one (1.1 % of its peak away at 0.99 mu P, 7.7 % at
    0.89, 17 % at 0.69), q to mu p outside the last stick panels."""
    beta, mu, m = BETA_RIGID, 0.3, 120
    sv = B.Solver(B.parabolic(R), WINDOW, m, A4, beta, mu)
    states = B.load_path(sv, P_HERTZ, 0.99 * mu * P_HERTZ, normal_steps=50,
                         tangential_steps=6, keep=True)
    sizes = [int(st.stick.sum()) for st in states[-7:]]
    assert all(a > b for a, b in zip(sizes, sizes[1:])) and 0 < sizes[-1] <= 8
    sl = sv.sliding(P_HERTZ, 1.0)
    st = states[-1]
    assert np.max(np.abs(st.p - sl.p)) < 0.02 * np.max(sl.p)
    assert np.all(st.state[~st.stick & st.contact] == B.SLIP_POS)


def test_beta_sign_flips_the_shear_only():
    """beta -> -beta with q -> -q (and s -> -s) maps the model onto itself: the same pressure
    and zones, the opposite shear (a soft punch on a stiff half-space, beta > 0, drags the
    surface outward: q > 0 on the right)."""
    for H, window, steps in ((B.flat(1.0), (-1.0, 1.0), 1), (B.parabolic(R), WINDOW, 20)):
        out = []
        for beta in (BETA_RIGID, -BETA_RIGID):
            sv = B.Solver(H, window, 80, A4, beta, 0.3)
            out.append(B.load_path(sv, 1.0, 0.0, normal_steps=steps))
        neg, pos = out
        assert np.allclose(neg.p, pos.p, atol=1e-12) and np.allclose(neg.q, -pos.q, atol=1e-12)
        assert np.array_equal(neg.stick, pos.stick) and np.all(pos.q[pos.x > 0] >= 0)
