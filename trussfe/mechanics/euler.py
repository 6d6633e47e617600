# SPDX-License-Identifier: MIT
"""Euler buckling load of a member (Lacy eq. 2.26 / 4.77).

.. math:: P_{cr} = \\frac{\\pi^2 E I}{(K L)^2}, \\qquad I = \\min(I_y, I_z),

with K the effective-length factor: 1 pinned–pinned, 0.5 fixed–fixed, 0.699 fixed–pinned,
2 fixed–free (the flagpole).  Lacy writes the same load as ``C π² E A / (l/k)²`` with the
end-condition constant C = 1/K² and the radius of gyration k = sqrt(I/A); he takes C = 1 for
the pinned–pinned members and, conservatively, for the cantilever–pinned leadscrew tube
(section 2.8).  The thesis prints ``k = sqrt(A/I)`` (a slip: that is the inverse of a radius
of gyration); his code (Appendix A: ``Pcr1 = pi^2*E*ina/l1^2``) uses sqrt(I/A), as here.

The weak axis governs: a member free to bow either way buckles about the axis of the smaller
second moment of area.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from ..model.structure import Structure


def weak_axis_inertia(Iy: np.ndarray, Iz: np.ndarray) -> np.ndarray:
    """min(Iy, Iz), the second moment of area about the weak axis, m⁴ (NaN if either is
    unknown and the other is not smaller)."""
    return np.fmin(Iy, Iz)


def euler_load(E: np.ndarray, inertia: np.ndarray, length: np.ndarray,
               effective_length_factor: np.ndarray | float = 1.0) -> np.ndarray:
    """Euler critical load π² E I / (K L)², N (Lacy eq. 2.26 with C = 1/K²).

    Parameters
    ----------
    E : ndarray
        Young's modulus, Pa.
    inertia : ndarray
        Second moment of area about the buckling (weak) axis, m⁴.
    length : ndarray
        Column length L between the supports, m.
    effective_length_factor : float or ndarray
        K (1 for pinned ends).

    Returns
    -------
    ndarray
        P_cr, broadcast over the arguments.

    Examples
    --------
    Lacy Table 3.3: the 2 m follower tube (OD 0.0254 m, ID 0.022225 m, E = 71 GPa), pinned,
    carries 1481.2 N:

    >>> from trussfe.model.sections import Section
    >>> s = Section.tube("t", 0.0254, 0.022225)
    >>> round(float(euler_load(71.0e9, s.Iy, 2.0)), 1)
    1481.2
    """
    kl = np.asarray(effective_length_factor, dtype=float) * np.asarray(length, dtype=float)
    return np.pi ** 2 * np.asarray(E, dtype=float) * np.asarray(inertia, dtype=float) / kl ** 2


def member_euler_loads(structure: Structure, length: np.ndarray | None = None,
                       effective_length_factor: np.ndarray | float = 1.0) -> np.ndarray:
    """Euler load of every member of a structure about its weak axis, shape (m,), N.

    ``length`` defaults to the member lengths (the column length of an active member is its
    leadscrew tube, which the caller passes).
    """
    L = structure.lengths() if length is None else length
    return euler_load(structure.E, weak_axis_inertia(structure.Iy, structure.Iz), L,
                      effective_length_factor)
