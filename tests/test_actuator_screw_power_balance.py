# SPDX-License-Identifier: MIT
"""``trussfe actuators`` against the power-screw relations, step by step along a motion whose
actuator force changes sign (Lacy 1991 eqs. 2.27–2.45; Shigley's power screw).

The expected values are written from first principles, not from trussfe: the lead angle
tan λ = l / (π d_m) with l = 2π G_ls (eq. 2.34), the virtual friction angle tan φ' = μ sec α_T
of a thread of half-angle α_T, and the screw torque in the sense that lengthens the member

    T_s = F d_m/2 · tan(λ + φ')   when the screw raises the load (F Ẋ > 0, and at rest:
                                   |Ẋ| within 1e-9 of the largest, a round-off rate),
    T_s = F d_m/2 · tan(λ − φ')   when it lowers it (F Ẋ < 0: the load drives the motion),

which are eqs. 2.37 and 2.38 (the latter written in the sense of the motion).  Power check:
the screw's shaft power T_s Ẋ / G_ls is F Ẋ / η when raising and F Ẋ · η' when lowering, with
η = tan λ / tan(λ + φ') and η' = tan(λ − φ') / tan λ.
"""
import json
import math
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe import api

MESHES = Path(__file__).resolve().parents[1] / "meshes"
MOTION = MESHES / "triangular_truss_motion_3s.toml"     # third-order, 2.5 -> 3.7 m in 3 s

# Lacy's triangular truss motor constants (Appendix A), a gearhead gain of 1.3.
JM, RA, KT, KB, GGH, VMAX, WMAX = 6.76e-6, 2.0, 0.0398, 0.0398, 1.3, 25.0, 400.0

CASES = {
    # self-locking square thread (G_ls < μ d_m / 2 = 0.003 m/rad)
    "square": {"gls": 0.002, "dm": 0.02, "mu": 0.3, "thread": "square", "alpha": 0.0},
    # Acme thread that does not self-lock: 0.0032 > 0.3 · 0.02 · sec 14.5° / 2 = 0.0030987
    "acme back-driven": {"gls": 0.0032, "dm": 0.02, "mu": 0.3, "thread": "acme",
                         "alpha": 14.5},
}


def model_file(tmp_path, c) -> Path:
    angle = f"thread_angle = {c['alpha']}\n" if c["thread"] == "acme" else ""
    text = (MESHES / "triangular_truss_motion_active.toml").read_text() + f"""
[actuators.active]
leadscrew_gain = {c['gls']}
mean_diameter = {c['dm']}
thread = "{c['thread']}"
{angle}friction = {c['mu']}
gearhead_gain = {GGH}
armature_inertia = {JM}
resistance = {RA}
torque_constant = {KT}
back_emf_constant = {KB}
max_speed = {WMAX}
max_voltage = {VMAX}
require_self_locking = false
convention = "physical"
"""
    p = tmp_path / "truss.toml"
    p.write_text(text)
    return p


@pytest.fixture(scope="module", params=list(CASES))
def run(request, tmp_path_factory):
    c = CASES[request.param]
    p = model_file(tmp_path_factory.mktemp("act"), c)
    sim = api.simulate(p, motion=MOTION).to_dict()
    summary = api.actuators(p, motion=MOTION).to_dict()["actuators"]["active"]
    a = sim["actuators"]["active"]
    h = {k: np.asarray(a[k], dtype=float) for k in
         ("force", "velocity", "acceleration", "leadscrew_torque", "motor_speed",
          "motor_torque", "motor_current", "motor_voltage", "motor_voltage_frictionless")}
    h["time"] = np.asarray(sim["time"], dtype=float)
    return c, h, summary


def at_rest(xd):
    """Samples whose rate is round-off: 1e-9 of the motion's largest."""
    return np.abs(xd) <= 1e-9 * np.abs(xd).max()


def expected(c, h):
    """Screw, motor and voltage histories from first principles (module docstring)."""
    F, xd, xdd = h["force"], h["velocity"], h["acceleration"]
    gls, dm = c["gls"], c["dm"]
    lam = math.atan(2 * math.pi * gls / (math.pi * dm))              # eq. 2.34
    phi = math.atan(c["mu"] / math.cos(math.radians(c["alpha"])))    # tan φ' = μ sec α_T
    raising = (F * xd > 0.0) | at_rest(xd)
    Ts = F * dm / 2 * np.where(raising, math.tan(lam + phi), math.tan(lam - phi))
    w = GGH / gls * xd                                               # eq. 2.28, rad/s
    Tm = JM * GGH / gls * xdd + Ts / GGH                             # eqs. 2.39-2.40
    V = Tm * RA / KT + KB * w                                        # eq. 2.44
    V0 = (JM * GGH / gls * xdd + F * gls / GGH) * RA / KT + KB * w   # μ = 0: T_s = F l/(2π)
    return {"lam": lam, "phi": phi, "raising": raising, "Ts": Ts, "w": w, "Tm": Tm,
            "I": Tm / KT, "V": V, "V0": V0}


def test_motion_covers_raising_lowering_and_rest(run):
    """The motion exercises every case: at rest (t = 0), the screw pushing the mass up
    (F > 0, Ẋ > 0), the load pulling the extending member (F < 0, Ẋ > 0: lowering), and the
    overshoot of the third-order move (Ẋ < 0)."""
    _, h, _ = run
    F, xd = h["force"], h["velocity"]
    assert at_rest(xd)[0] and np.count_nonzero(at_rest(xd)) == 1
    assert np.any((F > 0) & (xd > 0)) and np.any((F < 0) & (xd > 0)) and np.any(xd < 0)


def test_screw_and_motor_histories_follow_the_power_screw(run):
    """Leadscrew torque, motor speed, torque, current and voltage at every step, with and
    without friction (rtol 1e-12): raising uses tan(λ + φ'), lowering tan(λ − φ')."""
    c, h, _ = run
    e = expected(c, h)
    assert_allclose(h["leadscrew_torque"], e["Ts"], rtol=1e-12, atol=1e-15)
    assert_allclose(h["motor_speed"], e["w"], rtol=1e-12, atol=1e-12)
    assert_allclose(h["motor_torque"], e["Tm"], rtol=1e-12, atol=1e-15)
    assert_allclose(h["motor_current"], e["I"], rtol=1e-12, atol=1e-13)
    assert_allclose(h["motor_voltage"], e["V"], rtol=1e-12, atol=1e-12)
    assert_allclose(h["motor_voltage_frictionless"], e["V0"], rtol=1e-12, atol=1e-12)


def test_screw_power_is_load_power_over_efficiency(run):
    """Shaft power of the screw T_s Ẋ / G_ls = F Ẋ / η raising, F Ẋ · η' lowering; a screw
    that does not self-lock (λ > φ') returns power to the motor while it lowers."""
    c, h, _ = run
    e = expected(c, h)
    F, xd = h["force"], h["velocity"]
    lam, phi = e["lam"], e["phi"]
    shaft = h["leadscrew_torque"] * xd / c["gls"]
    eta, eta_back = math.tan(lam) / math.tan(lam + phi), math.tan(lam - phi) / math.tan(lam)
    want = np.where(e["raising"], F * xd / eta, F * xd * eta_back)
    assert_allclose(shaft, want, rtol=1e-10, atol=1e-12 * np.abs(F * xd).max())
    lowering = ~e["raising"]
    if lam > phi:
        assert np.all(shaft[lowering] < 0)           # back-driven: the motor brakes
    else:
        assert np.all(shaft[lowering] >= 0)          # self-locking: the motor drives it down


def test_summary_peaks_limit_and_flags(run):
    """``trussfe actuators`` summary: each peak is the largest magnitude of the history, signed,
    at the time it first occurs; the self-locking limit is μ d_m sec α_T / 2 (eq. 2.45); the
    flags fire exactly when |V| exceeds the supply, the speed the motor's maximum, and G_ls the
    limit."""
    c, h, s = run
    e = expected(c, h)
    t = h["time"]
    for key, x in (("force", h["force"]), ("motor_speed", e["w"]), ("motor_torque", e["Tm"]),
                   ("motor_current", e["I"]), ("motor_voltage", e["V"]),
                   ("motor_voltage_frictionless", e["V0"])):
        k = int(np.argmax(np.abs(x)))
        assert s[key]["time"] == t[k], key
        assert_allclose(s[key]["value"], x[k], rtol=1e-12, err_msg=key)
    limit = c["mu"] * c["dm"] / math.cos(math.radians(c["alpha"])) / 2
    assert_allclose(s["self_locking_limit"], limit, rtol=1e-12)
    assert s["self_locking"] == (c["gls"] <= limit)
    kinds = {f.split(":")[0] for f in s["flags"]}
    assert kinds == ({"voltage"} if np.abs(e["V"]).max() > VMAX else set()) \
        | ({"speed"} if np.abs(e["w"]).max() > WMAX else set()) \
        | ({"self-locking"} if c["gls"] > limit else set())
    json.dumps(s)                                    # the summary is plain JSON
