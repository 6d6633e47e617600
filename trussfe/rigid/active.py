# SPDX-License-Identifier: MIT
"""Active (variable-length) members: the ``[active_members]`` table of a model file.

An active member (Lacy section 2.1, 4.7) is a straight, variable-length member made of

* an **active base** pinned at the member's start node: motor, gearhead, leadscrew and supports
  lumped into one rigid body of mass ``base_mass`` whose centre of gravity sits at
  ``base_cg`` from the start node and whose moment of inertia about the start node is
  ``base_inertia`` (default ``base_mass * base_length**2 / 3``, Lacy Appendix A ``io2``);
* a **leadscrew tube** of length ``tube_length`` pinned at the member's end node; its other end
  is a cantilever connection sliding along the base (Lacy eqs. 4.58–4.61: its centre of gravity
  moves with the member length).

The member's length in ``[nodes]`` is its length at rest (the first instant of a motion).

Example (the triangular truss of Lacy Table 3.1)::

    [active_members.active]
    base_mass = 2.4          # kg
    base_length = 2.1        # m, overall actuator length l3max
    base_cg = 1.05           # m from the start node
    tube_length = 2.0        # m
    min_length = 2.5         # m, optional stroke limits
    max_length = 3.7

The data live in :mod:`trussfe.model.active` and are read by
:mod:`trussfe.io.extension_tables`; this module gives the analyses their view of them.
"""
from __future__ import annotations

import numpy as np

from ..model.active import ActiveMember
from ..model.structure import Structure

__all__ = ["ActiveMember", "active_indices", "active_members"]


def active_members(structure: Structure) -> list[ActiveMember]:
    """The structure's active members (empty list when it has none)."""
    return list(structure.extensions.get("active_members", []))


def active_indices(structure: Structure) -> np.ndarray:
    """Member indices of the active members, shape (n_active,)."""
    return np.array([a.member for a in active_members(structure)], dtype=np.int64)
