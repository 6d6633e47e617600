"""Property: any small model built from the format's tables — random ids, floats to the last
bit, bars and beams with releases, supports, loads, masses, springs, member loads, load
cases — reads back from the file written for it as the same model."""
from __future__ import annotations

import tempfile
from pathlib import Path

import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from test_model_roundtrip_tables import model_differences

import trussfe
from trussfe.errors import InputError
from trussfe.io.model_writer import write_model

# any finite float (subnormals and -0.0 included), positive ones, and small offsets
ANY = st.floats(allow_nan=False, allow_infinity=False)
POSITIVE = st.floats(min_value=5e-324, max_value=1e300)
NONNEG = st.floats(min_value=0.0, max_value=1e300)
OFFSET = st.floats(min_value=-0.25, max_value=0.25)
# a zero strain reads back as no strain (None), the same load
NONZERO = ANY.filter(lambda x: x != 0.0)
IDS = st.text(min_size=0, max_size=6)


@st.composite
def models(draw) -> dict:
    dim = draw(st.sampled_from((2, 3)))
    dofs = ("x", "y", "rz") if dim == 2 else ("x", "y", "z", "rx", "ry", "rz")
    n = draw(st.integers(2, 5))
    node_ids = draw(st.lists(IDS, min_size=n, max_size=n, unique=True))
    # nodes apart on a line, each moved by less than a quarter of the spacing
    nodes = {k: [i + draw(OFFSET), *(draw(OFFSET) for _ in range(dim - 1))]
             for i, k in enumerate(node_ids)}
    pairs = [(i, i + 1) for i in range(n - 1)] + draw(st.lists(
        st.tuples(st.integers(0, n - 1), st.integers(0, n - 1)).filter(
            lambda p: p[1] > p[0] + 1), max_size=3, unique=True))
    member_ids = draw(st.lists(IDS, min_size=len(pairs), max_size=len(pairs), unique=True))
    materials = {f"mat {j}": {"E": draw(POSITIVE), "G": draw(POSITIVE),
                              "density": draw(NONNEG),
                              **({"thermal_expansion": draw(ANY)} if draw(st.booleans())
                                 else {})} for j in range(draw(st.integers(1, 2)))}
    sections = {}
    for j in range(draw(st.integers(1, 2))):
        if draw(st.booleans()):
            outer = draw(st.floats(min_value=1e-3, max_value=1.0))
            sections[f"s.{j}"] = {"outer_diameter": outer,
                                  "inner_diameter": draw(st.floats(0.0, outer * 0.99))}
        else:
            sections[f"s.{j}"] = {"area": draw(POSITIVE), "Iy": draw(POSITIVE),
                                  "Iz": draw(POSITIVE), "J": draw(POSITIVE),
                                  "c": draw(POSITIVE)}
        if draw(st.booleans()):
            sections[f"s.{j}"]["shear_area_y"] = draw(POSITIVE)
    names = ["bending", "all", "mz"] + (["my", "t", "torsion"] if dim == 3 else [])
    members = {}
    for mid, (a, b) in zip(member_ids, pairs):
        m = {"nodes": [node_ids[a], node_ids[b]],
             "section": draw(st.sampled_from(sorted(sections))),
             "material": draw(st.sampled_from(sorted(materials)))}
        if draw(st.booleans()):
            m["type"] = "beam"
            m["releases"] = draw(st.one_of(
                st.lists(st.sampled_from(("start", "end")), unique=True),
                st.dictionaries(st.sampled_from(("start", "end")),
                                st.lists(st.sampled_from(names), min_size=1, unique=True))))
        members[mid] = m
    supports, springs = {}, {}
    for k in node_ids:
        fixed = draw(st.lists(st.sampled_from(dofs), unique=True))
        if fixed:
            supports[k] = fixed
        free = [d for d in dofs if d not in fixed]
        spring = draw(st.dictionaries(st.sampled_from(free), NONNEG)) if free else {}
        if spring:
            springs[k] = spring
    d = {"model": {"dimension": dim, "name": draw(st.text(max_size=8)),
                   "gravity": [draw(ANY) for _ in range(dim)]},
         "materials": materials, "sections": sections, "nodes": nodes, "members": members,
         "supports": supports, "springs": springs}
    loads = st.dictionaries(st.sampled_from(node_ids), st.lists(
        ANY, min_size=len(dofs), max_size=len(dofs)) | st.lists(ANY, min_size=dim,
                                                                 max_size=dim), max_size=3)
    masses = st.dictionaries(st.sampled_from(node_ids), NONNEG | st.fixed_dictionaries(
        {"mass": NONNEG, "inertia": st.lists(NONNEG, min_size=dim * 2 - 3,
                                             max_size=dim * 2 - 3)}), max_size=3)
    d["masses"] = draw(masses)
    member_load = st.fixed_dictionaries({
        "member": st.sampled_from(member_ids), "kind": st.just("point"),
        "at": st.floats(0.0, 1.0), "F": st.lists(ANY, min_size=dim, max_size=dim),
        "axes": st.sampled_from(("global", "local"))}) | st.fixed_dictionaries({
            "member": st.sampled_from(member_ids), "kind": st.just("trapezoidal"),
            "q_start": st.lists(ANY, min_size=dim, max_size=dim),
            "q_end": st.lists(ANY, min_size=dim, max_size=dim)})
    if draw(st.booleans()):
        d["loads"] = draw(loads)
        d["member_loads"] = draw(st.lists(member_load, max_size=2))
    else:
        cases = draw(st.lists(IDS, min_size=1, max_size=3, unique=True))
        d["load_cases"] = {c: {"loads": draw(loads),
                               "initial_strain": [{"member": draw(st.sampled_from(member_ids)),
                                                   "strain": draw(NONZERO)}],
                               "member_loads": draw(st.lists(member_load, max_size=2))}
                           for c in cases}
        d["combinations"] = {draw(IDS): {c: draw(ANY) for c in cases}}
    return d


@settings(max_examples=60, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(models())
def test_random_model_reads_back_identical(data):
    try:
        s = trussfe.model_from_dict(data)
    except InputError:
        assume(False)           # a drawn combination the format refuses (a couple on a bar, ...)
    with tempfile.TemporaryDirectory() as folder:
        r = trussfe.read_model(write_model(s, Path(folder) / "m.toml"))
    # an empty top-level member_loads array is not written (nothing reads an empty one)
    if s.extensions.get("member_loads") == ():
        s = s.without_extensions("member_loads")
    assert model_differences(s, r) == []
