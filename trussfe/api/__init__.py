# SPDX-License-Identifier: MIT
"""The Python API of trussfe: one function per analysis, each returning a result object.

>>> import trussfe
>>> r = trussfe.static("meshes/triangular_truss_static.toml")     # doctest: +SKIP
>>> r.axial_force, r.member_ids                                   # doctest: +SKIP

Every function takes the model (a :class:`~trussfe.model.Structure`, a model file path or a
dict of tables, see :func:`model_from_dict`) and keyword-only options with the defaults of
the command of the same name.  A call that does not match (an unknown option, an extra
positional argument, a missing required option, a model that is not a structure, path or
dict) raises :class:`~trussfe.api.options.ArgumentError`: a
:class:`~trussfe.errors.InputError` naming the argument that is also a :class:`TypeError`.
The command line and the validation suite call these functions.  docs/python.md is the guide.
"""
from __future__ import annotations

import functools
import importlib
import inspect
import os
from collections.abc import Mapping
from types import MappingProxyType
from typing import TYPE_CHECKING, Any, Callable

from ..model.structure import Structure
from . import model as _model
from .model import ModelLike
from .options import ArgumentError
from .results import Result


def _is_path(value: Any) -> bool:
    return isinstance(value, (str, os.PathLike))


def _is_motion(value: Any) -> bool:
    if value is None or _is_path(value):
        return True
    from ..rigid.motion import Motion
    return isinstance(value, Motion)


#: The arguments whose type is checked before a call: name -> (test, what it must be).
_ARGUMENT_TYPES: dict[str, tuple[Callable[[Any], bool], str]] = {
    "model": (lambda v: isinstance(v, (Structure, Mapping)) or _is_path(v),
              "a Structure, a model file path or a dict of tables"),
    "motion": (_is_motion, "a motion file path, a Motion or None"),
    "png": (_is_path, "a file path"),
    "results": (lambda v: v is None or isinstance(v, (Mapping, Result)) or _is_path(v),
                "a static Result, its to_dict() document, a results file path or None"),
    "base_dir": (_is_path, "a folder path"),
    "path": (_is_path, "a model file path"),
}


def _call_error(name: str, signature: inspect.Signature, args: tuple, kwargs: dict,
                error: TypeError) -> ArgumentError:
    """The :class:`ArgumentError` of a call of ``name`` that ``signature`` cannot bind."""
    from ..io.suggest import suggest as _suggest

    params = signature.parameters
    takes_kwargs = any(p.kind is p.VAR_KEYWORD for p in params.values())
    unknown = [] if takes_kwargs else [k for k in kwargs if k not in params]
    if unknown:
        key = unknown[0]
        options = [p.name for p in params.values() if p.kind is p.KEYWORD_ONLY]
        return ArgumentError(key, f"{name}() got an unexpected keyword argument '{key}'"
                                  + (_suggest(key, options) if options
                                     else f"; {name}() takes no options"))
    positional = [p.name for p in params.values()
                  if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    if len(args) > len(positional):
        return ArgumentError(f"{name}()", f"takes {len(positional)} positional argument(s) "
                             f"({', '.join(positional)}) but {len(args)} were given; give "
                             "the options by keyword")
    given = set(positional[:len(args)]) | set(kwargs)
    missing = [p.name for p in params.values()
               if p.default is p.empty and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)
               and p.name not in given]
    if missing:
        return ArgumentError(missing[0], f"{name}() is missing the required argument "
                                         f"'{missing[0]}'")
    return ArgumentError(f"{name}()", str(error))


def _checked_call(fn: Callable) -> Callable:
    """``fn`` refusing, as an :class:`ArgumentError`, a call that does not match its
    signature and a model, motion or file argument of a type it cannot take (checked before
    the run starts)."""
    signature = inspect.signature(fn)
    name = fn.__name__

    @functools.wraps(fn)
    def call(*args, **kwargs):
        try:
            bound = signature.bind(*args, **kwargs)
        except TypeError as exc:
            raise _call_error(name, signature, args, kwargs, exc) from None
        for key, value in bound.arguments.items():
            rule = _ARGUMENT_TYPES.get(key)
            if rule is not None and not rule[0](value):
                raise ArgumentError(key, f"the {key} must be {rule[1]}, not "
                                         f"{type(value).__name__}")
        return fn(*args, **kwargs)
    # found where it is offered, trussfe.api.NAME (pickle finds it there by name)
    call.__module__, call.__qualname__ = __name__, name
    return call


as_structure = _checked_call(_model.as_structure)
model_from_dict = _checked_call(_model.model_from_dict)
read_model = _checked_call(_model.read_model)

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
        if inspect.isfunction(value):
            value = _checked_call(value)
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
    """The keyword options of one of :data:`ANALYSES`, in signature order (an
    :class:`~trussfe.errors.InputError`, item ``analysis``, for another name)."""
    if analysis not in ANALYSIS_NAMES:
        from ..errors import InputError
        from ..io.suggest import suggest as _suggest
        raise InputError("analysis", f"unknown analysis {analysis!r}"
                                     f"{_suggest(analysis, ANALYSIS_NAMES)}")
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
