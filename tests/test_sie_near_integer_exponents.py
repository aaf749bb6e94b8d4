"""Building blocks for exponents within 1e-8 of -1 (a/b -> +-infinity).

References: mpmath at 40 digits from the *exact* shifted exponent (e + 1), never
from a rounded e.
"""

import numpy as np
import pytest
from mpmath import mp

from sie.exponents import sie_exponents
from sie.quadrature import WeightedRule
from sie.special import jacobi_end_values, jacobi_moment_shifted

mp.dps = 40

SHIFTS = [3.183098861837907e-09, 1e-12, 1e-4, 0.3, 1.0, 1.7]


@pytest.mark.parametrize("ap1", SHIFTS)
@pytest.mark.parametrize("bp1", [0.5, 1.2, 1.9999999968169011])
def test_moment_from_shifted_exponents(ap1, bp1):
    """mu_0 = 2^{a+b+1} B(a+1, b+1) (DLMF 5.12.1), relative to 1e-14."""
    ref = 2 ** (mp.mpf(ap1) + mp.mpf(bp1) - 1) * mp.beta(mp.mpf(ap1), mp.mpf(bp1))
    got = jacobi_moment_shifted(ap1, bp1)
    assert abs(got / ref - 1) < 1e-14


@pytest.mark.parametrize("ep1", SHIFTS)
@pytest.mark.parametrize("end", [1, -1])
def test_end_values(ep1, end):
    """P_k(+1) = binom(k+a, k), P_k(-1) = (-1)^k binom(k+b, k) (DLMF 18.6.1), k < 60."""
    vals = jacobi_end_values(60, ep1, end)
    for k in range(60):
        ref = mp.binomial(k + mp.mpf(ep1) - 1, k) * (end ** k)
        assert abs(vals[k] - ref) <= 1e-14 * abs(ref) * (k + 1)


def test_exponents_carry_exact_shifts():
    """a/b = -1e8: alpha0 = atan2(1, 1e8)/pi ~ 3.18e-9; 1 + alpha = alpha0 exactly for a
    singular right end, 1 - beta = alpha0 exactly for a bounded left end."""
    e = sie_exponents(-1e8, 1.0, "bounded", "singular")
    alpha0 = float(mp.mpf(1) / 2 + mp.atan(mp.mpf(-1e8)) / mp.pi)
    assert e.alpha_p1 == pytest.approx(alpha0, rel=1e-15)
    assert e.beta_m1 == pytest.approx(alpha0, rel=1e-15)
    # the rounded exponent itself has lost 8 digits in e + 1
    assert abs((e.alpha + 1.0) / alpha0 - 1) > 1e-10


@pytest.mark.parametrize("end", [1, -1])
@pytest.mark.parametrize("ep1", [3.183098861837907e-09, 1e-5, 0.005])
def test_end_corrected_rule_integrates_polynomials(end, ep1):
    """The end-corrected Gauss rule integrates x^k (1-x)^a (1+x)^b with the mass
    ~ 1/(e+1) at the end split off exactly; compare the *remainder* int W (x^k - end^k)
    (O(1), while the mass is ~3e8) to mpmath to 1e-13."""
    other = 0.37
    if end == 1:
        a, b, a_p1, b_p1 = ep1 - 1.0, other, ep1, 1.0 + other
    else:
        a, b, a_p1, b_p1 = other, ep1 - 1.0, 1.0 + other, ep1
    rule = WeightedRule.build(12, a, b, a_p1, b_p1)
    assert rule.end == end
    A, B = mp.mpf(a_p1) - 1, mp.mpf(b_p1) - 1
    for k in range(1, 20):
        # remainder = int W (x^k - end^k); W (x^k - end^k) has a regular end
        got = float(np.sum(rule.omega * (rule.x ** k - end ** k)))
        ref = mp.quad(lambda x: (1 - x) ** A * (1 + x) ** B * (x ** k - end ** k), [-1, 0, 1])
        assert abs(got - ref) <= 1e-13 * max(1.0, abs(ref)), k
    # and the full integral int W x^k relative to its size
    mu0 = mp.mpf(2) ** (A + B + 1) * mp.beta(A + 1, B + 1)
    for k in (0, 3, 8):
        got = float(np.sum(rule.omega * rule.x ** k) + end ** k * rule.corr)
        ref = mu0 * end ** k + mp.quad(lambda x: (1 - x) ** A * (1 + x) ** B * (x ** k - end ** k),
                                       [-1, 0, 1])
        assert abs(got / ref - 1) < 1e-14
