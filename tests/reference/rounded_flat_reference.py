"""Closed-form reference: frictionless flat punch with rounded edges on an elastic half-plane.

Reference
---------
M. Ciavarella, D. A. Hills and G. Monno, "The influence of rounded edges on indentation by a
flat punch", Proceedings of the Institution of Mechanical Engineers, Part C: Journal of
Mechanical Engineering Science 212(4) (1998) 319-328 (DOI 10.1243/0954406981521259).
The paper works with the angle phi0 = arcsin(b/a).  Written with the Hills & Nowell
composite compliance A = 2(1 - nu1^2)/E1 + 2(1 - nu2^2)/E2 (A = 2/E* = -N11 for a rigid
punch), the load relation derived below is 2 P A R / a^2 = pi - 2 phi0 - sin(2 phi0).  The
paper's equation numbers and exact printed form are not quoted here: the formulas were
derived independently (steps in the docstrings) in this library's convention and are checked
numerically in ``tests/reference/test_rounded_flat_reference.py``.

Problem, in the library's convention (``contact.solver``, static, mu = 0)
-----------------------------------------------------------------------
Gap profile H(X) = 0 for |X| <= b, (|X| - b)^2 / (2 R) for |X| > b; contact |X| < a, a > b:

    (N11/pi) PV int_{-a}^{a} p(t) / (t - X) dt = H'(X),   |X| < a,
    int p = P,   p bounded (-> 0) at X = +-a.

Sign of N11: for an isotropic static half-plane ``contact.surface_constants`` gives
N11 = -2 (1 - nu^2) / E = -2 / E*  (negative).  A compressive load P > 0 on a convex profile
therefore needs N11 < 0; the formulas are written for the equation exactly as above, so
they hold for either sign, and P has the sign of -N11.

Notation used throughout: eps = arccos(b/a) = pi/2 - phi0 (0 < eps <= pi/2),
g(eps) = eps - sin(eps) cos(eps) = (2 eps - sin(2 eps)) / 2  (evaluated without cancellation).

Results
-------
    P(a) = -a^2 g(eps) / (N11 R) = -[a^2 (pi/2 - phi0) - b sqrt(a^2 - b^2)] / (N11 R)

    p(X) = -1/(pi N11 R) * [ (pi - 2 phi0) sqrt(a^2 - X^2)
                             + (X - b) ln| (a^2 - X b + sqrt(a^2-X^2) sqrt(a^2-b^2)) / (a (b - X)) |
                             - (X + b) ln| (a^2 + X b + sqrt(a^2-X^2) sqrt(a^2-b^2)) / (a (b + X)) | ]

b = 0 gives Hertz: a^2 = -2 P R N11 / pi = 4 P R / (pi E*), p = sqrt(a^2 - X^2) / (-N11 R).
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["load_for_half_width", "half_width_for_load", "pressure", "profile_slope"]


# --------------------------------------------------------------------------
# helpers (scalar; ``lib`` is the math module or mpmath)
# --------------------------------------------------------------------------
def _is_mp(*args) -> bool:
    try:
        import mpmath
    except ImportError:  # pragma: no cover
        return False
    return any(isinstance(v, (mpmath.mpf, mpmath.mpc)) for v in args)


def _lib(*args):
    if _is_mp(*args):
        import mpmath
        return mpmath, mpmath.mp.eps
    return math, 2.0 ** -53


def _check(a, b, R, N11):
    if not (b >= 0 and R > 0 and N11 != 0):
        raise ValueError(f"need b >= 0, R > 0, N11 != 0; got b={b!r}, R={R!r}, N11={N11!r}")
    if not a > b:
        raise ValueError(f"the contact half-width a must exceed the flat half-width b: a={a!r}, b={b!r}")


def _eps(a, b, lib):
    """eps = arccos(b/a) = pi/2 - arcsin(b/a), accurate also for a -> b."""
    return lib.atan2(lib.sqrt((a - b) * (a + b)), b)


def _g(eps, lib, tiny):
    """g(eps) = eps - sin(eps) cos(eps) = (u - sin u)/2 with u = 2 eps, no cancellation."""
    u = 2 * eps
    if u < 1:
        # u - sin u = sum_{k>=1} (-1)^(k+1) u^(2k+1) / (2k+1)!
        term = u ** 3 / 6
        s = term
        k = 1
        while abs(term) > tiny * abs(s):
            term = -term * u * u / ((2 * k + 2) * (2 * k + 3))
            s += term
            k += 1
        return s / 2
    return (u - lib.sin(u)) / 2


def _atanh_minus_id(z, num, den, lib, tiny):
    """artanh(z) - z for 0 <= z < 1: its series for z < 1/2, else ln(num/den) - z, where the
    caller passes artanh(z) = ln(num/den) with num, den free of cancellation (see
    :func:`pressure`)."""
    if z < 0.5:
        # artanh(z) - z = sum_{k>=1} z^(2k+1) / (2k+1)
        z2 = z * z
        s = 0 * z
        k = 1
        power = z * z2
        while True:
            term = power / (2 * k + 1)
            s += term
            if term <= tiny * s:
                return s
            power *= z2
            k += 1
    return lib.log(num / den) - z


def _pressure_scalar(x, a, b, R, N11, lib, tiny):
    if not -a < x < a:
        return 0 * x
    sx = lib.sqrt((a - x) * (a + x))
    sb = lib.sqrt((a - b) * (a + b))
    eps = _eps(a, b, lib)
    se, ce = lib.sin(eps), lib.cos(eps)
    # linear (in z) part of the two logarithms combined with (pi - 2 phi0) sqrt(a^2 - X^2):
    # 2 sx [ g(eps) + sin^3(eps) cos(eps) X^2 / ((a^2 - X^2) + X^2 sin^2(eps)) ]
    lin = 2 * sx * (_g(eps, lib, tiny) + se ** 3 * ce * x * x / (sx * sx + x * x * se * se))
    u = sx * sb
    # c1 = a^2 - X b, c2 = a^2 + X b (> 0 for |X| < a), written without cancellation
    c1 = a * (a - x) + x * (a - b)
    c2 = a * (a + x) - x * (a - b)
    rest = 0 * x
    if x != b:
        # ln|A1| = artanh(z1) = ln((c1 + u) / (a |b - x|)),  z1 = u / c1
        rest += (x - b) * _atanh_minus_id(u / c1, c1 + u, a * abs(b - x), lib, tiny)
    if x != -b:
        rest -= (x + b) * _atanh_minus_id(u / c2, c2 + u, a * abs(b + x), lib, tiny)
    return -(lin + rest) / (lib.pi * N11 * R)


# --------------------------------------------------------------------------
# public functions
# --------------------------------------------------------------------------
def profile_slope(X, b, R):
    """H'(X) = sign(X) (|X| - b)/R for |X| > b, 0 otherwise (vectorised; mpmath scalars too)."""
    if _is_mp(X, b, R):
        return (X - b) / R if X > b else ((X + b) / R if X < -b else 0 * X)
    X = np.asarray(X, dtype=float)
    return np.where(np.abs(X) > b, np.sign(X) * (np.abs(X) - b) / R, 0.0)


def load_for_half_width(a, b, R, N11):
    """Load P that gives the contact half-width a (a > b >= 0).

    Citation: Ciavarella, Hills & Monno, Proc. IMechE C 212(4) (1998) 319-328 (module doc).

    Derivation
    ----------
    1. Write f = H'/N11, so (1/pi) PV int_{-a}^{a} p(t)/(t - X) dt = f(X).  The general
       solution of the finite Hilbert transform (unbounded at both ends) is
           p(X) = [C - (1/pi) PV int sqrt(a^2 - t^2) f(t)/(t - X) dt] / sqrt(a^2 - X^2),
       and int p = pi C (check: p = 1/sqrt(a^2-t^2) gives f = 0; p = sqrt(a^2-t^2) gives
       f = -X and C = a^2/2).
    2. Bounded at X = a and X = -a: the bracket must vanish at both ends,
           C = -(1/pi) int sqrt((a+t)/(a-t)) f dt = (1/pi) int sqrt((a-t)/(a+t)) f dt.
       Their difference is the consistency condition int f / sqrt(a^2 - t^2) dt = 0 (true for
       the odd H'), their mean gives C = -(1/pi) int t f(t)/sqrt(a^2 - t^2) dt, so
           P = -(1/N11) int_{-a}^{a} t H'(t) / sqrt(a^2 - t^2) dt.
       Cylinder (H' = t/R): P = -pi a^2 / (2 N11 R); with N11 = -2/E* this is Hertz,
       a^2 = 4 P R / (pi E*).
    3. Rounded flat: H' = sign(t)(|t| - b)/R beyond |t| = b, so with t = a sin(theta),
       b = a sin(phi0):
           int = (2/R) int_b^a t (t - b) / sqrt(a^2 - t^2) dt
               = (2/R) [ (a^2/2)(pi/2 - phi0) + (b/2) sqrt(a^2-b^2) - b sqrt(a^2-b^2) ]
               = [a^2 (pi/2 - phi0) - b sqrt(a^2 - b^2)] / R = a^2 g(eps) / R,
       eps = pi/2 - phi0, g(eps) = eps - sin(eps) cos(eps).
    Result: P = -a^2 g(eps) / (N11 R).  dP/da = -2 a eps / (N11 R) (the b-terms cancel), so
    P(a) is strictly monotone.  As a -> b, g ~ (2/3) eps^3 and P -> 0; g is evaluated from
    its series for eps < 1/2, so P has full relative accuracy there too.

    Accepts floats or mpmath numbers (then evaluated in mpmath).
    """
    _check(a, b, R, N11)
    lib, tiny = _lib(a, b, R, N11)
    eps = _eps(a, b, lib)
    return -a * a * _g(eps, lib, tiny) / (N11 * R)


def half_width_for_load(P, b, R, N11):
    """Contact half-width a > b for the load P (P N11 < 0), the root of P(a) = P.

    F(a) = a^2 g(eps(a)) - Q with Q = -P N11 R > 0 is increasing and convex on a > b
    (F' = 2 a eps, F'' = 2 eps + 2 b / sqrt(a^2 - b^2) > 0), so Newton's method started from
    a point with F >= 0 decreases monotonically to the root.  The start is found by
    expanding a bracket from b + a_H (a_H = sqrt(2 Q / pi), the Hertz half-width);
    iteration stops when a step is below 1e-16 a (or F rounds to <= 0).  The root is
    well conditioned: |da/a| ~ 1e-16 (eps^2 / 3 for small eps).  b = 0 returns a_H.
    """
    if not (b >= 0 and R > 0 and N11 != 0):
        raise ValueError(f"need b >= 0, R > 0, N11 != 0; got b={b!r}, R={R!r}, N11={N11!r}")
    Q = -P * N11 * R
    if not Q > 0:
        raise ValueError(f"need P * N11 < 0 (compressive load; N11 = -2/E* < 0 for an "
                         f"isotropic half-plane), got P={P!r}, N11={N11!r}")
    lib, tiny = _lib(P, b, R, N11)
    aH = lib.sqrt(2 * Q / lib.pi)
    if b == 0:
        return aH

    def F(a):
        return a * a * _g(_eps(a, b, lib), lib, tiny) - Q

    hi = b + aH
    while F(hi) < 0:
        hi = b + 2 * (hi - b)
    a = hi
    for _ in range(500):
        f = F(a)
        if f <= 0:
            return a
        step = f / (2 * a * _eps(a, b, lib))
        a_new = a - step
        if not a_new > b:                      # cannot happen for exact arithmetic
            a_new = (a + b) / 2
        if abs(a - a_new) <= 0.25 * tiny * a:
            return a_new
        a = a_new
    raise RuntimeError("half_width_for_load: Newton iteration did not converge")  # pragma: no cover


def pressure(X, a, b, R, N11):
    """Contact pressure p(X) for contact half-width a > b (zero for |X| >= a).

    Derivation (continuing :func:`load_for_half_width`)
    ---------------------------------------------------
    1. With both ends bounded the inversion becomes
           p(X) = -(1/pi) sqrt(a^2 - X^2) PV int_{-a}^{a} f(t) / (sqrt(a^2 - t^2) (t - X)) dt,
       f = H'/N11 (check: f = -X gives p = sqrt(a^2 - X^2)).
    2. Split (t -/+ b)/(t - X) = 1 + (X -/+ b)/(t - X) on t > b and t < -b.  The "1"
       parts give int_{b<|t|<a} dt/sqrt(a^2-t^2) = pi - 2 phi0; the rest needs
           PV int dt / ((t - X) sqrt(a^2 - t^2))
               = -(1/sqrt(a^2-X^2)) ln| (a^2 - X t + sqrt(a^2-X^2) sqrt(a^2-t^2)) / (t - X) |,
       whose value at t = +-a is ln(a) for every |X| < a.  Collecting terms:
           p(X) = -1/(pi N11 R) [ (pi - 2 phi0) sqrt(a^2 - X^2)
                                  + (X - b) ln|A1| - (X + b) ln|A2| ],
           A1 = (a^2 - X b + sqrt(a^2-X^2) sqrt(a^2-b^2)) / (a (b - X)),
           A2 = (a^2 + X b + sqrt(a^2-X^2) sqrt(a^2-b^2)) / (a (b + X)).
       In angles X = a sin(phi), b = a sin(phi0): A1 = cos((phi+phi0)/2) / sin((phi0-phi)/2),
       A2 = cos((phi-phi0)/2) / sin((phi+phi0)/2).
    3. p(+-a) = 0 (|A1| = |A2| = 1 there); p is continuous at X = +-b ((X-b) ln|X-b| -> 0);
       b = 0 gives Hertz, p = sqrt(a^2 - X^2) / (-N11 R).
    4. Flat-punch limit (R -> 0 at fixed P, so a -> b, eps -> 0 with P ~ (2/3) a^2 eps^3 /
       (-N11 R)): p(X) -> P / (pi sqrt(b^2 - X^2)) for |X| < b, the rigid flat punch, whose
       pressure is singular at the corners.

    Evaluation without cancellation: (a^2 - Xb)^2 - (a^2-X^2)(a^2-b^2) = a^2 (X-b)^2, so
    ln|A1| = artanh(z1), z1 = sqrt(a^2-X^2) sqrt(a^2-b^2) / (a^2 - X b) in [0, 1) (and
    ln|A2| = artanh(z2) likewise).  The terms linear in z1, z2 cancel the (pi - 2 phi0)
    term to leading order when eps is small; combined analytically they give
        2 sqrt(a^2-X^2) [ g(eps) + sin^3(eps) cos(eps) X^2 / ((a^2-X^2) + X^2 sin^2(eps)) ],
    a sum of non-negative terms; the remainders artanh(z) - z are summed from their series
    for z < 1/2 and from the log form otherwise.

    X may be a float, an array (returns an array) or an mpmath number (evaluated in mpmath,
    as are a, b, R, N11 if they are mpmath numbers).
    """
    _check(a, b, R, N11)
    if _is_mp(X, a, b, R, N11):
        import mpmath
        return _pressure_scalar(mpmath.mpf(X), a, b, R, N11, mpmath, mpmath.mp.eps)
    a, b, R, N11 = float(a), float(b), float(R), float(N11)
    Xa = np.asarray(X, dtype=float)
    out = np.array([_pressure_scalar(float(x), a, b, R, N11, math, 2.0 ** -53)
                    for x in Xa.ravel()]).reshape(Xa.shape)
    return out if out.ndim else float(out)
