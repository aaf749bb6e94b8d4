"""ContactResult.stress / stress_extrema: the field under a solved contact.

References: Hertz line contact and McEwen's (1949) closed forms of its field (Johnson,
*Contact Mechanics*, 1985, eqs. (4.48)-(4.49), sec. 7.2), written out below from those
formulas; the Flamant line load (Johnson eq. (2.15)); symmetry and linearity of the
equations.  The coefficients themselves are checked against a numerical Fourier inversion
of the state-space solution in tests/contact/test_subsurface.py.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq, minimize, minimize_scalar

import contact
from contact.subsurface import field_extrema, half_space_stress


# --------------------------------------------------------------------------------------
# McEwen 1949 (Johnson 1985, eqs. (4.49), (7.7)): Hertz pressure p0 sqrt(1 - x^2/a^2) and
# a tangential traction q_J = mu_J p on the solid in +x; z = depth, x along; m, n as there.
# The signs are those that agree with superposing the Flamant kernels (Johnson eqs. (2.15),
# (2.19)) over the tractions by quadrature (checked to 1e-13 at sample points; the printed
# forms differ in the sign convention of tau_xz and of q).
# Our axes: sigma_XX = sigma_x, sigma_YY = sigma_z, sigma_XY = -tau_xz, and our q = -q_J.
# --------------------------------------------------------------------------------------
def _mn(x, z, a):
    s = a * a - x * x + z * z
    root = np.sqrt(s * s + 4.0 * x * x * z * z)
    m = np.sqrt(0.5 * (root + s)) * np.where(z < 0, -1.0, 1.0)
    n = np.sqrt(np.maximum(0.5 * (root - s), 0.0)) * np.where(x < 0, -1.0, 1.0)
    return m, n


def mcewen(x, z, a, p0, mu_J):
    """(sigma_x, sigma_z, tau_xz) of Hertz pressure plus q_J = mu_J p (Johnson's axes)."""
    m, n = _mn(x, z, a)
    mn2 = m * m + n * n
    q0 = mu_J * p0
    sx = -(p0 / a) * (m * (1 + (z * z + n * n) / mn2) - 2 * z) \
        + (q0 / a) * (n * (2 - (z * z - m * m) / mn2) - 2 * x)
    sz = -(p0 / a) * m * (1 - (z * z + n * n) / mn2) - (q0 / a) * n * (m * m - z * z) / mn2
    txz = -(p0 / a) * n * (m * m - z * z) / mn2 \
        - (q0 / a) * (m * (1 + (z * z + n * n) / mn2) - 2 * z)
    return sx, sz, txz


def mcewen_max_shear(x, z, a, p0, mu_J):
    sx, sz, txz = mcewen(x, z, a, p0, mu_J)
    return np.hypot(0.5 * (sx - sz), txz)


ISO = contact.Isotropic(1.0, 0.3)


def _hertz(load=0.01, R=1.0):
    r = contact.solve(ISO, contact.CylindricalPunch(R), load=load, speed=0.0)
    a = r.half_width
    return r, a, 2.0 * load / (math.pi * a)


def test_hertz_contact_field_against_mcewen():
    """Numeric solve of a rigid cylinder on an isotropic half-space (static, no friction):
    a^2 = 4 P R (1 - nu^2) / (pi E) (Johnson eq. 4.45) and the whole field, McEwen's closed
    form, to 1e-10 p0."""
    R, P = 1.0, 0.01
    r, a, p0 = _hertz(P, R)
    assert a == pytest.approx(math.sqrt(4 * P * R * (1 - 0.3 ** 2) / (math.pi * 1.0)), rel=1e-12)
    X, Z = np.meshgrid(np.array([-2.5, -1.0 + 1e-9, -0.7, 0.0, 0.3, 0.99, 1.5]) * a,
                       np.array([1e-6, 0.05, 0.5, 0.786, 1.3, 4.0]) * a)
    f = r.stress(X, -Z)
    sx, sz, txz = mcewen(X, Z, a, p0, 0.0)
    assert np.max(np.abs(f.sigma_xx - sx)) <= 1e-10 * p0
    assert np.max(np.abs(f.sigma_yy - sz)) <= 1e-10 * p0
    assert np.max(np.abs(f.sigma_xy + txz)) <= 1e-10 * p0
    # along the axis (Johnson eq. 4.49): sigma_z = -p0 / sqrt(1 + z^2/a^2)
    zeta = np.array([0.1, 0.5, 1.0, 3.0])
    g = r.stress(0.0, -zeta * a)
    assert np.max(np.abs(g.sigma_yy + p0 / np.sqrt(1 + zeta ** 2))) <= 1e-10 * p0
    assert np.max(np.abs(g.sigma_xx + p0 * ((1 + 2 * zeta ** 2) / np.sqrt(1 + zeta ** 2)
                                            - 2 * zeta))) <= 1e-10 * p0


def test_hertz_max_shear_extremum():
    """tau_1 = p0 (zeta - zeta^2 / sqrt(1 + zeta^2)) on the axis peaks at 0.30028 p0 at
    zeta = 0.78615 (Johnson sec. 4.6: 0.30 p0 at 0.78 a)."""
    r, a, p0 = _hertz()
    ref = minimize_scalar(lambda s: -(s - s * s / math.sqrt(1 + s * s)), bounds=(0.3, 1.5),
                          method="bounded", options={"xatol": 1e-12})
    e = r.stress_extrema()
    assert e.max_shear.value / p0 == pytest.approx(-ref.fun, abs=1e-10)
    assert round(e.max_shear.value / p0, 3) == 0.300
    assert e.max_shear.depth_over_a == pytest.approx(ref.x, abs=1e-5)
    assert abs(e.max_shear.X) <= 1e-5 * a
    assert e.max_shear.half_width == r.half_width
    assert e.max_shear.depth == pytest.approx(-e.max_shear.Y)


@pytest.mark.parametrize("load", [1e-5, 1e-3])
def test_the_extrema_of_two_small_far_apart_zones_are_each_hertz(load):
    """The W face (curvature 0.4 at its valleys X = +-1) at loads where each of its two
    zones is a Hertz contact far (>> a) from the other: the largest shear is that of Hertz,
    0.30028 p0 at 0.786 a (Johnson sec. 4.6), found although a zone is narrower than the
    spacing of the grid over both (at load 1e-5 it was 0.2326 p0 at 1.725 a: no grid point
    came near a zone)."""
    w = contact.ProfilePunch(lambda X: 0.2 * X * (X * X - 1.0),
                             height=lambda X: 0.05 * (X * X - 1.0) ** 2, face=(-2.0, 2.0))
    r = contact.solve(ISO, w, load=load, speed=0.0)
    assert len(r.zones) == 2 and r.zones[0].width < 0.1 * (r.zones[1].ends[0] - r.zones[0].ends[1])
    z = r.zones[1]
    p0 = float(np.max(r.pressure(np.linspace(*z.ends, 2001)[1:-1])))
    e = r.stress_extrema()
    assert e.max_shear.value / p0 == pytest.approx(0.30028, rel=2e-3)
    assert e.max_shear.depth_over_a == pytest.approx(0.78615, rel=1e-2)


def _hertz_core(mu):
    return lambda X, Y: half_space_stress(ISO, 0.0, X, np.minimum(Y, -1e-300),
                                          lambda z: np.sqrt(z - 1) * np.sqrt(z + 1) - z,
                                          q_ratio=mu)


def test_friction_moves_the_max_shear_to_the_surface():
    """Hertz pressure with q = mu p (Smith & Liu 1953; Johnson sec. 7.2): on the surface
    under the contact tau_1 = mu p0 exactly; the subsurface peak rises, moves toward the
    leading edge and up, and falls below mu p0 at mu*, found from McEwen's closed form by
    an independent maximisation; the field's extrema give the same mu* to 1e-6."""
    def closed_peak(mu):
        # the subsurface local maximum of McEwen's tau_1 (a = p0 = 1, q_J = -mu p: our q = mu p)
        def f(u):
            return -mcewen_max_shear(u[0], max(u[1], 1e-3), 1.0, 1.0, -mu)
        X, Z = np.meshgrid(np.linspace(-1.5, 1.5, 121), np.linspace(1e-3, 2.0, 81))
        V = mcewen_max_shear(X, Z, 1.0, 1.0, -mu)
        k = np.unravel_index(np.argmax(V), V.shape)
        res = minimize(f, [X[k], Z[k]], method="Nelder-Mead",
                       options={"xatol": 1e-11, "fatol": 1e-15})
        return -res.fun, res.x

    def ours(mu):
        e = field_extrema(_hertz_core(mu), ((-1.5, 1.5), (-2.0, -1e-3)), lambda X: 1.0)
        return e.max_shear

    for mu in (0.1, 0.3):
        val, (x, z) = closed_peak(mu)
        got = ours(mu)
        assert got.value == pytest.approx(val, abs=1e-10)
        assert (got.X, -got.Y) == pytest.approx((x, z), abs=1e-5)
    mu_ref = brentq(lambda mu: closed_peak(mu)[0] - mu, 0.3, 0.39, xtol=1e-12)
    mu_got = brentq(lambda mu: ours(mu).value - mu, 0.3, 0.39, xtol=1e-12)
    assert mu_got == pytest.approx(mu_ref, abs=1e-6)
    assert 0.37 < mu_ref < 0.39     # 0.3780; published maps: below the surface at 0.1, on it at 0.4
    # above mu* the largest max shear is the surface value mu p0
    e = field_extrema(_hertz_core(0.5), ((-1.5, 1.5), (-2.0, 0.0)), lambda X: 1.0)
    assert e.max_shear.value == pytest.approx(0.5, abs=1e-10)
    assert e.max_shear.Y == 0.0


# --------------------------------------------------------------------------------------
# the surface, the closed forms, several zones
# --------------------------------------------------------------------------------------
@pytest.mark.parametrize("speed,friction", [(0.0, 0.0), (0.6, 0.3)])
def test_surface_points_are_the_tractions_and_the_field_tends_to_them(speed, friction):
    r = contact.solve(contact.zhou2014(), contact.CylindricalPunch(100.0), load=0.01,
                      speed=speed, friction=friction)
    xl, xr = r.ends
    X = np.array([xl - 0.3, xl + 1e-3, 0.5 * (xl + xr), xr - 1e-3, xr + 0.3])
    on = r.stress(X, 0.0)
    p = r.pressure(X)
    assert np.array_equal(on.sigma_yy, -p)
    assert np.array_equal(on.sigma_xy, -r.mu_f * p)
    assert np.array_equal(on.sigma_xx, r.sigma_xx(X))
    near = r.stress(X, -1e-12 * r.half_width)
    scale = np.max(p)
    for name in ("sigma_xx", "sigma_yy", "sigma_xy"):
        assert np.max(np.abs(getattr(near, name) - getattr(on, name))) <= 1e-8 * scale


@pytest.mark.parametrize("punch", [contact.FlatPunch(0.1), contact.TriangularPunch(0.01),
                                   contact.ParabolicPunch(100.0), contact.CylindricalPunch(100.0)],
                         ids=["flat", "triangular", "parabolic", "cylindrical"])
def test_closed_form_results_give_the_numeric_field(punch):
    """The closed forms' pressure is w(s) (d0 + d1 s): its Cauchy transform off the line
    through the Jacobi series; the field equals the numeric result's to 1e-10."""
    kw = dict(load=0.01, speed=0.6, friction=0.3)
    m = contact.zhou2014()
    num, cf = contact.solve(m, punch, **kw), contact.solve(m, punch, method="closed_form", **kw)
    a = num.half_width
    X, Y = np.meshgrid(num.center + np.linspace(-2, 2, 9) * a, np.array([-1e-3, -0.3, -2.0]) * a)
    f, g = num.stress(X, Y), cf.stress(X, Y)
    scale = np.max(np.abs(g.sigma_yy))
    for name in ("sigma_xx", "sigma_yy", "sigma_xy"):
        assert np.max(np.abs(getattr(f, name) - getattr(g, name))) <= 1e-10 * scale


def test_two_zones_far_field_is_the_flamant_field_of_the_resultant():
    """Far from the contact the field of any tractions is that of their resultant
    (P, Q = mu_f P) at their centroid, error O(a / r) of it."""
    w = contact.ProfilePunch(lambda X: 0.2 * X ** 3 - 0.2 * X, face=(-2.0, 2.0))
    m = contact.zhou2014()
    r = contact.solve(m, w, load=1e-3, speed=0.3, friction=0.3)
    assert len(r.zones) == 2
    P = sum(z.load for z in r.zones)
    span = r.zones[-1].ends[1] - r.zones[0].ends[0]
    errs = []
    for R in (1e3 * span, 2e3 * span):
        th = np.linspace(-0.45 * np.pi, 0.45 * np.pi, 7)
        Xp, Yp = R * np.sin(th), -R * np.cos(th)
        f = r.stress(Xp, Yp)
        g = half_space_stress(m, 0.3, Xp, Yp, lambda z: -P / (np.pi * z), q_ratio=r.mu_f)
        scale = np.max(np.abs(g.sigma_yy))
        errs.append(max(np.max(np.abs(getattr(f, k) - getattr(g, k)))
                        for k in ("sigma_xx", "sigma_yy", "sigma_xy")) / scale)
    assert errs[0] < 10 * span / (1e3 * span)
    assert errs[1] == pytest.approx(errs[0] / 2, rel=0.05)     # O(a / r)


# --------------------------------------------------------------------------------------
# invariants
# --------------------------------------------------------------------------------------
@settings(max_examples=25, deadline=None)
@given(x=st.floats(-3.0, 3.0), depth=st.floats(1e-3, 4.0))
def test_direction_mirrors_the_field(x, depth):
    """Sliding the other way mirrors the problem in X: sigma_XX, sigma_YY even, sigma_XY odd."""
    m, p = contact.zhou2014(), contact.CylindricalPunch(100.0)
    kw = dict(load=0.01, speed=0.6, friction=0.3)
    left = contact.solve(m, p, direction=-1, **kw)
    right = contact.solve(m, p, direction=1, **kw)
    a = left.half_width
    f, g = left.stress(x * a, -depth * a), right.stress(-x * a, -depth * a)
    scale = left.pressure(left.center)
    assert abs(f.sigma_xx - g.sigma_xx) <= 1e-10 * scale
    assert abs(f.sigma_yy - g.sigma_yy) <= 1e-10 * scale
    assert abs(f.sigma_xy + g.sigma_xy) <= 1e-10 * scale


def test_flat_punch_field_is_linear_in_the_load():
    """The flat punch's zone does not change with load: p, and the field, scale with P."""
    m, p = contact.zhou2014(), contact.FlatPunch(0.1)
    r1 = contact.solve(m, p, load=0.01, speed=0.3, friction=0.2)
    r3 = contact.solve(m, p, load=0.03, speed=0.3, friction=0.2)
    X, Y = np.meshgrid(np.linspace(-0.2, 0.2, 7), np.linspace(-0.3, -1e-3, 5))
    f1, f3 = r1.stress(X, Y), r3.stress(X, Y)
    for k in ("sigma_xx", "sigma_yy", "sigma_xy"):
        assert np.allclose(3 * getattr(f1, k), getattr(f3, k), rtol=1e-12, atol=1e-14)


def test_derived_quantities():
    r, a, p0 = _hertz()
    f = r.stress(np.array([0.3 * a, -0.5 * a]), np.array([-0.2 * a, -1.1 * a]))
    s1, s2 = f.principal
    # Mohr's circle: invariants trace and determinant
    assert np.allclose(s1 + s2, f.sigma_xx + f.sigma_yy, rtol=1e-14)
    assert np.allclose(s1 * s2, f.sigma_xx * f.sigma_yy - f.sigma_xy ** 2, rtol=1e-12)
    assert np.allclose(f.max_shear, 0.5 * (s1 - s2), rtol=1e-14)
    assert np.array_equal(f.max_tension, s1)
    th = f.principal_angle      # sigma_1 along (cos th, sin th)
    n = np.array([np.cos(th), np.sin(th)])
    t = np.array([f.sigma_xx * n[0] + f.sigma_xy * n[1], f.sigma_xy * n[0] + f.sigma_yy * n[1]])
    assert np.allclose(t, s1 * n, atol=1e-14 * p0)


@pytest.mark.parametrize("material,c", [(contact.zhou2014(), 0.0), (contact.zhou2014(), 0.9),
                                        (ISO, 0.5), (contact.Orthotropic(10.0, 1.0, 2.0, 3.0), 0.2)])
def test_modal_vectors_solve_the_equations_of_motion(material, c):
    """(C33 eta^2 - C11') u + i K eta v = 0 and i K eta u + (C22 eta^2 - C33') v = 0."""
    C11p = material.C11 - material.C33 * c * c
    C33p = material.C33 * (1 - c * c)
    K = material.C12 + material.C33
    V = material.modal_vectors(c)
    for eta, (u, v) in zip(material.decaying_roots(c), V):
        assert eta.real > 0
        scale = (abs(material.C33 * eta ** 2) + C11p + abs(K * eta)) * (abs(u) + abs(v))
        assert abs((material.C33 * eta ** 2 - C11p) * u + 1j * K * eta * v) <= 1e-12 * scale
        assert abs(1j * K * eta * u + (material.C22 * eta ** 2 - C33p) * v) <= 1e-12 * scale


# --------------------------------------------------------------------------------------
# bad input
# --------------------------------------------------------------------------------------
def test_bad_points_raise():
    r, a, _ = _hertz()
    with pytest.raises(contact.StressPointError, match="finite"):
        r.stress(np.nan, -1.0)
    with pytest.raises(contact.StressPointError, match="Y <= 0"):
        r.stress(0.0, 0.5)
    with pytest.raises(contact.StressPointError, match="broadcastable"):
        r.stress(np.zeros(3), np.zeros(2) - 1)
    flat = contact.solve(contact.zhou2014(), contact.FlatPunch(0.1), load=0.01, speed=0.0)
    with pytest.raises(contact.ContactInputError, match="singular"):
        flat.stress(0.1, 0.0)
    assert np.isfinite(flat.stress(0.1, -1e-9).max_shear)


def test_extrema_near_singular_corners_and_bad_regions():
    flat = contact.solve(contact.zhou2014(), contact.FlatPunch(0.1), load=0.01, speed=0.3,
                         friction=0.3)
    with pytest.raises(contact.UnboundedStressError, match="infinite at the singular"):
        flat.stress_extrema()
    e = flat.stress_extrema(region=((-0.2, 0.2), (-0.3, -0.01)))
    assert e.max_shear.Y <= -0.01 and np.isfinite(e.max_shear.value)
    r, a, _ = _hertz()
    for region in (((1.0, -1.0), (-1.0, 0.0)), ((-1.0, 1.0), (-1.0, 0.5)),
                   ((-1.0, np.nan), (-1.0, 0.0)), "everywhere"):
        with pytest.raises(contact.ContactInputError, match="region"):
            r.stress_extrema(region=region)
    with pytest.raises(contact.ContactInputError, match="3 x 3"):
        r.stress_extrema(grid=(2, 40))


def test_result_without_material_says_so():
    from dataclasses import replace
    r, a, _ = _hertz()
    bare = replace(r, material=None)
    with pytest.raises(contact.ContactInputError, match="no material"):
        bare.stress(0.0, -a)


def test_default_region_scales_with_the_zones_not_the_gap_between_them():
    """Two narrow zones far apart: the field varies within about a zone's width of the
    surface, so the default region is 3 x the largest zone half-width deep (one zone: its
    half-width) and reaches that far beyond the outer ends."""
    w = contact.ProfilePunch(lambda X: 0.2 * X ** 3 - 0.2 * X, face=(-2.0, 2.0))
    r = contact.solve(contact.zhou2014(), w, load=0.02, speed=0.3)
    assert len(r.zones) == 2
    a = max(z.width for z in r.zones) / 2
    assert r.zone_scale == a and a < 0.1 * (r.zones[1].ends[1] - r.zones[0].ends[0])
    e = r.stress_extrema()
    (x0, x1), (y0, y1) = e.region
    assert (x0, x1, y0, y1) == (r.zones[0].ends[0] - a, r.zones[1].ends[1] + a, -3 * a, 0.0)
    # against a finer search of the same region: the default grid resolves the zones
    fine = r.stress_extrema(region=e.region, grid=(401, 121))
    assert e.max_shear.value == pytest.approx(fine.max_shear.value, rel=1e-9)
    hertz, _, _ = _hertz()
    assert hertz.zone_scale == hertz.half_width
