# SPDX-License-Identifier: MIT
"""The Python API of trussfe: one function per analysis, each returning a result object.

>>> import trussfe
>>> r = trussfe.static("meshes/triangular_truss_static.toml")     # doctest: +SKIP
>>> r.axial_force, r.member_ids                                   # doctest: +SKIP

Every function takes the model (a :class:`~trussfe.model.Structure`, a model file path or a
dict of tables, see :func:`model_from_dict`) and keyword-only options with the defaults of
the command of the same name; an unknown option is refused with a :class:`TypeError`.  The
command line and the validation suite call these functions.  docs/python.md is the guide.
"""
from __future__ import annotations

from .along_motion import elastic, transient
from .kinematic import mechanism, trace
from .linear import buckling, modes, static
from .nonlinear_path import postcritical
from .model import ModelLike, as_structure, model_from_dict, read_model
from .results import Result
from .validation import ValidationResult, validate
from .rigid_body import actuators, simulate

#: The analyses that take a model, by command name (the validation suite's ``analysis``).
ANALYSES = {"static": static, "modes": modes, "buckling": buckling, "simulate": simulate,
            "actuators": actuators, "elastic": elastic, "transient": transient,
            "mechanism": mechanism, "trace": trace, "postcritical": postcritical}

__all__ = ["ANALYSES", "ModelLike", "Result", "actuators", "as_structure", "buckling",
           "model_from_dict", "modes", "read_model", "simulate", "static",
           "elastic", "transient", "mechanism", "trace",
           "postcritical", "ValidationResult", "validate"]
