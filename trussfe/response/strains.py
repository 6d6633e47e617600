# SPDX-License-Identifier: MIT
"""Member strains along a motion: gauge readings and Lacy's zeroing procedure (section 5.6).

**Gauges.**  A strain gauge on a tube of outer radius c at the fibre r (⊥ e, |r| = c) reads

.. math:: \\varepsilon(r) = \\frac{T}{EA} - \\frac{(e \\times M)\\cdot r}{E I},

with T the tension and M the section moment in Lacy's sign (moment the start side exerts on
the end side, :mod:`trussfe.rigid.sections`).  Three gauges at 120° average the bending part
away exactly (Σ cos(φ + 2πi/3) = 0), so their mean is the axial strain T/(EA) — what Lacy
compares (Table 5.5, figs. 5.7–5.8).

**Zeroing (Lacy section 5.6).**  The gauges only measure changes; they were zeroed at the
equilibrium position under gravity with no external load, then the 46.0 N loads were applied
and the truss moved.  The thesis made its simulation comparable as follows:

1. ε_full(t): simulation with gravity, loads and motion;
2. ε_nog(t): the same without gravity;
3. ε_grav(t) = ε_full(t) − ε_nog(t): the gravity strain along the motion;
4. ε_grav,eq: the gravity strain at the equilibrium position at rest (the gauges' zero);
5. ε_zeroed(t) = ε_nog(t) + [ε_grav(t) − ε_grav,eq].

By linearity ε_zeroed = ε_full − ε_grav,eq: exactly what a gauge zeroed at equilibrium
under gravity reads (checked by :func:`zeroed_strain`).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.structure import Structure
from ..rigid.kinematics import Kinematics, compute_kinematics
from ..rigid.motion import rest_motion
from ..mechanics.geometry import transverse_frames
from ..rigid.sections import SectionForces
from .along_motion import ElasticResponse, elastic_along_motion


def gauge_strains(structure: Structure, sections: SectionForces, member: int, section: int,
                  angles_deg=(0.0, 120.0, 240.0)) -> np.ndarray:
    """Strains of gauges on the outer fibre of one member section (module notes).

    Parameters
    ----------
    structure : Structure
    sections : SectionForces
        Section forces (rigid model's or :class:`ElasticResponse.sections`).
    member, section : int
        Member index and section index (into ``sections.position``).
    angles_deg : sequence of float
        Gauge angles about the member axis from its frame vector b1
        (:func:`trussfe.mechanics.geometry.transverse_frames`).

    Returns
    -------
    ndarray, shape (nt, n_gauges)
        Strain of every gauge at every step.
    """
    T = sections.tension[:, member, section]
    M = sections.moment[:, member, section]                     # (t, 3)
    e = sections.unit[:, member]
    b1, b2 = transverse_frames(e)
    phi = np.radians(np.asarray(angles_deg, dtype=float))
    c = structure.c[member]
    r = c * (np.cos(phi)[None, :, None] * b1[:, None] + np.sin(phi)[None, :, None] * b2[:, None])
    E, A = structure.E[member], structure.area[member]
    inertia = 0.5 * (structure.Iy[member] + structure.Iz[member])
    bend = -np.einsum("tgi,tgi->tg", np.cross(e, M)[:, None, :].repeat(phi.size, 1), r)
    return T[:, None] / (E * A) + bend / (E * inertia)


@dataclass
class ZeroedStrain:
    """Lacy's zeroing procedure (section 5.6) for one member; strains, arrays (nt,).

    Attributes
    ----------
    full, no_gravity, gravity : ndarray
        ε_full, ε_nog and ε_grav = ε_full − ε_nog along the motion.
    gravity_equilibrium : float
        ε_grav,eq: gravity strain at the equilibrium position at rest.
    zeroed : ndarray
        ε_nog + (ε_grav − ε_grav,eq): the history comparable with the gauges.
    """

    time: np.ndarray
    full: np.ndarray
    no_gravity: np.ndarray
    gravity: np.ndarray
    gravity_equilibrium: float
    zeroed: np.ndarray


def zeroed_strain(structure: Structure, kin: Kinematics, equilibrium: Structure, member: int,
                  *, subdivisions: int = 6) -> ZeroedStrain:
    """Strain history of one member's tube midpoint, zeroed as Lacy section 5.6.

    Parameters
    ----------
    structure : Structure
        The loaded truss with gravity (Lacy: 46.0 N on N7–N9, hanging).
    kin : Kinematics
        Kinematics of the maneuver.
    equilibrium : Structure
        The truss at the zero position (Lacy: the equilibrium position), with gravity; its
        loads are ignored.
    member : int
        Member index (Lacy: M6).
    subdivisions : int
        Elements per member of the FE model.

    Returns
    -------
    ZeroedStrain
    """
    full = elastic_along_motion(structure, kin, subdivisions=subdivisions).strain[:, member]
    nog = elastic_along_motion(structure, kin, subdivisions=subdivisions,
                               gravity=False).strain[:, member]
    keq = compute_kinematics(equilibrium, rest_motion(equilibrium)).at_rest()
    geq = float(elastic_along_motion(equilibrium, keq, subdivisions=subdivisions,
                                     loads=False).strain[0, member])
    grav = full - nog
    return ZeroedStrain(time=kin.time, full=full, no_gravity=nog, gravity=grav,
                        gravity_equilibrium=geq, zeroed=nog + (grav - geq))


def static_strain(structure: Structure, member: int, *, gravity: bool = False,
                  subdivisions: int = 6) -> float:
    """Axial strain at a member's tube midpoint of the truss at rest (FE, pinned-beam).

    ``gravity=False`` with the external loads only is Lacy's Table 5.5 experiment (gauges
    zeroed with no external load at each position, then the load applied).
    """
    kin = compute_kinematics(structure, rest_motion(structure)).at_rest()
    r: ElasticResponse = elastic_along_motion(structure, kin, subdivisions=subdivisions,
                                              gravity=gravity)
    return float(r.strain[0, member])
