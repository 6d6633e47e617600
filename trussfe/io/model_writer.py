# SPDX-License-Identifier: MIT
"""Writer of trussfe model files (TOML, docs/model-format.md): the inverse of
:func:`trussfe.io.model_file.read_model`.

``read_model(write_model(s, path))`` gives back the same nodes, members, sections, materials,
supports, loads, masses and gravity (floats are written with ``repr``, which round-trips
exactly).  The geometry may go to a meshio mesh file instead (``mesh="chain.vtu"``), for models
too large for a readable TOML table.
"""
from __future__ import annotations

import json
import logging
import math
import re
from pathlib import Path

import numpy as np

from ..errors import OutputError
from ..model.sections import Material, Section
from ..model.structure import DOF_NAMES, Structure
from .output import atomic_path

log = logging.getLogger(__name__)

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")
#: Characters a TOML comment may not hold (control characters but tab).
_COMMENT_CONTROL = re.compile(r"[\x00-\x08\x0a-\x1f\x7f]")


def _comment(line: str) -> str:
    """``line`` as the text of a TOML comment: its control characters written as ``\\xNN``."""
    return _COMMENT_CONTROL.sub(lambda c: "\\x" + format(ord(c[0]), "02x"), line)


def toml_key(key: str) -> str:
    """A TOML key: bare when it may be, else a quoted basic string.

    Examples
    --------
    >>> toml_key("M6"), toml_key("b1.N4")
    ('M6', '"b1.N4"')
    """
    key = str(key)
    return key if _BARE_KEY.match(key) else _string(key)


def _string(text: str) -> str:
    # JSON escapes (\\", \\\\, \\n, \\uXXXX) are valid in TOML basic strings; JSON leaves
    # DEL (U+007F) as it is, which a TOML string must escape.
    return json.dumps(str(text), ensure_ascii=False).replace("\x7f", "\\u007f")


def toml_value(value) -> str:
    """A TOML value for a number, bool, string or (nested) list.

    Examples
    --------
    >>> toml_value([0.1, -2, True, "a"])
    '[0.1, -2, true, "a"]'
    """
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        x = float(value)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{toml_key(k)} = {toml_value(v)}" for k, v in value.items()) + " }"
    raise TypeError(f"cannot write {type(value).__name__} to TOML")


def _unique_names(objs: list, kind: str) -> dict[int, str]:
    """Name of each distinct section/material object (by value); clashing names get suffixes."""
    names: dict = {}
    used: set[str] = set()
    out: dict[int, str] = {}
    by_id: dict[int, str] = {}
    for i, o in enumerate(objs):
        if id(o) in by_id:          # catalogue models share one object: skip hashing it
            out[i] = by_id[id(o)]
            continue
        if o in names:
            out[i] = by_id[id(o)] = names[o]
            continue
        base = o.name or kind
        name, k = base, 2
        while name in used:
            name, k = f"{base}_{k}", k + 1
        used.add(name)
        names[o] = name
        out[i] = by_id[id(o)] = name
    return out


def _section_table(sec: Section) -> dict:
    if sec.is_tube:
        out = {"outer_diameter": sec.outer_diameter, "inner_diameter": sec.inner_diameter}
        keys = ("shear_area_y", "shear_area_z")
    else:
        out = {"area": sec.area}
        keys = ("Iy", "Iz", "J", "c", "shear_area_y", "shear_area_z")
    for key in keys:
        v = getattr(sec, key)
        if not math.isnan(v):
            out[key] = v
    return out


def _material_table(mat: Material) -> dict:
    out = {"E": mat.E, "G": mat.G, "density": mat.density}
    if not math.isnan(mat.yield_strength):
        out["yield_strength"] = mat.yield_strength
    if not math.isnan(mat.thermal_expansion):
        out["thermal_expansion"] = mat.thermal_expansion
    return out


def model_toml(structure: Structure, *, mesh: str | None = None, header: str = "") -> str:
    """The TOML text of a model file for ``structure``.

    Parameters
    ----------
    structure : Structure
    mesh : str, optional
        When given, ``[model] mesh = mesh`` replaces the ``[nodes]`` and ``[members]`` tables
        (the mesh file must be written separately, see :func:`write_model`); node ids become
        the point indices.
    header : str
        Comment lines written at the top (without the ``#``).
    """
    s = structure
    lines = [f"# {_comment(ln)}" if ln else "#" for ln in header.splitlines()]
    if lines:
        lines.append("")
    node_ids = s.node_ids if mesh is None else [str(i) for i in range(s.n_nodes)]
    member_ids = s.member_ids if mesh is None else [str(i) for i in range(s.n_members)]
    # a top-level array: before the first table, as TOML requires
    member_loads = s.extensions.get("member_loads")
    if member_loads:
        lines.append("member_loads = [")
        lines += [f"  {toml_value(_member_load_entry(ml, member_ids))},"
                  for ml in member_loads]
        lines += ["]", ""]
    lines += ["[model]", f"name = {_string(s.name)}", f"dimension = {s.dim}"]
    if np.any(s.gravity != 0):
        lines.append(f"gravity = {toml_value(list(s.gravity))}")
    if mesh is not None:
        lines.append(f"mesh = {_string(mesh)}")
    mat_names = _unique_names(s.materials, "material")
    sec_names = _unique_names(s.sections, "section")
    lines.append("")
    seen = set()
    for i, mat in enumerate(s.materials):
        if mat_names[i] not in seen:
            seen.add(mat_names[i])
            lines += [f"[materials.{toml_key(mat_names[i])}]"]
            lines += [f"{k} = {toml_value(v)}" for k, v in _material_table(mat).items()]
            lines.append("")
    seen = set()
    for i, sec in enumerate(s.sections):
        if sec_names[i] not in seen:
            seen.add(sec_names[i])
            lines += [f"[sections.{toml_key(sec_names[i])}]"]
            lines += [f"{k} = {toml_value(v)}" for k, v in _section_table(sec).items()]
            lines.append("")

    def member_props(i: int) -> dict:
        d = {"section": sec_names[i], "material": mat_names[i]}
        if s.is_beam[i]:
            d["type"] = "beam"
            rel = [e for e, r in zip(("start", "end"), s.releases[i]) if r]
            axes = s.bending_axis_releases[i].copy()
            tors = s.torsion_releases[i].copy()
            if s.dim == 2:      # one bending axis (z), no twist: "my", "torsion" mean nothing
                axes[:, 0] = False
                tors[:] = False
            if tors.any() or axes.any():   # per-end form
                d["releases"] = {e: [w for w, r in (("bending", s.releases[i, k]),
                                                    ("my", axes[k, 0]), ("mz", axes[k, 1]),
                                                    ("torsion", tors[k])) if r]
                                 for k, e in enumerate(("start", "end"))
                                 if s.releases[i, k] or tors[k] or axes[k].any()}
            elif rel:
                d["releases"] = rel
        if s.orientation is not None and np.all(np.isfinite(s.orientation[i])):
            d["orientation"] = list(s.orientation[i])
        return d

    if mesh is None:
        lines.append("[nodes]")
        lines += [f"{toml_key(n)} = {toml_value(list(x))}" for n, x in zip(node_ids, s.coords)]
        lines += ["", "[members]"]
        for i, mid in enumerate(s.member_ids):
            d = {"nodes": [node_ids[a] for a in s.connectivity[i]], **member_props(i)}
            lines.append(f"{toml_key(mid)} = {toml_value(d)}")
        lines.append("")
    else:
        groups = _mesh_groups(s)
        for gname, idx in groups.items():
            lines += [f"[groups.{toml_key(gname)}]"]
            lines += [f"{k} = {toml_value(v)}" for k, v in member_props(int(idx[0])).items()]
            lines.append("")
    names = DOF_NAMES[s.dim]
    sup = np.flatnonzero(s.supports.any(axis=1))
    if sup.size:
        lines.append("[supports]")
        lines += [f"{toml_key(node_ids[i])} = "
                  f"{toml_value([names[d] for d in np.flatnonzero(s.supports[i])])}" for i in sup]
        lines.append("")
    loaded = np.flatnonzero(np.any(s.loads != 0, axis=1))
    if loaded.size:
        lines.append("[loads]")
        for i in loaded:
            f = s.loads[i] if np.any(s.loads[i, s.dim:] != 0) else s.loads[i, : s.dim]
            lines.append(f"{toml_key(node_ids[i])} = {toml_value(list(f))}")
        lines.append("")
    rotary = s.extensions.get("rotary_inertia")
    inertia = np.zeros((s.n_nodes, 0)) if rotary is None else rotary.inertia
    massive = np.flatnonzero((s.masses != 0) | np.any(inertia != 0, axis=1))
    if massive.size:
        lines.append("[masses]")
        for i in massive:
            value = (s.masses[i] if not np.any(inertia[i] != 0) else
                     {"mass": s.masses[i], "inertia": list(inertia[i])})
            lines.append(f"{toml_key(node_ids[i])} = {toml_value(value)}")
        lines.append("")
    lines += _load_case_lines(s, node_ids, member_ids)
    lines += _extension_lines(s, node_ids, member_ids)
    written = {"load_cases", "springs", "rotary_inertia", "member_loads", *_EXTENSION_WRITERS}
    others = [k for k in s.extensions if k not in written]
    if others:
        log.warning("extension tables %s are not written", ", ".join(others))
    return "\n".join(lines)


def _dof_values(row: np.ndarray, dim: int) -> dict:
    """``{DOF name: value}`` of the non-zero entries of a node's DOF row."""
    names = DOF_NAMES[dim]
    return {names[d]: row[d] for d in np.flatnonzero(row != 0)}


def _member_entries(values: np.ndarray | None, member_ids, key: str) -> list[dict]:
    if values is None:
        return []
    return [{"member": member_ids[i], key: values[i]} for i in np.flatnonzero(values != 0)]


def _member_load_entry(ml, member_ids) -> dict:
    """One member load (:class:`~trussfe.model.member_loads.MemberLoad`) as its model-file
    table."""
    d = {"member": member_ids[ml.member], "kind": ml.kind}
    if ml.kind == "uniform":
        d["q"] = list(ml.q_start)
    elif ml.kind == "trapezoidal":
        d["q_start"], d["q_end"] = list(ml.q_start), list(ml.q_end)
    if ml.span != (0.0, 1.0):
        d["span"] = list(ml.span)
    if ml.kind == "point":
        d["at"] = ml.at
        if ml.force:                # a couple alone has no F
            d["F"] = list(ml.force)
        if ml.moment:
            d["M"] = list(ml.moment)
    if ml.axes != "global":
        d["axes"] = ml.axes
    return d


def _load_case_lines(s: Structure, node_ids, member_ids) -> list[str]:
    """``[springs]``, ``[load_cases.NAME]`` and ``[combinations]`` of a model."""
    lines: list[str] = []
    springs = s.extensions.get("springs")
    if springs is not None:     # even with no spring: the model reads back as it was
        lines.append("[springs]")
        for i in np.flatnonzero(np.any(springs.stiffness != 0, axis=1)):
            lines.append(f"{toml_key(node_ids[i])} = "
                         f"{toml_value(_dof_values(springs.stiffness[i], s.dim))}")
        lines.append("")
    table = s.extensions.get("load_cases")
    if table is None:
        return lines
    for case in table.cases:
        lines.append(f"[load_cases.{toml_key(case.name)}]")
        if case.gravity:
            lines.append("gravity = true")
        loaded = np.flatnonzero(np.any(case.loads != 0, axis=1))
        if loaded.size:
            loads = {node_ids[i]: list(case.loads[i] if np.any(case.loads[i, s.dim:] != 0)
                                       else case.loads[i, :s.dim]) for i in loaded}
            lines.append(f"loads = {toml_value(loads)}")
        if case.prescribed is not None and np.any(case.prescribed):
            moved = {node_ids[i]: _dof_values(case.prescribed[i], s.dim)
                     for i in np.flatnonzero(np.any(case.prescribed != 0, axis=1))}
            lines.append(f"prescribed = {toml_value(moved)}")
        for key, values, value_key in (("temperature", case.delta_T, "delta_T"),
                                       ("initial_strain", case.initial_strain, "strain"),
                                       ("length_error", case.length_error, "delta")):
            entries = _member_entries(values, member_ids, value_key)
            if entries:
                lines.append(f"{key} = {toml_value(entries)}")
        if case.member_loads:
            lines.append("member_loads = "
                         + toml_value([_member_load_entry(ml, member_ids)
                                       for ml in case.member_loads]))
        lines.append("")
    if table.combinations:
        lines.append("[combinations]")
        for combo in table.combinations:
            lines.append(f"{toml_key(combo.name)} = {toml_value(dict(combo.factors))}")
        lines.append("")
    return lines


def _table_lines(header: str, values: dict) -> list[str]:
    return [header, *(f"{toml_key(k)} = {toml_value(v)}" for k, v in values.items()), ""]


def _finite(d: dict) -> dict:
    """``d`` without its ``nan`` values (the keys a table leaves to their default)."""
    return {k: v for k, v in d.items() if not (isinstance(v, float) and math.isnan(v))}


def _active_member_lines(s: Structure, node_ids, member_ids) -> list[str]:
    lines: list[str] = []
    for a in s.extensions["active_members"]:
        lines += _table_lines(f"[active_members.{toml_key(member_ids[a.member])}]", _finite({
            "base_mass": a.base_mass, "base_length": a.base_length, "base_cg": a.base_cg,
            "base_inertia": a.base_inertia, "tube_length": a.tube_length,
            "min_length": a.min_length, "max_length": a.max_length}))
    return lines


def _degrees(angle: float) -> float:
    """The angle in degrees that the reader's ``math.radians`` turns back into ``angle``."""
    d = math.degrees(angle)
    for candidate in (d, math.nextafter(d, math.inf), math.nextafter(d, -math.inf)):
        if math.radians(candidate) == angle:
            return candidate
    return d


def _actuator_lines(s: Structure, node_ids, member_ids) -> list[str]:
    lines: list[str] = []
    for a in s.extensions["actuators"]:
        d = {"leadscrew_gain": a.leadscrew_gain, "mean_diameter": a.mean_diameter,
             "thread": a.thread}
        if a.thread != "square":
            d["thread_angle"] = _degrees(a.thread_angle)
        d.update({"friction": a.friction, "gearhead_gain": a.gearhead_gain,
                  "armature_inertia": a.armature_inertia, "resistance": a.resistance,
                  "torque_constant": a.torque_constant,
                  "back_emf_constant": a.back_emf_constant, "max_speed": a.max_speed,
                  "max_voltage": a.max_voltage,
                  "require_self_locking": bool(a.require_self_locking),
                  "convention": a.convention})
        lines += _table_lines(f"[actuators.{toml_key(member_ids[a.member])}]", _finite(d))
    return lines


def _strength(force: float, area: float, material_strength: float) -> float | None:
    """The yield strength that gives the yield force ``force`` on ``area`` as the reader
    computes it (``None``: the material's own)."""
    if area * material_strength == force:
        return None
    f = force / area
    for candidate in (f, math.nextafter(f, math.inf), math.nextafter(f, -math.inf)):
        if area * candidate == force:
            return candidate
    return f


def _failure_lines(s: Structure, node_ids, member_ids) -> list[str]:
    from ..model.failure import BUCKLING, YIELD

    laws = s.extensions["failure"]
    lines = ["[failure]", ""]
    for i in np.flatnonzero(laws.any):
        d: dict = {}
        if laws.buckling[i]:
            d["buckling"] = BUCKLING[int(laws.buckling[i])]
            d["critical_load"] = float(laws.critical_load[i])
            if d["buckling"] == "softening":
                d["residual"] = float(laws.residual[i])
                d["softening_strain"] = float(laws.softening_strain[i])
        if laws.yield_mode[i]:
            d["yield"] = YIELD[int(laws.yield_mode[i])]
            f = _strength(float(laws.yield_force[i]), float(s.area[i]),
                          float(s.yield_strength[i]))
            if f is not None:
                d["yield_strength"] = f
        if np.isfinite(laws.fracture_strain[i]):
            d["fracture_strain"] = float(laws.fracture_strain[i])
        lines += _table_lines(f"[failure.members.{toml_key(member_ids[i])}]", d)
    return lines


def _postcritical_lines(s: Structure, node_ids, member_ids) -> list[str]:
    options = s.extensions["postcritical"].options()
    if "monitor" in options:                    # NODE:AXIS, by the ids written
        node, _, axis = options["monitor"].rpartition(":")
        options["monitor"] = f"{node_ids[s.node_index(node)]}:{axis}"
    return _table_lines("[postcritical]", options)


#: Writers of the extension tables (besides load cases, springs, rotary inertia and member
#: loads), in the reader's order.
_EXTENSION_WRITERS = {"active_members": _active_member_lines, "actuators": _actuator_lines,
                      "failure": _failure_lines, "postcritical": _postcritical_lines}


def _extension_lines(s: Structure, node_ids, member_ids) -> list[str]:
    lines: list[str] = []
    for key, writer in _EXTENSION_WRITERS.items():
        if s.extensions.get(key) is not None:
            lines += writer(s, node_ids, member_ids)
    return lines


def _mesh_groups(s: Structure) -> dict[str, np.ndarray]:
    """Member indices per distinct (section, material, type, releases) combination."""
    def codes(objs: list) -> np.ndarray:
        # equal objects share a code; identity first, as catalogue models share one object
        seen: dict = {}
        by_id: dict[int, int] = {}
        out = np.empty(len(objs), dtype=np.int64)
        for i, o in enumerate(objs):
            c = by_id.get(id(o))
            if c is None:
                c = by_id[id(o)] = seen.setdefault(o, len(seen))
            out[i] = c
        return out

    sec, mat = codes(s.sections), codes(s.materials)
    key = ((sec * (mat.max(initial=0) + 1) + mat) * 2 + s.is_beam) * 4 \
        + s.releases[:, 0] * 2 + s.releases[:, 1]
    key = key * 4 + s.torsion_releases[:, 0] * 2 + s.torsion_releases[:, 1]
    key = key * 16 + s.bending_axis_releases.reshape(-1, 4) @ np.array([8, 4, 2, 1])
    # a group carries one orientation vector: members with other vectors form other groups
    orient = np.where(np.isfinite(s.orientation), s.orientation, np.inf)
    _, orient_code = np.unique(orient.reshape(s.n_members, -1), axis=0, return_inverse=True)
    key = key * (int(orient_code.max(initial=0)) + 1) + orient_code.reshape(-1)
    uniq, first, inverse = np.unique(key, return_index=True, return_inverse=True)
    if len(uniq) == 1:
        return {"default": np.arange(s.n_members)}
    # Several groups, in order of first appearance, named by the integer tag the mesh
    # carries for them (see write_model).
    order = np.argsort(first)
    return {str(j + 1): np.flatnonzero(inverse.reshape(-1) == g) for j, g in enumerate(order)}


def write_model(structure: Structure, path: str | Path, *, mesh: str | None = None,
                header: str = "") -> Path:
    """Write ``structure`` as a model file (atomically).

    Parameters
    ----------
    structure : Structure
    path : path
        TOML file to write.
    mesh : str, optional
        File name (relative to ``path``'s folder) of a meshio mesh to hold the geometry, e.g.
        ``"chain.vtu"``: line cells in member order; when members differ in section, material
        or type, a cell-data tag ``gmsh:physical`` numbers the groups ``[groups.1]``, ...
    header : str
        Comment written at the top of the file.

    Returns
    -------
    Path
        ``path``.
    """
    path = Path(path)
    try:
        data = (model_toml(structure, mesh=mesh, header=header) + "\n").encode("utf-8")
    except UnicodeEncodeError as exc:       # a lone surrogate: no TOML text holds it
        raise OutputError(str(path), f"cannot write: text {exc.object[exc.start:exc.end]!r} "
                                     f"of the model is not valid Unicode") from None
    target = None if mesh is None else path.parent / mesh
    for p in (path, target):
        if p is not None and p.is_dir():
            raise OutputError(str(p), "cannot write: Is a directory")
    if target is None:
        with atomic_path(path) as tmp:
            tmp.write_bytes(data)
        return path
    import meshio

    pts = np.zeros((structure.n_nodes, 3))
    pts[:, : structure.dim] = structure.coords
    groups = _mesh_groups(structure)
    cell_data = {}
    if len(groups) > 1:
        # An integer tag per cell, read back as the group name (the reader's
        # "gmsh:physical" convention; VTU cannot hold named cell sets).
        tags = np.zeros(structure.n_members, dtype=np.int64)
        for g, idx in groups.items():
            tags[idx] = int(g)
        cell_data = {"gmsh:physical": [tags]}
    m = meshio.Mesh(pts, [("line", structure.connectivity)], cell_data=cell_data)
    # Both temporary files are written before either is renamed into place, so that a
    # failure leaves neither file (nor a model file naming a mesh that is not there).
    with atomic_path(target) as mesh_tmp:
        try:
            meshio.write(mesh_tmp, m)       # format from the suffix, which mesh_tmp keeps
        except Exception as exc:  # noqa: BLE001 - meshio raises many types
            message = str(exc).replace(str(mesh_tmp), str(target)) or type(exc).__name__
            raise OutputError(str(target), f"cannot write the mesh: {message}") from None
        with atomic_path(path) as tmp:
            tmp.write_bytes(data)
    return path
