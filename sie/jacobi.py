"""Jacobi polynomials P_k^{(a,b)}: series evaluation, Vandermonde matrices,
discrete projections and norms (one numba kernel + thin wrappers).

Standard normalisation throughout (as ``scipy.special.eval_jacobi``):
P_k(1) = (a+1)_k / k!, recurrence DLMF 18.9.1-2, norms DLMF Table 18.3.1.
"""
from __future__ import annotations

import functools

import numpy as np

from ._jit import jit
from .special import _jacobi_norm

__all__ = ["jacobi_series", "jacobi_vandermonde", "jacobi_project", "jacobi_norms",
           "jacobi_norms_cached", "plateau_start", "recurrence_coefficients"]


@jit()
def _vandermonde_into(a, b, x, V):
    """V[i, k] = P_k^{(a,b)}(x_i), k < V.shape[1], by the recurrence DLMF 18.9.1-2:
    P_{k+1} = (A_k x + B_k) P_k - C_k P_{k-1},  s = 2k + a + b,
    A_k = (s+1)(s+2)s/d,  B_k = (s+1)(a^2-b^2)/d,  C_k = 2(k+a)(k+b)(s+2)/d,
    d = 2(k+1)(k+a+b+1)s.

    Filled in place, so that one body serves real exponents (V float) and complex ones
    (V complex: the exponents of a system's modes, :mod:`sie.systems`).  The only compiled
    kernel of this module: series and projections are BLAS products with blocks of V (see
    ``_BLOCK``), which keeps the number of kernels a first call must compile small (each
    costs ~0.2 s).
    """
    m, n = V.shape
    if n == 0:
        return V
    for i in range(m):
        V[i, 0] = 1.0
    if n > 1:
        # a + b + 2 as (a+1) + (b+1): no cancellation when both exponents are near -1
        ap1 = a + 1.0
        abp2 = ap1 + (b + 1.0)
        for i in range(m):
            V[i, 1] = ap1 + 0.5 * abp2 * (x[i] - 1.0)
        for k in range(1, n - 1):
            s = 2.0 * (k - 1) + abp2
            d = 2.0 * (k + 1) * ((k - 1) + abp2) * s
            A = (s + 1.0) * (s + 2.0) * s / d
            B = (s + 1.0) * (a * a - b * b) / d
            C = 2.0 * (k + a) * (k + b) * (s + 2.0) / d
            for i in range(m):
                V[i, k + 1] = (A * x[i] + B) * V[i, k] - C * V[i, k - 1]
    return V


def recurrence_coefficients(a, b, J):
    """A_k, B_k, C_k (arrays, k = 1..J-1) of P_{k+1} = (A_k x + B_k) P_k - C_k P_{k-1}, DLMF
    18.9.1-2, as :func:`_vandermonde_into` forms them (a + b + 2 as (a + 1) + (b + 1)); real
    or complex a, b: for the recurrences outside the kernel (divided differences, functions
    of the second kind)."""
    k = np.arange(1, J, dtype=float)
    abp2 = (a + 1.0) + (b + 1.0)
    s = 2.0 * (k - 1) + abp2
    d = 2.0 * (k + 1) * ((k - 1) + abp2) * s
    return ((s + 1.0) * (s + 2.0) * s / d, (s + 1.0) * (a * a - b * b) / d,
            2.0 * (k + a) * (k + b) * (s + 2.0) / d)


def _parameter(a):
    """A Jacobi parameter as the kernel takes it: float, or complex when it has an
    imaginary part (a real one stays on the float kernel, the common and faster case)."""
    if isinstance(a, complex):            # numpy's complex types too
        return complex(a) if a.imag else float(a.real)
    return float(a)


def _vandermonde(n, a, b, x):
    """:func:`_vandermonde_into` into a new matrix (complex when a or b is)."""
    a, b = _parameter(a), _parameter(b)
    if type(a) is float and type(b) is float:
        return _vandermonde_into(a, b, x, np.empty((x.shape[0], n)))
    return _vandermonde_into(complex(a), complex(b), x,
                             np.empty((x.shape[0], n), dtype=complex))


@jit()
def plateau_start(c, scale, factor, run):
    """First k such that |c_j| scale_j <= factor * max_i |c_i| scale_i for j = k .. k+run-1,
    or len(c) when there is no such run (the start of a series' rounding-noise plateau)."""
    n = c.shape[0]
    top = 0.0
    for k in range(n):
        top = max(top, abs(c[k]) * scale[k])
    tol = factor * top
    count = 0
    for k in range(n):
        if abs(c[k]) * scale[k] <= tol:
            count += 1
            if count == run:
                return k - run + 1
        else:
            count = 0
    return n


_BLOCK = 1 << 16  # entries of one Vandermonde block (512 KiB): memory stays O(n) per point


def _blocks(n, m):
    """Row slices of an m-by-n Vandermonde matrix, each at most ``_BLOCK`` entries."""
    rows = max(1, _BLOCK // max(n, 1))
    return (slice(i, min(i + rows, m)) for i in range(0, m, rows))


@jit()
def _jacobi_norms(n, a, b):
    """h_k, k = 0..n-1: h_0 and h_1 in closed form, the rest from h_1 by the ratios
    h_{k+1}/h_k (DLMF Table 18.3.1), multiplied up in order.  Compiled: the contact layer
    asks for the norms of every new pair of exponents (a handful of numpy calls on
    arrays of two or six entries cost ~20 us; the kernel ~1 us)."""
    h = np.zeros(n)
    if n == 0:
        return h
    h[0] = _jacobi_norm(0, a, b)
    if n > 1:
        h1 = _jacobi_norm(1, a, b)
        h[1] = h1
        prod = 1.0
        for k in range(1, n - 1):
            s = 2.0 * k + a + b
            prod *= (s + 1.0) * (k + a + 1.0) * (k + b + 1.0) / (
                (s + 3.0) * (k + a + b + 1.0) * (k + 1.0))
            h[k + 1] = h1 * prod
    return h


def _f64(x):
    """C-contiguous, writeable float64: one numba specialisation per kernel (a read-only
    array, e.g. a memoised Gauss rule, is a different numba type and would compile again)."""
    x = np.ascontiguousarray(x, dtype=float)
    return x if x.flags.writeable else x.copy()


def jacobi_series(c, a, b, x):
    """Evaluate sum_k c[k] P_k^{(a,b)}(x) at the points x (any real x).

    Parameters
    ----------
    c : array_like
        Coefficients, in the standard normalisation of P_k^{(a,b)} (as
        ``scipy.special.eval_jacobi``: P_k(1) = (a+1)_k / k!).
    a, b : float or complex
        Jacobi parameters (not checked; the recurrence needs a + b + 2 != 0 and no
        vanishing denominator, as for a, b > -1 or real parts > -1).  Complex parameters
        or coefficients give a complex result (the modes of :mod:`sie.systems`).
    x : array_like
        Points, any shape.

    Returns
    -------
    ndarray
        The series at x, of x's shape.

    Notes
    -----
    The three-term recurrence DLMF 18.9.1-2, summed in blocks (BLAS products with blocks
    of the Vandermonde matrix, memory O(len(c)) per point).

    References
    ----------
    NIST DLMF, sec. 18.9 (recurrence) and Table 18.6.1 (P_k(1)).

    Examples
    --------
    P_2^{(0,0)}(x) = (3 x^2 - 1) / 2, the Legendre polynomial:

    >>> import sie
    >>> [round(float(v), 12) for v in sie.jacobi_series([0.0, 0.0, 1.0], 0.0, 0.0, [0.5, 1.0])]
    [-0.125, 1.0]
    """
    x = np.asarray(x, dtype=float)
    cplx = np.iscomplexobj(c) or type(_parameter(a)) is complex \
        or type(_parameter(b)) is complex
    c = np.ascontiguousarray(c, dtype=complex) if cplx else _f64(c)
    xf = _f64(x.ravel())
    out = np.zeros(xf.size, dtype=c.dtype)
    if c.size:
        for rows in _blocks(c.size, xf.size):
            out[rows] = _vandermonde(c.size, a, b, xf[rows]) @ c
    return out.reshape(x.shape)


def jacobi_vandermonde(n, a, b, x):
    """Matrix V[i, k] = P_k^{(a,b)}(x_i), k = 0..n-1 (complex when a or b is)."""
    return _vandermonde(int(n), a, b, _f64(x))


def jacobi_project(v, a, b, x, n):
    """Vector sum_i v_i P_k^{(a,b)}(x_i), k = 0..n-1 (in blocks: no n-by-len(x) matrix)."""
    v = _f64(v)
    x = _f64(x)
    n = int(n)
    out = np.zeros(n)
    if n:
        for rows in _blocks(n, x.size):
            out += v[rows] @ _vandermonde(n, a, b, x[rows])
    return out


def jacobi_norms(n, a, b):
    """h_k = int (1-x)^a (1+x)^b P_k^{(a,b)}(x)^2 dx, k = 0..n-1 (a fresh array).

    Parameters
    ----------
    n : int
        Number of norms.
    a, b : float
        Jacobi parameters, both > -1.

    Returns
    -------
    ndarray, shape (n,)
        h_0 = 2^{a+b+1} B(a+1, b+1) and, for k >= 1,
        h_k = 2^{a+b+1} Gamma(k+a+1) Gamma(k+b+1) / ((2k+a+b+1) Gamma(k+a+b+1) k!).

    Raises
    ------
    ValueError
        a or b <= -1.

    References
    ----------
    NIST DLMF, Table 18.3.1.

    Examples
    --------
    Legendre (a = b = 0): h_k = 2 / (2k + 1).

    >>> import sie
    >>> [round(float(h), 12) for h in sie.jacobi_norms(3, 0.0, 0.0)]
    [2.0, 0.666666666667, 0.4]
    """
    return jacobi_norms_cached(int(n), float(a), float(b)).copy()


@functools.lru_cache(maxsize=512)
def jacobi_norms_cached(n, a, b):
    """:func:`jacobi_norms`, memoised and read-only."""
    # memoised: the contact layer re-solves equations of the same exponents many times
    if not (a > -1.0 and b > -1.0):
        raise ValueError(f"jacobi_norms needs a, b > -1, got {a!r}, {b!r}")
    h = _jacobi_norms(n, a, b)
    h.flags.writeable = False
    return h
