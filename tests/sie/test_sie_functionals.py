"""sie.dominant_functionals returns exactly what sie.solve would (same rule): checked
against full solves, with and without breaks, for every index."""
import numpy as np
import pytest

import sie

F = [lambda s: np.exp(s) / (3 - s), lambda s: np.abs(s - 0.3) + np.cos(s)]


@pytest.mark.parametrize("left,right", [("singular", "bounded"), ("bounded", "singular"),
                                        ("bounded", "bounded")])
@pytest.mark.parametrize("a,b", [(0.7, 1.0), (-3.0, -2.0), (-1e8, 1.0)])
@pytest.mark.parametrize("k", [0, 1])
def test_functionals_equal_full_solve(left, right, a, b, k):
    f = F[k]
    breaks = (0.3,) if k == 1 else ()
    sol = sie.solve(f, a=a, b=b, n=24, left=left, right=right, breaks=breaks)
    fun = sie.dominant_functionals(f, a=a, b=b, n=24, left=left, right=right, breaks=breaks)
    assert fun.kappa == sol.kappa and fun.alpha == sol.alpha and fun.beta == sol.beta
    assert fun.integral == pytest.approx(sol.integral(), rel=1e-14, abs=1e-300)
    if sol.kappa == -1:
        assert fun.consistency == pytest.approx(sol.consistency, rel=1e-13, abs=1e-15)
    else:
        assert fun.consistency is None


def test_functionals_index_one_has_none():
    fun = sie.dominant_functionals(np.cos, a=0.3, b=1.0, n=8, left="singular", right="singular")
    assert fun.kappa == 1 and fun.integral is None and fun.consistency is None


def test_functionals_validate_like_solve():
    with pytest.raises(sie.InvalidCoefficientError):
        sie.dominant_functionals(np.cos, a=0.3, b=0.0, n=8, left="bounded", right="bounded")
    with pytest.raises(sie.CallableOutputError):
        sie.dominant_functionals(lambda s: s[:2], a=0.3, b=1.0, n=8, left="bounded", right="bounded")


@pytest.mark.parametrize("left,right", [("singular", "bounded"), ("bounded", "singular"),
                                        ("bounded", "bounded"), ("singular", "singular")])
@pytest.mark.parametrize("a,b", [(0.7, 1.0), (-3.0, -2.0), (-1e8, 1.0), (1e8, 1.0)])
def test_prepared_rule_equals_dominant_functionals(left, right, a, b):
    """FunctionalsRule (built once) returns what dominant_functionals computes per call,
    including the end-mass correction at a/b = +-1e8."""
    rule = sie.FunctionalsRule(a=a, b=b, n=16, left=left, right=right)
    for f in (F[0], lambda s: 0.3 * s ** 3 - s + 2.0):
        want = sie.dominant_functionals(f, a=a, b=b, n=16, left=left, right=right)
        got = rule(f)
        assert got.kappa == want.kappa
        if want.integral is None:
            assert got.integral is None
        else:
            assert got.integral == pytest.approx(want.integral, rel=1e-13, abs=1e-300)
        if want.consistency is None:
            assert got.consistency is None
        else:
            assert got.consistency == pytest.approx(want.consistency, rel=1e-12, abs=1e-15)


@pytest.mark.parametrize("left,right", [("singular", "bounded"), ("bounded", "singular"),
                                        ("bounded", "bounded")])
@pytest.mark.parametrize("breaks", [[0.3], [-0.5, 0.2], [0.2, -0.5, 0.2]])
def test_prepared_rule_with_breaks_equals_dominant_functionals(left, right, breaks):
    """rule(f, breaks) (the composite rule formed per call) returns what
    dominant_functionals(..., breaks=...) computes, for an f that kinks at the breaks."""
    rule = sie.FunctionalsRule(a=0.4, b=-1.0, n=12, left=left, right=right)

    def f(s):
        return np.abs(s - 0.3) + np.maximum(s + 0.5, 0.0) ** 2 + np.abs(s - 0.2)

    want = sie.dominant_functionals(f, a=0.4, b=-1.0, n=12, left=left, right=right,
                                    breaks=breaks)
    got = rule(f, breaks)
    assert got.integral == pytest.approx(want.integral, rel=1e-13)
    if want.consistency is None:
        assert got.consistency is None
    else:
        assert got.consistency == pytest.approx(want.consistency, rel=1e-12, abs=1e-15)


@pytest.mark.parametrize("breaks", [[1.0], [-1.2], [np.nan], ["x"]])
def test_prepared_rule_refuses_breaks_outside_the_interval(breaks):
    rule = sie.FunctionalsRule(a=0.4, b=-1.0, n=12, left="bounded", right="bounded")
    with pytest.raises(sie.InvalidBreakpointError):
        rule(np.cos, breaks)
