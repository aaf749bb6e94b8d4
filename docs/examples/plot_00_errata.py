"""
The paper's errata, in numbers
==============================

Each erratum of Zhou, Lee & Jang (2014) listed in :doc:`/theory/errata`, shown by a number
computed here against an independent reference.  The material is the paper's
(:func:`contact.zhou2014`), the punch the cylindrical one (R = 100, P = 0.01).
"""
import math
import warnings

import matplotlib.pyplot as plt
import numpy as np

import contact
from validation.report_paper import cylindrical_sigma_printed, printed_exponents

mat = contact.zhou2014()

# %%
# Item 5: the admissible speeds end at the Rayleigh speed
# -------------------------------------------------------
# The constants share the denominator Delta(c); N11 diverges and changes sign at c_R < 1.
c_R = contact.rayleigh_speed(mat)
print(f"c_R = {c_R:.10f}")
for c in (0.9 * c_R, 0.99 * c_R, 0.9999 * c_R):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        N11 = contact.surface_constants(mat, c).N11
    flag = f"  ({caught[0].category.__name__})" if caught else ""
    print(f"c = {c:.6f}: N11 = {N11:+.4e}{flag}")
try:
    contact.surface_constants(mat, 0.999)
except contact.SpeedError as exc:
    print("c = 0.999:", type(exc).__name__)

# %%
# Item 1: sigma_XX on the surface takes N22 for the shear traction
# ----------------------------------------------------------------
# The stress field under the surface is derived from the modal solution, independently of the
# surface constants.  Its limit at Y -> 0 under a sliding cylinder (q = mu p) must equal
# N21 p + N22 Hc[q] (corrected), not N21 p + N21 Hc[q] (printed).
r = contact.solve(mat, contact.CylindricalPunch(radius=100.0), load=0.01, speed=0.6,
                  friction=0.3)
k = r.constants
X = np.linspace(r.ends[0], r.ends[1], 41)[1:-1]
field = r.stress(X, np.full_like(X, -1e-13 * r.half_width)).sigma_xx
p, hq = r.pressure(X), r.mu_f * r.hilbert_pressure(X)
scale = np.max(np.abs(field))
print(f"|field - (N21 p + N22 Hc[q])| / max = {np.max(np.abs(field - (k.N21 * p + k.N22 * hq))) / scale:.1e}")
print(f"|field - (N21 p + N21 Hc[q])| / max = {np.max(np.abs(field - (k.N21 * p + k.N21 * hq))) / scale:.1e}")

# %%
# Item 2: the printed exponent branch
# -----------------------------------
# With friction xi = mu_f N12 / N11 < 0, and the printed eps = arctan(1/xi) takes the wrong
# branch.  The exponents must solve cot(pi alpha) = -xi with both in (-1, 1).
for mu in (0.1, 0.3, 0.5):
    k = contact.surface_constants(mat, 0.6)
    xi = mu * k.N12 / k.N11
    rr = contact.solve(mat, contact.CylindricalPunch(radius=100.0), load=0.01, speed=0.6,
                       friction=mu)
    pa, pb = printed_exponents("cylindrical", xi)
    print(f"mu = {mu}: printed (alpha, beta) = ({pa:+.4f}, {pb:+.4f}), "
          f"|cot(pi alpha) + xi| = {abs(1 / math.tan(math.pi * pa) + xi):.1e};  "
          f"corrected ({rr.alpha:.4f}, {rr.beta:.4f}), "
          f"|cot(pi alpha) + xi| = {abs(1 / math.tan(math.pi * rr.alpha) + xi):.1e}")

# %%
# Item 4: sigma_XX inside a sliding cylinder
# ------------------------------------------
# The printed inside row of eq. (5.45) lacks the cos(pi alpha) of the Plemelj formula.  The
# numeric path (the Cauchy transform of the computed pressure) is the reference.
Xs = np.linspace(r.ends[0], r.ends[1], 401)[1:-1]
num = r.sigma_xx(Xs)
printed = cylindrical_sigma_printed(r, Xs)
fixed = cylindrical_sigma_printed(r, Xs, corrected=True)
print(f"printed inside row: max relative difference {np.max(np.abs(printed - num)) / np.max(np.abs(num)):.0%}")
print(f"with cos(pi alpha): max relative difference {np.max(np.abs(fixed - num)) / np.max(np.abs(num)):.1e}")

fig, ax = plt.subplots(figsize=(6.4, 3.6))
a = r.half_width
ax.plot(Xs / a, num / r.pressure(0.0), label="numeric (Cauchy transform of p)")
ax.plot(Xs / a, printed / r.pressure(0.0), "--", label="printed eq. (5.45)")
ax.set_xlabel("X / a")
ax.set_ylabel(r"$\sigma_{XX}(X, 0) / p(0)$")
ax.set_title("cylinder, c = 0.6, mu = 0.3: the missing cos(pi alpha)")
ax.legend()
fig.tight_layout()
