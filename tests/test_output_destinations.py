# SPDX-License-Identifier: MIT
"""Every file a run writes is known before any is renamed into place: a file written twice
(a name given to two outputs, a file inside an output folder, the ``_stations`` file beside
a ``.vtu``) or an input replaced by an output is refused in one line, exit 2, with nothing
written (docs/bad-input.md); distinct names in one folder are all written."""
from __future__ import annotations

import shutil
from pathlib import Path

from trussfe.cli import main

MESHES = Path(__file__).resolve().parents[1] / "meshes"
STATIC = MESHES / "triangular_truss_static.toml"


def _one_error(capsys) -> str:
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("trussfe: error: "), err
    return err[0]


def test_json_named_as_a_file_of_the_vtk_folder(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["modes", str(STATIC), "--vtk", "out", "--json", "out/modes.pvd"]) == 2
    line = _one_error(capsys)
    assert "out/modes.pvd: would be written twice by this run" in line
    assert not (tmp_path / "out").exists()
    # other names in the same folder are fine: both outputs are written
    assert main(["modes", str(STATIC), "--vtk", "out", "--json", "out/modes.json"]) == 0
    assert (tmp_path / "out" / "modes.pvd").is_file()
    assert (tmp_path / "out" / "modes.json").is_file()


def test_json_named_as_the_stations_file_beside_the_vtu(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["static", str(STATIC), "--bar-model", "pinned-beam", "--vtk", "a.vtu",
                 "--json", "a_stations.vtu"]) == 2
    assert "a_stations.vtu: would be written twice" in _one_error(capsys)
    assert not list(tmp_path.iterdir())


def test_model_inside_the_vtk_folder_is_not_replaced(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "d").mkdir()
    model = tmp_path / "d" / "modes.pvd"
    shutil.copy(STATIC, model)
    assert main(["modes", str(model), "--vtk", "d"]) == 2
    assert "is also the model file" in _one_error(capsys)
    assert model.read_text() == STATIC.read_text()
    assert [p.name for p in (tmp_path / "d").iterdir()] == ["modes.pvd"]


def test_motion_inside_the_vtk_folder_is_not_replaced(tmp_path, capsys):
    (tmp_path / "v").mkdir()
    model = tmp_path / "X.toml"
    motion = tmp_path / "v" / "X.pvd"
    shutil.copy(MESHES / "triangular_truss_motion_active.toml", model)
    shutil.copy(MESHES / "triangular_truss_motion_3s.toml", motion)
    assert main(["simulate", str(model), "--motion", str(motion),
                 "--vtk", str(tmp_path / "v")]) == 2
    assert "is also --motion" in _one_error(capsys)
    assert motion.read_text() == (MESHES / "triangular_truss_motion_3s.toml").read_text()
