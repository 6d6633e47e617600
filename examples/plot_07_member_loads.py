"""
A beam under a load along its members
=====================================

A simply supported steel beam of span L = 3 m (EI = 1.6·10⁶ N·m²) carries q = 1 kN/m along
its two members (``member_loads``).  The closed forms of a simply supported beam under a
uniform load (Roark's Formulas for Stress and Strain, Table 8.1 case 2e) give the reactions
qL/2, the midspan deflection 5qL⁴/(384EI) and the midspan moment qL²/8; the consistent
fixed-end forces of the member loads make the finite-element values exact.
"""
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import trussfe

L, q, E, I = 3.0, 1000.0, 2.0e11, 8.0e-6
beam = trussfe.model_from_dict({
    "model": {"name": "simply supported beam, uniform member load", "dimension": 2},
    "materials": {"steel": {"E": E, "G": 8.0e10}},
    "sections": {"box": {"area": 4.0e-3, "Iz": I, "c": 0.05}},
    "nodes": {"A": [0.0, 0.0], "M": [L / 2, 0.0], "B": [L, 0.0]},
    "members": {"AM": {"nodes": ["A", "M"], "section": "box", "material": "steel",
                       "type": "beam"},
                "MB": {"nodes": ["M", "B"], "section": "box", "material": "steel",
                       "type": "beam"}},
    "supports": {"A": ["x", "y"], "B": ["y"]},
    "member_loads": [{"member": "AM", "kind": "uniform", "q": [0.0, -q]},
                     {"member": "MB", "kind": "uniform", "q": [0.0, -q]}],
})
result = trussfe.static(beam, subdivisions=8)
node = {nid: i for i, nid in enumerate(result.node_ids)}
moment = result.section_forces[:, :, 5]            # Mz at the stations of each member
print(f"reactions {result.reaction[node['A'], 1]:.1f} N, {result.reaction[node['B'], 1]:.1f} N;"
      f" midspan deflection {result.displacement[node['M'], 1]:.6e} m")

# %%
# Checks against the closed forms
# -------------------------------
# Global equilibrium first: the reactions carry the whole load qL.
assert np.isclose(result.reaction[:, 1].sum(), q * L, rtol=1e-12)

# (quantity, computed, closed form, relative tolerance, source)
CHECKS = [
    ("reaction at A, N", result.reaction[node["A"], 1], q * L / 2, 1e-10, "qL/2"),
    ("reaction at B, N", result.reaction[node["B"], 1], q * L / 2, 1e-10, "qL/2"),
    ("midspan deflection, m", result.displacement[node["M"], 1],
     -5 * q * L ** 4 / (384 * E * I), 1e-10, "5qL⁴/(384EI)"),
    ("midspan moment, N·m", moment[0, -1], q * L ** 2 / 8, 1e-10, "qL²/8"),
]
for name, value, ref, rtol, source in CHECKS:
    print(f"{name:24s} {value:14.8g}  {source}: {ref:.8g}")
    assert abs(value - ref) <= rtol * abs(ref), name

# %%
# The model and its bending moment
# --------------------------------
# Above, ``trussfe.show``: supports, the member loads as labelled arrows.  Below, the bending
# moment along the beam from the section forces at the stations of the members against the
# parabola qx(L − x)/2.
fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 8), height_ratios=(1, 1))
with tempfile.TemporaryDirectory() as folder:
    picture = Path(folder) / "beam.png"
    trussfe.show(beam, picture, backend="matplotlib", size=(1000, 420))
    ax1.imshow(plt.imread(picture))
ax1.set_axis_off()
x_station = np.concatenate([np.linspace(0.0, L / 2, moment.shape[1]),
                            np.linspace(L / 2, L, moment.shape[1])])
x = np.linspace(0.0, L, 200)
ax2.plot(x, q * x * (L - x) / 2, color="0.6", lw=3, label="closed form qx(L − x)/2")
ax2.plot(x_station, moment.ravel(), "o", ms=4, label="trussfe.static section forces")
ax2.set_xlabel("x [m]")
ax2.set_ylabel("bending moment Mz [N·m]")
ax2.grid(True, alpha=0.3)
ax2.legend(fontsize=8)
fig.tight_layout()
