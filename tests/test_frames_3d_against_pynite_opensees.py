# SPDX-License-Identifier: MIT
"""Irregular 3-D frames against independent solvers: PyNite (``Pynite.FEModel3D``) and
OpenSeesPy (``elasticBeamColumn`` with ``-releasey``/``-releasez``, ``ElasticTimoshenkoBeam``,
``Truss``).  Skipped when the solver is not installed.

The frames mix sections with Iy ≠ Iz and torsion, members along the global vertical axis
(default local y = global X) and with orientation vectors, releases of one bending moment,
of both, of torsion, members free to twist at both ends, ball joints (bars and released
ends only), a twist held by a rotational support at a ball joint, pin-jointed bars,
Timoshenko sections, nodal forces and moments, member loads (uniform, trapezoidal, point
forces and couples, local and global axes), self-weight, springs and supports of every kind,
rotations alone included.  Every trussfe result here is in global equilibrium
(tests/conftest.py).

Conversions, not fits: each reference member is built on the member axes of docs/fem.md
(*Local axes*; PyNite's ``rotation`` angle and OpenSees' ``vecxz`` = local z are set from
them, and PyNite's axes are checked against them); both programs report the forces the
joints exert on an element in member axes, so the section force (docs/fem.md, *Sign
conventions*) is minus that at an element's start and equal to it at its end.  Each
reference member is cut into pieces at trussfe's stations, so the pieces' end forces are the
section forces there; loads are cut over the pieces here (PyNite 3.2 interpolates a linearly
varying load wrongly when it splits a member at an interior node itself).  trussfe's
implicit rules are written out explicitly in the references: a bending-released end at a
ball joint transmits no torsion (docs/fem.md, *Releases*), and a member free to twist at
both ends has its start twist held.
"""
from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from trussfe.api.model import model_from_dict
from trussfe.fem.load_cases import solve_load_cases
from trussfe.fem.static import solve_static, static_json

DOFS = ("x", "y", "z", "rx", "ry", "rz")


# ------------------------------------------------------------------------------- frames
def frame_a(timoshenko: bool = False, torsion_releases: bool = True) -> dict:
    """Two storeys and a cantilever on perturbed (seeded) coordinates, braced by bars."""
    rng = np.random.default_rng(7)
    p = lambda s=0.3: rng.uniform(-s, s)
    N = {"A0": [0.0, 0.0, 0.0], "A1": [5.0 + p(), p(), 0.0],
         "A2": [5.0 + p(), 4.0 + p(), p(0.2)], "A3": [p(), 4.0 + p(), 0.0]}
    N["B0"] = [0.0, 0.0, 3.0 + p()]                                   # A0-B0 vertical
    N["B1"] = [N["A1"][0] + p(), N["A1"][1] + p(), 3.0 + p()]
    N["B2"] = [N["A2"][0], N["A2"][1], 3.2 + p()]                     # B2-A2 vertical, down
    N["B3"] = [N["A3"][0] + p(), N["A3"][1] + p(), 3.0 + p()]
    N["C0"] = [N["B0"][0] + p(), N["B0"][1] + p(), 6.0 + p()]
    N["C1"] = [N["B1"][0], N["B1"][1], 6.1 + p()]                     # B1-C1 vertical
    N["D"] = [N["C1"][0] + 1.5 + p(), N["C1"][1] + 1.0 + p(), N["C1"][2] + p()]
    col = {"area": 6.0e-3, "Iy": 4.0e-5, "Iz": 1.3e-5, "J": 6.0e-7, "c": 0.1}
    bm = {"area": 5.0e-3, "Iy": 2.2e-5, "Iz": 6.5e-5, "J": 9.0e-7, "c": 0.12}
    secs = {"col": col, "bm": bm, "col_eb": dict(col), "bm_eb": dict(bm),
            "rod": {"area": 8.0e-4, "Iy": 5.1e-8, "Iz": 5.1e-8, "c": 0.016}}
    if timoshenko:            # the released members keep the Euler-Bernoulli sections
        secs["col"] = dict(col, shear_area_y=2.0e-3, shear_area_z=3.5e-3)
        secs["bm"] = dict(bm, shear_area_y=1.2e-3, shear_area_z=2.4e-3)
    B = lambda a, b, s="bm", **kw: dict(nodes=[a, b], section=s + ("_eb" if "releases" in kw
                                                                     else ""),
                                        material="st", type="beam", **kw)
    T = lambda a, b: {"nodes": [a, b], "section": "rod", "material": "st"}
    M = {
        "c0": B("A0", "B0", "col"),
        "c1": B("A1", "B1", "col", orientation=[0.3, 1.0, 0.2]),
        "c2": B("B2", "A2", "col", orientation=[1.0, 1.0, 0.0]),
        "c3": B("A3", "B3", "col"),
        "c4": B("B0", "C0", "col", orientation=[-0.2, 1.0, 0.4]),
        "c5": B("B1", "C1", "col"),
        "b01": B("B0", "B1"),
        "b12": B("B1", "B2", releases={"start": ["mz"]}),
        "b23": B("B2", "B3", releases={"end": ["my", "t"] if torsion_releases else ["my"]}),
        "b30": B("B3", "B0", orientation=[0.0, 0.3, 1.0],
                 releases={"end": ["t"]} if torsion_releases else {"start": ["mz"]}),
        "g01": B("C0", "C1", releases={"start": ["bending"]}),
        "cant": B("C1", "D", orientation=[0.2, -0.4, 1.0]),
        "br1": T("A1", "B0"), "br2": T("A3", "B2"), "br3": T("B0", "B2"), "br4": T("C0", "B1"),
    }
    point = {"kind": "point"}
    ML = [
        {"member": "b01", "kind": "uniform", "q": [0.0, 0.0, -6.0e3]},
        {"member": "b23", **point, "at": 0.37, "F": [200.0, -3.0e3, 1.5e3],
         "M": [400.0, -300.0, 700.0], "axes": "local"},
        {"member": "c3", **point, "at": 0.62, "F": [1.5e3, -2.0e3, 300.0],
         "M": [0.0, 250.0, -150.0]},
        {"member": "c0", "kind": "uniform", "q": [800.0, 0.0, 0.0]},
        {"member": "c2", "kind": "uniform", "q": [0.0, -600.0, 200.0], "axes": "local"},
        {"member": "g01", **point, "at": 0.81, "F": [0.0, 0.0, -2.0e3]},
    ]
    if not timoshenko:        # OpenSees takes uniform loads only; loaded bars: PyNite
        ML += [
            {"member": "b12", "kind": "trapezoidal", "q_start": [0.0, -2.0e3, 1.0e3],
             "q_end": [300.0, -5.0e3, -1.5e3], "axes": "local"},
            {"member": "b30", "kind": "trapezoidal", "q_start": [1.0e3, 0.0, -2.0e3],
             "q_end": [-500.0, 800.0, -4.0e3]},
            {"member": "cant", "kind": "trapezoidal", "q_start": [0.0, -1.0e3, -500.0],
             "q_end": [0.0, 0.0, -1.5e3], "axes": "local"},
            {"member": "br3", "kind": "uniform", "q": [0.0, 0.0, -300.0]},
            {"member": "br1", **point, "at": 0.4, "F": [0.0, 200.0, -400.0]},
        ]
    return {"model": {"dimension": 3, "gravity": [0.0, 0.0, -9.81]},
            "materials": {"st": {"E": 2.1e11, "G": 8.1e10, "density": 7850.0}},
            "sections": secs, "nodes": N, "members": M,
            "supports": {"A0": list(DOFS), "A1": ["x", "y", "z"],
                         "A2": ["x", "y", "z", "rx", "ry"], "A3": ["z", "rx", "ry", "rz"],
                         "C0": ["rz"]},
            "loads": {"B1": [3.0e3, -1.5e3, -4.0e3, 500.0, -800.0, 1.2e3],
                      "C0": [-2.0e3, 1.0e3, 0.0, 0.0, 600.0, 0.0],
                      "D": [500.0, 800.0, -2.5e3, 300.0, 0.0, -400.0],
                      "B3": [1.0e3, 2.0e3, 0.0, 0.0, 0.0, 0.0]},
            "member_loads": ML}


def frame_b() -> dict:
    """Ball joints (P: bars and bending-released ends; Q: the same with its rotation about
    the global X axis, along EQ, supported), a member free to twist at both ends (EF),
    springs on translations and a rotation, supports on rotations alone (D)."""
    rng = np.random.default_rng(11)
    p = lambda s=0.25: rng.uniform(-s, s)
    N = {"A": [0.0, 0.0, 0.0], "B": [4.0 + p(), p(), 0.0], "C": [4.0 + p(), 3.5 + p(), 0.0],
         "D": [0.0, 0.0, 2.8 + p()], "E": [4.0 + p(), p(), 3.0 + p()],
         "F": [4.0 + p(), 3.5 + p(), 3.1 + p()], "P": [2.0 + p(), 4.5 + p(), 1.5 + p()]}
    N["Q"] = [7.0, N["E"][1], N["E"][2]]
    Bm = lambda a, b, s="box", **kw: dict(nodes=[a, b], section=s, material="st",
                                          type="beam", **kw)
    T = lambda a, b: {"nodes": [a, b], "section": "rod", "material": "st"}
    return {
        "model": {"dimension": 3, "gravity": [0.0, 0.0, -9.81]},
        "materials": {"st": {"E": 2.0e11, "G": 7.7e10, "density": 7850.0}},
        "sections": {"I": {"area": 5.4e-3, "Iy": 5.8e-5, "Iz": 4.2e-6, "J": 2.0e-7, "c": 0.11},
                     "box": {"area": 4.0e-3, "Iy": 1.1e-5, "Iz": 2.3e-5, "J": 2.6e-5,
                             "c": 0.08},
                     "rod": {"area": 6.0e-4, "Iy": 2.9e-8, "Iz": 2.9e-8, "c": 0.014}},
        "nodes": N,
        "members": {
            "AD": Bm("A", "D", "I"),
            "BE": Bm("B", "E", "I", orientation=[1.0, 0.2, 0.0]),
            "CF": Bm("C", "F", "I", orientation=[0.0, 1.0, 0.0]),
            "DE": Bm("D", "E"),
            "EF": Bm("E", "F", releases={"start": ["t"], "end": ["torsion", "my"]}),
            "FD": Bm("F", "D", "I", orientation=[0.1, 0.0, 1.0], releases={"end": ["mz"]}),
            "FP": Bm("F", "P", releases={"end": ["bending"]}),
            "DP": Bm("D", "P", releases=["end"]),
            "AP": T("A", "P"), "CP": T("C", "P"), "BP": T("B", "P"),
            "EQ": Bm("E", "Q", releases={"end": ["bending"]}),
            "QB": T("Q", "B"), "QC": T("Q", "C"), "AE": T("A", "E")},
        "supports": {"A": ["x", "y", "z"], "B": list(DOFS), "C": ["x", "y", "z", "ry"],
                     "Q": ["z", "rx"], "D": ["rx", "ry"]},
        "springs": {"Q": {"x": 4.0e6, "y": 2.5e6}, "F": {"rz": 3.0e6, "x": 1.0e6}},
        "loads": {"E": [2.0e3, -1.0e3, -3.0e3, 0.0, 500.0, -900.0],
                  "F": [-1.0e3, 2.5e3, -2.0e3, 400.0, 0.0, 0.0],
                  "P": [500.0, -700.0, -1.5e3], "Q": [0.0, 1.2e3, -2.0e3]},
        "member_loads": [
            {"member": "DE", "kind": "trapezoidal", "q_start": [0.0, -1.0e3, 400.0],
             "q_end": [200.0, -3.0e3, 0.0], "axes": "local"},
            {"member": "FP", "kind": "uniform", "q": [0.0, 300.0, -1.2e3]},
            {"member": "EQ", "kind": "point", "at": 0.45, "F": [0.0, -800.0, -1.0e3],
             "M": [350.0, 0.0, 0.0], "axes": "local"},
            {"member": "EF", "kind": "point", "at": 0.3, "F": [0.0, 0.0, -2.0e3]},
            {"member": "AD", "kind": "trapezoidal", "q_start": [600.0, 0.0, 0.0],
             "q_end": [0.0, 0.0, 0.0]}]}


# ------------------------------------------------------------------- model, as read here
def member_axes(xa, xb, orientation=None):
    """Length and member axes (rows x, y, z) by the rule of docs/fem.md, *Local axes*."""
    d = np.asarray(xb, float) - np.asarray(xa, float)
    L = float(np.linalg.norm(d))
    ex = d / L
    ref = np.asarray(orientation, float) if orientation is not None else \
        np.array([1.0, 0.0, 0.0]) if abs(ex[2]) > 1 - 1e-9 else np.array([0.0, 0.0, 1.0])
    ey = ref - (ref @ ex) * ex
    ey /= np.linalg.norm(ey)
    return L, np.array([ex, ey, np.cross(ex, ey)])


def released(member) -> list:
    """``[[my, mz, t] at the start, [my, mz, t] at the end]`` of a beam's releases."""
    out = [[False] * 3, [False] * 3]
    rel = member.get("releases") or {}
    if isinstance(rel, list):
        rel = {end: ["bending"] for end in rel}
    for end, names in rel.items():
        e = 0 if end == "start" else 1
        for w in names:
            out[e][0] |= w in ("bending", "all", "my")
            out[e][1] |= w in ("bending", "all", "mz")
            out[e][2] |= w in ("t", "torsion", "all")
    return out


def members_of(model, pinned_beam=False):
    """Per member: ends, length, axes, section, material, type, releases, and its loads in
    member axes: distributed ``(q1, q2)`` over the whole member (self-weight of frames
    included) and point ``(x, F, M)``; and the weight lumped at the joints (truss bars)."""
    X = model["nodes"]
    g = np.asarray(model["model"].get("gravity", [0.0, 0.0, 0.0]), float)
    out, lumped = {}, {}
    for k, m in model["members"].items():
        a, b = m["nodes"]
        L, R = member_axes(X[a], X[b], m.get("orientation"))
        sec, mat = model["sections"][m["section"]], model["materials"][m["material"]]
        beam = m.get("type", "bar") == "beam"
        weight = mat.get("density", 0.0) * sec["area"] * g
        d = {"a": a, "b": b, "L": L, "R": R, "sec": sec, "mat": mat, "beam": beam,
             "dist": [], "pts": [],
             "rel": released(m) if beam else [[True, True, False], [True, True, True]]}
        if beam or pinned_beam:
            d["dist"].append((R @ weight, R @ weight))
        else:
            for n in (a, b):
                lumped[n] = lumped.get(n, 0.0) + 0.5 * L * weight
        out[k] = d
    for ld in model.get("member_loads", []):
        d = out[ld["member"]]
        tr = (lambda v: np.asarray(v, float)) if ld.get("axes") == "local" else \
            (lambda v, R=d["R"]: R @ np.asarray(v, float))
        if ld["kind"] == "uniform":
            d["dist"].append((tr(ld["q"]), tr(ld["q"])))
        elif ld["kind"] == "trapezoidal":
            d["dist"].append((tr(ld["q_start"]), tr(ld["q_end"])))
        else:
            d["pts"].append((ld["at"] * d["L"], tr(ld["F"]), tr(ld.get("M", [0.0] * 3))))
    # trussfe's implicit rules, written out: the joints with rotations (a beam end rigid in
    # bending), the torsion of a bending-released end at a ball joint (none, unless a
    # support holds the rotation about the member axis), the start twist of a member free
    # to twist at both ends (held)
    rigid = {d[e] for d in out.values() if d["beam"]
             for i, e in enumerate("ab") if not (d["rel"][i][0] and d["rel"][i][1])}
    for d in out.values():
        if not d["beam"]:
            continue
        for i, e in enumerate("ab"):
            sup = set(model.get("supports", {}).get(d[e], []))
            held = all(abs(d["R"][0, c]) < 1e-9 or r in sup
                       for c, r in enumerate(("rx", "ry", "rz")))
            if d["rel"][i][0] and d["rel"][i][1] and d[e] not in rigid and not held:
                d["rel"][i][2] = True
        if d["rel"][0][2] and d["rel"][1][2]:
            d["rel"][0][2] = False
    return out, lumped, rigid


def pieces(d, cuts):
    """The loads of one member cut at ``cuts`` (m from its start): per piece its linearly
    varying loads ``(q_start, q_end)`` and point loads ``(x, F, M)`` relative to the piece;
    a point load on a cut goes to the piece that ends there (the next piece's start is the
    section just after it)."""
    out = []
    for a, b in itertools.pairwise(cuts):
        q = [(q1 + (q2 - q1) * a / d["L"], q1 + (q2 - q1) * b / d["L"]) for q1, q2 in d["dist"]]
        pl = [(x - a, F, M) for x, F, M in d["pts"] if a < x <= b or x == a == 0.0]
        out.append((q, pl))
    return out


def trussfe_solution(model, k=4, bar_model="truss"):
    r = solve_static(model_from_dict(model), subdivisions=k, bar_model=bar_model)
    s = r.structure
    return r, s, {n: r.displacements[s.node_index(n)] for n in model["nodes"]}, \
        {n: r.reactions[s.node_index(n)] for n in model["nodes"]}


# ------------------------------------------------------------------------------ PyNite
def pynite_solution(model, cuts=None, pinned_beam=False):
    """PyNite: displacements, reactions (global) and the section forces at the cuts of
    every member (member axes); ``cuts``: member → interior positions (default quarter
    points)."""
    pynite = pytest.importorskip("Pynite")
    mem, lumped, rigid = members_of(model, pinned_beam)
    fem = pynite.FEModel3D()
    for n, X in model["nodes"].items():
        fem.add_node(n, *map(float, X))
    for name, mat in model["materials"].items():
        fem.add_material(name, mat["E"], mat["G"], 0.3, mat.get("density", 0.0))
    for name, s in model["sections"].items():
        fem.add_section(name, s["area"], s["Iy"], s["Iz"], s.get("J", s["Iy"] + s["Iz"]))
    names = {}
    for k, d in mem.items():
        inner = [f * d["L"] for f in (0.25, 0.5, 0.75)] if cuts is None or k not in cuts \
            else list(cuts[k])
        at = [0.0] + inner + [d["L"]]
        nodes = [d["a"]] + [f"{k}:{j}" for j in range(len(inner))] + [d["b"]]
        for nm, x in zip(nodes[1:-1], inner):
            fem.add_node(nm, *(np.asarray(model["nodes"][d["a"]], float) + x * d["R"][0]))
        (myi, mzi, ti), (myj, mzj, tj) = d["rel"]
        names[k] = []
        for j, (q, pl) in enumerate(pieces(d, at)):
            nm = f"{k}#{j}"
            m = model["members"][k]
            fem.add_member(nm, nodes[j], nodes[j + 1], m["material"], m["section"])
            T = fem.members[nm].T()[:3, :3]
            fem.members[nm].rotation = math.degrees(math.atan2(d["R"][1] @ T[2],
                                                               d["R"][1] @ T[1]))
            first, last = j == 0, j == len(at) - 2
            fem.def_releases(nm, Rxi=ti and first, Ryi=myi and first, Rzi=mzi and first,
                             Rxj=tj and last, Ryj=myj and last, Rzj=mzj and last)
            for q1, q2 in q:
                for c in range(3):
                    if q1[c] or q2[c]:
                        fem.add_member_dist_load(nm, "F" + "xyz"[c], float(q1[c]), float(q2[c]))
            for x, F, M in pl:
                for c in range(3):
                    if F[c]:
                        fem.add_member_pt_load(nm, "F" + "xyz"[c], float(F[c]), x)
                    if M[c]:
                        fem.add_member_pt_load(nm, "M" + "xyz"[c], float(M[c]), x)
            names[k].append(nm)
    for n, W in lumped.items():
        for c in range(3):
            fem.add_node_load(n, "F" + "XYZ"[c], float(W[c]))
    for n, P in model.get("loads", {}).items():
        for c, v in enumerate(P):
            if v:
                fem.add_node_load(n, ("FX", "FY", "FZ", "MX", "MY", "MZ")[c], float(v))
    for n in model["nodes"]:
        sup = set(model.get("supports", {}).get(n, []))
        # a joint without rotations in trussfe (bars and released ends only): its
        # rotations carry nothing there, and are held here (reaction moments checked zero)
        fem.def_support(n, *[c in sup or (c[0] == "r" and n not in rigid) for c in DOFS])
    for n, spr in model.get("springs", {}).items():
        for c, kk in spr.items():
            fem.def_support_spring(n, ("D" + c).upper() if len(c) == 1 else c.upper(), kk)
    fem.analyze_linear(check_statics=False)
    combo = next(iter(fem.load_combos))
    disp = {n: np.array([getattr(fem.nodes[n], c)[combo] for c in
                         ("DX", "DY", "DZ", "RX", "RY", "RZ")]) for n in model["nodes"]}
    reac = {n: np.array([getattr(fem.nodes[n], c)[combo] for c in
                         ("RxnFX", "RxnFY", "RxnFZ", "RxnMX", "RxnMY", "RxnMZ")])
            for n in model["nodes"]}
    sections = {}
    for k, d in mem.items():
        subs = [next(iter(fem.members[nm].sub_members.values())) for nm in names[k]]
        assert all(len(fem.members[nm].sub_members) == 1 for nm in names[k])
        assert np.allclose(subs[0].T()[:3, :3], d["R"], atol=1e-12)      # the same axes
        f = [s.f(combo).ravel() for s in subs]
        sections[k] = np.array([-fi[:6] for fi in f] + [f[-1][6:]])
    return disp, reac, sections, rigid


# ---------------------------------------------------------------------------- OpenSees
def opensees_solution(model):
    """OpenSeesPy: members cut at their quarter points and point loads (applied at the
    cut as joint loads); shear-deformable sections as ``ElasticTimoshenkoBeam``, others
    ``elasticBeamColumn`` with ``-releasey``/``-releasez``, bars ``Truss``; distributed
    loads uniform (``-beamUniform`` in member axes)."""
    ops = pytest.importorskip("openseespy.opensees")
    mem, lumped, rigid = members_of(model)
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    tag = {n: i for i, n in enumerate(model["nodes"], start=1)}
    for n, X in model["nodes"].items():
        ops.node(tag[n], *map(float, X))
    ops.uniaxialMaterial("Elastic", 1, model["materials"]["st"]["E"])
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    joint = {n: np.zeros(6) for n in tag.values()}
    for n, W in lumped.items():
        joint[tag[n]][:3] += W
    for n, P in model.get("loads", {}).items():
        joint[tag[n]][:len(P)] += P
    new_node, ele, elements = len(tag) + 1, 1, {}
    for k, d in mem.items():
        sec, mat = d["sec"], d["mat"]
        if not d["beam"]:
            assert not d["pts"] and not d["dist"]
            ops.element("Truss", ele, tag[d["a"]], tag[d["b"]], sec["area"], 1)
            elements[k], ele = [ele], ele + 1
            continue
        inner = sorted({f * d["L"] for f in (0.25, 0.5, 0.75)} | {x for x, _, _ in d["pts"]})
        inner = [x for x in inner if 0 < x < d["L"]]
        nodes = [tag[d["a"]]]
        for x in inner:
            ops.node(new_node, *(np.asarray(model["nodes"][d["a"]], float) + x * d["R"][0]))
            joint[new_node] = np.zeros(6)
            nodes.append(new_node)
            new_node += 1
        nodes.append(tag[d["b"]])
        at = [0.0] + inner + [d["L"]]
        for x, F, M in d["pts"]:
            joint[nodes[int(np.argmin(np.abs(np.subtract(at, x))))]] += np.concatenate(
                [d["R"].T @ F, d["R"].T @ M])
        transf = 1000 + ele
        ops.geomTransf("Linear", transf, *d["R"][2])
        (myi, mzi, ti), (myj, mzj, tj) = d["rel"]
        assert not (ti or tj)
        elements[k] = []
        for j in range(len(nodes) - 1):
            first, last = j == 0, j == len(nodes) - 2
            if "shear_area_y" in sec:
                assert not (myi or mzi or myj or mzj)
                ops.element("ElasticTimoshenkoBeam", ele, nodes[j], nodes[j + 1], mat["E"],
                            mat["G"], sec["area"], sec["J"], sec["Iy"], sec["Iz"],
                            sec["shear_area_y"], sec["shear_area_z"], transf)
            else:
                ry = (1 if myi and first else 0) + (2 if myj and last else 0)
                rz = (1 if mzi and first else 0) + (2 if mzj and last else 0)
                extra = (["-releasez", rz] if rz else []) + (["-releasey", ry] if ry else [])
                ops.element("elasticBeamColumn", ele, nodes[j], nodes[j + 1], sec["area"],
                            mat["E"], mat["G"], sec["J"], sec["Iy"], sec["Iz"],
                            transf, *extra)
            for q1, q2 in d["dist"]:
                assert np.array_equal(q1, q2)
                ops.eleLoad("-ele", ele, "-type", "-beamUniform", float(q1[1]), float(q1[2]),
                            float(q1[0]))
            elements[k].append(ele)
            ele += 1
    for n, v in joint.items():
        if np.any(v):
            ops.load(n, *map(float, v))
    for n in model["nodes"]:
        sup = set(model.get("supports", {}).get(n, []))
        fix = [int(c in sup or (c[0] == "r" and n not in rigid)) for c in DOFS]
        if any(fix):
            ops.fix(tag[n], *fix)
    for cmd in (("system", "FullGeneral"), ("numberer", "Plain"), ("constraints", "Plain"),
                ("integrator", "LoadControl", 1.0), ("algorithm", "Linear"),
                ("analysis", "Static")):
        getattr(ops, cmd[0])(*cmd[1:])
    assert ops.analyze(1) == 0
    ops.reactions()
    disp = {n: np.array(ops.nodeDisp(tag[n])) for n in model["nodes"]}
    reac = {n: np.array(ops.nodeReaction(tag[n])) for n in model["nodes"]}
    ends = {}
    for k, d in mem.items():
        if not d["beam"]:
            N = ops.eleResponse(elements[k][0], "axialForce")[0]
            ends[k] = np.array([[N, 0, 0, 0, 0, 0], [N, 0, 0, 0, 0, 0]], float)
        else:
            f0 = np.array(ops.eleResponse(elements[k][0], "localForce"))
            f1 = np.array(ops.eleResponse(elements[k][-1], "localForce"))
            ends[k] = np.array([-f0[:6], f1[6:]])
    ops.wipe()
    return disp, reac, ends, rigid


# -------------------------------------------------------------------------------- checks
def assert_close(mine, theirs, scale, rtol, what):
    err = np.max(np.abs(np.asarray(mine) - np.asarray(theirs))) / scale
    assert err <= rtol, f"{what}: {err:.2e} of the largest value"


def compare_joints(model, disp, reac, rigid, ref_disp, ref_reac, rtol=1e-9):
    u = max(np.abs(v[:3]).max() for v in ref_disp.values())
    th = max(np.abs(v[3:]).max() for n, v in ref_disp.items() if n in rigid)
    f = max(np.abs(v).max() for v in ref_reac.values())
    for n in model["nodes"]:
        assert_close(disp[n][:3], ref_disp[n][:3], u, rtol, f"translation of {n}")
        if n in rigid:
            assert_close(disp[n][3:], ref_disp[n][3:], th, rtol, f"rotation of {n}")
        assert_close(reac[n], ref_reac[n], f, rtol, f"reaction of {n}")
    return f


@pytest.mark.parametrize("k", [1, 4])
def test_frame_with_releases_and_member_loads_against_pynite(k):
    """Joints, reactions and the section forces at the finite-element stations (PyNite cut
    at the same stations); with k = 1 only the ends."""
    model = frame_a()
    r, s, disp, reac = trussfe_solution(model, k)
    fracs = np.linspace(0.0, 1.0, k + 1)[1:-1]
    cuts = {m: fracs * d["L"] for m, d in members_of(model)[0].items()}
    ref_disp, ref_reac, ref_sec, rigid = pynite_solution(model, cuts)
    f = compare_joints(model, disp, reac, rigid, ref_disp, ref_reac)
    for m in model["members"]:
        i = s.member_index(m)
        ok = np.isfinite(r.station_x[i])
        mine = r.section_forces[i][ok]
        theirs = ref_sec[m] if mine.shape[0] == ref_sec[m].shape[0] else ref_sec[m][[0, -1]]
        assert_close(mine, theirs, f, 1e-9, f"section forces of {m}")
        assert_close(r.end_forces[i], ref_sec[m][[0, -1]], f, 1e-9, f"end forces of {m}")


def test_ball_joints_twist_springs_and_bars_against_pynite():
    model = frame_b()
    for k, bar_model in ((1, "truss"), (4, "truss"), (4, "pinned-beam")):
        r, s, disp, reac = trussfe_solution(model, k, bar_model)
        ref_disp, ref_reac, ref_sec, rigid = pynite_solution(
            model, pinned_beam=bar_model == "pinned-beam")
        assert {n for n in model["nodes"] if r.fe.has_rotation[s.node_index(n)]} \
            == rigid | {"Q"}          # Q: rotations held, for the twist of EQ
        f = compare_joints(model, disp, reac, rigid, ref_disp, ref_reac)
        for m in model["members"]:
            assert_close(r.end_forces[s.member_index(m)], ref_sec[m][[0, -1]], f, 1e-9,
                         f"end forces of {m} ({bar_model}, k = {k})")
    # the twist of EQ is held by the support of Q's rotation about X alone
    assert abs(reac["Q"][3]) > 100.0
    assert reac["Q"][4] == reac["Q"][5] == 0.0


def test_timoshenko_frame_against_opensees():
    model = frame_a(timoshenko=True, torsion_releases=False)
    ref_disp, ref_reac, ref_ends, rigid = opensees_solution(model)
    for k in (1, 4):
        r, s, disp, reac = trussfe_solution(model, k)
        f = compare_joints(model, disp, reac, rigid, ref_disp, ref_reac)
        for m in model["members"]:
            assert_close(r.end_forces[s.member_index(m)], ref_ends[m], f, 1e-9,
                         f"end forces of {m} (k = {k})")
    # the shear deformation matters here: the Euler-Bernoulli frame is 1 % off
    eb = dict(model, sections={n: {c: v for c, v in sec.items() if not c.startswith("shear")}
                               for n, sec in model["sections"].items()})
    u_eb = trussfe_solution(eb, 4)[2]["D"][:3]
    assert np.abs(u_eb - ref_disp["D"][:3]).max() > 5e-3 * np.abs(ref_disp["D"][:3]).max()


def test_joints_do_not_depend_on_subdivisions():
    """Euler-Bernoulli beams with exact member loads: joint results and end forces of one
    element per member equal those of four."""
    for model in (frame_a(), frame_b()):
        r1, _, d1, q1 = trussfe_solution(model, 1)
        r4, _, d4, q4 = trussfe_solution(model, 4)
        u = max(np.abs(v).max() for v in d4.values())
        f = max(np.abs(v).max() for v in q4.values())
        for n in model["nodes"]:
            assert_close(d1[n], d4[n], u, 1e-10, f"displacement of {n}")
            assert_close(q1[n], q4[n], f, 1e-10, f"reaction of {n}")
        assert_close(r1.end_forces, r4.end_forces, f, 1e-10, "end forces")


@pytest.mark.parametrize("k, bar_model", [(1, "truss"), (4, "truss"), (4, "pinned-beam")])
def test_stations_of_loaded_members_under_self_weight_against_pynite(k, bar_model):
    """The JSON ``stations`` of members carrying member loads (under point loads, where a
    shear force vanishes, at the finite-element stations) include the members' self-weight:
    PyNite cut at the same positions."""
    model = frame_a()
    r = trussfe_solution(model, k, bar_model)[0]
    doc = static_json(r)["members"]
    along = {m: v["stations"] for m, v in doc.items() if "stations" in v}
    assert set(along) == {ld["member"] for ld in model["member_loads"]}
    cuts = {m: v["x"][1:-1] for m, v in along.items()}
    _, ref_reac, ref_sec, _ = pynite_solution(model, cuts, bar_model == "pinned-beam")
    f = max(np.abs(v).max() for v in ref_reac.values())
    names = ("N", "Vy", "Vz", "T", "My", "Mz")
    for m, v in along.items():
        mine = np.array([v[c] for c in names]).T
        assert_close(mine, ref_sec[m], f, 1e-9, f"stations of {m}")
        ends = doc[m]["end_forces"]
        assert_close(mine[[0, -1]], [[ends[e][c] for c in names] for e in ("start", "end")],
                     f, 1e-9, f"end stations of {m} against its end forces")


def test_stations_of_a_combination_with_factored_self_weight_against_pynite():
    """A combination of a gravity case and a member-load case, with factors: its stations
    against PyNite under the factored loads."""
    model = frame_a()
    ml = model.pop("member_loads")
    loads = model.pop("loads")
    cased = dict(model, load_cases={"dead": {"gravity": True},
                                    "live": {"loads": loads, "member_loads": ml}},
                 combinations={"ULS": {"dead": 1.35, "live": 1.5}})
    r = solve_load_cases(model_from_dict(cased)).combinations["ULS"]
    doc = static_json(r)["members"]
    factored = dict(model, model=dict(model["model"], gravity=[0.0, 0.0, -1.35 * 9.81]),
                    loads={n: [1.5 * v for v in P] for n, P in loads.items()},
                    member_loads=[{c: ([1.5 * x for x in v] if c in ("q", "q_start", "q_end",
                                                                       "F", "M") else v)
                                   for c, v in ld.items()} for ld in ml])
    along = {m: v["stations"] for m, v in doc.items() if "stations" in v}
    _, ref_reac, ref_sec, _ = pynite_solution(factored, {m: v["x"][1:-1]
                                                         for m, v in along.items()})
    f = max(np.abs(v).max() for v in ref_reac.values())
    for m, v in along.items():
        mine = np.array([v[c] for c in ("N", "Vy", "Vz", "T", "My", "Mz")]).T
        assert_close(mine, ref_sec[m], f, 1e-9, f"stations of {m}")
