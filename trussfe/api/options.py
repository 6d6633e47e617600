# SPDX-License-Identifier: MIT
"""Checks of analysis options given from Python (the command line's parser makes the same
checks before an option reaches the API).  Errors name the option as the command line spells
it, e.g. ``--solver``, so that a message reads the same from both.  Numbers may be numpy
scalars; a string, a bool or ``None`` where a number is needed is refused, never converted."""
from __future__ import annotations

import math
import numbers
from typing import Any

from ..errors import InputError


class ArgumentError(InputError, TypeError):
    """A call that does not match a function of the API: a keyword it does not take, an
    extra positional argument, a missing required option, or a model or file argument of a
    type it cannot take.  An :class:`~trussfe.errors.InputError` naming the argument (the
    command line refuses the same mistakes), and a :class:`TypeError`, as Python raises for
    such a call."""


def choice(option: str, value: Any, choices) -> str:
    """``value`` if it is one of ``choices``, else an :class:`InputError`."""
    if value not in choices:
        from ..io.suggest import suggest as _suggest
        raise InputError(option, f"invalid choice {value!r}{_suggest(value, list(choices))}")
    return value


def is_integer(value: Any) -> bool:
    """Whether ``value`` is an integer (numpy's included), not a bool."""
    # numpy's integers are Integral; its bool_ is not (and Python's bool is refused here)
    return isinstance(value, numbers.Integral) and not isinstance(value, bool)


def positive_int(option: str, value: Any, *, optional: bool = True) -> int | None:
    """A positive integer, numpy integers included, as an ``int`` (``None`` passes when
    ``optional``)."""
    if value is None and optional:
        return None
    if not is_integer(value) or value < 1:
        raise InputError(option, f"must be a positive integer, got {value!r}")
    return int(value)


def nonneg_int(option: str, value: Any) -> int:
    """An integer 0 or more, as an ``int``."""
    if not is_integer(value) or value < 0:
        raise InputError(option, f"must be an integer (0 or more), got {value!r}")
    return int(value)


def real(option: str, value: Any, *, positive: bool = False, nonneg: bool = False,
         nonzero: bool = False, below: float | None = None, optional: bool = True
         ) -> float | None:
    """A finite real number as a ``float`` (``None`` passes when ``optional``);
    ``positive``/``nonneg``/``nonzero`` and ``below`` restrict it (:func:`number_problem`)."""
    if value is None and optional:
        return None
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise InputError(option, f"expected a number, got {value!r}")
    x = float(value)
    problem = number_problem(x, positive=positive, nonneg=nonneg, nonzero=nonzero,
                             below=below)
    if problem:
        raise InputError(option, problem if x == 0.0 and nonzero else f"{problem}, got {x!r}")
    return x


def number_problem(x: float, *, positive: bool = False, nonneg: bool = False,
                   nonzero: bool = False, below: float | None = None) -> str:
    """What is wrong with the number ``x`` under the rules of a real option, or ``""``: the
    one statement of those rules, for the Python API (:func:`real`) and the command line's
    option types (:func:`trussfe.cli.options.real`).

    Examples
    --------
    >>> number_problem(0.0, positive=True), number_problem(0.5, below=1.0)
    ('must be positive', '')
    """
    if not math.isfinite(x):
        return "must be a finite number"
    if positive and not x > 0.0:
        return "must be positive"
    if nonneg and x < 0.0:
        return "must not be negative"
    if nonzero and x == 0.0:
        return "must not be zero"
    if below is not None and not x < below:
        return f"must be smaller than {below:g}"
    return ""


def relative_tolerance(option: str, value: Any, *, optional: bool = True) -> float | None:
    """A relative tolerance, 0 < tol < 1 (docs/bad-input.md, *Options*)."""
    return real(option, value, positive=True, below=1.0, optional=optional)


def flag(option: str, value: Any, *, optional: bool = False) -> bool | None:
    """A yes/no option: ``True`` or ``False`` (numpy's bool too; ``None`` passes when
    ``optional``) — a string such as ``"no"`` is refused, not taken as true."""
    if value is None and optional:
        return None
    import numpy as np

    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise InputError(option, f"expected True or False, got {value!r}")


def progress_callback(value: Any):
    """``None`` or a callable ``progress(done, total)``, checked before the run starts."""
    if value is None or callable(value):
        return value
    raise InputError("progress", f"expected a callable progress(done, total) or None, got "
                                 f"{value!r}")
