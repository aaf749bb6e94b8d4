"""The punch face as the contact search sees it: slope, height differences, extent, breaks,
lowest points, and where to look for the gap.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import ProfileCallableError, PunchGeometryError

__all__ = ["Face", "Scan"]

_GL = np.polynomial.legendre.leggauss(24)
#: Samples of the slope over the search window in which :meth:`Face.dips` looks for valleys.
_DIP_SAMPLES = 8001
#: Samples per decade of distance of the outward scan (a ratio of 10^(1/16) = 1.155).
_PER_DECADE = 16
#: The scan's distances from its centre are 10^(j/16) for j = _J_MIN .. _J_MAX, in the user's
#: length unit: the grid maps onto itself when every length is multiplied by a power of 10,
#: so that what the scan finds does not depend on the unit lengths are written in.
_J_MIN, _J_MAX = -20 * _PER_DECADE, 20 * _PER_DECADE
#: Decades the scan goes on past the outermost feature (a slope that does not rise outward,
#: a break, an edge) ...
_PAST_FEATURES = 6
#: ... and past the distance at which the face has risen by that distance.
_PAST_RISE = 1
#: Decades the scan samples in one call of the slope (one at a time where a call fails).
_BLOCK = 8
#: Gap samples a decade of distance outward from the zones (:meth:`Face.sample_points`).
_GAP_PER_DECADE = 8
#: Gap samples inside each gap between neighbouring zones (Chebyshev points).
_GAP_INNER = 8


@dataclass(frozen=True)
class Scan:
    """What the outward scan of a face found (:meth:`Face.scan`).

    The slope is sampled on each side of the face that has no edge, outward from a centre
    ``c0`` (the finite edge, the middle of the breaks, or X = 0) at distances 10^(j/16),
    until it has been seen to rise outward for :data:`_PAST_FEATURES` decades past the
    outermost feature and :data:`_PAST_RISE` decade past the distance at which the face has
    risen by that distance.  A face that still falls, or is flat, toward a side without an
    edge at the end of the scan (10^20 from the centre) is refused.

    Attributes
    ----------
    c0 : float
    X, slope : ndarray
        The samples, ascending in X, and H' there.
    features : tuple of float
        X of each feature: the finite edges, the breaks, and the middle of each pair of
        neighbouring samples across which H' changes sign (or is zero).
    rise_run : float or None
        The smallest distance from ``c0`` at which the face has risen above the lowest of
        the samples before it by that distance (None where it never does: a face flatter
        than 45 degrees all the way).
    reach : (float, float)
        How far the face is known to rise outward: the outermost samples (the edge on a
        side that has one).
    """
    c0: float
    X: np.ndarray
    slope: np.ndarray
    features: tuple
    rise_run: float | None
    reach: tuple


def outside(zones, X):
    """Mask of the points ``X`` that lie in none of ``zones`` (ends included)."""
    inside = np.zeros(np.shape(X), dtype=bool)
    for z in zones:
        inside |= (X >= z.c) & (X <= z.d)
    return ~inside


_FEW_STRETCHES = 8      # Face._rises lists the parts of this many stretches in Python


def _sorted_unique(v):
    """np.unique(v, return_inverse=True) for a 1-d float array without NaN: the ascending
    distinct values and where each v lies among them (one stable sort)."""
    order = np.argsort(v, kind="stable")
    s = v[order]
    new = np.empty(s.size, dtype=bool)
    new[:1] = True
    np.not_equal(s[1:], s[:-1], out=new[1:])
    inv = np.empty(v.size, dtype=np.intp)
    inv[order] = np.cumsum(new) - 1
    return s[new], inv


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
                 convex=False, homogeneous=None, slope_from_height=False):
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
        self._dip_slope = None
        self._scan = None
        self._opens = None
        self._lowest = {}           # m -> lowest_points(m)
        self._grid = None           # (key, X, rises between neighbours or None): see _base_samples
        self._grid_dips = None      # (key, dips known, grid with the dips, rises): _dip_grid
        # the slope is a finite difference of the height, whose step follows the scale: the
        # scan reads the height itself
        self.slope_from_height = bool(slope_from_height) and height is not None

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
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        if a.size <= _FEW_STRETCHES:
            return self._few_rises(a, b, unit)
        # the pieces: stretch i runs over [a_i, breaks inside it..., b_i]
        br = np.array(self.breaks) if self.breaks else np.zeros(1)
        first = np.searchsorted(br, a, side="right") if self.breaks else np.zeros(a.size, int)
        inside = (np.searchsorted(br, b, side="left") - first) if self.breaks else first
        count = inside + 1
        stretch = np.repeat(np.arange(a.size), count)
        j = np.arange(stretch.size) - np.repeat(np.cumsum(count) - count, count)
        k0 = first[stretch] + j
        p = np.where(j == 0, a[stretch], br[np.clip(k0 - 1, 0, br.size - 1)])
        q = np.where(j == inside[stretch], b[stretch], br[np.clip(k0, 0, br.size - 1)])
        # each piece in k equal parts
        k = np.full(p.size, 8) if not unit > 0 else \
            np.clip(np.ceil((q - p) / unit), 1, 8).astype(int)
        h = (q - p) / k
        piece = np.repeat(np.arange(p.size), k)
        m = np.arange(piece.size) - np.repeat(np.cumsum(k) - k, k)
        starts, lengths = p[piece] + h[piece] * m, h[piece]
        u, w = _GL
        X = starts[:, None] + lengths[:, None] * (0.5 * (u[None, :] + 1.0))
        part = (0.5 * lengths) * (self.slope(X) @ w)
        return np.bincount(stretch[piece], weights=part, minlength=a.size)

    def _few_rises(self, a, b, unit):
        """:meth:`_rises` for a few stretches (the parts listed in Python, not by array
        bookkeeping: the same parts, points and sums)."""
        u, w = _GL
        lo, step, count, owner = [], [], [], []
        for i, (ai, bi) in enumerate(zip(a.tolist(), b.tolist())):
            cuts = [ai] + [c for c in self.breaks if ai < c < bi] + [bi]
            for p, q in zip(cuts[:-1], cuts[1:]):
                k = min(max(math.ceil((q - p) / unit), 1), 8) if unit > 0 else 8
                lo.append(p)
                step.append((q - p) / k)
                count.append(k)
                owner.append(i)
        count = np.array(count)
        lengths = np.repeat(step, count)
        m = np.arange(lengths.size) - np.repeat(np.cumsum(count) - count, count)
        starts = np.repeat(lo, count) + lengths * m
        X = starts[:, None] + lengths[:, None] * (0.5 * (u[None, :] + 1.0))
        part = (0.5 * lengths) * (self.slope(X) @ w)
        return np.bincount(np.repeat(owner, count), weights=part, minlength=a.size)

    def rise_from(self, ref, X):
        """H(X) - H(ref) at each X (without ``height``: the rises between neighbouring
        points, summed outward from ref, so that each stretch is integrated once)."""
        X = np.asarray(X, float)
        if self.height is not None:
            return self.height(X) - float(self.height(np.array([ref]))[0])
        H = self._rise_on_grid(float(ref), X.ravel())
        if H is not None:
            return H.reshape(X.shape)
        pts, inv = _sorted_unique(np.concatenate([[float(ref)], X.ravel()]))
        steps = self._steps(pts)
        # summed outward from ref on each side: a point near ref does not carry the rounding
        # of the (possibly far larger) rises beyond it
        k = int(inv[0])
        H = np.zeros(pts.size)
        H[k + 1:] = np.cumsum(steps[k:])
        H[:k] = -np.cumsum(steps[:k][::-1])[::-1]
        return H[inv[1:]].reshape(X.shape)

    def _rise_on_grid(self, ref, x):
        """:meth:`rise_from` where every x is a point of the sample grid or a dip
        (:meth:`_dip_grid`) and ref lies on the grid's span (else None): the rises between
        neighbours on that grid, known once per grid, and those of ref's cell on each side
        of it, summed outward from ref."""
        grid = self._dip_grid()
        if grid is None:
            return None
        _, _, G, S = grid
        n = G.size
        if not G[0] <= ref < G[-1]:
            return None
        idx = np.minimum(np.searchsorted(G, x), n - 1)
        if not np.array_equal(G[idx], x):
            return None
        j = int(np.searchsorted(G, ref, side="right")) - 1      # G[j] <= ref < G[j + 1]
        up, down = S[j:].copy(), S[:j + 1][::-1].copy()           # the cells outward from ref
        if G[j] == ref:
            down = down[1:]
        else:
            down[0], up[0] = self._rises(np.array([G[j], ref]), np.array([ref, G[j + 1]]))
        H = np.empty(n)
        H[n - up.size:] = np.cumsum(up)
        H[:down.size] = -np.cumsum(down)[::-1]
        if G[j] == ref:
            H[j] = 0.0
        return H[idx]

    def _dip_grid(self):
        """The sample grid (:meth:`_base_samples`) with the face's dips, where they are known
        (:meth:`dips`), among its points, and the rises between its neighbours: those of the
        grid's own cells, and of the cells a dip splits by :meth:`_rises`.  (key, whether the
        dips were known, points, rises), made once per grid; None without a grid."""
        if self._grid is None:
            return None
        key, G, S = self._grid
        known = self._dips is not None
        if self._grid_dips is not None and self._grid_dips[:2] == (key, known):
            return self._grid_dips
        if S is None:
            S = self._rises(G[:-1], G[1:])
            self._grid = (key, G, S)
        d = self._dips if known else np.zeros(0)
        d = d[(d > G[0]) & (d < G[-1])]
        d = d[G[np.searchsorted(G, d)] != d]                     # not on the grid already
        if d.size:
            Gd = np.sort(np.concatenate([G, d]))
            i = np.searchsorted(G, Gd[:-1], side="right") - 1     # the grid cell of each
            whole = (Gd[:-1] == G[i]) & (Gd[1:] == G[i + 1])
            Sd = np.empty(Gd.size - 1)
            Sd[whole] = S[i[whole]]
            Sd[~whole] = self._rises(Gd[:-1][~whole], Gd[1:][~whole])
            G, S = Gd, Sd
        self._grid_dips = (key, known, G, S)
        return self._grid_dips

    def _steps(self, pts):
        """H(pts[i+1]) - H(pts[i]) for ascending pts: from the rises between neighbours of
        the face's own sample grid (:meth:`_base_samples`, integrated once) where both
        points are neighbours on it, else from those and :meth:`_rises`
        (:meth:`_grid_steps`)."""
        if pts.size < 2:
            return np.zeros(0)
        a, b = pts[:-1], pts[1:]
        if self._grid is None:
            return self._rises(a, b)
        key, G, S = self._grid
        if S is None:
            S = self._rises(G[:-1], G[1:])
            self._grid = (key, G, S)
        i = np.minimum(np.searchsorted(G, a), G.size - 2)
        known = (G[i] == a) & (G[i + 1] == b)
        steps = np.empty(a.size)
        steps[known] = S[i[known]]
        if not known.all():
            steps[~known] = self._grid_steps(G, S, a[~known], b[~known])
        return steps

    def _grid_steps(self, G, S, a, b):
        """H(b_i) - H(a_i) for a_i < b_i that are not neighbours on the grid G, whose
        neighbours rise by S: a stretch with grid points inside (one across a zone, which
        has no samples) is the rises of the partial cells at its ends (:meth:`_rises`) and
        of the whole cells between them (S); others by :meth:`_rises` alone."""
        j0 = np.searchsorted(G, a, side="right")        # the first grid point above a_i
        j1 = np.searchsorted(G, b, side="left") - 1     # the last one below b_i
        across = j1 > j0
        if not across.any():
            return self._rises(a, b)
        k = np.flatnonzero(across)
        lo = np.concatenate([a[~across], a[k], G[j1[k]]])
        hi = np.concatenate([b[~across], G[j0[k]], b[k]])
        parts = self._rises(lo, hi)
        out = np.empty(a.size)
        out[~across] = parts[:a.size - k.size]
        left, right = parts[a.size - k.size:a.size], parts[a.size:]
        inner = np.array([S[p:q].sum() for p, q in zip(j0[k].tolist(), j1[k].tolist())])
        out[k] = (left + inner) + right
        return out

    # -- the face's own scale -------------------------------------------------------------
    def scan(self):
        """The face explored outward on its sides without an edge (:class:`Scan`): where it
        does anything, how far it rises, and that it does not fall or stay flat toward a side
        without an edge.  Computed once per face.

        Raises
        ------
        PunchGeometryError
            The face falls (its slope does not rise outward), or is flat, toward a side
            without an edge at the end of the scan; or its slope stops being finite before
            the face has been seen to rise.
        """
        if self._scan is None:
            self._scan = self._explore()
        return self._scan

    def _explore(self):
        lo, hi = self.extent
        finite = [x for x in (lo, hi) if math.isfinite(x)]
        known = finite + list(self.breaks)
        sides = [side for side, edge in ((-1, lo), (1, hi)) if not math.isfinite(edge)]
        if not sides:
            return Scan(0.5 * (lo + hi), np.zeros(0), np.zeros(0), tuple(sorted(set(known))),
                        None, (lo, hi))
        c0 = finite[0] if finite else (0.5 * (min(known) + max(known)) if known else 0.0)
        j = _J_MIN
        if c0 != 0.0:       # distances below a few ulps of c0 are not distances
            j = max(j, math.ceil(_PER_DECADE * math.log10(8.0 * np.finfo(float).eps * abs(c0))))
        r_known = max((abs(x - c0) for x in known), default=0.0)
        state = {side: _SideScan(side) for side in sides}
        if self.slope_from_height:
            H0 = float(self.height(np.array([c0]))[0])
            for t in state.values():
                t.height, t.H_prev = self.height, H0
        with np.errstate(over="ignore", invalid="ignore"):
            while j <= _J_MAX and not all(t.done for t in state.values()):
                step = min(_BLOCK * _PER_DECADE, _J_MAX + _PER_DECADE - j)
                r = 10.0 ** (np.arange(j, j + step) / _PER_DECADE)
                r_feat = max([r_known] + [t.r_wrong for t in state.values()])
                for t in state.values():
                    if not t.done:
                        t.extend(self.slope, c0, r, r_feat)
                j += step
        _scan_verdict(state, c0, self.extent)
        parts = [state[-1].samples(c0)] if -1 in state else []
        parts += [state[1].samples(c0)] if 1 in state else []
        X = np.concatenate([p[0] for p in parts])
        dH = np.concatenate([p[1] for p in parts])
        order = np.argsort(X, kind="stable")
        X, dH = X[order], dH[order]
        X, dH = X[np.isfinite(dH)], dH[np.isfinite(dH)]
        flips = np.flatnonzero((dH[:-1] * dH[1:] <= 0.0))
        features = sorted(set(known) | set((0.5 * (X[flips] + X[flips + 1])).tolist()))
        runs = [t.rise_run for t in state.values() if t.rise_run is not None]
        reach = (lo if math.isfinite(lo) else float(X[0]), hi if math.isfinite(hi) else float(X[-1]))
        return Scan(c0, X, dH, tuple(features), max(runs) if runs else None, reach)

    @property
    def scale(self):
        """The face's own length: its width where it has two edges; else the span of its
        features (:meth:`scan`), or where it has one feature, the distance at which it has
        risen by that distance; 1 where none of these exists (a straight face from one edge,
        which has no length of its own: the load sets the contact's).  A convex face (the
        library's punches) is not scanned: its extent, the span of its breaks, or 1."""
        lo, hi = self.extent
        if math.isfinite(lo) and math.isfinite(hi):
            return hi - lo
        if self.convex:
            return max(1.0, self.breaks[-1] - self.breaks[0]) if self.breaks else 1.0
        sc = self.scan()
        span = sc.features[-1] - sc.features[0]
        if span > 0.0:
            return span
        return sc.rise_run if sc.rise_run is not None else 1.0

    def search_window(self):
        """Where the face's lowest points and valleys are looked for: its extent where it has
        two edges, else its features (:meth:`scan`) and 8 times its :attr:`scale` beyond
        them, within its extent."""
        lo, hi = self.extent
        if math.isfinite(lo) and math.isfinite(hi):
            return lo, hi
        s = self.scale
        if self.convex:
            mid = lo + s if math.isfinite(lo) else (hi - s if math.isfinite(hi) else (
                0.5 * (self.breaks[0] + self.breaks[-1]) if self.breaks else 0.0))
            return (lo if math.isfinite(lo) else mid - 8.0 * s,
                    hi if math.isfinite(hi) else mid + 8.0 * s)
        f = self.scan().features
        return max(lo, f[0] - 8.0 * s), min(hi, f[-1] + 8.0 * s)

    def _window_samples(self, m):
        """m samples of the search window, and the scan's samples inside it down to 1e-6 of
        its width from the scan's centre (features finer than the window's spacing near the
        centre; closer in, a slope that vanishes at the centre would read as a flat stretch
        on the window's scale)."""
        a, b = self.search_window()
        X = np.linspace(a, b, m)
        if not self.convex:
            sc = self.scan()
            S = sc.X
            X = np.union1d(X, S[(S > a) & (S < b) & (np.abs(S - sc.c0) >= 1e-6 * (b - a))])
        return X

    def _core(self, X):
        """Mask of the points X within one :attr:`scale` of the face's features (all of X for
        a face with two edges or a convex one), at least the sample nearest to them."""
        lo, hi = self.extent
        if self.convex or (math.isfinite(lo) and math.isfinite(hi)):
            return np.ones(X.shape, dtype=bool)
        f, s = self.scan().features, self.scale
        core = (X >= f[0] - s) & (X <= f[-1] + s)
        if not core.any():
            core[int(np.argmin(np.abs(X - f[0])))] = True
        return core

    def lowest_points(self, m=2001):
        """[(X, kind)]: the global minima of H on the face, each an interior point
        ("interior"), an edge ("left-edge", "right-edge") or a flat stretch ((c, d), "flat").

        Candidates come from the slope at m samples of the search window (exact where H
        itself would be a quadrature): a sign change from - to + (polished by a bounded
        minimisation), a run of samples where H' = 0 exactly, an edge where H rises inward;
        the lowest of them (within 1e-9 of the range of H over them) are returned.  A convex
        face stated homogeneous about x0 (``homogeneous``) is lowest at x0, or at the edge
        next to it, and a convex face with a zero slope at both its ends is flat, without a
        search.  Computed once per face and m."""
        found = self._lowest.get(m)
        if found is None:
            found = self._lowest[m] = tuple(self._lowest_points(m))
        return list(found)

    def _lowest_points(self, m):
        known = self._convex_lowest()
        if known is not None:
            return known
        a, b = self.search_window()
        X = self._window_samples(m)
        m = X.size
        dH = self.slope(X)
        # H' = 0 to rounding: relative to the slope's size near the face's features (over
        # the whole window, a face that steepens fast -- 0.01 e^X -- would read as flat)
        top = max(float(np.max(np.abs(dH[self._core(X)]))), np.finfo(float).tiny)
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
        """The zero of the slope between a and b, where it changes sign (Brent's method);
        where the two ends' slopes do not differ in sign (a change that was rounding noise
        of a slope from the height), the end with the smaller slope."""
        from scipy.optimize import brentq   # here: its import slows every start otherwise

        def f(x):
            return float(self.slope(np.array([x]))[0])
        fa, fb = f(a), f(b)
        if fa * fb > 0.0:
            return a if abs(fa) <= abs(fb) else b
        eps = np.finfo(float).eps
        return brentq(f, a, b,
                      xtol=max(4 * eps * max(abs(a), abs(b)), np.finfo(float).tiny),
                      rtol=4 * eps)

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
            X, dH = self._dip_samples()
            out = [x for x in self.breaks if a < x < b]
            out += [self._slope_zero(X[k], X[k + 1])
                    for k in np.flatnonzero((dH[:-1] < 0) & (dH[1:] > 0)).tolist()]
            self._dips = np.array(sorted(out))
        return self._dips

    def _dip_samples(self):
        """(X, H'(X)) at ``_DIP_SAMPLES`` samples of the search window (:meth:`dips`), one
        call of the slope for the valleys and the convexity test.  Computed once per face."""
        if self._dip_slope is None:
            X = self._window_samples(_DIP_SAMPLES)
            self._dip_slope = (X, np.asarray(self.slope(X), dtype=float))
        return self._dip_slope

    @property
    def opens_by_itself(self):
        """Whether one zone's gap opens by itself: the face is convex, stated by the punch
        (:attr:`convex`) or read from its slope, nondecreasing (to 1e-12 of its largest
        value in the search window) at the samples :meth:`dips` reads (20 times finer than
        the gap's), the scan's outside the window, and both sides of each break.  The gap is
        then not sampled for one zone (:func:`contact.continuation._inspect`): a slope that
        falls between these samples would have to fall between the gap's too.  Computed
        once per face."""
        if self._opens is None:
            self._opens = self.convex or self._convex_at_samples()
        return self._opens

    def _convex_at_samples(self):
        a, b = self.search_window()
        Xw, sw = self._dip_samples()
        # the scan's samples outside the window, and each break's two sides, where a slope
        # that jumps down shows it
        lo, hi = self.extent
        extra = [] if math.isfinite(lo) and math.isfinite(hi) else [self.scan().X]
        extra += [[x - h, x + h] for x in self.breaks for h in [1e-9 * max(abs(x), b - a)]]
        Xe = np.setdiff1d(np.concatenate(extra) if extra else np.zeros(0), Xw)
        Xe = Xe[(Xe >= lo) & (Xe <= hi)]
        X = np.concatenate([Xw, Xe])
        s = np.concatenate([sw, np.asarray(self.slope(Xe), dtype=float) if Xe.size else []])
        order = np.argsort(X, kind="stable")
        top = float(np.max(np.abs(s[(X >= a) & (X <= b)]), initial=0.0))
        return bool(np.all(np.diff(s[order]) >= -1e-12 * top))

    def sample_points(self, zones, m):
        """The points outside the zones where the gap is checked, ascending: m samples of
        the search window and the zones; :data:`_GAP_INNER` Chebyshev points inside each gap
        between neighbouring zones (a gap that closes like a square root at a merge is soon
        narrower than the samples' spacing) where fewer than that many samples fall in it;
        and outward from the window, :data:`_GAP_PER_DECADE` a decade of distance from the
        samples' spacing out to the edge, or on a side without one to the reach of the face's
        :meth:`scan` (the last of them is where the gap is shown to stay open beyond:
        :func:`contact.continuation._stays_open`)."""
        a, b = self.search_window()
        c1, dJ = zones[0].c, zones[-1].d
        a, b = min(a, c1), max(b, dJ)
        X = self._base_samples(a, b, m)
        # (where the evenly spaced samples suffice they are left alone: the gap's valleys are
        # located by parabolas through them)
        u = np.cos(np.pi * (np.arange(_GAP_INNER) + 0.5) / _GAP_INNER)
        parts = [X]
        for z0, z1 in zip(zones[:-1], zones[1:]):
            if z1.c - z0.d < _GAP_INNER * (b - a) / (m - 1):
                parts.append(0.5 * (z0.d + z1.c) + 0.5 * (z1.c - z0.d) * u)
        if len(parts) > 1:
            X = np.unique(np.concatenate(parts))
        return X[outside(zones, X)]

    def _base_samples(self, a, b, m):
        """m samples of [a, b], and outward from it :data:`_GAP_PER_DECADE` a decade of
        distance from the samples' spacing out to the edge, or on a side without one to the
        reach of the face's :meth:`scan`; ascending.  Kept for the last (a, b, m) asked (the
        search window, for every state whose zones lie inside it), with the face's rises
        between neighbours once they are needed (:meth:`_steps`)."""
        key = (a, b, m)
        if self._grid is not None and self._grid[0] == key:
            return self._grid[1]
        parts = [np.linspace(a, b, m)]
        lo, hi = self.extent
        reach = self.scan().reach if not self.convex else (a, b)
        for side, end, far in ((-1.0, a, max(lo, reach[0])), (1.0, b, min(hi, reach[1]))):
            dist = abs(far - end)
            near = (b - a) / (m - 1)
            if math.isfinite(dist) and dist > near:
                k = math.ceil(_GAP_PER_DECADE * math.log10(dist / near))
                d = np.minimum(near * 10.0 ** (np.arange(1, k + 1) / _GAP_PER_DECADE), dist)
                parts.append(end + side * d)
        X = np.unique(np.concatenate(parts))
        X.flags.writeable = False
        self._grid = (key, X, None)
        return X

    def rise_scale(self, state):
        X = np.concatenate([z.c + z.width * np.linspace(0.0, 1.0, 9) for z in state.zones])
        width = state.zones[-1].d - state.zones[0].c
        return max(float(np.max(np.abs(self.slope(X)))) * width, np.finfo(float).tiny)


class _SideScan:
    """The outward scan of one side of a face without an edge (:meth:`Face.scan`): the
    slope at growing distances r from the centre, the largest r where it does not rise
    outward, and the height along the side by the trapezoid rule (only to tell where the face
    has risen by its own distance: a criterion to stop, not a value used)."""

    def __init__(self, side):
        self.side = side            # -1: toward -X, +1: toward +X
        self.r, self.s = [], []
        self.r_wrong = 0.0          # the largest r where side * H' <= 0
        self.r_rising = 0.0         # the largest r where side * H' > 0
        self.r_moving = 0.0         # the largest r where H' != 0
        self.H = self.H_low = 0.0
        self.last = None            # (r, side * H') of the last sample
        self.rise_run = None
        self.done = False
        self.error = None
        self.height = None          # read the face through its height (Face.slope_from_height)
        self.H_prev = None          # ... its height at the last sample

    def _secants(self, c0, r):
        """(H(X_k) - H(X_k-1)) / (X_k - X_k-1) at X_k = c0 + side r_k (the first from c0):
        the slope as the height's samples give it."""
        H = np.asarray(self.height(c0 + self.side * r), dtype=float)
        r_prev = self.r[-1][-1] if self.r else 0.0
        Hs = np.concatenate([[self.H_prev], H])
        dH = np.diff(Hs)
        dX = self.side * np.diff(np.concatenate([[r_prev], r]))
        self.H_prev = float(H[-1])
        # a difference at the rounding of the heights says nothing of the slope: NaN, which
        # is neither rising nor a feature
        noise = np.abs(dH) <= 8 * np.finfo(float).eps * np.maximum(np.abs(Hs[1:]), np.abs(Hs[:-1]))
        return np.where(noise, np.nan, dH / dX)

    def extend(self, slope, c0, r, r_feat):
        """More distances r (ascending, whole decades); ``r_feat``: the outermost feature's
        distance so far, over both sides."""
        try:
            s = self._secants(c0, r) if self.height is not None else \
                np.asarray(slope(c0 + self.side * r), dtype=float)
        except ProfileCallableError as exc:
            if r.size > _PER_DECADE:        # again a decade at a time: where does it fail?
                for k in range(0, r.size, _PER_DECADE):
                    if not self.done:
                        self.extend(slope, c0, r[k:k + _PER_DECADE],
                                    max(r_feat, self.r_wrong))
                return
            # a slope that stops being finite (or raises) far out ends the scan where the
            # face has been seen to rise; anywhere else it is the user's to know about
            self.done = True
            if not self.seen_rising(r_feat, self.r[-1][-1] if self.r else 0.0):
                self.error = exc
            return
        self.r.append(r)
        self.s.append(s)
        up = self.side * s
        wrong = up <= 0.0               # (NaN: a height difference at rounding, see _secants)
        if wrong.any():
            self.r_wrong = max(self.r_wrong, float(r[wrong][-1]))
        if (up > 0.0).any():
            self.r_rising = max(self.r_rising, float(r[up > 0.0][-1]))
        if (s != 0.0).any():
            self.r_moving = max(self.r_moving, float(r[s != 0.0][-1]))
        rr = np.concatenate([[self.last[0]], r]) if self.last else r
        uu = np.concatenate([[self.last[1]], np.nan_to_num(up)]) if self.last else np.nan_to_num(up)
        steps = np.cumsum(0.5 * np.diff(rr) * (uu[1:] + uu[:-1]))
        H = self.H + (steps if self.last else np.concatenate([[0.0], steps]))
        low = np.minimum.accumulate(np.minimum(H, self.H_low))
        if self.rise_run is None:
            k = np.flatnonzero(H - low >= r)
            if k.size:
                self.rise_run = float(r[k[0]])
        self.H, self.H_low = float(H[-1]), float(low[-1])
        self.last = (float(r[-1]), float(up[-1]))
        self.done = self.seen_rising(max(r_feat, self.r_wrong), float(r[-1]))

    def seen_rising(self, r_feat, r_end):
        """Whether the face has been seen to rise outward far enough (:class:`Scan`)."""
        return (self.rise_run is not None and r_end >= 10.0 ** _PAST_RISE * self.rise_run
                and r_end >= 10.0 ** _PAST_FEATURES * max(r_feat, self.r_wrong))

    def last_decade(self):
        """The first distance of the outermost decade sampled."""
        return self.r[-1][-1] / 10.0 ** ((_PER_DECADE - 1) / _PER_DECADE)

    def falling(self):
        """Whether the outermost decade sampled does not rise outward."""
        return bool(self.r) and self.r_wrong >= self.last_decade()

    def samples(self, c0):
        if not self.r:
            return np.zeros(0), np.zeros(0)
        return c0 + self.side * np.concatenate(self.r), np.concatenate(self.s)


def _scan_verdict(state, c0, extent):
    """PunchGeometryError for a side that the scan leaves falling or flat, or whose slope
    failed before the face was seen to rise."""
    lo, hi = extent
    flat = {side: t.falling() and t.r_moving < t.last_decade() for side, t in state.items()}
    for side, t in state.items():
        if t.error is not None and (flat[side] or not t.falling()):
            raise t.error               # the slope failed where the face does not fall
    if len(state) == 2 and all(flat.values()) and all(t.r_moving == 0.0 for t in state.values()):
        raise PunchGeometryError(
            "the face is flat everywhere, with no edge: give the face's extent (face=) so "
            "that contact has an edge there")
    for side, t in state.items():
        name = "-X" if side < 0 else "+X"
        if not t.falling():
            continue
        if flat[side]:
            start = c0 + side * t.r_moving
            raise PunchGeometryError(
                f"the face is flat toward {name} from X = {start:.6g}, a side without an "
                "edge: give the face's extent (face=) so that contact has an edge there")
        a = c0 + side * t.r_rising
        b = c0 + side * t.r_rising * 10.0 ** (1.0 / _PER_DECADE)     # the next sample
        far = c0 + side * t.r[-1][-1]
        where = (f"stops rising outward between X = {a:.6g} and {b:.6g} and does not rise "
                 "again" if t.r_rising > 0.0 else f"does not rise outward from X = {c0:.6g}")
        raise PunchGeometryError(
            f"the face falls toward {name}: its height {where} (sampled out to X = {far:.6g}), so contact "
            f"cannot be shown to stay away from it; give the face's extent (face=) where it "
            "ends" + (f" ({t.error})" if t.error is not None else ""))
