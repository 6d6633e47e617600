# SPDX-License-Identifier: MIT
"""Leadscrew, gearhead and motor data of an active member: the ``[actuators]`` table.

The data only; the actuator model that turns member forces and motions into motor torque,
current and voltage (Lacy section 2.9, eqs. 2.27–2.45) is :mod:`trussfe.rigid.actuator`.

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

import math
from dataclasses import dataclass

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
