"""A scene's anisotropic material: ``[material] kind = "anisotropic"`` with its 6x6 stiffness
``C`` or the ``engineering`` constants of an orthotropic material, turned by ``rotation``.

Oracles: the material built directly (``contact.Anisotropic``, ``from_engineering``,
``rotated`` with ``scipy.spatial.transform.Rotation``; the scene layer must not change a
number), the aligned orthotropic material given as its 6x6 stiffness, which must give the
contact of ``contact.Orthotropic`` (Zhou et al. 2014, the paper's material), and the
parser's errors, which name the key.
"""
from __future__ import annotations

import textwrap

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import contact
from contact.scene import SceneError, parse_scene_text, run_scene

#: A carbon/epoxy ply in its own axes (1 along the fibres; GPa)
PLY = dict(E1=135.0, E2=10.0, E3=10.0, nu12=0.3, nu13=0.3, nu23=0.45, G12=5.0, G13=5.0,
           G23=3.45)
#: The out-of-plane stiffnesses that complete the paper's plane material (GPa)
OUT_OF_PLANE = dict(C13=5.0, C23=5.5, C33=15.0, C44=5.0, C55=5.4)


def _aligned_paper():
    return contact.Anisotropic.from_orthotropic(contact.zhou2014(), **OUT_OF_PLANE)


def _scene(material: str, motion: str = "load = 0.01\nspeed = [0.0, 0.6]\nfriction = 0.3",
           fields: str = '["ends", "exponents", "pressure", "constants"]') -> str:
    return textwrap.dedent('''
        [material]
        {material}
        [punch]
        kind = "cylindrical"
        radius = 100.0
        [motion]
        {motion}
        [outputs]
        fields = {fields}
        x = {{ start = -0.4, stop = 0.4, num = 9 }}
    ''').format(material=material, motion=motion, fields=fields)


def _engineering_table():
    return "\n[material.engineering]\n" + "\n".join(f"{k} = {v!r}" for k, v in PLY.items())


def _C_rows(m) -> str:
    return "C = [" + ", ".join("[" + ", ".join(repr(float(v)) for v in row) + "]"
                               for row in m.C) + "]"


def test_the_aligned_paper_material_as_a_6x6_stiffness_gives_the_paper_contact():
    """The 6x6 of the paper's material (its C11, C12, C22, C33 -> C11, C12, C22, C66) gives
    the Orthotropic contact: the ends to 1e-12 of the width, and M12 = M21 = M22 = 0."""
    s = parse_scene_text(_scene('kind = "anisotropic"\n' + _C_rows(_aligned_paper())))
    assert s.material.kind == "anisotropic" and s.material.build() == _aligned_paper()
    res = run_scene(s)
    for case in res.cases:
        ref = contact.solve(contact.zhou2014(), contact.CylindricalPunch(100.0), load=0.01,
                            speed=case.entry["inputs"]["speed"], friction=0.3)
        width = ref.ends[1] - ref.ends[0]
        assert np.allclose(case.entry["ends"], ref.ends, rtol=0, atol=1e-12 * width)
        x, values = case.curve("pressure")
        assert np.allclose(values, ref.pressure(x), rtol=0,
                           atol=1e-11 * np.max(ref.pressure(x)))
        k = case.entry["constants"]
        scale = abs(k["N11"])
        assert abs(k["M12"]) <= 1e-13 * scale and abs(k["M21"]) <= 1e-13 \
            and abs(k["M22"]) <= 1e-13
        assert k["eta_product"] is None and k["eta_sum"] is None


@pytest.mark.parametrize("rotation,turns", [
    ('rotation = { axis = "y", degrees = 30 }', [("y", 30.0)]),
    ('rotation = { axis = "z", degrees = -20.5 }', [("z", -20.5)]),
    ('rotation = [{ axis = "y", degrees = 30 }, { axis = "x", degrees = 90 }]',
     [("y", 30.0), ("x", 90.0)]),
])
def test_engineering_constants_turned_are_the_material_built_directly(rotation, turns):
    """The scene's material equals from_engineering(...) turned by each rotation in order
    (value equality of the 6x6), and its contact is contact.solve's on that material, bit
    for bit."""
    s = parse_scene_text(_scene('kind = "anisotropic"\nrho = 1.6\n' + rotation
                                + _engineering_table(),
                                motion="load = 0.01\nspeed = [0.0, 0.3]\nfriction = 0.3"))
    direct = contact.Anisotropic.from_engineering(**PLY, rho=1.6)
    for axis, degrees in turns:
        direct = direct.rotated(Rotation.from_euler(axis, degrees, degrees=True))
    assert s.material.build() == direct
    assert s.material.rotation == tuple(turns)
    res = run_scene(s)
    for case in res.cases:
        ref = contact.solve(direct, contact.CylindricalPunch(100.0), load=0.01,
                            speed=case.entry["inputs"]["speed"], friction=0.3)
        assert case.entry["ends"] == list(ref.ends)
        x, values = case.curve("pressure")
        assert np.array_equal(values, ref.pressure(x))
    echo = s.echo()["material"]
    assert echo["kind"] == "anisotropic" and echo["engineering"] == PLY
    assert echo["rotation"] == [{"axis": a, "degrees": d} for a, d in turns]
    assert "anisotropic (engineering constants" in s.material.describe()


def test_two_rotations_compose_as_one():
    """y by 30 then z by 40 degrees is the single rotation R_z(40) R_y(30) (active: the
    later rotation acts on the turned material)."""
    a = parse_scene_text(_scene('kind = "anisotropic"\nrotation = [{ axis = "y", degrees = 30 '
                                '}, { axis = "z", degrees = 40 }]' + _engineering_table(),
                                motion="load = 0.01\nspeed = 0.0"))
    R = (Rotation.from_euler("z", 40, degrees=True) * Rotation.from_euler("y", 30, degrees=True))
    direct = contact.Anisotropic.from_engineering(**PLY).rotated(R)
    assert np.allclose(a.material.build().C, direct.C, rtol=0, atol=1e-12 * PLY["E1"])


def test_velocity_needs_the_density_and_uses_C66():
    """velocity V -> c = V / sqrt(C66 / rho), C66 of the turned material."""
    s = parse_scene_text(_scene('kind = "anisotropic"\nrho = 1.6\n'
                                'rotation = { axis = "y", degrees = 30 }' + _engineering_table(),
                                motion="load = 0.01\nvelocity = 0.5"))
    m = s.material.build()
    res = run_scene(s)
    c = 0.5 / np.sqrt(m.C[5, 5] / 1.6)
    assert res.cases[0].entry["inputs"]["speed"] == pytest.approx(c, rel=1e-15)
    with pytest.raises(SceneError, match="motion.velocity"):
        parse_scene_text(_scene('kind = "anisotropic"\n' + _C_rows(_aligned_paper()),
                                motion="load = 0.01\nvelocity = 0.5"))


@pytest.mark.parametrize("material,key,match", [
    ('kind = "anisotropc"', "material.kind", "did you mean 'anisotropic'"),
    ('kind = "anisotropic"', "material", "needs C or engineering"),
    ('kind = "anisotropic"\nC = [[1.0, 2.0]]', "material.C", "6 x 6"),
    ('kind = "anisotropic"\nC = 3.0', "material.C", "6 x 6"),
    ('kind = "anisotropic"\nC11 = 3.0', "material.C11", "not a key of an anisotropic"),
    ('kind = "anisotropic"\nengineering = 3', "material.engineering", "must be a table"),
    ('kind = "anisotropic"\nengineering = { E1 = 1.0 }', "material.engineering.E2",
     "is missing"),
    ('kind = "anisotropic"\nrotation = { axis = "w", degrees = 3 }\n' + _C_rows(_aligned_paper()),
     "material.rotation.axis", '"x", "y" or "z"'),
    ('kind = "anisotropic"\nrotation = { axis = "x" }\n' + _C_rows(_aligned_paper()),
     "material.rotation.degrees", "is missing"),
    ('kind = "anisotropic"\nrotation = [{ axis = "x", degrees = "9" }]\n'
     + _C_rows(_aligned_paper()), r"material.rotation\[0\].degrees", "number"),
    ('kind = "anisotropic"\nrotation = { axis = "x", angle = 9 }\n' + _C_rows(_aligned_paper()),
     "material.rotation.angle", "unknown key"),
    ('preset = "zhou2014"\nrotation = { axis = "x", degrees = 9 }', "material.rotation",
     'kind = "anisotropic"'),
    ('kind = "anisotropic"\nC = [' + ", ".join(
        "[" + ", ".join("1.0" if i == j and i < 5 else "0.0" for j in range(6)) + "]"
        for i in range(6)) + "]", "material", "positive definite"),
    ('kind = "anisotropic"\nC = [' + ", ".join(
        "[" + ", ".join("1.0" if i == j or (i, j) == (0, 1) else "0.0" for j in range(6)) + "]"
        for i in range(6)) + "]", "material", "symmetric"),
])
def test_a_bad_anisotropic_material_names_the_key(material, key, match):
    with pytest.raises(SceneError, match=key) as err:
        parse_scene_text(_scene(material))
    assert err.match(match)


def test_both_C_and_engineering_are_refused():
    with pytest.raises(SceneError, match="exactly one of C and engineering"):
        parse_scene_text(_scene('kind = "anisotropic"\n' + _C_rows(_aligned_paper())
                                + _engineering_table()))


def test_the_roots_field_needs_characteristic_roots():
    with pytest.raises(SceneError, match=r"outputs.fields\[0\].*characteristic_roots"):
        parse_scene_text(_scene('kind = "anisotropic"\n' + _C_rows(_aligned_paper()),
                                fields='["roots"]'))


def test_a_case_travels_to_a_worker_as_plain_data():
    """A process pool rebuilds the turned ply from the case's plain data (picklable: a
    spawned or remote worker gets the same) and gives the serial run's numbers, the
    subsurface extrema included."""
    import pickle
    from concurrent.futures import ProcessPoolExecutor
    s = parse_scene_text(_scene('kind = "anisotropic"\nrotation = { axis = "z", degrees = 30 }'
                                + _engineering_table(),
                                motion="load = 0.01\nspeed = [0.0, 0.2]\nfriction = 0.3",
                                fields='["ends", "constants", "subsurface"]'))
    assert pickle.loads(pickle.dumps(s.material)) == s.material
    with ProcessPoolExecutor(2) as ex:
        pooled = run_scene(s, executor=ex)
    serial = run_scene(s)
    for a, b in zip(pooled.cases, serial.cases, strict=True):
        assert a.entry["ends"] == b.entry["ends"]
        assert a.entry["constants"] == b.entry["constants"]
        assert a.entry["subsurface"] == b.entry["subsurface"]
