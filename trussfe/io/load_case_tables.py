# SPDX-License-Identifier: MIT
"""Readers of ``[load_cases]``, ``[combinations]``, ``[springs]`` and the rotary inertia of
``[masses]`` (docs/model-format.md).

Each becomes the typed data of :mod:`trussfe.model.load_cases` or
:mod:`trussfe.model.node_supports`, or raises one :class:`~trussfe.errors.InputError`
naming the item.  The tables are read against the model built from the core tables (nodes,
members, supports), so a prescribed displacement can be checked against the supports and a
temperature load against the members' materials.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..errors import InputError
from ..model.load_cases import Combination, LoadCase, LoadCases
from ..model.node_supports import Springs
from ..model.structure import DOF_NAMES, Structure
from .extension_tables import parse_member_loads as _parse_model_member_loads
from .suggest import suggest as _suggest

#: Keys of a ``[load_cases.NAME]`` table.
CASE_KEYS = ("loads", "gravity", "prescribed", "temperature", "initial_strain",
             "length_error", "member_loads")


def _number(value: Any, item: str, *, nonneg: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(item, f"expected a number, got {value!r}")
    try:
        x = float(value)
    except OverflowError:
        raise InputError(item, f"number too large: {value!r}") from None
    if not math.isfinite(x):
        raise InputError(item, f"expected a finite number, got {value!r}")
    if nonneg and x < 0.0:
        raise InputError(item, f"must not be negative, got {value!r}")
    return x


def _node(structure: Structure, key: Any, item: str) -> int:
    try:
        return structure.node_index(str(key))
    except KeyError:
        raise InputError(item, f"node '{key}' is not defined"
                               f"{_suggest(str(key), structure.node_ids)}") from None


def _member(structure: Structure, key: Any, item: str) -> int:
    if not isinstance(key, str):
        raise InputError(item, f"expected a member id, got {key!r}")
    try:
        return structure.member_index(key)
    except KeyError:
        raise InputError(item, f"member '{key}' is not defined"
                               f"{_suggest(key, structure.member_ids)}") from None


def _dof_table(raw: Any, item: str, dim: int, *, nonneg: bool = False
               ) -> list[tuple[int, float]]:
    """``{ z = -0.005, ry = 1e-3 }`` as (DOF column, value) pairs."""
    names = DOF_NAMES[dim]
    if not isinstance(raw, dict) or not raw:
        raise InputError(item, "expected a table of DOFs and values, e.g. "
                               f"{{ {names[1]} = 0.001 }}")
    out = []
    for d, v in raw.items():
        if d not in names:
            raise InputError(f"{item}.{d}", f"unknown DOF '{d}'{_suggest(str(d), names)}")
        out.append((names.index(d), _number(v, f"{item}.{d}", nonneg=nonneg)))
    return out


# ---------------------------------------------------------------------------- springs
def parse_springs(raw: Any, structure: Structure) -> Springs:
    """Read ``[springs]``: ``NODE = { x = k, ..., rz = k }`` (N/m, N·m/rad).

    A spring on a supported DOF, a negative stiffness and a rotational spring at a node of a
    pin-jointed truss are refused; a zero stiffness is accepted (no spring).
    """
    if not isinstance(raw, dict):
        raise InputError("[springs]", "expected a table NODE = { x = k, ... }")
    k = np.zeros((structure.n_nodes, structure.ndof_node))
    for key, value in raw.items():
        item = f"springs.{key}"
        i = _node(structure, key, item)
        for col, stiffness in _dof_table(value, item, structure.dim):
            name = DOF_NAMES[structure.dim][col]
            if stiffness < 0.0:
                raise InputError(f"{item}.{name}", f"spring stiffness must not be negative, "
                                                   f"got {stiffness!r}")
            if structure.supports[i, col]:
                raise InputError(f"{item}.{name}", f"node '{key}' is fixed in {name} by "
                                 "[supports]; a spring there would carry nothing: remove one")
            k[i, col] = stiffness
    return Springs(k)


# ---------------------------------------------------------------------------- masses
def parse_mass_entry(value: Any, item: str, dim: int) -> tuple[float, np.ndarray | None]:
    """One ``[masses]`` entry: a number (kg) or ``{ mass = kg, inertia = [...] }``.

    Returns the mass and the rotary inertia about the global axes (kg·m², one value in 2-D,
    three in 3-D), or None when none is given.
    """
    if not isinstance(value, dict):
        return _number(value, item, nonneg=True), None
    for key in value:
        if key not in ("mass", "inertia"):
            raise InputError(f"{item}.{key}", f"unknown key '{key}'"
                                              f"{_suggest(key, ('mass', 'inertia'))}")
    mass = _number(value.get("mass", 0.0), f"{item}.mass", nonneg=True)
    if "inertia" not in value:
        return mass, None
    nrot = 1 if dim == 2 else 3
    raw = value["inertia"]
    if dim == 2 and not isinstance(raw, list):
        raw = [raw]
    if not isinstance(raw, list) or len(raw) != nrot:
        raise InputError(f"{item}.inertia", f"expected {nrot} number{'s' if nrot > 1 else ''}"
                         f" (kg·m² about the global {'z axis' if dim == 2 else 'x, y, z axes'})")
    return mass, np.array([_number(v, f"{item}.inertia[{j}]", nonneg=True)
                           for j, v in enumerate(raw)])


# ---------------------------------------------------------------------------- cases
def parse_member_loads(raw: Any, structure: Structure, item: str) -> tuple:
    """The ``member_loads`` of one case: loads along members, read as the model's
    ``member_loads`` array is (:func:`trussfe.io.extension_tables.parse_member_loads`)."""
    return _parse_model_member_loads(raw, structure, None, item)


def _member_values(raw: Any, structure: Structure, item: str, value_key: str
                   ) -> np.ndarray:
    """``[ { member = "M1", <value_key> = v }, { members = ["M2", "M3"], ... } ]`` as a
    per-member array (values of entries naming one member add up)."""
    if not isinstance(raw, list) or not raw:
        raise InputError(item, f"expected a list of {{ members = [...], {value_key} = ... }}")
    out = np.zeros(structure.n_members)
    for j, entry in enumerate(raw):
        where = f"{item}[{j}]"
        if not isinstance(entry, dict):
            raise InputError(where, f"expected {{ members = [...], {value_key} = ... }}")
        allowed = ("member", "members", value_key)
        for key in entry:
            if key not in allowed:
                raise InputError(f"{where}.{key}", f"unknown key '{key}'"
                                                   f"{_suggest(key, allowed)}")
        if ("member" in entry) == ("members" in entry):
            raise InputError(where, "give either member = ID or members = [IDs]")
        if value_key not in entry:
            raise InputError(where, f"missing '{value_key}'")
        value = _number(entry[value_key], f"{where}.{value_key}")
        ids = [entry["member"]] if "member" in entry else entry["members"]
        if not isinstance(ids, list) or not ids:
            raise InputError(f"{where}.members", "expected a list of member ids")
        idx = [_member(structure, mid, f"{where}.member{'s' if 'members' in entry else ''}")
               for mid in ids]
        if len(set(idx)) < len(idx):
            # entries add up, so a member named twice in one list would take the value twice:
            # more likely a slip than a meaning
            twice = next(ids[k] for k in range(len(idx)) if idx[k] in idx[:k])
            raise InputError(f"{where}.members", f"member '{twice}' is named twice; name it "
                             "once (or give a second entry to add to it)")
        np.add.at(out, idx, value)
    return out


def parse_case(name: str, raw: Any, structure: Structure) -> LoadCase:
    """Read one ``[load_cases.NAME]`` table."""
    item = f"load_cases.{name}"
    s = structure
    if not isinstance(raw, dict):
        raise InputError(item, "expected a table of loads, gravity, prescribed, temperature, "
                               "initial_strain, length_error")
    for key in raw:
        if key not in CASE_KEYS:
            raise InputError(f"{item}.{key}", f"unknown key '{key}'{_suggest(key, CASE_KEYS)}")
    dim, ndof = s.dim, s.ndof_node
    loads = np.zeros((s.n_nodes, ndof))
    if "loads" in raw:
        table = raw["loads"]
        if not isinstance(table, dict):
            raise InputError(f"{item}.loads", "expected a table NODE = [forces]")
        for key, value in table.items():
            where = f"{item}.loads.{key}"
            i = _node(s, key, where)
            if not isinstance(value, list) or len(value) not in (dim, ndof):
                raise InputError(where, f"expected a list of {dim} or {ndof} numbers")
            f = np.array([_number(v, f"{where}[{j}]") for j, v in enumerate(value)])
            loads[i, :f.size] += f
    gravity = raw.get("gravity", False)
    if not isinstance(gravity, bool):
        raise InputError(f"{item}.gravity", f"expected true or false, got {gravity!r}")
    if gravity and not np.any(s.gravity):
        raise InputError(f"{item}.gravity", "self-weight needs the gravity vector: give "
                                            "[model] gravity = [...]")
    prescribed = None
    if "prescribed" in raw:
        table = raw["prescribed"]
        if not isinstance(table, dict) or not table:
            raise InputError(f"{item}.prescribed", "expected a table NODE = { DOF = value }")
        prescribed = np.zeros((s.n_nodes, ndof))
        for key, value in table.items():
            where = f"{item}.prescribed.{key}"
            i = _node(s, key, where)
            for col, u in _dof_table(value, where, dim):
                dof = DOF_NAMES[dim][col]
                if not s.supports[i, col]:
                    raise InputError(f"{where}.{dof}", f"a displacement is prescribed on a "
                                     f"free DOF: node '{key}' is not supported in {dof}; add "
                                     "it to [supports] (a settlement moves a support)")
                prescribed[i, col] = u
    delta_T = initial = error = None
    if "temperature" in raw:
        delta_T = _member_values(raw["temperature"], s, f"{item}.temperature", "delta_T")
        alpha = s.member_properties.thermal_expansion
        bad = np.flatnonzero((delta_T != 0.0) & ~np.isfinite(alpha))
        if bad.size:
            i = int(bad[0])
            raise InputError(f"{item}.temperature", f"member '{s.member_ids[i]}' is heated but "
                             f"its material '{s.materials[i].name}' has no thermal_expansion: "
                             f"give thermal_expansion (1/K) in [materials."
                             f"{s.materials[i].name}]")
    if "initial_strain" in raw:
        initial = _member_values(raw["initial_strain"], s, f"{item}.initial_strain", "strain")
    if "length_error" in raw:
        error = _member_values(raw["length_error"], s, f"{item}.length_error", "delta")
    member_loads = (parse_member_loads(raw["member_loads"], s, f"{item}.member_loads")
                    if "member_loads" in raw else ())
    return LoadCase(name=name, loads=loads, gravity=gravity, prescribed=prescribed,
                    delta_T=delta_T, initial_strain=initial, length_error=error,
                    member_loads=member_loads)


def parse_combinations(raw: Any, cases: tuple[LoadCase, ...]) -> tuple[Combination, ...]:
    """Read ``[combinations]``: ``NAME = { case = factor, ... }``."""
    if not isinstance(raw, dict):
        raise InputError("[combinations]", "expected a table NAME = { case = factor, ... }")
    names = [c.name for c in cases]
    out = []
    for name, table in raw.items():
        item = f"combinations.{name}"
        if not isinstance(table, dict) or not table:
            raise InputError(item, "expected a table { case = factor, ... }")
        for case, factor in table.items():
            if case not in names:
                raise InputError(f"{item}.{case}", f"load case '{case}' is not defined in "
                                                   f"[load_cases]{_suggest(case, names)}")
            _number(factor, f"{item}.{case}")
        out.append(Combination(str(name), tuple((str(c), float(f)) for c, f in table.items())))
    return tuple(out)


def parse_load_cases(data: dict, structure: Structure) -> LoadCases | None:
    """Read ``[load_cases]`` and ``[combinations]`` of a parsed model file; None when the
    file has neither (the model's ``[loads]`` is then its one case)."""
    if "load_cases" not in data:
        if "combinations" in data:
            raise InputError("[combinations]", "combinations need [load_cases.NAME] tables")
        return None
    raw = data["load_cases"]
    if not isinstance(raw, dict) or not raw:
        raise InputError("[load_cases]", "expected one table per case, e.g. "
                                         "[load_cases.dead]")
    if data.get("loads"):
        raise InputError("[loads]", "a model with [load_cases] gives its nodal loads in a "
                                    "case (loads = { NODE = [...] } in [load_cases.NAME])")
    if "member_loads" in data:
        raise InputError("member_loads", "a model with [load_cases] gives its member loads "
                                         "in a case (member_loads = [...] in "
                                         "[load_cases.NAME])")
    cases = tuple(parse_case(str(k), v, structure) for k, v in raw.items())
    combos = parse_combinations(data["combinations"], cases) if "combinations" in data else ()
    return LoadCases(cases=cases, combinations=combos)
