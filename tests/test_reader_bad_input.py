"""Bad model files: each gives one InputError naming the item, and ``trussfe static`` exits
with status 2, one line on stderr and no output file.  Plus a hypothesis fuzz test of the
reader: any TOML-ish input gives a Structure or an InputError, never another exception."""
import math
import string
import tomllib

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from trussfe.cli import main
from trussfe.errors import InputError
from trussfe.io.model_file import parse_model, read_model
from trussfe.io.model_writer import toml_key, toml_value
from trussfe.model import Structure

GOOD = """\
[model]
name = "two-bar"
dimension = 2

[materials.al]
E = 71.0e9
density = 2711.5

[sections.tube]
outer_diameter = 0.0254
inner_diameter = 0.022225

[nodes]
A = [-1.0, 0.0]
B = [0.0, 1.0]
C = [1.0, 0.0]

[members]
AB = { nodes = ["A", "B"], section = "tube", material = "al" }
BC = { nodes = ["B", "C"], section = "tube", material = "al" }

[supports]
A = ["x", "y"]
C = ["x", "y"]

[loads]
B = [0.0, -1000.0]
"""

# (name, replace old -> new in GOOD, item the message names, words the message holds)
BAD = [
    ("malformed TOML", ('[nodes]', '[nodes'), "m.toml", "malformed TOML"),
    ("unknown table", ('[supports]', '[suports]'), "[suports]", "did you mean 'supports'"),
    ("unknown key", ('density = 2711.5', 'densty = 2711.5'), "materials.al.densty",
     "did you mean 'density'"),
    ("unknown member key", ('section = "tube", material = "al" }\nBC',
                            'secton = "tube", material = "al" }\nBC'), "members.AB.secton",
     "did you mean 'section'"),
    ("missing node", ('nodes = ["B", "C"]', 'nodes = ["B", "D"]'), "members.BC.nodes",
     "node 'D' is not defined"),
    ("missing section", ('BC = { nodes = ["B", "C"], section = "tube"',
                         'BC = { nodes = ["B", "C"], section = "tub"'), "members.BC.section",
     "did you mean 'tube'"),
    ("missing material", ('BC = { nodes = ["B", "C"], section = "tube", material = "al"',
                          'BC = { nodes = ["B", "C"], section = "tube", material = "steel"'),
     "members.BC.material", "material 'steel' is not defined"),
    ("zero-length member (same node)", ('nodes = ["B", "C"]', 'nodes = ["B", "B"]'),
     "members.BC.nodes", "zero length"),
    ("zero-length member (coincident nodes)", ('C = [1.0, 0.0]\n', 'C = [0.0, 1.0]\n'),
     "members.BC", "zero length"),
    ("duplicate member", ('BC = { nodes = ["B", "C"]', 'BC = { nodes = ["B", "A"]'),
     "members.BC", "duplicates member 'AB'"),
    ("zero E", ('E = 71.0e9', 'E = 0.0'), "materials.al.E", "must be positive"),
    ("negative E", ('E = 71.0e9', 'E = -71.0e9'), "materials.al.E", "must be positive"),
    ("non-positive area", ('outer_diameter = 0.0254\ninner_diameter = 0.022225',
                           'area = -1e-4'), "sections.tube.area", "must be positive"),
    ("zero area", ('outer_diameter = 0.0254\ninner_diameter = 0.022225', 'area = 0'),
     "sections.tube.area", "must be positive"),
    ("inner diameter >= outer", ('inner_diameter = 0.022225', 'inner_diameter = 0.0254'),
     "sections.tube.inner_diameter", "must be smaller than outer diameter"),
    ("2-D model with 3-D coordinates", ('B = [0.0, 1.0]', 'B = [0.0, 1.0, 0.5]'), "nodes.B",
     "has 3 coordinates but [model] dimension = 2"),
    ("text for a number", ('E = 71.0e9', 'E = "71e9"'), "materials.al.E", "expected a number"),
    ("non-finite coordinate", ('B = [0.0, 1.0]', 'B = [0.0, inf]'), "nodes.B[1]", "finite"),
    ("unknown DOF", ('A = ["x", "y"]', 'A = ["x", "w"]'), "supports.A", "unknown DOF 'w'"),
    # holes found by fuzzing and probing the reader, fixed
    ("dimension as a float", ('dimension = 2', 'dimension = 2.0'), "model.dimension",
     "must be 2 or 3"),
    ("integer beyond float range", ('B = [0.0, 1.0]', 'B = [0.0, ' + '9' * 400 + ']'),
     "nodes.B[1]", "number too large"),
    ("name not a string", ('name = "two-bar"', 'name = { a = 1 }'), "model.name",
     "expected a string"),
    ("coordinates overflow", ('C = [1.0, 0.0]', 'C = [1e308, -1e308]'), "members.BC",
     "coordinates too large"),
    ("zero orientation vector", ('BC = { nodes = ["B", "C"], section = "tube", material = "al" }',
                                 'BC = { nodes = ["B", "C"], section = "tube", material = "al",'
                                 ' type = "beam", orientation = [0, 0, 0] }'),
     "members.BC.orientation", "non-zero"),
    ("load on missing node", ('B = [0.0, -1000.0]', 'Q = [0.0, -1000.0]'), "loads.Q",
     "node 'Q' is not defined"),
    # loads along members, per-axis releases and shear-deformable sections
    ("member load on missing member", ('[model]\n', 'member_loads = [{ member = "XY", '
                                       'kind = "uniform", q = [0.0, -1.0] }]\n[model]\n'),
     "member_loads[0].member", "member 'XY' is not defined"),
    ("member load position outside [0, 1]",
     ('[model]\n', 'member_loads = [{ member = "AB", kind = "point", at = 1.5, '
                    'F = [0.0, -1.0] }]\n[model]\n'), "member_loads[0] (member AB).at",
     "[0, 1]"),
    ("member load unknown kind",
     ('[model]\n', 'member_loads = [{ member = "AB", kind = "parabolic", q = [0.0, -1.0] }]'
                    '\n[model]\n'), "member_loads[0] (member AB).kind", "unknown member-load kind"),
    ("member load unknown axes",
     ('[model]\n', 'member_loads = [{ member = "AB", kind = "uniform", q = [0.0, -1.0], '
                    'axes = "polar" }]\n[model]\n'), "member_loads[0] (member AB).axes",
     "unknown axes"),
    ("member load vector length",
     ('[model]\n', 'member_loads = [{ member = "AB", kind = "uniform", q = [0.0, -1.0, 0.0] }]'
                    '\n[model]\n'), "member_loads[0] (member AB).q", "expected 2 numbers, got 3"),
    ("member load not an array", ('[model]\n', 'member_loads = 3\n[model]\n'),
     "member_loads", "expected an array of tables"),
    ("release name that does not exist",
     ('section = "tube", material = "al" }\nBC', 'section = "tube", material = "al", '
      'type = "beam", releases = { end = ["mq"] } }\nBC'), "members.AB.releases.end",
     "unknown release 'mq'"),
    ("Timoshenko section with zero shear area",
     ('inner_diameter = 0.022225', 'inner_diameter = 0.022225\nshear_area_y = 0.0'),
     "sections.tube.shear_area_y", "positive shear area"),
]


@pytest.mark.parametrize("name,edit,item,words", BAD, ids=[b[0] for b in BAD])
def test_bad_input(tmp_path, capsys, name, edit, item, words):
    old, new = edit
    assert old in GOOD
    path = tmp_path / "m.toml"
    path.write_text(GOOD.replace(old, new, 1), encoding="utf-8")
    with pytest.raises(InputError) as info:
        read_model(path)
    msg = str(info.value)
    assert msg.startswith(str(path)) and item in msg and words in msg, msg
    # the command line: exit 2, one line, nothing written
    out = tmp_path / "out.json"
    assert main(["static", str(path), "--json", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("trussfe: error: ") and item in err
    assert not out.exists()


def test_good_model_reads(tmp_path):
    path = tmp_path / "m.toml"
    path.write_text(GOOD, encoding="utf-8")
    s = read_model(path)
    assert s.member_ids == ("AB", "BC") and s.dim == 2


def test_missing_and_undecodable_file(tmp_path):
    with pytest.raises(InputError, match="file not found"):
        read_model(tmp_path / "none.toml")
    (tmp_path / "b.toml").write_bytes(b"\xff\xfe[model]")
    with pytest.raises(InputError, match="cannot read"):
        read_model(tmp_path / "b.toml")


# ------------------------------------------------------------------ fuzzing
KEYS = ["model", "materials", "sections", "nodes", "members", "supports", "loads", "masses",
        "groups", "name", "dimension", "gravity", "mesh", "E", "G", "density",
        "yield_strength", "outer_diameter", "inner_diameter", "area", "Iy", "Iz", "J", "c",
        "section", "material", "type", "releases", "orientation", "A", "B", "C", "al", "tube",
        "AB", "x", "y", "z", "rz", "start", "end", "beam", "bar"]

scalars = st.one_of(
    st.integers(-3, 3), st.integers(), st.integers(min_value=10**300, max_value=10**320),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from(KEYS), st.booleans(), st.text(string.printable, max_size=4))
values = st.recursive(
    scalars,
    lambda inner: st.one_of(st.lists(inner, max_size=4),
                            st.dictionaries(st.sampled_from(KEYS), inner, max_size=4)),
    max_leaves=25)
documents = st.dictionaries(st.sampled_from(KEYS), values, max_size=8)


def _mutate(base: dict, extra: dict) -> dict:
    """Merge fuzzed tables into a valid model, so that deep checks are reached too."""
    out = {k: (dict(v) if isinstance(v, dict) else v) for k, v in base.items()}
    for k, v in extra.items():
        if isinstance(out.get(k), dict) and isinstance(v, dict):
            out[k].update(v)
        else:
            out[k] = v
    return out


BASE = tomllib.loads(GOOD)


def _check(data):
    try:
        s = parse_model(data, source="fuzz.toml")
    except InputError as err:
        assert str(err) and "\n" not in str(err)
        return
    assert isinstance(s, Structure)
    assert s.coords.shape == (s.n_nodes, s.dim)
    assert all(math.isfinite(v) for v in s.coords.ravel())


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(documents)
def test_fuzz_reader_whole_documents(data):
    """Arbitrary TOML-shaped documents: a Structure or an InputError, nothing else."""
    _check(data)


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(documents)
def test_fuzz_reader_mutated_model(extra):
    """A valid model with fuzzed tables merged in."""
    _check(_mutate(BASE, extra))


@settings(max_examples=100, deadline=None)
@given(st.text(alphabet=string.printable, max_size=200))
def test_fuzz_reader_raw_text(tmp_path_factory, text):
    """Any text in a file: a Structure or one InputError."""
    path = tmp_path_factory.mktemp("fz") / "m.toml"
    path.write_text(GOOD[: len(GOOD) // 2] + text, encoding="utf-8")
    try:
        read_model(path)
    except InputError as err:
        assert "\n" not in str(err)


def test_writer_helpers_quote_fuzz_keys():
    """The writer's quoting is what the fuzz relies on to produce valid TOML text."""
    assert tomllib.loads(f"{toml_key('a b')} = {toml_value([1.5, 'x'])}") == {"a b": [1.5, "x"]}


def test_bad_mesh_files(tmp_path):
    """Mesh models: a missing file, a cell naming a missing point, a 3-D mesh for 2-D."""
    import meshio
    import numpy as np

    head = ('[model]\ndimension = 2\nmesh = "g.vtu"\n[materials.al]\nE = 1.0\n'
            '[sections.s]\narea = 1.0\n')
    (tmp_path / "m.toml").write_text(head)
    with pytest.raises(InputError, match="model.mesh.*not found"):
        read_model(tmp_path / "m.toml")
    pts = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])
    meshio.write(tmp_path / "g.vtu", meshio.Mesh(pts, [("line", np.array([[0, 1], [1, 5]]))]))
    with pytest.raises(InputError, match="point the mesh does not have"):
        read_model(tmp_path / "m.toml")
    pts[2, 2] = 1.0
    meshio.write(tmp_path / "g.vtu", meshio.Mesh(pts, [("line", np.array([[0, 1], [1, 2]]))]))
    with pytest.raises(InputError, match="non-zero z"):
        read_model(tmp_path / "m.toml")


# load cases, combinations, springs and rotary inertia: fuzzed into a model without [loads]
CASE_KEYS = ["loads", "gravity", "prescribed", "temperature", "initial_strain",
             "length_error", "member_loads", "member", "members", "delta_T", "strain",
             "delta", "A", "B", "C", "AB", "BC", "x", "y", "rz", "mass", "inertia", "dead",
             "live"]
case_scalars = st.one_of(
    st.integers(-3, 3), st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from(CASE_KEYS), st.booleans())
case_values = st.recursive(
    case_scalars,
    lambda inner: st.one_of(st.lists(inner, max_size=3),
                            st.dictionaries(st.sampled_from(CASE_KEYS), inner, max_size=3)),
    max_leaves=20)
CASE_BASE = {k: v for k, v in tomllib.loads(GOOD.replace(
    "density = 2711.5", "density = 2711.5\nthermal_expansion = 2.3e-5")).items()
    if k != "loads"}


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.fixed_dictionaries({}, optional={
    "load_cases": st.dictionaries(st.sampled_from(CASE_KEYS), case_values, max_size=3),
    "combinations": st.dictionaries(st.sampled_from(CASE_KEYS), case_values, max_size=2),
    "springs": st.dictionaries(st.sampled_from(CASE_KEYS), case_values, max_size=2),
    "masses": st.dictionaries(st.sampled_from(CASE_KEYS), case_values, max_size=2)}))
def test_fuzz_reader_load_case_tables(extra):
    """Fuzzed [load_cases], [combinations], [springs] and [masses]: a Structure (whose cases
    solve or are refused in one line) or an InputError, nothing else."""
    from trussfe.errors import TrussfeError
    from trussfe.fem.load_cases import solve_load_cases
    data = {**CASE_BASE, **extra}
    try:
        s = parse_model(data, source="fuzz.toml")
    except InputError as err:
        assert str(err) and "\n" not in str(err)
        return
    assert isinstance(s, Structure)
    try:
        solve_load_cases(s)
    except TrussfeError as err:
        assert "\n" not in str(err)
