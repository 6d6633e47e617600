# SPDX-License-Identifier: MIT
"""Shared output of mode sets (vibration and buckling modes) for the command line."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..io.vtk import write_mode_set


def station_shapes(fe, shapes: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """Mode shapes along subdivided members, or ``None`` when no member is subdivided.

    Members with fewer elements than others (truss bars beside beams) have their stations
    NaN-padded at the end of their row, as :func:`trussfe.io.vtk.station_mesh` takes them.

    Returns
    -------
    (xi, values) : ndarray (m, s) and ndarray (k, m, s, dim)
    """
    k = np.asarray(fe.member_subdivisions)
    if k.size == 0 or k.max() < 2:
        return None
    j = np.arange(int(k.max()) + 1)
    xi = np.where(j[None, :] <= k[:, None], j[None, :] / k[:, None], np.nan)
    vals = np.stack([fe.station_displacements(shapes[:, i]) for i in range(shapes.shape[1])])
    return xi, vals


def write_modes_vtk(directory: str | Path, fe, shapes: np.ndarray, node_shapes: np.ndarray,
                    name: str, values: dict, cell_data: dict | None = None) -> list[Path]:
    """``DIR/<name>.pvd`` (a step per mode) and, for subdivided members,
    ``DIR/<name>_stations.pvd`` with the shapes along the members."""
    dim = fe.structure.dim
    return write_mode_set(directory, fe.structure, node_shapes[:, :, :dim], name,
                          values=values, stations=station_shapes(fe, shapes),
                          cell_data=cell_data)
