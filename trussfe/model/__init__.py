# SPDX-License-Identifier: MIT
"""The structural model: :class:`Structure`, :class:`Section`, :class:`Material`, and the typed
extension tables a model carries (active members, actuators, failure laws, post-critical
settings).  Everything here is immutable; variants are made by ``Structure.with_…`` methods."""
from .active import ActiveMember
from .actuators import Actuator
from .failure import FailureLaws
from .postcritical import PostcriticalSettings
from .properties import MemberProperties
from .sections import Material, Section
from .structure import DOF_NAMES, Structure, build_structure

__all__ = ["ActiveMember", "Actuator", "DOF_NAMES", "FailureLaws", "Material",
           "MemberProperties", "PostcriticalSettings", "Section", "Structure",
           "build_structure"]
