"""A general anisotropic half-space in steady motion: the Stroh formalism without eigenvectors.

:class:`Anisotropic` holds the full 6x6 stiffness of a linear elastic material in the frame of
the contact problem; :meth:`Anisotropic.surface_response` gives the response of the surface of
the half-space Y <= 0 to tractions moving at a steady relative speed c, split into local and
Hilbert parts.  For an orthotropic material aligned with the frame it reproduces the closed
forms of :mod:`contact.constants`; it also holds for a material of any symmetry, rotated in any
way.  :class:`Anisotropic` is a :class:`contact.Material`: :meth:`Anisotropic.surface_constants`
gives :func:`contact.solve` the entries of the response that the contact equation needs
(N11, N12, N21, N22 and the couplings M12, M21, M22 of :class:`contact.SurfaceConstants`).

Conventions
-----------
Frame: X the sliding direction, Y the outward normal (the half-space is Y <= 0), Z along the
generators of the punch; nothing depends on Z (generalised plane strain: the displacement
w along Z may be nonzero, the strains along Z vanish).  Voigt order of stresses, strains and
of the rows and columns of C: (XX, YY, ZZ, YZ, ZX, XY) = 1..6, so C66 is the XY shear
stiffness (:attr:`Orthotropic.C33 <contact.Orthotropic.C33>` of the plane orthotropic model).

Surface tractions, the columns of the response (tractions s = (q, p, r))::

    sigma_XY(X, 0) = -q(X),   sigma_YY(X, 0) = -p(X),   sigma_ZY(X, 0) = -r(X),

i.e. sigma_iY(X, 0) = -s_i for i = X, Y, Z (p > 0 presses the surface in; q and r are the
tangential tractions along X and Z, r = 0 in contact).  With
Hc[f](X) = (1/pi) PV int f(t) / (t - X) dt (the Fourier multiplier +i sgn(k) on exp(i k X))
the surface responds as (:class:`SurfaceResponse`)::

    du_i/dX (X, 0)   = sum_j  L_ij s_j(X) + M_ij Hc[s_j](X),        i = X, Y, Z,
    sigma_a (X, 0)   = sum_j  A_aj s_j(X) + B_aj Hc[s_j](X),        a = Voigt 1..6.

For an aligned orthotropic material (:func:`contact.surface_constants`):
N11 = M_YY, N12 = L_YX, N21 = A_XX,p = A[0, 1], N22 = B_XX,q = B[0, 0].  For any material,
with r = 0 (the punch is frictionless along Z), the couplings M12 = M_YX, M21 = B_XX,p =
B[0, 1] and M22 = A_XX,q = A[0, 0] complete them (:meth:`SurfaceResponse.surface_constants`)::

    dv/dX (X, 0)    = N12 q + N11 Hc[p] + M12 Hc[q],
    sigma_XX (X, 0) = N21 p + N22 Hc[q] + M21 Hc[p] + M22 q;

L_YY, the local part of dv/dX under p, vanishes: L is antisymmetric.

Relative speed c = V / sqrt(C66 / rho), so that rho V^2 = C66 c^2 and a speed means what it
means for :class:`contact.Orthotropic` (whose C33 is this C66).

The Stroh matrix of the moving half-space
-----------------------------------------
In the frame moving with the load, u(X, Y) = u_hat(Y) exp(i k X) obeys
sigma_ij,j = rho V^2 u_i,XX.  With Q_ik = C_iXkX, R_ik = C_iXkY, T_ik = C_iYkY (Stroh 1962;
Ting 1996, ch. 5) and the state eta = (u_hat, t_hat / (i k)), t_i = sigma_iY the traction on
Y = const::

    d eta / dY = i k N eta,
    N = [[N1, N2], [N3, N1^T]],   N1 = -T^-1 R^T,  N2 = T^-1,  N3 = R T^-1 R^T - Q + rho V^2 I,

the fundamental elasticity matrix of Stroh with the inertia term (Ting 1996, ch. 12; Barnett
& Lothe 1985): its eigenvalues p are the roots of
det(Q - rho V^2 I + p (R + R^T) + p^2 T) = 0.  Below the limiting speed no p is real; for
k > 0 the modes with Im p < 0 decay as Y -> -inf (for k < 0 their complex conjugates).

Without eigenvectors: the sign function
---------------------------------------
The three decaying modes span the invariant subspace of i N whose eigenvalues have positive
real parts.  Its projector is (I + sign(i N)) / 2, and sign(i N) = i S_hat with S_hat real,
S_hat^2 = -I: S_hat is computed by the scaled Newton iteration
S <- (mu S - (mu S)^-1) / 2 from S = N (Higham 2008, ch. 5, the Newton iteration for the
matrix sign function, written for i N in real arithmetic).  It never forms eigenvectors nor
divides by differences of eigenvalues, and converges for repeated and defective eigenvalues
alike (the isotropic material at rest, where p = +-i are triple and N is not diagonalisable),
at a rate set by the distance of the eigenvalues from the real axis only.  S_hat is the
matrix (1/pi) int_0^pi N(theta) d theta of the integral formalism of Barnett & Lothe (Ting
1996, ch. 7; Barnett & Lothe 1985 for the moving half-space), whose lower left block is minus
the Barnett-Lothe tensor L_BL.

On the decaying subspace (k > 0) S_hat eta = -i eta.  Written in blocks
S_hat = [[S1, S2], [S3, S4]], its second row gives S3 u_hat = -(S4 + i I) t_hat / (i k), so
with du/dX = i k u, t = -s and the multiplier +i sgn(k) of Hc::

    L = S3^-1 S4,        M = S3^-1.

M = -L_BL^-1 is symmetric (reciprocity) and L antisymmetric (L_BL S_BL is antisymmetric:
Ting 1996, ch. 7, the identities of the Barnett-Lothe tensors); for the isotropic material
at rest L_YX = (1 - 2 nu) / (2G), M_YY = -(1 - nu) / G.  The stresses on the surface follow
from the stress-strain law with u_,Y = T^-1 (t - R^T u_,X)::

    sigma_ij = (C_ijkX - C_ijmY (T^-1 R^T)_mk) u_k,X + C_ijmY T^-1_mk t_k.

The Rayleigh speed and the limiting speed
-----------------------------------------
The limiting speed c_L is the lowest speed at which some p becomes real (a bulk wave whose
slowness projects onto 1/V along X):
rho V_L^2 = min over real p of the smallest eigenvalue of Q + p (R + R^T) + p^2 T
(Barnett & Lothe 1985; Ting 1996, ch. 12).  Below it the symmetric matrix L_BL = -S3 (the
Barnett-Lothe tensor of the moving half-space) is positive definite at c = 0 and its eigenvalues
decrease with c (Barnett & Lothe 1985); the Rayleigh speed c_R is the first zero of its
smallest eigenvalue (the surface impedance becomes singular: a free surface wave), found by
bisection; where it stays positive up to c_L (an exceptional limiting wave, e.g. a decoupled
shear wave polarised along Z that is itself traction free) c_R = c_L.

References
----------
Stroh, A. N., "Steady state problems in anisotropic elasticity", J. Math. Phys. 41 (1962)
77-103.
Ting, T. C. T., Anisotropic Elasticity: Theory and Applications, Oxford University Press (1996):
the Stroh formalism (ch. 5), the Barnett-Lothe tensors and the integral formalism (ch. 7),
steady motion and surface waves (ch. 12).
Barnett, D. M. & Lothe, J., "Free surface (Rayleigh) waves in anisotropic elastic half-spaces:
the surface impedance method", Proc. R. Soc. Lond. A 402 (1985) 135-152.
Higham, N. J., Functions of Matrices: Theory and Computation, SIAM (2008), ch. 5 (the matrix
sign function, the scaled Newton iteration).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .constants import SurfaceConstants
from .errors import FrictionError, MaterialError, SpeedError, check_finite, real_array
from .material import Orthotropic
from .stroh_modes import stroh_modes

__all__ = ["Anisotropic", "SurfaceResponse", "PressureCoefficients", "VOIGT",
           "voigt_to_tensor", "tensor_to_voigt"]

#: The Voigt order: index a of a 6-vector or of a row/column of C <-> the pair (i, j), 0 = X.
VOIGT = ((0, 0), (1, 1), (2, 2), (1, 2), (2, 0), (0, 1))
#: _PAIR[i, j]: the Voigt index of the pair (i, j).
_PAIR = np.array([[0, 5, 4], [5, 1, 3], [4, 3, 2]])

#: Relative asymmetry |C - C^T| / max|C| accepted (rounding) and removed by symmetrising.
SYMMETRY_TOLERANCE = 1e-12
#: Smallest eigenvalue of C allowed, as a fraction of its largest.
DEFINITENESS_TOLERANCE = 1e-12
#: Deviation |R^T R - I| accepted in a rotation matrix.
ROTATION_TOLERANCE = 1e-10
_SIGN_MAX_ITERATIONS = 100
#: The speeds whose surface constants a material keeps (:meth:`Anisotropic.surface_constants`).
CONSTANTS_CACHE_SIZE = 64
_LIMIT_SAMPLES = 2048


def voigt_to_tensor(C) -> np.ndarray:
    """The 3x3x3x3 stiffness tensor C_ijkl of a 6x6 Voigt matrix (order XX, YY, ZZ, YZ, ZX,
    XY; :data:`VOIGT`)."""
    C = np.asarray(C, dtype=float)
    return C[_PAIR[:, :, None, None], _PAIR[None, None, :, :]]


def tensor_to_voigt(t) -> np.ndarray:
    """The 6x6 Voigt matrix of a stiffness tensor with the minor and major symmetries (the
    inverse of :func:`voigt_to_tensor`)."""
    t = np.asarray(t, dtype=float)
    i, j = np.array(VOIGT).T
    return t[i[:, None], j[:, None], i[None, :], j[None, :]]


class PressureCoefficients(NamedTuple):
    """The surface response to a pressure p with q = q_ratio p and r = 0
    (:meth:`SurfaceResponse.pressure_coefficients`)::

        du_i/dX (X, 0) = slope_local[i] p(X) + slope_hilbert[i] Hc[p](X),
        sigma_a (X, 0) = stress_local[a] p(X) + stress_hilbert[a] Hc[p](X).
    """

    slope_local: np.ndarray
    slope_hilbert: np.ndarray
    stress_local: np.ndarray
    stress_hilbert: np.ndarray


@dataclass(frozen=True, eq=False)
class SurfaceResponse:
    """The surface of a moving anisotropic half-space: local and Hilbert parts of its
    response to the surface tractions (:meth:`Anisotropic.surface_response`).

    With the tractions s = (q, p, r), sigma_XY(X, 0) = -q, sigma_YY(X, 0) = -p,
    sigma_ZY(X, 0) = -r, and Hc[f](X) = (1/pi) PV int f(t) / (t - X) dt::

        du_i/dX (X, 0) = sum_j slope_local[i, j] s_j(X) + slope_hilbert[i, j] Hc[s_j](X),
        sigma_a (X, 0) = sum_j stress_local[a, j] s_j(X) + stress_hilbert[a, j] Hc[s_j](X),

    i = X, Y, Z (u, v, w); a in the Voigt order (XX, YY, ZZ, YZ, ZX, XY); j = q, p, r.

    Attributes
    ----------
    c : float
        Relative speed V / sqrt(C66 / rho).
    rayleigh_speed : float
        c_R of the material.
    slope_local, slope_hilbert : numpy.ndarray, shape (3, 3)
        L = S3^-1 S4 (antisymmetric) and M = S3^-1 (symmetric) of the module docstring
        (unit: 1 / stress unit of C).
    stress_local, stress_hilbert : numpy.ndarray, shape (6, 3)
        The stresses on the surface (dimensionless).  Rows YY, YZ, XY are the boundary
        conditions: -e_p, -e_r, -e_q and 0 (to rounding).

    Notes
    -----
    The entries of the plane orthotropic model (:class:`contact.SurfaceConstants`) are
    :attr:`N11` = slope_hilbert[Y, p], :attr:`N12` = slope_local[Y, q],
    :attr:`N21` = stress_local[XX, p], :attr:`N22` = stress_hilbert[XX, q]; a material
    without the mirror symmetries of an aligned orthotropic one has further entries
    (:attr:`M12` = slope_hilbert[Y, q], dv/dX under Hc[q]; :attr:`M21` =
    stress_hilbert[XX, p]; :attr:`M22` = stress_local[XX, q]; slope_local[Y, r], ...).
    :meth:`surface_constants` collects those of the contact equation.

    References
    ----------
    Stroh, J. Math. Phys. 41 (1962) 77-103; Ting, Anisotropic Elasticity (1996), ch. 5, 7 and
    12; Barnett & Lothe, Proc. R. Soc. Lond. A 402 (1985) 135-152; the derivation in
    :mod:`contact.anisotropic`.

    Examples
    --------
    The isotropic material at rest (G = 1, nu = 1/4): dv/dX = (1 - 2 nu)/(2G) q -
    (1 - nu)/G Hc[p]; the local part is antisymmetric, the Hilbert part symmetric:

    >>> import numpy as np, contact
    >>> r = contact.Anisotropic.isotropic(2.5, 0.25).surface_response(0.0)
    >>> round(r.N12, 12), round(r.N11, 12), r.M12
    (0.25, -0.75, 0.0)
    >>> bool(np.allclose(r.slope_local, -r.slope_local.T, rtol=0, atol=1e-15))
    True
    >>> r.surface_constants().equation_coefficients(0.2) == (0.2 * r.N12, r.N11)
    True
    """

    c: float
    rayleigh_speed: float
    slope_local: np.ndarray
    slope_hilbert: np.ndarray
    stress_local: np.ndarray
    stress_hilbert: np.ndarray

    @property
    def N11(self) -> float:
        """dv/dX per Hc[p]: slope_hilbert[1, 1] (:class:`contact.SurfaceConstants`)."""
        return float(self.slope_hilbert[1, 1])

    @property
    def N12(self) -> float:
        """dv/dX per q: slope_local[1, 0]."""
        return float(self.slope_local[1, 0])

    @property
    def N21(self) -> float:
        """sigma_XX per p: stress_local[0, 1]."""
        return float(self.stress_local[0, 1])

    @property
    def N22(self) -> float:
        """sigma_XX per Hc[q]: stress_hilbert[0, 0]."""
        return float(self.stress_hilbert[0, 0])

    @property
    def M12(self) -> float:
        """dv/dX per Hc[q]: slope_hilbert[1, 0] (0 with the mirror plane X = 0)."""
        return float(self.slope_hilbert[1, 0])

    @property
    def M21(self) -> float:
        """sigma_XX per Hc[p]: stress_hilbert[0, 1] (0 with the mirror plane X = 0)."""
        return float(self.stress_hilbert[0, 1])

    @property
    def M22(self) -> float:
        """sigma_XX per q: stress_local[0, 0] (0 with the mirror plane X = 0)."""
        return float(self.stress_local[0, 0])

    def surface_constants(self) -> SurfaceConstants:
        """The entries the contact equation needs, as :class:`contact.SurfaceConstants`:
        N11, N12, N21, N22 (the properties of the same names), the couplings M12, M21,
        M22 and the tangential compliance slope_hilbert[X, q]; ``eta_product``, ``eta_sum`` and ``rayleigh_denominator`` (of the orthotropic
        formulas) None.

        With q = mu_f p and r = 0 they give dv/dX = a p + b Hc[p], a = N12 mu_f,
        b = N11 + M12 mu_f, and sigma_XX = (N21 + M22 mu_f) p + (N22 mu_f + M21) Hc[p]: the
        entries [1] and [0] of :meth:`pressure_coefficients` but for slope_local[1, 1] (the
        local part of dv/dX under p), which vanishes because slope_local is antisymmetric
        (reciprocity: Ting 1996, ch. 7).
        """
        return SurfaceConstants(N11=self.N11, N12=self.N12, N21=self.N21, N22=self.N22,
                                c=self.c, rayleigh_speed=self.rayleigh_speed,
                                M12=self.M12, M21=self.M21, M22=self.M22,
                                tangential_compliance=float(self.slope_hilbert[0, 0]))

    def pressure_coefficients(self, q_ratio=0.0) -> PressureCoefficients:
        """The response to a pressure p alone, with q = q_ratio p (Coulomb friction, signed
        as the traction: sigma_XY(X, 0) = -q_ratio p) and r = 0.

        The contact equation of the punch reads dv/dX = a p + b Hc[p] with
        a = slope_local[1], b = slope_hilbert[1] of the result (for an aligned orthotropic
        material a = N12 q_ratio, b = N11); sigma_XX on the surface is
        stress_local[0] p + stress_hilbert[0] Hc[p].

        Parameters
        ----------
        q_ratio : float
            q / p, finite.

        Returns
        -------
        PressureCoefficients
            Vectors of length 3 (du/dX, dv/dX, dw/dX) and 6 (Voigt stresses).

        Raises
        ------
        FrictionError
            q_ratio not a finite real number.
        """
        f = check_finite("q_ratio", q_ratio, FrictionError)
        s = np.array([f, 1.0, 0.0])
        return PressureCoefficients(self.slope_local @ s, self.slope_hilbert @ s,
                                    self.stress_local @ s, self.stress_hilbert @ s)


class Anisotropic:
    """A linear elastic material of any symmetry, in the frame of the contact problem.

    Parameters
    ----------
    C : array_like, shape (6, 6)
        The stiffness in Voigt order (XX, YY, ZZ, YZ, ZX, XY), X the sliding direction, Y the
        outward normal of the half-space Y <= 0, Z along the punch's generators; any
        consistent stress unit.  Finite, symmetric (an asymmetry up to
        :data:`SYMMETRY_TOLERANCE` max|C|, rounding, is removed) and positive definite (the
        smallest eigenvalue above :data:`DEFINITENESS_TOLERANCE` times the largest).
    rho : float or None, optional
        Mass density (> 0), needed only by :meth:`relative_speed`.

    Raises
    ------
    MaterialError
        C not a 6x6 array of finite real numbers, not symmetric, or not positive definite
        (the message says which entries, or the smallest eigenvalue); rho not a finite
        number > 0.

    Notes
    -----
    A :class:`contact.Material`: :func:`contact.solve`, :func:`contact.load_curve` and
    :func:`contact.solve_batch` take it (:meth:`surface_constants`, :meth:`rayleigh_speed`,
    :meth:`limiting_speed`, :meth:`relative_speed`, :meth:`half_space_modes`).  The punch is
    frictionless along Z (r = 0); a material without the mirror plane X = 0 couples the
    pressure and the friction traction (M12, M21, M22 of :class:`contact.SurfaceConstants`),
    which ``method="closed_form"`` refuses.

    The relative speed is c = V / sqrt(C66 / rho), C66 the XY shear stiffness, as for
    :class:`contact.Orthotropic` (whose C33 is C66 here).  The moving half-space is the
    Stroh formalism with the inertia term, evaluated through the matrix sign function
    (:mod:`contact.anisotropic`): accurate for repeated roots (isotropy) and near them.
    Equal stiffness and density make equal (and equally hashed) materials.

    References
    ----------
    Stroh, J. Math. Phys. 41 (1962) 77-103; Ting, Anisotropic Elasticity (1996), ch. 5, 7 and
    12; Barnett & Lothe, Proc. R. Soc. Lond. A 402 (1985) 135-152.

    Examples
    --------
    An isotropic material (Lame constants lambda = G = 1) reproduces the plane isotropic
    constants N11 = -(1 - nu)/G, N12 = (1 - 2 nu)/(2G) at rest:

    >>> import contact
    >>> from contact.anisotropic import Anisotropic
    >>> m = Anisotropic.isotropic(2.5, 0.25)
    >>> float(m.C[0, 0]), float(m.C[0, 1]), float(m.C[5, 5])
    (3.0, 1.0, 1.0)
    >>> r = m.surface_response(0.0)
    >>> round(r.N11, 12), round(r.N12, 12), round(r.N21, 12), round(r.N22, 12)
    (-0.75, 0.25, -1.0, -2.0)
    >>> round(m.rayleigh_speed(), 12), m.limiting_speed()
    (0.919401686762, 1.0)

    It solves contacts as the plane isotropic material does:

    >>> r = contact.solve(m, contact.CylindricalPunch(1.0), load=0.01, speed=0.5,
    ...                   friction=0.3)
    >>> r0 = contact.solve(contact.Isotropic(2.5, 0.25), contact.CylindricalPunch(1.0),
    ...                    load=0.01, speed=0.5, friction=0.3)
    >>> abs(r.ends[1] - r0.ends[1]) < 1e-12 * r0.half_width
    True
    """

    __slots__ = ("_C", "_rho", "_scale", "_blocks", "_cache")

    def __init__(self, C, rho=None):
        C = _check_stiffness(C)
        self._C = C
        self._C.flags.writeable = False
        self._rho = None if rho is None else _check_positive("rho", rho)
        self._scale = float(C[5, 5])
        self._blocks = _plane_blocks(voigt_to_tensor(C / self._scale))
        self._cache = {}

    # ------------------------------------------------------------------ data
    @property
    def C(self) -> np.ndarray:
        """The 6x6 stiffness in Voigt order (read-only)."""
        return self._C

    @property
    def rho(self) -> float | None:
        """The density, or None."""
        return self._rho

    @property
    def tensor(self) -> np.ndarray:
        """The stiffness tensor C_ijkl, shape (3, 3, 3, 3), 0 = X, 1 = Y, 2 = Z."""
        return voigt_to_tensor(self._C)

    def __repr__(self) -> str:
        rows = ", ".join("[" + ", ".join(repr(float(v)) for v in row) + "]" for row in self._C)
        return f"Anisotropic(C=[{rows}], rho={self._rho!r})"

    def __eq__(self, other):
        if not isinstance(other, Anisotropic):
            return NotImplemented
        return self._rho == other._rho and np.array_equal(self._C, other._C)

    def __hash__(self):
        return hash((self._C.tobytes(), self._rho))

    # ------------------------------------------------------------------ constructors
    @classmethod
    def from_orthotropic(cls, material, *, C13, C23, C33, C44, C55, rho=None) -> Anisotropic:
        """The plane orthotropic ``material`` with its out-of-plane stiffnesses.

        Parameters
        ----------
        material : contact.Orthotropic
            Its C11, C12, C22 become C11, C12, C22 and its C33 (the in-plane shear
            stiffness) becomes C66 of the 6x6 matrix.
        C13, C23, C33, C44, C55 : float
            The out-of-plane stiffnesses, Voigt numbering: C13 = C_XXZZ, C23 = C_YYZZ,
            C33 = C_ZZZZ, C44 = C_YZYZ, C55 = C_ZXZX.  They leave the in-plane response of
            the aligned material unchanged; C55 sets the speed of the shear wave along X
            polarised along Z, which bounds the limiting speed: c_L^2 <= C55 / C66.
        rho : float or None, optional
            The density; by default the material's.

        Returns
        -------
        Anisotropic

        Raises
        ------
        MaterialError
            ``material`` not a :class:`contact.Orthotropic`, a stiffness not finite, or
            the 6x6 matrix not positive definite.
        """
        if not isinstance(material, Orthotropic):
            raise MaterialError(f"material must be a contact.Orthotropic (or "
                                f"contact.Isotropic(...)), got {type(material).__name__}")
        out = {name: check_finite(name, value, MaterialError) for name, value in
               dict(C13=C13, C23=C23, C33=C33, C44=C44, C55=C55).items()}
        C = np.zeros((6, 6))
        C[0, 0], C[1, 1], C[5, 5] = material.C11, material.C22, material.C33
        C[0, 1] = C[1, 0] = material.C12
        C[0, 2] = C[2, 0] = out["C13"]
        C[1, 2] = C[2, 1] = out["C23"]
        C[2, 2], C[3, 3], C[4, 4] = out["C33"], out["C44"], out["C55"]
        return cls(C, material.rho if rho is None else rho)

    @classmethod
    def isotropic(cls, E, nu, rho=None) -> Anisotropic:
        """The isotropic material of Young's modulus ``E`` and Poisson's ratio ``nu``
        (-1 < nu < 1/2): C11 = C22 = C33 = lambda + 2G, C12 = C13 = C23 = lambda,
        C44 = C55 = C66 = G (as :func:`contact.Isotropic`)."""
        from .material import Isotropic
        m = Isotropic(E, nu, rho)
        return cls.from_orthotropic(m, C13=m.C12, C23=m.C12, C33=m.C11, C44=m.C33, C55=m.C33)

    @classmethod
    def from_engineering(cls, E1, E2, E3, nu12, nu13, nu23, G12, G13, G23,
                         rho=None) -> Anisotropic:
        """An orthotropic material from its engineering constants, axes 1, 2, 3 = X, Y, Z.

        The compliance (Voigt order, strains from stresses) has S_ii = 1 / E_i,
        S_ij = -nu_ij / E_i (nu_ij: the contraction along j under a stress along i, so that
        nu_ij / E_i = nu_ji / E_j), S44 = 1 / G23, S55 = 1 / G13, S66 = 1 / G12, and
        C = S^-1 (Lekhnitskii's convention for nu_ij).  Rotate the result
        (:meth:`rotated`) for material axes off the frame.

        Parameters
        ----------
        E1, E2, E3, G12, G13, G23 : float
            Young's and shear moduli, finite and > 0.
        nu12, nu13, nu23 : float
            Poisson's ratios, finite.
        rho : float or None, optional
            The density.

        Returns
        -------
        Anisotropic

        Raises
        ------
        MaterialError
            A modulus not finite or not > 0, a ratio not finite, or the compliance not
            positive definite (for instance abs(nu12) >= sqrt(E1 / E2)).

        Examples
        --------
        >>> from contact.anisotropic import Anisotropic
        >>> m = Anisotropic.from_engineering(2.5, 2.5, 2.5, 0.25, 0.25, 0.25, 1.0, 1.0, 1.0)
        >>> [round(float(v), 12) for v in (m.C[0, 0], m.C[0, 1], m.C[3, 3])]
        [3.0, 1.0, 1.0]
        """
        moduli = {name: _check_positive(name, value) for name, value in
                  dict(E1=E1, E2=E2, E3=E3, G12=G12, G13=G13, G23=G23).items()}
        ratios = {name: check_finite(name, value, MaterialError) for name, value in
                  dict(nu12=nu12, nu13=nu13, nu23=nu23).items()}
        E = [moduli["E1"], moduli["E2"], moduli["E3"]]
        S = np.zeros((6, 6))
        S[[0, 1, 2], [0, 1, 2]] = [1.0 / e for e in E]
        for (i, j), name in (((0, 1), "nu12"), ((0, 2), "nu13"), ((1, 2), "nu23")):
            S[i, j] = S[j, i] = -ratios[name] / E[i]
        S[3, 3], S[4, 4], S[5, 5] = 1.0 / moduli["G23"], 1.0 / moduli["G13"], 1.0 / moduli["G12"]
        # positive definiteness of the normal block, relative to its diagonal
        d = np.sqrt(np.diag(S[:3, :3]))
        lam = np.linalg.eigvalsh(S[:3, :3] / np.outer(d, d))[0]
        if not lam > DEFINITENESS_TOLERANCE:
            raise MaterialError(
                f"the engineering constants give a compliance that is not positive definite "
                f"(E = {E}, nu12 = {ratios['nu12']!r}, nu13 = {ratios['nu13']!r}, "
                f"nu23 = {ratios['nu23']!r}: the smallest eigenvalue of the normal block, "
                f"scaled by its diagonal, is {lam!r}); allowed: |nu_ij| < sqrt(E_i / E_j) and "
                f"1 - nu12 nu21 - nu13 nu31 - nu23 nu32 - 2 nu21 nu32 nu13 > 0, "
                f"nu_ji = nu_ij E_j / E_i")
        C = np.linalg.inv(S)
        return cls(0.5 * (C + C.T), rho)

    def rotated(self, rotation) -> Anisotropic:
        """The material rotated actively: its direction e becomes R e.

        C'_ijkl = R_ia R_jb R_kc R_ld C_abcd (scipy's convention: R maps the material's axes
        to the frame's).  The density is kept.

        Parameters
        ----------
        rotation : array_like, shape (3, 3), or scipy.spatial.transform.Rotation
            A proper rotation: R^T R = I to :data:`ROTATION_TOLERANCE` and det R = +1.
            A Rotation must hold a single rotation.

        Returns
        -------
        Anisotropic

        Raises
        ------
        MaterialError
            Not a 3x3 real matrix, not orthogonal, or a reflection (det R = -1).

        Examples
        --------
        A cubic crystal turned by 45 degrees about Z: C11' = (C11 + C12)/2 + C44,
        C66' = (C11 - C12)/2:

        >>> import numpy as np
        >>> from scipy.spatial.transform import Rotation
        >>> from contact.anisotropic import Anisotropic
        >>> C = np.diag([2.0, 2.0, 2.0, 0.5, 0.5, 0.5]); C[:3, :3] += 0.8 * (1 - np.eye(3))
        >>> m = Anisotropic(C).rotated(Rotation.from_euler("z", 45, degrees=True))
        >>> [round(float(v), 12) for v in (m.C[0, 0], m.C[0, 1], m.C[5, 5])]
        [1.9, 0.9, 0.6]
        >>> bool(abs(m.C[0, 5]) < 1e-15)                  # still orthotropic
        True
        """
        R = _check_rotation(rotation)
        t = np.einsum("ia,jb,kc,ld,abcd->ijkl", R, R, R, R, self.tensor, optimize=True)
        C = tensor_to_voigt(t)
        return type(self)(0.5 * (C + C.T) + 0.0, self._rho)     # + 0.0: no signed zeros

    # ------------------------------------------------------------------ speeds
    @property
    def shear_wave_speed(self) -> float:
        """sqrt(C66 / rho), the unit of the relative speeds; needs ``rho``."""
        if self._rho is None:
            raise MaterialError("rho is None: give the density to convert speeds "
                                "(Anisotropic(C, rho=...))")
        return math.sqrt(self._C[5, 5] / self._rho)

    def relative_speed(self, V) -> float:
        """Relative speed c = abs(V) / sqrt(C66 / rho) of a punch moving at speed ``V``.

        Raises
        ------
        SpeedError
            V not a finite real number.
        MaterialError
            No density.
        """
        V = check_finite("speed V", V, SpeedError)
        return abs(V) / self.shear_wave_speed

    def limiting_speed(self) -> float:
        """Lowest relative speed at which a mode stops decaying into the half-space.

        c_L^2 C66 = min over real p of the smallest eigenvalue of
        Gamma(p) = Q + p (R + R^T) + p^2 T, the lowest speed of a bulk wave whose slowness
        projects onto 1/V along X (p = 0: the slowest bulk wave along X).  Found on 2048
        directions theta = arctan p and refined by bounded Brent minimisation around each
        sampled minimum within 1% of the lowest (memoised).

        Returns
        -------
        float

        References
        ----------
        Barnett & Lothe, Proc. R. Soc. Lond. A 402 (1985) 135-152 (the limiting speed);
        Ting 1996, ch. 12.
        """
        if "c_L" not in self._cache:
            self._cache["c_L"] = _limiting_speed(*self._blocks)
        return self._cache["c_L"]

    def rayleigh_speed(self) -> float:
        """Relative Rayleigh speed c_R: the first zero, below the limiting speed, of the
        smallest eigenvalue of the Barnett-Lothe tensor L_BL(c) = -S3 (the surface impedance
        singular: a free surface wave); c_L where there is none (memoised).

        Bisection to about one ulp: the eigenvalues of L_BL(c) decrease with c (Barnett &
        Lothe 1985), L_BL(0) is positive definite.

        Returns
        -------
        float

        References
        ----------
        Barnett & Lothe, Proc. R. Soc. Lond. A 402 (1985) 135-152; Ting 1996, ch. 12.
        """
        if "c_R" not in self._cache:
            c_L = self.limiting_speed()
            lo, hi = 0.0, c_L
            f = {}
            while True:
                mid = 0.5 * (lo + hi)
                if not lo < mid < hi:
                    break
                f[mid] = self._rayleigh_eigenvalue(mid)
                if f[mid] > 0.0:
                    lo = mid
                else:
                    hi = mid
            if hi == c_L:      # no zero below c_L: an exceptional limiting wave
                self._cache["c_R"] = float(c_L)
            else:              # adjacent doubles: the one nearer the zero
                self._cache["c_R"] = float(hi if abs(f[hi]) < abs(f.get(lo, math.inf))
                                           else lo)
        return self._cache["c_R"]

    def _rayleigh_eigenvalue(self, c: float) -> float:
        """The smallest eigenvalue of L_BL(c) = -S3 (normalised by C66); -inf where the
        sign iteration does not converge (within rounding of the limiting speed)."""
        S, converged = _sign_matrix(_stroh_matrix(*self._blocks, c * c))
        return _impedance_eigenvalue(S) if converged else -math.inf

    def check_speed(self, c) -> float:
        """``c`` as a float if 0 <= c < c_R, else :class:`~contact.SpeedError` saying
        whether it is negative, not finite, at or above the limiting speed, or at or above
        the Rayleigh speed."""
        c = check_finite("relative speed c", c, SpeedError)
        if c < 0.0:
            raise SpeedError(f"relative speed c must be >= 0 (V / sqrt(C66 / rho)), got {c!r}")
        c_L = self.limiting_speed()
        if not c < c_L:
            raise SpeedError(
                f"relative speed c = {c!r} is at or above the limiting speed c_L = {c_L!r} of "
                f"this material, where a mode stops decaying into the half-space (allowed: "
                f"0 <= c < c_R = {self.rayleigh_speed()!r})")
        c_R = self.rayleigh_speed()
        if not c < c_R:
            raise SpeedError(
                f"relative speed c must be below the Rayleigh speed c_R = {c_R!r} of this "
                f"material (allowed: 0 <= c < c_R), got c = {c!r}")
        return c

    # ------------------------------------------------------------------ the half-space
    def stroh_matrix(self, c) -> np.ndarray:
        """The 6x6 Stroh matrix N of the half-space moving at relative speed ``c`` (module
        docstring; Ting 1996, ch. 5 and 12): N3 includes rho V^2 I = C66 c^2 I.

        Parameters
        ----------
        c : float
            Relative speed, finite and >= 0 (any such value).
        """
        c = check_finite("relative speed c", c, SpeedError)
        if c < 0.0:
            raise SpeedError(f"relative speed c must be >= 0, got {c!r}")
        N = _stroh_matrix(*self._blocks, c * c)
        N[:3, 3:] /= self._scale
        N[3:, :3] *= self._scale
        return N

    def surface_response(self, c) -> SurfaceResponse:
        """The surface's response to moving tractions at the relative speed ``c``.

        Parameters
        ----------
        c : float
            Relative speed V / sqrt(C66 / rho), 0 <= c < c_R.

        Returns
        -------
        SurfaceResponse
            slope_local L = S3^-1 S4, slope_hilbert M = S3^-1 and the stresses on the
            surface (module docstring), in the units of C.

        Raises
        ------
        SpeedError
            c negative, not finite, or not below the Rayleigh speed (or the limiting
            speed).

        References
        ----------
        Stroh (1962); Ting (1996), ch. 7 and 12; Barnett & Lothe (1985);
        Higham (2008), ch. 5.
        """
        c = self.check_speed(c)
        S, converged = _sign_matrix(_stroh_matrix(*self._blocks, c * c))
        if not converged:
            raise SpeedError(
                f"relative speed c = {c!r} is too close to the limiting speed "
                f"{self.limiting_speed()!r} for the half-space's modes to be separated "
                f"(allowed: 0 <= c < c_R = {self.rayleigh_speed()!r}, not within rounding "
                f"of c_L)")
        S3, S4 = S[3:, :3], S[3:, 3:]
        ML = np.linalg.solve(S3, np.hstack([np.eye(3), S4]))
        M, L = ML[:, :3], ML[:, 3:]
        # stresses: sigma_ij = A_ij,k u_k,X + B_ij,k t_k, t = -s (normalised stiffness)
        Q, R, T = self._blocks
        t = voigt_to_tensor(self._C / self._scale)
        i, j = np.array(VOIGT).T
        CX = t[i, j, :, 0]                      # (6, 3): C_ijkX
        CY = t[i, j, :, 1]                      # (6, 3): C_ijkY
        Tinv_RT = np.linalg.solve(T, R.T)
        A = CX - CY @ Tinv_RT
        B = np.linalg.solve(T, CY.T).T          # C_ijmY T^-1_mk (T symmetric)
        stress_local = A @ L - B
        stress_hilbert = A @ M
        out = []
        for a in (L / self._scale, M / self._scale, stress_local, stress_hilbert):
            a = np.array(a, dtype=float) + 0.0          # no signed zeros
            a.flags.writeable = False
            out.append(a)
        return SurfaceResponse(c=c, rayleigh_speed=self.rayleigh_speed(),
                               slope_local=out[0], slope_hilbert=out[1],
                               stress_local=out[2], stress_hilbert=out[3])

    # ------------------------------------------------------------------ contact.Material
    def surface_constants(self, c) -> SurfaceConstants:
        """The constants of the contact equation at the relative speed ``c``
        (:class:`contact.Material`): N11, N12, N21, N22 and the couplings M12, M21, M22 of
        :class:`contact.SurfaceConstants`, from :meth:`surface_response`
        (:meth:`SurfaceResponse.surface_constants`); ``eta_product``, ``eta_sum`` and
        ``rayleigh_denominator`` None.  Memoised per speed (the material is immutable): the
        last :data:`CONSTANTS_CACHE_SIZE` speeds asked.

        Parameters
        ----------
        c : float
            Relative speed V / sqrt(C66 / rho), 0 <= c < c_R.

        Returns
        -------
        contact.SurfaceConstants

        Raises
        ------
        SpeedError
            c negative, not finite, or not below the Rayleigh speed.

        References
        ----------
        Stroh (1962); Ting (1996), ch. 7 and 12 (module docstring).

        Examples
        --------
        A ply turned by 30 degrees about Z couples p and q (M12 != 0); without friction the
        contact equation is still b = N11, a = 0:

        >>> import contact
        >>> from scipy.spatial.transform import Rotation
        >>> ply = contact.Anisotropic.from_engineering(140.0, 10.0, 10.0, 0.3, 0.3, 0.45,
        ...                                            5.0, 5.0, 3.4)
        >>> sc = ply.rotated(Rotation.from_euler("z", 30, degrees=True)).surface_constants(0.0)
        >>> sc.M12 != 0.0, sc.equation_coefficients(0.0) == (0.0, sc.N11)
        (True, True)
        """
        c = check_finite("relative speed c", c, SpeedError)
        key = ("constants", c)
        sc = self._cache.get(key)
        if sc is None:
            sc = self.surface_response(c).surface_constants()
            speeds = [k for k in self._cache if isinstance(k, tuple)]
            for old in speeds[:len(speeds) - CONSTANTS_CACHE_SIZE + 1]:
                del self._cache[old]
            self._cache[key] = sc
        return sc

    def half_space_modes(self, c):
        """The modes of the half-space at the relative speed ``c``, 0 <= c < c_R, for the
        field under the surface (:class:`contact.Material`, :class:`contact.MaterialModes`):
        the three decaying modes of the Stroh matrix, through Stroh's modal vectors, whose
        combination of the Cauchy transforms of the tractions gives the stresses at points
        (X, Y), Y < 0 (:mod:`contact.stroh_modes`).

        Parameters
        ----------
        c : float
            Relative speed V / sqrt(C66 / rho), 0 <= c < c_R.

        Returns
        -------
        contact.MaterialModes

        References
        ----------
        Stroh, J. Math. Phys. 41 (1962) 77-103; Ting (1996), ch. 5 and 12.
        """
        return stroh_modes(self, c)


# --------------------------------------------------------------------------
# checks
# --------------------------------------------------------------------------
def _check_positive(name: str, value) -> float:
    v = check_finite(name, value, MaterialError)
    if not v > 0.0:
        raise MaterialError(f"{name} must be > 0, got {v!r}")
    return v


def _label(a: int, b: int) -> str:
    names = ("XX", "YY", "ZZ", "YZ", "ZX", "XY")
    return f"C[{a}, {b}] (C{a + 1}{b + 1}, {names[a]}-{names[b]})"


def _check_stiffness(C) -> np.ndarray:
    """C as a fresh symmetric float (6, 6) array, or MaterialError saying what is wrong."""
    arr = real_array("stiffness C", C, MaterialError, "a 6x6 matrix of real numbers (Voigt "
                     "order XX, YY, ZZ, YZ, ZX, XY)")
    if arr.shape != (6, 6):
        raise MaterialError(f"stiffness C must be a 6x6 matrix (Voigt order XX, YY, ZZ, YZ, "
                            f"ZX, XY), got an array of shape {arr.shape}")
    bad = np.argwhere(~np.isfinite(arr))
    if bad.size:
        a, b = bad[0]
        raise MaterialError(f"stiffness C must be finite, got {float(arr[a, b])!r} at "
                            f"{_label(a, b)} ({len(bad)} entries not finite)")
    arr = np.array(arr, dtype=float)
    scale = np.abs(arr).max()
    asym = np.abs(arr - arr.T)
    if asym.max() > SYMMETRY_TOLERANCE * scale:
        a, b = np.unravel_index(np.argmax(asym), asym.shape)
        raise MaterialError(
            f"stiffness C must be symmetric, got {_label(a, b)} = {float(arr[a, b])!r} but "
            f"{_label(b, a)} = {float(arr[b, a])!r} (allowed: C[i, j] = C[j, i], to "
            f"{SYMMETRY_TOLERANCE:g} of max|C| = {float(scale)!r})")
    arr = 0.5 * (arr + arr.T)
    w, v = np.linalg.eigh(arr)
    if not w[0] > DEFINITENESS_TOLERANCE * max(w[-1], 0.0):
        vec = np.round(v[:, 0] / np.abs(v[:, 0]).max(), 6)
        raise MaterialError(
            f"stiffness C must be positive definite (positive strain energy for every "
            f"strain), got smallest eigenvalue {float(w[0])!r} (largest {float(w[-1])!r}; "
            f"strain of zero or negative energy, Voigt XX..XY: {vec.tolist()}); allowed: "
            f"every eigenvalue > "
            f"{DEFINITENESS_TOLERANCE:g} x the largest")
    return arr


def _check_rotation(rotation) -> np.ndarray:
    """A proper rotation as a float (3, 3) array, or MaterialError."""
    if hasattr(rotation, "as_matrix") and callable(rotation.as_matrix):
        R = np.asarray(rotation.as_matrix(), dtype=float)
        if R.shape != (3, 3):
            raise MaterialError(f"rotation must be a single rotation, got a "
                                f"{type(rotation).__name__} of {len(R)} rotations")
    else:
        R = real_array("rotation", rotation, MaterialError,
                       "a 3x3 rotation matrix or a scipy.spatial.transform.Rotation")
        if R.shape != (3, 3):
            raise MaterialError(f"rotation must be a 3x3 rotation matrix (or a "
                                f"scipy.spatial.transform.Rotation), got shape {R.shape}")
        if not np.all(np.isfinite(R)):
            raise MaterialError(f"rotation must be finite, got {R.tolist()}")
    err = np.abs(R.T @ R - np.eye(3)).max()
    if not err <= ROTATION_TOLERANCE:
        raise MaterialError(
            f"rotation must be orthogonal (R^T R = I), got |R^T R - I| = {err:.3g} "
            f"(allowed: {ROTATION_TOLERANCE:g}); build it with "
            f"scipy.spatial.transform.Rotation")
    det = float(np.linalg.det(R))
    if det < 0.0:
        raise MaterialError(
            f"rotation must be a proper rotation (det R = +1), got a reflection "
            f"(det R = {det:.15g}); allowed: det R = +1 (to mirror a material, rotate its "
            f"stiffness by a proper rotation instead or give C itself)")
    return R


# --------------------------------------------------------------------------
# the numerical core (stiffnesses normalised by C66: rho V^2 / C66 = c^2)
# --------------------------------------------------------------------------
def _plane_blocks(t):
    """Q_ik = C_iXkX, R_ik = C_iXkY, T_ik = C_iYkY of a stiffness tensor."""
    return (np.ascontiguousarray(t[:, 0, :, 0]), np.ascontiguousarray(t[:, 0, :, 1]),
            np.ascontiguousarray(t[:, 1, :, 1]))


def _stroh_matrix(Q, R, T, rv2) -> np.ndarray:
    """N = [[-T^-1 R^T, T^-1], [R T^-1 R^T - Q + rv2 I, -R T^-1]] (rv2 = rho V^2)."""
    Tinv = np.linalg.inv(T)
    Tinv = 0.5 * (Tinv + Tinv.T)
    N1 = -Tinv @ R.T
    N3 = R @ Tinv @ R.T - Q + rv2 * np.eye(3)
    return np.block([[N1, Tinv], [0.5 * (N3 + N3.T), N1.T]])


def _sign_matrix(N) -> tuple[np.ndarray, bool]:
    """S_hat = -i sign(i N), real with S_hat^2 = -I, and whether the iteration converged.

    Newton's iteration for the sign of i N written in real arithmetic,
    S <- (mu S - (mu S)^-1) / 2, S_0 = N, with the determinantal scaling
    mu = |det S|^(-1/6) while far from convergence (Higham 2008, ch. 5); stopped when the
    relative change is at rounding level or stops decreasing.
    """
    S = np.array(N, dtype=float)
    scale = True
    prev = math.inf
    for _ in range(_SIGN_MAX_ITERATIONS):
        inv = np.linalg.inv(S)
        if scale:
            det = abs(np.linalg.det(S))
            mu = det ** (-1.0 / 6.0) if det > 0.0 and math.isfinite(det) else 1.0
        else:
            mu = 1.0
        new = 0.5 * (mu * S - inv / mu)
        change = np.abs(new - S).sum(axis=0).max() / np.abs(new).sum(axis=0).max()
        S = new
        if change < 1e-2:
            scale = False
        if change <= 1e-14 or (change < 1e-9 and change >= prev):
            return S, True
        prev = change
    return S, bool(prev < 1e-9)


def _impedance_eigenvalue(S) -> float:
    """The smallest eigenvalue of -S3 (the Barnett-Lothe tensor L_BL, symmetric)."""
    L = -S[3:, :3]
    return float(np.linalg.eigvalsh(0.5 * (L + L.T))[0])


def _limiting_speed(Q, R, T) -> float:
    """c_L: sqrt of min over real p of lambda_min(Q + p (R + R^T) + p^2 T) (C66 = 1)."""
    from scipy.optimize import minimize_scalar

    P = R + R.T

    def g(theta):
        cs, sn = np.cos(theta), np.sin(theta)
        G = (np.multiply.outer(cs * cs, Q) + np.multiply.outer(cs * sn, P)
             + np.multiply.outer(sn * sn, T))
        return np.linalg.eigvalsh(G)[..., 0] / (cs * cs)

    theta = np.linspace(-0.5 * np.pi, 0.5 * np.pi, _LIMIT_SAMPLES + 1)[1:-1]
    values = g(theta)
    best = float(values.min())
    inner = np.flatnonzero((values[1:-1] <= values[:-2]) & (values[1:-1] <= values[2:])) + 1
    candidates = [i for i in inner if values[i] <= 1.01 * best]
    if int(np.argmin(values)) not in inner:
        candidates.append(int(np.argmin(values)))
    for i in candidates:
        lo = theta[max(i - 1, 0)]
        hi = theta[min(i + 1, len(theta) - 1)]
        res = minimize_scalar(lambda x: float(g(np.array(x))), bounds=(lo, hi),
                              method="bounded", options={"xatol": 1e-14})
        best = min(best, float(res.fun))
    return math.sqrt(best)
