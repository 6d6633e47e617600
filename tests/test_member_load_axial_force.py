# SPDX-License-Identifier: MIT
"""Axial forces of members loaded along their length: the midpoint value, the average along
each element (the geometric stiffness's input), load combinations, and the pinned-beam truss
against PyNite; each test names its closed form or independent solver, with global
equilibrium checked.
"""
import numpy as np
import pytest

import trussfe
from trussfe.fem.load_cases import solve_load_cases
from trussfe.fem.static import solve_static

L = 4.0
F_AXIAL = 1000.0                    # N, along the member at 0.3 L
Q_END = 600.0                       # N/m, axial, rising from 0 at A to Q_END at B


def _axially_loaded(member_type, cases=False, at=0.3):
    """A member A–B along x, A pinned, B on a roller in y: every axial load goes to A."""
    loads = [{"member": "AB", "kind": "point", "at": at, "F": [F_AXIAL, 0.0]},
             {"member": "AB", "kind": "trapezoidal", "q_start": [0.0, 0.0],
              "q_end": [Q_END, 0.0], "axes": "local"}]
    d = {"model": {"dimension": 2},
         "materials": {"st": {"E": 2.0e11, "G": 8.0e10}},
         "sections": {"b": {"area": 4.0e-3, "Iz": 8.0e-6, "c": 0.05}},
         "nodes": {"A": [0.0, 0.0], "B": [L, 0.0]},
         "members": {"AB": {"nodes": ["A", "B"], "section": "b", "material": "st",
                            "type": member_type}},
         "supports": {"A": ["x", "y"], "B": ["y"]}}
    if cases:
        d["load_cases"] = {"axial": {"member_loads": loads},
                           "push": {"loads": {"B": [0.0, 0.0] if member_type == "bar"
                                              else [0.0, 0.0, 0.0]}}}
        d["combinations"] = {"c": {"axial": 1.5, "push": 1.0}}
    else:
        d["member_loads"] = loads
    return trussfe.model_from_dict(d)


def _midpoint_tension():
    """N(L/2) by statics: A takes every axial load, so the section at L/2 carries the loads
    beyond it, ∫_{L/2}^{L} q(s) ds = Q_END·(L² − L²/4)/(2L); the point load at 0.3 L is
    before it."""
    return Q_END * (L**2 - (L / 2) ** 2) / (2 * L)


@pytest.mark.parametrize("member_type, bar_model, k", [
    ("bar", "truss", None), ("bar", "pinned-beam", 4), ("beam", "truss", 1),
    ("beam", "truss", 4), ("beam", "truss", 3)])
def test_midpoint_axial_force_under_non_uniform_axial_member_loads(member_type, bar_model, k,
                                                                   equilibrium):
    """``axial_force`` is the axial force at the member midpoint (docs/fem.md, *Sign
    conventions*; ``StaticResult.axial_force``).  Reference: statics of a member pinned at A
    and free to slide at B — a point load at 0.3 L and a load rising linearly along the
    member leave N(L/2) = ∫_{L/2}^{L} q = 900 N.  The mean of the end values (1100 N) is the
    midpoint value only when N is linear along the member, which it is not here."""
    s = _axially_loaded(member_type)
    r = solve_static(s, bar_model=bar_model, subdivisions=k)
    equilibrium(r, member_loads=s.extensions["member_loads"])
    total = F_AXIAL + 0.5 * Q_END * L
    assert r.reactions[s.node_index("A")][0] == pytest.approx(-total, rel=1e-10)
    # the end sections carry all the load and none of it
    assert r.end_forces[0][:, 0] == pytest.approx([total, 0.0], abs=1e-8 * total)
    assert r.axial_force[0] == pytest.approx(_midpoint_tension(), rel=1e-10)
    assert r.axial_stress[0] == pytest.approx(_midpoint_tension() / s.area[0], rel=1e-10)
    assert r.strain[0] == pytest.approx(_midpoint_tension() / (s.E[0] * s.area[0]),
                                        rel=1e-10)


def test_midpoint_axial_force_of_a_combination(equilibrium):
    """A combination's midpoint axial force is its factor times the case's (docs/model-format.md,
    *Load cases*: the combination is the factored sum); reference: the statics of
    :func:`_midpoint_tension`, 1.5 × 900 N."""
    s = _axially_loaded("beam", cases=True)
    sol = solve_load_cases(s, subdivisions=4)
    r = sol.combinations["c"]
    case = s.extensions["load_cases"].case("axial")
    equilibrium(r, structure=s, member_loads=[ml.scaled(1.5) for ml in case.member_loads])
    assert sol.cases["axial"].axial_force[0] == pytest.approx(_midpoint_tension(), rel=1e-10)
    assert r.axial_force[0] == pytest.approx(1.5 * _midpoint_tension(), rel=1e-10)


def test_point_load_at_the_midpoint_gives_the_mean_of_both_sides(equilibrium):
    """A point axial load exactly at L/2: N jumps there, and the midpoint value is the mean
    of the two sides, (P + 0)/2 — what the mean of the end values always gave (statics of
    the member of :func:`_axially_loaded`)."""
    s = _axially_loaded("beam").with_extensions(member_loads=[
        trussfe.model.MemberLoad(0, "point", at=0.5, force=(F_AXIAL, 0.0))])
    r = solve_static(s, subdivisions=4)
    equilibrium(r, member_loads=s.extensions["member_loads"])
    assert r.axial_force[0] == pytest.approx(0.5 * F_AXIAL, rel=1e-10)


TRUSS = {
    "model": {"dimension": 2, "gravity": [0.0, -9.81]},
    "materials": {"al": {"E": 7.0e10, "density": 2700.0}},
    "sections": {"s": {"area": 3.0e-4, "Iz": 2.0e-8, "c": 0.02}},
    "nodes": {"A": [0.0, 0.0], "B": [4.0, 0.0], "C": [2.0, 1.5], "D": [2.0, 0.0]},
    "members": {m: {"nodes": [m[0], m[1]], "section": "s", "material": "al"}
                for m in ("AC", "CB", "CD", "AD", "DB")},
    "supports": {"A": ["x", "y"], "B": ["y"]},
    "loads": {"C": [100.0, -500.0]},
    "member_loads": [
        {"member": "AC", "kind": "uniform", "q": [0.0, -300.0]},
        {"member": "CB", "kind": "point", "at": 0.3, "F": [50.0, -400.0]},
        {"member": "CD", "kind": "trapezoidal", "q_start": [0.0, 100.0],
         "q_end": [20.0, -200.0], "axes": "local"},
        {"member": "AD", "kind": "point", "at": 0.7, "F": [0.0, -100.0], "axes": "local",
         "M": [30.0]},
    ],
}


@pytest.mark.parametrize("k", [2, 4, 5])
def test_pinned_beam_truss_with_member_loads_against_pynite(k, equilibrium):
    """A truss of pin-ended beams (``bar_model="pinned-beam"``) under self-weight, a joint
    load and member loads with axial components, against PyNite 3.2 (``FEModel3D``, both end
    moments released, self-weight as global distributed loads ρAg): joint displacements,
    reactions, and the axial force at each member's midpoint (``Member3D.axial(L/2)``; PyNite's
    axial force is positive in compression)."""
    pynite = pytest.importorskip("Pynite")
    s = trussfe.model_from_dict(TRUSS)
    r = solve_static(s, bar_model="pinned-beam", subdivisions=k)
    equilibrium(r, member_loads=s.extensions["member_loads"])

    from trussfe.mechanics.geometry import local_axes
    m = pynite.FEModel3D()
    for n, (x, y) in TRUSS["nodes"].items():
        m.add_node(n, x, y, 0.0)
        sup = TRUSS["supports"].get(n, [])
        # out of plane held; the node rotations too (every member end is released there)
        m.def_support(n, "x" in sup, "y" in sup, True, True, True, True)
    E, rho, A, Iz = 7.0e10, 2700.0, 3.0e-4, 2.0e-8
    m.add_material("al", E, E / 2.6, 0.3, rho)
    m.add_section("s", A, Iz, Iz, 2 * Iz)
    R = local_axes(s)
    for mid, mb in TRUSS["members"].items():
        m.add_member(mid, *mb["nodes"], "al", "s")
        m.def_releases(mid, Ryi=True, Rzi=True, Ryj=True, Rzj=True)
        m.add_member_dist_load(mid, "FY", -rho * A * 9.81, -rho * A * 9.81)
    m.add_node_load("C", "FX", 100.0)
    m.add_node_load("C", "FY", -500.0)
    for ld in TRUSS["member_loads"]:
        i = s.member_index(ld["member"])
        to_global = (lambda v: R[i].T @ np.asarray(v)) if ld.get("axes") == "local" \
            else (lambda v: np.asarray(v, float))
        Lm = s.lengths()[i]
        if ld["kind"] == "point":
            F = to_global(ld["F"])
            for c, dn in enumerate(("FX", "FY")):
                if F[c]:
                    m.add_member_pt_load(ld["member"], dn, F[c], ld["at"] * Lm)
            if "M" in ld:
                m.add_member_pt_load(ld["member"], "MZ", ld["M"][0], ld["at"] * Lm)
        else:
            q1 = to_global(ld.get("q", ld.get("q_start")))
            q2 = to_global(ld.get("q", ld.get("q_end")))
            for c, dn in enumerate(("FX", "FY")):
                if q1[c] or q2[c]:
                    m.add_member_dist_load(ld["member"], dn, q1[c], q2[c])
    m.analyze_linear(check_statics=False, check_stability=False)

    for n in TRUSS["nodes"]:
        i = s.node_index(n)
        node = m.nodes[n]
        assert r.displacements[i][:2] == pytest.approx(
            [node.DX["Combo 1"], node.DY["Combo 1"]], rel=1e-9, abs=1e-15)
    for n in ("A", "B"):
        node = m.nodes[n]
        assert r.reactions[s.node_index(n)][:2] == pytest.approx(
            [node.RxnFX["Combo 1"], node.RxnFY["Combo 1"]], rel=1e-9, abs=1e-8)
    for mid in TRUSS["members"]:
        mm = m.members[mid]
        assert r.axial_force[s.member_index(mid)] == pytest.approx(
            -mm.axial(mm.L() / 2, "Combo 1"), rel=1e-9, abs=1e-8)


def _average_tension(x0, x1, at=0.3 * L):
    """Average of N(x) over [x0, x1] by statics: N(x) = ∫_x^L q(s) ds + F_AXIAL·[x < at],
    with q(s) = Q_END·s/L (A takes every axial load, B slides)."""
    def integral_of_n(x):      # ∫_0^x N(t) dt
        tail = Q_END * (L**2 * x - x**3 / 3.0) / (2 * L)   # ∫_0^x Q_END (L² − t²)/(2L) dt
        return tail + F_AXIAL * min(x, at)
    return (integral_of_n(x1) - integral_of_n(x0)) / (x1 - x0)


@pytest.mark.parametrize("bar_model, k, at", [
    ("truss", None, 0.6), ("pinned-beam", 4, 0.3), ("pinned-beam", 4, 0.25),
    ("pinned-beam", 4, 0.5), ("pinned-beam", 5, 0.0), ("pinned-beam", 5, 1.0),
    ("pinned-beam", 3, 0.7)])
def test_element_axial_force_is_the_average_along_the_element(bar_model, k, at, equilibrium):
    """``element_axial_force``, the one axial force per element of the geometric stiffness,
    is N averaged along the element (with it the string stiffness ∫N dx/h² of a bar is
    exact).  Reference: statics of the member pinned at A and sliding at B under a point load
    at ``at``·L and a load rising linearly along it — including point loads on a station
    (0.25, 0.5 with four elements) and at the member's ends."""
    s = _axially_loaded("bar", at=at)
    r = solve_static(s, bar_model=bar_model, subdivisions=k)
    equilibrium(r, member_loads=s.extensions["member_loads"])
    x = r.fe.element_x
    expected = [_average_tension(a, b, at * L) for a, b in x]        # tension: B pulls
    got = r.element_axial_force
    assert np.allclose(got, expected, rtol=0.0, atol=1e-9 * (F_AXIAL + Q_END * L)), \
        (got, expected)


@pytest.mark.parametrize("how", ["plain", "all", "case default"])
def test_the_default_case_carries_the_models_member_loads(how):
    """A model without ``[load_cases]`` has one case, ``default``, of the loads a plain
    static analysis applies — its member loads included (docs/model-format.md, *Load
    cases*).  Reference: a cantilever of 2 m under q = 1 kN/m, support reaction qL = 2000 N
    and moment qL²/2 = 2000 N·m (global equilibrium of the cantilever), by ``static``,
    ``static(all_cases=True)`` and ``static(case="default")`` alike."""
    q, span = 1000.0, 2.0
    s = trussfe.model_from_dict({
        "model": {"dimension": 2}, "materials": {"st": {"E": 2.0e11, "G": 8.0e10}},
        "sections": {"b": {"area": 4.0e-3, "Iz": 8.0e-6, "c": 0.05}},
        "nodes": {"A": [0.0, 0.0], "B": [span, 0.0]},
        "members": {"AB": {"nodes": ["A", "B"], "section": "b", "material": "st",
                           "type": "beam"}},
        "supports": {"A": ["x", "y", "rz"]},
        "member_loads": [{"member": "AB", "kind": "uniform", "q": [0.0, -q]}]})
    r = {"plain": lambda: trussfe.static(s),
         "all": lambda: trussfe.static(s, all_cases=True).cases["default"],
         "case default": lambda: trussfe.static(s, case="default")}[how]()
    assert r.reaction[0, 1] == pytest.approx(q * span, rel=1e-12)
    moment = r.to_dict()["nodes"]["A"]["reaction_moment"]
    assert abs(moment[0]) == pytest.approx(q * span**2 / 2.0, rel=1e-12)
