# SPDX-License-Identifier: MIT
"""Figures for reports: deformed shapes and mode shapes rendered off-screen to PNG.

pyvista (VTK) renders off-screen when an OpenGL context can be created (EGL, OSMesa or X);
otherwise — or when ``TRUSSFE_PLOT_BACKEND=matplotlib`` — the same figure is drawn with
matplotlib (Agg).  Whether VTK can render is probed once per process in a child process, so a
missing or broken OpenGL library can never crash or hang the caller.

The undeformed structure is drawn in light grey; the deformed or modal shape in colour, the
members coloured by a per-member quantity when one is given (e.g. axial force).
"""
from __future__ import annotations

import logging
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from .io.output import atomic_path
from .io.render_backend import _vtk_can_render, plot_backend  # noqa: F401 (re-exported)

log = logging.getLogger(__name__)

__all__ = ["plot_backend", "render_shape", "render_modes"]


def _pad3(x: np.ndarray) -> np.ndarray:
    x = np.asarray(x, dtype=float)
    return np.concatenate([x, np.zeros(x.shape[:-1] + (3 - x.shape[-1],))], axis=-1) \
        if x.shape[-1] < 3 else x


def _auto_scale(structure, shapes: np.ndarray, fraction: float = 0.1) -> np.ndarray:
    """Scale per shape so that the largest translation is ``fraction`` of the model size."""
    size = float(np.ptp(structure.coords, axis=0).max()) or 1.0
    amp = np.linalg.norm(shapes, axis=-1).reshape(shapes.shape[0], -1).max(axis=1)
    return np.where(amp > 0, fraction * size / np.where(amp > 0, amp, 1.0), 0.0)


# ---------------------------------------------------------------------- pyvista
def _pv_lines(points: np.ndarray, conn: np.ndarray):
    import pyvista as pv
    cells = np.hstack([np.full((conn.shape[0], 1), 2), conn]).ravel()
    return pv.PolyData(_pad3(points), lines=cells)


def _pv_panel(plotter, structure, deformed, scalars, label, title, polylines=None):
    under = _pv_lines(structure.coords, structure.connectivity)
    plotter.add_mesh(under, color="lightgrey", line_width=2)
    if polylines is not None:                  # member stations (m, s, 3)
        m, s = polylines.shape[:2]
        base = (np.arange(m) * s)[:, None] + np.arange(s - 1)[None, :]
        conn = np.stack([base, base + 1], -1).reshape(-1, 2)
        mesh = _pv_lines(polylines.reshape(-1, polylines.shape[-1]), conn)
        if scalars is not None:
            mesh.cell_data[label] = np.repeat(np.asarray(scalars, float), s - 1)
    else:
        mesh = _pv_lines(deformed, structure.connectivity)
        if scalars is not None:
            mesh.cell_data[label] = np.asarray(scalars, float)
    if scalars is not None:
        vmax = float(np.nanmax(np.abs(scalars))) or 1.0     # symmetric: 0 is white
        plotter.add_mesh(mesh, scalars=label, cmap="coolwarm", line_width=4,
                         clim=(-vmax, vmax),
                         scalar_bar_args={"title": label, "vertical": True,
                                          "title_font_size": 12, "label_font_size": 10})
    else:
        plotter.add_mesh(mesh, color="tab:blue", line_width=4)
    plotter.add_text(title, font_size=9)
    if structure.dim == 2:
        plotter.view_xy()
    else:
        plotter.view_isometric()


def _pv_render(path: Path, panels: list[dict], structure, window: tuple[int, int]) -> None:
    import pyvista as pv
    n = len(panels)
    cols = min(n, 3)
    rows = -(-n // cols)
    p = pv.Plotter(off_screen=True, shape=(rows, cols),
                   window_size=(window[0] * cols, window[1] * rows))
    p.set_background("white")
    for k, pan in enumerate(panels):
        p.subplot(k // cols, k % cols)
        _pv_panel(p, structure, pan["deformed"], pan.get("scalars"), pan.get("label", "value"),
                  pan["title"], pan.get("polylines"))
    with atomic_path(path) as tmp:
        p.screenshot(str(tmp))
    p.close()


# ---------------------------------------------------------------------- matplotlib
def _mpl_render(path: Path, panels: list[dict], structure, window: tuple[int, int]) -> None:
    from matplotlib import cm, colors

    from .io.figures import new_figure

    n = len(panels)
    cols = min(n, 3)
    rows = -(-n // cols)
    three = structure.dim == 3
    fig = new_figure(figsize=(window[0] * cols / 100, window[1] * rows / 100), dpi=100)
    conn = structure.connectivity
    for k, pan in enumerate(panels):
        ax = fig.add_subplot(rows, cols, k + 1, projection="3d" if three else None)
        x0 = structure.coords
        sc = pan.get("scalars")
        norm = None
        if sc is not None:
            sc = np.asarray(sc, float)
            vmax = float(np.nanmax(np.abs(sc))) or 1.0
            norm = colors.Normalize(-vmax, vmax)
        if pan.get("polylines") is not None:
            segs = pan["polylines"]                       # (m, s, dim)
        else:
            segs = pan["deformed"][conn]                  # (m, 2, dim)
        for i in range(conn.shape[0]):
            a = x0[conn[i]]
            ax.plot(*a.T, color="lightgrey", lw=1.5)
            col = cm.coolwarm(norm(sc[i])) if sc is not None else "tab:blue"
            ax.plot(*segs[i].T, color=col, lw=2.5)
        if sc is not None:
            fig.colorbar(cm.ScalarMappable(norm=norm, cmap="coolwarm"), ax=ax, shrink=0.7,
                         label=pan.get("label", "value"))
        ax.set_title(pan["title"], fontsize=9)
        if not three:
            ax.set_aspect("equal")
        ax.set_axis_off()
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png")


def _render(path, panels, structure, window, backend) -> Path:
    path = Path(path)
    backend = backend or plot_backend()
    if backend == "pyvista":
        try:
            _pv_render(path, panels, structure, window)
            return path
        except Exception as exc:  # a GL failure at render time: fall back, say why
            log.warning("pyvista rendering failed (%s); using matplotlib", exc)
    _mpl_render(path, panels, structure, window)
    return path


# ---------------------------------------------------------------------- public
def render_shape(path: str | Path, structure, displacement: np.ndarray,
                 scale: float | None = None, member_values: np.ndarray | None = None,
                 label: str = "axial_force", title: str = "deformed shape",
                 stations: np.ndarray | None = None, backend: str | None = None,
                 window: tuple[int, int] = (640, 480)) -> Path:
    """Render a deformed shape (undeformed in grey) to a PNG file.

    Parameters
    ----------
    path : str or Path
        Output PNG.
    structure : Structure
    displacement : ndarray, shape (n, dim)
        Nodal translations.
    scale : float, optional
        Magnification (default: largest translation drawn as 10 % of the model size).
    member_values : ndarray, shape (m,), optional
        Colours the members (e.g. axial force, N).
    label : str
        Name of ``member_values`` for the colour bar.
    title : str
    stations : ndarray, shape (m, s, dim), optional
        Translations along subdivided members at equally spaced stations: the members are
        drawn as deformed polylines (members' own bending visible).
    backend : {"pyvista", "matplotlib"}, optional
        Default :func:`plot_backend`.
    window : (int, int)
        Pixel size of the figure.

    Returns
    -------
    Path
    """
    d = np.asarray(displacement, float)
    if scale is None:
        both = d[None] if stations is None else np.concatenate(
            [d[None].reshape(1, -1, d.shape[-1]),
             np.asarray(stations, float).reshape(1, -1, d.shape[-1])], axis=1)
        scale = float(_auto_scale(structure, both)[0])
    pan = {"deformed": structure.coords + scale * d, "scalars": member_values,
           "label": label, "title": f"{title} (×{scale:.3g})"}
    if stations is not None:
        pan["polylines"] = _station_points(structure, np.asarray(stations, float), scale)
    return _render(path, [pan], structure, window, backend)


def _station_points(structure, stations: np.ndarray, scale: float) -> np.ndarray:
    m, s = stations.shape[:2]
    xi = np.linspace(0.0, 1.0, s)
    a = structure.coords[structure.connectivity[:, 0]]
    b = structure.coords[structure.connectivity[:, 1]]
    return a[:, None] + xi[None, :, None] * (b - a)[:, None] + scale * stations


def render_modes(path: str | Path, structure, node_shapes: np.ndarray,
                 titles: Sequence[str], stations: np.ndarray | None = None,
                 backend: str | None = None, window: tuple[int, int] = (420, 360)) -> Path:
    """Render a set of mode shapes (vibration or buckling) side by side to one PNG.

    Parameters
    ----------
    path : str or Path
    structure : Structure
    node_shapes : ndarray, shape (k, n, dim)
    titles : sequence of str
        One per mode (e.g. ``"mode 1: 44.6 Hz"``).
    stations : ndarray, shape (k, m, s, dim), optional
        Shapes along subdivided members.
    backend : {"pyvista", "matplotlib"}, optional
    window : (int, int)
        Pixel size of each panel.

    Returns
    -------
    Path
    """
    node_shapes = np.asarray(node_shapes, float)
    both = node_shapes.reshape(node_shapes.shape[0], -1, node_shapes.shape[-1])
    if stations is not None:
        st = np.asarray(stations, float)
        both = np.concatenate([both, st.reshape(st.shape[0], -1, st.shape[-1])], axis=1)
    scales = _auto_scale(structure, both)
    panels = []
    for i, t in enumerate(titles):
        pan = {"deformed": structure.coords + scales[i] * node_shapes[i], "title": t}
        if stations is not None:
            pan["polylines"] = _station_points(structure, stations[i], scales[i])
        panels.append(pan)
    return _render(path, panels, structure, window, backend)
