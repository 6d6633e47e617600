# SPDX-License-Identifier: MIT
"""The studies build on the one catalogue: Lacy's numbering and orientation applied on top of
:mod:`trussfe.models` give the same structure (geometry to rounding, same loads and active
members), and renumbering moves every per-node datum with its node."""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe.models as M
from trussfe.errors import InputError
from trussfe.studies import lacy_rigid
from trussfe.studies.numbering import renumber_nodes, reverse_members


def test_triangle_is_the_catalogue_entry_in_appendix_a_numbering():
    """Same apex (eq. 2.1 against the catalogue's forward-position solve, 1e-14 m), nodes
    O2, O1, B, the follower from O1 to B, the active member from O2 (its base) to B."""
    cat = M.triangular_truss(0.4, lumped_mass=10.0, member_weight=True, active_members=True)
    s = lacy_rigid.triangular_truss(0.4)
    assert list(s.node_ids) == ["O2", "O1", "B"]
    for nid in s.node_ids:
        assert_allclose(s.coords[s.node_index(nid)], cat.coords[cat.node_index(nid)],
                        rtol=0, atol=1e-14)
        assert_allclose(s.masses[s.node_index(nid)], cat.masses[cat.node_index(nid)])
    assert [s.node_ids[i] for i in s.connectivity[s.member_index("follower")]] == ["O1", "B"]
    assert [s.node_ids[i] for i in s.connectivity[s.member_index("active")]] == ["O2", "B"]
    assert s.extensions["active_members"] == cat.extensions["active_members"]
    assert_allclose(s.gravity, [0.0, -9.81])


def test_bay_is_the_catalogue_entry_in_appendix_c_orientation():
    """Same node positions (1e-14 m), section area (1e-15 relative), loads and active members
    as the catalogue bay; exactly the members of APPENDIX_C_REVERSED run the other way."""
    lengths = (1.1079, 1.2289, 1.2289)
    cat = M.double_octahedron(lengths, 44.498, gravity=[0, 0, 9.81], active_members=True)
    s = lacy_rigid.double_octahedron(lengths, top_load=44.498, gravity=-9.81)
    assert list(s.node_ids) == list(cat.node_ids)
    assert list(s.member_ids) == list(cat.member_ids)
    assert_allclose(s.coords, cat.coords, rtol=0, atol=1e-14)
    assert_allclose(s.area, cat.area, rtol=1e-15)
    assert_allclose(s.loads, cat.loads)
    assert_allclose(s.gravity, cat.gravity)
    assert s.extensions["active_members"] == cat.extensions["active_members"]
    flipped = [m for i, m in enumerate(s.member_ids)
               if not np.array_equal(s.connectivity[i], cat.connectivity[i])]
    assert flipped == list(lacy_rigid.APPENDIX_C_REVERSED)
    i = s.member_index("M9_10")
    assert [s.node_ids[k] for k in s.connectivity[i]] == ["N6", "N5"]   # base at N6 (u93)


def test_chain_has_every_bays_active_members():
    c = lacy_rigid.double_octahedral_chain(3)
    acts = [c.member_ids[a.member] for a in c.extensions["active_members"]]
    assert acts == [f"b{k}.{m}" for k in (1, 2, 3) for m in M.ACTIVE_MEMBERS]
    assert c.n_members == 54 and (~c.translation_supports.any(axis=1)).sum() == 18


def test_renumber_moves_node_data_with_the_nodes():
    s = M.triangular_truss(load=(1.0, -98.1), lumped_mass=3.0)
    r = renumber_nodes(s, ["B", "O1", "O2"])
    for nid in s.node_ids:
        i, j = s.node_index(nid), r.node_index(nid)
        assert_allclose(r.coords[j], s.coords[i])
        assert_allclose(r.loads[j], s.loads[i])
        assert r.masses[j] == s.masses[i]
        assert (r.supports[j] == s.supports[i]).all()
    assert_allclose(r.lengths(), s.lengths())
    with pytest.raises(InputError, match="renumber_nodes.order"):
        renumber_nodes(s, ["B", "B", "O2"])


def test_reverse_swaps_releases_with_the_ends():
    s = M.triangular_truss(split_active=True)
    r = reverse_members(s, ["active_base"])
    i = s.member_index("active_base")
    assert (r.connectivity[i] == s.connectivity[i][::-1]).all()
    assert (r.releases[i] == s.releases[i][::-1]).all()
    assert_allclose(r.lengths(), s.lengths())
