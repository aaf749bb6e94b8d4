"""sie.jacobi: Jacobi series, Vandermonde matrices, projections and norms.

References: scipy.special.eval_jacobi (hypergeometric evaluation, independent of our
recurrence) for values, mpmath quadrature at 30 digits for the norms (DLMF Table 18.3.1 is
what the code uses, so the integral is the independent check).
"""
from __future__ import annotations

import numpy as np
import pytest
from mpmath import mp, mpf, quad
from scipy.special import eval_jacobi

from sie.jacobi import _BLOCK, jacobi_norms, jacobi_project, jacobi_series, jacobi_vandermonde

PARAMS = [(0.0, 0.0), (-0.4, -0.6), (0.3, -0.7), (-0.99, 0.99), (2.5, 0.5)]


def reference_vandermonde(n, a, b, x):
    return np.array([[eval_jacobi(k, a, b, xi) for k in range(n)] for xi in x]).reshape(len(x), n)


@pytest.mark.parametrize("a,b", PARAMS)
def test_vandermonde_matches_scipy_eval_jacobi(a, b):
    x = np.concatenate([np.linspace(-1.0, 1.0, 21), [-1.3, 1.05, 2.0]])   # inside, ends, outside
    n = 12
    V = jacobi_vandermonde(n, a, b, x)
    ref = reference_vandermonde(n, a, b, x)
    scale = np.maximum(1.0, np.abs(ref))
    assert np.max(np.abs(V - ref) / scale) <= 5e-14


@pytest.mark.parametrize("a,b", PARAMS)
def test_series_and_projection_span_several_blocks(a, b):
    """m * n well above one block: the blocked BLAS products equal the dense ones."""
    rng = np.random.default_rng(3)
    n = 40
    m = 3 * _BLOCK // n + 7                      # four blocks, the last one partial
    x = rng.uniform(-1.0, 1.0, m)
    c = rng.standard_normal(n) / (1.0 + np.arange(n)) ** 2
    pick = np.arange(0, m, 97)                   # points from every block
    V = reference_vandermonde(n, a, b, x[pick])
    np.testing.assert_allclose(jacobi_series(c, a, b, x)[pick], V @ c, rtol=1e-12, atol=1e-13)
    v = rng.standard_normal(m)
    dense = v @ jacobi_vandermonde(n, a, b, x)
    np.testing.assert_allclose(jacobi_project(v, a, b, x, n), dense, rtol=1e-12,
                               atol=1e-12 * np.max(np.abs(dense)))


def test_series_keeps_the_shape_of_x():
    c = np.array([1.0, 0.5, 0.25])
    x = np.linspace(-0.9, 0.9, 12).reshape(3, 4)
    out = jacobi_series(c, 0.2, -0.3, x)
    assert out.shape == (3, 4)
    np.testing.assert_allclose(out.ravel(), jacobi_series(c, 0.2, -0.3, x.ravel()), rtol=0, atol=0)


def test_empty_inputs():
    x = np.linspace(-1.0, 1.0, 3)
    assert jacobi_vandermonde(0, 0.1, 0.2, x).shape == (3, 0)
    np.testing.assert_array_equal(jacobi_series([], 0.1, 0.2, x), np.zeros(3))
    assert jacobi_project(np.ones(3), 0.1, 0.2, x, 0).shape == (0,)
    assert jacobi_series([2.0], 0.1, 0.2, np.array([])).shape == (0,)


@pytest.mark.parametrize("a,b", [(-0.4, -0.6), (0.3, -0.7), (-0.9, 0.5)])
@pytest.mark.slow
def test_norms_match_quadrature(a, b):
    n = 6
    h = jacobi_norms(n, a, b)
    with mp.workdps(30):
        A, B = mpf(a), mpf(b)
        for k in range(n):
            # u = distance to the nearer end = v^(1/(e+1)): int_0^1 u^e g(u) du
            # = int_0^1 g(v^(1/(e+1))) dv / (e+1), a smooth integrand for tanh-sinh
            def half(e_near, e_far, sign):
                def g(v):
                    u = v ** (1 / (e_near + 1))
                    return (2 - u) ** e_far * mp.jacobi(k, A, B, sign * (1 - u)) ** 2
                return quad(g, [0, 1]) / (e_near + 1)
            ref = half(B, A, -1) + half(A, B, +1)
            assert abs(h[k] / float(ref) - 1.0) <= 1e-13, (k, h[k], ref)
