"""Section-6 unfolding (Hortobágyi 1999, section 6): second-order unfolding directions of a
folded assembly, the second-order prediction and the four traced unfolding shapes."""
import numpy as np
import pytest

from trussfe.errors import AnalysisError
from trussfe.kinematics import trace_mechanism
from trussfe.kinematics.compatibility import compatibility_matrix
from trussfe.kinematics.mechanism import compatibility_error
from trussfe.studies.hortobagyi import hortobagyi_section6, section6_unfolding_traces
from trussfe.kinematics.unfolding import (project_to_cone, second_order_prediction,
                                          tangent_cone)
from trussfe.models.mechanisms import section6_foldable


def _full(e, d):
    u = np.zeros(e.coords.size)
    u[np.flatnonzero(e.free.ravel())] = d
    return u.reshape(e.coords.shape)


def test_full_assembly_cannot_unfold():
    """Eight bars (section 6, Fig. 4): ρ(B) = 4, four self-stress states, no real unfolding
    direction (second-order rigid), and a trace with four prescribed increments is refused."""
    e = section6_foldable()
    c = tangent_cone(e.coords, e.bars, e.free)
    assert (c.mechanisms, c.self_stress_states, len(c.directions)) == (4, 4, 0)
    with pytest.raises(AnalysisError):
        trace_mechanism(e.coords, e.bars, e.free, [1, 3, 5, 7], [0.05, 0.02, 0.01, 0.005], 3)


@pytest.mark.parametrize("remove", [0, 2])
def test_unfolding_directions_satisfy_second_order_compatibility(remove):
    """Each direction v found has B v = 0 and Σ ω_i |Δv_i|²/l_i = 0 for every self-stress ω
    (independent check with a dense SVD of B), and all are simple roots."""
    e = section6_foldable(remove)
    c = tangent_cone(e.coords, e.bars, e.free)
    assert (c.mechanisms, c.self_stress_states) == (4, 3)
    assert len(c.directions) == 8 and c.simple.all()
    B = compatibility_matrix(e.coords, e.bars, e.free).toarray()
    U, s, _ = np.linalg.svd(B)
    Om = U[:, 4:]                                          # rank 4: self-stresses
    L = np.linalg.norm(e.coords[e.bars[:, 1]] - e.coords[e.bars[:, 0]], axis=1)
    for v in c.directions:
        np.testing.assert_allclose(B @ v, 0, atol=1e-12)
        u = _full(e, v)
        q = np.sum((u[e.bars[:, 1]] - u[e.bars[:, 0]]) ** 2, axis=1) / L
        np.testing.assert_allclose(Om.T @ q, 0, atol=1e-10)


def test_second_order_prediction_is_third_order_accurate():
    """Along an unfolding direction the prediction h v + h² w misses the bar lengths by O(h³)
    or better (halving h divides the error by at least about 8), the first-order one by O(h²)
    (about 4)."""
    e = section6_foldable(0)
    v = tangent_cone(e.coords, e.bars, e.free).directions[0]
    p = int(np.argmax(np.abs(v)))
    L = np.linalg.norm(e.coords[e.bars[:, 1]] - e.coords[e.bars[:, 0]], axis=1)
    err1, err2 = [], []
    for h in (0.02, 0.01):
        d2 = second_order_prediction(e.coords, e.bars, e.free, h * v, p)
        err2.append(np.abs(compatibility_error(e.coords, e.bars, L, _full(e, d2))).max())
        err1.append(np.abs(compatibility_error(e.coords, e.bars, L, _full(e, h * v))).max())
    assert err2[0] / err2[1] > 6.5
    assert err2[0] < 1e-3 * err1[0]
    assert 3.5 < err1[0] / err1[1] < 4.5


def test_projection_keeps_the_independent_increment():
    """A rounded prescription is moved onto the nearest unfolding direction with the largest
    increment kept (section 6: the largest displacement is the independent coordinate)."""
    e = section6_foldable(0)
    c = tangent_cone(e.coords, e.bars, e.free)
    v = c.directions[np.argmax(np.abs(c.directions[:, 1]))]
    v = v / v[1]
    rough = np.round(v, 2)
    w = project_to_cone(e.coords, e.bars, e.free, rough, 1)
    assert w[1] == pytest.approx(rough[1], rel=1e-12)
    np.testing.assert_allclose(w, v, atol=1e-9)


@pytest.mark.parametrize("remove", [0, 2])
def test_four_unfolding_shapes(remove):
    """Section 6: four prescribed vertical increments, one trace per inner joint leading; each
    unfolds to a one-degree-of-freedom finite mechanism (ρ(B) 4 → 7), keeps every bar length
    to the corrector tolerance, and the four final shapes differ (> 0.1 m apart after 0.3 m of
    lead motion)."""
    e, cone, traces = section6_unfolding_traces(remove, steps=6)
    L0 = np.linalg.norm(e.coords[e.bars[:, 1]] - e.coords[e.bars[:, 0]], axis=1)
    finals = []
    for i, (S, t) in enumerate(traces):
        assert t.rank[0] == 4 and np.all(t.rank[1:] == 7)
        assert t.events[0]["kind"] == "bifurcation" and t.events[0].get("unfolding")
        L = np.linalg.norm(t.coords[:, e.bars[:, 1]] - t.coords[:, e.bars[:, 0]], axis=2)
        assert np.abs(L - L0).max() < 1e-9
        assert np.abs(t.coords[-1, :4, 1]).max() > 0.25     # it really unfolds
        finals.append(t.coords[-1].ravel())
    F = np.array(finals)
    dist = np.linalg.norm(F[:, None] - F[None], axis=2)
    assert dist[np.triu_indices(4, 1)].min() > 0.1


def test_validation_entry_counts():
    """The validation case's dict: counts of the text (μ·j − ρ(B) = 4, four shapes, rank 7)."""
    r = hortobagyi_section6(figures=False)
    assert r["full"]["unfolding_directions"] == 0 and r["full"]["trace_refused"] == 1
    for key in ("minus1", "minus3"):
        assert r[key]["infinitesimal"] == 4 and r[key]["shapes"] == 4
        assert r[key]["rank_after_min"] == 7 and r[key]["misfit"] < 1e-9


def test_direction_count_sweep_never_gives_two():
    """Recomputed (section 6): folded states of the section-6 graph with a ground bar removed
    have 0 or 8 real unfolding directions (a flat four-bar with two branches carrying two
    dyads that open both ways or not at all), never the 2 the text's "two shapes and their
    symmetric pairs" needs.  Small deterministic sample of the documented sweep."""
    from trussfe.studies.hortobagyi import section6_direction_counts
    hist = section6_direction_counts(samples=4, seed=0)
    assert sum(hist.values()) >= 12
    assert set(hist) <= {0, 8} and 8 in hist
