"""
A custom punch profile
======================

Any face is a :class:`contact.ProfilePunch`: its slope dv/dX, its height, or both, with the
face's extent and any kinks (``breaks``).  Here a flat punch with rounded corners (a flat
centre of half-width 0.5, circular arcs of radius 5 out to X = +-1): the contact starts on the
flat part and, as the load grows, spreads over the rounded corners without ever reaching the
edges.  The rounded-flat punch has a classical closed form at rest (Ciavarella, Hills &
Monno 1998); at speed and with friction there is none, and the library's checks
(p >= 0, gap >= 0, convergence in n) are what vouch for the answer.
"""
import matplotlib.pyplot as plt
import numpy as np

import contact

b, R = 0.5, 5.0                                   # flat half-width, corner radius


def slope(X):
    """dv/dX: zero on the flat, the circular arc beyond |X| = b."""
    X = np.asarray(X, dtype=float)
    d = np.clip(np.abs(X) - b, 0.0, None)
    return np.sign(X) * d / np.sqrt(R * R - d * d)


face = contact.ProfilePunch(slope, breaks=(-b, b), face=(-1.0, 1.0))
mat = contact.zhou2014()
fig, ax = plt.subplots(figsize=(6.4, 3.8))
for load in (0.002, 0.005, 0.01, 0.02):
    r = contact.solve(mat, face, load=load, speed=0.3, friction=0.2)
    X = np.linspace(-1.0, 1.0, 801)
    ax.plot(X, r.pressure(X), label=f"P = {load}")
    print(f"P = {load:<6} ends ({r.ends[0]:+.5f}, {r.ends[1]:+.5f}), kinds {r.zones[0].kinds}, "
          f"n = {r.n}, residual {r.residual:.1e}, load check {r.load_check:.1e}")
ax.axvspan(-b, b, color="0.9", zorder=0, label="flat part")
ax.set_xlabel("X")
ax.set_ylabel("p(X)")
ax.set_title("rounded flat punch, c = 0.3, mu = 0.2")
ax.legend()
fig.tight_layout()
