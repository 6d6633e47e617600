# SPDX-License-Identifier: MIT
"""Top-plane rotations converted to active-member lengths (Lacy section 5.5)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.errors import AnalysisError, InputError
from trussfe.kinematics import solve_positions
from trussfe.studies.lacy_rigid import EQUILIBRIUM_LENGTH, double_octahedron, triangular_truss
from trussfe.rigid.motion import third_order_response
from trussfe.rigid.slew import plane_normal, rotation_matrix, rotation_motion

SLEW1 = {"type": "rotation", "axis": "n1", "start": -10.0, "end": 10.0, "duration": 5.5,
         "steps": 40, "top_nodes": ["N7", "N8", "N9"]}


@pytest.fixture(scope="module")
def bay():
    return double_octahedron()


@pytest.fixture(scope="module")
def slew(bay):
    return rotation_motion(SLEW1, bay)


def forward(bay, q, x0):
    L = bay.lengths().copy()
    L[[bay.member_index(k) for k in ("M7_8", "M9_10", "M11_12")]] = q
    return solve_positions(x0, bay.connectivity, L, bay.translation_supports).coords


def test_lengths_give_the_prescribed_orientation(bay, slew):
    """Independent check: the forward position of the returned lengths has the top-plane
    normal R_n1(θ(t)) n̂3, θ(t) = −10° + 20° y(t) with y the third-order step response, and the
    rest height of the top centroid (1.1218 m, Appendix D), to 1e-8 (spline interpolation of the
    inverse map between grid angles)."""
    assert slew.length.shape == (40, 3)
    y, _, _ = third_order_response(slew.time, 5.5)
    theta = np.radians(-10.0 + 20.0 * y)
    x = bay.coords.copy()
    for k in range(0, 40, 3):
        x = forward(bay, slew.length[k], x)
        n = plane_normal(x[6:9])
        n = n if n[2] > 0 else -n
        target = rotation_matrix(np.array([1.0, 0, 0]), theta[k]) @ [0.0, 0.0, 1.0]
        assert_allclose(n, target, atol=1e-8)
        assert_allclose(x[6:9, 2].mean(), 1.1218, atol=1e-4)          # Appendix D height
        assert_allclose(x[6:9, 2].mean(), bay.coords[6:9, 2].mean(), atol=1e-9)


def test_mirror_symmetry_about_the_n2_n3_plane(slew):
    """A rotation about n1 keeps the bay symmetric about the n2–n3 plane, which maps M9/10 onto
    M11/12 (Lacy Fig. 4.1): their lengths agree to round-off."""
    assert_allclose(slew.length[:, 1], slew.length[:, 2], rtol=1e-10)
    assert_allclose(slew.velocity[:, 1], slew.velocity[:, 2], rtol=1e-8, atol=1e-12)


def test_zero_rotation_is_the_equilibrium_position(bay):
    """θ = 0 returns the rest lengths, 1.1684 m (Lacy section 5.4 equilibrium position)."""
    m = rotation_motion({**SLEW1, "start": 0.0, "end": 0.0, "steps": 3}, bay)
    assert_allclose(m.length, EQUILIBRIUM_LENGTH, rtol=1e-10)
    assert_allclose(m.velocity, 0.0, atol=1e-14)


def test_rates_agree_with_differences_of_the_lengths(bay):
    """q̇ and q̈ (chain rule through the spline of q(θ)) agree with central differences of the
    solved lengths over a fine time grid to 1e-4 of their peaks (differencing error O(dt²))."""
    m = rotation_motion({**SLEW1, "steps": 2000}, bay)
    t = m.time
    v_fd = np.gradient(m.length, t, axis=0)
    a_fd = np.gradient(m.velocity, t, axis=0)
    inner = slice(5, -5)
    assert np.abs(v_fd - m.velocity)[inner].max() < 1e-4 * np.abs(m.velocity).max()
    assert np.abs(a_fd - m.acceleration)[inner].max() < 1e-3 * np.abs(m.acceleration).max()


def test_mean_length_hold(bay):
    """``hold = "mean_length"`` keeps the mean active length at its rest value."""
    m = rotation_motion({**SLEW1, "hold": "mean_length", "steps": 5}, bay)
    assert_allclose(m.length.mean(axis=1), EQUILIBRIUM_LENGTH, rtol=1e-10)


def test_given_angle_profile(bay):
    """A given (time, angle) profile: a constant angle gives constant lengths."""
    m = rotation_motion({"type": "rotation", "axis": [1, 0, 0], "time": [0, 1, 2, 3, 4, 5],
                         "angle": [5.0] * 6}, bay)
    assert_allclose(m.length - m.length[0], 0.0, atol=1e-12)
    assert_allclose(m.velocity, 0.0, atol=1e-9)


@pytest.mark.parametrize("spec, exc, match", [
    ({**SLEW1, "colour": 1}, InputError, r"motion\.colour"),
    ({**SLEW1, "axis": "n7"}, InputError, r"motion\.axis"),
    ({**SLEW1, "top_nodes": ["N7", "N8", "X"]}, InputError, r"motion\.top_nodes"),
    ({**SLEW1, "hold": "width"}, InputError, r"motion\.hold"),
    ({**SLEW1, "duration": -1.0}, InputError, r"motion\.duration"),
    ({**SLEW1, "end": 80.0}, AnalysisError, r"top-plane rotation"),
])
def test_bad_rotation_specs(bay, spec, exc, match):
    with pytest.raises(exc, match=match):
        rotation_motion(spec, bay)


def test_planar_truss_is_rejected():
    with pytest.raises(InputError, match="spatial"):
        rotation_motion(SLEW1, triangular_truss())


def test_shipped_rotation_motion_file():
    """meshes/double_octahedron_tilt_rotation.toml through the motion loader: 221 samples from
    −5° to +5°, M9/10 = M11/12 by symmetry, ending at rest (constant-velocity profile)."""
    from pathlib import Path

    import trussfe.rigid.actuator  # noqa: F401
    from trussfe.io.model_file import read_model
    from trussfe.rigid.motion_file import load_motion
    meshes = Path(__file__).resolve().parents[1] / "meshes"
    s = read_model(meshes / "double_octahedron_actuators.toml")
    m = load_motion(meshes / "double_octahedron_tilt_rotation.toml", s)
    assert m.time.size == 221
    assert_allclose(m.time[-1], 5.5, rtol=1e-12)
    assert_allclose(m.length[:, 1], m.length[:, 2], rtol=1e-10)
    assert_allclose(m.velocity[[0, -1]], 0.0, atol=1e-12)
