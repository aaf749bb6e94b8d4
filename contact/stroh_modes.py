"""The field under the surface of a moving anisotropic half-space (generalised plane strain).

:func:`stroh_modes` gives, for a material of any symmetry (:class:`contact.Anisotropic`),
the object that :meth:`contact.ContactResult.stress` and
:func:`contact.half_space_stress` need (:class:`contact.MaterialModes`): the complex points
at which the Cauchy transforms of the surface tractions are wanted and the fixed linear
combination of them that gives every stress component, in-plane and out-of-plane.

Conventions as in :mod:`contact.anisotropic`: X the sliding direction, Y the outward normal
(the half-space is Y <= 0), Z along the punch's generators, nothing depending on Z; the
tractions s = (q, p, r) with sigma_XY(X, 0) = -q, sigma_YY(X, 0) = -p, sigma_ZY(X, 0) = -r
(r = 0 here); Voigt order (XX, YY, ZZ, YZ, ZX, XY); C_f(z) = (1/pi) int f(t) / (t - z) dt,
Im z > 0.

Derivation
----------
A Fourier component exp(i k X), k > 0, of the state eta = (u_hat, t_hat / (i k)) (t_i =
sigma_iY) obeys d eta / dY = i k N eta with the Stroh matrix of the moving half-space N
(Stroh 1962; Ting 1996, ch. 5 and ch. 12: Q - rho V^2 I in place of Q).  The decaying
solutions (Y -> -inf) span the invariant subspace of N whose eigenvalues p have Im p < 0
(Ting 1996, ch. 12, for the moving half-space); in the basis whose traction part is the unit
matrix it is spanned by the columns of [W; I], W = -(L + i M), with L, M the local and Hilbert
parts of the surface response (:meth:`contact.Anisotropic.surface_response`, which takes
them from the matrix sign function), and N restricted to it is the 3x3 matrix

    N [W; I] = [W; I] A,    A = N3 W + N1^T     (the lower block row of N [W; I]).

The eigenvalues of A are the three decaying Stroh roots p_1, p_2, p_3, Im p_j < 0.  The
solution with the traction t_hat(0) = -s_hat is eta(Y) = [W; I] exp(i k A Y) a,
i k a = -s_hat, so

    t_hat(Y) = -exp(i k A Y) s_hat,    (u_,X)^(Y) = -W exp(i k A Y) s_hat,

and the six stresses, sigma = A_s u_,X + B_s t with A_s = C_ijkX - C_ijmY (T^-1 R^T)_mk,
B_s = C_ijmY T^-1_mk (the stress-strain law with u_,Y = T^-1 (t - R^T u_,X)), are
sigma^(k, Y) = -(A_s W + B_s) exp(i k A Y) s_hat.  The field is real, so the k < 0 half
is the conjugate, and for Im z > 0, (1/2 pi) int_0^inf f^(k) exp(i k z) dk = C_f(z) / (2 i):
with f_m(zeta) = C_{s_m}(X + zeta Y), a function of zeta analytic for Im zeta < 0 (Y < 0),
and the matrix function f_m(A) (Higham 2008, ch. 1),

    sigma(X, Y) = Re{ G sum_m f_m(A) e_m },    G = i (A_s W + B_s) = H_s - i L_s,

where L_s = A_s L - B_s and H_s = A_s M are the local and Hilbert parts of the stresses on the
surface (:class:`contact.SurfaceResponse`: stress_local, stress_hilbert).  On Y = 0 every
f_m(A) = C_{s_m}(X + i0) I = (Hc[s_m] + i s_m) I (Plemelj) and the field returns the surface
response L_s s + H_s Hc[s]; rows YY, YZ, XY are the tractions -p, -r, -q.  For distinct
roots f(A) = sum_j f(p_j) P_j (P_j the spectral projectors) is the modal sum of Stroh's
solution, u = 2 Re sum_j a_j f_j(X + p_j Y); each stress is a combination of the transforms
at z_j = X + p_j Y, Im z_j > 0.

Repeated and nearly repeated roots
----------------------------------
The modal sum divides by differences of the roots (through the eigenvectors): for an
isotropic material at rest p = -i is triple and A is not diagonalisable (Ting 1996,
ch. 5: a degenerate material), and near isotropy the eigenvector matrix is nearly singular,
so the modal sum loses digits as eps / abs(p_i - p_j)^2 (the eigenvectors of a nearly
defective matrix).  Instead f(A) is taken in
Newton's form, exact for any 3x3 A with the eigenvalues x_1, x_2, x_3 (Higham 2008,
ch. 1; confluent divided differences where roots repeat):

    f(A) = f[x_1] I + f[x_1, x_2] (A - x_1 I) + f[x_1, x_2, x_3] (A - x_1 I)(A - x_2 I).

It needs no eigenvectors; the computed x_j are the exact eigenvalues of a matrix within
rounding of A, so (A - x_1)(A - x_2)(A - x_3) is of rounding size (Cayley-Hamilton) however
ill-conditioned the roots themselves are.  What remains is the divided differences of
f(zeta) = C(X + zeta Y) at roots that may be close.  Roots closer than
:data:`CLUSTER` times their distance to the real axis, R = abs(Im x), form a cluster; over a
cluster f is interpolated at :data:`NODES` = n points zeta_l = m + h omega^l on the circle of
radius h = :data:`RADIUS` R about the cluster's mean m (omega = exp(2 pi i / n)):

    f(zeta) ~ sum_{j < n} c_j (zeta - m)^j,    c_j = (1/n) sum_l f(zeta_l) (h omega^l)^-j,

and its divided differences at nodes inside the cluster are those of the powers,
(zeta - m)^j [x_1, ..., x_{k+1}] = h_{j-k}(x_1 - m, ..., x_{k+1} - m) (the complete
homogeneous symmetric polynomials).  f is analytic in the disc of radius R about m (its
singularities lie where X + zeta Y meets the real axis), so the aliasing error of the c_j is
(h / R)^n = 0.12^16 = 2e-15 relative; rounding grows as eps (R / h)^k for the k-th
difference, 70 eps for k = 2.  Divided differences across clusters, whose roots are at least
CLUSTER R apart, are taken from their definition (rounding eps / CLUSTER^2 at worst).  All
of it is linear in the transforms with fixed weights: each stress is
Re sum_l (K_p,l C_p(z_l) + K_q,l C_q(z_l)), z_l = X + zeta_l Y, with K fixed by the material
and the speed.  A lone root costs one transform, a cluster NODES.

References
----------
Stroh, A. N., "Steady state problems in anisotropic elasticity", J. Math. Phys. 41 (1962)
77-103.
Ting, T. C. T., Anisotropic Elasticity: Theory and Applications, Oxford University Press (1996):
the Stroh formalism and degenerate materials (ch. 5), steady motion (ch. 12).
Higham, N. J., Functions of Matrices: Theory and Computation, SIAM (2008), ch. 1 (matrix
functions, the interpolating polynomial and divided differences).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import ContactInputError

__all__ = ["StrohModes", "stroh_modes", "CLUSTER", "RADIUS", "NODES"]

#: Roots closer than this times their distance to the real axis share a cluster.
CLUSTER = 0.04
#: The interpolation circle of a cluster: radius RADIUS times the cluster's distance to the
#: real axis (the cluster's roots lie within 0.0563 of it from its centre, so inside half
#: the circle).
RADIUS = 0.12
#: Points on the interpolation circle of a cluster: aliasing error RADIUS^NODES = 2e-15.
NODES = 16

#: Voigt rows of (sigma_xx, sigma_yy, sigma_xy) and (sigma_zz, sigma_yz, sigma_xz).
_IN_PLANE = (0, 1, 5)
_OUT_OF_PLANE = (2, 3, 4)


@dataclass(frozen=True, eq=False)
class StrohModes:
    """The three decaying modes of a moving anisotropic half-space, combined into the
    weights of the stress field (:func:`stroh_modes`; module docstring).

    Each Voigt stress is sigma_a(X, Y) = Re sum_l (K_p[a, l] C_p(z_l) + K_q[a, l] C_q(z_l))
    with z_l = X + zeta_l Y.

    Attributes
    ----------
    c : float
        The relative speed.
    roots : ndarray, complex, shape (3,)
        The decaying Stroh roots p_j (Im p_j < 0), in the order of the Newton form.
    zeta : ndarray, complex
        The points zeta_l: the roots themselves, or for a cluster of close roots the
        interpolation circle about them (Im zeta_l < 0).
    clusters : tuple of tuple of int
        Which roots share a cluster (indices into ``roots``).
    K_p, K_q : ndarray, complex, shape (6, len(zeta))
        The weights of the transforms of p and q, rows in Voigt order.
    """

    c: float
    roots: np.ndarray
    zeta: np.ndarray
    clusters: tuple
    K_p: np.ndarray
    K_q: np.ndarray

    def points(self, X, Y) -> list:
        """The complex points z_l = X + zeta_l Y (Im z_l > 0 for Y < 0) at which the Cauchy
        transforms are needed: one array of the shape of X, Y per zeta_l."""
        X = np.asarray(X, dtype=float)
        Y = np.asarray(Y, dtype=float)
        return [X + z * Y for z in self.zeta]

    def stresses(self, Cp, Cq=None, q_ratio=None) -> tuple:
        """(sigma_xx, sigma_yy, sigma_xy) from the transforms at :meth:`points`.

        Parameters
        ----------
        Cp : list of array_like
            C_p at each of the points, in the order of :meth:`points`.
        Cq : list of array_like, optional
            The same for q.
        q_ratio : float, optional
            q = q_ratio p, used without Cq (q = 0 when both are None).
        """
        return self._rows(_IN_PLANE, Cp, Cq, q_ratio)

    def out_of_plane(self, Cp, Cq=None, q_ratio=None) -> tuple:
        """(sigma_zz, sigma_yz, sigma_xz) from the transforms at :meth:`points` (generalised
        plane strain: sigma_zz from the in-plane strains through C, the shears from the
        antiplane displacement); arguments as :meth:`stresses`."""
        return self._rows(_OUT_OF_PLANE, Cp, Cq, q_ratio)

    def voigt(self, Cp, Cq=None, q_ratio=None) -> np.ndarray:
        """All six stresses, Voigt order (XX, YY, ZZ, YZ, ZX, XY) along the first axis."""
        return np.stack(self._rows(range(6), Cp, Cq, q_ratio))

    def _rows(self, rows, Cp, Cq, q_ratio):
        rows = list(rows)
        n = len(self.zeta)
        Cp = self._stack("Cp", Cp, n)
        if Cq is None:
            K = self.K_p[rows] + (0.0 if q_ratio is None else float(q_ratio)) * self.K_q[rows]
            out = np.tensordot(K, Cp, axes=(1, 0))
        else:
            Cq = self._stack("Cq", Cq, n)
            out = (np.tensordot(self.K_p[rows], Cp, axes=(1, 0))
                   + np.tensordot(self.K_q[rows], Cq, axes=(1, 0)))
        return tuple(np.asarray(o.real) for o in out)

    @staticmethod
    def _stack(name, C, n):
        if len(C) != n:
            raise ContactInputError(
                f"{name} must hold the Cauchy transforms at the {n} points of points(X, Y), "
                f"got {len(C)}")
        return np.stack([np.asarray(c, dtype=complex) for c in C])


def stroh_modes(material, c) -> StrohModes:
    """The modes of an anisotropic half-space moving at the relative speed ``c``.

    Parameters
    ----------
    material : contact.anisotropic.Anisotropic
        Read through its ``check_speed``, ``stroh_matrix`` and ``surface_response``.
    c : float
        Relative speed V / sqrt(C66 / rho), 0 <= c < c_R.

    Returns
    -------
    StrohModes

    Raises
    ------
    SpeedError
        ``c`` not below the Rayleigh speed, negative or not finite.

    References
    ----------
    Stroh (1962); Ting (1996), ch. 5 and 12; Higham (2008), ch. 1; the module docstring.

    Examples
    --------
    An isotropic material at rest: the three roots are p = -i (a triple root, one cluster),
    and under Flamant's line load P = 1, C(z) = -1 / (pi z), sigma_yy on the axis at depth 2
    is -2P / (pi depth) (Johnson 1985, eq. (2.15)) and sigma_zz = nu (sigma_xx + sigma_yy):

    >>> import numpy as np
    >>> from contact.anisotropic import Anisotropic
    >>> from contact.stroh_modes import stroh_modes
    >>> modes = stroh_modes(Anisotropic.isotropic(2.5, 0.25), 0.0)
    >>> modes.clusters, bool(np.allclose(modes.roots, -1j))
    (((0, 1, 2),), True)
    >>> X, Y = np.array([0.0]), np.array([-2.0])
    >>> C = [-1.0 / (np.pi * z) for z in modes.points(X, Y)]
    >>> sxx, syy, sxy = modes.stresses(C)
    >>> szz, syz, sxz = modes.out_of_plane(C)
    >>> round(float(syy[0] * np.pi), 12), round(float(szz[0] * np.pi), 12)
    (-1.0, -0.25)
    """
    c = material.check_speed(c)
    response = material.surface_response(c)
    N = material.stroh_matrix(c)
    W = -(response.slope_local + 1j * response.slope_hilbert)
    A = N[3:, :3] @ W + N[3:, 3:]
    G = response.stress_hilbert - 1j * response.stress_local
    roots = np.linalg.eigvals(A)
    roots = roots[[j for cl in _clusters(roots) for j in cl]]     # grouped by cluster
    clusters = [tuple(cl) for cl in _clusters(roots)]
    zeta, functionals = _points(roots, clusters)
    dd = [_divided(roots, clusters, functionals, list(range(k + 1))) for k in range(3)]
    I = np.eye(3)
    basis = [I, A - roots[0] * I, (A - roots[0] * I) @ (A - roots[1] * I)]
    # K[a, m, l] = sum_k dd_k[l] (G B_k)[a, m]
    K = sum(np.einsum("am,l->aml", G @ B, d) for B, d in zip(basis, dd))
    K_q, K_p = K[:, 0, :], K[:, 1, :]
    for a in (roots, zeta, K_p, K_q):
        a.flags.writeable = False
    return StrohModes(c=c, roots=roots, zeta=zeta, clusters=tuple(clusters),
                      K_p=K_p, K_q=K_q)


def _clusters(roots) -> list:
    """The roots joined (transitively) where abs(x_i - x_j) < CLUSTER min(R_i, R_j),
    R = abs(Im x); a list of index lists in the order of their first members."""
    n = len(roots)
    label = list(range(n))
    for i in range(n):
        for j in range(i + 1, n):
            R = min(abs(roots[i].imag), abs(roots[j].imag))
            if abs(roots[i] - roots[j]) < CLUSTER * R:
                old, new = label[j], label[i]
                label = [new if v == old else v for v in label]
    out = {}
    for i, v in enumerate(label):
        out.setdefault(v, []).append(i)
    return list(out.values())


def _points(roots, clusters):
    """The points zeta_l and, per cluster, what gives f there: ('root', l) for a lone root
    (f at zeta_l = the root), ('circle', first l, m, h) for an interpolation circle."""
    zeta, functionals = [], []
    for cl in clusters:
        if len(cl) == 1:
            functionals.append(("root", len(zeta)))
            zeta.append(roots[cl[0]])
            continue
        m = np.mean(roots[list(cl)])
        h = RADIUS * abs(m.imag)
        functionals.append(("circle", len(zeta), m, h))
        zeta.extend(m + h * np.exp(2j * np.pi * np.arange(NODES) / NODES))
    return np.array(zeta, dtype=complex), functionals


def _divided(roots, clusters, functionals, nodes) -> np.ndarray:
    """The weights w_l with f[x_nodes] = sum_l w_l f(zeta_l) (Newton's divided difference
    at the roots listed in ``nodes``, which are grouped by cluster)."""
    where = {j: k for k, cl in enumerate(clusters) for j in cl}
    n_points = sum(1 if f[0] == "root" else NODES for f in functionals)
    first, last = where[nodes[0]], where[nodes[-1]]
    if first == last:
        w = np.zeros(n_points, dtype=complex)
        f = functionals[first]
        if f[0] == "root":
            w[f[1]] = 1.0
            return w
        _, l0, m, h = f
        order = len(nodes) - 1
        v = (roots[nodes] - m) / h
        hs = _complete_homogeneous(v, NODES)          # h_n(v), n = 0..NODES-1
        omega = np.exp(-2j * np.pi * np.arange(NODES) / NODES)
        j = np.arange(order, NODES)
        # c_j = (1/n) sum_l f(zeta_l) (h omega^l)^-j and
        # f[x_1..x_{order+1}] = sum_{j >= order} c_j h^(j - order) h_{j - order}(v)
        powers = omega[None, :] ** j[:, None]                      # (j, l)
        w[l0:l0 + NODES] = (hs[j - order] @ powers) / (NODES * h ** order)
        return w
    return (_divided(roots, clusters, functionals, nodes[1:])
            - _divided(roots, clusters, functionals, nodes[:-1])) / (roots[nodes[-1]]
                                                                     - roots[nodes[0]])


def _complete_homogeneous(v, n) -> np.ndarray:
    """h_0..h_{n-1} of the variables v (h_k: the sum of all monomials of degree k)."""
    h = np.zeros(n, dtype=complex)
    h[0] = 1.0
    for x in v:
        for k in range(1, n):
            h[k] = h[k] + x * h[k - 1]
    return h
