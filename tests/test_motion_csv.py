# SPDX-License-Identifier: MIT
"""Measured motion histories from CSV (docs/actuators.md) and their one-line errors."""
import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.errors import InputError
from trussfe.rigid.motion import third_order_response
from trussfe.rigid.motion_csv import read_motion_csv
from trussfe.studies.lacy_rigid import triangular_truss


@pytest.fixture(scope="module")
def truss():
    return triangular_truss()


def write(tmp_path, text, name="m.csv"):
    p = tmp_path / name
    p.write_text(text)
    return p


def third_order_csv(tmp_path, n=301, cols="length"):
    """The Base Simulation move (2.5 → 3.7 m in 3 s, Lacy section 3.3) sampled at n points."""
    t = np.linspace(0.0, 3.0, n)
    y, dy, ddy = third_order_response(t, 3.0)
    L, v, a = 2.5 + 1.2 * y, 1.2 * dy, 1.2 * ddy
    head = ["time", "active"] + (["active.velocity"] if "velocity" in cols else []) + \
        (["active.acceleration"] if "acceleration" in cols else [])
    body = [t, L] + ([v] if "velocity" in cols else []) + ([a] if "acceleration" in cols else [])
    lines = ["# synthetic: third-order model, Lacy Appendix A", ",".join(head)]
    lines += [",".join(f"{x:.15g}" for x in row) for row in np.column_stack(body)]
    return write(tmp_path, "\n".join(lines) + "\n"), t, L, v, a


def test_given_rates_are_read_exactly(tmp_path, truss):
    p, t, L, v, a = third_order_csv(tmp_path, 51, cols="length velocity acceleration")
    m = read_motion_csv(p, truss)
    assert list(m.members) == [truss.member_index("active")]
    assert_allclose(m.time, t, rtol=1e-14)
    assert_allclose(m.length[:, 0], L, rtol=1e-14)
    assert_allclose(m.velocity[:, 0], v, rtol=1e-14, atol=1e-14)
    assert_allclose(m.acceleration[:, 0], a, rtol=1e-14, atol=1e-14)


def test_smooth_differentiation_recovers_the_analytic_rates(tmp_path, truss):
    """Lengths only, 301 samples of the third-order move: the smoothing-spline rates match the
    analytic ones (exact partial-fraction derivatives) to 0.1 % (velocity) and 1 %
    (acceleration) of their peaks away from the first and last 2 % of the record, where the
    spline's natural end conditions bend the second derivative (there: 1 % and 10 %)."""
    p, t, L, v, a = third_order_csv(tmp_path, 301)
    m = read_motion_csv(p, truss)
    inner = slice(6, -6)
    err_v = np.abs(m.velocity[:, 0] - v) / np.abs(v).max()
    err_a = np.abs(m.acceleration[:, 0] - a) / np.abs(a).max()
    assert err_v[inner].max() < 1e-3 and err_v.max() < 1e-2
    assert err_a[inner].max() < 1e-2 and err_a.max() < 1e-1
    assert_allclose(np.abs(m.velocity).max(), 1.2477, rtol=2e-3)      # Lacy section 3.7


def test_noisy_measurement_is_smoothed(tmp_path, truss):
    """0.1 mm noise on the lengths (200 samples): the spline's velocity stays within 2 % of the
    peak, where a central difference of the raw samples is off by far more (its error is of
    order noise/dt)."""
    rng = np.random.default_rng(1)
    t = np.linspace(0.0, 3.0, 200)
    y, dy, _ = third_order_response(t, 3.0)
    L = 2.5 + 1.2 * y + 1e-4 * rng.standard_normal(t.size)
    rows = "\n".join(f"{a:.15g},{b:.15g}" for a, b in zip(t, L))
    m = read_motion_csv(write(tmp_path, "time,active\n" + rows), truss)
    err = np.abs(m.velocity[:, 0] - 1.2 * dy).max() / (1.2 * dy.max())
    fd = np.abs(np.gradient(L, t) - 1.2 * dy).max() / (1.2 * dy.max())
    assert err < 0.02
    assert fd > 2 * err


@pytest.mark.parametrize("text, where, what", [
    ("time,active\n0,2.5\n1,2.6\n1,2.7\n2,2.8\n3,2.9\n", "m.csv: line 4", "does not increase"),
    ("time,active\n0,2.5\n1,nan\n2,2.7\n", "m.csv: line 3, column 2 'active'", "nan"),
    ("time,active\n0,2.5\n1,\n2,2.7\n", "m.csv: line 3, column 2 'active'", "empty"),
    ("time,active\n0,2.5\n1,abc\n", "m.csv: line 3, column 2 'active'", "not a number"),
    ("time,active\n0,2.5\n1\n", "m.csv: line 3", "1 cells"),
    ("time,M7_8\n0,2.5\n", "m.csv: column 2 'M7_8'", "not a member"),
    ("time,follower\n0,2.0\n", "m.csv: column 2 'follower'", "not an active member"),
    ("t,active\n0,2.5\n", "m.csv: header", "no 'time' column"),
    ("time,active.velocity\n0,0.0\n", "m.csv: header", "no length column"),
    ("time,active,active\n0,2.5,2.5\n", "m.csv: column 3", "twice"),
    ("time,active\n0,2.5\n1,2.6\n", "m.csv", "at least 5"),
    ("# only a comment\n", "m.csv", "empty motion file"),
    ("time,active\n", "m.csv", "no samples"),
    ("time,active\n0,2.5\n1,-2.6\n", "m.csv: line 3, column 2 'active'", "must be positive"),
])
def test_bad_motion_files(tmp_path, truss, text, where, what):
    """Every bad file gives one InputError naming the file, line and column."""
    with pytest.raises(InputError) as exc:
        read_motion_csv(write(tmp_path, text), truss)
    msg = str(exc.value)
    assert msg.startswith(where + ":"), msg
    assert what in msg


def test_missing_file(tmp_path, truss):
    with pytest.raises(InputError, match="motion file not found"):
        read_motion_csv(tmp_path / "nope.csv", truss)
