"""Scene vocabulary, errors and the parsed-scene data classes."""
from __future__ import annotations

import functools
import itertools
import math
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

import contact
from contact.registry import KINDS, import_callable


# --------------------------------------------------------------------------
# the vocabulary of a scene
# --------------------------------------------------------------------------
SECTIONS = ("title", "material", "punch_material", "punch", "motion", "outputs", "numerics")
MATERIAL_KEYS = ("kind", "preset", "C11", "C12", "C22", "C33", "rho", "factory", "arguments",
                 "C", "engineering", "rotation")
MATERIAL_KINDS = ("orthotropic", "anisotropic")
#: The engineering constants of an orthotropic material in its own axes 1, 2, 3
#: (:meth:`contact.Anisotropic.from_engineering`).
ENGINEERING_KEYS = ("E1", "E2", "E3", "nu12", "nu13", "nu23", "G12", "G13", "G23")
ROTATION_KEYS = ("axis", "degrees")
PRESETS = {"zhou2014": contact.zhou2014}
PIECE_KEYS = ("from", "to", "coefficients")
MOTION_KEYS = ("load", "speed", "velocity", "friction", "direction", "tangential_load",
               "creepage", "rolling")
#: The [motion] keys of partial slip and steady rolling (:mod:`contact.partial_slip`): a case
#: with one of them is solved by :func:`contact.solve` alone (not in a batch).
SLIP_INPUTS = ("tangential_load", "creepage")
#: What the entry of such a case adds after its inputs: Q and the creepage (the one given and
#: the one that follows; the creepage None for a static contact) and the stick zones.
SLIP_ENTRY_KEYS = ("tangential_load", "creepage", "stick_zones")
OUTPUT_KEYS = ("fields", "x", "grid", "figures")
X_KEYS = ("start", "stop", "num")
GRID_KEYS = ("x", "y")
NUMERICS_KEYS = ("method", "n", "tol")
METHODS = ("numeric", "closed_form")
FREE = "free"

#: Every field a scene may ask for, in the order they are documented.
FIELDS = ("ends", "exponents", "sif", "zones", "pressure", "shear", "sigma_xx", "roots",
          "constants", "subsurface")
#: Fields of one contact zone: with several zones a case lists ``zones`` in their place.
ZONE_FIELDS = ("ends", "exponents", "sif")
#: Fields sampled as curves on the x grid.
CURVE_FIELDS = ("pressure", "shear", "sigma_xx")
#: Fields that depend on (material, speed) only.
SPEED_FIELDS = ("roots", "constants")
DEFAULT_FIELDS = ("ends", "exponents", "pressure")
AUTO_X_POINTS = 401
AUTO_X_MARGIN = 0.5            # automatic x: the contact widened by this fraction of its length
#: The field under the surface (``"subsurface"``): the default map, in units of the largest
#: zone's half-width a (ContactResult.zone_scale), x_left, x_right the outer ends of the
#: zones: X from x_left - a to x_right + a, Y from -3 a to 0, with this many points (nx, ny).
SUBSURFACE_POINTS = (161, 121)
SUBSURFACE_MARGIN = 1.0        # X: the contact widened by this many a on each side
SUBSURFACE_DEPTH = 3.0         # Y: from -SUBSURFACE_DEPTH a up to the surface
#: Where the extrema are searched when a singular (corner) end lies under the map's top row
#: on Y = 0: the map's region with its top lowered to Y = -SUBSURFACE_CUT a (the stresses are
#: infinite at the corner itself).
SUBSURFACE_CUT = 1e-3
SUBSURFACE_MAX_POINTS = 4_000_000   # nx * ny of a user's grid

UNITS = {
    "statement": "consistent units: every stress (material C11..C33, pressure, shear, sigma_xx) "
                 "in one stress unit S, every length (X, ends, half_width, radius, breaks) in one "
                 "length unit L, as given in the scene",
    "load": "S*L (force per unit length of the punch)",
    "pressure, shear, sigma_xx": "S",
    "subsurface: sigma_xx, sigma_yy, sigma_xy, max_shear, max_tension, value": "S",
    "subsurface: X, Y, depth, half_width, grid, region": "L (Y <= 0 is the half-space, "
                                                         "depth = -Y)",
    "subsurface: depth_over_a": "dimensionless",
    "ends, x, half_width, radius": "L",
    "slope (triangular), speed, friction, exponents": "dimensionless",
    "sif": "S*L^(-e), e the exponent at that end (definitions: contact.ContactResult.sif)",
    "N11, N12": "1/S",
    "N21, N22, rayleigh_speed, roots": "dimensionless",
    "velocity": "the unit of sqrt(C33/rho)",
    "timing_s": "seconds",
    "diagnostics: n": "count (Jacobi coefficients per zone)",
    "diagnostics: residual, load_check": "dimensionless (relative)",
}

#: The default scene (``contact run`` without a scene file; ``make run``), as TOML text.
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
    """The scene's material: plain data, rebuilt into a material wherever it is solved (so
    a case can travel to another process or a Dask worker).

    Either the stiffnesses of an orthotropic material, Zhou et al. 2014, eq. (2.2) (and the
    density, if given), after a preset is expanded; or an anisotropic material
    (``kind = "anisotropic"``: its 6x6 stiffness, or the engineering constants of an
    orthotropic one, turned by rotations); or a user's ``factory``, a "module:function"
    called with ``arguments`` that returns any object with the methods of
    :class:`contact.Material`.

    Attributes
    ----------
    C11, C12, C22, C33 : float or None
        The stiffnesses of an orthotropic material (None otherwise).
    kind : str
        "orthotropic" or "anisotropic" (a factory's material: "orthotropic", unused).
    C : tuple of tuples or None
        The 6x6 stiffness in Voigt order (XX, YY, ZZ, YZ, ZX, XY) of an anisotropic material
        given by it.
    engineering : tuple of (key, value) or None
        The engineering constants (:data:`ENGINEERING_KEYS`) of an anisotropic material
        given by them.
    rotation : tuple of (axis, degrees)
        Rotations of an anisotropic material's axes, applied in order (each active, about
        the problem's axis "x", "y" or "z": :meth:`contact.Anisotropic.rotated`).
    rho : float or None
        The density (None with a factory: the factory's material converts velocities).
    preset : str or None
        The preset the stiffnesses came from.
    factory : str or None
        "module:function" returning the material.
    arguments : tuple of (key, value)
        The factory's keyword arguments (numbers, strings, booleans, and tuples of them).
    base_dir : str or None
        The scene file's directory (searched first for the factory's module).
    """
    C11: float | None = None
    C12: float | None = None
    C22: float | None = None
    C33: float | None = None
    rho: float | None = None
    preset: str | None = None
    factory: str | None = None
    arguments: tuple = ()
    base_dir: str | None = None
    kind: str = "orthotropic"
    C: tuple | None = None
    engineering: tuple | None = None
    rotation: tuple = ()

    def build(self):
        """The material: a :class:`contact.Orthotropic`, a :class:`contact.Anisotropic`, or
        what the factory returns."""
        if self.factory is not None:
            return import_callable(self.factory, self.base_dir)(**dict(self.arguments))
        if self.kind == "anisotropic":
            return anisotropic_material(self.C, self.engineering, self.rotation, self.rho)
        return contact.Orthotropic(self.C11, self.C12, self.C22, self.C33, rho=self.rho)

    def describe(self) -> str:
        """The material in a few words, for the printed table and the command's headers."""
        if self.factory is not None:
            args = ", ".join(f"{k}={v!r}" for k, v in self.arguments)
            return f"{self.factory}({args})"
        if self.kind == "anisotropic":
            given = ("engineering constants " + ", ".join(f"{k} = {v:.10g}"
                                                          for k, v in self.engineering)
                     if self.engineering is not None else "C (6x6, Voigt)")
            turns = "".join(f", turned {d:g} deg about {a}" for a, d in self.rotation)
            return f"anisotropic ({given}{turns})"
        return (f"{self.preset or 'custom'} (C11, C12, C22, C33 = {self.C11:.10g}, "
                f"{self.C12:.10g}, {self.C22:.10g}, {self.C33:.10g})")

    def echo(self) -> dict:
        """The material as the scene gave it after defaults, JSON-ready."""
        if self.factory is not None:
            return {"factory": self.factory,
                    "arguments": {k: _json_value(v) for k, v in self.arguments}}
        if self.kind == "anisotropic":
            out = {"kind": "anisotropic"}
            if self.C is not None:
                out["C"] = [list(row) for row in self.C]
            else:
                out["engineering"] = dict(self.engineering)
            out["rotation"] = [{"axis": a, "degrees": d} for a, d in self.rotation]
            out["rho"] = self.rho
            return out
        out = {"preset": self.preset} if self.preset else {}
        out.update(C11=self.C11, C12=self.C12, C22=self.C22, C33=self.C33, rho=self.rho)
        return out


def anisotropic_material(C, engineering, rotation, rho):
    """A :class:`contact.Anisotropic` from a scene's ``C`` (6x6, Voigt) or ``engineering``
    constants (pairs), turned by each (axis, degrees) of ``rotation`` in order (an active
    rotation about the problem's axis: ``scipy.spatial.transform.Rotation.from_euler``)."""
    from scipy.spatial.transform import Rotation
    if C is not None:
        m = contact.Anisotropic(np.array(C, dtype=float), rho)
    else:
        m = contact.Anisotropic.from_engineering(**dict(engineering), rho=rho)
    for axis, degrees in rotation:
        m = m.rotated(Rotation.from_euler(axis, degrees, degrees=True))
    return m


@dataclass(frozen=True)
class PunchSpec:
    """One punch (a single sweep point): plain data, rebuilt into a :class:`contact.Punch`
    wherever it is solved (so a case can travel to another process or a Dask worker).

    Attributes
    ----------
    kind : str
        A key of :data:`contact.registry.KINDS`.
    values : tuple of (key, value)
        The kind's scene keys given for this case, parsed: numbers, tuples, "module:function"
        strings, :class:`contact.registry.Piece` and :class:`contact.registry.Samples` (a
        tabulated face travels as its samples, not as a file name).
    base_dir : str or None
        The scene file's directory (searched first for a "module:function").
    """
    kind: str
    values: tuple = ()
    base_dir: str | None = None

    def get(self, key, default=None):
        """The value of a scene key, or ``default`` if the scene did not give it."""
        return dict(self.values).get(key, default)

    @property
    def dimension_key(self):
        """The kind's first dimension key (None for a profile)."""
        keys = KINDS[self.kind].dimensions
        return keys[0] if keys else None

    def build(self) -> contact.Punch:
        """The punch (:meth:`contact.registry.PunchKind.build`)."""
        return KINDS[self.kind].build(dict(self.values), self.base_dir)


@dataclass(frozen=True)
class XGrid:
    """Where curves are sampled: numpy.linspace(start, stop, num), without its float noise
    (:func:`clean_linspace`)."""
    start: float
    stop: float
    num: int

    def points(self) -> np.ndarray:
        """The grid's points (a read-only array, shared by the cases of a scene)."""
        return _grid_points(self.start, self.stop, self.num)

    def echo(self) -> dict:
        return {"start": self.start, "stop": self.stop, "num": self.num}


@dataclass(frozen=True)
class SubsurfaceGrid:
    """Where the field under the surface is mapped (``[outputs] grid``): numpy.linspace
    along X and along Y (Y <= 0); an axis left None takes its default, scaled to each case's
    contact (:data:`SUBSURFACE_POINTS`)."""
    x: XGrid | None = None
    y: XGrid | None = None

    def echo(self) -> dict:
        return {"x": None if self.x is None else self.x.echo(),
                "y": None if self.y is None else self.y.echo()}


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
    punch dimension, the velocity if the scene gave one, the tangential load or the creepage
    if given, and ``rolling = True`` for steady rolling); ``label`` names the swept values.
    """
    index: int
    label: str
    inputs: dict
    material: MaterialSpec
    punch: PunchSpec
    fields: tuple
    x: XGrid | None
    numerics: Numerics
    grid: SubsurfaceGrid | None = None
    punch_material: MaterialSpec | None = None

    @property
    def speed(self) -> float:
        return self.inputs["speed"]

    @property
    def partial_slip(self) -> bool:
        """Whether the case has a tangential load or a creepage (partial slip, steady
        rolling: :mod:`contact.partial_slip`)."""
        return any(key in self.inputs for key in SLIP_INPUTS)


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
    grid: SubsurfaceGrid | None = None
    figures: bool = True
    punch_material: MaterialSpec | None = None

    def cases(self) -> list[Case]:
        """Every case, in scene order (:meth:`iter_cases` as a list)."""
        return list(self.iter_cases())

    def iter_cases(self, start: int = 0, stop: int | None = None) -> Iterator[Case]:
        """The cases ``start`` <= index < ``stop`` (default: all) one at a time, built as they
        are asked for, in scene order (:meth:`case`)."""
        stop = self.case_count if stop is None else min(stop, self.case_count)
        swept = self._swept()
        for index in range(max(start, 0), stop):
            yield self._case_at(index, swept)

    def case(self, index: int) -> Case:
        """Case ``index`` of the sweep, built on its own: the point of the Cartesian product
        of the swept values with the first swept key varying slowest (the index read as a
        mixed-radix number, a digit per swept key).  A worker given a range of indices builds
        its cases from the scene this way.

        Raises
        ------
        IndexError
            ``index`` outside [0, case_count).
        """
        if isinstance(index, bool) or not isinstance(index, (int, np.integer)) or \
                not 0 <= index < self.case_count:
            raise IndexError(f"case index must be in [0, {self.case_count}), got {index!r}")
        return self._case_at(int(index), self._swept())

    def punch_specs(self) -> Iterator[PunchSpec]:
        """Each punch of the sweep once: the product of the punch section's swept keys, in
        scene order (a sweep over speed or friction alone has one)."""
        keys = [key for sec, key in self.sweep if sec == "punch"]
        for values in itertools.product(*(self.punch[k] for k in keys)):
            yield _punch_spec({**self.punch, **dict(zip(keys, values))}, self.base_dir)

    def _swept(self):
        return [self._section(sec)[key] for sec, key in self.sweep]

    def _case_at(self, index, swept):
        values, rest = [], index
        for column in reversed(swept):
            rest, digit = divmod(rest, len(column))
            values.append(column[digit])
        point = dict(zip(self.sweep, reversed(values)))
        punch = {k: point.get(("punch", k), v) for k, v in self.punch.items()}
        motion = {k: point.get(("motion", k), v) for k, v in self.motion.items()}
        label = ", ".join(f"{key} = {_fmt(v)}" for (_, key), v in point.items())
        return Case(index=index, label=label or self.title,
                    inputs=_case_inputs(self.material, punch, motion),
                    material=self.material, punch=_punch_spec(punch, self.base_dir),
                    fields=self.fields, x=self.x, numerics=self.numerics, grid=self.grid,
                    punch_material=self.punch_material)

    @property
    def case_count(self) -> int:
        """How many cases the scene has (the product of the swept lists' lengths), without
        building them."""
        return math.prod(len(self._section(sec)[key]) for sec, key in self.sweep)

    def _section(self, name):
        return self.punch if name == "punch" else self.motion

    def echo(self) -> dict:
        """The scene after defaults, as plain JSON-ready data."""
        material = self.material.echo()
        punch = {}
        for k, v in self.punch.items():
            if k == "pieces":
                v = [{"from": _json_float(p.start), "to": _json_float(p.stop),
                      "coefficients": list(p.coefficients)} for p in v]
            elif k == "corners":
                v = [FREE if c is None else c for c in v]
            elif k == "data":
                v = v.source
            elif isinstance(v, tuple):
                v = list(v)
            punch[k] = v
        motion = {k: list(v) if isinstance(v, tuple) else v for k, v in self.motion.items()}
        x = None if self.x is None else self.x.echo()
        outputs = {"fields": list(self.fields), "x": x}
        if self.grid is not None:
            outputs["grid"] = self.grid.echo()
        outputs["figures"] = self.figures
        out = {"title": self.title, "material": material, "punch": punch, "motion": motion,
               "outputs": outputs,
               "numerics": {"method": self.numerics.method, "n": self.numerics.n,
                            "tol": self.numerics.tol}}
        if self.punch_material is not None:
            out["punch_material"] = self.punch_material.echo()
        return out


def clean_linspace(start: float, stop: float, num: int) -> np.ndarray:
    """numpy.linspace(start, stop, num) without float noise on decimal grids.

    When start, stop (as Python writes them) and the step are decimals of at most 15 places,
    as in a scene's ``x = { start = -0.8, stop = 0.8, num = 801 }``, the k-th point is the
    float nearest to the decimal start + k step (computed as (S + k D) / 10^d with exact
    integers S, D), so it prints as that decimal (0.3, not 0.30000000000000004).  Otherwise
    (a step like 1/3, or ends that are not short decimals) it is numpy.linspace.  Either way
    the first and last points are ``start`` and ``stop`` exactly.
    """
    from decimal import Decimal
    a, b = Decimal(repr(float(start))), Decimal(repr(float(stop)))
    steps = num - 1
    if steps >= 1:
        for d in range(16):
            A, B = a.scaleb(d), b.scaleb(d)
            if A != A.to_integral_value() or B != B.to_integral_value():
                continue
            A, B = int(A), int(B)
            if max(abs(A), abs(B)) >= 2 ** 53:
                break
            if (B - A) % steps:
                continue
            k = np.arange(num, dtype=np.int64)
            return (A + (B - A) // steps * k) / 10.0 ** d
    return np.linspace(start, stop, num)


@functools.lru_cache(maxsize=64)
def _grid_points(start, stop, num) -> np.ndarray:
    x = clean_linspace(start, stop, num)
    x.setflags(write=False)
    return x


def _json_float(v):
    return None if v is None or not math.isfinite(v) else v


def _json_value(v):
    """A factory argument as JSON-ready data: tuples as lists."""
    return [_json_value(x) for x in v] if isinstance(v, tuple) else v


def _fmt(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    return f"{v:+d}" if isinstance(v, int) and not isinstance(v, bool) else f"{v:g}"


def _case_inputs(material: MaterialSpec, punch: dict, motion: dict) -> dict:
    inputs = {}
    if "velocity" in motion:
        inputs["speed"] = contact.relative_speed(material.build(), motion["velocity"])
    else:
        inputs["speed"] = motion["speed"]
    inputs["friction"] = motion["friction"]
    inputs["direction"] = motion["direction"]
    inputs["load"] = motion["load"]
    for key in KINDS[punch["kind"]].dimensions:
        inputs[key] = punch[key]
    if "velocity" in motion:
        inputs["velocity"] = motion["velocity"]
    for key in SLIP_INPUTS:
        if key in motion:
            inputs[key] = motion[key]
    if motion.get("rolling"):
        inputs["rolling"] = True
    return inputs


def _punch_spec(punch: dict, base_dir) -> PunchSpec:
    kind = KINDS[punch["kind"]]
    return PunchSpec(kind=kind.name, values=tuple((k, punch[k]) for k in kind.keys if k in punch),
                     base_dir=base_dir)
