"""sie: Cauchy singular integral equations of the second kind, by Gauss-Jacobi collocation.

    a psi(s) + (b/pi) PV int_L psi(t)/(t - s) dt + int_L k(s,t) psi(t) dt = f(s),
    L = [-1, 1] or a union of disjoint intervals,

Public API: the equation object :class:`Equation` (validated once; its blocks are
(unknown, interval) pairs; a leading case axis solves many one-interval equations at once),
:func:`solve` (the one-call form), :class:`Solution` / :class:`SolutionBatch`,
:func:`gauss_jacobi`, the exponent rule :func:`sie_exponents`, Jacobi helpers, systems with
constant matrix coefficients on one interval (:func:`solve_system`, :mod:`sie.systems`: modes
with real or complex exponents), and the exceptions (all ``ValueError`` subclasses).  This
package knows no mechanics.

``N_MAX`` (defined in :mod:`sie.solver`) is the largest number of Jacobi coefficients per
interval that :func:`solve` accepts: the projection is dense, O(n^2) work and memory per
interval.

>>> import sie
>>> sie.N_MAX
20000

References: Erdogan, Gupta & Cook (1973); Krenk, Quart. Appl. Math. 33 (1975) 225;
Muskhelishvili, Singular Integral Equations (1953); Hale & Townsend, SIAM J. Sci. Comput. 35
(2013) A652 (the quadrature); see the documentation, Theory: the singular integral equation.
"""
from .batch import FunctionalsBatch, SolutionBatch
from .cauchy import jacobi_cauchy
from .errors import (CallableOutputError, EvaluationPointError, InconsistentEquationWarning,
                     InvalidBreakpointError, InvalidCoefficientError, InvalidEndConditionError,
                     InvalidExponentError, InvalidIntervalError, InvalidOrderError,
                     KernelSingularityError, PerIntervalArgumentError, ResidualWarning,
                     ResolutionWarning, SideConditionError, SIEInputError, SIEWarning,
                     UnsupportedEquationError)
from .gaussjacobi import gauss_jacobi
from .jacobi import jacobi_norms, jacobi_series
from .exponents import Exponents, sie_exponents
from .solution import IntervalSolution, Solution
from .solver import N_MAX as _N_MAX
from .solver import Functionals
from .block import Block
from .equation import Equation, solve
from .fixed_ends import FixedEndSolution, end_exponent, end_exponents
from .junctions import junction_exponent, solve_junctions
from .special import jacobi_moment
from .systems import (ModeExponents, SystemModes, SystemSolution, mode_exponents,
                      solve_system, system_modes)

#: Largest number of Jacobi coefficients per interval that :meth:`Equation.solve`,
#: :meth:`Equation.functionals` and :func:`solve` accept (``sie.solver.N_MAX``;
#: a larger ``n`` raises :class:`InvalidOrderError`).  The projection is dense: O(n^2) work
#: and memory per interval.  A solution that needs more terms has a
#: singularity the basis does not carry (pass ``breaks=`` at kinks of f) or should be split
#: into intervals.
N_MAX = _N_MAX

__all__ = [
    "Equation", "Block", "solve", "Solution", "IntervalSolution", "SolutionBatch",
    "Functionals", "FunctionalsBatch",
    "gauss_jacobi", "sie_exponents", "Exponents", "jacobi_cauchy", "N_MAX",
    "jacobi_series", "jacobi_norms", "jacobi_moment",
    "solve_system", "system_modes", "mode_exponents", "SystemSolution", "SystemModes",
    "ModeExponents", "end_exponent", "end_exponents", "FixedEndSolution",
    "solve_junctions", "junction_exponent",
    "SIEInputError", "InvalidOrderError", "InvalidExponentError", "InvalidCoefficientError",
    "InvalidEndConditionError", "SideConditionError", "CallableOutputError",
    "InvalidBreakpointError", "EvaluationPointError", "InvalidIntervalError",
    "PerIntervalArgumentError", "KernelSingularityError", "UnsupportedEquationError",
    "SIEWarning", "InconsistentEquationWarning", "ResidualWarning", "ResolutionWarning",
]
