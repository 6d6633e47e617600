# SPDX-License-Identifier: MIT
"""Active (variable-length) members: the ``[active_members]`` table of a model file.

An active member (Lacy section 2.1, 4.7): an active base pinned at the start node and a
leadscrew tube pinned at the end node.  The table's format and the data are
:mod:`trussfe.model.active` (read by :mod:`trussfe.io.extension_tables`); this module gives
the analyses their view of them.
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
