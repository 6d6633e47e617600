# SPDX-License-Identifier: MIT
"""``trussfe static MODEL [--bar-model truss|pinned-beam] [--subdivisions K]
[--solver auto|superlu|pardiso] [--json OUT] [--vtk OUT.vtu]``: linear static finite-element analysis (docs/cli.md)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

from .. import api
from ..model.bar_models import BAR_MODELS
from ..fem.static import StaticResult
from ..io.output import write_json
from . import options as opt


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
                   help="sparse linear solver (default: PARDISO for large models when "
                   "installed, else SuperLU)")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the results as JSON")
    p.add_argument("--vtk", metavar="OUT.vtu", type=opt.output_file, help="write the deformed-shape fields as VTU")
    p.set_defaults(func=_main)


def write_vtu(path: str | Path, result: StaticResult) -> None:
    """Undeformed mesh with point data ``displacement`` and ``reaction`` and cell data
    ``axial_force``, ``axial_stress``, ``strain``, ``von_mises`` (written atomically)."""
    from ..io.vtk import write_vtu as _write_vtu    # meshio: only when a VTU is asked for

    s = result.structure
    dim = s.dim
    point_data = {"displacement": result.displacements[:, :dim],
                  "reaction": result.reactions[:, :dim]}
    cell_data = {"axial_force": result.axial_force, "axial_stress": result.axial_stress,
                 "strain": result.strain, "von_mises": result.max_von_mises}
    _write_vtu(path, s, point_data=point_data, cell_data=cell_data)


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
    sup = s.supports[:, :dim].any(axis=1)
    shown = range(s.n_nodes) if s.n_nodes <= TABLE_ROWS else np.flatnonzero(sup)[:TABLE_ROWS]
    for i in shown:
        u = "  ".join(f"{x:12.4e}" for x in result.displacements[i, :dim])
        r = "  ".join(f"{x:12.4f}" for x in result.reactions[i, :dim]) if sup[i] else ""
        lines.append(f"{s.node_ids[i]:>8}  {u}  {r}".rstrip())
    if s.n_nodes > TABLE_ROWS:
        lines.append(f"  ... supported nodes only, of {s.n_nodes}; --json has every node")
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


def _main(args: argparse.Namespace) -> int:
    res = api.static(args.model, bar_model=args.bar_model, subdivisions=args.subdivisions,
                     solver=args.solver)
    result = res.solution
    doc = res.to_dict() if args.json else None
    # all outputs are produced before any is renamed into place
    if args.vtk:
        write_vtu(args.vtk, result)
        if np.any(result.fe.is_frame) or result.member_loads is not None:
            # section forces along beams and loaded members: OUT_stations.vtu beside OUT.vtu
            from ..io.vtk import write_stations       # meshio: only when a VTU is asked for
            from ..io.vtk_results import static_station_fields
            xi, fields = static_station_fields(result)
            vtk = Path(args.vtk)
            write_stations(vtk.with_name(vtk.stem + "_stations.vtu"), result.structure, xi,
                           point_data=fields)
    if args.json:
        write_json(args.json, doc)
    sys.stdout.write(_table(result) + "\n")
    return 0
