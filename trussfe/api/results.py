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

Arrays are the solver's own or computed from them on access: copy one before changing it.
Each analysis module defines its results (:class:`~trussfe.api.linear.StaticResult`, …).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from ..io.output import plain
from ..model.structure import Structure


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
