"""The Python API (trussfe.api, docs/python.md): models built in Python, every analysis,
result arrays, ``to_dict()`` against the command's JSON, option checking and defaults."""
import inspect
import json
import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

import trussfe
from trussfe import api
from trussfe.cli import build_parser, main
from trussfe.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
MESHES = ROOT / "meshes"

P = 1000.0                       # N, downward at the apex
E = 210e9
D, DI = 0.05, 0.04               # tube outer and inner diameter, m
AREA = math.pi / 4 * (D ** 2 - DI ** 2)
INERTIA = math.pi / 64 * (D ** 4 - DI ** 4)
MASS = 10.0                      # kg, lumped at the apex


def two_bar(density: float = 0.0) -> dict:
    """Symmetric two-bar truss A(0, 0), B(2, 0) pinned, apex C(1, 1): bars at 45°, L = √2."""
    return {
        "model": {"name": "two-bar truss", "dimension": 2},
        "materials": {"steel": {"E": E, "density": density}},
        "sections": {"tube": {"outer_diameter": D, "inner_diameter": DI}},
        "nodes": {"A": [0.0, 0.0], "B": (2.0, 0.0), "C": np.array([1.0, 1.0])},
        "members": {"AC": {"nodes": ["A", "C"], "section": "tube", "material": "steel"},
                    "BC": {"nodes": ["B", "C"], "section": "tube", "material": "steel"}},
        "supports": {"A": ["x", "y"], "B": ["x", "y"]},
        "loads": {"C": [0.0, -P]},
        "masses": {"C": np.float64(MASS)},
    }


# ---------------------------------------------------------------- models built in Python
def test_model_from_dict_errors_read_as_the_file_readers(tmp_path):
    """The same bad member gives the same message from a dict and (prefixed with the file
    name) from a file: both go through one parser."""
    data = two_bar()
    data["members"]["AC"]["section"] = "tubo"
    with pytest.raises(InputError) as from_dict:
        trussfe.model_from_dict(data)
    text = (MESHES / "triangular_truss_static.toml").read_text()
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace('section = "tube"', 'section = "tubo"', 1))
    with pytest.raises(InputError) as from_file:
        trussfe.read_model(bad)
    assert "did you mean 'tube'" in str(from_dict.value)
    assert str(from_file.value).startswith(f"{bad}: members.")
    assert str(from_file.value).split(": ", 1)[1].split(": ", 1)[1] == \
        str(from_dict.value).split(": ", 1)[1]


def test_model_from_dict_equals_the_file_model():
    """A file's tables passed as a dict build the same structure as the file."""
    path = MESHES / "triangular_truss_static.toml"
    a = trussfe.read_model(path)
    b = trussfe.model_from_dict(tomllib.loads(path.read_text()))
    assert a.node_ids == b.node_ids and a.member_ids == b.member_ids
    assert_allclose(a.coords, b.coords, rtol=0)
    assert trussfe.static(a).to_dict() == trussfe.static(b).to_dict()


def test_static_of_a_python_model_method_of_joints():
    """Two bars at 45° under P at the apex: N = −P / (2 sin 45°) in each (method of joints),
    vertical reactions P/2, horizontal ±P/2; the reactions balance the load (equilibrium)."""
    r = trussfe.static(two_bar())
    assert r.member_ids == ("AC", "BC") and r.node_ids == ("A", "B", "C")
    assert r.axial_force.shape == (2,) and r.displacement.shape == (3, 2)
    assert_allclose(r.axial_force, -P / (2 * math.sin(math.pi / 4)), rtol=1e-12)
    assert_allclose(r.reaction[0], [P / 2, P / 2], rtol=1e-12)
    assert_allclose(r.reaction[1], [-P / 2, P / 2], rtol=1e-12)
    assert_allclose(r.reaction.sum(axis=0), [0.0, P], atol=1e-9 * P)
    # apex drop by the unit-load method: v = Σ N·n·L/(EA), n = N/P the unit-load forces
    L = math.sqrt(2.0)
    N = -P / math.sqrt(2.0)
    v = 2 * N * (N / P) * L / (E * AREA)
    assert_allclose(-r.displacement[2, 1], v, rtol=1e-10)
    assert r.to_dict()["members"]["AC"]["axial_force"] == r.axial_force[0]


def test_modes_of_a_python_model_closed_form():
    """Massless bars, 10 kg at the apex: stiffness EA/L in x and in y (two bars at 45°),
    so both frequencies are √(EA/(L m)) / 2π (single-DOF closed form)."""
    m = trussfe.modes(two_bar(), count=2)
    f = math.sqrt(E * AREA / (math.sqrt(2.0) * MASS)) / (2 * math.pi)
    assert m.shapes.shape == (2, 3, 2) and m.effective_mass.shape == (2, 2)
    assert_allclose(m.frequencies_hz, [f, f], rtol=1e-10)
    assert_allclose(m.effective_mass.sum(axis=0), [MASS, MASS], rtol=1e-10)


def test_buckling_of_a_python_model_euler():
    """Pinned-beam bars buckle between joints: λ·|N| = π²EI/L² (Euler, pinned ends; eight
    elements per member to 1e-4)."""
    b = trussfe.buckling(two_bar(), count=2, subdivisions=8)
    pe = math.pi ** 2 * E * INERTIA / 2.0
    assert_allclose(b.euler_load, pe, rtol=1e-12)
    assert_allclose(b.critical_load_factor * P / math.sqrt(2.0), pe, rtol=1e-4)
    assert b.shapes.shape == (2, 3, 2)


def test_mechanism_of_a_python_model_is_determinate():
    """b = 2 bars, f = 2 free coordinates, rank 2: no mechanism, no self-stress (Maxwell)."""
    k = trussfe.mechanism(two_bar())
    assert (k.rank, k.mechanisms, k.self_stress_states, k.rigid_body_motions) == (2, 0, 0, 0)
    assert k.mechanism_shapes.shape == (0, 3, 2) and k.self_stress.shape == (0, 2)


def test_postcritical_of_a_python_model_von_mises_closed_form():
    """Von Mises two-bar truss built in Python (a = 1, h = 0.1, EA = 1e6): the limit load is
    P = 2EA·w(1/ℓ − 1/L) with ℓ³ = a²L (closed form, docs/postcritical.md), and the path
    equals the one of the shipped file with the same tables."""
    data = tomllib.loads((MESHES / "postcritical_von_mises.toml").read_text())
    data.pop("postcritical")
    p = trussfe.postcritical(data, steps=200, step=0.002, max_step=0.004,
                             max_displacement=0.25, monitor="apex:y")
    a, h, EA = 1.0, 0.1, 1e6
    L = math.hypot(a, h)
    ell = (a * a * L) ** (1 / 3)
    w = math.sqrt(ell ** 2 - a ** 2)
    limit = 2 * EA * w * (1 / ell - 1 / L)
    lim = [e.load_factor for e in p.events if e.kind == "limit_point"]
    assert max(lim) == pytest.approx(limit, rel=1e-9)
    n = p.load_factors.size
    assert p.displacement.shape == (n, 3, 2) and p.axial_force.shape == (n, 2)
    assert p.monitor == ("apex", "y")
    assert_allclose(p.monitored_displacement, p.displacement[:, 1, 1], rtol=0)
    ref = trussfe.postcritical(MESHES / "postcritical_von_mises.toml", steps=200)
    assert_allclose(p.load_factors, ref.load_factors, rtol=1e-12)


def test_trace_of_a_python_model():
    """The four-bar linkage's tables from Python trace the same path as the file; the bars
    keep their lengths (inextensional motion) to the corrector tolerance."""
    path = MESHES / "mech_fourbar.toml"
    t = trussfe.trace(tomllib.loads(path.read_text()), drive="2:y", step=0.05, steps=4)
    assert t.position.shape == (5, 4, 2) and t.parameter.shape == (5,)
    f = trussfe.trace(path, drive=["2:y"], step=[0.05], steps=4)
    assert_allclose(t.position, f.position, rtol=0, atol=0)
    s = t.structure
    a, b = s.connectivity.T
    lengths = np.linalg.norm(t.position[:, b] - t.position[:, a], axis=2)
    assert_allclose(lengths, lengths[:1].repeat(5, axis=0), rtol=1e-9)


# ---------------------------------------------------------------- along a motion
def test_motion_analyses_shapes_and_equilibrium():
    """simulate, elastic, transient and actuators on the shipped models: arrays of the
    documented shapes.  At rest the rigid-body reactions carry the weight of the node masses,
    the tubes and the active bases (global statics)."""
    model = MESHES / "triangular_truss_motion_active.toml"
    rest = trussfe.simulate(model)
    b = rest.solution.bodies
    weight = (rest.structure.masses.sum() + b.tube_mass.sum() + b.base_mass.sum()) \
        * rest.structure.gravity
    assert rest.time.shape == (1,) and weight[1] < 0
    assert_allclose(rest.reaction.sum(axis=1)[0] + rest.structure.loads[:, :2].sum(axis=0),
                    -weight, rtol=1e-12, atol=1e-12)

    s = trussfe.simulate(model, motion="triangular_truss_motion_3s.toml", steps=20)
    nt = s.time.size
    assert s.position.shape == s.velocity.shape == s.reaction.shape == (nt, 3, 2)
    assert s.axial_force.shape == s.max_von_mises.shape == (nt, 2)
    assert s.von_mises.shape == s.station_axial_force.shape == (nt, 2, 7)
    assert s.actuator_ids == ("active",) and s.actuator_force.shape == (nt, 1)

    e = trussfe.elastic(model, motion="triangular_truss_motion_3s.toml", steps=10)
    assert e.displacement.shape == (10, 3, 2) and e.axial_force.shape == (10, 2)
    assert e.section_forces.shape[:2] == (10, 2) and e.section_forces.shape[3] == 6
    # a statically determinate truss: FE and rigid-body forces agree (Lacy section 3.3)
    assert_allclose(e.axial_force, e.axial_force_rigid,
                    atol=1e-8 * np.abs(e.axial_force_rigid).max())

    t = trussfe.transient(model, motion="triangular_truss_motion_3s.toml", dt=0.1)
    assert t.displacement.shape == (t.time.size, 3, 2)
    assert t.axial_force.shape == t.axial_force_quasi_static.shape == (t.time.size, 2)

    a = trussfe.actuators(MESHES / "double_octahedron_actuators.toml",
                          motion="double_octahedron_tilt_rotation.toml", steps=12)
    assert a.actuator_ids == ("M7_8", "M9_10", "M11_12")
    assert a.force.shape == a.motor_voltage.shape == (13, 3)
    doc = a.to_dict()["actuators"]["M7_8"]
    k = int(np.argmax(np.abs(a.motor_voltage[:, 0])))
    assert doc["motor_voltage"] == {"value": a.motor_voltage[k, 0], "time": a.time[k]}


# ---------------------------------------------------------------- to_dict() is the CLI's JSON
CLI_CASES = [
    ("static", "triangular_truss_static.toml", [], {}),
    ("static", "postcritical_euler_column.toml", ["--bar-model", "pinned-beam",
                                                  "--subdivisions", "3"],
     {"bar_model": "pinned-beam", "subdivisions": 3}),
    ("modes", "triangular_truss_static.toml", ["--count", "2", "--mass", "lumped"],
     {"count": 2, "mass": "lumped"}),
    ("buckling", "postcritical_euler_column.toml", ["--count", "2"], {"count": 2}),
    ("simulate", "triangular_truss_motion_active.toml",
     ["--motion", "triangular_truss_motion_3s.toml", "--steps", "20", "--scheme", "thesis"],
     {"motion": "triangular_truss_motion_3s.toml", "steps": 20, "scheme": "thesis"}),
    ("simulate", "chain3_motion_active.toml",
     ["--motion", "chain3_motion_rotation.toml", "--steps", "6", "--method", "bay-by-bay"],
     {"motion": "chain3_motion_rotation.toml", "steps": 6, "method": "bay-by-bay"}),
    ("actuators", "double_octahedron_actuators.toml",
     ["--motion", "double_octahedron_tilt_rotation.toml", "--steps", "12"],
     {"motion": "double_octahedron_tilt_rotation.toml", "steps": 12}),
    ("elastic", "triangular_truss_motion_active.toml",
     ["--motion", "triangular_truss_motion_3s.toml", "--steps", "10", "--sections", "5"],
     {"motion": "triangular_truss_motion_3s.toml", "steps": 10, "sections": 5}),
    ("transient", "triangular_truss_motion_active.toml",
     ["--motion", "triangular_truss_motion_3s.toml", "--dt", "0.1", "--damping", "0.1", "0"],
     {"motion": "triangular_truss_motion_3s.toml", "dt": 0.1, "damping": (0.1, 0.0)}),
    ("mechanism", "mech_bricard.toml", [], {}),
    ("trace", "mech_fourbar.toml", ["--drive", "2:y", "--step", "0.05", "--steps", "3"],
     {"drive": "2:y", "step": 0.05, "steps": 3}),
    ("postcritical", "postcritical_von_mises.toml", ["--steps", "40"], {"steps": 40}),
    ("topology", "mech_bennett.toml", [], {}),
    ("topology", "mech_slider_crank.toml", [], {}),
]


@pytest.mark.parametrize("command, model, argv, options", CLI_CASES,
                         ids=[f"{c[0]}-{c[1].split('.')[0]}" for c in CLI_CASES])
def test_to_dict_is_the_cli_json(command, model, argv, options, tmp_path, monkeypatch, capsys):
    """``trussfe COMMAND MODEL ... --json OUT`` writes exactly ``to_dict()`` of the API call
    with the same options (run in-process from an unrelated working directory: relative
    motion paths are found beside the model).  The document starts with ``units``,
    ``command`` and ``model`` (docs/json.md, "Conventions")."""
    monkeypatch.chdir(tmp_path)
    out = tmp_path / "out.json"
    assert main([command, str(MESHES / model), *argv, "--json", str(out)]) == 0
    capsys.readouterr()
    doc = api.ANALYSES[command](MESHES / model, **options).to_dict()
    written = json.loads(out.read_text())
    assert written == doc
    assert list(written)[:3] == ["units", "command", "model"]
    assert (written["units"], written["command"], written["model"]) == \
        ("SI", command, trussfe.read_model(MESHES / model).name)


# ---------------------------------------------------------------- options
def test_unknown_and_positional_options_are_refused():
    """A misspelt option raises TypeError (never silently ignored); options are
    keyword-only."""
    path = MESHES / "triangular_truss_static.toml"
    for name, func in {**api.ANALYSES, "validate": trussfe.validate}.items():
        with pytest.raises(TypeError, match="unexpected keyword argument 'mas'"):
            func(path, mas="lumped")
    with pytest.raises(TypeError):
        trussfe.static(path, "pinned-beam")
    with pytest.raises(TypeError, match="model must be"):
        trussfe.static(42)


def test_bad_option_values_raise_input_errors():
    """Values are checked with the command line's messages (naming its option)."""
    path = MESHES / "triangular_truss_static.toml"
    with pytest.raises(InputError, match="--solver"):
        trussfe.static(path, solver="fast")
    with pytest.raises(InputError, match="--mass: unknown mass kind 'lump'"):
        trussfe.modes(path, mass="lump")
    with pytest.raises(InputError, match="--scheme"):
        trussfe.simulate(path, scheme="approximate")
    with pytest.raises(InputError, match="--steps"):
        trussfe.simulate(path, steps=5)
    with pytest.raises(InputError, match="--step"):
        trussfe.postcritical(MESHES / "postcritical_von_mises.toml", step=-1.0)


def test_validation_case_with_an_unknown_option_is_an_error(tmp_path, capsys):
    """A case's misspelt option is a malformed case (with a suggestion, exit status 2), not
    dropped; the engine refuses it too if a case is built in Python."""
    from trussfe.validation import load_case, run_case
    case = tmp_path / "c.toml"
    case.write_text(f'[case]\nid = "c"\nanalysis = "modes"\n'
                    f'model = "{MESHES / "triangular_truss_static.toml"}"\n'
                    'options = { mas = "lumped" }\n'
                    '[[quantities]]\nname = "f"\npath = "frequencies_hz[0]"\n'
                    'reference = 1.0\nsource = "none"\nrtol = 1.0\n')
    message = "case.options: 'modes' has no option 'mas'; did you mean 'mass'?"
    with pytest.raises(InputError) as err:
        load_case(case)
    assert str(err.value) == f"{case}: {message}"
    assert main(["validate", "--cases", str(tmp_path), "--out", str(tmp_path / "r"),
                 "--no-progress"]) == 2
    assert capsys.readouterr().err == f"trussfe: error: {case}: {message}\n"
    case.write_text(case.read_text().replace("mas =", "mass ="))
    parsed = load_case(case)
    parsed.options = {"mas": "lumped"}
    r = run_case(parsed)
    assert r.status == "error" and r.error == message


#: Command-line options that only choose outputs (no API counterpart).
OUTPUTS = {"help", "model", "json", "vtk", "npz", "plots", "plot", "vtk_every", "out",
           "no_progress"}
#: API options without a command-line option (documented in docs/python.md).
API_ONLY = {"simulate": {"progress"}, "trace": {"progress"}, "postcritical": {"max_step", "progress"},
            "elastic": {"progress"}, "transient": {"progress"}, "modes": {"progress"},
            "validate": {"progress"}}
#: Command-line destinations spelt differently in the API.
RENAMED = {"validate": {"cases_selected": "case"}}


def _subparsers():
    parser = build_parser()
    action = next(a for a in parser._actions if a.dest == "command")
    return action.choices


@pytest.mark.parametrize("command", sorted([*api.ANALYSES, "validate"]))
def test_defaults_are_the_command_lines(command):
    """Every analysis option of the command exists in the API function, with the same
    default (a required command-line option is a keyword without default)."""
    sub = _subparsers()[command]
    func = trussfe.validate if command == "validate" else api.ANALYSES[command]
    params = list(inspect.signature(func).parameters.values())
    params = {p.name: p for p in (params if command == "validate" else params[1:])}
    cli = {}
    for a in sub._actions:
        if a.dest in OUTPUTS:
            continue
        cli[RENAMED.get(command, {}).get(a.dest, a.dest)] = a
    assert set(params) - API_ONLY.get(command, set()) == set(cli)
    for name, a in cli.items():
        p = params[name]
        if command != "validate":
            assert p.kind is inspect.Parameter.KEYWORD_ONLY
        if a.required:
            assert p.default is inspect.Parameter.empty, name
        else:
            assert p.default == a.default, name


# ---------------------------------------------------------------- package surface
def test_import_trussfe_gives_every_analysis():
    for name in ("read_model", "model_from_dict", "static", "modes", "buckling", "simulate",
                 "actuators", "elastic", "transient", "mechanism", "trace", "postcritical",
                 "validate"):
        assert name in trussfe.__all__ and callable(getattr(trussfe, name))
    import trussfe.response.transient as tr        # importing the packages behind them
    import trussfe.validation.engine as en         # leaves the functions in place
    assert callable(tr.transient_response) and callable(en.run_case)
    assert trussfe.elastic is api.elastic
    assert trussfe.validate is trussfe.validation.validate


def test_python_md_runs(monkeypatch):
    """Every ```python block of docs/python.md runs, in order, from the repository root."""
    monkeypatch.chdir(ROOT)
    text = (ROOT / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) >= 6
    namespace: dict = {}
    for i, block in enumerate(blocks):
        exec(compile(block, f"docs/python.md block {i + 1}", "exec"), namespace)
