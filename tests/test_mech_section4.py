"""Hortobágyi (1999) section 4, the worked example, recomputed (l = 1).

Reference numbers are the paper's printed values (matrices to 6 digits, iterates as l/q with
3–4 digits); the converged coordinates are analytic: x = l·√(1 − 0.01) = l − l/199.499.
"""
import numpy as np
import pytest

from trussfe.studies.hortobagyi import hortobagyi_section4


@pytest.fixture(scope="module")
def res():
    return hortobagyi_section4()


def test_ranks(res):
    assert res["rank_folded"] == 2
    assert res["path1"]["rank_after"] == 3 and res["path2"]["rank_after"] == 3


def test_path1_matrices(res):
    p = res["path1"]
    np.testing.assert_allclose([p["B"]["b1_11"], p["B"]["b1_12"], p["B"]["b2_11"],
                                p["B"]["b3_21"]], [0.995037, 0.0995037, -0.995037, -1.0],
                               rtol=1e-6)
    np.testing.assert_allclose([p["B11inv"]["r1_c2"], p["B11inv"]["r3_c1"],
                                p["B11inv"]["r3_c3"]], [-1.005, -10.05, 10.0], rtol=1e-3)
    np.testing.assert_allclose(p["B11invB12"], [-0.1, 0.0, -2.0], atol=1e-12)


def test_path1_iterates(res):
    """t⁽¹⁾ = (−l/66.44, l/202, −l/50); d1⁽³⁾ = (−l/199.5, −l/186.8, −l/10.15);
    t⁽³⁾ = (l/2960, ~0, l/2060); t⁽⁴⁾ = (−l/6822, 0, −l/7019); d1⁽⁵⁾ 21-entry −l/199.6 — the
    paper's printed values, rtol 1e-3 (it prints 3–4 digits)."""
    p = res["path1"]
    np.testing.assert_allclose(p["errors"][0], [-66.44, 202, -50], rtol=1e-3)
    np.testing.assert_allclose(list(p["iterates"][2].values()), [-199.5, -186.8, -10.15],
                               rtol=1e-3)
    np.testing.assert_allclose([p["errors"][2][0], p["errors"][2][2]], [2960, 2060], rtol=1e-3)
    np.testing.assert_allclose([p["errors"][3][0], p["errors"][3][2]], [-6822, -7019], rtol=1e-3)
    assert p["iterates"][4]["21"] == pytest.approx(-199.6, rel=1e-3)


def test_path1_misprints(res):
    """t₂⁽²⁾ is l/78 835, not the printed l/80 002; d1⁽²⁾ third entry is −l/9.85 (printed
    +l/9.85); the final x2 = 2l − l/199.6 is the fifth (unconverged) iterate."""
    p = res["path1"]
    assert p["errors"][1][1] == pytest.approx(78835, rel=1e-4)
    assert p["iterates"][1]["22"] == pytest.approx(-9.85, rel=1e-3)
    assert 2 - p["fifth_iterate_x2"] == pytest.approx(1 / 199.66, rel=1e-4)


def test_path1_converged(res):
    """Converged path 1: x1 = x2 − l = l − l/199.5, y1 = y2 = −l/10 (analytic, 1e-12)."""
    p = res["path1"]
    c = np.sqrt(0.99)
    np.testing.assert_allclose([p["x1"], p["y1"], p["x2"], p["y2"]], [c, -0.1, 1 + c, -0.1],
                               rtol=1e-12)
    assert p["max_bar_misfit"] < 1e-14


def test_path2(res):
    """Path 2: node 1 stays at (l, 0); x2 = 2l − l/199.5, y2 = −l/10; t⁽¹⁾ = (l/202, 0, l/202)."""
    p = res["path2"]
    c = np.sqrt(0.99)
    np.testing.assert_allclose([p["x1"], p["x2"], p["y2"]], [1, 1 + c, -0.1], rtol=1e-12)
    assert abs(p["y1"]) < 1e-14
    np.testing.assert_allclose([p["errors"][0][0], p["errors"][0][2]], [202, 202], rtol=1e-3)
    assert p["errors"][0][1] is None


def test_newton_versus_frozen(res):
    """At ε = 1e-14 l, refreshing B11 needs 4 corrections, the paper's frozen B11 14."""
    assert res["path1"]["iterations_newton"] == 4
    assert res["path1"]["iterations_frozen"] == 14


def test_trace_takes_both_branches(res):
    """trace_mechanism from the folded state: branch 0 = path 1, branch 1 = path 2."""
    c = np.sqrt(0.99)
    b0, b1 = res["trace"]["branch0"], res["trace"]["branch1"]
    np.testing.assert_allclose([b0["x1"], b0["y1"], b0["x2"], b0["y2"]], [c, -0.1, 1 + c, -0.1],
                               rtol=1e-10)
    np.testing.assert_allclose([b1["x1"], b1["x2"], b1["y2"]], [1, 1 + c, -0.1], rtol=1e-10)
    assert b0["rank_start"] == 2 and b0["rank_end"] == 3
    assert "bifurcation" in b0["events"]
