# SPDX-License-Identifier: MIT
"""Chains analysed bay by bay (positions of every bay alone carried up the chain, then the
block substitutions up and down the chain, O(n) per step) against an independent reference:
the whole chain's compatibility and equilibrium equations assembled as one sparse matrix per
step and solved by SuperLU (``scipy.sparse.linalg.spsolve``), on chains of 1 to 12 bays, with
equal and unequal strokes; and the automatic choice of the method."""
import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from numpy.testing import assert_allclose

from trussfe.mechanics.geometry import member_lengths
from trussfe.rigid.forces import pair_loads
from trussfe.rigid.kinematics import _Pattern
from trussfe.rigid.motion import Motion, third_order_response
from trussfe.rigid.simulate import simulate
from trussfe.studies.lacy_rigid import double_octahedral_chain, double_octahedron

STEPS = 60


def _motion(structure, strokes: np.ndarray) -> Motion:
    """A third-order motion of every active member by ``strokes`` (m) over 2 s."""
    acts = np.array([a.member for a in structure.extensions["active_members"]])
    L0 = structure.lengths()[acts]
    t = np.linspace(0.0, 2.0, STEPS)
    y, dy, ddy = third_order_response(t, 2.0)
    return Motion(time=t, members=acts, length=L0 + np.outer(y, strokes),
                  velocity=np.outer(dy, strokes), acceleration=np.outer(ddy, strokes),
                  source="test")


def _strokes(n_active: int, unequal: bool) -> np.ndarray:
    """Equal strokes (+0.02 m on every first actuator of a bay, alternating in sign), or
    unequal ones: every actuator its own stroke between −0.05 and +0.06 m."""
    if unequal:
        return 0.06 * np.sin(1.0 + 2.3 * np.arange(n_active))
    d = np.zeros(n_active)
    d[0::3] = 0.02 * (-1.0) ** np.arange(d[0::3].size)
    return d


CASES = [(1, True), (2, True), (3, False), (5, True), (12, False)]


@pytest.fixture(scope="module", params=CASES, ids=[f"{n}bays-{'unequal' if u else 'equal'}"
                                                    for n, u in CASES])
def run(request):
    bays, unequal = request.param
    chain = double_octahedral_chain(bays, gravity=9.81, top_load=46.0)
    motion = _motion(chain, _strokes(len(chain.extensions["active_members"]), unequal))
    res = simulate(chain, motion, n_sections=1, method="bay-by-bay")
    return chain, motion, res


def _sparse_B(pattern: _Pattern, unit: np.ndarray, k: int) -> sp.csc_matrix:
    return sp.csc_matrix((pattern.values(unit[k:k + 1])[0], (pattern.rows, pattern.cols)),
                         shape=(pattern.m, pattern.nfree))


def test_positions_close_every_bar(run):
    """The positions found bay by bay give every member its prescribed length (1e-10 m):
    passive members their model length, active ones the motion's."""
    chain, motion, res = run
    L = member_lengths(res.kinematics.coords, chain.connectivity)
    want = np.broadcast_to(chain.lengths(), L.shape).copy()
    want[:, motion.members] = motion.length
    assert_allclose(L, want, rtol=0, atol=1e-10)
    assert res.options["method"] == "bay-by-bay"


def test_velocities_and_accelerations_match_a_sparse_solve(run):
    """Reference: ``B v = L̇`` and ``B a = L̈ − (|v_b − v_a|² − L̇²)/L`` (the bar-length
    condition differentiated) solved by SuperLU on the whole chain at every 7th step; the
    bay-by-bay kinematics agree to 1e-10 of the largest value."""
    chain, motion, res = run
    kin = res.kinematics
    pattern = _Pattern(chain)
    conn = chain.connectivity
    for k in range(0, STEPS, 7):
        B = _sparse_B(pattern, kin.unit, k)
        Ld = np.zeros(chain.n_members)
        Ldd = np.zeros(chain.n_members)
        Ld[motion.members] = motion.velocity[k]
        Ldd[motion.members] = motion.acceleration[k]
        v = spla.spsolve(B, Ld[pattern.loaded_idx])
        V = np.zeros(chain.n_nodes * 3)
        V[pattern.free_flat] = v
        vrel = V.reshape(-1, 3)[conn[:, 1]] - V.reshape(-1, 3)[conn[:, 0]]
        quad = (np.einsum("mi,mi->m", vrel, vrel) - Ld ** 2) / kin.length[k]
        a = spla.spsolve(B, (Ldd - quad)[pattern.loaded_idx])
        got_v = kin.velocity[k].ravel()[pattern.free_flat]
        got_a = kin.acceleration[k].ravel()[pattern.free_flat]
        assert_allclose(got_v, v, rtol=0, atol=1e-10 * max(np.abs(v).max(), 1e-3))
        assert_allclose(got_a, a, rtol=0, atol=1e-10 * max(np.abs(a).max(), 1e-3))


def test_member_forces_match_a_sparse_solve(run):
    """Reference: ``Bᵀ t = f`` (Lacy's nodal equations with each member's transverse forces
    eliminated) solved by SuperLU on the whole chain at every 7th step, for the motion and
    at rest; the tensions found by the back substitution down the chain agree to 1e-10 of
    the largest."""
    chain, motion, res = run
    pattern = _Pattern(chain)
    _, rhs = pair_loads(chain, res.kinematics, res.bodies)
    for k in range(0, STEPS, 7):
        Bt = _sparse_B(pattern, res.kinematics.unit, k).T.tocsc()
        for j, forces in enumerate((res.forces, res.static_forces)):
            t = spla.spsolve(Bt, rhs[k, :, j])
            got = forces.tension_end[k, pattern.loaded_idx]
            assert_allclose(got, t, rtol=0, atol=1e-10 * np.abs(t).max())


def test_global_equilibrium_at_rest(run):
    """At the first step (the motion starts at rest) the ground reactions balance the applied
    loads and the weight of the tubes, active bases and node masses: global equilibrium,
    ``Σ r + Σ P + M g = 0``."""
    chain, _, res = run
    mass = res.bodies.tube_mass.sum() + res.bodies.base_mass.sum() + chain.masses.sum()
    applied = np.asarray(chain.loads)[:, :3].sum(axis=0) + mass * np.asarray(chain.gravity)
    total = res.forces.reactions[0].sum(axis=0)
    assert mass > 1.0 and np.abs(chain.loads).max() == 46.0        # both carried
    assert_allclose(total, -applied, rtol=1e-12, atol=1e-9)


def test_bay_by_bay_equals_direct(run):
    """The direct method (Newton's method on the whole truss) gives the same results to
    1e-10 of the largest value of every field."""
    chain, motion, res = run
    d = simulate(chain, motion, n_sections=1, method="direct")
    assert d.options["method"] == "direct"
    for x, y in ((d.kinematics.coords, res.kinematics.coords),
                 (d.kinematics.acceleration, res.kinematics.acceleration),
                 (d.forces.tension_end, res.forces.tension_end),
                 (d.static_forces.tension_end, res.static_forces.tension_end),
                 (d.stresses.von_mises, res.stresses.von_mises)):
        assert_allclose(y, x, rtol=0, atol=1e-10 * np.abs(x).max())


# ------------------------------------------------------------------ the automatic choice
def test_auto_chooses_bay_by_bay_for_a_chain():
    """A chain of two or more identical bays: ``method="auto"`` (the default) runs bay by
    bay, and says so in the result's options."""
    chain = double_octahedral_chain(4, gravity=9.81)
    motion = _motion(chain, _strokes(12, True))
    assert simulate(chain, motion, n_sections=1).options["method"] == "bay-by-bay"


@pytest.mark.parametrize("why", ["single bay", "thesis scheme", "planar truss",
                                 "bays that differ"])
def test_auto_chooses_direct_otherwise(why):
    """A single bay, the thesis scheme (bay by bay needs exact kinematics), a planar truss
    and a chain whose bays are not copies of each other run the direct method."""
    from trussfe.mechanics.conventions import THESIS
    from trussfe.studies.lacy_rigid import triangular_truss

    kwargs = {}
    if why == "single bay":
        s = double_octahedron(gravity=9.81)
    elif why == "thesis scheme":
        s = double_octahedral_chain(3, gravity=9.81)
        kwargs["conventions"] = THESIS
    elif why == "planar truss":
        s = triangular_truss()
    else:
        s = double_octahedral_chain(3, gravity=9.81)
        x = np.array(s.coords)
        x[-1] += [0.01, 0.0, 0.0]                   # the top bay's last node moved
        s = s.with_coords(x)
    assert simulate(s, **kwargs).options["method"] == "direct"
