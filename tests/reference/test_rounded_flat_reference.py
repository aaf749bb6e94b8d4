"""Independent checks of the rounded-flat-punch closed form in ``rounded_flat_reference``.

Ciavarella, Hills & Monno, "The influence of rounded edges on indentation by a flat punch",
Proc. IMechE Part C 212(4) (1998) 319-328, re-derived in the library's convention

    (N11/pi) PV int_{-a}^{a} p(t)/(t - X) dt = H'(X),  int p = P,  p(+-a) = 0,

with H = 0 on |X| <= b and (|X| - b)^2/(2R) beyond.  Every check below computes its
reference by quadrature of the defining equations (mpmath, or scipy's QAWC Cauchy rule),
not from the closed form.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from mpmath import mp, mpf
from scipy import integrate

import rounded_flat_reference as rf

# (a, b, R, N11): N11 < 0 as the library gives it (-2/E*); a mix of shapes: nearly flat
# (a close to b), moderate, nearly Hertzian (b << a); one case with N11 > 0 (negative load)
CASES = [
    (1.0, 0.6, 3.0, -0.4),
    (0.61, 0.6, 0.5, -0.0091),
    (2.5, 0.1, 40.0, -1.7),
    (0.6000001, 0.6, 1e-4, -2.0),
    (1.3, 0.9, 2.0, 0.25),
]
IDS = ["moderate", "near-flat", "near-Hertz", "very-flat", "N11>0"]


def _mp_case(case):
    return tuple(mpf(v) for v in case)


def _slope_mp(t, b, R):
    return (t - b) / R if t > b else ((t + b) / R if t < -b else mpf(0))


# --------------------------------------------------------------------------
# load relation
# --------------------------------------------------------------------------
@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_load_equals_quadrature_of_integral_formula(case):
    """P = -(1/N11) int t H'(t)/sqrt(a^2 - t^2) dt, by mpmath quadrature (t = a sin theta)."""
    mp.dps = 30
    a, b, R, N11 = _mp_case(case)
    phi0 = mp.asin(b / a)
    integral = mp.quad(lambda th: a * mp.sin(th) * _slope_mp(a * mp.sin(th), b, R),
                       [-mp.pi / 2, -phi0, phi0, mp.pi / 2])
    P_ref = -integral / N11
    assert abs(rf.load_for_half_width(*case) / float(P_ref) - 1) < 1e-14
    assert abs(rf.load_for_half_width(a, b, R, N11) / P_ref - 1) < mpf(10) ** -25


def test_load_cylinder_limit_is_hertz():
    """b = 0: P = pi a^2 / (2 |N11| R), i.e. a^2 = 4 P R / (pi E*) with N11 = -2/E*."""
    a, R, N11 = 0.37, 12.0, -0.0091
    assert rf.load_for_half_width(a, 0.0, R, N11) == pytest.approx(
        math.pi * a * a / (2 * -N11 * R), rel=1e-15)
    # and continuously so
    assert rf.load_for_half_width(a, 1e-9 * a, R, N11) == pytest.approx(
        math.pi * a * a / (2 * -N11 * R), rel=1e-8)


def test_load_flat_limit_asymptotics():
    """a -> b: P ~ (2/3) a^2 eps^3 / (-N11 R), eps = arccos(b/a) (no cancellation loss)."""
    b, R, N11 = 0.6, 1e-3, -0.0091
    for d in (1e-4, 1e-8, 1e-12):
        a = b * (1 + d)
        eps = math.acos(b / a) if d > 1e-8 else math.sqrt(2 * d)   # acos(1 - d) ~ sqrt(2d)
        P = rf.load_for_half_width(a, b, R, N11)
        assert P == pytest.approx(2 * a * a * eps ** 3 / (3 * -N11 * R), rel=2 * eps ** 2 + 1e-7)
        mp.dps = 40
        P_mp = rf.load_for_half_width(mpf(a), mpf(b), mpf(R), mpf(N11))
        assert abs(P / float(P_mp) - 1) < 1e-14


def test_load_monotone_and_inputs():
    b, R, N11 = 0.6, 3.0, -0.4
    a = b + np.geomspace(1e-12, 1e3, 200)
    P = np.array([rf.load_for_half_width(x, b, R, N11) for x in a])
    assert np.all(np.diff(P) > 0)
    with pytest.raises(ValueError):
        rf.load_for_half_width(0.6, 0.6, R, N11)
    with pytest.raises(ValueError):
        rf.load_for_half_width(1.0, 0.6, -1.0, N11)
    with pytest.raises(ValueError):
        rf.half_width_for_load(1.0, 0.6, R, +0.4)     # P N11 > 0: no compressive contact


# --------------------------------------------------------------------------
# inverse relation
# --------------------------------------------------------------------------
@pytest.mark.parametrize("Q_over_b2", [1e-15, 1e-9, 1e-4, 0.3, 1.0, 1e3, 1e9])
def test_half_width_for_load_against_mpmath_root(Q_over_b2):
    """a(P) against mpmath's root of a^2 (pi/2 - phi0) - b sqrt(a^2-b^2) = -P N11 R."""
    b, R, N11 = 0.6, 2.0, -0.0091
    P = -Q_over_b2 * b * b / (N11 * R)
    a = rf.half_width_for_load(P, b, R, N11)
    mp.dps = 50
    bm, Q = mpf(b), -mpf(P) * mpf(N11) * mpf(R)

    def F(x):
        return x * x * (mp.pi / 2 - mp.asin(bm / x)) - bm * mp.sqrt(x * x - bm * bm) - Q

    lo, hi = mpf(a) * (1 - mpf(10) ** -6), mpf(a) * (1 + mpf(10) ** -6)
    lo = max(lo, bm * (1 + mpf(10) ** -40))
    a_ref = mp.findroot(F, (lo, hi), solver="anderson")
    assert abs(a / float(a_ref) - 1) < 1e-14
    # round trip
    assert rf.load_for_half_width(a, b, R, N11) == pytest.approx(P, rel=1e-13)


def test_half_width_cylinder_and_mpmath_input():
    P, R, N11 = 0.7, 50.0, -0.0091
    assert rf.half_width_for_load(P, 0.0, R, N11) == pytest.approx(
        math.sqrt(-2 * P * R * N11 / math.pi), rel=1e-15)
    mp.dps = 40
    a = rf.half_width_for_load(mpf(P), mpf("0.3"), mpf(R), mpf(N11))
    assert abs(rf.load_for_half_width(a, mpf("0.3"), mpf(R), mpf(N11)) / mpf(P) - 1) < mpf(10) ** -35


# --------------------------------------------------------------------------
# pressure
# --------------------------------------------------------------------------
def _pv_mp(a, b, R, N11, X):
    """PV int_{-a}^{a} p(t)/(t - X) dt by subtraction of the singularity (mpmath).

    Extra breakpoints at distances 10^k (a - b) inside +-b resolve the near-flat cases, where
    p rises steeply over a length ~ a - b next to +-b."""
    pX = rf.pressure(X, a, b, R, N11)
    d = a - b
    extra = {s * (b - k * d) for k in (10, 100, 1000, 10000) for s in (1, -1) if k * d < b}
    pts = sorted({-a, -b, X, b, a} | extra)

    def f(t):
        if t == X:                           # a tanh-sinh node rounded onto the breakpoint
            return mpf(0)
        return (rf.pressure(t, a, b, R, N11) - pX) / (t - X)

    return mp.quad(f, pts) + pX * mp.log((a - X) / (a + X))


@pytest.mark.parametrize("case", CASES, ids=IDS)
@pytest.mark.slow
def test_pressure_satisfies_integral_equation_mpmath(case):
    """(N11/pi) PV int p/(t - X) = H'(X) at points inside the flat and on the rounds."""
    mp.dps = 18
    a, b, R, N11 = _mp_case(case)
    scale = (a - b) / R                      # max |H'| on the contact
    points = [mpf("0.37") * b, mpf("-0.8") * b,                  # inside the flat
              b + mpf("0.3") * (a - b), -(b + mpf("0.97") * (a - b))]   # on the rounds
    for X in points:
        lhs = N11 / mp.pi * _pv_mp(a, b, R, N11, X)
        assert abs(lhs - _slope_mp(X, b, R)) < mpf(10) ** -15 * scale


@pytest.mark.parametrize("case", CASES[:3] + CASES[4:], ids=IDS[:3] + IDS[4:])
def test_pressure_float_satisfies_equation_qawc(case):
    """The float pressure through scipy's Cauchy-weight quadrature (QAWC), split at +-b.

    (The very-flat case, a - b = 1e-7, is beyond QUADPACK in double precision; the mpmath
    check above covers it.)"""
    a, b, R, N11 = case
    p = lambda t: rf.pressure(t, a, b, R, N11)
    scale = (a - b) / R
    edges = [-a, -b, b, a]
    for X in (0.2 * b, -0.9 * b, b + 0.5 * (a - b), -(b + 0.9 * (a - b))):
        pv = 0.0
        for lo, hi in zip(edges[:-1], edges[1:]):
            if lo < X < hi:
                val, _ = integrate.quad(p, lo, hi, weight="cauchy", wvar=X,
                                        epsabs=0, epsrel=1e-11, limit=200)
            else:
                val, _ = integrate.quad(lambda t: p(t) / (t - X), lo, hi,
                                        epsabs=0, epsrel=1e-11, limit=200)
            pv += val
        lhs = N11 / math.pi * pv
        assert abs(lhs - float(rf.profile_slope(X, b, R))) < 1e-9 * scale


@pytest.mark.parametrize("case", CASES, ids=IDS)
@pytest.mark.slow
def test_pressure_integrates_to_load(case):
    mp.dps = 25
    a, b, R, N11 = _mp_case(case)
    total = mp.quad(lambda t: rf.pressure(t, a, b, R, N11), [-a, -b, b, a])
    assert abs(total / rf.load_for_half_width(a, b, R, N11) - 1) < mpf(10) ** -20
    af, bf, Rf, Nf = case
    tot_f, _ = integrate.quad(lambda t: rf.pressure(t, af, bf, Rf, Nf), -af, af,
                              points=[-bf, bf], epsabs=0, epsrel=1e-13, limit=200)
    assert tot_f == pytest.approx(rf.load_for_half_width(*case), rel=1e-11)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_pressure_bounded_ends_sign_and_symmetry(case):
    a, b, R, N11 = case
    pmax = abs(rf.pressure(np.linspace(-a, a, 401), a, b, R, N11)).max()
    # vanishes at the ends (and outside the contact)
    assert abs(rf.pressure(a, a, b, R, N11)) <= 1e-15 * pmax
    assert abs(rf.pressure(-a, a, b, R, N11)) <= 1e-15 * pmax
    assert np.all(rf.pressure(np.array([-2 * a, -1.0001 * a, 1.0001 * a, 3 * a]), a, b, R, N11) == 0)
    # like sqrt(a - X): p(a - h)/sqrt(h) has a finite limit
    x = a - (a - b) * np.array([1e-4, 1e-6])
    ratio = rf.pressure(x, a, b, R, N11) / np.sqrt(a - x)     # a - x exact in floating point
    assert ratio[0] == pytest.approx(ratio[1], rel=1e-3)
    # sign of -N11 (compressive for N11 < 0), even, continuous at +-b
    X = np.linspace(-a, a, 801)[1:-1]
    p = rf.pressure(X, a, b, R, N11)
    assert np.all(np.sign(p) == np.sign(-N11))
    np.testing.assert_allclose(p, p[::-1], rtol=1e-13)
    d = 1e-12 * (a - b)
    pb = rf.pressure(np.array([b - d, b, b + d]), a, b, R, N11)
    np.testing.assert_allclose(pb, pb[1], rtol=1e-8)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_pressure_float_matches_mpmath_evaluation(case):
    """Cancellation-free float evaluation: pointwise relative error ~1e-15, also near-flat."""
    mp.dps = 40
    a, b, R, N11 = case
    X = np.concatenate([np.linspace(-a, a, 61)[1:-1],
                        [b, -b, b * (1 - 1e-9), b + 1e-9 * (a - b), a * (1 - 1e-12)]])
    pf = rf.pressure(X, a, b, R, N11)
    pm = np.array([float(rf.pressure(mpf(x), mpf(a), mpf(b), mpf(R), mpf(N11))) for x in X])
    np.testing.assert_allclose(pf, pm, rtol=2e-14, atol=0)


def test_pressure_cylinder_limit_is_hertz():
    a, R, N11 = 0.45, 50.0, -0.0091
    X = np.linspace(-a, a, 21)
    hertz = np.sqrt(np.maximum(a * a - X * X, 0.0)) / (-N11 * R)
    np.testing.assert_allclose(rf.pressure(X, a, 0.0, R, N11), hertz, rtol=1e-14, atol=1e-16 * hertz.max())
    np.testing.assert_allclose(rf.pressure(X, a, 1e-10 * a, R, N11), hertz, rtol=0, atol=1e-8 * hertz.max())


def test_flat_punch_limit():
    """R -> 0 at fixed P: a -> b and p -> P/(pi sqrt(a^2 - X^2)) inside the flat.

    The relative deviation at |X| < b is observed to be below (a - b)/(b - |X|)."""
    b, N11, P = 0.6, -0.0091, 0.05
    X = np.array([0.0, 0.3, -0.5, 0.59])
    prev = None
    for R in (1e-3, 1e-5, 1e-7):
        a = rf.half_width_for_load(P, b, R, N11)
        flat = P / (np.pi * np.sqrt(a * a - X * X))
        dev = np.abs(rf.pressure(X, a, b, R, N11) / flat - 1)
        assert np.all(dev < (a - b) / (b - np.abs(X)))
        if prev is not None:
            assert np.all(dev < prev / 20)
        prev = dev


# --------------------------------------------------------------------------
# conventions against the library
# --------------------------------------------------------------------------
contact = pytest.importorskip("contact")


def _iso_N11(E, nu):
    if not hasattr(contact, "Isotropic"):           # pragma: no cover
        pytest.skip("contact.Isotropic not available")
    k = contact.surface_constants(contact.Isotropic(E, nu), 0.0)
    return k.N11


def test_library_N11_is_minus_two_over_Estar():
    E, nu = 200.0, 0.3
    assert _iso_N11(E, nu) == pytest.approx(-2 * (1 - nu * nu) / E, rel=1e-13)


@pytest.mark.parametrize("R", [50.0, 1.0])
def test_library_cylinder_matches_reference(R):
    E, nu, P = 200.0, 0.3, 0.7
    N11 = _iso_N11(E, nu)
    r = contact.solve(contact.Isotropic(E, nu), contact.CylindricalPunch(radius=R), load=P, speed=0.0)
    a = rf.half_width_for_load(P, 0.0, R, N11)
    assert a == pytest.approx(math.sqrt(4 * P * R * (1 - nu * nu) / (math.pi * E)), rel=1e-14)
    assert r.ends[0] == pytest.approx(-a, rel=1e-12) and r.ends[1] == pytest.approx(a, rel=1e-12)
    X = np.linspace(-a, a, 13)[1:-1]
    np.testing.assert_allclose(r.pressure(X), rf.pressure(X, a, 0.0, R, N11), rtol=1e-11)


@pytest.mark.parametrize("R", [3.0, 0.05])
def test_library_rounded_flat_profile_matches_reference(R):
    """The library's numerical ProfilePunch solve of the same rounded flat punch."""
    E, nu, P, b = 200.0, 0.3, 0.05, 0.6
    N11 = _iso_N11(E, nu)
    punch = contact.ProfilePunch(lambda X: rf.profile_slope(X, b, R), breaks=(-b, b))
    r = contact.solve(contact.Isotropic(E, nu), punch, load=P, speed=0.0)
    a = rf.half_width_for_load(P, b, R, N11)
    assert r.ends[0] == pytest.approx(-a, rel=1e-12) and r.ends[1] == pytest.approx(a, rel=1e-12)
    X = np.linspace(-a, a, 41)[1:-1]
    p_ref = rf.pressure(X, a, b, R, N11)
    np.testing.assert_allclose(r.pressure(X), p_ref, rtol=0, atol=1e-11 * p_ref.max())
