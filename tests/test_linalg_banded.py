# SPDX-License-Identifier: MIT
"""Band storage and banded factorisations (trussfe.linalg.banded).

References: LAPACK's band storage conventions (``dpbtrf``: ``ab[kd + i − j, j] = A[i, j]``
for i ≤ j; ``dgbtrf``: ``ab[kl + ku + i − j, j] = A[i, j]``), checked entry by entry against
the dense matrix; solutions are checked by their residuals.
"""
from __future__ import annotations

import threading

import numpy as np
import pytest
import scipy.sparse as sp
from threadpoolctl import threadpool_info

from trussfe.fem.discretisation import discretise
from trussfe.fem.solver import factorise, solve_free
from trussfe.linalg import banded
from trussfe.linalg.sparse import anchored_rows, free_submatrix
from trussfe.models import double_octahedral_chain


def _random_band(n: int, bw: int, seed: int, shift: float = 10.0) -> sp.csr_matrix:
    rng = np.random.default_rng(seed)
    A = np.zeros((n, n))
    for d in range(1, bw + 1):
        v = rng.standard_normal(n - d)
        A += np.diag(v, d) + np.diag(v, -d)
    return sp.csr_matrix(A + shift * np.eye(n))


@pytest.mark.parametrize("n,bw", [(1, 0), (2, 1), (7, 3), (40, 6), (60, 35)])
def test_band_arrays_hold_the_matrix(n, bw):
    """Both band arrays hold every entry of the (reordered) matrix where LAPACK expects it."""
    A = _random_band(n, bw, seed=n)
    if bw > banded.NATURAL_BANDWIDTH_OK:          # a scrambled numbering: RCM recovers a band
        p = np.random.default_rng(1).permutation(n)
        A = A[p][:, p].tocsr()
    L = banded.band_layout(A)
    D = A.toarray()[np.ix_(L.perm, L.perm)]
    ub, gb = L.upper_band(), L.general_band()
    b = L.bandwidth
    assert ub.flags.f_contiguous and gb.flags.f_contiguous
    for i in range(n):
        for j in range(n):
            if 0 <= j - i <= b:
                assert ub[b + i - j, j] == D[i, j]
            if abs(i - j) <= b:
                assert gb[2 * b + i - j, j] == D[i, j]
            else:
                assert D[i, j] == 0.0


def test_layout_of_free_rows_equals_layout_of_submatrix():
    """band_layout_free(K, free) = band_layout(K_ff, anchored) without forming K_ff: same
    ordering (reversed so that the supported end comes last), same entries."""
    s = double_octahedral_chain(40)
    fe = discretise(s, "truss")
    K = fe.stiffness()
    a = banded.band_layout_free(K, fe.free)
    b = banded.band_layout(free_submatrix(K, fe.free), anchored=anchored_rows(K, fe.free))
    assert a.bandwidth == b.bandwidth and np.array_equal(a.perm, b.perm)
    assert a.perm[0] == fe.free.size - 1             # the free end is eliminated first
    assert np.array_equal(a.upper_band(), b.upper_band())


def test_cholesky_and_lu_solve():
    """Cholesky for a positive definite matrix, LU for an indefinite one; residual ~ε."""
    A = _random_band(300, 5, seed=3)
    f = banded.banded_factor(A)
    x = f.solve(np.ones(300))
    assert f.kind == "banded" and np.abs(A @ x - 1.0).max() < 1e-12
    B = _random_band(300, 5, seed=3, shift=-0.5)          # indefinite
    g = banded.banded_factor(B)
    y = g.solve(np.ones(300))
    assert g.kind == "banded-lu" and np.abs(B @ y - 1.0).max() < 1e-10


@pytest.mark.parametrize("n,bw", [(1, 0), (2, 1), (5, 1), (7, 3), (30, 5), (6, 5), (40, 12)])
def test_general_band_from_upper(n, bw):
    """The LU storage copied from the upper band equals the one filled from the entries."""
    L = banded.band_layout(_random_band(n, bw, seed=n + bw))
    gb = banded.general_from_upper(L.upper_band())
    assert gb.flags.f_contiguous
    assert np.array_equal(gb, L.general_band())


def _blas_threads() -> list[int]:
    return [p["num_threads"] for p in threadpool_info() if p["user_api"] == "blas"]


def test_factor_restores_blas_threads():
    """The banded factorisations leave the BLAS thread count as they found it, also when
    called from a worker thread (as modal analysis does): library code sets no thread limit
    (the command line does, once: trussfe.threads.compute_threads)."""
    before = _blas_threads()
    banded.banded_factor(_random_band(200, 4, seed=6, shift=-0.5))
    assert _blas_threads() == before
    t = threading.Thread(target=lambda: banded.banded_factor(_random_band(200, 4, seed=6)))
    t.start()
    t.join()
    assert _blas_threads() == before


def test_static_solve_without_free_submatrix():
    """The static factorisation on the banded path uses K's free rows directly; its solution
    equals SuperLU's on the same K_ff (a 300-bay chain, 5,400 free DOFs)."""
    s = double_octahedral_chain(300)
    fe = discretise(s, "truss")
    K, f = fe.stiffness(), fe.load_vector()
    band = factorise(K, fe.free)
    ref = factorise(K, fe.free, backend="superlu")
    assert band.backend in ("banded", "banded-lu") and ref.backend == "superlu"
    u, v = solve_free(band, fe.free, f), solve_free(ref, fe.free, f)
    # forces, not displacements, are compared on a long chain (docs/fem.md)
    N1, N2 = fe.element_forces(u)[:, 1, 0], fe.element_forces(v)[:, 1, 0]
    assert np.abs(N1 - N2).max() <= 1e-6 * np.abs(N2).max()
