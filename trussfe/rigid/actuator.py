# SPDX-License-Identifier: MIT
"""Actuator and motor model: leadscrew torque, armature inertia, motor torque, current, voltage.

Each active member is driven by a DC motor through a gearhead and a leadscrew (Lacy section 2.9,
4.11).  The motor angle θ_m and the member's extension X are tied by (Lacy eqs. 2.27–2.29)

.. math:: X = \\frac{G_{ls}}{G_{gh}} \\theta_m, \\quad
          \\dot\\theta_m = \\frac{G_{gh}}{G_{ls}} \\dot X, \\quad
          \\ddot\\theta_m = \\frac{G_{gh}}{G_{ls}} \\ddot X .

The leadscrew torque that makes the screw exert the force F on the leadscrew tube, for a thread
of lead ``l = 2π G_ls``, mean diameter d_m, friction coefficient μ and thread angle α_T
(α_T = 0 for a square thread), is (Lacy eqs. 2.35–2.38)

.. math:: T_p = \\frac{F d_m}{2}\\,\\frac{l + s\\,\\pi\\mu d_m\\sec\\alpha_T}
                                      {\\pi d_m - s\\,\\mu l\\sec\\alpha_T},

with s = +1 when the screw works against the load (eqs. 2.35, 2.37) and s = −1 when it works
with the load (eqs. 2.36, 2.38).  The motor adds the armature inertia torque J_m θ̈_m
(eq. 2.39–2.40); current and voltage follow with the inductance neglected (eqs. 2.42–2.44):

.. math:: I_a = T_m / K_t, \\qquad V_m = T_m R_a / K_t + K_b \\dot\\theta_m .

The screw self-locks when the with-load torque is not negative, i.e. (eq. 2.45, generalised to
a thread angle by eq. 2.38) ``G_ls ≤ μ d_m sec α_T / 2``.  Given the motor's maximum speed, the
gearhead gain can be chosen from the largest extension rate (eq. 3.1):
``G_gh = G_ls θ̇_max / Ẋ_max``.

Two conventions
---------------
``convention = "physical"`` (default) keeps signs: the motor torque is positive in the sense of
increasing θ_m (lengthening the member); the ideal gearhead multiplies the torque by G_gh, so the
leadscrew torque reaches the motor as T_p / G_gh; the screw works against the load when it does
positive work (F Ẋ > 0), with it when F Ẋ < 0, and, at rest, against it (the torque that must be
overcome before motion starts, Lacy section 2.9).

``convention = "thesis"`` is Lacy's Appendix C code, literally: magnitudes only,
``T_m = J_m |θ̈_m| + |F| d_m/2 · ratio`` with the leadscrew torque applied at the motor without the
gearhead ratio (as eq. 2.40 is written), ``V_m = T_m R_a/K_t + K_b |θ̇_m|``, and "against the
load" when the force and the static force have the same sign.  It reproduces the thesis'
figures, e.g. the 29 V peak of section 5.7.

Model-file table (the key is the active member's id)::

    [actuators.M7_8]
    leadscrew_gain = 2.5266e-4     # m/rad, G_ls (1/16 in per revolution)
    mean_diameter = 0.0127         # m, d_m
    thread = "square"              # or "acme"
    thread_angle = 14.5            # degrees, α_T (acme only; default 14.5)
    friction = 0.1                 # μ
    gearhead_gain = 5.2            # G_gh; omit it to select it from max_speed (eq. 3.1)
    armature_inertia = 6.76e-6     # kg·m², J_m
    resistance = 2.0               # ohm, R_a
    torque_constant = 0.0398       # N·m/A, K_t
    back_emf_constant = 0.0398     # V·s/rad, K_b
    max_speed = 400.0              # rad/s, optional
    max_voltage = 25.0             # V, optional
    require_self_locking = true    # optional (default true)
    convention = "physical"        # or "thesis"
"""
from __future__ import annotations

import logging
import math
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import AnalysisError, InputError
from ..io.model_file import register_table
from ..model.structure import Structure
from .active import active_members

log = logging.getLogger(__name__)

_KEYS = ("leadscrew_gain", "mean_diameter", "thread", "thread_angle", "friction",
         "gearhead_gain", "armature_inertia", "resistance", "torque_constant",
         "back_emf_constant", "max_speed", "max_voltage", "require_self_locking", "convention")
#: Half-angle of an Acme thread (29° included angle), degrees (Shigley, Lacy ref. 19).
ACME_THREAD_ANGLE = 14.5
#: Relative slack on the self-locking limit: Lacy's triangular truss uses G_ls = μ d_m / 2
#: exactly (0.003 m/rad, section 3.7), the limiting value the thesis itself selects.
SELF_LOCKING_RTOL = 1e-9


@dataclass(frozen=True)
class Actuator:
    """Leadscrew, gearhead and motor data of one active member.

    Attributes
    ----------
    member : int
        Index of the active member in the structure.
    name : str
        Its id (for messages and output keys).
    leadscrew_gain : float
        G_ls, extension per radian of the leadscrew, m/rad (lead l = 2π G_ls).
    mean_diameter : float
        d_m, m.
    thread : str
        ``"square"`` or ``"acme"``.
    thread_angle : float
        α_T, radians (0 for a square thread).
    friction : float
        μ, thread friction coefficient.
    gearhead_gain : float
        G_gh (``nan``: select it from ``max_speed`` with eq. 3.1).
    armature_inertia, resistance, torque_constant, back_emf_constant : float
        J_m (kg·m²), R_a (Ω), K_t (N·m/A), K_b (V·s/rad).
    max_speed, max_voltage : float
        Motor limits, rad/s and V (``nan`` if not given).
    require_self_locking : bool
        Raise :class:`InputError` if the screw does not self-lock (eq. 2.45).
    convention : str
        ``"physical"`` or ``"thesis"`` (module docstring).
    """

    member: int
    name: str
    leadscrew_gain: float
    mean_diameter: float
    thread: str
    thread_angle: float
    friction: float
    gearhead_gain: float
    armature_inertia: float
    resistance: float
    torque_constant: float
    back_emf_constant: float
    max_speed: float = math.nan
    max_voltage: float = math.nan
    require_self_locking: bool = True
    convention: str = "physical"

    @property
    def lead(self) -> float:
        """Lead of the thread, l = 2π G_ls, m (Lacy eq. 2.34)."""
        return 2.0 * math.pi * self.leadscrew_gain

    @property
    def self_locking_limit(self) -> float:
        """Largest self-locking leadscrew gain μ d_m sec α_T / 2, m/rad (Lacy eq. 2.45)."""
        return max_leadscrew_gain(self.friction, self.mean_diameter, self.thread_angle)

    @property
    def self_locking(self) -> bool:
        """Whether the screw holds a static load without motor torque (Lacy eq. 2.45)."""
        return self.leadscrew_gain <= self.self_locking_limit * (1.0 + SELF_LOCKING_RTOL)


def max_leadscrew_gain(friction: float, mean_diameter: float, thread_angle: float = 0.0) -> float:
    """Largest leadscrew gain for which the screw self-locks (Lacy eq. 2.45).

    The with-load torque of eq. 2.38 is non-negative while ``l ≤ π μ d_m sec α_T``, i.e.
    ``G_ls ≤ μ d_m sec α_T / 2``; for a square thread (α_T = 0) this is eq. 2.45.

    Examples
    --------
    Lacy section 3.7: μ = 0.3 and d_m = 0.02 m give 0.003 m/rad.

    >>> round(max_leadscrew_gain(0.3, 0.02), 6)
    0.003
    """
    return friction * mean_diameter / (2.0 * math.cos(thread_angle))


def select_gearhead_gain(leadscrew_gain: float, max_speed: float, max_velocity: float) -> float:
    """Gearhead gain that lets the motor reach the largest extension rate (Lacy eq. 3.1).

    ``G_mech = Ẋ_max / θ̇_m,max`` and ``G_gh = G_ls / G_mech``.

    Examples
    --------
    Base Simulation (Lacy section 3.7): 1.2477 m/s at 400 rad/s with G_ls = 0.003 m/rad.

    >>> round(select_gearhead_gain(0.003, 400.0, 1.2477), 4)
    0.9618
    """
    if not (max_velocity > 0 and math.isfinite(max_velocity)):
        raise AnalysisError("gearhead_gain", "the motion never moves the actuator; give "
                            "gearhead_gain explicitly")
    return leadscrew_gain * max_speed / max_velocity


def thread_ratio(lead: float, mean_diameter: float, friction: float, thread_angle: float,
                 against: np.ndarray | bool) -> np.ndarray:
    """Leadscrew torque per unit force and half mean diameter, T_p / (F d_m / 2).

    Against the load ``(l + π μ d_m sec α_T) / (π d_m − μ l sec α_T)`` (Lacy eqs. 2.35, 2.37),
    with it ``(π μ d_m sec α_T − l) / (π d_m + μ l sec α_T)`` (eqs. 2.36, 2.38), as printed:
    the torque in the sense of the motion; with the load it is the torque still needed to
    lower the load, negative when the screw is not self-locking.

    Examples
    --------
    Without friction the cases are ``± l / (π d_m)`` = ± tan λ (eq. 2.34):

    >>> float(thread_ratio(0.01, 0.02, 0.0, 0.0, True)) == 0.01 / (math.pi * 0.02)
    True
    >>> float(thread_ratio(0.01, 0.02, 0.0, 0.0, False)) == -0.01 / (math.pi * 0.02)
    True
    """
    mu = friction / math.cos(thread_angle)
    pd = math.pi * mean_diameter
    return np.where(against, (lead + mu * pd) / (pd - mu * lead),
                    (mu * pd - lead) / (pd + mu * lead))


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


def parse_actuator(mid: str, t: Any, member: int) -> Actuator:
    """One ``[actuators.ID]`` table → :class:`Actuator` (checks every value)."""
    item = f"actuators.{mid}"
    if not isinstance(t, dict):
        raise InputError(item, "expected a table")
    for key in t:
        if key not in _KEYS:
            raise InputError(f"{item}.{key}", f"unknown key; valid: {', '.join(_KEYS)}")
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


def parse_actuators(raw: Any, structure: Structure, base_dir: Path) -> list[Actuator]:
    """Read the ``[actuators]`` table (registered with the model-file reader).

    Raises
    ------
    InputError
        Unknown or passive member, missing or invalid value, a screw that is not self-locking
        when it must be.
    """
    if not isinstance(raw, dict) or not raw:
        raise InputError("[actuators]", "expected one table per active member, "
                         "e.g. [actuators.M7_8]")
    active = {a.member for a in active_members(structure)}
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
    return out


register_table("actuators", parse_actuators)


def actuators_of(structure: Structure) -> list[Actuator]:
    """The structure's actuators (empty list when it has none)."""
    return list(structure.extensions.get("actuators", []))


def motor_histories(act: Actuator, force: np.ndarray, velocity: np.ndarray,
                    acceleration: np.ndarray, static_force: np.ndarray | None = None,
                    time: np.ndarray | None = None) -> dict:
    """Motor speed, torque, current and voltage of one actuator (Lacy eqs. 2.35–2.44).

    Parameters
    ----------
    act : Actuator
        Its data; ``gearhead_gain`` must be set (see :func:`select_gearhead_gain`).
    force : ndarray, shape (nt,)
        Force of the leadscrew on the leadscrew tube along the member, N (positive pushing the
        tube outward, i.e. lengthening the member).
    velocity, acceleration : ndarray, shape (nt,)
        Extension rate Ẋ (m/s) and its rate Ẍ (m/s²).
    static_force : ndarray, shape (nt,), optional
        Static force at the same positions (only the ``"thesis"`` convention uses it; default
        ``force``).
    time : ndarray, optional
        Times, for the messages of the flags.

    Returns
    -------
    dict
        Arrays ``force, motor_speed, motor_acceleration, leadscrew_torque, armature_torque,
        motor_torque, motor_current, motor_voltage``, the same ``*_frictionless`` (μ = 0),
        ``against_load`` (bool), scalars ``gearhead_gain, leadscrew_gain, self_locking,
        max_motor_voltage, max_motor_speed, convention`` and a ``flags`` list of strings.

    Examples
    --------
    A frictionless screw holding 100 N at rest: T_m = F G_ls / G_gh.

    >>> a = Actuator(0, "A", 1e-3, 0.02, "square", 0.0, 0.0, 2.0, 0.0, 1.0, 0.05, 0.05,
    ...              require_self_locking=False)
    >>> h = motor_histories(a, np.array([100.0]), np.zeros(1), np.zeros(1))
    >>> [round(float(h[k][0]), 12) for k in ("motor_torque", "motor_current", "motor_voltage")]
    [0.05, 1.0, 1.0]
    """
    force = np.asarray(force, dtype=float)
    velocity = np.asarray(velocity, dtype=float)
    acceleration = np.asarray(acceleration, dtype=float)
    gg, gl = act.gearhead_gain, act.leadscrew_gain
    if not (gg > 0 and math.isfinite(gg)):
        raise AnalysisError(f"actuators.{act.name}.gearhead_gain", "is not set")
    speed = gg / gl * velocity                   # θ̇_m, eq. 2.28
    accel = gg / gl * acceleration               # θ̈_m, eq. 2.29
    half_d = act.mean_diameter / 2.0
    if act.convention == "thesis":
        # Appendix C: |θ̈|, |F|, |θ̇|; no gearhead ratio on the leadscrew torque (eq. 2.40).
        fs = force if static_force is None else np.asarray(static_force, dtype=float)
        against = np.sign(force) == np.sign(fs)
        ratio = thread_ratio(act.lead, act.mean_diameter, act.friction, act.thread_angle,
                             against)
        lead_torque = half_d * np.abs(force) * ratio
        lead_torque0 = np.abs(force) * gl
        arm = act.armature_inertia * np.abs(accel)
        motor_lead, motor_lead0 = lead_torque, lead_torque0
        emf = act.back_emf_constant * np.abs(speed)
    else:
        # The screw does positive work on the tube when F Ẋ > 0 (against the load); at rest the
        # motor must overcome the static load before motion starts (Lacy section 2.9).
        against = force * velocity >= 0.0
        ratio = thread_ratio(act.lead, act.mean_diameter, act.friction, act.thread_angle,
                             against)
        # Torque in the +θ sense: F d_m/2 tan(λ ± φ); the with-load form of eqs. 2.36/2.38 is
        # the torque in the sense of the motion, i.e. of −F, hence its sign change.
        lead_torque = half_d * force * np.where(against, ratio, -ratio)
        lead_torque0 = force * gl                     # μ = 0: F l / (2π)
        arm = act.armature_inertia * accel            # eq. 2.39
        motor_lead, motor_lead0 = lead_torque / gg, lead_torque0 / gg   # ideal gearhead
        emf = act.back_emf_constant * speed
    torque = arm + motor_lead                          # eq. 2.40
    torque0 = arm + motor_lead0
    kt, ra = act.torque_constant, act.resistance
    out = {
        "force": force, "motor_speed": speed, "motor_acceleration": accel,
        "leadscrew_torque": lead_torque, "armature_torque": arm,
        "motor_torque": torque, "motor_current": torque / kt,                 # eq. 2.43
        "motor_voltage": torque * ra / kt + emf,                              # eq. 2.44
        "motor_torque_frictionless": torque0, "motor_current_frictionless": torque0 / kt,
        "motor_voltage_frictionless": torque0 * ra / kt + emf,
        "against_load": against,
        "gearhead_gain": gg, "leadscrew_gain": gl, "self_locking": act.self_locking,
        "convention": act.convention,
    }
    vmax = float(np.abs(out["motor_voltage"]).max()) if force.size else 0.0
    wmax = float(np.abs(speed).max()) if force.size else 0.0
    out["max_motor_voltage"] = vmax
    out["max_motor_speed"] = wmax
    flags = []
    t = np.arange(force.size, dtype=float) if time is None else np.asarray(time, dtype=float)
    unit = "step" if time is None else "t ="
    suffix = "" if time is None else " s"
    if not math.isnan(act.max_voltage) and vmax > act.max_voltage:
        k = int(np.argmax(np.abs(out["motor_voltage"])))
        flags.append(f"voltage: the motor needs {vmax:.4g} V at {unit} {t[k]:.4g}{suffix}, "
                     f"more than its maximum {act.max_voltage:.4g} V")
    if not math.isnan(act.max_speed) and wmax > act.max_speed * (1.0 + 1e-9):
        k = int(np.argmax(np.abs(speed)))
        flags.append(f"speed: the motor must turn at {wmax:.4g} rad/s at {unit} {t[k]:.4g}"
                     f"{suffix}, more than its maximum {act.max_speed:.4g} rad/s")
    if not act.self_locking:
        flags.append(f"self-locking: G_ls = {gl:.4g} m/rad exceeds μ d_m sec α_T / 2 = "
                     f"{act.self_locking_limit:.4g} m/rad; the static load back-drives the motor")
    for f in flags:
        log.warning("actuator %s: %s", act.name, f)
    out["flags"] = flags
    return out


def actuator_histories(structure: Structure, motion, actuator_force: np.ndarray,
                       static_force: np.ndarray | None = None) -> dict[str, dict]:
    """Actuator and motor histories of every active member that has ``[actuators]`` data.

    Parameters
    ----------
    structure : Structure
        Model with ``[active_members]`` and ``[actuators]``.
    motion : Motion
        The motion (``members``, ``time``, ``velocity``, ``acceleration``, columns in the order
        of ``motion.members``).
    actuator_force : ndarray, shape (nt, n_active)
        Axial force of the leadscrew on the leadscrew tube (positive pushing it outward), in
        the column order of ``motion.members``.
    static_force : ndarray, shape (nt, n_active), optional
        Static force at the same positions (thesis convention's with/against test).

    Returns
    -------
    dict
        Active member id → :func:`motor_histories` dictionary.  A gearhead gain left out of the
        model is selected from the motor's maximum speed and the motion's largest extension
        rate (Lacy eq. 3.1); the dictionary then says so in ``gearhead_gain_selected``.
    """
    force = np.atleast_2d(np.asarray(actuator_force, dtype=float))
    members = [int(k) for k in np.asarray(motion.members).reshape(-1)]
    if force.shape != (motion.time.size, len(members)):
        raise AnalysisError("actuator_force", f"expected shape {(motion.time.size, len(members))}"
                            f", got {force.shape}")
    if not np.all(np.isfinite(force)):
        i, j = np.argwhere(~np.isfinite(force))[0]
        raise AnalysisError("actuator_force", f"is NaN at step {int(i)} for active member "
                            f"{structure.member_ids[members[j]]}")
    fs = None if static_force is None else np.atleast_2d(np.asarray(static_force, dtype=float))
    out = {}
    for act in actuators_of(structure):
        if act.member not in members:
            log.info("actuator %s does not move in this motion; skipped", act.name)
            continue
        j = members.index(act.member)
        vel, acc = motion.velocity[:, j], motion.acceleration[:, j]
        selected = False
        if math.isnan(act.gearhead_gain):
            act = replace(act, gearhead_gain=select_gearhead_gain(
                act.leadscrew_gain, act.max_speed, float(np.abs(vel).max())))
            selected = True
        h = motor_histories(act, force[:, j], vel, acc, None if fs is None else fs[:, j],
                            time=motion.time)
        h["gearhead_gain_selected"] = selected
        out[act.name] = h
    return out
