"""
A fixed-fixed beam under load cases and a combination
=====================================================

A steel beam of span L = 4 m (EI = 1.6·10⁶ N·m²), clamped at both ends, under two load cases:
``dead``, a uniform load q = 2 kN/m along it (``member_loads``), and ``settlement``, its end B
sinking δ = 5 mm (``prescribed``).  The closed forms of a fixed-fixed beam (Roark's Formulas
for Stress and Strain, Table 8.1 case 2d for the uniform load; the slope-deflection equations
for the end displacement) give the end moments qL²/12 and 6EIδ/L² and the end shears qL/2 and
12EIδ/L³.  The combination ``ULS = 1.35 dead + 1.0 settlement`` is the factored sum of the two
cases.
"""
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import trussfe

L, q, E, I, delta = 4.0, 2000.0, 2.0e11, 8.0e-6, 0.005
beam = trussfe.model_from_dict({
    "model": {"name": "fixed-fixed beam, two load cases", "dimension": 2},
    "materials": {"steel": {"E": E, "G": 8.0e10}},
    "sections": {"box": {"area": 4.0e-3, "Iz": I, "c": 0.05}},
    "nodes": {"A": [0.0, 0.0], "B": [L, 0.0]},
    "members": {"AB": {"nodes": ["A", "B"], "section": "box", "material": "steel",
                       "type": "beam"}},
    "supports": {"A": ["x", "y", "rz"], "B": ["x", "y", "rz"]},
    "load_cases": {
        "dead": {"member_loads": [{"member": "AB", "kind": "uniform", "q": [0.0, -q]}]},
        "settlement": {"prescribed": {"B": {"y": -delta}}},
    },
    "combinations": {"ULS": {"dead": 1.35, "settlement": 1.0}},
})
result = trussfe.static(beam, subdivisions=8)
dead, settle = result.cases["dead"], result.cases["settlement"]
uls = result.combinations["ULS"]
A = dead.node_ids.index("A")

# %%
# Checks against the closed forms
# -------------------------------
# Each case is in global equilibrium: the dead load's reactions carry qL; a settlement moves
# a support of an unloaded beam, so its reactions balance each other.
assert np.isclose(dead.reaction[:, 1].sum(), q * L, rtol=1e-12)
assert abs(settle.reaction[:, 1].sum()) <= 1e-9 * abs(settle.reaction[:, 1]).max()

# (quantity, computed, closed form, relative tolerance, source)
CHECKS = [
    ("dead: end moment at A, N·m", abs(dead.reaction_moment[A, -1]), q * L ** 2 / 12, 1e-10,
     "qL²/12"),
    ("dead: end shear at A, N", dead.reaction[A, 1], q * L / 2, 1e-10, "qL/2"),
    ("settlement: end moment at A, N·m", abs(settle.reaction_moment[A, -1]),
     6 * E * I * delta / L ** 2, 1e-10, "6EIδ/L²"),
    ("settlement: end shear at A, N", abs(settle.reaction[A, 1]),
     12 * E * I * delta / L ** 3, 1e-10, "12EIδ/L³"),
    ("ULS: moment at A over 1.35 dead + settlement", uls.reaction_moment[A, -1]
     / (1.35 * dead.reaction_moment[A, -1] + settle.reaction_moment[A, -1]), 1.0, 1e-12,
     "the combination is the factored sum of its cases"),
]
for name, value, ref, rtol, source in CHECKS:
    print(f"{name:46s} {value:14.8g}  {source}: {ref:.8g}")
    assert abs(value - ref) <= rtol * abs(ref), name

# %%
# The model and the bending moment of each case
# ---------------------------------------------
# Above, ``trussfe.show``: clamped supports, the dead case's load along the member.  Below,
# the bending moment along the beam (section forces at the member's stations) of the two
# cases and of the combination.
fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 8))
with tempfile.TemporaryDirectory() as folder:
    picture = Path(folder) / "beam.png"
    trussfe.show(beam, picture, backend="matplotlib", size=(1000, 420))
    ax1.imshow(plt.imread(picture))
ax1.set_axis_off()
for name, r in (("dead", dead), ("settlement", settle), ("ULS", uls)):
    x = r.station_x[0]
    ax2.plot(x, r.section_forces[0, :, 5], "o-", ms=3, label=name)
ax2.set_xlabel("x [m]")
ax2.set_ylabel("bending moment Mz [N·m]")
ax2.grid(True, alpha=0.3)
ax2.legend(fontsize=8)
fig.tight_layout()
