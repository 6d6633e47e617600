# SPDX-License-Identifier: MIT
"""Member mechanics shared by every solver family.

Each physical quantity of a member (geometry and frames, section properties and stresses, the
Euler load, the mass, what an end release frees) is computed here, once, and asked for by the
finite-element, rigid-body, nonlinear and elastic solvers alike.
"""
