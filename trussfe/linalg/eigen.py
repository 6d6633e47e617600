# SPDX-License-Identifier: MIT
"""Eigen-solvers: shift-invert Lanczos for ``K φ = λ M φ`` and the eigenpair of a symmetric
matrix nearest zero.

A plain Lanczos iteration with full reorthogonalisation in the ``M`` inner product on the
operator ``(K − σM)⁻¹ M`` (Ericsson & Ruhe's spectral transformation): the operator is
self-adjoint in that inner product, and its largest eigenvalues ``μ = 1/(λ − σ)`` are the
eigenvalues ``λ`` nearest ``σ`` from above.  Every step costs one solve with the given
factorisation, one product with ``M`` and the reorthogonalisation; with a shift at or below
the lowest eigenvalue the wanted modes of a structure converge within a few dozen steps, so
no restart is needed.  When they have not converged within ``max_steps`` (clustered
spectra), :func:`shift_invert_lanczos` returns ``None`` and the caller falls back on ARPACK
(``scipy.sparse.linalg.eigsh``), which restarts implicitly.

Against ARPACK on the same factorisation this saves most of the overhead around the solves:
ARPACK's generalized mode asks for about three ``M`` products per solve and its
reorthogonalisation runs vector by vector (10,000-bay chain, 180k DOFs, 10 modes:
0.9 s → 0.4 s, benchmarks/bench_modal.py).
"""
from __future__ import annotations

import logging
from typing import Callable

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

log = logging.getLogger(__name__)

#: Relative residual bound ``|β_m s_mi| ≤ tol |μ_i|`` at which a Ritz pair is converged.
#: The eigenvalue error is of the order of the square of the residual over the gap: on a
#: 87k-DOF space grid 1e-10 and 1e-12 give eigenvalues equal to 6e-14 (27 against 37 solves).
LANCZOS_TOL = 1e-10


def shift_invert_lanczos(solve: Callable[[np.ndarray], np.ndarray], M: sp.spmatrix,
                         count: int, sigma: float = 0.0, tol: float = LANCZOS_TOL,
                         max_steps: int | None = None, seed: int = 0
                         ) -> tuple[np.ndarray, np.ndarray] | None:
    """The ``count`` eigenpairs of ``K φ = λ M φ`` nearest ``σ`` from above.

    Parameters
    ----------
    solve : callable
        ``x = solve(b)`` solves ``(K − σM) x = b`` (a factorisation computed once).
    M : sparse matrix, shape (n, n)
        Symmetric positive semi-definite mass.
    count : int
        Number of eigenpairs.
    sigma : float
        The shift of the factorisation; it must lie below the wanted eigenvalues.
    tol : float
        Convergence bound on the Ritz residual relative to the Ritz value ``μ``.
    max_steps : int, optional
        Largest Krylov dimension (default ``max(3 count + 30, 60)``, at most ``n``).
    seed : int
        Seed of the random starting vector (results are reproducible).

    Returns
    -------
    (eigenvalues, vectors) or None
        ``eigenvalues`` ascending, shape (count,); ``vectors`` M-orthonormal, shape
        (n, count).  None when the pairs did not converge within ``max_steps`` or the
        iteration broke down before finding ``count`` of them.

    Notes
    -----
    The starting vector is ``(K − σM)⁻¹ M r`` of a random ``r``, which removes components
    along massless DOFs (infinite λ).  Each new vector is orthogonalised against all the
    previous ones in the ``M`` inner product after the three-term recurrence (classical
    Gram–Schmidt, repeated once when more than half of what the three-term recurrence left cancels — Daniel, Gragg, Kaufman &
    Stewart's criterion).  Converged pairs are accepted only when a short Lanczos run on the
    complement of their span finds no eigenvalue above the smallest accepted one
    (:func:`_missed_copy`: copies of multiple eigenvalues).

    Examples
    --------
    Two unit masses on springs 2, −1 (fixed–free–free chain of stiffness 1):

    >>> import scipy.sparse as sp
    >>> from scipy.linalg import solve
    >>> K = np.array([[2.0, -1.0], [-1.0, 1.0]])
    >>> lam, V = shift_invert_lanczos(lambda b: solve(K, b), sp.identity(2), 2)
    >>> np.round(lam, 6).tolist()          # (3 ∓ √5)/2
    [0.381966, 2.618034]
    """
    n = M.shape[0]
    count = int(count)
    if count < 1 or count > n:
        return None
    m_max = min(n, max_steps if max_steps is not None else max(3 * count + 30, 60))
    Q = np.empty((n, m_max + 1), order="F")     # Lanczos vectors, M-orthonormal
    MQ = np.empty((n, m_max + 1), order="F")    # and their M products (reused by the solves)
    alpha = np.zeros(m_max)
    beta = np.zeros(m_max)
    tmp = np.empty(n)
    axpy = sla.blas.daxpy

    q = solve(M @ np.random.default_rng(seed).standard_normal(n))
    Mq = M @ q
    nrm = float(np.sqrt(max(q @ Mq, 0.0)))
    if not nrm > 0.0:
        return None
    Q[:, 0], MQ[:, 0] = q / nrm, Mq / nrm
    check = min(count + 8, m_max)               # first convergence test
    for j in range(m_max):
        w = solve(MQ[:, j])
        # three-term recurrence, then one full reorthogonalisation pass against Q[:, :j+1]
        # in the M inner product to remove what round-off left.  In place through BLAS:
        # a temporary of n doubles costs more in fresh pages than the arithmetic on it.
        if j:
            axpy(Q[:, j - 1], w, a=-beta[j - 1])
        a = float(MQ[:, j] @ w)
        axpy(Q[:, j], w, a=-a)
        h = MQ[:, : j + 1].T @ w
        w -= np.matmul(Q[:, : j + 1], h, out=tmp)
        Mw = M @ w
        b2 = float(w @ Mw)
        if b2 < 0.5 * (float(h @ h) + b2):      # more than half cancelled: once more (DGKS)
            h2 = MQ[:, : j + 1].T @ w
            w -= np.matmul(Q[:, : j + 1], h2, out=tmp)
            h += h2
            Mw = M @ w
            b2 = float(w @ Mw)
        alpha[j] = a + h[j]
        b = float(np.sqrt(max(b2, 0.0)))
        beta[j] = b
        steps = j + 1
        breakdown = not b > 1e-14 * max(abs(alpha[j]), 1e-300)
        if steps >= check or breakdown or steps == m_max:
            if steps >= count:
                mu, S = sla.eigh_tridiagonal(alpha[:steps], beta[: steps - 1])
                mu, S = mu[::-1][:count], S[:, ::-1][:, :count]
                bound = np.abs(b * S[-1]) if not breakdown else np.zeros(count)
                if np.all(mu > 0) and np.all(bound <= tol * np.abs(mu)):
                    V = Q[:, :steps] @ S
                    if _missed_copy(solve, M, V, float(mu[-1]), seed + 1):
                        log.debug("Lanczos: a copy of a multiple eigenvalue was missed")
                        return None
                    lam = sigma + 1.0 / mu
                    log.debug("Lanczos: %d pairs converged in %d steps", count, steps)
                    return lam, V
            if breakdown:
                log.debug("Lanczos: invariant subspace of dimension %d < %d", steps, count)
                return None
            check = steps + 2
        np.multiply(w, 1.0 / b, out=Q[:, j + 1])
        np.multiply(Mw, 1.0 / b, out=MQ[:, j + 1])
    log.debug("Lanczos: %d pairs not converged in %d steps", count, m_max)
    return None


#: Lanczos steps of the check for missed copies of multiple eigenvalues.
CHECK_STEPS = 6


def _missed_copy(solve, M, V: np.ndarray, mu_min: float, seed: int) -> bool:
    """Whether the operator has an eigenvalue ``μ > μ_min`` outside the span of ``V``.

    A single-vector Lanczos iteration sees one direction of each eigenspace: the other copies
    of a multiple eigenvalue (exact symmetries of a structure) enter only through round-off
    and may not have grown when the wanted pairs converge — four identical uncoupled spring
    chains, 12 pairs: the fourth copy of the third eigenvalue is replaced by the fourth
    eigenvalue.  A short Lanczos run from a new random vector on the M-orthogonal complement
    of the converged vectors finds such a copy as its largest Ritz value (it is the largest
    eigenvalue there, and Ritz values approach it from below); a value above ``μ_min`` by more
    than 1e-9 flags one.  A copy equal to ``μ_min`` (a multiple eigenvalue cut by ``count``)
    changes no eigenvalue and is not flagged.
    """
    n, k = V.shape
    steps = min(CHECK_STEPS, n - k)
    if steps < 1:
        return False
    MV = M @ V

    def deflate(x):
        # V spans eigenvectors to the solver's tolerance: one pass per step keeps the
        # iteration in their complement (the start vector gets two)
        x -= V @ (MV.T @ x)
        return x

    q = deflate(deflate(solve(M @ np.random.default_rng(seed).standard_normal(n))))
    Q = np.empty((n, steps + 1), order="F")
    MQ = np.empty((n, steps + 1), order="F")
    Mq = M @ q
    nrm = float(np.sqrt(max(q @ Mq, 0.0)))
    if not nrm > 0.0:
        return False
    Q[:, 0], MQ[:, 0] = q / nrm, Mq / nrm
    alpha, beta = np.zeros(steps), np.zeros(steps)
    for j in range(steps):
        w = deflate(solve(MQ[:, j]))
        h = MQ[:, : j + 1].T @ w                 # full reorthogonalisation, one pass
        w -= Q[:, : j + 1] @ h
        alpha[j] = h[j]
        Mw = M @ w
        b = float(np.sqrt(max(float(w @ Mw), 0.0)))
        theta = sla.eigvalsh_tridiagonal(alpha[: j + 1], beta[:j]).max()
        if theta > mu_min * (1.0 + 1e-9):
            return True
        if not b > 1e-14 * abs(alpha[j]):
            return False
        beta[j] = b
        np.multiply(w, 1.0 / b, out=Q[:, j + 1])
        np.multiply(Mw, 1.0 / b, out=MQ[:, j + 1])
    return False


#: Order up to which :func:`nearest_zero_mode` solves densely.
DENSE_EIGEN_LIMIT = 600


def nearest_zero_mode(K: sp.spmatrix) -> tuple[float, np.ndarray]:
    """Eigenvalue of a symmetric ``K`` nearest zero and its unit eigenvector.

    Dense for orders up to :data:`DENSE_EIGEN_LIMIT`, shift-invert Lanczos (``eigsh``,
    σ = 0) otherwise.

    Examples
    --------
    >>> w, v = nearest_zero_mode(sp.csr_matrix(np.diag([3.0, -0.5, 2.0])))
    >>> w, np.abs(v).tolist()
    (-0.5, [0.0, 1.0, 0.0])
    """
    n = K.shape[0]
    if n <= DENSE_EIGEN_LIMIT:
        w, v = sla.eigh(K.toarray())
        i = int(np.argmin(np.abs(w)))
        return float(w[i]), v[:, i]
    w, v = spla.eigsh(sp.csc_matrix(K), k=1, sigma=0.0, which="LM")
    return float(w[0]), v[:, 0] / np.linalg.norm(v[:, 0])


class EigenNotConverged(RuntimeError):
    """An eigen-solver did not converge; the message says why and what to change (the
    solvers report it as an analysis error of their model)."""


#: Restarts of ARPACK's first try at a buckling problem before the wider second one.
ARPACK_FIRST_RESTARTS = 300
#: Lanczos vectors of the second try: more than a group of equal load factors is likely to
#: hold (every equal member of a repetitive truss buckling alike, in two planes).
ARPACK_WIDE_VECTORS = 64
#: Order up to which a buckling problem ARPACK cannot converge is solved densely.
DENSE_BUCKLING_FALLBACK = 6000


def _arpack_buckling(A: sp.csc_matrix, M: sp.csc_matrix, Minv, k: int, which: str
                     ) -> tuple[np.ndarray, np.ndarray]:
    """``k`` eigenpairs of ``A φ = μ M φ`` (``which`` end) by ARPACK, robust to clusters.

    Many equal load factors — the identical members of a repetitive truss, each buckling
    between its joints — make an eigenvalue of high multiplicity, which ARPACK's default
    number of Lanczos vectors (2k + 1) cannot resolve: it then restarts until its iteration
    limit (ten times the order).  The first try stops early; a second one keeps
    :data:`ARPACK_WIDE_VECTORS` vectors; a problem that still does not converge is solved
    densely up to :data:`DENSE_BUCKLING_FALLBACK` unknowns, and refused above.

    Raises
    ------
    EigenNotConverged
        ARPACK did not converge and the problem is too large to solve densely.
    """
    n = A.shape[0]
    try:
        return spla.eigsh(A, k=k, M=M, Minv=Minv, which=which, maxiter=ARPACK_FIRST_RESTARTS)
    except spla.ArpackNoConvergence:
        pass
    ncv = min(n - 1, max(2 * k + 1, k + ARPACK_WIDE_VECTORS))
    try:
        return spla.eigsh(A, k=k, M=M, Minv=Minv, which=which, ncv=ncv)
    except spla.ArpackNoConvergence:
        if n > DENSE_BUCKLING_FALLBACK:
            raise EigenNotConverged(f"the eigen-solver did not converge on {n:,} unknowns "
                                    "(many equal or close load factors); ask for more load "
                                    "factors (--count) to take in a whole group of equal "
                                    "ones, or use fewer subdivisions") from None
    log.info("buckling: ARPACK did not converge on %d unknowns; solved densely", n)
    return sla.eigh(A.toarray(), M.toarray())


#: Order up to which a buckling eigenproblem is solved densely (LAPACK); above it, by ARPACK.
#: Dense is also deterministic in the modes' signs (ARPACK's depend on its start vector),
#: which matters where a mode becomes an imperfection.
DENSE_BUCKLING_LIMIT = 800


def buckling_pairs(K: sp.spmatrix, Kg: sp.spmatrix, count: int, *,
                   positive_only: bool = False, solve: Callable | None = None,
                   dense_limit: int = DENSE_BUCKLING_LIMIT) -> tuple[np.ndarray, np.ndarray]:
    """Eigenpairs of the linear buckling problem ``(K + λ K_g) φ = 0``, K positive definite.

    Solved as ``−K_g φ = μ K φ`` with ``λ = 1/μ``, so that the smallest load factors are the
    largest ``|μ|`` — the end of the spectrum ARPACK converges to fastest — and ``K`` is the
    positive definite "mass".  Both finite-element models (the linear core and the
    co-rotational model about its reference state) solve their buckling problem here.

    Parameters
    ----------
    K, Kg : sparse matrix, shape (n, n)
        Elastic and geometric stiffness on the free DOFs (``Kg`` of the reference load).
    count : int
        Number of pairs wanted.
    positive_only : bool
        Only ``μ > 0`` (``λ > 0``: the reference load's own sense), ascending ``λ``; else the
        ``count`` largest ``|μ|`` of either sign, by ascending ``|λ|``.
    solve : callable, optional
        ``K⁻¹ b`` from an existing factorisation, for ARPACK's generalized mode (otherwise
        ARPACK factorises ``K`` itself).
    dense_limit : int
        Largest order solved densely.

    Returns
    -------
    mu : ndarray, shape (k,)
        ``μ = 1/λ`` in the order above (``k ≤ count``; with ``positive_only`` only the
        positive ones found, tiny ones, ``μ ≤ 1e-12 max |μ|``, excluded).
    V : ndarray, shape (n, k)
        The modes, as the eigen-solver returns them (callers scale them).

    Raises
    ------
    EigenNotConverged
        ARPACK did not converge on a problem too large to solve densely.

    Examples
    --------
    A pinned–pinned bar as two springs: K = diag(2, 2), K_g = −diag(1, 0.5):

    >>> mu, V = buckling_pairs(sp.diags([2.0, 2.0]), sp.diags([-1.0, -0.5]), 2)
    >>> (1.0 / mu).round(12).tolist()
    [2.0, 4.0]
    """
    n = K.shape[0]
    if n <= dense_limit or count >= n - 1:
        mu, V = sla.eigh(-Kg.toarray(), K.toarray())
    else:
        k = min(max(2 * count, count + 4), n - 2) if positive_only else count
        op = None if solve is None else spla.LinearOperator((n, n), matvec=solve, dtype=float)
        mu, V = _arpack_buckling(-Kg.tocsc(), K.tocsc(), op, k,
                                 "LA" if positive_only else "LM")
    if positive_only:
        pos = mu > 1e-12 * np.abs(mu).max() if mu.size else np.zeros(0, bool)
        order = np.argsort(-mu[pos])[:count]
        return mu[pos][order], V[:, pos][:, order]
    order = np.argsort(-np.abs(mu), kind="stable")[:count]
    return mu[order], V[:, order]
