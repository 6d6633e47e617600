# SPDX-License-Identifier: MIT
"""The plots of a study: one PNG per output, ``DIR/<output>.png``, with the output against
each numeric parameter (failed runs left out) and, for a Monte Carlo study, its histogram."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from ..io.figures import subplots
from ..io.output import atomic_path


#: Panels per row of a plot.
COLUMNS = 4


def _file_name(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip("._") or "output"


def write_plots(run, folder: Path) -> list[str]:
    """Write the plots of ``run`` (a :class:`~trussfe.parametric.engine.StudyRun`) into
    ``folder``; returns the file names."""
    study, df = run.study, run.table
    ok = df[df["status"] == "ok"]
    params = [p for p in study.parameters
              if np.issubdtype(df[p.name].dtype, np.number) and df[p.name].nunique() > 1]
    names = []
    for o in study.outputs:
        y = ok[o.name].to_numpy(dtype=float)
        panels = len(params) + (1 if study.samples > 1 else 0)
        if panels == 0 or not np.isfinite(y).any():
            continue
        ncols = min(panels, COLUMNS)
        nrows = -(-panels // ncols)
        fig, axes = subplots(nrows, ncols, figsize=(4.0 * ncols, 3.2 * nrows), squeeze=False)
        axes = axes.ravel()
        for ax in axes[panels:]:
            ax.set_visible(False)
        for ax, p in zip(axes, params):
            x = ok[p.name].to_numpy(dtype=float)
            if p.is_grid and study.samples == 1:
                order = np.argsort(x, kind="stable")
                ax.plot(x[order], y[order], "o-", ms=3, lw=1)
            else:
                ax.plot(x, y, ".", ms=3, alpha=0.6)
            ax.set_xlabel(p.name)
            ax.set_ylabel(o.name)
            ax.grid(True, alpha=0.3)
        if study.samples > 1:
            ax = axes[panels - 1]
            ax.hist(y[np.isfinite(y)], bins=min(50, max(5, int(np.sqrt(y.size)))))
            ax.set_xlabel(o.name)
            ax.set_ylabel("runs")
        fig.suptitle(f"{study.name[:60]}\n{o.name} ({len(ok)} of {len(df)} runs ok)", fontsize=8)
        fig.tight_layout()
        name = f"{_file_name(o.name)}.png"
        with atomic_path(Path(folder) / name) as tmp:
            fig.savefig(tmp, dpi=90, format="png")
        names.append(name)
    return names
