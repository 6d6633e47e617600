"""``trussfe postcritical`` command: outputs, contract JSON, VTK series, plot, bad input."""
import json

import meshio
import pytest

from trussfe._resources import mesh_path
from trussfe.cli import main
from trussfe import api
from trussfe.io.vtk import read_pvd

DOME = str(mesh_path("postcritical_dome.toml"))
VON_MISES = str(mesh_path("postcritical_von_mises.toml"))


def test_dome_from_the_command_line_to_a_mechanism(tmp_path, capsys):
    """The lattice dome runs to the mechanism and its equilibrium form; the JSON follows
    docs/json.md (path with load factors and displacements; events with kinds), the .pvd has
    one .vtu per path point with failed members marked, and the plot is a PNG."""
    out = tmp_path / "out"
    rc = main(["postcritical", DOME, "--json", str(out / "d.json"), "--vtk", str(out / "vtk"),
               "--plot", str(out / "d.png")])
    assert rc == 0
    text = capsys.readouterr().out
    assert "mechanism" in text and "equilibrium form reached" in text
    doc = json.loads((out / "d.json").read_text())
    assert doc["command"] == "postcritical" and doc["units"] == "SI"
    assert {"load_factor", "displacements"} <= set(doc["path"][0])
    assert set(doc["path"][0]["displacements"]) == {"A", *[f"R{i}" for i in range(1, 7)],
                                                    *[f"S{i}" for i in range(1, 7)],
                                                    *[f"G{i}" for i in range(1, 7)]}
    kinds = [e["kind"] for e in doc["events"]]
    assert kinds.count("buckling") == 4 and "mechanism" in kinds
    for e in doc["events"]:
        if e["kind"] == "buckling":
            # every event is justified: the force at the event equals the law's limit
            assert abs(e["axial_force"] / e["law_limit"] - 1.0) < 1e-6
    mech = doc["mechanism"]
    assert mech["equilibrium_form_found"] and mech["stable"]
    assert all(mech["member_forces"][b] > 0 for b in ("A4", "A5"))
    assert mech["equilibrium_form"]["A"][2] < 0.0          # the apex hangs below the supports
    frames = read_pvd(out / "vtk" / "postcritical_dome_path.pvd")
    assert len(frames) == len(doc["path"])
    last = meshio.read(frames[-1][1])
    failed = last.cell_data["failed"][0]
    assert failed.sum() == 4
    first = meshio.read(frames[0][1])
    assert first.cell_data["failed"][0].sum() == 0
    assert (out / "d.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_analyse_von_mises_contract_and_controls():
    """trussfe.postcritical(...).to_dict() is the contract document; the three controls give
    the same limit load (closed form 381.0871904 N) — displacement control to its step
    resolution."""
    arc = api.postcritical(VON_MISES).to_dict()
    lim = [e["load_factor"] for e in arc["events"] if e["kind"] == "limit_point"]
    assert max(lim) == pytest.approx(381.0871904181, rel=1e-9)
    disp = api.postcritical(VON_MISES, control="displacement", step=0.002).to_dict()
    lim = [e["load_factor"] for e in disp["events"] if e["kind"] == "limit_point"]
    assert max(lim) == pytest.approx(381.0871904181, rel=1e-9)
    load = api.postcritical(VON_MISES, control="load", max_load_factor=500.0,
                            steps=50).to_dict()
    assert load["termination"].startswith("path cannot be continued at load factor 381.0")


@pytest.mark.parametrize("args, message", [
    (["--control", "sideways"], "invalid choice"),
    (["--steps", "0"], "--steps: must be a positive integer"),
    (["--step", "-1"], "--step: must be positive"),
    (["--monitor", "apex:q"], "NODE:AXIS"),
    (["--monitor", "nowhere:y"], "node 'nowhere' is not defined"),
])
def test_bad_options_exit_2_with_one_line(args, message, capsys):
    rc = None
    try:
        rc = main(["postcritical", VON_MISES, *args])
    except SystemExit as exc:                       # argparse choices
        rc = exc.code
    err = capsys.readouterr().err
    assert rc == 2
    assert message in err and err.count("\n") == 1 and err.startswith("trussfe: error:")


def _write(tmp_path, text):
    p = tmp_path / "m.toml"
    p.write_text(text)
    return str(p)


BASE = """
[model]
dimension = 2
[materials.m]
E = 1.0e10
yield_strength = 2.0e8
[sections.s]
area = 1.0e-4
Iy = 1.0e-8
[nodes]
a = [-1.0, 0.0]
b = [0.0, 0.1]
c = [1.0, 0.0]
[members]
L = { nodes = ["a", "b"], section = "s", material = "m" }
R = { nodes = ["b", "c"], section = "s", material = "m" }
[supports]
a = ["x", "y"]
c = ["x", "y"]
"""


@pytest.mark.parametrize("extra, message", [
    ("", "[loads]: no load pattern"),
    ('[loads]\nb = [0.0, -1.0]\n[failure.default]\nbuckling = "cap"\nresidual = 0.5\n',
     "failure.default.residual"),
    ('[loads]\nb = [0.0, -1.0]\n[failure.members.L]\nyield = "melt"\n',
     "failure.members.L.yield: unknown law"),
    ('[loads]\nb = [0.0, -1.0]\n[postcritical]\ncontrol = "fast"\n', "postcritical.control"),
    ('[loads]\nb = [0.0, -1.0]\n[postcritical]\nspeed = 1\n', "postcritical.speed"),
])
def test_bad_model_input_exit_2(tmp_path, capsys, extra, message):
    """No load pattern, inconsistent failure laws and bad settings: one line, exit 2."""
    rc = main(["postcritical", _write(tmp_path, BASE + extra)])
    err = capsys.readouterr().err
    assert rc == 2
    assert message in err and err.count("\n") == 1


def test_path_that_cannot_be_continued_says_where_and_why(tmp_path, capsys):
    """Load control past the limit load (381.087 N for EA = 1e6, a = 1, h = 0.1): the results
    up to the limit are kept, and the output says at which λ the path ends and why."""
    out = tmp_path / "r.json"
    rc = main(["postcritical", _write(tmp_path, BASE + "[loads]\nb = [0.0, -1.0]\n"),
               "--control", "load", "--step", "50", "--max-load-factor", "5000",
               "--json", str(out)])
    text = capsys.readouterr().out
    assert rc == 0
    assert "path cannot be continued at load factor 381.0" in text and "arc-length" in text
    doc = json.loads(out.read_text())
    assert doc["events"][-1]["kind"] == "end"
    assert doc["termination"].startswith("path cannot be continued at load factor 381.0")


def test_no_output_file_when_the_analysis_fails(tmp_path):
    """A failed analysis leaves no JSON behind."""
    out = tmp_path / "r.json"
    rc = main(["postcritical", _write(tmp_path, BASE), "--json", str(out)])
    assert rc == 2 and not out.exists()
