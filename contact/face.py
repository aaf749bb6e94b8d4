"""The punch face as the contact search sees it: slope, height differences, extent, breaks,
lowest points, and where to look for the gap.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import minimize_scalar

__all__ = ["Face"]

_GL = np.polynomial.legendre.leggauss(24)


class Face:
    """H'(X) (``slope``), optionally H(X) (``height``), on ``extent`` = (X_min, X_max)
    (infinite ends allowed), with ``breaks`` where H' or a derivative jumps."""

    def __init__(self, slope, extent=(-math.inf, math.inf), breaks=(), height=None):
        self.slope = slope
        self.extent = (float(extent[0]), float(extent[1]))
        self.breaks = tuple(sorted(float(b) for b in breaks))
        self.height = height

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
        """H(X) - H(ref) at each X."""
        if self.height is not None:
            return self.height(np.asarray(X, float)) - float(self.height(np.array([ref]))[0])
        return np.array([self.rise(ref, float(x)) for x in np.ravel(X)])

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
        """[(X, kind)]: the global minima of H on the face (within 1e-12 of its range), each
        an interior point ("interior"), an edge ("left-edge", "right-edge") or a flat stretch
        ((c, d), "flat")."""
        a, b = self.search_window()
        X = np.linspace(a, b, m)
        H = self.rise_from(a, X)
        span = max(float(np.max(H) - np.min(H)), np.finfo(float).tiny)
        low = H <= np.min(H) + 1e-12 * span
        out = []
        k = 0
        while k < m:
            if not low[k]:
                k += 1
                continue
            j = k
            while j + 1 < m and low[j + 1]:
                j += 1
            run_slope = np.max(np.abs(self.slope(X[k:j + 1]))) if j > k else np.inf
            top_slope = max(float(np.max(np.abs(self.slope(X)))), np.finfo(float).tiny)
            if j > k and run_slope <= 1e-14 * top_slope:       # a flat stretch (H' = 0)
                out.append(((X[k], X[j]), "flat"))
            elif k == 0 and math.isfinite(self.extent[0]):
                out.append((X[0], "left-edge"))
            elif k == m - 1 and math.isfinite(self.extent[1]):
                out.append((X[-1], "right-edge"))
            else:
                lo_, hi_ = X[max(k - 1, 0)], X[min(j + 1, m - 1)]
                r = minimize_scalar(lambda x: self.rise(a, x), bounds=(lo_, hi_),
                                    method="bounded", options={"xatol": 1e-14 * max(1.0, abs(lo_))})
                out.append((float(r.x), "interior"))
            k = j + 1
        return out

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
