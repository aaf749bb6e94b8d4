"""Property tests (hypothesis): invariants of the SIE solver and of the contact solve that
must hold for any admissible input, not only at the tabulated cases.

sie (equation a psi + (b/pi) PV int psi(t)/(t - s) dt = f):
  * the equation itself, with the Cauchy transform taken from ``Solution.cauchy`` (exact
    transforms of the Jacobi basis, not the collocation equations): a psi + b C[psi] = f;
  * reflection: psi~(s) = psi(-s) solves the equation with (a, -b), f(-s) and the end
    conditions swapped (substitute t -> -t in the principal value);
  * linearity in (f, total).
contact:
  * load balance and p >= 0 for any punch, speed below c_R, friction and direction;
  * a ProfilePunch given the face of a built-in punch reproduces it: the built-ins take
    the fixed-n / scaling-law path, the profile the adaptive-n / bracketing path;
  * power laws of the homogeneous faces: the contact length scales as P (wedge) and
    P^(1/2) (parabola), because Hc commutes with dilations.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

import contact
import sie

ENDS = ("bounded", "singular")
S_IN = np.linspace(-0.9, 0.9, 37)

coef = st.floats(min_value=-1.0, max_value=1.0, allow_nan=False, allow_subnormal=False)
ratio = st.floats(min_value=-20.0, max_value=20.0, allow_nan=False)     # a / b
b_mag = st.floats(min_value=0.05, max_value=20.0, allow_nan=False)
end = st.sampled_from(ENDS)


def _poly(cs):
    cs = np.asarray(cs, dtype=float)
    return lambda s: np.polynomial.polynomial.polyval(np.asarray(s, dtype=float), cs)


def _admissible(f, a, b, left, right, n):
    """For kappa = -1, shift f by a constant so that the solvability condition holds (the
    residual is linear in f); otherwise f itself."""
    e = sie.sie_exponents(a, b, left, right)
    if e.kappa != -1:
        return f
    eq = sie.Equation(a=a, b=b, left=left, right=right)
    r_f = eq.functionals(f, n=n).consistency
    r_1 = eq.functionals(lambda s: np.ones_like(s), n=n).consistency
    shift = -r_f / r_1
    return lambda s: f(s) + shift


@settings(max_examples=40, deadline=None)
@given(cs=st.lists(coef, min_size=1, max_size=6), r=ratio, bm=b_mag, sign=st.sampled_from((-1, 1)),
       left=end, right=end, total=coef)
@example(cs=[1.0, 0.5], r=1e-8, bm=1.0, sign=1, left="bounded", right="singular", total=0.0)
@example(cs=[0.3, -1.0, 0.2], r=-19.9, bm=0.05, sign=-1, left="singular", right="singular",
         total=1.0)
def test_equation_holds_through_the_cauchy_transform(cs, r, bm, sign, left, right, total):
    b = sign * bm
    a = r * b
    n = 16
    f0 = _poly(cs)
    f = _admissible(f0, a, b, left, right, n)
    kappa = sie.sie_exponents(a, b, left, right).kappa
    sol = sie.solve(f, a=a, b=b, n=n, left=left, right=right,
                    total=total if kappa == 1 else None)
    psi, cpsi = sol(S_IN), sol.cauchy(S_IN)
    lhs = a * psi + b * cpsi
    # the size of the terms: f may be a difference of O(1) numbers after the shift, and
    # C[psi] sums terms of the size of psi that may cancel (e.g. to 0 for a = 0, kappa = 1)
    scale = max(np.max(np.abs(f0(S_IN))), (abs(a) + abs(b)) * np.max(np.abs(psi)))
    assert np.max(np.abs(lhs - f(S_IN))) <= 1e-11 * scale
    if kappa == 1:
        assert abs(sol.integral() - total) <= 1e-13 * max(1.0, abs(total))


@settings(max_examples=40, deadline=None)
@given(cs=st.lists(coef, min_size=1, max_size=6), r=ratio, bm=b_mag, left=end, right=end,
       total=coef)
def test_reflection_swaps_the_ends_and_the_sign_of_b(cs, r, bm, left, right, total):
    a, b, n = r * bm, bm, 16
    f0 = _poly(cs)
    f = _admissible(f0, a, b, left, right, n)
    kappa = sie.sie_exponents(a, b, left, right).kappa
    tot = total if kappa == 1 else None
    sol = sie.solve(f, a=a, b=b, n=n, left=left, right=right, total=tot)
    mirrored = sie.solve(lambda s: f(-s), a=a, b=-b, n=n, left=right, right=left, total=tot)
    assert math.isclose(mirrored.alpha, sol.beta, abs_tol=1e-14)
    assert math.isclose(mirrored.beta, sol.alpha, abs_tol=1e-14)
    got, want = mirrored(S_IN), sol(-S_IN)
    scale = np.max(np.abs(want)) + np.max(np.abs(f0(S_IN))) / math.hypot(a, b) + abs(total)
    assert np.max(np.abs(got - want)) <= 1e-12 * scale


@settings(max_examples=30, deadline=None)
@given(c1=st.lists(coef, min_size=1, max_size=5), c2=st.lists(coef, min_size=1, max_size=5),
       lam=st.floats(min_value=-3.0, max_value=3.0), r=ratio, bm=b_mag, left=end, right=end,
       t1=coef, t2=coef)
def test_solution_is_linear_in_f_and_total(c1, c2, lam, r, bm, left, right, t1, t2):
    a, b, n = r * bm, bm, 12
    kappa = sie.sie_exponents(a, b, left, right).kappa
    f, g = _poly(c1), _poly(c2)

    def run(fun, tot):
        return sie.solve(fun, a=a, b=b, n=n, left=left, right=right,
                         total=tot if kappa == 1 else None)
    s1, s2 = run(f, t1), run(g, t2)
    s3 = run(lambda s: f(s) + lam * g(s), t1 + lam * t2)
    want = s1.coefficients + lam * s2.coefficients
    assert np.max(np.abs(s3.coefficients - want)) <= 1e-12 * max(np.max(np.abs(want)), 1.0)
    if kappa == -1:
        assert math.isclose(s3.consistency, s1.consistency + lam * s2.consistency,
                            rel_tol=1e-11, abs_tol=1e-13)


# ------------------------------------------------------------------------------------------
# contact
# ------------------------------------------------------------------------------------------
MAT = contact.zhou2014()
C_R = contact.rayleigh_speed(MAT)
speed = st.floats(min_value=0.0, max_value=0.97 * C_R)
friction = st.floats(min_value=0.0, max_value=0.8)
direction = st.sampled_from((-1, 1))
BUILT_IN = {
    "flat": (lambda: contact.FlatPunch(1.0),
             lambda: contact.ProfilePunch(np.zeros_like, corners=(-1.0, 1.0)), 1.0),
    "triangular": (lambda: contact.TriangularPunch(0.01),
                   lambda: contact.ProfilePunch(lambda X: np.full_like(X, 0.01),
                                                corners=(0.0, None)), 0.01),
    "parabolic": (lambda: contact.ParabolicPunch(100.0),
                  lambda: contact.ProfilePunch(lambda X: X / 100.0, corners=(0.0, None)), 0.01),
    "cylindrical": (lambda: contact.CylindricalPunch(100.0),
                    lambda: contact.ProfilePunch(lambda X: X / 100.0), 0.01),
}
kind = st.sampled_from(sorted(BUILT_IN))


@settings(max_examples=40, deadline=None)
@given(kind=kind, c=speed, mu=friction, d=direction,
       load_factor=st.floats(min_value=1e-3, max_value=1e3))
def test_load_balance_and_positive_pressure(kind, c, mu, d, load_factor):
    make, make_profile, load = BUILT_IN[kind]
    punch = make() if load_factor < 1.0 else make_profile()   # both search paths
    r = contact.solve(MAT, punch, load=load * load_factor, speed=c, friction=mu, direction=d)
    xl, xr = r.ends
    assert xl < xr
    assert r.load_check <= 1e-12
    X = 0.5 * (xl + xr) + 0.5 * (xr - xl) * np.cos(np.pi * (np.arange(200) + 0.5) / 200)
    assert np.all(r.pressure(X) >= 0.0)


@settings(max_examples=25, deadline=None)
@given(kind=kind, c=speed, mu=friction, d=direction)
@example(kind="cylindrical", c=0.0, mu=0.0, d=-1)
def test_profile_punch_reproduces_the_built_in_face(kind, c, mu, d):
    make, make_profile, load = BUILT_IN[kind]
    r = contact.solve(MAT, make(), load=load, speed=c, friction=mu, direction=d)
    q = contact.solve(MAT, make_profile(), load=load, speed=c, friction=mu, direction=d)
    xl, xr = r.ends
    L = xr - xl
    assert max(abs(q.ends[0] - xl), abs(q.ends[1] - xr)) <= 1e-12 * L
    X = 0.5 * (xl + xr) + 0.5 * L * np.linspace(-0.98, 0.98, 41)
    p = r.pressure(X)
    assert np.max(np.abs(q.pressure(X) - p)) <= 1e-10 * np.max(np.abs(p))


@settings(max_examples=25, deadline=None)
@given(kind=st.sampled_from(("triangular", "parabolic", "cylindrical")), c=speed, mu=friction,
       d=direction, lam=st.floats(min_value=0.01, max_value=100.0))
def test_contact_length_power_laws(kind, c, mu, d, lam):
    """With the faces as ProfilePunch (no scaling law known to the solver: every load is a
    fresh bracketing search), the ends must still follow the power laws."""
    _, make_profile, load = BUILT_IN[kind]
    power = 1.0 if kind == "triangular" else 0.5
    r1 = contact.solve(MAT, make_profile(), load=load, speed=c, friction=mu, direction=d)
    r2 = contact.solve(MAT, make_profile(), load=lam * load, speed=c, friction=mu, direction=d)
    scale = lam ** power
    # the faces are homogeneous about X = 0 (the corner, if any): ends scale about it
    L = r2.ends[1] - r2.ends[0]
    assert abs(r2.ends[1] - scale * r1.ends[1]) <= 1e-12 * L
    assert abs(r2.ends[0] - scale * r1.ends[0]) <= 1e-12 * L


@pytest.mark.parametrize("args, error", [
    ((0.0, 0.0, "bounded", "bounded"), sie.InvalidCoefficientError),        # b = 0: no SIE
    ((float("nan"), 1.0, "bounded", "bounded"), sie.InvalidCoefficientError),
    ((1.0, float("inf"), "bounded", "bounded"), sie.InvalidCoefficientError),
    ((0.3, 1.0, "free", "bounded"), sie.InvalidEndConditionError),
    ((0.3, 1.0, "bounded", None), sie.InvalidEndConditionError),
])
def test_sie_exponents_refuses_bad_input(args, error):
    with pytest.raises(error):
        sie.sie_exponents(*args)
