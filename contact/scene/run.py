"""Running scenes: cases in chunks, solved together where they share the material, the
punch and the numerics, delivered in order, serially or through any Executor."""
from __future__ import annotations

import functools
import itertools
import math
import sys
import time
import warnings
from concurrent.futures import Executor
from contextlib import contextmanager
from dataclasses import dataclass, field

import numpy as np

import contact
import sie

from .batch import build_once, iter_chunks
from .processes import cyclic_gc_paused
from .table import sweep_table, to_dataframe
from .spec import (AUTO_X_MARGIN, AUTO_X_POINTS, CURVE_FIELDS, Case, CaseError,
                   SLIP_ENTRY_KEYS, SPEED_FIELDS, SUBSURFACE_CUT, SUBSURFACE_DEPTH, SUBSURFACE_MARGIN,
                   SUBSURFACE_POINTS, Scene, SubsurfaceGrid, UNITS, XGrid, ZONE_FIELDS, _fmt)


# --------------------------------------------------------------------------
# running
# --------------------------------------------------------------------------
@dataclass
class CaseResult:
    """What one case produced.

    Attributes
    ----------
    index : int
    label : str
    entry : dict
        The JSON entry: inputs, then the requested fields in the scene's order (curves as
        numpy arrays).  With several contact zones, ``zones`` stands in place of the
        single-zone fields ends, exponents and sif.
    time_s : float
        Time to solve the case and sample its fields: its share of the solve of the cases
        solved together with it (:func:`run_cases`), and its own sampling.  The first case
        of a run also carries loading the compiled kernels, and so do the first chunk's
        cases of a worker that is not a fork of the running process (a Dask worker's, a
        spawned process's: :mod:`contact.scene.batch`).
    warnings : list of str
    zones : list of dict
        Every contact zone (:func:`zone_entry`), whatever the fields asked: the table and the
        figures mark them.
    subsurface : SubsurfaceMap or None
        The stress map under the surface, when the scene asks for ``"subsurface"`` (its
        extrema are in ``entry["subsurface"]``; the maps go to subsurface.npz/.csv, not to
        result.json).
    diagnostics : dict
        The solver's diagnostics (:func:`diagnostics`): ``n``, ``residual``, ``load_check``;
        written to result.json after the fields, and to sweep.csv.
    encoded : CaseText or None
        Its entry of result.json and its rows of sweep.csv as text, made where it was
        solved (:class:`contact.scene.output.CaseEncoder`); None: the writers make them.
    speed_warnings : tuple of str
        The warnings of its material at its speed (the surface constants: near the
        Rayleigh speed), which every case at that speed shares: a run lists each once,
        whichever case or worker met it first (``warnings`` holds the case's own).
    """
    index: int
    label: str
    entry: dict
    time_s: float
    warnings: list = field(default_factory=list)
    zones: list = field(default_factory=list)
    subsurface: "SubsurfaceMap | None" = None
    diagnostics: dict = field(default_factory=dict)
    encoded: tuple | None = field(default=None, repr=False)
    speed_warnings: tuple = ()

    def curve(self, name):
        """(x, values) of a sampled curve field."""
        c = self.entry[name]
        return c["x"], c["values"]


@dataclass
class SubsurfaceMap:
    """The plane stresses of one case on its grid (tension positive, stress unit S).

    Attributes
    ----------
    x : ndarray, shape (nx,)
        X of the grid's columns.
    y : ndarray, shape (ny,)
        Y of its rows (<= 0; the last row is the top).
    field : contact.StressField
        The stresses on the grid, arrays of shape (ny, nx), ``[i, j]`` at (x[j], y[i]); NaN
        only at a singular (corner) contact end on Y = 0, where the stresses are infinite (as
        the curve fields are NaN there).
    """
    x: np.ndarray
    y: np.ndarray
    field: contact.StressField

    def quantity(self, name: str) -> np.ndarray:
        """One of sigma_xx, sigma_yy, sigma_xy, max_shear, max_tension."""
        return getattr(self.field, name)


#: The maps written per case (subsurface.npz, subsurface.csv), in this order.
SUBSURFACE_QUANTITIES = ("sigma_xx", "sigma_yy", "sigma_xy", "max_shear", "max_tension")


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
        return {**_json_head(self.scene), "cases": [_json_case(c) for c in self.cases],
                **_json_tail(self.timing_s, self.warnings)}

    def table(self) -> tuple:
        """The tidy sweep table of sweep.csv: (column names, rows), one row per case in scene
        order, None where a cell is empty (:func:`contact.scene.table.sweep_table`)."""
        return sweep_table(self)

    def to_dataframe(self):
        """The sweep table (sweep.csv) as a pandas DataFrame, one row per case.

        Raises
        ------
        ImportError
            Without pandas (an optional extra: ``pip install 'sie-contact[pandas]'``).
        """
        return to_dataframe(self)


def _json_head(scene: Scene) -> dict:
    """The keys of result.json before ``cases``."""
    return {"scene": scene.echo(), "scene_file": scene.source}


def _json_tail(timing_s: float, messages) -> dict:
    """The keys of result.json after ``cases``."""
    return {"version": _version(), "timing_s": timing_s, "units": UNITS,
            "warnings": list(messages)}


def _json_case(res) -> dict:
    """A case's entry in result.json: its fields, then its diagnostics."""
    out = _json_entry(res.entry)
    if res.diagnostics:
        out["diagnostics"] = dict(res.diagnostics)
    return out


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
def _shared_constants(material, speed) -> tuple:
    """(surface_constants or its library input error, the messages of the warnings it gave)
    once per (material, speed) in each process (serial runs and each worker of a pool share
    them across the sweep): the warnings kept with the constants, so that every case at the
    speed has them, whether the constants were computed for it or before it."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            consts = contact.surface_constants(material, speed)
        except (contact.ContactInputError, sie.SIEInputError) as exc:
            consts = exc
    return consts, tuple(f"{w.category.__name__}: {w.message}" for w in caught)


def _constants_at(material, speed) -> tuple:
    """:func:`_shared_constants`, or the same uncached for a material that cannot be hashed
    (a factory's object of its own may not be)."""
    try:
        return _shared_constants(material, speed)
    except TypeError:                       # unhashable: the lru_cache could not key it
        return _shared_constants.__wrapped__(material, speed)


def run_cases(cases) -> list:
    """Solve a run of cases and compute the requested per-case fields of each (not
    roots/constants, which :func:`run_scene` computes once per speed): what a worker runs
    for a chunk.  Consecutive cases that share the material, the punch and the numerics
    are solved together (:func:`contact.solve_batch`: the first step of the continuation in
    lockstep, one vectorised call per stage).

    Returns
    -------
    list
        Per case, in order, its :class:`CaseResult`, or the library input error
        (contact.ContactInputError, sie.SIEInputError, ContactLossError included) that
        solving or sampling it raised.  A case's ``time_s`` is its share of its group's solve
        plus its own fields.
    """
    out = []
    with cyclic_gc_paused():
        for _, group in itertools.groupby(cases, key=_batch_key):
            out += _run_group(list(group))
    return out


def run_case(case: Case) -> CaseResult:
    """Solve one case (:func:`run_cases` of one), raising its library error."""
    (res,) = run_cases([case])
    if isinstance(res, Exception):
        raise res
    return res


def _batch_key(case):
    """What the cases solved together share."""
    return case.material, case.punch_material, case.punch, case.numerics


def _run_group(group) -> list:
    """:func:`run_cases` on cases of one batch key.  The solve of the group records its
    warnings; where it has any, each case is solved again alone, so that every warning is
    reported with the case it belongs to."""
    t0 = time.perf_counter()
    first = group[0]
    try:
        material = build_once(first.material)
        punch = build_once(first.punch)
        punch_material = None if first.punch_material is None else \
            build_once(first.punch_material)
    except (contact.ContactInputError, sie.SIEInputError) as exc:
        return [exc] * len(group)             # each case of the group fails with it
    by_speed = {}
    for case in group:
        if case.speed not in by_speed:
            by_speed[case.speed] = _constants_at(material, case.speed)
    consts = [by_speed[case.speed][0] for case in group]
    # partial slip and rolling: contact.solve one case at a time (solve_batch has neither)
    ready = [i for i, k in enumerate(consts) if not isinstance(k, Exception)
             and not group[i].partial_slip]
    results = [k if isinstance(k, Exception) else None for k in consts]
    if len(ready) > 1:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            solved = _solve_batch([group[i] for i in ready], material, punch,
                                  [consts[i] for i in ready], punch_material)
        if not caught:               # else each is solved alone below, warnings attributed
            for i, r in zip(ready, solved):
                results[i] = r
    share = (time.perf_counter() - t0) / len(group)
    out = []
    for i, case in enumerate(group):
        t1 = time.perf_counter()
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                res = results[i]
                if res is None:
                    res = _solve_one(case, material, punch, consts[i], punch_material)
                if not isinstance(res, Exception):
                    res = _case_result(case, res)
            except (contact.ContactInputError, sie.SIEInputError) as exc:
                res = exc
        if not isinstance(res, Exception):
            res.time_s = share + (time.perf_counter() - t1)
            res.warnings = [f"{w.category.__name__}: {w.message}" for w in caught] + \
                res.warnings
            res.speed_warnings = by_speed[case.speed][1]
        out.append(res)
    return out


def _solve_batch(cases, material, punch, consts, punch_material=None) -> list:
    """contact.solve_batch of the cases (one batch key), errors in place; ``consts`` the
    half-space's, an elastic punch's compliance added by solve_batch."""
    numerics = cases[0].numerics
    return contact.solve_batch(
        material, punch, load=[c.inputs["load"] for c in cases],
        speed=[c.speed for c in cases], friction=[c.inputs["friction"] for c in cases],
        direction=[c.inputs["direction"] for c in cases], method=numerics.method,
        n=numerics.n, tol=numerics.tol, constants=consts, residual=True, errors="return",
        punch_material=punch_material)


def _solve_one(case, material, punch, consts, punch_material=None):
    """One case alone: :func:`_solve_batch` of one, or, with a tangential load or a
    creepage, :func:`contact.solve` (a :class:`contact.PartialSlipResult`), raising."""
    if not case.partial_slip:
        (res,) = _solve_batch([case], material, punch, [consts], punch_material)
        return res
    inputs, numerics = case.inputs, case.numerics
    return contact.solve(
        material, punch, load=inputs["load"], speed=case.speed, friction=inputs["friction"],
        direction=inputs["direction"], method=numerics.method, n=numerics.n,
        tol=numerics.tol, constants=consts, punch_material=punch_material,
        tangential_load=inputs.get("tangential_load"), creepage=inputs.get("creepage"),
        rolling=inputs.get("rolling", False))


class _PartialSlipView:
    """A :class:`contact.PartialSlipResult` as :func:`_case_result` reads a ContactResult:
    the zones, ends, exponents, SIFs and diagnostics are those of the contact at P
    (``full``: the pressure is the frictionless one, the pair decoupling); the tractions, the
    surface stress and the stresses under the surface and their extrema the partial
    slip's."""

    def __init__(self, result):
        self._slip = result

    def __getattr__(self, name):
        return getattr(self._slip.full, name)

    def pressure(self, X):
        return self._slip.pressure(X)

    def shear(self, X):
        return self._slip.tangential_traction(X)

    def sigma_xx(self, X):
        return self._slip.sigma_xx(X)

    def stress(self, X, Y):
        return self._slip.stress(X, Y)

    def stress_extrema(self, *args, **kwargs):
        return self._slip.stress_extrema(*args, **kwargs)


def slip_entry(result) -> dict:
    """What a case in partial slip or steady rolling adds after its inputs: ``tangential_load``
    (Q), ``creepage`` (None for a static contact) and ``stick_zones`` ([lo, hi] each)."""
    return {"tangential_load": float(result.tangential_load),
            "creepage": None if result.creepage is None else float(result.creepage),
            "stick_zones": [[float(z.ends[0]), float(z.ends[1])] for z in result.stick_zones]}


def _case_result(case: Case, result) -> CaseResult:
    """The case's entry from its solved contact: the requested fields in the scene's order
    (after the partial slip's :func:`slip_entry` for a :class:`contact.PartialSlipResult`)."""
    entry = {"inputs": dict(case.inputs)}
    if isinstance(result, contact.PartialSlipResult):
        entry.update(slip_entry(result))
        result = _PartialSlipView(result)
    several = len(result.zones) > 1
    with_sif = "sif" in case.fields
    X = None
    stress_map = None
    for name in case.fields:
        if name == "zones" or (several and name in ZONE_FIELDS):
            if "zones" not in entry:
                entry["zones"] = [zone_entry(z, with_sif) for z in result.zones]
        elif name == "ends":
            entry["ends"] = [result.ends[0], result.ends[1]]
        elif name == "exponents":
            entry["exponents"] = {"left": result.beta, "right": result.alpha}
        elif name == "sif":
            entry["sif"] = dict(result.sif)
        elif name in CURVE_FIELDS:
            if X is None:
                X = case.x.points() if case.x is not None else _auto_x(result)
            entry[name] = {"x": X, "values": _sample(result, name, X)}
        elif name == "subsurface":
            entry[name], stress_map = subsurface(result, case.grid)
    zones = [zone_entry(z, False) for z in result.zones]
    return CaseResult(case.index, case.label, entry, 0.0,
                      grid_warnings(result, case.x if X is not None else None), zones,
                      stress_map, diagnostics(result))


def diagnostics(result) -> dict:
    """The solver's diagnostics of one case: ``n`` (Jacobi coefficients per zone),
    ``residual`` (:attr:`contact.ContactResult.residual`, relative) and ``load_check``
    (|int p dX - P| / P)."""
    return {"n": int(result.n), "residual": float(result.residual),
            "load_check": float(result.load_check)}


def grid_warnings(result, x: XGrid | None) -> list:
    """A warning when the contact (the outer ends of its zones) reaches beyond the scene's
    x grid, where the curves are sampled (they would miss part of the contact)."""
    if x is None:
        return []
    xl, xr = result.zones[0].ends[0], result.zones[-1].ends[1]
    if x.start <= xl and xr <= x.stop:
        return []
    return [f"the contact [{xl:.6g}, {xr:.6g}] is wider than the x grid [{x.start:g}, "
            f"{x.stop:g}] of outputs.x: the curves miss part of it (widen outputs.x, or leave "
            "it out to follow the contact)"]


def subsurface_axes(result, grid: SubsurfaceGrid | None = None) -> tuple:
    """The (x, y) axes of a case's map: the scene's ``[outputs] grid``, an axis it leaves out
    scaled to the contact: with x_left, x_right the outer ends of the zones and a the largest
    zone's half-width (:attr:`contact.ContactResult.zone_scale`), X from x_left - a to
    x_right + a (161 points) and Y from -3 a to 0 (121 points)."""
    xl, xr = result.zones[0].ends[0], result.zones[-1].ends[1]
    a = result.zone_scale
    gx = grid.x if grid is not None and grid.x is not None else XGrid(
        xl - SUBSURFACE_MARGIN * a, xr + SUBSURFACE_MARGIN * a, SUBSURFACE_POINTS[0])
    gy = grid.y if grid is not None and grid.y is not None else XGrid(
        -SUBSURFACE_DEPTH * a, 0.0, SUBSURFACE_POINTS[1])
    return gx, gy


def subsurface(result, grid: SubsurfaceGrid | None = None) -> tuple:
    """The ``"subsurface"`` field of one case: (JSON entry, :class:`SubsurfaceMap`).

    The map: :meth:`contact.ContactResult.stress` on the grid of :func:`subsurface_axes`
    (NaN at a point on Y = 0 that is exactly a singular contact end, where the stresses are
    infinite).  The entry: the largest in-plane maximum shear and the largest tension
    (:meth:`contact.ContactResult.stress_extrema`) in the map's region, each with its value,
    X, Y, depth = -Y, the half-width a of the nearest zone and depth / a; ``region`` is where
    they were searched -- the map's extent, except that when the map's top row is the surface
    and a singular end lies in its X range, the top is lowered to Y = -1e-3 a (a the largest
    zone's half-width; half the map's depth if that is shallower): the stresses grow without bound
    toward the corner, so such an extremum sits on that cut, next to the corner (its SIFs
    characterise the corner itself).  ``grid`` echoes the map's axes.
    """
    gx, gy = subsurface_axes(result, grid)
    xs, ys = gx.points(), gy.points()
    X, Y = np.meshgrid(xs, ys)                             # (ny, nx)
    singular = [end for end, _ in result.singular_ends]
    infinite = (Y == 0.0) & np.isin(X, singular)
    comps = [np.full(X.shape, np.nan) for _ in range(3)]
    ok = ~infinite
    field_ = result.stress(X[ok], Y[ok])
    for c, v in zip(comps, (field_.sigma_xx, field_.sigma_yy, field_.sigma_xy)):
        c[ok] = v
    stress_map = SubsurfaceMap(xs, ys, contact.StressField(X, Y, *comps))

    x0, x1, y0, y1 = gx.start, gx.stop, gy.start, gy.stop
    if y1 == 0.0 and any(x0 <= e <= x1 for e in singular):
        y1 = -min(SUBSURFACE_CUT * result.zone_scale, 0.5 * (y1 - y0))
    ext = result.stress_extrema(((x0, x1), (y0, y1)))
    entry = {}
    for name in ("max_shear", "max_tension"):
        e = getattr(ext, name)
        entry[name] = {"value": e.value, "X": e.X, "Y": e.Y, "depth": e.depth,
                       "half_width": e.half_width, "depth_over_a": e.depth_over_a}
    entry["region"] = {"x": [x0, x1], "y": [y0, y1]}
    entry["grid"] = {"x": gx.echo(), "y": gy.echo()}
    return entry, stress_map


def zone_entry(zone, with_sif: bool = False) -> dict:
    """One contact zone as JSON-ready data: ends, kinds ("free" | "corner"), exponents of p at
    each end (left: beta, right: alpha), index, load, and its SIFs if asked."""
    out = {"ends": [zone.ends[0], zone.ends[1]], "kinds": list(zone.kinds),
           "exponents": {"left": zone.beta, "right": zone.alpha}, "index": zone.kappa,
           "load": zone.load}
    if with_sif:
        out["sif"] = dict(zone.sif)
    return out


def _auto_x(result) -> np.ndarray:
    """The contact (the outer ends of its zones) widened by AUTO_X_MARGIN of its length."""
    xl, xr = result.zones[0].ends[0], result.zones[-1].ends[1]
    pad = AUTO_X_MARGIN * (xr - xl)
    return np.linspace(xl - pad, xr + pad, AUTO_X_POINTS)


def _sample(result, name: str, X: np.ndarray) -> np.ndarray:
    """A curve field at X; NaN at a singular contact end, where it is infinite."""
    finite = ~np.isin(X, [end for end, _ in result.singular_ends])
    values = np.full(X.shape, np.nan)
    values[finite] = getattr(result, name)(X[finite])
    return values


def speed_entry(material, speed: float, fields) -> dict:
    """The per-speed fields (roots and/or surface constants) asked among ``fields`` at one
    speed: {field: value}.  M12, M21, M22 are 0 for an aligned orthotropic material;
    ``eta_product`` and ``eta_sum`` are None (null, an empty cell) for a material without them (:class:`contact.SurfaceConstants`); the roots need the
    material's ``characteristic_roots(c)`` (the scene's parser checks that it has it)."""
    out = {}
    if "constants" in fields:
        k = contact.surface_constants(material, speed)
        out["constants"] = {"N11": k.N11, "N12": k.N12, "N21": k.N21, "N22": k.N22,
                            "M12": k.M12, "M21": k.M21, "M22": k.M22,
                            "rayleigh_speed": k.rayleigh_speed,
                            "eta_product": k.eta_product, "eta_sum": k.eta_sum}
    if "roots" in fields:
        r = material.characteristic_roots(speed)
        out["roots"] = {"real": (r.real + 0.0).tolist(), "imag": (r.imag + 0.0).tolist()}
    return out


def _solved_and_encoded(encode, cases) -> list:
    """:func:`run_cases`, each result passed through ``encode`` (what a worker runs for a
    writer that wants its cases encoded where they are solved), as the chunk function of
    :func:`contact.scene.batch.iter_chunks`: its chunks run with the collector paused
    throughout (:func:`contact.scene.batch.run_chunk`), the encoding included."""
    return [r if isinstance(r, Exception) else encode(r) for r in run_cases(cases)]


def iter_scene(scene: Scene, executor: Executor | None = None, progress: bool = False,
               encode=None) -> SceneRun:
    """The cases of a scene solved in chunks (:func:`run_cases`) in this process or through
    ``executor``, delivered in scene order as they complete (:class:`SceneRun`); nothing is
    solved until it is iterated.

    Parameters are those of :func:`run_scene`, and ``encode``: a picklable callable applied
    to each result where it is solved (:class:`contact.scene.output.CaseEncoder`, from
    :meth:`contact.scene.SceneWriter.encoder`: a writer's formatting done by the workers;
    what it returns is what the run gives for the case, a :class:`CaseText` from a lean
    one), unless the scene asks for per-speed fields (added here).  The cases are built as
    they are needed and a bounded number of them is solved ahead of the consumer
    (:func:`contact.scene.batch.iter_chunks`): a consumer that keeps nothing per case (the
    writers of ``contact run``, :class:`contact.scene.output.SceneWriter`) runs a sweep of any
    length in bounded memory.
    """
    return SceneRun(scene, executor, progress, encode)


class SceneRun:
    """A scene being run: iterate it (once) for its :class:`CaseResult` (its
    :class:`CaseText` with a lean encoder) in scene order, or take them a chunk at a time
    (:meth:`chunks`).

    Attributes
    ----------
    scene : Scene
    count : int
        How many cases it has.
    timing_s : float
        Seconds spent solving so far (the consumer's time between two chunks not counted,
        workers of an executor may solve meanwhile); the run's time once iterated.
    warnings : list of str
        The run's warnings so far: first those of the material at a speed (near the
        Rayleigh speed: the surface constants, the per-speed fields), once each message,
        then each case's own, named by case; all of them once iterated, the same whatever
        the executor.

    Raises
    ------
    CaseError
        While iterated, at the first case (in scene order) that fails in the library.
    """

    def __init__(self, scene: Scene, executor: Executor | None = None, progress: bool = False,
                 encode=None):
        self.scene, self.count = scene, scene.case_count
        self.timing_s = 0.0
        self._executor, self._progress, self._encode = executor, progress, encode
        self._speed_warnings = {}           # scene-wide messages, once each
        self._case_warnings = []
        self._per_speed = {}                # speed -> its per-speed fields
        self._results = self._solve()

    @property
    def warnings(self) -> list:
        """The run's warnings so far, a new list (see the class docstring)."""
        return list(self._speed_warnings) + self._case_warnings

    def __iter__(self):
        return itertools.chain.from_iterable(self._results)

    def chunks(self):
        """The results a chunk at a time (lists of :class:`CaseResult`, or of
        :class:`CaseText` with a lean encoder, in scene order): the same run as iterating
        it, for a consumer that takes cases in bulk
        (:meth:`contact.scene.SceneWriter.add_all`)."""
        return self._results

    def _solve(self):
        """The generator behind iteration, a chunk at a time: solve, add the per-speed
        fields, name a failing case, collect warnings, time."""
        per_speed = any(name in SPEED_FIELDS for name in self.scene.fields)
        t0 = time.perf_counter()
        bar = _progress_bar(self.count, self._progress)
        delivered = 0
        try:
            # the per-speed fields join the entries here: then the writers encode them
            fn = run_cases if self._encode is None or per_speed else \
                functools.partial(_solved_and_encoded, self._encode)
            for items in iter_chunks(fn, self.scene, self._executor, bar.update):
                failure = items.pop() if isinstance(items[-1][1], Exception) else None
                results = [res for _, res in items]
                delivered += len(results)
                for res in results:
                    if per_speed:
                        speed = res.entry["inputs"]["speed"]
                        res.entry = _with_speed_fields(res.entry, self._speed_fields(speed),
                                                       self.scene.fields)
                    if res.speed_warnings:     # in scene order, whatever the chunks
                        self._speed_warnings.update(dict.fromkeys(res.speed_warnings))
                self._case_warnings += [f"case {res.index} ({res.label}): {w}"
                                        for res in results for w in res.warnings]
                self.timing_s += time.perf_counter() - t0
                t0 = None                          # the consumer's time is not the run's
                if results:
                    yield results
                t0 = time.perf_counter()
                if failure is not None:                # after the cases before it
                    index, exc = failure
                    with _naming(self.scene.case(index), self.scene):
                        raise exc
            if delivered != self.count:            # a sweep is never cut short silently
                raise RuntimeError(f"{self.scene.source}: {delivered} of {self.count} cases "
                                   "came back from the runner; please report")
        finally:
            bar.close()
            if t0 is not None:
                self.timing_s += time.perf_counter() - t0

    def _speed_fields(self, speed) -> dict:
        """The per-speed fields at ``speed``, computed at its first case (their warnings are
        the run's, once each)."""
        if speed not in self._per_speed:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                self._per_speed[speed] = speed_entry(build_once(self.scene.material), speed,
                                                     self.scene.fields)
            self._speed_warnings.update(dict.fromkeys(
                f"{w.category.__name__}: {w.message}" for w in caught))
        return self._per_speed[speed]


def run_scene(scene: Scene, executor: Executor | None = None, progress: bool = False,
              ) -> SceneResult:
    """Run every case of a scene, in scene order, and keep them all (:func:`iter_scene`, the
    streaming run, collected).

    Parameters
    ----------
    scene : Scene
    executor : concurrent.futures.Executor, optional
        Where cases are solved (a ProcessPoolExecutor, or a Dask ``Client.get_executor()``);
        None: in this process, a chunk at a time.  Results are the same either way.  Cases
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
    run = iter_scene(scene, executor, progress)
    with cyclic_gc_paused():           # the results kept here are what the collector walks
        cases = list(run)
    return SceneResult(scene, cases, run.timing_s, run.warnings)


def _with_speed_fields(entry: dict, per_speed: dict, fields) -> dict:
    """The entry with the per-speed fields in their places among the scene's fields."""
    out = {"inputs": entry["inputs"]}
    out.update((k, entry[k]) for k in SLIP_ENTRY_KEYS if k in entry)
    for name in fields:
        if name in per_speed:
            out[name] = per_speed[name]
        elif name in entry:
            out[name] = entry[name]
        elif name in ZONE_FIELDS and "zones" in entry:
            out["zones"] = entry["zones"]
    return out


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
    """The part of a tqdm bar used here, doing nothing (progress off)."""
    def update(self, n=1):
        pass

    def set_postfix_str(self, s, refresh=True):
        pass

    def close(self):
        pass


def progress_bar(total, enabled, desc, unit, delay):
    """A tqdm bar on stderr that clears itself when done, shown after ``delay`` seconds, or
    one that does nothing when not ``enabled``."""
    if not enabled:
        return _NoBar()
    try:
        from tqdm import tqdm
    except ImportError:                      # tqdm is a dependency; be lenient all the same
        return _NoBar()
    return tqdm(total=total, desc=desc, unit=unit, delay=delay, file=sys.stderr,
                dynamic_ncols=True, leave=False)


def _progress_bar(total, progress):
    """The cases' bar (from one second on; none for a single case)."""
    return progress_bar(total, progress and total >= 2, "cases", "case", 1.0)
