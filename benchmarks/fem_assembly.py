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
from trussfe.model.sections import Material, Section  # noqa: E402
from trussfe.model.structure import Structure  # noqa: E402

ALUMINIUM = Material("aluminium", E=71.0e9, G=26.2e9, density=2711.5)
TUBE = Section.tube("tube", 0.01905, 0.62 * 0.0254)
# Appendix D equilibrium bay: base triangle, midplane triangle, member "Connect" order
BASE = np.array([[-0.6096, -0.3519], [0.6096, -0.3519], [0.0, 0.7039]])
MID = np.array([[-0.5842, 0.3373], [0.5842, 0.3373], [0.0, -0.6746]])
CONNECT = np.array([(2, 6), (1, 6), (1, 4), (3, 4), (3, 5), (2, 5), (4, 5), (5, 6), (4, 6),
                    (6, 9), (6, 7), (4, 7), (4, 8), (5, 8), (5, 9), (7, 9), (8, 7), (8, 9)]) - 1


def chain(n: int) -> Structure:
    """n stacked double-octahedral bays, base fixed, 44.498 N on the top nodes."""
    h = 0.5609
    xy = np.vstack([MID if j % 2 else BASE for j in range(2 * n + 1)])
    coords = np.column_stack([xy, np.repeat(np.arange(2 * n + 1) * h, 3)])
    local = np.array([0, 1, 2, 3, 4, 5, 6, 8, 7])     # Appendix D node → offset in 3 layers
    conn = (6 * np.arange(n)[:, None, None] + local[CONNECT][None]).reshape(-1, 2)
    nn, m = len(coords), len(conn)
    sup = np.zeros((nn, 6), bool)
    sup[:3, :3] = True
    loads = np.zeros((nn, 6))
    loads[-3:, 2] = 44.498
    return Structure(name=f"chain {n}", dim=3, node_ids=[str(i) for i in range(nn)],
                     coords=coords, member_ids=[str(i) for i in range(m)], connectivity=conn,
                     sections=[TUBE] * m, materials=[ALUMINIUM] * m,
                     is_beam=np.zeros(m, bool), releases=np.zeros((m, 2), bool),
                     supports=sup, loads=loads, masses=np.zeros(nn),
                     gravity=np.array([0.0, 0.0, -9.81]))


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
