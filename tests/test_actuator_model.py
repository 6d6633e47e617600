# SPDX-License-Identifier: MIT
"""Actuator and motor model (Lacy section 2.9, 3.7, 4.11): leadscrew, armature, motor."""
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.errors import AnalysisError, InputError
from trussfe.io.extension_tables import parse_actuator
from trussfe.rigid.actuator import (Actuator, max_leadscrew_gain, motor_histories,
                                    select_gearhead_gain, thread_ratio)
from trussfe.rigid.motion import third_order_response

NAN = math.nan



def make(**kw) -> Actuator:
    """Lacy's prototype actuator (Table 5.1 / Appendix C: G_ls = 2.5266e-4 m/rad, G_gh = 5.2,
    μ = 0.1, d_m = 0.0127 m, J_m = 6.76e-6 kg·m², R_a = 2 Ω, K_t = K_b = 0.0398)."""
    d = dict(member=0, name="M7_8", leadscrew_gain=2.5266e-4, mean_diameter=0.0127,
             thread="square", thread_angle=0.0, friction=0.1, gearhead_gain=5.2,
             armature_inertia=6.76e-6, resistance=2.0, torque_constant=0.0398,
             back_emf_constant=0.0398)
    d.update(kw)
    return Actuator(**d)


def thread_equilibrium(F, lam, mu, alpha, against):
    """Independent check: solve the unrolled-thread force balance (Lacy eqs. 2.30–2.31, with
    the flank normal tilted by the thread angle as in Shigley) for P and N; T = P d_m/2."""
    s = 1.0 if against else -1.0
    # P − N(cos α sin λ + s μ cos λ) = 0 ;  F − N(cos α cos λ − s μ sin λ) = 0
    A = np.array([[1.0, -(math.cos(alpha) * math.sin(lam) + s * mu * math.cos(lam))],
                  [0.0, -(math.cos(alpha) * math.cos(lam) - s * mu * math.sin(lam))]])
    P, _ = np.linalg.solve(A, [0.0, -F])
    return P


def test_self_locking_limit_and_gearhead_gain_of_the_base_simulation():
    """Lacy section 3.7: μ = 0.3, d_m = 0.02 m → G_ls,max = 0.003 m/rad (eq. 2.45); the Base
    Simulation's largest extension rate (third-order model, T = 3 s, 1.2 m, 50 samples) and a
    400 rad/s motor give G_gh = 0.9618 (eq. 3.1)."""
    assert_allclose(max_leadscrew_gain(0.3, 0.02), 0.003, rtol=1e-12)
    _, dy, _ = third_order_response(np.arange(50) * 0.06, 3.0)
    vmax = 1.2 * dy.max()
    assert_allclose(vmax, 1.2477, rtol=5e-5)                         # Lacy section 3.7
    assert_allclose(select_gearhead_gain(0.003, 400.0, vmax), 0.9618, rtol=5e-5)


@pytest.mark.parametrize("alpha_deg", [0.0, 14.5, 30.0])
@pytest.mark.parametrize("against", [True, False])
def test_thread_torque_matches_force_balance(alpha_deg, against):
    """Eqs. 2.35–2.38 equal the solved force balance of the unrolled thread (P d_m/2 per F d_m/2),
    to round-off (rtol 1e-12)."""
    gl, dm, mu = 2.5266e-4, 0.0127, 0.1
    lead = 2 * math.pi * gl
    lam = math.atan(lead / (math.pi * dm))                           # eq. 2.34
    alpha = math.radians(alpha_deg)
    P = thread_equilibrium(1.0, lam, mu, alpha, against)
    # With the load eqs. 2.36/2.38 give the torque in the sense of the motion, i.e. −P.
    assert_allclose(thread_ratio(lead, dm, mu, alpha, against), P if against else -P,
                    rtol=1e-12)


def test_square_thread_is_tan_lambda_plus_phi():
    """Against the load T = F d_m/2 tan(λ + φ), with it F d_m/2 tan(φ − λ), tan φ = μ
    (Shigley's power-screw result that eqs. 2.35/2.36 restate)."""
    lead, dm, mu = 0.005, 0.02, 0.2
    lam, phi = math.atan(lead / (math.pi * dm)), math.atan(mu)
    assert_allclose(thread_ratio(lead, dm, mu, 0.0, True), math.tan(lam + phi), rtol=1e-12)
    assert_allclose(thread_ratio(lead, dm, mu, 0.0, False), math.tan(phi - lam), rtol=1e-12)


def test_frictionless_power_balance():
    """μ = 0, physical convention: mechanical power T_m θ̇_m = F Ẋ + J_m θ̈_m θ̇_m and electrical
    power V I = R I² + T_m θ̇_m (energy conservation; rtol 1e-12)."""
    a = make(friction=0.0, require_self_locking=False)
    t = np.linspace(0, 1, 11)
    F = 50.0 * np.cos(3 * t) - 10.0
    v = 0.02 * np.sin(2 * t)
    acc = 0.04 * np.cos(2 * t)
    h = motor_histories(a, F, v, acc)
    w = h["motor_speed"]
    assert_allclose(w, 5.2 / 2.5266e-4 * v, rtol=1e-12)                # eq. 2.28
    mech = h["motor_torque"] * w
    assert_allclose(mech, F * v + 6.76e-6 * h["motor_acceleration"] * w, rtol=1e-12, atol=1e-15)
    I, V = h["motor_current"], h["motor_voltage"]
    assert_allclose(V * I, 2.0 * I ** 2 + mech, rtol=1e-12, atol=1e-15)
    assert_allclose(h["motor_torque_frictionless"], h["motor_torque"], rtol=1e-12)


def test_friction_always_costs_power():
    """With friction the motor delivers more power than the frictionless screw, whether the
    screw works against the load (F Ẋ > 0) or with it (F Ẋ < 0)."""
    a = make(armature_inertia=0.0)
    F = np.array([80.0, 80.0, -80.0, -80.0])
    v = np.array([0.01, -0.01, 0.01, -0.01])
    h = motor_histories(a, F, v, np.zeros(4))
    assert list(h["against_load"]) == [True, False, False, True]
    P, P0 = h["motor_torque"] * h["motor_speed"], h["motor_torque_frictionless"] * h["motor_speed"]
    assert np.all(P > P0)
    # With the load a self-locking screw needs torque in the sense of the motion (P > 0 even
    # though the load does work on the screw).
    assert np.all(P[[1, 2]] > 0)


def test_thesis_convention_is_appendix_c():
    """``convention="thesis"``: Appendix C's expressions, transcribed here (Tm1, Vm1, Im1 and the
    frictionless Tm1n), including its sign test against the static force."""
    a = make(convention="thesis")
    Jm, Ra, Ggh, Gls, Kt, Kb, mu, dm = 6.76e-6, 2.0, 5.2, 2.5266e-4, 0.0398, 0.0398, 0.1, 0.0127
    F = np.array([-74.5, -60.0, 5.0, -29.5])
    Fs = np.array([-74.0, -61.0, -3.0, -29.5])
    xd = np.array([0.0, -0.02, -0.03, 0.0])
    xdd = np.array([0.1, -0.2, 0.0, 0.0])
    h = motor_histories(a, F, xd, xdd, Fs)
    same = np.sign(F) == np.sign(Fs)
    pi = math.pi
    Tm = np.where(same,
                  Jm * abs(xdd) * Ggh / Gls + dm / 2 * abs(F)
                  * ((2 * pi * Gls + pi * mu * dm) / (pi * dm - mu * 2 * pi * Gls)),
                  Jm * abs(xdd) * Ggh / Gls + dm / 2 * abs(F)
                  * ((-2 * pi * Gls + pi * mu * dm) / (pi * dm + mu * 2 * pi * Gls)))
    Vm = Tm * Ra / Kt + Kb * Ggh * abs(xd) / Gls
    Tmn = Jm * abs(xdd) * Ggh / Gls + abs(F) * Gls
    assert_allclose(h["motor_torque"], Tm, rtol=1e-12)
    assert_allclose(h["motor_voltage"], Vm, rtol=1e-12)
    assert_allclose(h["motor_current"], Tm / Kt, rtol=1e-12)
    assert_allclose(h["motor_torque_frictionless"], Tmn, rtol=1e-12)


def test_holding_voltage_of_the_prototype():
    """At rest the physical model needs T = F d_m/2 tan(λ+φ) / G_gh; the thesis convention leaves
    out 1/G_gh, so its holding torque is exactly G_gh = 5.2 times larger (rtol 1e-12)."""
    F = np.array([-74.5])
    z = np.zeros(1)
    hp = motor_histories(make(), F, z, z)
    ht = motor_histories(make(convention="thesis"), F, z, z)
    lam, phi = math.atan(2 * 2.5266e-4 / 0.0127), math.atan(0.1)
    assert_allclose(hp["motor_torque"], -74.5 * 0.0127 / 2 * math.tan(lam + phi) / 5.2, rtol=1e-12)
    assert_allclose(ht["motor_torque"], -5.2 * hp["motor_torque"], rtol=1e-12)


def test_voltage_and_speed_flags():
    """Section 5.7: a demand above the motor's 25 V supply (and a speed above its maximum) is
    flagged with the value and the time."""
    a = make(max_voltage=25.0, max_speed=400.0)
    t = np.array([0.0, 1.0, 2.0])
    v = np.array([0.0, 0.032, 0.0])         # 0.032 m/s → 659 rad/s, back emf 26.2 V
    h = motor_histories(a, np.array([-70.0, -50.0, -30.0]), v, np.zeros(3), time=t)
    assert h["max_motor_speed"] == pytest.approx(0.032 * 5.2 / 2.5266e-4, rel=1e-12)
    assert any(f.startswith("voltage:") and "t = 1 s" in f and "25 V" in f for f in h["flags"])
    assert any(f.startswith("speed:") for f in h["flags"])
    ok = motor_histories(make(max_voltage=1e3, max_speed=1e4), np.array([-70.0]), v[:1],
                         np.zeros(1))
    assert ok["flags"] == []


def test_self_locking_check():
    """Eq. 2.45: G_ls < μ d_m/2.  A gain above it raises InputError naming the actuator unless
    self-locking is waived, in which case the histories carry a flag; the with-load torque of
    a non-self-locking screw is negative (the load back-drives it)."""
    raw = dict(leadscrew_gain=0.004, mean_diameter=0.02, friction=0.3, gearhead_gain=1.0,
               armature_inertia=0.0, resistance=1.0, torque_constant=0.1, back_emf_constant=0.1)
    with pytest.raises(InputError, match=r"actuators\.A: the leadscrew is not self-locking"):
        parse_actuator("A", raw, 0)
    a = parse_actuator("A", {**raw, "require_self_locking": False}, 0)
    assert not a.self_locking
    h = motor_histories(a, np.array([100.0]), np.array([-0.01]), np.zeros(1))
    assert h["motor_torque"][0] > 0        # F > 0, moving in −X: torque pushes back, i.e. holds
    assert any(f.startswith("self-locking") for f in h["flags"])
    # At the limit (Lacy's 0.003 m/rad) the screw self-locks with zero with-load torque.
    b = parse_actuator("B", {**raw, "leadscrew_gain": 0.003}, 0)
    assert b.self_locking
    assert_allclose(thread_ratio(b.lead, 0.02, 0.3, 0.0, False), 0.0, atol=1e-15)


def test_acme_thread_self_locking_uses_sec_alpha():
    """For an Acme thread (α_T = 14.5°) the limit is μ d_m sec α_T / 2 (eq. 2.38's numerator)."""
    raw = dict(leadscrew_gain=0.00305, mean_diameter=0.02, friction=0.3, gearhead_gain=1.0,
               armature_inertia=0.0, resistance=1.0, torque_constant=0.1, back_emf_constant=0.1)
    with pytest.raises(InputError):
        parse_actuator("A", raw, 0)                                # square: 0.00305 > 0.003
    a = parse_actuator("A", {**raw, "thread": "acme"}, 0)          # 0.00305 < 0.003/cos 14.5°
    assert_allclose(a.self_locking_limit, 0.003 / math.cos(math.radians(14.5)), rtol=1e-12)


@pytest.mark.parametrize("bad, item", [
    ({"thread": "buttress"}, "thread"),
    ({"friction": -0.1}, "friction"),
    ({"leadscrew_gain": 0.0}, "leadscrew_gain"),
    ({"torque_constant": "x"}, "torque_constant"),
    ({"thread_angle": 14.5}, "thread_angle"),
    ({"convention": "other"}, "convention"),
    ({"colour": 1}, "colour"),
])
def test_bad_actuator_values_name_the_item(bad, item):
    raw = dict(leadscrew_gain=2.5266e-4, mean_diameter=0.0127, friction=0.1, gearhead_gain=5.2,
               armature_inertia=6.76e-6, resistance=2.0, torque_constant=0.0398,
               back_emf_constant=0.0398)
    raw.update(bad)
    with pytest.raises(InputError, match=rf"actuators\.M7_8\.{item}"):
        parse_actuator("M7_8", raw, 0)


def test_missing_gearhead_gain_needs_max_speed():
    raw = dict(leadscrew_gain=0.003, mean_diameter=0.02, friction=0.3, armature_inertia=0.0,
               resistance=1.0, torque_constant=0.1, back_emf_constant=0.1)
    with pytest.raises(InputError, match=r"actuators\.A\.gearhead_gain"):
        parse_actuator("A", raw, 0)
    with pytest.raises(AnalysisError, match="gearhead_gain"):
        select_gearhead_gain(0.003, 400.0, 0.0)


def test_gain_selection_needs_motion():
    """Without motion (``simulate`` at rest) eq. 3.1 cannot select the gearhead gain: the
    actuator reports it in its flags instead of failing the analysis; with motion the gain
    makes the fastest sample turn the motor at exactly its maximum speed."""
    from types import SimpleNamespace
    from trussfe.rigid.actuator import actuator_histories
    a = make(gearhead_gain=NAN, max_speed=400.0)
    s = SimpleNamespace(extensions={"actuators": [a]}, member_ids=["M7_8"])
    rest = SimpleNamespace(members=[0], time=np.zeros(1), velocity=np.zeros((1, 1)),
                           acceleration=np.zeros((1, 1)))
    h = actuator_histories(s, rest, np.array([[10.0]]))["M7_8"]
    assert "motor_voltage" not in h and h["flags"][0].startswith("gearhead gain: not selected")
    moving = SimpleNamespace(members=[0], time=np.arange(3.0),
                             velocity=np.array([[0.0], [0.02], [-0.01]]),
                             acceleration=np.zeros((3, 1)))
    h = actuator_histories(s, moving, np.array([[10.0], [10.0], [10.0]]))["M7_8"]
    assert h["gearhead_gain_selected"]
    assert_allclose(h["max_motor_speed"], 400.0, rtol=1e-12)
