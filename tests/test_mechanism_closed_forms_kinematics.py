# SPDX-License-Identifier: MIT
"""Mechanism kinematics against closed forms: joint velocities and accelerations of a four-bar
linkage and a slider-crank, the traced slider-crank and four-bar motions, and the graph of
small linkages (incidence, spanning tree, cycle matrices)."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import trussfe
from trussfe.errors import AnalysisError
from trussfe.kinematics.velocity import mechanism_acceleration, mechanism_velocity

MESHES = Path(__file__).resolve().parents[1] / "meshes"

# ----------------------------------------------------------------------------- four-bar
#: Crank a (pivot at the origin), coupler b, rocker c (pivot at (d, 0)): the proportions of
#: meshes/mech_fourbar.toml, a Grashof crank-rocker (a + b ≤ c + d).
A_, B_, C_, D_ = 1.0, 3.2, 2.6, 3.0
FOURBAR_CONN = np.array([[0, 1], [1, 2], [3, 2]])
FOURBAR_FREE = np.array([[0, 0], [1, 1], [1, 1], [0, 0]], bool)


def _perp(v):
    return np.array([-v[1], v[0]])


def fourbar_position(theta):
    """Crank pin B and coupler-rocker joint C (upper assembly branch): C is the intersection
    of the circles |C − B| = b and |C − D| = c."""
    pin = A_ * np.array([np.cos(theta), np.sin(theta)])
    ground = np.array([D_, 0.0])
    v = ground - pin
    dist = np.linalg.norm(v)
    u = v / dist
    along = (dist ** 2 + B_ ** 2 - C_ ** 2) / (2 * dist)
    return pin, pin + along * u + np.sqrt(B_ ** 2 - along ** 2) * _perp(u)


def fourbar_rates(theta, omega, alpha):
    """Closed-form joint velocities and accelerations of the four-bar from the vector loop
    a e^{iθ2} + b e^{iθ3} = d + c e^{iθ4} differentiated once and twice (Norton, *Design of
    Machinery*, sections 6.7 and 7.3): a ω2 i e^{iθ2} + b ω3 i e^{iθ3} = c ω4 i e^{iθ4} and
    a(iα2 − ω2²)e^{iθ2} + b(iα3 − ω3²)e^{iθ3} = c(iα4 − ω4²)e^{iθ4}."""
    pin, joint = fourbar_position(theta)
    e2, e3, e4 = pin, joint - pin, joint - np.array([D_, 0.0])
    M = np.column_stack([_perp(e3), -_perp(e4)])
    w3, w4 = np.linalg.solve(M, -omega * _perp(e2))
    a_pin = alpha * _perp(e2) - omega ** 2 * e2
    _a3, a4 = np.linalg.solve(M, -a_pin + w3 ** 2 * e3 - w4 ** 2 * e4)
    return (pin, joint, omega * _perp(e2), w4 * _perp(e4), a_pin,
            a4 * _perp(e4) - w4 ** 2 * e4)


RATES = [(2.0, 0.0), (2.0, 3.0), (-1.5, -4.0)]          # (ω, α): uniform and accelerating


def test_fourbar_closed_form_matches_finite_difference():
    """The loop-closure rates above are the first and second θ-derivatives of the closed-form
    position (central differences, ω = 1, α = 0)."""
    th, h = 0.7, 1e-4
    _, c0 = fourbar_position(th)
    _, cp = fourbar_position(th + h)
    _, cm = fourbar_position(th - h)
    _, _, _, vc, _, ac = fourbar_rates(th, 1.0, 0.0)
    np.testing.assert_allclose((cp - cm) / (2 * h), vc, atol=1e-7)
    np.testing.assert_allclose((cp - 2 * c0 + cm) / h ** 2, ac, atol=1e-5)


@pytest.mark.parametrize("omega,alpha", RATES)
@pytest.mark.parametrize("drive", ["both", "x", "y"])
def test_fourbar_velocity_acceleration_closed_form(omega, alpha, drive):
    """``mechanism_velocity`` / ``mechanism_acceleration`` of a crank-rocker over a crank turn
    equal the loop-closure velocities and accelerations (Norton §6.7, §7.3) of the crank pin
    and the coupler-rocker joint, the crank driven at constant or accelerating speed through
    both components of its pin or through one."""
    checked = 0
    for th in np.linspace(0.0, 2 * np.pi, 37)[:-1] + 0.05:
        pin, joint, v_pin, v_joint, a_pin, a_joint = fourbar_rates(th, omega, alpha)
        x = np.array([[0.0, 0.0], pin, joint, [D_, 0.0]])
        comps = {"both": (0, 1), "x": (0,), "y": (1,)}[drive]
        if any(abs(v_pin[k]) < 0.3 * abs(omega) for k in comps) and drive != "both":
            continue                                     # the one driven component stalls
        pv = {2 + k: float(v_pin[k]) for k in comps}
        pa = {2 + k: float(a_pin[k]) for k in comps}
        v = mechanism_velocity(x, FOURBAR_CONN, FOURBAR_FREE, pv)
        a = mechanism_acceleration(x, FOURBAR_CONN, FOURBAR_FREE, v, pa)
        np.testing.assert_allclose(v[1], v_pin, atol=1e-11)
        np.testing.assert_allclose(v[2], v_joint, atol=1e-11)
        np.testing.assert_allclose(a[1], a_pin, atol=1e-11)
        np.testing.assert_allclose(a[2], a_joint, atol=1e-11)
        np.testing.assert_array_equal(v[[0, 3]], 0.0)
        np.testing.assert_array_equal(a[[0, 3]], 0.0)
        checked += 1
    assert checked >= 20


# ----------------------------------------------------------------------------- slider-crank
R_, L_ = 1.0, 3.0                                        # meshes/mech_slider_crank.toml
SC_CONN = np.array([[0, 1], [1, 2]])
SC_FREE = np.array([[0, 0], [1, 1], [1, 0]], bool)


def slider_x(th):
    """Slider position x = r cos θ + √(l² − r² sin² θ) (in-line slider-crank)."""
    return R_ * np.cos(th) + np.sqrt(L_ ** 2 - R_ ** 2 * np.sin(th) ** 2)


def slider_derivatives(th):
    """dx/dθ and d²x/dθ² of :func:`slider_x`, differentiated by hand:
    x' = −r sin θ − r² sin θ cos θ / s,
    x'' = −r cos θ − r² cos 2θ / s − r⁴ sin² θ cos² θ / s³, with s = √(l² − r² sin² θ)."""
    s = np.sqrt(L_ ** 2 - R_ ** 2 * np.sin(th) ** 2)
    d1 = -R_ * np.sin(th) - R_ ** 2 * np.sin(th) * np.cos(th) / s
    d2 = (-R_ * np.cos(th) - R_ ** 2 * np.cos(2 * th) / s
          - R_ ** 4 * np.sin(th) ** 2 * np.cos(th) ** 2 / s ** 3)
    return d1, d2


def test_slider_derivatives_match_finite_difference():
    """The hand derivatives of x(θ) agree with central differences of x(θ) itself."""
    h = 1e-4
    for th in np.linspace(0.0, 2 * np.pi, 25):
        d1, d2 = slider_derivatives(th)
        assert abs((slider_x(th + h) - slider_x(th - h)) / (2 * h) - d1) < 1e-7
        assert abs((slider_x(th + h) - 2 * slider_x(th) + slider_x(th - h)) / h ** 2 - d2) < 1e-5


@pytest.mark.parametrize("omega,alpha", RATES)
@pytest.mark.parametrize("drive", ["pin", "pin_y", "slider"])
def test_slider_crank_velocity_acceleration_closed_form(omega, alpha, drive):
    """Slider velocity ẋ = x'(θ) ω and acceleration ẍ = x''(θ) ω² + x'(θ) α of the in-line
    slider-crank x = r cos θ + √(l² − r² sin² θ), and the crank pin's rω tangential and
    −rω² + rα components, from ``mechanism_velocity`` / ``mechanism_acceleration`` over a
    crank turn (dead centres included when the pin is driven)."""
    checked = 0
    for th in np.linspace(0.0, 2 * np.pi, 73)[:-1]:
        d1, d2 = slider_derivatives(th)
        v_s, a_s = d1 * omega, d2 * omega ** 2 + d1 * alpha
        pin = R_ * np.array([np.cos(th), np.sin(th)])
        v_pin = omega * _perp(pin)
        a_pin = alpha * _perp(pin) - omega ** 2 * pin
        if drive == "pin":
            pv, pa = {2: v_pin[0], 3: v_pin[1]}, {2: a_pin[0], 3: a_pin[1]}
        elif drive == "pin_y":
            if abs(v_pin[1]) < 0.3 * abs(omega):
                continue
            pv, pa = {3: v_pin[1]}, {3: a_pin[1]}
        else:
            if abs(v_s) < 0.3 * abs(omega):
                continue
            pv, pa = {4: v_s}, {4: a_s}
        x = np.array([[0.0, 0.0], pin, [slider_x(th), 0.0]])
        v = mechanism_velocity(x, SC_CONN, SC_FREE, pv)
        a = mechanism_acceleration(x, SC_CONN, SC_FREE, v, pa)
        np.testing.assert_allclose(v[2], [v_s, 0.0], atol=1e-11)
        np.testing.assert_allclose(a[2], [a_s, 0.0], atol=1e-11)
        np.testing.assert_allclose(v[1], v_pin, atol=1e-11)
        np.testing.assert_allclose(a[1], a_pin, atol=1e-11)
        checked += 1
    assert checked >= 20


def test_slider_crank_top_dead_centre_acceleration():
    """At θ = 0 the slider's acceleration is −rω²(1 + r/l) (Norton eq. 7.16a at θ = 0)."""
    x = np.array([[0.0, 0.0], [R_, 0.0], [R_ + L_, 0.0]])
    v = mechanism_velocity(x, SC_CONN, SC_FREE, {3: 2.0 * R_})
    a = mechanism_acceleration(x, SC_CONN, SC_FREE, v, {3: 0.0})
    assert v[2, 0] == pytest.approx(0.0, abs=1e-14)
    assert a[2, 0] == pytest.approx(-R_ * 4.0 * (1 + R_ / L_), abs=1e-12)


def test_active_bar_rates_polar_closed_form():
    """A single telescoping bar from a fixed pivot: v = ṙ e_r + r φ̇ e_φ and
    a = (r̈ − r φ̇²) e_r + (r φ̈ + 2 ṙ φ̇) e_φ (polar coordinates), with L̇ = ṙ, L̈ = r̈ given
    as ``length_rates`` / ``length_accelerations`` and the joint's y rates prescribed."""
    r, phi, rd, rdd, pd, pdd = 5.0, 0.9273, 1.0, 0.5, 0.7, -0.3
    er = np.array([np.cos(phi), np.sin(phi)])
    ep = _perp(er)
    v_ex = rd * er + r * pd * ep
    a_ex = (rdd - r * pd ** 2) * er + (r * pdd + 2 * rd * pd) * ep
    x = np.array([[0.0, 0.0], r * er])
    conn, free = np.array([[0, 1]]), np.array([[0, 0], [1, 1]], bool)
    v = mechanism_velocity(x, conn, free, {3: v_ex[1]}, length_rates=np.array([rd]))
    a = mechanism_acceleration(x, conn, free, v, {3: a_ex[1]}, length_rates=np.array([rd]),
                               length_accelerations=np.array([rdd]))
    np.testing.assert_allclose(v[1], v_ex, atol=1e-13)
    np.testing.assert_allclose(a[1], a_ex, atol=1e-13)


def test_contradictory_prescribed_rates_are_refused():
    """Both crank-pin components prescribed, but not those of one crank rotation: no joint
    velocity satisfies B v = 0 and both prescriptions (the crank's own row requires
    e·v_pin = 0), so the call is refused, as ``cycle_rates`` refuses contradictory drives."""
    th = 0.8
    pin = np.array([np.cos(th), np.sin(th)])
    x = np.array([[0.0, 0.0], pin, [slider_x(th), 0.0]])
    with pytest.raises(AnalysisError, match="contradict"):
        mechanism_velocity(x, SC_CONN, SC_FREE, {2: 5.0, 3: 2.0 * np.cos(th)})
    # the same two components of one crank rotation (ω = 2) are consistent and kept
    v = mechanism_velocity(x, SC_CONN, SC_FREE, {2: -2.0 * pin[1], 3: 2.0 * pin[0]})
    np.testing.assert_allclose(v[1], 2.0 * np.array([-pin[1], pin[0]]), atol=1e-13)


def test_acceleration_of_a_fixed_coordinate_is_refused_like_velocity():
    """Prescribing a supported coordinate is refused by both functions with AnalysisError."""
    th = 0.8
    x = np.array([[0.0, 0.0], [np.cos(th), np.sin(th)], [slider_x(th), 0.0]])
    with pytest.raises(AnalysisError):
        mechanism_velocity(x, SC_CONN, SC_FREE, {0: 0.0})
    v = mechanism_velocity(x, SC_CONN, SC_FREE, {3: np.cos(th)})
    with pytest.raises(AnalysisError):
        mechanism_acceleration(x, SC_CONN, SC_FREE, v, {0: 0.0})


# ----------------------------------------------------------------------------- trace
@pytest.mark.parametrize("drive,step,steps", [("2:y", 0.02, 400), ("2:y", -0.1, 100),
                                               ("3:x", -0.02, 400), ("3:x", 0.05, 200)])
def test_trace_slider_crank_closed_form(drive, step, steps):
    """Every traced state of meshes/mech_slider_crank.toml (r = 1 m, l = 3 m) lies on the
    closed form x = r cos θ + √(l² − r² sin² θ), θ the crank angle of the state, through more
    than a crank turn; the limit points of the drive are reported at the states where it
    turns."""
    res = trussfe.trace(MESHES / "mech_slider_crank.toml", drive=drive, step=step, steps=steps)
    P = res.position
    th = np.arctan2(P[:, 1, 1], P[:, 1, 0])
    assert abs(np.unwrap(th)[-1] - np.unwrap(th)[0]) > 2 * np.pi
    tol = 2 * res.solution.residual.max() + 1e-12
    np.testing.assert_allclose(P[:, 2, 0], slider_x(th), atol=max(tol, 1e-9))
    np.testing.assert_allclose(np.hypot(P[:, 1, 0], P[:, 1, 1]), R_, atol=max(tol, 1e-9))
    np.testing.assert_array_equal(P[:, 2, 1], 0.0)
    np.testing.assert_array_equal(P[:, 0], 0.0)
    node, axis = (1, 1) if drive == "2:y" else (2, 0)
    d = np.diff(P[:, node, axis])
    turns = np.flatnonzero(np.sign(d[1:]) != np.sign(d[:-1])) + 1
    assert [e["step"] for e in res.events if e["kind"] == "limit_point"] == turns.tolist()


def test_trace_fourbar_closed_form():
    """Every traced state of meshes/mech_fourbar.toml has its coupler-rocker joint at the
    circle intersection of the closed form (upper branch), over more than a crank turn."""
    res = trussfe.trace(MESHES / "mech_fourbar.toml", drive="2:y", step=0.02, steps=400)
    P = res.position
    th = np.arctan2(P[:, 1, 1], P[:, 1, 0])
    assert abs(np.unwrap(th)[-1] - np.unwrap(th)[0]) > 2 * np.pi
    expected = np.array([fourbar_position(t)[1] for t in th])
    np.testing.assert_allclose(P[:, 2], expected, atol=1e-9)


# ----------------------------------------------------------------------------- topology
def _model(nodes, members, supports, dim=2):
    return {"model": {"name": "graph", "dimension": dim},
            "materials": {"m": {"E": 70e9, "G": 26e9, "density": 2700.0}},
            "sections": {"s": {"outer_diameter": 0.02, "inner_diameter": 0.016}},
            "nodes": nodes,
            "members": {k: {"nodes": v, "section": "s", "material": "m"}
                        for k, v in members.items()},
            "supports": supports}


TRIANGLE = {"nodes": {"1": [0, 0], "2": [1, 0], "3": [0.5, 0.8]},
            "members": {"a": ["1", "2"], "b": ["2", "3"], "c": ["3", "1"]}}


def _simple_cycles(n, conn):
    """Edge sets of every simple cycle of a multigraph, by depth-first search (each cycle
    found from its smallest joint)."""
    adj = {i: [] for i in range(n)}
    for j, (a, b) in enumerate(conn):
        adj[int(a)].append((j, int(b)))
        adj[int(b)].append((j, int(a)))
    found = set()

    def dfs(start, node, edges, joints):
        for j, nb in adj[node]:
            if j in edges:
                continue
            if nb == start:
                found.add(frozenset(edges | {j}))
            elif nb not in joints and nb > start:
                dfs(start, nb, edges | {j}, joints | {nb})

    for s in range(n):
        dfs(s, s, frozenset(), frozenset({s}))
    return found


CASES = [
    ("triangle, one pin", lambda: _model(**TRIANGLE, supports={"1": ["x", "y"]}), 3, 3, 1, 1),
    ("triangle, two pins", lambda: _model(**TRIANGLE, supports={"1": ["x", "y"],
                                                                 "2": ["x", "y"]}), 3, 4, 2, 3),
    ("four-bar", lambda: MESHES / "mech_fourbar.toml", 4, 4, 1, 1),
    ("slider-crank", lambda: MESHES / "mech_slider_crank.toml", 4, 4, 1, 1),
    ("Bennett", lambda: MESHES / "mech_bennett.toml", 8, 23, 16, 1802),
]


@pytest.mark.parametrize("label,model,joints,edges,links,cycles", CASES,
                         ids=[c[0] for c in CASES])
def test_topology_graph_closed_forms(label, model, joints, edges, links, cycles):
    """Incidence A_a (+1 leaving, −1 entering each edge's joint), the reduced A (the root's
    row dropped), a spanning tree of r edges, s − r = edges − joints + 1 (one component)
    fundamental cycles B_f = [(−A_t⁻¹A_l)ᵀ | I] with A_a B_fᵀ = 0 (Vlase et al. 2008 eq. 2),
    and B_a holding every simple cycle once (a depth-first enumeration), each oriented along
    its first link, A_a B_aᵀ = 0, rank s − r.  The triangle with two pins, and Bennett's
    linkage (20 bars, ground 1-2-7-8 closed by 3 ground edges), have parallel edges: their
    two-edge cycles count."""
    res = trussfe.topology(model())
    eq = res.solution.assembly
    conn = eq.connectivity
    A = res.incidence
    n, s = A.shape
    assert (n, s) == (joints, edges)
    expected = np.zeros((n, s), dtype=int)
    expected[conn[:, 0], np.arange(s)] += 1
    expected[conn[:, 1], np.arange(s)] -= 1
    np.testing.assert_array_equal(A, expected)
    g = res.solution.graph
    np.testing.assert_array_equal(res.reduced_incidence, np.delete(A, g.reference, axis=0))
    # spanning tree: n − 1 edges joining every joint (union-find, no cycle closed)
    assert g.tree.size == n - 1 and len(res.tree) == n - 1
    parent = list(range(n))

    def find(i):
        while parent[i] != i:
            i = parent[i]
        return i
    for j in g.tree:
        ra, rb = find(int(conn[j, 0])), find(int(conn[j, 1]))
        assert ra != rb
        parent[ra] = rb
    assert len({find(i) for i in range(n)}) == 1
    Bf = res.fundamental_cycles
    assert Bf.shape == (edges - joints + 1, s) == (links, s)
    assert not np.any(A @ Bf.T)
    np.testing.assert_array_equal(Bf[:, g.links], np.eye(links, dtype=int))
    assert np.linalg.matrix_rank(Bf) == links
    Ba = res.complete_cycles
    assert Ba.shape == (cycles, s)
    assert not np.any(A @ Ba.T)
    np.testing.assert_array_equal(Ba[:links], Bf)
    assert np.linalg.matrix_rank(Ba) == links
    assert {frozenset(np.flatnonzero(r)) for r in Ba} == _simple_cycles(n, conn)
    for row in Ba:
        first = next(j for j in np.flatnonzero(row) if j in set(g.links.tolist()))
        assert row[first] == 1
    assert res.to_dict()["counts"] == {"joints": n, "edges": s, "tree_edges": n - 1,
                                       "links": links, "cycles": cycles}
