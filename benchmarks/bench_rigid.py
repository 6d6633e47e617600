# SPDX-License-Identifier: MIT
"""Speed of the rigid-body dynamic force model (targets in docs/performance.md); prints a table.

Cases (each a whole ``simulate``: kinematics, nodal forces, axial forces at the sections,
buckling, actuator force; the shears, moments and stresses of the sections are computed on
first access to them, so every case is timed twice: ``simulate`` alone, and ``simulate`` plus
the first access to every output, ``res.sections``, ``res.static_sections``, ``res.stresses``,
``res.static_stresses``, which is what a caller who reads everything pays):

- the double-octahedral slew with 10,000 time steps; target ≥ 6× the dense-117 loop;
- chains of 10, 100 and 1,000 double-octahedral bays over 1,000 steps (the automatic method:
  bay by bay): target ≥ 12× the dense-117 loop for the 100-bay chain (the whole motion at
  once), and a time per bay and step that stays flat from 10 to 1,000 bays (O(n) per step),
  shown on the motion run as ten consecutive pieces of 100 steps (the whole result of the
  1,000-bay chain, about 10 GB, would not fit beside the other runs; the bays' positions of
  a step do not depend on the other steps, so the pieces give the same numbers); the 100-bay
  chain also with ``method="direct"``, and the largest difference of its member forces from
  the bay-by-bay ones.

The reference is a plain per-step dense solve of a 117 × 117 system (the size of Lacy's
double-octahedron system, eq. 4.20 / Table 4.1) in a Python loop over the steps, timed in
the same run after every case and taken at its fastest, as every trussfe time is; for a
chain, one such solve per bay and step (extrapolated).

Run from the source tree: ``PYTHONPATH=$PWD python benchmarks/bench_rigid.py [--quick]
[--repeat N]``.
"""
from __future__ import annotations

import argparse
import json
import os
import time

# One BLAS thread: the stacked small solves gain nothing from BLAS threads, and on a shared
# machine oversubscribed BLAS threads slow them down twentyfold (measured).  trussfe's own
# worker threads (trussfe.threads) take independent blocks of steps instead.
for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from trussfe.rigid.motion import Motion, third_order_motion, third_order_response  # noqa: E402
from trussfe.studies.lacy_rigid import double_octahedral_chain, double_octahedron  # noqa: E402
from trussfe.rigid.simulate import simulate  # noqa: E402
from trussfe.threads import worker_count  # noqa: E402
from trussfe.allocator import tune_allocator  # noqa: E402

tune_allocator()   # numpy temporaries reuse heap pages, as in the trussfe command


def access_outputs(res) -> None:
    """Read every output of a result that is computed on first access."""
    res.sections, res.static_sections, res.stresses, res.static_stresses


def _best(fn, repeat, access=access_outputs):
    """Best wall-clock and process (CPU) times over ``repeat`` runs of ``fn``, the same of
    ``fn`` followed by ``access`` of its result (every output materialised), and the last
    result.

    On a shared machine the CPU time is the steadier figure."""
    best, cpu, best_all, cpu_all = np.inf, np.inf, np.inf, np.inf
    out = None
    for _ in range(repeat):
        out = None                       # the previous result's memory is reused
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        t1, c1 = time.perf_counter(), time.process_time()
        access(out)
        t2, c2 = time.perf_counter(), time.process_time()
        best, cpu = min(best, t1 - t0), min(cpu, c1 - c0)
        best_all, cpu_all = min(best_all, t2 - t0), min(cpu_all, c2 - c0)
    return (best, cpu, best_all, cpu_all), out


class Dense117:
    """The reference: a per-step dense solve of Lacy's 117 × 117 system (assembled by
    :func:`trussfe.studies.lacy_newton_euler.newton_euler_system` from a slew's kinematics,
    solved step by step in a Python loop), timed on up to 2,000 steps.

    :meth:`measure` is called between the cases, and every row uses the fastest of all the
    measurements (as every trussfe time is the fastest of its runs): a reference timed once
    in a slow minute of a shared machine would flatter every ratio (seen: 1.81 s where the
    same run's other minutes gave 1.04–1.30 s)."""

    def __init__(self, structure, result):
        from trussfe.studies.lacy_newton_euler import newton_euler_system
        A, b, _ = newton_euler_system(structure, result.kinematics)
        k = min(A.shape[0], 2000)
        self.A, self.b = A[:k].copy(), b[:k].copy()
        self.per_solve = np.inf
        self.times: list[float] = []

    def measure(self) -> None:
        """Two timings of the loop; the fastest per solve is kept."""
        k = self.A.shape[0]
        for _ in range(2):
            t0 = time.perf_counter()
            for i in range(k):
                np.linalg.solve(self.A[i], self.b[i])
            dt = time.perf_counter() - t0
            self.times.append(dt / k)
            self.per_solve = min(self.per_solve, dt / k)


def result_bytes(res) -> int:
    """Bytes of the arrays a simulation result holds (views counted once, by their base),
    including the outputs computed on first access if they have been."""
    import dataclasses
    seen: dict[int, int] = {}

    def walk(obj):
        if isinstance(obj, np.ndarray):
            base = obj if obj.base is None else obj.base
            if isinstance(base, np.ndarray):
                seen[id(base)] = base.nbytes
        elif isinstance(obj, tuple):
            for o in obj:
                walk(o)
        elif dataclasses.is_dataclass(obj) and not isinstance(obj, type):
            for f in dataclasses.fields(obj):
                if f.name not in ("structure", "motion"):
                    walk(getattr(obj, f.name))
    walk(res)
    lazy = getattr(res, "_sections", None)
    if lazy is not None and lazy.evaluated:
        walk(lazy.get())
    return sum(seen.values())


def chain_motion(chain, bays: int, duration: float, steps: int, k0: int = 0,
                 k1: int | None = None) -> Motion:
    """Steps ``k0:k1`` of a third-order motion of ``steps`` steps in which every bay slews by
    ±0.02 m on M7/8 in alternate directions, so that the chain stays roughly straight (one
    direction for all bays would curl 100 bays into a spiral)."""
    acts = np.array([a.member for a in chain.extensions["active_members"]])
    L0 = chain.lengths()[acts]
    d = np.zeros_like(L0)
    d[0::3] = 0.02 * (-1.0) ** np.arange(bays)
    if k0 == 0 and k1 is None:
        return third_order_motion(chain, L0, L0 + d, duration, steps)
    t = np.arange(k0, k1) * (duration / steps)
    y, dy, ddy = third_order_response(t, duration)
    return Motion(time=t, members=acts, length=L0 + np.outer(y, d), velocity=np.outer(dy, d),
                  acceleration=np.outer(ddy, d), source="benchmark", first_step=k0)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="smaller runs (smoke test)")
    ap.add_argument("--repeat", type=int, default=2,
                    help="runs of each case; the best is shown (default 2; slew 3)")
    ap.add_argument("--no-numpy-hugepages", action="store_true",
                    help="turn off numpy's transparent-huge-page advice for its arrays (the "
                         "trussfe command keeps it); shows what it costs repeated runs in "
                         "one process")
    ap.add_argument("--json", metavar="PATH",
                    help="also write the table's rows to PATH as JSON (bench_targets.py)")
    args = ap.parse_args()
    if args.no_numpy_hugepages:
        np._core.multiarray._set_madvise_hugepage(False)
        print("numpy huge-page advice: off")
    rep = max(1, args.repeat)
    rows = []

    nt = 1000 if args.quick else 10000
    s = double_octahedron((1.2289, 1.1079, 1.1079), gravity=-9.81, top_load=46.0)
    m = third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289], 2.0, nt)
    t, res = _best(lambda: simulate(s, m, n_sections=1), max(3, rep))
    dense = Dense117(s, res)
    dense.measure()
    # (the reference loop is timed on the wall clock, like the first time column); a row
    # keeps the number of dense solves it stands for and its target ratio
    rows.append(("double octahedron slew", res.options["method"], s.n_members, 1, nt, *t,
                 6.0, nt, result_bytes(res)))
    del res

    nt2 = 200 if args.quick else 1000
    agreement = None
    # (bays, pieces): the 12x target on the whole motion; the growth with the number of bays
    # on equal pieces of the motion (the 1,000-bay chain cannot hold all 1,000 steps at once)
    runs = ([(3, 1), (10, 1), (3, 2), (10, 2)] if args.quick else
            [(10, 1), (100, 1), (10, 10), (100, 10), (1000, 10)])
    for bays, pieces in runs:
        c = double_octahedral_chain(bays, gravity=9.81, top_load=46.0)
        solves = nt2 * bays                       # one 117 × 117 solve per bay and step
        cuts = np.linspace(0, nt2, pieces + 1).astype(int)
        motions = [chain_motion(c, bays, 2.0, nt2, a, b if pieces > 1 else None)
                   for a, b in zip(cuts[:-1], cuts[1:])]

        def run(method="auto"):
            """Every piece of the motion in turn: the pieces' times (simulate; simulate and
            every output) added, the bytes of all pieces' results, the last result."""
            total = np.zeros(4)
            size = 0
            out = None
            for mo in motions:
                out = None
                t_piece, out = _best(lambda: simulate(c, mo, n_sections=1, method=method), 1)
                total += t_piece
                size += result_bytes(out)
            return tuple(total), size, out

        def best_of(method, repeat):
            times, size, out = (np.inf,) * 4, 0, None
            for _ in range(repeat):
                out = None
                t_run, size, out = run(method)
                times = tuple(np.minimum(times, t_run))
            return times, size, out
        name = f"{bays}-bay chain" + (f" ({pieces} x {nt2 // pieces} steps)" if pieces > 1
                                      else "")
        if bays == (10 if args.quick else 100) and pieces == 1:
            # both methods in turn, so that neither has the other's warm memory alone
            ta = td = (np.inf,) * 4
            for _ in range(rep):
                t1, size, rc = best_of("auto", 1)
                tension = rc.forces.tension_end
                meth_a = rc.options["method"]
                del rc
                t2, _, rd = best_of("direct", 1)
                ta, td = tuple(np.minimum(ta, t1)), tuple(np.minimum(td, t2))
                agreement = (bays, float(np.abs(rd.forces.tension_end - tension).max()
                                         / np.abs(tension).max()))
                meth_d = rd.options["method"]
                del rd, tension
            rows.append((name, meth_a, c.n_members, bays, nt2, *ta, 12.0, solves, size))
            rows.append((name, meth_d, c.n_members, bays, nt2, *td, 12.0, solves, size))
            dense.measure()
            continue
        tc, size, rc = best_of("auto", 1 if bays >= 1000 else rep)
        rows.append((name, rc.options["method"], c.n_members, bays, nt2, *tc, 12.0,
                     solves, size))
        del rc
        dense.measure()

    print(f"{'case':30s} {'method':>10s} {'members':>8s} {'steps':>7s} {'wall s':>8s} "
          f"{'cpu s':>8s} {'target s':>9s} {'us/(bay*step)':>14s} {'dense-117 loop s':>17s} "
          f"{'speed-up':>9s} {'all-out wall s':>15s} {'cpu s':>8s} {'speed-up':>9s} "
          f"{'result GB':>10s}")
    table = []
    for name, meth, mm, nb, n, tt, cpu, tt_all, cpu_all, ratio, solves, size in rows:
        r = dense.per_solve * solves
        target = r / ratio
        table.append({"case": name, "method": meth, "members": mm, "bays": nb, "steps": n,
                      "wall": tt, "cpu": cpu, "target_s": target,
                      "us_per_bay_step": 1e6 * tt / (n * nb), "reference": "dense-117 loop",
                      "reference_s": r, "speed_up": r / tt, "all_out_wall": tt_all,
                      "all_out_speed_up": r / tt_all, "target_ratio": ratio,
                      "result_gb": size / 1e9})
        print(f"{name:30s} {meth:>10s} {mm:8d} {n:7d} {tt:8.3f} {cpu:8.3f} {target:9.3f} "
              f"{1e6 * tt / (n * nb):14.2f} {r:17.3f} {r / tt:9.1f} {tt_all:15.3f} "
              f"{cpu_all:8.3f} {r / tt_all:9.1f} {size / 1e9:10.2f}")
    print(f"worker threads: {worker_count()} (TRUSSFE_THREADS); wall and cpu: best of "
          f"{max(3, rep)} runs (slew), {rep} (chains up to 100 bays), 1 (1,000 bays); "
          "a chain in pieces: the pieces' times added")
    print("wall s, cpu s: simulate (section shears, moments and stresses not yet computed); "
          "all-out: simulate and the first access to every output (sections, static_sections, "
          "stresses, static_stresses)")
    print("result GB: the arrays the analysis returns, every output computed (a chain in "
          "pieces: all pieces)")
    print("dense-117 loop: one np.linalg.solve of Lacy's 117 x 117 system (eq. 4.20) per step, "
          "assembly excluded; for a chain, one per bay and step.  Targets: slew 6x, chains 12x "
          "the dense loop.")
    times = np.array(dense.times) * 1e6
    print(f"dense-117 loop per solve: the fastest of {times.size} timings of "
          f"{dense.A.shape[0]:,} steps between the cases, {times.min():.1f} us (slowest "
          f"{times.max():.1f} us)")
    if agreement is not None:
        print(f"member forces of the {agreement[0]}-bay chain, bay-by-bay against direct: "
              f"largest difference {agreement[1]:.1e} of the largest force")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"rows": table, "workers": worker_count(),
                       "dense_per_solve_us": [float(t) for t in times],
                       "agreement": None if agreement is None else
                       {"bays": agreement[0], "relative_difference": agreement[1]}},
                      fh, indent=1)


if __name__ == "__main__":
    from trussfe.cli import environment_workers
    from trussfe.threads import compute_threads

    with compute_threads(workers=environment_workers(), blas=1):   # as the trussfe command
        main()
