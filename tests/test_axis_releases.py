"""Per-axis end releases (``my``, ``mz``, ``t``) against hand calculations.

Two collinear beams A–B–C along X, fixed at A and C, loaded at B (L = 2 m each).  Member
axes: local y = global Z, local z = −Y (mechanics.geometry.local_axes), so a force along Z
bends the beams about local z (``Iz``), a force along Y about local y (``Iy``).  Hand
calculations (slope-deflection, Timoshenko & Gere): with B's rotation free, a transverse
force P at B of two equal rigid beams gives δ = PL³/(24EI) (each one fixed-guided,
12EI/L³); releasing the bending moment of AB at B about the axis of that bending makes AB
fixed-pinned (3EI/L³) and BC fixed at C with B free to rotate (3EI/L³): δ = PL³/(6EI).
A torque T at B splits between AB and BC in proportion to GJ/L (half each here); releasing
AB's torsion at B sends all of it to C, and B twists by TL/(GJ).  Static results are in
global equilibrium (tests/conftest.py).
"""
import numpy as np
import pytest

from trussfe.errors import InputError
from trussfe.fem.static import solve_static
from trussfe.io import toml_text
from trussfe.io.model_file import parse_model

E, G, Iy, Iz, J, L = 2.0e11, 8.0e10, 8.0e-6, 5.0e-6, 1.0e-5, 2.0

TEXT = f"""
[model]
dimension = 3
[materials.st]
E = {E}
G = {G}
[sections.b]
area = 4.0e-3
Iy = {Iy}
Iz = {Iz}
J = {J}
c = 0.05
[nodes]
A = [0.0, 0.0, 0.0]
B = [{L}, 0.0, 0.0]
C = [{2 * L}, 0.0, 0.0]
[members]
AB = {{ nodes = ["A", "B"], section = "b", material = "st", type = "beam", RELEASES }}
BC = {{ nodes = ["B", "C"], section = "b", material = "st", type = "beam" }}
[supports]
A = ["x", "y", "z", "rx", "ry", "rz"]
C = ["x", "y", "z", "rx", "ry", "rz"]
[loads]
B = LOAD
"""


def model(releases: str, load):
    text = TEXT.replace("RELEASES", releases or 'releases = []').replace(
        "LOAD", str([float(v) for v in load]))
    return parse_model(toml_text.loads(text), source="axis.toml")


P, T = -1000.0, 300.0


@pytest.mark.parametrize("k", [1, 4])
def test_mz_released_alone(k):
    # bending about local z released at AB's end B: a force along Z (local y) sees two
    # propped members; a force along Y (bending about local y) two rigid ones
    s = model('releases = { end = ["mz"] }', [0, P, P, 0, 0, 0])
    r = solve_static(s, subdivisions=k)
    assert r.displacements[1, 2] == pytest.approx(P * L**3 / (6 * E * Iz), rel=1e-10)
    assert r.displacements[1, 1] == pytest.approx(P * L**3 / (24 * E * Iy), rel=1e-10)
    assert r.end_forces[0, 1, 5] == pytest.approx(0.0, abs=1e-9)          # Mz at B: none
    assert abs(r.end_forces[0, 1, 4]) == pytest.approx(abs(P) * L / 4, rel=1e-10)


@pytest.mark.parametrize("k", [1, 4])
def test_my_released_alone(k):
    s = model('releases = { end = ["my"] }', [0, P, P, 0, 0, 0])
    r = solve_static(s, subdivisions=k)
    assert r.displacements[1, 1] == pytest.approx(P * L**3 / (6 * E * Iy), rel=1e-10)
    assert r.displacements[1, 2] == pytest.approx(P * L**3 / (24 * E * Iz), rel=1e-10)
    assert r.end_forces[0, 1, 4] == pytest.approx(0.0, abs=1e-9)
    assert abs(r.end_forces[0, 1, 5]) == pytest.approx(abs(P) * L / 4, rel=1e-10)


@pytest.mark.parametrize("name", ["t", "torsion"])
def test_torsion_released_alone(name):
    base = solve_static(model("", [0, 0, 0, T, 0, 0]))
    assert base.reactions[[0, 2], 3] == pytest.approx([-T / 2, -T / 2], rel=1e-10)
    r = solve_static(model(f'releases = {{ end = ["{name}"] }}', [0, 0, 0, T, 0, 0]))
    assert r.reactions[[0, 2], 3] == pytest.approx([0.0, -T], abs=1e-9)
    assert r.displacements[1, 3] == pytest.approx(T * L / (G * J), rel=1e-10)
    # bending is untouched by a torsion release: a transverse force as without releases
    r = solve_static(model(f'releases = {{ end = ["{name}"] }}', [0, 0, P, 0, 0, 0]))
    assert r.displacements[1, 2] == pytest.approx(P * L**3 / (24 * E * Iz), rel=1e-10)


def test_both_axes_are_the_old_bending_release():
    load = [0, P, P, T / 10, 0, 0]
    old = solve_static(model('releases = ["end"]', load))
    new = solve_static(model('releases = { end = ["my", "mz"] }', load))
    assert new.displacements == pytest.approx(old.displacements, rel=1e-12, abs=1e-15)
    s = model('releases = { end = ["my", "mz"] }', load)
    assert s.releases[0].tolist() == [False, True]
    assert not s.bending_axis_releases.any()


@pytest.mark.parametrize("rel, why", [
    ('releases = { end = ["mx"] }', "unknown release 'mx'"),
    ('releases = { start = ["my", "bend"] }', "unknown release 'bend'"),
])
def test_unknown_release_name(rel, why):
    with pytest.raises(InputError, match=why) as e:
        model(rel, [0, P, 0, 0, 0, 0])
    assert "releases" in e.value.item


def test_my_in_2d_is_refused():
    text = """
[model]
dimension = 2
[materials.m]
E = 1e10
[sections.s]
area = 1e-4
Iz = 1e-8
[nodes]
A = [0.0, 0.0]
B = [1.0, 0.0]
[members]
AB = { nodes = ["A", "B"], section = "s", material = "m", type = "beam", releases = { end = ["my"] } }
[supports]
A = ["x", "y", "rz"]
"""
    with pytest.raises(InputError, match="2-D"):
        parse_model(toml_text.loads(text), source="p.toml")
    ok = parse_model(toml_text.loads(text.replace('["my"]', '["mz"]')), source="p.toml")
    assert ok.releases[0].tolist() == [False, True]


def test_axis_releases_are_written_back(tmp_path):
    from trussfe.io.model_writer import write_model
    s = model('releases = { end = ["mz", "t"], start = ["my"] }', [0, P, 0, 0, 0, 0])
    p = tmp_path / "m.toml"
    write_model(s, p)
    s2 = parse_model(toml_text.loads(p.read_text()), source=str(p))
    assert s2.bending_axis_releases.tolist() == s.bending_axis_releases.tolist()
    assert s2.torsion_releases.tolist() == s.torsion_releases.tolist()
    assert np.array_equal(s2.releases, s.releases)


SPIN = """
member_loads = [
  { member = "AB", kind = "point", at = 0.5, F = [0.0, 0.0, 0.0], M = [100.0, 0.0, 0.0], axes = "local" },
]
[model]
dimension = 3
[materials.st]
E = 2.1e11
G = 8.1e10
[sections.b]
area = 4.0e-3
Iy = 8.0e-6
Iz = 5.0e-6
J = 1.0e-5
c = 0.05
[nodes]
A = [0.0, 0.0, 0.0]
B = [4.0, 0.0, 0.0]
[members]
AB = { nodes = ["A", "B"], section = "b", material = "st", type = "beam", RELEASES }
[supports]
A = SUPPORT
B = SUPPORT
"""


@pytest.mark.parametrize("releases, support", [
    ('releases = ["start", "end"]', '["x", "y", "z"]'),          # joints free to turn
    ('releases = { start = ["all"], end = ["all"] }', '["x", "y", "z"]'),
    ('releases = { start = ["t"], end = ["t"] }', '["x", "y", "z", "rx", "ry", "rz"]'),
])
def test_a_couple_on_a_member_free_to_spin_is_refused(releases, support):
    """A couple about the axis of a beam that nothing holds in torsion at either end has no
    equilibrium (statics: the couple's moment about the axis has no reaction to balance it);
    it was taken by the hold that keeps such a member's stiffness regular — lost, or sent
    into a joint through a released end — and reported as a solution out of equilibrium by
    the couple.  It is refused, naming the member."""
    text = SPIN.replace("RELEASES", releases).replace("SUPPORT", support)
    s = parse_model(toml_text.loads(text), source="spin.toml")
    with pytest.raises(InputError, match="free to twist at both ends") as e:
        solve_static(s, "truss")
    assert "spin.toml" in str(e.value) and "member AB" in str(e.value)
    # torsion kept at one end into a joint that holds it: the couple goes there, balanced
    held = text.replace(releases, 'releases = { end = ["t"] }').replace(
        '["x", "y", "z"]', '["x", "y", "z", "rx", "ry", "rz"]')
    r = solve_static(parse_model(toml_text.loads(held), source="spin.toml"), "truss")
    assert r.reactions[:, 3] == pytest.approx([-100.0, 0.0], abs=1e-9)
