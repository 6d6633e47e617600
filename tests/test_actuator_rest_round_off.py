# SPDX-License-Identifier: MIT
"""A sample at rest whose computed extension rate is round-off (1e-17 m/s) is at rest: the
physical convention gives it the torque that overcomes the static load before motion starts
(Lacy 1991 section 2.9; eq. 2.37, T = F d_m/2 tan(λ + φ)), whatever the round-off's sign."""
import math
from pathlib import Path

import numpy as np
from numpy.testing import assert_allclose

from trussfe import api
from trussfe.rigid.actuator import Actuator, motor_histories

MESHES = Path(__file__).resolve().parents[1] / "meshes"

# Square thread, self-locking (G_ls = 0.002 < μ d_m / 2 = 0.003), gearhead 1.3; Appendix A's
# motor constants.
GLS, DM, MU, GGH, RA, KT = 0.002, 0.02, 0.3, 1.3, 2.0, 0.0398
LAM, PHI = math.atan(2 * GLS / DM), math.atan(MU)                 # eq. 2.34; tan φ = μ


def raising_torque(force):
    """Screw torque to move the load against it, F d_m/2 tan(λ + φ) (eq. 2.35)."""
    return force * DM / 2 * math.tan(LAM + PHI)


def test_round_off_rate_of_either_sign_is_rest():
    """Histories that start at rest with a rate of ±1e-17 m/s (the round-off of a computed
    rate) and then move at 0.05 m/s: the first sample carries the holding torque
    F d_m/2 tan(λ + φ) / G_gh for both signs (the with-load tan(λ − φ) is negative here)."""
    a = Actuator(0, "A", GLS, DM, "square", 0.0, MU, GGH, 0.0, RA, KT, KT)
    F = np.array([20.0, 20.0])
    for v0, v1 in ((1e-17, 0.05), (-1e-17, -0.05)):
        h = motor_histories(a, F, np.array([v0, v1]), np.zeros(2))
        assert bool(h["against_load"][0])
        assert_allclose(h["motor_torque"][0], raising_torque(20.0) / GGH, rtol=1e-12)


def test_retracting_third_order_move_starts_with_the_holding_torque(tmp_path):
    """Triangular truss retracting 2.6 -> 2.52 m (third-order model, 3 s): the leadscrew
    pushes the tube outward at the start (F > 0) and the start is at rest, so the motor
    torque there is F d_m/2 tan(λ + φ) / G_gh and the voltage T R_a / K_t (eq. 2.44, no back
    emf): +0.0737 N·m and +3.70 V, not the with-load −0.0131 N·m."""
    model = tmp_path / "truss.toml"
    model.write_text((MESHES / "triangular_truss_motion_active.toml").read_text() + f"""
[actuators.active]
leadscrew_gain = {GLS}
mean_diameter = {DM}
friction = {MU}
gearhead_gain = {GGH}
armature_inertia = 6.76e-6
resistance = {RA}
torque_constant = {KT}
back_emf_constant = {KT}
convention = "physical"
""")
    motion = tmp_path / "retract.toml"
    motion.write_text('[motion]\ntype = "third-order"\nduration = 3.0\nsteps = 50\n'
                      'start = { active = 2.6 }\nend = { active = 2.52 }\n')
    d = api.simulate(model, motion=motion).to_dict()
    a = d["actuators"]["active"]
    F0, v = a["force"][0], np.asarray(a["velocity"], dtype=float)
    assert F0 > 0 and abs(v[0]) < 1e-12 * np.abs(v).max()           # at rest
    T0 = 6.76e-6 * GGH / GLS * a["acceleration"][0] + raising_torque(F0) / GGH
    assert_allclose(a["motor_torque"][0], T0, rtol=1e-12)
    assert_allclose(a["motor_voltage"][0], T0 * RA / KT + KT * GGH / GLS * v[0], rtol=1e-12)
    assert a["against_load"][0]
