"""Independent references for the surface constants N11, N12, N21, N22 and the Rayleigh speed.

One home for the reference computations that ``tests/contact/test_contact_constants.py`` asserts
against and the report (section 2) tabulates; none of them calls :mod:`contact.constants`.

* **State space at one wavenumber k**: the 4x4 first-order system for the Fourier amplitudes
  w = (U, V, tau, sigma) of exp(i k X) in Y, eigen-decomposed by ``numpy.linalg.eig`` (or
  ``mpmath.eig`` at 40 digits for nearly repeated roots), decaying modes kept, unit surface
  tractions applied (:func:`eig_transfer`, :func:`eig_N`, :func:`mp_eig_N`).
* **Numerical Fourier inversion** of the surface response to a Gaussian load p (or q) =
  exp(-X^2), compared with N21 p, N11 Hc[p] etc.; Hc[exp(-t^2)] = -(2/sqrt(pi)) dawsn(x)
  (:func:`hc_gaussian`, :func:`invert_gaussian`, :func:`fourier_N`).
* **Moving isotropic closed forms** written with the Rayleigh function
  R(c) = 4 a_d a_s - (2 - c^2)^2, derived by hand, evaluated in mpmath at 40 digits
  (:func:`isotropic_moving`).
* **Rayleigh speed** as the root of Delta(c) at 40 digits (:func:`rayleigh_mp`) and as the
  sign change of 1/N11 of the state-space route (:func:`rayleigh_eig`).

Conventions (the documentation, Theory: the contact model and its conventions): half-space
Y < 0, sigma_YY(X,0) = -p, tau_XY(X,0) = -q, Hc[f](x) = (1/pi) PV int f(t)/(t - x) dt (Fourier
multiplier +i sgn k),
dv/dX = N12 q + N11 Hc[p],  sigma_XX(X,0) = N21 p + N22 Hc[q].
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["eig_transfer", "N_from_transfer", "eig_N", "mp_eig_N", "hc_gaussian",
           "invert_gaussian", "fourier_N", "FOURIER_X", "isotropic_moving", "rayleigh_mp",
           "rayleigh_eig"]


# ----------------------------------------------------------------------------------------
# state space at one wavenumber
# ----------------------------------------------------------------------------------------
def _state_matrix(m, c, k, one, I):
    """w = (U, V, tau, sigma) amplitudes of exp(i k X); w' = A w (d/dY).

    tau = C33 (U' + i k V), sigma = i k C12 U + C22 V'  (constitutive law, eq. (2.2));
    i k sigma_XX + tau' = -C33 c^2 k^2 U,  i k tau + sigma' = -C33 c^2 k^2 V  (eqs. (2.3)-(2.4)
    in the moving frame, rho V^2 = C33 c^2).  ``one`` and ``I`` are 1 and i in the arithmetic
    wanted (float/complex or mpmath).
    """
    C11, C12, C22, C33 = (one * x for x in (m.C11, m.C12, m.C22, m.C33))
    c2, k = (one * c) ** 2, one * k
    return [[0, -I * k, 1 / C33, 0],
            [-I * k * C12 / C22, 0, 0, 1 / C22],
            [k * k * (C11 - C12 ** 2 / C22 - C33 * c2), 0, 0, -I * k * C12 / C22],
            [0, -C33 * c2 * k * k, -I * k, 0]]


def _responses(W, m, k, I, solve):
    """Surface (dv/dX, sigma_XX) for unit p (sigma_YY = -1) and unit q (tau_XY = -1), from
    the two decaying modes W (columns) and a 2x2 linear solver."""
    out = []
    for p_hat, q_hat in ((1, 0), (0, 1)):
        a = solve([[W[2][0], W[2][1]], [W[3][0], W[3][1]]], [-q_hat, -p_hat])
        U, V, _, sig = (W[r][0] * a[0] + W[r][1] * a[1] for r in range(4))
        vx = I * k * V
        sxx = I * k * m.C11 * U + m.C12 * (sig - I * k * m.C12 * U) / m.C22
        out.append((vx, sxx))
    return out


def eig_transfer(m, c, k=1.0):
    """Complex transfer functions at wavenumber k, ``numpy.linalg.eig`` route.

    Returns (vx_p, sxx_p, vx_q, sxx_q): the Fourier amplitudes of dv/dX and sigma_XX(X,0)
    per unit amplitude of p (q = 0) and of q (p = 0).
    """
    A = np.array(_state_matrix(m, c, k, 1.0, 1j), dtype=complex)
    mu, vecs = np.linalg.eig(A)
    keep = mu.real > 0                          # exp(|k| eta Y) decays as Y -> -inf
    if keep.sum() != 2:
        raise ArithmeticError(f"expected two decaying modes, found {int(keep.sum())}")
    W = vecs[:, keep]
    (vx_p, sxx_p), (vx_q, sxx_q) = _responses(
        W, m, k, 1j, lambda M, r: np.linalg.solve(np.array(M), np.array(r, dtype=complex)))
    return vx_p, sxx_p, vx_q, sxx_q


def N_from_transfer(t, k):
    """dv/dX^ = N12 q^ + N11 (i sgn k) p^, sigma_XX^ = N21 p^ + N22 (i sgn k) q^."""
    vx_p, sxx_p, vx_q, sxx_q = t
    h = 1j * np.sign(k)                         # Fourier multiplier of Hc
    return np.array([vx_p / h, vx_q, sxx_p, sxx_q / h])


def eig_N(m, c, k=1.0):
    """(N11, N12, N21, N22) from the state-space route (complex; imaginary parts ~ rounding)."""
    return N_from_transfer(eig_transfer(m, c, k), k)


def mp_eig_N(m, c, dps=40):
    """The state-space route with ``mpmath.eig`` at ``dps`` digits (nearly repeated roots).

    A double root makes the two decaying eigenvectors parallel, so only ~dps/2 digits are
    left; an imaginary part above 10^(2 - dps/2) raises ArithmeticError."""
    import mpmath
    from mpmath import mp, mpf
    with mp.workdps(dps):
        one, I = mpf(1), mpmath.mpc(0, 1)
        mu, vecs = mp.eig(mpmath.matrix(_state_matrix(m, c, 1, one, I)))
        cols = [j for j in range(4) if mpmath.re(mu[j]) > 0]
        if len(cols) != 2:
            raise ArithmeticError(f"expected two decaying modes, found {len(cols)}")
        W = [[vecs[r, j] for j in cols] for r in range(4)]
        (vx_p, sxx_p), (vx_q, sxx_q) = _responses(
            W, m, 1, I, lambda M, r: list(mpmath.lu_solve(mpmath.matrix(M), mpmath.matrix(r))))
        N = [vx_p / I, vx_q, sxx_p, sxx_q / I]
        imag = max(abs(mpmath.im(z)) for z in N)
        if imag >= mpf(10) ** (-dps // 2 + 2):
            raise ArithmeticError(f"mpmath eig route: imaginary part {float(imag):.1e} left")
        return np.array([float(mpmath.re(z)) for z in N])


# ----------------------------------------------------------------------------------------
# Fourier inversion of a Gaussian surface load
# ----------------------------------------------------------------------------------------
def hc_gaussian(x):
    """Hc[exp(-t^2)](x) = (1/pi) PV int exp(-t^2)/(t - x) dt = -(2/sqrt(pi)) dawsn(x)."""
    from scipy.special import dawsn
    return -2.0 / math.sqrt(math.pi) * dawsn(x)


def invert_gaussian(T_plus, T_minus, x):
    """int_{-inf}^{inf} T(k) f^(k) e^{ikx} dk for f = exp(-X^2), f^(k) = e^{-k^2/4}/(2 sqrt(pi)),
    T(k) = T_plus for k > 0 and T_minus for k < 0 (QUADPACK's Fourier-weighted rules)."""
    from scipy.integrate import quad
    fhat = lambda k: math.exp(-k * k / 4) / (2 * math.sqrt(math.pi))      # noqa: E731
    cos_part, _ = quad(fhat, 0.0, 45.0, weight="cos", wvar=x, epsabs=1e-13, epsrel=1e-12)
    sin_part, _ = quad(fhat, 0.0, 45.0, weight="sin", wvar=x, epsabs=1e-13, epsrel=1e-12)
    return (T_plus + T_minus) * cos_part + 1j * (T_plus - T_minus) * sin_part


FOURIER_X = (0.0, 0.35, 1.0, 2.2, -1.7)


def fourier_N(m, c, xs=FOURIER_X):
    """N11..N22 read off the inverted surface response to a Gaussian load, by least squares
    over the sample points xs: vx_p = N11 Hc[g], sxx_p = N21 g, vx_q = N12 g, sxx_q = N22 Hc[g].

    Returns (N, the worst pointwise mismatch relative to the response's size, the largest
    imaginary part met, which should be rounding)."""
    Tp, Tm = eig_transfer(m, c, 1.0), eig_transfer(m, c, -1.0)
    g = np.array([math.exp(-x * x) for x in xs])
    hg = np.array([hc_gaussian(x) for x in xs])
    resp = np.array([[invert_gaussian(Tp[j], Tm[j], x) for x in xs] for j in range(4)])
    imag = float(np.max(np.abs(resp.imag)))
    r = resp.real
    fit = lambda y, basis: float(np.dot(y, basis) / np.dot(basis, basis))      # noqa: E731
    N = np.array([fit(r[0], hg), fit(r[2], g), fit(r[1], g), fit(r[3], hg)])
    pred = np.array([N[0] * hg, N[2] * g, N[1] * g, N[3] * hg])      # order of resp rows
    mis = float(np.max(np.abs(r - pred) / np.max(np.abs(pred), axis=1, keepdims=True)))
    return N, mis, imag


# ----------------------------------------------------------------------------------------
# classical isotropic limits and the Rayleigh speed
# ----------------------------------------------------------------------------------------
def isotropic_moving(G, nu, c):
    """Moving isotropic plane strain, derived by hand from the general formula:

    k^2 = (1 - 2nu) / (2(1 - nu)), a_d = sqrt(1 - k^2 c^2), a_s = sqrt(1 - c^2),
    R = 4 a_d a_s - (2 - c^2)^2,
    N11 = -c^2 a_d / (G R),               N12 = (2 - c^2 - 2 a_d a_s) / (G R),
    N21 = -(4 a_d (a_d - a_s) - (1 - 2k^2) c^4) / R,   N22 = -4 (1 - k^2) c^2 a_s / R.

    Evaluated in mpmath at 40 digits: R = O(c^2) cancels in double precision at small c.
    """
    from mpmath import mp, mpf, sqrt
    with mp.workdps(40):
        G, nu, c = mpf(G), mpf(nu), mpf(c)
        k2 = (1 - 2 * nu) / (2 * (1 - nu))
        ad, as_ = sqrt(1 - k2 * c * c), sqrt(1 - c * c)
        R = 4 * ad * as_ - (2 - c * c) ** 2
        N = [-c * c * ad / (G * R),
             (2 - c * c - 2 * ad * as_) / (G * R),
             -(4 * ad * (ad - as_) - (1 - 2 * k2) * c ** 4) / R,
             -4 * (1 - k2) * c * c * as_ / R]
        return np.array([float(x) for x in N])


def rayleigh_mp(m, guess):
    """Zero of Delta(c) = P (C22 C11' - C12^2) - C33 c^2 C11', P = sqrt((1 - c^2) C11'/C22),
    C11' = C11 - C33 c^2, at 40 digits (``mpmath.findroot`` from ``guess``); an mpf."""
    import mpmath
    from mpmath import mp, mpf
    with mp.workdps(40):
        C11, C12, C22, C33 = (mpf(x) for x in (m.C11, m.C12, m.C22, m.C33))

        def delta(c):
            C11p = C11 - C33 * c * c
            P = mpmath.sqrt((1 - c * c) * C11p / C22)
            return P * (C22 * C11p - C12 ** 2) - C33 * c * c * C11p

        return mpmath.re(mpmath.findroot(delta, mpf(guess)))


def rayleigh_eig(m, lo, hi):
    """c in [lo, hi] where 1/N11 of the state-space route crosses zero (the simple pole of
    N11 at c_R).  brentq raises unless 1/N11 changes sign on the bracket, so a bracket taken
    around the library's value is still an independent check."""
    from scipy.optimize import brentq
    return brentq(lambda c: 1.0 / eig_N(m, c)[0].real, lo, hi, xtol=1e-300,
                  rtol=4 * np.finfo(float).eps)
