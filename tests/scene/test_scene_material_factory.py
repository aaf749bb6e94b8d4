"""A scene's material of one's own: ``[material] factory = "module:function"`` with its
keyword ``arguments``, imported from the scene's directory as a profile's functions are, and
built again wherever a case is solved.

Oracles: contact.solve with the same material built directly (the scene layer must not
change a number), Hertz's half-width for the static isotropic material of the module below
(Johnson, Contact Mechanics 1985, eq. (5.7) with E* = 2G / (1 - nu) for a rigid cylinder
on a plane-strain half-space), and the scene parser's errors, which name the key.
"""
from __future__ import annotations

import math
import multiprocessing
import pickle
import textwrap
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest

import contact
from contact import cli
from contact.scene import SceneError, load_scene, run_scene

#: The module the scenes name (a name of its own: a module is imported once per process).
MODULE = "user_materials_of_scenes"
MODULE_TEXT = textwrap.dedent('''
    import math
    import contact


    class Wrapped:
        """An Orthotropic by composition (not a subclass)."""
        def __init__(self, inner):
            self.inner = inner
        def surface_constants(self, c):
            return self.inner.surface_constants(c)
        def rayleigh_speed(self):
            return self.inner.rayleigh_speed()
        def limiting_speed(self):
            return self.inner.limiting_speed()
        def relative_speed(self, V):
            return self.inner.relative_speed(V)
        def half_space_modes(self, c):
            return self.inner.half_space_modes(c)


    def wrapped(C11, C12, C22, C33, rho=None):
        return Wrapped(contact.Orthotropic(C11, C12, C22, C33, rho=rho))


    class StaticIsotropic:
        """Isotropic, at rest, plane strain: the classical constants; the Rayleigh speed of
        nu = 1/4 only (sqrt(2 - 2/sqrt(3))), the field of contact.Isotropic at rest."""
        def __init__(self, G, nu):
            self.G, self.nu = G, nu
            self.field = contact.Isotropic(2.0 * G * (1.0 + nu), nu)
        def surface_constants(self, c):
            G, nu = self.G, self.nu
            return contact.SurfaceConstants(N11=-(1 - nu) / G, N12=(1 - 2 * nu) / (2 * G),
                                            N21=-1.0, N22=-2.0, c=c,
                                            rayleigh_speed=self.rayleigh_speed())
        def rayleigh_speed(self):
            return math.sqrt(2.0 - 2.0 / math.sqrt(3.0))
        def limiting_speed(self):
            return 1.0
        def relative_speed(self, V):
            raise contact.MaterialError("StaticIsotropic has no density")
        def half_space_modes(self, c):
            return self.field.half_space_modes(c)


    def static_isotropic(G, nu=0.25):
        return StaticIsotropic(G, nu)


    def not_a_material():
        return "steel"


    def raising(**kwargs):
        raise RuntimeError("no such alloy")


    class Unhashable(Wrapped):
        __hash__ = None


    def unhashable():
        return Unhashable(contact.zhou2014())


    def nan_rayleigh():
        m = wrapped(159.7885, 5.2609, 15.4732, 5.52)
        m.rayleigh_speed = lambda: float("nan")
        return m
''')

PAPER = dict(C11=159.7885, C12=5.2609, C22=15.4732, C33=5.52)
GRID = ("{ x = { start = -0.2, stop = 0.2, num = 9 }, "
        "y = { start = -0.2, stop = 0.0, num = 5 } }")
CYL = '[punch]\nkind = "cylindrical"\nradius = 100.0\n'


@pytest.fixture
def where(tmp_path):
    (tmp_path / f"{MODULE}.py").write_text(MODULE_TEXT)

    def write(text, name="s.toml"):
        path = tmp_path / name
        path.write_text(textwrap.dedent(text))
        return path
    return write


def wrapped_scene(motion, fields='["ends", "exponents", "pressure", "constants"]', rho=""):
    return f'''
        [material]
        factory = "{MODULE}:wrapped"
        arguments = {{ C11 = 159.7885, C12 = 5.2609, C22 = 15.4732, C33 = 5.52{rho} }}
        [punch]
        kind = "cylindrical"
        radius = 100.0
        [motion]
        {motion}
        [outputs]
        fields = {fields}
        x = {{ start = -0.4, stop = 0.4, num = 9 }}
    '''


def test_a_factory_material_gives_the_contact_of_the_material_itself(where):
    s = load_scene(where(wrapped_scene("load = 0.01\nspeed = [0.3, 0.6]\nfriction = 0.3")))
    assert s.material.factory == f"{MODULE}:wrapped" and s.material.C11 is None
    res = run_scene(s)
    for case in res.cases:
        ref = contact.solve(contact.Orthotropic(**PAPER), contact.CylindricalPunch(100.0),
                            load=0.01, speed=case.entry["inputs"]["speed"], friction=0.3)
        assert case.entry["ends"] == list(ref.ends)
        x, values = case.curve("pressure")
        assert np.array_equal(values, ref.pressure(x))
        k = ref.constants
        assert case.entry["constants"] == {"N11": k.N11, "N12": k.N12, "N21": k.N21,
                                           "N22": k.N22, "M12": 0.0, "M21": 0.0, "M22": 0.0,
                                           "rayleigh_speed": k.rayleigh_speed,
                                           "eta_product": k.eta_product, "eta_sum": k.eta_sum}
    assert s.echo()["material"] == {"factory": f"{MODULE}:wrapped",
                                    "arguments": {**PAPER}}


def test_velocities_are_converted_by_the_factory_material(where):
    s = load_scene(where(wrapped_scene("load = 0.01\nvelocity = [0.5, 0.9]",
                                       rho=", rho = 5.52")))      # sqrt(C33/rho) = 1
    assert [c.inputs["speed"] for c in s.cases()] == [0.5, 0.9]
    with pytest.raises(SceneError, match=r"motion\.velocity: velocity = 0\.5: rho is None: "
                                         r"give the density"):
        load_scene(where(wrapped_scene("load = 0.01\nvelocity = 0.5")))


def test_a_material_without_the_orthotropic_quantities_leaves_their_cells_empty(where):
    path = where(f'''
        [material]
        factory = "{MODULE}:static_isotropic"
        arguments = {{ G = 2.0 }}
        [punch]
        kind = "cylindrical"
        radius = 1.0
        [motion]
        load = [0.01, 0.04]
        [outputs]
        fields = ["ends", "constants", "subsurface"]
        grid = {GRID}
    ''')
    res = run_scene(load_scene(path))
    G, nu = 2.0, 0.25
    for case in res.cases:
        P = case.entry["inputs"]["load"]
        a = math.sqrt(4.0 * P * 1.0 / (math.pi * 2.0 * G / (1.0 - nu)))   # Hertz
        assert case.entry["ends"] == pytest.approx([-a, a], rel=1e-12)
        k = case.entry["constants"]
        assert (k["N11"], k["N12"], k["N21"], k["N22"]) == (-(1 - nu) / G,
                                                            (1 - 2 * nu) / (2 * G), -1.0, -2.0)
        assert k["eta_product"] is None and k["eta_sum"] is None
        p0 = 2.0 * P / (math.pi * a)
        assert case.entry["subsurface"]["max_shear"]["value"] == pytest.approx(0.3 * p0,
                                                                              rel=0.01)
    columns, rows = res.table()
    assert [r[columns.index("eta_sum")] for r in rows] == [None, None]


def test_the_constants_command_prints_a_dash_where_a_material_has_no_roots(where, capsys):
    path = where(f'''
        [material]
        factory = "{MODULE}:static_isotropic"
        arguments = {{ G = 2.0 }}
        {CYL}
        [motion]
        load = 0.01
    ''')
    assert cli.main(["constants", str(path)]) == 0
    out = capsys.readouterr().out
    assert f"{MODULE}:static_isotropic(G=2.0)" in out
    assert out.splitlines()[-1].split() == ["0", "-0.375", "0.125", "-1", "-2", "-", "-"]


def test_an_unhashable_material_is_built_and_asked_per_group(where):
    path = where(f'[material]\nfactory = "{MODULE}:unhashable"\n{CYL}'
                 "[motion]\nload = 0.01\nspeed = [0.0, 0.3]\n")
    res = run_scene(load_scene(path))
    assert [c.entry["ends"] for c in res.cases] == [
        list(contact.solve(contact.zhou2014(), contact.CylindricalPunch(100.0), load=0.01,
                           speed=v).ends) for v in (0.0, 0.3)]


def test_a_case_travels_as_plain_data(where):
    s = load_scene(where(wrapped_scene("load = 0.01\nspeed = 0.3")))
    case = s.case(0)
    again = pickle.loads(pickle.dumps(case))
    assert again == case and again.material.build().inner == contact.Orthotropic(**PAPER)


@pytest.mark.slow
def test_a_fresh_worker_process_imports_the_factory_from_the_scene_directory(where):
    s = load_scene(where(wrapped_scene("load = 0.01\nspeed = [0.0, 0.3, 0.6]")))
    with ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("spawn")) as ex:
        pooled = run_scene(s, executor=ex)
    serial = run_scene(s)
    for a, b in zip(pooled.cases, serial.cases, strict=True):
        assert a.entry["ends"] == b.entry["ends"] and a.entry["constants"] == b.entry["constants"]
        assert np.array_equal(a.curve("pressure")[1], b.curve("pressure")[1])


FACTORY_BAD = {
    "does-not-import": ('factory = "no_such_module_xyz:make"',
                        ["material.factory", "cannot import", "no_such_module_xyz"]),
    "not-module-function": ('factory = "steel"', ["material.factory", "'module:function'"]),
    "not-a-string": ("factory = 3", ["material.factory", "must be a string", "integer 3"]),
    "raises": (f'factory = "{MODULE}:raising"',
               ["material.factory", f"{MODULE}:raising(**arguments) raised RuntimeError: no "
                "such alloy", "contact.Material"]),
    "wrong-arguments": (f'factory = "{MODULE}:static_isotropic"\narguments = {{ E = 1.0 }}',
                        ["material.factory", "raised TypeError", "'E'"]),
    "not-a-material": (f'factory = "{MODULE}:not_a_material"',
                       ["material.factory", "returned str", "which lacks surface_constants"]),
    "nan-rayleigh-speed": (f'factory = "{MODULE}:nan_rayleigh"',
                           ["material.factory", "rayleigh_speed() (a relative speed) must be "
                            "a finite real number, got nan"]),
    "with-stiffness": (f'factory = "{MODULE}:wrapped"\nC11 = 1.0',
                       ["material.C11", "given together with material.factory"]),
    "with-rho": (f'factory = "{MODULE}:wrapped"\nrho = 1.0',
                 ["material.rho", "given together with material.factory"]),
    "arguments-without-factory": ('preset = "zhou2014"\narguments = { G = 1.0 }',
                                  ["material.arguments", "without material.factory"]),
    "arguments-not-a-table": (f'factory = "{MODULE}:static_isotropic"\narguments = [1.0]',
                              ["material.arguments", "must be a table, got a list"]),
    "argument-a-table": (f'factory = "{MODULE}:static_isotropic"\n'
                         "arguments = { G = { value = 1.0 } }",
                         ["material.arguments.G", "must be a number, string or boolean"]),
    "unknown-key": (f'factory = "{MODULE}:wrapped"\nargs = {{ }}',
                    ["material.args", "did you mean 'arguments'"]),
}


@pytest.mark.parametrize("name", list(FACTORY_BAD))
def test_a_bad_factory_names_the_key(name, where):
    material, expected = FACTORY_BAD[name]
    path = where(f"[material]\n{material}\n{CYL}[motion]\nload = 0.01\n", name=f"{name}.toml")
    with pytest.raises(SceneError) as err:
        load_scene(path)
    message = str(err.value)
    assert message.startswith(str(path))
    for piece in expected:
        assert piece in message, (piece, message)


def test_roots_need_a_material_with_characteristic_roots(where):
    path = where(f'[material]\nfactory = "{MODULE}:static_isotropic"\narguments = {{ G = 1.0 }}\n'
                 f'{CYL}[motion]\nload = 0.01\n[outputs]\nfields = ["ends", "roots"]\n')
    with pytest.raises(SceneError, match=r"outputs\.fields\[1\]: the roots are the "
                                         r"characteristic roots .* has no "
                                         r"characteristic_roots\(c\)"):
        load_scene(path)


def test_a_factory_material_above_its_rayleigh_speed_is_refused(where):
    path = where(f'[material]\nfactory = "{MODULE}:static_isotropic"\narguments = {{ G = 1.0 }}\n'
                 f'{CYL}[motion]\nload = 0.01\nspeed = 0.95\n')
    with pytest.raises(SceneError, match=r"motion\.speed: 0\.95 is not below the Rayleigh "
                                         r"speed of this material, c_R = 0\.9194"):
        load_scene(path)
