# SPDX-License-Identifier: MIT
"""Rigid-body dynamic force model of adaptive trusses along a motion (Lacy, chapters 2–6).

Importing this package registers the ``[active_members]`` model-file table.

Modules: :mod:`~trussfe.rigid.active` (active-member data), :mod:`~trussfe.rigid.motion`
(motions, third-order actuator model), :mod:`~trussfe.rigid.kinematics` (positions, exact or
thesis velocities and accelerations), :mod:`~trussfe.rigid.forces` (Newton–Euler pin forces),
:mod:`~trussfe.rigid.sections` (internal forces, von Mises), :mod:`~trussfe.rigid.buckling`,
:mod:`~trussfe.rigid.simulate` (orchestration), :mod:`~trussfe.rigid.output` (JSON, NPZ, VTK,
plots).  Lacy's own numbers and his literal systems are reproduced in :mod:`trussfe.studies`.
"""
from .active import ActiveMember, active_members
from .motion import Motion, third_order_motion
from .motion_file import load_motion

# ``simulate`` is not re-exported: the name is the module trussfe.rigid.simulate.
__all__ = ["ActiveMember", "Motion", "active_members", "load_motion", "third_order_motion"]
