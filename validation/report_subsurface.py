"""Report section 10: the stress field under the surface.

* the Hertz check (isotropic, static, frictionless rigid cylinder): McEwen's closed form
  (Johnson, Contact Mechanics, 1985, eq. (4.49)), the maximum shear 0.300 p0 at 0.786 a;
* friction moving the maximum shear to the surface: Hertz pressure with q = mu p (Smith &
  Liu 1953, McEwen 1949; Johnson sec. 7.2), the coefficient mu* where the subsurface peak
  falls below the surface value mu p0;
* the rigid cylinder on the paper's orthotropic material and on an isotropic one: depth and
  value of the maximum shear against speed (up to 0.98 c_R) and friction;
* the paper's trailing-edge claim (Zhou et al. 2014, Sec. 6) re-examined with the whole
  field: where the largest tension sigma_1 is, and how it moves with mu and c.
"""
from __future__ import annotations

import numpy as np

import contact
from contact.subsurface import field_extrema, half_space_stress

from .report_doc import fmt_err, fmt_t

ISO = contact.Isotropic(1.0, 0.3)


def _hertz_core(mu, material=ISO, c=0.0):
    """The field of Hertz tractions (a = p0 = 1) with q = mu p, any material and speed."""
    return lambda X, Y: half_space_stress(material, c, X, np.minimum(Y, -1e-300),
                                          lambda z: np.sqrt(z - 1) * np.sqrt(z + 1) - z,
                                          q_ratio=mu)


def _hertz_check(doc):
    from scipy.optimize import minimize_scalar
    import time
    r = contact.solve(ISO, contact.CylindricalPunch(1.0), load=0.01, speed=0.0)
    a, p0 = r.half_width, 2 * 0.01 / (np.pi * r.half_width)
    zeta = np.linspace(0.01, 4.0, 200)
    f = r.stress(np.zeros_like(zeta), -zeta * a)
    err_z = np.max(np.abs(f.sigma_yy / p0 + 1 / np.sqrt(1 + zeta ** 2)))
    err_x = np.max(np.abs(f.sigma_xx / p0 + (1 + 2 * zeta ** 2) / np.sqrt(1 + zeta ** 2) - 2 * zeta))
    ref = minimize_scalar(lambda s: -(s - s * s / np.sqrt(1 + s * s)), bounds=(0.3, 1.5),
                          method="bounded", options={"xatol": 1e-12})
    t0 = time.perf_counter()
    e = r.stress_extrema()
    t = time.perf_counter() - t0
    doc.p("**Hertz check.** `contact.solve(Isotropic(1, 0.3), CylindricalPunch(1), load=0.01, "
          "speed=0)`, then `result.stress` on the axis against McEwen's closed form "
          "(sigma_YY = -p0/sqrt(1 + zeta^2), sigma_XX = -p0[(1 + 2 zeta^2)/sqrt(1 + zeta^2) - "
          "2 zeta], zeta = depth/a), and `result.stress_extrema()` against the maximum of "
          "tau_1 = p0 (zeta - zeta^2/sqrt(1 + zeta^2)).")
    doc.table(["quantity", "ours", "closed form", "difference"],
              [["max |sigma_YY/p0 - closed form| on the axis (200 depths)", fmt_err(err_z), "", ""],
               ["max |sigma_XX/p0 - closed form| on the axis", fmt_err(err_x), "", ""],
               ["max shear / p0", f"{e.max_shear.value / p0:.12f}", f"{-ref.fun:.12f}",
                fmt_err(abs(e.max_shear.value / p0 + ref.fun))],
               ["its depth / a", f"{e.max_shear.depth_over_a:.8f}", f"{ref.x:.8f}",
                fmt_err(abs(e.max_shear.depth_over_a - ref.x))],
               ["stress_extrema time", fmt_t(t), "", ""]])
    return e.max_shear.value / p0, e.max_shear.depth_over_a, max(err_z, err_x)


def _friction_table(doc, quick):
    from scipy.optimize import brentq
    mus = (0.0, 0.1, 0.2, 0.3, 0.35, 0.4, 0.5) if not quick else (0.0, 0.2, 0.4)
    rows, best = [], {}
    for mu in mus:
        sub = field_extrema(_hertz_core(mu), ((-1.5, 1.5), (-2.0, -1e-3)), lambda X: 1.0)
        whole = field_extrema(_hertz_core(mu), ((-1.5, 1.5), (-2.0, 0.0)), lambda X: 1.0)
        m = whole.max_shear
        best[mu] = m
        rows.append([f"{mu:g}", f"{sub.max_shear.value:.5f}", f"{sub.max_shear.X:+.4f}",
                     f"{sub.max_shear.depth:.4f}", f"{m.value:.5f}",
                     "surface" if m.Y == 0.0 else f"{m.depth:.4f}"])
    mu_star = brentq(lambda mu: field_extrema(_hertz_core(mu), ((-1.5, 1.5), (-2.0, -1e-3)),
                                              lambda X: 1.0).max_shear.value - mu,
                     0.3, 0.39, xtol=1e-10)
    doc.p("**Friction moves the maximum shear to the surface.** Hertz pressure p0 sqrt(1 - x^2/a^2) "
          "with q = mu p (the sliding cylinder of Smith & Liu 1953 / McEwen 1949, isotropic, "
          "static; a = p0 = 1; punch sliding toward -X, so the leading edge is on the left). On "
          "the surface under the contact the in-plane maximum shear is exactly mu p0 (sigma_XX - "
          "sigma_YY = -2 mu p0 X/a, sigma_XY = -mu p); below it a subsurface peak rises with mu and "
          "moves toward the leading edge and up, until at mu* it falls below mu p0.")
    doc.table(["mu", "subsurface peak / p0", "its X / a", "its depth / a",
               "largest max shear / p0", "where (depth / a)"], rows)
    doc.p(f"mu* = {mu_star:.6f} (our field's extrema; tests/contact/test_subsurface_api.py finds the "
          "same mu* to 1e-6 from McEwen's closed form by an independent maximisation). "
          "Published maps of this line contact bracket it: the peak is below the surface at "
          "mu = 0.1 and on it at mu = 0.4 (Rules of Thumb for Mechanical Engineers, 'Effect of "
          "friction on contact stress', figs. 8-9, after Smith & Liu 1953).")
    return mu_star, best


def _cylinder_sweep(doc, quick):
    speeds_frac = (0.0, 0.3, 0.6, 0.9, 0.98) if not quick else (0.0, 0.6)
    rows = []
    out = {}
    for name, mat in (("zhou2014 (orthotropic)", contact.zhou2014()), ("isotropic nu = 0.3", ISO)):
        cR = contact.rayleigh_speed(mat)
        for frac in speeds_frac:
            c = frac * cR if frac >= 0.9 else frac
            for mu in (0.0, 0.3):
                r = contact.solve(mat, contact.CylindricalPunch(100.0), load=0.01 * mat.C33 / 5.52,
                                  speed=c, friction=mu)
                X = np.linspace(*r.ends, 2001)[1:-1]
                pmax = float(np.max(r.pressure(X)))
                e = r.stress_extrema(grid=(81, 61) if not quick else (41, 31))
                ms, mt = e.max_shear, e.max_tension
                xl, xr = r.ends
                trailing = xr                           # direction -1: trailing edge on the right
                rows.append([name, f"{c:.4g}" + (f" ({frac:g} c_R)" if frac >= 0.9 else ""),
                             f"{mu:g}", f"{ms.value / pmax:.4f}",
                             "surface" if ms.Y == 0 else f"{ms.depth_over_a:.4f}",
                             f"{(ms.X - r.center) / r.half_width:+.3f}",
                             f"{mt.value / pmax:.4f}",
                             f"{(mt.X - trailing) / r.half_width:+.3f}",
                             "surface" if mt.Y == 0 else f"{mt.depth_over_a:.4f}"])
                out[(name, frac, mu)] = (ms, mt, r)
    doc.p("**A rigid cylinder (R = 100) on the paper's material and on an isotropic one**, "
          "sliding toward -X (trailing edge x_r on the right), load 0.01 (scaled by C33 / 5.52 GPa "
          "for the isotropic one): the largest in-plane maximum shear and the largest tension "
          "sigma_1 in the default region (one half-span either side, down to 3 a), both relative "
          "to the peak pressure p_max of that case. Positions: X relative to the centre (max "
          "shear) or to the trailing edge (tension) in half-widths a; depth / a.")
    doc.table(["material", "c", "mu", "max shear / p_max", "depth / a", "(X - centre) / a",
               "max tension / p_max", "(X - x_r) / a", "depth / a"], rows)
    return out


def _maps(ctx):
    import matplotlib.pyplot as plt
    mus = (0.0, 0.2, 0.4)
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8), sharey=True, layout="constrained")
    n = 121 if not ctx.quick else 61
    X, Y = np.meshgrid(np.linspace(-2, 2, n), np.linspace(-2, 0, n))
    for ax, mu in zip(axes, mus):
        f = _hertz_core(mu)(X, Y)
        cs = ax.contourf(X, -Y, f.max_shear, levels=np.linspace(0, 0.5, 21), cmap="viridis")
        ax.plot([-1, 1], [0, 0], color="k", lw=4)
        e = field_extrema(_hertz_core(mu), ((-2, 2), (-2, 0.0)), lambda X: 1.0)
        ax.plot(e.max_shear.X, e.max_shear.depth, "r*", ms=10)
        ax.set_title(f"mu = {mu:g}: max shear {e.max_shear.value:.3f} p0", fontsize=10)
        ax.set_xlabel("X / a")
        ax.invert_yaxis()
    axes[0].set_ylabel("depth -Y / a")
    fig.colorbar(cs, ax=axes, label="in-plane max shear / p0")
    fig.savefig(ctx.out / "subsurface_friction.png", dpi=110)
    plt.close(fig)
    ctx.doc.img("subsurface_friction.png", "In-plane maximum shear under Hertz tractions with "
                "q = mu p (isotropic, static; punch sliding toward -X): the peak (star) moves "
                "toward the leading edge and up as mu grows, and sits on the surface at mu = 0.4")


def _reading(out):
    """What the cylinder table shows, stated from its numbers."""
    orth = contact.zhou2014()
    N21 = contact.surface_constants(orth, 0.0).N21
    z0 = out[("zhou2014 (orthotropic)", 0.0, 0.0)][0]
    i0 = out[("isotropic nu = 0.3", 0.0, 0.0)][0]
    friction = [(k, v) for k, v in out.items() if k[2] > 0]
    at_trailing = [k for k, (ms, mt, r) in friction
                   if mt.Y == 0.0 and abs(mt.X - r.ends[1]) <= 1e-3 * r.half_width]
    lines = [
        f"On the paper's material (C11/C22 ~ 10) the frictionless static maximum shear is "
        f"{'on the surface' if z0.Y == 0 else f'at depth {z0.depth_over_a:.3f} a'} at the centre: "
        f"there sigma_XX = N21 p with N21 = {N21:.4f}, so the surface value |1 + N21| p / 2 = "
        f"{abs(1 + N21) / 2:.4f} p_max exceeds anything below (the isotropic material, N21 = -1, "
        f"has 0 there and its peak at {i0.depth_over_a:.4f} a).",
        f"With mu = 0.3 the largest tension sigma_1 lies on the surface at the trailing edge x_r in "
        f"{len(at_trailing)} of the {len(friction)} cases"
        + ("" if len(at_trailing) == len(friction) else
           " (elsewhere in: " + ", ".join(f"{k[0]} at {k[1]:g}" for k, _ in friction
                                           if k not in at_trailing) + ")")
        + ": the paper's trailing-edge claim, made from the surface sigma_XX, holds for the "
          "whole field (no subsurface point has a larger sigma_1).",
        "Without friction the tension is small and, in motion, below the surface (see the "
        "table); near c_R every stress grows relative to p_max and the maximum shear moves to "
        "the surface.",
    ]
    return "**Reading it.** " + " ".join(lines)


def section_subsurface(ctx):
    doc = ctx.doc
    doc.h("10. The stress field under the surface")
    doc.p("`ContactResult.stress(X, Y)` evaluates sigma_XX, sigma_YY, sigma_XY at any points of "
          "the half-space from the Cauchy transforms of the pressure at z_j = X - i eta_j Y over "
          "the two decaying characteristic roots (derivation in `contact.subsurface`, smooth "
          "through repeated roots); `stress_extrema` finds the largest in-plane maximum shear and "
          "the largest tension (grid, then a zoom polish). The coefficients are checked in the "
          "tests against McEwen's closed forms, the Flamant and strip loads, and a numerical "
          "Fourier inversion of the state-space solution at c up to 0.9.")
    tau, depth, err = _hertz_check(doc)
    mu_star, _ = _friction_table(doc, ctx.quick)
    _maps(ctx)
    out = _cylinder_sweep(doc, ctx.quick)
    doc.p(_reading(out))
    ctx.store["subsurface"] = {"tau": tau, "depth": depth, "axis_err": err, "mu_star": mu_star}
    ctx.headline["10"] = (f"subsurface: Hertz max shear {tau:.6f} p0 at {depth:.5f} a (closed form "
                          f"0.300283 at 0.786151; axis field to {fmt_err(err)}); friction brings "
                          f"the max shear to the surface at mu* = {mu_star:.4f} (Hertz tractions)")
