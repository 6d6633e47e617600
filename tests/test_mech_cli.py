"""The ``mechanism`` and ``trace`` commands on the shipped models (docs/cli.md, docs/json.md)."""
import json
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest

from trussfe._resources import mesh_path
from trussfe.cli import main
from trussfe import api
from trussfe.io.model_file import read_model
from trussfe.models.mechanisms import CATALOGUE, to_toml


@pytest.mark.parametrize("name", sorted(CATALOGUE))
def test_shipped_model_matches_catalogue(name):
    """meshes/<name>.toml is the catalogue entry written by to_toml, and reads back to the
    same geometry; `mechanism` reports the catalogue's counts."""
    p = mesh_path(f"{name}.toml")
    assert p.read_text() == to_toml(CATALOGUE[name])
    s = read_model(p)
    np.testing.assert_allclose(s.coords, CATALOGUE[name].coords, rtol=1e-14)
    doc = api.mechanism(p).to_dict()
    for k, v in CATALOGUE[name].expected.items():
        assert doc[k] == v


def test_mechanism_json_and_vtk(tmp_path):
    out = tmp_path / "r.json"
    rc = main(["mechanism", str(mesh_path("mech_bricard.toml")), "--json", str(out),
               "--vtk", str(tmp_path / "vtk")])
    assert rc == 0
    doc = json.loads(out.read_text())
    assert doc["units"] == "SI" and doc["command"] == "mechanism"
    assert (doc["rank"], doc["mechanisms"], doc["self_stress_states"]) == (11, 1, 1)
    assert len(doc["mechanism_modes"]) == 1 and len(doc["self_stress_modes"]) == 1
    m = meshio.read(tmp_path / "vtk" / "mechanism_01.vtu")
    assert m.point_data["displacement"].shape == (6, 3)
    s = meshio.read(tmp_path / "vtk" / "self_stress_01.vtu")
    assert s.cell_data["self_stress"][0].shape == (12,)
    ET.parse(tmp_path / "vtk" / "mechanisms.pvd")


def test_trace_json_vtk_plot(tmp_path):
    out = tmp_path / "t.json"
    rc = main(["trace", str(mesh_path("mech_hortobagyi_sec4.toml")), "--drive", "1:y",
               "--step", "-0.1", "--steps", "3", "--branch", "1", "--json", str(out),
               "--vtk", str(tmp_path / "vtk"), "--plot", str(tmp_path / "p.png")])
    assert rc == 0
    doc = json.loads(out.read_text())
    assert doc["command"] == "trace" and len(doc["path"]) == 4
    first = doc["path"][1]["positions"]
    # branch 1 = Hortobágyi's path 2: node 1 stays, node 2 goes to (2l − l/199.5, −l/10)
    np.testing.assert_allclose(first["1"], [1.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(first["2"], [1 + np.sqrt(0.99), -0.1], rtol=1e-10)
    assert doc["path"][0]["rank"] == 2 and doc["path"][1]["rank"] == 3
    assert doc["events"][0]["kind"] == "bifurcation"
    root = ET.parse(tmp_path / "vtk" / "path.pvd").getroot()
    assert len(root.findall(".//DataSet")) == 4
    assert (tmp_path / "p.png").stat().st_size > 1000


def test_trace_analyse_contract():
    doc = api.trace(mesh_path("mech_fourbar.toml"), drive="2:y", step=0.05,
                    steps=2).to_dict()
    assert set(doc["path"][0]) >= {"parameter", "positions", "rank"}
    assert isinstance(doc["events"], list)


@pytest.mark.parametrize("args, text", [
    (["--drive", "1:x", "--step", "0.1", "--steps", "3"], "fixed"),
    (["--drive", "2:z", "--step", "0.1", "--steps", "3"], "axis 'z'"),
    (["--drive", "2:y", "--step", "0.1", "--steps", "0"], "steps"),
    (["--drive", "2:y", "--drive", "3:y", "--step", "0.1", "--step", "0.1", "--step", "1",
      "--steps", "2"], "one --step per --drive"),
])
def test_trace_bad_input(args, text, capsys):
    rc = main(["trace", str(mesh_path("mech_fourbar.toml"))] + args)
    err = capsys.readouterr().err
    assert rc == 2 and err.startswith("trussfe: error:") and text in err
    assert err.count("\n") == 1


def test_trace_rigid_model(tmp_path, capsys):
    out = tmp_path / "t.json"
    rc = main(["trace", str(mesh_path("mech_octahedron_rigid.toml")), "--drive", "3:x",
               "--step", "0.02", "--steps", "2", "--json", str(out)])
    err = capsys.readouterr().err
    assert rc == 2 and "rigid" in err and "no mechanism to trace" in err
    assert not out.exists()                              # nothing written half-way


def test_trace_divergence_message(capsys):
    rc = main(["trace", str(mesh_path("mech_sec8_compound.toml")), "--drive", "5:y",
               "--step", "0.02", "--steps", "10"])
    err = capsys.readouterr().err
    assert rc == 2 and "leaves the motion region" in err


def test_mechanism_vtk_reads_back_values(tmp_path):
    """The VTK written through trussfe.io.vtk holds the values of the JSON: the mechanism shape
    (padded to 3 components), the self-stress tensions, and along a trace the positions and
    the displacement from the start state; the .pvd lists the path parameter as time."""
    from trussfe.io.vtk import read_pvd
    out = tmp_path / "r.json"
    assert main(["mechanism", str(mesh_path("mech_bricard.toml")), "--json", str(out),
                 "--vtk", str(tmp_path / "m")]) == 0
    doc = json.loads(out.read_text())
    m = meshio.read(tmp_path / "m" / "mechanism_01.vtu")
    shape = np.zeros((6, 3))
    for nid, v in doc["mechanism_modes"][0].items():     # JSON lists the moving nodes
        shape[int(nid) - 1] = v
    np.testing.assert_allclose(m.point_data["displacement"], shape, atol=1e-12)
    assert np.linalg.norm(m.point_data["displacement"]) > 0.1
    s = meshio.read(tmp_path / "m" / "self_stress_01.vtu")
    assert s.cell_data["member_id"][0].tolist() == list(range(12))
    t = tmp_path / "t.json"
    assert main(["trace", str(mesh_path("mech_fourbar.toml")), "--drive", "2:y", "--step",
                 "0.05", "--steps", "3", "--json", str(t), "--vtk", str(tmp_path / "t")]) == 0
    doc = json.loads(t.read_text())
    entries = read_pvd(tmp_path / "t" / "path.pvd")
    assert [e[0] for e in entries] == pytest.approx([p["parameter"] for p in doc["path"]])
    last = meshio.read(entries[-1][1])
    pos = np.array([doc["path"][-1]["positions"][str(i)] for i in range(1, 5)])
    np.testing.assert_allclose(last.points[:, :2], pos, rtol=1e-12, atol=1e-12)
    first = np.array([doc["path"][0]["positions"][str(i)] for i in range(1, 5)])
    np.testing.assert_allclose(last.point_data["displacement"][:, :2], pos - first, atol=1e-12)
    assert np.all(last.point_data["displacement"][:, 2] == 0)
