"""The solution psi of a Cauchy singular integral equation on L = union of intervals.

Immutable: everything is fixed at construction; the pointwise correction for breaks
(:mod:`sie.remainder`) and the log-potential map are computed on first use and cached.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from .cauchy import (_FAR_SERIES_MAX_N, _far_series_table, cauchy_series, evaluation_points,
                     limit_points,
                     l0_beside, log_potential_series)
from .errors import (EvaluationPointError, InvalidOrderError, SIEInputError, call_checked,
                     real_array)
from .exponents import Exponents
from .intervals import Interval
from .jacobi import jacobi_series
from .quadrature import WeightedRule
from .remainder import _LOG_FAR, log_far
from .special import jacobi_end_values, jacobi_moment_shifted
from .unknowns import dominant_lambda

__all__ = ["Solution", "IntervalSolution", "end_value_gaps", "equation_end_value"]


_BREAKS_EQUATION_END = 0.1   # with breaks, phi at a singular end from the equation where
#                              the end's exponent is above -0.1 (IntervalSolution.endpoint_value)


def end_value_gaps(n, eps, end):
    """P_k^{(alpha,beta)}(end) - P_k^{(-alpha,-beta)}(end), k < n, without cancellation.

    ``eps`` is the exponent at that end (alpha at +1, beta at -1).  With
    A_k = (1+eps)_k/k!, B_k = (1-eps)_k/k! (DLMF 18.6.1) the gap is end^k D_k,
    D_k = A_k - B_k = D_{k-1} + eps (A_{k-1} + B_{k-1}) / k, a sum of terms of one sign:
    it keeps full relative precision as eps -> 0, where A_k - B_k formed as it reads keeps
    only ~1e-16 / eps of itself.

    Parameters
    ----------
    n : int
        Number of degrees, k = 0..n-1.
    eps : float or ndarray
        The exponent(s) of the end, in (-1, 1).
    end : {1, -1}

    Returns
    -------
    ndarray, shape ``np.shape(eps) + (n,)``

    Examples
    --------
    >>> import sie.solution as so
    >>> [float(v) / 1e-20 for v in so.end_value_gaps(3, 1e-20, -1)]   # 0, -2 eps, 3 eps
    [0.0, -2.0, 3.0]
    """
    eps = np.asarray(eps, dtype=float)[..., None]
    k = np.arange(1, n, dtype=float)
    two = np.full(eps.shape, 2.0)                            # A_0 + B_0
    sums = np.concatenate([two, np.cumprod((k + eps) / k, axis=-1)[..., :-1]
                           + np.cumprod((k - eps) / k, axis=-1)[..., :-1]], axis=-1)
    D = np.concatenate([np.zeros(eps.shape), np.cumsum(eps * sums / k, axis=-1)], axis=-1)
    if end < 0:
        D[..., 1::2] *= -1.0
    return D


def equation_end_value(coefficients, eps, eps_p1, end, g, g_size, lam):
    """phi at the singular end ``end`` of index-0 intervals from the equation there, and
    where that form is the more accurate one.

    The dominant operator maps the basis exactly, lambda sum_k c_k P_k^{(-alpha,-beta)} = g
    at the collocation nodes (g = f - (coupling + kernel) psi), so that to the truncation
    of g
        phi(end) = g(end) / lambda + sum_k c_k [P_k^{(alpha,beta)} - P_k^{(-alpha,-beta)}](end).
    As the end's exponent eps -> 0 the gaps are O(eps) (:func:`end_value_gaps`): where g(end)
    is small (zero: the parabolic punch's corner) phi(end) is O(eps c), which the series
    sum_k c_k P_k^{(alpha,beta)}(end), of terms of size c, keeps only to ~1e-16 / eps.  Each
    form rounds to ~1e-16 times the sum of the sizes of its terms; the equation's form is
    the more accurate where its sum, g_size / abs(lambda) + sum abs(c_k gap_k), is the
    smaller.  (It is not next to a close interval's singular end, whose Cauchy integral
    makes g(end) the difference of large terms.)

    Parameters
    ----------
    coefficients : ndarray, shape (B, n)
        c_k of phi, one row per interval (of one index and n).
    eps, eps_p1 : ndarray, shape (B,)
        The exponent of each at that end (alpha at +1, beta at -1), and 1 + it (exact).
    end : {1, -1}
        The singular end.
    g, g_size : ndarray, shape (B,)
        g(end), and the sum of the sizes of the terms it was formed from (abs(f(end)) plus
        those of the coupling and kernel terms).
    lam : ndarray, shape (B,)
        lambda = -b / sin(pi alpha) (:func:`sie.unknowns.dominant_lambda` at index 0).

    Returns
    -------
    value : ndarray, shape (B,)
        phi(end) from the equation.
    better : ndarray of bool, shape (B,)
        Where it is the more accurate form (elsewhere sum the series).
    """
    C = np.asarray(coefficients, dtype=float)
    n = C.shape[-1]
    gaps = end_value_gaps(n, np.asarray(eps, dtype=float), end)
    basis = np.array([jacobi_end_values(n, v, end) for v in np.asarray(eps_p1).tolist()])
    value = g / lam + np.sum(C * gaps, axis=-1)
    better = (np.abs(g_size / lam) + np.sum(np.abs(C * gaps), axis=-1)
              < np.sum(np.abs(C * basis), axis=-1))
    return value, better


@dataclass(frozen=True, eq=False)
class IntervalSolution:
    """psi on one interval: psi(s) = w(u) phi(u), u = (s - m)/h, w = (1-u)^alpha (1+u)^beta.

    One entry of :attr:`Solution.pieces`, built by :func:`sie.solve`; its methods work in
    the local coordinate u in [-1, 1] (m the midpoint, h the half-width of the interval).

    Attributes
    ----------
    interval : Interval
        The interval [c, d] (``interval.c``, ``interval.d``).
    exp : Exponents
        Its exponents and index (:func:`sie.sie_exponents`).
    alpha, beta : float
        Exponents of psi at the right and the left end.
    kappa : int
        Index -(alpha + beta).
    n : int
        Number of Jacobi coefficients.
    coefficients : ndarray
        c_k with phi = sum_k c_k P_k^{(alpha,beta)} (scipy's normalisation); read-only.
    consistency : float or None
        kappa = -1: the weighted mean of g = f - (coupling + kernel) psi against
        (1-u)^{-alpha}(1+u)^{-beta}, in units of f; zero iff the equation is solvable.
    remainder : object or None
        With ``breaks``: the pointwise correction of phi (:mod:`sie.remainder`), built on
        first use; None without breaks.
    end_rhs : (ndarray, ndarray) or None
        (g, size) at the interval's ends (c, d): the right-hand side of the dominant
        equation, g = f - (coupling + kernel) psi, and the sum of the sizes of its terms;
        evaluated on first use (:meth:`endpoint_value` needs it); None where the solver gave
        no way to evaluate it.

    References
    ----------
    Erdogan, Gupta & Cook (1973), ch. 7; Muskhelishvili, Singular Integral Equations (1953),
    ch. 10 (the exponents and the solvability condition).

    Examples
    --------
    >>> import numpy as np, sie
    >>> sol = sie.solve(lambda s: -s, a=0.0, b=1.0, n=4, left="bounded", right="bounded")
    >>> piece = sol.pieces[0]
    >>> (piece.interval.c, piece.interval.d), piece.kappa, piece.n
    ((-1.0, 1.0), -1, 4)
    >>> round(float(piece.coefficients[0]), 12)        # psi = sqrt(1 - s^2): phi = 1
    1.0
    """
    interval: Interval
    exp: Exponents = field(repr=False)
    n: int
    coefficients: np.ndarray
    consistency: float | None
    _remainder_factory: object = field(default=None, repr=False)
    _end_rhs_factory: object = field(default=None, repr=False)

    @property
    def alpha(self) -> float:
        return self.exp.alpha

    @property
    def beta(self) -> float:
        return self.exp.beta

    @property
    def kappa(self) -> int:
        return self.exp.kappa

    @functools.cached_property
    def weight_data(self):
        from .cauchy import Weight
        return Weight.from_exponents(self.exp)

    @property
    def has_breaks(self) -> bool:
        """Whether f has breaks inside the interval: phi is then the series plus the
        pointwise correction (:attr:`remainder`), and the series' tail does not measure
        phi's error (the correction carries the kinks)."""
        return self._remainder_factory is not None

    @functools.cached_property
    def remainder(self):
        """The breaks correction, built on first use (None without breaks)."""
        return self._remainder_factory() if self._remainder_factory is not None else None

    @functools.cached_property
    def end_rhs(self):
        """(g, size) at the ends (c, d): g = f - (coupling + kernel) psi, and the sum of the
        sizes of the terms it is formed from; on first use, None without a way to evaluate
        it."""
        f = self._end_rhs_factory
        return None if f is None else tuple(np.asarray(v, dtype=float) for v in f())

    def endpoint_value(self, end, b):
        """phi(end) at the local end +1 or -1; ``b`` the equation's Cauchy coefficient.

        At a singular end of an index-0 interval, from the equation at the end where that
        keeps more digits than the series (:func:`equation_end_value`: as the end's exponent
        tends to 0); elsewhere the series, with the breaks' correction.  With breaks the
        correction's r(end) / lambda, the term that differs between the two forms, cancels
        in their sum: the equation's form adds only the rest of the correction
        (:meth:`sie.remainder.InversionRemainder.quotient_part`), and is taken only for an
        exponent within 0.1 of 0, where the series keeps less than a tenth of its digits
        (the rest's integral has rounding of its own, ~ 1e-16 times the other end's mass
        1 / (1 - abs(eps)): 1e-13 of phi at eps = -0.49, where the series keeps 4e-15)."""
        eps = self.alpha if end == 1 else self.beta
        if self.kappa == 0 and eps < 0 and self.end_rhs is not None and \
                (self.remainder is None or eps > -_BREAKS_EQUATION_END):
            e, i = self.exp, (end + 1) // 2
            g, size = self.end_rhs
            value, better = equation_end_value(
                self.coefficients[None, :], [eps], [e.alpha_p1 if end == 1 else e.beta_p1],
                end, g[i:i + 1], size[i:i + 1], np.array([dominant_lambda(e, b)]))
            if better[0]:
                if self.remainder is None:
                    return float(value[0])
                at = np.array([float(end)])
                return float(value[0] + self.remainder.quotient_part(at)[0])
        return float(self.phi_local(np.array([float(end)]))[0])

    def phi_local(self, u):
        out = jacobi_series(self.coefficients, self.alpha, self.beta, u)
        if self.remainder is not None:
            out = out + self.remainder.phi(u)
        return out

    def weight_local(self, u):
        return (1.0 - u) ** self.alpha * (1.0 + u) ** self.beta

    def psi_local(self, u):
        """psi at local u in [-1, 1]: zero at a bounded end."""
        out = np.zeros(u.shape)
        inside = np.abs(u) < 1.0
        if np.any(inside):
            ui = u[inside]
            out[inside] = self.weight_local(ui) * self.phi_local(ui)
        return out

    def integral(self) -> float:
        """int over the interval of psi = h mu_0 c_0 (orthogonality; exact with breaks too:
        the remainder is orthogonal to 1)."""
        mu0 = jacobi_moment_shifted(self.exp.alpha_p1, self.exp.beta_p1)
        return float(self.interval.h * mu0 * self.coefficients[0])

    def kernel_local(self, kernel, s, nodes):
        """int over the interval of k(s, t) psi(t) dt at the real points s (1-d): h sum_j
        omega_j k(s, t_j) phi(u_j) by the Gauss rule of the weight with ``nodes`` nodes (end
        mass split off where an exponent is near -1, :class:`sie.quadrature.WeightedRule`),
        plus, with breaks, the sum of the correction's rule
        (:attr:`sie.remainder.InversionRemainder.w_rule`)."""
        e, iv = self.exp, self.interval
        rule = WeightedRule.build(nodes, e.alpha, e.beta, e.alpha_p1, e.beta_p1)
        u = np.concatenate([rule.x, [float(rule.end)]]) if rule.end else rule.x
        phi = jacobi_series(self.coefficients, e.alpha, e.beta, rule.x) * rule.omega
        if rule.end:
            end_phi = float(rule.end_values(self.n) @ self.coefficients)
            phi = np.concatenate([phi, [rule.corr * end_phi]])
        if self.remainder is not None:
            tw, _ = self.remainder.w_rule
            u = np.concatenate([u, tw])
            phi = np.concatenate([phi, self.remainder._w_values()])
        S, T = np.meshgrid(s, iv.real(u), indexing="ij", sparse=False)
        kst = call_checked(kernel, "kernel", (S, T), S.shape)
        return iv.h * (kst @ phi)

    def cauchy_local(self, v, cplx, ends=None):
        """(1/pi) int_{-1}^{1} w phi / (u - v) du (real v: principal value inside);
        ``ends`` = (v - 1, v + 1) from the real coordinate.

        With breaks the pointwise correction adds (1/pi) int w delta_phi / (u - v) du: at real
        v inside through the equation itself
        (:meth:`sie.remainder.InversionRemainder.cauchy_inside`), elsewhere (complex v, real v
        outside) by :meth:`sie.remainder.InversionRemainder.cauchy_off`."""
        out = cauchy_series(self.coefficients, self.weight_data, v, ends=ends)
        rem = self.remainder
        if rem is None:
            return out if cplx else out.real
        if not cplx:
            out = out.real
            inside = np.abs(v) < 1.0
        else:
            inside = np.zeros(v.shape, dtype=bool)      # complex v is never on (-1, 1)
        if np.any(inside):
            vi = v[inside]
            out[inside] = rem.cauchy_inside(vi, self.psi_local(vi))
        off = ~inside
        if np.any(off):
            e = None if ends is None else (ends[0][off], ends[1][off])
            corr = rem.cauchy_off(v[off], e)
            out[off] = out[off] + (corr if cplx else corr.real)
        return out

    def cauchy_limit_local(self, v, ends=None):
        """(1/pi) int_{-1}^{1} w phi / (u - v - i0) du at real v: the limit from above,
        H[w phi](v) + i w phi(v) inside (Plemelj), the real transform outside.

        Without breaks this is the series' transform evaluated at v itself, which the
        recurrence starts from F_0(v + i0) (:func:`sie.cauchy.cauchy_series`): the two
        parts come from one pass."""
        if self.remainder is None:
            return cauchy_series(self.coefficients, self.weight_data, v, ends=ends)
        out = self.cauchy_local(v, False, ends).astype(complex)
        inside = np.abs(v) < 1.0
        out[inside] += 1j * self.psi_local(v[inside])
        return out

    def log_local(self, v, ends=None, tol=None):
        """(1/pi) int_{-1}^{1} w phi log|v - u| du at real v (with breaks, plus the
        correction's part, :meth:`sie.remainder.InversionRemainder.log_potential`, to ``tol``
        of (1/pi) int w abs(phi) where given).  With breaks, at abs(v) >= 2 both parts at once
        from the sum of their moments (:func:`sie.remainder.log_far`; the series' moments from
        the table :func:`sie.cauchy.log_potential_series` takes them from)."""
        rem = self.remainder
        c = self.coefficients
        if rem is None:
            return log_potential_series(c, self.weight_data, v, ends)
        rem = rem.for_accuracy(tol)
        v = np.asarray(v, dtype=float)
        far = np.abs(v) >= _LOG_FAR
        if c.size > _FAR_SERIES_MAX_N or not far.any():
            return log_potential_series(c, self.weight_data, v, ends) + rem.log_potential(v, ends)
        wt = self.weight_data
        coef = rem.far_coefficients().copy()
        coef[0] += c[0] * wt.mu0
        coef[1:] += _far_series_table(wt, c.size) @ c
        out = np.empty(v.shape)
        out[far] = log_far(v[far], coef)
        near = ~far
        if near.any():
            sub = None if ends is None else (np.asarray(ends[0])[near], np.asarray(ends[1])[near])
            vn = v[near]
            weight_potential = l0_beside(wt, vn)      # the same for both parts
            out[near] = (log_potential_series(c, wt, vn, sub, weight_potential)
                         + rem.log_potential(vn, sub, weight_potential))
        return out


@dataclass(frozen=True, eq=False)
class Solution:
    """Solution psi of a psi + (b/pi) PV int_L psi(t)/(t-s) dt + int_L k(s,t) psi(t) dt = f(s).

    Returned by :func:`sie.solve`; immutable.  Call it to evaluate psi.  Per-interval
    attributes (``alpha``, ``beta``, ``kappa``, ``n``, ``coefficients``, ``consistency``) are
    scalars when :func:`sie.solve` was called without ``intervals`` (one interval [-1, 1])
    and tuples with one entry per interval otherwise.  Methods: ``sol(s)`` (psi),
    :meth:`phi`, :meth:`weight`, :meth:`integral`, :meth:`endpoint_value`, :meth:`cauchy` and
    :meth:`log_potential`.

    Attributes
    ----------
    pieces : tuple of IntervalSolution
        psi on each interval.
    a, b : float or tuple
        The coefficients of the equation (a tuple, one per interval, where they differ
        between intervals).
    intervals : tuple of (c, d)
        L, left to right.
    alpha, beta : float or tuple
        Exponents of psi at the right and the left end(s).
    kappa : int or tuple
        Index (indices) -(alpha + beta).
    n : int or tuple
        Number(s) of Jacobi coefficients.
    coefficients : ndarray or tuple of ndarray
        c_k with phi = sum_k c_k P_k^{(alpha,beta)}, per interval (read-only).
    consistency : float, None or tuple
        Solvability residual(s) of index -1 intervals (None elsewhere).
    condition : float
        2-norm condition number of the (row-scaled) collocation system.

    Raises
    ------
    EvaluationPointError
        From the methods: points outside L (``phi``, ``weight``), a singular end (psi), an
        end (``cauchy``), complex or non-finite points where real ones are needed.

    References
    ----------
    Erdogan, Gupta & Cook (1973), ch. 7; Krenk, Quart. Appl. Math. 33 (1975) 225;
    Muskhelishvili, Singular Integral Equations (1953), ch. 10 (Plemelj formulae, index).

    Examples
    --------
    psi(s) = sqrt(1 - s^2) solves (1/pi) PV int psi/(t - s) dt = -s; its Cauchy transform
    off the interval is (1/pi) int psi/(t - z) dt = sqrt(z^2 - 1) - z (= sqrt(3) - 2 at z = 2):

    >>> import math, sie
    >>> sol = sie.solve(lambda s: -s, a=0.0, b=1.0, n=4, left="bounded", right="bounded")
    >>> sol.intervals, sol.kappa
    (((-1.0, 1.0),), -1)
    >>> round(float(sol(0.6)), 12), round(float(sol.phi(0.6)), 12)   # psi and psi / w
    (0.8, 1.0)
    >>> round(float(sol.cauchy(2.0)), 12) == round(math.sqrt(3.0) - 2.0, 12)
    True
    >>> round(float(sol.cauchy(0.5)), 12)                            # principal value: -s
    -0.5
    """
    pieces: tuple
    a: float
    b: float
    multi: bool = field(default=False, repr=False)
    _matrix: np.ndarray | None = field(default=None, repr=False)

    # -- per-interval attributes ---------------------------------------------
    def _per(self, name):
        vals = tuple(getattr(p, name) for p in self.pieces)
        return vals if self.multi else vals[0]

    @property
    def intervals(self):
        return tuple((p.interval.c, p.interval.d) for p in self.pieces)

    alpha = property(lambda self: self._per("alpha"), doc="Exponent(s) at the right end(s).")
    beta = property(lambda self: self._per("beta"), doc="Exponent(s) at the left end(s).")
    kappa = property(lambda self: self._per("kappa"), doc="Index (indices) -(alpha + beta).")
    n = property(lambda self: self._per("n"), doc="Number(s) of Jacobi coefficients.")
    coefficients = property(lambda self: self._per("coefficients"),
                            doc="c_k with phi = sum_k c_k P_k^{(alpha,beta)} (per interval).")
    consistency = property(lambda self: self._per("consistency"),
                           doc="Solvability residual(s) for index -1 (None elsewhere).")

    # -- locating points ------------------------------------------------------
    def _real_points(self, s, name="s"):
        s = np.asarray(s)
        if s.dtype.kind == "c":
            raise EvaluationPointError(
                f"{name} must be real (this quantity is defined on the real line); got complex")
        s = real_array(name, s, EvaluationPointError)
        if not np.all(np.isfinite(s)):
            raise EvaluationPointError(f"{name} must be finite real numbers")
        return s

    def _piece_of(self, s):
        """Index of the closed interval containing each s, -1 outside L."""
        idx = np.full(s.shape, -1, dtype=int)
        for j, p in enumerate(self.pieces):
            idx[p.interval.contains(s)] = j
        return idx

    def _piece(self, interval):
        if interval is None:
            if len(self.pieces) > 1:
                raise EvaluationPointError(
                    f"interval= is required: this solution lives on {len(self.pieces)} intervals")
            return self.pieces[0]
        if isinstance(interval, bool) or not isinstance(interval, (int, np.integer)) \
                or not 0 <= interval < len(self.pieces):
            raise EvaluationPointError(
                f"interval must be an index 0..{len(self.pieces) - 1}, got {interval!r}")
        return self.pieces[int(interval)]

    def _where(self):
        if not self.multi:
            return "[-1, 1]"
        return " U ".join(f"[{c:g}, {d:g}]" for c, d in self.intervals)

    # -- psi and phi ------------------------------------------------------------
    def _on_pieces(self, s, local_fn, what):
        """``local_fn(piece, u)`` at each s of a closed interval (u its local coordinate)."""
        s = self._real_points(s)
        idx = self._piece_of(s)
        if np.any(idx < 0):
            raise EvaluationPointError(f"{what} is defined on {self._where()}; got points outside")
        out = np.empty(s.shape)
        for j, p in enumerate(self.pieces):
            sel = idx == j
            if np.any(sel):
                out[sel] = local_fn(p, p.interval.local(s[sel]))
        return out

    def phi(self, s):
        """phi_j(u) = psi/w_j at s in the closed interval j, u = (s - m_j)/h_j (a polynomial of
        degree n_j - 1, plus the pointwise remainder correction when ``breaks`` were given)."""
        return self._on_pieces(s, IntervalSolution.phi_local, "phi")

    def weight(self, s):
        """w_j(u) = (1-u)^alpha_j (1+u)^beta_j at s in the closed interval j."""
        return self._on_pieces(s, IntervalSolution.weight_local, "the weight")

    def __call__(self, s):
        """psi(s); zero outside L; a singular end itself raises."""
        s = self._real_points(s)
        out = np.zeros(s.shape)
        for p in self.pieces:
            iv = p.interval
            for end, expo in ((iv.d, p.alpha), (iv.c, p.beta)):
                if expo < 0 and np.any(s == end):
                    raise EvaluationPointError(
                        f"psi is infinite at s = {end:+g} (singular end, exponent {expo:.6g})")
            sel = iv.contains(s)
            if np.any(sel):
                out[sel] = p.psi_local(iv.local(s[sel]))
        return out

    # -- functionals ------------------------------------------------------------
    def integral(self, interval=None) -> float:
        """int psi over L (``interval=None``) or over interval j (real coordinate)."""
        if interval is None:
            return float(sum(p.integral() for p in self.pieces))
        return self._piece(interval).integral()

    def kernel_integral(self, kernel, s, nodes=None):
        """int_L k(s, t) psi(t) dt at real points s: a regular kernel applied to psi.

        Parameters
        ----------
        kernel : callable
            k(S, T) for float arrays S, T of one shape, returning finite real values of that
            shape (as the ``kernel`` of :func:`sie.solve`): smooth in t on each interval.
        s : array_like of float
            Real points, anywhere (on L or off it).
        nodes : int, optional
            Gauss nodes per interval; default 2 n + 32, finer than the solver's own sums
            of the kernel (n + 16 nodes), so that this integral also measures how well the
            solve resolved it.

        Returns
        -------
        ndarray of float, the shape of ``s``.

        Raises
        ------
        EvaluationPointError
            s complex or not finite.
        SIEInputError
            ``kernel`` not callable, or it returns values of another shape, complex or not
            finite (:class:`sie.errors.CallableError` naming it and the points).
        InvalidOrderError
            ``nodes`` not an integer >= 1.

        Examples
        --------
        psi = sqrt(1 - t^2) (the airfoil equation with f = -s) against k = s t^2:
        int t^2 sqrt(1 - t^2) dt = pi / 8.

        >>> import numpy as np, sie
        >>> sol = sie.solve(lambda s: -s, a=0.0, b=1.0, n=4, left="bounded", right="bounded")
        >>> I = sol.kernel_integral(lambda s, t: s * t**2, np.array([1.0, 2.0]))
        >>> [round(float(v) * 8 / np.pi, 12) for v in I]
        [1.0, 2.0]
        """
        s = self._real_points(s)
        if nodes is not None and (isinstance(nodes, bool) or not isinstance(
                nodes, (int, np.integer)) or nodes < 1):
            raise InvalidOrderError(f"nodes must be an integer >= 1 (Gauss nodes per "
                                    f"interval) or None, got {nodes!r}")
        flat = np.ascontiguousarray(s.ravel(), dtype=float)
        out = np.zeros(flat.shape)
        for p in self.pieces:
            out += p.kernel_local(kernel, flat, 2 * p.n + 32 if nodes is None else int(nodes))
        return out.reshape(s.shape)

    def endpoint_value(self, end, interval=None):
        """phi_j(+1) or phi_j(-1) (local ends): the factor stress-intensity factors are
        built from.  ``interval`` may be omitted for one interval.

        At a singular end of an index-0 interval it is formed from the equation at that end
        where that keeps more digits (:func:`equation_end_value`): it keeps its relative
        precision as the end's exponent tends to 0, where the Jacobi series summed at the
        end keeps ~1e-16 / exponent of it; elsewhere it is the series, as :meth:`phi`."""
        if end not in (1, -1):
            raise EvaluationPointError(f"end must be +1 or -1, got {end!r}")
        piece = self._piece(interval)
        b = self.b if not isinstance(self.b, tuple) else self.b[self.pieces.index(piece)]
        return piece.endpoint_value(int(end), b)

    @property
    def condition(self):
        """2-norm condition number of the (row-scaled) collocation system (1 when diagonal)."""
        if self._matrix is None:
            return 1.0
        return float(np.linalg.cond(self._matrix))

    # -- transforms -------------------------------------------------------------
    def cauchy(self, z):
        """(1/pi) int_L psi(t)/(t - z) dt.

        Real z = x: the principal value H[psi](x) = (1/pi) PV int_L psi(t)/(t - x) dt anywhere
        except the ends of the intervals (real result).  Complex z off L: the integral
        (complex result); its one-sided limits on L are H[psi](x) +- i psi(x) (Plemelj).
        Each interval's part is the exact transform of its Jacobi series (:mod:`sie.cauchy`:
        three-term recurrence, forward near the interval from F_0 in closed form, backward
        continued fraction away from it), so points 1e-12 from L or its ends keep full
        accuracy.  With ``breaks``, the transform of the pointwise correction is added
        (:mod:`sie.remainder`: through the inversion formula from the projection remainder,
        graded toward Re z near the line).

        Raises
        ------
        EvaluationPointError
            z at an end, a complex z with Im z == 0 on L, non-finite z.
        """
        z, cplx = evaluation_points(z, self.intervals, "z")
        flat = z.ravel()
        out = np.zeros(flat.shape, dtype=complex if cplx else float)
        for p in self.pieces:
            out += p.cauchy_local(p.interval.local(flat), cplx, p.interval.local_ends(flat))
        return out.reshape(z.shape)

    def cauchy_limit(self, x, side=1):
        """The one-sided limits of the Cauchy transform on the real line:
        C(x + i0 side) with C(z) = (1/pi) int_L psi(t)/(t - z) dt.

        On L this is H[psi](x) + side i psi(x) (the Plemelj formulas): the principal value
        and psi from one evaluation.  Off L it is the (real) transform, as :meth:`cauchy`.

        Parameters
        ----------
        x : array_like of float
            Real points, not at an end of an interval.
        side : {1, -1}
            The limit from above (+1) or from below (-1).

        Returns
        -------
        ndarray of complex, the shape of ``x``.

        Raises
        ------
        EvaluationPointError
            x complex, not finite or at an end; ``side`` not +1 or -1.

        References
        ----------
        N. I. Muskhelishvili, Singular Integral Equations (1953), sec. 17 (the Plemelj
        formulas).

        Examples
        --------
        The airfoil equation's psi = sqrt(1 - s^2) (bounded ends, f = -s):

        >>> import numpy as np, sie
        >>> sol = sie.solve(lambda s: -s, a=0.0, b=1.0, n=4, left="bounded", right="bounded")
        >>> F = sol.cauchy_limit(np.array([0.5]))
        >>> round(float(F.real[0]), 12), round(float(F.imag[0]) ** 2, 12)   # H = -s, psi^2
        (-0.5, 0.75)
        """
        x = limit_points(x, side, self.intervals)
        flat = x.ravel()
        out = np.zeros(flat.shape, dtype=complex)
        for p in self.pieces:
            out += p.cauchy_limit_local(p.interval.local(flat), p.interval.local_ends(flat))
        return (out if side == 1 else out.conj()).reshape(x.shape)

    def log_potential(self, x, tol=None):
        """V(x) = (1/pi) int_L psi(t) log|x - t| dt at real x (any x; finite at the ends).

        dV/dx = -H[psi](x).  Per interval, with t = m + h u:
        V_j(x) = h [(log h / pi) int w phi du + (1/pi) int w phi log|v - u| du], v = (x-m)/h;
        the last integral in closed form through the Cauchy transform of a polynomial of
        degree n (integration by parts, DLMF 18.9.16; :mod:`sie.cauchy`).  With ``breaks``,
        the log potential of the pointwise correction is added (:mod:`sie.remainder`): a sum
        over a composite Gauss rule graded geometrically toward the breaks, where the
        correction behaves like (t - c) log|t - c|, with the correction evaluated at its
        nodes.

        Parameters
        ----------
        x : array_like of float
            Real points, anywhere (on L or off it).
        tol : float, optional
            The error allowed in V, relative to its scale, the sum over the intervals of
            (1/pi) int abs(psi(t)) dt.  With ``breaks`` the correction's part is then summed
            over a rule made for that accuracy (:mod:`sie.remainder`):
            graded toward the breaks only down to pieces of length h with h^2 log(1/h)
            about tol (what an unresolved piece at a break misses), with fewer nodes on the
            graded pieces, which needs the correction at fewer than half as many points
            (the first evaluation of V on a solution pays for them; later ones reuse them).
            Without breaks, or ``tol`` below ~1e-15, V is computed to rounding.  Default
            None: to rounding.

        Returns
        -------
        ndarray of float, the shape of ``x``.

        Raises
        ------
        EvaluationPointError
            complex or non-finite x.
        SIEInputError
            ``tol`` not a positive real number (nor None).

        References
        ----------
        N. I. Muskhelishvili, Singular Integral Equations (1953), sec. 107-110 (the
        inversion of the dominant equation that gives the correction); I. Babuska and
        B. Q. Guo, The h-p version of the finite element method, part 1: the basic
        approximation results, Comput. Mech. 1 (1986) 21-41 (geometric meshes toward a
        singularity, with node counts falling with depth).

        Examples
        --------
        Far away V(x) = (1/pi) int psi log x + O(1/x), here for psi = sqrt(1 - t^2):

        >>> import numpy as np, sie
        >>> sol = sie.solve(lambda s: -s, a=0.0, b=1.0, n=4, left="bounded", right="bounded")
        >>> x = 1e9
        >>> bool(abs(sol.log_potential(x) - sol.integral() * np.log(x) / np.pi) < 1e-10)
        True

        A right-hand side with a kink at 0.3 (psi ~ 1 here): V to 1e-12 of its scale, which
        costs less than V to rounding, agrees with it:

        >>> sol = sie.solve(lambda s: np.abs(s - 0.3), a=0.0, b=1.0, n=24, left="singular",
        ...                 right="bounded", breaks=[0.3])
        >>> x = np.array([-3.0, -1.0, 1.0 + 1e-9, 2.0])
        >>> bool(np.max(np.abs(sol.log_potential(x, tol=1e-12) - sol.log_potential(x)))
        ...      < 1e-12)
        True
        """
        x = self._real_points(x, "x")
        if tol is not None and (isinstance(tol, bool) or not isinstance(
                tol, (int, float, np.integer, np.floating)) or not 0.0 < tol < math.inf):
            raise SIEInputError(f"tol must be a positive real number or None, got {tol!r}")
        flat = x.ravel()
        out = np.zeros(flat.shape)
        for p in self.pieces:
            iv = p.interval
            mu0 = jacobi_moment_shifted(p.exp.alpha_p1, p.exp.beta_p1)
            out += iv.h * (math.log(iv.h) / math.pi * mu0 * p.coefficients[0]
                           + p.log_local(iv.local(flat), iv.local_ends(flat), tol))
        return out.reshape(x.shape)
