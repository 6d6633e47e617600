# SPDX-License-Identifier: MIT
"""Elastic supports and rotary inertia of nodes: ``Structure.extensions["springs"]`` and
``Structure.extensions["rotary_inertia"]``.

Both are per node and per DOF, in global axes, in the column order of ``Structure.supports``
(2-D: x, y, rz; 3-D: x, y, z, rx, ry, rz) for springs and of the rotations (2-D: rz; 3-D: rx,
ry, rz) for rotary inertia.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .sealed import sealed


def _readonly(value: Any, name: str) -> np.ndarray:
    a = np.array(value, dtype=float)
    if a.ndim != 2:
        raise ValueError(f"{name}: expected a (nodes, DOFs) array, got shape {a.shape}")
    if not np.all(np.isfinite(a)) or np.any(a < 0):
        raise ValueError(f"{name}: values must be finite and not negative")
    return sealed(a)


@dataclass(frozen=True, eq=False)
class Springs:
    """Elastic supports: a linear spring from each node DOF to the ground.

    Attributes
    ----------
    stiffness : ndarray, shape (n, ndof)
        N/m on translations, N·m/rad on rotations; 0 where there is no spring.

    Notes
    -----
    A spring adds its stiffness to the diagonal of the global stiffness at its DOF; the force
    it exerts on the structure, −k·u, is a support reaction.
    """

    stiffness: np.ndarray

    def __post_init__(self) -> None:
        object.__setattr__(self, "stiffness", _readonly(self.stiffness, "springs"))

    def __setstate__(self, state: dict) -> None:
        # unpickled arrays come back writable: freeze them again (pickle, copy.deepcopy)
        self.__dict__.update(state)
        self.__post_init__()


@dataclass(frozen=True, eq=False)
class RotaryInertia:
    """Mass moments of inertia lumped at nodes (with the ``[masses]`` point masses).

    Attributes
    ----------
    inertia : ndarray, shape (n, nrot)
        kg·m² about the global axes through the node (2-D: about z; 3-D: about x, y, z).
    """

    inertia: np.ndarray

    def __post_init__(self) -> None:
        object.__setattr__(self, "inertia", _readonly(self.inertia, "rotary_inertia"))

    def __setstate__(self, state: dict) -> None:
        # unpickled arrays come back writable: freeze them again (pickle, copy.deepcopy)
        self.__dict__.update(state)
        self.__post_init__()
