# SPDX-License-Identifier: MIT
"""An actuator without a gearhead gain (to be selected by Lacy eq. 3.1 from ``max_speed``)
whose member the motion does not move has no motor histories: eq. 3.1 has no speed to go
on.  ``trussfe actuators`` then reports its force and a flag, with the gain and the motor
peaks null in the JSON and NaN in the Python histories, and the other actuators as usual —
it does not stop with a traceback.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np

import trussfe
from trussfe.cli import main

MODEL = Path(__file__).resolve().parents[1] / "meshes" / "double_octahedron_actuators.toml"


def _without_gain(tmp_path: Path) -> Path:
    text = MODEL.read_text(encoding="utf-8")
    i = text.index("[actuators.M7_8]")
    j = text.index("gearhead_gain = 5.2", i)
    text = text[:j] + "max_speed = 400.0" + text[j + len("gearhead_gain = 5.2"):]
    path = tmp_path / "no_gain.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_document_and_histories_without_motor_histories(tmp_path, capsys):
    path = _without_gain(tmp_path)
    out = tmp_path / "a.json"
    assert main(["actuators", str(path), "--json", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "M7_8: " in printed and "G_gh not selected" in printed
    doc = json.loads(out.read_text())["actuators"]
    m78 = doc["M7_8"]
    assert m78["gearhead_gain"] is None and m78["gearhead_gain_selected"] is False
    assert m78["motor_voltage"] is None and m78["motor_torque"] is None
    assert m78["force"]["value"] != 0.0
    assert any("not selected" in f for f in m78["flags"])
    assert doc["M9_10"]["gearhead_gain"] == 5.2 and doc["M9_10"]["motor_voltage"] is not None
    r = trussfe.actuators(path)
    j = r.actuator_ids.index("M7_8")
    assert np.all(np.isnan(r.motor_voltage[:, j]))
    assert np.all(np.isfinite(r.force[:, j]))
    assert np.all(np.isfinite(np.delete(r.motor_voltage, j, axis=1)))
