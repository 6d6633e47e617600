"""Direct solvers of indeterminate space grids: PARDISO's Cholesky against SuperLU, its
singularity policy, and the automatic choice between the banded and the general sparse
factorisation (trussfe.linalg.factor).

References: SuperLU's LU (an independent factorisation) for the grid (the member forces of
the large grids against OpenSeesPy are in ``benchmarks/bench_static.py``); closed forms for the small matrices (a diagonal
matrix, a matrix of rank one); the bandwidth bound is checked against reverse Cuthill–McKee,
which any bound must not exceed.  Every ``solve_static`` here is checked for global
equilibrium by ``tests/conftest.py``.
"""
import numpy as np
import pytest
import scipy.sparse as sp
from numpy.testing import assert_allclose
from scipy.sparse.csgraph import reverse_cuthill_mckee

from trussfe.fem import discretise
from trussfe.fem.static import solve_static
from trussfe.linalg import factor, free_submatrix
from trussfe.linalg.banded import bandwidth_lower_bound
from trussfe.linalg.factor import BANDED_MAX_BANDWIDTH, BANDED_MIN_DOF, PARDISO_MIN_DOF
from trussfe.linalg.pardiso import available as pardiso_available
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.models import double_octahedral_chain

needs_pardiso = pytest.mark.skipif(not pardiso_available(), reason="pypardiso not installed")

ALUMINIUM = Material("aluminium", E=71.0e9, G=26.2e9, density=2711.5)
TUBE = Section.tube("tube", 0.01905, 0.016)


def space_grid(nx: int):
    """Square-on-square double-layer grid of nx × nx cells (1 m, depth 0.7071 m), the four
    top corners pinned, 1 kN down at every top node: statically indeterminate."""
    n1 = nx + 1
    ix, iy = np.meshgrid(np.arange(n1), np.arange(n1), indexing="ij")
    top = np.column_stack([ix.ravel(), iy.ravel(), np.zeros(ix.size)]).astype(float)
    bx, by = np.meshgrid(np.arange(nx), np.arange(nx), indexing="ij")
    bot = np.column_stack([bx.ravel() + 0.5, by.ravel() + 0.5, np.full(bx.size, -0.7071)])
    tid = lambda i, j: i * n1 + j  # noqa: E731
    bid = lambda i, j: n1 * n1 + i * nx + j  # noqa: E731
    members = []
    i, j = np.meshgrid(np.arange(nx), np.arange(n1), indexing="ij")
    members += [np.column_stack([tid(i, j).ravel(), tid(i + 1, j).ravel()]),
                np.column_stack([tid(j, i).ravel(), tid(j, i + 1).ravel()])]
    i, j = np.meshgrid(np.arange(nx - 1), np.arange(nx), indexing="ij")
    members += [np.column_stack([bid(i, j).ravel(), bid(i + 1, j).ravel()]),
                np.column_stack([bid(j, i).ravel(), bid(j, i + 1).ravel()])]
    i, j = np.meshgrid(np.arange(nx), np.arange(nx), indexing="ij")
    b = bid(i, j).ravel()
    for di, dj in ((0, 0), (1, 0), (0, 1), (1, 1)):
        members.append(np.column_stack([b, tid(i + di, j + dj).ravel()]))
    corners = (tid(0, 0), tid(nx, 0), tid(0, nx), tid(nx, nx))
    return build_structure(np.vstack([top, bot]), np.vstack(members), section=TUBE,
                           material=ALUMINIUM, supports={c: "xyz" for c in corners},
                           loads={k: [0.0, 0.0, -1000.0] for k in range(top.shape[0])},
                           name=f"grid {nx}x{nx}")


def _free_stiffness(structure):
    fe = discretise(structure, "truss")
    K = fe.stiffness().tocsr()
    return free_submatrix(K, fe.free), fe


@needs_pardiso
def test_pardiso_cholesky_grid_equals_superlu():
    """The 12 × 12 grid (1,011 free DOFs) solved by PARDISO's Cholesky and by SuperLU's LU:
    displacements agree to 1e-9 of the largest, member forces to 1e-9 of the largest (the
    grid's condition number is ~1e7, so agreement to ~1e-9 is what double precision gives);
    both in global equilibrium (conftest)."""
    s = space_grid(12)
    chol = solve_static(s, "truss", backend="pardiso", self_weight=False)
    lu = solve_static(s, "truss", backend="superlu", self_weight=False)
    assert chol.backend == "pardiso" and lu.backend == "superlu"
    assert_allclose(chol.u, lu.u, rtol=0, atol=1e-9 * np.abs(lu.u).max())
    N = np.abs(lu.axial_force).max()
    assert_allclose(chol.axial_force, lu.axial_force, rtol=0, atol=1e-9 * N)


@needs_pardiso
def test_pardiso_cholesky_reports_pivots_and_inertia():
    """diag(4, 9, 16): PARDISO's Cholesky returns the pivots 4, 9, 16 (pivot ratio 0.25,
    inertia 0, det > 0) and solves exactly."""
    fac = factor(sp.csr_matrix(np.diag([4.0, 9.0, 16.0])), "spd", "pardiso")
    assert fac.backend == "pardiso" and fac.inertia == 0 and fac.determinant_sign == 1
    assert fac.pivot_ratio == pytest.approx(0.25)
    assert_allclose(fac.solve(np.array([4.0, 9.0, 16.0])), [1.0, 1.0, 1.0], rtol=1e-15)


@needs_pardiso
@pytest.mark.parametrize("eps", [0.0, 1e-15])
def test_pardiso_cholesky_singular_matrix_is_flagged(eps):
    """[[1, 1], [1, 1 + ε]] has the pivots 1 and ε: exactly singular (ε = 0, Cholesky stops
    and the LDLᵀ reports a perturbed pivot) or below the one pivot policy (ε = 1e-15 < 1e-14
    of the largest): singular either way, never solved."""
    A = sp.csr_matrix([[1.0, 1.0], [1.0, 1.0 + eps]])
    fac = factor(A, "spd", "pardiso", singular="flag")
    assert fac.is_singular


@needs_pardiso
def test_pardiso_indefinite_spd_request_falls_back_to_ldlt():
    """A matrix said to be positive definite that is not, diag(2, −1, 3): Cholesky stops at
    the negative pivot, the LDLᵀ takes over and reports one negative eigenvalue, and the
    solution is exact."""
    fac = factor(sp.csr_matrix(np.diag([2.0, -1.0, 3.0])), "spd", "pardiso")
    assert fac.inertia == 1
    assert_allclose(fac.solve(np.array([2.0, 1.0, 3.0])), [1.0, -1.0, 1.0], rtol=1e-14)


def test_bandwidth_lower_bound_is_a_bound():
    """The bound from one breadth-first search never exceeds the half-bandwidth that reverse
    Cuthill–McKee reaches, and rejects a 60 × 60 grid for the band (above
    BANDED_MAX_BANDWIDTH) while a 300-bay chain stays below it."""
    Kg, _ = _free_stiffness(space_grid(60))
    Kc, _ = _free_stiffness(double_octahedral_chain(300))
    for K in (Kg, Kc):
        p = reverse_cuthill_mckee(K, symmetric_mode=True)
        inv = np.empty_like(p)
        inv[p] = np.arange(p.size)
        C = K.tocoo()
        assert bandwidth_lower_bound(K) <= np.max(np.abs(inv[C.row] - inv[C.col]))
    assert bandwidth_lower_bound(Kg) > BANDED_MAX_BANDWIDTH
    assert bandwidth_lower_bound(Kc) < BANDED_MAX_BANDWIDTH


def test_bandwidth_lower_bound_uses_the_eccentricity():
    """The bound is ⌈(n − 1)/(2e)⌉ with e the eccentricity of vertex 0, here from scipy's
    unweighted shortest paths: for a grid (a short path of predecessors, walked one by one)
    and for a path longer than WALK_STEPS (depths taken by pointer doubling)."""
    from scipy.sparse.csgraph import shortest_path
    from trussfe.linalg.banded import WALK_STEPS
    Kg, _ = _free_stiffness(space_grid(20))
    path = sp.csr_matrix(sp.diags([1.0, 2.0, 1.0], [-1, 0, 1], shape=(3 * WALK_STEPS,) * 2))
    for K in (Kg, path):
        e = int(shortest_path(abs(K), indices=0, unweighted=True).max())
        assert bandwidth_lower_bound(K) == int(np.ceil((K.shape[0] - 1) / (2 * e)))


def test_auto_rule_bands_a_long_chain_and_not_a_grid():
    """The automatic rule (no timing): a 300-bay chain (≥ BANDED_MIN_DOF unknowns, narrow)
    gets the banded Cholesky; a 60 × 60 grid (≥ PARDISO_MIN_DOF unknowns, wide) gets the
    general sparse factorisation — PARDISO's Cholesky where it is installed, SuperLU
    otherwise."""
    Kc, _ = _free_stiffness(double_octahedral_chain(300))
    assert Kc.shape[0] >= BANDED_MIN_DOF
    assert factor(Kc, "spd").backend == "banded"
    Kg, _ = _free_stiffness(space_grid(60))
    assert Kg.shape[0] >= PARDISO_MIN_DOF
    fac = factor(Kg, "spd")
    assert fac.backend == ("pardiso" if pardiso_available() else "superlu")
    if fac.backend == "pardiso":
        assert fac.inertia == 0 and np.isfinite(fac.pivot_ratio)


def test_truss_width_bound_below_the_band_and_above_it_for_a_grid():
    """The truss band path's bound from sampled bars (trussfe.fem.truss_band) never exceeds
    the half-bandwidth of the layout it then builds for a 300-bay chain, and exceeds the
    32 of a kept DOF order for a 20 × 20 grid, whose band path gives up (None)."""
    from trussfe.fem.truss_band import _width_lower_bound, truss_band_layout

    def bound(structure):
        fe = discretise(structure, "truss")
        new = np.full(fe.n_dof, -1)
        new[fe.free] = np.arange(fe.free.size)
        ndof = new[fe.node_dofs[:, :3]]
        return _width_lower_bound(ndof, structure.connectivity, structure.coords[:, :3]), fe

    b, fe = bound(double_octahedral_chain(300))
    layout = truss_band_layout(fe, BANDED_MAX_BANDWIDTH)
    assert layout is not None and 0 < b <= layout.bandwidth
    b, fe = bound(space_grid(20))
    assert b > 32 and truss_band_layout(fe, BANDED_MAX_BANDWIDTH) is None
