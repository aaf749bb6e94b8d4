"""The punch kinds: one entry per kind that a scene (``[punch] kind = ...``) and the ``contact``
command can name.

Each :class:`PunchKind` says which :class:`contact.Punch` subclass it builds, which scene keys
it takes, how a scene's values become the punch, and whether the paper's closed form exists
(the function in :mod:`contact.closed_form`).  The scene parser, the scene runner and the
command line read this table only, so a new punch kind is its class plus one entry in
:data:`KINDS`:

* a kind given by positive dimensions (``form="dimensions"``) needs nothing else: every
  dimension key is a positive number or a list of them (a sweep), a case input, and a keyword
  of the class (``cls(**{key: value})``);
* the profile (``form="profile"``) has its own keys (slope, height, pieces, data, ...), read by
  the scene parser's profile reader and built by :func:`build_profile`.

The plain-data carriers a profile is built from (:class:`Piece`, :class:`Samples`,
:class:`PolynomialSlope`, :class:`PiecewiseSlope`) live here too: they are picklable, so a
case travels to worker processes and Dask workers and is rebuilt there.
"""
from __future__ import annotations

import importlib
import sys
from dataclasses import dataclass
from typing import Callable, Optional

import numpy as np
from numpy.polynomial.polynomial import polyval

from contact import (CylindricalPunch, FlatPunch, ParabolicPunch, ProfilePunch, Punch,
                     TriangularPunch)

__all__ = ["PunchKind", "KINDS", "PROFILE_SHAPE_KEYS", "INTERPOLANTS", "Piece", "Samples",
           "PolynomialSlope", "PiecewiseSlope", "build_profile", "import_callable",
           "closed_form_kinds"]

#: The profile keys that give the shape of the face (data and pieces stand alone; slope and
#: height may go together).
PROFILE_SHAPE_KEYS = ("slope", "height", "pieces", "data")
#: Interpolants of a tabulated face (``contact.samples.face_from_samples``'s ``kind``).
INTERPOLANTS = ("quintic", "cubic")


@dataclass(frozen=True)
class PunchKind:
    """One punch kind.

    Attributes
    ----------
    name : str
        The scene's ``kind = "..."``.
    cls : type
        The :class:`contact.Punch` subclass built.
    form : {"dimensions", "profile"}
        How the scene gives it: positive dimensions, or the profile keys.
    keys : tuple of str
        Every scene key of the kind besides ``kind``.
    dimensions : tuple of str
        The positive-number keys: each sweepable, a case input and a keyword of ``cls``.
    closed_form : str or None
        The function of :mod:`contact.closed_form` that solves it in closed form
        (``numerics.method = "closed_form"``), or None.
    summary : str
        One line for listings (``contact punches``).
    """
    name: str
    cls: type
    form: str
    keys: tuple
    dimensions: tuple = ()
    closed_form: Optional[str] = None
    summary: str = ""

    def build(self, values: dict, base_dir: Optional[str] = None) -> Punch:
        """The punch from a scene's values for one case.

        Parameters
        ----------
        values : dict
            Scene key -> parsed value (numbers, tuples, :class:`Piece`, :class:`Samples`,
            "module:function" strings); keys the scene did not give are absent.
        base_dir : str, optional
            Searched first when importing a "module:function" (the scene file's directory).

        Returns
        -------
        contact.Punch
        """
        if self.form == "profile":
            return build_profile(values, base_dir)
        return self.cls(**{key: values[key] for key in self.dimensions})



_PROFILE_KEYS = ("slope", "height", "pieces", "data", "interpolant", "breaks", "corners", "face")

#: Every punch kind, by its scene name, in the order they are documented.
KINDS = {k.name: k for k in (
    PunchKind("flat", FlatPunch, "dimensions", ("half_width",), ("half_width",),
              "flat_closed_form", "flat face of half-width a, sharp corners at +-a (index 1)"),
    PunchKind("triangular", TriangularPunch, "dimensions", ("slope",), ("slope",),
              "triangular_closed_form", "wedge v = m0 X, sharp corner at X = 0 (index 0)"),
    PunchKind("parabolic", ParabolicPunch, "dimensions", ("radius",), ("radius",),
              "parabolic_closed_form", "v = X^2/(2R), sharp corner at X = 0 (index 0)"),
    PunchKind("cylindrical", CylindricalPunch, "dimensions", ("radius",), ("radius",),
              "cylindrical_closed_form", "v = X^2/(2R), both ends free (index -1)"),
    PunchKind("profile", ProfilePunch, "profile", _PROFILE_KEYS, (), None,
              "any face: slope or height (polynomial, pieces, module:function) or tabulated "
              "samples (data); contact found from first touch, several zones possible"),
)}


def closed_form_kinds() -> tuple:
    """The kinds with a closed form, in :data:`KINDS` order."""
    return tuple(name for name, k in KINDS.items() if k.closed_form is not None)


# --------------------------------------------------------------------------
# plain data a profile is built from
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class Piece:
    """One polynomial piece of a piecewise slope: dv/dX = sum c_k X^k on [start, stop)."""
    start: float              # -inf for the first piece
    stop: float               # +inf for the last piece
    coefficients: tuple


@dataclass(frozen=True, repr=False)
class Samples:
    """A tabulated face: the samples (X_i, h_i) read from ``source`` (the scene's ``data``
    value as written; ``path`` the file read)."""
    source: str
    path: str
    X: tuple
    h: tuple

    def __repr__(self):
        return f"Samples({self.source!r}, {len(self.X)} samples)"


@dataclass(frozen=True)
class PolynomialSlope:
    """dv/dX = sum c_k X^k (coefficients low to high)."""
    coefficients: tuple

    def __call__(self, X):
        X = np.asarray(X, dtype=float)
        return polyval(X, self.coefficients) + np.zeros_like(X)


@dataclass(frozen=True)
class PiecewiseSlope:
    """dv/dX given by polynomial pieces joined at ``joins`` (the first and last pieces extend
    to -inf and +inf)."""
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


def build_profile(values: dict, base_dir: Optional[str] = None) -> ProfilePunch:
    """A :class:`contact.ProfilePunch` from a scene's profile values.

    Parameters
    ----------
    values : dict
        ``data`` (:class:`Samples`, with optional ``interpolant`` and ``face``), or any of
        ``slope`` (coefficient tuple or "module:function"), ``height`` ("module:function"),
        ``pieces`` (tuple of :class:`Piece`), with optional ``breaks``, ``corners``
        (None for a free side) and ``face`` ((X_min, X_max)).
    base_dir : str, optional
        Searched first when importing a "module:function".

    Returns
    -------
    contact.ProfilePunch
    """
    face = values.get("face")
    data = values.get("data")
    if data is not None:
        return ProfilePunch.from_samples(np.array(data.X), np.array(data.h),
                                         kind=values.get("interpolant", INTERPOLANTS[0]),
                                         face=face)
    pieces = values.get("pieces", ())
    joins = tuple(p.start for p in pieces[1:])
    if pieces:
        slope = PiecewiseSlope(joins, tuple(p.coefficients for p in pieces))
    elif isinstance(values.get("slope"), str):
        slope = import_callable(values["slope"], base_dir)
    elif values.get("slope") is not None:
        slope = PolynomialSlope(tuple(values["slope"]))
    else:
        slope = None
    height = values.get("height")
    if height is not None:
        height = import_callable(height, base_dir)
    breaks = tuple(sorted(set(values.get("breaks", ())) | set(joins)))
    return ProfilePunch(slope, breaks=breaks, corners=values.get("corners", (None, None)),
                        height=height, face=face)


def import_callable(spec: str, base_dir: Optional[str] = None) -> Callable:
    """The function named by "module:function" (``base_dir`` searched first).

    Raises
    ------
    ImportError, AttributeError
        The module or the name in it does not exist.
    TypeError
        The name is not callable.
    """
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
