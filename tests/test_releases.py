# SPDX-License-Identifier: MIT
"""What a release frees (trussfe.mechanics.releases), in the linear analyses.

A released end transmits no bending moment; it transmits torsion only where the joint has
rotational stiffness from a rigid beam end or a rotational support.  References: PyNite
(``PyNiteFEA``, an independent frame solver) with the releases that meaning implies, computed
here; global equilibrium from statics (tests/equilibrium.py).
"""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.errors import InputError
from trussfe.fem.static import solve_static
from trussfe.io import toml_text
from trussfe.io.model_file import parse_model
from trussfe.mechanics.releases import HELD, JOINT, OWN, end_rotations

HEAD = """
[model]
name = "hinge torsion"
dimension = 3
[materials.steel]
E = 2.1e11
G = 8.1e10
[sections.tube]
outer_diameter = 0.1
inner_diameter = 0.08
"""

#: a beam released at a joint that nothing else gives rotations (a ball joint at H)
HINGE = HEAD + """
[nodes]
A = [0.0, 0.0, 0.0]
B = [2.0, 0.0, 0.0]
H = [2.0, 2.0, 0.0]
[members]
AB = { nodes = ["A", "B"], section = "tube", material = "steel", type = "beam" }
BH = { nodes = ["B", "H"], section = "tube", material = "steel", type = "beam", releases = ["end"] }
[supports]
A = ["x", "y", "z", "rx", "ry", "rz"]
H = ["x", "y", "z"]
[loads]
B = [0.0, 0.0, 0.0, 0.0, 1000.0, 0.0]
"""

#: a beam released at a joint where a rigid beam arrives: torsion passes, bending does not
FRAME = HEAD + """
[nodes]
A = [0.0, 0.0, 0.0]
B = [2.0, 0.0, 0.0]
C = [2.0, 2.0, 0.0]
D = [4.0, 2.0, 0.0]
[members]
AB = { nodes = ["A", "B"], section = "tube", material = "steel", type = "beam" }
BC = { nodes = ["B", "C"], section = "tube", material = "steel", type = "beam", releases = ["end"] }
CD = { nodes = ["C", "D"], section = "tube", material = "steel", type = "beam" }
[supports]
A = ["x", "y", "z", "rx", "ry", "rz"]
D = ["x", "y", "z", "rx", "ry", "rz"]
[loads]
B = [0.0, 0.0, -100.0, 0.0, 100.0, 0.0]
"""


def read_model_text(text, source="model.toml"):
    return parse_model(toml_text.loads(text), ".", source)


def _model(text, **replace):
    for a, b in replace.items():
        text = text.replace(a, b)
    return read_model_text(text)


def pynite_displacements(s, free_rotations, idle=()):
    """Node displacements (n, 6) of PyNite for structure ``s`` with member-end releases
    ``free_rotations[(member, end)] = "xyz"-style string of released local rotations``.
    The rotations of the ``idle`` nodes (which every member end reaching them leaves free)
    are held in PyNite, which needs stiffness on every node DOF."""
    Pynite = pytest.importorskip("Pynite")
    m = Pynite.FEModel3D()
    mat = s.materials[0]
    m.add_material("m", mat.E, mat.G, 0.3, mat.density)
    sec = s.sections[0]
    m.add_section("s", sec.area, sec.Iy, sec.Iz, sec.J)
    for nid, x in zip(s.node_ids, s.coords):
        m.add_node(nid, *x)
    for i, (a, b) in enumerate(s.connectivity):
        name = s.member_ids[i]
        m.add_member(name, s.node_ids[a], s.node_ids[b], "m", "s")
        kw = {}
        for end, tag in ((0, "i"), (1, "j")):
            for r in free_rotations.get((name, end), ""):
                kw[f"R{r}{tag}"] = True
        if kw:
            m.def_releases(name, **kw)
    for i, nid in enumerate(s.node_ids):
        sup = s.supports[i].copy()
        if nid in idle:
            sup[3:] = True
        if sup.any():
            m.def_support(nid, *[bool(v) for v in sup])
        for k, lab in enumerate(("FX", "FY", "FZ", "MX", "MY", "MZ")):
            if s.loads[i, k]:
                m.add_node_load(nid, lab, float(s.loads[i, k]))
    m.analyze_linear(check_statics=False)
    return np.array([[m.nodes[n].DX["Combo 1"], m.nodes[n].DY["Combo 1"],
                      m.nodes[n].DZ["Combo 1"], m.nodes[n].RX["Combo 1"],
                      m.nodes[n].RY["Combo 1"], m.nodes[n].RZ["Combo 1"]]
                     for n in s.node_ids])


def test_ball_joint_carries_no_torsion(equilibrium):
    """The released end of BH at H (where only BH arrives) is a ball joint: PyNite with BH's
    end free in torsion and bending gives B uz = −2.7282e-3 m; the reactions balance the
    applied moment (no hidden torsional support at H)."""
    s = _model(HINGE)
    r = solve_static(s, subdivisions=4)
    equilibrium(r)
    ref = pynite_displacements(s, {("BH", 1): "xyz"}, idle=("H",))
    assert_allclose(ref[1, 2], -2.7282e-3, rtol=1e-4)        # the reference's own figure
    assert_allclose(r.displacements[:, :3], ref[:, :3], rtol=1e-9, atol=1e-12)
    assert_allclose(r.displacements[:2, 3:], ref[:2, 3:], rtol=1e-9, atol=1e-12)
    assert_allclose(r.end_forces[1, 1, 3], 0.0, atol=1e-9)   # no torque into H
    assert not r.fe.has_rotation[2]


def test_released_end_at_rigid_joint_transmits_torsion(equilibrium):
    """BC released at C where the rigid beam CD arrives: bending is free, torsion passes
    (PyNite: Ry, Rz released at BC's end only)."""
    s = _model(FRAME)
    r = solve_static(s, subdivisions=4)
    equilibrium(r)
    ref = pynite_displacements(s, {("BC", 1): "yz"})
    assert_allclose(r.displacements, ref, rtol=1e-9, atol=1e-14)
    assert abs(r.end_forces[1, 1, 3]) > 1.0                  # torque does reach C


def test_explicit_torsion_release(equilibrium):
    """``releases = { end = ["bending", "torsion"] }`` frees the torsion even where a rigid
    beam arrives (PyNite: Rx, Ry, Rz released); ``{ end = ["torsion"] }`` frees the twist
    alone (PyNite: Rx released)."""
    s = _model(FRAME, **{'releases = ["end"]': 'releases = { end = ["bending", "torsion"] }'})
    assert s.torsion_releases[1].tolist() == [False, True]
    r = solve_static(s)
    equilibrium(r)
    assert_allclose(r.displacements, pynite_displacements(s, {("BC", 1): "xyz"}),
                    rtol=1e-9, atol=1e-14)
    s = _model(FRAME, **{'releases = ["end"]': 'releases = { end = ["torsion"] }'})
    assert s.releases[1].tolist() == [False, False]
    r = solve_static(s)
    equilibrium(r)
    assert_allclose(r.displacements, pynite_displacements(s, {("BC", 1): "x"}),
                    rtol=1e-9, atol=1e-14)


def test_rotational_support_holds_the_twist(equilibrium):
    """A released end at a joint whose rotations are supported transmits torsion to the
    support, which reports the reaction moment (PyNite: H fixed in rotation, Ry, Rz released
    at BH's end)."""
    s = _model(HINGE, **{'H = ["x", "y", "z"]': 'H = ["x", "y", "z", "rx", "ry", "rz"]'})
    r = solve_static(s)
    equilibrium(r)
    assert_allclose(r.displacements[:, :3], pynite_displacements(s, {("BH", 1): "yz"})[:, :3],
                    rtol=1e-9, atol=1e-14)
    assert abs(r.reactions[2, 4]) > 1.0                      # torque of BH about y at H


def test_member_free_to_twist_at_both_ends_is_held_at_its_start_only():
    """Both ends at ball joints: the start twist is held (the member cannot spin), the end
    twist is the member's own, and the bending rotations are the ends' own."""
    conn = np.array([[0, 1]])
    er = end_rotations(3, conn, np.array([[0.0, 1.0, 0.0]]), np.array([True]),
                       np.array([True]), np.array([[True, True]]), np.zeros((1, 2), bool),
                       np.zeros((2, 3), bool))
    assert er.state[0].tolist() == [[HELD, OWN, OWN], [OWN, OWN, OWN]]
    assert not er.joint_rotation.any()
    # a rotational support about an axis across the member does not hold its twist
    sup = np.zeros((2, 3), bool)
    sup[1, 0] = True
    er = end_rotations(3, conn, np.array([[0.0, 1.0, 0.0]]), np.array([True]),
                       np.array([True]), np.array([[False, True]]), np.zeros((1, 2), bool),
                       sup)
    assert er.state[0, 1, 0] == OWN
    sup[1, 1] = True                                           # about the member's axis: held
    er = end_rotations(3, conn, np.array([[0.0, 1.0, 0.0]]), np.array([True]),
                       np.array([True]), np.array([[False, True]]), np.zeros((1, 2), bool),
                       sup)
    assert er.state[0, 1, 0] == JOINT and er.joint_rotation[1]
    assert er.joint_rotation_held[1].all()


@pytest.mark.parametrize("bad, why", [
    ('releases = { end = ["twist"] }', "bending"),
    ('releases = { middle = ["torsion"] }', "middle"),
])
def test_bad_release_tables_are_named(bad, why):
    with pytest.raises(InputError, match=why):
        _model(FRAME, **{'releases = ["end"]': bad})


def test_torsion_release_needs_3d():
    text = """
[model]
name = "p"
dimension = 2
[materials.m]
E = 1e10
[sections.s]
area = 1e-4
Iz = 1e-8
[nodes]
A = [0.0, 0.0]
B = [1.0, 0.0]
[members]
AB = { nodes = ["A", "B"], section = "s", material = "m", type = "beam", releases = { end = ["torsion"] } }
[supports]
A = ["x", "y", "rz"]
"""
    with pytest.raises(InputError, match="3-D"):
        read_model_text(text, "p.toml")


def test_torsion_releases_are_written_back(tmp_path):
    from trussfe.io.model_writer import write_model
    s = _model(FRAME, **{'releases = ["end"]': 'releases = { end = ["bending", "torsion"] }'})
    p = tmp_path / "m.toml"
    write_model(s, p)
    s2 = read_model_text(p.read_text(), str(p))
    assert s2.torsion_releases.tolist() == s.torsion_releases.tolist()
    assert s2.releases.tolist() == s.releases.tolist()


# ------------------------------------------------------------------ same meaning in postcritical
_VARIANTS = {
    "ball joint": (HINGE, {}),
    "rigid joint": (FRAME, {}),
    "torsion released": (FRAME, {'releases = ["end"]':
                                 'releases = { end = ["bending", "torsion"] }'}),
    "twist only released": (FRAME, {'releases = ["end"]': 'releases = { end = ["torsion"] }'}),
    "my released alone": (FRAME, {'releases = ["end"]': 'releases = { end = ["my"] }'}),
    "mz released alone": (FRAME, {'releases = ["end"]': 'releases = { end = ["mz"], start = ["t"] }'}),
    "rotational support": (HINGE, {'H = ["x", "y", "z"]': 'H = ["x", "y", "z", "rx", "ry", "rz"]'}),
    "both ends released": (FRAME, {'releases = ["end"]': 'releases = ["start", "end"]',
                                   'B = [0.0, 0.0, -100.0, 0.0, 100.0, 0.0]':
                                   'B = [0.0, 0.0, -100.0, 0.0, 100.0, 0.0]\nC = [0.0, 0.0, -50.0]'}),
}


@pytest.mark.parametrize("name", list(_VARIANTS))
def test_small_load_postcritical_step_is_the_linear_static_answer(name, equilibrium):
    """A release means the same in the co-rotational model as in the linear core: under a
    load small enough for the geometry not to change (λ = 1e-4), one load-controlled step
    gives λ times the linear static displacements to 1e-6 (the linear answer of each model is
    in global equilibrium)."""
    from trussfe.nonlinear.model import NonlinearModel
    from trussfe.nonlinear.path import follow_path
    text, rep = _VARIANTS[name]
    s = _model(text, **rep)
    lin = solve_static(s, subdivisions=4)
    equilibrium(lin)
    nl = NonlinearModel(s, subdivisions=4)
    lam = 1e-4
    res = follow_path(nl, "load", steps=1, step=lam, max_load_factor=lam, tolerance=1e-12)
    assert_allclose(res.path[-1].load_factor, lam, rtol=1e-12)
    u = nl.joint_displacements(res.path[-1].u) / lam
    ref = lin.displacements[:, :3]
    assert_allclose(u, ref, rtol=0, atol=1e-6 * np.abs(ref).max())


@pytest.mark.parametrize("name", list(_VARIANTS))
def test_postcritical_tangent_at_the_undeformed_state_is_the_core_k_plus_kg(name):
    """The co-rotational tangent at the undeformed state with the linear axial forces is the
    linear core's K + K_g for every kind of release: the linear buckling load factors of the
    two models (co-rotational reference tangent; FE K + K_g about the static state) agree to
    1e-8 (AB compressed by 50 kN so that the frames buckle)."""
    from trussfe.fem.buckling import solve_buckling
    from trussfe.nonlinear.buckling import linear_buckling
    from trussfe.nonlinear.model import NonlinearModel
    text, rep = _VARIANTS[name]
    s = _model(text, **rep)
    loads = np.array(s.loads)
    loads[1, 0] -= 5.0e4
    s = s.with_loads(loads)
    core = solve_buckling(s, count=2, subdivisions=4, bar_model="truss").load_factors[:2]
    corot = linear_buckling(NonlinearModel(s, subdivisions=4), count=2)[0][:2]
    assert_allclose(corot, core, rtol=1e-8)


def test_reversing_a_member_moves_every_release_with_its_end():
    """Renumbering a member's ends (studies.numbering.reverse_members) carries the bending,
    per-axis and torsion releases of each end with it."""
    import numpy as np
    from trussfe.model.sections import Material, Section
    from trussfe.model.structure import build_structure
    from trussfe.studies.numbering import reverse_members
    s = build_structure([[0, 0, 0], [1, 0, 0]], [(0, 1)], section=Section("s", 1e-4, 1e-8, 1e-8, 2e-8, 0.01),
                        material=Material("m", E=2e11, G=8e10), supports={0: "xyz"})
    s = s.variant(releases=np.array([[True, False]]), torsion_releases=np.array([[False, True]]))
    r = reverse_members(s, [s.member_ids[0]])
    assert r.connectivity.tolist() == [[1, 0]]
    assert r.releases.tolist() == [[False, True]]
    assert r.torsion_releases.tolist() == [[True, False]]


def test_a_truss_has_the_end_rotations_of_the_general_classification():
    """``no_end_rotations`` (the shortcut for models without bending members) gives what
    ``end_rotations`` gives for the same members none of which is a frame: every component
    held, no joint with rotations (3-D chain and 2-D triangle)."""
    import dataclasses
    from trussfe.mechanics.releases import no_end_rotations
    from trussfe.models import double_octahedral_chain, triangular_truss
    for s in (double_octahedral_chain(3), triangular_truss()):
        d = s.member_vectors()
        axis = d / np.linalg.norm(d, axis=1)[:, None]
        m = s.n_members
        general = end_rotations(s.dim, s.connectivity, axis, np.zeros(m, bool),
                                np.zeros(m, bool), np.zeros((m, 2), bool),
                                np.zeros((m, 2), bool), s.supports[:, s.dim:])
        short = no_end_rotations(s.dim, m, s.n_nodes)
        for f in dataclasses.fields(general):
            a, b = getattr(general, f.name), getattr(short, f.name)
            assert a.dtype == b.dtype and np.array_equal(a, b), f.name
