"""What the solver and the stress field need of a material: the :class:`Material` protocol.

:func:`contact.solve` and the field under the surface see a material only through five
methods.  The surface relations of the moving half-space (Zhou, Lee & Jang 2014, eqs.
(4.5)-(4.6), with the conventions of the documentation, Theory: the contact model and its
conventions)::

    dv/dX (X, 0)   = N12 q(X) + N11 Hc[p](X) [+ M12 Hc[q](X)],
    sigma_XX(X, 0) = N21 p(X) + N22 Hc[q](X) [+ M21 Hc[p](X) + M22 q(X)],

need the constants at the relative speed c (:meth:`Material.surface_constants`; the
couplings M12, M21, M22 of a material without the mirror plane X = 0 default to 0); the
speeds admissible are 0 <= c < c_R (:meth:`Material.rayleigh_speed`); the field under the
surface is a combination of Cauchy transforms of the tractions at complex points
(:meth:`Material.half_space_modes`, :class:`MaterialModes`).  :class:`contact.Orthotropic`
(and :func:`contact.Isotropic`) and :class:`contact.Anisotropic` implement it; so may any
object of a user's own, of any class: nothing in :mod:`contact` looks at a material's class.

The public entries (:func:`contact.surface_constants`, :func:`contact.rayleigh_speed`,
:func:`contact.limiting_speed`, :func:`contact.relative_speed`,
:func:`contact.subsurface.half_space_modes`) check the
object (:func:`check_material`), the speed, and what each method returns, and raise a
:class:`~contact.errors.MaterialError` naming the method whose result is not admissible.
"""
from __future__ import annotations

from typing import Protocol, runtime_checkable

from .errors import ContactInputError, MaterialError

__all__ = ["Material", "MaterialModes", "SurfaceKernel", "MATERIAL_METHODS", "check_material",
           "call"]

#: The methods of :class:`Material`, as (name, signature) for the messages.
MATERIAL_METHODS = (("surface_constants", "surface_constants(c)"),
                    ("rayleigh_speed", "rayleigh_speed()"),
                    ("limiting_speed", "limiting_speed()"),
                    ("relative_speed", "relative_speed(V)"),
                    ("half_space_modes", "half_space_modes(c)"))


@runtime_checkable
class MaterialModes(Protocol):
    """The decaying modes of a half-space at one speed, as the stress field needs them.

    Returned by :meth:`Material.half_space_modes`.  The stresses at points (X, Y), Y < 0,
    are a combination of the Cauchy transforms C_f(z) = (1/pi) int f(t) / (t - z) dt of the
    tractions f = p, q at complex points z with Im z > 0 that depend on the material
    (z_j = X - i eta_j Y for the characteristic roots eta_j of an orthotropic material:
    :class:`contact.subsurface.HalfSpaceModes`; z = X + zeta Y for the Stroh roots of an
    anisotropic one, or points about a cluster of nearly repeated roots:
    :class:`contact.stroh_modes.StrohModes`).  The points are the modes' to choose: a
    repeated root needs no derivative of the transform when the modes interpolate it from
    points near the root.

    Attributes
    ----------
    points : callable (X, Y) -> list of ndarray
        The complex points where the transforms are needed: a list of complex arrays of the
        shape of X and Y (float arrays of one shape, Y < 0), each with Im z > 0.
    stresses : callable (Cp, Cq=None, q_ratio=None) -> (ndarray, ndarray, ndarray)
        (sigma_xx, sigma_yy, sigma_xy), real arrays of the points' shape (tension positive),
        from Cp (and Cq), lists of the transforms of p (and q) at each of the points, in
        the order ``points`` gave them; without Cq, q = q_ratio p (q = 0 when q_ratio is
        None).
    out_of_plane : callable (Cp, Cq=None, q_ratio=None) -> (ndarray, ndarray, ndarray), optional
        (sigma_zz, sigma_yz, sigma_xz) in generalised plane strain (Z along the punch's
        generators), from the same transforms.  Modes without it (the plane model,
        :class:`contact.subsurface.HalfSpaceModes`) leave those components None in
        :class:`contact.subsurface.StressField`, and with them von Mises and Tresca.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (2.4)-(3.1) (the modes of the orthotropic
    half-space); Johnson, Contact Mechanics (1985), Sec. 2.3 (the isotropic field of
    surface tractions).

    Examples
    --------
    Flamant's line load P = 1, C(z) = -1 / (pi z), on an isotropic material at rest: on the
    axis at depth 2, sigma_yy = -2P / (pi depth) (Johnson 1985, eq. (2.15)):

    >>> import numpy as np, contact
    >>> modes = contact.Isotropic(1.0, 0.3).half_space_modes(0.0)
    >>> isinstance(modes, contact.MaterialModes)
    True
    >>> X, Y = np.array([0.0]), np.array([-2.0])
    >>> C = [-1.0 / (np.pi * z) for z in modes.points(X, Y)]
    >>> sxx, syy, sxy = modes.stresses(C)
    >>> round(float(syy[0] * np.pi), 9)
    -1.0
    """

    def points(self, X, Y) -> list:
        ...

    def stresses(self, Cp, Cq=None, q_ratio=None) -> tuple:
        ...


@runtime_checkable
class SurfaceKernel(Protocol):
    """The regular part of a surface's response to a line load: what a layer or a coating
    adds to the half-space's.

    Returned by a material's optional ``surface_kernel(c)`` (:class:`Material`).  With it the
    surface relation of the half-space becomes

        dv/dX (X, 0) = N12 q(X) + N11 Hc[p](X) + int k(X, t) p(t) dt + int k_q(X, t) q(t) dt,

    and the contact equation gains the regular (Fredholm) term int k(X, t) p(t) dt, k
    bounded and smooth on the contact (a layer of thickness h: smooth on the scale h).  The
    gap between the zones and outside them needs the displacement itself, through an
    antiderivative K in X, dK/dX = k (any function of t may be added: it cancels).

    Attributes
    ----------
    slope : callable (X, t) -> ndarray
        k(X, t): dv/dX at (X, 0) per unit normal line load at t, beyond the half-space's
        N11 / (pi (t - X)).  Called with float arrays X, t of one shape; returns finite real
        values of that shape.
    deflection : callable (X, t) -> ndarray
        K(X, t), with dK/dX = k.
    shear_slope, shear_deflection : callable (X, t) -> ndarray, optional
        The same per unit tangential line load (q); needed when the contact has friction
        (q = mu_f p adds mu_f k_q to k): a kernel without them is refused there.
    sigma_xx, shear_sigma_xx : callable (X, t) -> ndarray, optional
        sigma_XX at (X, 0) per unit normal (tangential) line load at t, beyond the
        half-space's; without them :meth:`contact.ContactResult.sigma_xx` is refused.

    References
    ----------
    Erdogan, Gupta & Cook, "Numerical solution of singular integral equations", in Methods
    of Analysis and Solutions of Crack Problems (1973), ch. 7 (a Cauchy kernel plus a
    regular one, as the layered and bonded bodies give).

    Examples
    --------
    A constant k = kappa tilts what the punch sees by kappa P (dv/dX gains kappa int p):

    >>> import contact
    >>> class Tilting:
    ...     def slope(self, X, t):
    ...         return 0.01 + 0.0 * (X + t)
    ...     def deflection(self, X, t):
    ...         return 0.01 * X + 0.0 * t
    >>> isinstance(Tilting(), contact.SurfaceKernel)
    True
    """

    def slope(self, X, t):
        ...

    def deflection(self, X, t):
        ...


@runtime_checkable
class Material(Protocol):
    """What :func:`contact.solve` and the stress field need of a material.

    Any object with these five methods is a material, whatever its class.  The library
    calls them through :func:`contact.surface_constants`, :func:`contact.rayleigh_speed`,
    :func:`contact.limiting_speed`, :func:`contact.relative_speed` and
    :func:`contact.subsurface.half_space_modes`, which
    check what they return; a method may raise a :class:`~contact.ContactInputError`
    (e.g. :class:`~contact.SpeedError`, :class:`~contact.MaterialError`) to refuse its
    input, and any other exception it raises is reported as a
    :class:`~contact.MaterialError` naming it.

    Attributes
    ----------
    surface_constants : callable c -> SurfaceConstants
        N11, N12, N21, N22 at the relative speed c, 0 <= c < c_R (only such c are passed):
        finite real numbers with N11 < 0, ``c`` the speed asked and ``rayleigh_speed`` the
        material's c_R; the couplings M12, M21, M22 finite (0, the default, for a material
        with the mirror plane X = 0).  ``eta_product``, ``eta_sum`` and
        ``rayleigh_denominator`` are those of the orthotropic formulas, and may be left
        None.  With friction the coefficient b = N11 + M12 mu_f of Hc[p] must stay < 0
        (:class:`~contact.FrictionError` otherwise).
    rayleigh_speed : callable () -> float
        The relative Rayleigh speed c_R > 0: the admissible speeds are 0 <= c < c_R.
    limiting_speed : callable () -> float
        The lowest relative speed at which a mode stops decaying into the half-space
        (>= c_R).
    relative_speed : callable V -> float
        The relative speed c >= 0 of a punch moving at speed V (needs a density; may raise
        :class:`~contact.MaterialError` without one).
    half_space_modes : callable c -> MaterialModes
        The modes at the relative speed c (0 <= c < c_R) for the field under the surface.
    surface_kernel : callable c -> SurfaceKernel or None, optional
        The regular part of the surface's response at the relative speed c (a layer, a
        coating: :class:`SurfaceKernel`); absent or None for a homogeneous half-space, whose
        contact equations then take their kernel-free paths.  ``half_space_modes`` gives the
        whole field under the surface, the layer's part included.

    Notes
    -----
    ``isinstance(m, contact.Material)`` tells whether ``m`` has the five methods, not
    whether they return admissible values.  The relative speed is the punch's speed over a
    speed of the material's own (for :class:`contact.Orthotropic` the shear wave speed
    sqrt(C33 / rho)); the constants, c_R and the modes are given on that scale.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (4.5)-(4.6) (the surface relations) and
    Sec. 6.1 (the relative speed; the range 0 <= c < c_R: see the documentation, Theory:
    errata of Zhou et al. 2014).

    Examples
    --------
    A material of one's own may wrap an orthotropic one:

    >>> import contact
    >>> class Wrapped:
    ...     def __init__(self, inner):
    ...         self.inner = inner
    ...     def surface_constants(self, c):
    ...         return self.inner.surface_constants(c)
    ...     def rayleigh_speed(self):
    ...         return self.inner.rayleigh_speed()
    ...     def limiting_speed(self):
    ...         return self.inner.limiting_speed()
    ...     def relative_speed(self, V):
    ...         return self.inner.relative_speed(V)
    ...     def half_space_modes(self, c):
    ...         return self.inner.half_space_modes(c)
    >>> m = Wrapped(contact.zhou2014())
    >>> isinstance(m, contact.Material), isinstance("steel", contact.Material)
    (True, False)
    >>> r = contact.solve(m, contact.CylindricalPunch(100.0), load=0.01, speed=0.6)
    >>> r.ends == contact.solve(contact.zhou2014(), contact.CylindricalPunch(100.0),
    ...                         load=0.01, speed=0.6).ends
    True
    """

    def surface_constants(self, c):
        ...

    def rayleigh_speed(self) -> float:
        ...

    def limiting_speed(self) -> float:
        ...

    def relative_speed(self, V) -> float:
        ...

    def half_space_modes(self, c) -> MaterialModes:
        ...


def check_material(material, name: str = "material") -> None:
    """Raise :class:`~contact.ContactInputError` unless ``material`` has the methods of
    :class:`Material`, naming those it lacks and what is allowed.

    A few attribute look-ups: :func:`contact.solve_batch` runs it once for all its cases.
    """
    for method, _ in MATERIAL_METHODS:
        if not callable(getattr(material, method, None)):
            break
    else:
        if not isinstance(material, type):
            return
        raise ContactInputError(
            f"{name} must be a material object, got the class {material.__name__} itself: "
            f"make one, e.g. contact.Orthotropic(C11, C12, C22, C33) or a material of your "
            f"own (an instance of its class)")
    missing = [method for method, _ in MATERIAL_METHODS
               if not callable(getattr(material, method, None))]
    raise ContactInputError(
        f"{name} must have the methods {', '.join(sig for _, sig in MATERIAL_METHODS)} (the "
        f"contact.Material protocol; allowed: contact.Orthotropic, contact.Isotropic(...), "
        f"contact.zhou2014(), or an object of your own with these methods), got "
        f"{type(material).__name__}, which lacks {', '.join(missing)}")


def call(material, method: str, *args):
    """``material.<method>(*args)``: a :class:`~contact.ContactInputError` it raises passes
    as it is (the material refusing its input); any other exception is a
    :class:`~contact.MaterialError` naming the method and its arguments, chained."""
    try:
        return getattr(material, method)(*args)
    except ContactInputError:
        raise
    except Exception as exc:               # a user's material: any failure is named
        raise MaterialError(
            f"{describe_call(material, method, *args)} raised {type(exc).__name__}: "
            f"{exc}") from exc


def describe_call(material, method: str, *args) -> str:
    """``'<Class>.method(args)'`` for a message: which method of which material."""
    return f"{type(material).__name__}.{method}({', '.join(repr(a) for a in args)})"
