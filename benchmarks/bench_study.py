# SPDX-License-Identifier: MIT
"""Speed of parameter studies on Dask (``trussfe study``, docs/studies.md); prints a table.

Targets (docs/performance.md): on a 2-core machine, 2 workers give at least 1.7× the
throughput of 1 worker (runs per second, from the slope between two study sizes); the
overhead per run against calling the analysis in a loop in one process is at most 20 % for
runs of 50 ms or more; 1,000 double-octahedral slews of 500 steps each (the third-order slew
of meshes/double_octahedron_motion_slew.toml, duration × payload grid) in at most 60 s.

The clusters are started, and their workers have imported trussfe (a first small study),
before the clock runs: starting a local cluster takes a few seconds, once per study.  Each
study then runs on the running cluster by its address.  On a
machine shared with other work the times and the speed-up are indicative only.

Run from the source tree: ``PYTHONPATH=$PWD python benchmarks/bench_study.py [--quick]
[--slews N]``.
"""
from __future__ import annotations

import argparse
import os
import tempfile
import time
from pathlib import Path

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")


import trussfe  # noqa: E402
from trussfe.parametric import read_study  # noqa: E402
from trussfe.parametric.design import design  # noqa: E402
from trussfe.parametric.runner import run_one  # noqa: E402

MESHES = Path(__file__).resolve().parents[1] / "meshes"


def slew_study(folder: Path, durations: int, payloads: int, steps: int) -> Path:
    """A study file of ``durations × payloads`` third-order slews of ``steps`` steps."""
    f = folder / f"slews_{durations}x{payloads}_{steps}.toml"
    f.write_text(f"""
[study]
name = "slews"
analysis = "simulate"
model = "{MESHES / 'double_octahedron_actuators.toml'}"
options = {{ motion = "{MESHES / 'double_octahedron_motion_slew.toml'}", steps = {steps} }}

[parameters]
duration = {{ path = "motion.duration", from = 1.0, to = 6.0, count = {durations} }}
payload = {{ paths = ["masses.N7", "masses.N8", "masses.N9"], from = 0.0, to = 20.0, count = {payloads}, factor = 0.3333333333333333 }}

[outputs]
peak_voltage = {{ path = "actuators.*.max_motor_voltage", reduce = "max" }}
peak_force = {{ path = "actuators.M7_8.force", reduce = "absmax" }}
peak_von_mises = {{ path = "members.*.max_von_mises", reduce = "max" }}
""", encoding="utf-8")
    return f


def in_loop(study_file: Path) -> tuple[float, float]:
    """Wall-clock and CPU seconds to make every run's row in a loop in this process (no
    Dask).  On a shared machine the CPU time is the steadier figure."""
    s = read_study(study_file)
    t0, c0 = time.perf_counter(), time.process_time()
    for run in design(s):
        run_one(s, *run)
    return time.perf_counter() - t0, time.process_time() - c0


def on_cluster(study_file: Path, address: str, folder: Path) -> tuple[float, int]:
    """Seconds of the study on a running cluster, and the runs that succeeded."""
    t0 = time.perf_counter()
    df = trussfe.study(study_file, out=folder, scheduler=address)
    return time.perf_counter() - t0, int((df.status == "ok").sum())


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="smaller studies")
    ap.add_argument("--slews", type=int, default=None,
                    help="slews of the large study (default 1000; 100 with --quick)")
    args = ap.parse_args()
    from dask.distributed import LocalCluster

    from trussfe.parametric.engine import worker_allocator

    n_a, n_b = ((2, 4), (4, 6)) if args.quick else ((2, 4), (6, 8))   # durations × payloads
    n_slews = args.slews or (100 if args.quick else 1000)
    payloads = 25 if n_slews >= 25 else 1
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        warm = slew_study(tmp, 2, 2, steps=50)
        a = slew_study(tmp, *n_a, steps=500)
        b = slew_study(tmp, *n_b, steps=500)
        na, nb = n_a[0] * n_a[1], n_b[0] * n_b[1]
        t_loop, c_loop = in_loop(b)
        per_run = t_loop / nb
        rows.append(("in a loop, one process", nb, t_loop, nb / t_loop, "", nb / t_loop, "",
                     ""))
        times, slopes = {}, {}
        for workers in (1, 2):
            with worker_allocator():
                lc = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                  dashboard_address=":0")
            with lc:
                on_cluster(warm, lc.scheduler_address, tmp / f"warm{workers}")  # imports
                t_a, _ = on_cluster(a, lc.scheduler_address, tmp / f"a{workers}")
                t_b, ok = on_cluster(b, lc.scheduler_address, tmp / f"b{workers}")
                if workers == 2:
                    big = slew_study(tmp, n_slews // payloads, payloads, steps=500)
                    t_big, ok_big = on_cluster(big, lc.scheduler_address, tmp / "big")
            times[workers] = t_b
            # per-run cost from two study sizes: the slope leaves out the fixed cost of a
            # study (reading and checking it, its first run in this process, writing the
            # table); its inverse is the throughput of the cluster
            slope = (t_b - t_a) / (nb - na)
            slopes[workers] = slope
            over = f"{100 * (slope - per_run) / per_run:+.0f} %" if workers == 1 else ""
            rows.append((f"study, {workers} worker{'s' if workers > 1 else ''}", ok, t_b,
                         ok / t_b, f"{times[1] / t_b:.2f}x", 1.0 / slope,
                         f"{slopes[1] / slope:.2f}x", over))
            fixed = t_b - nb * slope
        rows.append((f"{n_slews} slews of 500 steps, 2 workers", ok_big, t_big, ok_big / t_big,
                     "", float("nan"), "", ""))

    print(f"parameter studies on Dask ({os.cpu_count()} cores; one run: a 500-step "
          f"double-octahedral slew with actuators, {1e3 * per_run:.0f} ms in a loop)")
    print(f"{'case':<38} {'runs':>6} {'time [s]':>9} {'runs/s':>8} {'speed-up':>9} "
          f"{'throughput':>11} {'speed-up':>9} {'overhead':>9}")
    print(f"{'':<38} {'':>6} {'':>9} {'':>8} {'(study)':>9} {'[runs/s]':>11} "
          f"{'(thr.)':>9} {'':>9}")
    for case, runs, t, rate, speed, thr, thr_speed, over in rows:
        thr_text = f"{thr:>11.1f}" if thr == thr else f"{'':>11}"
        print(f"{case:<38} {runs:>6d} {t:>9.2f} {rate:>8.1f} {speed:>9} {thr_text} "
              f"{thr_speed:>9} {over:>9}")
    print(f"throughput: runs per second from the slope between studies of {na} and {nb} runs "
          f"(the fixed cost of a study left out); speed-up (study): whole {nb}-run studies")
    print(f"overhead: per run, from the slope between studies of {na} and {nb} runs on one "
          f"worker, against the loop; fixed cost of a study on 2 workers ~{fixed:.1f} s")
    print(f"targets: throughput speed-up 2 vs 1 worker >= 1.7x; overhead <= 20 % per run of >= 50 ms; "
          f"1000 slews <= 60 s (measured: {t_big * 1000 / max(n_slews, 1):.1f} s for 1000)")
    print(f"CPU time of a run in the loop: {1e3 * c_loop / nb:.0f} ms; 1000 slews on 2 cores "
          f"free for them would take about {1000 * c_loop / nb / 2 + fixed:.0f} s")
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(f"load average at the end: {load:.1f} on {os.cpu_count()} cores"
          + ("  (shared machine: times indicative only)" if load > (os.cpu_count() or 1)
             else ""))


if __name__ == "__main__":
    main()
