"""Equation.functionals returns exactly what Equation.solve would (same rule, same n):
int psi and the solvability residual, checked against full solves with and without breaks,
for every index, on [-1, 1] and on other intervals (where int psi carries the half-width)."""
import warnings

import numpy as np
import pytest

import sie

F = [lambda s: np.exp(s) / (3 - s), lambda s: np.abs(s - 0.3) + np.cos(s)]


def _assert_same(fun, sol, rel=1e-14):
    assert fun.kappa == sol.kappa and fun.alpha == sol.alpha and fun.beta == sol.beta
    if sol.kappa == 1:
        assert fun.integral is None and fun.consistency is None
        return
    assert fun.integral == pytest.approx(sol.integral(), rel=rel, abs=1e-300)
    if sol.kappa == -1:
        assert fun.consistency == pytest.approx(sol.consistency, rel=1e-12, abs=1e-15)
    else:
        assert fun.consistency is None


@pytest.mark.parametrize("left,right", [("singular", "bounded"), ("bounded", "singular"),
                                        ("bounded", "bounded")])
@pytest.mark.parametrize("a,b", [(0.7, 1.0), (-3.0, -2.0), (-1e8, 1.0), (1e8, 1.0)])
@pytest.mark.parametrize("k", [0, 1])
def test_functionals_equal_full_solve(left, right, a, b, k):
    f = F[k]
    breaks = (0.3,) if k == 1 else ()
    eq = sie.Equation(a=a, b=b, left=left, right=right)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.InconsistentEquationWarning)
        sol = eq.solve(f, n=24, breaks=breaks)
    _assert_same(eq.functionals(f, n=24, breaks=breaks), sol)


@pytest.mark.filterwarnings("ignore::sie.InconsistentEquationWarning")
@pytest.mark.parametrize("left,right", [("singular", "bounded"), ("bounded", "singular"),
                                        ("bounded", "bounded"), ("singular", "singular")])
@pytest.mark.parametrize("interval, breaks", [((-1.0, 1.0), ()), ((2.0, 2.5), ()),
                                              ((-7.0, 3.0), (-2.0, 0.5)),
                                              ((1e-3, 2e-3), (1.5e-3,))])
def test_functionals_on_any_interval_equal_full_solve(left, right, interval, breaks):
    """On [c, d] the functionals are those of the solve on [c, d] (int psi in real
    coordinates: h times the local integral), breaks given in real coordinates."""
    c, d = interval
    m, h = 0.5 * (c + d), 0.5 * (d - c)

    def f(s):
        u = (s - m) / h
        return np.abs(u - 0.3) + np.cos(u) + np.maximum(u + 0.5, 0.0) ** 2

    eq = sie.Equation(a=0.4, b=-1.0, left=left, right=right, intervals=[interval])
    total = 0.7 if (left, right) == ("singular", "singular") else None
    sol = eq.solve(f, n=16, breaks=breaks, total=total)
    fun = eq.functionals(f, n=16, breaks=breaks)
    assert fun.kappa == sol.kappa[0] and fun.alpha == sol.alpha[0]
    if fun.kappa == 1:
        assert fun.integral is None and fun.consistency is None
        return
    assert fun.integral == pytest.approx(sol.integral(), rel=1e-13)
    if fun.kappa == -1:
        assert fun.consistency == pytest.approx(sol.consistency[0], rel=1e-12, abs=1e-15)


def test_functionals_index_one_has_none():
    eq = sie.Equation(a=0.3, b=1.0, left="singular", right="singular")
    fun = eq.functionals(np.cos, n=8)
    assert fun.kappa == 1 and fun.integral is None and fun.consistency is None


def test_functionals_validate_like_solve():
    with pytest.raises(sie.InvalidCoefficientError):
        sie.Equation(a=0.3, b=0.0, left="bounded", right="bounded")
    eq = sie.Equation(a=0.3, b=1.0, left="bounded", right="bounded")
    with pytest.raises(sie.CallableOutputError):
        eq.functionals(lambda s: s[:2], n=8)
    with pytest.raises(sie.InvalidOrderError):
        eq.functionals(np.cos, n=0)


@pytest.mark.parametrize("breaks", [[1.0], [-1.2], [np.nan], ["x"]])
def test_functionals_refuse_breaks_outside_the_interval(breaks):
    eq = sie.Equation(a=0.4, b=-1.0, left="bounded", right="bounded")
    with pytest.raises(sie.InvalidBreakpointError):
        eq.functionals(np.cos, n=12, breaks=breaks)


def test_functionals_need_one_interval_without_a_kernel():
    two = sie.Equation(a=0.4, b=1.0, left="bounded", right="bounded",
                       intervals=[(-1.0, 0.0), (0.5, 1.0)])
    with pytest.raises(sie.UnsupportedEquationError, match="one interval"):
        two.functionals(np.cos, n=8)
    kern = sie.Equation(a=0.4, b=1.0, left="bounded", right="bounded",
                        kernel=lambda s, t: s * t)
    with pytest.raises(sie.UnsupportedEquationError, match="kernel"):
        kern.functionals(np.cos, n=8)
