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

    A member carrying member loads is drawn through the stations of its JSON ``stations``
    (:func:`trussfe.fem.member_loads.loaded_member_stations`): its finite-element stations,
    its point loads (the section just after the load) and the points where a distributed
    load makes a shear force vanish, so that the moment between its finite-element stations
    (that of a pin-ended bar, which has none inside) is drawn and its largest von Mises
    stress is the member's ``max_von_mises``.  The displacement at a station between
    finite-element stations is interpolated linearly between them, so the deformed member
    is drawn as through its finite-element stations.

    Returns
    -------
    xi : ndarray, shape (m, s)
    fields : dict
        ``displacement`` (m, s, dim), ``axial_force`` (N), ``shear_y``, ``shear_z``,
        ``torque``, ``moment_y``, ``moment_z`` (member axes, N and N·m), ``von_mises_s1``,
        ``von_mises_s2``, ``von_mises`` (Pa), each (m, s).
    """
    s = result.structure
    L = s.lengths()
    xi = result.station_x / L[:, None]
    F = result.section_forces
    disp = fe_disp = result.fe.station_displacements(result.u)
    s1, s2 = result.von_mises_s1, result.von_mises_s2
    loaded = getattr(result, "loaded_stations", None)
    if loaded is not None and np.size(loaded[0]):
        from ..mechanics.stress import station_stresses   # as the JSON's von Mises
        lm, lx, lF = loaded
        lm = np.asarray(lm, dtype=int)
        width = max(xi.shape[1], lx.shape[1])

        def widen(a):
            out = np.full((a.shape[0], width) + a.shape[2:], np.nan)
            out[:, : a.shape[1]] = a
            return out

        xi, F, disp, s1, s2 = (widen(a) for a in (xi, F, disp, s1, s2))
        vm = station_stresses(s, lF, lm)
        ok = np.isfinite(lx)
        row = np.nonzero(ok)[0]
        col = (np.cumsum(ok, axis=1) - 1)[ok]          # each row's stations, packed first
        x = lx[ok]
        d = _interpolate_rows(x, row, result.station_x[lm], fe_disp[lm])
        for a in (xi, F, disp, s1, s2):
            a[lm] = np.nan
        at = lm[row]
        xi[at, col] = x / L[at]
        F[at, col] = lF[ok]
        disp[at, col] = d
        s1[at, col] = vm.s1[ok]
        s2[at, col] = vm.s2[ok]
    names = ("axial_force", "shear_y", "shear_z", "torque", "moment_y", "moment_z")
    fields = {n: F[:, :, i] for i, n in enumerate(names)}
    fields["displacement"] = disp
    fields["von_mises_s1"] = s1
    fields["von_mises_s2"] = s2
    fields["von_mises"] = np.fmax(s1, s2)
    return xi, fields


def _interpolate_rows(x: np.ndarray, row: np.ndarray, xp: np.ndarray, fp: np.ndarray
                      ) -> np.ndarray:
    """``numpy.interp`` row by row, for all rows at once: the values ``fp[r]`` (rows of
    (s, k), given at the ascending abscissae ``xp[r]``, NaN-padded at the end) at ``x``, the
    abscissa of row ``row``; clamped to a row's end values outside its abscissae."""
    good = np.isfinite(xp)
    count = good.sum(axis=1)
    start = np.concatenate([[0], np.cumsum(count)[:-1]])
    # one ascending key over all rows: each row's abscissae shifted past the row before
    span = np.nanmax(np.abs(xp)) if good.any() else 1.0
    shift = 4.0 * span + 1.0
    key = (xp + shift * np.arange(xp.shape[0])[:, None])[good]    # for the search only
    xs, vals = xp[good], fp[good]                                 # (points,), (points, k)
    at = np.searchsorted(key, x + shift * row, side="right") - 1
    lo = np.clip(at, start[row], start[row] + np.maximum(count[row] - 2, 0))
    hi = np.minimum(lo + 1, start[row] + count[row] - 1)
    width = xs[hi] - xs[lo]
    with np.errstate(invalid="ignore", divide="ignore"):
        frac = np.where(width > 0, (x - xs[lo]) / width, 0.0)
    frac = np.clip(frac, 0.0, 1.0)[:, None]
    return vals[lo] * (1.0 - frac) + vals[hi] * frac


def has_stations(result) -> bool:
    """Whether a static result has fields along its members worth a ``_stations`` file: beams
    (subdivided members) or member loads; a truss without member loads has none."""
    return bool(np.any(result.fe.is_frame) or result.member_loads is not None)


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
        Also write the fields along the members (:func:`static_station_fields`; the command
        writes them where :func:`has_stations`).

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
