"""Tests for ``contact.material``: Orthotropic, Isotropic, zhou2014, characteristic roots.

References used (each independent of the library's quadratic formula):
  * Table 1 of Zhou, Lee & Jang 2014 (all 14 printed speeds, 4 decimals, compared as sets
    because the paper's column labels are inconsistent at c = 1).
  * The characteristic determinant of eq. (3.1) as printed (the 2x2 matrix, not our expansion
    into a, b, d): its quartic coefficients are recovered in mpmath by interpolation at five
    points and solved with mpmath.polyroots at 40 digits.
  * Textbook plane-strain Lame relations for the isotropic helper.
"""
from __future__ import annotations

import dataclasses
import math

import mpmath
import numpy as np
import pytest
from mpmath import mp, mpf

from contact.errors import MaterialError, SpeedError
from contact.material import Isotropic, Orthotropic, zhou2014

PAPER = dict(C11=159.7885, C12=5.2609, C22=15.4732, C33=5.52)

# Table 1 of the paper: c -> printed roots (real, imag) to 4 decimals.
TABLE1 = {
    0.0: [5.2506, -5.2506, 0.6120, -0.6120],
    0.1: [5.2496, -5.2496, 0.6090, -0.6090],
    0.2: [5.2468, -5.2468, 0.5997, -0.5997],
    0.3: [5.2421, -5.2421, 0.5839, -0.5839],
    0.4: [5.2356, -5.2356, 0.5610, -0.5610],
    0.5: [5.2271, -5.2271, 0.5301, -0.5301],
    0.6: [5.2168, -5.2168, 0.4897, -0.4897],
    0.7: [5.2045, -5.2045, 0.4372, -0.4372],
    0.8: [5.1904, -5.1904, 0.3674, -0.3674],
    0.9: [5.1743, -5.1743, 0.2669, -0.2669],
    1.0: [0.0, 0.0, 5.1562, -5.1562],
    1.5: [5.0359, -5.0359, 0.6852j, -0.6852j],
    2.0: [4.8626, -4.8626, 1.0626j, -1.0626j],
    10.0: [8.5829j, -8.5829j, 5.8365j, -5.8365j],
}

# Materials covering every root structure at c = 0.
MATERIALS = {
    "paper": Orthotropic(**PAPER),                       # two real pairs
    "isotropic": Orthotropic(3.0, 1.0, 3.0, 1.0),        # double root eta = 1 (G=1, nu=1/4)
    "complex": Orthotropic(1.0, 0.5, 1.0, 0.5),          # complex-conjugate pair
    "C12=-C33": Orthotropic(2.0, -0.7, 1.3, 0.7),        # eigenvector form h(eta) singular
    "soft-C11": Orthotropic(0.5, 0.1, 1.0, 1.0),         # C11 < C33
}


def _key(z):
    return (round(z.real, 4) + 0.0, round(z.imag, 4) + 0.0)


@pytest.mark.parametrize("c", sorted(TABLE1))
def test_table1_root_sets(c):
    roots = zhou2014().characteristic_roots(c)
    got = sorted(_key(z) for z in roots)
    want = sorted(_key(complex(z)) for z in TABLE1[c])
    assert got == want


def _mp_quartic_roots(m: Orthotropic, c: float):
    """Roots of det M(eta) = 0 with M the printed 2x2 matrix of eq. (3.1), sgn(zeta) = 1."""
    with mp.workdps(40):
        C11, C12, C22, C33, c = (mpf(x) for x in (m.C11, m.C12, m.C22, m.C33, c))

        def det(eta):
            m11 = -(C11 - C33 * c ** 2) + C33 * eta ** 2
            m12 = -1j * (C12 + C33) * eta
            m22 = -C33 * (1 - c ** 2) + C22 * eta ** 2
            return m11 * m22 - m12 * m12

        xs = [mpf(k) for k in range(5)]
        V = mpmath.matrix([[x ** (4 - j) for j in range(5)] for x in xs])
        coeffs = mpmath.lu_solve(V, mpmath.matrix([mpmath.re(det(x)) for x in xs]))
        roots = mpmath.polyroots(list(coeffs)[::-1], maxsteps=200, extraprec=200, asc=True)
        return [complex(r) for r in roots], float(abs(coeffs[1])) + float(abs(coeffs[3]))


@pytest.mark.parametrize("name", [k for k in MATERIALS if k != "isotropic"])
@pytest.mark.parametrize("c", [0.0, 0.3, 0.8, 1.0, 1.2, 3.0])
def test_roots_match_mpmath_polyroots_of_printed_determinant(name, c):
    m = MATERIALS[name]
    ref, odd = _mp_quartic_roots(m, c)
    assert odd < 1e-25                      # only even powers of eta (text after eq. (3.1))
    got = list(m.characteristic_roots(c))
    scale = max(abs(z) for z in ref)
    for r in ref:                           # match as sets
        j = int(np.argmin([abs(g - r) for g in got]))
        assert abs(got[j] - r) <= 1e-13 * scale, (r, got)
        got.pop(j)


@pytest.mark.parametrize("name", list(MATERIALS))
@pytest.mark.parametrize("c", [0.0, 0.5, 0.95, 1.0, 1.7, 10.0])
def test_root_layout(name, c):
    """(eta1, -eta1, eta3, -eta3), |eta1| >= |eta3|, principal roots, conjugate pairs."""
    e = MATERIALS[name].characteristic_roots(c)
    assert e.dtype == complex and e.shape == (4,)
    assert e[1] == -e[0] and e[3] == -e[2]
    assert abs(e[0]) >= abs(e[2])
    for z in (e[0], e[2]):
        assert z.real > 0 or (z.real == 0 and z.imag >= 0)
    if e[0].imag != 0 and e[0].real != 0:   # complex pair: eta3 = conj(eta1), Im eta1 > 0
        assert e[0].imag > 0
        assert e[2] == np.conj(e[0])


def test_complex_conjugate_case_at_rest():
    e = MATERIALS["complex"].characteristic_roots(0.0)
    assert e[0].real > 0 and e[0].imag > 0 and e[2] == np.conj(e[0])


def test_repeated_roots():
    iso = Isotropic(2.5, 0.25)              # G = 1, lambda = 1: exactly representable
    np.testing.assert_array_equal(iso.characteristic_roots(0.0), [1, -1, 1, -1])
    # c = 1 for the paper material: eta^2 = 0 is a root (Table 1 prints 0, 0)
    e = zhou2014().characteristic_roots(1.0)
    assert e[2] == 0 and e[3] == 0


def test_isotropic_moving_roots_closed_form():
    """Isotropic: eta^2 = 1 - k^2 c^2 and 1 - c^2, k^2 = G / (lambda + 2G)."""
    nu = 0.3
    iso = Isotropic(1.0, nu)
    k2 = (1 - 2 * nu) / (2 * (1 - nu))
    for c in (0.2, 0.7, 0.99, 1.5):
        e = iso.characteristic_roots(c)
        want = sorted([np.sqrt(complex(1 - k2 * c * c)), np.sqrt(complex(1 - c * c))], key=abs)
        np.testing.assert_allclose([e[2], e[0]], want, rtol=1e-14, atol=1e-15)


def test_zhou2014_values():
    m = zhou2014()
    assert (m.C11, m.C12, m.C22, m.C33, m.rho) == (159.7885, 5.2609, 15.4732, 5.52, None)


@pytest.mark.parametrize("E,nu", [(1.0, 0.25), (210e9, 0.3), (3.0, -0.5), (1.0, 0.49)])
def test_isotropic_lame_constants(E, nu):
    m = Isotropic(E, nu)
    G = E / (2 * (1 + nu))
    lam = 2 * G * nu / (1 - 2 * nu)
    assert m.C33 == pytest.approx(G, rel=1e-15)
    assert m.C12 == pytest.approx(lam, rel=1e-14)
    assert m.C11 == m.C22 == pytest.approx(lam + 2 * G, rel=1e-14)
    # plane strain: C11 = E (1 - nu) / ((1 + nu)(1 - 2 nu)), C12 / C11 = nu / (1 - nu)
    assert m.C11 == pytest.approx(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)), rel=1e-14)
    assert m.C12 / m.C11 == pytest.approx(nu / (1 - nu), rel=1e-14, abs=1e-15)


def test_frozen_and_hashable():
    m = zhou2014()
    with pytest.raises(dataclasses.FrozenInstanceError):
        m.C11 = 1.0
    assert hash(m) == hash(zhou2014()) and m == zhou2014()


def test_speeds_with_density():
    m = Orthotropic(**PAPER, rho=1.6e-6)    # GPa and consistent density unit
    assert m.shear_wave_speed == pytest.approx(math.sqrt(5.52 / 1.6e-6), rel=1e-15)
    assert m.relative_speed(-0.5 * m.shear_wave_speed) == pytest.approx(0.5, rel=1e-15)
    with pytest.raises(MaterialError, match="rho is None"):
        zhou2014().shear_wave_speed
    with pytest.raises(SpeedError, match="speed V"):
        m.relative_speed(float("nan"))


NAN, INF = float("nan"), float("inf")


@pytest.mark.parametrize("kwargs,match", [
    (dict(PAPER, C11=0.0), r"C11 must be > 0, got 0\.0"),
    (dict(PAPER, C11=-1.0), r"C11 must be > 0"),
    (dict(PAPER, C22=-2.0), r"C22 must be > 0, got -2\.0"),
    (dict(PAPER, C33=0.0), r"C33 must be > 0"),
    (dict(PAPER, C11=NAN), r"C11 must be a finite real"),
    (dict(PAPER, C22=INF), r"C22 must be a finite real"),
    (dict(PAPER, C12=NAN), r"C12 must be a finite real"),
    (dict(PAPER, C33="x"), r"C33 must be a finite real"),
    (dict(PAPER, C12=100.0), r"positive definite.*C11\*C22 > C12\*\*2"),
    (dict(C11=1.0, C12=-1.0, C22=1.0, C33=1.0), r"positive definite"),   # boundary excluded
    (dict(PAPER, rho=0.0), r"rho must be > 0, got 0\.0"),
    (dict(PAPER, rho=-1.0), r"rho must be > 0"),
    (dict(PAPER, rho=NAN), r"rho must be a finite real"),
])
def test_bad_material(kwargs, match):
    with pytest.raises(MaterialError, match=match):
        Orthotropic(**kwargs)


@pytest.mark.parametrize("E,nu,match", [
    (0.0, 0.3, r"Young's modulus E must be > 0"),
    (-1.0, 0.3, r"Young's modulus E must be > 0"),
    (INF, 0.3, r"Young's modulus E must be a finite real"),
    (1.0, 0.5, r"-1 < nu < 0\.5, got 0\.5"),
    (1.0, -1.0, r"-1 < nu < 0\.5, got -1\.0"),
    (1.0, NAN, r"Poisson's ratio nu must be a finite real"),
])
def test_bad_isotropic(E, nu, match):
    with pytest.raises(MaterialError, match=match):
        Isotropic(E, nu)


@pytest.mark.parametrize("c,match", [
    (-0.1, r"c must be >= 0"), (NAN, r"finite real"), (INF, r"finite real"), (None, r"finite real"),
])
def test_bad_speed_for_roots(c, match):
    with pytest.raises(SpeedError, match=match):
        zhou2014().characteristic_roots(c)
