"""Manufactured-solution tests for ``sie.solve``.

Equation (|s| < 1), psi = w phi, w = (1-s)^alpha (1+s)^beta:

    a psi(s) + (b/pi) PV int_{-1}^{1} psi(t)/(t-s) dt + int k(s,t) psi(t) dt = f(s)

The right-hand sides are built independently of the solver in
``tests/reference/manufactured.py`` (Tricomi's closed form for the Hilbert transform of
the weight, mpmath Gauss-Jacobi rules and mpmath.quad); the first group of
tests below checks those references against brute-force mpmath quadrature,
so every later comparison is against a trusted value.

Tolerances (relative to max|phi| unless said otherwise):
  * analytic phi, n <= 64                    : 1e-11 (phi, psi/w, phi(+-1), int psi)
  * Jacobi coefficients of a polynomial phi : 1e-12 * max|c_k|
  * kappa = -1 consistency                  : |consistency| <= 1e-12 max(1, ||f||_inf)
  * cauchy outside, |x| = 1e3               : 1e-12 relative (no cancellation allowed)
  * n = 5000                                : 1e-10 (rounding may grow like sqrt(n) eps cond)
  * nearly degenerate kappa = -1 (delta)    : 1e-13/delta (error ~ eps * cond, cond ~ 1/delta)

Measured errors are printed as lines starting with ``[sie-mms]``; run with
``-s`` to see them.
"""

from __future__ import annotations

import functools
import re

import numpy as np
import pytest
from mpmath import mp
from scipy.special import eval_jacobi

import manufactured as M


TOL = 1e-11
N_DEFAULT = 48
RATIOS = (-1e8, -3.0, -0.5, -1e-8, 0.0, 1e-8, 0.7, 5.0, 1e8)
CONFIGS = (  # (left, right) -> index kappa = -(alpha + beta)
    ("singular", "singular"),   # kappa = +1
    ("singular", "bounded"),    # kappa =  0
    ("bounded", "singular"),    # kappa =  0
    ("bounded", "bounded"),     # kappa = -1
)
PHI_NAMES = ("exp(s)", "1/(3-s)", "cos(2s)+s^3", "poly5")
KERNEL_NAMES = (None, "0.3exp(st)", "cos(s-t)/2")

S = M.sample_points(50)          # evaluation points in (-1, 1)


# ----------------------------------------------------------------------------
# helpers
# ----------------------------------------------------------------------------

def _sie():
    import sie
    if not hasattr(sie, "solve"):
        pytest.fail("sie.solve does not exist (yet)")
    return sie


def _abbrev(end):
    return {"singular": "sing", "bounded": "bdd"}[end]


def case_id(ratio, b, left, right, phi, kernel, n=None, extra=""):
    k = M.index_of(left, right)
    r = "0" if ratio == 0 else f"{ratio:g}"
    s = f"kappa={k:+d}[L={_abbrev(left)},R={_abbrev(right)}] a/b={r} b={b:g} phi={phi} K={kernel or 'none'}"
    if n is not None:
        s += f" n={n}"
    return s + extra


def a_of(ratio, b):
    return 0.0 if ratio == 0 else ratio * b        # exact in binary for b in {1, -2}


def solve_problem(P, n, **extra):
    sie = _sie()
    kw = dict(a=P.a, b=P.b, n=n, left=P.left, right=P.right, total=P.total)
    if P.kernel is not None:
        kw["kernel"] = P.kernel.f
    kw.update(extra)
    return sie.solve(P.rhs, **kw)


def report(label, **vals):
    parts = []
    for k, v in vals.items():
        if isinstance(v, float):
            parts.append(f"{k}={v:.2e}")
        else:
            parts.append(f"{k}={v}")
    print(f"[sie-mms] {label}: " + " ".join(parts))


def max_phi(P):
    return float(max(np.max(np.abs(P.phi.f(S))), abs(P.phi.f(np.array(1.0))),
                     abs(P.phi.f(np.array(-1.0)))))


def measure(sol, P):
    """All error measures of one solution (relative numbers)."""
    scale = max_phi(P)
    phi_ex = P.phi.f(S)
    w = P.w(S)
    phi_num = np.asarray(sol.phi(S), dtype=float)
    psi_num = np.asarray(sol(S), dtype=float)
    out = {
        "phi": float(np.max(np.abs(phi_num - phi_ex))) / scale,
        # psi compared pointwise relative to the weight: |psi - w phi| / (w max|phi|)
        "psi": float(np.max(np.abs(psi_num - w * phi_ex) / w)) / scale,
        "integral": abs(float(sol.integral()) - P.integral) / P.abs_integral,
        "phi(+1)": abs(float(sol.endpoint_value(+1)) - float(P.phi.f(np.array(1.0)))) / scale,
        "phi(-1)": abs(float(sol.endpoint_value(-1)) - float(P.phi.f(np.array(-1.0)))) / scale,
    }
    return out


def check_errors(errs, tol, label):
    bad = {k: v for k, v in errs.items() if not (v <= tol)}      # NaN fails too
    assert not bad, f"{label}: errors above {tol:g}: {bad} (all: {errs})"


def f_norm(P):
    return float(np.max(np.abs(P.rhs(S))))


# ----------------------------------------------------------------------------
# 0. the references themselves (no library involved)
# ----------------------------------------------------------------------------

TRICOMI_PAIRS = [
    (0.3, -0.3), (-0.6, 0.6), (-0.3, -0.7), (0.4, 0.6),      # kappa = 0, 0, +1, -1
    (0.3, -0.45), (-0.2, 0.5), (0.75, -0.9), (-0.95, -0.05),  # non-integer alpha+beta, strong ends
    (-1 + 1e-8, -1e-8), (1e-8, 1 - 1e-8), (-1e-8, 1e-8), (1 - 1e-8, 1e-8),  # near-integer exponents
]


@pytest.mark.parametrize("alpha,beta", TRICOMI_PAIRS,
                         ids=[f"alpha={al:g},beta={be:g}" for al, be in TRICOMI_PAIRS])
@pytest.mark.slow
def test_tricomi_formula(alpha, beta):
    """(T): (1/pi) PV int w/(t-s) = cot(pi a) w - 2^{a+b}/pi G(a)G(b+1)/G(a+b+1) 2F1(1,-a-b;1-a;(1-s)/2)
    against the principal value by singularity subtraction
    PV int w/(t-s) = int (w(t)-w(s))/(t-s) dt + w(s) log((1-s)/(1+s))."""
    with mp.workdps(M.DPS):
        for s in ("-0.7", "0.1", "0.93"):
            closed = M.hilbert_weight_mp(alpha, beta, mp.mpf(s))
            brute = M.hilbert_mp(alpha, beta, lambda t: mp.mpf(1), mp.mpf(s))
            assert abs(closed - brute) <= mp.mpf("1e-20") * max(1, abs(brute)), (s, closed, brute)


REF_CASES = [
    (0.7, 1.0, "bounded", "singular", "exp(s)", None),
    (-3.0, -2.0, "singular", "singular", "1/(3-s)", "0.3exp(st)"),
    (1e8, 1.0, "singular", "bounded", "cos(2s)+s^3", "cos(s-t)/2"),
    (-1e8, 1.0, "singular", "singular", "poly5", None),
    (1e8, 1.0, "bounded", "bounded", "exp(s)", "0.3exp(st)"),
    (-1e8, -2.0, "bounded", "singular", "1/(3-s)", None),
    (0.0, 1.0, "bounded", "bounded", "poly5", "cos(s-t)/2"),
]


@pytest.mark.parametrize("ratio,b,left,right,phi,kernel", REF_CASES,
                         ids=[case_id(*c) for c in REF_CASES])
@pytest.mark.slow
def test_reference_rhs_against_brute_force(ratio, b, left, right, phi, kernel):
    """The fast double-precision f of (M2) equals a psi + b H[psi] + K psi computed
    by mpmath.quad at 40 digits (no use of Tricomi's formula), to ~1e-15."""
    P = M.problem(a_of(ratio, b), b, left, right, phi, kernel)
    xs = np.array([-0.9990001, -0.3, 0.123456789, 0.5, 0.9712])
    fd = P.rhs(xs)
    fm = np.array([float(P.rhs_mp(x)) for x in xs])
    err = float(np.max(np.abs(fd - fm)) / np.max(np.abs(fm)))
    ierr = abs(P.integral - float(P.integral_mp())) / P.abs_integral
    report("reference " + case_id(ratio, b, left, right, phi, kernel), f_err=err, int_err=ierr)
    assert err <= 1e-14
    assert ierr <= 1e-15
    # f is a genuine vectorised callable: shape in == shape out
    assert P.rhs(np.zeros((2, 3))).shape == (2, 3)


@pytest.mark.slow
def test_reference_cauchy_outside():
    """The mpmath.quad reference for x outside [-1, 1]: against the 40-digit Gauss-Jacobi
    sum where that converges (|x - (+-1)| >= 0.5), and against itself at 50 digits with
    a different subdivision for x = +-(1 + 1e-6)."""
    for i, case in enumerate((CAUCHY_CASES[0], CAUCHY_CASES[2], CAUCHY_CASES[3])):
        ratio, b, left, right, phi, kernel = case
        P = M.problem(a_of(ratio, b), b, left, right, phi, kernel)
        for x in (1.5, -2.0, 1e3, -1e3):
            q, g = _cauchy_outside_ref(*case, x), float(P.cauchy_outside_gauss(x))
            assert abs(q - g) <= 1e-15 * abs(g), (case, x, q, g)
        if i == 1:
            continue
        for x in (1 + 1e-6, -1 - 1e-6):
            q = _cauchy_outside_ref(*case, x)
            q2 = float(P.cauchy_outside_mp(x, dps=50, splits=[mp.mpf(4) ** -k for k in range(1, 13)]))
            assert abs(q - q2) <= 1e-15 * abs(q2), (case, x, q, q2)


# ----------------------------------------------------------------------------
# 1. manufactured solutions for every index and a/b from -1e8 to 1e8
# ----------------------------------------------------------------------------

def _mms_cases():
    cases = []
    for ir, ratio in enumerate(RATIOS):
        for ic, (left, right) in enumerate(CONFIGS):
            i = 4 * ir + ic
            b = -2.0 if (ir + ic // 2) % 2 else 1.0
            phi = PHI_NAMES[(ir + ic) % 4]
            kernel = KERNEL_NAMES[i % 3]
            cases.append(pytest.param(ratio, b, left, right, phi, kernel, (),
                                      id=case_id(ratio, b, left, right, phi, kernel, N_DEFAULT)))
    # positive control for `breaks`: a valid interior break point changes nothing
    cases.append(pytest.param(0.7, 1.0, "bounded", "singular", "exp(s)", "0.3exp(st)", (0.25,),
                              id=case_id(0.7, 1.0, "bounded", "singular", "exp(s)", "0.3exp(st)",
                                         N_DEFAULT, " breaks=(0.25,)")))
    return cases


@pytest.mark.parametrize("ratio,b,left,right,phi,kernel,breaks", _mms_cases())
@pytest.mark.slow
def test_manufactured_solution(ratio, b, left, right, phi, kernel, breaks):
    P = M.problem(a_of(ratio, b), b, left, right, phi, kernel)
    sol = solve_problem(P, N_DEFAULT, breaks=breaks)
    label = case_id(ratio, b, left, right, phi, kernel, N_DEFAULT)

    # exponents and index as defined by cot(pi alpha0) = -a/b
    assert sol.kappa == P.kappa
    assert abs(sol.alpha - P.alpha) <= 1e-15 and abs(sol.beta - P.beta) <= 1e-15, \
        (sol.alpha, P.alpha, sol.beta, P.beta)
    assert sol.n == N_DEFAULT

    errs = measure(sol, P)
    if P.kappa == -1:
        cons = sol.consistency
        errs["consistency/max(1,|f|)"] = abs(float(cons)) / max(1.0, f_norm(P))
        tol_cons = 1e-12
    else:
        assert sol.consistency is None
        tol_cons = None
    if P.phi.poly is not None:
        c_ex = P.jacobi_coefficients()
        c = np.asarray(sol.coefficients, dtype=float)
        d = np.zeros(max(len(c), len(c_ex)))
        d[:len(c)] += c
        d[:len(c_ex)] -= c_ex
        errs["coef"] = float(np.max(np.abs(d))) / float(np.max(np.abs(c_ex)))
    report(label, **errs, condition=getattr(sol, "condition", "n/a"))

    cons_err = errs.pop("consistency/max(1,|f|)", None)
    coef_err = errs.pop("coef", None)
    check_errors(errs, TOL, label)
    if tol_cons is not None:
        assert cons_err <= tol_cons, f"kappa=-1 consistency {cons_err:.3e} for a consistent f"
    if coef_err is not None:
        assert coef_err <= 1e-12, f"Jacobi coefficients off by {coef_err:.3e}"


COEF_CASES = [(ratio, left, right, kernel)
              for ratio in (-1e8, -0.5, 0.7, 1e8)
              for (left, right), kernel in zip(CONFIGS, (None, "0.3exp(st)", None, "cos(s-t)/2"))]


@pytest.mark.parametrize("ratio,left,right,kernel", COEF_CASES,
                         ids=[case_id(r, 1.0, l, rt, "poly5", k, 16) for r, l, rt, k in COEF_CASES])
def test_polynomial_jacobi_coefficients(ratio, left, right, kernel):
    """phi = 1/2 - s + 2 s^2 + s^3/4 - 3 s^5/4: coefficients in P_k^{(alpha,beta)}
    (scipy.special.eval_jacobi normalisation) are exact; all higher ones vanish."""
    P = M.problem(a_of(ratio, 1.0), 1.0, left, right, "poly5", kernel)
    c_ex = P.jacobi_coefficients()
    # the reference itself: sum c_k P_k(x) == p(x).  scipy's eval_jacobi (independent of
    # mpmath) where it is accurate; for alpha or beta within 1e-6 of -1 it loses ~1e-7
    # relative (binomial(k + alpha, k) cancellation), so there use mpmath.jacobi.
    x = np.linspace(-1, 1, 7)
    if min(P.alpha, P.beta) > -1 + 1e-6:
        recon = sum(ck * eval_jacobi(k, P.alpha, P.beta, x) for k, ck in enumerate(c_ex))
    else:
        with mp.workdps(M.DPS):
            recon = np.array([float(sum(ck * mp.jacobi(k, P.e.alpha, P.e.beta, xi)
                                        for k, ck in enumerate(c_ex))) for xi in x])
    assert np.max(np.abs(recon - M.poly_eval(M.POLY5, x))) <= 1e-13

    sol = solve_problem(P, 16)
    c = np.asarray(sol.coefficients, dtype=float)
    assert len(c) >= len(c_ex)
    err_low = float(np.max(np.abs(c[:len(c_ex)] - c_ex)))
    err_high = float(np.max(np.abs(c[len(c_ex):]), initial=0.0))
    scale = float(np.max(np.abs(c_ex)))
    report(case_id(ratio, 1.0, left, right, "poly5", kernel, 16),
           coef_low=err_low / scale, coef_high=err_high / scale)
    assert err_low <= 1e-12 * scale
    assert err_high <= 1e-12 * scale


@pytest.mark.parametrize("ratio,b", [(0.7, 1.0), (-3.0, -2.0), (0.0, 1.0)],
                         ids=["a/b=0.7 b=1", "a/b=-3 b=-2", "a/b=0 b=1"])
def test_kappa_minus_one_inconsistent_rhs(ratio, b):
    """f + 1 violates int f (1-s)^-alpha (1+s)^-beta ds = 0 by
    2^{1-alpha-beta} B(1-alpha, 1-beta) = pi/sin(pi alpha0) >= pi: reported, not hidden."""
    P = M.problem(a_of(ratio, b), b, "bounded", "bounded", "exp(s)", None)
    sie = _sie()
    ok = sie.solve(P.rhs, a=P.a, b=P.b, n=24, left="bounded", right="bounded")
    bad = sie.solve(lambda s: P.rhs(s) + 1.0, a=P.a, b=P.b, n=24, left="bounded", right="bounded")
    fn = max(1.0, f_norm(P))
    report(f"inconsistent kappa=-1 a/b={ratio:g} b={b:g}",
           consistent=abs(float(ok.consistency)), inconsistent=abs(float(bad.consistency)))
    assert abs(float(ok.consistency)) <= 1e-12 * fn
    assert abs(float(bad.consistency)) >= 1e-3
    assert abs(float(bad.consistency)) >= 1e6 * abs(float(ok.consistency))


# ----------------------------------------------------------------------------
# 2. spectral convergence
# ----------------------------------------------------------------------------

CONV_CASES = [
    (-0.5, 1.0, "singular", "singular", None),
    (0.7, 1.0, "singular", "bounded", "0.3exp(st)"),
    (-3.0, -2.0, "bounded", "singular", None),
    (5.0, -2.0, "bounded", "bounded", "cos(s-t)/2"),
]


@pytest.mark.parametrize("ratio,b,left,right,kernel", CONV_CASES,
                         ids=[case_id(r, b, l, rt, "1/(3-s)", k) for r, b, l, rt, k in CONV_CASES])
def test_spectral_convergence(ratio, b, left, right, kernel):
    """phi = 1/(3-s): Bernstein ellipse rho = 3 + sqrt 8, error ~ rho^-n, i.e. ~0.77 digits per
    unit of n until round-off."""
    P = M.problem(a_of(ratio, b), b, left, right, "1/(3-s)", kernel)
    scale = max_phi(P)
    dig = {}
    for n in (4, 8, 16, 32):
        sol = solve_problem(P, n)
        err = float(np.max(np.abs(np.asarray(sol.phi(S), float) - P.phi.f(S))))
        dig[n] = M.digits(err, scale) if np.isfinite(err) else -np.inf
    report("convergence " + case_id(ratio, b, left, right, "1/(3-s)", kernel),
           **{f"digits(n={n})": f"{d:.1f}" for n, d in dig.items()})
    assert dig[32] >= 11, dig
    assert dig[16] >= dig[8] + 3, dig
    assert dig[8] > dig[4], dig


# ----------------------------------------------------------------------------
# 3. the Cauchy transform of the solution
# ----------------------------------------------------------------------------

CAUCHY_CASES = [
    (-0.5, 1.0, "singular", "singular", "exp(s)", None),
    (0.7, 1.0, "singular", "bounded", "1/(3-s)", "0.3exp(st)"),
    (-3.0, -2.0, "bounded", "singular", "cos(2s)+s^3", None),
    (5.0, -2.0, "bounded", "bounded", "exp(s)", "cos(s-t)/2"),
]
CAUCHY_IDS = [case_id(r, b, l, rt, p, k) for r, b, l, rt, p, k in CAUCHY_CASES]


@functools.lru_cache(maxsize=None)
def _solved(ratio, b, left, right, phi, kernel, n=N_DEFAULT):
    P = M.problem(a_of(ratio, b), b, left, right, phi, kernel)
    return P, solve_problem(P, n)


@pytest.mark.parametrize("ratio,b,left,right,phi,kernel", CAUCHY_CASES, ids=CAUCHY_IDS)
def test_cauchy_inside(ratio, b, left, right, phi, kernel):
    """cauchy(x) = H[w phi](x) = cot(pi alpha) w phi + phi H_reg[w] + (1/pi) int w (phi(t)-phi(x))/(t-x),
    i.e. (M1) with (T)."""
    P, sol = _solved(ratio, b, left, right, phi, kernel)
    xs = np.concatenate([np.linspace(-0.97, 0.97, 21) + 1e-3 * np.pi, [-0.999, 0.999]])
    ref = P.hilbert(xs)
    got = np.array([float(np.asarray(sol.cauchy(float(x)))) for x in xs])
    scale = np.maximum(np.abs(ref), max_phi(P))
    err = float(np.max(np.abs(got - ref) / scale))
    report("cauchy inside " + case_id(ratio, b, left, right, phi, kernel), err=err)
    assert err <= TOL


@functools.lru_cache(maxsize=None)
def _cauchy_outside_ref(ratio, b, left, right, phi, kernel, x):
    P = M.problem(a_of(ratio, b), b, left, right, phi, kernel)
    return float(P.cauchy_outside_mp(x))


OUTSIDE_X = (1.5, -2.0, 1 + 1e-6, -1 - 1e-6, 1e3, -1e3)


@pytest.mark.parametrize("x", OUTSIDE_X, ids=[f"x={x!r}" for x in OUTSIDE_X])
@pytest.mark.parametrize("ratio,b,left,right,phi,kernel", CAUCHY_CASES[:1] + CAUCHY_CASES[2:],
                         ids=CAUCHY_IDS[:1] + CAUCHY_IDS[2:])
def test_cauchy_outside(ratio, b, left, right, phi, kernel, x):
    """(1/pi) int w phi/(t - x) dt for real x outside [-1, 1], against mpmath.quad at 40 digits.
    |x| = 1e3: the value is ~ -int psi/(pi x); demand 1e-12 relative (no cancellation)."""
    P, sol = _solved(ratio, b, left, right, phi, kernel)
    ref = _cauchy_outside_ref(ratio, b, left, right, phi, kernel, x)
    got = float(np.asarray(sol.cauchy(x)))
    rel = abs(got - ref) / abs(ref)
    report(f"cauchy outside x={x!r} " + case_id(ratio, b, left, right, phi, kernel),
           value=ref, rel_err=rel)
    assert rel <= (1e-12 if abs(x) >= 1e3 else TOL)


@pytest.mark.parametrize("x", (1.0, -1.0), ids=["x=+1 (singular end)", "x=-1 (singular end)"])
def test_cauchy_raises_at_singular_end(x):
    P, sol = _solved(*CAUCHY_CASES[0])
    with pytest.raises(ValueError):
        sol.cauchy(x)


# ----------------------------------------------------------------------------
# 4. hard cases
# ----------------------------------------------------------------------------

HARD_CASES = [(ratio, left, right) for ratio in (-1e8, 1e8, -1e-8, 1e-8) for (left, right) in CONFIGS]


def _hard_id(ratio, left, right):
    e = M.exponents(a_of(ratio, 1.0), 1.0, left, right)
    return (case_id(ratio, 1.0, left, right, "1/(3-s)", "0.3exp(st)")
            + f" alpha={float(e.alpha):.10g} beta={float(e.beta):.10g}")


@pytest.mark.parametrize("ratio,left,right", HARD_CASES, ids=[_hard_id(*c) for c in HARD_CASES])
def test_hard_exponents_near_integers(ratio, left, right):
    """a/b = +-1e8: alpha0 = 1/2 + atan(a/b)/pi within 3.2e-9 of 0 or 1, so alpha, beta
    are within 3.2e-9 of -1, 0 or 1; a/b = +-1e-8: alpha0 = 1/2 +- 3.2e-9.
    Everything stays finite (also at s = +-(1 - 1e-14)) and accurate."""
    P = M.problem(a_of(ratio, 1.0), 1.0, left, right, "1/(3-s)", "0.3exp(st)")
    e = P.e
    if abs(ratio) > 1:   # the case really is hard
        dist = min(abs(float(e.alpha - mp.nint(e.alpha))), abs(float(e.beta - mp.nint(e.beta))))
        assert dist < 1e-8
    sol = solve_problem(P, N_DEFAULT)
    assert sol.kappa == P.kappa
    assert abs(sol.alpha - P.alpha) <= 1e-15 and abs(sol.beta - P.beta) <= 1e-15

    edge = np.array([-1 + 1e-14, -1 + 1e-8, 1 - 1e-8, 1 - 1e-14])
    assert np.all(np.isfinite(np.asarray(sol.phi(edge), float)))
    assert np.all(np.isfinite(np.asarray(sol(edge), float)))
    assert np.all(np.isfinite(np.asarray(sol.coefficients, float)))
    assert np.isfinite(float(np.asarray(sol.cauchy(0.3))))
    errs = measure(sol, P)
    # phi at the extreme edge points too
    errs["phi(edge)"] = float(np.max(np.abs(np.asarray(sol.phi(edge), float) - P.phi.f(edge)))) / max_phi(P)
    cond = getattr(sol, "condition", None)
    report("hard " + _hard_id(ratio, left, right), **errs, condition=cond if cond is not None else "n/a")
    check_errors(errs, TOL, "hard")
    if P.kappa == -1:
        assert abs(float(sol.consistency)) <= 1e-12 * max(1.0, f_norm(P))


LARGE_N = [(-3.0, -2.0, "singular", "singular"), (0.7, 1.0, "bounded", "bounded")]


@pytest.mark.parametrize("ratio,b,left,right", LARGE_N,
                         ids=[case_id(r, b, l, rt, "exp(s)", None, 5000) for r, b, l, rt in LARGE_N])
def test_large_n(ratio, b, left, right):
    """n = 5000, no kernel: finite, accurate to 1e-10, and the coefficient tail is clean."""
    P = M.problem(a_of(ratio, b), b, left, right, "exp(s)", None)
    sol = solve_problem(P, 5000)
    c = np.asarray(sol.coefficients, float)
    assert np.all(np.isfinite(c))
    errs = measure(sol, P)
    tail = float(np.max(np.abs(c[60:]))) / float(np.max(np.abs(c)))
    report(case_id(ratio, b, left, right, "exp(s)", None, 5000), **errs, coef_tail=tail,
           condition=getattr(sol, "condition", "n/a"))
    check_errors(errs, 1e-10, "n=5000")
    assert tail <= 1e-10


@functools.lru_cache(maxsize=None)
def _near_degenerate(delta):
    """kappa = -1, a/b = 0.7, b = 1.  A psi := a psi + b H psi, psi0 = w/(3-s).
    k(s,t) = c(s) with c = -(1 - delta) A psi0 / int psi0, so (A + K) psi0 = delta A psi0:
    the operator is invertible (kappa = -1, A injective) but with cond ~ 1/delta.
    f = (A + K) psi for psi = w exp(s) lies in range(A), hence is consistent."""
    P0 = M.problem(0.7, 1.0, "bounded", "bounded", "1/(3-s)", None)
    scale = -(1.0 - delta) * P0.b / P0.integral

    def k(s, t):
        s, t = np.broadcast_arrays(np.asarray(s, float), np.asarray(t, float))
        return scale * P0.smooth_part(s)         # A psi0 = b R0(s)  (a + b cot = 0)

    ker = M.Kernel(f"near-degenerate(delta={delta:g})", k)
    return M.problem(0.7, 1.0, "bounded", "bounded", "exp(s)", ker)


@pytest.mark.parametrize("delta", (1e-3,), ids=["delta=1e-3"])
def test_nearly_degenerate_kappa_minus_one(delta):
    P = _near_degenerate(delta)
    sol = solve_problem(P, 32)
    errs = measure(sol, P)
    cons = abs(float(sol.consistency)) / max(1.0, f_norm(P))
    cond = getattr(sol, "condition", None)
    report(f"near-degenerate kappa=-1 delta={delta:g}", **errs, consistency=cons,
           condition=cond if cond is not None else "n/a")
    assert all(np.isfinite(v) for v in errs.values())
    check_errors(errs, 1e-13 / delta, "near-degenerate")
    assert cons <= 1e-12


def test_condition_number_recorded():
    """Optional API: if Solution exposes .condition it must be finite, >= 1 and see the
    near-degeneracy (delta = 1e-3 vs the same kernel family at delta = 1)."""
    P_bad, P_good = _near_degenerate(1e-3), _near_degenerate(1.0)
    s_bad, s_good = solve_problem(P_bad, 32), solve_problem(P_good, 32)
    if getattr(s_bad, "condition", None) is None:
        pytest.skip("Solution has no .condition")
    c_bad, c_good = float(s_bad.condition), float(s_good.condition)
    report("condition", delta_1e_3=c_bad, delta_1=c_good)
    assert np.isfinite(c_bad) and np.isfinite(c_good)
    assert c_good >= 1 and c_bad >= 1
    assert c_bad >= 10 * c_good


# ----------------------------------------------------------------------------
# 5. bad input
# ----------------------------------------------------------------------------

def _names(msg, name):
    """Does the message name the argument?  Multi-letter names: as a word.  Single
    letters (a, b, f, n) must be quoted or followed by an operator/verb, so that the
    English article 'a' in '... must be a finite number' does not count."""
    if len(name) > 1:
        return re.search(rf"\b{re.escape(name)}\b", msg) is not None
    pat = (rf"['\"`]{name}['\"`]|(?<![\w'\"`-]){name}(?=\s*(?:==|!=|=|≠|<|>|≤|≥|:|\(|\)|,|\.|;|\[|$)"
           rf"|\s+(?:must|is|was|should|has|had|cannot|can't|returned|returns|return|raised|raises|gave|produced"
           rf"|contains|evaluat|values?|output|of|not|may|needs?|required)\b)")
    return re.search(pat, msg) is not None


def _base(kappa):
    left, right = {1: ("singular", "singular"), 0: ("singular", "bounded"), -1: ("bounded", "bounded")}[kappa]
    kw = dict(a=0.7, b=1.0, n=8, left=left, right=right)
    if kappa == 1:
        kw["total"] = 1.0
    return kw


def _f_ok(s):
    return np.cos(np.asarray(s, float))


nan = float("nan")
inf = float("inf")

BAD = [
    # (id, kappa of baseline, overrides, f, argument that must be named)
    ("n=0 (kappa=+1)", 1, dict(n=0), _f_ok, "n"),
    ("n=0 (kappa=0)", 0, dict(n=0), _f_ok, "n"),
    ("n=0 (kappa=-1)", -1, dict(n=0), _f_ok, "n"),
    ("n=-1 (kappa=+1)", 1, dict(n=-1), _f_ok, "n"),
    # kappa = +1 with n = 1: no collocation equation is left after the side condition
    ("n=1 too small for kappa=+1", 1, dict(n=1), _f_ok, "n"),
    ("n=-1 (kappa=-1)", -1, dict(n=-1), _f_ok, "n"),
    ("b=0", 0, dict(b=0.0), _f_ok, "b"),
    ("a=nan", 0, dict(a=nan), _f_ok, "a"),
    ("a=+inf", 0, dict(a=inf), _f_ok, "a"),
    ("a=-inf", -1, dict(a=-inf), _f_ok, "a"),
    ("b=nan", 0, dict(b=nan), _f_ok, "b"),
    ("b=+inf", 0, dict(b=inf), _f_ok, "b"),
    ("b=-inf", 1, dict(b=-inf), _f_ok, "b"),
    ("left='free'", 0, dict(left="free"), _f_ok, "left"),
    ("right='free'", 0, dict(right="free"), _f_ok, "right"),
    ("total missing for kappa=+1", 1, dict(total=None), _f_ok, "total"),
    ("total given for kappa=0", 0, dict(total=1.0), _f_ok, "total"),
    ("total given for kappa=-1", -1, dict(total=1.0), _f_ok, "total"),
    ("f returns one value too many", 0, {}, lambda s: np.ones(np.size(s) + 1), "f"),
    ("f returns a 2-D array", 0, {}, lambda s: np.ones((2,) + np.shape(s)), "f"),
    ("f returns NaN", 0, {}, lambda s: np.full(np.shape(s), nan), "f"),
    ("f returns complex values", 0, {}, lambda s: np.exp(1j * np.asarray(s)), "f"),
    ("f returns strings", 1, {}, lambda s: np.full(np.shape(s), "x"), "f"),
    ("f raises ValueError", -1, {}, lambda s: float("not a number"), "f"),
    ("f returns NaN at s>0.5 only", -1, {}, lambda s: np.where(np.asarray(s) > 0.5, nan, 1.0), "f"),
    ("kernel returns NaN", 0, dict(kernel=lambda s, t: np.full(np.broadcast(s, t).shape, nan)), _f_ok, "kernel"),
    ("kernel returns NaN for s*t<-0.25", 1,
     dict(kernel=lambda s, t: np.where(np.asarray(s) * np.asarray(t) < -0.25, nan, 0.1 + 0 * np.asarray(s) * np.asarray(t))),
     _f_ok, "kernel"),
    ("breaks=(1.5,)", 0, dict(breaks=(1.5,)), _f_ok, "breaks"),
    ("breaks=(1.0,)", 0, dict(breaks=(1.0,)), _f_ok, "breaks"),
    ("breaks=(-1.0,)", -1, dict(breaks=(-1.0,)), _f_ok, "breaks"),
    ("breaks=(0.2,-3)", 1, dict(breaks=(0.2, -3.0)), _f_ok, "breaks"),
]


@pytest.mark.parametrize("kappa,overrides,f,name", [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_bad_input_raises_value_error_naming_argument(kappa, overrides, f, name):
    sie = _sie()
    kw = _base(kappa)
    kw.update(overrides)
    with pytest.raises(ValueError) as info:
        sie.solve(f, **kw)
    msg = str(info.value)
    assert _names(msg, name), f"message does not name {name!r}: {msg!r}"


def test_bad_input_baselines_are_valid():
    """The baselines of the bad-input table solve without error (so each bad-input test
    fails for the stated reason only)."""
    sie = _sie()
    for kappa in (1, 0, -1):
        sol = sie.solve(_f_ok, **_base(kappa))
        assert np.all(np.isfinite(np.asarray(sol.phi(S), float)))
    sie.solve(_f_ok, **_base(0), kernel=lambda s, t: 0.1 + 0 * s * t, breaks=(0.2, -0.3))
