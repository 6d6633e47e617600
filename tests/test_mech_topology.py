"""Graph topology (Vlase 2008, eq. 1–2) and the kinematically equivalent bar assembly."""
import numpy as np
import pytest

from trussfe.errors import InputError
from trussfe.kinematics import (compatibility_from_incidence, compatibility_matrix,
                                equivalent_assembly, graph_topology, incidence_matrix,
                                rank_analysis)
from trussfe.models.mechanisms import CATALOGUE


@pytest.mark.parametrize("name", sorted(CATALOGUE))
def test_cycle_matrix_relation(name):
    """Vlase eq. 2: B_f = [(−A_t⁻¹A_l)ᵀ | I] satisfies A B_fᵀ = 0, has s − r rows of rank
    s − r, entries in {−1, 0, 1}; each row is a closed cycle of the edge vectors."""
    e = CATALOGUE[name]
    ground = [i for i in e.supports if len(e.supports[i]) == e.dim] or [0]
    eq = equivalent_assembly(e.coords, e.bars, ground=ground)
    n = eq.coords.shape[0]
    t = eq.topology
    s, r = len(eq.connectivity), n - 1
    C = t.cycle_matrix
    assert C.shape == (s - r, s)
    assert set(np.unique(C)) <= {-1, 0, 1}
    np.testing.assert_array_equal(t.reduced_incidence @ C.T, 0)
    if C.shape[0]:
        assert np.linalg.matrix_rank(C) == s - r
        u = eq.coords[eq.connectivity[:, 1]] - eq.coords[eq.connectivity[:, 0]]
        np.testing.assert_allclose(C @ u, 0, atol=1e-12)   # cycles close geometrically


def test_incidence_signs():
    """+1 where the edge leaves the node, −1 where it enters (Vlase section 2.2)."""
    A = incidence_matrix(3, np.array([[0, 1], [2, 1]])).toarray()
    np.testing.assert_array_equal(A, [[1, 0], [-1, -1], [0, 1]])


@pytest.mark.parametrize("name", ["mech_bricard", "mech_sec9_space", "mech_fourbar"])
def test_compatibility_from_incidence(name):
    """The compatibility matrix is the incidence matrix expanded by the direction cosines."""
    e = CATALOGUE[name]
    np.testing.assert_allclose(compatibility_from_incidence(e.coords, e.bars).toarray(),
                               compatibility_matrix(e.coords, e.bars).toarray(), atol=1e-15)


def test_plate_triangulation_is_rigid():
    """Vlase construction I: a plate of five joints becomes 2·5 − 3 = 7 bars, rigid (3 rigid
    body motions, no mechanism, no self-stress) — in 3-D 3·5 − 6 = 9 bars."""
    rng = np.random.default_rng(0)
    for dim, nb in ((2, 7), (3, 9)):
        x = rng.normal(size=(5, dim))
        eq = equivalent_assembly(x, np.zeros((0, 2), int), ground=[0], plates=[[0, 1, 2, 3, 4]])
        assert (eq.kinds == "plate").sum() == nb
        r = rank_analysis(x, eq.connectivity, np.ones_like(x, bool))
        assert (r.mechanisms, r.self_stress_states) == (0, 0)


def test_disconnected_graph_is_an_input_error():
    with pytest.raises(InputError, match="not connected"):
        graph_topology(4, np.array([[0, 1], [2, 3]]))
