# SPDX-License-Identifier: MIT
"""Modal benchmark: the 10 lowest modes of an n-bay double-octahedral chain (truss model,
consistent mass) and of a square space grid, against OpenSeesPy's ``-genBandArpack`` when it
is installed (same model: truss elements with consistent mass, same supports).

Run ``python benchmarks/bench_modal.py [--bays 1000 3000 10000] [--grid 180] [--modes 10]``;
it prints a table of wall-clock and process times, eigen-residuals and the largest relative
frequency difference between the solvers.
A chain of 10,000 bays is 11 km tall and 1.2 m wide: its lowest eigenvalues are below what
double precision resolves.  The benchmark still times it and prints, beside every row, the
largest eigen-residual of trussfe's modes and of OpenSeesPy's (computed with trussfe's K and M),
flagging the row "unresolved" (``trussfe modes`` refuses such a model; docs/modal-buckling.md).
Target (docs/performance.md): 10,000 bays (180,000 DOFs) in ≤ 1.0 s for the eigen-solution, and the
180 × 180 grid no slower than OpenSeesPy in the same run.
"""
from __future__ import annotations

import argparse
import json
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
sys.path.insert(0, str(Path(__file__).resolve().parent))

from trussfe.cli import environment_workers  # noqa: E402
from trussfe.threads import compute_threads  # noqa: E402
from trussfe.allocator import tune_allocator  # noqa: E402

tune_allocator()   # the heap reuse of the trussfe command (trussfe.allocator)
from trussfe.fem import discretise  # noqa: E402
from trussfe.fem.modal import RESOLVED_RESIDUAL, mass_matrix, solve_modes  # noqa: E402
from trussfe.linalg import free_submatrix  # noqa: E402
from trussfe.model.structure import Structure  # noqa: E402
from _peers import blas_note  # noqa: E402
from trussfe.models import double_octahedral_chain  # noqa: E402


def octahedral_chain(bays: int) -> Structure:
    """A chain of double-octahedral bays at the symmetric position (Lacy ch. 4–6), unloaded:
    the catalogue's :func:`trussfe.models.double_octahedral_chain`.  Each bay adds 6 nodes and
    18 members (statically determinate): 18 DOFs.  The base nodes are pinned."""
    return double_octahedral_chain(bays, tip_load=0.0)


def space_grid(n: int) -> Structure:
    """The square-on-square space grid of ``benchmarks/_structures.py``."""
    from _structures import space_grid as grid
    return grid(n)


def trussfe_modes(s: Structure, count: int) -> tuple[np.ndarray, dict]:
    """Time discretisation and assembly + eigen-solution; the resolution check is off so
    that the benchmark can time and show what an unresolvable model gives (the CLI refuses
    it: ``solve_modes`` raises AnalysisError by default)."""
    t0 = time.perf_counter()
    c0 = time.process_time()
    fe = discretise(s)
    t1 = time.perf_counter()
    r = solve_modes(s, count=count, fe=fe, check_resolution=False)
    t2 = time.perf_counter()
    return r, {"discretise": t1 - t0, "assemble+eigen": t2 - t1,
               "cpu": time.process_time() - c0}


def residuals(r, lam: np.ndarray, shapes: np.ndarray) -> np.ndarray:
    """‖K φ − λ M φ‖ / (λ ‖M φ‖) of eigenpairs given on the free DOFs of trussfe's model."""
    fe = r.fe
    free = fe.free
    K = free_submatrix(fe.stiffness(), free)
    M = free_submatrix(mass_matrix(fe), free)
    MV = M @ shapes
    R = K @ shapes - MV * lam
    return np.linalg.norm(R, axis=0) / (np.abs(lam) * np.linalg.norm(MV, axis=0))


def opensees_modes(s: Structure, count: int, r) -> tuple[np.ndarray, dict] | None:
    """OpenSeesPy ``-genBandArpack`` on the same model; eigenvectors are read back and their
    residuals computed with trussfe's K and M (the same consistent truss mass)."""
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
    full = np.zeros((r.fe.n_dof, count))
    for k in range(count):
        full[: 3 * s.n_nodes, k] = np.array(
            [ops.nodeEigenvector(i + 1, k + 1) for i in range(s.n_nodes)]).ravel()
    ops.wipe()
    res = residuals(r, lam, full[r.fe.free])
    return np.sqrt(np.abs(lam)) / (2 * np.pi), {"build": t1 - t0, "eigen": t2 - t1,
                                               "residual": float(res.max())}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bays", type=int, nargs="+", default=[1000, 3000, 10000])
    ap.add_argument("--grid", type=int, default=180)
    ap.add_argument("--modes", type=int, default=10)
    ap.add_argument("--no-opensees", action="store_true")
    ap.add_argument("--json", metavar="PATH",
                    help="also write the table's rows to PATH as JSON (bench_targets.py)")
    a = ap.parse_args(argv)
    rows = []
    cases = [(f"chain {b}", lambda b=b: octahedral_chain(b)) for b in a.bays]
    if a.grid:
        cases.append((f"grid {a.grid}", lambda: space_grid(a.grid)))
    print(f"{'model':>11} {'free DOFs':>10} {'discretise':>11} {'asm+eigen':>10} "
          f"{'cpu':>7} {'residual':>9} {'OpenSees eigen':>15} {'OpenSees res.':>14} "
          f"{'max |df/f|':>11} {'f1 [Hz]':>12} {'f_last [Hz]':>12}")
    for name, build in cases:
        s = build()
        with compute_threads(workers=environment_workers(), blas=1):   # as the command does
            r, t = trussfe_modes(s, a.modes)
        f = r.frequencies_hz
        res = float(np.max(r.residuals))
        ops = None if a.no_opensees else opensees_modes(s, a.modes, r)
        diff = float(np.max(np.abs(ops[0] / f - 1))) if ops else float("nan")
        flag = " unresolved" if res > RESOLVED_RESIDUAL else ""
        print(f"{name:>11} {r.fe.free.size:>10d} {t['discretise']:>10.3f}s "
              f"{t['assemble+eigen']:>9.3f}s {t['cpu']:>6.2f}s {res:>9.1e} "
              f"{ops[1]['eigen'] if ops else float('nan'):>14.3f}s "
              f"{ops[1]['residual'] if ops else float('nan'):>14.1e} {diff:>11.2e} "
              f"{f[0]:>12.6g} {f[-1]:>12.6g}{flag}", flush=True)
        total = t["discretise"] + t["assemble+eigen"]
        rows.append({"model": name, "dof": int(r.fe.free.size), "modes": a.modes,
                     "discretise": t["discretise"], "assemble_eigen": t["assemble+eigen"],
                     "total": total, "cpu": t["cpu"], "residual": res,
                     "resolved": res <= RESOLVED_RESIDUAL,
                     "reference": "OpenSeesPy -genBandArpack" if ops else None,
                     "reference_s": ops[1]["eigen"] if ops else None,
                     "reference_residual": ops[1]["residual"] if ops else None,
                     "speed_up": ops[1]["eigen"] / total if ops else None,
                     "max_frequency_difference": diff if ops else None})
    print(f"\nresidual: max over the modes of ‖Kφ − ω²Mφ‖ / (ω²‖Mφ‖) with trussfe's K and M; "
          f"above {RESOLVED_RESIDUAL} a mode is not resolved in double precision "
          "(trussfe modes refuses it).")
    print(blas_note())
    if a.json:
        Path(a.json).write_text(json.dumps(
            {"rows": rows, "blas": None if a.no_opensees else blas_note()}, indent=1))


if __name__ == "__main__":
    main()
