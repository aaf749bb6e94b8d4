"""The tidy sweep table: one row per case, one column per input that varies and per requested
scalar (sweep.csv, :meth:`SceneResult.table`, :meth:`SceneResult.to_dataframe`).

Columns, in this order (a group only when its field is asked):

* ``case``: the case's index in scene order (as in result.json);
* the inputs that vary: the swept keys in scene order (``speed`` too when ``velocity`` is
  swept); a scene without a sweep has every input (speed, friction, direction, load, the
  punch's dimension, velocity);
* one contact zone in every case (and ``"zones"`` not asked):
  ``x_left``, ``x_right`` (``"ends"``); ``alpha`` (exponent of p at the right end), ``beta``
  (at the left end), ``kappa`` (``"exponents"``); ``K_left``, ``K_right`` (``"sif"``, empty
  at a free end, where there is no singularity);
* several zones in some case (or ``"zones"`` asked): ``zones`` (their number), then for each
  zone j = 1 .. the largest number of zones in the sweep, left to right:
  ``zone{j}_x_left``, ``zone{j}_x_right``, ``zone{j}_load`` (its share of the load;
  ``"ends"`` or ``"zones"``), ``zone{j}_alpha``, ``zone{j}_beta``, ``zone{j}_kappa``
  (``"exponents"`` or ``"zones"``), ``zone{j}_K_left``, ``zone{j}_K_right`` (``"sif"``); a
  case with fewer zones leaves the columns of the missing ones empty;
* ``"subsurface"``: for q in ``max_shear``, ``max_tension``: ``q`` (the value), ``q_X``,
  ``q_Y``, ``q_depth``, ``q_half_width``, ``q_depth_over_a``;
* ``"constants"``: ``N11``, ``N12``, ``N21``, ``N22``, ``M12``, ``M21``, ``M22`` (0 for an
  aligned orthotropic material), ``rayleigh_speed``, ``eta_product``, ``eta_sum`` (the last
  two empty for a material without them: an anisotropic one, or a scene's
  ``[material] factory``); ``"roots"``: ``root{k}_real``, ``root{k}_imag``,
  k = 1..4 (eta1, -eta1, eta3, -eta3);
* partial slip or steady rolling (``tangential_load`` or ``creepage`` in ``[motion]``):
  ``tangential_load`` (Q) and, rolling, ``creepage`` (the one that follows from the other;
  not again where it is an input column), ``stick_zones`` (their number), ``stick_x_left``
  and ``stick_x_right`` (the left end of the first stick zone and the right end of the last:
  the stick zone's ends where there is one; result.json has each of several);
* the solver's diagnostics, always: ``n``, ``residual``, ``load_check``.

Numbers are written as Python's repr (they read back exactly), integers as integers, an empty
cell where a value is missing: ``pandas.read_csv("sweep.csv")`` gives the table of
:meth:`SceneResult.to_dataframe` (bit for bit with pandas >= 3; older pandas needs
``float_precision="round_trip"`` for that).
"""
from __future__ import annotations

import csv
import math
import shutil
from pathlib import Path
from typing import NamedTuple

import numpy as np

from .spec import SLIP_INPUTS


class CaseText(NamedTuple):
    """A case as the writers write it: its entry of result.json and its rows of sweep.csv
    as text, made where it was solved (:class:`contact.scene.output.CaseEncoder`).  A
    result's ``encoded``; what a lean encoder gives in its place, for a writer that keeps
    nothing else of a case: a tuple of strings and numbers crosses from a worker at a
    fraction of a result's cost to pickle and unpickle."""
    index: int
    label: str
    #: As :attr:`CaseResult.time_s`.
    time_s: float
    #: As :attr:`CaseResult.warnings`.
    warnings: tuple
    #: Its entry of result.json, at its indentation there.
    json: str
    #: Its raw row of sweep.csv (:class:`contact.scene.table.SweepTable`), a line of CSV.
    row: str
    #: Its row of sweep.csv when every case has one zone; None if it has several.
    single_zone_row: str | None
    #: How many contact zones it has.
    zones: int
    #: Its row of the printed table, (columns, the raw number of each cell), or None when
    #: not made (:meth:`contact.scene.summary.TableRows.columns`).
    table_row: tuple | None = None
    #: As :attr:`CaseResult.speed_warnings`.
    speed_warnings: tuple = ()


def case_text(res) -> CaseText | None:
    """The text of a case as the writers have it: a :class:`CaseText` itself, a result's
    ``encoded`` (None: not encoded)."""
    return res if type(res) is CaseText else res.encoded


SUBSURFACE_COLUMNS = ("value", "X", "Y", "depth", "half_width", "depth_over_a")
STICK_COLUMNS = ("stick_zones", "stick_x_left", "stick_x_right")
CONSTANTS_COLUMNS = ("N11", "N12", "N21", "N22", "M12", "M21", "M22", "rayleigh_speed",
                     "eta_product", "eta_sum")
DIAGNOSTICS_COLUMNS = ("n", "residual", "load_check")
PANDAS_HINT = "pip install 'sie-contact[pandas]'"


class SweepTable:
    """The sweep table built one case at a time.

    :meth:`row` gives a case's cells in a layout of its own ("raw": the case, its inputs, its
    number of zones, each zone's cells, then the rest), so that rows can be kept (or written
    to disk) as the cases come; once every case is in, :meth:`columns` and :meth:`lay_out`
    give the table of the module docstring, whose zone columns depend on the largest number
    of zones in the sweep.

    Parameters
    ----------
    scene : Scene
    count : int
        How many cases the table will have.
    """

    def __init__(self, scene, count: int):
        fields = scene.fields
        self.scene, self.count = scene, count
        ends = "ends" in fields or "zones" in fields
        exponents = "exponents" in fields or "zones" in fields
        self._sif = "sif" in fields
        self._zone_keys = [k for k, on in
                           (("x_left", ends), ("x_right", ends), ("load", ends),
                            ("alpha", exponents), ("beta", exponents), ("kappa", exponents),
                            ("K_left", self._sif), ("K_right", self._sif)) if on]
        self._rest = []
        motion = scene.motion
        if any(k in motion for k in SLIP_INPUTS):
            self._rest += (["tangential_load"] + (["creepage"] if motion.get("rolling") else [])
                           + list(STICK_COLUMNS))
        if "subsurface" in fields:
            self._rest += [q if k == "value" else f"{q}_{k}"
                           for q in ("max_shear", "max_tension") for k in SUBSURFACE_COLUMNS]
        if "constants" in fields:
            self._rest += list(CONSTANTS_COLUMNS)
        if "roots" in fields:
            self._rest += [f"root{k}_{part}" for k in range(1, 5) for part in ("real", "imag")]
        self._rest += list(DIAGNOSTICS_COLUMNS)
        self._inputs = None
        self._most_zones = 1

    def input_columns(self, first_inputs: dict) -> list:
        """The inputs that vary across the scene (every input of the first case's
        ``first_inputs`` when it has one case)."""
        scene = self.scene
        if not scene.sweep or self.count == 1:
            return list(first_inputs)
        swept = [key for _, key in scene.sweep]
        if "velocity" in swept and "speed" not in swept:
            swept.append("speed")
        return swept

    def note(self, res) -> None:
        """Take in what the layout needs of a case (a CaseResult or its CaseText: its inputs,
        the first time; its number of zones), without making its row (made elsewhere:
        :class:`contact.scene.output.CaseEncoder`)."""
        text = case_text(res)
        if self._inputs is None:
            self._inputs = self.input_columns(res.entry["inputs"] if type(res) is not CaseText
                                              else self.scene.case(res.index).inputs)
            # Q or the creepage given as an input is its input column, not again here
            self._rest = [c for c in self._rest if c not in self._inputs]
        self.note_zones(text.zones if text is not None else len(res.zones))

    def note_zones(self, zones: int) -> None:
        """Take in a case's number of zones (the most of several cases')."""
        if zones > self._most_zones:
            self._most_zones = zones

    def row(self, res) -> list:
        """A case's raw row (class docstring): int, float or None (an empty cell) each."""
        e = res.entry
        self.note(res)
        cells = [res.index] + [e["inputs"].get(k) for k in self._inputs] + [len(res.zones)]
        sifs = _zone_sifs(res) if self._sif else None
        for j, z in enumerate(res.zones):
            sif = sifs[j] if sifs is not None and j < len(sifs) else {}
            zone = {"x_left": z["ends"][0], "x_right": z["ends"][1], "load": z["load"],
                    "alpha": z["exponents"]["right"], "beta": z["exponents"]["left"],
                    "kappa": z["index"], "K_left": sif.get("left"), "K_right": sif.get("right")}
            cells += [zone[k] for k in self._zone_keys]
        rest = dict(res.diagnostics)
        if "stick_zones" in e:
            rest.update(slip_cells(e))
        sub = e.get("subsurface")
        if sub is not None:
            rest.update((q if k == "value" else f"{q}_{k}", sub[q][k])
                        for q in ("max_shear", "max_tension") for k in SUBSURFACE_COLUMNS)
        if "constants" in e:
            rest.update((k, e["constants"][k]) for k in CONSTANTS_COLUMNS)
        if "roots" in e:
            for k in range(4):
                rest[f"root{k + 1}_real"] = e["roots"]["real"][k]
                rest[f"root{k + 1}_imag"] = e["roots"]["imag"][k]
        cells += [rest.get(c) for c in self._rest]
        return [_plain(v) for v in cells]

    @property
    def several_zones(self) -> bool:
        """Whether the table has a column per zone (``"zones"`` asked, or several zones in
        some case read so far)."""
        return "zones" in self.scene.fields or self._most_zones > 1

    def columns(self) -> list:
        """The column names, once every row is in."""
        columns = ["case"] + (self._inputs or [])
        if self.several_zones:
            columns.append("zones")
            columns += [f"zone{j}_{k}" for j in range(1, self._most_zones + 1)
                        for k in self._zone_keys]
        else:
            columns += [k for k in self._zone_keys if k != "load"]
        return columns + self._rest

    def lay_out(self, raw: list, blank=None) -> list:
        """A raw row (:meth:`row`, or its cells as text) in the table's columns, ``blank`` in
        the cells of zones the case does not have."""
        if not self.several_zones:
            return self.single_zone_row(raw)
        start = 1 + len(self._inputs)
        zones = int(raw[start])
        width = len(self._zone_keys)
        end = start + 1 + zones * width
        return raw[:end] + [blank] * ((self._most_zones - zones) * width) + raw[end:]

    def single_zone_row(self, raw: list) -> list:
        """The raw row of a case with one zone in the columns of a table of such cases
        (without the number of zones and the zone's share of the load): its row of sweep.csv
        when every case of the sweep has one zone."""
        start = 1 + len(self._inputs)
        kept = [raw[start + 1 + k] for k, key in enumerate(self._zone_keys) if key != "load"]
        return raw[:start] + kept + raw[start + 1 + len(self._zone_keys):]


def slip_cells(entry: dict) -> dict:
    """A partial slip or rolling case's cells: Q, the creepage, the number of stick zones
    and the ends of their span (module docstring)."""
    stick = entry["stick_zones"]
    return {"tangential_load": entry["tangential_load"], "creepage": entry["creepage"],
            "stick_zones": len(stick), "stick_x_left": stick[0][0] if stick else None,
            "stick_x_right": stick[-1][1] if stick else None}


def _zone_sifs(res) -> list | None:
    """The SIFs of each zone of a case ({"left": K, "right": K}, only at singular ends)."""
    zones = res.entry.get("zones")
    if zones and all("sif" in z for z in zones):
        return [z["sif"] for z in zones]
    if "sif" in res.entry:
        return [res.entry["sif"]]
    return None


def sweep_table(result) -> tuple:
    """(columns, rows) of the sweep table (module docstring) of a SceneResult; a row is a
    list of int, float or None (an empty cell), one per column."""
    table = SweepTable(result.scene, len(result.cases))
    raw = [table.row(res) for res in result.cases]
    return table.columns(), [table.lay_out(row) for row in raw]


class SweepCsv:
    """sweep.csv written one case at a time: each case's raw row (:class:`SweepTable`) goes to
    a spool file as it comes, and :meth:`write` lays the rows out under their header.

    While every case has one zone (and ``"zones"`` is not asked) the table's columns are
    known from the first case on, and each case's row as such a table has it
    (:meth:`SweepTable.single_zone_row`) also goes, under that header, to a second file,
    which :meth:`write` then moves into place as sweep.csv: a sweep of one-zone cases is
    neither read back nor copied at the end (a sweep of millions of cases writes a table
    of some hundred MB, which the workers of a pool would wait for).  A case with several zones drops
    that file, and the rows are laid out again from the raw spool.

    Parameters
    ----------
    scene : Scene
    count : int
        How many cases will be added.
    spool : Path
        The file the raw rows go to (removed by :meth:`write`); the one-zone table goes to
        ``spool`` with the suffix ``.single``.
    """

    def __init__(self, scene, count: int, spool):
        self.table = SweepTable(scene, count)
        self._spool = Path(spool)
        self._fh = open(self._spool, "w", newline="", encoding="utf-8")
        self._single_path = self._spool.with_suffix(".single")
        self._single = None if "zones" in scene.fields else \
            open(self._single_path, "w", newline="", encoding="utf-8")
        self._header = False                    # the one-zone table's header written

    def add_all(self, results) -> None:
        """The rows of cases, the next ones (made where the cases were solved,
        :class:`contact.scene.output.CaseEncoder`, or here)."""
        texts = [case_text(res) for res in results]
        if results and None not in texts:          # all made where they were solved
            self.table.note(results[0])
            self.table.note_zones(max(text.zones for text in texts))
            rows = [(text.row, text.single_zone_row) for text in texts]
        else:
            rows = []
            for res, text in zip(results, texts):
                if text is None:
                    rows.append(row_lines(self.table, res))     # its row notes it
                else:
                    self.table.note(res)
                    rows.append((text.row, text.single_zone_row))
        self._fh.write("".join(raw for raw, _ in rows))
        if self._single is not None:
            single_rows = [single for _, single in rows]
            if None in single_rows:               # a case with several zones: laid out later
                self._drop_single()
            elif single_rows:
                if not self._header:              # the columns: the scene's, the first case's
                    csv.writer(self._single).writerow(self.table.columns())
                    self._header = True
                self._single.write("".join(single_rows))

    def _drop_single(self) -> None:
        self._single.close()
        self._single_path.unlink()
        self._single = None

    def write(self, path) -> Path:
        """sweep.csv at ``path``: the header and one row per case added, in order."""
        path = Path(path)
        self._fh.close()
        if self._single is not None and self._header and not self.table.several_zones:
            self._single.close()
            self._single = None
            shutil.move(self._single_path, path)     # a rename within the spool directory
        else:
            with open(path, "w", newline="", encoding="utf-8") as fh:
                w = csv.writer(fh)
                w.writerow(self.table.columns())
                with open(self._spool, newline="", encoding="utf-8") as raw:
                    w.writerows(self.table.lay_out(row, "") for row in csv.reader(raw))
            if self._single is not None:
                self._drop_single()
        self._spool.unlink()
        return path

    def close(self) -> None:
        """Close the spool files (left for their directory's owner to remove)."""
        self._fh.close()
        if self._single is not None:
            self._single.close()


def _plain(v):
    """int, float or None (for NaN and missing values)."""
    t = type(v)
    if t is float:                             # most cells, first
        return None if v != v else v
    if t is int:
        return v
    if v is None or isinstance(v, (bool, np.bool_)):
        return None if v is None else int(v)
    if isinstance(v, (int, np.integer)):
        return int(v)
    v = float(v)
    return None if math.isnan(v) else v


def _cell(v) -> str:
    if v is None:
        return ""
    return str(v) if isinstance(v, int) else repr(v)


def to_dataframe(result):
    """The sweep table as a pandas DataFrame, with the dtypes ``pandas.read_csv`` gives
    sweep.csv: int64 for a column of integers without gaps, float64 (NaN in the gaps) for
    any other numeric column."""
    try:
        import pandas as pd
    except ImportError:
        raise ImportError("SceneResult.to_dataframe needs pandas, an optional extra: "
                          f"{PANDAS_HINT} (or read sweep.csv with any CSV reader)") from None
    columns, rows = sweep_table(result)
    data = {}
    for k, name in enumerate(columns):
        col = [row[k] for row in rows]
        if col and all(isinstance(v, int) for v in col):
            data[name] = np.array(col, dtype=np.int64)
        else:
            data[name] = np.array([np.nan if v is None else v for v in col], dtype=float)
    return pd.DataFrame(data, columns=columns)


def raw_cells(table: SweepTable, res) -> list:
    """A case's raw row of sweep.csv as the cells the csv module writes."""
    return [_cell(v) for v in table.row(res)]


def row_lines(table: SweepTable, res) -> tuple:
    """(its raw row, its row in a sweep of one-zone cases or None if it has several zones)
    of a case, as lines of CSV text (:class:`SweepCsv`)."""
    cells = raw_cells(table, res)
    single = _csv_line(table.single_zone_row(cells)) if len(res.zones) == 1 else None
    return _csv_line(cells), single


def _csv_line(cells) -> str:
    """A row of sweep.csv as the csv module writes it: its cells are numbers and empty
    cells, which it writes as they are (nothing to quote; never a lone empty cell, the case
    index comes first), ending in its "\\r\\n"."""
    return ",".join(cells) + "\r\n"
