"""Scene vocabulary, errors and the parsed-scene data classes."""
from __future__ import annotations

import importlib
import itertools
import math
import sys
from dataclasses import dataclass

import numpy as np
from numpy.polynomial.polynomial import polyval

import contact


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
