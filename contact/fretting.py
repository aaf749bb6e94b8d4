"""Fretting: the loading history of partial slip for pairs whose normal and tangential
problems decouple (Dundurs' beta = 0; :mod:`contact.partial_slip`).

The path.  The normal load is applied monotonically from first touch with Q = 0 (nothing
slips, q = 0) up to P; then, at constant P, the tangential load Q rises monotonically from
0 to the amplitude Q* < mu P (loading), falls to -Q* (unloading) and rises back to Q*
(reloading): the fretting test.  Each step is an increment of the one before: the
surfaces stick where the slip increment vanishes, and slip in the sense of the increment,
with q = +-mu p, elsewhere.  Every later cycle repeats the unloading and the reloading.

The correctives.  With p(X; P') the frictionless pressure of the face at the load P'
(the pair decouples: the pressure does not feel q), let

    Phi(X; P') = p(X; P) - p(X; P'),     P' <= P.                                    (1)

On the contact at P', Hc[Phi] = 0 (both pressures satisfy b Hc[p] = H'); on the rest of
the contact at P, Phi = p(X; P); its resultant is P - P'.  A traction q = sum_k w_k
Phi(X; P_k) therefore has the relative tangential slope d(u - u_p)/dX = T Hc[q] = 0 on the
contact at the smallest P_k (T the pair's tangential compliance,
:attr:`contact.SurfaceConstants.tangential_compliance`).  The contacts grow with the load,
contact(P') inside contact(P'') for P' < P'', and, as for Cattaneo's solution, the pressure
is taken to grow with the load too (p(X; P') <= p(X; P'')).  With P* = P - Q*/mu
(Mindlin & Deresiewicz 1953; Ciavarella 1998, Jager 1998, for any face of this class):

    loading, 0 <= Q <= Q*:       q = mu Phi(P - Q/mu)                                  (2)
    unloading, Q* >= Q >= -Q*:   q = mu Phi(P*) - 2 mu Phi(P - (Q* - Q)/(2 mu))        (3)
    reloading, -Q* <= Q <= Q*:   q = -mu Phi(P*) + 2 mu Phi(P - (Q* + Q)/(2 mu))       (4)

(2) is Cattaneo's (eq. (1) of :mod:`contact.partial_slip`).  In (3), with P_r =
P - (Q* - Q)/(2 mu) (P* <= P_r <= P for -Q* <= Q <= Q*), the increment since the turning
point, -2 mu Phi(P_r), is Cattaneo's solution at the amplitude Q* - Q with the friction
2 mu (the traction turns from +mu p to -mu p, a change of 2 mu p, where the surfaces slip
back): its slip increment vanishes on contact(P_r), the stick zone, and on the rest of the
contact q = mu p - 2 mu p = -mu p, the reverse slip zone.  On contact(P_r) the traction stays
within the friction cone: q + mu p = 2 mu p(P_r) - mu p(P*) >= 0 and mu p - q = 2 mu (p(P) -
p(P_r)) + mu p(P*) >= 0.  The resultant is mu (P - P*) - 2 mu (P - P_r) = Q.  At Q = -Q*,
P_r = P* and (3) is -mu Phi(P*), the loading state (2) at -Q*: (4), the same construction
from -Q*, is (3) mirrored, q_reloading(X; Q) = -q_unloading(X; -Q), and the loop closes.

The displacements.  With the log potential of a pressure,

    Lambda(X; P') = (1/pi) int p(t; P') log(abs(X - t) / l) dt,  dLambda/dX = -Hc[p],  (5)

(:meth:`sie.Solution.log_potential` less (P'/pi) log l), the relative tangential
displacement of the surfaces under q = sum_k w_k Phi(X; P_k) is

    h(X) = u - u_p = -T sum_k w_k [Lambda(X; P) - Lambda(X; P_k)].                      (6)

A half-plane's surface displacement is defined only up to a constant (relative to a remote
point it grows like the logarithm of the point's distance): (6) fixes it by the length l in
the logarithm (``reference_length``, by default the contact's half-width at P).
That constant is proportional to Q: another l' adds kappa Q to the displacement below,
kappa = -(T/pi) log(l'/l), which tilts the loop and leaves alone its width at each Q (the
difference of the two branches there) and its area.

On the core, the contact at the smallest P_k, the surfaces have stuck since first touch;
there h is constant and the punch has moved by

    delta = -h(X0) = T sum_k w_k [Lambda(X0; P) - Lambda(X0; P_k)],   X0 in the core,   (7)

in the sense of Q (Q > 0 is the traction on the half-space toward -X; T < 0, like N11): the
loop is
delta against Q; delta = 0 at Q = 0 on loading.  The accumulated slip of the punch's surface
over the half-space's, in the sense of Q, since first touch, is

    s(X) = h(X) - h(X0),                                                               (8)

0 on the core, constant where the surfaces slipped and then stuck (on contact(P_r) \\
contact(P*) during the unloading).  On the contact at P it is (T/b) sum_k w_k g(X; P_k),
g the gap of the frictionless contact at P_k: the tangential slip is the normal gap of the
correctives (Ciavarella 1998; Jager 1998).

The energy dissipated per cycle, the area of the loop,

    W = oint Q d(delta) = int_{-Q*}^{Q*} (delta_unloading - delta_reloading) dQ,        (9)

is the frictional work oint int q ds dX: on the unloading the reverse slip zone grows to
contact(P) \\ contact(P*), and there the surfaces slip back, under q = -mu p, from s(X; Q*)
to s(X; -Q*) = -s(X; Q*) (the loading state at -Q*), monotonically (the slip increment is
the gap of the contact at P_r, which grows as P_r falls), so that, with the reloading
alike,

    W = 4 mu int p(X; P) s(X; Q*) dX   over the slip zones at Q*.                      (10)

By (3), delta_unloading(Q) = delta(Q*) - 2 delta((Q* - Q)/2) (delta on the loading branch:
Masing's rule), so also W = 4 Q* delta(Q*) - 8 int_0^{Q*} delta dQ.  For two cylinders of one
material (Hertz: P* = x P, c = a sqrt(x)), delta = (T mu P/pi) [(1 - x) log(a/(2 l))
- (x/2) log x - (1 - x)/2] with x = 1 - Q/(mu P), and

    W = (abs(T) mu^2 P^2 / pi) (1 - x*^2 + 2 x* log x*),   x* = 1 - Q*/(mu P),          (11)

which grows like abs(T) Q*^3 / (3 pi mu P) for small amplitudes and tends to
abs(T) mu^2 P^2 / pi at full sliding.

References: R. D. Mindlin and H. Deresiewicz, J. Appl. Mech. 20 (1953) 327; M. Ciavarella,
Int. J. Solids Struct. 35 (1998) 2349; J. Jager, J. Appl. Mech. 65 (1998) 1037;
D. A. Hills and D. Nowell, Mechanics of Fretting Fatigue (1994), ch. 4 and 5.
"""
from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np

from sie import gauss_jacobi

from .constants import surface_constants
from .elastic_punch import punch_constants, two_body_constants
from .errors import ContactInputError, FrictionError, LoadError, check_finite, real_array
from .partial_slip import check_decoupled, slip_stretches
from .solver import load_curve

__all__ = ["FrettingCycle", "FrettingState", "fretting_cycle"]

_BRANCHES = ("loading", "unloading", "reloading")


# --------------------------------------------------------------------------
# the states of the path
# --------------------------------------------------------------------------
@dataclasses.dataclass(frozen=True, eq=False)
class FrettingState:
    """One state of a fretting cycle (:func:`contact.fretting_cycle`): the traction
    q = sum_k w_k (p(X; P) - p(X; P_k)) (eqs. (2)-(4) of :mod:`contact.fretting`).

    Attributes
    ----------
    branch : {"loading", "unloading", "reloading"}
    tangential_load : float
        Q, the tangential traction's resultant on the half-space.
    displacement : float
        delta, the punch's tangential displacement relative to the half-space in the sense
        of Q (eq. (7); the datum of :func:`contact.fretting_cycle`'s ``reference_length``).
    full : ContactResult
        The frictionless contact at P.
    terms : tuple of (float, ContactResult)
        (w_k, the frictionless contact at P_k): the correctives the traction is made of;
        the last one's zones are the stick zones, the first one's the core.
    tangential_compliance : float
        T of the pair: d(u - u_p)/dX = T Hc[q].

    References
    ----------
    R. D. Mindlin and H. Deresiewicz, J. Appl. Mech. 20 (1953) 327; M. Ciavarella, Int. J.
    Solids Struct. 35 (1998) 2349; J. Jager, J. Appl. Mech. 65 (1998) 1037.

    Examples
    --------
    Two cylinders of one material, halfway down the unloading branch: the stick zone
    c'/a = sqrt(1 - (Q* - Q) / (2 mu P)), the reverse slip zones beyond it:

    >>> import math, contact
    >>> m = contact.Isotropic(1.0, 0.3)
    >>> cyc = contact.fretting_cycle(m, contact.CylindricalPunch(1.0), load=0.01,
    ...                              friction=0.5, tangential_amplitude=0.003,
    ...                              punch_material=m, steps=4)
    >>> st = cyc.unloading[2]
    >>> st.tangential_load, st.slip_sense
    (0.0, -1)
    >>> (c0, c1), = [z.ends for z in st.stick_zones]
    >>> round(c1 / cyc.full.ends[1], 12) == round(math.sqrt(1 - 0.003 / 0.01), 12)
    True
    """
    branch: str
    tangential_load: float
    displacement: float
    full: object = dataclasses.field(repr=False)
    terms: tuple = dataclasses.field(repr=False)
    tangential_compliance: float = dataclasses.field(repr=False)
    _core_point: float = dataclasses.field(default=0.0, repr=False)

    @property
    def stick_zones(self) -> tuple:
        """Where the slip increment vanishes: the zones of the last corrective's contact
        (the whole contact where there is none, at Q = 0 on loading)."""
        return self.terms[-1][1].zones if self.terms else self.full.zones

    @property
    def slip_zones(self) -> tuple:
        """(lo, hi) of each stretch of the contact outside the stick zones, left to right:
        where the surfaces slip now, in the sense :attr:`slip_sense`."""
        return slip_stretches(self.full.zones, self.stick_zones)

    @property
    def slip_sense(self) -> int:
        """+1 where the slip zones slip in the sense of positive Q (q = mu p there), -1
        where they slip back (q = -mu p); 0 without slip zones' traction (Q = 0 on
        loading)."""
        return int(np.sign(self.terms[-1][0])) if self.terms else 0

    def pressure(self, X):
        """p(X; P), the frictionless pressure (the pair decouples)."""
        return self.full.pressure(X)

    def tangential_traction(self, X):
        """q(X) = sum_k w_k (p(X; P) - p(X; P_k)) (eqs. (1)-(4); tau_XY(X, 0) = -q on the
        half-space): abs(q) <= mu p, equality on the slip zones."""
        p = self.full.pressure(X)
        return sum((w * (p - r.pressure(X)) for w, r in self.terms), np.zeros_like(p))

    shear = tangential_traction

    def slip(self, X):
        """s(X) = h(X) - h(X0) (eq. (8)): the punch surface's tangential displacement over
        the half-space's at X, in the sense of Q, accumulated since first touch; 0 on the
        core, which never slipped."""
        X = real_array("X", X, ContactInputError, "finite real numbers")
        if not np.all(np.isfinite(X)):
            raise ContactInputError("X must be finite real numbers")
        return relative_displacement(self, X) - relative_displacement(self, self._core_point)


def log_potential(result, X):
    """(1/pi) int p(t) log abs(X - t) dt of a numeric contact's pressure at real X (the
    datum l = 1 of eq. (5); :meth:`sie.Solution.log_potential`)."""
    return result.solution.log_potential(X)


def relative_displacement(state, X):
    """h(X) = u - u_p = -T sum_k w_k [Lambda(X; P) - Lambda(X; P_k)] (eq. (6)), at the datum
    l = 1 (the datum's term, linear in Q, cancels in the slip (8))."""
    if not state.terms:
        return np.zeros_like(np.asarray(X, dtype=float))
    full = log_potential(state.full, X)
    return -state.tangential_compliance * sum(w * (full - log_potential(r, X))
                                              for w, r in state.terms)


# --------------------------------------------------------------------------
# the cycle
# --------------------------------------------------------------------------
@dataclasses.dataclass(frozen=True, eq=False)
class FrettingCycle:
    """The path of a fretting test (:func:`contact.fretting_cycle`): loading from Q = 0 to
    Q*, unloading to -Q*, reloading to Q* (:mod:`contact.fretting`).

    Attributes
    ----------
    states : tuple of FrettingState
        The path in order: ``loading`` (Q from 0 to Q*), ``unloading`` (Q* to -Q*),
        ``reloading`` (-Q* to Q*); each branch starts where the one before ends.
    loading, unloading, reloading : tuple of FrettingState
        The branches.
    tangential_loads, displacements : ndarray
        Q and delta of every state, in path order.
    loop : (ndarray, ndarray)
        (Q, delta) of the closed loop, unloading then reloading (the first point is the
        last).
    energy_per_cycle : float
        W, the energy dissipated per cycle: the loop's area, computed as the frictional work
        4 mu int p s dX over the slip zones at Q* (eq. (10)).
    full : ContactResult
        The frictionless contact at P.
    curve : LoadCurve
        The frictionless contacts at the loads P - Q* t / mu (t at the Chebyshev points of
        [0, 1]): every corrective of every state.
    load, friction, tangential_amplitude, reference_length : float
        P, mu, Q* and the datum l of the displacements (eq. (5)).

    References
    ----------
    R. D. Mindlin and H. Deresiewicz, J. Appl. Mech. 20 (1953) 327; M. Ciavarella, Int. J.
    Solids Struct. 35 (1998) 2349; J. Jager, J. Appl. Mech. 65 (1998) 1037; D. A. Hills and
    D. Nowell, Mechanics of Fretting Fatigue (1994).

    Examples
    --------
    The loop of two cylinders of one material is point-symmetric, and its area is eq. (11)
    of :mod:`contact.fretting`:

    >>> import math, contact
    >>> m = contact.Isotropic(1.0, 0.3)
    >>> P, mu, Qa = 0.01, 0.5, 0.003
    >>> cyc = contact.fretting_cycle(m, contact.CylindricalPunch(1.0), load=P,
    ...                              friction=mu, tangential_amplitude=Qa,
    ...                              punch_material=m, steps=8)
    >>> [(s.tangential_load, -r.tangential_load) for s, r in
    ...  zip(cyc.unloading, cyc.reloading)] == [(s.tangential_load,) * 2 for s in cyc.unloading]
    True
    >>> [s.displacement for s in cyc.unloading] == [-r.displacement for r in cyc.reloading]
    True
    >>> x, T = 1 - Qa / (mu * P), cyc.full.constants.tangential_compliance
    >>> W = abs(T) * (mu * P) ** 2 / math.pi * (1 - x * x + 2 * x * math.log(x))
    >>> round(cyc.energy_per_cycle / W, 10)
    1.0
    """
    states: tuple = dataclasses.field(repr=False)
    full: object = dataclasses.field(repr=False)
    curve: object = dataclasses.field(repr=False)
    load: float
    friction: float
    tangential_amplitude: float
    reference_length: float
    energy_per_cycle: float

    def _branch(self, name):
        return tuple(s for s in self.states if s.branch == name)

    @property
    def loading(self) -> tuple:
        """The loading branch: Q from 0 to Q*."""
        return self._branch("loading")

    @property
    def unloading(self) -> tuple:
        """The unloading branch: Q from Q* to -Q*."""
        return self._branch("unloading")

    @property
    def reloading(self) -> tuple:
        """The reloading branch: Q from -Q* to Q*."""
        return self._branch("reloading")

    @property
    def tangential_loads(self) -> np.ndarray:
        """Q of every state, in path order."""
        return np.array([s.tangential_load for s in self.states])

    @property
    def displacements(self) -> np.ndarray:
        """delta of every state, in path order (eq. (7))."""
        return np.array([s.displacement for s in self.states])

    @property
    def loop(self) -> tuple:
        """(Q, delta) of the closed loop: the unloading, then the reloading without its
        first state (the unloading's last)."""
        closed = self.unloading + self.reloading[1:]
        return (np.array([s.tangential_load for s in closed]),
                np.array([s.displacement for s in closed]))


def fretting_cycle(material, punch, *, load, tangential_amplitude, friction,
                   punch_material=None, steps=16, reference_length=None, n=None,
                   tol=1e-12):
    """The fretting cycle of a pair whose normal and tangential problems decouple: the normal
    load, then the tangential load from 0 to Q*, back to -Q* and up to Q* at that load.

    The states of each branch are at the Chebyshev points of Q (dense at the turning
    points): loading Q = Q* t, unloading Q = Q* c, reloading Q = -Q* c, with
    c = cos(pi i / steps), t = (1 - c) / 2, i = 0, ..., steps (at these points the loop's
    area (eq. (9)) is a Clenshaw-Curtis sum, spectrally accurate for a smooth face; a
    break of the slope puts a kink in the loop where the stick zone's end crosses it).  Each state is the superposition
    of frictionless contacts at the loads P - Q* t / mu (eqs. (2)-(4) of
    :mod:`contact.fretting`), followed in one continuation (:func:`contact.load_curve`).

    Parameters
    ----------
    material : Material
        The half-space's material, as for :func:`contact.solve` (at rest: speed 0).
    punch : Punch
        Its face.
    load : float
        P > 0, the normal load, applied first and then held.
    tangential_amplitude : float
        Q*, 0 < Q* < friction * load: the amplitude of the tangential load (Q > 0: the
        traction on the half-space toward -X).
    friction : float
        Coulomb coefficient mu > 0.
    punch_material : Orthotropic or Anisotropic, optional
        The punch's material (None: a rigid punch, which decouples only from an
        incompressible half-space).  The pair must decouple (Dundurs' beta = 0: two bodies
        of one material, or two isotropic ones with (1 - 2 nu1)/G1 = (1 - 2 nu2)/G2).
    steps : int
        Increments of Q per branch, >= 2.
    reference_length : float, optional
        l > 0, the datum of the displacements (eq. (5)): the displacement in 2-D is defined
        up to a term proportional to Q, fixed by l; the loop's area and its width at each Q
        do not depend on it.  None: the contact's half-width at P (half its span).
    n, tol
        As for :func:`contact.solve`.

    Returns
    -------
    FrettingCycle

    Raises
    ------
    FrictionError
        Q* not below friction * load (the punch slides as a whole: full sliding), or
        friction = 0.
    LoadError
        Q* not positive or not finite; ``load`` not positive.
    CoupledPartialSlipError
        The pair couples (beta != 0: a rigid punch on a compressible half-space, dissimilar
        bodies).
    ContactInputError
        Other inputs, as for :func:`contact.solve`; a material without the tangential
        compliance.

    Warns
    -----
    RuntimeWarning
        The energy's quadrature on a slip zone did not settle to 1e-11 (a face too rough
        there), or, from :func:`contact.load_curve`, the adaptive n reached its cap.

    References
    ----------
    R. D. Mindlin and H. Deresiewicz, J. Appl. Mech. 20 (1953) 327 (the unloading and the
    reloading, eqs. (3)-(4) of :mod:`contact.fretting`); M. Ciavarella, Int. J. Solids
    Struct. 35 (1998) 2349 and J. Jager, J. Appl. Mech. 65 (1998) 1037 (any face of this
    class); D. A. Hills and D. Nowell, Mechanics of Fretting Fatigue (1994).

    Examples
    --------
    Two cylinders of one material: at Q = 0 on the unloading the stick zone is
    c'/a = sqrt(1 - Q*/(2 mu P)), and the loop's area grows like Q*^3 for small amplitudes:

    >>> import math, contact
    >>> m = contact.Isotropic(1.0, 0.3)
    >>> def cycle(Qa):
    ...     return contact.fretting_cycle(m, contact.CylindricalPunch(1.0), load=0.01,
    ...                                   friction=0.5, tangential_amplitude=Qa,
    ...                                   punch_material=m, steps=4)
    >>> cyc = cycle(0.002)
    >>> [round(s.tangential_load, 6) for s in cyc.unloading]   # Q* cos(pi i / 4)
    [0.002, 0.001414, 0.0, -0.001414, -0.002]
    >>> c = cyc.unloading[2].stick_zones[0].ends[1]
    >>> round(c / cyc.full.ends[1] / math.sqrt(1 - 0.002 / 0.01), 12)
    1.0
    >>> round(math.log2(cycle(2e-4).energy_per_cycle / cycle(1e-4).energy_per_cycle), 1)
    3.0
    """
    P = check_finite("load", load, LoadError)
    mu = check_finite("friction", friction, FrictionError)
    Qa = check_finite("tangential_amplitude", tangential_amplitude, LoadError)
    if not Qa > 0:
        raise LoadError(f"tangential_amplitude must be positive (the amplitude Q* of the "
                        f"cycle; Q runs from Q* to -Q*), got {Qa!r}")
    if not mu > 0:
        raise FrictionError(f"a fretting cycle needs friction > 0 (without friction any "
                            f"tangential load slides the punch), got {mu!r}")
    if P > 0 and not Qa < mu * P:
        raise FrictionError(
            f"tangential_amplitude = {Qa!r} is not below friction * load = {mu * P!r}: the "
            "punch slides as a whole (full sliding) and the loop is a rectangle of "
            "gross slip, not partial slip")
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or steps < 2:
        raise ContactInputError(f"steps must be an integer >= 2 (increments of Q per "
                                f"branch), got {steps!r}")
    const = surface_constants(material, 0.0)
    if punch_material is not None:
        const = two_body_constants(const, punch_constants(punch_material))
    check_decoupled(const)
    T = const.tangential_compliance
    if T is None:
        raise ContactInputError("a fretting cycle needs the pair's tangential compliance "
                                "(du/dX per Hc[q], SurfaceConstants.tangential_compliance), "
                                "which this material does not give")
    m = int(steps)
    c = chebyshev_points(m)
    t = 0.5 * (1.0 - c)
    curve = load_curve(material, punch, (P - Qa * t / mu)[::-1], speed=0.0,
                       punch_material=punch_material, n=n, tol=tol)
    at = curve.results[::-1]          # at[i]: the contact at P - Q* t_i / mu
    full = at[0]
    span = full.zones[-1].ends[1] - full.zones[0].ends[0]
    ell = 0.5 * span if reference_length is None else \
        check_finite("reference_length", reference_length, ContactInputError)
    if not ell > 0:
        raise ContactInputError(f"reference_length must be positive, got {ell!r}")
    states = _states(full, at, c, Qa, mu, T, ell)
    return FrettingCycle(states, full, curve, P, mu, Qa, ell,
                         energy_per_cycle(states[m], mu))


def chebyshev_points(m: int) -> np.ndarray:
    """cos(pi i / m), i = 0..m, from 1 down to -1, as sin(pi (m - 2 i) / (2 m)): exactly
    odd about the middle (0 there for even m; the unloading and the reloading then meet
    at the same Q)."""
    return np.sin(0.5 * np.pi * (m - 2 * np.arange(m + 1)) / m)


def _states(full, at, c, Qa, mu, T, ell):
    """The states of eqs. (2)-(4) at the Chebyshev points c (the contacts ``at``
    P - Q* t / mu, t = (1 - c)/2), the displacement of each by eq. (7) on the core X0 (the
    middle of the first zone of the contact at P*, inside every contact of the path)."""
    m = len(c) - 1
    core = at[m].zones[0].ends
    X0 = 0.5 * (core[0] + core[1])
    # D_i = Lambda(X0; P) - Lambda(X0; P_i) of eq. (7), the datum l in Lambda (eq. (5))
    L = np.array([float(log_potential(r, X0)) for r in at])
    loads = np.array([r.load for r in at])
    D = (L[0] - L) - (full.load - loads) * math.log(ell) / math.pi

    def state(branch, Q, terms):
        delta = T * sum(w * D[i] for w, i in terms)
        return FrettingState(branch, float(Q), float(delta), full,
                             tuple((w, at[i]) for w, i in terms), T, X0)

    loading = [state("loading", Qa * 0.5 * (1.0 - c[i]), [(mu, i)] if i else [])
               for i in range(m + 1)]
    unloading = [state("unloading", Qa * c[i], [(mu, m), (-2 * mu, i)])
                 for i in range(m + 1)]
    reloading = [state("reloading", -Qa * c[i], [(-mu, m), (2 * mu, i)])
                 for i in range(m + 1)]
    return tuple(loading + unloading + reloading)


def energy_per_cycle(peak, mu):
    """W = 4 mu int p(X; P) s(X; Q*) dX over the slip zones of the loading state at Q*
    (eq. (10)), by Gauss-Jacobi quadrature on each zone (:func:`slip_zone_integral`)."""
    return 4.0 * mu * sum(slip_zone_integral(peak, lo, hi) for lo, hi in peak.slip_zones)


def slip_zone_integral(peak, lo, hi):
    """int p s dX over the slip zone (lo, hi) of the state ``peak``, cut at the face's breaks
    inside it: Gauss-Jacobi on each piece with the weight of the integrand's ends (p's
    exponent at an end of the contact; s's, 1 + that of the stick zone's pressure, at an
    end of a stick zone: there s grows like the gap of the contact at P*; 0 at a break),
    its nodes doubled from 32 until two rules agree to :data:`ENERGY_TOL` (spectral on a
    smooth piece), up to :data:`ENERGY_MAX_NODES` (a RuntimeWarning says the agreement
    reached)."""
    e = {b: 0.0 for b in peak.full.punch.breaks}
    for z in peak.stick_zones:
        e[z.ends[0]], e[z.ends[1]] = 1.0 + z.beta, 1.0 + z.alpha
    for z in peak.full.zones:
        e[z.ends[0]], e[z.ends[1]] = z.beta, z.alpha
    cuts = [lo, *(b for b in peak.full.punch.breaks if lo < b < hi), hi]

    def rule(n):
        total = 0.0
        for x0, x1 in zip(cuts, cuts[1:]):
            a, b, h = e[x0], e[x1], 0.5 * (x1 - x0)
            u, w = gauss_jacobi(n, b, a)              # weight (1 - u)^b (1 + u)^a
            X = x0 + h * (1.0 + u)
            f = peak.pressure(X) * peak.slip(X) / ((h * (1.0 + u)) ** a * (h * (1.0 - u)) ** b)
            total += h ** (1.0 + a + b) * float(w @ f)
        return total

    n, last, change = 32, rule(32), math.inf
    while n < ENERGY_MAX_NODES:
        n *= 2
        new = rule(n)
        if abs(new - last) <= ENERGY_TOL * abs(new):
            return new
        change, last = abs(new - last) / abs(new), new
    warnings.warn(f"contact.fretting_cycle: the energy on the slip zone ({lo!r}, {hi!r}) "
                  f"changed by {change:.2g} of itself from {n // 2} to {n} Gauss-Jacobi nodes "
                  f"(> {ENERGY_TOL:g}): the face is not smooth enough there for the rule, "
                  "or the slip is at the rounding of its log potentials",
                  RuntimeWarning, stacklevel=5)
    return last


#: The relative agreement of two successive rules of :func:`slip_zone_integral` (the slip,
#: a difference of log potentials, carries their rounding: at small amplitudes about 1e-13
#: of the energy).
ENERGY_TOL = 1e-11
#: The most nodes :func:`slip_zone_integral` doubles to.
ENERGY_MAX_NODES = 2048
