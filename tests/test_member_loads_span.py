"""Distributed member loads on part of a member (``span = [a, b]``) against closed forms and
PyNite.

Sources: statics of a simply supported beam (reactions of the load's resultant at its
centroid; the moment peaks where the shear force vanishes); the fixed-end moments of a
fixed-fixed Euler–Bernoulli beam, ``M_A = ∫ q x (L − x)²/L² dx`` and
``M_B = ∫ q x² (L − x)/L² dx`` over the loaded part (the influence lines of the end moments,
Roark's Formulas for Stress and Strain, 7th ed., Table 8.1 case 1d integrated over the load);
the exactness of the beam elements at their nodes (a member cut into any number of elements
has the same nodal displacements); PyNite's ``add_member_dist_load(x1, x2)``.  Every static
result here is in global equilibrium with the member loads counted as applied loads
(tests/conftest.py).
"""
import numpy as np
import pytest

from trussfe.api.model import model_from_dict
from trussfe.errors import InputError
from trussfe.fem.static import solve_static
from trussfe.model import Material, MemberLoad, Section, build_structure
from pynite_compare import assert_nodes_match_pynite

E, G, A, I, L = 2.0e11, 8.0e10, 4.0e-3, 8.0e-6, 3.0
SEC = Section("s", area=A, Iy=I, Iz=I, J=2 * I, c=0.05)
MAT = Material("m", E, G)


def beam(supports, section=SEC, is_beam=True):
    return build_structure([[0, 0], [L, 0]], [(0, 1)], section=section, material=MAT,
                           supports=supports, is_beam=is_beam)


@pytest.mark.parametrize("k", [1, 2, 4, 5])
@pytest.mark.parametrize("span", [(0.2, 0.7), (0.0, 0.4), (0.55, 1.0)])
def test_simply_supported_partial_uniform(span, k):
    """Reactions of the resultant wℓ at the span's centre; the largest moment where the shear
    force vanishes, R_A x* − w (x* − c)²/2 at x* = c + R_A/w, a station."""
    w = 1200.0
    c, d = span[0] * L, span[1] * L
    s = beam({0: ["x", "y"], 1: ["y"]}).with_extensions(
        member_loads=[MemberLoad.uniform(0, (0.0, -w), span=span)])
    r = solve_static(s, subdivisions=k)
    ell, m = d - c, 0.5 * (c + d)
    RA, RB = w * ell * (L - m) / L, w * ell * m / L
    assert r.reactions[:, 1] == pytest.approx([RA, RB], rel=1e-12)
    xs = c + RA / w
    Mmax = RA * xs - w * (xs - c) ** 2 / 2
    x = r.loaded_stations[1][0]
    Mz = r.loaded_stations[2][0][:, 5]
    ok = np.isfinite(x)
    assert np.any(np.abs(x[ok] - xs) < 1e-12)
    assert np.nanmax(np.abs(Mz)) == pytest.approx(Mmax, rel=1e-10)
    # the span's ends are stations, with the moment of statics there
    for xe in (c, d):
        j = int(np.argmin(np.abs(x[ok] - xe)))
        assert x[ok][j] == pytest.approx(xe, abs=1e-12)
        y = min(max(xe, c), d) - c
        Mx = RA * xe - w * y * (xe - c - y / 2)
        assert abs(Mz[ok][j]) == pytest.approx(Mx, rel=1e-10, abs=1e-9)


def fixed_end_moments(w, c, d):
    """∫ w x (L − x)²/L² dx and ∫ w x² (L − x)/L² dx over [c, d], by their antiderivatives."""
    def FA(x):
        return w * (L**2 * x**2 / 2 - 2 * L * x**3 / 3 + x**4 / 4) / L**2

    def FB(x):
        return w * (L * x**3 / 3 - x**4 / 4) / L**2
    return FA(d) - FA(c), FB(d) - FB(c)


@pytest.mark.parametrize("k", [1, 3, 4])
@pytest.mark.parametrize("span", [(0.25, 1.0), (0.1, 0.35), (0.0, 0.5)])
def test_fixed_fixed_partial_uniform(span, k):
    """End moments of the fixed-fixed beam: the integrals of the influence lines."""
    w = 900.0
    s = beam({0: ["x", "y", "rz"], 1: ["x", "y", "rz"]}).with_extensions(
        member_loads=[MemberLoad.uniform(0, (0.0, -w), span=span)])
    r = solve_static(s, subdivisions=k)
    MA, MB = fixed_end_moments(w, span[0] * L, span[1] * L)
    assert r.reactions[0, 2] == pytest.approx(MA, rel=1e-11)
    assert r.reactions[1, 2] == pytest.approx(-MB, rel=1e-11)
    # the vertical reactions: the load's moment about each end with the end moments
    ell, m = (span[1] - span[0]) * L, 0.5 * (span[0] + span[1]) * L
    RA = (w * ell * (L - m) + MA - MB) / L
    assert r.reactions[0, 1] == pytest.approx(RA, rel=1e-11)


@pytest.mark.parametrize("shear", [False, True])
def test_partial_element_equals_whole_elements(shear):
    """A trapezoidal load on [0.5 L, L]: one element covered in part (the Gauss rule) gives
    the nodal displacements of two elements, the second covered whole (the closed form) —
    Timoshenko elements too, as both are exact at their nodes."""
    sec = Section("s", area=A, Iy=I, Iz=I, J=2 * I, c=0.05,
                  shear_area_y=0.3 * A if shear else None,
                  shear_area_z=0.3 * A if shear else None)
    s = beam({0: ["x", "y", "rz"], 1: ["y"]}, section=sec).with_extensions(member_loads=[
        MemberLoad(0, "trapezoidal", (300.0, -500.0), (-100.0, -2500.0), span=(0.5, 1.0))])
    one = solve_static(s, subdivisions=1)
    two = solve_static(s, subdivisions=2)
    assert one.displacements == pytest.approx(two.displacements, rel=1e-12, abs=1e-18)
    assert one.reactions == pytest.approx(two.reactions, rel=1e-12, abs=1e-9)


@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
def test_axial_partial_load_midpoint_force(bar_model):
    """A bar held at both ends axially under q along [0.1 L, 0.4 L]: the ends share the load
    as a simply supported beam's reactions (a uniform bar: R_A = Q (L − m)/L); the force at
    the midpoint, beyond the load, is −R_B."""
    q = 5000.0
    sec = Section("s", area=A, Iy=I, Iz=I, J=2 * I, c=0.05)
    s = build_structure([[0, 0], [L, 0]], [(0, 1)], section=sec, material=MAT,
                        supports={0: ["x", "y"], 1: ["x", "y"]}).with_extensions(
        member_loads=[MemberLoad.uniform(0, (q, 0.0), span=(0.1, 0.4))])
    r = solve_static(s, bar_model=bar_model)
    Q, m = q * 0.3 * L, 0.25 * L
    RB = -Q * m / L                        # the reaction at B pushes back (−x)
    assert r.reactions[1, 0] == pytest.approx(RB, rel=1e-12)
    assert r.axial_force[0] == pytest.approx(RB, rel=1e-12)   # compression beyond the load


def test_element_axial_correction_of_a_partial_load():
    """The average of N over an element minus the mean of its end values, for a trapezoidal
    axial load on part of it: against the average of N = N(0) − Q(x) by a fine midpoint
    rule (Q from the load's definition)."""
    from trussfe.fem.member_loads import element_axial_correction
    h, xi0, xi1, qa, qb = 2.0, 0.3, 0.8, 700.0, -200.0
    got = element_axial_correction(1, np.array([0]), np.array([h]), np.array([qa]),
                                   np.array([qb]), np.zeros(0, int), np.zeros(0),
                                   np.zeros(0), np.array([xi0]), np.array([xi1]))[0]
    n = 200_000
    x = (np.arange(n) + 0.5) * h / n
    s = np.clip(x, xi0 * h, xi1 * h) - xi0 * h              # loaded length before x
    k = (qb - qa) / ((xi1 - xi0) * h)
    Q = qa * s + k * s**2 / 2
    Qh = qa * (xi1 - xi0) * h + k * ((xi1 - xi0) * h) ** 2 / 2
    assert got == pytest.approx(-Q.mean() + Qh / 2, rel=1e-8)


def test_span_outside_unit_interval_refused():
    with pytest.raises(ValueError, match="span"):
        MemberLoad.uniform(0, (0.0, -1.0), span=(0.5, 0.5))
    with pytest.raises(ValueError, match="span"):
        MemberLoad.uniform(0, (0.0, -1.0), span=(-0.1, 0.5))
    with pytest.raises(ValueError, match="point load"):
        MemberLoad(0, "point", at=0.5, force=(0.0, 1.0), span=(0.0, 0.5))


MODEL = {
    "model": {"dimension": 2},
    "materials": {"st": {"E": E, "G": G}},
    "sections": {"b": {"area": A, "Iz": I, "c": 0.1}},
    "nodes": {"A": [0.0, 0.0], "B": [4.0, 0.0]},
    "members": {"AB": {"nodes": ["A", "B"], "section": "b", "material": "st",
                       "type": "beam"}},
    "supports": {"A": ["x", "y"], "B": ["y"]},
}


@pytest.mark.parametrize("span,message", [
    ([0.6, 0.2], "0 <= a < b <= 1"), ([0.2, 1.5], "0 <= a < b <= 1"),
    ([0.2], "expected 2 numbers"), (["a", 1.0], "finite number")])
def test_bad_span_in_a_model_file(span, message):
    d = dict(MODEL, member_loads=[{"member": "AB", "kind": "uniform", "q": [0.0, -1.0],
                                   "span": span}])
    with pytest.raises(InputError, match=message) as exc:
        model_from_dict(d)
    assert "member_loads[0] (member AB).span" in str(exc.value)


@pytest.mark.parametrize("load,needs", [
    ({"kind": "uniform", "span": [0.0, 0.5]}, "missing 'q' (a uniform load needs q)"),
    ({"kind": "trapezoidal", "q_start": [0.0, -1.0], "span": [0.0, 0.5]},
     "missing 'q_end' (a trapezoidal load needs q_start and q_end)")])
def test_span_is_optional_in_the_missing_key_message(load, needs):
    d = dict(MODEL, member_loads=[{"member": "AB", **load}])
    with pytest.raises(InputError, match=needs.replace("(", r"\(").replace(")", r"\)")):
        model_from_dict(d)


def test_span_on_a_point_load_is_an_unknown_key():
    d = dict(MODEL, member_loads=[{"member": "AB", "kind": "point", "at": 0.5,
                                   "F": [0.0, -1.0], "span": [0.0, 0.5]}])
    with pytest.raises(InputError, match="unknown key 'span'"):
        model_from_dict(d)


def test_span_round_trip(tmp_path):
    """The model writer keeps a span (and writes none for a load on the whole member)."""
    from trussfe import read_model
    from trussfe.io.model_writer import write_model
    d = dict(MODEL, member_loads=[
        {"member": "AB", "kind": "trapezoidal", "q_start": [0.0, -1.0], "q_end": [0.0, -3.0],
         "span": [0.25, 0.75]},
        {"member": "AB", "kind": "uniform", "q": [0.0, -2.0]}])
    s = model_from_dict(d)
    p = tmp_path / "m.toml"
    write_model(s, p)
    text = p.read_text()
    assert text.count("span") == 1
    back = read_model(p).extensions["member_loads"]
    assert back == s.extensions["member_loads"]


# Iy = Iz: the two codes orient the local axes of a vertical member differently
FRAME3D = {
    "model": {"dimension": 3},
    "materials": {"st": {"E": E, "G": G}},
    "sections": {"b": {"area": A, "Iy": I, "Iz": I, "J": 2 * I, "c": 0.1}},
    "nodes": {"A": [0.0, 0.0, 0.0], "B": [0.0, 0.0, 3.0], "C": [4.0, 0.0, 3.0],
              "D": [4.0, 3.0, 3.0]},
    "members": {m: {"nodes": list(m), "section": "b", "material": "st", "type": "beam"}
                for m in ("AB", "BC", "CD")},
    "supports": {"A": ["x", "y", "z", "rx", "ry", "rz"],
                 "D": ["x", "y", "z", "rx", "ry", "rz"]},
    "member_loads": [
        {"member": "BC", "kind": "uniform", "q": [0.0, 0.0, -5.0e3], "span": [0.25, 0.75]},
        {"member": "CD", "kind": "trapezoidal", "q_start": [0.0, 0.0, -2.0e3],
         "q_end": [0.0, 0.0, -6.0e3], "span": [0.2, 0.8]},
        {"member": "AB", "kind": "uniform", "q": [1.0e3, 0.0, 0.0], "span": [0.0, 0.3]},
        {"member": "BC", "kind": "trapezoidal", "q_start": [0.0, 800.0, 0.0],
         "q_end": [0.0, 200.0, 0.0], "span": [0.6, 1.0]},
    ],
}


@pytest.mark.parametrize("k", [1, 3])
def test_3d_frame_partial_loads_against_pynite(k):
    """PyNite's distributed loads between x1 and x2 on the same frame: displacements,
    reactions and the bending moment along BC."""
    pynite = pytest.importorskip("Pynite")
    m = pynite.FEModel3D()
    for n, (x, y, z) in FRAME3D["nodes"].items():
        m.add_node(n, x, y, z)
    m.add_material("st", E, G, 0.25, 7850.0)
    m.add_section("b", A, I, I, 2 * I)
    for name in FRAME3D["members"]:
        m.add_member(name, name[0], name[1], "st", "b")
    for n in ("A", "D"):
        m.def_support(n, True, True, True, True, True, True)
    m.add_member_dist_load("BC", "FZ", -5.0e3, -5.0e3, 1.0, 3.0)
    m.add_member_dist_load("CD", "FZ", -2.0e3, -6.0e3, 0.6, 2.4)
    m.add_member_dist_load("AB", "FX", 1.0e3, 1.0e3, 0.0, 0.9)
    m.add_member_dist_load("BC", "FY", 800.0, 200.0, 2.4, 4.0)
    m.analyze_linear(check_statics=False)
    combo = next(iter(m.load_combos))

    r = solve_static(model_from_dict(FRAME3D), subdivisions=k)
    s = r.structure
    assert_nodes_match_pynite(r, m, combo, moving=("B", "C"), supported=("A", "D"))
    # BC's moment about its local axes along it, at the stations (magnitudes: the two codes
    # orient the local y and z of a horizontal member differently)
    members, x, F = r.loaded_stations
    j = list(members).index(s.member_index("BC"))
    ok = np.isfinite(x[j])
    bc = m.members["BC"]
    for xi, Fi in zip(x[j][ok], F[j][ok]):
        mine = sorted(np.abs(Fi[[4, 5]]))
        theirs = sorted(abs(bc.moment(d, float(xi), combo)) for d in ("My", "Mz"))
        assert mine == pytest.approx(theirs, rel=1e-6, abs=1e-3)


def test_many_point_loads_are_refused_for_their_memory_before_any_array(monkeypatch):
    """The section forces along a member take every load at every station: (loads ×
    stations) arrays, 30 GB for 10,000 point loads on one bar, which the kernel killed.  The
    size is checked first and refused naming member_loads; here with 200 loads against a
    machine said to have 10 MB free (the same model runs when memory allows)."""
    import trussfe.budget as budget
    s = build_structure([[0.0, 0.0], [2.0, 0.0]], [(0, 1)], section=Section.tube("t", 0.05),
                        material=Material("st", 2e11, 8e10), supports={0: "xy", 1: "y"},
                        is_beam=True)
    loads = [MemberLoad(0, "point", at=float(a), force=(0.0, -1.0))
             for a in np.linspace(0.01, 0.99, 200)]
    s = s.with_extensions(member_loads=loads)
    r = solve_static(s, "pinned-beam")
    assert np.abs(r.reactions[:, 1]).sum() == pytest.approx(200.0, rel=1e-12)
    monkeypatch.setattr(budget, "available_memory", lambda: 10 * 2**20)
    with pytest.raises(InputError, match="member_loads: the section forces of 200 member "
                                         "loads"):
        solve_static(s, "pinned-beam")
