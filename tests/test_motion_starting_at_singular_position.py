"""A motion that starts exactly at a singular position (the triangular truss with its two
members in line) is refused naming step 0, the position at fault, not step 1, the first
position the solver tried to reach from it; with few steps (one by one) and with many (the
coarse continuation of long motions) alike."""
from __future__ import annotations

import pytest

from trussfe._resources import mesh_path
from trussfe.cli import main

MODEL = mesh_path("triangular_truss_motion_active.toml")


@pytest.fixture
def in_line(tmp_path):
    """The truss with B on the line O2-O1 (active 4 m = follower 2 m + span 2 m)."""
    text = MODEL.read_text()
    old = "B = [1.5625, 1.9515618744994994]"
    assert old in text
    p = tmp_path / "in_line.toml"
    p.write_text(text.replace(old, "B = [4.0, 0.0]"))
    return p


def _motion(tmp_path, steps: int):
    p = tmp_path / f"from_singular_{steps}.toml"
    p.write_text(f"""[motion]
type = "third-order"
duration = 3.0
steps = {steps}
start = {{ active = 4.0 }}
end = {{ active = 3.0 }}
""")
    return p


@pytest.mark.parametrize("steps", [50, 200])
@pytest.mark.parametrize("scheme", ["exact", "thesis"])
def test_singular_start_names_step_0(in_line, tmp_path, capsys, steps, scheme):
    rc = main(["simulate", str(in_line), "--motion", str(_motion(tmp_path, steps)),
               "--scheme", scheme])
    err = capsys.readouterr().err
    assert rc == 2 and err.count("\n") == 1, err
    # the motion's file, then the step
    assert err.startswith(f"trussfe: error: from_singular_{steps}.toml: motion: step 0 (t = 0 "
                          "s): the assembly is at a singular position"), err
    assert "'active' = 4 m" in err


def test_regular_start_still_runs(tmp_path, capsys):
    """From the model's regular position the same kind of motion runs."""
    p = tmp_path / "m.toml"
    p.write_text("""[motion]
type = "third-order"
duration = 3.0
steps = 20
start = { active = 2.5 }
end = { active = 3.0 }
""")
    assert main(["simulate", str(MODEL), "--motion", str(p)]) == 0
