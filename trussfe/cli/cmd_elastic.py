# SPDX-License-Identifier: MIT
"""``trussfe elastic MODEL [--motion MOTION]``: FE response along a rigid-body motion."""
from __future__ import annotations

import argparse
import logging
from pathlib import Path

import numpy as np

from .. import rigid as _rigid  # noqa: F401  (registers [active_members])
from ..errors import InputError
from ..io.model_file import read_model
from ..io.output import write_json
from . import options as opt

log = logging.getLogger(__name__)


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
                   help="elements per member (default sections - 1)")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the results as JSON")
    p.add_argument("--vtk", metavar="DIR", type=opt.output_dir, help="write a .pvd time series")
    p.set_defaults(func=_run)


def _elastic(model_path, motion=None, steps=None, scheme="exact", sections=7,
             subdivisions=None):
    from ..elastic.along_motion import simulate_elastic
    from ..rigid.motion import load_motion

    structure = read_model(model_path)
    mot = None
    if motion is not None:
        beside = Path(model_path).parent / motion
        if not Path(motion).is_file() and not Path(motion).is_absolute() and beside.is_file():
            motion = beside
        mot = load_motion(motion, structure, steps=steps)
    elif steps is not None:
        raise InputError("--steps", "needs --motion (without a motion the model is at rest)")
    return simulate_elastic(structure, mot, scheme=scheme, n_sections=sections,
                            subdivisions=subdivisions)


def to_json(sim, resp, cmp) -> dict:
    """The ``elastic`` JSON document (CONTRACT.md §3 style, one value per time step).

    ``members[id]``: ``axial_force`` (FE, tube midpoint), ``strain`` (N/EA there),
    ``rigid_axial_force``; ``nodes[id]``: ``displacement`` (elastic, from the rigid-body
    position), ``reaction`` (supported nodes); ``comparison``: largest scaled FE − rigid
    differences (:func:`trussfe.elastic.along_motion.compare_with_rigid`).
    """
    s = sim.structure
    dim = s.dim
    members = {mid: {"axial_force": resp.midpoint_axial_force[:, i].tolist(),
                     "strain": resp.strain[:, i].tolist(),
                     "rigid_axial_force": sim.midpoint_axial_force[:, i].tolist()}
               for i, mid in enumerate(s.member_ids)}
    nodes = {}
    for i, nid in enumerate(s.node_ids):
        d = {"displacement": resp.displacements[:, i].tolist()}
        if s.supports[i, :dim].any():
            d["reaction"] = resp.reactions[:, i].tolist()
        nodes[nid] = d
    return {"units": "SI", "command": "elastic", "model": s.name, "bar_model": "pinned-beam",
            "subdivisions": resp.subdivisions, "time": sim.time.tolist(),
            "members": members, "nodes": nodes, "comparison": cmp}


def analyse(model_path, **options) -> dict:
    """Run ``elastic`` and return its JSON document (options: ``motion``, ``steps``,
    ``scheme``, ``sections``, ``subdivisions``)."""
    return to_json(*_elastic(model_path, **options))


def write_vtk(directory, sim, resp, stem: str = "elastic") -> Path:
    """Two time series at the positions of the rigid motion (CONTRACT.md §4).

    ``stem.pvd``: point data ``displacement`` (elastic), cell data ``axial_force`` (FE,
    midpoint), ``strain``, ``rigid_axial_force``.  ``stem_stations.pvd``: every member as a
    polyline through its FE stations with point data ``axial_force``, ``shear_y``,
    ``shear_z``, ``moment_y``, ``moment_z`` (member axes, N and N·m).
    """
    from ..io.vtk import station_mesh, write_series

    s = sim.structure
    frames = ({"time": float(t), "coords": sim.kinematics.coords[k],
               "point_data": {"displacement": resp.displacements[k]},
               "cell_data": {"axial_force": resp.midpoint_axial_force[k],
                             "strain": resp.strain[k],
                             "rigid_axial_force": sim.midpoint_axial_force[k]}}
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
    sim, resp, cmp = _elastic(args.model, args.motion, args.steps, args.scheme, args.sections,
                              args.subdivisions)
    if args.json:
        write_json(args.json, to_json(sim, resp, cmp))
    if args.vtk:
        write_vtk(args.vtk, sim, resp, stem=Path(args.model).stem)
    k = int(np.argmax(np.abs(resp.strain).max(axis=0)))
    print(f"{sim.structure.name}: {sim.time.size} steps; largest |strain| "
          f"{np.abs(resp.strain[:, k]).max():.4g} in member {sim.structure.member_ids[k]}; "
          f"FE vs rigid section forces: largest scaled difference {cmp['max']:.2e}")
    return 0
