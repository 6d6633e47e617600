"""Four-bar and slider-crank over a full crank turn against closed form (positions,
velocities, accelerations), from the compatibility matrix and from the cycle equations."""
import numpy as np
import pytest

from trussfe.studies.vlase import (fourbar_closed_form, fourbar_position,
                                  fourbar_rates, slider_crank_closed_form)


def test_fourbar_rates_closed_form_vs_finite_difference():
    """The closed-form ω4, α4 (Norton) against central differences of the closed-form position
    (h = 1e-5: truncation ~1e-10, round-off ~1e-10 / 1e-5 → rtol 1e-6)."""
    th, h, w = 0.7, 1e-5, 1.0
    ang = [np.arctan2(fourbar_position(t)[1][1], fourbar_position(t)[1][0] - 3.0)
           for t in (th - h, th, th + h)]
    r = fourbar_rates(th, omega=w, alpha=0.0)
    assert r["omega4"] == pytest.approx((ang[2] - ang[0]) / (2 * h), rel=1e-6)
    assert r["alpha4"] == pytest.approx((ang[2] - 2 * ang[1] + ang[0]) / h ** 2, rel=1e-4)


def test_fourbar():
    r = fourbar_closed_form()
    assert r["crank_turn"] >= 2 * np.pi                   # a full turn traced
    assert r["position_max_error"] < 1e-9                 # corrector tolerance 1e-10·L
    assert r["bar_length_misfit"] < 1e-9
    assert r["velocity_max_error"] < 1e-12 and r["acceleration_max_error"] < 1e-11
    assert r["cycle_velocity_max_error"] < 1e-12 and r["cycle_acceleration_max_error"] < 1e-11
    assert r["methods_max_difference"] < 1e-11
    assert r["limit_points"] == 2                         # crank pin y turns back twice


def test_slider_crank():
    r = slider_crank_closed_form()
    assert r["crank_turn"] >= 2 * np.pi
    assert r["position_max_error"] < 1e-9
    assert r["slider_travel"] == pytest.approx(2.0, abs=1e-3)   # stroke 2r (sampled path)
    assert r["velocity_max_error"] < 1e-12 and r["acceleration_max_error"] < 1e-11
    assert r["cycle_velocity_max_error"] < 1e-12 and r["cycle_acceleration_max_error"] < 1e-11
