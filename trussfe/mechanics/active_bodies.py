# SPDX-License-Identifier: MIT
"""The mass elements of every member — a distributed tube and an active member's lumped base —
and the weight of active members as loads along finite-element members.

A passive member is a uniform tube.  An active member (Lacy §2.1, §4.7; docs/model-format.md,
``[active_members]``) is its **active base**, a rigid body of ``base_mass`` with its centre of
gravity ``base_cg`` from the start node, pinned at the start node, and its **leadscrew tube**,
the member's section over ``tube_length`` ending at the end node; its own ρAL is not counted
besides.  :func:`member_bodies` gives these bodies to every analysis that follows a motion
(:mod:`trussfe.rigid`, :mod:`trussfe.response`); :func:`active_weight_loads` gives their weight
to the finite-element analyses, whose members weigh ρAL each.

**The base on a line model.**  In the rigid model the leadscrew tube is cut only through the
tube: the base is a separate body that reaches the tube at the cantilever connection
``x_c = L − L_t`` (Lacy eqs. 4.63–4.67), even where the two overlap physically (the triangular
truss: ``cg_b = 1.05 m`` lies beyond ``x_c = 0.5 m`` at the start of the Base Simulation).  A
finite-element member is one line, so the base's resultant is applied on the base side of the
connection, at ``x_p = min(cg_b, x_c)`` (:func:`base_load_point`), with the transfer couple
``(cg_b − x_p) e × F_b`` that keeps its moment: statically equivalent for the member and
identical for every section of the tube, which is where the rigid model reports forces.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..model.member_loads import MemberLoad
from ..model.structure import Structure
from .geometry import local_axes
from .mass import centroidal_inertia, gyration_squared, mass_per_length, member_mass


@dataclass
class MemberBodies:
    """Mass elements of every member: a distributed tube and a lumped base.

    Attributes
    ----------
    tube_mass, tube_length : ndarray, shape (m,)
        Mass ρ A L_t and length L_t of the uniform tube part (the whole member if passive).
    tube_radius2 : ndarray, shape (m,)
        Mean I/A of the tube section, m² (the cross-section part of its transverse inertia).
    base_mass, base_cg, base_inertia_cg : ndarray, shape (m,)
        Active base mass, its centre of gravity from the start node, its inertia about its
        own centre of gravity (zero for passive members).
    active : ndarray of bool, shape (m,)
    """

    tube_mass: np.ndarray
    tube_length: np.ndarray
    tube_radius2: np.ndarray
    base_mass: np.ndarray
    base_cg: np.ndarray
    base_inertia_cg: np.ndarray
    active: np.ndarray

    def tube_inertia(self, seg_length: np.ndarray | float, seg_mass: np.ndarray,
                     full_length: bool = False) -> np.ndarray:
        """Transverse inertia of a tube piece about its centre, m (I/A + ℓ²/12).

        ``full_length=True`` uses the whole tube length for every piece, as Lacy's Appendix A
        does for the section equations (``iz``, ``is``).
        """
        ell = self.tube_length if full_length else seg_length
        return centroidal_inertia(seg_mass, ell, self.tube_radius2)


def member_bodies(structure: Structure) -> MemberBodies:
    """Mass elements of the structure's members (Lacy Appendix A/C masses).

    Passive members: ρ A L, centre of gravity at L/2 and I = m (I_sec/A + L²/12)
    (Lacy's ``m (3 OD² + 3 ID² + 4 L²)/48`` for a tube).  Active members: base mass, centre of
    gravity and inertia from ``[active_members]``; tube ρ A L_tube with the member's section.
    """
    L = structure.lengths()
    A = structure.area
    m = structure.n_members
    tl = L.copy()
    mb = np.zeros(m)
    cg = np.zeros(m)
    ib = np.zeros(m)
    act = np.zeros(m, dtype=bool)
    for a in structure.extensions.get("active_members", ()):
        k = a.member
        tl[k] = a.tube_length
        mb[k], cg[k], ib[k] = a.base_mass, a.base_cg, a.base_inertia_cg
        act[k] = True
    return MemberBodies(tube_mass=member_mass(structure.density, A, tl), tube_length=tl,
                        tube_radius2=gyration_squared(structure.Iy, structure.Iz, A),
                        base_mass=mb, base_cg=cg, base_inertia_cg=ib,
                        active=act)



def massless_active(structure: Structure) -> Structure:
    """The structure with active members that carry no distributed mass (density 0), for the
    finite-element matrices of an analysis that adds their bodies itself
    (:func:`trussfe.fem.modal.active_member_mass`, the motion loads of
    :mod:`trussfe.response`)."""
    mats = structure.materials
    return structure.with_materials(
        {a.member: replace(mats[a.member], density=0.0)
         for a in structure.extensions.get("active_members", ())})

def base_load_point(bodies: MemberBodies, length: np.ndarray) -> np.ndarray:
    """``x_p = min(cg_b, L − L_t)``: where a line model applies an active base's resultant, m
    from the start node (module notes; 0 for passive members).

    Parameters
    ----------
    bodies : MemberBodies
    length : ndarray, shape (..., m)
        Member lengths (per step of a motion, or one configuration).
    """
    L = np.asarray(length, dtype=float)
    cg = np.broadcast_to(bodies.base_cg, L.shape)
    return np.where(bodies.active, np.minimum(cg, L - bodies.tube_length), 0.0)


def active_weight_loads(structure: Structure, gravity: np.ndarray | None = None,
                        members: np.ndarray | None = None) -> tuple[MemberLoad, ...]:
    """Loads along the active members that turn the weight of a uniform member (ρAL, which a
    finite-element member carries) into that of its base and leadscrew tube.

    For an active member of length L with the tube over ``[x_c, L]``, ``x_c = L − L_t``: the
    uniform weight ``ρA g`` taken off ``[0, x_c]`` (the tube keeps its own), and the base's
    weight ``m_b g`` at ``x_p`` with the transfer couple ``(cg_b − x_p) e × m_b g`` (module
    notes).  Added to a finite-element self-weight they make the member weigh
    ``m_b + ρA L_t`` with its centre of gravity where the rigid-body model has it.

    Parameters
    ----------
    structure : Structure
    gravity : ndarray, shape (dim,), optional
        Default ``structure.gravity``.
    members : ndarray of bool, shape (m,), optional
        The members to load (default all active members).

    Returns
    -------
    tuple of MemberLoad
        Empty without active members or gravity.

    Examples
    --------
    Lacy's triangular truss: the 2.5 m active member, tube 2.0 m, base 2.4 kg at 1.05 m.

    >>> from trussfe.models import triangular_truss
    >>> s = triangular_truss(member_weight=True, active_members=True)
    >>> [(ld.kind, round(ld.span[1] if ld.kind != "point" else ld.at, 6))
    ...  for ld in active_weight_loads(s)]
    [('uniform', 0.2), ('point', 0.2)]
    """
    s = structure
    g = np.asarray(s.gravity if gravity is None else gravity, dtype=float)
    acts = list(s.extensions.get("active_members", ()))
    if not acts or not np.any(g):
        return ()
    bodies = member_bodies(s)
    L = s.lengths()
    R = local_axes(s)
    xp = base_load_point(bodies, L)
    rho_a = mass_per_length(s.density, s.area)
    out: list[MemberLoad] = []
    for a in acts:
        j = a.member
        if members is not None and not members[j]:
            continue
        xc = L[j] - a.tube_length
        if xc > 0.0 and rho_a[j] > 0.0:
            q = tuple(-rho_a[j] * g)
            out.append(MemberLoad(j, "uniform", q, q, span=(0.0, min(xc / L[j], 1.0))))
        if a.base_mass > 0.0:
            # member axes: the couple of a lever along the member has no component about it
            # (exactly 0, which a bar without torsion needs)
            W = R[j] @ (a.base_mass * g)
            d = a.base_cg - xp[j]
            couple = (d * W[1],) if s.dim == 2 else (0.0, -d * W[2], d * W[1])
            out.append(MemberLoad(j, "point", at=float(min(max(xp[j] / L[j], 0.0), 1.0)),
                                  force=tuple(W), moment=couple if d != 0.0 else (),
                                  axes="local"))
    return tuple(out)


def active_weight_joint_loads(structure: Structure, gravity: np.ndarray | None = None,
                              members: np.ndarray | None = None) -> np.ndarray:
    """Joint loads that turn the weight of a uniform bar (ρAL, half at each end) into that of
    an active member's base and leadscrew tube, for a member modelled as an axial-only bar.

    The member is a rigid body pinned at its two joints (Lacy eqs. 2.9–2.11 at rest):
    transversely its weight goes to the joints by the lever rule about its centre of
    gravity; axially the base's share goes to the start joint, where the base is pinned, and
    the tube's to the end joint, so that the bar's axial force is the force at the cantilever
    connection — the actuator force of the rigid-body model, which ``simulate`` reports.

    Parameters
    ----------
    structure : Structure
    gravity : ndarray, shape (dim,), optional
        Default ``structure.gravity``.
    members : ndarray of bool, shape (m,), optional
        The members to count (default all active members).

    Returns
    -------
    ndarray, shape (n_nodes, dim)
        N; zero without active members or gravity.

    Examples
    --------
    The triangular truss's active member (13.688 − 11.449 kg more than a uniform member):

    >>> from trussfe.models import triangular_truss
    >>> s = triangular_truss(member_weight=True, active_members=True)
    >>> round(float(active_weight_joint_loads(s).sum(axis=0)[1] / -9.81), 4)
    2.239
    """
    s = structure
    g = np.asarray(s.gravity if gravity is None else gravity, dtype=float)
    out = np.zeros((s.n_nodes, s.dim))
    acts = [a for a in s.extensions.get("active_members", ())
            if members is None or members[a.member]]
    if not acts or not np.any(g):
        return out
    idx = np.array([a.member for a in acts], dtype=np.int64)
    bodies = member_bodies(s)
    L = s.lengths()[idx]
    e = s.unit_vectors()[idx]
    lt, m_tube, m_base = (bodies.tube_length[idx], bodies.tube_mass[idx],
                          bodies.base_mass[idx])
    rho_a = mass_per_length(s.density, s.area)[idx]
    # the bodies' weights and where they act from the start joint
    cg = np.clip(bodies.base_cg[idx], 0.0, L)
    W_base, W_tube = m_base[:, None] * g, m_tube[:, None] * g
    along = lambda W: np.einsum("ij,ij->i", W, e)[:, None] * e            # noqa: E731
    across = lambda W: W - along(W)                                       # noqa: E731
    to_end = (across(W_base) * (cg / L)[:, None]
              + across(W_tube) * ((L - 0.5 * lt) / L)[:, None] + along(W_tube))
    to_start = W_base + W_tube - to_end
    uniform = 0.5 * (rho_a * L)[:, None] * g                              # the bar's own, each end
    conn = s.connectivity[idx]
    np.add.at(out, conn[:, 0], to_start - uniform)
    np.add.at(out, conn[:, 1], to_end - uniform)
    return out
