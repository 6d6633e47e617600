# SPDX-License-Identifier: MIT
"""Motion model and kinematics checked against independent computations."""
import numpy as np
from numpy.testing import assert_allclose

from trussfe.rigid.kinematics import compute_kinematics
from trussfe.rigid.motion import third_order_motion, third_order_response
from trussfe.studies.lacy_rigid import double_octahedron, triangular_truss


def test_third_order_response_analytic_properties():
    """Relative degree 3: y, ẏ, ÿ start at 0; unit static gain; ẏ, ÿ are the derivatives
    of y (central differences, h = 1e-5 s, rtol 1e-6 of the peak)."""
    t = np.linspace(0, 3, 301)
    y, dy, ddy = third_order_response(t, 3.0)
    assert_allclose([y[0], dy[0], ddy[0]], 0.0, atol=1e-12)
    assert_allclose(third_order_response(np.array([100.0]), 3.0)[0], 1.0, rtol=1e-12)
    h = 1e-5
    yp, yp1, _ = third_order_response(t + h, 3.0)
    ym, ym1, _ = third_order_response(t - h, 3.0)
    assert_allclose((yp - ym) / (2 * h), dy, atol=1e-6 * np.abs(dy).max())
    assert_allclose((yp1 - ym1) / (2 * h), ddy, atol=1e-6 * np.abs(ddy).max())


def test_settling_with_text_constant():
    """With the text's ts = 4/(ζ ωn) the response is within 2 % of the step after 0.9 T
    (Lacy section 2.2), and the maximum velocity drops to about 0.83 m/s (checked here)."""
    t = np.linspace(2.7, 3.0, 31)
    y, _, _ = third_order_response(t, 3.0, settling_constant=4.0)
    assert np.all(np.abs(y - 1) < 0.02)
    _, dy, _ = third_order_response(np.arange(50) * 0.06, 3.0, settling_constant=4.0)
    assert_allclose(1.2 * dy.max(), 0.83, atol=0.01)


def _fd_check(structure, motion):
    """Exact node velocities and accelerations against central differences of positions.

    Central differences err by about dt²/6 times the next derivative; with the steps used
    here that is below 1e-3 of the peak value, the tolerance applied."""
    k = compute_kinematics(structure, motion)
    dt = motion.time[1] - motion.time[0]
    X = k.coords
    v_fd = (X[2:] - X[:-2]) / (2 * dt)
    a_fd = (X[2:] - 2 * X[1:-1] + X[:-2]) / dt ** 2
    d = structure.dim
    assert_allclose(k.velocity[1:-1, :, :d], v_fd, atol=1e-3 * np.abs(v_fd).max())
    assert_allclose(k.acceleration[1:-1, :, :d], a_fd, atol=1e-3 * np.abs(a_fd).max())
    # Member angular velocity: ė = ω × e.
    assert_allclose(np.cross(k.omega, k.unit), k.unit_rate, atol=1e-12)


def test_exact_kinematics_triangle():
    s = triangular_truss()
    _fd_check(s, third_order_motion(s, [2.5], [3.7], 3.0, 600, include_end=True))


def test_exact_kinematics_double_octahedron():
    s = double_octahedron((1.2289, 1.1079, 1.1079))
    m = third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289], 2.0, 600)
    _fd_check(s, m)


def test_blocked_evaluation_equals_whole_motion(monkeypatch):
    """Long motions are evaluated in blocks of steps; the results do not depend on it."""
    import trussfe.rigid.simulate as sim
    s = double_octahedron((1.2289, 1.1079, 1.1079), gravity=-9.81, top_load=46.0)
    m = third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289], 2.0, 300)
    whole = sim.simulate(s, m)
    monkeypatch.setattr(sim, "CHUNK_ENTRIES", 18 * 37)       # blocks of 37 steps
    blocked = sim.simulate(s, m)
    assert_allclose(blocked.stresses.von_mises, whole.stresses.von_mises, rtol=1e-13)
    assert_allclose(blocked.forces.reactions, whole.forces.reactions, rtol=1e-13, atol=1e-12)
    assert_allclose(blocked.actuator_force, whole.actuator_force, rtol=1e-13)
