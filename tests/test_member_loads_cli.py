"""``trussfe static`` with member loads: the JSON stations, the ``*_stations.vtu`` beside the
VTK file, and the refusals of what an analysis cannot apply (docs/cli.md, json.md, vtk.md).
Reference values: Roark's Formulas for Stress and Strain (7th ed.), Table 8.1 case 1d
(fixed-fixed beam, point load: moment under the load 2Pa²b²/L³)."""
import json
import shutil
from pathlib import Path

import meshio
import numpy as np
import pytest

from trussfe.cli import main

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "validation" / "models" / "member_loads_fixed_fixed_point.toml"


def test_static_json_and_station_vtu(tmp_path, capsys):
    model = tmp_path / "ff.toml"
    shutil.copy(MODEL, model)
    out, vtu = tmp_path / "r.json", tmp_path / "r.vtu"
    assert main(["static", str(model), "--subdivisions", "5", "--json", str(out),
                 "--vtk", str(vtu)]) == 0
    doc = json.loads(out.read_text())
    st = doc["members"]["AB"]["stations"]
    P, a, b, L = 2000.0, 1.2, 2.8, 4.0
    i = st["x"].index(pytest.approx(a))
    assert st["Mz"][i] == pytest.approx(2 * P * a**2 * b**2 / L**3, rel=1e-10)
    stations = tmp_path / "r_stations.vtu"
    mesh = meshio.read(stations)
    xi = mesh.point_data["xi"]
    # the loaded member is drawn through its JSON stations: the FE stations and its point load
    assert np.sort(xi) == pytest.approx(np.array(st["x"]) / L)
    got = mesh.point_data["moment_z"][np.argsort(xi)]
    assert got == pytest.approx(st["Mz"], rel=1e-10, abs=1e-9)
    capsys.readouterr()


POSTCRIT = """
member_loads = [{ member = "AB", kind = "uniform", q = [0.0, -100.0] }]
[model]
dimension = 2
[materials.st]
E = 2.0e11
[sections.b]
area = 4.0e-3
Iz = 8.0e-6
c = 0.05
[nodes]
A = [0.0, 0.0]
B = [2.0, 0.0]
[members]
AB = { nodes = ["A", "B"], section = "b", material = "st", type = "beam" }
[supports]
A = ["x", "y", "rz"]
[loads]
B = [-1000.0, 0.0, 0.0]
"""


def test_postcritical_refuses_member_loads(tmp_path, capsys):
    p = tmp_path / "m.toml"
    p.write_text(POSTCRIT)
    assert main(["postcritical", str(p), "--steps", "2"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "member_loads" in err and "co-rotational" in err


BAR3D = """
member_loads = [{ member = "AB", kind = "point", at = 0.5, F = [0.0, 0.0, -1.0], M = [5.0, 0.0, 0.0] }]
[model]
dimension = 3
[materials.st]
E = 2.0e11
[sections.b]
area = 4.0e-3
[nodes]
A = [0.0, 0.0, 0.0]
B = [2.0, 0.0, 0.0]
[members]
AB = { nodes = ["A", "B"], section = "b", material = "st" }
[supports]
A = ["x", "y", "z"]
B = ["x", "y", "z"]
"""


def test_torque_on_a_bar_is_refused(tmp_path, capsys):
    p = tmp_path / "m.toml"
    p.write_text(BAR3D)
    out = tmp_path / "r.json"
    assert main(["static", str(p), "--json", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "member_loads[0] (member AB).M" in err
    assert "torsion" in err and not out.exists()


def _toml_blocks(path: Path) -> list[str]:
    text = path.read_text(encoding="utf-8")
    return [b.split("```", 1)[0] for b in text.split("```toml\n")[1:]]


def test_model_format_member_load_examples_run(tmp_path, capsys):
    """The worked example of docs/model-format.md, *Member loads*, runs as printed, and its
    array-of-tables form reads as the same load."""
    blocks = _toml_blocks(ROOT / "docs" / "model-format.md")
    portal = next(b for b in blocks if 'name = "portal"' in b)
    p = tmp_path / "portal.toml"
    p.write_text(portal)
    out = tmp_path / "out.json"
    assert main(["static", str(p), "--json", str(out)]) == 0
    doc = json.loads(out.read_text())
    assert {"AB", "BC"} <= {m for m, v in doc["members"].items() if "stations" in v}
    # the reactions carry the whole vertical load: 800 N/m × 4 m + 300 N + 500 N/m on the
    # second half of BC (2 m)
    Rz = sum(doc["nodes"][n]["reaction"][2] for n in ("A", "D"))
    assert Rz == pytest.approx(800.0 * 4.0 + 300.0 + 500.0 * 2.0, rel=1e-10)
    # the start of the span is a station of BC
    assert 2.0 in doc["members"]["BC"]["stations"]["x"]
    table_form = next(b for b in blocks if b.startswith("[[member_loads]]"))
    from trussfe.io import toml_text
    assert toml_text.loads(table_form)["member_loads"][0] == toml_text.loads(
        portal)["member_loads"][1]
    capsys.readouterr()


@pytest.mark.parametrize("command", ["simulate", "elastic", "transient", "actuators"])
def test_motion_analyses_refuse_unapplied(command):
    """An analysis along a motion applies nodal loads only: a model with member loads is
    refused in one line, never run without them."""
    import trussfe
    from trussfe.errors import InputError
    from trussfe.model import MemberLoad
    from trussfe.models import triangular_truss
    s = triangular_truss().with_extensions(member_loads=[MemberLoad.uniform(0, (0.0, -1.0))])
    with pytest.raises(InputError, match=f"not by {command}"):
        getattr(trussfe, command)(s, motion="nope.toml")
