# SPDX-License-Identifier: MIT
"""Load cases of 3-D frames and long trusses against an independent dense direct-stiffness
solution written here (McGuire, Gallagher & Ziemian, *Matrix Structural Analysis*, 2nd ed.:
the 12 × 12 Euler–Bernoulli frame element, the truss bar, fixed-end forces of a uniform load
and of a restrained axial strain, support displacements by partitioning, springs on the
diagonal), closed forms for an elastically held heated bar, and the statements of
docs/model-format.md (*Load cases, combinations, springs*) about combinations and envelopes.
"""
from __future__ import annotations

import json

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe.cli import main
from trussfe.fem.load_cases import solve_load_cases
from trussfe.mechanics.stress import von_mises

E, G, RHO, ALPHA = 2.1e11, 8.1e10, 7850.0, 1.1e-5
BOX = {"area": 4e-3, "Iy": 8e-6, "Iz": 5e-6, "J": 1e-5, "c": 0.1}
ROD = {"area": 3e-4, "Iy": 1e-8, "Iz": 1e-8, "J": 2e-8, "c": 0.01}
GRAVITY = [0.5, -1.0, -9.81]
NODES = {"A": [0, 0, 0], "B": [0.3, 0.2, 3], "C": [4, 1.0, 3.4], "D": [4.2, 0, 0],
         "E": [2, 3, 0]}
MEMBERS = {"AB": ("A", "B", "box", "beam"), "BC": ("B", "C", "box", "beam"),
           "CD": ("C", "D", "box", "beam"), "AC": ("A", "C", "rod", "bar"),
           "EB": ("E", "B", "rod", "bar"), "EC": ("E", "C", "rod", "bar")}
DOFS = ["x", "y", "z", "rx", "ry", "rz"]
SUPPORTS = {"A": DOFS, "D": ["x", "y", "z"], "E": ["x", "y", "z"]}
SPRINGS = {"C": {"x": 3e5, "rx": 2e4}, "D": {"rz": 5e5, "ry": 1e5}}
MASSES = {"B": 10.0, "C": 25.0}
WIND = [2000.0, -500.0, 300.0, 100.0, -50.0, 20.0]
SETTLE = {"D": {"z": -0.004, "x": 0.001}, "A": {"ry": 0.002}}
LACK = 0.5e-3                                    # AC too long, m
HEAT = {"BC": 25.0, "EC": 30.0}                  # K
INITIAL = {"AB": 1e-5}


def _frame():
    return trussfe.model_from_dict({
        "model": {"dimension": 3, "gravity": GRAVITY},
        "materials": {"st": {"E": E, "G": G, "density": RHO, "thermal_expansion": ALPHA}},
        "sections": {"box": BOX, "rod": ROD},
        "nodes": NODES,
        "members": {k: {"nodes": [a, b], "section": sec, "material": "st", "type": t}
                    for k, (a, b, sec, t) in MEMBERS.items()},
        "supports": SUPPORTS, "springs": SPRINGS,
        "masses": {"B": {"mass": MASSES["B"]}, "C": MASSES["C"]},
        "load_cases": {
            "dead": {"gravity": True},
            "wind": {"loads": {"B": WIND}},
            "settle": {"prescribed": SETTLE},
            # BC: two entries add up (30 − 5 = 25 K)
            "thermal": {"temperature": [{"members": ["BC", "EC"], "delta_T": 30.0},
                                        {"member": "BC", "delta_T": -5.0}],
                        "initial_strain": [{"member": "AB", "strain": INITIAL["AB"]}],
                        "length_error": [{"member": "AC", "delta": LACK}]}},
        "combinations": {"ULS": {"dead": 1.35, "wind": 1.5, "settle": 1.0},
                         "SLS": {"dead": 1.0, "wind": -1.0, "thermal": 1.0}}})


# ------------------------------------------------------------------ independent solver
def _axes(p1, p2):
    """Member axes (docs/fem.md, *Local axes*): y is global Z made orthogonal to x (global
    X for a vertical member), z = x × y."""
    x = (p2 - p1) / np.linalg.norm(p2 - p1)
    ref = np.array([0.0, 0.0, 1.0])
    if abs(abs(x @ ref) - 1.0) < 1e-9:
        ref = np.array([1.0, 0.0, 0.0])
    y = ref - (ref @ x) * x
    y /= np.linalg.norm(y)
    return np.array([x, y, np.cross(x, y)])


def _frame_stiffness(sec, L):
    """12 × 12 local stiffness, DOFs [u, v, w, θx, θy, θz] at each end (McGuire eq. 4.34)."""
    k = np.zeros((12, 12))
    a, t = E * sec["area"] / L, G * sec["J"] / L
    k[np.ix_([0, 6], [0, 6])] = a * np.array([[1, -1], [-1, 1]])
    k[np.ix_([3, 9], [3, 9])] = t * np.array([[1, -1], [-1, 1]])
    for dofs, I, s in (([1, 5, 7, 11], sec["Iz"], 1.0), ([2, 4, 8, 10], sec["Iy"], -1.0)):
        c = E * I / L**3
        kb = c * np.array([[12, 6 * L, -12, 6 * L], [6 * L, 4 * L * L, -6 * L, 2 * L * L],
                           [-12, -6 * L, 12, -6 * L], [6 * L, 2 * L * L, -6 * L, 4 * L * L]])
        sign = np.array([1.0, s, 1.0, s])             # θy = −dw/dx
        k[np.ix_(dofs, dofs)] = kb * np.outer(sign, sign)
    return k


def _direct_stiffness(case):
    """Displacements (node, 6), reactions (node, 6; spring forces −k u included) and end
    section forces of every member ({id: (start[6], end[6])}, member axes) of one case."""
    ids = list(NODES)
    X = {n: np.array(p, float) for n, p in NODES.items()}
    n = 6 * len(ids)
    at = lambda node, d: 6 * ids.index(node) + d
    K, F = np.zeros((n, n)), np.zeros(n)
    g = np.array(GRAVITY) if case.get("gravity") else None
    eps0 = case.get("eps0", {})
    elements = {}
    for mid, (a, b, sec_name, kind) in MEMBERS.items():
        sec = BOX if sec_name == "box" else ROD
        L = np.linalg.norm(X[b] - X[a])
        R = _axes(X[a], X[b])
        fixed_end = np.zeros(12 if kind == "beam" else 2)   # forces on the held element
        N0 = -E * sec["area"] * eps0.get(mid, 0.0)          # restrained axial force
        if kind == "beam":
            kl = _frame_stiffness(sec, L)
            T = np.kron(np.eye(4), R)
            dofs = [at(a, d) for d in range(6)] + [at(b, d) for d in range(6)]
            if g is not None:                               # uniform self-weight
                qx, qy, qz = R @ (RHO * sec["area"] * g)
                eq = np.zeros(12)
                eq[[0, 6]], eq[[1, 7]], eq[[2, 8]] = qx * L / 2, qy * L / 2, qz * L / 2
                eq[5], eq[11] = qy * L * L / 12, -qy * L * L / 12
                eq[4], eq[10] = -qz * L * L / 12, qz * L * L / 12
                fixed_end -= eq
            fixed_end[[0, 6]] += [-N0, N0]
        else:
            kl = E * sec["area"] / L * np.array([[1.0, -1.0], [-1.0, 1.0]])
            T = np.zeros((2, 6))
            T[0, :3], T[1, 3:] = R[0], R[0]
            dofs = [at(a, d) for d in range(3)] + [at(b, d) for d in range(3)]
            if g is not None:                               # half the weight at each end
                w = RHO * sec["area"] * L * g / 2
                F[dofs[:3]] += w
                F[dofs[3:]] += w
            fixed_end += [-N0, N0]
        K[np.ix_(dofs, dofs)] += T.T @ kl @ T
        F[dofs] -= T.T @ fixed_end
        elements[mid] = (kl, T, dofs, fixed_end)
    if g is not None:
        for node, m in MASSES.items():
            F[at(node, 0):at(node, 3)] += m * g
    for node, load in case.get("loads", {}).items():
        F[at(node, 0):at(node, 6)] += load
    ks = np.zeros(n)
    for node, table in SPRINGS.items():
        for d, k in table.items():
            ks[at(node, DOFS.index(d))] = k
    K += np.diag(ks)
    fixed = np.zeros(n, bool)
    for node, held in SUPPORTS.items():
        fixed[[at(node, DOFS.index(d)) for d in held]] = True
    u = np.zeros(n)
    for node, table in case.get("prescribed", {}).items():
        for d, v in table.items():
            u[at(node, DOFS.index(d))] = v
    inert = ~fixed & ~np.any(K != 0.0, axis=1)             # rotations of bar-only nodes
    free = ~fixed & ~inert
    u[free] = np.linalg.solve(K[np.ix_(free, free)],
                              F[free] - K[np.ix_(free, ~free)] @ u[~free])
    reactions = np.where(fixed, K @ u - F, 0.0) - ks * u
    ends = {}
    for mid, (kl, T, dofs, fixed_end) in elements.items():
        fe = kl @ (T @ u[dofs]) + fixed_end                 # forces on the element
        h = fe.size // 2
        ends[mid] = (-fe[:h], fe[h:])
    return u.reshape(-1, 6), reactions.reshape(-1, 6), ends


def _reference_cases():
    X = {n: np.array(p, float) for n, p in NODES.items()}
    eps0 = {m: ALPHA * dT for m, dT in HEAT.items()}
    eps0["AB"] = INITIAL["AB"]
    eps0["AC"] = LACK / np.linalg.norm(X["C"] - X["A"])
    return {"dead": {"gravity": True}, "wind": {"loads": {"B": WIND}},
            "settle": {"prescribed": SETTLE}, "thermal": {"eps0": eps0}}


def _assert_same(result, u, r, ends, label):
    scale_u = np.abs(u).max()
    scale_f = np.abs(r).max()
    assert_allclose(result.displacements, u, rtol=0, atol=1e-11 * scale_u, err_msg=label)
    assert_allclose(result.reactions, r, rtol=0, atol=1e-11 * scale_f, err_msg=label)
    for i, mid in enumerate(MEMBERS):
        start, end = ends[mid]
        got = result.end_forces[i][:, :start.size]
        assert_allclose(got, [start, end], rtol=0, atol=1e-11 * scale_f,
                        err_msg=f"{label} {mid}")


@pytest.mark.parametrize("subdivisions", [1, 3])
def test_three_dimensional_frame_cases_and_combinations(subdivisions):
    """Every kind of case on a 3-D frame with bars, translational and rotational springs and
    a moved and turned support — self-weight of members and masses under an oblique gravity,
    a nodal force and moment, a settlement, a temperature change, an initial strain and a
    lack of fit — and two combinations agree with the dense direct-stiffness solution (end
    section forces, displacements, reactions with the springs' −k u)."""
    sol = solve_load_cases(_frame(), subdivisions=subdivisions)
    ref = {name: _direct_stiffness(case) for name, case in _reference_cases().items()}
    for name, (u, r, ends) in ref.items():
        _assert_same(sol.cases[name], u, r, ends, name)
    for name, factors in sol.factors.items():
        u = sum(f * ref[c][0] for c, f in factors.items())
        r = sum(f * ref[c][1] for c, f in factors.items())
        ends = {m: tuple(sum(f * ref[c][2][m][e] for c, f in factors.items()) for e in (0, 1))
                for m in MEMBERS}
        _assert_same(sol.combinations[name], u, r, ends, name)


def test_three_dimensional_frame_global_equilibrium():
    """Statics: the loads of each case (nodal force and moment, the weight of members at
    their midpoints and of the masses) and the reactions (springs included) have zero
    resultant force and zero resultant moment about the origin; a settlement or an imposed
    strain sets up reactions that balance among themselves."""
    sol = solve_load_cases(_frame(), subdivisions=2)
    X = np.array(list(NODES.values()), float)
    g = np.array(GRAVITY)
    for name, res in sol.cases.items():
        F = res.reactions[:, :3].copy()
        M = res.reactions[:, 3:].copy()
        if name == "wind":
            F[1] += WIND[:3]
            M[1] += WIND[3:]
        forces = [F]
        points = [X]
        if name == "dead":
            w, p = [], []
            for a, b, sec, _ in MEMBERS.values():
                L = np.linalg.norm(X[list(NODES).index(b)] - X[list(NODES).index(a)])
                w.append(RHO * (BOX if sec == "box" else ROD)["area"] * L * g)
                p.append(0.5 * (X[list(NODES).index(a)] + X[list(NODES).index(b)]))
            for node, m in MASSES.items():
                w.append(m * g)
                p.append(X[list(NODES).index(node)])
            forces.append(np.array(w))
            points.append(np.array(p))
        total_f = sum(f.sum(axis=0) for f in forces)
        total_m = M.sum(axis=0) + sum(np.cross(p, f).sum(axis=0)
                                      for p, f in zip(points, forces))
        scale = np.abs(res.reactions).max()
        assert_allclose(total_f, 0.0, atol=1e-10 * scale, err_msg=name)
        assert_allclose(total_m, 0.0, atol=1e-10 * scale * 5.0, err_msg=name)


# ------------------------------------------------------------------ the bars' band
def _long_truss(panels):
    nodes, members = {}, {}
    for i in range(panels + 1):
        nodes[f"b{i}"], nodes[f"t{i}"] = [float(i), 0.0], [float(i), 1.0]
        members[f"V{i}"] = (f"b{i}", f"t{i}")
    for i in range(panels):
        members[f"B{i}"] = (f"b{i}", f"b{i + 1}")
        members[f"T{i}"] = (f"t{i}", f"t{i + 1}")
        members[f"D{i}"] = (f"b{i}", f"t{i + 1}")
    mid = f"b{panels // 2}"
    s = trussfe.model_from_dict({
        "model": {"dimension": 2, "gravity": [0.0, -9.81]},
        "materials": {"st": {"E": 2e11, "density": 7850.0, "thermal_expansion": 1.2e-5}},
        "sections": {"s": {"area": 1e-4}},
        "nodes": nodes,
        "members": {k: {"nodes": list(v), "section": "s", "material": "st"}
                    for k, v in members.items()},
        "supports": {"b0": ["x", "y"], f"b{panels}": ["y"], mid: ["y"]},
        "load_cases": {
            "dead": {"gravity": True},
            "hot": {"temperature": [{"members": [f"T{i}" for i in range(panels)],
                                     "delta_T": 20.0}],
                    "length_error": [{"member": "D3", "delta": 1e-3}]},
            "settle": {"prescribed": {mid: {"y": -0.01}}}},
        "combinations": {"C": {"dead": 1.2, "hot": 1.0, "settle": 0.5}}})
    return s, nodes, members, mid


def _truss_reference(nodes, members, supports, case, E=2e11, A=1e-4, rho=7850.0):
    """Dense direct stiffness of a plane truss: (u (node, 2), axial forces)."""
    ids = list(nodes)
    X = np.array([nodes[k] for k in ids])
    n = 2 * len(ids)
    K, F = np.zeros((n, n)), np.zeros(n)
    data = []
    for mid, (a, b) in members.items():
        ia, ib = ids.index(a), ids.index(b)
        d = X[ib] - X[ia]
        L = np.linalg.norm(d)
        c = np.concatenate([-d / L, d / L])
        dofs = [2 * ia, 2 * ia + 1, 2 * ib, 2 * ib + 1]
        K[np.ix_(dofs, dofs)] += E * A / L * np.outer(c, c)
        if case.get("gravity"):
            F[[2 * ia + 1, 2 * ib + 1]] += -9.81 * rho * A * L / 2
        N0 = -E * A * case.get("eps0", {}).get(mid, 0.0)
        F[dofs] -= N0 * c                   # the joints take +N0 e at the start, −N0 e at the end
        data.append((dofs, c, L, N0))
    fixed = np.zeros(n, bool)
    for node, held in supports.items():
        for d in held:
            fixed[2 * ids.index(node) + "xy".index(d)] = True
    u = np.zeros(n)
    for node, table in case.get("prescribed", {}).items():
        for d, v in table.items():
            u[2 * ids.index(node) + "xy".index(d)] = v
    u[~fixed] = np.linalg.solve(K[np.ix_(~fixed, ~fixed)],
                                F[~fixed] - K[np.ix_(~fixed, fixed)] @ u[fixed])
    N = np.array([E * A / L * (c @ u[dofs]) + N0 for dofs, c, L, N0 in data])
    return u.reshape(-1, 2), N


def test_truss_solved_on_the_bars_band_with_imposed_strains_and_settlement():
    """A plain truss factorised on the band of its bars (no global K; the bars' own force
    recovery): temperature, lack of fit and a settled support agree with the dense direct
    stiffness solution, and so does their combination."""
    panels = 20
    s, nodes, members, mid = _long_truss(panels)
    sol = solve_load_cases(s, backend="banded")
    assert sol.cases["hot"].backend == "banded"
    supports = {"b0": "xy", f"b{panels}": "y", mid: "y"}
    eps0 = {f"T{i}": 1.2e-5 * 20.0 for i in range(panels)}
    eps0["D3"] = 1e-3 / np.sqrt(2.0)
    cases = {"dead": {"gravity": True}, "hot": {"eps0": eps0},
             "settle": {"prescribed": {mid: {"y": -0.01}}}}
    ref = {k: _truss_reference(nodes, members, supports, c) for k, c in cases.items()}
    order = list(members)
    perm = [order.index(m) for m in s.member_ids]
    for name, (u, N) in ref.items():
        r = sol.cases[name]
        assert_allclose(r.displacements[:, :2], u, rtol=0, atol=1e-10 * np.abs(u).max())
        assert_allclose(r.axial_force, N[perm], rtol=0, atol=1e-10 * np.abs(N).max())
    combo = sol.combinations["C"]
    N = sum(f * ref[c][1] for c, f in sol.factors["C"].items())
    assert_allclose(combo.axial_force, N[perm], rtol=0, atol=1e-10 * np.abs(N).max())


# ------------------------------------------------------------------ springs, closed forms
def test_heated_bar_held_by_a_spring():
    """A bar fixed at A and held at B by a spring k along it, warmed by ΔT: springs in
    series — the free expansion αΔT L shares between the bar and the spring, u_B =
    αΔT L · k_b/(k_b + k) with k_b = EA/L, N = −k u_B; the spring's force on the structure,
    the reaction at B, is −k u_B (docs/model-format.md, *springs*)."""
    L, A, k, dT = 2.0, 1e-4, 4e6, 40.0
    s = trussfe.model_from_dict({
        "model": {"dimension": 2},
        "materials": {"st": {"E": 2e11, "thermal_expansion": 1.2e-5}},
        "sections": {"s": {"area": A}},
        "nodes": {"A": [0.0, 0.0], "B": [L, 0.0]},
        "members": {"AB": {"nodes": ["A", "B"], "section": "s", "material": "st"}},
        "supports": {"A": ["x", "y"], "B": ["y"]}, "springs": {"B": {"x": k}},
        "load_cases": {"hot": {"temperature": [{"member": "AB", "delta_T": dT}]}}})
    r = trussfe.static(s, case="hot")
    kb = 2e11 * A / L
    uB = 1.2e-5 * dT * L * kb / (kb + k)
    assert_allclose(r.displacement[1, 0], uB, rtol=1e-12)
    assert_allclose(r.axial_force, [-k * uB], rtol=1e-12)
    assert_allclose(r.reaction[:, 0], [k * uB, -k * uB], rtol=1e-12)


# ------------------------------------------------------------------ combinations, envelope
def test_combination_von_mises_is_that_of_the_summed_section_forces():
    """docs/model-format.md: a combination's von Mises stresses are computed from the summed
    section forces (Lacy eqs. 2.24, 2.25 of the summed N, V, M), which differ from the sum
    of the cases' stresses."""
    s = _frame()
    sol = solve_load_cases(s, subdivisions=3)
    for name, factors in sol.factors.items():
        F = sum(f * sol.cases[c].section_forces for c, f in factors.items())
        col = lambda a: a[:, None]
        vm = von_mises(F[..., 0], F[..., 1], F[..., 2], F[..., 4], F[..., 5],
                       col(s.area), col(s.Iy), col(s.Iz), col(s.c), col(s.c), False)
        largest = np.fmax.reduce(np.fmax(vm.s1, vm.s2), axis=1)
        assert_allclose(sol.combinations[name].max_von_mises, largest, rtol=1e-12)
        summed = sum(f * sol.cases[c].max_von_mises for c, f in factors.items())
        assert np.abs(summed - largest).max() > 0.1 * largest.max()


def test_envelope_over_cases_without_combinations(tmp_path):
    """Without [combinations] the envelope runs over the cases (docs/json.md, *static*): the
    largest and smallest member force, end force and reaction component of the cases, each
    naming its case."""
    p = tmp_path / "m.toml"
    p.write_text("""\
[model]
dimension = 2

[materials.st]
E = 2.0e11
thermal_expansion = 1.2e-5

[sections.s]
area = 1.0e-4

[nodes]
A = [0.0, 0.0]
B = [1.0, 1.0]
C = [2.0, 0.0]

[members]
AB = { nodes = ["A", "B"], section = "s", material = "st" }
BC = { nodes = ["B", "C"], section = "s", material = "st" }
AC = { nodes = ["A", "C"], section = "s", material = "st" }

[supports]
A = ["x", "y"]
C = ["x", "y"]

[springs]
B = { x = 1.0e6 }

[load_cases.push]
loads = { B = [1000.0, -400.0] }

[load_cases.pull]
loads = { B = [-300.0, 800.0] }

[load_cases.hot]
temperature = [ { member = "AC", delta_T = 10.0 } ]
""")
    out = tmp_path / "r.json"
    assert main(["static", str(p), "--json", str(out)]) == 0
    doc = json.loads(out.read_text())
    env = doc["envelope"]
    assert env["over"] == "cases" and env["names"] == ["push", "pull", "hot"]
    names = env["names"]
    for mid in ("AB", "BC", "AC"):
        N = [doc["cases"][n]["members"][mid]["axial_force"] for n in names]
        e = env["members"][mid]["axial_force"]
        assert (e["max"], e["max_by"]) == (max(N), names[int(np.argmax(N))])
        assert (e["min"], e["min_by"]) == (min(N), names[int(np.argmin(N))])
    for node in ("A", "B", "C"):
        R = np.array([doc["cases"][n]["nodes"][node]["reaction"] for n in names])
        e = env["nodes"][node]["reaction"]
        assert e["max"] == R.max(axis=0).tolist() and e["min"] == R.min(axis=0).tolist()
        assert e["max_by"] == [names[i] for i in R.argmax(axis=0)]
    # the spring at B pushes back: −k u_B in x under the push
    uB = doc["cases"]["push"]["nodes"]["B"]["displacement"][0]
    assert doc["cases"]["push"]["nodes"]["B"]["reaction"][0] == pytest.approx(-1.0e6 * uB,
                                                                               rel=1e-12)
    # the hot member AC, held between two pinned supports, carries −EAαΔT
    assert doc["cases"]["hot"]["members"]["AC"]["axial_force"] == pytest.approx(
        -2e11 * 1e-4 * 1.2e-5 * 10.0, rel=1e-12)


# ------------------------------------------------------------------ errors name the file
PIN_TRUSS = """\
[model]
dimension = 2
[materials.st]
E = 2.0e11
[sections.s]
area = 1.0e-4
[nodes]
A = [0.0, 0.0]
B = [1.0, 1.0]
C = [2.0, 0.0]
[members]
AB = { nodes = ["A", "B"], section = "s", material = "st" }
BC = { nodes = ["B", "C"], section = "s", material = "st" }
AC = { nodes = ["A", "C"], section = "s", material = "st" }
[supports]
A = ["x", "y", "rz"]
C = ["y"]
[load_cases.wind]
"""


@pytest.mark.parametrize("case, item", [
    ("loads = { B = [500.0, 0.0, 30.0] }", "load_cases.wind.loads.B"),
    ("prescribed = { A = { rz = 0.01 } }", "load_cases.wind.prescribed.A"),
])
def test_a_case_acting_on_a_pin_joints_rotation_names_the_file_and_the_case(
        tmp_path, capsys, case, item):
    """docs/bad-input.md: one line naming the model file and the item.  A moment or a
    prescribed rotation of a case at a pin joint is found once the members are discretised;
    the line names the file and the case's own item."""
    f = tmp_path / "pin.toml"
    f.write_text(PIN_TRUSS + case + "\n")
    assert main(["static", str(f)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"trussfe: error: {f}: {item}: ") and err.count("\n") == 1


def test_a_moment_at_a_pin_joint_in_loads_names_the_file(tmp_path, capsys):
    """The same moment at a pin joint given in ``[loads]`` of a model without cases: one line
    naming the model file and ``loads.B``."""
    f = tmp_path / "pin.toml"
    f.write_text(PIN_TRUSS.replace("[load_cases.wind]\n", "[loads]\nB = [500.0, 0.0, 30.0]\n"))
    assert main(["static", str(f)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"trussfe: error: {f}: loads.B: a moment") and err.count("\n") == 1
