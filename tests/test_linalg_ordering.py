"""Geometric nested dissection (trussfe.linalg.ordering) and PARDISO's Cholesky in that order.

References: an independent factorisation (SuperLU's LU through ``scipy.sparse.linalg
.spsolve``) and PARDISO's own ordering of the same matrix for the solutions; for the
ordering, the defining property of nested dissection — eliminating the unknowns of one
region never fills the other region of the same cut, so the symbolic Cholesky factor of a
2-D Laplacian in this order has O(n log n) entries against the band's O(n^1.5) — counted by
an elimination-tree count of scipy's dense Cholesky factor.  Every ``solve_static`` here is
checked for global equilibrium by ``tests/conftest.py``.
"""
import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from numpy.testing import assert_allclose

from trussfe.fem import discretise
from trussfe.fem.solver import factorise
from trussfe.fem.static import solve_static
from trussfe.linalg import factor, free_submatrix, pardiso
from trussfe.linalg.factor import PARDISO_MIN_DOF
from trussfe.linalg.ordering import Points, nested_dissection

from test_grid_solvers import needs_pardiso, space_grid


def laplacian(k: int) -> tuple[sp.csr_matrix, Points]:
    """5-point Laplacian of a k × k grid of points, one unknown per point, and the points."""
    T = sp.diags([-1.0, 2.0, -1.0], [-1, 0, 1], shape=(k, k))
    A = sp.csr_matrix(sp.kronsum(T, T))
    i, j = np.meshgrid(np.arange(k), np.arange(k), indexing="ij")
    xy = np.column_stack([j.ravel(), i.ravel()]).astype(float)       # kronsum: row-major
    return A, Points(np.arange(k * k), xy)


def factor_entries(A: sp.csr_matrix, perm: np.ndarray) -> int:
    """Entries of the Cholesky factor of P A Pᵀ (dense factor, magnitudes above round-off)."""
    L = np.linalg.cholesky(A[perm][:, perm].toarray())
    return int(np.count_nonzero(np.abs(L) > 1e-12 * np.abs(L).max()))


def test_is_a_permutation_and_separates():
    A, pts = laplacian(24)
    perm = nested_dissection(A.indptr, A.indices, pts, leaf=4)
    assert sorted(perm.tolist()) == list(range(A.shape[0]))
    # the first cut: the last-ordered unknowns are a line of the grid that splits it in two
    # components (scipy's connected components of the rest)
    from scipy.sparse.csgraph import connected_components
    line = 24                              # a cut across a 24 × 24 grid: 24 points
    rest = np.setdiff1d(np.arange(A.shape[0]), perm[-line:])
    ncomp, _ = connected_components(A[rest][:, rest], directed=False)
    assert ncomp == 2


def test_fill_is_that_of_nested_dissection():
    A, pts = laplacian(32)
    natural = factor_entries(A, np.arange(A.shape[0]))          # the band: ~ n^1.5
    nd = factor_entries(A, nested_dissection(A.indptr, A.indices, pts, leaf=4))
    assert natural > 32 ** 3 * 0.9                               # 32 rows of 32 per column
    assert nd < 0.5 * natural


def test_points_of_no_matter_order():
    # the same matrix with its unknowns renumbered at random: the same cuts
    A, pts = laplacian(16)
    rng = np.random.default_rng(1)
    q = rng.permutation(A.shape[0])
    B = sp.csr_matrix(A[q][:, q])
    pb = nested_dissection(B.indptr, B.indices, Points(pts.of_unknown[q], pts.coords), leaf=4)
    pa = nested_dissection(A.indptr, A.indices, pts, leaf=4)
    # the same first separator (the last 16 unknowns: a line across the grid)
    assert set(q[pb[-16:]].tolist()) == set(pa[-16:].tolist())
    assert len({tuple(pts.coords[k]) for k in pa[-16:]}) == 16


def test_declines_when_members_join_far_points():
    # every unknown coupled to many random far-away ones: a cut plane separates nothing
    A, pts = laplacian(50)
    rng = np.random.default_rng(0)
    n = A.shape[0]
    i, j = rng.integers(0, n, (2, 20 * n))
    C = sp.csr_matrix((np.ones(i.size), (i, j)), shape=(n, n))
    C = sp.csr_matrix(A + C + C.T)
    assert nested_dissection(C.indptr, C.indices, pts) is None
    assert nested_dissection(A.indptr, A.indices, pts) is not None


def test_dof_points_of_a_frame_with_subdivided_members():
    from trussfe.models import double_octahedral_chain
    s = double_octahedral_chain(3)
    fe = discretise(s, "pinned-beam", subdivisions=3)
    p = fe.dof_points()
    assert p.of_unknown.shape == (fe.n_dof,)
    assert np.all(p.of_unknown < s.n_nodes + fe.interior_dofs.shape[0])   # none left over
    # a joint's DOFs at the joint; an interior point on its member's line
    i = 5
    assert np.all(p.of_unknown[fe.node_dofs[i][fe.node_dofs[i] >= 0]] == i)
    q = 0
    mem = fe.interior_member[q]
    a, b = s.coords[s.connectivity[mem]]
    x = p.coords[s.n_nodes + q]
    assert_allclose(np.cross(x - a, b - a), 0.0, atol=1e-12)
    assert 0 < np.dot(x - a, b - a) < np.dot(b - a, b - a)


@needs_pardiso
def test_cholesky_in_geometric_order_equals_pardiso_order():
    """12 × 12 grid: PARDISO's Cholesky in the geometric order and in its own give the same
    solution to round-off, and both that of SuperLU."""
    s = space_grid(12)
    fe = discretise(s, "truss")
    A = free_submatrix(fe.stiffness(), fe.free)
    f = fe.load_vector()[fe.free]
    every = fe.dof_points()
    pts = Points(every.of_unknown[fe.free], every.coords)
    solve_g, _, how_g = pardiso.cholesky(A, pts)
    solve_p, _, how_p = pardiso.cholesky(A)
    assert (how_g, how_p) == ("geometric", "pardiso")
    ug, up = solve_g(f), solve_p(f)
    ref = spla.spsolve(A.tocsc(), f)
    scale = np.abs(ref).max()
    assert_allclose(ug, up, rtol=0, atol=1e-9 * scale)
    assert_allclose(ug, ref, rtol=0, atol=1e-9 * scale)
    assert np.linalg.norm(A @ ug - f) <= 1e-10 * np.linalg.norm(f)


@needs_pardiso
def test_factor_chooses_the_geometric_order_for_a_large_grid():
    """60 × 60 grid (21,951 free DOFs ≥ PARDISO_MIN_DOF): the automatic choice orders by the
    DOFs' points, and the member forces equal those of SuperLU's solve of the same model."""
    s = space_grid(60)
    fe = discretise(s, "truss")
    assert fe.free.size >= PARDISO_MIN_DOF
    fac = factorise(fe.stiffness(), fe.free, fe=fe)
    assert (fac.backend, fac.ordering) == ("pardiso", "geometric")
    res = solve_static(s, "truss")
    ref = solve_static(s, "truss", backend="superlu")
    assert res.backend == "pardiso"
    N = ref.axial_force
    assert_allclose(res.axial_force, N, rtol=0, atol=1e-7 * np.abs(N).max())
    # without the points PARDISO orders the matrix itself
    plain = factor(free_submatrix(fe.stiffness(), fe.free), "spd")
    assert (plain.backend, plain.ordering) == ("pardiso", "pardiso")


@needs_pardiso
def test_mechanism_still_detected_in_geometric_order():
    """A grid with one corner support only is a mechanism: the geometric order changes
    nothing in the singularity policy (the Cholesky meets a pivot that is not positive or
    negligible, the LDLᵀ its perturbed pivots)."""
    from trussfe.errors import MechanismError
    s = space_grid(60)
    sup = np.zeros_like(s.supports)
    sup[0, :3] = True
    with pytest.raises(MechanismError, match="mechanism"):
        solve_static(s.variant(supports=sup), "truss")


def braced_cube(k: int):
    """A cubic lattice of k³ joints with every edge, face and body diagonal of its cells (1 m),
    its bottom face pinned."""
    from trussfe.model.structure import build_structure
    from test_grid_solvers import ALUMINIUM, TUBE
    g = np.stack(np.meshgrid(*[np.arange(k)] * 3, indexing="ij"), -1).reshape(-1, 3)
    idx = np.arange(k ** 3).reshape(k, k, k)
    members = [np.column_stack([idx[:k - a, :k - b, :k - c].ravel(), idx[a:, b:, c:].ravel()])
               for a, b, c in [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (1, 0, 1), (0, 1, 1),
                               (1, 1, 1)]]
    return build_structure(g.astype(float), np.vstack(members), section=TUBE,
                           material=ALUMINIUM,
                           supports={int(i): "xyz" for i in idx[:, :, 0].ravel()},
                           loads={int(idx[-1, -1, -1]): [0.0, 0.0, -1000.0]}, name="cube")


def test_declines_a_three_dimensional_lattice():
    """A cut plane through a braced cube holds ~1.4 n^(2/3) unknowns, more than the 4√n of a
    two-dimensional mesh: PARDISO orders it; a space grid's cuts are lines (1.6√n)."""
    for structure, taken in ((braced_cube(14), False), (space_grid(30), True)):
        fe = discretise(structure, "truss")
        A = free_submatrix(fe.stiffness(), fe.free)
        every = fe.dof_points()
        pts = Points(every.of_unknown[fe.free], every.coords)
        assert (nested_dissection(A.indptr, A.indices, pts) is not None) == taken


@needs_pardiso
def test_member_dofs_leave_the_order_to_pardiso():
    """A grid of pinned beams (each end's own rotations) is ordered by PARDISO; loaded at
    its joints only, its bars carry the axial forces of the truss model of the same grid
    (an independent discretisation: three DOFs per joint, no rotations)."""
    from trussfe.fem.solver import joint_dofs_only
    s = space_grid(24)
    fe = discretise(s, "pinned-beam", subdivisions=1)
    assert fe.free.size >= PARDISO_MIN_DOF and not joint_dofs_only(fe)
    assert joint_dofs_only(discretise(s, "truss"))
    fac = factorise(fe.stiffness(), fe.free, fe=fe)
    assert (fac.backend, fac.ordering) == ("pardiso", "pardiso")
    assert not np.any(s.gravity)
    res = solve_static(s, "pinned-beam", subdivisions=1)
    ref = solve_static(s, "truss", backend="superlu")
    N = ref.axial_force
    assert_allclose(res.axial_force, N, rtol=0, atol=1e-7 * np.abs(N).max())


@needs_pardiso
def test_plane_truss_in_geometric_order():
    """A plane truss of 110 × 110 joints (squares with both diagonals, one edge pinned;
    23,980 free DOFs): ordered by its points in two dimensions, with the member forces of
    SuperLU's solve."""
    from trussfe.model.structure import build_structure
    from test_grid_solvers import ALUMINIUM, TUBE
    k = 110
    xy = np.stack(np.meshgrid(np.arange(k), np.arange(k), indexing="ij"), -1).reshape(-1, 2)
    idx = np.arange(k * k).reshape(k, k)
    bars = [np.column_stack([idx[:k - a, :k - b].ravel(), idx[a:, b:].ravel()])
            for a, b in [(1, 0), (0, 1), (1, 1)]]
    bars.append(np.column_stack([idx[1:, :k - 1].ravel(), idx[:k - 1, 1:].ravel()]))
    s = build_structure(xy.astype(float), np.vstack(bars), section=TUBE, material=ALUMINIUM,
                        supports={int(i): "xy" for i in idx[0]},
                        loads={int(idx[-1, -1]): [0.0, -1000.0]}, name="plate")
    fe = discretise(s, "truss")
    assert fe.free.size >= PARDISO_MIN_DOF
    fac = factorise(fe.stiffness(), fe.free, fe=fe)
    assert (fac.backend, fac.ordering) == ("pardiso", "geometric")
    res = solve_static(s, "truss")
    ref = solve_static(s, "truss", backend="superlu")
    N = ref.axial_force
    assert_allclose(res.axial_force, N, rtol=0, atol=1e-9 * np.abs(N).max())
