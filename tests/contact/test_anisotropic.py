"""Tests for ``contact.anisotropic``: the general anisotropic moving half-space.

References, each independent of the module's route (the Stroh matrix's sign function):
  * the closed forms of ``contact.constants`` for aligned orthotropic materials (N11, N12,
    N21, N22, c_R, c_L through eta1 eta2 and eta1 + eta2), with the isotropic values of
    Johnson (1985) in their doctests;
  * the steady equations of motion in the Fourier domain written as a first-order system in
    Y for (u, du/dY) (not the Stroh state), built from the stiffness tensor with loops,
    whose decaying subspace is the first three Schur vectors of an ordered complex Schur
    decomposition (scipy.linalg.schur, sort='rhp'); the tractions from the stress-strain law
    (tests/reference/stroh_reference.py);
  * the Barnett-Lothe integral (1/pi) int_0^pi N(theta) d theta of the moving half-space
    (Ting 1996, ch. 7; Barnett & Lothe 1985), by the trapezoidal rule on the rotated frames
    (the same module);
  * symmetry: rotations of an isotropic material, a 90 degree turn of an orthotropic one,
    a cubic crystal turned by 45 degrees (C11' = (C11 + C12)/2 + C44, C12' = (C11 + C12)/2
    - C44, C66' = (C11 - C12)/2), reciprocity (the Hilbert part symmetric, the local part
    antisymmetric);
  * the derivative of the response in a perturbation of an isotropic material, by
    difference quotients at two step sizes (smoothness at the repeated roots).
"""
from __future__ import annotations

import math
import pickle

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.spatial.transform import Rotation

import contact
from contact.anisotropic import Anisotropic, SurfaceResponse, tensor_to_voigt, voigt_to_tensor
from contact.errors import FrictionError, MaterialError, SpeedError
from stroh_reference import barnett_lothe_integral, state_space_response, tensor_by_loops

# --------------------------------------------------------------------------
# materials
# --------------------------------------------------------------------------
#: A triclinic stiffness: all 21 constants nonzero, positive definite (eigenvalues 1.77..17.5).
TRICLINIC = np.array([
    [10.0, 4.0, 3.5, 0.6, -0.8, 1.1],
    [4.0, 12.0, 3.0, -0.7, 0.5, -0.9],
    [3.5, 3.0, 9.0, 0.4, 0.3, -0.5],
    [0.6, -0.7, 0.4, 3.2, 0.35, -0.25],
    [-0.8, 0.5, 0.3, 0.35, 2.8, 0.3],
    [1.1, -0.9, -0.5, -0.25, 0.3, 3.5],
])

#: Aligned orthotropic materials: (plane material, out-of-plane constants).  The shear
#: stiffnesses C44, C55 are above C66, so that the shear wave polarised along Z does not
#: bound c_L.
ORTHOTROPIC = {
    "zhou2014": (contact.zhou2014(), dict(C13=4.0, C23=3.0, C33=12.0, C44=6.0, C55=7.0)),
    "isotropic": (contact.Isotropic(2.5, 0.25), dict(C13=1.0, C23=1.0, C33=3.0, C44=1.0,
                                                      C55=1.0)),
    # limiting speed where eta1 + eta2 = 0 (c_L^2 = 0.0975), not a bulk wave along X
    "C12=0.9": (contact.Orthotropic(1.0, 0.9, 1.0, 1.0), dict(C13=0.5, C23=0.5, C33=1.0,
                                                              C44=1.0, C55=1.0)),
}

FRACTIONS = (0.0, 0.5, 0.9)        # c / c_R


def orthotropic(name, **changes) -> tuple[contact.Orthotropic, Anisotropic]:
    plane, out = ORTHOTROPIC[name]
    return plane, Anisotropic.from_orthotropic(plane, **{**out, **changes})


def rel(a, b) -> float:
    """max |a - b| over max |b| (arrays of one kind of entry)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.abs(a - b).max() / np.abs(b).max())


def response_vector(r: SurfaceResponse) -> np.ndarray:
    return np.concatenate([r.slope_local.ravel(), r.slope_hilbert.ravel(),
                           r.stress_local.ravel(), r.stress_hilbert.ravel()])


def same_response(r1: SurfaceResponse, r2: SurfaceResponse, tol: float) -> None:
    """Each of the four matrices of r1 equal to r2's to tol, relative to the largest entry of
    its kind (slopes: 1 / stress; stresses: dimensionless)."""
    slope = np.abs(r2.slope_hilbert).max()
    for name, scale in (("slope_local", slope), ("slope_hilbert", slope),
                        ("stress_local", 1.0), ("stress_hilbert", 1.0)):
        err = np.abs(getattr(r1, name) - getattr(r2, name)).max() / scale
        assert err <= tol, (name, err)


# --------------------------------------------------------------------------
# independent references
# --------------------------------------------------------------------------
def check_against_state_space(m: Anisotropic, c: float, tol: float) -> None:
    r = m.surface_response(c)
    slope, stress, _, _ = state_space_response(m.C, c)
    scale = np.abs(slope).max()
    assert np.abs(slope.real - r.slope_local).max() <= tol * scale
    assert np.abs(slope.imag - r.slope_hilbert).max() <= tol * scale
    assert np.abs(stress.real - r.stress_local).max() <= tol * np.abs(stress).max()
    assert np.abs(stress.imag - r.stress_hilbert).max() <= tol * np.abs(stress).max()


# --------------------------------------------------------------------------
# (a) aligned orthotropic materials: the closed forms
# --------------------------------------------------------------------------
@pytest.mark.parametrize("name", ORTHOTROPIC)
def test_aligned_orthotropic_speeds(name):
    plane, m = orthotropic(name)
    assert m.rayleigh_speed() == pytest.approx(contact.rayleigh_speed(plane), rel=1e-12)
    assert m.limiting_speed() == pytest.approx(contact.limiting_speed(plane), rel=1e-12)


@pytest.mark.parametrize("fraction", FRACTIONS)
@pytest.mark.parametrize("name", ORTHOTROPIC)
def test_aligned_orthotropic_constants(name, fraction):
    """N11 = slope_hilbert[Y, p], N12 = slope_local[Y, q], N21 = stress_local[XX, p],
    N22 = stress_hilbert[XX, q]; the entries that couple what the mirror symmetries of the
    material separate vanish."""
    plane, m = orthotropic(name)
    c = fraction * contact.rayleigh_speed(plane)
    sc = contact.surface_constants(plane, c)
    r = m.surface_response(c)
    assert r.c == c and r.rayleigh_speed == m.rayleigh_speed()
    for key, value in (("N11", r.slope_hilbert[1, 1]), ("N12", r.slope_local[1, 0]),
                       ("N21", r.stress_local[0, 1]), ("N22", r.stress_hilbert[0, 0])):
        assert value == pytest.approx(getattr(sc, key), rel=1e-12), key
        assert getattr(r, key) == value
    # the in-plane blocks are [[0, -N12], [N12, 0]] and diag(M_XX, N11); nothing couples
    # them to the antiplane ones
    scale = abs(sc.N11)
    assert r.slope_local[0, 1] == pytest.approx(-sc.N12, rel=1e-12)
    zero_local = [(0, 0), (1, 1), (0, 2), (1, 2), (2, 0), (2, 1), (2, 2)]
    zero_hilbert = [(0, 1), (1, 0), (0, 2), (1, 2), (2, 0), (2, 1)]
    assert max(abs(r.slope_local[ij]) for ij in zero_local) <= 1e-14 * scale
    assert max(abs(r.slope_hilbert[ij]) for ij in zero_hilbert) <= 1e-14 * scale
    assert abs(r.stress_local[0, 0]) + abs(r.stress_hilbert[0, 1]) <= 1e-14 * abs(sc.N22)


def test_out_of_plane_constants_leave_the_plane_alone():
    plane, m1 = orthotropic("zhou2014")
    _, m2 = orthotropic("zhou2014", C13=-2.0, C23=5.0, C33=30.0, C44=9.0, C55=12.0)
    for c in (0.0, 0.7):
        r1, r2 = m1.surface_response(c), m2.surface_response(c)
        for key in ("N11", "N12", "N21", "N22"):
            assert getattr(r1, key) == pytest.approx(getattr(r2, key), rel=1e-13)
    assert m1.rayleigh_speed() == pytest.approx(m2.rayleigh_speed(), rel=1e-13)


def test_exceptional_limiting_wave():
    """A shear wave polarised along Z slower than the in-plane Rayleigh wave (C55 < c_R^2 C66) is a
    traction-free limiting wave of the decoupled antiplane problem: c_R = c_L =
    sqrt(C55 / C66), and below it the in-plane constants are the plane material's."""
    plane, m = orthotropic("isotropic", C44=0.7, C55=0.5)
    assert m.limiting_speed() == pytest.approx(math.sqrt(0.5), rel=1e-13)
    assert m.rayleigh_speed() == m.limiting_speed()
    r, sc = m.surface_response(0.6), contact.surface_constants(plane, 0.6)
    for key in ("N11", "N12", "N21", "N22"):
        assert getattr(r, key) == pytest.approx(getattr(sc, key), rel=1e-12)
    # the antiplane compliance: w' = M_ZZ Hc[r], M_ZZ = -1 / sqrt(C44 (C55 - C66 c^2))
    assert r.slope_hilbert[2, 2] == pytest.approx(-1.0 / math.sqrt(0.7 * (0.5 - 0.36)),
                                                  rel=1e-12)


def test_isotropic_closed_forms():
    """The isotropic static constants, and the antiplane compliance
    M_ZZ = -1 / (G sqrt(1 - c^2)) of a shear wave polarised along Z
    (exp(i k X + k sqrt(1 - c^2) Y))."""
    m = Anisotropic.isotropic(5.2, 0.3)
    G, nu = 2.0, 0.3
    r = m.surface_response(0.0)
    assert r.N11 == pytest.approx(-(1 - nu) / G, rel=1e-14)
    assert r.N12 == pytest.approx((1 - 2 * nu) / (2 * G), rel=1e-14)
    assert (r.N21, r.N22) == (pytest.approx(-1.0, rel=1e-14), pytest.approx(-2.0, rel=1e-14))
    for c in (0.0, 0.5, 0.8):
        assert m.surface_response(c).slope_hilbert[2, 2] == pytest.approx(
            -1.0 / (G * math.sqrt(1.0 - c * c)), rel=1e-13)
    # N3 = R T^-1 R^T - Q + rho V^2 I, with Q, R, T written out for the isotropic material
    Q = np.diag([m.C[0, 0], G, G])
    R = np.array([[0.0, m.C[0, 1], 0.0], [G, 0.0, 0.0], [0.0, 0.0, 0.0]])
    T = np.diag([G, m.C[1, 1], G])
    N3 = R @ np.linalg.inv(T) @ R.T - Q + G * 0.25 * np.eye(3)
    assert np.abs(m.stroh_matrix(0.5)[3:, :3] - N3).max() <= 1e-14 * np.abs(N3).max()


# --------------------------------------------------------------------------
# (b) rotations
# --------------------------------------------------------------------------
def test_isotropic_any_rotation_changes_nothing():
    m = Anisotropic.isotropic(2.5, 0.25)
    base = {c: m.surface_response(c) for c in (0.0, 0.6)}
    for rotation in Rotation.random(4, random_state=20240611):
        mr = m.rotated(rotation)
        assert np.abs(mr.C - m.C).max() <= 1e-13 * np.abs(m.C).max()
        assert mr.rayleigh_speed() == pytest.approx(m.rayleigh_speed(), rel=1e-13)
        assert mr.limiting_speed() == pytest.approx(m.limiting_speed(), rel=1e-13)
        for c, r in base.items():
            same_response(mr.surface_response(c), r, 1e-13)


def test_ninety_degrees_about_z_swaps_x_and_y():
    """Material direction X turned onto Y: the orthotropic material with C11 <-> C22,
    C13 <-> C23, C44 <-> C55 (a plain matrix and a scipy Rotation, +-90 degrees)."""
    plane, m = orthotropic("zhou2014")
    out = ORTHOTROPIC["zhou2014"][1]
    swapped_plane = contact.Orthotropic(plane.C22, plane.C12, plane.C11, plane.C33)
    swapped = Anisotropic.from_orthotropic(
        swapped_plane, C13=out["C23"], C23=out["C13"], C33=out["C33"], C44=out["C55"],
        C55=out["C44"])
    matrix = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    for rotation in (matrix, Rotation.from_euler("z", -90.0, degrees=True)):
        mr = m.rotated(rotation)
        assert np.abs(mr.C - swapped.C).max() <= 1e-13 * np.abs(m.C).max()
        c_R = contact.rayleigh_speed(swapped_plane)
        assert mr.rayleigh_speed() == pytest.approx(c_R, rel=1e-12)
        for fraction in FRACTIONS:
            c = fraction * c_R
            r, sc = mr.surface_response(c), contact.surface_constants(swapped_plane, c)
            same_response(r, swapped.surface_response(c), 1e-12)
            for key in ("N11", "N12", "N21", "N22"):
                assert getattr(r, key) == pytest.approx(getattr(sc, key), rel=1e-12), key


def test_rotation_convention_is_active():
    """rotated(R) turns the material's direction e onto R e: the stiffest direction X of a
    material with C11 >> C22 turned by +30 degrees about Z is the stiffest along
    (cos 30, sin 30, 0)."""
    plane, m = orthotropic("zhou2014")
    mr = m.rotated(Rotation.from_euler("z", 30.0, degrees=True))
    t = mr.tensor
    angles = np.linspace(0.0, np.pi, 3601)
    n = np.stack([np.cos(angles), np.sin(angles), 0 * angles], axis=1)
    stiffness = np.einsum("ijkl,ai,aj,ak,al->a", t, n, n, n, n)
    assert math.degrees(angles[np.argmax(stiffness)]) == pytest.approx(30.0, abs=0.05)
    # and the tensor identity itself
    R = Rotation.from_euler("z", 30.0, degrees=True).as_matrix()
    expected = np.einsum("ia,jb,kc,ld,abcd->ijkl", R, R, R, R, tensor_by_loops(m.C))
    assert np.abs(t - expected).max() <= 1e-13 * np.abs(m.C).max()


def _cubic(C11, C12, C44):
    C = np.zeros((6, 6))
    C[:3, :3] = C12
    C[[0, 1, 2], [0, 1, 2]] = C11
    C[[3, 4, 5], [3, 4, 5]] = C44
    return C


def test_cubic_crystal_turned_45_degrees():
    C11, C12, C44 = 168.4, 121.4, 75.4              # copper, GPa
    m = Anisotropic(_cubic(C11, C12, C44)).rotated(Rotation.from_euler("z", 45.0, degrees=True))
    plane = contact.Orthotropic((C11 + C12) / 2 + C44, (C11 + C12) / 2 - C44,
                                (C11 + C12) / 2 + C44, (C11 - C12) / 2)
    expected = Anisotropic.from_orthotropic(plane, C13=C12, C23=C12, C33=C11, C44=C44,
                                            C55=C44)
    assert np.abs(m.C - expected.C).max() <= 1e-13 * C11
    c_R = contact.rayleigh_speed(plane)
    assert m.rayleigh_speed() == pytest.approx(c_R, rel=1e-12)
    assert m.limiting_speed() == pytest.approx(contact.limiting_speed(plane), rel=1e-12)
    for fraction in FRACTIONS:
        c = fraction * c_R
        r, sc = m.surface_response(c), contact.surface_constants(plane, c)
        for key in ("N11", "N12", "N21", "N22"):
            assert getattr(r, key) == pytest.approx(getattr(sc, key), rel=1e-12), key
        same_response(r, expected.surface_response(c), 1e-12)


# --------------------------------------------------------------------------
# (c) a triclinic material: independent routes
# --------------------------------------------------------------------------
@pytest.fixture(scope="module")
def triclinic():
    return Anisotropic(TRICLINIC)


def test_triclinic_constants_all_nonzero(triclinic):
    assert np.all(np.abs(TRICLINIC[np.triu_indices(6)]) > 0.2)
    assert np.linalg.eigvalsh(TRICLINIC)[0] > 1.7


@pytest.mark.parametrize("fraction", (0.0, 0.5, 0.9))
def test_triclinic_against_state_space_schur(triclinic, fraction):
    check_against_state_space(triclinic, fraction * triclinic.rayleigh_speed(), 1e-12)


def test_triclinic_negative_wavenumber_is_the_conjugate(triclinic):
    c = 0.5 * triclinic.rayleigh_speed()
    plus, minus = state_space_response(TRICLINIC, c, 1.0), state_space_response(TRICLINIC, c,
                                                                                  -1.0)
    assert np.abs(minus[0] - plus[0].conj()).max() <= 1e-13 * np.abs(plus[0]).max()
    assert np.abs(minus[1] - plus[1].conj()).max() <= 1e-13 * np.abs(plus[1]).max()


@pytest.mark.parametrize("fraction", (0.0, 0.5))
def test_triclinic_against_barnett_lothe_integral(triclinic, fraction):
    """S_hat = (1/pi) int N(theta) d theta: M = S3^-1 and L = S3^-1 S4 from the integral.
    The trapezoidal sums with 64 and 128 points agree to rounding (converged)."""
    c = fraction * triclinic.rayleigh_speed()
    S = barnett_lothe_integral(TRICLINIC, c, 128)
    assert np.abs(S - barnett_lothe_integral(TRICLINIC, c, 64)).max() <= 1e-13 * np.abs(S).max()
    M = np.linalg.inv(S[3:, :3])
    L = M @ S[3:, 3:]
    r = triclinic.surface_response(c)
    assert np.abs(r.slope_hilbert - M).max() <= 1e-12 * np.abs(M).max()
    assert np.abs(r.slope_local - L).max() <= 1e-12 * np.abs(M).max()


def orthorhombic_secular(X, C11, C22, C12, C66):
    """The secular equation of the Rayleigh wave of an orthorhombic half-space travelling
    along a symmetry axis X with the surface normal Y along another, in X = rho v^2
    (Chadwick, J. Sound Vib. 47 (1976) 39-52; Royer & Dieulesaint, J. Acoust. Soc. Am. 76
    (1984) 1438-1444; Destrade, Mech. Mater. 35 (2003) 931-939, its orthorhombic case):

        C22 C66 (C11 - X) X^2 = (C66 - X) (C22 (C11 - X) - C12^2)^2."""
    return C22 * C66 * (C11 - X) * X * X - (C66 - X) * (C22 * (C11 - X) - C12 ** 2) ** 2


@pytest.mark.parametrize("crystal,axis,constants", [
    # copper (C11, C12, C44 = 168.4, 121.4, 75.4 GPa) turned 45 degrees about Z: the (110)
    # surface, the wave along [1-10]; in the sagittal plane C11' = C22' = (C11 + C12)/2 +
    # C44, C12' = (C11 + C12)/2 - C44, C66' = (C11 - C12)/2
    ("copper", "z", (168.4, 121.4, 75.4)),
    # niobium (246.5, 133.3, 28.7 GPa: anisotropy 2 C44 / (C11 - C12) = 0.51) turned 45
    # degrees about the normal Y: the (001) surface, the wave along [110]; C11' = (C11 +
    # C12)/2 + C44, C22' = C11, C12' = C12, C66' = C44, the wave polarised along Z (C11 -
    # C12)/2 faster than the sagittal shear wave, the sagittal plane a mirror plane
    ("niobium", "y", (246.5, 133.3, 28.7)),
])
def test_rayleigh_speed_of_turned_cubic_crystals_solves_the_published_secular_equation(
        crystal, axis, constants):
    """Cubic crystals turned out of their axes so that the sagittal plane is a mirror plane:
    c_R^2 C66' is the root of the orthorhombic secular equation in (0, C66') (the only one
    there: sign changes on a fine grid), by brentq."""
    C11, C12, C44 = constants
    m = Anisotropic(_cubic(C11, C12, C44)).rotated(Rotation.from_euler(axis, 45.0,
                                                                         degrees=True))
    if axis == "z":
        sagittal = ((C11 + C12) / 2 + C44, (C11 + C12) / 2 + C44, (C11 + C12) / 2 - C44,
                    (C11 - C12) / 2)
    else:
        sagittal = ((C11 + C12) / 2 + C44, C11, C12, C44)
    C11s, C22s, C12s, C66s = sagittal
    # the turned stiffness in the sagittal plane is the one the secular equation takes
    np.testing.assert_allclose(m.C[[0, 1, 0, 5], [0, 1, 1, 5]], sagittal, rtol=1e-13)
    X = np.linspace(0.0, C66s, 20001)
    assert np.count_nonzero(np.diff(np.sign(orthorhombic_secular(X, *sagittal)))) == 1
    X_R = brentq(orthorhombic_secular, 0.0, C66s, args=sagittal, xtol=1e-14 * C66s,
                 rtol=1e-15)
    c_R = m.rayleigh_speed()
    assert c_R < m.limiting_speed()
    assert c_R ** 2 * m.C[5, 5] == pytest.approx(X_R, rel=1e-12)


def test_triclinic_rayleigh_speed_independent(triclinic):
    """c_R: the zero of the smallest eigenvalue of the (Hermitian) surface impedance of the
    state-space route, by brentq."""
    def impedance_eigenvalue(c):
        Z = state_space_response(TRICLINIC, c)[2]
        assert np.abs(Z - Z.conj().T).max() <= 1e-12 * np.abs(Z).max()
        return np.linalg.eigvalsh(0.5 * (Z + Z.conj().T))[0]

    c_R, c_L = triclinic.rayleigh_speed(), triclinic.limiting_speed()
    assert impedance_eigenvalue(0.0) > 0.0
    reference = brentq(impedance_eigenvalue, 0.5 * c_R, 0.5 * (c_R + c_L), xtol=1e-15,
                       rtol=1e-15)
    assert c_R == pytest.approx(reference, rel=1e-12)
    assert 0.5 < c_R < c_L < 1.0


def test_triclinic_limiting_speed_independent(triclinic):
    """Below c_L no eigenvalue of the state-space system is on the imaginary axis (every
    mode decays or grows); above it one pair is."""
    c_L = triclinic.limiting_speed()

    def closest_to_axis(c):
        return np.abs(state_space_response(TRICLINIC, c)[3].real).min()

    assert closest_to_axis(c_L * (1 - 1e-6)) > 1e-4
    assert closest_to_axis(c_L * (1 + 1e-6)) < 1e-10
    # and directly: c_L^2 C66 = min over p of the smallest eigenvalue of Q + p(R + R^T) + p^2 T
    t = tensor_by_loops(TRICLINIC)
    p = np.tan(np.linspace(-1.5, 1.5, 200001))
    n = np.stack([np.ones_like(p), p, 0 * p], axis=1)
    gamma = np.einsum("ijkl,aj,al->aik", t, n, n)
    assert c_L ** 2 * TRICLINIC[5, 5] == pytest.approx(np.linalg.eigvalsh(gamma)[:, 0].min(),
                                                       rel=1e-9)


def test_triclinic_rotated_against_state_space(triclinic):
    m = triclinic.rotated(Rotation.from_euler("zxz", [20.0, 35.0, -50.0], degrees=True))
    check_against_state_space(m, 0.0, 1e-12)
    check_against_state_space(m, 0.6 * m.rayleigh_speed(), 1e-12)


def test_reciprocity_and_boundary_rows(triclinic):
    """M symmetric, L antisymmetric (Ting 1996, ch. 7); the stress rows YY, YZ, XY are the
    boundary conditions -p, -r, -q."""
    for m in (triclinic, triclinic.rotated(Rotation.from_euler("y", 70.0, degrees=True))):
        for c in (0.0, 0.8 * m.rayleigh_speed()):
            r = m.surface_response(c)
            scale = np.abs(r.slope_hilbert).max()
            assert np.abs(r.slope_hilbert - r.slope_hilbert.T).max() <= 1e-14 * scale
            assert np.abs(r.slope_local + r.slope_local.T).max() <= 1e-14 * scale
            assert np.abs(r.stress_local[[1, 3, 5]] + np.eye(3)[[1, 2, 0]]).max() <= 1e-14
            assert np.abs(r.stress_hilbert[[1, 3, 5]]).max() <= 1e-14


def test_stroh_matrix_eigenvalues_solve_the_sextic(triclinic):
    c = 0.5 * triclinic.rayleigh_speed()
    N = triclinic.stroh_matrix(c)
    t = tensor_by_loops(TRICLINIC)
    Q, R, T = t[:, 0, :, 0], t[:, 0, :, 1], t[:, 1, :, 1]
    rv2 = TRICLINIC[5, 5] * c * c
    p = np.linalg.eigvals(N)
    assert np.sum(p.imag < 0) == 3 and np.abs(p.imag).min() > 0.1
    for root in p:
        K = Q - rv2 * np.eye(3) + root * (R + R.T) + root ** 2 * T
        assert np.linalg.svd(K, compute_uv=False)[-1] <= 1e-12 * np.linalg.norm(K, 2)


# --------------------------------------------------------------------------
# (d) near isotropy: accurate and smooth
# --------------------------------------------------------------------------
def test_nearly_isotropic_is_smooth():
    """C = C_iso + eps P, P symmetric: the response changes by O(eps), and its derivative in
    eps from eps = 1e-8 agrees with that from eps = 1e-4 (truncation 1e-8): no loss of digits
    at the triple roots p = +-i of the isotropic material (an eigenvector route loses half
    of them there)."""
    C0 = Anisotropic.isotropic(2.5, 0.25).C
    P = np.random.default_rng(7).standard_normal((6, 6))
    P = 0.5 * (P + P.T)

    def F(eps, c):
        return response_vector(Anisotropic(C0 + eps * P).surface_response(c))

    for c in (0.0, 0.5):
        plane = contact.surface_constants(contact.Isotropic(2.5, 0.25), c)
        r0 = Anisotropic(C0).surface_response(c)
        for key in ("N11", "N12", "N21", "N22"):
            assert getattr(r0, key) == pytest.approx(getattr(plane, key), rel=1e-14)
        D_big = (F(1e-4, c) - F(-1e-4, c)) / 2e-4
        D_small = (F(1e-8, c) - F(-1e-8, c)) / 2e-8
        assert np.abs(D_small - D_big).max() <= 1e-6 * np.abs(D_big).max()
        assert np.abs(F(1e-8, c) - F(0.0, c)).max() <= 2e-8 * np.abs(D_big).max()

    def c_R(eps):
        return Anisotropic(C0 + eps * P).rayleigh_speed()

    slope = (c_R(1e-4) - c_R(-1e-4)) / 2e-4
    assert (c_R(1e-8) - c_R(-1e-8)) / 2e-8 == pytest.approx(slope, rel=1e-5)


def test_nearly_isotropic_rotated_and_moving():
    """A perturbation of 1e-8 of an isotropic material, turned: within 1e-7 of isotropic."""
    m0 = Anisotropic.isotropic(1.0, 0.2)
    P = np.zeros((6, 6))
    P[0, 0] = P[1, 1] = 1e-8                               # slightly stiffer in X and Y
    m = Anisotropic(m0.C + P).rotated(Rotation.from_euler("xyz", [10, 20, 30], degrees=True))
    for c in (0.0, 0.3, 0.8):
        r, r0 = m.surface_response(c), m0.surface_response(c)
        assert np.abs(response_vector(r) - response_vector(r0)).max() <= 1e-7


# --------------------------------------------------------------------------
# conversions, speeds, coefficients
# --------------------------------------------------------------------------
def test_from_engineering():
    E, nu = 2.5, 0.25
    iso = Anisotropic.from_engineering(E, E, E, nu, nu, nu, 1.0, 1.0, 1.0)
    assert np.abs(iso.C - Anisotropic.isotropic(E, nu).C).max() <= 1e-14 * 3.0
    consts = dict(E1=140.0, E2=10.0, E3=9.0, nu12=0.3, nu13=0.28, nu23=0.45, G12=5.0,
                  G13=4.5, G23=3.2)
    m = Anisotropic.from_engineering(**consts, rho=1.6)
    S = np.linalg.inv(m.C)
    assert 1 / S[0, 0] == pytest.approx(140.0, rel=1e-13)
    assert 1 / S[2, 2] == pytest.approx(9.0, rel=1e-13)
    assert -S[0, 1] * 140.0 == pytest.approx(0.3, rel=1e-13)
    assert -S[1, 2] * 10.0 == pytest.approx(0.45, rel=1e-13)
    assert -S[1, 0] * 10.0 == pytest.approx(0.3 * 10.0 / 140.0, rel=1e-12)   # nu21
    assert 1 / S[3, 3] == pytest.approx(3.2, rel=1e-13)
    assert 1 / S[4, 4] == pytest.approx(4.5, rel=1e-13)
    assert 1 / S[5, 5] == pytest.approx(5.0, rel=1e-13)
    assert m.rho == 1.6 and np.abs(m.C - m.C.T).max() == 0.0


def test_relative_speed_and_density():
    plane = contact.Orthotropic(4.0, 1.0, 4.0, 1.0, rho=4.0)
    m = Anisotropic.from_orthotropic(plane, C13=1.0, C23=1.0, C33=4.0, C44=1.0, C55=1.0)
    assert m.rho == 4.0 and m.shear_wave_speed == 0.5
    assert m.relative_speed(-0.25) == plane.relative_speed(-0.25) == 0.5
    m2 = Anisotropic.from_orthotropic(plane, C13=1.0, C23=1.0, C33=4.0, C44=1.0, C55=1.0,
                                      rho=1.0)
    assert m2.relative_speed(0.25) == 0.25
    with pytest.raises(MaterialError, match="rho is None"):
        Anisotropic(TRICLINIC).relative_speed(1.0)
    with pytest.raises(SpeedError, match="speed V"):
        m.relative_speed(float("nan"))


def test_pressure_coefficients():
    plane, m = orthotropic("zhou2014")
    sc = contact.surface_constants(plane, 0.5)
    r = m.surface_response(0.5)
    k = r.pressure_coefficients(0.3)
    assert k.slope_local[1] == pytest.approx(0.3 * sc.N12, rel=1e-12)
    assert k.slope_hilbert[1] == pytest.approx(sc.N11, rel=1e-12)
    assert k.stress_local[0] == pytest.approx(sc.N21, rel=1e-12)
    assert k.stress_hilbert[0] == pytest.approx(0.3 * sc.N22, rel=1e-12)
    assert k.stress_local[1] == -1.0 and k.stress_local[5] == pytest.approx(-0.3)
    rt = Anisotropic(TRICLINIC).surface_response(0.2)
    kt = rt.pressure_coefficients(-0.4)
    s = np.array([-0.4, 1.0, 0.0])
    assert np.array_equal(kt.slope_hilbert, rt.slope_hilbert @ s)
    assert kt.slope_hilbert[1] != rt.slope_hilbert[1, 1]       # Hc[q] moves the surface
    with pytest.raises(FrictionError, match="q_ratio"):
        rt.pressure_coefficients(float("inf"))


def test_value_semantics():
    m = Anisotropic(TRICLINIC, rho=2.0)
    assert m == Anisotropic(TRICLINIC.tolist(), rho=2.0) and hash(m) == hash(
        Anisotropic(TRICLINIC, rho=2.0))
    assert m != Anisotropic(TRICLINIC) and m != "steel"
    assert pickle.loads(pickle.dumps(m)) == m
    with pytest.raises(ValueError):
        m.C[0, 0] = 1.0
    r = m.surface_response(0.1)
    with pytest.raises(ValueError):
        r.slope_hilbert[0, 0] = 1.0
    assert np.array_equal(tensor_to_voigt(voigt_to_tensor(TRICLINIC)), TRICLINIC)
    assert np.array_equal(voigt_to_tensor(TRICLINIC), tensor_by_loops(TRICLINIC))
    assert eval(repr(m), {"Anisotropic": Anisotropic}) == m


# --------------------------------------------------------------------------
# (e) what is refused
# --------------------------------------------------------------------------
def _changed(a, b, value, symmetric=True):
    C = TRICLINIC.copy()
    C[a, b] = value
    if symmetric:
        C[b, a] = value
    return C


@pytest.mark.parametrize("C, match", [
    (_changed(0, 5, 1.5, symmetric=False), r"symmetric.*C\[0, 5\]"),
    (_changed(0, 1, 15.0), "positive definite"),
    (-TRICLINIC, "positive definite"),
    (np.diag([1.0, 1.0, 1.0, 1.0, 1.0, 0.0]), "positive definite"),
    (_changed(2, 2, float("nan")), r"finite.*C\[2, 2\]"),
    (_changed(3, 4, float("inf")), "finite"),
    (TRICLINIC[:, :5], r"6x6.*\(6, 5\)"),
    (TRICLINIC.ravel(), r"6x6.*\(36,\)"),
    (TRICLINIC[:3, :3], "6x6"),
    ("steel", "6x6"),
    (TRICLINIC + 0j, "real"),
    ([[1.0] * 6] * 5 + [[1.0] * 5], "6x6"),
])
def test_bad_stiffness(C, match):
    with pytest.raises(MaterialError, match=match):
        Anisotropic(C)


def test_rounding_asymmetry_is_accepted():
    C = TRICLINIC.copy()
    C[0, 5] *= 1 + 1e-15
    assert np.array_equal(Anisotropic(C).C, Anisotropic(C).C.T)


@pytest.mark.parametrize("rho", [0.0, -1.0, float("nan"), "1"])
def test_bad_density(rho):
    with pytest.raises(MaterialError, match="rho"):
        Anisotropic(TRICLINIC, rho=rho)


@pytest.mark.parametrize("rotation, match", [
    (np.diag([1.0, 1.0, -1.0]), "reflection"),
    (-np.eye(3), "reflection"),
    (np.diag([1.0, 1.0, 1.001]), "orthogonal"),
    (np.eye(2), "3x3"),
    (np.full((3, 3), np.nan), "finite"),
    (Rotation.random(2, random_state=1), "single rotation"),
    ("z", "3x3"),
])
def test_bad_rotation(rotation, match):
    with pytest.raises(MaterialError, match=match):
        Anisotropic(TRICLINIC).rotated(rotation)


def test_bad_speed(triclinic):
    c_R, c_L = triclinic.rayleigh_speed(), triclinic.limiting_speed()
    for c in (c_L, 1.2 * c_L, 1e300):
        with pytest.raises(SpeedError, match="limiting speed"):
            triclinic.surface_response(c)
    for c in (c_R, 0.5 * (c_R + c_L)):
        with pytest.raises(SpeedError, match="below the Rayleigh speed"):
            triclinic.surface_response(c)
    with pytest.raises(SpeedError, match=">= 0"):
        triclinic.surface_response(-0.1)
    for c in (float("nan"), float("inf"), "0.5", None):
        with pytest.raises(SpeedError, match="relative speed c"):
            triclinic.surface_response(c)
    with pytest.raises(SpeedError, match=">= 0"):
        triclinic.stroh_matrix(-1.0)


def test_bad_conversions():
    with pytest.raises(MaterialError, match="contact.Orthotropic"):
        Anisotropic.from_orthotropic(Anisotropic(TRICLINIC), C13=0, C23=0, C33=1, C44=1,
                                     C55=1)
    with pytest.raises(MaterialError, match="C44"):
        Anisotropic.from_orthotropic(contact.zhou2014(), C13=0, C23=0, C33=1,
                                     C44=float("nan"), C55=1)
    with pytest.raises(MaterialError, match="positive definite"):
        Anisotropic.from_orthotropic(contact.zhou2014(), C13=0, C23=0, C33=1, C44=-1, C55=1)
    with pytest.raises(MaterialError, match="E2 must be > 0"):
        Anisotropic.from_engineering(1.0, 0.0, 1.0, 0.3, 0.3, 0.3, 1.0, 1.0, 1.0)
    with pytest.raises(MaterialError, match="nu13"):
        Anisotropic.from_engineering(1.0, 1.0, 1.0, 0.3, float("nan"), 0.3, 1.0, 1.0, 1.0)
    with pytest.raises(MaterialError, match="compliance that is not positive definite"):
        Anisotropic.from_engineering(1.0, 1.0, 1.0, 0.6, 0.6, 0.6, 1.0, 1.0, 1.0)
    with pytest.raises(MaterialError, match="nu"):
        Anisotropic.isotropic(1.0, 0.5)
