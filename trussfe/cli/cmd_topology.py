# SPDX-License-Identifier: MIT
"""``trussfe topology MODEL [--json OUT]``: graph of the bar-only equivalent mechanism.

Incidence matrices, spanning tree and cotree, fundamental and complete cycle matrices of the
model read as a linkage (Vlase et al. 2008; docs/json.md, ``topology``).
"""
from __future__ import annotations

import argparse
import sys

from .. import api
from ..io.output import write_json
from . import options as opt


def register(subparsers) -> None:
    """Add the ``topology`` command."""
    p = subparsers.add_parser(
        "topology", help="graph of the equivalent mechanism: incidence, tree, cycles",
        description="Graph description of a bar-and-joint assembly (Vlase et al. 2008): the "
        "bar-only equivalent mechanism (rigidly joined beams triangulated as plates, the "
        "fixed nodes closed by ground edges, one-direction supports as sliders), its "
        "complete and reduced incidence matrices, spanning tree and cotree, fundamental "
        "cycle matrix B_f and complete cycle matrix B_a.")
    p.add_argument("model", type=opt.input_file, help="model file (TOML)")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the results as JSON")
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    result = api.topology(args.model)
    doc = result.to_dict()
    if args.json:
        write_json(args.json, doc)
    c = doc["counts"]
    cycles = ("not enumerated (cycle space of more than 16 dimensions)" if c["cycles"] is None
              else f"{c['cycles']} simple cycle(s)")
    planar = (f"; node(s) {', '.join(doc['planar_supports'])} fixed in one direction only, "
              "left free" if doc["planar_supports"] else "")
    sys.stdout.write(
        f"{doc['model']}: {c['joints']} joints, {c['edges']} edges ({len(doc['plates'])} "
        f"plate(s), {len(doc['ground'])} ground joint(s)); tree of {c['tree_edges']} edges, "
        f"{c['links']} fundamental cycle(s); {cycles}{planar}\n")
    return 0
