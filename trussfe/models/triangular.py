# SPDX-License-Identifier: MIT
"""Lacy's planar triangular truss (ch. 2–3, Table 3.1, Appendix B).

Geometry (Fig. 2.1, Appendix B)::

            B  (lumped mass, load)
           / \\
   active /   \\ follower (L1 = 2.0 m)
         /     \\
       O2 ----- O1         ground L4 = 2.0 m (not a member: both pivots are pinned)

* ``O2`` = (0, 0): pivot of the active member (motor end, active base);
* ``O1`` = (2, 0): pivot of the follower;
* ``B``: apex where the follower meets the leadscrew tube and the lumped mass hangs.

The active member (active base + leadscrew tube) has length L3min + x + L2 = 0.5 + x + 2.0 m
between O2 and B.  Member ``follower`` is the thesis' member 1 and ``active`` its member 2
(Table 3.2: tensions −78.5429 N and −27.4900 N under 98.1 N at B).
"""
from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..errors import InputError
from ..kinematics.assembly import solve_positions
from ..model.structure import Structure, build_structure
from ..model.active import ActiveMember
from .materials import ALUMINIUM, triangular_tube

#: Table 3.1 dimensions, m.
FOLLOWER_LENGTH = 2.0      # L1
LEADSCREW_LENGTH = 2.0     # L2
ACTIVE_MIN_LENGTH = 0.5    # L3min
GROUND_LENGTH = 2.0        # L4
ACTIVE_MAX_LENGTH = 2.1    # L3max, the active base's overall length
GRAVITY = 9.81             # m/s², the value of Appendix A
#: Active base of Appendix A: 2.4 kg (``m3``), CG at mid-length, inertia about O2
#: ``io2 = m3·l3max²/3``.
ACTIVE_BASE_MASS = 2.4


def active_member(member: int) -> ActiveMember:
    """The triangular truss' active member (Table 3.1, Appendix A) as member ``member``.

    Base of 2.4 kg and 2.1 m pinned at O2 (the member's start node), centre of gravity at
    1.05 m, inertia m·l²/3 about O2; leadscrew tube of 2.0 m pinned at B; stroke 2.5–4.1 m.
    """
    return ActiveMember(
        member=member, base_mass=ACTIVE_BASE_MASS, base_length=ACTIVE_MAX_LENGTH,
        base_cg=ACTIVE_MAX_LENGTH / 2, base_inertia=ACTIVE_BASE_MASS * ACTIVE_MAX_LENGTH ** 2 / 3,
        tube_length=LEADSCREW_LENGTH, min_length=ACTIVE_MIN_LENGTH + LEADSCREW_LENGTH,
        max_length=ACTIVE_MAX_LENGTH + LEADSCREW_LENGTH)


def triangular_truss(x: float = 0.0, lumped_mass: float = 10.0, member_weight: bool = False,
                     load: Sequence[float] | None = None, *,
                     split_active: bool = False, active_members: bool = False) -> Structure:
    """Lacy's triangular truss with the active member extended by ``x``.

    Parameters
    ----------
    x : float
        Extension of the active member beyond L3min, m (Table 3.1: 0 → 1.2 m in the Base
        Simulation).  Node B is found from the bar lengths by the general forward-position
        solver (:func:`~trussfe.kinematics.solve_positions`), not a closed form.
    lumped_mass : float
        Mass at B, kg (Table 3.1: 10 kg).
    member_weight : bool
        If True, gravity (0, −9.81) m/s² acts on the members and the lumped mass (the static
        case with member weight in the text after Table 3.2); if False there is no gravity.
    load : (Fx, Fy), optional
        External force at B, N.  Table 3.2 applies (0, −98.1) N, the weight of the 10 kg
        lumped mass, with no gravity.
    split_active : bool
        If True the active member is two beams, ``active_base`` O2–C and ``leadscrew_tube``
        C–B, rigidly joined at the cantilever connection C (0.5 + x from O2) and pinned at O2
        and B — the Appendix B MSC/PAL model (its node 2).  If False (default) it is one bar.
    active_members : bool
        If True (one-bar model only), ``extensions["active_members"]`` holds the active
        member's data (:func:`active_member`: base at O2, tube at B), as the rigid-body model
        reads them; the static FE model does not use them.

    Returns
    -------
    Structure
        2-D; nodes ``O2`` (, ``C``), ``B``, ``O1`` (Appendix B order); members ``follower``,
        ``active`` (or ``active_base``, ``leadscrew_tube``); O2 and O1 pinned in x and y.

    Raises
    ------
    InputError
        For a negative extension or mass.
    AnalysisError
        If the follower and active member cannot meet (x too large).

    Examples
    --------
    >>> s = triangular_truss()
    >>> s.node_ids, s.member_ids
    (('O2', 'B', 'O1'), ('follower', 'active'))
    >>> np.round(s.coords[1], 4)    # Appendix B, node 3
    array([1.5625, 1.9516])
    """
    if not np.isfinite(x) or x < 0:
        raise InputError("triangular_truss.x", f"extension must be ≥ 0, got {x!r}")
    if not np.isfinite(lumped_mass) or lumped_mass < 0:
        raise InputError("triangular_truss.lumped_mass", f"must be ≥ 0, got {lumped_mass!r}")
    active = ACTIVE_MIN_LENGTH + x + LEADSCREW_LENGTH
    # O2, B, O1 with a guess for B above the ground link; B from the two bar lengths.
    guess = np.array([[0.0, 0.0], [0.75 * GROUND_LENGTH, GROUND_LENGTH], [GROUND_LENGTH, 0.0]])
    conn = np.array([[1, 2], [0, 1]])
    fixed = np.array([[True, True], [False, False], [True, True]])
    pos = solve_positions(guess, conn, np.array([FOLLOWER_LENGTH, active]), fixed,
                          member_ids=["follower", "active"], item="triangular_truss",
                          tolerance=1e-14).coords
    f_b = np.zeros(2) if load is None else np.asarray(load, dtype=float).ravel()
    if f_b.shape != (2,) or not np.all(np.isfinite(f_b)):
        raise InputError("triangular_truss.load", f"expected a finite force (Fx, Fy), got "
                                                  f"{load!r}")
    gravity = [0.0, -GRAVITY] if member_weight else None
    if not split_active:
        s = build_structure(
            pos, conn, section=triangular_tube(), material=ALUMINIUM,
            supports={0: "xy", 2: "xy"}, loads={1: f_b}, masses={1: lumped_mass},
            gravity=gravity, name=f"Lacy triangular truss, x = {x:g} m",
            node_ids=["O2", "B", "O1"], member_ids=["follower", "active"])
        return s.with_extensions(active_members=[active_member(1)]) if active_members else s
    if active_members:
        raise InputError("triangular_truss.active_members", "the active member's data belong "
                         "to the one-bar model (split_active=False)")
    unit = pos[1] / np.linalg.norm(pos[1])
    c = unit * (ACTIVE_MIN_LENGTH + x)
    coords = np.vstack([pos[0], c, pos[1], pos[2]])
    s = build_structure(
        coords, [[2, 3], [0, 1], [1, 2]], section=triangular_tube(), material=ALUMINIUM,
        supports={0: "xy", 3: "xy"}, loads={2: f_b}, masses={2: lumped_mass},
        gravity=gravity, is_beam=[False, True, True],
        name=f"Lacy triangular truss, x = {x:g} m (active member as two beams)",
        node_ids=["O2", "C", "B", "O1"],
        member_ids=["follower", "active_base", "leadscrew_tube"])
    # Pinned at O2 and B, rigid at the cantilever connection C.
    return s.with_member_data(releases={1: (True, False), 2: (False, True)})
