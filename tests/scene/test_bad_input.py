"""Bad input is loud: each test pins down a finding of a new user's trial of ``contact``.

1. half_space_stress trusted its Cauchy transforms (a wrong shape, NaN, a real-valued
   transform, a non-callable or a dict as material went through or raised a raw TypeError).
2. An exception of any kind inside a profile punch's slope or height passed through raw.
3. Numbers given as strings (or bools) were accepted in some places and refused in others.
4. ``contact table1 | head`` printed "[Errno 32] Broken pipe".
5. A ``contact run`` killed with SIGKILL left its staging folder in --out for good.
"""
from __future__ import annotations

import math
import os
import subprocess
import sys

import numpy as np
import pytest

import contact
import sie
from contact import cli
from contact.samples import OutsideSamplesError, face_from_samples
from contact.scene import output

from cli_helpers import child_env, run_cli

ISO = contact.Isotropic(1.0, 0.3)


def flamant(z):
    """C_p of a line load P = 1 at the origin: (1/pi) int delta(t) / (t - z) dt."""
    return -1.0 / (np.pi * z)


# --------------------------------------------------------------------------
# 1. half_space_stress checks its material and its transforms
# --------------------------------------------------------------------------
def test_flamant_through_a_checked_transform_is_flamants_field():
    """The checks let a correct transform through: on the axis at depth d,
    sigma_yy = -2P / (pi d) (Flamant; Johnson 1985, eq. (2.16))."""
    f = contact.half_space_stress(ISO, 0.0, 0.0, -1.0, flamant)
    assert float(f.sigma_yy) == pytest.approx(-2.0 / math.pi, rel=1e-9)


def test_a_real_valued_transform_is_refused():
    """-1/(pi Re z) gave sigma_yy = -0.159 where Flamant's is -0.637: a transform real at
    Im z > 0 has lost its imaginary part (the Poisson integral of the traction)."""
    with pytest.raises(contact.CauchyTransformError, match="cauchy_p must return complex"):
        contact.half_space_stress(ISO, 0.0, 0.5, -1.0, lambda z: -1.0 / (np.pi * z.real))
    with pytest.raises(contact.CauchyTransformError, match="cauchy_q must return complex"):
        contact.half_space_stress(ISO, 0.0, 0.0, -1.0, flamant,
                                  cauchy_q=lambda z: np.zeros(z.shape))


def test_a_transform_of_the_wrong_shape_is_refused():
    with pytest.raises(contact.CauchyTransformError, match=r"vectorised.*shape \(3,\).*\(1,\)"):
        contact.half_space_stress(ISO, 0.0, [-1.0, 0.0, 1.0], -1.0,
                                  lambda z: flamant(z)[:1])


def test_a_transform_returning_nan_is_refused_at_its_point():
    def nan_right(z):
        return np.where(z.real > 0.5, np.nan, flamant(z))
    with pytest.raises(contact.CauchyTransformError,
                       match=r"non-finite value .* \(X, Y\) = \(1\.0, -1\.0\)"):
        contact.half_space_stress(ISO, 0.0, [0.0, 1.0], -1.0, nan_right)


@pytest.mark.parametrize("kwargs", [dict(cauchy_p="1/z"), dict(cauchy_p=flamant, cauchy_q=3.0)])
def test_a_transform_that_is_not_callable_is_refused(kwargs):
    with pytest.raises(contact.CauchyTransformError, match="must be a vectorised callable"):
        contact.half_space_stress(ISO, 0.0, 0.0, -1.0, **kwargs)


def test_a_dict_as_material_is_a_contact_input_error():
    with pytest.raises(contact.ContactInputError,
                       match="material must have the methods .* got dict, which lacks "
                             "surface_constants"):
        contact.half_space_stress({"E": 1.0, "nu": 0.3}, 0.0, 0.0, -1.0, flamant)


def _raising(kind):
    def fn(z):
        if kind is KeyError:
            return {}["p"]
        if kind is IndexError:
            return [][0]
        if kind is AttributeError:
            return z.no_such_attribute
        if kind is ZeroDivisionError:
            return 1 / 0
        raise kind("inside the user's callable")
    return fn


KINDS = [KeyError, IndexError, AttributeError, ZeroDivisionError, TypeError, RuntimeError,
         contact.StressPointError]


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("which", ["cauchy_p", "cauchy_q"])
def test_an_exception_inside_a_transform_names_the_transform_and_the_point(kind, which):
    kwargs = {"cauchy_p": flamant, which: _raising(kind)}
    with pytest.raises(contact.CauchyTransformError,
                       match=rf"{which} raised {kind.__name__} when called at z = .*"
                             r"\(X, Y\) = \(0\.25, -1\.0\)") as info:
        contact.half_space_stress(ISO, 0.0, 0.25, -1.0, **kwargs)
    assert isinstance(info.value.__cause__, kind)


def test_keyboard_interrupt_inside_a_transform_is_not_wrapped():
    def interrupted(z):
        raise KeyboardInterrupt
    with pytest.raises(KeyboardInterrupt):
        contact.half_space_stress(ISO, 0.0, 0.0, -1.0, interrupted)


# --------------------------------------------------------------------------
# 2. a profile punch's slope and height: any exception named, the package's own unchanged
# --------------------------------------------------------------------------
@pytest.mark.parametrize("kind", KINDS[:-1])
def test_an_exception_inside_a_slope_names_the_slope_and_its_x(kind):
    punch = contact.ProfilePunch(_raising(kind), face=(-1.0, 1.0))
    with pytest.raises(contact.ProfileCallableError,
                       match=rf"slope raised {kind.__name__} when called at X = 0\.5") as info:
        punch.slope(0.5)
    assert isinstance(info.value.__cause__, kind)
    with pytest.raises(contact.ProfileCallableError,
                       match=r"slope raised .* 11 points X in \[-1\.0, 1\.0\]"):
        punch.slope(np.linspace(-1.0, 1.0, 11))


@pytest.mark.parametrize("kind", [KeyError, ZeroDivisionError, AttributeError])
def test_an_exception_inside_a_height_names_the_height(kind):
    both = contact.ProfilePunch(lambda X: X, height=_raising(kind), face=(-1.0, 1.0))
    with pytest.raises(contact.ProfileCallableError,
                       match=rf"height raised {kind.__name__} when called at X = -0\.25"):
        both.height(-0.25)
    alone = contact.ProfilePunch(height=_raising(kind), face=(-1.0, 1.0))
    with pytest.raises(contact.ProfileCallableError,   # its slope is the height's derivative
                       match=rf"height raised {kind.__name__} when called at") as info:
        alone.slope(np.array([0.0, 0.5]))
    assert isinstance(info.value.__cause__, kind)


def test_solve_names_an_exception_inside_the_slope():
    punch = contact.ProfilePunch(_raising(ZeroDivisionError), face=(-1.0, 1.0))
    with pytest.raises(contact.ProfileCallableError, match="slope raised ZeroDivisionError"):
        contact.solve(ISO, punch, load=0.01, speed=0.0)


def test_keyboard_interrupt_inside_a_slope_is_not_wrapped():
    def interrupted(X):
        raise KeyboardInterrupt
    with pytest.raises(KeyboardInterrupt):
        contact.ProfilePunch(interrupted, face=(-1.0, 1.0)).slope(0.0)


def test_the_packages_own_errors_pass_through_a_slope_unchanged():
    """A sampled face asked beyond its samples raises OutsideSamplesError (with its hint):
    it reaches the user as that, not as a ProfileCallableError."""
    X = np.linspace(-1.0, 1.0, 20)
    face = face_from_samples(X, X ** 2)
    punch = contact.ProfilePunch(face.slope, breaks=face.breaks)
    with pytest.raises(OutsideSamplesError, match="outside='tangent'"):
        punch.slope(np.array([0.0, 3.0]))
    err = sie.EvaluationPointError("from sie")

    def sie_inside(X):
        raise err
    with pytest.raises(sie.EvaluationPointError) as info:
        contact.ProfilePunch(sie_inside, face=(-1.0, 1.0)).slope(0.0)
    assert info.value is err


# --------------------------------------------------------------------------
# 3. numbers given as text (or bools) are refused everywhere, numpy's scalars accepted
# --------------------------------------------------------------------------
PAPER = dict(C11=159.7885, C12=5.2609, C22=15.4732, C33=5.52)


@pytest.fixture(scope="module")
def flat():
    return contact.solve(ISO, contact.FlatPunch(1.0), load=1.0, speed=0.0)


def _cases():
    """(what, call, error, the text given) for every place a number is read."""
    cyl = contact.CylindricalPunch(1.0)
    solve = lambda **kw: contact.solve(ISO, cyl, **{"load": 0.01, "speed": 0.0, **kw})  # noqa: E731
    profile = lambda **kw: contact.ProfilePunch(lambda X: X, **kw)  # noqa: E731
    out = [(f"Orthotropic({k}=text)", lambda k=k: contact.Orthotropic(**{**PAPER, k: "159"}),
            contact.MaterialError, "'159'") for k in PAPER]
    out += [
        ("Orthotropic(rho=text)", lambda: contact.Orthotropic(**PAPER, rho="1.5"),
         contact.MaterialError, "'1.5'"),
        ("Isotropic(E=text)", lambda: contact.Isotropic("1.0", 0.3), contact.MaterialError,
         "'1.0'"),
        ("Isotropic(nu=text)", lambda: contact.Isotropic(1.0, "0.3"), contact.MaterialError,
         "'0.3'"),
        ("Orthotropic(C11=True)", lambda: contact.Orthotropic(**{**PAPER, "C11": True}),
         contact.MaterialError, "True"),
        ("relative_speed", lambda: contact.Orthotropic(**PAPER, rho=1.0).relative_speed("1"),
         contact.SpeedError, "'1'"),
        ("surface_constants", lambda: contact.surface_constants(ISO, "0.5"),
         contact.SpeedError, "'0.5'"),
        ("load", lambda: solve(load="0.01"), contact.LoadError, "'0.01'"),
        ("load=True", lambda: solve(load=True), contact.LoadError, "True"),
        ("speed", lambda: solve(speed="0.5"), contact.SpeedError, "'0.5'"),
        ("friction", lambda: solve(friction="0.2"), contact.FrictionError, "'0.2'"),
        ("tol", lambda: solve(tol="1e-12"), contact.ContactInputError, "'1e-12'"),
        ("solve_batch", lambda: contact.solve_batch(ISO, cyl, load=["0.01"], speed=0.0),
         contact.ContactInputError, "'0.01'"),
        ("load_curve", lambda: contact.load_curve(ISO, cyl, [0.01, "0.02"], speed=0.0),
         contact.LoadError, "'0.02'"),
        ("load_curve of bools", lambda: contact.load_curve(ISO, cyl, [True], speed=0.0),
         contact.LoadError, "True"),
        ("CylindricalPunch", lambda: contact.CylindricalPunch("100"),
         contact.PunchGeometryError, "'100'"),
        ("ParabolicPunch", lambda: contact.ParabolicPunch("1"), contact.PunchGeometryError,
         "'1'"),
        ("FlatPunch", lambda: contact.FlatPunch("1"), contact.PunchGeometryError, "'1'"),
        ("FlatPunch(True)", lambda: contact.FlatPunch(True), contact.PunchGeometryError,
         "True"),
        ("TriangularPunch", lambda: contact.TriangularPunch("0.1"),
         contact.PunchGeometryError, "'0.1'"),
        ("face", lambda: profile(face=("-1", "1")), contact.PunchGeometryError, "'-1'"),
        ("corners", lambda: profile(corners=("-1", None)), contact.PunchGeometryError, "'-1'"),
        ("breaks", lambda: profile(breaks=["0.5"]), contact.PunchGeometryError, "'0.5'"),
        ("from_samples face", lambda: contact.ProfilePunch.from_samples(
            np.linspace(-1, 1, 9), np.linspace(-1, 1, 9) ** 2, face=(-1.0, "1")),
         contact.PunchGeometryError, "'1'"),
        ("half_space_stress c", lambda: contact.half_space_stress(ISO, "0", 0.0, -1.0, flamant),
         contact.SpeedError, "'0'"),
        ("half_space_stress X", lambda: contact.half_space_stress(ISO, 0.0, "0", -1.0, flamant),
         contact.StressPointError, "'0'"),
        ("half_space_stress q_ratio", lambda: contact.half_space_stress(
            ISO, 0.0, 0.0, -1.0, flamant, q_ratio="0.2"), contact.FrictionError, "'0.2'"),
    ]
    return out


def _result_cases():
    """The same for the methods of a ContactResult (``r``)."""
    return [
        ("stress X", lambda r: r.stress(["0.0"], -1.0), contact.StressPointError, "'0.0'"),
        ("stress Y", lambda r: r.stress(0.0, "-1"), contact.StressPointError, "'-1'"),
        ("pressure", lambda r: r.pressure("0.5"), contact.ContactInputError, "'0.5'"),
        ("stress_extrema region", lambda r: r.stress_extrema(region=(("-2", 2.0), (-1.0, 0.0))),
         contact.ContactInputError, "'-2'"),
        ("stress_extrema region Y", lambda r: r.stress_extrema(region=((-2, 2), (-1, False))),
         contact.ContactInputError, "False"),
        ("stress_extrema grid", lambda r: r.stress_extrema(grid=("81", 61)),
         contact.ContactInputError, "'81'"),
    ]


def _sie_cases():
    """The same for sie: every number of an equation and every point of a solution."""
    import sie
    kw = dict(a=0.3, b=1.0, n=8, left="bounded", right="singular")

    def solve(**over):
        return sie.solve(np.cos, **{**kw, **over})
    sol = solve()
    return [
        ("sie a", lambda: solve(a="0.3"), sie.InvalidCoefficientError, "'0.3'"),
        ("sie b", lambda: solve(b="1"), sie.InvalidCoefficientError, "'1'"),
        ("sie a bool", lambda: solve(a=True), sie.InvalidCoefficientError, "True"),
        ("sie total", lambda: solve(left="singular", total="1"), sie.SideConditionError, "'1'"),
        ("sie intervals", lambda: solve(intervals=[("-1", 1.0)]), sie.InvalidIntervalError,
         "'-1'"),
        ("sie breaks", lambda: solve(breaks=["0.1"]), sie.InvalidBreakpointError, "'0.1'"),
        ("sie Equation a", lambda: sie.Equation(a="0.3", b=1.0, left="bounded",
                                                right="singular"),
         sie.InvalidCoefficientError, "'0.3'"),
        ("sie functionals breaks", lambda: sie.Equation(
            a=0.3, b=1.0, left="bounded", right="singular").functionals(np.cos, n=8,
                                                                        breaks=["0.1"]),
         sie.InvalidBreakpointError, "'0.1'"),
        ("sie case axis intervals", lambda: sie.Equation(
            a=0.3, b=1.0, left="bounded", right="singular", intervals=[[("-1", 1.0)]]),
         sie.InvalidIntervalError, "'-1'"),
        ("sie case axis total", lambda: sie.Equation(
            a=0.3, b=1.0, left="singular", right="singular",
            intervals=[[(-1.0, 1.0)]]).solve(np.cos, n=8, total="1"),
         sie.SideConditionError, "'1'"),
        ("sie solution point", lambda: sol("0.2"), sie.EvaluationPointError, "'0.2'"),
        ("sie log_potential point", lambda: sol.log_potential(["0.2"]),
         sie.EvaluationPointError, "'0.2'"),
        ("sie gauss_jacobi", lambda: sie.gauss_jacobi(8, "0.5", 0.0), sie.InvalidExponentError,
         "'0.5'"),
    ]


@pytest.mark.parametrize("what, call, error, given", _cases() + _sie_cases(),
                         ids=[c[0] for c in _cases() + _sie_cases()])
def test_a_number_given_as_text_or_bool_is_refused(what, call, error, given):
    with pytest.raises(error) as info:
        call()
    message = str(info.value)
    assert given in message and "not a real number" in message, message


@pytest.mark.parametrize("what, call, error, given", _result_cases(),
                         ids=[c[0] for c in _result_cases()])
def test_a_point_or_region_given_as_text_is_refused(flat, what, call, error, given):
    with pytest.raises(error) as info:
        call(flat)
    message = str(info.value)
    assert given in message and "not a real number" in message, message


def test_numpy_scalars_are_numbers():
    """np.float64 / np.int64 stay accepted, and give what the Python numbers give."""
    m = contact.Orthotropic(*(np.float64(v) for v in PAPER.values()), rho=np.int64(2))
    assert m == contact.Orthotropic(**PAPER, rho=2.0)
    punch = contact.CylindricalPunch(np.int64(100))
    r = contact.solve(m, punch, load=np.float64(0.01), speed=np.float64(0.5),
                      friction=np.float64(0.2))
    ref = contact.solve(contact.Orthotropic(**PAPER), contact.CylindricalPunch(100.0),
                        load=0.01, speed=0.5, friction=0.2)
    assert r.ends == ref.ends
    p = contact.ProfilePunch(lambda X: X, face=(np.int64(-1), np.float64(1.0)),
                             breaks=np.array([0.5]))
    assert p.extent == (-1.0, 1.0) and p.breaks == (0.5,)


# --------------------------------------------------------------------------
# 4. a closed stdout ends the command quietly (status 141, as SIGPIPE's victims report)
# --------------------------------------------------------------------------
@pytest.mark.slow
def test_table1_into_a_closed_pipe_ends_quietly_with_141():
    """`contact table1 | head -0`: the reader is gone before the table is written."""
    read, write = os.pipe()
    os.close(read)
    try:
        proc = subprocess.run([sys.executable, "-m", "contact", "table1"], stdout=write,
                              stderr=subprocess.PIPE, env=child_env(), timeout=60)
    finally:
        os.close(write)
    assert proc.stderr == b"" and proc.returncode == cli.EXIT_BROKEN_PIPE == 141


@pytest.mark.slow
def test_table1_read_one_line_then_closed_ends_quietly():
    """`contact table1 | head -1`: one line read, the pipe closed (whether the rest was
    written before the close is a race: status 0 or 141, never a message)."""
    proc = subprocess.Popen([sys.executable, "-m", "contact", "table1"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=child_env())
    first = proc.stdout.readline()
    proc.stdout.close()
    err = proc.stderr.read()
    proc.stderr.close()
    assert proc.wait(timeout=60) in (0, 141)
    assert first.startswith(b"Table 1") and err == b""


class _ClosedPipe:
    """A standard output whose reader has gone."""

    def write(self, text):
        raise BrokenPipeError(32, "Broken pipe")

    def flush(self):
        pass


SMALL_SCENE = ('title = "small"\n[material]\npreset = "zhou2014"\n[punch]\nkind = "flat"\n'
               'half_width = 1.0\n[motion]\nload = 1.0\nspeed = 0.0\n'
               '[outputs]\nfields = ["ends"]\nfigures = false\n')


def test_run_into_a_closed_stdout_keeps_its_files(tmp_path, monkeypatch, capsys):
    """`contact run | head -0`: the table cannot be printed, the files are written all the
    same and the status is 141, without a message."""
    scene = tmp_path / "s.toml"
    scene.write_text(SMALL_SCENE)
    monkeypatch.setattr(cli, "_stdout_gone", lambda: True)
    monkeypatch.setattr(cli, "_silence_stdout", lambda: monkeypatch.setattr(sys, "stdout",
                                                                            open(os.devnull, "w")))
    monkeypatch.setattr(sys, "stdout", _ClosedPipe())
    rc = cli.main(["run", str(scene), "--out", str(tmp_path / "out")])
    sys.stdout.close()
    assert rc == 141 and capsys.readouterr().err == ""
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["result.json", "sweep.csv"]


# --------------------------------------------------------------------------
# 5. a dead run's staging folder is removed by the next run, and said so
# --------------------------------------------------------------------------
def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_a_dead_runs_staging_folder_is_removed_and_named(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    host = output._host()
    dead = out / f".contact-writing-{host}-{_dead_pid()}-k1ll3d0"
    (dead / "sweep.rows").parent.mkdir()
    (dead / "sweep.rows").write_text("a half-written row")
    live = out / f".contact-writing-{host}-{os.getppid()}-runn1ng"   # our parent: alive
    live.mkdir()
    foreign = out / ".contact-writing-otherhost-4242-elsewhere"
    foreign.mkdir()
    scene = tmp_path / "s.toml"
    scene.write_text(SMALL_SCENE)
    rc, _, err = run_cli("run", scene, "--out", out, "--quiet")
    assert rc == 0
    assert not dead.exists() and f"removed {dead.name}" in err
    assert live.is_dir() and live.name not in err          # a live run's is not touched
    assert foreign.is_dir() and foreign.name in err and "host otherhost" in err
    assert sorted(p.name for p in out.iterdir() if not p.name.startswith(".")) == [
        "result.json", "sweep.csv"]
    assert {p for p in out.iterdir() if p.name.startswith(".")} == {live, foreign}


def test_a_writers_staging_folder_names_its_host_and_process(tmp_path):
    from contact.scene import load_scene
    scene = tmp_path / "s.toml"
    scene.write_text(SMALL_SCENE)
    with output.SceneWriter(load_scene(scene), tmp_path / "out", 1) as writer:
        spool, = (tmp_path / "out").glob(".contact-writing-*")
        assert output.staging_owner(spool.name) == (output._host(), os.getpid())
        assert writer.staging_notes == []
    assert list((tmp_path / "out").glob(".contact-writing-*")) == []
