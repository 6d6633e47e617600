# SPDX-License-Identifier: MIT
"""Member vectors and lengths: the one computation every layer uses.

They live in the model layer so that :class:`~trussfe.model.structure.Structure` can give its
members' lengths without importing a solver layer; :mod:`trussfe.mechanics.geometry` re-exports
them beside the local frames and stations.  Every function is vectorised over members and over
any leading axes: node arrays have shape ``(..., n, dim)``, member arrays ``(..., m, dim)``.
"""
from __future__ import annotations

import numpy as np

from ..vectors import take


def member_vectors(x: np.ndarray, connectivity: np.ndarray) -> np.ndarray:
    """End-minus-start difference of a nodal field over every member.

    Parameters
    ----------
    x : ndarray, shape (..., n, dim)
        Node positions, or any nodal field (displacements, velocities, accelerations).
    connectivity : ndarray of int, shape (m, 2)
        Start and end node of every member.

    Returns
    -------
    ndarray, shape (..., m, dim)
        ``x[..., end] − x[..., start]``.
    """
    # np.take copies whole rows of the last axis: several times faster than fancy indexing
    # with an ellipsis over many leading steps, and the same numbers; a field stored
    # components first is gathered component by component, and so is the result
    # (trussfe.vectors).
    out = take(x, connectivity[:, 1], axis=-2)
    out -= take(x, connectivity[:, 0], axis=-2)
    return out


def lengths(d: np.ndarray) -> np.ndarray:
    """Lengths of member vectors ``d`` (..., m, dim), shape (..., m).

    The components' squares are summed in order along the last axis (as ``numpy.linalg.norm``
    does), so a length is the same to the last bit wherever it is computed.
    """
    sq = d * d
    if sq.ndim < 2 or not 0 < sq.shape[-1] <= 3:
        return np.sqrt(np.add.reduce(sq, axis=-1))
    # Column by column, in place: the same sums as ``np.add.reduce(sq, axis=-1)`` (which adds
    # a short axis in order), several times faster than a reduction over a last axis of two
    # or three.
    s = sq[..., 0].copy()
    for c in range(1, sq.shape[-1]):
        s += sq[..., c]
    return np.sqrt(s, out=s)


def member_lengths(x: np.ndarray, connectivity: np.ndarray) -> np.ndarray:
    """Member lengths for node positions ``x`` (..., n, dim), shape (..., m).

    Examples
    --------
    >>> import numpy as np
    >>> member_lengths(np.array([[0.0, 0.0], [3.0, 4.0]]), np.array([[0, 1]]))
    array([5.])
    """
    return lengths(member_vectors(x, connectivity))


def unit_vectors(d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Unit vectors and lengths of member vectors ``d`` (..., m, dim).

    Returns
    -------
    e : ndarray, shape (..., m, dim)
    L : ndarray, shape (..., m)
    """
    L = lengths(d)
    return d / L[..., None], L
