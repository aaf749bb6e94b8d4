"""The punch face as the contact search sees it: slope, height differences, extent, breaks,
lowest points, and where to look for the gap.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from .errors import PunchGeometryError

__all__ = ["Face"]

_GL = np.polynomial.legendre.leggauss(24)


def _end_between(breaks, a, b, default):
    inside = [x for x in breaks if a <= x <= b]
    return inside[0] if inside else default


class Face:
    """H'(X) (``slope``), optionally H(X) (``height``), on ``extent`` = (X_min, X_max)
    (infinite ends allowed), with ``breaks`` where H' or a derivative jumps; ``convex``:
    H' is nondecreasing (stated by the punch, not sampled)."""

    def __init__(self, slope, extent=(-math.inf, math.inf), breaks=(), height=None,
                 convex=False):
        self.slope = slope
        self.extent = (float(extent[0]), float(extent[1]))
        self.breaks = tuple(sorted(float(b) for b in breaks))
        self.height = height
        self.convex = bool(convex)       # H' nondecreasing: one zone's gap opens by itself

    # -- heights ---------------------------------------------------------------------------
    def rise(self, x0, x1):
        """H(x1) - H(x0): from ``height`` when given, else Gauss-Legendre of the slope on
        the pieces between breaks (24 points each, pieces at most 1/8 of the distance)."""
        if self.height is not None:
            return float(self.height(np.array([x1]))[0] - self.height(np.array([x0]))[0])
        a, b = (x0, x1) if x0 <= x1 else (x1, x0)
        pts = [a] + [x for x in self.breaks if a < x < b] + [b]
        edges = []
        for p, q in zip(pts[:-1], pts[1:]):
            edges.extend(np.linspace(p, q, 9)[:-1])
        edges.append(b)
        u, w = _GL
        lo, hi = np.array(edges[:-1]), np.array(edges[1:])
        X = 0.5 * (lo + hi)[:, None] + 0.5 * (hi - lo)[:, None] * u[None, :]
        total = float(np.sum(0.5 * (hi - lo)[:, None] * w[None, :] * self.slope(X)))
        return total if x0 <= x1 else -total

    def rise_from(self, ref, X):
        """H(X) - H(ref) at each X (without ``height``: the rises between neighbouring
        points, summed outward from ref, so that each stretch is integrated once)."""
        X = np.asarray(X, float)
        if self.height is not None:
            return self.height(X) - float(self.height(np.array([ref]))[0])
        pts, inv = np.unique(np.concatenate([[float(ref)], X.ravel()]), return_inverse=True)
        steps = np.array([self.rise(p, q) for p, q in zip(pts[:-1], pts[1:])])
        H = np.concatenate([[0.0], np.cumsum(steps)])
        return (H[inv[1:]] - H[inv[0]]).reshape(X.shape)

    # -- where the face is lowest --------------------------------------------------------
    @property
    def scale(self):
        lo, hi = self.extent
        if math.isfinite(lo) and math.isfinite(hi):
            return hi - lo
        if self.breaks:
            return max(1.0, self.breaks[-1] - self.breaks[0])
        return 1.0

    def search_window(self):
        lo, hi = self.extent
        s = self.scale
        mid = 0.5 * (lo + hi) if math.isfinite(lo + hi) else (
            lo + s if math.isfinite(lo) else (hi - s if math.isfinite(hi) else
                                               (0.5 * (self.breaks[0] + self.breaks[-1])
                                                if self.breaks else 0.0)))
        a = lo if math.isfinite(lo) else mid - 8.0 * s
        b = hi if math.isfinite(hi) else mid + 8.0 * s
        return a, b

    def lowest_points(self, m=2001):
        """[(X, kind)]: the global minima of H on the face, each an interior point
        ("interior"), an edge ("left-edge", "right-edge") or a flat stretch ((c, d), "flat").

        Candidates come from the slope at m samples of the search window (exact where H
        itself would be a quadrature): a sign change from - to + (polished by a bounded
        minimisation), a run of samples where H' = 0 exactly, an edge where H rises inward;
        the lowest of them (within 1e-9 of the range of H over them) are returned."""
        a, b = self.search_window()
        X = np.linspace(a, b, m)
        dH = self.slope(X)
        top = max(float(np.max(np.abs(dH))), np.finfo(float).tiny)
        zero = np.abs(dH) <= 1e-14 * top
        cands = []
        if math.isfinite(self.extent[0]) and (dH[0] > 0 or zero[0]) and not zero[:2].all():
            cands.append((X[0], "left-edge"))
        if math.isfinite(self.extent[1]) and (dH[-1] < 0 or zero[-1]) and not zero[-2:].all():
            cands.append((X[-1], "right-edge"))
        # flat stretches: runs of two or more exact zeros of H', falling before and rising after
        z = np.concatenate([[0], zero.astype(np.int8), [0]])
        starts = np.flatnonzero(np.diff(z) == 1)
        stops = np.flatnonzero(np.diff(z) == -1) - 1
        for k, j in zip(starts, stops):
            if j > k and (k == 0 or dH[k - 1] < 0) and (j == m - 1 or dH[j + 1] > 0):
                c = X[k] if k == 0 else _end_between(self.breaks, X[k - 1], X[k], X[k - 1])
                d = X[j] if j == m - 1 else _end_between(self.breaks, X[j], X[j + 1], X[j + 1])
                cands.append(((c, d), "flat"))
        # interior minima: H' from - to + (a single zero sample counts as the crossing)
        runs = np.zeros(m, dtype=bool)
        for k, j in zip(starts, stops):
            runs[k:j + 1] = j > k
        for k in np.flatnonzero((dH[:-1] < 0) & (dH[1:] >= 0) & ~runs[1:]):
            if dH[k + 1] > 0:               # the root of H' (a sign change: Brent)
                x0 = brentq(lambda x: float(self.slope(np.array([x]))[0]), X[k], X[k + 1],
                            xtol=1e-15 * max(1.0, abs(X[k])), rtol=4 * np.finfo(float).eps)
            else:
                x0 = X[k + 1]
            cands.append((float(x0), "interior"))
        if not cands:
            raise PunchGeometryError(
                f"the face has no lowest point in [{a:.6g}, {b:.6g}] (its height falls toward "
                "an unbounded side): give the face's extent (face=) so that contact has an edge")
        where = [c[0][0] if c[1] == "flat" else c[0] for c in cands]
        heights = np.array([self.rise(a, float(x)) for x in where])
        span = max(float(np.ptp(self.rise_from(a, X[:: max(1, m // 64)]))), np.finfo(float).tiny)
        low = heights <= heights.min() + 1e-9 * span
        return [c for c, keep in zip(cands, low) if keep]

    # -- the gap -----------------------------------------------------------------------------
    def sample_points(self, zones, m):
        """m points of the search window outside the zones."""
        a, b = self.search_window()
        a = min(a, zones[0].c)
        b = max(b, zones[-1].d)
        X = np.linspace(a, b, m)
        inside = np.zeros(m, dtype=bool)
        for z in zones:
            inside |= (X >= z.c) & (X <= z.d)
        return X[~inside]

    def rise_scale(self, state):
        X = np.concatenate([z.c + z.width * np.linspace(0.0, 1.0, 9) for z in state.zones])
        width = state.zones[-1].d - state.zones[0].c
        return max(float(np.max(np.abs(self.slope(X)))) * width, np.finfo(float).tiny)
