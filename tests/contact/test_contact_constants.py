"""Tests for ``contact.constants``: N11, N12, N21, N22 and the Rayleigh speed.

Conventions (the documentation, Theory: the contact model and its conventions): half-space
Y < 0, sigma_YY(X,0) = -p, tau_XY(X,0) = -q, Hc[f](X) = (1/pi) PV int f(t)/(t - X) dt,
dv/dX = N12 q + N11 Hc[p],  sigma_XX(X,0) = N21 p + N22 Hc[q].

Independent references (the computations live in ``validation/reference_constants.py``,
shared with the report; none of them calls contact.constants):
  * classical static isotropic limits (plane strain: N11 = -(1 - nu)/G, N12 = (1 - 2 nu)/(2G),
    N21 = -1, N22 = -2) and moving-isotropic closed forms written
    with the Rayleigh function R(c) = 4 a_d a_s - (2 - c^2)^2 (derived by hand, see
    ``isotropic_moving``); the isotropic nu = 1/4 Rayleigh speed sqrt(2 - 2/sqrt(3));
  * the characteristic roots of the paper's material as printed in its Table 1, and the
    equations of motion (the 2x2 modal determinant) at every root;
  * a state-space solve at one wavenumber: the 4x4 first-order system for the Fourier
    amplitudes (U, V, tau, sigma) in Y, eigen-decomposed with numpy.linalg.eig (or mpmath.eig
    at 40 digits near a double root), decaying modes kept, unit tractions applied;
  * numerical Fourier inversion of the wavenumber response to a Gaussian load, compared with
    the Dawson-function Hilbert transform of the Gaussian (itself checked by a PV quadrature);
  * the paper's eq. (4.4) with the Appendix (Case B) evaluated as printed.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
import mpmath
from mpmath import mpf
from scipy.integrate import quad
from scipy.optimize import brentq

from contact.constants import (
    SurfaceConstants,
    limiting_speed,
    rayleigh_function,
    rayleigh_speed,
    root_symmetric_functions,
    surface_constants,
)
from contact.errors import NearRayleighWarning, SpeedError
from contact.material import Isotropic, Orthotropic, zhou2014
from validation.reference_constants import (eig_N, eig_transfer, hc_gaussian,
                                            invert_gaussian, isotropic_moving, mp_eig_N,
                                            rayleigh_eig, rayleigh_mp)

PAPER = zhou2014()
ISO = Isotropic(2.5, 0.25)                     # G = 1, lambda = 1, nu = 1/4
COMPLEX = Orthotropic(1.0, 0.5, 1.0, 0.5)      # complex-conjugate roots at c = 0
SHEAR_STIFF = Orthotropic(1.0, 0.9, 1.0, 1.0)  # limiting speed set by eta1 + eta2 -> 0
SOFT_C11 = Orthotropic(0.5, -0.4, 1.0, 1.0)    # C11 < C33: limiting speed sqrt(C11/C33)
C12_MINUS_C33 = Orthotropic(2.0, -0.7, 1.3, 0.7)  # the paper's h(eta) divides by C12 + C33 = 0


def _N(sc: SurfaceConstants) -> np.ndarray:
    return np.array([sc.N11, sc.N12, sc.N21, sc.N22])


def assert_rel(got, want, rtol):
    got, want = np.asarray(got), np.asarray(want)
    err = np.abs(got - want) / np.abs(want)
    assert np.all(err <= rtol), (err, got, want)


# ----------------------------------------------------------------------------------------
# Classical isotropic limits
# ----------------------------------------------------------------------------------------
@pytest.mark.parametrize("E,nu", [(2.5, 0.25), (1.0, 0.3), (7.0, 0.0), (2.0, -0.6), (1.0, 0.499)])
def test_static_isotropic_limits(E, nu):
    G = E / (2 * (1 + nu))
    N = _N(surface_constants(Isotropic(E, nu), 0.0))
    want = [-(1 - nu) / G, (1 - 2 * nu) / (2 * G), -1.0, -2.0]
    np.testing.assert_allclose(N, want, rtol=1e-13, atol=1e-15)


@pytest.mark.parametrize("nu", [0.25, 0.3, -0.2, 0.45])
@pytest.mark.parametrize("frac", [1e-3, 0.2, 0.5, 0.8, 0.95, 0.999])
def test_moving_isotropic_closed_forms(nu, frac):
    E = 3.0
    m = Isotropic(E, nu)
    c = frac * rayleigh_speed(m)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", NearRayleighWarning)
        N = _N(surface_constants(m, c))
    # relative rounding of the reference near c_R grows like eps / (1 - c/c_R)
    assert_rel(N, isotropic_moving(E / (2 * (1 + nu)), nu, c), 2e-13 / (1 - frac) + 3e-14)


def test_moving_isotropic_closed_forms_tend_to_static():
    G, nu = 1.0, 0.25
    np.testing.assert_allclose(isotropic_moving(G, nu, 1e-5), [-0.75, 0.25, -1.0, -2.0],
                               rtol=1e-9)


def test_isotropic_rayleigh_speed_exact():
    """nu = 1/4: c_R^2 = 2 - 2/sqrt(3) (Rayleigh 1885), also at 30 digits (within one ulp)."""
    assert rayleigh_speed(ISO) == pytest.approx(math.sqrt(2 - 2 / math.sqrt(3)), rel=3e-16)
    with mpmath.workdps(30):
        exact = mpmath.sqrt(2 - 2 / mpmath.sqrt(3))
        assert abs(mpf(rayleigh_speed(ISO)) - exact) <= np.spacing(rayleigh_speed(ISO))


@pytest.mark.parametrize("nu", [-0.9, -0.3, 0.0, 0.1, 0.3, 0.45, 0.499])
def test_isotropic_rayleigh_speed_is_root_of_R(nu):
    k2 = (1 - 2 * nu) / (2 * (1 - nu))

    def R(c):  # R / c^2 has no trivial root at c = 0
        return (4 * math.sqrt(1 - k2 * c * c) * math.sqrt(1 - c * c) - (2 - c * c) ** 2) / c ** 2

    ref = brentq(R, 1e-3, 1 - 1e-15, xtol=1e-300, rtol=4 * np.finfo(float).eps)
    assert rayleigh_speed(Isotropic(1.0, nu)) == pytest.approx(ref, rel=2e-15)


# ----------------------------------------------------------------------------------------
# Independent reference 1: state-space eigen-decomposition
# ----------------------------------------------------------------------------------------
EIG_CASES = {
    "paper": (PAPER, [0.0, 0.1, 0.3, 0.6, 0.9, 0.98]),
    "isotropic": (ISO, [0.3, 0.6, 0.9]),     # c -> 0: (nearly) double root, see mp test
    "complex": (COMPLEX, [0.0, 0.2, 0.4, 0.6]),
    "shear-stiff": (SHEAR_STIFF, [0.0, 0.1, 0.2, 0.3]),
    "soft-C11": (SOFT_C11, [0.0, 0.2, 0.4]),
    "C12=-C33": (C12_MINUS_C33, [0.0, 0.3, 0.6]),
}


@pytest.mark.parametrize("name,c", [(n, c) for n, (_, cs) in EIG_CASES.items() for c in cs])
def test_formula_matches_numpy_eig(name, c):
    m = EIG_CASES[name][0]
    assert c < rayleigh_speed(m)
    N = _N(surface_constants(m, c))
    for k in (1.0, -1.0, 2.5):                  # the response is degree 0 in k, real, odd/even
        assert_rel(N, eig_N(m, c, k).real, 1e-12)
        assert np.all(np.abs(eig_N(m, c, k).imag) <= 1e-12 * np.abs(N))


def test_complex_material_really_has_complex_roots():
    e = COMPLEX.characteristic_roots(0.0)
    assert e[0].imag > 0.1 and e[0].real > 0.1


@pytest.mark.parametrize("name,c", [("isotropic", 0.0), ("isotropic", 0.05), ("isotropic", 1e-5),
                                    ("complex", 0.3), ("paper", 0.6)])
def test_formula_matches_mpmath_eig(name, c):
    m = EIG_CASES[name][0]
    assert_rel(_N(surface_constants(m, c)), mp_eig_N(m, c), 4e-15)


NEAR_ISO = {  # isotropic G=1, lambda=1 with one stiffness perturbed by 1e-8 (relative)
    "C11": Orthotropic(3.0 * (1 + 1e-8), 1.0, 3.0, 1.0),
    "C22": Orthotropic(3.0, 1.0, 3.0 * (1 - 1e-8), 1.0),
    "C12": Orthotropic(3.0, 1.0 * (1 + 1e-8), 3.0, 1.0),     # complex pair at c = 0
    "C33": Orthotropic(3.0, 1.0, 3.0, 1.0 * (1 - 1e-8)),
}


@pytest.mark.parametrize("which", list(NEAR_ISO))
@pytest.mark.parametrize("c", [0.0, 1e-4, 0.5])
def test_nearly_isotropic_matches_mpmath_eig(which, c):
    """Roots nearly repeated: the formula keeps full accuracy (reference: 40-digit eig)."""
    m = NEAR_ISO[which]
    N = _N(surface_constants(m, c))
    assert_rel(N, mp_eig_N(m, c), 4e-15)
    if c == 0.0:   # and it is continuous with the isotropic values
        np.testing.assert_allclose(N, [-0.75, 0.25, -1.0, -2.0], rtol=3e-8)


def test_nearly_isotropic_roots_straddle_the_double_root():
    e = NEAR_ISO["C12"].characteristic_roots(0.0)
    assert e[0].imag > 0 and e[2] == np.conj(e[0])      # really the complex branch
    e = NEAR_ISO["C11"].characteristic_roots(0.0)
    assert e[0].imag == 0 and e[0] != e[2]                # really the real branch


@pytest.mark.parametrize("seed", range(12))
def test_random_materials_match_numpy_eig(seed):
    rng = np.random.default_rng(seed)
    C11, C22, C33 = np.exp(rng.uniform(-2, 2, 3))
    C12 = rng.uniform(-0.95, 0.95) * math.sqrt(C11 * C22)
    m = Orthotropic(C11, C12, C22, C33)
    for frac in (0.0, 0.5, 0.9):
        c = frac * rayleigh_speed(m)
        assert_rel(_N(surface_constants(m, c)), eig_N(m, c).real, 1e-10)


def test_symmetric_functions_match_roots():
    for m, c in ((PAPER, 0.0), (PAPER, 0.7), (COMPLEX, 0.0), (COMPLEX, 0.5), (ISO, 0.4)):
        e = m.characteristic_roots(c)
        P, S = root_symmetric_functions(m, c)
        assert P == pytest.approx((e[0] * e[2]).real, rel=1e-14)
        assert S == pytest.approx((e[0] + e[2]).real, rel=1e-14)
        assert abs((e[0] * e[2]).imag) < 1e-14 * P and abs((e[0] + e[2]).imag) < 1e-14 * S


def _paper_appendix_case_B(m, c, zeta):
    """Eq. (4.4) with the Appendix, Case B (two real pairs), evaluated as printed."""
    s = np.sign(zeta)
    e = m.characteristic_roots(c)
    delta = [e[0].real, e[2].real]

    def h(x):  # eq. (3.4)
        return (m.C33 * x * x - m.C11 + m.C33 * c * c) / ((m.C12 + m.C33) * x)

    Th2 = [-1j * s * h(x) for x in delta]                          # eq. (3.6)
    O1 = [-1j * s * (m.C11 + m.C12 * x * h(x)) for x in delta]     # eq. (A.6)
    O2 = [-1j * s * (m.C12 + m.C22 * x * h(x)) for x in delta]     # eq. (A.7)
    O3 = [m.C33 * (x - h(x)) for x in delta]                       # eq. (A.8)
    den = O2[0] * O3[1] - O3[0] * O2[1]                            # eq. (A.9)
    M = [[O3[1] / den, O2[1] / den], [O3[0] / den, O2[0] / den]]   # (A.9)-(A.10)
    sgn = (-1, 1)                                                   # (-1)^n, n = 1, 2
    return np.array([
        sum(sgn[n] * M[n][0] * Th2[n] for n in range(2)),
        1j * sum(sgn[n] * M[n][1] * Th2[n] for n in range(2)),
        sum(sgn[n] * M[n][0] * O1[n] for n in range(2)),
        1j * sum(-sgn[n] * M[n][1] * O1[n] for n in range(2)),
    ])


@pytest.mark.parametrize("c", [0.0, 0.3, 0.6, 0.9])
def test_paper_appendix_agrees_for_positive_zeta(c):
    """The printed (4.4)/Appendix give our constants for zeta > 0 (the only zeta used in (4.3));
    N12 and N22 change sign with sgn(zeta), so they are not 'independent of zeta'."""
    N = _N(surface_constants(PAPER, c))
    plus = _paper_appendix_case_B(PAPER, c, 1.0)
    assert_rel(plus.real, N, 1e-12)
    assert np.all(np.abs(plus.imag) <= 1e-14 * np.abs(N))
    minus = _paper_appendix_case_B(PAPER, c, -1.0)
    assert_rel(minus.real, N * np.array([1, -1, 1, -1]), 1e-12)


def test_paper_appendix_loses_digits_near_isotropy():
    """It divides by (delta1 - delta2); ours does not."""
    m = NEAR_ISO["C11"]
    ref = mp_eig_N(m, 0.0)
    ours = np.max(np.abs(_N(surface_constants(m, 0.0)) - ref) / np.abs(ref))
    paper = np.max(np.abs(_paper_appendix_case_B(m, 0.0, 1.0).real - ref) / np.abs(ref))
    assert ours < 4e-15 and paper > 1e3 * ours


# ----------------------------------------------------------------------------------------
# Independent reference 2: Fourier inversion of a Gaussian surface load
# ----------------------------------------------------------------------------------------
@pytest.mark.parametrize("x", [0.0, 0.4, 1.3, 3.0])
def test_hc_gaussian_closed_form_by_pv_quadrature(x):
    pv, _ = quad(lambda t: math.exp(-t * t), -12.0, 12.0, weight="cauchy", wvar=x,
                 epsabs=1e-14, epsrel=1e-13, limit=200)
    assert pv / math.pi == pytest.approx(hc_gaussian(x), rel=1e-11, abs=1e-14)


@pytest.mark.parametrize("c", [0.0, 0.5, 0.9])
def test_gaussian_load_fourier_inversion(c):
    sc = surface_constants(PAPER, c)
    Tp, Tm = eig_transfer(PAPER, c, 1.0), eig_transfer(PAPER, c, -1.0)
    for x in (0.0, 0.35, 1.0, 2.2, -1.7):
        g, hg = math.exp(-x * x), hc_gaussian(x)
        vx_p, sxx_p, vx_q, sxx_q = (invert_gaussian(Tp[j], Tm[j], x) for j in range(4))
        for got in (vx_p, sxx_p, vx_q, sxx_q):
            assert abs(got.imag) < 1e-12
        # p = exp(-X^2), q = 0
        assert vx_p.real == pytest.approx(sc.N11 * hg, rel=1e-10, abs=1e-12 * abs(sc.N11))
        assert sxx_p.real == pytest.approx(sc.N21 * g, rel=1e-10, abs=1e-12 * abs(sc.N21))
        # q = exp(-X^2), p = 0
        assert vx_q.real == pytest.approx(sc.N12 * g, rel=1e-10, abs=1e-12 * abs(sc.N12))
        assert sxx_q.real == pytest.approx(sc.N22 * hg, rel=1e-10, abs=1e-12 * abs(sc.N22))


# ----------------------------------------------------------------------------------------
# Rayleigh speed and the speed range
# ----------------------------------------------------------------------------------------
def test_paper_rayleigh_speed():
    c_R = rayleigh_speed(PAPER)
    assert c_R == pytest.approx(0.9936, abs=5e-5)           # errata item 5
    assert limiting_speed(PAPER) == 1.0
    assert c_R == pytest.approx(rayleigh_eig(PAPER, 0.9, 0.99999), rel=1e-13)
    ref = rayleigh_mp(PAPER, "0.9936")                     # Delta's root at 40 digits
    assert abs(mpf(c_R) - ref) <= np.spacing(c_R)               # within one ulp


@pytest.mark.parametrize("m", [ISO, COMPLEX, SOFT_C11, C12_MINUS_C33],
                         ids=["iso", "complex", "soft-C11", "C12=-C33"])
def test_rayleigh_speed_matches_eig_route(m):
    c_R, c_L = rayleigh_speed(m), limiting_speed(m)
    ref = rayleigh_eig(m, 0.95 * c_R, min(1.02 * c_R, 0.5 * (c_R + c_L)))
    assert c_R == pytest.approx(ref, rel=1e-13)


def test_shear_stiff_material_exact_speeds():
    """C11 = C22 = C33 = 1, C12 = 0.9: Delta = (1 - c^2)(0.19 - 2c^2), S^2 = 0.39 - 4c^2."""
    assert limiting_speed(SHEAR_STIFF) == pytest.approx(math.sqrt(0.0975), rel=1e-15)
    assert rayleigh_speed(SHEAR_STIFF) == pytest.approx(math.sqrt(0.095), rel=1e-15)


def test_soft_C11_limiting_speed_is_longitudinal():
    assert limiting_speed(SOFT_C11) == math.sqrt(0.5)
    assert 0 < rayleigh_speed(SOFT_C11) < math.sqrt(0.5)


@pytest.mark.parametrize("m", [PAPER, ISO, COMPLEX, SHEAR_STIFF, SOFT_C11])
def test_rayleigh_function_changes_sign_at_c_R(m):
    c_R = rayleigh_speed(m)
    assert rayleigh_function(m, 0.0) > 0
    assert rayleigh_function(m, c_R * (1 - 4e-15)) > 0 > rayleigh_function(m, c_R * (1 + 4e-15))


def test_N11_diverges_at_rayleigh_speed():
    c_R = rayleigh_speed(PAPER)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", NearRayleighWarning)
        a = surface_constants(PAPER, c_R * (1 - 1e-6))
        b = surface_constants(PAPER, c_R * (1 - 1e-7))
    for sc in (a, b):
        assert np.all(np.isfinite(_N(sc)))
    assert a.N11 < 0 and abs(a.N11) > 1e5 * abs(surface_constants(PAPER, 0.0).N11)
    assert b.N11 / a.N11 == pytest.approx(10.0, rel=1e-3)           # simple pole
    assert_rel(_N(a), eig_N(PAPER, a.c).real, 1e-8)                  # still accurate


def test_near_rayleigh_warning():
    c_R = rayleigh_speed(PAPER)
    with pytest.warns(NearRayleighWarning, match=r"within 1% of the Rayleigh speed c_R = 0\.99"):
        surface_constants(PAPER, 0.995 * c_R)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        surface_constants(PAPER, 0.989 * c_R)
        surface_constants(PAPER, 0.0)


@pytest.mark.parametrize("c,match", [
    (-1e-300, r"c must be >= 0"),
    (-0.1, r"c must be >= 0"),
    (float("nan"), r"finite real"),
    (float("inf"), r"finite real"),
    ("fast", r"finite real"),
    (None, r"finite real"),
    ("rayleigh", None),
    (0.9937, r"below the Rayleigh speed c_R = 0\.9936.*0 <= c < c_R.*got c = 0\.9937"),
    (1.0, r"below the Rayleigh speed c_R = 0\.9936"),
    (5.0, r"below the Rayleigh speed"),
])
def test_bad_speed(c, match):
    if c == "rayleigh":
        c, match = rayleigh_speed(PAPER), r"below the Rayleigh speed"
    with pytest.raises(SpeedError, match=match):
        surface_constants(PAPER, c)


# ----------------------------------------------------------------------------------------
# The paper's material: Table 1 and the constants the report tabulates
# ----------------------------------------------------------------------------------------
PAPER_TABLE_1 = {   # Zhou, Lee & Jang 2014, Table 1: c -> (eta1, eta2, eta3, eta4) as printed
    0.0: (5.2506, -5.2506, 0.6120, -0.6120),
    0.1: (5.2496, -5.2496, 0.6090, -0.6090),
    0.2: (5.2468, -5.2468, 0.5997, -0.5997),
    0.3: (5.2421, -5.2421, 0.5839, -0.5839),
    0.4: (5.2356, -5.2356, 0.5610, -0.5610),
    0.5: (5.2271, -5.2271, 0.5301, -0.5301),
    0.6: (5.2168, -5.2168, 0.4897, -0.4897),
    0.7: (5.2045, -5.2045, 0.4372, -0.4372),
    0.8: (5.1904, -5.1904, 0.3674, -0.3674),
    0.9: (5.1743, -5.1743, 0.2669, -0.2669),
    1.0: (0.0, 0.0, 5.1562, -5.1562),          # the columns are in another order at c = 1
    1.5: (5.0359, -5.0359, 0.6852j, -0.6852j),
    2.0: (4.8626, -4.8626, 1.0626j, -1.0626j),
    10.0: (8.5829j, -8.5829j, 5.8365j, -5.8365j),
}


@pytest.mark.parametrize("c", list(PAPER_TABLE_1))
def test_paper_table_1_roots(c):
    """The roots of the paper's material are Table 1's values correctly rounded: each
    printed root within half a unit of its 4th decimal of a computed one and vice versa (root
    sets, not columns: the table labels them in another order at c = 1)."""
    got = PAPER.characteristic_roots(c)
    printed = np.array(PAPER_TABLE_1[c], dtype=complex)
    for a, b in ((printed, got), (got, printed)):
        nearest = np.min(np.abs(a[:, None] - b[None, :]), axis=1)
        assert np.all(nearest <= 0.5e-4), (c, got, printed)


@pytest.mark.parametrize("name", list(EIG_CASES))
def test_roots_solve_the_equations_of_motion(name):
    """Every root makes u, v ~ exp(i k X + k eta Y) a solution of the steady equations of
    motion C11' u_XX + C33 u_YY + K v_XY = 0, K u_XY + C33' v_XX + C22 v_YY = 0
    (K = C12 + C33, C11' = C11 - C33 c^2, C33' = C33 (1 - c^2)): the 2x2 determinant
    (C33 eta^2 - C11')(C22 eta^2 - C33') + K^2 eta^2 vanishes to rounding (relative to its
    largest term), written from the stiffnesses here, not from characteristic_coefficients;
    real, complex, repeated and imaginary roots (speeds past the limiting one)."""
    m = EIG_CASES[name][0]
    K = m.C12 + m.C33
    for c in (0.0, *EIG_CASES[name][1], 1.0, 1.5, 3.0):
        C11p, C33p = m.C11 - m.C33 * c * c, m.C33 * (1.0 - c * c)
        for eta in m.characteristic_roots(c):
            e2 = eta * eta
            det = (m.C33 * e2 - C11p) * (m.C22 * e2 - C33p) + K * K * e2
            scale = (abs(m.C22 * m.C33 * e2 * e2) + abs(m.C33 * C33p * e2)
                     + abs(m.C22 * C11p * e2) + abs(C11p * C33p) + abs(K * K * e2))
            assert abs(det) <= 1e-14 * scale, (c, eta, det, scale)


@pytest.mark.parametrize("c", [0.0, 0.6])
def test_paper_constants_of_the_report(c):
    """The constants the report tabulates (paper material, c = 0 and 0.6): the signs
    N11 < 0, N12 > 0, N21 < 0, N22 < 0, and every digit against the state-space solution at
    40 digits (mpmath.eig; it does not call contact.constants)."""
    N = _N(surface_constants(PAPER, c))
    assert N[0] < 0 < N[1] and N[2] < 0 and N[3] < 0
    assert_rel(N, mp_eig_N(PAPER, c), 4e-15)
