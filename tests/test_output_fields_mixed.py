# SPDX-License-Identifier: MIT
"""The files the commands write, read back and compared with docs/vtk.md, docs/json.md and
the Python results: mode sets of models whose members are subdivided unevenly (beams beside
truss bars), and the field data the VTK page lists."""
from __future__ import annotations

import json
import re
from pathlib import Path

import meshio
import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe.cli import main
from trussfe.io.vtk import read_pvd

DOCS = Path(__file__).resolve().parents[1] / "docs"

# Two beams (subdivided) beside three truss bars (one element each); ids are strings, not in
# the order of the nodes.  Under --bar-model truss only the beams are subdivided.
FRAME = """
[model]
name = "beams beside bars"
dimension = 2

[materials.steel]
E = 2.0e11
G = 8.0e10
density = 7850.0

[sections.bar]
area = 1.0e-4

[sections.beam]
area = 1.0e-3
Iz = 4.0e-6
c = 0.05

[nodes]
n7 = [2.0, 0.0]
"a.b" = [0.0, 0.0]
n3 = [1.0, 1.0]
"10" = [3.0, 1.0]

[members]
m9 = { nodes = ["n3", "10"], section = "beam", material = "steel", type = "beam" }
z1 = { nodes = ["a.b", "n3"], section = "bar", material = "steel" }
"beam 2" = { nodes = ["n7", "n3"], section = "beam", material = "steel", type = "beam" }
"3" = { nodes = ["a.b", "n7"], section = "bar", material = "steel" }
k = { nodes = ["n7", "10"], section = "bar", material = "steel" }

[supports]
"a.b" = ["x", "y"]
n7 = ["y"]
"10" = ["y"]

[loads]
n3 = [100.0, -2000.0]
"""


@pytest.fixture
def frame(tmp_path):
    p = tmp_path / "frame.toml"
    p.write_text(FRAME)
    return p


def _largest_translation(mesh: meshio.Mesh) -> float:
    return float(np.nanmax(np.linalg.norm(mesh.point_data["displacement"], axis=1)))


def _member_ends(station: meshio.Mesh, member: int) -> tuple[int, int]:
    """The first and last station point of a member in a station file."""
    seg = station.cells_dict["line"][station.cell_data["member_id"][0] == member]
    return int(seg[0, 0]), int(seg[-1, 1])


def test_buckling_stations_of_beams_beside_bars(frame, tmp_path, capsys):
    """docs/vtk.md: ``displacement`` of a mode set is "scaled so that the longest translation
    over the joints and the points along the members, in <name>_stations.pvd, is 1", and
    ``mode_shape`` (buckling) has "largest translation component over the joints and the
    points along the members +1" — as the JSON ``modes[i].shape`` (docs/json.md).  With
    beams subdivided and truss bars not, the members' shapes must still be written."""
    out = tmp_path / "vtk"
    assert main(["buckling", str(frame), "--bar-model", "truss", "--json",
                 str(tmp_path / "b.json"), "--vtk", str(out)]) == 0
    capsys.readouterr()
    doc = json.loads((tmp_path / "b.json").read_text())
    res = trussfe.buckling(frame, bar_model="truss")
    s = res.structure
    assert (out / "buckling_stations.pvd").is_file()
    joints = read_pvd(out / "buckling.pvd")
    along = read_pvd(out / "buckling_stations.pvd")
    assert [t for t, _ in along] == [t for t, _ in joints] == [1.0, 2.0, 3.0, 4.0]
    for i, ((_, fj), (_, fs)) in enumerate(zip(joints, along)):
        mj, ms = meshio.read(fj), meshio.read(fs)
        shape = np.array([doc["modes"][i]["shape"][n] for n in s.node_ids])
        assert_allclose(mj.point_data["mode_shape"][:, :2], shape, atol=1e-12)
        assert_allclose(shape, res.shapes[i], atol=1e-12)
        # the largest translation component over joints and stations is +1
        comp = ms.point_data["mode_shape"]
        assert comp.ravel()[np.argmax(np.abs(comp))] == pytest.approx(1.0)
        assert max(_largest_translation(mj), _largest_translation(ms)) == pytest.approx(1.0)
        # the beams have their stations, the bars their two ends
        counts = np.bincount(ms.cell_data["member_id"][0], minlength=s.n_members)
        assert counts.tolist() == res.solution.fe.member_subdivisions.tolist()
        for j, (a, b) in enumerate(s.connectivity):
            p, q = _member_ends(ms, j)
            assert_allclose(ms.point_data["mode_shape"][[p, q]],
                            mj.point_data["mode_shape"][[a, b]], atol=1e-12)
            assert ms.point_data["xi"][p] == 0.0 and ms.point_data["xi"][q] == 1.0


def test_vibration_stations_of_beams_beside_bars(frame, tmp_path, capsys):
    """docs/vtk.md, ``modes``: ``DIR/modes_stations.pvd`` holds the shapes along subdivided
    members, and ``displacement`` is scaled to a longest translation of 1 over the joints and
    those points; ``mode_shape`` is the mass-normalised shape of docs/json.md."""
    out = tmp_path / "vtk"
    assert main(["modes", str(frame), "--count", "3", "--json", str(tmp_path / "m.json"),
                 "--vtk", str(out)]) == 0
    capsys.readouterr()
    doc = json.loads((tmp_path / "m.json").read_text())
    s = trussfe.modes(frame, count=3).structure
    assert (out / "modes_stations.pvd").is_file()
    for i, ((_, fj), (_, fs)) in enumerate(zip(read_pvd(out / "modes.pvd"),
                                               read_pvd(out / "modes_stations.pvd"))):
        mj, ms = meshio.read(fj), meshio.read(fs)
        shape = np.array([doc["modes"][i]["shape"][n] for n in s.node_ids])
        assert_allclose(mj.point_data["mode_shape"][:, :2], shape, rtol=1e-12, atol=1e-12)
        assert max(_largest_translation(mj), _largest_translation(ms)) == pytest.approx(1.0)
        assert ms.field_data["frequency_hz"][0] == pytest.approx(doc["frequencies_hz"][i])


def _documented_field_data() -> set[str]:
    """The names of the rows of kind ``field`` in docs/vtk.md's table."""
    names = set()
    for line in (DOCS / "vtk.md").read_text().splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) >= 2 and cells[1] == "field":
            names |= set(re.findall(r"`([a-z_]+)`", cells[0]))
    return names


def test_documented_field_data_is_written(frame, tmp_path, capsys):
    """docs/vtk.md lists whole-data-set (field) values of a step; each one it names is in
    the field data of the files of some command (modes, buckling, postcritical and the
    motion series of simulate, elastic and transient)."""
    meshes = Path(__file__).resolve().parents[1] / "meshes"
    motion = ["--motion", str(meshes / "triangular_truss_motion_3s.toml"), "--steps", "3"]
    model = str(meshes / "triangular_truss_motion_active.toml")
    runs = {"modes": ["modes", str(frame), "--count", "2"],
            "buckling": ["buckling", str(frame), "--count", "2", "--bar-model", "truss"],
            "postcritical": ["postcritical", str(meshes / "postcritical_von_mises.toml"),
                             "--steps", "4"],
            "simulate": ["simulate", model, *motion],
            "elastic": ["elastic", model, *motion],
            "transient": ["transient", model, *motion]}
    written = set()
    for name, argv in runs.items():
        out = tmp_path / name
        assert main([*argv, "--vtk", str(out)]) == 0, name
        for pvd in out.glob("*.pvd"):
            for _, f in read_pvd(pvd):
                written |= set(meshio.read(f).field_data)
    capsys.readouterr()
    documented = _documented_field_data()
    assert {"frequency_hz", "load_factor", "mode"} <= documented
    assert documented <= written, f"documented but never written: {documented - written}"


def test_trace_parameter_is_the_pvd_time_and_grows_for_a_negative_step(tmp_path, capsys):
    """docs/json.md, ``trace``: ``path[k].parameter`` is the accumulated size of the drive
    increments, 0 at the start state and increasing whatever the sign of ``--step``;
    docs/vtk.md: it is the time value of ``DIR/path.pvd``, whose step ``k`` is at the
    positions ``path[k].positions`` with ``displacement`` from the start state."""
    model = Path(__file__).resolve().parents[1] / "meshes" / "mech_fourbar.toml"
    out = tmp_path / "vtk"
    assert main(["trace", str(model), "--drive", "2:y", "--step", "-0.02", "--steps", "5",
                 "--json", str(tmp_path / "t.json"), "--vtk", str(out)]) == 0
    capsys.readouterr()
    doc = json.loads((tmp_path / "t.json").read_text())
    param = [p["parameter"] for p in doc["path"]]
    assert param[0] == 0.0 and np.all(np.diff(param) > 0)
    steps = read_pvd(out / "path.pvd")
    assert [t for t, _ in steps] == pytest.approx(param, rel=1e-15)
    ids = list(doc["path"][0]["positions"])
    start = np.array([doc["path"][0]["positions"][n] for n in ids])
    for (_, f), p in zip(steps, doc["path"]):
        mesh = meshio.read(f)
        x = np.array([p["positions"][n] for n in ids])
        assert_allclose(mesh.points[:, :2], x, atol=1e-12)
        assert_allclose(mesh.point_data["displacement"][:, :2], x - start, atol=1e-12)


def test_simulate_pvd_times_are_the_json_times(tmp_path, capsys):
    """docs/vtk.md: the time of a step of a series is its ``.pvd`` time value; for
    ``simulate`` it is the JSON's ``time`` of the step to the last digit (a motion of 3 s in
    10 steps has times such as 0.3333333333333333 s, not 0.333333333)."""
    meshes = Path(__file__).resolve().parents[1] / "meshes"
    out = tmp_path / "vtk"
    assert main(["simulate", str(meshes / "triangular_truss_motion_active.toml"),
                 "--motion", str(meshes / "triangular_truss_motion_3s.toml"), "--steps", "10",
                 "--json", str(tmp_path / "s.json"), "--vtk", str(out)]) == 0
    capsys.readouterr()
    doc = json.loads((tmp_path / "s.json").read_text())
    times = [t for t, _ in read_pvd(next(out.glob("*.pvd")))]
    assert times == doc["time"]
    assert any(len(repr(t)) > 11 for t in times)
