# SPDX-License-Identifier: MIT
"""Lacy's double-octahedral variable-geometry truss bay and chains of it (ch. 4–6).

Numbering (Table 4.1, Fig. 4.1, Appendix D, whose ``Connect`` list is in member order)::

    top plane      N7 ── N9 ── N8        M19 = N7–N9, M20 = N8–N7, M21 = N8–N9
    mid plane      N4, N5, N6            M7/8 = N4–N5, M9/10 = N5–N6, M11/12 = N4–N6 (active)
    base plane     N1, N2, N3 (pinned)

    M1 N6–N2   M2 N6–N1   M3 N4–N1   M4 N4–N3   M5 N5–N3   M6 N5–N2      (base → mid)
    M13 N6–N9  M14 N6–N7  M15 N4–N7  M16 N4–N8  M17 N5–N8  M18 N5–N9      (mid → top)

The active members are numbered in pairs in the thesis (active base and leadscrew tube);
here each is one member with the id ``M7_8``, ``M9_10``, ``M11_12``.

Geometry, established by recomputing Appendix D: the base is an equilateral triangle of side
1.2192 m centred on the origin in the plane z = 0; the twelve cross longerons (base→mid and
mid→top) are 0.889 m (Appendix D's coordinates imply it; Table 5.1 and the FWD1 code say
0.9144 m, which does not reproduce the printed coordinates); each midplane node hinges about
its base edge (N6 about N1–N2, N4 about N1–N3, N5 about N2–N3); the top plane is the mirror
image of the base in the midplane; the equilibrium active length is 1.1684 m.  Every position
is found from the three active lengths by the general forward-position solver, started from
the equilibrium geometry.
"""
from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..errors import AnalysisError, InputError
from ..kinematics.assembly import solve_positions
from ..model.geometry import lengths as member_length_of
from ..model.structure import Structure
from ..model.active import ActiveMember
from .materials import ALUMINIUM, octahedral_tube

#: Member id → (start node, end node), thesis numbering (Table 4.1 / Appendix D order).
DOUBLE_OCTAHEDRON_MEMBERS: dict[str, tuple[int, int]] = {
    "M1": (6, 2), "M2": (6, 1), "M3": (4, 1), "M4": (4, 3), "M5": (5, 3), "M6": (5, 2),
    "M7_8": (4, 5), "M9_10": (5, 6), "M11_12": (4, 6),
    "M13": (6, 9), "M14": (6, 7), "M15": (4, 7), "M16": (4, 8), "M17": (5, 8), "M18": (5, 9),
    "M19": (7, 9), "M20": (8, 7), "M21": (8, 9),
}
#: Ids of the active (variable-length) members, in the order of ``active_lengths``.
ACTIVE_MEMBERS = ("M7_8", "M9_10", "M11_12")

BASE_SIDE = 1.2192          # m, fixed triangle side (Appendix D: 2 × 0.6096)
LONGERON = 0.889            # m, cross longeron implied by Appendix D's coordinates
EQUILIBRIUM_LENGTH = 1.1684  # m, Lacy section 5.1
SLEW_LONG = 1.2289          # m, active member at its maximum (section 5.1)
SLEW_SHORT_PRINTED = 1.1077  # m, minimum as printed in section 5.1
#: Minimum that reproduces Tables 5.3/5.4 to ~1e-4 (1.1077 gives errors up to 1.1e-3).
SLEW_SHORT = 1.1079
#: Stroke of the prototype's active members: ±0.0606 m about the equilibrium length (Lacy
#: section 5.5), 1.1078–1.2290 m; both slewed positions of section 5.1 lie inside it (the
#: printed 1.1077 m lies 0.1 mm short of it).
STROKE_HALF = 0.0606
STROKE = (EQUILIBRIUM_LENGTH - STROKE_HALF, EQUILIBRIUM_LENGTH + STROKE_HALF)
#: Load per top node that reproduces Tables 5.2–5.4 (their N1 reaction is −44.4980 N at the
#: symmetric position, where each base node carries one node load; ≈ 4.536 kg × 9.81).
#: The text and the Appendix D load file state 46.0 N, which gives every value 3.4 % high.
TABLE_LOAD = 44.498
STATED_LOAD = 46.0
#: Active members of Appendix C: base of 3 kg and 0.7 m, CG at 0.35 m from its pivot, inertia
#: m·l²/3 about it; leadscrew tube 0.254 m.
ACTIVE_BASE_MASS = 3.0
ACTIVE_BASE_LENGTH = 0.7
ACTIVE_TUBE_LENGTH = 0.254

# Appendix D "Nodal Point Locations" (4 decimals): the starting guess of the solver.
_APPENDIX_D = np.array([
    [-0.6096, -0.3519, 0.0], [0.6096, -0.3519, 0.0], [-0.0000, 0.7039, 0.0],
    [-0.5842, 0.3373, 0.5609], [0.5842, 0.3373, 0.5609], [0.0, -0.6746, 0.5609],
    [-0.6096, -0.3519, 1.1218], [0.0, 0.7039, 1.1218], [0.6096, -0.3519, 1.1218]])
_CONN = np.array(list(DOUBLE_OCTAHEDRON_MEMBERS.values()), dtype=np.int64) - 1   # (18, 2)
_MEMBER_IDS = list(DOUBLE_OCTAHEDRON_MEMBERS)
_ACTIVE_IDX = np.array([_MEMBER_IDS.index(a) for a in ACTIVE_MEMBERS])
_TOP_PLANE_IDX = np.array([_MEMBER_IDS.index(a) for a in ("M19", "M20", "M21")])
_NODE_IDS = [f"N{i}" for i in range(1, 10)]
_OWN_NODES = _NODE_IDS[3:]


def slew_lengths(position: str, short: float = SLEW_SHORT,
                 long: float = SLEW_LONG) -> tuple[float, float, float]:
    """Active lengths (M7/8, M9/10, M11/12) of a named position (Lacy section 5.1).

    Parameters
    ----------
    position : {"equilibrium", "slew1", "slew2"}
        ``slew1``: M7/8 at its maximum and the others at their minimum (the first slewed
        position as defined in section 5.1; the numbers printed in Table 5.3 belong to
        ``slew2``, see :mod:`trussfe.models`).  ``slew2``: M7/8 at its minimum.
    short, long : float
        Minimum and maximum active length, m.  ``short`` defaults to the 1.1079 m that
        reproduces the tables; pass :data:`SLEW_SHORT_PRINTED` for the printed 1.1077 m.

    Examples
    --------
    >>> slew_lengths("slew1")
    (1.2289, 1.1079, 1.1079)
    """
    if position == "equilibrium":
        return (EQUILIBRIUM_LENGTH,) * 3
    if position == "slew1":
        return (long, short, short)
    if position == "slew2":
        return (short, long, long)
    raise InputError("position", f"unknown position {position!r}; valid: equilibrium, slew1, "
                                 "slew2")


def _bay_lengths(active: np.ndarray, base_side: float, longeron: float) -> np.ndarray:
    """Member lengths of one bay in thesis order, shape (18,)."""
    lengths = np.full(len(_MEMBER_IDS), float(longeron))
    lengths[_ACTIVE_IDX] = active
    lengths[_TOP_PLANE_IDX] = base_side
    return lengths


def _check_lengths(active: np.ndarray, item: str) -> None:
    if not np.all(np.isfinite(active)) or np.any(active <= 0):
        raise InputError(item, f"active lengths must be positive and finite, got "
                               f"{np.asarray(active).tolist()}")


def _equilibrium_coords(base_side: float, longeron: float, length: float) -> np.ndarray:
    """Symmetric bay geometry from the Appendix D guess by the forward-position solver."""
    guess = _APPENDIX_D * (base_side / BASE_SIDE)
    fixed = np.zeros((9, 3), dtype=bool)
    fixed[:3] = True
    # The base of the guess is scaled exactly: side base_side, centroid at the origin.
    h = base_side / (2.0 * np.sqrt(3.0))
    guess[:3] = [[-base_side / 2, -h, 0.0], [base_side / 2, -h, 0.0], [0.0, 2 * h, 0.0]]
    return solve_positions(guess, _CONN, _bay_lengths(np.full(3, length), base_side, longeron),
                           fixed, member_ids=_MEMBER_IDS, item="double_octahedron",
                             tolerance=1e-14).coords


def double_octahedron(active_lengths: Sequence[float] = (EQUILIBRIUM_LENGTH,) * 3,
                      top_load: float = STATED_LOAD, *, base_side: float = BASE_SIDE,
                      longeron: float = LONGERON, inner_diameter: float | None = None,
                      gravity: Sequence[float] | None = None, top_mass: float = 0.0,
                      name: str | None = None, active_members: bool = False) -> Structure:
    """One double-octahedral bay at the position given by its three active lengths.

    Parameters
    ----------
    active_lengths : (3,) floats
        Lengths of M7/8 (N4–N5), M9/10 (N5–N6), M11/12 (N4–N6), m.
        :func:`slew_lengths` gives the thesis positions.
    top_load : float
        Force in +z on each top node N7, N8, N9, N (Appendix D load file: ``fz 46 7 8 9``).
        :data:`TABLE_LOAD` = 44.498 N reproduces Tables 5.2–5.4.
    base_side, longeron : float
        Fixed-triangle side and cross-longeron length, m (defaults from Appendix D).
    inner_diameter : float, optional
        Tube inner diameter, m; default 0.62 in (Appendix D area 9.0245e-5 m²).
    gravity : (3,) floats, optional
        Gravitational acceleration; default none (the static checks of section 5.1).
    top_mass : float
        Lumped mass at each top node, kg.
    name : str, optional
        Model name.
    active_members : bool
        If True, ``extensions["active_members"]`` holds M7/8, M9/10, M11/12's data
        (:func:`active_member`, base at each member's start node), as the rigid-body model
        reads them; the FE models do not use them.

    Returns
    -------
    Structure
        3-D, nodes ``N1``..``N9``, members as :data:`DOUBLE_OCTAHEDRON_MEMBERS`, base nodes
        pinned in x, y, z.

    Raises
    ------
    InputError
        Non-positive lengths.
    AnalysisError
        When no assembly with these lengths exists near the equilibrium geometry.

    Examples
    --------
    >>> s = double_octahedron()
    >>> np.round(s.coords[s.node_index("N6")], 4) + 0.0     # Appendix D node 6
    array([ 0.    , -0.6746,  0.5609])
    >>> round(float(s.lengths()[s.member_index("M6")]), 6)
    0.889
    """
    active = np.asarray(active_lengths, dtype=float).ravel()
    if active.shape != (3,):
        raise InputError("double_octahedron.active_lengths", f"expected 3 lengths (M7/8, "
                                                             f"M9/10, M11/12), got {active_lengths!r}")
    _check_lengths(active, "double_octahedron.active_lengths")
    if base_side <= 0 or longeron <= 0:
        raise InputError("double_octahedron", "base_side and longeron must be positive")
    x0 = _equilibrium_coords(base_side, longeron, float(np.mean(active)))
    fixed = np.zeros((9, 3), dtype=bool)
    fixed[:3] = True
    coords = solve_positions(x0, _CONN, _bay_lengths(active, base_side, longeron), fixed,
                             member_ids=_MEMBER_IDS, item="double_octahedron",
                             tolerance=1e-14).coords
    section = octahedral_tube() if inner_diameter is None else octahedral_tube(inner_diameter)
    m = len(_MEMBER_IDS)
    supports = np.zeros((9, 6), dtype=bool)
    supports[:3, :3] = True
    loads = np.zeros((9, 6))
    loads[6:, 2] = top_load
    masses = np.zeros(9)
    masses[6:] = top_mass
    if name is None:
        name = ("double-octahedral VGT bay, active lengths "
                + " / ".join(f"{v:g}" for v in active) + " m")
    ext = {"active_members": [active_member(i) for i in _ACTIVE_IDX]} if active_members else {}
    return Structure(
        name=name, dim=3, node_ids=list(_NODE_IDS), coords=coords,
        member_ids=list(_MEMBER_IDS), connectivity=_CONN.copy(), sections=[section] * m,
        materials=[ALUMINIUM] * m, is_beam=np.zeros(m, bool), releases=np.zeros((m, 2), bool),
        supports=supports, loads=loads, masses=masses,
        gravity=np.zeros(3) if gravity is None else np.asarray(gravity, float).reshape(3),
        extensions=ext)


def active_member(member: int) -> ActiveMember:
    """One active member of the bay (Appendix C) as member ``member``: base at its start node.

    Examples
    --------
    >>> a = active_member(6)
    >>> a.base_mass, a.base_cg, a.tube_length
    (3.0, 0.35, 0.254)
    """
    return ActiveMember(member=int(member), base_mass=ACTIVE_BASE_MASS,
                        base_length=ACTIVE_BASE_LENGTH, base_cg=ACTIVE_BASE_LENGTH / 2,
                        base_inertia=ACTIVE_BASE_MASS * ACTIVE_BASE_LENGTH ** 2 / 3,
                        tube_length=ACTIVE_TUBE_LENGTH)


def _bays_local(act: np.ndarray, bay0: np.ndarray, base_side: float,
                longeron: float, tolerance: float = 1e-14,
                max_iterations: int = 50) -> np.ndarray:
    """Geometry of each bay on the fixed reference base, from its active lengths.

    Newton's method on the 18 bar-length equations of every bay at once (batched dense
    18 × 18 solves; the Jacobian is the bay's compatibility matrix, as in
    :func:`~trussfe.kinematics.solve_positions`), started from the equilibrium bay.

    Returns
    -------
    ndarray, shape (bays, 9, 3)
    """
    nb = act.shape[0]
    lengths = np.tile(_bay_lengths(np.zeros(3), base_side, longeron), (nb, 1))
    lengths[:, _ACTIVE_IDX] = act
    x = np.broadcast_to(bay0, (nb, 9, 3)).copy()                    # (bay, node, xyz)
    a, b = _CONN[:, 0], _CONN[:, 1]
    rows = np.arange(18)
    scale = float(lengths.max())
    for _ in range(max_iterations):
        vec = x[:, b] - x[:, a]                                     # (bay, member, xyz)
        cur = member_length_of(vec)
        r = cur - lengths
        bad = np.max(np.abs(r), axis=1) > tolerance * scale
        if not bad.any():
            return x
        unit = vec[bad] / cur[bad][:, :, None]
        jac = np.zeros((int(bad.sum()), 18, 9, 3))                  # (bay, member, node, xyz)
        jac[:, rows, b] += unit
        jac[:, rows, a] -= unit
        jac = jac[:, :, 3:, :].reshape(-1, 18, 18)                  # free nodes N4..N9
        try:
            dx = np.linalg.solve(jac, -r[bad][:, :, None])[:, :, 0]
        except np.linalg.LinAlgError:
            raise AnalysisError("double_octahedral_chain", "a bay is at a singular position "
                                "for these active lengths") from None
        step = np.max(np.abs(dx), axis=1, keepdims=True)
        dx *= np.minimum(1.0, 0.1 * scale / np.maximum(step, 1e-300))
        x[np.flatnonzero(bad), 3:, :] += dx.reshape(-1, 6, 3)
    worst = int(np.argmax(np.max(np.abs(member_length_of(x[:, b] - x[:, a]) - lengths),
                                 axis=1)))
    raise AnalysisError("double_octahedral_chain", f"no assembly exists for the active "
                                                   f"lengths of bay {worst + 1}: "
                                                   f"{act[worst].tolist()}")


def _frame(p: np.ndarray) -> np.ndarray:
    """Orthonormal frames of triangles p (…, 3 points, xyz) as columns (…, xyz, 3)."""
    e1 = p[..., 1, :] - p[..., 0, :]
    e1 /= np.linalg.norm(e1, axis=-1, keepdims=True)
    e3 = np.cross(e1, p[..., 2, :] - p[..., 0, :])
    e3 /= np.linalg.norm(e3, axis=-1, keepdims=True)
    return np.stack([e1, np.cross(e3, e1), e3], axis=-1)


def _stack_bays(local: np.ndarray) -> np.ndarray:
    """Global node coordinates of a chain from each bay's geometry on the reference base.

    Bay k+1 sits on bay k's top triangle (N7, N9, N8 over N1, N2, N3): the rigid motion
    taking the reference base to bay k's top (rotation R_k, translation t_k) is composed up
    the chain, G_{k+1} = G_k ∘ T_k (Lacy ch. 6: each bay's kinematics in the frame of the
    bay below).
    """
    nb = local.shape[0]
    base = local[0, :3]
    top = local[:, [6, 8, 7]]                                       # (bay, 3, xyz)
    rot = _frame(top) @ _frame(base).T                              # (bay, 3, 3)
    trans = top[:, 0] - rot @ base[0]                               # (bay, 3)
    # Compose G_k = G_{k-1} ∘ T_{k-1}: one 3 × 3 product per bay (not per member).
    A = np.empty((nb, 3, 3))
    c = np.empty((nb, 3))
    A[0], c[0] = np.eye(3), 0.0
    for k in range(1, nb):
        A[k] = A[k - 1] @ rot[k - 1]
        c[k] = A[k - 1] @ trans[k - 1] + c[k - 1]
    own = np.einsum("kij,knj->kni", A, local[:, 3:]) + c[:, None, :]    # (bay, 6, xyz)
    return np.vstack([base, own.reshape(-1, 3)])


def double_octahedral_chain(n_bays: int, active_lengths: np.ndarray | None = None,
                            tip_load: float = STATED_LOAD, *, base_side: float = BASE_SIDE,
                            longeron: float = LONGERON, inner_diameter: float | None = None,
                            gravity: Sequence[float] | None = None,
                            name: str | None = None, active_members: bool = False
                            ) -> Structure:
    """``n_bays`` double-octahedral bays stacked, each bay's top plane the next one's base
    (Lacy ch. 6).

    Parameters
    ----------
    n_bays : int
        Number of bays (≥ 1).  Built with array operations only, so 10⁵ bays take well under a
        second.
    active_lengths : array, shape (n_bays, 3), optional
        Active lengths (M7/8, M9/10, M11/12) of every bay; default all at 1.1684 m.  Each bay
        is assembled on the reference base by Newton's method on its bar lengths (all bays at
        once), and the bays are stacked by composing the rigid motions base → top up the chain.
    tip_load : float
        Force in +z on each top node of the last bay, N.
    base_side, longeron, inner_diameter, gravity, name, active_members
        As :func:`double_octahedron` (every bay's M7/8, M9/10, M11/12 are active).

    Returns
    -------
    Structure
        Nodes ``b1.N1``..``b1.N3`` (the pinned base), then per bay k ``bk.N4``..``bk.N9``; bay
        k+1's N1, N2, N3 are bay k's N7, N9, N8 (the node directly above).  Members
        ``bk.M1``..``bk.M21`` (18 per bay; the top plane of bay k is the base plane of bay k+1).

    Examples
    --------
    >>> s = double_octahedral_chain(2)
    >>> s.n_nodes, s.n_members, s.node_ids[-1], s.member_ids[-1]
    (15, 36, 'b2.N9', 'b2.M21')
    """
    if isinstance(n_bays, bool) or not isinstance(n_bays, (int, np.integer)) or n_bays < 1:
        raise InputError("double_octahedral_chain.n_bays", f"must be a positive integer, got "
                                                           f"{n_bays!r}")
    n_bays = int(n_bays)
    bay = _equilibrium_coords(base_side, longeron, EQUILIBRIUM_LENGTH)
    height = float(bay[6, 2])                      # top plane height of one bay
    # Global index of each bay's nodes N1..N9, shape (bay, 9).
    k = np.arange(n_bays)
    own = 3 + 6 * k[:, None] + np.arange(6)[None, :]          # N4..N9 of bay k
    base = np.empty((n_bays, 3), dtype=np.int64)
    base[0] = (0, 1, 2)
    # bay k's N1, N2, N3 sit on bay k-1's N7, N9, N8 (the nodes above them)
    base[1:] = own[:-1][:, [3, 5, 4]]
    nodes = np.hstack([base, own])                              # (bay, 9)
    conn = nodes[:, _CONN].reshape(-1, 2)                       # (bay*18, 2)
    n = 3 + 6 * n_bays
    coords = np.empty((n, 3))
    coords[:3] = bay[:3]
    shift = np.zeros((n_bays, 1, 3))
    shift[:, 0, 2] = height * k
    coords[3:] = (bay[None, 3:, :] + shift).reshape(-1, 3)
    if active_lengths is not None:
        act = np.asarray(active_lengths, dtype=float)
        if act.shape != (n_bays, 3):
            raise InputError("double_octahedral_chain.active_lengths",
                             f"expected shape ({n_bays}, 3), got {act.shape}")
        _check_lengths(act, "double_octahedral_chain.active_lengths")
        coords = _stack_bays(_bays_local(act, bay, base_side, longeron))
    # Ids: one prefix string per bay, concatenated (twice as fast as formatting each id).
    prefixes = [f"b{i}." for i in range(1, n_bays + 1)]
    node_ids = ["b1.N1", "b1.N2", "b1.N3"] + [p + j for p in prefixes for j in _OWN_NODES]
    member_ids = [p + mid for p in prefixes for mid in _MEMBER_IDS]
    m = conn.shape[0]
    section = octahedral_tube() if inner_diameter is None else octahedral_tube(inner_diameter)
    supports = np.zeros((n, 6), dtype=bool)
    supports[:3, :3] = True
    loads = np.zeros((n, 6))
    loads[n - 3:, 2] = tip_load
    if name is None:
        name = f"chain of {n_bays} double-octahedral bays"
    ext = {}
    if active_members:
        idx = (18 * k[:, None] + _ACTIVE_IDX[None, :]).ravel()
        ext["active_members"] = [active_member(i) for i in idx]
    return Structure(
        name=name, dim=3, node_ids=node_ids, coords=coords, member_ids=member_ids,
        connectivity=conn, sections=[section] * m, materials=[ALUMINIUM] * m,
        is_beam=np.zeros(m, bool), releases=np.zeros((m, 2), bool), supports=supports,
        loads=loads, masses=np.zeros(n),
        gravity=np.zeros(3) if gravity is None else np.asarray(gravity, float).reshape(3),
        extensions=ext, member_groups=np.zeros(m, dtype=np.int64))   # one tube, one material
