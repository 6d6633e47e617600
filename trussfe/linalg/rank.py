# SPDX-License-Identifier: MIT
"""Rank and null spaces: the mechanism count of every solver.

* :func:`matrix_rank` — rank of a rectangular sparse matrix (a compatibility matrix ``B``),
  its null space (the mechanisms) and, on the dense path, its left null space (the states of
  self-stress).  Dense SVD up to ``dense_limit`` rows and columns; above, the inertia of the
  shifted Gram matrix ``BᵀB − σ_tol² I`` counted from one symmetric factorisation
  (:func:`trussfe.linalg.factor.factor`, ``kind="symmetric"``), with the null vectors by
  block inverse iteration on the same factorisation.
* :func:`stiffness_null_space` — the mechanism modes of a positive semi-definite stiffness
  ``K_ff``, from its diagonally scaled form.

Tolerances
----------
``B`` holds direction cosines, so its singular values are dimensionless; a singular value
counts as zero when ``σ ≤ tolerance · σ_max``, by default ``max(b, f) · 1e3 · ε`` (about 2e-10
for a hundred bars) on the dense path.  The sparse path resolves σ only through σ² (round-off
of ``BᵀB``), so its relative tolerance is at least :data:`SPARSE_MIN_TOLERANCE`.  A stiffness
is scaled to ``D^-1/2 K D^-1/2`` (largest eigenvalue O(1)), and eigenvalues below
:data:`NULL_TOLERANCE` are mechanisms.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from .factor import factor

log = logging.getLogger(__name__)

#: Relative rank tolerance of the sparse path (σ resolved through σ² ~ round-off of BᵀB).
SPARSE_MIN_TOLERANCE = 1e-6
#: Eigenvalues of the diagonally scaled stiffness below this (the largest is O(1)) are
#: counted as mechanisms.
NULL_TOLERANCE = 1e-10
#: Vectors beyond the null space that the sparse path's block inverse iteration may take on
#: to resolve the null space from eigenvalues of ``BᵀB`` just above the tolerance.
NULL_BLOCK_EXTRA = 64
#: Largest order for which the null space of a stiffness is computed densely.
DENSE_LIMIT = 3000


class RankError(ValueError):
    """The sparse rank path cannot decide (too many null vectors, or a failed
    factorisation): the dense path is needed."""


@dataclass
class Rank:
    """Outcome of :func:`matrix_rank`.

    Attributes
    ----------
    rank : int
    null : ndarray, shape (f, f − rank)
        Orthonormal basis of the null space.
    left_null : ndarray, shape (b, b − rank) or None
        Orthonormal basis of the left null space (None on the sparse path).
    tolerance : float
        Absolute singular-value threshold used.
    smallest_kept, largest_dropped : float
        Smallest singular value counted in the rank and largest one treated as zero (``nan``
        if none): the margin of the decision.
    backend : str
        "dense", or the sparse factorisation's backend.
    """

    rank: int
    null: np.ndarray
    left_null: np.ndarray | None
    tolerance: float
    smallest_kept: float
    largest_dropped: float
    backend: str


def matrix_rank(B, tolerance: float | None = None, dense_limit: int = 1500,
                backend: str = "auto") -> Rank:
    """Rank and null spaces of a (sparse) matrix ``B`` of shape (b, f).

    Parameters
    ----------
    B : sparse matrix or ndarray, shape (b, f)
    tolerance : float, optional
        Relative singular-value tolerance (σ ≤ tolerance·σ_max counts as zero).  Default
        ``max(b, f)·1e3·ε`` (dense) or :data:`SPARSE_MIN_TOLERANCE` (sparse, also its floor).
    dense_limit : int
        Dense SVD when both dimensions are at most this.
    backend : {"auto", "superlu", "pardiso"}
        Symmetric factorisation of the sparse path (``auto``: the rule of
        :mod:`trussfe.linalg.factor`); PARDISO's inertia is used only when no pivot was
        perturbed, SuperLU's otherwise.

    Returns
    -------
    Rank

    Raises
    ------
    RankError
        The sparse path found nearly every direction null, or its factorisation failed.

    Examples
    --------
    >>> r = matrix_rank(np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]))
    >>> r.rank, r.null.shape, r.left_null.shape
    (2, (3, 1), (2, 0))
    """
    b, f = B.shape
    if f <= dense_limit and b <= dense_limit:
        return _dense(B, tolerance)
    return _sparse(sp.csr_matrix(B), tolerance, backend)


def _dense(B, tolerance) -> Rank:
    b, f = B.shape
    A = B.toarray() if sp.issparse(B) else np.asarray(B, dtype=float)
    if b == 0 or f == 0:
        s = np.zeros(0)
        u = np.eye(b)
        vt = np.eye(f)
    else:
        u, s, vt = np.linalg.svd(A, full_matrices=True)
    rtol = max(b, f) * 1e3 * np.finfo(float).eps if tolerance is None else float(tolerance)
    smax = float(s.max()) if s.size else 0.0
    tol = rtol * max(smax, 1e-300)
    rank = int(np.sum(s > tol))
    kept = float(s[rank - 1]) if rank > 0 else float("nan")
    dropped = float(s[rank]) if rank < s.size else (0.0 if f > rank else float("nan"))
    return Rank(rank=rank, null=vt[rank:].T, left_null=u[:, rank:], tolerance=tol,
                smallest_kept=kept, largest_dropped=dropped, backend="dense")


def _sparse(B: sp.csr_matrix, tolerance, backend) -> Rank:
    b, f = B.shape
    rtol = max(SPARSE_MIN_TOLERANCE, 0.0 if tolerance is None else float(tolerance))
    K = (B.T @ B).tocsc()
    # λ_max(K) ≤ ‖K‖₁ (Gershgorin): a cheap, safe scale for the relative tolerance
    smax2 = float(abs(K).sum(axis=0).max())
    lam_tol = (rtol ** 2) * smax2
    # Sylvester's law of inertia: the number of eigenvalues of K below λ_tol is the number of
    # negative pivots of a symmetric factorisation of K − λ_tol·I.
    shifted = (K - lam_tol * sp.eye(f, format="csc")).tocsr()
    try:
        fac = factor(shifted, "symmetric", backend, singular="flag")
    except ValueError as exc:                    # PARDISO asked for but not installed
        raise RankError(str(exc)) from None
    if fac.backend == "pardiso" and (fac.is_singular or fac.inertia is None):
        # a perturbed pivot could change the inertia: count it from SuperLU's pivots instead
        log.info("PARDISO inertia not reliable (%s); using SuperLU", fac.reason)
        fac = factor(shifted, "symmetric", "superlu", singular="flag")
    if fac.is_singular or fac.inertia is None:
        raise RankError(f"sparse factorisation failed ({fac.reason or 'no inertia'}); use "
                        "the dense path (raise dense_limit)")
    nz = fac.inertia
    if nz >= f - 1:
        raise RankError("too many mechanisms for the sparse path; use the dense path "
                        "(raise dense_limit)")
    vals = np.zeros(0)
    vecs = np.zeros((f, 0))
    if nz:
        # Block inverse iteration with the same factorisation, then Rayleigh–Ritz.  It
        # favours the eigenvalues nearest the shift λ_tol, and one in (λ_tol, 2 λ_tol) is
        # nearer than the null ones: the block grows (and iterates on) until its nz smallest
        # Ritz values, upper bounds of the nz smallest eigenvalues, are below λ_tol.
        rng = np.random.default_rng(0)
        p = nz + 2
        largest = min(f, nz + NULL_BLOCK_EXTRA)
        V = np.linalg.qr(rng.normal(size=(f, p)))[0]
        while True:
            for _ in range(6):
                V = np.linalg.qr(fac.solve(V, refine=False))[0]
            w, Z = np.linalg.eigh(V.T @ (K @ V))
            if w[nz - 1] <= lam_tol:
                break
            if p >= largest:
                raise RankError(f"the null vectors did not converge ({nz} eigenvalues of BᵀB "
                                "below the tolerance and others close above it); use the "
                                "dense path (raise dense_limit) or another tolerance")
            grow = min(2 * p, largest) - p
            V = np.linalg.qr(np.hstack([V @ Z, rng.normal(size=(f, grow))]))[0]
            p += grow
        vals, vecs = w, V @ Z
    kept = float(np.sqrt(max(vals[nz], 0.0))) if nz < vals.size else float("nan")
    dropped = float(np.sqrt(max(vals[nz - 1], 0.0))) if nz > 0 else float("nan")
    log.info("sparse rank (%s): %d near-zero eigenvalues of BᵀB below %.3g", fac.backend, nz,
             lam_tol)
    return Rank(rank=f - nz, null=vecs[:, :nz], left_null=None,
                tolerance=float(np.sqrt(lam_tol)), smallest_kept=kept,
                largest_dropped=dropped, backend=fac.backend)


def stiffness_null_space(Kff, max_vectors: int = 12) -> np.ndarray:
    """Mechanism modes of a positive semi-definite stiffness K_ff.

    The stiffness is scaled by its diagonal (``D^-1/2 K D^-1/2``, largest eigenvalue O(1));
    eigenvalues below :data:`NULL_TOLERANCE` are mechanisms.  Dense ``eigh`` up to
    :data:`DENSE_LIMIT` DOFs, else shift-invert ``eigsh`` for at most ``max_vectors`` modes.

    Parameters
    ----------
    Kff : sparse matrix or FreeBlock, shape (n, n)

    Returns
    -------
    ndarray, shape (n, r)
        Mechanism modes in the original (unscaled) DOFs, each of unit max-norm.

    Examples
    --------
    A free spring has one rigid-body mode:

    >>> np.abs(stiffness_null_space(sp.csr_matrix([[1.0, -1.0], [-1.0, 1.0]]))).ravel().tolist()
    [1.0, 1.0]
    """
    d = Kff.diagonal().astype(float)
    zero = d <= 0
    dd = np.where(zero, 1.0, d)
    s = 1.0 / np.sqrt(dd)
    Kff = Kff if sp.issparse(Kff) else Kff.tocsr()
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
