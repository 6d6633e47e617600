# SPDX-License-Identifier: MIT
"""Data derived from a model, kept with it.

A :class:`~trussfe.model.structure.Structure` never changes once made (a frozen dataclass
with read-only arrays), so what an analysis derives from it alone — the rigid-body analysis's
compatibility pattern, a chain's layout of bays — can be kept for the model's later analyses
and cannot go stale.  :func:`kept` keeps each such value under a name while the model exists
(weak references: the model's lifetime is not extended) and shares it read-only.
"""
from __future__ import annotations

import threading
import weakref
from collections.abc import Callable
from typing import TypeVar

import numpy as np

from .structure import Structure

T = TypeVar("T")

#: Values derived from each model, by name (:func:`kept`).
_KEPT: weakref.WeakKeyDictionary[Structure, dict[str, object]] = weakref.WeakKeyDictionary()
_LOCK = threading.Lock()


def read_only(value: T) -> T:
    """``value`` with the arrays among its attributes made read-only, those in tuples and
    lists of them included (a value shared by every later caller), and returned."""
    def freeze(a) -> None:
        if isinstance(a, np.ndarray):
            a.setflags(write=False)
        elif isinstance(a, (tuple, list)):
            for b in a:
                freeze(b)
    for a in getattr(value, "__dict__", {}).values():
        freeze(a)
    return value


def kept(structure: Structure, name: str, make: Callable[[Structure], T]) -> T:
    """The value ``make(structure)`` kept under ``name`` with ``structure``: made on first
    request, then made read-only (:func:`read_only`: every later caller shares it).

    Two threads asking at once may both make it; the first one stored is kept and returned
    to both (they are equal).
    """
    with _LOCK:
        value = _KEPT.get(structure, {}).get(name)
    if value is None:
        value = read_only(make(structure))
        with _LOCK:
            value = _KEPT.setdefault(structure, {}).setdefault(name, value)
    return value
