"""Compiled kernels of the Cauchy transform F_k(z) = (1/pi) int w P_k^{(a,b)} / (t - z) dt
(:mod:`sie.cauchy` explains the method): F_0 in closed form and the three-term recurrence

    F_1 = P_1(z) F_0 + A_0 mu_0 / pi,     F_{k+1} = (A_k z + B_k) F_k - C_k F_{k-1}  (k >= 1)

(the recurrence of P_k, DLMF 18.9.1-2).  Per point z the recurrence runs

* **forward** from F_0 in closed form where the dominant solution ~|rho|^k cannot amplify
  rounding beyond the caller's limit log|rho| <= ``lr_max`` (and only inside a box around
  the interval, where the closed form has no cancellation);
* **backward** elsewhere (Miller's algorithm: y_K = 0, y_{K-1} = 1, K chosen so that
  |rho|^{-2(K-n)} < 1e-17, normalised through F_0 = A_0 mu_0 y_0 / (pi (y_1 - P_1(z) y_0));
  Gautschi, SIAM Rev. 9 (1967) 24).

Two drivers: :func:`basis_kernel` stores every F_k (the coupling blocks of the solver; few
points), :func:`series_kernel` sums sum_k c_k F_k (many points).  The latter runs the
recurrence for ``_LANES`` points at once, lane-wise: one point's recurrence is a chain of
dependent complex multiplications that runs at the latency of that chain, while the
independent lanes overlap in the processor's pipeline (Miller's points are
ordered by their start K so that a lane group shares it).

The points come with z - 1 and z + 1 (``zm1``, ``zp1``) formed by the caller from the real
coordinate, so that the distance to a nearby end keeps full relative precision in F_0.
``p`` holds the closed form's parameters (see :func:`f0_parameters` in :mod:`sie.cauchy`):
m = alpha + beta, alpha, 1 - alpha, sin(pi alpha), shifted (0/1), M_1, mu_0, 1 + alpha.
"""
from __future__ import annotations

import cmath
import math

import numpy as np

from ._jit import jit

__all__ = ["basis_kernel", "series_kernel", "f0_points", "series_forward_limit"]

_LANES = 8
_HUGE = 1e30       # |z| beyond this: F_k = 0 for k >= 1 and F_0 = -mu_0/(pi z), to 1/|z|
_RESCALE = 1e200   # Miller's values are scaled down past this (headroom for growth)
_BOX_RE, _BOX_IM = 1.3, 0.8   # |rho| <= 2 lies inside |Re z| < 1.25, |Im z| < 0.75


@jit()
def _expm1c(w):
    """expm1 of complex w without cancellation: expm1(x) cos y - 2 sin^2(y/2) + i e^x sin y."""
    x, y = w.real, w.imag
    s = math.sin(0.5 * y)
    return complex(math.expm1(x) * math.cos(y) - 2.0 * s * s, math.exp(x) * math.sin(y))


@jit()
def _f0(z, zm1, zp1, p):
    """F_0(z) in closed form (z off [-1, 1]; real z inside: the upper limit F_0(x + i0)).

    With L = log((z-1)/(z+1)) (principal; log((1-x)/(1+x)) + i pi on the cut from above):
        m = -1:  F_0 = e^{alpha L} / ((z+1) sin(pi alpha)),
        m =  0:  F_0 = expm1(alpha L) / sin(pi alpha),
        m =  1:  F_0 = [(z+1) expm1(alpha L) + 2 alpha] / sin(pi alpha)        (alpha <= 1/2)
                     = [(z-1) expm1(-(1-alpha) L) - 2 (1-alpha)] / sin(pi alpha)  (alpha > 1/2).
    Shifted (the weight with both exponents raised by one): (1 - z^2) F_0 - (M_1 + z mu_0)/pi,
    where (1 - z^2) F_0 -> 0 at an end.

    sin(pi alpha) is exact (``p[3]``), and so must be the part of e^{alpha L} that it
    divides: on the cut, Im e^{alpha L} = e^{alpha Re L} sin(pi alpha) made from alpha as
    rounded, whose distance to an integer r = +-1 has an absolute error of half an ulp, a
    relative error of ~1e-16 / |alpha - r| (2e-4 at |alpha - r| = 3e-13).  Near r = +-1,
    e^{alpha L} = ((z-1)/(z+1))^r e^{(alpha - r) L} with alpha - r carried exactly (1 + alpha,
    ``p[7]``; -(1 - alpha), ``p[2]``) instead."""
    m, alpha, am1, sn = p[0], p[1], p[2], p[3]
    at_end = zm1 == 0.0 or zp1 == 0.0
    f0 = 0j
    if not at_end:
        if z.imag == 0.0 and zm1.real < 0.0 and zp1.real > 0.0:
            L = complex(math.log(-zm1.real) - math.log(zp1.real), math.pi)
        else:
            L = cmath.log(zm1 / zp1)
        if m > 0.5:
            if alpha <= 0.5:
                num = zp1 * _expm1c(alpha * L) + 2.0 * alpha
            else:
                num = zm1 * _expm1c(-am1 * L) - 2.0 * am1
        elif abs(alpha) <= 0.5:
            num = cmath.exp(alpha * L) / zp1 if m < -0.5 else _expm1c(alpha * L)
        else:
            if alpha < 0.0:                  # e^{alpha L} = e^{(1 + alpha) L} (z+1)/(z-1)
                e = cmath.exp(p[7] * L) * (zp1 / zm1)
            else:                            # e^{alpha L} = e^{-(1 - alpha) L} (z-1)/(z+1)
                e = cmath.exp(-am1 * L) * (zm1 / zp1)
            num = e / zp1 if m < -0.5 else e - 1.0
        f0 = num / sn
    if p[4] != 0.0:
        return -(zm1 * zp1) * f0 - (p[5] + z * p[6]) / math.pi
    return f0


@jit()
def f0_points(z, zm1, zp1, p, out):
    """F_0 at every point (see :func:`_f0`)."""
    for i in range(z.shape[0]):
        out[i] = _f0(z[i], zm1[i], zp1[i], p)
    return out


@jit()
def _coefficients(kmax, a, b):
    """A_k, B_k, C_k and 1/C_k for k = 1..kmax (DLMF 18.9.2; a + b + 2 formed as
    (a + 1) + (b + 1))."""
    abp2 = (a + 1.0) + (b + 1.0)
    Ak = np.zeros(kmax + 1)
    Bk = np.zeros(kmax + 1)
    Ck = np.zeros(kmax + 1)
    iC = np.zeros(kmax + 1)
    for k in range(1, kmax + 1):
        s = 2.0 * (k - 1) + abp2
        d = 2.0 * (k + 1) * ((k - 1) + abp2) * s
        Ak[k] = (s + 1.0) * (s + 2.0) * s / d
        Bk[k] = (s + 1.0) * (a * a - b * b) / d
        Ck[k] = 2.0 * (k + a) * (k + b) * (s + 2.0) / d
        iC[k] = 1.0 / Ck[k]
    return Ak, Bk, Ck, iC


@jit()
def _setup(n, a, b, mu0, lr_max, z):
    """What both drivers need: A_0, B_0 and c0 = A_0 mu_0 / pi of F_1 = P_1(z) F_0 + c0, the
    start K per point (:func:`_starts`) and the recurrence coefficients up to max(n, K)."""
    ap1 = a + 1.0
    A0 = 0.5 * (ap1 + (b + 1.0))
    B0 = ap1 - A0
    c0 = A0 * mu0 / math.pi
    K = _starts(n, lr_max, z)
    Ak, Bk, Ck, iC = _coefficients(max(n, K.max()), a, b)
    return A0, B0, c0, K, Ak, Bk, Ck, iC


@jit()
def _starts(n, lr_max, z):
    """K per point: 0 for the forward recurrence, -1 for |z| > _HUGE (F_0 ~ -mu_0/(pi z):
    the recurrence could overflow between two rescalings there), else Miller's start."""
    m = z.shape[0]
    K = np.zeros(m, dtype=np.int64)
    for i in range(m):
        zr, zi = z[i].real, z[i].imag
        if abs(zr) + abs(zi) > _HUGE:
            K[i] = -1
            continue
        # |rho| from the Bernstein ellipse through z: |z - 1| + |z + 1| = rho + 1/rho
        a = 0.5 * (math.hypot(zr - 1.0, zi) + math.hypot(zr + 1.0, zi))
        lr = math.log(a + math.sqrt((a - 1.0) * (a + 1.0))) if a > 1.0 else 0.0
        near = abs(zr) < _BOX_RE and abs(zi) < _BOX_IM and lr <= lr_max
        if not near and lr > 0.0:
            K[i] = n + int(math.ceil(39.2 / (2.0 * lr))) + 2
    return K


@jit()
def _miller_point(i, n, K, z, Ak, Bk, iC, A0, B0, c0, V):
    """Miller's recurrence for one point into V[i, :n] (z real or complex: numba compiles
    both, and a real z off the interval runs in real arithmetic), rescaled against
    overflow."""
    y_next = 0.0 * z          # y_{k+1}
    y = 1.0 + 0.0 * z         # y_k, k = K - 1
    for k in range(K - 1, 0, -1):
        if k < n:
            V[i, k] = y
        y_prev = ((Ak[k] * z + Bk[k]) * y - y_next) * iC[k]
        y_next = y
        y = y_prev
        if abs(y.real) + abs(y.imag) > _RESCALE:     # rescale: only ratios matter
            y /= _RESCALE
            y_next /= _RESCALE
            for j in range(k, n):
                V[i, j] /= _RESCALE
    V[i, 0] = y
    scale = c0 / (y_next - (A0 * z + B0) * y)     # F_0 / y_0
    for k in range(n):
        V[i, k] *= scale


@jit()
def basis_kernel(n, a, b, mu0, lr_max, z, zm1, zp1, p, V):
    """V[i, k] = F_k(z_i), k < n."""
    A0, B0, c0, K, Ak, Bk, Ck, iC = _setup(n, a, b, mu0, lr_max, z)
    for i in range(z.shape[0]):
        zz = z[i]
        if K[i] < 0:
            V[i, 0] = -mu0 / (math.pi * zz)
            for k in range(1, n):
                V[i, k] = 0.0
            continue
        if K[i] > 0:
            if zz.imag == 0.0:
                _miller_point(i, n, K[i], zz.real, Ak, Bk, iC, A0, B0, c0, V)
            else:
                _miller_point(i, n, K[i], zz, Ak, Bk, iC, A0, B0, c0, V)
            continue
        f_prev = _f0(zz, zm1[i], zp1[i], p)
        V[i, 0] = f_prev
        if n > 1:
            f = (A0 * zz + B0) * f_prev + c0
            V[i, 1] = f
            for k in range(1, n - 1):
                f_next = (Ak[k] * zz + Bk[k]) * f - Ck[k] * f_prev
                V[i, k + 1] = f_next
                f_prev = f
                f = f_next
    return V


@jit()
def _order_by_start(K):
    """Indices of the points in ascending K (a counting sort: K takes few values): those
    with K = -1, then the forward ones (K = 0), then the backward ones; and where the
    forward and the backward ones start."""
    m = K.shape[0]
    kmax = 0
    for i in range(m):
        kmax = max(kmax, K[i])
    count = np.zeros(kmax + 3, dtype=np.int64)
    for i in range(m):
        count[K[i] + 2] += 1
    for k in range(1, kmax + 3):
        count[k] += count[k - 1]
    first_fwd = count[1]
    first_bwd = count[2]
    order = np.empty(m, dtype=np.int64)
    for i in range(m):
        order[count[K[i] + 1]] = i
        count[K[i] + 1] += 1
    return order, first_fwd, first_bwd


@jit()
def _forward_lanes(idx, n, z, zm1, zp1, p, A0, B0, c0, Ak, Bk, Ck, c, out, w):
    """sum_k c_k F_k forward from F_0 for the points idx (at most _LANES; the lanes are
    filled by repeating the last point)."""
    L = w.shape[1]
    cnt = idx.shape[0]
    xr, xi, pr, pi_, fr, fi, ar, ai = w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]
    for j in range(L):
        i = idx[min(j, cnt - 1)]
        xr[j] = z[i].real
        xi[j] = z[i].imag
        f0 = _f0(z[i], zm1[i], zp1[i], p)
        pr[j] = f0.real
        pi_[j] = f0.imag
        ar[j] = c[0] * pr[j]
        ai[j] = c[0] * pi_[j]
        # F_1 = (A0 z + B0) F_0 + c0
        tr = A0 * xr[j] + B0
        ti = A0 * xi[j]
        fr[j] = tr * pr[j] - ti * pi_[j] + c0
        fi[j] = tr * pi_[j] + ti * pr[j]
    if n > 1:
        for j in range(L):
            ar[j] += c[1] * fr[j]
            ai[j] += c[1] * fi[j]
    for k in range(1, n - 1):
        a_ = Ak[k]
        b_ = Bk[k]
        c_ = Ck[k]
        ck = c[k + 1]
        for j in range(L):
            tr = a_ * xr[j] + b_
            ti = a_ * xi[j]
            nr = tr * fr[j] - ti * fi[j] - c_ * pr[j]
            ni = tr * fi[j] + ti * fr[j] - c_ * pi_[j]
            pr[j] = fr[j]
            pi_[j] = fi[j]
            fr[j] = nr
            fi[j] = ni
            ar[j] += ck * nr
            ai[j] += ck * ni
    for j in range(cnt):
        out[idx[j]] = complex(ar[j], ai[j])


@jit()
def _backward_lanes(idx, K0, n, z, A0, B0, c0, Ak, Bk, iC, c, out, w):
    """sum_k c_k F_k by Miller's recurrence from K0 (>= each point's own start) for the
    points idx (at most _LANES), lane-wise.  Overflow: the lanes are checked every
    ``every`` steps, few enough that no lane can pass 1e308 in between (y grows by at most
    ~4|z| + 4 per step, and by 1/C_1 <~ 1/(a+1) in the last one)."""
    L = w.shape[1]
    cnt = idx.shape[0]
    xr, xi, yr, yi, qr, qi, ar, ai = w[0], w[1], w[2], w[3], w[4], w[5], w[6], w[7]
    zmax = 0.0
    for j in range(L):
        i = idx[min(j, cnt - 1)]
        xr[j] = z[i].real
        xi[j] = z[i].imag
        yr[j] = 1.0             # y_{K0-1}
        yi[j] = 0.0
        qr[j] = 0.0             # y_{K0}
        qi[j] = 0.0
        ar[j] = 0.0
        ai[j] = 0.0
        zmax = max(zmax, abs(xr[j]) + abs(xi[j]))
    every = max(1, int(50.0 / math.log10(4.0 * zmax + 4.0)))
    step = 0
    for k in range(K0 - 1, 0, -1):
        if k < n:
            ck = c[k]
            for j in range(L):
                ar[j] += ck * yr[j]
                ai[j] += ck * yi[j]
        a_ = Ak[k]
        b_ = Bk[k]
        ic = iC[k]
        for j in range(L):
            tr = a_ * xr[j] + b_
            ti = a_ * xi[j]
            nr = (tr * yr[j] - ti * yi[j] - qr[j]) * ic
            ni = (tr * yi[j] + ti * yr[j] - qi[j]) * ic
            qr[j] = yr[j]
            qi[j] = yi[j]
            yr[j] = nr
            yi[j] = ni
        step += 1
        if step == every:
            step = 0
            for j in range(L):
                if abs(yr[j]) + abs(yi[j]) > _RESCALE:    # only ratios matter
                    yr[j] /= _RESCALE
                    yi[j] /= _RESCALE
                    qr[j] /= _RESCALE
                    qi[j] /= _RESCALE
                    ar[j] /= _RESCALE
                    ai[j] /= _RESCALE
    for j in range(cnt):
        y = complex(yr[j], yi[j])                     # y_0
        acc = complex(ar[j], ai[j]) + c[0] * y
        z = complex(xr[j], xi[j])
        out[idx[j]] = acc * (c0 / (complex(qr[j], qi[j]) - (A0 * z + B0) * y))


@jit()
def series_kernel(a, b, mu0, lr_max, z, zm1, zp1, p, c, out):
    """out[i] = sum_k c_k F_k(z_i), k < len(c)."""
    n = c.shape[0]
    A0, B0, c0, K, Ak, Bk, Ck, iC = _setup(n, a, b, mu0, lr_max, z)
    order, first_fwd, first_bwd = _order_by_start(K)
    w = np.empty((8, _LANES))
    m = z.shape[0]
    for s in range(first_fwd):
        i = order[s]
        out[i] = -c[0] * mu0 / (math.pi * z[i])
    for s in range(first_fwd, first_bwd, _LANES):
        _forward_lanes(order[s:min(s + _LANES, first_bwd)], n, z, zm1, zp1, p, A0, B0, c0,
                       Ak, Bk, Ck, c, out, w)
    for s in range(first_bwd, m, _LANES):
        e = min(s + _LANES, m)
        _backward_lanes(order[s:e], K[order[e - 1]], n, z, A0, B0, c0, Ak, Bk, iC, c, out, w)
    return out


@jit()
def series_forward_limit(c, log_growth, cap):
    """min(cap, min over k >= 1 with c_k != 0 of (log_growth - log(|c_k| / max|c|)) / k):
    the largest log|rho| where the forward recurrence keeps |c_k| |rho|^k within
    exp(log_growth) max|c| for every k (:func:`sie.cauchy._forward_limit`).  One pass over
    c, for the series of any length (numpy would spend ~10 us on a series of five terms)."""
    top = 0.0
    for v in c:
        top = max(top, abs(v))
    top = max(top, 2.2250738585072014e-308)
    lim = cap
    for k in range(1, c.size):
        m = abs(c[k])
        if m > 0.0:
            lim = min(lim, (log_growth - math.log(m / top)) / k)
    return lim
