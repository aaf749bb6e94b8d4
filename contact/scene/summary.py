"""The console table of ``contact run``: one row per case for a short sweep; for a long one the
first and the last cases and the smallest and largest value of each column over every case
(:class:`TableSummary`, fed case by case)."""
from __future__ import annotations

import collections
import math

import numpy as np

import contact

from .run import CaseResult, SceneResult, _inputs_text
from .table import CaseText, slip_cells
from .spec import SUBSURFACE_CUT, Scene, _fmt

#: The printed table shows every case of a sweep of at most this many; a longer one shows the
#: first and the last TABLE_ROWS // 2, and the smallest and largest value of each column over
#: every case.
TABLE_ROWS = 40


def format_table(result: SceneResult) -> str:
    """A short text table: a row per case (the first and the last TABLE_ROWS // 2 of a longer
    sweep, then each column's smallest and largest value over every case) with its swept
    inputs, ends, exponents, peak pressure, SIFs and sigma_XX extremes (what was requested),
    the solver's check (the larger of its residual and load check) and the time taken.

    When a case has several contact zones, a ``zones`` column gives their number, and the ends,
    exponents and SIFs shown are those of the outer ends (result.json lists every zone).  A
    case in partial slip or rolling adds the tangential load and the creepage that are not
    swept and the span of its stick zones (``stick_zones`` where it has several)."""
    summary = TableSummary(result.scene, len(result.cases))
    summary.add_all(result.cases)
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
        self.rows = TableRows(scene)
        self._columns = dict.fromkeys(["case"] + self.rows.swept)
        self._head = []
        self._tail = collections.deque(maxlen=TABLE_ROWS // 2)
        self._lowest, self._highest = {}, {}          # column -> (value, cell)
        self._first_inputs = None
        self._added = 0
        self._other_than_one_zone = self._several_zones = False
        self._free_end = self._cut = False

    def add(self, res) -> None:
        """The next case, in scene order (:meth:`add_all` of one)."""
        self.add_all([res])

    def add_all(self, results) -> None:
        """The next cases, in scene order: CaseResult, or CaseText carrying its row
        (:class:`contact.scene.output.CaseEncoder` with ``table=True``).  Rows come as
        their columns' raw numbers (:meth:`TableRows.columns`) and are taken a column at a
        time: a column's extremes are the min and max of its finite numbers, and only the
        cells shown are formatted (:func:`table_cell`; formatting every cell of every case
        would cost each case)."""
        by_columns = {}                     # a row's columns -> its cases' raw numbers
        zones = []
        for res in results:
            if type(res) is CaseText:
                keys, raw = res.table_row
                zones.append(res.zones)
                if self._first_inputs is None:
                    self._first_inputs = self.scene.case(res.index).inputs
            else:
                keys, raw = self.rows.columns(res)
                zones.append(len(res.zones))
                if self._first_inputs is None:
                    self._first_inputs = res.entry["inputs"]
                self._cut |= _cut_below_surface(res.entry)   # a text has no map: never cut
            by_columns.setdefault(keys, []).append(raw)
            if self._added < TABLE_ROWS // 2 or self.count <= TABLE_ROWS:
                self._head.append((keys, raw))
            else:
                self._tail.append((keys, raw))
            self._added += 1
        if not zones:
            return
        self._other_than_one_zone |= min(zones) != 1 or max(zones) != 1
        self._several_zones |= max(zones) > 1
        for keys, rows in by_columns.items():
            self._columns.update(dict.fromkeys(keys))
            for key, column in zip(keys, zip(*rows)):
                if key in ("K_left", "K_right") and None in column:
                    self._free_end = True
                if key in _UNRANKED:
                    continue
                numbers = [v for v in column if isinstance(v, (int, float)) and math.isfinite(v)]
                if numbers:
                    self._extremes(key, min(numbers), max(numbers))

    def _extremes(self, key: str, lowest, highest) -> None:
        """Keep a column's smallest and largest number over the cases so far."""
        if key not in self._lowest or lowest < self._lowest[key]:
            self._lowest[key] = lowest
        if key not in self._highest or highest > self._highest[key]:
            self._highest[key] = highest

    def text(self, timing_s: float) -> str:
        """The table of the cases added, with its notes and the run's time."""
        scene = self.scene
        mat = scene.material
        c_R = contact.rayleigh_speed(mat.build())
        head = [scene.title,
                f"  scene: {scene.source}",
                f"  material: {mat.describe()}; Rayleigh speed c_R = {c_R:.10f}",
                f"  fixed inputs: {_inputs_text(_fixed_inputs(scene, self._first_inputs or {}))}"]
        columns = [k for k in self._columns
                   if k != "time ms" and (k != "zones" or self._other_than_one_zone)]
        columns.append("time ms")
        omitted = self._added - len(self._head) - len(self._tail)
        extremes = []
        if omitted:
            extremes = [{"case": "min", **_cells(self._lowest, self._lowest.values())},
                        {"case": "max", **_cells(self._highest, self._highest.values())}]
        first = [_cells(keys, raw) for keys, raw in self._head]
        tail = [_cells(keys, raw) for keys, raw in self._tail]
        shown = first + tail + extremes
        widths = {k: max(len(k), *(len(r.get(k, "")) for r in shown)) for k in columns}

        def line(row):
            return "  " + "  ".join(f"{row.get(k, ''):>{widths[k]}}" for k in columns)

        lines = head + ["", "  " + "  ".join(f"{k:>{widths[k]}}" for k in columns)]
        lines += [line(r) for r in first]
        if omitted:
            lines.append(line({"case": "..."}).rstrip())
            lines += [line(r) for r in tail + extremes]
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


class TableRows:
    """A case's row of the printed table (:func:`_table_row`) as :class:`TableSummary`
    takes it (:meth:`columns`): picklable, so that a worker can make it where the case is
    solved (:class:`contact.scene.output.CaseEncoder`)."""

    def __init__(self, scene: Scene):
        swept = [key for _, key in scene.sweep]
        if "velocity" in swept:
            swept.append("speed")
        #: The swept inputs, the table's first columns after ``case``.
        self.swept = swept
        self._outer = ("ends" in scene.fields or "zones" in scene.fields,
                       "exponents" in scene.fields, "sif" in scene.fields)

    def columns(self, res: CaseResult) -> tuple:
        """(columns, raw) of a case's row: the names of its columns and the number each
        cell is formatted from (:func:`table_cell`), None for a cell without one (a free
        end's SIF, a field without a finite value), a pair for ``max shear @ depth/a``."""
        row = _table_row(res, self.swept, self._outer)
        return tuple(row), tuple(row.values())


def _fixed(digits: int):
    """A cell of ``digits`` significant digits (``%g``), "-" without a number."""
    spec = f".{digits}g"
    return lambda v: "-" if v is None else format(v, spec)


#: How a column's raw number is printed (:func:`table_cell`); any other column is a swept
#: input (:func:`contact.scene.spec._fmt`).
_CELLS = {"case": str, "zones": str,
          "x_left": _fixed(10), "x_right": _fixed(10), "alpha": _fixed(8), "beta": _fixed(8),
          "K_left": _fixed(6), "K_right": _fixed(6), "max p (sampled)": _fixed(6),
          "stick_zones": str, "stick_x_left": _fixed(10), "stick_x_right": _fixed(10),
          "min sigma_xx": _fixed(6), "max sigma_xx": _fixed(6),
          "max shear @ depth/a": lambda v: f"{v[0]:.4g} @ {v[1]:.4g}",
          "check": lambda v: f"{v:.1e}", "time ms": lambda v: f"{v:.1f}"}
#: Columns without extremes: the case's index, and a cell of two numbers.
_UNRANKED = frozenset(("case", "max shear @ depth/a"))


def table_cell(key: str, raw) -> str:
    """The printed cell of column ``key`` holding ``raw`` (:meth:`TableRows.columns`).
    Each format rounds monotonically, so that the cell of a column's smallest raw number is
    its smallest printed value (what :class:`TableSummary` shows as the column's min)."""
    return _CELLS.get(key, _fmt)(raw)


def _cells(keys: tuple, raw: tuple) -> dict:
    """A row's printed cells by column."""
    return {k: table_cell(k, v) for k, v in zip(keys, raw)}


def _table_row(res: CaseResult, swept: list, outer: tuple) -> dict:
    """A case's raw numbers in the printed table, by column (the ``zones`` column always:
    the table drops it when every case has one zone)."""
    e = res.entry
    row = {"case": res.index}
    inputs = e["inputs"]
    row.update({k: inputs[k] for k in swept})
    row["zones"] = len(res.zones)
    zones = e.get("zones") if len(res.zones) > 1 else None
    if "ends" in e:
        row["x_left"], row["x_right"] = e["ends"]
    elif zones and outer[0]:
        row["x_left"], row["x_right"] = zones[0]["ends"][0], zones[-1]["ends"][1]
    if "exponents" in e:
        row["alpha"] = e["exponents"]["right"]
        row["beta"] = e["exponents"]["left"]
    elif zones and outer[1]:
        row["alpha"] = zones[-1]["exponents"]["right"]
        row["beta"] = zones[0]["exponents"]["left"]
    if "pressure" in e:
        row["max p (sampled)"] = _extreme(e["pressure"]["values"], np.nanmax)
    sif = e.get("sif")
    if sif is None and zones and outer[2]:
        sif = {k: v for k, v in (("left", zones[0]["sif"].get("left")),
                                 ("right", zones[-1]["sif"].get("right"))) if v is not None}
    if sif is not None:
        row["K_left"] = sif.get("left")
        row["K_right"] = sif.get("right")
    if "stick_zones" in e:
        # Q, the creepage (rolling) where not swept, and the stick zones' span
        for k, v in slip_cells(e).items():
            if k not in swept and v is not None and (k != "stick_zones" or v > 1):
                row[k] = v
    if "sigma_xx" in e:
        row["min sigma_xx"] = _extreme(e["sigma_xx"]["values"], np.nanmin)
        row["max sigma_xx"] = _extreme(e["sigma_xx"]["values"], np.nanmax)
    if "subsurface" in e:
        ms = e["subsurface"]["max_shear"]
        row["max shear @ depth/a"] = (ms["value"], ms["depth_over_a"])
    if res.diagnostics:
        d = res.diagnostics
        row["check"] = max(d["residual"], d["load_check"])
    row["time ms"] = 1e3 * res.time_s
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


def _extreme(values, fn) -> float | None:
    """fn (np.nanmax or np.nanmin) of a sampled field, None without a finite sample."""
    v = np.asarray(values, dtype=float)
    if not np.any(np.isfinite(v)):
        return None
    return float(fn(v)) + 0.0
