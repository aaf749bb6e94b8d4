"""Tests for ``sie.gauss_jacobi(n, alpha, beta) -> (x, w)``.

The rule is meant to satisfy

    int_{-1}^{1} (1-x)^alpha (1+x)^beta g(x) dx  =  sum_i w_i g(x_i)   (deg g <= 2n-1),

with x_i the zeros of the Jacobi polynomial P_n^{(alpha,beta)}, ascending.

Every reference value is computed independently of the library and of scipy,
in mpmath / exact integer arithmetic (see ``_mpref.py`` for the formulas and
their sources: DLMF 18.9.2 recurrence, DLMF 18.9.16 = Szegő (4.5.7)
derivative, Szegő (15.3.5) Christoffel numbers, DLMF 5.12.1 Beta integral).

Requirements covered:
  0. the reference itself                        test_reference_*
  1. nodes/weights vs. mpmath reference        test_nodes_*, test_weights_*,
                                                 test_chebyshev_rules_match_closed_form
  2. sum of weights = mu_0                       test_weights_sum_to_mu0
  3. exact for polynomials of degree <= 2n-1     test_polynomial_exactness
  4. continuity across dispatch / special params test_dispatch_sweep_*, test_one_ulp_*
  5. reflection symmetry (hypothesis)            test_reflection_*, test_gegenbauer_*
  6. bad input -> ValueError naming the argument test_bad_input_*
  7. n = 10^5 stays finite and sane              test_large_n_*
  large exponents (max(alpha, beta) > 5: O(n^2) rung) test_large_exponent*, test_extreme_*,
     refused up front where it cannot deliver     test_*refused*, test_large_exponent_limit_on_n
"""
from __future__ import annotations

import functools
import math
import re
import time
import warnings

import mpmath
import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from mpmath import mp, mpf

import sie
from sie.gaussjacobi import gauss_jacobi_cached   # memoised, read-only arrays

import _mpref as ref


# ---------------------------------------------------------------------------
# tolerances (the accuracy requirements; do not loosen)
# ---------------------------------------------------------------------------
NODE_ABS_TOL = 1e-14        # |x_lib - x_ref|
WEIGHT_REL_TOL = 1e-13      # |w_lib - w_ref| / w_ref
MU0_REL_TOL = 1e-14         # |sum w - mu_0| / mu_0
MIRROR_NODE_TOL = 1e-14
MIRROR_WEIGHT_REL_TOL = 1e-13
ULP_NODE_TOL = 1e-13
ULP_WEIGHT_REL_TOL = 1e-13
# Polynomial exactness: with w_i > 0 and |x_i| <= 1, perturbations dx, dw change
# sum w x^k by at most (k max|dx| + max|dw/w|) mu_0; a rule accurate to a few
# ulps (n <= 12, k <= 23) is off by < ~5e-15 mu_0.  The sums are formed exactly
# (mpmath) so only the library's nodes and weights contribute.
MOMENT_TOL_REL_MU0 = 1e-14


def _pid(n, a, b):
    return f"n={n}-a={a:g}-b={b:g}"


def _slow_if(cases, heavy):
    """The cases as parameters; one where heavy(*case) is true is marked slow (not in
    make test-fast)."""
    return [pytest.param(*c, marks=pytest.mark.slow) if heavy(*c) else c for c in cases]


# ---------------------------------------------------------------------------
# parameter sets
# ---------------------------------------------------------------------------
EXPONENTS = (-0.99, -0.5, 0.0, 0.5, 0.99)
GRID_PAIRS = [(a, b) for a in EXPONENTS for b in EXPONENTS]
ASYMMETRIC_PAIRS = [(-0.99, 0.99), (0.3, -0.7), (-0.4, -0.6)]
ALL_PAIRS = list(dict.fromkeys(GRID_PAIRS + ASYMMETRIC_PAIRS))          # 27 pairs

# every node checked for n <= 200; first/last 25 + 20 interior nodes above
N_FULL = (1, 2, 3, 5, 10, 50, 100, 101, 200)
# n = 10^4 costs ~1 s per pair in the reference: the corners and the centre of the grid
# and two asymmetric pairs (every pair of the grid is checked at n = 1000; the rule for
# (b, a) is the mirror image of (a, b), tested separately in 5.)
PAIRS_10K = [(-0.99, -0.99), (-0.99, 0.99), (0.99, 0.99), (0.0, 0.0), (0.3, -0.7), (-0.4, -0.6)]

REFERENCE_CASES = ([(n, a, b) for n in N_FULL + (1000,) for (a, b) in ALL_PAIRS]
                   + [(10_000, a, b) for (a, b) in PAIRS_10K])

# Requirement 4: every n in 20..200 (the method switch is somewhere in there)
SWEEP_PAIRS = [(0.3, -0.7), (-0.99, 0.99), (0.0, 0.0)]
SWEEP_CASES = [(n, a, b) for (a, b) in SWEEP_PAIRS for n in range(20, 201)]

# in make test-fast: the references up to n = 50, every 20th n of the sweep
REFERENCE_PARAMS = _slow_if(REFERENCE_CASES, lambda n, a, b: n > 50)
SWEEP_PARAMS = _slow_if(SWEEP_CASES, lambda n, a, b: n % 20 != 0)


# ---------------------------------------------------------------------------
# library vs. mpmath reference (cached: node and weight tests share it)
# ---------------------------------------------------------------------------
class Comparison:
    """Library rule vs. refined roots/weights for the checked node indices."""

    def __init__(self, n, alpha, beta):
        x, w = gauss_jacobi_cached(n, alpha, beta)
        self.n, self.alpha, self.beta = n, alpha, beta
        self.x, self.w = x, w
        self.index = ref.check_indices(n)
        self.r = ref.refine_gauss_jacobi(n, alpha, beta, x, self.index)
        with mp.workdps(ref.DPS):
            ex, ew = [], []
            for j, i in enumerate(self.index):
                if self.r.converged[j]:
                    ex.append(float(abs(mpf(float(x[i])) - self.r.x[j])))
                    ew.append(float(abs(mpf(float(w[i])) - self.r.w[j]) / self.r.w[j]))
                else:
                    ex.append(math.inf)
                    ew.append(math.inf)
            # gaps between consecutive refined roots (they must be distinct roots)
            self.gaps = [float(self.r.x[j + 1] - self.r.x[j]) for j in range(len(self.index) - 1)]
        self.node_err = np.array(ex)
        self.weight_err = np.array(ew)

    def worst(self, err):
        j = int(np.argmax(err))
        i = self.index[j]
        return (f"max error {err[j]:.3e} at node i={i} of n={self.n} "
                f"(x_lib={self.x[i]!r}, x_ref={mpmath.nstr(self.r.x[j], 20)}, "
                f"w_lib={self.w[i]!r}, w_ref={mpmath.nstr(self.r.w[j], 20)})")


@functools.lru_cache(maxsize=None)
def comparison(n, alpha, beta):
    return Comparison(n, alpha, beta)


def assert_roots_identified(c: Comparison):
    """The library's nodes lead Newton to *distinct* zeros of P_n, in order,
    and the Sturm count says each is the zero with the library's index."""
    bad = [i for i, ok in zip(c.index, c.r.converged) if not ok]
    assert not bad, f"Newton from the library's nodes did not converge to a zero of P_n at i={bad[:10]}"
    assert all(g > 1e-25 for g in c.gaps), (
        f"refined zeros not strictly increasing/distinct: min gap {min(c.gaps):.3e} "
        "(two library nodes are near the same zero of P_n)")
    wrong = [(i, k) for i, k in zip(c.index, c.r.sturm_index) if i != k]
    assert not wrong, f"(library index, true index of the zero it approximates): {wrong[:10]}"


def assert_output_contract(x, w, n):
    assert isinstance(x, np.ndarray) and isinstance(w, np.ndarray)
    assert x.dtype == np.float64 and w.dtype == np.float64
    assert x.shape == (n,) and w.shape == (n,)
    assert np.all(np.isfinite(x)) and np.all(np.isfinite(w))
    assert np.all(np.diff(x) > 0), "nodes not strictly ascending"
    assert np.all((x > -1) & (x < 1)), "nodes outside (-1, 1)"
    assert np.all(w > 0), "non-positive weight"


# ---------------------------------------------------------------------------
# 0. sanity of the reference itself (cheap; a broken reference must not pass silently)
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("n,a,b,x", [
    (1, 0.3, -0.7, 0.2), (2, -0.99, 0.99, -0.9), (7, 0.5, 0.5, 0.999),
    (30, -0.4, -0.6, -0.99999), (50, 0.99, -0.99, 0.3), (64, 0.0, 0.0, 1 - 2.0**-40),
], ids=lambda v: f"{v:g}" if isinstance(v, float) else str(v))
def test_reference_recurrence_matches_mpmath_jacobi(n, a, b, x):
    """Fixed-point DLMF 18.9.2 recurrence == mpmath.jacobi (hypergeometric 2F1, DLMF 18.5.7)."""
    p, pm1 = ref.jacobi_p_pair(n, a, b, x)
    with mp.workdps(80):
        want = mpmath.jacobi(n, mpf(a), mpf(b), mpf(x))
        want_m1 = mpmath.jacobi(n - 1, mpf(a), mpf(b), mpf(x))
        assert abs(p - want) <= mpf("1e-40") * max(1, abs(want))
        assert abs(pm1 - want_m1) <= mpf("1e-40") * max(1, abs(want_m1))


@pytest.mark.slow
def test_reference_fixed_point_matches_mpf_recurrence_long():
    """n = 3000: integer fixed point vs. the same recurrence in plain mpmath mpf."""
    for x in (0.9999, -0.3, 1 - 1e-9):
        p, _ = ref.jacobi_p_pair(3000, 0.3, -0.7, x)
        q = ref.jacobi_p_mpf(3000, 0.3, -0.7, x)
        assert abs(p - q) <= mpf("1e-35") * max(1, abs(q))


def _golub_welsch_guess(n, a, b):
    """Eigenvalues of the Jacobi matrix in numpy (independent of sie and scipy)."""
    with mp.workdps(30):
        a_, b_ = mpf(a), mpf(b)
        s = a_ + b_
        diag = [float((b_ - a_) / (s + 2))] + [
            float((b_**2 - a_**2) / ((2 * k + s) * (2 * k + s + 2))) for k in range(1, n)]
        # b_k^2 = 4k(k+a)(k+b)(k+s) / ((2k+s)^2 (2k+s+1)(2k+s-1)); for k = 1 the factor
        # (k+s)/(2k+s-1) = 1 is cancelled by hand (it is 0/0 when s = -1)
        off = [float(mpmath.sqrt(4 * (1 + a_) * (1 + b_) / ((2 + s) ** 2 * (3 + s))))] + [
            float(mpmath.sqrt(4 * k * (k + a_) * (k + b_) * (k + s)
                              / ((2 * k + s) ** 2 * (2 * k + s + 1) * (2 * k + s - 1))))
            for k in range(2, n)]
    J = np.diag(diag) + np.diag(off, 1) + np.diag(off, -1)
    return np.linalg.eigvalsh(J)


@pytest.mark.parametrize("n,a,b", [(1, 0.3, -0.7), (17, -0.99, 0.99), (64, 0.3, -0.7), (60, -0.5, -0.5)],
                         ids=lambda v: f"{v:g}" if isinstance(v, float) else str(v))
def test_reference_rule_is_a_gauss_rule(n, a, b):
    """Reference weights sum to mu_0 (to 1e-40) and Sturm indices are 0..n-1,
    starting from a numpy Golub-Welsch guess (not from the library)."""
    r = ref.refine_gauss_jacobi(n, a, b, _golub_welsch_guess(n, a, b), range(n))
    assert all(r.converged)
    assert r.sturm_index == list(range(n))
    with mp.workdps(ref.DPS):
        assert abs(mpmath.fsum(r.w) / ref.mu0(a, b) - 1) < mpf("1e-40")
        if (a, b) == (-0.5, -0.5):   # Gauss-Chebyshev: x_k = cos((2k+1)pi/(2n)), w_k = pi/n
            cheb = sorted(mpmath.cos((2 * k + 1) * mpmath.pi / (2 * n)) for k in range(n))
            assert max(abs(u - v) for u, v in zip(r.x, cheb)) < mpf("1e-40")
            assert max(abs(wk - mpmath.pi / n) for wk in r.w) < mpf("1e-40")


def test_reference_moments_closed_forms():
    """Binomial/Beta moment formula vs. Legendre (2/(k+1)) and Chebyshev (pi binom(2j,j)/4^j)."""
    leg = ref.jacobi_moments(0.0, 0.0, 23)
    cheb = ref.jacobi_moments(-0.5, -0.5, 23)
    with mp.workdps(ref.DPS):
        for k in range(24):
            want_leg = mpf(2) / (k + 1) if k % 2 == 0 else mpf(0)
            want_cheb = mpmath.pi * mpmath.binomial(k, k // 2) / 4 ** (k // 2) if k % 2 == 0 else mpf(0)
            assert abs(leg[k] - want_leg) < mpf("1e-40")
            assert abs(cheb[k] - want_cheb) < mpf("1e-40")


# ---------------------------------------------------------------------------
# 1. nodes and weights against the mpmath reference
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("n,alpha,beta", REFERENCE_PARAMS, ids=[_pid(*c) for c in REFERENCE_CASES])
def test_nodes_match_mpmath_reference(n, alpha, beta):
    c = comparison(n, alpha, beta)
    assert_output_contract(c.x, c.w, n)
    assert_roots_identified(c)
    assert c.node_err.max() <= NODE_ABS_TOL, c.worst(c.node_err)


@pytest.mark.parametrize("n,alpha,beta", REFERENCE_PARAMS, ids=[_pid(*c) for c in REFERENCE_CASES])
def test_weights_match_mpmath_reference(n, alpha, beta):
    c = comparison(n, alpha, beta)
    assert c.weight_err.max() <= WEIGHT_REL_TOL, c.worst(c.weight_err)


# ---------------------------------------------------------------------------
# 1b. Chebyshev cases in closed form (every node up to n = 10^4, a subset at 10^5)
#     alpha = beta = -1/2: T_n(cos t) = cos(n t) (DLMF 18.5.1), so
#        x_k = cos((2k+1) pi / (2n)),  w_k = pi / n          (A&S 25.4.38);
#     alpha = beta = +1/2: U_n(cos t) = sin((n+1) t)/sin t (DLMF 18.5.2), so
#        x_k = cos((k+1) pi / (n+1)),  w_k = pi/(n+1) sin^2((k+1) pi/(n+1))
#     (Christoffel numbers, Szegő (15.3.5)).  Listed ascending: k -> n-1-k.
CHEBYSHEV_CASES = [(n, a) for a in (-0.5, 0.5) for n in (1, 2, 7, 64, 101, 1000, 10_000, 100_000)]
CHEBYSHEV_PARAMS = _slow_if(CHEBYSHEV_CASES, lambda n, a: n >= 10_000)   # in make test-fast: n <= 1000


def chebyshev_rule(n, a, index):
    """Closed-form nodes/weights at the given (ascending) indices, rounded to double."""
    with mp.workdps(30):
        if a == -0.5:
            th = [(2 * (n - 1 - k) + 1) * mp.pi / (2 * n) for k in index]
            w = [float(mp.pi / n)] * len(th)
        else:
            th = [(n - k) * mp.pi / (n + 1) for k in index]
            w = [float(mp.pi / (n + 1) * mp.sin(t) ** 2) for t in th]
        return np.array([float(mp.cos(t)) for t in th]), np.array(w)


@pytest.mark.parametrize("n,a", CHEBYSHEV_PARAMS, ids=[f"n={n}-a=b={a:g}" for n, a in CHEBYSHEV_CASES])
def test_chebyshev_rules_match_closed_form(n, a):
    x, w = gauss_jacobi_cached(n, a, a)
    # all nodes up to 10^4; for 10^5 the 500 at each end and every 37th in between
    index = np.arange(n) if n <= 10_000 else np.unique(np.r_[0:500, n - 500:n, 0:n:37])
    x, w = x[index], w[index]
    x_ref, w_ref = chebyshev_rule(n, a, index.tolist())   # correctly rounded (~1e-16 rel)
    ex = np.abs(x - x_ref)
    ew = np.abs(w - w_ref) / w_ref
    i, j = int(np.argmax(ex)), int(np.argmax(ew))
    assert ex[i] <= NODE_ABS_TOL, f"node error {ex[i]:.3e} at i={index[i]}: {x[i]!r} vs {x_ref[i]!r}"
    assert ew[j] <= WEIGHT_REL_TOL, f"weight rel. error {ew[j]:.3e} at i={index[j]}: {w[j]!r} vs {w_ref[j]!r}"


# ---------------------------------------------------------------------------
# 2. sum of the weights is the zeroth moment
# ---------------------------------------------------------------------------
N_MU0 = (1, 2, 5, 50, 100, 101, 1000, 10_000)
MU0_CASES = ([(n, a, b) for n in N_MU0 for (a, b) in ALL_PAIRS]
             + [(100_000, a, b) for (a, b) in [(-0.99, 0.99), (0.3, -0.7), (0.0, 0.0)]])


@pytest.mark.parametrize("n,alpha,beta", MU0_CASES, ids=[_pid(*c) for c in MU0_CASES])
def test_weights_sum_to_mu0(n, alpha, beta):
    """sum_i w_i = mu_0 = 2^(a+b+1) Gamma(a+1) Gamma(b+1) / Gamma(a+b+2)  (DLMF 5.12.1)."""
    _, w = gauss_jacobi_cached(n, alpha, beta)
    total = math.fsum(w)                     # correctly rounded sum of the library's weights
    mu0 = ref.mu0(alpha, beta)
    with mp.workdps(ref.DPS):
        rel = float(abs(mpf(total) - mu0) / mu0)
    assert rel <= MU0_REL_TOL, f"|sum w - mu0|/mu0 = {rel:.3e} (sum w = {total!r}, mu0 = {mpmath.nstr(mu0, 20)})"


# ---------------------------------------------------------------------------
# 3. exact for x^k, k <= 2n-1
# ---------------------------------------------------------------------------
EXACTNESS_CASES = [(n, a, b) for n in range(1, 13) for (a, b) in ALL_PAIRS]
EXACTNESS_PARAMS = _slow_if(EXACTNESS_CASES, lambda n, a, b: n > 6)      # in make test-fast: n <= 6


@pytest.mark.parametrize("n,alpha,beta", EXACTNESS_PARAMS, ids=[_pid(*c) for c in EXACTNESS_CASES])
def test_polynomial_exactness(n, alpha, beta):
    """sum_i w_i x_i^k = int (1-x)^a (1+x)^b x^k dx for k = 0..2n-1 (moments: DLMF 5.12.1)."""
    x, w = gauss_jacobi_cached(n, alpha, beta)
    moments = ref.jacobi_moments(alpha, beta, 2 * n - 1)
    with mp.workdps(ref.DPS):
        xs = [mpf(float(v)) for v in x]
        ws = [mpf(float(v)) for v in w]
        tol = MOMENT_TOL_REL_MU0 * moments[0]
        errs = [abs(mpmath.fsum(wi * xi**k for wi, xi in zip(ws, xs)) - moments[k])
                for k in range(2 * n)]
        k_worst = max(range(2 * n), key=lambda k: errs[k])
        assert errs[k_worst] <= tol, (
            f"degree k={k_worst}: |sum w x^k - m_k| = {float(errs[k_worst]):.3e} "
            f"= {float(errs[k_worst] / moments[0]):.3e} mu_0")


# ---------------------------------------------------------------------------
# 3b. extreme exponents (each case defeats a plain version of some rung)
# ---------------------------------------------------------------------------
EXTREME_CASES = [
    # exponent within 1e-8..1e-12 of -1 on the asymptotic rung: the Gatteschi-Pittaluga start
    # of the first node is ~1e3..1e6 times too far out (Newton in theta only halves it)
    (101, -1.0 + 1e-8, 0.0), (101, -1.0 + 1e-10, 0.5), (150, -1.0 + 1e-12, 0.5),
    # both exponents near -1: s = 2 + a + b cancels in the recurrence coefficients
    (30, -1.0 + 1e-8, -1.0 + 1e-8), (60, -1.0 + 1e-8, -1.0 + 1e-8),
    # large exponents: the dd boundary series cancels more than dd holds (recurrence there)
    (60, 30.0, 0.0), (300, 10.0, -0.5), (400, 8.0, 0.0),
    # a Golub-Welsch eigenvalue at or beyond -1 (angle 0 start; the node is within one
    # double spacing of -1)
    (200, 7.0, -1.0 + 1e-14), (400, 7.0, -1.0 + 1e-12),
    # large exponents where the dd series can stop at a point of its own noise that is no root
    # (the nodes then come out not ascending; found by a random search over exponents <= 500)
    (896, 9.717318491045363, 55.780305189519034), (88, 112.03049493219392, 6.355986612205065),
    (304, 0.6039799211475647, 200.95055405006207), (99, 429.85777933720095, 35.3937981072577),
]


@pytest.mark.parametrize("n,alpha,beta", EXTREME_CASES, ids=[_pid(*c) for c in EXTREME_CASES])
def test_extreme_exponents_match_mpmath_reference(n, alpha, beta):
    c = comparison(n, alpha, beta)
    assert_output_contract(c.x, c.w, n)
    assert_roots_identified(c)
    # a node within 1e-16 of an end is only representable to the spacing of doubles there
    assert c.node_err.max() <= NODE_ABS_TOL, c.worst(c.node_err)
    assert c.weight_err.max() <= WEIGHT_REL_TOL, c.worst(c.weight_err)


# ---------------------------------------------------------------------------
# 3c. large exponents (max(alpha, beta) > 5: the O(n^2) rung for every n)
# ---------------------------------------------------------------------------
# A recurrence normalised at the end cancels like n^max / max!: in these cases it leaves the
# weights off by ~4e-9 .. 2e-6 or loses all accuracy, and the nodes are off too (1.5e-9 at
# n = 200, alpha = 20, where scipy.special.roots_jacobi has 2e-16).
LARGE_EXPONENT_CASES = [(200, 20.0, 0.0), (200, 0.0, 20.0), (1000, 10.0, -0.5), (300, 12.0, -0.5),
                        (300, 15.0, 0.0), (1000, 20.0, 0.0), (1000, 0.0, 15.0),
                        (3000, -0.999999, 20.0)]


@pytest.mark.parametrize("n,alpha,beta", LARGE_EXPONENT_CASES, ids=[_pid(*c) for c in LARGE_EXPONENT_CASES])
@pytest.mark.slow
def test_large_exponents_match_mpmath_reference_without_warning(n, alpha, beta):
    """The cases above, where a recurrence normalised at the end loses accuracy: nodes and
    weights to the same tolerances as everywhere else, and no warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        gauss_jacobi_cached(n, alpha, beta)
    c = comparison(n, alpha, beta)
    assert_output_contract(c.x, c.w, n)
    assert_roots_identified(c)
    assert c.node_err.max() <= NODE_ABS_TOL, c.worst(c.node_err)
    assert c.weight_err.max() <= WEIGHT_REL_TOL, c.worst(c.weight_err)


def test_large_exponent_nodes_n200_alpha20():
    """n = 200, (alpha, beta) = (20, 0): nodes to ~1 ulp and weights to 2e-14 (a recurrence
    normalised at the end leaves the nodes 1.5e-9 and the weights 1.1e-6 off here)."""
    c = comparison(200, 20.0, 0.0)
    assert c.node_err.max() <= 1e-15, c.worst(c.node_err)
    assert c.weight_err.max() <= 2e-14, c.worst(c.weight_err)


@pytest.mark.parametrize("n,alpha,beta", [(2, 300.0, 0.5), (7, 40.0, 60.0), (250, 6.5, 6.5)])
def test_large_exponents_weights_sum_to_mu0(n, alpha, beta):
    _, w = sie.gauss_jacobi(n, alpha, beta)
    with mp.workdps(ref.DPS):
        rel = float(abs(mpf(math.fsum(w)) - ref.mu0(alpha, beta)) / ref.mu0(alpha, beta))
    assert rel <= MU0_REL_TOL


@settings(max_examples=15, deadline=None)
@given(n=st.integers(min_value=2, max_value=300),
       alpha=st.floats(min_value=5.0, max_value=60.0, exclude_min=True),
       beta=st.floats(min_value=-0.999, max_value=60.0))
def test_large_exponents_reflection(n, alpha, beta):
    x_ab, w_ab = sie.gauss_jacobi(n, alpha, beta)
    x_ba, w_ba = sie.gauss_jacobi(n, beta, alpha)
    assert_output_contract(x_ab, w_ab, n)
    assert np.max(np.abs(x_ba + x_ab[::-1])) <= MIRROR_NODE_TOL
    assert np.max(np.abs(w_ba - w_ab[::-1]) / w_ab[::-1]) <= MIRROR_WEIGHT_REL_TOL


def test_large_n_with_large_exponent_is_refused_fast():
    """gauss_jacobi(100_000, -0.999999, 20.0) would work ~280 s in the O(n^2) rung: it is
    refused up front (InvalidOrderError, a ValueError), with a message that says what n and
    exponents are, what would be lost (time, not accuracy) and what is allowed."""
    t0 = time.perf_counter()
    with pytest.raises(sie.errors.InvalidOrderError) as info:
        sie.gauss_jacobi(100_000, -0.999999, 20.0)
    assert time.perf_counter() - t0 < 2.0        # measured: ~10 us
    msg = str(info.value)
    assert "n=100000" in msg and "alpha=-0.999999" in msg and "beta=20.0" in msg
    assert re.search(r"n must be <= 20000 when max\(alpha, beta\) > 5", msg), msg
    assert re.search(r"would take ~\d+ min", msg), msg
    assert "Accuracy is not the limit" in msg and "weights within ~3e-14" in msg, msg
    assert isinstance(info.value, ValueError)


@pytest.mark.parametrize("n,alpha,beta", [(20_001, 5.5, 0.0), (20_001, 0.0, 30.0)])
def test_large_exponent_limit_on_n(n, alpha, beta):
    with pytest.raises(ValueError, match=r"\bn must be <= 20000"):
        sie.gauss_jacobi(n, alpha, beta)


def test_small_exponents_have_no_limit_on_n():
    assert sie.gauss_jacobi(100_000, 5.0, -0.999999)[0].shape == (100_000,)


def test_weights_below_double_range_are_refused_before_any_work():
    """(20000, 60, 0): the weights next to x = 1 would be ~1e-321 (estimate; < 2.2e-308)."""
    t0 = time.perf_counter()
    with pytest.raises(FloatingPointError, match=r"would be ~1e-32\d, below the smallest normal"
                                                 r".*refused before starting.*Allowed:"):
        sie.gauss_jacobi(20_000, 60.0, 0.0)
    assert time.perf_counter() - t0 < 2.0


def test_weights_below_double_range_found_afterwards_raise():
    """(2509, 100, 0): the estimate (-308.3) lets it through; one weight is 5e-309."""
    with pytest.raises(FloatingPointError, match=r"1 weight\(s\) outside the range of normal doubles"):
        sie.gauss_jacobi(2509, 100.0, 0.0)


def test_common_case_pays_nothing_for_the_large_exponent_checks(monkeypatch):
    """The checks run only when max(alpha, beta) > 5."""
    from sie import gaussjacobi

    def boom(*args):
        raise AssertionError("large-exponent check called for small exponents")
    monkeypatch.setattr(gaussjacobi, "_check_large_exponents", boom)
    monkeypatch.setattr(gaussjacobi, "_check_rung2", boom)
    for n in (2, 50, 101, 10_000):
        gaussjacobi.gauss_jacobi(n, -0.4, -0.6)


# ---------------------------------------------------------------------------
# 4a. continuity across the method switch: every n = 20..200 against mpmath
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("n,alpha,beta", SWEEP_PARAMS, ids=[_pid(*c) for c in SWEEP_CASES])
def test_dispatch_sweep_nodes(n, alpha, beta):
    c = comparison(n, alpha, beta)
    assert_roots_identified(c)
    assert c.node_err.max() <= NODE_ABS_TOL, c.worst(c.node_err)


@pytest.mark.parametrize("n,alpha,beta", SWEEP_PARAMS, ids=[_pid(*c) for c in SWEEP_CASES])
def test_dispatch_sweep_weights(n, alpha, beta):
    c = comparison(n, alpha, beta)
    assert c.weight_err.max() <= WEIGHT_REL_TOL, c.worst(c.weight_err)


# ---------------------------------------------------------------------------
# 4a'. the small-n rule (Halley on the recurrence for every node, n <= N_RECURRENCE_MAX)
#      is what gauss_jacobi takes up to its bound, and nothing beyond; where it gives up,
#      the rungs behind it still deliver the mpmath reference
# ---------------------------------------------------------------------------
SMALL_N_RULE_NS = (2, 3, 20, 21, 50, 99, 100)


@pytest.mark.parametrize("n", SMALL_N_RULE_NS)
def test_small_n_rule_finishes_every_node(n):
    """Every pair of the grid (and exponents within 1e-8 of -1) converges on the small-n rule,
    with the output contract (so gauss_jacobi does not fall back to a slower rung)."""
    from sie import gaussjacobi
    for alpha, beta in ALL_PAIRS + [(-1.0 + 1e-8, -1.0 + 1e-8), (5.0, -0.99)]:
        x, w, ok = gaussjacobi._recurrence_rule(n, alpha, beta)
        assert ok, f"small-n rule gave up at n={n}, alpha={alpha!r}, beta={beta!r}"
        assert_output_contract(x, w, n)


def test_small_n_rule_dispatch_bound(monkeypatch):
    """n = N_RECURRENCE_MAX takes the small-n rule, n = N_RECURRENCE_MAX + 1 does not."""
    from sie import gaussjacobi
    calls = []
    rule = gaussjacobi._recurrence_rule

    def spy(n, a, b):
        calls.append(n)
        return rule(n, a, b)
    monkeypatch.setattr(gaussjacobi, "_recurrence_rule", spy)
    nmax = gaussjacobi.N_RECURRENCE_MAX
    for n in (2, nmax, nmax + 1):
        gaussjacobi.gauss_jacobi(n, 0.3, -0.7)
    gaussjacobi.gauss_jacobi(nmax, 6.0, 0.0)           # large exponents: rung 2
    assert calls == [2, nmax]


@pytest.mark.parametrize("n,alpha,beta", [(20, -0.99, 0.99), (100, -0.99, 0.99), (60, 0.3, -0.7)],
                         ids=lambda v: f"{v:g}" if isinstance(v, float) else str(v))
def test_small_n_rule_fallback_matches_mpmath_reference(n, alpha, beta, monkeypatch):
    """With the small-n rule made to give up, gauss_jacobi still meets the tolerances (the
    Golub-Welsch rule for n <= 20, rung 3 above), at the nodes the reference checks."""
    from sie import gaussjacobi
    monkeypatch.setattr(gaussjacobi, "_recurrence_rule",
                        lambda n, a, b: (np.zeros(n), np.zeros(n), False))
    x, w = gaussjacobi.gauss_jacobi(n, alpha, beta)
    assert_output_contract(x, w, n)
    index = ref.check_indices(n, n_edge=5, n_interior=5)
    r = ref.refine_gauss_jacobi(n, alpha, beta, x, index)
    assert all(r.converged) and r.sturm_index == list(index)
    with mp.workdps(ref.DPS):
        ex = max(float(abs(mpf(float(x[i])) - r.x[j])) for j, i in enumerate(index))
        ew = max(float(abs(mpf(float(w[i])) - r.w[j]) / r.w[j]) for j, i in enumerate(index))
    assert ex <= NODE_ABS_TOL and ew <= WEIGHT_REL_TOL, (ex, ew)


# ---------------------------------------------------------------------------
# 4b. special parameters: a one-ulp nudge must not change the rule
#     (d x_i / d alpha is O(1), so a 2.2e-16 nudge moves the true rule by ~1e-16)
# ---------------------------------------------------------------------------
SPECIAL_PAIRS = [(-0.5, -0.5), (0.0, 0.0), (0.5, 0.5), (-0.5, 0.5), (0.5, -0.5)]
ULP_CASES = [(n, a, b, which, direction)
             for (a, b) in SPECIAL_PAIRS
             for which in ("alpha", "beta", "both")
             for direction in ("up", "down")
             for n in (3, 50, 101, 1000)]


@pytest.mark.parametrize(
    "n,alpha,beta,which,direction", ULP_CASES,
    ids=[f"{_pid(n, a, b)}-nudge_{wh}_{d}" for (n, a, b, wh, d) in ULP_CASES])
def test_one_ulp_nudge_of_special_parameters(n, alpha, beta, which, direction):
    to = math.inf if direction == "up" else -math.inf
    a2 = float(np.nextafter(alpha, to)) if which in ("alpha", "both") else alpha
    b2 = float(np.nextafter(beta, to)) if which in ("beta", "both") else beta
    assert (a2, b2) != (alpha, beta)
    x0, w0 = gauss_jacobi_cached(n, alpha, beta)
    x1, w1 = gauss_jacobi_cached(n, a2, b2)
    dx = np.max(np.abs(x1 - x0))
    dw = np.max(np.abs(w1 - w0) / w0)
    assert dx <= ULP_NODE_TOL, f"nodes moved by {dx:.3e} (alpha={a2!r}, beta={b2!r})"
    assert dw <= ULP_WEIGHT_REL_TOL, f"weights moved by {dw:.3e} relative (alpha={a2!r}, beta={b2!r})"


# ---------------------------------------------------------------------------
# 5. reflection symmetry: P_n^{(a,b)}(-x) = (-1)^n P_n^{(b,a)}(x)  (DLMF 18.6.1)
# ---------------------------------------------------------------------------
exponent = st.floats(min_value=-0.999, max_value=2.0, exclude_max=True, allow_nan=False)
order = st.integers(min_value=1, max_value=400)


@settings(max_examples=30, deadline=None)
@given(n=order, alpha=exponent, beta=exponent)
@example(n=1, alpha=-0.999, beta=1.999)
@example(n=400, alpha=1.999, beta=-0.999)
@example(n=101, alpha=-0.5, beta=0.5)
@example(n=86, alpha=-0.7757587693724189, beta=-0.7917984580129861)   # found by random search
def test_reflection_swaps_alpha_and_beta(n, alpha, beta):
    """gauss_jacobi(n, b, a) is the mirror image of gauss_jacobi(n, a, b)."""
    x_ab, w_ab = sie.gauss_jacobi(n, alpha, beta)
    x_ba, w_ba = sie.gauss_jacobi(n, beta, alpha)
    dx = np.max(np.abs(x_ba + x_ab[::-1]))
    dw = np.max(np.abs(w_ba - w_ab[::-1]) / w_ab[::-1])
    assert dx <= MIRROR_NODE_TOL, f"mirror nodes differ by {dx:.3e}"
    assert dw <= MIRROR_WEIGHT_REL_TOL, f"mirror weights differ by {dw:.3e} relative"


@settings(max_examples=30, deadline=None)
@given(n=order, alpha=exponent)
@example(n=1, alpha=0.7)
@example(n=400, alpha=-0.999)
@example(n=101, alpha=1.999)
@example(n=86, alpha=-0.9984808667623498)                              # found by random search
def test_gegenbauer_rule_is_symmetric(n, alpha):
    """alpha == beta: x_i = -x_{n-1-i}, w_i = w_{n-1-i}; x = 0 is a node for odd n."""
    x, w = sie.gauss_jacobi(n, alpha, alpha)
    dx = np.max(np.abs(x + x[::-1]))
    dw = np.max(np.abs(w - w[::-1]) / w)
    assert dx <= MIRROR_NODE_TOL, f"nodes not symmetric: {dx:.3e}"
    assert dw <= MIRROR_WEIGHT_REL_TOL, f"weights not symmetric: {dw:.3e} relative"
    if n % 2 == 1:
        assert abs(x[n // 2]) <= MIRROR_NODE_TOL


# ---------------------------------------------------------------------------
# 6. bad input
# ---------------------------------------------------------------------------
BAD_INPUTS = [
    ("n", (0, 0.5, 0.5)),
    ("n", (-3, 0.5, 0.5)),
    ("n", (2.5, 0.5, 0.5)),
    ("n", (math.nan, 0.5, 0.5)),
    ("alpha", (5, -1.0, 0.5)),
    ("beta", (5, 0.5, -1.5)),
    ("alpha", (5, math.nan, 0.5)),
    ("beta", (5, 0.5, math.inf)),
    ("alpha", (5, -math.inf, 0.5)),
    ("beta", (5, 0.5, math.nan)),
    ("beta", (5, 0.5, -1.0)),
]


@pytest.mark.parametrize("name,args", BAD_INPUTS,
                         ids=[f"{name}-n={a[0]}-a={a[1]}-b={a[2]}" for name, a in BAD_INPUTS])
def test_bad_input_raises_value_error_naming_argument(name, args):
    with pytest.raises(ValueError) as info:
        sie.gauss_jacobi(*args)
    msg = str(info.value)
    assert re.search(rf"\b{name}\b", msg), f"message does not name {name!r}: {msg!r}"


def test_numpy_integer_n_is_accepted():
    x, w = sie.gauss_jacobi(np.int64(7), 0.3, -0.7)
    assert_output_contract(x, w, 7)


# ---------------------------------------------------------------------------
# 7. n = 10^5 stays finite
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("alpha,beta", [(-0.99, 0.99), (0.99, -0.99)], ids=["a=-0.99-b=0.99", "a=0.99-b=-0.99"])
def test_large_n_is_finite_ordered_positive(alpha, beta):
    n = 100_000
    x, w = gauss_jacobi_cached(n, alpha, beta)
    assert_output_contract(x, w, n)
    mu0 = ref.mu0(alpha, beta)
    with mp.workdps(ref.DPS):
        rel = float(abs(mpf(math.fsum(w)) - mu0) / mu0)
    assert rel <= MU0_REL_TOL, f"|sum w - mu0|/mu0 = {rel:.3e}"


@pytest.mark.slow
def test_large_n_end_nodes_match_mpmath_reference():
    """Beyond the n <= 1e4 of the accuracy requirements: the 6 nodes at each end for
    n = 10^5, same tolerances."""
    n, alpha, beta = 100_000, -0.99, 0.99
    x, w = gauss_jacobi_cached(n, alpha, beta)
    index = list(range(6)) + list(range(n - 6, n))
    r = ref.refine_gauss_jacobi(n, alpha, beta, x, index)
    assert all(r.converged) and r.sturm_index == index
    with mp.workdps(ref.DPS):
        ex = [float(abs(mpf(float(x[i])) - r.x[j])) for j, i in enumerate(index)]
        ew = [float(abs(mpf(float(w[i])) - r.w[j]) / r.w[j]) for j, i in enumerate(index)]
    assert max(ex) <= NODE_ABS_TOL, f"node errors {['%.2e' % e for e in ex]}"
    assert max(ew) <= WEIGHT_REL_TOL, f"weight rel. errors {['%.2e' % e for e in ew]}"
