# SPDX-License-Identifier: MIT
"""Load cases, combinations, imposed strains, prescribed displacements, springs and rotary
inertia against closed forms (the source of each is named in its test).  Every static result
here is checked for global equilibrium by tests/conftest.py (spring forces as reactions)."""
from __future__ import annotations

import json

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe.cli import main
from trussfe.errors import InputError, MechanismError
from trussfe.fem.load_cases import solve_load_cases

EXACT = 1e-10
E, A, ALPHA = 2.0e11, 1.0e-4, 1.2e-5
STEEL = {"E": E, "G": 8.0e10, "thermal_expansion": ALPHA}


def _model(nodes, members, supports, *, dim=2, section=None, **tables):
    data = {"model": {"dimension": dim}, "materials": {"st": dict(STEEL)},
            "sections": {"s": section or {"area": A}},
            "nodes": nodes,
            "members": {k: {"nodes": list(v[:2]), "section": "s", "material": "st",
                            **(v[2] if len(v) > 2 else {})} for k, v in members.items()},
            "supports": supports, **tables}
    return trussfe.model_from_dict(data)


# ------------------------------------------------------------------------- imposed strains
def test_heated_bar_between_walls():
    """A bar fixed at both ends and warmed by ΔT: N = −EAαΔT, no displacement (Timoshenko &
    Gere, Mechanics of Materials, thermal stress in a restrained bar).  Two bars in series
    with the middle joint free along them."""
    dT = 35.0
    s = _model({"A": [0, 0], "B": [1.3, 0], "C": [2.0, 0]},
               {"AB": ("A", "B"), "BC": ("B", "C")},
               {"A": ["x", "y"], "B": ["y"], "C": ["x", "y"]},
               load_cases={"hot": {"temperature": [{"members": ["AB", "BC"],
                                                    "delta_T": dT}]}})
    r = trussfe.static(s, case="hot")
    assert_allclose(r.axial_force, -E * A * ALPHA * dT, rtol=EXACT)
    assert_allclose(r.displacement, 0.0, atol=1e-18)


def test_heated_clamped_beam_carries_no_moment():
    """A beam clamped at both ends and warmed uniformly: N = −EAαΔT at every station,
    no bending (a uniform ΔT strains the axis only)."""
    dT = -20.0
    s = _model({"A": [0, 0], "B": [2.0, 0]}, {"AB": ("A", "B", {"type": "beam"})},
               {"A": ["x", "y", "rz"], "B": ["x", "y", "rz"]},
               section={"area": A, "Iz": 2e-6, "c": 0.05},
               load_cases={"cold": {"temperature": [{"member": "AB", "delta_T": dT}]}})
    r = trussfe.static(s, case="cold", subdivisions=3)
    N = r.section_forces[0, :, 0]
    assert_allclose(N, -E * A * ALPHA * dT, rtol=EXACT)
    assert_allclose(r.section_forces[0, :, 5], 0.0, atol=1e-9 * abs(N[0]))
    assert_allclose(r.reaction[:, 0], [E * A * ALPHA * dT, -E * A * ALPHA * dT], rtol=EXACT)


def _three_bar(**tables):
    h, th = 2.0, np.radians(40.0)
    b = h * np.tan(th)
    s = _model({"L": [-b, h], "M": [0.0, h], "R": [b, h], "J": [0.0, 0.0]},
               {"JL": ("J", "L"), "JM": ("J", "M"), "JR": ("J", "R")},
               {"L": ["x", "y"], "M": ["x", "y"], "R": ["x", "y"]}, **tables)
    return s, h, np.cos(th)


@pytest.mark.parametrize("bar_model", ["truss", "pinned-beam"])
def test_indeterminate_truss_with_a_member_too_long(bar_model):
    """Three-bar truss (outer bars at ±θ), middle bar too long by δ.  Force method: the
    self-stress state n = (−1/(2cos θ), 1, −1/(2cos θ)) and compatibility
    Σ n (N L/EA + e0) = 0 give N_mid = −2EAδ cos³θ / (h (1 + 2 cos³θ)) (Timoshenko & Young,
    Theory of Structures, lack of fit)."""
    delta = 0.4e-3
    s, h, c = _three_bar(load_cases={"fit": {"length_error": [{"member": "JM",
                                                                "delta": delta}]}},
                         section={"area": A, "Iz": 1e-8, "c": 0.01})
    r = trussfe.static(s, case="fit", bar_model=bar_model, subdivisions=3)
    n_mid = -2 * E * A * delta * c**3 / (h * (1 + 2 * c**3))
    assert_allclose(r.axial_force, [-n_mid / (2 * c), n_mid, -n_mid / (2 * c)], rtol=EXACT)
    # the same lack of fit as an initial strain δ/L
    if bar_model == "pinned-beam":                       # along the whole member
        assert_allclose(r.section_forces[1, :, 0], n_mid, rtol=EXACT)
    s2, _, _ = _three_bar(load_cases={"fit": {"initial_strain": [{"member": "JM",
                                                                   "strain": delta / h}]}})
    assert_allclose(trussfe.static(s2, case="fit").axial_force, r.axial_force, rtol=EXACT)


def test_moved_support_of_an_indeterminate_truss():
    """Moving the middle support of the three-bar truss up by Δ (away from the joint along
    its bar) is the lack of fit of a bar Δ too short: N_mid = +2EAΔ cos³θ / (h (1 + 2cos³θ))
    (force method, as above)."""
    d = 0.3e-3
    s, h, c = _three_bar(load_cases={"settle": {"prescribed": {"M": {"y": d}}}})
    r = trussfe.static(s, case="settle")
    n_mid = 2 * E * A * d * c**3 / (h * (1 + 2 * c**3))
    assert_allclose(r.axial_force, [-n_mid / (2 * c), n_mid, -n_mid / (2 * c)], rtol=EXACT)
    assert_allclose(r.displacement[1], [0.0, d], rtol=EXACT)


def test_determinate_truss_with_a_length_error_moves_without_stress():
    """Two-bar truss, bar AJ too long by δ: a statically determinate truss takes up a lack of
    fit without force; the joint moves so that AJ lengthens by δ and BJ not at all
    (compatibility e·u = elongation for each bar, Williot)."""
    delta, a, h = 1.0e-3, 0.8, 1.1
    s = _model({"A": [-a, h], "B": [a, h], "J": [0.0, 0.0]},
               {"AJ": ("A", "J"), "BJ": ("B", "J")}, {"A": ["x", "y"], "B": ["x", "y"]},
               load_cases={"fit": {"length_error": [{"member": "AJ", "delta": delta}]}})
    r = trussfe.static(s, case="fit")
    assert_allclose(r.axial_force, 0.0, atol=1e-9)
    L = np.hypot(a, h)
    e = np.array([[a, -h], [-a, -h]]) / L                    # unit vectors A→J, B→J
    assert_allclose(r.displacement[2], np.linalg.solve(e, [delta, 0.0]), rtol=EXACT)
    assert_allclose(r.reaction, 0.0, atol=1e-9)


# ------------------------------------------------------------------------- settlement
def test_fixed_fixed_beam_end_settlement():
    """Beam clamped at both ends, the end B settles by δ: end shears 12EIδ/L³ and end moments
    6EIδ/L², both ends the same sense (slope-deflection equations)."""
    L, I, delta = 3.0, 4.0e-6, 5.0e-3
    s = _model({"A": [0, 0], "B": [L, 0]}, {"AB": ("A", "B", {"type": "beam"})},
               {"A": ["x", "y", "rz"], "B": ["x", "y", "rz"]},
               section={"area": A, "Iz": I, "c": 0.05},
               load_cases={"settle": {"prescribed": {"B": {"y": -delta}}}})
    r = trussfe.static(s, case="settle")
    V, M = 12 * E * I * delta / L**3, 6 * E * I * delta / L**2
    assert_allclose(r.reaction[:, 1], [V, -V], rtol=EXACT)
    assert_allclose(r.reaction_moment[:, 0], [M, M], rtol=EXACT)
    assert_allclose(np.abs(r.end_forces[0, :, 5]), [M, M], rtol=EXACT)
    assert_allclose(r.displacement[1], [0.0, -delta], rtol=EXACT)


# ------------------------------------------------------------------------- springs
def test_cantilever_on_a_spring():
    """Cantilever with a spring k under its tip and a tip load P: the tip deflects
    P/(k + 3EI/L³) (springs in parallel); the spring's force −k v is a reaction."""
    L, I, k, P = 2.0, 3.0e-6, 4.0e5, -1500.0
    s = _model({"A": [0, 0], "B": [L, 0]}, {"AB": ("A", "B", {"type": "beam"})},
               {"A": ["x", "y", "rz"]}, section={"area": A, "Iz": I, "c": 0.05},
               springs={"B": {"y": k}}, loads={"B": [0.0, P]})
    r = trussfe.static(s)
    v = P / (k + 3 * E * I / L**3)
    assert_allclose(r.displacement[1, 1], v, rtol=EXACT)
    assert_allclose(r.reaction[1, 1], -k * v, rtol=EXACT)
    assert_allclose(r.reaction[0, 1] + r.reaction[1, 1], -P, rtol=EXACT)
    doc = r.to_dict()
    assert doc["nodes"]["B"]["reaction"][1] == pytest.approx(-k * v, rel=EXACT)


def test_spring_removes_a_mechanism():
    """A bar pinned at A and free to swing at B is a mechanism; a spring k on B's transverse
    DOF makes it carry a transverse load P with v = P/k and no bar force (statics)."""
    k, P = 2.0e4, 300.0
    base = dict(nodes={"A": [0, 0], "B": [1.5, 0]}, members={"AB": ("A", "B")},
                supports={"A": ["x", "y"]})
    with pytest.raises(MechanismError):
        trussfe.static(_model(**base, loads={"B": [0.0, P]}))
    r = trussfe.static(_model(**base, loads={"B": [0.0, P]}, springs={"B": {"y": k}}))
    assert_allclose(r.displacement[1], [0.0, P / k], rtol=EXACT, atol=1e-18)
    assert_allclose(r.axial_force, 0.0, atol=1e-9)


def test_springs_and_rotary_inertia_in_modes():
    """A massless cantilever with a tip mass m and rotary inertia J: the 2-DOF system of the
    tip (v, θ) with the cantilever's tip stiffness [[12EI/L³, −6EI/L²], [−6EI/L², 4EI/L]]
    (slope-deflection) and M = diag(m, J); Hermite elements are exact for this stiffness."""
    L, I, m, J = 1.2, 2.0e-6, 5.0, 0.3
    s = _model({"A": [0, 0], "B": [L, 0]}, {"AB": ("A", "B", {"type": "beam"})},
               {"A": ["x", "y", "rz"], "B": ["x"]}, section={"area": A, "Iz": I, "c": 0.05},
               masses={"B": {"mass": m, "inertia": J}})
    r = trussfe.modes(s, count=2)
    K = E * I * np.array([[12 / L**3, -6 / L**2], [-6 / L**2, 4 / L]])
    w2 = np.sort(np.linalg.eigvals(np.linalg.solve(np.diag([m, J]), K)).real)
    assert_allclose(r.frequencies_hz, np.sqrt(w2) / (2 * np.pi), rtol=1e-9)


# ------------------------------------------------------------------------- combinations
def _frame_with_cases():
    """A portal frame with every kind of case (2-D, beams, springs)."""
    return _model(
        {"A": [0, 0], "B": [0, 3.0], "C": [4.0, 3.0], "D": [4.0, 0]},
        {"AB": ("A", "B", {"type": "beam"}), "BC": ("B", "C", {"type": "beam"}),
         "CD": ("C", "D", {"type": "beam"}), "AC": ("A", "C")},
        {"A": ["x", "y", "rz"], "D": ["x", "y"]},
        section={"area": A, "Iz": 5e-6, "c": 0.05},
        model={"dimension": 2, "gravity": [0.0, -9.81]},
        materials={"st": {**STEEL, "density": 7850.0}},
        springs={"C": {"x": 3.0e5}},
        load_cases={"dead": {"gravity": True},
                    "wind": {"loads": {"B": [2000.0, 0.0]}},
                    "settle": {"prescribed": {"D": {"y": -4e-3}}},
                    "heat": {"temperature": [{"members": ["BC"], "delta_T": 30.0}],
                             "length_error": [{"member": "AC", "delta": 2e-4}]}},
        combinations={"ULS": {"dead": 1.35, "wind": 1.5, "settle": 1.0},
                      "SLS": {"dead": 1.0, "wind": -1.0, "heat": 1.0}})


def test_combination_is_the_factored_sum_of_its_cases():
    """Linearity: a combination's displacements, reactions and section forces equal the
    factored sum of its cases' (superposition), to round-off."""
    sol = solve_load_cases(_frame_with_cases(), subdivisions=3)
    for name, factors in sol.factors.items():
        combo = sol.combinations[name]
        for key in ("displacements", "reactions", "section_forces", "end_forces",
                    "axial_force"):
            total = sum(f * getattr(sol.cases[c], key) for c, f in factors.items())
            scale = np.nanmax(np.abs(total))
            assert_allclose(getattr(combo, key), total, rtol=0, atol=1e-12 * scale), key


def test_combination_equals_a_solve_of_the_summed_case():
    """A combination of nodal-load cases equals the single-case solve of the summed loads
    (the model's [loads] path): two routes to the same state."""
    s = _frame_with_cases()
    sol = solve_load_cases(s, combinations=["ULS"], cases=[], subdivisions=3)
    r = sol.combinations["ULS"]
    # the same without the settlement: a plain model with the factored loads and gravity
    plain = s.without_extensions("load_cases").with_loads(
        np.array([[0, 0, 0], [3000.0, 0, 0], [0, 0, 0], [0, 0, 0]])).with_gravity(
        [0.0, -9.81 * 1.35])
    settle = sol.cases["settle"]
    direct = trussfe.static(plain, subdivisions=3).solution
    assert_allclose(r.displacements, direct.displacements + settle.displacements,
                    rtol=0, atol=1e-12 * np.abs(r.displacements).max())


def test_envelope_names_the_governing_combination():
    """The envelope's max/min of each quantity is the largest/smallest over the
    combinations, and names the combination where it occurs."""
    res = trussfe.static(_frame_with_cases(), subdivisions=3)
    env = res.envelope
    assert env.over == "combinations"
    N = np.stack([c.axial_force for c in res.combinations.values()])
    names = list(res.combinations)
    mx, imx, mn, imn = env.fields["axial_force"]
    assert_allclose(mx, N.max(axis=0))
    assert_allclose(mn, N.min(axis=0))
    assert [names[i] for i in imx] == [names[i] for i in N.argmax(axis=0)]
    doc = res.to_dict()
    for j, mid in enumerate(res.member_ids):
        e = doc["envelope"]["members"][mid]["axial_force"]
        assert e["max_by"] == names[int(N[:, j].argmax())]
        assert e["max"] == pytest.approx(N[:, j].max())
    # the reactions of the spring node are enveloped too
    assert "C" in doc["envelope"]["nodes"] and "D" in doc["envelope"]["nodes"]


def test_all_cases_json_and_vtk(tmp_path):
    """``trussfe static --all`` writes every case and combination, the envelope, and one
    .vtu per result listed by a .pvd; the API's to_dict() is the CLI's JSON."""
    from trussfe.io.model_writer import write_model  # noqa: F401  (model files are TOML)
    text = MODEL_TOML
    p = tmp_path / "m.toml"
    p.write_text(text)
    out = tmp_path / "r.json"
    assert main(["static", str(p), "--json", str(out), "--vtk", str(tmp_path / "v.vtu")]) == 0
    doc = json.loads(out.read_text())
    assert set(doc["cases"]) == {"dead", "wind", "settle"} and set(doc["combinations"]) == {
        "ULS"}
    assert doc["combinations"]["ULS"]["factors"] == {"dead": 1.35, "wind": 1.5}
    assert doc == json.loads(json.dumps(trussfe.static(p).to_dict()))
    from trussfe.io.vtk import read_pvd
    files = [f.name for _, f in read_pvd(tmp_path / "v.pvd")]
    assert files == ["v_case_dead.vtu", "v_case_wind.vtu", "v_case_settle.vtu",
                     "v_combination_ULS.vtu"]
    assert all((tmp_path / f).is_file() for f in files)
    one = tmp_path / "one.json"
    assert main(["static", str(p), "--combination", "ULS", "--json", str(one)]) == 0
    d1 = json.loads(one.read_text())
    assert d1["combination"] == "ULS"
    assert d1["members"] == doc["combinations"]["ULS"]["members"]


MODEL_TOML = """\
[model]
dimension = 2
gravity = [0.0, -9.81]

[materials.st]
E = 2.0e11
density = 7850.0

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
C = ["y"]

[load_cases.dead]
gravity = true

[load_cases.wind]
loads = { B = [500.0, 0.0] }

[load_cases.settle]
prescribed = { C = { y = -0.002 } }

[combinations]
ULS = { dead = 1.35, wind = 1.5 }
"""


def test_model_without_cases_is_its_default_case():
    """[loads] and gravity are the one case "default": --case default gives the same numbers
    as a plain run, and --all lists it."""
    p = MODEL_TOML.split("[load_cases.dead]")[0] + "[loads]\nB = [500.0, -100.0]\n"
    s = trussfe.model_from_dict(__import__("trussfe.io.toml_text", fromlist=["x"]).loads(p))
    plain = trussfe.static(s)
    case = trussfe.static(s, case="default")
    assert_allclose(case.axial_force, plain.axial_force, rtol=1e-13)
    assert case.to_dict()["case"] == "default"
    allr = trussfe.static(s, all_cases=True)
    assert list(allr.cases) == ["default"] and allr.envelope.over == "cases"


# ------------------------------------------------------------------------- buckling
def test_buckling_about_a_combination():
    """A pinned column under two cases P1 and P2 combined with factors a and b buckles at
    λ (a P1 + b P2) = π²EI/L² (Euler; 8 Hermite elements are 3.3e-5 high)."""
    L, I = 2.0, 1.0e-8
    P1, P2, a, b = 1.0, 3.0, 1.35, 0.5
    s = _model({"A": [0, 0], "B": [0, L]}, {"AB": ("A", "B")},
               {"A": ["x", "y"], "B": ["x"]}, section={"area": A, "Iz": I, "c": 0.01},
               load_cases={"one": {"loads": {"B": [0.0, -P1]}},
                           "two": {"loads": {"B": [0.0, -P2]}}},
               combinations={"ULS": {"one": a, "two": b}})
    r = trussfe.buckling(s, combination="ULS", count=1, subdivisions=8)
    pe = np.pi**2 * E * I / L**2
    assert r.critical_load_factor * (a * P1 + b * P2) == pytest.approx(pe, rel=6e-5)
    assert r.to_dict()["combination"] == "ULS"
    with pytest.raises(InputError, match="--case NAME or --combination NAME"):
        trussfe.buckling(s)


def test_buckling_of_a_heated_restrained_column():
    """A column held at both ends and warmed buckles when EAαΔT reaches π²EI/L²: the load
    factor of the thermal case is π²EI/(L² EAαΔT) (Timoshenko & Gere, Theory of Elastic
    Stability, thermal buckling of a restrained bar)."""
    L, I, dT = 2.0, 1.0e-8, 10.0
    s = _model({"A": [0, 0], "B": [0, L]}, {"AB": ("A", "B")},
               {"A": ["x", "y"], "B": ["x", "y"]}, section={"area": A, "Iz": I, "c": 0.01},
               load_cases={"hot": {"temperature": [{"member": "AB", "delta_T": dT}]}})
    r = trussfe.buckling(s, case="hot", count=1, subdivisions=8)
    expected = np.pi**2 * E * I / L**2 / (E * A * ALPHA * dT)
    assert r.critical_load_factor == pytest.approx(expected, rel=6e-5)


# ------------------------------------------------------------------------- options
def test_static_options_are_keyword_only_and_checked():
    s = _frame_with_cases()
    with pytest.raises(TypeError):
        trussfe.static(s, "dead")
    with pytest.raises(TypeError):
        trussfe.static(s, cases="dead")
    with pytest.raises(InputError, match="--case"):
        trussfe.static(s, case="nope")
    with pytest.raises(InputError, match="--combination"):
        trussfe.static(s, combination="nope")
    with pytest.raises(InputError, match="not --case and --all"):
        trussfe.static(s, case="dead", all_cases=True)


def test_model_format_example_runs(tmp_path):
    """The worked example of docs/model-format.md (*Load cases*) is a valid model: static
    over every case, buckling about a combination, modes with its rotary inertia."""
    import re
    from pathlib import Path
    text = (Path(__file__).parents[1] / "docs" / "model-format.md").read_text()
    block = next(b for b in re.findall(r"```toml\n(.*?)```", text, re.S)
                 if "[load_cases.dead]" in b)
    p = tmp_path / "portal.toml"
    p.write_text(block)
    res = trussfe.static(p)
    assert list(res.cases) == ["dead", "wind", "settlement", "thermal"]
    assert list(res.combinations) == ["ULS", "SLS"]
    assert np.isfinite(trussfe.buckling(p, combination="ULS", count=2).load_factors).all()
    assert trussfe.modes(p, count=3).frequencies_hz.size == 3


def test_rotary_inertia_at_a_pin_joint_is_refused_by_modes():
    """A rotary inertia needs a rotation to sit on: at a pin joint modes refuses it in one
    line, naming the node."""
    s = _model({"A": [0, 0], "B": [1, 0]}, {"AB": ("A", "B")},
               {"A": ["x", "y"], "B": ["y"]}, masses={"B": {"mass": 1.0, "inertia": 0.1}},
               materials={"st": {**STEEL, "density": 7850.0}})
    with pytest.raises(InputError, match=r"masses\.B: acts on rotation rz"):
        trussfe.modes(s, count=1)



def test_a_spring_on_a_pin_joints_rotation_names_the_model_file(tmp_path, capsys):
    """docs/bad-input.md: one line naming the file and the item.  A spring on the rotation
    of a pin joint is refused by the analysis (the reader cannot know which joints are
    pinned before the members are discretised), with the model file before the item."""
    from trussfe.cli import main
    f = tmp_path / "pinned.toml"
    f.write_text("""[model]
dimension = 2
[materials.st]
E = 2.0e11
[sections.t]
area = 1e-4
[nodes]
A = [0.0, 0.0]
B = [1.0, 0.0]
C = [0.5, 0.5]
[members]
AB = { nodes = ["A", "B"], section = "t", material = "st" }
AC = { nodes = ["A", "C"], section = "t", material = "st" }
BC = { nodes = ["B", "C"], section = "t", material = "st" }
[supports]
A = ["x", "y"]
B = ["y"]
[springs]
B = { rz = 1000.0 }
[loads]
C = [0.0, -100.0]
""")
    assert main(["static", str(f)]) == 2
    err = capsys.readouterr().err
    assert err == (f"trussfe: error: {f}: springs.B: acts on rotation rz, which this node does "
                   "not have (a pin joint: no beam is rigidly attached); remove it\n")

def test_written_model_keeps_its_cases(tmp_path):
    """write_model writes [springs], rotary inertia, [load_cases] and [combinations]: the
    model read back gives the same results case by case."""
    from trussfe.io.model_writer import write_model
    s = _frame_with_cases().with_extensions(
        rotary_inertia=__import__("trussfe.model.node_supports", fromlist=["x"])
        .RotaryInertia(np.array([[0.0], [0.5], [0.0], [0.0]])))
    back = trussfe.read_model(write_model(s, tmp_path / "m.toml"))
    a, b = trussfe.static(s, subdivisions=2), trussfe.static(back, subdivisions=2)
    assert list(a.cases) == list(b.cases) and list(a.combinations) == list(b.combinations)
    for name in a.cases:
        assert_allclose(b.cases[name].displacement, a.cases[name].displacement, rtol=1e-13,
                        atol=1e-20)
    assert_allclose(back.extensions["rotary_inertia"].inertia,
                    s.extensions["rotary_inertia"].inertia)


# ------------------------------------------------------------------------- 3-D
_BOX3 = {"area": A, "Iy": 3.0e-6, "Iz": 3.0e-6, "J": 5.0e-6, "c": 0.05}
_CLAMP3 = ["x", "y", "z", "rx", "ry", "rz"]


def test_prescribed_end_rotation_of_a_clamped_beam_3d():
    """A 3-D beam clamped at both ends whose end B is turned by θ about z: end moments
    4EIθ/L at B and 2EIθ/L at A, end shears 6EIθ/L² (slope-deflection equations)."""
    L, th = 2.5, 2.0e-3
    s = _model({"A": [0, 0, 0], "B": [L, 0, 0]}, {"AB": ("A", "B", {"type": "beam"})},
               {"A": _CLAMP3, "B": _CLAMP3}, dim=3, section=_BOX3,
               load_cases={"turn": {"prescribed": {"B": {"rz": th}}}})
    r = trussfe.static(s, case="turn")
    EI = E * _BOX3["Iz"]
    assert_allclose(r.reaction_moment[:, 2], [2 * EI * th / L, 4 * EI * th / L], rtol=EXACT)
    assert_allclose(r.reaction[:, 1], [6 * EI * th / L**2, -6 * EI * th / L**2], rtol=EXACT)
    assert_allclose(r.rotation[1], [0.0, 0.0, th], rtol=EXACT, atol=1e-18)


def test_rotational_springs_at_a_cantilever_tip_3d():
    """A 3-D beam clamped at A, its end B held in translation and by rotational springs:
    under an end torque T the twist is T/(k_x + GJ/L), under an end moment M about y the
    rotation M/(k_y + 4EI/L) (springs in parallel with the member's end stiffness; 4EI/L is
    the rotational stiffness of a propped end, slope-deflection)."""
    L, kx, ky, T, M = 1.5, 2.0e5, 7.0e5, 300.0, -450.0
    s = _model({"A": [0, 0, 0], "B": [L, 0, 0]}, {"AB": ("A", "B", {"type": "beam"})},
               {"A": _CLAMP3, "B": ["x", "y", "z"]}, dim=3, section=_BOX3,
               springs={"B": {"rx": kx, "ry": ky}},
               load_cases={"torque": {"loads": {"B": [0, 0, 0, T, M, 0]}}})
    r = trussfe.static(s, case="torque")
    G, J, EI = STEEL["G"], _BOX3["J"], E * _BOX3["Iy"]
    phi = T / (kx + G * J / L)
    psi = M / (ky + 4 * EI / L)
    assert_allclose(r.rotation[1, :2], [phi, psi], rtol=EXACT)
    assert_allclose(r.reaction_moment[1, :2], [-kx * phi, -ky * psi], rtol=EXACT)


def test_buckling_combination_from_the_command_line(tmp_path):
    """``trussfe buckling --combination`` on a model file: the JSON names the combination
    and the load factor is that of the combined state (Euler, as above); without a choice a
    model with load cases is refused in one line, exit status 2."""
    p = tmp_path / "col.toml"
    p.write_text("""\
[model]
dimension = 2
[materials.st]
E = 2.0e11
[sections.s]
area = 1.0e-4
Iz = 1.0e-8
c = 0.01
[nodes]
A = [0.0, 0.0]
B = [0.0, 2.0]
[members]
AB = { nodes = ["A", "B"], section = "s", material = "st" }
[supports]
A = ["x", "y"]
B = ["x"]
[load_cases.one]
loads = { B = [0.0, -1.0] }
[load_cases.two]
loads = { B = [0.0, -3.0] }
[combinations]
ULS = { one = 1.35, two = 0.5 }
""")
    out = tmp_path / "b.json"
    assert main(["buckling", str(p), "--combination", "ULS", "--count", "1",
                 "--subdivisions", "8", "--json", str(out)]) == 0
    doc = json.loads(out.read_text())
    pe = np.pi**2 * E * 1.0e-8 / 2.0**2
    assert doc["combination"] == "ULS"
    assert doc["critical_load_factor"] * (1.35 + 1.5) == pytest.approx(pe, rel=6e-5)
    assert main(["buckling", str(p)]) == 2


def test_load_case_data_are_read_only_also_after_pickling():
    """The case, spring and inertia arrays of a model are read-only, and stay so through
    pickle and deepcopy (a model is immutable)."""
    import copy
    import pickle
    s = _frame_with_cases()
    for model in (s, pickle.loads(pickle.dumps(s)), copy.deepcopy(s)):
        table = model.extensions["load_cases"]
        arrays = [table.case("settle").prescribed, table.case("heat").delta_T,
                  table.case("heat").length_error, table.case("wind").loads,
                  model.extensions["springs"].stiffness]
        for a in arrays:
            assert not a.flags.writeable
            with pytest.raises(ValueError):
                a[0] = 1.0


def test_member_loads_in_load_cases():
    """A member load in a case: a simply supported beam under uniform q has reactions qL/2
    and midspan moment qL²/8 (statics); a combination of it with a nodal case is their
    factored sum, and its JSON has the section forces along the loaded member."""
    L, q = 4.0, -800.0
    s = _model({"A": [0, 0], "B": [L, 0]}, {"AB": ("A", "B", {"type": "beam"})},
               {"A": ["x", "y"], "B": ["y"]}, section={"area": A, "Iz": 8e-6, "c": 0.1},
               load_cases={"floor": {"member_loads": [{"member": "AB", "kind": "uniform",
                                                        "q": [0.0, q]}]},
                           "end": {"loads": {"B": [0.0, 0.0, 100.0]}}},
               combinations={"ULS": {"floor": 1.5, "end": 2.0}})
    res = trussfe.static(s, subdivisions=4)
    floor = res.cases["floor"]
    assert_allclose(floor.reaction[:, 1], [-q * L / 2, -q * L / 2], rtol=EXACT)
    assert_allclose(abs(floor.section_forces[0, 2, 5]), abs(q) * L**2 / 8, rtol=EXACT)
    uls = res.combinations["ULS"]
    total = 1.5 * floor.section_forces + 2.0 * res.cases["end"].section_forces
    assert_allclose(uls.section_forces, total, rtol=0, atol=1e-12 * np.nanmax(np.abs(total)))
    doc = res.to_dict()
    assert "stations" in doc["cases"]["floor"]["members"]["AB"]
    assert "stations" in doc["combinations"]["ULS"]["members"]["AB"]
    assert "stations" not in doc["cases"]["end"]["members"]["AB"]


def test_written_model_keeps_member_loads_of_its_cases(tmp_path):
    """A case's member loads survive write_model and read_model (same results)."""
    from trussfe.io.model_writer import write_model
    s = _model({"A": [0, 0], "B": [3.0, 0]}, {"AB": ("A", "B", {"type": "beam"})},
               {"A": ["x", "y", "rz"]}, section={"area": A, "Iz": 8e-6, "c": 0.1},
               load_cases={"p": {"member_loads": [
                   {"member": "AB", "kind": "trapezoidal", "q_start": [0.0, -100.0],
                    "q_end": [0.0, -300.0], "axes": "local"},
                   {"member": "AB", "kind": "point", "at": 0.4, "F": [10.0, -50.0],
                    "M": [20.0]}]}})
    back = trussfe.read_model(write_model(s, tmp_path / "m.toml"))
    a, b = trussfe.static(s, case="p"), trussfe.static(back, case="p")
    assert_allclose(b.section_forces, a.section_forces, rtol=1e-13, atol=1e-9)
