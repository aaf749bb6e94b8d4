"""sie: Cauchy singular integral equations of the second kind, by Gauss-Jacobi collocation.

    a psi(s) + (b/pi) PV int_L psi(t)/(t - s) dt + int_L k(s,t) psi(t) dt = f(s),
    L = [-1, 1] or a union of disjoint intervals,

Public API: :func:`gauss_jacobi`, :func:`solve`, :class:`Solution`, the
exponent rule :func:`sie_exponents`, Jacobi helpers, and the exceptions
(all ``ValueError`` subclasses).  This package knows no mechanics.
"""
from .cauchy import jacobi_cauchy
from .errors import (CallableOutputError, EvaluationPointError, InconsistentEquationWarning,
                     InvalidBreakpointError, InvalidCoefficientError, InvalidEndConditionError,
                     InvalidExponentError, InvalidIntervalError, InvalidOrderError,
                     KernelSingularityError, PerIntervalArgumentError, ResidualWarning,
                     SideConditionError, SIEInputError, SIEWarning)
from .gaussjacobi import gauss_jacobi
from .jacobi import jacobi_norms, jacobi_series
from .exponents import Exponents, sie_exponents
from .solution import IntervalSolution, Solution
from .solver import N_MAX, Functionals, FunctionalsRule, dominant_functionals, solve
from .special import jacobi_moment

__all__ = [
    "gauss_jacobi", "solve", "Solution", "IntervalSolution", "sie_exponents", "Exponents",
    "jacobi_cauchy", "N_MAX",
    "dominant_functionals", "Functionals", "FunctionalsRule",
    "jacobi_series", "jacobi_norms", "jacobi_moment",
    "SIEInputError", "InvalidOrderError", "InvalidExponentError", "InvalidCoefficientError",
    "InvalidEndConditionError", "SideConditionError", "CallableOutputError",
    "InvalidBreakpointError", "EvaluationPointError", "InvalidIntervalError",
    "PerIntervalArgumentError", "KernelSingularityError",
    "SIEWarning", "InconsistentEquationWarning", "ResidualWarning",
]
