r"""Systems of Cauchy singular integral equations with constant matrix coefficients on one
interval, by decoupling into modes with real or complex end exponents.

    A psi(s) + (B/pi) PV int_c^d psi(t)/(t - s) dt = f(s),   c < s < d,
    psi = (psi_1, ..., psi_m),  A, B real m x m constant, B invertible.        (1)

The interval is mapped onto [-1, 1] (the Cauchy integral is invariant under s = m + h u), so
everything below is on [-1, 1]; H[phi](s) = (1/pi) PV int phi(t)/(t - s) dt.  A regular
kernel, + int K(s, t) psi(t) dt on the left, couples the modes below into one linear
system: :mod:`sie.system_kernel`.

**Decoupling** (Muskhelishvili 1953, ch. 18 for systems; Erdogan, Gupta & Cook 1973).
Multiply (1) by B^{-1} and diagonalise B^{-1} A = V diag(lambda) V^{-1}.  With phi = V^{-1} psi
and g = V^{-1} B^{-1} f the system falls apart into m scalar equations

    lambda_k phi_k + H[phi_k] = g_k,   k = 1..m,                               (2)

each the scalar equation of :mod:`sie` with a = lambda_k, b = 1.  For real A, B the
eigenvalues are real or come in conjugate pairs, with conjugate eigenvectors (enforced exactly
here), so that conjugate modes have conjugate data g and psi = V phi is real.  A matrix B^{-1} A
that is not diagonalisable (a Jordan block, or cond(V) > 1e8) is refused.

**Exponents.**  phi_k = w_k Phi_k with w = (1-s)^alpha (1+s)^beta and Phi_k smooth; alpha0
solves cot(pi alpha0) = -lambda.  The branch is

    alpha0 = 1/2 + arctan(lambda)/pi     (principal arctan),                   (3)

which for real lambda is the principal arccot in (0, 1) that :func:`sie.sie_exponents` uses
(arccot(-lambda) = pi/2 + arctan(lambda)), and which is analytic in lambda off the cuts of
arctan, the imaginary half-lines Im lambda >= 1 and <= -1 (with Re lambda = 0).  It is
continuous across the real axis, so the limit Im lambda -> 0 of a complex mode is the real
mode (no jump between the branches), and 0 < Re alpha0 < 1 everywhere off the cuts, so that
"bounded" (alpha = alpha0, beta = 1 - alpha0) and "singular" (alpha = alpha0 - 1,
beta = -alpha0) keep their meaning through the real parts; kappa = -(alpha + beta) as for a
scalar equation.  Conjugate eigenvalues give conjugate exponents (arctan(conj z) =
conj arctan(z)).  On the cuts (lambda = i t, abs(t) >= 1) Re alpha0 is 0 or 1: an exponent
would lie on the border of integrability, and such systems are refused (lambda = +-i, where
A -+ i B is singular, is the equation that is not of normal type).  The interface crack has
lambda = +-i beta_D with abs(beta_D) < 1/2 (Dundurs): alpha0 = 1/2 +- i eps,
eps = artanh(beta_D)/pi, the oscillatory exponent -1/2 +- i eps of Rice & Sih (1965).

**The dominant identity for complex exponents.**  For real (alpha, beta) with alpha + beta =
-kappa an integer and lambda = -cot(pi alpha) (sie-math item 1; Erdogan, Gupta & Cook 1973),

    lambda w P_n^{(alpha,beta)} + H[w P_n^{(alpha,beta)}]
        = -2^{-kappa} / sin(pi alpha) P_{n-kappa}^{(-alpha,-beta)},  P_{-1} = 0.  (4)

Fix kappa, n and s in (-1, 1) and let alpha be complex with -1 < Re alpha < 1 - kappa (both
weights integrable), beta = -kappa - alpha.  P_n^{(alpha,beta)}(s) is a polynomial in alpha
(DLMF 18.5.7: its coefficients are polynomials in the parameters; Szegő 1975, sec. 4.21, for
complex parameters), w(t) = exp(alpha log(1-t) + beta log(1+t)) is entire in alpha, and
H[w P_n](s) = (1/pi)[int (F(t) - F(s))/(t - s) dt + F(s) log((1-s)/(1+s))], F = w P_n, is an
integral of functions analytic in alpha and dominated, locally uniformly in alpha, by an
integrable function (the difference quotient of a function C^1 near s, the weight
(1-t)^{Re alpha}(1+t)^{Re beta} at the ends): so both sides of (4) are analytic in alpha on
the connected strip minus the integers (where 1/sin(pi alpha) has poles).  They agree on its
real segment, hence on all of it (identity theorem).  The same argument carries the
bilinear orthogonality int W P_j P_k = h_k delta_jk of P^{(-alpha,-beta)} with the complex
weight W = (1-s)^{-alpha}(1+s)^{-beta} and the closed forms of h_k and of
mu_0 = int w over to complex parameters.  Tests: the manufactured solutions of
tests/sie/test_systems.py, whose f is computed from psi by mpmath quadrature of the
principal value, not from (4).

**The solution.**  With phi_k = w_k sum_{j<n} c_kj P_j^{(alpha_k,beta_k)} and g_k =
sum_j d_kj P_j^{(-alpha_k,-beta_k)}, (4) gives c_kj = -2^{kappa} sin(pi alpha_k) d_{k,j-kappa}:
kappa = 1 leaves c_k0 free (fixed by a side condition below), kappa = -1 needs d_k0 = 0 (the
solvability condition of the mode, reported as its consistency; the returned phi solves the
equation without that part).

**The projection with a complex weight.**  d_kj is the projection of g_k on
P_j^{(-alpha,-beta)} with respect to W = (1-s)^{-Re alpha}(1+s)^{-Re beta}
exp(-i Im alpha log(1-s) - i Im beta log(1+s)), which oscillates without bound at the ends: a
Gauss rule of its real part integrates the oscillating factor only approximately.  Instead,
the projection of the interpolant: with the N = n - kappa roots x_i of
P_N^{(-Re alpha, -Re beta)} (the Gauss-Jacobi nodes of the real part), the polynomial p of
degree < N through g(x_i) is expanded in P_j^{(-alpha,-beta)}, j < N, by a solve with the
matrix P_j^{(-alpha,-beta)}(x_i) (complex three-term recurrence, DLMF 18.9.1-2).  By the
bilinear orthogonality its coefficients are exactly the W-projections of p, so the rule is
exact for every g that is a polynomial of degree < N, and otherwise is as accurate as the
interpolant (the collocation of the scalar solver).  With the rows scaled by the square roots
of the real Gauss weights and the columns to unit norm, the matrix is close to unitary
(it is unitary for real exponents): its condition number is 1.2 at lambda = 0.3 + 0.2i, 1.7 at
0.5i, 4.6 at 0.9i, 1.7 at 0.3 + 2i, the same for N = 20, 100 and 400.  For a real mode the
rule is the Gauss-Jacobi projection itself, the scalar solver's collocation.  The solve costs
O(N^3) per complex mode (hence :data:`N_MAX_SYSTEM`).

**Side conditions.**  int phi_k = mu0_k c_k0 (the basis is orthogonal to P_0 = 1 with the
weight w), mu0 = 2^{1-kappa}/Gamma(2-kappa) Gamma(1+alpha) Gamma(1+beta) =
2^{1-kappa}/Gamma(2-kappa) (-pi/sin(pi alpha)) prod_{j=0}^{-kappa} (j - alpha) (reflection
formula).  Each mode of index 1 adds one unknown c_k0; as many totals int psi_i = T_i as there
are such modes, for components i the user chooses, fix them through
int psi = V (mu0 c_0): a square linear system, refused when singular.

**Evaluation.**  psi = Re(V phi) (the imaginary part is rounding for real data; its relative
size at seven check points is :attr:`SystemSolution.imaginary`, warned above 1e-8), and
inside the interval H[psi] = V H[phi] with H[phi_k] = -lambda_k phi_k +
sum_j c_kj (-2^{-kappa}/sin(pi alpha_k)) P_{j-kappa}^{(-alpha_k,-beta_k)} from (4).  Off
the interval, per mode (:func:`mode_cauchy_off`): (Omega Phi)(z)/sin(pi alpha) plus that
polynomial at z next to the interval, Omega = (z-1)^alpha (z+1)^beta, whose jump is
2i sin(pi alpha) w; the functions of the second kind by backward recurrence elsewhere.
The log potential (1/pi) int psi log abs(x - t) dt per mode (:func:`mode_log_potential`):
by DLMF 18.9.16 and an integration by parts, c_0 times the weight's potential (closed form
at the ends, binomial series from the nearer end, moments far) plus sum_{j>=1} c_j/(2j)
times the Cauchy transform of w (1 - u^2) P_{j-1}^{(alpha+1,beta+1)}.

References
----------
N. I. Muskhelishvili, Singular Integral Equations, Noordhoff (1953), ch. 10 and 18.
F. Erdogan, G. D. Gupta and T. S. Cook, "Numerical solution of singular integral equations",
in Methods of Analysis and Solutions of Crack Problems, G. C. Sih (ed.), Noordhoff (1973),
ch. 7.  G. Szegő, Orthogonal Polynomials, 4th ed., AMS (1975), ch. 4.  NIST DLMF, ch. 18.
J. R. Rice and G. C. Sih, "Plane problems of cracks in dissimilar media", J. Appl. Mech. 32
(1965) 418-423; J. R. Rice, "Elastic fracture mechanics concepts for interfacial cracks",
J. Appl. Mech. 55 (1988) 98-103.
"""
from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass

import numpy as np
import scipy.linalg
from scipy import special as sp_special

from .errors import (CallableOutputError, EvaluationPointError, InconsistentEquationWarning,
                     InvalidCoefficientError, InvalidEndConditionError, InvalidIntervalError,
                     InvalidOrderError, ResidualWarning, ResolutionWarning, SideConditionError,
                     SIEWarning, UnsupportedEquationError,
                     check_finite_real, check_order, is_number)
from .cauchy import limit_points
from .exponents import check_coefficients, check_end, exponents_of
from .gaussjacobi import gauss_jacobi_cached
from .jacobi import (_vandermonde_into, jacobi_norms_cached, jacobi_series, jacobi_vandermonde,
                     recurrence_coefficients)
from .auto import N_AUTO_START, check_tol, series_resolved
from .solver import RESIDUAL_TOL
from .system_kernel import (KERNEL_EXTRA, kernel_modes, probe_kernel, projection_matrix,
                            real_values, weighted_rule)

__all__ = ["SystemModes", "system_modes", "ModeExponents", "mode_exponents", "solve_system",
           "solve_system_auto",
           "SystemSolution", "N_MAX_SYSTEM", "mode_cauchy_off", "mode_log_potential",
           "weight_log_potential"]

#: Largest n :func:`solve_system` accepts: a complex mode's projection is a dense solve,
#: O(n^3) (about 1 s at n = 2000 on two cores).
N_MAX_SYSTEM = 2000
#: cond(V) above this: B^{-1} A is treated as not diagonalisable.
_COND_V_MAX = 1e8
#: cond(B) above this: B is treated as singular.
_COND_B_MAX = 1e13
_IMAG_WARN = 1e-8             # relative imaginary part of psi that warns
_CONSISTENCY_TOL = 1e-8       # as sie.solver.CONSISTENCY_TOL
_CHECK_POINTS = np.cos(np.pi * (np.arange(7) + 0.5) / 7) * 0.999


# --------------------------------------------------------------------------
# modes
# --------------------------------------------------------------------------
def _real_matrix(name, M):
    try:
        arr = np.asarray(M)
    except (TypeError, ValueError) as exc:
        raise InvalidCoefficientError(f"{name} must be a real square matrix, got {M!r}: {exc}") \
            from None
    if arr.dtype.kind not in "iuf" and not (arr.dtype == object and all(
            is_number(v) for v in arr.flat)):
        raise InvalidCoefficientError(
            f"{name} must be a real square matrix (real numbers), got dtype {arr.dtype}")
    arr = arr.astype(float)
    if arr.ndim != 2 or arr.shape[0] != arr.shape[1] or arr.shape[0] == 0:
        raise InvalidCoefficientError(
            f"{name} must be a square m x m matrix with m >= 1, got shape {arr.shape}")
    if not np.isfinite(arr).all():
        raise InvalidCoefficientError(f"{name} must have finite entries, got {arr.tolist()}")
    return arr


@dataclass(frozen=True, eq=False)
class SystemModes:
    """The modes of A psi + B H[psi]: B^{-1} A = V diag(lambdas) V^{-1}.

    Returned by :func:`system_modes`.  The modes are ordered by (Re lambda, Im lambda); that
    is the order of per-mode arguments (``left``, ``right``) and results.

    Attributes
    ----------
    lambdas : ndarray of complex, shape (m,)
        The eigenvalues of B^{-1} A (conjugate pairs exactly conjugate; real ones with
        imaginary part 0).
    vectors : ndarray of complex, shape (m, m)
        V, unit columns (real for real eigenvalues, conjugate for conjugate pairs).
    project : ndarray of complex, shape (m, m)
        (B V)^{-1} = V^{-1} B^{-1}: g = project @ f.
    partner : tuple of int
        For each mode the index of its conjugate mode (itself for a real mode).
    alpha0 : ndarray of complex
        The root of cot(pi alpha0) = -lambda on the branch (3) of the module docstring.

    References
    ----------
    N. I. Muskhelishvili, Singular Integral Equations (1953), ch. 18.

    Examples
    --------
    >>> import numpy as np, sie
    >>> md = sie.system_modes([[0.0, -0.2], [0.2, 0.0]], np.eye(2))
    >>> np.round(md.lambdas, 12).tolist(), md.partner
    ([-0.2j, 0.2j], (1, 0))
    """
    lambdas: np.ndarray
    vectors: np.ndarray
    project: np.ndarray
    partner: tuple
    alpha0: np.ndarray

    @property
    def m(self) -> int:
        return self.lambdas.size

    def is_real(self, k) -> bool:
        return self.partner[k] == k


def system_modes(A, B) -> SystemModes:
    """The modes of the dominant operator A psi + (B/pi) PV int psi/(t - s) dt.

    Parameters
    ----------
    A, B : array_like, shape (m, m)
        Real, finite; B invertible.

    Returns
    -------
    SystemModes

    Raises
    ------
    InvalidCoefficientError
        A or B not real, not square, not of one size, not finite; B singular (cond(B) above
        1e13); an eigenvalue of B^{-1} A on the cuts lambda = i t, abs(t) >= 1, where an
        exponent has real part 0 or 1 (see the module docstring); a real eigenvalue whose
        exponents double precision does not resolve (as :func:`sie.sie_exponents`).
    UnsupportedEquationError
        B^{-1} A not diagonalisable to working accuracy (cond(V) above 1e8).

    References
    ----------
    N. I. Muskhelishvili, Singular Integral Equations (1953), ch. 18.

    Examples
    --------
    A real pair and a conjugate pair; the modes ordered by (Re lambda, Im lambda):

    >>> import numpy as np, sie
    >>> A = np.array([[1.0, 0.0, 0.0], [0.0, 0.2, -0.5], [0.0, 0.5, 0.2]])
    >>> md = sie.system_modes(A, np.eye(3))
    >>> np.round(md.lambdas, 12).tolist(), md.partner
    ([(0.2-0.5j), (0.2+0.5j), (1+0j)], (1, 0, 2))
    """
    A = _real_matrix("A", A)
    B = _real_matrix("B", B)
    if A.shape != B.shape:
        raise InvalidCoefficientError(f"A and B must have the same shape, got {A.shape} and "
                                      f"{B.shape}")
    return _modes_of(A.shape[0], A.tobytes(), B.tobytes())


@functools.lru_cache(maxsize=64)
def _modes_of(m, a_bytes, b_bytes):
    """:func:`system_modes` of checked matrices, memoised by their bytes (read-only
    results): a system solved again for another right-hand side, as a load or a contact
    end changes, decomposes B^{-1} A once (half of a solve at n = 64)."""
    A = np.frombuffer(a_bytes).reshape(m, m)
    B = np.frombuffer(b_bytes).reshape(m, m)
    cb = np.linalg.cond(B)
    if not cb < _COND_B_MAX:
        raise InvalidCoefficientError(
            f"B must be invertible: cond(B) = {cb:.3g} (above {_COND_B_MAX:.0e}); a singular "
            "B leaves a combination of the unknowns without a Cauchy integral")
    M = np.linalg.solve(B, A)
    lam, V = np.linalg.eig(M)
    lam = lam.astype(complex)
    V = V.astype(complex)
    order = np.lexsort((lam.imag, lam.real))
    lam, V = lam[order], V[:, order]
    m = lam.size
    partner = list(range(m))
    done = np.zeros(m, bool)
    for k in range(m):
        if done[k]:
            continue
        done[k] = True
        if lam[k].imag == 0.0:
            v = V[:, k].real
            V[:, k] = v * (np.sign(v[np.argmax(np.abs(v))]) / np.linalg.norm(v))
            continue
        # its conjugate (LAPACK returns it exactly; the nearest one otherwise)
        cand = [j for j in range(m) if not done[j]]
        j = min(cand, key=lambda i: abs(lam[i] - np.conj(lam[k])))
        done[j] = True
        v = V[:, k]
        v = v * (np.conj(v[np.argmax(np.abs(v))]) / np.abs(v[np.argmax(np.abs(v))]))
        V[:, k] = v / np.linalg.norm(v)
        lam[j] = np.conj(lam[k])
        V[:, j] = np.conj(V[:, k])
        partner[k], partner[j] = j, k
    cv = np.linalg.cond(V)
    if not cv < _COND_V_MAX:
        raise UnsupportedEquationError(
            f"B^-1 A is not diagonalisable to working accuracy (cond of its eigenvectors "
            f"{cv:.3g}, above {_COND_V_MAX:.0e}): a Jordan block couples the modes, which "
            "solve_system does not decouple")
    alpha0 = np.array([_alpha0(l) for l in lam])
    for v in (lam, V, alpha0):
        v.flags.writeable = False
    P = np.linalg.inv(B @ V)
    P.flags.writeable = False
    return SystemModes(lam, V, P, tuple(partner), alpha0)


def _alpha0(lam: complex):
    """(alpha0, 1 - alpha0) of the branch (3), each without cancellation."""
    if lam.imag == 0.0:
        a, _ = check_coefficients(lam.real, 1.0)
        y = -a
        return complex(math.atan2(1.0, y) / math.pi)
    if lam.real == 0.0 and abs(lam.imag) >= 1.0:
        raise InvalidCoefficientError(
            f"an eigenvalue of B^-1 A is lambda = {lam:.6g}, on the cut lambda = i t, "
            "|t| >= 1, of the exponent's branch: the end exponents (cot(pi alpha0) = "
            "-lambda) have real part 0 or 1, on the border of integrability (at |t| = 1 the "
            "system is not of normal type: A -+ i B is singular)")
    return _alpha0_pair(lam)[0]


def _alpha0_pair(lam: complex):
    if abs(lam) <= 1.0:
        t = complex(np.arctan(lam)) / math.pi
        return 0.5 + t, 0.5 - t
    u = complex(np.arctan(1.0 / lam)) / math.pi    # arctan(l) = +-pi/2 - arctan(1/l)
    if lam.real < 0.0:
        return -u, 1.0 + u
    return 1.0 - u, u


@dataclass(frozen=True)
class ModeExponents:
    """End exponents of one mode: phi = (1-s)^alpha (1+s)^beta Phi.

    Returned by :func:`mode_exponents`.  Complex where lambda is complex; for a real lambda
    the values of :func:`sie.sie_exponents` (a = lambda, b = 1) with zero imaginary parts.

    Attributes
    ----------
    lam : complex
        The eigenvalue (cot(pi alpha) = -lambda).
    alpha0 : complex
        The root of cot(pi alpha0) = -lambda on the branch (3) of the module docstring.
    alpha, beta : complex
        The exponents at s = 1 and s = -1.
    kappa : int
        -(alpha + beta).
    sin : complex
        sin(pi alpha).
    left, right : str
        The end choices.

    References
    ----------
    N. I. Muskhelishvili, Singular Integral Equations (1953), ch. 10; J. R. Rice and
    G. C. Sih, J. Appl. Mech. 32 (1965) 418 (the exponents -1/2 +- i eps).

    Examples
    --------
    >>> import sie
    >>> e = sie.mode_exponents(0.0, "bounded", "singular")      # a = 0: +-1/2
    >>> type(e).__name__, e.alpha, e.beta, e.kappa
    ('ModeExponents', (-0.5+0j), (0.5+0j), 0)
    """
    lam: complex
    alpha0: complex
    alpha: complex
    beta: complex
    kappa: int
    sin: complex
    left: str
    right: str

    @property
    def is_real(self) -> bool:
        return self.lam.imag == 0.0


def mode_exponents(lam, left: str, right: str) -> ModeExponents:
    """End exponents of lambda phi + H[phi] = g for real or complex lambda.

    Right end: alpha = alpha0 ("bounded") or alpha0 - 1 ("singular"); left end:
    beta = 1 - alpha0 ("bounded") or -alpha0 ("singular"); alpha0 = 1/2 + arctan(lambda)/pi
    (eq. (3) of the module docstring: 0 < Re alpha0 < 1, continuous as Im lambda -> 0).

    Parameters
    ----------
    lam : complex
        Not on the cuts lambda = i t, abs(t) >= 1.
    left, right : {"bounded", "singular"}

    Returns
    -------
    ModeExponents

    Raises
    ------
    InvalidCoefficientError
        lam not finite, or on the cuts.
    InvalidEndConditionError
        left or right not "bounded" or "singular".

    References
    ----------
    N. I. Muskhelishvili, Singular Integral Equations (1953), ch. 10 (the exponents of a
    scalar equation); J. R. Rice and G. C. Sih, J. Appl. Mech. 32 (1965) 418 (the
    interface crack's -1/2 +- i eps).

    Examples
    --------
    The interface crack's mode (lambda = i beta_D): alpha = -1/2 + i eps at a singular end,
    eps = artanh(beta_D)/pi.

    >>> import numpy as np, sie
    >>> e = sie.mode_exponents(0.3j, "singular", "singular")
    >>> round(e.alpha.real, 12), bool(abs(e.alpha.imag - np.arctanh(0.3) / np.pi) < 1e-15), e.kappa
    (-0.5, True, 1)
    """
    left, right = check_end("left", left), check_end("right", right)
    try:
        lam = complex(lam)
    except (TypeError, ValueError):
        raise InvalidCoefficientError(f"lambda must be a number, got {lam!r}") from None
    if not (math.isfinite(lam.real) and math.isfinite(lam.imag)):
        raise InvalidCoefficientError(f"lambda must be finite, got {lam!r}")
    if lam.imag == 0.0:
        a, b = check_coefficients(lam.real, 1.0)
        e = exponents_of(a, b, left, right)
        return ModeExponents(complex(lam.real), complex(e.alpha0), complex(e.alpha),
                             complex(e.beta), e.kappa, complex(e.sin), left, right)
    _alpha0(lam)                                 # refuses the cuts
    a0, a0c = _alpha0_pair(lam)
    s0 = complex(np.sin(np.pi * a0))
    alpha, sin = (a0, s0) if right == "bounded" else (-a0c, -s0)
    beta = a0c if left == "bounded" else -a0
    kappa = {("singular", "singular"): 1, ("bounded", "bounded"): -1}.get((left, right), 0)
    return ModeExponents(lam, a0, alpha, beta, kappa, sin, left, right)


# --------------------------------------------------------------------------
# Jacobi polynomials with complex parameters
# --------------------------------------------------------------------------
@functools.lru_cache(maxsize=64)
def _projector(N, alpha, beta):
    """The projection of a mode with exponents (alpha, beta) onto P_j^{(-alpha,-beta)},
    j < N: the nodes (the roots of P_N^{(-Re alpha, -Re beta)}) and a function of the
    values there returning the N coefficients (the module docstring, "The projection")."""
    ar, br = -alpha.real, -beta.real
    x, w = gauss_jacobi_cached(N, ar, br)
    if alpha.imag == 0.0 and beta.imag == 0.0:
        # Gauss-Jacobi: d_j = sum_i w_i g_i P_j(x_i) / h_j
        V = jacobi_vandermonde(N, ar, br, x)
        Wt = np.ascontiguousarray((V * w[:, None]).T / jacobi_norms_cached(N, ar, br)[:, None])
        # real and imaginary parts apart: BLAS products (a real matrix times a complex
        # vector is not one)
        return x, lambda g: Wt @ g.real + 1j * (Wt @ g.imag)
    V = jacobi_vandermonde(N, -alpha, -beta, x)
    sw = np.sqrt(w)
    S = sw[:, None] * V
    col = np.linalg.norm(S, axis=0)
    lu = scipy.linalg.lu_factor(S / col, check_finite=False)
    return x, lambda g: scipy.linalg.lu_solve(lu, sw * g, check_finite=False) / col


def _weight(e: ModeExponents, u):
    """(1-u)^alpha (1+u)^beta at u in [-1, 1] (0 at a bounded end)."""
    u = np.asarray(u, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.exp(e.alpha * np.log1p(-u) + e.beta * np.log1p(u))
    w = np.where((u == 1.0) | (u == -1.0), 0.0, w)
    return w


def _mu0(e: ModeExponents):
    """int (1-u)^alpha (1+u)^beta du = 2^{1-kappa}/Gamma(2-kappa) Gamma(1+alpha)Gamma(1+beta),
    by the reflection formula."""
    prod = -np.pi / e.sin
    for j in range(0, -e.kappa + 1):
        prod *= (j - e.alpha)
    return 2.0 ** (1 - e.kappa) / math.gamma(2 - e.kappa) * prod


# --------------------------------------------------------------------------
# the Cauchy transform of a mode off the interval
# --------------------------------------------------------------------------
_NEAR_LOG = 3.5     # N log(rho) below this: the closed form (it cancels ~rho^N <= 33)
_MILLER_LOG = 40.0  # extra terms of the backward recurrence: rho^-L <= e^-40
_F0_SERIES = 2.0    # abs(z) from which F_0 is summed from the moments (60 terms: 2^-60)
_F0_TERMS = 60
_HUGE = 1e100       # abs(z) from which two terms of the expansion at infinity are exact


def _series_at(c, a, b, z):
    """sum_j c_j P_j^{(a,b)}(z) at complex points z (complex a, b, c)."""
    V = np.empty((z.size, len(c)), dtype=complex)
    if len(c) == 0:
        return np.zeros(z.shape, dtype=complex)
    return _vandermonde_into(complex(a), complex(b), z.astype(complex), V) @ \
        np.asarray(c, dtype=complex)


def _omega(e: ModeExponents, z):
    """(z-1)^alpha (z+1)^beta = ((z-1)/(z+1))^alpha (z+1)^(-kappa), cut on [-1, 1] only (the
    two principal powers' cuts on (-inf, -1) cancel: alpha + beta = -kappa is an integer);
    above the interval it is w e^{i pi alpha}."""
    return np.exp(e.alpha * np.log((z - 1.0) / (z + 1.0))) * (z + 1.0) ** (-e.kappa)


def _moment_images(e: ModeExponents, c):
    """The coefficients of sum_j c_j P_j^{(-alpha,-beta)} that the dominant identity (4)
    gives for H[w sum c_j P_j]: -2^{-kappa}/sin(pi alpha) c shifted by kappa."""
    fac = -(2.0 ** -e.kappa) / e.sin
    if e.kappa == 1:
        return fac * c[1:]
    if e.kappa == 0:
        return fac * c
    return np.concatenate([[0.0], fac * c])


def _weight_moments(e: ModeExponents, mu0, K):
    """mu_k = int (1-t)^alpha (1+t)^beta t^k dt, k < K, by (k + alpha + beta + 2) mu_{k+1} =
    (beta - alpha) mu_k + k mu_{k-1} (integrate d/dt[(1-t)^{alpha+1} (1+t)^{beta+1} t^k])."""
    mu = np.empty(K, dtype=complex)
    mu[0] = mu0
    ab2 = (e.alpha + 1.0) + (e.beta + 1.0)
    if K > 1:
        mu[1] = (e.beta - e.alpha) * mu0 / ab2
    for k in range(1, K - 1):
        mu[k + 1] = ((e.beta - e.alpha) * mu[k] + k * mu[k - 1]) / (k + ab2)
    return mu


def f0_far(e, mu0, z):
    """F_0(z) = (1/pi) int w/(t - z) dt at abs(z) >= 2 (_F0_SERIES) from the weight's
    moments, -(1/pi) sum_{k<60} mu_k z^{-k-1} (2^-60 of the first term left out), for any
    exponents alpha, beta > -1 (``e`` needs only ``alpha`` and ``beta``; alpha + beta need
    not be an integer: the moments' recurrence holds for any)."""
    mu = _weight_moments(e, mu0, _F0_TERMS)
    zi = 1.0 / z
    acc = np.zeros(zi.shape, dtype=complex)
    for k in range(_F0_TERMS - 1, -1, -1):              # Horner in 1/z
        acc = acc * zi + mu[k]
    return -acc * zi / np.pi


def _f0(e: ModeExponents, mu0, z):
    """F_0(z) = (1/pi) int w/(t - z) dt: the closed form (Omega(z) - 2^{-kappa}
    P_{-kappa}^{(-alpha,-beta)}(z)) / sin(pi alpha) below abs(z) = _F0_SERIES (it cancels
    at most abs(z)^2 there), the moments' series -(1/pi) sum mu_k z^{-k-1} beyond."""
    out = np.empty(z.shape, dtype=complex)
    far = np.abs(z) >= _F0_SERIES
    if far.any():
        out[far] = f0_far(e, mu0, z[far])
    near = ~far
    if near.any():
        zn = z[near]
        poly = _series_at(_moment_images(e, np.array([1.0 + 0j])), -e.alpha, -e.beta, zn)
        out[near] = _omega(e, zn) / e.sin + poly
    return out


def mode_cauchy_off(e: ModeExponents, mu0, c, z, f0=None):
    """(1/pi) int_{-1}^{1} w(t) sum_j c_j P_j^{(alpha,beta)}(t) / (t - z) dt at z off [-1, 1]
    (complex, or real with abs(z) > 1), for real or complex exponents.

    ``f0``: None for a mode (alpha + beta = -kappa an integer: the closed forms below);
    otherwise F_0 = (1/pi) int w/(t - z) dt at the points z (an array of their shape), for
    any real exponents (alpha + beta not an integer: :mod:`sie.fixed_ends`, whose ``e``
    needs only ``alpha`` and ``beta``).  Then the near points run the recurrence forward
    from F_0 and F_1 = P_1(z) F_0 + A_0 mu_0 / pi (stable there: a rounding error grows at
    most like rho^N < 33), and the backward recurrence is normalised by the given F_0.

    Near the interval (N log(rho) < 3.5, rho the Bernstein parameter of z, N = len(c)): the
    closed form (Omega(z) Phi(z)) / sin(pi alpha) + sum img_j P_j^{(-alpha,-beta)}(z) (the
    sectionally holomorphic function whose jump is w Phi and whose boundary values give the
    dominant identity (4); Muskhelishvili 1953, sec. 29), which cancels at most ~rho^N.
    Elsewhere the functions of the second kind F_j(z) = (1/pi) int w P_j/(t - z), the
    minimal solution of the three-term recurrence for j >= 1, by backward recurrence
    (Miller's algorithm, Gautschi, SIAM Rev. 9 (1967) 24) from j = N + 40/log(rho),
    normalised by F_0 (:func:`_f0`), summed against c."""
    z = np.asarray(z, dtype=complex).ravel()
    c = np.asarray(c, dtype=complex)
    N = c.size
    out = np.zeros(z.shape, dtype=complex)
    if N == 0 or z.size == 0:
        return out
    rho = np.abs(z + np.sqrt(z - 1.0) * np.sqrt(z + 1.0))
    log_rho = np.log(np.maximum(rho, 1.0 + 1e-300))
    near = N * log_rho < _NEAR_LOG
    if f0 is not None:
        f0 = np.asarray(f0, dtype=complex).ravel()
    if near.any() and f0 is None:
        zn = z[near]
        out[near] = (_omega(e, zn) * _series_at(c, e.alpha, e.beta, zn) / e.sin
                     + _series_at(_moment_images(e, c), -e.alpha, -e.beta, zn))
    elif near.any():
        out[near] = _forward_sum(e, mu0, c, z[near], f0[near])
    huge = np.abs(z) > _HUGE
    if huge.any():
        # -(1/pi)(M_0/z + M_1/z^2), M_k = int w Phi t^k: the rest is below z^-2 ~ 1e-200
        mu = _weight_moments(e, mu0, 3)
        M0 = c[0] * mu[0]
        M1 = c[0] * mu[1]
        if N > 1:               # int w P_1 t, P_1 = (a + 1) + (a + b + 2)(t - 1)/2
            ab2 = (e.alpha + 1.0) + (e.beta + 1.0)
            M1 += c[1] * ((e.alpha + 1.0) * mu[1] + 0.5 * ab2 * (mu[2] - mu[1]))
        zi = 1.0 / z[huge]
        out[huge] = -(M0 * zi + M1 * zi * zi) / np.pi
    far = ~near & ~huge
    if far.any():
        zf = z[far]
        J = N + int(np.ceil(_MILLER_LOG / float(log_rho[far].min()))) + 1
        A, B, C = recurrence_coefficients(e.alpha, e.beta, J)
        f_next = np.zeros(zf.shape, dtype=complex)          # f_{k+1}
        f_k = np.full(zf.shape, 1e-200 + 0j)                # f_k, k = J - 1
        acc = np.zeros(zf.shape, dtype=complex)
        for k in range(J - 1, 0, -1):
            if k < N:
                acc += c[k] * f_k
            f_prev = ((A[k - 1] * zf + B[k - 1]) * f_k - f_next) / C[k - 1]
            f_next, f_k = f_k, f_prev
            big = np.abs(f_k) > 1e100                          # keep the scale in range
            if big.any():
                f_k[big] *= 1e-100
                f_next[big] *= 1e-100
                acc[big] *= 1e-100
        acc += c[0] * f_k                                    # f_k is now f_0
        out[far] = acc * ((_f0(e, mu0, zf) if f0 is None else f0[far]) / f_k)
    return out


def _forward_sum(e, mu0, c, z, F0):
    """sum_j c_j F_j(z) by the recurrence run forward from F_0 (given) and F_1 = P_1(z) F_0
    + A_0 mu_0 / pi (P_1(t) - P_1(z) = A_0 (t - z), int w (t - z)/(t - z) = mu_0)."""
    N = c.size
    a0 = 0.5 * ((e.alpha + 1.0) + (e.beta + 1.0))
    acc = c[0] * F0
    if N == 1:
        return acc
    f_prev = F0
    f_k = ((e.alpha + 1.0) + a0 * (z - 1.0)) * F0 + a0 * mu0 / np.pi
    acc = acc + c[1] * f_k
    A, B, C = recurrence_coefficients(e.alpha, e.beta, N - 1)
    for k in range(1, N - 1):
        f_prev, f_k = f_k, (A[k - 1] * z + B[k - 1]) * f_k - C[k - 1] * f_prev
        acc = acc + c[k + 1] * f_k
    return acc


# --------------------------------------------------------------------------
# the logarithmic potential of a mode
# --------------------------------------------------------------------------
_L0_TERMS = 60      # terms of the end series (ratio <= 1/2) and of the series in 1/v


def _end_power_integral(a, b, sgn, T):
    """int_0^T tau^a (2 + sgn tau)^b dtau for 0 <= T <= 1 (Re a > -1, complex a, b, sgn =
    +-1): the binomial series 2^b T^{a+1} sum_k binom(b, k) (sgn T/2)^k / (a + 1 + k)
    (termwise integration of (1 + sgn tau/2)^b, which converges uniformly for tau <= 1:
    60 terms leave (1/2)^60 of the first), exact to rounding."""
    T = np.asarray(T, dtype=float)
    out = np.zeros(T.shape, dtype=complex)
    pos = T > 0.0
    if not pos.any():
        return out
    t = T[pos]
    r = 0.5 * sgn * t
    acc = np.zeros(t.shape, dtype=complex)
    coef = 1.0 + 0j
    pw = np.ones(t.shape)
    for k in range(_L0_TERMS):
        acc += (coef / (a + 1.0 + k)) * pw
        coef *= (b - k) / (k + 1.0)
        pw = pw * r
    out[pos] = 2.0 ** b * np.exp((a + 1.0) * np.log(t)) * acc
    return out


def _linear_integral(p, lo, hi):
    """int_lo^hi p for p of degree <= 1 (a callable on arrays): (hi - lo) p((lo + hi)/2)."""
    return (hi - lo) * p(0.5 * (lo + hi))


def _distances(v, dist):
    """(1 - v, 1 + v): from the caller's physical coordinate where given (``dist``), which
    keeps their relative precision next to the ends, else from v."""
    if dist is None:
        return 1.0 - v, 1.0 + v
    return (np.asarray(dist[0], dtype=float).ravel(), np.asarray(dist[1], dtype=float).ravel())


def weight_log_potential(e: ModeExponents, mu0, v, dist=None):
    r"""L_0(v) = (1/pi) int_{-1}^{1} w(u) log abs(v - u) du, w = (1-u)^alpha (1+u)^beta, at
    real v (complex exponents; any v, finite at the ends), complex.

    Parameters
    ----------
    e : ModeExponents
        The mode's exponents (alpha + beta = -kappa an integer).
    mu0 : complex
        int w (:attr:`SystemSolution.mu0`).
    v : array_like of float
        Real points.
    dist : (array_like, array_like), optional
        (1 - v, 1 + v) from the caller's coordinate (their relative precision next to the
        ends matters where w is singular).

    Returns
    -------
    ndarray of complex, the size of v (flat).

    Notes
    -----
    At the ends, the derivative of the Beta integral in an exponent (DLMF 5.12.1):
    L_0(1) = (mu_0/pi) (log 2 + digamma(alpha + 1) - digamma(alpha + beta + 2)), L_0(-1)
    the same with alpha and beta exchanged.  Elsewhere from the nearer end, dL_0/dv = -H[w]
    inside and -F_0 outside: inside (0 <= v < 1) L_0(v) = L_0(1) + int_v^1 (-lambda w + p),
    H[w] = -lambda w + p by the dominant identity (4) of the module docstring (p the image
    of c = (1), of degree <= 1); beside (1 < v < 2) L_0(v) = L_0(1) - int_1^v
    (Omega/sin(pi alpha) + p), F_0 as in :func:`_f0`; v < 0 the same from -1 (Omega =
    (-1)^kappa abs(v-1)^alpha abs(v+1)^beta for v < -1).  The integrals of the weight are
    binomial series in the distance to the end, at most 1 (:func:`_end_power_integral`,
    60 terms: 2^-60).  For abs(v) >= 2 the expansion (1/pi) [mu_0 log abs(v) -
    sum_{j>=1} mu_j / (j v^j)] with the weight's moments (:func:`_weight_moments`).

    References
    ----------
    NIST DLMF 5.12.1 (the Beta integral), 5.2.2 (digamma); N. I. Muskhelishvili, Singular
    Integral Equations (1953), sec. 29.

    Examples
    --------
    >>> import numpy as np
    >>> from sie.systems import mode_exponents, weight_log_potential
    >>> e = mode_exponents(0.0, "bounded", "bounded")        # w = sqrt(1 - u^2)
    >>> v = np.array([0.0, 1.0])
    >>> L = weight_log_potential(e, np.pi / 2, v)
    >>> bool(np.allclose(L, v ** 2 / 2 - 0.25 - np.log(2.0) / 2, rtol=0, atol=1e-15))
    True
    """
    v = np.asarray(v, dtype=float).ravel()
    dr, dl = _distances(v, dist)
    out = np.empty(v.shape, dtype=complex)
    al, be = e.alpha, e.beta
    dig_ab = sp_special.digamma(al + be + 2.0)
    l_right = mu0 / np.pi * (math.log(2.0) + sp_special.digamma(al + 1.0) - dig_ab)
    l_left = mu0 / np.pi * (math.log(2.0) + sp_special.digamma(be + 1.0) - dig_ab)
    img = _moment_images(e, np.array([1.0 + 0j]))

    def p(s):
        return _series_at(img, -al, -be, np.asarray(s, dtype=complex))
    av = np.abs(v)
    far = av >= 2.0
    if far.any():
        vf = v[far]
        K = _L0_TERMS
        top = float(np.max(1.0 / np.abs(vf)))
        if top < 0.5:
            K = max(1, min(_L0_TERMS, math.ceil(_L0_TERMS * math.log(2.0) / -math.log(top))))
        mu = _weight_moments(e, mu0, K + 1)
        y = 1.0 / vf
        acc = np.zeros(vf.shape, dtype=complex)
        for j in range(K, 0, -1):                      # Horner in 1/v
            acc = (acc + mu[j] / j) * y
        out[far] = (mu0 * np.log(np.abs(vf)) - acc) / np.pi
    near = ~far
    right = near & (v >= 0.0) & (dr <= 0.0)            # at or beside the right end
    left = near & (v < 0.0) & (dl <= 0.0)
    sel = right & (dr == 0.0)
    out[sel] = l_right
    sel = left & (dl == 0.0)
    out[sel] = l_left
    sel = near & (v >= 0.0) & (dr > 0.0)
    if sel.any():
        out[sel] = l_right + (-e.lam * _end_power_integral(al, be, -1.0, dr[sel])
                              + dr[sel] * p(0.5 * (1.0 + v[sel])))
    sel = near & (v < 0.0) & (dl > 0.0)
    if sel.any():
        out[sel] = l_left - (-e.lam * _end_power_integral(be, al, -1.0, dl[sel])
                             + dl[sel] * p(0.5 * (v[sel] - 1.0)))
    sel = right & (dr < 0.0)
    if sel.any():
        out[sel] = l_right - (_end_power_integral(al, be, 1.0, -dr[sel]) / e.sin
                              - dr[sel] * p(0.5 * (1.0 + v[sel])))
    sel = left & (dl < 0.0)
    if sel.any():
        out[sel] = l_left + ((-1.0) ** e.kappa * _end_power_integral(be, al, 1.0, -dl[sel])
                             / e.sin - dl[sel] * p(0.5 * (v[sel] - 1.0)))
    return out


def _shifted(e: ModeExponents):
    """The exponents raised by one, as :func:`mode_cauchy_off`, :func:`_forward_sum` and
    :func:`f0_far` need them (alpha and beta only)."""
    from types import SimpleNamespace
    return SimpleNamespace(alpha=e.alpha + 1.0, beta=e.beta + 1.0)


def mode_log_potential(e: ModeExponents, mu0, c, v, dist=None):
    r"""(1/pi) int_{-1}^{1} w(u) sum_j c_j P_j^{(alpha,beta)}(u) log abs(v - u) du at real v
    (any; finite at the ends), for a mode with real or complex exponents; complex.

    Parameters
    ----------
    e : ModeExponents
        The mode's exponents.
    mu0 : complex
        int w.
    c : array_like of complex
        The mode's Jacobi coefficients.
    v : array_like of float
        Real points.
    dist : (array_like, array_like), optional
        (1 - v, 1 + v) from the caller's coordinate.

    Returns
    -------
    ndarray of complex, the size of v (flat).

    Notes
    -----
    For j >= 1, w P_j = -(1/(2j)) d/du [w~ P_{j-1}^{(alpha+1,beta+1)}], w~ = (1 - u^2) w
    (DLMF 18.9.16; for complex parameters by the identity theorem, as the dominant identity
    in the module docstring), and w~ vanishes at both ends (Re alpha, Re beta > -1), so
    integrating by parts

        (1/pi) int w P_j log abs(v - u) du
            = (1/(2j)) (1/pi) int w~ P_{j-1}^{(alpha+1,beta+1)} / (u - v) du,

    a principal value for v inside, continuous up to the ends (w~ is Hoelder there).  That
    is the functions of the second kind F~_k of the shifted weight, from
    F~_0(v) = (1 - v^2) F_0(v) - (mu_1 + v mu_0)/pi (as 1 - u^2 = (1 - v^2) - (u - v)(u + v)),
    F_0 = H[w] = -lambda w + p on [-1, 1] (the dominant identity (4); the first term
    vanishes at the ends), the closed form Omega/sin(pi alpha) + p beside it
    (:func:`_f0`), the shifted weight's moments for abs(v) >= 2 (:func:`f0_far`), with
    mu~_0 = int w~ = 4 mu_0 (alpha+1)(beta+1) / ((alpha+beta+2)(alpha+beta+3)) (Beta
    function).  The recurrence runs forward from F~_0 on [-1, 1] (the mean of the two
    boundary values satisfies it; both solutions oscillate there, so it is stable), and off
    it as in :func:`mode_cauchy_off` (forward near, Miller's backward recurrence away).
    j = 0: c_0 L_0 (:func:`weight_log_potential`).

    References
    ----------
    NIST DLMF 18.9.16; N. I. Muskhelishvili, Singular Integral Equations (1953), sec. 29
    (boundary values at the ends).

    Examples
    --------
    w = sqrt(1 - u^2), P_1^{(1/2,1/2)} = 3u/2: the potential is (1/2) H[(1 - u^2)^{3/2}]
    = (v^3 - 3v/2)/2 on [-1, 1]:

    >>> import numpy as np
    >>> from sie.systems import mode_exponents, mode_log_potential
    >>> e = mode_exponents(0.0, "bounded", "bounded")
    >>> v = np.array([0.3, 1.0])
    >>> L = mode_log_potential(e, np.pi / 2, np.array([0.0, 1.0]), v)
    >>> bool(np.allclose(L, (v ** 3 - 1.5 * v) / 2, rtol=0, atol=1e-15))
    True
    """
    v = np.asarray(v, dtype=float).ravel()
    dr, dl = _distances(v, dist)
    c = np.asarray(c, dtype=complex)
    out = np.zeros(v.shape, dtype=complex)
    if c.size == 0 or v.size == 0:
        return out
    out += c[0] * weight_log_potential(e, mu0, v, (dr, dl))
    if c.size == 1:
        return out
    es = _shifted(e)
    ab = e.alpha + e.beta
    mu0s = 4.0 * mu0 * (e.alpha + 1.0) * (e.beta + 1.0) / ((ab + 2.0) * (ab + 3.0))
    mu1 = _weight_moments(e, mu0, 2)[1]
    cs = c[1:] / (2.0 * np.arange(1, c.size))
    img = _moment_images(e, np.array([1.0 + 0j]))
    f0s = np.empty(v.shape, dtype=complex)
    on = (dr >= 0.0) & (dl >= 0.0)
    if on.any():
        s, r, l = v[on], dr[on], dl[on]
        end = (r == 0.0) | (l == 0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            w = np.where(end, 0.0, np.exp(e.alpha * np.log(r) + e.beta * np.log(l)))
        h0 = -e.lam * w + _series_at(img, -e.alpha, -e.beta, s.astype(complex))
        f0s[on] = np.where(end, 0.0, r * l * h0) - (mu1 + s * mu0) / np.pi
        out[on] += _forward_sum(es, mu0s, cs, s.astype(complex), f0s[on])
    far = np.abs(v) >= 2.0
    beside = ~on & ~far
    if beside.any():
        s, r, l = v[beside], dr[beside], dl[beside]
        omega = np.exp(e.alpha * np.log(-r / l)) * l ** (-float(e.kappa))
        f0 = omega / e.sin + _series_at(img, -e.alpha, -e.beta, s.astype(complex))
        f0s[beside] = r * l * f0 - (mu1 + s * mu0) / np.pi
    if far.any():
        f0s[far] = f0_far(es, mu0s, v[far].astype(complex))
    off = ~on
    if off.any():
        out[off] += mode_cauchy_off(es, mu0s, cs, v[off].astype(complex), f0=f0s[off])
    return out


# --------------------------------------------------------------------------
# the solver
# --------------------------------------------------------------------------
def _per_mode(name, v, m):
    if isinstance(v, str):
        return [check_end(name, v)] * m
    try:
        vals = list(v)
    except TypeError:
        raise InvalidEndConditionError(
            f'{name} must be "bounded", "singular" or a sequence of them (one per mode), '
            f"got {v!r}") from None
    if len(vals) != m:
        raise InvalidEndConditionError(
            f"{name} must be one choice for all {m} modes or a sequence of {m} (one per mode, "
            f"in the order of system_modes), got {len(vals)} entries")
    return [check_end(f"{name}[{k}]", x) for k, x in enumerate(vals)]


def _check_interval(interval):
    try:
        c, d = (float(v) for v in interval)
    except (TypeError, ValueError):
        raise InvalidIntervalError(f"interval must be a (c, d) pair, got {interval!r}") from None
    if not (math.isfinite(c) and math.isfinite(d) and c < d):
        raise InvalidIntervalError(f"interval = {interval!r}: need finite c < d")
    return c, d


def _call_f(f, s, m):
    if not callable(f):
        raise CallableOutputError(f"f must be a vectorised callable f(s), got {type(f).__name__}")
    try:
        out = f(s)
    except Exception as exc:
        raise CallableOutputError(f"f raised {type(exc).__name__}: {exc}") from exc
    out = real_values("f", out)
    if out.shape != (m, s.size):
        raise CallableOutputError(
            f"f must return shape (m, len(s)) = ({m}, {s.size}) when called with an array of "
            f"{s.size} points, got {out.shape}")
    if not np.isfinite(out).all():
        k, i = np.argwhere(~np.isfinite(out))[0]
        raise CallableOutputError(f"f returned a non-finite value in component {k} at "
                                  f"s = {float(s[i])!r}")
    return out


def _totals(total, exps, m):
    """(indices of the components given, their values): as many as modes of index 1."""
    p = sum(e.kappa == 1 for e in exps)
    if total is None:
        if p:
            raise SideConditionError(
                f"total is required: {p} mode(s) have index 1 (both ends singular); give "
                f"int psi_i for {p} component(s) (a sequence of {m} with None elsewhere)")
        return [], []
    try:
        vals = list(total)
    except TypeError:
        raise SideConditionError(f"total must be a sequence of {m} (numbers or None), got "
                                 f"{total!r}") from None
    if len(vals) != m:
        raise SideConditionError(f"total must hold {m} entries (one per component, None where "
                                 f"not given), got {len(vals)}")
    idx = [i for i, v in enumerate(vals) if v is not None]
    if len(idx) != p:
        raise SideConditionError(
            f"total gives {len(idx)} value(s), but {p} mode(s) have index 1 (both ends "
            f"singular): give exactly {p} (None elsewhere)")
    return idx, [check_finite_real(f"total[{i}]", vals[i], SideConditionError) for i in idx]


def solve_system(f, A, B, *, n, left, right, total=None, interval=(-1.0, 1.0), kernel=None):
    """Solve A psi + (B/pi) PV int_c^d psi(t)/(t - s) dt [+ int_c^d K(s, t) psi(t) dt] = f(s)
    for psi = (psi_1..psi_m).

    Parameters
    ----------
    f : callable
        Vectorised: f(s) for s of shape (N,) returns shape (m, N), real and finite.
    A, B : array_like, shape (m, m)
        Real constant coefficients, B invertible (see :func:`system_modes`).
    n : int
        Jacobi coefficients per mode (>= 2 where a mode has index 1), at most
        :data:`N_MAX_SYSTEM`.
    left, right : {"bounded", "singular"} or a sequence of them
        The behaviour of each mode at s = c and s = d, one for all modes or one per mode in
        the order of :func:`system_modes` (conjugate modes must share their choices, so that
        psi is real).
    total : sequence of m (float or None), optional
        int_c^d psi_i ds for as many components i as there are modes of index 1 (both ends
        singular), None for the others.
    interval : (c, d), optional
        Default (-1, 1).
    kernel : callable, optional
        A regular kernel K(s, t), a real m x m matrix of functions bounded on [c, d]^2:
        called with arrays s, t of one shape it returns shape (m, m) + that shape
        (``kernel(s, t)[i, j]`` multiplies psi_j in equation i).  The modes then couple and
        are solved together (:mod:`sie.system_kernel`).

    Returns
    -------
    SystemSolution

    Raises
    ------
    InvalidCoefficientError, UnsupportedEquationError
        As :func:`system_modes`.
    InvalidEndConditionError
        A choice not "bounded"/"singular", a sequence of the wrong length, or conjugate modes
        with different choices.
    InvalidOrderError
        n not an integer >= 1 (>= 2 with a mode of index 1), or above N_MAX_SYSTEM.
    SideConditionError
        ``total`` missing, of the wrong length, with a count of values other than the number
        of modes of index 1, not finite, or with components that do not fix those modes.
    InvalidIntervalError
        ``interval`` not a finite (c, d) with c < d.
    CallableOutputError
        f not callable, raising, or not returning finite real values of shape (m, N); the
        kernel raising or not returning finite real values of shape (m, m) + shape.
    KernelSingularityError
        A kernel that grows without bound toward a corner of [c, d]^2.
    UnsupportedEquationError
        A kernel that makes the collocation system singular (an eigenvalue of the equation).

    Warns
    -----
    InconsistentEquationWarning
        A mode of index -1 whose solvability residual d_0 exceeds 1e-8 max abs(g_k).
    SIEWarning
        The imaginary part of V phi above 1e-8 of psi (it is rounding for real data).

    Notes
    -----
    The method and its derivation: the module docstring and the documentation, Theory:
    systems of singular integral equations.

    References
    ----------
    N. I. Muskhelishvili, Singular Integral Equations (1953), ch. 18; F. Erdogan, G. D. Gupta
    and T. S. Cook (1973), ch. 7 (the Jacobi basis and its dominant identity).

    Examples
    --------
    Two copies of (1/pi) PV int sqrt(1 - t^2)/(t - s) dt = -s, mixed by B = [[1, 1], [0, 1]]:

    >>> import numpy as np, sie
    >>> B = np.array([[1.0, 1.0], [0.0, 1.0]])
    >>> sol = sie.solve_system(lambda s: B @ np.array([-s, -2 * s]), np.zeros((2, 2)), B,
    ...                        n=4, left="bounded", right="bounded")
    >>> np.round(sol(np.array([0.0, 0.6])), 12).tolist()
    [[1.0, 0.8], [2.0, 1.6]]
    """
    modes = system_modes(A, B)
    m = modes.m
    lefts, rights = _per_mode("left", left, m), _per_mode("right", right, m)
    for k, j in enumerate(modes.partner):
        if (lefts[k], rights[k]) != (lefts[j], rights[j]):
            raise InvalidEndConditionError(
                f"modes {k} and {j} (lambda = {modes.lambdas[k]:.6g} and its conjugate) must "
                f"share their end choices so that psi is real; got {lefts[k]}/{rights[k]} "
                f"and {lefts[j]}/{rights[j]}")
    exps = tuple(mode_exponents(l, a, b) for l, a, b in zip(modes.lambdas, lefts, rights))
    any1 = any(e.kappa == 1 for e in exps)
    n = check_order(n, 2 if any1 else 1, " (2 where a mode has index 1)" if any1 else "")
    if n > N_MAX_SYSTEM:
        raise InvalidOrderError(f"n = {n} is beyond the limit {N_MAX_SYSTEM} of solve_system "
                                "(a complex mode's projection is a dense O(n^3) solve)")
    c, d = _check_interval(interval)
    idx, tvals = _totals(total, exps, m)
    mid, h = 0.5 * (c + d), 0.5 * (d - c)
    mu0 = np.array([_mu0(e) for e in exps])
    if kernel is not None:
        coeffs, consistency, scales = _coefficients_with_kernel(f, kernel, modes, exps, n, idx,
                                                                tvals, mu0, c, d)
        _warn_inconsistent(modes, consistency, scales)
        return _finish(modes, exps, coeffs, consistency, (c, d), n, mu0)

    # sample f once at the nodes of all modes (conjugate modes share theirs)
    rules = [_projector(n - e.kappa, e.alpha, e.beta) for e in exps]
    keys, starts, xs = {}, [], []
    pos = 0
    for e, (x, _) in zip(exps, rules):
        key = (n - e.kappa, e.alpha.real, e.beta.real)
        if key not in keys:
            keys[key] = pos
            xs.append(x)
            pos += x.size
        starts.append(keys[key])
    u_all = np.concatenate(xs + [_CHECK_POINTS])
    F = _call_f(f, mid + h * u_all, m)
    G = modes.project @ F                      # g = V^-1 B^-1 f at every node

    coeffs, consistency, scales = [], [], []
    for k, (e, (x, proj), st) in enumerate(zip(exps, rules, starts)):
        g = G[k, st:st + x.size]
        dk = proj(g)
        fac = -(2.0 ** e.kappa) * e.sin
        if e.kappa == 1:
            ck = np.concatenate([[0.0], fac * dk])
            consistency.append(None)
        elif e.kappa == 0:
            ck = fac * dk
            consistency.append(None)
        else:
            ck = fac * dk[1:]
            consistency.append(complex(dk[0]))
        scales.append(float(np.max(np.abs(g))))
        coeffs.append(ck.astype(complex))
    _warn_inconsistent(modes, consistency, scales)

    if idx:
        ones = [k for k, e in enumerate(exps) if e.kappa == 1]
        others = [k for k, e in enumerate(exps) if e.kappa != 1]
        V = modes.vectors
        known = sum((V[idx, k] * mu0[k] * coeffs[k][0] for k in others),
                    np.zeros(len(idx), complex))
        Msys = V[np.ix_(idx, ones)] * mu0[ones]
        if not np.linalg.cond(Msys) < 1e12:
            raise SideConditionError(
                f"the totals given (components {idx}) do not fix the null space of the modes of "
                f"index 1 (modes {ones}): their rows of V are dependent; give other components")
        x0 = np.linalg.solve(Msys, np.asarray(tvals) / h - known)
        for k, v in zip(ones, x0):
            coeffs[k][0] = v
    return _finish(modes, exps, coeffs, consistency, (c, d), n, mu0)


def solve_system_auto(f, A, B, *, left, right, total=None, interval=(-1.0, 1.0), kernel=None,
                      tol=None):
    """:func:`solve_system` with n chosen: from :data:`sie.auto.N_AUTO_START` doubling until
    every mode's series has a tail (its last 8 coefficients, in the orthonormal scale of the
    weight with the exponents' real parts) at most ``tol`` times its largest term, the
    chopping rule of :mod:`sie.auto`; at most :data:`N_MAX_SYSTEM` (then a ResolutionWarning
    and the last solution).  The solution's ``n`` is what was used; the warnings are those
    of the last solve.

    Parameters
    ----------
    f, A, B, left, right, total, interval, kernel
        As :func:`solve_system`.
    tol : float, optional
        The relative tail that counts as resolved, in [1e-15, 1e-2] (default
        :data:`sie.auto.TOL_AUTO`).

    Returns
    -------
    SystemSolution

    References
    ----------
    K. Aurentz and L. N. Trefethen, "Chopping a Chebyshev series", ACM Trans. Math. Softw. 43
    (2017) 33.

    Examples
    --------
    >>> import numpy as np, sie
    >>> A = np.array([[0.0, -0.3], [0.3, 0.0]])
    >>> sol = sie.solve(lambda s: np.array([np.cos(s), np.sin(s)]), a=A, b=np.eye(2),
    ...                 n="auto", left="bounded", right="singular")
    >>> sol.n
    32
    """
    tol = check_tol(tol)
    n = N_AUTO_START
    while True:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            sol = solve_system(f, A, B, n=n, left=left, right=right, total=total,
                               interval=interval, kernel=kernel)
        tail = max(series_resolved(np.abs(c), e.alpha.real, e.beta.real, tol)[1]
                   for e, c in zip(sol.exponents, sol.coefficients))
        last = 2 * n > N_MAX_SYSTEM
        if tail <= tol or last:
            if tail > tol:
                warnings.warn(
                    f"solve_system: n = {n} does not resolve the solution to tol = {tol:g} "
                    f"(a mode's tail is {tail:.1e} of its largest term; n stops at "
                    f"{N_MAX_SYSTEM}): f or the kernel has a feature the Jacobi basis does not "
                    "carry (a kink or jump) or needs a larger tol", ResolutionWarning,
                    stacklevel=3)
            for w in caught:
                warnings.warn(w.message, stacklevel=3)
            return sol
        n *= 2


def _warn_inconsistent(modes, consistency, scales):
    """InconsistentEquationWarning for each mode of index -1 whose solvability residual
    exceeds _CONSISTENCY_TOL of its data's size."""
    for k, (cons, scale) in enumerate(zip(consistency, scales)):
        if cons is not None and abs(cons) > _CONSISTENCY_TOL * max(scale, 1e-300):
            warnings.warn(
                f"solve_system: mode {k} (lambda = {modes.lambdas[k]:.6g}) has both ends "
                f"bounded (index -1) and its data violate the solvability condition: "
                f"consistency = {abs(cons):.3g} (max|g| = {scale:.3g}); the returned psi "
                "solves the system with that part taken out", InconsistentEquationWarning,
                stacklevel=3)


def _coefficients_with_kernel(f, kernel, modes, exps, n, idx, tvals, mu0, c, d):
    """The coefficients c_k of every mode, the consistencies of the modes of index -1 and
    the sizes of their data, from the linear system (3) of :mod:`sie.system_kernel`."""
    m = modes.m
    mid, h = 0.5 * (c + d), 0.5 * (d - c)
    probe_kernel(kernel, m, c, d)
    projections = [projection_matrix(n - e.kappa, e.alpha, e.beta) for e in exps]
    Q = n + KERNEL_EXTRA
    rules = [weighted_rule(Q, n, e.alpha, e.beta) for e in exps]
    xs = np.concatenate([x for x, _ in projections])
    # g = V^-1 B^-1 f at the nodes, and at the residual's check points after them
    G = modes.project @ _call_f(f, mid + h * np.concatenate([xs, _CHECK_POINTS]), m)
    ys = np.concatenate([y for y, _ in rules])
    Kt = kernel_modes(kernel, modes, h, mid, np.concatenate([xs, _CHECK_POINTS]), ys)
    M = np.zeros((m * n, m * n), dtype=complex)
    R = np.zeros(m * n, dtype=complex)
    solvability, scales = {}, []
    row = start = 0
    for k, (e, (x, Pr)) in enumerate(zip(exps, projections)):
        N = x.size
        nodes = slice(start, start + N)
        start += N
        block = np.concatenate([Kt[k, l, nodes, l * Q:(l + 1) * Q] @ Om
                                for l, (_, Om) in enumerate(rules)], axis=1)
        block = Pr @ block
        j = np.arange(N)
        keep = (j + e.kappa >= 0) & (j + e.kappa < n)        # the dominant identity (4)
        block[j[keep], k * n + j[keep] + e.kappa] += -(2.0 ** -e.kappa) / e.sin
        dk = Pr @ G[k, nodes]
        scales.append(float(np.max(np.abs(G[k, nodes]))))
        if e.kappa == -1:                 # the solvability row: left out, its residual kept
            solvability[k] = (block[0], dk[0])
            block, dk = block[1:], dk[1:]
        M[row:row + block.shape[0]] = block
        R[row:row + block.shape[0]] = dk
        row += block.shape[0]
    if idx:
        ones = [k for k, e in enumerate(exps) if e.kappa == 1]
        if not np.linalg.cond(modes.vectors[np.ix_(idx, ones)] * mu0[ones]) < 1e12:
            raise SideConditionError(
                f"the totals given (components {idx}) do not fix the null space of the modes of "
                f"index 1 (modes {ones}): their rows of V are dependent; give other components")
        for i, t in zip(idx, tvals):        # int psi_i = h sum_k V_ik mu0_k c_k0
            M[row, ::n] = modes.vectors[i] * mu0
            R[row] = t / h
            row += 1
    try:
        C = np.linalg.solve(M, R)
    except np.linalg.LinAlgError:
        raise UnsupportedEquationError(
            "the collocation system of the equation with this kernel is singular: the "
            "homogeneous equation has a nontrivial solution (an eigenvalue of the kernel), "
            "so the solution is not unique") from None
    coeffs = [C[k * n:(k + 1) * n].copy() for k in range(m)]
    consistency = [None if e.kappa != -1 else complex(solvability[k][1] - solvability[k][0] @ C)
                   for k, e in enumerate(exps)]
    _check_residual(modes, exps, coeffs, consistency, rules, Kt[:, :, xs.size:], G[:, xs.size:])
    return coeffs, consistency, scales


def _check_residual(modes, exps, coeffs, consistency, rules, Kt, G):
    """ResidualWarning where the modes' equations (2) of :mod:`sie.system_kernel`, at the
    seven check points between the nodes, are not satisfied to RESIDUAL_TOL of their scale:
    n does not resolve f or the kernel (the scalar solver's check, :mod:`sie.solver`).
    ``Kt``, ``G``: the modal kernel and data at the check points."""
    Q = rules[0][0].size
    worst, scale = 0.0, float(np.max(np.abs(G)))
    for k, (e, ck) in enumerate(zip(exps, coeffs)):
        shifted = ck[1:] if e.kappa == 1 else (ck if e.kappa == 0 else
                                               np.concatenate([[0.0], ck]))
        lhs = jacobi_vandermonde(shifted.size, -e.alpha, -e.beta, _CHECK_POINTS) @ shifted \
            * (-(2.0 ** -e.kappa) / e.sin)
        for l, (_, Om) in enumerate(rules):
            lhs = lhs + Kt[k, l, :, l * Q:(l + 1) * Q] @ (Om @ coeffs[l])
        g = G[k] - (consistency[k] or 0.0)
        scale = max(scale, float(np.max(np.abs(lhs))))
        worst = max(worst, float(np.max(np.abs(g - lhs))))
    worst /= max(scale, np.finfo(float).tiny)
    if worst > RESIDUAL_TOL:
        warnings.warn(
            f"solve_system: the solution leaves a residual of {worst:.2g} (relative to f) in "
            f"the equation between the collocation nodes: n = {coeffs[0].size} does not "
            "resolve f or the kernel (increase n), or the kernel is not smooth",
            ResidualWarning, stacklevel=4)


def _finish(modes, exps, coeffs, consistency, interval, n, mu0):
    """The SystemSolution, its imaginary part measured (and warned of)."""
    for ck in coeffs:
        ck.flags.writeable = False
    sol = SystemSolution(modes, exps, tuple(coeffs), tuple(consistency), interval, n, mu0)
    # the imaginary part of V phi, which is rounding for real data
    vals = sol._modal(_CHECK_POINTS)
    psi = modes.vectors @ vals
    size = float(np.max(np.abs(psi)))
    imag = float(np.max(np.abs(psi.imag))) / size if size > 0 else 0.0
    object.__setattr__(sol, "imaginary", imag)
    if imag > _IMAG_WARN:
        warnings.warn(f"solve_system: psi = V phi has a relative imaginary part {imag:.3g} "
                      "(rounding would leave ~1e-15); the returned real part is suspect",
                      SIEWarning, stacklevel=3)
    return sol


@dataclass(frozen=True, eq=False)
class SystemSolution:
    """psi = V phi of :func:`solve_system`, phi_k = w_k sum_j c_kj P_j^{(alpha_k,beta_k)}.

    Calling it evaluates psi (real, shape (m, len(s))).

    Attributes
    ----------
    modes : SystemModes
        lambdas, V, the order of the modes.
    exponents : tuple of ModeExponents
        Per mode (complex for complex lambda).
    coefficients : tuple of ndarray of complex
        c_kj per mode (in the local coordinate u = (s - m)/h).
    consistency : tuple
        Per mode: the solvability residual d_0 (complex) for index -1, else None.
    interval : (float, float)
    n : int
    mu0 : ndarray of complex
        int w_k du per mode.
    imaginary : float
        max abs(Im V phi) / max abs(V phi) at seven check points: rounding (~1e-16) for
        real data.

    References
    ----------
    As :func:`solve_system`.

    Examples
    --------
    The interface crack in reduced form (b = psi_1 + i psi_2, i beta_D b + H[b] = 1):

    >>> import numpy as np, sie
    >>> A = np.array([[0.0, -0.3], [0.3, 0.0]])
    >>> sol = sie.solve_system(lambda s: np.array([1.0 + 0 * s, 0 * s]), A, np.eye(2), n=4,
    ...                        left="singular", right="singular", total=[0.0, 0.0])
    >>> sol.imaginary < 1e-15, bool(np.abs(sol.integral()).max() < 1e-15)
    (True, True)
    >>> s = np.array([0.5]); bool(np.allclose(sol.cauchy(s), 1.0 * np.array([[1.0], [0.0]])
    ...                                       - A @ sol(s), atol=1e-14))
    True
    """
    modes: SystemModes
    exponents: tuple
    coefficients: tuple
    consistency: tuple
    interval: tuple
    n: int
    mu0: np.ndarray
    imaginary: float = float("nan")

    def _local(self, s, open_=False):
        s = np.asarray(s)
        if s.dtype.kind == "c" or not np.isfinite(s).all():
            raise EvaluationPointError("s must be finite real points")
        c, d = self.interval
        u = (np.asarray(s, dtype=float) - 0.5 * (c + d)) / (0.5 * (d - c))
        u = np.where(s == d, 1.0, np.where(s == c, -1.0, u))
        if open_:
            bad = (u <= -1.0) | (u >= 1.0)
            if bad.any():
                at = float(np.ravel(s)[np.argmax(bad.ravel())])
                raise EvaluationPointError(
                    f"s must lie strictly inside ({c!r}, {d!r}) for the Cauchy transform (off "
                    f"the interval it is not implemented here), got {at!r}")
        else:
            bad = (u < -1.0) | (u > 1.0)
            if bad.any():
                raise EvaluationPointError(f"s must lie in [{c!r}, {d!r}], got "
                                           f"{float(np.ravel(s)[np.argmax(bad.ravel())])!r}")
            for e in self.exponents:
                if ((u == 1.0) & (e.right == "singular")).any() or \
                        ((u == -1.0) & (e.left == "singular")).any():
                    raise EvaluationPointError("psi is infinite at a singular end")
        return u

    def regular(self, s):
        """The modal regular parts Phi_k(s) = sum_j c_kj P_j^{(alpha_k,beta_k)}(u), complex,
        shape (m,) + s.shape (s in [c, d], ends included): phi_k = w_k Phi_k."""
        c, d = self.interval
        s = np.asarray(s, dtype=float)
        u = (s - 0.5 * (c + d)) / (0.5 * (d - c))
        u = np.where(s == d, 1.0, np.where(s == c, -1.0, u))
        return np.array([jacobi_series(ck, e.alpha, e.beta, u)
                         for e, ck in zip(self.exponents, self.coefficients)])

    def _modal(self, u):
        return np.array([_weight(e, u) * jacobi_series(ck, e.alpha, e.beta, u)
                         for e, ck in zip(self.exponents, self.coefficients)])

    def phi(self, s):
        """The modes phi_k(s) (complex), shape (m,) + s.shape."""
        return self._modal(self._local(s))

    def __call__(self, s):
        """psi(s) = Re(V phi(s)), shape (m,) + s.shape, s in [c, d] (not at a singular end
        of any mode)."""
        u = self._local(s)
        vals = self._modal(u.ravel())
        return (self.modes.vectors @ vals).real.reshape((-1,) + u.shape)

    def cauchy(self, z):
        """(1/pi) PV int_c^d psi(t)/(t - z) dt, shape (m,) + z.shape.

        Real z strictly inside (c, d): the principal value H[psi] from the dominant identity
        (4) of the module docstring (real).  Real z outside [c, d]: real.  Complex z (off the
        real segment [c, d]): complex, mode by mode by :func:`mode_cauchy_off` (the closed
        form next to the interval, the functions of the second kind by backward recurrence
        elsewhere), for real and complex exponents alike.  Not at the ends themselves."""
        z = np.asarray(z)
        if not np.isfinite(z).all():
            raise EvaluationPointError("z must be finite")
        c, d = self.interval
        m, h = 0.5 * (c + d), 0.5 * (d - c)
        u = (z.astype(complex) - m) / h if z.dtype.kind == "c" else (z.astype(float) - m) / h
        u = np.ravel(u)
        on_line = np.imag(u) == 0.0
        inside = on_line & (np.abs(np.real(u)) < 1.0)
        if (on_line & (np.abs(np.real(u)) == 1.0)).any():
            raise EvaluationPointError(f"z must not be an end of the interval ({c!r}, {d!r})")
        out = np.zeros((self.modes.m, u.size), dtype=complex)
        if inside.any():
            out[:, inside] = self._hilbert_modes(np.real(u[inside]))
        off = ~inside
        if off.any():
            out[:, off] = np.array([mode_cauchy_off(e, mu, ck, u[off]) for e, mu, ck in
                                    zip(self.exponents, self.mu0, self.coefficients)])
        psi = self.modes.vectors @ out
        if z.dtype.kind != "c":
            psi = psi.real
        return psi.reshape((-1,) + z.shape)

    def cauchy_limit(self, x, side=1):
        """The one-sided limits of the Cauchy transform on the real line:
        C(x + i0 side) with C(z) = (1/pi) int_c^d psi(t)/(t - z) dt, shape (m,) + x.shape.

        Inside (c, d) this is H[psi](x) + side i psi(x) (the Plemelj formulas, per component;
        H[psi] from the dominant identity (4) of the module docstring); off [c, d] it is the
        (real) transform, as :meth:`cauchy`.  The conventions of
        :meth:`sie.Solution.cauchy_limit`.

        Parameters
        ----------
        x : array_like of float
            Real points, not at an end of the interval.
        side : {1, -1}
            The limit from above (+1) or from below (-1).

        Returns
        -------
        ndarray of complex, shape (m,) + x.shape

        Raises
        ------
        EvaluationPointError
            x complex, not finite or at an end; ``side`` not +1 or -1.

        References
        ----------
        N. I. Muskhelishvili, Singular Integral Equations (1953), sec. 17 (the Plemelj
        formulas).

        Examples
        --------
        The interface crack (b = psi_1 + i psi_2, i beta_D b + H[b] = 1, int b = 0):

        >>> import numpy as np, sie
        >>> A = np.array([[0.0, -0.3], [0.3, 0.0]])
        >>> sol = sie.solve_system(lambda s: np.array([1.0 + 0 * s, 0 * s]), A, np.eye(2),
        ...                        n=4, left="singular", right="singular", total=[0.0, 0.0])
        >>> x = np.array([0.5]); F = sol.cauchy_limit(x, side=-1)
        >>> bool(np.allclose(F, sol.cauchy(x) - 1j * sol(x), rtol=0, atol=1e-14))
        True
        """
        c, d = self.interval
        xf = limit_points(x, side, [(c, d)])
        out = self.cauchy(xf).astype(complex)
        inside = (xf > c) & (xf < d)
        if inside.any():
            out[:, inside] += side * 1j * self(xf[inside])
        return out

    def log_potential(self, x):
        r"""V_i(x) = (1/pi) int_c^d psi_i(t) log abs(x - t) dt at real x (anywhere: inside,
        at the ends, where it is finite, outside), shape (m,) + x.shape, real.

        With t = m + h u, x = m + h v and psi = Re(V phi),
        V(x) = h Re sum_k V_{ik} [(log h / pi) mu0_k c_k0 + L_k(v)], L_k the mode's
        (1/pi) int w_k Phi_k log abs(v - u) du (:func:`mode_log_potential`): for the terms
        j >= 1 integration by parts with w P_j^{(alpha,beta)} = -(1/(2j)) d/du[(1 - u^2) w
        P_{j-1}^{(alpha+1,beta+1)}] (DLMF 18.9.16, complex exponents by analytic
        continuation), which gives (1/(2j)) times the Cauchy transform (principal value
        inside) of the shifted series, by the recurrence of the functions of the second kind;
        the term j = 0, the potential of the weight, in closed form at the ends (the
        derivative of the Beta integral: digamma), from the nearer end by the integral of
        its derivative -H[w] (inside, the dominant identity) or -F_0 (beside) as binomial
        series, and by the expansion in 1/v with the weight's moments for abs(v) >= 2.  No
        quadrature: exact to rounding.  dV/dx = -H[psi](x) inside.

        Raises
        ------
        EvaluationPointError
            complex or non-finite x.

        References
        ----------
        N. I. Muskhelishvili, Singular Integral Equations (1953), sec. 29 (boundary values
        at the ends); NIST DLMF 18.9.16 (the derivative of the weighted Jacobi polynomial),
        5.12.1 (the Beta integral).

        Examples
        --------
        Far away the potential tends to (int psi_i) log abs(x) / pi:

        >>> import numpy as np, sie
        >>> A = np.array([[0.2, -0.3], [0.3, 0.2]])
        >>> sol = sie.solve_system(lambda s: np.array([1.0 + 0 * s, s]), A, np.eye(2), n=6,
        ...                        left="bounded", right="singular")
        >>> x = np.array([1e9])
        >>> bool(np.allclose(sol.log_potential(x)[:, 0], sol.integral() * np.log(1e9) / np.pi,
        ...                  rtol=1e-8, atol=0))
        True
        """
        x = np.asarray(x)
        if x.dtype.kind == "c" or not np.isfinite(x).all():
            raise EvaluationPointError("x must be finite real points")
        c, d = self.interval
        mid, h = 0.5 * (c + d), 0.5 * (d - c)
        xf = np.asarray(x, dtype=float).ravel()
        v = (xf - mid) / h
        v = np.where(xf == d, 1.0, np.where(xf == c, -1.0, v))
        dist = ((d - xf) / h, (xf - c) / h)     # 1 - v, 1 + v to full relative precision
        modal = np.array([h * (math.log(h) / math.pi * mu * ck[0]
                               + mode_log_potential(e, mu, ck, v, dist))
                          for e, mu, ck in zip(self.exponents, self.mu0, self.coefficients)])
        out = (self.modes.vectors @ modal).real
        return out.reshape((-1,) + x.shape)

    def _hilbert_modes(self, u):
        """H[phi_k](u) per mode at local points strictly inside (-1, 1), complex."""
        out = []
        for e, ck in zip(self.exponents, self.coefficients):
            out.append(-e.lam * _weight(e, u) * jacobi_series(ck, e.alpha, e.beta, u)
                       + jacobi_series(_moment_images(e, ck), -e.alpha, -e.beta, u))
        return np.array(out)

    def integral(self):
        """int_c^d psi ds, shape (m,)."""
        c, d = self.interval
        I = np.array([mu * ck[0] for mu, ck in zip(self.mu0, self.coefficients)])
        return 0.5 * (d - c) * (self.modes.vectors @ I).real
