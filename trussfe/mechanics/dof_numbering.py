# SPDX-License-Identifier: MIT
"""Which members bend, what their end rotations are, and the global DOF numbering of the
linear FE discretisation: pure functions of a structure, a bar model and a subdivision count.

The linear FE core (:class:`trussfe.fem.discretisation.FEModel`) numbers its DOFs with
:func:`number_dofs`; the co-rotational model (:class:`trussfe.nonlinear.model.NonlinearModel`)
takes from it which joints carry rotations and the numbering of the joints' translations and
rotations (the same numbers in both models), and from :func:`member_end_rotations` what every
member end rotation is.

Global DOFs of :func:`number_dofs`, in this order:

1. every node: ``dim`` translations (global axes), node by node;
2. joints with a rotation (:attr:`~trussfe.mechanics.releases.EndRotations.joint_rotation`):
   1 (2-D) or 3 (3-D) rotations, global axes;
3. the points inside subdivided frame members, member by member: translations and rotations
   in member axes (no twist where the member has no torsion field);
4. the rotation components that a member end owns (released ends), in member axes.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.structure import Structure
from .releases import OWN, EndRotations, end_rotations, no_end_rotations


def frame_members(structure: Structure, bar_model: str) -> np.ndarray:
    """Members that bend: beams, and under ``bar_model="pinned-beam"`` bars too, shape (m,)."""
    if bar_model == "truss":
        return structure.is_beam.copy()
    return np.ones(structure.n_members, dtype=bool)


def member_end_rotations(structure: Structure, bar_model: str,
                         axis: np.ndarray | None = None) -> EndRotations:
    """What every member end rotation is (the joint's, the end's own, or held).

    Beams are released as given; pinned-beam bars at both ends; torsion exists in 3-D beams
    only (a pinned-beam bar has no twist field).

    Parameters
    ----------
    structure : Structure
    bar_model : {"truss", "pinned-beam"}
    axis : ndarray, shape (m, dim), optional
        Unit vectors of the members (default: from ``structure.member_vectors()``).
    """
    s = structure
    dim = s.dim
    frame = frame_members(s, bar_model)
    if not frame.any():                 # a truss: nothing to classify
        return no_end_rotations(dim, s.n_members, s.n_nodes)
    if axis is None:
        d = s.member_vectors()
        axis = d / np.sqrt(np.einsum("ij,ij->i", d, d))[:, None]
    released = np.where(s.is_beam[:, None], s.releases, True) & frame[:, None]
    # per bending axis (my, mz): both where released, one where a beam releases one alone
    released = released[:, :, None] | (s.bending_axis_releases & (s.is_beam & frame)[:, None,
                                                                                     None])
    return end_rotations(dim, s.connectivity, axis, frame, s.is_beam & (dim == 3), released,
                         s.torsion_releases & s.is_beam[:, None], s.supports[:, dim:])


@dataclass(frozen=True)
class DofNumbering:
    """Global DOF numbering of the linear FE discretisation (see the module notes).

    Attributes
    ----------
    node_dofs : ndarray of int, shape (n, dim + r)
        Global DOF of each node DOF (translations, then rotations); −1 where absent.
    has_rotation : ndarray of bool, shape (n,)
        Joints with rotation DOFs.
    member_subdivisions : ndarray of int, shape (m,)
        Elements per member (1 for truss bars).
    interior_dofs : ndarray of int, shape (interior point, dim + r)
        DOFs of the points inside members (member axes); −1 where absent.
    interior_member : ndarray of int, shape (interior point,)
    interior_offset : ndarray of int, shape (m + 1,)
        Member i's interior points are ``interior_offset[i]:interior_offset[i + 1]``.
    private_dofs : ndarray of int, shape (m, 2, r)
        DOF of each rotation component a member end owns; −1 elsewhere.
    n_dof : int
    """

    node_dofs: np.ndarray
    has_rotation: np.ndarray
    member_subdivisions: np.ndarray
    interior_dofs: np.ndarray
    interior_member: np.ndarray
    interior_offset: np.ndarray
    private_dofs: np.ndarray
    n_dof: int

    def joint_rotation_rank(self) -> np.ndarray:
        """Rank of every joint among the joints with rotations (−1 without), shape (n,)."""
        n, ndn = self.node_dofs.shape
        dim = 2 if ndn == 3 else 3
        r = ndn - dim
        out = np.full(n, -1)
        out[self.has_rotation] = (self.node_dofs[self.has_rotation, dim] - n * dim) // r
        return out


def number_dofs(structure: Structure, bar_model: str, subdivisions: int,
                rotations: EndRotations | None = None) -> DofNumbering:
    """Number the global DOFs of a structure discretised with ``bar_model``.

    Parameters
    ----------
    structure : Structure
    bar_model : {"truss", "pinned-beam"}
    subdivisions : int
        Elements per frame member (truss bars have one).
    rotations : EndRotations, optional
        :func:`member_end_rotations` of the structure, when already at hand.

    Returns
    -------
    DofNumbering

    Examples
    --------
    >>> from trussfe.model.structure import build_structure
    >>> from trussfe.model.sections import Section, Material
    >>> s = build_structure([[0, 0], [1, 0]], [(0, 1)], section=Section.tube("t", .02),
    ...                     material=Material("al", 7e10, 2.6e10))
    >>> d = number_dofs(s, "pinned-beam", 2)
    >>> d.node_dofs.tolist(), d.interior_dofs.tolist(), d.private_dofs[:, :, 0].tolist()
    ([[0, 1, -1], [2, 3, -1]], [[4, 5, 6]], [[7, 8]])
    """
    s = structure
    dim = s.dim
    nrot = 1 if dim == 2 else 3
    n, m = s.n_nodes, s.n_members
    er = member_end_rotations(s, bar_model) if rotations is None else rotations
    frame = frame_members(s, bar_model)
    # (a subdivision count for no frame member at all is not taken into an array: a truss
    # does not care how large it is)
    ksub = np.ones(m, dtype=np.int64)
    if frame.any():
        ksub[frame] = int(subdivisions)
    node_dofs = -np.ones((n, dim + nrot), dtype=np.int64)
    node_dofs[:, :dim] = np.arange(n * dim).reshape(n, dim)
    has_rot = er.joint_rotation
    nxt = n * dim
    nr = int(has_rot.sum())
    node_dofs[has_rot, dim:] = nxt + np.arange(nr * nrot).reshape(nr, nrot)
    nxt += nr * nrot
    # interior points of frame members: member, index 1..k-1, DOFs in member axes
    npts_m = ksub - 1
    pt_off = np.zeros(m + 1, dtype=np.int64)
    np.cumsum(npts_m, out=pt_off[1:])
    pt_member = np.repeat(np.arange(m), npts_m)
    mask = np.ones((pt_member.size, dim + nrot), dtype=bool)
    if dim == 3:
        mask[:, dim] = s.is_beam[pt_member]          # twist only where torsion exists
    interior_dofs = -np.ones(mask.shape, dtype=np.int64)
    interior_dofs[mask] = nxt + np.arange(int(mask.sum()))
    nxt += int(mask.sum())
    # private rotations of member ends (member axes; 2-D θz, 3-D twist, θy, θz) where the
    # end's rotation is its own
    own = er.state == OWN
    private = -np.ones(er.state.shape, dtype=np.int64)
    private[own] = nxt + np.arange(int(own.sum()))
    nxt += int(own.sum())
    return DofNumbering(node_dofs=node_dofs, has_rotation=has_rot, member_subdivisions=ksub,
                        interior_dofs=interior_dofs, interior_member=pt_member,
                        interior_offset=pt_off, private_dofs=private, n_dof=int(nxt))
