"""Double-double ("dd") arithmetic kernels: a value is an unevaluated sum hi + lo.

Used where a short computation must survive heavy cancellation, i.e. the
hypergeometric series of P_n^{(a,b)} next to x = 1 (see gaussjacobi.py), which
loses up to e^{rho theta}/2 ~ 1e13 to cancellation for the tenth node.
Error-free transformations: Knuth's TwoSum and Dekker's TwoProduct (with
Veltkamp splitting, since Python/numba expose no fused multiply-add).
Reference: T. J. Dekker, Numer. Math. 18 (1971) 224-242.
"""
from __future__ import annotations

from ._jit import jit

_SPLIT = 134217729.0  # 2^27 + 1


@jit()
def two_sum(a, b):
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


@jit()
def two_prod(a, b):
    p = a * b
    t = _SPLIT * a
    ah = t - (t - a)
    al = a - ah
    t = _SPLIT * b
    bh = t - (t - b)
    bl = b - bh
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


@jit()
def dd_add(ah, al, bh, bl):
    s, e = two_sum(ah, bh)
    e += al + bl
    return two_sum(s, e)


@jit()
def dd_mul(ah, al, bh, bl):
    p, e = two_prod(ah, bh)
    e += ah * bl + al * bh
    return two_sum(p, e)


@jit()
def dd_div(ah, al, bh, bl):
    q1 = ah / bh
    ph, pl = dd_mul(bh, bl, q1, 0.0)
    rh, rl = dd_add(ah, al, -ph, -pl)
    q2 = rh / bh
    ph, pl = dd_mul(bh, bl, q2, 0.0)
    rh, rl = dd_add(rh, rl, -ph, -pl)
    q3 = rh / bh
    h, l = two_sum(q1, q2)
    return dd_add(h, l, q3, 0.0)
