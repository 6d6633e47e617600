# SPDX-License-Identifier: MIT
"""Timing of the actuator and motor model, the rotation-to-lengths conversion and the bay-by-bay
chain kinematics.  Prints a table (best wall-clock and CPU time); asserts nothing (target in
docs/performance.md: the whole double-octahedral slew of 10,000 steps, actuators included, < 1 s).

The bay-by-bay chain kinematics solve every bay alone for all bays and steps at once (one
batched Newton iteration over bays × steps), then carry the frames up the chain bay by bay.

Run from the source tree: ``PYTHONPATH=$PWD python benchmarks/bench_actuator.py``.
"""
from __future__ import annotations

import os
import time

# One BLAS thread: the stacked small solves gain nothing from threads (see bench_rigid.py).
for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from trussfe.rigid.actuator import actuator_histories  # noqa: E402
from trussfe.studies.lacy_actuators import slew1_structure  # noqa: E402
from trussfe.rigid.chain import chain_kinematics  # noqa: E402
from trussfe.rigid.motion import third_order_response  # noqa: E402
from trussfe.studies.lacy_rigid import EQUILIBRIUM_LENGTH, double_octahedron  # noqa: E402
from trussfe.rigid.slew import rotation_motion  # noqa: E402



def best(fn, repeat=3):
    """Best (wall, CPU) seconds over ``repeat`` runs, and the last result.  On a shared
    machine the CPU (process) time is the steadier figure."""
    out = None
    tmin, cmin = float("inf"), float("inf")
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        tmin = min(tmin, time.perf_counter() - t0)
        cmin = min(cmin, time.process_time() - c0)
    return (tmin, cmin), out


def main() -> None:
    rows = []
    s = slew1_structure("physical")
    nt = 10_000
    spec = {"type": "rotation", "axis": "n1", "start": -10.0, "end": 10.0, "duration": 5.5,
            "steps": nt, "top_nodes": ["N7", "N8", "N9"]}
    t_rot, m = best(lambda: rotation_motion(spec, s), repeat=1)
    rows.append(("rotation → active lengths", nt, t_rot))
    rng = np.random.default_rng(0)
    force = 50.0 + rng.standard_normal((nt, 3))
    t_act, _ = best(lambda: actuator_histories(s, m, force, force))
    rows.append(("actuator + motor histories (3 actuators)", nt, t_act))
    bay = double_octahedron()
    for nb, steps in ((10, 100), (100, 10)):
        t = np.linspace(0.0, 2.0, steps)
        y, dy, ddy = third_order_response(t, 2.0)
        amp = 0.02 * rng.standard_normal((nb, 3))
        L = EQUILIBRIUM_LENGTH + y[:, None, None] * amp
        tc, _ = best(lambda: chain_kinematics(bay, L, dy[:, None, None] * amp,
                                              ddy[:, None, None] * amp))
        rows.append((f"bay-by-bay chain kinematics, {nb} bays", steps, tc))
    print(f"{'task':45s} {'steps':>7s} {'wall s':>8s} {'cpu s':>8s} {'per step (µs, cpu)':>19s}")
    for name, n, (tt, cpu) in rows:
        print(f"{name:45s} {n:7d} {tt:8.3f} {cpu:8.3f} {1e6 * cpu / n:19.1f}")


if __name__ == "__main__":
    from trussfe.cli import environment_workers
    from trussfe.threads import compute_threads

    with compute_threads(workers=environment_workers(), blas=1):   # as the trussfe command
        main()
