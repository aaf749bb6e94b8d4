"""Scenes (contact.scene): parsing good and bad files, sweeps, custom profiles, and the
"simulate only what the scene asks for" property, counted call by call.

Oracles: contact.solve called directly with the same inputs (the scene layer must not change a
number), and the scene files shipped in validation/scenes/.
"""
from __future__ import annotations

import json
import textwrap
from pathlib import Path

import numpy as np
import pytest

import contact
import contact.result
import contact.solver
from contact import cli
from contact.scene import (CURVE_FIELDS, DEFAULT_SCENE_TOML, CaseError, SceneError,
                           default_scene, load_scene, parse_scene_text, run_scene)

SCENES = Path(__file__).resolve().parents[1] / "validation" / "scenes"

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
@pytest.mark.parametrize("path", sorted(SCENES.glob("*.toml")), ids=lambda p: p.stem)
def test_shipped_scenes_parse(path):
    s = load_scene(path)
    cases = s.cases()
    if path.stem == "default":
        assert len(cases) == 1
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
    assert echo["outputs"] == {"fields": ["ends", "exponents", "pressure"], "x": None}
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
    "bad-n": (CYL + MOTION + "[numerics]\nn = 1\n", ["numerics.n", "[2, 100000]"]),
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
        "solve": counter(monkeypatch, contact, "solve"),
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
    X = np.linspace(-1.5, 1.5, 31)
    for case in res.cases:
        i = case.entry["inputs"]
        ref = contact.solve(contact.zhou2014(), contact.FlatPunch(1.0), load=i["load"],
                            speed=i["speed"], friction=i["friction"], direction=i["direction"])
        assert case.entry["ends"] == list(ref.ends)
        assert case.entry["exponents"] == [ref.alpha, ref.beta]
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
