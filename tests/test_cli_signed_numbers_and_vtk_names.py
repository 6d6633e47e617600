"""Command-line values the contract (docs/cli.md, docs/bad-input.md) promises: a negative
number in any notation is an option's value, ``static --vtk`` names are checked before the
analysis, and a notice printed on success never stands beside an error line.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

import hostile_cases as hc
from trussfe.cli import main
from trussfe.io.output import OutputTransaction

ROOT = Path(__file__).resolve().parents[1]
TRUSS = ROOT / "meshes" / "triangular_truss_static.toml"

LOAD_CASES = """\
[model]
name = "two load cases"
dimension = 2

[materials.steel]
E = 2.0e11

[sections.tube]
outer_diameter = 0.05
inner_diameter = 0.04

[nodes]
A = [0.0, 0.0]
B = [2.0, 0.0]
C = [1.0, 1.0]

[members]
AB = { nodes = ["A", "B"], section = "tube", material = "steel" }
AC = { nodes = ["A", "C"], section = "tube", material = "steel" }
BC = { nodes = ["B", "C"], section = "tube", material = "steel" }

[supports]
A = ["x", "y"]
B = ["y"]

[load_cases.down]
loads = { C = [0.0, -1000.0] }

[load_cases.side]
loads = { C = [500.0, 0.0] }
"""


def _files(folder: Path) -> list[str]:
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


def _one_error_line(err: str) -> str:
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("trussfe: error: "), err
    return lines[0]


@pytest.fixture
def mech(tmp_path):
    p = tmp_path / "mech.toml"
    p.write_text(hc.MECH)
    return p


# ------------------------------------------------------------------ negative numbers as values
@pytest.mark.parametrize("step", ["-1e-2", "-1E-2", "-.01", "-0.01"])
def test_trace_takes_a_negative_step_in_any_notation(mech, tmp_path, capsys, step):
    """``trace --step`` is a signed increment: ``-1e-2`` is the value -0.01, as ``-0.01`` is,
    not an unknown option."""
    out = tmp_path / "t.json"
    rc = main(["trace", str(mech), "--drive", "2:y", "--step", step, "--steps", "2",
               "--json", str(out)])
    assert rc == 0, capsys.readouterr().err
    assert json.loads(out.read_text())["step"] == [-0.01]


@pytest.mark.parametrize("value", ["-inf", "-nan", "-1e400"])
def test_negative_non_finite_value_is_refused_by_its_option(mech, capsys, value):
    """``-inf`` given to a number option is refused as a number that is not finite, naming
    the option, not as a missing value."""
    rc = main(["trace", str(mech), "--drive", "2:y", "--step", value, "--steps", "2"])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2 and line.startswith("trussfe: error: --step: must be a finite number")


def test_negative_tolerance_is_refused_as_negative(capsys):
    rc = main(["mechanism", str(TRUSS), "--tolerance", "-1e-3"])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2 and line == "trussfe: error: --tolerance: must be positive, got -1e-3"


# ------------------------------------------------------------------------- static --vtk names
@pytest.fixture
def no_analysis(monkeypatch):
    """Fail the test if the static analysis starts."""
    import trussfe.cli.cmd_static as cmd

    def refuse(*args, **kwargs):
        raise AssertionError("the analysis ran before the --vtk name was checked")

    monkeypatch.setattr(cmd.api, "static", refuse)


@pytest.mark.parametrize("name", ["out.txt", "out", "out.vtk"])
def test_static_vtk_name_is_checked_before_the_analysis(tmp_path, capsys, no_analysis, name):
    out = tmp_path / "out"
    rc = main(["static", str(TRUSS), "--vtk", str(out / name), "--json",
               str(out / "r.json")])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2 and line.startswith("trussfe: error: --vtk: ") and ".vtu" in line
    assert not out.exists()


@pytest.mark.parametrize("extra", [[], ["--case", "default"]])
def test_static_pvd_for_one_case_is_refused_before_the_analysis(tmp_path, capsys,
                                                                no_analysis, extra):
    rc = main(["static", str(TRUSS), "--vtk", str(tmp_path / "r.pvd"), *extra])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2 and line.startswith("trussfe: error: --vtk: ") and "one .vtu" in line
    assert _files(tmp_path) == []


def test_static_pvd_for_load_cases_writes_the_collection(tmp_path, capsys):
    model = tmp_path / "lc.toml"
    model.write_text(LOAD_CASES)
    out = tmp_path / "out"
    assert main(["static", str(model), "--vtk", str(out / "r.pvd")]) == 0
    assert _files(out) == ["r.pvd", "r_case_down.vtu", "r_case_side.vtu"]
    capsys.readouterr()


# --------------------------------------------------------------- notices and the error line
def test_postcritical_note_is_not_printed_beside_an_error(tmp_path, capsys, monkeypatch):
    """The note that member buckling is not modelled is held with the run's warnings: when the
    outputs cannot be put in place the error line stands alone."""
    def refused(self):
        raise PermissionError(13, "Permission denied", str(tmp_path / "o.json"))

    assert main(["postcritical", str(TRUSS)]) == 0
    assert "member buckling is not modelled" in capsys.readouterr().err
    monkeypatch.setattr(OutputTransaction, "commit", refused)
    rc = main(["postcritical", str(TRUSS), "--json", str(tmp_path / "o.json")])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2 and "Permission denied" in line
