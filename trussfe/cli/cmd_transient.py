# SPDX-License-Identifier: MIT
"""``trussfe transient MODEL --motion MOTION``: elastic vibration along a prescribed motion."""
from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

from .. import api
from ..errors import InputError
from ..io.output import atomic_path, write_json
from . import options as opt
from .progress import progress_bar


def register(subparsers) -> None:
    """Add the ``transient`` command."""
    p = subparsers.add_parser(
        "transient", help="elastic vibration superposed on a prescribed motion",
        description="Linearised FE dynamics about the moving configuration (Newmark average "
        "acceleration): elastic member forces compared with the quasi-static FE and the "
        "rigid-body ones, and the energy balance.")
    p.add_argument("model", type=opt.input_file, help="model file (TOML) with [active_members]")
    p.add_argument("--motion", required=True, type=opt.input_file, help="motion file: TOML [motion] or CSV")
    p.add_argument("--steps", type=opt.positive_int, help="number of time steps of a generated motion")
    p.add_argument("--dt", type=opt.positive_real, help="time step, s (default: the motion's sampling)")
    p.add_argument("--t-end", type=opt.positive_real, help="end time, s (holds a motion that ended at rest)")
    p.add_argument("--bar-model", choices=("pinned-beam", "truss"), default="pinned-beam")
    p.add_argument("--subdivisions", type=opt.positive_int, help="elements per pinned-beam member (4)")
    p.add_argument("--update", choices=("per-step", "frozen"), default="per-step",
                   help="matrices of the current geometry (default) or the initial one")
    p.add_argument("--damping", type=opt.nonneg_real, nargs=2, metavar=("ALPHA", "BETA"),
                   help="Rayleigh damping C = ALPHA M + BETA K")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the results as JSON")
    p.add_argument("--plot", metavar="PNG", type=opt.output_file, help="axial-force histories of every member")
    p.add_argument("--vtk", metavar="DIR", type=opt.output_dir, help="write a .pvd time series for ParaView")
    p.add_argument("--vtk-every", type=opt.positive_int, default=1, metavar="K",
                   help="write every K-th time step to the VTK series (default 1: all)")
    p.set_defaults(func=_run)


def write_vtk(directory, res, stem: str = "transient", every: int = 1) -> Path:
    """The response as a time series at the positions of the rigid motion (docs/vtk.md).

    ``stem.pvd``: point data ``displacement`` (elastic, dynamic) and
    ``displacement_quasi_static``; cell data ``axial_force``, ``axial_stress`` (N/A),
    ``axial_force_quasi_static``, ``axial_force_rigid`` (member midpoint, N), ``moment``,
    ``moment_quasi_static``, ``moment_rigid`` (midpoint bending-moment magnitude, N·m).
    Every ``every``-th step is written, and always the last one.
    """
    from ..io.vtk import write_series

    if isinstance(every, bool) or int(every) != every or every < 1:
        raise InputError("--vtk-every", f"must be a positive integer, got {every!r}")
    s = res.structure
    steps = np.unique(np.r_[np.arange(0, res.time.size, int(every)), res.time.size - 1])
    area = s.area
    frames = ({"time": float(res.time[k]), "coords": res.coords[k],
               "point_data": {"displacement": res.displacement[k],
                              "displacement_quasi_static": res.displacement_qs[k]},
               "cell_data": {"axial_force": res.axial_force[k],
                             "axial_stress": res.axial_force[k] / area,
                             "axial_force_quasi_static": res.axial_force_qs[k],
                             "axial_force_rigid": res.axial_force_rigid[k],
                             "moment": res.moment[k], "moment_quasi_static": res.moment_qs[k],
                             "moment_rigid": res.moment_rigid[k]}}
              for k in steps)
    return write_series(directory, s, frames, stem)


def _plot(path, res) -> None:
    from ..io.figures import subplots

    m = res.structure.n_members
    fig, axes = subplots(m, 1, figsize=(7.0, 2.2 * m), squeeze=False)
    for j, ax in enumerate(axes[:, 0]):
        ax.plot(res.time, res.axial_force_rigid[:, j], color="0.6", lw=3, label="rigid body")
        ax.plot(res.time, res.axial_force_qs[:, j], "k--", lw=1.2, label="FE quasi-static")
        ax.plot(res.time, res.axial_force[:, j], color="tab:red", lw=1, label="FE elastic")
        ax.set_ylabel(f"{res.structure.member_ids[j]}, N", fontsize=8)
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=7)
    axes[-1, 0].set_xlabel("time, s")
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=110, format="png")


def _run(args: argparse.Namespace) -> int:
    if args.vtk_every < 1:          # before a long analysis, not after it
        raise InputError("--vtk-every", f"must be a positive integer, got {args.vtk_every}")
    with progress_bar("transient") as tick:
        result = api.transient(args.model, motion=args.motion, steps=args.steps, dt=args.dt,
                               t_end=args.t_end, bar_model=args.bar_model,
                               subdivisions=args.subdivisions, update=args.update,
                               damping=args.damping, progress=tick)
    res = result.solution
    if args.json:
        write_json(args.json, result.to_dict())
    if args.plot:
        _plot(args.plot, res)
    if args.vtk:
        write_vtk(args.vtk, res, stem=Path(args.model).stem, every=args.vtk_every)
    dep = res.departure()
    # the largest relative departure among members with a quasi-static force (a member
    # without one has no ratio, NaN, which must not win or lose the comparison at random);
    # the largest absolute departure when no member has one
    rated = [k for k in dep if math.isfinite(dep[k]["relative"])]
    worst = (max(rated, key=lambda k: dep[k]["relative"]) if rated
             else max(dep, key=lambda k: dep[k]["max_abs"]))
    share = (f" ({100 * dep[worst]['relative']:.3g} %)" if math.isfinite(dep[worst]["relative"])
             else "")
    print(f"{res.structure.name}: {res.time.size} steps of {res.dt:.3g} s; f1 = "
          f"{res.frequencies_hz[0]:.4g} Hz; largest departure of the elastic axial force from "
          f"the quasi-static one: {dep[worst]['max_abs']:.4g} N{share} in member {worst}; "
          f"energy residual {res.energy_residual():.2g}")
    return 0
