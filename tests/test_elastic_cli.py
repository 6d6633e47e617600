# SPDX-License-Identifier: MIT
"""``trussfe elastic`` end to end, and its one-line errors."""
import json

import numpy as np
from numpy.testing import assert_allclose

from trussfe._resources import mesh_path
from trussfe.cli import main
from trussfe import api

MODEL = "triangular_truss_motion_active.toml"


def _mesh(name):
    return str(mesh_path(name))


def test_elastic_cli_json_and_vtk(tmp_path):
    """Base Simulation model file + motion file: JSON per step and a .pvd series; the FE
    midpoint axial force equals the rigid one (statics, 1e-6 of the largest)."""
    out = tmp_path / "e.json"
    rc = main(["elastic", _mesh(MODEL), "--motion", _mesh("triangular_truss_motion_3s.toml"),
               "--json", str(out), "--vtk", str(tmp_path / "vtk")])
    assert rc == 0
    d = json.loads(out.read_text())
    assert d["command"] == "elastic" and d["units"] == "SI"
    assert len(d["time"]) == 50
    fol = d["members"]["follower"]
    assert len(fol["axial_force"]) == 50 and len(fol["strain"]) == 50
    fe, rig = np.array(fol["axial_force"]), np.array(fol["axial_force_rigid"])
    assert_allclose(fe, rig, rtol=0, atol=1e-6 * np.abs(rig).max())
    assert d["comparison"]["max"] <= 1e-6
    assert "reaction" in d["nodes"]["O1"] and "reaction" not in d["nodes"]["B"]
    assert (tmp_path / "vtk" / "triangular_truss_motion_active.pvd").is_file()
    import meshio
    st = tmp_path / "vtk" / "triangular_truss_motion_active_stations"
    frames = sorted(st.glob("*.vtu"))
    assert len(frames) == 50
    mesh = meshio.read(frames[10])
    assert mesh.points.shape == (2 * 7, 3)          # 2 members x 7 stations
    assert "moment_z" in mesh.point_data


def test_elastic_analyse_at_rest():
    """Without a motion: one step, the static state."""
    d = api.elastic(_mesh(MODEL)).to_dict()
    assert len(d["time"]) == 1 and d["comparison"]["max"] <= 1e-6


def test_elastic_cli_bad_input(tmp_path, capsys):
    """Missing file, --steps without --motion: exit 2 and one line on stderr."""
    for argv in (["elastic", str(tmp_path / "none.toml")],
                 ["elastic", _mesh(MODEL), "--steps", "5"],
                 ["elastic", _mesh(MODEL), "--subdivisions", "0"]):
        rc = main(argv)
        err = capsys.readouterr().err
        assert rc == 2
        assert err.startswith("trussfe: error:") and err.count("\n") == 1
