# SPDX-License-Identifier: MIT
"""Load cases: one factorisation for every case against one static solve per case.

A space grid (``_structures.space_grid``, statically indeterminate) carries ``N`` load cases,
each a different nodal load pattern (and every third a length error of one member); the
script times ``solve_load_cases`` (K factorised once, all cases solved together, each
recovered) against ``N`` separate solves (``solve_static`` with the same loads, or a one-case
``solve_load_cases`` for a length error), and prints the ratio
and the largest difference of the member forces (the two routes agree to round-off).  The
stiffness of a grid is not a band: the sparse factorisation dominates, so the ratio tends to
``N`` times the factorisation over the recovery as ``N`` grows.

Usage::

    python benchmarks/bench_load_cases.py               # 60 x 60 grid, 1, 4, 16 cases
    python benchmarks/bench_load_cases.py --cells 120 --cases 1 8 32
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _structures import space_grid  # noqa: E402

from trussfe.fem.load_cases import solve_load_cases  # noqa: E402
from trussfe.fem.static import solve_static  # noqa: E402
from trussfe.model.load_cases import LoadCase, LoadCases  # noqa: E402


def _cases(structure, n: int, seed: int = 1) -> list[LoadCase]:
    rng = np.random.default_rng(seed)
    free = ~structure.supports
    out = []
    for k in range(n):
        loads = np.where(free, rng.normal(size=structure.supports.shape), 0.0) * 100.0
        loads[:, structure.dim:] = 0.0
        error = None
        if k % 3 == 2:
            error = np.zeros(structure.n_members)
            error[rng.integers(structure.n_members)] = 1e-4
        out.append(LoadCase(f"c{k}", loads, length_error=error))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cells", type=int, default=60)
    ap.add_argument("--cases", type=int, nargs="+", default=[1, 4, 16])
    args = ap.parse_args()
    grid = space_grid(args.cells)
    print(f"space grid {args.cells} x {args.cells}: {grid.n_nodes} nodes, "
          f"{grid.n_members} members")
    print(f"{'cases':>6}  {'together [s]':>12}  {'one by one [s]':>14}  {'ratio':>6}  "
          f"{'max |dN| / max |N|':>18}")
    for n in args.cases:
        cases = _cases(grid, n)
        model = grid.with_extensions(load_cases=LoadCases(cases=tuple(cases)))
        t0 = time.perf_counter()
        sol = solve_load_cases(model)
        t1 = time.perf_counter()
        diff, scale = 0.0, 0.0
        for c in cases:
            # one case at a time: discretise, factorise, solve, recover (solve_static for a
            # nodal load, a one-case solve for a length error)
            if c.length_error is None:
                r = solve_static(grid, loads=c.loads, self_weight=False)
            else:
                r = solve_load_cases(model, cases=[c.name]).cases[c.name]
            diff = max(diff, float(np.abs(r.axial_force - sol.cases[c.name].axial_force).max()))
            scale = max(scale, float(np.abs(r.axial_force).max()))
        t2 = time.perf_counter()
        print(f"{n:>6}  {t1 - t0:12.3f}  {t2 - t1:14.3f}  {(t2 - t1) / (t1 - t0):6.2f}  "
              f"{diff / scale if scale else 0.0:18.2e}")


if __name__ == "__main__":
    main()
