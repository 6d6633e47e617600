"""Frames under member loads against independent solvers: OpenSeesPy (``eleLoad
-beamUniform``, ``-beamPoint`` on ``elasticBeamColumn`` elements) and PyNite (member
distributed and point loads).  Skipped when the solver is not installed.  Every trussfe
result here is in global equilibrium (tests/conftest.py).
"""
import numpy as np
import pytest

from trussfe.api.model import model_from_dict
from trussfe.fem.static import solve_static
from pynite_compare import assert_nodes_match_pynite

E, G, A, I, J = 2.0e11, 8.0e10, 6.0e-3, 3.0e-5, 5.0e-5

PORTAL = {
    "model": {"dimension": 2},
    "materials": {"st": {"E": E, "G": G}},
    "sections": {"b": {"area": A, "Iz": I, "c": 0.1}},
    "nodes": {"A": [0.0, 0.0], "B": [0.0, 4.0], "C": [6.0, 4.0], "D": [6.0, 0.0]},
    "members": {m: {"nodes": list(m), "section": "b", "material": "st", "type": "beam"}
                for m in ("AB", "BC", "CD")},
    "supports": {"A": ["x", "y", "rz"], "D": ["x", "y", "rz"]},
    "member_loads": [
        {"member": "BC", "kind": "uniform", "q": [0.0, -10.0e3]},
        {"member": "BC", "kind": "point", "at": 0.3, "F": [0.0, -20.0e3]},
        {"member": "AB", "kind": "uniform", "q": [2.0e3, 0.0]},
        {"member": "CD", "kind": "point", "at": 0.55, "F": [-5.0e3, 0.0], "axes": "global"},
        {"member": "BC", "kind": "point", "at": 0.8, "F": [1.0e3, 0.0]},
    ],
}


@pytest.mark.parametrize("k", [1, 4])
def test_portal_against_opensees(k):
    ops = pytest.importorskip("openseespy.opensees")
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    xy = PORTAL["nodes"]
    tags = {n: i + 1 for i, n in enumerate(xy)}
    for n, (x, y) in xy.items():
        ops.node(tags[n], x, y)
    ops.fix(tags["A"], 1, 1, 1)
    ops.fix(tags["D"], 1, 1, 1)
    ops.geomTransf("Linear", 1)
    ele = {}
    for e, m in enumerate(("AB", "BC", "CD"), start=1):
        ops.element("elasticBeamColumn", e, tags[m[0]], tags[m[1]], A, E, I, 1)
        ele[m] = e
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    # member axes: AB and CD: x = ±Y, local y = x rotated +90°; BC: x = X, y = Y
    ops.eleLoad("-ele", ele["BC"], "-type", "-beamUniform", -10.0e3, 0.0)
    ops.eleLoad("-ele", ele["BC"], "-type", "-beamPoint", -20.0e3, 0.3, 0.0)
    ops.eleLoad("-ele", ele["AB"], "-type", "-beamUniform", -2.0e3, 0.0)   # +X = local −y
    ops.eleLoad("-ele", ele["CD"], "-type", "-beamPoint", -5.0e3, 0.55, 0.0)  # CD: x = −Y, y = +X
    ops.eleLoad("-ele", ele["BC"], "-type", "-beamPoint", 0.0, 0.8, 1.0e3)
    ops.system("BandGeneral")
    ops.numberer("RCM")
    ops.constraints("Plain")
    ops.integrator("LoadControl", 1.0)
    ops.algorithm("Linear")
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    ops.reactions()
    disp = {n: np.array(ops.nodeDisp(tags[n])) for n in xy}
    reac = {n: np.array(ops.nodeReaction(tags[n])) for n in ("A", "D")}
    forces = {m: np.array(ops.eleResponse(ele[m], "localForce")) for m in ele}
    ops.wipe()

    r = solve_static(model_from_dict(PORTAL), subdivisions=k)
    s = r.structure
    for n in xy:
        assert r.displacements[s.node_index(n)] == pytest.approx(disp[n], rel=1e-8,
                                                                 abs=1e-14)
    for n in ("A", "D"):
        assert r.reactions[s.node_index(n)] == pytest.approx(reac[n], rel=1e-8, abs=1e-6)
    # end forces: OpenSees localForce is the force on the element at its ends (N, V, M);
    # trussfe's end sections are minus that at the start and equal at the end
    for m, f in forces.items():
        i = s.member_index(m)
        mine = r.end_forces[i][:, [0, 1, 5]]
        assert mine[0] == pytest.approx(-f[:3], rel=1e-8, abs=1e-6)
        assert mine[1] == pytest.approx(f[3:], rel=1e-8, abs=1e-6)


FRAME3D = {
    "model": {"dimension": 3},
    "materials": {"st": {"E": E, "G": G}},
    "sections": {"b": {"area": A, "Iy": I, "Iz": I, "J": J, "c": 0.1}},
    "nodes": {"A": [0.0, 0.0, 0.0], "B": [0.0, 0.0, 3.0], "C": [4.0, 0.0, 3.0],
              "D": [4.0, 3.0, 3.0]},
    "members": {m: {"nodes": list(m), "section": "b", "material": "st", "type": "beam"}
                for m in ("AB", "BC", "CD")},
    "supports": {"A": ["x", "y", "z", "rx", "ry", "rz"],
                 "D": ["x", "y", "z", "rx", "ry", "rz"]},
    "member_loads": [
        {"member": "BC", "kind": "uniform", "q": [0.0, 0.0, -5.0e3]},
        {"member": "CD", "kind": "trapezoidal", "q_start": [0.0, 0.0, -2.0e3],
         "q_end": [0.0, 0.0, -6.0e3]},
        {"member": "BC", "kind": "point", "at": 0.3, "F": [0.0, 0.0, -3.0e3]},
        {"member": "AB", "kind": "uniform", "q": [1.0e3, 0.0, 0.0]},
        {"member": "CD", "kind": "point", "at": 0.7, "F": [0.0, 800.0, 0.0]},
    ],
}


@pytest.mark.parametrize("k", [1, 3])
def test_3d_frame_against_pynite(k):
    pynite = pytest.importorskip("Pynite")
    m = pynite.FEModel3D()
    for n, (x, y, z) in FRAME3D["nodes"].items():
        m.add_node(n, x, y, z)
    m.add_material("st", E, G, 0.25, 7850.0)
    m.add_section("b", A, I, I, J)
    for name in FRAME3D["members"]:
        m.add_member(name, name[0], name[1], "st", "b")
    for n in ("A", "D"):
        m.def_support(n, True, True, True, True, True, True)
    m.add_member_dist_load("BC", "FZ", -5.0e3, -5.0e3)
    m.add_member_dist_load("CD", "FZ", -2.0e3, -6.0e3)
    m.add_member_pt_load("BC", "FZ", -3.0e3, 0.3 * 4.0)
    m.add_member_dist_load("AB", "FX", 1.0e3, 1.0e3)
    m.add_member_pt_load("CD", "FY", 800.0, 0.7 * 3.0)
    m.analyze_linear(check_statics=False)
    combo = next(iter(m.load_combos))

    r = solve_static(model_from_dict(FRAME3D), subdivisions=k)
    assert_nodes_match_pynite(r, m, combo, moving=("B", "C"), supported=("A", "D"))
