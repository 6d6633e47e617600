"""The null vectors of the sparse rank path (trussfe.linalg.matrix_rank above its dense limit)
when singular values of B lie just above the rank tolerance.

The inverse iteration on ``BᵀB − τ² I`` is drawn towards eigenvalues in (τ², 2τ²), which are
nearer its shift than the null ones; the null vectors returned must still span the null
space (or the path must refuse).

References: matrices ``B = U diag(s) Vᵀ`` built from random orthogonal ``U``, ``V`` (numpy
``qr``), whose null space is the span of the columns of ``V`` at the zero entries of ``s``
(closed form), and scipy.linalg.null_space.
"""
import numpy as np
import pytest
import scipy.linalg as sla
import scipy.sparse as sp

from trussfe.linalg import RankError, matrix_rank

F = 60


def _orthogonal(seed):
    rng = np.random.default_rng(seed)
    return (np.linalg.qr(rng.normal(size=(F, F)))[0],
            np.linalg.qr(rng.normal(size=(F, F)))[0])


def _built(U, V, s):
    return U @ np.diag(s) @ V.T


@pytest.mark.parametrize("seed", [0, 1])
def test_null_vectors_span_the_null_space_beside_a_cluster_above_the_tolerance(seed):
    """B with two zero singular values and four at 1.2 × the path's tolerance τ (the rest in
    [1, 2]): rank 58, and the two null vectors span the columns of V at the zero singular
    values (closed form; also scipy.linalg.null_space of B) — not the directions of the
    cluster, whose ‖B v‖ = 1.2 τ lies above the tolerance."""
    U, V = _orthogonal(seed)
    s = np.linspace(1.0, 2.0, F)
    s[:2] = 0.0
    tau = matrix_rank(sp.csr_matrix(_built(U, V, s)), dense_limit=5,
                      backend="superlu").tolerance
    s[2:6] = 1.2 * tau
    B = _built(U, V, s)
    r = matrix_rank(sp.csr_matrix(B), dense_limit=5, backend="superlu")
    assert r.rank == F - 2
    null = V[:, :2]
    assert np.linalg.norm(r.null - null @ (null.T @ r.null)) < 1e-4
    ref = sla.null_space(B, rcond=1e-9)
    assert ref.shape[1] == 2
    assert np.linalg.norm(r.null - ref @ (ref.T @ r.null)) < 1e-4
    assert np.linalg.norm(B @ r.null, axis=0).max() <= r.tolerance
    assert r.largest_dropped <= r.tolerance


def test_null_vectors_are_refused_rather_than_wrong_beside_a_wide_cluster():
    """B with one zero singular value and 58 at 1.2 τ: the null vector returned, if any,
    is the column of V at the zero singular value (closed form); otherwise the sparse path
    refuses with RankError."""
    U, V = _orthogonal(2)
    s = np.linspace(1.0, 2.0, F)
    s[0] = 0.0
    tau = matrix_rank(sp.csr_matrix(_built(U, V, s)), dense_limit=5,
                      backend="superlu").tolerance
    s[1:-1] = 1.2 * tau
    B = _built(U, V, s)
    try:
        r = matrix_rank(sp.csr_matrix(B), dense_limit=5, backend="superlu")
    except RankError:
        return
    assert r.rank == F - 1
    assert abs(abs(float(V[:, 0] @ r.null[:, 0])) - 1.0) < 1e-6
