"""The integration line L = [c_1, d_1] U ... U [c_J, d_J] and per-interval arguments."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import (InvalidBreakpointError, InvalidIntervalError, PerIntervalArgumentError,
                     describe_value, is_number, real_array)

__all__ = ["Interval", "check_intervals", "per_interval", "split_breaks"]


@dataclass(frozen=True)
class Interval:
    """[c, d] with the affine map s = m + h u onto u in [-1, 1] (m = (c+d)/2, h = (d-c)/2).

    The Cauchy integral is invariant under the map:
    (1/pi) int_c^d psi(t)/(t - s) dt = (1/pi) int_{-1}^{1} psi(m + h u)/(u - v) du, v = (s-m)/h.
    """
    c: float
    d: float

    @property
    def m(self) -> float:
        return 0.5 * (self.c + self.d)

    @property
    def h(self) -> float:
        return 0.5 * (self.d - self.c)

    def local(self, s):
        """v = (s - m)/h; exactly +-1 at the ends."""
        s = np.asarray(s)
        v = (s - self.m) / self.h
        if np.isrealobj(v):
            v = np.where(s == self.d, 1.0, np.where(s == self.c, -1.0, v))
        return v

    def local_ends(self, s):
        """(v - 1, v + 1) = ((s - d)/h, (s - c)/h): the local distances to the ends, to full
        relative precision next to an end (v + 1 formed from v would keep only eps/|v + 1|)."""
        s = np.asarray(s)
        return (s - self.d) / self.h, (s - self.c) / self.h

    def real(self, u):
        """s = m + h u."""
        return self.m + self.h * np.asarray(u)

    def contains(self, s):
        """c <= s <= d (closed)."""
        s = np.asarray(s)
        return (s >= self.c) & (s <= self.d)


UNIT = (Interval(-1.0, 1.0),)


def check_intervals(intervals):
    """Validate ``intervals`` (finite, c < d, ascending, disjoint and not touching) and return
    a tuple of :class:`Interval`."""
    if intervals is None:
        return UNIT
    try:
        pairs = [tuple(p) for p in intervals]
    except TypeError:
        raise InvalidIntervalError(
            f"intervals must be a sequence of (c, d) pairs, got {intervals!r}") from None
    if not pairs:
        raise InvalidIntervalError("intervals must hold at least one (c, d) pair, got none")
    out = []
    for j, p in enumerate(pairs):
        if len(p) != 2:
            raise InvalidIntervalError(f"intervals[{j}] must be a pair (c, d), got {p!r}")
        if not (is_number(p[0]) and is_number(p[1])):
            bad = p[0] if not is_number(p[0]) else p[1]
            raise InvalidIntervalError(
                f"intervals[{j}] must hold two real numbers, got {describe_value(bad)} in "
                f"{p!r}")
        try:
            c, d = float(p[0]), float(p[1])
        except (TypeError, ValueError, OverflowError):
            raise InvalidIntervalError(
                f"intervals[{j}] must hold two real numbers, got {p!r}") from None
        if not (math.isfinite(c) and math.isfinite(d)):
            raise InvalidIntervalError(f"intervals[{j}] = {p!r}: the ends must be finite")
        if not c < d:
            raise InvalidIntervalError(f"intervals[{j}] = {p!r}: need c < d")
        if out and not c > out[-1].d:
            prev = out[-1]
            what = "touches" if c == prev.d else ("overlaps" if c > prev.c else "is not after")
            raise InvalidIntervalError(
                f"intervals[{j}] = ({c!r}, {d!r}) {what} intervals[{j - 1}] = ({prev.c!r}, "
                f"{prev.d!r}): intervals must be disjoint, with gaps, in ascending order "
                "(two intervals that touch are one interval)")
        out.append(Interval(c, d))
    return tuple(out)


def per_interval(name, value, J):
    """One value per interval: a scalar (or a string) is repeated J times; a sequence must
    have exactly J entries."""
    if isinstance(value, (str, bytes, int, float)) or value is None or np.ndim(value) == 0:
        return [value] * J
    vals = list(value)
    if len(vals) != J:
        raise PerIntervalArgumentError(
            f"{name} must be one value for all {J} intervals or a sequence of {J} "
            f"(one per interval), got {len(vals)} entries")
    return vals


def split_breaks(breaks, intervals):
    """Breaks (real coordinates) per interval, in local coordinates, sorted, without repeats.

    Each break must lie strictly inside one interval."""
    vals = None
    if isinstance(breaks, (tuple, list)):
        if len(breaks) == 0:
            return [np.empty(0) for _ in intervals]
        if all(type(x) is float for x in breaks):
            vals = list(breaks)     # Python floats already: no conversion through numpy
    if vals is None:
        vals = real_array("breaks", breaks, InvalidBreakpointError).ravel().tolist()
    if not all(math.isfinite(x) for x in vals):
        raise InvalidBreakpointError(f"breaks must be finite, got {vals}")
    out = [[] for _ in intervals]
    # Python floats: the local coordinate (x - m) / h is Interval.local's (x lies strictly
    # inside, off both ends), without numpy's cost per scalar (a contact search splits the
    # breaks of every trial zone)
    for x in vals:
        for j, iv in enumerate(intervals):
            if iv.c < x < iv.d:
                u = (x - 0.5 * (iv.c + iv.d)) / (0.5 * (iv.d - iv.c))
                if abs(u) < 1.0:
                    out[j].append(u)
                break
        else:
            where = " or ".join(f"({iv.c!r}, {iv.d!r})" for iv in intervals)
            cls = InvalidBreakpointError if len(intervals) == 1 else PerIntervalArgumentError
            raise cls(f"breaks must lie strictly inside {where}; got {float(x)!r}")
    res = []
    for u in out:
        u = sorted(u)
        res.append(np.array([v for k, v in enumerate(u) if k == 0 or v > u[k - 1]], dtype=float))
    return res
