"""Building blocks for exponents within 1e-8 of -1 (a/b -> +-infinity).

References: mpmath at 40 digits from the *exact* shifted exponent (e + 1), never
from a rounded e.
"""

import numpy as np
import pytest
from mpmath import mp

import sie
import sie.exponents
from sie.exponents import sie_exponents
from sie.quadrature import WeightedRule, composite_weighted_rule
from sie.special import jacobi_end_values, jacobi_moment_shifted



@pytest.fixture(autouse=True)
def _forty_digits():
    """The references at 40 digits (tests/sie/conftest.py restores the precision after)."""
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
@pytest.mark.slow
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


@pytest.mark.parametrize("end", [1, -1])
@pytest.mark.parametrize("ep1", [3.183098861837907e-09, 1e-5, 0.005])
def test_composite_rule_splits_the_end_mass(end, ep1):
    """The composite rule of a projection with breaks, split at -0.4 and 0.3, with the mass
    ~ 1/(e+1) of the end split off as the Gauss rule's: int W x^k to 1e-14 of itself, the
    remainder int W (x^k - end^k) to 1e-13 (mpmath, 40 digits).  Without the split the sum
    loses eps / (e + 1): the projections of a moving punch with breaks at a huge friction."""
    other = 0.37
    if end == 1:
        a, b, a_p1, b_p1 = ep1 - 1.0, other, ep1, 1.0 + other
    else:
        a, b, a_p1, b_p1 = other, ep1 - 1.0, 1.0 + other, ep1
    rule = composite_weighted_rule(16, a, b, a_p1, b_p1, np.array([-0.4, 0.3]))
    assert rule.end == end
    A, B = mp.mpf(a_p1) - 1, mp.mpf(b_p1) - 1
    mu0 = mp.mpf(2) ** (A + B + 1) * mp.beta(A + 1, B + 1)
    for k in (1, 4, 9, 17):
        rest = mp.quad(lambda x: (1 - x) ** A * (1 + x) ** B * (x ** k - end ** k),
                       [-1, -0.4, 0.3, 1])
        got = float(np.sum(rule.omega * (rule.x ** k - end ** k)))
        assert abs(got - rest) <= 1e-13 * max(1.0, abs(rest)), k
        full = float(np.sum(rule.omega * rule.x ** k) + end ** k * rule.corr)
        assert abs(full / (mu0 * end ** k + rest) - 1) < 1e-14, k
    plain = composite_weighted_rule(16, a, b, a_p1 + 0.5, b_p1 + 0.5, np.array([0.3]))
    assert plain.end == 0 and plain.corr == 0.0


def _exact_solution(a, b, left, right, x):
    """psi and H[psi] at x of a psi + b H[psi] = f, f = 0 with int psi = 1 (both ends
    singular) or f = 1 (one end bounded): psi = w / mu_0, resp. -sin(pi alpha) w / b
    (the dominant operator on P_0, Erdogan, Gupta & Cook 1973), H[psi] = (f - a psi) / b;
    in 40 digits from alpha0 = arccot(-a/b) / pi, never from a rounded exponent."""
    a, b = mp.mpf(a), mp.mpf(b)
    alpha0 = mp.atan2(1, -a / b) / mp.pi
    alpha = alpha0 if right == "bounded" else alpha0 - 1
    beta = 1 - alpha0 if left == "bounded" else -alpha0
    out = []
    for xi in x:
        w = (1 - mp.mpf(xi)) ** alpha * (1 + mp.mpf(xi)) ** beta
        if left == right == "singular":
            mu0 = 2 ** (alpha + beta + 1) * mp.beta(alpha + 1, beta + 1)
            psi, f = w / mu0, 0
        else:
            psi, f = -mp.sin(mp.pi * alpha) * w / b, 1
        out.append((psi, (f - a * psi) / b))
    return out


# b/a < 0 puts 1 + alpha (a singular right end) near 0, b/a > 0 puts 1 + beta (a singular
# left end) there
NEAR_MINUS_ONE = [(left, right, sign * r) for r in (1e-8, 1e-12, 1e-15)
                  for left, right, sign in [("singular", "singular", -1.0),
                                            ("singular", "singular", 1.0),
                                            ("bounded", "singular", -1.0),
                                            ("singular", "bounded", 1.0)]]


@pytest.mark.parametrize("left, right, b_over_a", NEAR_MINUS_ONE)
def test_cauchy_limit_with_an_exponent_near_minus_one(left, right, b_over_a):
    """On the interval, cauchy_limit = H[psi] + i psi (Plemelj) with an end exponent within
    1e-15 of -1, at either end: its imaginary part is psi as the solution evaluates it
    (Jacobi series times the weight) to 4e-15, and a psi + b H[psi] = f holds to 1e-13 of
    its terms.  The closed form of F_0 divides by sin(pi alpha), exact, and so must be the
    e^{alpha L} it divides, formed from the exact 1 + alpha, not from alpha as rounded (that
    lost 1e-16 / (1 + alpha): 2e-4 at 1 + alpha = 3e-13, 1e-2 at 3e-16).  The solution
    itself against 40 digits: 2e-13 (its coefficients beyond the first carry ~1e-14)."""
    e = sie_exponents(1.0, b_over_a, left, right)
    assert min(e.alpha_p1, e.beta_p1) < 1e-7
    x = np.array([-0.9, -0.5, 0.0, 0.3, 0.9])
    both = left == right == "singular"
    f = np.zeros_like(x) if both else np.ones_like(x)
    sol = sie.solve((lambda s: np.zeros_like(s)) if both else np.ones_like, a=1.0, b=b_over_a,
                    n=4, left=left, right=right, **({"total": 1.0} if both else {}))
    F = sol.cauchy_limit(x)
    psi = sol(x)
    assert np.all(np.abs(F.imag - psi) <= 4e-15 * np.abs(psi))
    scale = np.maximum.reduce([np.abs(f), np.abs(psi), np.abs(b_over_a * F.real)])
    assert np.all(np.abs(psi + b_over_a * F.real - f) <= 1e-13 * scale)
    for (ref, _), got in zip(_exact_solution(1.0, b_over_a, left, right, x), psi):
        assert abs(got / float(ref) - 1) < 2e-13


@pytest.mark.parametrize("a, b", [(1.0, 1e-17), (1.0, -3e-16), (1e300, 1e-300), (-5.0, 1e-300)])
def test_a_ratio_that_rounds_an_exponent_to_an_integer_is_refused(a, b):
    """|b/a| below ~3.4e-16 makes alpha0 or 1 - alpha0 round to 1 (an exponent -1 or 1, a
    weight not integrable): refused as such, not a ZeroDivisionError or a NaN later."""
    with pytest.raises(sie.InvalidCoefficientError, match="too small for double precision"):
        sie.sie_exponents(a, b, "singular", "bounded")
    with pytest.raises(sie.InvalidCoefficientError, match="too small for double precision"):
        sie.solve(np.ones_like, a=a, b=b, n=6, left="singular", right="bounded")


def test_the_smallest_ratio_allowed_keeps_exponents_inside_the_open_interval():
    """Just above the bound every exponent of every end choice lies strictly inside (-1, 1)
    and its shift 1 + e stays positive and exact."""
    b = sie.exponents.MIN_B_OVER_A
    for sign in (1.0, -1.0):
        for left in ("bounded", "singular"):
            for right in ("bounded", "singular"):
                e = sie.sie_exponents(1.0, sign * b, left, right)
                assert -1.0 < e.alpha < 1.0 and -1.0 < e.beta < 1.0
                assert e.alpha_p1 > 0.0 and e.beta_p1 > 0.0
