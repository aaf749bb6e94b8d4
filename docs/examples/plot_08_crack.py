"""
The sie solver on a crack problem: two collinear cracks
=======================================================

:mod:`sie` knows no mechanics; a crack is one more equation of the same family.  A crack on
:math:`L` in an infinite plane, its faces loaded by a pressure :math:`\\sigma`, is described by a
dislocation density :math:`\\psi` with

.. math::

   \\frac{1}{\\pi}\\,\\mathrm{PV}\\!\\int_L \\frac{\\psi(t)}{t - s}\\,dt = 1, \\qquad
   \\int_{\\text{each crack}} \\psi = 0,

singular at every tip (a = 0, b = 1: the first kind, index 1 on each crack).  The
stress intensity factor at a tip follows from :math:`\\phi` there:
:math:`K/\\sigma = \\sqrt{\\pi h}\\,|\\phi(\\pm 1)|`, h the crack's half-length.  For one crack
[-1, 1] this gives Griffith's :math:`K = \\sigma\\sqrt{\\pi a}` exactly.  For two equal
collinear cracks :math:`b \\le |x| \\le c` Westergaard's stress function gives the closed form
(Tada, Paris & Irwin, *The Stress Analysis of Cracks Handbook*), with
:math:`k^2 = 1 - b^2/c^2` and :math:`\\lambda^2 = c^2 E(k)/K(k)`:

.. math::

   K_c = \\sigma\\sqrt{\\pi / c}\\;\\frac{c^2 - \\lambda^2}{\\sqrt{c^2 - b^2}}, \\qquad
   K_b = \\sigma\\sqrt{\\pi / b}\\;\\frac{\\lambda^2 - b^2}{\\sqrt{c^2 - b^2}}.
"""
import warnings

import matplotlib.pyplot as plt
import numpy as np
from scipy.special import ellipe, ellipk

import sie

one = sie.solve(lambda s: np.ones_like(s), a=0.0, b=1.0, n=8, left="singular",
                right="singular", total=0.0)
print(f"one crack: K / (sigma sqrt(pi a)) = {one.endpoint_value(+1):.15f} (exact: 1)")


def two_cracks(b, c=1.0, n=96):
    """(K at the outer tip, K at the inner tip) / sigma, from sie.solve."""
    sol = sie.solve(lambda s: np.ones_like(s), a=0.0, b=1.0, n=n, left="singular",
                    right="singular", total=(0.0, 0.0), intervals=[(-c, -b), (b, c)])
    h = 0.5 * (c - b)
    return (np.sqrt(np.pi * h) * abs(sol.endpoint_value(+1, interval=1)),
            np.sqrt(np.pi * h) * abs(sol.endpoint_value(-1, interval=1)))


def westergaard(b, c=1.0):
    m = 1.0 - (b / c) ** 2
    lam2 = c * c * ellipe(m) / ellipk(m)
    return (np.sqrt(np.pi / c) * (c * c - lam2) / np.sqrt(c * c - b * b),
            np.sqrt(np.pi / b) * (lam2 - b * b) / np.sqrt(c * c - b * b))


bs = np.linspace(0.02, 0.95, 40)
num = np.array([two_cracks(b) for b in bs])
ref = np.array([westergaard(b) for b in bs])
print(f"two cracks, b/c in [{bs[0]}, {bs[-1]}], n = 96 per crack: max relative difference "
      f"from Westergaard {np.max(np.abs(num / ref - 1)):.1e}")
# the closer the inner tips, the more coefficients the solution needs near them
# (sie warns when n does not resolve the solution between the nodes)
for n in (24, 48, 96):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        d = np.max(np.abs(np.array(two_cracks(0.02, n=n)) / westergaard(0.02) - 1))
    names = ", ".join(sorted({w.category.__name__ for w in caught}))
    print(f"  b/c = 0.02, n = {n:2d}: {d:.1e} {names}")

h = 0.5 * (1.0 - bs)
fig, ax = plt.subplots(figsize=(6.4, 3.8))
ax.plot(bs, num[:, 0] / np.sqrt(np.pi * h), label="outer tip (sie.solve)")
ax.plot(bs, num[:, 1] / np.sqrt(np.pi * h), label="inner tip (sie.solve)")
ax.plot(bs[::3], ref[::3, 0] / np.sqrt(np.pi * h[::3]), "ko", ms=3, label="Westergaard")
ax.plot(bs[::3], ref[::3, 1] / np.sqrt(np.pi * h[::3]), "ko", ms=3)
ax.axhline(1.0, color="0.6", ls=":")
ax.set_xlabel("b / c (inner tip / outer tip)")
ax.set_ylabel(r"$K / \sigma\sqrt{\pi h}$")
ax.set_title("two collinear cracks: interaction raises both SIFs")
ax.legend()
fig.tight_layout()
