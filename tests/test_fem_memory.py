# SPDX-License-Identifier: MIT
"""Memory of an analysis is given back when its last reference goes: the finite-element
model and the static result hold no reference cycle (which only Python's cyclic collector
would free, leaving the arrays in use and the next analysis of a program to map fresh
memory)."""
from __future__ import annotations

import gc
import weakref

import pytest

from trussfe.fem import discretise, solve_static
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

STEEL = Material("steel", E=2.0e11, G=8.0e10, density=7850.0)
TUBE = Section.tube("tube", 0.05, 0.04)


@pytest.mark.parametrize("beam, bar_model", [(False, "truss"), (False, "pinned-beam"),
                                             (True, "truss")])
def test_model_and_result_freed_without_the_cyclic_collector(beam, bar_model):
    """Bars, pinned beams (subdivided Hermite elements) and rigid-jointed frames."""
    s = build_structure([[0.0, 0.0], [1.0, 0.0], [0.5, 0.8]], [(0, 1), (1, 2), (2, 0)],
                        section=TUBE, material=STEEL, supports={0: "xy", 1: "y"},
                        loads={2: [100.0, -300.0]}, is_beam=beam)
    solve_static(s, bar_model)                   # first use: lazy imports and caches
    gc.collect()
    gc.disable()
    try:
        fe = discretise(s, bar_model)
        r = solve_static(s, bar_model, fe=fe)
        model, result = weakref.ref(fe), weakref.ref(r)
        del fe, r
        assert model() is None and result() is None
    finally:
        gc.enable()
