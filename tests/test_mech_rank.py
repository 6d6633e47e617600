"""Rank analysis: mechanisms, rigid-body motions and self-stress states.

Expected counts come from the catalogue entries' sources (Hortobágyi 1999 sections 4, 8, 9;
Bricard 1897; Cauchy 1813; Gruebler counting) — each entry names its source.
"""
import numpy as np
import pytest

from trussfe.kinematics import rank_analysis, rigid_body_modes, structure_rank
from trussfe.kinematics.compatibility import compatibility_matrix
from trussfe.models.mechanisms import CATALOGUE


@pytest.mark.parametrize("name", sorted(CATALOGUE))
def test_catalogue_counts(name):
    e = CATALOGUE[name]
    r = rank_analysis(e.coords, e.bars, e.free)
    got = {"rank": r.rank, "mechanisms": r.mechanisms,
           "rigid_body_motions": r.rigid_body_motions, "self_stress_states": r.self_stress_states}
    assert got == e.expected, e.source
    # Maxwell/Calladine: b − ρ = s, f − ρ = m + rigid (identity, checks the bookkeeping)
    assert r.n_coordinates - r.rank == r.mechanisms + r.rigid_body_motions


@pytest.mark.parametrize("name", sorted(CATALOGUE))
def test_bases_are_null_vectors(name):
    """Mechanism shapes do not stretch bars (B m = 0); self-stress states are in equilibrium
    without load (Bᵀ s = 0) — to round-off, 1e-10."""
    e = CATALOGUE[name]
    r = rank_analysis(e.coords, e.bars, e.free)
    B = compatibility_matrix(e.coords, e.bars, e.free).toarray()
    if r.mechanisms:
        np.testing.assert_allclose(B @ r.mechanism_basis, 0, atol=1e-10)
        np.testing.assert_allclose(r.mechanism_basis.T @ r.mechanism_basis,
                                   np.eye(r.mechanisms), atol=1e-10)
    if r.rigid_body_motions:
        np.testing.assert_allclose(B @ r.rigid_body_basis, 0, atol=1e-10)
        # internal mechanisms are orthogonal to the rigid-body motions
        np.testing.assert_allclose(r.rigid_body_basis.T @ r.mechanism_basis, 0, atol=1e-10)
    if r.self_stress_states:
        np.testing.assert_allclose(B.T @ r.self_stress_basis, 0, atol=1e-10)


def test_rigid_body_modes_count():
    """3 in the plane, 6 in space, 5 for collinear points in space (no spin about the line)."""
    assert rigid_body_modes(np.random.default_rng(0).normal(size=(4, 2))).shape[1] == 3
    assert rigid_body_modes(np.random.default_rng(0).normal(size=(4, 3))).shape[1] == 6
    line = np.column_stack([np.arange(4.0), np.zeros(4), np.zeros(4)])
    assert rigid_body_modes(line).shape[1] == 5


def test_section4_rank_after_step():
    """Hortobágyi section 4: rank 2 at the folded state, 3 after a step (node 1 down l/10)."""
    e = CATALOGUE["mech_hortobagyi_sec4"]
    x = e.coords.copy()
    x[0] = [np.sqrt(0.99), -0.1]
    x[1] = [1 + np.sqrt(0.99), -0.1]
    assert rank_analysis(x, e.bars, e.free).rank == 3


def test_scale_invariance():
    """B holds direction cosines: scaling the geometry by 1e4 does not change the rank."""
    e = CATALOGUE["mech_bricard"]
    r1 = rank_analysis(e.coords, e.bars, e.free)
    r2 = rank_analysis(1e4 * e.coords, e.bars, e.free)
    assert (r1.rank, r1.mechanisms) == (r2.rank, r2.mechanisms)


def test_tolerance_no_tighter_than_geometry():
    """Bricard's octahedron perturbed by 1e-7 is rigid at the default tolerance but flexible
    at a tolerance matching the 1e-7 geometric accuracy (the documented trap)."""
    e = CATALOGUE["mech_bricard"]
    x = e.coords + 1e-7 * np.random.default_rng(2).normal(size=e.coords.shape)
    assert rank_analysis(x, e.bars, e.free).mechanisms == 0
    assert rank_analysis(x, e.bars, e.free, tolerance=1e-5).mechanisms == 1


def _grid(nx, ny, diagonals=True):
    xs, ys = np.meshgrid(np.arange(nx + 1.0), np.arange(ny + 1.0), indexing="ij")
    X = np.column_stack([xs.ravel(), ys.ravel()])
    idx = np.arange(X.shape[0]).reshape(nx + 1, ny + 1)
    bars = [np.column_stack([idx[:-1].ravel(), idx[1:].ravel()]),
            np.column_stack([idx[:, :-1].ravel(), idx[:, 1:].ravel()])]
    if diagonals:
        bars.append(np.column_stack([idx[:-1, :-1].ravel(), idx[1:, 1:].ravel()]))
    return X, np.vstack(bars), idx


def test_sparse_path_agrees_with_dense():
    """An unbraced grid of 6 × 5 squares, pinned at a corner and on a roller: Bolker & Crapo
    (1977) — a grid of m × n squares without bracing has m + n − 1 internal degrees of
    freedom; the sparse Lanczos path (forced with dense_limit=0) gives the dense SVD's counts.
    Fully braced, it is rigid with b − (2j − 3) = 101 − 81 = 20 states of self-stress."""
    X, bars, idx = _grid(6, 5, diagonals=False)
    free = np.ones(X.shape, bool)
    free[idx[0, 0]] = False
    free[idx[-1, 0], 1] = False
    d = rank_analysis(X, bars, free)
    s = rank_analysis(X, bars, free, dense_limit=0)
    assert (d.mechanisms, d.rigid_body_motions, d.self_stress_states) == (10, 0, 0)
    assert (s.rank, s.mechanisms, s.self_stress_states) == (d.rank, d.mechanisms,
                                                            d.self_stress_states)
    X, bars, idx = _grid(6, 5, diagonals=True)
    d = rank_analysis(X, bars, free)
    s = rank_analysis(X, bars, free, dense_limit=0)
    assert (d.mechanisms, d.self_stress_states) == (0, 20)
    assert (s.mechanisms, s.self_stress_states) == (0, 20)


def test_structure_wrapper():
    e = CATALOGUE["mech_fourbar"]
    r = structure_rank(e.structure())
    assert r.mechanisms == 1 and r.classification == "III"


def _lattice3d(nx, ny, nz):
    """Braced cubic lattice (edges, face and body diagonals of each cube), base fixed."""
    g = np.stack(np.meshgrid(np.arange(nx + 1), np.arange(ny + 1), np.arange(nz + 1),
                             indexing="ij"), -1).reshape(-1, 3).astype(float)
    idx = np.arange(g.shape[0]).reshape(nx + 1, ny + 1, nz + 1)
    bars = []
    for d in [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (0, 1, 1), (1, 0, 1), (1, 1, 1)]:
        a = idx[: nx + 1 - d[0], : ny + 1 - d[1], : nz + 1 - d[2]]
        b = idx[d[0]:, d[1]:, d[2]:]
        bars.append(np.column_stack([a.ravel(), b.ravel()]))
    free = np.ones(g.shape, bool)
    free[idx[:, :, 0].ravel()] = False
    return g, np.vstack(bars), free


@pytest.mark.parametrize("backend", ["superlu", "pardiso"])
def test_sparse_backends_agree_with_dense_in_3d(backend):
    """A 3 × 3 × 3 braced lattice (base fixed) is rigid; a top joint stripped of all bars but
    one has two mechanisms (a joint on one bar moves on a sphere); removing every diagonal of
    the top layer leaves a sway mechanism field.  Each sparse backend (inertia of BᵀB − σ²I)
    gives the dense SVD's rank, and its mechanism basis satisfies B N ≈ 0."""
    from trussfe.linalg.pardiso import available as pardiso_available
    from trussfe.kinematics.compatibility import compatibility_matrix
    if backend == "pardiso" and not pardiso_available():
        pytest.skip("PARDISO not installed")
    X, bars, free = _lattice3d(3, 3, 3)
    top = np.flatnonzero(X[:, 2] == 3)
    cases = [bars]
    corner = int(np.flatnonzero((X == [3, 3, 3]).all(axis=1))[0])
    at = np.flatnonzero((bars == corner).any(axis=1))
    cases.append(np.delete(bars, at[1:], axis=0))
    d = X[bars[:, 1]] - X[bars[:, 0]]
    diag_top = np.isin(bars, top).all(axis=1) & (np.abs(d).sum(axis=1) > 1)
    cases.append(bars[~diag_top])
    for b in cases:
        dn = rank_analysis(X, b, free)
        sp_ = rank_analysis(X, b, free, dense_limit=0, sparse_backend=backend)
        assert (sp_.rank, sp_.mechanisms, sp_.self_stress_states) == (
            dn.rank, dn.mechanisms, dn.self_stress_states)
        if sp_.mechanisms:
            B = compatibility_matrix(X, b, free)
            assert np.abs(B @ sp_.mechanism_basis).max() < 1e-6
    assert rank_analysis(X, cases[1], free).mechanisms == 2


@pytest.mark.parametrize("offset", [0.0, 1e5, 1e6])
def test_a_straight_chain_far_from_the_origin_is_still_straight(offset):
    """Two bars through (0, 0), (0.6, 0.8), (1.2, 1.6) — a straight chain between two pins,
    type IV: one infinitesimal mechanism across it and one self-stress along it — moved
    1e5 or 1e6 m away.  Its direction cosines are computed from coordinates known to
    ε·|x|: the default tolerance follows that round-off (at 1e5 m the chain was called rigid,
    smallest singular value 2.3e-11 against a tolerance of 6.3e-13)."""
    from trussfe.kinematics.rank import rank_analysis
    x = np.array([[0.0, 0.0], [0.6, 0.8], [1.2, 1.6]]) + [offset, 2 * offset]
    free = np.array([[False, False], [True, True], [False, False]])
    r = rank_analysis(x, np.array([[0, 1], [1, 2]]), free)
    assert (r.rank, r.mechanisms, r.self_stress_states) == (1, 1, 1)
