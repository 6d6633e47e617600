# SPDX-License-Identifier: MIT
"""Elastic response along a motion: time of the FE part against the number of steps, batched
(one block-diagonal solve per block of steps) and step by step (one discretisation and solve
per step), and the FE − rigid agreement.

Run: ``python benchmarks/bench_elastic.py``.
"""
from __future__ import annotations

import time

import numpy as np

from trussfe.response.along_motion import compare_with_rigid, elastic_along_motion
from trussfe.studies.lacy_elastic import slew2_motion
from trussfe.studies.lacy_actuators import slew1_motion, slew1_structure
from trussfe.rigid.simulate import simulate



def _step_by_step(sim, k):
    """The same analysis with one discretisation and factorisation per step."""
    kin = sim.kinematics
    for i in range(kin.n_steps):
        sub = type(kin)(**{f: (getattr(kin, f)[i:i + 1] if isinstance(getattr(kin, f),
                                                                       np.ndarray) else
                              getattr(kin, f)) for f in kin.__dataclass_fields__})
        elastic_along_motion(sim.structure, sub, bodies=sim.bodies,
                             positions=sim.sections.position, subdivisions=k)


def main() -> None:
    rows = []
    # The synthetic slew 2 reaches 1.2302 m, 1.2 mm beyond the stroke: run without the limits,
    # as trussfe.studies.lacy_elastic does.
    for name, s, make in (("slew 1", slew1_structure(), slew1_motion),
                          ("slew 2", slew1_structure(stroke=False), slew2_motion)):
        for n in (55, 220, 880):
            m = make(s, steps=n)
            t0 = time.perf_counter()
            sim = simulate(s, m, actuators=False)
            t_rigid = time.perf_counter() - t0
            t0 = time.perf_counter()
            resp = elastic_along_motion(s, sim.kinematics, bodies=sim.bodies,
                                        positions=sim.sections.position, subdivisions=6)
            t_fe = time.perf_counter() - t0
            if n <= 55:
                t0 = time.perf_counter()
                _step_by_step(sim, 6)
                t_loop = f"{time.perf_counter() - t0:10.2f}"
            else:
                t_loop = f"{'-':>10}"
            c = compare_with_rigid(sim.sections, resp, sim.forces.reactions)
            rows.append((name, m.n_steps, t_rigid, t_fe, t_loop, c["max"]))
    print(f"{'motion':8} {'steps':>6} {'rigid s':>9} {'FE s':>8} {'FE/step ms':>11} "
          f"{'loop s':>10} {'max diff':>10}")
    for name, nt, tr, tf, tl, d in rows:
        print(f"{name:8} {nt:6d} {tr:9.2f} {tf:8.2f} {1e3 * tf / nt:11.2f} {tl} {d:10.1e}")


if __name__ == "__main__":
    from trussfe.cli import environment_workers
    from trussfe.threads import compute_threads

    with compute_threads(workers=environment_workers(), blas=1):   # as the trussfe command
        main()
