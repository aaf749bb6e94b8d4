"""Corrected closed-form solutions of Zhou, Lee & Jang (Arch. Mech. 2014), Section 5.

Four rigid punches slide over a half-space whose surface response is

    dv/dX     = N12*mu_f*p(X) + N11*Hc[p](X)        (inside the contact: the punch slope)
    sigma_XX  = N21*p(X)      + N22*mu_f*Hc[p](X)   (every real X; p = 0 off the contact)

with p > 0 the compressive contact pressure, Hc[f](X) = (1/pi) PV int f(t)/(t - X) dt and
mu_f the *signed* friction coefficient (mu_f = -direction*mu: the paper's case, punch sliding
toward -X, is mu_f = mu > 0; see :func:`signed_friction`). The constants are plain floats;
N11 must be negative (N11 >= 0 raises :class:`~contact.errors.MaterialError`), N12, N21, N22
any finite reals.

Mathematics (re-derived; every item is checked against mpmath quadrature in
``tests/contact/test_closed_form.py``)
--------------------------------------------------------------------------------------------
Contact [x_l, x_r], L = (x_r - x_l)/2, X = L*s + (x_r + x_l)/2, p(X) = psi(s),
psi(s) = w(s)*(d0 + d1*s), w(s) = (1 - s)^alpha (1 + s)^beta, kappa = -(alpha + beta).
With xi = mu_f*N12/N11 and alpha0 = atan2(1, -xi)/pi in (0, 1) (cot(pi*alpha0) = -xi):
right end alpha = alpha0 (bounded) or alpha0 - 1 (singular); left end beta = 1 - alpha0
(bounded) or -alpha0 (singular).

Cauchy transform of the weight. F(z) = (z - 1)^alpha (z + 1)^beta (cut on [-1, 1]) is single
valued outside the cut because alpha + beta = -kappa is an integer; F(x +- i0) = w(x) e^{+-i pi alpha}
on the cut, F(x) = (x-1)^alpha (x+1)^beta for x > 1 and F(x) = (-1)^kappa (1-x)^alpha (-1-x)^beta
for x < -1. Subtracting the polynomial part R of F at infinity (R = 0, 1, s + beta - alpha for
kappa = 1, 0, -1) gives, with H[f](x) = (1/pi) PV int_{-1}^{1} f(t)/(t - x) dt,

    H[w](x) = (F(x) - R(x)) / sin(pi alpha)                   |x| > 1,
    H[w](x) = (w(x) cos(pi alpha) - R(x)) / sin(pi alpha)      |x| < 1   (Plemelj: mean of F+-),

and for linear phi, H[w phi](x) = phi(x) H[w](x) + d1*mu0/pi, mu0 = int w (paper 5.5).
Far away (|s| > 4) the code uses instead the cancellation-free Euler integral
int w(t)/(t - x) dt = -mu0/(x - 1) * 2F1(1, alpha+1; alpha+beta+2; 2/(1 - x)) (x > 1; reflect
for x < -1) and writes w*phi = (d0 + d1) w - d1 (1-s)^{alpha+1}(1+s)^beta.
Hc[p](X) = H[psi](s) exactly (the Jacobian L cancels in dt/(t - s)).

Paper formulas found wrong, and what holds
------------------------------------------
1. Exponents (4.18) with the case tables (5.3) flat, (5.16) triangular/parabolic, (5.38)
   cylindrical: for xi < 0 (the usual case: mu_f > 0 with N12/N11 < 0) the printed rows give
   exponents with the wrong sign of eps = arctan(1/xi) in (-pi/2, 0). They violate the
   characteristic equation (they solve cot(pi alpha) = +xi) and leave the admissible range:
   (5.3) gives alpha = eps/pi - 1 < -1 (not integrable), (5.16) alpha = eps/pi < 0 at the
   end that must be bounded, (5.38) alpha = eps/pi < 0. What holds, for every sign of xi:
   alpha0 = atan2(1, -xi)/pi (principal arccot), and for xi < 0 the tables must read
   (5.3)  alpha = -eps/pi - 1, beta = eps/pi;
   (5.16) alpha = -eps/pi,     beta = eps/pi;
   (5.38) alpha = -eps/pi,     beta = 1 + eps/pi.
   Isotropic static (G = 1, nu = 0.3) at mu_f = 0.3: xi = -0.0857; flat printed alpha = -1.473
   (correct -0.527), triangular printed alpha = -0.473 (correct 0.473), cylindrical printed
   (alpha, beta) = (-0.473, 1.473) (correct (0.473, 0.527)). The xi > 0 rows are right.
2. (5.9): the exponents printed tau, theta are alpha, beta (the p term). (4.19): sin(pi tau) is
   sin(pi alpha).
3. (5.44)-(5.45), cylindrical sigma_XX inside -a < X < b: Upsilon_c must read
   (pi/sin(pi alpha)) [2 (b-X)^alpha (X+a)^beta cos(pi alpha) - 2X + b - a + (alpha-beta)(b+a)]
   (the cos(pi alpha) of the Plemelj formula is missing; Upsilon_c = pi*(b+a)*H[w]). The outside
   rows are right. Error of the printed inside row (max over the contact, relative to
   max|sigma_XX| inside): isotropic static (G = 1, nu = 0.3) 19% at mu_f = 0.1, 48% at 0.3,
   63% at 0.5 (57% at mu_f = -0.3); at the centre of the contact 54% at mu_f = 0.3. It vanishes
   only at mu_f = 0 (then N22 mu_f = 0).
Checked and found right (once the exponents of item 1 are used): (4.19)-(4.20) (with item 2),
(5.5), (5.6), (5.8); (5.9)-(5.10) flat sigma_XX (kappa = 1: R = 0, so H[w] = cot(pi alpha) w
inside and F/sin(pi alpha) outside, with F < 0 for X < -a, as printed); (5.11)-(5.13);
(5.18)-(5.23) including the triangular sigma_XX (5.20)-(5.21) (kappa = 0: R = 1, the "-1" terms);
(5.26)-(5.34) including the parabolic sigma_XX (5.29)-(5.31) (Upsilon_p^(1) = pi H[w P1] =
P1 Upsilon_p^(0) + 2 pi alpha/sin(pi alpha), since H[w P1] = P1 H[w] + int w/pi);
(5.41)-(5.43), (5.46), (5.47). In particular the load relations (5.22) b = -N11 P/(m0 pi alpha)
and (5.32) b^2 = -2 N11 P R/(pi alpha (1+alpha)) hold as printed: int w = 2 pi alpha/sin(pi alpha)
for beta = -alpha (the factor 2^{alpha+beta+1} = 2 is easy to drop when re-deriving, which would
wrongly suggest a factor-2 erratum). (5.46)-(5.47) give b + a = sqrt(-2 N11 P R/(pi alpha beta)),
a = alpha (b + a), b = beta (b + a).
Hertz limit (mu_f = 0, isotropic static): a_half^2 = -2 N11 P R/pi = 2 P R (1-nu)/(pi G)
= 4 P R/(pi E*), E* = 2G/(1-nu) (Johnson, Contact Mechanics 1985, ch. 4, plane strain).

Numerical limits: alpha0 -> 0 or 1 (|xi| -> infinity, e.g. near the Rayleigh speed where
N11 -> 0) divides small by small in the inside formula; accuracy there degrades like
eps/sin(pi alpha0).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
import numpy as np

from .punches import CylindricalPunch, FlatPunch, ParabolicPunch, TriangularPunch
from .errors import (
    DirectionError,
    FrictionError,
    LoadError,
    MaterialError,
    PunchGeometryError,
    check_finite,
)

__all__ = [
    "ClosedFormSolution",
    "signed_friction",
    "exponent_alpha0",
    "flat_closed_form",
    "triangular_closed_form",
    "parabolic_closed_form",
    "cylindrical_closed_form",
    "CLOSED_FORMS",
]

_FAR = 4.0  # |s| beyond which the hypergeometric (Euler integral) form is used outside


# ---------------------------------------------------------------------------------------------
# small helpers
# ---------------------------------------------------------------------------------------------
def signed_friction(mu: float, direction: int) -> float:
    """mu_f = -direction * mu.

    ``mu >= 0`` is the friction coefficient; ``direction = -1`` means the punch slides toward -X
    (the paper's case, mu_f = mu), ``+1`` toward +X (mu_f = -mu).
    """
    mu = check_finite("mu", mu, FrictionError)
    if mu < 0:
        raise FrictionError(f"mu must be >= 0 (friction coefficient), got {mu!r}")
    if direction not in (-1, 1) or isinstance(direction, bool):
        raise DirectionError(f"direction must be -1 (toward -X) or +1 (toward +X), got {direction!r}")
    return -float(direction) * mu


def exponent_alpha0(N11: float, N12: float, mu_f: float) -> float:
    """alpha0 in (0, 1) with cot(pi*alpha0) = -xi, xi = mu_f*N12/N11 (principal arccot).

    Replaces the case tables (5.3), (5.16), (5.38) of the paper (wrong for xi < 0).
    """
    return _alpha0_pair(N11, N12, mu_f)[0]


def _alpha0_pair(N11: float, N12: float, mu_f: float) -> tuple[float, float, float]:
    """(alpha0, 1 - alpha0, sin(pi alpha0)), each to full relative precision: 1 - alpha0
    as the arccot of +xi (not by subtracting a rounded alpha0, which loses its digits as
    alpha0 -> 1, i.e. as friction grows), and the sine from the smaller of the two."""
    xi = mu_f * N12 / N11
    a0, a0c = math.atan2(1.0, -xi) / math.pi, math.atan2(1.0, xi) / math.pi
    return a0, a0c, math.sin(math.pi * min(a0, a0c))


def _check_constants(N11, N12, N21, N22, mu_f):
    N11 = check_finite("N11", N11, MaterialError)
    N12 = check_finite("N12", N12, MaterialError)
    N21 = check_finite("N21", N21, MaterialError)
    N22 = check_finite("N22", N22, MaterialError)
    mu_f = check_finite("mu_f", mu_f, FrictionError)
    if not N11 < 0:
        raise MaterialError(
            f"N11 must be negative (a compressive load must push the surface down), got {N11!r}")
    return N11, N12, N21, N22, mu_f


def _positive(name, value, error):
    v = check_finite(name, value, error)
    if not v > 0:
        raise error(f"{name} must be a finite positive number, got {v!r}")
    return v


def _mu0(ap1: float, bp1: float) -> float:
    """int_{-1}^{1} (1-s)^alpha (1+s)^beta ds = 2^{alpha+beta+1} G(alpha+1)G(beta+1)/G(alpha+beta+2),
    from the shifted exponents ap1 = alpha + 1, bp1 = beta + 1 (exact: G(alpha + 1) from a
    rounded alpha near -1 would lose ~1e-16 / (alpha + 1) of itself)."""
    return (2.0 ** (ap1 + bp1 - 1.0) * math.gamma(ap1) * math.gamma(bp1)
            / math.gamma(ap1 + bp1))


def _cos_expm1(e, t):
    """e^x cos(pi t) - 1 from e = expm1(x): e cos(pi t) - 2 sin^2(pi t / 2), which keeps
    every digit as x and t tend to 0 (formed as it reads, it cancels)."""
    return e * math.cos(math.pi * t) - 2.0 * math.sin(0.5 * math.pi * t) ** 2


def _euler_J(ap1: float, bp1: float, x: np.ndarray) -> np.ndarray:
    """J(x) = int_{-1}^{1} (1-t)^alpha (1+t)^beta / (t - x) dt for |x| >= _FAR (vectorised),
    alpha = ap1 - 1, beta = bp1 - 1.

    x > 1:  J = -mu0/(x-1) * 2F1(1, alpha+1; alpha+beta+2; z), z = 2/(1-x), |z| <= 2/3
            (Euler's integral with t = 1 - 2u); x < -1: J_{alpha,beta}(x) = -J_{beta,alpha}(-x).
    """
    x = np.asarray(x, dtype=float)
    out = np.empty_like(x)
    for sign, a1, b1 in ((1.0, ap1, bp1), (-1.0, bp1, ap1)):
        m = (sign * x) > 0
        if not np.any(m):
            continue
        y = sign * x[m]
        z = 2.0 / (1.0 - y)
        term = np.ones_like(z)
        total = np.ones_like(z)
        c = a1 + b1
        for n in range(400):
            term = term * ((a1 + n) / (c + n)) * z
            total = total + term
            if np.all(np.abs(term) <= 1e-17 * np.abs(total)):
                break
        out[m] = sign * (-_mu0(a1, b1) / (y - 1.0) * total)
    return out


# ---------------------------------------------------------------------------------------------
# the solution object
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ClosedFormSolution:
    """Closed-form contact solution p(X) = psi(s) = (1-s)^alpha (1+s)^beta (d0 + d1 s).

    Fields
    ------
    punch : "flat" | "triangular" | "parabolic" | "cylindrical"
    N11, N12, N21, N22, mu_f : the constants and the signed friction used
    ends : (x_left, x_right), the contact zone
    alpha, beta : exponents at the right (X = x_right) and left (X = x_left) ends
    kappa : -(alpha + beta), the index (1, 0 or -1)
    alpha_p1, beta_p1 : alpha + 1, beta + 1, exact (not from the rounded exponents, which
        lose their digits in them at an exponent near -1: at friction ~1e4 and beyond)
    sin_alpha : sin(pi alpha), exact (likewise)
    phi : (d0, d1), psi(s) = w(s)*(d0 + d1*s) in the normalised variable s in (-1, 1)
    load : the prescribed total load P
    load_check : int p dX = L*(d0*mu0 + d1*mu1) evaluated in closed form (should equal ``load``)
    sif : paper's stress intensity factors, keys "right"/"left" (see the punch functions)
    """

    punch: str
    N11: float
    N12: float
    N21: float
    N22: float
    mu_f: float
    ends: tuple
    alpha: float
    beta: float
    kappa: int
    alpha_p1: float
    beta_p1: float
    sin_alpha: float
    phi: tuple
    load: float
    load_check: float
    sif: dict = field(default_factory=dict)

    # -- geometry ---------------------------------------------------------------------------
    @property
    def half_length(self) -> float:
        return 0.5 * (self.ends[1] - self.ends[0])

    def _one_minus_one_plus(self, X):
        """(1 - s, 1 + s) computed from the distances to the ends (no cancellation)."""
        X = np.asarray(X, dtype=float)
        if not np.all(np.isfinite(X)):
            raise ValueError("X must be finite real numbers")
        L = self.half_length
        return (self.ends[1] - X) / L, (X - self.ends[0]) / L

    def _phi(self, s):
        return self.phi[0] + self.phi[1] * s

    # -- pressure ---------------------------------------------------------------------------
    def pressure(self, X):
        """p(X) >= 0; zero outside [x_left, x_right]; +inf at a singular end."""
        X = np.asarray(X, dtype=float)
        um, up = self._one_minus_one_plus(X)
        s = up - 1.0
        inside = (um > 0) & (up > 0)
        p = np.zeros(X.shape, dtype=float)
        if np.any(inside):
            p[inside] = (um[inside] ** self.alpha * up[inside] ** self.beta
                         * self._phi(np.where(um[inside] < up[inside], 1.0 - um[inside], s[inside])))
        for end_mask, expo in ((um == 0, self.alpha), (up == 0, self.beta)):
            if np.any(end_mask):
                p[end_mask] = np.inf if expo < 0 else 0.0
        return p[()] if p.ndim == 0 else p

    def cauchy(self, z):
        """(1/pi) int p(t) / (t - z) dt at complex z off the contact, through the Jacobi
        series of d0 + d1 s (P_1^(alpha,beta)(s) = (alpha - beta)/2 + (alpha + beta + 2) s/2)
        and :func:`sie.cauchy.jacobi_cauchy` (the transform is scale-free: t = m + L u)."""
        from sie.cauchy import Weight, cauchy_series, evaluation_points
        c1 = 2.0 * self.phi[1] / (self.alpha_p1 + self.beta_p1)
        c0 = self.phi[0] - 0.5 * c1 * (self.alpha - self.beta)
        mid = 0.5 * (self.ends[0] + self.ends[1])
        # the weight from the exact shifts: 1 - alpha = 1 + beta + kappa (beta itself at
        # kappa = -1, where 1 + beta - 1 would cancel)
        am1 = self.beta if self.kappa == -1 else self.beta_p1 + self.kappa
        wt = Weight(self.alpha, self.beta, self.alpha_p1, self.beta_p1, am1, self.sin_alpha)
        u, cplx = evaluation_points((np.asarray(z) - mid) / self.half_length,
                                    ((-1.0, 1.0),), "z")
        out = cauchy_series(np.array([c0, c1]), wt, u.ravel()).reshape(u.shape)
        return out if cplx else out.real

    # -- Hilbert transform of p -------------------------------------------------------------
    def _G(self, um, up):
        """G = F(x) - R(x) (F = (x-1)^alpha (x+1)^beta from above: w cos(pi alpha) inside,
        +-|x-1|^alpha |x+1|^beta outside; R its polynomial part: 0, 1, x + beta - alpha for
        kappa = 1, 0, -1), at x = s from the signed distances um = 1 - s, up = 1 + s.

        F and R agree to first order in an exponent e near 0 (kappa = 0, -1), so that F - R
        formed as it reads keeps ~1e-16 / e of itself (e = 2e-12 at friction 1e12).  Written
        in expm1 of e log(|um| / |up|) it keeps every digit:
            kappa = 0:  w cos(pi a) - 1 = expm1(a l) cos(pi a) - 2 sin^2(pi a / 2) inside,
                        F - 1 = expm1(a l) outside;
            kappa = -1: up [expm1(a l) cos(pi a) - 2 sin^2(pi a / 2)] + 2a inside, and
                        +-|up| expm1(a l) + 2a outside (a <= 1/2); with b = 1 - a <= 1/2,
                        -um [expm1(-b l) cos(pi b) - 2 sin^2(pi b / 2)] - 2b inside and
                        +-|um| expm1(-b l) - 2b outside."""
        a, b, k = self.alpha, self.beta, self.kappa
        inside = (um > 0) & (up > 0)
        if k == 1:
            F = np.abs(um) ** a * np.abs(up) ** b
            return np.where(inside, F * math.cos(math.pi * a), np.where(up > 0, F, -F))
        ell = np.log(np.abs(um)) - np.log(np.abs(up))
        if k == 0:
            if abs(a) > 0.5:                  # no cancellation away from e = 0
                F = np.exp(a * ell)
                return np.where(inside, F * math.cos(math.pi * a), F) - 1.0
            e = np.expm1(a * ell)
            return np.where(inside, _cos_expm1(e, a), e)
        sign = np.where(up > 0, 1.0, -1.0)        # kappa = -1: F = -|...| left of the contact
        if a <= 0.5:
            e = np.expm1(a * ell)
            return np.where(inside, up * _cos_expm1(e, a) + 2.0 * a,
                            sign * np.abs(up) * e + 2.0 * a)
        e = np.expm1(-b * ell)
        return np.where(inside, -um * _cos_expm1(e, b) - 2.0 * b,
                        sign * np.abs(um) * e - 2.0 * b)

    def hilbert_pressure(self, X):
        """Hc[p](X) = (1/pi) PV int p(t)/(t - X) dt at any real X (ValueError at a singular end):
        phi(s) G(s) / sin(pi alpha) + d1 mu0 / pi near the contact (:meth:`_G`, every digit
        also with an exponent near 0), the Euler integral beyond |s| = 4."""
        X = np.asarray(X, dtype=float)
        um, up = self._one_minus_one_plus(X)
        a, b = self.alpha, self.beta
        if (a < 0 and np.any(um == 0)) or (b < 0 and np.any(up == 0)):
            raise ValueError(
                f"Hc[p] (and sigma_XX) is infinite at a singular end of the contact "
                f"{self.ends}; evaluate at X != {self.ends[1] if a < 0 and np.any(um == 0) else self.ends[0]}")
        # s from the nearer end
        s = np.where(um < up, 1.0 - um, up - 1.0)
        d0, d1 = self.phi
        sa = self.sin_alpha
        mu0 = _mu0(self.alpha_p1, self.beta_p1)
        const = d1 * mu0 / math.pi
        out = np.empty(X.shape, dtype=float)
        right = um < 0
        left = up < 0
        near = ~(right | left) | (np.abs(s) <= _FAR)
        atend = (um == 0) | (up == 0)     # bounded ends only (singular ones raised above)
        if np.any(near & ~atend):
            m = near & ~atend
            out[m] = self._phi(s[m]) * self._G(um[m], up[m]) / sa + const
        if np.any(atend):
            # F = 0 at a bounded end: G = -R, with R(+-1) = 2 beta, -2 alpha at kappa = -1
            # (not 1 + beta - alpha, which cancels as an exponent nears 0)
            se = s[atend]
            R = {1: np.zeros_like(se), 0: np.ones_like(se)}.get(
                self.kappa, np.where(se > 0, 2.0 * b, -2.0 * a))
            out[atend] = self._phi(se) * (-R) / sa + const
        far = (right | left) & (np.abs(s) > _FAR)
        if np.any(far):
            sf = s[far]
            ap1, bp1 = self.alpha_p1, self.beta_p1
            J = (d0 + d1) * _euler_J(ap1, bp1, sf) - d1 * _euler_J(ap1 + 1.0, bp1, sf)
            out[far] = J / math.pi
        return out[()] if out.ndim == 0 else out

    # -- in-plane surface stress ------------------------------------------------------------
    def sigma_xx(self, X):
        """sigma_XX(X, 0) = N21 p + N22 mu_f Hc[p] at any real X (ValueError at a singular end)."""
        X = np.asarray(X, dtype=float)
        h = np.asarray(self.hilbert_pressure(X), dtype=float)
        p = np.asarray(self.pressure(X), dtype=float)
        out = self.N21 * p + self.N22 * self.mu_f * h
        return out[()] if np.ndim(out) == 0 else out


def _build(punch, N11, N12, N21, N22, mu_f, ends, exponents, d0, d1, load, sif):
    """The solution; ``exponents`` = (alpha, beta, alpha + 1, beta + 1, sin(pi alpha))."""
    alpha, beta, ap1, bp1, sin_alpha = exponents
    kappa = int(round(-(alpha + beta)))
    L = 0.5 * (ends[1] - ends[0])
    mu0 = _mu0(ap1, bp1)
    mu1 = (beta - alpha) * mu0 / (ap1 + bp1)  # int w s ds (integrate d/ds[(1-s)^{a+1}(1+s)^{b+1}])
    load_check = L * (d0 * mu0 + d1 * mu1)
    return ClosedFormSolution(punch=punch, N11=N11, N12=N12, N21=N21, N22=N22, mu_f=mu_f,
                              ends=(float(ends[0]), float(ends[1])), alpha=alpha, beta=beta,
                              kappa=kappa, alpha_p1=ap1, beta_p1=bp1, sin_alpha=sin_alpha,
                              phi=(float(d0), float(d1)), load=load,
                              load_check=float(load_check), sif=dict(sif))


# ---------------------------------------------------------------------------------------------
# the four punches
# ---------------------------------------------------------------------------------------------
def flat_closed_form(N11, N12, N21, N22, mu_f, half_width, load) -> ClosedFormSolution:
    """Flat punch on [-a, a], both ends singular (kappa = 1); paper Sec. 5.1.

    alpha = alpha0 - 1, beta = -alpha0 (corrects (5.3)).
    p(X) = c0 (1 - X/a)^alpha (1 + X/a)^beta, c0 = -P sin(pi alpha)/(pi a)       (5.6)-(5.8)
    sigma_XX = c0 [N21 w + N22 mu_f Upsilon_f/pi], Upsilon_f = pi H[w] = pi F or pi w cot(pi alpha)
    (5.9)-(5.10: right, with tau, theta read as alpha, beta).
    sif:
      "right" = FI(a)  = lim_{X->a}  p(X) (a - X)^{-alpha} / 2^beta  = c0 a^{-alpha}   (5.11)
      "left"  = FI(-a) = lim_{X->-a} p(X) (a + X)^{-beta}  / 2^alpha = c0 a^{-beta}    (5.12)
    (mu_f = 0: both P/(pi sqrt(a)), (5.13)).
    """
    N11, N12, N21, N22, mu_f = _check_constants(N11, N12, N21, N22, mu_f)
    a = _positive("half_width", half_width, PunchGeometryError)
    P = _positive("load", load, LoadError)
    a0, a0c, sin0 = _alpha0_pair(N11, N12, mu_f)
    alpha, beta = -a0c, -a0                   # alpha0 - 1, -alpha0
    c0 = P * sin0 / (math.pi * a)             # = P / (a mu0) = -P sin(pi alpha)/(pi a)
    sif = {"right": c0 * a ** (-alpha), "left": c0 * a ** (-beta)}
    return _build("flat", N11, N12, N21, N22, mu_f, (-a, a), (alpha, beta, a0, a0c, -sin0),
                  c0, 0.0, P, sif)


def triangular_closed_form(N11, N12, N21, N22, mu_f, slope, load) -> ClosedFormSolution:
    """Triangular (wedge-flank) punch v = -v0 + m0 X on [0, b]; corner at X = 0 (singular),
    smooth at X = b (bounded): alpha = alpha0, beta = -alpha0, kappa = 0. Paper Sec. 5.2.

    p(X) = c0 ((b - X)/X)^alpha, c0 = -m0 sin(pi alpha)/N11                      (5.18)-(5.19)
    b = -N11 P/(m0 pi alpha)                          (5.22, right with the corrected alpha)
    sigma_XX = c0 [N21 w + N22 mu_f Upsilon_t/pi]                                (5.20)-(5.21)
    sif:
      "left" = k1(0) = lim_{X->0} X^alpha p(X) = c0 b^alpha = m0 sin(pi alpha) b^alpha/(-N11)  (5.23)
    """
    N11, N12, N21, N22, mu_f = _check_constants(N11, N12, N21, N22, mu_f)
    m0 = _positive("slope", slope, PunchGeometryError)
    P = _positive("load", load, LoadError)
    alpha, a0c, sin0 = _alpha0_pair(N11, N12, mu_f)
    beta = -alpha
    b = -N11 * P / (m0 * math.pi * alpha)
    c0 = -m0 * sin0 / N11
    sif = {"left": c0 * b ** alpha}
    return _build("triangular", N11, N12, N21, N22, mu_f, (0.0, b),
                  (alpha, beta, 1.0 + alpha, a0c, sin0), c0, 0.0, P, sif)


def parabolic_closed_form(N11, N12, N21, N22, mu_f, radius, load) -> ClosedFormSolution:
    """Parabolic punch v = -v0 + X^2/(2R) on [0, b]; corner at X = 0 (singular), smooth at
    X = b (bounded): alpha = alpha0, beta = -alpha0, kappa = 0. Paper Sec. 5.3.

    psi(s) = c0 w + c1 w P1^{(alpha,beta)}(s) = c1 w (s + 1 + 2 alpha),
    c1 = -b sin(pi alpha)/(2 N11 R), c0 = (1 + alpha) c1                          (5.27)
    p(X) = -(b sin(pi alpha)/(N11 R)) ((b - X)/X)^alpha (alpha + X/b)              (5.28)
    b^2 = -2 N11 P R/(pi alpha (1 + alpha))           (5.32, right with the corrected alpha)
    sigma_XX: (5.29)-(5.31) hold (Upsilon_p^(1) = P1 Upsilon_p^(0) + 2 pi alpha/sin(pi alpha)).
    sif:
      "left" = FI(0) = lim_{X->0} X^alpha p(X) = b^{alpha+1} alpha sin(pi alpha)/(-N11 R)  (5.33)
    """
    N11, N12, N21, N22, mu_f = _check_constants(N11, N12, N21, N22, mu_f)
    R = _positive("radius", radius, PunchGeometryError)
    P = _positive("load", load, LoadError)
    alpha, a0c, sin0 = _alpha0_pair(N11, N12, mu_f)
    beta = -alpha
    b = math.sqrt(-2.0 * N11 * P * R / (math.pi * alpha * (1.0 + alpha)))
    c1 = -b * sin0 / (2.0 * N11 * R)
    sif = {"left": b ** (alpha + 1.0) * alpha * sin0 / (-N11 * R)}
    return _build("parabolic", N11, N12, N21, N22, mu_f, (0.0, b),
                  (alpha, beta, 1.0 + alpha, a0c, sin0), c1 * (1.0 + 2.0 * alpha), c1, P, sif)


def cylindrical_closed_form(N11, N12, N21, N22, mu_f, radius, load) -> ClosedFormSolution:
    """Cylindrical punch v = -v0 + X^2/(2R) on [-a, b], both ends bounded:
    alpha = alpha0, beta = 1 - alpha0, kappa = -1. Paper Sec. 5.4.

    b + a = sqrt(-2 N11 P R/(pi alpha beta))                                        (5.46)
    b/a = beta/alpha  (consistency int Lambda/w = 0), i.e. a = alpha (b+a), b = beta (b+a)  (5.47)
    p(X) = -(sin(pi alpha)/(N11 R)) (b - X)^alpha (X + a)^beta                     (5.42)-(5.43)
    sigma_XX: (5.44) with the inside row of (5.45) corrected to contain cos(pi alpha).
    sif: {} (no singular end).
    """
    N11, N12, N21, N22, mu_f = _check_constants(N11, N12, N21, N22, mu_f)
    R = _positive("radius", radius, PunchGeometryError)
    P = _positive("load", load, LoadError)
    alpha, beta, sin0 = _alpha0_pair(N11, N12, mu_f)     # beta = 1 - alpha0, exact
    a0 = math.sqrt(-2.0 * N11 * P * R / (math.pi * alpha * beta))
    a, b = alpha * a0, beta * a0
    c0 = -a0 * sin0 / (2.0 * N11 * R)
    return _build("cylindrical", N11, N12, N21, N22, mu_f, (-a, b),
                  (alpha, beta, 1.0 + alpha, 1.0 + beta, sin0), c0, 0.0, P, {})


#: The punch types the paper solves in closed form (Zhou et al. 2014, Section 5) and the
#: function of this module for each; a subclass is not among them (it may change the face).
CLOSED_FORMS = {FlatPunch: flat_closed_form, TriangularPunch: triangular_closed_form,
                ParabolicPunch: parabolic_closed_form, CylindricalPunch: cylindrical_closed_form}
