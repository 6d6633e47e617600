# SPDX-License-Identifier: MIT
"""Reproductions of Lacy's published numbers with the rigid-body model (validation suite).

Each function returns a plain dict of quantities (paths used by
``validation/cases/rigid_*.toml``).  The triangular truss is Lacy's Fig. 2.1 with the data of
Table 3.1 and Appendix A: O2 = (0, 0) carries the active member, O1 = (2, 0) the 2 m follower;
the active member is 0.5 m (active base at minimum) + x + 2.0 m (leadscrew tube) long.
"""
from __future__ import annotations

import math

import numpy as np

from ..model.sections import Material, Section
from ..model.structure import Structure, build_structure
from .active import ActiveMember
from .motion import rest_motion, third_order_motion
from .simulate import simulate

#: Lacy Table 3.1 / Appendix A data.
L1, L2, L3MIN, L3MAX, L4 = 2.0, 2.0, 0.5, 2.1, 2.0
OD, ID = 0.0254, 0.022225
ALUMINIUM = Material(name="aluminium", E=71.0e9, G=26.2e9, density=2711.5,
                     yield_strength=math.nan)
TUBE = Section.tube("tube", OD, ID)


def triangular_truss(x: float = 0.0, mass: float = 10.0, *, gravity: bool = True,
                     load: float = 0.0) -> Structure:
    """Lacy's triangular truss with the active member extended by ``x`` (m).

    Parameters
    ----------
    x : float
        Actuator extension; the active member is L3min + x + L2 long.
    mass : float
        Lumped mass at B, kg.
    gravity : bool
        Downward gravity 9.81 m/s² (the physical sense; Appendix A's ``g = -9.81`` in
        equations written for +g would make it act upward).
    load : float
        Vertical external force at B, N (Table 3.2: −98.1 N without gravity).

    Examples
    --------
    >>> s = triangular_truss()
    >>> np.round(s.coords[2], 4)          # Appendix B node 3
    array([1.5625, 1.9516])
    """
    La = L3MIN + x + L2
    phi = math.acos((L1 ** 2 + L4 ** 2 - La ** 2) / (2 * L4 * L1))   # Lacy eq. 2.1
    B = [L4 - L1 * math.cos(phi), L1 * math.sin(phi)]
    s = build_structure([[0.0, 0.0], [L4, 0.0], B], [[1, 2], [0, 2]], section=TUBE,
                        material=ALUMINIUM, supports={0: "xy", 1: "xy"},
                        masses={2: mass} if mass else None,
                        loads={2: [0.0, load]} if load else None,
                        gravity=[0.0, -9.81] if gravity else None,
                        node_ids=["O2", "O1", "B"], member_ids=["follower", "active"],
                        name="triangular truss (Lacy Fig. 2.1)")
    s.extensions["active_members"] = [ActiveMember(
        member=1, base_mass=2.4, base_length=L3MAX, base_cg=L3MAX / 2,
        base_inertia=2.4 * L3MAX ** 2 / 3, tube_length=L2, min_length=L3MIN + L2,
        max_length=L3MAX + L2)]
    return s


def static_reactions() -> dict:
    """Static triangular truss: Table 3.2 (98.1 N at B, no gravity) and the text after it
    (member weight and 10 kg lumped mass under gravity)."""
    out = {}
    for key, s in (("table_3_2", triangular_truss(mass=0.0, gravity=False, load=-98.1)),
                   ("with_weight", triangular_truss())):
        r = simulate(s)
        react = r.forces.reactions[0]
        out[key] = {"O2": react[0].tolist(), "O1": react[1].tolist(),
                    "tension": {"follower": float(r.forces.tension_end[0, 0]),
                                "active": float(r.forces.tension_end[0, 1])},
                    "von_mises": {"follower": float(r.stresses.von_mises[0, 0].max()),
                                  "active": float(r.stresses.von_mises[0, 1].max())}}
    return out


def base_simulation(duration: float = 3.0, mass: float = 10.0, steps: int = 50,
                    scheme: str = "thesis", x_end: float = 1.2) -> dict:
    """The Base Simulation of Lacy section 3.3 and its variants (sections 3.4–3.5, Table 3.3).

    ``scheme="thesis"`` reproduces Appendix A (backward-difference angle rates, whole-length
    section inertia, 50 steps at t = (i−1)·dt); ``"exact"`` gives the exact kinematics.
    Lacy labels step i (1-based) with the time i·dt, one step after the instant at which its
    state is evaluated; ``thesis_time`` reports that label.
    """
    s = triangular_truss(mass=mass)
    m = third_order_motion(s, [L3MIN + L2], [L3MIN + x_end + L2], duration, steps)
    thesis = scheme == "thesis"
    r = simulate(s, m, scheme=scheme, full_length_inertia=thesis)
    dt = duration / steps
    fol = r.member_summary(0, section=3)       # motion-induced at the follower midpoint
    tube = r.member_summary(1)
    for d in (fol, tube):
        d["thesis_time"] = d["time"] + dt
        d["motion_induced_thesis_time"] = d["motion_induced_time"] + dt
    return {
        "max_actuator_velocity": float(np.abs(m.velocity).max()),
        "follower": fol, "leadscrew_tube": tube,
        "buckling": {"allowable": r.buckling.allowable.tolist(),
                     "follower_max_compression": float(r.buckling.max_compression[0]),
                     "tube_max_compression": float(r.buckling.max_compression[1])},
        "actuator_force": {"max": float(r.actuator_force.max()),
                           "min": float(r.actuator_force.min())},
    }
