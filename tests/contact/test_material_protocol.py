"""Materials of one's own through the :class:`contact.Material` protocol.

Two materials written here, neither a subclass of :class:`contact.Orthotropic`:

* ``Wrapped``: holds an Orthotropic and delegates every method to it.  Everything the
  library computes with it must be bit for bit what it computes with the Orthotropic: the
  library reaches a material only through the protocol's methods, never through its class.
* ``StaticIsotropic(G, nu)``: an isotropic half-space at rest with formulas of its own, the
  classical plane-strain surface constants (N11 = -(1 - nu)/G, N12 = (1 - 2 nu)/(2G),
  N21 = -1, N22 = -2; see the documentation, Theory: the contact model and its conventions)
  and the classical field of surface tractions from their Cauchy transforms (derived in
  ``IsotropicField``).  Checked against independent references: Hertz's half-width and
  pressure (Johnson, Contact Mechanics 1985, eqs. (5.7)-(5.8) with E* = 2G / (1 - nu) for a
  rigid cylinder on a plane-strain half-space; here from N11:
  a^2 = -2 N11 P R / pi = 2 (1 - nu) P R / (pi G), p0 = 2P / (pi a)), McEwen's field under
  it (Johnson 1985, Sec. 7.1, eq. (7.5)), Flamant's normal and tangential line loads
  (Johnson 1985, eqs. (2.15)-(2.21)), and the isotropic limit of the orthotropic field
  (contact.Isotropic, tested on its own against McEwen in test_subsurface_api.py).

And the bad materials: objects without the methods (ContactInputError naming them), and
methods that return garbage or raise (MaterialError naming the method).
"""
from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq

import contact
from contact.subsurface import half_space_modes

PAPER = contact.zhou2014()


class Wrapped:
    """An Orthotropic by composition: every method delegates, and each call is recorded."""

    def __init__(self, inner):
        self.inner = inner
        self.calls = []

    def surface_constants(self, c):
        self.calls.append("surface_constants")
        return self.inner.surface_constants(c)

    def rayleigh_speed(self):
        self.calls.append("rayleigh_speed")
        return self.inner.rayleigh_speed()

    def limiting_speed(self):
        self.calls.append("limiting_speed")
        return self.inner.limiting_speed()

    def relative_speed(self, V):
        self.calls.append("relative_speed")
        return self.inner.relative_speed(V)

    def half_space_modes(self, c):
        self.calls.append("half_space_modes")
        return self.inner.half_space_modes(c)


class StaticIsotropic:
    """An isotropic half-space at rest (plane strain), shear modulus G, Poisson's ratio nu.

    Its relative speed is V / sqrt(G / rho); it is solved only at c = 0 (a moving isotropic
    material is contact.Isotropic).
    """

    def __init__(self, G, nu, rho=None):
        self.G, self.nu, self.rho = float(G), float(nu), rho

    def surface_constants(self, c):
        if c != 0.0:
            raise contact.SpeedError(f"StaticIsotropic is solved at rest only (c = 0), got {c!r}")
        G, nu = self.G, self.nu
        return contact.SurfaceConstants(N11=-(1.0 - nu) / G, N12=(1.0 - 2.0 * nu) / (2.0 * G),
                                        N21=-1.0, N22=-2.0, c=c,
                                        rayleigh_speed=self.rayleigh_speed())

    def rayleigh_speed(self):
        """The root x = c_R^2 in (0, 1) of Rayleigh's (2 - x)^2 = 4 sqrt(1 - x) sqrt(1 - k x),
        k = (1 - 2 nu) / (2 (1 - nu)) the squared ratio of shear to longitudinal wave speed
        (Rayleigh 1885; Johnson 1985, Sec. 13.4)."""
        k = (1.0 - 2.0 * self.nu) / (2.0 * (1.0 - self.nu))
        x = brentq(lambda x: (2.0 - x) ** 2 - 4.0 * math.sqrt((1.0 - x) * (1.0 - k * x)),
                   1e-6, 1.0, xtol=1e-15)
        return math.sqrt(x)

    def limiting_speed(self):
        return 1.0                                   # the shear wave

    def relative_speed(self, V):
        if self.rho is None:
            raise contact.MaterialError("StaticIsotropic: give rho to convert a velocity")
        return abs(V) / math.sqrt(self.G / self.rho)

    def half_space_modes(self, c):
        if c != 0.0:
            raise contact.SpeedError(f"StaticIsotropic is solved at rest only (c = 0), got {c!r}")
        return IsotropicField()


class IsotropicField:
    """The isotropic field of surface tractions p, q from their Cauchy transforms.

    With depth d = -Y, w = X + i d (Im w > 0), C(w) = (1/pi) int p(t) / (t - w) dt and D the
    same for q, Johnson's integrals (1985, eqs. (2.23); his z is d, his tangential traction
    is -q) are, term by term (1/(t - w) = (-u + i d) / (u^2 + d^2), u = X - t),

        sigma_xx = -Im C - d Re C' - 2 Re D + d Im D',
        sigma_yy = -Im C + d Re C' - d Im D',
        sigma_xy = -d Im C' - Im D - d Re D'

    (sigma_xy = -tau_xz: Y = -z flips the shear).  C and d C' come from C at the four points
    w +- h, w +- i h, h = EPS d: their mean is C + O(h^4), and the mean of the two central
    differences is C' + O(h^4) (the h^2 terms cancel between the real and the imaginary
    step).  On d -> 0: sigma_yy -> -p, sigma_xy -> -q, sigma_xx -> -p - 2 Hc[q].
    """
    EPS = 1e-3

    def points(self, X, Y):
        d = -Y
        w = X + 1j * d
        h = self.EPS * d
        return [w + h, w - h, w + 1j * h, w - 1j * h]

    def _value_and_slope(self, C):
        """(C(w), d C'(w)) from the transforms at the four points."""
        value = 0.25 * (C[0] + C[1] + C[2] + C[3])
        slope = 0.5 * ((C[0] - C[1]) / (2.0 * self.EPS) + (C[2] - C[3]) / (2j * self.EPS))
        return value, slope

    def stresses(self, Cp, Cq=None, q_ratio=None):
        C, dC = self._value_and_slope(Cp)
        if Cq is not None:
            D, dD = self._value_and_slope(Cq)
        else:
            r = 0.0 if q_ratio is None else q_ratio
            D, dD = r * C, r * dC
        sxx = -C.imag - dC.real - 2.0 * D.real + dD.imag
        syy = -C.imag + dC.real - dD.imag
        sxy = -dC.imag - D.imag - dD.real
        return sxx, syy, sxy


def hertz(G, nu, P, R):
    """Half-width a and peak pressure p0 of a rigid cylinder of radius R pressed with P on
    an isotropic plane-strain half-space (Johnson 1985, eqs. (5.7)-(5.8) with the rigid
    cylinder's E* = E / (1 - nu^2) = 2G / (1 - nu))."""
    E_star = 2.0 * G / (1.0 - nu)
    a = math.sqrt(4.0 * P * R / (math.pi * E_star))
    return a, 2.0 * P / (math.pi * a)


def mcewen(X, d, a, p0):
    """McEwen's frictionless Hertz field (Johnson 1985, Sec. 7.1, eq. (7.5) with mu = 0), in
    this library's (sigma_xx, sigma_yy, sigma_xy) at X, depth d > 0: tau_xz < 0 for X > 0,
    as Flamant's field of the load P = pi a p0 / 2, to which it tends far away."""
    s = a * a - X * X + d * d
    root = np.sqrt(s * s + 4.0 * X * X * d * d)
    m = np.sqrt(0.5 * (root + s))
    n = np.sign(X) * np.sqrt(np.maximum(0.5 * (root - s), 0.0))
    r = (d * d + n * n) / (m * m + n * n)
    sxx = -(p0 / a) * (m * (1.0 + r) - 2.0 * d)
    szz = -(p0 / a) * m * (1.0 - r)
    txz = -(p0 / a) * n * (m * m - d * d) / (m * m + n * n)
    return sxx, szz, -txz


G, NU = 1.0, 0.3
STATIC = StaticIsotropic(G, NU)
ISO = contact.Isotropic(2.0 * G * (1.0 + NU), NU)        # the same solid, as an Orthotropic
CYL = contact.CylindricalPunch(1.0)


# ----------------------------------------------------------------------------------------
# (a) an Orthotropic wrapped by composition: bit for bit
# ----------------------------------------------------------------------------------------
def _same_field(f, g):
    for name in ("sigma_xx", "sigma_yy", "sigma_xy"):
        assert np.array_equal(getattr(f, name), getattr(g, name)), name


def test_a_wrapped_material_is_a_material_not_an_orthotropic():
    m = Wrapped(PAPER)
    assert isinstance(m, contact.Material) and not isinstance(m, contact.Orthotropic)
    assert isinstance(PAPER, contact.Material)
    assert isinstance(PAPER.half_space_modes(0.3), contact.MaterialModes)


def test_the_checked_entries_give_the_methods_results():
    m = Wrapped(PAPER)
    assert contact.rayleigh_speed(m) == contact.rayleigh_speed(PAPER)
    assert contact.limiting_speed(m) == contact.limiting_speed(PAPER)
    assert contact.surface_constants(m, 0.6) == contact.surface_constants(PAPER, 0.6)
    with_rho = contact.Orthotropic(2.0, 0.5, 1.0, 0.5, rho=2.0)
    assert contact.relative_speed(Wrapped(with_rho), 0.25) == 0.5      # sqrt(C33/rho) = 1/2


@pytest.mark.parametrize("punch,kw", [
    (contact.CylindricalPunch(100.0), dict(load=0.01, speed=0.6, friction=0.3)),
    (contact.FlatPunch(1.0), dict(load=0.01, speed=0.3, friction=0.2, direction=1)),
])
def test_solve_is_bit_for_bit_the_orthotropic_one(punch, kw):
    m = Wrapped(PAPER)
    r, o = contact.solve(m, punch, **kw), contact.solve(PAPER, punch, **kw)
    assert "surface_constants" in m.calls
    assert r.ends == o.ends and (r.alpha, r.beta) == (o.alpha, o.beta) and r.sif == o.sif
    X = np.linspace(r.ends[0], r.ends[1], 41)[1:-1]
    assert np.array_equal(r.pressure(X), o.pressure(X))
    assert np.array_equal(r.sigma_xx(X), o.sigma_xx(X))
    assert r.material is m
    Xg, Yg = np.meshgrid(np.linspace(-1.3, 1.3, 14), np.linspace(-1.0, 0.0, 7))
    _same_field(r.stress(Xg, Yg), o.stress(Xg, Yg))
    assert "half_space_modes" in m.calls
    e, eo = r.stress_extrema(((-0.9, 0.9), (-0.9, -0.05)), grid=(9, 9)), \
        o.stress_extrema(((-0.9, 0.9), (-0.9, -0.05)), grid=(9, 9))
    assert e == eo


def test_batch_load_curve_and_contact_length_are_bit_for_bit():
    m = Wrapped(PAPER)
    punch = contact.CylindricalPunch(100.0)
    kw = dict(load=[0.005, 0.01], speed=[[0.0], [0.6]], friction=0.3)
    for r, o in zip(contact.solve_batch(m, punch, **kw), contact.solve_batch(PAPER, punch, **kw)):
        assert r.ends == o.ends and r.constants == o.constants
    loads = np.geomspace(1e-3, 1e-2, 5)
    c, co = (contact.load_curve(mat, punch, loads, speed=0.6, friction=0.3)
             for mat in (m, PAPER))
    assert [x.ends for x in c.results] == [x.ends for x in co.results]
    assert contact.contact_length(m, punch, load=0.01, speed=0.6) == \
        contact.contact_length(PAPER, punch, load=0.01, speed=0.6)


def test_half_space_stress_is_bit_for_bit():
    X, Y = np.meshgrid(np.linspace(-2.0, 2.0, 9), np.linspace(-2.0, -0.1, 5))

    def flamant(z):
        return -1.0 / (np.pi * z)
    for kw in (dict(q_ratio=0.3), dict(cauchy_q=flamant)):
        _same_field(contact.half_space_stress(Wrapped(PAPER), 0.6, X, Y, flamant, **kw),
                    contact.half_space_stress(PAPER, 0.6, X, Y, flamant, **kw))


def test_speed_checks_and_warnings_are_the_materials():
    m = Wrapped(PAPER)
    c_R = contact.rayleigh_speed(PAPER)
    with pytest.raises(contact.SpeedError, match="below the Rayleigh speed c_R = 0.99361"):
        contact.solve(m, CYL, load=0.01, speed=c_R)
    with pytest.warns(contact.NearRayleighWarning, match="within 1% of the Rayleigh speed"):
        contact.surface_constants(m, 0.995 * c_R)
    with pytest.raises(contact.SpeedError, match="below the Rayleigh speed"):
        contact.half_space_stress(m, 1.0, 0.0, -1.0, lambda z: -1.0 / (np.pi * z))


# ----------------------------------------------------------------------------------------
# (b) a static isotropic material of its own, against Hertz, McEwen and Flamant
# ----------------------------------------------------------------------------------------
def test_static_isotropic_rayleigh_speed_at_quarter():
    """Poisson's ratio 1/4: c_R^2 = 2 - 2 / sqrt(3) (Rayleigh 1885)."""
    assert contact.rayleigh_speed(StaticIsotropic(1.0, 0.25)) == \
        pytest.approx(math.sqrt(2.0 - 2.0 / math.sqrt(3.0)), rel=1e-13)


@pytest.mark.parametrize("P", [0.01, 0.3])
def test_static_isotropic_hertz(P):
    r = contact.solve(STATIC, CYL, load=P, speed=0.0)
    a, p0 = hertz(G, NU, P, 1.0)
    assert r.half_width == pytest.approx(a, rel=1e-12)
    assert r.ends[0] == pytest.approx(-a, rel=1e-12) and r.ends[1] == pytest.approx(a, rel=1e-12)
    X = np.linspace(-0.99, 0.99, 21) * a
    assert np.allclose(r.pressure(X), p0 * np.sqrt(1.0 - (X / a) ** 2), rtol=0, atol=1e-11 * p0)


def test_static_isotropic_mcewen_field():
    P = 0.01
    r = contact.solve(STATIC, CYL, load=P, speed=0.0)
    a, p0 = hertz(G, NU, P, 1.0)
    on_axis = r.stress(0.0, -a)                   # McEwen: sigma_yy = -p0 / sqrt(2) at d = a
    assert float(on_axis.sigma_yy) == pytest.approx(-p0 / math.sqrt(2.0), rel=1e-9)
    assert float(on_axis.sigma_xx) == pytest.approx(-p0 * (3.0 / math.sqrt(2.0) - 2.0),
                                                    rel=1e-8)
    assert abs(float(on_axis.sigma_xy)) < 1e-10 * p0
    X, D = np.meshgrid(np.linspace(-2.0, 2.0, 17) * a, np.linspace(0.05, 2.5, 11) * a)
    f = r.stress(X, -D)
    for got, want in zip((f.sigma_xx, f.sigma_yy, f.sigma_xy), mcewen(X, D, a, p0)):
        assert np.max(np.abs(got - want)) < 1e-9 * p0
    e = r.stress_extrema(grid=(21, 21)).max_shear     # Johnson: 0.300 p0 at 0.786 a
    assert round(e.value / p0, 3) == 0.3 and round(e.depth_over_a, 3) == 0.786


def test_static_isotropic_flamant_line_loads():
    """Normal line load P: sigma_rr = -2 P cos(theta) / (pi r) radially (Johnson eq. 2.15),
    i.e. sigma_xx = -(2P/pi) x^2 d / r^4, sigma_yy = -(2P/pi) d^3 / r^4,
    sigma_xy = (2P/pi) x d^2 / r^4 here; a tangential one Q (q = Q delta, Johnson's is -Q,
    eq. 2.21): sigma_xx = (2Q/pi) x^3 / r^4, sigma_yy = (2Q/pi) x d^2 / r^4,
    sigma_xy = -(2Q/pi) x^2 d / r^4."""
    x, d = np.meshgrid(np.linspace(-2.0, 2.0, 9), np.linspace(0.1, 2.0, 5))
    r4 = (x * x + d * d) ** 2
    line = lambda z: -1.0 / (np.pi * z)               # noqa: E731  P = 1, Q = 1 at the origin
    f = contact.half_space_stress(STATIC, 0.0, x, -d, line)
    want = (-(2 / np.pi) * x * x * d / r4, -(2 / np.pi) * d ** 3 / r4, (2 / np.pi) * x * d * d / r4)
    for got, w in zip((f.sigma_xx, f.sigma_yy, f.sigma_xy), want):
        assert np.allclose(got, w, rtol=1e-9, atol=1e-12)
    g = contact.half_space_stress(STATIC, 0.0, x, -d, lambda z: 0.0 * z, cauchy_q=line)
    want = ((2 / np.pi) * x ** 3 / r4, (2 / np.pi) * x * d * d / r4, -(2 / np.pi) * x * x * d / r4)
    for got, w in zip((g.sigma_xx, g.sigma_yy, g.sigma_xy), want):
        assert np.allclose(got, w, rtol=1e-9, atol=1e-12)


def test_static_isotropic_with_friction_agrees_with_the_orthotropic_limit():
    """Sliding with friction (q = mu_f p, the pressure no longer Hertz's): the contact and the
    field of the material's own formulas against contact.Isotropic's."""
    kw = dict(load=0.01, speed=0.0, friction=0.4)
    r, o = contact.solve(STATIC, CYL, **kw), contact.solve(ISO, CYL, **kw)
    assert r.ends == pytest.approx(o.ends, rel=1e-12)
    assert (r.alpha, r.beta) == pytest.approx((o.alpha, o.beta), rel=1e-13)
    a, p0 = r.half_width, float(o.pressure(0.0))
    X, Y = np.meshgrid(np.linspace(-2.0, 2.0, 17) * a, np.linspace(-2.5, 0.0, 11) * a)
    f, g = r.stress(X, Y), o.stress(X, Y)
    for name in ("sigma_xx", "sigma_yy", "sigma_xy"):
        assert np.max(np.abs(getattr(f, name) - getattr(g, name))) < 1e-9 * p0, name


def test_static_isotropic_load_curve_follows_hertz():
    loads = np.geomspace(1e-3, 1e-1, 7)
    curve = contact.load_curve(STATIC, CYL, loads, speed=0.0)
    widths = [res.half_width for res in curve.results]
    assert widths == pytest.approx([hertz(G, NU, P, 1.0)[0] for P in loads], rel=1e-11)


def test_static_isotropic_refuses_motion_as_it_says():
    with pytest.raises(contact.SpeedError, match="at rest only"):
        contact.solve(STATIC, CYL, load=0.01, speed=0.1)
    with pytest.raises(contact.MaterialError, match="give rho"):
        contact.relative_speed(STATIC, 1.0)
    assert contact.relative_speed(StaticIsotropic(4.0, 0.3, rho=1.0), 1.0) == 0.5


# ----------------------------------------------------------------------------------------
# bad materials
# ----------------------------------------------------------------------------------------
class _Lacking:
    def surface_constants(self, c):
        return PAPER.surface_constants(c)

    rayleigh_speed = 0.99                       # not callable


@pytest.mark.parametrize("material,lacks", [
    ("steel", "surface_constants, rayleigh_speed, limiting_speed, relative_speed, "
              "half_space_modes"),
    ({"E": 1.0, "nu": 0.3}, "surface_constants, rayleigh_speed"),
    (_Lacking(), "rayleigh_speed, limiting_speed, relative_speed, half_space_modes"),
])
@pytest.mark.parametrize("entry", ["solve", "solve_batch", "load_curve", "contact_length",
                                   "half_space_stress", "surface_constants",
                                   "rayleigh_speed"])
def test_an_object_without_the_methods_is_refused(material, lacks, entry):
    calls = {
        "solve": lambda: contact.solve(material, CYL, load=0.01, speed=0.0),
        "solve_batch": lambda: contact.solve_batch(material, CYL, load=[0.01, 0.02], speed=0.0),
        "load_curve": lambda: contact.load_curve(material, CYL, [0.01], speed=0.0),
        "contact_length": lambda: contact.contact_length(material, CYL, load=0.01, speed=0.0),
        "half_space_stress": lambda: contact.half_space_stress(material, 0.0, 0.0, -1.0,
                                                               lambda z: -1 / (np.pi * z)),
        "surface_constants": lambda: contact.surface_constants(material, 0.0),
        "rayleigh_speed": lambda: contact.rayleigh_speed(material),
    }
    with pytest.raises(contact.ContactInputError) as info:
        calls[entry]()
    assert type(info.value) is contact.ContactInputError
    msg = str(info.value)
    assert msg.startswith("material must have the methods surface_constants(c), "
                          "rayleigh_speed(), limiting_speed(), relative_speed(V), "
                          "half_space_modes(c)")
    assert "allowed: contact.Orthotropic" in msg and f"which lacks {lacks}" in msg


def test_a_class_in_place_of_its_instance_is_refused():
    with pytest.raises(contact.ContactInputError,
                       match=r"material must be a material object, got the class Orthotropic "
                             r"itself: make one, e\.g\. contact\.Orthotropic\(C11, C12, "
                             r"C22, C33\)"):
        contact.solve(contact.Orthotropic, CYL, load=0.01, speed=0.0)


class Garbage(Wrapped):
    """The paper's material with one method's result replaced."""

    def __init__(self, **replace):
        super().__init__(PAPER)
        self.replace = replace

    def _or(self, name, value):
        if name not in self.replace:
            return value
        new = self.replace[name]
        if isinstance(new, BaseException):
            raise new
        return new(value) if callable(new) else new

    def surface_constants(self, c):
        return self._or("surface_constants", super().surface_constants(c))

    def rayleigh_speed(self):
        return self._or("rayleigh_speed", super().rayleigh_speed())

    def limiting_speed(self):
        return self._or("limiting_speed", super().limiting_speed())

    def half_space_modes(self, c):
        return self._or("half_space_modes", super().half_space_modes(c))


def _swap(**fields):
    from dataclasses import replace
    return lambda sc: replace(sc, **fields)


@pytest.mark.parametrize("replace,match", [
    (dict(rayleigh_speed=float("nan")), r"Garbage\.rayleigh_speed\(\) \(a relative speed\) "
                                        r"must be a finite real number, got nan"),
    (dict(rayleigh_speed=-0.5), r"Garbage\.rayleigh_speed\(\) must return a relative speed "
                                r"> 0, got -0\.5"),
    (dict(rayleigh_speed=0.0), r"rayleigh_speed\(\) must return a relative speed > 0"),
    (dict(rayleigh_speed=0.9 + 0.1j), r"rayleigh_speed\(\) \(a relative speed\) must be a "
                                      r"finite real number, got \(0\.9\+0\.1j\)"),
    (dict(rayleigh_speed="0.99"), r"rayleigh_speed\(\) \(a relative speed\) must be a finite "
                                  r"real number, got '0\.99'"),
    (dict(rayleigh_speed=ZeroDivisionError("float division by zero")),
     r"Garbage\.rayleigh_speed\(\) raised ZeroDivisionError: float division by zero"),
    (dict(surface_constants=_swap(N11=float("nan"))),
     r"N11 of Garbage\.surface_constants\(0\.3\) must be a finite real number, got nan"),
    (dict(surface_constants=_swap(N22=1j)),
     r"N22 of Garbage\.surface_constants\(0\.3\) must be a finite real number, got 1j"),
    (dict(surface_constants=_swap(N11=0.15)),
     r"N11 of Garbage\.surface_constants\(0\.3\) must be < 0 .* got 0\.15"),
    (dict(surface_constants=_swap(c=0.0)),
     r"Garbage\.surface_constants\(0\.3\) returned constants for c = 0\.0"),
    (dict(surface_constants=_swap(eta_sum=float("inf"))),
     r"eta_sum of Garbage\.surface_constants\(0\.3\) must be a finite real number"),
    (dict(surface_constants=(-0.15, 0.02, -3.0, -6.0)),
     r"Garbage\.surface_constants\(0\.3\) must return a contact\.SurfaceConstants, got tuple"),
    (dict(surface_constants=KeyError("N11")),
     r"Garbage\.surface_constants\(0\.3\) raised KeyError: 'N11'"),
])
def test_garbage_constants_are_a_material_error_naming_the_method(replace, match):
    m = Garbage(**replace)
    for call in (lambda: contact.solve(m, CYL, load=0.01, speed=0.3),
                 lambda: contact.solve_batch(m, CYL, load=[0.01, 0.02], speed=0.3),
                 lambda: contact.surface_constants(m, 0.3)):
        with pytest.raises(contact.MaterialError, match=match):
            call()


def test_a_material_error_of_a_method_is_chained_to_its_cause():
    with pytest.raises(contact.MaterialError) as info:
        contact.rayleigh_speed(Garbage(rayleigh_speed=ZeroDivisionError("x")))
    assert isinstance(info.value.__cause__, ZeroDivisionError)


@pytest.mark.parametrize("replace,match", [
    (dict(limiting_speed=float("nan")), r"Garbage\.limiting_speed\(\) \(a relative speed\) "
                                        r"must be a finite real number"),
    (dict(limiting_speed=0.5), r"Garbage\.limiting_speed\(\) returned 0\.5, below its "
                               r"Rayleigh speed 0\.9936"),
])
def test_garbage_limiting_speed(replace, match):
    with pytest.raises(contact.MaterialError, match=match):
        contact.limiting_speed(Garbage(**replace))


class _Points:
    """Modes whose points are wrong in one way, or whose stresses are."""

    def __init__(self, points=None, stresses=None):
        self.modes = PAPER.half_space_modes(0.3)
        self._points, self._stresses = points, stresses

    def points(self, X, Y):
        z = self.modes.points(X, Y)
        return z if self._points is None else self._points(z, X, Y)

    def stresses(self, Cp, Cq=None, q_ratio=None):
        s = self.modes.stresses(Cp, Cq, q_ratio)
        return s if self._stresses is None else self._stresses(s)


@pytest.mark.parametrize("modes,match", [
    ({"points": None}, r"Garbage\.half_space_modes\(0\.3\) must return the half-space's "
                       r"modes: an object with the methods points\(X, Y\) and "
                       r"stresses\(Cp, Cq, q_ratio\) \(contact\.MaterialModes\), got dict"),
    (None, r"half_space_modes\(0\.3\) must return the half-space's modes.*got NoneType"),
    (NotImplementedError("no field"), r"Garbage\.half_space_modes\(0\.3\) raised "
                                      r"NotImplementedError: no field"),
    (_Points(points=lambda z, X, Y: [X + 0j for _ in z]),
     r"_Points\.points\(X, Y\) .* must return finite points z with Im z > 0 .* got "
     r"z = \S*0j\)? in entry 0 for the point \(X, Y\) = \(-?0\.\d+, -0\.\d+\)"),
    (_Points(points=lambda z, X, Y: [zz.real for zz in z]),
     r"must return complex arrays of the points' shape \((\d+),\), got entry 0 of shape "
     r"\(\1,\) and dtype float64"),
    (_Points(points=lambda z, X, Y: z[0]), r"must return a non-empty list of complex arrays"),
    (_Points(points=lambda z, X, Y: [np.conj(zz) for zz in z]), r"Im z > 0"),
    (_Points(stresses=lambda s: s[:2]), r"_Points\.stresses\(Cp, Cq, q_ratio\) .* must "
                                        r"return \(sigma_xx, sigma_yy, sigma_xy\)"),
    (_Points(stresses=lambda s: (s[0], s[1] * np.nan, s[2])),
     r"returned sigma_yy = nan at the point \(X, Y\) = \(-?0\.\d+, -0\.\d+\), where the "
     r"transforms are finite"),
    (_Points(stresses=lambda s: (s[0], s[1] + 0j, s[2])),
     r"must return real arrays of the points' shape \((\d+),\), got sigma_yy of shape "
     r"\(\1,\) and dtype complex128"),
])
def test_garbage_modes_are_a_material_error_naming_the_method(modes, match):
    m = Garbage(half_space_modes=lambda _: modes)
    if isinstance(modes, BaseException):
        m = Garbage(half_space_modes=modes)
    r = contact.solve(m, contact.CylindricalPunch(100.0), load=0.01, speed=0.3)
    with pytest.raises(contact.MaterialError, match=match):
        r.stress([0.0], [-0.5])
    with pytest.raises(contact.MaterialError, match=match):
        contact.half_space_stress(m, 0.3, [0.0], [-0.5], lambda z: -1.0 / (np.pi * z))
    with pytest.raises(contact.MaterialError, match=match):
        half_space_modes(m, 0.3) if not isinstance(modes, _Points) else \
            r.stress_extrema(((-0.5, 0.5), (-0.5, -0.1)), grid=(3, 3))


def test_the_protocol_is_checked_once_per_batch_not_per_stage(monkeypatch):
    """solve_batch checks the material once for all its cases (it is one material) and
    asks it for the constants once per distinct speed."""
    import contact.solver as solver
    checked = []
    real = solver.check_material
    monkeypatch.setattr(solver, "check_material", lambda m: checked.append(m) or real(m))
    m = Wrapped(PAPER)
    contact.solve_batch(m, contact.CylindricalPunch(100.0), load=0.01,
                        speed=[[0.0], [0.3]], friction=[0.0, 0.1, 0.2])
    assert len(checked) == 1
    assert m.calls.count("surface_constants") == 2


def test_orthotropic_methods_are_the_module_functions():
    """One path: the module's entries and the class's methods give the same numbers (the
    entries check and delegate)."""
    m = contact.Orthotropic(1.0, 0.5, 1.0, 0.5)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert contact.surface_constants(m, 0.2) == m.surface_constants(0.2)
    assert contact.rayleigh_speed(m) == m.rayleigh_speed()
    assert contact.limiting_speed(m) == m.limiting_speed()
    with pytest.raises(contact.SpeedError, match="below the Rayleigh speed"):
        m.surface_constants(m.rayleigh_speed())
    with pytest.raises(contact.SpeedError, match="below the Rayleigh speed"):
        m.half_space_modes(1.0)
