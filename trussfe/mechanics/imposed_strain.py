# SPDX-License-Identifier: MIT
"""Strains imposed on members without load, and the axial force that restrains them.

A member whose stress-free state differs from its place in the structure — warmed by ΔT,
given an initial strain, or made (or commanded, for an actuator) δ longer than the distance
between its joints — carries

.. math:: N = EA\\,(\\varepsilon - \\varepsilon_0), \\qquad
          \\varepsilon_0 = \\alpha\\,\\Delta T + \\varepsilon_i + \\delta / L ,

where ε is the strain of the joints' displacements.  With the joints held (ε = 0) the member
pushes on them with the fixed-end axial force ``N0 = −EA ε0`` (compression for ε0 > 0); the
displacement method applies the opposite of those end forces to the joints and adds ``N0`` to
the member force recovered from the displacements (force method and displacement method
alike: Timoshenko & Young, *Theory of Structures*, lack of fit and temperature stresses).
"""
from __future__ import annotations

import numpy as np


def imposed_strain(length: np.ndarray, *, thermal_expansion: np.ndarray | None = None,
                   delta_T: np.ndarray | None = None,
                   initial_strain: np.ndarray | None = None,
                   length_error: np.ndarray | None = None) -> np.ndarray:
    """Stress-free axial strain ε0 = αΔT + ε_i + δ/L of every member.

    Parameters
    ----------
    length : ndarray, shape (m,)
        Member lengths L, m.
    thermal_expansion, delta_T : ndarray, shape (m,), optional
        Coefficient α (1/K) and uniform temperature change ΔT (K); α may be ``nan`` where
        ΔT is 0.
    initial_strain : ndarray, shape (m,), optional
        ε_i.
    length_error : ndarray, shape (m,), optional
        δ, m (positive: the member is too long).

    Returns
    -------
    ndarray, shape (m,)

    Examples
    --------
    >>> imposed_strain(np.array([2.0]), thermal_expansion=np.array([1e-5]),
    ...                delta_T=np.array([10.0]), length_error=np.array([1e-3])).round(12)
    array([0.0006])
    """
    L = np.asarray(length, dtype=float)
    eps = np.zeros(L.shape)
    if delta_T is not None:
        dT = np.asarray(delta_T, dtype=float)
        # α is irrelevant (and may be unknown) where the member is not heated
        eps += np.where(dT != 0.0, np.asarray(thermal_expansion, dtype=float) * dT, 0.0)
    if initial_strain is not None:
        eps += np.asarray(initial_strain, dtype=float)
    if length_error is not None:
        eps += np.asarray(length_error, dtype=float) / L
    return eps


def axial_fixed_end_force(E: np.ndarray, area: np.ndarray, strain: np.ndarray) -> np.ndarray:
    """Axial force N0 = −E·A·ε0 of a member held at both ends against a stress-free strain
    ε0 (tension positive), N.

    Examples
    --------
    A steel bar (E = 200 GPa, A = 1e-4 m²) warmed by 10 K (α = 1.2e-5/K) between fixed
    walls: N0 = −EAαΔT = −2400 N.

    >>> float(axial_fixed_end_force(np.array(2e11), np.array(1e-4), np.array(1.2e-4)))
    -2400.0
    """
    return -np.asarray(E, dtype=float) * np.asarray(area, dtype=float) * np.asarray(
        strain, dtype=float)
