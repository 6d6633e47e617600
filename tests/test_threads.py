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
from trussfe.studies.lacy_rigid import double_octahedral_chain, double_octahedron
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
    """A 30-bay chain over 600 steps (several blocks of steps, the positions' Newton
    iteration split in chunks between the threads), by both methods: every output of the
    threaded run equals the serial one bit for bit.  The chunks iterate in lockstep (one
    convergence test, the whole motion's chord Jacobians), so no step's arithmetic depends
    on the number of threads."""
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
    _assert_same_outputs(threaded, serial)


def test_slew_threaded_equals_serial():
    """The double-octahedral slew (the direct method: Newton on the whole truss, 2,000 steps
    in chunks) gives the same numbers with one thread and with three."""
    s = double_octahedron((1.2289, 1.1079, 1.1079), gravity=-9.81, top_load=46.0)
    m = third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289], 2.0, 2000)
    with threads.compute_threads(workers=1):
        serial = simulate(s, m, n_sections=3)
    with threads.compute_threads(workers=3):
        threaded = simulate(s, m, n_sections=3)
    assert serial.options["method"] == "direct"
    _assert_same_outputs(threaded, serial)


def _assert_same_outputs(a, b):
    """Positions, rates, member forces, section stresses and actuator forces equal."""
    for name in ("coords", "velocity", "acceleration"):
        np.testing.assert_array_equal(getattr(a.kinematics, name), getattr(b.kinematics, name))
    for x, y in ((a.forces.tension_end, b.forces.tension_end),
                 (a.static_forces.end_force, b.static_forces.end_force),
                 (a.midpoint_axial_force, b.midpoint_axial_force),
                 (a.stresses.von_mises, b.stresses.von_mises),
                 (a.actuator_force, b.actuator_force)):
        np.testing.assert_array_equal(x, y)


def test_compute_threads_lends_its_threads_to_every_map_and_ends_them():
    """Inside compute_threads the maps run on the calling thread and the context's one other
    thread (the same from map to map, started once; two workers, never more threads
    computing), a map nested in one of their calls starts its own instead of waiting for
    them (two levels of two items on two threads: would deadlock on shared threads), and no
    thread outlives the context."""
    import threading
    import time

    def ident(_):
        time.sleep(0.002)                # long enough for both threads to take items
        return threading.get_ident(), threading.current_thread().name

    def nested(x):
        return threads.parallel_map(lambda y: x * 10 + y, range(2))

    with threads.compute_threads(workers=2, blas=None):
        first = set(threads.parallel_map(ident, range(8)))
        second = set(threads.parallel_map(ident, range(8)))
        caller = (threading.get_ident(), threading.current_thread().name)
        # the caller and the context's thread, named for trussfe, and no others
        helpers = (first | second) - {caller}
        assert caller in first and len(helpers) == 1
        assert all(name.startswith("trussfe") for _, name in helpers)
        assert threads.parallel_map(nested, range(2)) == [[0, 1], [10, 11]]
        # an explicit, different count gets threads of its own
        assert threads.parallel_map(lambda x: x + 1, range(3), workers=3) == [1, 2, 3]
    alive = [t for t in threading.enumerate() if t.name.startswith("trussfe")]
    assert alive == []


def test_shared_map_keeps_order_and_raises_the_first_failure():
    """On the context's threads the results come back in the order of the items, every item
    runs once, and the exception of the first failing item is raised; after a failure no
    further item is started (items 3 and 5 fail: 6 and 7 never run, or not both)."""
    import threading

    seen = []
    lock = threading.Lock()

    def work(x):
        with lock:
            seen.append(x)
        if x in (3, 5):
            raise ValueError(f"item {x}")
        return x * x

    with threads.compute_threads(workers=2, blas=None):
        assert threads.parallel_map(lambda x: x * x, range(20)) == [x * x for x in range(20)]
        for _ in range(20):                              # whatever the timing
            seen.clear()
            with pytest.raises(ValueError, match="item 3"):
                threads.parallel_map(work, range(8))
            assert set(range(4)) <= set(seen) and len(seen) == len(set(seen))
            assert not {6, 7} <= set(seen)


def test_shared_map_raises_an_interrupt_before_an_error():
    """An interrupt that ends one item is what the map raises, also when an earlier item
    failed with an ordinary error."""
    import threading

    def work(x):
        if x == 0:
            both.wait(5.0)                   # item 1 runs too before item 0 fails
            raise ValueError("item 0")
        both.set()
        raise KeyboardInterrupt

    with threads.compute_threads(workers=2, blas=None):
        for _ in range(10):
            both = threading.Event()
            try:
                threads.parallel_map(work, range(2))
            except KeyboardInterrupt:
                pass
            else:                                      # pragma: no cover
                raise AssertionError("no interrupt raised")
