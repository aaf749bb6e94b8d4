"""sie.systems: systems A psi + (B/pi) PV int psi/(t - s) dt = f with constant matrices.

References, each independent of the code under test:
- decoupled systems: the scalar solver ``sie.solve`` of each mode (a constant change of
  unknowns psi = T chi turns the system into scalar equations);
- complex exponents: manufactured solutions psi = T (Re phi, Im phi), phi = w p with the
  exponents from mpmath's root of cot(pi alpha0) = -lambda, and f computed from psi by
  mpmath quadrature of the principal value (not from the dominant identity);
- the interface crack: the closed forms of Rice & Sih (1965) and Rice (1988).
"""
from __future__ import annotations

import functools

import mpmath as mp
import numpy as np
import pytest

import sie
from sie.systems import mode_exponents, solve_system, system_modes

PTS = np.array([-0.93, -0.5, -0.1, 0.2, 0.55, 0.97])


# --------------------------------------------------------------------------
# a system that a constant change of unknowns decouples
# --------------------------------------------------------------------------
T3 = np.array([[1.0, 0.3, -0.4], [0.2, 1.0, 0.5], [-0.6, 0.1, 1.0]])
B3 = np.array([[2.0, -0.5, 0.1], [0.3, 1.0, 0.2], [0.0, 0.4, 1.5]])
A_MODES = (-1.3, 0.0, 0.7)                           # the order of system_modes
G_MODES = (lambda s: np.cos(s + 0.3), lambda s: np.sin(2.0 * s), lambda s: np.exp(0.5 * s))
ENDS = (("singular", "singular"), ("bounded", "bounded"), ("bounded", "singular"))


def test_decoupled_system_equals_scalar_solves():
    A = B3 @ T3 @ np.diag(A_MODES) @ np.linalg.inv(T3)
    n = 30
    scal = [sie.solve(g, a=a, b=1.0, n=n, left=l, right=r, total=0.8 if l == r == "singular"
                      else None)
            for g, a, (l, r) in zip(G_MODES, A_MODES, ENDS)]

    def f(s):
        return B3 @ T3 @ np.array([g(s) for g in G_MODES])
    chi_int = np.array([sc.integral() for sc in scal])
    tot = T3 @ chi_int
    sol = solve_system(f, A, B3, n=n, left=[e[0] for e in ENDS], right=[e[1] for e in ENDS],
                       total=[None, None, tot[2]])
    np.testing.assert_allclose(sol.modes.lambdas.real, A_MODES, rtol=0, atol=1e-14)
    ref = T3 @ np.array([sc(PTS) for sc in scal])
    err = np.abs(sol(PTS) - ref).max() / np.abs(ref).max()
    assert err < 1e-13, err
    np.testing.assert_allclose(sol.integral(), tot, rtol=0, atol=1e-13 * np.abs(tot).max())
    assert sol.imaginary == 0.0                     # real modes: real to the last bit
    # H[psi] inside from the identity equals B^-1 (f - A psi)
    lhs = sol.cauchy(PTS[1:-1])
    rhs = np.linalg.solve(B3, f(PTS[1:-1]) - A @ sol(PTS[1:-1]))
    assert np.abs(lhs - rhs).max() < 1e-13 * np.abs(rhs).max()


def test_all_modes_index_one_take_the_totals_of_psi():
    T = np.array([[1.0, 0.5], [-0.3, 1.0]])
    A = T @ np.diag([-0.4, 0.9]) @ np.linalg.inv(T)
    g = (lambda s: 1.0 + s * s, lambda s: np.cos(3.0 * s))
    tc = (0.7, -1.1)
    scal = [sie.solve(gk, a=a, b=1.0, n=24, left="singular", right="singular", total=t)
            for gk, a, t in zip(g, (-0.4, 0.9), tc)]
    sol = solve_system(lambda s: T @ np.array([gk(s) for gk in g]), A, np.eye(2), n=24,
                       left="singular", right="singular", total=T @ np.array(tc))
    ref = T @ np.array([sc(PTS) for sc in scal])
    assert np.abs(sol(PTS) - ref).max() < 1e-13 * np.abs(ref).max()


# --------------------------------------------------------------------------
# complex exponents: manufactured solutions, f by mpmath quadrature
# --------------------------------------------------------------------------
LAM = mp.mpc(0.4, 0.3)
P_COEF = (mp.mpc(0.5, -0.2), mp.mpc(-0.3, 0.4), mp.mpc(0.25, 0.1), mp.mpc(-0.1, -0.15))
TM = np.array([[1.0, 0.4], [-0.7, 0.9]])
BM = np.array([[1.2, 0.3], [-0.4, 0.8]])


def _alpha0_reference():
    """The root of cot(pi a) = -lambda with 0 < Re a < 1, found by mpmath from the real
    case's root (lambda -> Re lambda), continued along lambda = Re + i t Im, t: 0 -> 1."""
    a = mp.acot(-mp.re(LAM)) / mp.pi
    a = a if mp.re(a) > 0 else a + 1
    for t in mp.linspace(0.1, 1, 10):
        lam = mp.re(LAM) + 1j * t * mp.im(LAM)
        a = mp.findroot(lambda z: mp.cot(mp.pi * z) + lam, a)
    return a


@functools.lru_cache(maxsize=None)
def _manufactured(left, right, smooth=False):
    mp.mp.dps = 20
    a0 = _alpha0_reference()
    al = a0 if right == "bounded" else a0 - 1
    be = 1 - a0 if left == "bounded" else -a0

    def p(t):
        poly = sum(c * t ** j for j, c in enumerate(P_COEF))
        return poly + mp.mpc(0.3, -0.6) * mp.exp(0.7 * t) if smooth else poly

    def phi_uv(u, v):
        """phi at t = 1 - u = v - 1, from both distances to the ends: near an end the
        distance is the quadrature variable itself, never 1 - t rounded."""
        return u ** al * v ** be * p(1 - u if u < v else v - 1)

    def phi(t):
        return phi_uv(1 - t, 1 + t)

    def hphi(s):
        # PV int phi/(t - s) = int (phi(t) - phi(s))/(t - s) dt + phi(s) log((1-s)/(1+s));
        # the quotient, analytic next to s, by Gauss-Legendre on [s - r, s + r] (tanh-sinh
        # would cluster nodes at s, where it cancels); the end pieces in u = 1 - t = y^4 and
        # v = 1 + t = y^4 (the weight's y^{4 Re e + 3} is integrable without a tail that
        # tanh-sinh's finite range would cut off: that of v^{-0.63} alone cost 2e-11)
        s = mp.mpf(s)
        ps = phi(s)
        r = min(1 - s, 1 + s) / 2
        mid = mp.quad(lambda t: (phi(t) - ps) / (t - s), [s - r, s, s + r],
                      method="gauss-legendre")
        right = mp.quad(lambda y: 4 * y ** 3 * (phi_uv(y ** 4, 2 - y ** 4) - ps)
                        / (1 - y ** 4 - s), [0, mp.root(1 - s - r, 4)])
        left = mp.quad(lambda y: 4 * y ** 3 * (phi_uv(2 - y ** 4, y ** 4) - ps)
                       / (y ** 4 - 1 - s), [0, mp.root(1 + s - r, 4)])
        return (mid + right + left + ps * mp.log((1 - s) / (1 + s))) / mp.pi
    total = mp.quad(lambda y: 4 * y ** 3 * phi_uv(y ** 4, 2 - y ** 4), [0, 1]) + \
        mp.quad(lambda y: 4 * y ** 3 * phi_uv(2 - y ** 4, y ** 4), [0, 1])
    return phi, hphi, total


def _system(left, right, smooth=False):
    phi, hphi, iphi = _manufactured(left, right, smooth)
    lr, li = float(mp.re(LAM)), float(mp.im(LAM))
    A0 = np.array([[lr, -li], [li, lr]])
    A = BM @ TM @ A0 @ np.linalg.inv(TM)
    cache = {}

    def g(x):
        if x not in cache:
            v = complex(LAM * phi(mp.mpf(x)) + hphi(x))
            cache[x] = (v.real, v.imag)
        return cache[x]

    def f(s):
        return BM @ TM @ np.array([g(float(x)) for x in s]).T

    def psi(x):
        v = [complex(phi(mp.mpf(float(t)))) for t in x]
        return TM @ np.array([[z.real for z in v], [z.imag for z in v]])
    tot = TM @ np.array([float(mp.re(iphi)), float(mp.im(iphi))])
    return A, f, psi, tot


@pytest.mark.parametrize("left,right", [("bounded", "singular"), ("singular", "singular"),
                                        ("bounded", "bounded"), ("singular", "bounded")])
def test_complex_exponents_manufactured(left, right):
    A, f, psi, tot = _system(left, right)
    md = system_modes(A, BM)
    assert np.allclose(md.lambdas, [complex(mp.conj(LAM)), complex(LAM)], rtol=0, atol=1e-14)
    kappa = {("singular", "singular"): 1, ("bounded", "bounded"): -1}.get((left, right), 0)
    total = list(tot) if kappa == 1 else None
    # f is a polynomial of degree 3 - kappa in each component: n = 5 resolves it
    sol = solve_system(f, A, BM, n=5, left=left, right=right, total=total)
    x = PTS[1:-1]
    ref = psi(x)
    err = np.abs(sol(x) - ref).max() / np.abs(ref).max()
    assert err < 1e-13, err
    assert sol.imaginary < 1e-14
    np.testing.assert_allclose(sol.integral(), tot, rtol=0, atol=1e-12 * np.abs(tot).max())
    if kappa == -1:
        assert all(abs(c) < 1e-13 for c in sol.consistency)


def test_complex_exponents_smooth_data_converge():
    """phi = w (p + c exp(0.7 t)): f is no polynomial, n = 20 resolves it."""
    A, f, psi, tot = _system("bounded", "singular", smooth=True)
    sol = solve_system(f, A, BM, n=20, left="bounded", right="singular")
    x = PTS[1:-1]
    ref = psi(x)
    assert np.abs(sol(x) - ref).max() < 1e-13 * np.abs(ref).max()
    np.testing.assert_allclose(sol.integral(), tot, rtol=0, atol=1e-13 * np.abs(tot).max())


# --------------------------------------------------------------------------
# the interface crack (Rice & Sih 1965; England 1965; Erdogan 1965)
# --------------------------------------------------------------------------
def _interface_crack(beta_d, sigma, tau, a, n=6):
    """The reduced form: b = psi_1 + i psi_2 the complex dislocation density on (-a, a),
    i beta_d b + H[b] = sigma + i tau (Dundurs' beta_d), int b = 0; as a real system
    A = [[0, -beta_d], [beta_d, 0]], B = I."""
    A = np.array([[0.0, -beta_d], [beta_d, 0.0]])
    return solve_system(lambda s: np.array([sigma + 0.0 * s, tau + 0.0 * s]), A, np.eye(2),
                        n=n, left="singular", right="singular", total=[0.0, 0.0],
                        interval=(-a, a))


def _k_from_solution(sol, a):
    """K = -sqrt(2 pi) lim_{x->a} (a - x)^{-alpha} b(x) / sin(pi alpha) (the Plemelj local
    analysis of the Cauchy integral at an end, Muskhelishvili 1953, sec. 29, applied to
    traction (sigma + i tau) F(x) ahead of the tip, F ~ K/(sigma + i tau) (2 pi r)^{-1/2}
    r^{i eps}), from the mode that carries b."""
    V = sol.modes.vectors
    comb = V[0] + 1j * V[1]                        # b = sum_k comb_k phi_k
    carry = [k for k in range(comb.size) if abs(comb[k]) > 1e-12]
    e = sol.exponents[carry[0]]
    assert all(abs(sol.exponents[k].alpha - e.alpha) < 1e-15 for k in carry)
    reg = sol.regular(np.array([a]))[:, 0]
    lim = sum(comb[k] * 2.0 ** sol.exponents[k].beta * reg[k] for k in carry) * a ** (-e.alpha)
    return -np.sqrt(2.0 * np.pi) * lim / e.sin, e


@pytest.mark.parametrize("sigma,tau", [(1.0, 0.0), (0.0, 1.0), (0.8, -0.3)])
@pytest.mark.parametrize("beta_d", [0.3, -0.15])
def test_interface_crack_closed_form(beta_d, sigma, tau):
    a = 2.0
    sol = _interface_crack(beta_d, sigma, tau, a)
    eps = np.arctanh(beta_d) / np.pi
    G = sigma + 1j * tau
    K, e = _k_from_solution(sol, a)
    assert abs(e.alpha - (-0.5 + 1j * eps)) < 1e-15
    # Rice (1988) convention: interface traction ahead of the tip sigma_yy + i sigma_xy =
    # K (2 pi r)^{-1/2} r^{i eps}
    K_ref = G * np.sqrt(np.pi * a) * (1 + 2j * eps) * (2 * a) ** (-1j * eps)
    assert abs(K - K_ref) < 1e-12 * abs(K_ref)
    # the density: b = G cosh(pi eps) (x + 2 i eps a)(a - x)^{-1/2 + i eps}(a + x)^{-1/2 - i eps}
    # (the jump of (sigma + i tau) F(z), F of Rice & Sih 1965)
    x = 2.0 * PTS
    b = sol(x)
    b_ref = G * np.cosh(np.pi * eps) * (x + 2j * eps * a) * (a - x) ** (-0.5 + 1j * eps) \
        * (a + x) ** (-0.5 - 1j * eps)
    assert np.abs(b[0] + 1j * b[1] - b_ref).max() < 1e-13 * np.abs(b_ref).max()
    assert np.abs(sol.integral()).max() < 1e-14


def test_interface_crack_limit_eps_to_zero_is_continuous():
    a, G = 1.5, 0.7 + 0.2j
    K0, _ = _k_from_solution(_interface_crack(0.0, G.real, G.imag, a), a)
    assert abs(K0 - G * np.sqrt(np.pi * a)) < 1e-14           # the Griffith crack
    for bd in (1e-4, 1e-8, 1e-12):
        K, _ = _k_from_solution(_interface_crack(bd, G.real, G.imag, a), a)
        eps = np.arctanh(bd) / np.pi
        K_ref = G * np.sqrt(np.pi * a) * (1 + 2j * eps) * (2 * a) ** (-1j * eps)
        assert abs(K - K_ref) < 1e-13 * abs(K_ref)
        assert abs(K - K0) < 10 * eps * abs(K0)


@pytest.mark.parametrize("x", [-3.0, -0.7, 0.0, 0.4, 2.5])
def test_branch_continuous_as_imaginary_part_vanishes(x):
    real = mode_exponents(x, "bounded", "singular")
    for y in (1e-3, 1e-7, -1e-7, 1e-11):
        e = mode_exponents(complex(x, y), "bounded", "singular")
        assert abs(e.alpha0 - real.alpha0) < abs(y)           # d alpha0/d lambda <= 1/pi
        assert abs(1.0 / np.tan(np.pi * e.alpha0) + complex(x, y)) < 1e-13


# --------------------------------------------------------------------------
# bad input
# --------------------------------------------------------------------------
def _f2(s):
    return np.array([np.cos(s), np.sin(s)])


@pytest.mark.parametrize("A,B,match", [
    (np.zeros((2, 3)), np.eye(2), "square"),
    (np.zeros((2, 2)), np.eye(3), "same shape"),
    (np.zeros((2, 2)), np.array([[1.0, 2.0], [2.0, 4.0]]), "invertible"),
    (np.array([[np.nan, 0.0], [0.0, 1.0]]), np.eye(2), "finite"),
    (np.array([[1j, 0.0], [0.0, 1.0]]), np.eye(2), "real"),
    (np.array([[0.0, -2.0], [2.0, 0.0]]), np.eye(2), "cut"),
])
def test_bad_coefficients(A, B, match):
    with pytest.raises(sie.InvalidCoefficientError, match=match):
        solve_system(_f2, A, B, n=4, left="bounded", right="singular")


def test_not_diagonalisable():
    with pytest.raises(sie.UnsupportedEquationError, match="diagonalisable"):
        solve_system(_f2, [[1.0, 1.0], [0.0, 1.0]], np.eye(2), n=4, left="bounded",
                     right="singular")


@pytest.mark.parametrize("f,match", [
    (lambda s: np.cos(s), r"shape \(m, len\(s\)\)"),
    (lambda s: np.array([np.cos(s), np.cos(s), s]), r"shape \(m, len\(s\)\)"),
    (lambda s: np.array([np.cos(s), np.where(s > 0, np.inf, s)]), "non-finite"),
    (lambda s: np.array([np.cos(s), 1j * s]), "real"),
    ("cos", "callable"),
])
def test_bad_f(f, match):
    with pytest.raises(sie.CallableOutputError, match=match):
        solve_system(f, np.eye(2), np.eye(2), n=4, left="bounded", right="singular")


def test_bad_ends_and_totals():
    A = np.array([[0.0, -0.3], [0.3, 0.0]])
    with pytest.raises(sie.InvalidEndConditionError, match="share"):
        solve_system(_f2, A, np.eye(2), n=4, left=["bounded", "singular"], right="singular")
    with pytest.raises(sie.InvalidEndConditionError, match="one per mode"):
        solve_system(_f2, A, np.eye(2), n=4, left=["bounded"], right="singular")
    with pytest.raises(sie.SideConditionError, match="required"):
        solve_system(_f2, A, np.eye(2), n=4, left="singular", right="singular")
    with pytest.raises(sie.SideConditionError, match="exactly 2"):
        solve_system(_f2, A, np.eye(2), n=4, left="singular", right="singular",
                     total=[0.0, None])
    with pytest.raises(sie.InvalidOrderError):
        solve_system(_f2, A, np.eye(2), n=sie.systems.N_MAX_SYSTEM + 1, left="bounded",
                     right="singular")
    with pytest.raises(sie.InvalidIntervalError):
        solve_system(_f2, A, np.eye(2), n=4, left="bounded", right="singular",
                     interval=(1.0, -1.0))


# --------------------------------------------------------------------------
# through sie.solve
# --------------------------------------------------------------------------
def test_solve_with_matrix_coefficients_is_the_system():
    """sie.solve(f, a=A, b=B, ...) with m x m A, B is sie.solve_system (the same numbers),
    on the default interval and on intervals=[(c, d)]; a scalar 0 stands for A = 0."""
    A = np.array([[0.3, 0.1], [0.05, -0.2]])
    B = np.array([[1.0, 0.2], [0.0, 1.0]])

    def f(s):
        return np.array([np.cos(s), np.sin(s)])
    x = np.linspace(-0.9, 1.9, 9)
    ref = solve_system(f, A, B, n=12, left="singular", right="bounded", interval=(-1.0, 2.0))
    got = sie.solve(f, a=A, b=B.tolist(), n=12, left="singular", right="bounded",
                    intervals=[(-1.0, 2.0)])
    assert np.array_equal(got(x), ref(x))
    zero = sie.solve(lambda s: B @ np.array([-s, -2 * s]), a=0.0, b=B, n=4, left="bounded",
                     right="bounded")
    np.testing.assert_allclose(zero(np.array([0.0, 0.6])), [[1.0, 0.8], [2.0, 1.6]],
                               rtol=0, atol=1e-13)


@pytest.mark.parametrize("extra,match", [
    (dict(breaks=(0.2,)), "no breaks"),
    (dict(intervals=[(-1.0, -0.5), (0.0, 1.0)]), "one interval, got 2"),
])
def test_solve_with_matrix_coefficients_refuses_what_systems_lack(extra, match):
    kw = dict(a=np.eye(2) * 0.3, b=np.eye(2), n=6, left="bounded", right="singular")
    kw.update(extra)
    with pytest.raises(sie.UnsupportedEquationError, match=match):
        sie.solve(lambda s: np.array([np.cos(s), np.sin(s)]), **kw)


# --------------------------------------------------------------------------
# the Cauchy transform off the interval
# --------------------------------------------------------------------------
#: Off the interval (-1, 1) (scaled by the crack's a): beside it at 1e-9, next to both ends,
#: far, on the real line outside, and both sides of the switch from the closed form to the
#: recurrence (N log(rho) = 3.5 at n = 8: rho = 1.55, i.e. 0.5 i next to the middle).
Z_OFF = np.array([0.3 - 1e-9j, -1.99 + 1e-3j, 1.999 + 1e-3j, 0.45j, 0.55j, -40.0 - 3.0j,
                  3.0 + 0j, 2.0001 + 0j])


def _quad_cauchy(density, z, a):
    """(1/pi) int_{-a}^{a} density(t)/(t - z) dt by mpmath (30 digits), split at Re z and
    graded toward it so that a pole beside the interval is resolved."""
    x0 = float(np.real(z))
    grade = [x0 + sgn * d for d in (1e-3, 1e-5, 1e-7, 1e-9) for sgn in (-1.0, 1.0)]
    pts = [-a, a] + ([x0] + grade if abs(x0) < a - 2e-3 else [])
    with mp.workdps(30):
        return complex(mp.quad(lambda t: density(t) / (t - z), sorted(pts)) / mp.pi)


@pytest.mark.parametrize("beta_d,points", [(0.3, Z_OFF[[0, 2, 4, 6]]),
                                           (-0.15, Z_OFF[[1, 3, 5, 7]])])
def test_interface_crack_cauchy_transform_off_the_crack(beta_d, points):
    """psi_1 + i psi_2 = G cosh(pi eps)(x + 2 i eps a)(a - x)^(-1/2 + i eps)(a + x)^(-1/2 - i eps)
    (Rice & Sih 1965): the Cauchy transform of each component at complex z, and of b at real
    z outside (the traction ahead of the tips), against mpmath's quadrature of the closed
    form, to 2e-15 of its size."""
    a, G = 2.0, 0.8 - 0.3j
    sol = _interface_crack(beta_d, G.real, G.imag, a, n=8)
    eps = np.arctanh(beta_d) / np.pi

    def b(t):
        return G * mp.cosh(mp.pi * eps) * (t + 2j * eps * a) * (a - t) ** (-0.5 + 1j * eps) \
            * (a + t) ** (-0.5 - 1j * eps)
    for z in a / 2.0 * points:
        got = sol.cauchy(np.array([z]))[:, 0]
        if z.imag == 0.0:
            ref = _quad_cauchy(b, z.real, a)
            assert abs(got[0] + 1j * got[1] - ref) <= 2e-15 * abs(ref), z
        else:
            for k, part in ((0, mp.re), (1, mp.im)):
                ref = _quad_cauchy(lambda t: part(b(t)), z, a)
                assert abs(got[k] - ref) <= 2e-15 * max(abs(ref), 1e-3), (z, k)


def test_real_modes_cauchy_transform_equals_the_scalar_solves():
    """The decoupled system of real modes: T times the scalar solutions' Cauchy transforms
    (sie.cauchy's recurrences, another route) at complex z and real z outside, to 1e-13."""
    A = B3 @ T3 @ np.diag(A_MODES) @ np.linalg.inv(T3)
    n = 30
    scal = [sie.solve(g, a=a, b=1.0, n=n, left=l, right=r, total=0.8 if l == r == "singular"
                      else None)
            for g, a, (l, r) in zip(G_MODES, A_MODES, ENDS)]
    tot = T3 @ np.array([sc.integral() for sc in scal])

    def f(s):
        return B3 @ T3 @ np.array([g(s) for g in G_MODES])
    sol = solve_system(f, A, B3, n=n, left=[e[0] for e in ENDS], right=[e[1] for e in ENDS],
                       total=[None, None, tot[2]])
    for z in (Z_OFF / 2.0, np.array([1.5, -3.0, 40.0, 1.0 + 1e-7])):
        ref = T3 @ np.array([sc.cauchy(z) for sc in scal])
        got = sol.cauchy(z)
        assert np.abs(got - ref).max() <= 1e-13 * np.abs(ref).max()


def test_cauchy_transform_at_infinity_and_at_the_ends():
    """Far away the transform of a crack with zero net opening decays like M_1/z^2 (the two
    expansions at 1e99 and 1e101 agree in z^2 C(z)); an end is refused."""
    sol = _interface_crack(0.3, 0.8, -0.3, 2.0)
    z = np.array([1e8, 1e99, 1e101, 1e150])
    scaled = sol.cauchy(z) * z ** 2
    np.testing.assert_allclose(scaled[:, 1:], scaled[:, :1] * np.ones((1, 3)), rtol=1e-7)
    with pytest.raises(sie.EvaluationPointError, match="end"):
        sol.cauchy(np.array([2.0]))
