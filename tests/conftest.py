# SPDX-License-Identifier: MIT
"""Shared test fixtures, and the global equilibrium check of every static result.

Every call of :func:`trussfe.fem.static.solve_static` and of
:func:`trussfe.fem.load_cases.solve_load_cases` (every case and combination) made while the
tests run (directly, or through the CLI, the validation suite or any analysis that solves a
static problem) returns a result that is checked for global equilibrium — forces and moments
about the origin of the loads, self-weight and reactions (spring forces included) sum to zero
(:mod:`equilibrium`) — before the test sees it.
"""
from __future__ import annotations

import functools
import inspect
import sys
import tempfile

import numpy as np
import pytest

import trussfe.fem.load_cases as _load_cases
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


_solve_load_cases = _load_cases.solve_load_cases


def _check_load_cases(solution):
    """Every case and combination of a load-case solution in global equilibrium: the case's
    nodal loads and (where it has them) self-weight against the reactions, spring forces
    included; imposed strains and moved supports add no external load."""
    s = solution.structure
    table = solution.load_cases
    for name, result in solution.cases.items():
        case = table.case(name)
        assert_global_equilibrium(result, structure=s, loads=case.loads,
                                  self_weight=case.gravity, force_scale=_scale(result),
                                  member_loads=case.member_loads)
    for name, result in solution.combinations.items():
        factors = solution.factors[name]
        loads = sum(f * table.case(c).loads for c, f in factors.items())
        weight = sum(f for c, f in factors.items() if table.case(c).gravity)
        member_loads = [ml.scaled(f) for c, f in factors.items()
                        for ml in table.case(c).member_loads]
        assert_global_equilibrium(result, structure=s, loads=loads,
                                  gravity=weight * s.gravity, self_weight=weight != 0,
                                  force_scale=_scale(result), member_loads=member_loads)


def _scale(result) -> float:
    """Size of the forces a case sets up: its joint loads (the equivalent loads of imposed
    strains included) and its largest member force."""
    return float(np.abs(result.f).sum() + np.abs(result.axial_force).max(initial=0.0))


@functools.wraps(_solve_load_cases)
def _solve_load_cases_in_equilibrium(*args, **kwargs):
    solution = _solve_load_cases(*args, **kwargs)
    _check_load_cases(solution)
    return solution


# bind the checked solvers wherever the library (already imported, or imported later through
# trussfe.fem.static and trussfe.fem.load_cases) refers to them
_static.solve_static = _solve_static_in_equilibrium
_load_cases.solve_load_cases = _solve_load_cases_in_equilibrium
for _mod in list(sys.modules.values()):
    if getattr(_mod, "__name__", "").startswith("trussfe"):
        if getattr(_mod, "solve_static", None) is _solve_static:
            _mod.solve_static = _solve_static_in_equilibrium
        if getattr(_mod, "solve_load_cases", None) is _solve_load_cases:
            _mod.solve_load_cases = _solve_load_cases_in_equilibrium


@pytest.fixture
def equilibrium():
    """The global equilibrium check of a static result: ``equilibrium(result)`` asserts that
    loads, self-weight and reactions have zero resultant force and moment
    (:func:`equilibrium.assert_global_equilibrium`)."""
    return assert_global_equilibrium


@pytest.fixture(scope="session", autouse=True)
def _own_temporary_folder(tmp_path_factory):
    """The system's temporary folder of the tests is a folder of this run's own: a study
    called directly hands its figures back in a new folder there (they are the caller's
    result), and pytest removes it with the run's other temporary files."""
    patch = pytest.MonkeyPatch()
    patch.setattr(tempfile, "tempdir", str(tmp_path_factory.mktemp("system-temp")))
    yield
    patch.undo()
