# SPDX-License-Identifier: MIT
"""Bay-by-bay chain forces (Lacy chapter 6: reactions passed down the chain) against the
direct analysis of the whole chain as one structure (the rigid-body force model)."""
import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.rigid.chain import chain_forces, stack_bays
from trussfe.rigid.forces import member_bodies
from trussfe.rigid.motion import Motion, third_order_response
from trussfe.studies.lacy_rigid import EQUILIBRIUM_LENGTH, double_octahedron
from trussfe.rigid.simulate import simulate

NB = 3
#: Different forces on the top bay's N7, N8, N9 (checks the node mapping between bays).
TOP = np.array([[0.0, 0.0, -46.0], [5.0, 0.0, -30.0], [0.0, -8.0, -20.0]])


@pytest.fixture(scope="module")
def case():
    bay = double_octahedron(gravity=9.81)          # standing chain, member and actuator weight
    t = np.linspace(0.0, 2.0, 6)
    y, dy, ddy = third_order_response(t, 2.0)
    amp = np.array([[0.05, -0.03, 0.01], [-0.04, 0.02, 0.06], [0.03, 0.05, -0.05]])
    L = EQUILIBRIUM_LENGTH + y[:, None, None] * amp
    Ld, Ldd = dy[:, None, None] * amp, ddy[:, None, None] * amp
    bbb = chain_forces(bay, t, L, Ld, Ldd, TOP)
    chain = stack_bays(bay, NB).with_gravity(bay.gravity)
    top_nodes = [chain.node_index(f"N{i}.{NB}") for i in (7, 8, 9)]
    loads = np.array(chain.loads)
    loads[top_nodes, :3] = TOP
    chain = chain.with_loads(loads)
    acts = np.array([a.member for a in chain.extensions["active_members"]])
    motion = Motion(t, acts, L.reshape(t.size, -1), Ld.reshape(t.size, -1),
                    Ldd.reshape(t.size, -1), source="test")
    res = simulate(chain, motion)
    return bbb, res


def test_member_forces_agree(case):
    """Every member's axial force at its end node, every step: bay by bay = direct, to 1e-10 of
    the largest force (round-off)."""
    bbb, res = case
    direct = res.forces.tension_end
    assert_allclose(bbb.tension_end, direct, atol=1e-10 * np.abs(direct).max())


def test_ground_reactions_agree(case):
    """The first bay's base reactions are the chain's ground reactions, and they balance the
    weight and the applied loads at rest (first step: the third-order motion starts at rest
    with zero acceleration)."""
    bbb, res = case
    assert_allclose(bbb.base_reactions[:, 0], res.forces.reactions[:, :3],
                    atol=1e-10 * np.abs(res.forces.reactions).max())
    bodies = member_bodies(res.structure)       # tubes (ρ A L_tube) and active bases
    weight = (bodies.tube_mass.sum() + bodies.base_mass.sum()) * 9.81
    total = bbb.base_reactions[0, 0].sum(axis=0)
    assert_allclose(total, -TOP.sum(axis=0) + [0.0, 0.0, weight], rtol=1e-12, atol=1e-9)


def test_agrees_with_the_shipped_chain_builder():
    """Against the whole chain (the catalogue chain in Appendix C's member orientation,
    ``trussfe.studies.lacy_rigid.double_octahedral_chain``) analysed directly along the same
    motion: every member force agrees with the bay-by-bay result to 1e-10 of the largest."""
    from trussfe.studies.lacy_rigid import double_octahedral_chain
    nb = 3
    chain = double_octahedral_chain(nb, top_load=-46.0, gravity=9.81)
    bay = double_octahedron(gravity=9.81)
    t = np.linspace(0.0, 2.0, 5)
    y, dy, ddy = third_order_response(t, 2.0)
    amp = np.array([[0.04, -0.02, 0.01], [0.0, 0.03, -0.03], [-0.05, 0.02, 0.02]])
    L = EQUILIBRIUM_LENGTH + y[:, None, None] * amp
    Ld, Ldd = dy[:, None, None] * amp, ddy[:, None, None] * amp
    acts = np.array([a.member for a in chain.extensions["active_members"]])
    res = simulate(chain, Motion(t, acts, L.reshape(t.size, -1), Ld.reshape(t.size, -1),
                                 Ldd.reshape(t.size, -1), source="test"))
    bbb = chain_forces(bay, t, L, Ld, Ldd, np.array([[0.0, 0.0, -46.0]] * 3))
    names = [f"b{k}.{mid}" for k in range(1, nb + 1) for mid in bay.member_ids]
    cols = [chain.member_index(n) for n in names]
    direct = res.forces.tension_end[:, cols]
    assert_allclose(bbb.tension_end, direct, atol=1e-10 * np.abs(direct).max())
