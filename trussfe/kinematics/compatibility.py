# SPDX-License-Identifier: MIT
"""The compatibility matrix B of a pin-jointed assembly and the DOF bookkeeping around it.

Row i of B (b × μ·j) holds the unit vector of bar i at its two joints, so that ``B d = e`` maps
joint displacements d to bar elongations e (Hortobágyi eq. 2, linearised).  Its
transpose is the equilibrium matrix, ``Bᵀ t = f`` (the axial part of Lacy eq. 2.13 / 4.20), and
the truss stiffness is ``K = Bᵀ diag(EA/L) B``.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from ..mechanics.geometry import member_vectors, unit_vectors


def compatibility_matrix(coords: np.ndarray, connectivity: np.ndarray,
                         free: np.ndarray | None = None) -> sp.csr_matrix:
    """Sparse compatibility matrix B of the current geometry.

    Parameters
    ----------
    coords : ndarray, shape (n, dim)
        Joint coordinates.
    connectivity : ndarray of int, shape (b, 2)
        Start and end joint of each bar.
    free : ndarray of bool, shape (n, dim), optional
        Free coordinates; when given only their columns are kept (in row-major order of
        ``coords``), otherwise all ``n * dim`` columns.

    Returns
    -------
    scipy.sparse.csr_matrix, shape (b, n_free)

    Notes
    -----
    .. math:: B_{i,(b,k)} = e_{ik},\\quad B_{i,(a,k)} = -e_{ik},\\quad
              e_i = (x_b - x_a)/\\lVert x_b - x_a\\rVert

    Examples
    --------
    >>> B = compatibility_matrix(np.array([[0., 0.], [3., 4.]]), np.array([[0, 1]]))
    >>> B.toarray()
    array([[-0.6, -0.8,  0.6,  0.8]])
    """
    coords = np.asarray(coords, dtype=float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    n, dim = coords.shape
    b = conn.shape[0]
    vec = member_vectors(coords, conn)          # (bar, dim)
    unit = unit_vectors(vec)[0]
    rows = np.repeat(np.arange(b), 2 * dim)
    cols = (conn[:, :, None] * dim + np.arange(dim)[None, None, :]).reshape(b, -1)  # (bar, 2*dim)
    vals = np.concatenate([-unit, unit], axis=1)
    if free is not None:
        return _free_columns(vals, cols, np.asarray(free, dtype=bool).ravel())
    return sp.csr_matrix((vals.ravel(), (rows, cols.ravel())), shape=(b, n * dim))


def _free_columns(vals: np.ndarray, cols: np.ndarray, free: np.ndarray) -> sp.csr_matrix:
    """The CSR matrix of the entries ``vals`` at columns ``cols`` (bar, 2 dim) restricted to
    the ``free`` columns, renumbered, each row's entries in increasing column order.

    The same matrix, array for array, as assembling all columns and selecting the free ones
    (explicit zeros kept), built directly: a forward-position Newton step is small, and
    the general assembly and column selection were most of its time."""
    b = cols.shape[0]
    renum = np.cumsum(free) - 1
    new = np.where(free[cols], renum[cols], -1)
    # each row's kept entries by increasing column (a bar's two joints are distinct)
    order = np.argsort(np.where(new >= 0, new, free.size), axis=1, kind="stable")
    new = np.take_along_axis(new, order, axis=1)
    vals = np.take_along_axis(vals, order, axis=1)
    keep = new >= 0
    indptr = np.zeros(b + 1, dtype=np.int32)
    np.cumsum(keep.sum(axis=1), out=indptr[1:])
    return sp.csr_matrix((vals[keep], new[keep].astype(np.int32), indptr),
                         shape=(b, int(free.sum())))


def equilibrium_matrix(coords: np.ndarray, connectivity: np.ndarray,
                       free: np.ndarray | None = None) -> sp.csr_matrix:
    """Equilibrium matrix Bᵀ, so that ``Bᵀ t = f`` for bar tensions t and joint loads f.

    The sign convention makes t positive in tension and f the external load on the joints
    (Lacy's nodal constraint equations with the member forces taken as bar tensions).
    """
    return compatibility_matrix(coords, connectivity, free).T.tocsr()


def anchored_bar_count(connectivity: np.ndarray, free: np.ndarray) -> int:
    """Bars whose two joints are fixed in every direction: zero rows of B, each a state of
    self-stress of its own that no motion changes (a four-bar's ground bar).

    Examples
    --------
    >>> free = np.array([[False, False], [False, False], [True, True]])
    >>> anchored_bar_count(np.array([[0, 1], [1, 2]]), free)
    1
    """
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    free = np.asarray(free, dtype=bool)
    return int(np.sum(~free[conn[:, 0]].any(axis=1) & ~free[conn[:, 1]].any(axis=1)))
