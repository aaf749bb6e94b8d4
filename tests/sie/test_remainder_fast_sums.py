"""The compiled sums behind delta_phi at many points and the log potential of w delta_phi
(:mod:`sie.remainder`), each against an independent route.

* The treecode of the difference-quotient sums (:func:`sie.remainder._tree_quotient_sums`)
  against the same sums term by term (:func:`sie.remainder._difference_quotient_sums`), to
  a few roundings of sum_j |w_j| (|r_j| + |r(x)|) / |t_j - x| (the rounding of r_j - r(x)
  in the terms one by one): at the nodes of ``w_rule`` and at points within 1e-15 of a break,
  on breaks and nodes, at the ends; for every index, exponents next to 0 and 1, and a break
  1e-12 from an end.
* delta_phi at the nodes of ``w_rule`` (interpolated on the end pieces, the rest by the
  treecode) against delta_phi from rules with twice the nodes on every piece, term by term
  (the yardstick of test_remainder_rules.py's test_delta_phi_against_finer_rules).
* The cluster moments (:func:`sie.remainder._log_moments`, compensated low orders, the
  others in vector lanes) against the moments summed exactly (``math.fsum``).
* The barycentric interpolant (:func:`sie.remainder._barycentric`) at and next to its
  points, against numpy's polynomial fit.
* The weight's potential beside the interval in one compiled loop
  (:func:`sie.cauchy.l0_beside`, which the log potential of a solution with breaks takes)
  against :func:`sie.cauchy.l0` and mpmath.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import sie
from sie import remainder

C = 0.3


def kinked(s):
    s = np.asarray(s, dtype=float)
    return np.abs(s - C) + 0.5 * np.cos(3.0 * s) + 0.2 * np.abs(s + 0.55) * s


CASES = {
    "index -1": dict(a=0.0, b=1.0, left="bounded", right="bounded"),
    "index 0": dict(a=0.6, b=1.0, left="singular", right="bounded"),
    "index 1": dict(a=-0.4, b=1.0, left="singular", right="singular", total=0.7),
    "alpha next to 1": dict(a=1e6, b=1.0, left="singular", right="bounded"),
    "alpha next to 0": dict(a=-1e6, b=1.0, left="singular", right="bounded"),
}
BREAKS = {"two breaks": (-0.55, C), "a break 1e-12 from an end": (-0.55, C, 1.0 - 1e-12)}


def _remainder(case, breaks, n=24):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.InconsistentEquationWarning)
        piece = sie.solve(kinked, breaks=breaks, n=n, **CASES[case]).pieces[0]
    return piece, piece._remainder_factory()


def _targets(rem, breaks):
    """The nodes of w_rule, points within 1e-15..1e-3 of each break on both sides, the
    breaks, nodes of both 1/w rules, the ends, and points spread over the interval."""
    tw, _ = rem.w_rule
    near = np.geomspace(1e-15, 1e-3, 13)
    b = np.array([c for c in breaks if abs(c) < 1.0])
    close = (b[:, None, None] + np.array([-1.0, 1.0])[None, :, None] * near).ravel()
    nodes = np.concatenate([rem.rules[0][0][::7], rem.rules[1][0][::11]])
    x = np.concatenate([tw, close, b, nodes, [-1.0, 1.0],
                        np.cos(np.pi * (np.arange(301) + 0.5) / 301)])
    return np.clip(x, -1.0, 1.0)


@pytest.mark.parametrize("breaks", BREAKS)
@pytest.mark.parametrize("case", CASES)
def test_treecode_is_the_direct_sum(case, breaks):
    _, rem = _remainder(case, BREAKS[breaks])
    x = _targets(rem, BREAKS[breaks])
    rx = rem._r(x, rem.f(x))
    (n0, w0, r0), (n1, w1, r1) = rem.rules
    direct = np.empty(x.size)
    remainder._difference_quotient_sums(x, rx, n0, r0, w0, n1, r1, w1, direct)
    tree = np.empty(x.size)
    remainder._tree_quotient_sums(x, rx, n0, r0, w0, n1, r1, w1, remainder._TREE_LIMITS,
                                  tree)
    # the yardstick: the rounding of the terms one by one, over the rule each x takes
    scale = np.empty(x.size)
    for i, xi in enumerate(x):
        d0 = np.min(np.abs(n0 - xi))
        d1 = np.min(np.abs(n1 - xi))
        nodes, w, r = (n1, w1, r1) if d1 > d0 else (n0, w0, r0)
        den = np.abs(nodes - xi)
        keep = den > 0.0
        scale[i] = np.sum(np.abs(w[keep]) * (np.abs(r[keep]) + abs(rx[i])) / den[keep])
    err = np.abs(tree - direct) / (np.finfo(float).eps * scale)
    k = int(np.argmax(err))
    assert err[k] <= 8.0, (x[k], tree[k], direct[k], err[k])


@pytest.mark.parametrize("breaks", BREAKS)
@pytest.mark.parametrize("case", ["index -1", "index 0", "index 1"])
def test_delta_phi_at_w_nodes_against_finer_rules(case, breaks, monkeypatch):
    """delta_phi at the nodes of w_rule as the log potential and the far moments take it
    (interpolated on the end pieces, the treecode elsewhere) against delta_phi at the same
    nodes from rules with twice the nodes on every piece (term by term, no interpolation):
    no worse than delta_phi term by term from the rules themselves (within |x| <= 0.99 and
    over all nodes; both to 2e-14 of max |phi| inside for breaks away from the ends), and
    delta_phi at the ends to rounding."""
    piece, rem = _remainder(case, BREAKS[breaks])
    tw, _ = rem.w_rule
    got, ends = rem._phi_at_w_nodes()
    assert got.size == tw.size
    monkeypatch.setattr(remainder, "_TREE_MIN", 10 ** 9)         # term by term
    plain = rem.phi(tw)
    plain_ends = rem.phi(np.array([-1.0, 1.0]))
    graded = remainder._graded_rule

    def finer(q, alpha, beta, breaks, pts, q_small=remainder._Q_SMALL, shift=0,
              details=False):
        return graded(2 * q + 8, alpha, beta, breaks, pts, 2 * q_small + 8, shift, details)
    monkeypatch.setattr(remainder, "_graded_rule", finer)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.InconsistentEquationWarning)
        ref = piece._remainder_factory().phi(tw)
    scale = np.max(np.abs(piece.phi_local(np.linspace(-0.99, 0.99, 199))))
    err, err_plain = np.abs(got - ref) / scale, np.abs(plain - ref) / scale
    inner = np.abs(tw) <= 0.99
    assert np.max(err[inner]) <= max(4e-15, 1.5 * np.max(err_plain[inner])), \
        (np.max(err[inner]), np.max(err_plain[inner]))
    if breaks == "two breaks":
        assert np.max(err[inner]) <= 2e-14, np.max(err[inner])
    assert np.max(err) <= max(2e-13, 1.5 * np.max(err_plain)), (np.max(err),
                                                                np.max(err_plain))
    assert np.max(np.abs(ends - plain_ends)) <= 4e-15 * scale


def test_log_moments_against_fsum():
    """Per cluster, the moments sum c_j s_j^p / p (p >= 1) and sum c_j against math.fsum of
    the same terms (s_j from the cluster's centre and radius as the kernel forms them): to
    1e-16 of sum |c_j| for p < _LOG_EXACT, and to 3e-15 of sum |c_j s_j^p| / p beyond, which
    the sums of _log_sums meet times r^p <= 3^-p."""
    rng = np.random.default_rng(3)
    e = np.sort(np.concatenate([np.geomspace(1e-15, 2.0, 300), rng.uniform(0.5, 1.0, 900)]))
    c = rng.normal(size=e.size) * np.sqrt(e)
    starts = remainder._cluster_starts(e)
    k = starts.size - 1
    centers, radii = np.empty(k), np.empty(k)
    terms = np.empty(k, dtype=np.int64)
    moments = np.empty((k, remainder._LOG_TERMS + 1))
    remainder._log_moments(e, c, starts, centers, radii, terms, moments)
    checked = 0
    for i in range(k):
        lo, hi = starts[i], starts[i + 1]
        if hi - lo <= remainder._LOG_DIRECT:
            continue
        s = (e[lo:hi] - centers[i]) * (1.0 / radii[i] if radii[i] > 0.0 else 0.0)
        size = math.fsum(np.abs(c[lo:hi]))
        for p in range(terms[i] + 1):
            t = c[lo:hi] * s ** p / max(p, 1)
            ref = math.fsum(t)
            tol = 1e-16 * size if p < remainder._LOG_EXACT else 3e-15 * math.fsum(np.abs(t))
            assert abs(moments[i, p] - ref) <= tol, (i, p, moments[i, p], ref)
            checked += 1
        assert np.all(moments[i, terms[i] + 1:] == 0.0)
    assert checked > 50 and np.max(np.diff(starts)) > 500


def test_barycentric_interpolant():
    """At Chebyshev points of the second kind (as offsets s = sin^2(theta/2) of [0, 1]) the
    interpolant of a polynomial of lower degree is the polynomial, at the points themselves
    (exactly their values), next to them and between them."""
    m = 25
    s = np.sin(0.5 * np.pi * np.arange(m) / (m - 1)) ** 2
    lam = (-1.0) ** np.arange(m)
    lam[[0, -1]] *= 0.5
    coef = np.random.default_rng(5).normal(size=m - 1)
    f = np.polynomial.polynomial.polyval(s, coef)
    u = np.concatenate([s, s[:-1] + 1e-17, s[1:] - 1e-13, np.linspace(0.0, 1.0, 101),
                        [1e-300, 5e-324]])
    out = np.empty(u.size)
    remainder._barycentric(u, s, lam, f, out)
    assert np.array_equal(out[:m], f)
    ref = np.polynomial.polynomial.polyval(u, coef)
    assert np.max(np.abs(out - ref)) <= 1e-14 * np.sum(np.abs(coef))


@pytest.mark.parametrize("alpha,beta", [(0.5, 0.5), (-0.5, -0.5), (0.3, -0.3), (-0.3, -0.7),
                                        (0.2, 0.8), (1.0 - 3e-7, -1.0 + 3e-7), (3e-7, -3e-7)])
def test_weight_potential_beside_the_interval(alpha, beta):
    """sie.cauchy.l0_beside (the points 1 <= |x| < 2 in one compiled loop) against
    sie.cauchy.l0 (the same rule by a matrix product): to 8 eps mu_0 / |sin(pi alpha)| (the
    closed form divides by sin(pi alpha)), exactly at +-1 and elsewhere; and both against
    mpmath's quadrature of (1/pi) int w log|x - u| du for exponents away from integers, to
    the same scale."""
    import mpmath
    from sie.cauchy import Weight, l0, l0_beside
    wt = Weight.plain(alpha, beta)
    near = np.geomspace(1e-15, 0.99, 25)
    x = np.concatenate([[1.0, -1.0], 1.0 + near, -1.0 - near, [0.3, -0.999, 2.5, -7.0]])
    got, ref = l0_beside(wt, x), l0(wt, x)
    scale = 8.0 * np.finfo(float).eps * wt.mu0 / abs(wt.sin)
    assert np.max(np.abs(got - ref)) <= scale
    assert np.array_equal(got[:2], ref[:2]) and np.array_equal(got[-4:], ref[-4:])
    if min(abs(alpha), abs(1.0 - abs(alpha))) < 1e-3:
        return
    mpmath.mp.dps = 30
    a, b = mpmath.mpf(alpha), mpmath.mpf(beta)
    for xi, g in zip(x[[2, 14, 26, 27, 39, 51]], got[[2, 14, 26, 27, 39, 51]]):
        X = mpmath.mpf(xi)
        # the end factors absorbed by u = (1 -+ t)^(1+e)/(1+e), as test_remainder_rules.py
        left = mpmath.quad(lambda s: (1 - (-1 + ((b + 1) * s) ** (1 / (b + 1)))) ** a
                           * mpmath.log(abs(X + 1 - ((b + 1) * s) ** (1 / (b + 1)))),
                           [0, 1 / (b + 1)])
        right = mpmath.quad(lambda s: (1 + (1 - ((a + 1) * s) ** (1 / (a + 1)))) ** b
                            * mpmath.log(abs(X - 1 + ((a + 1) * s) ** (1 / (a + 1)))),
                            [0, 1 / (a + 1)])
        # the scale of the first check: the closed form subtracts terms of size
        # mu_0 / abs(sin(pi alpha)), and its Gauss-Jacobi rule of 30 nodes is exact to a
        # few ulps of them
        assert abs(g - float((left + right) / mpmath.pi)) <= scale, xi
