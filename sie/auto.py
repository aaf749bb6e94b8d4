"""n chosen for the caller: grow the Jacobi series per interval until its tail is negligible.

``sie.solve(..., n="auto", tol=...)`` solves at n = 16 on every interval and doubles n on each
interval whose solution is not resolved to ``tol``, until all are or an interval reaches
:data:`N_AUTO_MAX` (then a :class:`sie.errors.ResolutionWarning`, and the last solution).

Resolved means (the chopping rule of chebfun, Aurentz & Trefethen 2017, in the orthonormal
scale the solver's own plateau chopping uses, :func:`sie.solver._chop_noise`):

* an interval without breaks: the last ``_RUN`` coefficients of phi, each times sqrt(h_k)
  (the norms of the weight with exponents max(alpha, -1/2), max(beta, -1/2)), are at most
  ``tol`` times the largest.  A series that reached rounding was already cut at its noise
  plateau by the solver: its tail is zero.  The coefficients of coupled intervals (or with a
  kernel) are solved together, so every interval is judged on each solve: the tail of one
  interval also reflects how well the others resolve the coupling;
* an interval with breaks (a kink that the pointwise correction carries, :mod:`sie.remainder`,
  whose series decays only algebraically by design): phi at 33 Chebyshev points agrees with
  the previous solve (at half the n) to ``tol`` of its largest value there.

The returned solution is the last one solved; its ``n`` reports what was used.
"""
from __future__ import annotations

import warnings

import numpy as np

from .errors import InvalidOrderError, ResolutionWarning, check_finite_real
from .jacobi import jacobi_norms_cached

__all__ = ["N_AUTO_START", "N_AUTO_MAX", "TOL_AUTO", "solve_auto", "series_resolved"]

#: n on every interval at the first solve of ``n="auto"``.
N_AUTO_START = 16
#: The largest n ``n="auto"`` reaches on an interval (doubling from N_AUTO_START).
N_AUTO_MAX = 4096
#: The default ``tol`` of ``n="auto"``.
TOL_AUTO = 1e-13
_RUN = 8                        # coefficients in the tail
_CHECK_U = np.cos(np.pi * (np.arange(33) + 0.5) / 33)


def check_tol(tol):
    """``tol`` of ``n="auto"`` as a float in [1e-15, 1e-2] (None: :data:`TOL_AUTO`)."""
    if tol is None:
        return TOL_AUTO
    tol = check_finite_real("tol", tol, InvalidOrderError)
    if not 1e-15 <= tol <= 1e-2:
        raise InvalidOrderError(f"tol must lie in [1e-15, 1e-2] (the relative size of the "
                                f"series' tail that counts as resolved), got {tol!r}")
    return tol


def series_resolved(c, alpha, beta, tol):
    """(resolved, tail): whether the last ``_RUN`` coefficients of c, in the orthonormal
    scale sqrt(h_k) of the weight with exponents max(alpha, -1/2), max(beta, -1/2), are at
    most ``tol`` times the largest, and that ratio."""
    c = np.asarray(c, dtype=float)
    if c.size <= _RUN:
        return False, np.inf
    s = np.abs(c) * np.sqrt(jacobi_norms_cached(c.size, max(alpha, -0.5), max(beta, -0.5)))
    top = s.max()
    if top == 0.0:
        return True, 0.0
    tail = float(s[-_RUN:].max() / top)
    return tail <= tol, tail


def _warn_again(caught, stacklevel):
    """The warnings recorded during the last solve, given at the caller's line."""
    for w in caught:
        warnings.warn(w.message, stacklevel=stacklevel + 1)


def _phi_at_checks(piece):
    return piece.phi_local(_CHECK_U)


def solve_auto(solve_at, n_intervals, has_breaks, tol, stacklevel, n_max=None):
    """Solve with n chosen per interval.

    Parameters
    ----------
    solve_at : callable
        n (a list, one per interval) -> Solution.
    n_intervals : int
        Number of intervals.
    has_breaks : sequence of bool
        Per interval: whether it has breaks (judged by the change from the previous solve).
    tol : float
        Checked (:func:`check_tol`).
    stacklevel : int
        For the warning.
    n_max : int, optional
        The largest n of the path that solves (default and at most :data:`N_AUTO_MAX`).

    Returns
    -------
    Solution
        The last solution; ``n`` per interval is what was used.
    """
    top = N_AUTO_MAX if n_max is None else min(n_max, N_AUTO_MAX)
    ns = [min(N_AUTO_START, top)] * n_intervals
    previous = None
    while True:
        # the warnings of a solve that is not the last (a residual at too small an n) are
        # not the caller's: kept, and given only for the solution returned
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            sol = solve_at(list(ns))
        pieces = sol.pieces
        grow, tails = [], []
        for j, p in enumerate(pieces):
            if has_breaks[j]:
                now = _phi_at_checks(p)
                if previous is None:
                    ok, tail = False, np.inf
                else:
                    scale = max(float(np.max(np.abs(now))), np.finfo(float).tiny)
                    tail = float(np.max(np.abs(now - previous[j]))) / scale
                    ok = tail <= tol
            else:
                ok, tail = series_resolved(p.coefficients, p.alpha, p.beta, tol)
            tails.append(tail)
            grow.append(not ok)
        if not any(grow):
            _warn_again(caught, stacklevel)
            return sol
        stuck = [j for j in range(n_intervals) if grow[j] and ns[j] >= top]
        if stuck:
            j = stuck[0]
            where = f" on interval {j}" if n_intervals > 1 else ""
            warnings.warn(
                f"n = {ns[j]}{where} does not resolve the solution to tol = {tol:g} (the "
                f"tail is {tails[j]:.1e} of its largest term): f or the kernel has a feature "
                "the Jacobi basis does not carry (a kink or jump: pass breaks=; a fixed "
                "singularity at an end: give its exponent) or needs the interval split",
                ResolutionWarning, stacklevel=stacklevel)
            _warn_again(caught, stacklevel)
            return sol
        previous = [_phi_at_checks(p) for p in pieces]
        ns = [min(2 * nj, top) if g else nj for nj, g in zip(ns, grow)]
