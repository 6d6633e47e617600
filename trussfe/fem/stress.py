# SPDX-License-Identifier: MIT
"""Member stresses from section forces (Lacy §2.7 and §4.9).

Section forces ``[N, Vy, Vz, T, My, Mz]`` (member axes, on the positive face, N positive in
tension) give

* axial stress σ_T = N / A and strain ε = N / (E A);
* von Mises at point S1 (neutral axis; Lacy eq. 2.24):  σ = sqrt(σ_T² + 3 τ²), τ = 2 V / A
  (thin tube, eq. 2.23 at y₁ = 0), V the resultant shear sqrt(Vy² + Vz²);
* von Mises at point S2 (outer fibre; eq. 2.25):  σ = |σ_T| + |σ_M|, σ_M = M c / I with the
  resultant moment, sqrt((My c/Iy)² + (Mz c/Iz)²) — exact for a circular tube.

Lacy's 3-D eqs. 4.75/4.76 add 3 τ² of one shear component at the point of maximum bending of
the other moment component; for the circular tubes of the thesis the resultant forms above
bound them from above at S2 by less than the shear term, which the thesis itself notes is
negligible.  The thesis has no torsion term; neither have these.
"""
from __future__ import annotations

import numpy as np


def von_mises(section_forces: np.ndarray, area: np.ndarray, Iy: np.ndarray, Iz: np.ndarray,
              c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Von Mises stress at the cross-section points S1 and S2.

    Parameters
    ----------
    section_forces : ndarray, shape (m, s, 6)
        ``[N, Vy, Vz, T, My, Mz]`` at ``s`` stations of ``m`` members.
    area, Iy, Iz, c : ndarray, shape (m,)
        Section properties; ``Iy``, ``Iz``, ``c`` are only used where a moment acts.

    Returns
    -------
    s1, s2 : ndarray, shape (m, s)

    Examples
    --------
    A pure axial force of −78.5429 N on the tube of Lacy Table 3.2 (A = 1.18760e-4 m²):

    >>> import numpy as np
    >>> sf = np.zeros((1, 1, 6)); sf[0, 0, 0] = -78.5429
    >>> s1, s2 = von_mises(sf, np.array([1.1875965e-4]), np.ones(1), np.ones(1), np.ones(1))
    >>> float(np.round(s1[0, 0], -1)), bool(s1[0, 0] == s2[0, 0])
    (661360.0, True)
    """
    A = np.asarray(area, float)[:, None]
    sig_t = section_forces[..., 0] / A
    V = np.hypot(section_forces[..., 1], section_forces[..., 2])
    tau = 2.0 * V / A
    s1 = np.sqrt(sig_t**2 + 3.0 * tau**2)
    My, Mz = section_forces[..., 4], section_forces[..., 5]
    with np.errstate(invalid="ignore", divide="ignore"):
        by = np.where(My != 0, My * (np.asarray(c, float) / np.asarray(Iy, float))[:, None], 0.0)
        bz = np.where(Mz != 0, Mz * (np.asarray(c, float) / np.asarray(Iz, float))[:, None], 0.0)
    s2 = np.abs(sig_t) + np.hypot(by, bz)
    return s1, s2
