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

import importlib
import inspect
from types import MappingProxyType
from typing import TYPE_CHECKING

from .model import ModelLike, as_structure, model_from_dict, read_model
from .results import Result

#: Where each analysis and result type lives: imported on first use, so that a command loads
#: only the solver family it runs (start-up time of the command line).
_LAZY = MappingProxyType({
    **dict.fromkeys(("ElasticResult", "TransientResult", "elastic", "transient"),
                    "along_motion"),
    **dict.fromkeys(("MechanismResult", "TopologyResult", "TraceResult", "mechanism",
                     "topology", "trace"), "kinematic"),
    **dict.fromkeys(("BucklingResult", "LoadCasesResult", "ModesResult", "StaticResult",
                     "buckling", "modes", "static"), "linear"),
    **dict.fromkeys(("PostcriticalResult", "postcritical"), "nonlinear_path"),
    **dict.fromkeys(("ActuatorsResult", "SimulateResult", "actuators", "simulate"),
                    "rigid_body"),
    **dict.fromkeys(("Picture", "show"), "picture"),
})

#: The analyses that take a model (the validation suite's ``analysis``).
ANALYSIS_NAMES = ("static", "modes", "buckling", "simulate", "actuators", "elastic",
                  "transient", "mechanism", "trace", "topology", "postcritical")

if TYPE_CHECKING:
    from .along_motion import ElasticResult, TransientResult, elastic, transient
    from .kinematic import (MechanismResult, TopologyResult, TraceResult, mechanism,
                            topology, trace)
    from .linear import (BucklingResult, LoadCasesResult, ModesResult, StaticResult,
                         buckling, modes, static)
    from .nonlinear_path import PostcriticalResult, postcritical
    from .picture import Picture, show
    from .rigid_body import ActuatorsResult, SimulateResult, actuators, simulate


def __getattr__(name: str):
    if name in _LAZY:
        value = getattr(importlib.import_module(f"{__name__}.{_LAZY[name]}"), name)
        globals()[name] = value
        return value
    if name == "ANALYSES":
        # by command name; importing every solver family, so made on first use
        value = MappingProxyType({a: __getattr__(a) for a in ANALYSIS_NAMES})
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


def option_names(analysis: str) -> tuple[str, ...]:
    """The keyword options of one of :data:`ANALYSES`, in signature order."""
    if analysis not in ANALYSIS_NAMES:
        raise KeyError(analysis)
    return tuple(p.name for p in inspect.signature(__getattr__(analysis)).parameters.values()
                 if p.kind is inspect.Parameter.KEYWORD_ONLY)


def check_options(analysis: str, options) -> None:
    """Raise :class:`~trussfe.errors.InputError` (item ``case.options``) for an option that
    ``analysis`` does not take, suggesting the closest one."""
    from ..errors import InputError
    from ..io.suggest import suggest as _suggest

    known = option_names(analysis)
    for key in options:
        if key not in known:
            raise InputError("case.options", f"'{analysis}' has no option '{key}'"
                                             f"{_suggest(key, known)}")


__all__ = ["ANALYSES", "ANALYSIS_NAMES", "ActuatorsResult", "BucklingResult", "ElasticResult",
           "LoadCasesResult", "MechanismResult", "ModelLike", "ModesResult", "Picture",
           "PostcriticalResult", "Result", "SimulateResult", "StaticResult", "TopologyResult",
           "TraceResult", "TransientResult", "actuators", "as_structure", "buckling",
           "check_options", "elastic", "mechanism", "model_from_dict", "modes", "option_names",
           "postcritical", "read_model", "show", "simulate", "static", "topology", "trace",
           "transient"]
