# SPDX-License-Identifier: MIT
"""The analyses along a motion refuse the model tables they do not apply.

``simulate``, ``actuators``, ``transient`` and ``elastic`` apply the model's ``[loads]``,
``[model] gravity`` and ``[masses]``.  A model with ``[load_cases]`` has no ``[loads]`` (its
actions are in its cases), and ``[springs]`` are elastic supports that neither the rigid-body
model nor the response along the motion contains: run regardless, the case loads would be
dropped (the M11/12 motor voltage of the double-octahedron slew comes out without the 46 N
top loads) and a spring would change nothing (the transient's first frequency is that of the
model without it).  Each is refused with one line naming the model file and the table, exit
status 2, before anything is written.
"""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

import trussfe
from trussfe.cli import main
from trussfe.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "meshes" / "double_octahedron_actuators.toml"
MOTION = ROOT / "meshes" / "double_octahedron_motion_slew.toml"
TOP_LOADS = ("[loads]\nN7 = [0.0, 0.0, 46.0]\nN8 = [0.0, 0.0, 46.0]\n"
             "N9 = [0.0, 0.0, 46.0]\n")
COMMANDS = ("simulate", "actuators", "transient", "elastic")


def _variant(tmp_path: Path, table: str) -> Path:
    text = MODEL.read_text(encoding="utf-8")
    assert TOP_LOADS in text
    if table == "load_cases":
        text = text.replace(TOP_LOADS, "[load_cases.live]\nloads = { N7 = [0.0, 0.0, 46.0], "
                            "N8 = [0.0, 0.0, 46.0], N9 = [0.0, 0.0, 46.0] }\n")
    else:
        text = text.replace(TOP_LOADS, "[springs]\nN8 = { x = 1.0e4 }\n\n" + TOP_LOADS)
    path = tmp_path / f"with_{table}.toml"
    path.write_text(text, encoding="utf-8")
    shutil.copy(MOTION, tmp_path / MOTION.name)
    return path


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("table", ["load_cases", "springs"])
def test_command_refuses_the_table(tmp_path, capsys, command, table):
    """One line on stderr naming the file and the table, exit status 2, no output file."""
    path = _variant(tmp_path, table)
    out = tmp_path / "out.json"
    code = main([command, str(path), "--motion", str(tmp_path / MOTION.name),
                 "--json", str(out)])
    err = capsys.readouterr().err
    assert code == 2
    assert err.count("\n") == 1 and "Traceback" not in err
    assert f"{path.name}: {table}:" in err and command in err
    assert not out.exists()


@pytest.mark.parametrize("function", COMMANDS)
@pytest.mark.parametrize("table", ["load_cases", "springs"])
def test_python_api_refuses_the_table(tmp_path, function, table):
    """The functions of the Python API raise the same InputError."""
    path = _variant(tmp_path, table)
    with pytest.raises(InputError, match=rf"{path.name}: {table}: {function} "):
        getattr(trussfe, function)(path, motion=tmp_path / MOTION.name)


def test_model_without_those_tables_runs(tmp_path):
    """The shipped model (``[loads]``, no cases, no springs) is analysed as before."""
    shutil.copy(MOTION, tmp_path / MOTION.name)
    r = trussfe.simulate(MODEL, motion=tmp_path / MOTION.name)
    assert r.axial_force.shape[0] == 201


def test_springs_of_zero_stiffness_are_no_springs(tmp_path):
    """A ``[springs]`` table whose stiffnesses are all zero holds nothing: the motion
    analyses run the model as without it."""
    path = _variant(tmp_path, "springs")
    path.write_text(path.read_text().replace("N8 = { x = 1.0e4 }", "N8 = { x = 0.0 }"))
    r = trussfe.simulate(path, motion=tmp_path / MOTION.name)
    base = trussfe.simulate(MODEL, motion=tmp_path / MOTION.name)
    assert (r.axial_force == base.axial_force).all()
