# SPDX-License-Identifier: MIT
"""A mechanism in a long chain of bays is named by the nodes that move in it.

The smallest eigenvalues of a long chain's scaled stiffness are its bending modes (~N⁻⁴ for N
bays, below the null tolerance 1e-10 from ~160 double-octahedral bays): counted as
mechanisms, they added phantom mechanisms whose moving nodes were the whole chain, and beyond
a few thousand bays the shift-invert eigen-solver did not finish.  The expected counts are
hand counts: a node held by two collinear bars in 3-D can move in the two directions across
them, and nothing else moves.
"""
from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from trussfe.errors import MechanismError
from trussfe.fem import solve_static
from trussfe.linalg.banded import band_layout, band_null_space
from trussfe.model.structure import Structure
from trussfe.models import double_octahedral_chain


def _chain_with_collinear_node(n_bays: int) -> Structure:
    """The chain with one member, halfway up, cut in two at a new node "X"."""
    s = double_octahedral_chain(n_bays)
    k = s.n_members // 2
    a, b = s.connectivity[k]
    coords = np.vstack([s.coords, 0.5 * (s.coords[a] + s.coords[b])])
    x = coords.shape[0] - 1
    conn = np.vstack([np.delete(s.connectivity, k, axis=0), [[a, x], [x, b]]])
    m = conn.shape[0]
    n = coords.shape[0]
    supports = np.zeros((n, s.supports.shape[1]), dtype=bool)
    supports[:-1] = s.supports
    loads = np.zeros((n, s.loads.shape[1]))
    loads[:-1] = s.loads
    return Structure(
        name="chain", dim=3, node_ids=list(s.node_ids) + ["X"], coords=coords,
        member_ids=[f"m{i}" for i in range(m)], connectivity=conn,
        sections=[s.sections[0]] * m, materials=[s.materials[0]] * m,
        is_beam=np.zeros(m, bool), releases=np.zeros((m, 2), bool), supports=supports,
        loads=loads, masses=np.zeros(n), gravity=np.zeros(3))


@pytest.mark.parametrize("n_bays", [200, 5000])
def test_collinear_node_deep_in_a_long_chain_is_the_only_moving_node(n_bays):
    with pytest.raises(MechanismError) as info:
        solve_static(_chain_with_collinear_node(n_bays))
    err = info.value
    assert err.mechanisms == 2
    assert err.moving_nodes == ["X"]
    assert "2 independent mechanisms" in str(err) and "moving nodes: X;" in str(err)


def test_band_null_space_of_a_spring_chain_cut_in_two():
    """Two free spring chains: each translates rigidly (2 null vectors), exactly."""
    n = 400
    main = np.full(n, 2.0)
    main[[0, n - 1, 199, 200]] = 1.0
    off = -np.ones(n - 1)
    off[199] = 0.0
    K = sp.diags([off, main, off], [-1, 0, 1], format="csr")
    V, complete = band_null_space(band_layout(K), 1e-10)
    assert complete and V.shape == (n, 2)
    assert np.abs(K @ V).max() <= 1e-12
    # the null space is spanned by the two pieces' translations
    pieces = np.zeros((n, 2))
    pieces[:200, 0] = 1.0
    pieces[200:, 1] = 1.0
    coef = np.linalg.lstsq(pieces, V, rcond=None)[0]
    assert np.abs(pieces @ coef - V).max() <= 1e-12


def test_band_null_space_stops_at_the_requested_number():
    n = 50
    K = sp.diags([np.ones(n)], [0], format="csr").tolil()
    K[10, 10] = 0.0
    K[20, 20] = 0.0
    K[30, 30] = 0.0
    V, complete = band_null_space(band_layout(K.tocsr()), 1e-10, max_vectors=2)
    assert not complete and V.shape == (n, 2)
    assert set(np.flatnonzero(np.abs(V).max(axis=1) > 0)) <= {10, 20, 30}
