# SPDX-License-Identifier: MIT
"""Sparse factorisation of the free-DOF stiffness, with mechanism detection.

A singular stiffness never reaches the user as a traceback or a NaN: the factorisation
(:mod:`trussfe.fem.linsolve`) is checked for negligible pivots, and when it fails
the null space of the (diagonally scaled) stiffness is computed to say how many independent
mechanisms there are and which nodes move in them.
"""
from __future__ import annotations

import logging
import time
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..errors import MechanismError
from .banded import band_layout_free, banded_factor
from .linsolve import (SINGULAR_PIVOT, Factor, SingularMatrixError, banded_limit, factorize,
                       general_backend)

log = logging.getLogger(__name__)

#: Eigenvalues of the diagonally scaled stiffness below this (the largest is O(1)) are
#: counted as mechanisms.
NULL_TOLERANCE = 1e-10

#: Largest free-DOF count for which the null space is computed densely.
DENSE_LIMIT = 3000


@dataclass
class Factorised:
    """A factorised stiffness restricted to the free DOFs.

    Attributes
    ----------
    free : ndarray of int
        Global indices of the free DOFs.
    n_dof : int
        Size of the global system.
    timings : dict
        Seconds spent gathering the stiffness (``assemble``) and factorising, where the
        factorisation assembled it itself (:func:`factorise_truss`).
    """

    lu: object
    free: np.ndarray
    n_dof: int
    timings: dict = field(default_factory=dict)

    def solve(self, f: np.ndarray) -> np.ndarray:
        """Solve K u = f on the free DOFs; fixed DOFs get 0.  ``f`` (n_dof,) or (n_dof, r)."""
        f = np.asarray(f, dtype=float)
        u = np.zeros(f.shape)
        u[self.free] = self.lu.solve(np.ascontiguousarray(f[self.free]))
        return u


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


def factorise(K: sp.spmatrix, free: np.ndarray, fe=None, item: str = "structure",
              backend: str = "auto") -> Factorised:
    """Factorise K_ff (:func:`trussfe.fem.linsolve.factorize`), raising
    :class:`MechanismError` when it is singular.

    Parameters
    ----------
    K : sparse matrix, shape (n_dof, n_dof)
    free : ndarray of int
        Free DOFs.
    fe : FEModel, optional
        Used to name the moving nodes in the error.
    item : str
        Item named in the error message (the model file).
    backend : {"auto", "superlu", "pardiso"}
        Linear-solver backend.
    """
    K = sp.csr_matrix(K)
    if not K.has_canonical_format:
        K = K.copy()
        K.sum_duplicates()
    free = np.asarray(free, dtype=np.int64)
    n = free.size
    if n == 0:
        return Factorised(lu=_Empty(), free=free, n_dof=K.shape[0])
    limit = banded_limit(backend, n)
    if limit is not None:
        # long, narrow structures: band storage straight from K's free rows and columns.  A
        # DOF nothing is attached to has an empty row: both band factorisations refuse it.
        layout = band_layout_free(K, free, limit)
        band = banded_factor(layout=layout) if layout is not None else None
        if band is not None:
            lu = Factor(matrix=FreeBlock(K, free), backend=band.kind, n=n, _solve=band.solve)
            log.debug("factorised %d free DOFs (%s)", n, lu.backend)
            return Factorised(lu=lu, free=free, n_dof=K.shape[0])
        backend = general_backend(n)
    Kff = free_submatrix(K, free)
    if np.any(Kff.diagonal() <= 0):        # a DOF nothing is attached to
        _raise_mechanism(Kff, free, fe, item)
    try:
        lu = factorize(Kff, backend=backend, anchored=_anchored(K, free), symmetric=True)
    except SingularMatrixError:
        _raise_mechanism(Kff, free, fe, item)
    log.debug("factorised %d free DOFs (%s)", n, lu.backend)
    return Factorised(lu=lu, free=free, n_dof=K.shape[0])


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


def factorise_truss(fe, backend: str = "auto") -> Factorised | None:
    """Banded factorisation of K_ff of a plain truss straight from its bars, without the
    global sparse K (:mod:`trussfe.fem.truss_band`); None where that path does not apply (not
    a truss of single bars, too few DOFs for ``auto``, a DOF order that is not narrow, or
    both band factorisations refuse the matrix) — :func:`factorise` then takes over and, for
    a singular K, names the mechanism.
    """
    from .truss_band import TrussStiffness, is_plain_truss, truss_band_layout

    n = fe.free.size
    limit = banded_limit(backend, n)
    if limit is None or n == 0 or not is_plain_truss(fe):
        return None
    t0 = time.perf_counter()
    layout = truss_band_layout(fe, limit)
    t1 = time.perf_counter()
    band = banded_factor(layout=layout) if layout is not None else None
    if band is None:
        return None
    lu = Factor(matrix=TrussStiffness(fe), backend=band.kind, n=n, _solve=band.solve)
    log.debug("factorised %d free DOFs of a truss from its bars (%s)", n, lu.backend)
    # the bars' node blocks gathered for the band ("assemble"); band fill + LAPACK
    return Factorised(lu=lu, free=fe.free, n_dof=fe.n_dof,
                      timings={"assemble": t1 - t0, "factorise": time.perf_counter() - t1})


def _anchored(K: sp.spmatrix, free: np.ndarray) -> np.ndarray:
    """For each free DOF, whether K couples it to a supported DOF."""
    K = sp.csr_matrix(K)
    fixed = np.ones(K.shape[0], dtype=bool)
    fixed[free] = False
    if not fixed.any():
        return np.zeros(free.size, dtype=bool)
    counts = np.diff(K.indptr)
    rows = free[counts[free] > 0]                      # reduceat needs non-empty rows
    out = np.zeros(free.size, dtype=bool)
    hit = np.logical_or.reduceat(fixed[K.indices], K.indptr[rows]) if rows.size else rows
    out[counts[free] > 0] = hit
    return out


class _Empty:
    def solve(self, f):
        return np.zeros(f.shape)


def null_space(Kff: sp.spmatrix, max_vectors: int = 12) -> np.ndarray:
    """Mechanism modes of a positive semi-definite K_ff.

    The stiffness is scaled by its diagonal (``D^-1/2 K D^-1/2``, largest eigenvalue O(1));
    eigenvalues below :data:`NULL_TOLERANCE` are mechanisms.  Dense ``eigh`` up to
    :data:`DENSE_LIMIT` DOFs, else shift-invert ``eigsh`` for at most ``max_vectors`` modes.

    Returns
    -------
    ndarray, shape (n_free, r)
        Mechanism modes in the original (unscaled) DOFs, each of unit max-norm.
    """
    d = Kff.diagonal().astype(float)
    zero = d <= 0
    dd = np.where(zero, 1.0, d)
    s = 1.0 / np.sqrt(dd)
    Ks = sp.diags(s) @ Kff @ sp.diags(s)
    n = Ks.shape[0]
    if n <= DENSE_LIMIT:
        w, V = sla.eigh(Ks.toarray())
        keep = w < NULL_TOLERANCE * max(1.0, w[-1])
        V = V[:, keep]
    else:
        k = min(max_vectors, n - 2)
        v0 = np.random.default_rng(0).standard_normal(n)     # reproducible start vector
        try:
            w, V = spla.eigsh(Ks.tocsc(), k=k, sigma=-1e-6, which="LM", v0=v0,
                              maxiter=50 * n)
        except spla.ArpackNoConvergence as exc:               # keep what converged
            w, V = exc.eigenvalues, exc.eigenvectors
        V = V[:, w < NULL_TOLERANCE]
    V = V * s[:, None]
    if V.size:
        V = V / np.abs(V).max(axis=0)
    return V


def _raise_mechanism(Kff, free, fe, item):
    V = null_space(Kff)
    r = V.shape[1]
    if r == 0:
        # pivots collapsed without an exact null space: ill-conditioned beyond double
        # precision; say so rather than return meaningless numbers
        raise MechanismError(item, "the stiffness matrix is numerically singular (a pivot "
                             f"below {SINGULAR_PIVOT:g} of the largest) although no exact "
                             "mechanism was found: the structure is too flexible for a "
                             "reliable linear solution; add supports or members",
                             mechanisms=0, moving_nodes=[])
    moving = _moving_nodes(V, free, fe)
    shown = ", ".join(moving[:20]) + (" ..." if len(moving) > 20 else "")
    more = "at least " if Kff.shape[0] > DENSE_LIMIT and r >= 12 else ""
    raise MechanismError(
        item, f"the structure is a mechanism: {more}{r} independent mechanism"
        f"{'s' if r != 1 else ''} (rigid-body motions included); moving nodes: "
        f"{shown or 'none (only member-internal DOFs)'}; add supports or members, or run "
        "'trussfe mechanism' for the rank analysis", mechanisms=r, moving_nodes=moving)


def _moving_nodes(V: np.ndarray, free: np.ndarray, fe) -> list[str]:
    if fe is None:
        return []
    full = np.zeros((fe.n_dof, V.shape[1]))
    full[free] = V
    amp = np.abs(full).max(axis=1)                   # (n_dof,)
    dofs = fe.node_dofs
    node_amp = np.where(dofs >= 0, amp[np.maximum(dofs, 0)], 0.0).max(axis=1)
    ids = fe.structure.node_ids
    moving = [ids[i] for i in np.flatnonzero(node_amp > 1e-6)]
    if not moving:
        pts = fe.interior_dofs
        pt_amp = np.where(pts >= 0, amp[np.maximum(pts, 0)], 0.0).max(axis=1) if pts.size \
            else np.zeros(0)
        mem = np.unique(fe.interior_member[pt_amp > 1e-6])
        moving = [f"member {fe.structure.member_ids[i]}" for i in mem]
    return moving
