# SPDX-License-Identifier: MIT
"""Discretisation of a :class:`~trussfe.model.structure.Structure` into finite elements.

Every member is cut into ``k`` sub-elements.  All sub-elements of one kind (axial-only truss
bars, or frames) are held by one scikit-fem ``MeshLine1`` in which each sub-element is a
disjoint segment ``[0, h_e]`` on its own local axis ("exploded" mesh: points ``2e, 2e+1``).
The forms of :mod:`trussfe.fem.forms` are assembled on that mesh, giving block-diagonal
*local* matrices; one sparse transformation ``T`` from global DOFs to local field DOFs gives

.. math:: K = T^T K_\\ell T, \\qquad M = T^T M_\\ell T, \\qquad f = T^T f_\\ell .

``T = S G`` where ``G`` gathers, for each sub-element, its end DOFs in member axes (rotation to
member axes, interior points, end releases, joint numbering) and ``S`` selects the field DOFs
(``θy = −w'``).

Global DOFs
-----------
* every node: ``dim`` translations (global axes);
* rotations (1 in 2-D, 3 in 3-D, global axes) only at nodes where a frame member attaches
  without a moment release;
* interior points of subdivided frame members: translations and rotations in member axes
  (no twist DOF where torsion is suppressed, see below);
* a member end rotation that is the end's own (:mod:`trussfe.mechanics.releases`): a private
  DOF in member axes (2-D: θz; 3-D: twist, θy, θz).  A released end owns its bending
  rotations; it owns its twist too where the joint has no rotational stiffness from a rigid
  beam end or a rotational support (a ball joint), or where torsion is released explicitly.
  A member free to twist at both ends has its start twist held (it cannot spin).

Bar models (docs/cli.md, ``--bar-model``)
---------------------------
``truss``: bars are axial-only two-node elements (``k = 1``) with P1 transverse fields that
carry mass and geometric stiffness only; their self-weight is lumped half to each end node
(MSC/PAL practice).  ``pinned-beam``: bars are frame members with both end moments released
and torsion suppressed (twist θ = 0 along the member), subdivided, carrying their self-weight
in bending.  Members of type ``beam`` are frames in both models.

Local axes
----------
Those of :mod:`trussfe.mechanics.geometry`: x runs from the start to the end node; 2-D: y = x
rotated by +90°; 3-D: y from the member's ``orientation`` vector, else the global Z axis (the
global X axis for a vertical member) made orthogonal to x; z = x × y.
"""
from __future__ import annotations

import logging
import weakref
from dataclasses import dataclass
from dataclasses import field as dc_field
from typing import Callable

import numpy as np
import scipy.sparse as sp
from skfem import Basis, ElementLineHermite, ElementLineP1, MeshLine1, asm

from ..budget import count_text, require
from ..errors import InputError
from ..linalg.ordering import Points
from ..mechanics.geometry import local_axes, member_vectors, unit_vectors
from ..mechanics.member_loads import (deflection_shapes, rotation_shapes, shear_parameter,
                                      slope_shapes)
from ..mechanics.mass import mass_per_length, twist_inertia_per_length
from ..mechanics.dof_numbering import frame_members, member_end_rotations, number_dofs
from ..mechanics.releases import JOINT, OWN
from ..model.bar_models import BAR_MODELS, DEFAULT_FRAME_SUBDIVISIONS
from ..model.structure import Structure
from . import forms

log = logging.getLogger(__name__)


#: Quadrature order: exact for the Hermite consistent mass (degree 6).
_INTORDER = 6


#: Peak memory of a linear solve per finite element, bytes (measured 5.6–6 KiB per 3-D
#: pinned-beam element from 72,000 to 720,000 elements: assembly, COO/CSR copies, factor).
BYTES_PER_ELEMENT = 8192


@dataclass
class _Field:
    name: str
    basis: Basis
    comps: tuple[int, ...]      # element component of each element DOF of the basis
    signs: tuple[float, ...]
    offset: int = 0

    @property
    def hermite(self) -> bool:
        return isinstance(self.basis.elem, ElementLineHermite)


@dataclass
class _Group:
    """The sub-elements of one kind ("bar" or "frame") on one exploded mesh.

    The scikit-fem bases, the selection ``S`` and the transformation ``T`` are built on first
    use (``build`` gives them): the global matrices of truss bars are assembled without them
    (:meth:`FEModel._bar_matrix`), so a large pin-jointed model never pays for them.
    """

    kind: str
    elements: np.ndarray            # global element numbers, (n_el_g,)
    ncomp: int                      # element DOF components per end
    build: Callable = dc_field(repr=False)   # () -> dict(fields, n_local, S, G_coo, T)
    _parts: dict | None = dc_field(default=None, repr=False)
    size: int | None = None         # n_local when known without building
    _G: sp.csr_matrix | None = None
    _K_local: sp.csr_matrix | None = None
    _K_global: sp.csr_matrix | None = None   # bar groups: global stiffness, once assembled
    _elongation: tuple | None = None         # bar groups: (B, EA/L), FEModel.bar_elongation

    def _part(self, name: str):
        if self._parts is None:
            self._parts = self.build()
        return self._parts[name]

    @property
    def fields(self) -> list[_Field]:
        """The fields (u, v, w, θ) of this group with their scikit-fem bases."""
        return self._part("fields")

    @property
    def n_local(self) -> int:
        """Size of the local (field) vector."""
        return self.size if self.size is not None else self._part("n_local")

    @property
    def S(self) -> sp.csc_matrix:
        """Field DOFs <- element components."""
        return self._part("S")

    @property
    def T(self) -> sp.csr_matrix:
        """Field DOFs <- global DOFs, ``S @ G``."""
        return self._part("T")

    @property
    def G(self) -> sp.csr_matrix:
        """Element components (member axes) <- global DOFs."""
        if self._G is None:
            coo = self._part("G_coo")
            vals, rows, cols, shape = coo() if callable(coo) else coo
            self._G = sp.csr_matrix((vals, (rows, cols)), shape=shape)
        return self._G

    def field(self, name: str) -> _Field | None:
        for f in self.fields:
            if f.name == name:
                return f
        return None


def _exploded_mesh(h: np.ndarray) -> MeshLine1:
    """One disjoint segment [0, h_e] per element."""
    n = h.size
    p = np.zeros((1, 2 * n))
    p[0, 1::2] = h
    t = np.ascontiguousarray(np.arange(2 * n, dtype=np.int64).reshape(n, 2).T)
    return MeshLine1(p, t)


_REFERENCE: dict | None = None


def reference_bar() -> dict:
    """The P1 forms of :mod:`trussfe.fem.forms` assembled by scikit-fem on one element of unit
    length with unit coefficients.

    On an element ``[0, h]`` the P1 shape functions are those of ``[0, 1]`` in ``ξ = x/h``, so
    ``∫ c u' v' dx = (c/h) ∫ u_ξ v_ξ dξ`` and ``∫ c u v dx = c h ∫ u v dξ``: a two-node bar's
    matrices are these reference matrices times one scalar per element.

    Returns
    -------
    dict
        ``"stiffness"`` (2, 2): ∫ u' v' (axial and geometric stiffness, scaled by EA/L or N/L);
        ``"mass"`` (2, 2): ∫ u v (scaled by ρAL); ``"load"`` (2,): ∫ v (scaled by qL).

    Examples
    --------
    >>> ref = reference_bar()
    >>> [(c * ref[k]).round(12).tolist() for k, c in (("stiffness", 1), ("mass", 6),
    ...                                                 ("load", 2))]
    [[[1.0, -1.0], [-1.0, 1.0]], [[2.0, 1.0], [1.0, 2.0]], [1.0, 1.0]]
    """
    global _REFERENCE
    if _REFERENCE is None:
        basis = Basis(_exploded_mesh(np.ones(1)), ElementLineP1(), intorder=_INTORDER)
        one = np.ones((1, basis.X.shape[-1]))
        _REFERENCE = {
            "stiffness": asm(forms.axial_stiffness, basis, EA=one).toarray(),
            "mass": asm(forms.mass, basis, rhoA=one).toarray(),
            "load": asm(forms.distributed_load, basis, q=one),
        }
    return _REFERENCE


def node_diagonal_blocks(n_nodes: int, ends: np.ndarray, ref: np.ndarray,
                         blocks: np.ndarray) -> np.ndarray:
    """Σ over the bars at each node of ``ref[0, 0]`` (bar starts there) or ``ref[1, 1]``
    (bar ends there) times the bar's block: one product with the node-by-bar incidence.

    Parameters
    ----------
    ends : ndarray of int, shape (e, 2)
    ref : ndarray, shape (2, 2)
    blocks : ndarray, shape (e, c)
        Any number ``c`` of block entries per bar.

    Returns
    -------
    ndarray, shape (n_nodes, c)
    """
    ne = ends.shape[0]
    incidence = sp.csc_matrix((np.tile([ref[0, 0], ref[1, 1]], ne), ends.ravel(),
                               np.arange(0, 2 * ne + 1, 2)), shape=(n_nodes, ne))
    return incidence @ blocks


def _node_block_matrix(n_nodes: int, dim: int, ends: np.ndarray, ref: np.ndarray,
                       blocks: np.ndarray, n_dof: int) -> sp.csr_matrix:
    """Σ over bars of ``ref ⊗ blocks[e]`` on the translations of the bars' two end nodes.

    Parameters
    ----------
    n_nodes, dim : int
    ends : ndarray of int, shape (e, 2)
        Start and end node of every bar.
    ref : ndarray, shape (2, 2)
        Reference matrix over the two ends (see :func:`reference_bar`), symmetric.
    blocks : ndarray, shape (e, dim, dim)
        Symmetric per-bar block, already scaled (e.g. EA/L · e eᵀ).
    n_dof : int
        Order of the result; node ``i``'s translations are DOFs ``dim·i … dim·i + dim − 1``.

    Returns
    -------
    scipy.sparse.csr_matrix, shape (n_dof, n_dof)
        Canonical (sorted, summed) and without stored zeros.

    Notes
    -----
    The matrix is built as a block-sparse (BSR) matrix with one ``dim × dim`` block per node
    pair: the diagonal blocks are summed per node with ``bincount``, the off-diagonal ones are
    one per bar and direction, so one sort of ``n + 2e`` block keys replaces the sort of the
    ``(2·dim)² e`` entries of a COO assembly.
    """
    a, b = ends[:, 0], ends[:, 1]
    ne = a.size
    flat = blocks.reshape(-1, dim * dim)                          # (bar, dim·dim)
    touched = np.bincount(ends.ravel(), minlength=n_nodes) > 0
    diag = node_diagonal_blocks(n_nodes, ends, ref, flat)         # (node, dim·dim)
    nodes = np.flatnonzero(touched)
    rows = np.concatenate([nodes, a, b])
    cols = np.concatenate([nodes, b, a])
    order = np.argsort(rows * n_nodes + cols, kind="stable")
    rows, cols = rows[order], cols[order]
    # blocks written once, without temporaries, then permuted as whole blocks (one
    # dim·dim-double record each): fresh memory is the main cost of large models
    nn = nodes.size
    data = np.empty((nn + 2 * ne, dim * dim))
    data[:nn] = diag[nodes]
    np.multiply(flat, ref[0, 1], out=data[nn:nn + ne])
    if ref[1, 0] == ref[0, 1]:                 # symmetric reference (always, in practice)
        data[nn + ne:] = data[nn:nn + ne]
    else:
        np.multiply(flat, ref[1, 0], out=data[nn + ne:])
    record = np.dtype((np.void, data.itemsize * dim * dim))
    data = data.view(record).ravel()[order].view(np.float64).reshape(-1, dim * dim)
    indptr = np.zeros(n_nodes + 1, dtype=np.int64)
    np.cumsum(np.bincount(rows, minlength=n_nodes), out=indptr[1:])
    K = sp.bsr_matrix((data.reshape(-1, dim, dim), cols, indptr),
                      shape=(n_nodes * dim, n_nodes * dim))
    if np.any((rows[1:] == rows[:-1]) & (cols[1:] == cols[:-1])):
        K.sum_duplicates()                                        # two bars on one node pair
    K = K.tocsr()
    K.eliminate_zeros()
    if n_dof > K.shape[0]:                                         # rotations etc. follow
        indptr = np.concatenate([K.indptr, np.full(n_dof - K.shape[0], K.indptr[-1])])
        K = sp.csr_matrix((K.data, K.indices, indptr), shape=(n_dof, n_dof))
    K.has_sorted_indices = True
    K.has_canonical_format = True        # sorted, one entry per position (summed above)
    return K


def _field_matrix(f, edofs: np.ndarray, vals: np.ndarray) -> sp.csr_matrix:
    """The matrix of one field of a group (its basis's ``N`` DOFs) from element blocks
    ``vals`` (el, k, k) on the element DOFs ``edofs`` (el, k)."""
    rows = np.broadcast_to(edofs[:, :, None], vals.shape)
    cols = np.broadcast_to(edofs[:, None, :], vals.shape)
    n = f.basis.N
    return sp.csr_matrix((vals.ravel(), (rows.ravel(), cols.ravel())), shape=(n, n))


def _qp(basis: Basis, values: np.ndarray) -> np.ndarray:
    """Per-element values broadcast to the quadrature points, shape (n_el, n_qp)."""
    return np.repeat(np.asarray(values, dtype=float)[:, None], basis.X.shape[-1], axis=1)


class FEModel:
    """A structure discretised into truss and frame elements on local axes.

    Build it with :func:`discretise`.

    Attributes
    ----------
    structure : Structure
    bar_model : str
        ``"truss"`` or ``"pinned-beam"``.
    subdivisions : int
        Sub-elements per frame member (truss bars always have one).
    n_dof : int
        Number of global DOFs.
    node_dofs : ndarray of int, shape (n_nodes, ndof_node)
        Global DOF of each node DOF (columns x, y, (z), (rx, ry), rz); −1 where absent.
    fixed : ndarray of bool, shape (n_dof,)
        Supported DOFs.
    free : ndarray of int
        Indices of the free DOFs.
    element_member : ndarray of int, shape (n_elements,)
        Member of each element; elements of a member are consecutive, start to end.
    element_x : ndarray, shape (n_elements, 2)
        Stations (distance from the member's start node) of each element's ends.
    member_elements : ndarray of int, shape (m + 1,)
        Member i owns elements ``member_elements[i]:member_elements[i+1]``.
    member_subdivisions : ndarray of int, shape (m,)
    is_frame : ndarray of bool, shape (m,)
        Member modelled as a frame (beam elements).
    rotation : ndarray, shape (m, dim, dim)
        Member axes, rows = local x, y, (z) (see :func:`local_axes`).
    """

    def __init__(self, structure: Structure, bar_model: str = "truss",
                 subdivisions: int | None = None):
        if bar_model not in BAR_MODELS:
            raise InputError("--bar-model", f"unknown bar model {bar_model!r}; use one of "
                             + ", ".join(BAR_MODELS))
        k = DEFAULT_FRAME_SUBDIVISIONS if subdivisions is None else subdivisions
        if int(k) != k or k < 1:
            raise InputError("--subdivisions", f"must be a positive integer, got {k!r}")
        # refuse a mesh that cannot fit in memory before any element array exists
        m = structure.n_members
        n_frame = int(np.count_nonzero(structure.is_beam)) if bar_model == "truss" else m
        n_el = n_frame * int(k) + (m - n_frame)
        require(n_el * BYTES_PER_ELEMENT, "--subdivisions",
                f"{count_text(n_el)} elements ({n_frame:,} frame members x "
                f"{count_text(k)} subdivisions)",
                "use fewer subdivisions")
        self.structure = structure
        self.bar_model = bar_model
        self.subdivisions = int(k)
        self._build()

    # ------------------------------------------------------------------ construction
    def _build(self) -> None:
        s = self.structure
        dim = s.dim
        nrot = 1 if dim == 2 else 3
        self.ndim = dim
        self.nrot = nrot
        m = s.n_members
        conn = s.connectivity
        # one pass over the member vectors for the lengths and the unit vectors (local_axes'
        # first row, by the same arithmetic)
        self._axis, L = unit_vectors(member_vectors(s.coords, conn))
        self._rotation = None
        is_frame = frame_members(s, self.bar_model)
        if np.any(is_frame) or np.any(np.isfinite(s.orientation)):
            self.rotation                      # frame axes needed now; bad orientations fail here
        self.is_frame = is_frame
        # released ends: beams as given; pinned-beam bars both ends
        released = np.where(s.is_beam[:, None], s.releases, True) & is_frame[:, None]
        self.released = released
        # torsion exists in beams only (pinned-beam bars: θ = 0 along the member)
        self.twist_member = s.is_beam & (dim == 3)
        # what each end rotation is (joint's, the end's own, or held): one definition
        er = member_end_rotations(s, self.bar_model, self._axis)
        self.end_rotations = er
        self._check_properties(is_frame)

        numbering = number_dofs(s, self.bar_model, self.subdivisions, er)
        ksub = numbering.member_subdivisions
        self.member_subdivisions = ksub
        offs = np.zeros(m + 1, dtype=np.int64)
        np.cumsum(ksub, out=offs[1:])
        self.member_elements = offs
        n_el = int(offs[-1])
        emem = np.repeat(np.arange(m), ksub)
        j = np.arange(n_el) - offs[emem]                      # position within member
        self.element_member = emem
        h = L[emem] / ksub[emem]
        self.element_x = np.stack([j * h, (j + 1) * h], axis=1)
        self.element_length = h

        # ---- global DOF numbering (mechanics.dof_numbering)
        node_dofs = numbering.node_dofs
        self.has_rotation = numbering.has_rotation
        pt_off = numbering.interior_offset
        self.n_dof = numbering.n_dof
        self.node_dofs = node_dofs
        self.interior_dofs = numbering.interior_dofs
        self.interior_member = numbering.interior_member
        self.private_dofs = numbering.private_dofs

        # ---- supports
        fixed = np.zeros(self.n_dof, dtype=bool)
        sup = s.supports
        cols = np.r_[np.arange(dim), dim + np.arange(nrot)]      # DOF columns of supports
        # structure.supports columns: 2-D x,y,rz; 3-D x,y,z,rx,ry,rz — same order as node_dofs
        gd = node_dofs[:, cols]
        hit = (sup[:, : dim + nrot] & (gd >= 0))
        hit[:, dim:] |= er.joint_rotation_held        # joints with rotations from supports only
        fixed[gd[hit]] = True
        self.fixed = fixed
        self.free = np.flatnonzero(~fixed)
        self.spring_stiffness = self._node_diagonal("springs", "stiffness", cols, "springs")

        # ---- element end points: joint node or interior point
        first = j == 0
        last = j == ksub[emem] - 1
        start_pt = pt_off[emem] + j - 1          # interior point index when not at a joint
        end_pt = pt_off[emem] + j
        ends = [(first, conn[emem, 0], start_pt), (last, conn[emem, 1], end_pt)]

        self.groups: list[_Group] = []
        # the groups build their parts through a weak reference to the model: a strong one
        # would close a reference cycle (model → group → build → model) that only Python's
        # cyclic collector frees, keeping the model's arrays (hundreds of MB for a large
        # grid) alive after its last use, and the next analysis in fresh, unmapped memory
        model = weakref.ref(self)
        for kind, sel in (("bar", ~is_frame[emem]), ("frame", is_frame[emem])):
            els = np.flatnonzero(sel)
            if els.size:
                ncomp = (dim + nrot) if kind == "frame" else dim
                self.groups.append(_Group(
                    kind=kind, elements=els, ncomp=ncomp,
                    # bars: dim P1 fields, two points per element on the exploded mesh
                    size=2 * dim * els.size if kind == "bar" else None,
                    build=lambda kind=kind, els=els: model()._group(
                        kind, els, h[els], ends, emem, released)))
        self.n_elements = n_el
        log.info("discretised %d members into %d elements, %d DOFs (%s model)",
                 m, n_el, self.n_dof, self.bar_model)

    def _node_diagonal(self, table: str, attr: str, cols: np.ndarray, item: str
                       ) -> np.ndarray | None:
        """A per-node, per-DOF table of the structure's extensions (springs, rotary inertia)
        as a global diagonal, shape (n_dof,); None when the model has no such table.

        Raises
        ------
        InputError
            A value on a rotation the node does not have (a pin joint).
        """
        data = self.structure.extensions.get(table)
        if data is None:
            return None
        values = getattr(data, attr)
        gd = self.node_dofs[:, cols[-values.shape[1]:]]
        lost = (values != 0.0) & (gd < 0)
        if np.any(lost):
            from ..model.structure import DOF_NAMES
            i, c = np.argwhere(lost)[0]
            names = DOF_NAMES[self.ndim][-values.shape[1]:]
            err = InputError(f"{item}.{self.structure.node_ids[i]}",
                             f"acts on rotation {names[c]}, which this node does not have (a "
                             "pin joint: no beam is rigidly attached); remove it")
            # the model file where there is one, as the reader's errors name it
            raise err.with_file(self.structure.source) if self.structure.source else err
        diag = np.zeros(self.n_dof)
        ok = gd >= 0
        np.add.at(diag, gd[ok], values[ok])
        return diag

    @property
    def rotation(self) -> np.ndarray:
        """Member axes, shape (m, dim, dim), rows = local x, y, (z) (:func:`local_axes`);
        made on first use (a truss needs only the first row, :attr:`axis`)."""
        if self._rotation is None:
            self._rotation = local_axes(self.structure)
        return self._rotation

    @property
    def axis(self) -> np.ndarray:
        """Unit vector of every member from start to end node, shape (m, dim): the first
        row of :attr:`rotation`, by the same arithmetic."""
        return self._axis

    def _check_properties(self, is_frame: np.ndarray) -> None:
        s = self.structure
        checks = [("area", "area", np.ones(s.n_members, bool)),
                  ("E", "E", np.ones(s.n_members, bool))]
        # bending and torsion properties are looked at only where a member needs them
        if np.any(is_frame):
            checks += [("Iz", "Iz", is_frame)] if s.dim == 2 else [
                ("Iy", "Iy", is_frame), ("Iz", "Iz", is_frame)]
        if s.dim == 3 and np.any(s.is_beam):
            checks += [("J", "J", s.is_beam), ("G", "G", s.is_beam)]
        for name, attr, need in checks:
            values = getattr(s, attr)
            bad = need & ~(np.isfinite(values) & (values > 0))
            if np.any(bad):
                i = int(np.flatnonzero(bad)[0])
                owner = (f"materials.{s.materials[i].name}" if name in ("E", "G")
                         else f"sections.{s.sections[i].name}")
                why = ("beam members bend" if not (self.bar_model == "pinned-beam"
                                                   and not s.is_beam[i])
                       else "--bar-model pinned-beam makes bars bend")
                if name in ("area", "E"):
                    why = "every member needs it"
                err = InputError(owner, f"{name} is missing or not positive (member "
                                 f"{s.member_ids[i]}); {why}: give a positive {name}")
                raise err.in_file(s.source)

    def _group(self, kind, els, h, ends, emem, released) -> dict:
        """Bases, field layout, ``S``, ``G`` and ``T`` of one element group."""
        dim, nrot = self.ndim, self.nrot
        mesh = _exploded_mesh(h)
        P1 = Basis(mesh, ElementLineP1(), intorder=_INTORDER)
        frame = kind == "frame"
        ncomp = dim + nrot if frame else dim
        c1 = ncomp                                             # first component of end 2
        if not frame:
            names = ("u", "v", "w")[:dim]
            fields = [_Field(nm, P1, (i, c1 + i), (1.0, 1.0)) for i, nm in enumerate(names)]
        else:
            H = Basis(mesh, ElementLineHermite(), intorder=_INTORDER)
            if dim == 2:
                fields = [_Field("u", P1, (0, c1), (1.0, 1.0)),
                          _Field("v", H, (1, 2, c1 + 1, c1 + 2), (1.0, 1.0, 1.0, 1.0))]
            else:
                fields = [_Field("u", P1, (0, c1), (1.0, 1.0)),
                          _Field("v", H, (1, 5, c1 + 1, c1 + 5), (1.0, 1.0, 1.0, 1.0)),
                          _Field("w", H, (2, 4, c1 + 2, c1 + 4), (1.0, -1.0, 1.0, -1.0)),
                          _Field("theta", P1, (3, c1 + 3), (1.0, 1.0))]
        ne = els.size
        nc2 = 2 * ncomp
        # S: field DOFs <- element components.  Every element component is exactly one
        # field DOF (with sign), so S has one entry per column.
        comp_row = np.empty((ne, nc2), dtype=np.int64)
        comp_sign = np.empty((ne, nc2))
        off = 0
        for f in fields:
            f.offset = off
            edofs = f.basis.element_dofs                          # (nbfun, ne)
            for b, (comp, sign) in enumerate(zip(f.comps, f.signs)):
                comp_row[:, comp] = off + edofs[b]
                comp_sign[:, comp] = sign
            off += f.basis.N
        S = sp.csc_matrix((comp_sign.ravel(), comp_row.ravel(), np.arange(ne * nc2 + 1)),
                          shape=(off, ne * nc2))
        if not frame:
            fast = self._bar_transformation(els, ends, emem, fields, ne, off)
            if fast is not None:
                T, G_coo = fast
                return dict(fields=fields, n_local=off, S=S, G_coo=G_coo, T=T)
        # G: element components <- global DOFs, in pieces
        rows, cols, vals = [], [], []

        def add(el_local, comp, gdof, val):
            r = el_local * nc2 + comp
            v = np.broadcast_to(val, gdof.shape)
            ok = gdof >= 0
            if not ok.all():
                r, gdof, v = r[ok], gdof[ok], v[ok]
            rows.append(r)
            cols.append(gdof)
            vals.append(v)

        def add_block(el_local, comp0, gdofs, Rsub):
            """local comps comp0 + i  <-  Σ_j Rsub[:, i, j] · U[gdofs[:, j]]."""
            k, di, dj = Rsub.shape
            el3 = el_local[:, None, None] * nc2 + comp0 + np.arange(di)[None, :, None]
            add(np.zeros(1, np.int64), np.broadcast_to(el3, (k, di, dj)).ravel(),
                np.broadcast_to(gdofs[:, None, :], (k, di, dj)).ravel(), Rsub.ravel())

        mem = emem[els]
        R = self.rotation[mem]                                    # (el, dim, dim)
        eidx = np.arange(ne)
        for end, (at_joint, node, pt) in enumerate(ends):
            at_joint = at_joint[els]
            node = node[els]
            pt = pt[els]
            base = end * ncomp
            jj = np.flatnonzero(at_joint)
            ii = np.flatnonzero(~at_joint)
            # translations at joints: local_i = Σ_j R_ij U_j
            add_block(eidx[jj], base, self.node_dofs[node[jj], :dim], R[jj])
            # interior translations are in member axes
            for i in range(dim):
                add(eidx[ii], base + i, self.interior_dofs[pt[ii], i], 1.0)
            if not frame:
                continue
            # end rotations at joints, component by component (member axes): the joint's
            # (a row of R on its rotations), the end's own (private DOF) or held (nothing)
            state = self.end_rotations.state[mem, end]            # (el, 1 or 3)
            comp0 = dim                                           # first rotation component
            for c in range(state.shape[1]):
                jc = np.flatnonzero(at_joint & (state[:, c] == JOINT))
                oc = np.flatnonzero(at_joint & (state[:, c] == OWN))
                if dim == 2:
                    add(eidx[jc], base + 2, self.node_dofs[node[jc], 2], 1.0)
                else:
                    for jd in range(3):
                        add(eidx[jc], base + comp0 + c, self.node_dofs[node[jc], 3 + jd],
                            R[jc, c, jd])
                add(eidx[oc], base + comp0 + c, self.private_dofs[mem[oc], end, c], 1.0)
            for i in range(nrot):
                add(eidx[ii], base + dim + i, self.interior_dofs[pt[ii], dim + i], 1.0)
        rows, cols, vals = (np.concatenate(a) for a in (rows, cols, vals))
        nz = vals != 0.0
        rows, cols, vals = rows[nz], cols[nz], vals[nz]
        # T = S G without a sparse product: map each G entry through S's single entry
        T = sp.csr_matrix((vals * comp_sign.ravel()[rows], (comp_row.ravel()[rows], cols)),
                          shape=(off, self.n_dof))
        return dict(fields=fields, n_local=off, S=S,
                    G_coo=(vals, rows, cols, (ne * nc2, self.n_dof)), T=T)

    def _bar_transformation(self, els, ends, emem, fields, ne, n_local):
        """T of two-node bars joining two joints, built directly in CSR form.

        Row ``(field f, element e, end s)`` of T is ``R[e, f, :]`` on the translations of the
        end node, so every row has exactly ``dim`` entries and no COO sort is needed.
        Returns None when the P1 numbering is not the exploded one (then the general path
        is used).
        """
        dim = self.ndim
        edofs = fields[0].basis.element_dofs
        if not (np.array_equal(edofs[0], 2 * np.arange(ne))
                and np.array_equal(edofs[1], 2 * np.arange(ne) + 1)):
            return None
        R = self.rotation[emem[els]]                                  # (e, f, j)
        nodes = np.stack([ends[0][1][els], ends[1][1][els]], axis=1)  # (e, s)
        gd = self.node_dofs[nodes][:, :, :dim]                        # (e, s, j)
        # data and indices in row order (f, e, s, j)
        data = np.broadcast_to(R.transpose(1, 0, 2)[:, :, None, :], (dim, ne, 2, dim))
        idx = np.broadcast_to(gd[None], (dim, ne, 2, dim))
        indptr = np.arange(0, n_local * dim + 1, dim)
        T = sp.csr_matrix((data.ravel(), idx.ravel(), indptr), shape=(n_local, self.n_dof))
        def g_coo():
            """G (element components (e, s, i) <- global DOFs): same numbers, on demand."""
            shape4 = (ne, 2, dim, dim)
            g_rows = np.broadcast_to((np.arange(ne)[:, None, None, None] * 2 * dim
                                      + np.arange(2)[None, :, None, None] * dim
                                      + np.arange(dim)[None, None, :, None]), shape4)
            g_vals = np.broadcast_to(R[:, None, :, :], shape4)
            g_cols = np.broadcast_to(gd[:, :, None, :], shape4)
            return g_vals.ravel(), g_rows.ravel(), g_cols.ravel(), (ne * 2 * dim, self.n_dof)

        return T, g_coo

    # ------------------------------------------------------------------ local matrices
    def _block_local(self, g: _Group, per_field) -> sp.csr_matrix:
        """Block-diagonal local matrix; ``per_field(field, members)`` gives the form and
        the per-element coefficient dict (or None for a zero block)."""
        blocks = []
        mem = self.element_member[g.elements]
        for f in g.fields:
            spec = per_field(f, mem)
            if spec is None:
                blocks.append(sp.csr_matrix((f.basis.N, f.basis.N)))
                continue
            form, coeffs = spec
            kw = {k: _qp(f.basis, v) for k, v in coeffs.items()}
            blocks.append(asm(form, f.basis, **kw))
        return sp.block_diag(blocks, format="csr")

    def _stiffness_spec(self, g: _Group):
        s = self.structure

        def spec(f: _Field, mem):
            if f.name == "u":
                return forms.axial_stiffness, {"EA": (s.E * s.area)[mem]}
            if f.name == "theta":
                GJ = np.where(self.twist_member, s.G * np.nan_to_num(s.J), 0.0)
                return forms.axial_stiffness, {"EA": GJ[mem]}
            if g.kind == "bar":
                return None
            # v bends about local z, w about local y
            EI = s.E * (s.Iz if f.name == "v" else s.Iy)
            return forms.bending_stiffness, {"EI": EI[mem]}
        return spec

    def local_stiffness(self, g: _Group) -> sp.csr_matrix:
        """Block-diagonal local stiffness of one element group (field DOF space); assembled
        once and kept, since static recovery and every later solve reuse it."""
        if g._K_local is None:
            K = self._block_local(g, self._stiffness_spec(g))
            if g.kind == "frame" and self.timoshenko:
                K = (K + self._shear_correction(g)).tocsr()
            g._K_local = K
        return g._K_local

    @property
    def timoshenko(self) -> bool:
        """True when a frame member has a shear area (a Timoshenko beam)."""
        s = self.structure
        return bool(np.any(self.is_frame & (np.isfinite(s.shear_area_y)
                                            | np.isfinite(s.shear_area_z))))

    def shear_parameter(self, field: str, elements: np.ndarray) -> np.ndarray:
        """Φ = 12 EI / (κGA h²) of ``elements`` for the bending field ``field``: ``"v"``
        (bending about z: ``Iz`` and ``shear_area_y``) or ``"w"`` (about y: ``Iy`` and
        ``shear_area_z``); 0 on Euler–Bernoulli members (no shear area)
        (:func:`~trussfe.mechanics.member_loads.shear_parameter`).  The one place the
        stiffness, the mass and the loads of a Timoshenko element take it from."""
        s = self.structure
        mem = self.element_member[elements]
        I, As = (s.Iz, s.shear_area_y) if field == "v" else (s.Iy, s.shear_area_z)
        return shear_parameter((s.E * I)[mem], (s.G * As)[mem], self.element_length[elements])

    def _shear_correction(self, g: _Group) -> sp.csr_matrix:
        """Shear flexibility of the Timoshenko elements of a frame group, added to the cubic
        Euler–Bernoulli bending stiffness.

        The two-node Timoshenko beam stiffness (Przemieniecki, Theory of Matrix Structural
        Analysis, 1968, ch. 5) in the DOFs ``[v_a, ψ_a, v_b, ψ_b]`` (end deflections and
        section rotations: the element's rotation DOFs are the section rotations, which a
        rigid joint shares),

        .. math:: K = \\frac{EI}{(1 + Φ) h³} \\begin{bmatrix} 12 & 6h & −12 & 6h \\\\
                  6h & (4 + Φ)h² & −6h & (2 − Φ)h² \\\\ −12 & −6h & 12 & −6h \\\\
                  6h & (2 − Φ)h² & −6h & (4 + Φ)h² \\end{bmatrix},
                  \\qquad Φ = \\frac{12 EI}{κGA\\,h²},

        differs from the Euler–Bernoulli one (Φ = 0) only in its antisymmetric (shear) mode
        ``a = [1, h/2, −1, h/2]``: ``K = K_EB − Φ/(1 + Φ) · 12EI/h³ · a aᵀ``.  The element is
        exact for end loads, so one element has no shear locking.  Bending about z (field
        ``v``) uses ``shear_area_y``, about y (field ``w``) ``shear_area_z``.
        """
        s = self.structure
        blocks = []
        mem = self.element_member[g.elements]
        h = self.element_length[g.elements]
        for f in g.fields:
            n = f.basis.N
            if f.name not in ("v", "w"):
                blocks.append(sp.csr_matrix((n, n)))
                continue
            EI = (s.E * (s.Iz if f.name == "v" else s.Iy))[mem]
            phi = self.shear_parameter(f.name, g.elements)
            c = -phi / (1.0 + phi) * 12.0 * EI / h**3                  # (el,)
            a = np.stack([np.ones_like(h), h / 2, -np.ones_like(h), h / 2], axis=1)
            vals = c[:, None, None] * a[:, :, None] * a[:, None, :]     # (el, 4, 4)
            blocks.append(_field_matrix(f, f.basis.element_dofs.T, vals))
        return sp.block_diag(blocks, format="csr")

    def local_mass(self, g: _Group) -> sp.csr_matrix:
        """Block-diagonal consistent local mass of one element group."""
        s = self.structure

        def spec(f, mem):
            if f.name == "theta":
                rho_ip = np.where(self.twist_member,
                                  twist_inertia_per_length(s.density, s.Iy, s.Iz, s.J), 0.0)
                return forms.mass, {"rhoA": rho_ip[mem]}
            return forms.mass, {"rhoA": mass_per_length(s.density, s.area)[mem]}
        M = self._block_local(g, spec)
        if g.kind == "frame" and self.timoshenko:
            M = (M + self._timoshenko_mass_correction(g)).tocsr()
        return M

    def _timoshenko_mass_correction(self, g: _Group) -> sp.csr_matrix:
        """Consistent mass of the Timoshenko elements of a frame group, as a correction of
        the cubic Euler–Bernoulli mass assembled by scikit-fem.

        On an element with Φ > 0 the bending mass is that of the element's own shape
        functions (:func:`~trussfe.mechanics.member_loads.deflection_shapes`,
        :func:`~trussfe.mechanics.member_loads.rotation_shapes`): translational inertia
        ``ρA ∫ N Nᵀ dx`` and rotary inertia ``ρI ∫ ψ ψᵀ dx`` (Friedman & Kosmatka 1993), by
        5-point Gauss–Legendre quadrature (exact: the integrands are of degree 6).
        Euler–Bernoulli elements (Φ = 0) keep their mass without rotary inertia.
        """
        s = self.structure
        blocks = []
        mem = self.element_member[g.elements]
        h = self.element_length[g.elements]
        gx, gw = np.polynomial.legendre.leggauss(5)
        xi, w = 0.5 * (gx + 1.0), 0.5 * gw
        rhoA = mass_per_length(s.density, s.area)[mem]
        for f in g.fields:
            n = f.basis.N
            if f.name not in ("v", "w"):
                blocks.append(sp.csr_matrix((n, n)))
                continue
            I = (s.Iz if f.name == "v" else s.Iy)[mem]
            phi = self.shear_parameter(f.name, g.elements)
            timo = phi > 0
            if not np.any(timo):
                blocks.append(sp.csr_matrix((n, n)))
                continue
            e = np.flatnonzero(timo)
            he, pe = h[e, None], phi[e, None]
            NT = deflection_shapes(xi[None, :], he, pe)                 # (el, q, 4)
            NH = deflection_shapes(xi[None, :], he, 0.0 * pe)
            psi = rotation_shapes(xi[None, :], he, pe)
            wq = (w[None, :] * he)[:, :, None, None]
            vals = (rhoA[e, None, None] * (wq * (NT[..., :, None] * NT[..., None, :]
                                                 - NH[..., :, None] * NH[..., None, :])).sum(1)
                    + (s.density[mem][e] * I[e])[:, None, None]
                    * (wq * psi[..., :, None] * psi[..., None, :]).sum(1))    # (el, 4, 4)
            blocks.append(_field_matrix(f, f.basis.element_dofs.T[e], vals))
        return sp.block_diag(blocks, format="csr")

    def local_geometric_stiffness(self, g: _Group, N: np.ndarray) -> sp.csr_matrix:
        """Block-diagonal local geometric stiffness of one group; ``N`` per global element.

        Transverse fields: ``∫ N v' w' dx`` with the element's own shape functions — a
        Timoshenko element's (:meth:`_timoshenko_geometric_correction`) take the slope of
        the deflection, bending and shear together, so that a column converges to
        Engesser's load ``P_E / (1 + P_E/κGA)``.  None on the axial field and on the twist
        (no torsional buckling: that of the co-rotational beams of ``postcritical``, whose
        tangent at the undeformed state is ``K + K_g``)."""
        Ng = np.asarray(N, dtype=float)[g.elements]

        def spec(f, mem):
            if f.name in ("u", "theta"):
                return None
            return forms.geometric_stiffness, {"N": Ng}
        Kg = self._block_local(g, spec)
        if g.kind == "frame" and self.timoshenko:
            Kg = (Kg + self._timoshenko_geometric_correction(g, Ng)).tocsr()
        return Kg

    def _timoshenko_geometric_correction(self, g: _Group, Ng: np.ndarray) -> sp.csr_matrix:
        """``N ∫ (S_T S_Tᵀ − S_H S_Hᵀ) dx`` on the Timoshenko elements of a frame group: the
        geometric stiffness of their own slopes ``S_T``
        (:func:`~trussfe.mechanics.member_loads.slope_shapes`) in place of the cubic
        Hermite ones ``S_H`` assembled by scikit-fem (three-point Gauss–Legendre: exact for
        the quartic integrands)."""
        blocks = []
        h = self.element_length[g.elements]
        gx, gw = np.polynomial.legendre.leggauss(3)
        xi, w = 0.5 * (gx + 1.0), 0.5 * gw
        for f in g.fields:
            n = f.basis.N
            phi = self.shear_parameter(f.name, g.elements) if f.name in ("v", "w") else None
            if phi is None or not np.any(phi > 0):
                blocks.append(sp.csr_matrix((n, n)))
                continue
            e = np.flatnonzero(phi > 0)
            he, pe = h[e, None], phi[e, None]
            ST = slope_shapes(xi[None, :], he, pe)                        # (el, q, 4)
            SH = slope_shapes(xi[None, :], he, 0.0 * pe)
            wq = (w[None, :] * he)[:, :, None, None]
            vals = Ng[e, None, None] * (wq * (ST[..., :, None] * ST[..., None, :]
                                              - SH[..., :, None] * SH[..., None, :])).sum(1)
            blocks.append(_field_matrix(f, f.basis.element_dofs.T[e], vals))
        return sp.block_diag(blocks, format="csr")

    def local_self_weight(self, g: _Group, gravity: np.ndarray) -> np.ndarray:
        """Local load vector of the member self-weight ρA·g (field DOF space)."""
        s = self.structure
        mem = self.element_member[g.elements]
        q = mass_per_length(s.density, s.area)[mem, None] * np.asarray(gravity, dtype=float)[None, :]
        q_local = np.einsum("eij,ej->ei", self.rotation[mem], q)  # (el, dim)
        out = np.zeros(g.n_local)
        for f in g.fields:
            if f.name == "theta":
                continue
            comp = {"u": 0, "v": 1, "w": 2}[f.name]
            qf = q_local[:, comp]
            if not np.any(qf):
                continue
            out[f.offset:f.offset + f.basis.N] = asm(forms.distributed_load, f.basis,
                                                     q=_qp(f.basis, qf))
        return out

    # ------------------------------------------------------------------ global matrices
    def _bar_geometry(self, g: _Group) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Members, end nodes, unit vectors and lengths of the two-node bars of group ``g``."""
        if g.elements.size == self.structure.n_members == self.n_elements:
            # every member one bar (a truss): the member arrays themselves, read only
            return (g.elements, self.structure.connectivity, self.axis, self.element_length)
        mem = self.element_member[g.elements]
        return (mem, self.structure.connectivity[mem], self.axis[mem],
                self.element_length[g.elements])

    def _bar_matrix(self, g: _Group, ref: str, scale: np.ndarray, transverse: bool = False,
                    full: bool = False) -> sp.csr_matrix:
        """Global matrix of the bars of group ``g``: the scikit-fem reference matrix
        ``ref`` (:func:`reference_bar`) times ``scale`` per bar, on its axial field only
        (block ``e eᵀ``), on its transverse fields only (``I − e eᵀ``) or on all its
        translation fields (``full``: ``I``, since the rows of the rotation are orthonormal).

        Equal to ``Tᵀ K_local T`` of the general path to round-off (tested), without building
        bases or ``T``.
        """
        _, ends, _, _ = self._bar_geometry(g)
        return _node_block_matrix(self.structure.n_nodes, self.ndim, ends, reference_bar()[ref],
                                  self.bar_blocks(g, scale, transverse, full), self.n_dof)

    def bar_blocks(self, g: _Group, scale: np.ndarray, transverse: bool = False,
                   full: bool = False) -> np.ndarray:
        """Per bar of group ``g``: ``scale · e eᵀ`` (axial), ``scale · (I − e eᵀ)``
        (``transverse``) or ``scale · I`` (``full``), shape (bar, dim, dim)."""
        _, _, ex, _ = self._bar_geometry(g)
        dim = self.ndim
        if full:
            return np.broadcast_to(np.eye(dim), (ex.shape[0], dim, dim)) * scale[:, None, None]
        blocks = ex[:, :, None] * ex[:, None, :]                     # (bar, dim, dim) e eᵀ
        if transverse:
            np.subtract(np.eye(dim)[None], blocks, out=blocks)       # I − e eᵀ
        blocks *= scale[:, None, None]                               # in place: no new memory
        return blocks

    def bar_elongation(self, g: _Group) -> tuple[sp.csr_matrix, np.ndarray]:
        """``(B, k)`` of the bars of group ``g``: the sparse matrix of their elongations
        ``e·(u_b − u_a)`` (one row per bar, shape (bar, n_dof)) and their stiffnesses
        ``EA/L``, so that the group's stiffness is ``Bᵀ diag(k) B`` (the reference bar's
        ``[[1, −1], [−1, 1]]``).  Made once per group: ``2·dim`` entries per bar."""
        if g._elongation is None:
            s = self.structure
            dim = self.ndim
            mem, ends, ex, L = self._bar_geometry(g)
            nb = ex.shape[0]
            cols = self.node_dofs[ends][:, :, :dim].reshape(nb, 2 * dim)   # start | end
            data = np.concatenate([-ex, ex], axis=1)
            B = sp.csr_matrix((data.ravel(), cols.ravel(),
                               np.arange(0, 2 * dim * nb + 1, 2 * dim)), shape=(nb, self.n_dof))
            g._elongation = (B, (s.E * s.area)[mem] / L)
        return g._elongation

    def _sum_groups(self, bar, general) -> sp.csr_matrix:
        """Σ over groups: ``bar(g)`` for the bar group, ``general(g)`` = Tᵀ X_local T else."""
        out = None
        for g in self.groups:
            A = bar(g) if g.kind == "bar" else (g.T.T @ general(g) @ g.T).tocsr()
            out = A if out is None else out + A
        return sp.csr_matrix((self.n_dof, self.n_dof)) if out is None else out.tocsr()

    def stiffness(self, copy: bool = True) -> sp.csr_matrix:
        """Global elastic stiffness K = Σ Tᵀ K_local T, shape (n_dof, n_dof).

        Truss bars (two nodes, axial stiffness only) are assembled as EA/L times the
        scikit-fem reference matrix on ``e eᵀ`` blocks (:func:`reference_bar`); frame members
        through their exploded local meshes.  ``copy=False`` may return the matrix the model
        keeps for later solves: the caller must not modify it.
        """
        s = self.structure

        def bar(g):
            if g._K_global is None:     # kept: static recovery and later solves reuse it
                mem, _, _, L = self._bar_geometry(g)
                g._K_global = self._bar_matrix(g, "stiffness", (s.E * s.area)[mem] / L)
            return g._K_global.copy() if copy else g._K_global
        K = self._sum_groups(bar, self.local_stiffness)
        if self.spring_stiffness is not None:
            # elastic supports (:class:`~trussfe.model.node_supports.Springs`): k on the
            # diagonal of their DOFs
            K = (K + sp.diags(self.spring_stiffness, format="csr")).tocsr()
        return K

    def mass(self, kind: str = "consistent", include_nodal_masses: bool = True
             ) -> sp.csr_matrix:
        """Global mass matrix.

        Parameters
        ----------
        kind : {"consistent", "lumped"}
            Consistent: ρA on every translation (P1 for bars, i.e. ρAL/6 [[2,1],[1,2]];
            Hermite + P1 for frames) and ρI_p (I_p = Iy + Iz) on the twist.  Lumped: ρA·h/2 on each
            translation DOF at both ends of every element, nothing on rotations.
        include_nodal_masses : bool
            Add ``structure.masses`` to the translations of their nodes.
        """
        s = self.structure
        if kind == "consistent":
            def bar(g):
                mem, _, _, L = self._bar_geometry(g)
                return self._bar_matrix(g, "mass", mass_per_length(s.density, s.area)[mem] * L, full=True)
            M = self._sum_groups(bar, self.local_mass)
        elif kind == "lumped":
            diag = np.zeros(self.n_dof)
            for g in self.groups:
                mem = self.element_member[g.elements]
                if g.kind == "bar":                  # half ρAL on each end's translations
                    ends = self.structure.connectivity[mem]
                    half = 0.5 * mass_per_length(s.density, s.area)[mem] * self.element_length[g.elements]
                    w = np.bincount(ends.ravel(), np.repeat(half, 2),
                                    minlength=s.n_nodes)
                    diag[self.node_dofs[:, : self.ndim]] += w[:, None]
                    continue
                half = 0.5 * mass_per_length(s.density, s.area)[mem] * self.element_length[g.elements]
                # translation components of both ends, weighted through G (rotation-free)
                ne, nc2 = g.elements.size, 2 * g.ncomp
                w = np.zeros((ne, nc2))
                w[:, : self.ndim] = half[:, None]
                w[:, g.ncomp: g.ncomp + self.ndim] = half[:, None]
                # Σ over element components of w·G² distributes mass onto the global DOFs
                # (G rows of translations are orthonormal rotations, so this is exact)
                diag += g.G.multiply(g.G).T @ w.ravel()
            M = sp.diags(diag, format="csr")
        else:
            raise InputError("--mass", f"unknown mass kind {kind!r}; use consistent or lumped")
        if include_nodal_masses and np.any(s.masses):
            d = np.zeros(self.n_dof)
            d[self.node_dofs[:, : self.ndim]] = s.masses[:, None]
            M = M + sp.diags(d)
        if include_nodal_masses and "rotary_inertia" in s.extensions:
            # rotary inertia of the nodal masses on the node rotations
            cols = np.arange(self.ndim, self.ndim + self.nrot)
            M = M + sp.diags(self._node_diagonal("rotary_inertia", "inertia", cols, "masses"))
        return M.tocsr()

    def geometric_stiffness(self, element_axial_force: np.ndarray) -> sp.csr_matrix:
        """Global geometric stiffness K_g for element axial forces N (tension positive).

        Parameters
        ----------
        element_axial_force : ndarray, shape (n_elements,)
        """
        N = np.asarray(element_axial_force, dtype=float).reshape(self.n_elements)

        def bar(g):
            return self._bar_matrix(g, "stiffness", N[g.elements] / self.element_length[
                g.elements], transverse=True)
        return self._sum_groups(bar, lambda g: self.local_geometric_stiffness(g, N))

    def load_vector(self, self_weight: bool = True, nodal_loads: bool = True,
                    gravity: np.ndarray | None = None, loads: np.ndarray | None = None,
                    item: str = "loads") -> np.ndarray:
        """Global load vector f = Tᵀ f_local + nodal loads + gravity on nodal masses.

        Parameters
        ----------
        self_weight : bool
            Include member self-weight (consistent for frames; for truss bars the P1 load
            form gives exactly half the weight at each end) and the weight of the nodal
            masses.
        nodal_loads : bool
            Include nodal forces and moments (``loads`` or ``structure.loads``).
        gravity : ndarray, optional
            Gravity vector (default ``structure.gravity``).
        loads : ndarray, shape (n_nodes, ndof_node), optional
            Nodal loads replacing ``structure.loads``.
        item : str
            The table of the nodal loads in error messages (``load_cases.NAME.loads`` for a
            load case's).

        Raises
        ------
        InputError
            A moment at a pin joint (no rotational DOF), naming the file and the node.
        """
        s = self.structure
        f = np.zeros(self.n_dof)
        grav = s.gravity if gravity is None else np.asarray(gravity, dtype=float)
        if self_weight and np.any(grav):
            for g in self.groups:
                if g.kind == "bar":      # P1 load form: ∫ v = h/2 at each end (reference_bar)
                    mem, ends, _, L = self._bar_geometry(g)
                    ref = reference_bar()["load"]
                    w = mass_per_length(s.density, s.area)[mem] * L
                    per_node = (ref[0] * np.bincount(ends[:, 0], w, minlength=s.n_nodes)
                                + ref[1] * np.bincount(ends[:, 1], w, minlength=s.n_nodes))
                    f[self.node_dofs[:, : self.ndim]] += per_node[:, None] * grav[None, :]
                else:
                    f += g.T.T @ self.local_self_weight(g, grav)
            f[self.node_dofs[:, : self.ndim]] += s.masses[:, None] * grav[None, :]
        if nodal_loads:
            P = s.loads if loads is None else np.asarray(loads, dtype=float)
            dofs = self.node_dofs
            present = dofs >= 0
            lost = ~present & (P[:, : dofs.shape[1]] != 0)
            if np.any(lost):
                i, c = np.argwhere(lost)[0]
                from ..model.structure import DOF_NAMES
                err = InputError(f"{item}.{s.node_ids[i]}",
                                 f"a moment ({DOF_NAMES[s.dim][c]}) is applied at a pin joint "
                                 "that has no rotational stiffness; attach a beam without a "
                                 "release or remove the moment")
                raise err.in_file(s.source)
            np.add.at(f, dofs[present], P[:, : dofs.shape[1]][present])
        return f

    # ------------------------------------------------------------------ recovery
    def element_self_weight_local(self, gravity: np.ndarray | None = None) -> list[np.ndarray]:
        """Per group, the local self-weight vector carried *by the elements* (frames only:
        truss bars have their weight lumped at the joints)."""
        grav = self.structure.gravity if gravity is None else np.asarray(gravity, float)
        out = []
        for g in self.groups:
            if g.kind == "frame" and np.any(grav):
                out.append(self.local_self_weight(g, grav))
            else:
                out.append(np.zeros(g.n_local))
        return out

    def element_forces(self, u_global: np.ndarray, f_local: list[np.ndarray] | None = None
                       ) -> np.ndarray:
        """End forces acting on every element, in member axes.

        ``f_e = Sᵀ (K_local T u − f_local)`` on the exploded mesh.

        Parameters
        ----------
        u_global : ndarray, shape (n_dof,)
        f_local : list of ndarray, optional
            Local distributed-load vectors per group (default: member self-weight of frames,
            see :meth:`element_self_weight_local`).

        Returns
        -------
        ndarray, shape (n_elements, 2, 6)
            ``[Fx, Fy, Fz, Mx, My, Mz]`` exerted on the element at its start (index 0) and
            end (index 1), member axes.  2-D: ``[Fx, Fy, 0, 0, 0, Mz]``.
        """
        if f_local is None:
            f_local = self.element_self_weight_local()
        out = np.zeros((self.n_elements, 2, 6))
        dim = self.ndim
        s = self.structure
        for g, fl in zip(self.groups, f_local):
            # a group of every element holds them in order (increasing numbers): its rows
            # are a slice, written without an index array
            rows = slice(None) if g.elements.size == self.n_elements else g.elements
            if g.kind == "bar" and not np.any(fl):
                # axial field only: end forces ∓EA/L e·(u_b − u_a) (reference_bar stiffness)
                if g._elongation is not None:
                    # made for a truss solved from its bars (trussfe.fem.truss_band): N = k·Bu
                    B, kb = g._elongation
                    N = kb * (B @ u_global)
                    out[rows, 0, 0] = -N
                    out[rows, 1, 0] = N
                    continue
                mem, ends, ex, L = self._bar_geometry(g)
                # node translations are the first n·dim global DOFs (see _build)
                U = u_global[: s.n_nodes * dim].reshape(s.n_nodes, dim)
                k = reference_bar()["stiffness"]
                ua = np.stack([np.einsum("ed,ed->e", ex, U[ends[:, 0]]),
                               np.einsum("ed,ed->e", ex, U[ends[:, 1]])], axis=1)
                axial = ((s.E * s.area)[mem] / L)[:, None] * (ua @ k.T)     # (bar, end)
                out[rows, :, 0] = axial
                continue
            fe = self.local_stiffness(g) @ (g.T @ u_global) - fl
            comp = (g.S.T @ fe).reshape(g.elements.size, 2, g.ncomp)
            out[rows, :, :dim] = comp[:, :, :dim]
            if g.kind == "frame":
                if dim == 2:
                    out[rows, :, 5] = comp[:, :, 2]
                else:
                    out[rows, :, 3:] = comp[:, :, 3:]
        return out

    def station_displacements(self, u_global: np.ndarray) -> np.ndarray:
        """Translations (global axes) at every station of every member.

        Returns
        -------
        ndarray, shape (m, kmax + 1, dim)
            Station ``j`` of member ``i`` is at ``x = j L_i / k_i`` (NaN past ``k_i``).
        """
        dim = self.ndim
        m = self.structure.n_members
        k = self.member_subdivisions
        kmax = int(k.max()) if m else 1
        out = np.full((m, kmax + 1, dim), np.nan)
        emem = self.element_member
        j = np.arange(self.n_elements) - self.member_elements[emem]
        for g in self.groups:
            comp = (g.G @ u_global).reshape(g.elements.size, 2, g.ncomp)[:, :, :dim]
            R = self.rotation[emem[g.elements]]
            glob = np.einsum("eji,esj->esi", R, comp)             # Rᵀ · local
            els = g.elements
            out[emem[els], j[els]] = glob[:, 0]
            lastmask = j[els] == k[emem[els]] - 1
            out[emem[els][lastmask], k[emem[els]][lastmask]] = glob[lastmask, 1]
        return out

    def largest_translations(self, U: np.ndarray) -> np.ndarray:
        """The translation component of largest magnitude, sign kept, of each column of ``U``
        (n_dof, k) over the joints and every station along the members.

        A mode scaled by it has a largest translation component of +1 wherever that lies —
        a member buckling between its joints moves a station most — and a scale free of the
        rotations, whose unit differs.  A column that translates nothing gives its
        component of largest magnitude instead.

        Returns
        -------
        ndarray, shape (k,)
        """
        U = np.asarray(U, dtype=float).reshape(self.n_dof, -1)
        dim = self.ndim
        k = self.member_subdivisions
        # the stations between a member's ends (its ends are joints, read exactly there)
        j = np.arange(int(k.max()) + 1 if k.size else 1)
        inside = (j >= 1) & (j < k[:, None])
        out = np.empty(U.shape[1])
        for i in range(U.shape[1]):
            values = np.concatenate([self.node_values(U[:, i])[:, :dim].ravel(),
                                     self.station_displacements(U[:, i])[inside].ravel()])
            largest = values[np.argmax(np.abs(values))] if values.size else 0.0
            if abs(largest) <= 1e-12 * np.abs(U[:, i]).max():
                largest = U[np.argmax(np.abs(U[:, i])), i]
            out[i] = largest
        return out

    def dof_points(self) -> Points:
        """Where every DOF sits (:class:`~trussfe.linalg.ordering.Points`, for the geometric
        ordering of :func:`trussfe.linalg.factor`): a joint's translations and rotations and
        the rotations a member end owns at the joint, a subdivided member's interior DOFs at
        their station.

        Returns
        -------
        Points
            ``of_unknown`` of shape (n_dof,) indexing ``coords`` of shape
            (n_nodes + interior points, dim).
        """
        s = self.structure
        n = s.n_nodes
        m = s.n_members
        of = np.full(self.n_dof, -1, dtype=np.int64)
        nd = self.node_dofs
        ok = nd >= 0
        of[nd[ok]] = np.nonzero(ok)[0]
        pd = self.private_dofs                         # (m, 2, r): at the member's end joint
        ok = pd >= 0
        if ok.any():
            mem, end, _ = np.nonzero(ok)
            of[pd[ok]] = s.connectivity[mem, end]
        pts = self.interior_dofs                       # (p, ncomp): inside members
        mem = self.interior_member
        if pts.size:
            off = np.zeros(m + 1, dtype=np.int64)
            np.cumsum(np.bincount(mem, minlength=m), out=off[1:])
            k = np.arange(mem.size) - off[mem] + 1     # station k of the member's k_i
            frac = k / self.member_subdivisions[mem]
            start = s.coords[s.connectivity[mem, 0]]
            inner = start + frac[:, None] * (s.coords[s.connectivity[mem, 1]] - start)
            ok = pts >= 0
            of[pts[ok]] = n + np.nonzero(ok)[0]
        else:
            inner = np.zeros((0, s.dim))
        coords = np.vstack([s.coords, inner])
        if np.any(of < 0):             # a DOF of no point: at the centre (ordered late)
            of[of < 0] = coords.shape[0]
            coords = np.vstack([coords, coords.mean(axis=0)])
        return Points(of, coords)

    def node_values(self, u_global: np.ndarray) -> np.ndarray:
        """Global vector → per-node array (n_nodes, ndof_node); 0 where a DOF is absent."""
        dofs = self.node_dofs
        out = np.zeros(dofs.shape)
        ok = dofs >= 0
        out[ok] = u_global[dofs[ok]]
        return out


def discretise(structure: Structure, bar_model: str = "truss",
               subdivisions: int | None = None) -> FEModel:
    """Discretise a structure into finite elements.

    Parameters
    ----------
    structure : Structure
    bar_model : {"truss", "pinned-beam"}
        How members of type ``bar`` are modelled (docs/cli.md, ``--bar-model``).
    subdivisions : int, optional
        Sub-elements per frame member (default :data:`DEFAULT_FRAME_SUBDIVISIONS`).

    Returns
    -------
    FEModel

    Examples
    --------
    Two bars meeting at a loaded joint (truss model): 3 nodes × 2 translations.

    >>> from trussfe.model.structure import build_structure
    >>> from trussfe.model.sections import Section, Material
    >>> s = build_structure([[0, 0], [1, 0], [0, 1]], [(0, 1), (2, 1)],
    ...                     section=Section("a", area=1e-4),
    ...                     material=Material("steel", 2e11, 8e10),
    ...                     supports={0: "xy", 2: "xy"})
    >>> fe = discretise(s)
    >>> fe.n_dof, fe.free.tolist()
    (6, [2, 3])
    """
    return FEModel(structure, bar_model=bar_model, subdivisions=subdivisions)
