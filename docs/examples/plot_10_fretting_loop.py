"""
A fretting cycle: the hysteresis loop and the energy per cycle
==============================================================

Two cylinders of one material are pressed together by P and then loaded tangentially at
that load: Q from 0 to the amplitude Q*, back to -Q* and up again.  On the unloading the
surfaces slip back from the edges inward while a stick zone of half-width
c' = a sqrt(1 - (Q* - Q)/(2 mu P)) holds (Mindlin & Deresiewicz): the traction is the sum of
three semi-ellipses, and the punch's displacement against Q traces a loop whose area is the
energy dissipated per cycle, W = (abs(T) mu^2 P^2 / pi)(1 - x^2 + 2 x log x),
x = 1 - Q*/(mu P) (:mod:`contact.fretting`).
"""
import math

import matplotlib.pyplot as plt
import numpy as np

import contact

mat = contact.Isotropic(1.0, 0.3)
P, mu = 0.01, 0.5
cyl = contact.CylindricalPunch(1.0)
amplitudes = (0.25, 0.5, 0.75, 0.95)
cycles = [contact.fretting_cycle(mat, cyl, load=P, friction=mu, tangential_amplitude=f * mu * P,
                                 punch_material=mat, steps=24) for f in amplitudes]
T = cycles[0].full.constants.tangential_compliance
for f, c in zip(amplitudes, cycles):
    x = 1 - f
    W = abs(T) * (mu * P) ** 2 / math.pi * (1 - x * x + 2 * x * math.log(x))
    print(f"Q*/(mu P) = {f:4.2f}: W = {c.energy_per_cycle:.6e} (closed form {W:.6e})")

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.8))
for f, c in zip(amplitudes, cycles):
    Q, d = c.loop
    ax1.plot(d / (abs(T) * mu * P), Q / (mu * P), label=f"Q*/(mu P) = {f:g}")
    ax1.plot(c.displacements[: len(c.loading)] / (abs(T) * mu * P),
             c.tangential_loads[: len(c.loading)] / (mu * P), color="0.6", lw=0.8)
ax1.set_xlabel("delta / (|T| mu P)   (datum: the half-width a)")
ax1.set_ylabel("Q / (mu P)")
ax1.set_title("loops (grey: the first loading)")
ax1.legend(fontsize=8)

c = cycles[2]
a = c.full.ends[1]
X = a * np.linspace(-0.999, 0.999, 801)
p0 = 2 * P / (math.pi * a)
for st in c.unloading[::6]:
    ax2.plot(X / a, st.tangential_traction(X) / (mu * p0),
             label=f"Q/Q* = {st.tangential_load / c.tangential_amplitude:+.2f}")
ax2.plot(X / a, c.full.pressure(X) / p0, "k:", lw=0.8)
ax2.plot(X / a, -c.full.pressure(X) / p0, "k:", lw=0.8)
ax2.set_xlabel("X / a")
ax2.set_ylabel("q / (mu p0)")
ax2.set_title("the unloading (Q* = 0.75 mu P)")
ax2.legend(fontsize=8)
fig.tight_layout()
