# SPDX-License-Identifier: MIT
"""Static solve benchmark: chains of double-octahedral bays and an indeterminate space grid.

For each model the script writes it as a line mesh (``.vtu``) plus a TOML file, then times
separately reading the model (``read_model``), assembling (``discretise``, the load vector and
the stiffness — the sparse K, or for a long truss the bars' node blocks that
``solve_static`` sends straight to band storage, timed inside it: ``StaticResult.timings``)
and solving (the rest of ``solve_static``: factorisation, solve, recovery of member forces and
stresses), and prints the relative residual ‖Ku − f‖/‖f‖, computed afterwards with the sparse
K, beside every time.  When OpenSeesPy is installed the same model is built and solved there
(``Truss`` elements, ``BandSPD`` / ``UmfPack`` solvers) and the largest member-force
difference is printed: member forces, not displacements, are compared, because the long chain
is so badly conditioned that two correct solvers disagree on displacements beyond ~300 bays.
OpenSeesPy runs on the system's ``libblas.so.3``: the footer names it, since the reference
implementation makes the peer about three times slower on the grid (``_peers.py``).
``speed-up`` is OpenSeesPy's total time over trussfe's, both measured in the same run;
``peak MiB`` is the process's resident-memory high-water mark during trussfe's runs of the
model (Linux: ``VmHWM`` of ``/proc/self/status``, reset before the model by writing 5 to
``/proc/self/clear_refs``; elsewhere ``resource.getrusage(RUSAGE_SELF).ru_maxrss``, which
never decreases).  Resident memory counts what MKL allocates for PARDISO, which
``tracemalloc`` does not see; it includes the Python process and the model itself.

Usage::

    python benchmarks/bench_static.py                 # chains 10..10,000 bays, grids to 180x180
    python benchmarks/bench_static.py --large         # adds 100,000 bays and a 10^6-DOF grid
    python benchmarks/bench_static.py --no-opensees
    python benchmarks/bench_static.py --repeat 3      # fastest of 3 runs in each program
    python benchmarks/bench_static.py --large --only "10000 " 180x180 410x410

Targets (2-core machine): 10,000 bays read + assemble + solve ≤ 0.5 s and ≥ 6× OpenSeesPy;
100,000 bays ≤ 6 s; 180 × 180 grid ≥ 6× OpenSeesPy; a 10^6-DOF grid (410 × 410 cells) ≤ 8 s.
"""
from __future__ import annotations

import argparse
import ctypes
import gc
import json
import os
import resource
import sys
import tempfile
import time
from pathlib import Path

import meshio
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _peers import blas_note  # noqa: E402
from _structures import space_grid  # noqa: E402

from trussfe import read_model  # noqa: E402
from trussfe.fem import discretise  # noqa: E402
from trussfe.fem.static import solve_static  # noqa: E402
from trussfe.models import double_octahedral_chain  # noqa: E402
from trussfe.cli import environment_workers  # noqa: E402
from trussfe.io.toml_text import compiled_parser  # noqa: E402
from trussfe.threads import compute_threads  # noqa: E402
from trussfe.allocator import tune_allocator  # noqa: E402

tune_allocator()   # the heap reuse of the trussfe command (trussfe.allocator)



def write_as_mesh_model(structure, folder: Path) -> Path:
    """Write ``structure`` as ``model.vtu`` + ``model.toml`` (geometry from the mesh)."""
    mesh = meshio.Mesh(structure.coords, [("line", structure.connectivity)])
    meshio.write(folder / "model.vtu", mesh)
    sec, mat = structure.sections[0], structure.materials[0]
    lines = ["[model]", f'name = "{structure.name}"', "dimension = 3", 'mesh = "model.vtu"', "",
             "[materials.m]", f"E = {mat.E!r}", f"G = {mat.G!r}", f"density = {mat.density!r}",
             "", "[sections.s]", f"outer_diameter = {sec.outer_diameter!r}",
             f"inner_diameter = {sec.inner_diameter!r}", "",
             "[groups.default]", 'section = "s"', 'material = "m"', "", "[supports]"]
    for i in np.flatnonzero(structure.supports[:, :3].any(axis=1)):
        dofs = [d for d, on in zip("xyz", structure.supports[i, :3]) if on]
        lines.append(f"{i} = {dofs!r}".replace("'", '"'))
    lines += ["", "[loads]"]
    for i in np.flatnonzero(np.any(structure.loads[:, :3] != 0, axis=1)):
        lines.append(f"{i} = {structure.loads[i, :3].tolist()!r}")
    path = folder / "model.toml"
    path.write_text("\n".join(lines) + "\n")
    return path


def time_trussfe(structure, folder: Path) -> dict:
    path = write_as_mesh_model(structure, folder)
    c0 = time.process_time()
    t0 = time.perf_counter()
    s = read_model(path)
    t1 = time.perf_counter()
    fe = discretise(s, "truss")
    t2 = time.perf_counter()
    res = solve_static(s, "truss", fe=fe)
    t3 = time.perf_counter()
    cpu = time.process_time() - c0
    # assembly: discretisation, load vector and stiffness (the sparse K, or the bars' blocks
    # a long truss sends straight to band storage); solve: everything else
    assemble = (t2 - t1) + res.timings["assemble"]
    free = fe.free
    K, f = fe.stiffness(), fe.load_vector()                    # the check, outside the times
    r = K[free][:, free] @ res.u[free] - f[free]
    return {"read": t1 - t0, "assemble": assemble, "solve": t3 - t1 - assemble,
            "total": t3 - t0, "cpu": cpu, "backend": res.backend,
            "residual": float(np.linalg.norm(r) / np.linalg.norm(f[free])),
            "forces": res.axial_force, "dof": int(free.size)}


def reset_peak_memory() -> bool:
    """Reset the resident-memory high-water mark (Linux ``clear_refs``); False elsewhere.

    The heap the earlier models left (the allocator tuning keeps freed memory) is first
    given back to the system (glibc ``malloc_trim``), so that it does not count for the
    next model."""
    try:
        ctypes.CDLL("libc.so.6").malloc_trim(0)
    except (OSError, AttributeError):
        pass
    try:
        with open("/proc/self/clear_refs", "w") as fh:
            fh.write("5")
        return True
    except OSError:
        return False


def peak_memory_mib(reset: bool) -> float:
    """Resident-memory high-water mark in MiB: ``VmHWM`` since :func:`reset_peak_memory`
    when it worked, else ``ru_maxrss`` of the whole process."""
    if reset:
        try:
            with open("/proc/self/status") as fh:
                for line in fh:
                    if line.startswith("VmHWM:"):
                        return int(line.split()[1]) / 1024          # kB
        except OSError:
            pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # KiB on Linux


def time_opensees(structure) -> dict | None:
    try:
        import openseespy.opensees as ops
    except Exception:
        return None
    t0 = time.perf_counter()
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    for i, x in enumerate(structure.coords):
        ops.node(i + 1, *map(float, x))
    for i in np.flatnonzero(structure.supports[:, :3].any(axis=1)):
        ops.fix(int(i) + 1, *map(int, structure.supports[i, :3]))
    ops.uniaxialMaterial("Elastic", 1, float(structure.materials[0].E))
    area = float(structure.sections[0].area)
    for e, (a, b) in enumerate(structure.connectivity):
        ops.element("Truss", e + 1, int(a) + 1, int(b) + 1, area, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    for i in np.flatnonzero(np.any(structure.loads[:, :3] != 0, axis=1)):
        ops.load(int(i) + 1, *map(float, structure.loads[i, :3]))
    ops.system("UmfPack")
    ops.numberer("RCM")
    ops.constraints("Plain")
    ops.integrator("LoadControl", 1.0)
    ops.algorithm("Linear")
    ops.analysis("Static")
    t1 = time.perf_counter()
    ok = ops.analyze(1)
    t2 = time.perf_counter()
    forces = np.array([ops.basicForce(e + 1)[0] for e in range(structure.n_members)])
    ops.wipe()
    return {"build": t1 - t0, "solve": t2 - t1, "total": t2 - t0, "ok": ok == 0,
            "forces": forces}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--large", action="store_true", help="add 100,000 bays and a 1e6-DOF grid")
    ap.add_argument("--no-opensees", action="store_true")
    ap.add_argument("--repeat", type=int, default=1,
                    help="runs of each model in each program; the fastest is shown (default 1)")
    ap.add_argument("--only", nargs="+", metavar="TEXT",
                    help="run only the models whose name contains one of these, e.g. "
                         "--only 10000 180x180")
    ap.add_argument("--json", metavar="PATH",
                    help="also write the table's rows to PATH as JSON (bench_targets.py)")
    args = ap.parse_args()
    repeat = max(1, args.repeat)
    chains = [10, 100, 1000, 10_000] + ([100_000] if args.large else [])
    grids = [20, 60, 120, 180] + ([410] if args.large else [])      # 410 × 410: 1.01e6 DOF
    cases = [(f"chain {n} bays", lambda n=n: double_octahedral_chain(n)) for n in chains]
    cases += [(f"grid {n}x{n}", lambda n=n: space_grid(n)) for n in grids]
    if args.only:
        cases = [c for c in cases if any(t in c[0] for t in args.only)]
    head = (f"{'model':<20}{'DOF':>9}{'read s':>9}{'assemble s':>11}{'solve s':>9}"
            f"{'total s':>9}{'cpu s':>8}{'residual':>10}{'backend':>10}{'OpenSees s':>11}"
            f"{'speed-up':>9}{'max |dN| N':>12}{'peak MiB':>10}")
    print(head)
    print("-" * len(head))
    rows = []
    for name, build in cases:
        s = runs = r = o = None          # the previous model's memory goes before the next
        gc.collect()
        s = build()
        runs = []
        reset = reset_peak_memory()
        for _ in range(repeat):
            # thread counts and TOML parser as the trussfe command sets them
            with tempfile.TemporaryDirectory() as tmp, compiled_parser(), \
                    compute_threads(workers=environment_workers(), blas=1):
                runs.append(time_trussfe(s, Path(tmp)))
        r = min(runs, key=lambda x: x["total"])
        peak = peak_memory_mib(reset)
        o = None
        if not (args.no_opensees or r["dof"] > 400_000):
            peers = [time_opensees(s) for _ in range(repeat)]
            ok = [p for p in peers if p and p["ok"]]
            o = min(ok, key=lambda x: x["total"]) if ok else peers[0]
        ops_t = f"{o['total']:11.2f}" if o and o["ok"] else f"{'–' if o is None else 'failed':>11}"
        dn = (f"{np.max(np.abs(o['forces'] - r['forces'])):12.2e}" if o and o["ok"]
              else f"{'–':>12}")
        ratio = (f"{o['total'] / r['total']:8.1f}×" if o and o["ok"] else f"{'–':>9}")
        print(f"{name:<20}{r['dof']:>9}{r['read']:9.3f}{r['assemble']:11.3f}{r['solve']:9.3f}"
              f"{r['total']:9.3f}{r['cpu']:8.2f}{r['residual']:10.1e}{r['backend']:>10}{ops_t}"
              f"{ratio}{dn}{peak:10.0f}", flush=True)
        ok = bool(o and o["ok"])
        rows.append({"model": name, "dof": r["dof"],
                     **{k: r[k] for k in ("read", "assemble", "solve", "total", "cpu",
                                          "residual", "backend")},
                     "reference": "OpenSeesPy" if ok else None,
                     "reference_s": o["total"] if ok else None,
                     "speed_up": o["total"] / r["total"] if ok else None,
                     "max_force_difference": (float(np.max(np.abs(o["forces"] - r["forces"])))
                                              if ok else None),
                     "max_force": float(np.max(np.abs(r["forces"]))),
                     "peak_mib": peak})
    print(f"\nmachine: {os.cpu_count()} cores; OpenSeesPy timed as model build + analyze(1); "
          "cpu = process time of read + assemble + solve; backend = the solver 'auto' picks; "
          "speed-up = OpenSees s / total s; peak MiB = resident high-water mark of trussfe's "
          f"runs of the model ({'VmHWM' if reset_peak_memory() else 'ru_maxrss'}); "
          f"fastest of {repeat} run(s) of each program.")
    if not args.no_opensees:
        print(blas_note())
    if args.json:
        Path(args.json).write_text(json.dumps(
            {"rows": rows, "repeat": repeat, "cores": os.cpu_count(),
             "blas": None if args.no_opensees else blas_note()}, indent=1))


if __name__ == "__main__":
    main()
