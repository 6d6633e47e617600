# SPDX-License-Identifier: MIT
"""``trussfe mechanism MODEL [--json OUT] [--vtk DIR]``: rank analysis of the bar assembly.

Reports ρ(B), the internal infinitesimal mechanisms, the rigid-body motions the supports leave
free, the states of self-stress and the determinacy (CONTRACT.md §3, ``mechanism``).
"""
from __future__ import annotations

import argparse
import logging
import sys

import numpy as np

from ..io.model_file import read_model
from ..io.output import write_json
from ..kinematics.rank import structure_rank
from . import options as opt

log = logging.getLogger(__name__)


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


def analyse(model_path: str, *, tolerance: float | None = None, vtk: str | None = None,
            structure=None) -> dict:
    """Rank analysis of a model file; returns the JSON document of CONTRACT.md §3.

    Keys: ``units``, ``command``, ``model``, ``rank``, ``mechanisms``, ``rigid_body_motions``,
    ``self_stress_states`` and, beyond the contract, ``coordinates``, ``bars``,
    ``infinitesimal_motions``, determinacy, the tolerance and decision margin, and the shapes
    ``mechanism_modes`` (node → displacement, unit norm) and ``self_stress_modes`` (member →
    tension, unit norm).
    """
    s = read_model(model_path) if structure is None else structure
    r = structure_rank(s, tolerance=tolerance)
    n, dim = s.coords.shape
    fidx = np.flatnonzero(r.free.ravel())

    def shape(col):
        d = np.zeros(n * dim)
        d[fidx] = col
        d = d.reshape(n, dim)
        moving = np.flatnonzero(np.linalg.norm(d, axis=1) > 1e-12)
        return {s.node_ids[i]: d[i].tolist() for i in moving}

    doc = {
        "units": "SI", "command": "mechanism", "model": s.name,
        "rank": r.rank, "mechanisms": r.mechanisms,
        "rigid_body_motions": r.rigid_body_motions, "self_stress_states": r.self_stress_states,
        "coordinates": r.n_coordinates, "bars": r.n_bars,
        "infinitesimal_motions": r.infinitesimal_motions,
        "statically_determinate": r.statically_determinate,
        "kinematically_determinate": r.kinematically_determinate,
        "classification": r.classification,
        "tolerance": r.tolerance,
        "smallest_kept_singular_value": r.smallest_kept,
        "largest_dropped_singular_value": r.largest_dropped,
        "mechanism_modes": [shape(r.mechanism_basis[:, k]) for k in range(r.mechanisms)],
        "rigid_body_modes": [shape(r.rigid_body_basis[:, k])
                             for k in range(r.rigid_body_motions)],
    }
    if r.self_stress_basis is not None:
        doc["self_stress_modes"] = [
            {s.member_ids[i]: float(v) for i, v in enumerate(r.self_stress_basis[:, k])
             if abs(v) > 1e-12} for k in range(r.self_stress_states)]
    if any(s.is_beam):
        doc["note"] = "beams are analysed as pin-jointed bars"
    if vtk:
        from ._mechanism_vtk import write_rank_vtk
        write_rank_vtk(vtk, s, r)
    return doc


def _run(args: argparse.Namespace) -> int:
    doc = analyse(args.model, tolerance=args.tolerance, vtk=args.vtk)
    if args.json:
        write_json(args.json, doc)
    sys.stdout.write(
        f"{doc['model']}: rank {doc['rank']} of {doc['bars']} bars x {doc['coordinates']} "
        f"free coordinates; {doc['mechanisms']} mechanism(s), {doc['rigid_body_motions']} "
        f"rigid-body motion(s), {doc['self_stress_states']} state(s) of self-stress "
        f"(type {doc['classification']})\n")
    return 0
