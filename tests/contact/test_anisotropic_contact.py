"""Tests of :func:`contact.solve`, :func:`contact.load_curve` and :func:`contact.solve_batch`
on :class:`contact.Anisotropic` (the material protocol, with the couplings M12, M21, M22).

References, each independent of the code under test:
  * aligned orthotropic materials (the paper's, an isotropic one): the same contact through
    :class:`contact.Orthotropic`, whose constants are the closed forms of
    :mod:`contact.constants` (Zhou, Lee & Jang 2014, eqs. (4.4)-(4.6), through eta1 eta2 and
    eta1 + eta2), not the Stroh sign function of :mod:`contact.anisotropic`;
  * a cubic crystal turned by 45 degrees about Z: the plane orthotropic material of the
    tensor transformation in closed form, C11' = C22' = (C11 + C12)/2 + C44,
    C12' = (C11 + C12)/2 - C44, C66' = (C11 - C12)/2 (Ting, Anisotropic Elasticity 1996,
    ch. 2, the cubic material in a rotated frame), solved as :class:`contact.Orthotropic`;
  * a ply turned by 30 degrees about Z, whose couplings M12, M21, M22 do not vanish: the
    constants from the state-space reference of ``tests/reference/stroh_reference.py``
    (ordered Schur decomposition of the equations of motion, not the Stroh state); the
    solve against the full surface response (every entry of the dv/dX and sigma_XX rows
    applied to (q, p, r) = (mu_f p, p, 0), Hc[p] from the solution's Cauchy transform), the
    end exponents against Muskhelishvili's cot(pi alpha) = -a/b (Singular Integral
    Equations 1953, ch. 10) and, without friction, the Hertz half-width
    a^2 = -2 N11 P R / pi (Johnson, Contact Mechanics 1985, eq. (4.45) with N11 for
    -(1 - nu^2) 2 / E) evaluated here;
  * mirror symmetry: the stiffness tensor is even under -I, so a rotation by 180 degrees
    about Z acts on it as the reflection Z -> -Z, which leaves the plane problem as it is
    (the same contact), and one about X or Y as the reflection X -> -X, which maps the
    contact of the face H(X) sliding one way onto that of H(-X) sliding the other way
    (mirrored: p(X) -> p(-X), the exponents swapped, N's kept, M's negated).
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import contact
from contact import Anisotropic
from contact.errors import ContactInputError, FrictionError, MaterialError, SpeedError
from stroh_reference import state_space_response

# --------------------------------------------------------------------------
# materials and punches
# --------------------------------------------------------------------------
#: Out-of-plane stiffnesses that leave an aligned material's in-plane response alone (C44,
#: C55 above C66: the shear wave polarised along Z does not set c_L).
ZHOU_OUT = dict(C13=4.0, C23=3.0, C33=12.0, C44=6.0, C55=7.0)
ISO_OUT = dict(C13=1.0, C23=1.0, C33=3.0, C44=1.0, C55=1.0)
ALIGNED = {
    "zhou2014": (contact.zhou2014(), ZHOU_OUT),
    "isotropic": (contact.Isotropic(2.5, 0.25), ISO_OUT),
}

#: A triclinic stiffness (all 21 constants nonzero, positive definite), as in
#: tests/contact/test_anisotropic.py.
TRICLINIC = np.array([
    [10.0, 4.0, 3.5, 0.6, -0.8, 1.1],
    [4.0, 12.0, 3.0, -0.7, 0.5, -0.9],
    [3.5, 3.0, 9.0, 0.4, 0.3, -0.5],
    [0.6, -0.7, 0.4, 3.2, 0.35, -0.25],
    [-0.8, 0.5, 0.3, 0.35, 2.8, 0.3],
    [1.1, -0.9, -0.5, -0.25, 0.3, 3.5],
])


def _exp_slope(X):
    return (np.exp(X) - 1.0) / 50.0


def _exp_height(X):
    return (np.exp(X) - X) / 50.0


def _exp_slope_mirrored(X):
    return -_exp_slope(-np.asarray(X, dtype=float))


def _exp_height_mirrored(X):
    return _exp_height(-np.asarray(X, dtype=float))


#: An asymmetric smooth face with two free ends (adaptive n: the full continuation).
PROFILE = contact.ProfilePunch(_exp_slope, height=_exp_height, face=(-3.0, 3.0))
PROFILE_MIRRORED = contact.ProfilePunch(_exp_slope_mirrored, height=_exp_height_mirrored,
                                       face=(-3.0, 3.0))

PUNCHES = {
    "flat": contact.FlatPunch(0.5),
    "triangular": contact.TriangularPunch(0.1),
    "parabolic": contact.ParabolicPunch(10.0),
    "cylindrical": contact.CylindricalPunch(100.0),
    "profile": PROFILE,
}
LOAD = 0.02


def aligned(name) -> tuple[contact.Orthotropic, Anisotropic]:
    plane, out = ALIGNED[name]
    return plane, Anisotropic.from_orthotropic(plane, **out)


@pytest.fixture(scope="module")
def ply():
    """The paper's material with out-of-plane constants, turned by 30 degrees about Z (its
    stiff direction 30 degrees off the sliding direction): monoclinic about Z = 0, p and q
    coupled (M12, M21, M22 != 0)."""
    return aligned("zhou2014")[1].rotated(Rotation.from_euler("z", 30.0, degrees=True))


@pytest.fixture(scope="module")
def triclinic():
    return Anisotropic(TRICLINIC)


# --------------------------------------------------------------------------
# comparisons
# --------------------------------------------------------------------------
def zone_points(zone, m=9):
    """m interior points of a zone (Chebyshev, away from the ends)."""
    u = np.cos(np.pi * (np.arange(m) + 0.5) / m)
    return zone.points(u)


def rel(a, b) -> float:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.abs(a - b).max() / max(np.abs(b).max(), np.finfo(float).tiny))


def contact_difference(r, ref, mirrored=False) -> float:
    """The largest relative difference between two contacts: ends (over the width),
    exponents, zone loads, pressure and sigma_XX at interior points (over their largest),
    SIFs (each over its own size).  ``mirrored``: r is ref reflected X -> -X."""
    assert len(r.zones) == len(ref.zones)
    flip = -1.0 if mirrored else 1.0
    zones_ref = ref.zones[::-1] if mirrored else ref.zones
    errs = []
    for z, zr in zip(r.zones, zones_ref):
        kinds_ref = zr.kinds[::-1] if mirrored else zr.kinds
        assert z.kinds == kinds_ref
        ends_ref = sorted(flip * e for e in zr.ends)
        errs.append(max(abs(e - f) for e, f in zip(z.ends, ends_ref)) / zr.width)
        ab_ref = (zr.beta, zr.alpha) if mirrored else (zr.alpha, zr.beta)
        errs.append(max(abs(z.alpha - ab_ref[0]), abs(z.beta - ab_ref[1])))
        errs.append(abs(z.load - zr.load) / zr.load)
        X = zone_points(zr)
        errs.append(rel(r.pressure(flip * X), ref.pressure(X)))
        sif_ref = {({"left": "right", "right": "left"}[k] if mirrored else k): v
                   for k, v in zr.sif.items()}
        assert set(z.sif) == set(sif_ref)
        errs += [abs(z.sif[k] - v) / abs(v) for k, v in sif_ref.items()]
    # sigma_XX inside and beside the zones
    lo, hi = ref.zones[0].ends[0], ref.zones[-1].ends[1]
    X = np.concatenate([np.concatenate([zone_points(z) for z in ref.zones]),
                        np.linspace(lo - 0.5 * (hi - lo), lo - 0.01 * (hi - lo), 5),
                        np.linspace(hi + 0.01 * (hi - lo), hi + 0.5 * (hi - lo), 5)])
    errs.append(rel(r.sigma_xx(flip * X), ref.sigma_xx(X)))
    return max(errs)


def full_response_check(r, response, scale_points=9):
    """dv/dX and sigma_XX on the surface from every entry of the response's rows applied
    to (q, p, r) = (mu_f p, p, 0), Hc[p] from the solution: (max abs(dv/dX - H') over the
    size of the terms, max abs(sigma_XX - r.sigma_xx) over its size).  The size of the
    Hilbert term is at least abs(b) max(p) (Hc[p] vanishes by symmetry under a frictionless
    flat punch, its rounding does not)."""
    s = np.array([r.mu_f, 1.0, 0.0])
    slope_err, sigma_err = 0.0, 0.0
    for z in r.zones:
        X = zone_points(z, scale_points)
        p, hp = r.pressure(X), r.hilbert_pressure(X)
        local, hilbert = response.slope_local[1] @ s * p, response.slope_hilbert[1] @ s * hp
        H = r.punch.slope(X)
        b = response.slope_hilbert[1] @ s
        scale = max(np.abs(H).max(), np.abs(local).max(), np.abs(hilbert).max(),
                    abs(b) * np.abs(p).max())
        slope_err = max(slope_err, float(np.abs(local + hilbert - H).max() / scale))
        sigma = response.stress_local[0] @ s * p + response.stress_hilbert[0] @ s * hp
        sigma_err = max(sigma_err, rel(r.sigma_xx(X), sigma))
    return slope_err, sigma_err


# --------------------------------------------------------------------------
# (a) aligned orthotropic materials: the Orthotropic contact
# --------------------------------------------------------------------------
@pytest.mark.parametrize("punch", PUNCHES)
@pytest.mark.parametrize("name", ALIGNED)
def test_aligned_material_gives_the_orthotropic_contact(name, punch):
    """From first touch to the load, static and at c = 0.6 (c_R = 0.9936 and 0.9194),
    friction 0 and 0.3, both directions: the same zones, ends, exponents, pressure,
    sigma_XX and SIFs to 1e-12."""
    plane, m = aligned(name)
    p = PUNCHES[punch]
    worst = 0.0
    for speed in (0.0, 0.6):
        assert m.surface_constants(speed).M12 == 0.0        # mirror plane X = 0: exactly
        for friction in (0.0, 0.3):
            for direction in (-1, 1):
                kw = dict(load=LOAD, speed=speed, friction=friction, direction=direction)
                r, ref = contact.solve(m, p, **kw), contact.solve(plane, p, **kw)
                assert r.material is m and r.residual < 1e-11
                worst = max(worst, contact_difference(r, ref))
    assert worst <= 1e-12, worst


def test_aligned_material_closed_forms():
    """method="closed_form" takes the aligned material (M's exactly 0) and agrees with the
    Orthotropic's closed form."""
    plane, m = aligned("zhou2014")
    for punch in ("flat", "triangular", "parabolic", "cylindrical"):
        kw = dict(load=LOAD, speed=0.6, friction=0.3, method="closed_form")
        r = contact.solve(m, PUNCHES[punch], **kw)
        assert contact_difference(r, contact.solve(plane, PUNCHES[punch], **kw)) <= 1e-12


# --------------------------------------------------------------------------
# (b) a cubic crystal turned by 45 degrees
# --------------------------------------------------------------------------
def test_cubic_crystal_turned_45_degrees_solves_as_its_orthotropic_material():
    C11, C12, C44 = 168.4, 121.4, 75.4              # copper, GPa
    C = np.zeros((6, 6))
    C[:3, :3] = C12
    C[[0, 1, 2], [0, 1, 2]] = C11
    C[[3, 4, 5], [3, 4, 5]] = C44
    m = Anisotropic(C).rotated(Rotation.from_euler("z", 45.0, degrees=True))
    # Orthotropic(C11, C12, C22, C33): C33 is the in-plane shear stiffness (C66 here)
    plane = contact.Orthotropic((C11 + C12) / 2 + C44, (C11 + C12) / 2 - C44,
                                (C11 + C12) / 2 + C44, (C11 - C12) / 2)
    c = 0.5 * contact.rayleigh_speed(plane)
    sc = m.surface_constants(c)
    # the couplings are rounding (the rotated matrix carries C16 ~ 1e-14)
    assert abs(sc.M12) <= 1e-14 * abs(sc.N11)
    assert max(abs(sc.M21), abs(sc.M22)) <= 1e-14 * abs(sc.N22)
    worst = 0.0
    for punch in ("flat", "cylindrical", "profile"):
        for friction in (0.0, 0.3):
            for direction in (-1, 1):
                kw = dict(load=10.0 * LOAD / C44, speed=c, friction=friction,
                          direction=direction)
                r = contact.solve(m, PUNCHES[punch], **kw)
                worst = max(worst, contact_difference(
                    r, contact.solve(plane, PUNCHES[punch], **kw)))
    assert worst <= 1e-12, worst
    # closed forms: couplings at rounding count as none
    kw = dict(load=LOAD, speed=c, friction=0.3, method="closed_form")
    r = contact.solve(m, PUNCHES["cylindrical"], **kw)
    assert contact_difference(r, contact.solve(plane, PUNCHES["cylindrical"], **kw)) <= 1e-12


# --------------------------------------------------------------------------
# (c) a ply off its axes: M12, M21, M22 != 0
# --------------------------------------------------------------------------
@pytest.mark.parametrize("fraction", (0.0, 0.5, 0.9))
def test_ply_couplings_against_state_space(ply, fraction):
    """N11, N12, N21, N22 and the couplings M12 = dv/dX per Hc[q], M21 = sigma_XX per
    Hc[p], M22 = sigma_XX per q from the Schur route (Hilbert part = imaginary part at
    k = 1) to 1e-12 of their kind's scale; the couplings are not small."""
    c = fraction * ply.rayleigh_speed()
    sc = contact.surface_constants(ply, c)
    slope, stress, _, _ = state_space_response(ply.C, c)
    slope_scale, stress_scale = np.abs(slope).max(), np.abs(stress).max()
    for value, ref, scale in ((sc.N11, slope.imag[1, 1], slope_scale),
                              (sc.N12, slope.real[1, 0], slope_scale),
                              (sc.M12, slope.imag[1, 0], slope_scale),
                              (sc.N21, stress.real[0, 1], stress_scale),
                              (sc.N22, stress.imag[0, 0], stress_scale),
                              (sc.M21, stress.imag[0, 1], stress_scale),
                              (sc.M22, stress.real[0, 0], stress_scale)):
        assert abs(value - ref) <= 1e-12 * scale
    assert abs(sc.M12) > 0.2 * abs(sc.N11)
    assert min(abs(sc.M21), abs(sc.M22)) > 0.01 * stress_scale
    # the reference itself: no local part of dv/dX under p (reciprocity)
    assert abs(slope.real[1, 1]) <= 1e-13 * slope_scale
    assert (sc.eta_product, sc.eta_sum, sc.rayleigh_denominator) == (None, None, None)
    assert (sc.c, sc.rayleigh_speed) == (c, ply.rayleigh_speed())


@pytest.mark.parametrize("fraction", (0.0, 0.6))
def test_triclinic_slopes_are_reciprocal_in_the_reference(triclinic, fraction):
    """The local part of the slopes is antisymmetric (so dv/dX has no local term in p) and
    the Hilbert part symmetric, in the Schur reference itself (Ting 1996, ch. 7), plain and
    turned; and the constants of the contact equation are those entries."""
    for m in (triclinic, triclinic.rotated(Rotation.from_euler("zxz", [20, 35, -50],
                                                               degrees=True))):
        c = fraction * m.rayleigh_speed()
        slope = state_space_response(m.C, c)[0]
        scale = np.abs(slope).max()
        assert np.abs(slope.real + slope.real.T).max() <= 1e-13 * scale
        assert np.abs(slope.imag - slope.imag.T).max() <= 1e-13 * scale
        sc = m.surface_constants(c)
        assert abs(sc.M12 - slope.imag[1, 0]) <= 1e-12 * scale
        assert abs(sc.N12 - slope.real[1, 0]) <= 1e-12 * scale


@pytest.mark.parametrize("punch", ["flat", "triangular", "cylindrical", "profile"])
def test_ply_solve_against_the_full_response(ply, punch):
    """The pressure solves a p + b Hc[p] = H' (residual), and, independently, the whole
    dv/dX row of the surface response applied to (mu_f p, p, 0) with the solution's
    Hc[p] gives the punch's slope; sigma_XX is the whole sigma_XX row (with M21 Hc[p]
    even without friction)."""
    c = 0.5 * ply.rayleigh_speed()
    response = ply.surface_response(c)
    for friction in (0.0, 0.3):
        for direction in (-1, 1):
            r = contact.solve(ply, PUNCHES[punch], load=LOAD, speed=c, friction=friction,
                              direction=direction)
            assert r.residual <= 1e-12 and r.load_check <= 1e-12
            slope_err, sigma_err = full_response_check(r, response)
            assert slope_err <= 1e-11, (friction, direction, slope_err)
            assert sigma_err <= 1e-11, (friction, direction, sigma_err)


def test_ply_flat_punch_exponents(ply):
    """cot(pi alpha) = -a/b with a = N12 mu_f and b = N11 + M12 mu_f, from the Schur
    reference, alpha + beta = -1 (two corners); the coupling moves alpha off the value
    b = N11 would give."""
    c = 0.5 * ply.rayleigh_speed()
    slope = state_space_response(ply.C, c)[0]
    for direction in (-1, 1):
        mu_f = -direction * 0.3
        a, b = slope.real[1, 0] * mu_f, slope.imag[1, 1] + slope.imag[1, 0] * mu_f
        r = contact.solve(ply, PUNCHES["flat"], load=LOAD, speed=c, friction=0.3,
                          direction=direction)
        assert r.zones[0].kinds == ("corner", "corner")
        assert 1.0 / math.tan(math.pi * r.alpha) == pytest.approx(-a / b, rel=1e-12)
        assert r.alpha + r.beta == pytest.approx(-1.0, abs=1e-14)
        assert -1.0 < r.alpha < 0.0
        uncoupled = math.atan2(1.0, -a / slope.imag[1, 1]) / math.pi - 1.0    # b = N11
        assert abs(r.alpha - uncoupled) > 1e-3


def test_ply_without_friction_is_hertz_with_n11(ply):
    """mu = 0 on a material turned about Z: a = 0 and b = N11 (the coupling multiplies
    mu_f), so alpha = beta = 1/2, the pressure is symmetric, the direction does not
    matter, and the cylinder's half-width is Hertz's a^2 = -2 N11 P R / pi with N11 of the
    Schur reference."""
    c = 0.5 * ply.rayleigh_speed()
    sc = contact.surface_constants(ply, c)
    assert sc.M12 != 0.0 and sc.equation_coefficients(0.0) == (0.0, sc.N11)
    R = 100.0
    r = contact.solve(ply, contact.CylindricalPunch(R), load=LOAD, speed=c)
    r2 = contact.solve(ply, contact.CylindricalPunch(R), load=LOAD, speed=c, direction=1)
    assert (r.alpha, r.beta) == (0.5, 0.5) and r.ends == r2.ends
    N11 = state_space_response(ply.C, c)[0].imag[1, 1]
    assert r.half_width == pytest.approx(math.sqrt(-2.0 * N11 * LOAD * R / math.pi),
                                         rel=1e-12)
    assert abs(r.center) <= 1e-13 * r.half_width
    X = zone_points(r.zones[0])
    assert rel(r.pressure(X), r.pressure(-X)) <= 1e-13
    flat = contact.solve(ply, PUNCHES["flat"], load=LOAD, speed=c)
    assert (flat.alpha, flat.beta) == (-0.5, -0.5)


# --------------------------------------------------------------------------
# (d) symmetry operations
# --------------------------------------------------------------------------
def test_half_turn_about_z_changes_nothing(triclinic):
    """R_z(180) = -diag(1, 1, -1): on the stiffness, the reflection Z -> -Z, which the plane
    problem (r = 0, nothing depends on Z) does not see: the same contact (to 1e-12) for a
    material whose stiffness it changes."""
    m = triclinic.rotated(Rotation.from_euler("z", 180.0, degrees=True))
    assert np.abs(m.C - triclinic.C).max() > 0.5
    c = 0.5 * triclinic.rayleigh_speed()
    assert m.rayleigh_speed() == pytest.approx(triclinic.rayleigh_speed(), rel=1e-12)
    for punch in ("cylindrical", "profile"):
        for direction in (-1, 1):
            kw = dict(load=LOAD, speed=c, friction=0.3, direction=direction)
            assert contact_difference(contact.solve(m, PUNCHES[punch], **kw),
                                      contact.solve(triclinic, PUNCHES[punch], **kw)) <= 1e-12


@pytest.mark.parametrize("axis", ["x", "y"])
def test_half_turn_about_x_or_y_mirrors_the_contact(triclinic, axis):
    """R_x(180) = -diag(-1, 1, 1) and R_y(180) = -diag(1, -1, 1) ... on the stiffness both
    are the reflection X -> -X (R_y(180) directly: X -> -X, Z -> -Z with Y kept; R_x(180)
    is R_y(180) R_z(180)).  The turned material under the face H(X) sliding toward -X is the
    mirror image of the plain one under H(-X) sliding toward +X: ends and exponents swapped,
    p(X) -> p(-X), sigma_XX(X) -> sigma_XX(-X) (to 1e-12); the N's are kept and the M's
    change sign."""
    m = triclinic.rotated(Rotation.from_euler(axis, 180.0, degrees=True))
    c = 0.5 * triclinic.rayleigh_speed()
    sc, sc0 = m.surface_constants(c), triclinic.surface_constants(c)
    for name in ("N11", "N12", "N21", "N22"):
        assert getattr(sc, name) == pytest.approx(getattr(sc0, name), rel=1e-12)
    for name in ("M12", "M21", "M22"):
        assert getattr(sc, name) == pytest.approx(-getattr(sc0, name), rel=1e-12)
        assert abs(getattr(sc0, name)) > 1e-3
    cases = (("cylindrical", "cylindrical"), ("triangular", None), ("profile", None))
    for punch, mirrored in cases:
        p = PUNCHES[punch]
        if punch == "triangular":       # its face X >= 0 mirrored: the corner on the right
            q = contact.ProfilePunch(lambda X: -0.1 + 0.0 * X, face=(-np.inf, 0.0))
        else:
            q = p if mirrored else PROFILE_MIRRORED
        for direction in (-1, 1):
            for friction in (0.0, 0.3):
                r = contact.solve(m, p, load=LOAD, speed=c, friction=friction,
                                  direction=direction)
                ref = contact.solve(triclinic, q, load=LOAD, speed=c, friction=friction,
                                    direction=-direction)
                assert contact_difference(r, ref, mirrored=True) <= 1e-12, (punch, direction)


# --------------------------------------------------------------------------
# (e) what is refused
# --------------------------------------------------------------------------
def test_speed_at_or_beyond_rayleigh_is_refused(ply):
    """As for contact.Orthotropic: SpeedError from solve and surface_constants at c_R,
    between c_R and c_L, at c_L and beyond; negative or not finite."""
    plane, m = aligned("zhou2014")
    c_R, c_L = ply.rayleigh_speed(), ply.limiting_speed()
    assert c_R < c_L
    for material, speeds in ((ply, (c_R, 0.5 * (c_R + c_L), c_L, 2.0)),
                             (m, (m.rayleigh_speed(), 1.5)),
                             (plane, (contact.rayleigh_speed(plane), 1.5))):
        for c in speeds + (-0.1, float("nan")):
            with pytest.raises(SpeedError):
                contact.solve(material, PUNCHES["cylindrical"], load=LOAD, speed=c)
            with pytest.raises(SpeedError):
                contact.surface_constants(material, c)
        with pytest.raises(SpeedError, match="Rayleigh speed"):
            contact.solve(material, PUNCHES["cylindrical"], load=LOAD, speed=speeds[0])


def test_friction_that_leaves_b_nonnegative_is_refused(ply):
    """b = N11 + M12 mu_f >= 0 from friction abs(N11 / M12) on, in the direction where
    M12 mu_f > 0 (mu_f = -direction * friction): FrictionError saying where; the other
    direction solves (b more negative)."""
    c = 0.5 * ply.rayleigh_speed()
    sc = contact.surface_constants(ply, c)
    limit = -sc.N11 / abs(sc.M12)
    bad_direction = -1 if sc.M12 > 0 else 1
    with pytest.raises(FrictionError, match=rf"stops sinking at friction = abs\(N11 / M12\) "
                                            rf"= {limit:.6g}"):
        contact.solve(ply, PUNCHES["cylindrical"], load=LOAD, speed=c,
                      friction=1.01 * limit, direction=bad_direction)
    r = contact.solve(ply, PUNCHES["cylindrical"], load=LOAD, speed=c,
                      friction=0.99 * limit, direction=bad_direction)
    assert r.residual < 1e-10
    r = contact.solve(ply, PUNCHES["cylindrical"], load=LOAD, speed=c,
                      friction=1.01 * limit, direction=-bad_direction)
    a, b = sc.equation_coefficients(r.mu_f)
    assert b < sc.N11 < 0.0 and r.residual < 1e-10
    out = contact.solve_batch(ply, PUNCHES["cylindrical"], load=LOAD, speed=c,
                              friction=[0.3, 1.01 * limit], direction=bad_direction,
                              errors="return")
    assert isinstance(out[1], FrictionError) and out[0].residual < 1e-12


class Coupled:
    """A material of one's own: an orthotropic one with a coupling M12 (and, optionally,
    anything else replaced in its constants)."""

    def __init__(self, inner, **changes):
        self.inner, self.changes = inner, changes

    def surface_constants(self, c):
        return dataclasses.replace(self.inner.surface_constants(c), **self.changes)

    def rayleigh_speed(self):
        return self.inner.rayleigh_speed()

    def limiting_speed(self):
        return self.inner.limiting_speed()

    def relative_speed(self, V):
        return self.inner.relative_speed(V)

    def half_space_modes(self, c):
        return self.inner.half_space_modes(c)


def test_friction_refused_through_a_users_material():
    """b >= 0 and, just short of it, b so small against a that an exponent rounds to
    -1 or 1: FrictionError either way, with the friction allowed."""
    iso = contact.Isotropic(2.5, 0.25)                  # N11 = -0.75, N12 = 0.25 at rest
    with pytest.raises(FrictionError, match=r"b = N11 \+ M12 mu_f = 0\.75 .*friction = abs"
                                            r"\(N11 / M12\) = 0\.25"):
        contact.solve(Coupled(iso, M12=3.0), PUNCHES["cylindrical"], load=LOAD, speed=0.0,
                      friction=0.5)
    # N11 = -1, N12 = 1, mu_f = 0.5: b = -1 + 0.5 M12 = -2^-53, |b / a| = 2^-52 < pi 2^-53
    m = Coupled(iso, N11=-1.0, N12=1.0, M12=2.0 - 2.0 ** -52)
    with pytest.raises(FrictionError, match="within rounding of -1 or 1.*friction below "
                                            "about 0.5"):
        contact.solve(m, PUNCHES["cylindrical"], load=LOAD, speed=0.0, friction=0.5)
    with pytest.raises(MaterialError, match="M21 of Coupled.surface_constants"):
        contact.solve(Coupled(iso, M21=float("nan")), PUNCHES["cylindrical"], load=LOAD,
                      speed=0.0)


def test_closed_form_refused_for_a_coupled_material(ply):
    c = 0.5 * ply.rayleigh_speed()
    for friction in (0.0, 0.3):
        with pytest.raises(ContactInputError, match=r'closed_form" holds for a material '
                                                    r'with the mirror plane X = 0.*M12 = '):
            contact.solve(ply, PUNCHES["cylindrical"], load=LOAD, speed=c,
                          friction=friction, method="closed_form")


# --------------------------------------------------------------------------
# (f) load curves and batches
# --------------------------------------------------------------------------
def test_load_curve_and_batch_agree_with_solve(ply):
    """load_curve through three loads and solve_batch over friction x direction (the
    lockstep first step, residuals in one pass) give what solve gives, case by case."""
    c = 0.5 * ply.rayleigh_speed()
    loads = [0.005, 0.01, 0.02]
    curve = contact.load_curve(ply, PROFILE, loads, speed=c, friction=0.3)
    for P, r in zip(loads, curve):
        ref = contact.solve(ply, PROFILE, load=P, speed=c, friction=0.3)
        assert contact_difference(r, ref) <= 1e-12
    frictions = np.array([[0.0], [0.2], [0.4]])
    directions = np.array([-1, 1])
    for punch in ("cylindrical", "flat", "triangular"):
        out = contact.solve_batch(ply, PUNCHES[punch], load=LOAD, speed=c,
                                  friction=frictions, direction=directions, residual=True)
        cases = [(f, d) for f in frictions.ravel() for d in directions]
        for r, (f, d) in zip(out, cases):
            ref = contact.solve(ply, PUNCHES[punch], load=LOAD, speed=c, friction=f,
                                direction=d)
            assert contact_difference(r, ref) <= 1e-12
            assert r.residual <= 1e-12 and ref.residual <= 1e-12
