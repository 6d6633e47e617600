# SPDX-License-Identifier: MIT
"""Batched solves of one sparse pattern over many time steps.

The compatibility matrix B of a truss keeps its sparsity pattern along a motion; only the
values (unit vectors) change.  Small systems are solved as a stack of dense matrices
(``numpy.linalg.solve`` over the time axis); large ones as a block-diagonal sparse matrix over
a chunk of time steps, factorised once by SuperLU.  Either way there is no Python loop per
time step, and a singular step is reported by its index.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

#: Largest system solved as a dense stack.
DENSE_LIMIT = 36
#: Steps per anchor factorisation of large systems (:class:`CompatSolver`).
ANCHOR_SPACING = 8
#: Refinement sweeps allowed before a step counts as singular.
REFINEMENT_SWEEPS = 200
#: Reciprocal condition number below which a step counts as singular.  The positions are
#: solved to 1e-12 of the truss size, so a singular (flat) position is only resolved to an
#: angle of about 1e-6: below 1e-5 the forces would be round-off magnified by 1e5 and more.
SINGULAR_RCOND = 1e-5


class SingularStep(Exception):
    """A time step whose matrix is singular; ``step`` is its index."""

    def __init__(self, step: int):
        super().__init__(step)
        self.step = step


def batched_solve(rows: np.ndarray, cols: np.ndarray, vals: np.ndarray, shape: tuple[int, int],
                  rhs: np.ndarray, check: bool = True) -> np.ndarray:
    """Solve ``A_k x_k = b_k`` for every step k; all ``A_k`` share one sparsity pattern.

    Parameters
    ----------
    rows, cols : ndarray of int, shape (nnz,)
        Pattern (duplicates are summed).
    vals : ndarray, shape (nt, nnz)
        Values per step.
    shape : (int, int)
        Square shape of each ``A_k``.
    rhs : ndarray, shape (nt, n) or (nt, n, r)
        Right-hand sides.
    check : bool
        Test every step for singularity (reciprocal condition number, dense path); skip when
        the same matrices were checked already.

    Returns
    -------
    ndarray, same shape as ``rhs``

    Raises
    ------
    SingularStep
        At the first step whose matrix is (numerically) singular.

    Examples
    --------
    >>> x = batched_solve(np.array([0, 1]), np.array([0, 1]), np.array([[2.0, 4.0]]),
    ...                   (2, 2), np.array([[2.0, 2.0]]))
    >>> x.tolist()
    [[1.0, 0.5]]
    """
    n = shape[0]
    nt = vals.shape[0]
    if n == 0:
        return np.zeros_like(rhs)
    vec = rhs.ndim == 2
    b = rhs[..., None] if vec else rhs
    if n <= DENSE_LIMIT:
        A = np.zeros((nt, n * n))
        lin = rows * n + cols
        # Duplicate-summing scatter of the same pattern for every step.
        order = np.argsort(lin, kind="stable")
        uniq, start = np.unique(lin[order], return_index=True)
        A[:, uniq] = np.add.reduceat(vals[:, order], start, axis=1)
        A = A.reshape(nt, n, n)
        if check:
            check_singular(A)
        try:
            x = np.linalg.solve(A, b)
        except np.linalg.LinAlgError:
            check_singular(A)
            raise
        return x[..., 0] if vec else x
    # Sparse, block-diagonal over chunks of steps (the pivots are always checked).
    out = np.empty_like(b)
    chunk = max(1, 200_000 // max(n, 1))
    for k0 in range(0, nt, chunk):
        k1 = min(nt, k0 + chunk)
        nk = k1 - k0
        off = (np.arange(nk) * n)[:, None]
        R = (rows[None, :] + off).ravel()
        C = (cols[None, :] + off).ravel()
        A = sp.csc_matrix((vals[k0:k1].ravel(), (R, C)), shape=(nk * n, nk * n))
        try:
            lu = spla.splu(A)
        except RuntimeError:
            raise SingularStep(k0) from None
        d = np.abs(lu.U.diagonal())
        scale = np.abs(vals[k0:k1]).max()
        if d.min() <= SINGULAR_RCOND * max(scale, 1e-300):
            raw = int(lu.perm_c[np.argmin(d)]) if lu.perm_c is not None else int(np.argmin(d))
            raise SingularStep(k0 + raw // n)
        rr = b[k0:k1].reshape(nk * n, -1)
        out[k0:k1] = lu.solve(rr).reshape(nk, n, -1)
    return out[..., 0] if vec else out


def check_singular(A: np.ndarray) -> None:
    """Raise :class:`SingularStep` at the first matrix of the stack ``A`` (nt, n, n) whose
    reciprocal condition number is below :data:`SINGULAR_RCOND`.

    The singular values come from the eigenvalues of AᵀA (cheaper than an SVD; the square
    root halves the attainable precision, ample for a 1e-5 threshold).
    """
    lam = np.linalg.eigvalsh(np.einsum("tji,tjk->tik", A, A))
    rc = np.sqrt(np.clip(lam[:, 0], 0.0, None) / np.maximum(lam[:, -1], 1e-300))
    bad = np.flatnonzero(~(rc >= SINGULAR_RCOND))
    if bad.size:
        raise SingularStep(int(bad[0]))


class CompatSolver:
    """Factorised compatibility matrices B_k of every step, for ``B x = b`` and ``Bᵀ y = c``.

    Small systems keep the stacked inverses (one batched LAPACK call; every later solve is a
    batched matrix–vector product); large ones keep one SuperLU factorisation of the
    block-diagonal matrix per chunk of steps, used for both B and Bᵀ (``trans="T"``).  The
    velocities, the accelerations and the dynamic and static member forces of a motion all
    reuse the same factorisation.

    Parameters
    ----------
    rows, cols : ndarray of int, shape (nnz,)
        Pattern of B (no duplicates).
    vals : ndarray, shape (nt, nnz)
    n : int
        Size of each square B_k.

    Raises
    ------
    SingularStep
        At the first step whose reciprocal condition number (dense: Frobenius norms, which
        bound the spectral one within a factor n) or relative pivot (sparse) is below
        :data:`SINGULAR_RCOND`.
    """

    def __init__(self, rows: np.ndarray, cols: np.ndarray, vals: np.ndarray, n: int):
        self.n = n
        self.nt = vals.shape[0]
        self.inverse = None
        self.blocks: list[tuple[int, int, object]] = []
        if n == 0:
            return
        if n <= DENSE_LIMIT:
            A = np.zeros((self.nt, n * n))
            A[:, rows * n + cols] = vals
            A = A.reshape(self.nt, n, n)
            try:
                inv = np.linalg.inv(A)
            except np.linalg.LinAlgError:
                check_singular(A)
                raise SingularStep(0) from None          # pragma: no cover
            with np.errstate(over="ignore", invalid="ignore"):
                rc = 1.0 / (np.linalg.norm(A, axis=(1, 2)) * np.linalg.norm(inv, axis=(1, 2)))
            bad = np.flatnonzero(~(rc >= SINGULAR_RCOND))
            if bad.size:
                raise SingularStep(int(bad[0]))
            self.inverse = inv
            return
        # Large systems: SuperLU factorisations of B at anchor steps only; every step is
        # solved by refinement against its own B with the nearest anchor's factors.  B changes
        # little between neighbouring steps, so a few refinement sweeps reach round-off, at a
        # fraction of the cost of one factorisation per step.
        self.rows, self.cols, self.vals = rows, cols, vals
        self.anchors = np.unique(np.linspace(0, self.nt - 1,
                                             max(1, -(-self.nt // ANCHOR_SPACING))).round()
                                 .astype(int))
        mids = (self.anchors[1:] + self.anchors[:-1]) / 2.0
        self.owner = np.searchsorted(mids, np.arange(self.nt))
        scale = np.abs(vals).max()
        self.lus = []
        for k in self.anchors:
            A = sp.csc_matrix((vals[k], (rows, cols)), shape=(n, n))
            try:
                lu = spla.splu(A)
            except RuntimeError:
                raise SingularStep(int(k)) from None
            if np.abs(lu.U.diagonal()).min() <= SINGULAR_RCOND * max(scale, 1e-300):
                raise SingularStep(int(k))
            self.lus.append(lu)
        # All steps' B_k as one block-diagonal CSR matrix, for the residuals.
        off = (np.arange(self.nt) * n)[:, None]
        self._block = sp.csr_matrix((vals.ravel(), ((rows[None, :] + off).ravel(),
                                                    (cols[None, :] + off).ravel())),
                                    shape=(self.nt * n, self.nt * n))
        self._block_t = self._block.T.tocsr()

    def _matvec(self, x: np.ndarray, transpose: bool) -> np.ndarray:
        """B_k x_k (or B_kᵀ x_k) for every step, vectorised over steps."""
        A = self._block_t if transpose else self._block
        return (A @ x.ravel()).reshape(x.shape)

    def _anchor_solve(self, r: np.ndarray, transpose: bool) -> np.ndarray:
        dx = np.empty_like(r)
        for j, lu in enumerate(self.lus):
            idx = np.flatnonzero(self.owner == j)
            if idx.size:
                dx[idx] = lu.solve(np.ascontiguousarray(r[idx].T),
                                   trans="T" if transpose else "N").T
        return dx

    def solve(self, rhs: np.ndarray, transpose: bool = False,
              approximate: bool = False) -> np.ndarray:
        """x with B_k x_k = rhs_k (or B_kᵀ x_k = rhs_k), rhs of shape (nt, n).

        ``approximate=True`` (large systems) returns the nearest anchor's solution without
        refinement — enough for an outer iteration that corrects itself (chord Newton).
        """
        if self.inverse is not None:
            sub = "tji,tj->ti" if transpose else "tij,tj->ti"
            return np.einsum(sub, self.inverse, rhs)
        if self.n == 0:
            return np.zeros_like(rhs, dtype=float)
        rhs = np.asarray(rhs, dtype=float)
        if approximate:
            return self._anchor_solve(rhs, transpose)
        x = np.zeros_like(rhs)
        r = rhs.copy()
        prev = np.full(self.nt, np.inf)
        bmax = np.abs(self.vals).max(axis=1)
        for _ in range(REFINEMENT_SWEEPS):
            x += self._anchor_solve(r, transpose)
            r = rhs - self._matvec(x, transpose)
            err = np.abs(r).max(axis=1)
            # Round-off floor of the residual: a few ulps of |B| |x| and of |rhs|.
            tol = 1e-13 * (np.abs(rhs).max(axis=1) + 4.0 * bmax * np.abs(x).max(axis=1)) + 1e-300
            if np.all(err <= tol):
                return x
            stalled = (err > tol) & (err >= 0.95 * prev)
            if np.any(stalled):
                # No contraction: B_k is (nearly) singular or far from its anchor.
                raise SingularStep(int(np.flatnonzero(stalled)[0]))
            prev = err
        raise SingularStep(int(np.flatnonzero(err > tol)[0]))
