# SPDX-License-Identifier: MIT
"""The structural model: :class:`Structure`, :class:`Section`, :class:`Material`."""
from .sections import Material, Section
from .structure import DOF_NAMES, Structure, build_structure

__all__ = ["DOF_NAMES", "Material", "Section", "Structure", "build_structure"]
