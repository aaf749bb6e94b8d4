"""Cauchy transforms at complex points, Plemelj limits, and log potentials.

    C[psi](z) = (1/pi) int_L psi(t)/(t - z) dt        (sie.jacobi_cauchy, Solution.cauchy)
    V(x)      = (1/pi) int_L psi(t) log|x - t| dt     (Solution.log_potential),  V' = -H[psi]

References (tests/reference/manufactured_intervals.py; nothing there imports ``sie``):
  * the weight's transform in closed form (W): [(z-1)^alpha (z+1)^beta - Pol(z)]/sin(pi alpha),
    principal powers, cut on [-1, 1], alpha + beta in {-1, 0, 1} (alpha = beta = 1/2:
    sqrt(z^2 - 1) - z ~ -1/(2z));
  * w times a polynomial or an entire phi:  phi(z) T_w(z) + (1/pi) sum_k W_k (phi(t_k) - phi(z))/(t_k - z)
    with a 40-digit Gauss-Jacobi rule (exact for polynomials), valid at any distance from the cut;
  * mpmath.quad (moderate distance), Szego's Q_n (hypergeometric), Tricomi's (T) for the PV;
  * log potential: mpmath.quad in the end distances, split at x.
Group 0 checks these against each other.

Yardstick: errors of C(z) are measured against S(z) = (1/pi) int_L |psi(t)|/|t - z| dt (what
rounding of the integrand alone costs); on L (real x) against S(x + i 1e-14 h); errors of V
against (1/pi) int_L |psi| (1 + |log|x - t||) dt.  Tolerance 1e-13 unless said otherwise.
Measured errors are printed as ``[sie-cauchy]`` lines (run with -s).
"""
from __future__ import annotations

import functools
import math

import numpy as np
import pytest
from mpmath import mp

import sie

import manufactured as M
import manufactured_intervals as MI

TOL = 1e-13


def _api(*names):
    import sie
    missing = [x for x in names if not hasattr(sie, x)]
    if missing:
        pytest.fail(f"sie has no {missing} (the new API is not there yet)")
    return sie


def report(label, **vals):
    parts = [f"{k}={v:.2e}" if isinstance(v, float) else f"{k}={v}" for k, v in vals.items()]
    print(f"[sie-cauchy] {label}: " + " ".join(parts))


# ----------------------------------------------------------------------------
# densities for sie.jacobi_cauchy
# ----------------------------------------------------------------------------

_E07 = M.exponents(0.7, 1.0, "bounded", "bounded")       # the exponents sie.solve would use
DENSITIES = {
    # id: (coefficients in P_k^{(alpha,beta)}, alpha, beta)
    "sqrt(1-t^2)": ((1.0,), 0.5, 0.5),
    "w(-1/2,-1/2)": ((1.0,), -0.5, -0.5),
    "w(0.375,-0.375)": ((1.0,), 0.375, -0.375),
    "w(-0.25,-0.75)": ((1.0,), -0.25, -0.75),
    "w(0.125,0.875)": ((1.0,), 0.125, 0.875),
    "w P_5(0.3,-0.3)": ((0.0, 0.0, 0.0, 0.0, 0.0, 1.0), 0.3, -0.3),
    "w series(-0.625,0.625)": ((0.3, -1.0, 0.5, 0.25), -0.625, 0.625),
    "w series(-0.25,-0.75)": ((0.5, 0.25, -0.75, 0.1), -0.25, -0.75),
    "w series a/b=0.7 bdd-bdd": ((1.0, -0.5, 0.25), _E07.alpha_f, _E07.beta_f),
    "w series near 0 (2^-26,-2^-26)": ((0.5, 0.25, -1.0), 2.0 ** -26, -(2.0 ** -26)),
    "w series near 1 (1-2^-26,2^-26)": ((0.5, 0.25, -1.0), 1 - 2.0 ** -26, 2.0 ** -26),
}
DENS_IDS = list(DENSITIES)


@functools.lru_cache(maxsize=None)
def density(name) -> MI.JacobiDensity:
    c, a, b = DENSITIES[name]
    return MI.JacobiDensity(tuple(c), a, b)


def S_rel(err, S):
    return float(np.max(np.abs(err) / S))


# ----------------------------------------------------------------------------
# 0. the references themselves
# ----------------------------------------------------------------------------

MODERATE = (0.3 + 0.7j, -0.9 - 0.25j, 2.5 + 0j, 1.5j, -1.6 + 0.1j)


@pytest.mark.parametrize("name", DENS_IDS, ids=DENS_IDS)
@pytest.mark.slow
def test_reference_closed_form_vs_quad(name):
    """(W) + exact Gauss-Jacobi subtraction against mpmath.quad of psi/(t - z) at moderate distance."""
    D = density(name)
    with mp.workdps(M.DPS):
        for z in MODERATE:
            a, q = D.cauchy_mp(z), D.cauchy_quad_mp(z, dps=30)
            assert abs(a - q) <= mp.mpf("1e-25") * max(1, abs(q)), (z, a, q)


def test_reference_sqrt_transform():
    """(1/pi) int sqrt(1-t^2)/(t - z) dt = sqrt(z^2 - 1) - z with sqrt(z^2-1) = sqrt(z-1) sqrt(z+1)
    (principal roots: ~ z at infinity, cut on [-1, 1]), hence ~ -1/(2z) - 1/(8 z^3); this is
    (W) at alpha = beta = 1/2, and mpmath.quad agrees at moderate distance."""
    half = mp.mpf(1) / 2
    with mp.workdps(M.DPS):
        for z in (0.3 + 1e-12j, 0.3 - 1e-12j, -0.99 + 1e-8j, 1 + 1e-10j, 2.0 + 0j, -3 + 4j, 0.2 - 0.5j):
            z = mp.mpc(z)
            closed = mp.sqrt(z - 1) * mp.sqrt(z + 1) - z
            assert abs(MI.weight_cauchy_mp(half, half, z) - closed) <= mp.mpf("1e-35")
        for z in (0.2 - 0.5j, -3 + 4j):
            z = mp.mpc(z)
            q = M.int_w_mp(half, half, lambda t: 1 / (t - z)) / mp.pi
            assert abs(q - (mp.sqrt(z - 1) * mp.sqrt(z + 1) - z)) <= mp.mpf("1e-28")
        for th in (0.0, 1.0, 2.5, -2.0):
            z = mp.mpf(10) ** 6 * mp.expjpi(th / mp.pi)
            T = MI.weight_cauchy_mp(half, half, z)
            assert abs(T + 1 / (2 * z) + 1 / (8 * z ** 3)) <= 1 / abs(z) ** 5
        # upper/lower limits on the cut: sqrt(1-x^2)(-x/sqrt(1-x^2) +- i) = -x +- i sqrt(1-x^2)
        x = mp.mpf("0.3")
        for sgn in (1, -1):
            T = MI.weight_cauchy_mp(half, half, mp.mpc(x, sgn * mp.mpf("1e-30")))
            assert abs(T - mp.mpc(-x, sgn * mp.sqrt(1 - x * x))) <= mp.mpf("1e-28")


@pytest.mark.slow
def test_reference_szego_and_recurrence():
    """The transform of w P_n outside [-1, 1] equals Szego's -(2/pi)(x-1)^a (x+1)^b Q_n(x)
    (x < -1 via P_n^{(a,b)}(-t) = (-1)^n P_n^{(b,a)}(t)); the recurrence for P_n equals
    mpmath.jacobi (hypergeometric) at interior points."""
    with mp.workdps(M.DPS):
        for (al, be) in ((0.375, -0.375), (-0.25, -0.75), (0.125, 0.875)):
            for n in range(6):
                D = MI.JacobiDensity(tuple([0.0] * n + [1.0]), al, be)
                A, B = D._mp[0], D._mp[1]
                for x in (1.7, 1 + 2.0 ** -30, 12.0):
                    ref = MI.jacobi_second_kind_cauchy_mp(n, A, B, x)
                    assert abs(D.cauchy_mp(x) - ref) <= mp.mpf("1e-22") * abs(ref), (al, be, n, x)
                    refm = -(-1) ** n * MI.jacobi_second_kind_cauchy_mp(n, B, A, x)
                    assert abs(D.cauchy_mp(-x) - refm) <= mp.mpf("1e-22") * abs(refm), (al, be, n, -x)
                for u in ("-0.99", "-0.3", "0.41", "0.999"):
                    u = mp.mpf(u)
                    assert abs(D.phi_mp(u) - mp.jacobi(n, A, B, u)) <= mp.mpf("1e-30") * max(1, abs(D.phi_mp(u)))


@pytest.mark.parametrize("name", ["w series(-0.625,0.625)", "w series(-0.25,-0.75)", "sqrt(1-t^2)"])
def test_reference_plemelj(name):
    """C(x +- i 1e-30) = PV(x) +- i psi(x) between the complex (W) branch and the real
    Tricomi branch of the reference (two different formulas)."""
    D = density(name)
    with mp.workdps(M.DPS):
        al, be, phi = D._mp[:3]
        for x in (-0.7, 0.05, 0.93):
            x = mp.mpf(x)                        # the double, exactly
            psi = (1 - x) ** al * (1 + x) ** be * phi(x)
            pv = D.cauchy_mp(float(x))           # x is a double here
            for sgn in (1, -1):
                c = D.cauchy_mp(complex(float(x), sgn * 1e-30))
                assert abs(c - mp.mpc(pv, sgn * psi)) <= mp.mpf("1e-25") * (1 + abs(psi))


@pytest.mark.slow
def test_reference_scale_S():
    """The numpy yardstick S(z) against mpmath.quad on the same mesh (1e-2 relative is all a
    yardstick needs)."""
    D = density("w series(-0.25,-0.75)")
    for z in (0.05 + 1e-12j, 1 + 1e-10 * np.exp(0.7j), 2.5 + 0j):
        a = D.S(z)
        b = float(MI.scale_S_mp(D.alpha, D.beta, D.phi_mp, z, dps=15))
        assert abs(a - b) <= 1e-2 * b, (z, a, b)
    P = _problem("two intervals, gap 0.5")
    for x in (-0.6, 0.0, 1.75, 3.0):
        v = P.V_scale(x)
        assert np.isfinite(v) and v > abs(float(P.log_potential_mp(x)))


# ----------------------------------------------------------------------------
# solutions from sie.solve (manufactured, polynomial phi: the solver is exact to rounding)
# ----------------------------------------------------------------------------

PROBLEMS = {
    # id: (a/b, b, lengths, gaps, ends, phis, one-interval default API?)
    "one interval [sing,bdd] a/b=0.7": (0.7, 1.0, None, None, (("singular", "bounded"),), ("poly5",), True),
    "one interval [sing,sing] a/b=-1.3 b=-2": (-1.3, -2.0, None, None, (("singular", "singular"),),
                                               ("poly3",), True),
    "two intervals, gap 0.5": (0.7, 1.0, (1.0, 1.5), (0.5,), (("singular", "singular"), ("bounded", "singular")),
                               ("poly2", "poly3"), False),
    "two intervals, gap 1e-4, singular ends facing": (0.7, 1.0, (1.0, 0.75), (1e-4,),
                                                      (("bounded", "singular"), ("singular", "bounded")),
                                                      ("poly3", "poly2"), False),
}
PROB_IDS = list(PROBLEMS)


@functools.lru_cache(maxsize=None)
def _problem(name) -> MI.MultiProblem:
    ratio, b, lengths, gaps, ends, phis, _ = PROBLEMS[name]
    ivs = ((-1.0, 1.0),) if lengths is None else MI.layout(lengths, gaps)
    return MI.multi_problem(ratio * b, b, ivs, ends, phis, None)


@functools.lru_cache(maxsize=None)
def _solved(name):
    sie = _api("solve")
    P = _problem(name)
    default_api = PROBLEMS[name][-1]
    if default_api:
        (l, r), = P.ends
        sol = sie.solve(P.rhs, a=P.a, b=P.b, n=16, left=l, right=r, total=P.total[0])
    else:
        tot = P.total
        sol = sie.solve(P.rhs, a=P.a, b=P.b, n=12, left=P.left, right=P.right, intervals=P.intervals,
                        total=tot if any(t is not None for t in tot) else None)
    return P, sol


@pytest.mark.slow
def test_reference_multi_transforms():
    """The closed-form transforms of the manufactured psi against mpmath.quad (complex z at
    moderate distance) and against brute-force PV (real x inside, in the gap)."""
    P = _problem("two intervals, gap 0.5")
    with mp.workdps(M.DPS):
        for z in (0.0 + 0.4j, -0.75 - 0.5j, 2.5 + 1j, 0.9 + 0.6j):
            a, q = P.cauchy_mp(z), P.cauchy_quad_mp(z)
            assert abs(a - q) <= mp.mpf("1e-25"), (z, a, q)
    for x in (-0.6, 0.0, 1.0, 3.0, -2.0):
        a, q = float(P.hilbert(np.array(x))), float(P.hilbert_mp(x))
        assert abs(a - q) <= 2e-15 * max(1.0, abs(q)), (x, a, q)


@pytest.mark.slow
def test_reference_log_potential():
    """V(x2) - V(x1) = -int_{x1}^{x2} H[psi] dx (H from the closed forms, 60-point Gauss-Legendre
    where H is smooth), and the quadrature of V agrees with itself at 45 digits (incl. at an end)."""
    P = _problem("two intervals, gap 0.5")
    g, w = np.polynomial.legendre.leggauss(60)
    for x1, x2 in ((-0.2, 0.2), (0.4, 1.6), (-1.0, -0.5), (2.0, 3.0), (-4.0, -1.5)):
        xm, hh = (x1 + x2) / 2, (x2 - x1) / 2
        I = -hh * float(np.sum(w * P.hilbert(xm + hh * g)))
        dV = float(P.log_potential_mp(x2) - P.log_potential_mp(x1))
        assert abs(dV - I) <= 1e-14 * P.V_scale(x1), (x1, x2, dV, I)
    for x in (-0.25, 0.25, 1.75, 0.9):
        a, b = P.log_potential_mp(x), P.log_potential_mp(x, dps=45)
        assert abs(a - b) <= 1e-25


# ----------------------------------------------------------------------------
# 1. sie.jacobi_cauchy
# ----------------------------------------------------------------------------

FAR = (1.5 + 0j, -2.5 + 0j, 0.3 + 1.5j, -0.7 - 1.6j, 4 - 3j, -8 + 6j, 2 + 0.5j, -1.5 - 0.1j, 10j)


@functools.lru_cache(maxsize=None)
def _quad_ref(name, z, source="density"):
    """mpmath.quad of the Cauchy integral (20 digits) of a density or a solved problem."""
    D = density(name) if source == "density" else _problem(name)
    with mp.workdps(20):
        return complex(D.cauchy_quad_mp(z, dps=20))


@pytest.mark.parametrize("name", DENS_IDS, ids=DENS_IDS)
@pytest.mark.slow
def test_jacobi_cauchy_far(name):
    """|z| from 1.5 to 10, above, below and on the real axis outside [-1, 1] (as complex):
    against mpmath.quad (20 digits) to 1e-13 S(z)."""
    sie = _api("jacobi_cauchy")
    c, al, be = DENSITIES[name]
    D = density(name)
    z = np.array(FAR)
    got = np.asarray(sie.jacobi_cauchy(np.array(c), al, be, z))
    assert got.dtype.kind == "c" and got.shape == z.shape
    ref = np.array([_quad_ref(name, zz) for zz in FAR])
    S = np.array([D.S(zz) for zz in FAR])
    err = S_rel(got - ref, S)
    report(f"jacobi_cauchy far {name}", err_over_S=err)
    assert err <= TOL


def _near_points(x=(-0.7, 0.05, 0.93), ys=(1e-12, 1e-8, 1e-4)):
    return np.array([complex(xx, s * y) for xx in x for y in ys for s in (1, -1)])


def _end_points(r):
    th = np.array([0.0, 0.25, 0.5, 0.75, -0.25, -0.5, -0.75]) * np.pi
    right = 1 + r * np.exp(1j * th)
    left = -1 - r * np.exp(1j * th)          # mirror: theta = 0 points away from the cut
    return np.concatenate([right, left])


NEAR_SETS = {
    "|Im z|=1e-12,1e-8,1e-4 above/below": _near_points(),
    "z=+-1+1e-10 e^(i theta)": _end_points(1e-10),
    "z=+-1+1e-6 e^(i theta)": _end_points(1e-6),
}


@pytest.mark.parametrize("where", list(NEAR_SETS), ids=list(NEAR_SETS))
@pytest.mark.parametrize("name", DENS_IDS, ids=DENS_IDS)
def test_jacobi_cauchy_near(name, where):
    """Near the cut and near its ends: against the exact transform, to 1e-13 S(z)."""
    sie = _api("jacobi_cauchy")
    c, al, be = DENSITIES[name]
    D = density(name)
    z = NEAR_SETS[where]
    got = np.asarray(sie.jacobi_cauchy(np.array(c), al, be, z))
    with mp.workdps(M.DPS):
        ref = np.array([complex(D.cauchy_mp(complex(zz))) for zz in z])
    S = np.array([D.S(zz) for zz in z])
    err = S_rel(got - ref, S)
    k = int(np.argmax(np.abs(got - ref) / S))
    report(f"jacobi_cauchy near {name} {where}", err_over_S=err, worst_z=str(z[k]))
    assert err <= TOL, (z[k], got[k], ref[k], S[k])


@pytest.mark.parametrize("name", DENS_IDS, ids=DENS_IDS)
def test_jacobi_cauchy_real(name):
    """Real z: principal value inside (-1, 1) (Tricomi-based reference), ordinary integral
    outside; real output.  Yardstick S(x + i 1e-14)."""
    sie = _api("jacobi_cauchy")
    c, al, be = DENSITIES[name]
    D = density(name)
    x = np.array([-0.999, -0.7, 0.05, 0.5, 0.93, 0.99999, -1 - 1e-9, 1 + 1e-6, 1.5, -3.0])
    got = np.asarray(sie.jacobi_cauchy(np.array(c), al, be, x))
    assert got.dtype.kind == "f" and got.shape == x.shape
    with mp.workdps(M.DPS):
        ref = np.array([float(D.cauchy_mp(float(xx))) for xx in x])
    S = np.array([D.S(complex(xx, 1e-14)) for xx in x])
    err = S_rel(got - ref, S)
    report(f"jacobi_cauchy real {name}", err_over_S=err)
    assert err <= TOL


def test_jacobi_cauchy_sqrt_closed_form():
    """c = [1], alpha = beta = 1/2: the transform is sqrt(z-1) sqrt(z+1) - z (principal roots),
    from 1e-12 to 1e4 away from the cut and its ends, to 1e-13 relative (|C(z)| ~ S(z) here)."""
    sie = _api("jacobi_cauchy")
    r = np.geomspace(1e-12, 1e4, 60)
    z = np.concatenate([0.4 + 1j * r, -0.9 - 1j * r, 1 + r * np.exp(0.3j), -1 + r * np.exp(2.5j)])
    with mp.workdps(30):
        ref = np.array([complex(mp.sqrt(mp.mpc(zz) - 1) * mp.sqrt(mp.mpc(zz) + 1) - mp.mpc(zz)) for zz in z])
    got = np.asarray(sie.jacobi_cauchy([1.0], 0.5, 0.5, z))
    err = np.abs(got - ref) / np.abs(ref)
    report("jacobi_cauchy sqrt(1-t^2)", rel_err=float(np.max(err)))
    assert float(np.max(err)) <= TOL, z[int(np.argmax(err))]


def test_jacobi_cauchy_bad_input():
    """Complex z on [-1, 1] (Im z == 0), z at +-1, non-finite z: EvaluationPointError; alpha + beta
    not in {-1, 0, 1} or an exponent <= -1: an SIEInputError."""
    sie = _api("jacobi_cauchy", "EvaluationPointError", "SIEInputError")
    for z in (np.array([0.3 + 0j]), np.array([-1.0 + 0j]), 1.0, -1.0, np.array([np.nan]),
              np.array([complex(np.inf, 1.0)])):
        with pytest.raises(sie.EvaluationPointError):
            sie.jacobi_cauchy([1.0], -0.5, -0.5, z)
    for al, be in ((0.3, 0.2), (-1.0, 0.0), (0.25, -1.25)):
        with pytest.raises(sie.SIEInputError):
            sie.jacobi_cauchy([1.0], al, be, np.array([2.0 + 1j]))


# ----------------------------------------------------------------------------
# 2. Solution.cauchy: far, near, Plemelj, rays, real line, bad points
# ----------------------------------------------------------------------------

def _far_points(P):
    lo, hi = P.intervals[0][0], P.intervals[-1][1]
    m, h = (lo + hi) / 2, (hi - lo) / 2
    return m + h * np.array([1.5 + 0j, -2.0 + 0j, 0.4 + 1.5j, -0.3 - 1.7j, 3 + 4j, -10 + 1j, 0.1 - 6j])




@pytest.mark.parametrize("name", PROB_IDS, ids=PROB_IDS)
def test_solution_cauchy_far(name):
    """Solution.cauchy at complex z at 1.5 .. 10 (half-)widths of L against mpmath.quad of the
    exact psi, to 1e-13 S(z)."""
    P, sol = _solved(name)
    z = _far_points(P)
    got = np.asarray(sol.cauchy(z))
    assert got.dtype.kind == "c" and got.shape == z.shape
    ref = np.array([_quad_ref(name, zz, "problem") for zz in z])
    S = np.array([P.S(zz) for zz in z])
    err = S_rel(got - ref, S)
    report(f"Solution.cauchy far {name}", err_over_S=err)
    assert err <= TOL


def _near_L(P):
    out = []
    for j, (c, d) in enumerate(P.intervals):
        m, h = P.m(j), P.h(j)
        for u in (-0.7, 0.05, 0.93):
            for y in (1e-12, 1e-8, 1e-4):
                out += [complex(m + h * u, y * h), complex(m + h * u, -y * h)]
        for e in (c, d):
            for th in (0.2, 0.5, -0.5, -0.8):
                out.append(e + 1e-10 * h * np.exp(1j * np.pi * th))
    for (c0, d0), (c1, d1) in zip(P.intervals, P.intervals[1:]):      # in the gaps, just off the axis
        g = (d0 + c1) / 2
        out += [complex(g, 1e-8), complex(d0 + 1e-3 * (c1 - d0), -1e-12)]
    return np.array(out)


@pytest.mark.parametrize("name", PROB_IDS, ids=PROB_IDS)
def test_solution_cauchy_near(name):
    """1e-12 .. 1e-4 (times h) above and below each interval, 1e-10 h from every end, and in the
    gaps: against the exact transform of the exact psi, to 1e-13 S(z)."""
    P, sol = _solved(name)
    z = _near_L(P)
    got = np.asarray(sol.cauchy(z))
    ref = np.array([complex(P.cauchy_mp(zz)) for zz in z])
    S = np.array([P.S(zz) for zz in z])
    err = np.abs(got - ref) / S
    k = int(np.argmax(err))
    report(f"Solution.cauchy near {name}", err_over_S=float(err[k]), worst_z=str(z[k]))
    assert float(err[k]) <= TOL, (z[k], got[k], ref[k], S[k])


@pytest.mark.parametrize("name", PROB_IDS, ids=PROB_IDS)
def test_plemelj(name):
    """cauchy(x +- i 1e-14) = cauchy(x) +- i psi(x) for x inside every interval (all three from
    the library).  The identity holds up to the exact O(y) defect y C'(x) (~1e-12 |C| at 5e-3
    from a singular end), so the library's defect cauchy(x+-iy) - cauchy(x) -+ i psi(x) is
    compared with the exact one, C(x+-iy) - H(x) -+ i psi(x), to 1e-13 S(x + i 1e-14)."""
    P, sol = _solved(name)
    x = np.concatenate([P.m(j) + P.h(j) * M.sample_points(12, margin=1e-6) for j in range(P.J)])
    H = np.asarray(sol.cauchy(x))
    psi = np.asarray(sol(x))
    assert H.dtype.kind == "f"
    S = np.array([P.S(complex(xx, 1e-14)) for xx in x])
    H_ref, psi_ref = P.hilbert(x), P.psi(x)
    worst = 0.0
    for sgn in (1, -1):
        z = x + sgn * 1e-14j
        c = np.asarray(sol.cauchy(z))
        defect = c - (H + sgn * 1j * psi)
        exact = np.array([complex(P.cauchy_mp(zz)) for zz in z]) - (H_ref + sgn * 1j * psi_ref)
        worst = max(worst, S_rel(defect - exact, S))
    report(f"Plemelj {name}", err_over_S=worst)
    assert worst <= TOL


RAY_ANGLES = (0.3, math.pi / 2, 2.2, -0.8, -2.9)


def _rays():
    rho = np.geomspace(1.0001, 100.0, 120)
    out = {f"|z| 1.0001..100, arg={th:.2f}": rho * np.exp(1j * th) for th in RAY_ANGLES}
    r = np.geomspace(1e-4, 100.0, 120)
    for th in (math.pi / 3, -math.pi / 2, 0.0):
        out[f"z=1+r e^(i {th:.2f}), r 1e-4..100"] = 1 + r * np.exp(1j * th)
    for th in (2 * math.pi / 3, -math.pi / 3, math.pi):
        out[f"z=-1+r e^(i {th:.2f}), r 1e-4..100"] = -1 + r * np.exp(1j * th)
    return out


RAYS = _rays()


@pytest.mark.parametrize("ray", list(RAYS), ids=list(RAYS))
@pytest.mark.slow
def test_rays_from_near_to_far(ray):
    """Dense rays from next to L (or an end) out to |z| = 100: every point against the exact
    transform (so no switch between near and far evaluation can jump by more than the
    accuracy), for a Solution with a singular and a bounded end and for jacobi_cauchy with
    two singular ends.  1e-13 S(z) at every point; the error may not jump between neighbours
    by more than that either."""
    sie = _api("jacobi_cauchy")
    z = RAYS[ray]
    P, sol = _solved("one interval [sing,bdd] a/b=0.7")
    got = np.asarray(sol.cauchy(z))
    ref = np.array([complex(P.cauchy_mp(zz)) for zz in z])
    S = np.array([P.S(zz) for zz in z])
    e1 = (got - ref) / S
    D = density("w series(-0.25,-0.75)")
    got2 = np.asarray(sie.jacobi_cauchy(np.array(D.coeffs), D.alpha, D.beta, z))
    with mp.workdps(M.DPS):
        ref2 = np.array([complex(D.cauchy_mp(complex(zz))) for zz in z])
    S2 = np.array([D.S(zz) for zz in z])
    e2 = (got2 - ref2) / S2
    report(f"ray {ray}", solution=float(np.max(np.abs(e1))), jacobi_cauchy=float(np.max(np.abs(e2))),
           max_jump=float(max(np.max(np.abs(np.diff(e1))), np.max(np.abs(np.diff(e2))))))
    assert float(np.max(np.abs(e1))) <= TOL, z[int(np.argmax(np.abs(e1)))]
    assert float(np.max(np.abs(e2))) <= TOL, z[int(np.argmax(np.abs(e2)))]
    assert float(np.max(np.abs(np.diff(e1)))) <= TOL and float(np.max(np.abs(np.diff(e2)))) <= TOL


def _real_points(P):
    pts = []
    for j, (c, d) in enumerate(P.intervals):
        h = P.h(j)
        pts += [P.m(j) + h * u for u in (-0.999, -0.5, 0.05, 0.7, 0.99)]
        pts += [c - 1e-6 * h, d + 1e-6 * h, c - 0.3 * h, d + 0.3 * h]
    lo, hi = P.intervals[0][0], P.intervals[-1][1]
    pts += [lo - 5.0, hi + 7.0, hi + 1e3]
    return np.array(sorted(pts))


@pytest.mark.parametrize("name", PROB_IDS, ids=PROB_IDS)
def test_solution_cauchy_real_line(name):
    """Real x inside the intervals (PV), in the gaps (also 1e-6 h from an end), and outside:
    against the exact H[psi] (own interval by (M1)+(T), others by (X)), to 1e-13 of S(x + i 1e-14 h)."""
    P, sol = _solved(name)
    x = _real_points(P)
    got = np.asarray(sol.cauchy(x))
    assert got.dtype.kind == "f" and got.shape == x.shape
    ref = P.hilbert(x)
    S = np.array([P.S(complex(xx, 1e-14)) for xx in x])
    err = np.abs(got - ref) / S
    k = int(np.argmax(err))
    report(f"real line {name}", err_over_S=float(err[k]), worst_x=float(x[k]))
    assert float(err[k]) <= TOL, (x[k], got[k], ref[k])


@pytest.mark.parametrize("name", PROB_IDS, ids=PROB_IDS)
def test_solution_cauchy_points_on_L(name):
    """A complex z with Im z == 0 exactly on L (inside or at an end) raises EvaluationPointError;
    real z at a singular end raises too; a complex z with Im z == 0 off L is fine and equals the
    real transform there."""
    sie = _api("EvaluationPointError")
    P, sol = _solved(name)
    for j, (c, d) in enumerate(P.intervals):
        for x in (P.m(j) + 0.3 * P.h(j), c, d):
            with pytest.raises(sie.EvaluationPointError):
                sol.cauchy(np.array([x + 0j]))
            with pytest.raises(sie.EvaluationPointError):
                sol.cauchy(np.array([0.0 + 1j, x + 0j]))          # one bad point in an array
        for e, end in ((c, P.ends[j][0]), (d, P.ends[j][1])):
            if end == "singular":
                with pytest.raises(sie.EvaluationPointError):
                    sol.cauchy(e)
    off = np.array([P.intervals[-1][1] + 0.5, P.intervals[0][0] - 2.0]
                   + [(d0 + c1) / 2 for (c0, d0), (c1, d1) in zip(P.intervals, P.intervals[1:])])
    zc = np.asarray(sol.cauchy(off + 0j))
    zr = np.asarray(sol.cauchy(off))
    assert zc.dtype.kind == "c"
    assert np.all(np.abs(zc.imag) <= 1e-14 * np.abs(zr))
    assert np.all(np.abs(zc.real - zr) <= 1e-14 * np.abs(zr))


# ----------------------------------------------------------------------------
# 3. log potential
# ----------------------------------------------------------------------------

def _log_points(P):
    pts = []
    for j, (c, d) in enumerate(P.intervals):
        h = P.h(j)
        pts += [c, d, P.m(j) - 0.6 * h, P.m(j) + 0.2 * h, P.m(j) + 0.97 * h]
    for (c0, d0), (c1, d1) in zip(P.intervals, P.intervals[1:]):
        pts += [(d0 + c1) / 2]
    lo, hi = P.intervals[0][0], P.intervals[-1][1]
    pts += [lo - 0.01, hi + 0.3, hi + 10.0, lo - 100.0]
    return np.array(pts)


@functools.lru_cache(maxsize=None)
def _V_ref(name, x):
    return float(_problem(name).log_potential_mp(x))


@pytest.mark.parametrize("name", PROB_IDS, ids=PROB_IDS)
@pytest.mark.slow
def test_log_potential(name):
    """V(x) = (1/pi) int_L psi(t) log|x - t| dt inside, at the ends, in the gaps and outside,
    against mpmath.quad (split at x and at the ends), to 1e-13 of (1/pi) int |psi|(1 + |log|x-t||)."""
    P, sol = _solved(name)
    x = _log_points(P)
    got = np.asarray(sol.log_potential(x))
    assert got.dtype.kind == "f" and got.shape == x.shape
    ref = np.array([_V_ref(name, float(xx)) for xx in x])
    scale = np.array([P.V_scale(xx) for xx in x])
    err = np.abs(got - ref) / scale
    k = int(np.argmax(err))
    report(f"log potential {name}", err_over_scale=float(err[k]), worst_x=float(x[k]))
    assert float(err[k]) <= TOL, (x[k], got[k], ref[k])


@pytest.mark.parametrize("name", PROB_IDS, ids=PROB_IDS)
def test_log_potential_derivative(name):
    """dV/dx = -H[psi]: V(x2) - V(x1) = -int_{x1}^{x2} cauchy(x) dx (60-point Gauss-Legendre on
    the library's own real transform, on stretches where it is smooth: inside an interval away
    from its ends, in a gap, outside), to 1e-13 of the log-potential yardstick."""
    P, sol = _solved(name)
    g, w = np.polynomial.legendre.leggauss(60)
    spans = []
    for j, (c, d) in enumerate(P.intervals):
        h = P.h(j)
        spans.append((c + 0.3 * h, d - 0.3 * h))
        spans.append((d + 0.2 * h, d + 2.0 * h) if j == P.J - 1 else (d + 0.05 * (P.intervals[j + 1][0] - d),
                                                                       P.intervals[j + 1][0] - 0.05 * (P.intervals[j + 1][0] - d)))
    spans.append((P.intervals[0][0] - 3.0, P.intervals[0][0] - 0.5))
    worst = 0.0
    for x1, x2 in spans:
        xm, hh = (x1 + x2) / 2, (x2 - x1) / 2
        I = -hh * float(np.sum(w * np.asarray(sol.cauchy(xm + hh * g))))
        V = np.asarray(sol.log_potential(np.array([x1, x2])))
        worst = max(worst, abs((V[1] - V[0]) - I) / P.V_scale(x1))
    report(f"log potential derivative {name}", err_over_scale=worst)
    assert worst <= TOL


def test_log_potential_rejects_complex():
    sie = _api("EvaluationPointError")
    P, sol = _solved("two intervals, gap 0.5")
    with pytest.raises(sie.EvaluationPointError):
        sol.log_potential(np.array([0.3 + 0.1j]))
    with pytest.raises(sie.EvaluationPointError):
        sol.log_potential(np.array([np.nan]))


# ---------------------------------------------------------------------------
# one-sided limits on the line: C(x +- i0) = H[psi](x) +- i psi(x) (Plemelj)
# ---------------------------------------------------------------------------
def _limit_cases():
    f = lambda s: np.cos(2.0 * s) + s ** 3          # noqa: E731
    yield "kappa=1", sie.solve(f, a=0.4, b=1.0, n=20, left="singular", right="singular",
                               total=1.0)
    yield "kappa=0", sie.solve(f, a=-0.7, b=1.3, n=20, left="bounded", right="singular")
    yield "breaks", sie.solve(lambda s: np.abs(s - 0.3), a=0.4, b=1.0, n=24, left="singular",
                              right="bounded", breaks=(0.3,))
    yield "two intervals", sie.solve(f, a=0.2, b=1.0, n=16, left="singular", right="singular",
                                     total=(0.5, -0.2), intervals=[(-1.0, -0.1), (0.2, 1.0)])


@pytest.mark.parametrize("name, sol", list(_limit_cases()), ids=[c[0] for c in _limit_cases()])
def test_cauchy_limit_is_plemelj(name, sol):
    x = np.concatenate([np.linspace(-0.999, 0.999, 41), [-3.0, 0.0, 2.5]])
    x = x[[all(abs(v - e) > 1e-9 for e in np.ravel(sol.intervals)) for v in x]]
    on = np.zeros(x.shape, dtype=bool)
    for c, d in sol.intervals:
        on |= (x > c) & (x < d)
    H, psi = sol.cauchy(x), sol(x)
    scale = max(np.max(np.abs(H)), np.max(np.abs(psi)))
    for side in (1, -1):
        F = sol.cauchy_limit(x, side)
        assert np.max(np.abs(F.real - H)) <= 1e-13 * scale
        assert np.max(np.abs(F.imag - side * np.where(on, psi, 0.0))) <= 1e-13 * scale
    # and the limit of the transform at complex points approaching the line from above
    xi = x[on][::5]
    near = sol.cauchy(xi + 1e-9j)
    assert np.max(np.abs(near - sol.cauchy_limit(xi))) <= 1e-6 * scale


def test_cauchy_limit_refuses_bad_points_and_sides():
    sol = sie.solve(lambda s: s, a=0.0, b=1.0, n=4, left="bounded", right="bounded")
    with pytest.raises(sie.EvaluationPointError):
        sol.cauchy_limit([1.0])                   # an end
    with pytest.raises(sie.EvaluationPointError):
        sol.cauchy_limit([0.5 + 0.1j])            # complex: use cauchy
    with pytest.raises(sie.EvaluationPointError):
        sol.cauchy_limit([0.5], side=0)
