"""The stress field under the surface of the moving half-space.

:func:`half_space_stress` and :meth:`contact.ContactResult.stress` take any material
(:class:`contact.Material`): its ``half_space_modes(c)`` (:class:`contact.MaterialModes`)
says at which complex points the Cauchy transforms of the tractions are needed and how the
stresses follow from them; :func:`half_space_modes`, :func:`modes_points` and
:func:`modes_stresses` (and :func:`modes_out_of_plane`, for modes that give sigma_zz,
sigma_yz, sigma_xz) check what it returns.  :class:`HalfSpaceModes` is the orthotropic
field, derived below; :mod:`contact.stroh_modes` is the anisotropic one (generalised plane
strain, with the out-of-plane stresses and so von Mises and Tresca).

Conventions as for the surface (:mod:`contact.constants`): the half-space is Y < 0 in the
frame moving with the punch, the tractions on Y = 0 are sigma_YY = -p, sigma_XY = -q, and
C(z) = (1/pi) int p(t) / (t - z) dt is the Cauchy transform of a traction.

Derivation
----------
A Fourier component exp(i k X + |k| eta Y) of the displacements solves the steady equations of
motion (Zhou, Lee & Jang 2014, eqs. (2.4)-(3.1))

    C11' u_XX + C33 u_YY + K v_XY = 0,    K u_XY + C33' v_XX + C22 v_YY = 0,
    C11' = C11 - C33 c^2,  C33' = C33 (1 - c^2),  K = C12 + C33,

when eta is a root of eq. (3.1); it decays as Y -> -inf for the two roots eta_1, eta_2 with
Re eta > 0.  For k > 0 the modal vector is e(eta) = e1 + w e2, the null vectors of the two
rows of the modal equations,

    e1 = (K eta, i (C33 eta^2 - C11')),    e2 = (C22 eta^2 - C33', -i K eta),

(parallel at a root; each vanishes at one root when K = 0, so w in {1, -1, i} is chosen to
keep e away from zero at both), and gives the stresses
(sigma_XX, sigma_YY, sigma_XY) = k b (i S_xx(eta), i S_yy(eta), S_xy(eta)) exp(i k z) with
z = X - i eta Y and S = S^(1) + w S^(2), cubic polynomials in eta:

    S_xx^(1) = C12 C33 eta^3 + (C11 K - C12 C11') eta,
    S_yy^(1) = C22 C33 eta^3 + (C12 K - C22 C11') eta,
    S_xy^(1) = C12 C33 eta^2 + C33 C11',
    S_xx^(2) = (C11 C22 - C12 K) eta^2 - C11 C33',
    S_yy^(2) = -C22 C33 eta^2 - C12 C33',
    S_xy^(2) = C22 C33 eta^3 + C33 (K - C33') eta.

The two traction conditions fix the amplitudes:

    k b_1 = ( i S_xy(eta_2) p^ + S_yy(eta_2) q^) / Delta,
    k b_2 = -(i S_xy(eta_1) p^ + S_yy(eta_1) q^) / Delta,
    Delta = S_yy(eta_1) S_xy(eta_2) - S_yy(eta_2) S_xy(eta_1).

The k < 0 half is the complex conjugate (the field is real), and for Im z > 0
(1/2 pi) int_0^inf f^(k) exp(i k z) dk = C_f(z) / (2 i), so, with A_c,f(a, b) = S_c(a) g_f(b),
g_p = i S_xy, g_q = S_yy and t_c = 1, 1, -i for c = XX, YY, XY,

    sigma_c(X, Y) = Re{ t_c sum_{f = p, q} [A_c,f(eta_1, eta_2) C_f(z_1)
                                           - A_c,f(eta_2, eta_1) C_f(z_2)] / Delta },
    z_j = X - i eta_j Y.

On Y = 0 this gives sigma_YY = -p, sigma_XY = -q and sigma_XX = N21 p + N22 Hc[q] (the
surface constants; checked in the tests).

Repeated roots.  With eta_{1,2} = eta_m +- delta, numerator and Delta are antisymmetric in
the two roots; dividing both by eta_1 - eta_2 = 2 delta,

    [A(e1, e2) C(z1) - A(e2, e1) C(z2)] / Delta
        = [A_s D + 2 A_a' E] / Delta',
    A_s = (A(e1, e2) + A(e2, e1)) / 2,    A_a' = (A(e1, e2) - A(e2, e1)) / (2 (e1 - e2)),
    Delta' = Delta / (e1 - e2),
    D = (C(z1) - C(z2)) / (e1 - e2),    E = (C(z1) + C(z2)) / 2,

where A_a' and Delta' are polynomial divided differences (g(b) f[a, b] - f(b) g[a, b] for
f(a) g(b) - f(b) g(a), no cancellation).  Everything is even in delta, so it depends on the
roots only through eta_m = S / 2 and delta^2 = S^2 / 4 - P (S = eta_1 + eta_2,
P = eta_1 eta_2 from the coefficients of eq. (3.1), well conditioned where the roots
themselves are not).  D and E are even analytic functions of delta; when
|delta| < h = 1e-3 eta_m (the isotropic static case has delta = 0: D -> -i Y C'(z)) they are
interpolated linearly in delta^2 between delta = h and delta = i h (delta^2 = +-h^2, so real
and complex pairs are treated alike; error ~ (h / eta_m)^4, rounding ~ eps eta_m / h, both
about 1e-12 relative), so the field is smooth through the repeated root.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .constants import check_speed, check_subrayleigh
from .errors import (CauchyTransformError, ContactInputError, FrictionError, MaterialError,
                     StressPointError, UnboundedStressError, check_finite, real_array)
from .protocol import call, check_material, describe_call

__all__ = ["HalfSpaceModes", "StressField", "StressExtrema", "Extremum", "half_space_stress",
           "half_space_modes", "modes_points", "modes_stresses", "modes_out_of_plane",
           "field_extrema", "EXTREMUM_QUANTITIES",
           "StressPointError", "UnboundedStressError", "CauchyTransformError"]

#: |delta| below this fraction of eta_m: the repeated-root form (interpolation in delta^2)
_NEAR = 1e-3


@dataclass(frozen=True)
class StressField:
    """Stresses at points (X, Y) of the half-space (tension positive).

    Returned by :meth:`contact.ContactResult.stress` and :func:`half_space_stress`.

    Attributes
    ----------
    X, Y : ndarray
        The points (Y <= 0), broadcast to one shape.
    sigma_xx, sigma_yy, sigma_xy : ndarray
        The in-plane stress components at the points.
    sigma_zz, sigma_yz, sigma_xz : ndarray or None
        The out-of-plane components (generalised plane strain, Z along the punch's
        generators), where the material's modes give them (an ``out_of_plane`` method,
        :class:`contact.MaterialModes`: :class:`contact.anisotropic.Anisotropic`); None for
        the plane model (:class:`contact.Orthotropic`, which has no C13, C23).
    von_mises : ndarray
        sqrt(((s_xx - s_yy)^2 + (s_yy - s_zz)^2 + (s_zz - s_xx)^2) / 2
        + 3 (s_xy^2 + s_yz^2 + s_xz^2)); needs the out-of-plane components.
    tresca : ndarray
        (s_1 - s_3) / 2, the largest shear stress over all planes, from the three principal
        stresses; needs the out-of-plane components.
    principal_3d : (ndarray, ndarray, ndarray)
        s_1 >= s_2 >= s_3, the principal stresses of the full tensor; needs the
        out-of-plane components.
    has_out_of_plane : bool
        Whether sigma_zz, sigma_yz, sigma_xz are known.
    mean : ndarray
        (sigma_xx + sigma_yy) / 2.
    max_shear : ndarray
        In-plane maximum shear stress, the radius of Mohr's circle.
    principal : (ndarray, ndarray)
        sigma_1 >= sigma_2.
    max_tension : ndarray
        sigma_1.
    principal_angle : ndarray
        Angle (radians, from +X) of the direction of sigma_1.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (2.2)-(3.1) (the field is derived in the
    module docstring); McEwen (1949), Johnson, Contact Mechanics (1985), Sec. 7.1 (the
    isotropic Hertz field).

    Examples
    --------
    Under a Hertz contact, on the axis at depth a: sigma_yy = -p0 / sqrt(2) and
    sigma_xx = -p0 (3 / sqrt(2) - 2) (McEwen 1949):

    >>> import math, contact
    >>> r = contact.solve(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0),
    ...                   load=0.01, speed=0.0)
    >>> a, p0 = r.half_width, float(r.pressure(0.0))
    >>> f = r.stress(0.0, -a)
    >>> type(f).__name__, round(float(f.sigma_yy) / p0 * math.sqrt(2.0), 9)
    ('StressField', -1.0)
    >>> round(float(f.sigma_xx) / p0, 9) == round(2.0 - 3.0 / math.sqrt(2.0), 9)
    True
    >>> f.sigma_zz is None              # the plane model gives no out-of-plane stresses
    True

    Flamant's line load P = 1 on an isotropic material with its out-of-plane stiffnesses
    (:class:`contact.Anisotropic`): on the axis at depth 2 the only stresses are
    sigma_yy = -1/pi and sigma_zz = nu sigma_yy, so von Mises is sqrt(1 - nu + nu^2) / pi
    and Tresca 1 / (2 pi):

    >>> import numpy as np
    >>> g = contact.half_space_stress(contact.Anisotropic.isotropic(1.0, 0.25), 0.0, 0.0,
    ...                               -2.0, lambda z: -1.0 / (np.pi * z))
    >>> round(float(g.sigma_zz * np.pi), 12), round(float(g.tresca * 2 * np.pi), 12)
    (-0.25, 1.0)
    >>> round(float(g.von_mises * np.pi) ** 2, 12)       # 1 - nu + nu^2
    0.8125
    """
    X: np.ndarray
    Y: np.ndarray
    sigma_xx: np.ndarray
    sigma_yy: np.ndarray
    sigma_xy: np.ndarray
    sigma_zz: np.ndarray | None = None
    sigma_yz: np.ndarray | None = None
    sigma_xz: np.ndarray | None = None

    @property
    def has_out_of_plane(self) -> bool:
        """Whether the out-of-plane components are known (the material's modes give them)."""
        return self.sigma_zz is not None

    def _need_out_of_plane(self, what: str) -> None:
        if not self.has_out_of_plane:
            raise MaterialError(
                f"{what} needs the out-of-plane stresses sigma_zz, sigma_yz, sigma_xz, which "
                f"this material's modes do not give (the plane model contact.Orthotropic has "
                f"no C13, C23; allowed: a material whose half_space_modes(c) has "
                f"out_of_plane, e.g. contact.anisotropic.Anisotropic); the in-plane "
                f"max_shear and max_tension are available")

    @property
    def von_mises(self) -> np.ndarray:
        """The von Mises equivalent stress
        sqrt(((s_xx - s_yy)^2 + (s_yy - s_zz)^2 + (s_zz - s_xx)^2) / 2
        + 3 (s_xy^2 + s_yz^2 + s_xz^2)), the yield criterion of von Mises (Johnson 1985,
        Sec. 6.1).

        Raises
        ------
        MaterialError
            The out-of-plane components are not known (:attr:`sigma_zz` is None).
        """
        self._need_out_of_plane("von_mises")
        sxx, syy, szz = self.sigma_xx, self.sigma_yy, self.sigma_zz
        return np.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2)
                       + 3.0 * (self.sigma_xy ** 2 + self.sigma_yz ** 2 + self.sigma_xz ** 2))

    @property
    def principal_3d(self) -> tuple:
        """(s_1, s_2, s_3), s_1 >= s_2 >= s_3: the eigenvalues of the full stress tensor.

        Raises
        ------
        MaterialError
            The out-of-plane components are not known (:attr:`sigma_zz` is None).
        """
        self._need_out_of_plane("principal_3d")
        S = np.stack([np.stack([self.sigma_xx, self.sigma_xy, self.sigma_xz], -1),
                      np.stack([self.sigma_xy, self.sigma_yy, self.sigma_yz], -1),
                      np.stack([self.sigma_xz, self.sigma_yz, self.sigma_zz], -1)], -2)
        w = np.linalg.eigvalsh(S)
        return w[..., 2], w[..., 1], w[..., 0]

    @property
    def tresca(self) -> np.ndarray:
        """(s_1 - s_3) / 2, the largest shear stress over all planes (the yield criterion of
        Tresca; Johnson 1985, Sec. 6.1), from the principal stresses of the full tensor.

        Raises
        ------
        MaterialError
            The out-of-plane components are not known (:attr:`sigma_zz` is None).
        """
        self._need_out_of_plane("tresca")
        s1, _, s3 = self.principal_3d
        return 0.5 * (s1 - s3)

    @property
    def mean(self) -> np.ndarray:
        """(sigma_xx + sigma_yy) / 2, the centre of Mohr's circle."""
        return 0.5 * (self.sigma_xx + self.sigma_yy)

    @property
    def max_shear(self) -> np.ndarray:
        """In-plane maximum shear stress, the radius of Mohr's circle,
        sqrt(((sigma_xx - sigma_yy) / 2)^2 + sigma_xy^2)."""
        return np.hypot(0.5 * (self.sigma_xx - self.sigma_yy), self.sigma_xy)

    @property
    def principal(self) -> tuple:
        """(sigma_1, sigma_2), the in-plane principal stresses, sigma_1 >= sigma_2."""
        m, r = self.mean, self.max_shear
        return m + r, m - r

    @property
    def max_tension(self) -> np.ndarray:
        """The largest principal stress sigma_1 (positive where the material is in tension)."""
        return self.mean + self.max_shear

    @property
    def principal_angle(self) -> np.ndarray:
        """Angle (radians, from +X) of the direction of sigma_1."""
        return 0.5 * np.arctan2(2.0 * self.sigma_xy, self.sigma_xx - self.sigma_yy)


def _modal_forms(material, c: float) -> tuple:
    """Coefficients (of eta^0..eta^3) of (S_xx, S_yy, S_xy) for the two null vectors of the
    modal equations, (u, v) = (K eta, i (C33 eta^2 - C11')) (first row) and
    (C22 eta^2 - C33', -i K eta) (second row); module docstring."""
    C11, C12, C22, C33 = material.C11, material.C12, material.C22, material.C33
    C11p = C11 - C33 * c * c
    C33p = C33 * (1.0 - c * c)
    K = C12 + C33
    first = {"xx": np.array([0.0, C11 * K - C12 * C11p, 0.0, C12 * C33]),
             "yy": np.array([0.0, C12 * K - C22 * C11p, 0.0, C22 * C33]),
             "xy": np.array([C33 * C11p, 0.0, C12 * C33, 0.0])}
    second = {"xx": np.array([-C11 * C33p, 0.0, C11 * C22 - C12 * K, 0.0]),
              "yy": np.array([-C12 * C33p, 0.0, -C22 * C33, 0.0]),
              "xy": np.array([0.0, C33 * (K - C33p), 0.0, C33 * C22])}
    vec1 = (np.array([0.0, K, 0.0, 0.0]), 1j * np.array([-C11p, 0.0, C33, 0.0]))
    vec2 = (np.array([-C33p, 0.0, C22, 0.0]), -1j * np.array([0.0, K, 0.0, 0.0]))
    return first, second, vec1, vec2


def _stress_polynomials(material, c: float) -> dict:
    """S_xx, S_yy, S_xy of the modal vector e1 + w e2, w in {1, -1, i} chosen so that it is
    farthest from vanishing at both roots.  e1 and e2 are parallel at a root (both null
    vectors of a rank-one matrix), and each vanishes at one root when C12 + C33 = 0; their
    ratio r is real for real roots (w = i: |1 + i r| >= 1) and conjugate over a complex
    pair (w = +-1 serves both)."""
    first, second, v1, v2 = _modal_forms(material, c)
    roots = material.decaying_roots(c)

    def quality(w):
        q = np.inf
        for eta in roots:
            e1 = np.array([_poly(v1[0], eta), _poly(v1[1], eta)])
            e2 = np.array([_poly(v2[0], eta), _poly(v2[1], eta)])
            size = np.linalg.norm(e1) + np.linalg.norm(e2)
            q = min(q, np.linalg.norm(e1 + w * e2) / size if size > 0 else 0.0)
        return q
    w = max((1.0, -1.0, 1j), key=quality)
    return {k: first[k] + w * second[k] for k in first}


def _poly(coef, x):
    return coef[0] + x * (coef[1] + x * (coef[2] + x * coef[3]))


def _divided(coef, em, d2):
    """f[a, b] = (f(a) - f(b)) / (a - b) of a cubic at a, b = em +- delta, from delta^2."""
    return coef[1] + 2.0 * em * coef[2] + (3.0 * em * em + d2) * coef[3]


@dataclass(frozen=True)
class HalfSpaceModes:
    """The two decaying modes of the moving orthotropic half-space, combined into the
    coefficients of the stress field (module docstring).

    sigma_c = Re{ sum_f (KD[c, f] D_f + KE[c, f] E_f) } with D_f, E_f the divided difference
    and the mean of the Cauchy transform C_f of traction f (p or q) at z_1, z_2.

    Attributes
    ----------
    eta_mid : float
        (eta_1 + eta_2) / 2 > 0.
    delta_sq : float
        ((eta_1 - eta_2) / 2)^2: > 0 for two real roots, < 0 for a complex pair, ~0 repeated.
    KD, KE : ndarray, complex, shape (3, 2)
        Rows XX, YY, XY; columns p, q.
    """
    eta_mid: float
    delta_sq: float
    KD: np.ndarray
    KE: np.ndarray

    @classmethod
    def of(cls, material, c: float) -> "HalfSpaceModes":
        """The modes of an orthotropic material (:class:`contact.Orthotropic`) at relative
        speed c (0 <= c < c_R), from its stiffnesses and the sum and product of its decaying
        roots (:meth:`contact.Orthotropic.root_symmetric_functions`).

        Raises
        ------
        SpeedError
            c outside [0, c_R).
        MaterialError
            A double root with two independent modal vectors (C12 + C33 = 0 and
            C11'/C33 = C33'/C22), where the form used here does not apply.
        """
        c = check_speed(c, material.rayleigh_speed())
        eta_product, eta_sum = material.root_symmetric_functions(c)
        em = 0.5 * eta_sum
        d2 = 0.25 * eta_sum ** 2 - eta_product
        delta = np.sqrt(complex(d2))
        a, b = em + delta, em - delta
        S = _stress_polynomials(material, c)
        g = {"p": 1j * S["xy"], "q": S["yy"]}          # the traction rows: i S_xy p^, S_yy q^
        dyy, dxy = _divided(S["yy"], em, d2), _divided(S["xy"], em, d2)
        delta_p = _poly(S["xy"], b) * dyy - _poly(S["yy"], b) * dxy
        size = abs(_poly(S["xy"], b) * dyy) + abs(_poly(S["yy"], b) * dxy)
        if not abs(delta_p) > 1e-10 * size:
            raise MaterialError(
                "the two decaying modes coincide with independent modal vectors (C12 + C33 = 0 "
                "and C11' / C33 = C33' / C22: u and v decouple with one wave speed); the "
                "field is then a sum of two scalar half-space problems, not implemented here")
        KD = np.zeros((3, 2), dtype=complex)
        KE = np.zeros((3, 2), dtype=complex)
        for i, (comp, t) in enumerate((("xx", 1.0), ("yy", 1.0), ("xy", -1j))):
            f = S[comp]
            fa, fb, fab = _poly(f, a), _poly(f, b), _divided(f, em, d2)
            for j, key in enumerate(("p", "q")):
                gc = g[key]
                ga, gb, gab = _poly(gc, a), _poly(gc, b), _divided(gc, em, d2)
                A_s = 0.5 * (fa * gb + fb * ga)
                A_a = 0.5 * (gb * fab - fb * gab)
                KD[i, j] = t * A_s / delta_p
                KE[i, j] = t * 2.0 * A_a / delta_p
        KD.flags.writeable = False
        KE.flags.writeable = False
        return cls(eta_mid=em, delta_sq=d2, KD=KD, KE=KE)

    @property
    def repeated(self) -> bool:
        """Whether the roots are within the repeated-root tolerance of each other."""
        return abs(self.delta_sq) < (_NEAR * self.eta_mid) ** 2

    def _etas(self):
        """The root pairs (eta_m + d, eta_m - d) whose z the Cauchy transforms are wanted at:
        the roots themselves, or eta_m +- h and eta_m +- i h near a repeated root."""
        if self.repeated:
            h = _NEAR * self.eta_mid
            return ((self.eta_mid + h, self.eta_mid - h, h),
                    (self.eta_mid + 1j * h, self.eta_mid - 1j * h, 1j * h))
        delta = np.sqrt(complex(self.delta_sq))
        return ((self.eta_mid + delta, self.eta_mid - delta, delta),)

    def points(self, X, Y) -> list:
        """The complex points z = X - i eta Y at which the Cauchy transforms are needed
        (two or four arrays of the shape of X, Y)."""
        out = []
        for e1, e2, _ in self._etas():
            out += [X - 1j * e1 * Y, X - 1j * e2 * Y]
        return out

    def stresses(self, Cp, Cq=None, q_ratio=None):
        """sigma_XX, sigma_YY, sigma_XY from the Cauchy transforms at :meth:`points`.

        Cp : list of arrays, C_p at each of the points; Cq : the same for q, or None; and
        ``q_ratio``: q = q_ratio p (then Cq is not needed).
        """
        KD, KE = self.KD, self.KE
        if Cq is None:
            r = 0.0 if q_ratio is None else q_ratio
            kd = KD[:, 0] + r * KD[:, 1]
            ke = KE[:, 0] + r * KE[:, 1]
            D, E = self._DE(Cp)
            return tuple((kd[i] * D + ke[i] * E).real for i in range(3))
        Dp, Ep = self._DE(Cp)
        Dq, Eq = self._DE(Cq)
        return tuple((KD[i, 0] * Dp + KE[i, 0] * Ep + KD[i, 1] * Dq + KE[i, 1] * Eq).real
                     for i in range(3))

    def _DE(self, C):
        etas = self._etas()
        if len(etas) == 1:
            (_, _, delta), = etas
            return (C[0] - C[1]) / (2.0 * delta), 0.5 * (C[0] + C[1])
        (_, _, h), _ = etas
        D1, E1 = (C[0] - C[1]) / (2.0 * h), 0.5 * (C[0] + C[1])          # delta^2 = h^2
        D2, E2 = (C[2] - C[3]) / (2j * h), 0.5 * (C[2] + C[3])           # delta^2 = -h^2
        w = self.delta_sq / (h * h)               # linear in delta^2 through -h^2 and h^2
        return 0.5 * (D1 + D2) + 0.5 * w * (D1 - D2), 0.5 * (E1 + E2) + 0.5 * w * (E1 - E2)


def half_space_modes(material, c):
    """The modes of a material at the relative speed ``c``, for the field under the surface.

    The checked entry to ``material.half_space_modes(c)`` (:class:`contact.Material`), as
    :func:`contact.surface_constants` is to ``material.surface_constants(c)``.

    Parameters
    ----------
    material : Material
        :class:`contact.Orthotropic` or any object with the methods of
        :class:`contact.Material`.
    c : float
        Relative speed, 0 <= c < c_R.

    Returns
    -------
    MaterialModes
        What ``material.half_space_modes(c)`` returned (:class:`HalfSpaceModes` for an
        orthotropic material), once it is seen to have the methods ``points`` and
        ``stresses``; what those return is checked where they are called
        (:func:`modes_points`, :func:`modes_stresses`).

    Raises
    ------
    ContactInputError
        ``material`` lacks the methods of :class:`contact.Material`.
    SpeedError
        ``c`` not a finite number in [0, c_R).
    MaterialError
        ``material.half_space_modes(c)`` raises, or returns an object without the methods
        ``points(X, Y)`` and ``stresses(Cp, Cq, q_ratio)``.

    Warns
    -----
    NearRayleighWarning
        c > 0.99 c_R.
    """
    c, _ = check_subrayleigh(material, c)
    modes = call(material, "half_space_modes", c)
    if not (callable(getattr(modes, "points", None))
            and callable(getattr(modes, "stresses", None))):
        raise MaterialError(
            f"{describe_call(material, 'half_space_modes', c)} must return the half-space's "
            f"modes: an object with the methods points(X, Y) and stresses(Cp, Cq, q_ratio) "
            f"(contact.MaterialModes), got {type(modes).__name__}")
    return modes


def modes_points(modes, X, Y) -> list:
    """``modes.points(X, Y)`` (:class:`contact.MaterialModes`), checked: a list of complex
    arrays of the shape of X and Y (float arrays of one shape, Y < 0), finite, in the upper
    half-plane Im z > 0 where the Cauchy transforms of the tractions are analytic.

    Raises
    ------
    MaterialError
        Anything else, or an exception inside ``points`` (chained), naming ``points`` of
        the modes' class.
    """
    Z = call(modes, "points", X, Y)
    where = f"{type(modes).__name__}.points(X, Y) (the modes of material.half_space_modes(c))"
    if isinstance(Z, np.ndarray) or not isinstance(Z, (list, tuple)) or not Z:
        raise MaterialError(f"{where} must return a non-empty list of complex arrays, one per "
                            f"point set, got {type(Z).__name__}")
    out = []
    for k, z in enumerate(Z):
        z = np.asarray(z)
        if z.shape != X.shape or z.dtype.kind != "c":
            raise MaterialError(
                f"{where} must return complex arrays of the points' shape {X.shape}, got "
                f"entry {k} of shape {z.shape} and dtype {z.dtype}")
        bad = ~(np.isfinite(z) & (z.imag > 0.0))
        if bad.any():
            i = int(np.flatnonzero(bad.ravel())[0])
            raise MaterialError(
                f"{where} must return finite points z with Im z > 0 (where the Cauchy "
                f"transforms of the tractions are analytic), got z = "
                f"{complex(z.ravel()[i])!r} in entry {k} for the point (X, Y) = "
                f"({float(X.ravel()[i])!r}, {float(Y.ravel()[i])!r})")
        out.append(z)
    return out


def modes_stresses(modes, Cp, Cq, q_ratio, X, Y) -> tuple:
    """``modes.stresses(Cp, Cq, q_ratio)`` (:class:`contact.MaterialModes`), checked: three
    real arrays of the shape of X and Y, finite wherever the transforms are.

    Raises
    ------
    MaterialError
        Anything else, or an exception inside ``stresses`` (chained), naming ``stresses``
        of the modes' class and the first point at fault.
    """
    return _checked_triple(modes, "stresses", ("sigma_xx", "sigma_yy", "sigma_xy"), Cp, Cq,
                           q_ratio, X, Y)


def modes_out_of_plane(modes, Cp, Cq, q_ratio, X, Y):
    """``modes.out_of_plane(Cp, Cq, q_ratio)`` (the optional method of
    :class:`contact.MaterialModes`), checked as :func:`modes_stresses`:
    (sigma_zz, sigma_yz, sigma_xz), three real arrays of the shape of X and Y; None when the
    modes have no ``out_of_plane`` (the plane model).

    Raises
    ------
    MaterialError
        What it returns is not three such arrays, or it raises (chained).
    """
    if not callable(getattr(modes, "out_of_plane", None)):
        return None
    return _checked_triple(modes, "out_of_plane", ("sigma_zz", "sigma_yz", "sigma_xz"), Cp,
                           Cq, q_ratio, X, Y)


def _checked_triple(modes, method, names, Cp, Cq, q_ratio, X, Y) -> tuple:
    """``modes.<method>(Cp, Cq, q_ratio)`` as three real arrays of the points' shape, finite
    wherever the transforms are, else MaterialError naming the method and the first point
    at fault."""
    out = call(modes, method, Cp, Cq, q_ratio)
    where = (f"{type(modes).__name__}.{method}(Cp, Cq, q_ratio) (the modes of "
             f"material.half_space_modes(c))")
    if isinstance(out, np.ndarray) or not isinstance(out, (list, tuple)) or len(out) != 3:
        raise MaterialError(f"{where} must return ({', '.join(names)}), three real "
                            f"arrays, got {type(out).__name__}")
    given = np.ones(X.shape, dtype=bool)
    for C in list(Cp) + list(Cq or ()):
        given &= np.isfinite(C)
    checked = []
    for name, v in zip(names, out):
        v = np.asarray(v)
        if v.shape != X.shape or v.dtype.kind not in "fiu":
            raise MaterialError(f"{where} must return real arrays of the points' shape "
                                f"{X.shape}, got {name} of shape {v.shape} and dtype {v.dtype}")
        bad = ~np.isfinite(v) & given
        if bad.any():
            i = int(np.flatnonzero(bad.ravel())[0])
            raise MaterialError(
                f"{where} returned {name} = {float(v.ravel()[i])!r} at the point (X, Y) = "
                f"({float(X.ravel()[i])!r}, {float(Y.ravel()[i])!r}), where the transforms "
                f"are finite (allowed: finite stresses)")
        checked.append(v.astype(float, copy=False))
    return tuple(checked)


def stress_points(X, Y):
    """X, Y as float arrays of one shape; raise StressPointError unless real numbers (not
    text, bools or complex: :func:`contact.errors.real_array`), finite, with Y <= 0."""
    X = real_array("X", X, StressPointError)
    Y = real_array("Y", Y, StressPointError)
    try:
        X, Y = np.broadcast_arrays(X, Y)
    except ValueError as exc:
        raise StressPointError(f"X and Y must be real arrays of broadcastable shapes: {exc}") \
            from None
    if not (np.all(np.isfinite(X)) and np.all(np.isfinite(Y))):
        raise StressPointError("X and Y must be finite (got NaN or inf)")
    if np.any(Y > 0):
        raise StressPointError(
            f"the half-space is Y <= 0; got Y up to {float(np.max(Y))!r} (depth below the "
            f"surface is -Y)")
    return np.array(X), np.array(Y)


def half_space_stress(material, c, X, Y, cauchy_p, cauchy_q=None,
                      q_ratio=None) -> StressField:
    """The stresses at points Y < 0 of the half-space under surface tractions p and q.

    Parameters
    ----------
    material : Material
        :class:`contact.Orthotropic` or any object with the methods of
        :class:`contact.Material` (its ``half_space_modes(c)`` gives the field).
    c : float
        Relative speed of the tractions, 0 <= c < c_R.
    X, Y : array_like
        Points, Y < 0 (broadcast together).
    cauchy_p : callable
        z -> C_p(z) = (1/pi) int p(t) / (t - z) dt at complex z with Im z > 0.
    cauchy_q : callable, optional
        The same for q (sigma_XY(X, 0) = -q).
    q_ratio : float, optional
        q = q_ratio p (instead of ``cauchy_q``; Coulomb friction q = mu_f p).

    Returns
    -------
    StressField

    Raises
    ------
    StressPointError
        Points not real numbers or not finite, or Y >= 0 (the surface itself is the
        traction: see :meth:`contact.ContactResult.stress`).
    ContactInputError
        ``material`` without the methods of :class:`contact.Material`; both ``cauchy_q``
        and ``q_ratio`` given.
    MaterialError
        The material's ``half_space_modes(c)``, or the ``points`` or ``stresses`` of what it
        returns, give what :class:`contact.MaterialModes` does not allow (or raise):
        :func:`half_space_modes`, :func:`modes_points`, :func:`modes_stresses`.
    SpeedError, FrictionError
        ``c`` outside [0, c_R) or not a number; ``q_ratio`` not a finite number.
    CauchyTransformError
        ``cauchy_p`` or ``cauchy_q`` not callable, raising (any exception, chained as the
        cause; the message names the callable and the points), or returning values of the
        wrong shape (it is called with complex arrays of the points' shape), not complex, or
        not finite.  A transform must return complex values: at Im z > 0 the transform of a
        traction is complex (its imaginary part is the traction's Poisson integral), and a
        real array there has lost that part (``lambda z: -1 / (np.pi * z.real)`` gives
        sigma_yy = -0.159 for Flamant's -0.637), so a real dtype is refused whatever its
        values.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eqs. (2.4)-(3.1) (equations of motion and
    characteristic roots; the stresses are derived in the module docstring).  Flamant's
    line load: Johnson, Contact Mechanics (1985), eqs. (2.15)-(2.19).

    Examples
    --------
    A Flamant line load P = 1 at the origin, C_p(z) = -P / (pi z), isotropic and static: on
    the axis sigma_yy = -2P / (pi depth), sigma_xx = sigma_xy = 0:

    >>> import numpy as np, contact
    >>> f = contact.half_space_stress(contact.Isotropic(1.0, 0.3), 0.0, 0.0, -2.0,
    ...                               lambda z: -1.0 / (np.pi * z))
    >>> round(float(f.sigma_yy * np.pi), 9)     # -(2P/pi) / depth
    -1.0
    >>> bool(abs(f.sigma_xx) < 1e-12 and abs(f.sigma_xy) < 1e-12)
    True
    """
    check_material(material)
    X, Y = stress_points(X, Y)
    if np.any(Y == 0):
        raise StressPointError("Y must be < 0 here (on Y = 0 the stresses are the tractions)")
    for name, fn in (("cauchy_p", cauchy_p), ("cauchy_q", cauchy_q)):
        if not callable(fn) and not (name == "cauchy_q" and fn is None):
            raise CauchyTransformError(
                f"{name} must be a vectorised callable z -> C(z) = (1/pi) int f(t) / (t - z) "
                f"dt at complex z, Im z > 0, got {type(fn).__name__}")
    if cauchy_q is not None and q_ratio is not None:
        raise ContactInputError("give cauchy_q or q_ratio, not both")
    if q_ratio is not None:
        q_ratio = check_finite("q_ratio", q_ratio, FrictionError)
    modes = half_space_modes(material, c)
    Z = modes_points(modes, X, Y)
    Cp = [_transform(cauchy_p, "cauchy_p", z, X, Y) for z in Z]
    Cq = None if cauchy_q is None else [_transform(cauchy_q, "cauchy_q", z, X, Y) for z in Z]
    sxx, syy, sxy = modes_stresses(modes, Cp, Cq, q_ratio, X, Y)
    out_of_plane = modes_out_of_plane(modes, Cp, Cq, q_ratio, X, Y) or (None, None, None)
    return StressField(X, Y, sxx, syy, sxy, *out_of_plane)


def _transform(fn, name, z, X, Y) -> np.ndarray:
    """``fn(z)``, a user's Cauchy transform at the complex points z (of the shape of X, Y),
    as a complex array of that shape with finite values, else CauchyTransformError naming
    ``name`` and where it was called: any exception inside it (chained), a result of
    another shape, of a real dtype (half_space_stress: the transform is complex at
    Im z > 0), or not finite."""
    try:
        out = np.asarray(fn(z))
    except Exception as exc:
        raise CauchyTransformError(f"{name} raised {type(exc).__name__} when called at "
                                   f"{_called_at(z, X, Y)}: {exc}") from exc
    if out.shape != z.shape:
        raise CauchyTransformError(
            f"{name} must be vectorised: called with complex z of shape {z.shape} (at "
            f"{_called_at(z, X, Y)}) it must return that shape, got {out.shape}")
    if out.dtype.kind != "c":
        if out.dtype.kind != "O":
            raise CauchyTransformError(
                f"{name} must return complex values C(z) (at Im z > 0 a Cauchy transform is "
                f"complex: its imaginary part is the Poisson integral of the traction), got "
                f"dtype {out.dtype} at {_called_at(z, X, Y)}: compute it from the complex z "
                f"itself (e.g. -P / (np.pi * z) for a line load P)")
        try:
            out = out.astype(complex)
        except (TypeError, ValueError) as exc:
            raise CauchyTransformError(f"{name} must return complex numbers, got objects "
                                       f"that are not ({exc})") from None
    bad = ~np.isfinite(out)
    if bad.any():
        k = int(np.flatnonzero(bad.ravel())[0])
        raise CauchyTransformError(
            f"{name} returned a non-finite value {complex(out.ravel()[k])!r} at "
            f"z = {complex(z.ravel()[k])!r}, for the point (X, Y) = "
            f"({float(X.ravel()[k])!r}, {float(Y.ravel()[k])!r})")
    return out


def _called_at(z, X, Y) -> str:
    """Where a transform was called, for a message: the one z and its point (X, Y), or how
    many there were, the range of X and Y, and the first z."""
    if z.size == 1:
        return (f"z = {complex(z.ravel()[0])!r}, for the point (X, Y) = "
                f"({float(X.ravel()[0])!r}, {float(Y.ravel()[0])!r})")
    if z.size == 0:
        return "an empty array of z"
    return (f"the {z.size} points z = X - i eta Y of X in [{float(X.min())!r}, "
            f"{float(X.max())!r}], Y in [{float(Y.min())!r}, {float(Y.max())!r}] (first "
            f"z = {complex(z.ravel()[0])!r})")


@dataclass(frozen=True)
class Extremum:
    """Where a stress quantity is largest in a region.

    One entry of :class:`StressExtrema`.

    Attributes
    ----------
    quantity : str
        "max_shear", "max_tension", "von_mises" or "tresca" (:class:`StressField`).
    value : float
        Its largest value there.
    X, Y : float
        Where (Y <= 0).
    depth : float
        -Y.
    half_width : float
        The half-width a of the contact zone nearest to X.
    depth_over_a : float
        depth / half_width.

    References
    ----------
    Johnson, Contact Mechanics (1985), ch. 4 (Hertz line contact: the largest shear,
    0.300 p0, lies on the axis at depth 0.786 a).

    Examples
    --------
    >>> import contact
    >>> r = contact.solve(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0),
    ...                   load=0.01, speed=0.0)
    >>> e = r.stress_extrema(grid=(21, 21)).max_shear
    >>> p0 = float(r.pressure(0.0))
    >>> e.quantity, round(e.value / p0, 3), round(e.depth_over_a, 3), abs(e.X) < 1e-6
    ('max_shear', 0.3, 0.786, True)
    """
    quantity: str
    value: float
    X: float
    Y: float
    depth: float
    half_width: float
    depth_over_a: float


@dataclass(frozen=True)
class StressExtrema:
    """The largest in-plane maximum shear and the largest tension in a region (and, where
    asked for, the largest von Mises stress and Tresca shear).

    Returned by :meth:`contact.ContactResult.stress_extrema`.

    Attributes
    ----------
    max_shear, max_tension : Extremum or None
        The largest in-plane maximum shear and the largest principal stress sigma_1 (None
        only where ``quantities`` left them out).
    region : ((X_min, X_max), (Y_min, Y_max))
        The region searched.
    von_mises, tresca : Extremum or None
        The largest von Mises stress and the largest shear (s_1 - s_3) / 2 over all planes,
        where asked for (``quantities``; they need a material whose modes give the
        out-of-plane stresses, :attr:`StressField.sigma_zz`); else None.

    References
    ----------
    Johnson, Contact Mechanics (1985), ch. 4 (the Hertz line contact) and Sec. 7.1 (with
    friction).

    Examples
    --------
    The Hertz contact: the shear peaks at 0.300 p0 at depth 0.786 a under the centre; the
    material is nowhere in tension without friction:

    >>> import contact
    >>> r = contact.solve(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0),
    ...                   load=0.01, speed=0.0)
    >>> ex = r.stress_extrema(grid=(21, 21))
    >>> p0 = float(r.pressure(0.0))
    >>> round(ex.max_shear.value / p0, 3), round(ex.max_shear.depth_over_a, 3)
    (0.3, 0.786)
    >>> ex.max_tension.value < 1e-9 * p0
    True
    """
    max_shear: Extremum | None
    max_tension: Extremum | None
    region: tuple
    von_mises: Extremum | None = None
    tresca: Extremum | None = None


#: The quantities :func:`field_extrema` can search for (properties of :class:`StressField`).
EXTREMUM_QUANTITIES = ("max_shear", "max_tension", "von_mises", "tresca")


def field_extrema(stress, region, half_width_at, grid=(81, 61),
                  quantities=("max_shear", "max_tension")) -> StressExtrema:
    """Largest values of ``quantities`` of ``stress(X, Y) -> StressField`` in ``region``
    (by default the max-shear and the tension).

    A grid search (``grid`` = (nx, ny) points, ends included), then each quantity's best
    grid maxima (the largest, and any other local maximum within 10 % of it) are polished by
    zooming: 7 x 7 points on a window of one grid cell about the best point, re-centred on
    the best of them and shrunk 3-fold, 24 times (to 3.5e-12 of a cell; the window stays
    inside the region), all windows of a round in one call of ``stress``.

    Parameters
    ----------
    stress : callable
    region : ((X_min, X_max), (Y_min, Y_max)), Y_max <= 0
    half_width_at : callable
        X -> the half-width used to scale the depth.
    grid : (int, int)
        At least (3, 3).
    quantities : sequence of str
        Some of :data:`EXTREMUM_QUANTITIES` ("von_mises" and "tresca" need the
        out-of-plane stresses: :attr:`StressField.sigma_zz`); the others are None in the
        result.

    Raises
    ------
    ContactInputError
        ``quantities`` empty or naming another quantity.
    MaterialError
        "von_mises" or "tresca" for a field without the out-of-plane stresses.
    """
    names = extremum_quantities(quantities)
    (x0, x1), (y0, y1) = region
    nx, ny = grid
    xs, ys = np.linspace(x0, x1, nx), np.linspace(y0, y1, ny)
    Xg, Yg = np.meshgrid(xs, ys, indexing="ij")
    field = stress(Xg, Yg)
    starts = []                                   # (quantity, X, Y, value)
    for name in names:
        V = getattr(field, name)
        cand = _grid_maxima(V, 4)
        top = V[cand[0]]
        for ij in cand:
            if ij == cand[0] or V[ij] >= top - 0.1 * abs(top):
                starts.append([name, Xg[ij], Yg[ij], V[ij]])
    wx, wy = (x1 - x0) / (nx - 1), (y1 - y0) / (ny - 1)
    t = np.linspace(-1.0, 1.0, 7)
    TX, TY = (a.ravel() for a in np.meshgrid(t, t, indexing="ij"))
    for _ in range(24):
        Xp = np.concatenate([np.clip(s[1] + wx * TX, x0, x1) for s in starts])
        Yp = np.concatenate([np.clip(s[2] + wy * TY, y0, y1) for s in starts])
        f = stress(Xp, Yp)
        for k, st in enumerate(starts):
            V = getattr(f, st[0])[k * TX.size:(k + 1) * TX.size]
            j = int(np.argmax(V))
            if V[j] >= st[3]:
                st[1], st[2], st[3] = Xp[k * TX.size + j], Yp[k * TX.size + j], V[j]
        wx, wy = wx / 3.0, wy / 3.0
    out = {}
    for name in names:
        _, X, Y, val = max((s for s in starts if s[0] == name), key=lambda s: s[3])
        a = half_width_at(X)
        depth = abs(float(Y))
        out[name] = Extremum(name, float(val), float(X), float(Y), depth, float(a),
                             depth / float(a))
    return StressExtrema(out.get("max_shear"), out.get("max_tension"), ((x0, x1), (y0, y1)),
                         von_mises=out.get("von_mises"), tresca=out.get("tresca"))


def extremum_quantities(quantities) -> tuple:
    """``quantities`` as a tuple of distinct names from :data:`EXTREMUM_QUANTITIES` (a single
    name is one quantity), else ContactInputError."""
    if isinstance(quantities, str):
        quantities = (quantities,)
    try:
        names = tuple(quantities)
    except TypeError:
        raise ContactInputError(f"quantities must be a sequence of names from "
                                f"{EXTREMUM_QUANTITIES}, got {quantities!r}") from None
    bad = [q for q in names if not isinstance(q, str) or q not in EXTREMUM_QUANTITIES]
    if bad or not names:
        raise ContactInputError(f"quantities must be a non-empty sequence of names from "
                                f"{EXTREMUM_QUANTITIES}, got {quantities!r}")
    return tuple(dict.fromkeys(names))


def _grid_maxima(V, k):
    """Indices of the k largest local maxima of a 2-D grid (>= their 8 neighbours)."""
    P = np.pad(V, 1, constant_values=-np.inf)
    core = P[1:-1, 1:-1]
    is_max = np.ones(V.shape, dtype=bool)
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            if di or dj:
                is_max &= core >= P[1 + di:P.shape[0] - 1 + di, 1 + dj:P.shape[1] - 1 + dj]
    idx = np.argwhere(is_max)
    order = np.argsort(-V[is_max], kind="stable")[:k]
    return [tuple(idx[o]) for o in order]
