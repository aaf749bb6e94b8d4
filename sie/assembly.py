"""Block assembly of the collocation system on several intervals, and its solution.

Unknowns c = (c^1, ..., c^J), c^j the Jacobi coefficients on interval j.  Row block i holds
the projections of the equation on L_i onto P_m^{(-alpha_i,-beta_i)}, m < n_i - kappa_i:

    diagonal block   lambda_i at (m, m + kappa_i)          (the exact dominant operator)
    block (i, j)     b_i <F^j_k(v_j(s)), P_m>_i / h_m    (i != j: the Cauchy integral over L_j
                     seen from L_i, F^j_k the exact transform of w_j P_k outside [-1, 1],
                     :mod:`sie.cauchy`, so that close intervals keep full accuracy)
                   + <h_j int k_i(s, m_j + h_j u) w_j P_k du, P_m>_i / h_m     (kernel)

(a_i, b_i and k_i: the coefficients and kernel of the equation on L_i, the row block).

Side conditions as rows: kappa_i = 1 adds h_i mu_0 c^i_0 = total_i (scaled by |lambda_i|);
kappa_i = -1 removes the row m = 0, whose residual is the solvability condition of L_i
(Muskhelishvili 1953, sec. 110), reported as the consistency.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .cauchy import cauchy_basis
from .errors import InvalidOrderError, KernelSingularityError, call_checked
from .jacobi import jacobi_vandermonde
from .quadrature import WeightedRule

__all__ = ["Assembled", "assemble_and_solve", "coupling_images", "kernel_images",
           "operator_images", "probe_kernel", "N_MAX_DENSE"]

_KERNEL_EXTRA = 16          # t-nodes beyond n for int k(s,t) psi(t) dt
N_MAX_DENSE = 6000          # unknowns of a dense system (several intervals or a kernel)


def coupling_images(x, uj, b):
    """b (1/pi) int_{L_j} w_j P_k / (t - x) dt at real x off L_j: matrix (len(x), n_j)
    (b: the coefficient of the equation at x)."""
    ends = uj.interval.local_ends(np.asarray(x, dtype=float))
    v = 0.5 * (ends[0] + ends[1])             # the local coordinate (x - m)/h
    return b * cauchy_basis(uj.n, uj.weight, v, ends=ends).real


def kernel_images(x, uj, kernel):
    """h_j int k(x, m_j + h_j u) w_j(u) P_k(u) du at real x: matrix (len(x), n_j).

    Inner integral by the (end-mass corrected) Gauss rule of w_j with n_j + 16 nodes."""
    e = uj.exp
    trule = WeightedRule.build(uj.n + _KERNEL_EXTRA, e.alpha, e.beta, e.alpha_p1, e.beta_p1)
    u = np.concatenate([trule.x, [float(trule.end)]]) if trule.end else trule.x
    S, T = np.meshgrid(np.asarray(x, dtype=float), uj.interval.real(u), indexing="ij")
    kst = call_checked(kernel, "kernel", (S, T), S.shape)
    nt = trule.x.size
    G = (kst[:, :nt] * trule.omega) @ jacobi_vandermonde(uj.n, e.alpha, e.beta, trule.x)
    if trule.end:
        G += np.outer(kst[:, nt], trule.corr * trule.end_values(uj.n))
    return uj.interval.h * G


_PROBE = (1e-3, 1e-6)


def grows_toward_end(k):
    """Per row of abs(k) sampled at the distances :data:`_PROBE` from a pair of ends: whether
    it grows by more than 100x from the first to the second (a fixed singularity there; a
    kernel that vanishes at the first point, to 1e-12 of the largest, is judged from 1e-300)."""
    return k[:, 1] > 100.0 * np.maximum(k[:, 0], 1e-300 + 1e-12 * k.max())


def probe_kernel(unknowns, explicit=()):
    """Refuse a kernel that grows without bound toward a pair of ends (s, t) (a fixed
    singularity: the generalised Cauchy kernels of edge cracks and of cracks ending at an
    interface; Erdogan, Gupta & Cook 1973; Kaya & Erdogan 1987).  It changes the exponent at
    that end, so the Jacobi basis of the end choices cannot represent the solution and the
    collocation converges to a wrong answer.  Sampled at distances 1e-3 and 1e-6 (relative
    to the half-widths) inside every pair of ends, for each row's kernel.  ``explicit``: the
    (interval, end) pairs (end -1 or 1) whose exponent the caller gave (:mod:`sie.fixed_ends`),
    where the kernel may be singular: a corner of two such ends is not probed."""
    for kernel in {id(u.kernel): u.kernel for u in unknowns if u.kernel is not None}.values():
        rows = [u for u in unknowns if u.kernel is kernel]
        _probe(kernel, rows, unknowns, frozenset(explicit))


def _probe(kernel, rows, unknowns, explicit=frozenset()):
    pts_s, pts_t, tags = [], [], []
    for ui in rows:
        for uj in unknowns:
            for es in (-1.0, 1.0):
                for et in (-1.0, 1.0):
                    if (ui.interval, es) in explicit and (uj.interval, et) in explicit:
                        continue
                    for d in _PROBE:
                        pts_s.append(ui.interval.real(es * (1.0 - d)))
                        pts_t.append(uj.interval.real(et * (1.0 - 1.5 * d)))
                    tags.append((ui.interval, es, uj.interval, et))
    if not tags:
        return
    S, T = np.array(pts_s), np.array(pts_t)
    try:
        k = np.abs(call_checked(kernel, "kernel", (S, T), S.shape)).reshape(-1, 2)
    except Exception as exc:        # non-finite or raising next to an end: singular there
        raise KernelSingularityError(
            f"the kernel cannot be evaluated next to the interval ends ({exc}); the solver "
            "needs k(s, t) bounded on L x L") from exc
    grow = grows_toward_end(k)
    if np.any(grow):
        i = int(np.flatnonzero(grow)[0])
        ivs, es, ivt, et = tags[i]
        s_end = ivs.d if es > 0 else ivs.c
        t_end = ivt.d if et > 0 else ivt.c
        side = "right" if es > 0 else "left"
        raise KernelSingularityError(
            f"the kernel grows without bound toward (s, t) = ({s_end!r}, {t_end!r}) "
            f"(|k| = {k[i, 0]:.3g} at distance 1e-3, {k[i, 1]:.3g} at 1e-6): a fixed "
            "singularity at an end, as in the generalised Cauchy kernel of an edge crack, "
            "sets the end exponent itself, not the end choice \"bounded\" / \"singular\"; "
            f"give that end's exponent, {side}=<float> in (-1, 1) (the root of the kernel's "
            "characteristic function, sie.end_exponent; for the edge crack's kernel at the "
            "free surface it is 0), or map the problem so that the kernel is bounded")


@dataclass(frozen=True)
class Assembled:
    """Coefficients per interval, the solvability residuals, the projections of
    g = f - (coupling + kernel) psi per interval, the dense matrix (None when diagonal), and
    (coupling + kernel) psi at the check points of each interval (None when diagonal)."""
    coefficients: list
    consistency: list
    g_hat: list
    matrix: np.ndarray | None
    at_checks: list | None


def operator_images(x, ui, unknowns):
    """The coupling (from the other intervals) and kernel terms at real points x of interval
    ``ui``, one matrix (len(x), n_j) per unknown j: applied to c^j and summed, they give
    (b_i/pi) int_{L minus L_i} psi/(t - x) dt + int_L k_i(x, t) psi(t) dt (the coefficient
    and kernel of the equation on L_i)."""
    out = []
    for uj in unknowns:
        img = coupling_images(x, uj, ui.b) if uj is not ui else np.zeros((x.size, uj.n))
        if ui.kernel is not None:
            img += kernel_images(x, uj, ui.kernel)
        out.append(img)
    return out


def _offdiagonal(unknowns, checks):
    """The projected coupling + kernel operator seen from each interval i: a row block of
    shape (m_eq_i, N) over all N unknowns, and the same operator (not projected) at the local
    points ``checks`` of interval i, shape (len(checks), N); one evaluation per interval."""
    blocks, at_checks = [], []
    for ui in unknowns:
        u = ui.sample_points()
        x = ui.interval.real(np.concatenate([u, checks]))
        img = np.hstack(operator_images(x, ui, unknowns))
        blocks.append(ui.project(img[:u.size]))
        at_checks.append(img[u.size:])
    return blocks, at_checks


def assemble_and_solve(unknowns, fhat, checks):
    """Solve the block system (see module docstring)."""
    J = len(unknowns)
    if J == 1 and unknowns[0].kernel is None:
        u = unknowns[0]
        c = u.dominant_rhs_solve(fhat[0], u.total)
        cons = float(fhat[0][0]) if u.kappa == -1 else None
        return Assembled([c], [cons], [fhat[0]], None, None)
    size = sum(u.n for u in unknowns)
    if size > N_MAX_DENSE:
        raise InvalidOrderError(
            f"n = {[u.n for u in unknowns]} gives {size} unknowns in one dense system (several "
            f"intervals or a kernel); at most {N_MAX_DENSE} are allowed (memory 8 N^2 bytes, "
            "time ~N^3)")
    blocks, at_checks = _offdiagonal(unknowns, checks)
    A = np.empty((size, size))
    rhs = np.empty(size)
    flat = A.reshape(-1)
    r0 = col = 0
    for ui, blk, fh in zip(unknowns, blocks, fhat):
        # rows of interval i: the side condition (kappa = 1), then the projected equations
        # m = drop .. m_eq - 1 (kappa = -1 drops m = 0: the solvability condition)
        drop = 1 if ui.kappa == -1 else 0
        if ui.kappa == 1:
            A[r0] = 0.0
            A[r0, col] = abs(ui.lam)
            rhs[r0] = abs(ui.lam) * ui.total / (ui.interval.h * ui.mu0)
            r0 += 1
        rows = ui.m_eq - drop
        A[r0:r0 + rows] = blk[drop:]
        rhs[r0:r0 + rows] = fh[drop:]
        # lambda at (m, m + kappa) for 0 <= m + kappa < n: a diagonal of the row block
        m0 = max(drop, -ui.kappa)
        count = min(ui.m_eq, ui.n - ui.kappa) - m0
        start = (r0 + m0 - drop) * size + col + m0 + ui.kappa
        flat[start:start + count * (size + 1):size + 1] += ui.lam
        r0 += rows
        col += ui.n
    c_all = np.linalg.solve(A, rhs)
    coeffs, cons, g_hat, checked = [], [], [], []
    col = 0
    for ui, blk, chk, fh in zip(unknowns, blocks, at_checks, fhat):
        coeffs.append(c_all[col:col + ui.n])
        col += ui.n
        g = fh - blk @ c_all
        g_hat.append(g)
        cons.append(float(g[0]) if ui.kappa == -1 else None)
        checked.append(chk @ c_all)
    return Assembled(coeffs, cons, g_hat, A, checked)
