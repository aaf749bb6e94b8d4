"""Exceptions and warnings raised by :mod:`contact`.

Every exception is a ``ValueError`` subclass whose message names the offending argument, the
value received and what is allowed.
"""
from __future__ import annotations

from sie.errors import check_finite_real

__all__ = [
    "ContactInputError",
    "MaterialError",
    "SpeedError",
    "LoadError",
    "FrictionError",
    "DirectionError",
    "PunchGeometryError",
    "ProfileCallableError",
    "ContactLossError",
    "StressPointError",
    "UnboundedStressError",
    "NearRayleighWarning",
    "check_finite",
]


class ContactInputError(ValueError):
    """Base class: an argument of a :mod:`contact` function is not admissible."""


class MaterialError(ContactInputError):
    """Stiffnesses not finite, or not positive definite; density not positive."""


class SpeedError(ContactInputError):
    """Relative speed negative, not finite, or not below the Rayleigh speed c_R."""


class LoadError(ContactInputError):
    """Load not finite or not positive."""


class FrictionError(ContactInputError):
    """Friction coefficient negative or not finite."""


class DirectionError(ContactInputError):
    """Direction of sliding not -1 or +1."""


class PunchGeometryError(ContactInputError):
    """Non-positive or non-finite punch dimension, or an inconsistent corner/break."""


class ProfileCallableError(ContactInputError):
    """A user slope callable returned the wrong shape or a non-finite value."""


class ContactLossError(ContactInputError):
    """The profile and load admit no single contact zone with p >= 0 (contact lost inside,
    or two separate zones would be needed)."""



class StressPointError(ContactInputError):
    """A point where the stress is asked for is not finite or lies outside the half-space
    Y <= 0."""


class UnboundedStressError(ContactInputError):
    """A stress extremum asked for in a region that holds a singular contact end (where the
    stresses are infinite)."""

class NearRayleighWarning(UserWarning):
    """Speed within 1% of the Rayleigh speed: results valid but extremely sensitive to c."""


def check_finite(name: str, value, error=ContactInputError) -> float:
    """Return ``value`` as a float, or raise ``error`` naming ``name`` if it is not a finite real
    (:func:`sie.errors.check_finite_real`, with the contact layer's base error as default)."""
    return check_finite_real(name, value, error)
