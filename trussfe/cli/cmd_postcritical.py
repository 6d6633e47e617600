# SPDX-License-Identifier: MIT
"""``trussfe postcritical MODEL [--control load|displacement|arc-length] [--steps N]
[--json OUT] [--vtk DIR] [--plot PNG] ...``: geometrically nonlinear path with member failure
(docs/cli.md, docs/json.md, docs/vtk.md).

The model's ``[loads]`` are the reference load pattern scaled by the load factor λ; failure
laws come from its ``[failure]`` table and analysis settings from ``[postcritical]`` (options
given here override them).
"""
from __future__ import annotations

import logging
import sys
from pathlib import Path

import numpy as np

from .. import api
from ..io.output import write_json
from ..nonlinear.analysis import unmodelled_buckling
from ..model.bar_models import BAR_MODELS, DEFAULT_POSTCRITICAL_SUBDIVISIONS
from ..nonlinear.path import CONTROLS, PathResult
from ..nonlinear.plot import write_plot
from . import options as opt
from .progress import progress_bar


def register(subparsers) -> None:
    """Add the ``postcritical`` command."""
    p = subparsers.add_parser(
        "postcritical", help="geometrically nonlinear path with member failure",
        description="Follow the equilibrium path of the model under its [loads] scaled by a "
        "load factor: co-rotational elements, limit and bifurcation points, member buckling, "
        "yield and fracture, and the hand-over to mechanism motion.")
    p.add_argument("model", type=opt.input_file, help="model file (TOML)")
    p.add_argument("--control", choices=CONTROLS, default=None,
                   help="path control (default arc-length, or the model's [postcritical])")
    p.add_argument("--steps", type=opt.positive_int, default=None, metavar="N", help="number of steps")
    p.add_argument("--step", type=opt.positive_real, default=None, metavar="S",
                   help="first increment: Δλ (load), Δu (displacement) or Δs (arc-length)")
    p.add_argument("--max-load-factor", type=opt.positive_real, default=None, metavar="L",
                   help="stop when the load factor exceeds L")
    p.add_argument("--max-displacement", type=opt.positive_real, default=None, metavar="D",
                   help="stop when the monitored displacement exceeds D (m)")
    p.add_argument("--monitor", default=None, metavar="NODE:AXIS",
                   help="displacement plotted (and prescribed under displacement control)")
    p.add_argument("--bar-model", choices=BAR_MODELS, default=None,
                   help="bars as co-rotational truss elements or as pinned beams")
    p.add_argument("--subdivisions", type=opt.positive_int, default=None, metavar="K",
                   help="beam elements per beam member (default "
                        f"{DEFAULT_POSTCRITICAL_SUBDIVISIONS})")
    p.add_argument("--imperfection", type=opt.nonneg_real, default=None, metavar="A",
                   help="amplitude (m) of the first buckling mode added to the geometry")
    p.add_argument("--branch", action="store_true", default=None,
                   help="at a bifurcation follow the secondary branch")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the path and events as JSON")
    p.add_argument("--vtk", metavar="DIR", type=opt.output_dir, help="write the path as a .pvd time series")
    p.add_argument("--plot", metavar="PNG", type=opt.output_file, help="plot the load-displacement curve")
    p.set_defaults(func=_main)


def write_vtk(directory: str | Path, result: PathResult) -> Path:
    """The path as ``DIR/<model>_path.pvd``: one ``.vtu`` per path point, the pvd time being
    the point index; point data ``displacement``; cell data ``axial_force`` and ``failed``
    (1 for a member that has failed — removed or past its law's limit), field data
    ``load_factor``."""
    from ..io.vtk import write_series
    m = result.model
    s = m.structure
    failed_by_law = np.zeros(s.n_members, dtype=np.int8)
    frames = []
    event_at = {}
    for e in result.events:
        if e.member is not None:
            event_at.setdefault(e.point, []).append(e.member)
    for i, p in enumerate(result.path):
        for mem in event_at.get(i, []):
            failed_by_law[mem] = 1
        d = p.u[: s.n_nodes * s.dim].reshape(s.n_nodes, s.dim)
        failed = np.maximum(failed_by_law, (~p.alive).astype(np.int8))
        frames.append({"time": float(i), "coords": s.coords + d,
                       "point_data": {"displacement": d},
                       "cell_data": {"axial_force": p.forces, "failed": failed.copy(),
                                     "axial_stress": p.forces / s.area},
                       "field_data": {"load_factor": p.load_factor}})
    name = "".join(ch if ch.isalnum() or ch in "-_" else "_" for ch in Path(
        s.source or s.name).stem) + "_path"
    return write_series(directory, s, frames, name)


def _main(args) -> int:
    with progress_bar("postcritical") as tick:
        res = api.postcritical(args.model, control=args.control, steps=args.steps, step=args.step,
                               max_load_factor=args.max_load_factor,
                               max_displacement=args.max_displacement, monitor=args.monitor,
                               bar_model=args.bar_model, subdivisions=args.subdivisions,
                               imperfection=args.imperfection, branch=args.branch,
                               progress=tick)
    result = res.solution
    doc = res.to_dict()
    if args.json:
        write_json(args.json, doc)
    if args.vtk:
        write_vtk(args.vtk, result)
    if args.plot:
        write_plot(args.plot, result)
    out = sys.stdout
    out.write(f"{doc['model']}: {len(doc['path'])} path points, maximum load factor "
              f"{doc['max_load_factor']:.6g}\n")
    if doc["gravity_dead_load"]:
        out.write("  gravity acts as a constant dead load; the load factor scales [loads]\n")
    for e in doc["events"]:
        who = f" member {e['member']}" if e["member"] is not None else ""
        out.write(f"  λ = {e['load_factor']:.6g}: {e['kind']}{who}"
                  f"{' — ' + e['detail'] if e['detail'] else ''}\n")
    out.write(f"  {doc['termination']}\n")
    over = unmodelled_buckling(result)
    if over is not None:
        mem, lam, pe = over
        s = result.model.structure
        # held with the run's warnings: printed once the outputs are in place, never beside
        # an error line
        logging.getLogger("trussfe").warning(
            "note: member buckling is not modelled (no [failure] table); member %s exceeds "
            "its Euler load %.4g N from load factor %.6g", s.member_ids[mem], pe, lam)
    return 0
