"""Where contact results are sampled by the tests and the report: points strictly inside a
contact (never on an end, where a pressure may be infinite) and points on both sides of it."""
from __future__ import annotations

import numpy as np

__all__ = ["S40", "interior", "outside"]

# s in (-1, 1): 40 Chebyshev points, never on an end
S40 = np.cos(np.pi * (np.arange(40) + 0.5) / 40)


def interior(ends, s=S40):
    """X = centre + half-width * s on the contact ``ends`` = (x_left, x_right)."""
    xl, xr = ends
    return 0.5 * (xl + xr) + 0.5 * (xr - xl) * s


def outside(ends):
    """Six points outside the contact, from 1% to 5 contact lengths off each end."""
    xl, xr = ends
    L = xr - xl
    return np.array([xl - 5.0 * L, xl - 0.3 * L, xl - 0.01 * L, xr + 0.01 * L, xr + 0.2 * L,
                     xr + 5.0 * L])
