# SPDX-License-Identifier: MIT
"""Mechanism-analysis benchmarks: trace speed on a large spatial mechanism, rank of a large
framework.  Prints a table; targets (docs/performance.md): ≥ 10 steps/s tracing 1,000 joints (3,000
coordinates), rank analysis of a 10^5-bar framework in < 10 s.

Run: ``python benchmarks/bench_mechanism.py [--quick]``.
"""
from __future__ import annotations

import argparse
import time

import numpy as np

from trussfe.kinematics import rank_analysis, trace_mechanism



def spatial_mechanism(n_joints: int, seed: int = 0):
    """A one-degree-of-freedom spatial assembly of ``n_joints`` free joints: the change-point
    four-bar of the section-9 construction plus Henneberg joints (three bars each) on its crank
    and rocker bodies; 3·n − 1 bars, full row rank."""
    rng = np.random.default_rng(seed)
    theta = np.deg2rad(150.0)
    P = np.array([np.cos(theta), np.sin(theta), 0.0])
    D = np.array([3.0, 0.0, 0.0])
    w = D - P
    dist = np.linalg.norm(w)
    u = w / dist
    along = (2.5 ** 2 - 1.5 ** 2 + dist ** 2) / (2 * dist)
    h = np.sqrt(2.5 ** 2 - along ** 2)
    Q = P + along * u - h * np.array([-u[1], u[0], 0.0])
    pts = [P, Q, [0, 0, 1], [0, 0, -1], [3, 0, 1], [3, 0, -1]]
    bars = [(0, 2), (0, 3), (1, 4), (1, 5), (0, 1)]
    bodies = [[0, 2, 3], [1, 4, 5]]
    for k in range(n_joints - 2):
        body = bodies[k % 2]
        while True:                                       # anchors spanning a good triangle
            pick = rng.choice(np.array(body), 3, replace=False)
            a, b, c = (np.asarray(pts[i]) for i in pick)
            normal = np.cross(b - a, c - a)
            if np.linalg.norm(normal) > 0.2 * max(np.linalg.norm(b - a), 1e-9) ** 2:
                break
        normal /= np.linalg.norm(normal)
        # off the anchors' plane (well-conditioned), drifting away from the axis
        pts.append((a + b + c) / 3 + 0.6 * normal + rng.normal(0, 0.1, 3))
        bars += [(int(i), len(pts) - 1) for i in pick]
        body.append(len(pts) - 1)
    X = np.array(pts, float)
    free = np.ones(X.shape, bool)
    free[2:6] = False
    return X, np.array(bars), free


def lattice(nx: int, ny: int, nz: int):
    """A braced cubic lattice (each cube: 12 edges shared + face and body diagonals)."""
    g = np.stack(np.meshgrid(np.arange(nx + 1), np.arange(ny + 1), np.arange(nz + 1),
                             indexing="ij"), -1).reshape(-1, 3).astype(float)
    idx = np.arange(g.shape[0]).reshape(nx + 1, ny + 1, nz + 1)
    bars = []
    for d in [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (0, 1, 1), (1, 0, 1), (1, 1, 1)]:
        a = idx[: nx + 1 - d[0], : ny + 1 - d[1], : nz + 1 - d[2]]
        b = idx[d[0]:, d[1]:, d[2]:]
        bars.append(np.column_stack([a.ravel(), b.ravel()]))
    free = np.ones(g.shape, bool)
    free[idx[:, :, 0].ravel()] = False                    # base fixed
    return g, np.vstack(bars), free


def grid2d(nx: int, ny: int):
    """A triangulated plane grid (squares with one diagonal), pinned and on a roller."""
    xs, ys = np.meshgrid(np.arange(nx + 1.0), np.arange(ny + 1.0), indexing="ij")
    X = np.column_stack([xs.ravel(), ys.ravel()])
    idx = np.arange(X.shape[0]).reshape(nx + 1, ny + 1)
    bars = np.vstack([np.column_stack([idx[:-1].ravel(), idx[1:].ravel()]),
                      np.column_stack([idx[:, :-1].ravel(), idx[:, 1:].ravel()]),
                      np.column_stack([idx[:-1, :-1].ravel(), idx[1:, 1:].ravel()])])
    free = np.ones(X.shape, bool)
    free[idx[0, 0]] = False
    free[idx[-1, 0], 1] = False
    return X, bars, free


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="smaller sizes")
    args = ap.parse_args()
    rows = []
    for n in ((100, 300) if args.quick else (100, 300, 1000)):
        X, bars, free = spatial_mechanism(n)
        steps = 20
        t, c = time.perf_counter(), time.process_time()
        r = trace_mechanism(X, bars, free, drives=[1], step=-0.02, steps=steps)
        dt, dc = time.perf_counter() - t, time.process_time() - c
        xe = r.coords[-1]
        misfit = np.max(np.abs(np.linalg.norm(xe[bars[:, 1]] - xe[bars[:, 0]], axis=1)
                               - np.linalg.norm(X[bars[:, 1]] - X[bars[:, 0]], axis=1)))
        rows.append((f"trace {n} joints ({3 * n} coords, {len(bars)} bars)",
                     f"{steps / dt:.1f} steps/s ({steps / dc:.1f} cpu)",
                     "≥ 10 steps/s" if n == 1000 else "",
                     f"misfit {misfit:.1e} m"))
    cases = [("3-D", lambda: lattice(6, 6, 6))]
    if not args.quick:
        cases += [("2-D", lambda: grid2d(182, 182)), ("3-D", lambda: lattice(17, 17, 23)),
                  ("3-D", lambda: lattice(22, 22, 28))]
    for label, make in cases:
        X, bars, free = make()
        size = f"{label} {X.shape[0]} joints"
        for backend in ("auto", "superlu") if len(bars) < 6e4 or not args.quick else ("auto",):
            if backend == "superlu" and len(bars) > 6e4:
                continue                                   # ~20 s: the reason for PARDISO
            t, c = time.perf_counter(), time.process_time()
            r = rank_analysis(X, bars, free, sparse_backend=backend)
            dt, dc = time.perf_counter() - t, time.process_time() - c
            used = r.extra.get("sparse_backend", "dense")
            rows.append((f"rank, {size}: {len(bars)} bars, {int(free.sum())} coords [{used}]",
                         f"{dt:.2f} s ({dc:.2f} cpu)", "< 10 s" if len(bars) >= 1e5 else "",
                         f"rank {r.rank}, m {r.mechanisms}, s {r.self_stress_states}"))
    w = max(len(r[0]) for r in rows)
    print("wall time (process CPU time in brackets: 2 shared cores)")
    print(f"{'case':<{w}}  {'result':>24}  {'target':>13}  check")
    for c, res, target, chk in rows:
        print(f"{c:<{w}}  {res:>24}  {target:>13}  {chk}")


if __name__ == "__main__":
    from trussfe.cli import environment_workers
    from trussfe.threads import compute_threads

    with compute_threads(workers=environment_workers(), blas=1):   # as the trussfe command
        main()
