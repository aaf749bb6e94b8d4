"""Systems with a regular kernel: A psi + (B/pi) PV int psi/(t - s) dt + int K psi dt = f
(sie.system_kernel, through sie.solve_system and sie.solve).

References, each independent of the kernel's assembly:
- a system that a constant change of unknowns and of equations decouples, psi = T chi,
  K = M diag(k_i) T^-1: the scalar solver ``sie.solve`` with each k_i (its own kernel rule);
- a separable kernel K(s, t) = u(s) v(t)^T with complex modes: the kernel-free system
  solver (tests/sie/test_systems.py checks it against mpmath) and one scalar unknown,
  psi = S[f] - c S[u], c = I[S[f]] / (1 + I[S[u]]), I[psi] = int v . psi dt, the moments
  int t^p psi dt taken from the kernel-free solution's Cauchy transform on a circle
  (C(z) = -(1/pi) sum_p z^(-p-1) int t^p psi, by the trapezoid rule, exact to rounding);
- the bilinear orthogonality int w P_j P_k = h_j delta_jk for complex exponents, against
  mpmath quadrature.
"""
from __future__ import annotations

import warnings

import mpmath as mp
import numpy as np
import pytest

import sie
from _stored import StoredReferences
from sie.system_kernel import complex_jacobi_norms, weighted_rule
from sie.systems import solve_system, system_modes

#: mpmath's integrals of the complex-weight test (SIE_TEST_RECOMPUTE_REFS=1 recomputes them,
#: ~30 s)
_REFS = StoredReferences("system_kernel_refs.json")


C_, D_ = -0.3, 1.7                          # an interval other than [-1, 1]
X = np.linspace(C_, D_, 9)[1:-1]

# --------------------------------------------------------------------------
# decoupled: psi = T chi, equations mixed by M
# --------------------------------------------------------------------------
T2 = np.array([[1.0, 0.5], [-0.3, 1.0]])
M2 = np.array([[1.2, 0.3], [-0.4, 0.8]])
A_SC, B_SC = (-0.4, 0.9), (1.0, 2.0)
K_SC = (lambda s, t: 0.5 * np.cos(s - 2.0 * t), lambda s, t: s * t / (3.0 + s + t))
G_SC = (lambda s: 1.0 + s * s, lambda s: np.cos(3.0 * s))


def _mixed_kernel(s, t):
    D = np.zeros((2, 2) + np.shape(s))
    D[0, 0], D[1, 1] = K_SC[0](s, t), K_SC[1](s, t)
    return np.einsum("ia,ab...,bj->ij...", M2, D, np.linalg.inv(T2))


@pytest.mark.parametrize("left,right", [("bounded", "singular"), ("singular", "bounded"),
                                        ("singular", "singular"), ("bounded", "bounded")])
def test_decoupled_system_with_kernel_equals_scalar_solves(left, right):
    Ti = np.linalg.inv(T2)
    A = M2 @ np.diag(A_SC) @ Ti
    B = M2 @ np.diag(B_SC) @ Ti
    both = left == right == "singular"
    tot = (0.7, -1.1) if both else (None, None)
    n = 24
    with np.errstate(all="ignore"), pytest.warns() if left == right == "bounded" else \
            _nothing():
        scal = [sie.solve(g, a=a, b=b, kernel=k, n=n, left=left, right=right,
                          intervals=[(C_, D_)], total=t)
                for g, a, b, k, t in zip(G_SC, A_SC, B_SC, K_SC, tot)]
        sol = sie.solve(lambda s: M2 @ np.array([g(s) for g in G_SC]), a=A, b=B,
                        kernel=_mixed_kernel, n=n, left=left, right=right,
                        intervals=[(C_, D_)], total=list(T2 @ np.array(tot)) if both else None)
    # the modes: lambda = a_i / b_i, ordered by their real parts
    np.testing.assert_allclose(system_modes(A, B).lambdas.real, [-0.4, 0.45], atol=1e-15)
    ref = T2 @ np.array([sc(X) for sc in scal])
    err = np.abs(sol(X) - ref).max() / np.abs(ref).max()
    assert err < 1e-13, err
    if both:
        np.testing.assert_allclose(sol.integral(), T2 @ np.array(tot), rtol=0, atol=1e-13)


class _nothing:
    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


# --------------------------------------------------------------------------
# complex modes, separable kernel
# --------------------------------------------------------------------------
TM = np.array([[1.0, 0.4], [-0.7, 0.9]])
BM = np.array([[1.2, 0.3], [-0.4, 0.8]])
LAM = 0.4 + 0.3j
A_C = BM @ TM @ np.array([[LAM.real, -LAM.imag], [LAM.imag, LAM.real]]) @ np.linalg.inv(TM)


def _f(s):
    return np.array([np.cos(s + 0.2), np.exp(0.5 * s) - 0.3 * s])


def _u(s):
    return np.array([np.cos(2.0 * s), 0.4 + np.exp(-0.5 * s)])


V_POLY = (np.array([1.0, 0.0, 0.5]), np.array([-0.2, 1.0, 0.0, -0.5]))   # v_i(t) = sum c_p t^p


def _v(t):
    return np.array([np.polynomial.polynomial.polyval(t, c) for c in V_POLY])


def _separable(s, t):
    return np.einsum("i...,j...->ij...", _u(s), _v(t))


def _moments(sol, count):
    """int t^p psi_i dt, p < count, from the Cauchy transform on the circle abs(z - m) = 2 h
    about the interval's midpoint: (1/pi) int psi/(t - z) = -(1/pi) sum_p int (t - m)^p
    psi / (z - m)^(p + 1), whose Fourier coefficients the trapezoid rule gives exactly
    (the rest falls like 2^-K)."""
    m, h = 0.5 * (C_ + D_), 0.5 * (D_ - C_)
    K = 128
    theta = 2.0 * np.pi * np.arange(K) / K
    zeta = 2.0 * h * np.exp(1j * theta)
    Cz = sol.cauchy(m + zeta)                                   # (2, K)
    # centred moments mu_p = -pi * mean(C(z) zeta^(p+1))
    mu = np.array([-np.pi * np.mean(Cz * zeta ** (p + 1), axis=1) for p in range(count)]).real
    # int t^p psi = sum_q binom(p, q) m^(p-q) mu_q
    from math import comb
    return np.array([sum(comb(p, q) * m ** (p - q) * mu[q] for q in range(p + 1))
                     for p in range(count)])                   # (count, 2)


def _pairing(sol):
    mom = _moments(sol, 4)
    return sum(c[p] * mom[p, i] for i, c in enumerate(V_POLY) for p in range(len(c)))


@pytest.mark.parametrize("left,right", [("bounded", "singular"), ("singular", "singular"),
                                        ("singular", "bounded")])
def test_complex_modes_separable_kernel_by_rank_one_correction(left, right):
    md = system_modes(A_C, BM)
    assert abs(md.lambdas[1] - LAM) < 1e-14
    both = left == right == "singular"
    tot_f = [0.6, -0.2] if both else None
    tot_u = [0.0, 0.0] if both else None
    n = 28
    kw = dict(n=n, left=left, right=right, interval=(C_, D_))
    psi_f = solve_system(_f, A_C, BM, total=tot_f, **kw)
    psi_u = solve_system(_u, A_C, BM, total=tot_u, **kw)
    c = _pairing(psi_f) / (1.0 + _pairing(psi_u))
    ref = psi_f(X) - c * psi_u(X)
    sol = solve_system(_f, A_C, BM, total=tot_f, kernel=_separable, **kw)
    err = np.abs(sol(X) - ref).max() / np.abs(ref).max()
    assert err < 1e-13, err
    assert sol.imaginary < 1e-14
    # the pairing of the solution with v is the c of the correction
    assert abs(_pairing(sol) - c) < 1e-13 * max(1.0, abs(c))


def test_complex_modes_kernel_converges_spectrally():
    """A kernel that is no polynomial in t (exp, 1/(3 + s + t)): n and 2n agree to rounding,
    and the error at n falls at least geometrically (by 1e-3 per 8 coefficients here)."""
    def K(s, t):
        return np.array([[np.exp(-s * t), 0.3 / (3.0 + s + t)],
                         [np.sin(s + 2.0 * t), 0.2 * np.cos(s * t)]])
    kw = dict(left="bounded", right="singular", interval=(C_, D_), kernel=K)
    ref = solve_system(_f, A_C, BM, n=64, **kw)(X)
    with warnings.catch_warnings():      # n = 8 leaves ~1e-6 between the nodes: warned of
        warnings.simplefilter("ignore", sie.ResidualWarning)
        errs = [np.abs(solve_system(_f, A_C, BM, n=n, **kw)(X) - ref).max() / np.abs(ref).max()
                for n in (8, 16, 32)]
    assert errs[2] < 1e-13, errs
    assert errs[1] < 1e-3 * errs[0] + 1e-14, errs


# --------------------------------------------------------------------------
# the rule for a complex weight
# --------------------------------------------------------------------------
@pytest.mark.parametrize("alpha", [0.3 + 0.2j, -0.5 + 0.12j, -0.2 - 0.4j])
def test_complex_norms_and_rule_against_mpmath(alpha):
    """h_j = int w P_j^2 (bilinear) and int g w P_j for g(v) = exp(v / 2) by the rule, with
    w = (1 - v)^alpha (1 + v)^beta, beta = -kappa - alpha (kappa = 0): mpmath quadrature
    of the Jacobi polynomials with complex parameters (hypergeometric form, DLMF 18.5.7)."""
    mp.mp.dps = 30
    beta = -alpha
    a, b = mp.mpc(alpha.real, alpha.imag), mp.mpc(beta.real, beta.imag)

    def P(j, v):
        return mp.binomial(j + a, j) * mp.hyp2f1(-j, j + a + b + 1, a + 1, (1 - v) / 2)

    def integral(fn):
        # the ends' weight in y: v = 1 - y^4, v = -1 + y^4 (no cancellation in 1 -+ v)
        right = mp.quad(lambda y: 4 * y ** 3 * (y ** 4) ** a * (2 - y ** 4) ** b
                        * fn(1 - y ** 4), [0, 1])
        left = mp.quad(lambda y: 4 * y ** 3 * (2 - y ** 4) ** a * (y ** 4) ** b
                       * fn(-1 + y ** 4), [0, 1])
        return complex(right + left)
    n = 5
    h = complex_jacobi_norms(n, alpha, beta)
    y, Om = weighted_rule(24, n, alpha, beta)
    for j in range(n):
        hj = _REFS.complex(f"h {alpha} {j}", lambda: integral(lambda v: P(j, v) ** 2))
        assert abs(h[j] - hj) < 1e-14 * abs(hj), (j, h[j], hj)
        gj = _REFS.complex(f"exp {alpha} {j}",
                           lambda: integral(lambda v: mp.exp(v / 2) * P(j, v)))
        assert abs(np.exp(y / 2) @ Om[:, j] - gj) < 1e-14 * max(1.0, abs(gj)), j


# --------------------------------------------------------------------------
# bad input
# --------------------------------------------------------------------------
@pytest.mark.parametrize("kernel,error,match", [
    (lambda s, t: s * t, sie.CallableOutputError, r"shape \(m, m\)"),
    (lambda s, t: np.array([[s, t], [t, s]]) * 1j, sie.CallableOutputError, "complex"),
    (lambda s, t: np.array([[s, t], [t, s]]) / 0.0, sie.KernelSingularityError, "evaluated"),
    (lambda s, t: np.array([[1.0 / (s + t - 2 * D_ - 1e-300) + 0 * s, 0 * s], [0 * s, 0 * s]]),
     sie.KernelSingularityError, "grows without bound"),
    (lambda s, t: 1 / 0, sie.KernelSingularityError, "ZeroDivisionError"),
])
def test_bad_kernels(kernel, error, match):
    with np.errstate(all="ignore"), pytest.raises(error, match=match):
        solve_system(_f, A_C, BM, n=6, left="bounded", right="singular", interval=(C_, D_),
                     kernel=kernel)


def test_an_unresolved_kernel_is_warned_of():
    """A kernel that varies on a scale far below the interval's (exp(-40 (s - t)^2)) at n = 8:
    the residual between the nodes says so, as the scalar solver's does."""
    def K(s, t):
        g = np.exp(-40.0 * (s - t) ** 2)
        return np.array([[g, 0.2 * g], [0.0 * g, g]])
    with pytest.warns(sie.ResidualWarning, match="does not resolve f or the kernel"):
        solve_system(_f, A_C, BM, n=8, left="bounded", right="singular", interval=(C_, D_),
                     kernel=K)
    with warnings.catch_warnings():
        warnings.simplefilter("error", sie.ResidualWarning)
        solve_system(_f, A_C, BM, n=96, left="bounded", right="singular", interval=(C_, D_),
                     kernel=K)


# --------------------------------------------------------------------------
# n chosen for the user
# --------------------------------------------------------------------------
def _kernel_smooth(s, t):
    return np.array([[np.exp(-s * t), 0.3 / (3.0 + s + t)],
                     [np.sin(s + 2.0 * t), 0.2 * np.cos(s * t)]])


@pytest.mark.parametrize("tol", [1e-13, 1e-6])
def test_n_auto_resolves_a_system_with_complex_modes_to_its_tolerance(tol):
    """n="auto" doubles n from 16 until every mode's tail is below tol: the solution agrees
    with n = 128 to about tol (each mode's series converges geometrically, so the tail bounds
    the error), with a smaller n for a larger tol."""
    kw = dict(left="bounded", right="singular", intervals=[(C_, D_)], kernel=_kernel_smooth)
    ref = sie.solve(_f, a=A_C, b=BM, n=128, **kw)(X)
    sol = sie.solve(_f, a=A_C, b=BM, n="auto", tol=tol, **kw)
    err = np.abs(sol(X) - ref).max() / np.abs(ref).max()
    assert err <= 10 * tol, (sol.n, err)
    assert sol.n <= (32 if tol > 1e-8 else 64), sol.n
    if tol < 1e-8:
        assert sie.solve(_f, a=A_C, b=BM, n="auto", tol=1e-6, **kw).n < sol.n


def test_n_auto_warns_where_the_data_has_a_kink():
    """f with a kink (abs(s)): the series decays only algebraically, n stops at its largest
    power of two below N_MAX_SYSTEM and says so."""
    from sie.systems import N_MAX_SYSTEM
    with pytest.warns(sie.ResolutionWarning, match="does not resolve the solution"):
        sol = sie.solve(lambda s: np.array([np.abs(s), np.cos(s)]), a=A_C, b=BM, n="auto",
                        left="bounded", right="singular")
    assert sol.n <= N_MAX_SYSTEM < 2 * sol.n


@pytest.mark.parametrize("kw,match", [(dict(n="automatic"), 'integer or "auto"'),
                                      (dict(n=8, tol=1e-8), 'tol is for n="auto" only'),
                                      (dict(n="auto", tol=1.0), r"tol must lie in")])
def test_n_auto_bad_input(kw, match):
    with pytest.raises(sie.InvalidOrderError, match=match):
        sie.solve(_f, a=A_C, b=BM, left="bounded", right="singular", **kw)
