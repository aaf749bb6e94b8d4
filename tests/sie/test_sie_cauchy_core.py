"""The Cauchy transform of Jacobi series off the line and the log potential, against
references not derived from the library: mpmath quadrature, and the exact transform of
sqrt(1 - t^2)."""
import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import sie

# references at 30 digits (mp.workdps, not the global mp.dps that other test modules set), the
# ends' factors absorbed by a change of variable (_quad_weighted): integrated in t, tanh-sinh
# stops ~10^-dps from an end, and a -0.7 end would miss (1e-30)^0.3 of its mass at 30 digits
# (60 digits and 10x the time were needed for 1e-18 without the change of variable)
DPS = 30
#: the tolerance's scale, an integral of absolute values (kinks where psi changes sign), only
#: sizes the tolerance: 15 digits and tanh-sinh degree 4 at most give it to 3e-4
SCALE_DPS, SCALE_DEGREE = 15, 4


def _mp_jacobi_series(c, a, b, t):
    """sum_k c_k P_k^(a,b)(t) in mpmath by the three-term recurrence (DLMF 18.9.1-2);
    mp.jacobi (a hypergeometric sum per k) would cost 10x more."""
    a, b = mp.mpf(a), mp.mpf(b)
    p0, p1 = mp.mpf(1), (a + 1) + (a + b + 2) * (t - 1) / 2
    out = c[0] * p0 + (c[1] * p1 if len(c) > 1 else 0)
    for k in range(1, len(c) - 1):
        s = 2 * k + a + b
        p0, p1 = p1, ((s + 1) * ((s + 2) * s * t + a * a - b * b) * p1
                      - 2 * (k + a) * (k + b) * (s + 2) * p0) / (2 * (k + 1) * (k + a + b + 1) * s)
        out += c[k + 1] * p1
    return out


def _quad_weighted(alpha, beta, h, **quad):
    """int (1-t)^alpha (1+t)^beta h(t) dt, h smooth on [-1, 1], by tanh-sinh on [-1, 0] and
    [0, 1], the end pieces in u = (1 -+ t)^(1+e)/(1+e) (du = (1 -+ t)^e dt: the end factor
    absorbed, the integrand bounded), as tests/sie/test_breaks.py's int_weighted."""
    a, b = mp.mpf(alpha), mp.mpf(beta)
    p, q = 1 + b, 1 + a

    def left(u):
        t = -1 + (p * u) ** (1 / p)
        return (1 - t) ** a * h(t)

    def right(u):
        t = 1 - (q * u) ** (1 / q)
        return (1 + t) ** b * h(t)
    return mp.quad(left, [0, 1 / p], **quad) + mp.quad(right, [0, 1 / q], **quad)


@mp.workdps(DPS)
def _quad_transform(alpha, beta, c, z):
    """(1/pi) int (1-t)^alpha (1+t)^beta sum c_k P_k(t) / (t - z) dt by mpmath (tanh-sinh);
    the same values as plain tanh-sinh in t at 60 digits."""
    z = mp.mpc(z)
    return complex(_quad_weighted(alpha, beta, lambda t: _mp_jacobi_series(c, alpha, beta, t)
                                  / (t - z)) / mp.pi)


@mp.workdps(SCALE_DPS)
def _abs_scale(alpha, beta, c, z):
    """(1/pi) int |psi(t)| / |t - z| dt: the size of the terms the transform sums."""
    z = mp.mpc(z)
    return float(_quad_weighted(alpha, beta, lambda t: abs(_mp_jacobi_series(c, alpha, beta, t)
                                                           / (t - z)),
                                maxdegree=SCALE_DEGREE) / mp.pi)


C = [0.7, -0.3, 0.2, 0.05, -0.01]


@pytest.mark.parametrize("alpha,beta", [(0.3, -0.3), (-0.7, -0.3), (0.3, 0.7)])
@pytest.mark.parametrize("z", [1.5 + 0.0j, 0.3 + 1.0j, 4.0 - 3.0j, 1.2 + 0.01j, -1.1 - 0.05j])
@pytest.mark.slow
def test_jacobi_cauchy_against_mpmath_quadrature(alpha, beta, z):
    got = sie.jacobi_cauchy(C, alpha, beta, np.array([z]))[0]
    ref = _quad_transform(alpha, beta, C, z)
    assert abs(got - ref) <= 1e-13 * _abs_scale(alpha, beta, C, z)


def _sqrt_transform(z):
    """(1/pi) int sqrt(1-t^2)/(t - z) dt = sqrt(z-1) sqrt(z+1) - z (branch ~ -1/(2z) at
    infinity; Muskhelishvili 1953, the elliptic density)."""
    z = mp.mpc(z)
    return complex(mp.sqrt(z - 1) * mp.sqrt(z + 1) - z)


@pytest.mark.parametrize("x", [-0.999, -0.5, 0.0, 0.37, 0.9999])
@pytest.mark.parametrize("eps", [1e-12, 1e-8, 1e-4])
@pytest.mark.parametrize("side", [1, -1])
def test_sqrt_density_near_the_interval(x, eps, side):
    # sqrt(1-t^2) = (1-t)^{1/2}(1+t)^{1/2} P_0
    z = complex(x, side * eps)
    got = sie.jacobi_cauchy([1.0], 0.5, 0.5, np.array([z]))[0]
    assert abs(got - _sqrt_transform(z)) <= 2e-15


@pytest.mark.parametrize("theta", np.linspace(0.1, 2 * np.pi - 0.1, 7))
def test_sqrt_density_next_to_an_end(theta):
    z = 1.0 + 1e-10 * np.exp(1j * theta)
    got = sie.jacobi_cauchy([1.0], 0.5, 0.5, np.array([z]))[0]
    assert abs(got - _sqrt_transform(z)) <= 2e-15


@pytest.mark.slow
def test_ray_from_near_to_far_is_continuous_and_exact():
    """Points across the switch between the forward recurrence and Miller's algorithm."""
    r = 1.0 + np.geomspace(1e-4, 100.0, 60)
    for ang in (0.05, 0.7, 2.0):
        z = r * np.exp(1j * ang)
        got = sie.jacobi_cauchy(np.ones(40) / np.arange(1, 41) ** 2, -0.5, -0.5, z)
        ref = np.array([complex(sum(ck * v for ck, v in zip(
            np.ones(40) / np.arange(1, 41) ** 2,
            [(-1.0) / mp.sqrt(zz - 1) / mp.sqrt(zz + 1) * (zz - mp.sqrt(zz - 1) * mp.sqrt(zz + 1)) ** k
             / (1 if k == 0 else 1) * (mp.gamma(k + 0.5) / (mp.sqrt(mp.pi) * mp.gamma(k + 1)))
             for k in range(40)]))) for zz in map(mp.mpc, z)])
        # Chebyshev: P_k^{(-1/2,-1/2)} = Gamma(k+1/2)/(sqrt(pi) k!) T_k, and
        # (1/pi) int T_k(t)/(sqrt(1-t^2)(t - z)) dt = -rho^{-k}/sqrt(z^2-1), rho^{-1} = z - sqrt(z^2-1)
        assert np.max(np.abs(got - ref)) <= 1e-14 * np.max(np.abs(ref))


def _solution():
    return sie.solve(np.cos, a=0.7, b=1.0, n=24, left="singular", right="bounded")


@pytest.mark.parametrize("x", [-0.9, -0.2, 0.4, 0.95])
def test_plemelj_limits(x):
    sol = _solution()
    h = sol.cauchy(np.array([x]))[0]
    psi = sol(np.array([x]))[0]
    up, down = sol.cauchy(np.array([x + 1e-14j, x - 1e-14j]))
    scale = abs(h) + abs(psi)
    assert abs(up - (h + 1j * psi)) <= 1e-13 * scale
    assert abs(down - (h - 1j * psi)) <= 1e-13 * scale


def test_complex_point_on_the_interval_is_rejected():
    sol = _solution()
    with pytest.raises(sie.EvaluationPointError, match="Im z == 0"):
        sol.cauchy(np.array([0.3 + 0.0j]))
    with pytest.raises(sie.EvaluationPointError, match="end"):
        sol.cauchy(np.array([1.0 + 0.0j]))
    with pytest.raises(sie.EvaluationPointError, match="real"):
        sol.log_potential(np.array([0.3 + 0.1j]))
    assert np.isrealobj(sol.cauchy(np.array([2.0 + 0.0j]).real))


def _log_potential_quad(sol, x, size=False, **quad):
    """(1/pi) int psi(t) log|x - t| dt by mpmath (tanh-sinh, split at x inside [-1, 1]), or
    with ``size`` the integral of its absolute value.  The piece from the singular end -1
    (beta < 0) is taken in u = (1+t)^(1+beta)/(1+beta), du = (1+t)^beta dt, which absorbs
    the end's factor (as _quad_weighted; the right end's exponent is positive).  1 + t is
    formed as such, so that log|x - t| at x = -1 is log(1 + t) without cancellation."""
    a, b = mp.mpf(sol.alpha), mp.mpf(sol.beta)
    cf = [float(v) for v in sol.coefficients]
    x = mp.mpf(x)
    split = x if abs(x) < 1 else mp.mpf(0)
    p = 1 + b

    def f(t, s):                                    # s = 1 + t
        v = (1 - t) ** a * _mp_jacobi_series(cf, a, b, t) * mp.log(abs((x + 1) - s))
        return abs(v) if size else v

    def from_left_end(u):
        s = (p * u) ** (1 / p)
        return f(s - 1, s)
    total = mp.quad(from_left_end, [0, (1 + split) ** p / p], **quad)
    total += mp.quad(lambda t: (1 + t) ** b * f(t, 1 + t), [split, 1], **quad)
    return float(total / mp.pi)


@pytest.mark.parametrize("x", [-3.0, -1.0, -0.4, 0.6, 1.3])
@pytest.mark.slow
def test_log_potential_against_mpmath(x):
    """The reference at DPS digits with the end substitution of _log_potential_quad (the
    same values as plain tanh-sinh at 60 digits, to 2e-20); the scale, the integral of
    |psi log|x - t|| that the tolerance is relative to, as _abs_scale's."""
    sol = _solution()
    assert sol.beta < 0 < sol.alpha                 # the singular end is the left one
    with mp.workdps(DPS):
        ref = _log_potential_quad(sol, x)
    with mp.workdps(SCALE_DPS):
        scale = _log_potential_quad(sol, x, size=True, maxdegree=SCALE_DEGREE)
    assert abs(sol.log_potential(np.array([x]))[0] - ref) <= 1e-13 * scale


def test_log_potential_derivative_is_minus_the_hilbert_transform():
    sol = _solution()
    x1, x2 = -0.3, 0.5
    dv = sol.log_potential(np.array([x2]))[0] - sol.log_potential(np.array([x1]))[0]
    t, w = np.polynomial.legendre.leggauss(60)
    xs = x1 + (x2 - x1) * (t + 1) / 2
    integral = (x2 - x1) / 2 * np.sum(w * sol.cauchy(xs))
    assert abs(dv + integral) <= 1e-13


@pytest.mark.parametrize("x", [-1 + 1e-12, -1 + 1e-6, -1 + 1e-3, -0.5])
@pytest.mark.slow
def test_l0_next_to_a_singular_left_end(x):
    """L_0(x) = (1/pi) int w log|x - u| du just inside a singular end (beta = -0.6944): mpmath
    with 1 + u and |x - u| formed as products (no cancellation at 40 digits), to 2e-14
    (the complement of betainc below 0: 2.7e-8 off at -1 + 1e-12 without it)."""
    from sie.cauchy import Weight, l0
    al = 0.6944
    be = -al
    with mp.workdps(40):
        X = mp.mpf(x)
        e = X + 1
        left = mp.quad(lambda s: (2 - e * s) ** al * (e * s) ** be * mp.log(e * (1 - s)) * e,
                       [0, 1])
        right = mp.quad(lambda t: ((1 - X) * (1 - t)) ** al * (e + (1 - X) * t) ** be
                        * mp.log((1 - X) * t) * (1 - X), [0, 1])
        ref = float((left + right) / mp.pi)
    got = float(l0(Weight.plain(al, be), np.array([x]))[0])
    assert abs(got - ref) <= 2e-14 * max(1.0, abs(ref)), (got, ref)


# --------------------------------------------------------------------------
# the forward-recurrence limit of a series
# --------------------------------------------------------------------------
@settings(max_examples=300, deadline=None)
@given(st.lists(st.floats(-1e3, 1e3) | st.just(0.0), min_size=1, max_size=40))
@pytest.mark.slow
def test_series_forward_limit_is_the_stated_bound(coefficients):
    """The compiled limit equals its definition: min(log 2, min over k >= 1, c_k != 0, of
    (log 30 - log(|c_k| / max|c|)) / k), written here with numpy; for it, every term
    |c_k| |rho|^k stays within 30 max|c|."""
    import math
    from sie.cauchy import _forward_limit
    c = np.array(coefficients)
    top = max(float(np.abs(c).max()), np.finfo(float).tiny)
    k = np.flatnonzero(c[1:] != 0.0) + 1
    want = min([math.log(2.0)] + list((math.log(30.0) - np.log(np.abs(c[k]) / top)) / k))
    got = _forward_limit(c.size, c)
    assert got == pytest.approx(want, rel=1e-15, abs=1e-300)
    rho = math.exp(got)
    assert all(abs(ck) * rho ** j <= 30.0 * top * (1 + 1e-12) for j, ck in enumerate(c))
