"""Jacobi polynomials P_k^{(a,b)}: series evaluation, Vandermonde matrices,
discrete projections and norms (numba kernels + thin wrappers).

Standard normalisation throughout (as ``scipy.special.eval_jacobi``):
P_k(1) = (a+1)_k / k!, recurrence DLMF 18.9.1-2, norms DLMF Table 18.3.1.
"""
from __future__ import annotations

import functools

import numpy as np

from ._jit import jit
from .special import jacobi_norm

__all__ = ["jacobi_series", "jacobi_vandermonde", "jacobi_project", "jacobi_norms"]


@jit(inline="always")
def _step(k, a, b):
    """Coefficients of P_{k+1} = (A x + B) P_k - C P_{k-1}, k >= 1 (DLMF 18.9.2)."""
    s = 2.0 * k + a + b
    d = 2.0 * (k + 1) * (k + a + b + 1.0) * s
    A = (s + 1.0) * (s + 2.0) * s / d
    B = (s + 1.0) * (a * a - b * b) / d
    C = 2.0 * (k + a) * (k + b) * (s + 2.0) / d
    return A, B, C


@jit()
def _series(c, a, b, x):
    """sum_k c_k P_k^{(a,b)}(x_i) by forward recurrence (O(len(c)) per point)."""
    n = c.shape[0]
    out = np.zeros(x.shape[0])
    if n == 0:
        return out
    for i in range(x.shape[0]):
        xi = x[i]
        p_prev = 1.0
        acc = c[0]
        if n > 1:
            p = (a + 1.0) + 0.5 * (a + b + 2.0) * (xi - 1.0)
            acc += c[1] * p
            for k in range(1, n - 1):
                A, B, C = _step(k, a, b)
                nxt = (A * xi + B) * p - C * p_prev
                p_prev = p
                p = nxt
                acc += c[k + 1] * p
        out[i] = acc
    return out


@jit()
def _vandermonde(n, a, b, x):
    """V[i, k] = P_k^{(a,b)}(x_i), k < n."""
    m = x.shape[0]
    V = np.empty((m, n))
    for i in range(m):
        V[i, 0] = 1.0
    if n > 1:
        for i in range(m):
            V[i, 1] = (a + 1.0) + 0.5 * (a + b + 2.0) * (x[i] - 1.0)
        for k in range(1, n - 1):
            A, B, C = _step(k, a, b)
            for i in range(m):
                V[i, k + 1] = (A * x[i] + B) * V[i, k] - C * V[i, k - 1]
    return V


@jit()
def _project(v, a, b, x, n):
    """out[k] = sum_i v_i P_k^{(a,b)}(x_i), k < n, in O(n) memory."""
    out = np.zeros(n)
    for i in range(x.shape[0]):
        xi = x[i]
        vi = v[i]
        p_prev = 1.0
        out[0] += vi
        if n > 1:
            p = (a + 1.0) + 0.5 * (a + b + 2.0) * (xi - 1.0)
            out[1] += vi * p
            for k in range(1, n - 1):
                A, B, C = _step(k, a, b)
                nxt = (A * xi + B) * p - C * p_prev
                p_prev = p
                p = nxt
                out[k + 1] += vi * p
    return out


def _norm_ratios(n, a, b, h1):
    """h_k for k = 1..n-1 from h_1 by h_{k+1}/h_k (DLMF Table 18.3.1); a cumulative
    product in numpy (no compiled kernel needed)."""
    h = np.zeros(n)
    if n > 1:
        k = np.arange(1, n - 1, dtype=float)
        s = 2.0 * k + a + b
        ratio = (s + 1.0) * (k + a + 1.0) * (k + b + 1.0) / ((s + 3.0) * (k + a + b + 1.0) * (k + 1.0))
        h[1] = h1
        h[2:] = h1 * np.cumprod(ratio)
    return h


def _f64(x):
    """C-contiguous, writeable float64: one numba specialisation per kernel (a read-only
    array, e.g. a memoised Gauss rule, is a different numba type and would compile again)."""
    x = np.ascontiguousarray(x, dtype=float)
    return x if x.flags.writeable else x.copy()


def jacobi_series(c, a, b, x):
    """Evaluate sum_k c[k] P_k^{(a,b)}(x) at the points x (any real x)."""
    x = np.asarray(x, dtype=float)
    return _series(_f64(c), float(a), float(b), _f64(x.ravel())).reshape(x.shape)


def jacobi_vandermonde(n, a, b, x):
    """Matrix V[i, k] = P_k^{(a,b)}(x_i), k = 0..n-1."""
    return _vandermonde(int(n), float(a), float(b), _f64(x))


def jacobi_project(v, a, b, x, n):
    """Vector sum_i v_i P_k^{(a,b)}(x_i), k = 0..n-1 (no n-by-len(x) matrix is formed)."""
    return _project(_f64(v), float(a), float(b), _f64(x), int(n))


def jacobi_norms(n, a, b):
    """h_k = int (1-x)^a (1+x)^b P_k^{(a,b)}(x)^2 dx, k = 0..n-1 (a fresh array)."""
    return _jacobi_norms_cached(int(n), float(a), float(b)).copy()


@functools.lru_cache(maxsize=512)
def _jacobi_norms_cached(n, a, b):
    # memoised: the contact layer re-solves equations of the same exponents many times
    h = _norm_ratios(n, a, b, jacobi_norm(1, a, b) if n > 1 else 0.0)
    h[0] = jacobi_norm(0, a, b)
    h.flags.writeable = False
    return h
