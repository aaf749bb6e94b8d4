"""sie: Cauchy singular integral equations of the second kind, by Gauss-Jacobi collocation.

    a psi(s) + (b/pi) PV int_{-1}^{1} psi(t)/(t - s) dt + int k(s,t) psi(t) dt = f(s)

Public API: :func:`gauss_jacobi`, :func:`solve`, :class:`Solution`, the
exponent rule :func:`sie_exponents`, Jacobi helpers, and the exceptions
(all ``ValueError`` subclasses).  This package knows no mechanics.
"""
from .errors import (CallableOutputError, EvaluationPointError, InvalidBreakpointError,
                     InvalidCoefficientError, InvalidEndConditionError, InvalidExponentError,
                     InvalidOrderError, SideConditionError, SIEInputError)
from .gaussjacobi import gauss_jacobi
from .jacobi import jacobi_norms, jacobi_series
from .solver import (Exponents, Functionals, FunctionalsRule, Solution, dominant_functionals,
                     sie_exponents, solve)
from .special import jacobi_moment

__all__ = [
    "gauss_jacobi", "solve", "Solution", "sie_exponents", "Exponents",
    "dominant_functionals", "Functionals", "FunctionalsRule",
    "jacobi_series", "jacobi_norms", "jacobi_moment",
    "SIEInputError", "InvalidOrderError", "InvalidExponentError", "InvalidCoefficientError",
    "InvalidEndConditionError", "SideConditionError", "CallableOutputError",
    "InvalidBreakpointError", "EvaluationPointError",
]
