"""Reading and validating scene TOML (every problem is a SceneError naming file and key)."""
from __future__ import annotations

import difflib
import math
import tomllib
from pathlib import Path

import numpy as np

import contact
from sie import N_MAX

from contact.registry import (INTERPOLANTS, KINDS, PROFILE_SHAPE_KEYS, Piece, Samples,
                              closed_form_kinds, import_callable)

from .spec import (DEFAULT_FIELDS, DEFAULT_SCENE_TOML, ENGINEERING_KEYS, FIELDS, FREE,
                   GRID_KEYS, MATERIAL_KEYS, MATERIAL_KINDS, METHODS, MOTION_KEYS, MaterialSpec, NUMERICS_KEYS, Numerics, OUTPUT_KEYS,
                   PIECE_KEYS, PRESETS, PunchSpec, SECTIONS, SUBSURFACE_MAX_POINTS,
                   ROTATION_KEYS, SUBSURFACE_POINTS, Scene, SceneError, SubsurfaceGrid, XGrid,
                   X_KEYS, anisotropic_material)


# --------------------------------------------------------------------------
# parsing and validation
# --------------------------------------------------------------------------
def default_scene() -> Scene:
    """The embedded default scene (:data:`DEFAULT_SCENE_TOML`)."""
    return parse_scene_text(DEFAULT_SCENE_TOML, source="<embedded default>")


def load_scene(path) -> Scene:
    """Read, parse and validate a scene file.

    Raises
    ------
    SceneError
        For any problem: unreadable file, TOML syntax (with its line), unknown key (with the
        closest known one), wrong type, missing load, speed >= c_R, negative friction, a
        profile function that does not import, ...  Nothing is solved before it returns.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise SceneError(path, None, "no such scene file") from None
    except IsADirectoryError:
        raise SceneError(path, None, "is a directory, not a scene file",
                         "a TOML file, e.g. validation/scenes/default.toml") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise SceneError(path, None, f"cannot be read: {exc}") from None
    return parse_scene_text(text, source=str(path), base_dir=str(path.resolve().parent))


def parse_scene_text(text: str, source: str = "<string>", base_dir=None) -> Scene:
    """Parse and validate a scene given as TOML text (see :func:`load_scene`)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(source, None, f"TOML syntax error: {exc}",
                         "TOML, see https://toml.io") from None
    return _Parser(source, base_dir).scene(data)


class _Parser:
    """Turns the dict from tomllib into a :class:`Scene`, raising SceneError on the way."""

    def __init__(self, source, base_dir):
        self.source = str(source)
        self.base_dir = base_dir

    def error(self, key, problem, allowed=None):
        return SceneError(self.source, key, problem, allowed)

    # ---- generic checks ---------------------------------------------------
    def check_keys(self, table: dict, allowed, where: str, hint: str = ""):
        for key in table:
            if key not in allowed:
                close = difflib.get_close_matches(key, allowed, n=1, cutoff=0.5)
                guess = f"; did you mean {close[0]!r}?" if close else ""
                name = f"{where}.{key}" if where else key
                raise self.error(name, f"unknown key{hint}{guess}", ", ".join(allowed))

    def table(self, data: dict, name: str, required=False) -> dict:
        if name not in data:
            if required:
                raise self.error(name, f"the [{name}] section is missing")
            return {}
        value = data[name]
        if not isinstance(value, dict):
            raise self.error(name, f"must be a table [{name}], got {_describe(value)}")
        return value

    def number(self, key, value, allowed="a number") -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.error(key, f"must be a number, got {_describe(value)}", allowed)
        v = float(value)
        if not math.isfinite(v):
            raise self.error(key, f"must be finite, got {v!r}", allowed)
        return v

    def values(self, key, value, check, sweepable=True):
        """A scalar, or a list of scalars (a sweep): each passed through ``check``."""
        if isinstance(value, list) and sweepable:
            if not value:
                raise self.error(key, "is an empty list", "a value, or a non-empty list of "
                                 "values (a sweep)")
            return tuple(check(f"{key}[{k}]", v) for k, v in enumerate(value))
        return check(key, value)

    # ---- sections -----------------------------------------------------------
    def scene(self, data: dict) -> Scene:
        self.check_keys(data, SECTIONS, "")
        title = data.get("title", "")
        if not isinstance(title, str):
            raise self.error("title", f"must be a string, got {_describe(title)}")
        material = self.material(self.table(data, "material", required=True))
        punch_material = self.punch_material(data)
        punch = self.punch(self.table(data, "punch", required=True))
        motion = self.motion(self.table(data, "motion", required=True), material)
        fields, x, grid, figures = self.outputs(self.table(data, "outputs"))
        numerics = self.numerics(self.table(data, "numerics"), punch["kind"])
        order = [name for name in data if name in ("punch", "motion")]
        sweepable = {"punch": KINDS[punch["kind"]].dimensions, "motion": MOTION_KEYS}
        sweep = tuple((sec, key) for sec in order
                      for key, v in (punch if sec == "punch" else motion).items()
                      if isinstance(v, tuple) and key in sweepable[sec])
        if not title:
            title = _default_title(punch)
        scene = Scene(source=self.source, title=title, material=material, punch=punch,
                      motion=motion, fields=fields, x=x, numerics=numerics, sweep=sweep,
                      base_dir=self.base_dir, grid=grid, figures=figures,
                      punch_material=punch_material)
        self.check_cases(scene)
        return scene

    def material(self, table: dict, section: str = "material") -> MaterialSpec:
        self.check_keys(table, MATERIAL_KEYS, section)
        if "factory" in table:
            return self.material_factory(table, section)
        if "arguments" in table:
            raise self.error(f"{section}.arguments", f"given without {section}.factory",
                             'factory = "module:function" with arguments = { ... } (its '
                             "keyword arguments)")
        kind = table.get("kind", "orthotropic")
        if kind not in MATERIAL_KINDS:
            close = difflib.get_close_matches(str(kind), MATERIAL_KINDS, n=1)
            guess = f"; did you mean {close[0]!r}?" if close else ""
            raise self.error(f"{section}.kind", f"unknown kind {kind!r}{guess}",
                             " | ".join(MATERIAL_KINDS))
        rho = None
        if "rho" in table:
            rho = self.number(f"{section}.rho", table["rho"], "a density > 0")
            if rho <= 0:
                raise self.error(f"{section}.rho", f"must be > 0, got {rho!r}", "a density > 0")
        if kind == "anisotropic":
            return self.anisotropic(table, rho, section)
        aniso = [k for k in ("C", "engineering", "rotation") if k in table]
        if aniso:
            raise self.error(f"{section}.{aniso[0]}", "is a key of an anisotropic material",
                             'kind = "anisotropic" with C or engineering (and rotation), or '
                             "an orthotropic material's C11, C12, C22, C33 or preset")
        stiff = [k for k in ("C11", "C12", "C22", "C33") if k in table]
        if "preset" in table:
            preset = table["preset"]
            if stiff:
                raise self.error(f"{section}.{stiff[0]}", f"given together with {section}.preset",
                                 "either preset or all of C11, C12, C22, C33")
            if preset not in PRESETS:
                close = difflib.get_close_matches(str(preset), PRESETS, n=1)
                guess = f"; did you mean {close[0]!r}?" if close else ""
                raise self.error(f"{section}.preset", f"unknown preset {preset!r}{guess}",
                                 ", ".join(repr(p) for p in PRESETS))
            m = PRESETS[preset]()
            return MaterialSpec(m.C11, m.C12, m.C22, m.C33, rho=rho, preset=preset)
        missing = [k for k in ("C11", "C12", "C22", "C33") if k not in table]
        if missing:
            raise self.error(f"{section}.{missing[0]}", "is missing",
                             'all of C11, C12, C22, C33 (numbers), or preset = "zhou2014"')
        C = [self.number(f"{section}.{k}", table[k], "a number (stiffness; sweeps are allowed "
                         "only under [motion] and [punch])") for k in ("C11", "C12", "C22", "C33")]
        try:
            contact.Orthotropic(*C, rho=rho)
        except contact.MaterialError as exc:
            raise self.error(section, str(exc)) from None
        return MaterialSpec(*C, rho=rho)

    def anisotropic(self, table: dict, rho, section: str = "material") -> MaterialSpec:
        """``kind = "anisotropic"``: ``C`` (6x6, Voigt order XX, YY, ZZ, YZ, ZX, XY) or
        ``engineering`` = {E1, E2, E3, nu12, nu13, nu23, G12, G13, G23}, and ``rotation``:
        a table {axis, degrees} or a list of them, applied in order."""
        allowed = ('C = [[...6 numbers...] x 6] (the stiffness, Voigt order XX, YY, ZZ, YZ, '
                   "ZX, XY) or engineering = { E1, E2, E3, nu12, nu13, nu23, G12, G13, G23 }, "
                   'with rotation = { axis = "x" | "y" | "z", degrees = ... } (or a list of '
                   "them) and rho")
        other = [k for k in table if k not in ("kind", "C", "engineering", "rotation", "rho")]
        if other:
            raise self.error(f"{section}.{other[0]}", "is not a key of an anisotropic material",
                             allowed)
        given = [k for k in ("C", "engineering") if k in table]
        if len(given) != 1:
            raise self.error(section, "needs exactly one of C and engineering" if given
                             else "needs C or engineering", allowed)
        C = engineering = None
        if "C" in table:
            rows = table["C"]
            if not (isinstance(rows, list) and len(rows) == 6
                    and all(isinstance(r, list) and len(r) == 6 for r in rows)):
                raise self.error(f"{section}.C", "must be a 6 x 6 array (six lists of six "
                                 "numbers)", allowed)
            C = tuple(tuple(self.number(f"{section}.C[{i}][{j}]", v, "a number (stiffness)")
                            for j, v in enumerate(row)) for i, row in enumerate(rows))
        else:
            eng = table["engineering"]
            if not isinstance(eng, dict):
                raise self.error(f"{section}.engineering", f"must be a table, got "
                                 f"{_describe(eng)}", allowed)
            self.check_keys(eng, ENGINEERING_KEYS, f"{section}.engineering")
            missing = [k for k in ENGINEERING_KEYS if k not in eng]
            if missing:
                raise self.error(f"{section}.engineering.{missing[0]}", "is missing",
                                 "all of " + ", ".join(ENGINEERING_KEYS))
            engineering = tuple((k, self.number(f"{section}.engineering.{k}", eng[k]))
                                for k in ENGINEERING_KEYS)
        rotation = table.get("rotation", [])
        turns = rotation if isinstance(rotation, list) else [rotation]
        parsed = []
        for k, turn in enumerate(turns):
            key = f"{section}.rotation" + (f"[{k}]" if isinstance(rotation, list) else "")
            if not isinstance(turn, dict):
                raise self.error(key, f"must be a table, got {_describe(turn)}",
                                 '{ axis = "x" | "y" | "z", degrees = ... }')
            self.check_keys(turn, ROTATION_KEYS, key)
            axis = turn.get("axis")
            if axis not in ("x", "y", "z"):
                raise self.error(f"{key}.axis", f"must be \"x\", \"y\" or \"z\", got "
                                 f"{_describe(axis)}", "the problem's axis X (sliding), Y "
                                 "(the surface's normal) or Z (the punch's generators)")
            if "degrees" not in turn:
                raise self.error(f"{key}.degrees", "is missing", "the angle in degrees")
            parsed.append((axis, self.number(f"{key}.degrees", turn["degrees"], "an angle in "
                                             "degrees")))
        try:
            anisotropic_material(C, engineering, tuple(parsed), rho)
        except contact.MaterialError as exc:
            raise self.error(section, str(exc), allowed) from None
        return MaterialSpec(rho=rho, kind="anisotropic", C=C, engineering=engineering,
                            rotation=tuple(parsed))

    def material_factory(self, table: dict, section: str = "material") -> MaterialSpec:
        """``factory = "module:function"`` (and ``arguments = { ... }``, its keyword
        arguments): a user's material, built now to check it and again wherever a case is
        solved (:meth:`MaterialSpec.build`)."""
        allowed = ('"module:function" returning an object with the methods of '
                   "contact.Material: surface_constants(c), rayleigh_speed(), limiting_speed(), "
                   "relative_speed(V), half_space_modes(c)")
        other = [k for k in table if k not in ("factory", "arguments")]
        if other:
            raise self.error(f"{section}.{other[0]}", "given together with material.factory",
                             "either factory (with arguments) or preset, or all of C11, C12, "
                             "C22, C33 (with rho)")
        factory = self.function(f"{section}.factory", table["factory"], allowed)
        arguments = table.get("arguments", {})
        if not isinstance(arguments, dict):
            raise self.error(f"{section}.arguments", f"must be a table, got {_describe(arguments)}",
                             "a table of the factory's keyword arguments, e.g. "
                             "arguments = { G = 80.0, nu = 0.3 }")
        arguments = tuple((k, self.argument(f"{section}.arguments.{k}", v))
                          for k, v in arguments.items())
        spec = MaterialSpec(factory=factory, arguments=arguments, base_dir=self.base_dir)
        try:
            material = spec.build()
        except Exception as exc:               # any failure of user code is a scene error
            raise self.error(f"{section}.factory", f"{factory}(**arguments) raised "
                             f"{type(exc).__name__}: {exc}", allowed) from None
        try:
            contact.rayleigh_speed(material)
        except contact.ContactInputError as exc:   # not a material, or a c_R refused
            raise self.error(f"{section}.factory", f"{factory}(**arguments) returned "
                             f"{type(material).__name__}: {exc}", allowed) from None
        return spec

    def punch_material(self, data: dict):
        """``[punch_material]``: an elastic punch's material, the keys of ``[material]``
        (:func:`contact.solve`'s ``punch_material``); None without the section.  A factory's
        material is refused: the punch is seen from below (its material turned half a turn
        about X, :func:`contact.elastic_punch.punch_constants`)."""
        if "punch_material" not in data:
            return None
        table = self.table(data, "punch_material")
        if "factory" in table:
            raise self.error("punch_material.factory", "is not available for the punch (it is "
                             "seen from below: its material turned half a turn about X)",
                             "the keys of [material]: C11, C12, C22, C33 or preset, or "
                             'kind = "anisotropic" with C or engineering (and rotation)')
        return self.material(table, "punch_material")

    def argument(self, key, value):
        """A factory argument: a number, string or boolean, or a list of them (a tuple)."""
        if isinstance(value, list):
            return tuple(self.argument(f"{key}[{k}]", v) for k, v in enumerate(value))
        if isinstance(value, (bool, int, float, str)):
            return value
        raise self.error(key, f"must be a number, string or boolean, or a list of them, got "
                         f"{_describe(value)}", "numbers, strings, booleans and lists of them "
                         "(the factory's keyword arguments)")

    def punch(self, table: dict) -> dict:
        kinds = " | ".join(KINDS)
        if "kind" not in table:
            raise self.error("punch.kind", "is missing", kinds)
        name = table["kind"]
        if not isinstance(name, str) or name not in KINDS:
            close = difflib.get_close_matches(str(name), KINDS, n=1)
            guess = f"; did you mean {close[0]!r}?" if close else ""
            raise self.error("punch.kind", f"unknown kind {name!r}{guess}", kinds)
        kind = KINDS[name]
        self.check_keys(table, ("kind",) + kind.keys, "punch", hint=f" for a {name} punch")
        out = {"kind": name}
        if kind.form == "profile":
            out.update(self.profile(table))
            return out
        for key in kind.dimensions:
            if key not in table:
                raise self.error(f"punch.{key}", f"is missing (a {name} punch needs it)",
                                 "a positive number, or a list of them (a sweep)")
            out[key] = self.values(f"punch.{key}", table[key], self.positive)
        return out

    def positive(self, key, value) -> float:
        v = self.number(key, value, "a positive number, or a list of them (a sweep)")
        if v <= 0:
            raise self.error(key, f"must be > 0, got {v!r}",
                             "a positive number, or a list of them (a sweep)")
        return v

    def profile(self, table: dict) -> dict:
        shape = [k for k in PROFILE_SHAPE_KEYS if k in table]
        allowed = ('slope = [a0, a1, ...] (dv/dX coefficients, low to high) or '
                   '"module:function"; height = "module:function" (alone or with slope); '
                   '[[punch.pieces]] tables; or data = "face.csv" (samples X, h)')
        if not shape:
            raise self.error("punch.slope", "a profile punch needs exactly one of slope, height, "
                             "pieces and data (slope and height may go together)", allowed)
        alone = [k for k in shape if k in ("pieces", "data")]
        if alone and len(shape) > 1:
            other = next(k for k in shape if k != alone[0])
            raise self.error(f"punch.{other}", f"given together with punch.{alone[0]}: a profile "
                             "punch needs exactly one of slope, height, pieces and data (slope "
                             "and height may go together)", allowed)
        if "data" in table:
            return self.tabulated(table)
        out = {}
        if "slope" in table:
            out["slope"] = self.profile_slope(table["slope"])
        if "height" in table:
            out["height"] = self.function("punch.height", table["height"],
                                          '"module:function", a vectorised v(X)')
        if "pieces" in table:
            out["pieces"] = self.pieces(table["pieces"])
        if "interpolant" in table:
            raise self.error("punch.interpolant", "applies only to a tabulated face (punch.data)",
                             'data = "face.csv" with interpolant = ' +
                             " | ".join(f'"{i}"' for i in INTERPOLANTS))
        breaks = table.get("breaks", [])
        if not isinstance(breaks, list):
            raise self.error("punch.breaks", f"must be a list of numbers, got {_describe(breaks)}",
                             "a list of X values, e.g. [-1.0, 1.0]")
        out["breaks"] = tuple(self.number(f"punch.breaks[{k}]", b, "a number (an X value)")
                              for k, b in enumerate(breaks))
        out["corners"] = self.corners(table.get("corners", [FREE, FREE]))
        if "face" in table:
            out["face"] = self.face(table["face"])
        return out

    def tabulated(self, table: dict) -> dict:
        """A face from samples: ``data`` (the file), ``interpolant`` and ``face``."""
        for key, why in (("breaks", "the interpolant's knots are its breaks"),
                         ("corners", "its edges are punch.face (default: the samples' extent)")):
            if key in table:
                raise self.error(f"punch.{key}", f"does not apply to a tabulated face "
                                 f"(punch.data): {why}",
                                 "data, interpolant and face for a tabulated face")
        interpolant = table.get("interpolant", INTERPOLANTS[0])
        if interpolant not in INTERPOLANTS:
            raise self.error("punch.interpolant", f"unknown interpolant {interpolant!r}",
                             " | ".join(f'"{i}"' for i in INTERPOLANTS))
        samples = self.samples(table["data"], interpolant)
        lo, hi = samples.X[0], samples.X[-1]
        face = (lo, hi)
        if "face" in table:
            face = self.face(table["face"])
            if face[0] < lo or face[1] > hi:
                raise self.error("punch.face", f"[{face[0]!r}, {face[1]!r}] reaches beyond the "
                                 f"samples of {samples.path}, which cover [{lo!r}, {hi!r}]",
                                 "a face inside the samples' extent")
        return {"data": samples, "interpolant": interpolant, "face": face}

    def samples(self, value, interpolant) -> Samples:
        """Read and check the samples of punch.data (two columns X, h)."""
        allowed = ('a file of two columns X, h (comma or whitespace separated, an optional '
                   f'header line, # comments), at least {contact.ProfilePunch.MIN_SAMPLES} rows, X increasing; '
                   "relative to the scene file's directory")
        if not isinstance(value, str) or not value:
            raise self.error("punch.data", f"must be a file name, got {_describe(value)}",
                             allowed)
        path = Path(value).expanduser()
        if not path.is_absolute():
            path = Path(self.base_dir or ".") / path
        try:
            text = path.read_text(encoding="utf-8")
        except FileNotFoundError:
            raise self.error("punch.data", f"no such file {str(path)!r}", allowed) from None
        except IsADirectoryError:
            raise self.error("punch.data", f"{str(path)!r} is a directory, not a file",
                             allowed) from None
        except (OSError, UnicodeDecodeError) as exc:
            raise self.error("punch.data", f"cannot read {str(path)!r}: {exc}", allowed) from None
        try:
            X, h = read_samples(text)
        except ValueError as exc:
            raise self.error("punch.data", f"{path}: {exc}", allowed) from None
        try:
            contact.ProfilePunch.from_samples(X, h, kind=interpolant)
        except contact.SampleError as exc:
            raise self.error("punch.data", f"{path}: {exc}", allowed) from None
        return Samples(source=value, path=str(path), X=tuple(X), h=tuple(h))

    def face(self, value) -> tuple:
        allowed = "[X_min, X_max], two numbers with X_min < X_max: the extent of the face"
        if not isinstance(value, list) or len(value) != 2:
            raise self.error("punch.face", f"must be a list of two numbers, got "
                             f"{_describe(value)}", allowed)
        lo, hi = (self.number(f"punch.face ({side})", v, allowed)
                  for side, v in zip(("left", "right"), value))
        if not lo < hi:
            raise self.error("punch.face", f"X_min = {lo!r} is not below X_max = {hi!r}", allowed)
        return lo, hi

    def function(self, key, value, what) -> str:
        """A "module:function" string that imports (checked now, imported again per case)."""
        allowed = f"{what} (the scene's directory is searched first)"
        if not isinstance(value, str):
            raise self.error(key, f"must be a string 'module:function', got {_describe(value)}",
                             allowed)
        module, sep, name = value.partition(":")
        if not sep or not module or not name:
            raise self.error(key, f"{value!r} is not of the form 'module:function'", allowed)
        try:
            import_callable(value, self.base_dir)
        except Exception as exc:               # any failure of user code is a scene error
            raise self.error(key, f"cannot import {value!r}: {type(exc).__name__}: {exc}",
                             "an importable module (the scene's directory is searched first) "
                             "and a function in it") from None
        return value

    def profile_slope(self, value):
        allowed = 'a list of polynomial coefficients of dv/dX, low to high, or "module:function"'
        if isinstance(value, str):
            return self.function("punch.slope", value, '"module:function", a vectorised dv/dX')
        if not isinstance(value, list) or not value:
            raise self.error("punch.slope", f"must be a non-empty list or a string, got "
                             f"{_describe(value)}", allowed)
        return tuple(self.number(f"punch.slope[{k}]", c, allowed) for k, c in enumerate(value))

    def pieces(self, value) -> tuple:
        allowed = "[[punch.pieces]] tables with from, to, coefficients, in increasing X"
        if not isinstance(value, list) or not value or not all(isinstance(p, dict) for p in value):
            raise self.error("punch.pieces", f"must be an array of tables, got {_describe(value)}",
                             allowed)
        pieces = []
        last = len(value) - 1
        for k, p in enumerate(value):
            key = f"punch.pieces[{k}]"
            self.check_keys(p, PIECE_KEYS, key)
            start = -math.inf if (k == 0 and "from" not in p) else None
            stop = math.inf if (k == last and "to" not in p) else None
            for name, bound in (("from", start), ("to", stop)):
                if bound is None and name not in p:
                    raise self.error(f"{key}.{name}", "is missing (only the first piece may "
                                     "omit from, only the last may omit to)", allowed)
            start = self.number(f"{key}.from", p["from"]) if start is None else start
            stop = self.number(f"{key}.to", p["to"]) if stop is None else stop
            if not start < stop:
                raise self.error(key, f"from = {start!r} is not below to = {stop!r}", allowed)
            if pieces and start != pieces[-1].stop:
                raise self.error(f"{key}.from", f"= {start!r} does not continue the previous "
                                 f"piece, which ends at to = {pieces[-1].stop!r}",
                                 "pieces that join: each from equal to the previous to")
            coefficients = p.get("coefficients")
            if not isinstance(coefficients, list) or not coefficients:
                raise self.error(f"{key}.coefficients", f"must be a non-empty list of numbers, "
                                 f"got {_describe(coefficients)}",
                                 "dv/dX coefficients, low to high")
            pieces.append(Piece(start, stop, tuple(
                self.number(f"{key}.coefficients[{j}]", c) for j, c in enumerate(coefficients))))
        return tuple(pieces)

    def corners(self, value) -> tuple:
        allowed = f'[left, right], each the X of a sharp corner or "{FREE}"'
        if not isinstance(value, list) or len(value) != 2:
            raise self.error("punch.corners", f"must be a list of two entries, got "
                             f"{_describe(value)}", allowed)
        out = []
        for side, c in zip(("left", "right"), value):
            if c == FREE:
                out.append(None)
            elif isinstance(c, str):
                raise self.error(f"punch.corners ({side})", f"unknown word {c!r}", allowed)
            else:
                out.append(self.number(f"punch.corners ({side})", c, allowed))
        if None not in out and not out[0] < out[1]:
            raise self.error("punch.corners", f"left = {out[0]!r} is not below right = "
                             f"{out[1]!r}", allowed)
        return tuple(out)

    def motion(self, table: dict, material: MaterialSpec) -> dict:
        self.check_keys(table, MOTION_KEYS, "motion")
        if "load" not in table:
            raise self.error("motion.load", "is missing",
                             "a positive number (force per unit length), or a list of them")
        out = {"load": self.values("motion.load", table["load"], self.positive)}
        if "velocity" in table:
            if "speed" in table:
                raise self.error("motion.velocity", "given together with motion.speed",
                                 "either speed (relative, c = V/sqrt(C33/rho)) or velocity V")
            if material.factory is None and material.rho is None:
                raise self.error("motion.velocity", "needs material.rho to convert V into the "
                                 "relative speed c = V/sqrt(C33/rho)",
                                 "material.rho > 0, or motion.speed instead")
            out["velocity"] = self.values("motion.velocity", table["velocity"], self.nonnegative)
        else:
            out["speed"] = self.values("motion.speed", table.get("speed", 0.0), self.nonnegative)
        out["friction"] = self.values("motion.friction", table.get("friction", 0.0),
                                      self.nonnegative)
        out["direction"] = self.values("motion.direction", table.get("direction", -1),
                                       self.direction)
        self.slip(table, out)
        # keep the scene's order of keys (it orders the sweep), defaults after
        order = [k for k in table if k in out] + [k for k in out if k not in table]
        return {k: out[k] for k in order}

    def slip(self, table: dict, out: dict) -> None:
        """``tangential_load`` (Q: partial slip, or steady rolling with ``rolling = true``),
        ``creepage`` (steady rolling only) and ``rolling`` into ``out``; the constraints of
        :func:`contact.solve` (abs(Q) < mu P, a pair that decouples, ...) are each case's,
        checked when it is solved."""
        rolling = table.get("rolling", False)
        if not isinstance(rolling, bool):
            raise self.error("motion.rolling", f"must be true or false, got "
                             f"{_describe(rolling)}", "true (steady rolling toward direction, "
                             "with tangential_load or creepage) or false (the default)")
        for key, allowed in (("tangential_load", "a number (Q, the tangential load on the "
                              "half-space, abs(Q) < friction * load), or a list of them (a "
                              "sweep)"),
                             ("creepage", "a number (the creepage of steady rolling), or a "
                              "list of them (a sweep)")):
            if key in table:
                out[key] = self.values(f"motion.{key}", table[key],
                                       lambda k, v, a=allowed: self.number(k, v, a))
        if "creepage" in table and not rolling:
            raise self.error("motion.creepage", "is the creepage of steady rolling, and "
                             "motion.rolling is not true",
                             "rolling = true with creepage, or tangential_load alone (a "
                             "static contact in partial slip)")
        if rolling:
            if "tangential_load" in table and "creepage" in table:
                raise self.error("motion.creepage", "given together with "
                                 "motion.tangential_load (either follows from the other)",
                                 "one of tangential_load and creepage with rolling = true")
            if "tangential_load" not in table and "creepage" not in table:
                raise self.error("motion.rolling", "needs motion.tangential_load or "
                                 "motion.creepage",
                                 "rolling = true with one of tangential_load and creepage")
        if "rolling" in table:
            out["rolling"] = rolling

    def nonnegative(self, key, value) -> float:
        allowed = "a number >= 0, or a list of them (a sweep)"
        v = self.number(key, value, allowed)
        if v < 0:
            raise self.error(key, f"{v!r} is negative", allowed)
        return v

    def direction(self, key, value) -> int:
        if isinstance(value, bool) or value not in (-1, 1):
            raise self.error(key, f"must be -1 or +1, got {_describe(value)}",
                             "-1 (punch slides toward -X) or +1 (toward +X), or a list of them")
        return int(value)

    def outputs(self, table: dict):
        self.check_keys(table, OUTPUT_KEYS, "outputs")
        fields = table.get("fields", list(DEFAULT_FIELDS))
        if isinstance(fields, str):
            fields = [fields]
        if not isinstance(fields, list) or not fields:
            raise self.error("outputs.fields", f"must be a non-empty list of field names, got "
                             f"{_describe(fields)}", ", ".join(FIELDS))
        seen = []
        for k, f in enumerate(fields):
            if not isinstance(f, str) or f not in FIELDS:
                close = difflib.get_close_matches(str(f), FIELDS, n=1)
                guess = f"; did you mean {close[0]!r}?" if close else ""
                raise self.error(f"outputs.fields[{k}]", f"unknown field {f!r}{guess}",
                                 ", ".join(FIELDS))
            if f not in seen:
                seen.append(f)
        x = None
        if "x" in table:
            x = self.x_grid(table["x"])
        grid = None
        if "grid" in table:
            grid = self.grid(table["grid"])
            if "subsurface" not in seen:
                raise self.error("outputs.grid", 'is the map of the "subsurface" field, which '
                                 "outputs.fields does not ask for",
                                 'add "subsurface" to outputs.fields, or remove outputs.grid')
        figures = table.get("figures", True)
        if not isinstance(figures, bool):
            raise self.error("outputs.figures", f"must be true or false, got "
                             f"{_describe(figures)}",
                             "true (write the PNG figures, the default) or false")
        return tuple(seen), x, grid, figures

    def x_grid(self, value, key="outputs.x", max_num=1_000_000, name="X") -> XGrid:
        allowed = (f"{{ start = {name}0, stop = {name}1, num = N }} with {name}0 < {name}1 and "
                   f"2 <= N <= {max_num}")
        if name == "Y":
            allowed += " and Y1 <= 0 (the half-space is Y <= 0; depth = -Y)"
        if not isinstance(value, dict):
            raise self.error(key, f"must be a table, got {_describe(value)}", allowed)
        self.check_keys(value, X_KEYS, key)
        for k in X_KEYS:
            if k not in value:
                raise self.error(f"{key}.{k}", "is missing", allowed)
        start = self.number(f"{key}.start", value["start"], allowed)
        stop = self.number(f"{key}.stop", value["stop"], allowed)
        num = value["num"]
        if isinstance(num, bool) or not isinstance(num, int) or not 2 <= num <= max_num:
            raise self.error(f"{key}.num", f"must be an integer in [2, {max_num}], got "
                             f"{_describe(num)}", allowed)
        if not start < stop:
            raise self.error(key, f"start = {start!r} is not below stop = {stop!r}", allowed)
        return XGrid(start, stop, num)

    def grid(self, value) -> SubsurfaceGrid:
        """``[outputs] grid = { x = {start, stop, num}, y = {start, stop, num} }``: where the
        "subsurface" field is mapped; an axis left out keeps its default (scaled to the
        contact)."""
        allowed = ("{ x = { start = X0, stop = X1, num = NX }, y = { start = Y0, stop = Y1, "
                   "num = NY } }, either axis optional (default: scaled to the contact), "
                   "Y1 <= 0")
        if not isinstance(value, dict):
            raise self.error("outputs.grid", f"must be a table, got {_describe(value)}", allowed)
        self.check_keys(value, GRID_KEYS, "outputs.grid")
        if not value:
            raise self.error("outputs.grid", "is empty", allowed)
        x = y = None
        if "x" in value:
            x = self.x_grid(value["x"], "outputs.grid.x", 10_000)
        if "y" in value:
            y = self.x_grid(value["y"], "outputs.grid.y", 10_000, name="Y")
            if y.stop > 0:
                raise self.error("outputs.grid.y.stop", f"{y.stop!r} is above the surface Y = 0",
                                 "Y1 <= 0 (the half-space is Y <= 0; depth = -Y)")
        nx = x.num if x is not None else SUBSURFACE_POINTS[0]
        ny = y.num if y is not None else SUBSURFACE_POINTS[1]
        if nx * ny > SUBSURFACE_MAX_POINTS:
            raise self.error("outputs.grid", f"{nx} x {ny} = {nx * ny} points is too many",
                             f"nx * ny <= {SUBSURFACE_MAX_POINTS}")
        return SubsurfaceGrid(x, y)

    def numerics(self, table: dict, kind: str) -> Numerics:
        self.check_keys(table, NUMERICS_KEYS, "numerics")
        method = table.get("method", "numeric")
        if method not in METHODS:
            raise self.error("numerics.method", f"unknown method {method!r}",
                             " | ".join(repr(m) for m in METHODS))
        if method == "closed_form" and KINDS[kind].closed_form is None:
            have = ", ".join(closed_form_kinds())
            raise self.error("numerics.method", f"closed_form exists only for the {have} "
                             f"punches, not for a {kind} punch",
                             f'"numeric" for a {kind} punch')
        if "n" in table and "tol" in table:
            raise self.error("numerics.n", "given together with numerics.tol",
                             "either n (fixed) or tol (n chosen adaptively)")
        n = table.get("n")
        if n is not None and (isinstance(n, bool) or not isinstance(n, int)
                              or not 2 <= n <= N_MAX):
            raise self.error("numerics.n", f"must be an integer in [2, {N_MAX}], got "
                             f"{_describe(n)}", f"an integer in [2, {N_MAX}] (Jacobi "
                             "coefficients per zone)")
        tol = table.get("tol", 1e-12)
        tol = self.number("numerics.tol", tol, "a number in (0, 1)")
        if not 0 < tol < 1:
            raise self.error("numerics.tol", f"must be in (0, 1), got {tol!r}",
                             "a number in (0, 1)")
        return Numerics(method, n, tol)

    # ---- checks that need the physics (cheap: no contact problem is solved) ----
    def check_cases(self, scene: Scene):
        """Every speed of the sweep below the Rayleigh speed, and every punch of the sweep
        buildable: each distinct value once (the punches: the product of the punch section's
        swept keys), not once per case.  The material has the characteristic roots if
        ``"roots"`` is asked."""
        material = scene.material.build()
        c_R = contact.rayleigh_speed(material)
        if "roots" in scene.fields and not callable(getattr(material, "characteristic_roots",
                                                            None)):
            k = scene.fields.index("roots")
            raise self.error(f"outputs.fields[{k}]", f"the roots are the characteristic roots "
                             f"eta of an orthotropic material (Zhou et al. 2014, eq. (3.1)); "
                             f"the material ({scene.material.describe()}) has no "
                             f"characteristic_roots(c)",
                             "the other fields, or a material with characteristic_roots(c) "
                             "(contact.Orthotropic)")
        by_velocity = "velocity" in scene.motion
        name = "velocity" if by_velocity else "speed"
        key, given = f"motion.{name}", scene.motion[name]
        for v in dict.fromkeys(given if isinstance(given, tuple) else (given,)):
            c = self.relative_speed(material, key, v) if by_velocity else v
            if not c < c_R:
                shown = f"velocity = {v!r} (relative speed c = {c!r})" if by_velocity else f"{c!r}"
                raise self.error(key, f"{shown} is not below the Rayleigh speed of this material, "
                                 f"c_R = {c_R!r}", f"0 <= speed < c_R = {c_R:.10g}")
        for spec in scene.punch_specs():
            self.check_punch(spec)

    def relative_speed(self, material, key, V) -> float:
        """The material's relative speed of the velocity V, or a SceneError at ``key``."""
        try:
            return contact.relative_speed(material, V)
        except contact.ContactInputError as exc:
            raise self.error(key, f"velocity = {V!r}: {exc}",
                             "a velocity the material converts into a relative speed "
                             "(relative_speed(V); material.rho for C11..C33), or motion.speed "
                             "instead") from None

    def check_punch(self, spec: PunchSpec):
        try:
            punch = spec.build()
        except contact.ContactInputError as exc:
            if spec.dimension_key:
                key, allowed = f"punch.{spec.dimension_key}", "a positive finite number"
            else:
                key, allowed = "punch", ('corners at the edges of the face (or "free"), face = '
                                         "[X_min, X_max] with X_min < X_max, finite breaks")
            raise self.error(key, str(exc), allowed) from None
        if spec.kind != "profile" or spec.get("data") is not None:
            return
        X = np.linspace(*_probe_range(punch), 7)
        checks = []
        if spec.get("height") is not None:
            checks.append(("punch.height", punch.height, "v(X)"))
        slope_key = ("punch.pieces" if spec.get("pieces") else
                     "punch.slope" if spec.get("slope") is not None else "punch.height")
        checks.append((slope_key, punch.slope, "dv/dX"))
        for key, fn, what in checks:
            try:
                fn(X)
            except Exception as exc:               # user code: any failure is a scene error
                raise self.error(key, f"{exc} (probed at X in [{X[0]:g}, {X[-1]:g}])",
                                 f"a vectorised function returning finite real {what} of the "
                                 "same shape as X") from None


def _probe_range(punch) -> tuple:
    """Where a profile's functions are tried: its face, or around its breaks and finite edges
    (X in [-1, 1] when it has neither)."""
    lo, hi = punch.extent
    if math.isfinite(lo) and math.isfinite(hi):
        return lo, hi
    xs = [x for x in (lo, hi) if math.isfinite(x)] + list(punch.breaks)
    if not xs:
        return -1.0, 1.0
    a, b = min(xs), max(xs)
    pad = max(1.0, b - a)
    return (lo if math.isfinite(lo) else a - pad), (hi if math.isfinite(hi) else b + pad)


def _default_title(punch: dict) -> str:
    name = punch["kind"]
    dims = KINDS[name].dimensions
    if name == "profile" and "data" in punch:
        return f"profile punch, data = {punch['data'].source}"
    if not dims or isinstance(punch[dims[0]], tuple):
        return f"{name} punch"
    return f"{name} punch, {dims[0]} = {punch[dims[0]]:g}"


def read_samples(text: str) -> tuple:
    """The two columns X, h of a samples file.

    Blank lines and lines starting with ``#`` are skipped; the first other line is a header
    when it is not two numbers; columns are separated by a comma or by whitespace.

    Returns
    -------
    (list of float, list of float)

    Raises
    ------
    ValueError
        A row without exactly two columns, or a value that is not a number (naming the line).
    """
    X, h = [], []
    first = True
    for number, line in enumerate(text.splitlines(), start=1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        cells = [c.strip() for c in (line.split(",") if "," in line else line.split())]
        numbers = [_is_number(c) for c in cells]
        header, first = first and not any(numbers), False
        if header:
            continue
        if not all(numbers):
            bad = cells[numbers.index(False)]
            raise ValueError(f"line {number}: {bad!r} is not a number")
        values = [float(c) for c in cells]
        if len(values) != 2:
            raise ValueError(f"line {number}: {len(values)} columns, expected 2 (X, h)")
        X.append(values[0])
        h.append(values[1])
    return X, h


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _describe(value) -> str:
    kinds = {bool: "boolean", int: "integer", float: "float", str: "string", list: "list",
             dict: "table"}
    name = kinds.get(type(value), type(value).__name__)
    if value is None:
        return "nothing"
    if isinstance(value, (dict, list)):
        return f"a {name}"
    return f"{name} {value!r}"
