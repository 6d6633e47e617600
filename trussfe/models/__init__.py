# SPDX-License-Identifier: MIT
"""Catalogue of named reference structures, numbered as in their sources.

Each entry is a plain function returning a :class:`~trussfe.model.Structure`:

========================================  ====================================================
:func:`triangular_truss`                  Lacy ch. 2–3, Table 3.1, Appendix B
:func:`double_octahedron`                 Lacy ch. 4–5, Table 4.1, Table 5.1, Appendix D
:func:`double_octahedral_chain`           Lacy ch. 6: bays stacked top-plane-on-base
:func:`two_bar`, :func:`three_bar`        classical hand-calculation trusses
:func:`four_bar_linkage`                  planar four-bar linkage (one finite mechanism)
========================================  ====================================================

Tests, benchmarks, the shipped model files (``meshes/generate.py``) and the validation suite
all build their structures here, so a number in a thesis table and the structure that
reproduces it are tied to one definition.
"""
from .octahedral import (DOUBLE_OCTAHEDRON_MEMBERS, EQUILIBRIUM_LENGTH, SLEW_LONG, SLEW_SHORT,
                         SLEW_SHORT_PRINTED, STATED_LOAD, STROKE, TABLE_LOAD, ACTIVE_MEMBERS, double_octahedral_chain,
                         double_octahedron, slew_lengths)
from .simple import four_bar_linkage, three_bar, two_bar
from .triangular import triangular_truss

__all__ = [
    "ACTIVE_MEMBERS", "DOUBLE_OCTAHEDRON_MEMBERS", "EQUILIBRIUM_LENGTH", "SLEW_LONG",
    "SLEW_SHORT", "SLEW_SHORT_PRINTED", "STATED_LOAD", "STROKE", "TABLE_LOAD", "double_octahedral_chain",
    "double_octahedron", "four_bar_linkage", "slew_lengths", "three_bar", "triangular_truss",
    "two_bar",
]
