# SPDX-License-Identifier: MIT
"""Euler buckling check of every member along a motion (Lacy eqs. 2.26 and 4.77).

The allowable load is the Euler load π² E I / (K l)² of :mod:`trussfe.mechanics.euler`
(Lacy's C π² E I / l² with C = 1/K²): K = 1 for a pinned–pinned member, and — as Lacy chooses
conservatively — 1 for the cantilever–pinned leadscrew tube.  The column length l is the
member length for a passive member and the leadscrew-tube length for an active one (Lacy
Appendix A: ``Pcr2 = pi^2*E*ina/l2^2``).  The largest compression is the most negative axial
force over all sections and time steps (Appendix A: ``max(abs(min(tension)))``).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AnalysisError
from ..mechanics.euler import euler_load, weak_axis_inertia
from ..model.structure import Structure


@dataclass
class BucklingCheck:
    """Buckling margins of every member.

    Attributes
    ----------
    allowable : ndarray, shape (m,)
        Euler load π² E I / (K l)², N.
    column_length : ndarray, shape (m,)
        l, m.
    max_compression : ndarray, shape (m,)
        Largest compressive axial force over the motion, N (0 if never compressed).
    step : ndarray of int, shape (m,)
        Time step of the largest compression.
    margin : ndarray, shape (m,)
        allowable / max_compression (inf if never compressed).
    """

    allowable: np.ndarray
    column_length: np.ndarray
    max_compression: np.ndarray
    step: np.ndarray
    margin: np.ndarray


#: Compressions below this fraction of the largest axial force of the analysis count as none.
COMPRESSION_ROUNDOFF = 1e-10


def buckling_check(structure: Structure, tension: np.ndarray, column_length: np.ndarray,
                   effective_length_factor: np.ndarray | float = 1.0) -> BucklingCheck:
    """Allowable load, largest compression and margin of every member.

    Parameters
    ----------
    structure : Structure
    tension : ndarray, shape (nt, m, k)
        Axial force at the sections along the motion.
    column_length : ndarray, shape (m,)
    effective_length_factor : float or ndarray, shape (m,)
        K of every member (1: pinned ends, Lacy's C = 1).
    """
    inertia = weak_axis_inertia(structure.Iy, structure.Iz)
    if np.any(~np.isfinite(inertia)):
        k = int(np.flatnonzero(~np.isfinite(inertia))[0])
        raise AnalysisError(f"members.{structure.member_ids[k]}", "its section has no moment of "
                            "inertia (give Iy or tube diameters) for the buckling check")
    allow = euler_load(structure.E, inertia, column_length, effective_length_factor)
    comp = -tension.min(axis=2)                         # (time, member)
    step = comp.argmax(axis=0)
    cmax = np.maximum(comp.max(axis=0), 0.0)
    # a compression at the round-off of the member forces is none (a member that carries
    # nothing, solved to 1e-14 N, is not compressed: its margin is not 1e17)
    scale = float(np.abs(tension).max()) if tension.size else 0.0
    cmax = np.where(cmax > COMPRESSION_ROUNDOFF * scale, cmax, 0.0)
    with np.errstate(divide="ignore"):
        margin = np.where(cmax > 0, allow / np.where(cmax > 0, cmax, 1.0), np.inf)
    return BucklingCheck(allowable=allow, column_length=np.asarray(column_length, float),
                         max_compression=cmax, step=step, margin=margin)
