# SPDX-License-Identifier: MIT
"""Load cases and their combinations: ``Structure.extensions["load_cases"]``.

A load case is one independent set of actions on the structure — nodal loads, self-weight,
displacements prescribed on supported DOFs (support settlement), a uniform temperature change
of members, initial strains and length errors of members (lack of fit) — each analysed on its
own.  A combination is a factored sum of cases; since the analysis is linear, its response is
the same factored sum of the cases' responses.

A model without ``[load_cases]`` has one implicit case, :data:`DEFAULT_CASE`, made of its
``[loads]`` and, under ``[model] gravity``, its self-weight (:func:`model_load_cases`), so
that every model is analysed the same way.

Members and nodes are referred to by index, as everywhere in the model layer; the per-member
arrays follow the members of a variant (:meth:`LoadCases.subset`).
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from .sealed import sealed

#: Name of the one case of a model without ``[load_cases]``.
DEFAULT_CASE = "default"


def _frozen(value: Any, dtype, shape: tuple[int, ...] | None, name: str) -> np.ndarray | None:
    if value is None:
        return None
    a = np.array(value, dtype=dtype)
    if shape is not None and a.shape != shape:
        raise ValueError(f"{name}: expected shape {shape}, got {a.shape}")
    return sealed(a)


@dataclass(frozen=True, eq=False)
class LoadCase:
    """One load case; immutable.

    Attributes
    ----------
    name : str
        Case name (the key of ``[load_cases.NAME]``).
    loads : ndarray, shape (n, ndof)
        Nodal forces and moments, N and N·m, global axes (as ``Structure.loads``).
    gravity : bool
        Self-weight of the members and the nodal masses under the model's gravity vector.
    prescribed : ndarray, shape (n, ndof), optional
        Displacements (m) and rotations (rad) imposed on supported DOFs, global axes; zero on
        the other supported DOFs (``None``: none).
    delta_T : ndarray, shape (m,), optional
        Uniform temperature change of each member, K (``None``: none).
    initial_strain : ndarray, shape (m,), optional
        Stress-free axial strain of each member (``None``: none).
    length_error : ndarray, shape (m,), optional
        Stress-free length minus geometric length of each member, m: a member too long by δ,
        or an actuator commanded δ off the length the geometry gives it (``None``: none).
    member_loads : tuple of MemberLoad
        Loads along members in this case (:mod:`trussfe.model.member_loads`); empty when
        the case has none.
    """

    name: str
    loads: np.ndarray
    gravity: bool = False
    prescribed: np.ndarray | None = None
    delta_T: np.ndarray | None = None
    initial_strain: np.ndarray | None = None
    length_error: np.ndarray | None = None
    member_loads: tuple = field(default_factory=tuple)

    def __post_init__(self) -> None:
        put = object.__setattr__
        loads = _frozen(self.loads, float, None, f"load case {self.name}: loads")
        if loads.ndim != 2:
            raise ValueError(f"load case {self.name}: loads must be (nodes, DOFs)")
        put(self, "name", str(self.name))
        put(self, "loads", loads)
        put(self, "gravity", bool(self.gravity))
        put(self, "prescribed", _frozen(self.prescribed, float, loads.shape,
                                        f"load case {self.name}: prescribed"))
        for key in ("delta_T", "initial_strain", "length_error"):
            put(self, key, _frozen(getattr(self, key), float, None,
                                   f"load case {self.name}: {key}"))
        put(self, "member_loads", tuple(self.member_loads))

    def __setstate__(self, state: dict) -> None:
        # unpickled arrays come back writable: freeze them again (pickle, copy.deepcopy)
        self.__dict__.update(state)
        self.__post_init__()

    @property
    def has_imposed_strain(self) -> bool:
        """True when the case strains members without load (temperature, lack of fit)."""
        return any(a is not None and np.any(a) for a in
                   (self.delta_T, self.initial_strain, self.length_error))

    @property
    def has_prescribed(self) -> bool:
        """True when the case moves a support."""
        return self.prescribed is not None and bool(np.any(self.prescribed))

    def subset(self, keep: np.ndarray) -> "LoadCase":
        """The case on the members ``keep`` (indices, ascending) of a variant: per-member
        values follow their members; member loads (records with a ``member`` index) on
        removed members are dropped, the others renumbered."""
        pick = lambda a: None if a is None else a[keep]
        new_index = {int(old): new for new, old in enumerate(keep)}
        member_loads = tuple(replace(ml, member=new_index[ml.member])
                             for ml in self.member_loads if ml.member in new_index)
        return replace(self, delta_T=pick(self.delta_T),
                       initial_strain=pick(self.initial_strain),
                       length_error=pick(self.length_error), member_loads=member_loads)

    def __repr__(self) -> str:
        parts = [key for key, present in (
            ("loads", bool(np.any(self.loads))), ("gravity", self.gravity),
            ("prescribed", self.has_prescribed),
            ("temperature", self.delta_T is not None and bool(np.any(self.delta_T))),
            ("initial_strain", self.initial_strain is not None
             and bool(np.any(self.initial_strain))),
            ("length_error", self.length_error is not None
             and bool(np.any(self.length_error))),
            ("member_loads", bool(self.member_loads))) if present]
        return f"LoadCase({self.name!r}: {', '.join(parts) or 'nothing'})"


@dataclass(frozen=True)
class Combination:
    """A factored sum of load cases.

    Attributes
    ----------
    name : str
    factors : tuple of (case name, factor)
        In the order given.
    """

    name: str
    factors: tuple[tuple[str, float], ...]

    def __post_init__(self) -> None:
        object.__setattr__(self, "factors",
                           tuple((str(c), float(f)) for c, f in self.factors))


@dataclass(frozen=True, eq=False)
class LoadCases:
    """The load cases and combinations of a model.

    Attributes
    ----------
    cases : tuple of LoadCase
        In the order of the model file.
    combinations : tuple of Combination
    """

    cases: tuple[LoadCase, ...]
    combinations: tuple[Combination, ...] = ()

    def __post_init__(self) -> None:
        cases = tuple(self.cases)
        combos = tuple(c if isinstance(c, Combination) else Combination(**c)
                       for c in self.combinations)
        for c in cases:
            if not isinstance(c, LoadCase):
                raise TypeError(f"load cases: expected LoadCase items, got {type(c).__name__}")
        names = [c.name for c in cases]
        if len(set(names)) != len(names):
            raise ValueError("load cases: two cases have the same name")
        if not cases:
            raise ValueError("load cases: at least one case is needed")
        for combo in combos:
            for case, _ in combo.factors:
                if case not in names:
                    raise ValueError(f"combination {combo.name}: no load case {case!r}")
        object.__setattr__(self, "cases", cases)
        object.__setattr__(self, "combinations", combos)

    @property
    def case_names(self) -> tuple[str, ...]:
        """Names of the cases, in order."""
        return tuple(c.name for c in self.cases)

    @property
    def combination_names(self) -> tuple[str, ...]:
        """Names of the combinations, in order."""
        return tuple(c.name for c in self.combinations)

    def case(self, name: str) -> LoadCase:
        """The case called ``name`` (KeyError if absent)."""
        for c in self.cases:
            if c.name == name:
                return c
        raise KeyError(name)

    def combination(self, name: str) -> Combination:
        """The combination called ``name`` (KeyError if absent)."""
        for c in self.combinations:
            if c.name == name:
                return c
        raise KeyError(name)

    def factor_matrix(self, combinations: Sequence[Combination] | None = None) -> np.ndarray:
        """Factors of the cases in the combinations, shape (combination, case)."""
        combos = self.combinations if combinations is None else combinations
        index = {n: i for i, n in enumerate(self.case_names)}
        out = np.zeros((len(combos), len(self.cases)))
        for k, combo in enumerate(combos):
            for case, factor in combo.factors:
                out[k, index[case]] += factor
        return out

    def subset(self, keep: np.ndarray) -> "LoadCases":
        """The cases on the members ``keep`` (indices) of a variant."""
        return replace(self, cases=tuple(c.subset(keep) for c in self.cases))


def model_load_cases(structure: Any) -> LoadCases:
    """The load cases of a structure: its ``load_cases`` table, or the one implicit case
    :data:`DEFAULT_CASE` of its ``loads``, ``member_loads`` and self-weight (a model without
    ``[load_cases]``: the loads a plain static analysis applies)."""
    table = structure.extensions.get("load_cases")
    if table is not None:
        return table
    return LoadCases(cases=(LoadCase(DEFAULT_CASE, structure.loads, gravity=True,
                                     member_loads=tuple(structure.extensions.get(
                                         "member_loads", ()))),))


def check_load_cases(value: Any, n_members: int,
                     node_shape: tuple[int, int] | None = None) -> LoadCases:
    """``value`` as :class:`LoadCases` of a model of ``n_members`` members and, when given,
    ``node_shape`` = (nodes, DOFs per node) (for
    :func:`trussfe.model.extensions.freeze_extensions`): a case's loads and prescribed values
    of shape (nodes, d) with d < DOFs per node are widened with zeros (forces without
    moments, translations without rotations); any other shape is refused."""
    if isinstance(value, Mapping):
        value = LoadCases(**value)
    if not isinstance(value, LoadCases):
        raise TypeError("extensions['load_cases']: expected LoadCases")
    if node_shape is not None:
        value = replace(value, cases=tuple(_node_tables(c, tuple(node_shape))
                                                       for c in value.cases))
    for c in value.cases:
        for key in ("delta_T", "initial_strain", "length_error"):
            a = getattr(c, key)
            if a is not None and a.shape != (n_members,):
                raise ValueError(f"extensions['load_cases']: case {c.name}: {key} has shape "
                                 f"{a.shape}, expected ({n_members},)")
    return value


def _node_tables(case: LoadCase, shape: tuple[int, int]) -> LoadCase:
    """``case`` with its ``loads`` and ``prescribed`` of ``shape`` (see
    :func:`check_load_cases`)."""
    changed = {}
    for key in ("loads", "prescribed"):
        a = getattr(case, key)
        if a is None or a.shape == shape:
            continue
        if a.ndim != 2 or a.shape[0] != shape[0] or a.shape[1] > shape[1]:
            raise ValueError(f"extensions['load_cases']: case {case.name}: {key} has shape "
                             f"{a.shape}, expected {shape}")
        wide = np.zeros(shape)
        wide[:, : a.shape[1]] = a
        changed[key] = wide
    return replace(case, **changed) if changed else case
