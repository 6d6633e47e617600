# SPDX-License-Identifier: MIT
"""``trussfe static --all --vtk OUT.vtu`` on a frame: ``OUT_stations.pvd`` lists every case's
and combination's ``_stations.vtu`` with the time values of ``OUT.pvd``, so that ParaView
steps through the section forces as through the cases; a truss without member loads writes
no stations series.

The values: a cantilever of length L = 2 m under a tip load P (case ``tip``) and its double
(case ``twice``): the root moment of each stations file is P L (statics).
"""
from __future__ import annotations

import meshio
import numpy as np
import pytest

from trussfe.cli import main
from trussfe.io.vtk import read_pvd

FRAME = """
[model]
name = "cantilever"
dimension = 2
[materials.st]
E = 2.0e11
[sections.s]
area = 1.0e-3
Iz = 1.0e-6
c = 0.05
[nodes]
A = [0.0, 0.0]
B = [2.0, 0.0]
[members]
AB = { nodes = ["A", "B"], section = "s", material = "st", type = "beam" }
[supports]
A = ["x", "y", "rz"]
[load_cases.tip]
loads = { B = [0.0, -1000.0, 0.0] }
[load_cases.twice]
loads = { B = [0.0, -2000.0, 0.0] }
[combinations]
both = { tip = 1.0, twice = 1.0 }
"""


def test_stations_series_of_the_cases(tmp_path):
    model = tmp_path / "frame.toml"
    model.write_text(FRAME)
    assert main(["static", str(model), "--vtk", str(tmp_path / "v.vtu")]) == 0
    cases = read_pvd(tmp_path / "v.pvd")
    stations = read_pvd(tmp_path / "v_stations.pvd")
    assert [t for t, _ in stations] == [t for t, _ in cases]
    assert [f.name for _, f in stations] == [f.with_name(f.stem + "_stations.vtu").name
                                              for _, f in cases]
    for (_, f), P in zip(stations, (1000.0, 2000.0, 3000.0)):
        mesh = meshio.read(f)
        root = int(np.argmin(mesh.point_data["xi"]))
        assert abs(mesh.point_data["moment_z"][root]) == pytest.approx(P * 2.0, rel=1e-12)


def test_truss_cases_have_no_stations_series(tmp_path):
    model = tmp_path / "truss.toml"
    truss = (FRAME.replace(', type = "beam"', "")
             .replace('A = ["x", "y", "rz"]', 'A = ["x", "y"]\nB = ["y"]')
             .replace("[0.0, -1000.0, 0.0]", "[-1000.0, 0.0]")
             .replace("[0.0, -2000.0, 0.0]", "[-2000.0, 0.0]"))
    model.write_text(truss)
    assert main(["static", str(model), "--vtk", str(tmp_path / "v.vtu")]) == 0
    assert (tmp_path / "v.pvd").is_file()
    assert not (tmp_path / "v_stations.pvd").exists()
