"""Result documents record what reproduces and explains them: the ``--mass-from`` case of
``modes``, the ``--tolerance`` and ``--frozen`` of ``trace``, and the id of the worst member
of the ``elastic`` comparison (docs/json.md)."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

import trussfe
from trussfe._resources import mesh_path
from trussfe.cli import main

JSON_MD = (Path(__file__).resolve().parents[1] / "docs" / "json.md").read_text()


def _section(command: str) -> str:
    return JSON_MD.split(f"## `{command}`", 1)[1].split("\n## ", 1)[0]


def _payload_model(tmp_path) -> Path:
    p = tmp_path / "bar.toml"
    p.write_text("""
[model]
name = "bar"
dimension = 2
gravity = [-9.81, 0.0]
[materials.steel]
E = 210e9
[sections.bar]
area = 1e-4
[nodes]
A = [0.0, 0.0]
B = [2.0, 0.0]
[members]
AB = { nodes = ["A", "B"], section = "bar", material = "steel" }
[supports]
A = ["x", "y"]
B = ["y"]
[load_cases.payload.loads]
B = [-981.0, 0.0]
""")
    return p


def test_modes_records_the_mass_case(tmp_path):
    model = _payload_model(tmp_path)
    out = tmp_path / "m.json"
    assert main(["modes", str(model), "--mass-from", "payload", "--json", str(out)]) == 0
    doc = json.loads(out.read_text())
    assert doc["mass_from"] == "payload"
    assert list(doc).index("mass_from") == list(doc).index("mass") + 1


def test_modes_without_a_mass_case_records_null():
    doc = trussfe.modes(mesh_path("double_octahedron_equilibrium.toml"), count=2).to_dict()
    assert "mass_from" in doc and doc["mass_from"] is None


def test_trace_records_tolerance_and_frozen(tmp_path):
    out = tmp_path / "t.json"
    assert main(["trace", str(mesh_path("mech_fourbar.toml")), "--drive", "2:y", "--step",
                 "0.05", "--steps", "2", "--tolerance", "1e-9", "--frozen", "--json",
                 str(out)]) == 0
    doc = json.loads(out.read_text())
    assert doc["tolerance"] == 1e-9 and doc["frozen"] is True
    doc = trussfe.trace(mesh_path("mech_fourbar.toml"), drive="2:y", step=0.05,
                        steps=2).to_dict()
    assert doc["tolerance"] == 1e-10 and doc["frozen"] is False


def test_elastic_worst_names_the_member_id():
    doc = trussfe.elastic(mesh_path("triangular_truss_motion_active.toml")).to_dict()
    worst = doc["comparison"]["worst"]
    ids = list(doc["members"])
    assert isinstance(worst["member"], int)
    assert worst["member_id"] == ids[worst["member"]]


@pytest.mark.parametrize("command, key", [
    ("modes", "`mass_from`"), ("trace", "`tolerance`"), ("trace", "`frozen`"),
    ("elastic", "member_id"),
])
def test_new_keys_are_documented(command, key):
    assert key in _section(command)
