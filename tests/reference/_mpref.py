"""Independent high-precision references for the Gauss-Jacobi tests.

Nothing here imports scipy or ``sie``.  The library's double-precision nodes
are used only as *starting guesses* for Newton's method; everything else is
computed from the textbook formulas below, with mpmath at ``DPS`` digits and
with exact integer arithmetic for the long three-term recurrence.

Formulas (s = alpha + beta):

* Three-term recurrence, DLMF 18.9.1 with the Jacobi coefficients of
  DLMF 18.9.2 (shifted n -> k-1), P_0 = 1, P_1 = ((s+2) x + alpha - beta)/2:

      P_k = (A_k x + B_k) P_{k-1} - C_k P_{k-2},            k >= 2,
      A_k = (2k+s-1)(2k+s) / (2k(k+s)),
      B_k = (2k+s-1)(alpha^2-beta^2) / (2k(k+s)(2k+s-2)),
      C_k = 2(k+alpha-1)(k+beta-1)(2k+s) / (2k(k+s)(2k+s-2)).

* Derivative, DLMF 18.9.16 = Szegő (4.5.7):

      (2n+s)(1-x^2) P_n'(x) = n[(alpha-beta) - (2n+s)x] P_n(x)
                              + 2(n+alpha)(n+beta) P_{n-1}(x).

* Christoffel numbers (Gauss-Jacobi weights), Szegő (15.3.5):

      w_k = C_n / ((1-x_k^2) [P_n'(x_k)]^2),
      C_n = 2^(s+1) Gamma(n+alpha+1) Gamma(n+beta+1) / (Gamma(n+s+1) n!).

* Moments: with x = 2u-1 and the Beta integral (DLMF 5.12.1)

      int_{-1}^{1} (1-x)^alpha (1+x)^beta x^k dx
          = 2^(s+1) sum_{j=0}^{k} binom(k,j) (-1)^(k-j) 2^j B(beta+j+1, alpha+1),

  in particular mu_0 = 2^(s+1) B(alpha+1, beta+1).

* Root index by a Sturm count: P_0, ..., P_m (positive leading coefficients)
  is a Sturm sequence, so the number of sign changes in P_0(x), ..., P_m(x)
  equals the number of zeros of P_m in (x, 1) (Wilkinson, The Algebraic
  Eigenvalue Problem, Ch. 5, Sturm sequence property of tridiagonal
  matrices).  At the i-th zero x_i of P_n (0-based, ascending), interlacing
  of the zeros of P_{n-1} and P_n (Szegő Thm 3.3.2) gives exactly n-1-i zeros
  of P_{n-1} above x_i.  This pins down *which* root a Newton iteration
  converged to, even when only a subset of the nodes is checked.

Speed: mpmath's ``mpf`` costs ~10 us per operation without gmpy2, far too slow
for a recurrence of length 10^4 at ~70 points.  The recurrence coefficients
are therefore formed exactly from the dyadic rationals alpha, beta (they are
doubles) and rounded once to fixed point with ``FRAC_BITS`` fractional bits;
the recurrence then runs on Python integers (~0.6 us/step).  This is plain
multiple-precision arithmetic with ~60 correct digits, checked against
mpmath's own ``mpmath.jacobi`` (hypergeometric series, an unrelated
algorithm) and a pure-``mpf`` recurrence in test_gauss_jacobi.py.  Newton
updates, weights and all Gamma functions are done in mpmath.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from fractions import Fraction

import mpmath
from mpmath import mp, mpf
from mpmath.libmp import to_fixed

DPS = 50                 # mpmath working precision (decimal digits)
FRAC_BITS = 200          # fixed-point fractional bits for the recurrence (~60 digits)
NEWTON_STOP = mpf("1e-20")   # |Newton step| below which the root is taken as x - dx
NEWTON_MAX_ITER = 8


# --------------------------------------------------------------------------
# exact recurrence coefficients in fixed point
# --------------------------------------------------------------------------
class _Coefficients:
    """A_k, B_k, C_k of DLMF 18.9.2 (k = 2..kmax) as fixed-point integers.

    alpha = pa/q, beta = pb/q exactly (q a power of two since both are doubles);
    every coefficient is a ratio of integers, rounded once (floor) to 2^-FRAC_BITS.
    """

    def __init__(self, alpha: float, beta: float):
        fa, fb = Fraction(alpha), Fraction(beta)
        q = max(fa.denominator, fb.denominator)
        self.pa = fa.numerator * (q // fa.denominator)
        self.pb = fb.numerator * (q // fb.denominator)
        self.q = q
        self.ps = self.pa + self.pb
        self.A: list[int] = []
        self.B: list[int] = []
        self.C: list[int] = []

    def upto(self, kmax: int):
        """Extend the tables to k = 2..kmax; return (A, B, C) lists (index k-2)."""
        P, q, pa, pb, ps = FRAC_BITS, self.q, self.pa, self.pb, self.ps
        dab = pa * pa - pb * pb
        A, B, C = self.A, self.B, self.C
        for k in range(len(A) + 2, kmax + 1):
            u = (2 * k - 1) * q + ps      # (2k+s-1) q
            v = 2 * k * q + ps            # (2k+s)   q
            w = k * q + ps                # (k+s)    q
            z = (2 * k - 2) * q + ps      # (2k+s-2) q
            A.append((u * v << P) // (2 * k * q * w))
            B.append((u * dab << P) // (2 * k * w * z * q))
            C.append((((k - 1) * q + pa) * ((k - 1) * q + pb) * v << P) // (k * w * z * q))
        return A, B, C

    def p1(self, xf: int) -> int:
        """P_1(x) = ((s+2) x + alpha - beta)/2 in fixed point."""
        q = self.q
        return ((self.ps + 2 * q) * xf + ((self.pa - self.pb) << FRAC_BITS)) // (2 * q)


@functools.lru_cache(maxsize=None)
def _coefficients(alpha: float, beta: float) -> _Coefficients:
    return _Coefficients(alpha, beta)


def jacobi_tail_fixed(n: int, alpha: float, beta: float, xs_fixed):
    """For each fixed-point x: (P_n, P_{n-1}, P_{n-2}) as fixed-point ints and the
    number of sign changes in P_0(x), ..., P_{n-1}(x).  P_{-1} := 0."""
    P = FRAC_BITS
    one = 1 << P
    co = _coefficients(alpha, beta)
    A, B, C = co.upto(n)
    out = []
    for xf in xs_fixed:
        p_prev, p = one, co.p1(xf)          # P_0, P_1
        pm2 = 0
        changes = 0
        for Ak, Bk, Ck in zip(A[: n - 1], B[: n - 1], C[: n - 1]):
            if (p ^ p_prev) < 0:            # sign change between P_{k-2}, P_{k-1}
                changes += 1
            pm2 = p_prev
            p_prev, p = p, ((((Ak * xf) >> P) + Bk) * p - Ck * p_prev) >> P
        # loop leaves p = P_n, p_prev = P_{n-1}, pm2 = P_{n-2} (0 for n = 1);
        # the pairs (P_0,P_1), ..., (P_{n-2},P_{n-1}) have all been counted
        out.append((p, p_prev, pm2, changes))
    return out


def _to_mpf(v: int) -> mpf:
    return mpmath.ldexp(mpf(v), -FRAC_BITS)


def _to_fixed(x: mpf) -> int:
    return to_fixed(x._mpf_, FRAC_BITS)


def jacobi_p_pair(n: int, alpha: float, beta: float, x) -> tuple[mpf, mpf]:
    """(P_n(x), P_{n-1}(x)) via the fixed-point recurrence (for self-tests)."""
    with mp.workdps(DPS):
        p, pm1, _, _ = jacobi_tail_fixed(n, alpha, beta, [_to_fixed(mpf(x))])[0]
        return _to_mpf(p), _to_mpf(pm1)


def jacobi_p_mpf(n: int, alpha: float, beta: float, x) -> mpf:
    """P_n(x) by the same DLMF 18.9.2 recurrence in plain mpmath mpf (slow; self-tests)."""
    with mp.workdps(DPS):
        a, b, x = mpf(alpha), mpf(beta), mpf(x)
        s = a + b
        p_prev, p = mpf(1), ((s + 2) * x + a - b) / 2
        if n == 0:
            return p_prev
        for k in range(2, n + 1):
            A = (2 * k + s - 1) * (2 * k + s) / (2 * k * (k + s))
            B = (2 * k + s - 1) * (a * a - b * b) / (2 * k * (k + s) * (2 * k + s - 2))
            Cc = 2 * (k + a - 1) * (k + b - 1) * (2 * k + s) / (2 * k * (k + s) * (2 * k + s - 2))
            p_prev, p = p, (A * x + B) * p - Cc * p_prev
        return p


# --------------------------------------------------------------------------
# constants
# --------------------------------------------------------------------------
def mu0(alpha: float, beta: float) -> mpf:
    """mu_0 = int (1-x)^alpha (1+x)^beta dx = 2^(s+1) Gamma(a+1)Gamma(b+1)/Gamma(a+b+2) (DLMF 5.12.1)."""
    with mp.workdps(DPS):
        a, b = mpf(alpha), mpf(beta)
        return mpf(2) ** (a + b + 1) * mpmath.beta(a + 1, b + 1)


@functools.lru_cache(maxsize=None)
def jacobi_moments(alpha: float, beta: float, kmax: int) -> tuple:
    """(m_0, ..., m_kmax), m_k = int_{-1}^1 (1-x)^alpha (1+x)^beta x^k dx (DLMF 5.12.1, binomial sum)."""
    with mp.workdps(DPS + 30):     # the alternating sum loses up to ~log10(3^k) digits
        a, b = mpf(alpha), mpf(beta)
        pref = mpf(2) ** (a + b + 1)
        betas = [mpmath.beta(b + j + 1, a + 1) for j in range(kmax + 1)]
        moms = []
        for k in range(kmax + 1):
            terms = [mpmath.binomial(k, j) * (-1) ** (k - j) * mpf(2) ** j * betas[j]
                     for j in range(k + 1)]
            moms.append(+(pref * mpmath.fsum(terms)))
    with mp.workdps(DPS):
        return tuple(+m for m in moms)


def christoffel_constant(n: int, alpha: float, beta: float) -> mpf:
    """C_n = 2^(s+1) Gamma(n+a+1) Gamma(n+b+1) / (Gamma(n+s+1) n!)  (Szegő (15.3.5))."""
    with mp.workdps(DPS):
        a, b = mpf(alpha), mpf(beta)
        return mpf(2) ** (a + b + 1) * mpmath.gammaprod([n + a + 1, n + b + 1], [n + a + b + 1, n + 1])


# --------------------------------------------------------------------------
# reference rule
# --------------------------------------------------------------------------
@dataclass
class RefNodes:
    index: list          # 0-based positions (ascending) of the checked nodes
    x: list              # refined roots of P_n (mpf)
    w: list              # Christoffel numbers at those roots (mpf)
    sturm_index: list    # root position implied by the Sturm count
    iterations: list     # Newton passes used per node
    converged: list      # bool per node


def refine_gauss_jacobi(n: int, alpha: float, beta: float, x_guess, index) -> RefNodes:
    """Refine the guesses x_guess[i] (i in index) to roots of P_n^{(alpha,beta)} by
    Newton's method, then compute the Gauss-Jacobi weights there.

    Newton step: dx = P_n / P_n' = P_n (1-x^2) / D with
    D = (1-x^2) P_n'(x) from DLMF 18.9.16 (no division by the small 1-x^2).
    Iterate until |dx| <= NEWTON_STOP; the root is then x - dx (quadratic
    convergence: error ~ |P_n''/P_n'| dx^2 < 1e-30).  The last recurrence
    values are taken at x, not at the root, so P_{n-1} is moved to the root
    by one Taylor term, P_{n-1}' again from DLMF 18.9.16 (degree n-1).
    Weight: w = C_n (1-x^2) / D^2 with D = 2(n+a)(n+b) P_{n-1} / (2n+s)
    at the root (Szegő (15.3.5) with DLMF 18.9.16, P_n = 0).
    """
    index = list(index)
    with mp.workdps(DPS):
        a, b = mpf(alpha), mpf(beta)
        s = a + b
        ab = a - b
        c2n = 2 * n + s
        knn = 2 * (n + a) * (n + b)
        m = n - 1
        c2m = 2 * m + s
        kmm = 2 * (m + a) * (m + b)
        Cn = christoffel_constant(n, alpha, beta)

        xs = [mpf(float(x_guess[i])) for i in index]
        # a non-finite or out-of-range guess is reported as "not converged"
        done = [not (mpmath.isfinite(x) and -1 < x < 1) for x in xs]
        iters = [0] * len(xs)
        result = [None] * len(xs)
        for _ in range(NEWTON_MAX_ITER):
            todo = [j for j in range(len(xs)) if not done[j]]
            if not todo:
                break
            vals = jacobi_tail_fixed(n, alpha, beta, [_to_fixed(xs[j]) for j in todo])
            for j, (pn, pm1, pm2, changes) in zip(todo, vals):
                x = xs[j]
                Pn, Pm1, Pm2 = _to_mpf(pn), _to_mpf(pm1), _to_mpf(pm2)
                omx2 = 1 - x * x
                D = (n * (ab - c2n * x) * Pn + knn * Pm1) / c2n        # (1-x^2) P_n'
                dx = Pn * omx2 / D
                iters[j] += 1
                if abs(dx) <= NEWTON_STOP:
                    # (1-x^2) P_{n-1}'(x), DLMF 18.9.16 at degree m = n-1 (P_0' = 0)
                    Dm = (m * (ab - c2m * x) * Pm1 + kmm * Pm2) / c2m if m >= 1 else mpf(0)
                    root = x - dx
                    Pm1_root = Pm1 - (Dm / omx2) * dx
                    D_root = knn * Pm1_root / c2n
                    w = Cn * (1 - root * root) / D_root ** 2
                    result[j] = (root, w, n - 1 - changes)
                    done[j] = True
                else:
                    xs[j] = x - dx
        roots, ws, sturm = [], [], []
        for j in range(len(xs)):
            if result[j] is None:
                roots.append(xs[j]); ws.append(mpf("nan")); sturm.append(-1)
            else:
                roots.append(result[j][0]); ws.append(result[j][1]); sturm.append(result[j][2])
        return RefNodes(index=index, x=roots, w=ws, sturm_index=sturm,
                        iterations=iters, converged=[r is not None for r in result])


def check_indices(n: int, n_edge: int = 25, n_interior: int = 20) -> list:
    """All indices for n <= 200; otherwise the n_edge nodes at each end plus
    n_interior spread through the interior (asymptotic methods fail at the ends)."""
    if n <= 200:
        return list(range(n))
    lo = list(range(n_edge))
    hi = list(range(n - n_edge, n))
    step = (n - 2 * n_edge) / (n_interior + 1)
    mid = sorted({n_edge + int(round(step * (i + 1))) for i in range(n_interior)})
    return lo + mid + hi
