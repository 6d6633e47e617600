# SPDX-License-Identifier: MIT
"""``trussfe buckling MODEL [--count N] [--bar-model pinned-beam|truss] [--subdivisions K]
[--case NAME | --combination NAME] [--json OUT] [--vtk DIR]``: linear buckling load factors about the static state
(docs/cli.md, docs/json.md, docs/vtk.md)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

from .. import api
from ..fem.buckling import DEFAULT_BUCKLING_COUNT, BucklingResult
from ..model.bar_models import BAR_MODELS
from ..io.output import write_json
from ._modeshapes import write_modes_vtk
from . import options as opt


def register(subparsers) -> None:
    """Add the ``buckling`` command."""
    p = subparsers.add_parser("buckling", help="linear (eigen) buckling load factors",
                              description="Linear buckling about the static state under the "
                              "model's loads and gravity: load factors (smallest magnitude "
                              "first, negative = reversed loads), modes, member Euler loads.")
    p.add_argument("model", type=opt.input_file, help="model file (TOML)")
    p.add_argument("--count", type=opt.positive_int, default=None, metavar="N",
                   help="number of load factors (default 4, or every finite one when there "
                   "are fewer)")
    p.add_argument("--bar-model", choices=BAR_MODELS, default="pinned-beam",
                   help="pinned beams (default: members buckle between joints) or "
                   "axial-only truss bars (joint instability only)")
    p.add_argument("--subdivisions", type=opt.positive_int, default=None, metavar="K",
                   help="elements per frame member (default 4)")
    which = p.add_mutually_exclusive_group()
    which.add_argument("--case", metavar="NAME", default=None,
                       help="buckle about the state of one load case")
    which.add_argument("--combination", metavar="NAME", default=None,
                       help="buckle about the state of one combination of load cases")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the results as JSON")
    p.add_argument("--vtk", metavar="DIR", type=opt.output_dir, help="write DIR/buckling.pvd, a step per mode")
    p.set_defaults(func=_main)


def write_vtk(directory: str | Path, result: BucklingResult) -> list[Path]:
    """``DIR/buckling.pvd``: point data ``mode_shape`` and ``displacement`` (largest
    translation 1), field data ``load_factor`` and ``mode``, cell data ``axial_force``
    (static), ``euler_load`` and ``buckling_utilisation``."""
    st = result.static
    return write_modes_vtk(directory, result.fe, result.shapes, result.node_shapes(),
                           "buckling", {"load_factor": result.load_factors},
                           cell_data={"axial_force": st.axial_force,
                                      "axial_stress": st.axial_stress,
                                      "von_mises": st.max_von_mises,
                                      "euler_load": result.euler_load,
                                      "buckling_utilisation": result.utilisation})


def _table(result: BucklingResult) -> str:
    s = result.structure
    fe = result.fe
    lines = [f"trussfe buckling: {s.name} ({fe.bar_model} model, {fe.free.size} free DOFs)",
             "", f"{'mode':>5}  {'load factor':>14}"]
    for i, lam in enumerate(result.load_factors):
        note = "  (reversed loads)" if lam < 0 else ""
        lines.append(f"{i + 1:>5}  {lam:14.6g}{note}")
    crit = result.critical_load_factor
    lines += ["", "critical load factor: " + (f"{crit:.6g}" if np.isfinite(crit) else
                                              "none among the modes computed"),
              "", "members (Lacy eq. 2.26, C = 1; N at mid-length, utilisation = largest "
              "compression along the member / P_euler)",
              f"{'id':>8}  {'N [N]':>12}  {'P_euler [N]':>12}  {'utilisation':>12}"]
    for i, mid in enumerate(s.member_ids):
        lines.append(f"{mid:>8}  {result.static.axial_force[i]:12.4f}  "
                     f"{result.euler_load[i]:12.4f}  {result.utilisation[i]:12.4g}")
    return "\n".join(lines)


def _main(args: argparse.Namespace) -> int:
    res = api.buckling(args.model, count=args.count, bar_model=args.bar_model,
                       subdivisions=args.subdivisions, case=args.case,
                       combination=args.combination)
    result = res.solution
    doc = res.to_dict() if args.json else None
    if args.vtk:
        write_vtk(args.vtk, result)
    if args.json:
        write_json(args.json, doc)
    sys.stdout.write(_table(result) + "\n")
    found = result.load_factors.size
    if args.count is None and found < DEFAULT_BUCKLING_COUNT:
        sys.stdout.write(f"the geometric stiffness has only {found} finite load factor(s): "
                         "all of them computed\n")
    return 0
