# SPDX-License-Identifier: MIT
"""Motions and options at the edge of what the along-motion commands accept: closely spaced
samples, huge angles, section counts beyond memory, sections without an outer-fibre distance.

Each command either answers with finite numbers or refuses in one line naming the item
(docs/bad-input.md); none ends in an internal error or prints a non-finite number."""
import json

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.interpolate import make_smoothing_spline

from trussfe._resources import mesh_path
from trussfe.cli import main
from trussfe.errors import InputError
from trussfe.io.model_file import read_model
from trussfe.rigid.motion_csv import read_motion_csv
from trussfe.rigid.smoothing import smooth_derivative

BAY = str(mesh_path("double_octahedron_actuators.toml"))
TRIANGLE = str(mesh_path("triangular_truss_motion_active.toml"))
TRIANGLE_MOTION = str(mesh_path("triangular_truss_motion_3s.toml"))


def run(capsys, *argv):
    """``main(argv)`` in-process: (exit status, stdout, stderr)."""
    rc = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return rc, out, err


def assert_refused(rc, out, err, *words):
    """One line on stderr, exit status 2, naming every one of ``words``; no internal error."""
    assert rc == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("trussfe: error: "), err
    assert "internal error" not in err
    for w in words:
        assert w in lines[0], (w, lines[0])


def assert_finite_output(out):
    """No non-finite number in the printed output."""
    words = out.replace(";", " ").replace(",", " ").split()
    assert not {"nan", "inf", "-inf"} & set(words), out


def csv_motion(tmp_path, dt, *, name="m.csv", rows=6, step=1e-4):
    """Lengths of M7_8 rising by ``step`` m per sample, samples ``dt`` s apart."""
    lines = ["time,M7_8"] + [f"{k * dt!r},{1.1684 + k * step!r}" for k in range(rows)]
    p = tmp_path / name
    p.write_text("\n".join(lines) + "\n")
    return p


def rotation_motion_file(tmp_path, times, angles, name="rot.toml", **extra):
    keys = "".join(f"{k} = {v}\n" for k, v in extra.items())
    p = tmp_path / name
    p.write_text('[motion]\ntype = "rotation"\naxis = "n1"\n'
                 f"time = {list(times)!r}\nangle = {list(angles)!r}\n"
                 'top_nodes = ["N7", "N8", "N9"]\nhold = "height"\n' + keys)
    return p


# ------------------------------------------------------------------- closely spaced samples
def test_records_sampled_at_100_hz_or_slower_are_fitted_in_seconds():
    """At a spacing of 10 ms or more the rates are those of the smoothing spline fitted in
    seconds, bit for bit (results of such records do not change)."""
    rng = np.random.default_rng(3)
    for dt in (0.01, 0.025, 1.0):
        t = dt * np.arange(40)
        y = np.sin(t / t[-1] * 3) + 1e-4 * rng.standard_normal(t.size)
        want = make_smoothing_spline(t, y).derivative(1)(t)
        want2 = make_smoothing_spline(t, y).derivative(2)(t)
        assert np.array_equal(smooth_derivative(t, y[:, None])[:, 0], want)
        assert np.array_equal(smooth_derivative(t, y[:, None], order=2)[:, 0], want2)


def test_faster_records_have_the_rates_of_the_same_record_at_100_hz():
    """A record sampled every microsecond gets 10⁴ (first derivative) and 10⁸ (second) times
    the rates of the same samples 10 ms apart, instead of failing or over-smoothing."""
    rng = np.random.default_rng(4)
    t = 0.01 * np.arange(60)
    y = np.sin(2 * t) + 1e-5 * rng.standard_normal(t.size)
    slow1 = smooth_derivative(t, y[:, None])
    slow2 = smooth_derivative(t, y[:, None], order=2)
    fast1 = smooth_derivative(t * 1e-4, y[:, None])
    fast2 = smooth_derivative(t * 1e-4, y[:, None], order=2)
    assert_allclose(fast1, 1e4 * slow1, rtol=1e-6, atol=1e-6 * np.abs(1e4 * slow1).max())
    assert_allclose(fast2, 1e8 * slow2, rtol=1e-6, atol=1e-6 * np.abs(1e8 * slow2).max())
    # and the rates are right: d/dt sin(2t) = 2 cos(2t) away from the ends
    assert np.abs(slow1[5:-5, 0] - 2 * np.cos(2 * t[5:-5])).max() < 1e-2


def test_csv_samples_a_nanosecond_apart_give_their_rates(tmp_path):
    """Lengths 0.1 mm apart every nanosecond: a velocity of 1e5 m/s and no acceleration
    (a straight line), fitted in a time unit that keeps the spline well conditioned."""
    s = read_model(BAY)
    m = read_motion_csv(csv_motion(tmp_path, 1e-9), s)
    assert_allclose(m.velocity[:, 0], 1e5, rtol=1e-5)
    assert np.abs(m.acceleration[:, 0]).max() < 1e-6 * 1e5 / 1e-9


@pytest.mark.parametrize("command", ["simulate", "actuators", "elastic"])
def test_commands_along_closely_sampled_csv_motion(tmp_path, capsys, command):
    """simulate, actuators and elastic run along a CSV motion sampled every nanosecond and
    print finite numbers."""
    rc, out, err = run(capsys, command, BAY, "--motion", csv_motion(tmp_path, 1e-9))
    assert rc == 0, err
    assert "internal error" not in err
    assert_finite_output(out)


@pytest.mark.parametrize("command", ["simulate", "elastic"])
def test_commands_along_closely_sampled_rotation(tmp_path, capsys, command):
    """A top-plane rotation given at times 0, 1, ..., 5 ns: its angular rates are finite and
    the commands run."""
    p = rotation_motion_file(tmp_path, [k * 1e-9 for k in range(6)],
                             [-5.0, -3.0, -1.0, 1.0, 3.0, 5.0])
    rc, out, err = run(capsys, command, BAY, "--motion", p)
    assert rc == 0, err
    assert_finite_output(out)


def test_transient_refuses_a_time_step_too_short_for_the_model(tmp_path, capsys):
    """transient along a motion sampled every nanosecond, or with --dt 3 ns: the Newmark
    matrix of the bay is singular to round-off at the massless active members, refused in one
    line naming the motion's time step or --dt."""
    p = csv_motion(tmp_path, 1e-9, name="fast.csv")
    assert_refused(*run(capsys, "transient", BAY, "--motion", p), "fast.csv: time step",
                   "too short")
    assert_refused(*run(capsys, "transient", BAY, "--motion", mesh_path("slew1_motion.csv"),
                        "--dt", "3e-9", "--t-end", "3e-8"), "--dt", "too short")


def test_rates_beyond_any_motion_are_refused(tmp_path, capsys):
    """Samples 1e-300 s apart would give rates of 1e296 m/s: refused naming the file and its
    time column (CSV) or motion.time (rotation), for every command."""
    p = csv_motion(tmp_path, 1e-300, name="vfast.csv")
    for command in ("simulate", "actuators", "elastic", "transient"):
        assert_refused(*run(capsys, command, BAY, "--motion", p),
                       "vfast.csv: column 1 'time'", "rates")
    r = rotation_motion_file(tmp_path, [k * 1e-300 for k in range(6)], [0, 1, 2, 3, 4, 5],
                             name="vrot.toml")
    assert_refused(*run(capsys, "simulate", BAY, "--motion", r), "vrot.toml: motion.time")
    with pytest.raises(InputError, match="column 1 'time'"):
        read_motion_csv(p, read_model(BAY))


# ----------------------------------------------------------------------------- huge angles
@pytest.mark.parametrize("command", ["simulate", "actuators", "elastic", "transient"])
def test_rotation_start_beyond_half_a_turn_is_refused(tmp_path, capsys, command):
    """start = 1e308 degrees (and 3600): refused at once naming motion.start, not an attempt
    to walk to it degree by degree."""
    spec = (mesh_path("double_octahedron_tilt_rotation.toml").read_text()
            .replace("start = -5.0", "start = 1e308"))
    assert "start = 1e308" in spec
    p = tmp_path / "big.toml"
    p.write_text(spec)
    assert_refused(*run(capsys, command, BAY, "--motion", p), "big.toml: motion.start",
                   "half turn")
    p.write_text(spec.replace("start = 1e308", "start = 3600"))
    assert_refused(*run(capsys, command, BAY, "--motion", p), "motion.start")


def test_sampled_rotation_angle_beyond_half_a_turn_is_refused(tmp_path, capsys):
    """A sampled angle of 400 degrees is refused naming motion.angle."""
    p = rotation_motion_file(tmp_path, [0.0, 0.1, 0.2, 0.3, 0.4], [0, 100, 200, 300, 400])
    assert_refused(*run(capsys, "simulate", BAY, "--motion", p), "rot.toml: motion.angle",
                   "400")


# --------------------------------------------------------------------------- section counts
def test_simulate_refuses_sections_beyond_memory(capsys):
    """--sections 1000000000 would need terabytes: refused at once naming --sections."""
    assert_refused(*run(capsys, "simulate", TRIANGLE, "--motion", TRIANGLE_MOTION,
                        "--sections", "1000000000"), "--sections", "memory")


@pytest.mark.parametrize("options, item", [
    (["--sections", "1000000000"], "--sections"),
    (["--sections", "3", "--subdivisions", "1000000000"], "--subdivisions"),
])
def test_elastic_refuses_sections_or_subdivisions_beyond_memory(capsys, options, item):
    """elastic's FE response grows with the sections and the elements: refused at once
    naming the option that drives it."""
    assert_refused(*run(capsys, "elastic", TRIANGLE, "--motion", TRIANGLE_MOTION, *options),
                   item, "memory")


# ----------------------------------------------------- sections without outer-fibre distance
def _triangle_without_c(tmp_path, both=True):
    """The triangular truss with explicit section properties without c (for the follower
    only when ``both`` is false)."""
    text = mesh_path("triangular_truss_motion_active.toml").read_text()
    head, sep, tail = text.partition("[sections.tube]")
    body = tail.split("\n[", 1)
    new = "[sections.tube]\narea = 9e-5\nIy = 1e-9\n"
    if not both:
        new += ("\n[sections.round]\nouter_diameter = 0.0254\ninner_diameter = 0.022225\n")
    text = head + new + "\n[" + body[1]
    if not both:
        text = text.replace('active = { nodes = ["O2", "B"], section = "tube"',
                            'active = { nodes = ["O2", "B"], section = "round"')
    p = tmp_path / "noc.toml"
    p.write_text(text)
    return p


def test_simulate_without_outer_fibre_distance_prints_no_nan(tmp_path, capsys):
    """A section of area and Iy only: the summary says von Mises is not computed for it and
    gives the largest axial stress (finite); JSON holds null for the von Mises stress."""
    p = _triangle_without_c(tmp_path)
    js = tmp_path / "r.json"
    rc, out, err = run(capsys, "simulate", p, "--motion", TRIANGLE_MOTION, "--json", js)
    assert rc == 0, err
    assert_finite_output(out)
    assert "von Mises not computed (section tube without an outer-fibre distance c)" in out
    assert "largest |axial stress|" in out
    d = json.loads(js.read_text())
    assert None in d["members"]["follower"]["max_von_mises"]
    # an undefined maximum has no time, step or section (not the first step's, where the
    # first undefined value lies)
    summary = d["summary"]["members"]["follower"]
    assert summary["max_von_mises"] is None
    assert summary["time"] is None and summary["step"] is None and summary["section"] is None
    assert summary["motion_induced_time"] is None


def test_simulate_summary_ranks_the_members_that_have_a_von_mises_stress(tmp_path, capsys):
    """One member without c, one tube: the largest von Mises stress is the tube's, and the
    other member's section is named as not computed."""
    p = _triangle_without_c(tmp_path, both=False)
    rc, out, err = run(capsys, "simulate", p, "--motion", TRIANGLE_MOTION)
    assert rc == 0, err
    assert_finite_output(out)
    assert "largest von Mises" in out and "in member active" in out
    assert "not computed for 1 member of section tube" in out


def test_simulate_with_no_member_in_compression_prints_no_inf(tmp_path, capsys):
    """Gravity upward hangs the triangle's apex on its members: no member is compressed and
    the summary says so instead of a margin of inf."""
    text = mesh_path("triangular_truss_motion_active.toml").read_text()
    p = tmp_path / "up.toml"
    p.write_text(text.replace("gravity = [0.0, -9.81]", "gravity = [0.0, 9.81]"))
    rc, out, err = run(capsys, "simulate", p)
    assert rc == 0, err
    assert_finite_output(out)
    assert "no member in compression" in out


def test_valid_summary_line_is_unchanged(capsys):
    """The summary of the shipped triangular truss motion (docs/rigid-body.md)."""
    rc, out, _ = run(capsys, "simulate", TRIANGLE, "--motion", TRIANGLE_MOTION)
    assert rc == 0
    assert out.strip() == ("triangular truss (Lacy Fig. 2.1): 50 steps; largest von Mises "
                           "2.6133e+07 Pa in member active at t = 1.5 s; smallest buckling "
                           "margin 4.86")


def test_a_member_driven_shorter_than_its_tube_is_refused():
    """The leadscrew tube lies between the member's end node and its base, so an active
    member may not become shorter than its ``tube_length`` (the model reader refuses a tube
    longer than the member at rest for the same reason): a motion to 1.8 m of the triangular
    truss's active member, whose tube is 2.0 m and which has no stroke limits, is refused
    naming the step, the member and the tube."""
    from dataclasses import replace

    from trussfe.models import triangular_truss
    from trussfe.rigid.motion import Motion
    from trussfe.rigid.simulate import simulate

    s = triangular_truss(active_members=True)
    a = s.extensions["active_members"][0]
    free = s.with_extensions(active_members=(replace(a, min_length=np.nan,
                                                     max_length=np.nan),))
    L0 = float(s.lengths()[a.member])
    t = np.linspace(0.0, 1.0, 5)
    length = np.linspace(L0, 1.8, 5)[:, None]
    motion = Motion(t, [a.member], length, np.full_like(length, 1.8 - L0),
                    np.zeros_like(length))
    with pytest.raises(InputError, match=r"step 3 \(t = 0\.75 s\): active member '\w+' is "
                                         r"1\.975 m long, shorter than its leadscrew tube "
                                         r"\(2 m, \[active_members\.\w+\] tube_length\)"):
        simulate(free, motion)
    ok = Motion(t, [a.member], np.linspace(L0, 2.0, 5)[:, None],
                np.full((5, 1), 2.0 - L0), np.zeros((5, 1)))
    assert np.all(np.isfinite(simulate(free, ok).midpoint_axial_force))
