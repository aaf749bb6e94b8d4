"""
Two contact zones and their merge along a load curve
====================================================

A W-shaped face first touches at its two lowest points.  Two zones grow from them; the gap
between them closes at a load P*, where they merge into one.  :func:`contact.load_curve`
follows the zones from first touch through the loads and records the events.
"""
import matplotlib.pyplot as plt
import numpy as np

import contact

w = contact.ProfilePunch(lambda X: 0.2 * X * (X * X - 1.0),
                         height=lambda X: 0.05 * (X * X - 1.0) ** 2, face=(-2.0, 2.0))
mat = contact.zhou2014()
loads = np.geomspace(1e-4, 3.0, 40)
curve = contact.load_curve(mat, w, loads, speed=0.3, friction=0.1)
for e in curve.events:
    print(f"{e.kind} at P* = {e.load:.8f} (zone {e.zone})")

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.8))
for P, res in zip(loads, curve):
    for z in res.zones:
        ax1.plot([P, P], z.ends, color="C0" if len(res.zones) == 2 else "C1", lw=2)
for e in curve.events:
    ax1.axvline(e.load, color="0.5", ls=":")
ax1.set_xscale("log")
ax1.set_xlabel("load P")
ax1.set_ylabel("contact zones (X)")
ax1.set_title("zones along the load (blue: two, orange: one)")

X = np.linspace(-2.0, 2.0, 801)
for P in (1e-3, 1e-2, 0.1, 3.0):
    r = contact.solve(mat, w, load=P, speed=0.3, friction=0.1)
    ax2.plot(X, r.pressure(X) / P, label=f"P = {P:g} ({len(r.zones)} zone{'s' * (len(r.zones) > 1)})")
ax2.set_xlabel("X")
ax2.set_ylabel("p(X) / P")
ax2.legend(fontsize=8)
fig.tight_layout()
