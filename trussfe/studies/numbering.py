# SPDX-License-Identifier: MIT
"""A source's own node order and member orientation, applied on top of a catalogue structure.

The catalogue (:mod:`trussfe.models`) numbers every structure once.  Where a published table
was computed with another numbering — Lacy's Appendix A lists the triangular truss' pivots
before the apex and runs the follower from its pivot; Appendix C's code runs each base→mid
longeron of the double-octahedral bay from its base node and M9/10 from N6 — the study
renumbers the catalogue entry with these two functions, so the change is explicit and the
geometry, sections and loads stay the catalogue's.  Orientation matters to the rigid-body
model: an active member's base sits at its start node, and end forces are reported per end.
"""
from __future__ import annotations

from collections.abc import Sequence
import numpy as np

from ..errors import InputError
from ..model.structure import Structure


def renumber_nodes(structure: Structure, order: Sequence[str]) -> Structure:
    """The structure with its nodes in the order of the ids ``order`` (a permutation).

    Coordinates, supports, loads and masses move with their nodes; members keep their index
    and join the same nodes.

    Examples
    --------
    >>> from trussfe.models import triangular_truss
    >>> s = renumber_nodes(triangular_truss(), ["O2", "O1", "B"])
    >>> s.node_ids, s.connectivity.tolist()
    (('O2', 'O1', 'B'), [[2, 1], [0, 2]])
    """
    perm = np.array([structure.node_index(i) for i in order], dtype=np.int64)
    if sorted(perm.tolist()) != list(range(structure.n_nodes)):
        raise InputError("renumber_nodes.order", f"expected every node id once, got {order!r}")
    new_index = np.empty_like(perm)
    new_index[perm] = np.arange(perm.size)
    return structure.variant(node_ids=[structure.node_ids[i] for i in perm],
                             coords=structure.coords[perm], supports=structure.supports[perm],
                             loads=structure.loads[perm], masses=structure.masses[perm],
                             connectivity=new_index[structure.connectivity])


def reverse_members(structure: Structure, member_ids: Sequence[str]) -> Structure:
    """The structure with the members ``member_ids`` running from their end to their start.

    Moment releases swap ends with the nodes; member indices (and so active-member records,
    which refer to the index) are unchanged.

    Examples
    --------
    >>> from trussfe.models import triangular_truss
    >>> reverse_members(triangular_truss(), ["follower"]).connectivity.tolist()
    [[2, 1], [0, 1]]
    """
    idx = np.array([structure.member_index(i) for i in member_ids], dtype=np.int64)
    conn = structure.connectivity.copy()
    conn[idx] = conn[idx, ::-1]
    releases = structure.releases.copy()
    releases[idx] = releases[idx, ::-1]
    axes = structure.bending_axis_releases.copy()
    axes[idx] = axes[idx, ::-1]
    torsion = structure.torsion_releases.copy()
    torsion[idx] = torsion[idx, ::-1]
    return structure.variant(connectivity=conn, releases=releases,
                             bending_axis_releases=axes, torsion_releases=torsion)
