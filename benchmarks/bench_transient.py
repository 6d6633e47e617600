# SPDX-License-Identifier: MIT
"""Speed of the transient elastic response (trussfe.response.transient): steps per second.

Runs the triangular truss (Lacy's Base Simulation model, pinned-beam FE with k sub-elements)
along its 1.2 m slew, with updated and frozen matrices, and prints a table.  Usage::

    python benchmarks/bench_transient.py [--quick]
"""
from __future__ import annotations

import argparse
import time

from trussfe.studies.transient_slews import triangle_slew



def run(cases) -> list[tuple]:
    rows = []
    for T, dt, k, update in cases:
        t0 = time.perf_counter()
        r = triangle_slew(T, dt, k=k, update=update)
        el = time.perf_counter() - t0
        rows.append((T, dt, k, update, r.fe.free.size, r.time.size, el, r.time.size / el))
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="short runs only")
    args = ap.parse_args()
    cases = [(0.3, 2.5e-4, 4, "per-step"), (0.3, 2.5e-4, 4, "frozen"),
             (0.3, 2.5e-4, 8, "per-step")]
    if not args.quick:
        cases += [(1.0, 1.25e-4, 4, "per-step"), (3.0, 2.5e-4, 4, "per-step")]
    print(f"{'T s':>5} {'dt s':>9} {'k':>3} {'matrices':>9} {'free DOFs':>9} {'steps':>7} "
          f"{'time s':>7} {'steps/s':>8}")
    for T, dt, k, upd, nf, n, el, rate in run(cases):
        print(f"{T:5.1f} {dt:9.2e} {k:3d} {upd:>9} {nf:9d} {n:7d} {el:7.2f} {rate:8.0f}")


if __name__ == "__main__":
    from trussfe.cli import environment_workers
    from trussfe.threads import compute_threads

    with compute_threads(workers=environment_workers(), blas=1):   # as the trussfe command
        main()
