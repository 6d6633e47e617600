"""Member failure laws on small trusses against hand statics, limit analysis and OpenSeesPy.

Expected values are closed forms of the co-rotational bar (``N = EA(ℓ − L)/L``, equilibrium
in the current geometry), stated in each test, and OpenSeesPy's ``corotTruss`` with
``ElasticPP`` (the yield ``cap``) or ``ElasticMultiLinear`` (the elastic buckling laws), driven
through the same displacements of the loaded joint."""
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.nonlinear import NonlinearModel, build_failure_laws, follow_path

A, E, FY = 1e-4, 2e11, 2.5e8
EA, NY = E * A, A * FY
SEC = Section(name="s", area=A, Iy=1e-8, Iz=1e-8, J=2e-8, c=0.01)
MAT = Material(name="m", E=E, G=8e10, density=0.0, yield_strength=FY)


def _opensees_path(nodes, bars, fixed, materials, load_node, load, axis, targets):
    """Load factors of an OpenSees ``corotTruss`` model at the prescribed displacements
    ``targets`` of ``load_node`` along ``axis`` (displacement control, one step per target).

    ``materials``: one ``uniaxialMaterial`` argument list (without the tag) per bar."""
    ops = pytest.importorskip("openseespy.opensees")
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for i, (x, y) in enumerate(nodes):
        ops.node(i + 1, float(x), float(y))
    for i, dofs in fixed.items():
        ops.fix(i + 1, *dofs)
    for k, ((a, b), mat) in enumerate(zip(bars, materials)):
        ops.uniaxialMaterial(mat[0], k + 1, *mat[1:])
        ops.element("corotTruss", k + 1, a + 1, b + 1, A, k + 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(load_node + 1, *load)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-14, 50)
    ops.algorithm("Newton")
    ops.integrator("DisplacementControl", load_node + 1, axis + 1, 0.0)
    ops.analysis("Static")
    lam, done = [], 0.0
    for t in targets:
        ops.integrator("DisplacementControl", load_node + 1, axis + 1, float(t - done))
        assert ops.analyze(1) == 0
        done = ops.nodeDisp(load_node + 1, axis + 1)
        lam.append(ops.getLoadFactor(1))
    ops.wipe()
    return np.array(lam)


# ------------------------------------------------------------------- three-bar truss
THREE_NODES = [[0.0, 0.0], [-1.0, 1.0], [0.0, 1.0], [1.0, 1.0]]
THREE_BARS = [(1, 0), (2, 0), (3, 0)]


def _three_bar(py):
    """Joint 0 hung from (−1, 1), (0, 1), (1, 1): a 1 m vertical bar between two bars at 45°;
    load (0, py) N on joint 0."""
    return build_structure(THREE_NODES, THREE_BARS, section=SEC, material=MAT,
                           supports={1: "xy", 2: "xy", 3: "xy"}, loads={0: [0.0, py]})


def _three_bar_yield_lambda(v, P=1000.0):
    """Exact equilibrium of the symmetric state, joint 0 down by v (elastic–perfectly
    plastic bars): λP = N_c + 2 N_s (1 + v)/ℓ_s, ℓ_s = √(1 + (1 + v)²)."""
    ls = math.hypot(1.0, 1.0 + v)
    Nc = min(EA * v, NY)
    Ns = min(EA * (ls / math.sqrt(2.0) - 1.0), NY)
    return (Nc + 2.0 * Ns * (1.0 + v) / ls) / P


@pytest.mark.parametrize("control", ["displacement", "arc-length"])
def test_three_bar_yield_cap_load_path_and_plastic_collapse(control):
    """Elastic–plastic load path of the classic three-bar truss (yield ``cap`` on all bars).

    The vertical bar yields first, at v₁ = f_y L/E: λ₁ = 42.6942320 (small displacements:
    A f_y (1 + 2cos³45°)/P = 42.678).  It then carries exactly A f_y while the inclined bars
    take the increase, until they yield at ℓ_s = √2 (1 + f_y/E): the plastic mechanism, whose
    limit-analysis load in the geometry at collapse is λ_c = A f_y (1 + 2cos θ)/P with
    cos θ = (1 + v₂)/ℓ_s — 60.3994230, against A f_y (1 + 2cos 45°)/P = 60.355 in the
    undeformed geometry.  The path between and after the events is the closed form."""
    s = _three_bar(-1000.0)
    m = NonlinearModel(s, laws=build_failure_laws(s, {"yield": "cap"}))
    kw = {"step": 2e-4} if control == "displacement" else {
        "step": 2e-4, "max_step": 2e-4, "max_displacement": 0.006}
    r = follow_path(m, control, steps=40, monitor=1, **kw)
    ev = [e for e in r.events if e.kind == "yield"]
    assert [e.member for e in ev] == [1, 0, 2]
    v1 = FY / E
    v2 = math.sqrt(2.0 * (1.0 + FY / E) ** 2 - 1.0) - 1.0
    ls2 = math.sqrt(2.0) * (1.0 + FY / E)
    lam1 = _three_bar_yield_lambda(v1)
    lam_c = NY * (1.0 + 2.0 * (1.0 + v2) / ls2) / 1000.0
    assert_allclose(lam1, 42.6942320, rtol=1e-8)
    assert_allclose(lam_c, 60.3994230, rtol=1e-8)
    assert_allclose(lam1, NY * (1 + 2 * math.cos(math.pi / 4) ** 3) / 1000.0, rtol=1e-3)
    assert_allclose(lam_c, NY * (1 + 2 * math.cos(math.pi / 4)) / 1000.0, rtol=1e-3)
    assert_allclose([e.load_factor for e in ev], [lam1, lam_c, lam_c], rtol=1e-6)
    assert_allclose([e.force for e in ev], [NY] * 3, rtol=1e-6)
    # each member's yield is reported once, although it stays at its limit
    assert len({e.member for e in ev}) == len(ev)
    v = -r.displacement()
    lam = r.load_factors
    assert_allclose(lam, [_three_bar_yield_lambda(x) for x in v], rtol=1e-9, atol=1e-9)
    between = [p for p in r.path if lam1 * 1.001 < p.load_factor < lam_c * 0.999]
    assert between
    for p in between:
        assert_allclose(p.forces[1], NY, rtol=1e-12)
    assert v.max() > 2.0 * v2        # the path went on past the mechanism (rotating bars)


@pytest.mark.parametrize("step", [2.0, 0.5])
def test_three_bar_load_control_reports_the_collapse_and_follows_the_hardening(step):
    """Load control through the plastic collapse of the three-bar truss (closed forms of
    ``test_three_bar_yield_cap_load_path_and_plastic_collapse``): the inclined bars' yield at
    λ_c = 60.3994230 is an equilibrium state, but a load step past it converges only far
    away (the yielded truss stiffens only by rotating its bars), so the step is taken under
    displacement control and the event located on it.  All three yield events are reported at
    their closed-form load factors, and the path goes on to λ = 70 on the closed form
    λ(v) of the rotating, yielded bars; every point is in equilibrium (the closed form is
    the equilibrium of the joint)."""
    s = _three_bar(-1000.0)
    m = NonlinearModel(s, laws=build_failure_laws(s, {"yield": "cap"}))
    r = follow_path(m, "load", steps=400, step=step, monitor=1, max_load_factor=70.0)
    assert r.termination == "reached the maximum load factor 70"
    ev = [e for e in r.events if e.kind == "yield"]
    assert [e.member for e in ev] == [1, 0, 2]
    v1 = FY / E
    v2 = math.sqrt(2.0 * (1.0 + FY / E) ** 2 - 1.0) - 1.0
    lam1 = _three_bar_yield_lambda(v1)
    lam_c = NY * (1.0 + 2.0 * (1.0 + v2) / (math.sqrt(2.0) * (1.0 + FY / E))) / 1000.0
    assert_allclose([e.load_factor for e in ev], [lam1, lam_c, lam_c], rtol=1e-6)
    assert_allclose([e.force for e in ev], [NY] * 3, rtol=1e-6)
    v = -r.displacement()
    lam = r.load_factors
    assert np.all(np.diff(lam) > 0.0)                # load control: λ only grows
    assert_allclose(lam, [_three_bar_yield_lambda(x) for x in v], rtol=1e-9, atol=1e-9)
    assert lam[-1] == pytest.approx(70.0, rel=1e-12)
    # λ = 70 needs cos θ = 0.9: the joint has dropped by (1 + v) = 0.9/√(1 − 0.81) − 1 m
    assert v[-1] == pytest.approx(0.9 / math.sqrt(0.19) - 1.0, rel=1e-6)


def test_three_bar_yield_cap_path_agrees_with_opensees():
    """The same truss with OpenSees ``corotTruss`` + ``ElasticPP`` (f_y/E): the load factors
    at trussfe's path displacements agree to 1e-9 of the collapse load."""
    s = _three_bar(-1000.0)
    m = NonlinearModel(s, laws=build_failure_laws(s, {"yield": "cap"}))
    r = follow_path(m, "displacement", steps=30, step=2e-4, monitor=1)
    targets = r.displacement()[1:]
    theirs = _opensees_path(THREE_NODES, THREE_BARS, {1: (1, 1), 2: (1, 1), 3: (1, 1)},
                            [("ElasticPP", E, FY / E)] * 3, 0, (0.0, -1000.0), 1, targets)
    assert_allclose(r.load_factors[1:], theirs, rtol=0, atol=1e-9 * 60.4)


def _softening_N(eps, Pcr, residual, es):
    """The softening law: EAε down to −P_cr, then linear to −residual·P_cr over es."""
    ecr = -Pcr / EA
    if eps >= ecr:
        return EA * eps
    return -Pcr * (1.0 - (1.0 - residual) * min((ecr - eps) / es, 1.0))


def test_three_bar_softening_strut_path_slope_and_opensees():
    """The three-bar truss pushed up (compression), the vertical strut with a ``softening``
    law (P_cr = 10 kN, residual 0.3, softening_strain 1e-3), the inclined bars elastic.
    Closed form, joint 0 up by v: λP = −N_c(−v) − 2EA(ℓ_s/√2 − 1)(1 − v)/ℓ_s with
    ℓ_s = √(1 + (1 − v)²); the strut's force falls on the post-peak branch with the slope
    dN/dε = −P_cr(1 − 0.3)/1e-3 = −7e6 N; OpenSees ``ElasticMultiLinear`` with the same
    polyline gives the same load factors."""
    Pcr, res, es = 1e4, 0.3, 1e-3
    s = _three_bar(1000.0)
    law = {"buckling": "softening", "critical_load": Pcr, "residual": res,
           "softening_strain": es}
    m = NonlinearModel(s, laws=build_failure_laws(s, per_member={1: law}))
    r = follow_path(m, "displacement", steps=40, step=5e-5, monitor=1)
    v = r.displacement()

    def lam_of(x):
        ls = math.hypot(1.0, 1.0 - x)
        return (-_softening_N(-x, Pcr, res, es)
                - 2.0 * EA * (ls / math.sqrt(2.0) - 1.0) * (1.0 - x) / ls) / 1000.0

    assert_allclose(r.load_factors, [lam_of(x) for x in v], rtol=1e-9, atol=1e-9)
    ev = [e for e in r.events if e.kind == "buckling"]
    assert len(ev) == 1 and ev[0].member == 1
    assert_allclose(ev[0].force, -Pcr, rtol=1e-6)
    # post-peak slope of the strut's force against its strain (ε = −v on the vertical bar)
    Nc = np.array([p.forces[1] for p in r.path])
    ramp = (-v < -Pcr / EA - 1e-6) & (-v > -Pcr / EA - es + 1e-6)
    assert ramp.sum() >= 3
    slope = np.diff(Nc[ramp]) / np.diff(-v[ramp])
    assert_allclose(slope, -Pcr * (1 - res) / es, rtol=1e-9)
    ecr = Pcr / EA
    strains = [-1.0, -(ecr + es), -ecr, 1.0]
    stresses = [-res * Pcr / A, -res * Pcr / A, -Pcr / A, E]
    soft = ("ElasticMultiLinear", 0.0, "-strain", *strains, "-stress", *stresses)
    theirs = _opensees_path(THREE_NODES, THREE_BARS, {1: (1, 1), 2: (1, 1), 3: (1, 1)},
                            [("Elastic", E), soft, ("Elastic", E)], 0, (0.0, 1000.0), 1,
                            v[1:])
    assert_allclose(r.load_factors[1:], theirs, rtol=0, atol=1e-9 * 100.0)


# --------------------------------------------------------------------- von Mises truss
def _von_mises(Pcr_law, scale=1.0):
    """Two bars from (∓1, 0) to the apex (0, 0.1), EA = 1e6 N, apex load −1 N (x held);
    ``scale`` 1e3 gives the same model in mm–N–MPa."""
    c = scale
    sec = Section(name="b", area=1e-4 * c * c, Iy=1e-9 * c ** 4, Iz=1e-9 * c ** 4,
                  J=2e-9 * c ** 4, c=0.01 * c)
    mat = Material(name="m", E=1e10 / (c * c), G=4e9 / (c * c), density=0.0,
                   yield_strength=math.nan)
    s = build_structure(np.array([[-1.0, 0.0], [0.0, 0.1], [1.0, 0.0]]) * c, [(0, 1), (1, 2)],
                        section=sec, material=mat, supports={0: "xy", 2: "xy"},
                        loads={1: [0.0, -1.0]})
    sup = np.array(s.supports)
    sup[1, 0] = True
    s = s.with_supports(sup)
    return s, build_failure_laws(s, Pcr_law)


def test_von_mises_buckling_cap_at_the_current_axial_force_and_opensees():
    """Buckling ``cap`` (P_cr = 1000 N) on both bars of the von Mises truss (EA = 1e6 N,
    L = √1.01): the event is where the co-rotational force EA(ℓ − L)/L reaches −P_cr,
    ℓ = L(1 − P_cr/EA), at λ = 2P_cr·√(ℓ² − 1)/ℓ = 177.964242; past it the path follows
    λ = 2P_cr(0.1 − w)/ℓ(w) down through the snap-through.  OpenSees ``ElasticMultiLinear``
    (flat at −P_cr/A beyond −P_cr/EA) gives the same load factors."""
    Pcr, EAv, h = 1000.0, 1e6, 0.1
    s, laws = _von_mises({"buckling": "cap", "critical_load": Pcr})
    m = NonlinearModel(s, laws=laws)
    r = follow_path(m, "displacement", steps=90, step=2e-3, monitor=3)
    L0 = math.sqrt(1.0 + h * h)
    l_ev = L0 * (1.0 - Pcr / EAv)
    lam_ev = 2.0 * Pcr * math.sqrt(l_ev ** 2 - 1.0) / l_ev
    assert_allclose(lam_ev, 177.964242, rtol=1e-8)
    ev = [e for e in r.events if e.kind == "buckling"]
    assert sorted(e.member for e in ev) == [0, 1]
    for e in ev:
        assert_allclose(e.load_factor, lam_ev, rtol=1e-6)
        assert_allclose(e.force, -Pcr, rtol=1e-6)

    def lam_of(w):
        ls = math.hypot(1.0, h - w)
        return -2.0 * max(EAv * (ls - L0) / L0, -Pcr) * (h - w) / ls

    w = -r.displacement()
    assert w.max() > 1.5 * h
    assert_allclose(r.load_factors, [lam_of(x) for x in w], rtol=1e-9, atol=1e-9 * lam_ev)
    ecr = Pcr / EAv
    cap = ("ElasticMultiLinear", 0.0, "-strain", -1.0, -ecr, 1.0,
           "-stress", -Pcr / 1e-4, -Pcr / 1e-4, 1e10)
    theirs = _opensees_path([[-1.0, 0.0], [0.0, h], [1.0, 0.0]], [(0, 1), (1, 2)],
                            {0: (1, 1), 2: (1, 1), 1: (1, 0)}, [cap, cap], 1, (0.0, -1.0), 1,
                            -w[1:])
    assert_allclose(r.load_factors[1:], theirs, rtol=0, atol=1e-9 * lam_ev)


@pytest.mark.parametrize("law", [{"buckling": "cap"}, {"buckling": "remove"},
                                 {"buckling": "cap", "critical_load": 1000.0}])
def test_buckling_events_do_not_depend_on_units(law):
    """The von Mises truss in m–N–Pa and in mm–N–MPa (P_cr from π²EI/L² or given in N): the
    buckling events and the path's load factors are the same numbers."""
    out = []
    for scale in (1.0, 1e3):
        s, laws = _von_mises(law, scale)
        r = follow_path(NonlinearModel(s, laws=laws), "arc-length", steps=40, monitor=3)
        out.append(r)
    a, b = out
    ea = [(e.kind, e.member) for e in a.events]
    assert ea == [(e.kind, e.member) for e in b.events]
    assert any(k == "buckling" for k, _ in ea)
    assert_allclose([e.load_factor for e in b.events], [e.load_factor for e in a.events],
                    rtol=1e-10)
    assert_allclose(b.load_factors, a.load_factors, rtol=1e-9, atol=1e-12)


# -------------------------------------------------------------- parallel-bar collapse
@pytest.mark.parametrize("control", ["load", "displacement", "arc-length"])
def test_parallel_bars_progressive_fracture(control):
    """Four collinear bars of lengths 1, 2, 3, 4 m on joint 0, pulled along +x by λ·1000 N,
    fracture strains 1.0, 1.2, 1.5, 2.5 ‰: bar i breaks at u = ε_f,i·L_i, when
    λ = u·Σ_alive EA/L_j /1000 — 41.667 (bar 0), 52.0 (bar 1), 52.5 (bar 2).  After bar 2 the
    last bar alone would need u = 52.5·1000·4/EA = 10.5 mm > its 10 mm: it breaks at the same
    λ, and nothing is left (collapse at λ = 52.5).  Each failure strain equals its law's limit
    to 1e-6, each member fails once, and the path's alive flags follow the events."""
    Ls, ef = [1.0, 2.0, 3.0, 4.0], [1e-3, 1.2e-3, 1.5e-3, 2.5e-3]
    nodes = [[0.0, 0.0]] + [[-L, 0.0] for L in Ls]
    s = build_structure(nodes, [(i + 1, 0) for i in range(4)], section=SEC, material=MAT,
                        supports={**{i + 1: "xy" for i in range(4)}, 0: "y"},
                        loads={0: [1000.0, 0.0]})
    m = NonlinearModel(s, laws=build_failure_laws(
        s, per_member={i: {"fracture_strain": ef[i]} for i in range(4)}))
    kw = {"load": {"step": 50.0, "max_load_factor": 1000.0},
          "displacement": {"step": 2e-4}, "arc-length": {}}[control]
    r = follow_path(m, control, steps=200, monitor=0, **kw)
    hand = [ef[i] * Ls[i] * sum(EA / L for L in Ls[i:]) / 1000.0 for i in range(3)]
    assert_allclose(hand, [125.0 / 3.0, 52.0, 52.5], rtol=1e-12)
    ev = [e for e in r.events if e.kind == "fracture"]
    assert [e.member for e in ev] == [0, 1, 2, 3]
    assert_allclose([e.load_factor for e in ev], hand + [52.5], rtol=1e-6)
    assert_allclose([e.force for e in ev], ef, rtol=1e-6)
    assert "redistribution" in ev[3].detail
    assert "collapsed" in r.termination
    for e in ev:
        p = r.path[e.point]
        assert p.alive[e.member]                        # the event state: still in place
        assert not any(q.alive[e.member] for q in r.path[e.point + 1:])
    # at the equilibrium states the surviving bars share the load elastically:
    # u = λP / Σ EA/L (a state inside a redistribution, where the release of the removed bars'
    # forces stopped because the next bar reached its limit, still carries part of them)
    for p in r.path:
        alive = [i for i in range(4) if p.alive[i]]
        if p.stage == "equilibrium" and alive and p.negative is not None:
            assert_allclose(p.u[0], p.load_factor * 1000.0 / sum(EA / Ls[i] for i in alive),
                            rtol=1e-9)
