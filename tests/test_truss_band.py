# SPDX-License-Identifier: MIT
"""The static solve of a long truss without the global sparse K (trussfe.fem.truss_band).

Reference: the general path — the sparse K of :meth:`FEModel.stiffness` (itself checked
against closed forms and the thesis tables elsewhere) with its own band layout or SuperLU.
"""
from __future__ import annotations

import numpy as np
import pytest

from trussfe.errors import MechanismError
from trussfe.fem import discretise
from trussfe.linalg.banded import band_layout_free
from trussfe.fem.solver import factorise_truss
from trussfe.fem.static import solve_static
from trussfe.fem.truss_band import internal_forces, is_plain_truss, truss_band_layout
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.models import double_octahedral_chain


def _plane_truss(bays: int, supports: dict) -> object:
    """A 2-D truss strip of ``bays`` square bays with both diagonals, numbered bay by bay
    (node 2i at the bottom, 2i + 1 at the top of station i)."""
    x = np.arange(bays + 1, dtype=float)
    coords = np.c_[np.repeat(x, 2), np.tile([0.0, 1.0], bays + 1)]
    bars = [(2 * i, 2 * i + 1) for i in range(bays + 1)]
    for i in range(bays):
        b, t = 2 * i, 2 * i + 1
        bars += [(b, b + 2), (t, t + 2), (b, t + 2), (t, b + 2)]
    loads = {2 * (bays // 2) + 1: [0.0, -1000.0], 2 * bays: [500.0, 0.0]}
    return build_structure(coords, bars, section=Section("a", area=1e-4),
                           material=Material("s", E=2e11, G=8e10, density=7850.0),
                           supports=supports, loads=loads, gravity=[0.0, -9.81])


def test_internal_forces_equal_sparse_product():
    """K·u bar by bar equals the sparse K times u, for one vector and for several."""
    fe = discretise(double_octahedral_chain(50), "truss")
    K = fe.stiffness()
    rng = np.random.default_rng(0)
    u = rng.standard_normal(fe.n_dof)
    U = rng.standard_normal((fe.n_dof, 3))
    assert is_plain_truss(fe)
    assert np.abs(internal_forces(fe, u) - K @ u).max() <= 1e-14 * np.abs(K @ u).max()
    assert np.abs(internal_forces(fe, U) - K @ U).max() <= 1e-14 * np.abs(K @ U).max()


@pytest.mark.parametrize("supports", [
    {0: "xy", 1: "x"},                          # one end: ordering reversed
    {400: "xy", 401: "x"},                      # the other end: kept
    {200: "xy", 0: "y", 401: "y"},              # the middle and both ends
])
def test_band_from_bars_equals_band_from_K(supports):
    """The band arrays gathered from the bars equal those read from the sparse K_ff (same
    ordering and bandwidth; entries to round-off of the summation order)."""
    fe = discretise(_plane_truss(200, supports), "truss")
    a = truss_band_layout(fe, 64)
    b = band_layout_free(fe.stiffness(), fe.free, 64)
    assert a.bandwidth == b.bandwidth and np.array_equal(a.perm, b.perm)
    for x, y in ((a.upper_band(), b.upper_band()), (a.general_band(), b.general_band())):
        assert np.abs(x - y).max() <= 1e-15 * np.abs(y).max()


@pytest.mark.parametrize("supports", [{0: "xy", 1: "x"}, {60: "xy", 0: "y", 121: "y"}])
def test_static_truss_path_equals_general_path(supports):
    """solve_static's bar path (forced here with backend="banded"; "auto" takes it from 5,000
    free DOFs) gives the general path's member forces and reactions (SuperLU on the sparse
    K_ff) to the conditioning of the system (the 60-bay cantilever: both solvers' residuals
    ~1e-10, results ~6e-10 apart), and the reactions balance the loads and the self-weight."""
    s = _plane_truss(60, supports)
    fe = discretise(s, "truss")
    fast = solve_static(s, fe=fe, backend="banded")
    ref = solve_static(s, fe=discretise(s, "truss"), backend="superlu")
    assert factorise_truss(fe, "banded") is not None and factorise_truss(fe) is None
    assert fast.backend == "banded" and ref.backend == "superlu"
    scale = np.abs(ref.axial_force).max()
    assert np.abs(fast.axial_force - ref.axial_force).max() <= 1e-8 * scale
    assert np.abs(fast.reactions - ref.reactions).max() <= 1e-8 * np.abs(ref.reactions).max()
    assert np.abs(fast.u - ref.u).max() <= 1e-8 * np.abs(ref.u).max()
    assert fast.residual < 1e-9
    assert set(fast.timings) == {"assemble", "factorise", "solve", "recover"}
    total = fe.load_vector()[: 2 * s.n_nodes].reshape(-1, 2).sum(axis=0)
    assert np.allclose(fast.reactions[:, :2].sum(axis=0), -total, rtol=1e-9, atol=1e-6)


def test_chain_takes_the_truss_path():
    """With backend "auto" a 300-bay chain (5,400 free DOFs) is solved from its bars; its
    member forces equal the general path's (the chain is statically determinate)."""
    s = double_octahedral_chain(300)
    fe = discretise(s, "truss")
    assert factorise_truss(fe) is not None
    fast = solve_static(s, fe=fe)
    ref = solve_static(s, fe=discretise(s, "truss"), backend="superlu")
    scale = np.abs(ref.axial_force).max()
    assert np.abs(fast.axial_force - ref.axial_force).max() <= 1e-8 * scale


def test_truss_mechanism_is_named():
    """A truss that is a mechanism (the roller missing) is refused with the mechanisms named,
    not solved: the bar path gives way to the general one."""
    s = _plane_truss(200, {0: "xy"})              # free to rotate about node 0
    with pytest.raises(MechanismError) as err:
        solve_static(s, backend="banded")
    assert err.value.mechanisms >= 1
