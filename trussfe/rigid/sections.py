# SPDX-License-Identifier: MIT
"""Internal forces and von Mises stresses along the members (Lacy sections 2.6–2.7, 4.8–4.9).

A member is cut at ``k`` equidistant sections along its tube (the whole member if passive,
the leadscrew tube if active), measured from the member's end node: ``u_j = j L_t/(k−1)``,
j = 0…k−1 (Lacy cuts the follower and the leadscrew tube from point B at seven points; the
tube's sections ride with the end node as an active member telescopes, so u, not the distance
x = L − u from the start node of :func:`trussfe.mechanics.geometry.from_end_node`, labels
them).  The
piece between the cut and the end node, of mass ``m u/L_t`` and centre of gravity at u/2 from
the end node, obeys (Lacy eqs. 2.16–2.18, 4.68–4.74)

.. math::

   N &= m_s (a_s - g) - F_b, \\\\
   M &= \\tfrac{u}{2} e \\times m_s (a_s - g) + I_s \\alpha - u\\, e \\times F_b ,

with N and M the force and moment the rest of the member exerts on the piece at the cut.
Tension T = −N·e, shear V = N − (N·e)e (two components in 3-D), bending moment M.

Stresses (Lacy eqs. 2.19–2.25, 4.75–4.76; :mod:`trussfe.mechanics.stress`) of a thin round
tube: σ_T = T/A, τ = 2|V|/A, σ_M = |M| c/I, and von Mises at the neutral axis
S1 = √(σ_T² + 3τ²) and at the outer fibre S2 = |σ_T| + σ_M; the member's stress is the larger.  Lacy's code uses
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

from ..mechanics.geometry import frame_rotations, stations, transverse_frames
from ..mechanics.mass import centroidal_inertia
from ..mechanics.stress import SectionStresses, round_sections, von_mises
from ..model.geometry import lengths
from ..model.structure import Structure
from .forces import MemberBodies, NodalForces, axis_acceleration
from .kinematics import Kinematics, pad3
from ..vectors import components_first, cross, dot, empty_vectors, take


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
        return lengths(self.shear)

    @property
    def moment_magnitude(self) -> np.ndarray:
        """|M|, (nt, m, k)."""
        return lengths(self.moment)


def section_forces(structure: Structure, kin: Kinematics, forces: NodalForces,
                   bodies: MemberBodies, n_sections: int = 7, *,
                   positions: np.ndarray | None = None,
                   full_length_inertia: bool = False,
                   members: np.ndarray | None = None, at_rest: bool = False,
                   tension: np.ndarray | None = None) -> SectionForces:
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
    tension : ndarray, shape (nt, m, k), optional
        The axial forces of these sections if already known (:func:`section_tension` of the
        same arguments, the same numbers); the shears and moments are computed beside them.

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
        positions = stations(tube_length, n_sections)                     # (member, section)
    u = positions[None, :, :]                                             # (1, m, k)
    g = pad3(np.asarray(structure.gravity, dtype=float))
    conn = structure.connectivity[sel]
    # every vector with its components stored first (trussfe.vectors): the shears and
    # moments below, and every term of them, follow that order
    e = components_first(_members(kin.unit, sel))                         # (t, m, 3)
    L = _members(kin.length, sel)[..., None]                              # (t, m, 1)
    if at_rest:
        p = np.broadcast_to(-g, e.shape)                                  # a_0 = 0
    else:
        edd = components_first(_members(kin.unit_acc, sel))
        p = _base_acceleration(kin, conn, sel, e, g)                      # a_0 − g
    Fb = components_first(_members(forces.end_force[:, :, 1], sel))
    mu = (bodies.tube_mass[sel] / tube_length)[None, :, None]
    mseg = mu * u                                                         # (1, m, k)
    ell = tube_length[:, None] if full_length_inertia else positions
    Iseg = centroidal_inertia(mu[0] * positions, ell,
                              bodies.tube_radius2[sel][:, None])[None]    # (1, m, k)
    pe = dot(p, e)[..., None]
    fe = dot(Fb, e)[..., None]
    p_perp = p - pe * e
    f_perp = Fb - fe * e
    c0 = cross(e, p)
    eF = cross(e, Fb)
    half = (mseg * u / 2.0)[..., None]
    shape = e.shape[:2] + u.shape[2:] + e.shape[2:]                      # (t, m, k, 3)
    if at_rest:
        # ë = α = 0: the lever terms vanish (same arithmetic as below without the zeros).
        if tension is None:
            tension = _tension(mseg, pe, fe)
        V = np.multiply(mseg[..., None], p_perp[:, :, None, :], out=empty_vectors(shape))
        V -= f_perp[:, :, None, :]
        M = np.multiply(half, c0[:, :, None, :], out=empty_vectors(shape))
        M -= np.multiply(u[..., None], eF[:, :, None, :], out=empty_vectors(shape))
        return SectionForces(position=positions, tension=tension, shear=V, moment=M, unit=e)
    lever = L - u / 2.0                                                   # (t, m, k)
    qe = dot(edd, e)[..., None]
    if tension is None:
        tension = _tension(mseg, pe, fe, lever, qe)
    q_perp = edd - qe * e
    # V = m_s p⊥ + m_s (L − u/2) q⊥ − F_b⊥ and
    # M = (m_s u/2) (c0 + (L − u/2) c1) + I_s α − u e × F_b, added in that order in place
    # (every (t, m, k, 3) term once, no temporaries of the sums)
    V = np.multiply(mseg[..., None], p_perp[:, :, None, :], out=empty_vectors(shape))
    term = np.multiply((mseg * lever)[..., None], q_perp[:, :, None, :],
                       out=empty_vectors(shape))
    V += term
    V -= f_perp[:, :, None, :]
    c1 = cross(e, edd)
    M = np.multiply(lever[..., None], c1[:, :, None, :], out=empty_vectors(shape))
    M += c0[:, :, None, :]
    M *= half
    M += np.multiply(Iseg[..., None], components_first(_members(kin.alpha, sel))[:, :, None, :],
                     out=term)
    M -= np.multiply(u[..., None], eF[:, :, None, :], out=term)
    return SectionForces(position=positions, tension=tension, shear=V, moment=M, unit=e)


def _base_acceleration(kin: Kinematics, conn: np.ndarray, sel, e: np.ndarray,
                       g: np.ndarray) -> np.ndarray:
    """a_0 − g of the members ``sel`` (start nodes ``conn``), (t, m, 3)
    (:func:`~trussfe.rigid.forces.axis_acceleration`)."""
    p = axis_acceleration(take(kin.acceleration, conn[:, 0], axis=1), e,
                          _members(kin.unit_rate, sel), _members(kin.length_rate, sel)[..., None],
                          _members(kin.length_acc, sel)[..., None])
    p -= g
    return p


def _members(a: np.ndarray, sel) -> np.ndarray:
    """``a[:, sel]`` of a history per member (t, m[, 3]): a view for a slice, else a gather
    along the member axis, component by component for vectors stored components first
    (:func:`trussfe.vectors.take`; the result is stored so too)."""
    return a[:, sel] if isinstance(sel, slice) else take(a, sel, axis=1)


def _tension(mseg, pe, fe, lever=None, qe=None):
    """Axial force T = −N·e at the cuts (Lacy eqs. 2.16, 4.68): −(m_s (a_s − g)·e − F_b·e),
    with (a_0 − g)·e = ``pe``, ë·e = ``qe`` and the lever L − u/2 (no lever at rest)."""
    if lever is None:
        return -(mseg * pe - fe)
    return -(mseg * (pe + lever * qe) - fe)


def section_tension(structure: Structure, kin: Kinematics, forces: NodalForces,
                    bodies: MemberBodies, n_sections: int = 7, *,
                    positions: np.ndarray | None = None, members: np.ndarray | None = None,
                    at_rest: bool = False) -> np.ndarray:
    """The axial forces of :func:`section_forces` alone, (nt, m, k), N (positive in tension).

    The same arithmetic as ``section_forces(...).tension`` (equal to the last bit), without
    the shears and moments: the buckling check and the midpoint axial force need only these.
    """
    sel = slice(None) if members is None else np.asarray(members, dtype=np.int64)
    tube_length = bodies.tube_length[sel]
    if positions is None:
        positions = stations(tube_length, n_sections)
    u = positions[None, :, :]
    g = pad3(np.asarray(structure.gravity, dtype=float))
    e = _members(kin.unit, sel)
    mu = (bodies.tube_mass[sel] / tube_length)[None, :, None]
    mseg = mu * u
    fe = dot(_members(forces.end_force[:, :, 1], sel), e)[..., None]
    if at_rest:
        pe = dot(np.broadcast_to(-g, e.shape), e)[..., None]
        return _tension(mseg, pe, fe)
    conn = structure.connectivity[sel]
    p = _base_acceleration(kin, conn, sel, e, g)
    pe = dot(p, e)[..., None]
    qe = dot(_members(kin.unit_acc, sel), e)[..., None]
    return _tension(mseg, pe, fe, _members(kin.length, sel)[..., None] - u / 2.0, qe)


def section_stresses(structure: Structure, sf: SectionForces, *,
                     shear_factor: float = 3.0, convention: str = "combined",
                     round_section: np.ndarray | None = None) -> SectionStresses:
    """von Mises stresses at S1 (neutral axis) and S2 (outer fibre), Lacy eqs. 2.19–2.25.

    The stresses are those of :func:`trussfe.mechanics.stress.von_mises`.  A round section
    needs only the magnitudes |V| and |M| (its stresses do not depend on the direction of
    bending); the shears and moments of any other section, and of the per-axis convention,
    are taken in the member axes of :func:`trussfe.mechanics.geometry.frame_rotations`.

    Parameters
    ----------
    shear_factor : float
        Factor of τ² under the root at S1: 3 (eq. 2.24, von Mises); Lacy's code uses 1.
    convention : {"combined", "lacy-per-axis"}
        See :mod:`trussfe.mechanics.stress`.
    round_section : ndarray of bool, shape (m,), optional
        :func:`~trussfe.mechanics.stress.round_sections` of the structure, if known (a caller
        that evaluates many blocks of steps asks the sections once).
    """
    col = lambda a: a[None, :, None]     # member properties against (time, member, section)
    rnd = round_sections(structure.sections) if round_section is None else round_section
    if convention == "combined" and np.all(rnd):
        V, M, zero = sf.shear_magnitude, sf.moment_magnitude, 0.0
        vm = von_mises(sf.tension, V, zero, M, zero, col(structure.area), col(structure.Iy),
                       col(structure.Iy), col(structure.c), col(structure.c), True,
                       shear_weight=shear_factor)
    else:
        # components in member axes; in 2-D local y is the in-plane normal and z the global z
        dim = structure.dim
        R = frame_rotations(sf.unit[..., :dim], structure.orientation if dim == 3 else None)
        y = R[:, :, None, 1]                                            # (t, m, 1, dim)
        Vy = dot(np.broadcast_to(y, sf.shear.shape[:3] + (dim,)), sf.shear[..., :dim])
        if dim == 2:
            Vz, My, Mz = 0.0, 0.0, sf.moment[..., 2]
        else:
            z = np.broadcast_to(R[:, :, None, 2], sf.shear.shape)
            Vz = dot(z, sf.shear)
            My = dot(np.broadcast_to(y, sf.moment.shape), sf.moment)
            Mz = dot(z, sf.moment)
        vm = von_mises(sf.tension, Vy, Vz, My, Mz, col(structure.area), col(structure.Iy),
                       col(structure.Iz), col(structure.c), col(structure.c), col(rnd),
                       convention=convention, shear_weight=shear_factor)
    return vm


def local_components(sf: SectionForces) -> tuple[np.ndarray, np.ndarray]:
    """The two shear forces and two bending moments of every section (Lacy eqs. 4.68–4.74).

    Returns
    -------
    shear, moment : ndarray, shape (nt, m, k, 2)
        Components along / about Lacy's member frame (b1, b2) of
        :func:`trussfe.mechanics.geometry.transverse_frames`.
    """
    frames = [b[:, :, None] for b in transverse_frames(sf.unit)]     # (t, m, 1, 3) each
    shear = np.stack([dot(sf.shear, b) for b in frames], axis=-1)
    moment = np.stack([dot(sf.moment, b) for b in frames], axis=-1)
    return shear, moment
