# SPDX-License-Identifier: MIT
"""``trussfe trace MODEL --drive NODE:AXIS --step S --steps N``: finite-mechanism motion.

Follows the motion of an inextensional bar-and-joint mechanism (Hortobágyi's algorithm) and
reports every state, the bifurcation points and the limit points (docs/json.md, ``trace``).
"""
from __future__ import annotations

import argparse
import sys

import numpy as np

from .. import api
from ..io.output import atomic_path, write_json
from . import options as opt
from .progress import progress_bar


def register(subparsers) -> None:
    """Add the ``trace`` command."""
    p = subparsers.add_parser("trace", help="finite-mechanism motion",
                              description=__doc__.splitlines()[0].strip("`"))
    p.add_argument("model", type=opt.input_file, help="model file (TOML)")
    p.add_argument("--drive", action="append", required=True, metavar="NODE:AXIS",
                   help="prescribed coordinate (repeat for several degrees of freedom)")
    p.add_argument("--step", action="append", type=opt.nonzero_real, required=True, metavar="S",
                   help="increment of the drive coordinate per step, m (one per --drive)")
    p.add_argument("--steps", type=opt.positive_int, required=True, metavar="N", help="number of steps")
    p.add_argument("--branch", type=opt.nonneg_int, default=0, metavar="K",
                   help="branch taken at a bifurcation point (0 = prescribe the drive)")
    p.add_argument("--tolerance", type=opt.relative_tolerance, default=1e-10,
                   help="relative bar-length tolerance of the corrector (default 1e-10)")
    p.add_argument("--frozen", action="store_true",
                   help="keep B11 of the predicted state (the paper's iteration) instead of "
                        "Newton's refresh")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the path as JSON")
    p.add_argument("--vtk", metavar="DIR", type=opt.output_dir, help="write every state as .vtu and a .pvd")
    p.add_argument("--plot", metavar="PNG", type=opt.output_file, help="plot the node trajectories")
    p.set_defaults(func=_run)


def _plot(path: str, s, r) -> None:
    """Node trajectories (as Hortobágyi's Fig. 11), start and end states drawn as bars."""
    from ..io.figures import subplots

    X = r.coords                                            # (state, node, dim)
    moving = np.flatnonzero(np.ptp(X, axis=0).max(axis=1) > 1e-12)
    if s.dim == 2:
        ax2 = (0, 1)
    else:                                                   # the plane the joints move most in
        spread = np.ptp(X[:, moving], axis=0).max(axis=0) if moving.size else np.ones(3)
        ax2 = tuple(sorted(np.argsort(-spread)[:2].tolist()))
    fig, ax = subplots(figsize=(6, 5))
    for x, style in ((X[0], "k-"), (X[-1], "k:")):
        for a, b in s.connectivity:
            ax.plot(x[[a, b], ax2[0]], x[[a, b], ax2[1]], style, lw=0.8)
    for i in moving:
        ax.plot(X[:, i, ax2[0]], X[:, i, ax2[1]], "-", lw=1.2, label=f"node {s.node_ids[i]}")
    ev = [e["step"] for e in r.events if e["kind"] == "bifurcation"]
    for k in ev:
        ax.plot(X[k, moving, ax2[0]], X[k, moving, ax2[1]], "rx")
    ax.set_aspect("equal")
    ax.set_xlabel(f"{'xyz'[ax2[0]]} (m)")
    ax.set_ylabel(f"{'xyz'[ax2[1]]} (m)")
    ax.set_title(f"{s.name}: node trajectories" + (" (x = bifurcation)" if ev else ""))
    if len(moving) <= 10:
        ax.legend(fontsize=7)
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=120, format="png")


#: Traces of at least this many steps show a progress bar (on a terminal).
PROGRESS_STEPS = 1000


def _progress_bar(steps: int):
    """The progress bar of a long trace (:func:`trussfe.cli.progress.progress_bar`)."""
    return progress_bar("trace", enabled=None if steps >= PROGRESS_STEPS else False)


def _run(args: argparse.Namespace) -> int:
    with _progress_bar(args.steps) as tick:
        result = api.trace(args.model, drive=args.drive, step=args.step, steps=args.steps,
                           branch=args.branch, tolerance=args.tolerance, frozen=args.frozen,
                           progress=tick)
        doc = result.to_dict()
        if args.vtk:
            from ._mechanism_vtk import write_trace_vtk
            write_trace_vtk(args.vtk, result.structure, result.solution)
        if args.plot:
            _plot(args.plot, result.structure, result.solution)
    if args.json:
        write_json(args.json, doc)
    ev = ", ".join(f"{e['kind']} at state {e['step']}" for e in doc["events"]) or "none"
    sys.stdout.write(f"{doc['model']}: traced {len(doc['path']) - 1} steps; events: {ev}\n")
    return 0
