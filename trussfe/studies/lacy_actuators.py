# SPDX-License-Identifier: MIT
"""Actuator and motor quantities of Lacy's thesis, reproduced (sections 3.7 and 5.7).

* **Base Simulation gains** (section 3.7): μ = 0.3 and d_m = 0.02 m give the largest
  self-locking leadscrew gain 0.003 m/rad (eq. 2.45); with the Base Simulation's largest
  extension rate (1.2477 m/s) and a 400 rad/s motor, eq. 3.1 gives G_gh = 0.9618.  Appendix A's
  listing sets ``Ggh = 5.2``, ``Gls = 2.5266e-4`` instead (the prototype's values): with those
  the motor would have to turn at 25,700 rad/s, 64 times its maximum.
* **Slewing Experiment 1** (sections 5.1, 5.5.1, 5.6, figs. 5.13–5.16): the measured link
  histories are not published, so the motion is rebuilt from the text
  (:func:`slew1_motion`): from the first slewed position (M7/8 at its maximum 1.2289 m, M9/10
  and M11/12 at their minimum) to the second (the reverse) — section 5.1: "corresponds to
  the starting point" / "the ending point for the dynamic simulation", "the maximum slew that
  the prototype truss can achieve" — every member at "virtually a constant velocity" between
  smooth 0.25 s ramps (the "large acceleration spike at the beginning and the end"), in
  "approximately 5.5 seconds", through the equilibrium position at 2.75 s (section 5.6:
  "approximately 2.8 seconds").  The whole motion lies inside the prototype's stroke,
  1.1684 ± 0.0606 m (section 5.5; :data:`trussfe.models.STROKE`).  The minimum is 1.1079 m,
  which reproduces Tables 5.3/5.4 (printed 1.1077 m, 0.1 mm outside the stroke).  Hanging
  truss, 46.0 N on N7–N9, Appendix C's actuators (G_ls = 2.5266e-4 m/rad, G_gh = 5.2,
  μ = 0.1, d_m = 0.0127 m, J_m = 6.76e-6 kg·m², R_a = 2 Ω, K_t = K_b = 0.0398).
  Table 5.1 prints the leadscrew gain as 2.527e-6 m/rad; Appendix C's 2.5266e-4 m/rad (1/16 in
  per revolution) is the value its code uses.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from .. import models
from ..mechanics.conventions import THESIS
from ..model.structure import Structure
from ..rigid.actuator import Actuator, max_leadscrew_gain, motor_histories, select_gearhead_gain
from ..rigid.motion import Motion, third_order_response
from .lacy_rigid import double_octahedron
from ..rigid.simulate import simulate
from ..rigid.slew import constant_velocity_profile

#: Appendix C / Table 5.1 actuator of the VPI&SU prototype.
PROTOTYPE = dict(leadscrew_gain=2.5266e-4, mean_diameter=0.5 * 0.0254, thread="square",
                 thread_angle=0.0, friction=0.1, gearhead_gain=5.2, armature_inertia=6.76e-6,
                 resistance=2.0, torque_constant=0.0398, back_emf_constant=0.0398,
                 max_voltage=25.0)
ACTIVE = ("M7_8", "M9_10", "M11_12")


def base_simulation_gains() -> dict:
    """Leadscrew and gearhead gains of the Base Simulation (Lacy section 3.7, eqs. 2.45, 3.1).

    Returns
    -------
    dict
        ``max_velocity`` (m/s, the third-order move of 1.2 m in 3 s sampled as Appendix A),
        ``max_leadscrew_gain`` (m/rad), ``gearhead_gain``, and ``appendix_a_motor_speed``
        (rad/s the motor would need with Appendix A's listed gains).
    """
    _, dy, _ = third_order_response(np.arange(50) * 0.06, 3.0)
    vmax = float(1.2 * np.abs(dy).max())
    gls = max_leadscrew_gain(0.3, 0.02)
    return {"max_velocity": vmax, "max_leadscrew_gain": gls,
            "gearhead_gain": select_gearhead_gain(gls, 400.0, vmax),
            "appendix_a_motor_speed": vmax * 5.2 / 2.5266e-4}


def slew1_structure(convention: str = "thesis", *, stroke: bool = True) -> Structure:
    """The hanging double-octahedral bay at equilibrium with 46.0 N on N7–N9, actuators and
    (``stroke``) the prototype's stroke (:data:`trussfe.models.STROKE`) on its active members,
    which makes :func:`~trussfe.rigid.simulate.simulate` refuse a motion that leaves it."""
    s = double_octahedron(top_load=46.0, gravity=-9.81)
    lo, hi = models.STROKE if stroke else (math.nan, math.nan)
    return s.with_extensions(
        active_members=[replace(a, min_length=lo, max_length=hi)
                        for a in s.extensions["active_members"]],
        actuators=[Actuator(member=s.member_index(k), name=k, convention=convention,
                            require_self_locking=True, **PROTOTYPE) for k in ACTIVE])


def slew1_motion(structure: Structure | None = None, *, duration: float = 5.5,
                 ramp: float = 0.25, steps: int = 220) -> Motion:
    """Slewing Experiment 1 rebuilt from the text (Lacy sections 5.1, 5.5.1; see the module
    docstring): from the first slewed position (M7/8 1.2289 m, M9/10 and M11/12 1.1079 m) to
    the second (the reverse), every active member at constant velocity between smooth ramps
    (:func:`~trussfe.rigid.slew.constant_velocity_profile`), samples ``t = i T/steps``,
    i = 0…steps.  The lengths are linear in one profile, so M9/10 and M11/12 stay equal and
    the top plane turns about n̂1 only (section 5.5.1: "no rotation about the n̂2 axis").

    Examples
    --------
    >>> m = slew1_motion(steps=4)
    >>> m.length[[0, -1]].round(4).tolist()
    [[1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289]]
    """
    s = structure if structure is not None else double_octahedron()
    q0 = np.array(models.slew_lengths("slew1"))
    q1 = np.array(models.slew_lengths("slew2"))
    t = np.arange(steps + 1) * (duration / steps)
    y, dy, ddy = constant_velocity_profile(t, duration, ramp)
    d = q1 - q0
    return Motion(time=t, members=np.array([s.member_index(k) for k in ACTIVE]),
                  length=q0 + np.outer(y, d), velocity=np.outer(dy, d),
                  acceleration=np.outer(ddy, d),
                  source="Slewing Experiment 1 (rebuilt from Lacy sections 5.1, 5.5.1)")


def slew1(convention: str = "thesis", steps: int = 220) -> dict:
    """Actuator force on M8 and motor torque, current and voltage of M7 along Slewing
    Experiment 1 (synthetic motion, :func:`slew1_motion`; Lacy figs. 5.13–5.16).

    Returns
    -------
    dict
        ``M8_force_start``/``_end``/``_max``/``_min`` (N, positive compressing the leadscrew
        tube: the leadscrew pushes it outward), ``M7_voltage_max`` and ``_frictionless_max``
        (V), ``M7_voltage_start``/``_end`` (holding voltage before/after the motion),
        ``M7_torque_max``, ``M7_current_max``, ``M7_speed_max`` (rad/s), ``voltage_flag``
        (1.0 when the 25 V supply is exceeded), ``M7_velocity_max`` (m/s), ``voltage_ratio``
        (with/without friction peak voltage) and
        ``force_decreasing`` (fig. 5.13: "the compressive load is decreasing throughout the
        motion"; checked over the constant-velocity phase), and the ``flags``.
    """
    s = slew1_structure(convention)
    m = slew1_motion(s, steps=steps)
    r = simulate(s, m)
    j = list(m.members).index(s.member_index("M7_8"))
    f = r.actuator_force[:, j]
    # Constant-velocity phase (the ramps' acceleration spikes add inertia forces).
    cruise = (m.time >= 0.25) & (m.time <= m.time[-1] - 0.25)
    h = r.actuators["M7_8"]
    return {
        "M8_force_start": float(f[0]), "M8_force_end": float(f[-1]),
        "M8_force_max": float(f.max()), "M8_force_min": float(f.min()),
        "force_decreasing": bool(np.all(np.diff(f[cruise]) < 0.0)),
        "M7_velocity_max": float(np.abs(m.velocity[:, j]).max()),
        "M7_speed_max": float(h["max_motor_speed"]),
        "M7_torque_max": float(np.abs(h["motor_torque"]).max()),
        "M7_current_max": float(np.abs(h["motor_current"]).max()),
        "M7_voltage_max": float(h["max_motor_voltage"]),
        "M7_voltage_frictionless_max": float(np.abs(h["motor_voltage_frictionless"]).max()),
        "M7_voltage_start": float(h["motor_voltage"][0]),
        "M7_voltage_end": float(h["motor_voltage"][-1]),
        "voltage_ratio": float(h["max_motor_voltage"]
                               / np.abs(h["motor_voltage_frictionless"]).max()),
        "voltage_flag": 1.0 if any(x.startswith("voltage:") for x in h["flags"]) else 0.0,
        "flags": list(h["flags"]),
    }


def validation_actuator_gains() -> dict:
    """Quantities of :func:`base_simulation_gains` and (``motor.…``) of
    :func:`base_simulation_motor` for ``trussfe validate``."""
    out = base_simulation_gains()
    out.update({f"motor.{k}": v for k, v in base_simulation_motor().items()})
    return out


def m8_force_at_tilt(angle: float = -10.0) -> dict:
    """Actuator force on M8 at rest (N, compressing the tube) with the bay's top plane tilted
    ``angle`` degrees about n̂1 at the equilibrium height (the start of the −10° → +10° slew
    section 5.5.1 names), and the M7/8 length there, which lies beyond the prototype's stroke
    for ±10°."""
    from ..rigid.slew import TopPlaneInverse
    s = slew1_structure(stroke=False)
    q = TopPlaneInverse(s, [6, 7, 8], np.array([1.0, 0.0, 0.0])).lengths_along(
        np.radians([angle]))[0]
    r = simulate(double_octahedron(tuple(q), top_load=46.0, gravity=-9.81), actuators=False)
    return {"M8_force": float(r.actuator_force[0, 0]), "M7_8_length": float(q[0])}


def validation_slew1() -> dict:
    """Quantities of :func:`slew1` in both conventions (``thesis.M7_voltage_max`` …) and of
    :func:`m8_force_at_tilt` (``tilt_minus_10.M8_force``)."""
    out = {}
    for conv in ("thesis", "physical"):
        for k, v in slew1(conv).items():
            if isinstance(v, (int, float)):
                out[f"{conv}.{k}"] = float(v)
    for k, v in m8_force_at_tilt(-10.0).items():
        out[f"tilt_minus_10.{k}"] = v
    return out


def holding_voltage(force: float, act: Actuator | None = None) -> float:
    """Voltage to hold ``force`` at rest against the load, thesis convention (Lacy §5.7).

    Examples
    --------
    >>> round(holding_voltage(74.5), 3)
    3.336
    """
    a = act or Actuator(member=0, name="M7_8", convention="thesis", **PROTOTYPE)
    lead = 2 * math.pi * a.leadscrew_gain
    pd = math.pi * a.mean_diameter
    ratio = (lead + a.friction * pd) / (pd - a.friction * lead)
    return abs(force) * a.mean_diameter / 2 * ratio * a.resistance / a.torque_constant


__all__ = ["actuator_force_variants", "base_simulation_gains", "base_simulation_motor",
           "m8_force_at_tilt", "slew1", "slew1_motion", "slew1_structure", "holding_voltage",
           "validation_actuator_gains", "validation_slew1"]


#: Section 3.7's motor for the triangular truss: square thread, μ = 0.3, d_m = 0.02 m, the
#: self-locking limit G_ls = 0.003 m/rad, gearhead gain selected for 400 rad/s (eq. 3.1),
#: Appendix A's motor constants.
TRIANGLE_MOTOR = dict(leadscrew_gain=0.003, mean_diameter=0.02, thread="square",
                      thread_angle=0.0, friction=0.3, gearhead_gain=math.nan,
                      armature_inertia=6.76e-6, resistance=2.0, torque_constant=0.0398,
                      back_emf_constant=0.0398, max_speed=400.0)


def base_simulation_motor(convention: str = "thesis") -> dict:
    """Motor torque, voltage and current of the Base Simulation (Lacy section 3.7, figs.
    3.8–3.10): T = 3 s, 10 kg, 50 steps, thesis kinematics scheme.

    Section 3.7: "The motor torque approaches 0 N-m at approximately 0.5 seconds.  At this
    point, the follower is vertical ... the torque loading on the motor at this point is due
    to the angular acceleration of the motor armature."  The instant it names is the one at
    which the follower is vertical, so the torque is compared there.  The smallest torque
    itself falls later (0.60 s) inside a plateau of near-zero torque: while the load aids the
    motion, a leadscrew gain at the self-locking limit (eq. 2.45) takes no with-load torque
    (eq. 2.36), and only the armature's inertia torque is left, whose smallest value depends
    on the motion's acceleration, not on the geometry the thesis describes.

    Returns
    -------
    dict
        ``gearhead_gain`` (selected), ``min_torque_time`` (s, the sample of the smallest
        torque), ``follower_vertical_time`` (s, interpolated between the samples at which
        the follower's horizontal component changes sign), ``torque_at_vertical`` (|motor
        torque| interpolated at that instant, over its peak along the motion),
        ``leadscrew_torque_at_vertical`` (largest |leadscrew torque| of the two samples
        around that instant, over the peak motor torque), ``force_zero_time`` (s, the
        actuator force changes sign), ``final_torque`` and ``final_holding_torque`` (N·m:
        the torque at the end and that needed to hold the final static force) and their
        ratio ``final_over_holding``, ``max_voltage`` (V), ``max_speed`` (rad/s).
    """
    from .lacy_rigid import L2, L3MIN, triangular_truss
    from ..rigid.motion import third_order_motion

    s = triangular_truss(mass=10.0)
    k = s.member_index("active")
    s = s.with_extensions(actuators=[Actuator(member=k, name="active", convention=convention,
                                              **TRIANGLE_MOTOR)])
    m = third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], 3.0, 50)
    r = simulate(s, m, conventions=THESIS)
    h = r.actuators["active"]
    tq = np.abs(h["motor_torque"])
    f = r.actuator_force[:, 0]
    z = int(np.flatnonzero(np.sign(f[1:]) != np.sign(f[:-1]))[0])
    t = m.time
    # Linear interpolation of the sign change between samples z and z+1.
    tz = t[z] + (t[z + 1] - t[z]) * f[z] / (f[z] - f[z + 1])
    # The follower (O1 -> B) is vertical where its unit vector's x component changes sign.
    ux = r.kinematics.unit[:, s.member_index("follower"), 0]
    v = int(np.flatnonzero(np.sign(ux[1:]) != np.sign(ux[:-1]))[0])
    w = ux[v] / (ux[v] - ux[v + 1])
    tv = t[v] + (t[v + 1] - t[v]) * w
    peak = float(tq.max())
    a = replace(s.extensions["actuators"][0], gearhead_gain=h["gearhead_gain"])
    hold = motor_histories(a, r.static_actuator_force[-1:, 0], np.zeros(1), np.zeros(1),
                           r.static_actuator_force[-1:, 0])
    holding = float(abs(hold["motor_torque"][0]))
    return {"gearhead_gain": float(h["gearhead_gain"]),
            "min_torque_time": float(t[int(np.argmin(tq))]),
            "follower_vertical_time": float(tv),
            "torque_at_vertical": float(((1 - w) * tq[v] + w * tq[v + 1]) / peak),
            "leadscrew_torque_at_vertical":
                float(np.abs(h["leadscrew_torque"][v:v + 2]).max() / peak),
            "force_zero_time": float(tz),
            "final_torque": float(tq[-1]),
            "final_holding_torque": holding,
            "final_over_holding": float(tq[-1] / holding),
            "max_voltage": float(h["max_motor_voltage"]),
            "max_speed": float(h["max_motor_speed"])}


def actuator_force_variants(durations=(3.0, 5.0, 10.0), mass: float = 10.0) -> dict:
    """Actuator force on the leadscrew tube in the 3, 5 and 10 s maneuvers (Lacy fig. 3.7).

    Returns, per duration ``T``: ``force`` and ``static_force`` (N, positive compressing the
    tube), the motion-induced part ``dynamic = force − static_force``, and the active member's
    ``acceleration`` (m/s²), at the 50 samples of Appendix A (thesis scheme).
    """
    from ..rigid.motion import third_order_motion
    from .lacy_rigid import L2, L3MIN, triangular_truss

    out = {}
    for T in durations:
        s = triangular_truss(mass=mass)
        m = third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], T, 50)
        r = simulate(s, m, conventions=THESIS)
        f, fs = r.actuator_force[:, 0], r.static_actuator_force[:, 0]
        out[T] = {"force": f, "static_force": fs, "dynamic": f - fs,
                  "acceleration": m.acceleration[:, 0]}
    return out
