# SPDX-License-Identifier: MIT
"""Modal benchmark: the 10 lowest modes of an n-bay double-octahedral chain (truss model,
consistent mass) and of a square space grid, against OpenSeesPy's ``-genBandArpack`` when it
is installed (same model: truss elements with consistent mass, same supports).

Run ``python benchmarks/bench_modal.py [--bays 1000 3000 10000] [--grid 180] [--modes 10]``; it
prints a table of wall-clock times and the largest relative frequency difference between the solvers.
A chain of 10,000 bays is 11 km tall and 1.2 m wide: its lowest eigenvalues are below what
double precision resolves (trussfe says so and prints nan; see docs/modal-buckling.md).
Target (issue 4, item 8): 10,000 bays (180,000 DOFs) in ≤ 1.0 s for the eigen-solution, and the
180 × 180 grid no slower than OpenSeesPy in the same run.
"""
from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

import numpy as np

# Level-1 BLAS on Lanczos vectors gains nothing from threads; on a shared machine the
# threads only contend.  Must be set before numpy is imported.
for _v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from trussfe.errors import AnalysisError  # noqa: E402
from trussfe.fem import discretise  # noqa: E402
from trussfe.fem.modal import solve_modes  # noqa: E402
from trussfe.model.sections import Material, Section  # noqa: E402
from trussfe.model.structure import Structure  # noqa: E402

ALUMINIUM = Material("aluminium", E=71.0e9, G=26.2e9, density=2711.5)
TUBE = Section.tube("tube", 0.01905, 0.016)


def octahedral_chain(bays: int, side: float = 1.2192, longeron: float = 0.889,
                     active: float = 1.1684) -> Structure:
    """A chain of double-octahedral bays at the symmetric position (Lacy ch. 4–5 geometry).

    Base triangle of side ``side``; each midplane node lies over the outer side of a base
    edge, joined to its two ends by longerons of length ``longeron``; the midplane triangle
    has side ``active``; the top plane mirrors the base in the midplane and is the next
    bay's base.  Each bay adds 6 nodes and 18 members (statically determinate): 18 DOFs.
    The base nodes are pinned.
    """
    R = side / np.sqrt(3.0)
    rm = active / np.sqrt(3.0)
    ang_b = np.deg2rad(90.0 + 120.0 * np.arange(3))
    ang_m = ang_b + np.deg2rad(60.0)
    pb = R * np.c_[np.cos(ang_b), np.sin(ang_b)]                 # (3, 2)
    pm = rm * np.c_[np.cos(ang_m), np.sin(ang_m)]
    h = np.sqrt(longeron**2 - np.sum((pm[0] - pb[0]) ** 2))
    nl = 2 * bays + 1                                            # node layers
    layer = np.arange(nl)
    xy = np.where((layer % 2 == 0)[:, None, None], pb[None], pm[None])   # (layer, 3, 2)
    z = np.broadcast_to((layer * h)[:, None, None], (nl, 3, 1))
    coords = np.concatenate([xy, z], axis=2).reshape(-1, 3)
    nid = lambda L, i: 3 * L + (i % 3)  # noqa: E731
    b = np.arange(bays)
    conn = []
    for i in range(3):
        lo, mid, hi = 2 * b, 2 * b + 1, 2 * b + 2
        conn.append(np.c_[nid(mid, i), nid(mid, i + 1)])         # midplane (active) triangle
        conn.append(np.c_[nid(hi, i), nid(hi, i + 1)])           # top triangle
        # mid node i lies over base edge (i, i+1)
        conn.append(np.c_[nid(lo, i), nid(mid, i)])
        conn.append(np.c_[nid(lo, i + 1), nid(mid, i)])
        conn.append(np.c_[nid(mid, i), nid(hi, i)])
        conn.append(np.c_[nid(mid, i), nid(hi, i + 1)])
    conn = np.vstack(conn)
    n, m = coords.shape[0], conn.shape[0]
    sup = np.zeros((n, 6), dtype=bool)
    sup[:3, :3] = True
    return Structure(
        name=f"double-octahedral chain, {bays} bays", dim=3,
        node_ids=[str(k) for k in range(n)], coords=coords,
        member_ids=[str(k) for k in range(m)], connectivity=conn, sections=[TUBE] * m,
        materials=[ALUMINIUM] * m, is_beam=np.zeros(m, bool), releases=np.zeros((m, 2), bool),
        supports=sup, loads=np.zeros((n, 6)), masses=np.zeros(n), gravity=np.zeros(3))


def space_grid(n: int) -> Structure:
    """The square-on-square space grid of ``benchmarks/_structures.py``."""
    from _structures import space_grid as grid
    return grid(n)


def trussfe_modes(s: Structure, count: int) -> tuple[np.ndarray, dict]:
    t0 = time.perf_counter()
    fe = discretise(s)
    t1 = time.perf_counter()
    try:
        f = solve_modes(s, count=count, fe=fe).frequencies_hz
    except AnalysisError as err:     # lowest modes below double-precision resolution
        print(f"trussfe: {err}", file=sys.stderr)
        f = np.full(count, np.nan)
    t2 = time.perf_counter()
    return f, {"discretise": t1 - t0, "assemble+eigen": t2 - t1}


def opensees_modes(s: Structure, count: int) -> tuple[np.ndarray, dict] | None:
    try:
        import openseespy.opensees as ops
    except ImportError:
        return None
    t0 = time.perf_counter()
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    for i, x in enumerate(s.coords):
        ops.node(i + 1, *map(float, x))
    for i in np.flatnonzero(s.supports[:, :3].any(axis=1)):
        ops.fix(int(i) + 1, *map(int, s.supports[i, :3]))
    ops.uniaxialMaterial("Elastic", 1, float(s.materials[0].E))
    A = float(s.sections[0].area)
    rho = float(s.materials[0].density) * A
    for e, (a, b) in enumerate(s.connectivity):
        ops.element("Truss", e + 1, int(a) + 1, int(b) + 1, A, 1, "-rho", rho, "-cMass", 1)
    t1 = time.perf_counter()
    lam = np.array(ops.eigen("-genBandArpack", count))
    t2 = time.perf_counter()
    ops.wipe()
    return np.sqrt(np.abs(lam)) / (2 * np.pi), {"build": t1 - t0, "eigen": t2 - t1}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bays", type=int, nargs="+", default=[1000, 3000, 10000])
    ap.add_argument("--grid", type=int, default=180)
    ap.add_argument("--modes", type=int, default=10)
    ap.add_argument("--no-opensees", action="store_true")
    a = ap.parse_args(argv)
    rows = []
    cases = [(f"chain {b}", octahedral_chain(b)) for b in a.bays]
    if a.grid:
        cases.append(("grid", space_grid(a.grid)))
    for name, s in cases:
        f, t = trussfe_modes(s, a.modes)
        ops = None if a.no_opensees else opensees_modes(s, a.modes)
        diff = float(np.max(np.abs(ops[0] / f - 1))) if ops else float("nan")
        rows.append((name, 3 * s.n_nodes - int(s.supports[:, :3].sum()), t["discretise"],
                     t["assemble+eigen"], ops[1]["eigen"] if ops else float("nan"),
                     ops[1]["build"] if ops else float("nan"), diff, f[0], f[-1]))
    print(f"{'model':>11} {'free DOFs':>10} {'discretise':>11} {'asm+eigen':>10} "
          f"{'OpenSees eigen':>15} {'OpenSees build':>15} {'max |df/f|':>11} "
          f"{'f1 [Hz]':>12} {'f_last [Hz]':>12}")
    for r in rows:
        print(f"{r[0]:>11} {r[1]:>10d} {r[2]:>10.3f}s {r[3]:>9.3f}s {r[4]:>14.3f}s "
              f"{r[5]:>14.3f}s {r[6]:>11.2e} {r[7]:>12.6g} {r[8]:>12.6g}")


if __name__ == "__main__":
    main()
