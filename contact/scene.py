"""Scenes: a contact problem (or a sweep of them) described in a TOML file, run, and written out.

A scene names a material, a punch, the motion, what to compute and, optionally, numerics::

    title = "cylindrical punch"           # optional; used in figures and the table

    [material]            # Zhou et al. 2014, eq. (2.2); any consistent stress unit
    C11 = 159.7885        # or: preset = "zhou2014" (the paper's material, GPa)
    C12 = 5.2609
    C22 = 15.4732
    C33 = 5.52
    # rho = 1.6e-6        # only needed when [motion] gives velocity instead of speed

    [punch]
    kind = "cylindrical"  # flat | triangular | parabolic | cylindrical | profile
    radius = 100.0        # flat: half_width; triangular: slope (m0); parabolic, cylindrical: radius

    [motion]
    load = 0.01           # P > 0, force per unit length (stress unit x length unit)
    speed = 0.6           # relative speed c = V / sqrt(C33/rho), 0 <= c < c_R (default 0)
    # velocity = 1.2      # instead of speed: V, converted with material.rho
    friction = 0.3        # mu >= 0 (default 0)
    direction = -1        # -1: slides toward -X (trailing edge on the right), +1: toward +X

    [outputs]
    fields = ["ends", "exponents", "pressure", "sigma_xx", "sif"]
    x = { start = -0.8, stop = 0.8, num = 801 }   # where curves are sampled

    [numerics]            # optional
    method = "numeric"    # or "closed_form" (the four classical punches only)
    n = 64                # fixed number of Jacobi coefficients; or tol = 1e-12 (adaptive n)

**Custom punches** (``kind = "profile"``) give the slope dv/dX of the face in one of three ways:

* ``slope = [a0, a1, a2, ...]``: polynomial coefficients, low to high: dv/dX = a0 + a1 X + ...
* ``slope = "module:function"``: a vectorised Python function of X (the scene file's directory is
  searched first when importing ``module``).
* piecewise polynomials, one ``[[punch.pieces]]`` table each, in increasing X::

      [[punch.pieces]]
      to = -1.0                      # the first piece extends to -inf ("from" may be omitted)
      coefficients = [0.01, 0.01]    # dv/dX = 0.01 + 0.01 X on this piece
      [[punch.pieces]]
      from = -1.0                    # must equal the previous piece's "to"
      to = 1.0
      coefficients = [0.0]
      [[punch.pieces]]
      from = 1.0                     # the last piece extends to +inf ("to" may be omitted)
      coefficients = [-0.01, 0.01]

  The joins are added to ``breaks`` automatically.

plus ``breaks = [X, ...]`` (kinks of the face) and ``corners = [left, right]``: the X of a sharp
corner that bounds the contact on that side, or ``"free"`` for a free end (TOML has no null;
``"free"`` is the default on both sides).

**Sweeps**: any scalar under [motion] or [punch] may be a list of values (for a profile punch
only scalars count: its ``slope``, ``breaks`` and ``corners`` lists are data, not sweeps).  The
scene runs the Cartesian product, the key met first in the file varying slowest.

**Only what is asked is computed**: curves are sampled only for the requested fields
(sigma_XX only with ``"sigma_xx"``), the characteristic roots and surface constants for the
``"roots"``/``"constants"`` fields once per speed, shared by every case at that speed.

**Errors**: every problem with a scene is a :class:`SceneError` (a ``ValueError``) naming the
file, the key and what is allowed, raised by :func:`load_scene` before anything is solved.
"""
from __future__ import annotations

import csv
import difflib
import functools
import importlib
import itertools
import json
import math
import sys
import time
import tomllib
import warnings
from concurrent.futures import Executor, as_completed
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from numpy.polynomial.polynomial import polyval

import contact
import sie

__all__ = ["SceneError", "Scene", "Case", "CaseResult", "SceneResult", "MaterialSpec",
           "PunchSpec", "XGrid", "Numerics", "load_scene", "parse_scene_text", "default_scene",
           "run_scene", "run_case", "write_outputs", "format_table", "DEFAULT_SCENE_TOML",
           "FIELDS", "CURVE_FIELDS"]

# --------------------------------------------------------------------------
# the vocabulary of a scene
# --------------------------------------------------------------------------
SECTIONS = ("title", "material", "punch", "motion", "outputs", "numerics")
MATERIAL_KEYS = ("preset", "C11", "C12", "C22", "C33", "rho")
PRESETS = {"zhou2014": contact.zhou2014}
PUNCH_DIMENSIONS = {"flat": ("half_width",), "triangular": ("slope",), "parabolic": ("radius",),
                    "cylindrical": ("radius",), "profile": ()}
PROFILE_KEYS = ("slope", "pieces", "breaks", "corners")
PIECE_KEYS = ("from", "to", "coefficients")
MOTION_KEYS = ("load", "speed", "velocity", "friction", "direction")
OUTPUT_KEYS = ("fields", "x")
X_KEYS = ("start", "stop", "num")
NUMERICS_KEYS = ("method", "n", "tol")
METHODS = ("numeric", "closed_form")
FREE = "free"

#: Every field a scene may ask for, in the order they are documented.
FIELDS = ("ends", "exponents", "sif", "pressure", "shear", "sigma_xx", "roots", "constants")
#: Fields sampled as curves on the x grid.
CURVE_FIELDS = ("pressure", "shear", "sigma_xx")
#: Fields that depend on (material, speed) only.
SPEED_FIELDS = ("roots", "constants")
DEFAULT_FIELDS = ("ends", "exponents", "pressure")
AUTO_X_POINTS = 401
AUTO_X_MARGIN = 0.5            # automatic x: the contact widened by this fraction of its length

UNITS = {
    "statement": "consistent units: every stress (material C11..C33, pressure, shear, sigma_xx) "
                 "in one stress unit S, every length (X, ends, half_width, radius, breaks) in one "
                 "length unit L, as given in the scene",
    "load": "S*L (force per unit length of the punch)",
    "pressure, shear, sigma_xx": "S",
    "ends, x, half_width, radius": "L",
    "slope (triangular), speed, friction, exponents": "dimensionless",
    "sif": "S*L^(-e), e the exponent at that end (definitions: contact.ContactResult.sif)",
    "N11, N12": "1/S",
    "N21, N22, rayleigh_speed, roots": "dimensionless",
    "velocity": "the unit of sqrt(C33/rho)",
    "timing_s": "seconds",
}

DEFAULT_SCENE_TOML = '''\
# The default scene (`contact run` without a scene file; `make run`): the paper's material,
# a cylindrical punch of radius 100 pressed with P = 0.01 and sliding toward -X at c = 0.6 with
# mu = 0.3 (Zhou, Lee & Jang 2014, Sec. 6.5 and Fig. 4).  Units: GPa and mm, so P is in GPa*mm.
title = "default scene: cylindrical punch, c = 0.6, mu = 0.3"

[material]
preset = "zhou2014"          # C11, C12, C22, C33 = 159.7885, 5.2609, 15.4732, 5.52 GPa

[punch]
kind = "cylindrical"
radius = 100.0

[motion]
load = 0.01
speed = 0.6
friction = 0.3
direction = -1

[outputs]
fields = ["ends", "exponents", "pressure", "sigma_xx", "sif"]
x = { start = -0.8, stop = 0.8, num = 801 }
'''


# --------------------------------------------------------------------------
# errors
# --------------------------------------------------------------------------
class SceneError(ValueError):
    """A scene file that cannot be run: names the file, the key and what is allowed.

    Attributes
    ----------
    file : str
        The scene file (or ``"<embedded default>"``, ``"<string>"``).
    key : str or None
        Dotted key, e.g. ``"motion.speed"``; None for a problem with the whole file.
    allowed : str or None
        What would have been accepted.
    """

    def __init__(self, file, key, problem, allowed=None):
        self.file, self.key, self.problem, self.allowed = str(file), key, problem, allowed
        where = f"{self.file}: {key}: " if key else f"{self.file}: "
        tail = f" (allowed: {allowed})" if allowed else ""
        super().__init__(f"{where}{problem}{tail}")

    def __reduce__(self):                      # picklable across process pools
        return (type(self), (self.file, self.key, self.problem, self.allowed))


class CaseError(RuntimeError):
    """A case of a valid scene failed while it was solved (e.g. the profile loses contact).

    The message names the file, the case and its inputs, and the library's reason."""


# --------------------------------------------------------------------------
# parsed scenes
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class MaterialSpec:
    """Stiffnesses of eq. (2.2) (and the density, if given), after a preset is expanded."""
    C11: float
    C12: float
    C22: float
    C33: float
    rho: float | None = None
    preset: str | None = None

    def build(self) -> contact.Orthotropic:
        return contact.Orthotropic(self.C11, self.C12, self.C22, self.C33, rho=self.rho)


@dataclass(frozen=True)
class Piece:
    """One polynomial piece of a piecewise slope: dv/dX = sum c_k X^k on [start, stop)."""
    start: float              # -inf for the first piece
    stop: float               # +inf for the last piece
    coefficients: tuple


@dataclass(frozen=True)
class PolynomialSlope:
    """dv/dX = sum c_k X^k (coefficients low to high); picklable."""
    coefficients: tuple

    def __call__(self, X):
        X = np.asarray(X, dtype=float)
        return polyval(X, self.coefficients) + np.zeros_like(X)


@dataclass(frozen=True)
class PiecewiseSlope:
    """dv/dX given by polynomial pieces joined at ``joins`` (the first and last pieces extend
    to -inf and +inf); picklable."""
    joins: tuple
    pieces: tuple             # coefficient tuples, one per piece

    def __call__(self, X):
        X = np.asarray(X, dtype=float)
        which = np.searchsorted(np.asarray(self.joins, dtype=float), X, side="right")
        out = np.zeros_like(X)
        for k, coefficients in enumerate(self.pieces):
            here = which == k
            out[here] = polyval(X[here], coefficients)
        return out


@dataclass(frozen=True)
class PunchSpec:
    """One punch (a single sweep point): plain data, rebuilt into a :class:`contact.Punch`
    wherever it is solved (so a case can travel to another process or a Dask worker).

    ``dimension`` is the value of the kind's dimension key (half_width, slope or radius);
    for a profile, exactly one of ``slope`` (coefficients or "module:function") and
    ``pieces`` is set.
    """
    kind: str
    dimension: float | None = None
    slope: tuple | str | None = None
    pieces: tuple = ()
    breaks: tuple = ()
    corners: tuple = (None, None)
    base_dir: str | None = None

    @property
    def dimension_key(self):
        keys = PUNCH_DIMENSIONS[self.kind]
        return keys[0] if keys else None

    def slope_function(self):
        """The profile's dv/dX as a callable (imports "module:function" slopes)."""
        if self.pieces:
            return PiecewiseSlope(tuple(p.start for p in self.pieces[1:]),
                                  tuple(p.coefficients for p in self.pieces))
        if isinstance(self.slope, str):
            return import_callable(self.slope, self.base_dir)
        return PolynomialSlope(tuple(self.slope))

    def build(self) -> contact.Punch:
        if self.kind == "flat":
            return contact.FlatPunch(half_width=self.dimension)
        if self.kind == "triangular":
            return contact.TriangularPunch(slope=self.dimension)
        if self.kind == "parabolic":
            return contact.ParabolicPunch(radius=self.dimension)
        if self.kind == "cylindrical":
            return contact.CylindricalPunch(radius=self.dimension)
        joins = tuple(p.start for p in self.pieces[1:])
        breaks = tuple(sorted(set(self.breaks) | set(joins)))
        return contact.ProfilePunch(self.slope_function(), breaks=breaks, corners=self.corners)


@dataclass(frozen=True)
class XGrid:
    """Where curves are sampled: numpy.linspace(start, stop, num)."""
    start: float
    stop: float
    num: int

    def points(self) -> np.ndarray:
        return np.linspace(self.start, self.stop, self.num)


@dataclass(frozen=True)
class Numerics:
    """Arguments of :func:`contact.solve`: method, n (None: adaptive) and tol."""
    method: str = "numeric"
    n: int | None = None
    tol: float = 1e-12


@dataclass(frozen=True)
class Case:
    """One point of a scene's sweep: everything needed to solve it and sample what is asked.

    ``inputs`` holds the scalar values of this point (speed, friction, direction, load, the
    punch dimension, and the velocity if the scene gave one); ``label`` names the swept values.
    """
    index: int
    label: str
    inputs: dict
    material: MaterialSpec
    punch: PunchSpec
    fields: tuple
    x: XGrid | None
    numerics: Numerics

    @property
    def speed(self) -> float:
        return self.inputs["speed"]


@dataclass(frozen=True)
class Scene:
    """A parsed and validated scene.

    ``punch`` and ``motion`` hold the values after defaults, lists where the scene sweeps;
    ``sweep`` lists the swept (section, key) pairs in scene order.
    """
    source: str
    title: str
    material: MaterialSpec
    punch: dict
    motion: dict
    fields: tuple
    x: XGrid | None
    numerics: Numerics
    sweep: tuple
    base_dir: str | None = None

    def cases(self) -> list[Case]:
        """The Cartesian product of the swept values, the first swept key varying slowest."""
        swept = [self._section(sec)[key] for sec, key in self.sweep]
        out = []
        for index, values in enumerate(itertools.product(*swept)):
            point = dict(zip(self.sweep, values))
            punch = {k: point.get(("punch", k), v) for k, v in self.punch.items()}
            motion = {k: point.get(("motion", k), v) for k, v in self.motion.items()}
            label = ", ".join(f"{key} = {_fmt(v)}" for (_, key), v in point.items())
            out.append(Case(index=index, label=label or self.title,
                            inputs=_case_inputs(self.material, punch, motion),
                            material=self.material, punch=_punch_spec(punch, self.base_dir),
                            fields=self.fields, x=self.x, numerics=self.numerics))
        return out

    def _section(self, name):
        return self.punch if name == "punch" else self.motion

    def echo(self) -> dict:
        """The scene after defaults, as plain JSON-ready data."""
        material = {"preset": self.material.preset} if self.material.preset else {}
        material.update(C11=self.material.C11, C12=self.material.C12, C22=self.material.C22,
                        C33=self.material.C33, rho=self.material.rho)
        punch = {}
        for k, v in self.punch.items():
            if k == "pieces":
                v = [{"from": _json_float(p.start), "to": _json_float(p.stop),
                      "coefficients": list(p.coefficients)} for p in v]
            elif k == "corners":
                v = [FREE if c is None else c for c in v]
            elif isinstance(v, tuple):
                v = list(v)
            punch[k] = v
        motion = {k: list(v) if isinstance(v, tuple) else v for k, v in self.motion.items()}
        x = None if self.x is None else {"start": self.x.start, "stop": self.x.stop,
                                          "num": self.x.num}
        return {"title": self.title, "material": material, "punch": punch, "motion": motion,
                "outputs": {"fields": list(self.fields), "x": x},
                "numerics": {"method": self.numerics.method, "n": self.numerics.n,
                             "tol": self.numerics.tol}}


def _json_float(v):
    return None if v is None or not math.isfinite(v) else v


def _fmt(v) -> str:
    return f"{v:+d}" if isinstance(v, int) and not isinstance(v, bool) else f"{v:g}"


def _case_inputs(material: MaterialSpec, punch: dict, motion: dict) -> dict:
    inputs = {}
    if "velocity" in motion:
        inputs["speed"] = material.build().relative_speed(motion["velocity"])
    else:
        inputs["speed"] = motion["speed"]
    inputs["friction"] = motion["friction"]
    inputs["direction"] = motion["direction"]
    inputs["load"] = motion["load"]
    for key in PUNCH_DIMENSIONS[punch["kind"]]:
        inputs[key] = punch[key]
    if "velocity" in motion:
        inputs["velocity"] = motion["velocity"]
    return inputs


def _punch_spec(punch: dict, base_dir) -> PunchSpec:
    kind = punch["kind"]
    if kind != "profile":
        return PunchSpec(kind=kind, dimension=punch[PUNCH_DIMENSIONS[kind][0]])
    slope = punch.get("slope")
    return PunchSpec(kind=kind, slope=slope, pieces=tuple(punch.get("pieces", ())),
                     breaks=tuple(punch.get("breaks", ())),
                     corners=tuple(punch.get("corners", (None, None))), base_dir=base_dir)


def import_callable(spec: str, base_dir=None):
    """Import "module:function" (the scene's directory searched first); ImportError,
    AttributeError or TypeError with a plain message if it cannot."""
    module_name, _, name = spec.partition(":")
    added = base_dir is not None and base_dir not in sys.path
    if added:
        sys.path.insert(0, base_dir)
    try:
        module = importlib.import_module(module_name)
    finally:
        if added:
            sys.path.remove(base_dir)
    fn = module
    for part in name.split("."):
        fn = getattr(fn, part)
    if not callable(fn):
        raise TypeError(f"{spec} is a {type(fn).__name__}, not a function")
    return fn


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
        punch = self.punch(self.table(data, "punch", required=True))
        motion = self.motion(self.table(data, "motion", required=True), material)
        fields, x = self.outputs(self.table(data, "outputs"))
        numerics = self.numerics(self.table(data, "numerics"), punch["kind"])
        order = [name for name in data if name in ("punch", "motion")]
        sweepable = {"punch": PUNCH_DIMENSIONS[punch["kind"]], "motion": MOTION_KEYS}
        sweep = tuple((sec, key) for sec in order
                      for key, v in (punch if sec == "punch" else motion).items()
                      if isinstance(v, tuple) and key in sweepable[sec])
        if not title:
            title = _default_title(punch)
        scene = Scene(source=self.source, title=title, material=material, punch=punch,
                      motion=motion, fields=fields, x=x, numerics=numerics, sweep=sweep,
                      base_dir=self.base_dir)
        self.check_cases(scene)
        return scene

    def material(self, table: dict) -> MaterialSpec:
        self.check_keys(table, MATERIAL_KEYS, "material")
        rho = None
        if "rho" in table:
            rho = self.number("material.rho", table["rho"], "a density > 0")
            if rho <= 0:
                raise self.error("material.rho", f"must be > 0, got {rho!r}", "a density > 0")
        stiff = [k for k in ("C11", "C12", "C22", "C33") if k in table]
        if "preset" in table:
            preset = table["preset"]
            if stiff:
                raise self.error(f"material.{stiff[0]}", "given together with material.preset",
                                 "either preset or all of C11, C12, C22, C33")
            if preset not in PRESETS:
                close = difflib.get_close_matches(str(preset), PRESETS, n=1)
                guess = f"; did you mean {close[0]!r}?" if close else ""
                raise self.error("material.preset", f"unknown preset {preset!r}{guess}",
                                 ", ".join(repr(p) for p in PRESETS))
            m = PRESETS[preset]()
            return MaterialSpec(m.C11, m.C12, m.C22, m.C33, rho=rho, preset=preset)
        missing = [k for k in ("C11", "C12", "C22", "C33") if k not in table]
        if missing:
            raise self.error(f"material.{missing[0]}", "is missing",
                             'all of C11, C12, C22, C33 (numbers), or preset = "zhou2014"')
        C = [self.number(f"material.{k}", table[k], "a number (stiffness; sweeps are allowed "
                         "only under [motion] and [punch])") for k in ("C11", "C12", "C22", "C33")]
        try:
            contact.Orthotropic(*C, rho=rho)
        except contact.MaterialError as exc:
            raise self.error("material", str(exc)) from None
        return MaterialSpec(*C, rho=rho)

    def punch(self, table: dict) -> dict:
        if "kind" not in table:
            raise self.error("punch.kind", "is missing", " | ".join(PUNCH_DIMENSIONS))
        kind = table["kind"]
        if kind not in PUNCH_DIMENSIONS:
            close = difflib.get_close_matches(str(kind), PUNCH_DIMENSIONS, n=1)
            guess = f"; did you mean {close[0]!r}?" if close else ""
            raise self.error("punch.kind", f"unknown kind {kind!r}{guess}",
                             " | ".join(PUNCH_DIMENSIONS))
        dims = PUNCH_DIMENSIONS[kind]
        allowed = ("kind",) + (PROFILE_KEYS if kind == "profile" else dims)
        self.check_keys(table, allowed, "punch", hint=f" for a {kind} punch")
        out = {"kind": kind}
        if kind != "profile":
            key = dims[0]
            if key not in table:
                raise self.error(f"punch.{key}", f"is missing (a {kind} punch needs it)",
                                 "a positive number, or a list of them (a sweep)")
            out[key] = self.values(f"punch.{key}", table[key], self.positive)
            return out
        out.update(self.profile(table))
        return out

    def positive(self, key, value) -> float:
        v = self.number(key, value, "a positive number, or a list of them (a sweep)")
        if v <= 0:
            raise self.error(key, f"must be > 0, got {v!r}",
                             "a positive number, or a list of them (a sweep)")
        return v

    def profile(self, table: dict) -> dict:
        out = {}
        if ("slope" in table) == ("pieces" in table):
            raise self.error("punch.slope", "a profile punch needs exactly one of slope and "
                             "pieces", 'slope = [a0, a1, ...] (dv/dX coefficients, low to high), '
                             'slope = "module:function", or [[punch.pieces]] tables')
        if "slope" in table:
            out["slope"] = self.profile_slope(table["slope"])
        else:
            out["pieces"] = self.pieces(table["pieces"])
        breaks = table.get("breaks", [])
        if not isinstance(breaks, list):
            raise self.error("punch.breaks", f"must be a list of numbers, got {_describe(breaks)}",
                             "a list of X values, e.g. [-1.0, 1.0]")
        out["breaks"] = tuple(self.number(f"punch.breaks[{k}]", b, "a number (an X value)")
                              for k, b in enumerate(breaks))
        out["corners"] = self.corners(table.get("corners", [FREE, FREE]))
        return out

    def profile_slope(self, value):
        allowed = 'a list of polynomial coefficients of dv/dX, low to high, or "module:function"'
        if isinstance(value, str):
            module, sep, name = value.partition(":")
            if not sep or not module or not name:
                raise self.error("punch.slope", f"{value!r} is not of the form 'module:function'",
                                 allowed)
            try:
                import_callable(value, self.base_dir)
            except Exception as exc:               # any failure of user code is a scene error
                raise self.error("punch.slope", f"cannot import {value!r}: "
                                 f"{type(exc).__name__}: {exc}",
                                 "an importable module (the scene's directory is searched first) "
                                 "and a function in it") from None
            return value
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
            if material.rho is None:
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
        # keep the scene's order of keys (it orders the sweep), defaults after
        order = [k for k in table if k in out] + [k for k in out if k not in table]
        return {k: out[k] for k in order}

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
        return tuple(seen), x

    def x_grid(self, value) -> XGrid:
        allowed = "{ start = X0, stop = X1, num = N } with X0 < X1 and 2 <= N <= 1000000"
        if not isinstance(value, dict):
            raise self.error("outputs.x", f"must be a table, got {_describe(value)}", allowed)
        self.check_keys(value, X_KEYS, "outputs.x")
        for k in X_KEYS:
            if k not in value:
                raise self.error(f"outputs.x.{k}", "is missing", allowed)
        start = self.number("outputs.x.start", value["start"], allowed)
        stop = self.number("outputs.x.stop", value["stop"], allowed)
        num = value["num"]
        if isinstance(num, bool) or not isinstance(num, int) or not 2 <= num <= 1_000_000:
            raise self.error("outputs.x.num", f"must be an integer in [2, 1000000], got "
                             f"{_describe(num)}", allowed)
        if not start < stop:
            raise self.error("outputs.x", f"start = {start!r} is not below stop = {stop!r}",
                             allowed)
        return XGrid(start, stop, num)

    def numerics(self, table: dict, kind: str) -> Numerics:
        self.check_keys(table, NUMERICS_KEYS, "numerics")
        method = table.get("method", "numeric")
        if method not in METHODS:
            raise self.error("numerics.method", f"unknown method {method!r}",
                             " | ".join(repr(m) for m in METHODS))
        if method == "closed_form" and kind == "profile":
            raise self.error("numerics.method", "closed_form exists only for the four classical "
                             "punches, not for a profile", '"numeric" for a profile punch')
        if "n" in table and "tol" in table:
            raise self.error("numerics.n", "given together with numerics.tol",
                             "either n (fixed) or tol (n chosen adaptively)")
        n = table.get("n")
        if n is not None and (isinstance(n, bool) or not isinstance(n, int)
                              or not 2 <= n <= 100_000):
            raise self.error("numerics.n", f"must be an integer in [2, 100000], got "
                             f"{_describe(n)}", "an integer in [2, 100000]")
        tol = table.get("tol", 1e-12)
        tol = self.number("numerics.tol", tol, "a number in (0, 1)")
        if not 0 < tol < 1:
            raise self.error("numerics.tol", f"must be in (0, 1), got {tol!r}",
                             "a number in (0, 1)")
        return Numerics(method, n, tol)

    # ---- checks that need the physics (cheap: no contact problem is solved) ----
    def check_cases(self, scene: Scene):
        material = scene.material.build()
        c_R = contact.rayleigh_speed(material)
        key = "motion.velocity" if "velocity" in scene.motion else "motion.speed"
        for case in scene.cases():
            c = case.speed
            if not c < c_R:
                shown = (f"velocity = {case.inputs['velocity']!r} (relative speed c = {c!r})"
                         if "velocity" in case.inputs else f"{c!r}")
                raise self.error(key, f"{shown} is not below the Rayleigh speed of this material, "
                                 f"c_R = {c_R!r}", f"0 <= speed < c_R = {c_R:.10g}")
            self.check_punch(case.punch)

    def check_punch(self, spec: PunchSpec):
        try:
            punch = spec.build()
        except contact.ContactInputError as exc:
            key = f"punch.{spec.dimension_key}" if spec.dimension_key else "punch"
            raise self.error(key, str(exc)) from None
        if spec.kind == "profile":
            lo, hi = _probe_range(punch)
            try:
                punch.slope(np.linspace(lo, hi, 7))
            except Exception as exc:               # user code: any failure is a scene error
                raise self.error("punch.slope", f"{exc} (probed at X in [{lo:g}, {hi:g}])",
                                 "a vectorised function returning finite real dv/dX "
                                 "of the same shape as X") from None


def _probe_range(punch) -> tuple:
    xs = [c for c in punch.corners if c is not None] + list(punch.breaks)
    if not xs:
        return -1.0, 1.0
    lo, hi = min(xs), max(xs)
    pad = max(1.0, hi - lo)
    return lo - pad, hi + pad


def _default_title(punch: dict) -> str:
    kind = punch["kind"]
    dims = PUNCH_DIMENSIONS[kind]
    if not dims or isinstance(punch[dims[0]], tuple):
        return f"{kind} punch"
    return f"{kind} punch, {dims[0]} = {punch[dims[0]]:g}"


def _describe(value) -> str:
    kinds = {bool: "boolean", int: "integer", float: "float", str: "string", list: "list",
             dict: "table"}
    name = kinds.get(type(value), type(value).__name__)
    if value is None:
        return "nothing"
    if isinstance(value, (dict, list)):
        return f"a {name}"
    return f"{name} {value!r}"


# --------------------------------------------------------------------------
# running
# --------------------------------------------------------------------------
@dataclass
class CaseResult:
    """What one case produced: the JSON entry (inputs, then the requested fields in the
    scene's order, curves as numpy arrays), the solve time and any warnings."""
    index: int
    label: str
    entry: dict
    time_s: float
    warnings: list = field(default_factory=list)

    def curve(self, name):
        """(x, values) of a sampled curve field."""
        c = self.entry[name]
        return c["x"], c["values"]


@dataclass
class SceneResult:
    """All cases of a scene, in scene order."""
    scene: Scene
    cases: list
    timing_s: float
    warnings: list = field(default_factory=list)

    @property
    def curve_fields(self):
        return [f for f in self.scene.fields if f in CURVE_FIELDS]

    def to_json(self) -> dict:
        """The content of result.json."""
        return {"scene": self.scene.echo(),
                "scene_file": self.scene.source,
                "cases": [_json_entry(c.entry) for c in self.cases],
                "version": _version(),
                "timing_s": self.timing_s,
                "units": UNITS,
                "warnings": list(self.warnings)}


def _version() -> str:
    from importlib.metadata import PackageNotFoundError, version
    try:
        return version("sie-contact")
    except PackageNotFoundError:             # pragma: no cover - running from a bare checkout
        return "unknown"


def _json_entry(entry: dict) -> dict:
    out = {}
    for k, v in entry.items():
        if isinstance(v, dict) and "values" in v:
            v = {"x": v["x"].tolist(), "values": [None if not math.isfinite(y) else y
                                                  for y in v["values"].tolist()]}
        out[k] = v
    return out


@functools.lru_cache(maxsize=256)
def _shared_constants(material, speed):
    """surface_constants once per (material, speed) in each process (serial runs and each
    worker of a pool share them across the sweep)."""
    return contact.surface_constants(material, speed)


def run_case(case: Case) -> CaseResult:
    """Solve one case and compute its requested per-case fields (not roots/constants, which
    :func:`run_scene` computes once per speed).  Runs in a worker process or Dask worker."""
    t0 = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        material = case.material.build()
        result = contact.solve(material, case.punch.build(),
                               load=case.inputs["load"], speed=case.speed,
                               friction=case.inputs["friction"],
                               direction=case.inputs["direction"], method=case.numerics.method,
                               n=case.numerics.n, tol=case.numerics.tol,
                               constants=_shared_constants(material, case.speed))
        entry = {"inputs": dict(case.inputs)}
        X = None
        for name in case.fields:
            if name == "ends":
                entry["ends"] = [result.ends[0], result.ends[1]]
            elif name == "exponents":
                entry["exponents"] = [result.alpha, result.beta]
            elif name == "sif":
                entry["sif"] = dict(result.sif)
            elif name in CURVE_FIELDS:
                if X is None:
                    X = case.x.points() if case.x is not None else _auto_x(result)
                entry[name] = {"x": X, "values": _sample(result, name, X)}
    return CaseResult(case.index, case.label, entry, time.perf_counter() - t0,
                      [f"{w.category.__name__}: {w.message}" for w in caught])


def _auto_x(result) -> np.ndarray:
    xl, xr = result.ends
    pad = AUTO_X_MARGIN * (xr - xl)
    return np.linspace(xl - pad, xr + pad, AUTO_X_POINTS)


def _sample(result, name: str, X: np.ndarray) -> np.ndarray:
    """A curve field at X; NaN at a singular contact end, where it is infinite."""
    s = (X - result.center) / result.half_width          # as ContactResult does
    finite = np.ones(X.shape, dtype=bool)
    if result.alpha < 0:
        finite &= s != 1.0
    if result.beta < 0:
        finite &= s != -1.0
    values = np.full(X.shape, np.nan)
    values[finite] = getattr(result, name)(X[finite])
    return values


def speed_fields(material: MaterialSpec, speeds, fields) -> dict:
    """Roots and/or surface constants once per distinct speed: {speed: {field: value}}."""
    wanted = [f for f in fields if f in SPEED_FIELDS]
    if not wanted:
        return {}
    m = material.build()
    out = {}
    for c in dict.fromkeys(speeds):
        out[c] = {}
        if "constants" in wanted:
            k = contact.surface_constants(m, c)
            out[c]["constants"] = {"N11": k.N11, "N12": k.N12, "N21": k.N21, "N22": k.N22,
                                   "rayleigh_speed": k.rayleigh_speed,
                                   "eta_product": k.eta_product, "eta_sum": k.eta_sum}
        if "roots" in wanted:
            r = m.characteristic_roots(c)
            out[c]["roots"] = {"real": (r.real + 0.0).tolist(), "imag": (r.imag + 0.0).tolist()}
    return out


def run_scene(scene: Scene, executor: Executor | None = None, progress: bool = False,
              ) -> SceneResult:
    """Run every case of a scene, in scene order.

    Parameters
    ----------
    scene : Scene
    executor : concurrent.futures.Executor, optional
        Where cases are solved (a ProcessPoolExecutor, or a Dask ``Client.get_executor()``);
        None: in this process, one after the other.  Results are the same either way.  Cases
        are plain data rebuilt where they run: the workers must be able to import ``contact``
        (and a profile's "module:function", looked up in the scene's directory first).
    progress : bool
        Show a tqdm progress bar (on stderr) if the run takes longer than about a second.

    Raises
    ------
    CaseError
        If a case fails in the library (e.g. the profile would lose contact); the message
        names the case.
    """
    cases = scene.cases()
    t0 = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        shared = speed_fields(scene.material, [c.speed for c in cases], scene.fields)
    results = _map_in_order(run_case, cases, executor, progress, scene)
    for res, case in zip(results, cases):
        if case.speed in shared:
            per_speed = shared[case.speed]
            res.entry = {k: res.entry[k] if k in res.entry else per_speed[k]
                         for k in ("inputs",) + scene.fields}
    messages = list(dict.fromkeys(f"{w.category.__name__}: {w.message}" for w in caught))
    for res in results:
        messages += [f"case {res.index} ({res.label}): {w}" for w in res.warnings]
    return SceneResult(scene, results, time.perf_counter() - t0, messages)


def _map_in_order(fn, cases, executor, progress, scene):
    """[fn(case) for case in cases], in this process or through ``executor``; the library's
    input errors become a CaseError naming the case."""
    bar = _progress_bar(len(cases), progress)
    try:
        if executor is None:
            out = []
            for case in cases:
                with _naming(case, scene):
                    out.append(fn(case))
                bar.update(1)
            return out
        futures = [executor.submit(fn, case) for case in cases]
        try:
            for fut in as_completed(futures):
                if fut.exception() is not None:
                    break                        # report it below, in scene order
                bar.update(1)
            out = []
            for fut, case in zip(futures, cases):
                with _naming(case, scene):
                    out.append(fut.result())
            return out
        finally:
            for fut in futures:
                fut.cancel()
    finally:
        bar.close()


@contextmanager
def _naming(case, scene):
    """Re-raise the library's input errors (contact.ContactInputError, sie.SIEInputError) as a
    CaseError that names the scene file and the case."""
    try:
        yield
    except (contact.ContactInputError, sie.SIEInputError) as exc:
        raise CaseError(f"{scene.source}: case {case.index} ({_inputs_text(case.inputs)}): "
                        f"{type(exc).__name__}: {exc}") from exc


def _inputs_text(inputs: dict) -> str:
    return ", ".join(f"{k} = {_fmt(v)}" for k, v in inputs.items())


class _NoBar:
    def update(self, n=1):
        pass

    def close(self):
        pass


def _progress_bar(total, progress):
    if not progress or total < 2:
        return _NoBar()
    try:
        from tqdm import tqdm
    except ImportError:                      # tqdm is a dependency; be lenient all the same
        return _NoBar()
    return tqdm(total=total, desc="cases", unit="case", delay=1.0, file=sys.stderr,
                dynamic_ncols=True, leave=False)


# --------------------------------------------------------------------------
# writing: result.json, CSV, PNG, the printed table
# --------------------------------------------------------------------------
def write_outputs(result: SceneResult, out_dir) -> list[Path]:
    """Write result.json, one CSV per sampled curve field and its PNG figure into
    ``out_dir`` (created if needed).  PNGs need matplotlib; without it they are skipped.

    Returns
    -------
    list of Path
        The files written.
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    written = [out / "result.json"]
    written[0].write_text(dumps_json(result.to_json()) + "\n", encoding="utf-8")
    for name in result.curve_fields:
        written.append(_write_csv(result, name, out / f"{name}.csv"))
    png = _write_figures(result, out)
    return written + png


def dumps_json(obj, indent: str = "  ", _level: int = 0) -> str:
    """JSON text with tables indented and lists of numbers on one line (readable, compact)."""
    pad, inner = indent * _level, indent * (_level + 1)
    if isinstance(obj, dict):
        if not obj:
            return "{}"
        items = [f"{inner}{json.dumps(str(k))}: {dumps_json(v, indent, _level + 1)}"
                 for k, v in obj.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(obj, (list, tuple)):
        if all(not isinstance(v, (dict, list, tuple)) for v in obj):
            return json.dumps(list(obj), allow_nan=False)
        items = [inner + dumps_json(v, indent, _level + 1) for v in obj]
        return "[\n" + ",\n".join(items) + "\n" + pad + "]"
    return json.dumps(obj, allow_nan=False)


def _write_csv(result: SceneResult, name: str, path: Path) -> Path:
    """One column per case; a single X column when every case shares its x grid."""
    curves = [res.curve(name) for res in result.cases]
    labels = [_column_label(res, result, name) for res in result.cases]
    shared = all(np.array_equal(x, curves[0][0]) for x, _ in curves)
    if shared:
        header = ["X"] + labels
        columns = [curves[0][0]] + [v for _, v in curves]
    else:
        header, columns = [], []
        for label, (x, v) in zip(labels, curves):
            header += [f"X ({label})", label]
            columns += [x, v]
    rows = max(len(c) for c in columns)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        for i in range(rows):
            w.writerow(["" if i >= len(c) or not math.isfinite(c[i]) else repr(float(c[i]))
                        for c in columns])
    return path


def _column_label(res: CaseResult, result: SceneResult, name: str) -> str:
    return res.label if result.scene.sweep else name


_AXIS_LABELS = {"pressure": "pressure p(X)", "shear": "shear traction q(X)",
                "sigma_xx": r"$\sigma_{XX}(X, 0)$"}


def _write_figures(result: SceneResult, out: Path) -> list[Path]:
    names = result.curve_fields
    if not names:
        return []
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        result.warnings.append("matplotlib is not installed: no PNG figures written "
                               "(pip install 'sie-contact[plot]')")
        return []
    written = []
    for name in names:
        fig, ax = plt.subplots(figsize=(7.0, 4.2))
        family = len(result.cases) > 1
        for res in result.cases:
            x, v = res.curve(name)
            ax.plot(x, v, lw=1.3, label=res.label if family else None)
        if not family and "ends" in result.cases[0].entry:
            for x_end in result.cases[0].entry["ends"]:
                ax.axvline(x_end, color="0.6", ls=":", lw=0.8)
        ax.axhline(0.0, color="0.7", lw=0.6)
        ax.set_xlabel("X")
        ax.set_ylabel(_AXIS_LABELS[name])
        ax.set_title(result.scene.title)
        ax.set_ylim(*_robust_limits([res.curve(name)[1] for res in result.cases]))
        if family:
            ax.legend(fontsize=8)
        fig.tight_layout()
        path = out / f"{name}.png"
        fig.savefig(path, dpi=120)
        plt.close(fig)
        written.append(path)
    return written


def _robust_limits(curves) -> tuple:
    """y-limits that show the curves without letting a sampled singular spike flatten them:
    the full range, unless it exceeds 4x the 1..99 percentile range."""
    v = np.concatenate([c[np.isfinite(c)] for c in curves] or [np.zeros(1)])
    if v.size == 0:
        return -1.0, 1.0
    lo, hi = float(v.min()), float(v.max())
    plo, phi = (float(q) for q in np.percentile(v, [1, 99]))
    if hi - lo > 4.0 * (phi - plo) > 0:
        lo, hi = plo, phi
    pad = 0.06 * (hi - lo) if hi > lo else max(1.0, abs(hi))
    return lo - pad, hi + pad


def format_table(result: SceneResult) -> str:
    """A short text table: one row per case with its swept inputs, ends, exponents, peak
    pressure, SIFs and sigma_XX extremes (what was requested) and the time taken."""
    scene = result.scene
    mat = scene.material
    c_R = contact.rayleigh_speed(mat.build())
    head = [scene.title,
            f"  scene: {scene.source}",
            f"  material: {mat.preset or 'custom'} (C11, C12, C22, C33 = {mat.C11:.10g}, "
            f"{mat.C12:.10g}, {mat.C22:.10g}, {mat.C33:.10g}); Rayleigh speed c_R = {c_R:.10f}",
            f"  fixed inputs: {_inputs_text(_fixed_inputs(result))}"]
    swept = [key for _, key in scene.sweep]
    if "velocity" in swept:
        swept.append("speed")
    columns = ["case"] + swept
    rows = []
    for res in result.cases:
        e = res.entry
        row = {"case": str(res.index)}
        row.update({k: _fmt(e["inputs"][k]) for k in swept})
        if "ends" in e:
            row["x_left"], row["x_right"] = (f"{x:.10g}" for x in e["ends"])
        if "exponents" in e:
            row["alpha"], row["beta"] = (f"{x:.8g}" for x in e["exponents"])
        if "pressure" in e:
            row["max p (sampled)"] = _extreme(e["pressure"]["values"], np.nanmax)
        if "sif" in e:
            row["K_left"] = f"{e['sif']['left']:.6g}" if "left" in e["sif"] else "-"
            row["K_right"] = f"{e['sif']['right']:.6g}" if "right" in e["sif"] else "-"
        if "sigma_xx" in e:
            row["min sigma_xx"] = _extreme(e["sigma_xx"]["values"], np.nanmin)
            row["max sigma_xx"] = _extreme(e["sigma_xx"]["values"], np.nanmax)
        row["time ms"] = f"{1e3 * res.time_s:.1f}"
        for k in row:
            if k not in columns:
                columns.append(k)
        rows.append(row)
    columns.remove("time ms")
    columns.append("time ms")
    widths = {k: max(len(k), *(len(r.get(k, "")) for r in rows)) for k in columns}
    lines = head + ["", "  " + "  ".join(f"{k:>{widths[k]}}" for k in columns)]
    lines += ["  " + "  ".join(f"{r.get(k, ''):>{widths[k]}}" for k in columns) for r in rows]
    if "sif" in scene.fields and any(not res.entry["sif"] for res in result.cases):
        lines.append("  (SIF '-': that contact end is free, the pressure vanishes there)")
    lines.append(f"  total time {result.timing_s:.3f} s for {len(result.cases)} case(s); units as "
                 "in the scene (stresses in the stiffness unit, lengths in the punch's unit)")
    return "\n".join(lines)


def _fixed_inputs(result: SceneResult) -> dict:
    swept = {key for _, key in result.scene.sweep}
    first = result.cases[0].entry["inputs"]
    return {k: v for k, v in first.items()
            if k not in swept and not (k == "speed" and "velocity" in swept)}


def _extreme(values, fn) -> str:
    v = np.asarray(values, dtype=float)
    if not np.any(np.isfinite(v)):
        return "-"
    return f"{fn(v) + 0.0:.6g}"
