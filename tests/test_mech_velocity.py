"""Velocities and accelerations from B v = L̇, B a = L̈ − (|v_rel|² − L̇²)/L."""
import numpy as np
import pytest

from trussfe.errors import InputError
from trussfe.kinematics import (cycle_kinematics, equivalent_assembly, mechanism_acceleration,
                                mechanism_velocity)


def test_active_bar_polar_closed_form():
    """A telescopic bar from a fixed pivot, length r with ṙ = 0.3, r̈ = −0.2, its end moving
    tangentially at r·θ̇ (θ̇ = 1.5, θ̈ = 0.4): polar kinematics give the radial acceleration
    r̈ − r θ̇² and the tangential one r θ̈ + 2 ṙ θ̇ (exact, 1e-12)."""
    r, rd, rdd, w, al, th = 2.0, 0.3, -0.2, 1.5, 0.4, 0.6
    e = np.array([np.cos(th), np.sin(th)])
    n = np.array([-np.sin(th), np.cos(th)])
    x = np.array([[0.0, 0.0], r * e])
    conn = np.array([[0, 1]])
    free = np.array([[0, 0], [1, 1]], bool)
    v_ref = rd * e + r * w * n
    a_ref = (rdd - r * w ** 2) * e + (r * al + 2 * rd * w) * n
    # prescribe the tangential component through the coordinate of largest |n|
    k = int(np.argmax(np.abs(n)))
    v = mechanism_velocity(x, conn, free, {2 + k: v_ref[k]}, length_rates=np.array([rd]))
    np.testing.assert_allclose(v[1], v_ref, rtol=1e-12)
    a = mechanism_acceleration(x, conn, free, v, {2 + k: a_ref[k]},
                               length_rates=np.array([rd]), length_accelerations=np.array([rdd]))
    np.testing.assert_allclose(a[1], a_ref, rtol=1e-12)


def test_cycle_method_is_planar_only():
    x = np.zeros((3, 3))
    x[1, 0] = x[2, 1] = 1.0
    eq = equivalent_assembly(x, np.array([[0, 1], [1, 2]]), ground=[0, 2])
    with pytest.raises(InputError, match="planar"):
        cycle_kinematics(eq, drive_edge=0, omega=1.0)
