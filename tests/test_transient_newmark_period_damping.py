# SPDX-License-Identifier: MIT
"""Time integration of :func:`trussfe.response.transient.transient_response` on the single-DOF
active bar (:func:`trussfe.studies.transient_slews.sdof_bar`, k = EA/L, m = 10 kg).

References: the exact discrete free vibration of Newmark's average-acceleration rule,
``u_{n+1} + u_{n-1} = 2 c u_n`` with ``c = (1 − Ω²/4)/(1 + Ω²/4)``, ``Ω = ω Δt`` (period
ratio ``Ω / (2 arctan(Ω/2))``, no amplitude decay); the logarithmic decrement of a viscously
damped oscillator, ``ζ = α/(2ω) + βω/2`` for ``C = αM + βK``; and SciPy's ``solve_ivp`` on
``m ü + EA/L(t) u = −m L̈(t)``, the single-DOF system with the stiffness of the current length.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from trussfe.response.transient import transient_response
from trussfe.studies.transient_slews import cycloidal_motion, sdof_bar

MASS, EA = 10.0, 1.0e5
STROKE, T = 0.05, 0.2


def _free_part(r):
    after = r.time > T + 1e-9
    return r.time[after], r.axial_force[after, 0]


def test_free_vibration_is_the_average_acceleration_recurrence():
    dt = 2.0e-3                                     # Ω = ω Δt = 0.2
    s = sdof_bar(1.0, MASS, EA)
    r = transient_response(s, cycloidal_motion(s, STROKE, T, dt), bar_model="truss",
                           update="frozen", t_end=0.6)
    _, n = _free_part(r)
    w = math.sqrt(EA / MASS)
    om2 = (w * dt) ** 2
    c = (1 - om2 / 4) / (1 + om2 / 4)
    # β = 1/6 (linear acceleration) would give c = 1 − Ω²/(2(1 + Ω²/6)): 7e-5 apart
    assert np.abs(n[2:] + n[:-2] - 2 * c * n[1:-1]).max() < 1e-10 * np.abs(n).max()


def test_rayleigh_damping_ratio_from_log_decrement():
    w = math.sqrt(EA / MASS)
    alpha, beta = 0.5, 1.0e-4
    s = sdof_bar(1.0, MASS, EA)
    r = transient_response(s, cycloidal_motion(s, STROKE, T, 1.0e-4), bar_model="truss",
                           update="frozen", t_end=1.0, damping=(alpha, beta))
    _, n = _free_part(r)
    i = np.flatnonzero((n[1:-1] > n[:-2]) & (n[1:-1] >= n[2:])) + 1
    peaks = n[i]
    delta = math.log(peaks[0] / peaks[-1]) / (peaks.size - 1)
    zeta = delta / math.sqrt(4 * math.pi ** 2 + delta ** 2)
    assert zeta == pytest.approx(alpha / (2 * w) + beta * w / 2, rel=1e-3)   # 0.0075
    e = r.energy
    assert e["dissipated"][-1] > 0.5 * e["work"][-1]
    assert r.energy_residual() < 1e-12


def test_updated_stiffness_against_ode_second_order():
    """``update="per-step"``: the bar's stiffness EA/L(t) follows its length (5 % longer at
    the end); the error against the ODE falls four-fold as Δt halves."""
    w_T = 2 * math.pi / T

    def length(t):
        tau = min(max(t / T, 0.0), 1.0)
        return 1.0 + STROKE * (tau - math.sin(2 * math.pi * tau) / (2 * math.pi))

    def rhs(t, y):
        acc = STROKE * w_T / T * math.sin(w_T * t) if t <= T else 0.0
        return [y[1], -acc - EA / length(t) / MASS * y[0]]

    ode = solve_ivp(rhs, (0.0, 0.4), [0.0, 0.0], rtol=1e-12, atol=1e-14, max_step=1e-4,
                    dense_output=True)
    errors = []
    for dt in (1.0e-3, 5.0e-4):
        s = sdof_bar(1.0, MASS, EA)
        r = transient_response(s, cycloidal_motion(s, STROKE, T, dt), bar_model="truss",
                               t_end=0.4)
        ref = EA / np.array([length(t) for t in r.time]) * ode.sol(r.time)[0]
        errors.append(np.abs(r.axial_force[:, 0] - ref).max() / np.abs(ref).max())
    assert errors[1] < 2.5e-3
    assert errors[0] / errors[1] == pytest.approx(4.0, rel=0.05)
