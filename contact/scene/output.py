"""Writing scene results: result.json, one CSV per curve field, figures, the console table."""
from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np

import contact

from .run import CaseResult, SceneResult, _inputs_text
from .spec import _fmt


# --------------------------------------------------------------------------
# writing: result.json, CSV, PNG, the printed table
# --------------------------------------------------------------------------
def write_outputs(result: SceneResult, out_dir) -> list[Path]:
    """Write result.json, one CSV per sampled curve field and its PNG figure into
    ``out_dir`` (created if needed).  PNGs need matplotlib; without it they are skipped.

    Returns
    -------
    list of Path
        The files written.
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    written = [out / "result.json"]
    written[0].write_text(dumps_json(result.to_json()) + "\n", encoding="utf-8")
    for name in result.curve_fields:
        written.append(_write_csv(result, name, out / f"{name}.csv"))
    png = _write_figures(result, out)
    return written + png


def dumps_json(obj, indent: str = "  ", _level: int = 0) -> str:
    """JSON text with tables indented and lists of numbers on one line (readable, compact)."""
    pad, inner = indent * _level, indent * (_level + 1)
    if isinstance(obj, dict):
        if not obj:
            return "{}"
        items = [f"{inner}{json.dumps(str(k))}: {dumps_json(v, indent, _level + 1)}"
                 for k, v in obj.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(obj, (list, tuple)):
        if all(not isinstance(v, (dict, list, tuple)) for v in obj):
            return json.dumps(list(obj), allow_nan=False)
        items = [inner + dumps_json(v, indent, _level + 1) for v in obj]
        return "[\n" + ",\n".join(items) + "\n" + pad + "]"
    return json.dumps(obj, allow_nan=False)


def _write_csv(result: SceneResult, name: str, path: Path) -> Path:
    """One column per case; a single X column when every case shares its x grid."""
    curves = [res.curve(name) for res in result.cases]
    labels = [_column_label(res, result, name) for res in result.cases]
    shared = all(np.array_equal(x, curves[0][0]) for x, _ in curves)
    if shared:
        header = ["X"] + labels
        columns = [curves[0][0]] + [v for _, v in curves]
    else:
        header, columns = [], []
        for label, (x, v) in zip(labels, curves):
            header += [f"X ({label})", label]
            columns += [x, v]
    rows = max(len(c) for c in columns)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        for i in range(rows):
            w.writerow(["" if i >= len(c) or not math.isfinite(c[i]) else repr(float(c[i]))
                        for c in columns])
    return path


def _column_label(res: CaseResult, result: SceneResult, name: str) -> str:
    return res.label if result.scene.sweep else name


_AXIS_LABELS = {"pressure": "pressure p(X)", "shear": "shear traction q(X)",
                "sigma_xx": r"$\sigma_{XX}(X, 0)$"}


def _write_figures(result: SceneResult, out: Path) -> list[Path]:
    names = result.curve_fields
    if not names:
        return []
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        result.warnings.append("matplotlib is not installed: no PNG figures written "
                               "(pip install 'sie-contact[plot]')")
        return []
    written = []
    for name in names:
        fig, ax = plt.subplots(figsize=(7.0, 4.2))
        family = len(result.cases) > 1
        for res in result.cases:
            x, v = res.curve(name)
            (line,) = ax.plot(x, v, lw=1.3, label=res.label if family else None)
            if family and len(res.zones) > 1:
                _mark_zone_ends(ax, res.zones, line.get_color())
        if not family:
            _draw_zones(ax, result.cases[0].zones)
        ax.axhline(0.0, color="0.7", lw=0.6)
        ax.set_xlabel("X")
        ax.set_ylabel(_AXIS_LABELS[name])
        ax.set_title(result.scene.title)
        ax.set_ylim(*_robust_limits([res.curve(name)[1] for res in result.cases]))
        if family:
            ax.legend(fontsize=8)
        fig.tight_layout()
        path = out / f"{name}.png"
        fig.savefig(path, dpi=120)
        plt.close(fig)
        written.append(path)
    return written


def _draw_zones(ax, zones):
    """One case: a dotted line at every contact end, each zone shaded when there are several."""
    for z in zones:
        for x_end in z["ends"]:
            ax.axvline(x_end, color="0.6", ls=":", lw=0.8)
        if len(zones) > 1:
            ax.axvspan(*z["ends"], color="0.85", alpha=0.5, lw=0)


def _mark_zone_ends(ax, zones, color):
    """A family of curves: the ends of one case's zones as ticks on the axis, in its colour."""
    ends = [x for z in zones for x in z["ends"]]
    ax.plot(ends, np.zeros(len(ends)), ls="none", marker="|", ms=10, mew=1.2, color=color)


def _robust_limits(curves) -> tuple:
    """y-limits that show the curves without letting a sampled singular spike flatten them:
    the full range, unless it exceeds 4x the 1..99 percentile range."""
    v = np.concatenate([c[np.isfinite(c)] for c in curves] or [np.zeros(1)])
    if v.size == 0:
        return -1.0, 1.0
    lo, hi = float(v.min()), float(v.max())
    plo, phi = (float(q) for q in np.percentile(v, [1, 99]))
    if hi - lo > 4.0 * (phi - plo) > 0:
        lo, hi = plo, phi
    pad = 0.06 * (hi - lo) if hi > lo else max(1.0, abs(hi))
    return lo - pad, hi + pad


def format_table(result: SceneResult) -> str:
    """A short text table: one row per case with its swept inputs, ends, exponents, peak
    pressure, SIFs and sigma_XX extremes (what was requested) and the time taken.

    When a case has several contact zones, a ``zones`` column gives their number, and the ends,
    exponents and SIFs shown are those of the outer ends (result.json lists every zone)."""
    scene = result.scene
    mat = scene.material
    c_R = contact.rayleigh_speed(mat.build())
    head = [scene.title,
            f"  scene: {scene.source}",
            f"  material: {mat.preset or 'custom'} (C11, C12, C22, C33 = {mat.C11:.10g}, "
            f"{mat.C12:.10g}, {mat.C22:.10g}, {mat.C33:.10g}); Rayleigh speed c_R = {c_R:.10f}",
            f"  fixed inputs: {_inputs_text(_fixed_inputs(result))}"]
    swept = [key for _, key in scene.sweep]
    if "velocity" in swept:
        swept.append("speed")
    columns = ["case"] + swept
    rows = []
    show_zones = any(len(res.zones) != 1 for res in result.cases)
    outer = ("ends" in scene.fields or "zones" in scene.fields, "exponents" in scene.fields,
             "sif" in scene.fields)
    for res in result.cases:
        e = res.entry
        row = {"case": str(res.index)}
        row.update({k: _fmt(e["inputs"][k]) for k in swept})
        if show_zones:
            row["zones"] = str(len(res.zones))
        zones = e.get("zones") if len(res.zones) > 1 else None
        if "ends" in e:
            row["x_left"], row["x_right"] = (f"{x:.10g}" for x in e["ends"])
        elif zones and outer[0]:
            row["x_left"], row["x_right"] = (f"{x:.10g}" for x in
                                             (zones[0]["ends"][0], zones[-1]["ends"][1]))
        if "exponents" in e:
            row["alpha"], row["beta"] = (f"{x:.8g}" for x in e["exponents"])
        elif zones and outer[1]:
            row["alpha"] = f"{zones[-1]['exponents']['right']:.8g}"
            row["beta"] = f"{zones[0]['exponents']['left']:.8g}"
        if "pressure" in e:
            row["max p (sampled)"] = _extreme(e["pressure"]["values"], np.nanmax)
        sif = e.get("sif")
        if sif is None and zones and outer[2]:
            sif = {k: v for k, v in (("left", zones[0]["sif"].get("left")),
                                     ("right", zones[-1]["sif"].get("right"))) if v is not None}
        if sif is not None:
            row["K_left"] = f"{sif['left']:.6g}" if "left" in sif else "-"
            row["K_right"] = f"{sif['right']:.6g}" if "right" in sif else "-"
        if "sigma_xx" in e:
            row["min sigma_xx"] = _extreme(e["sigma_xx"]["values"], np.nanmin)
            row["max sigma_xx"] = _extreme(e["sigma_xx"]["values"], np.nanmax)
        row["time ms"] = f"{1e3 * res.time_s:.1f}"
        for k in row:
            if k not in columns:
                columns.append(k)
        rows.append(row)
    columns.remove("time ms")
    columns.append("time ms")
    widths = {k: max(len(k), *(len(r.get(k, "")) for r in rows)) for k in columns}
    lines = head + ["", "  " + "  ".join(f"{k:>{widths[k]}}" for k in columns)]
    lines += ["  " + "  ".join(f"{r.get(k, ''):>{widths[k]}}" for k in columns) for r in rows]
    if "sif" in scene.fields and any(r.get("K_left") == "-" or r.get("K_right") == "-"
                                     for r in rows):
        lines.append("  (SIF '-': that contact end is free, the pressure vanishes there)")
    if any(len(res.zones) > 1 for res in result.cases):
        lines.append("  (several zones: x_left, x_right, alpha, beta, K_left, K_right are those "
                     "of the outer ends; result.json lists every zone)")
    lines.append(f"  total time {result.timing_s:.3f} s for {len(result.cases)} case(s); units as "
                 "in the scene (stresses in the stiffness unit, lengths in the punch's unit)")
    return "\n".join(lines)


def _fixed_inputs(result: SceneResult) -> dict:
    swept = {key for _, key in result.scene.sweep}
    first = result.cases[0].entry["inputs"]
    return {k: v for k, v in first.items()
            if k not in swept and not (k == "speed" and "velocity" in swept)}


def _extreme(values, fn) -> str:
    v = np.asarray(values, dtype=float)
    if not np.any(np.isfinite(v)):
        return "-"
    return f"{fn(v) + 0.0:.6g}"
