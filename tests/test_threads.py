# SPDX-License-Identifier: MIT
"""Worker threads (trussfe.threads) do not change results; thread counts are set at one
boundary (compute_threads), which the command line reads from TRUSSFE_THREADS."""
from __future__ import annotations

import numpy as np
import pytest

from threadpoolctl import threadpool_info

from trussfe import threads
from trussfe.cli import environment_workers
from trussfe.rigid import linalg
from trussfe.rigid.motion import third_order_motion
from trussfe.studies.lacy_rigid import double_octahedral_chain
from trussfe.rigid.simulate import simulate


def test_command_line_reads_the_environment(monkeypatch):
    """TRUSSFE_THREADS sets the command line's count; nonsense or nothing: the default."""
    monkeypatch.setenv("TRUSSFE_THREADS", "3")
    assert environment_workers() == 3
    monkeypatch.setenv("TRUSSFE_THREADS", "x")
    assert environment_workers() is None
    monkeypatch.delenv("TRUSSFE_THREADS")
    assert environment_workers() is None


def test_library_ignores_the_environment(monkeypatch):
    """Library code reads no thread setting from the environment: the count is an argument,
    or the enclosing compute_threads', or the default."""
    monkeypatch.setenv("TRUSSFE_THREADS", "3")
    assert threads.worker_count() == threads.default_worker_count()
    assert threads.worker_count(2) == 2
    with threads.compute_threads(workers=3, blas=None):
        assert threads.worker_count() == 3
        # nested calls in worker threads see the same count
        assert threads.parallel_map(lambda _: threads.worker_count(), range(4)) == [3] * 4
    assert threads.worker_count() == threads.default_worker_count()


def _blas_threads() -> list[int]:
    # numpy's and scipy's OpenBLAS (MKL, once PARDISO has loaded it, keeps its threads)
    return [p["num_threads"] for p in threadpool_info() if p["internal_api"] == "openblas"]


def test_blas_limit_is_applied_and_lifted_at_the_boundary():
    """compute_threads limits BLAS for its duration, worker threads included, and restores
    the count afterwards."""
    before = _blas_threads()
    with threads.compute_threads(blas=1):
        assert set(_blas_threads()) == {1}
        assert threads.parallel_map(lambda _: set(_blas_threads()), range(3), workers=2) \
            == [{1}] * 3
    assert _blas_threads() == before


def test_parallel_map_keeps_order_and_raises():
    assert threads.parallel_map(lambda x: -x, range(7), workers=2) == [0, -1, -2, -3, -4, -5,
                                                                      -6]

    def bad(x):
        if x == 3:
            raise ValueError("three")
        return x
    try:
        threads.parallel_map(bad, range(6), workers=2)
    except ValueError as err:
        assert str(err) == "three"
    else:                                                          # pragma: no cover
        raise AssertionError("the worker's exception was lost")


@pytest.mark.parametrize("method", ["bay-by-bay", "direct"])
def test_chain_simulation_threaded_equals_serial(monkeypatch, method):
    """A 30-bay chain over 600 steps (several blocks of steps, Newton split in chunks), by
    both methods: the threaded forces, stresses and actuator forces equal the serial ones.
    Positions come from the same converged Newton iteration (tolerance 1e-12 of the bar
    lengths), so forces agree to ~1e-9 relative; the block stages themselves are
    bit-identical."""
    c = double_octahedral_chain(30, gravity=9.81, top_load=46.0)
    acts = [a.member for a in c.extensions["active_members"]]
    L0 = c.lengths()[acts]
    L1 = L0.copy()
    L1[0::3] += 0.02 * (-1.0) ** np.arange(30)
    m = third_order_motion(c, L0, L1, 2.0, 600)
    with threads.compute_threads(workers=1):
        serial = simulate(c, m, n_sections=1, method=method)
    monkeypatch.setattr(linalg, "PARALLEL_INVERSE_MIN", 1)
    with threads.compute_threads(workers=3):
        threaded = simulate(c, m, n_sections=1, method=method)
    assert serial.options["method"] == threaded.options["method"] == method
    np.testing.assert_allclose(threaded.kinematics.coords, serial.kinematics.coords,
                               rtol=0, atol=1e-12 * np.abs(serial.kinematics.coords).max())
    for a, b in ((threaded.midpoint_axial_force, serial.midpoint_axial_force),
                 (threaded.stresses.von_mises, serial.stresses.von_mises),
                 (threaded.actuator_force, serial.actuator_force)):
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-9 * np.abs(b).max())
