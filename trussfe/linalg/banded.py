# SPDX-License-Identifier: MIT
"""Banded factorisations of sparse symmetric matrices: the solver for long, narrow structures.

A chain of bays numbered bay by bay has a half-bandwidth of 17 whatever its length, so LAPACK's
band routines factorise it in ``n·b²`` operations and solve in ``n·b`` — an order of magnitude
below a general sparse factorisation (PARDISO is 5–10x slower on such chains).

* :class:`BandedCholesky` (``pbtrf``/``pbtrs``) for positive definite matrices;
* :class:`BandedLU` (``gbtrf``/``gbtrs``, partial pivoting) when round-off has left a
  symmetric positive definite matrix numerically indefinite (chains beyond ~20,000 bays);
* :func:`band_layout` chooses the ordering (the given one, reverse Cuthill–McKee, and the
  direction that eliminates a cantilever from its free end) and :func:`band_layout_free`
  does the same for the free rows and columns of a global matrix without forming the
  submatrix.

Band arrays are Fortran-ordered, as LAPACK stores them: one column of the band per matrix
column, so the entries of a matrix row are written close together and nothing is copied on
the way into LAPACK.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
from scipy.sparse.csgraph import breadth_first_order, reverse_cuthill_mckee

from .sparse import free_submatrix
from .tolerance import SINGULAR_PIVOT


#: Half-bandwidth up to which the given DOF ordering is kept without trying reverse
#: Cuthill–McKee (whose cost would then exceed any gain).
NATURAL_BANDWIDTH_OK = 32


@dataclass
class BandLayout:
    """Entries of a symmetric matrix in the ordering chosen for band storage.

    Attributes
    ----------
    perm : ndarray of int, shape (n,)
        New → old row numbering.
    bandwidth : int
        Half-bandwidth in the new numbering.
    row, col : ndarray of int
        Every stored entry's row and column in the new numbering (duplicates summed).
    data : ndarray
        The entries.
    """

    perm: np.ndarray
    bandwidth: int
    row: np.ndarray
    col: np.ndarray
    data: np.ndarray

    @property
    def n(self) -> int:
        """Order of the matrix."""
        return self.perm.size

    def upper_band(self) -> np.ndarray:
        """LAPACK upper band storage ``ab[bw + i − j, j] = A[i, j]`` (i ≤ j), Fortran order."""
        bw, n = self.bandwidth, self.n
        up = self.row <= self.col
        flat = np.zeros((bw + 1) * n)
        # Fortran position of (bw + i − j, j) is (bw + 1)·j + bw + i − j = bw·(j + 1) + i
        idx = self.col[up].astype(np.int64 if flat.size >= 2**31 else self.col.dtype)
        idx *= bw
        idx += bw
        idx += self.row[up]
        flat[idx] = self.data[up]
        return flat.reshape((bw + 1, n), order="F")

    def general_band(self) -> np.ndarray:
        """LAPACK ``gbtrf`` storage with kl = ku = bw, Fortran order:
        ``ab[2bw + i − j, j] = A[i, j]`` (rows 0 … bw − 1: room for the fill-in)."""
        bw, n = self.bandwidth, self.n
        flat = np.zeros((3 * bw + 1) * n)
        # Fortran position of (2bw + i − j, j) is (3bw + 1)·j + 2bw + i − j = 3bw·j + 2bw + i
        idx = self.col.astype(np.int64 if flat.size >= 2**31 else self.col.dtype)
        idx *= 3 * bw
        idx += 2 * bw
        idx += self.row
        flat[idx] = self.data
        return flat.reshape((3 * bw + 1, n), order="F")



def bandwidth_lower_bound(A: sp.spmatrix) -> int:
    """A lower bound on the half-bandwidth of the symmetric matrix ``A`` under *any*
    ordering, from one breadth-first search: a connected graph of ``n`` vertices and diameter
    ``D`` has bandwidth at least ``(n − 1)/D`` (consecutive vertices of a shortest path are at
    most a bandwidth apart in any numbering, and some path must span the numbers 0 … n − 1),
    and ``D ≤ 2e`` with ``e`` the eccentricity of the search's root.  0 when the graph is not
    connected (no bound).

    A square space grid of 180 × 180 cells (195k DOF) has a bound of ~270, so the banded
    path is rejected at the cost of a search (~10 ms) instead of a reverse Cuthill–McKee
    ordering; a chain of bays has a bound of a few units.

    Examples
    --------
    >>> path = sp.diags([1.0, 1.0], [-1, 1], shape=(9, 9))
    >>> bandwidth_lower_bound(path)
    1
    """
    n = A.shape[0]
    if n <= 1:
        return 0
    # A is symmetric: its rows are its columns, and the directed search (4× faster than
    # scipy's undirected one, which first adds Aᵀ) visits the same graph
    order, pred = breadth_first_order(A, 0, directed=True, return_predecessors=True)
    if order.size < n:
        return 0
    # the search visits the vertices by increasing depth: the eccentricity of the root is
    # the depth of the last one, the length of its path of predecessors
    e, v = 0, int(order[-1])
    while v != 0 and e < WALK_STEPS:
        v = int(pred[v])
        e += 1
    if v != 0:
        # a long path (a chain of bays): its depth by pointer doubling along the tree
        p = pred.astype(np.int64)
        p[0] = 0
        depth = np.ones(n, dtype=np.int64)
        depth[0] = 0
        for _ in range(int(np.ceil(np.log2(n))) + 1):
            depth += depth[p]
            p = p[p]
            if not np.any(p):
                break
        e = int(depth.max())
    return int(np.ceil((n - 1) / (2 * e))) if e > 0 else 0


#: Steps of the predecessor path that :func:`bandwidth_lower_bound` walks one by one before
#: it takes every vertex's depth at once.
WALK_STEPS = 4096


def _finish(n: int, row: np.ndarray, col: np.ndarray, data: np.ndarray, max_bandwidth: int,
            anchored: np.ndarray | None, matrix=None, bounded: bool = False
            ) -> BandLayout | None:
    """Choose the ordering for entries given in the original numbering (see
    :func:`band_layout`); ``matrix`` (a callable returning the CSR matrix) is needed only when
    reverse Cuthill–McKee is tried; ``bounded``: :func:`bandwidth_lower_bound` already
    allowed ``max_bandwidth``."""
    bw = int(np.max(row - col)) if row.size else 0        # symmetric: max(i − j) = max|i − j|
    perm = None
    if bw > NATURAL_BANDWIDTH_OK:
        A = matrix()
        if (max_bandwidth is not None and not bounded
                and bandwidth_lower_bound(A) > max_bandwidth):
            return None                 # no ordering is narrow enough: skip the reordering
        rcm = reverse_cuthill_mckee(A, symmetric_mode=True).astype(np.int64)
        inv = np.empty(n, dtype=row.dtype)
        inv[rcm] = np.arange(n, dtype=row.dtype)
        r2, c2 = inv[row], inv[col]
        bw_rcm = int(np.max(r2 - c2)) if row.size else 0
        if bw_rcm < bw:
            perm, bw, row, col = rcm, bw_rcm, r2, c2
    if max_bandwidth is not None and bw > max_bandwidth:
        return None
    if perm is None:
        perm = np.arange(n, dtype=np.int64)
    if anchored is not None and np.any(anchored):
        pos = np.empty(n, dtype=np.int64)
        pos[perm] = np.arange(n)
        if np.mean(pos[np.asarray(anchored, dtype=bool)]) < 0.5 * (n - 1):
            # A Cholesky pivot is the stiffness of its DOF with the earlier DOFs free and the
            # later ones fixed: eliminating a cantilever from its free end keeps every pivot
            # at the stiffness of one bay (pivot ratio ~0.4 for a 10,000-bay chain, against
            # ~5e-14 when the soft tip comes last).
            perm = perm[::-1].copy()
            top = row.dtype.type(n - 1)
            row = top - row
            col = top - col
    return BandLayout(perm, bw, row, col, data)


def band_layout(A: sp.spmatrix, max_bandwidth: int | None = None,
                anchored: np.ndarray | None = None) -> BandLayout | None:
    """Ordering and entries of a symmetric sparse matrix for band storage.

    The given ordering is kept when its half-bandwidth is at most
    :data:`NATURAL_BANDWIDTH_OK` (a chain numbered bay by bay); otherwise reverse
    Cuthill–McKee is used when it is narrower.  With ``anchored`` (bool per row: the DOF is
    coupled to a support) the ordering is reversed when that puts the anchored rows towards
    the end, so a cantilever is eliminated from its free end.

    Returns
    -------
    BandLayout or None
        None when the half-bandwidth exceeds ``max_bandwidth`` (None: no limit).
    """
    A = sp.csr_matrix(A)
    if not A.has_canonical_format:
        A = A.copy()
        A.sum_duplicates()
    n = A.shape[0]
    it = A.indices.dtype                    # int32 below 2**31 entries: half the traffic
    row = np.repeat(np.arange(n, dtype=it), np.diff(A.indptr))
    return _finish(n, row, A.indices, A.data, max_bandwidth, anchored, matrix=lambda: A)


def band_layout_free(K: sp.csr_matrix, free: np.ndarray,
                     max_bandwidth: int | None = None,
                     submatrix: Callable[[], sp.csr_matrix] | None = None
                     ) -> BandLayout | None:
    """:func:`band_layout` of ``K[free][:, free]`` with ``anchored`` = the free rows coupled
    to a fixed DOF, in one pass over the entries of ``K`` (the submatrix is not formed).

    Parameters
    ----------
    K : scipy.sparse.csr_matrix, shape (N, N)
        Symmetric, canonical format (sorted, summed entries).
    free : ndarray of int
        Increasing indices of the kept rows and columns.
    submatrix : callable, optional
        Returns ``K[free][:, free]`` when a reordering needs it (a caller that keeps the
        submatrix for a later factorisation forms it once); by default it is formed here.
    """
    K = sp.csr_matrix(K)
    if not K.has_canonical_format:
        K = K.copy()
        K.sum_duplicates()
    N = K.shape[0]
    n = free.size
    it = K.indices.dtype
    new = np.full(N, -1, dtype=it)
    new[free] = np.arange(n, dtype=it)
    matrix = (lambda: free_submatrix(K, free)) if submatrix is None else submatrix
    bounded = False
    if max_bandwidth is not None and _sampled_width(K, free, new) > NATURAL_BANDWIDTH_OK:
        # the given order is not kept (a few rows are already wider), so only a reordering
        # could give a band: ask the bound first, before laying out every entry
        if bandwidth_lower_bound(matrix()) > max_bandwidth:
            return None
        bounded = True
    row = np.repeat(new, np.diff(K.indptr))
    col = new[K.indices]
    free_row = row >= 0
    keep = free_row & (col >= 0)
    anchored = np.zeros(n, dtype=bool)
    anchored[row[free_row & ~keep]] = True
    row, col, data = row[keep], col[keep], K.data[keep]
    return _finish(n, row, col, data, max_bandwidth, anchored, matrix=matrix,
                   bounded=bounded)


#: Rows looked at by :func:`_sampled_width` (evenly spread over the free rows).
WIDTH_SAMPLE_ROWS = 4096


def _sampled_width(K: sp.csr_matrix, free: np.ndarray, new: np.ndarray) -> int:
    """The largest ``|new[i] − new[j]|`` over the stored entries between free DOFs of
    :data:`WIDTH_SAMPLE_ROWS` rows spread over ``free``: a lower bound on the half-bandwidth
    of ``K[free][:, free]`` in its given order (any subset of the entries bounds the
    largest from below), for the cost of those rows."""
    rows = free[:: max(1, free.size // WIDTH_SAMPLE_ROWS)]
    if rows.size == 0:
        return 0
    start, stop = K.indptr[rows], K.indptr[rows + 1]
    counts = stop - start
    # positions of the sampled rows' entries in K.indices, row by row
    pos = np.repeat(start - np.cumsum(counts) + counts, counts) + np.arange(counts.sum())
    j = new[K.indices[pos]]
    i = np.repeat(new[rows], counts)
    ok = j >= 0
    return int(np.abs(i[ok] - j[ok]).max()) if np.any(ok) else 0


class SummedBandLayout(BandLayout):
    """A :class:`BandLayout` given by element blocks in the upper triangle (``row ≤ col``; −1
    in ``row`` marks an entry on a removed (supported) row, which is left out).  A position may
    occur more than once (every element at a node adds to its diagonal block), so the band
    arrays are summed with ``bincount``; ``reversed`` says the band numbering is ``n − 1 −``
    the numbering of ``row`` and ``col`` (see :func:`band_layout` on the direction).  The
    assembly of a truss straight into it is :func:`trussfe.fem.truss_band.truss_band_layout`.
    """

    def __init__(self, perm, bandwidth, row, col, data, reversed_: bool):
        super().__init__(perm, bandwidth, row, col, data)
        self.reversed = reversed_

    def _band_rc(self):
        # (row, col) in the band numbering with row ≤ col; left-out entries at row −1
        n = self.n
        if not self.reversed:
            return self.row, self.col
        lo = np.where(self.row >= 0, n - 1 - self.col, -1).astype(self.row.dtype)
        return lo, (n - 1 - self.row).astype(self.col.dtype)

    def upper_band(self) -> np.ndarray:
        bw, n = self.bandwidth, self.n
        size = (bw + 1) * n
        r, c = self._band_rc()
        # Fortran position of (bw + i − j, j) is bw·(j + 1) + i; left-out entries go to a
        # spare slot past the end (no compressed copies of the entry arrays)
        idx = np.empty(r.size, dtype=np.int64)
        np.multiply(c, bw, out=idx)
        idx += bw
        idx += r
        idx[r < 0] = size
        flat = np.bincount(idx, weights=self.data, minlength=size + 1)[:size]
        return flat.reshape((bw + 1, n), order="F")

    def general_band(self) -> np.ndarray:
        return general_from_upper(self.upper_band())


def general_from_upper(ab: np.ndarray) -> np.ndarray:
    """LAPACK ``gbtrf`` storage (kl = ku = bw, Fortran order) of the symmetric matrix whose
    upper band storage is ``ab`` (shape (bw + 1, n), Fortran order).

    ``gb[2bw + i − j, j] = A[i, j]``: rows bw … 2bw are ``ab`` itself; row 2bw + d holds the
    d-th subdiagonal, ``A[j + d, j] = ab[bw − d, j + d]``, read through a strided view of
    ``ab``; rows 0 … bw − 1 are zeros, LAPACK's room for the fill-in.

    Examples
    --------
    >>> A = np.array([[4.0, 1.0, 0.0], [1.0, 5.0, 2.0], [0.0, 2.0, 6.0]])
    >>> ab = np.asfortranarray([[0.0, 1.0, 2.0], [4.0, 5.0, 6.0]])
    >>> general_from_upper(ab)[1:].tolist()        # rows: superdiagonal, diagonal, sub
    [[0.0, 1.0, 2.0], [4.0, 5.0, 6.0], [1.0, 2.0, 0.0]]
    """
    bw1, n = ab.shape
    bw = bw1 - 1
    G = np.empty((n, 3 * bw + 1))             # C order: G.T is the Fortran (3bw + 1, n) array
    G[:, :bw] = 0.0
    G[:, bw:2 * bw + 1] = ab.T
    if bw:
        flat = ab.reshape(-1, order="F")      # ab[k, j] at (bw + 1)·j + k
        # G[j, 2bw + d] = ab[bw − d, j + d] = flat[(bw + 1)·j + bw + bw·d], d = 1 … bw
        full = max(n - bw, 0)
        step = flat.strides[0]
        sub = np.lib.stride_tricks.as_strided(flat[2 * bw:], shape=(full, bw),
                                              strides=((bw + 1) * step, bw * step),
                                              writeable=False)
        G[:full, 2 * bw + 1:] = sub
        j = np.arange(full, n)                # the last bw columns: a short tail
        for d in range(1, bw + 1):
            G[j, 2 * bw + d] = np.where(j + d < n, ab[bw - d, np.minimum(j + d, n - 1)], 0.0)
    return G.T


class BandedCholesky:
    """Banded Cholesky factorisation of a sparse symmetric positive definite matrix (cost
    n·b² to factorise, n·b per solve, b the half-bandwidth).

    Use :meth:`build`, which returns ``None`` when the bandwidth exceeds ``max_bandwidth`` or
    the matrix is not positive definite (the caller then falls back to LU).

    Examples
    --------
    >>> import scipy.sparse as sp
    >>> A = sp.diags([[-1.0] * 4, [2.0] * 5, [-1.0] * 4], [-1, 0, 1], format="csr")
    >>> f = BandedCholesky.build(A)
    >>> np.allclose(A @ f.solve(np.ones(5)), 1.0), f.bandwidth
    (True, 1)
    """

    kind = "banded"

    def __init__(self, factor: np.ndarray, perm: np.ndarray, bandwidth: int):
        self.factor = factor
        self.perm = perm
        self.inverse = np.empty_like(perm)
        self.inverse[perm] = np.arange(perm.size)
        self.bandwidth = bandwidth

    @classmethod
    def build(cls, A: sp.spmatrix | None = None, max_bandwidth: int | None = None,
              layout: BandLayout | None = None, upper: np.ndarray | None = None
              ) -> "BandedCholesky | None":
        """Factorise ``A`` (or the matrix of ``layout``), or return None (bandwidth above
        ``max_bandwidth``, or not numerically positive definite).  ``upper``: the layout's
        band array, already made; it is left unchanged (the factor goes to a copy)."""
        layout = band_layout(A, max_bandwidth) if layout is None else layout
        if layout is None:
            return None
        ab = layout.upper_band() if upper is None else upper
        c, info = sla.lapack.dpbtrf(ab, lower=0, overwrite_ab=int(upper is None))
        if info != 0:                          # a non-positive pivot: not positive definite
            return None
        d = np.abs(c[layout.bandwidth])
        # the LDLᵀ pivots are the squares of the Cholesky diagonal
        ratio = float((d.min() / d.max()) ** 2) if d.size else 1.0
        if ratio <= SINGULAR_PIVOT:
            return None
        out = cls(c, layout.perm, layout.bandwidth)
        out.pivot_ratio = ratio
        return out

    def solve(self, b: np.ndarray) -> np.ndarray:
        """Solve A x = b (b of shape (n,) or (n, k))."""
        x, info = sla.lapack.dpbtrs(self.factor, np.asarray(b, dtype=float)[self.perm], lower=0)
        return x[self.inverse]


class BandedLU:
    """Banded LU factorisation with partial pivoting (LAPACK ``gbtrf``/``gbtrs``), same
    ordering as :class:`BandedCholesky`, about three times its cost.

    It takes over when the Cholesky factorisation of a symmetric matrix breaks down on a pivot
    that round-off has made non-positive: beyond ~20,000 double-octahedral bays the stiffness
    of a chain's tip, ~L⁻⁴ relative to a bay's, is below the rounding of the entries, so the
    stored matrix is indefinite in its softest direction.  Accepted when the pivot ratio
    exceeds :data:`~trussfe.linalg.tolerance.SINGULAR_PIVOT` (the ratio is ~5e-14 for a 10,000-bay
    chain and ~3e-13 for 100,000 bays, measured); an exact mechanism leaves pivots at round-off
    level (≲ 1e-16) and is refused.

    Examples
    --------
    >>> import scipy.sparse as sp
    >>> A = sp.diags([[-1.0] * 4, [2.0] * 5, [-1.0] * 4], [-1, 0, 1], format="csr")
    >>> f = BandedLU.build(A)
    >>> np.allclose(A @ f.solve(np.ones(5)), 1.0)
    True
    """

    kind = "banded-lu"

    def __init__(self, lub: np.ndarray, piv: np.ndarray, perm: np.ndarray, bandwidth: int):
        self.lub, self.piv, self.perm, self.bandwidth = lub, piv, perm, bandwidth
        self.inverse = np.empty_like(perm)
        self.inverse[perm] = np.arange(perm.size)

    @classmethod
    def build(cls, A: sp.spmatrix | None = None, max_bandwidth: int | None = None,
              layout: BandLayout | None = None, upper: np.ndarray | None = None
              ) -> "BandedLU | None":
        """Factorise ``A`` (or the matrix of ``layout``) or return None (bandwidth too large,
        or numerically singular).  ``upper``: the layout's upper band array, already made
        (the LU storage is then copied from it instead of filled from the entries)."""
        layout = band_layout(A, max_bandwidth) if layout is None else layout
        if layout is None:
            return None
        bw = layout.bandwidth
        gb = layout.general_band() if upper is None else general_from_upper(upper)
        lub, piv, info = sla.lapack.dgbtrf(gb, bw, bw, overwrite_ab=1)
        if info != 0:                                      # an exactly zero pivot
            return None
        d = np.abs(lub[2 * bw])
        if not np.all(np.isfinite(d)):
            return None
        ratio = float(d.min() / d.max()) if d.size else 1.0
        if ratio <= SINGULAR_PIVOT:
            return None
        out = cls(lub, piv, layout.perm, bw)
        out.pivot_ratio = ratio
        return out

    def solve(self, b: np.ndarray) -> np.ndarray:
        """Solve A x = b (b of shape (n,) or (n, k))."""
        bw = self.bandwidth
        x, info = sla.lapack.dgbtrs(self.lub, bw, bw, np.asarray(b, dtype=float)[self.perm],
                                    self.piv)
        return x[self.inverse]


def banded_factor(A: sp.spmatrix | None = None, max_bandwidth: int | None = None,
                  anchored: np.ndarray | None = None, layout: BandLayout | None = None):
    """:class:`BandedCholesky` of ``A``, else :class:`BandedLU`, else None.

    ``anchored``: rows coupled to a support, ordered last when possible (see
    :func:`band_layout`); ``layout``: a layout already made (``A`` is then not needed)."""
    if layout is None:
        layout = band_layout(A, max_bandwidth, anchored)
    if layout is None:
        return None
    # one band array: Cholesky factorises a copy, LU (if needed) is laid out from it — a
    # second fill from the entries would cost more (1.6 s against 2.6 s at 1.8 M unknowns)
    upper = layout.upper_band()
    return (BandedCholesky.build(layout=layout, upper=upper)
            or BandedLU.build(layout=layout, upper=upper))


def band_null_space(layout: BandLayout, tolerance: float, max_vectors: int = 64
                    ) -> tuple[np.ndarray, bool]:
    """Null vectors of a symmetric positive semi-definite matrix from its banded Cholesky
    factorisation, one per vanishing pivot.

    A Cholesky pivot is the stiffness of its row with the earlier rows free and the later ones
    fixed.  When a pivot is at most ``tolerance`` times its diagonal entry, its row ``j`` is
    constrained (its row and column replaced by the identity) and the factorisation resumes
    after it.  The vector that is 1 in row ``j``, 0 in the later rows and in the constrained
    ones, and ``−K₁₁⁻¹ K₁ⱼ`` in the earlier rows has the vanishing pivot as its energy: a
    null vector, local to its mechanism, which is computed by one back substitution with the
    factor of the earlier rows.  Unlike the smallest eigenvalues of the matrix, which a long
    chain's flexible bending modes bring down to round-off (``~N⁻⁴`` for ``N`` bays, below
    1e-10 of the largest from ~160 double-octahedral bays), the pivots of an ordering that
    eliminates a cantilever from its free end stay at the stiffness of one bay, so only
    mechanisms are found.

    Parameters
    ----------
    layout : BandLayout
    tolerance : float
        A pivot at most this fraction of its diagonal entry vanishes.
    max_vectors : int
        Stop after this many null vectors.

    Returns
    -------
    V : ndarray, shape (n, r)
        Null vectors in the layout's original numbering, each of unit max-norm.
    complete : bool
        False when the search stopped at ``max_vectors`` (there may be more).
    """
    bw, n = layout.bandwidth, layout.n
    ab0 = layout.upper_band()
    ab = np.array(ab0, order="F")                # constrained rows become the identity
    diag = ab0[bw].copy()
    c = np.zeros_like(ab)                        # the factor of the constrained matrix
    found: list[tuple[int, np.ndarray]] = []     # (row, its factor column above the pivot)
    start = 0
    complete = True
    while start < n:
        sub = np.array(ab[:, start:], order="F")
        if start:
            # Schur complement of the factored rows: only the bw × bw corner changes
            lo = max(0, start - bw)
            w = min(bw, n - start)
            U11 = _upper_block(c, lo, start, bw)
            A12 = _full_block(ab, lo, start, start, start + w, bw)
            T = sla.solve_triangular(U11, A12, trans="T", lower=False, check_finite=False)
            for q in range(w):                   # U[lo:start, start + q], within the band
                i = np.arange(max(lo, start + q - bw), start)
                c[bw + i - start - q, start + q] = T[i - lo, q]
            S = T.T @ T
            for q in range(w):
                p = np.arange(max(0, q - bw), q + 1)
                sub[bw + p - q, q] -= S[p, q]
        ct, info = sla.lapack.dpbtrf(sub, lower=0)
        done = (info - 1) if info > 0 else sub.shape[1]
        piv = ct[bw, :done] ** 2
        small = np.flatnonzero(~(piv > tolerance * diag[start:start + done]))
        t = int(small[0]) if small.size else done
        # columns before t are the constrained matrix's factor (rows from `start` on), and
        # so is column t above its pivot
        last = min(t + 1, sub.shape[1])
        for q in range(min(last, bw)):
            c[bw - q:, start + q] = ct[bw - q:, q]
        if last > bw:
            c[:, start + bw:start + last] = ct[:, bw:last]
        if t >= sub.shape[1]:
            break
        if len(found) == max_vectors:
            complete = False
            break
        j = start + t
        found.append((j, c[:bw, j].copy()))
        ab[:bw, j] = 0.0
        ab[bw, j] = 1.0
        k = np.arange(j + 1, min(n, j + bw + 1))
        ab[bw + j - k, k] = 0.0
        c[:, j] = 0.0
        c[bw, j] = 1.0
        start = j + 1
    r = len(found)
    Y = np.zeros((n, r))
    for col, (j, above) in enumerate(found):
        Y[j, col] = 1.0
        if j == 0:
            continue
        m = min(bw, j)                          # U[j − m:j, j] = above[bw − m:]
        b = np.zeros(j)
        b[j - m:] = -above[bw - m:]
        x, _ = sla.lapack.dtbtrs(c[:, :j], b[:, None], uplo="U", trans="N", diag="N")
        Y[:j, col] = x[:, 0]
    V = np.zeros((n, 0))
    if r:
        # Each vector's energy is its vanishing pivot; nearly parallel vectors could still
        # span directions of higher energy: keep the Ritz vectors of the diagonally scaled
        # matrix in their span whose Rayleigh quotients are below the tolerance.
        scale = np.sqrt(np.where(diag > 0, diag, 1.0))
        Q, _ = np.linalg.qr(Y * scale[:, None])
        KQ = _band_matvec(ab0, Q / scale[:, None]) / scale[:, None]
        w, Z = np.linalg.eigh(0.5 * (Q.T @ KQ + KQ.T @ Q))
        Y = (Q @ Z[:, w <= tolerance]) / scale[:, None]
        V = np.zeros((n, Y.shape[1]))
        V[layout.perm] = Y
        if V.size:
            V /= np.abs(V).max(axis=0)
    return V, complete


def _band_matvec(ab: np.ndarray, X: np.ndarray) -> np.ndarray:
    """``A @ X`` for the symmetric matrix in upper band storage ``ab`` (shape (bw + 1, n))."""
    bw = ab.shape[0] - 1
    Y = ab[bw][:, None] * X
    for d in range(1, bw + 1):
        a = ab[bw - d, d:][:, None]                      # A[k − d, k], k = d … n − 1
        Y[:-d] += a * X[d:]
        Y[d:] += a * X[:-d]
    return Y


def _upper_block(c: np.ndarray, lo: int, hi: int, bw: int) -> np.ndarray:
    """Dense ``U[lo:hi, lo:hi]`` of an upper band factor (``hi − lo ≤ bw + 1``)."""
    m = hi - lo
    U = np.zeros((m, m))
    for q in range(m):
        p = np.arange(max(0, q - bw), q + 1)
        U[p, q] = c[bw + p - q, lo + q]
    return U


def _full_block(ab: np.ndarray, r0: int, r1: int, c0: int, c1: int, bw: int) -> np.ndarray:
    """Dense ``A[r0:r1, c0:c1]`` of the symmetric matrix in upper band storage ``ab``."""
    out = np.zeros((r1 - r0, c1 - c0))
    for q, k in enumerate(range(c0, c1)):
        i = np.arange(r0, r1)
        up = (i <= k) & (k - i <= bw)                    # A[i, k] = ab[bw + i − k, k]
        out[up, q] = ab[bw + i[up] - k, k]
        lowr = (i > k) & (i - k <= bw)                   # A[i, k] = A[k, i] = ab[bw + k − i, i]
        out[lowr, q] = ab[bw + k - i[lowr], i[lowr]]
    return out
