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

import inspect
from types import MappingProxyType

from .along_motion import ElasticResult, TransientResult, elastic, transient
from .kinematic import MechanismResult, TraceResult, mechanism, trace
from .linear import (BucklingResult, LoadCasesResult, ModesResult, StaticResult, buckling,
                     modes, static)
from .model import ModelLike, as_structure, model_from_dict, read_model
from .nonlinear_path import PostcriticalResult, postcritical
from .results import Result
from .rigid_body import ActuatorsResult, SimulateResult, actuators, simulate

#: The analyses that take a model, by command name (the validation suite's ``analysis``).
ANALYSES = MappingProxyType({
    "static": static, "modes": modes, "buckling": buckling, "simulate": simulate,
    "actuators": actuators, "elastic": elastic, "transient": transient,
    "mechanism": mechanism, "trace": trace, "postcritical": postcritical})



def option_names(analysis: str) -> tuple[str, ...]:
    """The keyword options of one of :data:`ANALYSES`, in signature order."""
    return tuple(p.name for p in inspect.signature(ANALYSES[analysis]).parameters.values()
                 if p.kind is inspect.Parameter.KEYWORD_ONLY)


def check_options(analysis: str, options) -> None:
    """Raise :class:`~trussfe.errors.InputError` (item ``case.options``) for an option that
    ``analysis`` does not take, suggesting the closest one."""
    from ..errors import InputError
    from ..io.model_file import _suggest

    known = option_names(analysis)
    for key in options:
        if key not in known:
            raise InputError("case.options", f"'{analysis}' has no option '{key}'"
                                             f"{_suggest(key, known)}")


__all__ = ["ANALYSES", "ActuatorsResult", "BucklingResult", "ElasticResult", "LoadCasesResult",
           "MechanismResult", "ModelLike", "ModesResult", "PostcriticalResult", "Result",
           "SimulateResult", "StaticResult", "TraceResult", "TransientResult",
           "actuators", "as_structure", "buckling", "check_options", "elastic",
           "mechanism", "model_from_dict", "modes", "option_names", "postcritical", "read_model", "simulate",
           "static", "trace", "transient"]
