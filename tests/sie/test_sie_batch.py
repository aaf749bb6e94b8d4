"""Tests of an :class:`sie.Equation` with a case axis (:mod:`sie.batch`): many one-interval
dominant equations

    a_i psi_i(s) + (b_i/pi) PV int_{c_i}^{d_i} psi_i(t)/(t - s) dt = f(s)

solved at once (intervals of shape (B, 1, 2)).

References, and why each is independent of the batch code:

* ``sie.solve`` with ``intervals=[(c_i, d_i)]``, one equation at a time: the path of one
  equation (``sie.unknowns.IntervalUnknown``, ``sie.assembly.assemble_and_solve``,
  ``sie.solution.IntervalSolution``), which the case axis runs with a batch axis in its
  own compiled loops.  It must agree to rounding.
* ``Equation.functionals`` of one equation on [-1, 1] with f mapped there (the rule of
  one block).
* Closed forms derived here, not read from the code: for w = (1-u)^alpha (1+u)^beta with
  alpha + beta = m in {-1, 0, 1} and cot(pi alpha) = -a/b (Muskhelishvili 1953, ch. 10;
  Tricomi 1957, sec. 4.3),

      H[w](x) = (1/pi) PV int_{-1}^{1} w(t)/(t - x) dt = cot(pi alpha) w(x) - p_m(x)/sin(pi alpha),
      p_{-1} = 0,  p_0 = 1,  p_1(x) = x + beta - alpha

  (p_m is the polynomial part of (z-1)^alpha (z+1)^beta at infinity), so that
  a w + b H[w] = -b p_m / sin(pi alpha): with that right-hand side psi = w, phi = 1 exactly,
  and int psi = h mu_0, mu_0 = 2^(m+1) Gamma(alpha+1) Gamma(beta+1) / Gamma(m+2).
  ``test_weight_identity_by_mpmath`` checks the identity itself by mpmath quadrature.
  Special cases: a = 0, b = 1, both ends bounded: sqrt(R^2 - s^2) solves H[psi] = -s on
  [-R, R] (int psi = pi R^2/2), and f = 1 is not solvable (consistency 1, the weighted mean).
* Exact equality (``np.array_equal``) between the same equation solved in different batches:
  the batch runs per equation in compiled loops, so a result must not depend on the others.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import sie

ENDS = (("bounded", "bounded"), ("singular", "bounded"), ("bounded", "singular"),
        ("singular", "singular"))
END_IDS = ["bb", "sb", "bs", "ss"]
NS = (2, 3, 4, 5, 12, 40)          # n > 8: the noise chopping of the coefficients
U = np.concatenate([np.linspace(-0.97, 0.97, 9), [-0.999, 0.999]])


def f_smooth(s):
    """A smooth right-hand side whose Jacobi series does not terminate (so that n = 40
    reaches the rounding plateau and the chopping acts) in real coordinates."""
    s = np.asarray(s, dtype=float)
    return np.cos(1.3 * s + 0.2) + 0.4 * s - 0.1 * s * s


def cases(a, b, left, right, iv):
    """The equations a_i, b_i on the intervals iv[i] as one sie.Equation with a case axis
    (scalars are shared)."""
    return sie.Equation(a=a, b=b, left=left, right=right,
                        intervals=np.asarray(iv, dtype=float)[:, None, :])


def kappa_of(left, right):
    return {("singular", "singular"): 1, ("bounded", "bounded"): -1}.get((left, right), 0)


def random_equations(rng, B):
    """B random equations: a/b in [-5, 5], |b| in [0.2, 3] of either sign, intervals in
    [-3, 5] of width 0.05 to 3, totals in [-2, 2]."""
    ratio = rng.uniform(-5.0, 5.0, B)
    b = rng.uniform(0.2, 3.0, B) * rng.choice([-1.0, 1.0], B)
    a = ratio * b
    c = rng.uniform(-3.0, 2.0, B)
    iv = np.column_stack([c, c + rng.uniform(0.05, 3.0, B)])
    total = rng.uniform(-2.0, 2.0, B)
    return a, b, iv, total


def scalar_reference(f, a, b, n, left, right, iv, total):
    """sie.solve of one equation on its interval (the independent scalar path); its
    solvability warning (index -1, f not admissible) is expected and silenced."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.InconsistentEquationWarning)
        return sie.solve(f, a=float(a), b=float(b), n=n, left=left, right=right,
                         intervals=[tuple(float(v) for v in iv)],
                         total=None if total is None else [float(total)])


def assert_matches_scalar(sb, i, f, n, left, right, total_i):
    """Equation i of the batch against sie.solve of it alone."""
    a, b, iv = sb.a[i], sb.b[i], sb.intervals[i]
    ref = scalar_reference(f, a, b, n, left, right, iv, total_i)
    piece = ref.pieces[0]
    c_ref = np.asarray(piece.coefficients)
    c = sb.coefficients[i]
    s = 0.5 * (iv[0] + iv[1]) + 0.5 * (iv[1] - iv[0]) * U
    fmax = np.max(np.abs(f(s)))
    # relative to max|c|, or to f's own scale in units of c (|lambda| ~ sqrt(a^2 + b^2))
    # where the coefficients are themselves rounding (f constant, index -1: psi = 0)
    scale = max(np.max(np.abs(c_ref)), fmax / math.hypot(a, b), np.finfo(float).tiny)
    assert c.shape == c_ref.shape == (n,)
    assert np.max(np.abs(c - c_ref)) <= 1e-13 * scale, (c, c_ref)
    assert sb.alpha[i] == piece.alpha and sb.beta[i] == piece.beta
    assert sb.kappa == piece.kappa
    # the solvability residual, in units of f
    if sb.kappa == -1:
        assert abs(sb.consistency[i] - piece.consistency) <= 1e-14 * fmax
    else:
        assert sb.consistency is None and piece.consistency is None
    # int psi (h mu_0 c_0), against the scalar Solution's own integral
    h = 0.5 * (iv[1] - iv[0])
    I_ref = ref.integral(interval=0)
    mu0 = sb.mu0[i]
    assert abs(sb.integral()[i] - I_ref) <= 1e-13 * h * mu0 * scale
    # phi and the weight at local points, and psi through the Solution built from the batch
    phi_ref = piece.phi_local(U)
    phi = sb.phi_local(U)[i]
    assert np.max(np.abs(phi - phi_ref)) <= 1e-12 * max(np.max(np.abs(phi_ref)), scale)
    np.testing.assert_allclose(sb.weight_local(U)[i],
                               (1 - U) ** piece.alpha * (1 + U) ** piece.beta, rtol=1e-15)
    psi_ref = ref(s[1:-1])
    psi = sb[i](s[1:-1])
    assert np.max(np.abs(psi - psi_ref)) <= 1e-12 * max(np.max(np.abs(psi_ref)), scale)
    # H[psi] + i psi (Plemelj) from the series' Cauchy transform
    C_ref = piece.cauchy_limit_local(U)
    C = sb.cauchy_limit_local(U)[i]
    assert np.max(np.abs(C - C_ref)) <= 1e-12 * max(np.max(np.abs(C_ref)), scale)


# --------------------------------------------------------------------------
# the batch against sie.solve, equation by equation
# --------------------------------------------------------------------------
@pytest.mark.parametrize("n", NS)
@pytest.mark.parametrize("ends", ENDS, ids=END_IDS)
def test_batch_matches_scalar_solve(ends, n):
    left, right = ends
    rng = np.random.default_rng(1000 * n + END_IDS.index("".join(e[0] for e in ends)))
    B = 5
    a, b, iv, total = random_equations(rng, B)
    k = kappa_of(left, right)
    t = total if k == 1 else None
    sb = cases(a, b, left, right, iv).solve(f_smooth, n=n, total=t)
    assert len(sb) == B and sb.n == n and sb.kappa == k
    for i in range(B):
        assert_matches_scalar(sb, i, f_smooth, n, left, right, None if t is None else t[i])


def test_batch_solution_item_is_a_solution_of_its_equation():
    """batch[i] is a sie.Solution with the equation's a, b and interval; the equation
    a psi + b H[psi] = f - consistency holds at interior points, with H[psi] from the
    Cauchy limit (exact transforms of the basis, not the collocation equations)."""
    rng = np.random.default_rng(7)
    a, b, iv, _ = random_equations(rng, 4)
    sb = cases(a, b, "bounded", "bounded", iv).solve(f_smooth, n=40)
    for i in range(4):
        sol = sb[i]
        assert isinstance(sol, sie.Solution)
        assert sol.a == a[i] and sol.b == b[i]
        assert sol.pieces[0].interval.c == iv[i, 0] and sol.pieces[0].interval.d == iv[i, 1]
        F = sb.cauchy_limit_local(U[:-2])[i]
        s = 0.5 * (iv[i, 0] + iv[i, 1]) + 0.5 * (iv[i, 1] - iv[i, 0]) * U[:-2]
        lhs = a[i] * F.imag + b[i] * F.real
        rhs = f_smooth(s) - sb.consistency[i]
        assert np.max(np.abs(lhs - rhs)) <= 1e-12 * np.max(np.abs(f_smooth(s)))
    with pytest.raises(IndexError):
        sb[4]
    assert sb[-1].a == a[-1]


poly = st.lists(st.floats(-1.0, 1.0, allow_nan=False, allow_subnormal=False),
                min_size=1, max_size=6)


@settings(max_examples=25, deadline=None)
@given(ratio=st.lists(st.floats(-30.0, 30.0, allow_nan=False), min_size=1, max_size=4),
       bmag=st.floats(0.05, 10.0), sign=st.sampled_from((-1.0, 1.0)),
       ends=st.sampled_from(ENDS), n=st.sampled_from(NS), cs=poly,
       c0=st.floats(-5.0, 5.0), width=st.floats(1e-3, 8.0), total=st.floats(-3.0, 3.0))
def test_property_batch_matches_scalar_solve(ratio, bmag, sign, ends, n, cs, c0, width,
                                             total):
    """Any coefficients (b of either sign), ends, n, polynomial f and intervals: each
    equation of the batch is sie.solve of it alone."""
    left, right = ends
    B = len(ratio)
    b = sign * bmag * (1.0 + 0.1 * np.arange(B))
    a = np.array(ratio) * b
    iv = np.column_stack([c0 + 0.3 * np.arange(B), c0 + 0.3 * np.arange(B) + width])
    coef = np.array(cs)

    def f(s):
        return np.polynomial.polynomial.polyval(np.asarray(s, dtype=float), coef)

    k = kappa_of(left, right)
    t = np.full(B, total) if k == 1 else None
    sb = cases(a, b, left, right, iv).solve(f, n=n, total=t)
    for i in range(B):
        assert_matches_scalar(sb, i, f, n, left, right, None if t is None else t[i])


# --------------------------------------------------------------------------
# exponents near 0 or 1: the projection rule splits off an end mass
# --------------------------------------------------------------------------
@pytest.mark.parametrize("n", (4, 12, 40))
@pytest.mark.parametrize("ends", ENDS, ids=END_IDS)
def test_end_mass_split_matches_scalar_solve(ends, n):
    """a/b = +-1e3 puts alpha0 within 3.2e-4 of 1 or 0, so a bounded end's exponent is
    within 0.01 of 1 (the WeightedRule end path, taken when 1 - alpha or 1 - beta < 0.01)."""
    left, right = ends
    a = np.array([1e3, -1e3, 40.0, -40.0, 0.5])
    b = np.array([1.0, 1.0, -1.0, 1.0, 1.0])
    iv = np.array([(-1.0, 1.0), (0.0, 2.5), (-3.0, -2.9), (1.0, 4.0), (-0.5, 0.5)])
    eqs = cases(a, b, left, right, iv)
    alpha = np.array([e.alpha for e in eqs.exponents])
    beta = np.array([e.beta for e in eqs.exponents])
    if left == "bounded" or right == "bounded":
        assert np.any(np.minimum(1 - alpha, 1 - beta) < 0.01)
    k, = eqs.kappa
    t = np.linspace(-1.0, 2.0, 5) if k == 1 else None
    sb = eqs.solve(f_smooth, n=n, total=t)
    for i in range(5):
        assert_matches_scalar(sb, i, f_smooth, n, left, right, None if t is None else t[i])


# --------------------------------------------------------------------------
# functionals against those of one equation on [-1, 1], f mapped there
# --------------------------------------------------------------------------
@pytest.mark.parametrize("n", (2, 4, 12, 40))
@pytest.mark.parametrize("ends", ENDS, ids=END_IDS)
def test_functionals_match_one_equation(ends, n):
    left, right = ends
    rng = np.random.default_rng(77 + n)
    a, b, iv, _ = random_equations(rng, 4)
    a = np.concatenate([a, [2e3]])              # one with a split-off end
    b = np.concatenate([b, [-1.5]])
    iv = np.vstack([iv, [(0.5, 0.75)]])
    fb = cases(a, b, left, right, iv).functionals(f_smooth, n=n)
    same = cases(a, b, left, right, iv).functionals(f_smooth, n=n)
    k = kappa_of(left, right)
    assert fb.kappa == k
    for i in range(5):
        c, d = iv[i]
        h, m = 0.5 * (d - c), 0.5 * (c + d)
        ref = sie.Equation(a=a[i], b=b[i], left=left, right=right).functionals(
            lambda u: f_smooth(m + h * u), n=n)
        assert fb.alpha[i] == ref.alpha and fb.beta[i] == ref.beta
        if k == 1:
            assert fb.integral is None and fb.consistency is None and ref.integral is None
            continue
        fmax = np.max(np.abs(f_smooth(m + h * U)))
        # int psi in real coordinates: h times the integral over u
        assert abs(fb.integral[i] - h * ref.integral) <= 1e-13 * abs(h * ref.integral) + \
            1e-15 * h * fmax / abs(b[i])
        assert np.array_equal(fb.integral, same.integral)
        if k == -1:
            assert abs(fb.consistency[i] - ref.consistency) <= 1e-14 * fmax
        else:
            assert fb.consistency is None


def test_functionals_agree_with_the_solution():
    """integral and consistency from the functionals are those of the full solve."""
    rng = np.random.default_rng(3)
    a, b, iv, _ = random_equations(rng, 6)
    for left, right in ENDS[:3]:
        eqs = cases(a, b, left, right, iv)
        fb, sb = eqs.functionals(f_smooth, n=12), eqs.solve(f_smooth, n=12)
        np.testing.assert_allclose(fb.integral, sb.integral(), rtol=1e-13, atol=1e-15)
        if eqs.kappa == (-1,):
            np.testing.assert_allclose(fb.consistency, sb.consistency, rtol=0, atol=1e-15)


# --------------------------------------------------------------------------
# closed forms
# --------------------------------------------------------------------------
def test_semicircle_closed_form():
    """sqrt(R^2 - (s - m)^2) solves (1/pi) PV int psi/(t - s) dt = -(s - m) on
    [m - R, m + R]; int psi = pi R^2 / 2; solvable (consistency 0)."""
    iv = np.array([(-1.0, 1.0), (-2.0, 2.0), (3.0, 3.5), (-10.0, -4.0)])
    mids, R = iv.mean(axis=1), 0.5 * (iv[:, 1] - iv[:, 0])
    f = lambda s: -s  # noqa: E731   (one f for all: intervals centred at 0 first)
    centred = np.column_stack([-R, R])
    fb = cases(0.0, 1.0, "bounded", "bounded", centred).functionals(f, n=4)
    np.testing.assert_allclose(fb.integral, np.pi * R ** 2 / 2, rtol=1e-14)
    assert np.all(np.abs(fb.consistency) <= 1e-14 * R)
    sb = cases(0.0, 1.0, "bounded", "bounded", centred).solve(f, n=4)
    np.testing.assert_allclose(sb.integral(), np.pi * R ** 2 / 2, rtol=1e-14)
    # psi(s) = sqrt(R^2 - s^2): phi = R in the local coordinate (w = sqrt(1 - u^2))
    np.testing.assert_allclose(sb.phi_local(U), np.repeat(R[:, None], U.size, axis=1),
                               rtol=1e-14)
    for i in range(len(R)):
        s = R[i] * np.array([-0.9, -0.3, 0.0, 0.6])
        np.testing.assert_allclose(sb[i](s), np.sqrt(R[i] ** 2 - s ** 2), rtol=1e-14)
    # H[psi] = -s and psi from the Cauchy limit
    F = sb.cauchy_limit_local(U[:-2])
    for i in range(len(R)):
        s = R[i] * U[:-2]
        np.testing.assert_allclose(F[i].real, -s, rtol=0, atol=1e-14 * R[i])
        np.testing.assert_allclose(F[i].imag, np.sqrt(R[i] ** 2 - s ** 2), rtol=1e-13)
    # shifted intervals, f = m - s with the shift known per equation: one batch per equation
    for i in range(len(iv)):
        g = lambda s, m=mids[i]: m - s  # noqa: E731
        sbi = cases(0.0, 1.0, "bounded", "bounded", iv[i:i + 1]).solve(g, n=4)
        assert abs(sbi.integral()[0] - np.pi * R[i] ** 2 / 2) <= 1e-14 * np.pi * R[i] ** 2
        assert abs(sbi.consistency[0]) <= 1e-14 * (R[i] + abs(mids[i]))


def test_unsolvable_constant_has_consistency_one():
    """a = 0, b = 1, both ends bounded, f = 1: no bounded solution; the solvability
    residual is the weighted mean of f against (1-u)^{-1/2}(1+u)^{-1/2} over its mass: 1."""
    iv = [(-1.0, 1.0), (2.0, 7.0), (-0.01, 0.0)]
    fb = cases(0.0, 1.0, "bounded", "bounded", iv).functionals(np.ones_like, n=4)
    np.testing.assert_allclose(fb.consistency, 1.0, rtol=1e-14)
    sb = cases(0.0, 1.0, "bounded", "bounded", iv).solve(np.ones_like, n=4)
    np.testing.assert_allclose(sb.consistency, 1.0, rtol=1e-14)
    assert np.all(np.abs(sb.coefficients) <= 1e-15)          # psi = 0 for f minus its mean


def _exponents(a, b, left, right):
    """alpha, beta from cot(pi alpha0) = -a/b, alpha0 in (0, 1) (computed here)."""
    alpha0 = math.atan2(1.0, -a / b) / math.pi
    alpha = alpha0 if right == "bounded" else alpha0 - 1.0
    beta = 1.0 - alpha0 if left == "bounded" else -alpha0
    return alpha, beta


def _mu0(alpha, beta):
    return 2.0 ** (alpha + beta + 1) * math.gamma(alpha + 1) * math.gamma(beta + 1) / \
        math.gamma(alpha + beta + 2)


RATIOS = (0.0, 0.7, -2.5, 1e3, -1e3)      # a/b; +-1e3: an exponent within 3.2e-4 of 0 or 1


@pytest.mark.parametrize("ends", ENDS, ids=END_IDS)
def test_jacobi_weight_closed_form(ends):
    """psi = w solves a psi + b H[psi] = -b p_m(u)/sin(pi alpha) (module docstring), so
    phi = 1 and int psi = h mu_0, for any a/b (end split included) and interval."""
    left, right = ends
    coefficients = [(r * b, b) for r in RATIOS for b in (1.0, -0.5)]
    iv = np.array([(-1.0, 1.0), (0.0, 0.3), (-5.0, 2.0), (2.0, 2.001), (-3.0, -1.0),
                   (1.0, 2.0), (-0.5, 0.25), (10.0, 14.0), (-1.0, 1.0), (0.0, 1.0)])
    m = {("singular", "singular"): -1, ("bounded", "bounded"): 1}.get(ends, 0)
    for i, (a_i, b_i) in enumerate(coefficients):
        alpha, beta = _exponents(a_i, b_i, left, right)
        c, d = iv[i]
        h, mid = 0.5 * (d - c), 0.5 * (c + d)
        sin = math.sin(math.pi * alpha)

        def f(s, alpha=alpha, beta=beta, sin=sin, b=b_i, h=h, mid=mid):
            u = (np.asarray(s, dtype=float) - mid) / h
            p = {-1: 0.0 * u, 0: 1.0 + 0.0 * u, 1: u + beta - alpha}[m]
            return -b * p / sin

        n = 6
        k = -m
        total = h * _mu0(alpha, beta) if k == 1 else None
        sb = cases([a_i], [b_i], left, right, iv[i:i + 1]).solve(
            f, n=n, total=None if total is None else [total])
        assert abs(sb.alpha[0] - alpha) <= 1e-15 and abs(sb.beta[0] - beta) <= 1e-15
        c_ex = np.zeros(n)
        c_ex[0] = 1.0
        assert np.max(np.abs(sb.coefficients[0] - c_ex)) <= 1e-12, (a_i, b_i, sb.coefficients)
        assert abs(sb.integral()[0] / (h * _mu0(alpha, beta)) - 1.0) <= 1e-12
        if k == -1:
            fmax = np.max(np.abs(f(mid + h * U)))
            assert abs(sb.consistency[0]) <= 1e-13 * fmax
        if k <= 0:
            fb = cases([a_i], [b_i], left, right, iv[i:i + 1]).functionals(f, n=n)
            assert abs(fb.integral[0] / (h * _mu0(alpha, beta)) - 1.0) <= 1e-12
        # the Cauchy limit: H[w] + i w at interior points
        u = np.array([-0.8, -0.1, 0.35, 0.9])
        w = (1 - u) ** alpha * (1 + u) ** beta
        p = {-1: 0.0 * u, 0: 1.0 + 0.0 * u, 1: u + beta - alpha}[m]
        H = math.cos(math.pi * alpha) / sin * w - p / sin
        F = sb.cauchy_limit_local(u)[0]
        assert np.max(np.abs(F.imag - w)) <= 1e-12 * np.max(np.abs(w))
        assert np.max(np.abs(F.real - H)) <= 1e-11 * max(np.max(np.abs(H)), np.max(np.abs(w)))


def test_weight_identity_by_mpmath():
    """The closed form used above, checked by direct quadrature (mpmath, 30 digits) of the
    principal value: PV int w/(t-x) = int (w(t) - w(x))/(t - x) dt + w(x) log((1-x)/(1+x)),
    the integral split at x and written in v = r^(1+e), r the distance to the end and e the
    exponent there, which makes the integrand smooth at the ends."""
    mp = pytest.importorskip("mpmath")
    with mp.workdps(30):
        x = mp.mpf("0.37")
        for (left, right), (a, b) in zip(ENDS, [(0.3, 1.2), (-0.7, -0.5), (1.1, 0.4),
                                                (0.5, -2.0)]):
            alpha, beta = _exponents(a, b, left, right)
            m = round(alpha + beta)
            al, be = mp.mpf(alpha), mp.mpf(beta)
            wx = (1 - x) ** al * (1 + x) ** be

            def half(e, other, sign, length):
                # r = 1 + t (left, sign -1) or 1 - t (right, sign +1); t - x = sign (1 - r) - x
                g = 1 / (1 + e)

                def integrand(v):
                    r = v ** g
                    w = r ** e * (2 - r) ** other
                    return (w - wx) / (sign * (1 - r) - x) * g * v ** (g - 1)
                return mp.quad(integrand, [0, length ** (1 + e)])

            pv = half(be, al, -1, 1 + x) + half(al, be, 1, 1 - x) + \
                wx * mp.log((1 - x) / (1 + x))
            H_quad = float(pv / mp.pi)
            xf = float(x)
            p = {-1: 0.0, 0: 1.0, 1: xf + beta - alpha}[m]
            H = math.cos(math.pi * alpha) / math.sin(math.pi * alpha) * float(wx) - \
                p / math.sin(math.pi * alpha)
            assert abs(H_quad - H) <= 1e-13 * max(1.0, abs(H)), (left, right, H_quad, H)


# --------------------------------------------------------------------------
# independence of the other equations, take
# --------------------------------------------------------------------------
def _solve_all(a, b, iv, t, n, left, right):
    return cases(a, b, left, right, iv).solve(f_smooth, n=n, total=t)


@pytest.mark.parametrize("n", (3, 12, 40))
@pytest.mark.parametrize("ends", ENDS, ids=END_IDS)
def test_result_does_not_depend_on_the_rest_of_the_batch(ends, n):
    left, right = ends
    rng = np.random.default_rng(11 * n)
    a, b, iv, total = random_equations(rng, 7)
    a[2], b[2] = 1e3, 1.0                      # an end split among the others
    a[5], b[5] = -1e3, -2.0
    k = kappa_of(left, right)
    t = total if k == 1 else None
    full = _solve_all(a, b, iv, t, n, left, right)
    rev = np.arange(7)[::-1]
    reversed_ = _solve_all(a[rev], b[rev], iv[rev], None if t is None else t[rev], n, left,
                           right)
    sub = np.array([5, 0, 2])
    part = _solve_all(a[sub], b[sub], iv[sub], None if t is None else t[sub], n, left, right)
    fb_full = cases(a, b, left, right, iv).functionals(f_smooth, n=n)
    for i in range(7):
        alone = _solve_all(a[i:i + 1], b[i:i + 1], iv[i:i + 1],
                           None if t is None else t[i:i + 1], n, left, right)
        others = [(reversed_, 6 - i), (alone, 0)]
        if i in sub:
            others.append((part, int(np.flatnonzero(sub == i)[0])))
        for other, j in others:
            assert np.array_equal(full.coefficients[i], other.coefficients[j])
            if k == -1:
                assert full.consistency[i] == other.consistency[j]
            assert full.integral()[i] == other.integral()[j]
            assert np.array_equal(full.phi_local(U)[i], other.phi_local(U)[j])
            assert np.array_equal(full.cauchy_limit_local(U)[i],
                                  other.cauchy_limit_local(U)[j])
        if k != 1:
            fb_alone = cases(a[i:i + 1], b[i:i + 1], left, right, iv[i:i + 1]).functionals(
                f_smooth, n=n)
            assert fb_full.integral[i] == fb_alone.integral[0]
            if k == -1:
                assert fb_full.consistency[i] == fb_alone.consistency[0]


@pytest.mark.parametrize("ends", ENDS, ids=END_IDS)
def test_take(ends):
    """Equation.take keeps the prepared rules of the chosen cases: solving with it is
    solving the subset afresh; SolutionBatch.take is the subset of the solutions."""
    left, right = ends
    rng = np.random.default_rng(5)
    a, b, iv, total = random_equations(rng, 6)
    a[1], b[1] = -1e3, 1.0
    k = kappa_of(left, right)
    t = total if k == 1 else None
    idx = [4, 1, 1, 0]
    eqs = cases(a, b, left, right, iv)
    eqs.solve(f_smooth, n=12, total=t)                   # the rules of n = 12, prepared
    sub_eqs = eqs.take(idx)
    fresh = cases(a[idx], b[idx], left, right, iv[idx])
    assert sub_eqs.cases == 4 and sub_eqs.kappa == (k,)
    assert sub_eqs.exponents == fresh.exponents
    assert np.array_equal(sub_eqs.intervals, fresh.intervals)
    t_sub = None if t is None else t[idx]
    s1 = sub_eqs.solve(f_smooth, n=12, total=t_sub)
    s2 = fresh.solve(f_smooth, n=12, total=t_sub)
    s3 = eqs.solve(f_smooth, n=12, total=t).take(idx)
    for s in (s1, s3):
        assert np.array_equal(s.coefficients, s2.coefficients)
        assert np.array_equal(s.intervals, s2.intervals)
        assert np.array_equal(s.integral(), s2.integral())
        assert np.array_equal(s.cauchy_limit_local(U), s2.cauchy_limit_local(U))
        if k == -1:
            assert np.array_equal(s.consistency, s2.consistency)
        assert len(s) == 4
    assert not s3.coefficients.flags.writeable
    if k != 1:
        f1 = sub_eqs.functionals(f_smooth, n=12)
        f2 = fresh.functionals(f_smooth, n=12)
        assert np.array_equal(f1.integral, f2.integral)


def test_scalar_coefficients_broadcast():
    """a or b given once is shared by every equation."""
    iv = [(-1.0, 1.0), (0.0, 2.0), (3.0, 3.5)]
    s1 = cases(0.4, [1.0, 1.0, 1.0], "singular", "bounded", iv).solve(f_smooth, n=6)
    s2 = cases([0.4] * 3, 1.0, "singular", "bounded", iv).solve(f_smooth, n=6)
    assert np.array_equal(s1.coefficients, s2.coefficients)
    assert np.array_equal(s1.a, [0.4] * 3) and np.array_equal(s1.b, [1.0] * 3)


# --------------------------------------------------------------------------
# f is called once per call
# --------------------------------------------------------------------------
class CountingF:
    def __init__(self):
        self.calls = 0

    def __call__(self, s):
        self.calls += 1
        return f_smooth(s)


@pytest.mark.parametrize("ends", ENDS, ids=END_IDS)
def test_f_called_once_per_call(ends):
    """One call of f on the nodes of all equations (the split-off end values included):
    the batch has equations with and without an end split."""
    left, right = ends
    a = np.array([0.3, 1e3, -1e3, -2.0])
    b = np.array([1.0, 1.0, 1.0, 0.5])
    iv = np.array([(-1.0, 1.0), (0.0, 2.0), (3.0, 3.5), (-2.0, -1.0)])
    eqs = cases(a, b, left, right, iv)
    k, = eqs.kappa
    t = np.ones(4) if k == 1 else None
    f = CountingF()
    eqs.solve(f, n=12, total=t)
    assert f.calls == 1
    f = CountingF()
    fb = eqs.functionals(f, n=12)
    # index 1: int psi is the side condition, nothing to compute
    assert f.calls == (0 if k == 1 else 1)
    if k == 1:
        assert fb.integral is None and fb.consistency is None
    f = CountingF()
    eqs.solve(f, n=40, total=t)
    assert f.calls == 1


# --------------------------------------------------------------------------
# errors
# --------------------------------------------------------------------------
BB = dict(left="bounded", right="bounded")


def test_error_coefficients():
    iv = [(0.0, 1.0), (1.0, 2.0)]
    with pytest.raises(sie.InvalidCoefficientError, match="nonzero"):
        cases([0.0, 1.0], [1.0, 0.0], "bounded", "bounded", iv)
    with pytest.raises(sie.InvalidCoefficientError, match="finite"):
        cases([0.0, np.nan], 1.0, "bounded", "bounded", iv)
    with pytest.raises(sie.InvalidCoefficientError, match="finite"):
        cases(0.0, np.inf, "bounded", "bounded", iv)
    with pytest.raises(sie.InvalidCoefficientError, match="one per case"):
        cases([0.0, 1.0], [1.0, 1.0, 1.0], "bounded", "bounded", iv)
    with pytest.raises(sie.InvalidCoefficientError, match="finite real number"):
        cases(["0.3", 1.0], 1.0, "bounded", "bounded", iv)         # text is refused
    with pytest.raises(sie.InvalidCoefficientError, match="at least one equation"):
        sie.Equation(a=[], b=[], intervals=np.empty((0, 1, 2)), **BB)


def test_error_ends_and_order():
    iv = [(0.0, 1.0)]
    with pytest.raises(sie.InvalidEndConditionError, match="left"):
        cases(0.0, 1.0, "free", "bounded", iv)
    with pytest.raises(sie.InvalidEndConditionError, match="right"):
        cases(0.0, 1.0, "bounded", None, iv)
    with pytest.raises(sie.PerIntervalArgumentError, match="shared by the cases"):
        cases(0.0, 1.0, ["bounded"], "bounded", iv)
    eqs = cases(0.0, 1.0, "bounded", "bounded", iv)
    ss = cases(0.0, 1.0, "singular", "singular", iv)
    for call in (eqs.solve, eqs.functionals):
        with pytest.raises(sie.InvalidOrderError, match="n must be"):
            call(f_smooth, n=0)
        with pytest.raises(sie.InvalidOrderError, match="n must be"):
            call(f_smooth, n=2.5)
        with pytest.raises(sie.InvalidOrderError, match="limit"):
            call(f_smooth, n=sie.N_MAX + 1)
    with pytest.raises(sie.InvalidOrderError, match="index 1"):
        ss.solve(f_smooth, n=1, total=1.0)


@pytest.mark.parametrize("intervals, word", [
    ([[(0.0, 1.0)]], "shape"),                          # one pair for two equations
    ([[(0.0, 1.0)], [(1.0, 2.0)], [(2.0, 3.0)]], "shape"),
    ([(0.0, 1.0), (1.5, 2.0)], "shape"),                # no case axis
    ([[(0.0, 1.0, 2.0)], [(1.0, 2.0, 3.0)]], "shape"),
    ([[(0.0, 1.0)], [(2.0, 2.0)]], "c < d"),            # c = d
    ([[(1.0, 0.0)], [(2.0, 3.0)]], "c < d"),            # c > d
    ([[(0.0, 1.0)], [(np.nan, 3.0)]], "finite"),
    ([[(0.0, np.inf)], [(1.0, 3.0)]], "finite"),
    ([[("x", 1.0)], [(1.0, 3.0)]], "real numbers"),
])
def test_error_intervals(intervals, word):
    eqs = cases([0.0, 0.5], 1.0, "bounded", "bounded", [(0.0, 1.0), (0.0, 2.0)])
    with pytest.raises(sie.InvalidIntervalError, match=word):
        eqs.on(intervals)
    if np.ndim(intervals) == 3 and np.shape(intervals)[-1] == 2 and len(intervals) == 2:
        with pytest.raises(sie.InvalidIntervalError, match=word):
            sie.Equation(a=[0.0, 0.5], b=1.0, intervals=intervals, **BB)


def test_error_unsupported_case_axis():
    """A case axis holds one-interval equations without a kernel or breaks."""
    with pytest.raises(sie.UnsupportedEquationError, match="one-interval"):
        sie.Equation(a=0.0, b=1.0, intervals=[[(0.0, 1.0), (2.0, 3.0)]], **BB)
    with pytest.raises(sie.UnsupportedEquationError, match="kernel"):
        sie.Equation(a=0.0, b=1.0, intervals=[[(0.0, 1.0)]], kernel=lambda s, t: s * t, **BB)
    eqs = cases(0.0, 1.0, "bounded", "bounded", [(0.0, 1.0)])
    with pytest.raises(sie.UnsupportedEquationError, match="breaks"):
        eqs.solve(f_smooth, n=4, breaks=[0.5])
    with pytest.raises(sie.UnsupportedEquationError, match="breaks"):
        eqs.functionals(f_smooth, n=4, breaks=[0.5])


def test_error_side_condition():
    iv = [(0.0, 1.0), (1.0, 2.0)]
    ss = cases([0.0, 0.5], 1.0, "singular", "singular", iv)
    with pytest.raises(sie.SideConditionError, match="required"):
        ss.solve(f_smooth, n=4)
    with pytest.raises(sie.SideConditionError, match="one finite number per case"):
        ss.solve(f_smooth, n=4, total=[1.0, 1.0, 1.0])
    with pytest.raises(sie.SideConditionError, match="one finite number per case"):
        ss.solve(f_smooth, n=4, total=[1.0, np.nan])
    with pytest.raises(sie.SideConditionError, match="real numbers"):
        ss.solve(f_smooth, n=4, total=["1.0", 1.0])
    for left, right in ENDS[:3]:
        eqs = cases([0.0, 0.5], 1.0, left, right, iv)
        with pytest.raises(sie.SideConditionError, match="must not be given"):
            eqs.solve(f_smooth, n=4, total=[1.0, 1.0])
    # a scalar total is shared
    s1 = ss.solve(f_smooth, n=4, total=2.0)
    s2 = ss.solve(f_smooth, n=4, total=[2.0, 2.0])
    assert np.array_equal(s1.coefficients, s2.coefficients)


@pytest.mark.parametrize("f, word", [
    (lambda s: np.where(s > 0.5, np.nan, s), "non-finite"),
    (lambda s: np.where(s > 0.5, np.inf, s), "non-finite"),
    (lambda s: s[:-1], "vectorised"),
    (lambda s: np.stack([s, s]), "vectorised"),
    (lambda s: s + 1j, "real"),
    (lambda s: 1.0 / (s - s), "non-finite"),
    (3.0, "f must be a vectorised callable"),            # not callable
])
def test_error_callable_output(f, word):
    eqs = cases([0.0, 0.5, 1e3], 1.0, "bounded", "bounded",
                [(0.0, 1.0), (0.25, 2.0), (-1.0, 1.0)])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)      # 1/0 in the f itself
        with pytest.raises(sie.CallableOutputError, match=word):
            eqs.solve(f, n=4)
        with pytest.raises(sie.CallableOutputError, match=word):
            eqs.functionals(f, n=4)


def test_error_evaluation_point():
    sb = cases(0.0, 1.0, "bounded", "bounded", [(0.0, 1.0)]).solve(f_smooth, n=4)
    for u in ([1.0], [-1.0], [0.0, 1.5], [np.nan]):
        with pytest.raises(sie.EvaluationPointError, match="strictly inside"):
            sb.cauchy_limit_local(np.array(u))
    assert np.isfinite(sb.cauchy_limit_local(np.array([np.nextafter(1.0, 0.0)]))).all()


def test_errors_are_sie_input_errors():
    """Every input error is an SIEInputError (one except clause catches them all)."""
    with pytest.raises(sie.SIEInputError):
        cases(0.0, 0.0, "bounded", "bounded", [(0.0, 1.0)])
    with pytest.raises(sie.SIEInputError):
        cases(0.0, 1.0, "bounded", "bounded", [(1.0, 0.0)])


@pytest.mark.filterwarnings("ignore::sie.InconsistentEquationWarning")
@pytest.mark.filterwarnings("ignore::sie.ResidualWarning")     # the two-interval solve at n = 4
def test_batch_of_its_own_solutions_is_the_batch():
    """SolutionBatch.of rebuilds a batch from the sie.Solution of each equation (what a
    contact result keeps): the same arrays, and the same Cauchy limits; solutions on several
    intervals, with breaks, or of different indices are refused."""
    sb = cases([0.3, -1.2, 4.0], [1.0, -2.0, 0.5], "bounded", "bounded",
               [(-1.0, 0.5), (0.0, 2.0), (-3.0, -1.0)]).solve(f_smooth, n=4)
    again = sie.SolutionBatch.of([sb[i] for i in range(len(sb))])
    for name in ("intervals", "a", "b", "alpha", "beta", "coefficients", "consistency", "mu0"):
        assert np.array_equal(getattr(again, name), getattr(sb, name)), name
    assert again.exponents == sb.exponents and (again.kappa, again.n) == (sb.kappa, sb.n)
    u = np.array([-0.9, 0.0, 0.7])
    assert np.array_equal(again.cauchy_limit_local(u), sb.cauchy_limit_local(u))
    two = sie.solve(f_smooth, a=0.3, b=1.0, n=4, left="bounded", right="bounded",
                    intervals=[(-1.0, 0.0), (0.5, 1.0)])
    with pytest.raises(sie.InvalidIntervalError, match="one interval each"):
        sie.SolutionBatch.of([two])
    other = sie.solve(f_smooth, a=0.3, b=1.0, n=4, left="singular", right="bounded",
                      intervals=[(-1.0, 0.0)])
    with pytest.raises(sie.InvalidIntervalError, match="one index and n"):
        sie.SolutionBatch.of([sb[0], other])
