"""An independent influence-matrix (boundary-element) solver for the frictional punch.

Written from scratch with numpy/scipy only: it uses neither ``sie`` nor ``contact``'s solver,
so that it can serve as a reference for multi-zone contact (a face that touches in several
places, zones that merge as the load grows).  No tests live here; see
``tests/reference/test_bem_reference.py``.

The model (conventions of the documentation, Theory: the contact model and its conventions)
------------------------------------------------------------------------------------------
Half-space Y < 0, v the Y-displacement of its surface, pressure p >= 0 (compressive positive),
shear q = mu_f p.  The surface relation dv/dX = N12 q + N11 Hc[p], with
Hc[f](X) = (1/pi) PV int f(t)/(t - X) dt, integrates, using

    d/dX log|X - t| = 1/(X - t) = -1/(t - X)   =>   Hc[p](X) = d/dX [-(1/pi) int p(t) log|X - t| dt],

to

    u(X) := v(X) = N12 mu_f int_{-inf}^X p(t) dt - (N11/pi) int_L p(t) log|X - t| dt + const.

u is the *upward* displacement.  The library's N11 is negative (static isotropic:
N11 = -(1 - nu)/G), so -(N11/pi) log|X - t| = (|N11|/pi) log|X - t| grows away from the load:
the loaded part of the surface sinks relative to the far field, as it must (this is the
2-D Boussinesq/Flamant result w_down = -(2(1 - nu^2)/(pi E)) int p log|X - t| + C with
2(1 - nu^2)/E = (1 - nu)/G).  The punch face is Y = H(X) - delta (delta the rigid approach),
so the gap is

    g(X) = H(X) - u(X) - delta,      g = 0 on L,  g >= 0 off L,  p >= 0,  p g = 0,

and differentiating g = 0 on L gives back N12 mu_f p + N11 Hc[p] = H'(X) = v'(X): the
library's equation, with the library's sign of N11.

Cylinder, frictionless (the sign check).  With (1/pi) PV int_{-a}^{a} sqrt(a^2 - t^2)/(t - X) dt
= -X (|X| < a), p = C sqrt(a^2 - X^2) solves N11 Hc[p] = X/R iff C = -1/(N11 R); so

    p(X) = sqrt(a^2 - X^2) / (|N11| R),   P = pi a^2 / (2 |N11| R),   a = sqrt(2 |N11| R P / pi),

positive because N11 < 0.  (With N11 > 0 this model would give tensile pressure: the solver
refuses N11 >= 0.)

Local behaviour at a free (smooth) end.  Near a left end a, p ~ (X - a)^g_L; the analytic
continuation of (1/pi) PV int_0^inf t^g/(t - x) dt = -cot(pi g) x^g (-1 < g < 0) gives the
leading term -cot(pi g_L) (X - a)^g_L of Hc[p], so N12 mu_f - N11 cot(pi g_L) = 0:

    cot(pi g_L) = xi,   cot(pi g_R) = -xi,   xi = N12 mu_f / N11,   g_L + g_R = 1,

with the principal arccot in (0, pi), g in (0, 1) (bounded, vanishing pressure).  mu_f > 0
(punch sliding toward -X, trailing edge on the right) gives g_R < 1/2 < g_L.  The solver
uses g_L, g_R only to place the zone edges between grid points (p^(1/g) is linear in the
distance to the edge); ``tests/reference/test_bem_reference.py`` checks them against the slope of
log p at the edges of the discrete solution.

Discretisation
--------------
Uniform panels of width h on the face [X_min, X_max], piecewise-constant pressure p_j,
collocation at the panel midpoints x_i.  With F(s) = s log|s| - s (F' = log|s|, F(0) = 0),

    int_{t_j}^{t_j + h} log|x_i - t| dt = F(x_i - t_j) - F(x_i - t_j - h),

so the influence matrix is Toeplitz: A_ij = -(N11/pi) [F((k + 1/2) h) - F((k - 1/2) h)]
+ N12 mu_f T_k, k = i - j, T_k = h (k > 0), h/2 (k = 0), 0 (k < 0).  The linear
complementarity problem (u = A p, g = H - A p - delta, sum h p_j = P) is solved exactly for
the discretisation by a primal-dual active-set iteration (drop panels with p < 0, add panels
with g < 0, resolve; with a one-change-at-a-time fallback if it ever cycles).  The friction
part of A has the symmetric part (N12 mu_f h/2) 1 1^T, which vanishes on load-preserving
variations, so the problem stays monotone (unique solution) with friction.

Zone edges are placed between grid points from the grid solution itself: outside a free
end g ~ d^(1 + g_R) (right end), inside p ~ d^g_R, so g^(1/(1 + g_R)) is smooth in d; a
quadratic fitted through the gap a few panels out gives the edge to ~0.03 h (first order in
h, with a small, erratic constant; see the tests).

Continuous edges (``refine``).  For fixed zones [a_k, b_k], each zone gets n cosine-graded
panels (the node spacing ~ d^(1/2) near the edges makes d^g smooth in the node index), a
piecewise-linear pressure vanishing at the edges, and u = H - delta collocated at all
interior nodes plus the load: a square linear system.  The edges are the roots of the gap
at the 2K edge nodes (Newton); the bounded solution exists only for the right edges, which
converge like n^-2 and are Richardson-extrapolated from n and 2n.  The log integrals against
hat functions are closed form (with G(s) = s^2/2 log|s| - s^2/4, G' = s log|s|).

Merge of two zones: see :func:`merge_load_bem` (both sides of the merge) and
:func:`merge_load_grid` (bisection on the grid solution's number of zones).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg as sla

__all__ = ["BemResult", "solve_bem", "load_curve_bem", "merge_load_bem", "merge_load_grid",
           "edge_exponents",
           "cylinder_closed_form", "w_face", "w_face_closed_form", "w_face_reference",
           "PolynomialFaceOneZone",
           "influence_matrix"]


# --------------------------------------------------------------------------
# BLAS threads: the dense solves here are small (<= a few thousand); a multithreaded
# OpenBLAS on a busy machine makes them 10-100x slower and erratic, so they run on one
# thread (best effort: the OpenBLAS libraries already loaded, restored afterwards).
# --------------------------------------------------------------------------
class _OneBlasThread:
    _libs = None

    @classmethod
    def _find(cls):
        if cls._libs is None:
            import ctypes
            libs = []
            try:
                paths = sorted({ln.split()[-1] for ln in open("/proc/self/maps")
                                if "openblas" in ln.lower() and ln.rstrip().endswith(".so")})
            except OSError:
                paths = []
            for path in paths:
                try:
                    lib = ctypes.CDLL(path)
                except OSError:
                    continue
                for get, set_ in (("scipy_openblas_get_num_threads64_", "scipy_openblas_set_num_threads64_"),
                                  ("scipy_openblas_get_num_threads", "scipy_openblas_set_num_threads"),
                                  ("openblas_get_num_threads", "openblas_set_num_threads")):
                    if hasattr(lib, get) and hasattr(lib, set_):
                        g, s = getattr(lib, get), getattr(lib, set_)
                        g.restype = ctypes.c_int
                        s.argtypes = [ctypes.c_int]
                        libs.append((g, s))
                        break
            cls._libs = libs
        return cls._libs

    def __enter__(self):
        self._saved = []
        for g, s in self._find():
            self._saved.append((s, g()))
            s(1)
        return self

    def __exit__(self, *exc):
        for s, n in self._saved:
            s(n)
        return False


def _one_thread(fn):
    import functools

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        with _OneBlasThread():
            return fn(*args, **kwargs)
    return wrapper


# --------------------------------------------------------------------------
# kernel
# --------------------------------------------------------------------------
def _F(s):
    s = np.asarray(s, dtype=float)
    out = np.zeros_like(s)
    nz = s != 0.0
    out[nz] = s[nz] * (np.log(np.abs(s[nz])) - 1.0)
    return out


def influence_matrix(m, h, N11, N12_muf):
    """m x m matrix A with u(x_i) = sum_j A_ij p_j (uniform panels of width h, midpoints)."""
    k = np.arange(m, dtype=float)
    logcol = _F((k + 0.5) * h) - _F((k - 0.5) * h)           # int over panel j of log|x_i - t|, k = i - j >= 0
    A = sla.toeplitz(-(N11 / math.pi) * logcol)               # symmetric in k
    if N12_muf != 0.0:
        fr = np.full(m, h)
        fr[0] = 0.5 * h
        A += N12_muf * np.tril(sla.toeplitz(fr))                # int_{-inf}^{x_i} p
    return A


def edge_exponents(N11, N12_muf):
    """(g_L, g_R): p ~ (X - a)^g_L at a left free end, (b - X)^g_R at a right one."""
    xi = N12_muf / N11
    gL = (0.5 * math.pi - math.atan(xi)) / math.pi              # principal arccot / pi, in (0, 1)
    return gL, 1.0 - gL


def cylinder_closed_form(N11, R, P):
    """Frictionless cylinder H = X^2/(2R): half-width a and pressure p(X) (N11 < 0)."""
    a = math.sqrt(2.0 * abs(N11) * R * P / math.pi)

    def p(X):
        X = np.asarray(X, dtype=float)
        return np.sqrt(np.maximum(a * a - X * X, 0.0)) / (abs(N11) * R)
    return a, p


# --------------------------------------------------------------------------
# result
# --------------------------------------------------------------------------
@dataclass
class BemResult:
    """One BEM solution.

    zones : list of (start, end) in X, edges placed between grid points (see module doc);
        an edge on the face boundary is the boundary itself (flagged in ``at_face_end``).
    zone_panels : list of (i0, i1), the active panels i0..i1 (inclusive) of each zone.
    x, p : panel midpoints and pressure there (p = 0 off the active set).
    gap : g at the midpoints (0 on the active set).
    delta : rigid approach.
    load_check : |h sum p - P| / P.
    complementarity : max(-min p, -min g, max |p g|) relative to the scales of p and g.
    iterations : active-set iterations.
    zones_grid : the zones of the uniform-grid solution (edges extrapolated from the grid).
    refined : whether ``zones`` come from the continuous-edge refinement (which passed its
        complementarity check); edge_error its estimate; delta_refined its approach.
    """
    zones: list
    zone_panels: list
    x: np.ndarray
    p: np.ndarray
    gap: np.ndarray
    delta: float
    load: float
    load_check: float
    complementarity: float
    iterations: int
    h: float
    at_face_end: bool
    exponents: tuple
    seconds: float = 0.0
    active: np.ndarray = field(default=None, repr=False)
    zones_grid: list = None
    refined: bool = False
    delta_refined: float = None
    edge_error: float = None
    fitted: tuple = field(default=None, repr=False)

    def pressure(self, X):
        """p(X): the refined (piecewise-linear) pressure if refined, else the grid's."""
        X = np.asarray(X, dtype=float)
        if self.refined:
            ts, pf = self.fitted
            nn = ts[0].size
            out = np.zeros_like(X)
            for k, t in enumerate(ts):
                inside = (X >= t[0]) & (X <= t[-1])
                out[inside] = np.interp(X[inside], t, pf[k * nn:(k + 1) * nn])
            return out
        i = np.clip(np.floor((X - self.x[0]) / self.h + 0.5).astype(int), 0, self.x.size - 1)
        return self.p[i]

    @property
    def n_zones(self):
        return len(self.zones)


# --------------------------------------------------------------------------
# active-set LCP
# --------------------------------------------------------------------------
def _solve_on(A, Hm, S, h, P):
    n = S.size
    M = np.empty((n + 1, n + 1))
    M[:n, :n] = A[np.ix_(S, S)]
    M[:n, n] = 1.0
    M[n, :n] = h
    M[n, n] = 0.0
    rhs = np.empty(n + 1)
    rhs[:n] = Hm[S]
    rhs[n] = P
    sol = sla.solve(M, rhs, check_finite=False)
    return sol[:n], sol[n]


def _active_set(A, Hm, h, P, S0, maxiter=500):
    m = Hm.size
    S = np.zeros(m, bool)
    S[S0] = True
    seen = set()
    conservative = False
    for it in range(1, maxiter + 1):
        idx = np.flatnonzero(S)
        pS, delta = _solve_on(A, Hm, idx, h, P)
        p = np.zeros(m)
        p[idx] = pS
        g = Hm - A[:, idx] @ pS - delta
        g[idx] = 0.0
        gscale = max(np.max(np.abs(Hm - delta)), np.finfo(float).tiny)
        pscale = max(np.max(np.abs(pS)), np.finfo(float).tiny)
        neg_p = idx[pS < 0.0]
        pen = np.flatnonzero((~S) & (g < -1e-13 * gscale))
        if neg_p.size == 0 and pen.size == 0:
            return p, g, delta, S, it
        key = S.tobytes()
        if key in seen:
            conservative = True
        seen.add(key)
        if conservative:              # one change at a time: the most violated constraint
            vp = -pS.min() / pscale if neg_p.size else 0.0
            vg = -g[pen].min() / gscale if pen.size else 0.0
            if vp >= vg:
                S[idx[np.argmin(pS)]] = False
            else:
                S[pen[np.argmin(g[pen])]] = True
        else:
            S[neg_p] = False
            S[pen] = True
        if not S.any():
            S[np.argmin(Hm)] = True
    raise RuntimeError(f"active set did not converge in {maxiter} iterations")


# --------------------------------------------------------------------------
# zone edges
# --------------------------------------------------------------------------
def _runs(S):
    idx = np.flatnonzero(S)
    if idx.size == 0:
        return []
    cut = np.flatnonzero(np.diff(idx) > 1)
    starts = np.concatenate([[idx[0]], idx[cut + 1]])
    ends = np.concatenate([idx[cut], [idx[-1]]])
    return list(zip(starts.tolist(), ends.tolist()))


def _root_of_power_fit(x, y, power, deg, near):
    """Root nearest ``near`` of the polynomial of degree ``deg`` fitted (least squares) to
    y^(1/power) against x."""
    if x.size <= deg or np.any(y <= 0.0):
        return None
    c = np.polyfit(x - near, y ** (1.0 / power), deg)
    r = np.roots(c)
    r = r[np.abs(r.imag) <= 1e-12 * max(1.0, np.max(np.abs(r)))].real if r.size else r
    if r.size == 0:
        return None
    return near + r[np.argmin(np.abs(r))]


def _edge(x, p, g, run, side, gamma, h, lim):
    """Edge of the zone ``run`` = (i0, i1) of the grid solution on ``side`` (-1 left, +1
    right), between grid points.  Outside a free end the gap grows like d^(1 + gamma), inside
    the pressure like d^gamma; after the power 1/(...) both are smooth in d, and a quadratic
    is fitted a few panels away from the edge, where the grid's own edge (a panel boundary)
    pollutes them least: the gap through panels 2..9 beyond the last active one if the free
    region ``lim`` has room (|error| <~ 0.03 h in the tests), else the pressure through
    panels 1..8 inside (<~ 0.1 h), else a straight line through the last two.  The result
    is clamped to within one panel of the grid's edge (a panel boundary)."""
    i0, i1 = run
    last = i1 if side > 0 else i0
    grid_edge = x[last] + side * 0.5 * h
    out = None
    io = last + side * np.arange(2, 10)
    if np.all((io > lim[0]) & (io < lim[1])):
        out = _root_of_power_fit(x[io], g[io], 1.0 + gamma, 2, grid_edge)
    for ks, deg in ((np.arange(1, 9), 2), (np.arange(0, 2), 1)):
        if out is not None:
            break
        ii = last - side * ks
        if np.all((ii >= i0) & (ii <= i1)):
            out = _root_of_power_fit(x[ii], p[ii], gamma, deg, grid_edge)
    if out is None or not np.isfinite(out):
        return float(grid_edge)
    return float(min(max(out, grid_edge - h), grid_edge + h))


# --------------------------------------------------------------------------
# zone-fitted refinement: continuous edges
# --------------------------------------------------------------------------
def _G(s):
    s = np.asarray(s, dtype=float)
    out = np.zeros_like(s)
    nz = s != 0.0
    s2 = s[nz] * s[nz]
    out[nz] = 0.5 * s2 * np.log(np.abs(s[nz])) - 0.25 * s2
    return out


def _zone_nodes(a, b, n):
    """n panels on [a, b], cosine-graded toward both ends (the pressure ~ d^g there)."""
    k = np.arange(n + 1)
    t = a + 0.5 * (b - a) * (1.0 - np.cos(np.pi * k / n))
    t[0], t[-1] = a, b
    return t


def _hat_matrix(xc, t, N11, N12_muf):
    """u(xc) per unit nodal value of a piecewise-linear p on the nodes t (all n + 1 nodes).

    log part: int phi_j(t) log|x - t| dt with J0 = int log|s| ds = F, J1 = int s log|s| ds = G,
    s = t - x; friction part: int_{-inf}^{x} phi_j (x is a node or lies outside the zone)."""
    t0, t1 = t[:-1], t[1:]
    w = t1 - t0
    s0 = t0[None, :] - xc[:, None]
    s1 = t1[None, :] - xc[:, None]
    J0 = _F(s1) - _F(s0)
    J1 = _G(s1) - _G(s0)
    left = (s1 * J0 - J1) / w              # hat of the panel's left node
    right = (J1 - s0 * J0) / w             # hat of its right node
    K = np.zeros((xc.size, t.size))
    K[:, :-1] += left
    K[:, 1:] += right
    K *= -(N11 / math.pi)
    if N12_muf != 0.0:
        # fraction of panel [t0, t1] left of x: full (w/2 to each node) if t1 <= x, else 0;
        # x lies on a node or outside the zone, so no panel is cut (tolerance for rounding)
        full = (t1[None, :] <= xc[:, None] + 1e-14 * max(1.0, np.max(np.abs(t))))
        Fr = np.zeros_like(K)
        Fr[:, :-1] += 0.5 * w * full
        Fr[:, 1:] += 0.5 * w * full
        K += N12_muf * Fr
    return K


class _Fitted:
    """Piecewise-linear pressure on cosine-graded zones [a_k, b_k], p = 0 at the edges,
    u = H - delta collocated at every interior node, int p = P.  The residual is the gap
    at the 2K edges; the edges are where it vanishes."""

    def __init__(self, H, N11, N12_muf, P, n):
        self.H, self.N11, self.N12_muf, self.P, self.n = H, N11, N12_muf, P, n

    def solve(self, edges):
        edges = np.asarray(edges, dtype=float)
        K = edges.size // 2
        ts = [_zone_nodes(edges[2 * k], edges[2 * k + 1], self.n) for k in range(K)]
        xc = np.concatenate(ts)                          # all nodes: collocation points
        cols, wts = [], []
        for t in ts:
            cols.append(_hat_matrix(xc, t, self.N11, self.N12_muf)[:, 1:-1])
            w = np.diff(t)
            wts.append(0.5 * (w[:-1] + w[1:]))           # trapezoid weights, interior nodes
        M = np.hstack(cols)
        wts = np.concatenate(wts)
        nn = self.n + 1
        interior = np.ones(xc.size, bool)
        interior[0::nn] = False
        interior[nn - 1::nn] = False
        Hx = np.asarray(self.H(xc), dtype=float)
        nI = int(interior.sum())
        S = np.empty((nI + 1, nI + 1))
        S[:nI, :nI] = M[interior]
        S[:nI, nI] = 1.0
        S[nI, :nI] = wts
        S[nI, nI] = 0.0
        rhs = np.concatenate([Hx[interior], [self.P]])
        sol = sla.solve(S, rhs, check_finite=False)
        pI, delta = sol[:nI], sol[nI]
        gap_edges = Hx[~interior] - M[~interior] @ pI - delta
        p = np.zeros(xc.size)
        p[interior] = pI
        return gap_edges, ts, p, delta

    def refine(self, edges, maxiter=40):
        """Newton (finite-difference Jacobian, backtracking) on the edges: gap(edges) = 0."""
        e = np.asarray(edges, dtype=float).copy()
        r, *_ = self.solve(e)
        width = np.min(e[1::2] - e[0::2])
        for it in range(maxiter):
            J = np.empty((e.size, e.size))
            d = 1e-7 * width
            for j in range(e.size):
                e2 = e.copy()
                e2[j] += d
                J[:, j] = (self.solve(e2)[0] - r) / d
            step = -np.linalg.solve(J, r)
            lam = 1.0
            while True:
                e_new = e + lam * step
                ok = bool(np.all(np.diff(e_new) > 0))
                if ok:
                    r_new = self.solve(e_new)[0]
                    if np.max(np.abs(r_new)) < np.max(np.abs(r)) or lam < 1e-3:
                        break
                elif lam < 1e-3:
                    raise RuntimeError("edge refinement: the zones collapsed")
                lam *= 0.5
            e, r = e_new, r_new
            if np.max(np.abs(lam * step)) <= 1e-11 * width:
                return e, it + 1
        raise RuntimeError(f"edge refinement did not converge in {maxiter} Newton steps")


# --------------------------------------------------------------------------
# public API
# --------------------------------------------------------------------------
def _fitted_zones(H, N11, N12_muf, P, n, edges0):
    """Edges on n/2, n and 2n panels per zone; the n, 2n pair Richardson-extrapolated
    (the edges converge like n^-2, checked in the tests), the error estimated by the change
    from the (n/2, n) extrapolation (conservative: the extrapolated edges converge like
    n^-3 .. n^-4).  Returns (edges, error estimate, (ts, p, delta, edges) at 2n)."""
    es = []
    e = np.asarray(edges0, dtype=float)
    for nn in (max(n // 2, 4), n, 2 * n):
        f = _Fitted(H, N11, N12_muf, P, nn)
        e, _ = f.refine(e)
        es.append(e)
    _, ts, p, delta = f.solve(e)
    r1 = (4.0 * es[1] - es[0]) / 3.0
    r2 = (4.0 * es[2] - es[1]) / 3.0
    return r2, np.abs(r2 - r1), (ts, p, delta, es[2])


@_one_thread
def solve_bem(H, face, N11, N12_muf, P, m=2000, *, refine=64, active=None, _A=None):
    """Frictional contact of a rigid face H(X) on [face[0], face[1]] by the influence-matrix
    method (see the module docstring for the model, signs and discretisation).

    Parameters
    ----------
    H : callable, vectorised: the face height (H' is the library's punch slope v').
    face : (X_min, X_max), the extent of the face (the discretised domain).
    N11 : float < 0, N12_muf : float (N12 * mu_f, mu_f = -direction * mu).
    P : float > 0, load per unit length.
    m : number of uniform panels of the complementarity (active-set) solve.
    refine : int or None.  With an int n, the zones found on the uniform grid are re-solved
        with continuous edges on n and 2n cosine-graded, piecewise-linear panels per zone
        and the edges Richardson-extrapolated; ``zones`` are then those edges (if the
        refined solution passes its own complementarity check; otherwise the grid's).
    active : optional boolean mask / index array: a warm start for the active set.

    Returns
    -------
    BemResult
    """
    t0 = time.perf_counter()
    if not N11 < 0:
        raise ValueError(f"N11 must be negative in the library's convention, got {N11!r}")
    if not P > 0:
        raise ValueError(f"P must be positive, got {P!r}")
    X0, X1 = map(float, face)
    h = (X1 - X0) / m
    x = X0 + (np.arange(m) + 0.5) * h
    Hm = np.asarray(H(x), dtype=float)
    A = influence_matrix(m, h, N11, N12_muf) if _A is None else _A
    if active is None:
        # start from the panels within 1% of the face's height range of its lowest point
        S0 = np.flatnonzero(Hm <= Hm.min() + 0.01 * (Hm.max() - Hm.min()))
    else:
        active = np.asarray(active)
        S0 = np.flatnonzero(active) if active.dtype == bool else active
        if S0.size == 0:
            S0 = np.array([int(np.argmin(Hm))])
    p, g, delta, S, it = _active_set(A, Hm, h, P, S0)
    gL, gR = edge_exponents(N11, N12_muf)
    zones, zp = [], []
    at_end = False
    runs = _runs(S)
    for k, (i0, i1) in enumerate(runs):
        zp.append((i0, i1))
        # the free region on each side: up to the neighbouring zone (exclusive) or the face end
        left_lim = runs[k - 1][1] if k > 0 else -1
        right_lim = runs[k + 1][0] if k + 1 < len(runs) else m
        if i0 == 0:
            a, at_end = X0, True
        else:
            a = _edge(x, p, g, (i0, i1), -1, gL, h, (left_lim, i0))
        if i1 == m - 1:
            b, at_end = X1, True
        else:
            b = _edge(x, p, g, (i0, i1), +1, gR, h, (i1, right_lim))
        zones.append((float(a), float(b)))
    pscale = max(np.max(p), np.finfo(float).tiny)
    gscale = max(np.max(np.abs(g)), np.finfo(float).tiny)
    comp = max(-min(p.min(), 0.0) / pscale, -min(g.min(), 0.0) / gscale,
               np.max(np.abs(p * g)) / (pscale * gscale))
    res = BemResult(zones=zones, zone_panels=zp, x=x, p=p, gap=g, delta=float(delta), load=P,
                    load_check=abs(h * p.sum() - P) / P, complementarity=float(comp),
                    iterations=it, h=h, at_face_end=at_end, exponents=(gL, gR),
                    active=S, zones_grid=list(zones))
    if refine and not at_end and all(i1 - i0 >= 3 for i0, i1 in zp):
        try:
            e, err, (ts, pf, df, e2) = _fitted_zones(H, N11, N12_muf, P, int(refine),
                                                     np.ravel(zones))
        except (RuntimeError, np.linalg.LinAlgError):
            e = None
        if e is not None:
            res.refined = _check_fitted(H, N11, N12_muf, x, ts, pf, df, e2)
            res.delta_refined = float(df)
            res.fitted = (ts, pf)
            res.edge_error = float(np.max(err))
            if res.refined:
                res.zones = [(float(e[2 * k]), float(e[2 * k + 1])) for k in range(e.size // 2)]
    res.seconds = time.perf_counter() - t0
    return res


def _check_fitted(H, N11, N12_muf, xs, ts, p, delta, edges):
    """The refined solution's own complementarity: p >= 0 at its nodes, gap >= 0 at the
    uniform grid's midpoints outside its zones."""
    nn = ts[0].size
    if np.min(p) < -1e-10 * np.max(np.abs(p)):
        return False
    outside = np.ones(xs.size, bool)
    for k in range(edges.size // 2):
        outside &= ~((xs >= edges[2 * k]) & (xs <= edges[2 * k + 1]))
    xo = xs[outside]
    if xo.size == 0:
        return True
    u = sum(_hat_matrix(xo, t, N11, N12_muf) @ p[k * nn:(k + 1) * nn] for k, t in enumerate(ts))
    g = np.asarray(H(xo), dtype=float) - u - delta
    scale = np.max(np.abs(np.asarray(H(xs), dtype=float) - delta))
    return bool(np.min(g) >= -1e-10 * scale)


@_one_thread
def load_curve_bem(H, face, N11, N12_muf, loads, m=2000, refine=64):
    """solve_bem at each load (in the given order, warm-starting each from the previous);
    returns the list of BemResult (``[r.zones for r in ...]`` gives the zones per load)."""
    X0, X1 = map(float, face)
    A = influence_matrix(m, (X1 - X0) / m, N11, N12_muf)
    out, S = [], None
    for P in loads:
        r = solve_bem(H, face, N11, N12_muf, float(P), m, refine=refine, active=S, _A=A)
        out.append(r)
        S = r.active
    return out


@_one_thread
def merge_load_grid(H, face, N11, N12_muf, P_two, P_one, m=2000, rtol=1e-9):
    """The load at which two zones merge into one, for the uniform-grid discretisation:
    bisection on the number of zones of its exact complementarity solution (no refinement);
    P_two must give 2 zones, P_one 1 zone.  Converges like the grid's pressure near the
    merge point (first order in h, see the tests).  Returns (P_merge, r_two, r_one)."""
    X0, X1 = map(float, face)
    A = influence_matrix(m, (X1 - X0) / m, N11, N12_muf)
    r2 = solve_bem(H, face, N11, N12_muf, P_two, m, refine=None, _A=A)
    r1 = solve_bem(H, face, N11, N12_muf, P_one, m, refine=None, _A=A)
    if r2.n_zones != 2 or r1.n_zones != 1:
        raise ValueError(f"bracket does not bracket a merge: {r2.n_zones} zones at {P_two}, "
                         f"{r1.n_zones} at {P_one}")
    lo, hi = P_two, P_one
    while abs(hi - lo) > rtol * abs(hi):
        mid = 0.5 * (lo + hi)
        r = solve_bem(H, face, N11, N12_muf, mid, m, refine=None, active=r2.active, _A=A)
        if r.n_zones >= 2:
            lo, r2 = mid, r
        else:
            hi, r1 = mid, r
    return 0.5 * (lo + hi), r2, r1


def _interior_min(t, p):
    """Smallest interior local minimum of the nodal p (parabola through it and its
    neighbours): (X, p) there, or None if p has no interior dip."""
    i = np.flatnonzero((p[1:-1] < p[:-2]) & (p[1:-1] <= p[2:])) + 1
    i = i[(i > 1) & (i < p.size - 2)]
    if i.size == 0:
        return None
    k = i[np.argmin(p[i])]
    c = np.polyfit(t[k - 1:k + 2] - t[k], p[k - 1:k + 2], 2)
    if c[0] <= 0:
        return t[k], p[k]
    xv = -c[1] / (2 * c[0])
    return t[k] + xv, c[2] - c[1] ** 2 / (4 * c[0])


def _one_zone_merge(H, N11, N12_muf, P_two, P_one, e_start, nn, xtol):
    """Root P* of the one-zone solution's interior pressure minimum, on nn panels."""
    from scipy.optimize import brentq
    state = {"e": np.asarray(e_start, dtype=float).copy(), "x": np.nan}

    def pmin(P):
        f = _Fitted(H, N11, N12_muf, P, nn)
        e, _ = f.refine(state["e"])
        state["e"] = e
        _, ts, p, _ = f.solve(e)
        mn = _interior_min(ts[0], p)
        if mn is None:
            return np.max(p)
        state["x"] = mn[0]
        return mn[1]

    if pmin(P_one) <= 0:
        raise ValueError(f"the one-zone pressure has no positive minimum at P_one = {P_one}")
    for P in np.linspace(P_one, P_two, 9)[1:]:       # continuation: edges move little
        v = pmin(P)
    if v >= 0:
        raise ValueError(f"the one-zone pressure stays positive at P_two = {P_two}")
    Ps = brentq(pmin, P_two, P_one, xtol=xtol * P_one, rtol=4 * np.finfo(float).eps)
    pmin(Ps)
    return Ps, state["e"].copy(), state["x"]


def _two_zone_merge(H, N11, N12_muf, loads, e_start, n):
    """Extrapolate the squared width of the gap between two zones, w^2 (smooth in P, ~ linear
    near the merge, since w ~ sqrt(P* - P)), to zero by quadratic and cubic least-squares fits
    over ``loads`` (all below the merge).  Returns (P* cubic, P* quadratic, edges per load)."""
    ws, es = [], []
    e = np.asarray(e_start, dtype=float).copy()
    for P in loads:
        e, _, _ = _fitted_zones(H, N11, N12_muf, P, n, e)
        if e.size != 4 or not e[1] < e[2]:
            raise RuntimeError("two-zone continuation lost the gap between the zones")
        ws.append((e[2] - e[1]) ** 2)
        es.append(e.copy())
    loads = np.asarray(loads, dtype=float)
    ws = np.asarray(ws)
    out = []
    for deg in (3, 2):
        c = np.polyfit(loads - loads.max(), ws, deg)
        r = np.roots(c)
        r = r[np.abs(r.imag) < 1e-9].real + loads.max()
        out.append(float(r[np.argmin(np.abs(r - loads.max()))]))
    return out[0], out[1], es


@_one_thread
def merge_load_bem(H, face, N11, N12_muf, P_two, P_one, m=400, n=64, xtol=1e-13,
                   offsets=(0.05, 0.04, 0.03, 0.02, 0.01)):
    """The load P* at which two contact zones merge into one, with continuous edges.

    Two estimates, from both sides of the merge:

    * one zone (P > P*): the load at which the one-zone solution's interior pressure minimum
      reaches zero (below it that solution has p < 0 there and the contact splits), solved on
      n/2, n and 2n cosine-graded piecewise-linear panels and Richardson-extrapolated (n^-2);
      error estimate: the change of the extrapolation from (n/2, n) to (n, 2n).
    * two zones (P < P*): the squared gap width between the zones, w^2, at the loads
      P1* (1 - offsets) (edges from ``_fitted_zones(n)``, accurate to ~1e-7 relative at n = 64),
      extrapolated to w^2 = 0 by a cubic fit; error estimate: max of |cubic - quadratic| and
      the change from the same extrapolation with n/2.  This one is the more accurate
      (w -> 0 like sqrt(P* - P), so w^2 is smooth through the merge).

    P_two must give two zones on the grid of m panels (it supplies the starting edges), P_one
    one zone.  Returns dict(merge_load (the two-zone estimate), error, one_zone, one_zone_error,
    x_merge (where the one-zone pressure first vanishes), zone (the one zone at P*),
    zones_below (the two zones at the loads of the fit), loads_below, per_n).
    """
    r1 = solve_bem(H, face, N11, N12_muf, P_one, m, refine=None)
    if r1.n_zones != 1:
        raise ValueError(f"P_one = {P_one} gives {r1.n_zones} zones on the grid, not 1")
    r2 = solve_bem(H, face, N11, N12_muf, P_two, m, refine=None)
    if r2.n_zones != 2:
        raise ValueError(f"P_two = {P_two} gives {r2.n_zones} zones on the grid, not 2")
    per_n = {}
    e = np.ravel(r1.zones)
    for nn in (max(n // 2, 4), n, 2 * n):
        Ps, e, xm = _one_zone_merge(H, N11, N12_muf, P_two, P_one, e, nn, xtol)
        per_n[nn] = Ps
    P0, P1, P2 = (per_n[k] for k in sorted(per_n))
    R1, R2 = (4 * P1 - P0) / 3, (4 * P2 - P1) / 3
    one, one_err = R2, abs(R2 - R1)
    # two-zone side: continuation from P_two up to the fit loads
    loads = one * (1.0 - np.asarray(offsets, dtype=float))
    if not P_two < loads.min():
        raise ValueError(f"P_two = {P_two} must lie below the fit loads {loads.min():.6g}..")
    e2 = np.ravel(r2.zones)
    for P in np.linspace(P_two, loads.min(), 6)[1:-1]:
        e2, _, _ = _fitted_zones(H, N11, N12_muf, P, max(n // 2, 8), e2)
    c_half, q_half, _ = _two_zone_merge(H, N11, N12_muf, loads, e2, max(n // 2, 8))
    c_full, q_full, es = _two_zone_merge(H, N11, N12_muf, loads, e2, n)
    err = max(abs(c_full - q_full), abs(c_full - c_half))
    zone, _, _ = _fitted_zones(H, N11, N12_muf, c_full, n, e)
    return dict(merge_load=c_full, error=err, one_zone=one, one_zone_error=one_err,
                x_merge=float(xm), zone=tuple(float(v) for v in zone),
                zones_below=[[(float(z[0]), float(z[1])), (float(z[2]), float(z[3]))] for z in es],
                loads_below=[float(v) for v in loads], per_n=per_n)


# --------------------------------------------------------------------------
# the W-shaped face used as the multi-zone reference
# --------------------------------------------------------------------------
W_AMPLITUDE = 0.05
W_FACE = (-2.0, 2.0)


def w_face(X):
    """H(X) = 0.05 (X^2 - 1)^2 on [-2, 2]: two valleys at X = +-1, a hump of 0.05 at X = 0."""
    X = np.asarray(X, dtype=float)
    return W_AMPLITUDE * (X * X - 1.0) ** 2


def w_face_closed_form(N11, P, amplitude=W_AMPLITUDE):
    """Frictionless zones of H = A (X^2 - 1)^2, H' = 4A (X^3 - X), N11 < 0.

    Two zones +-[c, b]: with R(z) = sqrt((z^2 - b^2)(z^2 - c^2)) ~ z^2 at infinity (cut on
    the zones; R+ = +i r on (c, b), -i r on (-b, -c), r = sqrt((b^2 - x^2)(x^2 - c^2))),
    F = R(z) z e0 - PolyPart gives Hc[|x| r e0] = -e0 PolyPart[z R(z)]
    = -e0 (x^3 - (b^2 + c^2) x / 2); matching N11 Hc[p] = H' gives e0 = 4A/|N11| and
    b^2 + c^2 = 2 (the one solvability condition left by the symmetry), and the load
    P = 2 e0 int_c^b x r dx = e0 (pi/8) (b^2 - c^2)^2, i.e. (b^2 - c^2)^2 = 2 P |N11| / (pi A),
    for P |N11| < 2 pi A.  One zone [-a, a] (``PolynomialFaceOneZone`` with g = 1/2):
    p = (4A/|N11|) sqrt(a^2 - X^2) (X^2 + a^2/2 - 1), 2 pi A a^2 (3 a^2/4 - 1) = P |N11|.
    They meet at P* |N11| = 2 pi A (c = 0, a = b = sqrt(2), p = (4A/|N11|) X^2 sqrt(2 - X^2)).
    ``tests/reference/test_bem_reference.py`` checks both by direct PV quadrature.  Returns the zones.
    """
    s = P * abs(N11) / (amplitude * math.pi)
    if s < 2.0:
        d = math.sqrt(2.0 * s)
        b, c = math.sqrt(1.0 + 0.5 * d), math.sqrt(1.0 - 0.5 * d)
        return [(-b, -c), (c, b)]
    y = (1.0 + math.sqrt(1.0 + 1.5 * s)) / 1.5
    return [(-math.sqrt(y), math.sqrt(y))]


# --------------------------------------------------------------------------
# closed forms for a polynomial face, one zone, with friction (a third, analytic route)
# --------------------------------------------------------------------------
def _binom_series(c, x, K):
    """Coefficients of (1 + x t)^c in t, orders 0..K."""
    out = np.empty(K + 1)
    out[0] = 1.0
    for k in range(1, K + 1):
        out[k] = out[k - 1] * (c - k + 1) / k * x
    return out


def _z_series(gL, gR, K):
    """Z(z)/u = (1 + gR t)^gL (1 - gL t)^gR and u/Z(z), t = L/u, as series in t (orders 0..K);
    Z = (z - a)^gL (z - b)^gR, u = z - m, m = gL a + gR b, L = b - a."""
    s = np.convolve(_binom_series(gL, gR, K), _binom_series(gR, -gL, K))[:K + 1]
    r = np.zeros(K + 1)                       # reciprocal series
    r[0] = 1.0
    for k in range(1, K + 1):
        r[k] = -np.dot(s[1:k + 1], r[k - 1::-1][:k])
    return s, r


class PolynomialFaceOneZone:
    """Exact one-zone solution for a face with polynomial slope H'(X) = sum_j c_j X^j.

    Derivation (tests/reference/test_bem_reference.py has the numerical checks).  With
    Phi(z) = (1/(2 pi i)) int p/(t - z) dt, p = Phi+ - Phi-, Hc[p] = i (Phi+ + Phi-), the
    equation N12 mu_f p + N11 Hc[p] = H' reads Phi+ = G Phi- + H'/(N12 mu_f + i N11),
    G = (N12 mu_f - i N11)/(N12 mu_f + i N11).  The canonical function bounded at both ends
    is Z(z) = (z - a)^gL (z - b)^gR (gL + gR = 1, the exponents of ``edge_exponents``), and
    Phi = (H' - Z Q)/(2 i N11) with the polynomial Q = PolyPart[H'/Z] decays at infinity iff
    the u^-1 coefficient of H'/Z vanishes (the solvability condition).  Then
    p(X) = sin(pi gR) (X - a)^gL (b - X)^gR Q(X) / |N11|, and the contour integral of Z Q
    gives the load P |N11| = -pi [u^-1 coefficient of Z Q].  Unknowns: the centre
    m = gL a + gR b and the length L = b - a (solvability, load).
    """

    def __init__(self, slope_coeffs, N11, N12_muf):
        self.c = np.asarray(slope_coeffs, dtype=float)      # ascending powers of X
        self.N11, self.N12_muf = N11, N12_muf
        self.gL, self.gR = edge_exponents(N11, N12_muf)
        self.K = self.c.size + 3
        self.s, self.r = _z_series(self.gL, self.gR, self.K)

    def _shifted(self, m):
        """Ascending coefficients of H'(u + m) in u."""
        return np.array([sum(self.c[j] * math.comb(j, i) * m ** (j - i) for j in range(i, self.c.size))
                      for i in range(self.c.size)])

    def parts(self, m, L):
        """(Q coefficients in u, solvability residual, P |N11|)."""
        F = self._shifted(m)
        d = F.size - 1
        Q = np.zeros(max(d, 1))
        for j in range(F.size):
            for k in range(0, j):                           # u^(j-1-k), j-1-k >= 0
                Q[j - 1 - k] += F[j] * self.r[k] * L ** k
        solv = sum(F[j] * self.r[j] * L ** j for j in range(F.size))
        cm1 = sum(Q[i] * self.s[i + 2] * L ** (i + 2) for i in range(Q.size))
        return Q, solv, -math.pi * cm1

    def solve(self, P, guess):
        """(a, b) for the load P, from a guess (a0, b0)."""
        from scipy.optimize import fsolve
        a0, b0 = guess
        v0 = [self.gL * a0 + self.gR * b0, b0 - a0]
        target = P * abs(self.N11)

        def eqs(v):
            _, solv, PN = self.parts(*v)
            return [solv, (PN - target) / target]
        m, L = fsolve(eqs, v0, xtol=1e-13)
        self.m, self.L = m, L
        return m - self.gR * L, m + self.gL * L

    def pressure(self, X, m, L):
        X = np.asarray(X, dtype=float)
        Q, _, _ = self.parts(m, L)
        a, b = m - self.gR * L, m + self.gL * L
        w = np.where((X > a) & (X < b),
                     np.abs(X - a) ** self.gL * np.abs(b - X) ** self.gR, 0.0)
        return math.sin(math.pi * self.gR) * w * np.polynomial.polynomial.polyval(X - m, Q) / abs(self.N11)

    def merge(self, guess):
        """Cubic slopes (quadratic Q): the load at which Q gets a double root, i.e. the
        one-zone pressure first touches zero inside.  Returns (P*, (a, b), X_merge)."""
        from scipy.optimize import fsolve
        if self.c.size != 4:
            raise ValueError("merge(): cubic slopes only")
        a0, b0 = guess

        def eqs(v):
            Q, solv, _ = self.parts(*v)
            return [solv, Q[1] ** 2 - 4 * Q[0] * Q[2]]
        m, L = fsolve(eqs, [self.gL * a0 + self.gR * b0, b0 - a0], xtol=1e-13)
        Q, _, PN = self.parts(m, L)
        return PN / abs(self.N11), (m - self.gR * L, m + self.gL * L), m - Q[1] / (2 * Q[2])


@_one_thread
def w_face_reference(N11, N12_muf=0.0, loads=(), m=400, n=64, bracket=(0.25, 0.40)):
    """Zones of the W face at the given loads and its merge load, for other code to call.

    Frictionless (N12_muf = 0) the answer depends on N11 only through P |N11|: the merge
    happens at P* |N11| = 2 pi A = pi/10 exactly (``w_face_closed_form``).  ``bracket`` is
    (P_two, P_one) in units of 1/|N11| (two zones on the grid at the first, one at the second).
    Returns dict(zones=[zones per load], edge_error=[per load], merge_load, merge_error,
    merge_one_zone, x_merge)."""
    s = abs(N11)
    res = load_curve_bem(w_face, W_FACE, N11, N12_muf, list(loads), m, refine=n) if len(loads) else []
    mg = merge_load_bem(w_face, W_FACE, N11, N12_muf, bracket[0] / s, bracket[1] / s, m=m, n=n)
    return dict(zones=[r.zones for r in res],
                edge_error=[r.edge_error for r in res],
                merge_load=mg["merge_load"], merge_error=mg["error"],
                merge_one_zone=mg["one_zone"], x_merge=mg["x_merge"])


# --------------------------------------------------------------------------
# convergence study (python tests/reference/bem_reference.py): the numbers quoted in the tests
# --------------------------------------------------------------------------
def convergence_report(ms=(250, 500, 1000, 2000), ns=(16, 32, 64, 128)):  # pragma: no cover
    import contact                                     # only for the constants and the oracle
    iso_N11 = contact.surface_constants(contact.Isotropic(1.0, 0.25), 0.0).N11
    R, a = 1.0, 0.5
    P = math.pi * a * a / (2 * abs(iso_N11) * R)
    _, pcf = cylinder_closed_form(iso_N11, R, P)
    H = lambda X: np.asarray(X) ** 2 / (2 * R)         # noqa: E731
    print(f"cylinder, static isotropic (N11 = {iso_N11}), a = {a}, P = {P:.6g}, face [-1, 1]")
    print("   m      h     left/h   right/h  p err (|X|<0.4a)  delta            s")
    for m in ms:
        r = solve_bem(H, (-1, 1), iso_N11, 0.0, P, m, refine=None)
        (za, zb), = r.zones
        inner = np.abs(r.x) < 0.8 * a
        ep = np.max(np.abs(r.p - pcf(r.x))[inner]) / pcf(0)
        print(f"{m:5d} {r.h:.1e} {(za + a) / r.h:+.4f} {(zb - a) / r.h:+.4f}  {ep:.3e}  "
              f"{r.delta:.12f}  {r.seconds:.2f}")
    print("  continuous edges, n panels:  edge error")
    for n in ns:
        f = _Fitted(H, iso_N11, 0.0, P, n)
        with _OneBlasThread():
            e, _ = f.refine([-0.49, 0.52])
        print(f"  n = {n:4d}: {np.max(np.abs(e - [-a, a])):.3e}")
    for n in ns[:-1]:
        r = solve_bem(H, (-1, 1), iso_N11, 0.0, P, 250, refine=n)
        print(f"  solve_bem refine={n:3d} (n/2, n, 2n; extrapolated): "
              f"{np.max(np.abs(np.ravel(r.zones) - [-a, a])):.3e} (estimate {r.edge_error:.1e})")

    mat = contact.zhou2014()
    k = contact.surface_constants(mat, 0.6)
    for direction in (-1, 1):
        lib = contact.solve(mat, contact.CylindricalPunch(radius=10.0), load=0.05, speed=0.6,
                            friction=0.3, direction=direction)
        print(f"cylinder R = 10, P = 0.05, zhou2014, c = 0.6, mu = 0.3, direction {direction}: "
              f"library ends {lib.ends}")
        for m in ms:
            r = solve_bem(_quad_face(10.0), (-0.5, 0.5), k.N11, k.N12 * 0.3 * -direction, 0.05, m,
                          refine=32)
            dg = (np.ravel(r.zones_grid) - lib.ends) / r.h
            dr = np.ravel(r.zones) - lib.ends
            print(f"  m = {m:5d}: grid (ends - lib)/h = {dg[0]:+.4f} {dg[1]:+.4f}; "
                  f"refined {dr[0]:+.2e} {dr[1]:+.2e}; {r.seconds:.2f} s")

    print("W face H = 0.05 (X^2 - 1)^2, N11 = -1, frictionless (zones scale with P |N11|)")
    for P in (0.05, 0.1, 0.2, 0.3, 0.31, 0.32, 0.4, 0.5, 1.0):
        ex = w_face_closed_form(-1.0, P)
        r = solve_bem(w_face, W_FACE, -1.0, 0.0, P, 2000, refine=64)
        eg = np.max(np.abs(np.ravel(r.zones_grid) - np.ravel(ex))) if r.n_zones == len(ex) else np.nan
        er = np.max(np.abs(np.ravel(r.zones) - np.ravel(ex))) if r.n_zones == len(ex) else np.nan
        print(f"  P = {P:5.2f}: exact {[tuple(round(v, 9) for v in z) for z in ex]}; "
              f"grid m=2000 err {eg:.1e}, refined err {er:.1e} (est. {r.edge_error:.1e})")
    print("  merge load, grid bisection (exact pi/10 = 0.314159265358979)")
    for m in ms:
        t0 = time.perf_counter()
        Pm, _, _ = merge_load_grid(w_face, W_FACE, -1.0, 0.0, 0.25, 0.4, m, rtol=1e-9)
        print(f"    m = {m:5d}: {Pm:.10f}  rel. err {(Pm - math.pi / 10) / (math.pi / 10):+.2e}  "
              f"{time.perf_counter() - t0:.1f} s")
    print("  merge load, continuous edges")
    for n in ns[:-1]:
        t0 = time.perf_counter()
        d = merge_load_bem(w_face, W_FACE, -1.0, 0.0, 0.25, 0.4, 400, n)
        print(f"    n = {n:3d}: two-zone {d['merge_load']:.10f} (err {d['merge_load'] - math.pi / 10:+.1e}, "
              f"est {d['error']:.1e}); one-zone {d['one_zone']:.10f} (err "
              f"{d['one_zone'] - math.pi / 10:+.1e}, est {d['one_zone_error']:.1e}); "
              f"{time.perf_counter() - t0:.1f} s")
    for direction in (-1, 1):
        muf = k.N12 * 0.3 * -direction
        pf = PolynomialFaceOneZone([0, -0.2, 0, 0.2], k.N11, muf)
        Ps, zs, xs = pf.merge((-1.4, 1.4))
        d = merge_load_bem(w_face, W_FACE, k.N11, muf, 0.25 / abs(k.N11), 0.4 / abs(k.N11), 400, 64)
        print(f"  zhou2014 c = 0.6 mu = 0.3 direction {direction}: closed-form P* = {Ps:.10f} "
              f"(P*|N11| = {Ps * abs(k.N11):.10f}), zone {zs}, X_merge {xs:+.6f}; "
              f"BEM {d['merge_load']:.10f} (est {d['error']:.1e}), zone {d['zone']}")
        for P in (0.1 / abs(k.N11), 0.2 / abs(k.N11), 0.3 / abs(k.N11), 2.5):
            r = solve_bem(w_face, W_FACE, k.N11, muf, P, 2000, refine=64)
            print(f"    P = {P:.5f}: zones {[tuple(round(v, 7) for v in z) for z in r.zones]} "
                  f"(est. {r.edge_error:.1e}, grid {[tuple(round(v, 4) for v in z) for z in r.zones_grid]})")


def _quad_face(R):
    return lambda X: np.asarray(X, dtype=float) ** 2 / (2.0 * R)


if __name__ == "__main__":                             # pragma: no cover
    import warnings as _w
    _w.simplefilter("ignore", RuntimeWarning)
    convergence_report()
