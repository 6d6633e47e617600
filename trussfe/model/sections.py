# SPDX-License-Identifier: MIT
"""Cross-section and material properties.

A section is either a hollow circular tube given by its diameters or a set of explicit
properties.  Properties that a section does not define are ``nan``; the analyses that need
them (bending, buckling) check for that and say which section lacks what.
"""
from __future__ import annotations

from dataclasses import dataclass
import math


@dataclass(frozen=True)
class Section:
    """Cross-section properties of a member.

    Attributes
    ----------
    name : str
        Section id in the model file.
    area : float
        Cross-sectional area A, m².
    Iy, Iz : float
        Second moments of area about the local y and z axes, m⁴ (``nan`` if unknown).
    J : float
        Torsion constant (polar moment for a tube), m⁴ (``nan`` if unknown).
    c : float
        Distance from the neutral axis to the outermost fibre, m (``nan`` if unknown).
    outer_diameter, inner_diameter : float
        Tube diameters, m (``nan`` for explicit sections).
    shear_area_y, shear_area_z : float
        Effective shear areas κA for shear along the local y and z axes, m² (``nan``: no
        shear deformation, an Euler–Bernoulli beam).  Bending about z (deflection along y)
        uses ``shear_area_y``; bending about y uses ``shear_area_z``.
    """

    name: str
    area: float
    Iy: float = math.nan
    Iz: float = math.nan
    J: float = math.nan
    c: float = math.nan
    outer_diameter: float = math.nan
    inner_diameter: float = math.nan
    shear_area_y: float = math.nan
    shear_area_z: float = math.nan

    @classmethod
    def tube(cls, name: str, outer_diameter: float, inner_diameter: float = 0.0) -> "Section":
        """Hollow circular tube.

        Notes
        -----
        A = π(D² − d²)/4, I = π(D⁴ − d⁴)/64, J = 2I, c = D/2.  With D = 0.0254 m and
        d = 0.022225 m (Lacy, Appendix B) A = 1.1876e-4 m², the area behind the von Mises
        stresses of Table 3.2.

        Examples
        --------
        >>> s = Section.tube("t", 0.0254, 0.022225)
        >>> round(s.area, 10)
        0.0001187596
        """
        D, d = float(outer_diameter), float(inner_diameter)
        area = math.pi * (D * D - d * d) / 4.0
        inertia = math.pi * (D**4 - d**4) / 64.0
        return cls(name=name, area=area, Iy=inertia, Iz=inertia, J=2.0 * inertia, c=D / 2.0,
                   outer_diameter=D, inner_diameter=d)

    @property
    def is_tube(self) -> bool:
        """True for a section defined by its tube diameters."""
        return not math.isnan(self.outer_diameter)

    @property
    def is_timoshenko(self) -> bool:
        """True for a shear-deformable (Timoshenko) section: a shear area is given."""
        return not (math.isnan(self.shear_area_y) and math.isnan(self.shear_area_z))

    @property
    def radius_of_gyration(self) -> float:
        """k = sqrt(I/A) about the weaker axis (Lacy eq. 2.26)."""
        return math.sqrt(min(self.Iy, self.Iz) / self.area)


@dataclass(frozen=True)
class Material:
    """Isotropic linear-elastic material.

    Attributes
    ----------
    name : str
        Material id in the model file.
    E : float
        Young's modulus, Pa.
    G : float
        Shear modulus, Pa (default E / 2.6).
    density : float
        Mass density, kg/m³.
    yield_strength : float
        Yield strength, Pa (``nan`` if not given).
    thermal_expansion : float
        Coefficient of linear thermal expansion α, 1/K (``nan`` if not given; a temperature
        load needs it).
    """

    name: str
    E: float
    G: float
    density: float = 0.0
    yield_strength: float = math.nan
    thermal_expansion: float = math.nan
