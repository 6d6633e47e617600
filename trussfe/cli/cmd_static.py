# SPDX-License-Identifier: MIT
"""``trussfe static MODEL [--bar-model truss|pinned-beam] [--subdivisions K]
[--solver auto|superlu|pardiso] [--case NAME | --combination NAME | --all] [--json OUT]
[--vtk OUT.vtu]``: linear static finite-element analysis (docs/cli.md)."""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

import numpy as np

from .. import api
from ..model.bar_models import BAR_MODELS
from ..fem.static import StaticResult, reacting_nodes
from ..errors import InputError
from ..io.output import write_json
from . import options as opt


#: Names ``--vtk`` accepts: a ``.vtu`` file, or for several load cases the ``.pvd``
#: collection (written as ``OUT.pvd`` beside ``OUT_case_NAME.vtu`` either way).
VTK_SUFFIXES = (".vtu", ".pvd")


def _vtk_output(value: str) -> str:
    """``--vtk``: an output file whose name ends in ``.vtu`` or ``.pvd``, checked with the other
    outputs before the model is read."""
    opt.output_file(value)
    if Path(value).suffix not in VTK_SUFFIXES:
        raise argparse.ArgumentTypeError(
            f"'{value}' must end in .vtu (or .pvd for the load cases of a model with "
            "[load_cases])")
    return value


def register(subparsers) -> None:
    """Add the ``static`` command."""
    p = subparsers.add_parser("static", help="linear static finite-element analysis",
                              description="Linear static finite-element analysis: "
                              "displacements, reactions, member forces and stresses.")
    p.add_argument("model", type=opt.input_file, help="model file (TOML)")
    p.add_argument("--bar-model", choices=BAR_MODELS, default="truss",
                   help="bars as axial-only truss elements (default) or as pinned beams")
    p.add_argument("--subdivisions", type=opt.positive_int, default=None, metavar="K",
                   help="elements per frame member (default 4)")
    p.add_argument("--solver", choices=("auto", "superlu", "pardiso"), default="auto",
                   help="linear solver (default auto: a banded Cholesky for chains of 5,000 "
                   "DOFs or more, PARDISO for 20,000 DOFs or more when installed, else "
                   "SuperLU)")
    which = p.add_mutually_exclusive_group()
    which.add_argument("--case", metavar="NAME", default=None,
                       help="analyse one load case ([load_cases.NAME])")
    which.add_argument("--combination", metavar="NAME", default=None,
                       help="analyse one combination ([combinations])")
    which.add_argument("--all", dest="all_cases", action="store_true", default=False,
                       help="every load case and combination with their envelope (the "
                       "default for a model with [load_cases])")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the results as JSON")
    p.add_argument("--vtk", metavar="OUT.vtu", type=_vtk_output,
                   help="write the deformed-shape fields as VTU (several cases: OUT.pvd and "
                   "one OUT_case_NAME.vtu / OUT_combination_NAME.vtu each)")
    p.set_defaults(func=_main)


def write_vtk(path: str | Path, result: StaticResult) -> Path | None:
    """``OUT.vtu`` and, for beams and loaded members, ``OUT_stations.vtu`` beside it
    (:func:`trussfe.io.vtk_results.write_static`; nothing along the members of a truss
    without member loads).  Returns the stations file, None when there is none."""
    from ..io.vtk_results import has_stations, write_static   # meshio: only when asked for
    stations = has_stations(result)
    written = write_static(path, result, stations=stations)
    return Path(written[1]) if stations else None


def write_collection(path: str | Path, solution) -> Path:
    """``OUT.pvd`` listing one ``.vtu`` (as :func:`write_vtk`) per case and combination of a
    :class:`~trussfe.fem.load_cases.LoadCaseSolution`: ``OUT_case_NAME.vtu``,
    ``OUT_combination_NAME.vtu`` beside it (characters other than letters, digits, ``-``,
    ``_`` and ``.`` of a name become ``_``), and ``OUT_stations.pvd`` listing their
    ``_stations.vtu`` files (with the same time values) where there are any."""
    from ..io.vtk import write_pvd

    path = Path(path)
    stem = path.with_suffix("")
    entries, along, used = [], [], set()
    results = [("case", n, r) for n, r in solution.cases.items()] + \
        [("combination", n, r) for n, r in solution.combinations.items()]
    for i, (kind, name, result) in enumerate(results):
        safe = re.sub(r"[^A-Za-z0-9_.-]", "_", name)
        file = Path(f"{stem}_{kind}_{safe}.vtu")
        if file in used:                                 # two names alike once sanitised
            file = Path(f"{stem}_{kind}_{safe}_{i}.vtu")
        used.add(file)
        stations = write_vtk(file, result)
        entries.append((i, file.name))
        if stations is not None:
            along.append((i, stations.name))
    if along:
        # the stations files as a series of their own, stepped through as the cases are
        write_pvd(Path(f"{stem}_stations.pvd"), along)
    return write_pvd(stem.with_suffix(".pvd"), entries)


#: Longest node or member list printed in full; larger models print a summary only.
TABLE_ROWS = 50


def _table(result: StaticResult) -> str:
    s = result.structure
    dim = s.dim
    axes = "xyz"[:dim]
    lines = [f"trussfe static: {s.name} ({result.fe.bar_model} model, {result.fe.n_dof} DOFs, "
             f"residual {result.residual:.1e})"]
    umag = np.linalg.norm(result.displacements[:, :dim], axis=1)
    if s.n_nodes:
        i = int(np.argmax(umag))
        lines.append(f"largest displacement {umag[i]:.4e} m at node {s.node_ids[i]}")
    if s.n_members:
        i = int(np.argmax(np.abs(result.axial_force)))
        j = int(np.argmax(result.max_von_mises))
        lines.append(f"largest axial force {result.axial_force[i]:.4f} N in member "
                     f"{s.member_ids[i]}; largest von Mises {result.max_von_mises[j]:.4e} Pa "
                     f"in member {s.member_ids[j]}")
    lines += ["", "nodes"]
    hdr = "  ".join(f"{'u' + a:>12}" for a in axes) + "  " + "  ".join(
        f"{'R' + a:>12}" for a in axes)
    lines.append(f"{'id':>8}  {hdr}")
    # reactions where a support or a spring holds the node (a spring's force on the
    # structure, -k u, is a reaction)
    sup = reacting_nodes(result.fe)[:, :dim].any(axis=1)
    shown = range(s.n_nodes) if s.n_nodes <= TABLE_ROWS else np.flatnonzero(sup)[:TABLE_ROWS]
    for i in shown:
        u = "  ".join(f"{x:12.4e}" for x in result.displacements[i, :dim])
        r = "  ".join(f"{x:12.4f}" for x in result.reactions[i, :dim]) if sup[i] else ""
        lines.append(f"{s.node_ids[i]:>8}  {u}  {r}".rstrip())
    if s.n_nodes > TABLE_ROWS:
        lines.append(f"  ... supported nodes only (supports and springs), of {s.n_nodes}; "
                     "--json has every node")
    lines += ["", "members", f"{'id':>8}  {'N [N]':>12}  {'sigma [Pa]':>12}  "
              f"{'max vM [Pa]':>12}"]
    order = (range(s.n_members) if s.n_members <= TABLE_ROWS
             else np.argsort(-result.max_von_mises)[:TABLE_ROWS])
    for i in order:
        lines.append(f"{s.member_ids[i]:>8}  {result.axial_force[i]:12.4f}  "
                     f"{result.axial_stress[i]:12.4e}  {result.max_von_mises[i]:12.4e}")
    if s.n_members > TABLE_ROWS:
        lines.append(f"  ... the {TABLE_ROWS} most stressed of {s.n_members} members; "
                     "--json has every member")
    return "\n".join(lines)


def _collection_table(res) -> str:
    """Summary of every case and combination, and the governing ones of the envelope."""
    s = res.structure
    sol = res.solution
    lines = [f"trussfe static: {s.name} ({sol.fe.bar_model} model, {sol.fe.n_dof} DOFs, "
             f"{len(sol.cases)} load case(s), {len(sol.combinations)} combination(s))", "",
             f"{'':>12}  {'name':>16}  {'max |u| [m]':>12}  {'max |N| [N]':>12}  "
             f"{'max vM [Pa]':>12}  {'residual':>9}"]
    for kind, group in (("case", sol.cases), ("combination", sol.combinations)):
        for name, r in group.items():
            umax = float(np.linalg.norm(r.displacements[:, :s.dim], axis=1).max(initial=0.0))
            nmax = float(np.abs(r.axial_force).max(initial=0.0))
            vmax = float(np.fmax.reduce(r.max_von_mises)) if s.n_members else 0.0
            lines.append(f"{kind:>12}  {name:>16}  {umax:12.4e}  {nmax:12.4f}  "
                         f"{vmax:12.4e}  {r.residual:9.1e}")
    env = sol.envelope
    if s.n_members:
        mx, imx, mn, imn = env.fields["axial_force"]
        i, j = int(np.argmax(mx)), int(np.argmin(mn))
        vm, ivm, _, _ = env.fields["max_von_mises"]
        k = int(np.argmax(vm))
        over = env.over[:-1]
        lines += ["", f"envelope over the {env.over}",
                  _extreme("tension", mx[i], s.member_ids[i], over, env.names[imx[i]]),
                  _extreme("compression", mn[j], s.member_ids[j], over, env.names[imn[j]]),
                  f"largest von Mises {vm[k]:.4e} Pa in member {s.member_ids[k]} ({over} "
                  f"{env.names[ivm[k]]})"]
    return "\n".join(lines)


def _extreme(kind: str, force: float, member: str, over: str, name: str) -> str:
    """The envelope's line of the largest tension (force > 0) or compression (force < 0):
    where no member is in that state in any case, it says so instead of calling the least
    compressive force a tension."""
    if (force > 0.0) if kind == "tension" else (force < 0.0):
        return f"largest {kind} {force:.4f} N in member {member} ({over} {name})"
    return f"no member in {kind} in any {over}"


def _main(args: argparse.Namespace) -> int:
    from ..api.linear import solves_one_case
    model = api.read_model(args.model)
    if args.vtk and Path(args.vtk).suffix == ".pvd" and solves_one_case(
            model, case=args.case, combination=args.combination, all_cases=args.all_cases):
        # refused before the analysis, not after it
        raise InputError("--vtk", f"'{args.vtk}': one case is written as one .vtu file; give "
                                  "a name ending in .vtu (a .pvd collection is written for the "
                                  "load cases of a model with [load_cases], or with --all)")
    res = api.static(model, bar_model=args.bar_model, subdivisions=args.subdivisions,
                     solver=args.solver, case=args.case, combination=args.combination,
                     all_cases=args.all_cases)
    doc = res.to_dict() if args.json else None
    # all outputs are produced before any is renamed into place
    if isinstance(res, api.StaticResult):
        result = res.solution
        if args.vtk:
            write_vtk(args.vtk, result)
        text = _table(result)
        if res.selected is not None:
            kind, name = res.selected
            text = text.replace("\n", f"\n{kind} {name}\n", 1)
    else:
        if args.vtk:
            write_collection(args.vtk, res.solution)
        text = _collection_table(res)
    if args.json:
        write_json(args.json, doc)
    sys.stdout.write(text + "\n")
    return 0
