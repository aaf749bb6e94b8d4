"""An independent reference for the anisotropic half-space in steady motion.

Nothing here imports ``contact``: the equations of motion are written from the stiffness
tensor with explicit loops, in a first-order form for (u, du/dY) (not the Stroh state of
``contact.anisotropic``), and solved for the decaying subspace by an ordered complex Schur
decomposition (scipy.linalg.schur); the Barnett-Lothe integral by the trapezoidal rule.
Used by tests/contact/test_anisotropic.py (the surface response) and
tests/contact/test_anisotropic_contact.py (the couplings of the contact equation).

References
----------
Stroh, J. Math. Phys. 41 (1962) 77-103; Ting, Anisotropic Elasticity (1996), ch. 5, 7 and 12;
Barnett & Lothe, Proc. R. Soc. Lond. A 402 (1985) 135-152.
"""
from __future__ import annotations

import math

import numpy as np
import scipy.linalg


def tensor_by_loops(C) -> np.ndarray:
    """C_ijkl from the Voigt matrix by explicit pairs (not the module's index tables)."""
    voigt = {(0, 0): 0, (1, 1): 1, (2, 2): 2, (1, 2): 3, (2, 1): 3, (0, 2): 4, (2, 0): 4,
             (0, 1): 5, (1, 0): 5}
    t = np.empty((3, 3, 3, 3))
    for i in range(3):
        for j in range(3):
            for k in range(3):
                for m in range(3):
                    t[i, j, k, m] = C[voigt[i, j], voigt[k, m]]
    return t


def state_space_response(C, c, k=1.0):
    """The surface response from the equations of motion in the Fourier domain.

    u(X, Y) = u_hat(Y) exp(i k X) in the frame moving at rho V^2 = C66 c^2 obeys
    T u'' + i k (R + R^T) u' - k^2 (Q - rho V^2 I) u = 0 (sigma_ij,j = rho V^2 u_i,XX), a
    first-order system for (u, u').  The solutions decaying as Y -> -inf are the invariant
    subspace of its matrix with Re lambda > 0: the first three Schur vectors of the ordered
    complex Schur form.  Unit tractions sigma_iY(X, 0) = -s_i fix the amplitudes; du/dX and
    the stresses at Y = 0 follow from the stress-strain law.  For k > 0 the Fourier
    multiplier of Hc is +i: local part = real part, Hilbert part = imaginary part.

    Returns (du/dX per s (3x3 complex), Voigt stresses per s (6x3 complex), the impedance
    t = Z u (3x3), the eigenvalues of the system).
    """
    t = tensor_by_loops(C)
    ex, ey = np.eye(3)[0], np.eye(3)[1]

    def ab(a, b):
        return np.einsum("ijkl,j,l->ik", t, a, b)

    Q, R, T = ab(ex, ex), ab(ex, ey), ab(ey, ey)
    rv2 = C[5, 5] * c * c
    Tinv = np.linalg.inv(T)
    A = np.block([[np.zeros((3, 3)), np.eye(3)],
                  [k * k * Tinv @ (Q - rv2 * np.eye(3)), -1j * k * Tinv @ (R + R.T)]])
    Tm, Z, sdim = scipy.linalg.schur(A, output="complex", sort="rhp")
    assert sdim == 3
    U, dU = Z[:3, :3], Z[3:, :3]
    traction = 1j * k * R.T @ U + T @ dU           # t_i = C_iYkX u_k,X + C_iYkY u_k,Y
    W = -np.linalg.inv(traction)                  # amplitudes for t = -s
    grad_x, grad_y = 1j * k * U @ W, dU @ W
    sigma = (np.einsum("ijk,kn->ijn", t[:, :, :, 0], grad_x)
             + np.einsum("ijk,kn->ijn", t[:, :, :, 1], grad_y))
    rows, cols = [0, 1, 2, 1, 2, 0], [0, 1, 2, 2, 0, 1]
    return grad_x, sigma[rows, cols], traction @ np.linalg.inv(U), np.diag(Tm)


def barnett_lothe_integral(C, c, n=128):
    """(1/pi) int_0^pi N(theta) d theta for the moving half-space: the Stroh matrix in the
    frame turned by theta about Z with C_ijkl - rho V^2 delta_ik delta_jX delta_lX (the
    inertia term as a stiffness; Barnett & Lothe 1985), by the trapezoidal rule (periodic,
    analytic: geometric convergence)."""
    t = tensor_by_loops(C) - C[5, 5] * c * c * np.einsum(
        "ik,j,l->ijkl", np.eye(3), np.eye(3)[0], np.eye(3)[0])
    total = np.zeros((6, 6))
    for theta in np.pi * np.arange(n) / n:
        n_ = np.array([math.cos(theta), math.sin(theta), 0.0])
        m_ = np.array([-math.sin(theta), math.cos(theta), 0.0])
        Q = np.einsum("ijkl,j,l->ik", t, n_, n_)
        R = np.einsum("ijkl,j,l->ik", t, n_, m_)
        T = np.einsum("ijkl,j,l->ik", t, m_, m_)
        Tinv = np.linalg.inv(T)
        total += np.block([[-Tinv @ R.T, Tinv], [R @ Tinv @ R.T - Q, -R @ Tinv]])
    return total / n
