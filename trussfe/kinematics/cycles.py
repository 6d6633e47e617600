# SPDX-License-Identifier: MIT
"""Cycle-equation kinematics in the plane and in space, and the complete cycle matrix
(Vlase et al. 2008 §2.2–3, extended to 3-D).

Every edge j of the bar-only equivalent assembly (:func:`~trussfe.kinematics.topology.
equivalent_assembly`) carries its vector ``u_j = L_j e_j``, and every cycle closes:
``B_f U = 0`` (Vlase eq. 2), hence ``B_f U̇ = 0`` and ``B_f Ü = 0``.  A bar turns with an
angular velocity ω_j; only its part normal to the bar moves the bar (the spin about its own
axis is no motion of a bar), so ω_j has two unknown components in space — along two unit
vectors p_j, q_j normal to e_j — and one (along n̂3) in the plane.  Differentiating
``u = L e`` with ``ė = ω × e``:

.. math::

   \\dot u_j &= \\dot L_j e_j + L_j\\, \\omega_j \\times e_j, \\\\
   \\ddot u_j &= \\ddot L_j e_j + L_j\\, \\alpha_j \\times e_j
      + 2 \\dot L_j\\, \\omega_j \\times e_j + L_j\\, \\omega_j \\times (\\omega_j \\times e_j),

with α_j normal to e_j as well (ω·e = 0 at all times gives α·e = −ω·ė = 0).  Ground edges do
not move; a slider edge keeps its direction and its L̇ is unknown; a bar's L̇ is zero unless
prescribed (an active member).  The unknowns are found from the ``dim × (s − r)`` cycle
equations together with the prescribed joint velocities (accelerations), each a sum of edge
rates along the tree from the ground (``−A_tᵀ V = U̇_t``).  The acceleration equations have
the velocity equations' matrix, with the known quadratic terms on the right.

The complete cycle matrix ``B_a`` (Vlase §2.2) has one row for every simple cycle of the
graph; :func:`complete_cycle_matrix` finds them among the ``2^(s−r) − 1`` sums of fundamental
cycles (a sum is a simple cycle when every node it touches has two of its edges and they are
connected).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.csgraph as csg

from ..errors import AnalysisError, InputError
from ..mechanics.geometry import member_vectors
from .topology import BAR, GROUND, PLATE, SLIDER, EquivalentAssembly, GraphTopology

#: Largest cycle-space dimension s − r for which the complete cycle matrix is enumerated
#: (2^16 − 1 sums of fundamental cycles).
MAX_COMPLETE_CYCLE_RANK = 16


def complete_cycle_matrix(n_nodes: int, connectivity: np.ndarray, topology: GraphTopology,
                          max_rank: int = MAX_COMPLETE_CYCLE_RANK) -> np.ndarray | None:
    """Every simple cycle of the graph, oriented, one row each (Vlase §2.2, ``B_a``).

    Parameters
    ----------
    n_nodes : int
    connectivity : ndarray of int, shape (s, 2)
    topology : GraphTopology
        Its tree, cotree and fundamental cycles (:func:`graph_topology`).
    max_rank : int
        ``None`` is returned when s − r exceeds it (the number of sums doubles with every
        link).

    Returns
    -------
    ndarray of int, shape (cycles, s), or None
        Entries +1 (edge along the cycle's sense), −1 (against), 0.  Each cycle's sense is
        that of its first link (cotree edge); the fundamental cycles come first, in the order
        of ``topology.cycle_matrix``, then the others by increasing length.

    Examples
    --------
    The complete graph on four nodes has seven simple cycles (four triangles, three
    four-cycles) and three fundamental ones:

    >>> from trussfe.kinematics.topology import graph_topology
    >>> conn = np.array([[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]])
    >>> Ba = complete_cycle_matrix(4, conn, graph_topology(4, conn))
    >>> Ba.shape, int(np.abs(Ba[:3]).sum())
    ((7, 6), 9)
    """
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    C = topology.cycle_matrix
    k, s = C.shape
    if k > max_rank:
        return None
    if k == 0:
        return np.zeros((0, s), dtype=np.int64)
    # All non-empty subsets of the fundamental cycles, their edge sets mod 2.
    bits = ((np.arange(1, 2 ** k)[:, None] >> np.arange(k)) & 1).astype(np.int64)
    support = (bits @ (C != 0).astype(np.int64)) % 2                  # (sums, s)
    inc = sp.csr_matrix((np.ones(2 * s), (conn.ravel(), np.repeat(np.arange(s), 2))),
                        shape=(n_nodes, s))
    degree = np.asarray(inc @ support.T).T                              # (sums, n)
    even = np.all((degree == 0) | (degree == 2), axis=1)
    rows = []
    for j in np.flatnonzero(even):
        edges = np.flatnonzero(support[j])
        nodes = np.unique(conn[edges])
        if edges.size != nodes.size:
            continue
        local = np.searchsorted(nodes, conn[edges])
        g = sp.csr_matrix((np.ones(edges.size), (local[:, 0], local[:, 1])),
                          shape=(nodes.size, nodes.size))
        if csg.connected_components(g, directed=False)[0] != 1:
            continue                                 # disjoint cycles: not a simple cycle
        rows.append(_orient(conn, edges, topology.links))
    B = np.array(rows, dtype=np.int64)
    # Fundamental cycles first (in their order), then the rest by length.
    key = {tuple(np.abs(c)): i for i, c in enumerate(C)}
    order = sorted(range(len(B)), key=lambda i: (key.get(tuple(np.abs(B[i])), k),
                                                 int(np.abs(B[i]).sum()), tuple(-np.abs(B[i]))))
    return B[order]


def _orient(conn: np.ndarray, edges: np.ndarray, links: np.ndarray) -> np.ndarray:
    """The signed row of the simple cycle on ``edges``, in the sense of its first link."""
    first = int(edges[np.isin(edges, links)][0])
    row = np.zeros(conn.shape[0], dtype=np.int64)
    row[first] = 1
    node = int(conn[first, 1])
    left = set(int(e) for e in edges) - {first}
    while left:
        e = next(e for e in left if node in conn[e])
        row[e] = 1 if conn[e, 0] == node else -1
        node = int(conn[e, 1] if conn[e, 0] == node else conn[e, 0])
        left.discard(e)
    return row


# --------------------------------------------------------------------------- rates
@dataclass
class CycleRates:
    """Velocities and accelerations of an assembly from its cycle equations.

    Attributes
    ----------
    omega, alpha : ndarray, shape (s, 3)
        Angular velocity and acceleration of every edge, normal to it (zero for ground and
        slider edges), rad/s and rad/s².
    length_rate, length_acceleration : ndarray, shape (s,)
        L̇ and L̈ of every edge.
    velocity, acceleration : ndarray, shape (n', dim)
        Joint velocities and accelerations, from the tree.
    """

    omega: np.ndarray
    length_rate: np.ndarray
    velocity: np.ndarray
    alpha: np.ndarray
    length_acceleration: np.ndarray
    acceleration: np.ndarray


def _normals(e: np.ndarray) -> np.ndarray:
    """Unit vectors normal to each edge, (s, c, 3): n̂3 in the plane, two in space."""
    if e.shape[1] == 2:
        return np.broadcast_to([[[0.0, 0.0, 1.0]]], (e.shape[0], 1, 3)).copy()
    helper = np.eye(3)[np.argmin(np.abs(e), axis=1)]
    p = np.cross(e, helper)
    p /= np.linalg.norm(p, axis=1)[:, None]
    return np.stack([p, np.cross(e, p)], axis=1)


def cycle_rates(eq: EquivalentAssembly, *, length_rates: dict[int, float] | None = None,
                node_velocities: dict[tuple[int, int], float] | None = None,
                length_accelerations: dict[int, float] | None = None,
                node_accelerations: dict[tuple[int, int], float] | None = None,
                item: str = "cycle kinematics") -> CycleRates:
    """Velocities and accelerations from the cycle equations, in the plane or in space
    (Vlase et al. 2008 eq. 3, module docstring).

    Parameters
    ----------
    eq : EquivalentAssembly
        Bar-only equivalent assembly (its first ground joint is the tree's root, at rest).
    length_rates, length_accelerations : dict, optional
        Edge → prescribed L̇, L̈ (active members; a slider edge's rate may be prescribed too).
    node_velocities, node_accelerations : dict, optional
        (joint, axis) → prescribed velocity, acceleration component (a driven joint).  Give
        the accelerations of the same components (zero when omitted).
    item : str
        Names the analysis in error messages.

    Returns
    -------
    CycleRates

    Raises
    ------
    AnalysisError
        The drives do not determine the motion (too few, or a singular position), or
        contradict the cycle equations.
    """
    x = eq.coords
    n, dim = x.shape
    conn = eq.connectivity
    topo = eq.topology
    C = topo.cycle_matrix.astype(float)
    s = conn.shape[0]
    u = member_vectors(x, conn)
    L = np.linalg.norm(u, axis=1)
    e = u / L[:, None]
    e3 = np.pad(e, ((0, 0), (0, 3 - dim)))
    normals = _normals(e)                                   # (s, c, 3)
    nc = normals.shape[1]
    rot = np.flatnonzero(np.isin(eq.kinds, [BAR, PLATE]))
    ld_given = dict(length_rates or {})
    ldd_given = dict(length_accelerations or {})
    for j in ld_given:
        if eq.kinds[j] == GROUND:
            raise InputError(item, f"edge {j} closes the ground; its length cannot change")
    sld = np.array([j for j in np.flatnonzero(eq.kinds == SLIDER) if j not in ld_given],
                   dtype=np.int64)
    # Columns: ω components of turning edges, then L̇ of sliders with unknown rate.
    # Edge-rate matrix G (s·dim, unknowns): u̇ = G z + known.
    nu = rot.size * nc + sld.size
    G = np.zeros((s, dim, nu))
    # L ω × e for ω = t (a normal): L (t × e)
    tx = np.cross(normals, e3[:, None, :])[..., :dim] * L[:, None, None]   # (s, c, dim)
    for c in range(nc):
        G[rot, :, np.arange(rot.size) * nc + c] = tx[rot, c]
    G[sld, :, rot.size * nc + np.arange(sld.size)] = e[sld]
    # Cycle rows (dim per cycle) and drive rows (joint rates along the tree).
    cyc = np.einsum("ij,jkz->ikz", C, G).reshape(-1, nu)
    P = _tree_operator(topo, n)                               # (n, s): V = P U̇ (per axis)
    drives_v = dict(node_velocities or {})
    drives_a = dict(node_accelerations or {})
    keys = sorted(set(drives_v) | set(drives_a))
    rows = [np.einsum("j,jz->z", P[i], G[:, a]) for i, a in keys]
    M = np.vstack([cyc, *rows]) if rows else cyc

    def solve(known: np.ndarray, values: dict) -> np.ndarray:
        rhs_c = -(C @ known).ravel()
        rhs_d = [values.get(k, 0.0) - P[k[0]] @ known[:, k[1]] for k in keys]
        rhs = np.concatenate([rhs_c, rhs_d])
        z, _, rank, _ = np.linalg.lstsq(M, rhs, rcond=1e-10)
        if rank < nu:
            raise AnalysisError(item, f"the drives do not determine the motion ({rank} "
                                      f"independent equations for {nu} unknowns: too few "
                                      "drives, or a singular position)")
        if np.linalg.norm(M @ z - rhs) > 1e-8 * max(1.0, np.linalg.norm(rhs)):
            raise AnalysisError(item, "the prescribed rates contradict the cycle equations")
        return z

    ld = np.zeros(s)
    for j, v in ld_given.items():
        ld[j] = v
    known_v = ld[:, None] * e
    z = solve(known_v, drives_v)
    w = np.zeros((s, 3))
    w[rot] = np.einsum("rc,rck->rk", z[:rot.size * nc].reshape(rot.size, nc), normals[rot])
    ld[sld] = z[rot.size * nc:]
    udot = known_v + np.einsum("jkz,z->jk", G, z)
    vel = P @ udot
    # Accelerations: the known quadratic part with the prescribed L̈.
    ldd = np.zeros(s)
    for j, v in ldd_given.items():
        ldd[j] = v
    wxe = np.cross(w, e3)
    known_a = (ldd[:, None] * e3 + 2 * ld[:, None] * wxe
               + L[:, None] * np.cross(w, wxe))[:, :dim]
    za = solve(known_a, drives_a)
    al = np.zeros((s, 3))
    al[rot] = np.einsum("rc,rck->rk", za[:rot.size * nc].reshape(rot.size, nc), normals[rot])
    ldd[sld] = za[rot.size * nc:]
    uddot = known_a + np.einsum("jkz,z->jk", G, za)
    return CycleRates(omega=w, length_rate=ld, velocity=vel, alpha=al,
                      length_acceleration=ldd, acceleration=P @ uddot)


def _tree_operator(topo: GraphTopology, n: int) -> np.ndarray:
    """P (n, s) with joint rates ``V = P U̇`` from the tree edges (``−A_tᵀ V = U̇_t``, the
    root at rest); zero columns for the links."""
    At = topo.reduced_incidence[:, topo.tree].T.toarray().astype(float)      # (r, r)
    inv = -np.linalg.inv(At)
    P = np.zeros((n, topo.reduced_incidence.shape[1]))
    keep = np.flatnonzero(np.arange(n) != topo.reference)
    P[np.ix_(keep, topo.tree)] = inv
    return P
