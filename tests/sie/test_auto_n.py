"""n chosen for the caller: ``sie.solve(..., n="auto", tol=...)`` (sie/auto.py).

References: the collinear cracks' closed form (Westergaard; tests/reference/
manufactured_intervals.py, in mpmath, independent of sie), where a fixed n = 16..32 is off
by 1e-10..3e-5 without a warning; the Jacobi-series tail of a smooth f against the solve at
the n that auto chose doubled (self-convergence, the property the chopping rule asserts); a
kink without breaks, which no n resolves (a warning, not a silent answer)."""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import sie
import sie.auto
from sie.auto import N_AUTO_START, series_resolved
from sie.errors import (InvalidOrderError, ResidualWarning, ResolutionWarning,
                        UnsupportedEquationError)
import manufactured_intervals as MI


def _ones(s):
    return np.ones_like(np.asarray(s, dtype=float))


def _no_warnings(fn):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = fn()
    return out, [w.category for w in caught]


@pytest.mark.parametrize("ratio", [0.5, 0.1, 1e-2, 1e-3])
def test_collinear_cracks_reach_their_closed_form(ratio):
    """Two collinear cracks [-c, -b] U [b, c] under unit pressure: the four stress
    intensity factors of the closed form (K_outer = sqrt(pi c) (1 - E/K)/k, K_inner =
    sqrt(pi c) sqrt(c/b) (E/K - b^2/c^2)/k) to 1e-12 with the default tol, and no warning
    (the solves at too small an n warned a residual of their own; they are not returned)."""
    C = MI.CollinearCracks(ratio, 1.0)
    sol, caught = _no_warnings(lambda: sie.solve(
        _ones, a=0.0, b=1.0, n="auto", left="singular", right="singular", total=(0.0, 0.0),
        intervals=C.intervals))
    assert caught == []
    assert all(n >= N_AUTO_START and n & (n - 1) == 0 for n in sol.n)
    sq = math.sqrt(math.pi * (C.c - C.b) / 2)
    got = (sq * sol.endpoint_value(+1, interval=1), -sq * sol.endpoint_value(-1, interval=1))
    want = (float(C.K_outer), float(C.K_inner))
    for g, w in zip(got, want):
        assert abs(g - w) <= 1e-12 * abs(w), (ratio, sol.n, g, w)


def test_a_fixed_small_n_is_what_auto_avoids():
    """The external check that motivated n="auto": at b/c = 0.1, n = 16 leaves the inner SIF
    off by 2e-7 without any warning (the residual between the nodes is below the check's
    threshold); auto reaches the closed form."""
    C = MI.CollinearCracks(0.1, 1.0)
    sq = math.sqrt(math.pi * (C.c - C.b) / 2)
    kw = dict(a=0.0, b=1.0, left="singular", right="singular", total=(0.0, 0.0),
              intervals=C.intervals)
    for n, silent_error in ((16, True), ("auto", False)):
        sol, caught = _no_warnings(lambda: sie.solve(_ones, n=n, **kw))
        err = abs(-sq * sol.endpoint_value(-1, interval=1) / float(C.K_inner) - 1)
        assert caught == []
        assert (err > 1e-7) if silent_error else (err < 1e-12), (n, err)


@pytest.mark.parametrize("tol", [1e-6, 1e-10, 1e-13])
@pytest.mark.parametrize("left,right", [("bounded", "singular"), ("singular", "singular"),
                                        ("bounded", "bounded")])
def test_smooth_f_is_resolved_to_tol(tol, left, right):
    """f with a nearby singularity (a pole at 1.1): the solution auto returns differs from
    the solve at twice its n by at most ~10 tol inside (relative to max abs(phi), plus a
    rounding floor), its tail is below tol, and a looser tol never takes a larger n."""
    def f(s):
        return np.exp(2.0 * s) / (1.1 - s)
    kw = dict(a=0.3, b=1.0, left=left, right=right)
    if left == right == "singular":
        kw["total"] = 0.5
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.InconsistentEquationWarning)
        sol = sie.solve(f, n="auto", tol=tol, **kw)
        ref = sie.solve(f, n=2 * sol.n, **kw)
        looser = sie.solve(f, n="auto", tol=100 * tol, **kw)
    # inside: next to an end the neglected tail is amplified by P_k(+-1) ~ k^alpha (at
    # u = 0.999, n = 128, tol = 1e-13: 1.3e-12 of the scale)
    u = np.linspace(-0.95, 0.95, 301)
    scale = np.max(np.abs(ref.phi(u)))
    assert np.max(np.abs(sol.phi(u) - ref.phi(u))) <= (10 * tol + 1e-14) * scale
    assert series_resolved(sol.coefficients, sol.alpha, sol.beta, tol)[0]
    assert looser.n <= sol.n


def test_kink_without_breaks_warns_at_the_limit_and_with_breaks_resolves(monkeypatch):
    """|s - 0.3| has a kink: no n resolves its series, and auto says so (ResolutionWarning
    at its largest n, here lowered to 256 to keep the test short; it is 4096, the doctest of
    ResolutionWarning goes there), pointing at the caller's line; with breaks=(0.3,) the
    correction carries the kink and auto stops early, agreeing with a solve at 8 times its
    n."""
    monkeypatch.setattr(sie.auto, "N_AUTO_MAX", 256)

    def f(s):
        return np.abs(s - 0.3)
    kw = dict(a=0.0, b=1.0, left="bounded", right="singular")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sol = sie.solve(f, n="auto", **kw)
    assert sol.n == 256
    assert [w.category for w in caught] == [ResolutionWarning]
    assert caught[0].filename == __file__ and "breaks=" in str(caught[0].message)
    sol, caught = _no_warnings(lambda: sie.solve(f, n="auto", breaks=(0.3,), **kw))
    assert caught == [] and sol.n < 512
    ref = sie.solve(f, n=8 * sol.n, breaks=(0.3,), **kw)
    u = np.array([-0.9, -0.2, 0.29, 0.31, 0.8])
    assert np.max(np.abs(sol.phi(u) - ref.phi(u))) <= 1e-11 * np.max(np.abs(ref.phi(u)))


def test_equation_object_takes_auto_and_reports_n():
    eq = sie.Equation(a=0.7, b=1.0, left="singular", right="bounded")
    sol = eq.solve(np.cos, n="auto")
    assert sol.n in (16, 32)
    assert np.max(np.abs(sol.coefficients[-8:])) <= 1e-13 * np.max(np.abs(sol.coefficients))


@pytest.mark.parametrize("n,tol,match", [
    ("Auto", None, 'or "auto"'),
    ("16", None, 'or "auto"'),
    (16, 1e-8, 'n="auto" only'),
    ("auto", 0.0, r"\[1e-15, 1e-2\]"),
    ("auto", 1e-20, r"\[1e-15, 1e-2\]"),
    ("auto", 0.5, r"\[1e-15, 1e-2\]"),
    ("auto", math.nan, "tol"),
    ("auto", "1e-8", "tol"),
])
def test_bad_n_or_tol(n, tol, match):
    with pytest.raises(InvalidOrderError, match=match):
        sie.solve(np.cos, a=0.0, b=1.0, n=n, tol=tol, left="bounded", right="singular")


def test_case_axis_takes_no_auto():
    eq = sie.Equation(a=0.0, b=1.0, left="bounded", right="singular",
                      intervals=np.array([[[-1.0, 1.0]], [[-2.0, 1.0]]]))
    with pytest.raises(UnsupportedEquationError, match="case axis"):
        eq.solve(np.cos, n="auto")


def test_residual_warning_of_the_returned_solution_is_kept(monkeypatch):
    """A kernel that no n up to the limit (lowered to 64) resolves within the residual
    check: the warnings of the returned solution reach the caller (ResidualWarning,
    ResolutionWarning), those of the smaller solves before it do not repeat."""
    monkeypatch.setattr(sie.auto, "N_AUTO_MAX", 64)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sie.solve(np.cos, a=0.0, b=1.0, n="auto", tol=1e-15, left="bounded",
                  right="singular", kernel=lambda s, t: np.abs(s - t) ** 0.5)
    cats = [w.category for w in caught]
    assert ResolutionWarning in cats
    assert cats.count(ResidualWarning) <= 1


def test_explicit_end_exponent_takes_auto_up_to_its_own_limit():
    """The edge crack (an explicit exponent 0 at the mouth, sie.fixed_ends, whose dense
    collocation stops at n = 400): auto at tol = 1e-10 gives Koiter's F = 1.12152 and agrees
    with twice its n to 1e-10 (its convergence is algebraic, ~n^-4.5: the mouth's second
    exponent 1.74 + 1.12i is not in the basis)."""
    from sie.fixed_ends import _N_MAX

    def edge_kernel(x, t):
        u = t + x
        return (-1.0 / u + 6.0 * x / u**2 - 4.0 * x**2 / u**3) / np.pi

    def tip_factor(sol):
        p = sol.pieces[0]
        phi = sol.endpoint_value(1, 0)
        return -math.sqrt(2.0 * p.interval.h) * 2.0 ** p.beta * phi

    kw = dict(a=0.0, b=1.0, left=0.0, right="singular", intervals=[(0.0, 1.0)],
              kernel=edge_kernel)
    sol, caught = _no_warnings(lambda: sie.solve(lambda s: -np.ones_like(s), n="auto",
                                                 tol=1e-10, **kw))
    assert caught == [] and sol.n[0] < _N_MAX
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResidualWarning)
        ref = sie.solve(lambda s: -np.ones_like(s), n=min(2 * sol.n[0], _N_MAX), **kw)
    F = tip_factor(sol)
    assert round(F, 5) == 1.12152
    assert abs(F - tip_factor(ref)) <= 1e-10
