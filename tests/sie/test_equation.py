"""The equation object, :class:`sie.Equation`: blocks with their own coefficients and kernel
rows, validated once, moved to other intervals by ``on``.

References (tests/reference/manufactured_intervals.py and manufactured.py, which import
nothing from ``sie``): on interval i the equation is

    a_i psi(s) + (b_i/pi) PV int_L psi(t)/(t - s) dt + int_L k_i(s, t) psi(t) dt = f(s),

psi = w_j phi_j on interval j with the exponents of (a_j, b_j) and its end choices, phi_j a
chosen polynomial.  f is built from closed forms: the own interval's a_i psi + b_i H[psi]
= b_i R_i (formula (M2), ``Problem.smooth_part`` of the part built with (a_i, b_i)), the other
intervals' Cauchy integrals by the weight's transform (W) and a regular Gauss-Jacobi sum
(``MultiProblem.cross``, each part with its own exponents), and the kernel term by a
40-node Gauss-Jacobi sum per interval.  The exact Jacobi coefficients of phi_j follow from
the polynomial (``Problem.jacobi_coefficients``), so the solution is checked coefficient by
coefficient.
"""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import manufactured as M
import manufactured_intervals as MI
import sie

INTERVALS = ((-2.0, -0.75), (-0.5, 1.5))


def per_block_problem(coefficients, ends, phis, kernels=(None, None), intervals=INTERVALS):
    """(f, parts): the manufactured right-hand side of blocks with their own coefficients
    and kernel rows, and the manufactured part of each interval."""
    parts = tuple(M.problem(a, b, l, r, p, None)
                  for (a, b), (l, r), p in zip(coefficients, ends, phis))
    base = MI.MultiProblem(0.0, 1.0, intervals, tuple(ends), tuple(phis), None, parts)
    rows = [dataclasses.replace(base, kernel=MI.KERNELS[k]) for k in kernels]

    def f(s):
        s = np.asarray(s, dtype=float)
        flat = s.reshape(-1)
        idx = base.locate(flat)
        assert np.all(idx >= 0), "f evaluated outside L"
        out = np.zeros(flat.shape)
        for i, (a_i, b_i) in enumerate(coefficients):
            sel = idx == i
            if not sel.any():
                continue
            v = np.clip(base.local(i, flat[sel]), -1.0, 1.0)
            val = b_i * parts[i].smooth_part(v)                   # a_i psi + b_i H_own psi
            for j in range(len(parts)):
                if j != i:
                    val = val + b_i * np.array([base.cross(j, x) for x in flat[sel]])
            out[sel] = val + rows[i].kernel_term(flat[sel])
        return out.reshape(s.shape)
    return f, parts


def assert_exact(sol, parts, digits=12):
    for j, P in enumerate(parts):
        c_ex = np.asarray(P.jacobi_coefficients(), dtype=float)
        c = np.asarray(sol.pieces[j].coefficients)
        scale = np.max(np.abs(c_ex))
        assert np.max(np.abs(c[:c_ex.size] - c_ex)) <= 10.0 ** -digits * scale, (j, c, c_ex)
        assert np.max(np.abs(c[c_ex.size:]), initial=0.0) <= 10.0 ** -digits * scale
        assert sol.pieces[j].alpha == pytest.approx(P.alpha, abs=1e-15)
        assert sol.pieces[j].beta == pytest.approx(P.beta, abs=1e-15)


CASES = [
    # (a_i, b_i) per block, ends per block, phi per block
    (((0.5, 1.0), (-2.0, 0.7)), (("bounded", "singular"), ("singular", "bounded")),
     ("poly2", "poly1")),
    (((0.0, 1.0), (3.0, -1.5)), (("singular", "singular"), ("bounded", "singular")),
     ("poly1", "poly3")),
    (((-0.4, 2.0), (0.4, 2.0)), (("singular", "bounded"), ("singular", "singular")),
     ("poly3", "poly2")),
]


@pytest.mark.parametrize("coefficients, ends, phis", CASES)
def test_blocks_with_their_own_coefficients(coefficients, ends, phis):
    """Two intervals whose equations have different (a, b), hence different exponents:
    the coefficients of the polynomial phi_j exactly (to 1e-12 of the largest)."""
    f, parts = per_block_problem(coefficients, ends, phis)
    eq = sie.Equation(a=[c[0] for c in coefficients], b=[c[1] for c in coefficients],
                      left=[e[0] for e in ends], right=[e[1] for e in ends],
                      intervals=INTERVALS)
    assert [blk.a for blk in eq.blocks] == [c[0] for c in coefficients]
    totals = [MI.MultiProblem(0.0, 1.0, INTERVALS, ends, phis, None, parts).integral(j)
              if P.kappa == 1 else None for j, P in enumerate(parts)]
    sol = eq.solve(f, n=8, total=totals)
    assert_exact(sol, parts)
    for name, k in (("a", 0), ("b", 1)):          # one value where the blocks share it
        vals = tuple(c[k] for c in coefficients)
        assert getattr(sol, name) == (vals[0] if len(set(vals)) == 1 else vals)
    # the same through the one-call form
    again = sie.solve(f, a=eq.a.tolist(), b=eq.b.tolist(), n=8, left=[e[0] for e in ends],
                      right=[e[1] for e in ends], intervals=INTERVALS, total=totals)
    for p, q in zip(sol.pieces, again.pieces):
        assert np.array_equal(p.coefficients, q.coefficients)


@pytest.mark.parametrize("kernels", [("0.3exp(st/4)", None), (None, "cos(s-t)/2"),
                                     ("cos(s-t)/2", "0.3exp(st/4)")])
def test_blocks_with_their_own_kernel_rows(kernels):
    """k_i acts on the rows collocated on interval i (s there, t anywhere on L)."""
    coefficients, ends, phis = CASES[0]
    f, parts = per_block_problem(coefficients, ends, phis, kernels)
    rows = [None if k is None else MI.KERNELS[k].f for k in kernels]
    eq = sie.Equation(a=[c[0] for c in coefficients], b=[c[1] for c in coefficients],
                      left=[e[0] for e in ends], right=[e[1] for e in ends],
                      intervals=INTERVALS, kernel=rows)
    assert [blk.kernel for blk in eq.blocks] == rows
    sol = eq.solve(f, n=24)
    assert_exact(sol, parts, digits=11)


def test_a_shared_kernel_is_every_row():
    """One callable is the kernel of every row: the same as giving it per row."""
    k = MI.KERNELS["cos(s-t)/2"].f
    kw = dict(a=[0.5, -2.0], b=[1.0, 0.7], left="bounded", right="singular",
              intervals=INTERVALS)
    one = sie.Equation(kernel=k, **kw).solve(np.cos, n=32)
    rows = sie.Equation(kernel=[k, k], **kw).solve(np.cos, n=32)
    for p, q in zip(one.pieces, rows.pieces):
        assert np.array_equal(p.coefficients, q.coefficients)


def test_on_moves_the_equation_and_keeps_the_rest():
    """on() gives the equation on other intervals: the same as building it there."""
    kw = dict(a=[0.5, -2.0], b=[1.0, 0.7], left=["bounded", "singular"],
              right=["singular", "bounded"])
    eq = sie.Equation(intervals=INTERVALS, **kw)
    other = [(-3.0, -1.0), (0.0, 0.25)]
    moved = eq.on(other)
    fresh = sie.Equation(intervals=other, **kw)
    assert moved.exponents == fresh.exponents == eq.exponents
    assert np.array_equal(moved.intervals, fresh.intervals)
    s1, s2 = moved.solve(np.cos, n=10), fresh.solve(np.cos, n=10)
    for p, q in zip(s1.pieces, s2.pieces):
        assert np.array_equal(p.coefficients, q.coefficients)
    with pytest.raises(sie.PerIntervalArgumentError, match="2 intervals"):
        eq.on([(0.0, 1.0)])
    with pytest.raises(sie.InvalidIntervalError, match="touches"):
        eq.on([(0.0, 1.0), (1.0, 2.0)])
    with pytest.raises(sie.InvalidIntervalError):
        eq.on([("0", 1.0), (2.0, 3.0)])


def test_equation_is_immutable_and_validated_once():
    eq = sie.Equation(a=0.3, b=1.0, left="bounded", right="singular")
    with pytest.raises(AttributeError, match="immutable"):
        eq.a = np.array([1.0])
    with pytest.raises(ValueError):
        eq.a[0] = 1.0                                   # read-only arrays
    with pytest.raises(dataclasses.FrozenInstanceError):
        eq.blocks[0].a = 2.0
    blk, = eq.blocks
    assert (blk.interval.c, blk.interval.d, blk.left, blk.right) == (-1.0, 1.0, "bounded",
                                                                      "singular")
    assert blk.exponents == sie.sie_exponents(0.3, 1.0, "bounded", "singular")
    assert eq.cases is None and eq.kappa == (0,)
    assert "bounded/singular" in repr(eq)


@pytest.mark.parametrize("kw, error, word", [
    (dict(a=[0.1, 0.2, 0.3]), sie.PerIntervalArgumentError, "a must be one value"),
    (dict(b=[1.0, 0.0]), sie.InvalidCoefficientError, "nonzero"),
    (dict(left=["bounded"]), sie.PerIntervalArgumentError, "left must be one value"),
    (dict(kernel=[np.cos]), sie.PerIntervalArgumentError, "kernel must be one value"),
    (dict(kernel=[np.cos, 3.0]), sie.CallableOutputError, r"kernel\[1\]"),
    (dict(kernel="k"), sie.CallableOutputError, "kernel must be a callable"),
])
def test_per_block_arguments_are_checked(kw, error, word):
    base = dict(a=0.3, b=1.0, left="bounded", right="singular", intervals=INTERVALS)
    with pytest.raises(error, match=word):
        sie.Equation(**{**base, **kw})


@pytest.mark.filterwarnings("ignore::sie.ResidualWarning")    # n = 8 on two intervals
@pytest.mark.parametrize("kw", [
    dict(a=[0.5, -2.0], b=[1.0, 0.7], left="bounded", right="singular", intervals=INTERVALS),
    dict(a=[0.2, -0.7], b=1.0, left="singular", right="bounded",
         intervals=[[(-1.0, 1.0)], [(0.0, 2.0)]]),
])
def test_equation_pickles(kw):
    """An equation travels to another process (pickle) and solves there as here."""
    import pickle
    eq = sie.Equation(**kw)
    eq.functionals(np.cos, n=8) if eq.cases else eq.solve(np.cos, n=8)
    again = pickle.loads(pickle.dumps(eq))
    assert again.exponents == eq.exponents and np.array_equal(again.intervals, eq.intervals)
    with pytest.raises(AttributeError, match="immutable"):
        again.cases = 3
    s1, s2 = eq.solve(np.cos, n=8), again.solve(np.cos, n=8)
    c1 = s1.coefficients if eq.cases else np.concatenate(s1.coefficients)
    c2 = s2.coefficients if eq.cases else np.concatenate(s2.coefficients)
    assert np.array_equal(c1, c2)


def test_case_axis_take_keeps_prepared_rules():
    """take() of a case axis carries the rules prepared for an n (no new rule is built)."""
    eq = sie.Equation(a=[0.2, -0.7, 1e3], b=1.0, left="singular", right="bounded",
                      intervals=[[(-1.0, 1.0)], [(0.0, 2.0)], [(3.0, 3.5)]])
    eq.functionals(np.cos, n=12)
    sub = eq.take([2, 0])
    assert sub.cases == 2 and set(sub._prepared) == {12}
    assert np.array_equal(sub.a, [1e3, 0.2])
    with pytest.raises(sie.UnsupportedEquationError, match="case axis"):
        sie.Equation(a=0.2, b=1.0, left="singular", right="bounded").take([0])
