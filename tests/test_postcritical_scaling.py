"""The post-critical path does not depend on the units or the size of the model.

A model scaled geometrically by ``s`` (coordinates and lengths × s, areas × s², second
moments × s⁴, loads × s², moduli unchanged) — or restated in another consistent unit system
(mm, N, MPa) — has the same dimensionless equilibrium path: the same load factors and the
same displacements divided by ``s``.  Every decision of the path following (arc length,
convergence, step control, critical points, the stop at the largest displacement) must
therefore be unit-free; for beams this needs rotations measured in a length of the model
(:func:`trussfe.nonlinear.path.rotation_length`).
"""
from __future__ import annotations

import copy
import tomllib
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe.api import as_structure
from trussfe.nonlinear.model import NonlinearModel
from trussfe.nonlinear.path import rotation_length

MESHES = Path(__file__).resolve().parents[1] / "meshes"

#: scale name -> (length factor, force factor, modulus factor)
SCALES = {
    "1e-4": (1e-4, 1e-8, 1.0),
    "1": (1.0, 1.0, 1.0),
    "1e4": (1e4, 1e8, 1.0),
    "mm": (1e3, 1.0, 1e-6),          # mm, N, MPa
}


def _scaled(name: str, scale: str) -> dict:
    """The model file ``meshes/<name>.toml`` scaled by :data:`SCALES` ``[scale]``, including
    its ``[postcritical]`` lengths (step, largest step and displacement, imperfection)."""
    L, F, E = SCALES[scale]
    with open(MESHES / f"{name}.toml", "rb") as fh:
        d = copy.deepcopy(tomllib.load(fh))
    d["nodes"] = {k: [x * L for x in v] for k, v in d["nodes"].items()}
    d["loads"] = {k: [x * F for x in v] for k, v in d["loads"].items()}
    for mat in d["materials"].values():
        for key in ("E", "G"):
            if key in mat:
                mat[key] *= E
        mat["density"] = 0.0
    powers = {"area": 2, "outer_diameter": 1, "inner_diameter": 1, "Iz": 4, "Iy": 4, "J": 4}
    for sec in d["sections"].values():
        for key in sec:
            sec[key] *= L ** powers[key]
    pc = d.get("postcritical", {})
    for key in ("step", "max_step", "max_displacement", "imperfection"):
        if key in pc:
            pc[key] *= L
    return d


_RUNS: dict = {}


def _run(name: str, scale: str):
    """(load factors, displacements / s, events, termination) of one scaled model, cached."""
    if (name, scale) not in _RUNS:
        r = trussfe.postcritical(trussfe.model_from_dict(_scaled(name, scale)))
        _RUNS[name, scale] = (np.asarray(r.load_factors),
                              np.asarray(r.displacement) / SCALES[scale][0],
                              list(r.events), r.termination)
    return _RUNS[name, scale]


def _assert_same_path(name: str, scale: str, located_rtol: float):
    lam0, u0, ev0, _ = _run(name, "1")
    lam, u, ev, term = _run(name, scale)
    assert len(lam) == len(lam0)
    assert [e.kind for e in ev] == [e.kind for e in ev0]
    assert [e.point for e in ev] == [e.point for e in ev0]
    # the load factors of every point, the critical ones and the largest: round-off
    lam_scale = np.abs(lam0).max()
    assert_allclose(lam, lam0, rtol=1e-9, atol=1e-9 * lam_scale)
    assert_allclose([e.load_factor for e in ev], [e.load_factor for e in ev0], rtol=1e-9)
    assert_allclose(lam.max(), lam0.max(), rtol=1e-9)
    # the dimensionless displacements: round-off at the ordinary points; a critical point
    # located on a singular tangent is fixed by its load factor only to the Newton
    # tolerance, its displacement to O(sqrt(tolerance)) (as against the closed form in
    # tests/test_postcritical_validation.py), hence the looser bound there
    u_scale = np.abs(u0).max()
    located = np.zeros(len(lam0), dtype=bool)
    located[[e.point for e in ev0 if e.kind in ("limit_point", "bifurcation")]] = True
    assert_allclose(u[~located], u0[~located], rtol=0, atol=1e-9 * u_scale)
    assert_allclose(u[located], u0[located], rtol=0, atol=located_rtol * u_scale)
    return term


@pytest.mark.parametrize("scale", ["1e-4", "1e4", "mm"])
def test_von_mises_path_is_unit_free(scale):
    """The two-bar truss: 66 points, limit points at ±381.087 and the stop at the largest
    displacement (a step ends on it, to round-off) in every unit system — an exact stop test
    would take one step more at s = 1e-4 (to λ = 2060), where the last step ends 1 ulp short
    of the largest displacement."""
    term = _assert_same_path("postcritical_von_mises", scale, located_rtol=1e-5)
    lam, _, ev, _ = _run("postcritical_von_mises", scale)
    assert len(lam) == 66
    assert [e.kind for e in ev] == ["limit_point", "limit_point"]
    assert_allclose(ev[0].load_factor, 381.0871904, rtol=1e-9)
    assert_allclose(lam.max(), 1830.2512025, rtol=1e-9)
    assert term.startswith("reached the maximum displacement")


@pytest.mark.parametrize("scale", ["1e-4", "1e4", "mm"])
def test_euler_column_path_is_unit_free(scale):
    """The pinned-beam column (rotations in the DOFs): the same 76 points up to λ = 1.5 in
    every unit system — the arc length, residual norms and eigen-analysis measure rotations
    in the column's length; before, the path had 31 points in mm and at s = 1e4 and did not
    start at s = 1e-4."""
    term = _assert_same_path("postcritical_euler_column", scale, located_rtol=1e-5)
    lam, _, _, _ = _run("postcritical_euler_column", scale)
    assert len(lam) == 76
    # the last step lands on the stop (it went on to 1.5155545 past it)
    assert_allclose(lam.max(), 1.5, rtol=1e-12)
    assert term.startswith("reached the maximum load factor")


@pytest.mark.parametrize("scale", ["1e-4", "1e4"])
def test_euler_column_3d_path_is_unit_free(scale):
    """The 3-D column (multiplicative rotations): the same path at s = 1e-4 and 1e4 (norms
    mixing metres and radians would stop it at λ = 0.001 at s = 1e-4)."""
    _assert_same_path("postcritical_euler_column_3d", scale, located_rtol=1e-5)


def test_rotation_length_scales_with_the_model():
    """The length per radian is the beams' median length, exactly proportional to the
    size of the model; a 1 m column is measured as before (1)."""
    for scale in ("1", "1e-4", "mm"):
        structure = as_structure(trussfe.model_from_dict(_scaled("postcritical_euler_column",
                                                                 scale)))
        model = NonlinearModel(structure, bar_model="pinned-beam", subdivisions=4)
        assert rotation_length(model) == pytest.approx(SCALES[scale][0], rel=1e-15)
