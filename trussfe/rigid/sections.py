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
from .linalg import cross


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
    unit : ndarray, shape (nt, m, 3)
        Member unit vectors.
    """

    position: np.ndarray
    tension: np.ndarray
    shear: np.ndarray
    moment: np.ndarray
    unit: np.ndarray

    @property
    def cut_force(self) -> np.ndarray:
        """Force N on the piece at the cut, (nt, m, k, 3): N = V − T e."""
        return self.shear - self.tension[..., None] * self.unit[:, :, None, :]

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
                   full_length_inertia: bool = False,
                   members: np.ndarray | None = None, at_rest: bool = False) -> SectionForces:
    """Internal forces at sections along every member, all steps at once.

    Parameters
    ----------
    structure, kin, forces, bodies
        The model, its kinematics, nodal forces and mass elements.
    n_sections : int
        Number of equidistant sections over each member's tube, end points included (≥ 2);
        1 means the midpoint only (Lacy's choice for the spatial truss).
    positions : ndarray, shape (m, k), optional
        Explicit section positions from the end node instead.
    full_length_inertia : bool
        Use the whole tube length in every piece's moment of inertia (Lacy Appendix A quirk).
    members : ndarray of int, optional
        Only these members (the member axis of the result follows this selection).
    at_rest : bool
        Take the kinematics' rates and accelerations as zero (the static case in the same
        positions; equal to passing ``kin.at_rest()``, without the vanishing terms).

    Notes
    -----
    The piece's acceleration is a_s = a_0 + (L − u/2) ë with a_0 = a_a + L̈ e + 2 L̇ ė
    independent of u, so every cross product is taken once per member and step and the
    sections only scale them:
    M = m_s (u/2) [e × (a_0 − g) + (L − u/2) e × ë] + I_s α − u e × F_b.
    """
    sel = slice(None) if members is None else np.asarray(members, dtype=np.int64)
    tube_length = bodies.tube_length[sel]
    if positions is None:
        frac = np.array([0.5]) if n_sections == 1 else np.linspace(0.0, 1.0, n_sections)
        positions = tube_length[:, None] * frac[None, :]                 # (member, section)
    u = positions[None, :, :]                                             # (1, m, k)
    g = pad3(np.asarray(structure.gravity, dtype=float))
    conn = structure.connectivity[sel]
    e = kin.unit[:, sel]                                                  # (t, m, 3)
    L = kin.length[:, sel, None]                                          # (t, m, 1)
    if at_rest:
        p = np.broadcast_to(-g, e.shape)                                  # a_0 = 0
    else:
        edd = kin.unit_acc[:, sel]
        p = (kin.acceleration[:, conn[:, 0]] + kin.length_acc[:, sel, None] * e
             + 2.0 * kin.length_rate[:, sel, None] * kin.unit_rate[:, sel] - g)   # a_0 − g
    Fb = forces.end_force[:, sel, 1]
    mu = (bodies.tube_mass[sel] / tube_length)[None, :, None]
    mseg = mu * u                                                         # (1, m, k)
    ell = tube_length[:, None] if full_length_inertia else positions
    Iseg = (mu[0] * positions * (bodies.tube_radius2[sel][:, None]
                                 + np.square(ell) / 12.0))[None]          # (1, m, k)
    pe = np.einsum("tmi,tmi->tm", p, e)[..., None]
    fe = np.einsum("tmi,tmi->tm", Fb, e)[..., None]
    p_perp = p - pe * e
    f_perp = Fb - fe * e
    c0 = cross(e, p)
    eF = cross(e, Fb)
    half = (mseg * u / 2.0)[..., None]
    if at_rest:
        # ë = α = 0: the lever terms vanish (same arithmetic as below without the zeros).
        tension = -(mseg * pe - fe)
        V = mseg[..., None] * p_perp[:, :, None, :] - f_perp[:, :, None, :]
        M = half * c0[:, :, None, :] - u[..., None] * eF[:, :, None, :]
        return SectionForces(position=positions, tension=tension, shear=V, moment=M, unit=e)
    lever = L - u / 2.0                                                   # (t, m, k)
    qe = np.einsum("tmi,tmi->tm", edd, e)[..., None]
    tension = -(mseg * (pe + lever * qe) - fe)
    q_perp = edd - qe * e
    V = ((mseg[..., None] * p_perp[:, :, None, :])
         + (mseg * lever)[..., None] * q_perp[:, :, None, :] - f_perp[:, :, None, :])
    c1 = cross(e, edd)
    M = (half * (c0[:, :, None, :] + lever[..., None] * c1[:, :, None, :])
         + Iseg[..., None] * kin.alpha[:, sel, None, :] - u[..., None] * eF[:, :, None, :])
    return SectionForces(position=positions, tension=tension, shear=V, moment=M, unit=e)


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


def member_frames(unit: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors perpendicular to each member, (…, 3) each (Lacy's b1, b2).

    b1 = e × k / |e × k| with k the global z axis (the global x axis for a member within 25°
    of z), b2 = e × b1.  In 2-D (e in the x–y plane) b1 is the in-plane normal and b2 = −z:
    the planar shear is the b1 component and the planar moment minus the b2 component.
    """
    helper = np.where(np.abs(unit[..., 2:3]) < 0.9, [0.0, 0.0, 1.0], [1.0, 0.0, 0.0])
    b1 = cross(unit, helper)
    b1 /= np.linalg.norm(b1, axis=-1, keepdims=True)
    b2 = cross(unit, b1)
    return b1, b2


def local_components(sf: SectionForces) -> tuple[np.ndarray, np.ndarray]:
    """The two shear forces and two bending moments of every section (Lacy eqs. 4.68–4.74).

    Returns
    -------
    shear, moment : ndarray, shape (nt, m, k, 2)
        Components along / about the member frame (b1, b2) of :func:`member_frames`.
    """
    b1, b2 = member_frames(sf.unit)
    frames = np.stack([b1, b2], axis=-2)[:, :, None]               # (t, m, 1, 2, 3)
    shear = np.einsum("tmkj,tmkcj->tmkc", sf.shear, np.broadcast_to(
        frames, sf.shear.shape[:3] + (2, 3)))
    moment = np.einsum("tmkj,tmkcj->tmkc", sf.moment, np.broadcast_to(
        frames, sf.moment.shape[:3] + (2, 3)))
    return shear, moment
