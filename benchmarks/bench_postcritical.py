# SPDX-License-Identifier: MIT
"""Speed of the post-critical analysis.

Targets (docs/performance.md):

* the von Mises truss's full path, 200 arc-length steps: < 1 s;
* progressive failure of a 10^4-member lattice through 50 member events: < 60 s.

Also timed, without a target: the 3-D co-rotational beam (internal forces and the consistent
tangent of a 9800-member grid modelled as pinned beams, 2 elements per member, assembled), and
the 3-D Euler column's imperfect path (the validation case).

Run ``python benchmarks/bench_postcritical.py [--grid N] [--events K]``; prints a table.
"""
from __future__ import annotations

import argparse
import time

import numpy as np

from trussfe._resources import mesh_path
from trussfe.io.model_file import read_model
from trussfe.nonlinear import NonlinearModel, follow_path
from trussfe.studies.postcritical import double_layer_grid
from trussfe.linalg import factor



def von_mises(steps: int = 200):
    s = read_model(mesh_path("postcritical_von_mises.toml"))
    m = NonlinearModel(s)
    t = time.perf_counter()
    r = follow_path(m, "arc-length", steps=steps, step=0.0015, monitor=m.dof(1, 1))
    dt = time.perf_counter() - t
    return dt, f"{len(r.path)} points, {len(r.events)} events, v_end = " \
               f"{-r.path[-1].u[r.monitor]:.3f} m", 1.0


def lattice(n: int = 36, events: int = 50, law: str = "cap"):
    s, laws = double_layer_grid(n, law=law)
    t = time.perf_counter()
    m = NonlinearModel(s, laws=laws)
    centre = (n // 2) * n + n // 2
    # first arc length: the linear displacement norm of one load factor unit
    free = np.flatnonzero(m.free)
    K = m.reference_tangent()[free][:, free]
    ds = float(np.linalg.norm(factor(K, "symmetric").solve(m.load[free], refine=False)))
    r = follow_path(m, "arc-length", steps=100000, monitor=m.dof(centre, 2),
                    max_failures=events, step=ds)
    dt = time.perf_counter() - t
    fails = [e for e in r.events if e.kind in ("buckling", "yield", "fracture")]
    worst = max((abs(e.force / e.threshold - 1) for e in fails), default=float("nan"))
    return dt, (f"{s.n_members} members, {int(m.free.sum())} DOF, {len(fails)} events "
                f"(λ {fails[0].load_factor:.3f} … {fails[-1].load_factor:.3f}), "
                f"{len(r.path)} points, max |N/N_law − 1| = {worst:.1e}"), 60.0


def beam3d_grid(n: int = 36):
    s, _ = double_layer_grid(n)
    m = NonlinearModel(s, bar_model="pinned-beam", subdivisions=2)
    u = np.zeros(m.ndof)
    m.evaluate(u)                                   # warm-up
    t = time.perf_counter()
    res = m.evaluate(u)
    dt = time.perf_counter() - t
    return dt, (f"{len(m.b_conn)} beam elements, {m.ndof} DOF, "
                f"{res['tangent'].nnz} tangent entries"), None


def euler_column_3d():
    from trussfe.nonlinear.analysis import run_postcritical
    s = read_model(mesh_path("postcritical_euler_column_3d.toml"))
    t = time.perf_counter()
    r = run_postcritical(s, steps=200)
    dt = time.perf_counter() - t
    return dt, f"{len(r.path)} points, λ_end = {r.load_factors[-1]:.4f}", None


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--grid", type=int, default=36, help="grid size n (9800 bars for 36)")
    ap.add_argument("--events", type=int, default=50)
    ap.add_argument("--law", default="cap", choices=("cap", "remove"))
    a = ap.parse_args()
    rows = [("von Mises truss, 200 arc-length steps",) + von_mises(),
            (f"double-layer grid {a.grid}x{a.grid}, {a.events} events ({a.law})",)
            + lattice(a.grid, a.events, a.law),
            (f"3-D beams: forces + tangent, grid {a.grid}x{a.grid}",) + beam3d_grid(a.grid),
            ("3-D Euler column, imperfect path",) + euler_column_3d()]
    print(f"{'case':<48} {'time (s)':>9} {'target':>7}  result")
    for name, dt, info, target in rows:
        if target is None:
            print(f"{name:<48} {dt:9.2f} {'-':>7}  {info}")
            continue
        ok = "ok" if dt < target else "SLOW"
        print(f"{name:<48} {dt:9.2f} {target:7.1f}  {ok}: {info}")


if __name__ == "__main__":
    from trussfe.cli import environment_workers
    from trussfe.threads import compute_threads

    with compute_threads(workers=environment_workers(), blas=1):   # as the trussfe command
        main()
