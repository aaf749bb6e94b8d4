"""One block of a singular integral equation: an unknown on its interval and the equation
collocated there (:class:`sie.Equation` is made of them; the solver's stages take them)."""
from __future__ import annotations

from dataclasses import dataclass

from .exponents import Exponents
from .intervals import Interval

__all__ = ["Block"]


@dataclass(frozen=True)
class Block:
    """One block of an :class:`Equation`: the unknown psi_j on the interval L_j and the
    equation collocated there,

        a psi(s) + (b/pi) PV int_L psi(t)/(t - s) dt + int_L k(s, t) psi(t) dt = f(s),
        s in L_j.

    Attributes
    ----------
    interval : Interval
        L_j = [c, d].
    a, b : float
        The coefficients on L_j (b != 0).
    left, right : {"bounded", "singular"}
        psi's behaviour at c and d.
    exponents : Exponents
        alpha (at d), beta (at c) and the index (:func:`sie.sie_exponents`).
    kernel : callable or None
        k(s, t) for s in L_j and t anywhere on L (None: no kernel on this row).

    References
    ----------
    Muskhelishvili, Singular Integral Equations (1953), ch. 10 (the exponents of each end).

    Examples
    --------
    >>> import sie
    >>> blk = sie.Equation(a=0.0, b=1.0, left="bounded", right="bounded").blocks[0]
    >>> (blk.interval.c, blk.interval.d), blk.exponents.kappa
    ((-1.0, 1.0), -1)
    """
    interval: Interval
    a: float
    b: float
    left: str
    right: str
    exponents: Exponents
    kernel: object = None

    @property
    def kappa(self) -> int:
        """The index -(alpha + beta) of the block."""
        return self.exponents.kappa
