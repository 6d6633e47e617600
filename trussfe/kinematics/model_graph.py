# SPDX-License-Identifier: MIT
"""The graph of a model file and its bar-only equivalent mechanism (``trussfe topology``).

A model is read as a linkage (Vlase et al. 2008 §2.1):

* **ground** — the nodes fixed in every translation: the fixed element.  Its joints are
  closed by ``ground`` edges (a chain, construction II: the closing element is the sum of the
  others and is left out);
* **sliders** — a node fixed in all translations but one slides along that axis: a
  ``slider`` edge of fixed direction and variable length from a virtual ground point behind
  it.  A node free in two directions of space but fixed in the third (a support that
  removes a rigid-body motion) has no edge of the cycle method: the equivalent mechanism
  leaves it free and lists it in ``planar_supports``;
* **plates** — beam members joined rigidly (no end release at the shared node) form one rigid
  body; when it has three or more joints it is triangulated by ``plate`` bars
  (construction I).  A beam alone, or a member of type bar, is a ``bar`` edge.

:func:`model_topology` returns the equivalent assembly with its graph: complete and reduced
incidence matrices, spanning tree and cotree, fundamental cycle matrix ``B_f`` (Vlase eq. 2)
and, for ``s − r ≤ 16``, the complete cycle matrix ``B_a``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from ..errors import InputError
from ..model.structure import Structure
from .cycles import MAX_COMPLETE_CYCLE_RANK, complete_cycle_matrix
from .topology import (EquivalentAssembly, GraphTopology, equivalent_assembly, graph_topology,
                       incidence_matrix)


@dataclass
class ModelTopology:
    """A model's equivalent mechanism and its graph.

    Attributes
    ----------
    assembly : EquivalentAssembly
    graph : GraphTopology
        Tree, cotree, reduced incidence matrix and ``B_f``.
    incidence : scipy.sparse.csr_matrix, shape (r + 1, s)
        Complete incidence matrix ``A_a``.
    complete_cycles : ndarray of int or None
        ``B_a`` (every simple cycle), ``None`` when s − r exceeds
        :data:`~trussfe.kinematics.cycles.MAX_COMPLETE_CYCLE_RANK`.
    node_ids, edge_ids : list of str
        Joint ids (the model's, then ``"ground:<node>"`` for each slider's virtual ground
        point) and edge ids (member ids for bars; ``"plate<k>:<a>-<b>"``, ``"ground:<a>-<b>"``,
        ``"slider:<node>"`` for added edges).
    plates : list of list of str
        The joints of each triangulated plate.
    planar_supports : list of str
        Nodes fixed in one direction of space only, left free in the equivalent mechanism.
    """

    assembly: EquivalentAssembly
    graph: GraphTopology
    incidence: sp.csr_matrix
    complete_cycles: np.ndarray | None
    node_ids: list[str]
    edge_ids: list[str]
    plates: list[list[str]]
    planar_supports: list[str]


def _plates(structure: Structure) -> list[list[int]]:
    """Groups of beam members joined rigidly; each group's joints, for groups of ≥ 3."""
    conn = structure.connectivity
    beams = np.flatnonzero(structure.is_beam)
    parent = {int(k): int(k) for k in beams}

    def find(k):
        while parent[k] != k:
            parent[k] = parent[parent[k]]
            k = parent[k]
        return k

    rigid_end = {}                                    # node → beams rigidly attached there
    for k in beams:
        for end in (0, 1):
            if not structure.releases[k, end]:
                rigid_end.setdefault(int(conn[k, end]), []).append(int(k))
    for members in rigid_end.values():
        for k in members[1:]:
            parent[find(k)] = find(members[0])
    groups: dict[int, set[int]] = {}
    for k in beams:
        groups.setdefault(find(int(k)), set()).update(int(i) for i in conn[k])
    return [sorted(g) for g in groups.values() if len(g) >= 3]


def model_topology(structure: Structure) -> ModelTopology:
    """The equivalent bar-only mechanism of a model and its graph (module docstring).

    Raises
    ------
    InputError
        A model without members, without a fixed node, or whose graph is not connected.
    """
    name = structure.source or structure.name or "model"
    if structure.n_members == 0:
        raise InputError(name, "the model has no members: its graph has no edges")
    sup = structure.translation_supports
    dim = structure.dim
    ground = np.flatnonzero(sup.all(axis=1))
    if ground.size == 0:
        raise InputError(name, "no node is fixed in every direction: the mechanism needs a "
                               "fixed element (the ground) for its graph to be closed")
    partial = np.flatnonzero(sup.any(axis=1) & ~sup.all(axis=1))
    sliders = {}
    planar = []
    for i in partial:
        free = np.flatnonzero(~sup[i])
        if free.size == 1:
            sliders[int(i)] = np.eye(dim)[free[0]]
        else:
            planar.append(int(i))
    plates = _plates(structure)
    in_plate = np.zeros(structure.n_members, dtype=bool)
    if plates:
        nodes_of = [set(p) for p in plates]
        for k in np.flatnonzero(structure.is_beam):
            a, b = (int(i) for i in structure.connectivity[k])
            in_plate[k] = any(a in p and b in p for p in nodes_of)
    bar_idx = np.flatnonzero(~in_plate)
    eq = equivalent_assembly(structure.coords, structure.connectivity[bar_idx],
                             ground=[int(g) for g in ground], plates=plates, sliders=sliders)
    n = eq.coords.shape[0]
    node_ids = list(structure.node_ids) + [f"ground:{structure.node_ids[j]}" for j in sliders]
    graph = graph_topology(n, eq.connectivity, int(eq.ground[0]), names=node_ids,
                           item=structure.source or structure.name)
    edge_ids = []
    for (a, b), kind, src in zip(eq.connectivity, eq.kinds, eq.source):
        if src >= 0:
            edge_ids.append(structure.member_ids[bar_idx[src]])
        elif kind == "plate":
            k = next(i for i, p in enumerate(plates) if a in p and b in p)
            edge_ids.append(f"plate{k + 1}:{node_ids[a]}-{node_ids[b]}")
        elif kind == "slider":
            edge_ids.append(f"slider:{node_ids[b]}")
        else:
            edge_ids.append(f"ground:{node_ids[a]}-{node_ids[b]}")
    return ModelTopology(
        assembly=eq, graph=graph, incidence=incidence_matrix(n, eq.connectivity),
        complete_cycles=complete_cycle_matrix(n, eq.connectivity, graph,
                                              MAX_COMPLETE_CYCLE_RANK),
        node_ids=node_ids, edge_ids=edge_ids,
        plates=[[node_ids[i] for i in p] for p in plates],
        planar_supports=[structure.node_ids[i] for i in planar])
