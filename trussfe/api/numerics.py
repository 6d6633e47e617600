# SPDX-License-Identifier: MIT
"""Floating-point failures of an analysis as one error, not warnings and infinities.

An overflow, a division by zero or an invalid operation in an analysis means input far out
of range (a modulus in the wrong unit, a strain of 1e300): numpy would warn and carry ``inf``
or ``nan`` into the result.  Every analysis function of the API runs with numpy's
floating-point errors raised — a setting of the calling thread's context for the duration of
the call, restored after it (``numpy.errstate``), so the caller's own setting is left as it
is — and turns them into one :class:`~trussfe.errors.AnalysisError` naming the model.
"""
from __future__ import annotations

import functools
import os
from collections.abc import Mapping
from typing import Any, Callable, TypeVar

import numpy as np

from ..errors import UNITS_ADVICE, AnalysisError, one_line

#: What a numerical overflow in a run usually means, appended to its message.
UNITS_HINT = f"a value is out of the range of floating-point numbers; {UNITS_ADVICE}"

F = TypeVar("F", bound=Callable[..., Any])


def failure_message(exc: BaseException) -> str:
    """The message of a run stopped by the floating-point failure ``exc`` (the analyses', the
    command line's and a study's)."""
    return f"numerical failure ({one_line(str(exc), 200)}): {UNITS_HINT}"


def numerical_failure(item: str, exc: BaseException) -> AnalysisError:
    """The error of a run stopped by a floating-point failure ``exc``, naming ``item``."""
    return AnalysisError(item, failure_message(exc))


def model_item(model: Any) -> str:
    """What an error about ``model`` names: the model file, or the model's name."""
    if isinstance(model, (str, os.PathLike)):
        return os.fspath(model)
    if isinstance(model, Mapping):
        head = model.get("model")
        name = head.get("name") if isinstance(head, Mapping) else None
    else:
        name = getattr(model, "source", None) or getattr(model, "name", None)
    return str(name) if name else "model"


def numerics_checked(fn: F) -> F:
    """Run the analysis ``fn(model, ...)`` with floating-point errors raised (underflow to
    zero is harmless and left alone) and raise them as one :class:`AnalysisError`."""
    @functools.wraps(fn)
    def run(model, *args, **kwargs):
        try:
            with np.errstate(over="raise", divide="raise", invalid="raise", under="ignore"):
                return fn(model, *args, **kwargs)
        except (FloatingPointError, OverflowError) as exc:
            raise numerical_failure(model_item(model), exc) from None
    return run  # type: ignore[return-value]
