# SPDX-License-Identifier: MIT
"""Per-node tables of the extensions built in Python have the model's node shape.

A load case's ``loads`` and ``prescribed`` of shape (nodes, dim) — forces without moments —
are widened to (nodes, DOFs per node), as ``Structure.with_loads`` widens loads, and solve as
the same loads given in full; any other shape, and springs of another shape, are refused when
the model is built, not met as a broadcasting error inside an analysis.
"""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe.model.load_cases import LoadCase, LoadCases
from trussfe.model.node_supports import Springs

MODEL = "meshes/triangular_truss_static.toml"


@pytest.fixture
def truss():
    from pathlib import Path
    return trussfe.read_model(Path(__file__).resolve().parents[1] / MODEL)


def _with_case(s, loads):
    return s.variant(extensions={"load_cases": LoadCases(
        cases=(LoadCase("live", loads=loads),), combinations=())})


def test_forces_without_moments_are_widened(truss):
    """The case's (nodes, 2) loads equal the model's own [loads] (98.1 N down at B): the same
    member forces as the model without cases."""
    ndof = truss.loads.shape[1]
    case = _with_case(truss, truss.loads[:, :2])
    assert case.extensions["load_cases"].cases[0].loads.shape == (truss.n_nodes, ndof)
    r = trussfe.static(case)
    assert_allclose(r.cases["live"].axial_force, trussfe.static(truss).axial_force,
                    rtol=1e-14)


@pytest.mark.parametrize("shape", [(2, 2), (3, 4), (3,)])
def test_other_load_shapes_are_refused(truss, shape):
    with pytest.raises(ValueError, match="loads"):
        _with_case(truss, np.zeros(shape))


def test_springs_of_another_shape_are_refused(truss):
    with pytest.raises(ValueError, match="springs"):
        truss.variant(extensions={"springs": Springs(np.zeros((2, truss.loads.shape[1])))})


def test_a_member_named_twice_in_one_entry_is_refused(tmp_path):
    """``temperature = [{ members = ["active", "active"], delta_T = 30 }]`` would heat the
    member twice (entries add up): refused, naming the file, the entry and the member; two
    entries naming it add up as documented."""
    from pathlib import Path
    src = (Path(__file__).resolve().parents[1] / MODEL).read_text()
    base = (src.replace("[loads]\nB = [0.0, -98.1]\n", "")
            .replace("[materials.aluminium]\n",
                     "[materials.aluminium]\nthermal_expansion = 2.3e-5\n"))
    twice = base + ('\n[load_cases.heat]\ntemperature = '
                    '[{ members = ["active", "active"], delta_T = 30.0 }]\n')
    path = tmp_path / "twice.toml"
    path.write_text(twice)
    with pytest.raises(trussfe.InputError, match=r"twice.toml: load_cases.heat.temperature"
                                                 r"\[0\].members: member 'active' is named twice"):
        trussfe.read_model(path)
    two = base + ('\n[load_cases.heat]\ntemperature = [{ member = "active", delta_T = 30.0 }, '
                  '{ members = ["active"], delta_T = 30.0 }]\n')
    path.write_text(two)
    case = trussfe.read_model(path).extensions["load_cases"].cases[0]
    assert case.delta_T[list(trussfe.read_model(path).member_ids).index("active")] == 60.0
