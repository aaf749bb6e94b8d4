"""A manufactured SIE of each index, solved and checked (``python -m validation.demo``).

For each index kappa in {1, 0, -1} we pick phi(s) = exp(s)/(3 - s), build f from
the exact Cauchy transform of the Jacobi basis (Erdogan-Gupta-Cook identity,
applied to a high-degree Jacobi expansion of phi computed independently by
Gauss-Jacobi projection), solve with increasing n and print the error in phi
and the time per solve.  (``make run`` runs the default contact scene instead.)
"""
from __future__ import annotations

import math
import time

import numpy as np

import sie


def phi_exact(s):
    return np.exp(s) / (3.0 - s)


def manufactured_rhs(a, b, left, right, degree=60):
    """f = a w phi + b H[w phi] from a degree-60 Jacobi expansion of phi (exact to rounding)."""
    e = sie.sie_exponents(a, b, left, right)
    t, w = sie.gauss_jacobi(degree + 20, e.alpha, e.beta)
    h = sie.jacobi_norms(degree, e.alpha, e.beta)
    from sie.jacobi import jacobi_project
    c = jacobi_project(w * phi_exact(t), e.alpha, e.beta, t, degree) / h
    lam = -(2.0 ** (-e.kappa)) * b / e.sin
    k = e.kappa
    shifted = c[1:] if k == 1 else (c if k == 0 else np.concatenate([[0.0], c]))

    def f(s):
        return lam * sie.jacobi_series(shifted, -e.alpha, -e.beta, s)

    total = sie.jacobi_moment(e.alpha, e.beta) * c[0]
    return f, e, total


def main():
    cases = [("singular", "singular"), ("singular", "bounded"), ("bounded", "singular"),
             ("bounded", "bounded")]
    a, b = 0.7, 1.0
    xs = np.linspace(-0.99, 0.99, 201)
    print(f"SIE  a psi + (b/pi) PV int psi/(t-s) dt = f,  a = {a}, b = {b},  phi = exp(s)/(3-s)")
    print(f"{'left':>9} {'right':>9} {'kappa':>5} {'n':>4} {'max|phi err|':>13} {'time [ms]':>10}")
    for left, right in cases:
        f, e, total = manufactured_rhs(a, b, left, right)
        for n in (4, 8, 16, 32):
            kw = dict(total=total) if e.kappa == 1 else {}
            sie.solve(f, a=a, b=b, n=n, left=left, right=right, **kw)  # warm (numba compile)
            t0 = time.perf_counter()
            sol = sie.solve(f, a=a, b=b, n=n, left=left, right=right, **kw)
            dt = (time.perf_counter() - t0) * 1e3
            err = np.max(np.abs(sol.phi(xs) - phi_exact(xs)))
            print(f"{left:>9} {right:>9} {e.kappa:>5} {n:>4} {err:13.2e} {dt:10.3f}")
    print(f"exponents at a/b = {a/b}: alpha0 = {sie.sie_exponents(a, b, 'bounded', 'bounded').alpha0:.12f}"
          f"  (cot(pi alpha0) = {-a/b})")
    assert math.isfinite(err)


if __name__ == "__main__":
    main()
