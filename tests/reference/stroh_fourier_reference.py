"""An independent reference for the field under the surface of a moving anisotropic
half-space (generalised plane strain): numerical Fourier inversion of the state-space
solution, wavenumber by wavenumber.

Nothing here imports :mod:`contact`; the material is a 6x6 Voigt stiffness (order XX, YY,
ZZ, YZ, ZX, XY), read into the tensor C_ijkl by explicit index pairs.  The route shares no
step with :mod:`contact.stroh_modes` (the sign function of the Stroh matrix, the 3x3
restriction A and its matrix function in Newton's form over Cauchy transforms):

* For one Fourier component u = u_hat(Y) exp(i k X), k > 0, in the frame moving at
  rho V^2 = C66 c^2, the equations of motion sigma_ij,j = rho V^2 u_i,XX read

      T u'' + i k (R + R^T) u' - k^2 (Q - rho V^2 I) u = 0,
      Q_ik = C_iXkX, R_ik = C_iXkY, T_ik = C_iYkY,

  a first-order system w' = M_k w for w = (u_hat, u_hat'), built afresh for every k.
* The solutions that decay as Y -> -inf are w(Y) = Z_1 exp(T_11 Y) b, with Z_1, T_11 the
  first three Schur vectors and the leading block of the ordered complex Schur form of M_k
  (scipy.linalg.schur, sort="rhp": the eigenvalues with Re > 0), and exp(T_11 Y) by
  scaling and squaring of the Taylor series (:func:`expm_taylor`).  This holds for repeated
  and defective eigenvalues alike (an isotropic material at rest).
* b is fixed by the tractions t_i = sigma_iY = i k C_iYlX u_l + C_iYlY u_l' at Y = 0:
  t_hat(0) = -s_hat(k), s = (q, p, r), i.e. sigma_XY(X, 0) = -q, sigma_YY(X, 0) = -p,
  sigma_ZY(X, 0) = -r (r = 0 here).  The six stresses at Y follow from the stress-strain
  law sigma_ij = i k C_ijlX u_l + C_ijlY u_l'.
* The field is real, so sigma(X, Y) = (1/pi) Re int_0^inf sigma_hat(k, Y) exp(i k X) dk,
  done by Gauss-Legendre panels on [0, k_max] for a Gaussian p of width w,
  p_hat(k) = P exp(-k^2 w^2 / 2), cut where that is below 1e-18 of its peak.

References: Stroh, J. Math. Phys. 41 (1962) 77-103 (the equations); Ting, Anisotropic
Elasticity (1996), ch. 12 (steady motion); Golub & Van Loan, Matrix Computations, 4th ed.
(2013), Sec. 7.6 (ordered Schur forms); Moler & Van Loan, "Nineteen dubious ways to compute
the exponential of a matrix, twenty-five years later", SIAM Rev. 45 (2003) 3-49.
"""
from __future__ import annotations

import math

import numpy as np
import scipy.linalg
from scipy.special import wofz

__all__ = ["VOIGT_PAIRS", "tensor_by_pairs", "gaussian_cauchy", "expm_taylor",
           "GaussianFourierField"]

#: Voigt index of each index pair.
VOIGT_PAIRS = {(0, 0): 0, (1, 1): 1, (2, 2): 2, (1, 2): 3, (2, 1): 3, (0, 2): 4, (2, 0): 4,
               (0, 1): 5, (1, 0): 5}


def tensor_by_pairs(C) -> np.ndarray:
    """C_ijkl of a 6x6 Voigt stiffness, by explicit pairs."""
    C = np.asarray(C, dtype=float)
    t = np.empty((3, 3, 3, 3))
    for i in range(3):
        for j in range(3):
            for k in range(3):
                for m in range(3):
                    t[i, j, k, m] = C[VOIGT_PAIRS[i, j], VOIGT_PAIRS[k, m]]
    return t


def gaussian_cauchy(P, w):
    """C(z) = (1/pi) int p(t) / (t - z) dt, Im z > 0, of p(t) = P exp(-t^2 / (2 w^2)) /
    (w sqrt(2 pi)): with t = w sqrt(2) u and the Faddeeva function
    wofz(v) = (i / pi) int exp(-u^2) / (v - u) du (Abramowitz & Stegun 7.1.4),
    C(z) = i P wofz(z / (w sqrt 2)) / (w sqrt(2 pi))."""
    def C(z):
        return 1j * P * wofz(np.asarray(z, dtype=complex) / (w * math.sqrt(2.0))) \
            / (w * math.sqrt(2.0 * math.pi))
    return C


def expm_taylor(A) -> np.ndarray:
    """exp(A) of a stack of square matrices (..., n, n) by scaling and squaring with the
    Taylor series (Moler & Van Loan 2003, method 3): A / 2^s of norm <= 1/2, 24 terms, s
    squarings.  No eigenvalues enter, so repeated and nearly repeated eigenvalues cost no
    accuracy (scipy.linalg.expm's triangular branch loses 1e-10 relative on the Schur block
    of a nearly defective matrix)."""
    A = np.asarray(A, dtype=complex)
    norm = np.abs(A).sum(axis=-2).max()
    s = max(0, int(math.ceil(math.log2(norm / 0.5)))) if norm > 0.5 else 0
    B = A / 2.0 ** s
    E = np.broadcast_to(np.eye(A.shape[-1], dtype=complex), A.shape).copy()
    term = E.copy()
    for j in range(1, 25):
        term = term @ B / j
        E = E + term
    for _ in range(s):
        E = E @ E
    return E


class GaussianFourierField:
    """The six stresses (Voigt order) under p(X) = P exp(-X^2 / (2 w^2)) / (w sqrt(2 pi)),
    q = q_ratio p, on the half-space of stiffness C moving at relative speed c
    (rho V^2 = C66 c^2), by Fourier inversion (module docstring).

    Parameters
    ----------
    C : array_like (6, 6)
    c : float
    w, P, q_ratio : float
    panels, nodes : int
        Gauss-Legendre panels on [0, k_max] and nodes per panel.
    """

    def __init__(self, C, c, w=0.5, P=1.0, q_ratio=0.3, panels=48, nodes=16):
        self.C = np.asarray(C, dtype=float)
        t = tensor_by_pairs(self.C)
        self.t = t
        self.Q, self.R, self.T = t[:, 0, :, 0], t[:, 0, :, 1], t[:, 1, :, 1]
        self.rv2 = self.C[5, 5] * c * c
        k_max = math.sqrt(2.0 * math.log(1e18)) / w
        x, wt = np.polynomial.legendre.leggauss(nodes)
        edges = np.linspace(0.0, k_max, panels + 1)
        self.k = np.concatenate([0.5 * (b - a) * x + 0.5 * (a + b)
                                 for a, b in zip(edges[:-1], edges[1:])])
        self.wk = np.concatenate([0.5 * (b - a) * wt for a, b in zip(edges[:-1], edges[1:])])
        load = P * np.exp(-0.5 * (self.k * w) ** 2)
        self.s_hat = np.stack([q_ratio * load, load, 0.0 * load], axis=1)   # (nk, 3)
        self.modes = [self._decaying(k) for k in self.k]

    def _decaying(self, k):
        """(Z1, T11, k) at wavenumber k: the decaying Schur basis and its block."""
        Tinv = np.linalg.inv(self.T)
        M = np.block([[np.zeros((3, 3)), np.eye(3)],
                      [k * k * Tinv @ (self.Q - self.rv2 * np.eye(3)),
                       -1j * k * Tinv @ (self.R + self.R.T)]])
        TT, Z, sdim = scipy.linalg.schur(M, output="complex", sort="rhp")
        if sdim != 3:
            raise ValueError(f"expected three decaying modes, got {sdim}: {np.diag(TT)}")
        return Z[:, :3], TT[:3, :3], k

    def stresses(self, X, Y) -> np.ndarray:
        """The six stresses (Voigt XX, YY, ZZ, YZ, ZX, XY) at the points, shape (6, n)."""
        X = np.atleast_1d(np.asarray(X, dtype=float))
        Y = np.atleast_1d(np.asarray(Y, dtype=float))
        rows = [(0, 0), (1, 1), (2, 2), (1, 2), (2, 0), (0, 1)]
        out = np.zeros((6, X.size))
        for (Z1, T11, k), s_hat, wk in zip(self.modes, self.s_hat, self.wk):
            U, dU = Z1[:3], Z1[3:]
            traction = 1j * k * self.R.T @ U + self.T @ dU     # t_i = sigma_iY per b
            b = np.linalg.solve(traction, -s_hat)
            E = expm_taylor(T11[None, :, :] * Y[:, None, None])             # (n, 3, 3)
            coef = E @ b                                                       # (n, 3)
            u = coef @ U.T
            du = coef @ dU.T
            sig = (1j * k * np.einsum("ijl,nl->nij", self.t[:, :, :, 0], u)
                   + np.einsum("ijl,nl->nij", self.t[:, :, :, 1], du))
            voigt = np.stack([sig[:, i, j] for i, j in rows])                  # (6, n)
            out += wk * (voigt * np.exp(1j * k * X)).real
        return out / math.pi
