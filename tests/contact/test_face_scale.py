"""A result does not depend on the unit lengths are written in, and a face is explored far
enough to be sure of its gap.

The same problem with every length multiplied by lam = 10^k (k = -3..3: the face's X and
heights, so H_lam(X) = lam H(X / lam) and its slope H'(X / lam)) and the load by lam (a
pressure is unchanged, a force per unit length scales with length) has its contact ends
multiplied by lam and nothing else changed.  (The search for the lowest point and the gap
check once looked at a window fixed in the user's unit: a protrusion at X = 40 written in
mm was pressed 0.95 into the half-space, touching at the tip instead.)
"""
import numpy as np
import pytest

import contact

MAT = contact.Isotropic(1.0, 0.3)
LAMS = [10.0 ** k for k in range(-3, 4)]

# a face rising like X^4 with a protrusion at X = 4 lower than its tip: it touches there
A, X1, W1 = 0.8, 4.0, 0.5


def _h(X):
    return X ** 4 / 400 - A * np.exp(-((X - X1) / W1) ** 2)


def _dh(X):
    return X ** 3 / 100 + A * 2 * (X - X1) / W1 ** 2 * np.exp(-((X - X1) / W1) ** 2)


def _rounded_flat(X, b=0.5, R=2.0):
    return np.where(np.abs(X) < b, 0.0, (np.abs(X) - b) * np.sign(X) / R)


def _w(X):
    return 0.2 * X * (X * X - 1.0)


def _sampled(lam):
    X = lam * np.linspace(-2.0, 2.0, 41)
    return contact.ProfilePunch.from_samples(X, lam * (1.0 - np.cos(X / lam)))


FACES = {
    # name: (punch at scale lam, load at lam = 1[, the scales lam tried: LAMS by default])
    "slope, protrusion far out": (lambda lam: contact.ProfilePunch(
        lambda X: _dh(X / lam)), 0.05),
    "slope and height, its extent": (lambda lam: contact.ProfilePunch(
        lambda X: _dh(X / lam), height=lambda X: lam * _h(X / lam),
        face=(-6.0 * lam, 6.0 * lam)), 0.05),
    # (its slope is a finite difference, ~40 ms a call: three scales, the ends of the range)
    "height alone, protrusion far out": (lambda lam: contact.ProfilePunch(
        height=lambda X: lam * _h(X / lam)), 0.05, [1e-3, 1.0, 1e3]),
    "slope, breaks": (lambda lam: contact.ProfilePunch(
        lambda X: _rounded_flat(X / lam), breaks=(-0.5 * lam, 0.5 * lam)), 0.3),
    # a face that steepens fast from its one edge (its slope spans 20 decades over the
    # window: read as flat there once)
    "exponential, one edge": (lambda lam: contact.ProfilePunch(
        lambda X: 0.01 * np.exp(X / lam), corners=(0.0, None)), 0.15),
    "W face, its extent": (lambda lam: contact.ProfilePunch(
        lambda X: _w(X / lam), face=(-2.0 * lam, 2.0 * lam)), 0.01),
    "samples": (_sampled, 0.2),
    "cylindrical punch": (lambda lam: contact.CylindricalPunch(100.0 * lam), 0.01),
}


@pytest.mark.parametrize("name", list(FACES))
@pytest.mark.slow
def test_the_result_does_not_depend_on_the_length_unit(name):
    make, load, *lams = FACES[name]
    ref = None
    for lam in (lams[0] if lams else LAMS):
        r = contact.solve(MAT, make(lam), load=load * lam, speed=0.3, friction=0.2)
        ends = np.array([z.ends for z in r.zones]) / lam
        if ref is None:
            ref, p_ref = ends, r.pressure(ends.mean(axis=1) * lam)
            continue
        assert ends.shape == ref.shape, (lam, ends, ref)
        np.testing.assert_allclose(ends, ref, rtol=0, atol=1e-9 * np.ptp(ref), err_msg=str(lam))
        np.testing.assert_allclose(r.pressure(ends.mean(axis=1) * lam), p_ref, rtol=1e-8)


def test_the_protrusion_far_out_is_where_the_face_touches():
    """The protrusion is the face's lowest point (H(4) = -0.16 < H(0) = 0): the contact is
    there, at any scale (touching at X = 0 was returned for lam >= 3)."""
    for lam in (1.0, 10.0, 1000.0):
        r = contact.solve(MAT, contact.ProfilePunch(lambda X: _dh(X / lam)), load=0.05 * lam,
                          speed=0.0)
        (z,) = r.zones
        assert 3.5 * lam < z.ends[0] < z.ends[1] < 4.5 * lam


def test_a_face_that_turns_down_far_out_is_refused():
    """A cubic spline through samples of a cylinder on [-2, 2], used past its samples: its
    slope changes sign far out and the face falls without bound (the result pressed 3.4 into
    the half-space at X = -18).  Refused, saying where and what to pass; with its extent it
    solves."""
    from scipy.interpolate import CubicSpline
    X = np.linspace(-2.0, 2.0, 9)
    H = X * X / 2 + 0.02 * X ** 3 * (X < 0)
    spline = CubicSpline(X, H, bc_type="natural")
    dspline = spline.derivative()
    falls = contact.ProfilePunch(lambda x: dspline(x), height=lambda x: spline(x))
    assert np.any(np.sign(dspline(np.array([-50.0, 50.0]))) != [-1.0, 1.0])
    with pytest.raises(contact.PunchGeometryError, match="falls toward .*face="):
        contact.solve(MAT, falls, load=0.01, speed=0.0)
    bounded = contact.ProfilePunch(lambda x: dspline(x), height=lambda x: spline(x),
                                   face=(-2.0, 2.0))
    r = contact.solve(MAT, bounded, load=0.01, speed=0.0)
    assert len(r.zones) == 1


def test_a_face_that_rises_too_slowly_is_refused():
    """A face that rises only like log|X| far out (as the half-space's own deflection does)
    cannot be shown to stay clear of the surface: refused with the hint, never solved with a
    gap below zero."""
    punch = contact.ProfilePunch(lambda X: 1e-9 * X / (1.0 + X * X))
    with pytest.raises(contact.PunchGeometryError, match="face="):
        contact.solve(MAT, punch, load=1.0, speed=0.0)


def test_a_face_that_falls_beyond_its_local_maximum_says_where():
    """v = X^2/200 - X^4/12000 has its lowest point at 0 and local maxima at X = +-sqrt(30)
    = +-5.477, beyond which it falls without bound: refused (it was a ContactLossError that
    did not name the cause), naming the stretch of the scan where it stops rising."""
    punch = contact.ProfilePunch(lambda X: X / 100 - X ** 3 / 3000)
    with pytest.raises(contact.PunchGeometryError, match="falls toward -X") as exc:
        contact.solve(MAT, punch, load=0.01, speed=0.0)
    a, b = (float(x) for x in
            str(exc.value).split("between X = ")[1].split(" and does")[0].split(" and "))
    assert b < -np.sqrt(30.0) < a
