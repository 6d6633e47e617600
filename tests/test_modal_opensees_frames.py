# SPDX-License-Identifier: MIT
"""Natural frequencies and mode shapes of frames and pin-jointed trusses against OpenSeesPy.

The same models are built in OpenSeesPy (independent solver): ``elasticBeamColumn`` elements
(``-cMass`` for the consistent mass, none for the lumped one), ``Truss`` elements
(``-cMass 1`` / ``0``), ``zeroLength`` springs to fixed nodes, ``mass`` with rotary inertia,
and a member-end moment or torsion release as a second node at the joint tied by ``equalDOF``
to the joint on its translations and on the rotations the end keeps.  Each frame member is cut
into the same number of elements in both, so frequencies agree to round-off and the mode
shapes (joint translations) have a modal assurance criterion of 1.  Skipped when OpenSeesPy is
missing.

OpenSeesPy's consistent mass turns a section about the member axis with ρJ, where the
section's mass has the polar moment I_p = Iy + Iz (trussfe; the two are equal only for a
round section, checked against the closed form of a non-round shaft in
``test_modal_closed_forms_beams_shafts.py``): the sections here have J = Iy + Iz, so both
solvers model the same structure while Iy ≠ Iz.
"""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe

ops = pytest.importorskip("openseespy.opensees")

DOFS = ("x", "y", "z", "rx", "ry", "rz")


def _local_axes(nodes, i, j, orientation):
    """Member axes as docs/fem.md defines them (y from the orientation vector, else global Z,
    or global X for a vertical member; z = x × y)."""
    x = np.subtract(nodes[j], nodes[i], dtype=float)
    x /= np.linalg.norm(x)
    o = orientation if orientation is not None else (
        [1.0, 0.0, 0.0] if abs(x[2]) > 1 - 1e-9 else [0.0, 0.0, 1.0])
    y = np.asarray(o, dtype=float) - np.dot(o, x) * x
    y /= np.linalg.norm(y)
    return x, y, np.cross(x, y)


def _mac(a, b):
    a, b = np.ravel(a), np.ravel(b)
    return (a @ b) ** 2 / ((a @ a) * (b @ b))


# ---------------------------------------------------------------------- 3-D frame
E, G, RHO = 2.0e11, 7.7e10, 7850.0
SECTIONS = {"box": {"area": 4.0e-3, "Iy": 8.0e-6, "Iz": 3.0e-6, "J": 1.1e-5},
            "rod": {"area": 5.0e-4, "Iy": 2.0e-8, "Iz": 2.0e-8, "J": 4.0e-8}}
FRAME_NODES = {"A": [0, 0, 0], "B": [4, 0, 0], "C": [4, 3, 0], "D": [0, 3, 0],
               "E": [0, 0, 3], "F": [4, 0, 3], "G": [4, 3, 3.5], "H": [0, 3, 3]}
# id: start, end, section, type, orientation, releases (on members whose released local axes
# are global axes, so equalDOF can keep the other rotations)
FRAME_MEMBERS = {
    "AE": ("A", "E", "box", "beam", None, {"end": ["my", "t"]}),
    "BF": ("B", "F", "box", "beam", [0, 1, 0], {"start": ["t"], "end": ["mz"]}),
    "CG": ("C", "G", "box", "beam", None, None),
    "DH": ("D", "H", "box", "beam", [1, 1, 0], None),
    "EF": ("E", "F", "box", "beam", None, {"end": ["bending"]}),
    "FG": ("F", "G", "box", "beam", [1, 0, 1], None),
    "GH": ("G", "H", "box", "beam", None, None),
    "HE": ("H", "E", "box", "beam", None, {"start": ["mz"]}),
    "AF": ("A", "F", "rod", "bar", None, None),
    "DG": ("D", "G", "rod", "bar", None, None),
}
FRAME_SUPPORTS = {"A": DOFS, "B": DOFS, "C": DOFS}
FRAME_SPRINGS = {"D": {"x": 2e6, "y": 3e6, "z": 5e7, "rx": 1e6, "ry": 2e6, "rz": 4e5}}
FRAME_MASSES = {"G": (50.0, [2.0, 3.0, 4.0]), "E": (30.0, None)}
SUB = 4
COUNT = 12


def _frame_trussfe():
    members = {}
    for mid, (i, j, sec, kind, ori, rel) in FRAME_MEMBERS.items():
        m = {"nodes": [i, j], "section": sec, "material": "st", "type": kind}
        if ori is not None:
            m["orientation"] = ori
        if rel is not None:
            m["releases"] = rel
        members[mid] = m
    return trussfe.model_from_dict({
        "model": {"dimension": 3},
        "materials": {"st": {"E": E, "G": G, "density": RHO}},
        "sections": SECTIONS, "nodes": FRAME_NODES, "members": members,
        "supports": {k: list(v) for k, v in FRAME_SUPPORTS.items()},
        "springs": FRAME_SPRINGS,
        "masses": {k: ({"mass": m, "inertia": I} if I else m)
                   for k, (m, I) in FRAME_MASSES.items()}})


def _frame_opensees(lumped: bool):
    """Frequencies (Hz) and joint translations of the modes, OpenSeesPy."""
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    count = [0]

    def node(xyz):
        count[0] += 1
        ops.node(count[0], *map(float, xyz))
        return count[0]

    tag = {k: node(xyz) for k, xyz in FRAME_NODES.items()}
    for k, fixed in FRAME_SUPPORTS.items():
        ops.fix(tag[k], *[int(d in fixed) for d in DOFS])
    mat = 0
    for k, springs in FRAME_SPRINGS.items():
        ground = node(FRAME_NODES[k])
        ops.fix(ground, 1, 1, 1, 1, 1, 1)
        mats, dirs = [], []
        for d, stiffness in springs.items():
            mat += 1
            ops.uniaxialMaterial("Elastic", mat, stiffness)
            mats.append(mat)
            dirs.append(DOFS.index(d) + 1)
        ops.element("zeroLength", 1000 + mat, ground, tag[k], "-mat", *mats, "-dir", *dirs)
    for k, (m, inertia) in FRAME_MASSES.items():
        ops.mass(tag[k], m, m, m, *(inertia or [0.0, 0.0, 0.0]))
    ele = transf = 0
    ties = []
    for i, j, sec, kind, ori, rel in FRAME_MEMBERS.values():
        s = SECTIONS[sec]
        if kind == "bar":
            mat += 1
            ops.uniaxialMaterial("Elastic", mat, E)
            ele += 1
            ops.element("Truss", ele, tag[i], tag[j], s["area"], mat, "-rho", RHO * s["area"],
                        "-cMass", 0 if lumped else 1)
            continue
        x, y, z = _local_axes(FRAME_NODES, i, j, ori)
        transf += 1
        ops.geomTransf("Linear", transf, *z)
        ends = [tag[i], tag[j]]
        for e, name in enumerate(("start", "end")):
            freed = [a for r in (rel or {}).get(name, [])
                     for a in {"bending": (y, z), "my": (y,), "mz": (z,), "t": (x,)}[r]]
            if freed:
                kept = [d for d in range(3) if not any(abs(a[d]) > 0.5 for a in freed)]
                twin = node(FRAME_NODES[(i, j)[e]])
                ties.append((ends[e], twin, [1, 2, 3] + [4 + d for d in kept]))
                ends[e] = twin
        p0, p1 = np.asarray(FRAME_NODES[i], float), np.asarray(FRAME_NODES[j], float)
        chain = [ends[0]] + [node(p0 + (p1 - p0) * q / SUB) for q in range(1, SUB)] + [ends[1]]
        for a, b in zip(chain[:-1], chain[1:]):
            ele += 1
            ops.element("elasticBeamColumn", ele, a, b, s["area"], E, G, s["J"], s["Iy"],
                        s["Iz"], transf, "-mass", RHO * s["area"], *([] if lumped else ["-cMass"]))
    for a, b, dofs in ties:
        ops.equalDOF(a, b, *dofs)
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    lam = np.array(ops.eigen(COUNT))
    shapes = np.array([[ops.nodeEigenvector(tag[k], m + 1)[:3] for k in FRAME_NODES]
                       for m in range(COUNT)])
    ops.wipe()
    return np.sqrt(lam) / (2 * np.pi), shapes


@pytest.mark.parametrize("mass", ["consistent", "lumped"])
def test_3d_frame_with_releases_springs_and_rotary_inertia_matches_opensees(mass):
    """A 3-D frame with box sections (Iy ≠ Iz), orientation vectors, bending, single-axis and
    torsion releases, springs on every DOF of a node, bars and nodal masses with rotary
    inertia: the 12 lowest frequencies, the mode shapes (MAC) and their mass normalisation
    (φᵀMφ = 1, so the shapes agree in size too) are OpenSeesPy's."""
    f_ops, s_ops = _frame_opensees(lumped=mass == "lumped")
    r = trussfe.modes(_frame_trussfe(), count=COUNT, subdivisions=SUB, mass=mass)
    assert_allclose(r.frequencies_hz, f_ops, rtol=1e-9)
    for m in range(COUNT):
        assert _mac(r.shapes[m], s_ops[m]) > 1 - 1e-9
        assert_allclose(np.linalg.norm(r.shapes[m]), np.linalg.norm(s_ops[m]), rtol=1e-7)


# ---------------------------------------------------------------------- pin-jointed trusses
AL_E, AL_G, AL_RHO = 7.0e10, 2.6e10, 2700.0
TUBE = {"area": 3.0e-4, "Iy": 4.0e-8, "Iz": 9.0e-8, "J": 1.3e-7}


def _truss_opensees(nodes, members, supports, masses, bar_model, lumped, count,
                    orientations=None):
    """Frequencies (Hz) of a pin-jointed truss in OpenSeesPy: ``Truss`` elements, or (pinned
    beams) every member a chain of ``SUB`` beam elements whose end nodes share only their
    translations with the joints.  In 3-D each chain's free spin about its own axis is a
    zero-frequency mode of its own (trussfe holds the twist of a pinned beam); the first
    ``len(members)`` frequencies, those spins, are dropped."""
    dim = len(next(iter(nodes.values())))
    ndf = 3 if dim == 2 else 6
    ops.wipe()
    ops.model("basic", "-ndm", dim, "-ndf", ndf)
    n = [0]

    def node(p):
        n[0] += 1
        ops.node(n[0], *map(float, p))
        return n[0]

    tag = {k: node(p) for k, p in nodes.items()}
    for k in nodes:
        fixed = supports.get(k, [])
        ops.fix(tag[k], *[int(d in fixed) for d in "xyz"[:dim]], *([1] * (ndf - dim)))
    for k, m in masses.items():
        ops.mass(tag[k], *([m] * dim), *([0.0] * (ndf - dim)))
    ops.uniaxialMaterial("Elastic", 1, AL_E)
    area = TUBE["area"]
    ele = transf = 0
    ties = []
    for i, j in members:
        ele += 1
        if bar_model == "truss":
            ops.element("Truss", ele, tag[i], tag[j], area, 1, "-rho", AL_RHO * area,
                        "-cMass", 0 if lumped else 1)
            continue
        transf += 1
        if dim == 2:
            ops.geomTransf("Linear", transf)
            props = (area, AL_E, TUBE["Iz"])
        else:
            ops.geomTransf("Linear", transf,
                           *_local_axes(nodes, i, j, (orientations or {}).get((i, j)))[2])
            props = (area, AL_E, AL_G, TUBE["J"], TUBE["Iy"], TUBE["Iz"])
        p0, p1 = np.asarray(nodes[i], float), np.asarray(nodes[j], float)
        chain = [node(p0 + (p1 - p0) * q / SUB) for q in range(SUB + 1)]
        ties += [(tag[i], chain[0]), (tag[j], chain[-1])]
        for a, b in zip(chain[:-1], chain[1:]):
            ele += 1
            ops.element("elasticBeamColumn", 100 * ele, a, b, *props, transf,
                        "-mass", AL_RHO * area, *([] if lumped else ["-cMass"]))
    for a, b in ties:
        ops.equalDOF(a, b, *range(1, dim + 1))
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    spins = len(members) if (bar_model == "pinned-beam" and dim == 3) else 0
    lam = np.array(ops.eigen("-fullGenLapack", count + spins))
    ops.wipe()
    assert np.all(np.abs(lam[:spins]) < 1e-6 * lam[spins])
    return np.sqrt(lam[spins:]) / (2 * np.pi)


def _truss_trussfe(nodes, members, supports, masses, orientations=None):
    dim = len(next(iter(nodes.values())))
    sec = TUBE if dim == 3 else {"area": TUBE["area"], "Iz": TUBE["Iz"]}
    mem = {}
    for i, j in members:
        m = {"nodes": [i, j], "section": "t", "material": "al"}
        if orientations and (i, j) in orientations:
            m["orientation"] = orientations[(i, j)]
        mem[i + j] = m
    return trussfe.model_from_dict({
        "model": {"dimension": dim},
        "materials": {"al": {"E": AL_E, "G": AL_G, "density": AL_RHO}},
        "sections": {"t": sec}, "nodes": nodes, "members": mem,
        "supports": supports, "masses": masses})


WARREN = ({"a": [0, 0], "b": [2, 0], "c": [4, 0], "d": [1, 1.5], "e": [3, 1.5]},
          [("a", "b"), ("b", "c"), ("a", "d"), ("d", "b"), ("b", "e"), ("e", "c"), ("d", "e")],
          {"a": ["x", "y"], "c": ["y"]}, {"d": 5.0, "e": 3.0})
SPACE = ({"a": [0, 0, 0], "b": [3, 0, 0], "c": [1.2, 2.5, 0], "t": [1.4, 0.9, 2.2],
          "u": [2.6, 1.9, 2.0]},
         [("a", "t"), ("b", "t"), ("c", "t"), ("a", "u"), ("b", "u"), ("c", "u"), ("t", "u"),
          ("a", "b")],
         {"a": ["x", "y", "z"], "b": ["x", "y", "z"], "c": ["x", "y", "z"]},
         {"t": 4.0, "u": 2.5})


@pytest.mark.parametrize("bar_model, count", [("truss", 7), ("pinned-beam", 10)])
@pytest.mark.parametrize("mass", ["consistent", "lumped"])
def test_plane_truss_bar_models_match_opensees(bar_model, count, mass):
    """A plane Warren truss with nodal masses: with the ``truss`` bar model the joints' modes
    (Truss elements), with ``pinned-beam`` the members' own bending modes as well (beam
    chains pinned to the joints), both mass kinds, as OpenSeesPy gives them."""
    f_ops = _truss_opensees(*WARREN, bar_model, mass == "lumped", count)
    r = trussfe.modes(_truss_trussfe(*WARREN), count=count, bar_model=bar_model,
                      subdivisions=SUB, mass=mass)
    assert_allclose(r.frequencies_hz, f_ops, rtol=1e-9)


@pytest.mark.parametrize("bar_model, count", [("truss", 6), ("pinned-beam", 14)])
def test_space_truss_bar_models_match_opensees(bar_model, count):
    """A space truss of tubes with Iy ≠ Iz, one member turned by an orientation vector:
    the consistent-mass frequencies of both bar models are OpenSeesPy's (the pinned beams'
    bending about both member axes)."""
    ori = {("t", "u"): [0.0, 0.3, 1.0]}
    f_ops = _truss_opensees(*SPACE, bar_model, False, count, orientations=ori)
    r = trussfe.modes(_truss_trussfe(*SPACE, orientations=ori), count=count,
                      bar_model=bar_model, subdivisions=SUB)
    assert_allclose(r.frequencies_hz, f_ops, rtol=1e-9)
