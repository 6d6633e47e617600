# SPDX-License-Identifier: MIT
"""Masses from loads: the nodal loads of a load case that act along gravity, as lumped masses.

A modal analysis of a structure that carries equipment or payload modelled as loads needs that
payload's mass; commercial codes call this a *mass source*.  The component of each nodal load
along the gravity direction ĝ is divided by ``|g|``: m_i = (F_i · ĝ) / ``|g|``.  Components across
gravity carry no mass (a wind load is not a weight).  A load against gravity would be a
negative mass and is refused.  The members' own mass is always in the mass matrix, so a case's
self-weight (``gravity = true``) adds nothing here.
"""
from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..errors import InputError


def masses_from_loads(loads: np.ndarray, gravity: np.ndarray, item: str,
                      node_ids: Sequence[str] | None = None) -> np.ndarray:
    """Lumped node masses equivalent to the nodal loads along gravity.

    Parameters
    ----------
    loads : ndarray, shape (n, ndof)
        Nodal loads (forces first, then moments), N.
    gravity : ndarray, shape (dim,)
        Gravitational acceleration, m/s² (not zero).
    item : str
        Names the load case in error messages.
    node_ids : sequence of str, optional
        Node ids, which name the node of a load against gravity (else its index).

    Returns
    -------
    ndarray, shape (n,)
        Masses, kg.

    Raises
    ------
    InputError
        Without gravity, or where a load points against it.

    Examples
    --------
    >>> masses_from_loads(np.array([[0.0, -98.1, 0.0], [5.0, 0.0, 0.0]]),
    ...                   np.array([0.0, -9.81]), "case").round(12).tolist()
    [10.0, 0.0]
    """
    g = np.asarray(gravity, dtype=float)
    size = float(np.linalg.norm(g))
    if not size > 0.0:
        raise InputError(item, "masses from loads need the gravity direction: give [model] "
                               "gravity")
    dim = g.size
    along = np.asarray(loads, dtype=float)[:, :dim] @ (g / size)
    scale = max(float(np.abs(loads).max(initial=0.0)), 1e-300)
    up = np.flatnonzero(along < -1e-12 * scale)
    if up.size:
        node = node_ids[up[0]] if node_ids is not None else str(up[0])
        raise InputError(f"{item}.{node}", f"a load against gravity ({along[up[0]]:.6g} N) is "
                                           "no mass: --mass-from takes loads along gravity")
    return np.maximum(along, 0.0) / size
