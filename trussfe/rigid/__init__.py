# SPDX-License-Identifier: MIT
"""Rigid-body dynamic force model of adaptive trusses along a motion (Lacy, chapters 2–6).

Importing this package registers the ``[active_members]`` model-file table.
"""
from .active import ActiveMember, active_members
from .motion import Motion, load_motion, third_order_motion

__all__ = ["ActiveMember", "Motion", "active_members", "load_motion", "third_order_motion"]
