# SPDX-License-Identifier: MIT
"""Every option of ``trussfe simulate`` / ``trussfe actuators`` does what its help says; in
particular ``--steps`` on rotation (slew) motions, which it used to ignore."""
import json
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe.rigid.actuator  # noqa: F401  (registers [actuators])
from trussfe.cli import main
from trussfe.errors import InputError
from trussfe.io.model_file import read_model
from trussfe.rigid.motion_file import load_motion
from trussfe import api


def analyse(model, **options):
    """The ``simulate`` JSON document through the Python API."""
    return api.simulate(model, **options).to_dict()


MESHES = Path(__file__).resolve().parents[1] / "meshes"
BAY = str(MESHES / "double_octahedron_actuators.toml")
ROTATION = str(MESHES / "double_octahedron_tilt_rotation.toml")
TRIANGLE = str(MESHES / "triangular_truss_motion_active.toml")
TRIANGLE_MOTION = str(MESHES / "triangular_truss_motion_3s.toml")


def test_steps_sets_the_samples_of_a_rotation_motion():
    """The shipped slew has steps = 220 with include_end (221 samples over 5.5 s); --steps 44
    gives 45 samples at dt = 5.5/44, i.e. every 5th sample of the spec's own run, which is the
    independent reference: the same angle profile in time, hence the same lengths (rtol 1e-9)."""
    s = read_model(BAY)
    ref = load_motion(ROTATION, s)
    m = load_motion(ROTATION, s, steps=44)
    assert m.time.size == 45
    assert_allclose(m.time, ref.time[::5], rtol=1e-12)
    assert_allclose(m.length, ref.length[::5], rtol=1e-9)
    assert_allclose(m.velocity, ref.velocity[::5], rtol=1e-9, atol=1e-12)


def test_simulate_honours_steps_for_a_rotation():
    """``analyse(..., steps=N)`` (the CLI's --steps) gives N + 1 time samples (include_end)."""
    d = analyse(BAY, motion=ROTATION, steps=10, sections=1)
    assert len(d["time"]) == 11
    assert_allclose(d["time"][-1], 5.5, rtol=1e-12)


def test_actuators_command_honours_steps_for_a_rotation(tmp_path):
    out = tmp_path / "a.json"
    assert main(["actuators", BAY, "--motion", ROTATION, "--steps", "12",
                 "--json", str(out)]) == 0
    doc = json.loads(out.read_text())
    # The peak times are sample times of the 12-step grid (dt = 5.5/12).
    for a in doc["actuators"].values():
        k = a["motor_voltage"]["time"] / (5.5 / 12)
        assert abs(k - round(k)) < 1e-9
    assert doc == api.actuators(BAY, motion=ROTATION, steps=12).to_dict()


def test_steps_refused_for_sampled_motions(tmp_path):
    """A CSV history or a rotation given by time/angle samples has its own steps: --steps is
    refused with a message naming it, not silently ignored."""
    s = read_model(BAY)
    with pytest.raises(InputError, match="--steps"):
        load_motion(MESHES / "slew1_motion.csv", s, steps=10)
    spec = tmp_path / "sampled.toml"
    spec.write_text('[motion]\ntype = "rotation"\naxis = "n1"\n'
                    'time = [0.0, 0.1, 0.2, 0.3, 0.4]\nangle = [0.0, 0.5, 1.0, 1.5, 2.0]\n')
    assert load_motion(spec, s).time.size == 5
    with pytest.raises(InputError, match="--steps"):
        load_motion(spec, s, steps=10)


@pytest.mark.parametrize("steps", [0, -3])
def test_bad_steps_for_a_rotation(steps):
    s = read_model(BAY)
    with pytest.raises(InputError, match="steps"):
        load_motion(ROTATION, s, steps=steps)


def test_cli_steps_error_is_one_line(capsys):
    rc = main(["simulate", BAY, "--motion", str(MESHES / "slew1_motion.csv"), "--steps", "5"])
    err = capsys.readouterr().err
    assert rc == 2
    assert err.startswith("trussfe: error: --steps:") and err.count("\n") == 1


def test_steps_sets_a_third_order_motion():
    """--steps on a third-order spec: 3 s motion file (50 steps) run with 20 steps."""
    d = analyse(TRIANGLE, motion=TRIANGLE_MOTION, steps=20)
    assert len(d["time"]) == 20
    assert_allclose(np.diff(d["time"]), 3.0 / 20, rtol=1e-12)


def test_sections_and_scheme_options():
    """--sections k gives k sections (positions 0 … L_t from the end node); --scheme thesis
    reaches the thesis scheme (its first-step angular rates are zero, Lacy Appendix A)."""
    r = api.simulate(TRIANGLE, motion=TRIANGLE_MOTION, sections=3, scheme="thesis").solution
    assert r.stresses.von_mises.shape[2] == 3
    assert r.options["scheme"] == "thesis"
    assert_allclose(r.kinematics.omega[0], 0.0, atol=0)
    k = r.structure.member_index("follower")
    assert_allclose(r.sections.position[k], [0.0, r.bodies.tube_length[k] / 2,
                                             r.bodies.tube_length[k]], rtol=1e-12)
