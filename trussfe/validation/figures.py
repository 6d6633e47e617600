# SPDX-License-Identifier: MIT
"""Figures the validation report draws itself: a structure with its members coloured by a
member result (matplotlib, off-screen)."""
from __future__ import annotations

import io

import numpy as np

from ..model.structure import Structure


def member_field_png(structure: Structure, values: np.ndarray, label: str,
                     title: str = "") -> bytes:
    """PNG of the structure's members coloured by ``values`` (one per member).

    Parameters
    ----------
    structure : Structure
        2-D or 3-D.
    values : ndarray, shape (m,)
        Member values (e.g. axial force); NaN members are drawn grey.
    label : str
        Colour-bar label.
    title : str
        Figure title.

    Returns
    -------
    bytes
        The PNG file.
    """
    import matplotlib
    from matplotlib import cm, colors

    from ..io.figures import new_figure

    values = np.asarray(values, dtype=float)
    finite = np.isfinite(values)
    vmax = float(np.max(np.abs(values[finite]))) if finite.any() else 1.0
    norm = colors.Normalize(vmin=-vmax or -1.0, vmax=vmax or 1.0)   # symmetric: tension red
    cmap = matplotlib.colormaps["coolwarm"]
    rgba = cmap(norm(np.where(finite, values, 0.0)))
    rgba[~finite] = (0.6, 0.6, 0.6, 1.0)
    seg = structure.coords[structure.connectivity]                  # (member, 2, dim)
    fig = new_figure(figsize=(6.4, 4.8), dpi=90)
    if structure.dim == 3:
        from mpl_toolkits.mplot3d.art3d import Line3DCollection

        ax = fig.add_subplot(projection="3d")
        ax.add_collection3d(Line3DCollection(seg, colors=rgba, linewidths=2.5))
        lo, hi = structure.coords.min(axis=0), structure.coords.max(axis=0)
        mid, half = (lo + hi) / 2, max(float(np.max(hi - lo)) / 2, 1e-9)
        for setter, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), mid):
            setter(c - half, c + half)
        ax.set_box_aspect((1, 1, 1))
        ax.set_zlabel("z (m)")
    else:
        from matplotlib.collections import LineCollection

        ax = fig.add_subplot()
        ax.add_collection(LineCollection(seg, colors=rgba, linewidths=2.5))
        ax.autoscale()
        ax.set_aspect("equal")
    sup = structure.translation_supports.any(axis=1)
    pts = structure.coords[sup]
    ax.scatter(*pts.T, marker="^", color="k", s=40)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, label=label, shrink=0.8)
    if title:
        ax.set_title(title, fontsize=9)
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    return buf.getvalue()
