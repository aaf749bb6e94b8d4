"""The field under the surface of a moving anisotropic half-space: ``contact.stroh_modes``.

References, each independent of the module's route (the Stroh matrix's sign function, the
3x3 restriction A of the Stroh matrix to the decaying modes and its matrix function in
Newton's form over Cauchy transforms):

  * the plane orthotropic field of ``contact.subsurface.HalfSpaceModes`` (Zhou, Lee & Jang
    2014: the characteristic roots of eq. (3.1), modal vectors and divided differences;
    validated in tests/contact/test_subsurface.py), for an aligned orthotropic material;
    its sigma_zz from plane strain, sigma_zz = C13 eps_xx + C23 eps_yy with the strains from
    the in-plane stresses through the in-plane stiffness;
  * Flamant's line loads on the static isotropic half-space (Johnson, Contact Mechanics
    1985, eqs. (2.15)-(2.19)): a radial stress only, sigma_rr = -(2 / (pi r)) F . e_r for
    the force F on the body, and in plane strain sigma_zz = nu (sigma_xx + sigma_yy); the
    moving isotropic line loads of tests/reference/fourier_stress_reference.py (potentials,
    Cole & Huth type); McEwen's (1949) Hertz field (Johnson 1985, Sec. 7.1), same file;
  * numerical Fourier inversion of the state-space solution, wavenumber by wavenumber, with
    ordered Schur bases of the (u, u') system (tests/reference/stroh_fourier_reference.py)
    under a Gaussian pressure, whose Cauchy transform is the Faddeeva function;
  * symmetry: a rotation of an isotropic stiffness changes nothing; a half-turn about Y
    mirrors the field; a material with the mirror plane Z = 0 has no antiplane stresses.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from fourier_stress_reference import hertz_cauchy, isotropic_moving_flamant, mcewen_hertz
from scipy.optimize import minimize
from scipy.spatial.transform import Rotation
from stroh_fourier_reference import GaussianFourierField, gaussian_cauchy

import contact
from contact.anisotropic import Anisotropic
from contact.errors import ContactInputError, MaterialError, SpeedError, StressPointError
from contact.stroh_modes import CLUSTER, StrohModes, stroh_modes
from contact.subsurface import half_space_stress, modes_points

#: The triclinic stiffness of tests/contact/test_anisotropic.py (all 21 constants nonzero,
#: positive definite).
TRICLINIC = np.array([
    [10.0, 4.0, 3.5, 0.6, -0.8, 1.1],
    [4.0, 12.0, 3.0, -0.7, 0.5, -0.9],
    [3.5, 3.0, 9.0, 0.4, 0.3, -0.5],
    [0.6, -0.7, 0.4, 3.2, 0.35, -0.25],
    [-0.8, 0.5, 0.3, 0.35, 2.8, 0.3],
    [1.1, -0.9, -0.5, -0.25, 0.3, 3.5],
])
OUT_OF_PLANE = dict(C13=4.0, C23=3.0, C33=12.0, C44=6.0, C55=7.0)
FRACTIONS = (0.0, 0.5, 0.9)        # c / c_R

# points over depth, shallow to deep, inside and outside the loaded width (1 or a)
X = np.array([0.0, 0.3, -0.8, 1.2, -2.0, 0.1, 3.0, 0.0, -0.4])
Y = np.array([-0.01, -0.1, -0.3, -0.5, -1.0, -2.0, -0.2, -5.0, -20.0])
E_ISO, NU_ISO = 2.5, 0.25


def voigt(field) -> np.ndarray:
    """The six stresses of a StressField in Voigt order (XX, YY, ZZ, YZ, ZX, XY)."""
    return np.stack([field.sigma_xx, field.sigma_yy, field.sigma_zz, field.sigma_yz,
                     field.sigma_xz, field.sigma_xy])


def line_load(P):
    """C(z) of the line load P delta(X): -P / (pi z)."""
    return lambda z: -P / (np.pi * z)


def flamant(X, Y, P, Q, nu):
    """Static isotropic line loads p = P delta, q = Q delta (sigma_YY(X, 0) = -p,
    sigma_XY(X, 0) = -q: the force on the body is F = (-Q, -P)): Johnson (1985), eqs.
    (2.15)-(2.19), sigma_rr = -(2 / (pi r)) F . e_r, e_r = (X, Y) / r, the only stress in the
    plane; sigma_zz = nu (sigma_xx + sigma_yy) (plane strain).  Voigt order, and sigma_rr."""
    r2 = X * X + Y * Y
    srr = 2.0 * (Q * X + P * Y) / (np.pi * r2)
    ex, ey = X / np.sqrt(r2), Y / np.sqrt(r2)
    z = np.zeros_like(X)
    return np.stack([srr * ex * ex, srr * ey * ey, nu * srr, z, z, srr * ex * ey]), srr


def field_of(material, c, cauchy_p, cauchy_q=None, q_ratio=None, x=X, y=Y):
    """The six stresses through stroh_modes directly (Voigt order)."""
    modes = stroh_modes(material, c)
    Z = modes.points(x, y)
    Cp = [cauchy_p(z) for z in Z]
    Cq = None if cauchy_q is None else [cauchy_q(z) for z in Z]
    return modes.voigt(Cp, Cq, q_ratio)


def rel(a, b, scale=None) -> float:
    scale = np.abs(b).max() if scale is None else scale
    return float(np.abs(np.asarray(a) - np.asarray(b)).max() / scale)


# --------------------------------------------------------------------------
# (a) an aligned orthotropic material: the plane model's field
# --------------------------------------------------------------------------
@pytest.mark.parametrize("fraction", FRACTIONS)
def test_aligned_orthotropic_matches_plane_model(fraction):
    """zhou2014 with out-of-plane constants at c = 0, 0.5, 0.9 c_R: sigma_xx, sigma_yy,
    sigma_xy equal HalfSpaceModes' under a normal and a tangential line load (separately,
    Cq) and under Hertz p with q = 0.3 p, to 1e-12 of the largest stress (measured
    8e-15);
    sigma_zz is the plane-strain C13 eps_xx + C23 eps_yy, sigma_yz = sigma_xz = 0."""
    plane = contact.zhou2014()
    m = Anisotropic.from_orthotropic(plane, **OUT_OF_PLANE)
    c = fraction * contact.rayleigh_speed(plane)
    ours, theirs = stroh_modes(m, c), plane.half_space_modes(c)
    hertz = hertz_cauchy(1.0, 1.0)
    cases = [(line_load(1.0), line_load(-0.6), None), (hertz, None, 0.3)]
    for cauchy_p, cauchy_q, q_ratio in cases:
        Zo, Zt = ours.points(X, Y), theirs.points(X, Y)
        args_o = ([cauchy_p(z) for z in Zo],
                  None if cauchy_q is None else [cauchy_q(z) for z in Zo], q_ratio)
        args_t = ([cauchy_p(z) for z in Zt],
                  None if cauchy_q is None else [cauchy_q(z) for z in Zt], q_ratio)
        got = np.array(ours.stresses(*args_o))
        want = np.array(theirs.stresses(*args_t))
        scale = np.abs(want).max()
        assert rel(got, want, scale) <= 1e-12
        szz, syz, sxz = ours.out_of_plane(*args_o)
        eps = np.linalg.solve([[plane.C11, plane.C12], [plane.C12, plane.C22]],
                              want[:2].reshape(2, -1))
        assert rel(szz, OUT_OF_PLANE["C13"] * eps[0] + OUT_OF_PLANE["C23"] * eps[1],
                   scale) <= 1e-12
        assert np.abs(syz).max() <= 1e-14 * scale and np.abs(sxz).max() <= 1e-14 * scale


def test_half_space_stress_fills_out_of_plane():
    """half_space_stress: an Anisotropic material fills sigma_zz, sigma_yz, sigma_xz (and
    von_mises, tresca); the plane model leaves them None and refuses von Mises."""
    plane = contact.zhou2014()
    m = Anisotropic.from_orthotropic(plane, **OUT_OF_PLANE)
    f = half_space_stress(m, 0.3, X, Y, line_load(1.0), q_ratio=0.2)
    g = half_space_stress(plane, 0.3, X, Y, line_load(1.0), q_ratio=0.2)
    assert f.has_out_of_plane and not g.has_out_of_plane
    assert g.sigma_zz is None and g.sigma_yz is None and g.sigma_xz is None
    for name in ("sigma_xx", "sigma_yy", "sigma_xy"):
        assert rel(getattr(f, name), getattr(g, name), np.abs(g.sigma_yy).max()) <= 1e-12
    assert f.von_mises.shape == X.shape and np.all(f.tresca >= 0.0)
    for name in ("von_mises", "tresca", "principal_3d"):
        with pytest.raises(MaterialError, match="out-of-plane stresses"):
            getattr(g, name)
    # the modes as the protocol sees them, through the material itself
    modes = m.half_space_modes(0.3)
    assert isinstance(modes, StrohModes) and isinstance(modes, contact.MaterialModes)


# --------------------------------------------------------------------------
# (b) isotropic: Flamant, moving line loads, Hertz
# --------------------------------------------------------------------------
def test_isotropic_static_flamant():
    """Isotropic at rest (a triple root, one cluster): normal and tangential line loads
    vs Flamant (Johnson 1985, eqs. (2.15)-(2.19)) with sigma_zz = nu (sigma_xx + sigma_yy),
    relative to the local scale (P + Q) / r: <= 1e-13 (measured 1.7e-15); von Mises
    |sigma_rr| sqrt(1 - nu + nu^2) and Tresca |sigma_rr| / 2 (principal stresses sigma_rr,
    nu sigma_rr, 0)."""
    m = Anisotropic.isotropic(E_ISO, NU_ISO)
    assert stroh_modes(m, 0.0).clusters == ((0, 1, 2),)
    r = np.hypot(X, Y)
    for P, Q in ((1.7, 0.0), (0.0, -0.6), (1.7, -0.6)):
        f = half_space_stress(m, 0.0, X, Y, line_load(P), line_load(Q))
        want, srr = flamant(X, Y, P, Q, NU_ISO)
        assert np.all(np.abs(voigt(f) - want) <= 1e-13 * (abs(P) + abs(Q)) / r)
        tol = 1e-13 * (abs(P) + abs(Q)) / r
        assert np.all(np.abs(f.von_mises - np.abs(srr) * math.sqrt(1 - NU_ISO + NU_ISO ** 2))
                      <= 4 * tol)
        assert np.all(np.abs(f.tresca - 0.5 * np.abs(srr)) <= 4 * tol)


@pytest.mark.parametrize("c", [0.3, 0.6, 0.9])
def test_isotropic_moving_line_loads(c):
    """Isotropic moving (a double shear root: SV and SH; at c = 0.3 the dilatational root
    is within the clustering distance too): line loads vs the potential solution of
    fourier_stress_reference.isotropic_moving_flamant, with sigma_zz = nu (sigma_xx +
    sigma_yy), relative to (P + Q) / r: <= 1e-12 (measured 4e-15 at c = 0.3 and 0.6,
    6e-13 at 0.9, near c_R = 0.919, where the reference's Rayleigh function cancels)."""
    m = Anisotropic.isotropic(E_ISO, NU_ISO)
    modes = stroh_modes(m, c)
    assert sorted(len(cl) for cl in modes.clusters) == ([3] if c == 0.3 else [1, 2])
    P, Q = 1.3, 0.4
    got = field_of(m, c, line_load(P), line_load(Q))
    sxx, syy, sxy = isotropic_moving_flamant(E_ISO, NU_ISO, c, X, Y, P, Q)
    z = np.zeros_like(X)
    want = np.stack([sxx, syy, NU_ISO * (sxx + syy), z, z, sxy])
    assert np.all(np.abs(got - want) <= 1e-12 * (P + Q) / np.hypot(X, Y))


def test_isotropic_hertz_contact_result():
    """contact.solve with Anisotropic.isotropic and with contact.Isotropic: the same
    in-plane field under the cylinder with friction 0.3 to 1e-12 p0; the out-of-plane
    stresses on and below the surface obey sigma_zz = nu (sigma_xx + sigma_yy),
    sigma_yz = sigma_xz = 0; without friction the field matches McEwen (1949) to 1e-9 p0."""
    nu, mu = 0.3, 0.3
    kw = dict(load=0.01, speed=0.0, friction=mu)
    r_iso = contact.solve(contact.Isotropic(1.0, nu), contact.CylindricalPunch(1.0), **kw)
    r = contact.solve(Anisotropic.isotropic(1.0, nu), contact.CylindricalPunch(1.0), **kw)
    a, p0 = r.half_width, float(r.pressure(0.0))
    x = np.linspace(-2.0, 2.0, 9) * a
    y = np.array([0.0, -0.01, -0.5, -1.0, -2.5])[:, None] * a
    f, g = r.stress(x, y), r_iso.stress(x, y)
    for name in ("sigma_xx", "sigma_yy", "sigma_xy"):
        assert rel(getattr(f, name), getattr(g, name), p0) <= 1e-12
    assert rel(f.sigma_zz, nu * (f.sigma_xx + f.sigma_yy), p0) <= 1e-12
    assert np.abs(f.sigma_yz).max() <= 1e-14 * p0 and np.abs(f.sigma_xz).max() <= 1e-14 * p0
    # frictionless, p is Hertz's (with friction N12 shifts it): McEwen's closed form, Y < 0
    r = contact.solve(Anisotropic.isotropic(1.0, nu), contact.CylindricalPunch(1.0),
                      load=0.01, speed=0.0)
    a, p0 = r.half_width, float(r.pressure(0.0))
    x, y = x / r_iso.half_width * a, y[1:] / r_iso.half_width * a
    f = r.stress(x, y)
    for got, w in zip((f.sigma_xx, f.sigma_yy, f.sigma_xy), mcewen_hertz(x, y + 0 * x, p0, a)):
        assert rel(got, w, p0) <= 1e-9


def _mcewen_von_mises(x, z, nu, mu):
    """Minus the von Mises stress of McEwen's field (p0 = a = 1) at (x, -z), plane strain."""
    sxx, syy, sxy = mcewen_hertz(np.array([x]), np.array([-z]), 1.0, 1.0, mu)
    szz = nu * (sxx + syy)
    return -float(np.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2)
                          + 3.0 * sxy ** 2)[0])


def test_von_mises_extremum_frictionless_hertz():
    """stress_extrema(quantities=("von_mises", "tresca")) for the frictionless Hertz
    contact: the largest von Mises stress and its depth vs McEwen's closed form maximised
    by scipy (0.5575 p0 at 0.704 a on the axis for nu = 0.3), to 1e-6; the largest Tresca
    shear is the in-plane maximum shear here (0.300 p0 at 0.786 a: sigma_zz lies between
    the in-plane principal stresses); the quantities not asked for are None."""
    nu = 0.3
    r = contact.solve(Anisotropic.isotropic(1.0, nu), contact.CylindricalPunch(1.0),
                      load=0.01, speed=0.0)
    a, p0 = r.half_width, float(r.pressure(0.0))
    ex = r.stress_extrema(grid=(21, 21), quantities=("von_mises", "tresca"))
    assert ex.max_shear is None and ex.max_tension is None
    best = minimize(lambda v: _mcewen_von_mises(v[0], v[1], nu, 0.0), [0.05, 0.7],
                    method="Nelder-Mead", options=dict(xatol=1e-10, fatol=1e-14))
    assert ex.von_mises.value / p0 == pytest.approx(-best.fun, rel=1e-6)
    assert ex.von_mises.depth_over_a == pytest.approx(best.x[1], abs=1e-4)
    assert abs(ex.von_mises.X) < 1e-4 * a
    shear = r.stress_extrema(grid=(21, 21)).max_shear
    assert ex.tresca.value == pytest.approx(shear.value, rel=1e-9)
    assert ex.tresca.depth_over_a == pytest.approx(shear.depth_over_a, abs=1e-4)


def test_von_mises_refused_for_plane_model():
    """The plane model has no sigma_zz: von Mises and Tresca extrema are refused with
    MaterialError before any search; unknown quantities with ContactInputError."""
    r = contact.solve(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0),
                      load=0.01, speed=0.0)
    for q in ("von_mises", ("max_shear", "tresca")):
        with pytest.raises(MaterialError, match="out-of-plane"):
            r.stress_extrema(grid=(5, 5), quantities=q)
    for q in ((), ("max_shear", "energy"), 3, ("max_shear", 1)):
        with pytest.raises(ContactInputError, match="quantities"):
            r.stress_extrema(grid=(5, 5), quantities=q)
    assert r.stress(0.0, -0.5).sigma_zz is None


# --------------------------------------------------------------------------
# (c) a triclinic material: numerical Fourier inversion
# --------------------------------------------------------------------------
@pytest.mark.parametrize("fraction", FRACTIONS)
def test_triclinic_vs_fourier(fraction):
    """The triclinic material at c = 0, 0.5, 0.9 c_R under a Gaussian p of width 0.5 and
    q = 0.3 p: all six stresses vs the Fourier inversion of the state-space solution
    (Schur bases per wavenumber; 384 Gauss-Legendre nodes, converged to 1.2e-14), to 1e-13
    of the largest stress (measured 3.5e-15, 6.6e-15, 1.4e-14)."""
    m = Anisotropic(TRICLINIC)
    c = fraction * m.rayleigh_speed()
    x, y = X[:7], Y[:7]
    want = GaussianFourierField(m.C, c, w=0.5, q_ratio=0.3, panels=24).stresses(x, y)
    got = field_of(m, c, gaussian_cauchy(1.0, 0.5), q_ratio=0.3, x=x, y=y)
    assert rel(got, want) <= 1e-13
    assert np.abs(want[3:5]).max() > 1e-3 * np.abs(want).max()      # antiplane coupled


def test_half_turn_about_Y_mirrors_the_field():
    """Turning the triclinic material by pi about Y maps (X, Y, Z) to (-X, Y, -Z): under
    the mirrored loads (p(-X), -q(-X)) the field is sigma'_ij(X, Y) = R_ia R_jb
    sigma_ab(-X, Y), at rest and moving; to 1e-12."""
    m = Anisotropic(TRICLINIC)
    turned = m.rotated(Rotation.from_euler("y", 180, degrees=True))
    R = np.diag([-1.0, 1.0, -1.0])
    sign = np.array([R[i, i] * R[j, j] for i, j in ((0, 0), (1, 1), (2, 2), (1, 2), (2, 0),
                                                     (0, 1))])
    P, Q = 1.0, 0.4
    for c in (0.0, 0.7 * min(m.rayleigh_speed(), turned.rayleigh_speed())):
        want = field_of(m, c, line_load(P), line_load(Q), x=-X) * sign[:, None]
        got = field_of(turned, c, line_load(P), line_load(-Q))     # line loads: p(-X) = p
        assert rel(got, want) <= 1e-12


# --------------------------------------------------------------------------
# (d) nearly isotropic: no loss of digits as the roots merge
# --------------------------------------------------------------------------
def _perturbation():
    """A fixed symmetric direction of anisotropy, entries of order 1 (seeded)."""
    B = np.random.default_rng(20240611).standard_normal((6, 6))
    return 0.5 * (B + B.T)


NEAR = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 0.0]


@pytest.mark.parametrize("c", [0.0, 0.5])
def test_nearly_isotropic_linear_in_perturbation(c):
    """C = C_iso + eps B: field(eps) - field_iso = eps D + O(eps^2), with field_iso the
    exact isotropic field (Flamant at rest, the potential solution moving; sigma_zz =
    nu (sigma_xx + sigma_yy)) and D the central difference at eps = +-1e-5.  The residual
    field(eps) - field_iso - eps D stays below 2 eps^2 + 5e-14 (relative to P / r) for
    eps = 1e-3 .. 1e-9 and 0 (measured: 0.23 eps^2 at rest, 0.37 eps^2 moving, down to
    rounding, 1e-15 .. 1.1e-14, from eps = 1e-7 on).  A modal sum over eigenvectors loses
    eps_mach / (p_i - p_j)^2 ~ 1e-7 at eps = 1e-9 (root gap 3e-5)."""
    iso = Anisotropic.isotropic(E_ISO, NU_ISO)
    B = _perturbation()
    P, Q = 1.0, 0.3
    z = np.zeros_like(X)
    if c == 0.0:
        exact, _ = flamant(X, Y, P, Q, NU_ISO)
    else:
        sxx, syy, sxy = isotropic_moving_flamant(E_ISO, NU_ISO, c, X, Y, P, Q)
        exact = np.stack([sxx, syy, NU_ISO * (sxx + syy), z, z, sxy])
    scale = (P + Q) / np.hypot(X, Y)

    def field(eps):
        return field_of(Anisotropic(iso.C + eps * B), c, line_load(P), line_load(Q))

    h = 1e-5
    D = (field(h) - field(-h)) / (2 * h)
    assert np.abs(D / scale).max() > 0.1                        # the field does move
    for eps in NEAR:
        m = Anisotropic(iso.C + eps * B)
        residual = np.abs(field(eps) - exact - eps * D) / scale
        assert residual.max() <= 2 * eps ** 2 + 5e-14, (eps, residual.max())
        if eps <= 1e-5:                                        # the roots do merge
            p = stroh_modes(m, c).roots
            gap = min(abs(p[i] - p[j]) for i in range(3) for j in range(i))
            assert gap < CLUSTER * abs(p[0].imag)


@pytest.mark.parametrize("c", [0.0, 0.5])
def test_nearly_isotropic_vs_fourier(c):
    """C = C_iso + eps B, eps = 1e-2 .. 1e-9 and 0, under the Gaussian pressure with
    q = 0.3 p: all six stresses vs the Fourier reference to 1e-13 of the largest (measured
    1.5e-15 .. 6.9e-15), either side of the clustering of the roots (at rest the roots are
    apart at eps = 1e-2, one cluster from 1e-3 on)."""
    iso = Anisotropic.isotropic(E_ISO, NU_ISO)
    B = _perturbation()
    x, y = X[:7], Y[:7]
    for eps in (1e-2, 1e-3, 1e-5, 1e-7, 1e-9, 0.0):
        m = Anisotropic(iso.C + eps * B)
        want = GaussianFourierField(m.C, c, w=0.5, q_ratio=0.3, panels=24).stresses(x, y)
        got = field_of(m, c, gaussian_cauchy(1.0, 0.5), q_ratio=0.3, x=x, y=y)
        assert rel(got, want) <= 1e-13, eps


# --------------------------------------------------------------------------
# (e) symmetry
# --------------------------------------------------------------------------
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_rotated_isotropic_unchanged(seed):
    """An isotropic stiffness under a random rotation: the same six stresses, at rest and
    moving, to 1e-13 of the largest."""
    iso = Anisotropic.isotropic(E_ISO, NU_ISO)
    turned = iso.rotated(Rotation.random(random_state=seed))
    for c in (0.0, 0.6):
        want = field_of(iso, c, line_load(1.0), q_ratio=0.3)
        got = field_of(turned, c, line_load(1.0), q_ratio=0.3)
        assert rel(got, want) <= 1e-13


@pytest.mark.parametrize("angle", [20.0, 45.0, 110.0])
def test_mirror_plane_Z_has_no_antiplane_stress(angle):
    """An orthotropic material turned about Z keeps the mirror plane Z = 0: the antiplane
    displacement is not excited (r = 0), sigma_yz = sigma_xz = 0 to 1e-14 of the largest
    stress, while the turned material couples sigma_xy to p (its field differs from the
    aligned one's)."""
    m = Anisotropic.from_engineering(9.0, 3.0, 4.0, 0.3, 0.25, 0.35, 1.5, 1.2, 1.0)
    turned = m.rotated(Rotation.from_euler("z", angle, degrees=True))
    for fraction in (0.0, 0.6):
        c = fraction * turned.rayleigh_speed()
        f = field_of(turned, c, line_load(1.0), line_load(0.5))
        assert np.abs(f[3:5]).max() <= 1e-14 * np.abs(f).max()
    assert rel(field_of(turned, 0.0, line_load(1.0)), field_of(m, 0.0, line_load(1.0))) > 1e-2


# --------------------------------------------------------------------------
# (f) inputs
# --------------------------------------------------------------------------
def test_points_off_the_half_space_as_plane_model():
    """Y > 0: points() computes the points without checking, as HalfSpaceModes.points does
    (Im z < 0 there), and the checked entries refuse them: modes_points with MaterialError,
    half_space_stress with StressPointError (Y >= 0), for both kinds of modes."""
    plane = contact.zhou2014()
    m = Anisotropic.from_orthotropic(plane, **OUT_OF_PLANE)
    Xb, Yb = np.array([0.0, 1.0]), np.array([-1.0, 0.5])
    for material, modes in ((m, stroh_modes(m, 0.2)), (plane, plane.half_space_modes(0.2))):
        Z = modes.points(Xb, Yb)
        assert all(z[0].imag > 0 and z[1].imag < 0 for z in Z)
        with pytest.raises(MaterialError, match="Im z > 0"):
            modes_points(modes, Xb, Yb)
        for y in (0.5, 0.0):
            with pytest.raises(StressPointError):
                half_space_stress(material, 0.2, 0.0, y, line_load(1.0))


def test_inputs_refused():
    """A speed at or above c_R: SpeedError (as HalfSpaceModes.of); transforms at the wrong
    number of points: ContactInputError naming how many are needed."""
    m = Anisotropic(TRICLINIC)
    with pytest.raises(SpeedError):
        stroh_modes(m, m.rayleigh_speed())
    with pytest.raises(SpeedError):
        stroh_modes(m, -0.1)
    modes = stroh_modes(m, 0.0)
    Z = modes.points(X, Y)
    with pytest.raises(ContactInputError, match=f"{len(Z)} points"):
        modes.stresses([line_load(1.0)(z) for z in Z[:-1]])
    with pytest.raises(ContactInputError, match=f"{len(Z)} points"):
        modes.out_of_plane([line_load(1.0)(z) for z in Z], Cq=[Z[0]])


def test_surface_limit():
    """At Y = -1e-13 the field is the surface response (Anisotropic.surface_response:
    local and Hilbert parts) of the triclinic material under a Gaussian: rows YY, XY are
    -p and -q, all six to 1e-10 of max p."""
    m = Anisotropic(TRICLINIC)
    c = 0.5 * m.rayleigh_speed()
    x = np.linspace(-2.0, 2.0, 9)
    C0 = gaussian_cauchy(1.0, 0.5)(x + 1e-300j)          # Hc[p] + i p on the line
    p, H = C0.imag, C0.real
    s = m.surface_response(c)
    local, hilbert = s.pressure_coefficients(0.3)[2:]
    want = np.outer(local, p) + np.outer(hilbert, H)
    got = field_of(m, c, gaussian_cauchy(1.0, 0.5), q_ratio=0.3, x=x, y=-1e-13 + 0 * x)
    assert rel(got, want, p.max()) <= 1e-10
    assert rel(got[1], -p, p.max()) <= 1e-10 and rel(got[5], -0.3 * p, p.max()) <= 1e-10
