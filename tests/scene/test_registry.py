"""The punch registry (contact.registry): one entry per punch class, read by the scene parser,
the scene runner and the command line.

Oracles: the classes ``contact`` exports, example scene values written here (one per scene
key), the functions of contact.closed_form, and a punch class defined here that only a
registry entry makes known to scenes.
"""
from __future__ import annotations

import inspect
import textwrap

import numpy as np
import pytest

import contact
import contact.closed_form
import contact.scene
from contact import cli
from contact.registry import KINDS, PunchKind, closed_form_kinds
from contact.scene import SceneError, parse_scene_text, run_scene

HEAD = '[material]\npreset = "zhou2014"\n'
MOTION = "[motion]\nload = 0.01\n"


def scene(punch: str, extra: str = "", **kw):
    return parse_scene_text(HEAD + "[punch]\n" + textwrap.dedent(punch) + MOTION + extra, **kw)


def exported_punch_classes():
    return {obj for name in contact.__all__ for obj in [getattr(contact, name)]
            if isinstance(obj, type) and issubclass(obj, contact.Punch) and obj is not contact.Punch}


def test_kinds_are_exactly_the_exported_punch_classes():
    assert {k.cls for k in KINDS.values()} == exported_punch_classes()
    assert len(KINDS) == len(exported_punch_classes())           # one kind per class
    for name, kind in KINDS.items():
        assert kind.name == name and kind.cls.kind == name        # the class's own name
        assert kind.form in ("dimensions", "profile") and kind.summary


def test_dimension_keys_are_keywords_of_the_class():
    for kind in KINDS.values():
        if kind.form == "dimensions":
            assert kind.keys == kind.dimensions
            params = inspect.signature(kind.cls).parameters
            assert set(kind.dimensions) <= set(params), kind.name


# one valid example per scene key of every kind; each parses in a scene of its own
def _examples(tmp_path):
    (tmp_path / "reg_face_fns.py").write_text(
        "import numpy as np\n"
        "def height(X):\n    return np.asarray(X, dtype=float) ** 2 / 200.0\n")
    X = np.linspace(-1.0, 1.0, 21)
    (tmp_path / "face.csv").write_text("X,h\n" + "".join(f"{x!r},{x * x / 200.0!r}\n"
                                                         for x in X.tolist()))
    pieces = ("[[punch.pieces]]\nto = 0.0\ncoefficients = [0.0, 0.01]\n"
              "[[punch.pieces]]\nfrom = 0.0\ncoefficients = [0.0, 0.02]\n")
    slope = "slope = [0.0, 0.01]\n"
    return {
        ("flat", "half_width"): "half_width = 1.0\n",
        ("triangular", "slope"): "slope = 0.01\n",
        ("parabolic", "radius"): "radius = 100.0\n",
        ("cylindrical", "radius"): "radius = 100.0\n",
        ("profile", "slope"): slope,
        ("profile", "height"): 'height = "reg_face_fns:height"\n',
        ("profile", "pieces"): pieces,
        ("profile", "data"): 'data = "face.csv"\n',
        ("profile", "interpolant"): 'data = "face.csv"\ninterpolant = "cubic"\n',
        ("profile", "breaks"): slope + "breaks = [0.5]\n",
        ("profile", "corners"): slope + 'corners = [-1.0, "free"]\n',
        ("profile", "face"): slope + "face = [-1.0, 1.0]\n",
    }


def test_every_scene_key_of_every_kind_parses(tmp_path):
    examples = _examples(tmp_path)
    assert set(examples) == {(k.name, key) for k in KINDS.values() for key in k.keys}
    for (name, key), text in examples.items():
        path = tmp_path / f"{name}_{key}.toml"
        path.write_text(HEAD + f'[punch]\nkind = "{name}"\n' + text + MOTION)
        s = contact.scene.load_scene(path)
        assert key in s.punch, (name, key)
        (case,) = s.cases()
        assert isinstance(case.punch.build(), KINDS[name].cls)
        for dim in KINDS[name].dimensions:
            assert case.inputs[dim] == s.punch[dim]


def test_parser_errors_list_the_registry_kinds():
    kinds = " | ".join(KINDS)
    for punch in ('kind = "cylinder"\n', "radius = 1.0\n", "kind = 3\n"):
        with pytest.raises(SceneError) as err:
            scene(punch)
        assert err.value.key == "punch.kind" and err.value.allowed == kinds
    for name, kind in KINDS.items():
        with pytest.raises(SceneError) as err:
            scene(f'kind = "{name}"\nno_such_key = 1.0\n')
        assert err.value.key == "punch.no_such_key"
        assert err.value.allowed == ", ".join(("kind",) + kind.keys)


def test_closed_form_entries_name_functions_of_contact_closed_form():
    have = closed_form_kinds()
    assert have == ("flat", "triangular", "parabolic", "cylindrical")
    forms = contact.closed_form.CLOSED_FORMS
    for name in have:
        kind = KINDS[name]
        # the registry names the function that contact.solve uses for that class
        assert kind.closed_form == f"{name}_closed_form" == forms[kind.cls].__name__
        assert forms[kind.cls] is getattr(contact.closed_form, kind.closed_form)
        dim = kind.dimensions[0]
        s = scene(f'kind = "{name}"\n{dim} = 1.0\n', '[numerics]\nmethod = "closed_form"\n')
        assert s.numerics.method == "closed_form"
    assert set(forms) == {KINDS[name].cls for name in have}
    assert KINDS["profile"].closed_form is None
    with pytest.raises(SceneError) as err:
        scene('kind = "profile"\nslope = [0.0, 0.01]\n', '[numerics]\nmethod = "closed_form"\n')
    assert err.value.key == "numerics.method"
    for name in have:
        assert name in str(err.value)


class BluntPunch(contact.FlatPunch):
    """A flat punch given by its full width (a class the library does not know)."""
    kind = "blunt"

    def __init__(self, width):
        super().__init__(half_width=width / 2.0)


def test_a_new_kind_needs_one_registry_entry(monkeypatch):
    monkeypatch.setitem(KINDS, "blunt", PunchKind("blunt", BluntPunch, "dimensions", ("width",),
                                                  ("width",), None, "flat, by its full width"))
    s = scene('kind = "blunt"\nwidth = [1.0, 3.0]\n', '[outputs]\nfields = ["ends"]\n')
    assert s.sweep == (("punch", "width"),) and s.title == "blunt punch"
    res = run_scene(s)
    assert [c.entry["inputs"]["width"] for c in res.cases] == [1.0, 3.0]
    assert [c.entry["ends"] for c in res.cases] == [[-0.5, 0.5], [-1.5, 1.5]]
    with pytest.raises(SceneError, match="punch.width"):
        scene('kind = "blunt"\nwidth = -1.0\n')
    with pytest.raises(SceneError) as err:
        scene('kind = "blunt"\nwidth = 1.0\n', '[numerics]\nmethod = "closed_form"\n')
    assert "not for a blunt punch" in str(err.value)


def test_contact_punches_lists_the_registry(capsys):
    assert cli.main(["punches"]) == 0
    out = capsys.readouterr().out
    for kind in KINDS.values():
        row = next(line for line in out.splitlines() if line.startswith(kind.name + " "))
        assert f"contact.{kind.cls.__name__}" in row and ", ".join(kind.keys) in row
        assert (kind.closed_form or "-") in row


def test_scene_documentation_names_every_kind_and_key():
    doc = contact.scene.__doc__
    for kind in KINDS.values():
        assert kind.name in doc
        for key in kind.keys:
            assert key in doc, key
