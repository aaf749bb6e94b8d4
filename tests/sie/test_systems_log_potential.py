"""SystemSolution.log_potential and cauchy_limit: the logarithmic potential
V_i(x) = (1/pi) int_c^d psi_i(t) log abs(x - t) dt of a system's solution, and the one-sided
limits of its Cauchy transform on the real line.

References, each independent of the code under test:
- the interface crack: the closed-form density of Rice & Sih (1965) (complex exponents
  -1/2 +- i eps at both ends), its log potential by mpmath quadrature;
- manufactured complex modes: psi = T (Re phi, Im phi), phi = w sum_j c_j P_j^{(alpha,beta)}
  (mpmath's hypergeometric jacobi, exponents from mpmath's arctan), f from phi by the
  dominant identity evaluated by mpmath, for the four end choices (indices 0, 1, -1), the
  log potential by mpmath quadrature of psi (the end pieces in 1 - tau = y^6, 1 + tau = y^6);
- a decoupled system of real modes: T times the scalar solves' log_potential and
  cauchy_limit (sie.cauchy's recurrences and end tables, another route).
The mpmath values are stored in tests/reference/system_log_potential_refs.json, keyed by
the case and the point (they take ~20 s); SIE_TEST_RECOMPUTE_REFS=1 computes them again and
rewrites the file.  Points: inside, 1e-6 (relative to h) from the ends, at the ends, beside
(1e-6 outside, and 1.25 h), far (2.05 h, 20 h, 5e4 h).
"""
from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
from _stored import StoredReferences

import sie
from sie.systems import solve_system

_REFS = StoredReferences("system_log_potential_refs.json")
_stored = _REFS.complex

#: local points v = (x - m)/h of every class
V_LOCAL = (0.3, -0.55, 1.0 - 1e-6, -1.0 + 1e-6, 1.0, -1.0, 1.0 + 1e-6, -1.25, 2.05, -20.0,
           5e4)



def _points(c, d):
    m, h = 0.5 * (c + d), 0.5 * (d - c)
    x = np.array([m + h * v for v in V_LOCAL])
    x[np.array(V_LOCAL) == 1.0] = d
    x[np.array(V_LOCAL) == -1.0] = c
    return x


def _mp_log_potential(density, c, d, x, K=6):
    """(1/pi) int_c^d density log abs(x - t) dt by mpmath (30 digits); ``density(U, W)`` of
    the local distances U = 1 - tau, W = 1 + tau to the ends (t = m + h tau), which the end
    pieces take as y^K (a singular end's power is smooth in y), split where x's distance
    to the end is y^K, the middle split at x."""
    with mp.workdps(30):
        c, d, x = mp.mpf(c), mp.mpf(d), mp.mpf(x)
        h, m = (d - c) / 2, (c + d) / 2
        half = mp.mpf(1) / 2

        def right(y):
            U = y ** K
            return K * y ** (K - 1) * density(U, 2 - U) * mp.log(abs(x - d + h * U))

        def left(y):
            W = y ** K
            return K * y ** (K - 1) * density(2 - W, W) * mp.log(abs(x - c - h * W))

        def mid(tau):
            return density(1 - tau, 1 + tau) * mp.log(abs(x - m - h * tau))

        def splits(dist):
            top = mp.root(half, K)
            return [0, mp.root(dist, K), top] if 0 < dist < half else [0, top]
        v = (x - m) / h
        pm = sorted(set([-half, half] + list(mp.linspace(-half, half, 5))
                        + ([v] if -half < v < half else [])))
        total = (mp.quad(right, splits(abs(x - d) / h)) + mp.quad(left, splits(abs(x - c) / h))
                 + mp.quad(mid, pm))
        return h * total / mp.pi


# --------------------------------------------------------------------------
# the interface crack (Rice & Sih 1965)
# --------------------------------------------------------------------------
def _interface_crack(beta_d, G, a, n=8):
    A = np.array([[0.0, -beta_d], [beta_d, 0.0]])
    return solve_system(lambda s: np.array([G.real + 0.0 * s, G.imag + 0.0 * s]), A,
                        np.eye(2), n=n, left="singular", right="singular", total=[0.0, 0.0],
                        interval=(-a, a))


@pytest.mark.parametrize("beta_d", [0.3, -0.15])
def test_interface_crack_log_potential(beta_d):
    """b = psi_1 + i psi_2 = G cosh(pi eps)(t + 2 i eps a)(a - t)^(-1/2 + i eps)
    (a + t)^(-1/2 - i eps): V_1 + i V_2 against mpmath at every class of point, to 1e-14 of
    max abs(V) (measured: 4e-16)."""
    a, G = 2.0, 0.8 - 0.3j
    sol = _interface_crack(beta_d, G, a)
    x = _points(-a, a)
    got = sol.log_potential(x)
    assert got.shape == (2, x.size) and got.dtype == float

    def density(U, W):
        eps = mp.atanh(beta_d) / mp.pi
        return G * mp.cosh(mp.pi * eps) * (a - a * U + 2j * eps * a) \
            * (a * U) ** (-0.5 + 1j * eps) * (a * W) ** (-0.5 - 1j * eps)
    ref = np.array([_stored(f"crack {beta_d!r} {float(xi)!r}",
                            lambda xi=xi: _mp_log_potential(density, -a, a, xi)) for xi in x])
    err = np.abs(got[0] + 1j * got[1] - ref)
    assert err.max() < 1e-14 * np.abs(ref).max(), err / np.abs(ref).max()
    # finite at the ends, and continuous there (dV/dx = -H[psi] ~ r^(-1/2): V moves by
    # ~ r^(1/2) = 1.4e-6 at r = 2e-12)
    near = sol.log_potential(np.array([a * (1 - 1e-12), a, a * (1 + 1e-12)]))
    assert np.abs(np.diff(near, axis=1)).max() < 1e-5 * np.abs(ref).max()


# --------------------------------------------------------------------------
# manufactured complex modes, f by the dominant identity (mpmath)
# --------------------------------------------------------------------------
LAM = mp.mpc(0.4, 0.3)
C_MODE = (mp.mpc(0.5, -0.2), mp.mpc(-0.3, 0.4), mp.mpc(0.25, 0.1), mp.mpc(-0.1, -0.15))
TM = np.array([[1.0, 0.4], [-0.7, 0.9]])
BM = np.array([[1.2, 0.3], [-0.4, 0.8]])
INTERVAL = (-0.5, 2.5)


def _exponents(left, right):
    a0 = mp.mpf(1) / 2 + mp.atan(LAM) / mp.pi           # the branch (3): 0 < Re a0 < 1
    assert abs(mp.cot(mp.pi * a0) + LAM) < 1e-25
    al = a0 if right == "bounded" else a0 - 1
    be = 1 - a0 if left == "bounded" else -a0
    return al, be, int(mp.nint(mp.re(-(al + be))))


def _manufactured(left, right):
    """phi = w sum_j C_j P_j^{(al,be)}(tau) solves LAM phi + H[phi] = g with
    g = sum_j C_j (-2^-kappa / sin(pi al)) P_{j-kappa}^{(-al,-be)} (the dominant identity);
    the system A psi + B H[psi] = f with psi = TM (Re phi, Im phi)."""
    mp.mp.dps = 30
    al, be, kappa = _exponents(left, right)
    c, d = INTERVAL
    m, h = 0.5 * (c + d), 0.5 * (d - c)
    fac = -mp.mpf(2) ** (-kappa) / mp.sin(mp.pi * al)

    def g(tau):
        return sum(C * fac * mp.jacobi(j - kappa, -al, -be, tau)
                   for j, C in enumerate(C_MODE) if j - kappa >= 0)

    def f(s):
        vals = [complex(g(mp.mpf((float(si) - m) / h))) for si in s]
        return BM @ TM @ np.array([[v.real for v in vals], [v.imag for v in vals]])

    def density(U, W):
        tau = 1 - U if U < W else W - 1
        return U ** al * W ** be * sum(C * mp.jacobi(j, al, be, tau)
                                       for j, C in enumerate(C_MODE))
    lr, li = float(mp.re(LAM)), float(mp.im(LAM))
    A = BM @ TM @ np.array([[lr, -li], [li, lr]]) @ np.linalg.inv(TM)
    total = None
    if kappa == 1:
        mu0 = 2 ** (al + be + 1) * mp.gamma(al + 1) * mp.gamma(be + 1) / mp.gamma(al + be + 2)
        I = complex(h * C_MODE[0] * mu0)
        total = list(TM @ np.array([I.real, I.imag]))
    return A, f, density, total


@pytest.mark.parametrize("left,right", [("bounded", "singular"), ("singular", "singular"),
                                        ("bounded", "bounded"), ("singular", "bounded")])
def test_complex_modes_log_potential(left, right):
    A, f, density, total = _manufactured(left, right)
    sol = solve_system(f, A, BM, n=6, left=left, right=right, total=total, interval=INTERVAL)
    x = _points(*INTERVAL)
    got = sol.log_potential(x)
    ref_phi = np.array([_stored(f"manufactured {left} {right} {float(xi)!r}",
                                lambda xi=xi: _mp_log_potential(density, *INTERVAL, xi))
                        for xi in x])
    ref = TM @ np.array([ref_phi.real, ref_phi.imag])
    err = np.abs(got - ref).max(axis=0) / np.abs(ref).max()
    assert err.max() < 1e-13, err


# --------------------------------------------------------------------------
# a decoupled system of real modes: the scalar solves
# --------------------------------------------------------------------------
T3 = np.array([[1.0, 0.3, -0.4], [0.2, 1.0, 0.5], [-0.6, 0.1, 1.0]])
B3 = np.array([[2.0, -0.5, 0.1], [0.3, 1.0, 0.2], [0.0, 0.4, 1.5]])
A_MODES = (-1.3, 0.0, 0.7)
G_MODES = (lambda u: np.cos(u + 0.3), lambda u: np.sin(2.0 * u), lambda u: np.exp(0.5 * u))
ENDS = (("singular", "singular"), ("bounded", "bounded"), ("bounded", "singular"))


def _decoupled(interval, n=30):
    c, d = interval
    m, h = 0.5 * (c + d), 0.5 * (d - c)
    scal = [sie.solve(lambda s, g=g: g((s - m) / h), a=a, b=1.0, n=n, left=l, right=r,
                      total=0.8 if l == r == "singular" else None, intervals=[interval])
            for g, a, (l, r) in zip(G_MODES, A_MODES, ENDS)]

    def f(s):
        return B3 @ T3 @ np.array([g((s - m) / h) for g in G_MODES])
    tot = T3 @ np.array([sc.integral() for sc in scal])
    A = B3 @ T3 @ np.diag(A_MODES) @ np.linalg.inv(T3)
    sol = solve_system(f, A, B3, n=n, left=[e[0] for e in ENDS], right=[e[1] for e in ENDS],
                       total=[None, None, tot[2]], interval=interval)
    return sol, scal


@pytest.mark.parametrize("interval", [(-1.0, 1.0), (0.5, 3.0)])
def test_decoupled_system_log_potential_equals_the_scalar_solves(interval):
    sol, scal = _decoupled(interval)
    x = np.concatenate([_points(*interval), [0.5 * sum(interval) + 1e8]])
    ref = T3 @ np.array([sc.log_potential(x) for sc in scal])
    got = sol.log_potential(x)
    err = np.abs(got - ref).max(axis=0) / np.abs(ref).max()
    assert err.max() < 1e-13, err
    # a 2-d array of points keeps its shape
    assert sol.log_potential(x[:6].reshape(2, 3)).shape == (3, 2, 3)


def test_decoupled_system_cauchy_limit_equals_the_scalar_solves():
    interval = (0.5, 3.0)
    sol, scal = _decoupled(interval)
    x = np.array([0.52, 1.0, 2.2, 2.999, 0.4, 3.5, 40.0])
    for side in (1, -1):
        ref = T3 @ np.array([sc.cauchy_limit(x, side) for sc in scal])
        got = sol.cauchy_limit(x, side)
        assert got.dtype == complex and got.shape == (3, x.size)
        assert np.abs(got - ref).max() < 1e-13 * np.abs(ref).max()


def test_cauchy_limit_is_the_plemelj_pair():
    """Inside: H[psi] +- i psi; outside: the real transform; the two sides are conjugate."""
    sol = _interface_crack(0.3, 0.8 - 0.3j, 2.0)
    x = np.array([-1.9, 0.0, 1.3, 2.5, -7.0])
    up, down = sol.cauchy_limit(x, 1), sol.cauchy_limit(x, -1)
    inside = np.abs(x) < 2.0
    psi = np.zeros((2, x.size))
    psi[:, inside] = sol(x[inside])
    np.testing.assert_array_equal(up, sol.cauchy(x) + 1j * psi)
    np.testing.assert_array_equal(down, np.conj(up))
    # the limit from above is that of cauchy() at x + i y as y -> 0 (Plemelj)
    z = x[inside] + 1e-9j
    near = sol.cauchy(z)
    assert np.abs(near - up[:, inside]).max() < 1e-6 * np.abs(up).max()


def test_bad_points_and_sides():
    sol = _interface_crack(0.3, 0.8 - 0.3j, 2.0)
    with pytest.raises(sie.EvaluationPointError, match="real"):
        sol.log_potential(np.array([0.5 + 1j]))
    with pytest.raises(sie.EvaluationPointError, match="finite"):
        sol.log_potential(np.array([np.nan]))
    with pytest.raises(sie.EvaluationPointError, match="side"):
        sol.cauchy_limit(np.array([0.5]), side=0)
    with pytest.raises(sie.EvaluationPointError, match="side"):
        sol.cauchy_limit(np.array([0.5]), side=True)
    with pytest.raises(sie.EvaluationPointError, match="real"):
        sol.cauchy_limit(np.array([0.5 + 0j]))
    with pytest.raises(sie.EvaluationPointError, match="end"):
        sol.cauchy_limit(np.array([2.0]))
