# SPDX-License-Identifier: MIT
"""The structural model: :class:`Structure`, :class:`Section`, :class:`Material`, and the typed
extension tables a model carries (active members, actuators, failure laws, post-critical
settings, member loads).  Everything here is immutable; variants are made by ``Structure.with_…`` methods."""
from .active import ActiveMember
from .actuators import Actuator
from .failure import FailureLaws
from .member_loads import MemberLoad
from .postcritical import PostcriticalSettings
from .properties import MemberProperties
from .sections import Material, Section
from .structure import DOF_NAMES, Structure, build_structure

__all__ = ["ActiveMember", "Actuator", "DOF_NAMES", "FailureLaws", "Material", "MemberLoad",
           "MemberProperties", "PostcriticalSettings", "Section", "Structure",
           "build_structure"]
