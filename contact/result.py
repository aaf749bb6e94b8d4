"""The result of a contact solve (:func:`contact.solve`): fields, SIFs, residual.

Zhou, Lee & Jang 2014, eqs. (4.5)-(4.6), (5.11)-(5.13), (5.23), (5.33); conventions of the
project's errata notes (p > 0 compressive, q = mu_f p, Hc[f](X) = (1/pi) PV int f(t)/(t - X) dt).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .constants import SurfaceConstants
from .errors import ContactInputError
from .punches import Punch

__all__ = ["ContactResult"]


@dataclass(eq=False)
class ContactResult:
    """Solution of one contact problem.

    Attributes
    ----------
    ends : (float, float)
        Contact ends (x_left, x_right).
    alpha, beta : float
        Exponents of p ~ (x_right - X)^alpha at the right end and (X - x_left)^beta at the left.
    kappa : int
        Index -(alpha + beta).
    n : int
        Jacobi coefficients used.
    residual : float
        max |(dominant operator applied to p) - v'| at 64 check points inside the contact,
        relative to max |v'| (or to the operator's size when v' = 0).
    load_check : float
        |int p dX - P| / P.
    sif : dict
        Stress intensity factors at singular (corner) ends, keyed "left"/"right".  Two
        corners (flat type, Zhou et al. 2014 eqs. (5.11)-(5.12)):
        K_right = lim (x_r - X)^(-alpha) p(X) / 2^beta, K_left = lim (X - x_l)^(-beta) p(X) / 2^alpha.
        One corner (eqs. (5.23), (5.33)): K = lim |X - x_corner|^(-e) p(X), e its exponent.
    constants : SurfaceConstants
    mu_f : float
        Signed friction coefficient -direction * friction.
    """
    ends: tuple
    alpha: float
    beta: float
    kappa: int
    n: int
    load_check: float
    constants: SurfaceConstants
    load: float
    speed: float
    friction: float
    direction: int
    mu_f: float
    punch: Punch
    method: str = "numeric"
    solution: object = field(default=None, repr=False)
    _sif: dict | None = field(default=None, repr=False)
    _residual: float | None = field(default=None, repr=False)

    @property
    def residual(self) -> float:
        """max |N12 mu_f p + N11 Hc[p] - v'| at 64 Chebyshev points of the contact, relative
        to max |v'| (or to the size of N11 Hc[p] when v' = 0); computed on first access."""
        if self._residual is None:
            self._residual = _residual_of(self)
        return self._residual

    @property
    def sif(self) -> dict:
        """Stress intensity factors (see the class docstring), computed on first access."""
        if self._sif is None:
            self._sif = _sif(self.solution, self.punch, self.half_width)
        return self._sif

    # geometry ------------------------------------------------------------
    @property
    def half_width(self):
        return 0.5 * (self.ends[1] - self.ends[0])

    @property
    def center(self):
        return 0.5 * (self.ends[1] + self.ends[0])

    def _s(self, X):
        X = np.asarray(X, dtype=float)
        if not np.all(np.isfinite(X)):
            raise ContactInputError("X must be finite real numbers")
        return (X - self.center) / self.half_width

    def _check_not_singular_end(self, X, s, what):
        for end, expo in ((1.0, self.alpha), (-1.0, self.beta)):
            if expo < 0 and np.any(s == end):
                raise ContactInputError(
                    f"{what} is infinite at the singular contact end X = "
                    f"{self.ends[0] if end < 0 else self.ends[1]!r} (exponent {expo:.6g}); "
                    "evaluate at points off it")

    # fields --------------------------------------------------------------
    def pressure(self, X):
        """Contact pressure p(X) >= 0 (compressive), zero outside the contact."""
        s = self._s(X)
        self._check_not_singular_end(X, s, "the pressure")
        return self.solution(s)

    def shear(self, X):
        """Friction traction q(X) = mu_f p(X) (tau_XY(X, 0) = -q; errata conventions)."""
        return self.mu_f * self.pressure(X)

    def hilbert_pressure(self, X):
        """Hc[p](X) = (1/pi) PV int p(u)/(u - X) du at any real X (not at a singular end)."""
        s = self._s(X)
        self._check_not_singular_end(X, s, "Hc[p]")
        s = np.array(s, dtype=float, copy=True)
        # bounded ends: Hc[p] is continuous there; take the limit from inside
        s[s == 1.0] = np.nextafter(1.0, 0.0)
        s[s == -1.0] = np.nextafter(-1.0, 0.0)
        return self.solution.cauchy(s)

    def sigma_xx(self, X):
        """Surface in-plane stress sigma_XX(X, 0) = N21 p + N22 mu_f Hc[p] at any real X
        (errata item 1: N22 multiplies the shear term).  At mu_f = 0 only N21 p."""
        p = self.pressure(X)
        if self.mu_f == 0.0:
            return self.constants.N21 * p
        return self.constants.N21 * p + self.constants.N22 * self.mu_f * self.hilbert_pressure(X)



class _ClosedFormContactResult(ContactResult):
    """ContactResult whose fields come from the corrected closed forms
    (:mod:`contact.closed_form`); same interface as the numeric result."""

    def pressure(self, X):
        s = self._s(X)
        self._check_not_singular_end(X, s, "the pressure")
        return self.solution.pressure(np.asarray(X, dtype=float))

    def hilbert_pressure(self, X):
        s = self._s(X)
        self._check_not_singular_end(X, s, "Hc[p]")
        return self.solution.hilbert_pressure(np.asarray(X, dtype=float))


def _residual_of(res):
    """Relative max residual of the dominant equation at 64 Chebyshev points."""
    if res.method == "closed_form":
        return 0.0
    sol = res.solution
    s = np.cos(np.pi * (np.arange(64) + 0.5) / 64)
    f = res.punch.slope(res.half_width * s + res.center)
    psi = sol(s)
    hc = res.constants.N11 * sol.cauchy(s)
    lhs = res.constants.N12 * res.mu_f * psi + hc
    # the scale of the terms: Hc[p] can vanish by symmetry (flat punch, mu = 0) while its
    # rounding is eps |N11| max|p|
    scale = max(np.max(np.abs(f)), np.max(np.abs(hc)), abs(res.constants.N11) * np.max(np.abs(psi)),
                np.finfo(float).tiny)
    return float(np.max(np.abs(lhs - f)) / scale)


def _sif(sol, punch, h):
    e = punch.ends
    out = {}
    if e == ("singular", "singular"):
        out["right"] = h ** (-sol.alpha) * sol.endpoint_value(1)
        out["left"] = h ** (-sol.beta) * sol.endpoint_value(-1)
    elif e == ("singular", "bounded"):
        out["left"] = 2.0 ** sol.alpha * h ** (-sol.beta) * sol.endpoint_value(-1)
    elif e == ("bounded", "singular"):
        out["right"] = 2.0 ** sol.beta * h ** (-sol.alpha) * sol.endpoint_value(1)
    return out
