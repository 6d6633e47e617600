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
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError
from ..io.model_file import register_table
from ..model.structure import Structure

_KEYS = ("base_mass", "base_length", "base_cg", "base_inertia", "tube_length",
         "min_length", "max_length")


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


def _num(raw: dict, key: str, item: str, *, positive=False, nonneg=False, default=None) -> float:
    if key not in raw:
        if default is None:
            raise InputError(f"{item}.{key}", "is required")
        return default
    v = raw[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(float(v)):
        raise InputError(f"{item}.{key}", f"expected a finite number, got {v!r}")
    v = float(v)
    if positive and v <= 0:
        raise InputError(f"{item}.{key}", f"must be positive, got {v!r}")
    if nonneg and v < 0:
        raise InputError(f"{item}.{key}", f"must not be negative, got {v!r}")
    return v


def parse_active_members(raw: Any, structure: Structure, base_dir: Path) -> list[ActiveMember]:
    """Read the ``[active_members]`` table (registered with the model-file reader).

    Raises
    ------
    InputError
        For an unknown member id, a missing or non-positive quantity, a tube longer than the
        member, or a member that is not a pin-jointed bar.
    """
    if not isinstance(raw, dict) or not raw:
        raise InputError("[active_members]", "expected one table per active member, "
                         "e.g. [active_members.M7_8]")
    out = []
    for mid, t in raw.items():
        item = f"active_members.{mid}"
        try:
            k = structure.member_index(str(mid))
        except KeyError:
            raise InputError(item, f"'{mid}' is not a member of the model; the table key must "
                             "be a member id from [members]") from None
        if not isinstance(t, dict):
            raise InputError(item, "expected a table")
        for key in t:
            if key not in _KEYS:
                raise InputError(f"{item}.{key}", f"unknown key; valid: {', '.join(_KEYS)}")
        if structure.is_beam[k]:
            raise InputError(item, "an active member must be a pin-jointed bar (type = \"bar\")")
        mb = _num(t, "base_mass", item, nonneg=True)
        lb = _num(t, "base_length", item, positive=True)
        cg = _num(t, "base_cg", item, nonneg=True, default=lb / 2.0)
        ib = _num(t, "base_inertia", item, nonneg=True, default=mb * lb * lb / 3.0)
        if ib < mb * cg * cg * (1 - 1e-12):
            raise InputError(f"{item}.base_inertia", f"{ib} kg·m² is less than base_mass·"
                             f"base_cg² = {mb * cg * cg} kg·m²; give it about the start node")
        lt = _num(t, "tube_length", item, positive=True)
        L0 = float(structure.lengths()[k])
        if lt > L0 * (1 + 1e-12):
            raise InputError(f"{item}.tube_length", f"{lt} m is longer than the member "
                             f"({L0:.6g} m at rest)")
        lo = _num(t, "min_length", item, positive=True, default=math.nan)
        hi = _num(t, "max_length", item, positive=True, default=math.nan)
        out.append(ActiveMember(member=k, base_mass=mb, base_length=lb, base_cg=cg,
                                base_inertia=ib, tube_length=lt, min_length=lo, max_length=hi))
    return out


register_table("active_members", parse_active_members)


def active_members(structure: Structure) -> list[ActiveMember]:
    """The structure's active members (empty list when it has none)."""
    return list(structure.extensions.get("active_members", []))


def active_indices(structure: Structure) -> np.ndarray:
    """Member indices of the active members, shape (n_active,)."""
    return np.array([a.member for a in active_members(structure)], dtype=np.int64)
