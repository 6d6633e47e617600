# SPDX-License-Identifier: MIT
"""Outputs of a simulation: the JSON document (docs/json.md), NPZ arrays, VTK time series, plots.

Every writer goes through :mod:`trussfe.io.output` (temporary file, then rename), so a failed
run leaves nothing half-written.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..io.json_document import result_json
from ..io.output import atomic_dir, atomic_path
from .active import active_members
from .simulate import SimulationResult


def to_json(res: SimulationResult) -> dict:
    """The ``simulate`` JSON document (docs/json.md, ``simulate``), with its ``summary`` section.

    ``members.ID.axial_force`` is the axial force at the middle of the member's tube (N,
    positive in tension), ``max_von_mises`` the largest von Mises stress over its sections (Pa),
    both per time step; ``nodes.ID.reaction`` only on supported nodes.
    """
    s = res.structure
    dim = s.dim
    members = {}
    summary = {}
    for k, mid in enumerate(s.member_ids):
        members[mid] = {"axial_force": res.midpoint_axial_force[:, k],
                        "max_von_mises": res.stresses.von_mises[:, k].max(axis=1),
                        "static_max_von_mises": res.static_stresses.von_mises[:, k].max(axis=1)}
        d = res.member_summary(k)
        d["buckling"] = {"allowable": float(res.buckling.allowable[k]),
                         "column_length": float(res.buckling.column_length[k]),
                         "max_compression": float(res.buckling.max_compression[k]),
                         "margin": float(res.buckling.margin[k])}
        summary[mid] = d
    nodes = {}
    supported = s.translation_supports.any(axis=1)
    for i, nid in enumerate(s.node_ids):
        nodes[nid] = {"position": res.kinematics.coords[:, i, :dim]}
        if supported[i]:
            nodes[nid]["reaction"] = res.forces.reactions[:, i]
    actuators = {}
    for j, a in enumerate(active_members(s)):
        aid = s.member_ids[a.member]
        col = list(res.motion.members).index(a.member) if a.member in res.motion.members \
            else None
        entry = {"length": res.kinematics.length[:, a.member],
                 "force": res.actuator_force[:, j],
                 "static_force": res.static_actuator_force[:, j],
                 "cantilever_moment": res.cantilever_moment[:, j]}
        if col is not None:
            entry["velocity"] = res.motion.velocity[:, col]
            entry["acceleration"] = res.motion.acceleration[:, col]
        entry.update(res.actuators.get(aid, {}))
        actuators[aid] = entry
    return result_json("simulate", s.name, time=res.time, options=res.options,
                           members=members, nodes=nodes, actuators=actuators,
                           summary={"members": summary})


def write_npz(path: str | Path, res: SimulationResult) -> None:
    """All arrays of the result in one NumPy ``.npz`` file: the motion's positions, node
    velocities and accelerations, member lengths and their rates, member angular velocities
    and accelerations, pin forces and reactions (in motion and at rest), section forces
    (tension, shear, moment; at rest: tension), von Mises stresses (in motion and at rest),
    midpoint axial forces, actuator forces (in motion and at rest), cantilever moments and
    the buckling check (allowable, largest compression, margin).

    ``shear_local`` and ``moment_local`` (nt, m, k, 2) are the two shears and two bending
    moments in the member frames of :func:`trussfe.mechanics.geometry.transverse_frames`.
    """
    from .sections import local_components
    shear_local, moment_local = local_components(res.sections)
    arrays = {
        "shear_local": shear_local, "moment_local": moment_local,
        "time": res.time, "coords": res.kinematics.coords,
        "velocity": res.kinematics.velocity, "acceleration": res.kinematics.acceleration,
        "end_force": res.forces.end_force, "reactions": res.forces.reactions,
        "static_end_force": res.static_forces.end_force,
        "section_position": res.sections.position, "tension": res.sections.tension,
        "shear": res.sections.shear, "moment": res.sections.moment,
        "von_mises": res.stresses.von_mises, "static_von_mises": res.static_stresses.von_mises,
        "actuator_force": res.actuator_force, "member_ids": np.array(res.structure.member_ids),
        "node_ids": np.array(res.structure.node_ids),
        # the member kinematics, the forces at rest and the checks beside them
        "length": res.kinematics.length, "length_rate": res.kinematics.length_rate,
        "length_acc": res.kinematics.length_acc, "omega": res.kinematics.omega,
        "alpha": res.kinematics.alpha, "static_reactions": res.static_forces.reactions,
        "static_tension": res.static_sections.tension,
        "midpoint_axial_force": res.midpoint_axial_force,
        "static_actuator_force": res.static_actuator_force,
        "cantilever_moment": res.cantilever_moment,
        "buckling_allowable": res.buckling.allowable,
        "buckling_max_compression": res.buckling.max_compression,
        "buckling_margin": res.buckling.margin,
    }
    with atomic_path(path) as tmp:
        with open(tmp, "wb") as fh:
            np.savez_compressed(fh, **arrays)


def write_vtk(directory: str | Path, res: SimulationResult, stem: str = "simulate") -> Path:
    """A ParaView time series: ``stem.pvd`` + one ``.vtu`` per step (docs/vtk.md).

    Point data ``displacement`` (from the first step), ``velocity``, ``acceleration``; cell data
    ``axial_force`` (midpoint), ``von_mises`` and ``static_von_mises`` (maxima over sections),
    ``buckling_utilisation`` (largest compression over the member's sections divided by its
    Euler allowable load, eq. 2.26/4.77: 0 in tension, 1 at the allowable) and
    ``actuator_force`` (force of the active base on the leadscrew tube; 0 on passive members,
    which have no actuator).
    """
    import meshio

    from ..io.vtk import write_pvd

    s = res.structure
    X = res.kinematics.coords
    pad = np.zeros(X.shape[:2] + (3 - s.dim,))
    X3 = np.concatenate([X, pad], axis=2)
    vm = res.stresses.von_mises.max(axis=2)
    vs = res.static_stresses.von_mises.max(axis=2)
    compression = np.clip(-res.sections.tension, 0.0, None).max(axis=2)      # (nt, m)
    utilisation = compression / res.buckling.allowable[None, :]
    act = np.zeros_like(res.midpoint_axial_force)
    members = [a.member for a in active_members(s)]
    if members:
        act[:, members] = res.actuator_force
    entries = []
    with atomic_dir(directory) as tmp:
        for k, t in enumerate(res.time):
            name = f"{stem}_{k:05d}.vtu"
            mesh = meshio.Mesh(
                X3[k], [("line", s.connectivity)],
                point_data={"displacement": X3[k] - X3[0],
                            "velocity": res.kinematics.velocity[k],
                            "acceleration": res.kinematics.acceleration[k]},
                cell_data={"axial_force": [res.midpoint_axial_force[k]],
                           "von_mises": [vm[k]], "static_von_mises": [vs[k]],
                           "buckling_utilisation": [utilisation[k]],
                           "actuator_force": [act[k]]})
            mesh.write(tmp / name)
            entries.append((float(t), name))
        # the step times as the JSON gives them (every digit), in the one .pvd writer
        write_pvd(tmp / f"{stem}.pvd", entries)
    return Path(directory) / f"{stem}.pvd"


def write_plots(directory: str | Path, res: SimulationResult) -> list[Path]:
    """Thesis-style figures as PNG (Lacy Figs. 3.1–3.10, 5.9–5.16).

    ``active_motion.png`` (position, velocity, acceleration of the active members),
    ``von_mises.png`` (maximum von Mises over time, total versus static, per member),
    ``actuator_force.png`` and, with motor data, ``motor.png`` (torque, voltage, current).
    """
    from ..io.figures import subplots

    s = res.structure
    t = res.time
    names = []
    with atomic_dir(directory) as tmp:
        fig, ax = subplots(3, 1, sharex=True, figsize=(6, 7))
        for j, k in enumerate(res.motion.members):
            lab = s.member_ids[k]
            ax[0].plot(t, res.motion.length[:, j], label=lab)
            ax[1].plot(t, res.motion.velocity[:, j], label=lab)
            ax[2].plot(t, res.motion.acceleration[:, j], label=lab)
        for a, yl in zip(ax, ("length (m)", "velocity (m/s)", "acceleration (m/s²)")):
            a.set_ylabel(yl)
            a.grid(True)
        ax[0].legend(fontsize="small")
        ax[2].set_xlabel("time (s)")
        fig.tight_layout()
        fig.savefig(tmp / "active_motion.png", dpi=120)
        names.append("active_motion.png")

        vm = res.stresses.von_mises.max(axis=2)
        vs = res.static_stresses.von_mises.max(axis=2)
        worst = np.argsort(-vm.max(axis=0))[:6]
        fig, ax = subplots(figsize=(7, 4.5))
        for k in worst:
            line, = ax.plot(t, vm[:, k], label=f"{s.member_ids[k]} total")
            ax.plot(t, vs[:, k], "--", color=line.get_color(), label=f"{s.member_ids[k]} static")
        ax.set_xlabel("time (s)")
        ax.set_ylabel("maximum von Mises stress (Pa)")
        ax.grid(True)
        ax.legend(fontsize="small", ncol=2)
        fig.tight_layout()
        fig.savefig(tmp / "von_mises.png", dpi=120)
        names.append("von_mises.png")

        if res.actuator_force.size:
            fig, ax = subplots(figsize=(7, 4))
            for j, a in enumerate(active_members(s)):
                line, = ax.plot(t, res.actuator_force[:, j], label=s.member_ids[a.member])
                ax.plot(t, res.static_actuator_force[:, j], "--", color=line.get_color(),
                        label=f"{s.member_ids[a.member]} static")
            ax.set_xlabel("time (s)")
            ax.set_ylabel("actuator force on the leadscrew tube (N)")
            ax.grid(True)
            ax.legend(fontsize="small")
            fig.tight_layout()
            fig.savefig(tmp / "actuator_force.png", dpi=120)
            names.append("actuator_force.png")

        keys = [("motor_torque", "motor torque (N·m)"), ("motor_voltage", "motor voltage (V)"),
                ("motor_current", "motor current (A)")]
        if res.actuators and any(k in v for v in res.actuators.values() for k, _ in keys):
            fig, ax = subplots(3, 1, sharex=True, figsize=(6, 7))
            for aid, h in res.actuators.items():
                for a, (k, yl) in zip(ax, keys):
                    if k in h:
                        a.plot(t, np.asarray(h[k]), label=aid)
                    a.set_ylabel(yl)
                    a.grid(True)
            ax[0].legend(fontsize="small")
            ax[2].set_xlabel("time (s)")
            fig.tight_layout()
            fig.savefig(tmp / "motor.png", dpi=120)
            names.append("motor.png")
    return [Path(directory) / n for n in names]
