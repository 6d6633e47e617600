# SPDX-License-Identifier: MIT
"""The post-critical analysis of a model file: settings, run, JSON document, VTK, plot.

Analysis settings may be given in the model file's ``[postcritical]`` table (command-line
options override them)::

    [postcritical]
    control = "arc-length"        # "load" | "displacement" | "arc-length"
    steps = 200
    step = 0.002                  # first increment (Δλ, Δu or Δs; see follow_path)
    max_step = 0.01               # largest increment the step control may grow to
    max_load_factor = 5.0
    monitor = "3:y"               # node:axis of the displacement plotted and controlled
    bar_model = "truss"           # "truss" | "pinned-beam"
    subdivisions = 8
    imperfection = 0.001          # m, amplitude of the first linear buckling mode
    branch = false                # follow the secondary branch at a bifurcation
    max_displacement = 0.5        # m, stop when the monitored displacement exceeds it
"""
from __future__ import annotations

import logging
import math
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import AnalysisError, InputError
from ..io.model_file import read_model, register_table
from ..model.structure import Structure
from .buckling import apply_imperfection, linear_buckling
from .failure import FailureLaws, parse_failure_table
from .model import BAR_MODELS, NonlinearModel
from .path import CONTROLS, PathResult, follow_path

SETTINGS = {"control": str, "steps": int, "step": float, "max_load_factor": float,
            "monitor": str, "bar_model": str, "subdivisions": int, "imperfection": float,
            "branch": bool, "max_displacement": float, "max_step": float}
AXES = "xyz"
log = logging.getLogger(__name__)


def parse_settings(raw: Any, structure: Structure | None = None, base_dir=None) -> dict:
    """Read the ``[postcritical]`` table (every value checked, item named)."""
    if not isinstance(raw, dict):
        raise InputError("[postcritical]", "expected a table of analysis settings")
    out = {}
    for k, v in raw.items():
        item = f"postcritical.{k}"
        if k not in SETTINGS:
            raise InputError(item, f"unknown key; valid: {', '.join(SETTINGS)}")
        typ = SETTINGS[k]
        if typ is float:
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                raise InputError(item, f"expected a finite number, got {v!r}")
            v = float(v)
            if k in ("step", "max_load_factor", "max_displacement", "max_step") and v <= 0:
                raise InputError(item, f"must be positive, got {v}")
            if k == "imperfection" and v < 0:
                raise InputError(item, f"must not be negative, got {v}")
        elif typ is int:
            if isinstance(v, bool) or not isinstance(v, int) or v < 1:
                raise InputError(item, f"expected a positive integer, got {v!r}")
        elif typ is bool:
            if not isinstance(v, bool):
                raise InputError(item, f"expected true or false, got {v!r}")
        else:
            if not isinstance(v, str):
                raise InputError(item, f"expected a string, got {v!r}")
        out[k] = v
    if "control" in out and out["control"] not in CONTROLS:
        raise InputError("postcritical.control", f"unknown control {out['control']!r}; "
                                                 f"valid: {', '.join(CONTROLS)}")
    if "bar_model" in out and out["bar_model"] not in BAR_MODELS:
        raise InputError("postcritical.bar_model", f"unknown bar model; valid: "
                                                   f"{', '.join(BAR_MODELS)}")
    if "monitor" in out and structure is not None:
        parse_monitor(out["monitor"], structure, "postcritical.monitor")
    return out


def parse_monitor(text: str, structure: Structure, item: str = "--monitor") -> tuple[int, int]:
    """``"NODE:AXIS"`` → (node index, axis index)."""
    node, sep, axis = str(text).rpartition(":")
    if not sep or axis not in AXES[: structure.dim]:
        raise InputError(item, f"expected NODE:AXIS with AXIS in {AXES[:structure.dim]}, "
                               f"got {text!r}")
    if node not in structure.node_ids:
        raise InputError(item, f"node '{node}' is not defined")
    return structure.node_index(node), AXES.index(axis)


register_table("failure", parse_failure_table)
register_table("postcritical", parse_settings)


def run_postcritical(structure: Structure, **options) -> PathResult:
    """Follow the post-critical path of a structure (options as in ``[postcritical]``).

    Options given as keywords override the model's ``[postcritical]`` table; ``None`` values
    are ignored.  Extra keywords go to :func:`~trussfe.nonlinear.path.follow_path`.
    """
    opts = dict(structure.extensions.get("postcritical", {}))
    given = {k: v for k, v in options.items() if v is not None}
    if "control" in given and given["control"] != opts.get("control", "arc-length") \
            and "step" not in given:
        # the file's increments belong to its own control (Δλ, Δu and Δs differ)
        opts.pop("step", None)
        opts.pop("max_step", None)
    opts.update(given)
    laws = structure.extensions.get("failure") or FailureLaws.none(structure.n_members)
    if np.any(structure.gravity != 0):
        log.info("%s: gravity acts as a constant dead load; [loads] is scaled by the load "
                 "factor", structure.source or structure.name)
    model = NonlinearModel(structure, bar_model=opts.pop("bar_model", "truss"),
                           subdivisions=opts.pop("subdivisions", 8), laws=laws)
    imperfection = opts.pop("imperfection", 0.0)
    if imperfection:
        _, modes = linear_buckling(model, count=1)
        apply_imperfection(model, modes[:, 0], imperfection)
    monitor = opts.pop("monitor", None)
    if monitor is not None:
        node, axis = parse_monitor(monitor, structure) if isinstance(monitor, str) else monitor
        monitor = model.dof(node, axis)
    result = follow_path(model, monitor=monitor, **opts)
    if len(result.path) < 2 and result.termination.startswith("path cannot"):
        raise AnalysisError(structure.source or structure.name, result.termination)
    return result


def unmodelled_buckling(result: PathResult) -> tuple[int, float, float] | None:
    """The first bar to pass its Euler load on a path that does not model member buckling.

    Without a ``[failure]`` table a bar modelled as a truss element stays straight in
    compression whatever the force; this finds, along the path, the first state where a
    live bar's compression exceeds its pinned–pinned Euler load
    (:func:`~trussfe.fem.buckling.euler_load`, Lacy eq. 2.26).

    Returns
    -------
    tuple or None
        ``(member, load factor, Euler load N)``, or None when no bar passes it, when the model
        has failure laws, or when its bars have no second moment of area.
    """
    from ..fem.buckling import euler_load
    m = result.model
    s = m.structure
    if "failure" in s.extensions or m.t_member.size == 0 or not result.path:
        return None
    with np.errstate(invalid="ignore"):
        Pe = euler_load(s)[m.t_member]
    ok = np.isfinite(Pe) & (Pe > 0)
    if not ok.any():
        return None
    N = np.array([p.forces[m.t_member] for p in result.path])          # (point, bar)
    over = (N < -Pe[None, :]) & ok[None, :]
    if not over.any():
        return None
    point = int(np.flatnonzero(over.any(axis=1))[0])
    bar = int(np.argmax(np.where(over[point], -N[point] / np.where(ok, Pe, 1.0), -np.inf)))
    return int(m.t_member[bar]), float(result.path[point].load_factor), float(Pe[bar])


def monitor_label(model, dof: int) -> dict:
    """``{"node": id, "axis": "x" … "z" or "rx" … "rz"}`` of a monitored DOF (a joint's
    translation, or a joint rotation when the loads are moments only)."""
    s = model.structure
    ids = s.node_ids
    if dof < s.n_nodes * s.dim:
        node, axis = divmod(dof, s.dim)
        return {"node": ids[node], "axis": AXES[axis]}
    slot, comp = divmod(dof - model.n_points * s.dim, model.rdof)
    node = int(np.flatnonzero(model.joint_slot == slot)[0])
    return {"node": ids[node], "axis": "rz" if s.dim == 2 else "r" + AXES[comp]}


def result_document(result: PathResult) -> dict:
    """The CONTRACT §3 ``postcritical`` JSON document of a path."""
    m = result.model
    s = m.structure
    ids = s.node_ids
    path = []
    for p in result.path:
        d = p.u[: s.n_nodes * s.dim].reshape(s.n_nodes, s.dim)
        path.append({"load_factor": float(p.load_factor), "stage": p.stage,
                     "negative_eigenvalues": int(p.negative),
                     "displacements": {ids[i]: d[i].tolist() for i in range(s.n_nodes)},
                     "failed_members": [s.member_ids[i] for i in np.flatnonzero(~p.alive)]})
    events = []
    for e in result.events:
        ev = {"load_factor": float(e.load_factor),
              "member": None if e.member is None else s.member_ids[e.member],
              "kind": e.kind, "path_index": int(e.point), "detail": e.detail}
        if e.kind in ("buckling", "yield"):
            ev["axial_force"] = float(e.force)
            ev["law_limit"] = float(e.threshold)
        elif e.kind == "fracture":
            ev["strain"] = float(e.force)
            ev["law_limit"] = float(e.threshold)
        events.append(ev)
    doc = {"units": "SI", "command": "postcritical", "model": s.name,
           "monitor": monitor_label(result.model, result.monitor),
           "path": path, "events": events, "termination": result.termination,
           "max_load_factor": float(max(p.load_factor for p in result.path)),
           "gravity_dead_load": bool(np.any(result.model.dead != 0))}
    mot = result.mechanism
    if mot is not None:
        alive = result.path[-1].alive
        form = mot.positions[-1]
        doc["mechanism"] = {
            "mechanisms": int(mot.mechanisms), "equilibrium_form_found": bool(mot.converged),
            "stable": bool(mot.stable), "residual": float(mot.residual), "reason": mot.reason,
            "potential": [float(v) for v in mot.potential],
            "equilibrium_form": {ids[i]: form[i].tolist() for i in range(s.n_nodes)},
            "member_forces": ({s.member_ids[j]: float(t) for j, t in
                               zip(np.flatnonzero(alive), mot.tensions)}
                              if mot.tensions is not None else {}),
        }
    return doc


def analyse(model_path: str | Path, **options) -> dict:
    """Read a model file, run the post-critical analysis, return the JSON document."""
    structure = read_model(model_path)
    return result_document(run_postcritical(structure, **options))
