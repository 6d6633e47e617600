# SPDX-License-Identifier: MIT
"""Worker threads (trussfe.threads) do not change results."""
from __future__ import annotations

import numpy as np

from trussfe import threads
from trussfe.rigid import linalg
from trussfe.rigid.motion import third_order_motion
from trussfe.studies.lacy_rigid import double_octahedral_chain
from trussfe.rigid.simulate import simulate


def test_worker_count_follows_environment(monkeypatch):
    """TRUSSFE_THREADS sets the count; nonsense falls back to the default (≥ 1)."""
    monkeypatch.setenv("TRUSSFE_THREADS", "3")
    assert threads.worker_count() == 3
    monkeypatch.setenv("TRUSSFE_THREADS", "x")
    assert 1 <= threads.worker_count() <= threads.MAX_THREADS


def test_parallel_map_keeps_order_and_raises(monkeypatch):
    monkeypatch.setenv("TRUSSFE_THREADS", "2")
    assert threads.parallel_map(lambda x: -x, range(7)) == [0, -1, -2, -3, -4, -5, -6]

    def bad(x):
        if x == 3:
            raise ValueError("three")
        return x
    try:
        threads.parallel_map(bad, range(6))
    except ValueError as err:
        assert str(err) == "three"
    else:                                                          # pragma: no cover
        raise AssertionError("the worker's exception was lost")


def test_chain_simulation_threaded_equals_serial(monkeypatch):
    """A 30-bay chain over 600 steps (several blocks of steps, Newton split in chunks): the
    threaded forces, stresses and actuator forces equal the serial ones.  Positions come from
    the same converged Newton iteration (tolerance 1e-12 of the bar lengths), so forces agree
    to ~1e-9 relative; the block stages themselves are bit-identical."""
    c = double_octahedral_chain(30, gravity=9.81, top_load=46.0)
    acts = [a.member for a in c.extensions["active_members"]]
    L0 = c.lengths()[acts]
    L1 = L0.copy()
    L1[0::3] += 0.02 * (-1.0) ** np.arange(30)
    m = third_order_motion(c, L0, L1, 2.0, 600)
    monkeypatch.setenv("TRUSSFE_THREADS", "1")
    serial = simulate(c, m, n_sections=1)
    monkeypatch.setenv("TRUSSFE_THREADS", "3")
    monkeypatch.setattr(linalg, "PARALLEL_INVERSE_MIN", 1)
    threaded = simulate(c, m, n_sections=1)
    np.testing.assert_allclose(threaded.kinematics.coords, serial.kinematics.coords,
                               rtol=0, atol=1e-12 * np.abs(serial.kinematics.coords).max())
    for a, b in ((threaded.midpoint_axial_force, serial.midpoint_axial_force),
                 (threaded.stresses.von_mises, serial.stresses.von_mises),
                 (threaded.actuator_force, serial.actuator_force)):
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-9 * np.abs(b).max())
