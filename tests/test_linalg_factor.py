"""The factorisation contract (trussfe.linalg.factor): solutions, inertia, singularity, and the
backend-selection rule.

References: closed forms (a chain of unit springs: node k moves k under a unit tip load),
dense eigenvalue counts (numpy ``eigvalsh``) for the inertia, dense solves (numpy ``solve``)
for the agreement of the backends, and a truss that is a mechanism by construction.
"""
import numpy as np
import pytest
import scipy.sparse as sp
from numpy.testing import assert_allclose

from trussfe.fem import discretise
from trussfe.linalg import SINGULAR_PIVOT, FreeBlock, SingularMatrixError, factor
from trussfe.linalg.factor import BANDED_MAX_BANDWIDTH, BANDED_MIN_DOF
from trussfe.linalg.eigen import nearest_zero_mode
from trussfe.linalg.pardiso import available as pardiso_available
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.models import double_octahedral_chain

GENERAL = ["superlu"] + (["pardiso"] if pardiso_available() else [])
ALL = ["banded"] + GENERAL
needs_pardiso = pytest.mark.skipif(not pardiso_available(), reason="pypardiso not installed")


def _spring_chain(n, grounded=True):
    """Stiffness of n unit springs in series; grounded at the first node when asked."""
    main = np.full(n, 2.0)
    main[-1] = 1.0
    if not grounded:
        main[0] = 1.0
    return sp.diags([main, -np.ones(n - 1), -np.ones(n - 1)], [0, 1, -1], format="csr")


def _indefinite(n, seed):
    """A sparse symmetric indefinite matrix (random pattern and diagonal)."""
    rng = np.random.default_rng(seed)
    A = rng.normal(size=(n, n)) * (rng.random((n, n)) < 0.1)
    return A + A.T + np.diag(rng.normal(size=n))


@pytest.mark.parametrize("backend", ALL)
def test_chain_tip_displacement(backend):
    """A unit load at the free end of n unit springs in series moves every node k by k."""
    n = 50
    f = np.zeros(n)
    f[-1] = 1.0
    fac = factor(_spring_chain(n), "spd", backend)
    assert_allclose(fac.solve(f), np.arange(1, n + 1), rtol=1e-12)
    assert fac.backend == ("banded" if backend == "banded" else backend)


@pytest.mark.parametrize("backend", GENERAL)
@pytest.mark.parametrize("kind", ["general", "symmetric", "spd"])
def test_many_right_hand_sides(backend, kind):
    """One factorisation solves several load cases (columns) at once."""
    K = _spring_chain(20)
    F = np.random.default_rng(1).normal(size=(20, 3))
    U = factor(K, kind, backend).solve(F)
    assert_allclose(K @ U, F, rtol=1e-10, atol=1e-12)


def test_every_backend_gives_the_same_solution():
    """K_ff of a 40-bay double-octahedral chain (720 free DOFs; longer chains are so badly
    conditioned that correct solvers differ in the displacements) under its self-weight:
    banded Cholesky, SuperLU and PARDISO give the same displacements, and the dense solve of
    a small banded system agrees with all of them."""
    fe = discretise(double_octahedral_chain(40), "truss")
    K = fe.stiffness()
    block = FreeBlock(K, fe.free)
    f = fe.load_vector()[fe.free]
    sols = {}
    for backend in ALL:
        fac = factor(block, "spd", backend)
        sols[fac.backend] = fac.solve(f)
    assert {"banded", "superlu"} <= set(sols)
    ref = sols["superlu"]
    for name, u in sols.items():
        assert np.abs(u - ref).max() <= 1e-9 * np.abs(ref).max(), name
    A = _spring_chain(30) + sp.diags(np.linspace(0.1, 1.0, 30))
    b = np.random.default_rng(4).normal(size=30)
    dense = np.linalg.solve(A.toarray(), b)
    for backend in ALL:
        for kind in ("spd", "symmetric", "general"):
            assert_allclose(factor(A, kind, backend).solve(b), dense, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_inertia_equals_dense_eigenvalue_count(seed):
    """Sylvester: the negative pivots of the symmetric factorisation equal the number of
    negative eigenvalues (dense eigvalsh) of small indefinite matrices, for SuperLU and
    PARDISO; the solution solves the system."""
    A = _indefinite(60, seed)
    expected = int(np.sum(np.linalg.eigvalsh(A) < 0))
    assert 0 < expected < 60
    b = np.random.default_rng(seed).normal(size=60)
    for backend in GENERAL:
        f = factor(sp.csr_matrix(A), "symmetric", backend)
        assert f.inertia == expected, backend
        assert_allclose(A @ f.solve(b), b, atol=1e-8 * np.abs(b).max() * np.linalg.cond(A))


def test_inertia_is_a_count_or_none():
    """A positive definite banded Cholesky has inertia 0; factorisations that do not reveal
    the inertia (LU with row pivoting) say None, never a negative number."""
    n = 6000
    K = _spring_chain(n)
    assert factor(K, "spd").backend == "banded" and factor(K, "spd").inertia == 0
    for kind in ("general", "spd"):
        assert factor(K, kind, "superlu").inertia is None
    B = sp.csr_matrix(_indefinite(40, 7))
    lu = factor(B, "spd", "banded")                   # Cholesky refuses: banded LU
    assert lu.backend == "banded-lu" and lu.inertia is None


def _mechanism_truss():
    """A plane truss of two square bays whose second bay has no diagonal: a sway mechanism
    of the top right node pair (closed form: one independent mechanism)."""
    coords = [[0, 0], [1, 0], [2, 0], [0, 1], [1, 1], [2, 1]]
    bars = [(0, 1), (1, 2), (3, 4), (4, 5), (0, 3), (1, 4), (2, 5), (0, 4)]
    return build_structure(coords, bars, section=Section("a", 1e-4),
                           material=Material("s", E=2e11, G=8e10),
                           supports={0: "xy", 3: "x"}, loads={5: [0.0, -1000.0]})


@pytest.mark.parametrize("backend", ALL)
@pytest.mark.parametrize("kind", ["spd", "symmetric", "general"])
def test_mechanism_is_singular(backend, kind):
    """The stiffness of a mechanism is singular for every backend and kind: flagged with
    ``singular="flag"`` (and then it refuses to solve), raised by default.  So is an
    ungrounded spring chain (a rigid-body mode)."""
    fe = discretise(_mechanism_truss(), "truss")
    Kff = fe.stiffness()[fe.free][:, fe.free].tocsr()
    for A in (Kff, _spring_chain(30, grounded=False)):
        fac = factor(A, kind, backend, singular="flag")
        assert fac.is_singular
        with pytest.raises(SingularMatrixError):
            fac.solve(np.ones(A.shape[0]))
        with pytest.raises(SingularMatrixError):
            factor(A, kind, backend)


@pytest.mark.parametrize("backend", ["banded", "superlu"])
def test_one_pivot_tolerance(backend):
    """The same relative pivot threshold for every backend that returns pivots: a diagonal
    matrix with a pivot ratio ten times above SINGULAR_PIVOT is regular, ten times below
    singular."""
    for kind in ("spd", "symmetric", "general"):
        ok = factor(sp.diags([1.0, 2.0, 10 * SINGULAR_PIVOT], format="csr"), kind, backend,
                    singular="flag")
        assert not ok.is_singular and ok.pivot_ratio == pytest.approx(5 * SINGULAR_PIVOT)
        bad = factor(sp.diags([1.0, 2.0, 0.1 * SINGULAR_PIVOT], format="csr"), kind, backend,
                     singular="flag")
        assert bad.is_singular


def test_backend_rule():
    """One rule: ``auto`` bands an SPD system from BANDED_MIN_DOF unknowns up to
    BANDED_MAX_BANDWIDTH, never a symmetric-indefinite or general one; else SuperLU below
    PARDISO_MIN_DOF."""
    small = _spring_chain(100)
    big = _spring_chain(BANDED_MIN_DOF)
    assert factor(small, "spd").backend == "superlu"
    assert factor(big, "spd").backend == "banded"
    assert factor(big, "symmetric").backend == "superlu"
    assert factor(big, "general").backend == "superlu"
    # a square grid Laplacian of m × m nodes: no ordering narrows its half-bandwidth much
    # below m, above the limit
    m = BANDED_MAX_BANDWIDTH + 7
    L = sp.diags([-np.ones(m - 1), 2.0 * np.ones(m), -np.ones(m - 1)], [-1, 0, 1])
    A = (sp.kronsum(L, L) + 1e-3 * sp.identity(m * m)).tocsr()
    assert A.shape[0] >= BANDED_MIN_DOF
    assert factor(A, "spd").backend == "superlu"
    assert factor(A, "spd", "banded").backend == "banded"
    with pytest.raises(ValueError):
        factor(small, "spd", "lapack")
    with pytest.raises(ValueError):
        factor(small, "hermitian")


@needs_pardiso
def test_symmetric_pardiso_solves_chain():
    """PARDISO on a positive definite matrix (its Cholesky, mtype 2): node k of a grounded
    chain of unit springs moves k under a unit tip load (analytic), with inertia 0."""
    n = 40
    f = np.zeros(n)
    f[-1] = 1.0
    fac = factor(_spring_chain(n), "spd", "pardiso")
    assert_allclose(fac.solve(f), np.arange(1, n + 1), rtol=1e-12)
    assert fac.inertia == 0


def test_nearest_zero_mode_is_eigenvector_nearest_zero():
    """nearest_zero_mode returns the eigenpair of smallest |λ| (dense reference)."""
    A = np.diag([5.0, -0.01, 2.0, 0.3])
    w, v = nearest_zero_mode(sp.csr_matrix(A))
    assert w == pytest.approx(-0.01)
    assert abs(v[1]) == pytest.approx(1.0)


def test_linalg_sits_below_the_solvers():
    """trussfe.linalg imports nothing from the mechanics, the solvers or the command line:
    every trussfe import of its modules stays inside the package (read from the source)."""
    import ast
    from pathlib import Path

    import trussfe.linalg

    for path in Path(trussfe.linalg.__file__).parent.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom):
                assert node.level <= 1, (path.name, node.module)
                assert node.level == 1 or not (node.module or "").startswith("trussfe"), \
                    (path.name, node.module)
            elif isinstance(node, ast.Import):
                assert not any(a.name.startswith("trussfe") for a in node.names), path.name


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_determinant_sign_and_transposed_solve(seed):
    """The sign of det A from the pivots and the permutations' parity equals numpy's slogdet
    sign on random sparse nonsymmetric matrices; the transposed solve solves Aᵀ x = b (dense
    reference); symmetric factorisations give (−1)^inertia."""
    rng = np.random.default_rng(seed)
    n = 50
    A = rng.normal(size=(n, n)) * (rng.random((n, n)) < 0.15) + np.diag(rng.normal(size=n))
    b = rng.normal(size=n)
    f = factor(sp.csr_matrix(A), "general", "superlu")
    assert f.determinant_sign == int(np.linalg.slogdet(A)[0])
    assert_allclose(A.T @ f.solve(b, transpose=True), b, atol=1e-8 * np.linalg.cond(A))
    S = _indefinite(n, seed)
    g = factor(sp.csr_matrix(S), "symmetric", "superlu")
    assert g.determinant_sign == int(np.linalg.slogdet(S)[0]) == (-1) ** g.inertia
    assert factor(sp.csr_matrix([[1.0, 2.0], [2.0, 4.0]]), "general",
                  singular="flag").determinant_sign == 0
