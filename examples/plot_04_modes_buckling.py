"""
Modes and buckling of a pinned column
=====================================

A 2 m aluminium tube pinned at both ends (the follower of Lacy's triangular truss, Table 3.3)
is cut into beam elements.  Its lowest bending frequencies and its buckling load have closed
forms: f_k = k² π / (2 L²) √(EI/ρA) for the simply supported beam and the Euler load
P_cr = π² EI / L² (Lacy eq. 2.26), 1481.2 N in Lacy Table 3.3.
"""
import matplotlib.pyplot as plt
import numpy as np

import trussfe

L, P = 2.0, 1000.0
column = trussfe.model_from_dict({
    "model": {"name": "pinned column", "dimension": 2},
    "materials": {"al": {"E": 71e9, "density": 2770.0}},
    "sections": {"tube": {"outer_diameter": 0.0254, "inner_diameter": 0.022225}},
    "nodes": {"A": [0.0, 0.0], "B": [L, 0.0]},
    "members": {"AB": {"nodes": ["A", "B"], "section": "tube", "material": "al",
                       "type": "beam"}},
    "supports": {"A": ["x", "y"], "B": ["y"]},
    "loads": {"B": [-P, 0.0]},               # compression: the buckling reference load
})
E, I, A, rho = 71e9, column.Iy[0], column.area[0], 2770.0

modes = trussfe.modes(column, count=6, subdivisions=16)
buckling = trussfe.buckling(column, count=1, subdivisions=16)
p_cr = buckling.critical_load_factor * P
print("frequencies [Hz]:", np.round(modes.frequencies_hz, 3))
print(f"critical load {p_cr:.2f} N")

# %%
# Checks against the closed forms
# -------------------------------
# The column's own modes are bending modes (the axial mode of a 2 m aluminium bar is above
# 600 Hz), so the first two frequencies are the first two of the simply supported beam.
f1 = np.pi / (2 * L ** 2) * np.sqrt(E * I / (rho * A))

# (quantity, computed, closed form, relative tolerance, source)
CHECKS = [
    ("first bending frequency, Hz", modes.frequencies_hz[0], f1, 1e-4,
     "simply supported beam, f1 = π/(2L²)√(EI/ρA)"),
    ("second bending frequency, Hz", modes.frequencies_hz[1], 4 * f1, 1e-3,
     "simply supported beam, f2 = 4 f1"),
    ("Euler load, N", p_cr, np.pi ** 2 * E * I / L ** 2, 1e-4, "Lacy eq. 2.26"),
    ("Euler load of the Table 3.3 follower, N", p_cr, 1481.2, 1e-4, "Lacy Table 3.3"),
]
for name, value, ref, rtol, source in CHECKS:
    print(f"{name:40s} {value:10.5g}  {source}: {ref:.5g}")
    assert abs(value - ref) <= rtol * abs(ref), name

# %%
# Frequencies against the closed form
# -----------------------------------
# The six lowest frequencies are the bending modes k = 1 … 6 (f_k = k² f1); the finite
# elements converge from above, the error growing with the mode number.
k = np.arange(1, modes.frequencies_hz.size + 1)
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 4))
ax1.plot(k, modes.frequencies_hz, "o", label="trussfe.modes (16 beam elements)")
ax1.plot(k, k ** 2 * f1, "-", color="0.5", label="closed form k² f1")
ax1.set_xlabel("mode k")
ax1.set_ylabel("frequency [Hz]")
ax1.legend(fontsize=8)
ax1.grid(True, alpha=0.3)
ax2.semilogy(k, np.abs(modes.frequencies_hz / (k ** 2 * f1) - 1.0), "s-")
ax2.set_xlabel("mode k")
ax2.set_ylabel("relative error")
ax2.grid(True, alpha=0.3)
fig.suptitle(f"Pinned 2 m tube: bending modes; Euler load {p_cr:.1f} N (Lacy Table 3.3: 1481.2 N)")
fig.tight_layout()
