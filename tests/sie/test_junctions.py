"""sie.solve_junctions: touching intervals whose coefficients (a, b) jump at a junction.

References independent of the solver:
- the junction exponent against the local analysis done by mpmath (the principal value of
  the two-sided power on the whole line, no cot / sin formula);
- the index's integer sum against sie.sie_exponents' outer exponents;
- manufactured solutions psi = W (sigma_i abs(t - e)^gamma g(t) + r(t)) (the junction's
  amplitude ratio sigma_2 / sigma_1 from the local analysis, W the outer ends' weight, g and
  r smooth across the junction), f from psi by mpmath's principal value over the whole of
  L at Chebyshev points of each interval, its Chebyshev coefficients checked to decay (f is
  smooth on each closed interval), the interpolant as f.  The mpmath values (f at the
  Chebyshev points, psi at the test points, the integrals) are stored in
  tests/reference/junction_refs.json, keyed by the case and the point (they take ~40 s);
  SIE_TEST_RECOMPUTE_REFS=1 computes them again and rewrites the file;
- self-convergence for a generic f, and the limit of a vanishing jump against sie.solve on
  the one interval.
"""
from __future__ import annotations

import math
import warnings

import mpmath as mp
import numpy as np
import pytest
from _stored import StoredReferences
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.polynomial import chebyshev as cheb

import sie
from sie.junctions import _cross_images, junction_ratio


_REFS = StoredReferences("junction_refs.json")
_stored = _REFS.real



# ---------------------------------------------------------------------------------------
# the local analysis
# ---------------------------------------------------------------------------------------
def _local_images(a, b, gamma, ratio):
    """a_i psi(x) + (b_i/pi) PV int_R psi(t)/(t - x) dt at x = -1 and x = 1 for the
    two-sided power psi = (-t)^gamma (t < 0), ratio t^gamma (t > 0), -1 < gamma < 0, by
    mpmath (the principal value at x by the symmetric difference)."""
    g = mp.mpf(gamma)

    def psi(t):
        return (-t) ** g if t < 0 else ratio * t ** g

    out = []
    half = mp.mpf(1) / 2
    for i, x in ((0, mp.mpf(-1)), (1, mp.mpf(1))):
        pv = mp.quad(lambda u: (psi(x + u) - psi(x - u)) / u, [0, half])
        edges = sorted([mp.mpf(-2), mp.mpf(0), mp.mpf(2), x - half, x + half])
        k0, k1 = 1 / (1 + g), -1 / g
        for lo, hi in zip(edges[:-1], edges[1:]):
            if lo == x - half:                     # the window around x is done above
                continue
            if lo == 0 or hi == 0:                 # t = end +- h y^k0: abs(t)^gamma dt ~ dy
                h = hi - lo
                sgn = 1 if lo == 0 else -1
                pv += mp.quad(lambda y: psi(sgn * h * y**k0) / (sgn * h * y**k0 - x)
                              * h * k0 * y**(k0 - 1), [0, 1])
            else:
                pv += mp.quad(lambda t: psi(t) / (t - x), [lo, hi])
        # the tails abs(t) > 2: t = +-1/u, u = y^k1 / 2, which take the decay t^(gamma - 1)
        # out of the integrand
        for sgn in (1, -1):
            def tail(y, sgn=sgn):
                u = y**k1 / 2
                return psi(sgn / u) / (sgn / u - x) / u**2 * k1 * y**(k1 - 1) / 2
            pv += mp.quad(tail, [0, 1])
        out.append(a[i] * psi(x) + b[i] * pv / mp.pi)
    return out


def _check_local(a1, b1, a2, b2):
    gamma = sie.junction_exponent(a1, b1, a2, b2) - 1.0       # in (-1, 0): convergent
    ratio = junction_ratio(a1, b1, a2, b2, gamma)
    left, right = _local_images((a1, a2), (b1, b2), gamma, ratio)
    scale = abs(a1) + abs(b1) + abs(a2) + abs(b2)
    return abs(left) / scale, abs(right) / scale


@pytest.mark.parametrize("coef", [(0.0, 1.0, 1.0, 1.0), (1.0, 1.0, 0.0, 1.0),
                                  (1.0, -2.0, 0.5, 3.0), (-0.7, 0.4, 2.0, 1.5)])
def test_junction_exponent_zeroes_the_local_images(coef):
    """With gamma = gamma0 - 1 (the integrals converge at infinity) and the amplitude ratio
    of junction_ratio, the equation's image of the two-sided power vanishes on both sides
    (mpmath); a slightly different exponent leaves it nonzero."""
    mp.mp.dps = 20
    left, right = _check_local(*coef)
    assert left < 1e-12 and right < 1e-12
    a1, b1, a2, b2 = coef
    gamma = sie.junction_exponent(*coef) - 1.0 + 0.02
    ratio = junction_ratio(a1, b1, a2, b2, gamma)
    off = _local_images((a1, a2), (b1, b2), gamma, ratio)
    assert max(abs(v) for v in off) > 1e-3


def test_junction_exponent_example_and_range():
    assert sie.junction_exponent(0.0, 1.0, 1.0, 1.0) == pytest.approx(0.75, abs=1e-15)
    rng = np.random.default_rng(7)
    for _ in range(200):
        a1, b1, a2, b2 = rng.normal(size=4)
        g = sie.junction_exponent(a1, b1, a2, b2)
        assert 0.0 < g < 1.0
        cot = -(a1 * a2 + b1 * b2) / (a2 * b1 - a1 * b2)
        assert math.cos(math.pi * g) / math.sin(math.pi * g) == pytest.approx(cot, rel=1e-9,
                                                                             abs=1e-12)


@pytest.mark.parametrize("delta, from_left", [(1e-10, True), (1e-4, False), (3.0, True)])
def test_cross_term_next_to_the_junction(delta, from_left):
    """(1/pi) int w P_k / (v - x) dv at x a distance delta beyond an end of [-1, 1] (the
    coupling of a collocation point to the neighbouring interval) against mpmath, the
    distance (1 + v) + delta (or (1 - v) + delta) formed from the pinned distance."""
    mp.mp.dps = 20
    alpha, beta, n = 0.3, -0.6, 12
    e = sie.sie_exponents(1.0, 1.0, "bounded", "bounded")
    e = type(e)(alpha, beta, 0, e.alpha0, e.cot, e.sin, 1 + alpha, 1 + beta, 1 - alpha,
                1 - beta)
    got = _cross_images(n, e, np.array([delta]), from_left, 40)[0]
    one, dlt = mp.mpf(1), mp.mpf(delta)

    def integrand(k):
        def F(v, pin=None):
            dl, dr = 1 + v, 1 - v
            if pin is not None:
                dl, dr = (pin[2], 2 - pin[2]) if pin[0] == -one else (2 - pin[2], pin[2])
            if dl <= 0 or dr <= 0:
                return mp.mpf(0)
            denom = (dl + dlt) if from_left else -(dr + dlt)
            return dr ** alpha * dl ** beta * mp.jacobi(k, alpha, beta, v) / denom
        return F

    # the reference split toward the near end on the scale of delta too
    near = -one + 4 * dlt if from_left else one - 4 * dlt
    cuts = sorted({-one, one, mp.mpf(0)} | ({near} if delta < 0.25 else set()))
    for k in (0, 5, 11):
        ref = sum(_segment(integrand(k), p0, p1, {-one: beta, one: alpha})
                  for p0, p1 in zip(cuts[:-1], cuts[1:])) / mp.pi
        assert abs(got[k] - float(ref)) < 1e-13 * max(1.0, abs(float(ref))), (k, got[k], ref)


# ---------------------------------------------------------------------------------------
# the index
# ---------------------------------------------------------------------------------------
_coef = st.floats(-3.0, 3.0).filter(lambda v: abs(v) > 0.05)
_choice = st.sampled_from(["bounded", "singular"])


@settings(max_examples=60, deadline=None)
@given(a1=_coef, b1=_coef, a2=_coef, b2=_coef, left=_choice, mid=_choice, right=_choice)
def test_exponent_sum_is_an_integer(a1, b1, a2, b2, left, mid, right):
    """beta_c + gamma + alpha_d is an integer in [-2, 2] for every choice (the outer
    exponents by sie.sie_exponents); solve_junctions' kappa is minus it."""
    if abs(a1 * b2 - a2 * b1) < 1e-3 * (abs(a1 * b2) + abs(a2 * b1)):
        return                                             # nearly no jump
    beta_c = sie.sie_exponents(a1, b1, left, "bounded").beta
    alpha_d = sie.sie_exponents(a2, b2, "bounded", right).alpha
    g0 = sie.junction_exponent(a1, b1, a2, b2)
    gamma = g0 if mid == "bounded" else g0 - 1.0
    total = beta_c + gamma + alpha_d
    kappa = -round(total)
    assert abs(total + kappa) < 1e-12 and -2 <= kappa <= 2
    tot = {1: 1.0, 2: [0.5, 0.5]}.get(kappa)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.SIEWarning)
        sol = sie.solve_junctions(np.cos, [a1, a2], [b1, b2], [(-1.0, 0.2), (0.2, 1.0)], n=4,
                                  left=left, right=right, junctions=[mid], total=tot,
                                  regular=0, check_residual=False)
    assert sol.kappa == kappa and sol.gamma[0] == pytest.approx(gamma, abs=4e-16)
    assert sum(p.exp.kappa for p in sol.pieces) == kappa


# ---------------------------------------------------------------------------------------
# manufactured solutions
# ---------------------------------------------------------------------------------------
_M = 24          # Chebyshev points per interval for f


def _segment(F, p0, p1, singular):
    """int_{p0}^{p1} F(t) by mpmath, halved; a half that ends at a point of ``singular``
    (point: exponent e there) with t = point +- h y^k, k = 1/(1 + e), which takes the power
    out of the integrand (abs(t - point)^e dt ~ dy; tanh-sinh leaves ~1e-6 of a bare
    power -3/4), F called as F(t, (point, +-1, h y^k)) there."""
    mid = (p0 + p1) / 2
    total = mp.mpf(0)
    for lo, hi in ((p0, mid), (mid, p1)):
        end, sgn = (lo, 1) if lo in singular else ((hi, -1) if hi in singular else (None, 0))
        if end is None:
            total += mp.quad(F, [lo, hi])
            continue
        k, h = 1 / (1 + mp.mpf(singular[end])), hi - lo
        total += mp.quad(lambda y: F(end + sgn * h * y**k, (end, sgn, h * y**k))
                         * h * k * y**(k - 1), [0, 1])
    return total


def _manufactured(a, b, ends, left, mid, right, g, r, label):
    """psi = W (sigma_i prod_j abs(t - e_j)^gamma_j g(t) + r(t)) on the intervals between
    ``ends`` = (c, e_1, ..., d) (``mid``: one choice or one per junction; sigma_1 = 1,
    sigma_(i+1) = sigma_i junction_ratio at e_i), and f from it (an interpolant of the mpmath
    values on each interval, after checking that they are smooth).  ``label`` names g and r
    in the keys of the stored values."""
    case = repr((a, b, ends, left, mid, right, label))
    J = len(ends) - 1
    mids = [mid] * (J - 1) if isinstance(mid, str) else list(mid)
    pts = [mp.mpf(v) for v in ends]
    c, d, es = pts[0], pts[-1], pts[1:-1]
    beta_c = sie.sie_exponents(a[0], b[0], left, "bounded").beta
    alpha_d = sie.sie_exponents(a[-1], b[-1], "bounded", right).alpha
    gammas, sigmas = [], [1.0]
    for i, m in enumerate(mids):
        g0 = sie.junction_exponent(a[i], b[i], a[i + 1], b[i + 1])
        gammas.append(g0 if m == "bounded" else g0 - 1.0)
        sigmas.append(sigmas[-1] * junction_ratio(a[i], b[i], a[i + 1], b[i + 1], gammas[-1]))
    singular = dict(zip(pts, [beta_c] + gammas + [alpha_d]))

    def psi(t, pin=None):
        """psi at t; ``pin`` = (point, side, distance): t lies at that distance from one of
        the ends on that side, and the factor of that point is taken from the distance (t
        itself rounds to the point within ~1e-20 of it, where the substituted integrand is
        still finite)."""
        dist = {p: abs(t - p) for p in es}
        dist[c], dist[d] = t - c, d - t
        piece = sum(1 for p in es if t > p)
        if pin is not None:
            dist[pin[0]] = pin[2]
            if pin[0] in es:
                piece = es.index(pin[0]) + (1 if pin[1] > 0 else 0)
        if min(dist.values()) <= 0:
            return mp.mpf(0)
        power = sigmas[piece] * g(t)
        for p, gm in zip(es, gammas):
            power *= dist[p] ** gm
        return dist[c] ** beta_c * dist[d] ** alpha_d * (power + r(t))

    def f_mp(x):
        rad = min(abs(x - p) for p in pts) / 2
        pv = mp.quad(lambda u: (psi(x + u) - psi(x - u)) / u, [0, rad])
        edges = sorted(set(pts) | {x - rad, x + rad})
        for p0, p1 in zip(edges[:-1], edges[1:]):
            if not (p0 == x - rad and p1 == x + rad):
                pv += _segment(lambda t, pin=None: psi(t, pin) / (t - x), p0, p1,
                               singular)
        i = sum(1 for p in es if x > p)
        return a[i] * psi(x) + b[i] * pv / mp.pi

    fits = []
    xs = np.cos(np.pi * (np.arange(_M) + 0.5) / _M)
    for lo, hi in zip(ends[:-1], ends[1:]):
        vals = [_stored(f"{case} f {lo!r} {hi!r} {k}",
                        lambda u=u: f_mp(mp.mpf(lo) + (mp.mpf(hi) - lo) * (mp.mpf(float(u)) + 1)
                                         / 2))
                for k, u in enumerate(xs)]
        co = cheb.chebfit(xs, vals, _M - 1)
        # f smooth on the closed interval: the tail of its Chebyshev series is at rounding
        assert np.max(np.abs(co[-6:])) < 1e-12 * max(1.0, np.max(np.abs(co)))
        fits.append((lo, hi, co))

    def f(s):
        s = np.asarray(s, dtype=float)
        out = np.empty(s.shape)
        for lo, hi, co in fits:
            sel = (s >= lo) & (s <= hi)
            out[sel] = cheb.chebval((2 * s[sel] - lo - hi) / (hi - lo), co)
        return out

    def psi_np(s):
        return np.array([_stored(f"{case} psi {float(v)!r}", lambda v=v: psi(mp.mpf(float(v))))
                         for v in s])

    def integral(lo, hi):
        """int_lo^hi psi, lo < hi among the ends."""
        sel = [p for p in pts if mp.mpf(lo) <= p <= mp.mpf(hi)]
        return _stored(f"{case} int {lo!r} {hi!r}", lambda: sum(
            _segment(psi, p0, p1, singular) for p0, p1 in zip(sel[:-1], sel[1:])))

    return f, psi_np, integral, (gammas[0] if len(gammas) == 1 else tuple(gammas))


_ENDS = (-1.0, 0.5, 2.0)
_S = np.array([-0.95, -0.6, 0.0, 0.4, 0.49, 0.51, 0.6, 1.2, 1.9])


@pytest.fixture(scope="module")
def kappa0_case():
    """a = (0, 1), b = (1, 2): gamma0 = 0.852416; left, right singular, junction bounded:
    index 0; g = exp(t/2), r = cos(t) (a regular part: psi(e) = r(e) W(e) != 0)."""
    mp.mp.dps = 20
    return _manufactured((0.0, 1.0), (1.0, 2.0), _ENDS, "singular", "bounded", "singular",
                         lambda t: mp.exp(t / 2), lambda t: mp.cos(t), "exp(t/2), cos(t)")


def test_manufactured_index_0_with_a_regular_part(kappa0_case):
    f, psi_np, _, gamma = kappa0_case
    exact = psi_np(_S)
    errs = []
    for n in (8, 16, 24):
        sol = sie.solve_junctions(f, [0.0, 1.0], [1.0, 2.0], [_ENDS[:2], _ENDS[1:]], n=n,
                                  left="singular", right="singular", junctions=["bounded"],
                                  check_residual=False)
        errs.append(float(np.max(np.abs(sol(_S) - exact))))
    assert sol.gamma == (gamma,) and sol.kappa == 0
    assert abs(gamma - 0.8524163823495667) < 1e-15
    assert errs[1] < errs[0] and errs[-1] < 1e-10, errs
    # psi at the junction: W(e) r(e) = (e - c)^(-1/2) (d - e)^alpha_d cos(e) (the power's
    # part vanishes there)
    assert sol(np.array([0.5]))[0] == pytest.approx(
        1.5 ** -0.5 * 1.5 ** sol.alpha[1] * math.cos(0.5), abs=1e-9)


def test_without_the_regular_part_the_error_stalls(kappa0_case):
    """regular=0 (the pieces' series alone) cannot carry psi(e) != 0 next to a bounded
    junction: the error stays large (the documented algebraic convergence)."""
    f, psi_np, _, _ = kappa0_case
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.ResidualWarning)
        sol = sie.solve_junctions(f, [0.0, 1.0], [1.0, 2.0], [_ENDS[:2], _ENDS[1:]], n=24,
                                  left="singular", right="singular", junctions=["bounded"],
                                  regular=0)
    assert np.max(np.abs(sol(_S) - psi_np(_S))) > 1e-3


def test_manufactured_power_part_only_plain_basis():
    """r = 0: psi is the basis' own kind (w_i times a smooth function on each piece), and
    the plain collocation (regular=0) converges geometrically; a = (1, 0), b = (1, 1): every
    end singular, index 2, the two integrals over the intervals given."""
    mp.mp.dps = 20
    a, b = (1.0, 0.0), (1.0, 1.0)
    f, psi_np, integral, gamma = _manufactured(a, b, _ENDS, "singular", "singular",
                                               "singular", lambda t: 1 + t / 3 - t**2 / 5,
                                               lambda t: 0, "1 + t/3 - t^2/5, 0")
    tot = [integral(_ENDS[0], _ENDS[1]), integral(_ENDS[1], _ENDS[2])]
    exact = psi_np(_S)
    errs = []
    for n in (6, 12, 18):
        sol = sie.solve_junctions(f, a, b, [_ENDS[:2], _ENDS[1:]], n=n, left="singular",
                                  right="singular", junctions=["singular"], total=tot,
                                  regular=0, check_residual=False)
        errs.append(float(np.max(np.abs(sol(_S) - exact))))
    assert sol.kappa == 2 and gamma == pytest.approx(-0.75, abs=1e-15)
    assert errs[0] > errs[1] > errs[2] and errs[2] < 1e-10, errs
    assert sol.integral(0) == pytest.approx(tot[0], abs=1e-11)
    assert sol.integral() == pytest.approx(sum(tot), abs=1e-11)


def test_manufactured_index_1_and_minus_1():
    """a = (0, 1), b = (1, 1) (the brief's check: gamma0 = 3/4): all singular, index 1
    with int_L psi; all bounded, index -2, least squares with a consistency at rounding."""
    mp.mp.dps = 20
    a, b = (0.0, 1.0), (1.0, 1.0)
    for left, mid, right, kappa in (("singular", "singular", "singular", 1),
                                    ("bounded", "bounded", "bounded", -2)):
        f, psi_np, integral, gamma = _manufactured(a, b, _ENDS, left, mid, right,
                                                   lambda t: mp.exp(-t / 3),
                                                   lambda t: 1 + t / 4, "exp(-t/3), 1 + t/4")
        tot = integral(_ENDS[0], _ENDS[2]) if kappa == 1 else None
        with warnings.catch_warnings():
            warnings.simplefilter("error", sie.InconsistentEquationWarning)
            sol = sie.solve_junctions(f, a, b, [_ENDS[:2], _ENDS[1:]], n=20, left=left,
                                      right=right, junctions=[mid], total=tot)
        assert sol.kappa == kappa
        assert np.max(np.abs(sol(_S) - psi_np(_S))) < 1e-9
        if kappa == 1:
            assert sol.integral() == pytest.approx(tot, abs=1e-11)
        else:
            assert sol.consistency < 1e-11


def test_manufactured_two_junctions():
    """Three intervals, a = (0, 1, -1/2), b = (1, 2, 1), junctions bounded and singular
    (gamma = 0.852416, -0.704833), index 1: a power part and a regular part, recovered to
    1e-8 (3e-10 from n = 16 on: the reference's plateau)."""
    mp.mp.dps = 20
    a, b = (0.0, 1.0, -0.5), (1.0, 2.0, 1.0)
    ends = (-1.0, -0.2, 0.7, 2.0)
    f, psi_np, integral, gammas = _manufactured(a, b, ends, "singular",
                                                ["bounded", "singular"], "singular",
                                                lambda t: 1 + t / 5, lambda t: mp.cos(t),
                                                "1 + t/5, cos(t)")
    tot = integral(ends[0], ends[-1])
    s = np.array([-0.9, -0.3, -0.21, -0.19, 0.0, 0.69, 0.71, 1.5])
    exact = psi_np(s)
    errs = []
    for n in (8, 16, 32):
        sol = sie.solve_junctions(f, a, b, list(zip(ends[:-1], ends[1:])), n=n,
                                  left="singular", right="singular",
                                  junctions=["bounded", "singular"], total=tot,
                                  check_residual=False)
        errs.append(float(np.max(np.abs(sol(s) - exact))))
    assert sol.kappa == 1 and sol.gamma == pytest.approx(gammas, abs=1e-15)
    # 2e-7, 3e-10, 3e-10: geometric, then the reference's plateau (f's interpolant from
    # mpmath values; the self-convergence of a generic f reaches 1e-14)
    assert errs[1] < 1e-2 * errs[0] and errs[-1] < 1e-8, errs
    assert sol.integral() == pytest.approx(tot, abs=1e-10)
    # over one interval: the pieces' moments plus the regular part's share of it
    assert sol.integral(1) == pytest.approx(integral(ends[1], ends[2]), abs=1e-9)


# ---------------------------------------------------------------------------------------
# generic f: self-convergence; a vanishing jump
# ---------------------------------------------------------------------------------------
def test_generic_f_self_convergence():
    """f = cos on (-1, 0.5) U (0.5, 2), a = (0, 1), b = (1, 2), index 0: n = 8, 16, 32, 64
    settle geometrically to 1e-11 (the regular part carries psi(e))."""
    s = np.linspace(-0.95, 1.95, 30)
    vals = []
    for n in (8, 16, 32, 64):
        sol = sie.solve_junctions(np.cos, [0.0, 1.0], [1.0, 2.0], [_ENDS[:2], _ENDS[1:]],
                                  n=n, left="singular", right="singular",
                                  junctions=["bounded"])
        vals.append(sol(s))
    d = [float(np.max(np.abs(v - w))) for v, w in zip(vals[1:], vals[:-1])]
    # 6e-8, 1e-13, 2e-14: geometric to rounding (the oversampled least squares of the
    # regular part's frame)
    assert d[1] < 1e-3 * d[0] and max(d[1:]) < 1e-11, d


@pytest.mark.parametrize("f, f_left, f_right", [
    (np.cos, math.cos(0.5), math.cos(0.5)),
    (lambda s: np.where(s < 0.5, 1.0 + s, 2.0 - s * s), 1.5, 1.75)])
def test_value_at_a_bounded_junction_is_the_regular_part(f, f_left, f_right):
    """psi(e) = (b_1 f(e+) - b_2 f(e-)) / (a_2 b_1 - a_1 b_2) at a bounded junction (the
    order (x - e)^0 of the equation on the two sides; docs, Theory: junctions), here
    0.2193956 and 0.25; a = (1, -1/2), b = (1, 3/2): gamma = 0.352416, index 0."""
    a, b = [1.0, -0.5], [1.0, 1.5]
    expected = (b[0] * f_right - b[1] * f_left) / (a[1] * b[0] - a[0] * b[1])
    for n, tol in ((16, 1e-10), (32, 1e-12)):
        sol = sie.solve_junctions(f, a, b, [_ENDS[:2], _ENDS[1:]], n=n, left="singular",
                                  right="bounded", junctions=["bounded"])
        assert sol.kappa == 0 and sol.gamma[0] == pytest.approx(0.35241638234956674)
        assert sol(np.array([0.5]))[0] == pytest.approx(expected, abs=tol)


def test_vanishing_jump_tends_to_the_one_interval_solve():
    """(a, b) = (1, 1) on [-1, 0.2], (1 + delta, 1) on [0.2, 1]: with the junction choice
    whose exponent tends to 0 the solution tends to sie.solve's on [-1, 1]."""
    f = lambda s: np.exp(s / 2)                                    # noqa: E731
    ref_sol = sie.solve(f, a=1.0, b=1.0, n=40, left="singular", right="bounded")
    s = np.array([-0.8, -0.3, 0.0, 0.15, 0.25, 0.5, 0.8])
    ref = ref_sol(s)
    errs = []
    for delta in (1e-1, 1e-2, 1e-3):
        g0 = sie.junction_exponent(1.0, 1.0, 1.0 + delta, 1.0)
        mid = "bounded" if g0 < 0.5 else "singular"
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", sie.ResidualWarning)
            sol = sie.solve_junctions(f, [1.0, 1.0 + delta], [1.0, 1.0],
                                      [(-1.0, 0.2), (0.2, 1.0)], n=32, left="singular",
                                      right="bounded", junctions=[mid])
        assert sol.kappa == 0 and abs(sol.gamma[0]) < delta
        errs.append(float(np.max(np.abs(sol(s) - ref))))
    # 7.8e-2, 8.2e-3, 8.2e-4: O(delta), the change the jump itself makes
    assert errs[0] > 5 * errs[1] > 25 * errs[2] and errs[2] < 2e-3, errs


# ---------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------
_GOOD = dict(n=4, left="singular", right="singular", junctions=["bounded"])
_IV = [(-1.0, 0.0), (0.0, 1.0)]


@pytest.mark.parametrize("intervals", [[(-1.0, 0.0), (0.1, 1.0)], [(-1.0, 0.1), (0.0, 1.0)],
                                       [(-1.0, 1.0)], [(0.0, -1.0), (-1.0, 1.0)],
                                       [(-1.0, 0.0), (0.0, float("inf"))], 3.0])
def test_bad_intervals(intervals):
    with pytest.raises(sie.InvalidIntervalError):
        sie.solve_junctions(np.cos, [0.0, 1.0], [1.0, 1.0], intervals, **_GOOD)


def test_bad_lengths():
    with pytest.raises(sie.PerIntervalArgumentError, match="a must hold 2"):
        sie.solve_junctions(np.cos, [0.0, 1.0, 2.0], [1.0, 1.0], _IV, **_GOOD)
    with pytest.raises(sie.PerIntervalArgumentError, match="b must"):
        sie.solve_junctions(np.cos, [0.0, 1.0], 1.0, _IV, **_GOOD)
    with pytest.raises(sie.PerIntervalArgumentError, match="junctions"):
        sie.solve_junctions(np.cos, [0.0, 1.0], [1.0, 1.0], _IV, n=4, left="singular",
                            right="singular", junctions=["bounded", "bounded"])
    with pytest.raises(sie.PerIntervalArgumentError, match="n must"):
        sie.solve_junctions(np.cos, [0.0, 1.0], [1.0, 1.0], _IV, n=[4, 4, 4],
                            left="singular", right="singular", junctions=["bounded"])


def test_proportional_coefficients():
    with pytest.raises(sie.InvalidCoefficientError, match="nothing jumps"):
        sie.solve_junctions(np.cos, [1.0, 2.0], [1.0, 2.0], _IV, **_GOOD)
    with pytest.raises(sie.InvalidCoefficientError, match="nothing jumps"):
        sie.junction_exponent(0.0, 1.0, 0.0, -3.0)
    with pytest.raises(sie.InvalidCoefficientError):
        sie.solve_junctions(np.cos, [0.0, 1.0], [1.0, 0.0], _IV, **_GOOD)


@pytest.mark.parametrize("kw", [dict(left="free"), dict(right=0.3), dict(junctions=["open"]),
                                dict(junctions="bounded")])
def test_bad_choices(kw):
    args = dict(_GOOD, **kw)
    with pytest.raises(sie.InvalidEndConditionError):
        sie.solve_junctions(np.cos, [0.0, 1.0], [1.0, 1.0], _IV, **args)


def test_index_without_side_conditions():
    """Three intervals, z = a + i b = 1 + i, i, 1 + 3i (t = 1/4, 1/2, 0.398: one wrap), every
    end singular: index 3 - 1 = 2 < J, for which no side conditions are defined."""
    with pytest.raises(sie.UnsupportedEquationError, match="index 2 on 3 intervals"):
        sie.solve_junctions(np.cos, [1.0, 0.0, 1.0], [1.0, 1.0, 3.0],
                            [(-1.0, 0.0), (0.0, 1.0), (1.0, 2.0)], n=4, left="singular",
                            right="singular", junctions=["singular", "singular"], total=1.0)


def test_side_condition_errors():
    with pytest.raises(sie.SideConditionError, match="required"):
        sie.solve_junctions(np.cos, [0.0, 1.0], [1.0, 1.0], _IV, n=4, left="singular",
                            right="singular", junctions=["singular"])
    with pytest.raises(sie.SideConditionError, match="must not"):
        sie.solve_junctions(np.cos, [0.0, 1.0], [1.0, 1.0], _IV, total=1.0, **_GOOD)


# ---------------------------------------------------------------------------------------
# through sie.solve: intervals that touch
# ---------------------------------------------------------------------------------------
def test_solve_on_touching_intervals_is_solve_junctions():
    """sie.solve with intervals that touch and per-interval a, b: the junction's choice is
    right[i] = left[i + 1]; the same numbers as sie.solve_junctions."""
    ivs = [(-1.0, 0.5), (0.5, 2.0)]
    ref = sie.solve_junctions(np.cos, [0.0, 1.0], [1.0, 2.0], ivs, n=16, left="singular",
                              right="singular", junctions=["bounded"])
    got = sie.solve(np.cos, a=[0.0, 1.0], b=[1.0, 2.0], n=16, left=["singular", "bounded"],
                    right=["bounded", "singular"], intervals=ivs)
    s = np.array([-0.5, 0.3, 0.6, 1.5])
    assert np.array_equal(got(s), ref(s)) and got.gamma == ref.gamma


@pytest.mark.parametrize("kw,error,match", [
    (dict(left="singular", right=["bounded", "singular"]), sie.InvalidEndConditionError,
     r"junction x = 0.5 .* right\[0\] = 'bounded', left\[1\] = 'singular'"),
    (dict(a=0.0, b=1.0), sie.InvalidCoefficientError, "nothing jumps"),
    (dict(intervals=[(-1.0, 0.5), (0.5, 2.0), (3.0, 4.0)], a=[0.0, 1.0, 0.0],
          b=[1.0, 2.0, 1.0]), sie.UnsupportedEquationError, "gaps between them"),
    (dict(kernel=lambda s, t: s * t), sie.UnsupportedEquationError, "no kernel"),
    (dict(n="auto"), sie.UnsupportedEquationError, 'no n="auto"'),
])
def test_solve_on_touching_intervals_refuses(kw, error, match):
    args = dict(a=[0.0, 1.0], b=[1.0, 2.0], n=8, left="singular", right="singular",
                intervals=[(-1.0, 0.5), (0.5, 2.0)], total=0.0)
    args.update(kw)
    with pytest.raises(error, match=match):
        sie.solve(np.cos, **args)
