"""The Cauchy transform, its boundary values and the log potential of solutions with an
explicit end exponent (sie.FixedEndSolution) and of junction solutions (sie.JunctionSolution,
regular part included), against mpmath quadrature of the definitions.

References independent of the transforms: psi = w phi with the coefficients of phi given
(the explicit-exponent solution is manufactured so that its coefficients are those, to
rounding; the junction solution's own coefficients, pieces and regular part, are summed by
mpmath's Jacobi polynomials), and

- C(z) = (1/pi) int psi/(t - z) dt by mpmath.quad in the distance s = 1 + t from the left
  end (exact at the ends), split at the point of L nearest to z and geometrically (ratio 4)
  around it on the scale of z's distance to L;
- H[psi](x) by symmetric subtraction: int_0^1 [psi(x + m s) - psi(x - m s)] / s ds over
  [x - m, x + m] (m the distance to the nearer end), the rest a plain integral;
- V(x) = (1/pi) int psi log|x - t| dt split at x (the log at the ends of the pieces), with
  breaks graded toward x and the ends.

The mpmath values take ~2 minutes: they are stored in
tests/reference/fixed_end_transform_refs.json, keyed by the case and the point;
SIE_TEST_RECOMPUTE_REFS=1 computes them again and rewrites the file.
"""
from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
from _stored import StoredReferences

import sie
from sie.fixed_ends import hilbert_images

_REFS = StoredReferences("fixed_end_transform_refs.json")
_stored = _REFS.complex



# ---------------------------------------------------------------------------------------
# mpmath references for psi given on a list of intervals as functions of the distance
# ---------------------------------------------------------------------------------------
class _MpPsi:
    """psi as a sum of parts, each (c, d, alpha, beta, coefficients) on [c, d]: (1-u)^alpha
    (1+u)^beta sum c_k P_k^{(alpha,beta)}(u), u local; evaluated by mpmath from the distance
    to c (exact next to the ends)."""

    def __init__(self, parts):
        self.parts = [(mp.mpf(c), mp.mpf(d), mp.mpf(a), mp.mpf(b), [mp.mpf(v) for v in cf])
                      for c, d, a, b, cf in parts]
        self.lo = min(p[0] for p in self.parts)
        self.hi = max(p[1] for p in self.parts)
        self.breaks = sorted({p[0] for p in self.parts} | {p[1] for p in self.parts})

    def __call__(self, t):
        out = mp.mpf(0)
        for c, d, a, b, cf in self.parts:
            if c < t < d:
                h = (d - c) / 2
                dl, dr = (t - c) / h, (d - t) / h
                u = dl - 1
                out += dr ** a * dl ** b * sum(ck * mp.jacobi(k, a, b, u)
                                               for k, ck in enumerate(cf))
        return out

    def _split(self, x, d, lo, hi):
        """lo, hi, the breaks of L and x -+ d 4^j between them."""
        pts = {lo, hi} | {b for b in self.breaks if lo < b < hi}
        if lo < x < hi:
            pts.add(x)
        for j in range(60):
            for sg in (-1, 1):
                v = x + sg * d * 4 ** j
                if lo < v < hi:
                    pts.add(v)
        return sorted(pts)

    def cauchy(self, z):
        z = mp.mpc(z)
        x = min(max(z.real, self.lo), self.hi)
        d = abs(z - x)
        return mp.quad(lambda t: self(t) / (t - z), self._split(x, d, self.lo, self.hi)) / mp.pi

    def hilbert(self, x):
        x = mp.mpf(x)
        near = [b for b in self.breaks]
        m = min(abs(x - b) for b in near)
        sym = mp.quad(lambda s: (self(x + m * s) - self(x - m * s)) / s, [0, 0.125, 0.5, 1])
        rest = mp.mpf(0)
        f = lambda t: self(t) / (t - x)          # noqa: E731
        if x - m > self.lo:
            rest += mp.quad(f, self._split(x, m, self.lo, x - m))
        if x + m < self.hi:
            rest += mp.quad(f, self._split(x, m, x + m, self.hi))
        return (sym + rest) / mp.pi

    def log_potential(self, x):
        x = mp.mpf(x)
        total = mp.mpf(0)
        lo, hi = self.lo, self.hi
        for a, b in ((lo, min(x, hi)), (max(x, lo), hi)):
            if b <= a:
                continue
            if x <= a:          # integrate in the distance from x: the log at its end
                g = lambda s: self(x + s) * mp.log(s)          # noqa: E731
                pts = [p - x for p in self._split(x, max(a - x, mp.mpf(10) ** -8), a, b)]
            else:
                g = lambda s: self(x - s) * mp.log(s)          # noqa: E731
                pts = sorted(x - p for p in self._split(x, max(x - b, mp.mpf(10) ** -8), a, b))
            total += mp.quad(g, pts)
        return total / mp.pi


# ---------------------------------------------------------------------------------------
# the explicit-exponent case
# ---------------------------------------------------------------------------------------
ALPHA, BETA = 0.3, -0.2                    # right, left (explicit)
COEF = np.array([1.0, -0.4, 0.25, 0.1, -0.05, 0.02])


@pytest.fixture(scope="module")
def fixed():
    """b H[psi] = f with psi = w phi, phi = sum COEF_k P_k^{(0.3,-0.2)}: f from the exact
    images (:func:`sie.fixed_ends.hilbert_images`), so that the solution's coefficients are
    COEF to rounding (checked)."""
    n = COEF.size
    sol = sie.solve(lambda s: hilbert_images(n, ALPHA, BETA, np.asarray(s, float)) @ COEF,
                    a=0.0, b=1.0, n=n, left=BETA, right=ALPHA)
    assert isinstance(sol, sie.FixedEndSolution)
    np.testing.assert_allclose(sol.coefficients, COEF, rtol=0, atol=1e-14)
    mp.mp.dps = 30
    return sol, _MpPsi([(-1.0, 1.0, ALPHA, BETA, COEF)])


_Z_OFF = [2.5, 1.5, 1 + 1e-6, -1 - 1e-6, 30.0 + 2j, 0.3 + 1e-3j, 0.3 - 1e-9j, 1 + 1e-6j,
          0.5 + 1.2j, -0.9 - 0.5j, 1.99j, -1 + 1e-7 + 1e-9j]
_X_IN = [0.3, -0.7, 0.0, 1 - 1e-6, -1 + 1e-6, 0.999]
_X_LOG = [0.3, -0.7, 0.0, 1 - 1e-6, -1 + 1e-6, 1.0, -1.0, 1 + 1e-6, -1 - 1e-6, 3.0, -1.5]


def test_fixed_cauchy_off_L(fixed):
    sol, ref = fixed
    z = np.array(_Z_OFF, dtype=complex)
    got = sol.cauchy(z)
    want = np.array([_stored(f"fixed C {v!r}", lambda v=v: ref.cauchy(v)) for v in _Z_OFF])
    np.testing.assert_allclose(got, want, rtol=2e-15 * 8, atol=0)
    # real points outside: a real result, the same values
    xr = np.array([2.5, 1.5, 1 + 1e-6, -1 - 1e-6])
    gr = sol.cauchy(xr)
    assert gr.dtype == float
    np.testing.assert_allclose(gr, want[:4].real, rtol=1e-15 * 8, atol=0)


def test_fixed_principal_value_and_plemelj(fixed):
    sol, ref = fixed
    x = np.array(_X_IN)
    want = np.array([_stored(f"fixed H {v!r}", lambda v=v: ref.hilbert(v)).real for v in _X_IN])
    got = sol.cauchy(x)
    scale = np.max(np.abs(want))
    assert np.max(np.abs(got - want)) < 1e-14 * scale
    # Plemelj: the limits from above and below, H +- i psi
    psi = np.array([float(ref(mp.mpf(v))) for v in _X_IN])
    up, down = sol.cauchy_limit(x), sol.cauchy_limit(x, side=-1)
    np.testing.assert_allclose(up.real, got, rtol=0, atol=0)
    np.testing.assert_allclose(up.imag, psi, rtol=1e-13, atol=0)
    np.testing.assert_array_equal(down, up.conj())
    # the jump of C across L is 2 i psi: against C at x +- 1e-11 i (off-L branch)
    zc = x[:3] + 1e-11j
    jump = sol.cauchy(zc) - sol.cauchy(zc.conj())
    np.testing.assert_allclose(jump.imag, 2 * psi[:3], rtol=1e-10)
    # off L the limit is the real transform
    np.testing.assert_array_equal(sol.cauchy_limit(np.array([2.5])), sol.cauchy(np.array([2.5])))


def test_fixed_log_potential(fixed):
    sol, ref = fixed
    x = np.array(_X_LOG)
    want = np.array([_stored(f"fixed V {v!r}", lambda v=v: ref.log_potential(v)).real
                     for v in _X_LOG])
    got = sol.log_potential(x)
    assert np.max(np.abs(got - want)) < 1e-14 * np.max(np.abs(want))


def test_fixed_transform_errors(fixed):
    sol, _ = fixed
    with pytest.raises(sie.EvaluationPointError):
        sol.cauchy(1.0)
    with pytest.raises(sie.EvaluationPointError):
        sol.cauchy(0.5 + 0j)
    with pytest.raises(sie.EvaluationPointError):
        sol.cauchy_limit(-1.0)
    with pytest.raises(sie.EvaluationPointError):
        sol.cauchy_limit(0.5, side=2)
    with pytest.raises(sie.EvaluationPointError):
        sol.log_potential(0.5 + 1j)


def test_zero_exponent_at_an_end():
    """left = 0.0 (the edge crack's mouth): psi = (1-t)^0.4 (phi = 1 - t/2), transforms at
    points next to that end against mpmath."""
    a, coef = -0.4, np.array([0.8, -0.5])
    # right = -0.4 (singular), left = 0 (bounded): index 0
    sol = sie.solve(lambda s: hilbert_images(2, a, 0.0, np.asarray(s, float)) @ coef,
                    a=0.0, b=1.0, n=2, left=0.0, right=a)
    np.testing.assert_allclose(sol.coefficients, coef, atol=1e-14)
    mp.mp.dps = 30
    ref = _MpPsi([(-1.0, 1.0, a, 0.0, coef)])
    z = [-1 - 1e-6, -1 + 1e-6j, -0.5 + 1e-8j]
    want = np.array([_stored(f"zero C {v!r}", lambda v=v: ref.cauchy(v)) for v in z])
    np.testing.assert_allclose(sol.cauchy(np.array(z, dtype=complex)), want, rtol=1e-14)
    xs = [-1.0, -1 + 1e-6, 0.2, -1 - 1e-3]
    wv = np.array([_stored(f"zero V {v!r}", lambda v=v: ref.log_potential(v)).real for v in xs])
    assert np.max(np.abs(sol.log_potential(np.array(xs)) - wv)) < 1e-14 * np.max(np.abs(wv))


# ---------------------------------------------------------------------------------------
# a junction solution with its regular part
# ---------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def junction():
    sol = sie.solve_junctions(np.cos, [0.0, 1.0], [1.0, 1.0], [(-1.0, 0.0), (0.0, 1.0)],
                              n=12, left="singular", right="singular",
                              junctions=["bounded"], regular=4)
    assert sol.regular is not None
    parts = [(p.interval.c, p.interval.d, p.alpha, p.beta, p.coefficients)
             for p in sol.pieces]
    r = sol.regular
    parts.append((r.interval.c, r.interval.d, r.alpha, r.beta, r.coefficients))
    mp.mp.dps = 30
    # the reference's coefficients are the solution's: keyed by them (rounded), so that a
    # change of the solve recomputes instead of comparing against stale values
    tag = "%.12e" % float(sum(np.sum(np.abs(p[4])) for p in parts))
    return sol, _MpPsi(parts), tag


def test_junction_transforms(junction):
    sol, ref, tag = junction
    z = [1.5, -1 - 1e-6, 0.5 + 1e-3j, 1e-7 + 1e-9j, -0.5 - 0.8j]
    want = np.array([_stored(f"junction {tag} C {v!r}", lambda v=v: ref.cauchy(v))
                     for v in z])
    got = sol.cauchy(np.array(z, dtype=complex))
    assert np.max(np.abs(got - want) / np.abs(want)) < 1e-13
    x = [-0.5, 0.4, 1e-6, -1e-6, 0.999999]
    wh = np.array([_stored(f"junction {tag} H {v!r}", lambda v=v: ref.hilbert(v)).real
                   for v in x])
    gh = sol.cauchy(np.array(x))
    assert np.max(np.abs(gh - wh)) < 1e-13 * np.max(np.abs(wh))
    lim = sol.cauchy_limit(np.array(x))
    np.testing.assert_allclose(lim.imag, sol(np.array(x)), rtol=0, atol=0)
    xv = [-0.5, 0.0, 1e-6, 1.0, 2.0, -1.0]
    wv = np.array([_stored(f"junction {tag} V {v!r}", lambda v=v: ref.log_potential(v)).real
                   for v in xv])
    gv = sol.log_potential(np.array(xv))
    assert np.max(np.abs(gv - wv)) < 1e-13 * np.max(np.abs(wv))
    with pytest.raises(sie.EvaluationPointError):
        sol.cauchy(0.0)                       # the junction is an end of both pieces
