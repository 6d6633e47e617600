# SPDX-License-Identifier: MIT
"""Newton–Euler force model of a pin-jointed truss along a motion (Lacy chapters 2 and 4).

Every member is a rigid body pinned at its two end nodes.  A passive member is a uniform tube;
an active member is its active base (pinned at the start node) plus its leadscrew tube
(pinned at the end node) turning together (:mod:`trussfe.rigid.active`).  Each member is a set
of mass elements ``k`` with mass m_k, centre of gravity at distance s_k(t) from the start node
along the unit vector e and moment of inertia I_k about its own centre of gravity.

**Member equations** (Lacy eqs. 2.9–2.11, 4.20).  With F_a, F_b the forces the nodes exert on
the member's ends, d = x_b − x_a = L e, and a_k = a_a + s̈_k e + 2 ṡ_k ė + s_k ë the
acceleration of element k,

.. math::

   F_a + F_b &= R = \\sum_k m_k (a_k - g), \\\\
   d \\times F_b &= M_a = \\sum_k \\left[ s_k e \\times m_k (a_k - g) + I_k \\alpha \\right].

The moment equation fixes the transverse part of F_b, ``F_b⊥ = (M_a × e)/L``, and the force
equation the transverse part of F_a; along the axis one unknown is left per member, the
tension ``t = F_b·e`` at its end node (then ``−F_a·e = t − R·e``).

**Nodal equations** (Lacy's nodal constraint equations with lumped masses M_n and loads P_n):
``Σ_ends F = P + M g − M a + r`` with r the support reactions.  On the free coordinates the
tensions enter through the equilibrium matrix, ``Bᵀ t = P + M g − M a − Σ F_known``, a sparse
square system for a statically determinate truss; the reactions then follow on the supported
coordinates.  This is Lacy's 11 × 11 (triangle) and 117 × 117 (double octahedron) system
with each member's transverse forces eliminated by its own equations; it is
solved for all time steps at once.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AnalysisError
from ..mechanics.active_bodies import MemberBodies, member_bodies
from ..model.derived import kept
from ..model.structure import Structure
from .kinematics import Kinematics, _count_message, _Pattern, pad3
from .linalg import SingularStep, batched_solve
from ..vectors import components_first, cross, dot, empty_vectors, take


@dataclass
class NodalForces:
    """Forces at every pin, every time step.

    Attributes
    ----------
    end_force : ndarray, shape (nt, m, 2, 3)
        Force exerted by the start / end node on the member, N.
    tension_end : ndarray, shape (nt, m)
        Axial force at the end node, t = F_b·e (positive in tension).
    tension_start : ndarray, shape (nt, m)
        Axial force at the start node, −F_a·e.
    reactions : ndarray, shape (nt, n, dim)
        Support reactions (zero on free coordinates), N.
    """

    end_force: np.ndarray
    tension_end: np.ndarray
    tension_start: np.ndarray
    reactions: np.ndarray


def _to_nodes(plan: _NodeSums, at_start: np.ndarray, at_end: np.ndarray) -> np.ndarray:
    """Sum member-end vectors (t, m, 3) into the nodes of ``plan`` (:func:`node_sums`): all
    of them, (t, n, 3), or the (t, len(nodes), 3) it was made for; the result's components
    are stored first (:mod:`trussfe.vectors`).

    Each node's sum runs over its member ends in one fixed order — its members' start ends
    by member, then their end ends — from −0 (the exact identity of addition, so that the
    sum is the ends' own left-to-right sum to the last bit, signed zeros included): one
    gathered column of start ends per pass for all nodes that have that many, then one of
    end ends, a few passes of the node degree in all (:class:`_NodeSums`).
    """
    starts, ends = components_first(at_start), components_first(at_end)
    acc = empty_vectors((at_start.shape[0], plan.size, at_start.shape[-1]))
    acc[...] = -0.0
    for sides, cols, counts, reorder in ((starts, plan.start_cols, plan.start_counts, None),
                                         (ends, plan.end_cols, plan.end_counts,
                                          plan.to_end_order)):
        if reorder is not None:
            acc = take(acc, reorder, axis=1)
        for col, c in zip(cols, counts):
            acc[:, :c] += take(sides, col, axis=1)
    acc = take(acc, plan.to_nodes, axis=1)
    if plan.isolated.size:
        acc[:, plan.isolated] = 0.0                  # no end: an empty sum
    return acc


@dataclass(frozen=True)
class _NodeSums:
    """How :func:`_to_nodes` sums the member ends of the nodes of one connectivity.

    The nodes are ordered by their number of start ends, most first, so that the nodes with
    a d-th start end are the first ``start_counts[d]``; ``start_cols[d]`` are those ends'
    members.  ``to_end_order`` reorders them by their number of end ends, with
    ``end_cols``, ``end_counts`` likewise; ``to_nodes`` puts them back in the order asked
    for; ``isolated``: the positions of nodes with no end at all.
    """

    size: int
    start_cols: tuple
    start_counts: tuple
    to_end_order: np.ndarray
    end_cols: tuple
    end_counts: tuple
    to_nodes: np.ndarray
    isolated: np.ndarray


def _supported(structure: Structure) -> np.ndarray:
    """The nodes with a held translation (where reactions act)."""
    return np.flatnonzero(structure.translation_supports.any(axis=1))


def _kept_sums(structure: Structure, at_supports: bool) -> _NodeSums:
    """The :func:`node_sums` of every node of ``structure`` (or of its supported nodes),
    made once and kept with the model (every block of steps of an analysis sums at its
    nodes several times)."""
    def make(s: Structure) -> _NodeSums:
        return node_sums(s.connectivity, s.n_nodes, _supported(s) if at_supports else None)
    return kept(structure, "nodal sums at supports" if at_supports else "nodal sums", make)


def _side_columns(node_of_end: np.ndarray, size: int):
    """For the ends of one side of the members (in member order) at the nodes
    ``node_of_end`` (positions among the ``size`` summed nodes, -1: not summed): the nodes
    ordered by their number of such ends (most first, stably), for each d the members of
    the d-th end of the first nodes that have one, and the nodes' numbers of ends."""
    keep = node_of_end >= 0
    members = np.flatnonzero(keep)
    at = node_of_end[keep]
    counts = np.bincount(at, minlength=size)
    order = np.argsort(-counts, kind="stable")      # nodes with most ends first
    pos = np.empty(size, dtype=np.int64)
    pos[order] = np.arange(size)
    # the ends by node in the new order, each node's in member order
    by = np.lexsort((members, pos[at]))
    node_sorted, member_sorted = pos[at][by], members[by]
    first = np.searchsorted(node_sorted, np.arange(size))
    d = np.arange(node_sorted.size) - first[node_sorted]
    depth = int(counts.max(initial=0))
    cols, cnts = [], []
    for k in range(depth):
        sel = d == k                               # ascending node positions: a prefix
        cols.append(member_sorted[sel])
        cnts.append(int(sel.sum()))
    return order, tuple(cols), tuple(cnts), counts


def node_sums(conn: np.ndarray, n: int, nodes: np.ndarray | None = None) -> _NodeSums:
    """The :class:`_NodeSums` of the ``n`` nodes of connectivity ``conn`` for
    :func:`_to_nodes`, or of the given (distinct) nodes only."""
    wanted = np.arange(n) if nodes is None else np.asarray(nodes, dtype=np.int64)
    size = wanted.size
    where = np.full(n, -1, dtype=np.int64)
    where[wanted] = np.arange(size)
    start_order, start_cols, start_counts, s_counts = _side_columns(where[conn[:, 0]], size)
    # after the start ends the nodes stand in start_order; the end ends by their own order
    position = np.empty(size, dtype=np.int64)       # each node's place in start_order
    position[start_order] = np.arange(size)
    end_order, end_cols, end_counts, e_counts = _side_columns(where[conn[:, 1]], size)
    # acc (in start order) reordered to end order: take the start-order place of each node
    to_end_order = position[end_order]
    back = np.empty(size, dtype=np.int64)
    back[end_order] = np.arange(size)
    return _NodeSums(size=size, start_cols=start_cols, start_counts=start_counts,
                     to_end_order=to_end_order, end_cols=end_cols, end_counts=end_counts,
                     to_nodes=back, isolated=np.flatnonzero((s_counts + e_counts) == 0))


def axis_acceleration(start_acc: np.ndarray, e: np.ndarray, ed: np.ndarray, Ld: np.ndarray,
                      Ldd: np.ndarray) -> np.ndarray:
    """a_0 = a_a + L̈ e + 2 L̇ ė of members (t, m, 3) whose start nodes accelerate by
    ``start_acc``; ``Ld``, ``Ldd`` (t, m, 1).

    A member's point at a distance x from its start node accelerates by a_0 + x ë (Lacy eqs.
    2.3–2.5): the tube's and a section piece's centres of gravity take their accelerations
    from this one sum (the terms added in the order written)."""
    a0 = Ldd * e
    a0 += start_acc
    a0 += np.multiply(2.0 * Ld, ed)
    return a0


def element_accelerations(kin: Kinematics, bodies: MemberBodies, conn: np.ndarray,
                          base_members: np.ndarray | None = None):
    """Accelerations of the tube and base centres of gravity, each (nt, m, 3), and the tube
    centre's distance s_t from the start node, (nt, m, 1); ``base_members``: the bases of
    these members only."""
    edd = kin.unit_acc
    aa = take(kin.acceleration, conn[:, 0], axis=1)
    s_t = kin.length[..., None] - bodies.tube_length[None, :, None] / 2.0
    # a_0 + s_t ë at the tube's centre (eqs. 2.3–2.5)
    a_tube = axis_acceleration(aa, kin.unit, kin.unit_rate, kin.length_rate[..., None],
                               kin.length_acc[..., None])
    a_tube += s_t * edd
    if base_members is None:
        a_base = aa + bodies.base_cg[None, :, None] * edd
    else:
        a_base = (take(aa, base_members, axis=1)
                  + bodies.base_cg[None, base_members, None]
                  * take(edd, base_members, axis=1))
    return a_tube, s_t, a_base


def nodal_forces(structure: Structure, kin: Kinematics, bodies: MemberBodies | None = None,
                 *, check: bool | None = None) -> NodalForces:
    """Solve the Newton–Euler equations at every time step (Lacy eqs. 2.13–2.14, 4.20).

    Parameters
    ----------
    structure : Structure
        Statically determinate pin-jointed truss.
    kin : Kinematics
        Its kinematics along the motion (use ``kin.at_rest()`` for the static forces).
    bodies : MemberBodies, optional
        Mass elements (default :func:`member_bodies`).
    check : bool, optional
        Test every step's equilibrium matrix for singularity; by default only when the
        kinematics carry no factorisation (:func:`compute_kinematics` has tested the same
        matrices already).

    Returns
    -------
    NodalForces

    Raises
    ------
    AnalysisError
        A statically indeterminate truss (its forces need the FE model), a mechanism, or a
        singular configuration (naming the time step).
    """
    return _solve_forces(structure, [kin], bodies, check)[0]


def nodal_forces_with_static(structure: Structure, kin: Kinematics,
                             bodies: MemberBodies | None = None
                             ) -> tuple[NodalForces, NodalForces]:
    """Forces along the motion and at rest in the same positions, with one solve.

    Equal to ``nodal_forces(structure, kin)`` and ``nodal_forces(structure, kin.at_rest())``
    (the same arithmetic; the terms that vanish at rest are left out), but both right-hand
    sides of ``Bᵀ t = rhs`` go through the factorisation together.
    """
    return tuple(_solve_forces(structure, [kin, None], bodies, None))


def _check_model(structure: Structure) -> _Pattern:
    if np.any(structure.is_beam):
        raise AnalysisError(structure.source or structure.name, "the rigid-body model handles "
                            "pin-jointed bars only; member "
                            f"'{structure.member_ids[int(np.flatnonzero(structure.is_beam)[0])]}'"
                            " is a beam")
    pattern = _Pattern.of(structure)
    if pattern.m != pattern.nfree:
        raise AnalysisError(structure.source or structure.name, _count_message(pattern))
    return pattern


def member_resultants(kin: Kinematics, bodies: MemberBodies, gravity: np.ndarray,
                      conn: np.ndarray, rest: bool = False, *, bases: bool = True
                      ) -> tuple[np.ndarray | None, ...]:
    """Inertia-and-weight loads of every member's bodies (Lacy eqs. 2.9–2.11, 4.20).

    Parameters
    ----------
    gravity : ndarray, shape (3,)
    rest : bool
        The kinematics' rates and accelerations taken as zero (the terms that vanish are not
        computed: adding an exact zero changes no bit of the result).
    bases : bool
        Return ``f_base`` (False: None; the caller needs only ``R`` and ``Ma``).

    Returns
    -------
    f_tube, f_base : ndarray, shape (nt, m, 3)
        m_k (a_k − g) of the tube and of the base.
    R : ndarray, shape (nt, m, 3)
        f_tube + f_base, the force the nodes exert on the member in all.
    Ma : ndarray, shape (nt, m, 3)
        Σ [s_k e × m_k (a_k − g) + I_k α] about the start node, I_k about each body's centre.
    """
    g = gravity
    e = kin.unit
    mt = bodies.tube_mass[None, :, None]
    # Only active members have a base body: the others' base terms are exact zeros, which
    # change no bit of R and Ma, so they are computed for the members with a base only.
    act = np.flatnonzero(bodies.base_mass)
    mb = bodies.base_mass[None, act, None]
    cg = bodies.base_cg[None, act, None]
    if rest:
        s_t = kin.length[..., None] - bodies.tube_length[None, :, None] / 2.0
        f_tube = components_first(mt * -g)                      # a_tube = 0
        f_base = components_first(mb * -g)
    else:
        a_tube, s_t, a_base = element_accelerations(kin, bodies, conn, act)
        f_tube = a_tube                  # m_t (a_tube − g), in the accelerations' place
        f_tube -= g
        f_tube *= mt                                             # (time, member, 3)
        f_base = mb * (a_base - g)
    R = f_tube.copy(order="K")
    _add_to_members(R, act, f_base)
    Ma = cross(s_t * e, f_tube)
    _add_to_members(Ma, act, cross(cg * take(e, act, axis=1), f_base))
    if not rest:
        inertia = (bodies.tube_inertia(bodies.tube_length, bodies.tube_mass)
                   + bodies.base_inertia_cg)[None, :, None]
        Ma += inertia * kin.alpha
    if not bases:
        return f_tube, None, R, Ma
    full_base = np.zeros_like(R)
    full_base[:, act] = f_base
    return f_tube, full_base, R, Ma


def _add_to_members(a: np.ndarray, members: np.ndarray, b: np.ndarray) -> None:
    """``a[:, members] += b`` for distinct ``members``, through a gathered copy (numpy's
    fancy indexing with a leading slice is several times slower than ``np.take`` and a
    plain assignment on the (steps, members, 3) arrays of a motion)."""
    part = take(a, members, axis=1)
    part += b
    a[:, members] = part


def _member_loads(structure: Structure, kin: Kinematics, bodies: MemberBodies, rest: bool):
    """Member resultants and the right-hand side of ``Bᵀ t = rhs`` (Lacy eqs. 2.9–2.11).

    ``rest``: the kinematics' rates and accelerations are zero (the static case); the terms
    that vanish are not computed (adding an exact zero changes no bit of the result).
    """
    conn = structure.connectivity
    dim = structure.dim
    nt, m = kin.length.shape
    g = pad3(np.asarray(structure.gravity, dtype=float))
    e = kin.unit
    L = kin.length[..., None]
    _, _, R, Ma = member_resultants(kin, bodies, g, conn, rest, bases=False)
    Fb_perp = cross(Ma, e)
    Fb_perp /= L
    Re = dot(R, e)
    axial = Re[..., None] * e
    Fa_perp = np.subtract(R, axial, out=np.empty_like(axial))
    Fa_perp -= Fb_perp
    n = structure.n_nodes
    # Known (tension-free) parts of the end forces, summed at the nodes: the start ends'
    # Re e + Fa_perp (in place of the axial part, which is not needed again).
    axial += Fa_perp
    S = _to_nodes(_kept_sums(structure, False), axial, Fb_perp)
    P = pad3(structure.loads[:, :dim])[None]
    Mn = structure.masses[None, :, None]
    mg = Mn * g if rest else Mn * (g - kin.acceleration)      # lumped masses' loads
    rhs = (P + mg - S)[..., :dim].reshape(nt, n * dim)
    return Re, Fa_perp, Fb_perp, (P, mg), rhs


def pair_loads(structure: Structure, kin: Kinematics, bodies: MemberBodies,
               out: np.ndarray | None = None) -> tuple:
    """Member resultants of the motion and of rest, and their right-hand sides of
    ``Bᵀ t = rhs`` on the free coordinates, (nt, n_free, 2): the first half of
    :func:`nodal_forces_with_static`, so that the solve can be done for many blocks of steps
    at once (:func:`forces_from_tensions` finishes).  ``out``: an (nt, n_free, 2) array to
    write the right-hand sides into (a block's rows of the whole motion's)."""
    pattern = _check_model(structure)
    loads = [_member_loads(structure, kin, bodies, False),
             _member_loads(structure, kin, bodies, True)]
    if out is None:
        out = np.empty((kin.length.shape[0], pattern.free_flat.size, len(loads)))
    for j, ld in enumerate(loads):
        np.take(ld[4], pattern.free_flat, axis=1, out=out[..., j])
    return loads, out


def forces_from_tensions(structure: Structure, kin: Kinematics, bodies: MemberBodies,
                         loads: list, tension: np.ndarray) -> tuple[NodalForces, NodalForces]:
    """Dynamic and static :class:`NodalForces` from :func:`pair_loads` and the solved
    tensions (nt, n_loaded, 2)."""
    return tuple(_solve_forces(structure, [kin, None], bodies, False, loads, tension))


def _solve_forces(structure: Structure, kins: list, bodies: MemberBodies | None,
                  check: bool | None, loads: list | None = None,
                  tension: np.ndarray | None = None) -> list[NodalForces]:
    """Nodal forces for kinematics ``kins`` sharing one geometry; ``None`` in the list stands
    for the first one at rest.  The right-hand sides are solved together (or the member loads
    and their solved tensions are given)."""
    pattern = _check_model(structure)
    bodies = member_bodies(structure) if bodies is None else bodies
    kin = kins[0]
    if check is None:
        check = kin.compat is None
    dim = structure.dim
    e = kin.unit
    if loads is None:
        loads = [_member_loads(structure, kin, bodies, False) if k is not None
                 else _member_loads(structure, kin, bodies, True) for k in kins]
    rhs = (None if tension is not None else
           np.stack([ld[4][:, pattern.free_flat] for ld in loads], axis=2))   # (t, f, r)
    try:
        if tension is not None:
            tl = tension
        elif kin.compat is not None:
            # Bᵀ t = rhs with the factorisation kept from the kinematics.
            if kin.compat.direct:
                tl = kin.compat.solve(rhs, transpose=True)
            else:
                tl = np.stack([kin.compat.solve(rhs[..., j], transpose=True)
                               for j in range(rhs.shape[2])], axis=2)
        else:
            tl = batched_solve(pattern.cols, pattern.rows, pattern.values(e[..., :dim]),
                               (pattern.nfree, pattern.m), rhs, check=check)
    except SingularStep as s:
        raise AnalysisError(f"step {s.step} (t = {kin.time[s.step]:.6g} s)",
                            "the truss is at a singular position (its equilibrium matrix is "
                            "rank deficient): the member forces are not determined there"
                            ) from None
    n = structure.n_nodes
    # Reactions act on supported nodes only: the end forces are summed there alone.
    held = _supported(structure)
    out = []
    for j, (Re, Fa_perp, Fb_perp, ext, _) in enumerate(loads):
        t = 0.5 * Re                   # members between two fixed nodes: symmetric split
        t[:, pattern.loaded_cols] = tl[..., j]
        # F_a and F_b written into the (t, m, 2, 3) end forces, each component of each end
        # stored contiguously (trussfe.vectors)
        end_force = np.empty((3, 2) + t.shape).transpose(2, 3, 1, 0)
        Fa, Fb = end_force[:, :, 0], end_force[:, :, 1]
        np.multiply(t[..., None], e, out=Fb)
        Fb += Fb_perp
        np.multiply((Re - t)[..., None], e, out=Fa)
        Fa += Fa_perp
        tot = _to_nodes(_kept_sums(structure, True), Fa, Fb)
        P, mg = (np.broadcast_to(x, (x.shape[0], n, 3))[:, held] for x in ext)
        react = np.zeros(t.shape[:1] + (n, dim))
        react[:, held] = np.where(structure.translation_supports[None, held],
                                  (tot - P - mg)[..., :dim], 0.0)
        if not np.all(np.isfinite(react)):
            k = int(np.flatnonzero(~np.isfinite(react).all(axis=(1, 2)))[0])
            raise AnalysisError(f"step {k}", "non-finite forces (degenerate geometry)")
        out.append(NodalForces(end_force=end_force, tension_end=t,
                               tension_start=t - Re, reactions=react))
    return out


def composite_cg_inertia(bodies: MemberBodies, length: np.ndarray
                         ) -> tuple[np.ndarray, np.ndarray]:
    """Moving centre of gravity and varying inertia of every member (Lacy eqs. 4.58–4.61).

    Parameters
    ----------
    bodies : MemberBodies
    length : ndarray, shape (nt, m)
        Member lengths along the motion.

    Returns
    -------
    cg : ndarray, shape (nt, m)
        Distance of the member's centre of gravity from its start node, m.
    inertia : ndarray, shape (nt, m)
        Transverse moment of inertia about that centre of gravity, kg·m².

    Notes
    -----
    For an active member (Appendix C, ``cg7``, ``i7b1``)

    .. math:: cg = \\frac{m_t (L - l_t/2) + m_b\\, cg_b}{m_t + m_b}, \\quad
              I = I_t + I_b + m_t (L - l_t/2 - cg)^2 + m_b (cg - cg_b)^2 .

    The force model itself keeps the tube and base as separate bodies, which is equivalent.
    """
    L = np.asarray(length, dtype=float)
    mt, mb = bodies.tube_mass, bodies.base_mass
    st = L - bodies.tube_length / 2.0
    cg = (mt * st + mb * bodies.base_cg) / (mt + mb)
    inertia = (bodies.tube_inertia(bodies.tube_length, mt) + bodies.base_inertia_cg
               + mt * (st - cg) ** 2 + mb * (cg - bodies.base_cg) ** 2)
    return cg, inertia
