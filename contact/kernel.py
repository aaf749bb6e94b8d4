"""The regular kernel a material adds to the contact equations (a layer, a coating).

A material may give, besides the constants of its half-space, the regular part of its
surface response (:class:`contact.SurfaceKernel`, from its optional ``surface_kernel(c)``).
The contact equation on the zones L is then (the conventions of the documentation, Theory:
the contact model and its conventions; q = mu_f p)

    a p(X) + (b/pi) PV int_L p(t)/(t - X) dt + int_L k(X, t) p(t) dt = H'(X),

    a = N12 mu_f, b = N11 + M12 mu_f, k = k_p + mu_f k_q,

and the gap g = H - v - v_0 between and outside the zones gains -int_L (K(X, t) - K(X0, t))
p(t) dt against a point X0 where it is known, K the antiderivative of k in X.  A material
without one (``surface_kernel`` absent, or returning None) is a homogeneous half-space, and
the equations take their kernel-free paths (one-zone functionals, the lockstep first step,
the convex face that opens by itself).
"""
from __future__ import annotations

from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

import sie

from .errors import ContactInputError, MaterialError
from .protocol import call, describe_call

__all__ = ["ContactKernel", "contact_kernel", "own_errors"]


def contact_kernel(material, c, mu_f):
    """The :class:`ContactKernel` of ``material`` at the relative speed ``c`` and signed
    friction ``mu_f``, or None when the material has no surface kernel.

    Raises
    ------
    MaterialError
        ``surface_kernel`` is not callable, raises, or returns something without the
        callables ``slope`` and ``deflection`` (or, with friction, ``shear_slope`` and
        ``shear_deflection``).
    """
    method = getattr(material, "surface_kernel", None)
    if method is None:
        return None
    where = describe_call(material, "surface_kernel", c)
    if not callable(method):
        raise MaterialError(f"{type(material).__name__}.surface_kernel must be a method "
                            f"c -> contact.SurfaceKernel or None, got "
                            f"{type(method).__name__}")
    source = call(material, "surface_kernel", c)
    if source is None:
        return None
    needed = ("slope", "deflection") + (("shear_slope", "shear_deflection") if mu_f else ())
    missing = [name for name in needed if not callable(getattr(source, name, None))]
    if missing:
        why = (" (the contact has friction: q = mu_f p loads the surface too; give them, "
               "zero where the tangential traction does not couple)"
               if set(missing) & {"shear_slope", "shear_deflection"} else "")
        raise MaterialError(
            f"{where} must return a contact.SurfaceKernel (callables slope(X, t) and "
            f"deflection(X, t)) or None; got {type(source).__name__}, which lacks "
            f"{', '.join(missing)}{why}")
    return ContactKernel(source, float(mu_f), where)


@dataclass(frozen=True, eq=False)
class ContactKernel:
    """k(X, t) = k_p + mu_f k_q and its antiderivative K in X, of one problem (a material at
    one speed, one signed friction), each value checked.  Hashed by identity: the cached
    equations of the zones (:func:`contact.zones._equation`) key on it."""
    source: object              # the material's SurfaceKernel
    mu_f: float
    where: str                  # 'Class.surface_kernel(c)', for the messages

    def slope(self, X, t):
        """k(X, t) (float arrays of one shape)."""
        return self._combined("slope", "shear_slope", X, t)

    def deflection(self, X, t):
        """K(X, t), dK/dX = k."""
        return self._combined("deflection", "shear_deflection", X, t)

    def sigma_xx(self, X, t):
        """sigma_XX at (X, 0) per unit pressure at t (beyond the half-space's).

        Raises
        ------
        ContactInputError
            The material's kernel gives no ``sigma_xx`` (or, with friction, no
            ``shear_sigma_xx``)."""
        for name in ("sigma_xx",) + (("shear_sigma_xx",) if self.mu_f else ()):
            if not callable(getattr(self.source, name, None)):
                raise ContactInputError(
                    f"sigma_XX on the surface needs the {name}(X, t) of the material's "
                    f"surface kernel ({self.where}), which it does not give")
        return self._combined("sigma_xx", "shear_sigma_xx", X, t)

    def _combined(self, normal, shear, X, t):
        out = self._value(normal, X, t)
        if self.mu_f:
            out = out + self.mu_f * self._value(shear, X, t)
        return out

    def _value(self, name, X, t):
        """source.<name>(X, t), checked: real, finite, of the points' shape."""
        where = f"{self.where}.{name}(X, t)"
        try:
            value = getattr(self.source, name)(X, t)
        except ContactInputError:
            raise
        except Exception as exc:            # a user's kernel: any failure is named
            raise MaterialError(f"{where} raised {type(exc).__name__}: {exc}") from exc
        try:
            value = np.broadcast_to(np.asarray(value), np.shape(X))
        except ValueError:
            raise MaterialError(f"{where} must return values of the points' shape "
                                f"{np.shape(X)}, got shape {np.shape(value)}") from None
        if value.dtype.kind not in "fiu":
            raise MaterialError(f"{where} must return real numbers, got dtype {value.dtype}")
        value = value.astype(float, copy=False)
        bad = ~np.isfinite(value)
        if bad.any():
            i = np.unravel_index(int(np.argmax(bad)), value.shape)
            raise MaterialError(f"{where} is not finite ({value[i]!r}) at X = "
                                f"{float(np.asarray(X)[i])!r}, t = {float(np.asarray(t)[i])!r}")
        return value


@contextmanager
def own_errors():
    """A :class:`~contact.ContactInputError` raised inside a call of :mod:`sie` passes as
    itself: sie's checks of the callables it is given (the kernel, the slope) report any
    exception inside them as a :class:`sie.SIEInputError` chained to it, and the contact's
    own (a kernel's :class:`~contact.MaterialError`, a slope's
    :class:`~contact.ProfileCallableError`) already name what was wrong."""
    try:
        yield
    except sie.SIEInputError as exc:
        cause = exc.__cause__
        while cause is not None and not isinstance(cause, ContactInputError):
            cause = cause.__cause__ if isinstance(cause, sie.SIEInputError) else None
        if cause is not None:
            raise cause from cause.__cause__
        raise
