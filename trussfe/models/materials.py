# SPDX-License-Identifier: MIT
"""Materials and sections the catalogue's structures share (Lacy Tables 3.1 and 5.1)."""
from __future__ import annotations

from ..model.sections import Material, Section

#: Aluminium of both of Lacy's trusses: E and G from the MSC/PAL files (Appendix B and D,
#: "Material Properties 71.e9 26.2e9 2711.5"), density 2711.5 kg/m³ (Tables 3.1, 5.1).
ALUMINIUM = Material(name="aluminium", E=71.0e9, G=26.2e9, density=2711.5)

#: One inch, m.
INCH = 0.0254


def triangular_tube() -> Section:
    """Tube of the triangular truss: OD 0.0254 m, ID 0.022225 m (Appendix B; A = 1.1876e-4 m²)."""
    return Section.tube("tube", 0.0254, 0.022225)


def octahedral_tube(inner_diameter: float = 0.015748) -> Section:
    """Tube of the double-octahedral bay: OD 0.75 in = 0.01905 m (Table 5.1).

    The inner diameter defaults to 0.62 in = 0.015748 m, which gives Appendix D's area
    9.0245e-5 m² (``Beam Type 1, 9.0245e-5``), the area behind the stresses of Tables 5.2–5.4.
    Table 5.1 prints 0.016 m and the MATLAB code uses 0.63 in (A = 8.396e-5 m², stresses
    7.5 % higher than the tables).
    """
    return Section.tube("tube", 0.01905, inner_diameter)
