# SPDX-License-Identifier: MIT
"""The model is immutable: variants are new models with new results, and nothing changes a
model in place.

Expected numbers are closed forms of a statically determinate two-bar truss (method of joints
and virtual work, named in each test)."""
from __future__ import annotations

import dataclasses
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe.fem import solve_static
from trussfe.io.model_file import read_model
from trussfe.model import (ActiveMember, FailureLaws, PostcriticalSettings, Section,
                           Structure, build_structure)
from trussfe.model.sections import Material

ROOT = Path(__file__).resolve().parents[1]
STEEL = Material("steel", E=2.0e11, G=8.0e10, density=0.0)
TUBE = Section.tube("tube", 0.05, 0.04)
BIG = Section("big", area=2.0 * TUBE.area, Iy=TUBE.Iy, Iz=TUBE.Iz, J=TUBE.J, c=TUBE.c)
P, L, TH = 1200.0, 1.5, np.radians(35.0)
EXACT = 1e-10


def two_bar() -> Structure:
    """Two bars of length L at ±θ to the vertical carrying a hanging load P."""
    a, h = L * np.sin(TH), L * np.cos(TH)
    return build_structure([[-a, h], [a, h], [0.0, 0.0]], [(2, 0), (2, 1)], section=TUBE,
                           material=STEEL, supports={0: "xy", 1: "xy"}, loads={2: [0.0, -P]},
                           member_ids=["left", "right"])


def _check_equilibrium(s: Structure, r) -> None:
    # every static result is in global equilibrium: reactions balance the applied loads
    assert_allclose(r.reactions[:, :2].sum(axis=0), -s.loads[:, :2].sum(axis=0),
                    rtol=0, atol=1e-9 * P)


def test_with_sections_gives_new_properties_and_stresses():
    """Method of joints: each bar carries N = P / (2 cos θ) whatever its area (the truss is
    determinate), so the stress of the bar whose area doubles halves; virtual work gives the
    joint's drop δ = Σ N n L / (E A_i) = P L / (4 E cos² θ) (1/A_0 + 1/A_1)."""
    s = two_bar()
    r1 = solve_static(s)
    N = P / (2 * np.cos(TH))
    A = TUBE.area
    assert_allclose(r1.axial_stress, [N / A, N / A], rtol=EXACT)

    s2 = s.with_sections({"left": BIG})
    assert s2.sections == (BIG, TUBE) and s.sections == (TUBE, TUBE)
    assert_allclose(s2.area, [2 * A, A], rtol=0)
    assert_allclose(s.area, [A, A], rtol=0)                 # the original is unchanged
    r2 = solve_static(s2)
    assert_allclose(r2.axial_force, [N, N], rtol=EXACT)
    assert_allclose(r2.axial_stress, [N / (2 * A), N / A], rtol=EXACT)
    drop = P * L / (4 * STEEL.E * np.cos(TH) ** 2) * (1 / (2 * A) + 1 / A)
    assert_allclose(-r2.displacements[2, 1], drop, rtol=EXACT)
    _check_equilibrium(s2, r2)
    # the first result and a new solve of the first model still belong to the thin bars
    assert_allclose(r1.axial_stress, [N / A, N / A], rtol=EXACT)
    assert_allclose(solve_static(s).axial_stress, [N / A, N / A], rtol=EXACT)

    # one section per member, and member indices, mean the same
    s3 = s.with_sections([BIG, TUBE])
    s4 = s.with_sections({0: BIG})
    assert_allclose(s3.area, s2.area, rtol=0)
    assert_allclose(s4.area, s2.area, rtol=0)


def test_with_materials_and_loads():
    """A stiffer material shortens the drop P L / (2 E A cos² θ) in proportion; twice the load
    doubles the bar forces P / (2 cos θ)."""
    s = two_bar()
    stiff = dataclasses.replace(STEEL, name="stiff", E=2 * STEEL.E)
    r = solve_static(s.with_materials([stiff, stiff]))
    assert_allclose(-r.displacements[2, 1],
                    P * L / (2 * 2 * STEEL.E * TUBE.area * np.cos(TH) ** 2), rtol=EXACT)
    s2 = s.with_loads(2 * s.loads)
    r2 = solve_static(s2)
    assert_allclose(r2.axial_force, P / np.cos(TH), rtol=EXACT)
    _check_equilibrium(s2, r2)
    # a translational load table (n, dim) is padded with zero moments
    assert_allclose(s.with_loads(2 * s.loads[:, :2]).loads, s2.loads, rtol=0)


@pytest.mark.parametrize("mutate", [
    lambda s: s.sections.__setitem__(0, BIG),
    lambda s: s.materials.__setitem__(0, STEEL),
    lambda s: s.coords.__setitem__((0, 0), 1.0),
    lambda s: s.area.__setitem__(0, 1.0),
    lambda s: s.E.__setitem__(0, 1.0),
    lambda s: s.loads.__setitem__((2, 1), 0.0),
    lambda s: s.supports.__setitem__((2, 0), True),
    lambda s: s.masses.__setitem__(0, 1.0),
    lambda s: s.gravity.__setitem__(0, 1.0),
    lambda s: s.connectivity.__setitem__((0, 0), 1),
    lambda s: s.releases.__setitem__(0, True),
    lambda s: s.is_beam.__setitem__(0, True),
    lambda s: s.orientation.__setitem__(0, 1.0),
    lambda s: s.node_ids.__setitem__(0, "x"),
    lambda s: s.extensions.__setitem__("failure", None),
    lambda s: setattr(s, "coords", np.zeros((3, 2))),
    lambda s: setattr(s, "sections", (BIG, BIG)),
    lambda s: setattr(s, "name", "other"),
], ids=["sections", "materials", "coords", "area", "E", "loads", "supports", "masses",
        "gravity", "connectivity", "releases", "is_beam", "orientation", "node_ids",
        "extensions", "set coords", "set sections", "set name"])
def test_direct_mutation_raises(mutate):
    s = two_bar()
    with pytest.raises((TypeError, ValueError, AttributeError)):
        mutate(s)


def test_arrays_given_are_copied_not_aliased():
    """Changing the array a model was built from does not change the model."""
    x = np.array([[0.0, 0.0], [1.0, 0.0]])
    loads = np.zeros((2, 3))
    s = build_structure(x, [(0, 1)], section=TUBE, material=STEEL)
    s2 = s.with_loads(loads)
    x[1, 0] = 5.0
    loads[1, 0] = 7.0
    assert s.coords[1, 0] == 1.0 and s2.loads[1, 0] == 0.0
    assert_allclose(s.lengths(), [1.0], rtol=0)


def test_variants_share_what_does_not_change():
    """A variant of other coordinates keeps the member properties (no recomputation)."""
    s = two_bar()
    moved = s.with_coords(s.coords * 2.0)
    assert moved.area is s.area and moved.connectivity is s.connectivity
    assert_allclose(moved.lengths(), 2 * s.lengths(), rtol=EXACT)
    assert s.variant(name="renamed").name == "renamed" and s.name != "renamed"
    with pytest.raises(TypeError, match="no field"):
        s.variant(colour="red")


def test_identity_equality_and_hash():
    """Models compare and hash by identity (documented in Structure's notes)."""
    s = two_bar()
    same_data = s.variant()
    assert s == s and s != same_data
    assert hash(s) == hash(s)
    assert {s: 1, same_data: 2}[s] == 1


def test_pickled_and_deep_copied_models_stay_frozen():
    import copy
    import pickle
    s = two_bar().with_sections({"left": BIG})
    for t in (pickle.loads(pickle.dumps(s)), copy.deepcopy(s)):
        assert_allclose(t.area, s.area, rtol=0)
        assert_allclose(t.coords, s.coords, rtol=0)
        with pytest.raises(ValueError):
            t.coords[0, 0] = 1.0
        with pytest.raises(ValueError):
            t.area[0] = 1.0


def test_subset_members_renumbers_extensions():
    s = build_structure([[0, 0], [1, 0], [2, 0]], [(0, 1), (1, 2), (0, 2)], section=TUBE,
                        material=STEEL, member_ids=["a", "b", "c"])
    act = ActiveMember(member=2, base_mass=1.0, base_length=0.5, base_cg=0.25,
                       base_inertia=1.0 * 0.5 ** 2 / 3, tube_length=1.0)
    laws = dataclasses.replace(FailureLaws.none(3), critical_load=[1.0, 2.0, 3.0])
    s = s.with_extensions(active_members=[act], failure=laws)
    sub = s.subset_members([False, True, True])
    assert sub.member_ids == ("b", "c")
    assert [a.member for a in sub.extensions["active_members"]] == [1]
    assert_allclose(sub.extensions["failure"].critical_load, [2.0, 3.0], rtol=0)
    assert_allclose(sub.area, [TUBE.area] * 2, rtol=0)
    # the active member's member is not kept: its table is empty
    assert s.subset_members([True, True, False]).extensions["active_members"] == ()


def test_extension_tables_are_checked():
    s = two_bar()
    with pytest.raises(ValueError, match="unknown extension table"):
        s.with_extensions(colour="red")
    with pytest.raises(ValueError, match="member index 5"):
        s.with_extensions(active_members=[ActiveMember(5, 1.0, 1.0, 0.5, 1.0, 1.0)])
    with pytest.raises(ValueError, match="FailureLaws of 2 members"):
        s.with_extensions(failure=FailureLaws.none(3))
    p = s.with_extensions(postcritical={"steps": 3}).extensions["postcritical"]
    assert p == PostcriticalSettings(steps=3) and p.options() == {"steps": 3}
    assert "postcritical" not in s.with_extensions(postcritical=None).extensions


def test_reading_a_model_file_imports_the_model_layer_only(tmp_path):
    """A model file with every extension table (active members, actuators, failure laws,
    post-critical settings) is read without importing an analysis package."""
    text = (ROOT / "meshes" / "double_octahedron_actuators.toml").read_text(encoding="utf-8")
    text += ('\n[failure.default]\nbuckling = "cap"\n\n'
             '[postcritical]\nsteps = 10\nmonitor = "N7:z"\n')
    path = tmp_path / "all_tables.toml"
    path.write_text(text, encoding="utf-8")
    code = ("import sys\n"
            "from trussfe.io.model_file import read_model\n"
            f"s = read_model({str(path)!r})\n"
            "print(sorted(s.extensions))\n"
            "bad = sorted(m for m in sys.modules if m.split('.')[:2] in (['trussfe', 'rigid'],"
            " ['trussfe', 'nonlinear'], ['trussfe', 'fem'], ['trussfe', 'kinematics'],"
            " ['trussfe', 'elastic']))\n"
            "print(bad)\n")
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=env, cwd=str(tmp_path), check=True).stdout.splitlines()
    assert out == ["['active_members', 'actuators', 'failure', 'postcritical']", "[]"]
    s = read_model(path)
    assert len(s.extensions["active_members"]) == 3 and len(s.extensions["actuators"]) == 3
    assert s.extensions["postcritical"].monitor == "N7:z"
    assert int(s.extensions["failure"].buckling.sum()) == s.n_members   # "cap" on every bar


def _arrays(obj, seen=None, depth=0):
    """Every numpy array reachable from a model: its fields, its member properties and the
    fields of its extension tables (dataclasses, mappings and tuples of them)."""
    seen = set() if seen is None else seen
    if id(obj) in seen or depth > 4:
        return
    seen.add(id(obj))
    if isinstance(obj, np.ndarray):
        yield obj
    elif dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        for f in dataclasses.fields(obj):
            yield from _arrays(getattr(obj, f.name), seen, depth + 1)
    elif isinstance(obj, (tuple, list)):
        for v in obj:
            yield from _arrays(v, seen, depth + 1)
    elif hasattr(obj, "items"):
        for v in obj.values():
            yield from _arrays(v, seen, depth + 1)


def _models():
    import copy
    import pickle
    s = two_bar()
    many = s.with_sections({"left": BIG})
    read = read_model(ROOT / "meshes" / "loads_closed_forms.toml")
    return {"one section": s, "two sections": many, "moved": s.with_coords(s.coords * 2.0),
            "subset": many.subset_members([True, False]),
            "pickled": pickle.loads(pickle.dumps(many)), "deep copy": copy.deepcopy(many),
            "model file with extensions": read}


@pytest.mark.parametrize("name", sorted(_models()))
def test_no_array_of_a_model_can_be_made_writable_again(name):
    """Structure's notes: every array is read-only.  ``flags.writeable = False`` alone would
    let ``setflags(write=True)`` undo it on an array that owns its memory, after which a
    change would reach every analysis of the model; numpy refuses it for a read-only view of
    a read-only owner."""
    s = _models()[name]
    arrays = list(_arrays(s)) + [s.area, s.E, s.Iy, s.Iz, s.J, s.density, s.c]
    assert len(arrays) > 10
    for a in arrays:
        assert not a.flags.writeable
        with pytest.raises(ValueError):
            a.setflags(write=True)
