# SPDX-License-Identifier: MIT
"""Finite-element matrices and driving loads of a truss at many instants of a motion at once.

The elastic model of :mod:`trussfe.response.transient` needs, at every time step ``n``, the
stiffness ``K_n`` and mass ``M_n`` of the structure in its current (rigid-motion) geometry and
the driving load ``f_n = f_g − M_n a_r,n`` (gravity and d'Alembert inertia of the prescribed
motion).  Assembling one model per step would cost one scikit-fem assembly per step, so a
*block* of ``nb`` steps is assembled as one structure made of ``nb`` disjoint copies of the
truss, each copy in the geometry of its own step; one :func:`~trussfe.fem.discretise` call then
gives a block-diagonal ``K`` and ``M`` whose diagonal blocks are the per-step matrices.
:func:`copy_dof_map` finds, for every copy, the DOFs of the batch model that correspond to the
DOFs of the single model, so every per-step quantity is in one DOF numbering.

Rigid acceleration field
------------------------
In the rigid motion every member stays straight, so the acceleration along a member is linear
between its end nodes: ``a(s) = (1 − s/L) a_a + (s/L) a_b``.  On the FE DOFs
(:mod:`trussfe.fem.discretisation`) that is

* node translations: the node accelerations of the rigid kinematics (global axes);
* interior points of a subdivided member (member axes): ``R (1 − s/L) a_a + R (s/L) a_b``;
* bending rotations (interior and released ends, member axes): the slope of the transverse
  field, ``θz = e_y·(a_b − a_a)/L`` and, in 3-D, ``θy = −e_z·(a_b − a_a)/L``.

For a passive member this is exact (material points sit at fixed ``s``), and the consistent
mass reproduces linear fields exactly, so ``M a_r`` is the exact d'Alembert load of the member
(only the tube's rotary inertia of its cross-section, a relative ``r²/L² ≈ 4e-5`` effect, is
missing).  An active member telescopes: its base moves with the start node and its leadscrew
tube with the end node, and its rigid-body inertia has Coriolis terms ``2 L̇ ė`` that no mass
matrix acting on a field reproduces.  Its load is therefore taken from the rigid-body
Newton–Euler equations of :mod:`trussfe.rigid.forces` (Lacy eqs. 2.9–2.11, 4.20): with
``R = Σ m_k (a_k − g)`` and ``M_a`` its moment about the start node, the member needs
``F_b⊥ = (M_a × e)/L`` at its end node and ``R⊥ − F_b⊥`` at its start node; axially the base's
share goes to the start node and the tube's to the end node (as in
:func:`trussfe.fem.modal.active_member_mass`), so the FE bar's axial force is the force at the
cantilever connection, i.e. the actuator force of the rigid-body model.  The member exerts the
opposite forces on the nodes.  Its distributed FE mass is removed (density 0), and its elastic
mass is :func:`~trussfe.fem.modal.active_member_mass`.
"""
from __future__ import annotations

import dataclasses
import logging
from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np
import scipy.sparse as sp

from ..fem.discretisation import FEModel, discretise
from ..fem.modal import active_member_mass
from ..mechanics.geometry import member_vectors
from ..model.structure import Structure
from ..rigid.active import active_members
from ..mechanics.active_bodies import MemberBodies, massless_active
from ..rigid.forces import member_resultants
from ..rigid.kinematics import Kinematics, pad3
from .along_motion import copy_ids

log = logging.getLogger(__name__)


def batch_structure(structure: Structure, coords: np.ndarray) -> Structure:
    """``nb`` disjoint copies of a structure, copy ``c`` at node positions ``coords[c]``.

    Parameters
    ----------
    structure : Structure
    coords : ndarray, shape (nb, n, dim)

    Returns
    -------
    Structure
        Nodes ``c·n + i`` and members ``c·m + j`` (ids
        :func:`~trussfe.response.along_motion.copy_ids`); active members carried along
        (index offset).
    """
    s = structure
    nb = coords.shape[0]
    n, m = s.n_nodes, s.n_members
    conn = (s.connectivity[None] + (n * np.arange(nb))[:, None, None]).reshape(-1, 2)
    acts = [dataclasses.replace(a, member=a.member + c * m)
            for c in range(nb) for a in active_members(s)]
    ext = {"active_members": acts} if acts else {}
    return Structure(
        name=s.name, dim=s.dim,
        node_ids=copy_ids(s.node_ids, nb),
        coords=coords.reshape(nb * n, s.dim),
        member_ids=copy_ids(s.member_ids, nb),
        connectivity=conn, sections=list(s.sections) * nb, materials=list(s.materials) * nb,
        is_beam=np.tile(s.is_beam, nb), releases=np.tile(s.releases, (nb, 1)),
        torsion_releases=np.tile(s.torsion_releases, (nb, 1)),
        bending_axis_releases=np.tile(s.bending_axis_releases, (nb, 1, 1)),
        supports=np.tile(s.supports, (nb, 1)), loads=np.tile(s.loads, (nb, 1)),
        masses=np.tile(s.masses, nb), gravity=np.array(s.gravity, dtype=float),
        orientation=np.tile(s.orientation, (nb, 1)), extensions=ext, source=s.source)


def copy_dof_map(single: FEModel, batch: FEModel, nb: int) -> np.ndarray:
    """Batch-model DOF of every single-model DOF in every copy.

    Returns
    -------
    ndarray of int, shape (nb, single.n_dof)
        ``map[c, d]`` is the DOF of the batch model that plays the part of DOF ``d`` of the
        single model in copy ``c`` (node DOFs, interior points and released-end rotations
        are numbered per node / point / member, and copies are consecutive in each).
    """
    out = -np.ones((nb, single.n_dof), dtype=np.int64)
    np.arange(nb)[:, None]
    for a1, ab in ((single.node_dofs, batch.node_dofs),
                   (single.interior_dofs, batch.interior_dofs),
                   (single.private_dofs.reshape(single.private_dofs.shape[0], -1),
                    batch.private_dofs.reshape(batch.private_dofs.shape[0], -1))):
        k = a1.shape[0]
        if k == 0:
            continue
        abc = ab.reshape(nb, k, -1)                         # (copy, entity, component)
        ok = a1.reshape(k, -1) >= 0
        out[:, a1.reshape(k, -1)[ok]] = abc[:, ok]
    if np.any(out < 0):                                     # pragma: no cover - invariant
        raise RuntimeError("batch DOF numbering does not match the single model")
    return out


def rigid_field(fe: FEModel, node_vectors: np.ndarray) -> np.ndarray:
    """FE DOF vector of a field that is linear along every member (members stay straight).

    Parameters
    ----------
    fe : FEModel
        A model of bars (no joint rotations).
    node_vectors : ndarray, shape (n_nodes, 3) or (n_nodes, dim)
        The field at the nodes (global axes), e.g. the rigid-body accelerations.

    Returns
    -------
    ndarray, shape (n_dof,)

    Examples
    --------
    A rigid rotation about the origin strains nothing: ``K u = 0``.

    >>> from trussfe.models import triangular_truss
    >>> from trussfe.fem.discretisation import discretise
    >>> s = triangular_truss()
    >>> fe = discretise(s, "pinned-beam", 4)
    >>> rot = np.c_[-s.coords[:, 1], s.coords[:, 0]]          # ω × x, ω = 1 rad/s
    >>> u = rigid_field(fe, rot)
    >>> bool(np.abs(fe.stiffness() @ u).max() < 1e-6 * np.abs(fe.stiffness()).max())
    True
    """
    s = fe.structure
    dim = fe.ndim
    a = np.asarray(node_vectors, dtype=float)[:, :dim]
    out = np.zeros(fe.n_dof)
    out[fe.node_dofs[:, :dim]] = a
    conn = s.connectivity
    L = s.lengths()
    R = fe.rotation                                          # (member, local, global)
    slope = np.einsum("mij,mj->mi", R, member_vectors(a, conn)) / L[:, None]
    rot = np.zeros((s.n_members, fe.nrot))                   # bending rotations, member axes
    if dim == 2:
        rot[:, 0] = slope[:, 1]
    else:
        rot[:, 1] = -slope[:, 2]
        rot[:, 2] = slope[:, 1]
    if fe.interior_dofs.size:
        pm = fe.interior_member
        first = np.searchsorted(pm, pm, side="left")         # first point of its member
        frac = (np.arange(pm.size) - first + 1) / fe.member_subdivisions[pm]
        glob = (1.0 - frac)[:, None] * a[conn[pm, 0]] + frac[:, None] * a[conn[pm, 1]]
        loc = np.einsum("pij,pj->pi", R[pm], glob)
        vals = np.concatenate([loc, rot[pm]], axis=1)        # (point, dim + nrot)
        ok = fe.interior_dofs >= 0
        out[fe.interior_dofs[ok]] = vals[ok]
    priv = fe.private_dofs                                   # (member, end, npriv)
    if priv.size:
        pr = rot[:, -priv.shape[2]:]                         # 2-D: θz; 3-D: θy, θz
        vals = np.broadcast_to(pr[:, None, :], priv.shape)
        ok = priv >= 0
        out[priv[ok]] = vals[ok]
    return out


def active_member_loads(structure: Structure, kin: Kinematics, bodies: MemberBodies
                        ) -> np.ndarray:
    """Equivalent nodal loads of the active members' rigid-body inertia and weight.

    See the module docstring (Lacy eqs. 2.9–2.11 and 4.20, with the axial split base → start
    node, tube → end node).

    Parameters
    ----------
    structure : Structure
    kin : Kinematics
        Rigid-body kinematics at ``nt`` instants.
    bodies : MemberBodies
        From :func:`trussfe.mechanics.active_bodies.member_bodies`.

    Returns
    -------
    ndarray, shape (nt, n_nodes, dim)
        Force the active members exert on the nodes, N.
    """
    conn = structure.connectivity
    nt = kin.n_steps
    out = np.zeros((nt, structure.n_nodes, 3))
    idx = np.array([a.member for a in active_members(structure)], dtype=np.int64)
    if idx.size == 0:
        return out[..., :structure.dim]
    g = pad3(np.asarray(structure.gravity, dtype=float))
    f_tube, f_base, R, Ma = (a[:, idx] for a in member_resultants(kin, bodies, g, conn))
    e = kin.unit[:, idx]
    L = kin.length[:, idx, None]
    Fb_perp = np.cross(Ma, e) / L
    R_perp = R - np.einsum("tmi,tmi->tm", R, e)[..., None] * e
    Fa = R_perp - Fb_perp + np.einsum("tmi,tmi->tm", f_base, e)[..., None] * e
    Fb = Fb_perp + np.einsum("tmi,tmi->tm", f_tube, e)[..., None] * e
    np.add.at(out, (slice(None), conn[idx, 0]), -Fa)
    np.add.at(out, (slice(None), conn[idx, 1]), -Fb)
    return out[..., :structure.dim]


@dataclass
class Block:
    """Matrices and loads of ``nb`` consecutive time steps.

    Attributes
    ----------
    fe : FEModel
        The batch model (``nb`` copies), for member-force recovery.
    dof_map : ndarray, shape (nb, n_dof)
        :func:`copy_dof_map`.
    K, M : scipy.sparse.csr_matrix
        Block-diagonal stiffness and mass of the batch model.
    f : ndarray, shape (nb, n_dof)
        Driving load ``f_g − M a_r`` (+ active-member loads), single-model DOFs.
    a_rigid : ndarray, shape (nb, n_dof)
        Rigid acceleration field on the DOFs.
    """

    fe: FEModel
    dof_map: np.ndarray
    K: sp.csr_matrix
    M: sp.csr_matrix
    f: np.ndarray
    a_rigid: np.ndarray

    @property
    def n_steps(self) -> int:
        """Number of steps in the block."""
        return self.dof_map.shape[0]

    def dense(self, which: str, dofs: np.ndarray) -> np.ndarray:
        """Per-step dense matrices restricted to single-model DOFs ``dofs``.

        Returns
        -------
        ndarray, shape (nb, len(dofs), len(dofs))
        """
        A = getattr(self, which)
        nd = dofs.size
        P = self.dof_map[:, dofs].ravel()
        C = A[P][:, P].tocoo()                   # block diagonal, copy-major
        out = np.zeros((self.n_steps, nd, nd))
        np.add.at(out, (C.row // nd, C.row % nd, C.col % nd), C.data)
        return out

    def sparse(self, which: str, dofs: np.ndarray) -> list:
        """Per-step sparse matrices restricted to single-model DOFs ``dofs`` (CSC)."""
        A = getattr(self, which)
        return [A[d][:, d].tocsc() for d in self.dof_map[:, dofs]]


def assemble_block(structure: Structure, single: FEModel, geometry: np.ndarray,
                   kin: Kinematics, bodies: MemberBodies, *, bar_model: str,
                   subdivisions: int | None, mass: str = "consistent") -> Block:
    """Assemble the per-step matrices and driving loads of a block of steps.

    Parameters
    ----------
    structure : Structure
        The truss (real densities).
    single : FEModel
        Discretisation of the massless-active copy in the initial geometry (DOF numbering).
    geometry : ndarray, shape (nb, n, dim)
        Node positions in which the matrices are formed (current positions, or the initial
        ones repeated for frozen matrices).
    kin : Kinematics
        Rigid kinematics of the ``nb`` steps (node accelerations, active-member motion).
    bodies : MemberBodies
    bar_model, subdivisions, mass
        As :func:`trussfe.fem.discretise` and :meth:`FEModel.mass`.
    """
    nb = geometry.shape[0]
    s0 = massless_active(structure)
    sb = batch_structure(s0, geometry)
    fe = discretise(sb, bar_model=bar_model, subdivisions=subdivisions)
    dmap = copy_dof_map(single, fe, nb)
    K = fe.stiffness()
    M0 = fe.mass(kind=mass)
    real = batch_structure(structure, geometry)
    M = M0 + active_member_mass(SimpleNamespace(structure=real, n_dof=fe.n_dof,
                                                node_dofs=fe.node_dofs))
    fg = fe.load_vector()
    acc = kin.acceleration[..., :structure.dim].reshape(nb * structure.n_nodes, -1)
    a_r = rigid_field(fe, acc)
    qa = active_member_loads(structure, kin, bodies)          # (nb, n, dim)
    # d'Alembert load of the members and nodal masses; the active members' rigid-body
    # inertia comes from their Newton–Euler loads (not from their linearised mass).
    f = fg - M0 @ a_r
    f[fe.node_dofs[:, :structure.dim]] += qa.reshape(nb * structure.n_nodes, -1)
    return Block(fe=fe, dof_map=dmap, K=K.tocsr(), M=M.tocsr(), f=f[dmap], a_rigid=a_r[dmap])
