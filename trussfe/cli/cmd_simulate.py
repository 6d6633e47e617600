# SPDX-License-Identifier: MIT
"""``trussfe simulate MODEL [--motion MOTION]``: rigid-body dynamic force analysis (Lacy)."""
from __future__ import annotations

import argparse
import logging
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from .. import api
from ..io.output import write_json
from . import options as opt
from .progress import progress_bar

if TYPE_CHECKING:
    from ..rigid.simulate import SimulationResult

log = logging.getLogger(__name__)


def register(subparsers) -> None:
    """Add the ``simulate`` command."""
    p = subparsers.add_parser(
        "simulate", help="rigid-body dynamic force analysis along a motion",
        description="Forces, section forces, von Mises stresses, buckling margins and actuator "
        "loads of a pin-jointed truss along a prescribed motion of its active members. "
        "Without --motion the model is analysed at rest (one step).")
    p.add_argument("model", type=opt.input_file, help="model file (TOML) with [active_members]")
    p.add_argument("--motion", type=opt.input_file, help="motion file: TOML [motion] spec or CSV history")
    p.add_argument("--steps", type=opt.positive_int, help="number of time steps of a generated motion")
    p.add_argument("--scheme", choices=("exact", "thesis"), default="exact",
                   help="kinematics: exact (default) or Lacy's backward differences")
    p.add_argument("--method", choices=("auto", "direct", "bay-by-bay"), default="auto",
                   help="auto (default): bay-by-bay for a chain of two or more identical bays, "
                   "else direct; direct: the whole truss at once; bay-by-bay: a chain of "
                   "identical bays by Lacy's chapter 6 (positions bay by bay, kinematics up "
                   "the chain, forces down)")
    p.add_argument("--sections", type=opt.positive_int, default=7,
                   help="sections per member for internal forces (default 7)")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the results as JSON")
    p.add_argument("--npz", metavar="OUT", type=opt.output_file, help="write all arrays as NumPy .npz")
    p.add_argument("--vtk", metavar="DIR", type=opt.output_dir, help="write a .pvd time series")
    p.add_argument("--plots", metavar="DIR", type=opt.output_dir, help="write thesis-style PNG figures")
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    from ..rigid.output import write_npz, write_plots, write_vtk

    with progress_bar("simulate") as tick:
        result = api.simulate(args.model, motion=args.motion, steps=args.steps,
                              scheme=args.scheme, sections=args.sections,
                              method=args.method, progress=tick)
    res = result.solution
    if args.json:
        write_json(args.json, result.to_dict())
    if args.npz:
        write_npz(args.npz, res)
    if args.vtk:
        write_vtk(args.vtk, res, stem=Path(args.model).stem)
    if args.plots:
        write_plots(args.plots, res)
    print(f"{res.structure.name}: {res.time.size} steps; {_stress_clause(res)}; "
          f"{_buckling_clause(res)}")
    return 0


def _stress_clause(res: SimulationResult) -> str:
    """The summary's stress: the largest von Mises stress over the members that have one.

    A member whose section has no outer-fibre distance c has no bending stress, so no von
    Mises stress where it bends (NaN in the arrays, ``null`` in JSON); the clause names such
    sections, and gives the largest axial stress instead when no member has a von Mises stress.
    """
    s = res.structure
    vm = res.stresses.von_mises                                  # (step, member, section)
    defined = np.all(np.isfinite(vm), axis=(0, 2))
    if np.all(defined):
        worst = max(range(s.n_members), key=lambda k: vm[:, k].max())
        summ = res.member_summary(worst)
        return (f"largest von Mises {summ['max_von_mises']:.5g} Pa in member "
                f"{s.member_ids[worst]} at t = {summ['time']:.4g} s")
    names = sorted({s.sections[k].name for k in np.flatnonzero(~defined)})
    why = (f"section{'s' if len(names) > 1 else ''} {', '.join(names)} "
           f"without an outer-fibre distance c")
    if np.any(defined):
        worst = max(np.flatnonzero(defined).tolist(), key=lambda k: vm[:, k].max())
        summ = res.member_summary(worst)
        n_out = int(np.count_nonzero(~defined))
        return (f"largest von Mises {summ['max_von_mises']:.5g} Pa in member "
                f"{s.member_ids[worst]} at t = {summ['time']:.4g} s (not computed for "
                f"{n_out} member{'s' if n_out > 1 else ''} of {why})")
    axial = np.abs(res.stresses.axial)
    i, k, _ = np.unravel_index(int(np.argmax(axial)), axial.shape)
    return (f"von Mises not computed ({why}); largest |axial stress| "
            f"{axial[i, k].max():.5g} Pa in member {s.member_ids[k]} at t = {res.time[i]:.4g} s")


def _buckling_clause(res: SimulationResult) -> str:
    """The summary's buckling margin; none when no member is ever compressed."""
    margin = res.buckling.margin
    if not np.any(np.isfinite(margin)):
        return "no member in compression (no buckling margin)"
    return f"smallest buckling margin {margin.min():.3g}"
