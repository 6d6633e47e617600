# SPDX-License-Identifier: MIT
"""One mass, one weight, in every analysis.

The hand computation of a model's mass (docs/model-format.md, docs/rigid-body.md,
docs/modal-buckling.md):

* a passive member is a uniform tube, mass ρAL centred at its midpoint;
* a node mass (``[masses]``) sits at its node, supported or not;
* an active member (``[active_members]``) is its active base, mass ``base_mass`` at
  ``base_cg`` from its start node, and its leadscrew tube, the member's section over
  ``tube_length`` at its end node (mass ρA·tube_length centred ``tube_length/2`` from the end
  node); its own ρAL is not counted besides.

Under gravity g the supports then carry the weight m·g, and the moment of the reactions about
the origin is that of the weight at the centre of mass: Σ x × R = −x_G × m g.  A unit rigid
translation r of the mass matrix gives rᵀ M r = m, and a rigid rotation its first moment.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe import read_model
from trussfe.fem.discretisation import discretise
from trussfe.fem.modal import mass_matrix, rigid_translations

MESHES = Path(__file__).resolve().parents[1] / "meshes"
RTOL = 1e-9


# ---------------------------------------------------------------------- hand computation
def hand_mass(s, active=True):
    """Total mass and centre of mass of a model by the rules of the module docstring.

    ``active=False`` counts every member as a uniform tube ρAL (the model read without its
    ``[active_members]``)."""
    X = np.asarray(s.coords, dtype=float)
    acts = {a.member: a for a in s.extensions.get("active_members", ())} if active else {}
    m, first = 0.0, np.zeros(s.dim)
    for j, (a, b) in enumerate(s.connectivity):
        rho = s.materials[j].density or 0.0
        area = s.sections[j].area
        d = X[b] - X[a]
        L = float(np.linalg.norm(d))
        e = d / L
        if j in acts:
            act = acts[j]
            mt = rho * area * act.tube_length
            m += act.base_mass + mt
            first += act.base_mass * (X[a] + act.base_cg * e)
            first += mt * (X[a] + (L - 0.5 * act.tube_length) * e)
        else:
            mm = rho * area * L
            m += mm
            first += mm * 0.5 * (X[a] + X[b])
    nodal = np.asarray(s.masses, dtype=float)
    m += nodal.sum()
    first += nodal @ X
    return m, first / m


def _cross(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    if a.shape[-1] == 2:
        return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    return np.cross(a, b)


def check_reactions(s, forces, moments=None, positions=None, active=True, rtol=RTOL):
    """Reactions (node, dim) [+ reaction moments] balance the hand weight and its moment."""
    g = np.asarray(s.gravity, dtype=float)
    X = np.asarray(s.coords if positions is None else positions, dtype=float)
    loads = np.asarray(s.loads, dtype=float)[:, : s.dim]
    R = np.asarray(forces, dtype=float)[:, : s.dim]
    m, cg = hand_mass(s, active)
    W = m * g
    scale = float(np.linalg.norm(W))
    assert_allclose((R + loads).sum(axis=0), -W, rtol=0, atol=rtol * scale)
    M = _cross(X, R + loads).sum(axis=0)
    if moments is not None:
        M = M + np.asarray(moments, dtype=float).sum(axis=0)
    lever = float(np.abs(X).max())
    assert_allclose(M, -_cross(cg, W), rtol=0, atol=rtol * scale * lever)


# ---------------------------------------------------------------------- models
def triangle_weight():
    """Lacy's triangular truss with its members' weight and 10 kg at B (no active member)."""
    return read_model(MESHES / "triangular_truss_weight.toml")


def triangle_active():
    """The same truss with its active member: 2.4 kg base at 1.05 m, 2.0 m tube."""
    return read_model(MESHES / "triangular_truss_motion_active.toml")


def octahedron_active():
    """Double-octahedral bay, hanging, three active members of 3 kg bases."""
    return read_model(MESHES / "double_octahedron_motion_active.toml")


def octahedron_passive():
    return octahedron_active().without_extensions("active_members")


def chain3_active():
    """Three-bay double-octahedral chain, nine active members."""
    return read_model(MESHES / "chain3_motion_active.toml")


def tripod(active=False):
    """A 3-D tripod under oblique gravity, a mass at its apex and one on a support; with
    ``active`` its member BD is active, its base's centre of gravity (0.9 m) beyond the
    cantilever connection (L − tube_length = 1.01 m is close) and its tube shorter than the
    member."""
    d = {"model": {"name": "tripod", "dimension": 3, "gravity": [1.5, -2.0, -9.0]},
         "materials": {"st": {"E": 2e11, "density": 7850.0}},
         "sections": {"t": {"outer_diameter": 0.04, "inner_diameter": 0.03}},
         "nodes": {"A": [0, 0, 0], "B": [2, 0, 0], "C": [0.5, 1.8, 0], "D": [0.8, 0.6, 1.5]},
         "members": {k: {"nodes": [k[0], k[1]], "section": "t", "material": "st"}
                     for k in ("AD", "BD", "CD")},
         "supports": {n: ["x", "y", "z"] for n in "ABC"},
         "masses": {"D": 5.0, "A": 2.0},
         "loads": {"D": [0.0, 0.0, 1.0]}}
    if active:
        d["active_members"] = {"BD": {"base_mass": 3.5, "base_length": 1.2, "base_cg": 0.9,
                                      "base_inertia": 3.2, "tube_length": 1.0}}
    return trussfe.model_from_dict(d)


def free_tetrahedron(active=False):
    """An unsupported tetrahedron: every mass is on free DOFs."""
    d = {"model": {"name": "tetrahedron", "dimension": 3, "gravity": [0.0, 0.0, -9.81]},
         "materials": {"st": {"E": 2e11, "density": 7850.0}},
         "sections": {"t": {"outer_diameter": 0.04, "inner_diameter": 0.03}},
         "nodes": {"A": [0, 0, 0], "B": [2, 0, 0], "C": [0.5, 1.8, 0], "D": [0.8, 0.6, 1.5]},
         "members": {k: {"nodes": [k[0], k[1]], "section": "t", "material": "st"}
                     for k in ("AD", "BD", "CD", "AB", "BC", "CA")},
         "masses": {"D": 5.0, "A": 2.0}}
    if active:
        d["active_members"] = {"BD": {"base_mass": 3.5, "base_length": 1.2, "base_cg": 0.9,
                                      "base_inertia": 3.2, "tube_length": 1.0}}
    return trussfe.model_from_dict(d)


def portal(dim):
    """A frame of beams (one end released) with a pin-jointed brace, oblique gravity, a node
    mass with rotary inertia, masses on a fixed and on a free node."""
    if dim == 2:
        nodes = {"A": [0, 0], "B": [0, 3], "C": [4, 3.5], "D": [4, 0]}
        g = [1.2, -9.81]
        sup = {"A": ["x", "y", "rz"], "D": ["x", "y"]}
        masses = {"B": {"mass": 10.0, "inertia": 0.5}, "A": 3.0, "C": 4.0}
    else:
        nodes = {"A": [0, 0, 0], "B": [0, 0.5, 3], "C": [4, 0, 3.5], "D": [4, 0.3, 0]}
        g = [1.2, 0.7, -9.81]
        sup = {n: ["x", "y", "z", "rx", "ry", "rz"] for n in "AD"}
        masses = {"B": {"mass": 10.0, "inertia": [0.5, 0.4, 0.3]}, "A": 3.0, "C": 4.0}
    return trussfe.model_from_dict({
        "model": {"name": f"portal {dim}-D", "dimension": dim, "gravity": g},
        "materials": {"st": {"E": 2e11, "G": 8e10, "density": 7850.0},
                      "al": {"E": 7e10, "density": 2700.0}},
        "sections": {"box": {"area": 4e-3, "Iy": 8e-6, "Iz": 5e-6, "J": 1e-5, "c": 0.1},
                     "rod": {"outer_diameter": 0.03, "inner_diameter": 0.0}},
        "nodes": nodes,
        "members": {"AB": {"nodes": ["A", "B"], "section": "box", "material": "st", "type": "beam"},
                    "BC": {"nodes": ["B", "C"], "section": "box", "material": "st", "type": "beam",
                           "releases": ["end"]},
                    "CD": {"nodes": ["C", "D"], "section": "box", "material": "st", "type": "beam"},
                    "AC": {"nodes": ["A", "C"], "section": "rod", "material": "al"}},
        "supports": sup, "masses": masses})


PASSIVE = {"triangle": triangle_weight, "octahedron": octahedron_passive,
           "tripod": tripod}
ACTIVE = {"triangle": triangle_active, "octahedron": octahedron_active,
          "chain3": chain3_active, "tripod": lambda: tripod(active=True)}
BAR_MODELS = [("truss", None), ("pinned-beam", None), ("pinned-beam", 1),
              ("pinned-beam", 2), ("pinned-beam", 5)]


def _hold_motion(tmp_path, s):
    """A motion file that holds every active member at its length in the model."""
    X = np.asarray(s.coords, dtype=float)
    items = []
    for a in s.extensions["active_members"]:
        i, j = s.connectivity[a.member]
        items.append(f'"{s.member_ids[a.member]}" = {float(np.linalg.norm(X[j] - X[i]))!r}')
    lengths = "{ " + ", ".join(items) + " }"
    f = tmp_path / "hold.toml"
    f.write_text(f'[motion]\ntype = "third-order"\nduration = 0.5\nsteps = 4\n'
                 f"start = {lengths}\nend = {lengths}\n")
    return str(f)


# ---------------------------------------------------------------------- static
@pytest.mark.parametrize("bar_model,subdivisions", BAR_MODELS)
@pytest.mark.parametrize("name", list(PASSIVE))
def test_static_reactions_carry_the_hand_weight(name, bar_model, subdivisions):
    """Σ reactions = −(Σ ρAL + Σ node masses) g, and their moment puts the weight at the hand
    centre of mass (members at their midpoints), for every bar model and subdivision."""
    s = PASSIVE[name]()
    r = trussfe.static(s, bar_model=bar_model, subdivisions=subdivisions)
    check_reactions(s, r.reaction)


@pytest.mark.parametrize("subdivisions", [None, 1, 2, 5])
@pytest.mark.parametrize("dim", [2, 3])
def test_static_frame_reactions_carry_the_hand_weight(dim, subdivisions):
    """Beams (a released end among them) and a bar, with reaction moments at fixed supports:
    the weight and its moment, node masses on a support included, rotary inertia adding
    nothing."""
    s = portal(dim)
    r = trussfe.static(s, bar_model="pinned-beam", subdivisions=subdivisions)
    R = np.asarray(r.solution.reactions)
    moments = R[:, 2] if dim == 2 else R[:, 3:6]
    check_reactions(s, R[:, :dim], moments)


# ---------------------------------------------------------------------- modes
@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
@pytest.mark.parametrize("kind", ["consistent", "lumped"])
@pytest.mark.parametrize("name", list(PASSIVE) + [f"active {k}" for k in ACTIVE]
                         + ["portal 2", "portal 3"])
def test_mass_matrix_rigid_translation_is_the_hand_mass(name, kind, bar_model):
    """rᵀ M r = total mass along every axis: ρAL per passive member, node masses, and for an
    active member its base plus ρA·tube_length (not its ρAL)."""
    if name.startswith("active"):
        s = ACTIVE[name.split()[1]]()
    elif name.startswith("portal"):
        s = portal(int(name.split()[1]))
    else:
        s = PASSIVE[name]()
    fe = discretise(s, bar_model=bar_model)
    M = mass_matrix(fe, kind)
    r = rigid_translations(fe)
    m, _ = hand_mass(s)
    assert_allclose(np.diag(r.T @ (M @ r)), m, rtol=RTOL)


@pytest.mark.parametrize("kind", ["consistent", "lumped"])
@pytest.mark.parametrize("active", [False, True])
def test_mass_matrix_first_moment_is_the_hand_centre_of_mass(active, kind):
    """For a rigid rotation u = ω × x (truss bar model) r_jᵀ M u = m (ω × x_G)_j: the base at
    base_cg and the tube centred tube_length/2 from the end node."""
    s = tripod(active)
    fe = discretise(s, bar_model="truss")
    M = mass_matrix(fe, kind)
    r = rigid_translations(fe)
    X = np.asarray(s.coords, dtype=float)
    m, cg = hand_mass(s)
    for k in range(3):
        w = np.eye(3)[k]
        u = np.zeros(fe.n_dof)
        u[fe.node_dofs[:, :3].ravel()] = np.cross(w, X).ravel()
        assert_allclose(r.T @ (M @ u), m * np.cross(w, cg), rtol=0, atol=RTOL * m)


@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
@pytest.mark.parametrize("kind", ["consistent", "lumped"])
@pytest.mark.parametrize("active", [False, True])
def test_modes_of_a_free_structure_capture_the_hand_mass(active, kind, bar_model):
    """Unsupported: total_mass and the sum of all effective masses are the hand mass."""
    s = free_tetrahedron(active)
    res = trussfe.modes(s, count=12, mass=kind, bar_model=bar_model).solution
    m, _ = hand_mass(s)
    assert res.rigid_modes == 6
    assert_allclose(res.total_mass, m, rtol=RTOL)
    assert_allclose(np.asarray(res.effective_mass).sum(axis=0), m, rtol=1e-8)


# ---------------------------------------------------------------------- along a motion, at rest
@pytest.mark.parametrize("name", list(PASSIVE) + [f"active {k}" for k in ACTIVE])
def test_simulate_and_elastic_at_rest_carry_the_hand_weight(name):
    """The rigid-body model and the FE model along the motion, at rest: the weight of the
    members, node masses and active bases and tubes, at the hand centre of mass."""
    s = ACTIVE[name.split()[1]]() if name.startswith("active") else PASSIVE[name]()
    sim = trussfe.simulate(s)
    check_reactions(s, np.asarray(sim.reaction)[0], positions=np.asarray(sim.position)[0])
    el = trussfe.elastic(s)
    check_reactions(s, np.asarray(el.reaction)[0], positions=np.asarray(el.position)[0])


@pytest.mark.parametrize("name", list(PASSIVE))
@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
def test_simulate_at_rest_equals_static_without_active_members(name, bar_model):
    """Statically determinate, no active member: the rigid-body reactions are the static
    ones, whatever the bar model."""
    s = PASSIVE[name]()
    sim = trussfe.simulate(s)
    st = trussfe.static(s, bar_model=bar_model)
    scale = float(np.abs(st.reaction).max())
    assert_allclose(np.asarray(sim.reaction)[0], st.reaction, rtol=0, atol=RTOL * scale)


@pytest.mark.parametrize("method", ["direct", "bay-by-bay"])
def test_simulate_holding_still_carries_the_weight_at_every_step(tmp_path, method):
    """A motion that holds the nine active members of the chain still: every step's
    reactions are the hand weight, by either method."""
    s = chain3_active()
    r = trussfe.simulate(s, motion=_hold_motion(tmp_path, s), method=method)
    for R, X in zip(np.asarray(r.reaction), np.asarray(r.position)):
        check_reactions(s, R, positions=X)


@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
@pytest.mark.parametrize("name", ["triangle", "tripod", "chain3"])
def test_transient_holding_still_has_the_rigid_body_forces(tmp_path, name, bar_model):
    """Transient dynamics along a motion that holds still: the passive members' midpoint
    forces are those of simulate at rest (whose reactions carry the hand weight, base masses
    included); the FE and the rigid-body forces agree at every step."""
    s = ACTIVE[name]()
    tr = trussfe.transient(s, motion=_hold_motion(tmp_path, s), bar_model=bar_model)
    sim = trussfe.simulate(s)
    act = {a.member for a in s.extensions["active_members"]}
    passive = [j for j in range(s.n_members) if j not in act]
    N = np.asarray(tr.axial_force)
    ref = np.asarray(sim.axial_force)[0]
    scale = float(np.abs(ref).max())
    for row in N:
        assert_allclose(row[passive], ref[passive], rtol=0, atol=1e-9 * scale)
    assert_allclose(N, np.asarray(tr.axial_force_rigid), rtol=0, atol=1e-9 * scale)


# ---------------------------------------------------------------------- postcritical
def _postcritical_reactions(s, bar_model):
    """Support reactions at the first point of the path (λ = 0, gravity as dead load)."""
    sol = trussfe.postcritical(s, steps=2, max_load_factor=0.01, bar_model=bar_model).solution
    model, p0 = sol.model, sol.path[0]
    assert p0.load_factor == 0.0
    R = model.evaluate(p0.u, tangent=False)["internal"] - model.dead
    R = np.where(model.free, 0.0, R)[: s.n_nodes * s.dim].reshape(s.n_nodes, s.dim)
    return R, model.positions(p0.u)[: s.n_nodes]


@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
def test_postcritical_dead_load_is_the_hand_weight(bar_model):
    """λ = 0 (the [loads] pattern not yet applied): the reactions carry the weight of the
    members (lumped at element ends) and the node masses; the moment is taken in the
    deformed state, so to its size."""
    s = tripod(active=False)
    R, _ = _postcritical_reactions(s, bar_model)
    m, _ = hand_mass(s)
    assert_allclose(R.sum(axis=0), -m * np.asarray(s.gravity), rtol=1e-9)
    check_reactions(s.with_loads(np.zeros_like(s.loads)), R, rtol=1e-4)


# ---------------------------------------------------------------------- active members
# every analysis weighs an active member as its base and its leadscrew tube: static,
# buckling and postcritical (loads along the finite-element member, lumped by the lever rule
# in the post-critical elements) as simulate, elastic, transient and modes do


@pytest.mark.parametrize("bar_model,subdivisions", [("truss", None), ("pinned-beam", 4)])
@pytest.mark.parametrize("name", ["triangle", "octahedron", "tripod"])
def test_static_counts_active_member_bases(name, bar_model, subdivisions):
    """The static reactions of a model with active members carry the hand weight (bases at
    base_cg, tubes of tube_length), as simulate's at rest and the modal mass do."""
    s = ACTIVE[name]()
    r = trussfe.static(s, bar_model=bar_model, subdivisions=subdivisions)
    check_reactions(s, r.reaction)


@pytest.mark.parametrize("name", ["triangle", "octahedron"])
def test_static_equals_simulate_at_rest_with_active_members(name):
    """docs/rigid-body.md and docs/cli.md: simulate without a motion can be compared with
    static — the determinate truss's reactions are equal."""
    s = ACTIVE[name]()
    sim = trussfe.simulate(s)
    st = trussfe.static(s, bar_model="pinned-beam")
    scale = float(np.abs(st.reaction).max())
    assert_allclose(np.asarray(sim.reaction)[0], st.reaction, rtol=0, atol=RTOL * scale)


def test_buckling_static_state_counts_active_member_bases():
    """The buckling analysis's static state under gravity: the follower's force is that of
    elastic at rest (same FE members, base weight included)."""
    s = triangle_active()
    b = trussfe.buckling(s, count=1)
    el = trussfe.elastic(s)
    j = s.member_ids.index("follower")
    assert_allclose(b.axial_force[j], np.asarray(el.axial_force)[0, j], rtol=1e-6)


@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
def test_postcritical_dead_load_counts_active_member_bases(bar_model):
    s = tripod(active=True)
    R, _ = _postcritical_reactions(s, bar_model)
    m, _ = hand_mass(s)
    assert_allclose(R.sum(axis=0), -m * np.asarray(s.gravity), rtol=1e-9)


def test_hand_masses_of_the_triangular_truss():
    """Members 2 m and 2.5 m of A = 1.1876e-4 m², ρ = 2711.5 kg/m³, 10 kg at B: 11.449 kg;
    with the active member as 2.4 kg base and 2.0 m tube: 13.688 kg."""
    s = triangle_active()
    assert_allclose(hand_mass(s, active=False)[0], 11.449074527, rtol=1e-9)
    assert_allclose(hand_mass(s)[0], 13.688066246, rtol=1e-9)


def test_static_of_active_members_runs_without_a_note(capsys):
    """static weighs the hardware of [active_members] as every other analysis does: exit
    status 0 and nothing on stderr."""
    from trussfe.cli import main
    root = Path(__file__).resolve().parents[1] / "meshes"
    assert main(["static", str(root / "double_octahedron_actuators.toml")]) == 0
    assert capsys.readouterr().err.strip() == ""


@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
def test_load_case_combination_counts_active_member_bases(bar_model):
    """A dead case (gravity) and a live case (a nodal load) of the tripod with its active
    member, combined 1.35 dead + 1.5 live: the case reactions carry the hand weight, the
    combination's 1.35 of it plus 1.5 of the load (statics, linear superposition)."""
    from trussfe.fem.load_cases import solve_load_cases
    from trussfe.model.load_cases import Combination, LoadCase, LoadCases
    s = tripod(active=True)
    live = np.zeros_like(s.loads)
    top = int(np.argmax(s.coords[:, 2]))
    live[top, :3] = [120.0, -40.0, -300.0]
    table = LoadCases(cases=(LoadCase("dead", np.zeros_like(s.loads), gravity=True),
                             LoadCase("live", live)),
                      combinations=(Combination("ULS", (("dead", 1.35), ("live", 1.5))),))
    sol = solve_load_cases(s.with_extensions(load_cases=table), bar_model=bar_model)
    m, _ = hand_mass(s)
    W = m * np.asarray(s.gravity)
    dead = sol.cases["dead"].reactions[:, :3].sum(axis=0)
    assert_allclose(dead, -W, rtol=1e-9)
    uls = sol.combinations["ULS"].reactions[:, :3].sum(axis=0)
    assert_allclose(uls, -(1.35 * W + 1.5 * live[top, :3]), rtol=1e-9)


@pytest.mark.parametrize("name", ["triangle", "octahedron", "chain3"])
def test_static_truss_active_member_carries_the_actuator_force(name):
    """An active member modelled as a truss bar keeps its bodies' weight at its joints, the
    base's axial share at the start joint and the tube's at the end joint: its axial force is
    the force at the cantilever connection, which the rigid-body model (Lacy eqs. 4.63–4.67,
    an independent Newton–Euler solution) reports as the actuator force at rest (positive
    pushing the tube out, i.e. compression)."""
    from trussfe.rigid.motion import rest_motion
    from trussfe.rigid.simulate import simulate
    s = ACTIVE[name]()
    rigid = simulate(s, rest_motion(s))
    st = trussfe.static(s)
    idx = [a.member for a in s.extensions["active_members"]]
    assert_allclose(st.axial_force[idx], -np.asarray(rigid.actuator_force)[0],
                    rtol=1e-9, atol=1e-9 * float(np.abs(st.axial_force).max()))
