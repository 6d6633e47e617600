"""A written model reads back as the same model: every table of the format, every shipped model
file, to the last bit (trussfe.io.model_writer against trussfe.io.model_file)."""
from __future__ import annotations

import dataclasses
import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import trussfe
from trussfe.errors import OutputError
from trussfe.io.extension_tables import TABLES as EXTENSION_TABLES
from trussfe.io.model_file import CORE_TABLES
from trussfe.io.model_writer import model_toml, write_model

ROOT = Path(__file__).resolve().parents[1]

#: Per-structure arrays compared bit for bit.
ARRAYS = ("coords", "connectivity", "is_beam", "releases", "torsion_releases",
          "bending_axis_releases", "orientation", "supports", "loads", "masses", "gravity",
          "area", "Iy", "Iz", "J", "c", "E", "G", "density", "yield_strength")


def _same_bits(a, b) -> bool:
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape:
        return False
    if a.dtype.kind == "f" or b.dtype.kind == "f":
        # bit patterns: -0.0 differs from 0.0, nan equals nan
        return np.array_equal(np.asarray(a, float).view(np.int64),
                              np.asarray(b, float).view(np.int64))
    return np.array_equal(a, b)


def _differences(a, b, where: str, out: list[str]) -> None:
    if a is None or b is None:
        if a is not b:
            out.append(f"{where}: {a!r} != {b!r}")
    elif isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        if not _same_bits(a, b):
            out.append(f"{where}: arrays differ")
    elif dataclasses.is_dataclass(a) and not isinstance(a, type):
        if type(a) is not type(b):
            out.append(f"{where}: {type(a).__name__} != {type(b).__name__}")
            return
        for f in dataclasses.fields(a):
            _differences(getattr(a, f.name), getattr(b, f.name), f"{where}.{f.name}", out)
    elif isinstance(a, (tuple, list)):
        if not isinstance(b, (tuple, list)) or len(a) != len(b):
            out.append(f"{where}: {a!r} != {b!r}")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            _differences(x, y, f"{where}[{i}]", out)
    elif isinstance(a, float) or isinstance(b, float):
        if not _same_bits(float(a), float(b)):
            out.append(f"{where}: {a!r} != {b!r}")
    elif a != b:
        out.append(f"{where}: {a!r} != {b!r}")


def model_differences(a, b, *, ids: bool = True) -> list[str]:
    """What differs between two structures: ids, arrays, sections, materials and extension
    tables, floats compared bit for bit (an empty list: the same model)."""
    out: list[str] = []
    if ids:
        _differences(list(a.node_ids), list(b.node_ids), "node_ids", out)
        _differences(list(a.member_ids), list(b.member_ids), "member_ids", out)
    _differences((a.name, a.dim), (b.name, b.dim), "name, dim", out)
    for key in ARRAYS:
        _differences(getattr(a, key), getattr(b, key), key, out)
    _differences(a.sections, b.sections, "sections", out)
    _differences(a.materials, b.materials, "materials", out)
    _differences(a.member_properties, b.member_properties, "member_properties", out)
    if set(a.extensions) != set(b.extensions):
        out.append(f"extensions: {sorted(a.extensions)} != {sorted(b.extensions)}")
    for key in sorted(set(a.extensions) & set(b.extensions)):
        _differences(a.extensions[key], b.extensions[key], f"extensions[{key}]", out)
    return out


def analysis_results(s) -> list[str]:
    """The static (every case and combination) and modal results of ``s`` as JSON text, or
    the error an analysis raises (without the file name)."""
    out = []
    for run in (lambda: trussfe.static(s, all_cases="load_cases" in s.extensions),
                lambda: trussfe.modes(s, count=min(4, 3 * s.n_nodes))):
        try:
            out.append(json.dumps(run().to_dict(), default=repr, sort_keys=True))
        except trussfe.errors.TrussfeError as err:
            out.append(f"{type(err).__name__}: {str(err).split('.toml: ')[-1]}")
    return out


def _same_static_arrays(a, b) -> None:
    """Displacements, axial forces and reactions of every case and combination of two
    ``static(..., all_cases=True)`` results agree to the bit."""
    assert list(a.cases) == list(b.cases) and list(a.combinations) == list(b.combinations)
    for name in [*a.cases, *a.combinations]:
        x = a.cases.get(name) or a.combinations[name]
        y = b.cases.get(name) or b.combinations[name]
        for attr in ("displacement", "axial_force", "reaction"):
            assert _same_bits(getattr(x, attr), getattr(y, attr)), (name, attr)


def _is_model_file(path: Path) -> bool:
    """A model file, not a motion or study file that shares the folder."""
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    return "model" in data and set(data) <= set(CORE_TABLES) | set(EXTENSION_TABLES)


MODEL_FILES = sorted(p.relative_to(ROOT).as_posix() for p in
                     [*ROOT.glob("meshes/*.toml"), *ROOT.glob("validation/models/*.toml"),
                      *ROOT.glob("examples/*.toml")] if _is_model_file(p))


def test_model_files_are_found():
    assert len(MODEL_FILES) >= 30 and "meshes/chain_mesh.toml" in MODEL_FILES


@pytest.mark.parametrize("name", MODEL_FILES)
def test_shipped_model_reads_back_identical(tmp_path, name):
    """read → write → read: the same arrays and tables, bit for bit, and the same static and
    modal results; writing what was read back gives the same text."""
    s = trussfe.read_model(ROOT / name)
    r = trussfe.read_model(write_model(s, tmp_path / "a.toml"))
    assert model_differences(s, r) == []
    assert analysis_results(r) == analysis_results(s)
    assert model_toml(r) == model_toml(s)


@pytest.mark.parametrize("name", MODEL_FILES)
def test_shipped_model_reads_back_through_a_mesh(tmp_path, name):
    """With the geometry in a VTU file: ids become indices (in the monitor of [postcritical]
    and the actuator names too), everything else is the same, results included."""
    s = trussfe.read_model(ROOT / name)
    r = trussfe.read_model(write_model(s, tmp_path / "a.toml", mesh="a.vtu"))
    assert list(r.node_ids) == [str(i) for i in range(s.n_nodes)]
    diff = model_differences(s, r, ids=False)
    assert [d for d in diff if not d.startswith(("extensions[postcritical].monitor",
                                                 "extensions[actuators]"))] == []
    if "actuators" in s.extensions:
        assert [a.name for a in r.extensions["actuators"]] == [
            str(a.member) for a in s.extensions["actuators"]]
    if s.n_members < 2000:
        try:
            a, b = trussfe.static(s, all_cases=True), trussfe.static(r, all_cases=True)
        except trussfe.errors.TrussfeError:
            return
        _same_static_arrays(a, b)


# --------------------------------------------------------------------- every table at once
def every_table(with_cases: bool) -> dict:
    """A 3-D model holding every table and key of the format, with floats that need all 17
    digits, subnormals and ids that must be quoted."""
    third = 0.1 + 0.2
    steel = {"E": 2.1e11, "G": 8.1e10, "density": 7850.0, "yield_strength": 3.55e8,
             "thermal_expansion": 1.2e-5}
    d = {
        "model": {"name": 'every "table" \\ model\n\té', "dimension": 3,
                  "gravity": [third, -0.0, -9.81]},
        "materials": {
            "steel": steel,
            'alu.6061 "T6"': {"E": 7.0e10, "density": 2700.0, "yield_strength": 2.7e8},
            "1": {"E": 1.0e9, "G": 5e8, "density": 5e-324, "yield_strength": 1e8},
        },
        "sections": {
            "box": {"area": 4.0e-3, "Iy": 8.0e-6, "Iz": 5.0e-6, "J": 1.0e-5, "c": 0.05,
                    "shear_area_y": 2.0e-3, "shear_area_z": 1.5e-3},
            "tube": {"outer_diameter": 0.0254, "inner_diameter": 0.022225},
            "tube T": {"outer_diameter": 0.05, "inner_diameter": 0.0,
                       "beam_theory": "timoshenko", "shear_coefficient": 0.9},
            "rod": {"area": 5e-4, "Iy": 2e-8},
            "solid.T": {"area": 2.5e-3, "Iy": 3.1e-7, "Iz": 5.2e-7, "c": 0.04,
                        "beam_theory": "timoshenko", "shear_coefficient": 0.8333},
        },
        "nodes": {"A": [0.0, 0.0, 0.0], "B": [0.0, 0.0, 3.0], "C": [4.0, third, 3.0],
                  "D": [4.0, 0.0, 0.0], "e f": [2.0, 2.0, 1.5], "g.h": [2.0, -2.0, 1.5],
                  '"q"': [1e-320, 1.0, 2.0], "ü": [-0.0, 3.0, 1.0], "1": [3.0, 3.0, 1.0]},
        "members": {
            "AB": {"nodes": ["A", "B"], "section": "box", "material": "steel", "type": "beam",
                   "releases": {"start": ["my", "mz"], "end": ["t"]},
                   "orientation": [1.0, 0.0, 0.0]},
            "BC": {"nodes": ["B", "C"], "section": "box", "material": "steel", "type": "beam",
                   "releases": {"end": ["mz"]}},
            "CD": {"nodes": ["C", "D"], "section": "tube T", "material": "steel",
                   "type": "beam", "releases": ["start"]},
            "BD.x": {"nodes": ["B", "D"], "section": "solid.T", "material": "steel",
                     "type": "beam", "releases": {"start": ["my"], "end": ["bending", "torsion"]},
                     "orientation": [third, 1.0, -0.0]},
            "x y": {"nodes": ["A", "e f"], "section": "tube", "material": 'alu.6061 "T6"'},
            "2": {"nodes": ["e f", "C"], "section": "tube", "material": 'alu.6061 "T6"'},
            "3": {"nodes": ["g.h", "B"], "section": "rod", "material": "1"},
            "4": {"nodes": ["g.h", "D"], "section": "rod", "material": "1"},
            "5": {"nodes": ["g.h", "A"], "section": "rod", "material": "steel"},
            "q1": {"nodes": ['"q"', "A"], "section": "rod", "material": "steel"},
            "q2": {"nodes": ['"q"', "B"], "section": "rod", "material": "steel"},
            "q3": {"nodes": ['"q"', "e f"], "section": "rod", "material": "steel"},
            "u1": {"nodes": ["ü", "e f"], "section": "rod", "material": "steel"},
            "u2": {"nodes": ["ü", "B"], "section": "rod", "material": "steel"},
            "u3": {"nodes": ["ü", "A"], "section": "rod", "material": "steel"},
            "o1": {"nodes": ["1", "C"], "section": "box", "material": "steel", "type": "beam",
                   "releases": {"start": ["all"]}},
            "o2": {"nodes": ["1", "ü"], "section": "rod", "material": "steel"},
            "o3": {"nodes": ["1", "e f"], "section": "rod", "material": "steel"},
        },
        "supports": {"A": ["x", "y", "z", "rx", "ry", "rz"],
                     "D": ["x", "y", "z", "rx", "ry", "rz"], "e f": ["z"]},
        "springs": {"C": {"x": 3.0e5, "ry": 1e-320}, "1": {"z": 2e5}},
        "masses": {"B": {"mass": 10.0, "inertia": [0.5, third, 5e-324]},
                   "C": {"inertia": [1.0, 2.0, 3.0]}, "ü": third, "e f": 2.0},
        "active_members": {
            "q1": {"base_mass": 2.4, "base_length": 2.1, "tube_length": 1.0,
                   "min_length": 1.5, "max_length": 2.5},
            "u3": {"base_mass": 3.0, "base_length": 0.7, "base_cg": third,
                   "base_inertia": 0.5, "tube_length": 0.254}},
        "actuators": {
            "q1": {"leadscrew_gain": 2.5266e-4, "mean_diameter": 0.0127, "thread": "acme",
                   "thread_angle": 14.5, "friction": 0.1, "gearhead_gain": 5.2,
                   "armature_inertia": 6.76e-6, "resistance": 2.0, "torque_constant": 0.0398,
                   "back_emf_constant": 0.0398, "max_voltage": 25.0, "convention": "thesis",
                   "require_self_locking": False},
            "u3": {"leadscrew_gain": 2.5266e-4, "mean_diameter": 0.0127, "friction": 0.1,
                   "max_speed": 3.0, "armature_inertia": 6.76e-6, "resistance": 2.0,
                   "torque_constant": 0.0398, "back_emf_constant": 0.0398}},
        "failure": {
            "default": {"buckling": "cap", "effective_length_factor": 0.7, "yield": "cap",
                        "fracture_strain": 0.05},
            "members": {
                "q2": {"buckling": "softening", "critical_load": 1200.0, "residual": 0.3,
                       "softening_strain": 0.002},
                "x y": {"buckling": "none", "yield": "remove", "yield_strength": 2.4e8},
                "3": {"buckling": "remove", "critical_load": third, "yield": "none"},
                "4": {"yield": "remove", "yield_strength": 1.0e8}}},
        "postcritical": {"control": "arc-length", "steps": 200, "step": 0.002,
                         "max_step": 0.01, "max_load_factor": 5.0, "monitor": "e f:y",
                         "bar_model": "pinned-beam", "subdivisions": 8,
                         "imperfection": 0.001, "branch": True, "max_displacement": 0.5},
    }
    loads = {"B": [2000.0, 0.0, 0.0], "C": [0.0, 1.0, 0.0, third, 0.0, -0.0]}
    if with_cases:
        d["load_cases"] = {
            "dead": {"gravity": True},
            "wind load": {"loads": loads, "member_loads": [
                {"member": "BC", "kind": "uniform", "q": [0.0, 0.0, -800.0]},
                {"member": "AB", "kind": "trapezoidal", "q_start": [0.0, 200.0, 0.0],
                 "q_end": [0.0, 600.0, 0.0], "axes": "local"},
                {"member": "BC", "kind": "point", "at": 0.25, "F": [0.0, 0.0, -300.0],
                 "M": [0.0, 10.0, 0.0]},
                {"member": "x y", "kind": "point", "at": third, "F": [0.0, 0.0, -300.0]}]},
            "settle.1": {"prescribed": {"D": {"z": -0.004, "rx": 1e-3}, "A": {"x": 1e-320}}},
            "thermal": {"temperature": [{"members": ["BC", "AB"], "delta_T": 30.0},
                                        {"member": "BC", "delta_T": third}],
                        "initial_strain": [{"member": "AB", "strain": 1.0e-5}],
                        "length_error": [{"member": "5", "delta": 0.5e-3}]},
            "1": {"loads": {"C": [0.0, 0.0, -1.0]}},
        }
        d["combinations"] = {"ULS": {"dead": 1.35, "wind load": 1.5, "settle.1": 1.0},
                             "S L S": {"dead": 1.0, "thermal": third, "1": -0.0}}
    else:
        d["loads"] = loads
        d["member_loads"] = [
            {"member": "BC", "kind": "uniform", "q": [0.0, 0.0, -800.0]},
            {"member": "BD.x", "kind": "point", "at": 1.0, "M": [0.0, 1.0, 0.0],
             "axes": "local"},
            {"member": "x y", "kind": "point", "at": 0.0, "F": [0.0, 0.0, -300.0]}]
    return d


@pytest.mark.parametrize("with_cases", [True, False], ids=["load_cases", "member_loads"])
def test_every_table_reads_back_identical(tmp_path, with_cases):
    s = trussfe.model_from_dict(every_table(with_cases))
    expected = {"active_members", "actuators", "failure", "postcritical", "rotary_inertia",
                "springs", "load_cases" if with_cases else "member_loads"}
    assert set(s.extensions) == expected
    r = trussfe.read_model(write_model(s, tmp_path / "every.toml"))
    assert model_differences(s, r) == []
    assert analysis_results(r) == analysis_results(s)
    assert not analysis_results(s)[0].startswith(("InputError", "AnalysisError"))


@pytest.mark.parametrize("with_cases", [True, False], ids=["load_cases", "member_loads"])
def test_every_table_reads_back_through_a_mesh(tmp_path, with_cases):
    s = trussfe.model_from_dict(every_table(with_cases))
    r = trussfe.read_model(write_model(s, tmp_path / "every.toml", mesh="every.vtu"))
    assert model_differences(s, r, ids=False) == [
        "extensions[actuators][0].name: 'q1' != '9'",
        "extensions[actuators][1].name: 'u3' != '14'",
        "extensions[postcritical].monitor: 'e f:y' != '4:y'"]
    _same_static_arrays(trussfe.static(s, all_cases=True), trussfe.static(r, all_cases=True))
    assert _same_bits(trussfe.modes(s, count=4).frequencies_hz,
                      trussfe.modes(r, count=4).frequencies_hz)


# ------------------------------------------------------------------------ single cases
def _two_d(**extra) -> dict:
    d = {"model": {"dimension": 2, "name": "frame"},
         "materials": {"s": {"E": 2e11, "density": 7850.0}},
         "sections": {"r": {"area": 1e-3, "Iz": 1e-6, "c": 0.05}},
         "nodes": {"A": [0.0, 0.0], "B": [1.0, 1.0], "C": [2.0, 1.0], "D": [3.0, 0.0]},
         "members": {k: {"nodes": list(k), "section": "r", "material": "s", "type": "beam"}
                     for k in ("AB", "BC", "CD")},
         "supports": {"A": ["x", "y", "rz"], "D": ["x", "y", "rz"]},
         "loads": {"B": [10.0, -1000.0], "C": [0.0, -500.0, 3.0]}}
    d.update(extra)
    return d


def test_point_couple_without_force(tmp_path):
    """A point load with a couple M and no force F is written without F (``F = []`` is
    refused by the reader)."""
    ml = [{"member": "BC", "kind": "point", "at": 0.5, "M": [250.0]},
          {"member": "AB", "kind": "point", "at": 0.25, "F": [0.0, -10.0], "M": [1.0]}]
    s = trussfe.model_from_dict(_two_d(member_loads=ml))
    text = model_toml(s)
    assert "F = []" not in text
    r = trussfe.read_model(write_model(s, tmp_path / "m.toml"))
    assert model_differences(s, r) == []
    assert r.extensions["member_loads"][0].force == ()
    assert analysis_results(r) == analysis_results(s)


def test_springs_table_without_a_spring(tmp_path):
    """A ``[springs]`` table of zero stiffnesses is written (empty) and reads back the same:
    the analyses along a motion treat the model alike before and after (no spring to refuse),
    while a spring of some stiffness is refused in both."""
    from trussfe.api.model import refuse_unapplied

    s = trussfe.model_from_dict(_two_d(springs={"B": {"x": 0.0}}))
    r = trussfe.read_model(write_model(s, tmp_path / "m.toml"))
    assert model_differences(s, r) == []
    for model in (s, r):
        assert refuse_unapplied(model, "simulate") is model
    s = trussfe.model_from_dict(_two_d(springs={"B": {"x": 1.0e3}}))
    r = trussfe.read_model(write_model(s, tmp_path / "k.toml"))
    for model in (s, r):
        with pytest.raises(trussfe.errors.InputError, match="springs"):
            refuse_unapplied(model, "simulate")


def test_ids_and_names_with_control_characters(tmp_path):
    """DEL (U+007F) and the C0 controls are escaped in keys and strings, as TOML requires."""
    ids = ["\x7f", "a\x1fb", "\u2028", '"', "\\", "\t"]
    d = _two_d()
    d["nodes"] = dict(zip(ids, d["nodes"].values()))
    d["members"] = {f"m{c}": {"nodes": [ids[i], ids[i + 1]], "section": "r", "material": "s"}
                    for i, c in enumerate("\x7f\x1b\x0c")}
    d["supports"] = {ids[0]: ["x", "y"], ids[3]: ["x", "y"]}
    d["loads"] = {ids[1]: [1.0, -2.0]}
    d["model"]["name"] = "x\x7fy\x00"
    s = trussfe.model_from_dict(d)
    for mesh in (None, "m\x7f.vtu"):
        r = trussfe.read_model(write_model(s, tmp_path / "m.toml", mesh=mesh))
        assert model_differences(s, r, ids=mesh is None) == []


def test_header_with_control_characters(tmp_path):
    s = trussfe.model_from_dict(_two_d())
    p = write_model(s, tmp_path / "m.toml", header="made by\x1b[1m me\x7f\nsecond\tline")
    assert p.read_text(encoding="utf-8").startswith("# made by\\x1b[1m me\\x7f\n"
                                                    "# second\tline\n")
    assert model_differences(s, trussfe.read_model(p)) == []


def test_release_flags_a_plane_model_has_no_axis_for(tmp_path):
    """A 2-D beam's "my" and torsion flags (which a structure built in Python may hold, and no
    analysis reads in 2-D) are left out, so that the file is readable; "mz" alone reads back as
    the bending release it is, with the same results."""
    s = trussfe.model_from_dict(_two_d())
    for variant in (s.with_member_data(bending_axis_releases={1: [[True, False], [True, False]]}),
                    s.with_member_data(torsion_releases={1: [True, True]}),
                    s.with_member_data(bending_axis_releases={1: [[False, True], [False, False]]})):
        r = trussfe.read_model(write_model(variant, tmp_path / "m.toml"))
        assert analysis_results(r) == analysis_results(variant)
    assert r.releases[1].tolist() == [True, False]


@pytest.mark.parametrize("value", [0.1 + 0.2, 1e-320, 5e-324, -0.0, 1 / 3, 2.2250738585072014e-308,
                                   1.2345678901234567e17, 9007199254740993.0])
def test_floats_read_back_to_the_bit(tmp_path, value):
    d = _two_d()
    d["nodes"]["B"] = [value if abs(value) < 1.0 else value % 1.0, 1.0]
    d["model"]["gravity"] = [value, -9.81]
    d["materials"]["s"]["thermal_expansion"] = value
    d["sections"]["r"]["Iy"] = abs(value) or 1e-6
    d["loads"]["C"] = [value, -500.0, value]
    d["masses"] = {"B": abs(value), "C": {"mass": 1.0, "inertia": [abs(value) + 1e-300]}}
    s = trussfe.model_from_dict(d)
    r = trussfe.read_model(write_model(s, tmp_path / "m.toml"))
    assert model_differences(s, r) == []
    assert math.copysign(1.0, r.gravity[0]) == math.copysign(1.0, value)


def test_integer_and_string_keys_from_python(tmp_path):
    """``1`` and ``"1"`` are one id: written once, quoted where TOML needs it, read back."""
    d = _two_d()
    d["nodes"] = {1: [0.0, 0.0], "2": [1.0, 1.0], 3.5: [2.0, 1.0], "true": [3.0, 0.0]}
    d["members"] = {1: {"nodes": [1, "2"], "section": "r", "material": "s", "type": "beam"},
                    "2": {"nodes": ["2", 3.5], "section": "r", "material": "s", "type": "beam"},
                    "inf": {"nodes": ["3.5", "true"], "section": "r", "material": "s",
                            "type": "beam"}}
    d["supports"] = {1: ["x", "y", "rz"], "true": ["x", "y", "rz"]}
    d["loads"] = {"2": [1.0, -1.0]}
    s = trussfe.model_from_dict(d)
    assert list(s.node_ids) == ["1", "2", "3.5", "true"]
    r = trussfe.read_model(write_model(s, tmp_path / "m.toml"))
    assert model_differences(s, r) == []
    assert '"3.5" = [2.0, 1.0]' in model_toml(s)


def test_long_ids_and_name(tmp_path):
    d = _two_d(model={"dimension": 2, "name": "n" * 100_000})
    d["nodes"] = {k * 10_000: v for k, v in zip("abcd", d["nodes"].values())}
    d["members"] = {f"{k} {'x' * 5000}": {"nodes": ["a" * 10_000, "b" * 10_000],
                                           "section": "r", "material": "s"} for k in "m"}
    d["members"]["other"] = {"nodes": ["b" * 10_000, "c" * 10_000], "section": "r",
                             "material": "s"}
    d["members"]["third"] = {"nodes": ["c" * 10_000, "d" * 10_000], "section": "r",
                             "material": "s"}
    d["supports"] = {"a" * 10_000: ["x", "y"], "d" * 10_000: ["x", "y"]}
    d["loads"] = {"b" * 10_000: [1.0, 2.0]}
    s = trussfe.model_from_dict(d)
    r = trussfe.read_model(write_model(s, tmp_path / "m.toml"))
    assert model_differences(s, r) == []


# ---------------------------------------------------------------------- files and paths
def test_relative_paths(tmp_path, monkeypatch):
    """A relative model path, and a mesh named relative to the model file's folder (below it
    or above it), read back from any working folder."""
    s = trussfe.model_from_dict(every_table(True))
    monkeypatch.chdir(tmp_path)
    (tmp_path / "sub").mkdir()
    for path, mesh in (("m.toml", "m.vtu"), ("sub/m.toml", "geometry/m.vtu"),
                       ("sub/n.toml", "../n.vtu")):
        assert write_model(s, path, mesh=mesh) == Path(path)
        assert (Path(path).parent / mesh).is_file()
        monkeypatch.chdir("/")
        r = trussfe.read_model(tmp_path / path)
        monkeypatch.chdir(tmp_path)
        assert len(model_differences(s, r, ids=False)) == 3       # the ids of the mesh only
    assert oct((tmp_path / "m.toml").stat().st_mode & 0o777) == oct(
        (tmp_path / "m.vtu").stat().st_mode & 0o777)


def _files(folder: Path) -> list[str]:
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


@pytest.mark.parametrize("mesh", [None, "m.vtu"])
def test_unwritable_destination_is_one_error_and_nothing_is_written(tmp_path, mesh):
    """A model path that is a folder, or whose parent is a file: one OutputError naming the
    file; neither the model file nor its mesh is left behind (nor a temporary file)."""
    s = trussfe.model_from_dict(_two_d())
    (tmp_path / "folder.toml").mkdir()
    (tmp_path / "file").write_text("x")
    before = _files(tmp_path)
    for path in (tmp_path / "folder.toml", tmp_path / "file" / "m.toml"):
        with pytest.raises(OutputError) as err:
            write_model(s, path, mesh=mesh)
        assert str(tmp_path) in str(err.value) and "\n" not in str(err.value)
        assert _files(tmp_path) == before


def test_existing_mesh_is_kept_when_the_model_cannot_be_written(tmp_path):
    s = trussfe.model_from_dict(_two_d())
    (tmp_path / "m.vtu").write_text("an earlier mesh")
    (tmp_path / "m.toml").mkdir()
    with pytest.raises(OutputError, match="m.toml"):
        write_model(s, tmp_path / "m.toml", mesh="m.vtu")
    assert (tmp_path / "m.vtu").read_text() == "an earlier mesh"


def test_mesh_format_meshio_cannot_write(tmp_path):
    s = trussfe.model_from_dict(_two_d())
    with pytest.raises(OutputError, match=r"m\.unknown-format: cannot write the mesh") as err:
        write_model(s, tmp_path / "m.toml", mesh="m.unknown-format")
    assert ".m.unknown-format." not in str(err.value)        # the temporary file is not named
    assert _files(tmp_path) == []


def test_text_that_is_not_unicode(tmp_path):
    """A lone surrogate (possible in a Python string, not in a TOML file): one OutputError
    before anything is written."""
    s = trussfe.model_from_dict(_two_d()).variant(name="bad \ud800 name")
    with pytest.raises(OutputError, match="not valid Unicode"):
        write_model(s, tmp_path / "m.toml", mesh="m.vtu")
    assert _files(tmp_path) == []
