# SPDX-License-Identifier: MIT
"""A braced portal frame with a support settlement, an elastic support and a nodal load,
against OpenSeesPy (independent solver: ``sp`` imposed displacement, a ``zeroLength`` spring,
``elasticBeamColumn`` and ``truss`` elements).  Skipped when OpenSeesPy is missing."""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe

ops = pytest.importorskip("openseespy.opensees")

E, A, I, A_ROD = 2.0e11, 4.0e-3, 8.0e-6, 5.0e-4
K_SPRING, SETTLE, PUSH = 3.0e5, -4.0e-3, 2000.0
NODES = {"A": [0.0, 0.0], "B": [0.0, 3.0], "C": [4.0, 3.0], "D": [4.0, 0.0]}


def _trussfe():
    return trussfe.model_from_dict({
        "model": {"dimension": 2},
        "materials": {"st": {"E": E}},
        "sections": {"box": {"area": A, "Iz": I, "c": 0.1}, "rod": {"area": A_ROD}},
        "nodes": NODES,
        "members": {"AB": {"nodes": ["A", "B"], "section": "box", "material": "st",
                           "type": "beam"},
                    "BC": {"nodes": ["B", "C"], "section": "box", "material": "st",
                           "type": "beam"},
                    "CD": {"nodes": ["C", "D"], "section": "box", "material": "st",
                           "type": "beam"},
                    "AC": {"nodes": ["A", "C"], "section": "rod", "material": "st"}},
        "supports": {"A": ["x", "y", "rz"], "D": ["x", "y"]},
        "springs": {"C": {"x": K_SPRING}},
        "load_cases": {"wind": {"loads": {"B": [PUSH, 0.0]}},
                       "settle": {"prescribed": {"D": {"y": SETTLE}}}},
        "combinations": {"both": {"wind": 1.0, "settle": 1.0}}})


def _opensees():
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, xy in enumerate(NODES.values(), start=1):
        ops.node(tag, *xy)
    ops.node(5, *NODES["C"])                           # the spring's ground end
    ops.fix(1, 1, 1, 1)
    ops.fix(4, 1, 0, 0)                                # y is imposed by sp below
    ops.fix(5, 1, 1, 1)
    ops.geomTransf("Linear", 1)
    for tag, (i, j) in enumerate(((1, 2), (2, 3), (3, 4)), start=1):
        ops.element("elasticBeamColumn", tag, i, j, A, E, I, 1)
    ops.uniaxialMaterial("Elastic", 1, E)
    ops.element("truss", 4, 1, 3, A_ROD, 1)
    ops.uniaxialMaterial("Elastic", 2, K_SPRING)
    ops.element("zeroLength", 5, 5, 3, "-mat", 2, "-dir", 1)
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, PUSH, 0.0, 0.0)
    ops.sp(4, 2, SETTLE)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("FullGeneral")
    ops.algorithm("Linear")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    ops.reactions()
    disp = np.array([ops.nodeDisp(t)[:2] for t in (1, 2, 3, 4)])
    reac = np.array([ops.nodeReaction(t)[:2] for t in (1, 2, 3, 4)])
    rot = np.array([ops.nodeDisp(t)[2] for t in (2, 3)])
    ops.wipe()
    return disp, reac, rot


def test_settlement_and_spring_against_opensees():
    """Displacements, rotations and support reactions of the combination (nodal load +
    settlement) agree with OpenSeesPy to 1e-9; the spring's force −k u_C is the reaction at
    C in trussfe (OpenSees reports it at the spring's ground node)."""
    res = trussfe.static(_trussfe(), combination="both")
    disp, reac, rot = _opensees()
    assert_allclose(res.displacement, disp, rtol=1e-9, atol=1e-12)
    assert_allclose(res.rotation[[1, 2], 0], rot, rtol=1e-9)
    assert_allclose(res.reaction[[0, 3]], reac[[0, 3]], rtol=1e-9, atol=1e-6)
    assert_allclose(res.reaction[2, 0], -K_SPRING * disp[2, 0], rtol=1e-9)
