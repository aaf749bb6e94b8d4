"""The scene field "subsurface" (contact.scene): the [outputs] grid vocabulary and its errors,
the default grid scaled to the contact, the Hertz scene's extrema in result.json, the files
(subsurface.npz, subsurface.csv, two contour maps), "computed only when asked", and singular
(flat punch) corners.

Oracles: Hertz's line contact (the largest in-plane shear on the axis of an isotropic static
frictionless cylinder, from the closed-form axis stresses below), and
contact.ContactResult.stress called directly (the scene layer must not change a number).
"""
from __future__ import annotations

import csv
import json
import textwrap
import warnings
from pathlib import Path

import numpy as np
import pytest

import contact
from contact import cli
from contact.scene import (FIELDS, SceneError, format_table, load_scene, parse_scene_text,
                           run_scene, write_outputs)
from contact.scene.figures import SUBSURFACE_PANELS, _subsurface_shown

SCENES = Path(__file__).resolve().parents[2] / "validation" / "scenes"
HERTZ = SCENES / "subsurface_hertz.toml"

CYL = """
[material]
preset = "zhou2014"
[punch]
kind = "cylindrical"
radius = 100.0
[motion]
load = 0.01
speed = 0.6
friction = 0.3
"""
FLAT = """
[material]
preset = "zhou2014"
[punch]
kind = "flat"
half_width = 1.0
[motion]
load = 0.01
speed = 0.3
friction = 0.3
"""
QUANTITIES = ("sigma_xx", "sigma_yy", "sigma_xy", "max_shear", "max_tension")


def scene(text: str, outputs: str = 'fields = ["ends", "subsurface"]'):
    return parse_scene_text(textwrap.dedent(text) + "[outputs]\n" + textwrap.dedent(outputs))


def hertz_axis_maximum():
    """Hertz line contact on the axis X = 0 (Johnson, Contact Mechanics, eq. 4.49, zeta = depth
    / a): sigma_x = -p0 ((1 + 2 zeta^2) / s - 2 zeta), sigma_z = -p0 / s, s = sqrt(1 + zeta^2),
    so tau = (sigma_z - sigma_x) / 2 = p0 (zeta - zeta^2 / s): its maximum and where."""
    zeta = np.linspace(0.7, 0.9, 2_000_001)
    tau = zeta - zeta ** 2 / np.sqrt(1.0 + zeta ** 2)
    k = int(np.argmax(tau))
    return float(tau[k]), float(zeta[k])


# --------------------------------------------------------------------------
# the vocabulary
# --------------------------------------------------------------------------
def test_subsurface_is_a_field():
    assert "subsurface" in FIELDS
    s = scene(CYL)
    assert s.fields == ("ends", "subsurface") and s.grid is None
    assert "grid" not in s.echo()["outputs"]              # only echoed when given


def test_grid_is_parsed_and_echoed():
    s = scene(CYL, 'fields = ["subsurface"]\n'
                   'grid = { x = { start = -1, stop = 1, num = 5 }, '
                   'y = { start = -2, stop = 0, num = 3 } }\n')
    assert s.echo()["outputs"]["grid"] == {"x": {"start": -1.0, "stop": 1.0, "num": 5},
                                           "y": {"start": -2.0, "stop": 0.0, "num": 3}}
    (case,) = s.cases()
    assert case.grid == s.grid
    only_y = scene(CYL, 'fields = ["subsurface"]\ngrid = { y = { start = -2, stop = -1, '
                        'num = 3 } }\n')
    assert only_y.grid.x is None and only_y.grid.y.stop == -1.0


@pytest.mark.parametrize("grid, key, words", [
    ("grid = 3", "outputs.grid", "must be a table"),
    ("grid = [1, 2]", "outputs.grid", "must be a table"),
    ("grid = { z = 1 }", "outputs.grid.z", "unknown key"),
    ("grid = {}", "outputs.grid", "is empty"),
    ("grid = { y = 2 }", "outputs.grid.y", "must be a table"),
    ("grid = { y = { start = -1, stop = 0, num = 5, step = 1 } }", "outputs.grid.y.step",
     "did you mean 'stop'"),
    ("grid = { y = { start = -1, stop = 0 } }", "outputs.grid.y.num", "is missing"),
    ("grid = { y = { start = -1, stop = 0, num = 1 } }", "outputs.grid.y.num", "[2, 10000]"),
    ("grid = { x = { start = -1, stop = 1, num = 2.5 } }", "outputs.grid.x.num", "integer"),
    ("grid = { x = { start = -1, stop = 1, num = true } }", "outputs.grid.x.num", "integer"),
    ("grid = { y = { start = -1, stop = 0.5, num = 5 } }", "outputs.grid.y.stop",
     "above the surface"),
    ("grid = { y = { start = 0, stop = -1, num = 5 } }", "outputs.grid.y", "not below"),
    ("grid = { x = { start = 1, stop = 1, num = 5 } }", "outputs.grid.x", "not below"),
    ("grid = { x = { start = -inf, stop = 1, num = 5 } }", "outputs.grid.x.start", "finite"),
    ("grid = { y = { start = nan, stop = 0, num = 5 } }", "outputs.grid.y.start", "finite"),
    ("grid = { y = { start = -1, stop = 0, num = '5' } }", "outputs.grid.y.num", "integer"),
    ("grid = { x = { start = -1, stop = 1, num = 5000 }, y = { start = -1, stop = 0, "
     "num = 5000 } }", "outputs.grid", "too many"),
])
def test_grid_errors_name_the_key(grid, key, words):
    with pytest.raises(SceneError) as err:
        scene(CYL, 'fields = ["subsurface"]\n' + grid + "\n")
    assert err.value.key == key and words in str(err.value)
    assert err.value.allowed                                # says what would be accepted


def test_grid_without_the_field_is_an_error():
    with pytest.raises(SceneError) as err:
        scene(CYL, 'fields = ["ends"]\ngrid = { y = { start = -1, stop = 0, num = 5 } }\n')
    assert err.value.key == "outputs.grid" and "subsurface" in err.value.allowed


# --------------------------------------------------------------------------
# running
# --------------------------------------------------------------------------
def test_default_grid_is_scaled_to_the_contact():
    (res,) = run_scene(scene(CYL)).cases
    xl, xr = res.entry["ends"]
    a = 0.5 * (xr - xl)
    sub = res.entry["subsurface"]
    assert list(res.entry) == ["inputs", "ends", "subsurface"]
    assert sub["grid"] == {"x": {"start": xl - a, "stop": xr + a, "num": 161},
                           "y": {"start": -3.0 * a, "stop": 0.0, "num": 121}}
    assert sub["region"] == {"x": [xl - a, xr + a], "y": [-3.0 * a, 0.0]}   # free ends
    m = res.subsurface
    assert np.array_equal(m.x, np.linspace(xl - a, xr + a, 161))
    assert np.array_equal(m.y, np.linspace(-3.0 * a, 0.0, 121)) and m.y[-1] == 0.0
    assert m.field.sigma_xx.shape == m.field.sigma_yy.shape == m.field.sigma_xy.shape == (121, 161)
    assert all(np.all(np.isfinite(m.quantity(q))) for q in QUANTITIES)
    # the map is ContactResult.stress at those points, and the extrema its stress_extrema
    ref = contact.solve(contact.zhou2014(), contact.CylindricalPunch(100.0), load=0.01,
                        speed=0.6, friction=0.3, direction=-1)
    X, Y = np.meshgrid(m.x, m.y)
    f = ref.stress(X, Y)
    for q in QUANTITIES:
        np.testing.assert_allclose(m.quantity(q), getattr(f, q), rtol=1e-12, atol=1e-18)
    ext = ref.stress_extrema(((xl - a, xr + a), (-3.0 * a, 0.0)))
    for q in ("max_shear", "max_tension"):
        e = getattr(ext, q)
        assert sub[q] == {"value": e.value, "X": e.X, "Y": e.Y, "depth": e.depth,
                          "half_width": e.half_width, "depth_over_a": e.depth_over_a}
    # on the surface the map is the tractions
    np.testing.assert_allclose(m.field.sigma_yy[-1], -ref.pressure(m.x), rtol=1e-12, atol=1e-18)


def test_a_given_grid_is_used_and_an_omitted_axis_scaled():
    s = scene(CYL, 'fields = ["subsurface"]\ngrid = { y = { start = -0.5, stop = -0.1, '
                   'num = 7 } }\n')
    (res,) = run_scene(s).cases
    m, sub = res.subsurface, res.entry["subsurface"]
    assert np.array_equal(m.y, np.linspace(-0.5, -0.1, 7)) and m.x.size == 161
    assert m.field.sigma_xx.shape == (7, 161)
    assert sub["region"]["y"] == [-0.5, -0.1]
    assert -0.5 <= sub["max_shear"]["Y"] <= -0.1


def test_not_asked_computes_and_writes_nothing(monkeypatch, tmp_path):
    def boom(*a, **k):
        raise AssertionError("subsurface computed although not requested")
    monkeypatch.setattr(contact.ContactResult, "stress", boom)
    monkeypatch.setattr(contact.ContactResult, "stress_extrema", boom)
    s = scene(FLAT, 'fields = ["ends", "pressure", "sigma_xx"]\n')
    result = run_scene(s)
    assert all(res.subsurface is None and "subsurface" not in res.entry
               for res in result.cases)
    written = write_outputs(result, tmp_path)
    assert not [p for p in written if "subsurface" in p.name]
    assert not list(tmp_path.glob("subsurface*"))
    assert "max shear" not in format_table(result)


# --------------------------------------------------------------------------
# Hertz, end to end
# --------------------------------------------------------------------------
@pytest.fixture(scope="module")
def hertz(tmp_path_factory):
    out = tmp_path_factory.mktemp("hertz")
    with warnings.catch_warnings():
        warnings.simplefilter("error")           # no matplotlib (layout) warnings either
        assert cli.main(["run", str(HERTZ), "--out", str(out), "--quiet"]) == 0
    return out


def test_hertz_scene_is_isotropic_static_frictionless():
    s = load_scene(HERTZ)
    iso = contact.Isotropic(1.0, 0.3)
    m = s.material
    assert (m.C11, m.C12, m.C22, m.C33) == (iso.C11, iso.C12, iso.C22, iso.C33)
    assert s.punch["kind"] == "cylindrical"
    assert s.motion["speed"] == 0.0 and s.motion["friction"] == 0.0
    assert s.fields == ("ends", "pressure", "subsurface")


@pytest.mark.slow
def test_hertz_max_shear_in_result_json(hertz):
    result = json.loads((hertz / "result.json").read_text())
    (case,) = result["cases"]
    sub = case["subsurface"]
    assert set(sub) == {"max_shear", "max_tension", "region", "grid"}
    assert set(sub["max_shear"]) == {"value", "X", "Y", "depth", "half_width", "depth_over_a"}
    xl, xr = case["ends"]
    a = 0.5 * (xr - xl)
    P = case["inputs"]["load"]
    p0 = 2.0 * P / (np.pi * a)
    ref = contact.solve(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0), load=P,
                        speed=0.0)
    assert ref.pressure(0.0) == pytest.approx(p0, rel=1e-12)
    tau, zeta = hertz_axis_maximum()
    assert tau == pytest.approx(0.30028, abs=1e-5) and zeta == pytest.approx(0.7861, abs=1e-4)
    ms = sub["max_shear"]
    assert abs(ms["value"] / p0 - tau) < 1e-6
    assert abs(ms["depth_over_a"] - zeta) < 1e-4
    assert abs(ms["X"]) < 1e-4 * a and ms["Y"] == -ms["depth"]
    assert ms["half_width"] == pytest.approx(a, rel=1e-12)
    assert sub["max_tension"]["value"] < 1e-12 * p0        # frictionless: no tension
    assert "subsurface: sigma_xx, sigma_yy, sigma_xy, max_shear, max_tension, value" in \
        result["units"]
    assert len((hertz / "result.json").read_text()) < 20_000        # no maps in the JSON


def test_hertz_npz(hertz):
    result = json.loads((hertz / "result.json").read_text())
    with np.load(hertz / "subsurface.npz") as z:
        assert set(z.files) == {"cases", "labels"} | {f"case0/{k}" for k in ("x", "y") +
                                                      QUANTITIES}
        assert z["cases"].tolist() == [0] and z["labels"].shape == (1,)
        x, y = z["case0/x"], z["case0/y"]
        assert x.shape == (161,) and y.shape == (121,)
        g = result["cases"][0]["subsurface"]["grid"]
        assert x[0] == g["x"]["start"] and x[-1] == g["x"]["stop"] and y[-1] == 0.0
        for q in QUANTITIES:
            assert z[f"case0/{q}"].shape == (121, 161)
        sxx, syy, sxy = z["case0/sigma_xx"], z["case0/sigma_yy"], z["case0/sigma_xy"]
        np.testing.assert_allclose(z["case0/max_shear"], np.hypot(0.5 * (sxx - syy), sxy))
        assert np.nanmax(z["case0/max_shear"]) <= result["cases"][0]["subsurface"][
            "max_shear"]["value"] * (1 + 1e-12)


def test_hertz_csv(hertz):
    with open(hertz / "subsurface.csv", newline="") as fh:
        rows = list(csv.reader(fh))
    assert rows[0] == ["case", "X", "Y", "sigma_xx", "sigma_yy", "sigma_xy", "max_shear",
                       "max_tension"]
    assert len(rows) == 1 + 161 * 121
    assert {r[0] for r in rows[1:]} == {"0"}
    ref = contact.solve(contact.Isotropic(1.0, 0.3), contact.CylindricalPunch(1.0), load=0.01,
                        speed=0.0)
    for k in (1, 5000, 161 * 60 + 80, len(rows) - 1):
        X, Y, *values = (float(v) for v in rows[k][1:])
        f = ref.stress(X, Y)
        for q, v in zip(QUANTITIES, values):
            assert v == pytest.approx(float(getattr(f, q)), rel=1e-12, abs=1e-18), (k, q)
    # row by row of the grid: Y fixed along a row, X increasing; Y increasing up to 0
    assert {r[2] for r in rows[1:162]} == {rows[1][2]} and rows[162][2] != rows[1][2]
    assert float(rows[1][1]) < float(rows[2][1])
    assert float(rows[1][2]) < float(rows[-1][2]) == 0.0


def test_hertz_figures_and_table(hertz):
    for name in ("subsurface_max_shear.png", "subsurface_sigma_xx.png"):
        data = (hertz / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10_000
    table = format_table(run_scene(load_scene(HERTZ)))
    assert "max shear @ depth/a" in table and "@ 0.7862" in table


# --------------------------------------------------------------------------
# singular corners (flat punch) and sweeps
# --------------------------------------------------------------------------
@pytest.mark.slow
def test_flat_punch_corners(tmp_path):
    s = scene(FLAT.replace("friction = 0.3", "friction = [0.0, 0.3]"),
              'fields = ["ends", "subsurface"]\n')
    result = run_scene(s)
    for res in result.cases:
        m, sub = res.subsurface, res.entry["subsurface"]
        xl, xr = res.entry["ends"]
        assert (xl, xr) == (-1.0, 1.0)
        corner = (m.y[:, None] == 0.0) & np.isin(m.x, [xl, xr])[None, :]
        assert corner.sum() == 2                       # the default grid holds both corners
        for q in QUANTITIES:
            v = m.quantity(q)
            assert np.all(np.isnan(v[corner])) and np.all(np.isfinite(v[~corner]))
        assert sub["region"]["y"] == [-3.0, -1e-3]          # cut 1e-3 a below the surface
        assert sub["grid"]["y"]["stop"] == 0.0
        assert sub["max_shear"]["Y"] <= -1e-3 and np.isfinite(sub["max_shear"]["value"])
    written = write_outputs(result, tmp_path)
    assert {p.name for p in written} >= {"subsurface.npz", "subsurface.csv",
                                         "subsurface_max_shear.png", "subsurface_sigma_xx.png"}
    with open(tmp_path / "subsurface.csv", newline="") as fh:
        rows = list(csv.reader(fh))
    assert len(rows) == 1 + 2 * 161 * 121
    assert sum(1 for r in rows[1:] if r[3] == "") == 4     # the corners: empty cells
    assert "searched below Y = -0.001 a" in format_table(result)


def test_user_grid_through_a_corner_is_nan_there_not_an_error():
    s = scene(FLAT, 'fields = ["subsurface"]\n'
                    'grid = { x = { start = -1, stop = 1, num = 3 }, '
                    'y = { start = -1, stop = 0, num = 3 } }\n')
    (res,) = run_scene(s).cases
    m = res.subsurface
    assert np.isnan(m.field.sigma_xx[-1, 0]) and np.isnan(m.field.sigma_xx[-1, 2])
    assert np.isfinite(m.field.sigma_xx[-1, 1]) and np.all(np.isfinite(m.field.sigma_xx[:-1]))
    assert res.entry["subsurface"]["region"]["y"] == [-1.0, -1e-3]
    # a grid below the surface needs no cut
    s = scene(FLAT, 'fields = ["subsurface"]\ngrid = { y = { start = -1, stop = -0.25, '
                    'num = 4 } }\n')
    (res,) = run_scene(s).cases
    assert res.entry["subsurface"]["region"]["y"] == [-1.0, -0.25]


def test_long_sweeps_show_evenly_spaced_cases():
    for n in (1, 5, SUBSURFACE_PANELS):
        assert _subsurface_shown(list(range(n))) == list(range(n))
    shown = _subsurface_shown(list(range(20)))
    assert len(shown) == SUBSURFACE_PANELS and shown[0] == 0 and shown[-1] == 19
    assert shown == sorted(set(shown))
