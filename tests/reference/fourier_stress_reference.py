"""Independent references for the subsurface stress field of the moving orthotropic half-space.

Nothing here imports :mod:`contact`; a material is read only through its four stiffnesses
(attributes ``C11, C12, C22, C33`` or a tuple), so the references share no code with
:mod:`contact.subsurface` (which works with the characteristic roots of Zhou et al. 2014,
eq. (3.1), modal vectors and Cauchy transforms).

1. :class:`FourierReference` -- numerical Fourier inversion of the 4x4 state-space form.

   Plane strain, steady motion in the moving frame (tension positive)::

       sigma_xx = C11 u_X + C12 v_Y,  sigma_yy = C12 u_X + C22 v_Y,  sigma_xy = C33 (u_Y + v_X),
       sigma_xx,X + sigma_xy,Y = C33 c^2 u_XX,   sigma_xy,X + sigma_yy,Y = C33 c^2 v_XX.

   For one Fourier mode exp(i k X), k > 0, and the state w = (u, v, T, S), T = sigma_xy / k,
   S = sigma_yy / k, these give dw/dY = k M w with (derivation: u_Y = sigma_xy / C33 - i k v;
   v_Y = (sigma_yy - i k C12 u) / C22; sigma_xx = i k (C11 - C12^2/C22) u + (C12/C22) sigma_yy;
   T_Y = (-i k sigma_xx - C33 c^2 k^2 u) / k; S_Y = (-i k sigma_xy - C33 c^2 k^2 v) / k)::

       M = [[0,                          -i,        1/C33, 0         ],
            [-i C12/C22,                 0,         0,     1/C22     ],
            [C11 - C12^2/C22 - C33 c^2,  0,         0,     -i C12/C22],
            [0,                          -C33 c^2,  -i,    0         ]].

   The solution decaying as Y -> -inf lies in the invariant subspace of the two eigenvalues
   of M with Re > 0: either the eigenvectors (``method="eig"``, numpy.linalg.eig; distinct
   eigenvalues only) or an ordered complex Schur basis (``method="schur"``,
   scipy.linalg.schur with sort="rhp"; also valid for the defective double eigenvalue of the
   static isotropic material).  With the scaled state w~ = k w (so that the stresses are
   sigma_yy = S~, sigma_xy = T~, independent of k) the two amplitudes are fitted to
   sigma_yy^(k, 0) = -p^(k), sigma_xy^(k, 0) = -q^(k), and

       sigma(X, Y) = (1/pi) Re int_0^inf sigma^(k, Y) exp(i k X) dk

   (the k < 0 half is the complex conjugate because the field is real).  The k integral is
   done with Gauss-Legendre panels up to where exp(-k Re(lambda_min) |Y|) < 1e-16, or, for
   a point load (p^ = P, q^ = Q constant), in closed form: int_0^inf exp(k (t Y + i X)) dk =
   -1 / (t Y + i X).  The displacement gradients u_X, v_X, u_Y, v_Y come with the stresses
   (so that the equations of motion can be checked by finite differences).

2. :func:`isotropic_moving_flamant` -- the moving (0 < c < c_R) line loads on an isotropic
   half-space from displacement potentials (Cole & Huth 1958 type solution, derived here):
   u = phi_X + psi_Y, v = phi_Y - psi_X, with beta_1^2 phi_XX + phi_YY = 0 and
   beta_2^2 psi_XX + psi_YY = 0, beta_1^2 = 1 - c^2 G / (lambda + 2 G), beta_2^2 = 1 - c^2,
   so phi_XX = Re f(z_1), psi_XX = Re g(z_2), z_j = X + i beta_j Y (Im z_j < 0 for Y < 0),
   and

       sigma_yy = -G (1 + beta_2^2) Re f + 2 G beta_2 Im g,
       sigma_xy = -G [2 beta_1 Im f + (1 + beta_2^2) Re g],
       sigma_xx = G (1 + 2 beta_1^2 - beta_2^2) Re f - 2 G beta_2 Im g.

   With 1 / (X - i0) = PV 1/X + i pi delta(X) and R = (1 + beta_2^2)^2 - 4 beta_1 beta_2 (the
   Rayleigh function, > 0 below c_R):
   normal load p = P delta (sigma_yy(X, 0) = -P delta, sigma_xy = 0):
   f = i A / z_1, g = B / z_2, A = -P (1 + beta_2^2) / (pi G R), B = 2 beta_1 P / (pi G R);
   tangential load q = Q delta (sigma_xy(X, 0) = -Q delta, sigma_yy = 0):
   f = A' / z_1, g = i B' / z_2, A' = -2 beta_2 Q / (pi G R), B' = -(1 + beta_2^2) Q / (pi G R).
   At c = 0 (R = 0) use :func:`static_flamant` instead.

3. :func:`static_flamant`, :func:`mcewen_hertz` -- the classical static isotropic fields
   (Flamant; McEwen 1949 / Johnson 1985 for Hertz tractions), in this project's axes.

Conventions as in :mod:`contact.subsurface`: half-space Y < 0, sigma_YY(X, 0) = -p,
sigma_XY(X, 0) = -q.
"""
from __future__ import annotations

import math

import numpy as np
import scipy.linalg
from scipy.special import j1

__all__ = ["FIELDS", "FourierReference", "state_matrix", "hertz_hat", "strip_hat", "static_flamant",
           "isotropic_moving_flamant", "mcewen_hertz", "hertz_cauchy", "lame"]

#: Field names returned by :meth:`FourierReference.field` in this order.
FIELDS = ("sigma_xx", "sigma_yy", "sigma_xy", "u_X", "v_X", "u_Y", "v_Y")


def _stiffnesses(material):
    if isinstance(material, (tuple, list)):
        return tuple(float(x) for x in material)
    return (float(material.C11), float(material.C12), float(material.C22),
            float(material.C33))


def lame(E, nu):
    """(lambda, G) of an isotropic material in plane strain."""
    G = E / (2.0 * (1.0 + nu))
    return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), G


def state_matrix(C11, C12, C22, C33, c):
    """The matrix M of dw/dY = k M w (module docstring)."""
    rv = C33 * c * c
    return np.array([[0.0, -1j, 1.0 / C33, 0.0],
                     [-1j * C12 / C22, 0.0, 0.0, 1.0 / C22],
                     [C11 - C12 * C12 / C22 - rv, 0.0, 0.0, -1j * C12 / C22],
                     [0.0, -rv, -1j, 0.0]], dtype=complex)


def hertz_hat(p0, a):
    """k -> p^(k) = int p(t) exp(-i k t) dt of p = p0 sqrt(1 - t^2/a^2): p0 pi J1(k a) / k."""
    def f(k):
        k = np.asarray(k, dtype=float)
        return p0 * math.pi * j1(k * a) / k
    return f


def strip_hat(p0, a):
    """k -> p^(k) of the uniform strip p0 on [-a, a]: 2 p0 sin(k a) / k."""
    def f(k):
        k = np.asarray(k, dtype=float)
        return 2.0 * p0 * np.sin(k * a) / k
    return f


def hertz_cauchy(p0, a):
    """C_p(z) = (1/pi) int p(t)/(t - z) dt of the Hertz pressure, Im z > 0:
    p0 (sqrt(w - 1) sqrt(w + 1) - w) = -p0 / (sqrt(w - 1) sqrt(w + 1) + w), w = z / a
    (the second form has no cancellation for |w| >> 1)."""
    def C(z):
        w = np.asarray(z, dtype=complex) / a
        return -p0 / (np.sqrt(w - 1.0) * np.sqrt(w + 1.0) + w)
    return C


class FourierReference:
    """The stress field of tractions (p, q) on the moving orthotropic half-space by Fourier
    inversion of the state-space form (module docstring, item 1).

    Parameters
    ----------
    material : object with C11, C12, C22, C33, or a 4-tuple
    c : float
        Relative speed V / sqrt(C33 / rho).
    method : "eig" or "schur"
        How the decaying subspace of M is represented.
    """

    def __init__(self, material, c, method="eig"):
        C11, C12, C22, C33 = _stiffnesses(material)
        self.M = M = state_matrix(C11, C12, C22, C33, c)
        if method == "eig":
            lam, vec = np.linalg.eig(M)
            keep = lam.real > 0
            if keep.sum() != 2:
                raise ValueError(f"expected two eigenvalues with Re > 0, got {lam}")
            Z1 = vec[:, keep]
            T11 = np.diag(lam[keep])
        elif method == "schur":
            T, Z, sdim = scipy.linalg.schur(M, output="complex", sort="rhp")
            if sdim != 2:
                raise ValueError(f"expected two eigenvalues with Re > 0, got {np.diag(T)}")
            Z1, T11 = Z[:, :2], T[:2, :2]
        else:
            raise ValueError(method)
        # output map of the scaled state w~ = k w: (sxx, syy, sxy, u_X, v_X, u_Y, v_Y)
        L = np.zeros((7, 4), dtype=complex)
        L[0] = [1j * (C11 - C12 * C12 / C22), 0.0, 0.0, C12 / C22]
        L[1] = [0.0, 0.0, 0.0, 1.0]
        L[2] = [0.0, 0.0, 1.0, 0.0]
        L[3] = [1j, 0.0, 0.0, 0.0]
        L[4] = [0.0, 1j, 0.0, 0.0]
        L[5] = M[0]
        L[6] = M[1]
        B = Z1[[3, 2], :]                      # (S~, T~) at Y = 0
        amp = np.linalg.solve(B, np.array([[-1.0, 0.0], [0.0, -1.0]], dtype=complex))
        self.out = L @ Z1                      # (7, 2)
        self.amp = amp                         # columns: unit p^, unit q^
        self.T11 = T11
        self.eigenvalues = np.diag(T11).copy()
        self.lambda_min = float(np.min(self.eigenvalues.real))

    # -- the 2x2 propagator exp(s T11), s = k Y <= 0 -------------------------------------------
    def _propagator(self, s):
        t1, t2, t12 = self.T11[0, 0], self.T11[1, 1], self.T11[0, 1]
        e1, e2 = np.exp(s * t1), np.exp(s * t2)
        ta, tb = (t1, t2) if t1.real <= t2.real else (t2, t1)
        x = s * (tb - ta)                      # Re x <= 0
        with np.errstate(invalid="ignore", divide="ignore"):
            phi1 = np.where(x == 0, 1.0, np.expm1(x) / np.where(x == 0, 1.0, x))
        e12 = t12 * np.exp(s * ta) * s * phi1  # t12 (e1 - e2) / (t1 - t2), no cancellation
        return e1, e2, e12

    def _modal(self, s, f_hat, g_hat):
        """sigma^ (7, nk) at s = k Y for loads f_hat = p^(k), g_hat = q^(k) (arrays)."""
        e1, e2, e12 = self._propagator(s)
        cvec = self.amp[:, 0][:, None] * f_hat + self.amp[:, 1][:, None] * g_hat   # (2, nk)
        y0 = e1 * cvec[0] + e12 * cvec[1]
        y1 = e2 * cvec[1]
        return self.out[:, 0][:, None] * y0 + self.out[:, 1][:, None] * y1

    def field(self, X, Y, p_hat, q_hat=None, q_ratio=None, length=1.0, panel=1.0, nodes=24,
              tail=37.0):
        """The fields (dict of FIELDS -> arrays) at points (X, Y), Y < 0.

        p_hat, q_hat : callables k -> Fourier transforms of p and q (k > 0, arrays); or
        q_ratio = mu for q = mu p.  ``length`` is the load's length scale (the half-width a);
        the k axis is cut in panels of ``panel / length`` with ``nodes`` Gauss-Legendre nodes
        each, up to where exp(-k lambda_min |Y|) < exp(-tail).
        """
        X, Y = np.broadcast_arrays(np.asarray(X, float), np.asarray(Y, float))
        gx, gw = np.polynomial.legendre.leggauss(nodes)
        h = panel / length
        out = {name: np.empty(X.shape) for name in FIELDS}
        for idx in np.ndindex(X.shape):
            x, y = X[idx], Y[idx]
            if not y < 0:
                raise ValueError("Y must be < 0")
            kmax = tail / (self.lambda_min * -y)
            npan = int(math.ceil(kmax / h))
            left = h * np.arange(npan)
            k = (left[:, None] + 0.5 * h * (gx + 1.0)[None, :]).ravel()
            w = np.tile(0.5 * h * gw, npan)
            ph = p_hat(k)
            if q_hat is not None:
                qh = q_hat(k)
            else:
                qh = (0.0 if q_ratio is None else q_ratio) * ph
            sig = self._modal(k * y, ph, qh)
            vals = (sig * (w * np.exp(1j * k * x))[None, :]).sum(axis=1).real / math.pi
            for name, v in zip(FIELDS, vals):
                out[name][idx] = v
        return out

    def point_load(self, X, Y, P=1.0, Q=0.0):
        """The fields of the line loads p = P delta(X), q = Q delta(X), k integral exact."""
        X, Y = np.broadcast_arrays(np.asarray(X, float), np.asarray(Y, float))
        t1, t2, t12 = self.T11[0, 0], self.T11[1, 1], self.T11[0, 1]
        A1 = t1 * Y + 1j * X
        A2 = t2 * Y + 1j * X
        F1, F2, F12 = -1.0 / A1, -1.0 / A2, t12 * Y / (A1 * A2)
        cvec = self.amp[:, 0] * P + self.amp[:, 1] * Q
        y0 = F1 * cvec[0] + F12 * cvec[1]
        y1 = F2 * cvec[1]
        vals = [(self.out[i, 0] * y0 + self.out[i, 1] * y1).real / math.pi for i in range(7)]
        return dict(zip(FIELDS, vals))


def static_flamant(X, Y, P=1.0, Q=0.0):
    """(sigma_xx, sigma_yy, sigma_xy) of static line loads p = P delta, q = Q delta at the
    origin of an isotropic half-space Y < 0 (independent of the elastic constants).

    Johnson (1985) eqs. (2.15)-(2.19) with depth z = -Y, sigma_XY = -tau_xz and a tangential
    force Q_J = -Q in +x on the solid:
    sigma_xx = 2 (P X^2 Y + Q X^3) / (pi r^4), sigma_yy = 2 (P Y^3 + Q X Y^2) / (pi r^4),
    sigma_xy = 2 (P X Y^2 + Q X^2 Y) / (pi r^4).
    """
    X, Y = np.asarray(X, float), np.asarray(Y, float)
    r4 = (X * X + Y * Y) ** 2 * math.pi
    return (2.0 * (P * X * X * Y + Q * X ** 3) / r4,
            2.0 * (P * Y ** 3 + Q * X * Y * Y) / r4,
            2.0 * (P * X * Y * Y + Q * X * X * Y) / r4)


def isotropic_moving_flamant(E, nu, c, X, Y, P=1.0, Q=0.0):
    """(sigma_xx, sigma_yy, sigma_xy) of line loads p = P delta, q = Q delta moving at the
    relative speed 0 < c < c_R over an isotropic half-space (module docstring, item 2)."""
    lam, G = lame(E, nu)
    b1 = math.sqrt(1.0 - c * c * G / (lam + 2.0 * G))
    b2 = math.sqrt(1.0 - c * c)
    R = (1.0 + b2 * b2) ** 2 - 4.0 * b1 * b2
    X, Y = np.asarray(X, float), np.asarray(Y, float)
    z1, z2 = X + 1j * b1 * Y, X + 1j * b2 * Y
    A = -P * (1.0 + b2 * b2) / (math.pi * G * R)
    B = 2.0 * b1 * P / (math.pi * G * R)
    Ap = -2.0 * b2 * Q / (math.pi * G * R)
    Bp = -(1.0 + b2 * b2) * Q / (math.pi * G * R)
    f = (1j * A + Ap) / z1
    g = (B + 1j * Bp) / z2
    syy = -G * (1.0 + b2 * b2) * f.real + 2.0 * G * b2 * g.imag
    sxy = -G * (2.0 * b1 * f.imag + (1.0 + b2 * b2) * g.real)
    sxx = G * (1.0 + 2.0 * b1 * b1 - b2 * b2) * f.real - 2.0 * G * b2 * g.imag
    return sxx, syy, sxy


def _mn(x, z, a):
    A = a * a - x * x + z * z
    R = np.sqrt(A * A + 4.0 * x * x * z * z)
    m = np.sqrt(np.maximum(R + A, 0.0) / 2.0) * np.sign(z)
    n = np.sqrt(np.maximum(R - A, 0.0) / 2.0) * np.sign(x)
    return m, n


def mcewen_hertz(X, Y, p0=1.0, a=1.0, mu=0.0):
    """(sigma_xx, sigma_yy, sigma_xy) in this project's axes of the static isotropic
    half-space under p = p0 sqrt(1 - X^2/a^2) and q = mu p (so sigma_XY(X, 0) = -mu p).

    McEwen (1949); Johnson, Contact Mechanics (1985), Sec. 7.1, with depth z = -Y and
    m^2 = (sqrt((a^2 - x^2 + z^2)^2 + 4 x^2 z^2) + (a^2 - x^2 + z^2)) / 2,
    n^2 = (sqrt(...) - (a^2 - x^2 + z^2)) / 2, sign(m) = sign(z), sign(n) = sign(x).

    Normal pressure p0:
        sigma_x = -(p0/a) [m (1 + (z^2 + n^2)/(m^2 + n^2)) - 2 z],
        sigma_z = -(p0/a) m (1 - (z^2 + n^2)/(m^2 + n^2)),
        tau_xz  = -(p0/a) n (m^2 - z^2)/(m^2 + n^2).
    Tangential traction q_J = q0 sqrt(1 - x^2/a^2) on the solid in +x:
        sigma_x = +(q0/a) [n (2 - (z^2 - m^2)/(m^2 + n^2)) - 2 x],
        sigma_z = -(q0/a) n (m^2 - z^2)/(m^2 + n^2),
        tau_xz  = -(q0/a) [m (1 + (z^2 + n^2)/(m^2 + n^2)) - 2 z].

    SIGN CORRECTIONS.  These formulas also circulate with tau_xz = +(p0/a) n (...) for the
    normal load and sigma_x = -(q0/a)[...], sigma_z = +(q0/a) n (...) for the tangential one.
    Integrating the Flamant kernels (Johnson eqs. 2.15 and 2.19) over the Hertz distribution
    with scipy.integrate.quad gives the signs above (agreement ~1e-15 at 9 points inside,
    outside, near an end and deep; the other signs are off by 0.06-0.9 p0).  Independent sanity
    checks of the corrected signs: on the surface |x| < a the tangential sigma_x is -2 q0 x / a
    (= -(2/pi) int q(s)/(x - s) ds, the Flamant surface limit); for x > 0 the normal load gives
    tau_xz < 0 like its Flamant kernel -2 P x z^2 / (pi r^4); and tau_xz(normal) =
    sigma_z(tangential) q0/p0 (reciprocity of the two kernels, -2 x z^2 / (pi r^4) both).

    Mapping to this project: sigma_XX = sigma_x, sigma_YY = sigma_z, sigma_XY = -tau_xz,
    and q_J = -q, i.e. q0 = -mu p0.
    """
    x = np.asarray(X, float)
    z = -np.asarray(Y, float)
    m, n = _mn(x, z, a)
    s = m * m + n * n
    sx = -(p0 / a) * (m * (1.0 + (z * z + n * n) / s) - 2.0 * z)
    sz = -(p0 / a) * m * (1.0 - (z * z + n * n) / s)
    txz = -(p0 / a) * n * (m * m - z * z) / s
    q0 = -mu * p0
    if q0 != 0.0:
        sx = sx + (q0 / a) * (n * (2.0 - (z * z - m * m) / s) - 2.0 * x)
        sz = sz - (q0 / a) * n * (m * m - z * z) / s
        txz = txz - (q0 / a) * (m * (1.0 + (z * z + n * n) / s) - 2.0 * z)
    return sx, sz, -txz
