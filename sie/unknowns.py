"""The unknown on one interval: psi = w phi, phi = sum_{k<n} c_k P_k^{(alpha,beta)}.

On interval L_j = [c_j, d_j] (local u = (s - m_j)/h_j) the dominant operator maps the basis
exactly (Erdogan, Gupta & Cook 1973; Zhou et al. 2014, eq. 4.19):

    a w P_k + b H[w P_k] = lambda P_{k-kappa}^{(-alpha,-beta)},
    lambda = -2^{-kappa} b / sin(pi alpha),      P_{-1} = 0,

so the equation on L_j is projected onto P_m^{(-alpha,-beta)}, m < n - kappa, with the
Gauss-Jacobi rule of the weight (1-u)^{-alpha}(1+u)^{-beta} at n - kappa nodes: collocation
at the roots of P_{n-kappa}^{(-alpha,-beta)} (Krenk 1975).  An unknown carries its interval,
exponents, basis size and that projection rule.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np

from .cauchy import Weight
from .errors import call_checked
from .exponents import Exponents
from .intervals import Interval
from .jacobi import jacobi_norms, jacobi_project, jacobi_vandermonde
from .quadrature import WeightedRule, composite_weighted_rule
from .special import jacobi_moment_shifted

__all__ = ["IntervalUnknown", "dominant_lambda"]

_EXTRA_PER_PIECE = 24       # extra nodes per piece of the composite rule (breaks)
_PROJECTOR_CACHE_MAX = 1 << 16   # entries of a projection matrix kept between solves (512 KiB)


def dominant_lambda(e: Exponents, b: float) -> float:
    """lambda = -2^{-kappa} b / sin(pi alpha)."""
    return -(2.0 ** (-e.kappa)) * b / e.sin


@dataclass(frozen=True, eq=False)
class IntervalUnknown:
    """Interval, exponents, basis size and projection rule of one block of unknowns, with
    the coefficients and kernel of the equation collocated on its interval.

    Attributes
    ----------
    interval : Interval
    a, b : float
        The coefficients of the equation on the interval.
    kernel : callable or None
        Its kernel row k(s, t), s on the interval.
    exp : Exponents
    n : int
        Basis size (coefficients c_0..c_{n-1}).
    breaks : ndarray
        Breaks in the local coordinate.
    total : float or None
        int over the interval of psi (real coordinate), for kappa = 1.
    lam : float
        The dominant operator's factor lambda.
    rule : WeightedRule or None
        Gauss-Jacobi rule of (1-u)^{-alpha}(1+u)^{-beta} (None with breaks: composite rule).
    split : WeightedRule or None
        With breaks, the composite rule when it splits off an end's mass
        (:func:`sie.quadrature.composite_weighted_rule`), else None.
    s, ws : ndarray
        Projection nodes (local) and weights.
    norms : ndarray
        h_m of P_m^{(-alpha,-beta)}, m < n - kappa (h_0 exact).
    """
    interval: Interval
    a: float
    b: float
    kernel: object = field(repr=False)
    exp: Exponents
    n: int
    breaks: np.ndarray
    total: float | None
    lam: float
    rule: WeightedRule | None
    s: np.ndarray
    ws: np.ndarray
    norms: np.ndarray
    weight: Weight = field(repr=False)
    split: WeightedRule | None = None

    @classmethod
    def build(cls, block, n, breaks, total, count=None):
        """The unknown of ``block`` (:class:`sie.Block`: interval, coefficients, exponents,
        kernel) with n coefficients; ``count``: how many projections are needed (default
        n - kappa, all equations)."""
        e, b = block.exponents, block.b
        m_eq = n - e.kappa
        count = m_eq if count is None else count
        norms = _projection_norms(count, e.alpha, e.beta, e.alpha_m1, e.beta_m1)
        split = None
        if breaks.size == 0:
            rule = _projection_rule(m_eq, e.alpha, e.beta, e.alpha_m1, e.beta_m1)
            s, ws = rule.x, rule.omega
        else:
            rule = None
            comp = composite_weighted_rule(m_eq + _EXTRA_PER_PIECE, -e.alpha, -e.beta,
                                           e.alpha_m1, e.beta_m1, breaks)
            s, ws = comp.x, comp.omega
            split = comp if comp.end else None
        return cls(block.interval, block.a, b, block.kernel, e, n, breaks, total,
                   dominant_lambda(e, b), rule, s, ws, norms, Weight.from_exponents(e), split)

    @property
    def kappa(self) -> int:
        return self.exp.kappa

    @property
    def m_eq(self) -> int:
        """Number of projected equations, n - kappa."""
        return self.n - self.exp.kappa

    @property
    def mu0(self) -> float:
        """int_{-1}^{1} w (exact)."""
        return jacobi_moment_shifted(self.exp.alpha_p1, self.exp.beta_p1)

    @property
    def end_rule(self) -> WeightedRule | None:
        """The projection rule that splits off an end's mass (None: none does)."""
        if self.rule is not None:
            return self.rule if self.rule.end else None
        return self.split

    @property
    def end(self) -> int:
        """The end whose mass the projection rule splits off (0: none)."""
        r = self.end_rule
        return r.end if r is not None else 0

    def sample_points(self):
        """Local points where the projection needs values: the nodes, and the split-off end."""
        return np.concatenate([self.s, [float(self.end)]]) if self.end else self.s

    def sample(self, fn, name, extra=None):
        """``fn`` at the sample points (real coordinates), checked; with ``extra`` (local
        points) also there, in the same call: (at the sample points, at ``extra``)."""
        u = self.sample_points()
        if extra is None:
            return call_checked(fn, name, (self.interval.real(u),), u.shape)
        x = self.interval.real(np.concatenate([u, extra]))
        v = call_checked(fn, name, (x,), x.shape)
        return v[:u.size], v[u.size:]

    def project(self, values, count=None):
        """<g, P_m^{(-alpha,-beta)}> / h_m, m < count, from g at :meth:`sample_points`
        (values may be a vector or a matrix with one column per function)."""
        count = self.norms.size if count is None else count
        v = np.asarray(values)
        q = self.s.size
        if v.ndim == 1 and count * q > _PROJECTOR_CACHE_MAX:
            # large n: blocked sums, no count-by-q matrix
            rule = self.rule if self.rule is not None else self.split
            if rule is not None:
                out = rule.project(v[:q], v[q] if self.end else 0.0, count)
            else:
                out = jacobi_project(self.ws * v, -self.exp.alpha, -self.exp.beta, self.s, count)
            return out / self.norms[:count]
        out = self._projector[:count] @ v[:q]
        if self.end:
            ev = self.end_rule.corr * self.end_rule.end_values(count)
            out = out + (ev * v[q] if v.ndim == 1 else np.outer(ev, v[q]))
        return out / (self.norms[:count] if v.ndim == 1 else self.norms[:count, None])

    @functools.cached_property
    def _projector(self):
        """(P_m(s_j) ws_j), m < n - kappa: the projection of sampled columns."""
        e = self.exp
        if self.rule is not None and self.norms.size * self.s.size <= _PROJECTOR_CACHE_MAX:
            return _projector(self.norms.size, self.s.size, e.alpha, e.beta, e.alpha_m1, e.beta_m1)
        return jacobi_vandermonde(self.norms.size, -e.alpha, -e.beta, self.s).T * self.ws

    def dominant_rhs_solve(self, fhat, total):
        """Coefficients from the diagonal system alone (no coupling, no kernel):
        lambda c_{m+kappa} = fhat_m, and c_0 = total/(h mu_0) for kappa = 1."""
        c = np.empty(self.n)
        k = self.kappa
        if k == 1:
            c[0] = total / (self.interval.h * self.mu0)
            c[1:] = fhat / self.lam
        elif k == 0:
            c[:] = fhat / self.lam
        else:
            c[:] = fhat[1:] / self.lam
        return c


# Memoised per exponents and size: the contact layer and load continuations solve equations
# with the same exponents many times (the arrays are read-only).
@functools.lru_cache(maxsize=256)
def _projection_norms(count, alpha, beta, alpha_m1, beta_m1):
    """h_m of P_m^{(-alpha,-beta)}, m < count, h_0 from the exact 1 - alpha, 1 - beta."""
    norms = jacobi_norms(count, -alpha, -beta)
    if count:
        norms[0] = jacobi_moment_shifted(alpha_m1, beta_m1)
    norms.flags.writeable = False
    return norms


@functools.lru_cache(maxsize=256)
def _projection_rule(m_eq, alpha, beta, alpha_m1, beta_m1):
    """The Gauss-Jacobi rule of (1-u)^{-alpha}(1+u)^{-beta} with m_eq nodes."""
    return WeightedRule.build(m_eq, -alpha, -beta, alpha_m1, beta_m1)


@functools.lru_cache(maxsize=64)
def _projector(count, q, alpha, beta, alpha_m1, beta_m1):
    rule = _projection_rule(q, alpha, beta, alpha_m1, beta_m1)
    out = jacobi_vandermonde(count, -alpha, -beta, rule.x).T * rule.omega
    out.flags.writeable = False
    return out
