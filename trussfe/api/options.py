# SPDX-License-Identifier: MIT
"""Checks of analysis options given from Python (the command line's parser makes the same
checks before an option reaches the API).  Errors name the option as the command line spells
it, e.g. ``--solver``, so that a message reads the same from both."""
from __future__ import annotations

from typing import Any

from ..errors import InputError


def choice(option: str, value: Any, choices) -> str:
    """``value`` if it is one of ``choices``, else an :class:`InputError`."""
    if value not in choices:
        from ..io.suggest import suggest as _suggest
        raise InputError(option, f"invalid choice {value!r}{_suggest(value, list(choices))}")
    return value


def positive_int(option: str, value: Any, *, optional: bool = True) -> int | None:
    """A positive integer (``None`` passes when ``optional``)."""
    if value is None and optional:
        return None
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        raise InputError(option, f"must be a positive integer, got {value!r}")
    return int(value)
