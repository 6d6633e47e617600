# SPDX-License-Identifier: MIT
"""Kinematics and mechanisms: compatibility matrix, forward position, rank, motion."""
from .assembly import AssemblyResult, solve_positions, solve_structure_positions
from .compatibility import compatibility_matrix, equilibrium_matrix

__all__ = ["AssemblyResult", "compatibility_matrix", "equilibrium_matrix", "solve_positions",
           "solve_structure_positions"]
from .mechanism import compatibility_error, hortobagyi_step, pivoted_partition
from .trace import TraceResult, trace_mechanism, trace_structure
from .rank import RankResult, rank_analysis, rigid_body_modes, structure_rank
from .topology import (EquivalentAssembly, GraphTopology, compatibility_from_incidence,
                       cycle_kinematics, equivalent_assembly, graph_topology, incidence_matrix,
                       reduced_incidence_matrix)
from .velocity import bar_angular_velocity, mechanism_acceleration, mechanism_velocity
from .cycles import CycleRates, complete_cycle_matrix, cycle_rates

__all__ += ["TraceResult", "compatibility_error", "hortobagyi_step", "pivoted_partition",
            "trace_mechanism", "trace_structure", "RankResult", "rank_analysis",
            "rigid_body_modes", "structure_rank", "EquivalentAssembly", "GraphTopology",
            "compatibility_from_incidence", "cycle_kinematics", "equivalent_assembly",
            "graph_topology", "incidence_matrix", "reduced_incidence_matrix",
            "bar_angular_velocity", "mechanism_acceleration", "mechanism_velocity",
            "CycleRates", "complete_cycle_matrix", "cycle_rates"]
from .order import MechanismOrder, mechanism_order

__all__ += ["MechanismOrder", "mechanism_order"]
