"""The symmetric factorisation (``factor(A, "symmetric")``, SuperLU with diagonal pivots) when
diagonal pivoting breaks down on an indefinite matrix.

A regular matrix whose elimination in SuperLU's order meets a pivot at round-off level is
still factorised, with its inertia and solution; a matrix whose smallest eigenvalue is below
the singularity ratio is refused even when SuperLU had to pivot off the diagonal.

References: dense eigenvalues (numpy ``eigvalsh``) for the inertia and the conditioning,
dense solves (numpy ``solve``) for the solutions.
"""
import numpy as np
import pytest
import scipy.sparse as sp
from numpy.testing import assert_allclose

from trussfe.linalg import SINGULAR_PIVOT, SingularMatrixError, factor

# Eliminated in SuperLU's order (the last unknown first, then the first one), the second
# pivot is 0.9 − 0.3²/0.1, zero up to round-off: LDLᵀ with diagonal pivots breaks down
# although the matrix is well conditioned (eigenvalues −1.25, 0.0247, 3.23).
BREAKDOWN = np.array([[0.9, 2.0, 0.3],
                      [2.0, 1.0, 1.0],
                      [0.3, 1.0, 0.1]])


def test_regular_matrix_with_a_round_off_diagonal_pivot_is_factorised():
    """The 3 × 3 matrix above is regular (dense eigvalsh: smallest magnitude 0.0247, one
    negative eigenvalue): it is not refused, its inertia is 1, its determinant sign −1, and
    its solution for (1, 1, 1) and for a block of right-hand sides is numpy's solve."""
    w = np.linalg.eigvalsh(BREAKDOWN)
    assert np.abs(w).min() > 1e-3 * np.abs(w).max()          # far from singular
    f = factor(sp.csr_matrix(BREAKDOWN), "symmetric", "superlu")
    assert not f.is_singular
    assert f.inertia == int(np.sum(w < 0)) == 1
    assert f.determinant_sign == int(np.sign(np.linalg.det(BREAKDOWN))) == -1
    b = np.ones(3)
    assert_allclose(f.solve(b), np.linalg.solve(BREAKDOWN, b), rtol=1e-12)
    B = np.arange(6.0).reshape(3, 2)
    assert_allclose(f.solve(B), np.linalg.solve(BREAKDOWN, B), rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("seed", range(6))
def test_regular_indefinite_matrices_are_never_refused(seed):
    """Random sparse symmetric indefinite matrices with a zero-free spectrum (smallest
    eigenvalue magnitude above 1e-3 of the largest, dense eigvalsh) are factorised: inertia
    equal to the dense count of negative eigenvalues, solution equal to numpy's solve."""
    rng = np.random.default_rng(seed)
    done = 0
    while done < 100:
        n = int(rng.integers(2, 15))
        A = rng.normal(size=(n, n)) * (rng.random((n, n)) < 0.3)
        A = A + A.T + np.diag(rng.normal(size=n) * (rng.random(n) < 0.5))
        w = np.linalg.eigvalsh(A)
        if np.abs(w).min() <= 1e-3 * np.abs(w).max():
            continue
        done += 1
        f = factor(sp.csr_matrix(A), "symmetric", "superlu")
        assert f.inertia == int(np.sum(w < 0))
        b = np.ones(n)
        assert_allclose(A @ f.solve(b), b, atol=1e-9)


def test_off_diagonal_pivoting_keeps_the_singularity_rule():
    """diag([[0, 1], [1, 0]], 1e-20) has eigenvalues −1, 1e-20, 1 (dense eigvalsh): the
    smallest over the largest magnitude is 1e-20, below SINGULAR_PIVOT, so the symmetric
    factorisation refuses it as the general one does — although the zero diagonal makes
    SuperLU pivot off the diagonal."""
    A = np.zeros((3, 3))
    A[0, 1] = A[1, 0] = 1.0
    A[2, 2] = 1e-20
    w = np.abs(np.linalg.eigvalsh(A))
    assert w.min() / w.max() <= SINGULAR_PIVOT
    with pytest.raises(SingularMatrixError):
        factor(sp.csr_matrix(A), "general", "superlu")
    with pytest.raises(SingularMatrixError):
        factor(sp.csr_matrix(A), "symmetric", "superlu")
    assert factor(sp.csr_matrix(A), "symmetric", "superlu", singular="flag").is_singular


def test_off_diagonal_pivoting_regular_matrix():
    """[[0, 2], [2, 0]] ⊕ [3] (eigenvalues −2, 2, 3): regular, inertia 1, solution
    (1/2, 1/2, 1/3) for a right-hand side of ones (closed form)."""
    A = np.array([[0.0, 2.0, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, 3.0]])
    f = factor(sp.csr_matrix(A), "symmetric", "superlu")
    assert f.inertia == 1
    assert_allclose(f.solve(np.ones(3)), [0.5, 0.5, 1.0 / 3.0], rtol=1e-14)


def test_unsymmetric_matrix_keeps_its_inertia_unknown():
    """A slightly unsymmetric matrix given as "symmetric" whose diagonal pivots break down
    (a zero leading pivot): solved by LU with partial pivoting (numpy ``solve`` as reference),
    and its inertia is None — the eigenvalues of one triangle say nothing of it."""
    A = np.array([[0.0, 1.0, 0.0], [1.001, 2.0, 0.5], [0.0, 0.5, 3.0]])
    f = factor(sp.csr_matrix(A), "symmetric")
    assert not f.is_singular and f.inertia is None
    b = np.array([1.0, -2.0, 0.5])
    assert_allclose(f.solve(b), np.linalg.solve(A, b), rtol=1e-13)
