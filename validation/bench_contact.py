"""``make bench`` (contact part): what the contact solutions cost, measured in one run.

Writes validation/out/bench_contact.md.  Times are the best of k warm runs in process time
(``time.process_time``: the machine is shared, and wall time counts the other processes);
the sweeps that use worker processes are wall times.  Each continuation row also gives the
ratio of its time to a baseline measured in the same run (a plain ``sie.solve`` of the same
size, or the exact face's solve), which varies much less between machines and loads than
the time itself.

Targets
-------
* the four punches of the paper through ``contact.solve``, to 1e-12 of the closed forms,
  in < 1 ms each (the single-zone solver they replaced took 0.15-0.2 ms);
* the W face H = A (X^2 - 1)^2 on [-2, 2] (mu = 0.3, c = 0.6, n = 16): one ``follow_load``
  to a load with two zones in < 10 ms; a load curve of 100 loads (log-spaced, 1e-3 P* to
  1.5 P*, through the merge at P* = 2 pi A / |N11|) in < 0.5 s;
* a cylinder tabulated at 1000 samples (``contact.samples``, no breaks), P = 0.01, in
  < 20 ms;
* a free-end custom profile to 1e-10 in < 20 ms; a sweep of 1e4 (speed, friction) cases for
  one punch in < 10 s;
* the stress field under a solved contact (cylinder, c = 0.6, mu = 0.3, n = 64): a 200 x 200
  map in < 50 ms, 1e6 points in < 0.5 s, ``stress_extrema`` in < 20 ms; the baseline is one
  Cauchy transform of the pressure at the same points (the map needs one per decaying root);
* an anisotropic material (``contact.Anisotropic``, the Stroh formalism) as fast as the
  orthotropic one it equals: the paper's material as ``Anisotropic.from_orthotropic``, a
  cylinder (R = 100, P = 0.01, c = 0.6, mu = 0.3) in <= 3 x the ``contact.Orthotropic``
  solve of the same run (its constants memoised per speed; the first solve on a fresh
  material, which finds c_L, c_R and the response, is listed as well);
* a face with kinks as fast as a smooth one (static, frictionless, isotropic E = 1,
  nu = 0.3): a flat punch with rounded corners (breaks at X = +-1, radius 50) pressed wider
  than its flat in <= 10 x the time of the cylinder of the same radius; the gap check's share
  of that solve <= 20 %; the cylinder at n = 20000 no slower than the same parabola as a
  ProfilePunch slope at n = 20000 (ratio <= 1);
* two bodies in contact: a cylinder of one isotropic material pressed on itself
  (``punch_material``) and pulled in partial slip (``tangential_load``, Cattaneo) in
  <= 5 x the sliding solve of the same pair and face.
"""
from __future__ import annotations

import math
import time
from contextlib import contextmanager
from pathlib import Path

import numpy as np

import contact
import contact.continuation
import sie
from contact.continuation import follow_load
from contact.face import Face
from contact.samples import face_from_samples
from contact.zones import Zone, ZoneEquations
from validation.profiles import ROUNDED_FLAT_BREAKS, rounded_flat_slope, w_slope

OUT = Path(__file__).resolve().parent / "out"

W_AMPLITUDE = 0.05


def best(fn, repeat=7, clock=time.process_time):
    """The shortest of ``repeat`` warm runs of fn() (one run first to warm up)."""
    fn()
    t = np.inf
    for _ in range(repeat):
        t0 = clock()
        fn()
        t = min(t, clock() - t0)
    return t


def _sweep_row(c):
    """One speed of the 100 x 100 sweep: constants once, 100 frictions."""
    mat = contact.zhou2014()
    p = contact.CylindricalPunch(100.0)
    k = contact.surface_constants(mat, c)
    for mu in np.linspace(0.0, 0.5, 100):
        contact.solve(mat, p, load=0.01, speed=c, friction=mu, constants=k)


def _w_face(mat, friction):
    """The W face H = A (X^2 - 1)^2 on [-2, 2] at c = 0.6, its equations (n = 16) and the
    frictionless merge load P* = 2 pi A / |N11|."""
    A = W_AMPLITUDE
    k = contact.surface_constants(mat, 0.6)
    face = Face(lambda X: 4 * A * X * (X * X - 1.0), extent=(-2.0, 2.0),
                height=lambda X: A * (X * X - 1.0) ** 2)
    eq = ZoneEquations(slope=face.slope, rise=face.rise, breaks=(),
                       a=k.N12 * friction if friction else 0.0, b=k.N11, load=1.0, n=16)
    return face, eq, 2.0 * math.pi * A / abs(k.N11)


def _mark(t, limit):
    return f"< {limit * 1e3:g} ms {'PASS' if t < limit else 'FAIL'}"


def continuation_rows(mat, repeat=7):
    """Rows (case, time [ms], ratio to its baseline, target) of the zone continuation."""
    rows = []
    # the four punches against one plain single-interval sie.solve of the same size
    base1 = best(lambda: sie.solve(lambda s: s, a=0.3, b=-1.0, n=6, left="singular",
                                   right="bounded"), 50)
    punches = {"flat": contact.FlatPunch(0.5), "triangular": contact.TriangularPunch(0.1),
               "parabolic": contact.ParabolicPunch(10.0),
               "cylindrical": contact.CylindricalPunch(100.0)}
    for name, p in punches.items():
        t = best(lambda: contact.solve(mat, p, load=0.02, speed=0.6, friction=0.3), 50)
        rows.append((f"{name} punch from first touch, P = 0.02, c = 0.6, mu = 0.3", t,
                     f"{t / base1:.1f} x one sie.solve (n = 6)", _mark(t, 1e-3)))
    # the W face against one two-interval sie.solve at n = 16
    face, eq, p_star = _w_face(mat, 0.3)
    zones = [Zone(-1.24, -0.67), Zone(0.68, 1.25)]
    base2 = best(lambda: sie.solve(face.slope, a=eq.a, b=eq.b, n=16, left="singular",
                                   right="bounded", intervals=[(z.c, z.d) for z in zones],
                                   check_residual=False), 20)
    P = 0.3 * p_star
    t = best(lambda: follow_load(face, eq, [P]), repeat)
    rows.append(("W face, two zones, mu = 0.3: follow_load to 0.3 P*", t,
                 f"{t / base2:.0f} x one two-interval sie.solve (n = 16)", _mark(t, 1e-2)))
    face0, eq0, _ = _w_face(mat, 0.0)
    loads = np.geomspace(1e-3 * p_star, 1.5 * p_star, 100)
    for name, f, e in (("mu = 0", face0, eq0), ("mu = 0.3", face, eq)):
        t = best(lambda: follow_load(f, e, loads), max(1, repeat // 3))
        rows.append((f"W face load curve, 100 loads 1e-3 P* .. 1.5 P* (merge), {name}", t,
                     f"{t / base2 / 100:.1f} x one two-interval sie.solve per load",
                     _mark(t, 0.5)))
    # the tabulated cylinder against the exact cylinder's solve
    X = np.linspace(-2.0, 2.0, 1000)
    sampled = face_from_samples(X, X ** 2 / 200.0, outside="tangent")
    punch = contact.ProfilePunch(sampled.slope, breaks=sampled.breaks)
    exact = contact.CylindricalPunch(100.0)
    t_exact = best(lambda: contact.solve(mat, exact, load=0.01, speed=0.6, friction=0.3), 50)
    t = best(lambda: contact.solve(mat, punch, load=0.01, speed=0.6, friction=0.3), repeat)
    rows.append(("cylinder from 1000 samples (quintic spline, no breaks), P = 0.01", t,
                 f"{t / t_exact:.0f} x the exact cylinder's solve", _mark(t, 2e-2)))
    return rows


KINK_B, KINK_R = 1.0, 50.0       # the rounded flat: flat on |X| < b, radius R beyond


def _rounded_flat_slope(X):
    X = np.asarray(X, dtype=float)
    return np.where(np.abs(X) < KINK_B, 0.0, (np.abs(X) - KINK_B) * np.sign(X) / KINK_R)


KINK_FLANK = 4.0     # ... whose flanks flatten beyond |X| = 4 (not convex: the gap is checked)


def _flanked_flat_slope(X):
    X = np.asarray(X, dtype=float)
    r = np.abs(X)
    s = np.where(r < KINK_FLANK, np.maximum(r - KINK_B, 0.0) / KINK_R,
                 (KINK_FLANK - KINK_B) / KINK_R * (0.8 + 0.2 * np.exp(KINK_FLANK - r)))
    return np.sign(X) * s


@contextmanager
def _timed(owner, name, spent):
    """Adds the process time of every call of ``owner.name`` to spent[0] while inside."""
    original = getattr(owner, name)

    def timed(*args, **kwargs):
        t0 = time.process_time()
        try:
            return original(*args, **kwargs)
        finally:
            spent[0] += time.process_time() - t0
    setattr(owner, name, timed)
    try:
        yield
    finally:
        setattr(owner, name, original)


def kink_rows(repeat=7):
    """Rows (case, time [ms], ratio to its baseline, target): a face with breaks against the
    smooth face of the same radius; the gap check's share of the solve of a face with breaks
    that is not convex (the rounded flat whose flanks flatten far out: a convex face's gap
    opens by itself and is not checked); and the cylinder at n = 20000 against the same
    parabola as a ProfilePunch slope (all in this run)."""
    mat = contact.Isotropic(1.0, 0.3)
    rounded = contact.ProfilePunch(_rounded_flat_slope, breaks=(-KINK_B, KINK_B))
    flanked = contact.ProfilePunch(_flanked_flat_slope,
                                   breaks=(-KINK_FLANK, -KINK_B, KINK_B, KINK_FLANK))
    assert rounded.as_face().opens_by_itself and not flanked.as_face().opens_by_itself
    cylinder = contact.CylindricalPunch(KINK_R)
    load = 0.05                                 # the contact reaches |X| = 2.43 > b
    kw = dict(load=load, speed=0.0, friction=0.0)
    r = contact.solve(mat, rounded, **kw)
    assert r.ends[1] - r.ends[0] > 2.0 * KINK_B, r.ends
    t_cyl = best(lambda: contact.solve(mat, cylinder, **kw), 50)
    t_kink = best(lambda: contact.solve(mat, rounded, **kw), repeat)
    rows = [(f"rounded flat punch (breaks +-{KINK_B:g}, R = {KINK_R:g}), static, P = {load:g}",
             t_kink, f"{t_kink / t_cyl:.1f} x the cylinder R = {KINK_R:g} (same load)",
             f"<= 10 x {'PASS' if t_kink <= 10.0 * t_cyl else 'FAIL'}")]
    # the gap checks (contact.continuation._gap_samples: the face's rise and the log
    # potential of p at its samples), and the log potential alone
    contact.solve(mat, flanked, **kw)           # its scan and sample grid, once per face
    shares = []
    for _ in range(repeat):
        gap, log = [0.0], [0.0]
        with _timed(contact.continuation, "_gap_samples", gap), \
                _timed(sie.Solution, "log_potential", log):
            t0 = time.process_time()
            contact.solve(mat, flanked, **kw)
            total = time.process_time() - t0
        shares.append((total, gap[0], log[0]))
    total, gap, log = min(shares)
    rows.append((f"the gap checks (the face's rise and V[p] at its samples) of the same flat "
                 f"whose flanks flatten beyond |X| = {KINK_FLANK:g} (not convex)", gap,
                 f"{gap / total:.0%} of that solve (the log potential V[p]: {log / total:.0%})",
                 f"<= 20 % {'PASS' if gap <= 0.2 * total else 'FAIL'}"))
    # n = 20000: the same parabola, exact and as a ProfilePunch slope
    parabola = contact.ProfilePunch(lambda X: X / 100.0)
    exact = contact.CylindricalPunch(100.0)
    kw = dict(load=0.01, speed=0.6, friction=0.3, n=20000)
    t_prof = best(lambda: contact.solve(mat, parabola, **kw), 1)
    t_exact = best(lambda: contact.solve(mat, exact, **kw), 1)
    rows.append(("cylinder R = 100 at n = 20000 (c = 0.6, mu = 0.3)", t_exact,
                 f"{t_exact / t_prof:.2f} x the same parabola as a ProfilePunch at n = 20000",
                 f"<= 1 x {'PASS' if t_exact <= t_prof else 'FAIL'}"))
    return rows


def subsurface_rows(mat, repeat=7):
    """Rows (case, time [ms], ratio to its baseline, target) of the field under the surface."""
    r = contact.solve(mat, contact.CylindricalPunch(1.0), load=0.1, speed=0.6, friction=0.3,
                      n=64)
    a = r.half_width
    rows = []
    for m, limit in ((200, 0.05), (1000, 0.5)):
        X, Y = np.meshgrid(np.linspace(-3 * a, 3 * a, m), np.linspace(-3 * a, -a / m, m))
        z = X - 1j * r._modes.eta_mid * Y
        base = best(lambda: r.solution.cauchy(z), max(1, repeat // 2))
        t = best(lambda: r.stress(X, Y), max(1, repeat // 2))
        rows.append((f"stress map {m} x {m} under a cylinder (n = 64, c = 0.6, mu = 0.3)", t,
                     f"{t / base:.1f} x one Cauchy transform at the same points",
                     _mark(t, limit)))
    X, Y = np.meshgrid(np.linspace(-3 * a, 3 * a, 81), np.linspace(-3 * a, 0.0, 61))
    base = best(lambda: r.stress(X, Y), repeat)
    t = best(lambda: r.stress_extrema(), repeat)
    rows.append(("stress_extrema (grid 81 x 61, then zoom polish)", t,
                 f"{t / base:.1f} x the 81 x 61 grid's stress", _mark(t, 0.02)))
    return rows


def anisotropic_rows(mat, repeat=50):
    """Rows (case, time [ms], ratio to its baseline, target): a solve on the anisotropic
    material equal to ``mat`` against the solve on ``mat`` itself."""
    aniso = contact.Anisotropic.from_orthotropic(mat, C13=4.0, C23=3.0, C33=12.0, C44=6.0,
                                                 C55=7.0)
    punch = contact.CylindricalPunch(100.0)
    kw = dict(load=0.01, speed=0.6, friction=0.3)
    base = best(lambda: contact.solve(mat, punch, **kw), repeat)
    t = best(lambda: contact.solve(aniso, punch, **kw), repeat)
    rows = [("cylinder on the paper's material as contact.Anisotropic, P = 0.01, c = 0.6, "
             "mu = 0.3", t, f"{t / base:.2f} x the contact.Orthotropic solve",
             f"<= 3 x {'PASS' if t <= 3.0 * base else 'FAIL'}")]
    C = aniso.C
    t = best(lambda: contact.solve(contact.Anisotropic(C), punch, **kw), max(1, repeat // 10))
    rows.append(("the same on a fresh contact.Anisotropic (c_L, c_R, the response)", t,
                 f"{t / base:.0f} x the contact.Orthotropic solve", "(information)"))
    return rows


def two_body_rows(repeat=20):
    """Rows (case, time [ms], ratio to its baseline, target): Cattaneo's partial slip of two
    cylinders of one material against the sliding solve of the same pair and face."""
    m = contact.Isotropic(1.0, 0.3)
    punch = contact.CylindricalPunch(1.0)
    kw = dict(load=0.01, speed=0.0, friction=0.5, punch_material=m)
    base = best(lambda: contact.solve(m, punch, **kw), repeat)
    t = best(lambda: contact.solve(m, punch, tangential_load=0.003, **kw), repeat)
    return [("two cylinders of one material, partial slip (Q / mu P = 0.6, Cattaneo)", t,
             f"{t / base:.2f} x the sliding solve of the pair",
             f"<= 5 x {'PASS' if t <= 5.0 * base else 'FAIL'}")]


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    mat = contact.zhou2014()
    lines = ["# contact benchmarks", "",
             "Process time, best of several warm runs.", "",
             "| case | time [ms] | target | max rel. error vs closed form |", "|---|---|---|---|"]
    punches = {"flat": contact.FlatPunch(1.0), "triangular": contact.TriangularPunch(0.01),
               "parabolic": contact.ParabolicPunch(100.0), "cylindrical": contact.CylindricalPunch(100.0)}
    for name, p in punches.items():
        kw = dict(load=0.01, speed=0.6, friction=0.3)
        t = best(lambda: contact.solve(mat, p, **kw), 20)
        r = contact.solve(mat, p, **kw)
        q = contact.solve(mat, p, method="closed_form", **kw)
        xl, xr = q.ends
        X = np.linspace(xl, xr, 41)[1:-1]
        err = max(np.max(np.abs(r.pressure(X) - q.pressure(X))) / np.max(q.pressure(X)),
                  max(abs(r.ends[0] - xl), abs(r.ends[1] - xr)) / (xr - xl))
        lines.append(f"| {name} punch, c=0.6, mu=0.3 (default n) | {t*1e3:.2f} | {_mark(t, 1e-3)} "
                     f"| {err:.1e} |")
    rflat = contact.ProfilePunch(rounded_flat_slope, breaks=ROUNDED_FLAT_BREAKS)
    w = contact.ProfilePunch(w_slope)
    for name, p, load in (("rounded flat punch (breaks), free ends", rflat, 0.05),
                          ("W profile, free ends", w, 0.2)):
        t = best(lambda: contact.solve(mat, p, load=load, speed=0.6, friction=0.3), repeat=3)
        lines.append(f"| {name} | {t*1e3:.1f} | {_mark(t, 2e-2)} | (no closed form) |")
    speeds = np.linspace(0.0, 0.9, 100)
    t0 = time.perf_counter()
    for c in speeds:
        _sweep_row(c)
    t = time.perf_counter() - t0
    lines.append(f"| sweep 1e4 (speed, friction), cylindrical, serial (constants shared per speed; "
                 f"wall time) | {t*1e3:.0f} | < 10 s {'PASS' if t < 10 else 'FAIL'} | |")
    from concurrent.futures import ProcessPoolExecutor
    t0 = time.perf_counter()
    with ProcessPoolExecutor(2) as ex:
        list(ex.map(_sweep_row, speeds))
    t = time.perf_counter() - t0
    lines.append(f"| same sweep, 2 worker processes (contact run --jobs 2; wall time) | "
                 f"{t*1e3:.0f} | < 10 s {'PASS' if t < 10 else 'FAIL'} | |")
    lines += ["", "## zone continuation (contact.continuation)", "",
              "| case | time [ms] | against a baseline of the same run | target |",
              "|---|---|---|---|"]
    for case, t, ratio, target in continuation_rows(mat):
        lines.append(f"| {case} | {t * 1e3:.2f} | {ratio} | {target} |")
    lines += ["", "## the stress field under the surface (ContactResult.stress)", "",
              "| case | time [ms] | against a baseline of the same run | target |",
              "|---|---|---|---|"]
    for case, t, ratio, target in subsurface_rows(mat):
        lines.append(f"| {case} | {t * 1e3:.2f} | {ratio} | {target} |")
    lines += ["", "## an anisotropic material (contact.Anisotropic)", "",
              "| case | time [ms] | against a baseline of the same run | target |",
              "|---|---|---|---|"]
    for case, t, ratio, target in anisotropic_rows(mat):
        lines.append(f"| {case} | {t * 1e3:.2f} | {ratio} | {target} |")
    lines += ["", "## faces with kinks, and large n", "",
              "| case | time [ms] | against a baseline of the same run | target |",
              "|---|---|---|---|"]
    for case, t, ratio, target in kink_rows():
        lines.append(f"| {case} | {t * 1e3:.2f} | {ratio} | {target} |")
    lines += ["", "## two bodies: an elastic punch, partial slip", "",
              "| case | time [ms] | against a baseline of the same run | target |",
              "|---|---|---|---|"]
    for case, t, ratio, target in two_body_rows():
        lines.append(f"| {case} | {t * 1e3:.2f} | {ratio} | {target} |")
    text = "\n".join(lines) + "\n"
    (OUT / "bench_contact.md").write_text(text)
    print(text)


if __name__ == "__main__":
    main()
