"""``make bench`` (contact part): what the contact solutions cost, measured in one run.

Writes validation/out/bench_contact.md.  Times are best-of-k warm wall times on this machine;
the accuracy column is against the corrected closed forms (independent oracle, verified
against mpmath quadrature in tests/test_closed_form.py).  Issue targets: four-punch numeric
solution to 1e-12 in < 1 ms warm each; a free-end custom profile to 1e-10 in < 20 ms warm; a
sweep of 1e4 (speed, friction) cases for one punch in < 10 s.
"""
from __future__ import annotations

import time
from pathlib import Path

import numpy as np

import contact
from validation.profiles import ROUNDED_FLAT_BREAKS, rounded_flat_slope, w_slope

OUT = Path(__file__).resolve().parent / "out"


def best(fn, repeat=7):
    fn()
    t = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        t = min(t, time.perf_counter() - t0)
    return t


def _sweep_row(c):
    """One speed of the 100 x 100 sweep: constants once, 100 frictions."""
    mat = contact.zhou2014()
    p = contact.CylindricalPunch(100.0)
    k = contact.surface_constants(mat, c)
    for mu in np.linspace(0.0, 0.5, 100):
        contact.solve(mat, p, load=0.01, speed=c, friction=mu, constants=k)


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    mat = contact.zhou2014()
    lines = ["# contact benchmarks", "",
             "| case | time [ms] | target | max rel. error vs closed form |", "|---|---|---|---|"]
    punches = {"flat": contact.FlatPunch(1.0), "triangular": contact.TriangularPunch(0.01),
               "parabolic": contact.ParabolicPunch(100.0), "cylindrical": contact.CylindricalPunch(100.0)}
    for name, p in punches.items():
        kw = dict(load=0.01, speed=0.6, friction=0.3)
        t = best(lambda: contact.solve(mat, p, **kw))
        r = contact.solve(mat, p, **kw)
        q = contact.solve(mat, p, method="closed_form", **kw)
        xl, xr = q.ends
        X = np.linspace(xl, xr, 41)[1:-1]
        err = max(np.max(np.abs(r.pressure(X) - q.pressure(X))) / np.max(q.pressure(X)),
                  max(abs(r.ends[0] - xl), abs(r.ends[1] - xr)) / (xr - xl))
        lines.append(f"| {name} punch, c=0.6, mu=0.3 (default n) | {t*1e3:.2f} | < 1 ms "
                     f"{'PASS' if t < 1e-3 else 'FAIL'} | {err:.1e} |")
    rflat = contact.ProfilePunch(rounded_flat_slope, breaks=ROUNDED_FLAT_BREAKS)
    w = contact.ProfilePunch(w_slope)
    for name, p, load in (("rounded flat punch (breaks), free ends", rflat, 0.05),
                          ("W profile, free ends", w, 0.2)):
        t = best(lambda: contact.solve(mat, p, load=load, speed=0.6, friction=0.3), repeat=3)
        lines.append(f"| {name} | {t*1e3:.1f} | < 20 ms {'PASS' if t < 2e-2 else 'FAIL'} | (no closed form) |")
    speeds = np.linspace(0.0, 0.9, 100)
    t0 = time.perf_counter()
    for c in speeds:
        _sweep_row(c)
    t = time.perf_counter() - t0
    lines.append(f"| sweep 1e4 (speed, friction), cylindrical, serial (constants shared per speed) "
                 f"| {t*1e3:.0f} | < 10 s {'PASS' if t < 10 else 'FAIL'} | |")
    from concurrent.futures import ProcessPoolExecutor
    t0 = time.perf_counter()
    with ProcessPoolExecutor(2) as ex:
        list(ex.map(_sweep_row, speeds))
    t = time.perf_counter() - t0
    lines.append(f"| same sweep, 2 worker processes (contact run --jobs 2) | {t*1e3:.0f} | < 10 s "
                 f"{'PASS' if t < 10 else 'FAIL'} | |")
    text = "\n".join(lines) + "\n"
    (OUT / "bench_contact.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
