# SPDX-License-Identifier: MIT
"""The typed tables a model may carry beside its geometry: ``Structure.extensions``.

=================  ==============================================  ==========================
table              value                                           data module
=================  ==============================================  ==========================
active_members     tuple of :class:`~.active.ActiveMember`         :mod:`trussfe.model.active`
actuators          tuple of :class:`~.actuators.Actuator`          :mod:`trussfe.model.actuators`
failure            :class:`~.failure.FailureLaws`                  :mod:`trussfe.model.failure`
member_loads       tuple of :class:`~.member_loads.MemberLoad`     :mod:`trussfe.model.member_loads`
postcritical       :class:`~.postcritical.PostcriticalSettings`    :mod:`trussfe.model.postcritical`
load_cases         :class:`~.load_cases.LoadCases`                 :mod:`trussfe.model.load_cases`
springs            :class:`~.node_supports.Springs`                :mod:`trussfe.model.node_supports`
rotary_inertia     :class:`~.node_supports.RotaryInertia`          :mod:`trussfe.model.node_supports`
=================  ==============================================  ==========================

Members are referred to by index, so a variant of a model with other members
(:meth:`~trussfe.model.structure.Structure.subset_members`) renumbers them here.
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from types import MappingProxyType
from typing import Any

import numpy as np

from .active import ActiveMember
from .actuators import Actuator
from .failure import FailureLaws
from .load_cases import check_load_cases
from .member_loads import MemberLoad
from .node_supports import RotaryInertia, Springs
from .postcritical import PostcriticalSettings

#: Extension tables, in the order a model file lists them.
EXTENSION_TABLES = ("active_members", "actuators", "failure", "postcritical",
                    "member_loads", "load_cases", "springs", "rotary_inertia")


def _members(items, cls, table: str, m: int) -> tuple:
    out = tuple(items)
    for a in out:
        if not isinstance(a, cls):
            raise TypeError(f"extensions[{table!r}]: expected {cls.__name__} items, "
                            f"got {type(a).__name__}")
        if not 0 <= a.member < m:
            raise ValueError(f"extensions[{table!r}]: member index {a.member} is not one of "
                             f"the {m} members")
    return out


def freeze_extensions(tables: Mapping[str, Any], n_members: int,
                      node_shape: tuple[int, int] | None = None) -> Mapping[str, Any]:
    """Check the extension tables of a model of ``n_members`` members, as a read-only mapping.

    ``node_shape`` = (nodes, DOFs per node), when given, is the shape every per-node table
    (a load case's ``loads`` and ``prescribed``, the ``springs``) must have; a case's
    ``(nodes, dim)`` loads or prescribed values (no moments, no rotations) are widened to it,
    as :meth:`trussfe.model.structure.Structure.with_loads` widens loads.

    Lists become tuples; a ``None`` value drops the table; a ``postcritical`` dict becomes
    :class:`PostcriticalSettings`.

    Raises
    ------
    ValueError, TypeError
        An unknown table, a value of the wrong type, a member index out of range.
    """
    out: dict[str, Any] = {}
    for key, value in tables.items():
        if value is None:
            continue
        if key == "active_members":
            value = _members(value, ActiveMember, key, n_members)
        elif key == "actuators":
            value = _members(value, Actuator, key, n_members)
        elif key == "member_loads":
            value = _members(value, MemberLoad, key, n_members)
        elif key == "failure":
            if not isinstance(value, FailureLaws) or value.n_members != n_members:
                raise ValueError(f"extensions['failure']: expected FailureLaws of "
                                 f"{n_members} members")
        elif key == "postcritical":
            if isinstance(value, Mapping):
                value = PostcriticalSettings(**value)
            if not isinstance(value, PostcriticalSettings):
                raise TypeError("extensions['postcritical']: expected PostcriticalSettings")
        elif key == "load_cases":
            value = check_load_cases(value, n_members, node_shape)
        elif key in ("springs", "rotary_inertia"):
            cls = Springs if key == "springs" else RotaryInertia
            if not isinstance(value, cls):
                raise TypeError(f"extensions[{key!r}]: expected {cls.__name__}")
            if key == "springs" and node_shape is not None \
                    and value.stiffness.shape != tuple(node_shape):
                raise ValueError(f"extensions['springs']: stiffness has shape "
                                 f"{value.stiffness.shape}, expected {tuple(node_shape)}")
        else:
            raise ValueError(f"unknown extension table {key!r}; valid: "
                             f"{', '.join(EXTENSION_TABLES)}")
        out[key] = value
    return MappingProxyType(out)


def subset_extensions(tables: Mapping[str, Any], keep: np.ndarray) -> dict[str, Any]:
    """The extension tables of the members ``keep`` (indices, ascending), renumbered.

    Active members, actuators and member loads of members not kept are dropped.
    """
    new_index = {int(old): new for new, old in enumerate(keep)}
    out: dict[str, Any] = {}
    for key, value in tables.items():
        if key in ("active_members", "actuators", "member_loads"):
            value = tuple(replace(a, member=new_index[a.member]) for a in value
                          if a.member in new_index)
        elif key == "failure":
            value = value.subset(np.asarray(keep, dtype=np.int64))
        elif key == "load_cases":
            value = value.subset(np.asarray(keep, dtype=np.int64))
        out[key] = value
    return out
