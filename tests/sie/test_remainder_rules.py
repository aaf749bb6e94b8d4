"""The quadrature rules behind the pointwise correction for breaks (:mod:`sie.remainder`) and
the projection rule split at breaks (:func:`sie.quadrature.composite_rule`), each against an
independent reference.

* The composite rule and the graded rules integrate (1-x)^alpha (1+x)^beta g for g with a
  kink, and with (x - c) log|x - c|, at the breaks, against mpmath's tanh-sinh quadrature
  split at the breaks (to 1e-14 of the integral of |g| w).
* The graded rules' node counts fall with depth toward a break (hp); delta_phi from them
  against delta_phi from rules with twice the nodes on every piece, without the fall
  (``_HP_SLOPE = 0``): to rounding of phi away from the ends, where the end pieces decide
  (and both rules agree with the finer one as well as the rules without the fall do).
* The log potential of w delta_phi beyond |v| = 2 from the moments of w delta_phi
  (:func:`sie.remainder.log_far`) against the sum over the nodes of ``w_rule`` taken term by
  term with ``math.fsum``; and a solution's log potential there (series and correction
  from their moments together) against the two parts taken apart.
"""
from __future__ import annotations

import math
import warnings

import mpmath
import numpy as np
import pytest

import sie
from sie import quadrature, remainder

C = 0.41                            # breaks at +-C


def rounded_flat(s):
    """A slope 0 on |s| < C and (|s| - C) sign(s) beyond (odd: index -1 solvable)."""
    s = np.asarray(s, dtype=float)
    return np.where(np.abs(s) < C, 0.0, (np.abs(s) - C) * np.sign(s))


def kinked(x):
    return np.abs(x - C) + 0.5 * np.abs(x + 0.3) + np.cos(x)


def log_kinked(x):
    d = np.abs(x - C)
    return np.where(d > 0.0, (x - C) * np.log(np.where(d > 0.0, d, 1.0)), 0.0) + x * x


def _mp_integral(g, alpha, beta, breaks):
    """int (1-x)^alpha (1+x)^beta g(x) dx and the integral of its modulus, by mpmath split
    at the breaks; on the end pieces the end factor is absorbed by u = (1 -+ x)^(1+e)/(1+e)
    (du = (1 -+ x)^e dx), which leaves tanh-sinh an integrand without the singularity."""
    mpmath.mp.dps = 30
    edges = [-1.0] + sorted(breaks) + [1.0]

    def gx(x):
        return float(g(np.array([float(x)]))[0])

    def piece(lo, hi, absolute):
        a1, b1 = mpmath.mpf(alpha) + 1, mpmath.mpf(beta) + 1
        if lo == -1.0:              # x = -1 + (b1 u)^(1/b1)
            def f(u):
                x = -1 + (b1 * u) ** (1 / b1)
                return (1 - x) ** alpha * gx(x)
            span = (0, (1 + mpmath.mpf(hi)) ** b1 / b1)
        elif hi == 1.0:             # x = 1 - (a1 u)^(1/a1)
            def f(u):
                x = 1 - (a1 * u) ** (1 / a1)
                return (1 + x) ** beta * gx(x)
            span = (0, (1 - mpmath.mpf(lo)) ** a1 / a1)
        else:
            def f(x):
                return (1 - x) ** alpha * (1 + x) ** beta * gx(x)
            span = (lo, hi)
        return mpmath.quad((lambda u: abs(f(u))) if absolute else f, span)
    value = sum(piece(lo, hi, False) for lo, hi in zip(edges[:-1], edges[1:]))
    size = sum(piece(lo, hi, True) for lo, hi in zip(edges[:-1], edges[1:]))
    return float(value), float(size)


EXPONENTS = [(-0.5, -0.5), (0.5, 0.5), (0.3, -0.7), (-0.25, 0.6)]


@pytest.mark.parametrize("alpha,beta", EXPONENTS)
def test_composite_rule_against_mpmath(alpha, beta):
    breaks = np.array([-0.3, C])
    x, w = quadrature.composite_rule(40, alpha, beta, breaks)
    ref, size = _mp_integral(kinked, alpha, beta, breaks)
    assert abs(w @ kinked(x) - ref) <= 1e-14 * size, (w @ kinked(x) - ref) / size


@pytest.mark.parametrize("alpha,beta", EXPONENTS)
@pytest.mark.parametrize("w_rule", [False, True])
def test_graded_rule_against_mpmath(alpha, beta, w_rule):
    """The rules of ``rules`` (graded toward the breaks) and of ``w_rule`` (toward the ends
    too) integrate g with (x - c) log|x - c| at a break, with the counts' fall with depth."""
    breaks = np.array([-C, C])
    pts = remainder.graded_points(breaks)
    if w_rule:
        pts = np.union1d(pts, remainder._end_grading(breaks))
    x, w = remainder._graded_rule(49, alpha, beta, breaks, pts, remainder._Q_SMALL + 2 * w_rule)
    ref, size = _mp_integral(log_kinked, alpha, beta, [-C, C])
    assert abs(w @ log_kinked(x) - ref) <= 1e-14 * size, (w @ log_kinked(x) - ref) / size


def test_counts_fall_with_depth():
    """One node fewer per level toward a break, down to _HP_MIN; the innermost piece, at the
    break, keeps its count."""
    breaks = np.array([-C, C])
    lo, hi, counts = remainder._panels(49, breaks, remainder.graded_points(breaks))
    right = (lo >= C) & (hi <= 1.0) & (hi - lo < 0.2 * (1.0 - C))   # graded, right of +C
    order = np.argsort(hi[right] - lo[right])[::-1]                  # outermost first
    c, length = counts[right][order], (hi - lo)[right][order]
    assert lo[right][order][-1] == C and c[-1] == remainder._Q_SMALL + 1
    c = c[:-1]
    assert c[0] == remainder._Q_SMALL + math.ceil(49 * length[0] / (1.0 - C))
    assert np.all(np.diff(c) <= 0) and c[-1] >= remainder._HP_MIN and c[-1] < c[0] - 8
    assert np.all(c[1:-1] - c[2:] == 1)             # one fewer per level, past the first


def _solved(**kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.InconsistentEquationWarning)
        return sie.solve(rounded_flat, breaks=(-C, C), **kw).pieces[0]


CASES = {
    "free ends a=0": dict(a=0.0, b=1.0, n=24, left="bounded", right="bounded"),
    "corner a=0.6": dict(a=0.6, b=1.0, n=24, left="singular", right="bounded"),
    "two corners a=-0.4": dict(a=-0.4, b=1.0, n=32, left="singular", right="singular",
                               total=0.7),
}


@pytest.mark.parametrize("name", CASES)
def test_delta_phi_against_finer_rules(name, monkeypatch):
    piece = _solved(**CASES[name])
    x = np.concatenate([np.cos(np.pi * (np.arange(64) + 0.5) / 64),
                        (C + np.outer([-1.0, 1.0], np.geomspace(1e-15, 0.3, 30))).ravel(),
                        (-C + np.outer([-1.0, 1.0], np.geomspace(1e-15, 0.3, 30))).ravel()])
    scale = np.max(np.abs(piece.phi_local(np.linspace(-0.99, 0.99, 199))))
    got = piece._remainder_factory().phi(x)
    graded = remainder._graded_rule

    def finer(q, alpha, beta, breaks, pts, q_small=remainder._Q_SMALL, shift=0, details=False):
        return graded(2 * q + 8, alpha, beta, breaks, pts, 2 * q_small + 8, shift, details)
    monkeypatch.setattr(remainder, "_HP_SLOPE", 0.0)
    without = piece._remainder_factory().phi(x)
    monkeypatch.setattr(remainder, "_graded_rule", finer)
    ref = piece._remainder_factory().phi(x)
    inner = np.abs(x) <= 0.99
    err, err_without = np.abs(got - ref) / scale, np.abs(without - ref) / scale
    assert np.max(err[inner]) <= 4e-15, np.max(err[inner])
    assert np.max(err) <= max(2e-13, 1.5 * np.max(err_without)), (np.max(err), np.max(err_without))


def test_far_log_sums_against_fsum():
    piece = _solved(**CASES["corner a=0.6"])
    rem = piece._remainder_factory()
    t, _ = rem.w_rule
    c = rem._w_values()
    v = np.concatenate([np.geomspace(2.0, 1e12, 40), -np.geomspace(2.0, 1e12, 40)])
    got = remainder.log_far(v, rem.far_coefficients()) * math.pi
    for vi, g in zip(v, got):
        terms = c * np.log(np.abs(vi - t))
        ref = math.fsum(terms)
        assert abs(g - ref) <= 4e-16 * math.fsum(np.abs(terms)) + 1e-16 * math.fsum(np.abs(c)), \
            (vi, g, ref)
    # and through log_potential, which takes the moments from |v| = 2 on
    far = np.array([2.0, 2.01, -2.0, 1e3])
    direct = [math.fsum(c * np.log(np.abs(vi - t))) / math.pi for vi in far]
    assert np.allclose(rem.log_potential(far), direct, rtol=0.0,
                       atol=1e-16 * math.fsum(np.abs(c)))


@pytest.mark.parametrize("name", CASES)
def test_far_log_potential_of_both_parts(name):
    """IntervalSolution.log_local at |v| >= 2 sums the series and the correction from their
    moments together; the parts apart: the series by sie.cauchy.log_potential_series, the
    correction term by term over ``w_rule`` (math.fsum)."""
    from sie.cauchy import log_potential_series
    piece = _solved(**CASES[name])
    rem = piece.remainder
    t, _ = rem.w_rule
    c = rem._w_values()
    v = np.concatenate([[2.0, -2.0, 2.5, -7.0], np.geomspace(3.0, 1e15, 20)])
    got = piece.log_local(v)
    series = log_potential_series(piece.coefficients, piece.weight_data, v)
    part = np.array([math.fsum(c * np.log(np.abs(vi - t))) for vi in v]) / math.pi
    scale = np.abs(series) + np.sum(np.abs(c)) * (1.0 + np.log(np.abs(v)))
    # a few ulps of the scale: the moments' sums and the series' recurrence round apart
    # (4.2e-16 seen at the corner, a = 0.6)
    assert np.all(np.abs(got - (series + part)) <= 8e-16 * scale), \
        np.max(np.abs(got - (series + part)) / scale)
