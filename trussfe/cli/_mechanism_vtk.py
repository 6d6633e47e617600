# SPDX-License-Identifier: MIT
"""VTK output of the mechanism commands, written with :mod:`trussfe.io.vtk` (ParaView opens it
as is).

Line cells are the members; point data ``displacement`` holds a mechanism shape (or the motion
from the start state along a trace); cell data ``self_stress`` a state of self-stress.  A set of
shapes or a path is a ``.pvd`` collection of ``.vtu`` files.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..io.output import atomic_dir
from ..io.vtk import write_pvd, write_vtu


def _write_vtu(path: Path, structure, coords=None, point_data=None, cell_data=None) -> None:
    """One configuration through :func:`trussfe.io.vtk.write_vtu` (2-D vectors padded)."""
    write_vtu(path, structure, coords=coords, point_data=point_data, cell_data=cell_data)


def _write_pvd(path: Path, entries: list[tuple[float, str]]) -> None:
    write_pvd(path, entries)


def write_rank_vtk(directory: str | Path, structure, result) -> None:
    """Mechanism shapes (``mechanism_NN.vtu``) and self-stress states (``self_stress_NN.vtu``)."""
    n, dim = structure.coords.shape
    fidx = np.flatnonzero(result.free.ravel())
    with atomic_dir(directory) as tmp:
        entries = []
        bases = [("mechanism", result.mechanism_basis), ("rigid_body", result.rigid_body_basis)]
        for prefix, basis in bases:
            for k in range(basis.shape[1]):
                d = np.zeros(n * dim)
                d[fidx] = basis[:, k]
                name = f"{prefix}_{k + 1:02d}.vtu"
                _write_vtu(tmp / name, structure,
                           point_data={"displacement": d.reshape(n, dim)})
                entries.append((len(entries), name))
        if entries:
            _write_pvd(tmp / "mechanisms.pvd", entries)
        if result.self_stress_basis is not None and result.self_stress_basis.shape[1]:
            st = []
            for k in range(result.self_stress_basis.shape[1]):
                name = f"self_stress_{k + 1:02d}.vtu"
                _write_vtu(tmp / name, structure,
                           cell_data={"self_stress": result.self_stress_basis[:, k]})
                st.append((k, name))
            _write_pvd(tmp / "self_stress.pvd", st)
        _write_vtu(tmp / "structure.vtu", structure)


def write_trace_vtk(directory: str | Path, structure, trace) -> None:
    """One ``step_NNNN.vtu`` per state (point data ``displacement`` from the start) and
    ``path.pvd`` with the path parameter as time."""
    with atomic_dir(directory) as tmp:
        entries = []
        for k, x in enumerate(trace.coords):
            name = f"step_{k:04d}.vtu"
            _write_vtu(tmp / name, structure, coords=x,
                       point_data={"displacement": x - trace.coords[0]})
            entries.append((float(trace.parameter[k]), name))
        _write_pvd(tmp / "path.pvd", entries)
