# SPDX-License-Identifier: MIT
"""Internal forces and von Mises stresses along the members (Lacy sections 2.6–2.7, 4.8–4.9).

A member is cut at ``k`` equidistant sections along its tube (the whole member if passive,
the leadscrew tube if active), measured from the member's end node: ``u_j = j L_t/(k−1)``,
j = 0…k−1 (Lacy cuts the follower and the leadscrew tube from point B at seven points).  The
piece between the cut and the end node, of mass ``m u/L_t`` and centre of gravity at u/2 from
the end node, obeys (Lacy eqs. 2.16–2.18, 4.68–4.74)

.. math::

   N &= m_s (a_s - g) - F_b, \\\\
   M &= \\tfrac{u}{2} e \\times m_s (a_s - g) + I_s \\alpha - u\\, e \\times F_b ,

with N and M the force and moment the rest of the member exerts on the piece at the cut.
Tension T = −N·e, shear V = N − (N·e)e (two components in 3-D), bending moment M.

Stresses (Lacy eqs. 2.19–2.25, 4.75–4.76) of a thin round tube: σ_T = T/A,
τ = 2|V|/A, σ_M = |M| c/I, and von Mises at the neutral axis S1 = √(σ_T² + 3τ²) and at the
outer fibre S2 = |σ_T| + σ_M; the member's stress is the larger.  Lacy's code uses
√(σ_T² + τ²) at S1 (and 3V/2A for the static shear); S2 governs every published number, so the
difference does not show there.

At the cut u = L_t of an active member the piece is the whole leadscrew tube and N is the
force the active base exerts on it through the cantilever connection: ``N·e`` is the
**actuator force** (positive pushing the tube outward, Lacy ``actfor``), and M the cantilever
moment (the leadscrew-tube sub-analysis, eqs. 4.63–4.67).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.structure import Structure
from .forces import MemberBodies, NodalForces
from .kinematics import Kinematics, pad3


@dataclass
class SectionForces:
    """Internal forces at the sections, arrays (nt, m, k).

    Attributes
    ----------
    position : ndarray, shape (m, k)
        Distance of each section from the member's end node, m.
    tension : ndarray
        Axial force, N (positive in tension).
    shear : ndarray, shape (nt, m, k, 3)
        Shear force vector (perpendicular to the member), N.
    moment : ndarray, shape (nt, m, k, 3)
        Bending moment vector, N·m (z component only in 2-D).
    cut_force : ndarray, shape (nt, m, k, 3)
        Force N on the piece at the cut.
    """

    position: np.ndarray
    tension: np.ndarray
    shear: np.ndarray
    moment: np.ndarray
    cut_force: np.ndarray

    @property
    def shear_magnitude(self) -> np.ndarray:
        """|V|, (nt, m, k)."""
        return np.linalg.norm(self.shear, axis=-1)

    @property
    def moment_magnitude(self) -> np.ndarray:
        """|M|, (nt, m, k)."""
        return np.linalg.norm(self.moment, axis=-1)


def section_forces(structure: Structure, kin: Kinematics, forces: NodalForces,
                   bodies: MemberBodies, n_sections: int = 7, *,
                   positions: np.ndarray | None = None,
                   full_length_inertia: bool = False) -> SectionForces:
    """Internal forces at sections along every member, all steps at once.

    Parameters
    ----------
    structure, kin, forces, bodies
        The model, its kinematics, nodal forces and mass elements.
    n_sections : int
        Number of equidistant sections over each member's tube (≥ 2).
    positions : ndarray, shape (m, k), optional
        Explicit section positions from the end node instead.
    full_length_inertia : bool
        Use the whole tube length in every piece's moment of inertia (Lacy Appendix A quirk).
    """
    if positions is None:
        frac = np.linspace(0.0, 1.0, n_sections)
        positions = bodies.tube_length[:, None] * frac[None, :]          # (member, section)
    u = positions[None, :, :, None]                                       # (1, m, k, 1)
    g = pad3(np.asarray(structure.gravity, dtype=float))
    conn = structure.connectivity
    e = kin.unit[:, :, None, :]
    ed, edd = kin.unit_rate[:, :, None, :], kin.unit_acc[:, :, None, :]
    L = kin.length[:, :, None, None]
    Ld, Ldd = kin.length_rate[:, :, None, None], kin.length_acc[:, :, None, None]
    aa = kin.acceleration[:, conn[:, 0]][:, :, None, :]
    a_seg = aa + Ldd * e + 2.0 * Ld * ed + (L - u / 2.0) * edd
    mu = (bodies.tube_mass / bodies.tube_length)[None, :, None, None]
    mseg = mu * u
    Iseg = bodies.tube_inertia(positions.T, (mu[0, :, :, 0] * positions).T,
                               full_length=full_length_inertia).T[None, :, :, None]
    Fb = forces.end_force[:, :, 1][:, :, None, :]
    N = mseg * (a_seg - g) - Fb
    alpha = kin.alpha[:, :, None, :]
    M = (np.cross(0.5 * u * e, mseg * (a_seg - g)) + Iseg * alpha
         - np.cross(u * e, Fb * np.ones_like(u)))
    Ne = np.einsum("tmki,tmki->tmk", N, e * np.ones_like(u))
    V = N - Ne[..., None] * e
    return SectionForces(position=positions, tension=-Ne, shear=V, moment=M, cut_force=N)


@dataclass
class SectionStresses:
    """Stresses at the sections, arrays (nt, m, k), Pa."""

    axial: np.ndarray
    shear: np.ndarray
    bending: np.ndarray
    s1: np.ndarray
    s2: np.ndarray

    @property
    def von_mises(self) -> np.ndarray:
        """max(S1, S2)."""
        return np.maximum(self.s1, self.s2)


def section_stresses(structure: Structure, sf: SectionForces, *,
                     shear_factor: float = 3.0) -> SectionStresses:
    """von Mises stresses at S1 (neutral axis) and S2 (outer fibre), Lacy eqs. 2.19–2.25.

    Parameters
    ----------
    shear_factor : float
        Factor of τ² under the root at S1: 3 (eq. 2.24, von Mises); Lacy's code uses 1.
    """
    A = structure.area[None, :, None]
    inertia = np.fmin(structure.Iy, structure.Iz)[None, :, None]
    c = structure.c[None, :, None]
    sig_t = sf.tension / A
    tau = 2.0 * sf.shear_magnitude / A
    sig_m = sf.moment_magnitude * c / inertia
    s1 = np.sqrt(sig_t ** 2 + shear_factor * tau ** 2)
    s2 = np.abs(sig_t) + np.abs(sig_m)
    return SectionStresses(axial=sig_t, shear=tau, bending=sig_m, s1=s1, s2=s2)
