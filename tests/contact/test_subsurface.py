"""Tests of :func:`contact.subsurface.half_space_stress` against references not derived from it.

References (all in ``tests/reference/fourier_stress_reference.py``, which does not import ``contact``):

* McEwen (1949) / Johnson, Contact Mechanics (1985), Sec. 7.1: static isotropic Hertz field
  (with two sign corrections, see :func:`fourier_stress_reference.mcewen_hertz`), and the
  axis closed forms of Johnson eq. (4.49) / Sec. 7.1;
* Flamant (Johnson 1985, eqs. 2.15-2.19) for static line loads, and a potential solution
  (Cole & Huth 1958 type, derived in the reference module) for moving ones;
* numerical Fourier inversion of the 4x4 state-space form (``FourierReference``) for the
  moving orthotropic half-space, itself checked below against the closed forms, against
  quadrature of the Flamant kernels, between its two subspace methods and two resolutions,
  and by the finite-difference residual of the equations of motion.

Units: a and p0 are not 1 where it matters (scaling errors would show); errors are relative
to p0 (or to P / r for line loads).
"""
from __future__ import annotations

import functools
import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

import contact
from contact.constants import surface_constants
from contact.subsurface import StressPointError, half_space_stress

from fourier_stress_reference import (FIELDS, FourierReference, hertz_cauchy, hertz_hat,
                                      isotropic_moving_flamant, mcewen_hertz, static_flamant)

A = 1.3          # contact half-width
P0 = 2.0         # Hertz peak pressure
E_ISO, NU_ISO = 2.0, 0.3

COMPONENTS = ("sigma_xx", "sigma_yy", "sigma_xy")


def _stack(field):
    return np.array([field.sigma_xx, field.sigma_yy, field.sigma_xy])


def _ref_stack(ref):
    return np.array([ref[name] for name in COMPONENTS])


def _flamant_cauchy(P):
    """C(z) of the line load P delta(X): -P / (pi z)."""
    return lambda z: -P / (math.pi * z)


def _strip_cauchy(p0, a):
    """C(z) of the uniform strip p0 on [-a, a]: (p0/pi) (log(a - z) - log(-a - z))."""
    return lambda z: (p0 / math.pi) * (np.log(a - z) - np.log(-a - z))


def _hertz(x, p0=P0, a=A):
    return p0 * np.sqrt(np.maximum(1.0 - (x / a) ** 2, 0.0))


def _hertz_hilbert(x, p0=P0, a=A):
    """Hc[p](x) = (1/pi) PV int p(t) / (t - x) dt of the Hertz pressure."""
    s = x / a
    return np.where(np.abs(s) < 1.0, -p0 * s,
                    p0 * (np.sign(s) * np.sqrt(np.maximum(s * s - 1.0, 0.0)) - s))


def _root_type(material, c):
    """'real' (two distinct real decaying roots), 'complex' (a conjugate pair) or 'repeated'."""
    r = material.characteristic_roots(c)
    e1, e2 = r[0], r[2]
    if abs(e1 - e2) < 1e-6 * abs(e1):
        return "repeated"
    return "complex" if abs(e1.imag) > 0 else "real"


# --- materials -------------------------------------------------------------------------------
ISO = contact.Isotropic(E_ISO, NU_ISO)
ZHOU = contact.zhou2014()
#: strongly anisotropic (C11/C22 = 10, C33 large): complex-conjugate roots at every speed
CPLX = contact.Orthotropic(10.0, 1.0, 1.0, 3.0)
_ISO25 = contact.Isotropic(1.0, 0.25)
#: isotropic nu = 0.25 with C33 raised by 1%: complex pair at c = 0, two real roots at high c,
#: so a repeated root at one speed c* > 0 (0.64392...)
NEARCROSS = contact.Orthotropic(_ISO25.C11, _ISO25.C12, _ISO25.C22, 1.01 * _ISO25.C33)


@functools.lru_cache(maxsize=None)
def _crossing_speed():
    def disc(c):
        a, b, d = NEARCROSS.characteristic_coefficients(c)
        return (b * b - 4.0 * a * d) / (a * a)
    return brentq(disc, 0.5, 0.8, xtol=1e-16)


# Points: inside, outside, near the ends, shallow and deep (in units of a).
_XS = np.array([0.0, 0.3, -0.7, 0.99, -1.01, 1.5, -3.0])
_YS = np.array([-0.05, -0.3, -0.78, -2.0, -3.0])
GRID_X, GRID_Y = (g.ravel() * A for g in np.meshgrid(_XS, _YS))


@functools.lru_cache(maxsize=None)
def _reference(material, c, method="eig"):
    return FourierReference(material, c, method=method)


@functools.lru_cache(maxsize=None)
def _reference_hertz(material, c, mu, method="eig"):
    ref = _reference(material, c, method)
    return _ref_stack(ref.field(GRID_X, GRID_Y, hertz_hat(P0, A), q_ratio=mu, length=A))


# =============================================================================================
# 0. The reference itself
# =============================================================================================
class TestReference:
    """Checks of ``FourierReference`` and the closed forms against each other and against
    quadrature (so that a wrong reference cannot certify a wrong field)."""

    @pytest.mark.parametrize("mu", [0.0, 0.5])
    def test_schur_static_isotropic_matches_mcewen(self, mu):
        """Fourier inversion (Schur basis; M is defective here) vs McEwen's closed form."""
        ref = FourierReference(ISO, 0.0, method="schur")
        got = _ref_stack(ref.field(GRID_X, GRID_Y, hertz_hat(P0, A), q_ratio=mu, length=A))
        want = np.array(mcewen_hertz(GRID_X, GRID_Y, P0, A, mu))
        assert np.abs(got - want).max() <= 1e-12 * P0

    def test_mcewen_matches_flamant_quadrature(self):
        """The (sign-corrected) McEwen formulas vs scipy quad of the Flamant kernels over the
        Hertz distribution (Johnson 1985 eq. 2.15/2.19 convolved)."""
        mu = 0.4
        for x, y in [(0.3, -0.2), (-0.7, -0.5), (1.5, -0.3), (-2.0, -1.0), (0.99, -0.05)]:
            x, y = x * A, y * A
            want = [quad(lambda t, k=k: _hertz(t) * static_flamant(x - t, y, 1.0, mu)[k],
                         -A, A, epsabs=1e-13, epsrel=1e-13, limit=400)[0] for k in range(3)]
            got = mcewen_hertz(x, y, P0, A, mu)
            assert np.allclose(got, want, rtol=0, atol=1e-12 * P0)

    def test_mcewen_surface_and_axis(self):
        """McEwen on the surface gives the tractions, on the axis sigma_z = -p0 a/sqrt(a^2+z^2)."""
        mu = 0.5
        x = np.array([-1.5, -0.6, 0.0, 0.4, 0.9, 2.0]) * A
        sx, sz, sxy = mcewen_hertz(x, -1e-14 * A, P0, A, mu)
        assert np.allclose(sz, -_hertz(x), atol=1e-12)
        assert np.allclose(sxy, -mu * _hertz(x), atol=1e-12)
        # Flamant surface limit sigma_x = -2 p + 2 Hc[q] (N21 = -1, N22 = -2 with our q = mu p)
        assert np.allclose(sx, -_hertz(x) - 2 * mu * _hertz_hilbert(x), atol=1e-12)
        z = np.array([0.1, 0.5, 1.0, 3.0]) * A
        assert np.allclose(mcewen_hertz(0.0, -z, P0, A)[1], -P0 * A / np.sqrt(A * A + z * z),
                           rtol=1e-14)

    def test_moving_flamant_closed_form(self):
        """The potential solution: static limit O(c^2), and resultants int sigma_yy dX = -P,
        int sigma_xy dX = -Q at any depth (scipy quad over the whole line)."""
        X = np.array([0.3, -1.0, 2.0, 0.0])
        Y = np.array([-0.5, -1.0, -0.2, -3.0])
        for c, tol in [(1e-3, 1e-6), (1e-2, 1e-4)]:
            got = np.array(isotropic_moving_flamant(E_ISO, NU_ISO, c, X, Y, 1.0, 0.7))
            want = np.array(static_flamant(X, Y, 1.0, 0.7))
            assert np.abs(got - want).max() < tol
        P, Q = 1.3, -0.4
        for c in (0.4, 0.9):
            for k, want in ((1, -P), (2, -Q)):
                tot = quad(lambda x: isotropic_moving_flamant(E_ISO, NU_ISO, c, x, -0.7, P, Q)[k],
                           -np.inf, np.inf, epsabs=1e-12, limit=400)[0]
                assert tot == pytest.approx(want, abs=1e-9)

    @pytest.mark.parametrize("c", [0.3, 0.6, 0.9])
    def test_point_load_matches_moving_flamant(self, c):
        """Fourier modes with the exact k integral of a line load vs the potential solution."""
        X = np.array([0.3, -0.7, 1.5, -2.0, 0.0, 5.0, -0.01])
        Y = np.array([-0.2, -0.5, -0.3, -1.0, -1.0, -0.1, -3.0])
        got = _ref_stack(_reference(ISO, c).point_load(X, Y, 1.0, 0.7))
        want = np.array(isotropic_moving_flamant(E_ISO, NU_ISO, c, X, Y, 1.0, 0.7))
        scale = 1.0 / np.hypot(X, Y)
        assert np.all(np.abs(got - want) <= 1e-12 * scale)

    def test_hertz_matches_quadrature_of_moving_flamant(self):
        """Fourier inversion of the Hertz load (Gauss panels in k) vs scipy quad of the moving
        Flamant kernel over the Hertz distribution, isotropic c = 0.5."""
        c, mu = 0.5, 0.3
        X = np.array([0.3, -0.7, 1.5, 0.99, 3.0]) * A
        Y = np.array([-0.2, -0.5, -0.3, -0.05, -3.0]) * A
        got = _ref_stack(_reference(ISO, c).field(X, Y, hertz_hat(P0, A), q_ratio=mu,
                                                  length=A))
        for i in range(len(X)):
            want = [quad(lambda t, k=k: _hertz(t) * isotropic_moving_flamant(
                E_ISO, NU_ISO, c, X[i] - t, Y[i], 1.0, mu)[k], -A, A, epsabs=1e-14,
                epsrel=1e-13, limit=400)[0] for k in range(3)]
            assert np.allclose(got[:, i], want, rtol=0, atol=1e-12 * P0)

    @pytest.mark.parametrize("material, c", [(ZHOU, 0.6), (CPLX, 0.6), (ISO, 0.5)])
    def test_eig_equals_schur_and_resolution(self, material, c):
        """The two subspace methods agree, and halving the panels / more nodes changes
        nothing (the k quadrature has converged)."""
        a = _reference_hertz(material, c, 0.3, "eig")
        b = _reference_hertz(material, c, 0.3, "schur")
        assert np.abs(a - b).max() <= 1e-13 * P0
        fine = _ref_stack(_reference(material, c).field(
            GRID_X, GRID_Y, hertz_hat(P0, A), q_ratio=0.3, length=A, panel=0.5, nodes=32,
            tail=40.0))
        assert np.abs(a - fine).max() <= 1e-13 * P0

    @pytest.mark.parametrize("material, c", [(ZHOU, 0.6), (ZHOU, 0.9), (CPLX, 0.6)])
    def test_equations_of_motion(self, material, c):
        """Finite-difference residual (4th order, h = 0.005 a) of the moving equations of
        motion and of compatibility, and the stress law, for the reference's orthotropic
        field: a wrong entry of M (e.g. the C33 c^2 inertia, which is 6-15% of the largest
        term here) would leave an O(1e-2) residual; the truncation is ~1e-7."""
        C11, C12, C22, C33 = material.C11, material.C12, material.C22, material.C33
        ref = _reference(material, c)
        x0, y0, h = 0.4 * A, -0.6 * A, 0.005 * A
        off = np.array([-2.0, -1.0, 1.0, 2.0]) * h
        wts = np.array([1.0, -8.0, 8.0, -1.0]) / (12.0 * h)

        def F(x, y):
            return ref.field(x, y, hertz_hat(P0, A), q_ratio=0.3, length=A)

        fx, fy = F(x0 + off, y0 + 0 * off), F(x0 + 0 * off, y0 + off)
        f0 = F(x0, y0)
        dX = {n: (wts * fx[n]).sum() for n in FIELDS}
        dY = {n: (wts * fy[n]).sum() for n in FIELDS}
        rv = C33 * c * c
        for terms in ([dX["sigma_xx"], dY["sigma_xy"], -rv * dX["u_X"]],
                      [dX["sigma_xy"], dY["sigma_yy"], -rv * dX["v_X"]],
                      [dY["u_X"], -dX["u_Y"]], [dY["v_X"], -dX["v_Y"]]):
            assert abs(sum(terms)) <= 1e-6 * max(abs(t) for t in terms)
        law = [(f0["sigma_xx"], C11 * f0["u_X"] + C12 * f0["v_Y"]),
               (f0["sigma_yy"], C12 * f0["u_X"] + C22 * f0["v_Y"]),
               (f0["sigma_xy"], C33 * (f0["u_Y"] + f0["v_X"]))]
        for s, want in law:
            assert s == pytest.approx(want, abs=1e-13 * P0)


# =============================================================================================
# 1. Isotropic static Hertz: McEwen / Johnson
# =============================================================================================
@pytest.mark.parametrize("nu", [-0.3, 0.0, 0.3, 0.49])
@pytest.mark.parametrize("mu", [0.0, 0.2, 0.5])
def test_isotropic_static_hertz_mcewen(nu, mu):
    """Isotropic, c = 0 (repeated root), Hertz p and q = mu p, vs McEwen (1949) / Johnson
    (1985) Sec. 7.1 (signs corrected, see ``mcewen_hertz``), at 35 points inside, outside,
    near the ends and deep; <= 1e-10 p0.  (q with the wrong sign would be off by ~mu p0.)"""
    field = half_space_stress(contact.Isotropic(3.0, nu), 0.0, GRID_X, GRID_Y,
                              hertz_cauchy(P0, A), q_ratio=mu)
    want = np.array(mcewen_hertz(GRID_X, GRID_Y, P0, A, mu))
    assert np.abs(_stack(field) - want).max() <= 1e-10 * P0


@pytest.mark.parametrize("mu", [0.0, 0.3])
def test_isotropic_static_hertz_axis(mu):
    """Along x = 0 (Johnson 1985 eq. 4.49 and Sec. 7.1), z = -Y:
    sigma_x = -(p0/a) [(a^2 + 2 z^2)/sqrt(a^2 + z^2) - 2 z], sigma_z = -p0 a/sqrt(a^2 + z^2),
    sigma_XY = -mu (p0/a) [(a^2 + 2 z^2)/sqrt(a^2 + z^2) - 2 z] (tau_xz of the tangential
    traction, q_J = -mu p); and Johnson's max shear 0.30 p0 at z = 0.78 a (mu = 0)."""
    z = np.linspace(0.01, 4.0, 400) * A
    f = half_space_stress(ISO, 0.0, 0.0, -z, hertz_cauchy(P0, A), q_ratio=mu)
    root = np.sqrt(A * A + z * z)
    bracket = (A * A + 2 * z * z) / root - 2 * z
    assert np.allclose(f.sigma_xx, -(P0 / A) * bracket, rtol=0, atol=1e-10 * P0)
    assert np.allclose(f.sigma_yy, -P0 * A / root, rtol=0, atol=1e-10 * P0)
    assert np.allclose(f.sigma_xy, -mu * (P0 / A) * bracket, rtol=0, atol=1e-10 * P0)
    if mu == 0.0:
        i = int(np.argmax(f.max_shear))
        assert f.max_shear[i] == pytest.approx(0.300 * P0, abs=5e-4 * P0)
        # exact: max of (p0/a)(z - z^2/sqrt(a^2 + z^2)) is 0.30028 p0 at z = 0.78615 a
        assert z[i] == pytest.approx(0.786 * A, abs=0.01 * A)


def test_stress_field_properties():
    """max_shear, principal, max_tension, principal_angle vs numpy.linalg.eigh of the tensor."""
    f = half_space_stress(ZHOU, 0.6, GRID_X, GRID_Y, hertz_cauchy(P0, A), q_ratio=0.3)
    T = np.array([[f.sigma_xx, f.sigma_xy], [f.sigma_xy, f.sigma_yy]]).transpose(2, 0, 1)
    w, v = np.linalg.eigh(T)
    s1, s2 = f.principal
    assert np.allclose(s1, w[:, 1], atol=1e-13 * P0) and np.allclose(s2, w[:, 0], atol=1e-13 * P0)
    assert np.allclose(f.max_tension, w[:, 1], atol=1e-13 * P0)
    assert np.allclose(f.max_shear, 0.5 * (w[:, 1] - w[:, 0]), atol=1e-13 * P0)
    d = np.stack([np.cos(f.principal_angle), np.sin(f.principal_angle)], axis=1)
    big = np.abs(w[:, 1] - w[:, 0]) > 1e-6 * P0          # direction defined
    assert np.allclose(np.abs(np.einsum("ij,ij->i", d, v[:, :, 1]))[big], 1.0, atol=1e-8)


# =============================================================================================
# 2. Line loads and the uniform strip
# =============================================================================================
_ANG = np.radians([1.0, 10.0, 45.0, 90.0, 135.0, 170.0, 179.0])
_R = np.array([1e-3, 0.7, 1.0, 50.0])
_RR, _TT = np.meshgrid(_R, _ANG)
FL_X, FL_Y = (_RR * np.cos(_TT)).ravel(), (-_RR * np.sin(_TT)).ravel()
FL_SCALE = 1.0 / _RR.ravel()


@pytest.mark.parametrize("nu", [0.0, 0.3])
def test_static_flamant(nu):
    """Static isotropic normal and tangential line loads (P = 1.7 and Q = -0.6 separately
    and together) vs Flamant (Johnson 1985, eqs. 2.15-2.19), relative to P / r: <= 1e-10."""
    m = contact.Isotropic(1.0, nu)
    for P, Q in [(1.7, 0.0), (0.0, -0.6), (1.7, -0.6)]:
        f = half_space_stress(m, 0.0, FL_X, FL_Y, _flamant_cauchy(P), _flamant_cauchy(Q))
        want = np.array(static_flamant(FL_X, FL_Y, P, Q))
        assert np.all(np.abs(_stack(f) - want) <= 1e-10 * 1.7 * FL_SCALE)


@pytest.mark.parametrize("c", [0.3, 0.6, 0.9])
def test_moving_isotropic_flamant(c):
    """Moving line loads on the isotropic half-space (two distinct real roots
    sqrt(1 - c^2 G/(lambda + 2G)), sqrt(1 - c^2)) vs the potential solution; <= 1e-10 P/r."""
    P, Q = 1.7, -0.6
    f = half_space_stress(ISO, c, FL_X, FL_Y, _flamant_cauchy(P), _flamant_cauchy(Q))
    want = np.array(isotropic_moving_flamant(E_ISO, NU_ISO, c, FL_X, FL_Y, P, Q))
    assert np.all(np.abs(_stack(f) - want) <= 1e-10 * P * FL_SCALE)


@pytest.mark.parametrize("material, c", [(ZHOU, 0.0), (ZHOU, 0.9), (CPLX, 0.6)])
def test_orthotropic_line_load(material, c):
    """Orthotropic line loads vs the Fourier modes with the exact k integral (real roots for
    zhou2014, a complex pair for CPLX); <= 1e-10 P / r."""
    P, Q = 1.7, -0.6
    f = half_space_stress(material, c, FL_X, FL_Y, _flamant_cauchy(P), _flamant_cauchy(Q))
    want = _ref_stack(_reference(material, c).point_load(FL_X, FL_Y, P, Q))
    assert np.all(np.abs(_stack(f) - want) <= 1e-10 * P * FL_SCALE)


@pytest.mark.parametrize("c", [0.0, 0.6])
def test_uniform_strip(c):
    """Uniform strip p0 on [-a, a] (normal, then tangential) on the isotropic half-space vs
    scipy quad of the static / moving Flamant kernel over the strip; <= 1e-10 p0."""
    X = np.array([0.0, 0.5, -0.95, 1.05, -2.0, 4.0]) * A
    Y = np.array([-0.1, -0.02, -0.3, -0.05, -1.0, -2.0]) * A
    cp = _strip_cauchy(P0, A)
    for load in ("p", "q"):
        if load == "p":
            f = half_space_stress(ISO, c, X, Y, cp)
        else:
            f = half_space_stress(ISO, c, X, Y, lambda z: 0.0 * z, cp)
        PQ = (1.0, 0.0) if load == "p" else (0.0, 1.0)

        def kern(x, y, k):
            if c == 0.0:
                return static_flamant(x, y, *PQ)[k]
            return isotropic_moving_flamant(E_ISO, NU_ISO, c, x, y, *PQ)[k]

        for i in range(len(X)):
            want = [P0 * quad(lambda t: kern(X[i] - t, Y[i], k), -A, A, points=[X[i]]
                              if abs(X[i]) < A else None, epsabs=1e-13, epsrel=1e-13,
                              limit=400)[0] for k in range(3)]
            assert np.allclose(_stack(f)[:, i], want, rtol=0, atol=1e-10 * P0)


# =============================================================================================
# 3. Moving orthotropic Hertz vs the Fourier reference
# =============================================================================================
# (material, c, root type at that speed, reference method)
MOVING_CASES = [
    (ZHOU, 0.0, "real", "eig"),
    (ZHOU, 0.3, "real", "eig"),
    (ZHOU, 0.6, "real", "eig"),
    (ZHOU, 0.9, "real", "eig"),
    (ISO, 0.5, "real", "eig"),          # sqrt(1 - c^2 G/(lambda+2G)) = 0.9636, sqrt(1-c^2) = 0.8660
    (CPLX, 0.0, "complex", "eig"),      # 1.3532 +- 1.1537 i
    (CPLX, 0.6, "complex", "eig"),      # 1.0415 +- 1.1422 i
    (NEARCROSS, "c*", "repeated", "schur"),   # double root 0.8424 at c* = 0.6439
]


_NAMES = {id(ZHOU): "zhou", id(ISO): "iso", id(CPLX): "cplx", id(NEARCROSS): "cross"}


@pytest.mark.parametrize("material, c, kind, method", MOVING_CASES,
                         ids=[f"{_NAMES[id(m)]}-{c}" for m, c, _, _ in MOVING_CASES])
@pytest.mark.parametrize("mu", [0.0, 0.3])
def test_moving_hertz_vs_fourier(material, c, kind, method, mu):
    """Hertz p and q = mu p on the moving half-space vs numerical Fourier inversion of the
    state-space form, 35 points with Y from -0.05 a to -3 a: <= 1e-10 p0 (asked: 1e-8;
    measured ~2e-14, 6e-13 at the repeated root)."""
    if c == "c*":
        c = _crossing_speed()
    assert _root_type(material, c) == kind
    field = half_space_stress(material, c, GRID_X, GRID_Y, hertz_cauchy(P0, A), q_ratio=mu)
    want = _reference_hertz(material, c, mu, method)
    assert np.abs(_stack(field) - want).max() <= 1e-10 * P0


@pytest.mark.parametrize("dc", [-1e-3, -1e-6, -1e-9, 1e-9, 1e-6, 1e-3])
def test_moving_hertz_through_root_crossing(dc):
    """Speeds around c* where the roots of NEARCROSS turn from a complex pair (c < c*) into
    two real roots: vs the Fourier reference (Schur basis), <= 1e-10 p0."""
    c = _crossing_speed() + dc
    assert _root_type(NEARCROSS, c) == ("complex" if dc < 0 else "real")
    field = half_space_stress(NEARCROSS, c, GRID_X, GRID_Y, hertz_cauchy(P0, A), q_ratio=0.3)
    want = _reference_hertz(NEARCROSS, c, 0.3, "schur")
    assert np.abs(_stack(field) - want).max() <= 1e-10 * P0


# =============================================================================================
# 4. Nearly isotropic materials (repeated-root switch)
# =============================================================================================
NI_X = np.array([0.0, 0.5, -0.9, 1.2, -2.0, 0.3]) * A
NI_Y = np.array([-0.1, -0.5, -0.3, -1.0, -0.7, -2.0]) * A
NI_MU = 0.3


def _perturbed(which, eps):
    C = {"C11": ISO.C11, "C12": ISO.C12, "C22": ISO.C22, "C33": ISO.C33}
    C[which] *= 1.0 + eps
    return contact.Orthotropic(C["C11"], C["C12"], C["C22"], C["C33"])


def _ni_field(material):
    return _stack(half_space_stress(material, 0.0, NI_X, NI_Y, hertz_cauchy(P0, A),
                                    q_ratio=NI_MU))


def _switch_eps(which):
    """eps at which |eta_1 - eta_2| / 2 = 1e-3 (eta_1 + eta_2) / 2 (the switch of
    contact.subsurface), from the roots at eps = 1e-6 (delta ~ sqrt(eps))."""
    r = _perturbed(which, 1e-6).characteristic_roots(0.0)
    rel = abs(r[0] - r[2]) / abs(r[0] + r[2])
    return 1e-6 * (1e-3 / rel) ** 2


NI_EPS = [1e-14, 1e-13, 1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 3e-6, 1e-5, 1e-4]


@pytest.mark.parametrize("which", ["C22", "C33", "C11"])
def test_nearly_isotropic(which):
    """C22, C33 or C11 of the isotropic material times (1 + eps) (C33: a complex pair, C11 and
    C22: two real roots; root gap ~ sqrt(eps), 1.6e-7 at eps = 1e-14, so within 1e-6 for
    eps <= 1e-13, and either side of the 1e-3 switch for 1e-6 / 3e-6): field - McEwen is
    O(eps), with (field(eps) - McEwen) / eps bounded and agreeing to 2% of its size between
    neighbouring eps >= 1e-9 (measured 0.2% at 1e-9, 1e-4 elsewhere)."""
    base = np.array(mcewen_hertz(NI_X, NI_Y, P0, A, NI_MU))
    ratios = {}
    roots = {}
    for eps in NI_EPS:
        m = _perturbed(which, eps)
        r = m.characteristic_roots(0.0)
        roots[eps] = abs(r[0] - r[2]) / abs(r[0] + r[2])
        diff = _ni_field(m) - base
        assert np.abs(diff).max() <= 1e-11 * P0 + 2.0 * eps * P0
        ratios[eps] = diff / eps
    assert roots[1e-13] < 1e-6 and roots[1e-6] < 1e-3 < roots[3e-6]
    big = [e for e in NI_EPS if e >= 1e-9]
    size = max(np.abs(ratios[e]).max() for e in big)
    assert 1e-3 * P0 < size < 10 * P0
    for e1, e2 in zip(big, big[1:]):
        assert np.abs(ratios[e1] - ratios[e2]).max() <= 2e-2 * size, (e1, e2)


@pytest.mark.parametrize("which", ["C22", "C33"])
def test_nearly_isotropic_no_jump_at_switch(which):
    """Just below / above the repeated-root switch (eps_s (1 -+ 1e-4)): the change of the field
    equals derivative * d eps (derivative from eps = 1e-6) to 5e-12 p0, i.e. no jump (the
    expected change is ~1e-10; a jump would be the size of the interpolation error)."""
    es = _switch_eps(which)
    lo, hi = es * (1 - 1e-4), es * (1 + 1e-4)
    base = np.array(mcewen_hertz(NI_X, NI_Y, P0, A, NI_MU))
    deriv = (_ni_field(_perturbed(which, 1e-6)) - base) / 1e-6
    jump = _ni_field(_perturbed(which, hi)) - _ni_field(_perturbed(which, lo)) - deriv * (hi - lo)
    assert np.abs(jump).max() <= 5e-12 * P0


def test_nearly_isotropic_vs_fourier():
    """eps = 1e-4 (roots 1.6% apart, outside the switch) and eps = 1e-6 (inside): vs the
    Fourier reference, <= 1e-10 p0."""
    for eps in (1e-4, 1e-6):
        m = _perturbed("C22", eps)
        field = half_space_stress(m, 0.0, GRID_X, GRID_Y, hertz_cauchy(P0, A), q_ratio=0.3)
        want = _ref_stack(FourierReference(m, 0.0, method="schur").field(
            GRID_X, GRID_Y, hertz_hat(P0, A), q_ratio=0.3, length=A))
        assert np.abs(_stack(field) - want).max() <= 1e-10 * P0


# =============================================================================================
# 5. Surface limits
# =============================================================================================
SURF_X = np.array([-3.0, -1.5, -1.05, -0.95, -0.5, 0.0, 0.3, 0.9, 1.01, 2.0, 5.0]) * A


@pytest.mark.parametrize("material", [ZHOU, ISO], ids=["zhou", "iso"])
@pytest.mark.parametrize("c", [0.0, 0.6])
@pytest.mark.parametrize("mu", [0.0, 0.3])
def test_surface_limit(material, c, mu):
    """At Y = -1e-13 a: sigma_YY -> -p, sigma_XY -> -q, sigma_XX -> N21 p + N22 Hc[q]
    (surface constants of contact.constants; Hertz Hc[p] = -p0 x/a inside,
    p0 (sign(x) sqrt(x^2/a^2 - 1) - x/a) outside), inside and outside the contact;
    <= 1e-10 p0 (measured 1.5e-11, linear in |Y|)."""
    f = half_space_stress(material, c, SURF_X, -1e-13 * A, hertz_cauchy(P0, A), q_ratio=mu)
    N = surface_constants(material, c)
    p = _hertz(SURF_X)
    assert np.abs(f.sigma_yy + p).max() <= 1e-10 * P0
    assert np.abs(f.sigma_xy + mu * p).max() <= 1e-10 * P0
    assert np.abs(f.sigma_xx - (N.N21 * p + N.N22 * mu * _hertz_hilbert(SURF_X))).max() \
        <= 1e-10 * P0


# =============================================================================================
# 6. Far field
# =============================================================================================
@pytest.mark.parametrize("material, c", [(ZHOU, 0.0), (ZHOU, 0.6), (ISO, 0.0), (ISO, 0.5),
                                         (CPLX, 0.6)])
@pytest.mark.parametrize("mu", [0.0, 0.3])
def test_far_field(material, c, mu):
    """At r = 1e3 a and 2e3 a (angles 5..175 deg) the Hertz field equals the line-load field
    of its resultant P = pi p0 a / 2, Q = mu P (static isotropic: Flamant; moving isotropic:
    the potential solution; orthotropic: the Fourier modes) up to a quadrupole term:
    error / (P / r) < 3 (a/r)^2 (measured 0.3-1.6 (a/r)^2; the dipole term vanishes by
    symmetry), and it quarters (ratio 3.9-4.1) when r doubles."""
    P = math.pi * P0 * A / 2.0
    th = np.radians([5.0, 30.0, 60.0, 90.0, 120.0, 150.0, 175.0])
    errs = []
    for r in (1e3 * A, 2e3 * A):
        X, Y = r * np.cos(th), -r * np.sin(th)
        got = _stack(half_space_stress(material, c, X, Y, hertz_cauchy(P0, A), q_ratio=mu))
        if material is ISO and c == 0.0:
            want = np.array(static_flamant(X, Y, P, mu * P))
        elif material is ISO:
            want = np.array(isotropic_moving_flamant(E_ISO, NU_ISO, c, X, Y, P, mu * P))
        else:
            want = _ref_stack(_reference(material, c).point_load(X, Y, P, mu * P))
        errs.append(np.abs(got - want).max() / (P / r))
        assert errs[-1] < 3.0 * (A / r) ** 2
    assert 3.9 < errs[0] / errs[1] < 4.1


# =============================================================================================
# 7. Bad input
# =============================================================================================
_CP = hertz_cauchy(P0, A)


@pytest.mark.parametrize("X, Y", [
    (np.nan, -1.0), (0.0, np.nan), (np.inf, -1.0), (0.0, -np.inf),
    ([0.0, np.nan], [-1.0, -1.0]),
    (0.0, 0.5), ([0.0, 1.0], [-1.0, 1e-300]),
    (0.0, 0.0), ([0.0, 1.0], [-1.0, 0.0]), (0.0, -0.0),
    ([0.0, 1.0], [-1.0, -2.0, -3.0]), ("x", -1.0),
])
def test_bad_points(X, Y):
    """NaN / inf, Y > 0, Y == 0, shapes that do not broadcast, non-numbers ->
    StressPointError (a ContactInputError)."""
    with pytest.raises(StressPointError):
        half_space_stress(ISO, 0.0, X, Y, _CP)
    assert issubclass(StressPointError, contact.ContactInputError)


@pytest.mark.parametrize("material", [ZHOU, ISO, CPLX], ids=["zhou", "iso", "cplx"])
def test_bad_speed(material):
    """c >= c_R, c < 0, NaN c -> SpeedError."""
    c_R = contact.rayleigh_speed(material)
    for c in (c_R, 1.01 * c_R, 1.0, -0.1, np.nan):
        with pytest.raises(contact.SpeedError):
            half_space_stress(material, c, 0.0, -1.0, _CP)


def test_both_q_forms_rejected():
    """cauchy_q and q_ratio together -> ContactInputError."""
    with pytest.raises(contact.ContactInputError):
        half_space_stress(ISO, 0.0, 0.0, -1.0, _CP, cauchy_q=_CP, q_ratio=0.2)


# =============================================================================================
# 8. Nearly decoupled materials, K = C12 + C33 -> 0
# =============================================================================================
@pytest.mark.parametrize("K", [1e-2, 1e-6, 1e-10, 0.0])
@pytest.mark.parametrize("c", [0.0, 0.5])
def test_nearly_decoupled(K, c):
    """C12 = -(1 - K) C33 (two well separated real roots sqrt(C11'/C33), sqrt(C33'/C22)),
    down to K = 0 where u and v decouple and each of the two modal null vectors vanishes
    at one root: vs the Fourier reference (which does not care about K), <= 1e-10 p0."""
    m = contact.Orthotropic(3.0, -(1.0 - K), 2.0, 1.0)
    field = half_space_stress(m, c, GRID_X, GRID_Y, hertz_cauchy(P0, A), q_ratio=0.3)
    want = _reference_hertz(m, c, 0.3, "schur")
    assert np.abs(_stack(field) - want).max() <= 1e-10 * P0
