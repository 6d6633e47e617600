# SPDX-License-Identifier: MIT
"""Stresses of a member section under its section forces (Lacy §2.7 and §4.9).

Section forces ``N, Vy, Vz, T, My, Mz`` in member axes (N positive in tension) give

* axial stress σ_T = N / A (and strain ε = N / (E A));
* shear stress at the neutral axis τ = κ V / A with V = sqrt(Vy² + Vz²) and κ = 2, the peak
  of a thin round tube (Lacy eq. 2.23 at y₁ = 0);
* bending stress at the outer fibre, each moment with its own second moment and fibre
  distance: σ_My = My c_z / I_y (My bends the fibres at ±c_z along local z), σ_Mz = Mz c_y / I_z.

Von Mises at two points of the section (Lacy eqs. 2.24 and 2.25):

* **S1**, the neutral axis: sqrt(σ_T² + 3 τ²);
* **S2**, the outer fibre: ``|σ_T|`` + σ_M, the shear being zero there.  σ_M combines the two
  bending stresses as the section's shape requires: for a *round* section (a tube) the fibre
  of largest stress lies in the direction of the resultant moment, σ_M = sqrt(σ_My² + σ_Mz²)
  (= ``|M|`` c / I); for any other section the corner fibre carries both,
  σ_M = ``|σ_My|`` + ``|σ_Mz|`` (exact for rectangles and I-sections, an upper bound for
  other shapes).  Under bending about one axis the two rules agree.

Convention ``"lacy-per-axis"`` is the thesis' 3-D form (Lacy eqs. 4.75/4.76): each moment
component is taken at its own extreme fibre together with the shear of the component that
peaks there, S2 = max over the two axes of sqrt((``|σ_T|`` + ``|σ_My|``)² + 3 τ_y²) and
sqrt((``|σ_T|`` + ``|σ_Mz|``)² + 3 τ_z²), τ_y = κ Vy / A, τ_z = κ Vz / A.  On a tube it agrees
with ``"combined"`` up to the shear term (negligible, as the thesis notes) when the moment is about
one member axis; when it has components about both, the per-axis form takes the larger one
where the tube's extreme fibre carries their resultant (up to √2 more), so its value depends on
the member frame.  Neither form has a torsion term (the thesis has none).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from ..model.structure import Structure

#: Ways of combining the section forces into the outer-fibre von Mises stress S2.
CONVENTIONS = ("combined", "lacy-per-axis")

#: Peak shear stress of a thin round tube over V/A (Lacy eq. 2.23 at the neutral axis).
THIN_TUBE_SHEAR_COEFFICIENT = 2.0


@dataclass(frozen=True)
class SectionStresses:
    """Stresses at the section points, Pa, arrays of one shape.

    Attributes
    ----------
    axial : ndarray
        σ_T = N / A (signed, tension positive).
    shear : ndarray
        τ = κ V / A at the neutral axis (κ = 2, thin tube).
    bending : ndarray
        σ_M, the outer-fibre bending stress (see the module docstring).
    s1, s2 : ndarray
        Von Mises stress at the neutral axis (S1) and the outer fibre (S2).
    """

    axial: np.ndarray
    shear: np.ndarray
    bending: np.ndarray
    s1: np.ndarray
    s2: np.ndarray

    @property
    def von_mises(self) -> np.ndarray:
        """max(S1, S2): the section's von Mises stress."""
        return np.maximum(self.s1, self.s2)


def _ratio(moment: np.ndarray, fibre: np.ndarray, inertia: np.ndarray) -> np.ndarray:
    """M c / I, zero where no moment acts (a bar section may have no I or c)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(moment != 0, moment * (fibre / inertia), 0.0)


def von_mises(N: np.ndarray, Vy: np.ndarray, Vz: np.ndarray, My: np.ndarray, Mz: np.ndarray,
              area: np.ndarray, Iy: np.ndarray, Iz: np.ndarray, c_y: np.ndarray,
              c_z: np.ndarray, round_section: np.ndarray | bool = True, *,
              convention: str = "combined",
              shear_coefficient: float = THIN_TUBE_SHEAR_COEFFICIENT,
              shear_weight: float = 3.0) -> SectionStresses:
    """Von Mises stress at the neutral axis (S1) and the outer fibre (S2) of a section.

    Parameters
    ----------
    N, Vy, Vz, My, Mz : ndarray
        Section forces in member axes, N and N·m, all of one shape (any).  Torsion does not
        enter (Lacy has no torsion term).
    area, Iy, Iz, c_y, c_z : ndarray
        Section properties broadcastable against the forces (m², m⁴, m).  ``c_y`` and ``c_z``
        are the fibre distances along local y and z; I and c are only read where a moment
        acts, so an axial bar may leave them NaN.
    round_section : bool or ndarray of bool
        True where the section is round (a tube): the two bending stresses combine as a
        resultant, otherwise at the corner (sum).
    convention : {"combined", "lacy-per-axis"}
        S2 as in the module docstring.
    shear_coefficient : float
        κ of τ = κ V / A (2, thin round tube).
    shear_weight : float
        Factor of τ² under the root: 3 for von Mises (eq. 2.24); Lacy's Appendix A code
        uses 1, which the rigid model offers to reproduce it.

    Returns
    -------
    SectionStresses

    Examples
    --------
    A pure axial force of −78.5429 N on the tube of Lacy Table 3.2 (A = 1.1875965e-4 m²)
    gives S1 = S2 = ``|N|``/A ≈ 661,360 Pa:

    >>> import numpy as np
    >>> z = np.zeros(1)
    >>> r = von_mises(np.array([-78.5429]), z, z, z, z, 1.1875965e-4, 1.0, 1.0, 1.0, 1.0)
    >>> float(np.round(r.s1[0], -1)), bool(r.s1[0] == r.s2[0])
    (661360.0, True)
    """
    if convention not in CONVENTIONS:
        raise ValueError(f"unknown von Mises convention {convention!r}; use one of "
                         f"{', '.join(CONVENTIONS)}")
    sig_t = N / area
    tau = shear_coefficient * np.hypot(Vy, Vz) / area
    s1 = np.sqrt(sig_t ** 2 + shear_weight * tau ** 2)
    by = _ratio(My, c_z, Iy)
    bz = _ratio(Mz, c_y, Iz)
    bending = np.where(round_section, np.hypot(by, bz), np.abs(by) + np.abs(bz))
    if convention == "combined":
        s2 = np.abs(sig_t) + bending
    else:
        ty = shear_coefficient * Vy / area
        tz = shear_coefficient * Vz / area
        s2 = np.maximum(np.sqrt((np.abs(sig_t) + np.abs(by)) ** 2 + shear_weight * ty ** 2),
                        np.sqrt((np.abs(sig_t) + np.abs(bz)) ** 2 + shear_weight * tz ** 2))
    return SectionStresses(axial=sig_t, shear=tau, bending=bending, s1=s1, s2=s2)


def round_sections(sections: list) -> np.ndarray:
    """True for every section given as a tube (round), shape (len(sections),).

    Each distinct section object is asked once, so a model of many members sharing a few
    sections costs a dictionary look-up per member.
    """
    seen: dict[int, bool] = {}
    return np.fromiter((seen.setdefault(id(s), bool(s.is_tube)) for s in sections),
                       dtype=bool, count=len(sections))


def station_stresses(s: "Structure", F: np.ndarray,
                     members: np.ndarray | None = None) -> SectionStresses:
    """Von Mises stresses (Lacy eqs. 2.24, 2.25; :func:`von_mises`) of the section forces
    ``F`` (member, station, 6: N, Vy, Vz, T, My, Mz) of the ``members`` of ``s`` (all by
    default), with their sections' areas, second moments, outer-fibre distances and shapes."""
    pick = slice(None) if members is None else members
    col = lambda a: a[pick][:, None]     # member properties against (member, station)
    return von_mises(F[..., 0], F[..., 1], F[..., 2], F[..., 4], F[..., 5], col(s.area),
                     col(s.Iy), col(s.Iz), col(s.c), col(s.c),
                     col(round_sections(s.sections)))
