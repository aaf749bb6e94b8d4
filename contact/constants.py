"""Surface constants N11, N12, N21, N22 of a moving half-space, and its Rayleigh speed.

The public entries :func:`surface_constants`, :func:`rayleigh_speed`,
:func:`limiting_speed` and :func:`relative_speed` take any material
(:class:`contact.Material`): they check it, the speed, and what its methods return.  The formulas below are those of an orthotropic
material (:func:`orthotropic_surface_constants`, :func:`orthotropic_rayleigh_speed`,
:func:`orthotropic_limiting_speed`), which :class:`contact.Orthotropic`'s methods call.

Conventions (see the documentation, Theory: the contact model and its conventions):
half-space Y < 0, surface tractions sigma_YY(X, 0) = -p(X), tau_XY(X, 0) = -q(X),
Hc[f](X) = (1/pi) PV int f(t) / (t - X) dt.  The surface response to (p, q) is (Zhou, Lee &
Jang 2014, eqs. (4.5)-(4.6), with N22 where the paper's eq. (4.3) prints N21 in L2; see the
documentation, Theory: errata of Zhou et al. 2014)::

    dv/dX (X, 0)   = N12 q(X) + N11 Hc[p](X),
    sigma_XX(X, 0) = N21 p(X) + N22 Hc[q](X).

A material without the mirror symmetries of an aligned orthotropic one (a rotated ply, a
crystal: :class:`contact.Anisotropic`) adds three terms, M12 Hc[q], M21 Hc[p] and M22 q
(:class:`SurfaceConstants`); the contact equation keeps its form a p + b Hc[p] = H' with
a = N12 mu_f and b = N11 + M12 mu_f (:meth:`SurfaceConstants.equation_coefficients`).

Derivation (independent of the paper's eq. (4.4) and Appendix)
---------------------------------------------------------------
Take u, v ~ exp(i k X + |k| eta Y).  The equations of motion give eq. (3.1), the quadratic
a eta^4 + b eta^2 + d = 0 of :meth:`contact.material.Orthotropic.characteristic_coefficients`.
Decay as Y -> -inf keeps the two roots eta1, eta2 with Re eta > 0; with the eigenvectors
v_n = i sgn(k) h(eta_n) u_n, h(eta) = (C33 eta^2 - C11') / ((C12 + C33) eta), and
C11' = C11 - C33 c^2, the two traction conditions at Y = 0 fix the amplitudes.  Hc has the
Fourier multiplier +i sgn(k), so dv/dX and sigma_XX can be read off.  Every 2x2 determinant
carries a factor (eta1 - eta2), which cancels; the factor (C12 + C33) of the eigenvectors
cancels as well.  What is left depends on the roots only through

    P = eta1 eta2 = sqrt(d / a) = sqrt((1 - c^2) C11' / C22),
    S = eta1 + eta2 = sqrt(eta1^2 + eta2^2 + 2 P) = sqrt(2 P - b / a),

which are real and positive for real, complex-conjugate and repeated roots alike
(0 <= c < c_R).  With the Rayleigh function

    Delta(c) = P (C22 C11' - C12^2) - C33 c^2 C11'

the constants are

    N11 = -S C11' / Delta,
    N12 = (C11' - C12 P) / Delta,
    N21 = -[C11' (C11 C22 - C12^2 - C12 C33 c^2) - C12 C22 C33 c^2 P] / (C22 Delta),
    N22 = -P S (C11 C22 - C12^2) / Delta.

Static isotropic check (P = 1, S = 2): N11 = -(1 - nu)/G, N12 = (1 - 2 nu)/(2G), N21 = -1,
N22 = -2.  Evaluated at zeta > 0, the paper's eq. (4.4) with the Appendix (Case B) gives the
same numbers, but it divides by (eta1 - eta2) and by (C12 + C33): it is singular at isotropy
and loses digits near it.
"""
from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass

from .errors import MaterialError, NearRayleighWarning, SpeedError, check_finite
from .protocol import call, check_material, describe_call

__all__ = [
    "SurfaceConstants",
    "surface_constants",
    "rayleigh_speed",
    "limiting_speed",
    "relative_speed",
    "check_speed",
    "check_subrayleigh",
    "root_symmetric_functions",
    "rayleigh_function",
    "orthotropic_surface_constants",
    "orthotropic_rayleigh_speed",
    "orthotropic_limiting_speed",
    "NEAR_RAYLEIGH_FRACTION",
]

#: A speed above this fraction of c_R triggers :class:`~contact.errors.NearRayleighWarning`.
NEAR_RAYLEIGH_FRACTION = 0.99


@dataclass(frozen=True)
class SurfaceConstants:
    """Surface constants of eqs. (4.5)-(4.6) of Zhou et al. 2014 at one relative speed,
    with the couplings of a material of any symmetry.

    Returned by :func:`surface_constants` (and by a material's ``surface_constants(c)``,
    :class:`contact.Material`); :func:`contact.solve` accepts one as ``constants=`` (a sweep
    over friction at one speed shares it).  With the tangential traction q
    (sigma_XY(X, 0) = -q), the pressure p (sigma_YY(X, 0) = -p), no traction along Z
    (the punch is frictionless along its generators) and
    Hc[f](X) = (1/pi) PV int f(t) / (t - X) dt, the surface responds as::

        dv/dX (X, 0)    = N12 q + N11 Hc[p] + M12 Hc[q],                     (1)
        sigma_XX (X, 0) = N21 p + N22 Hc[q] + M21 Hc[p] + M22 q.              (2)

    With q = mu_f p (Coulomb friction, signed), (1) on the contact is the equation
    a p + b Hc[p] = H'(X) of the punch's slope H', a = N12 mu_f, b = N11 + M12 mu_f
    (:meth:`equation_coefficients`), and (2) is
    sigma_XX = (N21 + M22 mu_f) p + (N22 mu_f + M21) Hc[p]
    (:meth:`sigma_xx_coefficients`).

    Attributes
    ----------
    N11, N12 : float
        dv/dX (X, 0) = N12 q + N11 Hc[p] (+ M12 Hc[q])  (unit: 1 / stress unit of the
        material).
    N21, N22 : float
        sigma_XX(X, 0) = N21 p + N22 Hc[q] (+ M21 Hc[p] + M22 q)  (dimensionless).
    c : float
        Relative speed (V / sqrt(C33 / rho) for an orthotropic material).
    rayleigh_speed : float
        c_R of the material.
    eta_product, eta_sum : float or None
        P = eta1 eta2 and S = eta1 + eta2 of the two decaying characteristic roots of an
        orthotropic material (eq. (3.1)); None for a material without them.
    rayleigh_denominator : float or None
        Delta(c) = P (C22 C11' - C12^2) - C33 c^2 C11' of an orthotropic material (> 0
        below c_R); None for a material without it.
    M12 : float, keyword, default 0
        dv/dX per Hc[q]: the Hilbert part of the normal slope under the tangential
        traction (unit: 1 / stress unit).
    M21 : float, keyword, default 0
        sigma_XX per Hc[p] (dimensionless).
    M22 : float, keyword, default 0
        sigma_XX per q, the local part (dimensionless).
    tangential_compliance : float or None, keyword, default None
        du/dX (X, 0) per Hc[q], the tangential slope under the tangential traction (the
        counterpart of N11; unit: 1 / stress unit): what the creepage of rolling is made of.
        None where the material does not give it.

    Notes
    -----
    M12, M21 and M22 vanish for a material with the mirror plane X = 0, an orthotropic
    material aligned with the frame among them (mirrored, p(X) -> p(-X), q(X) -> -q(-X),
    Hc changes sign, dv/dX is odd and sigma_XX even: each N term maps onto itself and each
    M term onto minus itself), so that :class:`contact.Orthotropic` leaves them 0; a ply
    rotated about Z or a crystal off its axes (:class:`contact.Anisotropic`) has them.

    Equation (1) has no local term in p: the local part L of the slopes
    du_i/dX = L_ij s_j + M_ij Hc[s_j] (s = (q, p, r)) is antisymmetric, so L_YY = 0, and
    its Hilbert part M symmetric, by reciprocity (Ting, Anisotropic Elasticity (1996),
    ch. 7, the identities of the Barnett-Lothe tensors; tests/contact/test_anisotropic.py
    checks both on a triclinic material, plain and rotated).  Hence N12 = L_Yq = -L_Xp and
    M12 = M_Yq = M_Xp.  Without friction (mu_f = 0) the equation is a = 0, b = N11 for any
    symmetry: both end exponents are 1/2 or -1/2.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (4.4)-(4.6); the formulas in closed form
    through P and S: see :func:`orthotropic_surface_constants` and the module docstring.
    Stroh, J. Math. Phys. 41 (1962) 77-103 and Ting (1996), ch. 5, 7 and 12 (M12, M21, M22
    of an anisotropic half-space: :meth:`contact.Anisotropic.surface_constants`).

    Examples
    --------
    An isotropic material at rest has a double root eta = 1 (P = 1, S = 2):

    >>> import contact
    >>> sc = contact.surface_constants(contact.Isotropic(2.5, 0.25), 0.0)
    >>> type(sc).__name__, sc.c, sc.eta_product, sc.eta_sum
    ('SurfaceConstants', 0.0, 1.0, 2.0)

    A material of one's own gives the four constants, its speed and c_R, and may leave the
    orthotropic quantities out:

    >>> sc = contact.SurfaceConstants(N11=-0.75, N12=0.25, N21=-1.0, N22=-2.0, c=0.0,
    ...                               rayleigh_speed=0.9194)
    >>> sc.eta_sum is None, sc.M12
    (True, 0.0)

    The equation's coefficients with friction mu_f = 0.3, and with a coupling M12:

    >>> sc.equation_coefficients(0.3)
    (0.075, -0.75)
    >>> import dataclasses
    >>> dataclasses.replace(sc, M12=0.5).equation_coefficients(0.3)
    (0.075, -0.6)
    """

    N11: float
    N12: float
    N21: float
    N22: float
    c: float
    rayleigh_speed: float
    eta_product: float | None = None
    eta_sum: float | None = None
    rayleigh_denominator: float | None = None
    M12: float = 0.0
    M21: float = 0.0
    M22: float = 0.0
    tangential_compliance: float | None = None

    def equation_coefficients(self, mu_f) -> tuple[float, float]:
        """(a, b) of the contact equation a p + b Hc[p] = H'(X) with q = mu_f p: eq. (1) of
        the class docstring, a = N12 mu_f, b = N11 + M12 mu_f; (0.0, N11) at mu_f = 0."""
        if mu_f == 0.0:
            return 0.0, self.N11
        return self.N12 * mu_f, self.N11 + self.M12 * mu_f

    def sigma_xx_coefficients(self, mu_f) -> tuple[float, float]:
        """(A, B) of sigma_XX(X, 0) = A p + B Hc[p] with q = mu_f p: eq. (2) of the class
        docstring, A = N21 + M22 mu_f, B = N22 mu_f + M21; (N21, M21) at mu_f = 0."""
        if mu_f == 0.0:
            return self.N21, self.M21
        return self.N21 + self.M22 * mu_f, self.N22 * mu_f + self.M21


# --------------------------------------------------------------------------
# any material: the checked entries
# --------------------------------------------------------------------------
def check_speed(c, c_R: float | None = None) -> float:
    """Return the relative speed ``c`` as a float; raise SpeedError unless it is finite,
    >= 0 and, when the Rayleigh speed ``c_R`` is given, below it."""
    c = check_finite("relative speed c", c, SpeedError)
    if c < 0.0:
        raise SpeedError(f"relative speed c must be >= 0 (the punch's speed over the "
                         f"material's shear wave speed, V / sqrt(C33/rho) for an orthotropic "
                         f"material), got {c!r}")
    if c_R is not None and not c < c_R:
        raise SpeedError(
            f"relative speed c must be below the Rayleigh speed c_R = {c_R!r} of this material "
            f"(allowed: 0 <= c < c_R), got c = {c!r}")
    return c


def check_subrayleigh(material, c, stacklevel: int = 3) -> tuple[float, float]:
    """(c, c_R): the relative speed checked against the material's Rayleigh speed.

    Raises
    ------
    SpeedError
        c not a finite number, negative, or not below c_R.

    Warns
    -----
    NearRayleighWarning
        c > :data:`NEAR_RAYLEIGH_FRACTION` c_R (``stacklevel`` as for ``warnings.warn``,
        counted from this function).
    """
    c_R = rayleigh_speed(material)
    c = check_speed(c, c_R)
    if c > NEAR_RAYLEIGH_FRACTION * c_R:
        warnings.warn(
            f"relative speed c = {c!r} is within 1% of the Rayleigh speed c_R = {c_R!r}: "
            f"the surface constants are valid but extremely sensitive to c",
            NearRayleighWarning, stacklevel=stacklevel)
    return c, c_R


def rayleigh_speed(material) -> float:
    """Relative Rayleigh speed c_R of a material: the admissible speeds are 0 <= c < c_R.

    For an orthotropic material, the first zero of the common denominator of the surface
    constants (:func:`orthotropic_rayleigh_speed`, :func:`rayleigh_function`).
    Zhou et al. 2014 material: c_R = 0.9936147...; isotropic nu = 0.25: 0.9194017...
    (the paper, Sec. 6.1, gives [0, 1): see the documentation, Theory: errata of Zhou
    et al. 2014).

    Parameters
    ----------
    material : Material
        :class:`contact.Orthotropic` or any object with the methods of
        :class:`contact.Material`.

    Returns
    -------
    float
        ``material.rayleigh_speed()``, checked: a finite real number > 0.

    Raises
    ------
    ContactInputError
        ``material`` lacks the methods of :class:`contact.Material`.
    MaterialError
        Its ``rayleigh_speed()`` does not return a finite real number > 0, or raises.

    References
    ----------
    Lord Rayleigh, "On waves propagated along the plane surface of an elastic solid",
    Proc. London Math. Soc. 17 (1885) 4-11 (isotropic: c_R^2 = 2 - 2/sqrt(3) at nu = 1/4).
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (4.4)-(4.6).

    Examples
    --------
    >>> import math, contact
    >>> c_R = contact.rayleigh_speed(contact.Isotropic(1.0, 0.25))
    >>> round(c_R, 12), round(math.sqrt(2.0 - 2.0 / math.sqrt(3.0)), 12)
    (0.919401686762, 0.919401686762)
    >>> round(contact.rayleigh_speed(contact.zhou2014()), 6)
    0.993615
    """
    check_material(material)
    c_R = call(material, "rayleigh_speed")
    return _positive(c_R, material, "rayleigh_speed")


def limiting_speed(material) -> float:
    """Lowest relative speed at which a mode of the material stops decaying into the
    half-space (for an orthotropic material, a characteristic root reaches the imaginary
    axis: :func:`orthotropic_limiting_speed`).

    Parameters
    ----------
    material : Material
        :class:`contact.Orthotropic` or any object with the methods of
        :class:`contact.Material`.

    Returns
    -------
    float
        ``material.limiting_speed()``, checked: a finite real number, at least
        :func:`rayleigh_speed`.

    Raises
    ------
    ContactInputError
        ``material`` lacks the methods of :class:`contact.Material`.
    MaterialError
        Its ``limiting_speed()`` is not a finite real number >= its Rayleigh speed, or
        raises.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eq. (3.1) and Table 1 (the roots against c).

    Examples
    --------
    For the paper's material the shear wave (c = 1) comes first.  For C11 = C22 = C33 = 1,
    C12 = 0.9: S^2 = 0.39 - 4 c^2, which vanishes at c^2 = 0.0975:

    >>> import math, contact
    >>> contact.limiting_speed(contact.zhou2014())
    1.0
    >>> m = contact.Orthotropic(1.0, 0.9, 1.0, 1.0)
    >>> round(contact.limiting_speed(m) / math.sqrt(0.0975), 12)
    1.0
    """
    c_R = rayleigh_speed(material)
    c_L = _positive(call(material, "limiting_speed"), material, "limiting_speed")
    if not c_L >= c_R:
        raise MaterialError(
            f"{describe_call(material, 'limiting_speed')} returned {c_L!r}, below its Rayleigh "
            f"speed {c_R!r} (allowed: c_R <= c_L: below c_L every mode decays into the "
            f"half-space, and c_R is below c_L)")
    return c_L


def relative_speed(material, V) -> float:
    """The relative speed c of a punch moving at speed ``V`` over a material.

    Parameters
    ----------
    material : Material
        :class:`contact.Orthotropic` (c = abs(V) / sqrt(C33 / rho), Zhou et al. 2014,
        Sec. 6.1; needs its density) or any object with the methods of
        :class:`contact.Material`.
    V : float
        The punch's speed, in the unit of the material's wave speeds.

    Returns
    -------
    float
        ``material.relative_speed(V)``, checked: a finite real number >= 0.

    Raises
    ------
    ContactInputError
        ``material`` lacks the methods of :class:`contact.Material`.
    SpeedError
        ``V`` not a finite real number (as the material says).
    MaterialError
        The material has no density, or its ``relative_speed(V)`` returns what is not a
        finite real number >= 0, or raises.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), Sec. 6.1 (which prints sqrt(C33 rho) for the
    shear wave speed: see the documentation, Theory: errata of Zhou et al. 2014).

    Examples
    --------
    >>> import contact
    >>> m = contact.Orthotropic(4.0, 1.0, 4.0, 1.0, rho=4.0)      # sqrt(C33 / rho) = 0.5
    >>> contact.relative_speed(m, 0.25)
    0.5
    """
    check_material(material)
    where = describe_call(material, "relative_speed", V)
    c = check_finite(f"{where} (a relative speed)", call(material, "relative_speed", V),
                     MaterialError)
    if c < 0.0:
        raise MaterialError(f"{where} must return a relative speed >= 0, got {c!r}")
    return c


def surface_constants(material, c) -> SurfaceConstants:
    """Surface constants N11, N12, N21, N22 (and M12, M21, M22) of a material at the
    relative speed ``c``.

    dv/dX (X, 0) = N12 q + N11 Hc[p] and sigma_XX (X, 0) = N21 p + N22 Hc[q] (Zhou et al.
    2014, eqs. (4.5)-(4.6); for an orthotropic material the closed forms of
    :func:`orthotropic_surface_constants`), with M12 Hc[q] and M21 Hc[p] + M22 q added for
    a material of lower symmetry (:class:`SurfaceConstants`).

    Parameters
    ----------
    material : Material
        :class:`contact.Orthotropic` or any object with the methods of
        :class:`contact.Material`.
    c : float
        Relative speed (V / sqrt(C33 / rho) for an orthotropic material), 0 <= c < c_R.

    Returns
    -------
    SurfaceConstants
        ``material.surface_constants(c)``, checked.

    Raises
    ------
    ContactInputError
        ``material`` lacks the methods of :class:`contact.Material`.
    SpeedError
        If c is not finite, negative, or not below the Rayleigh speed c_R.
    MaterialError
        The material's ``surface_constants(c)`` returns something other than a
        :class:`SurfaceConstants` of finite real N's and M's with N11 < 0, for this c
        and its c_R, or raises (or its ``rayleigh_speed()`` is not admissible).

    Warns
    -----
    NearRayleighWarning
        If c > 0.99 c_R.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (4.4)-(4.6).

    Examples
    --------
    The isotropic static limit (plane strain, shear modulus G, Poisson's ratio nu):
    N11 = -(1 - nu)/G, N12 = (1 - 2 nu)/(2G), N21 = -1, N22 = -2; here G = 1, nu = 1/4:

    >>> import contact
    >>> sc = contact.surface_constants(contact.Isotropic(2.5, 0.25), 0.0)
    >>> [round(v, 12) for v in (sc.N11, sc.N12, sc.N21, sc.N22)]
    [-0.75, 0.25, -1.0, -2.0]
    """
    c, c_R = check_subrayleigh(material, c)
    sc = call(material, "surface_constants", c)
    if type(sc) is SurfaceConstants and sc.c == c and sc.rayleigh_speed == c_R and \
            _finite_floats(sc.N11, sc.N12, sc.N21, sc.N22, sc.M12, sc.M21, sc.M22) and \
            sc.N11 < 0.0 and \
            _finite_floats(*(v for v in (sc.eta_product, sc.eta_sum,
                                         sc.rayleigh_denominator) if v is not None)):
        return sc           # what the checks below accept, at a fraction of their cost
    where = describe_call(material, "surface_constants", c)
    if not isinstance(sc, SurfaceConstants):
        raise MaterialError(f"{where} must return a contact.SurfaceConstants, got "
                            f"{type(sc).__name__}")
    for name in ("N11", "N12", "N21", "N22", "M12", "M21", "M22"):
        check_finite(f"{name} of {where}", getattr(sc, name), MaterialError)
    for name in ("eta_product", "eta_sum", "rayleigh_denominator"):
        if getattr(sc, name) is not None:
            check_finite(f"{name} of {where}", getattr(sc, name), MaterialError)
    if not sc.N11 < 0.0:
        raise MaterialError(
            f"N11 of {where} must be < 0 (below the Rayleigh speed the surface sinks under a "
            f"pressure: dv/dX = N11 Hc[p] + ...; N11 changes sign at c_R), got {sc.N11!r}")
    if sc.c != c or sc.rayleigh_speed != c_R:
        raise MaterialError(
            f"{where} returned constants for c = {sc.c!r} with rayleigh_speed = "
            f"{sc.rayleigh_speed!r} (allowed: c = {c!r}, the speed asked, and the material's "
            f"rayleigh_speed() = {c_R!r})")
    return sc


def _finite_floats(*values) -> bool:
    """Whether every value is a finite float (Python's or numpy's; the common case that
    the detailed checks of a material's results then need not look at)."""
    return all(isinstance(v, float) and math.isfinite(v) for v in values)


def _positive(value, material, method: str) -> float:
    """A speed returned by ``material.<method>()`` as a float, or MaterialError."""
    if _finite_floats(value) and value > 0.0:
        return float(value)
    where = describe_call(material, method)
    v = check_finite(f"{where} (a relative speed)", value, MaterialError)
    if not v > 0.0:
        raise MaterialError(f"{where} must return a relative speed > 0, got {v!r}")
    return v


# --------------------------------------------------------------------------
# the orthotropic formulas (what contact.Orthotropic's methods call)
# --------------------------------------------------------------------------
def root_symmetric_functions(material, c) -> tuple[float, float]:
    """P = eta1 eta2 and S = eta1 + eta2 of the decaying roots of eq. (3.1), Zhou et al. 2014.

    Computed from the coefficients of a eta^4 + b eta^2 + d = 0 only (``material`` an
    :class:`contact.Orthotropic`): P = sqrt(d/a), S = sqrt(2P - b/a).  Valid for 0 <= c
    below the limiting speed (see :func:`orthotropic_limiting_speed`), where d >= 0 and
    2P - b/a >= 0; outside, NaN may result.
    """
    a, b, d = material.characteristic_coefficients(c)
    P = math.sqrt(d / a) if d > 0.0 else 0.0
    S2 = 2.0 * P - b / a
    S = math.sqrt(S2) if S2 >= 0.0 else math.nan
    return P, S


def rayleigh_function(material, c) -> float:
    """The common denominator Delta(c) of the orthotropic surface constants (a Rayleigh
    function).

    Delta(c) = P (C22 C11' - C12^2) - C33 c^2 C11', C11' = C11 - C33 c^2, P = eta1 eta2
    (``material`` an :class:`contact.Orthotropic`).  Delta(0) = P (C11 C22 - C12^2) > 0;
    its first zero is the Rayleigh speed c_R.
    """
    P, _ = root_symmetric_functions(material, c)
    c2 = float(c) ** 2
    C11p = material.C11 - material.C33 * c2
    return P * (material.C22 * C11p - material.C12 ** 2) - material.C33 * c2 * C11p


def _scaled_rayleigh_function(material, c: float) -> float:
    """Delta(c) / sqrt(C11'): same sign as Delta below the limiting speed, without the trivial
    zero of Delta at C11' = 0 (c^2 = C11/C33 < 1)."""
    c2 = c * c
    C11p = max(material.C11 - material.C33 * c2, 0.0)
    return (math.sqrt(max(1.0 - c2, 0.0) / material.C22) * (material.C22 * C11p - material.C12 ** 2)
            - material.C33 * c2 * math.sqrt(C11p))


def _eta_sum_squared(material, c: float) -> float:
    a, b, d = material.characteristic_coefficients(c)
    return 2.0 * math.sqrt(max(d, 0.0) / a) - b / a


@functools.lru_cache(maxsize=256)
def orthotropic_limiting_speed(material) -> float:
    """Lowest relative speed at which a decaying root of an orthotropic material reaches the
    imaginary axis (:meth:`contact.Orthotropic.limiting_speed`).

    The smallest of 1 (shear wave, d = 0), sqrt(C11/C33) (longitudinal wave, d = 0) and the
    speed where eta1 + eta2 = 0 (a complex pair eta^2 becomes a negative double root).
    S^2 = 2P - b/a is positive at c = 0 for every positive definite stiffness and strictly
    decreasing in c, so that speed is found by bisection (:func:`_decreasing_root`).

    Parameters
    ----------
    material : Orthotropic

    Returns
    -------
    float
        The limiting relative speed c_L <= 1 (memoised per material).

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eq. (3.1) and Table 1 (the roots against c);
    a, b, d as in :meth:`contact.Orthotropic.characteristic_coefficients`.
    """
    c_max = min(1.0, math.sqrt(material.C11 / material.C33))
    if _eta_sum_squared(material, c_max) >= 0.0:
        return c_max
    return _decreasing_root(functools.partial(_eta_sum_squared, material), 0.0, c_max)


@functools.lru_cache(maxsize=256)
def orthotropic_rayleigh_speed(material) -> float:
    """Relative Rayleigh speed c_R of an orthotropic material: the first zero of
    :func:`rayleigh_function` (:meth:`contact.Orthotropic.rayleigh_speed`).

    Delta > 0 at c = 0 and Delta <= 0 at the limiting speed c_L <= 1 (a subsonic surface wave
    exists for an orthotropic half-space; also checked on 20000 random stiffnesses, each with
    a single sign change of Delta on (0, c_L)), so c_R is bracketed in (0, c_L] and found
    by bisection on Delta / sqrt(C11') to about one ulp (:func:`_decreasing_root`).

    Parameters
    ----------
    material : Orthotropic

    Returns
    -------
    float
        c_R, relative to the shear wave speed sqrt(C33 / rho) (memoised per material).

    References
    ----------
    Lord Rayleigh, Proc. London Math. Soc. 17 (1885) 4-11; Zhou, Lee & Jang, Arch. Mech.
    66 (2014), eqs. (4.4)-(4.6) (Delta is the common denominator of the surface constants).
    """
    c_lim = orthotropic_limiting_speed(material)
    f = functools.partial(_scaled_rayleigh_function, material)
    if f(c_lim) >= 0.0:  # exceptional limiting wave that is itself traction free
        return c_lim
    return _decreasing_root(f, 0.0, c_lim)


def _decreasing_root(f, lo: float, hi: float) -> float:
    """Root of f with f(lo) > 0 >= f(hi), to about one ulp.

    Bisection down to two adjacent doubles (f > 0 at the left one, f <= 0 at the right
    one), returning the one with the smaller |f|; the rounding noise of f itself limits
    this to about one ulp.  Bisection rather than scipy.optimize.brentq: Brent's method
    stops a few ulp away and needs this bisection after it anyway, and importing
    scipy.optimize is a noticeable part of the start of the ``contact`` command and of every
    worker process that is not forked (docs: Accuracy and speed), for a root memoised per
    material that bisection finds in ~55 evaluations of f.
    """
    a, b = float(lo), float(hi)
    while True:
        mid = 0.5 * (a + b)
        if not a < mid < b:
            break
        if f(mid) > 0.0:
            a = mid
        else:
            b = mid
    return float(a if abs(f(a)) < abs(f(b)) else b)


def orthotropic_surface_constants(material, c) -> SurfaceConstants:
    """Surface constants of an orthotropic material, Zhou et al. 2014, eqs. (4.4)-(4.6)
    (:meth:`contact.Orthotropic.surface_constants`).

    Parameters
    ----------
    material : Orthotropic
    c : float
        Relative speed V / sqrt(C33 / rho), 0 <= c < c_R.

    Returns
    -------
    SurfaceConstants
        With C11' = C11 - C33 c^2, P = eta1 eta2 = sqrt((1 - c^2) C11' / C22),
        S = eta1 + eta2 = sqrt(2P - b/a) (see :func:`root_symmetric_functions`) and
        Delta = P (C22 C11' - C12^2) - C33 c^2 C11'::

            N11 = -S C11' / Delta
            N12 = (C11' - C12 P) / Delta
            N21 = -[C11' (C11 C22 - C12^2 - C12 C33 c^2) - C12 C22 C33 c^2 P] / (C22 Delta)
            N22 = -P S (C11 C22 - C12^2) / Delta
            tangential_compliance = -P S C22 / Delta

        for dv/dX = N12 q + N11 Hc[p], sigma_XX = N21 p + N22 Hc[q] and du/dX =
        -N12 p + tangential_compliance Hc[q] (the last from the same derivation; checked
        against the Stroh formalism of :class:`contact.Anisotropic`, whose
        slope_hilbert[X, q] it is).

    Raises
    ------
    SpeedError
        If c is not finite, negative, or not below the Rayleigh speed c_R (the checked
        entry :func:`surface_constants` also warns near c_R).

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (4.4)-(4.6), rewritten through
    P = eta1 eta2 and S = eta1 + eta2 (module docstring): the paper's form divides by
    eta1 - eta2 and by C12 + C33 and is singular at isotropy.
    """
    c_R = orthotropic_rayleigh_speed(material)
    c = check_speed(c, c_R)
    C11, C12, C22, C33 = material.C11, material.C12, material.C22, material.C33
    c2 = c * c
    C11p = C11 - C33 * c2
    P, S = root_symmetric_functions(material, c)
    det = C11 * C22 - C12 ** 2
    delta = P * (C22 * C11p - C12 ** 2) - C33 * c2 * C11p
    return SurfaceConstants(
        N11=-S * C11p / delta,
        N12=(C11p - C12 * P) / delta,
        N21=-(C11p * (det - C12 * C33 * c2) - C12 * C22 * C33 * c2 * P) / (C22 * delta),
        N22=-P * S * det / delta,
        c=c,
        rayleigh_speed=c_R,
        eta_product=P,
        eta_sum=S,
        rayleigh_denominator=delta,
        tangential_compliance=-P * S * C22 / delta,
    )
