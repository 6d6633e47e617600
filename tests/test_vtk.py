# SPDX-License-Identifier: MIT
"""VTK output read back with meshio and with VTK's own reader (through pyvista).

Expected values are the arrays written: the files must carry them unchanged (round-off of the
binary Float64 encoding is exact, so rtol=0 is used except where stated).
"""
from __future__ import annotations

import numpy as np
import meshio
import pytest
from numpy.testing import assert_allclose, assert_array_equal

from trussfe.errors import InputError
from trussfe.io.vtk import read_pvd, write_pvd, write_series, write_stations, write_vtu
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

pv = pytest.importorskip("pyvista")


@pytest.fixture
def tri3d():
    """A tetrahedron of 6 bars (3-D)."""
    x = np.array([[0, 0, 0], [1, 0, 0], [0.5, 0.8, 0], [0.5, 0.3, 0.9]], float)
    conn = [[0, 1], [1, 2], [2, 0], [0, 3], [1, 3], [2, 3]]
    return build_structure(x, conn, section=Section.tube("t", 0.02, 0.016),
                           material=Material("al", 71e9, 2711.5), supports={0: "xyz"})


@pytest.fixture
def tri2d():
    """A 2-D triangle of 3 bars."""
    return build_structure([[0, 0], [1, 0], [0.5, 0.7]], [[0, 1], [1, 2], [2, 0]],
                           section=Section("s", 1e-4), material=Material("st", 2e11, 7850.0))


def test_vtu_roundtrip_meshio_and_vtk(tmp_path, tri3d):
    rng = np.random.default_rng(1)
    disp = rng.normal(size=(4, 3))
    force = rng.normal(size=6) * 1e3
    stress = force / tri3d.area
    path = write_vtu(tmp_path / "a" / "static.vtu", tri3d, point_data={"displacement": disp},
                     cell_data={"axial_force": force, "axial_stress": stress,
                                "von_mises": np.abs(stress)}, field_data={"time": 0.5})
    m = meshio.read(path)
    assert_array_equal(m.points, tri3d.coords)
    assert_array_equal(m.cells_dict["line"], tri3d.connectivity)
    assert_array_equal(m.point_data["displacement"], disp)
    assert_array_equal(m.cell_data["axial_force"][0], force)
    assert_array_equal(m.cell_data["member_id"][0], np.arange(6))
    assert_allclose(m.field_data["time"], [0.5], rtol=0)
    # VTK's own XML reader
    g = pv.read(path)
    assert g.n_points == 4 and g.n_cells == 6
    assert_array_equal(np.asarray(g.point_data["displacement"]), disp)
    assert_array_equal(np.asarray(g.cell_data["axial_stress"]), stress)
    assert_array_equal(np.asarray(g.cell_data["von_mises"]), np.abs(stress))
    assert_allclose(np.asarray(g.field_data["time"]), [0.5], rtol=0)
    # line cells (VTK_LINE = 3) between the right points
    assert set(np.asarray(g.celltypes).tolist()) == {3}
    assert_array_equal(np.asarray(g.cell_connectivity).reshape(-1, 2), tri3d.connectivity)
    # no temporary file left behind
    assert sorted(p.name for p in (tmp_path / "a").iterdir()) == ["static.vtu"]


def test_2d_vectors_padded(tmp_path, tri2d):
    """ParaView vectors are 3-D: 2-D points and displacements get z = 0."""
    d = np.array([[0, 0], [1e-3, 2e-3], [0, -1e-3]])
    g = pv.read(write_vtu(tmp_path / "t.vtu", tri2d, coords=tri2d.coords + d,
                          point_data={"displacement": d}))
    assert_array_equal(np.asarray(g.points)[:, :2], tri2d.coords + d)
    assert_array_equal(np.asarray(g.points)[:, 2], 0.0)
    assert np.asarray(g.point_data["displacement"]).shape == (3, 3)
    assert_array_equal(np.asarray(g.point_data["displacement"])[:, :2], d)


def test_bad_shapes_raise(tmp_path, tri2d):
    with pytest.raises(InputError, match="axial_force.*first dimension must be 3"):
        write_vtu(tmp_path / "x.vtu", tri2d, cell_data={"axial_force": [1.0, 2.0]})
    with pytest.raises(InputError, match="displacement"):
        write_vtu(tmp_path / "x.vtu", tri2d, point_data={"displacement": np.zeros((2, 2))})
    with pytest.raises(InputError, match=r"\.vtu"):
        write_vtu(tmp_path / "x.vtk", tri2d)
    assert not any(tmp_path.iterdir())


def test_series_pvd(tmp_path, tri3d):
    """A time series: one .vtu per step, .pvd times, arrays per step (meshio and VTK)."""
    times = np.array([0.0, 0.1, 0.2])
    vel = np.arange(3 * 4 * 3, dtype=float).reshape(3, 4, 3)
    frames = [{"time": t, "coords": tri3d.coords + 0.01 * k,
               "point_data": {"displacement": np.full((4, 3), 0.01 * k), "velocity": vel[k],
                              "acceleration": -vel[k]},
               "cell_data": {"axial_force": np.full(6, 10.0 * k),
                             "buckling_utilisation": np.full(6, 0.1 * k)}}
              for k, t in enumerate(times)]
    pvd = write_series(tmp_path / "out", tri3d, frames, "slew")
    entries = read_pvd(pvd)
    assert_allclose([t for t, _ in entries], times, rtol=0)
    for k, (_, f) in enumerate(entries):
        m = meshio.read(f)
        assert_array_equal(m.point_data["velocity"], vel[k])
        assert_array_equal(m.cell_data["axial_force"][0], np.full(6, 10.0 * k))
    # VTK's PVD reader resolves the collection and its time values
    reader = pv.get_reader(pvd)
    assert_allclose(reader.time_values, times, rtol=0)
    reader.set_active_time_value(0.2)
    g = reader.read()[0]
    assert_array_equal(np.asarray(g.point_data["acceleration"]), -vel[2])
    assert_allclose(np.asarray(g.cell_data["buckling_utilisation"]), 0.2, rtol=1e-15)


def test_series_failure_leaves_nothing(tmp_path, tri3d):
    frames = [{"cell_data": {"axial_force": np.zeros(6)}},
              {"cell_data": {"axial_force": np.zeros(5)}}]
    with pytest.raises(InputError):
        write_series(tmp_path / "out", tri3d, frames, "bad")
    assert not (tmp_path / "out" / "bad.pvd").exists()
    assert not (tmp_path / "out" / "bad").exists()


def test_pvd_rejects_nan(tmp_path):
    with pytest.raises(InputError, match="not finite"):
        write_pvd(tmp_path / "a.pvd", [(float("nan"), "a.vtu")])


def test_stations(tmp_path, tri2d):
    """Fields along members: m·s points on the member axes, m·(s−1) segments."""
    xi = np.linspace(0.0, 1.0, 5)
    m = tri2d.n_members
    moment = np.outer(np.arange(1, m + 1), xi * (1 - xi))        # (member, station)
    seg = np.arange(m * 4, dtype=float).reshape(m, 4)
    path = write_stations(tmp_path / "st.vtu", tri2d, xi, point_data={"bending_moment": moment},
                          cell_data={"axial_force": seg})
    g = pv.read(path)
    assert g.n_points == m * 5 and g.n_cells == m * 4
    pts = np.asarray(g.points)[:, :2].reshape(m, 5, 2)
    a, b = tri2d.coords[tri2d.connectivity[:, 0]], tri2d.coords[tri2d.connectivity[:, 1]]
    assert_allclose(pts, a[:, None] + xi[None, :, None] * (b - a)[:, None], rtol=0, atol=1e-15)
    assert_array_equal(np.asarray(g.point_data["bending_moment"]), moment.ravel())
    assert_array_equal(np.asarray(g.cell_data["axial_force"]), seg.ravel())
    assert_array_equal(np.asarray(g.cell_data["member_id"]), np.repeat(np.arange(m), 4))
    # each segment joins consecutive stations of one member
    c = np.asarray(g.cell_connectivity).reshape(-1, 2)
    assert np.all(c[:, 1] - c[:, 0] == 1)
    with pytest.raises(InputError, match="ascend"):
        write_stations(tmp_path / "b.vtu", tri2d, xi[::-1])


def test_static_fields_along_members(tmp_path):
    """A simply supported pinned-beam member under self-weight: the bending moment along it,
    read back from the stations file, is the parabola q x (L − x)/2 with q = ρ A g (statics;
    Hermite elements with consistent loads are exact at the nodes: rtol 1e-9); the truss bar
    beside it has its two end stations only (NaN padding dropped)."""
    from trussfe.fem import solve_static
    from trussfe.io.vtk_results import write_static
    mat = Material("steel", E=2.1e11, G=8.1e10, density=7850.0)
    sec = Section.tube("t", 0.02, 0.016)
    s = build_structure([[0, 0], [2, 0], [2, -1]], [[0, 1], [1, 2]], section=sec, material=mat,
                        supports={0: "xy", 2: "xy"}, gravity=[0.0, -9.81],
                        is_beam=[True, False])
    s = s.with_member_data(releases={0: [True, True]})   # member 0: pinned beam, 8 elements
    r = solve_static(s, subdivisions=8)
    files = write_static(tmp_path / "static.vtu", r)
    assert [f.name for f in files] == ["static.vtu", "static_stations.vtu"]
    g = pv.read(files[1])
    member = np.asarray(g.cell_data["member_id"])
    assert (member == 0).sum() == 8 and (member == 1).sum() == 1
    assert g.n_points == 9 + 2
    xi = np.asarray(g.point_data["xi"])[:9]
    M = np.asarray(g.point_data["moment_z"])[:9]
    q = mat.density * sec.area * 9.81
    x = xi * 2.0
    assert_allclose(np.abs(M), q * x * (2.0 - x) / 2, rtol=1e-9, atol=1e-12 * q)
    top = pv.read(files[0])
    assert_allclose(np.asarray(top.cell_data["axial_force"]), r.axial_force, rtol=0)
