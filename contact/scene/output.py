"""Writing scene results: result.json, sweep.csv (:mod:`contact.scene.table`), one CSV per
curve field, figures, the console table; with the ``"subsurface"`` field also subsurface.npz,
subsurface.csv and two contour maps.

The files are written as the cases come (:class:`SceneWriter`, fed by
:func:`contact.scene.run.iter_scene` in ``contact run``, or by a :class:`SceneResult` in
:func:`write_outputs`): result.json case by case, the rows of sweep.csv and the curves spooled
to disk, and only a fixed number of cases kept for the figures and the printed table, so that
a sweep of any length is written in bounded memory.
"""
from __future__ import annotations

import collections
import csv
import dataclasses
import io
import itertools
import json
import math
import os
import shutil
import tempfile
import zipfile
from pathlib import Path

import numpy as np

import contact

from .run import (SUBSURFACE_QUANTITIES, CaseResult, SceneResult, _inputs_text, _json_case,
                  _json_head, _json_tail, progress_bar)
from .spec import CURVE_FIELDS, SUBSURFACE_CUT, Scene, _fmt
from .table import SweepCsv

#: The subsurface figures show at most this many cases (small multiples); a longer sweep shows
#: this many, evenly spaced through it (first and last included), and says so in the title.
SUBSURFACE_PANELS = 6
#: The printed table shows every case of a sweep of at most this many; a longer one shows the
#: first and the last TABLE_ROWS // 2, and the smallest and largest value of each column over
#: every case.
TABLE_ROWS = 40
NO_MATPLOTLIB = ("matplotlib is not installed: no PNG figures written "
                 "(pip install 'sie-contact[plot]')")


# --------------------------------------------------------------------------
# writing: result.json, CSV, PNG, the printed table
# --------------------------------------------------------------------------
def write_outputs(result: SceneResult, out_dir, *, figures: bool | None = None,
                  progress: bool = False) -> list[Path]:
    """Write result.json, sweep.csv, one CSV per sampled curve field and its PNG figure into
    ``out_dir`` (created if needed).  PNGs need matplotlib; without it they are skipped (and
    the run's warnings say so).

    With the ``"subsurface"`` field: subsurface.npz and subsurface.csv (the maps, see
    :class:`SubsurfaceFiles`), and the contour maps subsurface_max_shear.png and
    subsurface_sigma_xx.png (:func:`_write_subsurface_figures`).

    The cases go through a :class:`SceneWriter`, as in ``contact run``.

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
    with SceneWriter(result.scene, out_dir, len(result.cases), figures=figures) as writer:
        for res in result.cases:
            writer.add(res)
        return writer.finish(result.timing_s, result.warnings, progress=progress)


class SceneWriter:
    """A scene's outputs (:func:`write_outputs`) written as its cases come, in scene order.

    :meth:`add` writes each case to result.json and spools its row of sweep.csv and its curves
    to disk; the writer keeps only what the figures draw (at most MAX_CURVES cases, and
    SUBSURFACE_PANELS maps, evenly spaced through the sweep), the printed table's rows and
    extremes (:class:`TableSummary`) and, with the ``"subsurface"`` field, each case's index
    and label.  :meth:`finish` writes the rest.

    The files are made in a hidden directory inside ``out_dir`` and moved into it by
    :meth:`finish`; a writer left unfinished (an error, a failing case) removes them, and
    ``out_dir`` too when it made it.  Use it as a context manager (or call :meth:`abort`).

    Parameters
    ----------
    scene : Scene
    out_dir : path
        Created if needed.
    count : int
        How many cases will be added (``Scene.case_count``).
    figures : bool, optional
        Write the PNG figures; None: as the scene says.
    """

    def __init__(self, scene: Scene, out_dir, count: int, *, figures: bool | None = None):
        self.scene, self.count = scene, count
        self.figures = scene.figures if figures is None else figures
        self.out = Path(out_dir)
        self._made_out = not self.out.exists()
        self.out.mkdir(parents=True, exist_ok=True)
        self._spool = Path(tempfile.mkdtemp(prefix=".contact-writing-", dir=self.out))
        self._files = []
        self.summary = TableSummary(scene, count)
        self.curve_fields = [f for f in scene.fields if f in CURVE_FIELDS]
        try:
            self._json = self._open(ResultJson(scene, self._spool / "result.json"))
            self._sweep = self._open(SweepCsv(scene, count, self._spool / "sweep.rows"))
            self._curves = {name: self._open(CurveColumns(name, count, self._spool / name))
                            for name in self.curve_fields}
            self._maps = (self._open(SubsurfaceFiles(self._spool))
                          if "subsurface" in scene.fields else None)
        except BaseException:
            self.abort()
            raise
        self._drawn = (set(evenly_spaced(count, MAX_CURVES)) if self.figures
                       and self.curve_fields else set())
        self._mapped = (set(evenly_spaced(count, SUBSURFACE_PANELS)) if self.figures
                        and self._maps is not None else set())
        self._drawn_cases, self._mapped_cases = [], []
        self._added = 0
        self._done = False

    def _open(self, part):
        self._files.append(part)
        return part

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        if not self._done:
            self.abort()

    def add(self, res: CaseResult) -> None:
        """Write (or spool) one case, the next in scene order."""
        self._json.add(res)
        self._sweep.add(res)
        for name, columns in self._curves.items():
            x, values = res.curve(name)
            columns.add(res.index, res.label if self.scene.sweep else name, x, values)
        if self._maps is not None:
            self._maps.add(res)
        self.summary.add(res)
        if self._added in self._drawn:              # the figures' cases, without their maps
            self._drawn_cases.append(dataclasses.replace(res, subsurface=None))
        if self._added in self._mapped:
            self._mapped_cases.append(res)
        self._added += 1

    def table(self, timing_s: float) -> str:
        """The printed table of the cases added (:func:`format_table`)."""
        return self.summary.text(timing_s)

    def finish(self, timing_s: float, messages: list, *, progress: bool = False) -> list[Path]:
        """Write the rest (result.json's tail, sweep.csv, the curve CSVs, the maps, the
        figures), move the files into the output directory and return them.

        ``messages``: the run's warnings, written to result.json; a figure that cannot be
        drawn (no matplotlib) appends its warning to it.
        """
        if self._added != self.count:
            raise ValueError(f"{self._added} case(s) added, the writer was made for "
                             f"{self.count}")
        out = self.out
        steps = [("result.json", lambda: self._json.finish(timing_s, messages)),
                 ("sweep.csv", lambda: self._sweep.write(self._spool / "sweep.csv"))]
        steps += [(f"{name}.csv", lambda c=c, name=name: c.write(self._spool / f"{name}.csv"))
                  for name, c in self._curves.items()]
        if self._maps is not None:
            steps += [("subsurface.npz", self._maps.finish_npz),
                      ("subsurface.csv", self._maps.finish_csv)]
        if self.figures:
            steps += [(f"{name}.png", lambda name=name: _write_curve_figures(
                self.scene, self._drawn_cases, self.count, self._spool, name, messages))
                for name in self.curve_fields]
            if self._maps is not None:
                steps.append(("subsurface_*.png", lambda: _write_subsurface_figures(
                    self.scene, self._mapped_cases, self.count, self._spool, messages)))
        written = []
        immediate = self.count > 100
        bar = _writing_bar(len(steps), progress, immediate)
        try:
            for name, step in steps:
                bar.set_postfix_str(name, refresh=immediate)
                paths = step()
                for path in paths if isinstance(paths, list) else [paths]:
                    written.append(path.replace(out / path.name))
                bar.update(1)
        finally:
            bar.close()
        self._done = True
        shutil.rmtree(self._spool, ignore_errors=True)
        return written

    def abort(self) -> None:
        """Close and remove what was written, and the output directory if this writer made
        it (and it is empty)."""
        self._done = True
        for part in self._files:
            part.close()
        shutil.rmtree(self._spool, ignore_errors=True)
        if self._made_out:
            try:
                self.out.rmdir()
            except OSError:                    # something else was put there meanwhile
                pass


def evenly_spaced(count: int, most: int) -> list:
    """Positions of at most ``most`` of ``count`` cases, evenly spaced through them (first and
    last included; all of them when there are no more than ``most``)."""
    if count <= most:
        return list(range(count))
    return np.unique(np.round(np.linspace(0, count - 1, most)).astype(int)).tolist()


def _writing_bar(total: int, progress: bool, immediate: bool = False):
    """The second phase of ``contact run``'s progress: the files being written (shown at once
    for a long sweep, whose curve CSVs alone can take seconds; otherwise after half a
    second)."""
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
    if not os.access(parent, os.W_OK | os.X_OK):
        raise OSError(f"{out} cannot be created: {parent} is not writable")


class ResultJson:
    """result.json written case by case: the text :func:`dumps_json` gives
    :meth:`SceneResult.to_json` (the keys after ``cases`` -- version, timing_s, units,
    warnings -- are written by :meth:`finish`)."""

    def __init__(self, scene: Scene, path: Path):
        self.path = path
        self._fh = open(path, "w", encoding="utf-8")
        self._fh.write("{\n" + "".join(_json_item(k, v) + ",\n"
                                        for k, v in _json_head(scene).items())
                       + f"{_INDENT}{json.dumps('cases')}: [")
        self._count = 0

    def add(self, res: CaseResult) -> None:
        self._fh.write(("\n" if self._count == 0 else ",\n") + 2 * _INDENT
                       + dumps_json(_json_case(res), _INDENT, 2))
        self._count += 1

    def finish(self, timing_s: float, messages) -> Path:
        """Write the keys after ``cases`` and close the file."""
        tail = _json_tail(timing_s, messages)
        self._fh.write(("\n" + _INDENT + "]" if self._count else "]")
                       + "".join(",\n" + _json_item(k, v) for k, v in tail.items()) + "\n}\n")
        self._fh.close()
        return self.path

    def close(self) -> None:
        self._fh.close()


def _json_item(key: str, value) -> str:
    """A key of result.json's top level and its value, as :func:`dumps_json` writes them."""
    return f"{_INDENT}{json.dumps(key)}: {dumps_json(value, _INDENT, 1)}"


class CurveColumns:
    """One curve field of every case, for its CSV: a column X and one column per case when
    every case shares its x, else a pair of columns ``X (label)``, ``label`` per case.

    The cases come one by one and the CSV runs across them, so each case's (x, values) go to a
    spool file laid out point by point (``{spool}.f8``: for each of the curve's points, (x,
    value) of every case in order; written a block of cases at a time) and the labels to
    ``{spool}.labels``; :meth:`write` then writes the CSV a row (a point) at a time, in
    slices of cases.

    Parameters
    ----------
    name : str
        The field.
    count : int
        How many cases will be added.
    spool : Path
        The spool files' stem.
    """

    #: Cases buffered before they are written to the spool; cases per slice of a row.
    BLOCK = 1024

    def __init__(self, name: str, count: int, spool: Path):
        self.name, self.count = name, count
        self._data = open(spool.with_suffix(".f8"), "w+b")
        self._labels = open(spool.with_suffix(".labels"), "w+", encoding="utf-8")
        self._block = []
        self._written = 0                       # cases in the spool
        self._first_x = None
        self._shared = True

    def add(self, index: int, label: str, x: np.ndarray, values: np.ndarray) -> None:
        """The next case's curve; ``label`` names its column."""
        if self._first_x is None:
            self._first_x = np.array(x, dtype=float)
        elif len(x) != len(self._first_x):
            raise ValueError(f"{self.name}: case {index} is sampled at {len(x)} points, the "
                             f"first case at {len(self._first_x)}: a curve CSV needs one "
                             "number of points")
        self._shared = self._shared and np.array_equal(x, self._first_x)
        self._labels.write(json.dumps(label) + "\n")
        self._block.append(np.column_stack([x, values]))
        if len(self._block) == self.BLOCK:
            self._flush()

    def _flush(self) -> None:
        """Write the buffered cases into their places of the point-by-point spool."""
        if not self._block:
            return
        block = np.stack(self._block, axis=1)           # (points, cases, 2)
        row = self.count * 16                            # bytes per point: (x, value) of all
        for k in range(block.shape[0]):
            self._data.seek(k * row + self._written * 16)
            self._data.write(block[k].tobytes())
        self._written += block.shape[1]
        self._block = []

    def write(self, path: Path) -> Path:
        """The CSV: a header, then one row per point of the curve; numbers as their repr,
        empty cells where a value is not finite (a singular end); the spool closed."""
        self._flush()
        points = 0 if self._first_x is None else len(self._first_x)
        with open(path, "w", newline="", encoding="utf-8") as fh:
            _write_row(fh, self._header())
            for k in range(points):
                _write_row(fh, self._row(k))
        self.close()
        return path

    def _header(self):
        """The header's text, a slice of cases at a time."""
        if self._shared:
            yield "X"
        self._labels.seek(0)
        lines = iter(self._labels)
        while labels := [json.loads(line) for line in itertools.islice(lines, self.BLOCK)]:
            yield _csv_text(labels if self._shared else
                            [cell for label in labels for cell in (f"X ({label})", label)])

    def _row(self, k: int):
        """The text of point ``k``'s row, a slice of cases at a time."""
        if self._shared:
            yield repr(float(self._first_x[k]))
        for start in range(0, self.count, self.BLOCK):
            n = min(self.BLOCK, self.count - start)
            self._data.seek((k * self.count + start) * 16)
            pairs = np.frombuffer(self._data.read(n * 16), dtype=float).reshape(n, 2)
            yield ",".join(_cells(pairs[:, 1] if self._shared else pairs.ravel()))

    def close(self) -> None:
        self._data.close()
        self._labels.close()


def _write_row(fh, pieces) -> None:
    """A CSV row from pieces of its text (cells joined by commas), as :mod:`csv` writes it."""
    for k, piece in enumerate(pieces):
        fh.write(("," if k else "") + piece)
    fh.write("\r\n")


def _csv_text(cells) -> str:
    """Cells as :mod:`csv` writes them in a row (quoted where needed), without the line end."""
    line = io.StringIO()
    csv.writer(line).writerow(cells)
    return line.getvalue()[:-2]


def _cells(values: np.ndarray) -> list:
    """CSV cells of a column: repr of each number, empty where it is not finite."""
    v = np.asarray(values, dtype=float)
    cells = [repr(x) for x in v.tolist()]
    for k in np.flatnonzero(~np.isfinite(v)).tolist():
        cells[k] = ""
    return cells


class SubsurfaceFiles:
    """subsurface.npz and subsurface.csv written case by case (``"subsurface"`` field).

    subsurface.npz (``numpy.load(path)``; no pickles) has the keys ``cases`` (int array, the
    case indices, as in result.json), ``labels`` (str array, their labels) and for each case
    ``i``:

    * ``case{i}/x`` (nx,) and ``case{i}/y`` (ny,): the grid's X and Y (Y <= 0, increasing: the
      last row is the top, Y = 0 the surface);
    * ``case{i}/sigma_xx``, ``case{i}/sigma_yy``, ``case{i}/sigma_xy``, ``case{i}/max_shear``,
      ``case{i}/max_tension``: (ny, nx) arrays, ``[k, j]`` at (x[j], y[k]), tension positive,
      in the scene's stress unit S; NaN only where a singular (corner) contact end meets the
      surface (the stresses are infinite there).

    subsurface.csv, long format: a header ``case, X, Y, sigma_xx, sigma_yy, sigma_xy,
    max_shear, max_tension`` and one row per grid point of every case (case by case, then Y
    increasing, X increasing within a row of the grid); an empty cell where the map is NaN (a
    singular contact end on the surface).

    Parameters
    ----------
    folder : Path
        Where the two files are written.
    """

    def __init__(self, folder: Path):
        self.npz_path, self.csv_path = folder / "subsurface.npz", folder / "subsurface.csv"
        self._npz = zipfile.ZipFile(self.npz_path, "w", zipfile.ZIP_STORED, allowZip64=True)
        self._csv_file = open(self.csv_path, "w", newline="", encoding="utf-8")
        self._csv = csv.writer(self._csv_file)
        self._csv.writerow(("case", "X", "Y") + SUBSURFACE_QUANTITIES)
        self._indices, self._labels = [], []

    def add(self, res: CaseResult) -> None:
        """One case's maps, written to both files."""
        m = res.subsurface
        self._indices.append(res.index)
        self._labels.append(res.label)
        self._put(f"case{res.index}/x", m.x)
        self._put(f"case{res.index}/y", m.y)
        for name in SUBSURFACE_QUANTITIES:
            self._put(f"case{res.index}/{name}", m.quantity(name))
        X, Y = np.meshgrid(m.x, m.y)
        cols = [X, Y] + [m.quantity(name) for name in SUBSURFACE_QUANTITIES]
        table = np.column_stack([c.ravel() for c in cols])
        rows = [[res.index] + r for r in table.tolist()]
        for k in np.flatnonzero(~np.all(np.isfinite(table), axis=1)).tolist():
            rows[k] = [res.index] + ["" if not math.isfinite(v) else v
                                     for v in table[k].tolist()]
        self._csv.writerows(rows)

    def _put(self, key: str, array) -> None:
        """An array into the npz (as numpy.savez stores it)."""
        with self._npz.open(key + ".npy", "w", force_zip64=True) as fh:
            np.lib.format.write_array(fh, np.asanyarray(array), allow_pickle=False)

    def finish_npz(self) -> Path:
        self._put("cases", np.array(self._indices, dtype=int))
        self._put("labels", np.array(self._labels, dtype=str))
        self._npz.close()
        return self.npz_path

    def finish_csv(self) -> Path:
        self._csv_file.close()
        return self.csv_path

    def close(self) -> None:
        self._npz.close()
        self._csv_file.close()


# --------------------------------------------------------------------------
# the field under the surface: contour maps
# --------------------------------------------------------------------------
_MAP_LABELS = {"max_shear": "max shear (S)", "sigma_xx": r"$\sigma_{XX}$ (S)"}
_MAP_MARKS = {"max_shear": ("max_shear", "max shear"), "sigma_xx": ("max_tension",
                                                                    r"max tension $\sigma_1$")}


def _subsurface_shown(cases) -> list:
    """The cases the subsurface figures show: all, or SUBSURFACE_PANELS evenly spaced."""
    return _shown_cases(cases, SUBSURFACE_PANELS)


def _write_subsurface_figures(scene: Scene, shown: list, total: int, out: Path,
                              messages: list) -> list[Path]:
    """subsurface_max_shear.png and subsurface_sigma_xx.png: filled contours of each shown case
    (``shown``, at most SUBSURFACE_PANELS of the ``total`` cases: small multiples, one shared
    colour bar), the surface at the top, each contact zone a thick segment on it and the
    extremum marked (the largest max shear; on the sigma_XX map the largest tension
    sigma_1).  Without matplotlib: none, and a warning in ``messages``."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.ticker import MaxNLocator
    except ImportError:
        _no_matplotlib(messages)
        return []
    n = len(shown)
    title = scene.title
    if n < total:
        title += f"\n{n} of {total} cases shown (evenly spaced; subsurface.npz has all)"
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
        width, height = 1.5 + pw * ncols, (1.0 if n < total else 0.8) + ph * nrows
        left, right = 0.75 / width, 1.0 - 1.3 / width
        bottom, top = 0.55 / height, 1.0 - (0.75 if n < total else 0.55) / height
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
            if total > 1:
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
_INDENT = "  "


def dumps_json(obj, indent: str = _INDENT, _level: int = 0) -> str:
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
    """At most ``most`` of ``cases``, evenly spaced (:func:`evenly_spaced`)."""
    return [cases[k] for k in evenly_spaced(len(cases), most)]


def _input_label(key: str) -> str:
    unit = _INPUT_UNITS.get(key)
    return f"{key} ({unit})" if unit else key


def _no_matplotlib(messages: list) -> None:
    """The warning that no PNG is written, once in ``messages``."""
    if NO_MATPLOTLIB not in messages:
        messages.append(NO_MATPLOTLIB)


def _write_curve_figures(scene: Scene, shown: list, total: int, out: Path, name: str,
                         messages: list) -> list[Path]:
    """{name}.png, the figure of one curve field (:func:`curve_figure`) from the cases it
    draws (``shown``: at most MAX_CURVES of the ``total`` cases, evenly spaced).  Without
    matplotlib: none, and a warning in ``messages``."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        _no_matplotlib(messages)
        return []
    fig = _curve_figure(scene, shown, total, name)
    path = out / f"{name}.png"
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return [path]


def curve_figure(result: SceneResult, name: str):
    """The matplotlib figure of one curve field; the caller closes it.

    One case: its curve, the contact ends dotted (the zones shaded when there are several).
    A sweep: a family of curves (one LineCollection) coloured by the first swept input, with
    a colour bar (viridis; discrete ticks at its values when it takes few); a second swept
    input with at most 4 values is told apart by line style (legend), a further one is named
    in the title; the ends of every zone of a case with several are ticks on the axis in its
    colour.  At most :data:`MAX_CURVES` cases are drawn (evenly spaced; the title says so).
    """
    return _curve_figure(result.scene, _shown_cases(result.cases, MAX_CURVES),
                         len(result.cases), name)


def _curve_figure(scene: Scene, shown: list, total: int, name: str):
    """:func:`curve_figure` of the cases drawn, ``shown``, out of ``total``."""
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7.5, 4.5), layout="constrained")
    if total > 1 and scene.sweep:
        title = _draw_family(fig, ax, scene, shown, total, name)
    else:
        res = shown[0]
        x, v = res.curve(name)
        ax.plot(x, v, lw=1.3, color="C0")
        _draw_zones(ax, res.zones)
        ax.set_ylim(*_robust_limits([v]))
        title = scene.title
    ax.axhline(0.0, color="0.7", lw=0.6, zorder=0)
    ax.set_xlabel("X (L)")
    ax.set_ylabel(f"{_AXIS_LABELS[name]} ({_CURVE_UNIT})")
    ax.set_title(title, fontsize=10)
    return fig


def _draw_family(fig, ax, scene: Scene, shown: list, total: int, name: str) -> str:
    """A sweep's curves of one field on ``ax`` (see :func:`curve_figure`): ``shown``, out of
    ``total`` cases; returns the title."""
    import matplotlib as mpl
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D

    swept = [key for _, key in scene.sweep]
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
    title = scene.title
    if notes:
        title += f" ({'; '.join(notes)})"
    if len(shown) < total:
        title += (f"\n{len(shown)} of {total} cases drawn (evenly spaced; {name}.csv has "
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
    """A short text table: a row per case (the first and the last TABLE_ROWS // 2 of a longer
    sweep, then each column's smallest and largest value over every case) with its swept
    inputs, ends, exponents, peak pressure, SIFs and sigma_XX extremes (what was requested),
    the solver's check (the larger of its residual and load check) and the time taken.

    When a case has several contact zones, a ``zones`` column gives their number, and the ends,
    exponents and SIFs shown are those of the outer ends (result.json lists every zone)."""
    summary = TableSummary(result.scene, len(result.cases))
    for res in result.cases:
        summary.add(res)
    return summary.text(result.timing_s)


class TableSummary:
    """The printed table (:func:`format_table`) built one case at a time: it keeps the rows
    shown (all up to TABLE_ROWS cases, else the first and the last TABLE_ROWS // 2), each
    column's extremes over every case, and what the notes under the table depend on.

    Parameters
    ----------
    scene : Scene
    count : int
        How many cases will be added.
    """

    def __init__(self, scene: Scene, count: int):
        self.scene, self.count = scene, count
        swept = [key for _, key in scene.sweep]
        if "velocity" in swept:
            swept.append("speed")
        self._swept = swept
        self._outer = ("ends" in scene.fields or "zones" in scene.fields,
                       "exponents" in scene.fields, "sif" in scene.fields)
        self._columns = dict.fromkeys(["case"] + swept)
        self._head = []
        self._tail = collections.deque(maxlen=TABLE_ROWS // 2)
        self._lowest, self._highest = {}, {}          # column -> (value, cell)
        self._first_inputs = None
        self._added = 0
        self._other_than_one_zone = self._several_zones = False
        self._free_end = self._cut = False

    def add(self, res: CaseResult) -> None:
        """The next case, in scene order."""
        row = _table_row(res, self._swept, self._outer)
        if self._first_inputs is None:
            self._first_inputs = res.entry["inputs"]
        self._columns.update(dict.fromkeys(row))
        self._other_than_one_zone |= len(res.zones) != 1
        self._several_zones |= len(res.zones) > 1
        self._free_end |= row.get("K_left") == "-" or row.get("K_right") == "-"
        self._cut |= _cut_below_surface(res.entry)
        for key, cell in row.items():
            self._extremes(key, cell)
        if self._added < TABLE_ROWS // 2 or self.count <= TABLE_ROWS:
            self._head.append(row)
        else:
            self._tail.append(row)
        self._added += 1

    def _extremes(self, key: str, cell: str) -> None:
        """Keep ``cell`` as its column's smallest or largest when it is (cells that are not
        a finite number are passed over)."""
        try:
            value = float(cell)
        except ValueError:
            return
        if key == "case" or not math.isfinite(value):
            return
        if key not in self._lowest or value < self._lowest[key][0]:
            self._lowest[key] = (value, cell)
        if key not in self._highest or value > self._highest[key][0]:
            self._highest[key] = (value, cell)

    def text(self, timing_s: float) -> str:
        """The table of the cases added, with its notes and the run's time."""
        scene = self.scene
        mat = scene.material
        c_R = contact.rayleigh_speed(mat.build())
        head = [scene.title,
                f"  scene: {scene.source}",
                f"  material: {mat.preset or 'custom'} (C11, C12, C22, C33 = {mat.C11:.10g}, "
                f"{mat.C12:.10g}, {mat.C22:.10g}, {mat.C33:.10g}); Rayleigh speed c_R = "
                f"{c_R:.10f}",
                f"  fixed inputs: {_inputs_text(_fixed_inputs(scene, self._first_inputs or {}))}"]
        columns = [k for k in self._columns
                   if k != "time ms" and (k != "zones" or self._other_than_one_zone)]
        columns.append("time ms")
        omitted = self._added - len(self._head) - len(self._tail)
        extremes = []
        if omitted:
            extremes = [{"case": "min", **{k: c for k, (_, c) in self._lowest.items()}},
                        {"case": "max", **{k: c for k, (_, c) in self._highest.items()}}]
        shown = self._head + list(self._tail) + extremes
        widths = {k: max(len(k), *(len(r.get(k, "")) for r in shown)) for k in columns}

        def line(row):
            return "  " + "  ".join(f"{row.get(k, ''):>{widths[k]}}" for k in columns)

        lines = head + ["", "  " + "  ".join(f"{k:>{widths[k]}}" for k in columns)]
        lines += [line(r) for r in self._head]
        if omitted:
            lines.append(line({"case": "..."}).rstrip())
            lines += [line(r) for r in list(self._tail) + extremes]
            lines.append(f"  ({omitted} of {self._added} cases not shown; min, max: each "
                         "column's smallest and largest value over every case; sweep.csv has "
                         "every case)")
        if "sif" in scene.fields and self._free_end:
            lines.append("  (SIF '-': that contact end is free, the pressure vanishes there)")
        if self._cut:
            lines.append(f"  (max shear with a corner on the surface: searched below Y = "
                         f"-{SUBSURFACE_CUT:g} a, the stresses being unbounded at the corner; "
                         "result.json gives the region)")
        if "check" in columns:
            lines.append("  (check: the larger of the solver's relative residual and load "
                         "check; result.json and sweep.csv give n, residual and load_check)")
        if self._several_zones:
            lines.append("  (several zones: x_left, x_right, alpha, beta, K_left, K_right are "
                         "those of the outer ends; result.json lists every zone)")
        lines.append(f"  total time {timing_s:.3f} s for {self._added} case(s); units as "
                     "in the scene (stresses in the stiffness unit, lengths in the punch's "
                     "unit)")
        return "\n".join(lines)


def _table_row(res: CaseResult, swept: list, outer: tuple) -> dict:
    """A case's cells in the printed table (the ``zones`` column always: the table drops it
    when every case has one zone)."""
    e = res.entry
    row = {"case": str(res.index)}
    row.update({k: _fmt(e["inputs"][k]) for k in swept})
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
    return row


def _cut_below_surface(entry: dict) -> bool:
    """Whether a case's subsurface extrema were searched below a cut under the surface."""
    sub = entry.get("subsurface")
    return sub is not None and sub["region"]["y"][1] != sub["grid"]["y"]["stop"]


def _fixed_inputs(scene: Scene, first: dict) -> dict:
    """The inputs of the first case that the scene does not sweep."""
    swept = {key for _, key in scene.sweep}
    return {k: v for k, v in first.items()
            if k not in swept and not (k == "speed" and "velocity" in swept)}


def _extreme(values, fn) -> str:
    v = np.asarray(values, dtype=float)
    if not np.any(np.isfinite(v)):
        return "-"
    return f"{fn(v) + 0.0:.6g}"
