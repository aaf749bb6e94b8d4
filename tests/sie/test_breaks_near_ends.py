"""Breaks next to an end of the interval: phi from the collocation solution and its
pointwise correction (:mod:`sie.remainder`) stays at its converged value as n grows.

Next to an end a degree-n Jacobi series oscillates like cos(n theta), x = cos(theta), so the
pieces of the correction's graded rules between a break and a nearby end span far more of
theta than of x; and with breaks the coefficients are kept as solved (the correction
inverts the rest of exactly those coefficients).  References:

* the same problem at n = 48, where the values have converged (they agree with n = 96 and
  192 to rounding);
* for a = 0 (alpha, beta = +-1/2) the classical inversion of the dominant equation
  (1/pi) PV int psi(t) / (t - x) dt = g(x) (Muskhelishvili, Singular Integral Equations,
  1953, sec. 88 and 107-110; Erdogan, Gupta & Cook, in Methods of Analysis and Solutions
  of Crack Problems, 1973, eq. (7.17)-(7.19)):

      bounded at both ends:
          psi(x) = -(1/pi) sqrt(1 - x^2) PV int g(t) / (sqrt(1 - t^2) (t - x)) dt,
      singular at both:
          psi(x) = [-(1/pi) PV int sqrt(1 - t^2) g(t) / (t - x) dt + total / pi]
                   / sqrt(1 - x^2),

  the principal values with g(x) subtracted (PV int 1 / (sqrt(1 - t^2) (t - x)) dt = 0,
  PV int sqrt(1 - t^2) / (t - x) dt = -pi x), in t = cos(theta) by mpmath's tanh-sinh
  quadrature split at the break and at x: no part of sie;
* a contact problem (flat punch with rounded edges at a tiny load) whose right-hand side
  vanishes except beyond the breaks, against itself at n = 48.
"""
from __future__ import annotations

import warnings

import mpmath
import numpy as np
import pytest

import sie

X = np.array([-0.9, 0.0, 0.5])
ENDS = [("bounded", "bounded"), ("singular", "singular"), ("bounded", "singular"),
        ("singular", "bounded")]


def _kinked(s0):
    """A kink at s0 (its linear part beyond s0, toward the nearer end) plus a line."""
    if s0 > 0:
        return lambda s: np.where(s > s0, s - s0, 0.0) + 0.3 * s
    return lambda s: np.where(s < s0, s0 - s, 0.0) + 0.3 * s


def _values(f, n, s0, a, left, right):
    kw = dict(total=0.7) if left == right == "singular" else {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", sie.InconsistentEquationWarning)
        sol = sie.solve(f, a=a, b=-1.0, n=n, left=left, right=right, breaks=(s0,), **kw)
    return sol(X)


def _check_converged(s0, a, ends, ns, tol):
    f = _kinked(s0)
    ref = _values(f, 48, s0, a, *ends)
    for n in ns:
        v = _values(f, n, s0, a, *ends)
        err = np.max(np.abs(v - ref)) / np.max(np.abs(ref))
        assert err <= tol, (n, err)


@pytest.mark.parametrize("ends", ENDS)
@pytest.mark.parametrize("a", [0.0, 0.2, -0.7])
@pytest.mark.parametrize("s0", [1 - 1e-2, 1 - 1e-4, -1 + 1e-3, -1 + 1e-6])
def test_values_converge_in_n(s0, a, ends):
    """phi at n = 768 equals phi at n = 48 to 1e-12 (it had drifted by 2e-10 to 5e-9)."""
    _check_converged(s0, a, ends, (768,), 1e-12)


@pytest.mark.slow
@pytest.mark.parametrize("s0,a,ends", [
    (1 - 1e-2, 0.2, ("bounded", "bounded")),
    (1 - 1e-5, 0.0, ("singular", "bounded")),
    (-1 + 1e-6, -0.7, ("singular", "singular")),
    (-1 + 1e-6, -0.7, ("singular", "bounded")),
])
def test_values_converge_to_large_n(s0, a, ends):
    """Up to n = 3072 (the last two: a kink whose coefficients fall below the rounding
    plateau, which chopping would have cut from the series but not from the correction)."""
    _check_converged(s0, a, ends, (1536, 3072), 1e-12)


def _inversion(s0, x, kind, total):
    """psi at x for a = 0, b = -1 and f = the kink at s0 over its distance to the end
    (module docstring), by mpmath."""
    mpmath.mp.dps = 30
    d = 1 - abs(s0)
    sign = 1 if s0 > 0 else -1

    def g(t):                                   # f / b
        return -max(sign * (t - s0), 0) / d
    xm = mpmath.mpf(x)
    gx = g(xm)
    pts = sorted([mpmath.mpf(0), mpmath.acos(xm), mpmath.acos(mpmath.mpf(s0)), mpmath.pi])
    if kind == "bounded":
        q = mpmath.quad(lambda th: (g(mpmath.cos(th)) - gx) / (mpmath.cos(th) - xm), pts)
        return float(-mpmath.sqrt(1 - xm ** 2) / mpmath.pi * q)
    q = mpmath.quad(lambda th: mpmath.sin(th) ** 2 * (g(mpmath.cos(th)) - gx)
                    / (mpmath.cos(th) - xm), pts) - mpmath.pi * xm * gx
    return float((-q + total) / mpmath.pi / mpmath.sqrt(1 - xm ** 2))


@pytest.mark.parametrize("kind", ["bounded", "singular"])
@pytest.mark.parametrize("s0", [1 - 1e-3, 1 - 1e-6, -1 + 1e-6])
def test_against_inversion_formula(s0, kind):
    """a = 0, f nonzero only beyond the break (size 1 at the end): psi against the closed
    inversion to 1e-13 of max abs(f) at n = 48 and 768 (it was off by 4e-4 at n = 768)."""
    total = 0.7 if kind == "singular" else 0.0
    ref = np.array([_inversion(s0, x, kind, total) for x in X])
    d, sign = 1 - abs(s0), 1 if s0 > 0 else -1

    def f(s):
        return np.maximum(sign * (s - s0), 0.0) / d
    kw = dict(total=total) if kind == "singular" else {}
    for n in (48, 768):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", sie.InconsistentEquationWarning)
            v = sie.solve(f, a=0.0, b=-1.0, n=n, left=kind, right=kind, breaks=(s0,), **kw)(X)
        assert np.max(np.abs(v - ref)) <= 1e-13, (n, v - ref)


def test_contact_rounded_flat_tiny_load():
    """A flat punch rounded beyond abs(X) = 1/2 (radius 3) at load 1e-6: the contact ends
    lie 4e-5 (relative) beyond the breaks, and the pressure at n = 192, 384, 768 equals that
    at n = 48 to 1e-10 (it was off by 8e-3 at n = 768)."""
    import contact
    b, radius = 0.5, 3.0
    face = contact.ProfilePunch(
        lambda X: np.where(np.abs(X) > b, np.sign(X) * (np.abs(X) - b) / radius, 0.0),
        height=lambda X: np.where(np.abs(X) > b, (np.abs(X) - b) ** 2 / (2 * radius), 0.0),
        breaks=(-b, b), face=(-3.0, 3.0))
    mat = contact.zhou2014()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r0 = contact.solve(mat, face, load=1e-6, speed=0.0, friction=0.0, n=48)
        c, d = r0.ends
        x = c + (d - c) * np.array([1e-5, 0.3, 0.5])
        p0 = r0.pressure(x)
        for n in (192, 384, 768):
            r = contact.solve(mat, face, load=1e-6, speed=0.0, friction=0.0, n=n)
            assert np.max(np.abs(r.pressure(x) / p0 - 1)) <= 1e-10, n
