"""Partial slip under a tangential load below full sliding (Cattaneo, Mindlin), for pairs whose
normal and tangential problems decouple.

The punch is pressed by P and then pulled by a tangential load Q, abs(Q) < mu P, at constant
P (monotonically: the fretting test); nothing slides as a whole, so the contact has a stick
zone, where the two surfaces move together (the relative tangential displacement is a
rigid shift), and slip zones, where q = +-mu p.  When the relative tangential slope does not
depend on p (the local coupling N12* of the pair and its Hilbert coupling M12* both vanish:
Dundurs' beta = 0: two bodies of one material at rest, or two isotropic ones with
(1 - 2 nu1)/G1 = (1 - 2 nu2)/G2), the normal problem is the frictionless one and, on the stick
zones, Hc[q] = 0 with q = s mu p on the slip zones (s = sign Q).  Then (Ciavarella, Int. J.
Solids Struct. 35 (1998) 2349; Jager, J. Appl. Mech. 65 (1998) 1037)

    q(X) = s mu (p(X; P) - p(X; P*)),     P* = P - abs(Q) / mu,                     (1)

p(X; P*) the pressure of the same face at the smaller load P*: Hc[p(.; P*)] = H'/b on its
own contact, which is where Hc[p(.; P)] = H'/b too, so Hc[q] = 0 there; its contact is the
stick zone (inside the full contact: the zones grow with the load), and q = s mu p beyond
it.  For two cylinders this is Cattaneo's c/a = sqrt(1 - abs(Q)/(mu P)).  The cyclic
history (unloading, reversal, the hysteresis loop and the energy per cycle) follows from the
same correctives: :mod:`contact.fretting`.

Steady rolling (Carter 1926; quasi-static: the bodies roll at speed 0 in the frame of the
contact, ``rolling=True``): in the stick zone the two surfaces move together while the
material flows through it, so there the relative tangential strain is constant, the
creepage xi = d(u - u_p)/dX = T Hc[q] (T the pair's tangential compliance), not 0.  With
q = s mu p - q*, Hc[q*] = s mu (H' - k) / b on the stick zone, k = b xi / (T s mu): q* is
s mu times the pressure of the face tilted by k, H(X) - k X, at the load P*, and the stick
zone its contact, which in steady rolling lies at the leading edge (the material entering the
contact sticks first).  k is found so that the stick zone's leading end is the contact's;
given the creepage instead of Q, P* is.  For two cylinders this is Carter's stick zone
[-a, -a + 2c] (rolling toward -X), c/a = sqrt(1 - abs(Q)/(mu P)), and creepage
abs(xi) = mu (a - c) / R when T = b (one isotropic material).

Linearity carries (1) to every field: the surface stress and the field under it are those
of the result at P with the friction s mu, minus the friction part of the result at P*
(:class:`PartialSlipResult`).  A pair that couples (beta != 0: a rigid punch on a
compressible half-space, dissimilar bodies, a moving half-space under a punch at rest)
needs the coupled system with coefficients that jump at the stick-slip ends, and is refused
here (:class:`CoupledPartialSlipError`).
"""
from __future__ import annotations

import dataclasses
import math

from .errors import ContactInputError, FrictionError, LoadError, check_finite
from .punches import ProfilePunch
from .result import ContactResult

__all__ = ["CoupledPartialSlipError", "PartialSlipResult", "check_decoupled",
           "slip_stretches", "stick_load", "tilted_face"]

#: abs(N12*), abs(M12*) below this fraction of abs(N11*) count as decoupled (beta = 0).
DECOUPLED_TOLERANCE = 1e-12


class CoupledPartialSlipError(ContactInputError):
    """Partial slip asked of a pair whose normal and tangential problems couple (Dundurs'
    beta != 0 or a Hilbert coupling M12): not available yet.

    Examples
    --------
    >>> import contact
    >>> try:
    ...     contact.solve(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0),
    ...                   load=0.01, speed=0.0, friction=0.5, tangential_load=0.002)
    ... except contact.CoupledPartialSlipError as exc:
    ...     print(str(exc)[:52])
    partial slip needs the normal and tangential problem
    """


def check_decoupled(constants) -> None:
    """CoupledPartialSlipError unless the pair's N12 and M12 vanish against N11
    (:data:`DECOUPLED_TOLERANCE`)."""
    scale = abs(constants.N11)
    n12, m12 = constants.N12, constants.M12
    if abs(n12) <= DECOUPLED_TOLERANCE * scale and abs(m12) <= DECOUPLED_TOLERANCE * scale:
        return
    raise CoupledPartialSlipError(
        f"partial slip needs the normal and tangential problems decoupled (N12 = M12 = 0, "
        f"Dundurs' beta = 0); this pair has N12 / N11 = {n12 / constants.N11:.6g}, M12 / N11 "
        f"= {m12 / constants.N11:.6g} at speed {constants.c:g}.  Decoupled pairs: two bodies "
        "of one material at rest (punch_material = the material, speed = 0), or two isotropic "
        "ones with (1 - 2 nu1)/G1 = (1 - 2 nu2)/G2; the coupled problem (a system whose "
        "coefficients jump at the stick-slip ends) is not available yet")


def tilted_face(punch, k):
    """The face of ``punch`` tilted by k: slope H'(X) - k, the same breaks and extent (a
    :class:`contact.ProfilePunch`)."""
    lo, hi = punch.extent
    face = ProfilePunch(lambda X: punch.slope(X) - k, breaks=tuple(punch.breaks),
                        face=(lo, hi))
    # a constant off the slope keeps its degree (an exact basis size) and its monotony
    face.slope_degree, face.convex = punch.slope_degree, punch.convex
    return face


def stick_load(load: float, tangential_load, friction: float) -> float:
    """P* = P - abs(Q) / mu of eq. (1) (module docstring), Q checked: finite, mu > 0 where Q
    != 0, abs(Q) < mu P (else the punch slides: FrictionError saying so)."""
    Q = check_finite("tangential_load", tangential_load, LoadError)
    if Q == 0.0:
        return load
    if friction == 0.0:
        raise FrictionError(f"tangential_load = {Q!r} needs friction > 0 (without friction "
                            "any tangential load slides the punch)")
    if not abs(Q) < friction * load:
        raise FrictionError(
            f"abs(tangential_load) = {abs(Q)!r} is not below friction * load = "
            f"{friction * load!r}: the punch slides as a whole (full sliding); solve it "
            f"with friction = {friction!r} and direction = {-int(math.copysign(1, Q))} "
            "(the sense of the tangential load on the half-space) and no tangential_load")
    return load - abs(Q) / friction


@dataclasses.dataclass(frozen=True, eq=False)
class PartialSlipResult:
    """A contact under a normal load P and a tangential load Q, abs(Q) < mu P, in partial slip
    (:mod:`contact.partial_slip`): returned by :func:`contact.solve` with
    ``tangential_load``.

    Attributes
    ----------
    full : ContactResult
        The contact at P, with the friction s mu (s = sign Q; the pressure is the
        frictionless one: the pair decouples).
    stick : ContactResult or None
        The contact at P* = P - abs(Q)/mu with the same friction: its zones are the stick
        zones (None at Q = 0: everything sticks).
    tangential_load : float
        Q, the tangential traction's resultant on the half-space.
    load, friction : float
        P and mu.
    creepage : float or None
        Steady rolling's creepage xi = d(u - u_p)/dX on the stick zone (module docstring);
        None for a static contact.

    References
    ----------
    C. Cattaneo, Rend. Accad. Naz. Lincei 27 (1938) 342; R. D. Mindlin, J. Appl. Mech. 16
    (1949) 259; M. Ciavarella, Int. J. Solids Struct. 35 (1998) 2349; J. Jager, J. Appl.
    Mech. 65 (1998) 1037.

    Examples
    --------
    Two steel-like cylinders (one material): Cattaneo's stick zone c/a = sqrt(1 - Q/(mu P)):

    >>> import math, contact
    >>> m = contact.Isotropic(1.0, 0.3)
    >>> r = contact.solve(m, contact.CylindricalPunch(1.0), load=0.01, speed=0.0,
    ...                   friction=0.5, punch_material=m, tangential_load=0.003)
    >>> (c0, c1), = [z.ends for z in r.stick_zones]
    >>> a = r.ends[1]
    >>> round(c1 / a, 12) == round(math.sqrt(1 - 0.003 / 0.005), 12)
    True
    """
    full: object
    stick: object
    tangential_load: float
    load: float
    friction: float
    creepage: float | None = None

    # -- zones --------------------------------------------------------------------------
    @property
    def zones(self) -> tuple:
        """The contact zones (:class:`contact.ContactZone`), as without the tangential load."""
        return self.full.zones

    @property
    def ends(self) -> tuple:
        """The ends of the one contact zone."""
        return self.full.ends

    @property
    def zone_scale(self) -> float:
        """The largest half-width of the contact zones (:attr:`ContactResult.zone_scale`)."""
        return self.full.zone_scale

    @property
    def singular_ends(self) -> tuple:
        """The contact's singular ends (:attr:`ContactResult.singular_ends`)."""
        return self.full.singular_ends

    @property
    def material(self):
        """The half-space's material."""
        return self.full.material

    @property
    def _has_out_of_plane(self) -> bool:
        return self.full._has_out_of_plane

    @property
    def stick_zones(self) -> tuple:
        """The stick zones (each with ``ends``): the contact zones at P*; at Q = 0 the
        contact zones themselves."""
        return self.full.zones if self.stick is None else self.stick.zones

    @property
    def slip_zones(self) -> tuple:
        """(lo, hi) of each stretch of the contact outside the stick zones, left to right."""
        return slip_stretches(self.full.zones, self.stick_zones)

    # -- tractions ----------------------------------------------------------------------
    def pressure(self, X):
        """p(X), as without the tangential load (the pair decouples)."""
        return self.full.pressure(X)

    def tangential_traction(self, X):
        """q(X) = s mu (p(X; P) - p(X; P*)) (eq. (1) of :mod:`contact.partial_slip`;
        tau_XY(X, 0) = -q on the half-space): abs(q) <= mu p, equality on the slip zones."""
        q = self.full.shear(X)
        return q if self.stick is None else q - self.stick.shear(X)

    shear = tangential_traction

    def sigma_xx(self, X):
        """The half-space's surface stress sigma_XX(X, 0): that of the contact at P with the
        friction s mu, minus the friction part of the contact at P* (linearity)."""
        out = self.full.sigma_xx(X)
        if self.stick is None:
            return out
        return out - (self.stick.sigma_xx(X) - dataclasses.replace(self.stick, mu_f=0.0)
                      .sigma_xx(X))

    def stress(self, X, Y):
        """The stress under the surface (:meth:`contact.ContactResult.stress`, a
        :class:`contact.StressField`), by the same superposition as :meth:`sigma_xx`."""
        from .subsurface import StressField
        out = self.full.stress(X, Y)
        if self.stick is None:
            return out
        with_q = self.stick.stress(X, Y)
        without = dataclasses.replace(self.stick, mu_f=0.0).stress(X, Y)
        parts = [None if getattr(out, k) is None else
                 getattr(out, k) - (getattr(with_q, k) - getattr(without, k))
                 for k in _COMPONENTS]
        return StressField(out.X, out.Y, *parts)

    # the extrema of the field under the surface: ContactResult's search, on this stress
    stress_extrema = ContactResult.stress_extrema


def slip_stretches(zones, stick_zones) -> tuple:
    """(lo, hi) of each stretch of the contact ``zones`` outside the ``stick_zones`` (each
    with ``ends``, each inside a contact zone: the contacts grow with the load), left to
    right."""
    out = []
    stick = [z.ends for z in stick_zones]
    for z in zones:
        lo, hi = z.ends
        inner = sorted((a, b) for a, b in stick if lo <= a and b <= hi)
        for a, b in inner:
            if a > lo:
                out.append((lo, a))
            lo = b
        if hi > lo:
            out.append((lo, hi))
    return tuple(out)


_COMPONENTS = ("sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz", "sigma_yz", "sigma_xz")
