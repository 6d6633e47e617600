# SPDX-License-Identifier: MIT
"""Static finite-element results against analytic solutions (hand calculations named in each
test).  Tolerances: rtol = 1e-10 where the element is exact (bars, Hermite beams under nodal
or uniform loads), otherwise stated."""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.fem import discretise, solve_static
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

STEEL = Material("steel", E=2.0e11, G=8.0e10, density=7850.0)
TUBE = Section.tube("tube", 0.05, 0.04)
EXACT = 1e-10


def test_two_bar_truss_by_hand():
    """Two bars of length L at ±θ to the vertical carry a hanging load P: each bar carries
    N = P / (2 cos θ) in tension and the joint drops by δ = P L / (2 EA cos² θ)
    (method of joints + virtual work)."""
    P, L, th = 1200.0, 1.5, np.radians(35.0)
    a, h = L * np.sin(th), L * np.cos(th)
    s = build_structure([[-a, h], [a, h], [0.0, 0.0]], [(2, 0), (2, 1)], section=TUBE,
                        material=STEEL, supports={0: "xy", 1: "xy"}, loads={2: [0.0, -P]})
    r = solve_static(s)
    EA = STEEL.E * TUBE.area
    assert_allclose(r.axial_force, P / (2 * np.cos(th)), rtol=EXACT)
    assert_allclose(r.displacements[2, :2], [0.0, -P * L / (2 * EA * np.cos(th) ** 2)],
                    rtol=EXACT, atol=1e-18)
    assert_allclose(r.reactions[0, :2] + r.reactions[1, :2], [0.0, P], rtol=EXACT)
    assert_allclose(r.axial_stress, r.axial_force / TUBE.area, rtol=EXACT)
    assert_allclose(r.strain, r.axial_force / EA, rtol=EXACT)


def test_three_bar_truss_by_hand():
    """Statically indeterminate three-bar truss: vertical bar of length h and two bars at ±θ,
    same EA, load P at the common joint.  Compatibility δ_outer = δ cos θ gives
    N_mid = P / (1 + 2 cos³ θ), N_out = P cos² θ / (1 + 2 cos³ θ), δ = N_mid h / EA
    (Timoshenko & Gere, Mechanics of Materials, three-bar problem)."""
    P, h, th = 5000.0, 2.0, np.radians(40.0)
    b = h * np.tan(th)
    s = build_structure([[-b, h], [0.0, h], [b, h], [0.0, 0.0]], [(3, 0), (3, 1), (3, 2)],
                        section=TUBE, material=STEEL, supports={0: "xy", 1: "xy", 2: "xy"},
                        loads={3: [0.0, -P]})
    r = solve_static(s)
    c = np.cos(th)
    n_mid = P / (1 + 2 * c**3)
    n_out = P * c**2 / (1 + 2 * c**3)
    assert_allclose(r.axial_force, [n_out, n_mid, n_out], rtol=EXACT)
    assert_allclose(r.displacements[3, 1], -n_mid * h / (STEEL.E * TUBE.area), rtol=EXACT)


@pytest.mark.parametrize("k", [1, 3])
def test_cantilever_2d_tip(k):
    """2-D cantilever, tip load P: tip deflection PL³/(3EI), rotation PL²/(2EI), root moment
    PL (Euler–Bernoulli; Hermite elements are nodally exact)."""
    P, L = 250.0, 1.7
    s = build_structure([[0.0, 0.0], [L, 0.0]], [(0, 1)], section=TUBE, material=STEEL,
                        supports={0: ["x", "y", "rz"]}, loads={1: [0.0, -P, 0.0]},
                        is_beam=True)
    r = solve_static(s, subdivisions=k)
    EI = STEEL.E * TUBE.Iz
    assert_allclose(r.displacements[1], [0.0, -P * L**3 / (3 * EI), -P * L**2 / (2 * EI)],
                    rtol=EXACT, atol=1e-16)
    # section forces at the root (force of the part beyond the section on the part before
    # it): the beam pushes the root down by P and turns it by −PL about z
    assert_allclose(r.end_forces[0, 0, [1, 5]], [-P, -P * L], rtol=EXACT)
    assert_allclose(r.end_forces[0, 1, [1, 5]], [-P, 0.0], rtol=EXACT, atol=1e-9)
    # S2 at the root: M c / I (no axial force)
    assert_allclose(r.max_von_mises[0], P * L * TUBE.c / TUBE.Iz, rtol=EXACT)


@pytest.mark.parametrize("direction", [[1.0, 0.0, 0.0], [1.0, 1.0, 1.0], [0.0, 0.0, 1.0]])
def test_cantilever_3d_both_planes(direction):
    """3-D cantilever along an arbitrary axis, tip loads in both transverse planes: tip
    deflection PL³/(3EI) along each load and rotation PL²/(2EI) about load × axis; a tip
    torque T twists by TL/(GJ).  Checks the rotation to member axes as well as both planes."""
    L = 1.3
    e = np.array(direction) / np.linalg.norm(direction)
    a = np.cross(e, [0.0, 1.0, 0.0] if abs(e[1]) < 0.9 else [1.0, 0.0, 0.0])
    a /= np.linalg.norm(a)
    b = np.cross(e, a)
    P1, P2, T = 300.0, -120.0, 45.0
    F = P1 * a + P2 * b
    s = build_structure([[0.0, 0.0, 0.0], L * e], [(0, 1)], section=TUBE, material=STEEL,
                        supports={0: ["x", "y", "z", "rx", "ry", "rz"]},
                        loads={1: np.r_[F, T * e]}, is_beam=True)
    r = solve_static(s, subdivisions=2)
    EI, GJ = STEEL.E * TUBE.Iy, STEEL.G * TUBE.J
    u_tip = r.displacements[1, :3]
    rot_tip = r.displacements[1, 3:]
    assert_allclose(u_tip, F * L**3 / (3 * EI), rtol=EXACT, atol=1e-15)
    assert_allclose(rot_tip, np.cross(e, F) * L**2 / (2 * EI) + T * L / GJ * e,
                    rtol=EXACT, atol=1e-15)
    # root moment resultant PL, torque T, shear resultant P
    root = r.end_forces[0, 0]
    assert_allclose(np.hypot(root[4], root[5]), np.linalg.norm(F) * L, rtol=EXACT)
    assert_allclose(root[3], T, rtol=EXACT)
    assert_allclose(np.hypot(root[1], root[2]), np.linalg.norm(F), rtol=EXACT)


def _simply_supported(k_bars=False, L=3.0, angle=0.0):
    """A pin-ended bar on two supports under self-weight (gravity −y)."""
    c, s_ = np.cos(angle), np.sin(angle)
    return build_structure([[0.0, 0.0], [L * c, L * s_]], [(0, 1)], section=TUBE,
                           material=STEEL, supports={0: "xy", 1: "y"}, gravity=[0.0, -9.81])


@pytest.mark.parametrize("k", [2, 4, 8])
def test_pinned_beam_self_weight_deflection(k):
    """Simply supported member under its own weight w = ρAg (pinned-beam model): midspan
    deflection 5wL⁴/(384EI), end rotations wL³/(24EI), reactions wL/2 (beam tables;
    Hermite elements with consistent loads are nodally exact)."""
    s = _simply_supported()
    L = 3.0
    r = solve_static(s, bar_model="pinned-beam", subdivisions=k)
    w = STEEL.density * TUBE.area * 9.81
    EI = STEEL.E * TUBE.Iz
    disp = r.fe.station_displacements(r.u)
    assert_allclose(disp[0, k // 2, 1], -5 * w * L**4 / (384 * EI), rtol=EXACT)
    assert_allclose(r.reactions[[0, 1], 1], [w * L / 2, w * L / 2], rtol=EXACT)
    # end rotations are the private (released) rotations of the member ends
    th = r.u[r.fe.private_dofs[0, :, 0]]
    assert_allclose(th, [-w * L**3 / (24 * EI), w * L**3 / (24 * EI)], rtol=EXACT)
    # released ends carry no moment
    assert_allclose(r.end_forces[0, :, 5], 0.0, atol=1e-9 * w * L**2)


@pytest.mark.parametrize("k", [1, 3, 5, 7, 9, 2, 6])
def test_pinned_beam_midspan_moment_converges(k):
    """Midspan moment under self-weight → wL²/8 with k.  Element end moments are exact, so the
    moment at the station nearest midspan is M(x) = w x (L − x)/2: exactly wL²/8 for even k
    and wL²/8 (1 − 1/k²) for odd k — an O(k⁻²) approach to wL²/8 (statics of the beam)."""
    s = _simply_supported()
    L = 3.0
    r = solve_static(s, bar_model="pinned-beam", subdivisions=k)
    w = STEEL.density * TUBE.area * 9.81
    M = np.nanmax(np.abs(r.section_forces[0, :, 5]))
    expected = w * L**2 / 8 * (1.0 - (1.0 / k**2 if k % 2 else 0.0))
    assert_allclose(M, expected, rtol=1e-9)
    if k == 1:
        assert M == pytest.approx(0.0, abs=1e-9)


def test_truss_model_lumps_self_weight_at_the_ends():
    """Truss bar model (MSC/PAL practice): an inclined bar's weight goes half to each end
    node, so a bar with both ends fully supported carries no axial force and each support
    takes W/2 (plus the weight of a nodal mass).  The pinned-beam model has the same
    reactions (statics) but bends the bar."""
    L = 2.0
    s = build_structure([[0.0, 0.0], [1.2, 1.6]], [(0, 1)], section=TUBE, material=STEEL,
                        supports={0: "xy", 1: "xy"}, gravity=[0.0, -9.81], masses={1: 3.0})
    r = solve_static(s)
    W = STEEL.density * TUBE.area * L * 9.81
    assert_allclose(r.axial_force, 0.0, atol=1e-9)
    assert_allclose(r.reactions[:, 1], [W / 2, W / 2 + 3.0 * 9.81], rtol=EXACT)
    # pinned-beam model: same reactions (statics), but the bar bends
    rb = solve_static(s, bar_model="pinned-beam")
    assert_allclose(rb.reactions[:, :2], r.reactions[:, :2], rtol=1e-9, atol=1e-9)
    assert np.nanmax(np.abs(rb.section_forces[0, :, 5])) > 0.1


def test_space_truss_indeterminate_against_dense_direct_stiffness():
    """A 3-D statically indeterminate truss (a perturbed two-storey tower, 8 free nodes)
    against an independent dense direct-stiffness solve K = Bᵀ diag(EA/L) B written here
    from the bar unit vectors."""
    rng = np.random.default_rng(7)
    base = np.array([[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0]], float)
    nodes = np.vstack([base, base + [0.1, 0.2, 1.5], base + [0.3, -0.1, 3.0]])
    nodes[4:] += rng.uniform(-0.1, 0.1, size=(8, 3))
    bars = []
    for lvl in (0, 4):
        for i in range(4):
            a, b = lvl + i, lvl + (i + 1) % 4
            bars += [(a, a + 4), (a, b + 4), (b, a + 4)]
    for i in range(4):
        bars += [(4 + i, 4 + (i + 1) % 4), (8 + i, 8 + (i + 1) % 4)]
    bars += [(4, 6), (8, 10), (9, 11)]
    bars = sorted(set(tuple(sorted(b)) for b in bars))
    loads = {i: rng.uniform(-1000, 1000, 3) for i in range(4, 12)}
    s = build_structure(nodes, bars, section=TUBE, material=STEEL,
                        supports={i: "xyz" for i in range(4)}, loads=loads)
    n, m = len(nodes), len(bars)
    assert m > 3 * 8, "must be statically indeterminate"
    r = solve_static(s)
    # independent dense solve
    B = np.zeros((m, 3 * n))
    Lb = np.zeros(m)
    for i, (a, b) in enumerate(bars):
        d = nodes[b] - nodes[a]
        Lb[i] = np.linalg.norm(d)
        B[i, 3 * a:3 * a + 3] = -d / Lb[i]
        B[i, 3 * b:3 * b + 3] = d / Lb[i]
    K = B.T @ np.diag(STEEL.E * TUBE.area / Lb) @ B
    f = np.zeros(3 * n)
    for i, v in loads.items():
        f[3 * i:3 * i + 3] = v
    free = np.arange(12, 3 * n)
    u = np.zeros(3 * n)
    u[free] = np.linalg.solve(K[np.ix_(free, free)], f[free])
    t = STEEL.E * TUBE.area / Lb * (B @ u)
    assert_allclose(r.displacements[:, :3].ravel(), u, rtol=1e-9, atol=1e-12 * abs(u).max())
    assert_allclose(r.axial_force, t, rtol=1e-8, atol=1e-8 * abs(t).max())
    # reactions balance the loads
    assert_allclose(r.reactions[:4, :3].sum(axis=0), -f.reshape(n, 3).sum(axis=0), rtol=1e-9)


def test_station_displacements_of_truss_bar_interpolate_ends():
    """A bar's only stations are its end nodes."""
    s = _simply_supported()
    fe = discretise(s)
    u = np.arange(fe.n_dof, dtype=float)
    st = fe.station_displacements(u)
    assert_allclose(st[0], fe.node_values(u)[:, :2])


def test_3d_frame_with_releases_bars_and_self_weight_is_in_equilibrium():
    """A 3-D frame mixing beams (one released at an end), pinned bars, nodal loads, moments,
    nodal masses and self-weight: reactions balance the applied forces and moments about the
    origin (global statics), and released ends carry no bending moment."""
    x = np.array([[0, 0, 0], [2, 0, 0], [2, 1.5, 0], [0, 1.5, 0],
                  [0, 0, 1.8], [2, 0, 1.8], [2, 1.5, 1.8], [0, 1.5, 1.8]], float)
    members = [(0, 4), (1, 5), (2, 6), (3, 7), (4, 5), (5, 6), (6, 7), (7, 4), (0, 5), (3, 6)]
    s = build_structure(x, members, section=TUBE, material=STEEL,
                        supports={i: ["x", "y", "z", "rx", "ry", "rz"] for i in range(4)},
                        loads={5: [300.0, -200.0, -500.0, 10.0, 0.0, 0.0],
                               6: [0.0, 150.0, -800.0, 0.0, 0.0, 0.0]},
                        masses={7: 20.0}, gravity=[0.0, 0.0, -9.81],
                        is_beam=[True] * 8 + [False, False])
    s = s.with_member_data(releases={4: [False, True]})   # beam 4-5 pinned at node 5
    for bar_model in ("truss", "pinned-beam"):
        r = solve_static(s, bar_model=bar_model, subdivisions=3)
        # resultant of the applied loads, member weights and the nodal mass's weight
        total_weight = (STEEL.density * TUBE.area * s.lengths().sum() + 20.0) * 9.81
        applied = np.array([300.0, -50.0, -1300.0 - total_weight])
        R = r.reactions[:4]
        assert_allclose(R[:, :3].sum(axis=0), -applied, rtol=1e-9)
        # moments about the origin: Σ x × F + Σ M over loads and reactions (weights of the
        # members act at their midpoints, nodal mass at node 7)
        w = STEEL.density * TUBE.area * s.lengths() * 9.81
        mid = 0.5 * (x[s.connectivity[:, 0]] + x[s.connectivity[:, 1]])
        mom = np.cross(x[5], [300.0, -200.0, -500.0]) + [10.0, 0, 0] + \
            np.cross(x[6], [0.0, 150.0, -800.0]) + np.cross(x[7], [0, 0, -20.0 * 9.81]) + \
            np.cross(mid, np.c_[np.zeros((len(w), 2)), -w]).sum(axis=0)
        mom_r = np.cross(x[:4], R[:, :3]).sum(axis=0) + R[:, 3:].sum(axis=0)
        assert_allclose(mom + mom_r, 0.0, atol=1e-8 * np.abs(mom).max())
        assert abs(r.end_forces[4, 1, 4]) < 1e-9 and abs(r.end_forces[4, 1, 5]) < 1e-9


def test_largest_per_row_is_the_nan_skipping_maximum():
    """The members' largest von Mises stress over their stations (NaN padding past a
    member's own stations skipped): the same values as numpy's ``fmax`` reduction over the
    row, and ``nanmax`` where a row has a number."""
    from trussfe.fem.static import _largest_per_row
    rng = np.random.default_rng(7)
    a = rng.random((200, 5))
    a[rng.random(a.shape) < 0.3] = np.nan
    a[3] = np.nan                                          # a row without a number
    a[4] = 0.0                                             # ties
    got = _largest_per_row(a)
    assert np.array_equal(got, np.fmax.reduce(a, axis=1), equal_nan=True)
    has = ~np.isnan(a).all(axis=1)
    assert np.array_equal(got[has], np.nanmax(a[has], axis=1))
    assert np.isnan(got[3])
    assert np.array_equal(_largest_per_row(a[:, :1]), a[:, 0], equal_nan=True)
