"""Orthotropic plane-strain materials and the characteristic roots of Zhou et al. (2014).

:class:`Orthotropic` is a :class:`contact.Material`: its methods ``surface_constants(c)``,
``rayleigh_speed()``, ``limiting_speed()``, ``relative_speed(V)`` and
``half_space_modes(c)`` are the orthotropic formulas of :mod:`contact.constants` and
:mod:`contact.subsurface`.

Stress-strain law (Zhou, Lee & Jang 2014, eq. (2.2), plane strain, C13 = C23 = 0)::

    sigma_xx = C11 u_x + C12 v_y,   sigma_yy = C12 u_x + C22 v_y,   tau_xy = C33 (u_y + v_x).

Steady motion at speed V in the frame X = x -/+ V t (eq. (2.5)) turns rho u_tt into rho V^2
u_XX = C33 c^2 u_XX, with the relative speed c = V / sqrt(C33 / rho) (Sec. 6.1; the paper
prints sqrt(C33 rho): see the documentation, Theory: errata of Zhou et al. 2014).
Displacements exp(i k X + |k| eta Y) solve the equations of motion when eta is a root of the
characteristic equation (eq. (3.1)), a quadratic in eta^2::

    a eta^4 + b eta^2 + d = 0,
    a = C22 C33,
    b = (C12 + C33)^2 - C22 (C11 - C33 c^2) - C33^2 (1 - c^2),
    d = C33 (1 - c^2) (C11 - C33 c^2).

Any consistent stress unit may be used (the paper's material is in GPa).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .constants import (SurfaceConstants, check_speed, orthotropic_limiting_speed,
                        orthotropic_rayleigh_speed, orthotropic_surface_constants,
                        root_symmetric_functions)
from .errors import MaterialError, SpeedError, check_finite
from .subsurface import HalfSpaceModes

__all__ = ["Orthotropic", "Isotropic", "zhou2014", "check_speed"]


def _check_positive(name: str, value) -> float:
    v = check_finite(name, value, MaterialError)
    if not v > 0.0:
        raise MaterialError(f"{name} must be > 0, got {v!r}")
    return v


@dataclass(frozen=True)
class Orthotropic:
    """Orthotropic material in plane strain (Zhou et al. 2014, eq. (2.2)).

    Parameters
    ----------
    C11, C12, C22, C33 : float
        Plane-strain stiffnesses, any consistent stress unit.  Admissible when all are finite,
        C11 > 0, C22 > 0, C33 > 0 and C11*C22 > C12**2 (positive definite strain energy).
    rho : float or None, optional
        Mass density (> 0), needed only to convert a speed V to the relative speed
        c = V / sqrt(C33 / rho).

    Attributes
    ----------
    C11, C12, C22, C33 : float
        As given.
    rho : float or None
        As given.

    Raises
    ------
    MaterialError
        If a stiffness is not finite, not positive where required, the stiffness is not
        positive definite, or rho is given and is not a finite positive number.

    Notes
    -----
    sigma_xx = C11 u_x + C12 v_y, sigma_yy = C12 u_x + C22 v_y, tau_xy = C33 (u_y + v_x);
    the methods give the characteristic equation of the moving half-space
    (:meth:`characteristic_coefficients`, :meth:`characteristic_roots`), its decaying roots
    and modes, and speeds (:attr:`shear_wave_speed`, :meth:`relative_speed`).  With
    :meth:`surface_constants`, :meth:`rayleigh_speed`, :meth:`limiting_speed` and
    :meth:`half_space_modes` they make it a :class:`contact.Material`, which is all that
    :func:`contact.solve` and the stress field use of it.

    References
    ----------
    Zhou, Lee & Jang, "Indentation theory on orthotropic materials subjected to a frictional
    moving punch", Arch. Mech. 66 (2014), eqs. (2.2) (stress-strain law) and (3.1)
    (characteristic equation).

    Examples
    --------
    C11 = C22 = 3, C12 = C33 = 1 is isotropic (lambda = G = 1); at rest its characteristic
    equation 3 eta^4 - 6 eta^2 + 3 = 0 has the double root eta^2 = 1:

    >>> import contact
    >>> m = contact.Orthotropic(C11=3.0, C12=1.0, C22=3.0, C33=1.0)
    >>> m.characteristic_coefficients(0.0)
    (3.0, -6.0, 3.0)
    >>> [round(e.real, 12) for e in m.decaying_roots(0.0)]
    [1.0, 1.0]
    >>> contact.Orthotropic(1.0, 2.0, 1.0, 1.0)
    Traceback (most recent call last):
        ...
    contact.errors.MaterialError: stiffness must be positive definite: need C11*C22 > C12**2, ...
    """

    C11: float
    C12: float
    C22: float
    C33: float
    rho: float | None = None

    def __post_init__(self):
        for name in ("C11", "C22", "C33"):
            object.__setattr__(self, name, _check_positive(name, getattr(self, name)))
        object.__setattr__(self, "C12", check_finite("C12", self.C12, MaterialError))
        if not self.C11 * self.C22 > self.C12 ** 2:
            raise MaterialError(
                f"stiffness must be positive definite: need C11*C22 > C12**2, got "
                f"C11*C22 = {self.C11 * self.C22!r} and C12**2 = {self.C12 ** 2!r} "
                f"(C12 = {self.C12!r}); allowed: |C12| < sqrt(C11*C22) = "
                f"{math.sqrt(self.C11 * self.C22)!r}")
        if self.rho is not None:
            object.__setattr__(self, "rho", _check_positive("rho", self.rho))

    @property
    def shear_wave_speed(self) -> float:
        """Bulk shear wave speed sqrt(C33/rho) (Zhou et al. 2014, Sec. 6.1, which prints
        sqrt(C33 rho); see the documentation, Theory: errata of Zhou et al. 2014); needs
        ``rho``."""
        if self.rho is None:
            raise MaterialError("rho is None: give the density to convert speeds")
        return math.sqrt(self.C33 / self.rho)

    def relative_speed(self, V) -> float:
        """Relative speed c = abs(V) / sqrt(C33/rho) of a punch moving at speed ``V``."""
        V = check_finite("speed V", V, SpeedError)
        return abs(V) / self.shear_wave_speed

    def surface_constants(self, c) -> SurfaceConstants:
        """N11, N12, N21, N22 at the relative speed ``c``, 0 <= c < c_R: the closed forms of
        :func:`contact.constants.orthotropic_surface_constants` (Zhou et al. 2014, eqs.
        (4.4)-(4.6), through eta1 eta2 and eta1 + eta2).  :func:`contact.surface_constants`
        is the checked entry (it also warns near c_R).

        Raises
        ------
        SpeedError
            c not a finite number, negative, or not below :meth:`rayleigh_speed`.
        """
        return orthotropic_surface_constants(self, c)

    def rayleigh_speed(self) -> float:
        """Relative Rayleigh speed c_R, the first zero of the common denominator of the
        surface constants (:func:`contact.constants.orthotropic_rayleigh_speed`, memoised)."""
        return orthotropic_rayleigh_speed(self)

    def limiting_speed(self) -> float:
        """Lowest relative speed at which a decaying root reaches the imaginary axis
        (:func:`contact.constants.orthotropic_limiting_speed`, memoised)."""
        return orthotropic_limiting_speed(self)

    def half_space_modes(self, c) -> HalfSpaceModes:
        """The two decaying modes at the relative speed ``c``, 0 <= c < c_R, combined into
        the coefficients of the stress field under the surface
        (:class:`contact.subsurface.HalfSpaceModes`)."""
        return HalfSpaceModes.of(self, c)

    def root_symmetric_functions(self, c) -> tuple[float, float]:
        """P = eta1 eta2 and S = eta1 + eta2 of the decaying roots, from the coefficients of
        eq. (3.1) only (:func:`contact.constants.root_symmetric_functions`): well
        conditioned where the roots themselves are not (near a double root)."""
        return root_symmetric_functions(self, c)

    def characteristic_coefficients(self, c) -> tuple[float, float, float]:
        """Coefficients (a, b, d) of a eta^4 + b eta^2 + d = 0, Zhou et al. 2014, eq. (3.1).

        Parameters
        ----------
        c : float
            Relative speed, finite and >= 0.

        Returns
        -------
        a, b, d : float
            a = C22 C33, b = (C12 + C33)^2 - C22 (C11 - C33 c^2) - C33^2 (1 - c^2),
            d = C33 (1 - c^2) (C11 - C33 c^2).
        """
        c2 = check_speed(c) ** 2
        C11, C12, C22, C33 = self.C11, self.C12, self.C22, self.C33
        a = C22 * C33
        b = (C12 + C33) ** 2 - C22 * (C11 - C33 * c2) - C33 ** 2 * (1.0 - c2)
        d = C33 * (1.0 - c2) * (C11 - C33 * c2)
        return a, b, d

    def characteristic_roots(self, c) -> np.ndarray:
        """The four roots of the characteristic equation, Zhou et al. 2014, eq. (3.1).

        Parameters
        ----------
        c : float
            Relative speed, finite and >= 0 (any value: real, complex-conjugate, purely
            imaginary and repeated roots are all returned).

        Returns
        -------
        numpy.ndarray of complex, shape (4,)
            (eta1, -eta1, eta3, -eta3) as in Table 1: abs(eta1) >= abs(eta3); eta1 and eta3 are the
            principal square roots of the two roots eta^2 of a eta^4 + b eta^2 + d = 0
            (real part > 0, or on the positive imaginary axis when eta^2 < 0).  For a
            complex-conjugate pair eta^2 = r exp(+-i phi), eta1 has Im > 0 and eta3 = conj(eta1).

        Notes
        -----
        The pair eta^2 comes from the cancellation-free quadratic formula
        q = -(b + sign(b) sqrt(b^2 - 4ad)) / 2, eta^2 = q/a (larger modulus) and d/q.  Near a
        double root (isotropy at c = 0) the roots are intrinsically ill-conditioned (a
        perturbation delta of the coefficients moves them by ~sqrt(delta)); the surface
        constants in :mod:`contact.constants` use only a, b, d and are not affected.
        """
        a, b, d = self.characteristic_coefficients(c)
        big, small = _quadratic_roots(a, b, d)
        eta1 = np.sqrt(complex(big))
        eta3 = np.sqrt(complex(small))
        return np.array([eta1, -eta1, eta3, -eta3], dtype=complex)

    def decaying_roots(self, c) -> tuple[complex, complex]:
        """(eta_1, eta_2) = (eta1, eta3) of :meth:`characteristic_roots`: the two roots with
        Re eta > 0, whose modes exp(i k X + abs(k) eta Y) decay into the half-space Y < 0
        (below the limiting speed).  Near a double root they are ill-conditioned (see
        :meth:`characteristic_roots`); their sum and product are not
        (:func:`contact.constants.root_symmetric_functions`)."""
        r = self.characteristic_roots(c)
        return complex(r[0]), complex(r[2])

    def modal_vectors(self, c) -> np.ndarray:
        """Displacement amplitudes (u, v) of the two decaying modes, for k > 0.

        Returns
        -------
        numpy.ndarray of complex, shape (2, 2)
            Row j: a null vector of the equations of motion for
            u, v ~ exp(i k X + k eta_j Y) (Zhou et al. 2014, eqs. (2.4), (3.1)),

                (C33 eta^2 - C11') u + i K eta v = 0,
                i K eta u + (C22 eta^2 - C33') v = 0,

            K = C12 + C33, C11' = C11 - C33 c^2, C33' = C33 (1 - c^2): the larger of
            (K eta, i (C33 eta^2 - C11')) and (C22 eta^2 - C33', -i K eta) (parallel at a
            root; each vanishes at one root when K = 0), scaled to unit length.
        """
        c = check_speed(c)
        C11p = self.C11 - self.C33 * c * c
        C33p = self.C33 * (1.0 - c * c)
        K = self.C12 + self.C33
        out = []
        for eta in self.decaying_roots(c):
            e1 = np.array([K * eta, 1j * (self.C33 * eta * eta - C11p)])
            e2 = np.array([self.C22 * eta * eta - C33p, -1j * K * eta])
            e = e1 if np.linalg.norm(e1) >= np.linalg.norm(e2) else e2
            out.append(e / np.linalg.norm(e))
        return np.array(out, dtype=complex)


def _quadratic_roots(a: float, b: float, d: float) -> tuple[complex, complex]:
    """Roots of a x^2 + b x + d (a > 0), larger modulus first, without cancellation.

    Real roots come as floats (signed zeros normalised to +0.0), a complex pair as complex
    numbers with the positive imaginary part first.
    """
    disc = b * b - 4.0 * a * d
    if disc < 0.0:
        re, im = -b / (2.0 * a), math.sqrt(-disc) / (2.0 * a)
        return complex(re, im), complex(re, -im)
    q = -0.5 * (b + math.copysign(math.sqrt(disc), b))
    if q == 0.0:  # b = 0 and d = 0: double root at zero
        return 0.0, 0.0
    return q / a + 0.0, d / q + 0.0


def Isotropic(E, nu, rho=None) -> Orthotropic:
    """Isotropic material in plane strain as an :class:`Orthotropic`.

    Parameters
    ----------
    E : float
        Young's modulus, finite and > 0.
    nu : float
        Poisson's ratio, -1 < nu < 0.5.
    rho : float or None, optional
        Mass density (> 0).

    Returns
    -------
    Orthotropic
        C11 = C22 = lambda + 2G, C12 = lambda, C33 = G with G = E / (2 (1 + nu)) and
        lambda = E nu / ((1 + nu)(1 - 2 nu)) (the Lame constants).

    Raises
    ------
    MaterialError
        E not finite or not positive, nu not in (-1, 1/2), rho not positive.

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), eq. (2.2) with C11 = C22, C12 = lambda, C33 = G.

    Examples
    --------
    E = 5/2, nu = 1/4 gives lambda = G = 1:

    >>> import contact
    >>> m = contact.Isotropic(2.5, 0.25)
    >>> m.C11, m.C12, m.C22, m.C33
    (3.0, 1.0, 3.0, 1.0)
    """
    E = _check_positive("Young's modulus E", E)
    nu = check_finite("Poisson's ratio nu", nu, MaterialError)
    if not -1.0 < nu < 0.5:
        raise MaterialError(f"Poisson's ratio nu must satisfy -1 < nu < 0.5, got {nu!r}")
    G = E / (2.0 * (1.0 + nu))
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    return Orthotropic(lam + 2.0 * G, lam, lam + 2.0 * G, G, rho=rho)


def zhou2014() -> Orthotropic:
    """The orthotropic material of Zhou et al. 2014, Sec. 6 (stiffnesses in GPa).

    C11 = 159.7885, C12 = 5.2609, C22 = 15.4732, C33 = G0 = 5.52.

    Returns
    -------
    Orthotropic
        Without a density (``rho=None``).

    References
    ----------
    Zhou, Lee & Jang, Arch. Mech. 66 (2014), Sec. 6 and Table 1 (the characteristic roots
    of this material against the relative speed c).

    Examples
    --------
    The characteristic roots at c = 0 and c = 0.5, as printed in Table 1 of the paper
    (5.2506, 0.6120 and 5.2271, 0.5301):

    >>> import contact
    >>> m = contact.zhou2014()
    >>> [round(e.real, 4) for e in m.decaying_roots(0.0)]
    [5.2506, 0.612]
    >>> [round(e.real, 4) for e in m.decaying_roots(0.5)]
    [5.2271, 0.5301]
    """
    return Orthotropic(C11=159.7885, C12=5.2609, C22=15.4732, C33=5.52)
