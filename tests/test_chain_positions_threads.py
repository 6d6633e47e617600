# SPDX-License-Identifier: MIT
"""The bay positions' chord Newton iteration (trussfe.rigid.chain._batched_positions, Lacy
eqs. 6.1-6.3 bay by bay) split between worker threads runs every chunk of steps in lockstep
(one convergence test, one factorisation), so its positions equal the one-thread run's to the
last bit; the bar lengths are those of the motion (the analytic constraint)."""
from __future__ import annotations

import numpy as np

from trussfe import threads
from trussfe.rigid import chain
from trussfe.rigid.motion import third_order_motion
from trussfe.rigid.simulate import simulate
from trussfe.studies.lacy_rigid import double_octahedral_chain


def test_threaded_bay_positions_equal_serial(monkeypatch):
    c = double_octahedral_chain(6, gravity=9.81, top_load=46.0)
    acts = [a.member for a in c.extensions["active_members"]]
    L0 = c.lengths()[acts]
    L1 = L0.copy()
    L1[0::3] += 0.03 * (-1.0) ** np.arange(6)
    m = third_order_motion(c, L0, L1, 2.0, 300)
    monkeypatch.setattr(chain, "PARALLEL_POSITION_MIN_STEPS", 200)   # 6 x 300 steps: 3 chunks
    with threads.compute_threads(workers=1, blas=None):
        serial = simulate(c, m, n_sections=1, method="bay-by-bay")
    with threads.compute_threads(workers=3, blas=None):
        threaded = simulate(c, m, n_sections=1, method="bay-by-bay")
    np.testing.assert_array_equal(threaded.kinematics.coords, serial.kinematics.coords)
    np.testing.assert_array_equal(threaded.forces.end_force, serial.forces.end_force)
    X = threaded.kinematics.coords
    d = X[:, c.connectivity[:, 1]] - X[:, c.connectivity[:, 0]]
    L = np.broadcast_to(c.lengths(), (m.n_steps, c.n_members)).copy()
    L[:, m.members] = m.length
    np.testing.assert_allclose(np.linalg.norm(d, axis=2), L, rtol=0, atol=1e-11)


def test_kinematics_in_blocks_equal_whole_motion(monkeypatch):
    """The element-wise kinematics (trussfe.rigid.kinematics._in_blocks) in blocks of 50
    steps on 3 threads equal one block of the whole motion to the last bit; the unit vectors
    have unit length and the angular velocity is e x e_dot (Lacy eqs. 2.3-2.8)."""
    from trussfe.rigid import kinematics
    from trussfe.studies.lacy_rigid import double_octahedron
    s = double_octahedron((1.2289, 1.1079, 1.1079), gravity=-9.81, top_load=46.0)
    m = third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289], 2.0, 400)
    X = kinematics.solve_motion_positions(s, m)
    with threads.compute_threads(workers=1, blas=None):
        whole = kinematics.compute_kinematics(s, m, coords=X)
    monkeypatch.setattr(kinematics, "BLOCK_ENTRIES", 50 * s.n_members)
    with threads.compute_threads(workers=3, blas=None):
        blocked = kinematics.compute_kinematics(s, m, coords=X)
    for name in ("length", "unit", "velocity", "acceleration", "unit_rate", "unit_acc",
                 "omega", "alpha"):
        np.testing.assert_array_equal(getattr(blocked, name), getattr(whole, name),
                                      err_msg=name)
    np.testing.assert_allclose(np.linalg.norm(blocked.unit, axis=2), 1.0, rtol=0, atol=1e-14)
    np.testing.assert_array_equal(blocked.omega, np.cross(blocked.unit, blocked.unit_rate))


def test_chord_newton_steps_are_all_applied():
    """Each chunk adds its correction in its next residual pass; when the iterations run out
    the last corrections still count: one and two iterations (three chunks, stacked
    inverses) give exactly the guess plus one and two chord steps
    ``Δx = B(x₀)⁻¹ (L − |d(x)|)`` with B at the guess (Hortobágyi eqs. 1-2), computed here
    by dense solves step by step."""
    from trussfe.rigid.bays import chain_layout
    from trussfe.rigid.kinematics import _Pattern, chord_newton
    c = double_octahedral_chain(1, gravity=9.81, top_load=46.0)
    bay = chain_layout(c).template
    pat = _Pattern.of(bay)
    conn = bay.connectivity
    nt = 30
    rng = np.random.default_rng(5)
    L = np.broadcast_to(bay.lengths(), (nt, bay.n_members)).copy()
    L *= 1.0 + 0.01 * rng.standard_normal(L.shape)
    x0 = np.asarray(bay.coords, dtype=float)

    def dense_B(x):
        d = x[conn[:, 1]] - x[conn[:, 0]]
        e = d / np.linalg.norm(d, axis=1)[:, None]
        B = np.zeros((bay.n_members, bay.n_nodes, 3))
        B[np.arange(bay.n_members), conn[:, 1]] += e
        B[np.arange(bay.n_members), conn[:, 0]] -= e
        return B.reshape(bay.n_members, -1)[pat.loaded_idx][:, pat.free_flat]

    B0 = dense_B(x0)
    expected = np.broadcast_to(x0, (nt,) + x0.shape).copy()
    for its in (1, 2):
        flat = expected.reshape(nt, -1)
        d = expected[:, conn[:, 1]] - expected[:, conn[:, 0]]
        misfit = L - np.linalg.norm(d, axis=2)
        flat[:, pat.free_flat] += np.linalg.solve(B0, misfit[:, pat.loaded_idx].T).T
        X = np.broadcast_to(x0, (nt,) + x0.shape).copy()
        with threads.compute_threads(workers=3, blas=None):
            got, ok = chord_newton(conn, pat, L, X, np.broadcast_to(x0, X.shape),
                                   min_chunk_steps=10, iterations=its)
        assert got is X and not ok.any()          # not converged in one or two steps
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-13)
