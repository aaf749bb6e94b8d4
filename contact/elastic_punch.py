"""An elastic punch: the compliance of the punch body added to the half-space's.

The punch is a body of its own material, large against the contact (a half-space Y >= 0 in
the frame of the contact), at rest in that frame: only the half-space Y <= 0 moves (at the
relative speed c).  The surfaces touch where the gap between them closes,

    g(X) = [H(X) - delta + v_p(X)] - v(X),

v and v_p the displacements along Y of the half-space's surface and of the punch's.  The
punch feels the tractions opposite to the half-space's.  Seen from below (the half-turn
about X, Y' = -Y, Z' = -Z, which keeps X: a proper rotation), it is a half-space Y' <= 0 of
its material turned by that half-turn, under the pressure p and the tangential traction
q' = -q, and its surface slope along Y' is, by the constants of :class:`SurfaceConstants`
of the turned material at rest,

    dv'/dX = -N12_p q + N11_p Hc[p] - M12_p Hc[q],     v_p = -v'.

In contact g' = 0: dv/dX - dv_p/dX = H'(X), i.e. the equation of the rigid punch with

    N11 -> N11 + N11_p,   N12 -> N12 - N12_p,   M12 -> M12 - M12_p             (1)

(:func:`two_body_constants`); the surface stress sigma_XX of the half-space and the field
under it keep the half-space's own constants (N21, N22, M21, M22 and its modes): the
tractions are the same, only their relation to the geometry changes.  The gap of the
result is the gap between the two deformed surfaces.

For two isotropic bodies, (1) is the classical two-body contact (K. L. Johnson, Contact
Mechanics (1985), the chapters on Hertz's theory and on sliding contact): N11 + N11_p = -(1 - nu1)/G1 - (1 - nu2)/G2, the compliance 2/E* of the pair,
and N12 - N12_p = (1 - 2 nu1)/(2 G1) - (1 - 2 nu2)/(2 G2); their ratio is Dundurs' beta of
the pair (the half-space body 1; the coupling of the normal and the tangential problems),
0 for identical materials, where friction leaves the pressure alone.  For two bodies of one anisotropic
material in one orientation the local parts cancel (N12 - N12_p = 0) and the Hilbert parts
double (M12 - M12_p = 2 M12): the material seen from below has the opposite M12.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from .anisotropic import Anisotropic
from .constants import SurfaceConstants, surface_constants
from .errors import ContactInputError
from .material import Orthotropic
from .protocol import check_material

__all__ = ["HALF_TURN_ABOUT_X", "punch_constants", "two_body_constants"]

#: The half-turn about X (Y -> -Y, Z -> -Z): the punch's material seen from below.
HALF_TURN_ABOUT_X = np.diag([1.0, -1.0, -1.0])


def punch_constants(punch_material) -> SurfaceConstants:
    """The surface constants of the punch body at rest, seen from below (its material turned
    by the half-turn about X; module docstring).

    Parameters
    ----------
    punch_material : Orthotropic or Anisotropic
        An orthotropic material aligned with the frame (:class:`contact.Orthotropic`,
        :func:`contact.Isotropic`: the half-turn leaves it as it is) or any anisotropic one
        (:class:`contact.Anisotropic`, turned here).  A layered material is refused (its
        kernel is the half-space's below a layer, not a body's), and so is a material of
        one's own: the punch is seen from below, which needs the material's turn.

    Returns
    -------
    SurfaceConstants
        At relative speed 0.

    Raises
    ------
    ContactInputError
        Not one of the materials above.
    MaterialError
        From the material's own checks.

    References
    ----------
    T. C. T. Ting, Anisotropic Elasticity (1996), ch. 5 and 7 (the surface response);
    K. L. Johnson, Contact Mechanics (1985) (two elastic bodies in contact).

    Examples
    --------
    An isotropic punch is its own turn:

    >>> import contact
    >>> from contact.elastic_punch import punch_constants
    >>> pc = punch_constants(contact.Isotropic(2.0, 0.25))
    >>> round(pc.N11, 12), round(pc.N12, 12)
    (-0.9375, 0.3125)
    """
    check_material(punch_material, "punch_material")
    if getattr(punch_material, "surface_kernel", None) is not None:
        raise ContactInputError("punch_material must be a homogeneous body: a layered "
                                "material describes a half-space under a layer, not a punch")
    if isinstance(punch_material, Anisotropic):
        return surface_constants(punch_material.rotated(HALF_TURN_ABOUT_X), 0.0)
    if isinstance(punch_material, Orthotropic):
        return surface_constants(punch_material, 0.0)
    raise ContactInputError(
        f"punch_material must be a contact.Orthotropic, contact.Isotropic(...) or "
        f"contact.Anisotropic material, got {type(punch_material).__name__}: the punch is "
        f"seen from below (its material turned half a turn about X), which a material of "
        f"one's own cannot be asked for")


def two_body_constants(half_space: SurfaceConstants, punch: SurfaceConstants) -> SurfaceConstants:
    """The constants of the contact equation with an elastic punch: eq. (1) of the module
    docstring (N11 + N11_p, N12 - N12_p, M12 - M12_p), and the relative tangential slope's
    compliance T + T_p (du/dX - du_p/dX = (T + T_p) Hc[q] - (N12 - N12_p) p + ...: seen from
    below the punch feels -q and keeps X); the half-space's own N21, N22, M21, M22, speed
    and Rayleigh speed.

    Parameters
    ----------
    half_space : SurfaceConstants
        The moving half-space's, at the contact's speed.
    punch : SurfaceConstants
        The punch's at rest, seen from below (:func:`punch_constants`).

    Returns
    -------
    SurfaceConstants

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985) (two elastic bodies in contact); J. Dundurs,
    J. Appl. Mech. 36 (1969) 650 (beta).

    Examples
    --------
    Two bodies of one isotropic material: the coupling N12 cancels (Dundurs' beta = 0),
    the compliance doubles:

    >>> import contact
    >>> from contact.elastic_punch import punch_constants, two_body_constants
    >>> m = contact.Isotropic(1.0, 0.3)
    >>> both = two_body_constants(contact.surface_constants(m, 0.0), punch_constants(m))
    >>> round(both.N11, 12), both.N12
    (-3.64, 0.0)
    """
    T, Tp = half_space.tangential_compliance, punch.tangential_compliance
    return dataclasses.replace(half_space, N11=half_space.N11 + punch.N11,
                               N12=half_space.N12 - punch.N12,
                               M12=half_space.M12 - punch.M12,
                               tangential_compliance=None if T is None or Tp is None
                               else T + Tp)
