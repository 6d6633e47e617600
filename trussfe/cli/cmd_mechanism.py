# SPDX-License-Identifier: MIT
"""``trussfe mechanism MODEL [--json OUT] [--vtk DIR]``: rank analysis of the bar assembly.

Reports ρ(B), the internal infinitesimal mechanisms, the rigid-body motions the supports leave
free, the states of self-stress, the determinacy and the order of the infinitesimal mechanism
(docs/json.md, ``mechanism``).
"""
from __future__ import annotations

import argparse
import sys

from .. import api
from ..api.kinematic import MAX_ORDER_LIMIT
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
    p.add_argument("--max-order", type=opt.integer(2, MAX_ORDER_LIMIT), default=64,
                   help="highest order of the compatibility equations examined for the order "
                        "of the infinitesimal mechanism (default 64)")
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    result = api.mechanism(args.model, tolerance=args.tolerance, max_order=args.max_order)
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
        f"(type {doc['classification']})\n{_order_line(doc)}\n")
    return 0


def _order_line(doc: dict) -> str:
    """One line on the order of the infinitesimal mechanism."""
    a = doc["order_analysis"]
    if doc["order"] == "infinite":
        if doc["self_stress_states"]:               # only bars between fixed joints
            return ("order: infinite (a finite mechanism: its only states of self-stress are "
                    "in bars between fixed joints)")
        return "order: infinite (a finite mechanism: no state of self-stress)"
    if doc["order"] is not None:
        return (f"order: {doc['order']} (compatible to order {doc['order']}, not "
                f"{doc['order'] + 1})")
    if a["status"] == "undecided":
        return f"order: undecided, {a['checked']} orders checked ({a['note']})"
    if a["status"] == "rigid":
        return f"order: none ({a['note']})"
    return f"order: not computed ({a['note']})"
