"""Forward position of pin-jointed assemblies from bar lengths (trussfe.kinematics.assembly)."""
import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.errors import AnalysisError
from trussfe.kinematics import compatibility_matrix, solve_positions


def _triangle(active_length):
    """Lacy's triangular truss (Appendix B): O2 = (0, 0), O1 = (2, 0), follower 2 m."""
    x0 = np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 1.5]])
    conn = np.array([[0, 2], [1, 2], [0, 1]])
    fixed = np.array([[1, 1], [1, 1], [0, 0]], dtype=bool)
    return solve_positions(x0, conn, np.array([active_length, 2.0, 2.0]), fixed)


@pytest.mark.parametrize("active", [0.5 + 2.0, 1.7 + 2.0, 2.2])
def test_triangle_apex_law_of_cosines(active):
    """Apex from the law of cosines (Lacy eq. 2.1) with L1 = L4 = 2 m."""
    r = _triangle(active)
    phi = np.arccos((2.0**2 + 2.0**2 - active**2) / (2 * 2.0 * 2.0))  # angle at O1
    expected = np.array([2.0 - 2.0 * np.cos(phi), 2.0 * np.sin(phi)])
    assert_allclose(r.coords[2], expected, rtol=1e-12)
    assert r.residual <= 1e-12 * active


def test_appendix_b_node_b():
    """Appendix B prints node 3 (B) at (1.5625, 1.9516) for the 2.5 m active member."""
    assert_allclose(_triangle(2.5).coords[2], [1.5625, 1.9516], atol=5e-5)


def test_no_assembly_names_members():
    """Bar lengths violating the triangle inequality: no assembly, members named."""
    with pytest.raises(AnalysisError, match="no assembly exists"):
        _triangle(4.5)


def test_overdetermined_consistent_square_with_diagonals():
    """A unit square with both diagonals (one redundant bar) closes by least squares."""
    x0 = np.array([[0, 0], [1, 0], [1.1, 0.9], [0.05, 1.05]], dtype=float)
    conn = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [0, 2], [1, 3]])
    L = np.array([1, 1, 1, 1, np.sqrt(2), np.sqrt(2)])
    fixed = np.array([[1, 1], [0, 1], [0, 0], [0, 0]], dtype=bool)
    r = solve_positions(x0, conn, L, fixed)
    assert_allclose(np.linalg.norm(r.coords[conn[:, 1]] - r.coords[conn[:, 0]], axis=1), L,
                    rtol=1e-11)


def test_compatibility_matches_finite_difference():
    """B d equals the first-order change of the bar lengths (Hortobágyi eq. 2)."""
    rng = np.random.default_rng(0)
    x = rng.normal(size=(6, 3))
    conn = np.array([[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [0, 3]])
    d = rng.normal(size=x.shape) * 1e-7
    B = compatibility_matrix(x, conn)
    L = lambda y: np.linalg.norm(y[conn[:, 1]] - y[conn[:, 0]], axis=1)  # noqa: E731
    assert_allclose(B @ d.ravel(), L(x + d) - L(x), rtol=1e-5, atol=1e-13)
