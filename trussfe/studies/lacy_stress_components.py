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
  (:func:`trussfe.studies.lacy_actuators.slew1_motion`), in Lacy's member frame (b̂1, b̂2)
  of :func:`trussfe.mechanics.geometry.transverse_frames`, beside the resultant and the von
  Mises stress of both conventions, with eqs. 4.75/4.76 evaluated here from the components as
  a check of the convention's implementation.
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


def fig_5_12_components(steps: int = 220) -> dict:
    """Fig. 5.12's components for the thesis' numbers and for trussfe's M6 along the slew.

    Returns
    -------
    dict
        ``thesis.per_axis`` / ``thesis.combined`` (:func:`thesis_components_combined`);
        ``ours.*``: maxima over the motion at M6's midpoint, Pa — ``tension`` (σ_T = N/A),
        ``bending_b1``, ``bending_b2`` (|M·b̂i| c / I), ``bending_resultant`` (|M| c / I),
        ``shear_b1``, ``shear_b2`` (κ |V·b̂i| / A), ``von_mises_per_axis`` and
        ``von_mises_combined`` (:func:`trussfe.rigid.sections.section_stresses`), and
        ``eq_4_75_4_76_residual``: the largest difference, over every instant, between the
        per-axis convention and eqs. 4.75/4.76 evaluated here from the b̂1/b̂2 components,
        over the largest von Mises stress.
    """
    s = slew1_structure()
    r = simulate(s, slew1_motion(s, steps=steps))
    i = s.member_index("M6")
    sf = r.sections
    k = int(np.argmin(np.abs(sf.position[i] - 0.5 * sf.position[i, -1])))      # midpoint
    V, M = local_components(sf)
    A, I, c = s.area[i], s.Iy[i], s.c[i]
    kappa = THIN_TUBE_SHEAR_COEFFICIENT
    sig_t = sf.tension[:, i, k] / A
    bend = np.abs(M[:, i, k]) * c / I                     # (t, 2): about b̂1, b̂2
    tau = kappa * np.abs(V[:, i, k]) / A
    vm = {conv: section_stresses(s, sf, convention=conv).von_mises[:, i, k]
          for conv in ("lacy-per-axis", "combined")}
    # eqs. 4.75/4.76 written out: S1max, S2max at the two fibres; the neutral axis sqrt(σ² + 3τ²)
    eq = np.maximum.reduce([np.sqrt((np.abs(sig_t) + bend[:, 0]) ** 2 + 3 * tau[:, 0] ** 2),
                            np.sqrt((np.abs(sig_t) + bend[:, 1]) ** 2 + 3 * tau[:, 1] ** 2),
                            np.sqrt(sig_t ** 2 + 3 * (tau ** 2).sum(axis=1))])
    peak = float(vm["lacy-per-axis"].max())
    return {"thesis": thesis_components_combined(),
            "ours": {"tension": float(sig_t.max()),
                     "bending_b1": float(bend[:, 0].max()),
                     "bending_b2": float(bend[:, 1].max()),
                     "bending_resultant": float(np.hypot(bend[:, 0], bend[:, 1]).max()),
                     "shear_b1": float(tau[:, 0].max()), "shear_b2": float(tau[:, 1].max()),
                     "von_mises_per_axis": peak,
                     "von_mises_combined": float(vm["combined"].max()),
                     "eq_4_75_4_76_residual": float(np.abs(vm["lacy-per-axis"] - eq).max()
                                                    / peak)}}


__all__ = ["FIG_5_12", "fig_5_12_components", "thesis_components_combined"]
