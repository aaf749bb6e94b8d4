"""Validation of the independent influence-matrix solver ``tests/reference/bem_reference.py``.

The BEM uses neither ``sie`` nor ``contact``'s solver; here it is checked against

* closed forms derived in ``bem_reference`` (cylinder; W face H = A (X^2 - 1)^2 with two
  zones, one zone and the merge load P* |N11| = 2 pi A, frictionless; any polynomial face,
  one zone, with friction, and the merge load of a cubic slope),
* the library's single-zone numeric solution (cylinder and W face, with friction, both
  directions),

and its own convergence orders are pinned: on the uniform grid, edges to ~0.03 h (first
order, small erratic constant) and interior pressure O(h^2); with continuous edges, edges
O(n^-2) before and ~O(n^-4) after Richardson extrapolation.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy.integrate import quad

import contact

import bem_reference as B


ISO = contact.Isotropic(1.0, 0.25)
ISO_N11 = contact.surface_constants(ISO, 0.0).N11          # -(1 - nu)/G = -1.875
ZHOU = contact.zhou2014()
ZK = contact.surface_constants(ZHOU, 0.6)
W_SLOPE = [0.0, -4 * B.W_AMPLITUDE, 0.0, 4 * B.W_AMPLITUDE]   # H' = 4A (X^3 - X)


def _cyl(R):
    return lambda X: np.asarray(X, dtype=float) ** 2 / (2.0 * R)


# --------------------------------------------------------------------------
# kernel and signs
# --------------------------------------------------------------------------
def test_panel_log_integrals_closed_form():
    """The influence matrix entries equal direct quadratures of log|x_i - t| (+ friction)."""
    m, h, N11, a = 7, 0.3, -1.3, 0.07
    A = B.influence_matrix(m, h, N11, a)
    x = (np.arange(m) + 0.5) * h
    for i in (0, 3, 6):
        for j in (0, 3, 5, 6):
            t0, t1 = j * h, (j + 1) * h
            pts = [x[i]] if t0 < x[i] < t1 else None
            lg = quad(lambda t: math.log(abs(x[i] - t)), t0, t1, points=pts, limit=200)[0]
            fr = h if j < i else (0.5 * h if j == i else 0.0)
            assert A[i, j] == pytest.approx(-(N11 / math.pi) * lg + a * fr, rel=1e-12, abs=1e-14)


def test_hat_function_integrals_closed_form():
    t = np.array([-0.4, -0.1, 0.05, 0.5])
    xc = np.array([-0.4, -0.1, 0.3, 0.5, 1.7, -2.0])
    K = B._hat_matrix(xc, t, -1.0, 0.0)
    for i, x in enumerate(xc):
        for j in range(t.size):
            def hat(s, j=j):
                return float(np.interp(s, t, np.eye(t.size)[j]))
            pts = [v for v in t[1:-1]] + ([x] if t[0] < x < t[-1] else [])
            ref = quad(lambda s: hat(s) * math.log(abs(x - s)) if s != x else 0.0,
                       t[0], t[-1], points=pts, limit=200)[0]
            assert K[i, j] == pytest.approx(ref / math.pi, rel=1e-10, abs=1e-13)


def test_sign_conventions():
    """N11 < 0 (so -(N11/pi) log|X - t| makes the loaded surface sink), and the Hilbert
    identity behind p = sqrt(a^2 - X^2)/(|N11| R): (1/pi) PV int sqrt(1-t^2)/(t-x) = -x."""
    assert ISO_N11 == pytest.approx(-(1 - 0.25) / (1.0 / 2.5))
    assert ZK.N11 < 0 < ZK.N12
    for x in (-0.7, 0.1, 0.55):
        pv = quad(lambda t: math.sqrt(1 - t * t), -1, 1, weight="cauchy", wvar=x)[0] / math.pi
        assert pv == pytest.approx(-x, abs=1e-10)


def test_w_face_closed_forms_satisfy_the_equation():
    """N11 Hc[p] = H' on the contact for the frictionless two-zone and one-zone W solutions,
    by direct PV quadrature (an independent check of their derivation)."""
    A, N11 = B.W_AMPLITUDE, -1.0
    for P in (0.1, 0.5):
        zones = B.w_face_closed_form(N11, P)
        if len(zones) == 2:
            b, c = zones[1][1], zones[1][0]

            def p(t):
                return 4 * A / abs(N11) * abs(t) * math.sqrt(max((b * b - t * t) * (t * t - c * c), 0))
        else:
            a = zones[0][1]

            def p(t):
                return 4 * A / abs(N11) * math.sqrt(max(a * a - t * t, 0)) * (t * t + a * a / 2 - 1)
        load = sum(quad(p, lo, hi, limit=200)[0] for lo, hi in zones)
        assert load == pytest.approx(P, rel=1e-9)
        for lo, hi in zones:
            for x in np.linspace(lo, hi, 5)[1:-1]:
                hc = sum(quad(p, l2, h2, weight="cauchy", wvar=x, limit=200)[0] for l2, h2 in zones)
                assert N11 * hc / math.pi == pytest.approx(4 * A * (x ** 3 - x), abs=1e-8)


@pytest.mark.slow
def test_polynomial_face_closed_form_matches_library():
    """The one-zone closed form with friction (a third route) equals the library's numeric
    solution for the cylinder and the W face (both exact for polynomial slopes)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        for punch, coeffs, P, guess in (
                (contact.CylindricalPunch(radius=10.0), [0.0, 0.1], 0.05, (-0.2, 0.2)),
                (contact.ProfilePunch(lambda X: 4 * B.W_AMPLITUDE * (X ** 3 - X)), W_SLOPE, 2.5,
                 (-1.4, 1.4))):
            for direction in (-1, 1):
                r = contact.solve(ZHOU, punch, load=P, speed=0.6, friction=0.3, direction=direction)
                pf = B.PolynomialFaceOneZone(coeffs, ZK.N11, ZK.N12 * 0.3 * -direction)
                ab = pf.solve(P, guess)
                assert np.allclose(ab, r.ends, rtol=0, atol=1e-12)
                X = np.linspace(*r.ends, 11)[1:-1]
                assert np.allclose(pf.pressure(X, pf.m, pf.L), r.pressure(X), rtol=1e-10,
                                   atol=1e-12 * np.max(r.pressure(X)))


# --------------------------------------------------------------------------
# cylinder: closed form (frictionless) and the library (friction)
# --------------------------------------------------------------------------
CYL_R, CYL_A = 1.0, 0.5
CYL_P = math.pi * CYL_A ** 2 / (2 * abs(ISO_N11) * CYL_R)


def test_cylinder_grid_convergence():
    """Uniform grid, exact complementarity: edges within 0.05 h (first order), interior
    pressure O(h^2), load exact, p >= 0 and g >= 0."""
    a, pcf = B.cylinder_closed_form(ISO_N11, CYL_R, CYL_P)
    assert a == pytest.approx(CYL_A, rel=1e-15)
    errs_p = []
    for m in (250, 500, 1000):
        r = B.solve_bem(_cyl(CYL_R), (-1, 1), ISO_N11, 0.0, CYL_P, m, refine=None)
        assert r.n_zones == 1 and not r.at_face_end
        (za, zb), = r.zones
        assert abs(za + a) < 0.05 * r.h and abs(zb - a) < 0.05 * r.h
        assert r.load_check < 1e-12 and r.complementarity < 1e-12
        inner = np.abs(r.x) < 0.8 * a
        errs_p.append(np.max(np.abs(r.p - pcf(r.x))[inner]) / pcf(0.0))
    assert errs_p[0] / errs_p[1] > 3.0 and errs_p[1] / errs_p[2] > 3.0   # O(h^2)
    assert errs_p[-1] < 1e-6


def test_cylinder_continuous_edges_convergence():
    """Zone-fitted panels with continuous edges: edge error ~ n^-2 (ratio 4 per doubling);
    the Richardson-extrapolated edges of solve_bem to 1e-7 (n = 32) with an honest error
    estimate."""
    f_errs = []
    for n in (16, 32, 64):
        f = B._Fitted(_cyl(CYL_R), ISO_N11, 0.0, CYL_P, n)
        e, _ = f.refine([-0.49, 0.52])
        f_errs.append(np.max(np.abs(e - [-CYL_A, CYL_A])))
    for e1, e2 in zip(f_errs, f_errs[1:]):
        assert 3.8 < e1 / e2 < 4.2
    r = B.solve_bem(_cyl(CYL_R), (-1, 1), ISO_N11, 0.0, CYL_P, 250, refine=32)
    assert r.refined
    err = np.max(np.abs(np.ravel(r.zones) - [-CYL_A, CYL_A]))
    assert err < 1e-7 and err <= r.edge_error
    _, pcf = B.cylinder_closed_form(ISO_N11, CYL_R, CYL_P)
    X = np.linspace(-0.45, 0.45, 19)
    assert np.max(np.abs(r.pressure(X) - pcf(X))) < 1e-3 * pcf(0.0)


@pytest.mark.parametrize("direction", [-1, 1])
def test_cylinder_friction_matches_library(direction):
    """µ = 0.3, speed 0.6, zhou2014: the grid's ends within 0.05 h and the refined ends within
    1e-7 (n = 32) of the library's; the edge exponents equal its alpha, beta and the BEM's own
    log-log slope of p at the edges."""
    R, P, mu = 10.0, 0.05, 0.3
    lib = contact.solve(ZHOU, contact.CylindricalPunch(radius=R), load=P, speed=0.6,
                        friction=mu, direction=direction)
    N12_muf = ZK.N12 * mu * -direction
    gL, gR = B.edge_exponents(ZK.N11, N12_muf)
    assert gL == pytest.approx(lib.beta, abs=1e-14) and gR == pytest.approx(lib.alpha, abs=1e-14)
    assert (gR < 0.5) == (direction == -1)             # trailing edge: the smaller exponent
    r = B.solve_bem(_cyl(R), (-0.5, 0.5), ZK.N11, N12_muf, P, 500, refine=32)
    assert np.max(np.abs(np.ravel(r.zones_grid) - lib.ends)) < 0.05 * r.h
    err = np.max(np.abs(np.ravel(r.zones) - lib.ends))
    assert r.refined and err < 1e-7 and err <= r.edge_error
    X = np.linspace(*lib.ends, 13)[2:-2]
    assert np.max(np.abs(r.pressure(X) - lib.pressure(X))) < 1e-3 * np.max(lib.pressure(X))
    # grid pressure, interior, O(h^2)-small
    inner = (r.x > lib.ends[0] + 0.1) & (r.x < lib.ends[1] - 0.1)
    assert np.max(np.abs(r.p[inner] - lib.pressure(r.x[inner]))) < 1e-4 * np.max(r.p)
    # local exponents from the BEM itself (nodes 3..6 of the fitted mesh at each edge)
    ts, pf = r.fitted
    t = ts[0]
    for side, g in ((0, gL), (1, gR)):
        k = np.arange(3, 7) if side == 0 else t.size - 1 - np.arange(3, 7)
        d = np.abs(t[k] - t[0 if side == 0 else -1])
        slope = np.polyfit(np.log(d), np.log(pf[k]), 1)[0]
        assert slope == pytest.approx(g, abs=0.02)


# --------------------------------------------------------------------------
# W face: two zones that merge
# --------------------------------------------------------------------------
def test_w_face_two_zones_then_one_frictionless():
    """Light loads: two mirror-symmetric zones (grid to 0.05 h, refined to 1e-7 of the closed
    form, n = 32; the inner edge near the merge is the worst); past P* |N11| = pi/10 one zone."""
    N11 = -1.0
    loads = [0.05, 0.2, 0.3, 0.33, 0.5]
    rs = B.load_curve_bem(B.w_face, B.W_FACE, N11, 0.0, loads, m=400, refine=32)
    assert [r.n_zones for r in rs] == [2, 2, 2, 1, 1]
    for r in rs:
        ex = np.ravel(B.w_face_closed_form(N11, r.load))
        assert r.refined and not r.at_face_end
        assert np.max(np.abs(np.ravel(r.zones_grid) - ex)) < 0.05 * r.h
        err = np.max(np.abs(np.ravel(r.zones) - ex))
        assert err < (5e-6 if r.load == 0.3 else 1e-6) and err <= r.edge_error
        z = np.ravel(r.zones)
        assert np.allclose(z, -z[::-1], atol=1e-12)               # mirror symmetric
        assert r.complementarity < 1e-12 and r.load_check < 1e-12


@pytest.mark.slow
def test_w_face_merge_load_frictionless():
    """P* = 2 pi A / |N11| (= pi/10 for N11 = -1, A = 0.05): the grid bisection (m = 500)
    to 5e-5 relative (~O(h^2): 2.1e-4, 2.7e-5, 9.1e-6, 2.3e-6 at m = 250..2000), the
    continuous-edge estimate within its own error bound (n = 64: actual 6e-7, bound 4e-6
    relative)."""
    N11 = -1.0
    Pstar = 2 * math.pi * B.W_AMPLITUDE / abs(N11)
    Pg, r2, r1 = B.merge_load_grid(B.w_face, B.W_FACE, N11, 0.0, 0.25, 0.4, m=500, rtol=1e-8)
    assert r2.n_zones == 2 and r1.n_zones == 1
    assert abs(Pg - Pstar) < 5e-5 * Pstar
    d = B.merge_load_bem(B.w_face, B.W_FACE, N11, 0.0, 0.25, 0.4, m=400, n=64)
    assert abs(d["merge_load"] - Pstar) <= d["error"] < 1e-5 * Pstar
    assert abs(d["one_zone"] - Pstar) <= d["one_zone_error"] < 1e-4 * Pstar
    assert abs(d["x_merge"]) < 1e-9
    assert np.allclose(d["zone"], [-math.sqrt(2), math.sqrt(2)], atol=1e-5)
    # below P*: the inner gap closes like sqrt(P* - P)
    for Pb, z in zip(d["loads_below"], d["zones_below"]):
        assert np.allclose(np.ravel(z), np.ravel(B.w_face_closed_form(N11, Pb)), atol=2e-6)


@pytest.mark.parametrize("direction", [-1, 1])
@pytest.mark.slow
def test_w_face_with_friction(direction):
    """µ = 0.3, speed 0.6, zhou2014: one zone above the merge agrees with the closed form and
    the library; the merge load agrees with the closed form (double root of Q); the zones
    below it are mirror images between the two directions and not symmetric themselves."""
    mu = 0.3
    N12_muf = ZK.N12 * mu * -direction
    pf = B.PolynomialFaceOneZone(W_SLOPE, ZK.N11, N12_muf)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        Pstar, zstar, xstar = pf.merge((-1.4, 1.4))
        ab = pf.solve(2.5, (-1.4, 1.4))
    assert Pstar * abs(ZK.N11) == pytest.approx(math.pi / 10, rel=1e-6)   # nearly µ-independent
    assert (xstar > 0) == (direction == -1)
    r = B.solve_bem(B.w_face, B.W_FACE, ZK.N11, N12_muf, 2.5, 400, refine=32)
    err = np.max(np.abs(np.ravel(r.zones) - ab))
    assert r.n_zones == 1 and r.refined and err < 1e-6 and err <= r.edge_error
    lib = contact.solve(ZHOU, contact.ProfilePunch(lambda X: 4 * B.W_AMPLITUDE * (X ** 3 - X)),
                        load=2.5, speed=0.6, friction=mu, direction=direction)
    assert np.max(np.abs(np.ravel(r.zones) - lib.ends)) < 1e-6
    s = abs(ZK.N11)
    d = B.merge_load_bem(B.w_face, B.W_FACE, ZK.N11, N12_muf, 0.25 / s, 0.4 / s, m=400, n=32)
    assert abs(d["merge_load"] - Pstar) <= d["error"] < 5e-5 * Pstar
    assert np.allclose(d["zone"], zstar, atol=1e-5)
    assert d["x_merge"] == pytest.approx(xstar, abs=1e-4)
    # two zones below the merge: asymmetric, mirrored by the other direction
    other = B.solve_bem(B.w_face, B.W_FACE, ZK.N11, -N12_muf, 0.2 / s, 400, refine=32)
    here = B.solve_bem(B.w_face, B.W_FACE, ZK.N11, N12_muf, 0.2 / s, 400, refine=32)
    assert here.n_zones == other.n_zones == 2 and here.refined and other.refined
    z, zo = np.ravel(here.zones), np.ravel(other.zones)
    assert np.allclose(z, -zo[::-1], atol=1e-9)
    assert np.max(np.abs(z + z[::-1])) > 1e-3
    assert np.max(np.abs(np.ravel(here.zones_grid) - z)) < 0.05 * here.h


@pytest.mark.slow
def test_w_face_reference_api_scales_with_N11():
    """w_face_reference: zones and merge load for other code; frictionless they depend on
    P |N11| only."""
    out = B.w_face_reference(-1.0, 0.0, loads=[0.1, 0.5], m=300, n=16)
    out2 = B.w_face_reference(-0.2, 0.0, loads=[0.5, 2.5], m=300, n=16)
    assert [len(z) for z in out["zones"]] == [2, 1]
    assert np.allclose(np.ravel(out["zones"][0]), np.ravel(out2["zones"][0]), atol=1e-9)
    assert out2["merge_load"] * 0.2 == pytest.approx(out["merge_load"], rel=1e-9)
    assert abs(out["merge_load"] - math.pi / 10) <= out["merge_error"]
