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

A :class:`Structure` is immutable: its arrays are read-only, its sections and materials are
tuples, and the per-member properties (``area``, ``E``, …) are computed once, when it is made.
A variant of a model is a new model, made by the ``with_…`` methods::

    stiffer = s.with_sections({"M3": Section.tube("big", 0.05, 0.04)})
    loaded = s.with_loads(new_loads)
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import InitVar, dataclass, field, fields
from typing import Any

import numpy as np

from . import geometry
from .extensions import freeze_extensions, subset_extensions
from .sealed import sealed
from .ids import IdRange, id_index
from .properties import MemberProperties, member_properties
from .sections import Material, Section

#: Names of the nodal DOFs, in the order of the ``supports`` and ``loads`` columns.
DOF_NAMES = {2: ("x", "y", "rz"), 3: ("x", "y", "z", "rx", "ry", "rz")}


@dataclass(frozen=True, eq=False)
class Structure:
    """A bar-and-joint (or frame) structure; immutable.

    Attributes
    ----------
    name : str
        Model name.
    dim : int
        Spatial dimension, 2 or 3.
    node_ids : tuple of str
        Node ids, index = node number (a tuple, or an :class:`~trussfe.model.ids.IdRange` for
        a mesh model's "0", "1", …).
    coords : ndarray, shape (n, dim)
        Node coordinates, m.
    member_ids : tuple of str
        Member ids, index = member number (tuple or :class:`~trussfe.model.ids.IdRange`).
    connectivity : ndarray of int, shape (m, 2)
        Start and end node of each member.
    sections, materials : tuple
        :class:`Section` and :class:`Material` of each member.
    is_beam : ndarray of bool, shape (m,)
        True for ``type = "beam"`` (rigid joints), False for pin-jointed bars.
    releases : ndarray of bool, shape (m, 2)
        Bending-moment releases of a beam at its start and end.
    torsion_releases : ndarray of bool, shape (m, 2)
        Explicit torsion releases of a 3-D beam at its start and end (what a release frees:
        :mod:`trussfe.mechanics.releases`).
    bending_axis_releases : ndarray of bool, shape (m, 2, 2)
        Releases of one bending moment alone, per end and axis ``(my, mz)`` (about local y,
        about local z) of a 3-D beam; ``releases`` releases both.
    orientation : ndarray, shape (m, 3)
        For 3-D beams, a vector in the local x–y plane (``nan`` row: default orientation).
    supports : ndarray of bool, shape (n, ndof)
    loads : ndarray, shape (n, ndof)
    masses : ndarray, shape (n,)
    gravity : ndarray, shape (dim,)
    extensions : mapping
        Typed tables of other analyses, read-only (:mod:`trussfe.model.extensions`).
    source : str
        File the model was read from ("" when built in code), for error messages.
    member_groups : ndarray of int, shape (m,), optional
        Construction only: a code per member such that members with equal codes share their
        section and material objects (a mesh reader's cell-set code); it spares the pass over
        every member that otherwise finds which members share them.

    Notes
    -----
    Every array is read-only (``flags.writeable`` is False) and the constructor copies an
    array it is given unless that array is already read-only, so neither the caller nor a
    solver can change a model behind the back of the properties computed from it.  Variants
    are new models: :meth:`with_coords`, :meth:`with_sections`, :meth:`with_materials`,
    :meth:`with_loads`, :meth:`with_supports`, :meth:`with_masses`, :meth:`with_gravity`,
    :meth:`with_member_data`, :meth:`with_extensions`, :meth:`subset_members`, and
    :meth:`variant` for any other field.

    Two models compare equal only when they are the same object, and hash by identity: a
    model is a value that never changes, so it can key a dictionary, but comparing the
    contents of two models (float arrays, ``nan`` orientations) is left to the caller.
    """

    name: str
    dim: int
    node_ids: Sequence[str]
    coords: np.ndarray
    member_ids: Sequence[str]
    connectivity: np.ndarray
    sections: tuple[Section, ...]
    materials: tuple[Material, ...]
    is_beam: np.ndarray
    releases: np.ndarray
    supports: np.ndarray
    loads: np.ndarray
    masses: np.ndarray
    gravity: np.ndarray
    orientation: np.ndarray | None = None
    torsion_releases: np.ndarray | None = None
    bending_axis_releases: np.ndarray | None = None
    extensions: Mapping[str, Any] = field(default_factory=dict)
    source: str = ""
    member_groups: InitVar[np.ndarray | None] = None

    def __post_init__(self, member_groups: np.ndarray | None) -> None:
        self._freeze(None, member_groups)

    def _freeze(self, properties: MemberProperties | None,
                member_groups: np.ndarray | None = None) -> None:
        """Normalise every field to its immutable form and compute the member properties."""
        put = object.__setattr__
        dim = int(self.dim)
        if dim not in (2, 3):
            raise ValueError(f"dim must be 2 or 3, got {self.dim!r}")
        node_ids, member_ids = _frozen_ids(self.node_ids), _frozen_ids(self.member_ids)
        n, m = len(node_ids), len(member_ids)
        ndof = 3 if dim == 2 else 6
        sections, materials = tuple(self.sections), tuple(self.materials)
        if len(sections) != m or len(materials) != m:
            raise ValueError(f"{m} members but {len(sections)} sections and "
                             f"{len(materials)} materials")
        put(self, "dim", dim)
        put(self, "node_ids", node_ids)
        put(self, "member_ids", member_ids)
        put(self, "sections", sections)
        put(self, "materials", materials)
        put(self, "coords", _frozen_array(self.coords, float, (n, dim), "coords"))
        put(self, "connectivity", _frozen_array(self.connectivity, np.int64, (m, 2),
                                                "connectivity"))
        put(self, "is_beam", _frozen_array(self.is_beam, bool, (m,), "is_beam"))
        put(self, "releases", _frozen_array(self.releases, bool, (m, 2), "releases"))
        tors = np.zeros((m, 2), dtype=bool) if self.torsion_releases is None \
            else self.torsion_releases
        put(self, "torsion_releases", _frozen_array(tors, bool, (m, 2), "torsion_releases"))
        axes = np.zeros((m, 2, 2), dtype=bool) if self.bending_axis_releases is None \
            else self.bending_axis_releases
        put(self, "bending_axis_releases", _frozen_array(axes, bool, (m, 2, 2),
                                                         "bending_axis_releases"))
        orient = np.full((m, 3), np.nan) if self.orientation is None else self.orientation
        put(self, "orientation", _frozen_array(orient, float, (m, 3), "orientation"))
        put(self, "supports", _frozen_array(self.supports, bool, (n, ndof), "supports"))
        put(self, "loads", _frozen_array(self.loads, float, (n, ndof), "loads"))
        put(self, "masses", _frozen_array(self.masses, float, (n,), "masses"))
        put(self, "gravity", _frozen_array(self.gravity, float, (dim,), "gravity"))
        put(self, "extensions", freeze_extensions(self.extensions, m, (n, ndof)))
        put(self, "_properties", properties if properties is not None
            else member_properties(sections, materials, member_groups))
        put(self, "_node_index", None)
        put(self, "_member_index", None)

    def __getstate__(self) -> dict[str, Any]:
        state = {f.name: getattr(self, f.name) for f in fields(self)}
        state["extensions"] = dict(self.extensions)       # a mappingproxy does not pickle
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        # unpickled arrays come back writable: freeze them again (pickle, copy.deepcopy)
        self.__dict__.update(state)
        self._freeze(None)

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
        if self._node_index is None:       # built on first use: the ids never change
            object.__setattr__(self, "_node_index", id_index(self.node_ids))
        return self._node_index[str(node_id)]

    def member_index(self, member_id: str) -> int:
        """Index of the member with id ``member_id`` (KeyError if absent)."""
        if self._member_index is None:
            object.__setattr__(self, "_member_index", id_index(self.member_ids))
        return self._member_index[str(member_id)]

    # ------------------------------------------------------------------ member properties
    @property
    def member_properties(self) -> MemberProperties:
        """Section and material properties of every member (computed with the model)."""
        return self._properties

    @property
    def area(self) -> np.ndarray:
        """Cross-sectional area of each member, m², shape (m,)."""
        return self._properties.area

    @property
    def Iy(self) -> np.ndarray:
        """Second moment of area about local y, m⁴, shape (m,)."""
        return self._properties.Iy

    @property
    def Iz(self) -> np.ndarray:
        """Second moment of area about local z, m⁴, shape (m,)."""
        return self._properties.Iz

    @property
    def J(self) -> np.ndarray:
        """Torsion constant, m⁴, shape (m,)."""
        return self._properties.J

    @property
    def c(self) -> np.ndarray:
        """Outer-fibre distance, m, shape (m,)."""
        return self._properties.c

    @property
    def shear_area_y(self) -> np.ndarray:
        """Effective shear area κA for shear along local y, m² (nan: none), shape (m,)."""
        return self._properties.shear_area_y

    @property
    def shear_area_z(self) -> np.ndarray:
        """Effective shear area κA for shear along local z, m² (nan: none), shape (m,)."""
        return self._properties.shear_area_z

    @property
    def E(self) -> np.ndarray:
        """Young's modulus of each member, Pa, shape (m,)."""
        return self._properties.E

    @property
    def G(self) -> np.ndarray:
        """Shear modulus of each member, Pa, shape (m,)."""
        return self._properties.G

    @property
    def density(self) -> np.ndarray:
        """Mass density of each member, kg/m³, shape (m,)."""
        return self._properties.density

    @property
    def yield_strength(self) -> np.ndarray:
        """Yield strength of each member, Pa (nan if unknown), shape (m,)."""
        return self._properties.yield_strength

    # ------------------------------------------------------------------ geometry
    def member_vectors(self, coords: np.ndarray | None = None) -> np.ndarray:
        """End-to-end vectors x_end − x_start, shape (m, dim)."""
        return geometry.member_vectors(self.coords if coords is None else coords,
                                       self.connectivity)

    def lengths(self, coords: np.ndarray | None = None) -> np.ndarray:
        """Member lengths, m, shape (m,)."""
        return geometry.lengths(self.member_vectors(coords))

    def unit_vectors(self, coords: np.ndarray | None = None) -> np.ndarray:
        """Member unit vectors from start to end node, shape (m, dim)."""
        return geometry.unit_vectors(self.member_vectors(coords))[0]

    @property
    def member_mass(self) -> np.ndarray:
        """Mass ρAL of each member, kg, shape (m,)."""
        return self.density * self.area * self.lengths()

    @property
    def translation_supports(self) -> np.ndarray:
        """Fixed translational DOFs, shape (n, dim)."""
        return self.supports[:, : self.dim]

    # ------------------------------------------------------------------ variants
    def variant(self, **changes: Any) -> "Structure":
        """A new model with the given fields changed (checked as by the constructor).

        The member properties are carried over unless ``sections`` or ``materials`` change.

        Examples
        --------
        >>> from trussfe.model import Material, Section, build_structure
        >>> s = build_structure([[0, 0], [1, 0]], [(0, 1)], section=Section("a", area=1e-4),
        ...                     material=Material("m", E=2e11, G=8e10), name="one bar")
        >>> s.variant(name="renamed").name, s.name
        ('renamed', 'one bar')
        """
        same_members = not {"sections", "materials", "member_ids"} & set(changes)
        return self._derive(changes, self._properties if same_members else None)

    def _derive(self, changes: dict[str, Any], properties: MemberProperties | None
                ) -> "Structure":
        unknown = sorted(set(changes) - _FIELD_NAMES)
        if unknown:
            raise TypeError(f"Structure has no field {unknown[0]!r}")
        new = object.__new__(Structure)
        new.__dict__.update(self.__dict__)
        if properties is not None and _NODE_DATA.issuperset(changes):
            # node data only (a structure at each step of a motion): check what changed
            shapes = {"coords": (self.n_nodes, self.dim), "masses": (self.n_nodes,),
                      "loads": (self.n_nodes, self.ndof_node), "gravity": (self.dim,),
                      "supports": (self.n_nodes, self.ndof_node)}
            for key, value in changes.items():
                object.__setattr__(new, key, _frozen_array(
                    value, bool if key == "supports" else float, shapes[key], key))
            return new
        for key, value in changes.items():
            object.__setattr__(new, key, value)
        new._freeze(properties)
        return new

    def with_coords(self, coords: np.ndarray) -> "Structure":
        """The structure at other node positions (same topology and data)."""
        return self.variant(coords=coords)

    def with_loads(self, loads: np.ndarray) -> "Structure":
        """The structure under other nodal loads, shape (n, ndof) or (n, dim) (no moments)."""
        return self.variant(loads=self._node_table(loads, float, "loads"))

    def with_supports(self, supports: np.ndarray) -> "Structure":
        """The structure on other supports, shape (n, ndof) or (n, dim) (rotations free)."""
        return self.variant(supports=self._node_table(supports, bool, "supports"))

    def with_masses(self, masses: np.ndarray) -> "Structure":
        """The structure with other lumped node masses, shape (n,), kg."""
        return self.variant(masses=masses)

    def with_gravity(self, gravity: Sequence[float]) -> "Structure":
        """The structure under another gravitational acceleration, shape (dim,), m/s²."""
        return self.variant(gravity=gravity)

    def with_sections(self, sections: Mapping[int | str, Section] | Sequence[Section]
                      ) -> "Structure":
        """The structure with other member sections.

        Parameters
        ----------
        sections : mapping or sequence
            Member (index or id) → :class:`Section` for the members that change, or one
            section per member.
        """
        return self.variant(sections=self._per_member(self.sections, sections, "sections"))

    def with_materials(self, materials: Mapping[int | str, Material] | Sequence[Material]
                       ) -> "Structure":
        """The structure with other member materials (a mapping member → material, or one
        material per member, as :meth:`with_sections`)."""
        return self.variant(
            materials=self._per_member(self.materials, materials, "materials"))

    def with_member_data(self, *, is_beam=None, releases=None, orientation=None,
                         torsion_releases=None, bending_axis_releases=None) -> "Structure":
        """The structure with other member types, moment releases or beam orientations.

        Each argument is either a whole array (shapes (m,), (m, 2), (m, 3); (m, 2, 2) for
        ``bending_axis_releases``) or a mapping
        member (index or id) → the value of that member, e.g.
        ``releases={"M1": (True, False)}`` releases the start of beam M1.
        """
        changes = {}
        for key, value in (("is_beam", is_beam), ("releases", releases),
                           ("orientation", orientation),
                           ("torsion_releases", torsion_releases),
                           ("bending_axis_releases", bending_axis_releases)):
            if value is None:
                continue
            if isinstance(value, Mapping):
                arr = np.array(getattr(self, key))
                for k, v in value.items():
                    arr[self._member(k)] = v
                value = arr
            changes[key] = value
        return self.variant(**changes)

    def with_extensions(self, **tables: Any) -> "Structure":
        """The structure with extension tables replaced or added (``None`` drops a table).

        Examples
        --------
        >>> from trussfe.model import Material, Section, build_structure
        >>> s = build_structure([[0, 0], [1, 0]], [(0, 1)], section=Section("a", area=1e-4),
        ...                     material=Material("m", E=2e11, G=8e10))
        >>> dict(s.with_extensions(postcritical={"steps": 5}).extensions)
        {'postcritical': PostcriticalSettings(control=None, steps=5, step=None, \
max_step=None, max_load_factor=None, monitor=None, bar_model=None, subdivisions=None, \
imperfection=None, branch=None, max_displacement=None)}
        """
        return self.variant(extensions={**self.extensions, **tables})

    def without_extensions(self, *names: str) -> "Structure":
        """The structure without the named extension tables (all of them if none named)."""
        drop = set(names) if names else set(self.extensions)
        return self.variant(extensions={k: v for k, v in self.extensions.items()
                                        if k not in drop})

    def subset_members(self, keep: np.ndarray) -> "Structure":
        """The structure of only the members where ``keep`` is True (nodes unchanged).

        Extension tables follow the members: the active members and actuators of removed
        members are dropped, the others renumbered.
        """
        idx = np.flatnonzero(np.asarray(keep, dtype=bool))
        props = MemberProperties(*(sealed(np.array(getattr(self._properties, f.name)[idx]))
                                   for f in fields(MemberProperties)))
        return self._derive(dict(
            member_ids=tuple(self.member_ids[i] for i in idx),
            connectivity=self.connectivity[idx],
            sections=tuple(self.sections[i] for i in idx),
            materials=tuple(self.materials[i] for i in idx),
            is_beam=self.is_beam[idx], releases=self.releases[idx],
            torsion_releases=self.torsion_releases[idx],
            bending_axis_releases=self.bending_axis_releases[idx],
            orientation=self.orientation[idx],
            extensions=subset_extensions(self.extensions, idx)), props)

    # ------------------------------------------------------------------ helpers
    def _member(self, key: int | str) -> int:
        if isinstance(key, (int, np.integer)):
            if not -self.n_members <= key < self.n_members:
                raise IndexError(f"member index {key} out of range")
            return int(key) % self.n_members
        return self.member_index(key)

    def _per_member(self, current: tuple, change, what: str) -> tuple:
        if isinstance(change, Mapping):
            out = list(current)
            for k, v in change.items():
                out[self._member(k)] = v
            return tuple(out)
        out = tuple(change)
        if len(out) != self.n_members:
            raise ValueError(f"{what}: expected one per member ({self.n_members}), "
                             f"got {len(out)}")
        return out

    def _node_table(self, values, dtype, what: str) -> np.ndarray:
        a = np.asarray(values, dtype=dtype)
        if a.ndim == 2 and a.shape == (self.n_nodes, self.dim) and self.dim != self.ndof_node:
            full = np.zeros((self.n_nodes, self.ndof_node), dtype=dtype)
            full[:, : self.dim] = a
            return full
        return a


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
        sections=(section,) * m, materials=(material,) * m,
        is_beam=np.broadcast_to(np.asarray(is_beam, dtype=bool), (m,)).copy(),
        releases=np.zeros((m, 2), dtype=bool), supports=sup, loads=ld, masses=ms, gravity=g,
        member_groups=np.zeros(m, dtype=np.int64),     # one section and material for all
    )


_FIELD_NAMES = frozenset(f.name for f in fields(Structure))
#: Fields whose change leaves every member datum and id as it is.
_NODE_DATA = frozenset(("coords", "loads", "supports", "masses", "gravity"))


def _frozen_ids(ids: Sequence[str]) -> Sequence[str]:
    # an IdRange is immutable already: keep it rather than spell out every id
    return ids if isinstance(ids, (IdRange, tuple)) else tuple(ids)


def _frozen_array(value, dtype, shape: tuple[int, ...], name: str) -> np.ndarray:
    """``value`` as a read-only array of ``dtype`` and ``shape``.

    An array that is read-only already, and whose memory no writable array owns, is shared
    (a model's arrays pass unchanged to its variants); anything else is copied, so the
    caller keeps a writable array that the model no longer sees.
    """
    if (isinstance(value, np.ndarray) and value.dtype == dtype and not value.flags.writeable
            and (value.base is None or (isinstance(value.base, np.ndarray)
                                        and not value.base.flags.writeable))):
        a = value
    else:
        a = np.array(value, dtype=dtype)
    if a.shape != shape:
        if a.size != int(np.prod(shape)):
            raise ValueError(f"{name}: expected shape {shape}, got {a.shape}")
        a = a.reshape(shape)
    return sealed(a)
