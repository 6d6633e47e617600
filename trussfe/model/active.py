# SPDX-License-Identifier: MIT
"""Active (variable-length) members: the data of the ``[active_members]`` table of a model file.

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
"""
from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class ActiveMember:
    """Data of one active member (see the module docstring for the model).

    Attributes
    ----------
    member : int
        Index of the member in the structure.
    base_mass, base_cg, base_inertia : float
        Active base mass (kg), centre of gravity from the start node (m) and moment of inertia
        about the start node (kg·m²).
    base_length : float
        Overall base length, m (used for the default inertia).
    tube_length : float
        Leadscrew tube length, m; the tube's section and material are the member's.
    min_length, max_length : float
        Stroke limits of the whole member, m (``nan`` if not given).
    """

    member: int
    base_mass: float
    base_length: float
    base_cg: float
    base_inertia: float
    tube_length: float
    min_length: float = math.nan
    max_length: float = math.nan

    @property
    def base_inertia_cg(self) -> float:
        """Moment of inertia of the base about its own centre of gravity, kg·m²."""
        return self.base_inertia - self.base_mass * self.base_cg ** 2
