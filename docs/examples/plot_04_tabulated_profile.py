"""
A tabulated (measured) profile
==============================

A face known only by samples of its height -- a profilometer trace -- is a
:meth:`contact.ProfilePunch.from_samples`: the not-a-knot quintic spline through the samples
gives the slope.  Here the samples are those of a circular face of radius R = 1,
R - sqrt(R^2 - X^2), on [-0.8, 0.8], so the reference is the same face given by its exact
slope X / sqrt(R^2 - X^2).  The difference shows what tabulating the face costs: it falls by a
factor of 40 to 300 each time the sample spacing h is halved (the dotted line is h^6, the
order of the quintic spline's slope error, for scale).
"""
import matplotlib.pyplot as plt
import numpy as np

import contact

R, edge = 1.0, 0.8
mat = contact.zhou2014()
exact_face = contact.ProfilePunch(lambda X: X / np.sqrt(R * R - X * X),
                                  height=lambda X: R - np.sqrt(R * R - X * X),
                                  face=(-edge, edge))
exact = contact.solve(mat, exact_face, load=0.05, speed=0.6, friction=0.3)
X = np.linspace(exact.ends[0], exact.ends[1], 401)[1:-1]

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.6))
ax1.plot(X, exact.pressure(X), "k", lw=3, alpha=0.3, label="exact slope")
counts, errors = [], []
for m in (9, 17, 33, 65, 129):
    Xs = np.linspace(-edge, edge, m)
    face = contact.ProfilePunch.from_samples(Xs, R - np.sqrt(R * R - Xs ** 2))
    r = contact.solve(mat, face, load=0.05, speed=0.6, friction=0.3)
    d_ends = max(abs(a - b) for a, b in zip(r.ends, exact.ends))
    d_p = np.max(np.abs(r.pressure(X) - exact.pressure(X))) / np.max(exact.pressure(X))
    counts.append(m)
    errors.append(d_p)
    print(f"{m:4d} samples: ends differ by {d_ends:.1e}, pressure by {d_p:.1e} (relative)")
    if m in (9, 33):
        ax1.plot(X, r.pressure(X), "--", label=f"{m} samples")
ax1.set_xlabel("X")
ax1.set_ylabel("p(X)")
ax1.legend()
h = 2 * edge / (np.array(counts) - 1.0)
ax2.loglog(h, errors, "o-", label="max |p - p_exact| / max p")
ax2.loglog(h, errors[0] * (h / h[0]) ** 6, "k:", label="h^6")
ax2.set_xlabel("sample spacing h")
ax2.legend()
fig.tight_layout()
