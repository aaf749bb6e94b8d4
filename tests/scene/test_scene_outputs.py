"""What ``contact run`` writes for a researcher: the tidy sweep table
(sweep.csv, SceneResult.to_dataframe), the solver's diagnostics, exponents labelled by end,
clean sampled x, the warning for a grid narrower than the contact, an --out that cannot be
written failing before anything is solved, and the figures (a coloured family, fast, or none).

Oracles: contact.solve called directly with the same inputs, and result.json of the same run.
"""
from __future__ import annotations

import csv
import json
import os
import sys
import textwrap
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import contact
from contact.scene import load_scene, parse_scene_text, run_scene
from contact.scene.figures import MAX_CURVES
from contact.scene.output import _writing_bar
from contact.scene.spec import clean_linspace

from cli_helpers import run_cli

SCENES = Path(__file__).resolve().parents[2] / "validation" / "scenes"

CYLINDER_SWEEP = """
title = "cylinder: speed x friction"
[material]
preset = "zhou2014"
[punch]
kind = "cylindrical"
radius = 100.0
[motion]
load = 0.01
speed = [0.3, 0.6]
friction = [0.0, 0.1, 0.3]
direction = -1
[outputs]
fields = ["ends", "exponents", "sif", "pressure"]
x = { start = -0.8, stop = 0.8, num = 801 }
"""


def write_scene(tmp_path, text, name="scene.toml"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return path


def read_sweep(path):
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    return rows[0], rows[1:]


def cell(text):
    """A sweep.csv cell as Python reads it: None when empty, int, or float."""
    if text == "":
        return None
    try:
        return int(text)
    except ValueError:
        return float(text)


@pytest.fixture(scope="module")
def cylinder_run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("cylinder")
    scene = write_scene(tmp, CYLINDER_SWEEP)
    rc, stdout, stderr = run_cli("run", scene, "--out", tmp / "out", "--no-figures")
    assert rc == 0, stderr
    out = tmp / "out"
    return json.loads((out / "result.json").read_text()), (out / "result.json").read_text(), \
        out, stdout


def reference(inputs):
    return contact.solve(contact.zhou2014(), contact.CylindricalPunch(inputs["radius"]
                                                                      if "radius" in inputs
                                                                      else 100.0),
                         load=inputs["load"], speed=inputs["speed"],
                         friction=inputs["friction"], direction=inputs["direction"])


# --------------------------------------------------------------------------
# sweep.csv
# --------------------------------------------------------------------------
def test_sweep_csv_columns_and_values_equal_result_json_and_contact_solve(cylinder_run):
    result, _, out, _ = cylinder_run
    header, rows = read_sweep(out / "sweep.csv")
    assert header == ["case", "speed", "friction", "x_left", "x_right", "alpha", "beta",
                      "kappa", "K_left", "K_right", "n", "residual", "load_check"]
    assert len(rows) == 6 == len(result["cases"])
    for k, (row, case) in enumerate(zip(rows, result["cases"])):
        r = dict(zip(header, map(cell, row)))
        assert r["case"] == k
        assert (r["speed"], r["friction"]) == (case["inputs"]["speed"],
                                               case["inputs"]["friction"])
        assert [r["x_left"], r["x_right"]] == case["ends"]
        assert (r["beta"], r["alpha"]) == (case["exponents"]["left"],
                                           case["exponents"]["right"])
        assert {k: r[k] for k in ("n", "residual", "load_check")} == case["diagnostics"]
        ref = reference(case["inputs"])
        assert (r["x_left"], r["x_right"]) == ref.ends
        assert (r["alpha"], r["beta"], r["kappa"]) == (ref.alpha, ref.beta, ref.kappa)
        assert r["K_left"] is None and r["K_right"] is None     # free ends: empty cells
        assert row[header.index("K_left")] == ""
        assert (r["n"], r["load_check"]) == (ref.n, ref.load_check)
        assert r["residual"] == ref.residual
    # scene order: the first swept key varies slowest
    assert [cell(row[1]) for row in rows] == [0.3] * 3 + [0.6] * 3


def test_sweep_csv_of_two_zones_has_per_zone_columns(tmp_path):
    rc, _, err = run_cli("run", SCENES / "w_face_two_zones.toml", "--out", tmp_path,
                         "--no-figures", "--quiet")
    assert rc == 0, err
    result = json.loads((tmp_path / "result.json").read_text())
    header, rows = read_sweep(tmp_path / "sweep.csv")
    per_zone = ["x_left", "x_right", "load", "alpha", "beta", "kappa"]
    assert header == (["case", "friction", "zones"]
                      + [f"zone{j}_{k}" for j in (1, 2) for k in per_zone]
                      + ["n", "residual", "load_check"])
    for row, case in zip(rows, result["cases"]):
        r = dict(zip(header, map(cell, row)))
        assert r["zones"] == len(case["zones"]) == 2
        for j, z in enumerate(case["zones"], start=1):
            assert [r[f"zone{j}_x_left"], r[f"zone{j}_x_right"]] == z["ends"]
            assert r[f"zone{j}_load"] == z["load"]
            assert (r[f"zone{j}_alpha"], r[f"zone{j}_beta"]) == (z["exponents"]["right"],
                                                                 z["exponents"]["left"])
            assert r[f"zone{j}_kappa"] == z["index"]
        assert {k: r[k] for k in ("n", "residual", "load_check")} == case["diagnostics"]
        assert r["load_check"] < 1e-12 and r["residual"] < 1e-10


def test_a_one_zone_sweeps_csv_is_the_file_written_as_the_cases_came(tmp_path, monkeypatch):
    """A sweep whose cases each have one zone: sweep.csv is the one-zone table written under
    its header as the cases came, moved into place, neither laid out again from the raw rows
    nor copied at the end; it equals the table made from the kept results."""
    from contact.scene import table as table_module

    def read_back(*args, **kwargs):
        raise AssertionError("sweep.csv read back at the end")
    path = write_scene(tmp_path, CYLINDER_SWEEP)
    columns, table = run_scene(load_scene(path)).table()
    monkeypatch.setattr(table_module.SweepTable, "lay_out", read_back)
    monkeypatch.setattr(table_module.shutil, "copyfileobj", read_back)
    rc, _, err = run_cli("run", path, "--out", tmp_path / "out", "--quiet", "--no-figures")
    assert rc == 0, err
    header, rows = read_sweep(tmp_path / "out" / "sweep.csv")
    assert header == columns and "zones" not in header
    assert [[cell(c) for c in row] for row in rows] == table


@pytest.mark.slow
def test_sweep_csv_when_a_later_case_has_two_zones_equals_the_table(tmp_path):
    """sweep.csv is written from the one-zone rows while every case has one zone; a case
    with two (the W face at a light load, after heavy loads that close the gap) lays every
    row out again with per-zone columns, the one-zone cases' second zone empty: the file
    equals the table made from the kept results (SceneResult.table)."""
    text = (SCENES / "w_face_two_zones.toml").read_text()
    text = text.replace("load = 0.02", "load = [3.0, 2.5, 0.02]").replace(
        '"pressure", "sigma_xx"', '"sif"').replace(
        "x = { start = -1.25, stop = 1.25, num = 1001 }", "")
    path = tmp_path / "s.toml"
    path.write_text(text)
    rc, _, err = run_cli("run", path, "--out", tmp_path / "out", "--quiet")
    assert rc == 0, err
    header, rows = read_sweep(tmp_path / "out" / "sweep.csv")
    columns, table = run_scene(load_scene(path)).table()
    assert header == columns and "zone2_x_left" in header
    assert [[cell(c) for c in row] for row in rows] == table
    zones = [row[columns.index("zones")] for row in table]
    assert zones == [1, 1, 1, 1, 2, 2]                    # loads 3.0, 2.5 close the gap
    first = table[0]
    assert first[columns.index("zone2_x_left")] is None


def test_sweep_table_sifs_and_a_single_case_lists_every_input(tmp_path):
    s = parse_scene_text(textwrap.dedent("""
        [material]
        preset = "zhou2014"
        [punch]
        kind = "triangular"
        slope = 0.01
        [motion]
        load = 0.01
        speed = 0.6
        friction = 0.3
        [outputs]
        fields = ["sif", "ends"]
    """))
    res = run_scene(s)
    columns, rows = res.table()
    assert columns == ["case", "speed", "friction", "direction", "load", "slope", "x_left",
                       "x_right", "K_left", "K_right", "n", "residual", "load_check"]
    ref = contact.solve(contact.zhou2014(), contact.TriangularPunch(0.01), load=0.01,
                        speed=0.6, friction=0.3)
    r = dict(zip(columns, rows[0]))
    assert set(ref.sif) == {"left"}                      # the corner: its SIF; free: empty
    assert r["K_left"] == ref.sif["left"] and r["K_right"] is None
    assert (r["speed"], r["friction"], r["direction"], r["load"], r["slope"]) == (
        0.6, 0.3, -1, 0.01, 0.01)


def test_to_dataframe_equals_reading_sweep_csv(cylinder_run):
    pd = pytest.importorskip("pandas")
    result, _, out, _ = cylinder_run
    scene = parse_scene_text(CYLINDER_SWEEP)
    df = run_scene(scene).to_dataframe()
    exact = {} if int(pd.__version__.split(".")[0]) >= 3 else {"float_precision": "round_trip"}
    pd.testing.assert_frame_equal(df, pd.read_csv(out / "sweep.csv", **exact), check_exact=True)
    assert df["K_left"].isna().all() and df["n"].dtype == np.int64


def test_to_dataframe_without_pandas_says_how_to_install(monkeypatch):
    res = run_scene(parse_scene_text(CYLINDER_SWEEP.replace("[0.3, 0.6]", "0.6")
                                     .replace("[0.0, 0.1, 0.3]", "0.3")))
    monkeypatch.setitem(sys.modules, "pandas", None)       # import pandas -> ImportError
    with pytest.raises(ImportError, match=r"pip install 'sie-contact\[pandas\]'"):
        res.to_dataframe()


# --------------------------------------------------------------------------
# result.json: diagnostics, exponents by end, clean x
# --------------------------------------------------------------------------
def test_diagnostics_are_present_and_sensible(cylinder_run):
    result, _, _, stdout = cylinder_run
    for case in result["cases"]:
        d = case["diagnostics"]
        assert list(case)[-1] == "diagnostics" and set(d) == {"n", "residual", "load_check"}
        assert isinstance(d["n"], int) and d["n"] >= 2
        assert 0.0 <= d["load_check"] < 1e-12 and 0.0 <= d["residual"] < 1e-10
    assert "check" in stdout.splitlines()[5]          # the table's column


def test_exponents_are_labelled_by_end(cylinder_run):
    result, _, _, _ = cylinder_run
    for case in result["cases"]:
        ref = reference(case["inputs"])
        assert case["exponents"] == {"left": ref.beta, "right": ref.alpha}
        assert case["exponents"]["left"] == ref.zones[0].beta


def test_sampled_x_is_clean(cylinder_run):
    result, text, _, _ = cylinder_run
    assert "0.30000000000000004" not in text and "0.6000000000000001" not in text
    x = result["cases"][0]["pressure"]["x"]
    assert x[:3] == [-0.8, -0.798, -0.796] and x[550] == 0.3 and x[400] == 0.0
    assert x == [round(-0.8 + 0.002 * k, 3) for k in range(801)]
    ref = reference(result["cases"][0]["inputs"])          # sampled at those very numbers
    assert result["cases"][0]["pressure"]["values"] == ref.pressure(np.array(x)).tolist()


def test_clean_linspace():
    assert clean_linspace(-1.25, 1.25, 11).tolist() == [-1.25, -1.0, -0.75, -0.5, -0.25, 0.0,
                                                        0.25, 0.5, 0.75, 1.0, 1.25]
    assert clean_linspace(0.1, 0.7, 7).tolist() == [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7]
    third = clean_linspace(0.0, 1.0, 4)                     # not a decimal step: linspace
    assert np.array_equal(third, np.linspace(0.0, 1.0, 4))
    x = clean_linspace(-0.8, 0.8, 801)
    assert np.max(np.abs(x - np.linspace(-0.8, 0.8, 801))) <= 2.3e-16
    assert (x[0], x[-1]) == (-0.8, 0.8)


# --------------------------------------------------------------------------
# warnings and errors
# --------------------------------------------------------------------------
def test_contact_wider_than_the_grid_is_a_warning(tmp_path):
    scene = write_scene(tmp_path, """
        [material]
        preset = "zhou2014"
        [punch]
        kind = "cylindrical"
        radius = 100.0
        [motion]
        load = [0.01, 1.0]
        speed = 0.6
        friction = 0.3
        [outputs]
        fields = ["ends", "pressure"]
        x = { start = -3, stop = 3, num = 61 }
    """)
    rc, _, err = run_cli("run", scene, "--out", tmp_path / "out", "--no-figures", "--quiet")
    assert rc == 0
    result = json.loads((tmp_path / "out" / "result.json").read_text())
    xl, xr = result["cases"][1]["ends"]
    assert xl < -3 and xr > 3                                 # (-3.12, 3.61)
    (message,) = result["warnings"]
    assert message.startswith("case 1 (load = 1): ")
    assert f"[{xl:.6g}, {xr:.6g}]" in message and "x grid [-3, 3]" in message
    assert f"contact: warning: {message}" in err
    res = run_scene(parse_scene_text(scene.read_text()))
    assert res.cases[0].warnings == [] and len(res.cases[1].warnings) == 1


@pytest.fixture
def no_solving(monkeypatch):
    calls = []

    def solve(*args, **kw):
        calls.append(args)
        raise AssertionError("solved")
    monkeypatch.setattr(contact, "solve", solve)
    return calls


def test_out_that_is_a_file_fails_before_solving(tmp_path, no_solving):
    scene = write_scene(tmp_path, CYLINDER_SWEEP)
    target = tmp_path / "taken"
    target.write_text("not a directory")
    for out in (target, target / "sub"):
        rc, stdout, err = run_cli("run", scene, "--out", out)
        assert rc == 2 and no_solving == []
        assert err.startswith(f"contact: error: --out {out}: ") and "not a directory" in err
        assert "Traceback" not in err and stdout == ""
    assert target.read_text() == "not a directory"


def test_out_refused_by_the_system_fails_before_solving(tmp_path, no_solving, monkeypatch):
    """The same without real permissions (as root, every directory is writable): the
    system's refusal is simulated."""
    import tempfile

    def refuse(*args, **kw):
        raise PermissionError(13, "Permission denied")
    scene = write_scene(tmp_path, CYLINDER_SWEEP)
    monkeypatch.setattr(tempfile, "TemporaryFile", refuse)
    monkeypatch.setattr(tempfile, "mkdtemp", refuse)
    for out, why in ((tmp_path, "is not writable (Permission denied)"),
                     (tmp_path / "new" / "dir",
                      f"cannot be created in {tmp_path} (Permission denied)")):
        rc, _, err = run_cli("run", scene, "--out", out)
        assert rc == 2 and no_solving == [] and why in err, err
    assert not (tmp_path / "new").exists()


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="no /proc")
def test_out_under_a_pseudo_filesystem_fails_before_solving(tmp_path, no_solving):
    """/proc takes no new directory, even from root, whom os.access lets write anywhere: the
    check makes (and removes) one, so the refusal comes before solving, not after."""
    scene = write_scene(tmp_path, CYLINDER_SWEEP)
    rc, _, err = run_cli("run", scene, "--out", "/proc/contact-out-check/new")
    assert rc == 2 and no_solving == [] and "cannot be created in /proc" in err, err
    assert list(tmp_path.glob(".contact-write-check*")) == []


@pytest.mark.skipif(not hasattr(os, "geteuid") or os.geteuid() == 0,
                    reason="root writes into read-only directories")
def test_out_without_write_permission_fails_before_solving(tmp_path, no_solving):
    scene = write_scene(tmp_path, CYLINDER_SWEEP)
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        for out, why in ((locked, "not writable"), (locked / "new", "cannot be created in")):
            rc, _, err = run_cli("run", scene, "--out", out)
            assert rc == 2 and no_solving == [] and why in err
    finally:
        locked.chmod(0o700)


# --------------------------------------------------------------------------
# figures and progress
# --------------------------------------------------------------------------
SMALL = CYLINDER_SWEEP.replace("[0.0, 0.1, 0.3]", "0.3")


def test_no_figures_writes_no_png(tmp_path):
    scene = write_scene(tmp_path, SMALL)
    rc, _, err = run_cli("run", scene, "--out", tmp_path / "flag", "--no-figures", "--quiet")
    assert rc == 0, err
    assert not list((tmp_path / "flag").glob("*.png"))
    assert {p.name for p in (tmp_path / "flag").iterdir()} == {"result.json", "sweep.csv",
                                                               "pressure.csv"}
    off = write_scene(tmp_path, SMALL + "figures = false\n", "off.toml")
    rc, _, err = run_cli("run", off, "--out", tmp_path / "key", "--quiet")
    assert rc == 0, err
    assert not list((tmp_path / "key").glob("*.png"))
    assert json.loads((tmp_path / "key" / "result.json").read_text())[
        "scene"]["outputs"]["figures"] is False
    bad = write_scene(tmp_path, SMALL + 'figures = "no"\n', "bad.toml")
    rc, _, err = run_cli("run", bad, "--out", tmp_path / "bad", "--quiet")
    assert rc == 2 and "outputs.figures" in err


def test_quiet_run_is_silent(tmp_path):
    scene = write_scene(tmp_path, SMALL)
    rc, stdout, err = run_cli("run", scene, "--out", tmp_path / "out", "--quiet")
    assert rc == 0 and stdout == "" and err == ""
    assert (tmp_path / "out" / "pressure.png").stat().st_size > 10_000
    assert type(_writing_bar(3, False)).__name__ == "_NoBar"
    bar = _writing_bar(3, True)                  # the second phase: files being written
    assert type(bar).__name__ == "tqdm" and bar.desc == "writing outputs"
    bar.close()


@pytest.mark.slow
def test_figures_of_a_long_sweep_are_a_coloured_family_of_at_most_max_curves(tmp_path):
    """A long sweep's figure draws MAX_CURVES cases as one coloured LineCollection (what
    keeps it cheap to draw; its time is a benchmark's matter, not this test's)."""
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection

    from contact.scene.figures import _shown_cases, _write_curve_figures, curve_figure
    speeds = ", ".join(f"{0.05 * k:.2f}" for k in range(10))
    frictions = ", ".join(f"{0.02 * k:.2f}" for k in range(25))
    s = parse_scene_text(CYLINDER_SWEEP.replace("[0.3, 0.6]", f"[{speeds}]")
                         .replace("[0.0, 0.1, 0.3]", f"[{frictions}]")
                         .replace('"ends", "exponents", "sif", "pressure"',
                                  '"pressure", "sigma_xx"'))
    res = run_scene(s)
    assert len(res.cases) == 250
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        shown = _shown_cases(res.cases, MAX_CURVES)             # what SceneWriter keeps
        written = [path for name in ("pressure", "sigma_xx") for path in
                   _write_curve_figures(res.scene, shown, len(res.cases), tmp_path, name, [])]
    assert [p.name for p in written] == ["pressure.png", "sigma_xx.png"]
    assert not [w for w in caught if "layout" in str(w.message).lower()]
    fig = curve_figure(res, "pressure")
    ax = fig.axes[0]
    title = ax.get_title()
    (lc,) = [c for c in ax.collections if isinstance(c, LineCollection)]
    assert len(lc.get_segments()) == MAX_CURVES
    assert f"{MAX_CURVES} of 250 cases drawn" in title
    assert len(fig.axes) == 2 and fig.axes[1].get_ylabel() == "speed"      # the colour bar
    assert ax.get_ylabel() == "pressure p(X) (S)" and ax.get_xlabel() == "X (L)"
    assert ax.get_legend() is None                    # 25 frictions: named in the title
    assert "friction also varies" in title
    plt.close(fig)


# --------------------------------------------------------------------------
# result.json's encoder
# --------------------------------------------------------------------------
_JSON_SCALARS = (st.floats(allow_nan=False, allow_infinity=False) | st.integers()
                 | st.text() | st.booleans() | st.none())
_JSON_VALUES = st.recursive(
    _JSON_SCALARS | st.lists(_JSON_SCALARS, max_size=5),
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=5), inner,
                                                                 max_size=4),
    max_leaves=20)


@settings(max_examples=200, deadline=None)
@given(_JSON_VALUES)
def test_dumps_json_is_json(value):
    """dumps_json writes what json.dumps would, laid out differently: the same value back,
    and each scalar (and each list of scalars) exactly as json.dumps spells it."""
    from contact.scene.output import _json_scalar, dumps_json
    assert json.loads(dumps_json(value)) == json.loads(json.dumps(value))
    if not isinstance(value, (dict, list)):
        assert _json_scalar(value) == json.dumps(value)
    elif not any(isinstance(v, (dict, list))
                 for v in (value.values() if isinstance(value, dict) else value)):
        assert dumps_json(value) == json.dumps(value)         # scalars: on one line
    else:
        assert "\n" in dumps_json(value)                      # lists and tables: indented


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), [1.0, float("-inf")]])
def test_dumps_json_refuses_what_json_cannot_hold(bad):
    from contact.scene.output import dumps_json
    with pytest.raises(ValueError, match="not JSON compliant"):
        dumps_json(bad)
