"""
A mechanism trace: the four-bar linkage
=======================================

A crank-rocker four-bar linkage (``meshes/mech_fourbar.toml``): ground 1–4, crank 1–2,
coupler 2–3, rocker 4–3.  ``trussfe.mechanism`` finds its one degree of freedom (two free
joints with two coordinates each against three bars: 2·2 − 3 = 1; Grübler's count of four
links and four pins: 3·3 − 2·4 = 1) and ``trussfe.trace`` follows the finite motion, driving
the crank tip's y coordinate.  At every state the coupler–rocker joint must lie on the
intersection of the two circles about joints 2 and 4, which gives its position in closed form.
"""
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import trussfe

HERE = Path(__file__).resolve().parent if "__file__" in globals() else Path.cwd()
MODEL = HERE.parent / "meshes" / "mech_fourbar.toml"

rank = trussfe.mechanism(MODEL)
print(f"rank {rank.rank}, {rank.mechanisms} mechanism(s), "
      f"{rank.self_stress_states} state(s) of self-stress")
trace = trussfe.trace(MODEL, drive="2:y", step=0.02, steps=40)
x = trace.position                       # (state, node, 2)
n2, n3, n4 = (trace.node_ids.index(k) for k in ("2", "3", "4"))


def circle_intersection(c1, r1, c2, r2, near):
    """The intersection of two circles nearer to ``near`` (one per row)."""
    d = np.linalg.norm(c2 - c1, axis=1)
    a = (r1 ** 2 - r2 ** 2 + d ** 2) / (2 * d)
    h = np.sqrt(r1 ** 2 - a ** 2)
    e = (c2 - c1) / d[:, None]
    base = c1 + a[:, None] * e
    perp = np.stack([-e[:, 1], e[:, 0]], axis=1)
    both = np.stack([base + h[:, None] * perp, base - h[:, None] * perp])
    pick = np.argmin(np.linalg.norm(both - near, axis=2), axis=0)
    return both[pick, np.arange(len(pick))]


coupler = np.linalg.norm(x[0, n3] - x[0, n2])
rocker = np.linalg.norm(x[0, n3] - x[0, n4])
closed = circle_intersection(x[:, n2], coupler, x[:, n4], rocker, x[:, n3])
error = np.abs(x[:, n3] - closed).max()
length_change = np.abs(np.linalg.norm(x[:, n3] - x[:, n2], axis=1) - coupler).max()
print(f"{len(x)} states; joint 3 against the circle intersection: {error:.2e} m")

# %%
# Checks
# ------

# (quantity, computed, expected, absolute tolerance, source)
CHECKS = [
    ("mechanisms", rank.mechanisms, 1, 0, "2 joints · 2 − 3 bars = 1 degree of freedom"),
    ("joint 3 position error, m", error, 0.0, 1e-8, "closed-form circle intersection"),
    ("coupler length change, m", length_change, 0.0, 1e-8, "rigid bars"),
]
for name, value, ref, atol, source in CHECKS:
    print(f"{name:30s} {value:10.3g}  {source}: {ref:g}")
    assert abs(value - ref) <= atol, name

# %%
# The path of the linkage
# -----------------------
fig, ax = plt.subplots(figsize=(7, 5))
for k in range(0, len(x), 5):
    links = x[k][[0, 1, 2, 3]]           # 1-2-3-4
    ax.plot(*links.T, "-", color=plt.cm.viridis(k / (len(x) - 1)), lw=1.5, alpha=0.8)
ax.plot(*x[:, n2].T, "k--", lw=1, label="crank tip (joint 2)")
ax.plot(*x[:, n3].T, "r-", lw=2, label="coupler–rocker joint 3 (trace)")
ax.plot(*closed[::5].T, "kx", ms=7, label="closed form (circle intersection)")
ax.set_aspect("equal")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.set_title("Four-bar linkage traced by trussfe.trace")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
