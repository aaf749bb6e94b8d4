"""Example punch faces (slopes dv/dX) used by the tests, the report and the benchmarks.

Each is a vectorised function of X for :class:`contact.ProfilePunch`; none has a closed-form
contact solution, which is why they exercise the numerical path (free ends, breaks, index -1).
"""
from __future__ import annotations

import numpy as np

__all__ = ["w_slope", "asymmetric_slope", "ASYMMETRIC_FACE", "rounded_flat_slope", "ROUNDED_FLAT_BREAKS",
           "HYP_D", "hyperbolic_tip_slope", "exp_wedge_slope"]


def w_slope(X):
    """W profile: dv/dX = 0.01 (X^3 - X), two pressure peaks under a large enough load."""
    return 0.01 * (X ** 3 - X)


def asymmetric_slope(X):
    """Asymmetric face: dv/dX = X/100 + X^2/3000 (on ASYMMETRIC_FACE)."""
    return X / 100.0 + X ** 2 / 3000.0


#: The extent of the asymmetric face: v = X^2/200 + X^3/9000 has a local maximum at X = -30
#: and falls without bound beyond it (back to the height of its tip at X = -45), so the face
#: must end before that; contact.solve refuses it without an extent.
ASYMMETRIC_FACE = (-20.0, 20.0)


ROUNDED_FLAT_BREAKS = (-1.0, 1.0)


def rounded_flat_slope(X):
    """Flat punch with rounded corners: dv/dX = 0 on |X| <= 1 and (X -+ 1)/50 beyond; the
    slope has kinks at X = +-1 (:data:`ROUNDED_FLAT_BREAKS`)."""
    X = np.asarray(X, dtype=float)
    return np.where(X > 1.0, (X - 1.0) / 50.0, np.where(X < -1.0, (X + 1.0) / 50.0, 0.0))


HYP_D = 0.05


def hyperbolic_tip_slope(X):
    """Rounded wedge v = 0.01 sqrt(X^2 + d^2), d = :data:`HYP_D`: analytic on the real line
    but not a polynomial (branch points at +-i d), so convergence in n is geometric, not exact."""
    return 0.01 * X / np.sqrt(X * X + HYP_D * HYP_D)


def exp_wedge_slope(X):
    """dv/dX = 0.01 exp(X) (with a corner at X = 0 it has one free end, index 0)."""
    return 0.01 * np.exp(X)
