"""Tests of ``contact.closed_form`` against independent mpmath references.

Nothing here re-uses a closed form of the module as a reference. The candidate solution is the
module's output: its exponents (checked against the characteristic equation cot(pi alpha) = -xi)
and its pressure p(X) (checked to be w(s)*(e0 + e1 s) at many points; e0, e1 fitted from two
values). Everything else is brute-force mpmath quadrature of that candidate:

* the SIE (paper 4.8): N12 mu_f psi(s) + (N11/pi) PV int psi(t)/(t - s) dt = dv/dX(X(s)),
* the load int p dX = P,
* sigma_XX = N21 p + N22 mu_f Hc[p] inside and on both sides outside the contact,
* the kappa = -1 solvability condition int Lambda/w ds = 0 (paper 5.40),
* SIF definitions (5.11), (5.12), (5.23), (5.33) as numerical limits of p,
* classical mu_f = 0 limits (flat: Sadowsky, cylinder: Hertz),
* the paper's printed formulas that are wrong (exponent tables, (5.44)-(5.45) inside row).

Quadrature: every integrand is (1-t)^gr (1+t)^gl G(t) with G smooth; a piece touching t = 1 is
mapped by t = 1 - u^q, q = 1/(1+gr) (so (1-t)^gr dt = q du, and 1 - t = u^q is computed without
cancellation), likewise at t = -1. Principal values: the interval is split at s -/+ delta and the
symmetric middle piece is integrated as int_0^delta (psi(s+h) - psi(s-h))/h dh.

Run with ``-s`` to see the measured errors (lines starting with ``[closed-form]``).
"""
from __future__ import annotations

import functools
import math

import mpmath
import numpy as np
import pytest
from mpmath import mp, mpf

from contact import closed_form as cf

DPS = 20
LOAD = 1.7
GEOM = {"flat": 1.3, "triangular": 0.4, "parabolic": 2.0, "cylindrical": 2.0}
FUNCS = {
    "flat": cf.flat_closed_form,
    "triangular": cf.triangular_closed_form,
    "parabolic": cf.parabolic_closed_form,
    "cylindrical": cf.cylindrical_closed_form,
}
G_ISO, NU_ISO = 1.0, 0.3
CONSTANTS = {
    # isotropic, static, plane strain: N11 = -(1-nu)/G, N12 = (1-2nu)/(2G), N21 = -1, N22 = -2
    "iso": (-(1 - NU_ISO) / G_ISO, (1 - 2 * NU_ISO) / (2 * G_ISO), -1.0, -2.0),
    "ortho": (-0.37, 0.05, -0.6, -1.3),
}
MUS = (0.0, 0.1, -0.1, 0.3, -0.3, 0.5, -0.5)
PUNCHES = tuple(FUNCS)
# (left, right) end types dictated by the geometry
END_TYPES = {"flat": ("singular", "singular"), "triangular": ("singular", "bounded"),
             "parabolic": ("singular", "bounded"), "cylindrical": ("bounded", "bounded")}

CASES = [(p, c, m) for p in PUNCHES for c in CONSTANTS for m in MUS]
CASE_IDS = [f"{p}-{c}-mu{m:+.1f}" for p, c, m in CASES]

S_INSIDE = (-0.93, -0.4, 0.2, 0.85)          # SIE / sigma points (normalised s)
S_OUTSIDE = (-150.0, -6.0, -1.7, -1.05, 1.05, 1.7, 3.9, 4.1, 6.0, 150.0)

MAXERR: dict[str, float] = {}


def _record(name, err):
    """Keep the worst error of a kind for the summary printed after the module's tests (each
    test that records an error also asserts its own bound on it)."""
    MAXERR[name] = max(MAXERR.get(name, 0.0), float(err))


@pytest.fixture(scope="module", autouse=True)
def _print_worst_errors():
    """After the tests of this module that ran, print the worst error of each kind (run with
    ``-s`` to see them); not a test: it checks nothing and fails nothing."""
    yield
    for k, v in sorted(MAXERR.items()):
        print(f"[closed-form] max {k}: {v:.2e}")


@functools.lru_cache(maxsize=None)
def solution(punch, cname, mu):
    N = CONSTANTS[cname]
    return FUNCS[punch](*N, mu, GEOM[punch], LOAD)


def slope(punch, X):
    """dv/dX of the punch profile (v = -v0 + ...), at X (mpf)."""
    if punch == "flat":
        return mpf(0)
    if punch == "triangular":
        return mpf(GEOM["triangular"])
    return X / mpf(GEOM[punch])                 # parabolic, cylindrical: v = -v0 + X^2/(2R)


# ----------------------------------------------------------------------------------------------
# the mpmath reference
# ----------------------------------------------------------------------------------------------
def jint(gr, gl, G, lo, hi, scale=None):
    """int_lo^hi (1-t)^gr (1+t)^gl G(t, 1-t, 1+t) dt, lo, hi in [-1, 1], in mpmath.

    Pieces touching t = +-1 are mapped by t = 1 - u^q / -1 + u^q (q = 1/(1+gr) / 1/(1+gl)).
    ``scale``: distance (in t) of a near-singularity from the end, adds break points.
    """
    lo, hi = mpf(lo), mpf(hi)
    if lo == -1 and hi == 1:
        return jint(gr, gl, G, -1, 0, scale) + jint(gr, gl, G, 0, 1, scale)
    if hi == 1:
        q = 1 / (1 + mpf(gr))
        U = (1 - lo) ** (1 / q)

        def f(u):
            om = u ** q
            op = 2 - om
            return q * op ** gl * G(1 - om, om, op)
        return mp.quad(f, _breaks(U, q, scale))
    if lo == -1:
        q = 1 / (1 + mpf(gl))
        U = (1 + hi) ** (1 / q)

        def f(u):
            op = u ** q
            om = 2 - op
            return q * om ** gr * G(op - 1, om, op)
        return mp.quad(f, _breaks(U, q, scale))
    return mp.quad(lambda t: (1 - t) ** gr * (1 + t) ** gl * G(t, 1 - t, 1 + t), [lo, hi])


def _breaks(U, q, scale):
    pts = [mpf(0)]
    if scale is not None:
        u0 = mpf(scale) ** (1 / q)
        pts += [v for v in (u0 / 10, u0, 10 * u0) if v < U]
    return pts + [U]


class Ref:
    """mpmath model of a module solution: psi(s) = (1-s)^a (1+s)^b (e0 + e1 s)."""

    def __init__(self, sol):
        with mp.workdps(DPS):
            self.sol = sol
            self.a, self.b = mpf(sol.alpha), mpf(sol.beta)
            xl, xr = sol.ends
            self.xl, self.xr = mpf(xl), mpf(xr)
            self.L = (self.xr - self.xl) / 2
            self.c = (self.xr + self.xl) / 2
            # fit phi = e0 + e1 s through two values of the module's pressure
            vals = []
            for s in (mpf(-0.5), mpf(0.5)):
                X = float(self.X(s))
                s_exact = (mpf(X) - self.c) / self.L
                vals.append((s_exact, mpf(float(sol.pressure(X))) / self.w(s_exact)))
            (s1, f1), (s2, f2) = vals
            self.e1 = (f2 - f1) / (s2 - s1)
            self.e0 = f1 - self.e1 * s1

    def X(self, s):
        return self.L * s + self.c

    def s_of(self, X):
        return (mpf(X) - self.c) / self.L

    def w(self, s):
        return (1 - s) ** self.a * (1 + s) ** self.b

    def phi(self, s):
        return self.e0 + self.e1 * s

    def psi(self, s):
        return self.w(s) * self.phi(s)

    def hilbert(self, s):
        """H[psi](s) = (1/pi) PV int_{-1}^{1} psi(t)/(t - s) dt = Hc[p](X(s)), any real s."""
        with mp.workdps(DPS):
            s = mpf(s)
            a, b = self.a, self.b
            if abs(s) < 1:
                d = min(1 - s, 1 + s) / 2
                G = lambda t, om, op: self.phi(t) / (t - s)
                I1 = jint(a, b, G, -1, s - d)
                I2 = jint(a, b, G, s + d, 1)
                I3 = mp.quad(lambda h: (self.psi(s + h) - self.psi(s - h)) / h, [0, d])
                return (I1 + I2 + I3) / mp.pi
            if s == 1 or s == -1:   # bounded end: integrand ~ (1 -/+ t)^(exponent - 1)
                if s == 1:
                    G = lambda t, om, op: -self.phi(t)
                    return jint(a - 1, b, G, -1, 1) / mp.pi
                G = lambda t, om, op: self.phi(t)
                return jint(a, b - 1, G, -1, 1) / mp.pi
            G = lambda t, om, op: self.phi(t) / (t - s)
            return jint(a, b, G, -1, 1, scale=abs(s) - 1) / mp.pi

    def sigma(self, s):
        N11, N12, N21, N22 = (mpf(v) for v in (self.sol.N11, self.sol.N12, self.sol.N21, self.sol.N22))
        mu = mpf(self.sol.mu_f)
        p = self.psi(s) if abs(s) < 1 else mpf(0)
        return N21 * p + N22 * mu * self.hilbert(s)

    def load(self):
        with mp.workdps(DPS):
            return self.L * jint(self.a, self.b, lambda t, om, op: self.phi(t), -1, 1)


@functools.lru_cache(maxsize=None)
def ref(punch, cname, mu):
    return Ref(solution(punch, cname, mu))


@functools.lru_cache(maxsize=None)
def ref_hilbert(punch, cname, mu, s):
    return ref(punch, cname, mu).hilbert(s)


def stress_scale(sol):
    return sol.load / (sol.ends[1] - sol.ends[0])


def end_types(sol):
    return ("singular" if sol.beta < 0 else "bounded", "singular" if sol.alpha < 0 else "bounded")


# ----------------------------------------------------------------------------------------------
# exponents and structure
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("punch,cname,mu", CASES, ids=CASE_IDS)
def test_exponents(punch, cname, mu):
    sol = solution(punch, cname, mu)
    N11, N12, _, _ = CONSTANTS[cname]
    xi = mu * N12 / N11
    with mp.workdps(30):
        # characteristic equation of the dominant part (4.14)-(4.16): N12 mu_f + N11 cot(pi alpha) = 0
        assert abs(mpmath.cot(mp.pi * mpf(sol.alpha)) + xi) < 1e-13 * (1 + abs(xi))
    assert sol.kappa == -(sol.alpha + sol.beta) == {"flat": 1, "triangular": 0,
                                                    "parabolic": 0, "cylindrical": -1}[punch]
    assert -1 < sol.alpha < 1 and -1 < sol.beta < 1
    assert end_types(sol) == END_TYPES[punch]
    if mu == 0:
        assert {abs(sol.alpha), abs(sol.beta)} == {0.5}


@pytest.mark.parametrize("punch,cname,mu", CASES, ids=CASE_IDS)
def test_pressure_structure(punch, cname, mu):
    """p = w(s)(e0 + e1 s) everywhere inside, p >= 0, p = 0 outside, inf/0 at singular/bounded ends."""
    sol = solution(punch, cname, mu)
    r = ref(punch, cname, mu)
    xl, xr = sol.ends
    L = (xr - xl) / 2
    s = np.concatenate([np.linspace(-0.999, 0.999, 41), [-1 + 1e-9, 1 - 1e-9]])
    X = xl + L * (1 + s)
    p = sol.pressure(X)
    assert p.shape == X.shape and np.all(p > 0)
    with mp.workdps(DPS + 15):   # 1 - s ~ 1e-9 near the ends: keep digits in the reference
        err = max(abs(pi - r.psi(r.s_of(Xi))) / r.psi(r.s_of(Xi)) for pi, Xi in zip(p, X))
    _record("pressure = w*linear (rel)", err)
    assert err < 1e-12
    if punch != "parabolic":
        assert abs(r.e1) < 1e-13 * abs(r.e0)      # phi is a constant for these punches
    out = sol.pressure(np.array([xl - 5 * L, xl - 1e-12, xr + 1e-12, xr + 5 * L]))
    assert np.all(out == 0)
    ends = sol.pressure(np.array([xl, xr]))
    for val, kind in zip(ends, END_TYPES[punch]):
        assert (val == np.inf) if kind == "singular" else (val == 0)
    assert np.isscalar(sol.pressure(0.5 * (xl + xr))) or np.ndim(sol.pressure(0.5 * (xl + xr))) == 0


# ----------------------------------------------------------------------------------------------
# 1. the SIE
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("punch,cname,mu", CASES, ids=CASE_IDS)
@pytest.mark.slow
def test_sie_residual(punch, cname, mu):
    sol = solution(punch, cname, mu)
    r = ref(punch, cname, mu)
    N11, N12 = mpf(sol.N11), mpf(sol.N12)
    worst = 0.0
    with mp.workdps(DPS):
        for s in S_INSIDE:
            s = mpf(s)
            t1 = N12 * mpf(mu) * r.psi(s)
            t2 = N11 * ref_hilbert(punch, cname, mu, s)
            lam = slope(punch, r.X(s))
            scale = abs(t1) + abs(t2) + abs(lam) + abs(N11 * r.psi(s))   # flat, mu_f = 0: all 0
            worst = max(worst, float(abs(t1 + t2 - lam) / scale))
    _record("SIE residual (rel)", worst)
    assert worst < 1e-10


# ----------------------------------------------------------------------------------------------
# 2. load
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("punch,cname,mu", CASES, ids=CASE_IDS)
def test_load(punch, cname, mu):
    sol = solution(punch, cname, mu)
    P = ref(punch, cname, mu).load()
    err = float(abs(P - LOAD) / LOAD)
    _record("load by quadrature (rel)", err)
    assert err < 1e-12
    assert abs(sol.load_check - LOAD) < 1e-13 * LOAD
    assert sol.load == LOAD


# ----------------------------------------------------------------------------------------------
# 3. sigma_XX inside, at bounded ends and outside on both sides (near, |s| < 4, |s| > 4)
# ----------------------------------------------------------------------------------------------
#: sigma_XX needs an mpmath Hilbert transform per point: no friction, and 0.3 and 0.5 with
#: opposite signs (the exponent branches either side of 1/2)
SIGMA_CASES = [c for c in CASES if c[2] in (0.0, 0.3, -0.5)]


@pytest.mark.parametrize("punch,cname,mu", SIGMA_CASES,
                         ids=[f"{p}-{c}-mu{m:+.1f}" for p, c, m in SIGMA_CASES])
@pytest.mark.slow
def test_sigma_xx(punch, cname, mu):
    sol = solution(punch, cname, mu)
    r = ref(punch, cname, mu)
    xl, xr = sol.ends
    L = (xr - xl) / 2
    pts = list(S_INSIDE) + list(S_OUTSIDE)
    kinds = END_TYPES[punch]
    if kinds[0] == "bounded":
        pts.append(-1.0)
    if kinds[1] == "bounded":
        pts.append(1.0)
    X = np.array([xl if s == -1 else xr if s == 1 else xl + L * (1 + s) for s in pts])
    got = sol.sigma_xx(X)
    got_h = sol.hilbert_pressure(X)
    floor = 1e-3 * stress_scale(sol)      # values near a zero crossing: absolute 1e-12 * P/(2L)
    worst = worst_h = 0.0
    with mp.workdps(DPS):
        N21, N22, muf = mpf(sol.N21), mpf(sol.N22), mpf(mu)
        for Xi, g, gh, s_nom in zip(X, got, got_h, pts):
            s = mpf(-1) if s_nom == -1 else mpf(1) if s_nom == 1 else r.s_of(Xi)
            h = ref_hilbert(punch, cname, mu, s) if s_nom in S_INSIDE else r.hilbert(s)
            p = r.psi(s) if abs(s) < 1 else mpf(0)
            ref_sigma = N21 * p + N22 * muf * h
            e = float(abs(g - ref_sigma) / max(abs(ref_sigma), floor))
            eh = float(abs(gh - h) / max(abs(h), floor))
            worst, worst_h = max(worst, e), max(worst_h, eh)
            assert e < 1e-9, (s_nom, g, ref_sigma)
            assert eh < 1e-9, (s_nom, gh, h)
    _record("sigma_xx vs quadrature (rel)", worst)
    _record("Hc[p] vs quadrature (rel)", worst_h)
    # scalar in, scalar out
    assert np.ndim(sol.sigma_xx(float(X[0]))) == 0


@pytest.mark.parametrize("punch", PUNCHES)
def test_sigma_xx_raises_at_singular_ends(punch):
    sol = solution(punch, "iso", 0.3)
    xl, xr = sol.ends
    for X, kind in zip((xl, xr), END_TYPES[punch]):
        if kind == "singular":
            with pytest.raises(ValueError):
                sol.sigma_xx(X)
            with pytest.raises(ValueError):
                sol.sigma_xx(np.array([0.5 * (xl + xr), X]))
        else:
            assert np.isfinite(sol.sigma_xx(X))
    with pytest.raises(ValueError):
        sol.sigma_xx(np.nan)


@pytest.mark.parametrize("punch", PUNCHES)
def test_sigma_xx_continuous_across_far_switch(punch):
    """The code switches to the hypergeometric form at |s| = 4: no jump there (the smooth change
    over the 2e-13 relative step in X is ~2e-13 relative, since Hc ~ 1/X out there)."""
    sol = solution(punch, "ortho", -0.5)
    xl, xr = sol.ends
    L = (xr - xl) / 2
    for s0 in (-4.0, 4.0):
        X0 = xl + L * (1 + s0)
        v = sol.hilbert_pressure(np.array([X0 * (1 - 1e-13), X0 * (1 + 1e-13)]))
        assert abs(v[0] - v[1]) < 1e-12 * abs(v[0])


# ----------------------------------------------------------------------------------------------
# 4. cylindrical: solvability, positivity, p -> 0 at both ends
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("cname", tuple(CONSTANTS))
@pytest.mark.parametrize("mu", MUS)
def test_cylindrical_solvability(cname, mu):
    sol = solution("cylindrical", cname, mu)
    r = ref("cylindrical", cname, mu)
    with mp.workdps(DPS):
        lam = lambda t, om, op: slope("cylindrical", r.X(t))
        val = jint(-r.a, -r.b, lam, -1, 1)
        absval = jint(-r.a, -r.b, lambda t, om, op: abs(slope("cylindrical", r.X(t))), -1, 1)
    err = float(abs(val) / absval)
    _record("cylinder int Lambda/w (rel)", err)
    assert err < 1e-13
    xl, xr = sol.ends
    assert xl < 0 < xr
    L = (xr - xl) / 2
    for h in (1e-3, 1e-6, 1e-9):
        for X in (xl + h * L, xr - h * L):
            assert 0 < sol.pressure(X) < 10 * h ** 0.4 * sol.pressure(0.5 * (xl + xr))
    assert sol.pressure(xl) == 0 and sol.pressure(xr) == 0


# ----------------------------------------------------------------------------------------------
# 5. classical mu_f = 0 limits (formulas from the literature, not from the paper)
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("cname", tuple(CONSTANTS))
def test_mu0_flat_sadowsky(cname):
    """Rigid flat punch: p = P/(pi sqrt(a^2 - X^2)) (Sadowsky 1928; Johnson 1985, ch. 2)."""
    sol = solution("flat", cname, 0.0)
    a, P = GEOM["flat"], LOAD
    X = np.linspace(-0.999 * a, 0.999 * a, 31)
    exact = P / (np.pi * np.sqrt(a * a - X * X))
    assert sol.ends == (-a, a)
    np.testing.assert_allclose(sol.pressure(X), exact, rtol=2e-14)


@pytest.mark.parametrize("cname", tuple(CONSTANTS))
def test_mu0_cylinder_hertz(cname):
    """Hertz 2D (Johnson, Contact Mechanics 1985, ch. 4).

    For a rigid cylinder on a half-plane with dv/dX = N11 Hc[p]: a^2 = -2 N11 P R/pi,
    p = (2P/(pi a^2)) sqrt(a^2 - X^2). Isotropic static: N11 = -(1-nu)/G, so
    a^2 = 2 P R (1-nu)/(pi G) = 4 P R/(pi E*), E* = E/(1-nu^2) = 2G/(1-nu): Johnson's a^2 = 4PR/(pi E*).
    """
    sol = solution("cylindrical", cname, 0.0)
    N11 = CONSTANTS[cname][0]
    R, P = GEOM["cylindrical"], LOAD
    a2 = -2 * N11 * P * R / math.pi
    if cname == "iso":
        Estar = 2 * G_ISO / (1 - NU_ISO)
        assert abs(a2 - 4 * P * R / (math.pi * Estar)) < 1e-15 * a2
    a = math.sqrt(a2)
    assert abs(sol.ends[0] + a) < 1e-14 * a and abs(sol.ends[1] - a) < 1e-14 * a
    X = np.linspace(-0.999 * a, 0.999 * a, 31)
    np.testing.assert_allclose(sol.pressure(X), 2 * P / (math.pi * a2) * np.sqrt(a2 - X * X),
                               rtol=1e-13)


@pytest.mark.parametrize("cname", tuple(CONSTANTS))
def test_mu0_triangular_parabolic(cname):
    """alpha = 1/2, beta = -1/2; p from Muskhelishvili's bounded-at-b inversion of N11 Hc[p] = v'
    on [0, b]: p = -(1/(pi N11)) sqrt((b-X)/X) int_0^b sqrt(t/(b-t)) v'(t)/(t-X) dt (done by hand)."""
    N11 = CONSTANTS[cname][0]
    P = LOAD
    # triangular: v' = m0 -> p = -(m0/N11) sqrt((b-X)/X), int p = -(m0/N11) b pi/2 = P
    m0 = GEOM["triangular"]
    sol = solution("triangular", cname, 0.0)
    b = -2 * N11 * P / (m0 * math.pi)
    assert sol.ends[0] == 0 and abs(sol.ends[1] - b) < 1e-14 * b
    X = np.linspace(0.001 * b, 0.999 * b, 31)
    np.testing.assert_allclose(sol.pressure(X), -(m0 / N11) * np.sqrt((b - X) / X), rtol=1e-13)
    # parabolic: v' = X/R -> p = -(b/(N11 R)) sqrt((b-X)/X) (1/2 + X/b), int p = -3 pi b^2/(8 N11 R)
    R = GEOM["parabolic"]
    sol = solution("parabolic", cname, 0.0)
    b = math.sqrt(-8 * N11 * P * R / (3 * math.pi))
    assert sol.ends[0] == 0 and abs(sol.ends[1] - b) < 1e-14 * b
    X = np.linspace(0.001 * b, 0.999 * b, 31)
    np.testing.assert_allclose(sol.pressure(X),
                               -(b / (N11 * R)) * np.sqrt((b - X) / X) * (0.5 + X / b), rtol=1e-13)
    # sigma_XX at mu_f = 0 is N21 p inside and exactly 0 outside
    N21 = CONSTANTS[cname][2]
    np.testing.assert_allclose(sol.sigma_xx(X), N21 * sol.pressure(X), rtol=1e-15)
    assert np.all(sol.sigma_xx(np.array([-1.0, 2 * b, 50 * b])) == 0)


# ----------------------------------------------------------------------------------------------
# 6. SIF definitions as numerical limits of p
# ----------------------------------------------------------------------------------------------
def _limit(f, h):
    """Richardson: f(h) = F + c h + O(h^2)  ->  F ~ 2 f(h) - f(2h)."""
    return 2 * f(h) - f(2 * h)


@pytest.mark.parametrize("punch,cname,mu", [c for c in CASES if c[0] != "cylindrical"],
                         ids=[i for c, i in zip(CASES, CASE_IDS) if c[0] != "cylindrical"])
def test_sif_limits(punch, cname, mu):
    sol = solution(punch, cname, mu)
    xl, xr = sol.ends
    L = (xr - xl) / 2
    h = 1e-5 * L
    al, be = sol.alpha, sol.beta
    if punch == "flat":
        a = xr
        # (5.11) FI(a) = lim p(X) (a - X)^(-alpha) / 2^beta; (5.12) FI(-a) = lim p(X) (a + X)^(-beta) / 2^alpha
        right = _limit(lambda d: sol.pressure(a - d) * d ** (-al) / 2 ** be, h)
        left = _limit(lambda d: sol.pressure(-a + d) * d ** (-be) / 2 ** al, h)
        assert set(sol.sif) == {"right", "left"}
        checks = [(sol.sif["right"], right), (sol.sif["left"], left)]
        if mu == 0:   # (5.13)
            checks.append((sol.sif["right"], LOAD / (math.pi * math.sqrt(a))))
    else:
        # (5.23) / (5.33): lim_{X -> 0} X^alpha p(X)
        left = _limit(lambda d: d ** al * sol.pressure(d), h)
        assert set(sol.sif) == {"left"}
        checks = [(sol.sif["left"], left)]
        if mu == 0 and punch == "parabolic":   # (5.34)
            b, N11, R = xr, CONSTANTS[cname][0], GEOM["parabolic"]
            checks.append((sol.sif["left"], b ** 1.5 / (-2 * N11 * R)))
    for got, want in checks:
        err = abs(got - want) / abs(want)
        _record("SIF vs numerical limit (rel)", err)
        assert err < 1e-8


def test_cylindrical_has_no_sif():
    assert solution("cylindrical", "iso", 0.3).sif == {}


# ----------------------------------------------------------------------------------------------
# direction: mu_f -> -mu_f mirrors the symmetric punches
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("punch", ("flat", "cylindrical"))
@pytest.mark.parametrize("mu", (0.1, 0.5))
def test_mirror_symmetry(punch, mu):
    """X -> -X with mu_f -> -mu_f: p(X; -mu_f) = p(-X; mu_f), sigma_XX likewise (Hc is odd)."""
    s1, s2 = solution(punch, "ortho", mu), solution(punch, "ortho", -mu)
    assert abs(s1.ends[0] + s2.ends[1]) < 1e-14 and abs(s1.ends[1] + s2.ends[0]) < 1e-14
    L = s1.ends[1] - s1.ends[0]
    X = np.array([-20, -1.5, -0.8, -0.3, 0.1, 0.45, 0.9, 1.2, 7.0]) * L / 2
    X = X[(np.abs(X - s1.ends[0]) > 1e-9) & (np.abs(X - s1.ends[1]) > 1e-9)]
    np.testing.assert_allclose(s2.pressure(X), s1.pressure(-X), rtol=1e-13)
    np.testing.assert_allclose(s2.sigma_xx(X), s1.sigma_xx(-X), rtol=1e-12, atol=1e-15)


def test_signed_friction():
    assert cf.signed_friction(0.3, -1) == 0.3
    assert cf.signed_friction(0.3, +1) == -0.3
    for bad in ((-0.1, 1), (math.nan, 1), (0.3, 0), (0.3, 2), (0.3, True)):
        with pytest.raises(ValueError):
            cf.signed_friction(*bad)


@pytest.mark.parametrize("punch", PUNCHES)
def test_bad_input(punch):
    f = FUNCS[punch]
    N = CONSTANTS["iso"]
    for N11 in (0.0, 0.5, math.nan):
        with pytest.raises(ValueError):
            f(N11, *N[1:], 0.3, GEOM[punch], LOAD)
    with pytest.raises(ValueError):
        f(*N, math.inf, GEOM[punch], LOAD)
    for g in (0.0, -1.0, math.inf):
        with pytest.raises(ValueError):
            f(*N, 0.3, g, LOAD)
    for P in (0.0, -1.0, math.nan):
        with pytest.raises(ValueError):
            f(*N, 0.3, GEOM[punch], P)


# ----------------------------------------------------------------------------------------------
# the paper's printed formulas that are wrong (errata 1 and 3 in the module docstring)
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("mu", (0.1, 0.3, 0.5))
def test_paper_exponent_tables_wrong_for_negative_xi(mu):
    """(4.18) with (5.3), (5.16), (5.38): for xi < 0 the printed rows solve cot(pi alpha) = +xi
    and leave the admissible range; the xi > 0 rows agree with the module."""
    N11, N12, _, _ = CONSTANTS["iso"]
    for sign in (1, -1):
        m = sign * mu
        xi = m * N12 / N11
        eps = math.atan(1 / xi)
        if xi < 0:
            printed = {"flat": (eps / math.pi - 1, -eps / math.pi),           # (5.3)
                       "triangular": (eps / math.pi, -eps / math.pi),         # (5.16)
                       "cylindrical": (eps / math.pi, 1 - eps / math.pi)}     # (5.38)
        else:
            printed = {"flat": (-eps / math.pi, eps / math.pi - 1),
                       "triangular": (1 - eps / math.pi, -1 + eps / math.pi),
                       "cylindrical": (1 - eps / math.pi, eps / math.pi)}
        for punch, (pa, pb) in printed.items():
            sol = solution(punch, "iso", m)
            if xi < 0:
                assert abs(1 / math.tan(math.pi * pa) - xi) < 1e-12      # solves cot = +xi
                assert abs(pa - sol.alpha) > 0.9                          # far from the truth
                # out of range, or the wrong bounded/singular type at an end
                if punch == "flat":
                    assert pa < -1                       # (1-s)^pa not integrable
                else:
                    assert pa < 0                        # singular where geometry demands bounded
                if mu == 0.3:
                    print(f"[closed-form] paper exponents {punch} mu_f={m}: printed alpha={pa:.4f}"
                          f" beta={pb:.4f}; correct alpha={sol.alpha:.4f} beta={sol.beta:.4f}")
            else:
                assert abs(pa - sol.alpha) < 1e-14 and abs(pb - sol.beta) < 1e-14


@pytest.mark.parametrize("cname", tuple(CONSTANTS))
@pytest.mark.parametrize("mu", (0.3, -0.3, 0.5))
def test_paper_5_45_inside_row_is_wrong(cname, mu):
    """(5.44)-(5.45) as printed (no cos(pi alpha) inside) vs quadrature; the corrected row agrees."""
    sol = solution("cylindrical", cname, mu)
    r = ref("cylindrical", cname, mu)
    N11, _, N21, N22 = CONSTANTS[cname]
    R = GEOM["cylindrical"]
    a, b = -sol.ends[0], sol.ends[1]
    al, be = sol.alpha, sol.beta
    pref = math.sin(math.pi * al) / (-N11 * R)

    def paper(X, with_cos):
        base = 2 * (b - X) ** al * (X + a) ** be * (math.cos(math.pi * al) if with_cos else 1.0)
        ups = math.pi / math.sin(math.pi * al) * (base - 2 * X + b - a + (al - be) * (b + a))
        return pref * (N21 * (b - X) ** al * (X + a) ** be + N22 * mu / (2 * math.pi) * ups)

    worst_printed = worst_fixed = 0.0
    refs = []
    with mp.workdps(DPS):
        for s in S_INSIDE:
            refs.append((float(r.X(mpf(s))), float(r.sigma(mpf(s)))))
    scale = max(abs(v) for _, v in refs)
    for X, v in refs:
        worst_printed = max(worst_printed, abs(paper(X, False) - v) / scale)
        worst_fixed = max(worst_fixed, abs(paper(X, True) - v) / scale)
    print(f"[closed-form] paper 5.44 inside row, {cname} mu_f={mu}: printed error "
          f"{worst_printed:.3f} of max|sigma_xx|, corrected {worst_fixed:.1e}")
    assert worst_printed > 0.05
    assert worst_fixed < 1e-12


def test_paper_load_relations_hold():
    """(5.22), (5.32), (5.46)-(5.47) hold as printed once alpha is corrected."""
    N11, N12, N21, N22 = CONSTANTS["ortho"]
    for mu in MUS:
        t = solution("triangular", "ortho", mu)
        assert abs(t.ends[1] - (-N11 * LOAD / (GEOM["triangular"] * math.pi * t.alpha))) < 1e-14
        p = solution("parabolic", "ortho", mu)
        R = GEOM["parabolic"]
        assert abs(p.ends[1] - math.sqrt(-2 * N11 * LOAD * R / (math.pi * p.alpha * (1 + p.alpha)))) < 1e-14
        c = solution("cylindrical", "ortho", mu)
        a, b = -c.ends[0], c.ends[1]
        assert abs(LOAD - math.pi * c.alpha * c.beta / (-2 * N11 * R) * (a + b) ** 2) < 1e-13
        assert abs(b - c.beta / c.alpha * a) < 1e-14

