# SPDX-License-Identifier: MIT
"""Member mass: distributed ρA, tube pieces as rigid bodies, active members' rigid-body mass.

* A passive member is a uniform tube of mass per length ρA, total ρAL (and ρI_p, I_p = Iy + Iz, about its axis
  for a beam that twists); the finite elements spread ρA with their shape functions (consistent, ``ρAL/6 [[2, 1], [1, 2]]`` for a bar on
  every translation) or half to each end (lumped) in :meth:`trussfe.fem.FEModel.mass`.
* A tube piece of length ℓ and mass m turning as a rigid body about a transverse axis through
  its centre has the moment of inertia m (r² + ℓ²/12): ℓ²/12 from its length and the
  **rotary inertia** m r² of its cross-sections, r² = I/A the squared radius of gyration of
  the section (Lacy's m (3 OD² + 3 ID² + 4 L²)/48 for a tube).  I is the mean of Iy and Iz,
  the inertia about any transverse axis of a round section.
* An active member (Lacy §2.1, §4.7) is its active base (pinned at the start node) and its
  leadscrew tube (at the end node) on the member's line; :func:`rigid_line_mass` is the mass
  matrix of such a set of bodies following the member's rigid motion transversely.
"""
from __future__ import annotations

import numpy as np


def mass_per_length(density: np.ndarray, area: np.ndarray) -> np.ndarray:
    """ρA, kg/m."""
    return np.asarray(density, dtype=float) * np.asarray(area, dtype=float)


def twist_inertia_per_length(density: np.ndarray, Iy: np.ndarray, Iz: np.ndarray,
                             J: np.ndarray) -> np.ndarray:
    """ρ I_p, the rotary inertia per length of a member's sections about its own axis, kg·m.

    The section's mass turns about the axis with its polar moment of area I_p = Iy + Iz
    (St-Venant torsion: ρ I_p θ̈ = G J θ''), which is the torsion constant J only for a round
    section: a rectangle's J is below its I_p, an open section's far below.  Where Iy or Iz
    is unknown, J stands for I_p (a round section); an unknown J too counts as 0.

    Examples
    --------
    A tube (J = Iy + Iz) and a 100 × 300 mm steel rectangle (J = 1.88e-4 m⁴ against
    I_p = 2.5e-4 m⁴):

    >>> twist_inertia_per_length(7850.0, 1e-6, 1e-6, 2e-6).item()
    0.0157
    >>> round(twist_inertia_per_length(7850.0, 2.25e-4, 2.5e-5, 1.88e-4).item(), 4)
    1.9625
    """
    polar = np.asarray(Iy, dtype=float) + np.asarray(Iz, dtype=float)
    polar = np.where(np.isfinite(polar), polar, np.asarray(J, dtype=float))
    return np.asarray(density, dtype=float) * np.nan_to_num(polar)


def member_mass(density: np.ndarray, area: np.ndarray, length: np.ndarray) -> np.ndarray:
    """ρAL of a uniform member (or tube piece of that length), kg.

    Examples
    --------
    Lacy's follower (Appendix B: ρ = 2711.5 kg/m³, A = 1.1876e-4 m², L = 2 m): 0.644 kg.

    >>> round(float(member_mass(2711.5, 1.1875965e-4, 2.0)), 4)
    0.644
    """
    return mass_per_length(density, area) * np.asarray(length, dtype=float)


def gyration_squared(Iy: np.ndarray, Iz: np.ndarray, area: np.ndarray) -> np.ndarray:
    """r² = I/A of the section about a transverse axis, m² (mean of Iy and Iz; an unknown I
    counts as 0, a section without bending properties has no rotary inertia)."""
    return 0.5 * (np.nan_to_num(Iy) + np.nan_to_num(Iz)) / area


def centroidal_inertia(mass: np.ndarray, length: np.ndarray, r2: np.ndarray) -> np.ndarray:
    """m (r² + ℓ²/12): transverse moment of inertia of a uniform tube piece about its centre,
    kg·m² — its length term and its sections' rotary inertia m r²."""
    return mass * (r2 + np.square(length) / 12.0)


def tube_moments(rho_a: np.ndarray, start: np.ndarray, end: np.ndarray, r2: np.ndarray
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Mass, first and second moments about the member's start node of a uniform tube piece
    from ``start`` to ``end`` along the member.

    Returns
    -------
    m, S, I : ndarray
        ``m = ρA ℓ``, ``S = m (start + end)/2``, ``I = ρA (end³ − start³)/3 + m r²``: the
        second moment of the line plus the rotary inertia of the sections.
    """
    m = rho_a * (end - start)
    return m, m * (start + end) / 2.0, rho_a * (end ** 3 - start ** 3) / 3.0 + m * r2


def rigid_line_mass(length: np.ndarray, unit: np.ndarray, mass: np.ndarray,
                    first_moment: np.ndarray, second_moment: np.ndarray,
                    axial_start: np.ndarray, axial_end: np.ndarray) -> np.ndarray:
    """End-node mass blocks of bodies on a member's line that follow its rigid motion.

    Transversely the bodies move with the member, ``u(s) = (1 − s/L) u_a + (s/L) u_b``, which
    gives the exact rigid-body matrix

    .. math:: M_\\perp = \\begin{bmatrix} m - 2S/L + I/L^2 & S/L - I/L^2 \\\\
              S/L - I/L^2 & I/L^2 \\end{bmatrix} \\otimes (\\mathbf 1 - e e^T)

    (m, S, I the total mass and first and second moments about the start node, I with the
    rotary inertia of the bodies about their own centres); axially ``axial_start`` moves with
    the start node and ``axial_end`` with the end node (a telescoping active member: base
    and leadscrew tube).

    Parameters
    ----------
    length : ndarray, shape (k,)
    unit : ndarray, shape (k, dim)
    mass, first_moment, second_moment : ndarray, shape (k,)
    axial_start, axial_end : ndarray, shape (k,)
        Mass carried axially by the start and the end node.

    Returns
    -------
    ndarray, shape (k, 2, dim, 2, dim)
        Block ``[i, r, :, s, :]`` couples end r with end s of body set i (global axes).
    """
    L = length
    tr = np.array([[mass - 2 * first_moment / L + second_moment / L ** 2,
                    first_moment / L - second_moment / L ** 2],
                   [first_moment / L - second_moment / L ** 2, second_moment / L ** 2]])
    zero = np.zeros_like(axial_start)
    ax = np.array([[axial_start, zero], [zero, axial_end]])              # (2, 2, k)
    P = np.einsum("ai,aj->aij", unit, unit)                               # (k, dim, dim)
    Q = np.eye(unit.shape[-1])[None] - P
    return np.einsum("rsa,aij->arisj", tr, Q) + np.einsum("rsa,aij->arisj", ax, P)
