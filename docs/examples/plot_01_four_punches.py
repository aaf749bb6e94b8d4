"""
The four punches against their closed forms
===========================================

The paper gives closed forms for four punch faces (Zhou, Lee & Jang 2014, Sec. 5): flat
(two corners, index 1), triangular and parabolic (one corner, index 0) and cylindrical (two
free ends, index -1).  The library solves them numerically, through :func:`sie.solve`, like
any other face; the corrected closed forms (``method="closed_form"``) are the independent
reference.  Material: the paper's; speed c = 0.6, friction 0.3, load P = 0.01.
"""
import matplotlib.pyplot as plt
import numpy as np

import contact

mat = contact.zhou2014()
punches = {
    "flat, a = 1": contact.FlatPunch(1.0),
    "triangular, m0 = 0.01": contact.TriangularPunch(0.01),
    "parabolic, R = 100": contact.ParabolicPunch(100.0),
    "cylindrical, R = 100": contact.CylindricalPunch(100.0),
}

fig, axes = plt.subplots(2, 2, figsize=(8, 6))
for ax, (name, punch) in zip(axes.flat, punches.items()):
    num = contact.solve(mat, punch, load=0.01, speed=0.6, friction=0.3)
    ref = contact.solve(mat, punch, load=0.01, speed=0.6, friction=0.3, method="closed_form")
    xl, xr = num.ends
    X = np.linspace(xl, xr, 201)[1:-1]            # the ends may be singular
    p, p_ref = num.pressure(X), ref.pressure(X)
    err = np.max(np.abs(p - p_ref)) / np.max(np.abs(p_ref))
    d_ends = max(abs(a - b) for a, b in zip(num.ends, ref.ends)) / (xr - xl)
    sif = {k: f"{v:.6g}" for k, v in num.sif.items()}
    print(f"{name:22s} ends ({xl:+.6f}, {xr:+.6f})  alpha {num.alpha:+.4f} beta {num.beta:+.4f}"
          f"  SIF {sif}  |p - closed form| / max p = {err:.1e}, ends {d_ends:.1e}")
    ax.plot(X, p, label="numeric")
    ax.plot(X[::10], p_ref[::10], "o", ms=3, label="closed form")
    ax.set_title(name, fontsize=10)
    ax.set_xlabel("X")
    ax.set_ylabel("p(X)")
axes[0, 0].legend()
fig.suptitle("pressure under the four punches, c = 0.6, mu = 0.3")
fig.tight_layout()
