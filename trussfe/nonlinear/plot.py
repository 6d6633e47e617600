# SPDX-License-Identifier: MIT
"""The load–displacement plot of a post-critical path."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..io.output import atomic_path
from .path import PathResult


def write_plot(path: str | Path, result: PathResult) -> None:
    """Load factor against the monitored displacement, events marked; written atomically."""
    from ..io.figures import subplots
    from .analysis import monitor_label
    s = result.model.structure
    label = monitor_label(result.model, result.monitor)
    lam = result.load_factors
    u = result.displacement()
    eq = np.array([p.stage == "equilibrium" for p in result.path])
    fig, ax = subplots(figsize=(6.4, 4.4))
    ax.plot(u[eq], lam[eq], ".-", lw=1.2, ms=3, label="equilibrium path")
    if (~eq).any():
        j = np.flatnonzero(~eq)
        j = np.concatenate([[j[0] - 1], j])              # from the hand-over state
        ax.plot(u[j], lam[j], "--", color="0.5", label="mechanism motion (λ held)")
    marks = {"limit_point": ("o", "limit point"), "bifurcation": ("s", "bifurcation"),
             "buckling": ("v", "buckling"), "yield": ("^", "yield"),
             "fracture": ("x", "fracture"), "mechanism": ("*", "mechanism")}
    seen = set()
    for e in result.events:
        if e.kind in marks and 0 <= e.point < len(result.path):
            mk, lab = marks[e.kind]
            ax.plot(u[e.point], result.path[e.point].load_factor, mk, ms=8, mfc="none",
                    color="C3", label=None if lab in seen else lab)
            seen.add(lab)
    ax.set_xlabel(f"displacement of node {label['node']}, {label['axis']} "
                  f"({'rad' if label['axis'].startswith('r') else 'm'})")
    ax.set_ylabel("load factor λ")
    ax.set_title(s.name)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=120, format="png")
