"""Compile (and cache on disk) every numba kernel once, e.g. right after installation.

``make`` runs this when it sets up ``.venv``, so a user's first call loads compiled code
from the cache (~0.2 s) instead of compiling it (~1.8 s on the 2-core CI machine).
"""
from __future__ import annotations

import warnings

import numpy as np

__all__ = ["warm_up"]


def warm_up() -> None:
    """Exercise each compiled kernel once: Gauss-Jacobi on every rung of its ladder (large
    exponents included), solve for every index, with a kernel, with breaks and on two
    intervals, Cauchy transforms at real and complex points, the log potential (with breaks
    too), a system with complex modes, and a case axis of one-interval equations
    (:class:`sie.Equation`)."""
    from .equation import Equation, solve
    from .gaussjacobi import gauss_jacobi
    for n in (1, 30, 300):      # closed form, the small-n rule (_recurrence_rule), rung 3
        gauss_jacobi(n, -0.4, -0.6)
    gauss_jacobi(30, 6.0, 0.0)
    gauss_jacobi(120, 6.0, 0.0)      # large exponents past N_RECURRENCE_MAX: dd coefficients
    f = np.cos
    with warnings.catch_warnings():
        # cos violates the index -1 solvability condition; only compilation matters here
        warnings.simplefilter("ignore")
        for left, right, total in (("singular", "singular", 1.0), ("singular", "bounded", None),
                                   ("bounded", "bounded", None)):
            sol = solve(f, a=0.7, b=1.0, n=12, left=left, right=right, total=total)
            sol.phi(np.array([0.1]))
            sol.cauchy(np.array([0.2, 1.5, 1e3]))
            sol.cauchy(np.array([0.2 + 1e-3j, 3.0 - 2.0j]))
            sol.log_potential(np.array([0.2, 1.5, 3.0]))
        sol = solve(f, a=0.7, b=1.0, n=12, left="bounded", right="bounded",
                    kernel=lambda s, t: np.exp(s * t), breaks=(0.3,))
        sol.phi(np.array([0.1]))
        sol.cauchy(np.array([0.2, 1.5]))
        sol.log_potential(np.array([-1.5, 0.2, 1.5, 3.0]))   # by clusters, and from moments
        sol.log_potential(np.array([-1.5, 0.2, 1.5, 3.0]), tol=1e-9)   # the coarser rules
        # a break next to an end: the graded composite rule and near-line splits
        solve(f, a=0.7, b=1.0, n=12, left="bounded", right="bounded",
              breaks=(0.9999,)).cauchy(np.array([0.2 + 1e-3j]))
        solve(f, a=0.7, b=1.0, n=12, left="singular", right="bounded",
              intervals=[(-1.0, -0.2), (0.1, 1.0)])
        # a system with a conjugate pair of modes: the complex Jacobi kernel, the transform
        # off the interval by both of its routes
        from .systems import solve_system
        sys_sol = solve_system(lambda s: np.array([np.cos(s), np.sin(s)]),
                               np.array([[0.0, -0.3], [0.3, 0.0]]), np.eye(2), n=8,
                               left="singular", right="bounded")
        sys_sol.cauchy(np.array([0.3 + 1e-3j, 3.0 + 0j]))
        eqs = Equation(a=[0.7, -0.3], b=1.0, left="bounded", right="bounded",
                       intervals=[[(-1.0, 1.0)], [(0.0, 2.0)]])
        eqs.functionals(f, n=5)
        batch = eqs.solve(f, n=5)
        batch.phi_local(np.array([0.1]))
        batch.cauchy_limit_local(np.array([0.1]))


if __name__ == "__main__":
    warm_up()
