# SPDX-License-Identifier: MIT
"""Lacy's literal formulation of the triangular truss (eq. 2.13, Appendix A), kept for fidelity.

The general model (:mod:`trussfe.rigid.forces`) eliminates each member's transverse end forces
with its own moment equation; Lacy instead assembles the 11 equations of motion of the
follower, leadscrew tube, active base and lumped mass in the 11 unknowns
``{F} = (Fx1, Fx2, Fx3, Fy1, Fy2, Fy3, Rx1, Rx2, Ry1, Ry2, M1)`` and solves
``{F} = [SM]⁻¹ {MẌ}`` (eqs. 2.13–2.14) at every step.  This module rebuilds that system exactly
as Appendix A codes it — with the zeros the OCR dropped from rows e3–e11 restored, the stray 1
of eq. 2.13 row 7 removed, and gravity g = +9.81 m/s² in equations written for a downward
weight (the printed ``g = -9.81`` would make gravity act upward) — and solves it for all steps
at once, as an independent cross-check of the general model.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..mechanics.geometry import transverse_frames
from .lacy_rigid import ID, L1, L2, L3MAX, L3MIN, L4, OD, TUBE, ALUMINIUM

G = 9.81


@dataclass
class LacyTriangle:
    """Solution of eq. 2.13 per step: ``forces`` (nt, 11) in Lacy's unknown order."""

    forces: np.ndarray
    matrix: np.ndarray
    rhs: np.ndarray


def thesis_angles(x: np.ndarray, dt: float):
    """φ, θ (law of cosines, eqs. 2.1–2.2) and their backward-difference rates (section 2.3)."""
    La = L2 + L3MIN + x
    phi = np.arccos((L1 ** 2 + L4 ** 2 - La ** 2) / (2 * L4 * L1))
    theta = np.arccos((La ** 2 + L4 ** 2 - L1 ** 2) / (2 * L4 * La))

    def rates(a):
        d = np.zeros_like(a)
        d[1:] = np.diff(a) / dt
        dd = np.zeros_like(a)
        dd[1:] = np.diff(d) / dt
        return d, dd

    return phi, *rates(phi), theta, *rates(theta)


def lacy_triangle(x, xvel, xacel, dt: float, mass4: float, g: float = G) -> LacyTriangle:
    """Assemble and solve Lacy's 11 × 11 system (eq. 2.13) at every step.

    Parameters
    ----------
    x, xvel, xacel : ndarray, shape (nt,)
        Actuator extension, velocity and acceleration (``lpos``, ``xvel``, ``xacel``).
    dt : float
        Time step of the backward differences.
    mass4 : float
        Lumped mass at B, kg.
    g : float
        Gravity, positive downward.
    """
    phi, phid, phidd, th, thd, thdd = thesis_angles(np.asarray(x, float), dt)
    area = TUBE.area
    rho = ALUMINIUM.density
    m1, m2, m3 = rho * area * L1, rho * area * L2, 2.4
    cg1, cg2, cg3 = L1 / 2, L2 / 2, L3MAX / 2
    ic = m2 * (3 * OD ** 2 + 3 * ID ** 2 + 4 * L2 ** 2) / 48
    io1 = m1 * (3 * OD ** 2 + 3 * ID ** 2 + 4 * L1 ** 2) / 48 + m1 * L1 ** 2 / 4
    io2 = m3 * L3MAX ** 2 / 3
    sp, cp, st, ct = np.sin(phi), np.cos(phi), np.sin(th), np.cos(th)
    aax = cg1 * phid ** 2 * cp + cg1 * phidd * sp
    aay = -cg1 * phid ** 2 * sp + cg1 * phidd * cp
    abx = L1 * phid ** 2 * cp + L1 * phidd * sp
    aby = -L1 * phid ** 2 * sp + L1 * phidd * cp
    r = x + L3MIN + cg2
    acx = xacel * ct - 2 * xvel * thd * st - r * thdd * st - r * thd ** 2 * ct
    acy = xacel * st + 2 * xvel * thd * ct + r * thdd * ct - r * thd ** 2 * st
    adx = -cg3 * thdd * st - cg3 * thd ** 2 * ct
    ady = cg3 * thdd * ct - cg3 * thd ** 2 * st
    rhs = np.stack([m1 * aax, m1 * aay + m1 * g, io1 * phidd + m1 * g * cg1 * cp,
                    m2 * acx, m2 * acy + m2 * g, ic * thdd,
                    m3 * adx, m3 * ady + m3 * g, io2 * thdd + m3 * g * cg3 * ct,
                    mass4 * abx, mass4 * aby + mass4 * g], axis=1)
    nt = phi.size
    SM = np.zeros((nt, 11, 11))
    val1 = L2 - cg2
    val3, val4 = (x + L3MIN) * st, (x + L3MIN) * ct
    SM[:, 0, [0, 6]] = 1
    SM[:, 1, [3, 8]] = 1
    SM[:, 2, 0], SM[:, 2, 3] = L1 * sp, L1 * cp
    SM[:, 3, [1, 2]] = 1
    SM[:, 4, [4, 5]] = 1
    SM[:, 5, 1], SM[:, 5, 2], SM[:, 5, 4], SM[:, 5, 5] = (-val1 * st, cg2 * st, val1 * ct,
                                                          -cg2 * ct)
    SM[:, 5, 10] = 1
    SM[:, 6, 2], SM[:, 6, 7] = -1, 1
    SM[:, 7, 5], SM[:, 7, 9] = -1, 1
    SM[:, 8, 2], SM[:, 8, 5], SM[:, 8, 10] = val3, -val4, -1
    SM[:, 9, [0, 1]] = -1
    SM[:, 10, [3, 4]] = -1
    F = np.linalg.solve(SM, rhs[..., None])[..., 0]
    return LacyTriangle(forces=F, matrix=SM, rhs=rhs)


# ------------------------------------------------------------------ the unreduced system
def newton_euler_system(structure, kin, bodies=None):
    """Lacy's unreduced Newton–Euler system (eq. 4.20, Table 4.1) for any pin-jointed truss.

    Unknowns: the three components of the force each node exerts on each member end (F_a,
    F_b; 6 per member in 3-D, 4 in 2-D) and the support reactions.  Equations: each member's
    force balance (dim rows) and its moment balance about its start node along two directions
    perpendicular to it (one in 2-D), and the nodal constraint equations (dim rows per node).
    For the double-octahedral bay: 18 × 6 + 9 = 117 unknowns and 18 × 5 + 27 = 117 equations —
    Lacy's 117 × 117 system.  Dense, assembled and solved per step (``numpy.linalg.solve``
    over the time axis); kept as an independent check of :func:`~trussfe.rigid.forces.
    nodal_forces`, which eliminates each member's transverse forces first.

    Returns
    -------
    A : ndarray, shape (nt, N, N)
    b : ndarray, shape (nt, N)
    layout : dict
        ``"end_force"``: index array (m, 2, dim) of the force unknowns; ``"reaction"``: list of
        (node, component, column).
    """
    from ..rigid.forces import member_bodies, member_resultants
    from ..rigid.kinematics import pad3

    bodies = member_bodies(structure) if bodies is None else bodies
    dim = structure.dim
    conn = structure.connectivity
    m, n = structure.n_members, structure.n_nodes
    nt = kin.n_steps
    e = kin.unit
    g = pad3(np.asarray(structure.gravity, dtype=float))
    _, _, R, Ma = member_resultants(kin, bodies, g, conn)
    # Directions of the moment equations: perpendicular to the member (Lacy's b1, b2).
    if dim == 2:
        dirs = np.zeros((nt, m, 1, 3))
        dirs[..., 0, 2] = 1.0
    else:
        b1, b2 = transverse_frames(e)
        dirs = np.stack([b1, b2], axis=2)                     # (t, m, 2, 3)
    nmom = dirs.shape[2]
    fcol = np.arange(m * 2 * dim).reshape(m, 2, dim)
    sup = np.argwhere(structure.translation_supports)
    rcol = m * 2 * dim + np.arange(len(sup))
    N = m * 2 * dim + len(sup)
    rows_member = m * (dim + nmom)
    if rows_member + n * dim != N:
        raise ValueError(f"the unreduced system is {rows_member + n * dim} × {N}: the truss is "
                         "not statically determinate (or has members between fixed nodes)")
    A = np.zeros((nt, N, N))
    b = np.zeros((nt, N))
    ar = np.arange(m)
    for c in range(dim):                                      # force balance
        row = ar * (dim + nmom) + c
        A[:, row, fcol[:, 0, c]] = 1.0
        A[:, row, fcol[:, 1, c]] = 1.0
        b[:, row] = R[..., c]
    d = (kin.length[..., None] * e)
    for j in range(nmom):                                     # moment balance about start
        row = ar * (dim + nmom) + dim + j
        coef = np.cross(dirs[:, :, j], d)                     # (b_j × d)·F_b = b_j·(d × F_b)
        for c in range(dim):
            A[:, row, fcol[:, 1, c]] = coef[..., c]
        b[:, row] = np.einsum("tmi,tmi->tm", dirs[:, :, j], Ma)
    P = pad3(structure.loads[:, :dim])
    Mn = structure.masses
    rhs_nodes = P[None] + Mn[None, :, None] * (g - kin.acceleration)
    for c in range(dim):                                      # nodal equations
        for end in (0, 1):
            A[:, rows_member + conn[:, end] * dim + c, fcol[:, end, c]] = 1.0
        b[:, rows_member + np.arange(n) * dim + c] = rhs_nodes[..., c]
    for (node, c), col in zip(sup, rcol):
        A[:, rows_member + node * dim + c, col] = -1.0
    return A, b, {"end_force": fcol, "reaction": [(int(a), int(c), int(k))
                                                  for (a, c), k in zip(sup, rcol)]}
