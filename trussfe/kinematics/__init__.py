# SPDX-License-Identifier: MIT
"""Kinematics and mechanisms: compatibility matrix, forward position, rank, motion."""
from .assembly import AssemblyResult, solve_positions, solve_structure_positions
from .compatibility import compatibility_matrix, equilibrium_matrix

__all__ = ["AssemblyResult", "compatibility_matrix", "equilibrium_matrix", "solve_positions",
           "solve_structure_positions"]
