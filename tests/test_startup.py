"""Start-up of the command line: a command imports only what it runs.

The start-up time itself is measured in benchmarks/bench_startup.py (a table, not a timed
test); here the modules behind it are checked, in a fresh interpreter."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "meshes" / "triangular_truss_static.toml"

PROBE = """
import json, sys
from trussfe.cli import main
code = main(sys.argv[1:])
print(json.dumps({"code": code, "modules": sorted(sys.modules)}))
"""


def _loaded(*argv: str) -> tuple[int, set[str]]:
    out = subprocess.run([sys.executable, "-c", PROBE, *argv], capture_output=True, text=True,
                         cwd=ROOT, check=True).stdout.strip().splitlines()[-1]
    doc = json.loads(out)
    return doc["code"], set(doc["modules"])


#: Libraries and solver families that a linear static run of a truss does not need.
NOT_FOR_STATIC = ("meshio", "matplotlib", "pyvista", "tqdm", "trussfe.nonlinear",
                  "trussfe.rigid", "trussfe.kinematics", "trussfe.response",
                  "trussfe.validation", "trussfe.studies")


def test_static_loads_only_the_linear_solver(tmp_path):
    code, mods = _loaded("static", str(MODEL), "--json", str(tmp_path / "r.json"))
    assert code == 0
    assert "trussfe.fem.static" in mods
    for name in NOT_FOR_STATIC:
        assert not any(m == name or m.startswith(name + ".") for m in mods), name


def test_static_vtk_loads_meshio_when_asked(tmp_path):
    code, mods = _loaded("static", str(MODEL), "--vtk", str(tmp_path / "r.vtu"))
    assert code == 0 and "meshio" in mods and (tmp_path / "r.vtu").stat().st_size > 0


@pytest.mark.parametrize("argv", [["--version"], ["-v", "--version"]])
def test_version_loads_no_command(argv):
    code, mods = _loaded(*argv)
    assert code == 0
    assert not any(m.startswith(("trussfe.fem", "trussfe.cli.cmd_")) for m in mods)


def test_every_command_still_listed():
    """Commands not chosen are bare names; a misspelt one is refused naming all of them."""
    r = subprocess.run([sys.executable, "-m", "trussfe", "statc", str(MODEL)],
                       capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 2
    for name in ("static", "modes", "buckling", "simulate", "validate", "trace"):
        assert f"'{name}'" in r.stderr
