"""The moving frictional punch, solved numerically through :func:`sie.solve`.

Zhou, Lee & Jang 2014, eqs. (4.5)-(4.10), with the conventions of the documentation (Theory:
the contact model and its conventions): on the contact [x_l, x_r], with X = h s + m
(h = (x_r - x_l)/2, m = (x_r + x_l)/2), p(X) = psi(s) solves

    a psi(s) + (b/pi) PV int psi(t)/(t - s) dt = v'(h s + m),     |s| < 1,
    h int psi ds = P,

a = N12 mu_f, b = N11 + M12 mu_f (M12 = 0 for an orthotropic material aligned with the frame:
:class:`contact.SurfaceConstants`),

with mu_f = -direction * mu (direction -1: the punch slides toward -X, friction traction on
the half-space toward -X, trailing edge on the right).  A sharp corner makes its end singular
and fixes it; a free end is bounded and unknown.  Index 1 (two corners): ends known, the load
is the side condition.  Index 0 (one corner): the free end is the root of load(L) = P.  Index
-1 (two free ends): the solvability condition of the equation (eq. (5.40)) and the load.
"""
from __future__ import annotations

import gc
import warnings
from contextlib import contextmanager
from dataclasses import dataclass, replace

import numpy as np

import sie
from sie import N_MAX
from sie.assembly import N_MAX_DENSE
from sie.exponents import MIN_B_OVER_A, check_coefficients

from .closed_form import CLOSED_FORMS
from .constants import SurfaceConstants, surface_constants
from .elastic_punch import punch_constants, two_body_constants
from .partial_slip import PartialSlipResult, check_decoupled, stick_load, tilted_face
from .kernel import contact_kernel, own_errors
from .continuation import (ZoneState, follow_last_again, follow_load, inspect_state,
                           zone_pressures)
from .lockstep import first_steps
from .errors import (ContactInputError, ContactLossError, DirectionError, FrictionError, LoadError,
                     check_finite, real_array)
from .protocol import check_material
from .punches import Punch
from .result import (RESIDUAL_U, ContactResult, ContactZone, LoadCurve,
                     _ClosedFormContactResult, _sif, relative_residual)
from .zones import CORNER, Zone, ZoneEquations

__all__ = ["solve", "solve_batch", "load_curve", "ContactResult", "LoadCurve", "contact_length"]

_N_DEFAULT = 12
_N_FOLLOW = 512    # the continuation raises n up to here to resolve its states (adaptive n)
_N_MAX = 4096      # adaptive doubling stops here
#: Couplings M12, M21, M22 below this fraction of their scale are rounding
#: (:func:`_closed_form_result`).
_ROUNDING = 64 * np.finfo(float).eps


# --------------------------------------------------------------------------
# public entry point
# --------------------------------------------------------------------------
def _check_inputs(material, punch, load, speed, friction, direction, method, n, tol,
                  material_checked=False):
    if not material_checked:
        check_material(material)
    if not isinstance(punch, Punch):
        raise ContactInputError(
            "punch must be one of FlatPunch, TriangularPunch, ParabolicPunch, CylindricalPunch, "
            f"ProfilePunch; got {type(punch).__name__}")
    load = check_finite("load", load, LoadError)
    if load <= 0:
        raise LoadError(f"load must be positive (force per unit length pressing the punch in), got {load!r}")
    friction = check_finite("friction", friction, FrictionError)
    if friction < 0:
        raise FrictionError(f"friction must be >= 0 (a coefficient; the sliding direction is "
                            f"set by `direction`), got {friction!r}")
    if isinstance(direction, bool) or direction not in (-1, 1):
        raise DirectionError(f"direction must be -1 (punch slides toward -X) or +1 (toward +X), "
                             f"got {direction!r}")
    if method not in ("numeric", "closed_form"):
        raise ContactInputError(f'method must be "numeric" or "closed_form", got {method!r}')
    if n is not None:
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 2 <= n <= N_MAX:
            raise ContactInputError(f"n must be an integer in [2, {N_MAX}] (Jacobi coefficients "
                                    f"per zone, sie.N_MAX at most) or None, got {n!r}")
    tol = check_finite("tol", tol, ContactInputError)
    if not 0 < tol < 1:
        raise ContactInputError(f"tol must be in (0, 1), got {tol!r}")
    return load, friction, int(direction), tol


def _surface_constants(material, speed, constants):
    if constants is None:
        return surface_constants(material, speed)
    if not isinstance(constants, SurfaceConstants):
        raise ContactInputError(f"constants must be a contact.SurfaceConstants or None, got "
                                f"{type(constants).__name__}")
    if constants.c != check_finite("speed", speed, ContactInputError):
        raise ContactInputError(f"constants are for speed {constants.c!r}, but speed = {speed!r}")
    return constants


def solve(material, punch, *, load, speed, friction=0.0, direction=-1, method="numeric",
          n=None, tol=1e-12, constants=None, punch_material=None, tangential_load=None,
          rolling=False, creepage=None):
    """Contact zones, pressure, SIFs and surface stress of a sliding punch.

    The zones are followed in load from the first touch of the face (its lowest point or
    points) up to ``load`` (:mod:`contact.continuation`): zones appear where the face closes
    a valley, merge, and turn an end into a corner at an edge of the face.

    Parameters
    ----------
    material : Material
        :class:`Orthotropic` (or :func:`Isotropic`), or any object with the methods of the
        :class:`Material` protocol.
    punch : Punch
        FlatPunch, TriangularPunch, ParabolicPunch, CylindricalPunch or ProfilePunch.
    load : float
        P > 0, normal force per unit length.
    speed : float
        Relative speed c = V / sqrt(C33/rho), 0 <= c < c_R.
    friction : float
        Coulomb coefficient mu >= 0.
    direction : {-1, +1}
        -1: the punch slides toward -X (trailing edge on the right, the paper's figures).
    method : {"numeric", "closed_form"}
        "closed_form" evaluates the corrected closed forms (the four punches only, on a
        material without the couplings M12, M21, M22 of :class:`SurfaceConstants`, to
        rounding).
    n : int, optional
        Jacobi coefficients per zone; by default chosen adaptively until two successive n
        agree to tol.
    tol : float
        Target relative accuracy of the pressure and the ends (adaptive n).
    constants : SurfaceConstants, optional
        ``surface_constants(material, speed)`` computed beforehand (a sweep over friction
        at one speed shares them); must be for this speed (the half-space's alone, also
        with ``punch_material``).
    punch_material : Orthotropic or Anisotropic, optional
        The punch's own material: an elastic punch, its compliance added to the
        half-space's (:mod:`contact.elastic_punch`; the punch at rest, the half-space
        moving).  None: a rigid punch.  The result's gap is then the gap between the two
        deformed surfaces; its stresses are the half-space's.
    tangential_load : float, optional
        Q, abs(Q) < friction * load: the contact pressed by ``load`` and then pulled by Q at
        that load, in partial slip (Cattaneo, Mindlin; :mod:`contact.partial_slip`), for a
        pair whose normal and tangential problems decouple (``punch_material`` the
        material, at speed 0: Dundurs' beta = 0); ``direction`` is not used
        (the sign of Q is the sense of the traction on the half-space).  Returns a
        :class:`contact.partial_slip.PartialSlipResult`.
    rolling : bool
        Steady rolling (Carter; quasi-static, ``speed`` 0) toward ``direction`` with
        ``tangential_load`` or ``creepage`` (one of them): the stick zone at the leading
        edge (:mod:`contact.partial_slip`), for a pair that decouples.
    creepage : float, optional
        With ``rolling``: the creepage xi = d(u - u_p)/dX on the stick zone; the tangential
        load follows.

    Returns
    -------
    ContactResult, or PartialSlipResult with ``tangential_load``

    Raises
    ------
    ContactInputError
        (or a subclass: LoadError, FrictionError, SpeedError, ...) for inputs outside what is
        allowed; ContactLossError when no change of the zones gives a valid contact.

    Warns
    -----
    NearRayleighWarning
        speed > 0.99 c_R.
    RuntimeWarning
        The adaptive n reached its cap before two successive n agreed to ``tol``.

    Notes
    -----
    On each zone the pressure solves a p + (b/pi) PV int p(t)/(t - X) dt = v'(X),
    a = N12 mu_f, b = N11 + M12 mu_f (module docstring; :class:`SurfaceConstants`), by
    :func:`sie.solve` on the union of the zones; free ends are found from the loads, the
    solvability condition of index -1 zones and the common rigid face.

    References
    ----------
    Zhou, Lee & Jang, "Indentation theory on orthotropic materials subjected to a frictional
    moving punch", Arch. Mech. 66 (2014), eqs. (4.5)-(4.10) (the equation), (5.40) (the
    solvability condition), Sec. 5 (the four punches); see the documentation, Theory: the
    contact model and its conventions.

    Examples
    --------
    >>> import contact
    >>> r = contact.solve(contact.zhou2014(), contact.CylindricalPunch(radius=100.0),
    ...                   load=0.01, speed=0.6, friction=0.3)
    >>> len(r.zones), r.zones[0].kinds
    (1, ('free', 'free'))

    Without friction the cylinder gives the Hertz pressure p(0) = 2P / (pi a):

    >>> import math
    >>> r = contact.solve(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0),
    ...                   load=0.01, speed=0.0)
    >>> round(float(r.pressure(0.0)) / (2 * 0.01 / (math.pi * r.half_width)), 12)
    1.0
    """
    load, friction, direction, tol = _check_inputs(material, punch, load, speed, friction,
                                                   direction, method, n, tol)
    if rolling is not False:
        return _rolling(material, punch, load, speed, friction, direction, method, n, tol,
                        constants, punch_material, tangential_load, creepage, rolling)
    if creepage is not None:
        raise ContactInputError("creepage is the creepage of rolling: give rolling=True (a "
                                "static contact under a tangential load: tangential_load=)")
    if tangential_load is not None:
        return _partial_slip(material, punch, load, speed, friction, method, n, tol,
                             constants, punch_material, tangential_load)
    problem = _problem(material, punch, speed, friction, direction, constants, punch_material)
    return _solve_problem(problem, load, method, n, tol)


def _solve_problem(problem, load, method, n, tol):
    """The ContactResult of a checked problem at one load."""
    if method == "closed_form":
        return _closed_form_result(problem, load)
    return _numeric_cases(problem.punch, [_Case(problem, load)], n, tol)[0]


def _partial_slip(material, punch, load, speed, friction, method, n, tol, constants,
                  punch_material, tangential_load) -> PartialSlipResult:
    """:func:`solve` with a tangential load: the contact at P and at P* = P - abs(Q)/mu with
    the friction sign(Q) mu (eq. (1) of :mod:`contact.partial_slip`), for a pair that
    decouples (checked on the constants)."""
    P_star = stick_load(load, tangential_load, friction)
    Q = float(tangential_load)
    # mu_f = -direction * friction = sign(Q) mu: q = mu_f p on the slip zones
    direction = -1 if Q > 0 else 1
    problem = _problem(material, punch, speed, friction if Q != 0.0 else 0.0, direction,
                       constants, punch_material)
    check_decoupled(problem.const)
    full = _solve_problem(problem, load, method, n, tol)
    stick = None if Q == 0.0 else _solve_problem(problem, P_star, method, n, tol)
    return PartialSlipResult(full, stick, Q, load, friction)


def _rolling(material, punch, load, speed, friction, direction, method, n, tol, constants,
             punch_material, tangential_load, creepage, rolling) -> PartialSlipResult:
    """:func:`solve` with ``rolling``: Carter's stick zone at the leading edge (module
    docstring of :mod:`contact.partial_slip`), the tilt k of the stick zone's face from Q
    (or P* from the creepage) by Brent's method on the leading end."""
    from scipy.optimize import brentq
    if rolling is not True:
        raise ContactInputError(f"rolling must be True or False, got {rolling!r}")
    if (tangential_load is None) == (creepage is None):
        raise ContactInputError("rolling needs one of tangential_load and creepage (the other "
                                "follows)")
    if method != "numeric":
        raise ContactInputError('rolling takes method="numeric" (the stick zone\'s face is '
                                "tilted: no closed form)")
    lead = 0 if direction < 0 else 1          # the leading end: toward the rolling
    problem = _problem(material, punch, speed, friction, -1, constants, punch_material)
    check_decoupled(problem.const)
    T, b = problem.const.tangential_compliance, problem.const.N11
    if T is None:
        raise ContactInputError("rolling needs the pair's tangential compliance (du/dX per "
                                "Hc[q], SurfaceConstants.tangential_compliance), which this "
                                "material does not give")
    if friction == 0.0:
        raise FrictionError("rolling needs friction > 0 (without friction nothing is "
                            "transmitted and there is no stick zone)")

    problems = {1.0: problem}       # by s = sign Q (mu_f = s mu, its kernel with it)

    def at(P, face, s):
        if s not in problems:
            problems[s] = _problem(material, punch, speed, friction, -int(s), constants,
                                   punch_material)
        return _solve_problem(replace(problems[s], punch=face), P, method, n, tol)

    def lead_end(r):
        return r.zones[0].ends[0] if lead == 0 else r.zones[-1].ends[1]

    sign = -1.0 if lead == 0 else 1.0      # a convex face's stick zone moves that way
    if creepage is None:
        P_star = stick_load(load, tangential_load, friction)
        Q = float(tangential_load)
        s = -1.0 if Q < 0 else 1.0
    else:
        xi = check_finite("creepage", creepage, ContactInputError)
        # xi = T s mu k / b with k of the sign that moves the stick zone to the leading end
        s = 1.0 if xi * b / T * sign > 0 else -1.0
        Q = None if xi != 0.0 else 0.0
    full = at(load, punch, s)       # the pressure does not depend on s (decoupled)
    if Q == 0.0:
        return PartialSlipResult(replace(full, mu_f=0.0), None, 0.0, load, friction, 0.0)
    edge = lead_end(full)
    if creepage is None:
        span = abs(float(punch.slope(full.ends[1])) - float(punch.slope(full.ends[0])))
        k = brentq(lambda k: lead_end(at(P_star, tilted_face(punch, k), s)) - edge, 0.0,
                   sign * span, xtol=1e-15 * max(span, 1e-300), rtol=4 * np.finfo(float).eps)
    else:
        k = xi * b / (T * s * friction)
        face = tilted_face(punch, k)    # one face (its scan) for every load tried
        try:
            P_star = brentq(lambda P: lead_end(at(P, face, s)) - edge, 1e-12 * load, load,
                            xtol=1e-15 * load, rtol=4 * np.finfo(float).eps)
        except ValueError:
            raise FrictionError(
                f"creepage = {xi!r} is beyond full slip for friction = {friction!r} at load = "
                f"{load!r} (no stick zone at the leading edge): the rolling contact slides "
                "everywhere") from None
        Q = s * friction * (load - P_star)
    stick = at(P_star, tilted_face(punch, k), s)
    return PartialSlipResult(full, stick, Q, load, friction, T * s * friction * k / b)


def solve_batch(material, punch, *, load, speed, friction=0.0, direction=-1,
                method="numeric", n=None, tol=1e-12, constants=None, residual=False,
                errors="raise", punch_material=None):
    """:func:`solve` for many cases of one material and punch at once.

    ``load``, ``speed``, ``friction`` and ``direction`` broadcast against each other (numpy
    rules); each element of the broadcast is a case.  The cases go through the first step
    of the load continuation together (:mod:`contact.lockstep`: each stage one vectorised
    call for all of them); a case that step cannot finish (an event on the way, a face that
    needs Newton's method or a larger n) is solved alone.  Either way each result is what
    :func:`solve` returns for that case -- which goes the same way, as a batch of one.

    Parameters
    ----------
    material, punch, method, n, tol, punch_material
        As for :func:`solve`, shared by all cases.
    load, speed, friction, direction : float or array_like
        Per case, broadcast together.
    constants : sequence of SurfaceConstants, optional
        One per case (``surface_constants(material, speed)`` of its speed), computed
        beforehand; by default computed once for each distinct speed.
    residual : bool
        Compute each result's ``residual`` diagnostic now, for all cases in one vectorised
        pass (otherwise on first access, case by case).
    errors : {"raise", "return"}
        "raise": the first case with inputs outside what is allowed (or whose contact cannot
        be found) raises, as :func:`solve` would.  "return": that case's exception takes its
        place in the output, and the other cases are solved.

    Returns
    -------
    list of ContactResult
        One per case, in the C order of the broadcast shape.

    Raises
    ------
    ContactInputError
        (or a subclass) as for :func:`solve`, for the first case at fault (``errors="raise"``);
        also for arguments that do not broadcast, ``constants`` of the wrong length, or an
        ``errors`` other than "raise" or "return".

    References
    ----------
    As for :func:`solve`.

    Examples
    --------
    Three frictions of a cylinder sliding at 0.6: the trailing (right) exponent falls as the
    friction grows.

    >>> import contact
    >>> rs = contact.solve_batch(contact.zhou2014(), contact.CylindricalPunch(radius=100.0),
    ...                          load=0.01, speed=0.6, friction=[0.0, 0.2, 0.4])
    >>> [round(r.alpha, 6) for r in rs]
    [0.5, 0.489798, 0.479616]
    >>> r = contact.solve(contact.zhou2014(), contact.CylindricalPunch(radius=100.0),
    ...                   load=0.01, speed=0.6, friction=0.2)
    >>> r.ends == rs[1].ends
    True
    """
    if errors not in ("raise", "return"):
        raise ContactInputError(f'errors must be "raise" or "return", got {errors!r}')
    try:
        P, V, M, D = np.broadcast_arrays(*(np.asarray(v, dtype=object)
                                           for v in (load, speed, friction, direction)))
    except ValueError:
        raise ContactInputError(
            "load, speed, friction and direction must broadcast against each other, got "
            f"shapes {[np.shape(v) for v in (load, speed, friction, direction)]}") from None
    count = P.size
    if constants is not None and (isinstance(constants, SurfaceConstants)
                                  or not hasattr(constants, "__len__")):
        raise ContactInputError("constants must be a sequence of SurfaceConstants, one per "
                                f"case, or None; got {type(constants).__name__}")
    if constants is not None and len(constants) != count:
        raise ContactInputError(f"constants must hold one SurfaceConstants per case "
                                f"({count}), got {len(constants)}")
    cases, out = [], [None] * count
    shared = {}
    punch_const = None if punch_material is None else punch_constants(punch_material)
    material_ok = False
    layered = getattr(material, "surface_kernel", None) is not None
    for i, (Pi, Vi, Mi, Di) in enumerate(zip(P.ravel().tolist(), V.ravel().tolist(),
                                             M.ravel().tolist(), D.ravel().tolist())):
        try:
            Pi, Mi, Di, _ = _check_inputs(material, punch, Pi, Vi, Mi, Di, method, n, tol,
                                          material_checked=material_ok)
            material_ok = True          # one material for all: checked once
            if constants is not None:
                const = _surface_constants(material, Vi, constants[i])
            else:
                key = check_finite("speed", Vi, ContactInputError)
                const = shared.get(key)
                if const is None:
                    const = shared[key] = surface_constants(material, Vi)
            if punch_const is not None:
                const = two_body_constants(const, punch_const)
            mu_f = _signed_friction(const, Mi, Di)
            problem = _Problem(material, punch, const, const.c, Mi, Di, mu_f,
                               contact_kernel(material, const.c, mu_f) if layered else None,
                               punch_material)
            if method == "closed_form":
                out[i] = _closed_form_result(problem, Pi)
                continue
        except ContactInputError as exc:
            if errors == "raise":
                raise
            out[i] = exc
            continue
        cases.append((i, _Case(problem, Pi)))
    if cases:
        with _collections_deferred():
            solved = _numeric_cases(punch, [c for _, c in cases], n, tol, errors=errors,
                                    residual=residual)
        for (i, _), r in zip(cases, solved):
            out[i] = r
    return out


#: Allocations between passes of the collector over the young objects while a batch of cases
#: runs (Python's default is 700); the open batches of the process, and the thresholds before
#: the first of them, which come back when the last one ends.
_BATCH_GC_THRESHOLD = 100_000
_deferrals = 0
_threshold_before = None


@contextmanager
def _collections_deferred():
    """Python's cyclic collector run rarely while a batch of cases runs: a batch allocates
    some hundred small objects a case and keeps them to its end, and each pass of the
    collector that they set off walks the young objects, every so often all of the
    process's (numpy's, numba's, scipy's).  Reference counting frees what a batch discards
    (it makes no reference cycles).  The collector stays on, its first threshold raised to
    :data:`_BATCH_GC_THRESHOLD` until the last open batch of the process ends.  No lock
    (a process forked while a thread held one would wait on it for ever): two threads that
    open and close batches at the same instant can at worst leave the threshold raised, and
    a process forked inside a batch keeps it; either only makes the collector run less
    often."""
    global _deferrals, _threshold_before
    if _deferrals == 0:
        _threshold_before = gc.get_threshold()
        gc.set_threshold(max(_BATCH_GC_THRESHOLD, _threshold_before[0]), *_threshold_before[1:])
    _deferrals += 1
    try:
        yield
    finally:
        _deferrals = max(0, _deferrals - 1)
        if _deferrals == 0 and _threshold_before is not None:
            gc.set_threshold(*_threshold_before)


def _signed_friction(const, friction, direction) -> float:
    """mu_f = -direction * friction (0 without friction: no friction terms), refused where
    the coefficients a = N12 mu_f, b = N11 + M12 mu_f of the equation
    (:meth:`SurfaceConstants.equation_coefficients`) leave b >= 0 (the surface outside the
    contact no longer sinks under the pressure: dv/dX = b Hc[p] there) or make a so large
    against b that an end exponent of the pressure rounds to -1 or 1
    (:func:`sie.exponents.check_coefficients`)."""
    if friction == 0.0:
        return 0.0
    mu_f = -direction * friction
    a, b = const.equation_coefficients(mu_f)
    toward = "-X" if direction < 0 else "+X"
    if not b < 0.0:
        # b = N11 + M12 mu_f < 0 for -direction * M12 * friction < -N11
        limit = -const.N11 / abs(const.M12)
        raise FrictionError(
            f"friction = {friction!r} sliding toward {toward} makes the coefficient "
            f"b = N11 + M12 mu_f = {b:.6g} of Hc[p] in the contact equation >= 0 (N11 = "
            f"{const.N11:.6g}, M12 = {const.M12:.6g}, mu_f = {mu_f!r}): the surface would no "
            f"longer sink under the pressure.  This material at this speed stops sinking at "
            f"friction = abs(N11 / M12) = {limit:.6g} in this direction (allowed: friction "
            f"below that; sliding toward {'+X' if direction < 0 else '-X'} the coupling M12 "
            f"makes b more negative)") from None
    try:
        check_coefficients(a, b)
    except sie.InvalidCoefficientError:
        # |b| >= MIN_B_OVER_A |a|: friction (MIN_B_OVER_A |N12| + M12 mu_f / friction) < -N11
        rate = MIN_B_OVER_A * abs(const.N12) + const.M12 * (mu_f / friction)
        allowed = (f"friction below about {-const.N11 / rate:.3g} for this material at this "
                   f"speed and direction" if rate > 0.0 else
                   "a friction that resolves the exponents in double precision")
        raise FrictionError(
            f"friction = {friction!r} puts an end exponent of the pressure within rounding "
            f"of -1 or 1 in double precision (|a / b| = |N12 mu_f / (N11 + M12 mu_f)| = "
            f"{abs(a / b):.3g}): its singularity is not integrable there (allowed: "
            f"{allowed}; Coulomb coefficients of real materials are below ~10)") from None
    return mu_f


@dataclass(frozen=True)
class _Problem:
    """A contact problem, validated once: the material and the punch, the punch's motion
    (relative speed, friction, direction) and what the equation is made of, the surface
    constants at that speed, the signed friction mu_f = -direction * friction and the
    material's regular kernel (:mod:`contact.kernel`; None for a homogeneous half-space).
    The loads of a load curve share one; the cases of a batch have one each."""
    material: object
    punch: Punch
    const: SurfaceConstants
    speed: float
    friction: float
    direction: int
    mu_f: float
    kernel: object = None
    punch_material: object = None

    @property
    def a(self) -> float:
        """N12 mu_f, the coefficient of p in the equation (0 without friction: no friction
        terms; :meth:`SurfaceConstants.equation_coefficients`)."""
        return self.const.equation_coefficients(self.mu_f)[0]

    @property
    def b(self) -> float:
        """N11 + M12 mu_f, the coefficient of the Hilbert transform of p (N11 without
        friction, and for a material with the mirror plane X = 0, M12 = 0)."""
        return self.const.equation_coefficients(self.mu_f)[1]

    def result(self, load, **fields) -> ContactResult:
        """The ContactResult of this problem at ``load`` (``fields``: the rest)."""
        cls = _ClosedFormContactResult if fields.get("method") == "closed_form" else \
            ContactResult
        return cls(constants=self.const, load=load, speed=self.speed, friction=self.friction,
                   direction=self.direction, mu_f=self.mu_f, punch=self.punch,
                   material=self.material, punch_material=self.punch_material,
                   _kernel=self.kernel, **fields)


def _problem(material, punch, speed, friction, direction, constants,
             punch_material=None) -> _Problem:
    """The _Problem of checked inputs (``constants``: given for this speed, or None; an
    elastic punch's compliance added to them, :mod:`contact.elastic_punch`)."""
    const = _surface_constants(material, speed, constants)
    if punch_material is not None:
        const = two_body_constants(const, punch_constants(punch_material))
    mu_f = _signed_friction(const, friction, direction)
    return _Problem(material, punch, const, float(speed), friction, direction, mu_f,
                    contact_kernel(material, const.c, mu_f), punch_material)


@dataclass(frozen=True)
class _Case:
    """One case of :func:`_numeric_cases`: a problem and one load (checked)."""
    problem: _Problem
    load: float


def _basis_choice(punch, n):
    """(n, adaptive): a polynomial slope of degree d is exact with d + 4 coefficients (the
    projection with n - kappa > d terms is exact, so phi, of degree <= d + 1, is too); else
    the given n, or the adaptive start."""
    if n is None and punch.slope_degree is not None:
        return punch.slope_degree + 4, False
    return (n if n is not None else _N_DEFAULT), n is None


def _numeric_cases(punch, cases, n, tol, errors="raise", residual=False):
    """ContactResult of each case (one load each): the lockstep first step for those it
    finishes (:mod:`contact.lockstep`), the full continuation for the others; with
    ``errors="return"`` a library error (ContactLossError, a face without a lowest point...)
    takes its case's place."""
    n_use, adaptive = _basis_choice(punch, n)
    out = [None] * len(cases)
    steps = None
    # the lockstep step knows no kernel: the cases of a layered material go alone
    plain = [i for i, c in enumerate(cases) if c.problem.kernel is None]
    if not adaptive and plain:
        lock = [cases[i] for i in plain]
        try:
            steps = first_steps(punch.as_face(), punch.slope, tuple(punch.breaks),
                                [c.problem.a for c in lock], [c.problem.b for c in lock],
                                [c.load for c in lock], n_use)
        except (ContactInputError, sie.SIEInputError):
            steps = None        # each case alone below: each raises (or returns) its error
        if steps is not None and steps.done.size:
            for k, r in zip(steps.done.tolist(), _lockstep_results(lock, steps, residual)):
                out[plain[k]] = r
    for i, c in enumerate(out):
        if c is not None:
            continue
        c = cases[i]
        try:
            out[i] = _numeric(c.problem, [c.load], n, tol).results[0]
        except (ContactInputError, sie.SIEInputError) as exc:
            if errors == "raise":
                raise
            out[i] = exc
    if n is not None:               # a fixed n is checked here; an adaptive one converged
        for r in out:
            if not isinstance(r, Exception):
                _warn_unresolved(r, n)
    return out


#: A residual (:attr:`ContactResult.residual`) above this, at a fixed n, is warned.
RESIDUAL_WARN = 1e-6


def _warn_unresolved(result, n):
    """A sie.ResidualWarning where the fixed ``n`` leaves the equation unsolved between the
    nodes (residual > RESIDUAL_WARN of its scale): the face varies faster than n resolves."""
    if result.residual > RESIDUAL_WARN:
        warnings.warn(
            f"contact.solve: the fixed n = {n} leaves a residual of {result.residual:.2g} of "
            f"the equation's scale between the nodes (> {RESIDUAL_WARN:g}) at load "
            f"{result.load!r}, speed {result.speed!r}, friction {result.friction!r}: n does "
            f"not resolve the face (pass a larger n, or leave n out for the adaptive n)",
            sie.ResidualWarning, stacklevel=4)


def _lockstep_results(cases, steps, residual):
    """The ContactResult of each case the lockstep step finished."""
    sols, kinds = steps.solutions, steps.kinds
    loads = sols.integral()
    phi_ends = sols.endpoint_values() if CORNER in kinds else None
    done = [cases[i] for i in steps.done.tolist()]
    res = _residuals(sols, [c.problem for c in done]) if residual else [None] * len(sols)
    out = []
    for k, i in enumerate(steps.done.tolist()):
        c = cases[i]
        ends = tuple(sols.intervals[k].tolist())
        alpha, beta = float(sols.alpha[k]), float(sols.beta[k])
        sif = {} if phi_ends is None else _sif(lambda e, k=k: float(phi_ends[k, (e + 1) // 2]),
                                               ends, kinds, alpha, beta)
        zone = ContactZone(Zone(*ends, *kinds), alpha, beta, float(loads[k]), sif)
        out.append(c.problem.result(
            c.load, zones=(zone,), n=sols.n,
            load_check=abs(float(loads[k]) - c.load) / c.load, method="numeric",
            solution=sols[k], _residual=res[k], _residual_source=_residual_alone))
    return out


def _residual_alone(result):
    """The residual of a result of the lockstep step on first access: :func:`_residuals` of
    its solution as a batch of one (each row of that computation is its own: the same value
    as in its batch)."""
    problem = _Problem(result.material, result.punch, result.constants, result.speed,
                       result.friction, result.direction, result.mu_f)
    return _residuals(sie.SolutionBatch.of([result.solution]), [problem])[0]


def _residuals(sols, problems):
    """:attr:`ContactResult.residual` of each solution of a batch (one problem each, all of
    one punch), in one pass (the check points and formula of
    :func:`contact.result._residual_of`)."""
    iv = sols.intervals
    X = 0.5 * (iv[:, :1] + iv[:, 1:]) + 0.5 * (iv[:, 1:] - iv[:, :1]) * RESIDUAL_U
    f = problems[0].punch.slope(X.ravel()).reshape(X.shape)
    return relative_residual(f, sols.cauchy_limit_local(RESIDUAL_U),
                             np.array([p.b for p in problems])[:, None],
                             np.array([p.a for p in problems])[:, None]).tolist()


def load_curve(material, punch, loads, *, speed, friction=0.0, direction=-1, n=None,
               tol=1e-12, constants=None, punch_material=None):
    """The contact at each of many loads, in one continuation from first touch.

    What a user plots as contact width against load: the zones are followed through the
    loads in ascending order, and where they change (a new zone, a merge, an end reaching
    an edge of the face) the load is located (by extrapolating what reaches zero there,
    bisection where that fails; :mod:`contact.continuation`) and recorded in ``events``.
    Each result is what :func:`solve` returns at that load (the same adaptive n per load).

    Parameters
    ----------
    material, punch, speed, friction, direction, n, tol, constants, punch_material
        As for :func:`solve`.
    loads : sequence of float
        Strictly increasing positive loads.

    Returns
    -------
    LoadCurve

    Raises
    ------
    LoadError
        ``loads`` empty, not finite, not positive or not strictly increasing.
    ContactInputError
        Other inputs, as for :func:`solve`; ContactLossError as there.

    References
    ----------
    As for :func:`solve`.

    Examples
    --------
    The W-shaped face touches in two zones, which merge at a load of about 0.17:

    >>> import numpy as np, contact
    >>> w = contact.ProfilePunch(lambda X: 0.2 * X**3 - 0.2 * X, face=(-2.0, 2.0))
    >>> curve = contact.load_curve(contact.Isotropic(1.0, 0.3), w, [1e-3, 1.0], speed=0.0)
    >>> curve.zone_count.tolist()
    [2, 1]
    >>> [(e.kind, round(e.load, 2)) for e in curve.events]
    [('merge', 0.17)]
    """
    _, friction, direction, tol = _check_inputs(material, punch, 1.0, speed, friction,
                                                direction, "numeric", n, tol)
    P = real_array("loads", loads, LoadError, "a sequence of positive numbers").ravel()
    if P.size == 0:
        raise LoadError("loads must hold at least one load, got none")
    if not np.all(np.isfinite(P)) or not np.all(P > 0):
        bad = float(P[~(np.isfinite(P) & (P > 0))][0])
        raise LoadError(f"every load must be positive and finite, got {bad!r}")
    if np.any(np.diff(P) <= 0):
        i = int(np.flatnonzero(np.diff(P) <= 0)[0])
        raise LoadError(f"loads must be strictly increasing, got loads[{i}] = {float(P[i])!r} and "
                        f"loads[{i + 1}] = {float(P[i + 1])!r}")
    problem = _problem(material, punch, speed, friction, direction, constants, punch_material)
    return _numeric(problem, P.tolist(), n, tol)


def _numeric(problem, loads, n, tol):
    """The numeric path: the zones along the loads, refined in n at each load (an error of
    the contact's own raised inside sie passes as itself, :func:`contact.kernel.own_errors`)."""
    with own_errors():
        return _follow_loads(problem, loads, n, tol)


def _follow_loads(problem, loads, n, tol):
    """:func:`_numeric`."""
    punch = problem.punch
    n_use, adaptive = _basis_choice(punch, n)
    face = punch.as_face()
    eq = ZoneEquations(slope=punch.slope, rise=face.rise, breaks=tuple(punch.breaks),
                       a=problem.a, b=problem.b, load=loads[0], n=n_use,
                       n_max=_N_FOLLOW if adaptive else None, kernel=problem.kernel)
    # adaptive: each state is refined and then checked in full (inspect_state below), so the
    # step that lands on the last load leaves the gap to that check
    states = follow_load(face, eq, loads, final_gap=not adaptive)
    results, events = [], []
    n_start = eq.n
    for i, state in enumerate(states):
        refined = state
        if adaptive:
            # a load curve starts each load's doubling at half the n the previous one needed
            refined = _refine(face, eq, state, tol, punch, n_start)
            valid = inspect_state(face, eq, refined)
            if i == len(states) - 1 and not valid:
                # the step to the last load did not check the gap: to that load again with
                # every check (and the events on the way), from the load before or from
                # first touch
                state = follow_last_again(face, eq, states, loads)
                refined = _refine(face, eq, state, tol, punch, n_start)
                valid = inspect_state(face, eq, refined)
            if not valid:
                # the continuation's state passed its checks at a smaller n, within that n's
                # truncation; at the refined n it violates p >= 0 or the gap: follow the
                # load again at that n (its checks are then as tight as the answer)
                refined = _refollow(face, eq, refined, loads, len(results), tol, punch)
            n_start = max(eq.n, _basis_size(refined) // 2)
        events.extend(state.events)         # those the continuation located on its way
        sol = refined.solution
        zones = tuple(_zone_info(z, j, sol) for j, z in enumerate(refined.zones))
        integral = sum(z.load for z in zones)
        results.append(problem.result(
            refined.load, zones=zones, n=_basis_size(refined),
            load_check=abs(integral - refined.load) / refined.load, method="numeric",
            solution=sol))
    return LoadCurve(loads=np.array(loads, dtype=float), results=tuple(results),
                     events=tuple(events))


def _basis_size(state):
    n = state.solution.n
    return int(n if np.ndim(n) == 0 else max(n))


def _zone_info(z, j, sol):
    multi = np.ndim(sol.alpha) > 0
    alpha = sol.alpha[j] if multi else sol.alpha
    beta = sol.beta[j] if multi else sol.beta
    load = sol.integral(interval=j) if multi else sol.integral()
    interval = j if multi else None
    return ContactZone(Zone(float(z.c), float(z.d), z.left, z.right), float(alpha),
                       float(beta), float(load),
                       lambda end: sol.endpoint_value(end, interval=interval))


def _closed_form_result(problem, load):
    """The corrected closed form of the paper's punches (:mod:`contact.closed_form`)."""
    punch, const = problem.punch, problem.const
    if problem.kernel is not None:
        raise ContactInputError(
            'method="closed_form" is for a homogeneous half-space; the material has a '
            f'surface kernel ({problem.kernel.where}): use method="numeric"')
    solver = CLOSED_FORMS.get(type(punch))
    if solver is None:
        names = ", ".join(cls.__name__ for cls in CLOSED_FORMS)
        raise ContactInputError(
            f'method="closed_form" exists only for {names}; use method="numeric" for '
            f'{type(punch).__name__}')
    # couplings within rounding of 0 are 0: a material turned onto its own symmetry (a
    # cubic crystal by 45 degrees, an isotropic one by any rotation) carries them at ~eps
    scales = {"M12": abs(const.N11), "M21": max(abs(const.N21), abs(const.N22)),
              "M22": max(abs(const.N21), abs(const.N22))}
    couplings = ", ".join(f"{name} = {getattr(const, name):.3g}" for name, scale in
                          scales.items() if abs(getattr(const, name)) > _ROUNDING * scale)
    if couplings:
        raise ContactInputError(
            'method="closed_form" holds for a material with the mirror plane X = 0 (M12 = '
            'M21 = M22 = 0, as an orthotropic material aligned with the frame); this '
            f'material couples p and q at this speed ({couplings}; allowed: abs(M12) up '
            f'to {_ROUNDING:.2g} abs(N11), abs(M21) and abs(M22) up to {_ROUNDING:.2g} '
            f'max(abs(N21), abs(N22)), i.e. rounding): use method="numeric"')
    N = (const.N11, const.N12, const.N21, const.N22, problem.mu_f)
    c = solver(*N, punch.dimension, load)
    kinds = tuple("corner" if x is not None else "free" for x in punch.corners)
    zone = ContactZone(Zone(float(c.ends[0]), float(c.ends[1]), *kinds), float(c.alpha),
                       float(c.beta), float(load), dict(c.sif))
    return problem.result(load, zones=(zone,), n=2,
                          load_check=abs(c.load_check - load) / load, method="closed_form",
                          solution=c)


def _refollow(face, eq, refined, loads, i, tol, punch):
    """The state at ``loads[i]`` from a continuation run at the n of ``refined`` (which
    failed its checks), refined again; raises ContactLossError when it fails the checks
    too."""
    n_ref = _basis_size(refined)
    eq_ref = replace(eq, n=n_ref, n_max=n_ref)
    state = follow_load(face, eq_ref, loads[:i + 1])[-1]
    state = _refine(face, eq_ref, state, tol, punch, n_ref)
    if not inspect_state(face, eq_ref, state):
        raise ContactLossError(
            f"contact.solve: at load {loads[i]!r} the zones found violate p >= 0 or the "
            f"gap >= 0 at n = {_basis_size(state)}; the face has features the solver cannot "
            f"resolve at that n (pass a larger n=, or breaks= at its kinks)")
    return state


def _refine(face, eq, state, tol, punch, n_start):
    """``state`` with n doubled (Newton from the previous zones and Jacobian) until the ends
    and the pressure at check points agree between n and 2n to ``tol`` (or, where the ends'
    side conditions are ill-conditioned, to what their rounding allows: warned); the doubling
    starts
    from ``n_start`` (the state re-solved there first when it is larger than the state's)."""
    lo, hi = face.extent
    eq = replace(eq, load=state.load, n=max(eq.n, _basis_size(state)))   # the state's own n
    m = len(state.zones)
    n_start = min(n_start, _N_MAX // 2, N_MAX_DENSE // (2 * m) if m > 1 else n_start)
    if n_start > eq.n:
        eq = replace(eq, n=n_start)
        zs, ts, sol, J = eq.solve_ends(list(state.zones), list(state.totals), lo=lo, hi=hi,
                                       jacobian=state.jacobian)
        state = ZoneState(state.load, tuple(zs), tuple(ts), sol, J)
    while True:
        eq2 = replace(eq, n=2 * eq.n)
        zs, ts, sol2, J = eq2.solve_ends(list(state.zones), list(state.totals), lo=lo, hi=hi,
                                         jacobian=state.jacobian)
        width = zs[-1].d - zs[0].c
        d_ends = max(max(abs(a.c - b.c), abs(a.d - b.d)) for a, b in zip(zs, state.zones)) / width
        # compare the pressures at each zone's own normalised points (the same local points
        # of the old and the new zones; evaluated with the check points of each solution)
        p1 = np.concatenate([q for _, q in zone_pressures(state.solution, refine=True)])
        p2 = np.concatenate([q for _, q in zone_pressures(sol2, refine=True)])
        d_p = float(np.abs(p2 - p1).max()) / max(float(np.abs(p2).max()),
                                                  np.finfo(float).tiny)
        new = ZoneState(state.load, tuple(zs), tuple(ts), sol2, J)
        # the next doubling must fit one zone's cap and, for several zones, sie's dense
        # system (N_MAX_DENSE unknowns in all)
        last = 2 * eq2.n > _N_MAX or (len(zs) > 1 and 2 * eq2.n * len(zs) > N_MAX_DENSE)
        change = max(d_ends, d_p)
        if change <= tol:
            return new
        # the ends cannot be fixed better than the rounding of their side conditions allows
        # (ZoneEquations.end_uncertainty): once n and 2n agree to that, a larger n only moves
        # them within it (two ends about to meet); say so instead of doubling n to its cap
        floor = ZoneEquations.end_uncertainty(zs, ts, J) / width
        if change <= 2.0 * floor:
            gaps = [b.c - a.d for a, b in zip(zs, zs[1:])]
            where = (f"two zones {min(gaps):.2g} apart, about to merge" if gaps and
                     min(gaps) < 0.01 * width else "ends close together: zones about to "
                     "merge or split, or a zone just born")
            warnings.warn(
                f"contact.solve: at load {state.load!r} the ends are fixed only to about "
                f"{floor:.0e} of the contact's width (tol = {tol:.2g}): the side conditions "
                f"that fix them are ill-conditioned there ({where}); n = {eq.n} and "
                f"{eq2.n} agree to {change:.2g}, and a larger n does not help",
                RuntimeWarning, stacklevel=4)
            return new
        if last:
            hint = ("; if the slope varies on a length scale much shorter than the contact, "
                    "pass a larger n= (the error falls geometrically, at a rate set by that "
                    "scale)")
            if not punch.breaks:
                hint += ("; if it has a kink or a jump in a derivative, pass its X positions "
                         "as breaks= (spectral instead of algebraic convergence)")
            warnings.warn(f"contact.solve: n = {eq2.n} reached with a change of "
                          f"{max(d_ends, d_p):.2g} (> tol = {tol:.2g}) between n and 2n{hint}",
                          RuntimeWarning, stacklevel=4)
            return new
        eq, state = eq2, new


def contact_length(material, punch, *, load, speed, friction=0.0, direction=-1):
    """x_right - x_left of the contact (numeric path).

    ``solve(material, punch, load=..., speed=..., friction=..., direction=...)`` and the
    width of its one zone.

    Parameters
    ----------
    material, punch, load, speed, friction, direction
        As for :func:`solve`.

    Returns
    -------
    float
        The contact length.

    Raises
    ------
    ContactInputError
        As for :func:`solve`; also when the contact has several zones (use ``solve`` and
        ``result.zones``).

    References
    ----------
    As for :func:`solve`.

    Examples
    --------
    The Hertz contact of a cylinder: 2a with a^2 = 4 P R / (pi E*), E* = E / (1 - nu^2):

    >>> import math, contact
    >>> L = contact.contact_length(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0),
    ...                            load=0.01, speed=0.0)
    >>> round(L / (2 * math.sqrt(4 * 0.01 / (math.pi / (1 - 0.3**2)))), 12)
    1.0
    """
    r = solve(material, punch, load=load, speed=speed, friction=friction, direction=direction)
    return r.ends[1] - r.ends[0]
