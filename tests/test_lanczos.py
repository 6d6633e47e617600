# SPDX-License-Identifier: MIT
"""Shift-invert Lanczos (trussfe.linalg.eigen) against closed forms and other eigen-solvers."""
from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from trussfe.fem import modal
from trussfe.linalg import factor
from trussfe.linalg.eigen import shift_invert_lanczos


def spring_chain(n: int) -> sp.csc_matrix:
    """Fixed–free chain of n unit springs: tridiag(−1, 2, −1) with a last diagonal of 1."""
    main = np.full(n, 2.0)
    main[-1] = 1.0
    return sp.diags([-np.ones(n - 1), main, -np.ones(n - 1)], [-1, 0, 1], format="csc")


def test_spring_chain_closed_form():
    """Unit masses: λ_k = 4 sin²((2k − 1)π / (2(2n + 1))) (fixed–free discrete string)."""
    n, count = 3000, 8
    K = spring_chain(n)
    lam, V = shift_invert_lanczos(spla.splu(K).solve, sp.identity(n, format="csr"), count)
    k = np.arange(1, count + 1)
    exact = 4.0 * np.sin((2 * k - 1) * np.pi / (2 * (2 * n + 1))) ** 2
    np.testing.assert_allclose(lam, exact, rtol=1e-10)
    np.testing.assert_allclose(V.T @ V, np.eye(count), atol=1e-10)      # M-orthonormal
    np.testing.assert_allclose((K @ V - V * lam) / lam, 0.0, atol=1e-9)  # eigen-residual


def test_shifted_generalized_problem_against_dense():
    """Consistent-mass chain (M = tridiag(1, 4, 1)/6) with a shift between eigenvalues' floor
    and the lowest one: the same pairs as a dense generalized eigh."""
    n, count, sigma = 400, 6, -1e-4
    K = spring_chain(n)
    main = np.full(n, 4.0)
    main[-1] = 2.0
    M = sp.diags([np.ones(n - 1), main, np.ones(n - 1)], [-1, 0, 1], format="csr") / 6.0
    lam, V = shift_invert_lanczos(spla.splu((K - sigma * M).tocsc()).solve, M, count,
                                  sigma=sigma)
    ref = sla.eigh(K.toarray(), M.toarray(), eigvals_only=True, subset_by_index=[0, count - 1])
    np.testing.assert_allclose(lam, ref, rtol=1e-10)
    np.testing.assert_allclose(V.T @ (M @ V), np.eye(count), atol=1e-10)


def test_massless_dofs_have_no_effect():
    """Every second DOF massless (singular M): the finite eigenvalues are those of the
    statically condensed problem (dense reference), none is spurious."""
    n, count = 600, 5
    K = spring_chain(n).tocsr()
    m = np.where(np.arange(n) % 2 == 1, 1.0, 0.0)
    lam, _ = shift_invert_lanczos(spla.splu(K.tocsc()).solve, sp.diags(m, format="csr"), count)
    Kd = K.toarray()
    a, b = np.flatnonzero(m == 0), np.flatnonzero(m > 0)
    condensed = Kd[np.ix_(b, b)] - Kd[np.ix_(b, a)] @ np.linalg.solve(Kd[np.ix_(a, a)],
                                                                        Kd[np.ix_(a, b)])
    ref = np.linalg.eigvalsh(condensed)[:count]
    np.testing.assert_allclose(lam, ref, rtol=1e-10)


def _four_chains(n: int = 500):
    """Four identical, uncoupled fixed–free spring chains: every eigenvalue is quadruple."""
    K = sp.block_diag([spring_chain(n)] * 4, format="csc")
    k = np.arange(1, 4)
    exact = np.repeat(4.0 * np.sin((2 * k - 1) * np.pi / (2 * (2 * n + 1))) ** 2, 4)
    return K, sp.identity(4 * n, format="csr"), exact


def test_missed_copy_of_multiple_eigenvalue_falls_back():
    """Quadruple eigenvalues, 12 pairs: the single-vector iteration converges with only three
    copies of the third eigenvalue; the check on the complement flags it (None), and
    generalized_eigen then gets all twelve from ARPACK (closed form, as above)."""
    K, M, exact = _four_chains()
    lu = spla.splu(K)
    assert shift_invert_lanczos(lu.solve, M, 12) is None
    lam, _ = modal.generalized_eigen(K, M, 12, factor=factor(K, "spd"))
    np.testing.assert_allclose(lam, exact, rtol=1e-10)


def test_multiple_eigenvalue_cut_by_count_is_accepted():
    """10 of the quadruple eigenvalues: the cut falls inside the third quadruplet, the copies
    left out equal the last one returned, so the pairs are accepted as they are."""
    K, M, exact = _four_chains()
    lam, V = shift_invert_lanczos(spla.splu(K).solve, M, 10)
    np.testing.assert_allclose(lam, exact[:10], rtol=1e-10)
    np.testing.assert_allclose(V.T @ V, np.eye(10), atol=1e-10)


def test_not_converged_returns_none():
    """A Krylov space too small for the wanted pairs gives None (the caller falls back)."""
    n = 500
    K = spring_chain(n)
    assert shift_invert_lanczos(spla.splu(K).solve, sp.identity(n, format="csr"), 10,
                                max_steps=12) is None


def test_modal_chain_agrees_with_arpack(monkeypatch):
    """solve_modes on a 100-bay chain (1,800 free DOFs: the sparse path) gives the same
    frequencies and shapes with the Lanczos iteration as with ARPACK on the same factor."""
    from trussfe.models import double_octahedral_chain

    s = double_octahedral_chain(100)
    fast = modal.solve_modes(s, count=8)
    monkeypatch.setattr(modal, "shift_invert_lanczos", lambda *a, **k: None)
    slow = modal.solve_modes(s, count=8)
    assert fast.fe.free.size > modal.DENSE_MODAL_LIMIT
    np.testing.assert_allclose(fast.frequencies_hz, slow.frequencies_hz, rtol=1e-9)
    # shapes up to the sign convention both apply; the pairs of equal bending frequencies
    # may rotate within their plane, so compare the spanned subspaces
    Mff = modal.free_submatrix(modal.mass_matrix(fast.fe), fast.fe.free)
    A, B = fast.shapes[fast.fe.free], slow.shapes[slow.fe.free]
    cross = A.T @ (Mff @ B)
    np.testing.assert_allclose(np.linalg.svd(cross, compute_uv=False), 1.0, atol=1e-6)


@pytest.mark.parametrize("count", [0, 11])
def test_impossible_counts(count):
    """No pairs, or more pairs than the order of the matrices: None."""
    assert shift_invert_lanczos(lambda b: b, sp.identity(10, format="csr"), count) is None
