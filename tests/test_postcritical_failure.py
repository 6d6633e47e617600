"""Member failure laws and their input checks (trussfe.nonlinear.failure / path).

Expected values are closed forms of small bar assemblies (stated in each test)."""
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.errors import InputError, MechanismError
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure
from trussfe.nonlinear import NonlinearModel, build_failure_laws, follow_path
from trussfe.io.extension_tables import parse_failure_table

A, E, FY = 1e-4, 2e11, 2.5e8
SEC = Section(name="s", area=A, Iy=1e-8, Iz=1e-8, J=2e-8, c=0.01)
MAT = Material(name="m", E=E, G=8e10, density=0.0, yield_strength=FY)


def _parallel(load=1000.0):
    """Node 0 at the origin held by bar 0 (to x = −1, L1 = 1 m) and bar 1 (to x = −2,
    L2 = 2 m), both along x; y of the node supported; load along +x (or −x)."""
    return build_structure([[0.0, 0.0], [-1.0, 0.0], [-2.0, 0.0]], [(1, 0), (2, 0)],
                           section=SEC, material=MAT, supports={1: "xy", 2: "xy", 0: "y"},
                           loads={0: [load, 0.0]})


def test_yield_cap_events_at_closed_form_load_factors():
    """Equal displacement u in both bars: bar 0 (L1 = 1) yields at u = f_y L1/E, i.e.
    λ1 = A f_y (1 + L1/L2)/P = 37.5; bar 1 at λ2 = 2 A f_y / P = 50 (P = 1000 N).  At the
    second yield the assembly has no stiffness left along x: the path ends there."""
    s = _parallel()
    laws = build_failure_laws(s, {"yield": "cap"})
    m = NonlinearModel(s, laws=laws)
    r = follow_path(m, "displacement", steps=40, step=5e-4, monitor=0)
    ev = [e for e in r.events if e.kind == "yield"]
    assert [e.member for e in ev] == [0, 1]
    assert_allclose([e.load_factor for e in ev], [37.5, 50.0], rtol=2e-6)
    assert_allclose([e.force for e in ev], [A * FY, A * FY], rtol=1e-6)
    assert "cannot be continued" in r.termination
    # between the events bar 0 carries exactly A f_y (perfectly plastic) while bar 1 is elastic
    between = [p for p in r.path if 37.6 < p.load_factor < 49.9]
    assert between
    for p in between:
        assert_allclose(p.forces[0], A * FY, rtol=1e-9)
        assert_allclose(p.forces[1], E * A * p.u[0] / 2.0, rtol=1e-6)


def test_fracture_removes_the_bar_and_the_other_takes_the_load():
    """Bar 0 breaks at ε = 1e-3, i.e. u = 1 mm: λ = EA u (1/L1 + 1/L2)/P = 30.  After the
    removal bar 1 alone carries λP at the same λ: u = λP L2/(EA) = 3 mm."""
    s = _parallel()
    m = NonlinearModel(s, laws=build_failure_laws(s, per_member={0: {"fracture_strain": 1e-3}}))
    r = follow_path(m, "load", steps=20, step=2.0, max_load_factor=36.0, monitor=0)
    ev = [e for e in r.events if e.kind == "fracture"]
    assert len(ev) == 1 and ev[0].member == 0
    assert_allclose(ev[0].load_factor, 30.0, rtol=1e-6)
    assert_allclose(ev[0].force, 1e-3, rtol=1e-6)                 # strain at the event
    after = [p for p in r.path if not p.alive[0]]
    assert_allclose(after[0].u[0], 30.0 * 1000.0 * 2.0 / (E * A), rtol=1e-6)
    assert after[-1].load_factor == pytest.approx(36.0)


def test_softening_buckling_law_along_the_path():
    """A single strut pushed by displacement control: N = −EAε up to P_cr = 1000 N, then the
    compression falls linearly to 0.4 P_cr over 1e-3 of extra shortening and stays there —
    the load factor (P = 1 N) equals −N(ε) at every point, through the negative tangent."""
    s = build_structure([[0.0, 0.0], [-1.0, 0.0]], [(1, 0)], section=SEC, material=MAT,
                        supports={1: "xy", 0: "y"}, loads={0: [-1.0, 0.0]})
    law = {"buckling": "softening", "critical_load": 1000.0, "residual": 0.4,
           "softening_strain": 1e-3}
    m = NonlinearModel(s, laws=build_failure_laws(s, law))
    r = follow_path(m, "displacement", steps=60, step=5e-5, monitor=0)
    eps = r.displacement() / 1.0                    # shortening u < 0: strain = u / L
    ecr = -1000.0 / (E * A)
    over = np.clip((ecr - eps) / 1e-3, 0.0, 1.0)
    N = np.where(eps > ecr, E * A * eps, -1000.0 * (1 - 0.6 * over))
    assert_allclose(r.load_factors, -N, rtol=1e-8, atol=1e-8)
    assert r.load_factors[-1] == pytest.approx(400.0)
    ev = [e for e in r.events if e.kind == "buckling"]
    assert len(ev) == 1 and ev[0].load_factor == pytest.approx(1000.0, rel=1e-6)


def test_cap_law_keeps_the_euler_load():
    """Cap law on bar 0 of the parallel pair pushed along −x, with the Euler load of its
    section (π²EI/L² = 19739.2 N for I = 1e-8, L = 1): it buckles at u = P_cr/EA, i.e.
    λP = 1.5 P_cr (bar 1 with L2 = 2 carries half as much), then keeps −P_cr while bar 1
    takes the rest elastically."""
    s = _parallel(load=-1000.0)
    laws = build_failure_laws(s, per_member={0: {"buckling": "cap"}})
    Pcr = math.pi ** 2 * E * 1e-8
    assert_allclose(laws.critical_load[0], Pcr, rtol=1e-14)
    m = NonlinearModel(s, laws=laws)
    r = follow_path(m, "displacement", steps=30, step=1e-4, monitor=0)
    ev = [e for e in r.events if e.kind == "buckling"]
    assert len(ev) == 1
    assert_allclose(ev[0].load_factor * 1000.0, 1.5 * Pcr, rtol=1e-6)
    late = [p for p in r.path if p.u[0] < -1.2 * Pcr / (E * A)]
    assert late
    for p in late:
        assert_allclose(p.forces[0], -Pcr, rtol=1e-12)
        assert_allclose(p.load_factor * 1000.0, Pcr - E * A * p.u[0] / 2.0, rtol=1e-8)


@pytest.mark.parametrize("table, match", [
    ({"default": {"buckling": "cap", "residual": 0.3}}, "belongs to buckling"),
    ({"default": {"buckling": "softening", "residual": 1.3, "softening_strain": 1e-3}},
     r"\[0, 1\]"),
    ({"default": {"buckling": "softening"}}, "needs residual and softening_strain"),
    ({"default": {"buckling": "bend"}}, "unknown law"),
    ({"default": {"fracture_strain": -0.01}}, "must be positive"),
    ({"default": {"critical_load": 100.0}}, "without a buckling law"),
    ({"default": {"buckling": "cap", "critical_load": 1.0, "effective_length_factor": 1.0}},
     "either critical_load"),
    ({"default": {"yield_strength": 1e8}}, "without a yield law"),
    ({"members": {"nope": {"buckling": "cap"}}}, "not defined"),
    ({"default": {"bucklng": "cap"}}, "unknown key"),
    ({"other": {}}, "unknown key"),
])
def test_inconsistent_failure_laws_are_rejected(table, match):
    """Each inconsistent [failure] table raises InputError naming the item."""
    s = _parallel()
    with pytest.raises(InputError, match=match) as err:
        parse_failure_table(table, s)
    assert str(err.value).startswith("failure")


def test_laws_needing_missing_section_or_material_data():
    """A buckling law on a section without I, a yield law on a material without f_y."""
    sec = Section(name="bare", area=1e-4)
    mat = Material(name="nofy", E=E, G=8e10, density=0.0, yield_strength=math.nan)
    s = build_structure([[0.0, 0.0], [1.0, 0.0]], [(0, 1)], section=sec, material=mat)
    with pytest.raises(InputError, match="no second moment of area"):
        build_failure_laws(s, {"buckling": "cap"})
    with pytest.raises(InputError, match="no yield_strength"):
        build_failure_laws(s, {"yield": "cap"})
    assert build_failure_laws(s, {"buckling": "cap", "critical_load": 5.0}).critical_load[0] == 5


def test_no_load_pattern():
    """A model without loads on free DOFs cannot be scaled by a load factor."""
    s = _parallel(load=0.0)
    with pytest.raises(InputError, match="no load pattern"):
        follow_path(NonlinearModel(s))


def test_unloaded_mechanism_is_refused():
    """A bar hinged at one end (free to swing) is a mechanism before any load."""
    s = build_structure([[0.0, 0.0], [1.0, 0.0]], [(0, 1)], section=SEC, material=MAT,
                        supports={0: "xy"}, loads={1: [0.0, -1.0]})
    with pytest.raises(MechanismError, match="1 independent mechanism"):
        follow_path(NonlinearModel(s))


def test_three_dimensional_beam_without_torsion_constant_is_refused():
    """A 3-D beam needs GJ: a section without J is named with the member."""
    sec = Section(name="noj", area=A, Iy=1e-8, Iz=1e-8, c=0.01)
    s = build_structure([[0, 0, 0], [1, 0, 0]], [(0, 1)], section=sec, material=MAT,
                        is_beam=True, supports={0: ["x", "y", "z", "rx", "ry", "rz"]})
    with pytest.raises(InputError, match="torsion constant"):
        NonlinearModel(s)


@pytest.mark.parametrize("step", [4.0, 1.0, 0.3])
def test_load_control_reports_both_yields_and_the_collapse(step):
    """The two parallel bars of ``test_yield_cap_events_at_closed_form_load_factors`` under
    load control: bar 0 yields at λ₁ = 37.5, bar 1 at λ₂ = 2 A f_y / P = 50, where the
    assembly keeps no stiffness along the load — a plastic collapse, which the path reports
    with the yield that causes it instead of stopping short of it."""
    s = _parallel()
    m = NonlinearModel(s, laws=build_failure_laws(s, {"yield": "cap"}))
    r = follow_path(m, "load", steps=400, step=step, max_load_factor=80.0, monitor=0)
    ev = [e for e in r.events if e.kind == "yield"]
    assert [e.member for e in ev] == [0, 1]
    assert_allclose([e.load_factor for e in ev], [37.5, 50.0], rtol=1e-6)
    assert r.load_factors.max() == pytest.approx(50.0, rel=1e-6)
    assert r.load_factors.max() <= 50.0 * (1 + 1e-9)
    assert r.termination.startswith("path cannot be continued at load factor 50: no "
                                    "equilibrium at a larger load factor: the structure "
                                    "collapses when member(s) 1 reach their limit")
    assert "displacement or arc-length" in r.termination


def test_load_control_stops_at_the_limit_point_and_says_why():
    """Load control cannot pass the von Mises truss's limit load (381.087 N): the path ends
    there, naming the load factor and the remedy."""
    s = build_structure([[-1.0, 0.0], [0.0, 0.1], [1.0, 0.0]], [(0, 1), (1, 2)],
                        section=Section(name="b", area=1e-4), material=Material(
                            name="m", E=1e10, G=4e9, density=0.0, yield_strength=math.nan),
                        supports={0: "xy", 2: "xy"}, loads={1: [0.0, -1.0]})
    supports = np.array(s.supports)
    supports[1, 0] = True
    s = s.with_supports(supports)
    r = follow_path(NonlinearModel(s), "load", steps=100, step=10.0, max_load_factor=500.0,
                    monitor=3)
    assert r.termination.startswith("path cannot be continued at load factor 381.0")
    assert "arc-length" in r.termination
    assert r.load_factors.max() <= 381.0871904181 * (1 + 1e-12)
    assert r.load_factors.max() > 381.0
