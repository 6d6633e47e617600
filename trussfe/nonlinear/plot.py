# SPDX-License-Identifier: MIT
"""The load–displacement plot of a post-critical path."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..io.output import atomic_path
from .path import PathResult


#: A mechanism motion this many times wider than the equilibrium path gets a panel of its own:
#: on one axis the equilibrium path would be squashed into a vertical line.
WIDE_MOTION = 5.0


def write_plot(path: str | Path, result: PathResult) -> None:
    """Load factor against the monitored displacement, events marked; written atomically.

    When the path ends in a mechanism motion much wider than the equilibrium path, the
    equilibrium path is drawn on its own scale in a second panel beside the whole path.
    """
    from ..io.figures import subplots
    from .analysis import monitor_label
    s = result.model.structure
    label = monitor_label(result.model, result.monitor)
    lam = result.load_factors
    u = result.displacement()
    eq = np.array([p.stage == "equilibrium" for p in result.path])
    span = float(np.ptp(u[eq])) if eq.any() else 0.0
    wide = (~eq).any() and np.ptp(u) > WIDE_MOTION * max(span, 1e-300)
    fig, axes = subplots(1, 2 if wide else 1, figsize=(11.0 if wide else 6.4, 4.6),
                         squeeze=False)
    unit = "rad" if label["axis"].startswith("r") else "m"
    for n, ax in enumerate(axes[0]):
        whole = n == 0
        _draw_path(ax, result, u, lam, eq, motion=whole)
        ax.set_xlabel(f"displacement of node {label['node']}, {label['axis']} ({unit})")
        ax.set_ylabel("load factor λ")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        if wide:
            ax.set_title("whole path" if whole else "equilibrium path (its own scale)",
                         fontsize=10)
    fig.suptitle(s.name)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=120, format="png")


def _draw_path(ax, result: PathResult, u: np.ndarray, lam: np.ndarray, eq: np.ndarray,
               motion: bool) -> None:
    """The equilibrium path, the mechanism motion (when ``motion``) and the events on it."""
    ax.plot(u[eq], lam[eq], ".-", lw=1.2, ms=3, label="equilibrium path")
    # a collapse (every member failed) closes the path with one state off the equilibrium
    # path at the last one's position: there is no motion of bars to draw
    if motion and (~eq).any() and result.mechanism is not None:
        j = np.flatnonzero(~eq)
        j = np.concatenate([[j[0] - 1], j])              # from the hand-over state
        ax.plot(u[j], lam[j], "--", color="0.5", label="mechanism motion (λ held)")
    marks = {"limit_point": ("o", "limit point"), "bifurcation": ("s", "bifurcation"),
             "buckling": ("v", "buckling"), "yield": ("^", "yield"),
             "fracture": ("x", "fracture"), "mechanism": ("*", "mechanism")}
    seen = set()
    for e in result.events:
        if e.kind in marks and 0 <= e.point < len(result.path) and (motion or eq[e.point]):
            mk, lab = marks[e.kind]
            ax.plot(u[e.point], result.path[e.point].load_factor, mk, ms=8, mfc="none",
                    color="C3", label=None if lab in seen else lab)
            seen.add(lab)
