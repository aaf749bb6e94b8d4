"""
Steady rolling: the stick zone at the leading edge and Carter's traction curve
===============================================================================

Two cylinders of one material roll over each other (quasi-static, the contact at rest in
the frame that follows it) while a tractive force Q is transmitted.  The material entering
the contact sticks first: the stick zone lies at the leading edge, of half-width
c = a sqrt(1 - Q/(mu P)), the rest slips, and the surfaces' strains differ by the creepage
xi.  Carter (1926) found the traction curve Q/(mu P) = 1 - (1 - xi R/(mu a))^2;
``contact.solve(..., rolling=True)`` takes either the force or the creepage and returns the
other (:mod:`contact.partial_slip`).  The same solve works for any face of this class; here
a flat punch with rounded corners rolls beside the cylinder.
"""
import math

import matplotlib.pyplot as plt
import numpy as np

import contact

mat = contact.Isotropic(1.0, 0.3)
P, mu, R = 0.01, 0.5, 1.0
cyl = contact.CylindricalPunch(R)


def roll(punch, **kw):
    return contact.solve(mat, punch, load=P, speed=0.0, friction=mu, punch_material=mat,
                         rolling=True, direction=-1, **kw)


# the traction curve: the creepage for each force, against Carter's
ratios = np.linspace(0.05, 0.99, 12)
a = roll(cyl, tangential_load=0.0).ends[1]
xi = np.array([abs(roll(cyl, tangential_load=f * mu * P).creepage) for f in ratios])
carter = mu * a / R * (1 - np.sqrt(1 - ratios))
print(f"largest relative difference from Carter's creepage: {np.max(np.abs(xi / carter - 1)):.1e}")

# the tractions at Q = 0.6 mu P: the stick zone at the leading edge (rolling toward -X)
r = roll(cyl, tangential_load=0.6 * mu * P)
(c0, c1), = [z.ends for z in r.stick_zones]
print(f"stick zone [{c0 / a:.6f}, {c1 / a:.6f}] a (Carter: [-1, {-1 + 2 * math.sqrt(0.4):.6f}])")

flat = contact.ProfilePunch(
    lambda X: np.where(np.abs(X) < 0.05, 0.0, (np.abs(X) - 0.05) * np.sign(X) / R),
    breaks=(-0.05, 0.05))
rf = roll(flat, tangential_load=0.6 * mu * P)

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.8))
s = np.linspace(0, 1, 201)
ax1.plot(s, 1 - (1 - s) ** 2, "k-", lw=1, label="Carter")
ax1.plot(xi * R / (mu * a), ratios, "o", label="contact.solve")
ax1.set_xlabel("creepage xi R / (mu a)")
ax1.set_ylabel("Q / (mu P)")
ax1.set_title("the traction curve")
ax1.legend()
for res, name in ((r, "cylinder"), (rf, "rounded flat")):
    lo, hi = res.ends
    X = np.linspace(lo, hi, 801)[1:-1]
    line, = ax2.plot(X / a, res.tangential_traction(X) / (mu * P), label=f"q, {name}")
    ax2.plot(X / a, res.pressure(X) / P, ":", color=line.get_color(), lw=0.8)
    for z in res.stick_zones:
        ax2.axvspan(z.ends[0] / a, z.ends[1] / a, color=line.get_color(), alpha=0.1)
ax2.set_xlabel("X / a (rolling toward -X)")
ax2.set_ylabel("q / (mu P), p / P (dotted)")
ax2.set_title("Q = 0.6 mu P: stick zones shaded")
ax2.legend(fontsize=8)
fig.tight_layout()
plt.show()
