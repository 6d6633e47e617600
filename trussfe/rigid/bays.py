# SPDX-License-Identifier: MIT
"""Lacy's chapter 6 applied to a model file: a chain of identical bays analysed bay by bay.

``trussfe simulate --method bay-by-bay`` (and the default ``--method auto`` on a chain of two
or more bays) analyses a chain the way Lacy (1991) §6.1–6.2 describes it, in O(n) per time
step and batched over the steps:

* **positions** of each bay alone in a frame attached to its base plane — every bay and step
  in one batched Newton iteration from guesses interpolated along the motion
  (:func:`trussfe.rigid.chain.bay_positions`) — carried up the chain, ``x = o_n + R_n p``
  (:func:`trussfe.rigid.chain.chain_positions`, eqs. 6.1–6.3);
* **velocities and accelerations** up the chain and **forces** down it.  The compatibility
  matrix B of a chain is block lower triangular with one 9 × 9 block per plane (a bay's
  midplane, then its top plane: the nodes each bay's own members fix once the plane below
  is known), so ``B v = L̇`` is a forward block substitution from the ground up, and
  ``Bᵀ t = f`` a backward one from the top bay down, in which each bay's member forces at
  its base nodes — its base reactions, reversed — enter the equations of the bay below
  (§6.2).  Both are the stacked 9 × 9 inverses of :class:`~trussfe.rigid.linalg.CompatSolver`
  applied to all steps at once; the loop runs over the bays, never over the steps.

The direct analysis (``--method direct``) differs only in the positions: Newton's method on
the whole truss to a tolerance on the whole chain (on a 1,000-bay chain it stops at a misfit
of 1e-8 m, measured); both give the same results to round-off, which the validation case
``rigid-chain-bay-by-bay`` checks on chains of 1 to 50 bays.

**Which models are chains** (:func:`chain_layout`).  The supported nodes are the ground
triangle: exactly three nodes, fixed in x, y and z.  Counting members from them, every node
lies at a graph distance d ≥ 1 from the ground; the nodes at each distance form a triangle
(three nodes), and bay k holds the planes at distances 2k − 1 (midplane) and 2k (top plane).
Every bay is a rigid copy of the first one (same members between corresponding nodes, the
same active members, congruent node positions, proper rotation — not a mirror image), and
its top plane is the next bay's base in the same node correspondence for every bay.  Lacy's
double-octahedral chains (``meshes/chain3_motion_active.toml``,
``meshes/double_octahedral_chain_10.toml``) are of this kind; a member between two ground
nodes belongs to the first bay's force analysis.
"""
from __future__ import annotations

from dataclasses import dataclass
from itertools import permutations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.csgraph as csg

from ..errors import InputError
from ..model.derived import kept
from ..model.structure import Structure
from .active import active_members
from .chain import chain_positions, triangle_frame
from .motion import Motion

#: The analysis methods of ``simulate``: chosen from the model (``auto``: bay by bay for a
#: chain of two or more identical bays, else direct), the whole truss at once, or Lacy's
#: chapter 6.
METHODS = ("auto", "direct", "bay-by-bay")

#: Relative tolerance of the congruence of the bays (of the bay's largest member length).
CONGRUENCE_TOLERANCE = 1e-9


@dataclass(frozen=True)
class ChainLayout:
    """How a chain model decomposes into identical bays.

    Attributes
    ----------
    nodes : ndarray of int, shape (n_bays, 9)
        Model node of each template node in every bay: base 0–2, midplane 3–5, top 6–8.
    members : ndarray of int, shape (n_bays, m_bay)
        Model member of each template member in every bay.
    ground_members : ndarray of int
        Members between two ground nodes (taken with the first bay's forces).
    next_base : tuple of int
        Template nodes that are the next bay's base nodes 0, 1, 2.
    template : Structure
        The first bay alone: its nine nodes (base fixed), its members and active members.
    """

    nodes: np.ndarray
    members: np.ndarray
    ground_members: np.ndarray
    next_base: tuple[int, int, int]
    template: Structure

    @property
    def n_bays(self) -> int:
        """Number of bays."""
        return int(self.nodes.shape[0])

    @property
    def active(self) -> np.ndarray:
        """Template members that are active, in the template's active-member order."""
        return np.array([a.member for a in active_members(self.template)], dtype=np.int64)

    def stacked_nodes(self) -> np.ndarray:
        """Model node of every node of the stacked numbering of
        :func:`~trussfe.rigid.chain.chain_kinematics` (base, then six per bay)."""
        return np.concatenate([self.nodes[0, :3], self.nodes[:, 3:].ravel()])


def _not_a_chain(structure: Structure, why: str) -> InputError:
    return InputError(structure.source or structure.name or "model",
                      f"--method bay-by-bay needs a chain of identical bays on a ground "
                      f"triangle (Lacy ch. 6): {why}")


def _distances(structure: Structure, ground: np.ndarray) -> np.ndarray:
    """Graph distance (number of members) of every node from the ground nodes."""
    n, conn = structure.n_nodes, structure.connectivity
    adj = sp.csr_matrix((np.ones(conn.shape[0]), (conn[:, 0], conn[:, 1])), shape=(n, n))
    d = csg.shortest_path(adj, unweighted=True, directed=False, indices=ground)
    return d.min(axis=0)


def chain_layout(structure: Structure) -> ChainLayout:
    """Find the bays of a chain model (module docstring: which models are chains).

    The layout is kept with the model for its later analyses
    (:func:`~trussfe.model.derived.kept`): finding it searches the bays one after another,
    about 0.12 ms per bay.

    Raises
    ------
    InputError
        The model is not a chain of identical bays, saying why.
    """
    return kept(structure, "chain layout", _find_layout)


def _find_layout(structure: Structure) -> ChainLayout:
    """:func:`chain_layout`, searched."""
    if structure.dim != 3:
        raise _not_a_chain(structure, "the model is planar")
    sup = structure.translation_supports
    if np.any(sup.any(axis=1) & ~sup.all(axis=1)):
        raise _not_a_chain(structure, "a node is supported in some directions only")
    ground = np.flatnonzero(sup.all(axis=1))
    if ground.size != 3:
        raise _not_a_chain(structure, f"{ground.size} supported nodes (the ground triangle "
                                      "is three nodes fixed in x, y, z)")
    dist = _distances(structure, ground)
    if not np.all(np.isfinite(dist)):
        k = int(np.flatnonzero(~np.isfinite(dist))[0])
        raise _not_a_chain(structure, f"node '{structure.node_ids[k]}' is not connected to "
                                      "the ground")
    dist = dist.astype(np.int64)
    depth = int(dist.max())
    counts = np.bincount(dist, minlength=depth + 1)
    if depth < 2 or depth % 2 or np.any(counts[1:] != 3):
        raise _not_a_chain(structure, "the nodes at each member count from the ground do "
                                      "not form triangles of three nodes, two per bay")
    conn = structure.connectivity
    dm = dist[conn]
    if np.any(np.abs(dm[:, 0] - dm[:, 1]) > 1):
        k = int(np.flatnonzero(np.abs(dm[:, 0] - dm[:, 1]) > 1)[0])
        raise _not_a_chain(structure, f"member '{structure.member_ids[k]}' skips a plane")
    bay_of = (dm.max(axis=1) + 1) // 2                     # 0: between ground nodes
    nb = depth // 2
    plane = [np.flatnonzero(dist == d) for d in range(depth + 1)]
    first = np.concatenate(plane[:3])
    template = _template(structure, first, np.flatnonzero(bay_of == 1))
    local = _local(template.coords)
    scale = float(template.lengths().max())
    pairs = {frozenset(map(int, c)) for c in template.connectivity}
    tact = {frozenset(map(int, template.connectivity[a.member]))
            for a in active_members(template)}
    act_model = {int(a.member) for a in active_members(structure)}
    member_of = {frozenset(map(int, c)): j for j, c in enumerate(conn)}

    def matches(phi: np.ndarray, k: int) -> np.ndarray | None:
        """Model members of bay k for the node map ``phi``, or None if it is no copy."""
        own = np.flatnonzero(bay_of == k)
        if own.size != len(pairs):
            return None
        mem = []
        for c in template.connectivity:
            j = member_of.get(frozenset((int(phi[c[0]]), int(phi[c[1]]))))
            if j is None or bay_of[j] != k:
                return None
            mem.append(j)
        if {frozenset(map(int, template.connectivity[i])) for i, j in enumerate(mem)
                if j in act_model} != tact:
            return None
        o, R = triangle_frame(structure.coords[phi[:3]])
        if np.abs(o + local @ R.T - structure.coords[phi]).max() > \
                CONGRUENCE_TOLERANCE * scale:
            return None
        return np.array(mem, dtype=np.int64)

    nodes = [first]
    members = [matches(first, 1)]
    next_base = None
    for k in range(2, nb + 1):
        found = None
        bases = ([(nb_, first[list(nb_)]) for nb_ in permutations((6, 7, 8))]
                 if next_base is None else [(next_base, nodes[-1][list(next_base)])])
        for nbase, base in bases:
            for mid in permutations(plane[2 * k - 1]):
                for top in permutations(plane[2 * k]):
                    phi = np.concatenate([base, mid, top]).astype(np.int64)
                    mem = matches(phi, k)
                    if mem is not None:
                        found = (nbase, phi, mem)
                        break
                if found:
                    break
            if found:
                break
        if found is None:
            raise _not_a_chain(structure, f"bay {k} is not a copy of bay 1 (its members, "
                                          "active members or node positions differ)")
        next_base = tuple(int(i) for i in found[0])
        nodes.append(found[1])
        members.append(found[2])
    in_bays = {int(j) for mem in members for j in mem}
    ground_members = np.flatnonzero(bay_of == 0)
    if act_model - in_bays:
        j = sorted(act_model - in_bays)[0]
        raise _not_a_chain(structure, f"active member '{structure.member_ids[j]}' joins "
                                      "two ground nodes")
    return ChainLayout(nodes=np.array(nodes, dtype=np.int64),
                       members=np.array(members, dtype=np.int64),
                       ground_members=ground_members,
                       next_base=next_base or (6, 8, 7), template=template)


def _local(x: np.ndarray) -> np.ndarray:
    """Coordinates of the nine template nodes in the frame of their base triangle."""
    o, R = triangle_frame(x[:3])
    return (x - o) @ R


def _template(structure: Structure, nodes: np.ndarray, members: np.ndarray) -> Structure:
    """The first bay alone: nodes ``nodes`` (base first, fixed), members ``members``."""
    keep = np.zeros(structure.n_members, dtype=bool)
    keep[members] = True
    sub = structure.subset_members(keep)
    where = -np.ones(structure.n_nodes, dtype=np.int64)
    where[nodes] = np.arange(nodes.size)
    sup = np.zeros((nodes.size, structure.ndof_node), dtype=bool)
    sup[:3, :3] = True
    return sub.variant(node_ids=tuple(structure.node_ids[i] for i in nodes),
                       coords=structure.coords[nodes], connectivity=where[sub.connectivity],
                       supports=sup, loads=np.zeros((nodes.size, structure.ndof_node)),
                       masses=np.zeros(nodes.size))


# --------------------------------------------------------------------------- kinematics
def bay_lengths(structure: Structure, layout: ChainLayout, motion: Motion
                ) -> tuple[np.ndarray, ...]:
    """Active lengths, rates and accelerations of every bay, each (nt, n_bays, n_active)
    in the template's active order (an active member the motion does not drive keeps its
    model length)."""
    nt = motion.n_steps
    cols = layout.members[:, layout.active]                 # (nb, na)
    L = np.broadcast_to(structure.lengths()[cols], (nt,) + cols.shape).copy()
    Ld = np.zeros_like(L)
    Ldd = np.zeros_like(L)
    if motion.members.size:
        # the bays' active members the motion drives, and their columns in the motion (a
        # member listed twice: its last column, as an assignment by member would leave it)
        order = np.argsort(motion.members, kind="stable")
        at = np.maximum(np.searchsorted(motion.members, cols, side="right", sorter=order) - 1,
                        0)
        driven = motion.members[order[at]] == cols
        src = order[at[driven]]
        L[:, driven] = motion.length[:, src]
        Ld[:, driven] = motion.velocity[:, src]
        Ldd[:, driven] = motion.acceleration[:, src]
    return L, Ld, Ldd


def bay_by_bay_positions(structure: Structure, motion: Motion, layout: ChainLayout
                         ) -> np.ndarray:
    """Node positions of the chain found bay by bay (Lacy eqs. 6.1–6.3): each bay alone in
    the frame of its base plane, all bays and steps at once, carried up the chain; in the
    model's node numbering, (nt, n, 3)."""
    L, Ld, _ = bay_lengths(structure, layout, motion)
    Xc = chain_positions(layout.template, L, next_base=layout.next_base, rates=Ld,
                         time=motion.time)
    nodes = layout.stacked_nodes()
    if nodes.size == structure.n_nodes and np.array_equal(nodes, np.arange(nodes.size)):
        return Xc                  # the model numbers its nodes as the stacked chain does
    X = np.zeros((motion.n_steps, structure.n_nodes, 3))
    X[:, nodes] = Xc
    return X


def chain_layout_or_none(structure: Structure) -> ChainLayout | None:
    """:func:`chain_layout`, or ``None`` when the model is not a chain of identical bays
    (``simulate``'s automatic method runs bay by bay when it finds two or more)."""
    try:
        return chain_layout(structure)
    except InputError:
        return None
