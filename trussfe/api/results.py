# SPDX-License-Identifier: MIT
"""Result objects of the Python API.

Every analysis returns a :class:`Result`: numpy arrays with documented shapes, the node and
member ids that index their axes, the solver's own result object (``solution``) for anything
further, and :meth:`Result.to_dict`, the JSON document that ``trussfe COMMAND --json`` writes.

The same quantity has the same attribute name in every family (docs/python.md has the table):

=====================  =====================================================================
``displacement``       node translations, ``(node, dim)``, or ``(step, node, dim)`` along a
                       motion or a path
``reaction``           support reactions (forces), same layout, zero on free coordinates
``position``           node positions along a motion or path, ``(step, node, dim)``
``axial_force``        member axial force (N, tension positive): ``(member,)`` static,
                       ``(step, member)`` along a motion (at the middle of the member)
``section_forces``     ``(…, member, station, 6)``: N, Vy, Vz, T, My, Mz in member axes
``shapes``             mode shapes at the nodes, ``(mode, node, dim)``
``time``               ``(step,)``, s
=====================  =====================================================================

Every array a result's property returns is read-only (a view of the solver's array, or an
array computed on access): writing into it raises ``ValueError: assignment destination is
read-only`` instead of changing the result, its other arrays and :meth:`Result.to_dict`.
``np.array(r.axial_force)`` is a copy to change.  Dicts and lists a property returns are new
containers (their arrays read-only too, their events copies).  ``solution`` is the solver's
own object, as it is.
Each analysis module defines its results (:class:`~trussfe.api.linear.StaticResult`, …).
"""
from __future__ import annotations

import copy
import functools
from dataclasses import dataclass, is_dataclass
from typing import Any, ClassVar

import numpy as np

from ..io.output import plain
from ..model.structure import Structure


def read_only(value: Any) -> Any:
    """``value`` as a result property hands it out: an array as a read-only view, a dict or a
    list as a new one of read-only values, a mutable dataclass (an event) as a copy (a user's
    change cannot reach the solver's data)."""
    if isinstance(value, np.ndarray):
        view = value.view()
        view.flags.writeable = False
        return view
    if type(value) is dict:
        return {k: read_only(v) for k, v in value.items()}
    if type(value) is list:
        return [read_only(v) for v in value]
    if is_dataclass(value) and not isinstance(value, type) \
            and not type(value).__dataclass_params__.frozen:
        return copy.copy(value)             # e.g. a path event: a copy to change
    return value


def _read_only_property(prop: property) -> property:
    @functools.wraps(prop.fget)
    def get(self):
        return read_only(prop.fget(self))
    return property(get, doc=prop.__doc__)


@dataclass(frozen=True, eq=False)
class Result:
    """Base of every analysis result.

    Attributes
    ----------
    structure : Structure
        The analysed model.
    solution : object
        The solver's result (e.g. :class:`trussfe.fem.static.StaticResult`).
    """

    command: ClassVar[str] = ""
    structure: Structure
    solution: Any

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        # every property of a result hands out read-only arrays (module docstring)
        for name, attr in list(vars(cls).items()):
            if isinstance(attr, property) and attr.fget is not None and attr.fset is None:
                setattr(cls, name, _read_only_property(attr))

    @property
    def node_ids(self) -> tuple[str, ...]:
        """Node ids, in the order of every ``node`` axis."""
        return tuple(self.structure.node_ids)

    @property
    def member_ids(self) -> tuple[str, ...]:
        """Member ids, in the order of every ``member`` axis."""
        return tuple(self.structure.member_ids)

    @property
    def dim(self) -> int:
        """Spatial dimension, 2 or 3."""
        return int(self.structure.dim)

    def _document(self) -> dict:          # pragma: no cover - every subclass defines it
        raise NotImplementedError

    def to_dict(self) -> dict:
        """The JSON document of ``trussfe COMMAND --json`` (plain lists, numbers, strings;
        non-finite numbers as ``None``)."""
        return plain(self._document())

    def __repr__(self) -> str:
        return (f"<{type(self).__name__} of '{self.structure.name}': "
                f"{self.structure.n_nodes} nodes, {self.structure.n_members} members>")
