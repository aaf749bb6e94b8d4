"""The punch face as the contact search sees it: slope, height differences, extent, breaks,
lowest points, and where to look for the gap.
"""
from __future__ import annotations

import math

import numpy as np

from .errors import PunchGeometryError

__all__ = ["Face"]

_GL = np.polynomial.legendre.leggauss(24)
#: Samples of the slope over the search window in which :meth:`Face.dips` looks for valleys.
_DIP_SAMPLES = 8001


def outside(zones, X):
    """Mask of the points ``X`` that lie in none of ``zones`` (ends included)."""
    inside = np.zeros(np.shape(X), dtype=bool)
    for z in zones:
        inside |= (X >= z.c) & (X <= z.d)
    return ~inside


def _end_between(breaks, a, b, default):
    inside = [x for x in breaks if a <= x <= b]
    return inside[0] if inside else default


class Face:
    """The punch face for the contact search.

    Parameters
    ----------
    slope : callable
        H'(X), vectorised.
    extent : (float, float)
        (X_min, X_max); infinite ends allowed.
    breaks : sequence of float
        X where H' or a derivative jumps.
    height : callable, optional
        H(X), vectorised (else height differences integrate the slope).
    convex : bool
        H' is nondecreasing (stated by the punch, not sampled): one zone's gap opens by
        itself, and the face has one lowest point or flat stretch.
    homogeneous : (x0, d), optional
        slope(x0 + lam xi) = lam^d slope(x0 + xi) for lam > 0 (stated by the punch): a zone
        anchored at x0 carries a load that scales like its size^(d + 1).  By default taken
        from the punch when ``slope`` is a punch's bound ``slope`` method.
    """

    def __init__(self, slope, extent=(-math.inf, math.inf), breaks=(), height=None,
                 convex=False, homogeneous=None):
        self.slope = slope
        self.extent = (float(extent[0]), float(extent[1]))
        self.breaks = tuple(sorted(float(b) for b in breaks))
        self.height = height
        self.convex = bool(convex)       # H' nondecreasing: one zone's gap opens by itself
        if homogeneous is None:
            homogeneous = getattr(getattr(slope, "__self__", None), "homogeneous", None)
        self.homogeneous = None if homogeneous is None else (float(homogeneous[0]),
                                                             float(homogeneous[1]))
        self._dips = None

    # -- heights ---------------------------------------------------------------------------
    def rise(self, x0, x1):
        """H(x1) - H(x0): from ``height`` when given, else Gauss-Legendre of the slope on
        the pieces between breaks (24 points each, pieces at most 1/8 of the distance)."""
        if self.height is not None:
            return float(self.height(np.array([x1]))[0] - self.height(np.array([x0]))[0])
        a, b = (x0, x1) if x0 <= x1 else (x1, x0)
        total = float(self._rises(np.array([a]), np.array([b]))[0])
        return total if x0 <= x1 else -total

    def _rises(self, a, b):
        """H(b_i) - H(a_i) for a_i <= b_i: each stretch split at the breaks inside it, each
        piece into k equal parts (k = 8, fewer for a piece shorter than 1/8 of the search
        window: one per 1/64 of it), 24 Gauss-Legendre points per part; one call of the
        slope for all stretches."""
        lo_w, hi_w = self.search_window()
        unit = (hi_w - lo_w) / 64.0
        starts, lengths, owner = [], [], []
        for i, (p0, p1) in enumerate(zip(a.tolist(), b.tolist())):
            pts = [p0] + [x for x in self.breaks if p0 < x < p1] + [p1]
            for p, q in zip(pts[:-1], pts[1:]):
                k = 8 if not unit > 0 else min(8, max(1, math.ceil((q - p) / unit)))
                h = (q - p) / k
                starts.extend(p + h * j for j in range(k))
                lengths.extend([h] * k)
                owner.extend([i] * k)
        starts, lengths = np.array(starts), np.array(lengths)
        u, w = _GL
        X = starts[:, None] + lengths[:, None] * (0.5 * (u[None, :] + 1.0))
        piece = (0.5 * lengths) * (self.slope(X) @ w)
        return np.bincount(np.array(owner, dtype=int), weights=piece, minlength=a.size)

    def rise_from(self, ref, X):
        """H(X) - H(ref) at each X (without ``height``: the rises between neighbouring
        points, summed outward from ref, so that each stretch is integrated once)."""
        X = np.asarray(X, float)
        if self.height is not None:
            return self.height(X) - float(self.height(np.array([ref]))[0])
        pts, inv = np.unique(np.concatenate([[float(ref)], X.ravel()]), return_inverse=True)
        steps = self._rises(pts[:-1], pts[1:]) if pts.size > 1 else np.zeros(0)
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
        the lowest of them (within 1e-9 of the range of H over them) are returned.  A convex
        face stated homogeneous about x0 (``homogeneous``) is lowest at x0, or at the edge
        next to it, and a convex face with a zero slope at both its ends is flat, without a
        search."""
        known = self._convex_lowest()
        if known is not None:
            return known
        a, b = self.search_window()
        X = np.linspace(a, b, m)
        dH = self.slope(X)
        top = max(float(np.max(np.abs(dH))), np.finfo(float).tiny)
        zero = np.abs(dH) <= 1e-14 * top
        cands = []
        if math.isfinite(self.extent[0]) and (dH[0] > 0 or zero[0]) and not zero[:2].all():
            cands.append((float(X[0]), "left-edge"))
        if math.isfinite(self.extent[1]) and (dH[-1] < 0 or zero[-1]) and not zero[-2:].all():
            cands.append((float(X[-1]), "right-edge"))
        # flat stretches: runs of two or more exact zeros of H', falling before and rising after
        z = np.concatenate([[0], zero.astype(np.int8), [0]])
        starts = np.flatnonzero(np.diff(z) == 1)
        stops = np.flatnonzero(np.diff(z) == -1) - 1
        for k, j in zip(starts, stops):
            if j > k and (k == 0 or dH[k - 1] < 0) and (j == m - 1 or dH[j + 1] > 0):
                c = X[k] if k == 0 else _end_between(self.breaks, X[k - 1], X[k], X[k - 1])
                d = X[j] if j == m - 1 else _end_between(self.breaks, X[j], X[j + 1], X[j + 1])
                left_open = k == 0 and not math.isfinite(self.extent[0])
                right_open = j == m - 1 and not math.isfinite(self.extent[1])
                if left_open or right_open:     # no lowest point: flat toward no edge
                    where = ("everywhere, with no edge" if left_open and right_open else
                             f"toward -X from X = {float(d):.6g}, a side without an edge"
                             if left_open else
                             f"toward +X from X = {float(c):.6g}, a side without an edge")
                    raise PunchGeometryError(
                        f"the face is flat {where}: give the face's extent (face=) so that "
                        "contact has an edge there")
                cands.append(((float(c), float(d)), "flat"))
        # interior minima: H' from - to + (a single zero sample counts as the crossing)
        runs = np.zeros(m, dtype=bool)
        for k, j in zip(starts, stops):
            runs[k:j + 1] = j > k
        for k in np.flatnonzero((dH[:-1] < 0) & (dH[1:] >= 0) & ~runs[1:]):
            if dH[k + 1] > 0:               # the root of H' (a sign change: Brent)
                x0 = self._slope_zero(X[k], X[k + 1])
            else:
                x0 = X[k + 1]
            if k + 1 == m - 1 and math.isfinite(self.extent[1]):
                continue                    # H' = 0 at the right edge: the edge candidate
            cands.append((float(x0), "interior"))
        if not cands:
            raise PunchGeometryError(
                f"the face has no lowest point in [{a:.6g}, {b:.6g}] (its height falls toward "
                "an unbounded side): give the face's extent (face=) so that contact has an edge")
        if len(cands) == 1:
            return cands
        cands.sort(key=lambda c: c[0][0] if c[1] == "flat" else c[0])     # left to right
        where = [c[0][0] if c[1] == "flat" else c[0] for c in cands]
        heights = np.array([self.rise(a, float(x)) for x in where])
        span = max(float(np.ptp(self.rise_from(a, X[:: max(1, m // 64)]))), np.finfo(float).tiny)
        low = heights <= heights.min() + 1e-9 * span
        return [c for c, keep in zip(cands, low) if keep]

    def _convex_lowest(self):
        """The lowest point of a convex face homogeneous about x0 (slope(x0 + lam xi) =
        lam^d slope(x0 + xi)), or None where that needs the general search (a slope that
        vanishes on one side of x0: a flat stretch).  The slope is the same on each side of
        x0 up to the factor lam^d, so its sign there is that at x0 -+ 1; convex: the
        left sign is not above the right one.  A convex face of finite extent whose slope
        vanishes at both ends is flat."""
        if not self.convex:
            return None
        lo, hi = self.extent
        if self.homogeneous is None:
            if math.isfinite(lo) and math.isfinite(hi) and \
                    not np.any(self.slope(np.array([lo, hi]))):
                return [((lo, hi), "flat")]     # H' nondecreasing from 0 to 0: flat
            return None
        x0, _ = self.homogeneous
        # one point of the face on each side of x0 that the face has (the slope's sign is
        # the same along each side)
        left = x0 - min(1.0, 0.5 * (x0 - lo)) if x0 > lo else None
        right = x0 + min(1.0, 0.5 * (hi - x0)) if x0 < hi else None
        if x0 < lo:
            right = lo + min(1.0, 0.5 * (hi - lo))
        if x0 > hi:
            left = hi - min(1.0, 0.5 * (hi - lo))
        pts = [p for p in (left, right) if p is not None]
        vals = [float(v) for v in self.slope(np.array(pts))]
        s_left = vals[0] if left is not None else None
        s_right = vals[-1] if right is not None else None
        if 0.0 in vals:
            return None                    # a flat side: the general search
        if s_left is not None and s_left > 0.0:
            x = lo                         # rising from the left end on
        elif s_right is not None and s_right < 0.0:
            x = hi                         # falling up to the right end
        else:
            x = min(max(x0, lo), hi)       # falling into x0, rising after it
        if not math.isfinite(x):
            return None                    # falls toward an unbounded side: the search says so
        if x == lo:
            return [(x, "left-edge")]
        if x == hi:
            return [(x, "right-edge")]
        return [(x, "interior")]

    def _slope_zero(self, a, b):
        """The zero of the slope between a and b, where it changes sign (Brent's method)."""
        from scipy.optimize import brentq   # here: ~0.15 s of every start otherwise
        return brentq(lambda x: float(self.slope(np.array([x]))[0]), a, b,
                      xtol=1e-15 * max(1.0, abs(a)), rtol=4 * np.finfo(float).eps)

    # -- the gap -----------------------------------------------------------------------------
    def dips(self):
        """X of every valley of the face: the local minima of H (its slope from - to +
        between neighbours of ``_DIP_SAMPLES`` samples of the search window, 20 times finer
        than the gap's samples, polished by Brent's method) and its breaks.  The gap is
        checked there too (:func:`contact.continuation._inspect`): a dip of the face
        narrower than the spacing of the gap's samples could press into the half-space
        between them unseen.  Computed once per face."""
        if self._dips is None:
            a, b = self.search_window()
            X = np.linspace(a, b, _DIP_SAMPLES)
            dH = self.slope(X)
            out = [x for x in self.breaks if a < x < b]
            out += [self._slope_zero(X[k], X[k + 1])
                    for k in np.flatnonzero((dH[:-1] < 0) & (dH[1:] > 0)).tolist()]
            self._dips = np.array(sorted(out))
        return self._dips

    def sample_points(self, zones, m):
        """m points of the search window outside the zones."""
        a, b = self.search_window()
        a = min(a, zones[0].c)
        b = max(b, zones[-1].d)
        X = np.linspace(a, b, m)
        return X[outside(zones, X)]

    def rise_scale(self, state):
        X = np.concatenate([z.c + z.width * np.linspace(0.0, 1.0, 9) for z in state.zones])
        width = state.zones[-1].d - state.zones[0].c
        return max(float(np.max(np.abs(self.slope(X)))) * width, np.finfo(float).tiny)
