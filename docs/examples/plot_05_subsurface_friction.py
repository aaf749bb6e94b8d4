"""
The maximum shear under a sliding cylinder, and how friction brings it to the surface
=====================================================================================

Frictionless Hertz contact on an isotropic half-space has its largest in-plane shear stress
below the surface, 0.30028 p0 at depth 0.78615 a (McEwen 1949; Johnson 1985, sec. 4.2).
Friction adds a surface shear traction q = mu p, and at a critical coefficient the maximum
jumps to the surface.  Here the contact itself is solved with friction (the pressure is no
longer exactly Hertzian: its exponents move away from 1/2), at rest, on an isotropic
material with nu = 0.3.
"""
import matplotlib.pyplot as plt
import numpy as np

import contact

mat = contact.Isotropic(1.0, 0.3)
punch = contact.CylindricalPunch(1.0)

r = contact.solve(mat, punch, load=0.01, speed=0.0)
e = r.stress_extrema()
p0, a = r.pressure(0.0), r.half_width
print(f"frictionless: max shear {e.max_shear.value / p0:.6f} p0 at depth {e.max_shear.depth / a:.5f} a"
      f"  (Hertz: 0.300283 p0 at 0.786152 a)")

# %%
# Maps of the maximum shear stress at three friction coefficients.
fig, axes = plt.subplots(1, 3, figsize=(11, 3.8), sharey=True, layout="constrained")
for ax, mu in zip(axes, (0.0, 0.2, 0.45)):
    r = contact.solve(mat, punch, load=0.01, speed=0.0, friction=mu)
    a, p0 = r.half_width, np.max(r.pressure(np.linspace(*r.ends, 201)[1:-1]))
    X, Y = np.meshgrid(np.linspace(-2, 2, 161) * a, np.linspace(-2, -0.002, 100) * a)
    tau = r.stress(X, Y).max_shear / p0
    cs = ax.contourf(X / a, Y / a, tau, levels=np.linspace(0, max(0.5, tau.max()), 21),
                     cmap="viridis")
    ext = r.stress_extrema(((-2 * a, 2 * a), (-2 * a, -0.002 * a))).max_shear
    ax.plot(ext.X / a, ext.Y / a, "r+", ms=12)
    ax.set_title(f"mu = {mu}\nmax {ext.value / p0:.3f} p_max at depth {ext.depth / a:.3f} a",
                 fontsize=9)
    ax.set_xlabel("X / a")
axes[0].set_ylabel("Y / a")
fig.colorbar(cs, ax=axes, label="max shear / p_max", shrink=0.9)
plt.show()

# %%
# The depth of the maximum against the friction coefficient: it reaches the surface at mu*.
mus = np.linspace(0.0, 0.5, 26)
depth = []
for mu in mus:
    r = contact.solve(mat, punch, load=0.01, speed=0.0, friction=mu)
    depth.append(r.stress_extrema().max_shear.depth_over_a)
depth = np.array(depth)
k = int(np.argmax(depth < 1e-3))
print(f"the maximum reaches the surface between mu = {mus[k - 1]:.2f} and {mus[k]:.2f}")
fig2, ax2 = plt.subplots(figsize=(6, 3.4))
ax2.plot(mus, depth, "o-")
ax2.set_xlabel("friction coefficient mu")
ax2.set_ylabel("depth of the max shear / a")
fig2.tight_layout()
