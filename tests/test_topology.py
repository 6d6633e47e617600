# SPDX-License-Identifier: MIT
"""``trussfe topology`` and the spatial cycle-equation kinematics (Vlase et al. 2008,
extended to 3-D): complete cycle matrix, equivalent mechanism of a model, velocities and
accelerations against the compatibility matrix, the Bennett linkage."""
import json
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe.cli import main
from trussfe.errors import InputError
from trussfe.kinematics.cycles import complete_cycle_matrix, cycle_rates
from trussfe.kinematics.topology import (cycle_kinematics, equivalent_assembly,
                                         graph_topology, incidence_matrix)
from trussfe.kinematics.velocity import mechanism_acceleration, mechanism_velocity
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.models.bennett import (bennett_angles, bennett_frames, bennett_linkage,
                                    bennett_rate, bennett_toml)

MESHES = Path(__file__).resolve().parents[1] / "meshes"


def _simple_cycles_networkx(joints, edges) -> int:
    """Independent count: networkx's simple cycles on the graph with every edge subdivided
    (parallel edges stay distinct)."""
    nx = pytest.importorskip("networkx")
    G = nx.Graph()
    for k, (a, b) in enumerate(edges):
        G.add_edge(a, ("e", k))
        G.add_edge(("e", k), b)
    return sum(1 for _ in nx.simple_cycles(G))


# ---------------------------------------------------------------- complete cycle matrix
@pytest.mark.parametrize("model, cycles", [("mech_fourbar", 1), ("mech_bricard", None),
                                           ("double_octahedron_motion_active", None),
                                           ("mech_bennett", None)])
def test_complete_cycle_matrix(model, cycles):
    """B_a (Vlase §2.2): every row a closed, simple, oriented cycle (A B_aᵀ = 0, ±1 entries,
    two edges at each joint it touches), rank s − r, the fundamental cycles first; the
    number of rows equals networkx's count of simple cycles."""
    r = trussfe.topology(MESHES / f"{model}.toml")
    Ba, Bf, A = r.complete_cycles, r.fundamental_cycles, r.reduced_incidence
    s = len(r.edge_ids)
    assert Bf.shape == (s - len(r.tree), s) and len(r.cotree) == Bf.shape[0]
    assert_allclose(A @ Ba.T, 0)
    assert np.linalg.matrix_rank(Ba) == Bf.shape[0]
    assert set(np.unique(Ba)) <= {-1, 0, 1}
    assert_allclose(Ba[:Bf.shape[0]], Bf)
    degree = np.abs(r.incidence) @ np.abs(Ba).T
    assert set(np.unique(degree)) <= {0, 2}
    assert len({tuple(row) for row in np.abs(Ba)}) == Ba.shape[0]      # no duplicates
    doc = r.to_dict()
    ref = _simple_cycles_networkx(doc["joints"], [e["nodes"] for e in doc["edges"]])
    assert Ba.shape[0] == ref == (cycles or ref)


def test_complete_cycle_matrix_of_k4_and_the_limit():
    """K4 has 7 simple cycles (4 triangles, 3 squares: combinatorics); above the limit on
    s − r the enumeration is skipped (None)."""
    conn = np.array([[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]])
    t = graph_topology(4, conn)
    Ba = complete_cycle_matrix(4, conn, t)
    assert Ba.shape == (7, 6)
    assert sorted(np.abs(Ba).sum(axis=1).tolist()) == [3, 3, 3, 3, 4, 4, 4]
    assert complete_cycle_matrix(4, conn, t, max_rank=2) is None


# ---------------------------------------------------------------- the command
def test_topology_json_and_summary(tmp_path, capsys):
    """The document's matrices have the documented shapes; edges are the model's members
    plus the ground chain; the tree has one edge fewer than the joints."""
    out = tmp_path / "t.json"
    assert main(["topology", str(MESHES / "mech_bennett.toml"), "--json", str(out)]) == 0
    line = capsys.readouterr().out
    assert "8 joints, 23 edges" in line and "16 fundamental cycle(s)" in line
    d = json.loads(out.read_text())
    c = d["counts"]
    assert (c["joints"], c["edges"], c["tree_edges"], c["links"]) == (8, 23, 7, 16)
    assert np.array(d["incidence"]).shape == (8, 23)
    assert np.array(d["reduced_incidence"]).shape == (7, 23)
    assert np.array(d["fundamental_cycles"]).shape == (16, 23)
    assert [e["kind"] for e in d["edges"]].count("ground") == 3
    assert d["ground"] == ["1", "2", "7", "8"] and d["reference"] == "1"
    assert sorted(d["tree"] + d["cotree"]) == sorted(e["id"] for e in d["edges"])


@pytest.mark.parametrize("n_nodes, edges", [
    (3, [(0, 1), (1, 0), (1, 2), (2, 0)]),                 # a parallel pair and a triangle
    (2, [(0, 1), (1, 0), (0, 1)]),                          # three edges between two joints
    (4, [(0, 1), (1, 2), (2, 3), (3, 0), (2, 1), (0, 2)]),  # K4 less one edge, one repeated
])
def test_parallel_edges_make_cycles_of_their_own(n_nodes, edges):
    """Parallel edges (a bar between two ground joints beside the edge closing the ground):
    the tree has n − 1 edges, the cotree the other s − n + 1 (the cyclomatic number of a
    connected graph), and every fundamental cycle is a cycle — in the null space of the
    incidence matrix, A Cᵀ = 0 — that uses its own link once (graph theory, Vlase eq. 2)."""
    conn = np.array(edges)
    t = graph_topology(n_nodes, conn)
    s = len(edges)
    assert t.tree.size == n_nodes - 1 and t.links.size == s - n_nodes + 1
    assert sorted(np.r_[t.tree, t.links].tolist()) == list(range(s))
    A = incidence_matrix(n_nodes, conn).toarray()
    assert not np.any(A @ t.cycle_matrix.T)
    assert np.array_equal(t.cycle_matrix[:, t.links], np.eye(t.links.size, dtype=np.int64))


def test_supported_joints_joined_by_members(tmp_path, capsys):
    """A model whose members join supported joints (the ground's own edges beside them):
    one line, exit 0, with 8 joints, 10 edges, a tree of 7 and 3 fundamental cycles
    (s − n + 1)."""
    assert main(["topology", str(MESHES / "loads_closed_forms.toml")]) == 0
    line = capsys.readouterr().out
    assert "8 joints, 10 edges" in line and "tree of 7 edges, 3 fundamental cycle(s)" in line


def test_slider_and_plate_edges():
    """A node fixed in y only is a slider (virtual ground point, edge along x); three beams
    joined rigidly are one plate, triangulated (2·3 − 3 = 3 plate bars in the plane); a
    node free in two directions of space is listed and left free."""
    st = trussfe.topology(MESHES / "mech_slider_crank.toml")
    assert "slider" in st.edge_kinds and st.joint_ids[-1].startswith("ground:")
    sec, mat = Section.tube("t", 0.02, 0.016), Material("al", E=7e10, G=2.6e10)
    x = [[0, 0], [1, 0], [1, 1], [0, 1], [2, 1]]
    s = build_structure(x, [[0, 1], [1, 2], [2, 0], [2, 4], [3, 0]], section=sec,
                        material=mat, supports={0: "xy", 4: "xy"},
                        is_beam=[True, True, True, False, False])
    t = trussfe.topology(s)
    assert t.to_dict()["plates"] == [["0", "1", "2"]]
    assert t.edge_kinds.count("plate") == 3 and t.edge_kinds.count("bar") == 2
    b = trussfe.topology(MESHES / "mech_bricard.toml")
    assert b.to_dict()["planar_supports"] == ["3"]


@pytest.mark.parametrize("argv, message", [
    (["nobars"], "no members"),
    (["mech_fourbar.toml", "--drive", "2:y"], "unrecognized arguments"),
    (["free"], "no node is fixed"),
    (["split"], "split.toml: the assembly is not connected: node(s) 'C', 'D' cannot be reached "
                "from node 'A'"),
])
def test_bad_input_is_one_line_exit_2(argv, message, tmp_path, capsys, monkeypatch):
    """Bad input: one line ``trussfe: error: ...`` and exit status 2, naming the file and the
    model's ids."""
    head = '[model]\nname = "m"\ndimension = 2\n[materials.al]\nE = 7e10\n' \
           '[sections.t]\narea = 1e-4\n'
    mem = '{ nodes = ["%s", "%s"], section = "t", material = "al" }'
    files = {
        "nobars": head + '[nodes]\nA = [0.0, 0.0]\n[members]\n[supports]\nA = ["x", "y"]\n',
        "free": head + '[nodes]\nA = [0.0, 0.0]\nB = [1.0, 0.0]\n[members]\nm = '
                + mem % ("A", "B") + "\n",
        "split": head + '[nodes]\nA = [0.0, 0.0]\nB = [1.0, 0.0]\nC = [2.0, 0.0]\n'
                 'D = [3.0, 0.0]\n[members]\nm = ' + mem % ("A", "B") + "\nn = "
                 + mem % ("C", "D") + '\n[supports]\nA = ["x", "y"]\n',
    }
    name = argv[0]
    path = str(MESHES / name) if name.endswith(".toml") else str(tmp_path / f"{name}.toml")
    if name in files:
        Path(path).write_text(files[name])
    assert main(["topology", path, *argv[1:]]) == 2
    err = capsys.readouterr().err
    assert err.startswith("trussfe: error: ") and err.count("\n") == 1 and message in err


def test_api_refuses_a_structure_without_members():
    """The same check from Python (a structure built without members)."""
    s = build_structure([[0.0, 0.0], [1.0, 0.0]], np.zeros((0, 2), int),
                        section=Section.tube("t", 0.02, 0.016),
                        material=Material("al", E=7e10, G=2.6e10), supports={0: "xy"})
    with pytest.raises(InputError, match="no members"):
        trussfe.topology(s)


# ---------------------------------------------------------------- spatial cycle kinematics
def test_cycle_rates_equal_the_planar_method_on_the_fourbar():
    """In the plane, cycle_rates (drive: the crank pin's velocity) gives the planar cycle
    method's joint velocities and accelerations (drive: the crank's ω, α) and both equal the
    compatibility-matrix ones."""
    from trussfe.models.mechanisms import FOURBAR, fourbar_position
    t, w, al = 0.7, 2.0, 0.5
    B, C = fourbar_position(t, FOURBAR["crank"], FOURBAR["coupler"], FOURBAR["rocker"],
                            FOURBAR["ground"])
    x = np.array([[0.0, 0.0], B, C, [FOURBAR["ground"], 0.0]])
    conn = np.array([[0, 1], [1, 2], [3, 2]])
    eq = equivalent_assembly(x, conn, ground=[0, 3])
    ref = cycle_kinematics(eq, drive_edge=0, omega=w, alpha=al)
    vB = ref.velocity[1]
    aB = ref.acceleration[1]
    cr = cycle_rates(eq, node_velocities={(1, 0): vB[0]}, node_accelerations={(1, 0): aB[0]})
    assert_allclose(cr.velocity, ref.velocity, atol=1e-12)
    assert_allclose(cr.acceleration, ref.acceleration, atol=1e-11)
    assert_allclose(cr.omega[:3, 2], ref.omega[:3], atol=1e-12)
    free = np.array([[0, 0], [1, 1], [1, 1], [0, 0]], bool)
    v = mechanism_velocity(x, conn, free, {2: vB[0]})
    assert_allclose(cr.velocity[:4], v, atol=1e-12)


def test_octahedral_bay_cycles_equal_compatibility():
    """Lacy's double-octahedral bay, three actuators moving: the spatial cycle equations
    give the joint velocities and accelerations of B v = L̇, B a = L̈ − (|v_rel|² − L̇²)/L
    (compatibility matrix) to round-off; each bar's ω is normal to it and gives its
    transverse velocity, ω × (L e) = v_rel − L̇ e."""
    s = trussfe.read_model(MESHES / "double_octahedron_motion_active.toml")
    x, conn = s.coords, s.connectivity
    free = ~s.translation_supports
    acts = [a.member for a in s.extensions["active_members"]]
    ld, ldd = np.zeros(len(conn)), np.zeros(len(conn))
    ld[acts], ldd[acts] = (0.1, -0.05, 0.02), (0.3, 0.1, -0.2)
    v = mechanism_velocity(x, conn, free, {}, ld)
    a = mechanism_acceleration(x, conn, free, v, {}, ld, ldd)
    eq = equivalent_assembly(x, conn, ground=[0, 1, 2])
    cr = cycle_rates(eq, length_rates={j: ld[j] for j in acts},
                     length_accelerations={j: ldd[j] for j in acts})
    assert_allclose(cr.velocity[:9], v, atol=1e-13 * np.abs(v).max())
    assert_allclose(cr.acceleration[:9], a, atol=1e-13 * np.abs(a).max())
    d = x[conn[:, 1]] - x[conn[:, 0]]
    e = d / np.linalg.norm(d, axis=1)[:, None]
    m = len(conn)
    assert_allclose(np.einsum("jk,jk->j", cr.omega[:m], e), 0, atol=1e-13)
    vrel = v[conn[:, 1]] - v[conn[:, 0]]
    assert_allclose(np.cross(cr.omega[:m], d), vrel - ld[:, None] * e, atol=1e-13)


def test_bennett_geometry_closes_and_keeps_its_bars():
    """Bennett (1903): with a / sin α = b / sin β the DH loop T1 T2 T3 T4 closes for every
    input angle with the closed-form θ2, θ3 = −θ1, θ4 = −θ2; the bar model keeps every bar
    length; dθ2/dθ1 of the closed form equals its central difference (h = 1e-6)."""
    L0 = None
    for t1 in np.linspace(0.2, 6.0, 9):
        assert_allclose(bennett_frames(t1)[4], np.eye(4), atol=1e-14)
        x, bars, _ = bennett_linkage(t1)
        L = np.linalg.norm(x[bars[:, 1]] - x[bars[:, 0]], axis=1)
        L0 = L if L0 is None else L0
        assert_allclose(L, L0, atol=1e-13)
        h = 1e-6
        fd = (bennett_angles(t1 + h)[1] - bennett_angles(t1 - h)[1]) / (2 * h)
        assert bennett_rate(t1) == pytest.approx(fd, rel=1e-8)


def test_bennett_is_a_one_degree_of_freedom_mechanism():
    """``trussfe mechanism`` on the shipped file: rank 11 of 12 free coordinates, one
    mechanism, 9 self-stress states = 20 bars − 11 (three from the overconstraint, six from
    bars between fixed joints); Grübler's count for a 4R loop, 6·3 − 5·4 = −2, would say
    it cannot move."""
    r = trussfe.mechanism(MESHES / "mech_bennett.toml")
    assert (r.rank, r.mechanisms, r.rigid_body_motions, r.self_stress_states) == (11, 1, 0, 9)


def test_shipped_bennett_file_is_the_builder():
    """meshes/mech_bennett.toml is written by trussfe.models.bennett (no drift)."""
    assert (MESHES / "mech_bennett.toml").read_text() == bennett_toml()


def test_bennett_cycles_equal_compatibility_and_closed_form():
    """Over a turn of the input link (θ̇1 = 2 rad/s, θ̈1 = 0.5 rad/s²): cycle-equation joint
    rates = compatibility-matrix rates, and the rocker link (axes 2–3) turns at the closed
    form θ̇1 z1 + θ̇2 z2 (its bars' normal parts) — study ``spatial_cycles_bennett``."""
    from trussfe.studies.vlase import spatial_cycles_bennett
    r = spatial_cycles_bennett(samples=5)
    assert r["velocity_scale"] > 1.0
    assert r["velocity_difference"] < 1e-12 and r["acceleration_difference"] < 1e-11
    assert r["closed_form_velocity_error"] < 1e-12 and r["closed_form_omega_error"] < 1e-12


def test_too_few_drives_are_reported():
    """The Bennett linkage without a drive: the cycle equations do not determine the
    motion, an AnalysisError naming the count of equations."""
    from trussfe.errors import AnalysisError
    x, bars, fixed = bennett_linkage()
    eq = equivalent_assembly(x, bars, ground=fixed)
    with pytest.raises(AnalysisError, match="do not determine the motion"):
        cycle_rates(eq)
