"""Report section 11: partial slip (Cattaneo-Mindlin) and steady rolling (Carter) for a pair
whose normal and tangential problems decouple: two cylinders of one isotropic material.

References (K. L. Johnson, Contact Mechanics (1985), secs. 7.1 and 8.2; C. Cattaneo 1938,
R. D. Mindlin 1949, F. W. Carter 1926), Hertz's half-width a and p0 = 2P/(pi a):

* fretting (static, tangential load Q at constant P): the stick zone abs(x) < c,
  c/a = sqrt(1 - Q/(mu P)), and q = mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)];
* steady rolling toward -X with the tractive force Q: the stick zone [-a, -a + 2c] at the
  leading edge, the same c/a, and the creepage xi = mu (a - c)/R in magnitude: Carter's
  traction curve Q/(mu P) = 1 - (1 - xi R/(mu a))^2.

A face with no closed form (a flat punch with rounded corners, breaks at its corners) is
checked by what holds for any face: Coulomb's inequality abs(q) <= mu p with equality on the
slip zones, and int q = Q by quadrature.
"""
from __future__ import annotations

import math
import time

import numpy as np
from scipy.integrate import quad

import contact

from .profiles import ROUNDED_FLAT_BREAKS, rounded_flat_slope
from .report_doc import fmt_err, fmt_t

MAT = contact.Isotropic(1.0, 0.3)
P, MU, R = 0.01, 0.5, 1.0


def _cylinder(**kw):
    return contact.solve(MAT, contact.CylindricalPunch(R), load=P, speed=0.0, friction=MU,
                         punch_material=MAT, **kw)


def _timed(fn):
    fn()
    best = math.inf
    for _ in range(3):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return out, best


def _cattaneo_rows(ratios):
    rows = []
    for ratio in ratios:
        Q = ratio * MU * P
        r, t = _timed(lambda: _cylinder(tangential_load=Q))
        a = r.ends[1]
        c = a * math.sqrt(1.0 - ratio)
        ((c0, c1),) = [z.ends for z in r.stick_zones]
        x = a * np.linspace(-0.999, 0.999, 201)
        p0 = 2 * P / (math.pi * a)
        stick = np.where(np.abs(x) < c, (c / a) * np.sqrt(np.maximum(1 - (x / c) ** 2, 0.0)),
                         0.0)
        q_ref = MU * p0 * (np.sqrt(1 - (x / a) ** 2) - stick)
        err_q = float(np.max(np.abs(r.tangential_traction(x) - q_ref))) / (MU * p0)
        rows.append((ratio, c1 / a, c / a, max(abs(c0 + c), abs(c1 - c)) / a, err_q, t))
    return rows


def _carter_rows(ratios):
    rows = []
    for ratio in ratios:
        Q = ratio * MU * P
        r, t = _timed(lambda: _cylinder(rolling=True, tangential_load=Q))
        a = r.ends[1]
        xi_ref = MU * a / R * (1.0 - math.sqrt(1.0 - ratio))
        xi = abs(r.creepage)
        back = _cylinder(rolling=True, creepage=r.creepage)         # the curve read backwards
        rows.append((ratio, xi * R / (MU * a), xi_ref * R / (MU * a), abs(xi / xi_ref - 1),
                     abs(abs(back.tangential_load) / Q - 1), t))
    return rows


def _general_face_rows(ratios):
    """The rounded flat: Coulomb's inequality and int q = Q (no closed form)."""
    punch = contact.ProfilePunch(rounded_flat_slope, breaks=ROUNDED_FLAT_BREAKS)
    rows = []
    for ratio in ratios:
        Q = ratio * MU * P
        r, t = _timed(lambda: contact.solve(MAT, punch, load=P, speed=0.0, friction=MU,
                                            punch_material=MAT, tangential_load=Q))
        lo, hi = r.ends
        x = np.linspace(lo, hi, 2003)[1:-1]
        q, p = r.tangential_traction(x), r.pressure(x)
        excess = float(np.max(np.abs(q) - MU * p)) / (MU * float(np.max(p)))
        stick = [z.ends for z in r.stick_zones]
        slip = np.ones(x.shape, dtype=bool)
        for s0, s1 in stick:
            slip &= ~((x > s0) & (x < s1))
        equal = float(np.max(np.abs(q[slip] - MU * p[slip]))) / (MU * float(np.max(p)))
        pts = sorted({*(e for z in stick for e in z), *ROUNDED_FLAT_BREAKS} - {lo, hi})
        total = quad(lambda s: float(r.tangential_traction(s)), lo, hi,
                     points=[s for s in pts if lo < s < hi], epsabs=1e-16, epsrel=1e-13,
                     limit=400)[0]
        rows.append((ratio, (stick[0][1] - stick[0][0]) / (hi - lo), max(excess, 0.0), equal,
                     abs(total / Q - 1), t))
    return rows


def _against_closed_form(rows):
    """Table cells of rows (Q/(mu P), computed, closed form, error, error, time)."""
    return [(f"{r[0]:g}", f"{r[1]:.15f}", f"{r[2]:.15f}", fmt_err(r[3]), fmt_err(r[4]),
             fmt_t(r[5])) for r in rows]


def _figure(ctx, cat, car):
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    s = np.linspace(0.0, 1.0, 201)
    ax1.plot(s, np.sqrt(1 - s), "k-", lw=1, label="Cattaneo: sqrt(1 - Q/(mu P))")
    ax1.plot([r[0] for r in cat], [r[1] for r in cat], "o", color="C0", label="contact.solve")
    ax1.set_xlabel("Q / (mu P)")
    ax1.set_ylabel("stick half-width c / a")
    ax1.set_title("fretting: the stick zone of two cylinders")
    ax1.legend()
    xi = np.linspace(0.0, 1.0, 201)
    ax2.plot(xi, 1 - (1 - xi) ** 2, "k-", lw=1, label="Carter: 1 - (1 - xi R/(mu a))^2")
    ax2.plot([r[1] for r in car], [r[0] for r in car], "s", color="C1",
             label="contact.solve, rolling=True")
    ax2.set_xlabel("creepage xi R / (mu a)")
    ax2.set_ylabel("Q / (mu P)")
    ax2.set_title("steady rolling: the traction curve")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(ctx.out / "partial_slip.png", dpi=110)
    plt.close(fig)


def section_partial_slip(ctx):
    doc = ctx.doc
    ratios = (0.1, 0.5, 0.9) if ctx.quick else (0.05, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99)
    doc.h("11. Partial slip and rolling (a pair that decouples)")
    doc.p("Two cylinders of one isotropic material (E = 1, nu = 0.3, R = 1 the relative "
          "radius, P = 0.01, mu = 0.5): `contact.solve(..., punch_material=m, "
          "tangential_load=Q)` (fretting) and `rolling=True` (Carter), against the closed "
          "forms of Cattaneo-Mindlin and Carter (Johnson 1985, secs. 7.1, 8.2).  The pair's "
          "Dundurs beta is 0: the pressure is Hertz's and q follows from frictionless "
          "contacts at smaller loads (module `contact.partial_slip`).")
    cat = _cattaneo_rows(ratios)
    doc.table(["Q/(mu P)", "c/a computed", "c/a Cattaneo", "stick ends err / a",
               "max abs(q - q_ref) / (mu p0)", "time"], _against_closed_form(cat),
              "Fretting: the stick zone and the tangential traction (201 points).")
    car = _carter_rows(ratios)
    doc.table(["Q/(mu P)", "xi R/(mu a) computed", "Carter", "rel. err of xi",
               "Q back from xi: rel. err", "time"], _against_closed_form(car),
              "Steady rolling: the creepage for a given tractive force, and the force for "
              "that creepage (the traction curve read both ways).")
    gen = _general_face_rows(ratios[::2] if not ctx.quick else ratios[1:2])
    doc.table(["Q/(mu P)", "stick width / contact width", "max(abs q - mu p) / (mu max p)",
               "slip zones: max abs(q - mu p)", "int q / Q - 1", "time"],
              [(f"{r[0]:g}", f"{r[1]:.6f}", fmt_err(r[2]), fmt_err(r[3]), fmt_err(r[4]),
                fmt_t(r[5])) for r in gen],
              "A face with no closed form: the flat punch with rounded corners of "
              "validation/profiles.py (flat on abs(X) <= 1, radius 50 beyond, breaks at the "
              "corners).")
    _figure(ctx, cat, car)
    doc.img("partial_slip.png", "Left: the stick zone against Q/(mu P), computed (dots) and "
            "Cattaneo's. Right: Carter's traction curve, computed (squares) and closed form.")
    worst_c = max(max(r[3], r[4]) for r in cat)
    worst_r = max(max(r[3], r[4]) for r in car)
    worst_g = max(max(r[2], r[3], r[4]) for r in gen)
    ctx.store["partial_slip"] = dict(cattaneo=worst_c, carter=worst_r, general=worst_g)
    ctx.headline["11"] = (f"Cattaneo's stick zone and traction to {fmt_err(worst_c)}, Carter's "
                          f"creepage to {fmt_err(worst_r)} for Q/(mu P) in "
                          f"[{ratios[0]:g}, {ratios[-1]:g}]; a rounded flat keeps Coulomb's "
                          f"law and int q = Q to {fmt_err(worst_g)}.")
