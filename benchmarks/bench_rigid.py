# SPDX-License-Identifier: MIT
"""Speed of the rigid-body dynamic force model (targets in docs/performance.md); prints a table.

Targets: the double-octahedral slew with 10,000 time steps (kinematics, nodal forces,
section forces, stresses, buckling, actuator force and, when available, motor histories)
in < 1 s; a 100-bay chain (1,800 members) over 1,000 steps in < 10 s.  For comparison, the
time of a plain per-step dense solve of a 117 × 117 system (the size of Lacy's double-
octahedron system, eq. 4.20 / Table 4.1), in a Python loop over the steps.

Run from the source tree: ``PYTHONPATH=$PWD python benchmarks/bench_rigid.py [--quick]``.
"""
from __future__ import annotations

import argparse
import os
import time

# One BLAS thread: the stacked small solves gain nothing from BLAS threads, and on a shared
# machine oversubscribed BLAS threads slow them down twentyfold (measured).  trussfe's own
# worker threads (trussfe.threads) take independent blocks of steps instead.
for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from trussfe.rigid.motion import third_order_motion  # noqa: E402
from trussfe.studies.lacy_rigid import double_octahedral_chain, double_octahedron  # noqa: E402
from trussfe.rigid.simulate import simulate  # noqa: E402
from trussfe.threads import worker_count  # noqa: E402
from trussfe.allocator import tune_allocator  # noqa: E402

tune_allocator()   # numpy temporaries reuse heap pages, as in the trussfe command



def _best(fn, repeat):
    """Best wall-clock and process (CPU) time over ``repeat`` runs, and the last result.

    On a shared machine the CPU time is the steadier figure."""
    best, cpu = np.inf, np.inf
    out = None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        best = min(best, time.perf_counter() - t0)
        cpu = min(cpu, time.process_time() - c0)
    return (best, cpu), out


def dense_117_per_step(structure, result, nt_total: int) -> float:
    """Seconds for a per-step dense solve of Lacy's 117 × 117 system (assembled by
    :func:`trussfe.studies.lacy_newton_euler.newton_euler_system`, solved step by step in a Python loop),
    measured on up to 2,000 steps and scaled to ``nt_total``."""
    from trussfe.studies.lacy_newton_euler import newton_euler_system
    A, b, _ = newton_euler_system(structure, result.kinematics)
    k = min(A.shape[0], 2000)
    t0 = time.perf_counter()
    for i in range(k):
        np.linalg.solve(A[i], b[i])
    return (time.perf_counter() - t0) * nt_total / k


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="smaller runs (smoke test)")
    ap.add_argument("--repeat", type=int, default=1,
                    help="runs of the chain case; the best is shown (default 1)")
    args = ap.parse_args()
    rows = []

    nt = 1000 if args.quick else 10000
    s = double_octahedron((1.2289, 1.1079, 1.1079), gravity=-9.81, top_load=46.0)
    m = third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289], 2.0, nt)
    t, res = _best(lambda: simulate(s, m, n_sections=1), 3)
    ref = dense_117_per_step(s, res, nt)
    # (the reference loop is timed on the wall clock, like the first time column)
    rows.append(("double octahedron slew", s.n_members, nt, *t, 1.0, ref))

    bays, nt2 = (10, 200) if args.quick else (100, 1000)
    c = double_octahedral_chain(bays, gravity=9.81, top_load=46.0)
    acts = [a.member for a in c.extensions["active_members"]]
    L0 = c.lengths()[acts]
    # Every bay slews by ±0.02 m on M7/8 in alternate directions, so that the chain stays
    # roughly straight (one direction for all bays would curl 100 bays into a spiral).
    L1 = L0.copy()
    L1[0::3] += 0.02 * (-1.0) ** np.arange(bays)
    mc = third_order_motion(c, L0, L1, 2.0, nt2)
    tc, _ = _best(lambda: simulate(c, mc, n_sections=1), max(1, args.repeat))
    # One 117 × 117 solve per bay and step (the bay-by-bay cost of Lacy's formulation).
    refc = ref / nt * nt2 * bays
    rows.append((f"{bays}-bay chain", c.n_members, nt2, *tc, 10.0, refc))

    print(f"{'case':26s} {'members':>8s} {'steps':>7s} {'wall s':>8s} {'cpu s':>8s} "
          f"{'target s':>9s} {'us/(step*member)':>17s} {'dense-117 loop s':>17s} "
          f"{'speed-up':>9s}")
    for name, mm, n, tt, cpu, target, r in rows:
        print(f"{name:26s} {mm:8d} {n:7d} {tt:8.3f} {cpu:8.3f} {target:9.1f} "
              f"{1e6 * tt / (n * mm):17.3f} {r:17.3f} {r / tt:9.1f}")
    print(f"worker threads: {worker_count()} (TRUSSFE_THREADS); wall and cpu: best of 3 runs "
          f"(slew) and of {max(1, args.repeat)} (chain)")
    print("dense-117 loop: one np.linalg.solve of Lacy's 117 x 117 system (eq. 4.20) per step, "
          "assembly excluded; for the chain, one per bay and step.")


if __name__ == "__main__":
    from trussfe.cli import environment_workers
    from trussfe.threads import compute_threads

    with compute_threads(workers=environment_workers(), blas=1):   # as the trussfe command
        main()
