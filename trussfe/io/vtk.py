# SPDX-License-Identifier: MIT
"""VTK output through meshio (docs/vtk.md): results that open in ParaView without plugins.

Members are ``line`` cells between the structure's nodes; results on nodes are point data,
results on members are cell data.  Names are snake_case and values SI:

=================  =========  ==========================================================
name               kind       meaning
=================  =========  ==========================================================
``displacement``   point      nodal displacement, m (3 components, z = 0 in 2-D)
``velocity``       point      nodal velocity, m/s
``acceleration``   point      nodal acceleration, m/s²
``reaction``       point      support reaction, N
``axial_force``    cell       member axial force, N, positive in tension
``axial_stress``   cell       axial stress, Pa
``von_mises``      cell       von Mises stress, Pa
``member_id``      cell       index of the member in the model (always written)
=================  =========  ==========================================================

Time series and mode sets are ``.pvd`` collections of ``.vtu`` files (:func:`write_series`).
Fields along subdivided members (stations) go to their own ``.vtu`` (:func:`write_stations`),
where every member is a polyline of line cells through its stations.

Every file is written to a temporary name and renamed, so a failure leaves no partial file.
"""
from __future__ import annotations

import logging
import os
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any
from xml.sax.saxutils import quoteattr

import meshio
import numpy as np

from ..errors import InputError
from .output import atomic_dir, atomic_path

__all__ = ["write_vtu", "write_pvd", "write_series", "write_stations", "station_mesh",
           "write_mode_set", "read_pvd"]

log = logging.getLogger(__name__)

ArrayMap = Mapping[str, Any] | None


# ---------------------------------------------------------------------- helpers
def _pad3(x: np.ndarray) -> np.ndarray:
    """Pad the last axis of a vector field to 3 components (ParaView's vectors are 3-D)."""
    x = np.asarray(x, dtype=float)
    if x.ndim >= 2 and x.shape[-1] == 2:
        pad = np.zeros(x.shape[:-1] + (3 - x.shape[-1],))
        x = np.concatenate([x, pad], axis=-1)
    return x


def _check_array(name: str, value: Any, n: int, where: str) -> np.ndarray:
    """A data array of first dimension ``n``, vectors padded to 3-D, non-finite values kept.

    VTK represents missing values as NaN, which ParaView shows as "no value"; we therefore keep
    NaN (e.g. a von Mises stress of a member without a section modulus) rather than invent one.
    """
    arr = np.asarray(value)
    if arr.dtype == bool:
        arr = arr.astype(np.int8)
    if arr.dtype.kind not in "iuf":
        raise InputError(f"vtk {where} data '{name}'", f"must be numeric, got {arr.dtype}")
    if arr.ndim == 0 or arr.shape[0] != n:
        raise InputError(f"vtk {where} data '{name}'",
                         f"has shape {arr.shape}; its first dimension must be {n}")
    if arr.ndim > 2:
        arr = arr.reshape(n, -1)
    if arr.dtype.kind == "f":
        arr = arr.astype(float)
        # 2-D nodal vectors get a zero z so that ParaView treats them as vectors.
        if where in ("point", "station") and arr.ndim == 2 and arr.shape[1] == 2:
            arr = _pad3(arr)
    return np.ascontiguousarray(arr)


def _points(structure, coords: np.ndarray | None) -> np.ndarray:
    x = structure.coords if coords is None else np.asarray(coords, dtype=float)
    if x.shape != structure.coords.shape:
        raise InputError("vtk coords", f"shape {x.shape} does not match the model's "
                         f"{structure.coords.shape}")
    return _pad3(x)


def structure_mesh(structure, coords: np.ndarray | None = None, point_data: ArrayMap = None,
                   cell_data: ArrayMap = None, field_data: ArrayMap = None) -> meshio.Mesh:
    """The :class:`meshio.Mesh` of a structure: its nodes and one line cell per member.

    Parameters
    ----------
    structure : Structure
        The model.
    coords : ndarray, shape (n, dim), optional
        Node positions to write (default the model's own); use them for a moved configuration,
        and put displacements in ``point_data["displacement"]`` so ParaView's *Warp By Vector*
        shows deformation.
    point_data : mapping name → array of shape (n, ...), optional
    cell_data : mapping name → array of shape (m, ...), optional
    field_data : mapping name → array_like, optional
        Whole-dataset values such as ``time`` or ``frequency_hz``.

    Returns
    -------
    meshio.Mesh
    """
    n, m = structure.n_nodes, structure.n_members
    pdata = {k: _check_array(k, v, n, "point") for k, v in (point_data or {}).items()}
    cdata = {k: [_check_array(k, v, m, "cell")] for k, v in (cell_data or {}).items()}
    cdata.setdefault("member_id", [np.arange(m, dtype=np.int64)])
    fdata = {k: np.atleast_1d(np.asarray(v, dtype=float)) for k, v in (field_data or {}).items()}
    return meshio.Mesh(_points(structure, coords),
                       [("line", np.asarray(structure.connectivity, dtype=np.int64))],
                       point_data=pdata, cell_data=cdata, field_data=fdata)


def _field_data_xml(field_data: Mapping[str, np.ndarray]) -> str:
    """``<FieldData>`` block (ASCII arrays; VTK allows mixed formats within one file)."""
    parts = ["<FieldData>"]
    for k, v in field_data.items():
        v = np.asarray(v, dtype=float).ravel()
        parts.append(f'<DataArray type="Float64" Name={quoteattr(k)} NumberOfTuples="{v.size}"'
                     f' format="ascii">' + " ".join(repr(float(x)) for x in v) + "</DataArray>")
    parts.append("</FieldData>")
    return "\n".join(parts) + "\n"


def _meshio_write(path: Path, mesh: meshio.Mesh) -> None:
    """``meshio.write`` as VTU, plus the field data that meshio's VTU writer leaves out."""
    meshio.write(path, mesh, file_format="vtu", binary=True, compression="zlib")
    if mesh.field_data:
        text = path.read_text()
        tag = "<UnstructuredGrid>"
        i = text.index(tag) + len(tag)
        path.write_text(text[:i] + "\n" + _field_data_xml(mesh.field_data) + text[i:])


def _write_mesh(path: str | Path, mesh: meshio.Mesh) -> Path:
    path = Path(path)
    if path.suffix != ".vtu":
        raise InputError(str(path), "VTK unstructured-grid output must end in .vtu")
    with atomic_path(path) as tmp:
        # The temporary name keeps the ".vtu" suffix.
        _meshio_write(tmp, mesh)
    log.info("wrote %s", path)
    return path


# ---------------------------------------------------------------------- public writers
def write_vtu(path: str | Path, structure, coords: np.ndarray | None = None,
              point_data: ArrayMap = None, cell_data: ArrayMap = None,
              field_data: ArrayMap = None) -> Path:
    """Write one configuration of a structure with its results as a ``.vtu`` file.

    Parameters
    ----------
    path : str or Path
        Output file, must end in ``.vtu``; parent folders are created.
    structure : Structure
    coords, point_data, cell_data, field_data
        As in :func:`structure_mesh`.  2-D vectors are padded to three components.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    InputError
        If an array's first dimension does not match the nodes or members.

    Examples
    --------
    >>> import tempfile, pathlib, numpy as np, meshio
    >>> from trussfe.model.structure import build_structure
    >>> from trussfe.model.sections import Section, Material
    >>> s = build_structure([[0, 0], [1, 0]], [[0, 1]], section=Section("s", 1e-4),
    ...                     material=Material("steel", 2e11, 7850.0))
    >>> p = write_vtu(pathlib.Path(tempfile.mkdtemp()) / "bar.vtu", s,
    ...               point_data={"displacement": [[0, 0], [1e-3, 0]]},
    ...               cell_data={"axial_force": [2e4]})
    >>> meshio.read(p).cell_data["axial_force"][0].tolist()
    [20000.0]
    """
    return _write_mesh(path, structure_mesh(structure, coords, point_data, cell_data,
                                            field_data))


def write_pvd(path: str | Path, entries: Iterable[tuple[float, str | Path]]) -> Path:
    """Write a ParaView collection (``.pvd``) listing ``.vtu`` files with their times.

    Parameters
    ----------
    path : str or Path
        The ``.pvd`` file.
    entries : iterable of (time_or_index, vtu_path)
        Time (or mode number) of each step and the file's path relative to the ``.pvd``'s
        folder (absolute paths are made relative when they lie under it).

    Returns
    -------
    Path
    """
    path = Path(path)
    if path.suffix != ".pvd":
        raise InputError(str(path), "a ParaView collection must end in .pvd")
    lines = ['<?xml version="1.0"?>',
             '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">',
             "  <Collection>"]
    for t, f in entries:
        t = float(t)
        if not np.isfinite(t):
            raise InputError(str(path), f"time step value {t} is not finite")
        f = Path(f)
        if f.is_absolute():
            f = Path(os.path.relpath(f, path.parent.resolve()))
        lines.append(f'    <DataSet timestep="{t!r}" group="" part="0" '
                     f"file={quoteattr(f.as_posix())}/>")
    lines += ["  </Collection>", "</VTKFile>", ""]
    with atomic_path(path) as tmp:
        tmp.write_text("\n".join(lines))
    log.info("wrote %s", path)
    return path


def read_pvd(path: str | Path) -> list[tuple[float, Path]]:
    """Read a ``.pvd`` collection back: (timestep, absolute file path) per data set."""
    import xml.etree.ElementTree as ET
    path = Path(path)
    root = ET.parse(path).getroot()
    return [(float(d.get("timestep")), path.parent / d.get("file"))
            for d in root.iter("DataSet")]


def write_series(directory: str | Path, structure, frames: Iterable[Mapping[str, Any]],
                 name: str) -> Path:
    """Write a time series or a set of modes as ``directory/name.pvd`` + one ``.vtu`` per frame.

    Parameters
    ----------
    directory : str or Path
        Output folder (created).  The ``.vtu`` files go to ``directory/name/``.
    structure : Structure
    frames : iterable of mapping
        One mapping per step with optional keys ``"time"`` (the pvd timestep: a time in s,
        or a mode number; default the frame index), ``"coords"``, ``"point_data"``,
        ``"cell_data"``, ``"field_data"`` (as in :func:`write_vtu`); or ``"mesh"``, a ready
        :class:`meshio.Mesh` (e.g. from :func:`station_mesh`), written as it is.
    name : str
        Base name of the collection.

    Returns
    -------
    Path
        The ``.pvd`` file.

    Notes
    -----
    All files are first written into a temporary folder and moved into ``directory`` only when
    every frame succeeded, so a failure leaves no partial series.
    """
    directory = Path(directory)
    if not name or "/" in name or "\\" in name:
        raise InputError("vtk series", f"invalid collection name {name!r}")
    entries = []
    with atomic_dir(directory) as tmp:
        for i, fr in enumerate(frames):
            rel = Path(name) / f"{name}_{i:04d}.vtu"
            mesh = fr.get("mesh") or structure_mesh(structure, fr.get("coords"),
                                                    fr.get("point_data"), fr.get("cell_data"),
                                                    fr.get("field_data"))
            (tmp / name).mkdir(exist_ok=True)
            _meshio_write(tmp / rel, mesh)
            entries.append((fr.get("time", i), rel))
        if not entries:
            raise InputError("vtk series", f"no frames to write for {name!r}")
        write_pvd(tmp / f"{name}.pvd", entries)
    log.info("wrote %s (%d steps)", directory / f"{name}.pvd", len(entries))
    return directory / f"{name}.pvd"


def station_mesh(structure, stations: np.ndarray, coords: np.ndarray | None = None,
                 point_data: ArrayMap = None, cell_data: ArrayMap = None,
                 field_data: ArrayMap = None) -> meshio.Mesh:
    """Mesh of fields along members: each member is a polyline through its stations.

    Parameters
    ----------
    structure : Structure
    stations : ndarray, shape (s,) or (m, s)
        Stations as fractions ξ ∈ [0, 1] of each member's length, ascending, at least two per
        member.  Members with fewer stations than others are NaN-padded at the end of their
        row (e.g. truss bars with 2 stations beside beams with k + 1); padded entries of the
        data arrays are ignored.
    coords : ndarray, shape (n, dim), optional
        Node positions defining the straight member axes (default the model's).
    point_data : mapping name → array of shape (m, s, ...)
        Values at the stations (e.g. ``displacement`` (m, s, dim), ``axial_force`` (m, s),
        ``bending_moment``, ``von_mises``).
    cell_data : mapping name → array of shape (m, s − 1, ...)
        Values on the segments between stations.
    field_data : mapping, optional

    Returns
    -------
    meshio.Mesh
        One point per station and one line cell per segment between consecutive stations
        (``m·s`` points and ``m·(s − 1)`` cells without padding); cell data ``member_id`` gives
        each segment's member and point data ``xi`` the station fraction.
    """
    m = structure.n_members
    xi = np.asarray(stations, dtype=float)
    if xi.ndim == 1:
        xi = np.broadcast_to(xi, (m, xi.size))
    if xi.ndim != 2 or xi.shape[0] != m or xi.shape[1] < 2:
        raise InputError("vtk stations", f"shape {np.shape(stations)}: need (s,) or ({m}, s) "
                         "with s >= 2")
    s = xi.shape[1]
    valid = np.isfinite(xi)                                          # (member, station)
    nvalid = valid.sum(axis=1)
    prefix = np.arange(s)[None, :] < nvalid[:, None]
    if np.any(valid != prefix) or np.any(nvalid < 2):
        raise InputError("vtk stations", "each member needs at least 2 stations; NaN padding "
                         "may only follow them")
    xf = np.where(valid, xi, 1.0)
    dx = np.diff(xf, axis=1)
    seg = valid[:, 1:]                                               # (member, segment)
    if np.any(dx[seg] <= 0) or xf.min() < 0 or xf.max() > 1:
        raise InputError("vtk stations", "stations must ascend within [0, 1]")
    x = structure.coords if coords is None else np.asarray(coords, dtype=float)
    xa, xb = x[structure.connectivity[:, 0]], x[structure.connectivity[:, 1]]  # (m, dim)
    pts = xa[:, None, :] + xf[:, :, None] * (xb - xa)[:, None, :]  # (member, station, dim)
    pts = _pad3(pts[valid])
    # point number of every valid station; segments join consecutive valid stations
    number = np.cumsum(valid.ravel()).reshape(m, s) - 1
    cells = np.stack([number[:, :-1][seg], number[:, 1:][seg]], axis=-1)
    pdata = {"xi": xi[valid]}
    for k, v in (point_data or {}).items():
        v = np.asarray(v)
        if v.shape[:2] != (m, s):
            raise InputError(f"vtk station data '{k}'",
                             f"has shape {v.shape}; need ({m}, {s}, ...)")
        pdata[k] = _check_array(k, v[valid], int(valid.sum()), "station")
    nseg = int(seg.sum())
    member = np.broadcast_to(np.arange(m, dtype=np.int64)[:, None], seg.shape)
    cdata = {"member_id": [member[seg]]}
    for k, v in (cell_data or {}).items():
        v = np.asarray(v)
        if v.shape[:2] != (m, s - 1):
            raise InputError(f"vtk segment data '{k}'",
                             f"has shape {v.shape}; need ({m}, {s - 1}, ...)")
        cdata[k] = [_check_array(k, v[seg], nseg, "segment")]
    fdata = {k: np.atleast_1d(np.asarray(v, dtype=float)) for k, v in (field_data or {}).items()}
    return meshio.Mesh(pts, [("line", cells)], point_data=pdata, cell_data=cdata,
                       field_data=fdata)


def write_stations(path: str | Path, structure, stations: np.ndarray,
                   coords: np.ndarray | None = None, point_data: ArrayMap = None,
                   cell_data: ArrayMap = None, field_data: ArrayMap = None) -> Path:
    """Write fields along subdivided members to a ``.vtu`` file (see :func:`station_mesh`).

    Examples
    --------
    >>> import tempfile, pathlib, numpy as np, meshio
    >>> from trussfe.model.structure import build_structure
    >>> from trussfe.model.sections import Section, Material
    >>> s = build_structure([[0, 0], [2, 0]], [[0, 1]], section=Section("s", 1e-4),
    ...                     material=Material("steel", 2e11, 7850.0))
    >>> xi = np.linspace(0, 1, 5)
    >>> moment = (xi * (1 - xi))[None, :]            # (member, station)
    >>> p = write_stations(pathlib.Path(tempfile.mkdtemp()) / "st.vtu", s, xi,
    ...                    point_data={"bending_moment": moment})
    >>> mesh = meshio.read(p)
    >>> mesh.points.shape, mesh.cells_dict["line"].shape
    ((5, 3), (4, 2))
    """
    return _write_mesh(path, station_mesh(structure, stations, coords, point_data, cell_data,
                                          field_data))


def write_mode_set(directory: str | Path, structure, node_shapes: np.ndarray, name: str,
                   values: Mapping[str, np.ndarray] | None = None,
                   stations: tuple[np.ndarray, np.ndarray] | None = None,
                   cell_data: Mapping[str, np.ndarray] | None = None) -> list[Path]:
    """Write mode shapes (vibration or buckling) as one ``.pvd`` with a step per mode.

    Parameters
    ----------
    directory : str or Path
    structure : Structure
    node_shapes : ndarray, shape (k, n, dim)
        Translations of each mode at the nodes.  Written as point data ``mode_shape`` as
        given and as ``displacement`` scaled to a largest nodal translation of 1, so that
        ParaView's *Warp By Vector* with a scale factor of a length shows every mode alike.
    name : str
        Collection name (``modes``, ``buckling``).
    values : mapping name → ndarray (k,), optional
        Per-mode scalars written as field data (``frequency_hz``, ``load_factor``); the pvd
        timestep is the mode number 1..k.
    stations : (xi, shapes), optional
        Shapes along subdivided members: ``xi`` (m, s) fractions and ``shapes``
        (k, m, s, dim); written as a second collection ``<name>_stations.pvd`` (polylines,
        :func:`station_mesh`) scaled by the same factor as ``displacement``.
    cell_data : mapping name → ndarray (m,) or (k, m), optional
        Member data (e.g. ``buckling_utilisation``, ``axial_force``), the same for every mode
        when 1-D.

    Returns
    -------
    list of Path
        The ``.pvd`` files written.
    """
    node_shapes = np.asarray(node_shapes, dtype=float)
    k = node_shapes.shape[0]
    amp = np.linalg.norm(node_shapes, axis=2).max(axis=1)                 # (k,)
    if stations is not None:
        amp = np.fmax(amp, np.nanmax(np.linalg.norm(stations[1], axis=3), axis=(1, 2)))
    scale = np.where(amp > 0, 1.0 / np.where(amp > 0, amp, 1.0), 0.0)
    values = dict(values or {})
    cells = dict(cell_data or {})
    frames = []
    for i in range(k):
        fd = {key: float(np.asarray(v)[i]) for key, v in values.items()}
        fd["mode"] = i + 1
        cd = {key: (np.asarray(v)[i] if np.ndim(v) == 2 else v) for key, v in cells.items()}
        frames.append({"time": i + 1, "field_data": fd, "cell_data": cd,
                       "point_data": {"mode_shape": node_shapes[i],
                                      "displacement": node_shapes[i] * scale[i]}})
    out = [write_series(directory, structure, frames, name)]
    if stations is not None:
        xi, shp = stations
        sframes = [{"time": i + 1, "mesh": station_mesh(
            structure, xi, point_data={"mode_shape": shp[i], "displacement": shp[i] * scale[i]},
            field_data={**{key: float(np.asarray(v)[i]) for key, v in values.items()},
                        "mode": i + 1})} for i in range(k)]
        out.append(write_series(directory, structure, sframes, f"{name}_stations"))
    return out
