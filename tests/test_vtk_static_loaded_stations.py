# SPDX-License-Identifier: MIT
"""``trussfe static --vtk``: the stations file of members carrying member loads.

A loaded member is drawn through the stations of the JSON ``stations`` of the same run, so the
section forces read back from ``OUT_stations.vtu`` are the JSON's (the same numbers, rtol=0),
and the largest station ``von_mises`` of a member is its JSON ``max_von_mises``.  The
independent check is statics: a pin-ended bar of length L under a uniform transverse load q
has the simply supported moment q L²/8 at its midspan, a station of its JSON ``stations``
though no finite-element station lies inside the bar.
"""
from __future__ import annotations

import json

import meshio
import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal

from trussfe.cli import main

FORCES = {"N": "axial_force", "Vy": "shear_y", "Vz": "shear_z", "T": "torque",
          "My": "moment_y", "Mz": "moment_z"}
Q = 1000.0          # N/m, transverse uniform load on bar AB
L_AB = 2.0          # m
P = 500.0           # N, point load on bar BC at 0.3 of its length


def _model(tmp_path):
    text = f"""
member_loads = [
  {{ member = "AB", kind = "uniform", q = [0.0, -{Q}] }},
  {{ member = "BC", kind = "point", at = 0.3, F = [0.0, -{P}] }},
]

[model]
name = "pin-jointed bars under member loads"
dimension = 2

[materials.steel]
E = 2.0e11
G = 8.0e10

[sections.tube]
outer_diameter = 0.05
inner_diameter = 0.04

[nodes]
A = [0.0, 0.0]
B = [{L_AB}, 0.0]
C = [3.0, 1.0]

[members]
AB = {{ nodes = ["A", "B"], section = "tube", material = "steel" }}
BC = {{ nodes = ["B", "C"], section = "tube", material = "steel" }}
AC = {{ nodes = ["A", "C"], section = "tube", material = "steel" }}

[supports]
A = ["x", "y"]
B = ["y"]
C = ["x", "y"]
"""
    path = tmp_path / "bars.toml"
    path.write_text(text)
    return path


@pytest.fixture
def run(tmp_path):
    model = _model(tmp_path)
    out = tmp_path / "out" / "bars.vtu"
    js = tmp_path / "bars.json"
    assert main(["static", str(model), "--vtk", str(out), "--json", str(js)]) == 0
    return json.loads(js.read_text()), meshio.read(out.with_name("bars_stations.vtu")), \
        meshio.read(out)


def _member_points(mesh, k):
    """Points of member k in the stations file, in order along it."""
    cells = mesh.cells_dict["line"][mesh.cell_data["member_id"][0] == k]
    return np.r_[cells[:, 0], cells[-1, 1]]


def test_loaded_members_drawn_through_their_json_stations(run):
    doc, st, _ = run
    for k, (mid, member) in enumerate(doc["members"].items()):
        pts = _member_points(st, k)
        if "stations" not in member:
            assert st.point_data["xi"][pts].tolist() == [0.0, 1.0]
            continue
        along = member["stations"]
        x = np.asarray(along["x"])
        assert_allclose(st.point_data["xi"][pts], x / x[-1], rtol=0, atol=1e-15)
        for key, name in FORCES.items():
            assert_array_equal(st.point_data[name][pts], along[key], err_msg=f"{mid} {name}")


def test_simply_supported_moment_of_a_pin_ended_bar(run):
    doc, st, _ = run
    pts = _member_points(st, 0)                        # AB, horizontal, pin-ended
    xi = st.point_data["xi"][pts]
    mz = st.point_data["moment_z"][pts]
    mid = np.flatnonzero(np.isclose(xi, 0.5))
    assert mid.size == 1
    assert_allclose(abs(mz[mid[0]]), Q * L_AB ** 2 / 8, rtol=1e-12)


def test_largest_station_von_mises_is_the_members(run):
    doc, st, top = run
    for k, member in enumerate(doc["members"].values()):
        pts = _member_points(st, k)
        assert_allclose(np.nanmax(st.point_data["von_mises"][pts]), member["max_von_mises"],
                        rtol=1e-12)
        assert_allclose(top.cell_data["von_mises"][0][k], member["max_von_mises"], rtol=0)


def test_station_displacements_follow_the_joints(run):
    """The bars bend only between their joints in the finite-element model: the displacement
    along them is that of the joints, interpolated linearly; a 2-D model has z = 0."""
    doc, st, top = run
    conn = top.cells_dict["line"]
    u = np.array([n["displacement"] for n in doc["nodes"].values()])
    for k in range(conn.shape[0]):
        pts = _member_points(st, k)
        xi = st.point_data["xi"][pts][:, None]
        a, b = conn[k]
        assert_allclose(st.point_data["displacement"][pts, :2], (1 - xi) * u[a] + xi * u[b],
                        rtol=1e-12, atol=1e-20)
    assert not np.any(st.point_data["displacement"][:, 2])
    assert not np.any(st.points[:, 2])
    for v in st.point_data.values():
        assert np.all(np.isfinite(v))


def test_station_displacements_interpolate_each_member_as_numpy_interp():
    """The displacements at a loaded member's stations are interpolated between its
    finite-element stations for all members at once; reference: ``numpy.interp`` member by
    member (rows of different lengths, NaN-padded, stations beyond the ends clamped)."""
    from trussfe.io.vtk_results import _interpolate_rows
    rng = np.random.default_rng(1)
    rows, fe_stations, stations = 40, 7, 9
    xp = np.full((rows, fe_stations), np.nan)
    fp = rng.normal(size=(rows, fe_stations, 3))
    x = np.full((rows, stations), np.nan)
    for r in range(rows):
        n = rng.integers(2, fe_stations + 1)
        length = rng.uniform(0.5, 20.0)
        xp[r, :n] = np.sort(np.r_[0.0, length, rng.uniform(0.0, length, n - 2)])
        k = rng.integers(1, stations + 1)
        x[r, :k] = np.sort(rng.uniform(-0.1, length + 0.1, k))
    ok = np.isfinite(x)
    got = _interpolate_rows(x[ok], np.nonzero(ok)[0], xp, fp)
    ref = np.concatenate([np.stack([np.interp(x[r, ok[r]], xp[r, np.isfinite(xp[r])],
                                              fp[r, np.isfinite(xp[r]), c])
                                    for c in range(3)], axis=-1) for r in range(rows)])
    assert_allclose(got, ref, rtol=0, atol=1e-14)
