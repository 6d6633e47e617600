# SPDX-License-Identifier: MIT
"""Shared test fixtures, and the global equilibrium check of every static result.

Every call of :func:`trussfe.fem.static.solve_static` made while the tests run (directly, or
through the CLI, the validation suite or any analysis that solves a static problem) returns
a result that is checked for global equilibrium — forces and moments about the origin of the
loads, self-weight and reactions sum to zero (:mod:`equilibrium`) — before the test sees it.
"""
from __future__ import annotations

import functools
import inspect
import sys

import pytest

import trussfe.fem.static as _static
from equilibrium import assert_global_equilibrium

_solve_static = _static.solve_static
_signature = inspect.signature(_solve_static)


@functools.wraps(_solve_static)
def _solve_static_in_equilibrium(*args, **kwargs):
    result = _solve_static(*args, **kwargs)
    bound = _signature.bind(*args, **kwargs)
    bound.apply_defaults()
    a = bound.arguments
    assert_global_equilibrium(result, structure=result.structure, loads=a["loads"],
                              self_weight=a["self_weight"], member_loads=a["member_loads"])
    return result


# bind the checked solver wherever the library (already imported, or imported later through
# trussfe.fem.static) refers to it
_static.solve_static = _solve_static_in_equilibrium
for _mod in list(sys.modules.values()):
    if getattr(_mod, "__name__", "").startswith("trussfe") and \
            getattr(_mod, "solve_static", None) is _solve_static:
        _mod.solve_static = _solve_static_in_equilibrium


@pytest.fixture
def equilibrium():
    """The global equilibrium check of a static result: ``equilibrium(result)`` asserts that
    loads, self-weight and reactions have zero resultant force and moment
    (:func:`equilibrium.assert_global_equilibrium`)."""
    return assert_global_equilibrium
