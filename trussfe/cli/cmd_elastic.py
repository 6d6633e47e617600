# SPDX-License-Identifier: MIT
"""``trussfe elastic MODEL [--motion MOTION]``: FE response along a rigid-body motion."""
from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from .. import api
from ..io.output import write_json
from . import options as opt
from .progress import progress_bar


def register(subparsers) -> None:
    """Add the ``elastic`` command."""
    p = subparsers.add_parser(
        "elastic", help="finite-element response along a rigid-body motion",
        description="At every step of a motion, the pinned-beam finite-element model in the "
        "current configuration under gravity and the d'Alembert loads of the rigid-body "
        "motion: displacements, reactions, section forces and strains, compared with the "
        "rigid-body model's internal forces. Without --motion the model is analysed at rest.")
    p.add_argument("model", type=opt.input_file, help="model file (TOML), with [active_members] if it moves")
    p.add_argument("--motion", type=opt.input_file, help="motion file: TOML [motion] spec or CSV history")
    p.add_argument("--steps", type=opt.positive_int, help="number of time steps of a generated motion")
    p.add_argument("--scheme", choices=("exact", "thesis"), default="exact",
                   help="kinematics: exact (default) or Lacy's backward differences")
    p.add_argument("--sections", type=opt.positive_int, default=7,
                   help="sections per member tube compared with the rigid model (default 7)")
    p.add_argument("--subdivisions", type=opt.positive_int,
                   help="elements per member (default sections - 1, at least 2)")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the results as JSON")
    p.add_argument("--vtk", metavar="DIR", type=opt.output_dir, help="write a .pvd time series")
    p.set_defaults(func=_run)


def write_vtk(directory, sim, resp, stem: str = "elastic") -> Path:
    """Two time series at the positions of the rigid motion (docs/vtk.md).

    ``stem.pvd``: point data ``displacement`` (elastic), cell data ``axial_force`` (FE,
    midpoint), ``strain``, ``axial_force_rigid``.  ``stem_stations.pvd``: every member as a
    polyline through its FE stations with point data ``axial_force``, ``shear_y``,
    ``shear_z``, ``moment_y``, ``moment_z`` (member axes, N and N·m).
    """
    from ..io.vtk import station_mesh, write_series

    s = sim.structure
    frames = ({"time": float(t), "coords": sim.kinematics.coords[k],
               "point_data": {"displacement": resp.displacements[k]},
               "cell_data": {"axial_force": resp.midpoint_axial_force[k],
                             "strain": resp.strain[k],
                             "axial_force_rigid": sim.midpoint_axial_force[k]}}
              for k, t in enumerate(sim.time))
    out = write_series(directory, s, frames, stem)
    names = {"axial_force": 0, "shear_y": 1, "shear_z": 2, "moment_y": 4, "moment_z": 5}
    stations = ({"time": float(t), "mesh": station_mesh(
        s, resp.station_x[k] / resp.station_x[k, :, -1:], coords=sim.kinematics.coords[k],
        point_data={nm: resp.station_forces[k, :, :, i] for nm, i in names.items()})}
        for k, t in enumerate(sim.time))
    write_series(directory, s, stations, f"{stem}_stations")
    return out


def _run(args: argparse.Namespace) -> int:
    with progress_bar("elastic") as tick:
        result = api.elastic(args.model, motion=args.motion, steps=args.steps, scheme=args.scheme,
                             sections=args.sections, subdivisions=args.subdivisions,
                             progress=tick)
    sim, resp, cmp = result.rigid, result.solution, result.comparison
    if args.json:
        write_json(args.json, result.to_dict())
    if args.vtk:
        write_vtk(args.vtk, sim, resp, stem=Path(args.model).stem)
    k = int(np.argmax(np.abs(resp.strain).max(axis=0)))
    print(f"{sim.structure.name}: {sim.time.size} steps; largest |strain| "
          f"{np.abs(resp.strain[:, k]).max():.4g} in member {sim.structure.member_ids[k]}; "
          f"FE vs rigid section forces: largest scaled difference {cmp['max']:.2e}")
    return 0
