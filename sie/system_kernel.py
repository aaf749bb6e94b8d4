r"""The regular kernel of a system of singular integral equations, in the modes of
:mod:`sie.systems`:

    A psi(s) + (B/pi) PV int_c^d psi(t)/(t - s) dt + int_c^d K(s, t) psi(t) dt = f(s),   (1)

K(s, t) a real m x m matrix of functions bounded on [c, d]^2.  With psi = V phi and
g = V^-1 B^-1 f (:mod:`sie.systems`, "Decoupling") and the local coordinates
s = mid + h u, t = mid + h v, mode k reads

    lambda_k phi_k + H[phi_k] + sum_l int_{-1}^{1} Kt_kl(u, v) phi_l(v) dv = g_k,           (2)

Kt = h V^-1 B^-1 K V (complex where modes are).  The modes no longer decouple: the
coefficients c_lj of every mode (phi_l = w_l sum_j c_lj P_j^{(alpha_l, beta_l)}) are the
unknowns of one linear system.

**The kernel integral with a complex weight.**  int g(v) w_l(v) P_j^{(alpha_l,beta_l)}(v) dv
for a smooth g: for a real mode, the Gauss-Jacobi rule of w_l with Q nodes; for a complex
mode the weight (1-v)^alpha (1+v)^beta oscillates without bound at the ends and no real
Gauss rule integrates it.  Instead g is interpolated at the Q roots y_q of
P_Q^{(Re alpha, Re beta)} in the basis P_p^{(alpha, beta)}, p < Q, and integrated exactly by
the bilinear orthogonality int w P_p P_j = h_j delta_pj, which holds for complex parameters
(:mod:`sie.systems`, "The dominant identity for complex exponents"), with

    h_j = 2^(alpha+beta+1) Gamma(j+alpha+1) Gamma(j+beta+1)
          / ((2j+alpha+beta+1) Gamma(j+alpha+beta+1) j!)     (DLMF 18.3, Table 18.3.1),

h_0 = 2^(alpha+beta+1) Gamma(alpha+1) Gamma(beta+1) / Gamma(alpha+beta+2).  So
int g w_l P_j = sum_q g(y_q) Omega_l[q, j], exact for a polynomial g of degree < Q, and as
accurate as the interpolant otherwise (spectrally for an analytic kernel).  For a real mode
the same construction is the Gauss-Jacobi rule itself (the interpolant's Gauss sum).  The
interpolation matrix, rows scaled by the square roots of the Gauss weights and columns to unit
norm, is close to unitary (as the projection's, :mod:`sie.systems`).

**The linear system.**  Mode k's equation (2) at the N_k = n - kappa_k projection nodes x_i
of :mod:`sie.systems` ("The projection"), projected onto P_j^{(-alpha_k,-beta_k)}, j < N_k:

    (-2^(-kappa_k) / sin(pi alpha_k)) c_{k, j+kappa_k}
        + sum_l [Pr_k Kt_kl(x, y_l) Omega_l c_l]_j = [Pr_k g_k(x)]_j,                   (3)

the first term the dominant identity (4) of :mod:`sie.systems` (c_{k,j} = 0 for j < 0 or
j >= n).  A mode of index 1 has one row fewer than unknowns; the totals of :mod:`sie.systems`
("Side conditions"), int psi_i = h sum_k V_ik mu0_k c_k0, are the missing rows.  A mode of
index -1 has one row more: its row j = 0, the mode's solvability condition, is left out of
the solve and its residual reported as the mode's consistency.  The system is square,
m n unknowns, solved densely.

References
----------
F. Erdogan, G. D. Gupta and T. S. Cook, "Numerical solution of singular integral equations",
in Methods of Analysis and Solutions of Crack Problems, G. C. Sih (ed.), Noordhoff (1973),
ch. 7 (collocation of systems with a regular kernel).  NIST DLMF, sec. 18.3 (the norms) and
18.9 (the recurrence).  N. I. Muskhelishvili, Singular Integral Equations (1953), ch. 18.
"""
from __future__ import annotations

import functools

import numpy as np
from scipy import special as sp_special

from .assembly import _PROBE, grows_toward_end
from .errors import CallableOutputError, KernelSingularityError
from .gaussjacobi import gauss_jacobi_cached
from .jacobi import jacobi_norms_cached, jacobi_vandermonde

__all__ = ["complex_jacobi_norms", "projection_matrix", "weighted_rule", "kernel_modes",
           "probe_kernel", "real_values", "KERNEL_EXTRA"]

#: Kernel nodes beyond n per mode (as the scalar solver's rule for its kernel).
KERNEL_EXTRA = 16


def complex_jacobi_norms(n, alpha, beta):
    """h_j = int (1-x)^alpha (1+x)^beta P_j^{(alpha,beta)}(x)^2 dx, j < n, for complex
    alpha, beta with real parts > -1 (module docstring; the bilinear form, no conjugate)."""
    ab = alpha + beta
    j = np.arange(n)
    lg = sp_special.loggamma
    out = np.empty(n, dtype=complex)
    out[0] = np.exp((ab + 1.0) * np.log(2.0) + lg(alpha + 1.0) + lg(beta + 1.0) - lg(ab + 2.0))
    if n > 1:
        k = j[1:]
        out[1:] = np.exp((ab + 1.0) * np.log(2.0) + lg(k + alpha + 1.0) + lg(k + beta + 1.0)
                         - lg(k + ab + 1.0) - sp_special.gammaln(k + 1.0)) / (2 * k + ab + 1.0)
    return out


def _scaled_inverse(Q, a, b, x, w):
    """(D^-1 S^-1 diag(sqrt w)): the map from values at the Gauss nodes x (weights w) to the
    coefficients of the interpolant in P_p^{(a,b)}, p < Q (a, b complex), by the inverse of
    the Vandermonde matrix with rows scaled by sqrt(w) and columns to unit norm."""
    sw = np.sqrt(w)
    S = sw[:, None] * jacobi_vandermonde(Q, a, b, x)
    col = np.linalg.norm(S, axis=0)
    return np.linalg.inv(S / col) * sw[None, :] / col[:, None]


@functools.lru_cache(maxsize=64)
def projection_matrix(N, alpha, beta):
    """(x, Pr): the N projection nodes of a mode with exponents (alpha, beta) (the roots of
    P_N^{(-Re alpha, -Re beta)}) and the N x N matrix taking g(x) to the coefficients d_j of
    g in P_j^{(-alpha,-beta)}, j < N (:mod:`sie.systems`, "The projection").  Memoised; a
    mode's conjugate partner takes the conjugate matrix (the nodes are real)."""
    if alpha.imag < 0.0:
        x, Pr = projection_matrix(N, alpha.conjugate(), beta.conjugate())
        return x, Pr.conj()
    ar, br = -alpha.real, -beta.real
    x, w = gauss_jacobi_cached(N, ar, br)
    if alpha.imag == 0.0 and beta.imag == 0.0:
        V = jacobi_vandermonde(N, ar, br, x)
        Pr = ((V * w[:, None]).T / jacobi_norms_cached(N, ar, br)[:, None]).astype(complex)
    else:
        Pr = _scaled_inverse(N, -alpha, -beta, x, w)
    Pr.flags.writeable = False
    return x, Pr


@functools.lru_cache(maxsize=64)
def weighted_rule(Q, n, alpha, beta):
    """(y, Omega): int_{-1}^{1} g(v) (1-v)^alpha (1+v)^beta P_j^{(alpha,beta)}(v) dv
    ~ sum_q g(y_q) Omega[q, j], j < n <= Q, for smooth g (module docstring).  Memoised; the
    conjugate exponents take the conjugate rule."""
    if alpha.imag < 0.0:
        y, Om = weighted_rule(Q, n, alpha.conjugate(), beta.conjugate())
        return y, Om.conj()
    y, om = gauss_jacobi_cached(Q, alpha.real, beta.real)
    if alpha.imag == 0.0 and beta.imag == 0.0:
        Om = (om[:, None] * jacobi_vandermonde(n, alpha.real, beta.real, y)).astype(complex)
    else:
        coef = _scaled_inverse(Q, alpha, beta, y, om)[:n]    # (n, Q): values -> coefficients
        Om = (coef * complex_jacobi_norms(n, alpha, beta)[:, None]).T
    Om.flags.writeable = False
    return y, Om


def real_values(name, out):
    """A callable's output as a float array, or CallableOutputError naming ``name`` (complex
    or not numbers)."""
    out = np.asarray(out)
    if out.dtype.kind == "c":
        raise CallableOutputError(f"{name} must return real values, got complex")
    try:
        return out.astype(float)
    except (TypeError, ValueError) as exc:
        raise CallableOutputError(f"{name} must return real numbers, got {out.dtype}") from exc


def _call_kernel(kernel, S, T, m, unbounded=CallableOutputError):
    """kernel(S, T) as a real array of shape (m, m) + S.shape, checked; an exception inside
    the kernel or a non-finite value raises ``unbounded`` (KernelSingularityError where the
    points are next to the ends)."""
    try:
        out = kernel(S, T)
    except Exception as exc:
        raise unbounded(f"kernel raised {type(exc).__name__}: {exc}") from exc
    out = real_values("kernel", out)
    want = (m, m) + S.shape
    if out.shape != want:
        raise CallableOutputError(
            f"kernel must return shape (m, m) + shape of s = {want} when called with arrays "
            f"s, t of shape {S.shape}, got {out.shape}")
    if not np.isfinite(out).all():
        idx = np.argwhere(~np.isfinite(out))[0]
        at = tuple(float(a[tuple(idx[2:])]) for a in (S, T))
        raise unbounded(f"kernel returned a non-finite value in entry ({idx[0]}, {idx[1]}) "
                        f"at (s, t) = {at}")
    return out


class _NextToEnds(KernelSingularityError):
    """A kernel raising or not finite next to the ends (its message says what it did)."""

    def __init__(self, what):
        super().__init__(f"the kernel cannot be evaluated next to the interval ends ({what}); "
                         "the solver needs K(s, t) bounded on [c, d]^2")


def probe_kernel(kernel, m, c, d):
    """KernelSingularityError where abs(K(s, t)) grows without bound toward a corner of
    [c, d]^2 (a fixed singularity: the end exponents would not be those of the modes),
    sampled at 1e-3 and 1e-6 of the half-width inside each corner, as the scalar solver
    does (:func:`sie.assembly.probe_kernel`)."""
    mid, h = 0.5 * (c + d), 0.5 * (d - c)
    S, T, tags = [], [], []
    for es in (-1.0, 1.0):
        for et in (-1.0, 1.0):
            for dist in _PROBE:
                S.append(mid + h * es * (1.0 - dist))
                T.append(mid + h * et * (1.0 - 1.5 * dist))
            tags.append((es, et))
    K = _call_kernel(kernel, np.array(S), np.array(T), m, _NextToEnds)
    size = np.abs(K).max(axis=(0, 1)).reshape(-1, 2)
    grow = grows_toward_end(size)
    if grow.any():
        es, et = tags[int(np.flatnonzero(grow)[0])]
        raise KernelSingularityError(
            f"the kernel grows without bound toward (s, t) = ({mid + h * es!r}, "
            f"{mid + h * et!r}) (abs(K) {size[grow][0, 0]:.3g} at 1e-3 of the half-width, "
            f"{size[grow][0, 1]:.3g} at 1e-6): a fixed singularity at an end, which a system "
            "does not take (its end exponents are those of the modes)")


def kernel_modes(kernel, modes, h, mid, s_local, t_local):
    """Kt_kl(u, v) = h (V^-1 B^-1 K(mid + h u, mid + h v) V)_kl on the grid s_local x
    t_local: complex, shape (m, m, len(s_local), len(t_local))."""
    S, T = np.meshgrid(mid + h * np.asarray(s_local), mid + h * np.asarray(t_local),
                       indexing="ij")
    K = _call_kernel(kernel, S, T, modes.m)
    # (P K V)_kl on every (s, t): two small tensor products (m is small; einsum's path
    # search alone cost about as much)
    PK = np.tensordot(modes.project, K, axes=(1, 0))                 # (k, b, s, t)
    return h * np.moveaxis(np.tensordot(PK, modes.vectors, axes=(1, 0)), 3, 1)
