"""
A post-critical dome: progressive buckling to a mechanism
=========================================================

A shallow lattice dome (``meshes/postcritical_dome.toml``) under a growing load at its apex.
Each apex bar follows its failure law (``[failure.members]``): it carries compression up to
its critical force and is then removed.  The co-rotational path of ``trussfe.postcritical``
follows the load past each failure; when four of the six apex bars are gone the apex hangs on
two bars (a mechanism) and the path ends in the equilibrium form of that mechanism.
"""
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import trussfe

HERE = Path(__file__).resolve().parent if "__file__" in globals() else Path.cwd()
MODEL = HERE.parent / "meshes" / "postcritical_dome.toml"

path = trussfe.postcritical(MODEL)
failures = [e for e in path.events if e.kind == "buckling"]
for e in path.events:
    print(f"{e.kind:17s} load factor {e.load_factor:7.4f}  {e.detail}")

# %%
# Checks
# ------
# Every bar fails at the force its failure law gives (the threshold of the model file), and
# four of the six apex bars must go before the apex is left on two bars: a node held by two
# bars in space has a mechanism (Maxwell's count, 3 coordinates against 2 bars).  In its
# equilibrium form the apex hangs on the two bars left (A4 and A5, of length l) straight
# below the middle of their ring nodes R4 and R5 (a distance s apart), √(l² − s²/4) below
# them, so it has moved down by that depth plus its rise above the ring (the bars' elastic
# stretch and the ring's small movement are not in that closed form).
xyz = dict(zip(path.node_ids, path.structure.coords))
bar = np.linalg.norm(xyz["A"] - xyz["R4"])
half = np.linalg.norm(xyz["R4"] - xyz["R5"]) / 2
hanging = xyz["R4"][2] - np.sqrt(bar ** 2 - half ** 2) - xyz["A"][2]

# (quantity, computed, expected, relative tolerance, source)
CHECKS = [("apex displacement, equilibrium form, m", path.monitored_displacement[-1], hanging,
           1e-3, "two bars hanging below R4–R5: √(l² − s²/4)"),
          ("apex bars failed before the mechanism", len(failures), 4, 0.0,
           "four of six apex bars must go before two are left")]
CHECKS += [(f"force of {path.member_ids[e.member]} at failure, N", e.force, e.threshold, 1e-5,
            "failure law: N = -P_cr at buckling") for e in failures]
for name, value, ref, rtol, source in CHECKS:
    print(f"{name:38s} {value:12.6g}  {source}: {ref:g}")
    assert abs(value - ref) <= rtol * abs(ref), name
assert any(e.kind == "mechanism" for e in path.events)

# %%
# The load–displacement path
# --------------------------
# The apex deflection (the model's monitor, A:z) against the load factor, with the failures
# marked.  Left: the path up to the mechanism, the bars failing one after the other; right:
# the whole path, in which the load stays at its last value while the mechanism swings the
# apex down to its hanging equilibrium (1.63 m, against 24 mm when the mechanism forms).
w, lam = path.monitored_displacement, path.load_factors
mech = next(e.point for e in path.events if e.kind == "mechanism")
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.5))
ax1.plot(w[:mech + 1] * 1e3, lam[:mech + 1], ".-")
for e in failures:
    ax1.plot(w[e.point] * 1e3, e.load_factor, "rx", ms=10)
    ax1.annotate(path.member_ids[e.member], (w[e.point] * 1e3, e.load_factor),
                 textcoords="offset points", xytext=(6, -12), fontsize=8, color="r")
ax1.set_xlabel("apex displacement z [mm]")
ax1.set_ylabel("load factor")
ax1.set_title("up to the mechanism")
ax2.plot(w, lam, ".-")
ax2.plot(w[mech], lam[mech], "ks", label="mechanism")
ax2.plot(w[-1], lam[-1], "g^", label="equilibrium form")
ax2.set_xlabel("apex displacement z [m]")
ax2.set_title("the whole path")
ax2.legend(fontsize=8)
for ax in (ax1, ax2):
    ax.grid(True, alpha=0.3)
fig.suptitle("Lattice dome: progressive buckling of the apex bars")
fig.tight_layout()
