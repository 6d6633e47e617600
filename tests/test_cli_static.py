# SPDX-License-Identifier: MIT
"""``trussfe static``: outputs, exit statuses and atomic writes (docs/cli.md, json.md, vtk.md).
Expected numbers: Lacy Table 3.2 (follower tension −78.5429 N, reactions at O1)."""
from __future__ import annotations

import json
import textwrap

import meshio
import numpy as np
import pytest

from trussfe.cli import main
from trussfe import api

MODEL = textwrap.dedent("""
    [model]
    name = "triangular truss, Table 3.2"
    dimension = 2
    [materials.al]
    E = 71.0e9
    G = 26.2e9
    density = 2711.5
    [sections.tube]
    outer_diameter = 0.0254
    inner_diameter = 0.022225
    [sections.follower]
    area = 1.1876e-4
    [nodes]
    1 = [0.0, 0.0]
    2 = [0.3128, 0.3903]
    3 = [1.5625, 1.9516]
    4 = [2.0, 0.0]
    [members]
    [members.base]
    nodes = ["1", "2"]
    section = "tube"
    material = "al"
    type = "beam"
    releases = ["start"]
    [members.leadscrew]
    nodes = ["2", "3"]
    section = "tube"
    material = "al"
    type = "beam"
    releases = ["end"]
    [members.follower]
    nodes = ["3", "4"]
    section = "follower"
    material = "al"
    [supports]
    1 = ["x", "y"]
    4 = ["x", "y"]
    [loads]
    3 = [0.0, -98.1]
    """)

MECHANISM = textwrap.dedent("""
    [model]
    name = "four-bar"
    dimension = 2
    [materials.al]
    E = 71.0e9
    [sections.rod]
    area = 1e-4
    [nodes]
    1 = [0.0, 0.0]
    2 = [1.0, 0.0]
    3 = [1.0, 1.0]
    4 = [0.0, 1.0]
    [members]
    a = { nodes = ["1", "2"], section = "rod", material = "al" }
    b = { nodes = ["2", "3"], section = "rod", material = "al" }
    c = { nodes = ["3", "4"], section = "rod", material = "al" }
    d = { nodes = ["4", "1"], section = "rod", material = "al" }
    [supports]
    1 = ["x", "y"]
    2 = ["x", "y"]
    [loads]
    3 = [10.0, 0.0]
    """)


@pytest.fixture
def model(tmp_path):
    p = tmp_path / "triangle.toml"
    p.write_text(MODEL)
    return p


def test_static_writes_json_and_vtu(model, tmp_path, capsys):
    out, vtu = tmp_path / "out" / "r.json", tmp_path / "r.vtu"
    status = main(["static", str(model), "--json", str(out), "--vtk", str(vtu)])
    assert status == 0
    doc = json.loads(out.read_text())
    assert doc["units"] == "SI" and doc["command"] == "static"
    assert doc["model"] == "triangular truss, Table 3.2"
    np.testing.assert_allclose(doc["members"]["follower"]["axial_force"], -78.5429, rtol=1e-4)
    np.testing.assert_allclose(doc["nodes"]["4"]["reaction"], [-17.1813, 76.6406], rtol=1e-4)
    assert "reaction" not in doc["nodes"]["3"]
    assert set(doc["members"]["base"]["end_forces"]["start"]) == {"N", "Vy", "Vz", "T", "My",
                                                                 "Mz"}
    mesh = meshio.read(vtu)
    assert mesh.points.shape == (4, 3)
    np.testing.assert_allclose(mesh.point_data["displacement"][2, :2],
                               doc["nodes"]["3"]["displacement"], rtol=1e-12)
    np.testing.assert_allclose(mesh.cell_data["axial_force"][0][2], -78.5429, rtol=1e-4)
    assert {"axial_stress", "von_mises"} <= set(mesh.cell_data)
    printed = capsys.readouterr().out
    assert "follower" in printed and "-78.54" in printed


def test_analyse_returns_the_json_document(model, tmp_path):
    out = tmp_path / "r.json"
    assert main(["static", str(model), "--json", str(out), "--bar-model", "pinned-beam",
                 "--subdivisions", "2"]) == 2   # follower has no Iz: pinned-beam refuses
    assert not out.exists()
    doc = api.static(model).to_dict()
    main(["static", str(model), "--json", str(out)])
    assert json.loads(out.read_text()) == json.loads(json.dumps(doc))


def test_mechanism_exits_2_and_writes_nothing(tmp_path, capsys):
    p = tmp_path / "four_bar.toml"
    p.write_text(MECHANISM)
    out, vtu = tmp_path / "r.json", tmp_path / "r.vtu"
    status = main(["static", str(p), "--json", str(out), "--vtk", str(vtu)])
    assert status == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("trussfe: error: ")
    assert "1 independent mechanism" in err and "3, 4" in err
    assert not out.exists() and not vtu.exists()
    assert list(tmp_path.iterdir()) == [p]


def test_missing_file_and_bad_subdivisions(model, tmp_path, capsys):
    assert main(["static", str(tmp_path / "nope.toml")]) == 2
    assert main(["static", str(model), "--subdivisions", "0"]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 2 and all(e.startswith("trussfe: error: ") for e in err)
    assert "--subdivisions" in err[1]


def test_large_model_prints_a_summary(tmp_path, capsys):
    """A 40-panel cantilevered Warren truss (82 nodes, 161 bars): the printed table stays
    short.  Method of sections at the first panel (panel length = depth = 1 m, tip load P at
    the bottom tip node): moments about t1 and b0 give the bottom chord −P·39 and the top
    chord +P·40."""
    n = 40
    lines = ["[model]", 'name = "warren"', "dimension = 2", "[materials.s]", "E = 2e11",
             "[sections.a]", "area = 1e-3", "[nodes]"]
    lines += [f"b{i} = [{i}.0, 0.0]" for i in range(n + 1)]
    lines += [f"t{i} = [{i}.0, 1.0]" for i in range(n + 1)]
    lines.append("[members]")
    k = 0
    for i in range(n):
        for a, b in ((f"b{i}", f"b{i + 1}"), (f"t{i}", f"t{i + 1}"), (f"b{i}", f"t{i + 1}")):
            lines.append(f'm{k} = {{ nodes = ["{a}", "{b}"], section = "a", material = "s" }}')
            k += 1
    for i in range(n + 1):
        lines.append(f'm{k} = {{ nodes = ["b{i}", "t{i}"], section = "a", material = "s" }}')
        k += 1
    lines += ["[supports]", 'b0 = ["x", "y"]', 't0 = ["x", "y"]', "[loads]",
              f"b{n} = [0.0, -100.0]"]
    p = tmp_path / "warren.toml"
    p.write_text("\n".join(lines) + "\n")
    out = tmp_path / "w.json"
    assert main(["static", str(p), "--json", str(out)]) == 0
    printed = capsys.readouterr().out.splitlines()
    assert len(printed) < 70
    assert any("most stressed of 161 members" in x for x in printed)
    doc = json.loads(out.read_text())
    np.testing.assert_allclose(doc["members"]["m0"]["axial_force"], -100.0 * (n - 1),
                               rtol=1e-9)
    np.testing.assert_allclose(doc["members"]["m1"]["axial_force"], 100.0 * n, rtol=1e-9)
