# SPDX-License-Identifier: MIT
"""The structural model: one source of truth for every solver.

Inside, everything is an integer-indexed array; string ids live only in ``node_ids`` and
``member_ids`` and are used at the I/O edge.

Array conventions (``n`` nodes, ``m`` members, ``dim`` = 2 or 3)::

    coords       (n, dim)      node coordinates, m
    connectivity (m, 2)        start and end node index of each member
    supports     (n, ndof)     True where a DOF is fixed; ndof = 3 (2-D: x, y, rz) or 6 (3-D)
    loads        (n, ndof)     nodal forces (and moments), N (N·m)
    masses       (n,)          lumped masses, kg
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from .ids import IdRange, id_index
from .sections import Material, Section

#: Names of the nodal DOFs, in the order of the ``supports`` and ``loads`` columns.
DOF_NAMES = {2: ("x", "y", "rz"), 3: ("x", "y", "z", "rx", "ry", "rz")}


@dataclass
class Structure:
    """A bar-and-joint (or frame) structure.

    Attributes
    ----------
    name : str
        Model name.
    dim : int
        Spatial dimension, 2 or 3.
    node_ids : sequence of str
        Node ids, index = node number (a list, or an :class:`~trussfe.model.ids.IdRange` for
        a mesh model's "0", "1", …).
    coords : ndarray, shape (n, dim)
        Node coordinates, m.
    member_ids : sequence of str
        Member ids, index = member number (list or :class:`~trussfe.model.ids.IdRange`).
    connectivity : ndarray of int, shape (m, 2)
        Start and end node of each member.
    sections, materials : list
        :class:`Section` and :class:`Material` of each member.
    is_beam : ndarray of bool, shape (m,)
        True for ``type = "beam"`` (rigid joints), False for pin-jointed bars.
    releases : ndarray of bool, shape (m, 2)
        Bending-moment releases of a beam at its start and end.
    torsion_releases : ndarray of bool, shape (m, 2)
        Explicit torsion releases of a 3-D beam at its start and end (what a release frees:
        :mod:`trussfe.mechanics.releases`).
    orientation : ndarray, shape (m, 3)
        For 3-D beams, a vector in the local x–y plane (``nan`` row: default orientation).
    supports : ndarray of bool, shape (n, ndof)
    loads : ndarray, shape (n, ndof)
    masses : ndarray, shape (n,)
    gravity : ndarray, shape (dim,)
    extensions : dict
        Tables added by other analyses (e.g. ``active_members``), parsed by their readers.
    source : str
        File the model was read from ("" when built in code), for error messages.
    """

    name: str
    dim: int
    node_ids: list[str]
    coords: np.ndarray
    member_ids: list[str]
    connectivity: np.ndarray
    sections: list[Section]
    materials: list[Material]
    is_beam: np.ndarray
    releases: np.ndarray
    supports: np.ndarray
    loads: np.ndarray
    masses: np.ndarray
    gravity: np.ndarray
    orientation: np.ndarray | None = None
    torsion_releases: np.ndarray | None = None
    extensions: dict[str, Any] = field(default_factory=dict)
    source: str = ""

    def __post_init__(self) -> None:
        self.coords = np.asarray(self.coords, dtype=float)
        self.connectivity = np.asarray(self.connectivity, dtype=np.int64).reshape(-1, 2)
        m = len(self.member_ids)
        self.is_beam = np.asarray(self.is_beam, dtype=bool).reshape(m)
        self.releases = np.asarray(self.releases, dtype=bool).reshape(m, 2)
        self.torsion_releases = (np.zeros((m, 2), dtype=bool) if self.torsion_releases is None
                                 else np.asarray(self.torsion_releases, dtype=bool).reshape(m, 2))
        if self.orientation is None:
            self.orientation = np.full((m, 3), np.nan)
        self._node_index: dict[str, int] | None = None
        self._member_index: dict[str, int] | None = None

    # ------------------------------------------------------------------ sizes and lookups
    @property
    def n_nodes(self) -> int:
        """Number of nodes."""
        return len(self.node_ids)

    @property
    def n_members(self) -> int:
        """Number of members."""
        return len(self.member_ids)

    @property
    def ndof_node(self) -> int:
        """Number of DOF columns of ``supports`` and ``loads`` (3 in 2-D, 6 in 3-D)."""
        return 3 if self.dim == 2 else 6

    def node_index(self, node_id: str) -> int:
        """Index of the node with id ``node_id`` (KeyError if absent)."""
        if self._node_index is None:
            self._node_index = id_index(self.node_ids)
        return self._node_index[str(node_id)]

    def member_index(self, member_id: str) -> int:
        """Index of the member with id ``member_id`` (KeyError if absent)."""
        if self._member_index is None:
            self._member_index = id_index(self.member_ids)
        return self._member_index[str(member_id)]

    # ------------------------------------------------------------------ member properties
    def _prop(self, objs: list, attr: str) -> np.ndarray:
        # Members share few section/material objects: look each distinct object up once.
        cache = self.__dict__.setdefault("_prop_cache", {})
        key = ("_groups", id(objs), len(objs))
        if key not in cache:
            ids = np.fromiter((id(o) for o in objs), dtype=np.int64, count=len(objs))
            cache[key] = np.unique(ids, return_index=True, return_inverse=True)[1:]
        first, inverse = cache[key]
        values = np.array([getattr(objs[i], attr) for i in first], dtype=float)
        return values[inverse] if len(objs) else np.zeros(0)

    @property
    def area(self) -> np.ndarray:
        """Cross-sectional area of each member, m², shape (m,)."""
        return self._cached("area", lambda: self._prop(self.sections, "area"))

    @property
    def Iy(self) -> np.ndarray:
        """Second moment of area about local y, m⁴, shape (m,)."""
        return self._cached("Iy", lambda: self._prop(self.sections, "Iy"))

    @property
    def Iz(self) -> np.ndarray:
        """Second moment of area about local z, m⁴, shape (m,)."""
        return self._cached("Iz", lambda: self._prop(self.sections, "Iz"))

    @property
    def J(self) -> np.ndarray:
        """Torsion constant, m⁴, shape (m,)."""
        return self._cached("J", lambda: self._prop(self.sections, "J"))

    @property
    def c(self) -> np.ndarray:
        """Outer-fibre distance, m, shape (m,)."""
        return self._cached("c", lambda: self._prop(self.sections, "c"))

    @property
    def E(self) -> np.ndarray:
        """Young's modulus of each member, Pa, shape (m,)."""
        return self._cached("E", lambda: self._prop(self.materials, "E"))

    @property
    def G(self) -> np.ndarray:
        """Shear modulus of each member, Pa, shape (m,)."""
        return self._cached("G", lambda: self._prop(self.materials, "G"))

    @property
    def density(self) -> np.ndarray:
        """Mass density of each member, kg/m³, shape (m,)."""
        return self._cached("density", lambda: self._prop(self.materials, "density"))

    @property
    def yield_strength(self) -> np.ndarray:
        """Yield strength of each member, Pa (nan if unknown), shape (m,)."""
        return self._cached("yield", lambda: self._prop(self.materials, "yield_strength"))

    def _cached(self, key: str, fn):
        cache = self.__dict__.setdefault("_prop_cache", {})
        if key not in cache:
            cache[key] = fn()
        return cache[key]

    # ------------------------------------------------------------------ geometry
    def member_vectors(self, coords: np.ndarray | None = None) -> np.ndarray:
        """End-to-end vectors x_end − x_start, shape (m, dim)."""
        x = self.coords if coords is None else coords
        return x[self.connectivity[:, 1]] - x[self.connectivity[:, 0]]

    def lengths(self, coords: np.ndarray | None = None) -> np.ndarray:
        """Member lengths, m, shape (m,)."""
        return np.linalg.norm(self.member_vectors(coords), axis=1)

    def unit_vectors(self, coords: np.ndarray | None = None) -> np.ndarray:
        """Member unit vectors from start to end node, shape (m, dim)."""
        v = self.member_vectors(coords)
        return v / np.linalg.norm(v, axis=1)[:, None]

    @property
    def member_mass(self) -> np.ndarray:
        """Mass ρAL of each member, kg, shape (m,)."""
        return self.density * self.area * self.lengths()

    @property
    def translation_supports(self) -> np.ndarray:
        """Fixed translational DOFs, shape (n, dim)."""
        return self.supports[:, : self.dim]

    def with_coords(self, coords: np.ndarray) -> "Structure":
        """A copy of the structure at other node positions (same topology and data)."""
        new = replace(self, coords=np.array(coords, dtype=float))
        return new

    def copy(self) -> "Structure":
        """A deep-enough copy: arrays copied, sections and materials shared."""
        return replace(
            self,
            node_ids=_copy_ids(self.node_ids), coords=self.coords.copy(),
            member_ids=_copy_ids(self.member_ids), connectivity=self.connectivity.copy(),
            sections=list(self.sections), materials=list(self.materials),
            is_beam=self.is_beam.copy(), releases=self.releases.copy(),
            torsion_releases=self.torsion_releases.copy(),
            supports=self.supports.copy(), loads=self.loads.copy(), masses=self.masses.copy(),
            gravity=np.array(self.gravity, dtype=float), orientation=self.orientation.copy(),
            extensions=dict(self.extensions),
        )

    def subset_members(self, keep: np.ndarray) -> "Structure":
        """A copy holding only the members where ``keep`` is True (nodes unchanged)."""
        keep = np.asarray(keep, dtype=bool)
        idx = np.flatnonzero(keep)
        s = self.copy()
        s.member_ids = [self.member_ids[i] for i in idx]
        s.connectivity = self.connectivity[idx]
        s.sections = [self.sections[i] for i in idx]
        s.materials = [self.materials[i] for i in idx]
        s.is_beam = self.is_beam[idx]
        s.releases = self.releases[idx]
        s.torsion_releases = self.torsion_releases[idx]
        s.orientation = self.orientation[idx]
        s.__dict__.pop("_prop_cache", None)
        s._member_index = None
        return s


def build_structure(
    nodes: dict[str, list[float]] | np.ndarray,
    members: list[tuple[int, int]] | np.ndarray,
    *,
    section: Section,
    material: Material,
    supports: dict[int, str] | None = None,
    loads: dict[int, list[float]] | None = None,
    masses: dict[int, float] | None = None,
    gravity: list[float] | None = None,
    is_beam: bool | np.ndarray = False,
    name: str = "structure",
    node_ids: list[str] | None = None,
    member_ids: list[str] | None = None,
) -> Structure:
    """Build a :class:`Structure` in code, with one section and material for all members.

    Parameters
    ----------
    nodes : array_like, shape (n, dim)
        Node coordinates.
    members : array_like of int, shape (m, 2)
        Start and end node indices.
    section, material : Section, Material
        Applied to every member.
    supports : dict, optional
        Node index → string of fixed DOF letters, e.g. ``{0: "xyz"}``; or a list of DOF names.
    loads : dict, optional
        Node index → force vector (translational, optionally followed by moments).
    masses : dict, optional
        Node index → lumped mass.
    gravity : sequence, optional
        Gravitational acceleration vector.
    is_beam : bool or array of bool
        Member type(s).

    Returns
    -------
    Structure
    """
    coords = np.asarray(nodes, dtype=float)
    n, dim = coords.shape
    conn = np.asarray(members, dtype=np.int64).reshape(-1, 2)
    m = conn.shape[0]
    ndof = 3 if dim == 2 else 6
    names = DOF_NAMES[dim]
    sup = np.zeros((n, ndof), dtype=bool)
    for k, dofs in (supports or {}).items():
        letters = list(dofs) if isinstance(dofs, str) and len(dofs) <= 3 and all(
            ch in "xyz" for ch in dofs) else list(dofs)
        for d in letters:
            sup[k, names.index(d)] = True
    ld = np.zeros((n, ndof))
    for k, f in (loads or {}).items():
        f = np.asarray(f, dtype=float)
        ld[k, : f.size] = f
    ms = np.zeros(n)
    for k, v in (masses or {}).items():
        ms[k] = v
    g = np.zeros(dim) if gravity is None else np.asarray(gravity, dtype=float)
    return Structure(
        name=name, dim=dim,
        node_ids=node_ids or [str(i) for i in range(n)], coords=coords,
        member_ids=member_ids or [str(i) for i in range(m)], connectivity=conn,
        sections=[section] * m, materials=[material] * m,
        is_beam=np.broadcast_to(np.asarray(is_beam, dtype=bool), (m,)).copy(),
        releases=np.zeros((m, 2), dtype=bool), supports=sup, loads=ld, masses=ms, gravity=g,
    )


def _copy_ids(ids):
    # an IdRange is immutable: share it rather than spell out every id
    return ids if isinstance(ids, IdRange) else list(ids)
