"""sie: Cauchy singular integral equations of the second kind, by Gauss-Jacobi collocation."""
from .errors import *  # noqa: F401,F403
from .gaussjacobi import gauss_jacobi

__all__ = ["gauss_jacobi"]
