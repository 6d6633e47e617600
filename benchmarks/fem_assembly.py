# SPDX-License-Identifier: MIT
"""Cost of the finite-element core: discretisation (transformation T), assembly of K, M and
K_g on the exploded local-axis meshes, and recovery of element forces, for a chain of n
double-octahedral bays (truss model) and a pinned-beam space grid.

Run ``python benchmarks/fem_assembly.py [n_bays ...]``; it prints one table row per model.
Solver times are measured by the static benchmarks; here ``u`` is a random vector.
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from trussfe.fem import discretise  # noqa: E402
from trussfe.model.structure import Structure  # noqa: E402
from trussfe.models import TABLE_LOAD, double_octahedral_chain  # noqa: E402


def chain(n: int) -> Structure:
    """n stacked double-octahedral bays (the catalogue chain), base fixed, 44.498 N on the top
    nodes, gravity."""
    return double_octahedral_chain(n, tip_load=TABLE_LOAD, gravity=[0.0, 0.0, -9.81])


def _time(fn):
    t = time.perf_counter()
    out = fn()
    return out, time.perf_counter() - t


def row(name, structure, bar_model, k=None):
    structure.area, structure.E, structure.density        # property tables, read once
    fe, t_d = _time(lambda: discretise(structure, bar_model=bar_model, subdivisions=k))
    _, t_k = _time(fe.stiffness)
    _, t_m = _time(fe.mass)
    _, t_g = _time(lambda: fe.geometric_stiffness(np.ones(fe.n_elements)))
    _, t_f = _time(fe.load_vector)
    u = np.random.default_rng(0).standard_normal(fe.n_dof)
    _, t_e = _time(lambda: fe.element_forces(u))
    print(f"| {name:<28} | {bar_model:<11} | {fe.n_elements:>9} | {fe.n_dof:>9} | {t_d:7.3f} "
          f"| {t_k:7.3f} | {t_m:7.3f} | {t_g:7.3f} | {t_f:7.3f} | {t_e:7.3f} |")


def main(argv: list[str]) -> None:
    sizes = [int(a) for a in argv] or [10, 100, 1000, 10000]
    print("| model | bar model | elements | DOFs | discretise s | K s | M s | K_g s | f s "
          "| element forces s |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for n in sizes:
        row(f"chain of {n} bays", chain(n), "truss")
    for n in sizes[:-1] if len(sizes) > 1 else sizes:
        row(f"chain of {n} bays, k = 4", chain(n), "pinned-beam", 4)


if __name__ == "__main__":
    main(sys.argv[1:])
