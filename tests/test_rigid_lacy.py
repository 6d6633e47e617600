# SPDX-License-Identifier: MIT
"""The general sparse Newton–Euler model against Lacy's literal 11 × 11 system (eq. 2.13)."""
import numpy as np
from numpy.testing import assert_allclose

from trussfe.mechanics.conventions import THESIS
from trussfe.studies.lacy_newton_euler import lacy_triangle
from trussfe.rigid.motion import third_order_motion
from trussfe.studies.lacy_rigid import L2, L3MIN, triangular_truss
from trussfe.rigid.simulate import simulate


def test_general_model_equals_lacy_eq_2_13():
    """Same kinematics (thesis scheme), two formulations: every pin force, the reactions and
    the cantilever force agree to round-off (rtol 1e-9 of the largest force)."""
    s = triangular_truss(mass=10.0)
    m = third_order_motion(s, [L3MIN + L2], [L3MIN + 1.2 + L2], 3.0, 50)
    r = simulate(s, m, conventions=THESIS)
    x = m.length[:, 0] - L3MIN - L2
    lit = lacy_triangle(x, m.velocity[:, 0], m.acceleration[:, 0], 0.06, 10.0).forces
    fx1, fx2, fx3, fy1, fy2, fy3, rx1, rx2, ry1, ry2, m1 = lit.T
    f = r.forces.end_force
    scale = np.abs(lit).max()
    tol = dict(rtol=0, atol=1e-9 * scale)
    assert_allclose(f[:, 0, 1, :2], np.c_[fx1, fy1], **tol)      # node B on the follower
    assert_allclose(f[:, 1, 1, :2], np.c_[fx2, fy2], **tol)      # node B on the tube
    assert_allclose(r.forces.reactions[:, 1], np.c_[rx1, ry1], **tol)   # O1
    assert_allclose(r.forces.reactions[:, 0], np.c_[rx2, ry2], **tol)   # O2
    assert_allclose(r.sections.cut_force[:, 1, -1, :2], np.c_[fx3, fy3], **tol)
    assert_allclose(np.abs(r.sections.moment[:, 1, -1, 2]), np.abs(m1), **tol)


def test_lacy_matrix_is_full_rank_along_motion():
    """Eq. 2.14 needs [SM] invertible at every step (statically determinate truss)."""
    x = np.linspace(0, 1.2, 20)
    sol = lacy_triangle(x, np.zeros(20), np.zeros(20), 0.1, 10.0)
    assert np.all(np.linalg.cond(sol.matrix) < 1e6)


def test_reduced_model_equals_unreduced_117_system():
    """Double octahedron along a slew under gravity and top loads: the 117 × 117 unreduced
    Newton–Euler system (Lacy eq. 4.20 layout) and the reduced sparse model give the same
    end forces and reactions (rtol 1e-9 of the largest force)."""
    from trussfe.studies.lacy_newton_euler import newton_euler_system
    from trussfe.studies.lacy_rigid import double_octahedron
    s = double_octahedron((1.2289, 1.1079, 1.1079), gravity=-9.81, top_load=46.0)
    m = third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289], 2.0, 40)
    r = simulate(s, m)
    A, b, lay = newton_euler_system(s, r.kinematics)
    assert A.shape[1:] == (117, 117)
    x = np.linalg.solve(A, b[..., None])[..., 0]
    F = x[:, lay["end_force"]]                              # (t, m, 2, 3)
    scale = np.abs(F).max()
    assert_allclose(r.forces.end_force, F, rtol=0, atol=1e-9 * scale)
    for node, c, col in lay["reaction"]:
        assert_allclose(r.forces.reactions[:, node, c], x[:, col], rtol=0, atol=1e-9 * scale)
