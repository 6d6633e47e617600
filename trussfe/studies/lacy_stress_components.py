# SPDX-License-Identifier: MIT
"""The components of stress in M6 along Slewing Experiment 1 (Lacy section 5.7, Fig. 5.12).

Fig. 5.12 is not in the text; section 5.7 states its maxima: tensile stress 8.4e5 Pa, bending
stress "in the b̂2 direction" 4.5e5 Pa, "in the b̂1 direction" 3.95e5 Pa, largest shear stress
230.8 Pa (b̂2), and M6's largest von Mises stress 1.294e6 Pa (Fig. 5.9).  The thesis combines
the components per axis (Lacy eqs. 4.75/4.76, convention ``"lacy-per-axis"`` of
:mod:`trussfe.mechanics.stress`): each bending component at its own extreme fibre, with the
shear of the same axis.  A round tube's extreme fibre carries the *resultant* bending stress
(convention ``"combined"``).

:func:`fig_5_12_components` gives both sides in the same terms:

* the thesis' stated components combined both ways — the per-axis form gives its von Mises
  stress from its own numbers, the resultant does not;
* trussfe's components at M6's midpoint (the thesis' stress point for the spatial truss)
  along the shipped synthetic Slewing Experiment 1
  (:func:`trussfe.studies.lacy_actuators.slew1_motion`), in the thesis' body-fixed frame
  (Lacy eqs. 4.2–4.4: b̂1 normal to the plane of the member and the axis it hinges about),
  beside the resultant and the von Mises stress of both conventions, with eqs. 4.75/4.76
  evaluated here from the components as a check of the convention's implementation.
"""
from __future__ import annotations

import numpy as np

from ..mechanics.stress import THIN_TUBE_SHEAR_COEFFICIENT, von_mises
from ..rigid.sections import local_components, section_stresses
from ..rigid.simulate import simulate
from .lacy_actuators import slew1_motion, slew1_structure

#: Lacy section 5.7: maxima of the components of stress in M6 (Fig. 5.12) and its largest
#: von Mises stress (Fig. 5.9), Pa.
FIG_5_12 = {"tension": 8.4e5, "bending_b2": 4.5e5, "bending_b1": 3.95e5, "shear_b2": 230.8,
            "von_mises": 1.294e6}


def thesis_components_combined() -> dict:
    """The thesis' stated M6 maxima combined into a von Mises stress both ways (Pa).

    On a unit section (A = I = c = 1) the stresses are the section forces: N = σ_T,
    M about b̂1 and b̂2 = the bending stresses, V = τ/κ.  Taking the maxima together assumes
    they occur at one instant, as the thesis' own sum suggests: σ_T + σ_M,b̂2 = 1.29e6 Pa.

    Returns
    -------
    dict
        ``per_axis`` (eqs. 4.75/4.76) and ``combined`` (resultant bending) von Mises stress.
    """
    one = np.ones(1)
    kappa = THIN_TUBE_SHEAR_COEFFICIENT
    args = (one * FIG_5_12["tension"], one * 0.0, one * FIG_5_12["shear_b2"] / kappa,
            one * FIG_5_12["bending_b1"], one * FIG_5_12["bending_b2"], 1.0, 1.0, 1.0, 1.0, 1.0)
    return {conv.replace("lacy-per-axis", "per_axis"):
            float(von_mises(*args, True, convention=conv).von_mises[0])
            for conv in ("lacy-per-axis", "combined")}


def hinge_axis_frames(unit: np.ndarray, axis: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Lacy's body-fixed member frame, eqs. 4.2–4.4: b̂3 along the member, b̂1 = x̂ × b̂3
    normalised, normal to the plane of the member and the axis x̂ it hinges about, and
    b̂2 = b̂3 × b̂1, in that plane.

    Parameters
    ----------
    unit : ndarray, shape (..., 3)
        Member unit vectors b̂3.
    axis : ndarray, shape (..., 3)
        The hinge axis x̂ (any length, not parallel to the member).

    Returns
    -------
    b1, b2 : ndarray, shape (..., 3)

    Examples
    --------
    A vertical member hinging about the x axis bends about b̂1 = −ŷ and b̂2 = x̂:

    >>> b1, b2 = hinge_axis_frames(np.array([0.0, 0.0, 1.0]), np.array([2.0, 0.0, 0.0]))
    >>> (b1 + 0.0).tolist(), (b2 + 0.0).tolist()
    ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0])
    """
    b1 = np.cross(axis, unit)
    b1 = b1 / np.linalg.norm(b1, axis=-1, keepdims=True)
    return b1, np.cross(unit, b1)


#: The axis each member of Fig. 5.12 hinges about (Lacy section 4.2.1): a base→mid longeron
#: turns with its midplane node about that node's base edge (N5 about N2–N3 for M6).
HINGE_AXES = {"M6": ("N2", "N3")}


def fig_5_12_components(steps: int = 220) -> dict:
    """Fig. 5.12's components for the thesis' numbers and for trussfe's M6 along the slew.

    Returns
    -------
    dict
        ``thesis.per_axis`` / ``thesis.combined`` (:func:`thesis_components_combined`);
        ``ours.*``: maxima over the motion at M6's midpoint, Pa, in the thesis' hinge-axis
        frame (:func:`hinge_axis_frames`, Lacy eqs. 4.2–4.4) — ``tension`` (σ_T = N/A),
        ``bending_b1``, ``bending_b2`` (|M·b̂i| c / I), ``bending_resultant`` (|M| c / I),
        ``shear_b1``, ``shear_b2`` (κ |V·b̂i| / A), ``von_mises_per_axis`` (eqs. 4.75/4.76 in
        that frame, convention ``"lacy-per-axis"``), ``von_mises_combined`` (resultant
        bending, :func:`trussfe.rigid.sections.section_stresses`), and
        ``eq_4_75_4_76_residual``: the largest difference over the motion between the
        convention and eqs. 4.75/4.76 written out here, over the largest value;
        ``transverse.*``: the same bending components in the frame b̂1 = e × ẑ of
        :func:`trussfe.rigid.sections.local_components`, for comparison.
    """
    s = slew1_structure()
    r = simulate(s, slew1_motion(s, steps=steps))
    i = s.member_index("M6")
    sf = r.sections
    k = int(np.argmin(np.abs(sf.position[i] - 0.5 * sf.position[i, -1])))      # midpoint
    A, I, c = s.area[i], s.Iy[i], s.c[i]
    kappa = THIN_TUBE_SHEAR_COEFFICIENT
    start, end = (s.node_index(n) for n in HINGE_AXES["M6"])
    xyz = r.kinematics.coords
    b1, b2 = hinge_axis_frames(sf.unit[:, i], xyz[:, end] - xyz[:, start])
    M, V = sf.moment[:, i, k], sf.shear[:, i, k]
    m1, m2 = np.einsum("tj,tj->t", M, b1), np.einsum("tj,tj->t", M, b2)
    v1, v2 = np.einsum("tj,tj->t", V, b1), np.einsum("tj,tj->t", V, b2)
    N = sf.tension[:, i, k]
    per_axis = von_mises(N, v1, v2, m1, m2, A, I, I, c, c, True,
                         convention="lacy-per-axis").von_mises
    sig_t, bend = N / A, np.abs(np.stack([m1, m2], axis=1)) * c / I
    tau = kappa * np.abs(np.stack([v1, v2], axis=1)) / A
    # eqs. 4.75/4.76 written out: each bending component with its own shear; the neutral axis
    eq = np.maximum.reduce([np.sqrt((np.abs(sig_t) + bend[:, 0]) ** 2 + 3 * tau[:, 0] ** 2),
                            np.sqrt((np.abs(sig_t) + bend[:, 1]) ** 2 + 3 * tau[:, 1] ** 2),
                            np.sqrt(sig_t ** 2 + 3 * (tau ** 2).sum(axis=1))])
    combined = section_stresses(s, sf, convention="combined").von_mises[:, i, k]
    _, Mt = local_components(sf)
    bend_t = np.abs(Mt[:, i, k]) * c / I
    return {"thesis": thesis_components_combined(),
            "ours": {"tension": float(sig_t.max()),
                     "bending_b1": float(bend[:, 0].max()),
                     "bending_b2": float(bend[:, 1].max()),
                     "bending_resultant": float(np.hypot(bend[:, 0], bend[:, 1]).max()),
                     "shear_b1": float(tau[:, 0].max()), "shear_b2": float(tau[:, 1].max()),
                     "von_mises_per_axis": float(per_axis.max()),
                     "von_mises_combined": float(combined.max()),
                     "eq_4_75_4_76_residual": float(np.abs(per_axis - eq).max()
                                                    / per_axis.max())},
            "transverse": {"bending_b1": float(bend_t[:, 0].max()),
                           "bending_b2": float(bend_t[:, 1].max())}}


__all__ = ["FIG_5_12", "HINGE_AXES", "fig_5_12_components", "hinge_axis_frames",
           "thesis_components_combined"]
