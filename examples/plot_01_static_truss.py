"""
A static truss: Lacy's triangular truss
=======================================

The triangular truss of Lacy (1991), Fig. 2.1 and Table 3.2: a 2 m follower and the 2.5 m
active member pinned to the ground at O1 and O2, 98.1 N (10 kg) hanging at the apex B.  A
linear static finite-element analysis gives the member forces and the support reactions,
which Table 3.2 prints.
"""
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import trussfe

HERE = Path(__file__).resolve().parent if "__file__" in globals() else Path.cwd()
MODEL = HERE.parent / "meshes" / "triangular_truss_static.toml"

result = trussfe.static(MODEL)
force = dict(zip(result.member_ids, result.axial_force))
reaction = dict(zip(result.node_ids, result.reaction))
for mid, n in force.items():
    print(f"member {mid:9s} axial force {n:10.4f} N")
for nid in ("O1", "O2"):
    print(f"support {nid}: reaction {reaction[nid][0]:9.4f} N, {reaction[nid][1]:9.4f} N")

# %%
# Checks
# ------
# Global equilibrium (the reactions carry the 98.1 N load) and the numbers of Lacy Table 3.2.
assert np.allclose(result.reaction.sum(axis=0), [0.0, 98.1], atol=1e-9)

# (quantity, computed, published, relative tolerance, source)
CHECKS = [
    ("follower axial force, N", force["follower"], -78.5429, 5e-6, "Lacy Table 3.2"),
    ("active member axial force, N", force["active"], -27.49, 5e-6, "Lacy Table 3.2"),
    ("O1 reaction x, N", reaction["O1"][0], -17.1813, 5e-6, "Lacy Table 3.2"),
    ("O1 reaction y, N", reaction["O1"][1], 76.6406, 5e-6, "Lacy Table 3.2"),
    ("O2 reaction y, N", reaction["O2"][1], 21.4594, 5e-6, "Lacy Table 3.2"),
]
for name, value, ref, rtol, source in CHECKS:
    print(f"{name:32s} {value:12.5g}  {source}: {ref:g}")
    assert abs(value - ref) <= rtol * abs(ref), name

# %%
# The picture
# -----------
# ``trussfe.show`` (the ``trussfe show`` command) draws the model with its results: members
# coloured by axial force, supports, the load arrow, and the deformed shape magnified.
with tempfile.TemporaryDirectory() as folder:
    picture = Path(folder) / "static_truss.png"
    trussfe.show(MODEL, picture, results=result, size=(800, 640), backend="matplotlib")
    fig, ax = plt.subplots(figsize=(8, 6.4))
    ax.imshow(plt.imread(picture))
    ax.set_axis_off()
    fig.tight_layout()
