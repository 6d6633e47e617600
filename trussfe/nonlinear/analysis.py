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
        log.warning("%s: gravity is not part of the post-critical load pattern; only [loads] "
                    "is scaled by the load factor", structure.source or structure.name)
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


def result_document(result: PathResult) -> dict:
    """The CONTRACT §3 ``postcritical`` JSON document of a path."""
    m = result.model
    s = m.structure
    ids = s.node_ids
    path = []
    for p in result.path:
        d = p.u[: s.n_nodes * s.dim].reshape(s.n_nodes, s.dim)
        path.append({"load_factor": float(p.load_factor), "stage": p.stage,
                     "negative_eigenvalues": (None if p.negative is None
                                             else int(p.negative)),
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
    node, axis = divmod(result.monitor, s.dim)
    doc = {"units": "SI", "command": "postcritical", "model": s.name,
           "monitor": {"node": ids[node], "axis": AXES[axis]},
           "path": path, "events": events, "termination": result.termination,
           "max_load_factor": float(max(p.load_factor for p in result.path))}
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
