"""
Convergence and work-precision
==============================

Two questions a numerical analyst asks first: how accurate are the building blocks, and what
does accuracy cost?

1. The Gauss-Jacobi rule (:func:`sie.gauss_jacobi`) against an mpmath reference computed at
   40 digits (Golub-Welsch in multiple precision).
2. A contact with a non-polynomial face (a circular punch of radius 1 on [-0.8, 0.8], exact
   slope X / sqrt(1 - X^2)): the error in the pressure and the contact ends against n, the
   number of Jacobi coefficients, and against the time a solve takes.  The error falls
   geometrically (the slope is analytic on the contact) to the rounding floor by n = 12;
   at these sizes the time is that of following the load from first touch, not of n.
"""
import time

import matplotlib.pyplot as plt
import mpmath as mp
import numpy as np

import contact
import sie

# %%
# Gauss-Jacobi against mpmath
# ---------------------------
mp.mp.dps = 40


def mp_gauss_jacobi(n, a, b):
    """Nodes and weights of (1-x)^a (1+x)^b by Golub-Welsch at 40 digits."""
    a, b = mp.mpf(a), mp.mpf(b)
    J = mp.zeros(n, n)
    J[0, 0] = (b - a) / (a + b + 2)
    for k in range(1, n):
        s = 2 * k + a + b
        J[k, k] = (b * b - a * a) / (s * (s + 2))
    for k in range(1, n):
        s1 = 2 * k + a + b
        ratio = 1 if k == 1 else (k + a + b) / (s1 - 1)        # 0/0 at k = 1, a + b = -1
        J[k, k - 1] = J[k - 1, k] = 2 / s1 * mp.sqrt(k * (k + a) * (k + b) * ratio / (s1 + 1))
    E, Q = mp.eigsy(J)
    mu0 = 2 ** (a + b + 1) * mp.beta(a + 1, b + 1)
    order = sorted(range(n), key=lambda i: E[i])
    return [E[i] for i in order], [mu0 * Q[0, i] ** 2 for i in order]


rows = []
for n, a, b in ((10, -0.5, -0.5), (20, 0.3, -0.7), (30, -0.9, 0.4), (40, 0.5, 0.5)):
    x, w = sie.gauss_jacobi(n, a, b)
    X, W = mp_gauss_jacobi(n, a, b)
    ex = max(abs(float(xi - Xi)) for xi, Xi in zip(x, X))
    ew = max(abs(float((wi - Wi) / Wi)) for wi, Wi in zip(w, W))
    rows.append((n, a, b, ex, ew))
    print(f"n = {n:3d}, alpha = {a:+.1f}, beta = {b:+.1f}: nodes {ex:.1e} (absolute), "
          f"weights {ew:.1e} (relative)")

# %%
# A contact with a non-polynomial face
# ------------------------------------
mat = contact.zhou2014()
face = contact.ProfilePunch(lambda X: X / np.sqrt(1.0 - X * X),
                            height=lambda X: 1.0 - np.sqrt(1.0 - X * X), face=(-0.8, 0.8))
kw = dict(load=0.05, speed=0.6, friction=0.3)
ref = contact.solve(mat, face, n=256, **kw)
Xc = np.linspace(*ref.ends, 201)[1:-1]
ns = [4, 6, 8, 12, 16, 24, 32, 48, 64]
err_p, err_e, cost = [], [], []
for n in ns:
    times = []
    for _ in range(6):                          # the fastest of six (the first fills caches)
        t0 = time.process_time()
        r = contact.solve(mat, face, n=n, **kw)
        times.append(time.process_time() - t0)
    cost.append(min(times))
    u = (Xc - ref.ends[0]) / (ref.ends[1] - ref.ends[0])        # compare at the same
    Xn = r.ends[0] + u * (r.ends[1] - r.ends[0])                # relative positions
    err_p.append(np.max(np.abs(r.pressure(Xn) - ref.pressure(Xc))) / np.max(ref.pressure(Xc)))
    err_e.append(max(abs(x - y) for x, y in zip(r.ends, ref.ends)) / (ref.ends[1] - ref.ends[0]))
    print(f"n = {n:3d}: pressure {err_p[-1]:.1e}, ends {err_e[-1]:.1e}, {1e3 * cost[-1]:.2f} ms")

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9.5, 3.6))
ax1.semilogy(ns, np.maximum(err_p, 1e-17), "o-", label="pressure")
ax1.semilogy(ns, np.maximum(err_e, 1e-17), "s-", label="ends")
ax1.set_xlabel("n (Jacobi coefficients)")
ax1.set_ylabel("relative error")
ax1.set_title("spectral convergence")
ax1.legend()
ax2.loglog(np.array(cost) * 1e3, np.maximum(err_p, 1e-17), "o-")
ax2.set_xlabel("time per solve [ms]")
ax2.set_ylabel("relative error in p")
ax2.set_title("work-precision")
fig.tight_layout()
