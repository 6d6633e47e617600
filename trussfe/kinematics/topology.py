# SPDX-License-Identifier: MIT
"""Graph topology of bar-and-joint assemblies and cycle kinematics (Vlase et al. 2008).

The joints are the graph's nodes and the bars its edges, each edge oriented from its start to
its end joint (Vlase section 2.1).  With ``r + 1`` nodes and ``s`` edges:

* complete incidence matrix ``A_a`` ((r+1) × s): ``+1`` where the edge leaves the node, ``−1``
  where it enters; the reduced incidence matrix ``A`` drops the row of a reference node;
* a spanning tree (r edges) and its cotree (the ``s − r`` links) partition ``A = [A_t | A_l]``
  (Vlase eq. 1);
* the fundamental cycle matrix ``B_f = [(−A_t⁻¹ A_l)ᵀ | I]`` (Vlase eq. 2), one row per link,
  satisfying ``A B_fᵀ = 0``;
* the compatibility matrix is the incidence matrix expanded by the direction cosines:
  ``B[j, (i, ·)] = −A_a[i, j] e_j``.

Cycle kinematics (planar, Vlase section 3): the edge vectors ``u_j = L_j e_j`` close every
fundamental cycle, ``B_f U = 0``; differentiating, ``B_f U̇ = 0`` with
``u̇_j = L̇_j e_j + ω_j L_j e_j^⊥`` gives the bar angular velocities ω and the slider rates L̇, and
once more the angular accelerations.  The kinematically equivalent assembly needed for this is
built of bars only: a rigid plate becomes triangulated bars, the ground joints are closed by
"ground" edges (fixed length and direction) and each slider by a "slider" edge of fixed
direction and variable length.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.csgraph as csg

from ..errors import AnalysisError, InputError
from ..linalg import factor
from ..mechanics.geometry import member_vectors, unit_vectors


def incidence_matrix(n_nodes: int, connectivity: np.ndarray) -> sp.csr_matrix:
    """Complete incidence matrix ``A_a`` ((r+1) × s), Vlase section 2.2.

    Examples
    --------
    >>> incidence_matrix(3, np.array([[0, 1], [1, 2], [2, 0]])).toarray()
    array([[ 1,  0, -1],
           [-1,  1,  0],
           [ 0, -1,  1]])
    """
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    s = conn.shape[0]
    rows = conn.ravel()                                    # (edge, end) flattened
    cols = np.repeat(np.arange(s), 2)
    vals = np.tile(np.array([1, -1], dtype=np.int64), s)
    return sp.csr_matrix((vals, (rows, cols)), shape=(n_nodes, s))


def reduced_incidence_matrix(n_nodes: int, connectivity: np.ndarray,
                             reference: int = 0) -> sp.csr_matrix:
    """Incidence matrix ``A`` without the row of the ``reference`` node."""
    A = incidence_matrix(n_nodes, connectivity)
    keep = np.flatnonzero(np.arange(n_nodes) != reference)
    return A[keep]


@dataclass
class GraphTopology:
    """Tree/cotree partition and fundamental cycles of an assembly's graph.

    Attributes
    ----------
    reference : int
        Node whose incidence row is dropped (the tree's root).
    tree, links : ndarray of int
        Edge indices of the spanning tree (r) and the cotree (s − r).
    reduced_incidence : scipy.sparse.csr_matrix, shape (r, s)
    cycle_matrix : ndarray of int, shape (s − r, s)
        Fundamental cycle matrix in the original edge order (columns), one row per link.
    """

    reference: int
    tree: np.ndarray
    links: np.ndarray
    reduced_incidence: sp.csr_matrix
    cycle_matrix: np.ndarray


def graph_topology(n_nodes: int, connectivity: np.ndarray, reference: int = 0, *,
                   names: list[str] | None = None, item: str = "topology") -> GraphTopology:
    """Spanning tree, cotree and fundamental cycle matrix (Vlase eq. 1–2).

    Parameters
    ----------
    n_nodes : int
    connectivity : ndarray of int, shape (s, 2)
    reference : int
        The tree's root (its incidence row is dropped).
    names : list of str, optional
        The joints' ids, for the message of a graph that is not connected (else indices).
    item : str
        Where the message says the fault lies (the model file).

    Raises
    ------
    InputError
        If the graph is not connected (no spanning tree exists).

    Examples
    --------
    A four-bar loop has one fundamental cycle through all four edges:

    >>> t = graph_topology(4, np.array([[0, 1], [1, 2], [2, 3], [3, 0]]))
    >>> t.cycle_matrix.shape, int(np.abs(t.cycle_matrix).sum())
    ((1, 4), 4)
    """
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    s = conn.shape[0]
    # One edge per pair of joints carries the tree (the first of parallel edges, such as a
    # bar between two ground joints beside the edge closing the ground): a sparse matrix
    # built from repeated pairs would add their indices up.
    lo, hi = np.minimum(conn[:, 0], conn[:, 1]), np.maximum(conn[:, 0], conn[:, 1])
    _, first = np.unique(lo * n_nodes + hi, return_index=True)
    sym = sp.csr_matrix((np.r_[first, first] + 1, (np.r_[lo[first], hi[first]],
                                                    np.r_[hi[first], lo[first]])),
                        shape=(n_nodes, n_nodes))
    order, pred = csg.breadth_first_order(sym, reference, directed=False,
                                          return_predecessors=True)
    if order.size != n_nodes:
        missing = np.setdiff1d(np.arange(n_nodes), order)
        label = (lambda i: f"'{names[i]}'") if names is not None else str
        more = f" and {missing.size - 5} more" if missing.size > 5 else ""
        raise InputError(item, "the assembly is not connected: node(s) "
                         f"{', '.join(label(int(i)) for i in missing[:5])}{more} cannot be "
                         f"reached from node {label(int(reference))} (a joint with no bar "
                         "to the rest)")
    child = order[1:]
    parent = pred[child]
    # edge index of each (parent, child) pair, whichever way the edge is oriented
    tree = np.asarray(sym[parent, child]).ravel() - 1
    links = np.setdiff1d(np.arange(s), tree)
    A = reduced_incidence_matrix(n_nodes, conn, reference)
    At = A[:, tree].tocsc().astype(float)
    Al = A[:, links].toarray().astype(float)
    C = np.zeros((links.size, s))
    if links.size:
        X = factor(At, "general").solve(Al, refine=False)   # A_t⁻¹ A_l, (r, s − r)
        C[:, tree] = -X.T
        C[np.arange(links.size), links] = 1.0
    return GraphTopology(reference=reference, tree=tree, links=links, reduced_incidence=A,
                         cycle_matrix=np.rint(C).astype(np.int64))


def compatibility_from_incidence(coords: np.ndarray, connectivity: np.ndarray) -> sp.csr_matrix:
    """Compatibility matrix as the incidence matrix expanded by the direction cosines.

    ``B[j, (i, k)] = −A_a[i, j] e_jk`` — equal to
    :func:`~trussfe.kinematics.compatibility.compatibility_matrix` (tested).
    """
    x = np.asarray(coords, float)
    n, dim = x.shape
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    Aa = incidence_matrix(n, conn).T.tocsr().astype(float)  # (s, n)
    vec = member_vectors(x, conn)
    e = unit_vectors(vec)[0]
    blocks = [(-sp.diags(e[:, k]) @ Aa) for k in range(dim)]  # (s, n) per axis
    B = sp.hstack(blocks).tocsr()                           # columns ordered (axis, node)
    perm = (np.arange(n)[:, None] + n * np.arange(dim)[None, :]).ravel()  # to (node, axis)
    return B[:, perm]


# --------------------------------------------------------------------------- equivalent assembly
#: Edge kinds of the kinematically equivalent assembly.
BAR, PLATE, GROUND, SLIDER = "bar", "plate", "ground", "slider"


@dataclass
class EquivalentAssembly:
    """A bar-only assembly kinematically equivalent to a linkage (Vlase section 2.1).

    Attributes
    ----------
    coords : ndarray, shape (n', dim)
        Joints; virtual ground points of sliders are appended after the original joints.
    connectivity : ndarray of int, shape (s, 2)
    kinds : ndarray of str, shape (s,)
        ``"bar"`` (given bars), ``"plate"`` (triangulation of a rigid plate), ``"ground"``
        (closes the ground: fixed length and direction), ``"slider"`` (fixed direction,
        variable length).
    source : ndarray of int, shape (s,)
        Index of the given bar an edge stands for (−1 for added edges).
    ground : ndarray of int
        Ground joints (fixed).
    """

    coords: np.ndarray
    connectivity: np.ndarray
    kinds: np.ndarray
    source: np.ndarray
    ground: np.ndarray

    @property
    def topology(self) -> GraphTopology:
        """Tree, cotree and fundamental cycles, rooted at the first ground joint."""
        return graph_topology(self.coords.shape[0], self.connectivity, int(self.ground[0]))


def _triangulate_plate(coords: np.ndarray, plate: list[int], item: str) -> list[tuple[int, int]]:
    """Bars making a plate's joints rigid: a base pair, then each joint tied to it (2-D) or to a
    base triangle (3-D) — Henneberg's construction, rigid unless the base is degenerate."""
    p = [int(i) for i in plate]
    if len(p) < 2:
        raise InputError(item, "a plate needs at least two joints")
    x = coords[p]
    dim = coords.shape[1]
    a = 0
    b = int(np.argmax(np.linalg.norm(x - x[a], axis=1)))
    base = [a, b]
    if dim == 3 and len(p) > 2:
        u = x[b] - x[a]
        area = np.linalg.norm(np.cross(x - x[a], u), axis=1)
        c = int(np.argmax(area))
        if area[c] > 1e-9 * np.dot(u, u):
            base.append(c)
    bars = [(p[base[i]], p[base[j]]) for i in range(len(base)) for j in range(i + 1, len(base))]
    for i in range(len(p)):
        if i not in base:
            bars += [(p[k], p[i]) for k in base]
    return bars


def equivalent_assembly(coords: np.ndarray, bars: np.ndarray, *, ground: list[int],
                        plates: list[list[int]] = (), sliders: dict[int, np.ndarray] | None = None
                        ) -> EquivalentAssembly:
    """Build the kinematically equivalent bar-only assembly of a linkage (Vlase section 2.1).

    Parameters
    ----------
    coords : ndarray, shape (n, dim)
    bars : ndarray of int, shape (m, 2)
        Binary links (bars).
    ground : list of int
        Joints on the fixed element.  They are chained by ``ground`` edges that close the
        polygon with the frame (Vlase construction II: the closing element is the sum of the
        others and is left out).
    plates : list of list of int
        Joints of each rigid plate (a link with more than two joints); triangulated by bars
        (construction I).
    sliders : dict, optional
        Joint → slide direction.  A virtual ground point is placed behind the joint along the
        direction (half the assembly's largest extent); the ``slider`` edge from it to the joint
        has a fixed direction and variable length.

    Returns
    -------
    EquivalentAssembly

    Examples
    --------
    A slider-crank (pivot 0, crank pin 1, slider 2 on the x axis): the equivalent assembly has
    the crank, the connecting rod, a slider edge and a ground edge, one fundamental cycle.

    >>> x = np.array([[0., 0.], [0.3, 0.4], [1.5, 0.]])
    >>> eq = equivalent_assembly(x, np.array([[0, 1], [1, 2]]), ground=[0],
    ...                          sliders={2: np.array([1., 0.])})
    >>> eq.kinds.tolist(), eq.topology.cycle_matrix.shape
    (['bar', 'bar', 'slider', 'ground'], (1, 4))
    """
    x = np.asarray(coords, float)
    n, dim = x.shape
    conn = [tuple(map(int, c)) for c in np.asarray(bars, dtype=np.int64).reshape(-1, 2)]
    kinds = [BAR] * len(conn)
    source = list(range(len(conn)))
    for k, plate in enumerate(plates):
        tri = _triangulate_plate(x, plate, f"plates[{k}]")
        conn += tri
        kinds += [PLATE] * len(tri)
        source += [-1] * len(tri)
    ground = [int(g) for g in ground]
    if not ground:
        raise InputError("ground", "at least one ground joint is needed")
    scale = 0.5 * float(np.ptp(x, axis=0).max()) or 1.0
    pts = [x]
    gchain = list(ground)
    for j, direction in (sliders or {}).items():
        e = np.asarray(direction, float)
        e = e / np.linalg.norm(e)
        g = n + len(pts) - 1
        g_x = x[int(j)] - scale * e
        if np.min(np.linalg.norm(np.vstack(pts) - g_x, axis=1)) < 1e-9 * scale:
            g_x = x[int(j)] - 1.5 * scale * e              # avoid a zero-length ground edge
        pts.append(g_x[None, :])
        conn.append((g, int(j)))
        kinds.append(SLIDER)
        source.append(-1)
        gchain.append(g)
    for a, b in zip(gchain[:-1], gchain[1:]):
        conn.append((a, b))
        kinds.append(GROUND)
        source.append(-1)
    return EquivalentAssembly(coords=np.vstack(pts), connectivity=np.array(conn, dtype=np.int64),
                              kinds=np.array(kinds), source=np.array(source, dtype=np.int64),
                              ground=np.array(gchain, dtype=np.int64))


# --------------------------------------------------------------------------- cycle kinematics
@dataclass
class CycleKinematics:
    """Velocities (and accelerations) of a planar linkage from its cycle equations.

    Attributes
    ----------
    omega : ndarray, shape (s,)
        Angular velocity of every edge, rad/s (zero for ground and slider edges).
    length_rate : ndarray, shape (s,)
        L̇ of every edge, m/s (non-zero only for sliders).
    velocity : ndarray, shape (n', 2)
        Joint velocities from the tree.
    alpha, length_acceleration, acceleration : ndarray or None
        The second derivatives, when computed.
    """

    omega: np.ndarray
    length_rate: np.ndarray
    velocity: np.ndarray
    alpha: np.ndarray | None = None
    length_acceleration: np.ndarray | None = None
    acceleration: np.ndarray | None = None


def cycle_kinematics(eq: EquivalentAssembly, drive_edge: int, omega: float,
                     alpha: float = 0.0) -> CycleKinematics:
    """Velocities and accelerations of a planar one-degree-of-freedom linkage (Vlase eq. 3).

    Parameters
    ----------
    eq : EquivalentAssembly
        Planar, bar-only equivalent assembly.
    drive_edge : int
        Edge whose angular velocity is prescribed (the crank).
    omega, alpha : float
        Its angular velocity (rad/s) and angular acceleration (rad/s²).

    Returns
    -------
    CycleKinematics

    Notes
    -----
    Unknowns: ω of every bar and plate edge, L̇ of every slider edge (ground edges do not move).
    Velocity equations: ``Σ_j B_f[i, j] (L̇_j e_j + ω_j L_j e_j^⊥) = 0`` (two per cycle);
    accelerations:
    ``Σ_j B_f[i, j] (L̈_j e_j + α_j L_j e_j^⊥ + 2 L̇_j ω_j e_j^⊥ − ω_j² L_j e_j) = 0``.
    Joint velocities follow along the tree from the ground: ``−A_tᵀ V = U̇_t``.
    """
    x = eq.coords
    if x.shape[1] != 2:
        raise InputError("cycle kinematics", "the cycle method is implemented for planar "
                                             "linkages; use the compatibility-matrix method")
    conn = eq.connectivity
    topo = eq.topology
    C = topo.cycle_matrix.astype(float)                    # (cycle, edge)
    u = member_vectors(x, conn)
    L = np.linalg.norm(u, axis=1)
    e = u / L[:, None]
    ep = np.column_stack([-e[:, 1], e[:, 0]])
    rot = np.isin(eq.kinds, [BAR, PLATE])
    sld = eq.kinds == SLIDER
    s = conn.shape[0]
    # columns: ω of rotating edges, L̇ of sliders
    rot_idx = np.flatnonzero(rot)
    sld_idx = np.flatnonzero(sld)
    if drive_edge not in rot_idx:
        raise InputError("drive", f"edge {drive_edge} is not a bar that can turn")
    unk_rot = rot_idx[rot_idx != drive_edge]

    def system(coef_rot, coef_sld):
        # (2·cycles, unknowns): stack x and y components of the cycle sums
        cols = [C[:, unk_rot] * coef_rot[unk_rot, k] for k in range(2)]
        cs = [C[:, sld_idx] * coef_sld[sld_idx, k] for k in range(2)]
        return np.vstack([np.hstack([cols[k], cs[k]]) for k in range(2)])

    M = system(L[:, None] * ep, e)
    if np.linalg.matrix_rank(M) < M.shape[1]:
        raise AnalysisError("cycle kinematics", "the linkage is at a singular position or "
                                                "has more than one degree of freedom")
    known_v = omega * L[drive_edge] * ep[drive_edge]       # (2,)
    rhs = -np.concatenate([C[:, drive_edge] * known_v[k] for k in range(2)])
    sol = np.linalg.lstsq(M, rhs, rcond=None)[0]
    w = np.zeros(s)
    w[drive_edge] = omega
    w[unk_rot] = sol[:unk_rot.size]
    ld = np.zeros(s)
    ld[sld_idx] = sol[unk_rot.size:]
    udot = ld[:, None] * e + (w * L)[:, None] * ep          # (edge, 2)
    vel = _tree_values(topo, udot, x.shape[0])
    # accelerations: known part from ω, L̇ and the driven α
    known_a = (2 * ld * w)[:, None] * ep - (w ** 2 * L)[:, None] * e
    known_a[drive_edge] += alpha * L[drive_edge] * ep[drive_edge]
    rhs_a = -np.concatenate([C @ known_a[:, k] for k in range(2)])
    sol_a = np.linalg.lstsq(M, rhs_a, rcond=None)[0]
    al = np.zeros(s)
    al[drive_edge] = alpha
    al[unk_rot] = sol_a[:unk_rot.size]
    ldd = np.zeros(s)
    ldd[sld_idx] = sol_a[unk_rot.size:]
    uddot = known_a + ldd[:, None] * e + (np.where(np.arange(s) == drive_edge, 0.0, al)
                                          * L)[:, None] * ep
    acc = _tree_values(topo, uddot, x.shape[0])
    return CycleKinematics(omega=w, length_rate=ld, velocity=vel, alpha=al,
                           length_acceleration=ldd, acceleration=acc)


def _tree_values(topo: GraphTopology, edge_rates: np.ndarray, n: int) -> np.ndarray:
    """Joint rates from edge rates along the tree: ``−A_tᵀ V = U̇_t``, root at rest."""
    At = topo.reduced_incidence[:, topo.tree].T.tocsc().astype(float)  # (r, r)
    V = factor(At, "general").solve(-edge_rates[topo.tree], refine=False)
    out = np.zeros((n, edge_rates.shape[1]))
    keep = np.flatnonzero(np.arange(n) != topo.reference)
    out[keep] = V
    return out
