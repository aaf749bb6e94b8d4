"""Physical checks on a contact solution: p >= 0 inside, the gap opens outside free ends."""
from __future__ import annotations

import numpy as np

from .errors import ContactLossError


def _check_positive_pressure(sol, xl, xr, breaks=()):
    """p >= 0 inside the contact, sampled at Chebyshev points (401; 129 when the breaks
    correction makes each point cost O(n) more) plus both sides of every break."""
    m = 129 if len(breaks) else 401
    s = np.cos(np.pi * (np.arange(m) + 0.5) / m)
    if len(breaks):
        h, c = 0.5 * (xr - xl), 0.5 * (xr + xl)
        sb = np.array([(b - c) / h for b in breaks if xl < b < xr])
        s = np.concatenate([s, sb * (1 - 1e-6), sb * (1 + 1e-6)]) if sb.size else s
    phi = sol.phi(s)
    top = np.max(np.abs(phi))
    if np.min(phi) < -1e-9 * top:
        k = int(np.argmin(phi))
        X = 0.5 * (xr - xl) * s[k] + 0.5 * (xr + xl)
        raise ContactLossError(
            f"the contact pressure is negative inside the contact [{xl:.6g}, {xr:.6g}] "
            f"(at X = {X:.6g}): the punch would lose contact there; this profile and load need "
            "more than one contact zone, which this solver does not model")


def _slope_nondecreasing(punch, x0, x1, samples=2001):
    """Is the punch slope nondecreasing on [min(x0,x1), max(x0,x1)] (sampled)?"""
    X = np.linspace(min(x0, x1), max(x0, x1), samples)
    v = punch.slope(X)
    return bool(np.all(np.diff(v) >= -1e-14 * max(np.max(np.abs(v)), np.finfo(float).tiny)))


_GAP_RULE = tuple(0.5 * v for v in np.polynomial.legendre.leggauss(12))
_GAP_RULE = (_GAP_RULE[0] + 0.5, _GAP_RULE[1])          # Gauss-Legendre on [0, 1]


def _check_gap(res, prob):
    """The punch face must stay above the surface outside free ends (gap >= 0), checked at
    1/8 .. 16 contact widths beyond each free end.

    gap(x_end + side D) = side int_0^D (v'(X) - N11 Hc[p](X)) dxi, X = x_end + side xi
    (outside the contact q = 0, so the surface slope is N11 Hc[p]); xi = D u^2 grades the
    Gauss-Legendre nodes toward the end, where the integrand behaves like xi^alpha."""
    xl, xr = res.ends
    L = xr - xl
    u, wu = _GAP_RULE
    Ds = L * np.array([0.125, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0])
    N11 = res.constants.N11
    for k, (side, x_end) in enumerate(((-1.0, xl), (1.0, xr))):
        if prob.punch.corners[k] is not None:
            continue                       # a corner: the punch face ends there
        if _slope_nondecreasing(prob.punch, x_end, x_end + side * Ds[-1]):
            # gap' = v'(X) - N11 Hc[p](X) with N11 Hc[p] > 0 and decreasing away from the
            # contact (p >= 0), and gap' = 0 at a free end: a nondecreasing slope makes the
            # gap grow on this side, no quadrature needed
            continue
        X = x_end + side * (Ds[:, None] * (u * u)[None, :])          # (7, 24)
        slope = prob.punch.slope(X)
        n11hc = N11 * res.hilbert_pressure(X.ravel()).reshape(X.shape)
        gap = side * ((slope - n11hc) * (wu * 2.0 * u)[None, :]).sum(axis=1) * Ds
        scale = Ds * np.maximum(np.abs(slope).max(axis=1), np.abs(n11hc).max(axis=1))
        bad = np.flatnonzero(gap < -1e-9 * scale)
        if bad.size:
            j = bad[0]
            raise ContactLossError(
                f"the punch face penetrates the surface outside the contact (at X = "
                f"{x_end + side * Ds[j]:.6g}, gap {gap[j]:.3g}): a second contact zone would be "
                "needed, which this solver does not model")
