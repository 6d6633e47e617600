# SPDX-License-Identifier: MIT
"""``trussfe modes MODEL [--count N] [--mass consistent|lumped] [--bar-model ...]
[--subdivisions K] [--json OUT] [--vtk DIR]``: natural frequencies and mode shapes
(docs/cli.md, docs/json.md, docs/vtk.md)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..model.bar_models import BAR_MODELS
from .. import api
from ..fem.modal import DEFAULT_MODE_COUNT, MASS_KINDS, ModalResult
from ..io.output import write_json
from ._modeshapes import write_modes_vtk
from . import options as opt
from .progress import progress_bar


def register(subparsers) -> None:
    """Add the ``modes`` command."""
    p = subparsers.add_parser("modes", help="natural frequencies and mode shapes",
                              description="Modal analysis: the lowest natural frequencies, "
                              "mass-normalised mode shapes, participation factors and "
                              "effective masses.")
    p.add_argument("model", type=opt.input_file, help="model file (TOML)")
    p.add_argument("--count", type=opt.positive_int, default=None, metavar="N",
                   help="number of modes (default 6, or all there are when the model has "
                   "fewer free DOFs that carry mass)")
    p.add_argument("--mass", choices=MASS_KINDS, default="consistent",
                   help="member mass matrix (default consistent)")
    p.add_argument("--bar-model", choices=BAR_MODELS, default="truss",
                   help="bars as axial-only truss elements (default) or as pinned beams, "
                   "which adds the members' own bending modes")
    p.add_argument("--subdivisions", type=opt.positive_int, default=None, metavar="K",
                   help="elements per frame member (default 4)")
    p.add_argument("--mass-from", metavar="CASE", default=None,
                   help="add the mass of a load case's nodal loads along gravity (F/g)")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the results as JSON")
    p.add_argument("--vtk", metavar="DIR", type=opt.output_dir, help="write DIR/modes.pvd, a step per mode")
    p.set_defaults(func=_main)


def write_vtk(directory: str | Path, result: ModalResult) -> list[Path]:
    """``DIR/modes.pvd``: point data ``mode_shape`` (mass-normalised) and ``displacement``
    (largest translation 1), field data ``frequency_hz`` and ``mode``; pvd timestep = mode
    number.  Subdivided members also give ``DIR/modes_stations.pvd``."""
    return write_modes_vtk(directory, result.fe, result.shapes, result.node_shapes(), "modes",
                           {"frequency_hz": result.frequencies_hz})


def _table(result: ModalResult) -> str:
    s = result.structure
    dim = s.dim
    axes = "xyz"[:dim]
    fe = result.fe
    lines = [f"trussfe modes: {s.name} ({fe.bar_model} model, {result.mass_kind} mass, "
             f"{fe.free.size} free DOFs)"]
    if result.rigid_modes:
        lines.append(f"{result.rigid_modes} zero-frequency mode(s): the structure is "
                     "unsupported or a mechanism (rigid-body / mechanism motion)")
    lines += ["", f"{'mode':>5}  {'f [Hz]':>14}  " + "  ".join(
        f"{'m_eff,' + a + ' [kg]':>14}" for a in axes) + "  kind"]
    for i in range(result.count):
        f = result.frequencies_hz[i]
        meff = "  ".join(f"{x:14.6g}" for x in result.effective_mass[i])
        lines.append(f"{i + 1:>5}  {f:14.6g}  {meff}  {result.kinds[i]}")
    lines.append(f"{'total':>5}  {'':>14}  " + "  ".join(f"{x:14.6g}"
                                                         for x in result.total_mass))
    return "\n".join(lines)


def _main(args: argparse.Namespace) -> int:
    with progress_bar("modes", unit="stage") as tick:
        res = api.modes(args.model, count=args.count, mass=args.mass,
                        bar_model=args.bar_model, subdivisions=args.subdivisions,
                        mass_from=args.mass_from, progress=tick)
    result = res.solution
    doc = res.to_dict() if args.json else None
    if args.vtk:
        write_vtk(args.vtk, result)
    if args.json:
        write_json(args.json, doc)
    sys.stdout.write(_table(result) + "\n")
    if args.count is None and result.count < DEFAULT_MODE_COUNT:
        sys.stdout.write(f"the model has only {result.count} free DOFs that carry mass: all "
                         f"{result.count} modes computed\n")
    return 0
