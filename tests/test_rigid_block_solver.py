# SPDX-License-Identifier: MIT
"""Block-triangular compatibility solver (trussfe.rigid.linalg) against independent solves."""
import numpy as np
import pytest
import scipy.sparse as sp
from numpy.testing import assert_allclose

from trussfe.rigid.kinematics import _Pattern
from trussfe.model.geometry import lengths
from trussfe.rigid.linalg import CompatSolver, SingularStep, block_triangular_form
from trussfe.vectors import cross
from trussfe.rigid.motion import third_order_motion
from trussfe.studies.lacy_rigid import double_octahedral_chain, double_octahedron
from trussfe.rigid.simulate import simulate


def _perturbed_values(structure, nt, seed=0):
    p = _Pattern(structure)
    conn = structure.connectivity
    d = structure.coords[conn[:, 1]] - structure.coords[conn[:, 0]]
    e = np.repeat((d / np.linalg.norm(d, axis=1)[:, None])[None], nt, axis=0)
    e = e + 1e-2 * np.random.default_rng(seed).standard_normal(e.shape)
    return p, p.values(e)


def test_double_octahedron_and_chain_split_into_9x9_blocks():
    """The bay's B: two 9 × 9 blocks (midplane nodes, then top nodes); a 4-bay chain: eight."""
    for s, nb in ((double_octahedron(), 2), (double_octahedral_chain(4), 8)):
        p = _Pattern(s)
        f = block_triangular_form(p.rows, p.cols, p.m)
        assert f.n_blocks == nb and f.max_size == 9
        assert sorted(np.concatenate(f.rows).tolist()) == list(range(p.m))
        assert sorted(np.concatenate(f.cols).tolist()) == list(range(p.m))


def test_block_solves_equal_dense_solves():
    """B x = b and Bᵀ y = c by block substitution equal numpy.linalg.solve of the assembled
    dense matrices (independent), for 5 perturbed steps of a 4-bay chain, 1 and 2 right-hand
    sides (residual 1e-12 relative)."""
    s = double_octahedral_chain(4)
    p, vals = _perturbed_values(s, 5)
    cs = CompatSolver(p.rows, p.cols, vals, p.m)
    assert cs.block_inverses is not None and cs.direct
    rng = np.random.default_rng(1)
    b = rng.standard_normal((5, p.m, 2))
    x, y = cs.solve(b, transpose=False), cs.solve(b, transpose=True)
    x1 = cs.solve(b[..., 0])
    for t in range(5):
        B = sp.csr_matrix((vals[t], (p.rows, p.cols)), shape=(p.m, p.m)).toarray()
        assert_allclose(x[t], np.linalg.solve(B, b[t]), rtol=0, atol=1e-12 * np.abs(x).max())
        assert_allclose(y[t], np.linalg.solve(B.T, b[t]), rtol=0, atol=1e-12 * np.abs(y).max())
        assert_allclose(x1[t], x[t, :, 0], rtol=0, atol=1e-13 * np.abs(x).max())
    sub = cs.subset(2, 4)
    assert_allclose(sub.solve(b[2:4, :, 0]), x1[2:4], rtol=0, atol=1e-14 * np.abs(x).max())


@pytest.mark.parametrize("workers", [1, 3])
def test_singular_block_names_the_step(monkeypatch, workers):
    """A step with a zero (singular) diagonal block is reported by its index, also when
    worker threads invert groups of the blocks (three threads, every stack split)."""
    import trussfe.rigid.linalg as la
    from trussfe.threads import compute_threads
    monkeypatch.setattr(la, "PARALLEL_INVERSE_MIN", 1)
    s = double_octahedral_chain(2)
    p, vals = _perturbed_values(s, 4)
    f = block_triangular_form(p.rows, p.cols, p.m)
    vals[2, f.diag[1][2]] = 0.0
    with compute_threads(workers=workers), pytest.raises(SingularStep) as err:
        CompatSolver(p.rows, p.cols, vals, p.m)
    assert err.value.step == 2
    # invertible but nearly singular (one row scaled by 1e-9): the condition number finds it
    _, pert = _perturbed_values(s, 4)
    r, _, d = f.diag[1]
    pert[2, d[r == 0]] *= 1e-9
    vals = pert
    with compute_threads(workers=workers), pytest.raises(SingularStep) as err:
        CompatSolver(p.rows, p.cols, vals, p.m)
    assert err.value.step == 2


def test_chain_block_and_superlu_paths_agree(monkeypatch):
    """A 3-bay chain slewing over 150 steps: the block-triangular solver and the anchored
    SuperLU path (forced by DENSE_LIMIT = 0) give the same forces to 1e-9 relative."""
    import trussfe.rigid.linalg as la
    c = double_octahedral_chain(3, gravity=9.81, top_load=46.0)
    acts = [a.member for a in c.extensions["active_members"]]
    L0 = c.lengths()[acts]
    L1 = L0.copy()
    L1[0::3] += 0.02
    m = third_order_motion(c, L0, L1, 2.0, 150)
    a = simulate(c, m, n_sections=3)
    monkeypatch.setattr(la, "DENSE_LIMIT", 0)
    b = simulate(c, m, n_sections=3)
    assert_allclose(b.forces.end_force, a.forces.end_force, rtol=0,
                    atol=1e-9 * np.abs(a.forces.end_force).max())
    assert_allclose(b.stresses.von_mises, a.stresses.von_mises, rtol=0,
                    atol=1e-9 * np.abs(a.stresses.von_mises).max())


def test_cross_and_lengths_equal_numpy():
    """The fast helpers against numpy.cross and numpy.linalg.norm, bit for bit: the cross
    product (also written into a given array), and the lengths of 1-, 2- and 3-vectors that
    the section shears' and moments' magnitudes are (summed column by column in place)."""
    rng = np.random.default_rng(2)
    a, b = rng.standard_normal((2, 50, 7, 3))
    assert np.array_equal(cross(a, b), np.cross(a, b))
    assert np.array_equal(cross(a, b[0, 0]), np.cross(a, b[0, 0]))
    out = np.empty_like(a)
    assert cross(a, b, out=out) is out and np.array_equal(out, np.cross(a, b))
    for width in (1, 2, 3):
        v = a[..., :width] * 1e3
        assert np.array_equal(lengths(v), np.linalg.norm(v, axis=-1))
    assert np.array_equal(lengths(a[:, :, None]), np.linalg.norm(a[:, :, None], axis=-1))


def test_pattern_is_kept_with_the_model():
    """The compatibility pattern of a model is made once (read-only arrays) and kept while
    the model exists; a model with other supports gets its own."""
    import gc
    import weakref
    s = double_octahedral_chain(2)
    p = _Pattern.of(s)
    assert _Pattern.of(s) is p and not p.rows.flags.writeable
    sup = s.supports.copy()
    sup[3] = True                                   # one more supported node
    other = s.variant(supports=sup)
    q = _Pattern.of(other)
    assert q is not p and q.nfree == p.nfree - 3
    ref = weakref.ref(other)
    del other, q
    gc.collect()
    assert ref() is None


def test_block_form_and_nodal_sums_are_kept_with_the_model():
    """The pattern's block-triangular form and the plans of the nodal sums are made once per
    model (read-only, shared by every later analysis of it), another model gets its own,
    and nothing of them outlives the model: no table outside it holds them."""
    import gc
    import weakref

    from trussfe.rigid.forces import _kept_sums
    s = double_octahedral_chain(2)
    form = _Pattern.of(s).form
    assert _Pattern.of(s).form is form and not form.rows[0].flags.writeable
    plan, held = _kept_sums(s, False), _kept_sums(s, True)
    assert _kept_sums(s, False) is plan and _kept_sums(s, True) is held
    assert plan.size == s.n_nodes and held.size == 3                # the three base nodes
    assert not plan.to_nodes.flags.writeable and not plan.start_cols[0].flags.writeable
    other = double_octahedral_chain(3)
    other_form, other_held = _Pattern.of(other).form, _kept_sums(other, True)
    assert other_form.n_blocks == 6 and form.n_blocks == 4 and other_held.size == 3
    refs = [weakref.ref(x) for x in (other, other_form, other_held)]
    del other, other_form, other_held
    gc.collect()
    assert all(r() is None for r in refs)
