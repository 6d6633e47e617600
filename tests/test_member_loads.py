"""Loads along members: equivalent end loads, reactions, deflections and section forces
against closed forms.

Sources: Roark's Formulas for Stress and Strain (7th ed.), Table 8.1 — simply supported beam
under a uniform load (case 2e: deflection 5qL⁴/384EI, reactions qL/2, M = qL²/8 at midspan),
fixed-fixed beam under a point load (case 1d: end moments Pab²/L², Pa²b/L², reactions
Pb²(3a + b)/L³, Pa²(a + 3b)/L³); statics for the resultants of a trapezoidal load
((q₁ + q₂)L/2 at L(q₁ + 2q₂)/(3(q₁ + q₂))).  Every static result here is in global
equilibrium with the member loads counted as applied loads (tests/conftest.py).
"""
import json

import numpy as np
import pytest

from trussfe.api.model import model_from_dict
from trussfe.fem.member_loads import member_load_vector
from trussfe.fem.static import solve_static, static_json
from trussfe.mechanics.member_loads import (linear_load_bending, point_load_bending,
                                            resultant, section_forces_along)
from trussfe.model import Material, MemberLoad, Section, build_structure

E, G, A, I, L = 2.0e11, 8.0e10, 4.0e-3, 8.0e-6, 3.0
SEC = Section("s", area=A, Iy=I, Iz=I, J=2 * I, c=0.05)
MAT = Material("m", E, G)
ALL3 = ["x", "y", "z", "rx", "ry", "rz"]


def beam(dim, supports, section=SEC, length=L):
    nodes = [[0, 0], [length, 0]] if dim == 2 else [[0, 0, 0], [length, 0, 0]]
    return build_structure(nodes, [(0, 1)], section=section, material=MAT,
                           supports=supports, is_beam=True)


def simply_supported(dim):
    sup = ({0: ["x", "y"], 1: ["y"]} if dim == 2
           else {0: ["x", "y", "z", "rx"], 1: ["y", "z"]})
    return beam(dim, sup)


def fixed_fixed(dim):
    return beam(dim, {0: ALL3[:2] + ["rz"], 1: ALL3[:2] + ["rz"]} if dim == 2
                else {0: ALL3, 1: ALL3})


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("k", [2, 4, 6])
def test_simply_supported_uniform(dim, k):
    q = -1000.0
    vec = [0.0, q] if dim == 2 else [0.0, 0.0, q]
    s = simply_supported(dim).with_extensions(member_loads=[MemberLoad.uniform(0, vec)])
    r = solve_static(s, subdivisions=k)
    # reactions qL/2 each (the structure's own transverse axis: y in 2-D, z in 3-D)
    c = dim - 1
    assert r.reactions[:, c] == pytest.approx([-q * L / 2] * 2, rel=1e-12)
    # midspan deflection 5qL⁴/384EI (Roark 8.1 case 2e): exact at the nodes
    mid = r.fe.station_displacements(r.u)[0, k // 2, c]
    assert mid == pytest.approx(5 * q * L**4 / (384 * E * I), rel=1e-10)
    # M = qL²/8 at midspan, sagging; 3-D: the global-z load is along the local y axis
    M = r.section_forces[0, k // 2, 5]
    assert abs(M) == pytest.approx(abs(q) * L**2 / 8, rel=1e-10)
    # the same moment along the member: wx(L − x)/2 at every station
    x = r.station_x[0]
    assert np.abs(r.section_forces[0, :, 5]) == pytest.approx(
        abs(q) * x * (L - x) / 2, rel=1e-9, abs=1e-9)


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("frac", [0.0, 0.13, 0.25, 0.5, 0.61, 1.0])
def test_fixed_fixed_point_load(dim, frac):
    P = -2000.0
    F = [0.0, P] if dim == 2 else [0.0, 0.0, P]
    s = fixed_fixed(dim).with_extensions(member_loads=[
        MemberLoad(0, "point", at=frac, force=tuple(F))])
    a, b = frac * L, (1 - frac) * L
    for k in (1, 4, 5):
        r = solve_static(s, subdivisions=k)
        c = dim - 1
        # reactions Pb²(3a + b)/L³ and Pa²(a + 3b)/L³ (Roark 8.1 case 1d)
        assert r.reactions[:, c] == pytest.approx(
            [-P * b**2 * (3 * a + b) / L**3, -P * a**2 * (a + 3 * b) / L**3], abs=1e-8)
        # end moments |Pab²/L²|, |Pa²b/L²|
        rot = 2 if dim == 2 else 4
        assert np.abs(r.reactions[:, rot]) == pytest.approx(
            [abs(P) * a * b**2 / L**2, abs(P) * a**2 * b / L**2], abs=1e-8)
        # the member's own end moments equal them
        assert np.abs(r.end_forces[0, :, 5]) == pytest.approx(
            [abs(P) * a * b**2 / L**2, abs(P) * a**2 * b / L**2], abs=1e-8)


def test_fixed_end_forces_closed_forms():
    # Roark 8.1 case 2 (uniform, triangular) and case 1 (point): Euler–Bernoulli, Φ = 0
    h, q = 2.0, 3.0
    assert linear_load_bending(h, 0.0, q, q) == pytest.approx(
        [q * h / 2, q * h**2 / 12, q * h / 2, -q * h**2 / 12])
    assert linear_load_bending(h, 0.0, 0.0, q) == pytest.approx(
        [3 * q * h / 20, q * h**2 / 30, 7 * q * h / 20, -q * h**2 / 20])
    a, b, P = 0.5, 1.5, 7.0
    assert point_load_bending(a / h, h, 0.0, P, 0.0) == pytest.approx(
        [P * b**2 * (3 * a + b) / h**3, P * a * b**2 / h**2, P * a**2 * (a + 3 * b) / h**3,
         -P * a**2 * b / h**2])
    # the fixed-end forces of a uniform load do not depend on Φ (symmetric load)
    assert linear_load_bending(h, 0.8, q, q) == pytest.approx(
        [q * h / 2, q * h**2 / 12, q * h / 2, -q * h**2 / 12])


@pytest.mark.parametrize("axes", ["global", "local"])
def test_trapezoidal_resultants(axes):
    # a simply supported 3-D beam along a skew line: the reactions of a trapezoidal load are
    # its resultant (q₁ + q₂)L/2 split by the centroid L(q₁ + 2q₂)/(3(q₁ + q₂)) (statics)
    d = np.array([2.0, 1.0, 0.5])
    Lm = float(np.linalg.norm(d))
    s = build_structure([[0, 0, 0], list(d)], [(0, 1)], section=SEC, material=MAT,
                        supports={0: ["x", "y", "z", "rx"], 1: ["y", "z"]}, is_beam=True)
    q1, q2 = -200.0, -600.0
    R = np.eye(3) if axes == "local" else None
    from trussfe.mechanics.geometry import local_axes
    ax = local_axes(s)[0]
    # the same physical load, a transverse one along the member's local z
    if axes == "local":
        ld = MemberLoad(0, "trapezoidal", (0, 0, q1), (0, 0, q2), axes="local")
    else:
        ld = MemberLoad(0, "trapezoidal", tuple(q1 * ax[2]), tuple(q2 * ax[2]))
    r = solve_static(s.with_extensions(member_loads=[ld]), subdivisions=3)
    total, xbar = resultant(Lm, q1, q2)
    assert total == pytest.approx((q1 + q2) * Lm / 2)
    assert xbar == pytest.approx(Lm * (q1 + 2 * q2) / (3 * (q1 + q2)))
    Rb = -total * xbar / Lm
    Ra = -total - Rb
    reac = r.reactions[:, :3] @ ax[2]
    assert reac == pytest.approx([Ra, Rb], rel=1e-10)
    del R


def test_section_forces_along_and_json_stations():
    # simply supported beam, point load P at a = 0.3L with 4 sub-elements (the load inside
    # an element): M(x) = Pbx/L before the load, Pa(L − x)/L after it (Roark 8.1 case 1e);
    # the JSON stations add x = a, where M = Pab/L
    P, frac = -1500.0, 0.3
    a, b = frac * L, (1 - frac) * L
    s = simply_supported(2).with_extensions(member_loads=[
        MemberLoad(0, "point", at=frac, force=(0.0, P))])
    r = solve_static(s, subdivisions=4)
    doc = json.loads(json.dumps(static_json(r)))
    st = doc["members"]["0"]["stations"]
    x = np.array(st["x"])
    assert x.tolist() == pytest.approx([0, 0.75, 0.9, 1.5, 2.25, 3.0])
    M = np.where(x <= a, -P * b * x / L, -P * a * (L - x) / L)
    assert st["Mz"] == pytest.approx(M.tolist(), abs=1e-9)
    # the FE stations agree with the statics along the member
    assert r.section_forces[0, :, 5] == pytest.approx(np.delete(M, 2), abs=1e-9)
    # shear: −R_a before the load, −R_a − P after it (section just after a station load)
    Ra = -P * b / L
    assert st["Vy"] == pytest.approx([-Ra, -Ra, -Ra - P, -Ra - P, -Ra - P, -Ra - P])


def test_section_forces_along_formula_uniform():
    # a cantilever of length L under q from its free start: M(x) = −qx²/2 (statics)
    q = np.array([[0.0, -10.0, 0.0]])
    x = np.linspace(0, 2.0, 5)[None]
    F = section_forces_along(x, np.array([2.0]), np.zeros((1, 6)), np.array([0]),
                             np.array([False]), q, q, np.zeros(1), np.zeros((1, 3)),
                             np.zeros((1, 3)))
    assert F[0, :, 5] == pytest.approx(-10.0 * x[0] ** 2 / 2)
    assert F[0, :, 1] == pytest.approx(10.0 * x[0])


@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
def test_truss_bar_simply_supported(bar_model):
    # a pin-ended bar (truss model) under a transverse uniform load and an axial one: the
    # end joints take qL/2 each (simply supported bar), the axial force varies linearly, and
    # the JSON stations of the bar show the simply supported moment qx(L − x)/2
    s = build_structure([[0, 0], [L, 0], [L, 2.0]], [(0, 1), (1, 2)], section=SEC,
                        material=MAT, supports={0: ["x", "y"], 2: ["x", "y"]})
    q, p = -400.0, 100.0
    s = s.with_extensions(member_loads=[MemberLoad.uniform(0, (p, q)),
                                        MemberLoad(0, "point", at=0.5, force=(0.0, -50.0))])
    # the same as a pin-ended beam (--bar-model pinned-beam, 4 elements, ends released)
    r = solve_static(s, bar_model=bar_model)
    # the free joint 1 takes half of each transverse load; bar 1 (vertical) carries it
    # as axial force.  Nothing but bar 0 holds joint 1 along x, so bar 0's axial force
    # runs from pL at its support to 0 at joint 1: N(x) = p(L − x)
    N1 = -(q * L / 2 - 25.0)
    assert r.axial_force[1] == pytest.approx(N1, rel=1e-12)
    assert r.end_forces[0, 1, 0] == pytest.approx(0.0, abs=1e-9)
    assert r.end_forces[0, 0, 0] == pytest.approx(p * L, rel=1e-12)
    st = static_json(r)["members"]["0"]["stations"]
    x = np.array(st["x"])
    assert x.tolist() == pytest.approx([0.0, L / 2, L] if bar_model == "truss"
                                       else [0.0, L / 4, L / 2, 3 * L / 4, L])
    M = -q * x * (L - x) / 2 + 50.0 * np.minimum(x, L - x) / 2
    assert st["Mz"] == pytest.approx(M.tolist(), abs=1e-9)
    assert st["N"] == pytest.approx((p * (L - x)).tolist(), abs=1e-9)


def test_member_load_vector_is_statically_equivalent():
    # the global equivalent loads of a load on a 3-D beam have the load's resultant
    # (statics), whatever the axes the load is given in
    s = build_structure([[0, 0, 0], [1.0, 2.0, 2.0]], [(0, 1)], section=SEC, material=MAT,
                        supports={0: ALL3, 1: ALL3}, is_beam=True)
    from trussfe.fem.discretisation import discretise
    fe = discretise(s, subdivisions=1)
    loads = [MemberLoad(0, "trapezoidal", (1.0, -2.0, 3.0), (4.0, 0.5, -1.0)),
             MemberLoad(0, "point", at=0.4, force=(0, 0, -7.0), moment=(1.0, 2.0, 3.0),
                        axes="local")]
    f = member_load_vector(fe, loads).global_vector
    F = f[fe.node_dofs[:, :3]].sum(axis=0)
    from trussfe.mechanics.geometry import local_axes
    Rm = local_axes(s)[0]
    expect = 0.5 * (np.array([1.0, -2.0, 3.0]) + np.array([4.0, 0.5, -1.0])) * 3.0 \
        + Rm.T @ np.array([0, 0, -7.0])
    assert F == pytest.approx(expect, rel=1e-12)


def test_model_file_member_loads_and_api(tmp_path):
    d = {"model": {"dimension": 2}, "materials": {"st": {"E": E, "G": G}},
         "sections": {"b": {"area": A, "Iz": I, "c": 0.05}},
         "nodes": {"A": [0, 0], "B": [L, 0]},
         "members": {"AB": {"nodes": ["A", "B"], "section": "b", "material": "st",
                            "type": "beam"}},
         "supports": {"A": ["x", "y"], "B": ["y"]},
         "member_loads": [{"member": "AB", "kind": "uniform", "q": [0.0, -1000.0]}]}
    import trussfe
    r = trussfe.static(model_from_dict(d))
    assert r.reaction[:, 1] == pytest.approx([1500.0, 1500.0])
    doc = r.to_dict()
    assert max(doc["members"]["AB"]["stations"]["Mz"]) == pytest.approx(1000.0 * L**2 / 8)


@pytest.mark.parametrize("k", [1, 3])
def test_point_couple(k):
    # Roark 8.1 case 3: a couple M0 (counter-clockwise) at a.  Simply supported: reactions
    # ±M0/L; fixed-fixed at midspan: end moments M0/4 each, reactions ±3M0/(2L) (signs from
    # statics: R_B L + M_A + M_B + M0 = 0)
    M0, frac = 600.0, 0.5
    ss = simply_supported(2).with_extensions(member_loads=[
        MemberLoad(0, "point", at=0.3, moment=(M0,))])
    r = solve_static(ss, subdivisions=k)
    assert r.reactions[:, 1] == pytest.approx([M0 / L, -M0 / L], rel=1e-10)
    ff = fixed_fixed(2).with_extensions(member_loads=[
        MemberLoad(0, "point", at=frac, moment=(M0,))])
    r = solve_static(ff, subdivisions=k)
    assert r.reactions[:, 2] == pytest.approx([M0 / 4, M0 / 4], rel=1e-10)
    assert r.reactions[:, 1] == pytest.approx([1.5 * M0 / L, -1.5 * M0 / L], rel=1e-10)


def test_buckling_under_distributed_axial_load():
    # a cantilever column under a uniform axial load q along its length buckles where
    # J₋₁/₃((2/3)√(qL³/EI)) = 0, (qL)cr = 7.837 EI/L² (Timoshenko & Gere, Theory of Elastic
    # Stability, §2.10); the element-wise constant axial force of the geometric stiffness
    # converges at second order: the error falls four-fold when the elements halve
    from scipy.optimize import brentq
    from scipy.special import jv
    from trussfe.fem.buckling import solve_buckling
    coef = (1.5 * brentq(lambda z: jv(-1.0 / 3.0, z), 1.0, 2.5)) ** 2
    assert coef == pytest.approx(7.837, abs=5e-4)
    H, q = 2.0, -1000.0
    s = build_structure([[0, 0], [0, H]], [(0, 1)], section=SEC, material=MAT,
                        supports={0: ["x", "y", "rz"]}, is_beam=True)
    s = s.with_extensions(member_loads=[MemberLoad.uniform(0, (0.0, q))])
    err = []
    for k in (16, 32):
        lam = solve_buckling(s, count=1, subdivisions=k, bar_model="truss").load_factors[0]
        err.append(abs(lam * abs(q) * H / (coef * E * I / H**2) - 1.0))
    assert 3.8 < err[0] / err[1] < 4.2 and err[1] < 5e-4, err


def test_load_cases_superpose_through_the_plug_in_points():
    # linear statics: the response to 1.35·(case 1) + 1.5·(case 2) is the factored sum of
    # the cases' responses (superposition) — through solve_static(member_loads=...), with
    # MemberLoad.scaled, and through member_load_vector added to a case's own load vector
    from trussfe.fem.discretisation import discretise
    s = fixed_fixed(3)
    c1 = [MemberLoad(0, "trapezoidal", (0.0, 100.0, -300.0), (20.0, 0.0, -100.0))]
    c2 = [MemberLoad(0, "point", at=0.37, force=(0.0, 50.0, -80.0), moment=(3.0, 0.0, 7.0),
                     axes="local")]
    fe = discretise(s, subdivisions=3)
    r1 = solve_static(s, fe=fe, member_loads=c1)
    r2 = solve_static(s, fe=fe, member_loads=c2)
    combo = [ld.scaled(1.35) for ld in c1] + [ld.scaled(1.5) for ld in c2]
    rc = solve_static(s, fe=fe, member_loads=combo)
    for name in ("u", "reactions", "end_forces", "section_forces"):
        assert getattr(rc, name) == pytest.approx(
            1.35 * getattr(r1, name) + 1.5 * getattr(r2, name), rel=1e-10, abs=1e-9)
    v = member_load_vector(fe, combo)
    f = fe.load_vector() + v.global_vector
    assert f == pytest.approx(rc.f, rel=1e-12, abs=1e-12)
    fel = fe.element_forces(rc.u, [sw + ml for sw, ml in
                                   zip(fe.element_self_weight_local(), v.local)])
    from trussfe.fem.static import section_forces
    assert section_forces(fe, rc.u, fel)[1] == pytest.approx(rc.section_forces, rel=1e-12,
                                                             abs=1e-9)
    assert solve_static(s, fe=fe, member_loads=()).reactions == pytest.approx(
        np.zeros_like(rc.reactions))


@pytest.mark.parametrize("k", [1, 4])
def test_torque_on_a_shaft_fixed_at_both_ends(k):
    # a torque T at a on a shaft fixed at both ends: reactions T·b/L and T·a/L, the twist
    # under the load T·a·b/(GJ L) (Gere & Timoshenko, Mechanics of Materials, statically
    # indeterminate torsion); here in member axes, inside an element for both k
    T, frac = 120.0, 0.3
    a, b = frac * L, (1 - frac) * L
    s = fixed_fixed(3).with_extensions(member_loads=[
        MemberLoad(0, "point", at=frac, moment=(T, 0.0, 0.0), axes="local")])
    r = solve_static(s, subdivisions=k)
    assert r.reactions[:, 3] == pytest.approx([-T * b / L, -T * a / L], rel=1e-10)
    st = static_json(r)["members"]["0"]["stations"]
    i = st["x"].index(pytest.approx(a))
    assert st["T"][i - 1 if k == 4 else 0] == pytest.approx(T * b / L, rel=1e-10)
    assert st["T"][-1] == pytest.approx(-T * a / L, rel=1e-10)


def test_couple_on_a_pin_ended_bar():
    # a couple M0 on a pin-ended bar (truss model): its end joints take the reactions of a
    # simply supported member, ±M0/L transverse (statics), and the bar's moment jumps by M0
    # under the couple (M = R_A x before it, R_A x − M0 after)
    M0 = 90.0
    s = build_structure([[0, 0], [L, 0]], [(0, 1)], section=SEC, material=MAT,
                        supports={0: ["x", "y"], 1: ["x", "y"]})
    s = s.with_extensions(member_loads=[MemberLoad(0, "point", at=0.4, moment=(M0,))])
    r = solve_static(s)
    assert r.reactions[:, 1] == pytest.approx([M0 / L, -M0 / L], rel=1e-12)
    st = static_json(r)["members"]["0"]["stations"]
    assert st["x"] == pytest.approx([0.0, 0.4 * L, L])
    # section convention: Mz(x) = −x·Vy0 − M0 beyond the couple, Vy0 = −R_A
    assert st["Mz"] == pytest.approx([0.0, 0.4 * L * M0 / L - M0, 0.0], abs=1e-9)
