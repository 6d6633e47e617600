# SPDX-License-Identifier: MIT
"""Reader of trussfe model files (TOML, docs/model-format.md).

Every check on user input lives here (or in the extension-table readers of
:mod:`trussfe.io.extension_tables`), so that any input either becomes a
:class:`~trussfe.model.Structure` or raises one :class:`~trussfe.errors.InputError` naming the
file and the item.  Reading a model imports the model layer only, none of the analyses.
"""
from __future__ import annotations

import contextvars
import logging
import math
from itertools import chain
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from ..budget import check_input_file
from ..errors import InputError, TrussfeError, one_line
from .regular_file import read_regular_file
from . import toml_text
from .extension_tables import TABLES as EXTENSION_TABLES
from .load_case_tables import parse_load_cases, parse_mass_entry, parse_springs
from ..model.geometry import member_lengths
from ..model.ids import IdIndex, IdRange, id_index
from .suggest import suggest as _suggest
from ..model.sections import Material, Section
from ..mechanics.releases import parse_end_release
from ..model.structure import DOF_NAMES, Structure

log = logging.getLogger(__name__)

#: The file being read, as "path: " for warnings (errors get it from TrussfeError.with_file).
_source: contextvars.ContextVar[str] = contextvars.ContextVar("trussfe_model_source",
                                                              default="")

#: Top-level tables of the core format.
CORE_TABLES = ("model", "materials", "sections", "nodes", "members", "supports", "loads",
               "masses", "groups", "springs", "load_cases", "combinations")

def _check_keys(table: dict, allowed, item: str) -> None:
    for key in table:
        if key not in allowed:
            raise InputError(f"{item}.{key}" if item else key,
                             f"unknown key '{key}'{_suggest(key, allowed)}")


def _number(value: Any, item: str, *, positive: bool = False, nonneg: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(item, f"expected a number, got {value!r}")
    try:
        x = float(value)
    except OverflowError:           # a TOML integer beyond the float range
        raise InputError(item, f"number too large: {value!r}") from None
    if not math.isfinite(x):
        raise InputError(item, f"expected a finite number, got {value!r}")
    if positive and x <= 0.0:
        raise InputError(item, f"must be positive, got {value!r}")
    if nonneg and x < 0.0:
        raise InputError(item, f"must not be negative, got {value!r}")
    return x


def _vector(value: Any, item: str, sizes: tuple[int, ...]) -> np.ndarray:
    if not isinstance(value, list):
        raise InputError(item, f"expected a list of {' or '.join(map(str, sizes))} numbers")
    if len(value) not in sizes:
        raise InputError(item, f"expected {' or '.join(map(str, sizes))} numbers, "
                               f"got {len(value)}")
    return np.array([_number(v, f"{item}[{i}]") for i, v in enumerate(value)], dtype=float)


def _table(data: dict, name: str, *, required: bool = False) -> dict:
    t = data.get(name, {})
    if required and name not in data:
        raise InputError(f"[{name}]", "table is missing")
    if not isinstance(t, dict):
        raise InputError(name, f"expected a table [{name}]")
    return t


# ---------------------------------------------------------------------------- pieces
def parse_material(name: str, raw: Any) -> Material:
    """Read one ``[materials.NAME]`` table."""
    item = f"materials.{name}"
    if not isinstance(raw, dict):
        raise InputError(item, "expected a table with E, density (and optional G, "
                               "yield_strength, thermal_expansion)")
    _check_keys(raw, ("E", "G", "density", "yield_strength", "thermal_expansion"), item)
    if "E" not in raw:
        raise InputError(item, "missing E (Young's modulus, Pa)")
    E = _number(raw["E"], f"{item}.E", positive=True)
    G = _number(raw["G"], f"{item}.G", positive=True) if "G" in raw else E / 2.6
    rho = _number(raw.get("density", 0.0), f"{item}.density", nonneg=True)
    fy = (_number(raw["yield_strength"], f"{item}.yield_strength", positive=True)
          if "yield_strength" in raw else math.nan)
    alpha = (_number(raw["thermal_expansion"], f"{item}.thermal_expansion")
             if "thermal_expansion" in raw else math.nan)
    return Material(name=name, E=E, G=G, density=rho, yield_strength=fy,
                    thermal_expansion=alpha)


def parse_section(name: str, raw: Any) -> Section:
    """Read one ``[sections.NAME]`` table (tube diameters or explicit properties)."""
    item = f"sections.{name}"
    tube_keys = ("outer_diameter", "inner_diameter")
    expl_keys = ("area", "Iy", "Iz", "J", "c")
    if not isinstance(raw, dict):
        raise InputError(item, "expected a table with outer_diameter/inner_diameter or area")
    _check_keys(raw, tube_keys + expl_keys + SHEAR_KEYS, item)
    section = _section_properties(item, raw, tube_keys, expl_keys)
    return _shear_deformation(item, raw, section)


#: Keys of a section that make it shear-deformable (a Timoshenko beam).
SHEAR_KEYS = ("shear_area_y", "shear_area_z", "beam_theory", "shear_coefficient")
#: Beam theories a section may name.
BEAM_THEORIES = ("euler-bernoulli", "timoshenko")


def _shear_deformation(item: str, raw: dict, section: Section) -> Section:
    """The section with its shear areas: given (``shear_area_y``, ``shear_area_z``, m²), or
    ``shear_coefficient`` κ times the area under ``beam_theory = "timoshenko"``."""
    theory = raw.get("beam_theory")
    if theory is not None and theory not in BEAM_THEORIES:
        raise InputError(f"{item}.beam_theory", f"unknown beam theory {theory!r}; use "
                                                "euler-bernoulli or timoshenko")
    given = [k for k in ("shear_area_y", "shear_area_z") if k in raw]
    if theory == "euler-bernoulli" and (given or "shear_coefficient" in raw):
        raise InputError(f"{item}.beam_theory", "an euler-bernoulli section has no shear "
                                                "area: remove the shear keys or use timoshenko")
    if "shear_coefficient" in raw and theory != "timoshenko":
        raise InputError(f"{item}.shear_coefficient", 'needs beam_theory = "timoshenko"')
    areas = {}
    for k in given:
        v = raw[k]
        if isinstance(v, (int, float)) and not isinstance(v, bool) and v <= 0:
            raise InputError(f"{item}.{k}", f"a Timoshenko section needs a positive shear "
                                            f"area, got {v!r}")
        areas[k] = _number(v, f"{item}.{k}", positive=True)
    if theory == "timoshenko" and len(areas) < 2:
        if "shear_coefficient" not in raw:
            if not areas:
                raise InputError(f"{item}.beam_theory", "a timoshenko section needs "
                                 "shear_area_y and shear_area_z (m²) or shear_coefficient")
        else:
            kappa = _number(raw["shear_coefficient"], f"{item}.shear_coefficient",
                            positive=True)
            for k in ("shear_area_y", "shear_area_z"):
                areas.setdefault(k, kappa * section.area)
    if not areas:
        return section
    return replace(section, **areas)


def _section_properties(item: str, raw: dict, tube_keys, expl_keys) -> Section:
    name = item.split(".", 1)[1]
    if "outer_diameter" in raw:
        extra = [k for k in raw if k in expl_keys and k != "c"]
        if extra:
            raise InputError(f"{item}.{extra[0]}",
                             "give either tube diameters or explicit properties, not both")
        D = _number(raw["outer_diameter"], f"{item}.outer_diameter", positive=True)
        d = _number(raw.get("inner_diameter", 0.0), f"{item}.inner_diameter", nonneg=True)
        if d >= D:
            raise InputError(f"{item}.inner_diameter",
                             f"inner diameter {d} must be smaller than outer diameter {D}")
        if "c" in raw:
            c = _number(raw["c"], f"{item}.c", positive=True)
            if abs(c - D / 2.0) > 1e-12 * D:
                raise InputError(f"{item}.c", f"a tube's outer-fibre distance is "
                                 f"outer_diameter / 2 = {D / 2.0!r} m, computed; got {c!r}: "
                                 "remove c, or give explicit properties (area, Iy, ...)")
        return Section.tube(name, D, d)
    if "inner_diameter" in raw:
        raise InputError(f"{item}.inner_diameter", "inner_diameter needs outer_diameter")
    if "area" not in raw:
        raise InputError(item, "missing area (or outer_diameter for a tube)")
    A = _number(raw["area"], f"{item}.area", positive=True)
    Iy = _number(raw["Iy"], f"{item}.Iy", positive=True) if "Iy" in raw else math.nan
    Iz = _number(raw["Iz"], f"{item}.Iz", positive=True) if "Iz" in raw else Iy
    J = _number(raw["J"], f"{item}.J", positive=True) if "J" in raw else Iy + Iz
    c = _number(raw["c"], f"{item}.c", positive=True) if "c" in raw else math.nan
    return Section(name=name, area=A, Iy=Iy, Iz=Iz, J=J, c=c)


def _parse_member(mid: str, raw: Any, node_index: dict, sections: dict, materials: dict,
                  dim: int = 3):
    item = f"members.{mid}"
    keys = ("nodes", "section", "material", "type", "releases", "orientation")
    if not isinstance(raw, dict):
        raise InputError(item, "expected an inline table { nodes = [..], section = .., "
                               "material = .. }")
    _check_keys(raw, keys, item)
    for k in ("nodes", "section", "material"):
        if k not in raw:
            raise InputError(item, f"missing '{k}'")
    ends = raw["nodes"]
    if not isinstance(ends, list) or len(ends) != 2:
        raise InputError(f"{item}.nodes", "expected two node ids")
    idx = []
    for e in ends:
        if str(e) not in node_index:
            raise InputError(f"{item}.nodes", f"node '{e}' is not defined in [nodes]"
                                              f"{_suggest(str(e), node_index)}")
        idx.append(node_index[str(e)])
    if idx[0] == idx[1]:
        raise InputError(f"{item}.nodes", f"both ends are node '{ends[0]}' (zero length)")
    sec, mat = str(raw["section"]), str(raw["material"])
    if sec not in sections:
        raise InputError(f"{item}.section", f"section '{sec}' is not defined in [sections]"
                                            f"{_suggest(sec, sections) if sections else ''}")
    if mat not in materials:
        raise InputError(f"{item}.material", f"material '{mat}' is not defined in [materials]"
                                             f"{_suggest(mat, materials) if materials else ''}")
    mtype = raw.get("type", "bar")
    if mtype not in ("bar", "beam"):
        raise InputError(f"{item}.type", f"unknown member type '{mtype}'{_suggest(mtype, ('bar', 'beam'))}")
    rel = raw.get("releases", [])
    if isinstance(rel, dict):
        # per-end form: { start = ["bending", "torsion"] or ["my", "mz", "t"], end = [...] }
        _check_keys(rel, ("start", "end"), f"{item}.releases")
        axes, tors = [[False, False], [False, False]], [False, False]
        for e, key in enumerate(("start", "end")):
            if key in rel:
                try:
                    my, mz, tors[e] = parse_end_release(rel[key], dim)
                except ValueError as exc:
                    raise InputError(f"{item}.releases.{key}", str(exc)) from None
                axes[e] = [my, mz]
        # both bending moments released: the ``releases`` flag; one alone: per axis
        bend = [mz if dim == 2 else (my and mz) for my, mz in axes]
        one = [[a and not b for a in ax] for ax, b in zip(axes, bend)]
        flags = (tuple(bend), tuple(tors), one)
    elif not isinstance(rel, list) or any(r not in ("start", "end") for r in rel):
        raise InputError(f"{item}.releases", "expected a list of \"start\" and/or \"end\", "
                                             "or a table { start = [...], end = [...] } of "
                                             "\"bending\" and/or \"torsion\"")
    else:
        flags = (("start" in rel, "end" in rel), (False, False),
                 [[False, False], [False, False]])
    if rel and mtype != "beam":
        raise InputError(f"{item}.releases", "releases apply to beams only (a bar is pinned "
                                             "at both ends already)")
    orient = (_vector(raw["orientation"], f"{item}.orientation", (3,))
              if "orientation" in raw else np.full(3, np.nan))
    if "orientation" in raw and not np.any(orient != 0.0):
        raise InputError(f"{item}.orientation", "must be a non-zero vector in the member's "
                                                "local x-y plane")
    return idx, sections[sec], materials[mat], mtype == "beam", flags, orient


def _parse_dofs(raw: Any, item: str, dim: int) -> list[int]:
    names = DOF_NAMES[dim]
    if isinstance(raw, str):
        raw = [raw]
    if not isinstance(raw, list):
        raise InputError(item, f"expected a list of DOF names from {', '.join(names)}")
    out = []
    for d in raw:
        if d not in names:
            raise InputError(item, f"unknown DOF '{d}'{_suggest(str(d), names)}")
        out.append(names.index(d))
    return out


# ---------------------------------------------------------------------------- model
def parse_model(data: dict, base_dir: Path | str = ".", source: str = "") -> Structure:
    """Build a :class:`Structure` from the parsed TOML ``data``.

    Parameters
    ----------
    data : dict
        The model file as parsed (:func:`trussfe.io.toml_text.loads`).
    base_dir : path
        Directory against which a ``[model] mesh`` path is resolved.
    source : str
        File name for error messages.

    Raises
    ------
    InputError
        Naming the table and item at fault.
    """
    base_dir = Path(base_dir)
    token = _source.set(f"{source}: " if source else "")
    try:
        return _parse_model(data, base_dir, source)
    finally:
        _source.reset(token)


#: Core tables keyed by ids or names.
_KEYED_TABLES = ("materials", "sections", "nodes", "members", "supports", "loads", "masses",
                 "groups", "springs")


def _string_keys(data: dict) -> dict:
    """``data`` with the keys of its id tables as strings, each id once.

    A file's keys are strings already; a dict built in Python may hold ``1`` and ``"1"``,
    which would be two nodes (or members, or loads on one node) of the same id.
    """
    out = data
    for name in _KEYED_TABLES:
        t = data.get(name)
        if not isinstance(t, dict) or set(map(type, t)) <= {str}:
            continue
        keyed: dict = {}
        for k, v in t.items():
            if str(k) in keyed:
                raise InputError(f"{name}.{k}", f"'{k}' is given twice in [{name}] (an id is "
                                                "a string: 1 and \"1\" are the same id)")
            keyed[str(k)] = v
        out = {**out, name: keyed}
    return out


def _parse_model(data: dict, base_dir: Path, source: str) -> Structure:
    allowed = CORE_TABLES + tuple(EXTENSION_TABLES)
    for key in data:
        if key not in allowed:
            raise InputError(f"[{key}]", f"unknown table '{key}'{_suggest(key, allowed)}")
    data = _string_keys(data)

    model = _table(data, "model", required=True)
    _check_keys(model, ("name", "dimension", "gravity", "mesh"), "model")
    dim = model.get("dimension", 3)
    if not isinstance(dim, int) or isinstance(dim, bool) or dim not in (2, 3):
        raise InputError("model.dimension", f"must be 2 or 3, got {dim!r}")
    name = model.get("name", Path(source).stem if source else "model")
    if not isinstance(name, str):
        raise InputError("model.name", f"expected a string, got {name!r}")
    if "mesh" in model and not isinstance(model["mesh"], str):
        raise InputError("model.mesh", f"expected a file name, got {model['mesh']!r}")
    gravity = (_vector(model["gravity"], "model.gravity", (dim,)) if "gravity" in model
               else np.zeros(dim))

    materials = {k: parse_material(k, v) for k, v in _table(data, "materials").items()}
    sections = {k: parse_section(k, v) for k, v in _table(data, "sections").items()}

    if "mesh" in model:
        for key in ("nodes", "members"):
            if key in data:
                raise InputError(f"[{key}]", f"the geometry comes from [model] mesh = "
                                 f"'{model['mesh']}': remove [{key}] (or the mesh)")
        (node_ids, coords, member_ids, conn, secs, mats, beam, rel, orient,
         group_code, axis_rel) = _mesh_geometry(str(model["mesh"]), base_dir, dim, data, sections,
                                      materials)
    else:
        if _table(data, "groups"):
            raise InputError("[groups]", "groups give the properties of a mesh's cell sets, "
                             "and this model has no [model] mesh: name the section and "
                             "material in each member of [members]")
        nodes = _table(data, "nodes", required=True)
        if not nodes:
            raise InputError("[nodes]", "no nodes defined")
        node_ids = [str(k) for k in nodes]
        coords = np.array([_vector(v, f"nodes.{k}", (dim,)) if isinstance(v, list)
                           and len(v) == dim else _bad_coords(k, v, dim)
                           for k, v in nodes.items()])
        node_index = {k: i for i, k in enumerate(node_ids)}
        members = _table(data, "members", required=True)
        if not members:
            raise InputError("[members]", "no members defined")
        parsed = [_parse_member(str(k), v, node_index, sections, materials, dim)
                  for k, v in members.items()]
        member_ids = [str(k) for k in members]
        conn = np.array([p[0] for p in parsed], dtype=np.int64)
        secs = [p[1] for p in parsed]
        mats = [p[2] for p in parsed]
        beam = np.array([p[3] for p in parsed], dtype=bool)
        rel = np.array([p[4][:2] for p in parsed], dtype=bool).reshape(-1, 2, 2)
        axis_rel = np.array([p[4][2] for p in parsed], dtype=bool).reshape(-1, 2, 2)
        orient = np.array([p[5] for p in parsed]).reshape(-1, 3)
        group_code = None

    n = len(node_ids)
    node_index = id_index(node_ids)
    _check_geometry(coords, conn, member_ids, node_ids)

    ndof = 3 if dim == 2 else 6
    supports = np.zeros((n, ndof), dtype=bool)
    for k, v in _table(data, "supports").items():
        i = _node_ref(k, node_index, "supports")
        supports[i, _parse_dofs(v, f"supports.{k}", dim)] = True
    loads = np.zeros((n, ndof))
    load_table = _table(data, "loads")
    if not _loads_fast(load_table, node_index, loads, dim):
        for k, v in load_table.items():
            i = _node_ref(k, node_index, "loads")
            f = _vector(v, f"loads.{k}", (dim, ndof))
            loads[i, : f.size] += f
    masses = np.zeros(n)
    rotary = None
    for k, v in _table(data, "masses").items():
        i = _node_ref(k, node_index, "masses")
        masses[i], inertia = parse_mass_entry(v, f"masses.{k}", dim)
        if inertia is not None:
            if rotary is None:
                rotary = np.zeros((n, inertia.size))
            rotary[i] = inertia

    for a in (coords, conn, supports, loads, masses, beam, rel, orient, axis_rel):
        a.flags.writeable = False           # the reader's own arrays: the model need not copy
    s = Structure(name=name, dim=dim, node_ids=node_ids, coords=coords, member_ids=member_ids,
                  connectivity=conn, sections=secs, materials=mats, is_beam=beam,
                  releases=rel[:, 0], torsion_releases=rel[:, 1],
                  bending_axis_releases=axis_rel,
                  supports=supports, loads=loads, masses=masses, gravity=gravity,
                  orientation=orient, source=source, member_groups=group_code)
    if dim == 3 and np.isfinite(orient).any():
        from ..mechanics.geometry import local_axes
        local_axes(s)                       # an orientation along its member: InputError
    # the node tables that refer to the supports, and the load cases (read against the model
    # of the core tables: a settlement must sit on a support, a heated member needs α)
    nodal = {}
    if "springs" in data:
        nodal["springs"] = parse_springs(data["springs"], s)
    if rotary is not None and np.any(rotary):
        from ..model.node_supports import RotaryInertia
        nodal["rotary_inertia"] = RotaryInertia(rotary)
    cases = parse_load_cases(data, s)
    if cases is not None:
        nodal["load_cases"] = cases
    if nodal:
        s = s.with_extensions(**nodal)
    # each table is read against the model holding the ones before it (actuators need the
    # active members)
    for key, reader in EXTENSION_TABLES.items():
        if key in data:
            s = s.with_extensions(**{key: reader(data[key], s, base_dir)})
    return s


def _loads_fast(table: dict, node_index: dict, loads: np.ndarray, dim: int) -> bool:
    """Add a ``[loads]`` table of plain force vectors in one vectorised step.

    Handles the common large case — every entry a list of ``dim`` (or all of ``ndof``) finite
    numbers on a defined node — and returns False for anything else, which the per-entry
    reader then checks and reports item by item (so errors are the same).
    """
    if len(table) < 64:                     # small tables: the per-entry path is as fast
        return False
    values = list(table.values())
    width = len(values[0]) if isinstance(values[0], list) else -1
    # the type checks by set(map(...)), which run in C: 0.01 s instead of 0.05 s for the
    # 32,761 loads of a 180 x 180 grid
    if (width not in (dim, loads.shape[1]) or set(map(type, values)) != {list}
            or set(map(len, values)) != {width}):
        return False
    flat = list(chain.from_iterable(values))
    if not set(map(type, flat)) <= {int, float}:         # bool, str, tables: not plain numbers
        return False
    try:
        arr = np.array(flat, dtype=float).reshape(len(values), width)
        rows = _node_rows(list(table), node_index)
    except (KeyError, OverflowError):
        return False
    if not np.all(np.isfinite(arr)):
        return False
    np.add.at(loads[:, :width], rows, arr)
    return True


def _node_rows(keys: list, node_index) -> np.ndarray:
    """The rows of the nodes named by ``keys``; KeyError when one is not a node (nodes
    numbered 0 … n − 1, a mesh model's :class:`~trussfe.model.ids.IdIndex`, in one
    vectorised pass)."""
    if isinstance(node_index, IdIndex):
        return node_index.positions(keys)
    return np.array([node_index[str(k)] for k in keys], dtype=np.int64)


def _bad_coords(k, v, dim):
    if isinstance(v, list) and len(v) in (2, 3) and len(v) != dim:
        raise InputError(f"nodes.{k}", f"has {len(v)} coordinates but [model] dimension = {dim}")
    raise InputError(f"nodes.{k}", f"expected a list of {dim} coordinates, got {v!r}")


def _node_ref(key: str, node_index: dict, table: str) -> int:
    if str(key) not in node_index:
        raise InputError(f"{table}.{key}", f"node '{key}' is not defined"
                                           f"{_suggest(str(key), node_index)}")
    return node_index[str(key)]


def _check_geometry(coords, conn, member_ids, node_ids) -> None:
    """Zero-length and duplicate members (vectorised)."""
    with np.errstate(over="ignore", invalid="ignore"):
        length = member_lengths(coords, conn)
        scale = max(float(np.ptp(coords, axis=0).max()) if len(coords) > 1 else 1.0, 1e-300)
    if not (np.all(np.isfinite(length)) and math.isfinite(scale)):
        i = int(np.flatnonzero(~np.isfinite(length))[0]) if not np.all(
            np.isfinite(length)) else 0
        raise InputError(f"members.{member_ids[i]}", "coordinates too large: the member "
                                                     "length overflows (use SI units, m)")
    bad = np.flatnonzero(length <= 1e-12 * scale)
    if bad.size:
        i = bad[0]
        a, b = conn[i]
        raise InputError(f"members.{member_ids[i]}",
                         f"has zero length (nodes '{node_ids[a]}' and '{node_ids[b]}' coincide)")
    # one integer per unordered node pair: a 1-D unique is much faster than unique(axis=0)
    n = len(node_ids)
    flat = np.minimum(conn[:, 0], conn[:, 1]) * n + np.maximum(conn[:, 0], conn[:, 1])
    # a plain sort (no index or count arrays); the stable one finds the runs of a mesh's
    # numbering: 4 ms instead of 76 ms for the 1.3 million bars of a 10⁶-DOF grid
    ordered = np.sort(flat, kind="stable")
    repeated = ordered[1:][ordered[1:] == ordered[:-1]]
    if repeated.size:
        dup = repeated.min()                # the same pair unique() would name first
        same = np.flatnonzero(flat == dup)
        raise InputError(f"members.{member_ids[same[1]]}",
                         f"duplicates member '{member_ids[same[0]]}' (same two nodes)")
    _warn_coincident(coords, node_ids, scale)


def _warn_coincident(coords: np.ndarray, node_ids, scale: float) -> None:
    """Warn, in one line, about nodes at the same place that no member joins.

    Two nodes at one point are a common modelling slip (a joint typed twice, each half
    carrying some members): the structure then falls apart there.  A member between them is
    refused as zero-length before this check, so the pairs found here are unjoined.  Exact
    positions are compared after rounding to 1e-9 of the model size (one sort, vectorised).
    """
    if len(coords) < 2:
        return
    unit = 1e9 / scale
    if not math.isfinite(unit):
        return
    # positions from the lower corner in 1e-9 of the model size (below 1e9: no overflow)
    q = ((coords - coords.min(axis=0)) * unit).astype(np.int64)
    # one integer key per node (a wrapping hash of its coordinates): a 1-D sort finds equal
    # keys; only then are nodes ordered and neighbours compared exactly
    key = q[:, 0] * np.int64(0x9E3779B97F4A7C15 - (1 << 64))
    for j in range(1, q.shape[1]):
        key = (key ^ q[:, j]) * np.int64(0x100000001B3)
    ks = np.sort(key)
    if not np.any(ks[1:] == ks[:-1]):
        return
    order = np.argsort(key, kind="stable")
    ks = key[order]
    cand = np.flatnonzero(ks[1:] == ks[:-1])
    if not cand.size:
        return
    same = cand[np.all(q[order[cand]] == q[order[cand + 1]], axis=1)]
    if not same.size:
        return
    k = int(same[0])
    a, b = sorted((int(order[k]), int(order[k + 1])))
    more = int(same.size) - 1
    where = ", ".join(f"{x:.6g}" for x in coords[a])
    log.warning("warning: %s", one_line(
        f"{_source.get()}nodes '{node_ids[a]}' and '{node_ids[b]}' coincide at ({where})"
        + (f", and {more} more pair(s) of nodes" if more else "")
        + "; no member joins them, so the structure is not connected there — merge them "
          "into one node if they are meant to be one joint"))


def _mesh_geometry(mesh_name, base_dir, dim, data, sections, materials):
    """Nodes and members from a meshio-readable line mesh (``[model] mesh``)."""
    path = (base_dir / mesh_name)
    if not path.exists():
        raise InputError("model.mesh", f"mesh file '{path}' not found")
    try:
        check_input_file(str(path), "mesh file")
    except InputError as err:
        raise InputError("model.mesh", err.message.replace("is ", f"'{path}' is ", 1)) from None
    mesh = _read_mesh(path)
    pts = np.asarray(mesh.points, dtype=float)
    if pts.ndim != 2 or pts.shape[0] == 0:
        raise InputError("model.mesh", "mesh has no points")
    if dim == 2 and pts.shape[1] == 3:
        if np.any(np.abs(pts[:, 2]) > 0):
            raise InputError("model.mesh", "mesh has non-zero z coordinates but [model] "
                                           "dimension = 2")
    if pts.shape[1] < dim:
        pts = np.hstack([pts, np.zeros((pts.shape[0], dim - pts.shape[1]))])
    coords = pts[:, :dim].copy()
    blocks = [(i, cb) for i, cb in enumerate(mesh.cells) if cb.type == "line"]
    if not blocks:
        raise InputError("model.mesh", "mesh has no line cells to use as members")
    conn = np.vstack([cb.data for _, cb in blocks]).astype(np.int64)
    m = conn.shape[0]
    if not np.all(np.isfinite(coords)):
        raise InputError("model.mesh", "mesh has non-finite point coordinates")
    if conn.size and (conn.min() < 0 or conn.max() >= coords.shape[0]):
        raise InputError("model.mesh", "a line cell refers to a point the mesh does not have")
    # Group of each line cell as an integer code into `names` (cell sets first, then gmsh
    # physical tags); integer codes keep this vectorised for meshes of millions of cells.
    names = ["default"]
    code = np.zeros(m, dtype=np.int64)
    offsets = np.cumsum([0] + [len(cb.data) for _, cb in blocks])
    for set_name, per_block in (mesh.cell_sets or {}).items():
        names.append(str(set_name))
        for (bi, _), off in zip(blocks, offsets):
            if bi < len(per_block) and per_block[bi] is not None and len(per_block[bi]):
                code[off + np.asarray(per_block[bi], dtype=np.int64)] = len(names) - 1
    phys = mesh.cell_data.get("gmsh:physical")
    if phys is not None:
        for (bi, _), off, nxt in zip(blocks, offsets[:-1], offsets[1:]):
            tags = np.asarray(phys[bi]).astype(np.int64)
            uniq, inv = np.unique(tags, return_inverse=True)
            first = len(names)
            names += [str(t) for t in uniq]
            unset = code[off:nxt] == 0
            code[off:nxt][unset] = first + inv.reshape(-1)[unset]
    groups = _table(data, "groups")
    if not groups:
        if len(sections) == 1 and len(materials) == 1:
            groups = {"default": {"section": next(iter(sections)),
                                  "material": next(iter(materials))}}
        else:
            raise InputError("[groups]", "a mesh model needs [groups.NAME] = { section, "
                                         "material } for its cell sets (or 'default')")
    for gname in groups:                    # names[0] is "default"
        if gname not in names:
            raise InputError(f"groups.{gname}", f"the mesh has no cell set (or Gmsh physical "
                             f"tag) '{gname}'{_suggest(str(gname), names)}")
    used = np.unique(code)
    sec_of, mat_of = {}, {}
    beam_of = np.zeros(len(names), dtype=bool)
    rel_of = np.zeros((len(names), 2, 2), dtype=bool)
    axis_of = np.zeros((len(names), 2, 2), dtype=bool)
    orient_of = np.full((len(names), 3), np.nan)
    for c in used:
        gname = names[c]
        g = groups.get(gname, groups.get("default"))
        if g is None:
            raise InputError("[groups]", f"cell set '{gname}' has no entry and there is no "
                                         "'default' group")
        if not isinstance(g, dict):
            raise InputError(f"groups.{gname}", "expected a table { section, material }")
        raw = dict(g)
        raw["nodes"] = ["0", "1"]
        _, sec_of[c], mat_of[c], beam_of[c], flags, orient_of[c] = _parse_member(
            f"groups.{gname}", raw, {"0": 0, "1": 1}, sections, materials, dim)
        rel_of[c], axis_of[c] = flags[:2], flags[2]
    # per-member lists by one object-array gather (no Python loop over millions of cells)
    sec_obj = np.empty(len(names), dtype=object)
    mat_obj = np.empty(len(names), dtype=object)
    for c in used:
        sec_obj[c], mat_obj[c] = sec_of[c], mat_of[c]
    # mesh items are named by their index: ids made on demand, not a string per item
    node_ids = IdRange(coords.shape[0])
    member_ids = IdRange(m)
    return (node_ids, coords, member_ids, conn, tuple(sec_obj[code].tolist()),
            tuple(mat_obj[code].tolist()), beam_of[code], rel_of[code], orient_of[code], code,
            axis_of[code])


def _read_mesh(path: Path):
    """``meshio.read`` without its console output.

    When no reader accepts a file, ``meshio.read`` prints the reader's complaint on stdout and
    an "Error:" line on stderr, then calls ``sys.exit(1)``.  The readers of the formats the
    suffix allows are therefore called directly, and every failure becomes one InputError.
    """
    import meshio

    try:
        from meshio._helpers import _filetypes_from_path, reader_map
    except ImportError:                                  # pragma: no cover - other meshio
        readers = None
    else:
        readers = reader_map
    try:
        if readers is None:                              # pragma: no cover
            return meshio.read(path)
        formats = _filetypes_from_path(path)
        last = None
        for fmt in formats:
            if fmt not in readers:
                continue
            try:
                return readers[fmt](str(path))
            except Exception as exc:   # readers raise many types; the message is what matters
                last = exc
        what = f" ({str(last) or type(last).__name__})" if last else ""
        raise InputError("model.mesh", f"cannot read '{path}' as {' or '.join(formats)}{what}")
    except InputError:
        raise
    except (Exception, SystemExit) as exc:
        raise InputError("model.mesh", f"cannot read '{path}': {exc or type(exc).__name__}"
                         ) from None


def read_model(path: str | Path) -> Structure:
    """Read a model file.

    Parameters
    ----------
    path : path
        TOML model file (docs/model-format.md).

    Returns
    -------
    Structure

    Raises
    ------
    InputError
        One line naming the file and the item at fault.
    """
    path = Path(path)
    # a folder, device or named pipe is refused before it is opened (a pipe would block), and
    # what is read is what was checked (read_regular_file)
    try:
        text = read_regular_file(path, "model file").decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(str(path), f"cannot read the model file: {exc}") from None
    try:
        data = toml_text.loads(text)
    except toml_text.TOMLDecodeError as exc:
        raise InputError(str(path), f"malformed TOML: {exc}") from None
    except RecursionError:
        raise InputError(str(path), "arrays or tables nest too deeply") from None
    try:
        return parse_model(data, base_dir=path.parent, source=str(path))
    except TrussfeError as err:
        raise err.with_file(str(path)) from None
    except RecursionError:
        raise InputError(str(path), "model nests too deeply") from None
