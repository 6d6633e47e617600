# SPDX-License-Identifier: MIT
"""The post-critical analysis of a model file: settings, run, JSON document, VTK, plot.

Analysis settings may be given in the model file's ``[postcritical]`` table
(:class:`trussfe.model.postcritical.PostcriticalSettings`; command-line options override
them)::

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

import inspect
import logging
import math
from pathlib import Path

import numpy as np

from ..budget import count_text, require
from ..errors import AnalysisError
from ..io.extension_tables import AXES, parse_monitor
from ..io.json_document import result_json
from ..io.model_file import read_model
from ..mechanics.euler import member_euler_loads
from ..model.bar_models import DEFAULT_POSTCRITICAL_SUBDIVISIONS
from ..model.structure import Structure
from .buckling import apply_imperfection, linear_buckling
from .failure import FailureLaws
from .model import NonlinearModel
from .path import PathResult, follow_path

log = logging.getLogger(__name__)


def run_postcritical(structure: Structure, **options) -> PathResult:
    """Follow the post-critical path of a structure (options as in ``[postcritical]``).

    Options given as keywords override the model's ``[postcritical]`` table; ``None`` values
    are ignored.  Extra keywords go to :func:`~trussfe.nonlinear.path.follow_path`.
    """
    settings = structure.extensions.get("postcritical")
    opts = settings.options() if settings is not None else {}
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
                           subdivisions=opts.pop("subdivisions",
                                                  DEFAULT_POSTCRITICAL_SUBDIVISIONS), laws=laws,
                           subdivisions_item=_option_item(structure, given, "subdivisions"))
    _require_path_memory(model, opts.get("steps", _DEFAULT_STEPS),
                         _option_item(structure, given, "steps"))
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


#: Steps of a path when neither the option nor ``[postcritical]`` gives them
#: (:func:`~trussfe.nonlinear.path.follow_path`'s default).
_DEFAULT_STEPS = inspect.signature(follow_path).parameters["steps"].default

#: Bytes kept per path point and DOF: the displacement vector, its entries in the JSON
#: document (a Python float in a list, then its text) and in the ``--vtk`` frame.
BYTES_PER_POINT_DOF = 96
#: ... per path point and member: axial force, alive flag, stress and failure flags.
BYTES_PER_POINT_MEMBER = 64
#: ... per path point: the point's record and its JSON entry.
BYTES_PER_POINT = 1024


def path_bytes(model: NonlinearModel, steps: float) -> float:
    """Estimated memory of the points of a path of ``steps`` steps: every step keeps one
    point (and the start state one), with the displacements of all DOFs and the member
    forces (:class:`~trussfe.nonlinear.path.PathPoint`), which the JSON document and the
    ``--vtk`` series write out again."""
    s = model.structure
    per_point = (BYTES_PER_POINT_DOF * model.ndof + BYTES_PER_POINT_MEMBER * s.n_members
                 + BYTES_PER_POINT)
    # an integer count beyond the largest float asks for unbounded memory
    points = float(steps) + 1.0 if steps < 1e300 else math.inf
    return points * per_point


def _require_path_memory(model: NonlinearModel, steps, item: str) -> None:
    """Refuse, before the first step, a number of steps whose path points cannot all be
    kept (:func:`trussfe.budget.require`): a path stops early only at an event, so the
    steps asked for are what it may store."""
    s = model.structure
    require(path_bytes(model, steps), item,
            f"a path of {count_text(steps)} steps ({s.n_nodes:,} nodes, {model.ndof:,} DOFs, "
            f"{s.n_members:,} members per point)", "use fewer steps")


def _option_item(structure: Structure, given: dict, key: str) -> str:
    """What gave the option ``key`` (``steps``, ``subdivisions``), to name when it is
    refused: the option, else the model file's ``[postcritical]`` table."""
    if key in given:
        return f"--{key}"
    return ": ".join(filter(None, (structure.source, f"postcritical.{key}")))


def unmodelled_buckling(result: PathResult) -> tuple[int, float, float] | None:
    """The first bar to pass its Euler load on a path that does not model member buckling.

    Without a ``[failure]`` table a bar modelled as a truss element stays straight in
    compression whatever the force; this finds, along the path, the first state where a
    live bar's compression exceeds its pinned–pinned Euler load
    (:func:`~trussfe.mechanics.euler.member_euler_loads`, Lacy eq. 2.26).

    Returns
    -------
    tuple or None
        ``(member, load factor, Euler load N)``, or None when no bar passes it, when the model
        has failure laws, or when its bars have no second moment of area.
    """
    m = result.model
    s = m.structure
    if "failure" in s.extensions or m.t_member.size == 0 or not result.path:
        return None
    with np.errstate(invalid="ignore"):
        Pe = member_euler_loads(s)[m.t_member]
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
    """The ``postcritical`` JSON document of a path (docs/json.md, ``postcritical``)."""
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
    doc = result_json("postcritical", s.name,
                          monitor=monitor_label(result.model, result.monitor),
                          path=path, events=events, termination=result.termination,
                          max_load_factor=float(max(p.load_factor for p in result.path)),
                          gravity_dead_load=bool(np.any(result.model.dead != 0)))
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
