# SPDX-License-Identifier: MIT
"""Readers of the extension tables of a model file.

``[active_members]``, ``[actuators]``, ``[failure]`` and ``[postcritical]`` become the typed,
immutable data of :mod:`trussfe.model` (see :mod:`trussfe.model.extensions`).  Every check of
these tables lives here: any table either becomes its data or raises one
:class:`~trussfe.errors.InputError` naming the item.  The tables are read in the order of
:data:`TABLES`, each against the model holding the ones read before it (an actuator must sit on
an active member).
"""
from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Callable

from ..errors import InputError
from ..model.active import ActiveMember
from ..model.actuators import ACME_THREAD_ANGLE, Actuator
from ..model.failure import BUCKLING, YIELD, FailureLaws
from .failure_laws import build_failure_laws
from ..model.bar_models import BAR_MODELS
from ..model.member_loads import AXES as LOAD_AXES
from ..model.member_loads import KINDS as LOAD_KINDS
from ..model.member_loads import MemberLoad
from ..model.postcritical import CONTROLS, SETTING_TYPES, PostcriticalSettings
from ..model.structure import Structure

_ACTIVE_KEYS = ("base_mass", "base_length", "base_cg", "base_inertia", "tube_length",
                "min_length", "max_length")
_ACTUATOR_KEYS = ("leadscrew_gain", "mean_diameter", "thread", "thread_angle", "friction",
                  "gearhead_gain", "armature_inertia", "resistance", "torque_constant",
                  "back_emf_constant", "max_speed", "max_voltage", "require_self_locking",
                  "convention")
_FAILURE_KEYS = ("buckling", "effective_length_factor", "critical_load", "residual",
                 "softening_strain", "yield", "yield_strength", "fracture_strain")
#: Axis letters of a ``NODE:AXIS`` monitor.
AXES = "xyz"


def _num(raw: dict, key: str, item: str, *, positive=False, nonneg=False,
         default: float | None = None) -> float:
    if key not in raw:
        if default is None:
            raise InputError(f"{item}.{key}", "is required")
        return default
    v = raw[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(float(v)):
        raise InputError(f"{item}.{key}", f"expected a finite number, got {v!r}")
    v = float(v)
    if positive and not v > 0:
        raise InputError(f"{item}.{key}", f"must be positive, got {v!r}")
    if nonneg and v < 0:
        raise InputError(f"{item}.{key}", f"must not be negative, got {v!r}")
    return v


def parse_active_members(raw: Any, structure: Structure, base_dir: Path | None = None
                         ) -> tuple[ActiveMember, ...]:
    """Read the ``[active_members]`` table.

    Raises
    ------
    InputError
        For an unknown member id, a missing or non-positive quantity, a tube longer than the
        member, or a member that is not a pin-jointed bar.
    """
    if not isinstance(raw, dict) or not raw:
        raise InputError("[active_members]", "expected one table per active member, "
                         "e.g. [active_members.M7_8]")
    out = []
    for mid, t in raw.items():
        item = f"active_members.{mid}"
        try:
            k = structure.member_index(str(mid))
        except KeyError:
            raise InputError(item, f"'{mid}' is not a member of the model; the table key must "
                             "be a member id from [members]") from None
        if not isinstance(t, dict):
            raise InputError(item, "expected a table")
        for key in t:
            if key not in _ACTIVE_KEYS:
                raise InputError(f"{item}.{key}",
                                 f"unknown key; valid: {', '.join(_ACTIVE_KEYS)}")
        if structure.is_beam[k]:
            raise InputError(item, "an active member must be a pin-jointed bar (type = \"bar\")")
        mb = _num(t, "base_mass", item, nonneg=True)
        lb = _num(t, "base_length", item, positive=True)
        cg = _num(t, "base_cg", item, nonneg=True, default=lb / 2.0)
        ib = _num(t, "base_inertia", item, nonneg=True, default=mb * lb * lb / 3.0)
        if ib < mb * cg * cg * (1 - 1e-12):
            raise InputError(f"{item}.base_inertia", f"{ib} kg·m² is less than base_mass·"
                             f"base_cg² = {mb * cg * cg} kg·m²; give it about the start node")
        lt = _num(t, "tube_length", item, positive=True)
        L0 = float(structure.lengths()[k])
        if lt > L0 * (1 + 1e-12):
            raise InputError(f"{item}.tube_length", f"{lt} m is longer than the member "
                             f"({L0:.6g} m at rest)")
        lo = _num(t, "min_length", item, positive=True, default=math.nan)
        hi = _num(t, "max_length", item, positive=True, default=math.nan)
        if lo > hi:                                     # (False when either is not given)
            raise InputError(f"{item}.min_length", f"{lo} m is more than max_length = {hi} m: "
                             "no length lies in the stroke")
        out.append(ActiveMember(member=k, base_mass=mb, base_length=lb, base_cg=cg,
                                base_inertia=ib, tube_length=lt, min_length=lo, max_length=hi))
    return tuple(out)


def parse_actuator(mid: str, t: Any, member: int) -> Actuator:
    """One ``[actuators.ID]`` table → :class:`Actuator` (checks every value)."""
    item = f"actuators.{mid}"
    if not isinstance(t, dict):
        raise InputError(item, "expected a table")
    for key in t:
        if key not in _ACTUATOR_KEYS:
            raise InputError(f"{item}.{key}", f"unknown key; valid: {', '.join(_ACTUATOR_KEYS)}")
    thread = t.get("thread", "square")
    if thread not in ("square", "acme"):
        raise InputError(f"{item}.thread", f"must be \"square\" or \"acme\", got {thread!r}")
    if thread == "square":
        if "thread_angle" in t and float(_num(t, "thread_angle", item)) != 0.0:
            raise InputError(f"{item}.thread_angle", "a square thread has no thread angle; "
                             "set thread = \"acme\" or remove thread_angle")
        angle = 0.0
    else:
        angle = _num(t, "thread_angle", item, nonneg=True, default=ACME_THREAD_ANGLE)
        if angle >= 90.0:
            raise InputError(f"{item}.thread_angle", f"must be below 90 degrees, got {angle}")
    convention = t.get("convention", "physical")
    if convention not in ("physical", "thesis"):
        raise InputError(f"{item}.convention", f"must be \"physical\" or \"thesis\", got "
                         f"{convention!r}")
    req = t.get("require_self_locking", True)
    if not isinstance(req, bool):
        raise InputError(f"{item}.require_self_locking", f"expected true or false, got {req!r}")
    act = Actuator(
        member=member, name=str(mid),
        leadscrew_gain=_num(t, "leadscrew_gain", item, positive=True),
        mean_diameter=_num(t, "mean_diameter", item, positive=True),
        thread=thread, thread_angle=math.radians(angle),
        friction=_num(t, "friction", item, nonneg=True),
        gearhead_gain=_num(t, "gearhead_gain", item, positive=True, default=math.nan),
        armature_inertia=_num(t, "armature_inertia", item, nonneg=True),
        resistance=_num(t, "resistance", item, nonneg=True),
        torque_constant=_num(t, "torque_constant", item, positive=True),
        back_emf_constant=_num(t, "back_emf_constant", item, nonneg=True),
        max_speed=_num(t, "max_speed", item, positive=True, default=math.nan),
        max_voltage=_num(t, "max_voltage", item, positive=True, default=math.nan),
        require_self_locking=req, convention=convention)
    if math.isnan(act.gearhead_gain) and math.isnan(act.max_speed):
        raise InputError(f"{item}.gearhead_gain", "is required unless max_speed is given "
                         "(the gain is then selected from the motion, Lacy eq. 3.1)")
    pd = math.pi * act.mean_diameter
    if act.friction / math.cos(act.thread_angle) * act.lead >= pd:
        raise InputError(item, "the thread cannot be driven against the load "
                         "(μ l sec α_T ≥ π d_m in Lacy eq. 2.35); check friction and gain")
    check_self_locking(act)
    return act


def check_self_locking(act: Actuator) -> None:
    """Raise :class:`InputError` if ``act`` must self-lock and does not (Lacy eq. 2.45)."""
    if act.require_self_locking and not act.self_locking:
        raise InputError(
            f"actuators.{act.name}",
            f"the leadscrew is not self-locking: G_ls = {act.leadscrew_gain:.6g} m/rad exceeds "
            f"μ d_m sec α_T / 2 = {act.self_locking_limit:.6g} m/rad (Lacy eq. 2.45); lower "
            "leadscrew_gain or set require_self_locking = false")


def parse_actuators(raw: Any, structure: Structure, base_dir: Path | None = None
                    ) -> tuple[Actuator, ...]:
    """Read the ``[actuators]`` table (of a model holding its ``[active_members]``).

    Raises
    ------
    InputError
        Unknown or passive member, missing or invalid value, a screw that is not self-locking
        when it must be.
    """
    if not isinstance(raw, dict) or not raw:
        raise InputError("[actuators]", "expected one table per active member, "
                         "e.g. [actuators.M7_8]")
    active = {a.member for a in structure.extensions.get("active_members", ())}
    out = []
    for mid, t in raw.items():
        try:
            k = structure.member_index(str(mid))
        except KeyError:
            raise InputError(f"actuators.{mid}", f"'{mid}' is not a member of the model") \
                from None
        if k not in active:
            raise InputError(f"actuators.{mid}", f"'{mid}' is not an active member; add an "
                             f"[active_members.{mid}] table")
        out.append(parse_actuator(str(mid), t, k))
    return tuple(out)


def _law(raw: Any, item: str) -> dict:
    if not isinstance(raw, dict):
        raise InputError(item, "expected a table of failure-law keys "
                               f"({', '.join(_FAILURE_KEYS)})")
    for k in raw:
        if k not in _FAILURE_KEYS:
            raise InputError(f"{item}.{k}",
                             f"unknown key '{k}'; valid: {', '.join(_FAILURE_KEYS)}")
    out = dict(raw)
    for k in ("effective_length_factor", "critical_load", "residual", "softening_strain",
              "yield_strength", "fracture_strain"):
        if k in out:
            v = out[k]
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                raise InputError(f"{item}.{k}", f"expected a finite number, got {v!r}")
            out[k] = float(v)
    for k, allowed in (("buckling", BUCKLING), ("yield", YIELD)):
        if k in out and out[k] not in allowed:
            raise InputError(f"{item}.{k}", f"unknown law {out[k]!r}; valid: "
                                             f"{', '.join(allowed)}")
    return out


def parse_failure_table(raw: Any, structure: Structure, base_dir: Path | None = None
                        ) -> FailureLaws:
    """Read the ``[failure]`` table into :class:`FailureLaws` (checks every parameter).

    Raises
    ------
    InputError
        Unknown keys, unknown laws, non-positive parameters, parameters that the chosen law
        does not use (e.g. ``residual`` with ``buckling = "cap"``), a residual outside [0, 1],
        a buckling law on a section without a second moment of area, a yield law on a material
        without ``yield_strength``.
    """
    if not isinstance(raw, dict):
        raise InputError("[failure]", "expected a table with 'default' and/or 'members'")
    for k in raw:
        if k not in ("default", "members"):
            raise InputError(f"failure.{k}", "unknown key; valid: default, members")
    default = _law(raw.get("default", {}), "failure.default")
    members = raw.get("members", {})
    if not isinstance(members, dict):
        raise InputError("failure.members", "expected a table of member ids")
    per = {}
    for mid, law in members.items():
        if str(mid) not in structure.member_ids:
            raise InputError(f"failure.members.{mid}", f"member '{mid}' is not defined")
        per[structure.member_index(str(mid))] = _law(law, f"failure.members.{mid}")
    return build_failure_laws(structure, default, per)


def parse_settings(raw: Any, structure: Structure | None = None, base_dir: Path | None = None
                   ) -> PostcriticalSettings:
    """Read the ``[postcritical]`` table (every value checked, item named)."""
    if not isinstance(raw, dict):
        raise InputError("[postcritical]", "expected a table of analysis settings")
    out = {}
    for k, v in raw.items():
        item = f"postcritical.{k}"
        if k not in SETTING_TYPES:
            raise InputError(item, f"unknown key; valid: {', '.join(SETTING_TYPES)}")
        typ = SETTING_TYPES[k]
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
    return PostcriticalSettings(**out)


def parse_monitor(text: str, structure: Structure, item: str = "--monitor") -> tuple[int, int]:
    """``"NODE:AXIS"`` → (node index, axis index)."""
    node, sep, axis = str(text).rpartition(":")
    if not sep or axis not in AXES[: structure.dim]:
        raise InputError(item, f"expected NODE:AXIS with AXIS in {AXES[:structure.dim]}, "
                               f"got {text!r}")
    if node not in structure.node_ids:
        raise InputError(item, f"node '{node}' is not defined")
    return structure.node_index(node), AXES.index(axis)

#: Keys of a member load besides ``member``, ``kind`` and ``axes``, per kind.
_LOAD_KEYS = {"uniform": ("q",), "trapezoidal": ("q_start", "q_end"), "point": ("at", "F", "M")}
#: Optional keys of a distributed member load.
_OPTIONAL_KEYS = {"uniform": ("span",), "trapezoidal": ("span",), "point": ()}


def _load_vector(raw: dict, key: str, item: str, size: int) -> tuple[float, ...]:
    v = raw[key]
    if not isinstance(v, list) or len(v) != size:
        n = len(v) if isinstance(v, list) else "not a list"
        raise InputError(f"{item}.{key}", f"expected {size} numbers, got {n}"
                         + (f" ({v!r})" if not isinstance(v, list) else ""))
    out = []
    for i, x in enumerate(v):
        if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(
                float(x)):
            raise InputError(f"{item}.{key}[{i}]", f"expected a finite number, got {x!r}")
        out.append(float(x))
    return tuple(out)


def parse_member_loads(raw: Any, structure: Structure, base_dir: Path | None = None,
                       item: str = "member_loads") -> tuple[MemberLoad, ...]:
    """Read a ``member_loads`` array (:mod:`trussfe.model.member_loads`).

    ``item`` names the array in messages (``member_loads``, or the array of a load case).

    Raises
    ------
    InputError
        Not an array of tables, a member that does not exist, an unknown kind or axes, a
        position outside [0, 1], a span that is not [a, b] with 0 <= a < b <= 1, a vector of
        the wrong length, a couple about the axis of a pin-ended bar (it carries no
        torsion).
    """
    if not isinstance(raw, list) or not all(isinstance(t, dict) for t in raw):
        raise InputError(item, "expected an array of tables { member = .., kind = .., ... }")
    dim = structure.dim
    out = []
    for n, t in enumerate(raw):
        it = f"{item}[{n}]"
        if "member" not in t:
            raise InputError(it, "missing 'member'")
        mid = str(t["member"])
        try:
            k = structure.member_index(mid)
        except KeyError:
            raise InputError(f"{it}.member", f"member '{mid}' is not defined in [members]") \
                from None
        it = f"{item}[{n}] (member {mid})"
        kind = t.get("kind")
        if kind not in LOAD_KINDS:
            raise InputError(f"{it}.kind", f"unknown member-load kind {kind!r}; use one of "
                             + ", ".join(LOAD_KINDS))
        allowed = ("member", "kind", "axes") + _LOAD_KEYS[kind] + _OPTIONAL_KEYS[kind]
        for key in t:
            if key not in allowed:
                raise InputError(f"{it}.{key}", f"unknown key '{key}' for a {kind} load; "
                                 f"valid: {', '.join(allowed)}")
        axes = t.get("axes", "global")
        if axes not in LOAD_AXES:
            raise InputError(f"{it}.axes", f"unknown axes {axes!r}; use global or local")
        for key in _LOAD_KEYS[kind]:
            if key not in t and key not in ("M", "F"):
                raise InputError(it, f"missing '{key}' (a {kind} load needs "
                                     f"{' and '.join(_LOAD_KEYS[kind][:2])})")
        if kind in ("uniform", "trapezoidal"):
            span = _load_vector(t, "span", it, 2) if "span" in t else (0.0, 1.0)
            if not 0.0 <= span[0] < span[1] <= 1.0:
                raise InputError(f"{it}.span", f"expected [a, b] with 0 <= a < b <= 1 "
                                 f"(fractions of the member length), got {t['span']!r}")
        if kind == "uniform":
            q = _load_vector(t, "q", it, dim)
            ld = MemberLoad(k, kind, q, q, axes=axes, span=span)
        elif kind == "trapezoidal":
            ld = MemberLoad(k, kind, _load_vector(t, "q_start", it, dim),
                            _load_vector(t, "q_end", it, dim), axes=axes, span=span)
        else:
            a = _num(t, "at", it)
            if not 0.0 <= a <= 1.0:
                raise InputError(f"{it}.at", f"must be a fraction of the member length in "
                                             f"[0, 1], got {t['at']!r}")
            if "F" not in t and "M" not in t:
                raise InputError(it, "a point load needs F (a force) and/or M (a couple)")
            F = _load_vector(t, "F", it, dim) if "F" in t else ()
            M = _load_vector(t, "M", it, 1 if dim == 2 else 3) if "M" in t else ()
            if M and dim == 3 and not structure.is_beam[k]:
                e = structure.unit_vectors()[k] if axes == "global" else (1.0, 0.0, 0.0)
                if abs(sum(mi * ei for mi, ei in zip(M, e))) > 1e-12 * max(map(abs, M)):
                    raise InputError(f"{it}.M", "a bar carries no torsion: a couple on a bar "
                                                "must be perpendicular to it (or make the "
                                                "member a beam)")
            ld = MemberLoad(k, kind, at=a, force=F, moment=M, axes=axes)
        out.append(ld)
    return tuple(out)


#: Extension tables and their readers ``reader(raw, structure, base_dir)``, in reading order.
TABLES: dict[str, Callable[[Any, Structure, Path], Any]] = {
    "active_members": parse_active_members,
    "actuators": parse_actuators,
    "failure": parse_failure_table,
    "postcritical": parse_settings,
    "member_loads": parse_member_loads,
}
