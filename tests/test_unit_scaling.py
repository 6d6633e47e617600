# SPDX-License-Identifier: MIT
"""Invariance of the finite-element decisions under the unit of length and geometric scale.

A structure scaled by ``s`` (lengths × s, loads × s², moduli unchanged) is the same structure
written in another unit of length: its displacements are × s and its load factors unchanged,
and whether it is solved or refused as singular must not change.
"""
from __future__ import annotations

import numpy as np
import pytest

import trussfe
from trussfe.fem.discretisation import discretise
from trussfe.fem.solver import factorise, rotation_scale


def _cantilever(s: float, n: int = 4, side: float = 1e-2) -> trussfe.Structure:
    """A steel cantilever frame 1 m long of a square section ``side`` wide, loaded at its
    tip by 1 N along and across it, scaled geometrically by ``s``."""
    a = (side * s) ** 2
    nodes = {f"N{i}": [s * i / n, 0.0] for i in range(n + 1)}
    members = {f"M{i}": {"nodes": [f"N{i}", f"N{i + 1}"], "section": "sq", "material": "st",
                         "type": "beam"} for i in range(n)}
    return trussfe.model_from_dict({
        "model": {"dimension": 2},
        "materials": {"st": {"E": 2.0e11, "density": 7850.0}},
        "sections": {"sq": {"area": a, "Iz": a * a / 12.0, "c": side * s / 2.0}},
        "nodes": nodes, "members": members,
        "supports": {"N0": ["x", "y", "rz"]},
        "loads": {f"N{n}": [-s * s, -s * s, 0.0]}})


@pytest.mark.parametrize("s", [1e-4, 1e-2, 1e2, 1e4])
def test_geometric_similarity_frame_static_displacements_scale_with_length(s):
    """Geometric similarity: the frame scaled by s is solved, not refused as singular, and
    its displacements are those of the unscaled frame × s and its forces × s²."""
    ref = trussfe.static(_cantilever(1.0))
    got = trussfe.static(_cantilever(s))
    np.testing.assert_allclose(got.displacement, s * ref.displacement, rtol=1e-8,
                               atol=1e-8 * s * np.abs(ref.displacement).max())
    np.testing.assert_allclose(got.axial_force, s * s * ref.axial_force, rtol=1e-8)


@pytest.mark.parametrize("s", [1e-4, 1e4])
def test_geometric_similarity_frame_buckling_load_factor_unchanged(s):
    """Geometric similarity: loads × s² on a structure × s keep the buckling load factor."""
    ref = trussfe.buckling(_cantilever(1.0), count=1).load_factors
    got = trussfe.buckling(_cantilever(s), count=1).load_factors
    np.testing.assert_allclose(got, ref, rtol=1e-8)


def test_unit_of_length_frame_scaled_stiffness_unchanged():
    """Unit of length: the stiffness the pivot test sees is the same matrix (× s, the unit
    of N/m) in metres as in a unit 2²⁰ times smaller (about a micrometre) — rotational
    entries scale as length² against translational ones, and the factorisation measures
    rotations in a model length (a power of two, so the comparison is exact)."""
    s1 = 2.0 ** -20
    scaled = []
    for s in (1.0, s1):
        fe = discretise(_cantilever(s), "truss")
        Kff = fe.stiffness()[fe.free][:, fe.free].toarray()
        d = rotation_scale(fe, fe.free)
        assert d is not None and np.ptp(d) > 0
        scaled.append(d[:, None] * Kff * d[None, :])
    np.testing.assert_allclose(scaled[1], s1 * scaled[0], rtol=1e-9,
                               atol=1e-12 * np.abs(scaled[1]).max())


def test_scaled_factorisation_solves_the_unscaled_stiffness():
    """The factor from the scaled stiffness solves ``K_ff u = f`` itself, for one and
    several right-hand sides."""
    fe = discretise(_cantilever(1e-3), "truss")
    K = fe.stiffness()
    fac = factorise(K, fe.free, fe=fe)
    Kff = K[fe.free][:, fe.free].toarray()
    b = np.random.default_rng(1).normal(size=(fe.free.size, 2))
    for rhs in (b[:, 0], b):
        np.testing.assert_allclose(fac.solve(rhs), np.linalg.solve(Kff, rhs), rtol=1e-8,
                                   atol=1e-10 * np.abs(np.linalg.solve(Kff, b)).max())
