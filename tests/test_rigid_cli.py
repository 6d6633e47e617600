# SPDX-License-Identifier: MIT
"""``trussfe simulate`` end to end, and the one-line errors for bad input."""
import json

import numpy as np
import trussfe
import pytest
from numpy.testing import assert_allclose

from trussfe._resources import mesh_path
from trussfe.cli import main
from trussfe.errors import AnalysisError, InputError
from trussfe.io.model_file import read_model
from trussfe.rigid.motion import Motion
from trussfe.rigid.motion_file import load_motion
from trussfe.studies.lacy_rigid import triangular_truss
from trussfe.rigid.simulate import simulate
from trussfe import api


def analyse(model, **options):
    """The ``simulate`` JSON document through the Python API."""
    return api.simulate(model, **options).to_dict()


MODEL = "triangular_truss_motion_active.toml"


def _mesh(name):
    return str(mesh_path(name))


def test_simulate_cli_writes_every_output(tmp_path):
    out = tmp_path / "r.json"
    rc = main(["simulate", _mesh(MODEL), "--motion", _mesh("triangular_truss_motion_3s.toml"),
               "--json", str(out), "--npz", str(tmp_path / "r.npz"), "--vtk",
               str(tmp_path / "vtk"), "--plots", str(tmp_path / "png")])
    assert rc == 0
    d = json.loads(out.read_text())
    assert d["command"] == "simulate" and d["units"] == "SI"
    assert len(d["time"]) == 50
    assert len(d["members"]["follower"]["axial_force"]) == 50
    assert set(d["nodes"]["O1"]) == {"position", "reaction"}
    assert "reaction" not in d["nodes"]["B"]
    assert len(d["actuators"]["active"]["force"]) == 50
    assert (tmp_path / "vtk" / "triangular_truss_motion_active.pvd").is_file()
    assert len(list((tmp_path / "vtk").glob("*.vtu"))) == 50
    assert (tmp_path / "png" / "von_mises.png").is_file()
    z = np.load(tmp_path / "r.npz")
    assert z["von_mises"].shape == (50, 2, 7)
    # the NPZ holds the arrays the JSON summarises: the same buckling margin and actuator
    # force history
    follower = list(z["member_ids"]).index("follower")
    margin = d["summary"]["members"]["follower"]["buckling"]["margin"]
    assert z["buckling_margin"][follower] == pytest.approx(margin, rel=1e-12)
    assert_allclose(z["actuator_force"][:, 0], d["actuators"]["active"]["force"], rtol=1e-12)
    assert z["static_tension"].shape == z["tension"].shape
    assert {"length", "length_rate", "length_acc", "omega", "alpha", "static_reactions",
            "midpoint_axial_force", "static_actuator_force", "cantilever_moment",
            "buckling_allowable", "buckling_max_compression"} <= set(z.files)
    _check_vtk_series(tmp_path / "vtk", d)


def _check_vtk_series(folder, d):
    """The .vtu steps read back (meshio and VTK's own reader) hold the JSON histories.

    Independent of the writer: the actuator force must equal the JSON history of the active
    member, and the largest buckling utilisation over the steps must equal the reciprocal of
    the JSON buckling margin (max compression / Euler allowable, Lacy eq. 2.26).
    """
    import meshio
    import pyvista as pv

    files = sorted(folder.glob("*.vtu"))
    order = list(d["members"])                      # member order of the model file
    util = []
    for k, f in enumerate(files):
        mesh = meshio.read(f)
        cd = {name: v[0] for name, v in mesh.cell_data.items()}
        assert set(cd) >= {"axial_force", "von_mises", "buckling_utilisation", "actuator_force"}
        assert_allclose(cd["actuator_force"][order.index("active")],
                        d["actuators"]["active"]["force"][k], rtol=1e-12)
        assert cd["actuator_force"][order.index("follower")] == 0.0
        assert_allclose(cd["axial_force"], [d["members"][m]["axial_force"][k] for m in order],
                        rtol=1e-12)
        util.append(cd["buckling_utilisation"])
    util = np.array(util)
    for j, m in enumerate(order):
        b = d["summary"]["members"][m]["buckling"]
        assert_allclose(util[:, j].max(), b["max_compression"] / b["allowable"], rtol=1e-12)
    grid = pv.read(files[-1])
    assert_allclose(grid.cell_data["buckling_utilisation"], util[-1], rtol=1e-12)


def test_model_file_matches_built_model():
    """The shipped TOML model gives the O1 reaction after Table 3.2 (−20.1303, 92.9545 N)."""
    d = analyse(_mesh(MODEL))
    assert_allclose(d["nodes"]["O1"]["reaction"][0], [-20.1303, 92.9545], rtol=5e-6)
    assert d["time"] == [0.0]


def test_motion_file_reproduces_velocity():
    """Lacy section 3.7: 1.2477 m/s from the shipped 3 s motion file."""
    s = read_model(_mesh(MODEL))
    m = load_motion(_mesh("triangular_truss_motion_3s.toml"), s)
    assert_allclose(m.velocity.max(), 1.2477, rtol=5e-5)


def test_no_assembly_names_step_and_members():
    """Active member longer than follower + base (4 m): no triangle exists.  The truss' own
    stroke (2.5-4.1 m) refuses 4.5 m first; without stroke limits the assembly fails."""
    import dataclasses
    s = triangular_truss()
    L = np.array([[2.5], [3.5], [4.5]])
    m = Motion([0, 1, 2], [1], L, np.zeros_like(L), np.zeros_like(L))
    with pytest.raises(InputError, match=r"step 2 \(t = 2 s\): active member 'active' is 4\.5 m"):
        simulate(s, m)
    free = s.with_extensions(active_members=[
        dataclasses.replace(a, max_length=float("nan")) for a in s.extensions["active_members"]])
    with pytest.raises(AnalysisError, match=r"step 2 .*no assembly.*'active' = 4\.5"):
        simulate(free, m)


def test_singular_position_is_reported_not_garbage():
    """At 4.0 m the triangle is flat: the forces are not determined there."""
    s = triangular_truss()
    L = np.array([[3.9], [3.99], [4.0]])
    m = Motion([0, 1, 2], [1], L, np.ones_like(L), np.zeros_like(L))
    with pytest.raises(AnalysisError, match="singular"):
        simulate(s, m)


def test_non_monotonic_time_and_nan():
    with pytest.raises(InputError, match="increase strictly"):
        Motion([0.0, 0.2, 0.1], [1], np.full((3, 1), 2.5), np.zeros((3, 1)), np.zeros((3, 1)))
    L = np.array([[2.5], [np.nan]])
    with pytest.raises(InputError, match="NaN at sample 1"):
        Motion([0.0, 0.1], [1], L, np.zeros((2, 1)), np.zeros((2, 1)))


def test_unknown_active_member_in_motion(tmp_path):
    f = tmp_path / "m.toml"
    f.write_text('[motion]\nduration = 1.0\nstart = { actuator = 2.5 }\nend = { active = 3 }\n')
    with pytest.raises(InputError, match="'actuator' is not an active member"):
        load_motion(f, read_model(_mesh(MODEL)))


def test_unknown_member_in_active_members_table(tmp_path):
    text = open(_mesh(MODEL)).read().replace("[active_members.active]",
                                             "[active_members.activ]")
    f = tmp_path / "bad.toml"
    f.write_text(text)
    with pytest.raises(InputError, match="'activ' is not a member"):
        read_model(f)


def test_cli_bad_input_one_line_exit_2(tmp_path, capsys):
    f = tmp_path / "m.toml"
    f.write_text('[motion]\nduration = -1.0\nstart = { active = 2.5 }\nend = { active = 3 }\n')
    rc = main(["simulate", _mesh(MODEL), "--motion", str(f), "--json", str(tmp_path / "o.json")])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and err[0].startswith("trussfe: error:")
    assert not (tmp_path / "o.json").exists()


def test_statically_indeterminate_truss_needs_fe():
    """A third bar from O1 to B over-constrains B: rigid-body forces are not determined."""
    from trussfe import build_structure
    from trussfe.studies.lacy_rigid import ALUMINIUM, TUBE
    s = build_structure([[0, 0], [2, 0], [1, 1], [1, 0]], [[0, 2], [1, 2], [3, 2]],
                        section=TUBE, material=ALUMINIUM, supports={0: "xy", 1: "xy", 3: "xy"})
    with pytest.raises(AnalysisError, match="statically indeterminate.*finite-element"):
        simulate(s)


@pytest.mark.parametrize("edit, match", [
    ("tube_length = 2.0", "tube_length = 5.0", ),
    ("base_mass = 2.4", "base_mass = -1.0"),
    ("base_cg = 1.05", "base_cg = 1.05\nstroke = 3"),
])
def test_active_member_table_errors(tmp_path, edit, match):
    """Tube longer than the member, negative mass, unknown key: one InputError each."""
    text = open(_mesh(MODEL)).read().replace(edit, match)
    f = tmp_path / "bad.toml"
    f.write_text(text)
    with pytest.raises(InputError, match=r"active_members\.active"):
        read_model(f)


def test_simulate_without_active_members_is_a_static_analysis(tmp_path):
    """A model without [active_members] is analysed at rest; a --motion for it is refused."""
    text = open(_mesh(MODEL)).read().split("[active_members.active]")[0]
    f = tmp_path / "plain.toml"
    f.write_text(text)
    d = analyse(str(f))
    from trussfe.fem.static import solve_static
    fe = solve_static(read_model(f), "pinned-beam")      # independent solver, uniform tubes
    assert_allclose(d["nodes"]["O1"]["reaction"][0], fe.reactions[1, :2], rtol=1e-9)
    with pytest.raises(InputError, match="no \\[active_members\\]"):
        analyse(str(f), motion=_mesh("triangular_truss_motion_3s.toml"))


def test_cli_thesis_scheme_reproduces_base_simulation():
    """``--scheme thesis`` on the shipped files gives Lacy's 4.3393e6 Pa and 2.6256e7 Pa."""
    d = analyse(_mesh(MODEL), motion=_mesh("triangular_truss_motion_3s.toml"), scheme="thesis")
    summ = d["summary"]["members"]
    assert_allclose(summ["follower"]["max_von_mises"], 4.3393e6, rtol=5e-5)
    assert_allclose(summ["active"]["max_von_mises"], 2.6256e7, rtol=5e-5)


def test_singular_position_detected_on_the_sparse_path(monkeypatch):
    """The same flat triangle through the sparse (anchored SuperLU) solver path."""
    import trussfe.rigid.linalg as la
    monkeypatch.setattr(la, "DENSE_LIMIT", 0)
    s = triangular_truss()
    L = np.array([[3.9], [3.99], [4.0]])
    m = Motion([0, 1, 2], [1], L, np.ones_like(L), np.zeros_like(L))
    with pytest.raises(AnalysisError, match="singular"):
        simulate(s, m)


def test_sparse_and_dense_paths_agree(monkeypatch):
    """Base Simulation through both solver paths: identical to round-off (rtol 1e-10)."""
    import trussfe.rigid.linalg as la
    s = triangular_truss()
    m = load_motion(_mesh("triangular_truss_motion_3s.toml"), s)
    dense = simulate(s, m)
    monkeypatch.setattr(la, "DENSE_LIMIT", 0)
    sparse = simulate(s, m)
    assert_allclose(sparse.forces.end_force, dense.forces.end_force, rtol=0,
                    atol=1e-10 * np.abs(dense.forces.end_force).max())
    assert_allclose(sparse.kinematics.acceleration, dense.kinematics.acceleration, rtol=0,
                    atol=1e-10 * np.abs(dense.kinematics.acceleration).max())


def test_batched_positions_dense_and_sparse_agree(monkeypatch):
    """A 500-step slew (coarse continuation + chord Newton over all steps) through both
    solver paths: positions to 1e-11 m, forces to 1e-10 relative."""
    import trussfe.rigid.linalg as la
    from trussfe.rigid.motion import third_order_motion
    from trussfe.studies.lacy_rigid import double_octahedron
    s = double_octahedron((1.2289, 1.1079, 1.1079), gravity=-9.81, top_load=46.0)
    m = third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289], 2.0, 500)
    a = simulate(s, m)
    monkeypatch.setattr(la, "DENSE_LIMIT", 0)
    b = simulate(s, m)
    assert_allclose(b.kinematics.coords, a.kinematics.coords, rtol=0, atol=1e-11)
    assert_allclose(b.forces.end_force, a.forces.end_force, rtol=0,
                    atol=1e-10 * np.abs(a.forces.end_force).max())


@pytest.mark.parametrize("threads", ["1", "2"])
def test_singular_position_in_a_later_block_names_its_step(monkeypatch, threads):
    """A long motion evaluated in blocks of 10 steps (serially or in worker threads): the
    flat triangle at the last of 40 steps is reported as step 39 of the whole motion."""
    import trussfe.rigid.simulate as sim
    monkeypatch.setattr(sim, "CHUNK_ENTRIES", 3 * 10)
    monkeypatch.setenv("TRUSSFE_THREADS", threads)
    s = triangular_truss()
    L = np.linspace(3.5, 4.0, 40)[:, None]
    m = Motion(np.linspace(0.0, 1.0, 40), [1], L, np.ones_like(L), np.zeros_like(L))
    with pytest.raises(AnalysisError, match=r"step 39 \(t = 1 s\).*singular"):
        simulate(s, m)


def _spinning_follower():
    """The follower O1–B (aluminium tube, 1 m) turned about O1 by a massless active member
    O2–B so that it spins at a constant ω = 3 rad/s; no gravity.  Exact kinematics: B moves on
    the unit circle, and the active length is |B − O2|."""
    from trussfe.rigid.motion import Motion
    s = trussfe.model_from_dict({
        "model": {"dimension": 2, "gravity": [0.0, 0.0]},
        "materials": {"al": {"E": 70e9, "density": 2700.0}, "light": {"E": 70e9, "density": 0.0}},
        "sections": {"tube": {"outer_diameter": 0.02, "inner_diameter": 0.016}},
        "nodes": {"O1": [0.0, 0.0], "O2": [-2.0, 0.0], "B": [np.cos(0.5), np.sin(0.5)]},
        "members": {"follower": {"nodes": ["O1", "B"], "section": "tube", "material": "al"},
                    "act": {"nodes": ["O2", "B"], "section": "tube", "material": "light"}},
        "supports": {"O1": ["x", "y"], "O2": ["x", "y"]},
        "active_members": {"act": {"base_mass": 0.0, "base_length": 1.0, "base_cg": 0.0,
                                   "base_inertia": 0.0, "tube_length": 0.5}}})
    w = 3.0
    t = np.linspace(0.0, 0.4, 9)
    th = 0.5 + w * t
    B = np.stack([np.cos(th), np.sin(th)], axis=1)
    V = w * np.stack([-np.sin(th), np.cos(th)], axis=1)
    Acc = -w * w * B
    d = B - [-2.0, 0.0]
    L = np.linalg.norm(d, axis=1)
    Ld = np.einsum("ti,ti->t", d, V) / L
    Ldd = (np.einsum("ti,ti->t", V, V) + np.einsum("ti,ti->t", d, Acc) - Ld**2) / L
    return s, Motion(t, [s.member_index("act")], L[:, None], Ld[:, None], Ldd[:, None])


def test_a_member_in_tension_or_unloaded_has_no_buckling_margin():
    """The spinning follower is in tension (ρA ω² (L² − x²)/2 along it, 0 at B) and the
    massless active member carries nothing: no member is compressed (it reported a
    round-off "compression" of 1e-14 N and a margin of 2e17)."""
    s, mot = _spinning_follower()
    r = trussfe.simulate(s, motion=mot)
    b = r.solution.buckling
    assert np.all(b.max_compression == 0.0) and np.all(np.isinf(b.margin))
    rho_a = 2700.0 * np.pi / 4 * (0.02**2 - 0.016**2)
    f = s.member_index("follower")
    assert_allclose(r.solution.section_tension[:, f, -1], rho_a * 9.0 / 2, rtol=1e-9)


def test_a_stroke_upside_down_is_refused_when_read():
    """min_length above max_length leaves no length in the stroke: refused on reading the
    model, naming the item (every motion was refused, blamed on the motion)."""
    with pytest.raises(InputError, match=r"active_members\.act\.min_length: 3\.5 m is more "
                                         r"than max_length = 3\.0 m"):
        trussfe.model_from_dict({
            "model": {"dimension": 2},
            "materials": {"al": {"E": 70e9, "density": 2700.0}},
            "sections": {"tube": {"outer_diameter": 0.02, "inner_diameter": 0.016}},
            "nodes": {"O1": [0.0, 0.0], "O2": [-2.0, 0.0], "B": [1.0, 0.0]},
            "members": {"f": {"nodes": ["O1", "B"], "section": "tube", "material": "al"},
                        "act": {"nodes": ["O2", "B"], "section": "tube", "material": "al"}},
            "supports": {"O1": ["x", "y"], "O2": ["x", "y"]},
            "active_members": {"act": {"base_mass": 0.0, "base_length": 1.0,
                                       "tube_length": 0.5, "min_length": 3.5,
                                       "max_length": 3.0}}})


def test_a_length_just_outside_the_stroke_shows_by_how_much():
    """A length 5e-9 m short of the stroke is shown with the digits that tell it from the
    limit and the amount (it read "2.5 m long, short of its stroke 2.5-3 m")."""
    from trussfe.errors import InputError
    from trussfe.rigid.motion import Motion, check_stroke
    s = trussfe.model_from_dict({
        "model": {"dimension": 2},
        "materials": {"al": {"E": 70e9, "density": 2700.0}},
        "sections": {"tube": {"outer_diameter": 0.02, "inner_diameter": 0.016}},
        "nodes": {"O1": [0.0, 0.0], "O2": [-2.0, 0.0], "B": [0.6, 0.0]},
        "members": {"f": {"nodes": ["O1", "B"], "section": "tube", "material": "al"},
                    "act": {"nodes": ["O2", "B"], "section": "tube", "material": "al"}},
        "supports": {"O1": ["x", "y"], "O2": ["x", "y"]},
        "active_members": {"act": {"base_mass": 0.0, "base_length": 1.0, "tube_length": 0.5,
                                   "min_length": 2.5, "max_length": 3.0}}})
    z = np.zeros((1, 1))
    with pytest.raises(InputError, match=r"is 2\.499999995 m long, short of its stroke "
                                         r"2\.5-3 m by 5e-09 m"):
        check_stroke(s, Motion([0.0], [s.member_index("act")], [[2.499999995]], z, z))
