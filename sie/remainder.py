"""Pointwise correction for right-hand sides with breaks (kinks, jumps in a derivative).

The collocation solution phi_N = sum_{k<n} c_k P_k^{(alpha,beta)} has exact
coefficients when the projections are computed by the composite rule, but its
truncation error decays only algebraically when f has a kink.  What is missing
is the inverse of the dominant operator applied to the projection remainder

    r = g - sum_{m<M} g_m P_m^{(-alpha,-beta)},     g = f - int k psi_N,

which the Muskhelishvili inversion formula gives pointwise (derived from
sie-math.md item 1 applied to the weight 1/w, checked in tests):

    R[r] = w delta_phi,
    delta_phi(x) = -b/(a^2+b^2) [ I(x) + 2^kappa P_kappa^{(alpha,beta)}(x) r(x)/sin(pi alpha) ] + C,
    I(x) = (1/pi) int (1-t)^{-alpha}(1+t)^{-beta} (r(t) - r(x))/(t - x) dt,

with P_{-1} = 0 and C fixing int w delta_phi = 0 when kappa = 1 (the total is
carried by c_0).  I(x) is a regular integral whose integrand is smooth on each
piece between breaks, so the composite Gauss-Jacobi rule converges spectrally.
Two interleaved rules (q and q+1 nodes per piece) are kept, and each x uses the
one whose nearest node is farther away, so r(t) - r(x) never cancels badly.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .gaussjacobi import gauss_jacobi
from .jacobi import jacobi_series
from .special import jacobi_moment_shifted

__all__ = ["InversionRemainder"]


@dataclass(eq=False)
class InversionRemainder:
    """delta_phi, its integral and Cauchy transform (see module docstring)."""
    sol: object
    f: object
    kernel: object
    rules: list                 # [(s, ws, r_s)] for weight 1/w
    g_coef: np.ndarray          # projections g_m of g
    t_k: np.ndarray | None      # kernel quadrature (weight w)
    w_k: np.ndarray | None
    phi_k: np.ndarray | None
    const: float = 0.0
    w_rule: tuple = ()

    @classmethod
    def build(cls, sol, f, kernel, breaks, s, ws, fs, fhat, kc, lam):
        from .solver import _composite_rule, _call_checked
        alpha, beta = sol.alpha, sol.beta
        g_coef = fhat - (kc if kc is not None else 0.0)
        t_k = w_k = phi_k = None
        if kernel is not None:
            t_k, w_k = gauss_jacobi(sol.n + 16, alpha, beta)
            phi_k = jacobi_series(sol.coefficients, alpha, beta, t_k)
        self = cls(sol, f, kernel, [], g_coef, t_k, w_k, phi_k)
        q = s.size // (breaks.size + 1)
        s2, ws2 = _composite_rule(q + 1, -alpha, -beta, breaks)
        f2 = _call_checked(f, "f", (s2,), s2.shape)
        for nodes, weights, fvals in ((s, ws, fs), (s2, ws2, f2)):
            self.rules.append((nodes, weights, self._r(nodes, fvals)))
        # rule for integrals against w (piecewise smooth delta_phi)
        self.w_rule = _composite_rule(q, alpha, beta, breaks)
        if sol.kappa == 1:
            tw, ww = self.w_rule
            self.const = -float(ww @ self._phi_no_const(tw)) / jacobi_moment_shifted(
                sol._exp.alpha_p1, sol._exp.beta_p1)
        return self

    # g - Pi g at points x, given f(x)
    def _r(self, x, fx):
        sol = self.sol
        out = fx - jacobi_series(self.g_coef, -sol.alpha, -sol.beta, x)
        if self.kernel is not None:
            out = out - self._kpsi(x)
        return out

    def _kpsi(self, x):
        from .solver import _call_checked
        X, T = np.meshgrid(x, self.t_k, indexing="ij")
        k = _call_checked(self.kernel, "kernel", (X, T), X.shape)
        return k @ (self.w_k * self.phi_k)

    def _phi_no_const(self, x):
        from .solver import _call_checked
        sol = self.sol
        x = np.asarray(x, dtype=float)
        fx = _call_checked(self.f, "f", (x,), x.shape)
        rx = self._r(x, fx)
        # per point, the rule whose nearest node is farther from x
        dist = [np.min(np.abs(nodes[None, :] - x[:, None]), axis=1) for nodes, _, _ in self.rules]
        choice = (dist[1] > dist[0]).astype(int)
        integral = np.empty(x.shape)
        for idx, (nodes, weights, r_nodes) in enumerate(self.rules):
            sel = choice == idx
            if np.any(sel):
                xs = x[sel]
                diff = (r_nodes[None, :] - rx[sel][:, None]) / (nodes[None, :] - xs[:, None])
                integral[sel] = diff @ weights / math.pi
        k = sol.kappa
        if k == 1:
            pk = (sol.alpha + 1.0) + 0.5 * (sol.alpha + sol.beta + 2.0) * (x - 1.0)
        elif k == 0:
            pk = np.ones(x.shape)
        else:
            pk = np.zeros(x.shape)
        a, b = sol.a, sol.b
        return -b / (a * a + b * b) * (integral + 2.0 ** k * pk * rx / sol._exp.sin)

    def phi(self, x):
        return self._phi_no_const(x) + self.const

    def integral(self):
        if self.sol.kappa == 1:
            return 0.0
        tw, ww = self.w_rule
        return float(ww @ self.phi(tw))

    def cauchy_inside(self, x, psi_full, _series_value):
        """H[psi](x) = (g(x) - a psi(x)) / b, the equation itself, with the accurate psi."""
        from .solver import _call_checked
        sol = self.sol
        gx = _call_checked(self.f, "f", (x,), x.shape)
        if self.kernel is not None:
            gx = gx - self._kpsi(x)
        return (gx - sol.a * psi_full) / sol.b

    def cauchy_outside(self, x):
        """(1/pi) int w delta_phi/(t - x) dt by the composite rule (x off [-1, 1])."""
        tw, ww = self.w_rule
        d = ww * self.phi(tw)
        return (d[None, :] / (tw[None, :] - x[:, None])).sum(axis=1) / math.pi
