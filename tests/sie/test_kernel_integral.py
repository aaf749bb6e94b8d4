"""sie.Solution.kernel_integral: int_L k(s, t) psi(t) dt, a regular kernel applied to psi.

References:
* closed forms: psi = sqrt(1 - t^2) (the airfoil equation with f = -s) against t^2 and
  e^{s t} (int e^{s t} sqrt(1 - t^2) dt = pi I_1(s) / s, DLMF 10.32.2);
* QUADPACK (scipy.integrate.quad) with the algebraic end weights ``weight="alg"`` on phi
  times the kernel, split at the breaks: a different quadrature of the same integral, for
  solutions with breaks, each kind of end, several intervals and an exponent near -1 (the
  Gauss rule's end mass taken out, :class:`sie.quadrature.WeightedRule`).
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import iv

import sie


def _airfoil():
    return sie.solve(lambda s: -s, a=0.0, b=1.0, n=4, left="bounded", right="bounded")


def test_closed_forms():
    sol = _airfoil()
    s = np.array([-2.0, 0.5, 3.0])
    got = sol.kernel_integral(lambda s, t: np.exp(s * t), s)
    assert np.allclose(got, np.pi * iv(1, s) / s, rtol=1e-14, atol=0)
    got = sol.kernel_integral(lambda s, t: s * t ** 2, s.reshape(3, 1))
    assert got.shape == (3, 1)
    assert np.allclose(got.ravel(), s * np.pi / 8, rtol=1e-14)


def _reference(sol, k, x, cuts):
    """int_L k(x, t) psi(t) dt by QUADPACK: on each interval, phi k times the weight's
    factors, the end one as quad's algebraic weight, split at ``cuts`` (real points)."""
    total = 0.0
    for j, (c, d) in enumerate(sol.intervals):
        piece = sol.pieces[j]
        a, b = piece.alpha, piece.beta
        h, m = 0.5 * (d - c), 0.5 * (c + d)
        pts = [c] + [u for u in cuts if c < u < d] + [d]
        for lo, hi in zip(pts[:-1], pts[1:]):
            def g(t, lo=lo, hi=hi):
                u = min(max((t - m) / h, -1.0), 1.0)
                val = k(x, t) * piece.phi_local(np.array([u]))[0]
                if lo != c:
                    val *= (1.0 + u) ** b
                if hi != d:
                    val *= (1.0 - u) ** a
                return val
            # the weight's end factors in units of the local coordinate: (t - c)^b / h^b ...
            wl, wr = (b if lo == c else 0.0), (a if hi == d else 0.0)
            scale = h ** -(wl + wr)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                total += scale * quad(g, lo, hi, weight="alg", wvar=(wl, wr), epsabs=1e-15,
                                      epsrel=1e-14, limit=400)[0]
    return total


def _kinked(s):
    return np.abs(s - 0.3) + 0.2 * s


@pytest.mark.parametrize("left,right", [("bounded", "bounded"), ("singular", "bounded"),
                                        ("bounded", "singular"), ("singular", "singular")])
def test_with_breaks_against_quadpack(left, right):
    total = 1.0 if left == right == "singular" else None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.InconsistentEquationWarning)
        sol = sie.solve(_kinked, a=0.4, b=1.0, n=24, left=left, right=right, breaks=[0.3],
                        total=total)
    k = lambda s, t: np.cos(s - 2.0 * t) * np.exp(t)          # noqa: E731
    s = np.array([-3.0, 0.1, 0.7, 5.0])
    got = sol.kernel_integral(k, s)
    ref = np.array([_reference(sol, k, x, [0.3]) for x in s])
    assert np.max(np.abs(got - ref)) <= 1e-13 * np.max(np.abs(ref))


def test_several_intervals_against_quadpack():
    sol = sie.solve(lambda s: np.sin(s), a=0.3, b=1.0, n=12, left=["singular", "bounded"],
                    right=["bounded", "singular"], intervals=[(-2.0, -0.5), (0.4, 1.7)])
    k = lambda s, t: 1.0 / (1.0 + (s - t) ** 2)                 # noqa: E731
    s = np.array([-1.0, 0.0, 1.0])
    got = sol.kernel_integral(k, s)
    ref = np.array([_reference(sol, k, x, []) for x in s])
    assert np.max(np.abs(got - ref)) <= 1e-13 * np.max(np.abs(ref))


def test_exponent_near_minus_one():
    """alpha + 1 = 2e-3 (the rule's end mass split off): psi's integral is ~1/(alpha + 1)
    and the kernel's integral keeps its relative digits."""
    b_over_a = np.tan(np.pi * 2e-3) * -1.0
    sol = sie.solve(np.ones_like, a=1.0, b=b_over_a, n=6, left="bounded", right="singular")
    assert sol.alpha + 1.0 < 0.01
    k = lambda s, t: np.exp(-s * t)                               # noqa: E731
    s = np.array([0.5, 2.0])
    got = sol.kernel_integral(k, s)
    ref = np.array([_reference(sol, k, x, []) for x in s])
    assert np.allclose(got, ref, rtol=1e-12, atol=0)
    assert sol.kernel_integral(lambda s, t: 1.0 + 0 * s, np.array([0.0]))[0] == \
        pytest.approx(sol.integral(), rel=1e-13)


def test_nodes_converge():
    """A kernel with structure on a short scale: more nodes, the QUADPACK value."""
    sol = _airfoil()
    k = lambda s, t: np.cos(40.0 * (t - s))                       # noqa: E731
    ref = _reference(sol, k, 0.2, [])
    few = sol.kernel_integral(k, np.array([0.2]), nodes=8)[0]
    many = sol.kernel_integral(k, np.array([0.2]), nodes=64)[0]
    assert abs(many - ref) < 1e-14 < abs(few - ref)


@pytest.mark.parametrize("kernel,error", [
    (lambda s, t: np.zeros(3), sie.CallableOutputError),
    (lambda s, t: np.full(np.shape(s), np.nan), sie.CallableOutputError),
    (lambda s, t: 1j * s, sie.CallableOutputError),
    ("k", sie.CallableOutputError)])
def test_bad_kernels(kernel, error):
    with pytest.raises(error, match="kernel"):
        _airfoil().kernel_integral(kernel, np.array([0.0, 1.0]))


@pytest.mark.parametrize("s,nodes,error", [
    (np.array([1j]), None, sie.EvaluationPointError),
    (np.array([np.inf]), None, sie.EvaluationPointError),
    (np.array([0.0]), 0, sie.InvalidOrderError),
    (np.array([0.0]), 2.5, sie.InvalidOrderError),
    (np.array([0.0]), True, sie.InvalidOrderError)])
def test_bad_points_and_nodes(s, nodes, error):
    with pytest.raises(error):
        _airfoil().kernel_integral(lambda s, t: s + t, s, nodes=nodes)
