# SPDX-License-Identifier: MIT
"""Free rows and columns of a sparse matrix: the submatrix, the same block as an operator,
and which kept rows are coupled to the removed ones (the supports of a stiffness)."""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp


def free_submatrix(A: sp.spmatrix, free: np.ndarray) -> sp.csr_matrix:
    """``A[free][:, free]`` of a sparse matrix, in one vectorised pass over its entries.

    Parameters
    ----------
    A : sparse matrix, shape (n, n)
    free : ndarray of int
        Increasing indices of the kept rows and columns.

    Returns
    -------
    scipy.sparse.csr_matrix, shape (len(free), len(free))
        Column indices stay sorted when they were sorted in ``A``.

    Examples
    --------
    >>> A = sp.csr_matrix(np.arange(16.0).reshape(4, 4))
    >>> free_submatrix(A, np.array([0, 2, 3])).toarray()
    array([[ 0.,  2.,  3.],
           [ 8., 10., 11.],
           [12., 14., 15.]])
    """
    A = sp.csr_matrix(A)
    n = A.shape[0]
    free = np.asarray(free, dtype=np.int64)
    if free.size == n:
        return A
    idx = A.indices.dtype
    new = np.full(n, -1, dtype=idx)
    new[free] = np.arange(free.size, dtype=idx)
    is_free = new >= 0
    col = new[A.indices]
    keep = (col >= 0) & np.repeat(is_free, np.diff(A.indptr))   # kept column in a kept row
    # entries of kept row k are those kept between A.indptr[free[k]] and the next row
    kept_before = np.zeros(A.nnz + 1, dtype=np.int64)
    np.cumsum(keep, out=kept_before[1:])
    indptr = kept_before[A.indptr[np.r_[free, n]]]
    indptr[-1] = kept_before[-1]
    out = sp.csr_matrix((A.data[keep], col[keep], indptr), shape=(free.size, free.size))
    out.has_sorted_indices = bool(A.has_sorted_indices)
    return out


class FreeBlock:
    """``K[free][:, free]`` as an operator: products without forming the submatrix.

    Examples
    --------
    >>> K = sp.csr_matrix(np.arange(9.0).reshape(3, 3))
    >>> FreeBlock(K, np.array([0, 2])) @ np.array([1.0, 1.0])
    array([ 2., 14.])
    """

    def __init__(self, K: sp.csr_matrix | None, free: np.ndarray, n_dof: int | None = None):
        self.K, self.free = K, free
        self.n_dof = K.shape[0] if K is not None else int(n_dof)
        self.shape = (free.size, free.size)
        self._csr: sp.csr_matrix | None = None

    def _product(self, full: np.ndarray) -> np.ndarray:
        """The whole matrix times a vector over all DOFs (subclasses: without a matrix)."""
        return self.K @ full

    def _matrix(self) -> sp.csr_matrix:
        """The whole sparse matrix."""
        return self.K

    def __matmul__(self, x: np.ndarray) -> np.ndarray:
        x = np.asarray(x, dtype=float)
        full = np.zeros((self.n_dof,) + x.shape[1:])
        full[self.free] = x
        return self._product(full)[self.free]

    def diagonal(self) -> np.ndarray:
        """The diagonal of the block."""
        return self._matrix().diagonal()[self.free]

    def tocsr(self) -> sp.csr_matrix:
        """The block as a sparse matrix (formed once, on first request)."""
        if self._csr is None:
            self._csr = free_submatrix(self._matrix(), self.free)
        return self._csr


def anchored_rows(K: sp.spmatrix, free: np.ndarray) -> np.ndarray:
    """For each free DOF, whether K couples it to a supported DOF."""
    K = sp.csr_matrix(K)
    fixed = np.ones(K.shape[0], dtype=bool)
    fixed[free] = False
    if not fixed.any():
        return np.zeros(free.size, dtype=bool)
    row = np.repeat(np.arange(K.shape[0]), np.diff(K.indptr))
    coupled = np.zeros(K.shape[0], dtype=bool)
    coupled[row[fixed[K.indices]]] = True            # rows with an entry in a fixed column
    return coupled[free]
