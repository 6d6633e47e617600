# SPDX-License-Identifier: MIT
"""``trussfe trace MODEL --drive NODE:AXIS --step S --steps N``: finite-mechanism motion.

Follows the motion of an inextensional bar-and-joint mechanism (Hortobágyi's algorithm) and
reports every state, the bifurcation points and the limit points (CONTRACT.md §3, ``trace``).
"""
from __future__ import annotations

import argparse
import contextlib
import os
import sys
from typing import Callable, Iterator

import numpy as np

from ..errors import InputError
from ..io.model_file import read_model
from ..io.output import atomic_path, write_json
from ..kinematics.mechanism import trace_structure
from . import options as opt


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


def analyse(model_path: str, *, drive, step, steps: int, branch: int = 0,
            tolerance: float = 1e-10, frozen: bool = False, vtk: str | None = None,
            plot: str | None = None, structure=None, progress=None) -> dict:
    """Trace a model file's mechanism; returns the JSON document of CONTRACT.md §3.

    ``path``: one entry per state, ``{"parameter", "positions": {node: [..]}, "rank"}`` (and
    ``iterations`` and ``residual``, beyond the contract); ``events``: bifurcation and limit
    points with the step after which they were found.
    """
    s = read_model(model_path) if structure is None else structure
    drives = [drive] if isinstance(drive, str) else list(drive)
    steps_ = [step] if np.isscalar(step) else list(step)
    if len(steps_) == 1 and len(drives) > 1:
        steps_ = steps_ * len(drives)
    if len(steps_) != len(drives):
        raise InputError("--step", f"give one --step per --drive ({len(drives)} drives, "
                                   f"{len(steps_)} steps)")
    if not isinstance(steps, (int, np.integer)) or steps < 1:
        raise InputError("--steps", f"must be a positive integer, got {steps!r}")
    if branch < 0:
        raise InputError("--branch", f"must be 0 or more, got {branch}")
    r = trace_structure(s, drives, steps_ if len(steps_) > 1 else steps_[0], steps,
                        branch=branch, tolerance=tolerance, newton=not frozen,
                        progress=progress)
    path = []
    for k in range(r.coords.shape[0]):
        entry = {"parameter": float(r.parameter[k]),
                 "positions": {nid: r.coords[k, i].tolist() for i, nid in enumerate(s.node_ids)},
                 "rank": int(r.rank[k]), "residual": float(r.residual[k])}
        if k > 0:
            entry["iterations"] = int(r.iterations[k - 1])
        path.append(entry)
    doc = {"units": "SI", "command": "trace", "model": s.name, "drive": drives,
           "step": steps_, "steps": steps, "branch": branch, "path": path,
           "events": r.events}
    if vtk:
        from ._mechanism_vtk import write_trace_vtk
        write_trace_vtk(vtk, s, r)
    if plot:
        _plot(plot, s, r)
    return doc


def _plot(path: str, s, r) -> None:
    """Node trajectories (as Hortobágyi's Fig. 11), start and end states drawn as bars."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    X = r.coords                                            # (state, node, dim)
    moving = np.flatnonzero(np.ptp(X, axis=0).max(axis=1) > 1e-12)
    if s.dim == 2:
        ax2 = (0, 1)
    else:                                                   # the plane the joints move most in
        spread = np.ptp(X[:, moving], axis=0).max(axis=0) if moving.size else np.ones(3)
        ax2 = tuple(sorted(np.argsort(-spread)[:2].tolist()))
    fig, ax = plt.subplots(figsize=(6, 5))
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
    plt.close(fig)


#: Traces of at least this many steps show a progress bar (on a terminal).
PROGRESS_STEPS = 1000


@contextlib.contextmanager
def _progress_bar(steps: int) -> Iterator[Callable[[int], None] | None]:
    """A tqdm bar on stderr for a long trace, only when stderr is a terminal (a log file or
    pipe gets no carriage-return noise); closed however the trace ends, Ctrl-C included."""
    if steps < PROGRESS_STEPS or not sys.stderr.isatty():
        yield None
        return
    from tqdm import tqdm

    try:                    # a terminal that reports no width (a bare pty): 80 columns
        width = os.get_terminal_size(sys.stderr.fileno()).columns or 80
    except (OSError, ValueError, AttributeError):
        width = 80
    with tqdm(total=steps, desc="trace", unit="step", leave=False, file=sys.stderr,
              mininterval=0.5, ncols=width) as bar:
        def tick(k: int) -> None:
            bar.update(k - bar.n)
        yield tick


def _run(args: argparse.Namespace) -> int:
    with _progress_bar(args.steps) as tick:
        doc = analyse(args.model, drive=args.drive, step=args.step, steps=args.steps,
                      branch=args.branch, tolerance=args.tolerance, frozen=args.frozen,
                      vtk=args.vtk, plot=args.plot, progress=tick)
    if args.json:
        write_json(args.json, doc)
    ev = ", ".join(f"{e['kind']} at state {e['step']}" for e in doc["events"]) or "none"
    sys.stdout.write(f"{doc['model']}: traced {len(doc['path']) - 1} steps; events: {ev}\n")
    return 0
