# SPDX-License-Identifier: MIT
"""``trussfe modes`` and ``trussfe buckling`` end to end: JSON per docs/json.md, VTK mode
sets read back with VTK's own reader, exit status 2 with one line on bad input."""
from __future__ import annotations

import json

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.cli import main
from trussfe import api
from trussfe.io.vtk import read_pvd

pv = pytest.importorskip("pyvista")

COLUMN = """
[model]
name = "pinned column"
dimension = 2
[materials.aluminium]
E = 71.0e9
G = 26.2e9
density = 2711.5
[sections.tube]
outer_diameter = 0.0254
inner_diameter = 0.022225
[nodes]
A = [0.0, 0.0]
B = [0.0, 2.0]
[members]
follower = { nodes = ["A", "B"], section = "tube", material = "aluminium" }
[supports]
A = ["x", "y"]
B = ["x"]
[loads]
B = [0.0, LOAD]
"""

SQUARE = """
[model]
name = "square without diagonal"
dimension = 2
[materials.steel]
E = 2.1e11
density = 7850.0
[sections.s]
area = 1e-4
Iy = 1e-9
[nodes]
1 = [0.0, 0.0]
2 = [1.0, 0.0]
3 = [1.0, 1.0]
4 = [0.0, 1.0]
[members]
a = { nodes = ["1", "2"], section = "s", material = "steel" }
b = { nodes = ["2", "3"], section = "s", material = "steel" }
c = { nodes = ["3", "4"], section = "s", material = "steel" }
d = { nodes = ["4", "1"], section = "s", material = "steel" }
[supports]
1 = ["x", "y"]
2 = ["x", "y"]
[loads]
3 = [0.0, -10.0]
"""


@pytest.fixture
def column(tmp_path):
    p = tmp_path / "column.toml"
    p.write_text(COLUMN.replace("LOAD", "-1.0"))
    return p


def test_buckling_cli(tmp_path, column, capsys):
    """Load factor = Euler load of the follower, 1481.2 N (Lacy Table 3.3); k = 8 elements
    are 3.3e-5 stiff (measured convergence, tests/test_buckling.py)."""
    out = tmp_path / "b.json"
    assert main(["buckling", str(column), "--count", "2", "--subdivisions", "8",
                 "--json", str(out), "--vtk", str(tmp_path / "vtk")]) == 0
    doc = json.loads(out.read_text())
    assert doc["units"] == "SI" and doc["command"] == "buckling"
    assert doc["model"] == "pinned column"
    lf = doc["load_factors"]
    assert abs(lf[0]) <= abs(lf[1])
    assert_allclose(lf[0], 1481.2, rtol=5e-5)
    assert_allclose(doc["members"]["follower"]["euler_load"], 1481.2, rtol=5e-5)
    assert doc == api.buckling(column, count=2, subdivisions=8).to_dict()
    # VTK: a step per mode, with the load factor as field data and member cell data
    pvd = tmp_path / "vtk" / "buckling.pvd"
    assert [t for t, _ in read_pvd(pvd)] == [1.0, 2.0]
    r = pv.get_reader(pvd)
    r.set_active_time_value(1.0)
    g = r.read()[0]
    assert_allclose(np.asarray(g.field_data["load_factor"]), [lf[0]], rtol=1e-12)
    assert_allclose(np.asarray(g.cell_data["euler_load"]), [1481.2], rtol=5e-5)
    # first buckling mode of a pinned column: both ends stay on the axis, so the nodal
    # displacement is axial only; the half sine appears along the member stations
    st = pv.get_reader(tmp_path / "vtk" / "buckling_stations.pvd")
    st.set_active_time_value(1.0)
    sg = st.read()[0]
    xi = np.asarray(sg.point_data["xi"])
    w = np.asarray(sg.point_data["displacement"])[:, 0]        # transverse = global x
    assert_allclose(np.abs(w), np.abs(w).max() * np.sin(np.pi * xi), atol=1e-3)
    assert "critical load factor: 1481.24" in capsys.readouterr().out


def test_modes_cli(tmp_path, column):
    out = tmp_path / "m.json"
    assert main(["modes", str(column), "--count", "2", "--bar-model", "pinned-beam",
                 "--subdivisions", "16", "--json", str(out), "--vtk", str(tmp_path)]) == 0
    doc = json.loads(out.read_text())
    f = doc["frequencies_hz"]
    assert f == sorted(f) and len(doc["modes"]) == 2
    # simply supported beam: f1 = (π/L)² √(EI/ρA) / 2π (16 elements: 1.0e-6 high, measured)
    from trussfe.model.sections import Section
    t = Section.tube("t", 0.0254, 0.022225)
    exact = (np.pi / 2.0) ** 2 * np.sqrt(71e9 * t.Iz / (2711.5 * t.area)) / (2 * np.pi)
    assert_allclose(f[0], exact, rtol=2e-6)
    assert set(doc["modes"][0]["shape"]) == {"A", "B"}
    assert doc["modes"][0]["frequency_hz"] == f[0]
    g = pv.get_reader(tmp_path / "modes.pvd")
    assert_allclose(g.time_values, [1.0, 2.0])
    g.set_active_time_value(2.0)
    assert_allclose(np.asarray(g.read()[0].field_data["frequency_hz"]), [f[1]], rtol=1e-12)
    assert api.modes(column, count=2, bar_model="pinned-beam",
                    subdivisions=16).frequencies_hz.tolist() == pytest.approx(f, rel=1e-12)


def test_mechanism_modes_and_buckling(tmp_path, capsys):
    p = tmp_path / "square.toml"
    p.write_text(SQUARE)
    out = tmp_path / "m.json"
    assert main(["modes", str(p), "--count", "2", "--json", str(out)]) == 0
    doc = json.loads(out.read_text())
    assert doc["rigid_modes"] == 1 and doc["frequencies_hz"][0] == 0.0
    assert "1 zero-frequency mode(s)" in capsys.readouterr().out
    assert main(["buckling", str(p)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("trussfe: error: ") and "mechanism" in err and err.count("\n") == 1


@pytest.mark.parametrize("args,needle", [
    (["modes", "{col}", "--count", "99"], "asked for 99 modes"),
    (["modes", "{col}", "--count", "0"], "--count"),
    (["buckling", "{unloaded}"], "unloaded"),
])
def test_bad_input(tmp_path, column, capsys, args, needle):
    unloaded = tmp_path / "unloaded.toml"
    unloaded.write_text(COLUMN.replace("LOAD", "0.0"))
    argv = [a.format(col=column, unloaded=unloaded) for a in args]
    assert main(argv + ["--json", str(tmp_path / "x.json")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("trussfe: error: ") and needle in err and err.count("\n") == 1
    assert not (tmp_path / "x.json").exists()


LEAN = """
[model]
name = "lean"
dimension = 2
[materials.steel]
E = 2.0e11
density = 0.0
[sections.s]
area = 1.0e-3
Iz = 1.0e-6
c = 0.05
[sections.big]
area = 1.0e-1
Iz = 1.0e-6
c = 0.05
[nodes]
A = [0.0, 0.0]
B = [0.0, 3.0]
C = [2.0, 0.0]
D = [2.0, 3.0]
[members]
AB = { nodes = ["A", "B"], section = "s", material = "steel", type = "beam" }
CD = { nodes = ["C", "D"], section = "s", material = "steel" }
BD = { nodes = ["B", "D"], section = "big", material = "steel" }
[supports]
A = ["x", "y", "rz"]
C = ["x", "y"]
[loads]
D = [0.0, -1000.0]
"""


def test_buckling_without_count_lists_the_finite_load_factors_there_are(tmp_path, capsys):
    """A leaning column with truss bars has one finite load factor, 3EI/L² / 1000 N = 66.67
    (the strut leaning on the cantilever): without --count the command lists it and says
    that there are no more (it stopped: "asked for 4 load factors but only 1")."""
    path = tmp_path / "lean.toml"
    path.write_text(LEAN)
    assert main(["buckling", str(path), "--bar-model", "truss"]) == 0
    out = capsys.readouterr().out
    assert "critical load factor: 66.666" in out
    assert "only 1 finite load factor(s): all of them computed" in out
    assert main(["buckling", str(path), "--bar-model", "truss", "--count", "2"]) == 2
    assert "only 1 finite ones exist" in capsys.readouterr().err
