"""``make bench``: Gauss-Jacobi and SIE timings against baselines, in one run.

Writes validation/out/bench_sie.md (table).  Baseline: scipy.special.roots_jacobi
(O(n^2) eigenvalue method), timed in the same run.  Still to come (issue 3):
the gauss-jacobi-quad column, mpmath accuracy beside each time, and the
work-precision figure.
"""
from __future__ import annotations

import time
from pathlib import Path

import numpy as np
from scipy.special import roots_jacobi

import sie

OUT = Path(__file__).resolve().parent / "out"
ALPHA, BETA = -0.4, -0.6


def best_time(fn, repeat=3):
    fn()
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    rows = []
    try:
        import gauss_jacobi_quad as gjq  # bench-only extra
    except ImportError:
        gjq = None
    for n in (100, 1000, 10_000, 100_000):
        t_ours = best_time(lambda: sie.gauss_jacobi(n, ALPHA, BETA))
        x, w = sie.gauss_jacobi(n, ALPHA, BETA)
        mu0 = sie.jacobi_moment(ALPHA, BETA)
        row = {"n": n, "ours_s": t_ours, "ours_sum_err": abs(w.sum() / mu0 - 1)}
        if n <= 10_000:
            t_sc = best_time(lambda: roots_jacobi(n, ALPHA, BETA), repeat=1)
            xs, ws = roots_jacobi(n, ALPHA, BETA)
            row.update(scipy_s=t_sc, ratio=t_sc / t_ours,
                       scipy_w_vs_ours=float(np.max(np.abs(ws / w - 1))))
        rows.append(row)
    # SIE: smooth problem to 1e-12
    from validation.demo import manufactured_rhs, phi_exact
    f, e, _ = manufactured_rhs(0.7, 1.0, "bounded", "bounded")
    t_sie = best_time(lambda: sie.solve(f, a=0.7, b=1.0, n=24, left="bounded", right="bounded"), repeat=20)
    sol = sie.solve(f, a=0.7, b=1.0, n=24, left="bounded", right="bounded")
    xs = np.linspace(-0.99, 0.99, 201)
    err = float(np.max(np.abs(sol.phi(xs) - phi_exact(xs))))
    lines = ["| n | ours [ms] | Σw rel. err | scipy [ms] | scipy/ours | max|w_scipy/w_ours−1| |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['n']} | {r['ours_s']*1e3:.2f} | {r['ours_sum_err']:.1e} | "
                     f"{r.get('scipy_s', float('nan'))*1e3:.1f} | {r.get('ratio', float('nan')):.0f} | "
                     f"{r.get('scipy_w_vs_ours', float('nan')):.1e} |")
    lines.append("")
    lines.append(f"Smooth SIE (kappa = -1, n = 24): phi error {err:.1e}, {t_sie*1e3:.3f} ms warm")
    if gjq is None:
        lines.append("gauss-jacobi-quad not installed: that column is left out")
    text = "\n".join(lines)
    (OUT / "bench_sie.md").write_text(text + "\n")
    print(text)


if __name__ == "__main__":
    main()
