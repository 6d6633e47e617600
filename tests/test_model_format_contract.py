# SPDX-License-Identifier: MIT
"""The model file as docs/model-format.md states it: keys, defaults, ids, mesh geometry, and
the writer that reads back exactly (``read_model(write_model(s, p))``)."""
from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import meshio
import numpy as np
import pytest

import trussfe
from trussfe import read_model
from trussfe.errors import InputError
from trussfe.io.model_writer import write_model

ROOT = Path(__file__).resolve().parents[1]


# ---------------------------------------------------------------------------- helpers
def _differences(a, b, path="") -> list[str]:
    """Where two values differ (dataclasses field by field, arrays exactly, nan = nan)."""
    if dataclasses.is_dataclass(a) and not isinstance(a, type):
        if type(a) is not type(b):
            return [f"{path}: {type(a).__name__} vs {type(b).__name__}"]
        return [d for f in dataclasses.fields(a)
                for d in _differences(getattr(a, f.name), getattr(b, f.name),
                                      f"{path}.{f.name}")]
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        a, b = np.asarray(a), np.asarray(b)
        same = a.shape == b.shape and (np.array_equal(a, b, equal_nan=True)
                                       if a.dtype.kind == "f" else np.array_equal(a, b))
        return [] if same else [path]
    if isinstance(a, (tuple, list)):
        if len(a) != len(b):
            return [f"{path}: {len(a)} vs {len(b)} items"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in _differences(x, y, f"{path}[{i}]")]
    if hasattr(a, "keys"):
        if set(a.keys()) != set(b.keys()):
            return [f"{path}: tables {sorted(a.keys())} vs {sorted(b.keys())}"]
        return [d for k in a.keys() for d in _differences(a[k], b[k], f"{path}[{k}]")]
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return []
    return [] if a == b else [f"{path}: {a!r} vs {b!r}"]


def _structure_differences(s, r, *, ids=True) -> list[str]:
    skip = {"source"} | (set() if ids else {"node_ids", "member_ids"})
    out = [d for f in dataclasses.fields(s) if f.name not in skip
           for d in _differences(getattr(s, f.name), getattr(r, f.name), f.name)]
    for attr in ("area", "Iy", "Iz", "J", "c", "shear_area_y", "shear_area_z", "E", "G",
                 "density", "yield_strength"):
        out += _differences(getattr(s, attr), getattr(r, attr), attr)
    return out


def _frame(**member_extra) -> dict:
    """A 2-D portal as plain tables (docs/python.md, *Building a model in Python*)."""
    beam = {"section": "box", "material": "steel", "type": "beam"}
    return {
        "model": {"name": "portal", "dimension": 2},
        "materials": {"steel": {"E": 2.0e11, "density": 7850.0, "thermal_expansion": 1.2e-5,
                                "yield_strength": 2.5e8}},
        "sections": {"box": {"area": 4.0e-3, "Iz": 8.0e-6, "c": 0.1}},
        "nodes": {"A": [0.0, 0.0], "B": [0.0, 3.0], "C": [4.0, 3.0], "D": [4.0, 0.0]},
        "members": {"AB": {"nodes": ["A", "B"], **beam}, "BC": {"nodes": ["B", "C"], **beam},
                    "CD": {"nodes": ["C", "D"], **beam, **member_extra}},
        "supports": {"A": ["x", "y", "rz"], "D": ["x", "y"]},
    }


# ---------------------------------------------------------------------------- the writer
EXTENSION_MODELS = [
    "meshes/triangular_truss_motion_active.toml",     # [active_members]
    "meshes/double_octahedron_actuators.toml",        # [active_members], [actuators]
    "meshes/postcritical_dome.toml",                  # [failure], [postcritical]
    "meshes/postcritical_euler_column.toml",          # [postcritical]
    "validation/models/member_loads_simply_supported.toml",    # member_loads
    "validation/models/member_loads_fixed_fixed_point.toml",
]


@pytest.mark.parametrize("name", EXTENSION_MODELS)
def test_writer_reads_back_extension_tables(tmp_path, name):
    """model-format.md, *Writing model files*: the file written "reads back exactly"; the
    extension tables (member loads, active members, actuators, failure laws, post-critical
    settings) are part of the model and are written too."""
    s = read_model(ROOT / name)
    assert s.extensions, name
    r = read_model(write_model(s, tmp_path / "m.toml"))
    assert _structure_differences(s, r) == []


def test_writer_reads_back_every_shipped_model(tmp_path):
    """read -> write -> read gives the same structure for every model in meshes/ and
    validation/models/ (motion files, which are not models, are left out)."""
    names = sorted(ROOT.glob("meshes/*.toml")) + sorted(ROOT.glob("validation/models/*.toml"))
    checked = 0
    for path in names:
        if "[motion]" in path.read_text(encoding="utf-8"):
            continue
        s = read_model(path)
        r = read_model(write_model(s, tmp_path / path.name))
        assert _structure_differences(s, r) == [], path.name
        checked += 1
    assert checked >= 30


def test_writer_reads_back_failure_laws_and_acme_threads(tmp_path):
    """Every failure law and an Acme thread angle come back to the last bit: a softening law,
    a yield law with a member's own strength, a fracture strain, thread angles in degrees."""
    text = (ROOT / "meshes/double_octahedron_actuators.toml").read_text(encoding="utf-8")
    text = text.replace('thread = "square"', 'thread = "acme"\nthread_angle = 10.3')
    text += """
[failure.members.M2]
yield = "remove"

[failure.default]
buckling = "softening"
effective_length_factor = 0.7
residual = 0.3
softening_strain = 0.002

[failure.members.M1]
yield = "cap"
yield_strength = 1.234567e8
fracture_strain = 0.05
"""
    text = text.replace("[materials.aluminium]", "[materials.aluminium]\nyield_strength = 2.76e8")
    src = tmp_path / "src.toml"
    src.write_text(text, encoding="utf-8")
    s = read_model(src)
    assert s.extensions["actuators"][0].thread == "acme"
    r = read_model(write_model(s, tmp_path / "m.toml"))
    assert _structure_differences(s, r) == []


def test_writer_mesh_file_names_members_by_index_in_load_cases(tmp_path):
    """With mesh=..., ids become the mesh's indices (model-format.md, *Geometry from a mesh
    file*): the load cases must name members by those indices too (they kept 'BC', which the
    file read back refused)."""
    d = _frame()
    d["load_cases"] = {"hot": {"temperature": [{"members": ["BC"], "delta_T": 30.0}],
                               "member_loads": [{"member": "CD", "kind": "uniform",
                                                 "q": [0.0, -500.0]}]}}
    s = trussfe.model_from_dict(d)
    r = read_model(write_model(s, tmp_path / "m.toml", mesh="m.vtu"))
    assert _structure_differences(s, r, ids=False) == []


def test_writer_mesh_file_keeps_each_beam_orientation(tmp_path):
    """With mesh=..., a group carries one orientation: beams alike in all else but their
    orientation vector (model-format.md, `orientation`) must not share a group."""
    beam = {"section": "box", "material": "steel", "type": "beam"}
    s = trussfe.model_from_dict({
        "model": {"dimension": 3},
        "materials": {"steel": {"E": 2.1e11, "G": 8.1e10}},
        "sections": {"box": {"area": 4e-3, "Iy": 8e-6, "Iz": 5e-6, "J": 1e-5, "c": 0.05}},
        "nodes": {"A": [0, 0, 0], "B": [0, 0, 3], "C": [4, 0, 3]},
        "members": {"AB": {"nodes": ["A", "B"], **beam, "orientation": [1, 0, 0]},
                    "BC": {"nodes": ["B", "C"], **beam, "orientation": [0, 1, 0]}},
        "supports": {"A": ["x", "y", "z", "rx", "ry", "rz"]}})
    r = read_model(write_model(s, tmp_path / "m.toml", mesh="m.vtu"))
    np.testing.assert_array_equal(r.orientation, [[1, 0, 0], [0, 1, 0]])


# ---------------------------------------------------------------------------- ids
@pytest.mark.parametrize("table, entries", [
    ("nodes", {1: [0.0, 0.0], "1": [5.0, 5.0]}),
    ("members", {7: {"nodes": ["A", "B"], "section": "box", "material": "steel"},
                 "7": {"nodes": ["A", "C"], "section": "box", "material": "steel"}}),
    ("loads", {"C": [1.0, 0.0]}),
])
def test_python_ids_are_strings_given_once(table, entries):
    """model-format.md: "ids are strings"; model_from_dict goes through the reader's checks
    (python.md).  1 and "1" are one id: given twice, it is refused naming the table (a second
    node '1' was kept apart from the members, a load on node 2 and "2" doubled)."""
    d = _frame()
    d["nodes"] = {"A": [0.0, 0.0], "B": [0.0, 3.0], "C": [4.0, 3.0], "D": [4.0, 0.0]}
    if table == "nodes":
        d["nodes"].update(entries)
    elif table == "members":
        d["members"] = entries
    else:
        d["nodes"] = {1: [0.0, 0.0], 2: [0.0, 3.0], 3: [4.0, 3.0], 4: [4.0, 0.0]}
        for m in d["members"].values():
            m["nodes"] = [{"A": 1, "B": 2, "C": 3, "D": 4}[n] for n in m["nodes"]]
        d["supports"] = {1: ["x", "y", "rz"], "4": ["x", "y"]}
        d["loads"] = {2: [1.0, 0.0], "2": [1.0, 0.0]}
    with pytest.raises(InputError, match=rf"^{table}\.\S+: .*given twice"):
        trussfe.model_from_dict(d)


def test_python_integer_ids_name_the_string_ids():
    """Integer keys in a Python dict are the string ids (a section named 1 is section '1')."""
    d = _frame()
    d["sections"] = {1: d["sections"]["box"]}
    for m in d["members"].values():
        m["section"] = 1
    d["nodes"] = {10: [0.0, 0.0], "B": [0.0, 3.0], "C": [4.0, 3.0], "D": [4.0, 0.0]}
    d["members"]["AB"]["nodes"] = [10, "B"]
    d["supports"] = {10: ["x", "y", "rz"], "D": ["x", "y"]}
    s = trussfe.model_from_dict(d)
    assert s.node_ids[0] == "10" and s.sections[0].name == "1"
    assert s.supports[0, :3].all()


# ---------------------------------------------------------------------------- sections
def test_tube_outer_fibre_distance_is_computed():
    """model-format.md: a tube has "A, I, J = 2I, c = D/2 computed".  A c that differs was
    accepted and dropped (c stayed D/2); it is refused, and c = D/2 is accepted."""
    D, d = 0.05, 0.04
    model = _frame()
    model["sections"] = {"box": {"outer_diameter": D, "inner_diameter": d, "c": 0.5}}
    with pytest.raises(InputError, match=r"^sections\.box\.c: .*outer_diameter / 2"):
        trussfe.model_from_dict(model)
    model["sections"]["box"]["c"] = D / 2
    s = trussfe.model_from_dict(model)
    # the closed forms π/4(D²−d²), π/64(D⁴−d⁴), π/32(D⁴−d⁴), D/2
    assert s.area[0] == pytest.approx(math.pi / 4 * (D**2 - d**2), rel=1e-15)
    assert s.Iy[0] == s.Iz[0] == pytest.approx(math.pi / 64 * (D**4 - d**4), rel=1e-15)
    assert s.J[0] == pytest.approx(math.pi / 32 * (D**4 - d**4), rel=1e-15)
    assert s.c[0] == D / 2


# ---------------------------------------------------------------------------- orientation
def test_orientation_along_its_member_is_refused_naming_the_file(tmp_path):
    """model-format.md: orientation is "a non-zero vector in the local x-y plane", and every
    problem in a model file is reported naming the file (the reader accepted a vector along
    the member; the analysis then refused it without the file's name)."""
    path = tmp_path / "m.toml"
    path.write_text("""
[model]
dimension = 3
[materials.steel]
E = 2.1e11
[sections.box]
area = 4.0e-3
Iy = 8.0e-6
c = 0.05
[nodes]
A = [0.0, 0.0, 0.0]
B = [2.0, 0.0, 0.0]
[members]
AB = { nodes = ["A", "B"], section = "box", material = "steel", type = "beam", orientation = [-3.0, 0.0, 0.0] }
[supports]
A = ["x", "y", "z", "rx", "ry", "rz"]
""")
    with pytest.raises(InputError, match=r"m\.toml: members\.AB: orientation vector is parallel"):
        read_model(path)


# ---------------------------------------------------------------------------- mesh models
def _mesh_model(tmp_path, tables: str, mesh: meshio.Mesh | None = None) -> Path:
    pts = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
    if mesh is None:
        mesh = meshio.Mesh(pts, [("line", np.array([[0, 1], [1, 2], [2, 3], [3, 0]]))],
                           cell_data={"gmsh:physical": [np.array([1, 1, 2, 2])]})
    meshio.write(tmp_path / "m.msh", mesh, file_format="gmsh22", binary=False)
    path = tmp_path / "m.toml"
    path.write_text("""
[model]
mesh = "m.msh"
dimension = 2
[materials.al]
E = 7.0e10
[sections.thin]
area = 1.0e-4
[sections.thick]
area = 4.0e-4
[supports]
0 = ["x", "y"]
1 = ["x", "y"]
""" + tables)
    return path


def test_group_that_names_no_cell_set_is_refused(tmp_path):
    """model-format.md: a line cell's cell set (or Gmsh physical tag) picks a [groups.NAME]
    table; a group naming none of them (a typo) is refused with the valid names (the members
    silently took the 'default' group)."""
    path = _mesh_model(tmp_path, """
[groups.default]
section = "thin"
material = "al"
[groups.3]
section = "thick"
material = "al"
""")
    with pytest.raises(InputError, match=r"groups\.3: the mesh has no cell set .*'3'"):
        read_model(path)


def test_groups_need_a_mesh():
    """model-format.md: [groups.NAME] gives properties per cell set of *mesh models*; beside
    [members] it would be ignored unchecked (here it names a section that does not exist),
    so it is refused."""
    d = _frame()
    d["groups"] = {"default": {"section": "nosuch", "material": "steel"}}
    with pytest.raises(InputError, match=r"^\[groups\]: .*no \[model\] mesh"):
        trussfe.model_from_dict(d)


@pytest.mark.parametrize("table", ["nodes", "members"])
def test_mesh_model_refuses_nodes_and_members_tables(tmp_path, table):
    """model-format.md: `[model] mesh` "reads the nodes and members from" the mesh; a
    [nodes] or [members] table beside it would be ignored, even one naming an undefined
    node, so it is refused."""
    extra = {"nodes": '[nodes]\nA = [0.0, 0.0]\n',
             "members": '[members]\nX = { nodes = ["A", "B"], section = "thin", '
                        'material = "al" }\n'}[table]
    path = _mesh_model(tmp_path, "[groups.1]\nsection = \"thin\"\nmaterial = \"al\"\n"
                       "[groups.2]\nsection = \"thick\"\nmaterial = \"al\"\n" + extra)
    with pytest.raises(InputError, match=rf"m\.toml: \[{table}\]: the geometry comes from"):
        read_model(path)


def test_mesh_members_are_the_line_cells_in_order(tmp_path):
    """model-format.md, *Geometry from a mesh file*: only line cells are members, numbered
    from 0 in file order (a vertex cell before them does not shift the numbering), and each
    takes the group of its physical tag."""
    pts = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
    mesh = meshio.Mesh(pts, [("vertex", np.array([[0]])),
                             ("line", np.array([[0, 1], [1, 2], [2, 3], [3, 0]]))],
                       cell_data={"gmsh:physical": [np.array([5]), np.array([1, 2, 2, 1])],
                                  "gmsh:geometrical": [np.array([1]), np.array([1, 2, 2, 1])]})
    path = _mesh_model(tmp_path, """
[groups.1]
section = "thin"
material = "al"
[groups.2]
section = "thick"
material = "al"
""", mesh)
    s = read_model(path)
    assert list(s.member_ids) == ["0", "1", "2", "3"]
    np.testing.assert_array_equal(s.connectivity, [[0, 1], [1, 2], [2, 3], [3, 0]])
    np.testing.assert_array_equal(s.area, [1e-4, 4e-4, 4e-4, 1e-4])
