# SPDX-License-Identifier: MIT
"""The global equilibrium check itself (tests/equilibrium.py, applied by tests/conftest.py to
every static result): it is active, and it fails when a reaction is lost.
Source: statics (zero resultant force and moment of a body at rest)."""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import trussfe.fem.static as static
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure


def _frame():
    sec = Section.tube("t", 0.1, 0.08)
    mat = Material("steel", 2.1e11, 8.1e10, density=7850.0)
    return build_structure([[0, 0, 0], [2, 0, 0], [2, 2, 1]], [(0, 1), (1, 2)], section=sec,
                           material=mat, is_beam=True,
                           supports={0: ["x", "y", "z", "rx", "ry", "rz"], 2: "xyz"},
                           loads={1: [10.0, -20.0, 30.0, 5.0, 0.0, -7.0]},
                           gravity=[0.0, 0.0, -9.81])


def test_every_static_solve_is_checked():
    """conftest.py replaces the solver by one that checks its result."""
    assert hasattr(static.solve_static, "__wrapped__")


def test_the_check_passes_and_fails_when_it_should(equilibrium):
    """A frame under loads, end moments and self-weight balances; the same result with one
    force reaction, one moment reaction or the self-weight reactions lost does not."""
    r = static.solve_static(_frame())
    equilibrium(r)
    assert np.all(r.reactions[0, 3:] != 0)
    for i, col in ((0, 1), (0, 4), (2, 0)):
        lost = r.reactions.copy()
        lost[i, col] = 0.0
        with pytest.raises(AssertionError):
            equilibrium(dataclasses.replace(r, reactions=lost))
    weightless = static.solve_static(_frame(), self_weight=False)
    with pytest.raises(AssertionError):
        equilibrium(dataclasses.replace(r, reactions=weightless.reactions))


def test_every_load_case_solve_is_checked_and_springs_count():
    """conftest.py checks every case and combination of a load-case solution; a spring's
    force is a reaction: without it a sprung structure is out of balance."""
    import trussfe
    import trussfe.fem.load_cases as load_cases
    from equilibrium import assert_global_equilibrium
    assert hasattr(load_cases.solve_load_cases, "__wrapped__")
    s = trussfe.model_from_dict({
        "model": {"dimension": 2},
        "materials": {"st": {"E": 2e11}}, "sections": {"s": {"area": 1e-4}},
        "nodes": {"A": [0, 0], "B": [1, 0], "C": [1, 1]},
        "members": {"AB": {"nodes": ["A", "B"], "section": "s", "material": "st"},
                    "AC": {"nodes": ["A", "C"], "section": "s", "material": "st"},
                    "BC": {"nodes": ["B", "C"], "section": "s", "material": "st"}},
        "supports": {"A": ["x", "y"]}, "springs": {"B": {"y": 1e5}, "C": {"x": 2e5}},
        "load_cases": {"p": {"loads": {"C": [100.0, -50.0]}}}})
    r = load_cases.solve_load_cases(s).cases["p"]
    assert_global_equilibrium(r, loads=s.extensions["load_cases"].case("p").loads)
    lost = dataclasses.replace(r, reactions=r.reactions.copy())
    lost.reactions[1:] = 0.0                               # the spring forces dropped
    with pytest.raises(AssertionError):
        assert_global_equilibrium(lost, loads=s.extensions["load_cases"].case("p").loads)


def test_the_check_counts_member_loads(equilibrium):
    """Member loads are applied loads of the check: a frame under a trapezoidal load, a point
    force and a couple along its members balances with them, and does not without them (or
    with a load's couple dropped)."""
    from trussfe.model import MemberLoad
    s = _frame().with_extensions(member_loads=[
        MemberLoad(0, "trapezoidal", (0.0, 100.0, -200.0), (50.0, 0.0, -600.0)),
        MemberLoad(1, "point", at=0.3, force=(10.0, 0.0, -40.0), moment=(0.0, 25.0, 5.0),
                   axes="local")])
    r = static.solve_static(s)
    equilibrium(r)
    with pytest.raises(AssertionError):
        equilibrium(r, member_loads=())
    with pytest.raises(AssertionError):
        equilibrium(r, member_loads=s.extensions["member_loads"][:1])
