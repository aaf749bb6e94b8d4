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

    [outputs]             # fields: ends exponents sif zones pressure shear sigma_xx roots constants
    fields = ["ends", "exponents", "pressure", "sigma_xx", "sif"]
    x = { start = -0.8, stop = 0.8, num = 801 }   # where curves are sampled

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

**Several contact zones**: the contact is found from first touch, so a face with several
valleys can touch in several zones.  A case with one zone writes ``ends``, ``exponents`` and
``sif`` as they are; a case with several writes, in their place, ``zones``: one entry per
zone, left to right, ``{"ends": [xl, xr], "kinds": ["free" | "corner", ...], "exponents":
{"left": beta, "right": alpha}, "index": kappa, "load": its share of the load}`` (and
``"sif"`` per zone when ``sif`` is asked).  Ask for ``"zones"`` to get that list for every
case.  The table adds a ``zones`` column and shows the outer ends; the figures mark every
zone.

**Sweeps**: any scalar under [motion], and a punch's dimensions (``half_width``, ``slope``,
``radius``), may be a list of values (a profile's lists -- ``slope``, ``breaks``, ``corners``,
``face`` -- are data, not sweeps).  The scene runs the Cartesian product, the key met first in
the file varying slowest.

**Only what is asked is computed**: curves are sampled only for the requested fields
(sigma_XX only with ``"sigma_xx"``), the characteristic roots and surface constants for the
``"roots"``/``"constants"`` fields once per speed, shared by every case at that speed.

**Errors**: every problem with a scene is a :class:`SceneError` (a ``ValueError``) naming the
file, the key and what is allowed, raised by :func:`load_scene` before anything is solved.
"""
from __future__ import annotations

from .output import format_table, write_outputs
from .parse import default_scene, load_scene, parse_scene_text
from .run import CaseResult, SceneResult, run_case, run_scene
from .spec import (CURVE_FIELDS, DEFAULT_SCENE_TOML, FIELDS, CaseError, Case, MaterialSpec,
                   Numerics, PunchSpec, Scene, SceneError, XGrid)

__all__ = ["SceneError", "CaseError", "Scene", "Case", "CaseResult", "SceneResult", "MaterialSpec",
           "PunchSpec", "XGrid", "Numerics", "load_scene", "parse_scene_text", "default_scene",
           "run_scene", "run_case", "write_outputs", "format_table", "DEFAULT_SCENE_TOML",
           "FIELDS", "CURVE_FIELDS"]
