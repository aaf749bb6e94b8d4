"""An independent influence-matrix solver for 2-D partial slip of two elastic bodies whose normal
and tangential problems couple (Dundurs' beta != 0).

Written from scratch with numpy/scipy only: it uses neither ``sie`` nor ``contact``'s solver, so
that a future solver of the coupled partial-slip problem can be tested against it.  Modelled
on ``tests/reference/bem_reference.py`` (uniform panels, piecewise-constant tractions,
collocation at the midpoints, an exact active-set solution of the discrete complementarity
problem).  No tests live here; see ``tests/reference/test_bem_partial_slip.py``.

Conventions (those of the library: ``contact.SurfaceConstants``)
----------------------------------------------------------------
Body 1 is the lower body, the half-space Y < 0; body 2 the upper one (the punch, Y > 0).  On
body 1's surface sigma_YY = -p (p >= 0 compressive) and sigma_XY = -q: q is the X-traction the
lower body exerts on the upper one (and -q the one the upper body exerts on the lower one).
u, v are the X- and Y-displacements.  For one isotropic half-space at rest (plane strain,
kappa = 3 - 4 nu; plane stress kappa = (3 - nu)/(1 + nu)), with
Hc[f](X) = (1/pi) PV int f(t)/(t - X) dt,

    dv/dX = N12 q + N11 Hc[p],       du/dX = -N12 p + N11 Hc[q],
    N11 = -(kappa + 1)/(4 G),        N12 = (kappa - 1)/(4 G).                         (1)

The first is the library's eq. (1) (``contact.SurfaceConstants``: N11 = -(1 - nu)/G,
N12 = (1 - 2 nu)/(2 G) in plane strain).  The second is its counterpart: du/dX per Hc[q] is the
``tangential_compliance`` (= N11 for an isotropic material), and du/dX per p is -N12 (the
local part of the slopes is antisymmetric, L_Xp = -L_Yq: the SurfaceConstants notes).  In
Johnson's form (Contact Mechanics, 1985, eqs. 2.25), with the traction f = -q along +X,
du/dX = -(kappa - 1)/(4 G) p - ((kappa + 1)/(4 pi G)) PV int f(t)/(X - t) dt: the loaded
surface is drawn toward the load (u = -(1 - 2 nu) P sgn(X)/(4 G) under a point force P), and a
tangential force drags the surface near it along.

Body 2 is body 1 mirrored in Y (v -> -v; it carries p and the X-traction +q), so
dv2/dX = N12_2 q - N11_2 Hc[p] and du2/dX = -N12_2 p - N11_2 Hc[q].  With Dundurs' parameters

    A = (kappa1 + 1)/G1 + (kappa2 + 1)/G2,
    beta = [(kappa2 - 1)/G2 - (kappa1 - 1)/G1] / A                                   (2)

(Dundurs 1969: beta = [G1 (kappa2 - 1) - G2 (kappa1 - 1)] / [G1 (kappa2 + 1) + G2 (kappa1 + 1)]),
the relative displacements w = v2 - v1 (normal) and s = u2 - u1 (tangential, the upper body's
slip on the lower one) satisfy

    dw/dX = (A/4) (Hc[p] + beta q),      ds/dX = (A/4) (Hc[q] - beta p).               (3)

(In plane strain A/4 = 2 [(1 - nu1^2)/E1 + (1 - nu2^2)/E2], the compliance often written A
in the fretting literature.)  A rigid punch (G2 -> inf) on an isotropic half-space has
A = (kappa1 + 1)/G1 and
beta = -(kappa1 - 1)/(kappa1 + 1) < 0 (-(1 - 2 nu)/(2 (1 - nu)) in plane strain), and (3) is (1)
with N11* = -A/4, N12* = -beta A/4: the library's pair constants, beta = N12*/N11*.  Two
bodies of one material (or an incompressible half-space under a rigid punch) have beta = 0.

The model
---------
The upper body's profile is Y = H(X) - delta (delta the rigid approach), so the gap and the
relative tangential displacement are, integrating (3) (d/dX log|X - t| = 1/(X - t), and
d/dX (1/2) sgn(X - t) = delta(X - t)),

    g(X) = H(X) - delta + (A/4) [ -(1/pi) int p(t) log|X - t| dt + beta int sgn(X - t) q(t) dt / 2 ],
    s(X) = D          + (A/4) [ -(1/pi) int q(t) log|X - t| dt - beta int sgn(X - t) p(t) dt / 2 ],

D the rigid tangential shift of the upper body (both constants of integration are rigid
motions and are absorbed in delta and D).  Contact: p >= 0, g >= 0, p g = 0.  Friction
(Coulomb, static, quasi-static): on the contact |q| <= mu p; in stick the increment of s over
a load step vanishes (Delta s = 0: the points that stick move together); in slip |q| = mu p
and q opposes the slip increment, q = -mu p sgn(Delta s) (q is the force on the upper body,
Delta s its motion relative to the lower one).  Off the contact p = q = 0.  Resultants:
int p = P, int q = Q (Q > 0: the lower body pushes the upper one along +X, i.e. the upper
body is pulled along -X by the external load).

Loading path.  With beta != 0 the problems couple and the answer depends on the path.  The
normal load is applied first, from the first touch, at Q = 0, in increments (for a growing
contact: Spence's problem, whose edges slip under the normal load alone; the rigid punch
(beta < 0) draws the half-space's surface toward the centre, so the friction on the punch
points inward: q < 0 on the right, q > 0 on the left); then Q is raised at constant P in
increments.  Each increment is solved exactly for the discretisation by a primal-dual
active-set iteration on the panels' states (separated, stick, slip with q = +mu p, slip with
q = -mu p), the slip direction from the increment (Kalker 1990, ch. 2; Hills & Nowell 1994,
ch. 2): a contact panel with p < 0 separates; a separated one with g < 0 touches (in stick);
a stick panel with |q| > mu p slips with the sign of q; a slip panel whose increment has the
sign of q (q Delta s > 0) sticks.  The joint iteration on all four states can cycle, so the
states are found by a staggered iteration (:meth:`Solver.step`): the normal LCP for the
current q, then the tangential problem for the new p (a strictly convex box-constrained QP:
min (1/2) q.(A/4)L q + c.q over |q| <= mu p, sum h q = Q, whose optimality conditions are
the friction law with Delta s its gradient), each by its own active set (one change at a
time if it cycles); after each sweep the joint linear system with the sweep's states is
solved and accepted if it satisfies every condition.  Full sliding (q = +-mu p on the whole
contact) is :meth:`Solver.sliding`: the library's equation N12* mu_f p + N11* Hc[p] = H'
(``bem_reference`` solves the same discrete problem; the tests compare them).

Discretisation
--------------
Uniform panels of width h on the window [X_min, X_max], p_j, q_j constant on each, collocation
at the midpoints x_i.  With F(t) = t log|t| - t (as in ``bem_reference``)

    L_ij = -(1/pi) int_panel j log|x_i - t| dt = -(1/pi) [F((k + 1/2) h) - F((k - 1/2) h)],
    S_ij = int_panel j sgn(x_i - t) dt / 2 = (h/2) sgn(k),        k = i - j,

both Toeplitz, L symmetric and S antisymmetric, and g = H - delta + (A/4) (L p + beta S q),
s = D + (A/4) (L q - beta S p).  The unknowns of one increment for given states are p on the
contact, q on the stick panels (q = +-mu p on the slip ones), delta and D; the equations are
g = 0 on the contact, s = s_previous on the stick panels, sum h p = P, sum h q = Q: a square
linear system.  A panel that comes into contact during a step has its stick condition
imposed over the whole step: an O(step) error, which sits in the slip zones at the edges of
a growing contact (Spence's problem) and so does not enter there.

Zone ends between grid points (the grid itself gives them to +-h/2):

* contact edge (free, smooth end): in a slip zone with q = eps mu p the pressure vanishes like
  d^g, g_R = 1/2 + arctan(eps beta mu)/pi at a right end, g_L = 1/2 - arctan(eps beta mu)/pi
  at a left end (the equation Hc[p] + eps beta mu p = smooth; cf.
  ``bem_reference.edge_exponents`` with xi = eps beta mu), so the gap outside grows like
  d^(1 + g); g^(1/(1 + g)) is fitted by a quadratic through panels 2..9 outside.
* stick-slip transition: near it, with the increments (dp, dq), write dq = eps mu dp + r on
  the contact, r = 0 on the slip side.  Eliminating dp through the normal equation
  (Hc^2 = -1: (Hc + eps beta mu)^-1 = -(Hc - eps beta mu)/(1 + beta^2 mu^2)) leaves, on the
  stick side, Hc[r] - eps beta mu r = smooth (the factor (1 - beta^2)/(1 + beta^2 mu^2)
  drops), so the stick deficit mu p - |q| ~ eps r vanishes like d^lam,
  lam = 1/2 - arctan(eps beta mu)/pi at the right end of a stick zone (slip zone on its
  right, q = eps mu p there) and 1/2 + arctan(eps beta mu)/pi at its left end; beta = 0 gives
  Cattaneo's square root.  (mu p - |q|)^(1/lam) is fitted by a quadratic through panels
  1..8 inside the stick zone (where the stick zone grows, as under a growing normal load, the
  deficit is an integral of such increments and vanishes like d^(1 + lam)); or, on the slip
  side, the slip accumulated in the present monotone phase, ~d^(1 + lam), through panels
  2..9 beyond the end (:func:`stick_zone`).  ``test_bem_partial_slip.py`` checks lam against
  a free power-law fit of the solution's own deficit.

Normal load alone (Spence's problem)
------------------------------------
Under a growing normal load the profile's slope does not change, so the load increment of a
Hertzian contact of half-width a is a flat-punch problem on [-a, a]: with the same stick-slip
conditions, c/a is the same for the growing cylinder (at every load: self-similarity) and for
the flat punch loaded proportionally.  In the limit beta -> 0 at fixed beta/mu the pressure is
the frictionless one and c/a is the root of K'(c/a)/K(c/a) = abs(beta)/mu
(:func:`goodman_stick_ratio`); the full problem also depends on beta mu (c/a = 0.8531,
0.8485, 0.8313, 0.8000, 0.7508 at beta/mu = 0.8 for beta = 0.04, 0.1, 0.2, 0.3, 0.4, flat
punch, m = 1600).  For large mu the slip zones shrink below a panel and the grid sees full
stick (the continuous full-stick solution has Abramov's oscillatory singularity, whose
traction ratio exceeds any mu, and even p < 0, in an exponentially thin layer at the edges).

References
----------
J. Dundurs, J. Appl. Mech. 36 (1969) 650 (the parameters alpha, beta).
K. L. Johnson, Contact Mechanics, Cambridge (1985), ch. 2 (eqs. 2.25), ch. 5 (partial slip;
    friction under normal load, sec. 5.5).
D. A. Hills, D. Nowell, Mechanics of Fretting Fatigue, Kluwer (1994), ch. 2-3 (the
    formulation with A and beta, incremental partial slip).
D. A. Spence, J. Elasticity 5 (1975) 297 (the Hertz problem with finite friction: a
    self-similar stick zone); Proc. Camb. Phil. Soc. 73 (1973) 249 (the flat punch with
    finite friction).  Neither was available here: no number of theirs is quoted.
L. E. Goodman, J. Appl. Mech. 29 (1962) 515 (the shear's effect on the pressure neglected).
J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling Contact, Kluwer (1990) (active-set
    solution of the incremental frictional problem).
C. Cattaneo, Rend. Accad. Naz. Lincei 27 (1938) 342 (the decoupled case).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg as sla

from bem_reference import _OneBlasThread      # small dense solves: one BLAS thread

__all__ = ["OFF", "STICK", "SLIP_POS", "SLIP_NEG",
           "dundurs", "rigid_punch_dundurs", "single_body_slopes",
           "influence_matrices", "parabolic", "flat", "rounded_flat",
           "State", "Solver", "load_path", "contact_edges", "stick_zone",
           "slip_edge_exponent", "stick_deficit_exponent",
           "hertz_closed_form", "cattaneo_closed_form", "goodman_stick_ratio", "richardson"]

#: panel states
OFF, STICK, SLIP_POS, SLIP_NEG = 0, 1, 2, 3


# --------------------------------------------------------------------------
# material constants
# --------------------------------------------------------------------------
def _kappa(nu, plane_strain=True):
    return 3.0 - 4.0 * nu if plane_strain else (3.0 - nu) / (1.0 + nu)


def dundurs(G1, nu1, G2=math.inf, nu2=0.0, plane_strain=True):
    """Dundurs' (A, beta) of eq. (2) of the module docstring.

    Parameters
    ----------
    G1, nu1 : float
        Shear modulus and Poisson's ratio of the lower body (the half-space Y < 0).
    G2, nu2 : float
        Those of the upper body (the punch); G2 = inf for a rigid punch.
    plane_strain : bool
        kappa = 3 - 4 nu (plane strain) or (3 - nu)/(1 + nu) (plane stress).

    Returns
    -------
    A, beta : float
        A = (kappa1 + 1)/G1 + (kappa2 + 1)/G2 and
        beta = [(kappa2 - 1)/G2 - (kappa1 - 1)/G1] / A.

    References
    ----------
    J. Dundurs, J. Appl. Mech. 36 (1969) 650; Hills & Nowell (1994), ch. 2.
    """
    k1, k2 = _kappa(nu1, plane_strain), _kappa(nu2, plane_strain)
    c1p, c1m = (k1 + 1.0) / G1, (k1 - 1.0) / G1
    c2p, c2m = ((k2 + 1.0) / G2, (k2 - 1.0) / G2) if math.isfinite(G2) else (0.0, 0.0)
    A = c1p + c2p
    return A, (c2m - c1m) / A


def rigid_punch_dundurs(G, nu, plane_strain=True):
    """(A, beta) of a rigid punch on an isotropic half-space: beta = -(kappa - 1)/(kappa + 1)."""
    return dundurs(G, nu, math.inf, 0.0, plane_strain)


def single_body_slopes(G, nu, plane_strain=True):
    """The coefficients of eq. (1) for one isotropic half-space at rest.

    Returns
    -------
    dict
        ``dv_dq`` = N12, ``dv_dHp`` = N11 (dv/dX = N12 q + N11 Hc[p]) and ``du_dp`` = -N12,
        ``du_dHq`` = N11 (du/dX = -N12 p + N11 Hc[q]), N11 = -(kappa + 1)/(4 G),
        N12 = (kappa - 1)/(4 G).

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), eqs. 2.25; ``contact.SurfaceConstants`` (the
    library's eq. (1) and the antisymmetry of the local part of the slopes).
    """
    k = _kappa(nu, plane_strain)
    N11, N12 = -(k + 1.0) / (4.0 * G), (k - 1.0) / (4.0 * G)
    return dict(dv_dq=N12, dv_dHp=N11, du_dp=-N12, du_dHq=N11)


# --------------------------------------------------------------------------
# kernels
# --------------------------------------------------------------------------
def _F(s):
    s = np.asarray(s, dtype=float)
    out = np.zeros_like(s)
    nz = s != 0.0
    out[nz] = s[nz] * (np.log(np.abs(s[nz])) - 1.0)
    return out


def influence_matrices(m, h):
    """(L, S): the m x m panel matrices of the log kernel and of the half sign kernel.

    L_ij = -(1/pi) int_panel_j log|x_i - t| dt,  S_ij = (1/2) int_panel_j sgn(x_i - t) dt
    (uniform panels of width h, x_i the midpoints; module docstring, Discretisation).
    """
    k = np.arange(m, dtype=float)
    L = sla.toeplitz(-(_F((k + 0.5) * h) - _F((k - 0.5) * h)) / math.pi)
    col = np.full(m, 0.5 * h)
    col[0] = 0.0
    S = sla.toeplitz(col, -col)
    return L, S


# --------------------------------------------------------------------------
# profiles
# --------------------------------------------------------------------------
def parabolic(R):
    """H(X) = X^2/(2R) (a cylinder, or two of relative radius R)."""
    return lambda X: np.asarray(X, dtype=float) ** 2 / (2.0 * R)


def flat(b):
    """A flat punch of half-width b: H = 0 (use the window [-b, b])."""
    return lambda X: np.zeros_like(np.asarray(X, dtype=float))


def rounded_flat(b, R):
    """A flat of half-width b with corners of radius R: H = (|X| - b)^2/(2R) beyond |X| = b."""
    def H(X):
        d = np.maximum(np.abs(np.asarray(X, dtype=float)) - b, 0.0)
        return d * d / (2.0 * R)
    return H


# --------------------------------------------------------------------------
# state and one increment
# --------------------------------------------------------------------------
@dataclass
class State:
    """The discrete solution after one load step.

    x, h : panel midpoints and width.
    p, q : tractions (module docstring for the signs).
    s : relative tangential displacement s = D + (A/4)(L q - beta S p) at the midpoints.
    g : gap (0 on the contact).
    state : OFF, STICK, SLIP_POS (q = +mu p) or SLIP_NEG (q = -mu p) per panel.
    delta, D : rigid approach and tangential shift.
    P, Q : the resultants.
    ds : the increment of s over the step that led here.
    iterations : active-set iterations of that step.
    """
    x: np.ndarray
    h: float
    p: np.ndarray
    q: np.ndarray
    s: np.ndarray
    g: np.ndarray
    state: np.ndarray
    delta: float
    D: float
    P: float
    Q: float
    ds: np.ndarray = field(default=None, repr=False)
    iterations: int = 0

    @property
    def contact(self):
        return self.state != OFF

    @property
    def stick(self):
        return self.state == STICK


class Solver:
    """The discrete model of the module docstring on a window with m panels.

    Parameters
    ----------
    H : callable
        The profile H(X).
    window : (float, float)
        [X_min, X_max]: contact is possible only there.
    m : int
        Number of panels.
    A, beta : float
        Dundurs' compliance and parameter (:func:`dundurs`).
    mu : float
        Coefficient of friction (> 0).
    """

    def __init__(self, H, window, m, A, beta, mu):
        self.window = tuple(float(v) for v in window)
        self.m = int(m)
        self.h = (self.window[1] - self.window[0]) / m
        self.x = self.window[0] + (np.arange(m) + 0.5) * self.h
        self.Hx = np.asarray(H(self.x), dtype=float)
        self.A, self.beta, self.mu = float(A), float(beta), float(mu)
        self.k = 0.25 * self.A
        self.L, self.S = influence_matrices(m, self.h)

    def initial(self):
        """The unloaded state: no contact, no displacement."""
        z = np.zeros(self.m)
        return State(self.x, self.h, z, z.copy(), z.copy(), self.Hx - self.Hx.min(),
                     np.full(self.m, OFF), 0.0, 0.0, 0.0, 0.0, z.copy())

    # -- the linear system for given states ---------------------------------------------
    def _solve_states(self, st, s_prev, P, Q):
        k, b, mu, h = self.k, self.beta, self.mu, self.h
        C = np.flatnonzero(st != OFF)
        T = np.flatnonzero(st == STICK)
        eps = np.where(st == SLIP_POS, 1.0, np.where(st == SLIP_NEG, -1.0, 0.0))
        nC, nT = C.size, T.size
        n = nC + nT + 2
        M = np.zeros((n, n))
        rhs = np.zeros(n)
        ec = eps[C] * mu
        # rows: g = 0 on C
        M[:nC, :nC] = k * (self.L[np.ix_(C, C)] + b * self.S[np.ix_(C, C)] * ec)
        M[:nC, nC:nC + nT] = k * b * self.S[np.ix_(C, T)]
        M[:nC, -2] = -1.0
        rhs[:nC] = -self.Hx[C]
        # rows: s = s_prev on T
        r = slice(nC, nC + nT)
        M[r, :nC] = k * (self.L[np.ix_(T, C)] * ec - b * self.S[np.ix_(T, C)])
        M[r, nC:nC + nT] = k * self.L[np.ix_(T, T)]
        M[r, -1] = 1.0
        rhs[r] = s_prev[T]
        # resultants
        M[-2, :nC] = h
        rhs[-2] = P
        M[-1, :nC] = h * ec
        M[-1, nC:nC + nT] = h
        rhs[-1] = Q
        sol = sla.solve(M, rhs, check_finite=False)
        p = np.zeros(self.m)
        q = np.zeros(self.m)
        p[C] = sol[:nC]
        q[T] = sol[nC:nC + nT]
        q += eps * mu * p
        delta, D = sol[-2], sol[-1]
        g = self.Hx - delta + k * (self.L @ p + b * (self.S @ q))
        g[C] = 0.0
        s = D + k * (self.L @ q - b * (self.S @ p))
        return p, q, g, s, delta, D

    # -- violations of the complementarity conditions for given states -------------------
    def _violations(self, st, p, q, g, ds, P):
        """(new states, size of each violation relative to its scale) for a solution of the
        linear system with the states ``st`` (module docstring: the active-set rules)."""
        mu = self.mu
        pscale = max(np.max(np.abs(p)), np.finfo(float).tiny)
        gscale = max(np.max(np.abs(g)), self.k * P, np.finfo(float).tiny)
        sscale = max(np.max(np.abs(ds)), self.k * self.h * pscale, np.finfo(float).tiny)
        C = st != OFF
        viol = np.zeros(self.m)
        new = st.copy()
        bad = C & (p < 0.0)
        viol[bad] = -p[bad] / pscale
        new[bad] = OFF
        bad = (~C) & (g < -1e-12 * gscale)
        viol[bad] = -g[bad] / gscale
        new[bad] = STICK
        bad = (st == STICK) & (np.abs(q) > mu * p + 1e-12 * pscale * mu) & (p >= 0.0)
        viol[bad] = (np.abs(q[bad]) - mu * p[bad]) / (mu * pscale)
        new[bad] = np.where(q[bad] > 0.0, SLIP_POS, SLIP_NEG)
        eps = np.where(st == SLIP_POS, 1.0, np.where(st == SLIP_NEG, -1.0, 0.0))
        bad = (eps != 0.0) & (eps * ds > 1e-12 * sscale) & (p >= 0.0)
        viol[bad] = eps[bad] * ds[bad] / sscale
        new[bad] = STICK
        return new, viol

    # -- the two convex subproblems of the staggered iteration ---------------------------
    def _normal(self, q, P, C0, maxiter=200):
        """p, delta for a given q: g = H - delta + (A/4)(L p + beta S q) >= 0, p >= 0, p g = 0,
        sum h p = P (an LCP with the symmetric positive definite L; active set)."""
        k, h = self.k, self.h
        Hq = self.Hx + k * self.beta * (self.S @ q)
        C = C0.copy()
        if not C.any():
            C[np.argmin(Hq)] = True
        seen, conservative = set(), False
        for _ in range(maxiter):
            idx = np.flatnonzero(C)
            n = idx.size
            M = np.empty((n + 1, n + 1))
            M[:n, :n] = k * self.L[np.ix_(idx, idx)]
            M[:n, n] = -1.0
            M[n, :n] = h
            M[n, n] = 0.0
            sol = sla.solve(M, np.concatenate([-Hq[idx], [P]]), check_finite=False)
            p = np.zeros(self.m)
            p[idx] = sol[:n]
            delta = sol[n]
            g = Hq - delta + k * (self.L[:, idx] @ sol[:n])
            g[idx] = 0.0
            gscale = max(np.max(np.abs(Hq - delta)), np.finfo(float).tiny)
            neg = C & (p < 0.0)
            pen = (~C) & (g < -1e-13 * gscale)
            if not (neg.any() or pen.any()):
                return p, delta, C
            key = C.tobytes()
            conservative = conservative or key in seen
            seen.add(key)
            if conservative:
                vp = -p.min() / max(p.max(), 1e-300)
                vg = -g.min() / gscale
                if vp >= vg:
                    C[np.argmin(p)] = False
                else:
                    C[np.argmin(g)] = True
            else:
                C = (C & ~neg) | pen
            if not C.any():
                C[np.argmin(Hq)] = True
        raise RuntimeError("normal active set did not converge")

    def _tangential(self, p, C, s_prev, Q, st0, maxiter=200):
        """q, D for a given p on the contact C: the box-constrained QP
        min (1/2) q.(A/4) L q - q.(s_prev + (A/4) beta S p) over |q| <= mu p, sum h q = Q,
        whose optimality conditions are the friction law with Delta s its gradient (+ D)."""
        k, h, mu = self.k, self.h, self.mu
        c = -s_prev - k * self.beta * (self.S @ p)        # Delta s = D + k L q + c
        st = np.where(C, np.where(st0 == OFF, STICK, st0), OFF)
        seen, conservative = set(), False
        for _ in range(maxiter):
            T = np.flatnonzero(st == STICK)
            eps = np.where(st == SLIP_POS, 1.0, np.where(st == SLIP_NEG, -1.0, 0.0))
            qf = eps * mu * p
            n = T.size
            M = np.empty((n + 1, n + 1))
            M[:n, :n] = k * self.L[np.ix_(T, T)]
            M[:n, n] = 1.0
            M[n, :n] = h
            M[n, n] = 0.0
            rhs = np.concatenate([-c[T] - k * (self.L[T] @ qf), [Q - h * qf.sum()]])
            sol = sla.solve(M, rhs, check_finite=False)
            q = qf.copy()
            q[T] = sol[:n]
            D = sol[n]
            ds = D + k * (self.L @ q) + c
            new, viol = self._violations(st, p, q, np.zeros(self.m), ds, 0.0)
            new[~C] = OFF
            if not np.any(new != st):
                return q, D, st
            key = st.tobytes()
            conservative = conservative or key in seen
            seen.add(key)
            if conservative:
                i = int(np.argmax(np.where(new != st, viol, -1.0)))
                st[i] = new[i]
            else:
                st = new
        raise RuntimeError("tangential active set did not converge")

    def sliding(self, P, eps, maxiter=200):
        """Full sliding, q = eps mu p everywhere on the contact (Q = eps mu P; the upper body
        slides toward -eps X): the normal LCP g = H - delta + (A/4)(L + eps beta mu S) p >= 0,
        p >= 0, p g = 0, sum h p = P, by the active set of :meth:`_normal` (the friction
        part (A/4) eps beta mu S is antisymmetric).  Returns a State (s, D undefined: nan)."""
        k, h = self.k, self.h
        K = k * (self.L + eps * self.beta * self.mu * self.S)
        C = np.zeros(self.m, bool)
        C[np.argmin(self.Hx)] = True
        seen, conservative = set(), False
        for it in range(1, maxiter + 1):
            idx = np.flatnonzero(C)
            n = idx.size
            M = np.empty((n + 1, n + 1))
            M[:n, :n] = K[np.ix_(idx, idx)]
            M[:n, n] = -1.0
            M[n, :n] = h
            M[n, n] = 0.0
            with _OneBlasThread():
                sol = sla.solve(M, np.concatenate([-self.Hx[idx], [P]]), check_finite=False)
            p = np.zeros(self.m)
            p[idx] = sol[:n]
            g = self.Hx - sol[n] + K[:, idx] @ sol[:n]
            g[idx] = 0.0
            gscale = max(np.max(np.abs(self.Hx - sol[n])), np.finfo(float).tiny)
            neg, pen = C & (p < 0.0), (~C) & (g < -1e-13 * gscale)
            if not (neg.any() or pen.any()):
                st = np.where(C, SLIP_POS if eps > 0 else SLIP_NEG, OFF)
                nan = np.full(self.m, np.nan)
                return State(self.x, self.h, p, eps * self.mu * p, nan, g, st, sol[n], np.nan,
                             P, eps * self.mu * P, nan, it)
            key = C.tobytes()
            conservative = conservative or key in seen
            seen.add(key)
            if conservative:
                if neg.any() and -p.min() / max(p.max(), 1e-300) >= -g.min() / gscale:
                    C[np.argmin(p)] = False
                else:
                    C[np.argmin(g)] = True
            else:
                C = (C & ~neg) | pen
        raise RuntimeError("sliding active set did not converge")

    def step(self, prev, P, Q, maxiter=200):
        """Solve the increment from ``prev`` to the resultants (P, Q).

        Staggered (block Gauss-Seidel, Kalker's and Hills & Nowell's normal-tangential
        iteration): the normal LCP for the current q, then the tangential box QP for the new
        p, each by its own active set; after each sweep the joint linear system with the
        sweep's panel states (exact for the discretisation) is solved and accepted if it
        satisfies every condition (module docstring), else the sweeps go on.
        """
        st = prev.state.copy()
        q = prev.q.copy()
        for it in range(1, maxiter + 1):
            p, _, C = self._normal(q, P, st != OFF)
            q, _, st = self._tangential(p, C, prev.s, Q, st)
            p2, q2, g2, s2, delta, D = self._solve_states(st, prev.s, P, Q)
            ds = s2 - prev.s
            new, _ = self._violations(st, p2, q2, g2, ds, P)
            if not np.any(new != st):
                return State(self.x, self.h, p2, q2, s2, g2, st, delta, D, P, Q, ds, it)
        raise RuntimeError(f"staggered iteration did not converge in {maxiter} sweeps")


def load_path(solver, P, Q=0.0, normal_steps=20, tangential_steps=10, first=None,
              growing=True, keep=False):
    """Normal load from the first touch to P at Q = 0, then Q from 0 at constant P.

    Parameters
    ----------
    solver : Solver
    P, Q : float
        The final resultants (abs(Q) < mu P).
    normal_steps, tangential_steps : int
        Number of increments of each phase (the tangential phase is skipped at Q = 0).
    first : float, optional
        The first load; default P / normal_steps^2.
    growing : bool
        Normal loads P (k / n)^2 (k = 1..n: a Hertzian contact's half-width grows evenly) if
        True, else P k / n.
    keep : bool
        Return the list of all states instead of the last one.
    """
    st = solver.initial()
    n = int(normal_steps)
    t = np.arange(1, n + 1) / n
    loads = P * (t * t if growing else t)
    if first is not None:
        loads = np.concatenate([[first], loads[loads > first]])
    out = []
    with _OneBlasThread():
        for Pk in loads:
            st = solver.step(st, float(Pk), 0.0)
            out.append(st)
        if Q != 0.0:
            for Qk in Q * np.arange(1, tangential_steps + 1) / tangential_steps:
                st = solver.step(st, float(P), float(Qk))
                out.append(st)
    return out if keep else st


# --------------------------------------------------------------------------
# local exponents and zone ends between grid points
# --------------------------------------------------------------------------
def slip_edge_exponent(beta, mu, eps, side):
    """g with p ~ d^g at a smooth contact edge inside a slip zone where q = eps mu p:
    1/2 + arctan(eps beta mu)/pi at a right edge (side = +1), 1/2 - ... at a left one."""
    return 0.5 + side * math.atan(eps * beta * mu) / math.pi


def stick_deficit_exponent(beta, mu, eps, side):
    """lam with mu p - |q| ~ d^lam inside a stick zone at its end on ``side`` (+1 right, -1
    left), next to a slip zone where q = eps mu p: 1/2 - side arctan(eps beta mu)/pi."""
    return 0.5 - side * math.atan(eps * beta * mu) / math.pi


def _root_of_power_fit(x, y, power, deg, near):
    """Root nearest ``near`` of the polynomial of degree ``deg`` fitted to y^(1/power)."""
    if x.size <= deg or np.any(y <= 0.0):
        return None
    c = np.polyfit(x - near, y ** (1.0 / power), deg)
    r = np.roots(c)
    r = r[np.abs(r.imag) <= 1e-12 * max(1.0, np.max(np.abs(r)))].real if r.size else r
    if r.size == 0:
        return None
    return near + r[np.argmin(np.abs(r))]


def _runs(mask):
    idx = np.flatnonzero(mask)
    if idx.size == 0:
        return []
    cut = np.flatnonzero(np.diff(idx) > 1)
    return list(zip(np.concatenate([[idx[0]], idx[cut + 1]]).tolist(),
                    np.concatenate([idx[cut], [idx[-1]]]).tolist()))


def _eps(st, i):
    return 1.0 if st[i] == SLIP_POS else (-1.0 if st[i] == SLIP_NEG else 0.0)


def contact_edges(state, beta, mu):
    """(a_left, a_right) of the one contact zone, between grid points.

    At a smooth free edge the gap outside grows like d^(1 + g) (g from
    :func:`slip_edge_exponent`, or 1/2 in stick); a quadratic in g^(1/(1 + g)) through panels
    2..9 outside gives its root.  An edge on the window's end (a flat punch) is the window's
    end.
    """
    runs = _runs(state.contact)
    if len(runs) != 1:
        raise ValueError(f"{len(runs)} contact zones")
    (i0, i1), = runs
    x, h, m = state.x, state.h, state.x.size
    out = []
    for side, last in ((-1, i0), (1, i1)):
        grid = x[last] + side * 0.5 * h
        io = last + side * np.arange(2, 10)
        if not np.all((io >= 0) & (io < m)):
            out.append(float(grid))
            continue
        e = _eps(state.state, last)
        g = slip_edge_exponent(beta, mu, e, side) if e != 0.0 else 0.5
        r = _root_of_power_fit(x[io], state.g[io], 1.0 + g, 2, grid)
        out.append(float(grid) if r is None else float(min(max(r, grid - h), grid + h)))
    return tuple(out)


def stick_zone(state, beta, mu, slip_since=None, growing=False):
    """(c_left, c_right) of the one stick zone, between grid points (module docstring).

    Parameters
    ----------
    state : State
    beta, mu : float
    slip_since : ndarray, optional
        s at a reference state: the slip measured from it, abs(s - slip_since), grows like
        d^(1 + lam) beyond a stick end (lam of :func:`stick_deficit_exponent`; the slip is the
        integral of the slope Hc[q] - beta p, which jumps like d^lam), the analogue of the gap
        outside a contact edge; a quadratic in it^(1/(1 + lam)) through panels 2..9 beyond the
        end gives the end (the more accurate estimate, as the gap is in ``bem_reference``).
        Pass the s of the state where the present monotone phase began (the end of the normal
        loading, for Q raised at constant P: the stick zone recedes, and the slip accumulated
        since is the closed-form one of a single step), or that of the previous step for a
        stick zone that grows (Spence's problem: the last increment is a flat-punch problem),
        or zeros for a single proportional step (a flat punch).
    growing : bool
        Only where ``slip_since`` is None or the slip zone is too short: the stick deficit
        mu p - |q| is fitted instead (panels 1..8 inside), ~d^lam where the stick zone recedes
        or stays, ~d^(1 + lam) where it grows (a point joins the stick zone as the end passes
        it, and its deficit is the integral of increments ~ (c(t) - x)^lam).

    Returns the grid's own end where the stick zone reaches the contact's edge.
    """
    runs = _runs(state.stick)
    if len(runs) != 1:
        raise ValueError(f"{len(runs)} stick zones")
    (i0, i1), = runs
    x, h, st = state.x, state.h, state.state
    deficit = mu * state.p - np.abs(state.q)
    out = []
    for side, last in ((-1, i0), (1, i1)):
        grid = x[last] + side * 0.5 * h
        nb = last + side
        if not (0 <= nb < x.size) or st[nb] == OFF:
            out.append(float(grid))
            continue
        lam = stick_deficit_exponent(beta, mu, _eps(st, nb), side)
        r = None
        io = last + side * np.arange(2, 10)
        if slip_since is not None and np.all((io >= 0) & (io < x.size)) and np.all(st[io] == st[nb]):
            r = _root_of_power_fit(x[io], np.abs(state.s[io] - slip_since[io]), 1.0 + lam, 2, grid)
        ii = last - side * np.arange(1, 9)
        if r is None and np.all((ii >= i0) & (ii <= i1)):
            r = _root_of_power_fit(x[ii], deficit[ii], lam + (1.0 if growing else 0.0), 2, grid)
        out.append(float(grid) if r is None else float(min(max(r, grid - h), grid + h)))
    return tuple(out)


# --------------------------------------------------------------------------
# closed forms (beta = 0) and extrapolation
# --------------------------------------------------------------------------
def hertz_closed_form(A, R, P):
    """Frictionless (or beta = 0) cylinder: a = sqrt(A R P / (2 pi)) and
    p = (4/(A R)) sqrt(a^2 - X^2) (from Hc[p] = -4 H'/A on the contact)."""
    a = math.sqrt(A * R * P / (2.0 * math.pi))

    def p(X):
        X = np.asarray(X, dtype=float)
        return 4.0 / (A * R) * np.sqrt(np.maximum(a * a - X * X, 0.0))
    return a, p


def cattaneo_closed_form(A, R, P, Q, mu):
    """Cattaneo's partial slip of a cylinder (beta = 0), Q > 0 along the module's convention:
    c/a = sqrt(1 - Q/(mu P)), q = mu p0 (sqrt(1 - X^2/a^2) - (c/a) sqrt(1 - X^2/c^2)) (the
    second term on |X| < c only), p0 = 4 a/(A R).

    References
    ----------
    C. Cattaneo (1938); K. L. Johnson, Contact Mechanics (1985), sec. 7.1.
    """
    a, p = hertz_closed_form(A, R, P)
    c = a * math.sqrt(1.0 - abs(Q) / (mu * P))
    s = math.copysign(1.0, Q)

    def q(X):
        X = np.asarray(X, dtype=float)
        inner = c / a * np.sqrt(np.maximum(1.0 - X * X / (c * c), 0.0)) * (4.0 * a / (A * R))
        return s * mu * (p(X) - inner)
    return a, c, q


def goodman_stick_ratio(beta_over_mu):
    """c/a of the flat punch (and of a growing Hertzian contact) under normal load alone in the
    limit beta -> 0 at fixed beta/mu: the root of K'(k)/K(k) = abs(beta)/mu.

    Derivation (Goodman's approximation: the shear's effect on the pressure neglected, which is
    exact as beta mu -> 0).  Flat punch on [-1, 1], p = 1/sqrt(1 - x^2) (Hc[p] = 0 there),
    q = mu qt; stick |x| < c: Hc[qt] = r p (r = beta/mu, eq. (3) with Delta s = 0); slip:
    qt = -sigma sgn(x) p.  With qt = -sigma sgn(x) p + phi, phi odd on (-c, c) solves
    Hc[phi] = r p + sigma Hc[sgn p] =: f there, and is bounded at both ends iff
    int_{-c}^{c} f / sqrt(c^2 - x^2) dx = 0.  With b = sqrt(1 - x^2),
    Hc[sgn p](x) = (2/pi) PV int_0^1 t dt / ((t^2 - x^2) sqrt(1 - t^2)) = (2/pi) artanh(b)/b,
    int_0^c dx / (b sqrt(c^2 - x^2)) = K(c) and int_0^c artanh(b) dx / (b sqrt(c^2 - x^2))
    = (pi/2) K'(c) (checked by quadrature in the tests), so abs(r) = K'(c)/K(c), sigma
    = -sgn(r).  The increment of Spence's self-similar Hertz problem under normal load is this
    flat-punch problem on the current contact (H' does not change with the load), hence the
    same c/a.  K(k) is the complete elliptic integral of the first kind of modulus k and
    K'(k) = K(sqrt(1 - k^2)).

    References
    ----------
    D. A. Spence, J. Elasticity 5 (1975) 297 (self-similarity; c/a a function of beta/mu);
    L. E. Goodman, J. Appl. Mech. 29 (1962) 515 (the approximation); K. L. Johnson, Contact
    Mechanics (1985), sec. 5.5.
    """
    from scipy.optimize import brentq
    from scipy.special import ellipk
    r = abs(beta_over_mu)
    if r == 0.0:
        return 1.0
    return brentq(lambda k: ellipk(1.0 - k * k) / ellipk(k * k) - r, 1e-300, 1.0 - 1e-16,
                  xtol=1e-15)


def richardson(values, hs, order):
    """Extrapolate the last two of ``values`` (at mesh sizes ``hs``) to h = 0 assuming an
    error ~ h^order; returns (extrapolated, |extrapolated - last|)."""
    v1, v2 = values[-2], values[-1]
    r = (hs[-2] / hs[-1]) ** order
    ext = v2 + (v2 - v1) / (r - 1.0)
    return ext, abs(ext - v2)


# --------------------------------------------------------------------------
# convergence study (python tests/reference/bem_partial_slip.py): the numbers quoted in the
# tests and the converged table
# --------------------------------------------------------------------------
def _table_row(m, beta, mu, xis_normal, xis_tangential, Qfrac):  # pragma: no cover
    A, R, P = 4.0, 1.0, 0.5 * math.pi                 # beta = 0 would give a = 1, p0 = 1
    sv = Solver(parabolic(R), (-1.25, 1.25), m, A, beta, mu)
    sts = load_path(sv, P, Qfrac * mu * P, normal_steps=m // 2, tangential_steps=10, keep=True)
    n = m // 2
    sp, prev = sts[n - 1], sts[n - 2]
    a = contact_edges(sp, beta, mu)
    c_def = stick_zone(sp, beta, mu, growing=True)
    c_slip = stick_zone(sp, beta, mu, slip_since=prev.s)
    row = dict(a=a[1], c_a=c_def[1] / a[1], c_a_slip=c_slip[1] / a[1])
    for xi in xis_normal:
        row[f"qN({xi:+.2f})"] = float(np.interp(xi * a[1], sp.x, sp.q)) / mu
    st = sts[-1]
    a2 = contact_edges(st, beta, mu)
    c2 = stick_zone(st, beta, mu, slip_since=sp.s)
    c2d = stick_zone(st, beta, mu)
    row.update(aQ_left=a2[0], aQ_right=a2[1], cL_a=c2[0] / a2[1], cR_a=c2[1] / a2[1],
               cL_a_def=c2d[0] / a2[1],
               cR_a_def=c2d[1] / a2[1])
    for xi in xis_tangential:
        row[f"qT({xi:+.2f})"] = float(np.interp(xi * a2[1], st.x, st.q)) / mu
    fl = Solver(flat(1.0), (-1.0, 1.0), m, A, beta, mu)
    sf = load_path(fl, 1.0, 0.0, normal_steps=1)
    row["flat_c_a"] = stick_zone(sf, beta, mu)[1]
    row["flat_c_a_slip"] = stick_zone(sf, beta, mu, slip_since=np.zeros(m))[1]
    return row


def convergence_report(ms=(100, 200, 400, 800), cases=((-0.2857142857142857, 0.3),
                                                       (-0.5, 0.5)), Qfrac=0.5):  # pragma: no cover
    """Print c/a and q/(mu p0) for the normal load alone (Spence) and after Q = Qfrac mu P,
    on the grids ``ms``, with the observed order and Richardson extrapolation from the last
    two grids.

    A = 4, R = 1, P = pi/2 (beta = 0 would give a0 = 1, p0 = 4 a0/(A R) = 1), window
    [-1.25, 1.25], normal load in m/2 steps P (k/n)^2, then Q in 10 steps.  Rows: ``a`` the
    contact half-width under P alone, ``c_a`` its stick end / a (deficit; ``c_a_slip`` from
    the last step's slip), ``qN(xi)`` = q(xi a)/mu; after Q: the contact ends ``aQ_*``, the
    stick ends / aQ_right from the slip since Q = 0 (``cL_a``, ``cR_a``) and from the deficit
    (``*_def``), ``qT(xi)`` = q(xi aQ_right)/mu; ``flat_c_a*`` the flat punch [-1, 1] under
    normal load (one step).
    """
    import time
    for beta, mu in cases:
        print(f"beta = {beta:.6g}, mu = {mu:g} (beta/mu = {beta / mu:.6g}; Goodman limit c/a = "
              f"{goodman_stick_ratio(beta / mu):.6f}), Q = {Qfrac} mu P")
        rows = []
        for m in ms:
            t0 = time.perf_counter()
            with _OneBlasThread():
                rows.append(_table_row(m, beta, mu, (0.25, 0.5, 0.75), (-0.5, 0.0, 0.5), Qfrac))
            print(f"  m = {m}: {time.perf_counter() - t0:.1f} s", flush=True)
        hs = [2.5 / m for m in ms]
        for key in rows[0]:
            v = [r[key] for r in rows]
            d1, d2 = v[-2] - v[-3], v[-1] - v[-2]
            order = math.log2(abs(d1 / d2)) if d2 != 0 and d1 != 0 else float("nan")
            ext, err = richardson(v, hs, 1.0)
            print(f"  {key:12s} " + " ".join(f"{x:+.6f}" for x in v)
                  + f"  order {order:4.2f}  Richardson(1) {ext:+.6f} (change {err:.1e})", flush=True)


if __name__ == "__main__":                             # pragma: no cover
    convergence_report()
