"""``trussfe postcritical`` under hostile input: a path on which every member fails, a
stiffness too small for floating-point numbers, a mesh larger than the memory."""
import json
import re

import meshio
import pytest

from trussfe._resources import mesh_path
from trussfe.cli import main
from trussfe.io.vtk import read_pvd
from trussfe.nonlinear import model as nonlinear_model

VON_MISES = mesh_path("postcritical_von_mises.toml")
TRIANGLE = mesh_path("triangular_truss_static.toml")
EULER_COLUMN = str(mesh_path("postcritical_euler_column.toml"))

#: failure tables under which both bars of the von Mises truss fail
EVERY_MEMBER_FAILS = {
    "fracture": 'fracture_strain = 1e-300\n',
    "yield": 'yield = "remove"\nyield_strength = 1e3\n',
    "buckling": 'buckling = "remove"\ncritical_load = 10.0\n',
}


def _one_error_line(err: str) -> str:
    """The single stderr line of a refused run, checked against the bad-input contract."""
    lines = err.splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("trussfe: error: ") and "internal error" not in lines[0]
    assert not re.search(r"\b(nan|inf)\b", lines[0])
    return lines[0]


@pytest.mark.parametrize("cause", sorted(EVERY_MEMBER_FAILS))
def test_every_member_failing_ends_the_path_as_a_collapse(cause, tmp_path, capsys):
    """When every member fails the path ends cleanly (exit 0): the termination says the
    structure collapsed, the failure events are listed, the last path point of the JSON and
    the last VTK frame show every member failed and carrying no force, and the plot is
    written."""
    model = tmp_path / f"{cause}.toml"
    model.write_text(VON_MISES.read_text() + "\n[failure.default]\n"
                     + EVERY_MEMBER_FAILS[cause])
    out = tmp_path / "out"
    rc = main(["postcritical", str(model), "--json", str(out / "r.json"),
               "--vtk", str(out / "vtk"), "--plot", str(out / "r.png")])
    captured = capsys.readouterr()
    assert rc == 0, captured.err
    assert captured.err == ""
    doc = json.loads((out / "r.json").read_text())
    assert doc["termination"].startswith("every member has failed at load factor")
    assert "collapsed" in doc["termination"] and doc["termination"] in captured.out
    failures = [e for e in doc["events"] if e["kind"] == cause]
    assert sorted(e["member"] for e in failures) == ["L", "R"]
    end = doc["events"][-1]
    assert end["kind"] == "end" and end["path_index"] == len(doc["path"]) - 1
    assert end["load_factor"] == failures[-1]["load_factor"]
    last = doc["path"][-1]
    assert sorted(last["failed_members"]) == ["L", "R"]
    assert last["load_factor"] == end["load_factor"]
    assert "mechanism" not in doc                     # no bars left to move
    frames = read_pvd(out / "vtk" / f"{cause}_path.pvd")
    assert len(frames) == len(doc["path"])
    final = meshio.read(frames[-1][1])
    assert final.cell_data["failed"][0].tolist() == [1, 1]
    assert final.cell_data["axial_force"][0].tolist() == [0.0, 0.0]
    assert (out / "r.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("edit, extra", [
    ((r"(?m)^E = .*$", "E = 1e-308"), []),
    ((r"(?m)^outer_diameter = .*\ninner_diameter = .*$", "area = 1e-320"), []),
    ((r"(?m)^E = .*$", "E = 1e-308"), ["--imperfection", "0.001"]),
], ids=["E-1e-308", "area-1e-320", "E-1e-308-imperfect"])
def test_stiffness_below_floating_point_is_refused_in_one_line(edit, extra, tmp_path,
                                                               capsys):
    """A stiffness so small that the first solve is not finite (E = 1e-308, an area of
    1e-320) is refused with exit 2 and one line naming the model file and saying the
    stiffness is numerically singular — with or without an imperfection from the linear
    buckling mode."""
    model = tmp_path / "soft.toml"
    text, n = re.subn(edit[0], edit[1], TRIANGLE.read_text())
    assert n == 1
    model.write_text(text)
    rc = main(["postcritical", str(model), *extra])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2
    assert line.startswith(f"trussfe: error: {model}: ")
    assert "numerically singular" in line and "mechanism" not in line



def test_a_singular_tangent_of_a_rigid_geometry_is_not_called_a_mechanism(tmp_path, capsys):
    """The von Mises truss with E = 1e-320 Pa (a subnormal number): its geometry is rigid
    (rank test: no mechanism), its tangent singular in floating point. The one line says so
    and points at the units — not "a mechanism (0 independent mechanisms)"."""
    model = tmp_path / "subnormal.toml"
    text, n = re.subn(r"(?m)^E = .*$", "E = 1e-320", VON_MISES.read_text())
    assert n == 1
    model.write_text(text)
    rc = main(["postcritical", str(model)])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2
    assert line.startswith(f"trussfe: error: {model}: ")
    assert "numerically singular" in line and "geometry is rigid" in line
    assert "mechanism" not in line


def test_subdivisions_beyond_memory_are_refused_before_allocating(monkeypatch, capsys):
    """``--subdivisions 1000000000`` is refused at once (exit 2, one line naming the option and
    the memory it would need), before any element array of the co-rotational model exists."""
    def allocates(*args, **kwargs):
        raise AssertionError("the elements were built before the memory check")

    monkeypatch.setattr(nonlinear_model.NonlinearModel, "_number_points_and_slots", allocates)
    rc = main(["postcritical", EULER_COLUMN, "--subdivisions", "1000000000"])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2
    assert line.startswith("trussfe: error: --subdivisions: ")
    assert "1,000,000,000" in line and "of memory" in line


def test_subdivisions_from_the_model_file_name_the_file(tmp_path, monkeypatch, capsys):
    """A ``[postcritical] subdivisions`` too large for the memory is refused naming the model
    file and the key, not a command-line option that was not given."""
    def allocates(*args, **kwargs):
        raise AssertionError("the elements were built before the memory check")

    monkeypatch.setattr(nonlinear_model.NonlinearModel, "_number_points_and_slots", allocates)
    model = tmp_path / "column.toml"
    text, n = re.subn(r"(?m)^subdivisions = .*$", "subdivisions = 1000000000",
                      mesh_path("postcritical_euler_column.toml").read_text())
    assert n == 1
    model.write_text(text)
    rc = main(["postcritical", str(model)])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2
    assert line.startswith(f"trussfe: error: {model}: postcritical.subdivisions: ")


def test_a_model_with_load_cases_is_told_what_the_path_follows(capsys):
    """A model with ``[load_cases]`` has no ``[loads]`` (the reader refuses both), and the
    post-critical path follows ``[loads]``: the one line says so and what to do, instead of
    only "no load pattern"."""
    model = mesh_path("loads_closed_forms.toml")
    rc = main(["postcritical", str(model)])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2
    assert line.startswith(f"trussfe: error: {model}: [loads]: no load pattern")
    assert "[load_cases]" in line and "give the case to follow as [loads]" in line
