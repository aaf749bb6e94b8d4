"""Scenes (contact.scene): parsing good and bad files, sweeps, custom profiles, and the
"simulate only what the scene asks for" property, counted call by call.

Oracles: contact.solve called directly with the same inputs (the scene layer must not change a
number), and the scene files shipped in validation/scenes/.
"""
from __future__ import annotations

import json
import textwrap
import warnings
from pathlib import Path

import numpy as np
import pytest

import contact
import contact.result
import contact.solver
from contact import cli
from contact.scene import (CURVE_FIELDS, DEFAULT_SCENE_TOML, CaseError, SceneError,
                           default_scene, load_scene, parse_scene_text, run_case, run_scene)

SCENES = Path(__file__).resolve().parents[2] / "validation" / "scenes"

HEAD = """
[material]
preset = "zhou2014"
"""
CYL = HEAD + """
[punch]
kind = "cylindrical"
radius = 100.0
"""


def scene(text: str, **kw):
    return parse_scene_text(textwrap.dedent(text), **kw)


# --------------------------------------------------------------------------
# good files
# --------------------------------------------------------------------------
#: The shipped scenes that are not the paper's Figs 1-4: their number of cases and sweep.
OTHER_SCENES = {"default": (1, ()), "profile_samples": (3, (("motion", "load"),)),
                "w_face_two_zones": (2, (("motion", "friction"),)),
                "subsurface_hertz": (1, ()),
                "cattaneo_fretting": (3, (("motion", "tangential_load"),)),
                "carter_rolling": (3, (("motion", "creepage"),))}


@pytest.mark.parametrize("path", sorted(SCENES.glob("*.toml")), ids=lambda p: p.stem)
def test_shipped_scenes_run(path):
    """Every shipped scene solves every case (each case from first touch on its own, as a
    sweep runs them), and every result passes its own load check."""
    res = run_scene(load_scene(path))
    assert all(c.diagnostics["load_check"] <= 1e-12 for c in res.cases)
    if path.stem == "profile_samples":     # the last load reaches both edges of the face
        last = res.cases[-1].entry
        assert last["ends"] == [-0.5, 0.5] and last["sif"].keys() == {"left", "right"}


@pytest.mark.parametrize("path", sorted(SCENES.glob("*.toml")), ids=lambda p: p.stem)
def test_shipped_scenes_parse(path):
    s = load_scene(path)
    cases = s.cases()
    if path.stem in OTHER_SCENES:
        assert (len(cases), s.sweep) == OTHER_SCENES[path.stem]
    else:                                   # the paper's Figs 1-4: a 4-point sweep each
        assert len(cases) == 4 and len(s.sweep) == 1
        swept = s.sweep[0][1]
        assert swept == ("speed" if "speed" in path.stem else "friction")
        assert [c.inputs[swept] for c in cases] == (
            [0.0, 0.3, 0.6, 0.9] if swept == "speed" else [0.0, 0.1, 0.3, 0.5])
        assert {c.inputs["friction" if swept == "speed" else "speed"] for c in cases} == (
            {0.3} if swept == "speed" else {0.6})


def test_default_file_is_the_embedded_default():
    shipped = load_scene(SCENES / "default.toml")
    embedded = default_scene()
    assert shipped.echo() == embedded.echo()
    assert (SCENES / "default.toml").read_text() == DEFAULT_SCENE_TOML
    (case,) = embedded.cases()
    assert case.inputs == {"speed": 0.6, "friction": 0.3, "direction": -1, "load": 0.01,
                           "radius": 100.0}
    assert embedded.material.C11 == contact.zhou2014().C11


def test_defaults_are_filled_in_and_echoed():
    s = scene(CYL + "[motion]\nload = 0.02\n")
    echo = s.echo()
    assert echo["motion"] == {"load": 0.02, "speed": 0.0, "friction": 0.0, "direction": -1}
    assert echo["outputs"] == {"fields": ["ends", "exponents", "pressure"], "x": None,
                               "figures": True}
    assert echo["numerics"] == {"method": "numeric", "n": None, "tol": 1e-12}
    assert echo["material"]["preset"] == "zhou2014" and echo["material"]["C33"] == 5.52
    json.dumps(echo, allow_nan=False)


def test_explicit_material_and_velocity_with_rho():
    s = scene("""
        [material]
        C11 = 3.0
        C12 = 1.0
        C22 = 3.0
        C33 = 1.0
        rho = 4.0
        [punch]
        kind = "flat"
        half_width = 2.0
        [motion]
        load = 1.0
        velocity = [0.1, 0.2]
    """)
    cases = s.cases()
    # c = V / sqrt(C33/rho) = V / 0.5
    assert [c.inputs["speed"] for c in cases] == pytest.approx([0.2, 0.4], rel=1e-15)
    assert [c.inputs["velocity"] for c in cases] == [0.1, 0.2]
    assert s.sweep == (("motion", "velocity"),)


def test_sweep_is_the_cartesian_product_in_scene_order():
    s = scene(HEAD + """
        [motion]
        friction = [0.0, 0.3]
        load = 0.01
        speed = [0.1, 0.2, 0.3]
        [punch]
        kind = "parabolic"
        radius = [50.0, 100.0]
    """)
    assert s.sweep == (("motion", "friction"), ("motion", "speed"), ("punch", "radius"))
    got = [(c.inputs["friction"], c.inputs["speed"], c.inputs["radius"]) for c in s.cases()]
    want = [(f, c, r) for f in (0.0, 0.3) for c in (0.1, 0.2, 0.3) for r in (50.0, 100.0)]
    assert got == want
    assert [c.index for c in s.cases()] == list(range(12))
    assert s.cases()[1].label == "friction = 0, speed = 0.1, radius = 100"


def test_profile_polynomial_slope_is_not_a_sweep_and_matches_cylindrical():
    s = scene(HEAD + """
        [punch]
        kind = "profile"
        slope = [0.0, 0.01]          # dv/dX = X/100: the cylindrical punch of radius 100
        [motion]
        load = 0.01
        speed = 0.6
        friction = 0.3
    """)
    assert s.sweep == () and len(s.cases()) == 1
    res = run_scene(s).cases[0]
    ref = contact.solve(contact.zhou2014(), contact.CylindricalPunch(100.0), load=0.01,
                        speed=0.6, friction=0.3)
    assert res.entry["ends"] == pytest.approx(list(ref.ends), rel=1e-9, abs=1e-12)


def test_profile_pieces_join_into_breaks():
    s = scene(HEAD + """
        [punch]
        kind = "profile"
        breaks = [3.0]
        corners = ["free", "free"]
        [[punch.pieces]]
        to = -0.5
        coefficients = [0.005, 0.01]
        [[punch.pieces]]
        from = -0.5
        to = 0.5
        coefficients = [0.0]
        [[punch.pieces]]
        from = 0.5
        coefficients = [-0.005, 0.01]
        [motion]
        load = 0.05
    """)
    punch = s.cases()[0].punch.build()
    assert punch.breaks == (-0.5, 0.5, 3.0) and punch.corners == (None, None)
    X = np.array([-2.0, -0.5, 0.0, 0.49, 0.5, 2.0])
    assert punch.slope(X) == pytest.approx([-0.015, 0.0, 0.0, 0.0, 0.0, 0.015], abs=1e-17)
    xl, xr = run_scene(s).cases[0].entry["ends"]
    assert xl < -0.5 and xr > 0.5 and xl == pytest.approx(-xr, rel=1e-9)   # mu = 0: symmetric


def test_profile_function_is_imported_from_the_scene_directory(tmp_path):
    (tmp_path / "my_face_slope.py").write_text(
        "import numpy as np\ndef slope(X):\n    return np.asarray(X) / 100.0\n")
    path = tmp_path / "s.toml"
    path.write_text(HEAD + '[punch]\nkind = "profile"\nslope = "my_face_slope:slope"\n'
                    'corners = [0.0, "free"]\n[motion]\nload = 0.01\nspeed = 0.3\n')
    s = load_scene(path)
    res = run_scene(s).cases[0]
    ref = contact.solve(contact.zhou2014(), contact.ParabolicPunch(100.0), load=0.01, speed=0.3)
    assert res.entry["ends"] == pytest.approx(list(ref.ends), rel=1e-9, abs=1e-15)


def test_closed_form_method_gives_the_numeric_ends():
    text = CYL + "[motion]\nload = 0.01\nspeed = 0.6\nfriction = 0.3\n"
    num = run_scene(scene(text)).cases[0].entry["ends"]
    cf = run_scene(scene(text + '[numerics]\nmethod = "closed_form"\n')).cases[0].entry["ends"]
    assert cf == pytest.approx(num, rel=1e-10)


# --------------------------------------------------------------------------
# bad files: SceneError naming file, key and what is allowed; nothing computed
# --------------------------------------------------------------------------
MOTION = "[motion]\nload = 0.01\n"
BAD = {
    "toml-syntax": (CYL + "[motion]\nload = 0.01\nspeed = = 0.3\n",
                    ["TOML syntax error",
                     f"line {(CYL + '[motion]').count(chr(10)) + 3}, column 9"]),
    "unknown-key": (CYL + "[motion]\nlaod = 0.01\n", ["motion.laod", "did you mean 'load'",
                                                      "allowed: load, speed"]),
    "unknown-section": (CYL + "[motoin]\nload = 0.01\n", ["motoin", "did you mean 'motion'"]),
    "unknown-material-key": (HEAD + "C1 = 3.0\n" + MOTION, ["material.C1", "did you mean"]),
    "wrong-type": (CYL + '[motion]\nload = "heavy"\n', ["motion.load", "must be a number",
                                                       "string 'heavy'", "allowed"]),
    "bool-is-not-a-number": (CYL + "[motion]\nload = true\n", ["motion.load", "boolean"]),
    "missing-load": (CYL + "[motion]\nspeed = 0.3\n", ["motion.load", "missing"]),
    "missing-punch": (HEAD + MOTION, ["punch", "missing"]),
    "speed-at-rayleigh": (CYL + "[motion]\nload = 0.01\nspeed = [0.3, 0.995]\n",
                          ["motion.speed", "0.995", "c_R = 0.99361473"]),
    "velocity-above-rayleigh": (
        '[material]\npreset = "zhou2014"\nrho = 1.6\n[punch]\nkind = "flat"\nhalf_width = 1.0\n'
        "[motion]\nload = 0.01\nvelocity = 2.0\n", ["motion.velocity", "c_R = 0.99361473"]),
    "velocity-without-rho": (CYL + "[motion]\nload = 0.01\nvelocity = 1.0\n",
                             ["motion.velocity", "material.rho"]),
    "negative-friction": (CYL + "[motion]\nload = 0.01\nfriction = -0.1\n",
                          ["motion.friction", "negative", ">= 0"]),
    "negative-load": (CYL + "[motion]\nload = -1.0\n", ["motion.load", "> 0"]),
    "empty-sweep": (CYL + "[motion]\nload = []\n", ["motion.load", "empty list"]),
    "bad-direction": (CYL + "[motion]\nload = 0.01\ndirection = 0\n",
                      ["motion.direction", "-1 or +1"]),
    "module-does-not-import": (HEAD + '[punch]\nkind = "profile"\nslope = "no_such_module_xyz:f"\n'
                               + MOTION, ["punch.slope", "no_such_module_xyz", "cannot import"]),
    "function-does-not-exist": (HEAD + '[punch]\nkind = "profile"\nslope = "numpy:no_such_fn"\n'
                                + MOTION, ["punch.slope", "no_such_fn"]),
    "slope-not-module-function": (HEAD + '[punch]\nkind = "profile"\nslope = "numpy.sin"\n'
                                  + MOTION, ["punch.slope", "module:function"]),
    "function-not-vectorised": (HEAD + '[punch]\nkind = "profile"\nslope = "math:sin"\n' + MOTION,
                                ["punch.slope", "vectorised"]),
    "dimension-of-another-kind": (HEAD + '[punch]\nkind = "flat"\nradius = 1.0\n' + MOTION,
                                  ["punch.radius", "flat punch", "half_width"]),
    "unknown-kind": (HEAD + '[punch]\nkind = "cylinder"\nradius = 1.0\n' + MOTION,
                     ["punch.kind", "did you mean 'cylindrical'"]),
    "zero-radius": (HEAD + '[punch]\nkind = "parabolic"\nradius = 0.0\n' + MOTION,
                    ["punch.radius", "> 0"]),
    "pieces-do-not-join": (HEAD + '[punch]\nkind = "profile"\n[[punch.pieces]]\nto = 0.0\n'
                           "coefficients = [1.0]\n[[punch.pieces]]\nfrom = 0.5\n"
                           "coefficients = [2.0]\n" + MOTION,
                           ["punch.pieces[1].from", "previous"]),
    "corner-word": (HEAD + '[punch]\nkind = "profile"\nslope = [0.0, 1.0]\n'
                    'corners = ["sharp", "free"]\n' + MOTION, ["punch.corners", "'sharp'", "free"]),
    "slope-and-pieces-missing": (HEAD + '[punch]\nkind = "profile"\n' + MOTION,
                                 ["punch.slope", "exactly one"]),
    "unknown-field": (CYL + MOTION + '[outputs]\nfields = ["pressure", "sigmaxx"]\n',
                      ["outputs.fields[1]", "did you mean 'sigma_xx'", "allowed"]),
    "bad-x": (CYL + MOTION + "[outputs]\nx = { start = 1.0, stop = 0.0, num = 10 }\n",
              ["outputs.x", "not below"]),
    "bad-n": (CYL + MOTION + "[numerics]\nn = 1\n", ["numerics.n", "[2, 20000]"]),
    "n-over-the-solver's": (CYL + MOTION + "[numerics]\nn = 20001\n",
                            ["numerics.n", "[2, 20000]", "per zone"]),
    "n-and-tol": (CYL + MOTION + "[numerics]\nn = 16\ntol = 1e-8\n", ["numerics.n", "tol"]),
    "closed-form-profile": (HEAD + '[punch]\nkind = "profile"\nslope = [0.0, 0.01]\n' + MOTION
                            + '[numerics]\nmethod = "closed_form"\n',
                            ["numerics.method", "closed_form", "numeric"]),
    "not-positive-definite": ("[material]\nC11 = 1.0\nC12 = 5.0\nC22 = 1.0\nC33 = 1.0\n"
                              '[punch]\nkind = "flat"\nhalf_width = 1.0\n' + MOTION,
                              ["material", "positive definite"]),
    "preset-and-stiffness": (HEAD + "C11 = 1.0\n" + '[punch]\nkind = "flat"\nhalf_width = 1.0\n'
                             + MOTION, ["material.C11", "preset"]),
    "material-sweep": ('[material]\nC11 = [1.0, 2.0]\nC12 = 0.1\nC22 = 1.0\nC33 = 1.0\n'
                       '[punch]\nkind = "flat"\nhalf_width = 1.0\n' + MOTION,
                       ["material.C11", "only under [motion] and [punch]"]),
}


@pytest.mark.parametrize("name", list(BAD))
def test_bad_scene_names_file_key_and_what_is_allowed(name, tmp_path):
    text, expected = BAD[name]
    path = tmp_path / f"{name}.toml"
    path.write_text(text)
    with pytest.raises(SceneError) as err:
        load_scene(path)
    message = str(err.value)
    assert message.startswith(str(path))
    for piece in expected:
        assert piece in message, (piece, message)
    assert err.value.file == str(path)


def test_bad_scene_fails_before_any_computation(tmp_path, monkeypatch, capsys):
    def forbidden(*a, **k):
        raise AssertionError("a contact problem was solved for a bad scene")
    monkeypatch.setattr(contact, "solve", forbidden)
    monkeypatch.setattr(contact.scene.run, "run_case", forbidden)
    for name in ("unknown-key", "speed-at-rayleigh", "module-does-not-import", "toml-syntax"):
        path = tmp_path / f"{name}.toml"
        path.write_text(BAD[name][0])
        assert cli.main(["run", str(path), "--out", str(tmp_path / "out")]) == 2
        err = capsys.readouterr().err
        assert err.startswith("contact: error: ") and str(path) in err
        assert "Traceback" not in err
    assert not (tmp_path / "out").exists()


def test_missing_file_and_directory(tmp_path):
    with pytest.raises(SceneError, match="no such scene file"):
        load_scene(tmp_path / "nope.toml")
    with pytest.raises(SceneError, match="directory"):
        load_scene(tmp_path)


def test_case_that_loses_contact_is_named_not_a_traceback(tmp_path, capsys):
    path = tmp_path / "concave.toml"
    path.write_text(HEAD + '[punch]\nkind = "profile"\nslope = [0.0, -0.01]\n'
                    "[motion]\nload = 0.01\nspeed = [0.2, 0.4]\n")
    s = load_scene(path)                     # a valid scene: the failure is physical
    with pytest.raises(CaseError, match=r"case 0 \(speed = 0.2"):
        run_scene(s)
    assert cli.main(["run", str(path), "--out", str(tmp_path / "o"), "--quiet"]) == 1
    err = capsys.readouterr().err
    assert "PunchGeometryError" in err and str(path) in err and "Traceback" not in err


def test_scene_error_pickles():
    import pickle
    e = SceneError("f.toml", "motion.load", "is missing", "a number")
    f = pickle.loads(pickle.dumps(e))
    assert str(f) == str(e) and f.key == "motion.load"


# --------------------------------------------------------------------------
# only what is asked is computed
# --------------------------------------------------------------------------
def counter(monkeypatch, owner, name):
    """Wrap owner.name to record its calls; return the list of calls."""
    calls = []
    original = getattr(owner, name)

    def wrapper(*args, **kwargs):
        calls.append(args)
        return original(*args, **kwargs)

    monkeypatch.setattr(owner, name, wrapper)
    return calls


def case_counter(monkeypatch):
    """Wrap contact.solve_batch (how a scene solves its cases) to record each case it
    solves; return the list of their loads."""
    calls = []
    original = contact.solve_batch

    def wrapper(*args, **kwargs):
        calls.extend(np.broadcast_to(np.asarray(kwargs["load"], dtype=float),
                                     np.broadcast(*(np.asarray(kwargs[k], dtype=object) for k in
                                                    ("load", "speed", "friction",
                                                     "direction"))).shape).ravel())
        return original(*args, **kwargs)

    monkeypatch.setattr(contact, "solve_batch", wrapper)
    return calls


def sweep_scene(kind_dim, fields, friction="[0.0, 0.3]", speed="[0.3, 0.6]"):
    return scene(HEAD + f"""
        [punch]
        {kind_dim}
        [motion]
        load = 0.01
        speed = {speed}
        friction = {friction}
        [outputs]
        fields = {json.dumps(fields)}
        x = {{ start = -1.5, stop = 1.5, num = 31 }}
    """)


@pytest.fixture
def counts(monkeypatch):
    R = contact.ContactResult
    return {
        "solve": case_counter(monkeypatch),
        "pressure": counter(monkeypatch, R, "pressure"),
        "shear": counter(monkeypatch, R, "shear"),
        "sigma_xx": counter(monkeypatch, R, "sigma_xx"),
        "hilbert_pressure": counter(monkeypatch, R, "hilbert_pressure"),
        "constants": counter(monkeypatch, contact, "surface_constants"),
        "roots": counter(monkeypatch, contact.Orthotropic, "characteristic_roots"),
    }


def tally(counts):
    return {k: len(v) for k, v in counts.items()}


def test_ends_only_samples_no_curve_and_no_constants(counts):
    res = run_scene(sweep_scene('kind = "cylindrical"\nradius = 100.0', ["ends"]))
    t = tally(counts)
    t.pop("hilbert_pressure")        # contact.solve's own gap check beyond free ends uses Hc[p]
    assert t == {"solve": 4, "pressure": 0, "shear": 0, "sigma_xx": 0, "constants": 0,
                 "roots": 0}
    for case in res.cases:
        assert list(case.entry) == ["inputs", "ends"]


def test_pressure_only_never_touches_sigma_xx(counts):
    flat = 'kind = "flat"\nhalf_width = 1.0'
    res = run_scene(sweep_scene(flat, ["pressure", "sif"]))
    assert tally(counts) == {"solve": 4, "pressure": 4, "shear": 0, "sigma_xx": 0,
                             "hilbert_pressure": 0, "constants": 0, "roots": 0}
    assert [list(c.entry) for c in res.cases] == [["inputs", "pressure", "sif"]] * 4


def test_sigma_xx_without_friction_has_no_friction_term(counts):
    flat = 'kind = "flat"\nhalf_width = 1.0'
    run_scene(sweep_scene(flat, ["sigma_xx"], friction="0.0"))
    t = tally(counts)
    assert t["sigma_xx"] == 2 and t["hilbert_pressure"] == 0       # mu = 0: N21 p only
    run_scene(sweep_scene(flat, ["sigma_xx"], friction="0.3"))
    assert len(counts["hilbert_pressure"]) == 2                     # mu > 0: N22 mu Hc[p]


def test_roots_and_constants_once_per_speed_and_shared(counts):
    s = sweep_scene('kind = "flat"\nhalf_width = 1.0', ["roots", "constants", "ends"],
                    friction="[0.0, 0.1, 0.3]", speed="[0.3, 0.6]")
    res = run_scene(s)
    assert len(res.cases) == 6
    assert len(counts["constants"]) == 2 and len(counts["roots"]) == 2
    assert sorted(c[1] for c in counts["constants"]) == [0.3, 0.6]
    by_speed = {}
    for case in res.cases:
        assert list(case.entry) == ["inputs", "roots", "constants", "ends"]
        by_speed.setdefault(case.entry["inputs"]["speed"], []).append(case.entry)
    for speed, entries in by_speed.items():
        k = contact.surface_constants(contact.zhou2014(), speed)
        assert all(e["constants"]["N11"] == k.N11 for e in entries)
        assert all(e["roots"] == entries[0]["roots"] for e in entries)


def test_unrequested_computation_would_raise(monkeypatch):
    """Make every unrequested computation raise: the run must not notice."""
    def boom(*a, **k):
        raise AssertionError("computed although not requested")
    for name in ("sigma_xx", "shear"):
        monkeypatch.setattr(contact.ContactResult, name, boom)
    monkeypatch.setattr(contact, "surface_constants", boom)
    monkeypatch.setattr(contact.Orthotropic, "characteristic_roots", boom)
    res = run_scene(sweep_scene('kind = "triangular"\nslope = 0.01',
                                ["ends", "exponents", "pressure", "sif"]))
    assert len(res.cases) == 4


def test_solver_shares_surface_constants_across_a_sweep(monkeypatch):
    calls = counter(monkeypatch, contact.solver, "surface_constants")
    run_scene(sweep_scene('kind = "flat"\nhalf_width = 1.0', ["ends"],
                          friction="[0.0, 0.1, 0.3]", speed="[0.3, 0.6]"))
    assert len(calls) <= 2


def test_solver_skips_sif_when_not_requested(monkeypatch):
    calls = counter(monkeypatch, contact.result, "_sif")
    run_scene(sweep_scene('kind = "flat"\nhalf_width = 1.0', ["ends"]))
    assert len(calls) == 0


# --------------------------------------------------------------------------
# what a run produces
# --------------------------------------------------------------------------
def test_case_values_are_contact_solve_values():
    s = sweep_scene('kind = "flat"\nhalf_width = 1.0',
                    ["ends", "exponents", "sif", "pressure", "shear", "sigma_xx"])
    res = run_scene(s)
    X = np.round(np.linspace(-1.5, 1.5, 31), 1)    # the grid's clean decimals (-1.5, -1.4, ...)
    for case in res.cases:
        i = case.entry["inputs"]
        ref = contact.solve(contact.zhou2014(), contact.FlatPunch(1.0), load=i["load"],
                            speed=i["speed"], friction=i["friction"], direction=i["direction"])
        assert case.entry["ends"] == list(ref.ends)
        assert case.entry["exponents"] == {"left": ref.beta, "right": ref.alpha}
        assert case.entry["sif"] == ref.sif
        for name in CURVE_FIELDS:
            x, v = case.curve(name)
            assert np.array_equal(x, X)
            at_end = np.isin(X, ref.ends)                 # singular corners: NaN, not inf
            assert np.all(np.isnan(v[at_end]))
            assert np.array_equal(v[~at_end], getattr(ref, name)(X[~at_end]))


def test_automatic_x_covers_the_contact():
    s = scene(CYL + "[motion]\nload = 0.01\n[outputs]\nfields = [\"pressure\"]\n")
    case = run_scene(s).cases[0]
    x, p = case.curve("pressure")
    xl, xr = run_scene(scene(CYL + "[motion]\nload = 0.01\n")).cases[0].entry["ends"]
    assert x[0] < xl and x[-1] > xr and len(x) == 401
    assert np.all(p[(x < xl) | (x > xr)] == 0.0) and np.all(p[(x > xl) & (x < xr)] > 0.0)


def test_near_rayleigh_warning_is_collected_not_printed(recwarn):
    s = scene(CYL + "[motion]\nload = 0.01\nspeed = 0.99\n[outputs]\nfields = [\"ends\", "
              "\"constants\"]\n")
    res = run_scene(s)
    assert any("NearRayleighWarning" in w for w in res.warnings)
    assert not [w for w in recwarn if issubclass(w.category, contact.NearRayleighWarning)]


NEAR_RAYLEIGH_SWEEP = CYL + """[motion]
load = [0.005, 0.01]
speed = [0.3, 0.99, 0.6, 0.993]
friction = [0.0, 0.1, 0.3]
"""


def _near_rayleigh(messages):
    return [m for m in messages if "NearRayleighWarning" in m]


def test_a_speed_near_rayleigh_is_warned_once_for_the_run_in_any_run():
    """The surface constants' warning belongs to the material at a speed: each near-Rayleigh
    speed of a sweep is warned once, naming its speed and no case, in scene order; and so is
    it again in a second run of the same process, whose constants are cached (a warning
    kept only where they were first computed would be lost there)."""
    s = scene(NEAR_RAYLEIGH_SWEEP)
    first, again = run_scene(s), run_scene(s)
    near = _near_rayleigh(first.warnings)
    assert [m.split("c = ")[1].split(" ")[0] for m in near] == ["0.99", "0.993"]
    assert not [m for m in first.warnings if m.startswith("case ")]
    assert again.warnings == first.warnings
    at_speed = [c for c in first.cases if c.entry["inputs"]["speed"] > 0.9]
    assert len(at_speed) == 12 and all(len(c.speed_warnings) == 1 for c in at_speed)
    assert all(c.speed_warnings == () for c in first.cases if c not in at_speed)


@pytest.mark.parametrize("chunks", [1, 5, 7])
def test_the_warnings_of_a_run_do_not_depend_on_how_it_is_chunked(chunks, monkeypatch):
    """The same sweep solved in chunks of any size, each chunk in a fresh process's cache
    (the cache cleared between chunks, as a pool's workers each start with their own):
    the same warnings as a serial run."""
    from contact.scene import batch
    from contact.scene import run as scene_run
    serial = run_scene(scene(NEAR_RAYLEIGH_SWEEP)).warnings
    original = batch.run_chunk

    def fresh_worker(fn, cases):
        scene_run._shared_constants.cache_clear()
        return original(fn, cases)
    monkeypatch.setattr(batch, "run_chunk", fresh_worker)
    monkeypatch.setattr(batch, "SERIAL_CHUNK", chunks)
    assert run_scene(scene(NEAR_RAYLEIGH_SWEEP)).warnings == serial


def test_a_warning_in_a_batch_is_reported_with_its_case(monkeypatch):
    """Cases are solved together (contact.solve_batch); a warning raised while solving one
    of them is reported with that case alone (the batch is solved again case by case)."""
    original = contact.solve_batch

    def warns_at_friction_02(*args, **kwargs):
        for f in np.atleast_1d(kwargs["friction"]):
            if f == 0.2:
                warnings.warn("solving friction 0.2", RuntimeWarning)
        return original(*args, **kwargs)
    monkeypatch.setattr(contact, "solve_batch", warns_at_friction_02)
    res = run_scene(scene(CYL + "[motion]\nload = 0.01\nfriction = [0.0, 0.1, 0.2, 0.3]\n"))
    assert [c.warnings for c in res.cases] == [[], [], ["RuntimeWarning: solving friction 0.2"],
                                               []]
    assert res.warnings == ["case 2 (friction = 0.2): RuntimeWarning: solving friction 0.2"]


# --------------------------------------------------------------------------
# profiles from data and from a height; faces with several contact zones
# --------------------------------------------------------------------------
def cylinder_closed_form(**motion):
    """The cylindrical punch (R = 100) by the paper's corrected closed form."""
    return contact.solve(contact.zhou2014(), contact.CylindricalPunch(100.0),
                         method="closed_form", **motion)


def test_tabulated_cylinder_gives_the_cylinder_ends():
    """200 samples of X^2/200: the quintic spline is exact on a parabola, so the ends are the
    cylinder's to rounding (reference: the closed form, which no spline enters)."""
    s = load_scene(SCENES / "profile_samples.toml")
    case = s.cases()[0]
    assert case.inputs == {"speed": 0.6, "friction": 0.3, "direction": -1, "load": 0.01}
    data = case.punch.get("data")
    assert len(data.X) == 200 and data.X[0] == -0.5 and data.X[-1] == 0.5
    assert s.punch["face"] == (-0.5, 0.5) and s.punch["interpolant"] == "quintic"
    ref = cylinder_closed_form(load=0.01, speed=0.6, friction=0.3, direction=-1)
    ends = run_case(case).entry["ends"]
    width = ref.ends[1] - ref.ends[0]
    assert np.max(np.abs(np.subtract(ends, ref.ends))) <= 1e-12 * width
    assert s.echo()["punch"] == {"kind": "profile", "data": "cylinder_samples.csv",
                                 "interpolant": "quintic", "face": [-0.5, 0.5]}


@pytest.mark.parametrize("layout", ["comma-header", "whitespace", "comments-crlf"])
def test_data_file_layouts(layout, tmp_path):
    X = np.linspace(-1.0, 1.0, 9)
    h = np.cos(X)
    rows = [(repr(x), repr(y)) for x, y in zip(X.tolist(), h.tolist())]
    if layout == "comma-header":
        text = "X, h\n" + "".join(f"{a}, {b}\n" for a, b in rows)
    elif layout == "whitespace":
        text = "".join(f"  {a}\t {b}\n" for a, b in rows)
    else:
        text = "# measured\r\n\r\nX h\r\n" + "".join(f"{a} {b}\r\n# note\r\n" for a, b in rows)
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "f.csv").write_text(text, newline="")
    path = tmp_path / "s.toml"
    path.write_text(HEAD + '[punch]\nkind = "profile"\ndata = "sub/f.csv"\nface = [-0.5, 1.0]\n'
                    + "[motion]\nload = 0.01\n")
    spec = load_scene(path).cases()[0].punch
    assert spec.get("data").X == tuple(X.tolist()) and spec.get("data").h == tuple(h.tolist())
    assert spec.build().extent == (-0.5, 1.0)


def test_data_travels_with_the_case(tmp_path):
    """A case carries its samples, not the file: it is rebuilt after the file is gone."""
    import pickle
    X = np.linspace(-0.5, 0.5, 40)
    (tmp_path / "f.csv").write_text("".join(f"{x!r} {x * x / 200.0!r}\n" for x in X.tolist()))
    path = tmp_path / "s.toml"
    path.write_text(HEAD + '[punch]\nkind = "profile"\ndata = "f.csv"\ninterpolant = "cubic"\n'
                    "[motion]\nload = 0.01\n")
    case = load_scene(path).cases()[0]
    (tmp_path / "f.csv").unlink()
    again = pickle.loads(pickle.dumps(case))
    assert again == case
    punch = again.punch.build()
    x = np.linspace(-0.5, 0.5, 7)
    np.testing.assert_allclose(punch.slope(x), x / 100.0, rtol=0, atol=1e-15)


def write_data(tmp_path, text):
    (tmp_path / "face.csv").write_text(text)
    return tmp_path / "face.csv"


GOOD_ROWS = "".join(f"{x} {x * x}\n" for x in (-1.0, -0.5, 0.0, 0.5, 1.0))
BAD_DATA = {
    "missing-file": (None, 'data = "nope.csv"\n', ["punch.data", "no such file", "nope.csv"]),
    "directory": (None, 'data = "."\n', ["punch.data", "is a directory"]),
    "not-utf8": (b"\xff\xfe\x00", 'data = "face.csv"\n', ["punch.data", "cannot read",
                                                           "face.csv"]),
    "not-a-number": ("X,h\n0.0,1.0\n1.0,abc\n", 'data = "face.csv"\n',
                     ["punch.data", "face.csv", "line 3", "'abc' is not a number"]),
    "three-columns": ("0 1\n1 2 3\n", 'data = "face.csv"\n',
                      ["punch.data", "face.csv", "line 2", "3 columns, expected 2"]),
    "too-few-rows": ("X,h\n0,0\n1,1\n2,4\n", 'data = "face.csv"\n',
                     ["punch.data", "face.csv", "at least 4 samples", "got 3"]),
    "empty": ("# nothing\n", 'data = "face.csv"\n', ["punch.data", "at least 4 samples"]),
    "nan": ("0 0\n1 nan\n2 4\n3 9\n", 'data = "face.csv"\n',
            ["punch.data", "face.csv", "h must be finite", "nan"]),
    "unsorted": ("0 0\n2 4\n1 1\n3 9\n", 'data = "face.csv"\n',
                 ["punch.data", "face.csv", "strictly increasing", "unsorted"]),
    "repeated": ("0 0\n1 1\n1 1\n3 9\n", 'data = "face.csv"\n',
                 ["punch.data", "face.csv", "repeated"]),
    "not-a-string": (GOOD_ROWS, "data = 3\n", ["punch.data", "file name"]),
    "unknown-interpolant": (GOOD_ROWS, 'data = "face.csv"\ninterpolant = "pchip"\n',
                            ["punch.interpolant", "'pchip'", '"quintic" | "cubic"']),
    "interpolant-without-data": (None, 'slope = [0.0, 0.01]\ninterpolant = "cubic"\n',
                                 ["punch.interpolant", "punch.data"]),
    "face-beyond-samples": (GOOD_ROWS, 'data = "face.csv"\nface = [-2.0, 1.0]\n',
                            ["punch.face", "beyond the samples", "face.csv", "[-1.0, 1.0]"]),
    "breaks-with-data": (GOOD_ROWS, 'data = "face.csv"\nbreaks = [0.0]\n',
                         ["punch.breaks", "tabulated face"]),
    "corners-with-data": (GOOD_ROWS, 'data = "face.csv"\ncorners = [-1.0, 1.0]\n',
                          ["punch.corners", "punch.face"]),
    "data-and-slope": (GOOD_ROWS, 'data = "face.csv"\nslope = [0.0, 0.01]\n',
                       ["punch.slope", "together with punch.data", "exactly one"]),
    "face-not-increasing": (None, 'slope = [0.0, 0.01]\nface = [1.0, -1.0]\n',
                            ["punch.face", "not below"]),
    "face-one-number": (None, 'slope = [0.0, 0.01]\nface = [1.0]\n',
                        ["punch.face", "two numbers"]),
    "height-not-a-string": (None, "height = [0.0, 1.0]\n", ["punch.height", "module:function"]),
    "height-does-not-import": (None, 'height = "no_such_module_xyz:h"\n',
                               ["punch.height", "cannot import"]),
    "height-not-vectorised": (None, 'height = "math:cos"\n', ["punch.height", "vectorised"]),
    "corner-inside-face": (None, 'slope = [0.0, 0.01]\ncorners = [-0.5, "free"]\n'
                           "face = [-1.0, 1.0]\n", ["punch", "inside the face"]),
}


@pytest.mark.parametrize("name", list(BAD_DATA))
def test_bad_profile_names_the_key_and_the_file(name, tmp_path):
    content, punch, expected = BAD_DATA[name]
    if isinstance(content, bytes):
        (tmp_path / "face.csv").write_bytes(content)
    elif content is not None:
        write_data(tmp_path, content)
    path = tmp_path / f"{name}.toml"
    path.write_text(HEAD + '[punch]\nkind = "profile"\n' + punch + MOTION)
    with pytest.raises(SceneError) as err:
        load_scene(path)
    message = str(err.value)
    assert message.startswith(str(path)) and err.value.allowed
    for piece in expected:
        assert piece in message, (piece, message)


def test_profile_height_alone_and_with_slope(tmp_path):
    (tmp_path / "cyl_face.py").write_text(
        "import numpy as np\n"
        "def height(X):\n    return np.asarray(X, dtype=float) ** 2 / 200.0\n"
        "def slope(X):\n    return np.asarray(X, dtype=float) / 100.0\n")
    ref = cylinder_closed_form(load=0.01, speed=0.3, friction=0.3, direction=1)
    width = ref.ends[1] - ref.ends[0]
    for keys, tol in (('height = "cyl_face:height"\n', 1e-10),
                      ('height = "cyl_face:height"\nslope = "cyl_face:slope"\n', 1e-12)):
        path = tmp_path / "s.toml"
        path.write_text(HEAD + '[punch]\nkind = "profile"\n' + keys +
                        "[motion]\nload = 0.01\nspeed = 0.3\nfriction = 0.3\ndirection = 1\n")
        ends = run_scene(load_scene(path)).cases[0].entry["ends"]
        assert np.max(np.abs(np.subtract(ends, ref.ends))) <= tol * width, keys


@pytest.fixture(scope="module")
def w_face_run(tmp_path_factory):
    """The shipped W-face scene through ``contact run`` (table printed, files written)."""
    import contextlib
    import io
    out = tmp_path_factory.mktemp("w_face")
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout):
        rc = cli.main(["run", str(SCENES / "w_face_two_zones.toml"), "--out", str(out)])
    assert rc == 0
    return json.loads((out / "result.json").read_text()), stdout.getvalue(), out


def test_w_face_lists_two_mirror_zones_carrying_the_load(w_face_run):
    """Independent checks: at friction 0 the face and the load are mirror-symmetric, so the
    zones are too; the zones' loads add up to the load."""
    result, _, _ = w_face_run
    assert [c["inputs"]["friction"] for c in result["cases"]] == [0.0, 0.3]
    for case in result["cases"]:
        assert list(case) == ["inputs", "zones", "pressure", "sigma_xx", "diagnostics"]
        zones = case["zones"]
        assert len(zones) == 2
        for z in zones:
            assert set(z) == {"ends", "kinds", "exponents", "index", "load"}
            assert z["kinds"] == ["free", "free"] and z["index"] == -1
            assert z["exponents"]["left"] + z["exponents"]["right"] == pytest.approx(1.0)
        (l1, r1), (l2, r2) = zones[0]["ends"], zones[1]["ends"]
        assert -2.0 < l1 < r1 < 0.0 < l2 < r2 < 2.0
        load = case["inputs"]["load"]
        assert abs(zones[0]["load"] + zones[1]["load"] - load) <= 1e-12 * load
    (l1, r1), (l2, r2) = (z["ends"] for z in result["cases"][0]["zones"])
    width = r2 - l1
    assert abs(l1 + r2) <= 1e-10 * width and abs(r1 + l2) <= 1e-10 * width
    x = np.array(result["cases"][0]["pressure"]["x"])
    p = np.array(result["cases"][0]["pressure"]["values"])
    inside = ((x > l1) & (x < r1)) | ((x > l2) & (x < r2))
    assert np.all(p[inside] > 0.0) and np.all(p[~inside] == 0.0)


def test_w_face_table_and_figures(w_face_run):
    result, table, out = w_face_run
    lines = table.splitlines()
    header = next(line for line in lines if line.strip().startswith("case"))
    assert header.split()[:3] == ["case", "friction", "zones"]
    rows = [line.split() for line in lines[lines.index(header) + 1:][:2]]
    for row, case in zip(rows, result["cases"]):
        zones = case["zones"]
        assert row[2] == "2"
        assert row[3:5] == [f"{zones[0]['ends'][0]:.10g}", f"{zones[1]['ends'][1]:.10g}"]
    assert "several zones" in table
    for name in ("pressure.png", "sigma_xx.png"):
        assert (out / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_sif_per_zone_with_several_zones(tmp_path):
    """A W face cut at X = +-1.01: each zone reaches an edge, a corner.  Reference: the
    definition K = lim |X - x_c|^(-e) p(X), from the pressure next to the corner."""
    from contact.scene import write_outputs
    s = scene(HEAD + """
        [punch]
        kind = "profile"
        slope = [0.0, -0.2, 0.0, 0.2]
        face = [-1.01, 1.01]
        [motion]
        load = 0.02
        speed = 0.3
        [outputs]
        fields = ["sif", "pressure"]
    """)
    res = run_scene(s)
    (case,) = res.cases
    assert list(case.entry) == ["inputs", "zones", "pressure"]
    left, right = case.entry["zones"]
    assert left["kinds"] == ["corner", "free"] and right["kinds"] == ["free", "corner"]
    assert set(left["sif"]) == {"left"} and set(right["sif"]) == {"right"}
    assert left["sif"]["left"] == pytest.approx(right["sif"]["right"], rel=1e-10)   # mirror
    ref = contact.solve(contact.zhou2014(), contact.ProfilePunch(
        lambda X: 0.2 * X ** 3 - 0.2 * X, face=(-1.01, 1.01)), load=0.02, speed=0.3)
    d = 1e-7
    e = left["exponents"]["left"]
    assert e < 0
    k_def = d ** (-e) * ref.pressure(np.array([-1.01 + d]))[0]
    assert left["sif"]["left"] == pytest.approx(k_def, rel=1e-5)
    x, p = case.curve("pressure")
    assert np.isnan(p[x == -1.01]).all() and np.isnan(p[x == 1.01]).all()
    assert x[0] < -1.01 and x[-1] > 1.01
    written = write_outputs(res, tmp_path)                 # one case: each zone shaded
    assert tmp_path / "pressure.png" in written


def test_zones_field_lists_one_zone_next_to_the_single_zone_fields():
    s = sweep_scene('kind = "triangular"\nslope = 0.01', ["ends", "zones", "exponents", "sif"],
                    friction="0.3", speed="0.6")
    (case,) = run_scene(s).cases
    assert list(case.entry) == ["inputs", "ends", "zones", "exponents", "sif"]
    (zone,) = case.entry["zones"]
    ref = contact.solve(contact.zhou2014(), contact.TriangularPunch(0.01), load=0.01, speed=0.6,
                        friction=0.3, method="closed_form")
    assert zone["ends"] == pytest.approx(list(ref.ends), rel=1e-12)
    assert zone["ends"] == case.entry["ends"] and zone["kinds"] == ["corner", "free"]
    assert zone["exponents"] == case.entry["exponents"]
    assert case.entry["exponents"] == {"left": ref.beta, "right": ref.alpha}
    assert zone["index"] == 0 and zone["load"] == pytest.approx(0.01, rel=1e-12)
    assert zone["sif"] == case.entry["sif"] and set(zone["sif"]) == {"left"}
    assert zone["sif"]["left"] == pytest.approx(ref.sif["left"], rel=1e-10)


def test_a_punch_that_cannot_be_built_fails_its_cases_by_name(monkeypatch):
    """A library error while building a chunk's material or punch is each of its cases'
    error: the run names the first case, as for an error while solving it."""
    def broken(spec):
        raise contact.PunchGeometryError("this face cannot be built here")
    monkeypatch.setattr(contact.scene.run, "build_once", broken)
    s = scene(CYL + "[motion]\nload = 0.01\nfriction = [0.0, 0.1]\n")
    with pytest.raises(CaseError, match=r"case 0 .*this face cannot be built here"):
        run_scene(s)


# --------------------------------------------------------------------------
# an elastic punch
# --------------------------------------------------------------------------
PUNCH_MATERIAL = """
[punch_material]
C11 = 200.0
C12 = 60.0
C22 = 200.0
C33 = 70.0
"""


def test_a_punch_material_makes_the_punch_elastic_as_solve_does():
    """[punch_material] (the keys of [material]): each case is contact.solve with
    punch_material=, the sweep batched as without it; echoed."""
    s = scene(CYL + PUNCH_MATERIAL + """
        [motion]
        load = 0.01
        speed = 0.5
        friction = [0.0, 0.3]
    """)
    assert s.echo()["punch_material"]["C33"] == 70.0
    steel = contact.Orthotropic(200.0, 60.0, 200.0, 70.0)
    for case in run_scene(s).cases:
        ref = contact.solve(contact.zhou2014(), contact.CylindricalPunch(100.0), load=0.01,
                            speed=0.5, friction=case.entry["inputs"]["friction"],
                            punch_material=steel)
        assert case.entry["ends"] == pytest.approx(list(ref.ends), abs=1e-13)
    rigid = run_scene(scene(CYL + "[motion]\nload = 0.01\nspeed = 0.5\n")).cases[0]
    assert rigid.entry["ends"][1] < case.entry["ends"][1]      # the pair is more compliant


@pytest.mark.parametrize("table,key", [("[punch_material]\nC11 = 1.0\n", "punch_material.C12"),
                                       ("[punch_material]\nC11s = 1.0\n", "punch_material.C11s"),
                                       ('[punch_material]\nfactory = "json:loads"\n',
                                        "punch_material")])
def test_a_bad_punch_material_names_its_key(table, key):
    with pytest.raises(SceneError) as exc:
        scene(CYL + table + "[motion]\nload = 0.01\n")
    assert exc.value.key.startswith(key), exc.value


# --------------------------------------------------------------------------
# partial slip and steady rolling
# --------------------------------------------------------------------------
ONE_MATERIAL = """
[material]
C11 = 3.0
C12 = 1.0
C22 = 3.0
C33 = 1.0
[punch_material]
C11 = 3.0
C12 = 1.0
C22 = 3.0
C33 = 1.0
[punch]
kind = "cylindrical"
radius = 1.0
"""
SLIP_MATERIAL = contact.Orthotropic(3.0, 1.0, 3.0, 1.0)


def test_a_tangential_load_sweep_is_cattaneos_partial_slip_as_solve_gives_it():
    """[motion] tangential_load = [...] (one material, at rest): each case is contact.solve
    with tangential_load=, its stick zone and shear (the tangential traction) to 1e-13, and
    the stick zone Cattaneo's c/a = sqrt(1 - Q/(mu P))."""
    s = scene(ONE_MATERIAL + """
        [motion]
        load = 0.01
        speed = 0.0
        friction = 0.5
        tangential_load = [0.001, 0.003]
        [outputs]
        fields = ["ends", "shear", "pressure"]
        x = { start = -0.12, stop = 0.12, num = 49 }
    """)
    assert s.sweep == (("motion", "tangential_load"),)
    res = run_scene(s)
    for case, Q in zip(res.cases, (0.001, 0.003)):
        e = case.entry
        assert list(e) == ["inputs", "tangential_load", "creepage", "stick_zones", "ends",
                           "shear", "pressure"]
        assert e["inputs"]["tangential_load"] == e["tangential_load"] == Q
        assert e["creepage"] is None                         # a static contact
        ref = contact.solve(SLIP_MATERIAL, contact.CylindricalPunch(1.0), load=0.01, speed=0.0,
                            friction=0.5, punch_material=SLIP_MATERIAL, tangential_load=Q)
        (stick,) = e["stick_zones"]
        assert stick == pytest.approx(list(ref.stick_zones[0].ends), abs=1e-13)
        assert e["ends"] == pytest.approx(list(ref.ends), abs=1e-13)
        x, q = case.curve("shear")
        assert q == pytest.approx(ref.tangential_traction(x), abs=1e-13)
        assert np.max(np.abs(q)) > 0
        a = e["ends"][1]
        assert stick[1] / a == pytest.approx(np.sqrt(1 - Q / (0.5 * 0.01)), rel=1e-10)
        assert stick[0] == pytest.approx(-stick[1], abs=1e-13)
    columns, rows = res.table()                        # the swept Q is a column of sweep.csv
    assert columns[:2] == ["case", "tangential_load"] and [r[1] for r in rows] == [0.001, 0.003]
    # ... once (an input), then the stick zone's ends (no creepage column: static)
    assert columns.count("tangential_load") == 1 and "creepage" not in columns
    for r, case in zip(rows, res.cases):
        cells = dict(zip(columns, r))
        assert cells["stick_zones"] == 1
        assert [cells["stick_x_left"], cells["stick_x_right"]] == case.entry["stick_zones"][0]
    from contact.scene.summary import format_table
    printed = format_table(res)
    assert "stick_x_left" in printed and "stick_x_right" in printed
    text = json.dumps(res.to_json())                   # JSON-ready
    assert '"stick_zones"' in text


def test_steady_rolling_with_a_creepage_gives_solves_tangential_load():
    """rolling = true with creepage: the entry's tangential_load is contact.solve's; the stick
    zone at the leading edge (toward direction = -1)."""
    xi = -0.011
    s = scene(ONE_MATERIAL + f"""
        [motion]
        load = 0.01
        friction = 0.5
        rolling = true
        creepage = {xi!r}
        [outputs]
        fields = ["ends", "constants"]
    """)
    (case,) = run_scene(s).cases
    e = case.entry
    ref = contact.solve(SLIP_MATERIAL, contact.CylindricalPunch(1.0), load=0.01, speed=0.0,
                        friction=0.5, punch_material=SLIP_MATERIAL, rolling=True, creepage=xi)
    assert e["inputs"]["rolling"] is True and e["inputs"]["creepage"] == xi
    assert e["creepage"] == ref.creepage == pytest.approx(xi, rel=1e-14)
    assert e["tangential_load"] == pytest.approx(ref.tangential_load, abs=1e-13)
    assert 0 < abs(e["tangential_load"]) < 0.5 * 0.01
    (stick,) = e["stick_zones"]
    assert stick == pytest.approx(list(ref.stick_zones[0].ends), abs=1e-13)
    assert stick[0] == pytest.approx(e["ends"][0], abs=1e-13)      # the leading edge
    assert "constants" in e and list(e)[:4] == ["inputs", "tangential_load", "creepage",
                                                "stick_zones"]
    # sweep.csv: the tangential load that follows from the creepage, and the stick zone
    columns, (row,) = run_scene(s).table()
    cells = dict(zip(columns, row))
    assert columns.count("creepage") == 1 and cells["creepage"] == xi           # the input
    assert cells["tangential_load"] == e["tangential_load"]
    assert [cells["stick_x_left"], cells["stick_x_right"]] == stick


def test_a_pair_that_couples_fails_its_partial_slip_case_by_name():
    """A rigid punch on the orthotropic half-space couples (N12 != 0): the case fails with
    contact.solve's CoupledPartialSlipError, named as other case errors are."""
    s = scene(ONE_MATERIAL.split("[punch_material]")[0] + """
        [punch]
        kind = "cylindrical"
        radius = 1.0
        [motion]
        load = 0.01
        friction = 0.5
        tangential_load = 0.002
    """)
    with pytest.raises(CaseError, match=r"case 0 .*tangential_load = 0\.002.*"
                                        r"CoupledPartialSlipError") as exc:
        run_scene(s)
    assert isinstance(exc.value.__cause__, contact.CoupledPartialSlipError)


@pytest.mark.parametrize("motion,key", [
    ("creepage = 0.01", "motion.creepage"),                         # without rolling
    ("rolling = true", "motion.rolling"),                           # without Q or creepage
    ("rolling = true\ntangential_load = 0.001\ncreepage = 0.01", "motion.creepage"),
    ('tangential_load = "0.001"', "motion.tangential_load"),
    ('tangential_load = [0.001, "x"]', "motion.tangential_load[1]"),
    ("rolling = true\ncreepage = [0.01, true]", "motion.creepage[1]"),
    ('rolling = "yes"\ntangential_load = 0.001', "motion.rolling"),
])
def test_bad_partial_slip_keys_are_named(motion, key):
    with pytest.raises(SceneError) as exc:
        scene(ONE_MATERIAL + "[motion]\nload = 0.01\nfriction = 0.5\n" + motion + "\n")
    assert exc.value.key == key, exc.value
