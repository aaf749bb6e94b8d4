"""``sie.solve(..., intervals=...)``: Cauchy singular integral equations on several intervals.

On L = [c_1, d_1] U ... U [c_J, d_J], for s in L,

    a psi(s) + (b/pi) PV int_L psi(t)/(t - s) dt + int_L k(s,t) psi(t) dt = f(s),

psi = w_j(u) phi_j(u) on interval j, u = (s - m_j)/h_j (API: /tmp/sie2/API.md).

References (tests/reference/manufactured_intervals.py, nothing there imports ``sie``): phi_j is chosen,
f is built from it -- the own interval by (M2) of tests/reference/manufactured.py, the other intervals
by (X) = phi(v) T_w(v) + regular Gauss-Jacobi sum with the weight's transform T_w in closed
form (W) -- and the solver must give phi_j back.  Group 0 checks those references against
brute-force mpmath quadrature (and (W) against Szego's hypergeometric Q_0), so a later
failure is a failure of the code, not of the reference.

Interval layouts are dyadic (``manufactured_intervals.layout``): "gap=1e-06" means a gap of
2^-20 ~ 9.5e-7 times the shorter neighbour, so that c_j = m_j - h_j exactly.

Tolerances (relative to max|phi_j| on its interval unless said otherwise):
  * polynomial phi_j (collocation exact), any gap down to 1e-6, n = 12..24 : 1e-12
  * exp / cos phi_j, n = 28                                               : 1e-12
  * int psi over an interval                       : 1e-12 * int |psi| over it
  * kappa_j = -1 consistency                       : 1e-12 * max(1, max|f|)
  * two collinear cracks, SIF at all four tips     : 1e-12 relative
  * an exponent within 3e-5 of -1 (a/b = -1e4, 1e8): 1e-12 + 1e-14 * int w du (the mass of
    the weight, ~1e4..1e8, multiplies the cross terms; f carries eps * that absolutely)
  * n = 2000 on one interval                        : 1e-10
Measured errors are printed as ``[sie-multi]`` lines (run with -s).
"""
from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass

import numpy as np
from scipy.special import roots_jacobi
import pytest
from mpmath import mp

import manufactured as M
import manufactured_intervals as MI
from _stored import StoredReferences
from test_solve_manufactured import _names as names_argument

TOL = 1e-12
S_LOC = M.sample_points(40)          # local evaluation points in (-1, 1)
CONFIGS = (("singular", "singular"), ("singular", "bounded"),
           ("bounded", "singular"), ("bounded", "bounded"))      # kappa = +1, 0, 0, -1


# ----------------------------------------------------------------------------
# helpers
# ----------------------------------------------------------------------------

def _api(*names):
    import sie
    missing = [x for x in names if not hasattr(sie, x)]
    if missing:
        pytest.fail(f"sie has no {missing} (the several-intervals API is not there yet)")
    return sie


def _abbrev(end):
    return {"singular": "sing", "bounded": "bdd"}[end]


def case_id(P, n, extra=""):
    """Id of a case from a MultiProblem or a Spec (no problem is built at collection)."""
    ends = "|".join(f"{_abbrev(l)},{_abbrev(r)}" for l, r in P.ends)
    kap = ",".join(f"{M.index_of(l, r):+d}" for l, r in P.ends)
    if isinstance(P, Spec):
        r, b, ivs, phis, ker = P.ratio, P.b, P.intervals, P.phis, P.kernel
    else:
        r, b, ivs, phis, ker = (0.0 if P.a == 0 else P.a / P.b), P.b, P.intervals, P.phi_names, \
            (P.kernel.name if P.kernel else None)
    gaps = ",".join(f"{(c1 - d0) / min(d0 - c0, d1 - c1):.0e}"
                    for (c0, d0), (c1, d1) in zip(ivs, ivs[1:]))
    nn = n if isinstance(n, int) else ",".join(map(str, n))
    return (f"J={len(ivs)} [{ends}] kappa=({kap}) a/b={r:g} b={b:g} gap/width=({gaps}) "
            f"phi=({','.join(phis)}) K={ker or 'none'} n={nn}{extra}")


@dataclass(frozen=True)
class Spec:
    """A manufactured multi-interval problem, built on first use (not at collection)."""
    ratio: float
    b: float
    lengths: tuple
    gaps: tuple
    ends: tuple
    phis: tuple
    kernel: object = None
    start: float = -1.25

    @property
    def intervals(self):
        return MI.layout(self.lengths, self.gaps, self.start)

    def build(self):
        return MI.multi_problem(self.ratio * self.b, self.b, self.intervals, self.ends,
                                self.phis, self.kernel)


def report(label, **vals):
    parts = [f"{k}={v:.2e}" if isinstance(v, float) else f"{k}={v}" for k, v in vals.items()]
    print(f"[sie-multi] {label}: " + " ".join(parts))


def solve_multi(P, n, **extra):
    """sie.solve on the manufactured problem P.  A value the same for all intervals
    (left, right) is passed once, otherwise per interval; totals only where kappa_j = 1.
    Asserts that no SIEWarning is emitted (f is consistent and resolved)."""
    sie = _api("solve", "SIEWarning")
    left = P.left[0] if len(set(P.left)) == 1 else P.left
    right = P.right[0] if len(set(P.right)) == 1 else P.right
    tot = P.total
    kw = dict(a=P.a, b=P.b, n=n, left=left, right=right, intervals=P.intervals,
              total=tot if any(t is not None for t in tot) else None)
    if P.kernel is not None:
        kw["kernel"] = P.kernel.f
    kw.update(extra)
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        sol = sie.solve(P.rhs, **kw)
    bad = [str(w.message) for w in rec if issubclass(w.category, sie.SIEWarning)]
    assert not bad, f"unexpected warnings for a consistent, resolved f: {bad}"
    return sol


def phi_scale(P, j):
    u = np.concatenate([S_LOC, [-1.0, 1.0]])
    return float(np.max(np.abs(P.parts[j].phi.f(u))))


FLOOR_PER_N = 32 * np.finfo(float).eps / TOL     # see rounding_scale


@functools.lru_cache(maxsize=None)
def _largest_term(P, j, n):
    """max |f| at the collocation nodes of interval j (roots of P_{n-kappa}^{(-alpha,-beta)})
    divided by |lambda_j| = 2^{-kappa} |b| / |sin(pi alpha_j)|: the largest term of the equation
    there, in units of phi.  Next to a tiny gap the neighbour's Cauchy integral makes it large
    (640 / 3.3 at n = 16 for a singular end facing a bounded one 1e-6 away), and the terms
    cancel to lambda phi = O(1): an ulp of f at such a node costs ~ n ulps of this in phi."""
    e = P.parts[j].e
    u = roots_jacobi(n - e.kappa, -float(e.alpha), -float(e.beta))[0]   # a scale, not a reference
    lam = 2.0 ** (-e.kappa) * abs(float(P.b)) / abs(float(mp.sin(mp.pi * e.alpha)))
    return float(np.max(np.abs(P.rhs(P.m(j) + P.h(j) * u)))) / lam


def rounding_scale(P, j, n):
    """Scale of the phi errors of interval j: max|phi_j| + 32 n eps / TOL * (largest term of the
    equation at the nodes, in units of phi), so that err <= TOL * max|phi_j| + 32 n eps * that
    term.  That is the rounding floor of the discrete system: for the three-interval case with a
    1e-6 gap (n = 12,16,20) f and the coupling correctly rounded at the nodes and everything else
    exact give 2.1e-12 in phi_1 (first-order bound 2.6e-12), the double projection of the rows
    1.2e-11 (bound), the library 9.3e-12; TOL * max|phi| alone (1e-12) is below what double
    data allow there."""
    return phi_scale(P, j) + FLOOR_PER_N * n * _largest_term(P, j, n)


def check_structure(sol, P, n):
    J = P.J
    ns = (n,) * J if isinstance(n, int) else tuple(n)
    assert tuple(tuple(map(float, iv)) for iv in sol.intervals) == P.intervals
    assert tuple(sol.kappa) == P.kappa
    assert tuple(sol.n) == ns
    assert len(sol.alpha) == len(sol.beta) == len(sol.coefficients) == len(sol.consistency) == J
    for j in range(J):
        assert abs(sol.alpha[j] - P.alpha[j]) <= 1e-15 and abs(sol.beta[j] - P.beta[j]) <= 1e-15, \
            (j, sol.alpha[j], P.alpha[j], sol.beta[j], P.beta[j])


def measure(sol, P):
    """Error measures (relative numbers) per interval and overall."""
    errs = {}
    for j in range(P.J):
        c, d = P.intervals[j]
        s = P.m(j) + P.h(j) * S_LOC
        s_all = np.concatenate([s, [c, d]])                   # closed interval for phi
        scale = rounding_scale(P, j, int(sol.n[j]))
        errs[f"phi[{j}]"] = float(np.max(np.abs(np.asarray(sol.phi(s_all), float)
                                                - P.phi_true(j, s_all)))) / scale
        w = P.parts[j].w(S_LOC)
        errs[f"psi/w[{j}]"] = float(np.max(np.abs(np.asarray(sol(s), float) - P.psi(s)) / w)) / scale
        errs[f"int[{j}]"] = abs(float(sol.integral(interval=j)) - P.integral(j)) / P.abs_integral(j)
        for end in (+1, -1):
            got = float(sol.endpoint_value(end, interval=j))
            errs[f"phi[{j}]({end:+d})"] = abs(got - float(P.parts[j].phi.f(np.array(float(end))))) / scale
        if P.parts[j].phi.poly is not None:
            c_ex = MI.jacobi_coefficients(P, j)
            cj = np.asarray(sol.coefficients[j], float)
            dd = np.zeros(max(len(cj), len(c_ex)))
            dd[:len(cj)] += cj
            dd[:len(c_ex)] -= c_ex
            errs[f"coef[{j}]"] = float(np.max(np.abs(dd))) / float(np.max(np.abs(c_ex)))
    tot_abs = sum(P.abs_integral(j) for j in range(P.J))
    errs["int(L)"] = abs(float(sol.integral()) - sum(P.integral(j) for j in range(P.J))) / tot_abs
    return errs


def check_consistency(sol, P, tol=1e-12):
    fs = max(1.0, P.fscale())
    for j, k in enumerate(P.kappa):
        if k == -1:
            assert sol.consistency[j] is not None
            assert abs(float(sol.consistency[j])) <= tol * fs, \
                f"interval {j}: consistency {float(sol.consistency[j]):.3e} for a consistent f"
        else:
            assert sol.consistency[j] is None, f"interval {j} (kappa={k:+d}): consistency should be None"


def check_errors(errs, tol, label):
    bad = {k: v for k, v in errs.items() if not (v <= tol)}          # NaN fails too
    assert not bad, f"{label}: errors above {tol:g}: {bad}"


def run_case(P, n, tol=TOL, **extra):
    sol = solve_multi(P, n, **extra)
    check_structure(sol, P, n)
    errs = measure(sol, P)
    report(case_id(P, n), worst=max(errs.values()), **{k: v for k, v in errs.items() if k.startswith("phi[")})
    check_errors(errs, tol, case_id(P, n))
    check_consistency(sol, P)
    return sol


# ----------------------------------------------------------------------------
# 0. the references themselves (no library involved)
# ----------------------------------------------------------------------------

WEIGHT_PAIRS = [(0.3, -0.3), (-0.5, -0.5), (0.25, 0.75), (-0.3, -0.7), (0.694, 0.306),
                (-1 + 3e-9, -3e-9), (3e-9, 1 - 3e-9)]


@pytest.mark.parametrize("alpha,beta", WEIGHT_PAIRS, ids=[f"alpha={a:g},beta={b:g}" for a, b in WEIGHT_PAIRS])
def test_reference_weight_transform_outside(alpha, beta):
    """(W) = [(v-1)^alpha (v+1)^beta - Pol(v)]/sin(pi alpha) against Szego's hypergeometric
    Q_0 form (Q0) (v > 1; v < -1 through the reflection) and, away from the ends, mpmath.quad.
    1e-20 at 40 digits: near-integer exponents at v = 1e3 cancel ~14 digits in F - Pol."""
    with mp.workdps(M.DPS):
        al = mp.mpf(alpha)
        be = mp.nint(al + mp.mpf(beta)) - al
        for v, dist in ((1.5, 0.5), (1 + 2 ** -20, 2 ** -20), (7.0, 6.0), (1e3, 999.0)):
            w = MI.weight_cauchy_outside_mp(al, be, v, dist)
            q = MI.weight_cauchy_szego_mp(al, be, v)
            assert abs(w - q) <= mp.mpf("1e-20") * abs(q), (v, w, q)
            # v < -1: T^{(alpha,beta)}(-v) = -T^{(beta,alpha)}(v), here against Szego directly
            wn = MI.weight_cauchy_outside_mp(al, be, -v, dist)
            qn = -MI.weight_cauchy_szego_mp(be, al, v)
            assert abs(wn - qn) <= mp.mpf("1e-20") * abs(qn), (-v, wn, qn)
        if min(alpha, beta) > -0.9:
            for v in (1.5, -2.5):
                w = MI.weight_cauchy_outside_mp(al, be, v, abs(v) - 1)
                quad = M.int_w_mp(al, be, lambda t: 1 / (t - v)) / mp.pi
                assert abs(w - quad) <= mp.mpf("1e-28") * abs(quad), (v, w, quad)


XREF = [
    Spec(0.7, 1.0, (1.0, 0.625, 1.375), (1e-6, 0.5),
         (("bounded", "singular"), ("singular", "singular"), ("bounded", "bounded")),
         ("poly5", "exp(s)", "poly2"), "0.3exp(st/4)"),
    Spec(-1.3, -2.0, (1.0, 0.625, 1.375), (1e-4, 1e-6),
         (("singular", "bounded"), ("bounded", "singular"), ("singular", "singular")),
         ("poly3", "cos(2s)+s^3", "1/(3-s)")),
]


#: mpmath's brute-force values of the manufactured right-hand sides (40 digits, ~5 s a case;
#: SIE_TEST_RECOMPUTE_REFS=1 computes them again)
_BRUTE = StoredReferences("intervals_brute_force_refs.json")


@pytest.mark.parametrize("spec", XREF, ids=["J=3 gaps=(1e-6,0.5) with kernel", "J=3 gaps=(1e-4,1e-6) b=-2"])
@pytest.mark.slow
def test_reference_rhs_against_brute_force(spec):
    """The double-precision f (M2 + X + Gauss-Jacobi kernel sum) equals a psi + b PV + K psi
    computed by mpmath.quad at 40 digits (no (T), no (W)), to 2e-15 * max(1, |f|), also at
    points 5e-8 from the tiny gap.  Likewise every cross term alone and H[psi] in the gap."""
    P = spec.build()
    pts = []
    for (c, d) in P.intervals:
        h = (d - c) / 2
        pts += [c + 2 ** -10 * h, d - 2 ** -24 * h]
    pts = np.array(pts)
    fd = P.rhs(pts)
    case = case_id(P, 0)
    fm = np.array([_BRUTE.real(f"rhs|{case}|{s!r}", lambda: P.rhs_mp(s)) for s in pts])
    err = np.abs(fd - fm) / np.maximum(1.0, np.abs(fm))
    report("reference rhs " + case_id(P, 0), max_err=float(err.max()), max_f=float(np.abs(fm).max()))
    assert float(err.max()) <= 2e-15, err
    assert P.rhs(np.zeros((2, 3)) + P.m(0)).shape == (2, 3)
    # cross terms next to the tiny gap, and H[psi] inside the gap
    (c0, d0), (c1, _) = P.intervals[0], P.intervals[1]
    for s in (d0, d0 - 2 ** -24, c0 + 0.25):
        x, y = P.cross(1, s), _BRUTE.real(f"cross|{case}|{s!r}", lambda: P.cross_mp(1, s))
        assert abs(x - y) <= 2e-15 * abs(y), (s, x, y)
    g = (d0 + c1) / 2                  # the two large cross terms cancel here: scale = sum |.|
    x, y = float(P.hilbert(np.array(g))), _BRUTE.real(f"hilbert|{case}|{g!r}",
                                                     lambda: P.hilbert_mp(g))
    assert abs(x - y) <= 2e-15 * sum(abs(P.cross(j, g)) for j in range(P.J)), (g, x, y)


def test_reference_polynomials_registered():
    """The extra phi's are the polynomials they claim to be, with the stable divided difference."""
    t, s = np.array([0.3, -0.99, 1.0]), np.array([0.3 + 1e-9, 0.5, -1.0])
    for name, c in MI.POLYS.items():
        ph = M.PHIS[name]
        assert ph.poly == c
        x = np.linspace(-1, 1, 5)
        assert np.allclose(ph.f(x), sum(ck * x ** k for k, ck in enumerate(c)), rtol=0, atol=1e-15)
        with mp.workdps(30):
            for ti, si in zip(t, s):
                exact = (ph.f_mp(mp.mpf(ti)) - ph.f_mp(mp.mpf(si))) / (mp.mpf(ti) - mp.mpf(si))
                assert abs(float(ph.divdiff(np.array(ti), np.array(si))) - float(exact)) <= 1e-14


CRACK_RATIOS = (0.1, 0.5, 0.9, 0.999)


@pytest.mark.parametrize("ratio", CRACK_RATIOS, ids=[f"b/c={r}" for r in CRACK_RATIOS])
@pytest.mark.slow
def test_reference_collinear_cracks(ratio):
    """The exact density psi = sgn(t)(t^2 - lambda^2)/sqrt((t^2-b^2)(c^2-t^2)), lambda^2 = c^2 E/K:
    (i) zero net integral over each crack; (ii) H[psi] = 1 on the cracks (brute-force PV);
    (iii) 1 - H[psi] = Westergaard's Z = (x^2-lambda^2)/X(x) off the cracks; (iv) the SIF
    closed forms equal sqrt(2 pi r) (1 - H[psi])(tip +- r) computed by quadrature of the
    density, r = 1e-10 h (error O(r)); (v) and the local end values of phi."""
    C = MI.CollinearCracks(ratio, 1.0)
    d = C._mp
    half = mp.mpf(-1) / 2
    with mp.workdps(M.DPS):
        tol = mp.mpf("1e-25")
        assert abs(M.int_w_mp(half, half, C.phi_right_mp)) <= tol                    # (i)
        for u in ("-0.7", "0.2", "0.95"):                                            # (ii)
            x = d["m"] + d["h"] * mp.mpf(u)
            assert abs(C.hilbert_mp(x) - 1) <= tol and abs(C.hilbert_mp(-x) - 1) <= tol
        for x in (mp.mpf("1.5"), d["b"] / 2, -mp.mpf(3), mp.zero):                   # (iii)
            assert abs(1 - C.hilbert_mp(x) - C.westergaard_mp(x)) <= tol
        r = d["h"] * mp.mpf("1e-10")                                                 # (iv)
        K_out = mp.sqrt(2 * mp.pi * r) * (1 - C.hilbert_mp(d["c"] + r))
        K_in = mp.sqrt(2 * mp.pi * r) * (1 - C.hilbert_mp(d["b"] - r))
        assert abs(K_out / C.K_outer - 1) <= mp.mpf("1e-8"), (K_out, C.K_outer)
        assert abs(K_in / C.K_inner - 1) <= mp.mpf("1e-8"), (K_in, C.K_inner)
        sq = mp.sqrt(mp.pi * d["h"])                                                 # (v)
        assert abs(sq * C.phi_right_mp(1) - C.K_outer) <= tol * C.K_outer
        assert abs(-sq * C.phi_right_mp(-1) - C.K_inner) <= tol * C.K_inner
        assert abs(sq * C.phi_left_mp(1) - C.K_inner) <= tol * C.K_inner
        assert abs(-sq * C.phi_left_mp(-1) - C.K_outer) <= tol * C.K_outer
    report(f"reference cracks b/c={ratio}", K_outer=float(C.K_outer), K_inner=float(C.K_inner),
           lam2=float(C.lam2))


def test_reference_collinear_cracks_limits():
    """b/c -> 1: two far-apart cracks of half-length a = (c-b)/2, K -> sqrt(pi a) at both tips,
    with a relative correction O(a/c).  b/c -> 0: one crack |x| < c, K_outer -> sqrt(pi c),
    K_outer/sqrt(pi c) = 1 - 1/ln(4c/b) + O((b/c)^2 ln) (K(k) = ln(4/k') + O(k'^2 ln k'),
    E(k) = 1 + O(k'^2 ln k'), DLMF 19.12.1-2)."""
    with mp.workdps(M.DPS):
        for eps in (1e-3, 1e-6):
            C = MI.CollinearCracks(1 - eps, 1.0)
            a = mp.mpf(eps) / 2
            for K in (C.K_outer, C.K_inner):
                assert abs(K / mp.sqrt(mp.pi * a) - 1) <= 2 * eps, (eps, K)
        for ratio in (1e-6, 1e-9):
            C = MI.CollinearCracks(ratio, 1.0)
            want = 1 - 1 / mp.log(4 / mp.mpf(ratio))
            assert abs(C.K_outer / mp.sqrt(mp.pi) - want) <= 100 * ratio ** 2 * abs(mp.log(ratio))


@pytest.mark.slow
def test_reference_airfoil_solvability_violated():
    """f = 1, a = 0 on two intervals bounded at all four ends: the solvability conditions
    int_L f t^k/R+(t) dt = 0 (k = 0, 1) fail (k = 1 gives pi by the residue at infinity), so
    sie must warn; for one interval the single condition int (1-s^2)^(-1/2) ds = pi != 0."""
    for L in (((-1.0, 0.0), (0.5, 2.0)), ((-2.0, -1.0), (1.0, 2.0))):
        vals = MI.airfoil_solvability_mp(L, lambda t: 1)
        assert max(abs(v) for v in vals) >= 1.0, vals
        assert abs(vals[1] - mp.pi) <= 1e-12, vals


# ----------------------------------------------------------------------------
# 1. manufactured solutions: two intervals, every pair of end choices
# ----------------------------------------------------------------------------

# a/b with its b: a != 0 gives exponents that are not multiples of 1/2; b = -2 flips the
# orientation of the dominant operator.  (Few distinct (a, b): each costs a 40-digit rule.)
AB = ((0.7, 1.0), (-1.3, -2.0), (0.0, 1.0))
GAPS2 = (1.0, 1e-2, 1e-4, 1e-6)
PHIS2 = (("poly2", "poly3"), ("poly5", "poly1"), ("poly3", "poly5"), ("poly1", "poly2"))


def _two_interval_cases():
    out = []
    for i0, e0 in enumerate(CONFIGS):
        for i1, e1 in enumerate(CONFIGS):
            k = 4 * i0 + i1
            ratio, b = AB[(i0 + i1) % 3]
            spec = Spec(ratio, b, (1.0, 1.5), (GAPS2[(i0 + 2 * i1) % 4],), (e0, e1), PHIS2[k % 4],
                        "0.3exp(st/4)" if k % 2 else None)
            n = 12 if k % 4 < 2 else (12, 20)
            out.append(pytest.param(spec, n, id=case_id(spec, n)))
    return out


@pytest.mark.parametrize("spec,n", _two_interval_cases())
def test_two_intervals_polynomial(spec, n):
    """16 pairs of (left, right) choices, a/b in {0.7, -1.3, 0}, gaps 1..1e-6, with and
    without a kernel: polynomial phi_j come back to 1e-12 (the collocation is exact)."""
    run_case(spec.build(), n)


GAP_SWEEP = (1.0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6)
FACING = {
    "singular ends facing": (("bounded", "singular"), ("singular", "bounded")),
    "bounded ends facing": (("singular", "bounded"), ("bounded", "singular")),
}


@pytest.mark.parametrize("gap", GAP_SWEEP, ids=[f"gap/width={g:g}" for g in GAP_SWEEP])
@pytest.mark.parametrize("facing", list(FACING), ids=list(FACING))
def test_gap_sweep(facing, gap):
    """gap/width from 1 down to 1e-6 with singular (psi ~ dist^(-0.69)) or bounded ends facing
    each other across the gap, a/b = 0.7 and a kernel: no loss of accuracy at n = 12."""
    run_case(Spec(0.7, 1.0, (1.0, 0.75), (gap,), FACING[facing], ("poly3", "poly2"),
                  "cos(s-t)/2").build(), 12)


# ----------------------------------------------------------------------------
# 2. three intervals, an entire phi, ten intervals
# ----------------------------------------------------------------------------

def _three_interval_cases():
    gaps = ((1e-6, 0.5), (1e-2, 1e-6), (1.0, 1e-4), (1e-6, 1e-6))
    phis = (("poly5", "poly2", "poly3"), ("poly1", "poly3", "poly2"))
    out = []
    for k in range(8):
        if k < 4:
            ends = (CONFIGS[k], CONFIGS[(k + 1) % 4], CONFIGS[(k + 3) % 4])
        else:
            ends = (CONFIGS[k % 4], CONFIGS[(k + 2) % 4], CONFIGS[k % 4])
        ratio, b = AB[k % 3]
        spec = Spec(ratio, b, (1.0, 0.625, 1.375), gaps[k % 4], ends, phis[k % 2],
                    ("cos(s-t)/2", None)[k % 2])
        n = 16 if k % 2 else (12, 16, 20)
        out.append(pytest.param(spec, n, id=case_id(spec, n)))
    return out


@pytest.mark.parametrize("spec,n", _three_interval_cases())
def test_three_intervals_polynomial(spec, n):
    """Every interval position sees every (left, right) choice, mixed with the others."""
    run_case(spec.build(), n)


ENTIRE = [
    Spec(0.7, 1.0, (1.0, 1.5), (1e-6,), (("bounded", "singular"), ("singular", "singular")),
         ("exp(s)", "cos(2s)+s^3"), "0.3exp(st/4)"),
    Spec(-1.3, -2.0, (1.0, 1.5), (1e-3,), (("singular", "bounded"), ("bounded", "bounded")),
         ("cos(2s)+s^3", "exp(s)")),
    Spec(0.0, 1.0, (1.0, 1.5, 0.75), (1e-6, 1e-1),
         (("bounded", "bounded"), ("singular", "singular"), ("bounded", "singular")),
         ("exp(s)", "poly3", "exp(s)"), "cos(s-t)/2"),
]


@pytest.mark.parametrize("spec", ENTIRE, ids=[case_id(sp, 28) for sp in ENTIRE])
def test_entire_phi(spec):
    """phi = exp(u), cos(2u) + u^3 (not polynomials): spectral convergence; n = 28 is enough
    for 1e-12, also with a gap of 1e-6 next to a singular end."""
    run_case(spec.build(), 28)


def _ten_intervals(kernel):
    lengths = (1.0, 0.5, 0.75, 1.25, 0.5, 1.0, 0.625, 0.75, 1.5, 0.5)
    gaps = (1.0, 1e-6, 1e-2, 0.5, 1e-4, 1e-6, 0.25, 1e-3, 1e-6)
    ends = tuple(CONFIGS[(3 * j) % 4] for j in range(10))
    phis = tuple(("poly1", "poly2", "poly3", "poly5")[j % 4] for j in range(10))
    return Spec(0.7, 1.0, lengths, gaps, ends, phis, kernel, start=-5.0).build()


@pytest.mark.parametrize("kernel", (None, "cos(s-t)/2"), ids=["K=none", "K=cos(s-t)/2"])
@pytest.mark.slow
def test_ten_intervals(kernel):
    """Ten intervals on [-5, ~4], gaps from 1 to 1e-6, all four end choices, polynomial phi."""
    run_case(_ten_intervals(kernel), 12)


# ----------------------------------------------------------------------------
# 3. two equal collinear cracks: stress intensity factors in closed form
# ----------------------------------------------------------------------------

@pytest.mark.parametrize("ratio", CRACK_RATIOS, ids=[f"b/c={r}" for r in CRACK_RATIOS])
def test_two_collinear_cracks(ratio):
    """(1/pi) PV int_L psi(t)/(t - x) dt = 1 on L = [-c,-b] U [b,c] (a = 0, b = 1, f = 1: unit
    crack-face pressure, equivalently unit remote tension), both ends singular, int psi = 0
    over each crack.  Exact solution and SIFs: manufactured_intervals.CollinearCracks
    (Westergaard's Z = (z^2 - c^2 E/K)/sqrt((z^2-b^2)(z^2-c^2)); Tada, Paris & Irwin,
    3rd ed., two-collinear-cracks entry), with K = sqrt(2 pi r) sigma_yy(r ahead of the tip),
    sigma_yy = 1 - H[psi] on the crack line.

    Normalisation: psi = (1-u)^(-1/2)(1+u)^(-1/2) phi(u) on each crack, half-width h, so at a
    right end psi ~ phi(1) 2^(-1/2) (h/(d - s))^(1/2) and K = sqrt(pi h) phi(+1); at a left end
    K = -sqrt(pi h) phi(-1) (psi -> -inf there: the opening gap is concave at both tips).
        K_outer = sqrt(pi c) (1 - E/K)/k,   K_inner = sqrt(pi c) sqrt(c/b) (E/K - b^2/c^2)/k,
    k^2 = 1 - b^2/c^2.  All four tips to 1e-12; phi at interior points to 1e-12, psi to 1e-12
    (relative to w max|phi|) plus the effect of rounding the interval midpoint."""
    sie = _api("solve")
    C = MI.CollinearCracks(ratio, 1.0)
    sol = sie.solve(lambda s: np.ones_like(np.asarray(s, float)), a=0.0, b=1.0, n=48,
                    left="singular", right="singular", total=(0.0, 0.0), intervals=C.intervals)
    assert tuple(sol.kappa) == (1, 1)
    assert sol.alpha == (-0.5, -0.5) and sol.beta == (-0.5, -0.5)
    h = (C.c - C.b) / 2
    sq = math.sqrt(math.pi * h)
    K_out, K_in = float(C.K_outer), float(C.K_inner)
    got = {
        "outer right (x=c)": (sq * float(sol.endpoint_value(+1, interval=1)), K_out),
        "inner right (x=b)": (-sq * float(sol.endpoint_value(-1, interval=1)), K_in),
        "inner left (x=-b)": (sq * float(sol.endpoint_value(+1, interval=0)), K_in),
        "outer left (x=-c)": (-sq * float(sol.endpoint_value(-1, interval=0)), K_out),
    }
    rel = {k: abs(g - w) / abs(w) for k, (g, w) in got.items()}
    # psi at interior points of both cracks, relative to w(s) max|phi|
    u = S_LOC
    s = (C.b + C.c) / 2 + h * u
    with mp.workdps(M.DPS):
        psi_ex = np.array([float(C.psi_mp(x)) for x in s])
    w = 1 / np.sqrt((1 - u) * (1 + u))
    scale = float(np.max(np.abs(C.phi_right(np.concatenate([u, [-1.0, 1.0]])))))
    # b = 0.999 etc. are not dyadic: the library's m = (b + c)/2 is rounded, which moves the
    # ends it works with by up to ~2 ulp(c), i.e. delta = 4 eps c/h in u; psi ~ dist^(-1/2)
    # then changes by ~delta/(2 dist) relatively.  That ambiguity is allowed for pointwise.
    delta = 4 * np.finfo(float).eps * C.c / h
    allow = 1e-12 + delta / (1 - np.abs(u))
    err_r = float(np.max(np.abs(np.asarray(sol(s), float) - psi_ex) / w / scale / allow))
    err_l = float(np.max(np.abs(np.asarray(sol(-s), float) + psi_ex) / w / scale / allow))
    err_phi = float(np.max(np.abs(np.asarray(sol.phi(s), float) - C.phi_right(u)))) / scale
    report(f"collinear cracks b/c={ratio}", K_outer=K_out, K_inner=K_in, psi_right_vs_allowed=err_r,
           psi_left_vs_allowed=err_l,
           phi=err_phi, **{k.split(" (")[0].replace(" ", "_"): v for k, v in rel.items()})
    bad = {k: v for k, v in rel.items() if not v <= 1e-12}
    assert not bad, f"SIF errors above 1e-12: {bad} (computed vs exact: {got})"
    assert err_r <= 1 and err_l <= 1 and err_phi <= 1e-12, (err_r, err_l, err_phi)
    for j in (0, 1):
        assert abs(float(sol.integral(interval=j))) <= 1e-13
        assert sol.consistency[j] is None


# ----------------------------------------------------------------------------
# 4. hard cases: exponents near 0 and +-1, n = 2000
# ----------------------------------------------------------------------------

HARD = [  # (a/b, ends): no exponent near -1 ...
    (-1e8, (("bounded", "bounded"), ("singular", "bounded"))),     # alpha ~ 3e-9, beta ~ 1 or -3e-9
    (1e8, (("bounded", "singular"), ("bounded", "bounded"))),      # alpha ~ -3e-9 or 1, beta ~ 3e-9
    (-1e4, (("singular", "bounded"), ("bounded", "bounded"))),
    (1e4, (("bounded", "bounded"), ("bounded", "singular"))),
    # ... and with one (within 3e-5 resp. 3e-9 of -1: the weight's mass ~ 1/(alpha+1))
    (-1e4, (("bounded", "singular"), ("bounded", "bounded"))),     # alpha_0 ~ -1 + 3.2e-5
    (1e8, (("bounded", "bounded"), ("singular", "bounded"))),      # beta_1 ~ -1 + 3.2e-9
]


HARD_SPECS = [Spec(ratio, 1.0, (1.0, 1.5), (1e-3,), ends, ("poly3", "poly2"), "0.3exp(st/4)")
              for ratio, ends in HARD]


def _hard_id(spec):
    ex = ",".join(f"({float(e.alpha):.3g},{float(e.beta):.3g})"
                  for e in (M.exponents(spec.ratio, 1.0, l, r) for l, r in spec.ends))
    return case_id(spec, 16, f" exponents={ex}")


@pytest.mark.parametrize("spec", HARD_SPECS, ids=[_hard_id(sp) for sp in HARD_SPECS])
@pytest.mark.slow
def test_hard_exponents(spec):
    """a/b = +-1e4, +-1e8: exponents within 3e-5 .. 3e-9 of 0, 1 or -1 on two intervals."""
    P = spec.build()
    mu = max(P.mu0(j) for j in range(P.J))
    tol = TOL + 1e-14 * mu
    sol = solve_multi(P, 16)
    check_structure(sol, P, 16)
    edge = np.array([-1 + 1e-14, -1 + 1e-8, 1 - 1e-8, 1 - 1e-14])
    for j in range(P.J):
        s = P.m(j) + P.h(j) * edge
        assert np.all(np.isfinite(np.asarray(sol.phi(s), float)))
    errs = measure(sol, P)
    report(case_id(P, 16), worst=max(errs.values()), tol=tol, mass=mu)
    check_errors(errs, tol, case_id(P, 16))
    check_consistency(sol, P, tol=1e-12 + 1e-14 * mu)


@pytest.mark.slow
def test_n_2000_on_one_interval():
    """n = (2000, 24): the long expansion converges (coefficient tail at rounding level) and
    matches the exact phi; it agrees with n = (32, 24)."""
    P = Spec(0.7, 1.0, (1.0, 1.5), (1e-3,), (("bounded", "singular"), ("singular", "singular")),
             ("exp(s)", "poly3")).build()
    sol = solve_multi(P, (2000, 24))
    check_structure(sol, P, (2000, 24))
    errs = measure(sol, P)
    c = np.asarray(sol.coefficients[0], float)
    tail = float(np.max(np.abs(c[60:]))) / float(np.max(np.abs(c)))
    small = solve_multi(P, (32, 24))
    s = P.m(0) + P.h(0) * S_LOC
    agree = float(np.max(np.abs(np.asarray(sol.phi(s), float) - np.asarray(small.phi(s), float))))
    report(case_id(P, (2000, 24)), worst=max(errs.values()), coef_tail=tail, vs_n32=agree)
    check_errors(errs, 1e-10, "n=2000")
    assert tail <= 1e-10
    assert agree <= 1e-10 * phi_scale(P, 0)


# ----------------------------------------------------------------------------
# 5. bad input: the specific error, naming the argument
# ----------------------------------------------------------------------------

nan, inf = float("nan"), float("inf")
IV = ((-1.0, 0.0), (0.5, 2.0))


def _base():
    # kappa = (+1, 0): a total for interval 0 only
    return dict(a=0.7, b=1.0, n=16, left=("singular", "singular"), right=("singular", "bounded"),
                total=(1.0, None), intervals=IV)


BAD = [
    # (id, overrides, error class name, argument the message must name)
    ("intervals overlap", dict(intervals=((-1.0, 0.5), (0.0, 2.0))), "InvalidIntervalError", "intervals"),
    # touching intervals are a junction (sie.solve_junctions); with the same a, b nothing jumps
    ("intervals touch", dict(intervals=((-1.0, 0.0), (0.0, 2.0))), "InvalidCoefficientError", "intervals"),
    ("intervals unordered", dict(intervals=((0.5, 2.0), (-1.0, 0.0))), "InvalidIntervalError", "intervals"),
    ("interval reversed c>d", dict(intervals=((0.0, -1.0), (0.5, 2.0))), "InvalidIntervalError", "intervals"),
    ("interval empty c=d", dict(intervals=((0.0, 0.0), (0.5, 2.0))), "InvalidIntervalError", "intervals"),
    ("interval end NaN", dict(intervals=((nan, 0.0), (0.5, 2.0))), "InvalidIntervalError", "intervals"),
    ("interval end NaN (right)", dict(intervals=((-1.0, 0.0), (0.5, nan))), "InvalidIntervalError", "intervals"),
    ("interval end -inf", dict(intervals=((-inf, 0.0), (0.5, 2.0))), "InvalidIntervalError", "intervals"),
    ("no intervals", dict(intervals=()), "InvalidIntervalError", "intervals"),
    ("n of length 3 for 2 intervals", dict(n=(16, 16, 16)), "PerIntervalArgumentError", "n"),
    ("n of length 1 for 2 intervals", dict(n=(16,)), "PerIntervalArgumentError", "n"),
    ("left of length 3", dict(left=("singular", "singular", "bounded")), "PerIntervalArgumentError", "left"),
    ("right of length 1", dict(right=("singular",)), "PerIntervalArgumentError", "right"),
    ("total of length 3", dict(total=(1.0, None, None)), "PerIntervalArgumentError", "total"),
    ("total missing (None) for kappa=+1", dict(total=None), "SideConditionError", "total"),
    ("total missing in sequence for kappa=+1", dict(total=(None, None)), "SideConditionError", "total"),
    ("total superfluous for kappa=0", dict(total=(1.0, 1.0)), "SideConditionError", "total"),
    ("break in the gap", dict(breaks=(0.25,)), "PerIntervalArgumentError", "breaks"),
    ("break at an interval end", dict(breaks=(0.5,)), "PerIntervalArgumentError", "breaks"),
    ("break outside L", dict(breaks=(-0.5, 3.0)), "PerIntervalArgumentError", "breaks"),
]


@pytest.mark.parametrize("overrides,err,name", [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_bad_input(overrides, err, name):
    sie = _api("solve", "SIEInputError", err)
    cls = getattr(sie, err)
    assert issubclass(cls, sie.SIEInputError) and issubclass(cls, ValueError)
    kw = _base()
    kw.update(overrides)
    with pytest.raises(cls) as info:
        sie.solve(np.cos, **kw)
    msg = str(info.value)
    assert names_argument(msg, name), f"message does not name {name!r}: {msg!r}"


def test_bad_input_baseline_is_valid():
    """The baseline of the bad-input table solves (so each case fails for its stated reason),
    also with a valid break inside an interval and totals given as a sequence."""
    sie = _api("solve")
    for extra in ({}, dict(breaks=(-0.5, 1.0)), dict(n=(16, 20))):
        kw = _base()
        kw.update(extra)
        sol = sie.solve(np.cos, **kw)
        assert len(sol.intervals) == 2
        assert abs(float(sol.integral(interval=0)) - 1.0) <= 1e-13


# ----------------------------------------------------------------------------
# 6. warnings and fixed kernel singularities
# ----------------------------------------------------------------------------

def _ones(s):
    return np.ones_like(np.asarray(s, float))


INCONSISTENT = [
    ("one interval, no intervals=", dict()),
    ("intervals=[(-1,1)]", dict(intervals=((-1.0, 1.0),))),
    ("two intervals", dict(intervals=((-1.0, 0.0), (0.5, 2.0)))),
    ("two symmetric intervals", dict(intervals=((-2.0, -1.0), (1.0, 2.0)))),
]


@pytest.mark.parametrize("extra", [c[1] for c in INCONSISTENT], ids=[c[0] for c in INCONSISTENT])
def test_inconsistent_kappa_minus_one_warns(extra):
    """a = 0, b = 1, f = 1, bounded at every end: index -1 per interval and f violates the
    solvability condition (test_reference_airfoil_solvability_violated) -> warning.  (The
    manufactured kappa = -1 cases above, all consistent, must not warn.)"""
    sie = _api("solve", "InconsistentEquationWarning", "SIEWarning")
    assert issubclass(sie.InconsistentEquationWarning, sie.SIEWarning)
    assert issubclass(sie.SIEWarning, UserWarning)
    with pytest.warns(sie.InconsistentEquationWarning):
        sol = sie.solve(_ones, a=0.0, b=1.0, n=16, left="bounded", right="bounded", **extra)
    if "intervals" not in extra:
        assert abs(float(sol.consistency)) >= 1e-3


def _edge_crack_kernel(shift):
    """Edge crack of a half plane (Erdogan, Gupta & Cook 1973) on [shift-1, shift+1]: the
    kernel has a fixed singularity at s = t = shift - 1 (the left end)."""
    def k(s, t):
        s, t = np.asarray(s, float) - shift, np.asarray(t, float) - shift
        u = t + s + 2
        return (-1 / u + 6 * (1 + s) / u ** 2 - 4 * (1 + s) ** 2 / u ** 3) / np.pi
    return k


EDGE = [
    ("one interval, no intervals=", 0.0, dict()),
    ("intervals=[(-1,1)]", 0.0, dict(intervals=((-1.0, 1.0),))),
    ("intervals=[(0,2)], kernel shifted", 1.0, dict(intervals=((0.0, 2.0),))),
    ("two intervals, singular end of the first", 0.0,
     dict(intervals=((-1.0, 1.0), (1.5, 2.5)), left="bounded", right="singular")),
]


@pytest.mark.parametrize("shift,extra", [c[1:] for c in EDGE], ids=[c[0] for c in EDGE])
def test_edge_crack_kernel_raises(shift, extra):
    sie = _api("solve", "KernelSingularityError", "SIEInputError")
    assert issubclass(sie.KernelSingularityError, sie.SIEInputError)
    kw = dict(a=0.0, b=1.0, n=16, left="bounded", right="singular", kernel=_edge_crack_kernel(shift))
    kw.update(extra)
    with pytest.raises(sie.KernelSingularityError) as info:
        sie.solve(_ones, **kw)
    assert names_argument(str(info.value), "kernel"), str(info.value)


def test_kernel_singular_outside_L_is_fine():
    """Negative control: the same kernel family with its singularity at s = t = -1.5, 0.5
    outside [-1, 1], is smooth on L x L (analytic in t with Bernstein parameter ~2.6, so
    n = 32 resolves it to ~1e-13): no KernelSingularityError and no SIEWarning."""
    sie = _api("solve", "SIEWarning")
    k = _edge_crack_kernel(-0.5)
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        sol = sie.solve(_ones, a=0.0, b=1.0, n=32, left="bounded", right="singular", kernel=k,
                        intervals=((-1.0, 1.0),))
    assert not [str(w.message) for w in rec if issubclass(w.category, sie.SIEWarning)]
    x = np.linspace(-0.95, 0.95, 9) + 1e-3
    assert np.all(np.isfinite(np.asarray(sol.phi(x), float)))
