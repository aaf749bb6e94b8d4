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
            ax.plot(x, v, lw=1.3, label=res.label if family else None)
        if not family and "ends" in result.cases[0].entry:
            for x_end in result.cases[0].entry["ends"]:
                ax.axvline(x_end, color="0.6", ls=":", lw=0.8)
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
    pressure, SIFs and sigma_XX extremes (what was requested) and the time taken."""
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
    for res in result.cases:
        e = res.entry
        row = {"case": str(res.index)}
        row.update({k: _fmt(e["inputs"][k]) for k in swept})
        if "ends" in e:
            row["x_left"], row["x_right"] = (f"{x:.10g}" for x in e["ends"])
        if "exponents" in e:
            row["alpha"], row["beta"] = (f"{x:.8g}" for x in e["exponents"])
        if "pressure" in e:
            row["max p (sampled)"] = _extreme(e["pressure"]["values"], np.nanmax)
        if "sif" in e:
            row["K_left"] = f"{e['sif']['left']:.6g}" if "left" in e["sif"] else "-"
            row["K_right"] = f"{e['sif']['right']:.6g}" if "right" in e["sif"] else "-"
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
    if "sif" in scene.fields and any(not res.entry["sif"] for res in result.cases):
        lines.append("  (SIF '-': that contact end is free, the pressure vanishes there)")
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
