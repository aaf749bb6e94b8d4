"""
A cylinder sliding on a carbon/epoxy ply: the fibre angle
==========================================================

A unidirectional ply is stiff along its fibres (E1 = 135 GPa) and soft across them
(E2 = E3 = 10 GPa).  With the fibres along the sliding direction X (the ply's axes on the
problem's axes) it is an orthotropic material of the paper's kind; turned by an angle theta
it is not, and :class:`contact.Anisotropic` takes it in the problem's frame (the Stroh
formalism: :doc:`/theory/anisotropic`).  Two turns matter here:

* about the normal Y: the fibres stay in the surface plane, at theta to the sliding
  direction (a ply swept across at an angle).  The in-plane problem couples to the
  displacement along the punch's axis (generalised plane strain);
* about the punch's axis Z: the fibres tilt into the depth.  The material loses its mirror
  symmetry X -> -X, the surface's slope under a shear gains a Hilbert part (the coupling
  M12 of :class:`contact.SurfaceConstants`), and with friction the contact equation's
  coefficient b = N11 + M12 mu_f, hence the end exponents, depend on which way the fibres
  lean.

A rigid cylinder R = 10 mm, a line load P = 0.05 GPa mm (50 N/mm), Coulomb friction 0.3,
the punch sliding toward -X, slowly (at rest for the elastic field).
"""
import matplotlib.pyplot as plt
import numpy as np
from scipy.spatial.transform import Rotation

import contact

ply = contact.Anisotropic.from_engineering(E1=135.0, E2=10.0, E3=10.0, nu12=0.3, nu13=0.3,
                                           nu23=0.45, G12=5.0, G13=5.0, G23=3.45)
punch = contact.CylindricalPunch(10.0)
P, mu = 0.05, 0.3


def turned(axis, degrees):
    return ply.rotated(Rotation.from_euler(axis, degrees, degrees=True))


# %%
# The pressure under the cylinder for fibres at 0, 30, 60 and 90 degrees, turned in the
# surface plane (left) and into the depth (right).  At 0 and 90 degrees both turns give an
# orthotropic material; in between, the tilt into the depth shifts the contact and skews
# its pressure.
fig, axes = plt.subplots(1, 2, figsize=(10, 3.6), sharey=True, layout="constrained")
for ax, axis, name in zip(axes, "yz", ("in the surface plane (about Y)",
                                       "into the depth (about Z)")):
    for theta in (0, 30, 60, 90):
        r = contact.solve(turned(axis, theta), punch, load=P, speed=0.0, friction=mu)
        X = np.linspace(*r.ends, 401)
        ax.plot(X, r.pressure(X), label=f"{theta} deg")
    ax.set_title(f"fibres turned {name}", fontsize=10)
    ax.set_xlabel("X [mm]")
axes[0].set_ylabel("p [GPa]")
axes[1].legend()
plt.show()

# %%
# The contact's half-width, its centre and the exponent alpha at its right end (the
# pressure vanishes like (d - X)^alpha there; beta = 1 - alpha at the left end) against the
# fibre angle.  The exponent follows from
# cot(pi alpha) = -a / b with a = N12 mu_f and b = N11 + M12 mu_f: in the surface plane the
# coupling M12 stays zero and alpha moves only with N12 / N11; tilted into the depth, M12
# changes b as well.
angles = np.arange(0, 91, 5)
rows = {}
for axis in "yz":
    out = []
    for theta in angles:
        m = turned(axis, theta)
        r = contact.solve(m, punch, load=P, speed=0.0, friction=mu)
        k = contact.surface_constants(m, 0.0)
        out.append((r.half_width, 0.5 * (r.ends[0] + r.ends[1]), r.alpha, k.M12 / k.N11))
    rows[axis] = np.array(out)
    print(f"about {axis.upper()}: alpha from {rows[axis][:, 2].min():.4f} to "
          f"{rows[axis][:, 2].max():.4f}, M12/N11 up to {np.abs(rows[axis][:, 3]).max():.3f}")
fig2, ax2 = plt.subplots(1, 3, figsize=(11, 3.2), layout="constrained")
for axis, style in zip("yz", ("o-", "s--")):
    label = "about Y (surface plane)" if axis == "y" else "about Z (into the depth)"
    for j, ax in enumerate(ax2):
        ax.plot(angles, rows[axis][:, j], style, ms=3, label=label)
for ax, ylabel in zip(ax2, ("half-width a [mm]", "centre of the contact [mm]",
                            "alpha (right end)")):
    ax.set_xlabel("fibre angle [deg]")
    ax.set_ylabel(ylabel)
ax2[0].legend(fontsize=8)
plt.show()

# %%
# Under the surface: the largest von Mises stress (from the full 3D stress, sigma_ZZ and the
# out-of-plane shears that generalised plane strain brings included) against the fibre
# angle, over and below the contact.  For the isotropic Hertz contact it is 0.56 p0 at
# depth 0.70 a (Johnson 1985, sec. 4.2, nu = 0.3).  The ply at 0 degrees, stiff along X,
# has sigma_XX = N21 p = -sqrt(C11 / C22) p = -3.3 p on the surface under the pressure
# alone, and its maximum lies there.
fig3, ax3 = plt.subplots(1, 2, figsize=(10, 3.2), layout="constrained")
for axis, style in zip("yz", ("o-", "s--")):
    label = "about Y (surface plane)" if axis == "y" else "about Z (into the depth)"
    value, depth = [], []
    for theta in angles[::2]:
        r = contact.solve(turned(axis, theta), punch, load=P, speed=0.0, friction=mu)
        p_max = np.max(r.pressure(np.linspace(*r.ends, 401)[1:-1]))
        e = r.stress_extrema(quantities=("von_mises",)).von_mises
        value.append(e.value / p_max)
        depth.append(e.depth_over_a)
    ax3[0].plot(angles[::2], value, style, ms=3, label=label)
    ax3[1].plot(angles[::2], depth, style, ms=3, label=label)
    print(f"about {axis.upper()}: max von Mises {min(value):.3f} .. {max(value):.3f} p_max")
ax3[0].set_ylabel("max von Mises / p_max")
ax3[1].set_ylabel("its depth / a")
for ax in ax3:
    ax.set_xlabel("fibre angle [deg]")
ax3[0].legend(fontsize=8)
plt.show()
