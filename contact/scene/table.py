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
* ``"constants"``: ``N11``, ``N12``, ``N21``, ``N22``, ``rayleigh_speed``, ``eta_product``,
  ``eta_sum``; ``"roots"``: ``root{k}_real``, ``root{k}_imag``, k = 1..4 (eta1, -eta1, eta3,
  -eta3);
* the solver's diagnostics, always: ``n``, ``residual``, ``load_check``.

Numbers are written as Python's repr (they read back exactly), integers as integers, an empty
cell where a value is missing: ``pandas.read_csv("sweep.csv")`` gives the table of
:meth:`SceneResult.to_dataframe` (bit for bit with pandas >= 3; older pandas needs
``float_precision="round_trip"`` for that).
"""
from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

SUBSURFACE_COLUMNS = ("value", "X", "Y", "depth", "half_width", "depth_over_a")
CONSTANTS_COLUMNS = ("N11", "N12", "N21", "N22", "rayleigh_speed", "eta_product", "eta_sum")
DIAGNOSTICS_COLUMNS = ("n", "residual", "load_check")
PANDAS_HINT = "pip install 'sie-contact[pandas]'"


def input_columns(result) -> list:
    """The inputs that vary across the scene (every input when it has one case)."""
    scene = result.scene
    if not scene.sweep or len(result.cases) == 1:
        return list(result.cases[0].entry["inputs"]) if result.cases else []
    swept = [key for _, key in scene.sweep]
    if "velocity" in swept and "speed" not in swept:
        swept.append("speed")
    return swept


def _several_zones(result) -> bool:
    return "zones" in result.scene.fields or any(len(r.zones) > 1 for r in result.cases)


def _zone_sifs(res) -> list | None:
    """The SIFs of each zone of a case ({"left": K, "right": K}, only at singular ends)."""
    zones = res.entry.get("zones")
    if zones and all("sif" in z for z in zones):
        return [z["sif"] for z in zones]
    if "sif" in res.entry:
        return [res.entry["sif"]]
    return None


def sweep_table(result) -> tuple:
    """(columns, rows) of the sweep table (module docstring); a row is a list of int, float
    or None (an empty cell), one per column."""
    fields = result.scene.fields
    inputs = input_columns(result)
    columns = ["case"] + inputs
    several = _several_zones(result)
    want_ends = "ends" in fields or (several and "zones" in fields)
    want_exp = "exponents" in fields or (several and "zones" in fields)
    want_sif = "sif" in fields
    nz = max((len(r.zones) for r in result.cases), default=1)
    if several:
        columns.append("zones")
        for j in range(1, nz + 1):
            columns += [f"zone{j}_{k}" for k, on in
                        (("x_left", want_ends), ("x_right", want_ends), ("load", want_ends),
                         ("alpha", want_exp), ("beta", want_exp), ("kappa", want_exp),
                         ("K_left", want_sif), ("K_right", want_sif)) if on]
    else:
        columns += [k for k, on in (("x_left", want_ends), ("x_right", want_ends),
                                    ("alpha", want_exp), ("beta", want_exp),
                                    ("kappa", want_exp), ("K_left", want_sif),
                                    ("K_right", want_sif)) if on]
    if "subsurface" in fields:
        for q in ("max_shear", "max_tension"):
            columns += [q if k == "value" else f"{q}_{k}" for k in SUBSURFACE_COLUMNS]
    if "constants" in fields:
        columns += list(CONSTANTS_COLUMNS)
    if "roots" in fields:
        columns += [f"root{k}_{part}" for k in range(1, 5) for part in ("real", "imag")]
    columns += list(DIAGNOSTICS_COLUMNS)

    rows = []
    for res in result.cases:
        e = res.entry
        cells = {"case": res.index}
        cells.update((k, e["inputs"].get(k)) for k in inputs)
        sifs = _zone_sifs(res) if want_sif else None
        prefixes = [f"zone{j}_" for j in range(1, len(res.zones) + 1)] if several else [""]
        if several:
            cells["zones"] = len(res.zones)
        for j, (prefix, z) in enumerate(zip(prefixes, res.zones)):
            if want_ends:
                cells[prefix + "x_left"], cells[prefix + "x_right"] = z["ends"]
                if several:                       # one zone carries the whole load
                    cells[prefix + "load"] = z["load"]
            if want_exp:
                cells[prefix + "alpha"] = z["exponents"]["right"]
                cells[prefix + "beta"] = z["exponents"]["left"]
                cells[prefix + "kappa"] = z["index"]
            if sifs is not None and j < len(sifs):
                cells[prefix + "K_left"] = sifs[j].get("left")
                cells[prefix + "K_right"] = sifs[j].get("right")
        sub = e.get("subsurface")
        if sub is not None:
            for q in ("max_shear", "max_tension"):
                for k in SUBSURFACE_COLUMNS:
                    cells[q if k == "value" else f"{q}_{k}"] = sub[q][k]
        if "constants" in e:
            cells.update((k, e["constants"][k]) for k in CONSTANTS_COLUMNS)
        if "roots" in e:
            for k in range(4):
                cells[f"root{k + 1}_real"] = e["roots"]["real"][k]
                cells[f"root{k + 1}_imag"] = e["roots"]["imag"][k]
        cells.update(res.diagnostics)
        rows.append([_plain(cells.get(c)) for c in columns])
    return columns, rows


def _plain(v):
    """int, float or None (for NaN and missing values)."""
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


def write_sweep_csv(result, path) -> Path:
    """sweep.csv: the sweep table (module docstring), a header and one row per case."""
    path = Path(path)
    columns, rows = sweep_table(result)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(columns)
        w.writerows([_cell(v) for v in row] for row in rows)
    return path


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
