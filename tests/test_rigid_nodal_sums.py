# SPDX-License-Identifier: MIT
"""Member-end vectors summed at the nodes (trussfe.rigid.forces._to_nodes with a plan of
node_sums: the nodal sums of the Newton-Euler equations, Lacy eq. 4.20) equal the product
with the node-member incidence matrix (scipy.sparse, summing each node's ends in the same
order) to the last bit, for all nodes and for a subset, on a model with nodes of different
degrees and an isolated node; and to each node's left-to-right sum of its ends, signed zeros
included."""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from trussfe.rigid.forces import _to_nodes, node_sums
from trussfe.studies.lacy_rigid import double_octahedral_chain


def _incidence_sum(conn, n, at_start, at_end):
    m = conn.shape[0]
    inc = sp.csr_matrix((np.ones(2 * m), (conn.T.ravel(), np.arange(2 * m))), shape=(n, 2 * m))
    stacked = np.concatenate([at_start, at_end], axis=1)
    nt = stacked.shape[0]
    out = inc @ stacked.transpose(1, 0, 2).reshape(2 * m, -1)
    return np.asarray(out).reshape(n, nt, 3).transpose(1, 0, 2)


def test_nodal_sums_equal_the_incidence_product():
    rng = np.random.default_rng(3)
    chain = double_octahedral_chain(4).connectivity
    # an extra node (index n) with no member, and members listed in a shuffled order
    n = int(chain.max()) + 2
    conn = chain[rng.permutation(chain.shape[0])]
    conn[::3] = conn[::3, ::-1]
    at_start, at_end = rng.standard_normal((2, 7) + conn.shape[:1] + (3,)) * 10.0 ** \
        rng.integers(-8, 8, size=(2, 7, conn.shape[0], 1))
    want = _incidence_sum(conn, n, at_start, at_end)
    np.testing.assert_array_equal(_to_nodes(node_sums(conn, n), at_start, at_end), want)
    nodes = np.array([n - 1, 0, 5, 2])
    np.testing.assert_array_equal(_to_nodes(node_sums(conn, n, nodes), at_start, at_end), want[:, nodes])
    assert not want[:, n - 1].any()


def test_nodal_sums_of_another_connectivity_of_the_same_size_and_components_first():
    """A second connectivity of the same shape (members reversed, shuffled) sums by its own
    grouping, and member-end vectors stored components first (trussfe.vectors) give the same
    sums to the last bit."""
    from trussfe.vectors import components_first, is_components_first
    rng = np.random.default_rng(5)
    chain = double_octahedral_chain(3).connectivity
    n = int(chain.max()) + 1
    at_start, at_end = rng.standard_normal((2, 6) + chain.shape[:1] + (3,))
    for conn in (chain, chain[rng.permutation(chain.shape[0])][:, ::-1].copy()):
        want = _incidence_sum(conn, n, at_start, at_end)
        np.testing.assert_array_equal(_to_nodes(node_sums(conn, n), at_start, at_end), want)
        got = _to_nodes(node_sums(conn, n), components_first(at_start),
                        components_first(at_end))
        np.testing.assert_array_equal(got, want)
        assert is_components_first(got)


def test_nodal_sums_are_left_to_right_sums_with_signed_zeros():
    """Each node's sum is its ends added left to right (start ends by member, then end ends
    by member), the sign of a zero included: ends that are all −0 sum to −0 (the static
    loads' components across gravity are −0 exactly), a node without ends to +0."""
    rng = np.random.default_rng(7)
    conn = double_octahedral_chain(2).connectivity
    n = int(conn.max()) + 2                                   # the last node has no member
    nt, m = 5, conn.shape[0]
    at_start, at_end = rng.standard_normal((2, nt, m, 3))
    zero = rng.random((2, nt, m, 3)) < 0.6                    # many exact zeros, both signs
    sign = np.where(rng.random((2, nt, m, 3)) < 0.5, -0.0, 0.0)
    at_start = np.where(zero[0], sign[0], at_start)
    at_end = np.where(zero[1], sign[1], at_end)
    at_start[:, :, 0] = -0.0                                  # x components all −0
    at_end[:, :, 0] = -0.0
    want = np.zeros((nt, n, 3))
    for k in range(n - 1):
        ends = ([at_start[:, j] for j in np.flatnonzero(conn[:, 0] == k)]
                + [at_end[:, j] for j in np.flatnonzero(conn[:, 1] == k)])
        acc = ends[0].copy()
        for x in ends[1:]:
            acc = acc + x
        want[:, k] = acc
    got = _to_nodes(node_sums(conn, n), at_start, at_end)
    np.testing.assert_array_equal(got, want)
    np.testing.assert_array_equal(np.signbit(got), np.signbit(want))
    assert np.all(np.signbit(got[:, :n - 1, 0])) and not np.any(np.signbit(got[:, n - 1]))
