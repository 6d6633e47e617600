# SPDX-License-Identifier: MIT
"""VTK files of analysis results: a static solution with the fields along its members.

:func:`write_static` writes the VTK file (docs/vtk.md) of a :class:`~trussfe.fem.StaticResult`
and, beside it, ``<name>_stations.vtu`` with the section forces, von Mises stresses and
displacements at every station of every member (members subdivided by the pinned-beam model or
beams show their bending along their length).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from .vtk import write_stations, write_vtu

#: Section-force components of ``StaticResult.section_forces`` (member axes).
SECTION_FORCES = ("N", "Vy", "Vz", "T", "My", "Mz")


def static_station_fields(result) -> tuple[np.ndarray, dict]:
    """Stations (fractions of the member length, NaN-padded) and the point data along
    members of a static result.

    Returns
    -------
    xi : ndarray, shape (m, kmax + 1)
    fields : dict
        ``displacement`` (m, s, dim), ``axial_force`` (N), ``shear_y``, ``shear_z``,
        ``torque``, ``moment_y``, ``moment_z`` (member axes, N and N·m), ``von_mises_s1``,
        ``von_mises_s2``, ``von_mises`` (Pa), each (m, s).
    """
    s = result.structure
    xi = result.station_x / s.lengths()[:, None]
    F = result.section_forces
    names = ("axial_force", "shear_y", "shear_z", "torque", "moment_y", "moment_z")
    fields = {n: F[:, :, i] for i, n in enumerate(names)}
    fields["displacement"] = result.fe.station_displacements(result.u)
    fields["von_mises_s1"] = result.von_mises_s1
    fields["von_mises_s2"] = result.von_mises_s2
    fields["von_mises"] = np.fmax(result.von_mises_s1, result.von_mises_s2)
    return xi, fields


def write_static(path: str | Path, result, stations: bool = True) -> list[Path]:
    """Write a static result: ``path`` (nodes and members) and ``<stem>_stations.vtu``.

    Parameters
    ----------
    path : str or Path
        The ``.vtu`` file.  Point data ``displacement``, ``reaction``; cell data
        ``axial_force`` (midpoint), ``axial_stress``, ``strain``, ``von_mises`` (largest over
        the member).
    result : StaticResult
    stations : bool
        Also write the fields along the members (:func:`static_station_fields`).

    Returns
    -------
    list of Path
    """
    s = result.structure
    dim = s.dim
    path = Path(path)
    out = [write_vtu(path, s, point_data={"displacement": result.displacements[:, :dim],
                                          "reaction": result.reactions[:, :dim]},
                     cell_data={"axial_force": result.axial_force,
                                "axial_stress": result.axial_stress,
                                "strain": result.strain, "von_mises": result.max_von_mises})]
    if stations:
        xi, fields = static_station_fields(result)
        out.append(write_stations(path.with_name(path.stem + "_stations.vtu"), s, xi,
                                  point_data=fields))
    return out
