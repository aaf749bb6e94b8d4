"""A layered material's regular kernel through the contact equations (:mod:`contact.kernel`).

A material may add to its half-space's response a regular kernel k(X, t) (dv/dX gains
int k p) with its antiderivative K in X (the gap gains -int K p).  Kernels whose effect is
known exactly without the kernel path:

* constant k = kappa: dv/dX gains kappa P, which is the same as tilting the face by -kappa P
  (slope H' - kappa P), everywhere: in the equation, between the zones and in the gap
  outside them.  Compared with the homogeneous half-space and the tilted face, one zone (with
  and without friction) and the W face's two zones and their merge.
* linear k = kappa (X - t): dv/dX gains kappa (P X - M1), M1 = int t p, a tilt and a change
  of curvature that depend on the answer through M1: the solution with the kernel and the
  homogeneous solve of the face H' - kappa (P X - M1), M1 taken from the first, agree.
  Exercises the t-dependence of k and of K.

And: the residual diagnostic includes the kernel term; a material whose ``surface_kernel``
returns None is the homogeneous half-space bit for bit (the kernel-free paths); bad kernels
get a MaterialError naming the method; the closed forms refuse a layered material.
"""
from __future__ import annotations

import numpy as np
import pytest

import contact

MAT = contact.Isotropic(1.0, 0.3)


class Layered:
    """``inner``'s half-space plus the surface kernel ``kernel`` (None: none)."""

    def __init__(self, inner, kernel):
        self.inner, self.kernel, self.kernel_calls = inner, kernel, 0

    def surface_constants(self, c):
        return self.inner.surface_constants(c)

    def rayleigh_speed(self):
        return self.inner.rayleigh_speed()

    def limiting_speed(self):
        return self.inner.limiting_speed()

    def relative_speed(self, V):
        return self.inner.relative_speed(V)

    def half_space_modes(self, c):
        return self.inner.half_space_modes(c)

    def surface_kernel(self, c):
        self.kernel_calls += 1
        return self.kernel


class Constant:
    """k = kappa (no coupling of the tangential traction); sigma_XX gains s0 per unit p."""

    def __init__(self, kappa, s0=0.0):
        self.kappa, self.s0 = kappa, s0

    def slope(self, X, t):
        return np.full(np.shape(X), self.kappa)

    def deflection(self, X, t):
        return self.kappa * X + 0.0 * t

    def shear_slope(self, X, t):
        return np.zeros(np.shape(X))

    def shear_deflection(self, X, t):
        return np.zeros(np.shape(X))

    def sigma_xx(self, X, t):
        return np.full(np.shape(X), self.s0)

    def shear_sigma_xx(self, X, t):
        return np.zeros(np.shape(X))


class Linear:
    """k = kappa (X - t), K = kappa (X - t)^2 / 2."""

    def __init__(self, kappa):
        self.kappa = kappa

    def slope(self, X, t):
        return self.kappa * (X - t)

    def deflection(self, X, t):
        return 0.5 * self.kappa * (X - t) ** 2


def _w(X):
    return 0.2 * X ** 3 - 0.2 * X


def _same_pressure(r1, r2, tol):
    assert len(r1.zones) == len(r2.zones)
    for z1, z2 in zip(r1.zones, r2.zones):
        assert z1.kinds == z2.kinds
        w = z2.ends[1] - z2.ends[0]
        assert np.allclose(z1.ends, z2.ends, rtol=0, atol=tol * w), (z1.ends, z2.ends)
        X = np.linspace(*z2.ends, 41)[1:-1]
        p2 = r2.pressure(X)
        assert np.max(np.abs(r1.pressure(X) - p2)) <= tol * np.max(p2)


@pytest.mark.parametrize("friction", [0.0, 0.3])
@pytest.mark.parametrize("kappa", [0.3, -0.3])
def test_constant_kernel_is_a_tilt_one_zone(kappa, friction):
    P = 0.01
    r = contact.solve(Layered(MAT, Constant(kappa)), contact.ProfilePunch(lambda X: X),
                      load=P, speed=0.0, friction=friction)
    tilted = contact.solve(MAT, contact.ProfilePunch(lambda X: X - kappa * P), load=P,
                           speed=0.0, friction=friction)
    _same_pressure(r, tilted, 1e-12)
    assert r.residual < 1e-12


def test_constant_kernel_moving_orthotropic_flat():
    """A flat punch (two corners, index 1: the load is a side condition) on the paper's
    material at speed 0.6 with friction: the tilt changes the pressure and the SIFs, not
    the ends (a tilt below the one at which a corner lifts off)."""
    kappa, P = 0.01, 0.2
    m = contact.zhou2014()
    r = contact.solve(Layered(m, Constant(kappa)), contact.ProfilePunch(
        lambda X: np.zeros_like(X), face=(-1.0, 1.0)), load=P, speed=0.6, friction=0.3)
    tilted = contact.solve(m, contact.ProfilePunch(lambda X: np.zeros_like(X) - kappa * P,
                                                   face=(-1.0, 1.0)),
                           load=P, speed=0.6, friction=0.3)
    _same_pressure(r, tilted, 1e-11)
    for side in ("left", "right"):
        assert r.sif[side] == pytest.approx(tilted.sif[side], rel=1e-11)
    assert abs(r.sif["left"] / r.sif["right"] - 1.0) > 0.2     # the tilt shows in them


@pytest.mark.parametrize("kappa,P", [(0.05, 0.05), (-0.05, 0.05), (0.05, 0.3)])
def test_constant_kernel_is_a_tilt_two_zones(kappa, P):
    """The W face: two zones at P = 0.05 (the gap condition between them carries the
    kernel's K), one after their merge at P = 0.3 (found by the continuation through the gap
    check, which carries it too)."""
    r = contact.solve(Layered(MAT, Constant(kappa)), contact.ProfilePunch(_w, face=(-2.0, 2.0)),
                      load=P, speed=0.0)
    tilted = contact.solve(MAT, contact.ProfilePunch(lambda X: _w(X) - kappa * P,
                                                     face=(-2.0, 2.0)), load=P, speed=0.0)
    _same_pressure(r, tilted, 1e-11)


def test_linear_kernel_self_consistent():
    """k = kappa (X - t) on an asymmetric face: the homogeneous solve of the face whose
    slope is H' - kappa (P X - M1), with M1 = int t p of the layered solution, is that
    solution."""
    kappa, P = 0.4, 0.02
    face = lambda X: X + 0.8 * X ** 2                        # noqa: E731
    r = contact.solve(Layered(MAT, Linear(kappa)), contact.ProfilePunch(face, face=(-1, 1)),
                      load=P, speed=0.0)
    M1 = float(r.solution.kernel_integral(lambda s, t: t + 0.0 * s, np.array([0.0]))[0])
    assert abs(M1) > 1e-2 * P * r.half_width               # the kernel's t-part matters
    ref = contact.solve(MAT, contact.ProfilePunch(lambda X: face(X) - kappa * (P * X - M1),
                                                  face=(-1, 1)), load=P, speed=0.0)
    _same_pressure(r, ref, 1e-11)


def test_residual_includes_the_kernel():
    """The residual of the layered solution is at rounding, and the same pressure put into
    the equation without the kernel term misses it by kappa P of the slope's scale."""
    kappa, P = 0.3, 0.01
    r = contact.solve(Layered(MAT, Constant(kappa)), contact.ProfilePunch(lambda X: X),
                      load=P, speed=0.0)
    assert r.residual < 1e-12
    X = np.linspace(*r.ends, 11)[1:-1]
    F = r.solution.cauchy_limit(X)
    bare = np.max(np.abs(r.constants.N11 * F.real - X))      # N11 Hc[p] - H'
    assert bare == pytest.approx(kappa * P, rel=1e-9)


def test_sigma_xx_with_the_kernel():
    kappa, s0, P = 0.3, 0.7, 0.01
    r = contact.solve(Layered(MAT, Constant(kappa, s0)), contact.ProfilePunch(lambda X: X),
                      load=P, speed=0.0)
    X = np.array([r.center, r.ends[1] + 0.5])
    assert np.allclose(r.sigma_xx(X), r.constants.N21 * r.pressure(X) + s0 * P, rtol=1e-13,
                       atol=1e-15)
    without = contact.solve(Layered(MAT, Linear(kappa)), contact.ProfilePunch(lambda X: X),
                            load=P, speed=0.0)
    with pytest.raises(contact.ContactInputError, match="sigma_xx"):
        without.sigma_xx(X)


def test_no_kernel_is_the_half_space_bit_for_bit():
    """surface_kernel returning None: the kernel-free paths, the same numbers."""
    punch = contact.CylindricalPunch(100.0)
    kw = dict(load=0.01, speed=0.6, friction=0.3)
    m = Layered(contact.zhou2014(), None)
    r, ref = contact.solve(m, punch, **kw), contact.solve(contact.zhou2014(), punch, **kw)
    assert r.ends == ref.ends and r.residual == ref.residual
    w = contact.ProfilePunch(_w, face=(-2.0, 2.0))
    r = contact.solve(Layered(MAT, None), w, load=0.05, speed=0.0)
    ref = contact.solve(MAT, w, load=0.05, speed=0.0)
    assert [z.ends for z in r.zones] == [z.ends for z in ref.zones]


def test_batch_and_load_curve_with_a_kernel():
    """solve_batch (the lockstep step declines a layered case: it goes alone) and
    load_curve give solve's numbers."""
    kappa = 0.3
    m = Layered(MAT, Constant(kappa))
    punch = contact.ProfilePunch(lambda X: X)
    loads = [0.005, 0.01]
    batch = contact.solve_batch(m, punch, load=loads, speed=0.0, n=16)
    curve = contact.load_curve(m, punch, loads, speed=0.0)
    for P, rb, rc in zip(loads, batch, curve):
        single = contact.solve(m, punch, load=P, speed=0.0)
        assert rb.ends == pytest.approx(single.ends, abs=1e-13)
        assert rc.ends == pytest.approx(single.ends, abs=1e-13)
        tilted = contact.solve(MAT, contact.ProfilePunch(lambda X, P=P: X - kappa * P),
                               load=P, speed=0.0)
        assert rc.ends == pytest.approx(tilted.ends, abs=1e-12)


def test_closed_form_refuses_a_kernel():
    with pytest.raises(contact.ContactInputError, match="surface kernel"):
        contact.solve(Layered(MAT, Constant(0.1)), contact.CylindricalPunch(1.0), load=0.01,
                      speed=0.0, method="closed_form")


class _Bad(Constant):
    def __init__(self, what):
        super().__init__(0.1)
        self.what = what

    def slope(self, X, t):
        if self.what == "nan":
            return np.where(X > 0.0, np.nan, 0.1)
        if self.what == "shape":
            return np.zeros(3)
        if self.what == "complex":
            return np.full(np.shape(X), 0.1 + 1e-3j)
        if self.what == "raise":
            raise KeyError("layer")
        return super().slope(X, t)


@pytest.mark.parametrize("what,match", [
    ("nan", "not finite"), ("shape", "shape"), ("complex", "real numbers"),
    ("raise", "raised KeyError")])
def test_bad_kernel_values_are_named(what, match):
    with pytest.raises(contact.MaterialError, match=rf"Layered\.surface_kernel\(0\.0\)\.slope.*{match}"):
        contact.solve(Layered(MAT, _Bad(what)), contact.ProfilePunch(lambda X: X), load=0.01,
                      speed=0.0)


class _NoShear:
    def slope(self, X, t):
        return np.zeros(np.shape(X))

    def deflection(self, X, t):
        return np.zeros(np.shape(X))


@pytest.mark.parametrize("kernel,friction,match", [
    ("text", 0.0, "lacks slope, deflection"),
    (_NoShear(), 0.3, "lacks shear_slope, shear_deflection.*friction")])
def test_bad_kernel_objects_are_named(kernel, friction, match):
    with pytest.raises(contact.MaterialError, match=match):
        contact.solve(Layered(MAT, kernel), contact.ProfilePunch(lambda X: X), load=0.01,
                      speed=0.0, friction=friction)


def test_surface_kernel_raising_is_named():
    class Raising(Layered):
        def surface_kernel(self, c):
            raise RuntimeError("no layer data")
    with pytest.raises(contact.MaterialError, match=r"surface_kernel\(0\.0\) raised RuntimeError"):
        contact.solve(Raising(MAT, None), contact.ProfilePunch(lambda X: X), load=0.01,
                      speed=0.0)


def test_frictionless_kernel_needs_no_shear_part():
    r = contact.solve(Layered(MAT, _NoShear()), contact.ProfilePunch(lambda X: X), load=0.01,
                      speed=0.0)
    ref = contact.solve(MAT, contact.ProfilePunch(lambda X: X), load=0.01, speed=0.0)
    assert r.ends == pytest.approx(ref.ends, abs=1e-14)
