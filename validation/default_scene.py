"""The default contact scene (what ``make run`` shows): the paper's material, a cylindrical
punch sliding toward -X at c = 0.6 with mu = 0.3 (Zhou et al. 2014, Sec. 6.5, Fig. 4).

Prints a short table (ends, exponents, peak pressure, sigma_XX extremes, Rayleigh speed, time,
and the agreement with the corrected closed form) and writes
validation/out/default_scene.png (pressure and sigma_XX against X).  Issue 6 turns this into
the ``contact run`` command with TOML scenes.
"""
from __future__ import annotations

import time
from pathlib import Path

import numpy as np

import contact

OUT = Path(__file__).resolve().parent / "out"


def main(out: Path = OUT) -> dict:
    mat = contact.zhou2014()
    punch = contact.CylindricalPunch(radius=100.0)
    kw = dict(load=0.01, speed=0.6, friction=0.3, direction=-1)
    t0 = time.perf_counter()
    r = contact.solve(mat, punch, **kw)
    t_first = time.perf_counter() - t0
    t0 = time.perf_counter()
    r = contact.solve(mat, punch, **kw)
    t_warm = time.perf_counter() - t0
    q = contact.solve(mat, punch, method="closed_form", **kw)
    xl, xr = r.ends
    L = xr - xl
    X = np.linspace(xl - 0.6 * L, xr + 0.6 * L, 801)
    Xi = X[(X > xl) & (X < xr)]
    p = r.pressure(X)
    sxx = r.sigma_xx(X)
    agree = np.max(np.abs(r.pressure(Xi) - q.pressure(Xi))) / np.max(q.pressure(Xi))
    rows = [
        ("material", "Zhou et al. 2014 (C11, C12, C22, C33 = 159.7885, 5.2609, 15.4732, 5.52 GPa)"),
        ("punch", f"cylindrical, R = {punch.radius:g}"),
        ("load P, speed c, friction mu, direction", f"{kw['load']:g}, {kw['speed']:g}, {kw['friction']:g}, {kw['direction']:+d}"),
        ("Rayleigh speed c_R", f"{contact.rayleigh_speed(mat):.10f}"),
        ("N11, N12, N21, N22", ", ".join(f"{v:.6g}" for v in (r.constants.N11, r.constants.N12,
                                                            r.constants.N21, r.constants.N22))),
        ("contact ends [x_l, x_r]", f"[{xl:.12f}, {xr:.12f}]"),
        ("exponents alpha (right), beta (left)", f"{r.alpha:.12f}, {r.beta:.12f}"),
        ("peak pressure", f"{p.max():.8g} at X = {X[np.argmax(p)]:.6g}"),
        ("sigma_XX min / max (sampled)", f"{sxx.min():.6g} / {sxx.max():.6g} (tensile behind the trailing edge X > x_r)"),
        ("load check |int p - P|/P, residual", f"{r.load_check:.1e}, {r.residual:.1e}"),
        ("numeric vs corrected closed form (p)", f"{agree:.1e}"),
        ("time: first call (incl. compile) / warm", f"{t_first*1e3:.0f} ms / {t_warm*1e3:.2f} ms (n = {r.n})"),
    ]
    width = max(len(k) for k, _ in rows)
    print("\nDefault contact scene")
    for k, v in rows:
        print(f"  {k:<{width}}  {v}")
    out.mkdir(parents=True, exist_ok=True)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    ax[0].plot(X, p, "k-")
    ax[0].set_ylabel("p(X)")
    ax[0].set_title("cylindrical punch, c = 0.6, mu = 0.3, sliding toward -X")
    ax[1].plot(X, sxx, "b-")
    ax[1].axhline(0.0, color="0.7", lw=0.8)
    for x in (xl, xr):
        for a in ax:
            a.axvline(x, color="0.7", ls=":", lw=0.8)
    ax[1].set_ylabel("sigma_XX(X, 0)")
    ax[1].set_xlabel("X")
    fig.tight_layout()
    path = out / "default_scene.png"
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print(f"  figure: {path}")
    return {"ends": r.ends, "agree": agree, "png": path}


if __name__ == "__main__":
    main()
