# SPDX-License-Identifier: MIT
"""Finite elements with scikit-fem: truss and Euler–Bernoulli frame members on local axes.

>>> from trussfe.fem import discretise, solve_static  # the public entry points
"""
from .discretisation import DEFAULT_FRAME_SUBDIVISIONS, FEModel, discretise, local_axes
from .solver import factorise, solve_free
from .static import StaticResult, section_forces, solve_static, static_json

__all__ = ["DEFAULT_FRAME_SUBDIVISIONS", "FEModel", "discretise", "local_axes", "factorise",
           "solve_free", "StaticResult", "section_forces", "solve_static", "static_json"]
