# SPDX-License-Identifier: MIT
"""``trussfe show`` and ``trussfe.show``: a picture of every shipped model, pictures of
static results, and the one-line errors of bad input.

Sources: the triangular truss of Lacy Table 3.2 (follower force -78.5429 N) and Table 3.3
(follower Euler load 1481.2 N) give the utilisation 78.5429 / 1481.2 of the follower.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest

import trussfe
from trussfe.io.model_picture import read_results, results_from_document, utilisation
from trussfe.cli import main
from trussfe.io.render_backend import plot_backend

ROOT = Path(__file__).resolve().parents[1]
#: Every shipped model (the motion files beside them hold a [motion] table instead).
MESHES = sorted(p for p in (ROOT / "meshes").glob("*.toml")
                if "motion" not in tomllib.loads(p.read_text(encoding="utf-8")))
TRIANGLE = ROOT / "meshes" / "triangular_truss_static.toml"
image = pytest.importorskip("matplotlib.image")


def _picture(path: Path) -> np.ndarray:
    """The PNG's RGB pixels (width and height from the file itself)."""
    return image.imread(str(path))[..., :3]


def _has_colour(rgb: np.ndarray, colour: tuple[float, float, float], tol: float = 0.12) -> int:
    return int((np.abs(rgb - np.asarray(colour)).max(axis=-1) < tol).sum())


@pytest.mark.parametrize("path", MESHES, ids=[p.stem for p in MESHES])
def test_every_shipped_model_is_drawn(tmp_path, path):
    """A PNG of the requested size with a drawing on it (not one flat colour)."""
    out = tmp_path / "model.png"
    pic = trussfe.show(path, out, size=(480, 360))
    rgb = _picture(out)
    assert out.stat().st_size > 1000
    assert rgb.shape == (360, 480, 3) and pic.size == (480, 360)
    assert pic.backend in ("pyvista", "matplotlib")
    assert rgb.std() > 0.02
    dark = (rgb.max(axis=-1) < 0.35).sum()          # members, nodes, ids and supports
    assert dark > 100


@pytest.mark.parametrize("backend", ["matplotlib", "pyvista"])
@pytest.mark.parametrize("model", ["triangular_truss_static", "double_octahedral_chain_10",
                                   "mech_bricard"])
def test_both_backends_draw_2d_and_3d(tmp_path, backend, model):
    if backend == "pyvista" and plot_backend() != "pyvista":
        pytest.skip("VTK cannot render off-screen on this machine")
    out = tmp_path / f"{model}.png"
    pic = trussfe.show(ROOT / "meshes" / f"{model}.toml", out, backend=backend)
    assert pic.backend == backend
    rgb = _picture(out)
    assert rgb.shape == (800, 1000, 3)
    # the members of a one-section model are drawn in the first section colour (tab:blue)
    assert _has_colour(rgb, (0.12, 0.47, 0.71)) > 200


@pytest.fixture(scope="module")
def triangle_static():
    r = trussfe.static(TRIANGLE)
    # global equilibrium of the results that are drawn: reactions balance the 98.1 N load
    assert np.allclose(r.reaction.sum(axis=0), [0.0, 98.1], atol=1e-9)
    return r


def test_utilisation_from_lacy_tables(triangle_static):
    """Follower: compression 78.5429 N (Lacy Table 3.2) over its Euler load 1481.2 N (Lacy
    Table 3.3); no yield strength is given, so buckling governs."""
    s = triangle_static.structure
    u = utilisation(s, results_from_document(triangle_static.to_dict(), s))
    i = s.member_index("follower")
    assert u[i] == pytest.approx(78.5429 / 1481.2, rel=1e-4)
    assert np.all(u >= 0)


def test_results_file_matches_api_document(tmp_path, triangle_static):
    out = tmp_path / "r.json"
    assert main(["static", str(TRIANGLE), "--json", str(out)]) == 0
    s = triangle_static.structure
    r = read_results(out, s)
    assert np.allclose(r.axial_force, triangle_static.axial_force, rtol=1e-12)
    assert np.allclose(r.displacement, triangle_static.displacement, rtol=1e-12)


@pytest.mark.parametrize("backend", ["matplotlib", "pyvista"])
def test_results_drawn_deformed_and_coloured(tmp_path, triangle_static, backend):
    """Both members are in compression: the axial-force map paints them blue (coolwarm's
    compression end), and the undeformed model is drawn in light grey beside them."""
    if backend == "pyvista" and plot_backend() != "pyvista":
        pytest.skip("VTK cannot render off-screen on this machine")
    out = tmp_path / "forces.png"
    trussfe.show(TRIANGLE, out, results=triangle_static, backend=backend)
    rgb = _picture(out)
    coolwarm_min = (0.23, 0.30, 0.75)
    assert _has_colour(rgb, coolwarm_min, tol=0.1) > 200
    assert _has_colour(rgb, (0.83, 0.83, 0.83), tol=0.05) > 50      # undeformed, lightgrey
    out2 = tmp_path / "util.png"
    trussfe.show(TRIANGLE, out2, results=triangle_static.to_dict(), color="utilisation",
                 backend=backend)
    assert _picture(out2).shape == (800, 1000, 3)


def _cli(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run([sys.executable, "-m", "trussfe", "show", *args], cwd=cwd,
                          capture_output=True, text=True, env=env, timeout=300)


def test_cli_writes_default_name_and_no_warning_lines(tmp_path, triangle_static):
    res = tmp_path / "r.json"
    res.write_text(json.dumps(triangle_static.to_dict()))
    r = _cli(str(TRIANGLE), "--results", str(res), cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    out = tmp_path / "triangular_truss_static.png"
    assert out.is_file() and "wrote triangular_truss_static.png" in r.stdout
    assert _picture(out).shape == (800, 1000, 3)
    small = tmp_path / "small.png"
    assert main(["show", str(TRIANGLE), "--png", str(small), "--size", "400x300",
                 "--no-labels"]) == 0
    assert _picture(small).shape == (300, 400, 3)


@pytest.mark.parametrize("case", ["missing model", "bad json", "other model's results",
                                  "missing results", "unwritable png", "utilisation alone",
                                  "bad size"])
def test_cli_bad_input_one_line_exit_2(tmp_path, capsys, case):
    bad = tmp_path / "bad.json"
    bad.write_text("{\"members\": ")
    other = tmp_path / "other.json"
    other.write_text(json.dumps({"command": "static", "members": {"m1": {"axial_force": 1.0}}}))
    blocker = tmp_path / "file"
    blocker.write_text("")
    args = {"missing model": ["nosuch.toml"],
            "bad json": [str(TRIANGLE), "--results", str(bad)],
            "other model's results": [str(TRIANGLE), "--results", str(other)],
            "missing results": [str(TRIANGLE), "--results", "nosuch.json"],
            "unwritable png": [str(TRIANGLE), "--png", str(blocker / "x.png")],
            "utilisation alone": [str(TRIANGLE), "--color", "utilisation"],
            "bad size": [str(TRIANGLE), "--size", "big"]}[case]
    if "--png" not in args:
        args += ["--png", str(tmp_path / "out.png")]
    assert main(["show", *args]) == 2
    err = capsys.readouterr().err
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("trussfe: error: "), err
    assert not (tmp_path / "out.png").exists()


LOAD_CASES = ROOT / "meshes" / "loads_closed_forms.toml"


def test_one_case_of_load_case_results_is_drawn(tmp_path, capsys):
    """``static --all --json`` holds every case and combination: ``--case`` picks the one
    drawn, whose forces and displacements are that case's of the document (and equal to
    ``trussfe.static(model, case=...)``), with its name in the title."""
    res = tmp_path / "all.json"
    assert main(["static", str(LOAD_CASES), "--all", "--json", str(res)]) == 0
    doc = json.loads(res.read_text())
    s = trussfe.read_model(LOAD_CASES)
    for name, part in (("tip", doc["cases"]["tip"]), ("all", doc["combinations"]["all"])):
        r = read_results(res, s, case=name)
        want = [part["members"][m]["axial_force"] for m in s.member_ids]
        assert np.allclose(r.axial_force, want, rtol=0, atol=0) and r.case == name
    one = trussfe.static(LOAD_CASES, case="tip")
    r = read_results(res, s, case="tip")
    assert np.allclose(r.axial_force, one.axial_force, rtol=1e-12, atol=1e-9)
    assert np.allclose(r.displacement, one.displacement, rtol=1e-12, atol=1e-15)
    out = tmp_path / "tip.png"
    assert main(["show", str(LOAD_CASES), "--results", str(res), "--case", "settlement",
                 "--png", str(out)]) == 0
    assert _picture(out).shape == (800, 1000, 3)
    # a single-case document names its case; another name is refused
    assert results_from_document(one.to_dict(), s).case == "tip"
    with pytest.raises(trussfe.InputError, match="not of load case 'heat'"):
        results_from_document(one.to_dict(), s, case="heat")


@pytest.mark.parametrize("args, message", [
    ([], "choose one with --case NAME (one of heat, settlement, tip, all)"),
    (["--case", "wind"], "has no load case or combination 'wind'"),
])
def test_load_case_results_need_a_known_case(tmp_path, capsys, args, message):
    res = tmp_path / "all.json"
    assert main(["static", str(LOAD_CASES), "--all", "--json", str(res)]) == 0
    capsys.readouterr()
    out = tmp_path / "out.png"
    assert main(["show", str(LOAD_CASES), "--results", str(res), "--png", str(out),
                 *args]) == 2
    lines = capsys.readouterr().err.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"trussfe: error: {res}: "), lines
    assert message in lines[0]
    assert not out.exists()
    assert main(["show", str(LOAD_CASES), "--case", "tip", "--png", str(out)]) == 2
    assert "give --results too" in capsys.readouterr().err


@pytest.mark.parametrize("backend", ["matplotlib", "pyvista"])
def test_member_loads_drawn(tmp_path, backend):
    """A uniform load along both halves of a simply supported beam is drawn as two
    dark-magenta arrows labelled with the intensity."""
    if backend == "pyvista" and plot_backend() != "pyvista":
        pytest.skip("VTK cannot render off-screen on this machine")
    model = ROOT / "validation" / "models" / "member_loads_simply_supported.toml"
    out = tmp_path / "beam.png"
    trussfe.show(model, out, backend=backend)
    rgb = _picture(out)
    assert _has_colour(rgb, (0.545, 0.0, 0.545), tol=0.15) > 100     # darkmagenta


def test_results_that_are_a_device_or_a_pipe_are_refused(tmp_path, capsys):
    """``--results /dev/zero`` filled the memory until the kernel killed the process, and a
    named pipe blocked it for ever: a results file must be a regular file, as a model,
    motion, study or case file must (one line naming it, exit 2)."""
    import os
    from trussfe.cli import main
    from trussfe._resources import mesh_path
    fifo = tmp_path / "results.fifo"
    os.mkfifo(fifo)
    for path, what in (("/dev/zero", "is a device"), (str(fifo), "is a named pipe")):
        assert main(["show", str(mesh_path("triangular_truss_static.toml")), "--results", path,
                     "--png", str(tmp_path / "p.png")]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and path in err and what in err
    assert not (tmp_path / "p.png").exists()
