# SPDX-License-Identifier: MIT
"""Member results of Slewing Experiment 1 (Lacy sections 5.7 and 5.8), reproduced.

The thesis reports, along its Slewing Experiment 1, the largest von Mises stresses of M6 (a
base-cell longeron), M8 (the leadscrew tube of M7/8) and M19 (a top-plane member), and the
largest compressions of M8 and M19–M21 (section 5.8); the parts of M6's stress (fig. 5.12)
are computed by :mod:`trussfe.studies.lacy_stress_components`.  The motion is :func:`trussfe.studies.lacy_actuators.slew1_motion` (the slew rebuilt from the
text inside the prototype's stroke), the bay the hanging one with its top-plane loads.

Two computations:

* **physical** — trussfe's rigid-body model as it is: the model's tube (Appendix D's area,
  ID 0.62 in), von Mises of the resultant moment (:mod:`trussfe.mechanics.stress`), the
  leadscrew tube cut at its cantilever connection, where it meets the active base
  (:mod:`trussfe.rigid.sections`: the tube is pinned at N5, the member's end node).
* **listing** — what Appendix C's code computes:

  - the code's tube, ID 0.63 in (0.016002 m; Table 5.1 prints 0.01600 m) for the area,
    section modulus and weight of every member (Appendix D's 0.62 in gives the tables);
  - the cantilever of M8 as the code writes it ("To find cantilever forces for Member 8"):
    the force on the leadscrew tube is ``forces(37:39)``, the pin force of member 7 at N4 —
    the active base's end, which carries most of the 3 kg base — and the tube's centre of
    gravity is reached from N4's acceleration, as if the tube hung from N4 (the code's own
    centre of gravity of M7/8 puts the tube at N5); and the second moment row uses the
    lever ``l2/2`` for the cantilever force, where ``l2`` is the length of member M2
    (0.889 m, set earlier in the listing) — in Appendix A's triangle code ``l2`` was the
    leadscrew tube's length — instead of ``ls/2`` (0.127 m); it also takes α about b̂1 in
    that row.  :func:`listing_cantilever` evaluates the code's five equations, in the code's
    frame of M7/8 (``c7``), and the code's per-axis von Mises stress (eqs. 4.75/4.76).

Neither slip is a modelling convention of the solvers (:mod:`trussfe.mechanics.conventions`):
they belong to the listing alone, so they live here.

The load is the stated 46.0 N per top node and, as a variant, the 44.498 N that reproduces
Tables 5.2–5.4 (:data:`trussfe.models.TABLE_LOAD`).
"""
from __future__ import annotations

import numpy as np

from .. import models
from ..mechanics.stress import von_mises
from ..model.sections import Section
from ..model.structure import Structure
from ..rigid.simulate import SimulationResult, simulate
from .lacy_actuators import slew1_motion
from .lacy_rigid import double_octahedron

#: Appendix C's tube: OD 0.75 in, ID 0.63 in (``idls``, ``idf``).
LISTING_TUBE = Section.tube("tube", 0.75 * models.materials.INCH, 0.63 * models.materials.INCH)
#: Appendix C's ``l2``: the length of member M2 (N1–N6), m — the lever of the cantilever
#: force in the code's second moment equation of the leadscrew tube.
LISTING_L2 = models.octahedral.LONGERON
#: Appendix C's leadscrew tube length ``ls``, m.
TUBE_LENGTH = models.octahedral.ACTIVE_TUBE_LENGTH

def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def listing_frame(structure: Structure, coords: np.ndarray) -> np.ndarray:
    """Appendix C's direction-cosine matrix ``c7`` of M7/8 at every step, (nt, 3, 3), rows
    b̂1, b̂2, b̂3: b̂3 = unit(N5 − N4), b̂1 = unit(unit(N6 − N4) × b̂3), b̂2 = b̂3 × b̂1
    (``u73``, ``u71 = cross(junk, u73)``, ``u72``)."""
    x = lambda n: coords[:, structure.node_index(n)]
    b3 = _unit(x("N5") - x("N4"))
    b1 = _unit(np.cross(_unit(x("N6") - x("N4")), b3))
    return np.stack([b1, np.cross(b3, b1), b3], axis=1)


def _per_axis(structure: Structure, k: int, N, V1, V2, M1, M2):
    """Per-axis stresses (eqs. 4.75/4.76) of member ``k``'s section."""
    return von_mises(N, V1, V2, M1, M2, structure.area[k], structure.Iy[k], structure.Iy[k],
                     structure.c[k], structure.c[k], True, convention="lacy-per-axis")


def listing_cantilever(r: SimulationResult, *, lever: float = LISTING_L2 / 2,
                       tube_length: float = TUBE_LENGTH) -> dict:
    """M8's cantilever forces and stress as Appendix C's code computes them, every step.

    The code's five equations for the leadscrew tube of M7/8 (unknowns: the cantilever force
    F in n̂ axes and the moments M1, M2 about b̂1, b̂2), with f the pin force at N4, a the
    tube's centre-of-gravity acceleration reached from N4, m and I the tube's mass and
    moment of inertia, W its weight::

        F = m a − f − W
        (ls/2) b̂2·F + M1 = I α1 + (ls/2) b̂2·f
        −lever b̂1·F − M2 = I α1 − (ls/2) b̂1·f        (the code: lever = l2/2)

    ``lever = ls/2`` gives the tube's own moment equation (with α1 where α2 belongs; the
    motion is too slow for it to matter).

    Returns
    -------
    dict
        ``axial`` (b̂3·F, N; negative = compression, the code's ``actfor8``), ``M1``, ``M2``
        (N·m) and ``von_mises`` (Pa, per-axis, the larger of ``vmst8a``/``vmst8b``), each
        (nt,).
    """
    s = r.structure
    kin = r.kinematics
    k = s.member_index("M7_8")
    n4 = s.node_index("N4")
    c = listing_frame(s, kin.coords)
    b1, b2, b3 = c[:, 0], c[:, 1], c[:, 2]
    dot = lambda u, v: np.einsum("ti,ti->t", u, v)
    w1, w2 = dot(b1, kin.omega[:, k]), dot(b2, kin.omega[:, k])
    a1, a2 = dot(b1, kin.alpha[:, k]), dot(b2, kin.alpha[:, k])
    half = tube_length / 2
    A4 = kin.acceleration[:, n4]
    acg = (b1 * (dot(b1, A4) + a2 * half)[:, None] + b2 * (dot(b2, A4) - a1 * half)[:, None]
           + b3 * (dot(b3, A4) - (w1 ** 2 + w2 ** 2) * half)[:, None])
    sec = s.sections[k]
    mass = s.materials[k].density * sec.area * tube_length
    od, idd = sec.outer_diameter, sec.inner_diameter
    inertia = mass / 48 * (3 * od ** 2 + 3 * idd ** 2 + 4 * tube_length ** 2)   # iglsb1
    f = r.forces.end_force[:, k, 0]                              # forces(37:39): pin N4
    g = np.zeros(3)
    g[:len(s.gravity)] = s.gravity
    F = mass * acg - f - mass * g
    M1 = inertia * a1 + half * dot(b2, f - F)
    M2 = -inertia * a1 + half * dot(b1, f) - lever * dot(b1, F)
    st = _per_axis(s, k, dot(b3, F), dot(b1, F), dot(b2, F), M1, M2)
    return {"axial": dot(b3, F), "M1": M1, "M2": M2, "von_mises": st.s2}


def slew_bay(top_load: float = models.STATED_LOAD, section: Section | None = None) -> Structure:
    """The hanging bay of the slew (gravity, ``top_load`` on N7–N9) with ``section`` on every
    member (``None``: the model's tube)."""
    s = double_octahedron(top_load=top_load, gravity=-9.81)
    return s if section is None else s.with_sections([section] * s.n_members)


def _at(values: np.ndarray, time: np.ndarray) -> dict:
    i = int(np.argmax(values))
    return {"max": float(values[i]), "time": float(time[i])}


def members_along_slew(top_load: float = models.STATED_LOAD, *, listing: bool = False,
                       steps: int = 220) -> dict:
    """Section 5.7/5.8 member results along Slewing Experiment 1.

    Parameters
    ----------
    top_load : float
        Vertical load on each of N7–N9, N.
    listing : bool
        Appendix C's computation (its tube, its M8 cantilever; see the module docstring)
        instead of trussfe's physical one.

    Returns
    -------
    dict
        ``M8``: ``{"max", "time"}`` of the leadscrew tube's largest von Mises stress (Pa, s;
        physical: over its seven sections, the cantilever included; listing: at the
        cantilever as coded); physical only: ``M6``/``M19``, of the midpoint von Mises
        stress; ``compression``: largest midpoint compression of ``M19``–``M21`` and the
        largest actuator force on ``M8`` (N).
    """
    s = slew_bay(top_load, LISTING_TUBE if listing else None)
    m = slew1_motion(s, steps=steps)
    r = simulate(s, m, n_sections=1)
    t = r.time
    out: dict = {}
    if listing:
        out["M8"] = _at(listing_cantilever(r)["von_mises"], t)
    else:
        vm = r.stresses.von_mises[:, :, 0]
        out["M6"] = _at(vm[:, s.member_index("M6")], t)
        out["M19"] = _at(vm[:, s.member_index("M19")], t)
        tube = simulate(s, m, n_sections=7, actuators=False)
        out["M8"] = _at(tube.stresses.von_mises[:, s.member_index("M7_8")].max(axis=1), t)
    T = r.sections.tension[:, :, 0]
    out["compression"] = {k: float(-T[:, s.member_index(k)].min())
                          for k in ("M19", "M20", "M21")}
    out["compression"]["M8"] = float(r.actuator_force.max())
    return out


def m8_cantilever_steps(top_load: float = models.STATED_LOAD, steps: int = 220) -> dict:
    """M8's largest stress from trussfe's cantilever to Appendix C's, one change at a time
    (Pa, with the time of the maximum): ``physical`` (the tube at N5, its own pin force,
    resultant moment, ID 0.62 in); ``pin_N4`` (the code's pin force and acceleration at N4,
    its lever ls/2, ID 0.62 in); ``lever_l2`` (and the code's l2/2); ``listing`` (and the
    code's ID 0.63 in: Appendix C as written)."""
    out = {"physical": members_along_slew(top_load, steps=steps)["M8"]}
    for key, section, lever in (("pin_N4", None, TUBE_LENGTH / 2),
                                ("lever_l2", None, LISTING_L2 / 2),
                                ("listing", LISTING_TUBE, LISTING_L2 / 2)):
        s = slew_bay(top_load, section)
        r = simulate(s, slew1_motion(s, steps=steps), n_sections=1)
        out[key] = _at(listing_cantilever(r, lever=lever)["von_mises"], r.time)
    return out


def validation_slew_members() -> dict:
    """Quantities for ``trussfe validate`` (case lacy_slew1_members): ``physical.…`` and
    ``listing.…`` of :func:`members_along_slew` at 46.0 N, ``listing_44_498.…`` at the
    tables' 44.498 N, and ``m8_steps.…`` of :func:`m8_cantilever_steps`."""
    return {"physical": members_along_slew(),
            "listing": members_along_slew(listing=True),
            "listing_44_498": members_along_slew(models.TABLE_LOAD, listing=True),
            "m8_steps": m8_cantilever_steps()}


__all__ = ["LISTING_L2", "LISTING_TUBE", "TUBE_LENGTH", "listing_cantilever", "listing_frame",
           "m8_cantilever_steps", "members_along_slew", "slew_bay", "validation_slew_members"]
