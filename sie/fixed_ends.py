"""Ends with an explicit exponent: kernels with a fixed singularity at an end.

    a psi(s) + (b/pi) PV int_c^d psi(t)/(t - s) dt + int_c^d k(s, t) psi(t) dt = f(s)

on one interval, where k(s, t) grows without bound toward (s, t) = (end, end) (a
generalised Cauchy kernel: the edge crack's -1/(t+s) + 6s/(t+s)^2 - 4s^2/(t+s)^3).  Such a
kernel sets the exponent of psi at that end itself, so the end choices "bounded" /
"singular" (which take it from cot(pi alpha0) = -a/b) do not apply there; the caller gives
it (``left=0.0``), e.g. as the root of the kernel's Mellin symbol (:func:`end_exponent`).

With an explicit exponent alpha + beta is in general not an integer and the dominant
operator no longer maps w P_k^{(alpha,beta)} onto a Jacobi polynomial, so the equation is
collocated in general form: psi = w phi, w = (1-u)^alpha (1+u)^beta, phi =
sum_{k<N} c_k P_k^{(alpha,beta)}, and at each collocation point x

    a w P_k (x) + b H[w P_k](x) + h int k(x, t(v)) w(v) P_k(v) dv,

with (Erdogan, Gupta & Cook 1973, eqs. (7.38)-(7.40) for the splitting)

    H[w P_k](x) = (1/pi) int w(t) (P_k(t) - P_k(x))/(t - x) dt + P_k(x) H[w](x),

the first term exact by Gauss-Jacobi (its integrand is a polynomial of degree k - 1 times
w; the divided differences by their own three-term recurrence, without cancellation) and
H[w] in closed form (:func:`weight_hilbert`).  The kernel term is nearly singular for x next
to an explicit end: it is integrated by a rule graded geometrically toward that end on the
scale of x's distance to it (:func:`graded_weight_rule`).

The index rule (Muskhelishvili 1953, the index and the count of conditions): an explicit
exponent below 0 counts as singular, one at or above 0 as bounded; kappa = (number of
singular ends) - 1.  kappa = 0: N collocation points (unique solution); kappa = 1: N - 1
points and the side condition int psi = total; kappa = -1: N + 1 points solved in least
squares, with the root-mean-square residual reported as ``consistency``.  The points are
the roots of P_{N-kappa}^{(-alpha,-beta)}, the classical choice when alpha + beta is an
integer (Erdogan, Gupta & Cook 1973; Krenk 1975).

Further exponents (``left=(e0, g1, ...)``, :func:`check_further`): near the explicit end psi
= sum_j c_j d^{g_j} over the roots of the kernel's symbol (d the distance to the end), and
the basis w P_k carries d^{e0} but not d^{g1}, so the series converges algebraically.  Each
further g_j adds the term e_j = w s_j, s_j = (1+u)^{g_j - beta} (left end; mirrored at the
right), as real columns (Re and Im for a complex g_j, whose conjugate is implied) and as
many more collocation points (the roots of P_{N'-kappa}^{(-alpha,-beta)}, N' all the
columns): a e_j + b H[e_j] + h int k e_j at each point, H[e_j](x) = (1/pi) int w (s(t) -
s(x))/(t - x) dt + s(x) H[w](x) and the kernel term on a rule graded geometrically toward
the end from deep enough that the innermost piece holds 1e-17 of the integral
(:func:`further_rule`, :func:`further_images`).  The solution's phi, psi, end values,
integral, kernel integral, Cauchy transform and log potential include the terms
(:class:`FurtherIntervalSolution`, :func:`further_cauchy`, :func:`further_log_potential`).

References
----------
F. Erdogan, G. D. Gupta and T. S. Cook, "Numerical solution of singular integral
equations", in Methods of Analysis and Solutions of Crack Problems, G. C. Sih (ed.),
Noordhoff (1973), ch. 7.  M. C. Kaya and F. Erdogan, "On the solution of integral equations
with strongly singular kernels", Quart. Appl. Math. 45 (1987) 105.  W. T. Koiter, "Discussion
of 'Rectangular tensile sheet with symmetric edge cracks'", J. Appl. Mech. 32 (1965) 237.
N. I. Muskhelishvili, Singular Integral Equations (1953).
"""
from __future__ import annotations

import cmath
import math
import numbers
import warnings
from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np
from scipy.special import gamma, hyp2f1, rgamma

from .assembly import probe_kernel
from .errors import (InconsistentEquationWarning, InvalidEndConditionError, ResidualWarning,
                     SideConditionError, UnsupportedEquationError, call_checked,
                     check_finite_real, check_order)
from .exponents import Exponents, check_explicit_exponent, is_explicit
from .gaussjacobi import gauss_jacobi_cached
from .jacobi import jacobi_series, jacobi_vandermonde, recurrence_coefficients
from .solution import IntervalSolution, Solution
from .special import jacobi_moment_shifted

__all__ = ["end_exponent", "end_exponents", "is_explicit", "check_explicit_exponent", "explicit_exponents",
           "weight_hilbert", "hilbert_images", "graded_weight_rule", "solve_fixed",
           "FixedEndSolution"]

_RATIO = 4.0            # growth of the graded pieces away from an explicit end
_Q_MIN = 24             # Gauss nodes per piece of the graded rule, at least
_N_MAX = 400            # unknowns of the general collocation (dense, O(N^2) kernel sums)
_CHECKS = np.cos(np.pi * (np.arange(7) + 0.5) / 7) * 0.999
_RESIDUAL_TOL = 1e-6    # as sie.solver.RESIDUAL_TOL
_CONSISTENCY_TOL = 1e-8  # as sie.solver.CONSISTENCY_TOL


# --------------------------------------------------------------------------
# the end conditions
# --------------------------------------------------------------------------
def index_of(left, right, alpha: float, beta: float) -> int:
    """kappa = (number of singular-like ends) - 1: an explicit exponent below 0 counts as
    singular, one at or above 0 as bounded; a named end counts as named."""
    def singular(choice, e):
        return e < 0.0 if is_explicit(choice) else choice == "singular"
    return int(singular(left, beta)) + int(singular(right, alpha)) - 1


def explicit_exponents(a: float, b: float, left, right) -> Exponents:
    """The :class:`sie.Exponents` of an interval with at least one explicit end: the
    explicit exponent(s) as given, a named end's from cot(pi alpha0) = -a/b as
    :func:`sie.sie_exponents` forms it, kappa by :func:`index_of`."""
    from .exponents import exponents_of
    named = exponents_of(a, b, "bounded" if is_explicit(left) else left,
                         "bounded" if is_explicit(right) else right)
    alpha = float(right) if is_explicit(right) else named.alpha
    beta = float(left) if is_explicit(left) else named.beta
    return Exponents(alpha, beta, index_of(left, right, alpha, beta), named.alpha0,
                     named.cot, math.sin(math.pi * alpha), 1.0 + alpha, 1.0 + beta,
                     1.0 - alpha, 1.0 - beta)


# --------------------------------------------------------------------------
# the Mellin helper
# --------------------------------------------------------------------------
def end_exponent(symbol, bracket=(-0.99, 0.99), *, xtol=1e-15):
    """The end exponent gamma in (-1, 1) that a fixed singularity dictates: the root of the
    kernel's characteristic function (its Mellin symbol) in ``bracket``.

    Near an end where k(s, t) is homogeneous of degree -1 in the distances to it, psi ~
    t^gamma is a local solution of the homogeneous equation when the Mellin symbol of the
    operator vanishes at gamma (Erdogan, Gupta & Cook 1973, sec. 7.3): the user writes it
    down, this finds its root.

    Parameters
    ----------
    symbol : callable
        The characteristic function D(gamma), real for real gamma, continuous on the
        bracket, with a sign change there.
    bracket : (float, float)
        lo < hi inside (-1, 1).
    xtol : float
        Absolute tolerance of the root (Brent's method).

    Returns
    -------
    float
        The root, in (-1, 1): pass it as ``left=`` / ``right=`` to :func:`sie.solve`.

    Raises
    ------
    InvalidEndConditionError
        A bracket outside (-1, 1), no sign change on it, or a non-finite symbol value.

    References
    ----------
    F. Erdogan, G. D. Gupta and T. S. Cook (1973), sec. 7.3 (the characteristic equation of
    generalised Cauchy kernels); M. C. Kaya and F. Erdogan, Quart. Appl. Math. 45 (1987) 105.

    Examples
    --------
    The edge crack normal to a free surface, k(x, t) = -1/(t+x) + 6x/(t+x)^2 -
    4x^2/(t+x)^3 (distances from the surface): t^gamma is mapped to x^gamma times
    D(gamma) / sin(pi gamma), D(gamma) = 1 - cos(pi gamma) + 4 gamma + 2 gamma^2, whose root
    in (-1, 1) is 0, the exponent at the crack's mouth:

    >>> import math, sie
    >>> D = lambda g: 1.0 - math.cos(math.pi * g) + 4.0 * g + 2.0 * g * g
    >>> abs(sie.end_exponent(D, (-0.5, 0.5))) < 1e-14
    True
    """
    try:
        lo, hi = (float(v) for v in bracket)
    except (TypeError, ValueError):
        raise InvalidEndConditionError(f"bracket must be two floats (lo, hi), got "
                                       f"{bracket!r}") from None
    if not (-1.0 < lo < hi < 1.0):
        raise InvalidEndConditionError(f"bracket must satisfy -1 < lo < hi < 1, got "
                                       f"{bracket!r}")
    flo, fhi = float(symbol(lo)), float(symbol(hi))
    if not (math.isfinite(flo) and math.isfinite(fhi)):
        raise InvalidEndConditionError(f"the symbol is not finite on the bracket: "
                                       f"D({lo}) = {flo}, D({hi}) = {fhi}")
    if flo == 0.0:
        return lo
    if fhi == 0.0:
        return hi
    if (flo > 0) == (fhi > 0):
        raise InvalidEndConditionError(
            f"the symbol has no sign change on [{lo}, {hi}] (D = {flo:.3g}, {fhi:.3g}): give a "
            "bracket around the root")
    # scipy.optimize imported here: a moving sweep never needs it (its import is the
    # scene's start-up, tests/scene/test_cli.py)
    from scipy.optimize import brentq
    return float(brentq(lambda g: float(symbol(g)), lo, hi, xtol=xtol,
                        rtol=4.0 * np.finfo(float).eps))


_WINDING_STEP = 0.02     # the argument principle's first sampling of the box's edges


def _winding(symbol, corners, max_depth=40):
    """The number of zeros of ``symbol`` inside the polygon ``corners`` (counter-clockwise),
    by the argument principle: its argument's change along the edges, sampled every 0.02
    and halved until the argument turns by less than pi/4 between neighbouring points (a
    symbol like cos(pi g) turns by pi per unit of Re g)."""
    total = 0.0
    for p, q in zip(corners, corners[1:] + corners[:1]):
        k = max(1, math.ceil(abs(q - p) / _WINDING_STEP))
        pts = [p + (q - p) * j / k for j in range(k + 1)]
        vals = [complex(symbol(z)) for z in pts]
        stack = [(pts[j], pts[j + 1], vals[j], vals[j + 1], 0) for j in range(k)]
        while stack:
            a, b, fa, fb, depth = stack.pop()
            if not (np.isfinite(fa) and np.isfinite(fb)) or fa == 0 or fb == 0:
                raise InvalidEndConditionError(
                    f"the symbol is zero or not finite on the search box's boundary near "
                    f"{a:.6g}: change above= or box=")
            turn = cmath.phase(fb / fa)
            if abs(turn) > math.pi / 4 and depth < max_depth:
                m = 0.5 * (a + b)
                fm = complex(symbol(m))
                stack.append((m, b, fm, fb, depth + 1))
                stack.append((a, m, fa, fm, depth + 1))
            else:
                total += turn
    return int(round(total / (2.0 * math.pi)))


def _newton(symbol, g, tol, iters=60):
    """A root of ``symbol`` near g by Newton's method, the derivative by central
    differences; None if it does not converge."""
    for _ in range(iters):
        fg = complex(symbol(g))
        h = 1e-6 * (1.0 + abs(g))
        df = (complex(symbol(g + h)) - complex(symbol(g - h))) / (2.0 * h)
        if not (np.isfinite(fg) and np.isfinite(df)) or df == 0:
            return None
        step = fg / df
        g = g - step
        if abs(step) <= tol * (1.0 + abs(g)):
            return g
        if abs(g) > 1e6:
            return None
    return None


def end_exponents(symbol, count=1, *, above=0.0, box=(12.0, 6.0), tol=1e-14):
    """The further exponents of psi at an end with a fixed singularity: the roots g of the
    kernel's Mellin symbol D(g) with Re g > ``above``, the ``count`` with the smallest real
    parts, complex ones with Im g > 0 (their conjugates are roots too).

    Near an end where the kernel is homogeneous of degree -1 in the distances to it, psi
    = sum_j c_j d^{g_j} over the roots of D (Erdogan, Gupta & Cook 1973, sec. 7.3; d the
    distance to the end): the root in (-1, 1), :func:`end_exponent`, is the leading
    exponent, the next roots (the edge crack's are complex) the terms the Jacobi basis
    does not carry.  Pass them as ``left=(e0, g1, ...)`` / ``right=(e0, g1, ...)`` to
    :func:`sie.solve`: the basis then carries them and the solution converges faster.

    The roots are found by Newton's method (the derivative by central differences) from a
    grid of starting points (spacing 1/4) in the box ``above`` < Re g < ``above`` + box[0],
    0 <= Im g < box[1]; their number is checked against the argument principle on the box
    ``above`` + 1e-6 < Re g < ``above`` + box[0], abs(Im g) < box[1] (the symbol real on the
    real axis: roots in conjugate pairs).

    Parameters
    ----------
    symbol : callable
        D(g) for complex g (write it with :mod:`cmath` or numpy, not :mod:`math`), analytic
        in the box, real for real g.
    count : int
        How many roots (>= 1).
    above : float
        Only roots with real part above it (the leading exponent).
    box : (float, float)
        The search box's width in Re g (from ``above``) and height in Im g.
    tol : float
        Relative tolerance of Newton's steps.

    Returns
    -------
    tuple of complex
        The roots, by increasing real part (a real root with Im 0).

    Raises
    ------
    InvalidEndConditionError
        count not a positive integer, a bad box, fewer than ``count`` roots in the box, the
        roots found fewer than the argument principle counts, or a symbol not finite or
        zero on the box's boundary.

    References
    ----------
    F. Erdogan, G. D. Gupta and T. S. Cook (1973), sec. 7.3 (the characteristic equation of
    generalised Cauchy kernels); W. T. Koiter, J. Appl. Mech. 32 (1965) 237 (the edge
    crack); P. Henrici, Applied and Computational Complex Analysis, vol. 1, Wiley (1974),
    sec. 4.10 (the argument principle).

    Examples
    --------
    The edge crack's symbol D(g) = 1 - cos(pi g) + 4 g + 2 g^2: the leading exponent 0 at
    the mouth, the next roots complex:

    >>> import cmath, sie
    >>> D = lambda g: 1.0 - cmath.cos(cmath.pi * g) + 4.0 * g + 2.0 * g * g
    >>> g1, g2 = sie.end_exponents(D, 2, above=0.0)
    >>> round(g1.real, 6), round(g1.imag, 6)
    (1.739593, 1.119025)
    >>> round(g2.real, 6), round(g2.imag, 6)
    (3.808251, 1.463928)
    """
    if isinstance(count, bool) or not isinstance(count, (int, np.integer)) or count < 1:
        raise InvalidEndConditionError(f"count must be an integer >= 1, got {count!r}")
    above = check_finite_real("above", above, InvalidEndConditionError)
    try:
        width, height = (float(v) for v in box)
    except (TypeError, ValueError):
        raise InvalidEndConditionError(f"box must be two positive floats (width, height), "
                                       f"got {box!r}") from None
    if not (0.0 < width < 1e3 and 0.0 < height < 1e3):
        raise InvalidEndConditionError(f"box must be two positive floats below 1e3, got "
                                       f"{box!r}")
    lo, hi = above + 1e-6 * (1.0 + abs(above)), above + width
    roots = []
    for re in np.arange(lo, hi, 0.25) + 0.125:
        for im in np.arange(0.0, height, 0.25) + 0.125:
            g = _newton(symbol, complex(re, im), tol)
            if g is None:
                continue
            if abs(g.imag) < 1e-9 * (1.0 + abs(g.real)):
                g = complex(g.real, 0.0)
            g = complex(g.real, abs(g.imag))
            if not (lo < g.real < hi and g.imag < height):
                continue
            if all(abs(g - h) > 1e-8 * (1.0 + abs(g)) for h in roots):
                roots.append(g)
    found = sum(1 if g.imag == 0.0 else 2 for g in roots)
    inside = _winding(symbol, [complex(lo, -height), complex(hi, -height),
                               complex(hi, height), complex(lo, height)])
    if found != inside:
        raise InvalidEndConditionError(
            f"the search found {found} roots (conjugates counted) of the symbol in the box "
            f"{lo:.6g} < Re g < {hi:.6g}, abs(Im g) < {height:g}, the argument principle "
            f"{inside}: the symbol is not analytic or not real on the real axis there, or "
            "roots lie too close together (change box=)")
    roots.sort(key=lambda g: (g.real, g.imag))
    if len(roots) < count:
        raise InvalidEndConditionError(
            f"only {len(roots)} roots with {lo:.6g} < Re g < {hi:.6g}, Im g < {height:g}: "
            f"enlarge box= to find {count}")
    return tuple(roots[:count])


# --------------------------------------------------------------------------
# the finite Hilbert transform of the weight and of the basis
# --------------------------------------------------------------------------
_NEAR_INTEGER = 0.05    # weight_hilbert: an end's form avoided with its exponent this near an
#                         integer (and nearer one than the other end's)


def _dist_to_integer(e):
    return abs(e - round(e))


def weight_hilbert(x, alpha: float, beta: float):
    """H[w](x) = (1/pi) PV int_{-1}^{1} w(t)/(t - x) dt, w = (1-t)^alpha (1+t)^beta, for
    x in (-1, 1) and any alpha, beta in (-1, 1).

    With alpha not an integer (Erdogan, Gupta & Cook 1973, eq. (7.29); Gradshteyn & Ryzhik
    3.228, checked against mpmath's principal value in the tests):

        H[w](x) = cot(pi alpha) w(x) - 2^{alpha+beta} Gamma(alpha) Gamma(beta+1)
                  / (pi Gamma(alpha+beta+1)) 2F1(1, -alpha-beta; 1-alpha; (1-x)/2),

    and with the ends exchanged (x -> -x, H -> -H): at each x the form of the nearer end
    (its 2F1's argument is small), unless that end's exponent is within 0.05 of an integer
    and nearer one than the other's (alpha = 0: the cotangent and Gamma(alpha) are
    infinite).  With
    alpha = beta = 0, w = 1: H[1](x) = (1/pi) log((1-x)/(1+x)).
    """
    x = np.asarray(x, dtype=float)
    return _weight_hilbert_dist(1.0 - x, 1.0 + x, alpha, beta)


def _weight_hilbert_dist(one_minus, one_plus, alpha, beta):
    """:func:`weight_hilbert` from the distances 1 - x and 1 + x (formed from the real
    coordinate next to an end)."""
    one_minus = np.asarray(one_minus, dtype=float)
    one_plus = np.asarray(one_plus, dtype=float)
    if alpha == 0.0 and beta == 0.0:
        return np.log(one_minus / one_plus) / math.pi
    da, db = _dist_to_integer(alpha), _dist_to_integer(beta)
    # the nearer end's form (its series' argument, the distance / 2, is small: the far
    # end's at 1e-6 from an end keeps ~1e-11), unless its exponent is within 0.05 of an
    # integer and nearer one than the other end's (the cotangent and Gamma(alpha) blow up)
    right_ok = da >= min(_NEAR_INTEGER, db)
    left_ok = db >= min(_NEAR_INTEGER, da)
    use_right = np.where(one_minus <= one_plus, right_ok, not left_ok)
    out = np.empty(np.broadcast(one_minus, one_plus).shape)
    if np.any(use_right):
        out[use_right] = _weight_hilbert_right(one_minus[use_right], one_plus[use_right],
                                               alpha, beta)
    if np.any(~use_right):
        out[~use_right] = -_weight_hilbert_right(one_plus[~use_right], one_minus[~use_right],
                                                 beta, alpha)
    return out


def _weight_hilbert_right(one_minus, one_plus, alpha, beta):
    """The closed form of :func:`weight_hilbert`, alpha not an integer, from the distances
    1 - x and 1 + x."""
    w = one_minus ** alpha * one_plus ** beta
    const = 2.0 ** (alpha + beta) * gamma(alpha) * gamma(beta + 1.0) * rgamma(
        alpha + beta + 1.0) / math.pi
    return w / math.tan(math.pi * alpha) - const * hyp2f1(1.0, -alpha - beta, 1.0 - alpha,
                                                          0.5 * one_minus)


def _divided_sums(n, alpha, beta, x, t, omega):
    """S[i, k] = sum_j omega_j (P_k(t_j) - P_k(x_i))/(t_j - x_i), P_k = P_k^{(alpha,beta)},
    k < n, by the recurrence of the divided differences Q_k = (P_k(t) - P_k(x))/(t - x):

        Q_{k+1} = (A_k t + B_k) Q_k + A_k P_k(x) - C_k Q_{k-1},   Q_0 = 0,

    from P_{k+1} = (A_k t + B_k) P_k - C_k P_{k-1} (DLMF 18.9.1-2): no difference of close
    numbers where t_j is next to x_i."""
    P = jacobi_vandermonde(n, alpha, beta, x)          # (m, n)
    S = np.zeros((x.size, n))
    if n < 2:
        return S
    T = t[None, :]
    A, B, C = recurrence_coefficients(alpha, beta, n - 1)
    q_prev = np.zeros((x.size, t.size))
    q = np.full((x.size, t.size), 0.5 * ((alpha + 1.0) + (beta + 1.0)))   # Q_1: P_1's slope
    S[:, 1] = q @ omega
    for k in range(1, n - 1):
        q_prev, q = q, (A[k - 1] * T + B[k - 1]) * q + A[k - 1] * P[:, k:k + 1] - C[k - 1] * q_prev
        S[:, k + 1] = q @ omega
    return S


def hilbert_images(n, alpha, beta, x):
    """H[w P_k](x) = (1/pi) PV int w P_k/(t - x) dt, k < n, at x in (-1, 1): matrix
    (len(x), n); the divided-difference part by the n-point Gauss rule of w (exact), the
    rest P_k(x) H[w](x)."""
    x = np.asarray(x, dtype=float)
    t, omega = gauss_jacobi_cached(max(n, 1), alpha, beta)
    S = _divided_sums(n, alpha, beta, x, np.asarray(t), np.asarray(omega))
    P = jacobi_vandermonde(n, alpha, beta, x)
    return S / math.pi + P * weight_hilbert(x, alpha, beta)[:, None]


# --------------------------------------------------------------------------
# the graded rule for the kernel term
# --------------------------------------------------------------------------
def _piece(lo, hi, q, e_near, e_far):
    """Nodes and weights of int g(v) w(v) dv over the piece of distances [lo, hi] from one
    end of [-1, 1] (0 <= lo < hi <= 1), w = (near distance)^e_near (far distance)^e_far:
    Gauss-Jacobi of the near factor on a piece that touches the end (lo = 0), Gauss-Legendre
    elsewhere, the rest of w evaluated.  Returns the distances of the nodes to that end and
    to the other, and the weights; the width hi - lo is formed from distances to one end,
    so that a piece of width 1e-7 keeps its relative precision (from 2 - (2 - d) it would
    keep 1e-9 of it)."""
    e = e_near if lo == 0.0 else 0.0
    y, om = gauss_jacobi_cached(q, 0.0, e)          # the factor (1 + y)^e at the near end
    h = 0.5 * (hi - lo)
    near = lo + h * (1.0 + np.asarray(y))
    far = 2.0 - near
    wt = np.asarray(om) * h ** (1.0 + e) * far ** e_far
    if lo != 0.0:
        wt = wt * near ** e_near
    return near, far, wt


def graded_weight_rule(dist_left, dist_right, q, alpha, beta, graded_left, graded_right):
    """A rule for int_{-1}^{1} g(v) w(v) dv with g nearly singular at the explicit end(s) on
    the scale of the point's distance to them (``dist_left`` = 1 + x, ``dist_right`` = 1 - x).

    Each half, [-1, 0] and [0, 1]: toward a graded end at distance d < 1, the piece
    [end, end -+ d] by Gauss-Jacobi of that end's factor of w and pieces growing by the
    ratio 4 up to the middle by Gauss-Legendre times w; otherwise one piece, Gauss-Jacobi of
    the end's factor.  With q nodes per piece a kernel singular at distance d beyond the end
    of its piece converges like 3^(-2q) (the Bernstein ellipse of the piece).

    Returns
    -------
    (ndarray, ndarray, ndarray)
        1 + v, 1 - v and the weights (w included).
    """
    return _rule_on_edges(_edges(dist_left) if graded_left and dist_left < 1.0 else _WHOLE,
                          _edges(dist_right) if graded_right and dist_right < 1.0 else _WHOLE,
                          q, alpha, beta)


_WHOLE = (0.0, 1.0)     # a half in one piece


def _rule_on_edges(left_edges, right_edges, q, alpha, beta):
    """The rule of :func:`graded_weight_rule` and :func:`further_rule` on the pieces between
    the edges of each half (distances 0 .. 1 from its end, ascending), :func:`_piece` on
    each: 1 + v, 1 - v (each from its own end) and the weights (w included)."""
    dls, drs, wts = [], [], []
    for edges, left_side in ((left_edges, True), (right_edges, False)):
        e_near, e_far = (beta, alpha) if left_side else (alpha, beta)
        for lo, hi in zip(edges[:-1], edges[1:]):
            near, far, wt = _piece(lo, hi, q, e_near, e_far)
            dls.append(near if left_side else far)
            drs.append(far if left_side else near)
            wts.append(wt)
    return np.concatenate(dls), np.concatenate(drs), np.concatenate(wts)


def kernel_term(kernel, x_dist, interval, n, alpha, beta, graded_left, graded_right, q):
    """h int k(x, t(v)) w(v) P_k(v) dv at the points of local distances x_dist = (1 + x,
    1 - x): matrix (len(x), n), the kernel called once on all nodes."""
    dl_x, dr_x = x_dist
    rules = [graded_weight_rule(a, b, q, alpha, beta, graded_left, graded_right)
             for a, b in zip(dl_x, dr_x)]
    sizes = np.array([r[0].size for r in rules])
    dl = np.concatenate([r[0] for r in rules])
    dr = np.concatenate([r[1] for r in rules])
    wt = np.concatenate([r[2] for r in rules])
    c, d, h = interval.c, interval.d, interval.h
    # real coordinates from the nearer end: next to an end, s - c and t - c keep their
    # relative precision (the edge crack's kernel is a function of t + s there)
    t = np.where(dl <= dr, c + h * dl, d - h * dr)
    s_pts = np.where(dl_x <= dr_x, c + h * dl_x, d - h * dr_x)
    S = np.repeat(s_pts, sizes)
    kst = call_checked(kernel, "kernel", (S, t), S.shape)
    v = np.where(dl <= dr, dl - 1.0, 1.0 - dr)
    V = jacobi_vandermonde(n, alpha, beta, v) * (kst * wt)[:, None]
    starts = np.concatenate([[0], np.cumsum(sizes)[:-1]])
    return h * np.add.reduceat(V, starts, axis=0)


# --------------------------------------------------------------------------
# the transforms of a solution: Cauchy transform and log potential, any exponents
# --------------------------------------------------------------------------
_Q_TRANSFORM = 28       # Gauss nodes per piece of the transforms' graded rules


def _graded_pieces(p, delta):
    """Pieces of [-1, 1] graded geometrically, ratio 4, toward the point at distance p in
    [0, 2] from -1, on the scale delta > 0: [p - delta, p + delta], then p -+ delta 4^j out
    to the ends, as offsets from that point (exact: a node next to it keeps its distance
    to it, which the integrand 1/(t - z) with Im z = 1e-9 needs to ~1e-25).  A break is
    kept only where the end beyond it is at least half the half-width of the piece it
    bounds away (else that piece reaches the end and takes the end's factor of the weight
    by Gauss-Jacobi), so that every piece sees the point z (distance delta from p) and any
    end it does not touch at a Bernstein-ellipse parameter of 2 or more (2.08 at worst:
    2.08^(-2q) < 1e-17 with q = 28 nodes).  Returns the offsets of the edges, the first
    -p (the left end), the last 2 - p (the right end)."""
    lefts, rights = [], []
    h, j = delta, 0
    while True:
        o = delta * 4.0 ** j
        if p - o <= 0.0 or p - o < 0.5 * h:
            break
        lefts.append(-o)
        h, j = 1.5 * o, j + 1
    h, j = delta, 0
    while True:
        o = delta * 4.0 ** j
        if (2.0 - p) - o <= 0.0 or (2.0 - p) - o < 0.5 * h:
            break
        rights.append(o)
        h, j = 1.5 * o, j + 1
    return [-p] + lefts[::-1] + rights + [2.0 - p]


def _graded_rule_at(p, delta, q, alpha, beta):
    """Nodes and weights of int_{-1}^{1} g(v) w(v) dv for g nearly singular at a point at
    distance delta from the point of [-1, 1] whose distance to -1 is p: the pieces of
    :func:`_graded_pieces`, Gauss-Jacobi of an end's factor on a piece that touches it
    (:func:`_piece`; both factors on the whole of [-1, 1]), Gauss-Legendre times w
    elsewhere.  Returns 1 + v, 1 - v (each from the piece's own end), v - (p - 1) (the
    offset from the point, exact next to it) and the weights."""
    edges = _graded_pieces(p, delta)
    dls, drs, offs, wts = [], [], [], []
    y, om = (np.asarray(a) for a in gauss_jacobi_cached(q, 0.0, 0.0))
    for k, (lo, hi) in enumerate(zip(edges[:-1], edges[1:])):
        first, last = k == 0, k == len(edges) - 2
        if first and last:
            x, w = gauss_jacobi_cached(q, alpha, beta)
            x = np.asarray(x)
            dl, dr, wt = 1.0 + x, 1.0 - x, np.asarray(w)
            off = dl - p
        elif last:
            dr, dl, wt = _piece(0.0, hi - lo, q, alpha, beta)
            off = hi - dr
        elif first:
            dl, dr, wt = _piece(0.0, hi - lo, q, beta, alpha)
            off = lo + dl
        else:
            h = 0.5 * (hi - lo)
            off = lo + h * (1.0 + y)
            dl = p + off
            dr = 2.0 - dl
            wt = om * h * dl ** beta * dr ** alpha
        dls.append(dl)
        drs.append(dr)
        offs.append(off)
        wts.append(wt)
    return np.concatenate(dls), np.concatenate(drs), np.concatenate(offs), np.concatenate(wts)


def weight_cauchy(zm1, zp1, alpha: float, beta: float):
    """F_0(z) = (1/pi) int_{-1}^{1} w(t)/(t - z) dt, w = (1-t)^alpha (1+t)^beta, at z off
    [-1, 1] (complex, or real outside), for any alpha, beta in (-1, 2): alpha + beta need
    not be an integer.

    ``zm1``, ``zp1``: z - 1 and z + 1 (formed from the real coordinate next to an end).  At
    abs(z) >= 2 the moments' series (:func:`sie.systems.f0_far`); nearer, a rule graded
    geometrically toward the point of [-1, 1] nearest to z on the scale of z's distance to
    it (:func:`_graded_rule_at`), in the frame of the nearer end (F_0(z; alpha, beta) =
    -F_0(-z; beta, alpha)), t - z formed from the distances to that end.  No closed form:
    with alpha + beta not an integer the weight's transform is a hypergeometric function
    whose forms at the ends degenerate where an exponent is 0 (the edge crack's mouth)."""
    from types import SimpleNamespace as _NS
    from .systems import f0_far
    zm1 = np.asarray(zm1, dtype=complex).ravel()
    zp1 = np.asarray(zp1, dtype=complex).ravel()
    z = 0.5 * (zm1 + zp1)
    out = np.empty(z.shape, dtype=complex)
    mu0 = jacobi_moment_shifted(1.0 + alpha, 1.0 + beta)
    far = np.abs(z) >= 2.0
    if far.any():
        out[far] = f0_far(_NS(alpha=alpha, beta=beta), mu0, z[far])
    for i in np.flatnonzero(~far):
        if z[i].real <= 0.0:
            zl, a, b, sign = zp1[i], alpha, beta, 1.0
        else:
            zl, a, b, sign = -zm1[i], beta, alpha, -1.0
        p = min(max(zl.real, 0.0), 2.0)
        _, _, off, wt = _graded_rule_at(p, abs(zl - p), _Q_TRANSFORM, a, b)
        out[i] = sign * np.sum(wt / (off - (zl - p))) / math.pi
    return out


def _series_pv(c, alpha, beta, v, vm1, vp1):
    """H[w sum c_k P_k](v) at real v in (-1, 1): :func:`hilbert_images` summed, H[w] from
    the distances 1 - v = -vm1, 1 + v = vp1."""
    n = c.size
    t, omega = gauss_jacobi_cached(max(n, 1), alpha, beta)
    S = _divided_sums(n, alpha, beta, v, np.asarray(t), np.asarray(omega))
    P = jacobi_vandermonde(n, alpha, beta, v)
    return (S @ c) / math.pi + (P @ c) * _weight_hilbert_dist(-vm1, vp1, alpha, beta)


def series_cauchy(c, alpha: float, beta: float, v, ends, cplx: bool):
    """(1/pi) int_{-1}^{1} w(u) sum_k c_k P_k^{(alpha,beta)}(u) / (u - v) du for any real
    alpha, beta > -1: the principal value at real v inside (:func:`hilbert_images`, exact),
    elsewhere the functions of the second kind (:func:`sie.systems.mode_cauchy_off`:
    forward from F_0 next to the interval, backward (Miller) away from it), F_0 by
    :func:`weight_cauchy`.  ``ends`` = (v - 1, v + 1) from the real coordinate; real v
    outside gives the real transform; ``cplx``: v complex (never on (-1, 1))."""
    from types import SimpleNamespace as _NS
    from .systems import mode_cauchy_off
    c = np.asarray(c, dtype=float)
    vm1, vp1 = (np.asarray(e) for e in ends)
    out = np.zeros(v.shape, dtype=complex if cplx else float)
    inside = np.zeros(v.shape, dtype=bool) if cplx else (vm1 < 0.0) & (vp1 > 0.0)
    if inside.any():
        out[inside] = _series_pv(c, alpha, beta, v[inside].real, vm1[inside].real,
                                 vp1[inside].real)
    off = ~inside
    if off.any():
        zo = np.asarray(v[off], dtype=complex)
        f0 = weight_cauchy(vm1[off], vp1[off], alpha, beta)
        mu0 = jacobi_moment_shifted(1.0 + alpha, 1.0 + beta)
        val = mode_cauchy_off(_NS(alpha=alpha, beta=beta), mu0, c, zo, f0=f0)
        out[off] = val if cplx else val.real
    return out


def series_log_potential(c, alpha: float, beta: float, vm1, vp1):
    """(1/pi) int_{-1}^{1} w(u) sum_k c_k P_k^{(alpha,beta)}(u) log abs(v - u) du at real v
    (anywhere; finite at the ends), given v - 1 and v + 1 from the real coordinate: the
    rule of :func:`_graded_rule_at` in the frame of the nearer end (the series mirrored,
    c_k -> (-1)^k c_k, alpha <-> beta, for v > 0), graded toward v on the scale of its
    distance to [-1, 1], or on v's own rounding scale where v lies on it (the log
    singularity: the piece [v - d, v + d] left to Gauss-Legendre, d ~ 8 eps (1 + v)),
    max(28, n/2 + 20) nodes a piece (phi is a polynomial of degree n - 1)."""
    c = np.asarray(c, dtype=float)
    vm1 = np.asarray(vm1, dtype=float).ravel()
    vp1 = np.asarray(vp1, dtype=float).ravel()
    q = max(_Q_TRANSFORM, c.size // 2 + 20)
    q += q % 2               # even: no node at the centre of [v - d, v + d], v itself
    mirrored = c * (-1.0) ** np.arange(c.size)
    out = np.empty(vm1.shape)
    for i in range(vm1.size):
        if vp1[i] <= -vm1[i]:                       # v <= 0: the left end's frame
            vl, a, b, cc = vp1[i], alpha, beta, c
        else:
            vl, a, b, cc = -vm1[i], beta, alpha, mirrored
        p = min(max(vl, 0.0), 2.0)
        delta = abs(vl - p)
        if delta == 0.0:
            delta = 8.0 * np.finfo(float).eps * max(p, 1e-8)
        dl, dr, off, wt = _graded_rule_at(p, delta, q, a, b)
        u = np.where(dl <= dr, dl - 1.0, 1.0 - dr)
        phi = jacobi_series(cc, a, b, u)
        out[i] = np.sum(wt * phi * np.log(np.abs(off - (vl - p)))) / math.pi
    return out


# --------------------------------------------------------------------------
# further exponents at an explicit end: extra columns of the basis
# --------------------------------------------------------------------------
_MAX_FURTHER = 8        # further exponents per end, at most
_BRANCH_TOL = 1e-17     # the innermost piece toward a further exponent's branch point holds
#                         at most this fraction of the integral (the grading's depth)
_MAX_LEVELS = 60        # geometric levels toward such an end, at most


def check_further(name: str, value):
    """``value`` as (leading exponent, further exponents): a tuple ``(e0, g1, g2, ...)`` of an
    explicit exponent e0 in (-1, 1) and further exponents of psi's expansion at that end,
    psi ~ c0 d^e0 + sum_j c_j d^g_j + ... (d the distance to the end): real or complex,
    finite, Re g_j > e0, none repeated (a complex g_j stands for itself and its conjugate;
    the one with Im g_j >= 0 is kept); else InvalidEndConditionError."""
    if not isinstance(value, tuple) or len(value) < 2:
        raise InvalidEndConditionError(
            f"{name}: further exponents are given as a tuple (e0, g1, ...) of the leading "
            f"exponent and at least one further one, got {value!r}")
    lead = check_explicit_exponent(name, value[0]) if is_explicit(value[0]) else None
    if lead is None:
        raise InvalidEndConditionError(
            f"{name} = {value!r}: the first entry of (e0, g1, ...) must be the end's leading "
            "exponent, a real number in (-1, 1) (further exponents need an explicit end)")
    rest = value[1:]
    if len(rest) > _MAX_FURTHER:
        raise InvalidEndConditionError(f"{name}: at most {_MAX_FURTHER} further exponents, "
                                       f"got {len(rest)}")
    out = []
    for g in rest:
        if isinstance(g, (bool, np.bool_, str, bytes)) or not isinstance(g, numbers.Number):
            raise InvalidEndConditionError(
                f"{name}: a further exponent must be a real or complex number, got {g!r}")
        g = complex(g)
        if not (math.isfinite(g.real) and math.isfinite(g.imag)):
            raise InvalidEndConditionError(f"{name}: a further exponent must be finite, "
                                           f"got {g!r}")
        if not g.real > lead:
            raise InvalidEndConditionError(
                f"{name}: a further exponent must have a real part above the leading "
                f"exponent {lead!r} (the expansion's later terms), got {g!r}")
        g = complex(g.real, abs(g.imag))
        if g in out:
            raise InvalidEndConditionError(
                f"{name}: the further exponent {g!r} is repeated (a complex exponent implies "
                "its conjugate: give one of the pair)")
        out.append(g)
    return lead, tuple(out)


def _expm1c(z):
    """exp(z) - 1 for complex z without cancellation for small z."""
    a, b = z.real, z.imag
    return (np.expm1(a) * np.cos(b) - 2.0 * np.sin(0.5 * b) ** 2) + 1j * np.exp(a) * np.sin(b)


def _log_ratio(num, den, diff):
    """log(num / den) (num, den real > 0 or complex off the cut) with diff = num - den given
    exactly: log1p(diff / den) where the ratio is near 1 (Kahan's form, complex too)."""
    w = diff / den
    near = np.abs(w) < 0.5
    out = np.where(near, 0j, np.log(num + 0j) - np.log(den + 0j))
    if np.any(near):
        wn = np.broadcast_to(w, out.shape)[near] + 0j
        u = 1.0 + wn
        same = u == 1.0
        lg = np.where(same, wn, np.log(u) * wn / np.where(same, 1.0, u - 1.0))
        out[near] = lg
    return out


def _levels(dmin_frac, e_sum):
    """The depth toward a branch point of exponent sum e_sum = 1 + e_near + Re r > 0: the
    first edge at (point scale) times this fraction."""
    k = math.ceil(math.log(1.0 / _BRANCH_TOL) / (e_sum * math.log(_RATIO)))
    return _RATIO ** -min(max(k, 1), _MAX_LEVELS) * dmin_frac


def _edges(dmin):
    """Distances 0, dmin, 4 dmin, ..., 1 (the last piece at least a quarter of its
    neighbour)."""
    edges = [0.0]
    e = dmin
    while e < 1.0:
        edges.append(e)
        e *= _RATIO
    edges.append(1.0)
    return edges


def further_rule(q, alpha, beta, left_min, right_min):
    """A rule for int_{-1}^{1} g(v) w(v) dv, w = (1-v)^alpha (1+v)^beta, graded geometrically
    (ratio 4) toward each end from the distance ``left_min`` / ``right_min`` (None: one piece
    on that half, Gauss-Jacobi of the end's factor): g may have a branch point at the end
    (a further exponent, (1+v)^r) and be nearly singular beyond it on the scale of the
    graded pieces.  Returns 1 + v, 1 - v (each from its own end) and the weights."""
    return _rule_on_edges(_WHOLE if left_min is None else _edges(min(left_min, 0.25)),
                          _WHOLE if right_min is None else _edges(min(right_min, 0.25)),
                          q, alpha, beta)


def _frame(end, dl, dr, alpha, beta):
    """The frame in which the further term's end is the left one: (near distances, far
    distances, exponent at the far end, at the near end, sign of the transform)."""
    return (dl, dr, alpha, beta, 1.0) if end == -1 else (dr, dl, beta, alpha, -1.0)


def further_hilbert(end, r, alpha, beta, dl_x, dr_x, rule):
    """H[e](x) = (1/pi) PV int e(t)/(t - x) dt for e = w s, s = (1+t)^r (end -1) or
    (1-t)^r (end +1), Re r > 0, at x with 1 + x = dl_x, 1 - x = dr_x: the divided
    difference of s by ``rule`` = (1 + t, 1 - t, weights), the weight's transform in closed
    form, H[e](x) = (1/pi) int w (s(t) - s(x))/(t - x) dt + s(x) H[w](x) (complex)."""
    dl_t, dr_t, wt = rule
    nl_t, nr_t, a_far, b_near, sign = _frame(end, dl_t, dr_t, alpha, beta)
    nl_x, nr_x, *_ = _frame(end, dl_x, dr_x, alpha, beta)
    # t - x in the frame, from the distances to the nearer end of each (exact next to it)
    diff = np.where(nl_t <= nr_t, nl_t - nl_x, nr_x - nr_t)
    sx = np.exp(r * np.log(nl_x))
    dd = sx * _expm1c(r * _log_ratio(nl_t, nl_x, diff))
    dd = np.where(diff == 0.0, r * sx / nl_x, dd / np.where(diff == 0.0, 1.0, diff))
    hw = _weight_hilbert_dist(np.array([nr_x]), np.array([nl_x]), a_far, b_near)[0]
    return sign * (np.sum(wt * dd) / math.pi + sx * hw)


def further_moment(end, r, alpha, beta):
    """int_{-1}^{1} w s dt = 2^{alpha+beta+r+1} B(far + 1, near + r + 1) (complex)."""
    from scipy.special import loggamma
    a_far, b_near = (alpha, beta) if end == -1 else (beta, alpha)
    return complex(np.exp((a_far + b_near + r + 1.0) * math.log(2.0) + loggamma(a_far + 1.0)
                          + loggamma(b_near + r + 1.0) - loggamma(a_far + b_near + r + 2.0)))


def further_values(end, r, u):
    """s(u) = (1+u)^r (end -1) or (1-u)^r (end +1) at local u in [-1, 1], 0 at the end."""
    d = (1.0 + u) if end == -1 else (1.0 - u)
    d = np.asarray(d, dtype=float)
    return np.where(d > 0.0, np.exp(r * np.log(np.where(d > 0.0, d, 1.0))), 0.0)


def _further_terms(further, alpha, beta):
    """[(end, r)] with r = g - (that end's exponent), one per further exponent."""
    left, right = further
    return [(-1, g - beta) for g in left] + [(1, g - alpha) for g in right]


def _branch_min(terms, end, d):
    """The grading's first edge toward ``end`` for the terms there (None if none), on the
    scale min(d, 1) of the point's distance d to it."""
    sums = [1.0 + (beta_or_alpha) + t_r.real for (e, t_r, beta_or_alpha) in terms if e == end]
    if not sums:
        return None
    return _levels(min(d, 1.0), min(sums))


def further_images(block, x_dist, terms, alpha, beta, q):
    """The complex images a e + b H[e] + h int k(x, t) e(t) dt of the further terms
    (``terms`` = [(end, r)]) at the points of local distances x_dist = (1 + x, 1 - x):
    matrix (len(x), len(terms)), by :func:`further_rule` graded toward the terms' ends
    (and toward an explicit end the kernel is singular at)."""
    dl_x, dr_x = x_dist
    iv = block.interval
    out = np.zeros((dl_x.size, len(terms)), dtype=complex)
    tagged = [(e, r, beta if e == -1 else alpha) for e, r in terms]
    graded = (is_explicit(block.left), is_explicit(block.right))
    c, d, h = iv.c, iv.d, iv.h
    for i in range(dl_x.size):
        lm = _branch_min(tagged, -1, dl_x[i])
        rm = _branch_min(tagged, 1, dr_x[i])
        if block.kernel is not None:
            if lm is None and graded[0] and dl_x[i] < 1.0:
                lm = dl_x[i]
            if rm is None and graded[1] and dr_x[i] < 1.0:
                rm = dr_x[i]
        rule = further_rule(q, alpha, beta, lm, rm)
        dl, dr, wt = rule
        ux = dl_x[i] - 1.0 if dl_x[i] <= dr_x[i] else 1.0 - dr_x[i]
        if block.kernel is not None:
            t = np.where(dl <= dr, c + h * dl, d - h * dr)
            s_pt = c + h * dl_x[i] if dl_x[i] <= dr_x[i] else d - h * dr_x[i]
            S = np.full(t.shape, s_pt)
            kst = call_checked(block.kernel, "kernel", (S, t), S.shape)
        wx = dr_x[i] ** alpha * dl_x[i] ** beta
        for j, (end, r) in enumerate(terms):
            val = block.b * further_hilbert(end, r, alpha, beta, dl_x[i], dr_x[i], rule)
            if block.a != 0.0:
                val += block.a * wx * complex(further_values(end, r, np.array([ux]))[0])
            if block.kernel is not None:
                s_t = np.exp(r * np.log(dl if end == -1 else dr))
                val += h * np.sum(kst * wt * s_t)
            out[i, j] = val
    return out


def _real_columns(M, terms):
    """The real columns of complex images: Re and Im for a complex exponent (the term
    Re((d1 - i d2) s) = d1 Re s + d2 Im s), Re alone for a real one."""
    cols = []
    for j, (_, r) in enumerate(terms):
        cols.append(M[:, j].real)
        if r.imag != 0.0:
            cols.append(M[:, j].imag)
    return np.column_stack(cols) if cols else np.zeros((M.shape[0], 0))


def _complex_coefficients(d, terms):
    """The complex coefficient of each term from the real unknowns (:func:`_real_columns`)."""
    out, k = [], 0
    for _, r in terms:
        if r.imag != 0.0:
            out.append(complex(d[k], -d[k + 1]))
            k += 2
        else:
            out.append(complex(d[k], 0.0))
            k += 1
    return tuple(out)


def further_cauchy(end, r, alpha, beta, v, ends, cplx):
    """(1/pi) int_{-1}^{1} e(u)/(u - v) du for e = w s (:func:`further_hilbert`), complex: at
    real v inside the principal value (:func:`further_hilbert`); elsewhere, in the frame of
    the term's end, (1/pi) int w (s(t) - s(v))/(t - v) dt + s(v) F_0(v) (:func:`weight_cauchy`)
    by :func:`further_rule` graded toward that end on the scale of v's distance to it, or
    for v beyond that end (Re v on the far side of it, s's branch cut) the integral itself
    by that rule.  ``ends`` = (v - 1, v + 1) from the real coordinate."""
    vm1, vp1 = (np.asarray(e).ravel() for e in ends)
    v = np.asarray(v).ravel()
    out = np.empty(v.shape, dtype=complex)
    a_far, b_near = (alpha, beta) if end == -1 else (beta, alpha)
    e_sum = 1.0 + b_near + r.real
    q = _Q_TRANSFORM
    for i in range(v.size):
        if not cplx and vm1[i].real < 0.0 < vp1[i].real:
            dl_x, dr_x = float(vp1[i].real), float(-vm1[i].real)
            dn = dl_x if end == -1 else dr_x
            lm = _levels(min(dn, 1.0), e_sum)
            rule = further_rule(q, alpha, beta, *((lm, None) if end == -1 else (None, lm)))
            out[i] = further_hilbert(end, r, alpha, beta, dl_x, dr_x, rule)
            continue
        zl = complex(vp1[i]) if end == -1 else -complex(vm1[i])      # 1 + v in the frame
        zr = -complex(vm1[i]) if end == -1 else complex(vp1[i])      # 1 - v in the frame
        dl, dr, wt = further_rule(q, a_far, b_near, _levels(min(abs(zl), 1.0), e_sum), None)
        s_t = np.exp(r * np.log(dl))
        diff = dl - zl
        if zl.real <= 0.0:
            val = np.sum(wt * s_t / diff) / math.pi
        else:
            sz = np.exp(r * np.log(zl))
            dd = sz * _expm1c(r * _log_ratio(dl, zl, diff)) / diff
            f0 = weight_cauchy(np.array([-zr]), np.array([zl]), a_far, b_near)[0]
            val = np.sum(wt * dd) / math.pi + sz * f0
        out[i] = val if end == -1 else -val
    return out


def _further_log_rule(p, delta, q, a_far, b_near, dmin):
    """Nodes and weights of int_{-1}^{1} g(v) w(v) dv in the frame of a further term's end
    (the left one, w = (1-v)^a_far (1+v)^b_near), g with a log singularity at the point at
    distance p from that end (delta: the scale, as :func:`_graded_rule_at`) and a branch
    point at the end: the pieces of :func:`_graded_pieces`, the one touching the end
    subdivided geometrically from ``dmin`` (:func:`_edges`; beyond distance 1 left to the
    far end's piece).  Returns 1 + v, the offsets v - (p - 1) and the weights."""
    edges = _graded_pieces(p, delta)
    y, om = (np.asarray(a) for a in gauss_jacobi_cached(q, 0.0, 0.0))
    dls, offs, wts = [], [], []
    for k, (lo, hi) in enumerate(zip(edges[:-1], edges[1:])):
        first, last = k == 0, k == len(edges) - 2
        if first:
            top = p + hi                                  # the piece's far edge, a distance
            cut = min(top, 1.0) if last else top
            sub = [e for e in _edges(min(dmin, 0.25)) if e < cut] + [cut]
            for a, b in zip(sub[:-1], sub[1:]):
                dl, _, wt = _piece(a, b, q, b_near, a_far)
                dls.append(dl)
                offs.append(dl - p)
                wts.append(wt)
            if last and cut < top:
                dr, dl, wt = _piece(0.0, 2.0 - cut, q, a_far, b_near)
                dls.append(dl)
                offs.append(hi - dr)
                wts.append(wt)
        elif last:
            dr, dl, wt = _piece(0.0, hi - lo, q, a_far, b_near)
            dls.append(dl)
            offs.append(hi - dr)
            wts.append(wt)
        else:
            h = 0.5 * (hi - lo)
            off = lo + h * (1.0 + y)
            dl = p + off
            dls.append(dl)
            offs.append(off)
            wts.append(om * h * dl ** b_near * (2.0 - dl) ** a_far)
    return np.concatenate(dls), np.concatenate(offs), np.concatenate(wts)


def further_log_potential(end, r, alpha, beta, vm1, vp1):
    """(1/pi) int_{-1}^{1} e(u) log abs(v - u) du for e = w s (:func:`further_hilbert`),
    complex, at real v (anywhere) given v - 1 and v + 1: :func:`_further_log_rule` in the
    frame of the term's end, graded toward v on the scale of its distance to [-1, 1] (or
    its rounding scale on it) and toward the branch point at the end."""
    a_far, b_near = (alpha, beta) if end == -1 else (beta, alpha)
    e_sum = 1.0 + b_near + r.real
    vm1 = np.asarray(vm1, dtype=float).ravel()
    vp1 = np.asarray(vp1, dtype=float).ravel()
    out = np.empty(vm1.shape, dtype=complex)
    q = _Q_TRANSFORM + (_Q_TRANSFORM % 2)
    for i in range(vm1.size):
        vl = vp1[i] if end == -1 else -vm1[i]          # 1 + v in the frame
        pp = min(max(vl, 0.0), 2.0)
        delta = abs(vl - pp)
        if delta == 0.0:
            delta = 8.0 * np.finfo(float).eps * max(pp, 1e-8)
        dmin = _levels(min(max(delta, min(pp, 1.0)), 1.0), e_sum)
        dl, off, wt = _further_log_rule(pp, delta, q, a_far, b_near, dmin)
        s = np.exp(r * np.log(dl))
        out[i] = np.sum(wt * s * np.log(np.abs(off - (vl - pp)))) / math.pi
    return out


def _terms_cauchy(terms, alpha, beta, v, ends, cplx):
    """The transform of the real terms Re(coef e) of a piece (:func:`further_cauchy`)."""
    out = np.zeros(np.shape(v), dtype=complex if cplx else float)
    for end, r, coef in terms:
        cz = further_cauchy(end, r, alpha, beta, v, ends, cplx).reshape(np.shape(v))
        if cplx:
            conj_ends = tuple(np.conj(np.asarray(e)) for e in ends)
            cc = further_cauchy(end, r, alpha, beta, np.conj(v), conj_ends, True)
            out += 0.5 * (coef * cz + np.conj(coef * cc.reshape(np.shape(v))))
        else:
            out += (coef * cz).real
    return out


# --------------------------------------------------------------------------
# the solver
# --------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class FurtherIntervalSolution(IntervalSolution):
    """An :class:`sie.IntervalSolution` whose psi carries further terms at an explicit end:
    psi = w (sum_k c_k P_k + sum_j Re(d_j s_j)), s_j = (1+u)^{r_j} (left end) or
    (1-u)^{r_j} (right end), r_j = g_j - (that end's exponent); ``terms`` = ((end, r_j, d_j),
    ...) with end -1 or +1.  :meth:`phi_local` (so psi, phi and the end values) and
    :meth:`integral` include them."""
    terms: tuple = ()
    given: tuple = ()        # the further exponents g_j as given, one per term

    def phi_local(self, u):
        out = super().phi_local(u)
        u = np.asarray(u, dtype=float)
        for end, r, coef in self.terms:
            out = out + (coef * further_values(end, r, u)).real
        return out

    def kernel_local(self, kernel, s, nodes):
        """The Jacobi part's sum (:meth:`sie.IntervalSolution.kernel_local`) plus the further
        terms' on :func:`further_rule` graded toward their end (the kernel smooth in t)."""
        out = super().kernel_local(kernel, s, nodes)
        iv = self.interval
        mins = {}
        for end, r, _ in self.terms:
            e_sum = 1.0 + (self.beta if end == -1 else self.alpha) + r.real
            mins[end] = min(mins.get(end, 1.0), _levels(1.0, e_sum))
        dl, dr, wt = further_rule(_Q_MIN, self.alpha, self.beta, mins.get(-1), mins.get(1))
        vals = np.zeros(dl.shape)
        for end, r, coef in self.terms:
            vals += (coef * np.exp(r * np.log(dl if end == -1 else dr))).real
        t = np.where(dl <= dr, iv.c + iv.h * dl, iv.d - iv.h * dr)
        S, T = np.meshgrid(s, t, indexing="ij")
        kst = call_checked(kernel, "kernel", (S, T), S.shape)
        return out + iv.h * (kst @ (wt * vals))

    def integral(self) -> float:
        extra = sum((coef * further_moment(end, r, self.alpha, self.beta)).real
                    for end, r, coef in self.terms)
        return super().integral() + float(self.interval.h * extra)


@dataclass(frozen=True, eq=False)
class FixedEndSolution(Solution):
    """A :class:`sie.Solution` of an interval with an explicit end exponent: psi, phi,
    the weight, ``integral``, ``kernel_integral``, ``endpoint_value`` (the series at the
    end) and ``condition`` as for any solution; psi at an end of exponent 0 is phi there.
    The Cauchy transform (:meth:`cauchy`), its one-sided limits on L (:meth:`cauchy_limit`)
    and the log potential (:meth:`log_potential`) for any exponents: the principal value
    by the divided differences of the basis plus P_k H[w] (:func:`hilbert_images`), off L
    the functions of the second kind from F_0 by a graded rule (:func:`series_cauchy`,
    :func:`weight_cauchy`), the log potential by a graded rule (:func:`series_log_potential`)
    (the closed forms of :mod:`sie.cauchy` need alpha + beta an integer).

    With further exponents (``left=(e0, g1, ...)``) phi, psi, the end values,
    ``integral``, ``kernel_integral`` (their terms on a rule graded toward their end), the
    Cauchy transform and the log potential include their terms (:func:`further_cauchy`,
    :func:`further_log_potential`).

    Attributes
    ----------
    pieces, a, b, intervals, alpha, beta, kappa, n, coefficients, consistency
        As for :class:`sie.Solution`; the exponent given at an end is its ``alpha`` or
        ``beta``; ``coefficients`` those of the Jacobi part.
    further : tuple
        ((end, g, d), ...): the further terms and their complex coefficients
        (:attr:`further`).

    References
    ----------
    F. Erdogan, G. D. Gupta and T. S. Cook, "Numerical solution of singular integral
    equations", in Methods of Analysis and Solutions of Crack Problems, G. C. Sih (ed.),
    Noordhoff (1973), ch. 7.

    Examples
    --------
    A smooth kernel and the exponent 0.3 given at the left end (alpha from a = b = 1 at the
    right, singular there):

    >>> import numpy as np, sie
    >>> sol = sie.solve(np.cos, a=1.0, b=1.0, n=12, left=0.3, right="singular",
    ...                 kernel=lambda s, t: 0.1 * s * t)
    >>> type(sol).__name__, sol.beta, sol.alpha
    ('FixedEndSolution', 0.3, -0.25)
    """

    def __call__(self, s):
        out = super().__call__(s)
        s = np.asarray(s, dtype=float)
        for p in self.pieces:
            for end, expo, u in ((p.interval.c, p.beta, -1.0), (p.interval.d, p.alpha, 1.0)):
                at = s == end
                if expo == 0.0 and np.any(at):
                    out = np.where(at, p.phi_local(np.array([u]))[0], out)
        return out

    def _transform_pieces(self):
        """The parts psi is the sum of (a junction solution adds its regular part)."""
        return self.pieces

    def phi(self, s):
        """psi / w at s in the closed interval: the Jacobi series plus the further terms
        at an explicit end (:attr:`further`), if any."""
        return self._on_pieces(s, lambda p, u: p.phi_local(u), "phi")

    @property
    def further(self) -> tuple:
        """The further terms of psi at its explicit end(s) (left=/right= (e0, g1, ...)):
        ((end, g, d), ...), end -1 (left) or +1 (right), g the exponent as given (Im g >=
        0), d complex: psi = w (phi + sum Re(d (1 -+ u)^(g - e0))), u the local coordinate,
        e0 that end's exponent (next to the left end the term is ~ 2^alpha Re(d
        (dist/h)^g), dist the distance to it, h the half-width); () without them."""
        out = []
        for p in self.pieces:
            for (end, _, d), g in zip(getattr(p, "terms", ()), getattr(p, "given", ())):
                out.append((end, g, d))
        return tuple(out)

    def cauchy(self, z):
        """(1/pi) int_L psi(t)/(t - z) dt: complex z off L, real z outside L (real), and the
        principal value at real z inside an interval (real).

        Each part w phi (any exponents, alpha + beta not an integer): inside, the divided
        differences of the basis plus P_k(x) H[w](x) (:func:`hilbert_images`, exact); off
        the interval the Jacobi functions of the second kind (:func:`series_cauchy`:
        :func:`sie.systems.mode_cauchy_off` from F_0 by :func:`weight_cauchy`, a rule graded
        toward z, so that points 1e-12 from L or from an end keep their accuracy).

        Parameters
        ----------
        z : array_like of float or complex
            Not at an end of an interval; a complex z not on L (Im z != 0 there).

        Returns
        -------
        ndarray of float (real z) or complex, the shape of ``z``.

        Raises
        ------
        EvaluationPointError
            z at an end, a complex z with Im z == 0 on L, non-finite z.

        References
        ----------
        F. Erdogan, G. D. Gupta and T. S. Cook (1973), ch. 7 (the splitting of H[w P_k]);
        W. Gautschi, SIAM Rev. 9 (1967) 24 (the minimal solution by backward recurrence).

        Examples
        --------
        psi = (1 + t)^0.3 (phi = 1; left=0.3, right=0.0 and f = H[w]): far away the
        transform is -(1/pi) int psi / z to O(z^-2):

        >>> import numpy as np, sie
        >>> from sie.fixed_ends import weight_hilbert
        >>> sol = sie.solve(lambda s: weight_hilbert(s, 0.0, 0.3), a=0.0, b=1.0, n=4,
        ...                 left=0.3, right=0.0)
        >>> z = 1e8
        >>> bool(abs(sol.cauchy(z) * z * np.pi + sol.integral()) < 1e-6)
        True
        """
        from .cauchy import evaluation_points
        z, cplx = evaluation_points(z, self.intervals, "z")
        flat = z.ravel()
        out = np.zeros(flat.shape, dtype=complex if cplx else float)
        for p in self._transform_pieces():
            iv = p.interval
            v, ends = iv.local(flat), iv.local_ends(flat)
            out += series_cauchy(p.coefficients, p.alpha, p.beta, v, ends, cplx)
            terms = getattr(p, "terms", ())
            if terms:
                out += _terms_cauchy(terms, p.alpha, p.beta, v, ends, cplx)
        return out.reshape(z.shape)

    def cauchy_limit(self, x, side=1):
        """C(x + i0 side), C(z) = (1/pi) int_L psi(t)/(t - z) dt, at real x: on L the
        principal value plus side i psi(x) (Plemelj), off L the real transform.

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
        >>> import numpy as np, sie
        >>> from sie.fixed_ends import weight_hilbert
        >>> sol = sie.solve(lambda s: weight_hilbert(s, 0.0, 0.3), a=0.0, b=1.0, n=4,
        ...                 left=0.3, right=0.0)
        >>> F = sol.cauchy_limit(np.array([0.5]))
        >>> bool(abs(F.imag[0] - 1.5 ** 0.3) < 1e-12)      # psi = (1 + x)^0.3
        True
        """
        from .cauchy import limit_points
        x = limit_points(x, side, self.intervals)
        return self.cauchy(x) + 1j * side * self(x)

    def log_potential(self, x, tol=None):
        """V(x) = (1/pi) int_L psi(t) log abs(x - t) dt at real x (any x; finite at the
        ends); dV/dx = -H[psi](x).

        Per part, with t = m + h u: h [(log h / pi) int w phi du + (1/pi) int w phi log
        abs(v - u) du], v = (x - m)/h, the last by a Gauss rule graded toward v and toward the
        ends (:func:`series_log_potential`; no closed form for alpha + beta not an
        integer).

        Parameters
        ----------
        x : array_like of float
        tol : float, optional
            As :meth:`sie.Solution.log_potential`'s; V is computed to rounding here
            whatever it is (no pointwise correction to sum to a lower accuracy).

        Returns
        -------
        ndarray of float, the shape of ``x``.

        Raises
        ------
        EvaluationPointError
            complex or non-finite x.

        References
        ----------
        F. Erdogan, G. D. Gupta and T. S. Cook (1973), ch. 7; N. I. Muskhelishvili, Singular
        Integral Equations (1953) (the logarithmic potential of a density on arcs).

        Examples
        --------
        psi = (1 + t)^0.3: far away V(x) = (1/pi) int psi log x + O(1/x):

        >>> import numpy as np, sie
        >>> from sie.fixed_ends import weight_hilbert
        >>> sol = sie.solve(lambda s: weight_hilbert(s, 0.0, 0.3), a=0.0, b=1.0, n=4,
        ...                 left=0.3, right=0.0)
        >>> x = 1e9
        >>> bool(abs(sol.log_potential(x) - sol.integral() * np.log(x) / np.pi) < 1e-8)
        True
        """
        x = self._real_points(x, "x")
        flat = x.ravel()
        out = np.zeros(flat.shape)
        for p in self._transform_pieces():
            iv = p.interval
            mu0 = jacobi_moment_shifted(p.exp.alpha_p1, p.exp.beta_p1)
            vm1, vp1 = iv.local_ends(flat)
            out += iv.h * (math.log(iv.h) / math.pi * mu0 * p.coefficients[0]
                           + series_log_potential(p.coefficients, p.alpha, p.beta, vm1, vp1))
            for end, r, coef in getattr(p, "terms", ()):
                mom = further_moment(end, r, p.alpha, p.beta)
                lp = further_log_potential(end, r, p.alpha, p.beta, vm1, vp1)
                out += iv.h * (coef * (math.log(iv.h) / math.pi * mom + lp)).real
        return out.reshape(x.shape)


def solve_fixed(block, f, n, total=None, breaks=(), check_residual=True, multi=False,
                stacklevel=2, further=((), ())):
    """Solve one block with an explicit end exponent by the general collocation of the
    module docstring; a :class:`FixedEndSolution`.  ``further`` = (left's, right's further
    exponents, complex, from :func:`check_further`): each adds the columns of its term
    w s (Re and Im for a complex exponent, :func:`further_images`) and as many collocation
    points."""
    if np.size(breaks):
        raise UnsupportedEquationError("breaks= is not available with an explicit end "
                                       "exponent (the general collocation has no remainder)")
    e, iv = block.exponents, block.interval
    kappa = e.kappa
    n = check_order(n, 2 if kappa == 1 else 1, "")
    if n > _N_MAX:
        raise UnsupportedEquationError(f"n = {n}: the general collocation of an explicit end "
                                       f"exponent takes at most {_N_MAX} coefficients")
    if kappa == 1:
        if total is None:
            raise SideConditionError("total (= int psi) is required when both ends are "
                                     "singular (an explicit exponent below 0 counts as "
                                     "singular)")
        total = check_finite_real("total", total, SideConditionError)
    elif total is not None:
        raise SideConditionError(f"total must not be given: the index is {kappa} (an "
                                 "explicit exponent at or above 0 counts as bounded)")
    alpha, beta = e.alpha, e.beta
    terms = _further_terms(further, alpha, beta)
    n_extra = sum(2 if r.imag != 0.0 else 1 for _, r in terms)
    m = n + n_extra - kappa
    xc = np.asarray(gauss_jacobi_cached(m, -alpha, -beta)[0])
    checks = _CHECKS if check_residual else np.empty(0)
    x = np.concatenate([xc, checks])
    dist = (1.0 + x, 1.0 - x)
    A = block.b * hilbert_images(n, alpha, beta, x)
    if block.a != 0.0:
        A += block.a * (((1.0 - x) ** alpha * (1.0 + x) ** beta)[:, None]
                        * jacobi_vandermonde(n, alpha, beta, x))
    if block.kernel is not None:
        # the corners of two explicit ends may be singular; the others must be bounded
        ends = {(iv, -1.0) for _ in [0] if is_explicit(block.left)} | \
            {(iv, 1.0) for _ in [0] if is_explicit(block.right)}
        probe_kernel([SimpleNamespace(interval=iv, kernel=block.kernel)], ends)
        q = max(_Q_MIN, n // 2 + 16)
        A += kernel_term(block.kernel, dist, iv, n, alpha, beta,
                         is_explicit(block.left), is_explicit(block.right), q)
    if terms:
        q_extra = max(_Q_MIN, n // 2 + 16)
        A = np.hstack([A, _real_columns(further_images(block, dist, terms, alpha, beta,
                                                       q_extra), terms)])
    s_real = np.where(x <= 0.0, iv.c + iv.h * dist[0], iv.d - iv.h * dist[1])
    fx = call_checked(f, "f", (s_real,), s_real.shape)
    Ac, fc = A[:m], fx[:m]
    consistency = None
    mu0 = jacobi_moment_shifted(e.alpha_p1, e.beta_p1)
    if kappa == 1:
        row = np.zeros(n + n_extra)
        row[0] = iv.h * mu0
        if terms:
            moments = np.array([[further_moment(end, r, alpha, beta)] for end, r in terms])
            row[n:] = iv.h * _real_columns(moments.T, terms)[0]
        scale = float(np.max(np.abs(Ac))) / abs(row[0])
        c = np.linalg.solve(np.vstack([scale * row, Ac]), np.concatenate([[scale * total], fc]))
        matrix = np.vstack([scale * row, Ac])
    elif kappa == 0:
        c = np.linalg.solve(Ac, fc)
        matrix = Ac
    else:
        c, *_ = np.linalg.lstsq(Ac, fc, rcond=None)
        consistency = float(np.sqrt(np.mean((Ac @ c - fc) ** 2)))
        matrix = Ac
    fscale = max(float(np.max(np.abs(fx))), np.finfo(float).tiny)
    if consistency is not None and consistency > _CONSISTENCY_TOL * fscale:
        warnings.warn(
            f"sie.solve: the collocation with an explicit end exponent is over-determined "
            f"(index -1) and its least-squares residual is {consistency:.3g} (max|f| = "
            f"{fscale:.3g}): f violates the solvability condition, or n is too small",
            InconsistentEquationWarning, stacklevel=stacklevel)
    if checks.size:
        lhs = A[m:] @ c
        r = float(np.max(np.abs(lhs - fx[m:]))) / max(fscale, float(np.max(np.abs(lhs))))
        if r > _RESIDUAL_TOL:
            warnings.warn(
                f"sie.solve: the solution leaves a residual of {r:.2g} (relative to f) in the "
                f"equation between the collocation nodes: n = {n} does not resolve f or the "
                "kernel, or the end exponents do not fit the kernel", ResidualWarning,
                stacklevel=stacklevel)
    if terms:
        coefs = _complex_coefficients(c[n:], terms)
        c = c[:n].copy()
        c.flags.writeable = False
        piece = FurtherIntervalSolution(iv, e, n, c, consistency, None, None,
                                        tuple((end, r, d) for (end, r), d in zip(terms, coefs)),
                                        tuple(further[0]) + tuple(further[1]))
        return FixedEndSolution((piece,), block.a, block.b, multi, matrix)
    c.flags.writeable = False
    piece = IntervalSolution(iv, e, n, c, consistency, None, None)
    return FixedEndSolution((piece,), block.a, block.b, multi, matrix)
