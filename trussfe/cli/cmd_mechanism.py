# SPDX-License-Identifier: MIT
"""``trussfe mechanism MODEL [--json OUT] [--vtk DIR]``: rank analysis of the bar assembly.

Reports ρ(B), the internal infinitesimal mechanisms, the rigid-body motions the supports leave
free, the states of self-stress and the determinacy (docs/json.md, ``mechanism``).
"""
from __future__ import annotations

import argparse
import sys

from .. import api
from ..io.output import write_json
from . import options as opt


def register(subparsers) -> None:
    """Add the ``mechanism`` command."""
    p = subparsers.add_parser("mechanism", help="rank analysis: mechanisms and self-stress states",
                              description=__doc__.splitlines()[0].strip("`"))
    p.add_argument("model", type=opt.input_file, help="model file (TOML)")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the results as JSON")
    p.add_argument("--vtk", metavar="DIR", type=opt.output_dir, help="write mechanism shapes and self-stress states")
    p.add_argument("--tolerance", type=opt.relative_tolerance, default=None,
                   help="relative singular-value tolerance (default max(b, f)·1e3·eps)")
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    result = api.mechanism(args.model, tolerance=args.tolerance)
    doc = result.to_dict()
    if args.vtk:
        from ._mechanism_vtk import write_rank_vtk
        write_rank_vtk(args.vtk, result.structure, result.solution)
    if args.json:
        write_json(args.json, doc)
    sys.stdout.write(
        f"{doc['model']}: rank {doc['rank']} of {doc['bars']} bars x {doc['coordinates']} "
        f"free coordinates; {doc['mechanisms']} mechanism(s), {doc['rigid_body_motions']} "
        f"rigid-body motion(s), {doc['self_stress_states']} state(s) of self-stress "
        f"(type {doc['classification']})\n")
    return 0
