# SPDX-License-Identifier: MIT
"""Timing of the actuator and motor model, the rotation-to-lengths conversion and the bay-by-bay
chain kinematics.  Prints a table; asserts nothing (targets in the issue: the whole
double-octahedral slew of 10,000 steps, actuators included, < 1 s)."""
from __future__ import annotations

import time

import numpy as np

from trussfe.rigid.actuator import actuator_histories
from trussfe.rigid.actuator_reproductions import slew1_structure
from trussfe.rigid.chain import chain_kinematics
from trussfe.rigid.motion import third_order_response
from trussfe.rigid.reproductions import EQUILIBRIUM_LENGTH, double_octahedron
from trussfe.rigid.slew import rotation_motion


def best(fn, repeat=3):
    out = None
    tmin = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        tmin = min(tmin, time.perf_counter() - t0)
    return tmin, out


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
                                              ddy[:, None, None] * amp), repeat=1)
        rows.append((f"bay-by-bay chain kinematics, {nb} bays", steps, tc))
    print(f"{'task':45s} {'steps':>7s} {'time (s)':>9s} {'per step (µs)':>14s}")
    for name, n, tt in rows:
        print(f"{name:45s} {n:7d} {tt:9.3f} {1e6 * tt / n:14.1f}")


if __name__ == "__main__":
    main()
