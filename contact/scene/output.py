"""Writing scene results: result.json, sweep.csv (:mod:`contact.scene.table`), one CSV per
curve field, the figures (:mod:`contact.scene.figures`) and the console table
(:mod:`contact.scene.summary`); with the ``"subsurface"`` field also subsurface.npz,
subsurface.csv and two contour maps.

The files are written as the cases come (:class:`SceneWriter`, fed by
:func:`contact.scene.run.iter_scene` in ``contact run``, or by a :class:`SceneResult` in
:func:`write_outputs`): result.json case by case, the rows of sweep.csv and the curves spooled
to disk, and only a fixed number of cases kept for the figures and the printed table, so that
a sweep of any length is written in bounded memory.
"""
from __future__ import annotations

import csv
import dataclasses
import io
import itertools
import json
from json.encoder import encode_basestring_ascii
import math
import os
import re
import shutil
import socket
import tempfile
import warnings
import zipfile
from pathlib import Path

import numpy as np

from .figures import (MAX_CURVES, SUBSURFACE_PANELS, _write_curve_figures,
                      _write_subsurface_figures, evenly_spaced)
from .run import (SUBSURFACE_QUANTITIES, CaseResult, SceneResult, _json_case, _json_head,
                  _json_tail, progress_bar)
from .table import CaseText, case_text
from .spec import CURVE_FIELDS, Scene
from .summary import TableRows, TableSummary
from .table import SweepCsv, SweepTable, row_lines

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
        for note in writer.staging_notes:
            warnings.warn(note, UserWarning, stacklevel=2)
        for k in range(0, len(result.cases), _WRITE_SLICE):
            writer.add_all(result.cases[k:k + _WRITE_SLICE])
        return writer.finish(result.timing_s, result.warnings, progress=progress)


class SceneWriter:
    """A scene's outputs (:func:`write_outputs`) written as its cases come, in scene order.

    :meth:`add` writes each case to result.json and spools its row of sweep.csv and its curves
    to disk; the writer keeps only what the figures draw (at most MAX_CURVES cases, and
    SUBSURFACE_PANELS maps, evenly spaced through the sweep), the printed table's rows and
    extremes (:class:`TableSummary`) and, with the ``"subsurface"`` field, each case's index
    and label.  :meth:`finish` writes the rest.

    The files are made in a hidden directory inside ``out_dir`` (its staging folder,
    ``.contact-writing-<host>-<pid>-<random>``) and moved into it by :meth:`finish`; a writer
    left unfinished (an error, a failing case) removes them, and ``out_dir`` too when it made
    it.  Use it as a context manager (or call :meth:`abort`).  A run killed outright
    (SIGKILL, the out-of-memory killer) cannot remove its staging folder: the next writer
    into ``out_dir`` removes the staging folders of the runs on this host whose process has
    ended (:func:`remove_dead_staging`) and says so in :attr:`staging_notes`.

    Parameters
    ----------
    scene : Scene
    out_dir : path
        Created if needed.
    count : int
        How many cases will be added (``Scene.case_count``).
    figures : bool, optional
        Write the PNG figures; None: as the scene says.
    table : bool
        Keep the printed table's rows and extremes (:meth:`table`); False for a run that
        prints none (``contact run --quiet``).

    Attributes
    ----------
    staging_notes : list of str
        What :func:`remove_dead_staging` found in ``out_dir`` when the writer was made: the
        dead runs' staging folders it removed, and those it kept because their owner
        cannot be told (``contact run`` prints them as warnings).
    """

    def __init__(self, scene: Scene, out_dir, count: int, *, figures: bool | None = None,
                 table: bool = True):
        self.scene, self.count = scene, count
        self.figures = scene.figures if figures is None else figures
        self.out = Path(out_dir)
        self._made_out = not self.out.exists()
        self.out.mkdir(parents=True, exist_ok=True)
        self.staging_notes = remove_dead_staging(self.out)
        self._spool = Path(tempfile.mkdtemp(prefix=_staging_prefix(), dir=self.out))
        self._files = []
        self.summary = TableSummary(scene, count) if table else None
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

    def encoder(self) -> "CaseEncoder":
        """What makes this writer's text of a case where the case is solved (pass it to
        :func:`contact.scene.iter_scene` as ``encode``); a lean one when the writer keeps
        nothing of a case but its text and its row of the printed table (no curves, no
        maps)."""
        return CaseEncoder(self.scene, lean=self._lean, table=self.summary is not None)

    @property
    def _lean(self) -> bool:
        """Whether it keeps nothing of a case but its text and its row of the printed table
        (no curves, no maps): it takes CaseText in place of results."""
        return not self.curve_fields and self._maps is None

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
        self.add_all([res])

    def add_all(self, results) -> None:
        """Write (or spool) cases, the next ones in scene order (a list: one write per file
        for the lot): :class:`CaseResult`, or :class:`~contact.scene.table.CaseText` from
        this writer's lean :meth:`encoder`."""
        self._json.add_all(results)
        self._sweep.add_all(results)
        if self._lean:                          # texts (see encoder): their table rows
            if self.summary is not None:
                self.summary.add_all(results)
            self._added += len(results)
            return
        for res in results:
            self._keep(res)

    def _keep(self, res: CaseResult) -> None:
        """A case's curves, map and table row; the case itself if a figure draws it."""
        for name, columns in self._curves.items():
            x, values = res.curve(name)
            columns.add(res.index, res.label if self.scene.sweep else name, x, values)
        if self._maps is not None:
            self._maps.add(res)
        if self.summary is not None:
            self.summary.add(res)
        if self._added in self._drawn:              # the figures' cases, without their maps
            self._drawn_cases.append(dataclasses.replace(res, subsurface=None))
        if self._added in self._mapped:
            self._mapped_cases.append(res)
        self._added += 1

    def table(self, timing_s: float) -> str:
        """The printed table of the cases added (:func:`format_table`)."""
        if self.summary is None:
            raise ValueError("this SceneWriter was made with table=False: it kept no table")
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


#: The start of the name of a :class:`SceneWriter`'s staging folder in the output directory;
#: the host, the writer's process id and a random part follow, separated by "-".
STAGING_PREFIX = ".contact-writing-"


def _host() -> str:
    """This machine's name as it goes into a staging folder's name (no "-": the name is
    split at them)."""
    return re.sub(r"[^A-Za-z0-9.]", "_", socket.gethostname())[:64] or "_"


def _staging_prefix() -> str:
    """``.contact-writing-<host>-<pid>-``: mkdtemp adds the random part."""
    return f"{STAGING_PREFIX}{_host()}-{os.getpid()}-"


def staging_owner(name: str):
    """(host, pid) of the run that made the staging folder ``name``, or None for a name not
    of that form (another program's, or made by a version of contact that did not record
    its owner)."""
    if not name.startswith(STAGING_PREFIX):
        return None
    parts = name[len(STAGING_PREFIX):].rsplit("-", 2)
    if len(parts) != 3 or not parts[0] or not parts[1].isdigit() or int(parts[1]) == 0:
        return None
    return parts[0], int(parts[1])


def process_alive(pid: int) -> bool:
    """Whether a process ``pid`` exists on this machine (signal 0: nothing is sent).  Where
    that cannot be asked (not POSIX: os.kill would end the process there) it is taken to
    exist.  A pid reused by an unrelated process since reads as alive."""
    if pid == os.getpid() or os.name != "posix":
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:                        # PermissionError: another user's process
        return True
    return True


def remove_dead_staging(out_dir) -> list[str]:
    """Remove the staging folders (:data:`STAGING_PREFIX`) in ``out_dir`` of runs on this
    host whose process has ended without finishing (killed outright: SIGKILL, the
    out-of-memory killer) and return one message for each; a staging folder whose owner
    cannot be told (made on another host sharing the directory, or with no process id in
    its name) is kept and named in a message too.  A live run's folder (its process exists:
    :func:`process_alive`) is left alone and not named."""
    out, host = Path(out_dir), _host()
    notes = []
    for path in sorted(out.glob(STAGING_PREFIX + "*")):
        if path.is_symlink() or not path.is_dir():
            continue
        owner = staging_owner(path.name)
        if owner is None or owner[0] != host:
            who = "no run recorded in its name" if owner is None else f"host {owner[0]}"
            notes.append(f"{out} holds {path.name}, the staging folder of a contact run that "
                         f"did not finish ({who}: whether it still runs cannot be told from "
                         "here); remove it if no run is writing into this directory")
            continue
        if process_alive(owner[1]):
            continue
        shutil.rmtree(path, ignore_errors=True)
        if path.exists():
            notes.append(f"{out} holds {path.name}, the staging folder of a run (process "
                         f"{owner[1]}) that ended without finishing; it could not be removed")
        else:
            notes.append(f"removed {path.name} from {out}: the staging folder of a run "
                         f"(process {owner[1]}, no longer running) that ended without "
                         "finishing (killed before it could clean up)")
    return notes


def _writing_bar(total: int, progress: bool, immediate: bool = False):
    """The second phase of ``contact run``'s progress: the files being written (shown at once
    for a long sweep, whose curve CSVs alone can take seconds; otherwise after half a
    second)."""
    return progress_bar(total, progress, "writing outputs", "file", 0 if immediate else 0.5)


def check_out_dir(out_dir) -> None:
    """Raise OSError, before anything is solved, when ``out_dir`` cannot receive the outputs:
    it exists and is not a directory, or it (or, when it does not exist yet, its nearest
    existing parent) is not writable: a file (resp. a directory) is made there and removed
    at once, since os.access says yes to root even where the system refuses (/proc, /sys,
    a read-only mount).  Nothing is left behind."""
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
    try:        # a directory made and removed: os.access says yes to root on /proc, /sys
        os.rmdir(tempfile.mkdtemp(dir=parent, prefix=".contact-write-check"))
    except OSError as exc:
        raise OSError(f"{out} cannot be created in {parent} ({exc.strerror or exc})") from None


def stale_outputs(out_dir, written) -> list[str]:
    """The names of the files in ``out_dir`` that a scene's run may write and this one did
    not (``written``: its paths): an earlier run's outputs, which a reader could take for
    this run's (the curve CSVs and figures of a field asked then, not now).  Other files
    are not a run's and are not named."""
    mine = {Path(p).name for p in written}
    return sorted(p.name for p in Path(out_dir).iterdir()
                  if p.name not in mine and p.is_file() and _written_by_a_run(p.name))


def _written_by_a_run(name: str) -> bool:
    """Whether :meth:`SceneWriter.finish` writes files of this name for some scene."""
    stem, _, suffix = name.rpartition(".")
    return (name in ("result.json", "sweep.csv", "subsurface.npz", "subsurface.csv")
            or (suffix in ("csv", "png") and stem in CURVE_FIELDS)
            or (suffix == "png" and stem.startswith("subsurface_")))


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

    def add_all(self, results) -> None:
        """The entries of cases, the next ones."""
        if not results:
            return
        sep = ",\n" + 2 * _INDENT
        texts = [case_text(res) for res in results]
        self._fh.write(("\n" + 2 * _INDENT if self._count == 0 else sep) + sep.join(
            text.json if text is not None else case_json(res)
            for res, text in zip(results, texts)))
        self._count += len(results)

    def finish(self, timing_s: float, messages) -> Path:
        """Write the keys after ``cases`` and close the file."""
        tail = _json_tail(timing_s, messages)
        self._fh.write(("\n" + _INDENT + "]" if self._count else "]")
                       + "".join(",\n" + _json_item(k, v) for k, v in tail.items()) + "\n}\n")
        self._fh.close()
        return self.path

    def close(self) -> None:
        self._fh.close()


def case_json(res: CaseResult) -> str:
    """A case's entry in result.json, as text at its indentation there."""
    return dumps_json(_json_case(res), _INDENT, 2)


class CaseEncoder:
    """What the writers make of a case on its own -- its entry of result.json and its rows
    of sweep.csv, as text (:class:`~contact.scene.table.CaseText`) -- made where the case is
    solved (a worker of an executor: :func:`contact.scene.iter_scene`'s ``encode``), so that
    the process that writes the files copies them instead of formatting them (formatting
    them there bounds how many workers it can keep busy).  A picklable callable:
    ``encoder(res)`` returns ``res`` with ``res.encoded`` set, or, ``lean``, the
    :class:`~contact.scene.table.CaseText` alone (for a writer that keeps nothing else of a
    case: :meth:`SceneWriter.encoder`).  ``table``: the text carries the case's row of the
    printed table too (:class:`~contact.scene.summary.TableRows`).
    """

    def __init__(self, scene: Scene, lean: bool = False, table: bool = False):
        self.scene, self.lean = scene, lean
        self._table = SweepTable(scene, scene.case_count)
        self._rows = TableRows(scene) if table else None

    def __call__(self, res: CaseResult):
        table_row = self._rows.columns(res) if self._rows is not None else None
        text = CaseText(res.index, res.label, res.time_s, tuple(res.warnings), case_json(res),
                        *row_lines(self._table, res), len(res.zones), table_row,
                        res.speed_warnings)
        if self.lean:
            return text
        res.encoded = text
        return res


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


#: Cases written at a time by :func:`write_outputs`.
_WRITE_SLICE = 1024
_CONTAINERS = frozenset((dict, list, tuple))
_INDENT = "  "
#: One encoder for every call (json.dumps with an option builds a new one each time).
_ENCODE = json.JSONEncoder(allow_nan=False).encode
_LITERALS = {None: "null", True: "true", False: "false"}


def _json_scalar(v) -> str:
    """json.dumps(v, allow_nan=False) for a number, string, bool or None, without its
    per-call set-up (result.json has a dozen scalars per case)."""
    t = type(v)
    if t is float:
        if not math.isfinite(v):
            raise ValueError(f"Out of range float values are not JSON compliant: {v!r}")
        return float.__repr__(v)
    if t is int:
        return int.__repr__(v)
    if t is str:
        return encode_basestring_ascii(v)
    if t is bool or v is None:
        return _LITERALS[v]
    return _ENCODE(v)


def dumps_json(obj, indent: str = _INDENT, _level: int = 0) -> str:
    """JSON text laid out to be read: a list or table of scalars (numbers, strings, booleans,
    null) on one line, as ``json.dumps`` writes it; a list or table holding lists or tables
    one item a line, indented.  A case of result.json is a few lines: its inputs, ends,
    exponents, diagnostics, one line each.

    The one-line parts are written by the json module's C encoder (faster than a number at a
    time here, most of either the shortest repr of each float); values it does not take as they are (numpy scalars, NaN)
    go the slow way, which says what is wrong."""
    t = type(obj)
    if (t is list or t is tuple) and _ATOMS.issuperset(map(type, obj)) or \
            t is dict and _ATOMS.issuperset(map(type, obj.values())) and \
            all(type(k) is str for k in obj):
        try:
            return _ENCODE_LINE(obj)
        except ValueError:                     # NaN or infinity: said with its value below
            pass
    if isinstance(obj, dict):
        if not _CONTAINERS.intersection(map(type, obj.values())):
            return "{" + ", ".join(f"{encode_basestring_ascii(str(k))}: {_json_scalar(v)}"
                                   for k, v in obj.items()) + "}"
        inner = indent * (_level + 1)
        items = [f"{inner}{encode_basestring_ascii(str(k))}: {dumps_json(v, indent, _level + 1)}"
                 for k, v in obj.items()]
        return "{\n" + ",\n".join(items) + "\n" + indent * _level + "}"
    if isinstance(obj, (list, tuple)):
        if not _CONTAINERS.intersection(map(type, obj)):     # scalars only
            return "[" + ", ".join(map(_json_scalar, obj)) + "]"
        inner = indent * (_level + 1)
        items = [inner + dumps_json(v, indent, _level + 1) for v in obj]
        return "[\n" + ",\n".join(items) + "\n" + indent * _level + "]"
    return _json_scalar(obj)


#: The JSON scalars (exact types) the C encoder writes as :func:`_json_scalar` does.
_ATOMS = frozenset((float, int, str, bool, type(None)))


def _c_encoder(item_separator: str):
    """obj -> its JSON text, by the json module's C encoder (NaN and infinity refused, no
    check for circular references: the data are made here), made once
    (``JSONEncoder.encode`` makes a new one per call, which costs more than encoding a table
    of five numbers); the json module's encoder where its C accelerator is missing."""
    make = json.encoder.c_make_encoder
    if make is None:                           # pragma: no cover - a Python without _json
        return json.JSONEncoder(allow_nan=False, separators=(item_separator, ": ")).encode
    chunks = make(None, None, encode_basestring_ascii, None, ": ", item_separator,
                  False, False, False)
    return lambda obj: "".join(chunks(obj, 0))


#: A list or table of scalars on one line.
_ENCODE_LINE = _c_encoder(", ")
