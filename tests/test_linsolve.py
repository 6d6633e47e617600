"""Sparse linear solvers (trussfe.fem.linsolve): accuracy and singularity detection."""
import numpy as np
import pytest
import scipy.sparse as sp
from numpy.testing import assert_allclose

from trussfe.fem.linsolve import SingularMatrixError, factorize, pardiso_available

BACKENDS = ["superlu"] + (["pardiso"] if pardiso_available() else [])


def _spring_chain(n, grounded=True):
    """Stiffness of n unit springs in series; grounded at the first node when asked."""
    main = np.full(n, 2.0)
    main[-1] = 1.0
    if not grounded:
        main[0] = 1.0
    return sp.diags([main, -np.ones(n - 1), -np.ones(n - 1)], [0, 1, -1], format="csr")


@pytest.mark.parametrize("backend", BACKENDS)
def test_chain_tip_displacement(backend):
    """A unit load at the free end of n unit springs in series moves every node k by k."""
    n = 50
    f = np.zeros(n)
    f[-1] = 1.0
    u = factorize(_spring_chain(n), backend).solve(f)
    assert_allclose(u, np.arange(1, n + 1), rtol=1e-12)


@pytest.mark.parametrize("backend", BACKENDS)
def test_floating_chain_is_singular(backend):
    """An ungrounded spring chain has a rigid-body mode: its stiffness is singular."""
    with pytest.raises(SingularMatrixError):
        factorize(_spring_chain(30, grounded=False), backend)


@pytest.mark.parametrize("backend", BACKENDS)
def test_many_right_hand_sides(backend):
    """One factorisation solves several load cases (columns) at once."""
    K = _spring_chain(20)
    F = np.random.default_rng(1).normal(size=(20, 3))
    U = factorize(K, backend).solve(F)
    assert_allclose(K @ U, F, rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("backend", BACKENDS)
def test_symmetric_singular_and_indefinite(backend):
    """``symmetric=True`` is a hint: a singular stiffness is still refused, and an indefinite but
    regular matrix is still solved (LU fallback).  [[1, 2], [2, 1]] x = [3, 3] → x = [1, 1]."""
    with pytest.raises(SingularMatrixError):
        factorize(_spring_chain(30, grounded=False), backend, symmetric=True)
    A = sp.csr_matrix(np.array([[1.0, 2.0, 0.0], [2.0, 1.0, 0.0], [0.0, 0.0, 4.0]]))
    x = factorize(A, backend, symmetric=True).solve(np.array([3.0, 3.0, 4.0]))
    assert_allclose(x, [1.0, 1.0, 1.0], rtol=1e-12)


def test_symmetric_pardiso_solves_chain():
    """PARDISO's symmetric LDLᵀ (mtype −2): node k of a grounded chain of unit springs moves
    k under a unit tip load (analytic)."""
    if not pardiso_available():
        pytest.skip("pypardiso not installed")
    n = 40
    f = np.zeros(n)
    f[-1] = 1.0
    fac = factorize(_spring_chain(n), "pardiso", symmetric=True)
    assert_allclose(fac.solve(f), np.arange(1, n + 1), rtol=1e-12)
