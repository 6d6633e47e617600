"""Rank and null spaces (trussfe.linalg.rank): the one routine behind the mechanism count of
the rank analysis and of the post-critical hand-over.

References: the dense SVD (numpy) for ranks, the defining property ``B N = 0`` for null
spaces, and a free spring's rigid-body mode (closed form).
"""
import numpy as np
import pytest
import scipy.linalg as sla
import scipy.sparse as sp

from trussfe.kinematics.compatibility import compatibility_matrix
from trussfe.kinematics.rank import rank_analysis
from trussfe.linalg import matrix_rank, stiffness_null_space
from trussfe.linalg.pardiso import available as pardiso_available
from trussfe.nonlinear.mechanism import mechanism_count
from trussfe.studies.postcritical import double_layer_grid


def test_sparse_rank_equals_dense_svd_rank():
    """The inertia-based rank used on large models equals the SVD rank (tolerance 1e-9) on
    double-layer grids with random bars removed, with and without mechanisms, and its null
    basis satisfies B N ≈ 0."""
    rng = np.random.default_rng(0)
    backends = ["superlu"] + (["pardiso"] if pardiso_available() else [])
    for n in (5, 7):
        s, _ = double_layer_grid(n)
        free = ~s.supports[:, :3]
        for drop in (0, 10, 40, 70):
            keep = np.ones(s.n_members, bool)
            keep[rng.choice(s.n_members, drop, replace=False)] = False
            B = compatibility_matrix(s.coords, s.connectivity[keep], free)
            sv = sla.svdvals(B.toarray())
            expected = int(np.sum(sv > 1e-9 * sv.max()))
            for backend in backends:
                r = matrix_rank(B, 1e-9, dense_limit=0, backend=backend)
                assert r.rank == expected and r.left_null is None
                assert r.null.shape == (B.shape[1], B.shape[1] - expected)
                if r.null.size:
                    assert np.abs(B @ r.null).max() < 1e-6
            d = matrix_rank(B, 1e-9)
            assert d.rank == expected and d.backend == "dense"
            assert np.abs(B.T @ d.left_null).max() < 1e-9


def test_one_rank_for_kinematics_and_hand_over():
    """The rank analysis and the post-critical mechanism count are the same routine: equal
    counts on a grid with a bottom node stripped of its diagonals (3 free motions)."""
    s, _ = double_layer_grid(5)
    free = ~s.supports[:, :3]
    keep = ~np.any(s.connectivity == 25, axis=1)
    for conn in (s.connectivity, s.connectivity[keep]):
        r = rank_analysis(s.coords, conn, free, tolerance=1e-9, dense_limit=200)
        nm, rank = mechanism_count(s.coords, conn, free)
        assert (nm, rank) == (r.mechanisms + r.rigid_body_motions, r.rank)
    assert mechanism_count(s.coords, s.connectivity[keep], free)[0] == 3


def test_stiffness_null_space_of_free_spring():
    """A free spring (k = 1 between two points on a line) has one rigid-body mode, the
    translation [1, 1]; grounded, none."""
    K = sp.csr_matrix([[1.0, -1.0], [-1.0, 1.0]])
    V = stiffness_null_space(K)
    assert V.shape == (2, 1)
    assert np.allclose(np.abs(V[:, 0]), 1.0)
    assert stiffness_null_space(K + sp.diags([1.0, 0.0])).shape[1] == 0


def test_rank_of_empty_and_full_matrices():
    """Edge cases: a matrix with no rows has rank 0 and every column free; the identity has
    full rank."""
    r = matrix_rank(np.zeros((0, 4)))
    assert r.rank == 0 and r.null.shape == (4, 4)
    assert matrix_rank(np.eye(5)).rank == 5


@pytest.mark.parametrize("tolerance", [1e-3, 1e-9])
def test_tolerance_is_relative(tolerance):
    """σ ≤ tolerance · σ_max counts as zero: singular values 1, 1e-6 give rank 1 at 1e-3 and
    rank 2 at 1e-9, whatever the scale of B."""
    for scale in (1.0, 1e6):
        B = scale * np.diag([1.0, 1e-6])
        assert matrix_rank(B, tolerance).rank == (1 if tolerance > 1e-6 else 2)
