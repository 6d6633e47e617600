# SPDX-License-Identifier: MIT
"""Elastic response of an adaptive truss along a prescribed large motion.

The rigid-body model (:mod:`trussfe.rigid`) gives the kinematics of every member along a
maneuver; this package loads the finite-element model (:mod:`trussfe.fem`) in the current
configuration with gravity and the d'Alembert inertial loads of that motion: quasi-statically
(member section forces compared with the rigid-body internal forces, member strains) and
dynamically (the elastic vibration superposed on the prescribed motion).
"""
