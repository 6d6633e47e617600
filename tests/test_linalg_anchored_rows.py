"""Which free rows of a sparse stiffness are coupled to a supported DOF
(trussfe.linalg.sparse.anchored_rows, the rows a banded factorisation orders last).

References: hand-built matrices (the coupling read off the matrix) and the dense test
``(A[free][:, fixed] != 0).any(axis=1)`` with numpy.
"""
import numpy as np
import scipy.sparse as sp

from trussfe.linalg.sparse import anchored_rows


def test_a_free_row_before_a_fixed_row_is_not_anchored_by_it():
    """DOF 0 is coupled to DOF 2 only, and the fixed DOF 1 to DOF 3 only: of the free DOFs
    0, 2, 3 only DOF 3 is anchored (read off the matrix)."""
    A = 2.0 * np.eye(4)
    A[0, 2] = A[2, 0] = -1.0
    A[1, 3] = A[3, 1] = -1.0
    assert anchored_rows(sp.csr_matrix(A), np.array([0, 2, 3])).tolist() == [False, False, True]


def test_random_patterns_match_the_dense_coupling():
    """Random symmetric sparse patterns with random supports (empty rows included): the
    anchored rows are those with a nonzero entry in a fixed column (dense numpy test)."""
    rng = np.random.default_rng(0)
    for _ in range(200):
        n = int(rng.integers(1, 25))
        A = (rng.random((n, n)) < 0.15) * rng.normal(size=(n, n))
        A = A + A.T
        free = np.flatnonzero(rng.random(n) < 0.7)
        fixed = np.setdiff1d(np.arange(n), free)
        expected = (A[np.ix_(free, fixed)] != 0).any(axis=1)
        got = anchored_rows(sp.csr_matrix(A), free)
        assert got.tolist() == expected.tolist()
