"""Scenes: a contact problem (or a sweep of them) described in a TOML file, run, and written out.

A scene names a material, a punch, the motion, what to compute and, optionally, numerics::

    title = "cylindrical punch"           # optional; used in figures and the table

    [material]            # Zhou et al. 2014, eq. (2.2); any consistent stress unit
    C11 = 159.7885        # or: preset = "zhou2014" (the paper's material, GPa)
    C12 = 5.2609
    C22 = 15.4732
    C33 = 5.52
    # rho = 1.6e-6        # only needed when [motion] gives velocity instead of speed
    # factory = "mymaterials:layered"      # instead of the stiffnesses: a material of one's
    # arguments = { h = 0.1 }              # own (contact.Material) from module:function

    # [punch_material]    # optional: an elastic punch of this material (the keys of
    # preset = "zhou2014" # [material], no factory); without it the punch is rigid

    [punch]
    kind = "cylindrical"  # flat | triangular | parabolic | cylindrical | profile
    radius = 100.0        # flat: half_width; triangular: slope (m0); parabolic, cylindrical: radius

    [motion]
    load = 0.01           # P > 0, force per unit length (stress unit x length unit)
    speed = 0.6           # relative speed c = V / sqrt(C33/rho), 0 <= c < c_R (default 0)
    # velocity = 1.2      # instead of speed: V, converted with material.rho
    friction = 0.3        # mu >= 0 (default 0)
    direction = -1        # -1: slides toward -X (trailing edge on the right), +1: toward +X
    # tangential_load = [0.001, 0.003]   # partial slip (Cattaneo) under Q, abs(Q) < mu P;
    # rolling = true      # steady rolling (Carter) toward direction, with tangential_load
    # creepage = -0.01    # or the creepage instead (rolling only); see below

    [outputs]             # fields: ends exponents sif zones pressure shear sigma_xx roots constants
                          #         subsurface
    fields = ["ends", "exponents", "pressure", "sigma_xx", "sif"]
    x = { start = -0.8, stop = 0.8, num = 801 }   # where curves are sampled
    # grid = { x = { start = -1, stop = 1, num = 161 }, y = { start = -1.5, stop = 0, num = 121 } }
    #                   # where the "subsurface" field is mapped (Y <= 0); optional, see below
    # figures = false   # no PNG figures (as `contact run --no-figures`); default true

    [numerics]            # optional
    method = "numeric"    # or "closed_form" (the four classical punches only)
    n = 64                # fixed number of Jacobi coefficients; or tol = 1e-12 (adaptive n)

The punch kinds and their keys are those of :data:`contact.registry.KINDS` (``contact punches``
lists them).

**Custom punches** (``kind = "profile"``) give the face in one of these ways:

* ``slope = [a0, a1, a2, ...]``: polynomial coefficients, low to high: dv/dX = a0 + a1 X + ...
* ``slope = "module:function"``: a vectorised Python function of X (the scene file's directory is
  searched first when importing ``module``).
* ``height = "module:function"``: the height v(X) instead (its slope by finite differences), or
  together with ``slope`` (the height then gives the gap between zones exactly).
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

* ``data = "face.csv"``: measured samples, two columns X, h (comma or whitespace separated; a
  header line and ``#`` comment lines are skipped), at least 4 rows, X increasing; the path is
  relative to the scene file.  ``interpolant = "quintic"`` (default) or ``"cubic"``
  (:func:`contact.samples.face_from_samples`).  The samples are read when the scene is loaded
  and travel with each case.

plus ``breaks = [X, ...]`` (kinks of the face), ``corners = [left, right]``: the X of a sharp
corner that ends the face on that side, or ``"free"`` (TOML has no null; ``"free"`` is the
default on both sides), and ``face = [X_min, X_max]``: the extent of the face (the default of
a tabulated face is its samples' extent, which ``face`` may narrow).  Contact cannot go beyond
the face: an end that reaches an edge becomes a sharp corner (singular pressure).  A tabulated
face takes neither ``breaks`` (the spline's knots are handled by the interpolant) nor
``corners`` (its edges are ``face``).

**What a run writes** (:func:`write_outputs`, ``contact run --out DIR``):

* ``result.json``: the scene after defaults, and per case ``inputs``, the requested fields
  in the scene's order and ``diagnostics = {"n": Jacobi coefficients per zone, "residual":
  the relative residual of the dominant equation, "load_check": |int p dX - P| / P}``
  (:class:`contact.ContactResult`).  ``ends`` is ``[x_left, x_right]``, ``exponents`` is
  labelled by end, ``{"left": beta, "right": alpha}`` (p ~ (X - x_left)^beta,
  p ~ (x_right - X)^alpha), ``sif`` is ``{"left": K, "right": K}`` at singular ends only.
  A curve is ``{"x": [...], "values": [...]}`` (null where it is infinite: a singular end);
  its x are the grid's clean decimals (-0.8, -0.798, ..., 0.3, not 0.30000000000000004:
  :func:`contact.scene.spec.clean_linspace`), the very numbers the curve was sampled at.
* ``sweep.csv``: the tidy table, one row per case in scene order: ``case``, the inputs that
  vary (every input for a single case), then every requested scalar -- ``x_left``,
  ``x_right``, ``alpha``, ``beta``, ``kappa``, ``K_left``, ``K_right`` (one zone), or
  ``zones`` and ``zone1_x_left``, ..., ``zone{j}_K_right`` (several), the subsurface extrema
  (``max_shear``, ``max_shear_X``, ..., ``max_tension_depth_over_a``), the constants and
  roots -- and ``n``, ``residual``, ``load_check`` (the columns: :mod:`contact.scene.table`).
  Numbers as Python's repr, empty cells where a value is missing (a free end has no SIF):
  ``pandas.read_csv("sweep.csv")``, or :meth:`SceneResult.to_dataframe` in Python (needs the
  ``pandas`` extra: ``pip install 'sie-contact[pandas]'``).
* one CSV per curve field (a column X, one column per case), and its PNG figure: one case
  plotted alone, a sweep as a family coloured by its first swept input (viridis, with a
  colour bar; at most 200 curves, evenly spaced, the title says so; the full data is in the
  CSV).  ``figures = false`` or ``--no-figures``: no PNGs.
* the run's warnings (in result.json and on stderr), e.g. a case whose contact is wider than
  the ``[outputs] x`` grid (its curves miss part of the contact), named by case.

``--out`` must be a writable directory (or creatable); ``contact run`` checks it before
solving anything and exits with status 2 otherwise.  It prints a table of the cases (the
first and the last 20 of a longer sweep, and each column's smallest and largest value).

**Long sweeps** run in bounded memory: ``contact run`` builds the cases as they are needed
(:meth:`Scene.iter_cases`), solves a bounded number ahead (:func:`iter_scene`, in scene order
as they complete, serially or through a pool) and writes each as it comes
(:class:`SceneWriter`: result.json case by case, sweep.csv and the curve CSVs through spool
files on disk, only the cases the figures draw kept); the outputs appear in ``--out`` when
every case is done, and a case that fails leaves none.  :func:`run_scene` keeps every case
(:class:`SceneResult`) for use in Python.

**Several contact zones**: the contact is found from first touch, so a face with several
valleys can touch in several zones.  A case with one zone writes ``ends``, ``exponents`` and
``sif`` as they are; a case with several writes, in their place, ``zones``: one entry per
zone, left to right, ``{"ends": [xl, xr], "kinds": ["free" | "corner", ...], "exponents":
{"left": beta, "right": alpha}, "index": kappa, "load": its share of the load}`` (and
``"sif"`` per zone when ``sif`` is asked).  Ask for ``"zones"`` to get that list for every
case.  The table adds a ``zones`` column and shows the outer ends; sweep.csv has a
``zones`` column and columns per zone (``zone{j}_...``); the figures mark every zone.

**The field under the surface** (``"subsurface"``, computed only when asked): the plane
stresses sigma_xx, sigma_yy, sigma_xy (tension positive, stress unit S) of
:meth:`contact.ContactResult.stress` mapped on a grid of the half-space Y <= 0 (the moving
frame), with the in-plane maximum shear and the largest tension sigma_1 derived from them.
The grid is ``[outputs] grid = { x = {start, stop, num}, y = {start, stop, num} }``
(2 <= num <= 10000, start < stop, y.stop <= 0, nx * ny <= 4e6); either axis may be left out.
By default, per case, scaled to its contact (x_left, x_right the outer ends of its zones,
a the largest zone's half-width): X from x_left - a to x_right + a (161 points) and Y from
-3 a up to the surface Y = 0 (121 points).  A grid point on Y = 0 that is exactly a singular (corner)
contact end, where the stresses are infinite, is NaN (as the curve fields are there); every
other point is finite.  result.json gets, per case, ``subsurface = {"max_shear": {value, X, Y,
depth, half_width, depth_over_a}, "max_tension": {...}, "region": {"x": [X0, X1], "y": [Y0,
Y1]}, "grid": {"x": {start, stop, num}, "y": {...}}}``: the largest max shear and tension in
``region`` (:meth:`contact.ContactResult.stress_extrema`), which is the grid's extent except
that, when the grid's top row is the surface and a singular end lies in its X range, Y1 is
lowered to -1e-3 a (the stresses grow without bound toward a corner: such an extremum lies on
that cut next to the corner, and the corner itself is characterised by its SIFs).  The maps go
to ``subsurface.npz`` (keys ``cases``, ``labels``, and per case ``case{i}/x``, ``case{i}/y``
(1-D) and ``case{i}/sigma_xx``, ``sigma_yy``, ``sigma_xy``, ``max_shear``, ``max_tension``
((ny, nx) arrays, ``[k, j]`` at (x[j], y[k]))) and ``subsurface.csv`` (long format: columns
case, X, Y, sigma_xx, sigma_yy, sigma_xy, max_shear, max_tension, one row per point); the
figures ``subsurface_max_shear.png`` and ``subsurface_sigma_xx.png`` are filled contour maps,
one panel per case (at most 6: a longer sweep shows 6 evenly spaced cases and says so in the
title), with the contact zones drawn on the surface and the extremum marked.  The table adds
``max shear @ depth/a``.

**Sweeps**: any scalar under [motion], and a punch's dimensions (``half_width``, ``slope``,
``radius``), may be a list of values (a profile's lists -- ``slope``, ``breaks``, ``corners``,
``face`` -- are data, not sweeps).  The scene runs the Cartesian product, the key met first in
the file varying slowest.

**Partial slip and steady rolling** (:mod:`contact.partial_slip`): ``[motion]
tangential_load = Q`` pulls the contact, pressed by the load, with Q (the traction's
resultant on the half-space, abs(Q) < friction * load) in partial slip (Cattaneo); with
``rolling = true`` (default false) the bodies roll steadily toward ``direction`` (Carter),
under ``tangential_load`` or ``creepage`` (one of them: the other follows).  Both may be
lists (a sweep, e.g. a traction curve over Q).  Such a case is :func:`contact.solve` with
``tangential_load``/``creepage``/``rolling`` and the built ``[punch_material]``, one case at
a time (not in a batch).  Only pairs whose normal and tangential problems decouple are
allowed (one material at rest: ``[punch_material]`` = ``[material]``, speed 0); another pair,
abs(Q) >= mu P, a creepage beyond full slip, friction 0 fail that case when it is solved
(a :class:`CaseError` naming it and the library's error, e.g. ``CoupledPartialSlipError``).
The parser refuses, by key: ``creepage`` without ``rolling = true`` (``motion.creepage``),
``rolling = true`` without either (``motion.rolling``), both together
(``motion.creepage``), a value that is not a number (``motion.tangential_load[k]``, ...),
and a ``rolling`` that is not a boolean.  The case's inputs carry the one given (and
``rolling = true``); its entry adds, after the inputs, ``tangential_load`` (Q),
``creepage`` (the creepage; null for a static contact) and ``stick_zones`` (``[[lo, hi],
...]``).  ``ends``, ``exponents``, ``sif``, ``zones``, ``pressure`` and the diagnostics are
those of the contact at the load (the pressure is the frictionless one, the pair
decoupling); ``shear`` is the tangential traction q, and ``sigma_xx`` and ``"subsurface"``
are the partial slip's fields (by superposition).  sweep.csv and the printed table have
``tangential_load`` and (rolling) ``creepage`` (an input column where swept or given, else
the one that follows), the number of stick zones and the ends of their span
(``stick_x_left``, ``stick_x_right``; :mod:`contact.scene.table`): a traction curve is a
sweep over either.

**Only what is asked is computed**: curves are sampled only for the requested fields
(sigma_XX only with ``"sigma_xx"``, the field under the surface only with ``"subsurface"``),
the characteristic roots and surface constants for the ``"roots"``/``"constants"`` fields once
per speed, shared by every case at that speed.

**Errors**: every problem with a scene is a :class:`SceneError` (a ``ValueError``) naming the
file, the key and what is allowed, raised by :func:`load_scene` before anything is solved.
"""
from __future__ import annotations

from .output import SceneWriter, check_out_dir, stale_outputs, write_outputs
from .summary import format_table
from .parse import default_scene, load_scene, parse_scene_text
from .run import (CaseResult, SceneResult, SceneRun, SubsurfaceMap, iter_scene, run_case,
                  run_cases, run_scene)
from .table import CaseText
from .spec import (CURVE_FIELDS, DEFAULT_SCENE_TOML, FIELDS, CaseError, Case, MaterialSpec,
                   Numerics, PunchSpec, Scene, SceneError, SubsurfaceGrid, XGrid)

__all__ = ["SceneError", "CaseError", "Scene", "Case", "CaseResult", "CaseText", "SceneResult",
           "SceneRun",
           "MaterialSpec", "PunchSpec", "XGrid", "SubsurfaceGrid", "SubsurfaceMap", "Numerics",
           "load_scene", "parse_scene_text", "default_scene", "run_scene", "iter_scene",
           "run_case", "run_cases", "write_outputs", "SceneWriter", "check_out_dir",
           "stale_outputs", "format_table",
           "DEFAULT_SCENE_TOML", "FIELDS", "CURVE_FIELDS"]
