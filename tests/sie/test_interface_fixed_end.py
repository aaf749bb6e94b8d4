"""A second classical fixed end singularity: a crack perpendicular to a bimaterial interface,
its tip at the interface (T. S. Cook and F. Erdogan, "Stresses in bonded materials with a
crack perpendicular to the interface", Int. J. Eng. Sci. 10 (1972) 677; F. Erdogan and
V. Biricikoglu, Int. J. Eng. Sci. 11 (1973) 745).

Geometry: material 1 (mu1, kappa1) in x > 0, material 2 (mu2, kappa2) in x < 0, bonded along
x = 0; the crack 0 < x < a on y = 0 in material 1, its tip x = 0 on the interface, under
uniform pressure p.  With phi the dislocation density (the derivative of the opening) and
s, t the distances from the interface, the SIE is

    (1/pi) int_0^a [1/(t - s) + k(s, t)] phi(t) dt = -p,   0 < s < a,
    k(s, t) = c1/(t + s) + c2 s/(t + s)^2 + c3 s^2/(t + s)^3,
    c1 = (3 B - C)/2,  c2 = -6 B,  c3 = 4 B,
    B = (alpha - beta)/(1 + beta) = (G - 1)/(G kappa1 + 1),
    C = (alpha + beta)/(1 - beta) = (G kappa1 - kappa2)/(G + kappa2),   G = mu2/mu1,

alpha, beta Dundurs' parameters with material 1 the cracked one,
alpha = (G (kappa1 + 1) - (kappa2 + 1)) / (G (kappa1 + 1) + kappa2 + 1),
beta = (G (kappa1 - 1) - (kappa2 - 1)) / (G (kappa1 + 1) + kappa2 + 1) (alpha > 0: material 2
the stiffer).  Derived here from the edge dislocation at distance t from the interface
(Muskhelishvili's potentials Phi, Omega; the infinite-body dislocation Phi0, Omega0; the bonded
half-planes by analytic continuation across x = 0): in material 1 Phi = Phi0 + B Omega0,
Omega = Omega0 + C Phi0, in material 2 Phi = (1 + C) Phi0, Omega = (1 + B) Omega0 (the same
image constants as Dundurs' dislocation near an interface; Cook & Erdogan's kernel for the
crack touching the interface has this form, 1/(t+s), s/(t+s)^2, s^2/(t+s)^3).  The tests check
the bonding conditions of these potentials and that sigma_xx on the crack's line is the
kernel; mu2 -> 0 (B = C = -1) gives the edge crack's -1/(t+s) + 6s/(t+s)^2 - 4s^2/(t+s)^3
(Koiter 1965; Kaya & Erdogan 1987), and mu2 = mu1, kappa2 = kappa1 (B = C = 0) no kernel.

The exponent at the interface: the Mellin symbol of the operator, (1/pi) int_0^inf
[1/(t-1) + k(1, t)] t^g dt = D(g)/sin(pi g) for -1 < g < 0 (the Cauchy part -cot(pi g),
the kernel's from int_0^inf t^g (1+t)^-m dt = B(g+1, m-g-1); checked against mpmath),
D(g) = -cos(pi g) + (C - 3B)/2 - 4B g - 2B g^2; phi ~ t^g at the interface with g the root
of D in (-1, 0) (there is one).  The independent reference: the characteristic equation of
a crack normal to and ending at a bimaterial interface (A. R. Zak and M. L. Williams, J. Appl.
Mech. 30 (1963) 142; Cook & Erdogan 1972), in Dundurs' parameters as M.-Y. He and
J. W. Hutchinson write it ("Crack deflection at an interface between dissimilar elastic
materials", Int. J. Solids Struct. 25 (1989) 1053), stresses ~ r^(-lambda),

    cos(pi lambda) = 2 (beta - alpha)/(1 + beta) (1 - lambda)^2
                     + (alpha + beta^2)/(1 - beta^2),

its root in (0, 1) by mpmath; g = -lambda.  (lambda = 1/2 for one material; lambda > 1/2, a
stronger singularity, when material 2 is the softer; lambda -> 1 as mu2 -> 0.)  With
lambda = -g the two equations are the same: (alpha + beta^2)/(1 - beta^2) = (B + C)/2.

The SIE solved with left = g (index 1: int phi = 0, the crack closed at both ends) and the far
tip "singular": the Griffith crack (mu2 = mu1) gives K_I = p sqrt(pi a/2) exactly; mu2 -> 0
tends to the edge crack's K_I = 1.1215 p sqrt(pi a) (Koiter 1965; Tada, Paris & Irwin 2000).
No published table of Cook & Erdogan's stress intensity factors was at hand: no published
digits of K_I are compared here.
"""
import math
import warnings

import mpmath as mp
import numpy as np
import pytest

import sie

KOITER_F = 1.1215            # the edge crack, Tada, Paris & Irwin (2000), p. 8.1


def dundurs(G, kappa1, kappa2):
    """Dundurs' alpha, beta with material 1 the cracked one, G = mu2/mu1."""
    den = G * (kappa1 + 1.0) + kappa2 + 1.0
    return ((G * (kappa1 + 1.0) - (kappa2 + 1.0)) / den,
            (G * (kappa1 - 1.0) - (kappa2 - 1.0)) / den)


def image_constants(G, kappa1, kappa2):
    al, be = dundurs(G, kappa1, kappa2)
    return (al - be) / (1.0 + be), (al + be) / (1.0 - be)


def interface_kernel(B, C):
    """(1/pi) k(s, t), s, t the distances from the interface."""
    c1, c2, c3 = 0.5 * (3.0 * B - C), -6.0 * B, 4.0 * B

    def k(s, t):
        u = t + s
        return (c1 / u + c2 * s / u**2 + c3 * s**2 / u**3) / np.pi
    return k


def interface_symbol(B, C):
    return lambda g: -math.cos(math.pi * g) + 0.5 * (C - 3.0 * B) - 4.0 * B * g - 2.0 * B * g * g


def interface_exponent(B, C):
    return sie.end_exponent(interface_symbol(B, C), (-1.0 + 1e-12, -1e-12))


def kappa_plane_strain(nu):
    return 3.0 - 4.0 * nu


# material pairs (G = mu2/mu1, nu1, nu2), plane strain: material 2 stiffer, softer, equal G
PAIRS = [(23.0, 0.35, 0.30), (1.0 / 23.0, 0.30, 0.35), (3.0, 0.30, 0.25), (0.3, 0.25, 0.30),
         (1.0, 0.30, 0.45), (1e3, 0.30, 0.30), (1e-3, 0.30, 0.30)]


def minus_p(s):
    return -np.ones_like(s)


def far_tip_factor(sol, a):
    """K_I / (p sqrt(pi a)) at the far tip (exponent -1/2), as in test_fixed_end_singularity:
    K_I = -sqrt(pi) sqrt(2h) 2^beta phi(1)."""
    p = sol.pieces[0]
    assert p.alpha == -0.5
    K = -math.sqrt(math.pi) * math.sqrt(2.0 * p.interval.h) * 2.0 ** p.beta \
        * sol.endpoint_value(1, 0)
    return K / math.sqrt(math.pi * a)


def interface_crack(B, C, n, a=1.0):
    g = interface_exponent(B, C)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.ResidualWarning)
        return sie.solve(minus_p, a=0.0, b=1.0, n=n, left=g, right="singular",
                         intervals=[(0.0, a)], kernel=interface_kernel(B, C), total=0.0)


# ---------------------------------------------------------------------------------------
# the kernel: the image field of a dislocation next to the interface
# ---------------------------------------------------------------------------------------
def _dislocation_potentials(t, A=1j):
    """Interface on the real axis, material 1 above (y > 0), the crack on the positive
    imaginary axis (the distance from the interface along it): the infinite-body edge
    dislocation at z0 = i t, Phi0 = A/(z - z0), Omega0(z) = conj(Phi0(conj z)) +
    z conj(Phi0'(conj z)) + conj(Psi0(conj z)), Psi0 = conj(A)/(z - z0) + A conj(z0)/(z - z0)^2,
    with their derivatives."""
    z0 = 1j * t
    Ab, zb0 = np.conj(A), np.conj(z0)
    phi0 = lambda z: A / (z - z0)                                             # noqa: E731
    dphi0 = lambda z: -A / (z - z0) ** 2                                      # noqa: E731
    om0 = lambda z: (A + Ab) / (z - zb0) + Ab * (z0 - z) / (z - zb0) ** 2     # noqa: E731
    dom0 = lambda z: (-(A + 2.0 * Ab) / (z - zb0) ** 2                        # noqa: E731
                      - 2.0 * Ab * (z0 - z) / (z - zb0) ** 3)
    return phi0, dphi0, om0, dom0


def test_image_potentials_bond_the_half_planes_and_give_the_kernel():
    """Muskhelishvili: sigma_yy - i sigma_xy = Phi(z) + Omega(conj z) + (z - conj z)
    conj(Phi'(z)), sigma_xx + sigma_yy = 4 Re Phi, 2 mu d(u + iv)/dx = kappa Phi(z) -
    Omega(conj z) - (z - conj z) conj(Phi'(z)).  On the interface traction and displacement
    are continuous; on the crack's line sigma_xx = -2 [1/(t - s) + k(s, t)] (A = i)."""
    for G, nu1, nu2 in PAIRS:
        k1, k2 = kappa_plane_strain(nu1), kappa_plane_strain(nu2)
        B, C = image_constants(G, k1, k2)
        assert B == pytest.approx((G - 1.0) / (G * k1 + 1.0), abs=1e-14)
        assert C == pytest.approx((G * k1 - k2) / (G + k2), abs=1e-14)
        kern = interface_kernel(B, C)
        for t in (0.3, 1.7):
            phi0, dphi0, om0, dom0 = _dislocation_potentials(t)
            x = np.array([-3.0, -0.4, 0.1, 2.5]) + 0j          # on the interface
            phi1, om1 = phi0(x) + B * om0(x), om0(x) + C * phi0(x)
            phi2, om2 = (1.0 + C) * phi0(x), (1.0 + B) * om0(x)
            np.testing.assert_allclose(phi1 + om1, phi2 + om2, atol=1e-13)
            np.testing.assert_allclose((k1 * phi1 - om1), (k2 * phi2 - om2) / G, atol=1e-12)
            s = np.array([0.05, 0.9, 1.2, 4.0])
            z = 1j * s
            Phi = phi0(z) + B * om0(z)
            dPhi = dphi0(z) + B * dom0(z)
            Om = om0(np.conj(z)) + C * phi0(np.conj(z))
            syy = (Phi + Om + (z - np.conj(z)) * np.conj(dPhi)).real
            sxx = 4.0 * Phi.real - syy
            np.testing.assert_allclose(sxx, -2.0 * (1.0 / (t - s) + np.pi * kern(s, t)),
                                       rtol=1e-12)


def test_kernel_limits():
    """mu2 = 0: the edge crack's kernel (B = C = -1, whatever kappa2); mu2 = mu1, kappa2 =
    kappa1: none."""
    s, t = np.array([0.1, 0.5, 2.0]), np.array([0.3, 0.05, 1.0])
    u = s + t
    edge = (-1.0 / u + 6.0 * s / u**2 - 4.0 * s**2 / u**3) / np.pi
    for k2 in (1.0, 1.8, 3.0):
        B, C = image_constants(0.0, 1.8, k2)
        assert (B, C) == (-1.0, -1.0)
        np.testing.assert_allclose(interface_kernel(B, C)(s, t), edge, rtol=1e-15)
    B, C = image_constants(1.0, 2.2, 2.2)
    assert (B, C) == (0.0, 0.0)
    assert np.all(interface_kernel(B, C)(s, t) == 0.0)


# ---------------------------------------------------------------------------------------
# the exponent at the interface
# ---------------------------------------------------------------------------------------
def _mellin_mp(h, g):
    """int_0^inf t^g h(t) dt by mpmath for h smooth on [0, inf), h ~ 1/t at infinity:
    t = y^(1/(1+g)) on [0, 1] and t = y^(1/g) on [1, inf) take the powers of the ends out of
    the integrands (the plain tanh-sinh rule loses 7 digits on t^g and t^(g-1) at dps 20)."""
    g = mp.mpf(g)
    head = mp.quad(lambda y: h(y ** (1 / (1 + g))), [0, 1]) / (1 + g)
    tail = mp.quad(lambda y: h(y ** (1 / g)) * y ** (1 / g), [0, 1]) / (-g)
    return head + tail


def test_symbol_is_the_mellin_transform_of_the_operator():
    """(1/pi) int_0^inf k(1, t) t^g dt by mpmath + the Cauchy part's -cot(pi g) (its
    quadrature is in test_fixed_end_singularity) = D(g)/sin(pi g), for g in (-1, 0)."""
    mp.mp.dps = 20
    B, C = image_constants(3.0, kappa_plane_strain(0.3), kappa_plane_strain(0.25))
    c1, c2, c3 = 0.5 * (3 * B - C), -6 * B, 4 * B
    D = interface_symbol(B, C)
    for g in (-0.3, -0.7, -0.95):
        reg = _mellin_mp(lambda t: c1 / (t + 1) + c2 / (t + 1)**2 + c3 / (t + 1)**3, g)
        val = float(reg / mp.pi) - 1.0 / math.tan(math.pi * g)
        assert abs(val - D(g) / math.sin(math.pi * g)) < 1e-12


def zak_williams_lambda(al, be):
    """The root in (0, 1) of cos(pi l) = 2 (be - al)/(1 + be) (1 - l)^2 + (al + be^2)/(1 - be^2)
    (He & Hutchinson 1989), by mpmath."""
    mp.mp.dps = 30
    al, be = mp.mpf(al), mp.mpf(be)
    f = lambda l: (mp.cos(mp.pi * l) - 2 * (be - al) / (1 + be) * (1 - l)**2   # noqa: E731
                   - (al + be**2) / (1 - be**2))
    return mp.findroot(f, (mp.mpf("1e-9"), 1 - mp.mpf("1e-9")), solver="anderson")


def test_exponent_against_zak_williams():
    """sie.end_exponent on the kernel's symbol = -lambda of the Zak-Williams equation, to
    1e-12, for seven material pairs; above -1/2 when material 2 is the stiffer, below when
    it is the softer; mu2 = mu1 and nu2 = nu1 gives -1/2."""
    for G, nu1, nu2 in PAIRS:
        k1, k2 = kappa_plane_strain(nu1), kappa_plane_strain(nu2)
        al, be = dundurs(G, k1, k2)
        lam = zak_williams_lambda(al, be)
        assert 0.0 < lam < 1.0
        g = interface_exponent(*image_constants(G, k1, k2))
        assert abs(g + float(lam)) < 1e-12, (G, nu1, nu2, g, lam)
        if G > 1.0:
            assert -0.5 < g < 0.0
        elif G < 1.0:
            assert -1.0 < g < -0.5
    assert abs(interface_exponent(0.0, 0.0) + 0.5) < 1e-14


# ---------------------------------------------------------------------------------------
# the crack ending at the interface
# ---------------------------------------------------------------------------------------
def test_same_material_is_the_griffith_crack():
    """mu2 = mu1, kappa2 = kappa1: no kernel, exponent -1/2 at both ends: K_I = p sqrt(pi
    a/2) exactly, F = 1/sqrt(2) at n = 4 already (and on (0, 2): F is scale-free)."""
    B, C = image_constants(1.0, 1.8, 1.8)
    for a in (1.0, 2.0):
        sol = interface_crack(B, C, 4, a)
        assert sol.kappa == (1,)
        assert abs(far_tip_factor(sol, a) - 1.0 / math.sqrt(2.0)) < 1e-13


def test_convergence_in_n():
    """Algebraic convergence (phi carries t^(g2 - g) at the interface, g2 the symbol's next
    root).  Material 2 stiffer (G = 23, g2 - g = 1.060 + 0.584i): F = 0.62366, 0.624066,
    0.6240746, 0.62407375, 0.624073649 at n = 8, 16, 32, 64, 128 and 0.6240736429 at
    n = 256, about n^-4.  Softer (G = 1/23, g2 - g = 0.860): 0.94832, 0.948657, 0.948733,
    0.9487476, 0.9487504 and 0.9487509 at n = 256, about n^-2.7."""
    for G, nu1, nu2, tol in ((23.0, 0.35, 0.30, 2e-7), (1.0 / 23.0, 0.30, 0.35, 1e-5)):
        B, C = image_constants(G, kappa_plane_strain(nu1), kappa_plane_strain(nu2))
        F = {n: far_tip_factor(interface_crack(B, C, n), 1.0) for n in (8, 16, 32, 64, 128)}
        e = {n: abs(F[n] - F[128]) for n in (8, 16, 32, 64)}
        assert e[64] < tol
        assert e[8] > 30.0 * e[64]
        if G > 1.0:
            assert F[128] < 1.0 / math.sqrt(2.0)          # the stiffer neighbour shields
        else:
            assert F[128] > 1.0 / math.sqrt(2.0)


def test_soft_neighbour_tends_to_the_edge_crack():
    """mu2/mu1 -> 0: the far tip's F rises toward Koiter's edge crack 1.1215 (slowly: the
    gap ~ 1.1 (1 + g), g -> -1 the interface exponent)."""
    k = kappa_plane_strain(0.3)
    gaps = []
    for G in (1e-2, 1e-3, 1e-4):
        B, C = image_constants(G, k, k)
        sol = interface_crack(B, C, 64)
        gaps.append((KOITER_F - far_tip_factor(sol, 1.0), 1.0 + sol.beta[0]))
    assert all(gap > 0 for gap, _ in gaps)
    assert gaps[0][0] > 2.5 * gaps[1][0] > 6.0 * gaps[2][0]
    assert gaps[2][0] < 0.012
    for gap, one_plus_g in gaps:
        assert 0.9 < gap / one_plus_g < 1.3
