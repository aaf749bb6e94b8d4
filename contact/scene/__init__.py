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

from .output import format_table, write_outputs
from .parse import default_scene, load_scene, parse_scene_text
from .run import CaseResult, SceneResult, run_case, run_scene
from .spec import (CURVE_FIELDS, DEFAULT_SCENE_TOML, FIELDS, CaseError, Case, MaterialSpec,
                   Numerics, PunchSpec, Scene, SceneError, XGrid)

__all__ = ["SceneError", "CaseError", "Scene", "Case", "CaseResult", "SceneResult", "MaterialSpec",
           "PunchSpec", "XGrid", "Numerics", "load_scene", "parse_scene_text", "default_scene",
           "run_scene", "run_case", "write_outputs", "format_table", "DEFAULT_SCENE_TOML",
           "FIELDS", "CURVE_FIELDS"]
