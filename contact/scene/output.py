"""Writing scene results: result.json, sweep.csv (:mod:`contact.scene.table`), one CSV per
curve field, figures, the console table; with the ``"subsurface"`` field also subsurface.npz,
subsurface.csv and two contour maps."""
from __future__ import annotations

import csv
import itertools
import json
import math
from pathlib import Path

import numpy as np

import contact

from .run import SUBSURFACE_QUANTITIES, CaseResult, SceneResult, _inputs_text, progress_bar
from .spec import SUBSURFACE_CUT, _fmt

#: The subsurface figures show at most this many cases (small multiples); a longer sweep shows
#: this many, evenly spaced through it (first and last included), and says so in the title.
SUBSURFACE_PANELS = 6


# --------------------------------------------------------------------------
# writing: result.json, CSV, PNG, the printed table
# --------------------------------------------------------------------------
def write_outputs(result: SceneResult, out_dir, *, figures: bool | None = None,
                  progress: bool = False) -> list[Path]:
    """Write result.json, sweep.csv, one CSV per sampled curve field and its PNG figure into
    ``out_dir`` (created if needed).  PNGs need matplotlib; without it they are skipped.

    With the ``"subsurface"`` field: subsurface.npz and subsurface.csv (the maps, see
    :func:`write_subsurface_npz` and :func:`write_subsurface_csv`), and the contour maps
    subsurface_max_shear.png and subsurface_sigma_xx.png (:func:`_write_subsurface_figures`).

    Parameters
    ----------
    figures : bool, optional
        Write the PNG figures; None: as the scene says (``[outputs] figures``, default true).
    progress : bool
        Show a tqdm bar (on stderr) over the files while they are written, if that takes
        longer than half a second.

    Returns
    -------
    list of Path
        The files written.
    """
    from .table import write_sweep_csv
    if figures is None:
        figures = result.scene.figures
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    maps = "subsurface" in result.scene.fields
    steps = [("result.json", lambda: _write_json(result, out / "result.json")),
             ("sweep.csv", lambda: write_sweep_csv(result, out / "sweep.csv"))]
    steps += [(f"{name}.csv", lambda name=name: _write_csv(result, name, out / f"{name}.csv"))
              for name in result.curve_fields]
    if maps:
        steps += [("subsurface.npz",
                   lambda: write_subsurface_npz(result, out / "subsurface.npz")),
                  ("subsurface.csv",
                   lambda: write_subsurface_csv(result, out / "subsurface.csv"))]
    if figures:
        steps += [(f"{name}.png", lambda name=name: _write_figures(result, out, [name]))
                  for name in result.curve_fields]
        if maps:
            steps.append(("subsurface_*.png", lambda: _write_subsurface_figures(result, out)))
    written = []
    immediate = len(result.cases) > 100
    bar = _writing_bar(len(steps), progress, immediate)
    try:
        for name, step in steps:
            bar.set_postfix_str(name, refresh=immediate)
            paths = step()
            written += paths if isinstance(paths, list) else [paths]
            bar.update(1)
    finally:
        bar.close()
    return written


def _write_json(result: SceneResult, path: Path) -> Path:
    path.write_text(dumps_json(result.to_json()) + "\n", encoding="utf-8")
    return path


def _writing_bar(total: int, progress: bool, immediate: bool = False):
    """The second phase of ``contact run``'s progress: the files being written (shown at once
    for a long sweep, whose result.json alone takes seconds; otherwise after half a second)."""
    return progress_bar(total, progress, "writing outputs", "file", 0 if immediate else 0.5)


def check_out_dir(out_dir) -> None:
    """Raise OSError, before anything is solved, when ``out_dir`` cannot receive the outputs:
    it exists and is not a directory, or it (or, when it does not exist yet, its nearest
    existing parent) is not writable.  Nothing is created."""
    out = Path(out_dir)
    if out.exists():
        if not out.is_dir():
            raise OSError(f"{out} exists and is not a directory")
        try:                                   # os.access is not enough (root, ACLs, ...)
            import tempfile
            with tempfile.TemporaryFile(dir=out, prefix=".contact-write-check"):
                pass
        except OSError as exc:
            raise OSError(f"{out} is not writable ({exc.strerror or exc})") from None
        return
    parent = out.absolute().parent
    while not parent.exists():
        parent = parent.parent
    if not parent.is_dir():
        raise OSError(f"{out} cannot be created: {parent} is not a directory")
    import os
    if not os.access(parent, os.W_OK | os.X_OK):
        raise OSError(f"{out} cannot be created: {parent} is not writable")


# --------------------------------------------------------------------------
# the field under the surface: subsurface.npz, subsurface.csv, contour maps
# --------------------------------------------------------------------------
def write_subsurface_npz(result: SceneResult, path: Path) -> Path:
    """subsurface.npz: the maps of every case (``numpy.load(path)``; no pickles).

    Keys
    ----
    ``cases`` : int array, the case indices (as in result.json); ``labels`` : str array, their
    labels; and for each case ``i``:

    * ``case{i}/x`` (nx,) and ``case{i}/y`` (ny,): the grid's X and Y (Y <= 0, increasing: the
      last row is the top, Y = 0 the surface);
    * ``case{i}/sigma_xx``, ``case{i}/sigma_yy``, ``case{i}/sigma_xy``, ``case{i}/max_shear``,
      ``case{i}/max_tension``: (ny, nx) arrays, ``[k, j]`` at (x[j], y[k]), tension positive,
      in the scene's stress unit S; NaN only where a singular (corner) contact end meets the
      surface (the stresses are infinite there).
    """
    arrays = {"cases": np.array([res.index for res in result.cases], dtype=int),
              "labels": np.array([res.label for res in result.cases], dtype=str)}
    for res in result.cases:
        m = res.subsurface
        arrays[f"case{res.index}/x"] = m.x
        arrays[f"case{res.index}/y"] = m.y
        for name in SUBSURFACE_QUANTITIES:
            arrays[f"case{res.index}/{name}"] = m.quantity(name)
    np.savez(path, **arrays)
    return path


def write_subsurface_csv(result: SceneResult, path: Path) -> Path:
    """subsurface.csv, long format: a header ``case, X, Y, sigma_xx, sigma_yy, sigma_xy,
    max_shear, max_tension`` and one row per grid point of every case (case by case, then Y
    increasing, X increasing within a row of the grid); an empty cell where the map is NaN
    (a singular contact end on the surface)."""
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(("case", "X", "Y") + SUBSURFACE_QUANTITIES)
        for res in result.cases:
            m = res.subsurface
            X, Y = np.meshgrid(m.x, m.y)
            cols = [X, Y] + [m.quantity(name) for name in SUBSURFACE_QUANTITIES]
            table = np.column_stack([c.ravel() for c in cols])
            rows = [[res.index] + r for r in table.tolist()]
            for k in np.flatnonzero(~np.all(np.isfinite(table), axis=1)).tolist():
                rows[k] = [res.index] + ["" if not math.isfinite(v) else v
                                         for v in table[k].tolist()]
            w.writerows(rows)
    return path


_MAP_LABELS = {"max_shear": "max shear (S)", "sigma_xx": r"$\sigma_{XX}$ (S)"}
_MAP_MARKS = {"max_shear": ("max_shear", "max shear"), "sigma_xx": ("max_tension",
                                                                    r"max tension $\sigma_1$")}


def _subsurface_shown(cases) -> list:
    """The cases the subsurface figures show: all, or SUBSURFACE_PANELS evenly spaced."""
    if len(cases) <= SUBSURFACE_PANELS:
        return list(cases)
    picks = np.unique(np.round(np.linspace(0, len(cases) - 1, SUBSURFACE_PANELS)).astype(int))
    return [cases[k] for k in picks]


def _write_subsurface_figures(result: SceneResult, out: Path) -> list[Path]:
    """subsurface_max_shear.png and subsurface_sigma_xx.png: filled contours of each shown case
    (small multiples, one shared colour bar, at most SUBSURFACE_PANELS cases), the surface at
    the top, each contact zone a thick segment on it and the extremum marked (the largest max
    shear; on the sigma_XX map the largest tension sigma_1)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.ticker import MaxNLocator
    except ImportError:
        if not result.curve_fields:          # otherwise _write_figures has said so
            result.warnings.append("matplotlib is not installed: no PNG figures written "
                                   "(pip install 'sie-contact[plot]')")
        return []
    shown = _subsurface_shown(result.cases)
    n = len(shown)
    title = result.scene.title
    if n < len(result.cases):
        title += (f"\n{n} of {len(result.cases)} cases shown (evenly spaced; subsurface.npz "
                  "has all)")
    ncols = min(n, 3)
    nrows = -(-n // ncols)
    written = []
    for name in ("max_shear", "sigma_xx"):
        maps = [res.subsurface.quantity(name) for res in shown]
        lo, hi = _robust_limits(maps, pad=False)
        if name == "sigma_xx":
            top = max(abs(lo), abs(hi)) or 1.0
            lo, hi, cmap = -top, top, "RdBu_r"
        else:
            lo, hi, cmap = 0.0, (hi if hi > 0 else 1.0), "viridis"
        full = np.concatenate([m[np.isfinite(m)] for m in maps] or [np.zeros(1)])
        levels = MaxNLocator(nbins=20).tick_values(lo, hi)
        lo, hi = levels[0], levels[-1]
        extend = {(False, False): "neither", (True, False): "min", (False, True): "max",
                  (True, True): "both"}[(bool(full.size and full.min() < lo),
                                         bool(full.size and full.max() > hi))]
        # a fixed layout (no layout engine: constrained layout would double the time)
        pw, ph = (5.0, 3.8) if n == 1 else (3.3, 2.9)          # one panel's box, inches
        width, height = 1.5 + pw * ncols, (1.0 if n < len(result.cases) else 0.8) + ph * nrows
        left, right = 0.75 / width, 1.0 - 1.3 / width
        bottom, top = 0.55 / height, 1.0 - (0.75 if n < len(result.cases) else 0.55) / height
        fig, axes = plt.subplots(nrows, ncols, figsize=(width, height), squeeze=False,
                                 gridspec_kw=dict(left=left, right=right, bottom=bottom, top=top,
                                                  wspace=0.25, hspace=0.45))
        quantity, mark_label = _MAP_MARKS[name]
        for k, ax in enumerate(axes.flat):
            if k >= n:
                ax.set_axis_off()
                continue
            res = shown[k]
            m = res.subsurface
            cs = ax.contourf(m.x, m.y, maps[k], levels=levels, cmap=cmap, extend=extend)
            for z in res.zones:
                ax.plot(z["ends"], [0.0, 0.0], color="k", lw=4, solid_capstyle="butt",
                        clip_on=False, zorder=5, label="contact" if k == 0 and z is res.zones[0]
                        else None)
            e = res.entry["subsurface"][quantity]
            ax.plot([e["X"]], [e["Y"]], ls="none", marker="X", ms=8, mfc="w", mec="k",
                    zorder=6, clip_on=False, label=mark_label if k == 0 else None)
            ax.set_xlim(m.x[0], m.x[-1])
            ax.set_ylim(m.y[0], m.y[-1])
            ratio = (m.y[-1] - m.y[0]) / (m.x[-1] - m.x[0])
            if 0.2 <= ratio <= 5.0:
                ax.set_aspect("equal")
            if len(result.cases) > 1:
                ax.set_title(f"case {res.index}: {res.label}", fontsize=8)
            if k % ncols == 0:
                ax.set_ylabel("Y (L)")
            if k // ncols == nrows - 1 or k + ncols >= n:
                ax.set_xlabel("X (L)")
            ax.xaxis.set_major_locator(MaxNLocator(5))         # few ticks: each costs time
            ax.yaxis.set_major_locator(MaxNLocator(4))
            ax.tick_params(labelsize=8)
            if k == 0:
                ax.legend(fontsize=7, loc="lower right", framealpha=0.8)
        cax = fig.add_axes((right + 0.25 / width, bottom, 0.15 / width, top - bottom))
        ticks = MaxNLocator(6).tick_values(lo, hi)
        ticks = ticks[(ticks >= lo - 1e-9 * (hi - lo)) & (ticks <= hi + 1e-9 * (hi - lo))]
        cbar = fig.colorbar(cs, cax=cax, ticks=ticks)
        cbar.set_label(_MAP_LABELS[name])
        fig.suptitle(title, fontsize=10)
        path = out / f"subsurface_{name}.png"
        fig.savefig(path, dpi=100)
        plt.close(fig)
        written.append(path)
    return written


_CONTAINERS = frozenset((dict, list, tuple))


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
        if not _CONTAINERS.intersection(map(type, obj)):     # numbers (strings) only
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
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        w.writerows(itertools.zip_longest(*(_cells(c) for c in columns), fillvalue=""))
    return path


def _cells(values: np.ndarray) -> list:
    """CSV cells of a column: repr of each number, empty where it is not finite."""
    v = np.asarray(values, dtype=float)
    cells = [repr(x) for x in v.tolist()]
    for k in np.flatnonzero(~np.isfinite(v)).tolist():
        cells[k] = ""
    return cells


def _column_label(res: CaseResult, result: SceneResult, name: str) -> str:
    return res.label if result.scene.sweep else name


_AXIS_LABELS = {"pressure": "pressure p(X)", "shear": "shear traction q(X)",
                "sigma_xx": r"$\sigma_{XX}(X, 0)$"}
#: Units of the quantities in the figures (UNITS: stresses S, lengths L).
_CURVE_UNIT = "S"
_INPUT_UNITS = {"load": "S L", "radius": "L", "half_width": "L"}
#: A sweep's curve figures draw at most this many cases (evenly spaced through the sweep,
#: first and last included; the title says so).
MAX_CURVES = 200
#: A swept input with at most this many distinct values gets a discrete colour bar.
DISCRETE_COLOURS = 12
_LINESTYLES = ("-", "--", ":", "-.")


def _shown_cases(cases, most: int) -> list:
    if len(cases) <= most:
        return list(cases)
    picks = np.unique(np.round(np.linspace(0, len(cases) - 1, most)).astype(int))
    return [cases[k] for k in picks]


def _input_label(key: str) -> str:
    unit = _INPUT_UNITS.get(key)
    return f"{key} ({unit})" if unit else key


def _write_figures(result: SceneResult, out: Path, names=None) -> list[Path]:
    """One PNG per curve field (``names``, default all the scene's).

    One case: its curve, the contact ends dotted (the zones shaded when there are several).
    A sweep: a family of curves (one LineCollection) coloured by the first swept input, with
    a colour bar (viridis; discrete ticks at its values when it takes few); a second swept
    input with at most 4 values is told apart by line style (legend), a further one is named
    in the title; the ends of every zone of a case with several are ticks on the axis in its
    colour.  At most :data:`MAX_CURVES` cases are drawn (evenly spaced; the title says so).
    """
    names = result.curve_fields if names is None else names
    if not names:
        return []
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        message = ("matplotlib is not installed: no PNG figures written "
                   "(pip install 'sie-contact[plot]')")
        if message not in result.warnings:
            result.warnings.append(message)
        return []
    written = []
    for name in names:
        fig = curve_figure(result, name)
        path = out / f"{name}.png"
        fig.savefig(path, dpi=120)
        plt.close(fig)
        written.append(path)
    return written


def curve_figure(result: SceneResult, name: str):
    """The matplotlib figure of one curve field (see :func:`_write_figures`); the caller
    closes it."""
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7.5, 4.5), layout="constrained")
    if len(result.cases) > 1 and result.scene.sweep:
        title = _draw_family(fig, ax, result, name)
    else:
        res = result.cases[0]
        x, v = res.curve(name)
        ax.plot(x, v, lw=1.3, color="C0")
        _draw_zones(ax, res.zones)
        ax.set_ylim(*_robust_limits([v]))
        title = result.scene.title
    ax.axhline(0.0, color="0.7", lw=0.6, zorder=0)
    ax.set_xlabel("X (L)")
    ax.set_ylabel(f"{_AXIS_LABELS[name]} ({_CURVE_UNIT})")
    ax.set_title(title, fontsize=10)
    return fig


def _draw_family(fig, ax, result: SceneResult, name: str) -> str:
    """A sweep's curves of one field on ``ax`` (see :func:`_write_figures`); returns the
    title."""
    import matplotlib as mpl
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D

    cases = result.cases
    shown = _shown_cases(cases, MAX_CURVES)
    swept = [key for _, key in result.scene.sweep]
    key = swept[0]
    values = np.array([res.entry["inputs"][key] for res in shown], dtype=float)
    distinct = np.unique(values)
    cmap = mpl.colormaps["viridis"]
    if len(distinct) <= DISCRETE_COLOURS:
        mids = 0.5 * (distinct[1:] + distinct[:-1])
        first = distinct[0] - (mids[0] - distinct[0] if len(distinct) > 1 else 0.5)
        last = distinct[-1] + (distinct[-1] - mids[-1] if len(distinct) > 1 else 0.5)
        bounds = np.concatenate([[first], mids, [last]])
        norm = mpl.colors.BoundaryNorm(bounds, cmap.N)
        ticks = distinct
    else:
        norm = mpl.colors.Normalize(distinct[0], distinct[-1])
        ticks = None
    curves = [res.curve(name) for res in shown]
    segments = [np.column_stack([x, v]) for x, v in curves]
    styles = "solid"
    legend = []
    second = swept[1] if len(swept) > 1 else None
    notes = []
    if second is not None:
        other = [res.entry["inputs"][second] for res in shown]
        levels = list(dict.fromkeys(other))
        if len(levels) <= len(_LINESTYLES):
            styles = [_LINESTYLES[levels.index(v)] for v in other]
            legend = [Line2D([], [], color="0.3", lw=1.2, ls=_LINESTYLES[k],
                             label=f"{second} = {_fmt(v)}") for k, v in enumerate(levels)]
        else:
            notes.append(f"{second} also varies")
        notes += [f"{k} also varies" for k in swept[2:]]
    lc = LineCollection(segments, cmap=cmap, norm=norm, linewidths=1.2, linestyles=styles)
    lc.set_array(values)
    ax.add_collection(lc)
    xs = np.concatenate([x for x, _ in curves])
    ax.set_xlim(float(np.min(xs)), float(np.max(xs)))
    ax.set_ylim(*_robust_limits([v for _, v in curves]))
    marks = [(x, val) for res, val in zip(shown, values) if len(res.zones) > 1
             for z in res.zones for x in z["ends"]]
    if marks:
        mx, mv = np.array(marks).T
        ax.scatter(mx, np.zeros_like(mx), c=mv, cmap=cmap, norm=norm, marker="|", s=100,
                   linewidths=1.2, zorder=3)
    cbar = fig.colorbar(lc, ax=ax, ticks=ticks, pad=0.02)
    cbar.set_label(_input_label(key))
    if ticks is not None:
        whole = isinstance(shown[0].entry["inputs"][key], int)     # direction: -1, +1
        cbar.ax.set_yticklabels([_fmt(int(v) if whole else float(v)) for v in ticks])
    if legend:
        ax.legend(handles=legend, fontsize=8)
    title = result.scene.title
    if notes:
        title += f" ({'; '.join(notes)})"
    if len(shown) < len(cases):
        title += (f"\n{len(shown)} of {len(cases)} cases drawn (evenly spaced; {name}.csv has "
                  "all)")
    return title


def _draw_zones(ax, zones):
    """One case: a dotted line at every contact end, each zone shaded when there are several."""
    for z in zones:
        for x_end in z["ends"]:
            ax.axvline(x_end, color="0.6", ls=":", lw=0.8)
        if len(zones) > 1:
            ax.axvspan(*z["ends"], color="0.85", alpha=0.5, lw=0)


def _robust_limits(curves, pad=True) -> tuple:
    """y-limits that show the curves without letting a sampled singular spike flatten them:
    the full range, unless it exceeds 4x the 1..99 percentile range (padded by 6 %, or not)."""
    v = np.concatenate([c[np.isfinite(c)].ravel() for c in curves] or [np.zeros(1)])
    if v.size == 0:
        return -1.0, 1.0
    lo, hi = float(v.min()), float(v.max())
    plo, phi = (float(q) for q in np.percentile(v, [1, 99]))
    if hi - lo > 4.0 * (phi - plo) > 0:
        lo, hi = plo, phi
    if not pad:
        return lo, hi
    pad = 0.06 * (hi - lo) if hi > lo else max(1.0, abs(hi))
    return lo - pad, hi + pad


def format_table(result: SceneResult) -> str:
    """A short text table: one row per case with its swept inputs, ends, exponents, peak
    pressure, SIFs and sigma_XX extremes (what was requested), the solver's check (the larger
    of its residual and load check) and the time taken.

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
            row["alpha"] = f"{e['exponents']['right']:.8g}"
            row["beta"] = f"{e['exponents']['left']:.8g}"
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
        if "subsurface" in e:
            ms = e["subsurface"]["max_shear"]
            row["max shear @ depth/a"] = f"{ms['value']:.4g} @ {ms['depth_over_a']:.4g}"
        if res.diagnostics:
            d = res.diagnostics
            row["check"] = f"{max(d['residual'], d['load_check']):.1e}"
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
    if any(_cut_below_surface(res.entry) for res in result.cases):
        lines.append(f"  (max shear with a corner on the surface: searched below Y = "
                     f"-{SUBSURFACE_CUT:g} a, the stresses being unbounded at the corner; "
                     "result.json gives the region)")
    if "check" in columns:
        lines.append("  (check: the larger of the solver's relative residual and load check; "
                     "result.json and sweep.csv give n, residual and load_check)")
    if any(len(res.zones) > 1 for res in result.cases):
        lines.append("  (several zones: x_left, x_right, alpha, beta, K_left, K_right are those "
                     "of the outer ends; result.json lists every zone)")
    lines.append(f"  total time {result.timing_s:.3f} s for {len(result.cases)} case(s); units as "
                 "in the scene (stresses in the stiffness unit, lengths in the punch's unit)")
    return "\n".join(lines)


def _cut_below_surface(entry: dict) -> bool:
    """Whether a case's subsurface extrema were searched below a cut under the surface."""
    sub = entry.get("subsurface")
    return sub is not None and sub["region"]["y"][1] != sub["grid"]["y"]["stop"]


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
