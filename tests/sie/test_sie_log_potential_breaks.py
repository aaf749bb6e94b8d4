"""The log potential of a solution with breaks, V(x) = (1/pi) int psi(t) log|x - t| dt, at
the points the contact gap check asks for, and the compiled sums behind it.

* ``Solution.log_potential`` against an independent quadrature of the defining integral:
  composite Gauss-Legendre (numpy's ``leggauss``) on pieces split at the ends, the breaks and
  x, graded geometrically toward each split (ratio 0.15, down to 1e-16 of the piece: the
  kinks of psi at the breaks, the logarithm at x, and x just beyond an end are resolved),
  the end factor (1 -+ t)^e absorbed by u = (1 -+ t)^(1+e)/(1+e) on the end pieces.  psi is
  ``Solution.__call__``'s (its own accuracy is test_breaks.py's).  The reference shares no
  code with the library's route (a rule graded toward the breaks and ends, delta_phi(end)
  subtracted and added back in closed form, sums by clusters of nodes, V' = -H inside).
  Errors over (1/pi) int |psi| (1 + |log|x - t||) dt (test_sie_breaks_transforms.py's
  yardstick), at points inside, beside the breaks, 1e-15..1e-3 inside and beyond each end,
  at the ends, and far.
* The clustered sum of :func:`sie.remainder._log_sums` against the same sum taken term by
  term with ``math.fsum`` (exactly rounded): the expansion's truncation and the moments'
  rounding are what it adds.
* The batch projection kernel at a size where a Vandermonde matrix would no longer be
  formed, against the scalar path of ``sie.solve``.
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import sie
from sie import remainder

GRADING = 0.15
LEVELS = 20                         # 0.15^20 ~ 3e-17 of a piece left ungraded
NODES = 30                          # Gauss-Legendre nodes per graded piece
GL = np.polynomial.legendre.leggauss(NODES)
TOL = 1e-14

C = 0.41                            # the breaks +-C: a flat with rounded corners


def rounded_flat(s):
    """dv/dX of a flat punch with rounded corners in the zone's coordinate: 0 on |s| < C,
    (|s| - C) sign(s) beyond (odd: the index -1 solvability condition holds)."""
    s = np.asarray(s, dtype=float)
    return np.where(np.abs(s) < C, 0.0, (np.abs(s) - C) * np.sign(s))


CASES = {
    # free ends (index -1), frictionless: the contact gap check's case
    "free ends a=0": dict(a=0.0, b=1.0, n=24, left="bounded", right="bounded"),
    # one corner, friction: index 0, a singular left end
    "corner a=0.6": dict(a=0.6, b=1.0, n=24, left="singular", right="bounded"),
    # two corners: index 1
    "two corners a=-0.4": dict(a=-0.4, b=1.0, n=32, left="singular", right="singular",
                               total=0.7),
}


def solved(name):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.InconsistentEquationWarning)
        return sie.solve(rounded_flat, breaks=(-C, C), **CASES[name])


def _graded_offsets(length):
    """Offsets s in [0, length] from a split point, graded toward it (ratio GRADING, down to
    3e-17 of the length): composite Gauss-Legendre nodes and weights."""
    edges = np.unique(np.concatenate([[0.0, length],
                                      length * GRADING ** np.arange(1, LEVELS + 1)]))
    u, w = GL
    lo, hi = edges[:-1, None], edges[1:, None]
    half = 0.5 * (hi - lo)
    return (lo + half * (u + 1.0)).ravel(), (half * w).ravel()


def _half_piece(sol, x, point, length, toward):
    """Nodes t, weights times (1-t)^alpha (1+t)^beta, and |x - t| on the half of a piece
    next to ``point`` (the other end at point + toward * length), graded toward it, with the
    offset s = |t - point| exact; next to an end (+-1) in u = s^(1+e)/(1+e), s^e ds = du,
    which absorbs the end factor."""
    al, be = sol.alpha, sol.beta
    if abs(point) == 1.0:
        e = al if point == 1.0 else be
        u, w = _graded_offsets(length ** (1.0 + e) / (1.0 + e))
        s = ((1.0 + e) * u) ** (1.0 / (1.0 + e))
        t = point + toward * s
        factor = (2.0 - s) ** (be if point == 1.0 else al)
    else:
        s, w = _graded_offsets(length)
        t = point + toward * s
        # 1 -+ t from the point's own 1 -+ point (exact next to an end, where t is not)
        factor = ((1.0 - point) - toward * s) ** al * ((1.0 + point) + toward * s) ** be
    # |x - t| from the offset when x is the point itself or beyond it (exact next to it)
    beyond = (x - point) * toward <= 0.0
    dist = abs(x - point) + s if beyond else np.abs(x - t)
    return t, w * factor, dist


def reference(sol, xs):
    """(1/pi) int psi(t) log|x - t| dt and (1/pi) int |psi| (1 + |log|x - t||) dt at each x
    of ``xs`` by the graded composite rule of the module docstring (phi called once)."""
    parts = []                                      # (owner, t, weight, |x - t|)
    for i, x in enumerate(xs):
        splits = sorted({-1.0, 1.0, -C, C} | ({x} if -1.0 < x < 1.0 else set()))
        for lo, hi in zip(splits[:-1], splits[1:]):
            for point, toward in ((lo, 1.0), (hi, -1.0)):
                t, w, dist = _half_piece(sol, x, point, 0.5 * (hi - lo), toward)
                parts.append((np.full(t.size, i), t, w, dist))
    owner, t, w, dist = (np.concatenate(a) for a in zip(*parts))
    phi = sol.phi(np.clip(t, -1.0, 1.0))
    log = np.log(dist)
    value = [math.fsum(v) for v in np.split(w * phi * log, np.flatnonzero(np.diff(owner)) + 1)]
    scale = [math.fsum(v) for v in np.split(w * np.abs(phi) * (1.0 + np.abs(log)),
                                            np.flatnonzero(np.diff(owner)) + 1)]
    return np.array(value) / math.pi, np.array(scale) / math.pi


def gap_check_points(sol):
    """Inside, beside the breaks, next to the ends on both sides, the ends, far.  Inside
    next to a singular end no closer than 1e-3: there the polynomial part's closed form
    loses eps |V'| ~ eps / sqrt(1 -+ x) (without breaks as well; test_sie_breaks_transforms.py
    stops at 1e-3 for the same reason)."""
    near = np.geomspace(1e-15, 1e-3, 5)
    inside_right = 1.0 - (near if sol.alpha > 0 else near[-1:])
    inside_left = -1.0 + (near if sol.beta > 0 else near[-1:])
    return np.concatenate([[-0.7, 0.0, 0.2, 0.9], -C + np.array([-1e-9, 1e-9]),
                           C + np.array([-1e-12, 1e-6]), inside_right, inside_left,
                           [-1.0, 1.0], 1.0 + near, -1.0 - near, [1.5, -3.0, 40.0]])


@pytest.mark.parametrize("name", list(CASES))
def test_log_potential_against_quadrature(name):
    """V at the points of :func:`gap_check_points` to 1e-14 of its yardstick."""
    sol = solved(name)
    x = gap_check_points(sol)
    got = sol.log_potential(x)
    ref, scale = reference(sol, x)
    err = np.abs(got - ref) / scale
    k = int(np.argmax(err))
    print(f"[sie-log-potential-breaks] {name}: max error / yardstick {err[k]:.1e} at {x[k]!r}")
    assert err[k] <= TOL, (name, x[k], got[k], ref[k])


def test_clustered_log_sum_is_the_direct_sum():
    """sum_j c_j log(z + e_j) by clusters (:func:`sie.remainder._log_sums`) against the same
    sum term by term, exactly rounded (math.fsum), to 1e-16 of sum |c_j log(z + e_j)| +
    sum |c_j|: offsets graded toward 0 over 15 decades, as the nodes of a rule graded toward
    an end, with coefficients of both signs; z from 0 (an end itself) to far."""
    rng = np.random.default_rng(7)
    e = np.sort(np.concatenate([np.geomspace(1e-15, 2.0, 400), rng.uniform(0.0, 2.0, 600)]))
    c = rng.normal(size=e.size) * np.sqrt(e)
    starts = remainder._cluster_starts(e)
    k = starts.size - 1
    centers, radii = np.empty(k), np.empty(k)
    terms = np.empty(k, dtype=np.int64)
    moments = np.empty((k, remainder._LOG_TERMS + 1))
    remainder._log_moments(e, c, starts, centers, radii, terms, moments)
    assert np.all(np.diff(starts) > 0) and starts[-1] == e.size
    assert np.all(radii <= centers / 3.0 * (1.0 + 1e-15))          # every point sees r <= 1/3
    assert k < 60 and np.max(np.diff(starts)) > 100                  # sums by clusters
    z = np.concatenate([[0.0], np.geomspace(1e-16, 1e3, 40)])
    got = np.empty(z.size)
    remainder._log_sums(z, e, c, starts, centers, radii, terms, moments, got)
    for zi, g in zip(z, got):
        terms_ = c * np.log(zi + e)
        ref = math.fsum(terms_)
        assert abs(g - ref) <= 1e-16 * (math.fsum(np.abs(terms_)) + math.fsum(np.abs(c))), \
            (zi, g, ref)


def test_batch_projection_at_large_n():
    """An sie.Equation with a case axis at n = 1500 (the projections by the recurrence over
    all nodes) against the sie.solve of each equation alone (Vandermonde blocks and BLAS),
    to 1e-13 of the largest coefficient."""
    f = lambda s: np.cos(2.0 * s) + 0.3 * s
    iv = [(-1.0, 1.0), (-0.5, 2.0)]
    eqs = sie.Equation(a=[0.4, -0.8], b=1.0, left="singular", right="bounded",
                       intervals=[[p] for p in iv])
    batch = eqs.solve(f, n=1500)
    for i, (c, d) in enumerate(iv):
        one = sie.solve(f, a=float(eqs.a[i]), b=1.0, n=1500, left="singular", right="bounded",
                        intervals=[(c, d)], check_residual=False)
        ref = one.pieces[0].coefficients
        assert np.max(np.abs(batch.coefficients[i] - ref)) <= 1e-13 * np.max(np.abs(ref))
