# SPDX-License-Identifier: MIT
"""Geometrically nonlinear (post-critical) analysis: co-rotational elements, path following
with load, displacement and arc-length control, bifurcation detection, member failure laws,
progressive failure and the hand-over to finite-mechanism motion.

Importing the package registers the model-file tables ``[failure]`` and ``[postcritical]``.
"""
from .analysis import analyse, result_document, run_postcritical
from .buckling import apply_imperfection, linear_buckling
from .failure import FailureLaws, build_failure_laws
from .mechanism import equilibrium_form, mechanism_count
from .model import NonlinearModel
from .path import PathResult, follow_path

__all__ = ["analyse", "apply_imperfection", "build_failure_laws", "equilibrium_form",
           "FailureLaws", "follow_path", "linear_buckling", "mechanism_count", "NonlinearModel",
           "PathResult", "result_document", "run_postcritical"]
