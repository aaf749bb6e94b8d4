"""phi at a singular end whose exponent nears 0, and the SIFs built from it (large friction).

At friction mu the corner exponent of the triangular and parabolic punches is ~ 1/(pi xi),
xi = mu_f N12 / N11 ~ mu, and the parabolic punch's phi at its corner is O(exponent) of its
Jacobi coefficients (the slope vanishes there): summed as a series it kept ~1e-16 / exponent
of itself.  References, each independent of the code under test:

* the closed forms of Zhou, Lee & Jang 2014, themselves checked here against mpmath at 40
  digits from the paper's formulas (5.22)-(5.23), (5.32)-(5.33), with the exponent from the
  principal arccot of -xi (the errata: /work/shared/notes/paper-errata.md, item 2);
* for the sie core, the inversion formula of the index-0 dominant equation
  a psi + b H[psi] = f (Muskhelishvili 1953, sec. 107), whose limit at the singular end is
      phi(-1) = -b / (pi (a^2 + b^2)) int f(t) (1-t)^{-alpha} (1+t)^{-beta-1} dt,
      phi(+1) = +b / (pi (a^2 + b^2)) int f(t) (1-t)^{-alpha-1} (1+t)^{-beta} dt,
  for polynomial f in exact Beta functions (mpmath, 40 digits).
"""
import numpy as np
import pytest
from mpmath import mp

import contact
import sie



@pytest.fixture(autouse=True)
def _forty_digits():
    """The references here are taken at 40 digits (tests/conftest.py restores the default)."""
    mp.dps = 40

MAT = contact.zhou2014()
LOAD, SPEED = 0.01, 0.3
FRICTIONS = [1e4, 1e9, 1e12, 1e15, 1.8e16]        # the FrictionError limit is ~1.9e16
PUNCHES = {"flat": contact.FlatPunch(1.0), "triangular": contact.TriangularPunch(0.1),
           "parabolic": contact.ParabolicPunch(1.0)}


def _closed(punch, mu, direction):
    return contact.solve(MAT, punch, load=LOAD, speed=SPEED, friction=mu, direction=direction,
                         method="closed_form")


def _check_sifs(numeric, closed, rel=1e-12):
    assert closed.sif and set(numeric.sif) == set(closed.sif)
    for side, k in closed.sif.items():
        assert numeric.sif[side] == pytest.approx(k, rel=rel, abs=0.0), side


# -- contact: numeric against the closed forms -----------------------------------------------
@pytest.mark.parametrize("direction", [-1, 1])
@pytest.mark.parametrize("mu", FRICTIONS)
@pytest.mark.parametrize("name", sorted(PUNCHES))
def test_numeric_sif_matches_closed_form(name, mu, direction):
    """contact.solve (the batched first step: sie.SolutionBatch.endpoint_values)."""
    punch = PUNCHES[name]
    r = contact.solve(MAT, punch, load=LOAD, speed=SPEED, friction=mu, direction=direction)
    _check_sifs(r, _closed(punch, mu, direction))


@pytest.mark.parametrize("direction", [-1, 1])
@pytest.mark.parametrize("mu", [0.3, 30.0] + FRICTIONS)
@pytest.mark.parametrize("name", ["triangular", "parabolic"])
def test_breaks_keep_the_sif(name, mu, direction):
    """The same one-corner faces as a ProfilePunch with a break inside the contact (where
    the slope is smooth: the breaks' correction runs, and must change nothing): the ends
    and the SIF as the closed form's.  Toward alpha = 1 (direction +1) the projections
    split off the end's mass (sie.quadrature.composite_weighted_rule: the ends were off by
    2e-9 at mu = 1e8, 3e-2 at 1e15); toward a corner exponent 0 (direction -1) phi at the
    corner comes from the equation with the correction's quotient part (the SIF of the
    parabolic face was off by 1e-11 at mu = 1e4, 98 % at 1e15)."""
    punch = PUNCHES[name]
    closed = _closed(punch, mu, direction)
    e0, e1 = closed.ends
    for frac in (0.3, 0.9):
        face = contact.ProfilePunch(punch.slope, face=punch.extent,
                                    breaks=(e0 + frac * (e1 - e0),))
        r = contact.solve(MAT, face, load=LOAD, speed=SPEED, friction=mu, direction=direction)
        assert r.zones[0].kinds == closed.zones[0].kinds
        assert np.allclose(r.ends, closed.ends, rtol=0, atol=1e-13 * (e1 - e0))
        _check_sifs(r, closed, rel=1e-13)


@pytest.mark.parametrize("direction", [-1, 1])
@pytest.mark.parametrize("mu", [1e9, 1e15])
def test_load_curve_sif_matches_closed_form(mu, direction):
    """contact.load_curve (the load continuation: sie.Solution.endpoint_value)."""
    punch = PUNCHES["parabolic"]
    r = contact.load_curve(MAT, punch, [LOAD], speed=SPEED, friction=mu,
                           direction=direction)[0]
    _check_sifs(r, _closed(punch, mu, direction))


# -- the closed forms against mpmath ------------------------------------------------------------
def _alpha0(N, mu_f):
    """alpha0 in (0, 1) with cot(pi alpha0) = -xi, xi = mu_f N12 / N11 (principal arccot)."""
    xi = mp.mpf(mu_f) * mp.mpf(N.N12) / mp.mpf(N.N11)
    return mp.atan2(1, -xi) / mp.pi


def _parabolic_sif(N, mu_f, P, R):
    """(5.32)-(5.33): b^2 = -2 N11 P R / (pi alpha (1 + alpha)),
    FI(0) = b^(alpha+1) alpha sin(pi alpha) / (-N11 R)."""
    a, N11 = _alpha0(N, mu_f), mp.mpf(N.N11)
    b = mp.sqrt(-2 * N11 * P * R / (mp.pi * a * (1 + a)))
    return b ** (a + 1) * a * mp.sin(mp.pi * a) / (-N11 * R)


def _triangular_sif(N, mu_f, P, m0):
    """(5.22)-(5.23): b = -N11 P / (m0 pi alpha), k1(0) = m0 sin(pi alpha) b^alpha / (-N11)."""
    a, N11 = _alpha0(N, mu_f), mp.mpf(N.N11)
    b = -N11 * P / (m0 * mp.pi * a)
    return m0 * mp.sin(mp.pi * a) * b ** a / (-N11)


@pytest.mark.parametrize("mu, direction", [(1e12, -1), (1.8e16, -1), (1e15, 1)])
def test_closed_form_sif_against_mpmath(mu, direction):
    P = mp.mpf(LOAD)
    c = _closed(PUNCHES["parabolic"], mu, direction)
    ref = _parabolic_sif(c.constants, c.mu_f, P, mp.mpf(1))
    assert abs(c.sif["left"] / ref - 1) < 1e-14
    c = _closed(PUNCHES["triangular"], mu, direction)
    ref = _triangular_sif(c.constants, c.mu_f, P, mp.mpf("0.1"))
    assert abs(c.sif["left"] / ref - 1) < 1e-14


# -- sie: phi at the singular end against the inversion formula ----------------------------------
def _moment(poly, p, q):
    """int_{-1}^{1} poly(t) (1-t)^p (1+t)^q dt, poly's coefficients in powers of t, exact:
    t^j = sum_i C(j, i) (1+t)^i (-1)^(j-i) and int (1-t)^p (1+t)^(q+i) = 2^(p+q+i+1) B."""
    return mp.fsum(mp.mpf(c) * mp.binomial(j, i) * (-1) ** (j - i) * 2 ** (p + q + i + 1)
                   * mp.beta(p + 1, q + i + 1)
                   for j, c in enumerate(poly) for i in range(j + 1))


def _phi_end_reference(poly, a, b, end):
    """phi at the singular end ``end`` of a psi + b H[psi] = poly (index 0)."""
    a, b = mp.mpf(a), mp.mpf(b)
    alpha0 = mp.atan2(1, -a / b) / mp.pi           # cot(pi alpha0) = -a/b
    alpha0c = mp.atan2(1, a / b) / mp.pi           # 1 - alpha0
    k = -b / (mp.pi * (a * a + b * b))
    if end == -1:                                  # beta = -alpha0, alpha = alpha0
        return k * _moment(poly, -alpha0, alpha0 - 1)
    return -k * _moment(poly, alpha0c - 1, -alpha0c)  # alpha = -alpha0c, beta = alpha0c


# f vanishing at the singular end (as the parabolic punch's slope at its corner) and not
# ((1 + s) (2 - s + s^2 / 4) and (1 - s) (2 + s + s^2 / 4): binary fractions, so that the
# exact polynomial vanishes at the end as its float evaluation does -- phi there moves by
# ~f(end) / exponent)
POLYS = {-1: {"zero at the end": [2.0, 1.0, -0.75, 0.25], "nonzero": [0.5, 1.0, 0.25]},
         1: {"zero at the end": [2.0, -1.0, -0.75, -0.25], "nonzero": [0.5, -1.0, 0.25]}}
# (a, b) with the singular end's exponent ~ 3e-9, 3e-13, 3e-16 and one of -1/4
CASES = {-1: [(-1e8, 1.0), (1e12, -1.0), (-1e15, 1.0), (-1.0, 1.0)],
         1: [(1e8, 1.0), (-1e12, -1.0), (1e15, 1.0), (1.0, -1.0)]}


def _f(poly):
    return lambda s: np.polynomial.polynomial.polyval(s, poly)


@pytest.mark.parametrize("kind", ["zero at the end", "nonzero"])
@pytest.mark.parametrize("end", [-1, 1])
def test_endpoint_value_at_a_near_zero_exponent(end, kind):
    poly = POLYS[end][kind]
    ends = dict(left="singular", right="bounded") if end == -1 else \
        dict(left="bounded", right="singular")
    for a, b in CASES[end]:
        sol = sie.solve(_f(poly), a=a, b=b, n=6, **ends)
        ref = _phi_end_reference(poly, a, b, end)
        assert abs(sol.endpoint_value(end) / ref - 1) < 1e-13, (a, b)


@pytest.mark.parametrize("end", [-1, 1])
def test_batch_endpoint_values_at_a_near_zero_exponent(end):
    """An sie.Equation with a case axis, its solutions' take(), and each
    batch[i].endpoint_value."""
    poly = POLYS[end]["zero at the end"]
    ends = dict(left="singular", right="bounded") if end == -1 else \
        dict(left="bounded", right="singular")
    a, b = (np.array(v) for v in zip(*CASES[end]))
    iv = [[(-1.0, 1.0)]] * a.size
    sb = sie.Equation(a=a, b=b, intervals=iv, **ends).solve(_f(poly), n=6)
    col = (end + 1) // 2
    refs = [_phi_end_reference(poly, ai, bi, end) for ai, bi in zip(a, b)]
    for i, ref in enumerate(refs):
        assert abs(sb.endpoint_values()[i, col] / ref - 1) < 1e-13, i
        assert abs(sb[i].endpoint_value(end) / ref - 1) < 1e-13, i
    sub = sb.take([2, 0])
    assert abs(sub.endpoint_values()[0, col] / refs[2] - 1) < 1e-13


def test_equation_end_value_with_coupling_and_kernel():
    """On two intervals with a kernel, phi at each singular end (exponent -1/4, where the
    series summed at the end is accurate) from the equation there -- f less the other
    interval's Cauchy integral and the kernel term at the end -- agrees with the series."""
    f = _f([0.4, 1.3, -0.5, 0.25])
    b = 1.0
    sol = sie.solve(f, a=-1.0, b=b, n=24, left="singular", right="bounded",
                    intervals=[(-2.0, -0.5), (0.5, 2.0)], kernel=lambda s, t: 0.3 * np.cos(s - t))
    for j, p in enumerate(sol.pieces):
        series = float(sol.phi(np.array([sol.intervals[j][0]]))[0])
        g, size = p.end_rhs
        assert abs(g[0] - f(sol.intervals[j][0])) > 0.1 * abs(g[0])     # coupling counts
        value, _ = sie.solution.equation_end_value(
            p.coefficients[None, :], [p.exp.beta], [p.exp.beta_p1], -1, g[:1], size[:1],
            np.array([-b / p.exp.sin]))
        assert abs(value[0] - series) < 1e-13 * abs(series), j
        assert abs(sol.endpoint_value(-1, interval=j) - series) < 1e-13 * abs(series), j
