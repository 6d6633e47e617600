"""``trussfe postcritical``: a number of steps whose path points cannot all be kept (every
point holds the displacements of all DOFs and the member forces) is refused in one line
naming what gave it (``--steps``, or the model file's ``postcritical.steps``) before the
analysis starts, as the other commands check their sizes."""
from __future__ import annotations

import pytest

import trussfe
from trussfe._resources import mesh_path
from trussfe.cli import main
from trussfe.errors import InputError
from trussfe.nonlinear import analysis

VON_MISES = mesh_path("postcritical_von_mises.toml")


@pytest.fixture
def no_path(monkeypatch):
    """The path must not be followed: a refusal comes before it."""
    def follow_path(*args, **kwargs):
        raise AssertionError("the path was followed before the size was checked")
    monkeypatch.setattr(analysis, "follow_path", follow_path)


def test_api_refuses_steps_whose_points_cannot_be_kept(no_path):
    with pytest.raises(InputError) as info:
        trussfe.postcritical(VON_MISES, steps=10 ** 12)
    assert info.value.item == "--steps"
    msg = str(info.value)
    assert "a path of 1,000,000,000,000 steps" in msg and "of memory" in msg
    assert "use fewer steps" in msg


def test_cli_refuses_in_one_line(capsys, no_path, tmp_path):
    out = tmp_path / "p.json"
    rc = main(["postcritical", str(VON_MISES), "--steps", "1000000000000", "--json",
               str(out)])
    err = capsys.readouterr().err
    assert rc == 2 and err.count("\n") == 1
    assert err.startswith("trussfe: error: --steps: a path of 1,000,000,000,000 steps")
    assert not out.exists()


def test_model_file_steps_name_the_file(tmp_path, no_path):
    text = VON_MISES.read_text().replace("steps = 400", "steps = 1000000000000")
    assert "steps = 1000000000000" in text
    model = tmp_path / "vm.toml"
    model.write_text(text)
    with pytest.raises(InputError) as info:
        trussfe.postcritical(model)
    assert info.value.item == f"{model}: postcritical.steps"


def test_integer_beyond_float_range_is_refused():
    with pytest.raises(InputError, match=r"a path of about 1e\+400 steps"):
        trussfe.postcritical(VON_MISES, steps=10 ** 400)


def test_reasonable_steps_still_run():
    r = trussfe.postcritical(VON_MISES, steps=5)
    assert len(r.load_factors) >= 2


def test_estimate_grows_with_dofs_and_members():
    """Per point: every DOF's displacement and every member's force."""
    from trussfe.nonlinear.model import NonlinearModel
    m = NonlinearModel(trussfe.read_model(VON_MISES))
    one = analysis.path_bytes(m, 1) / 2
    assert one >= 8 * (m.ndof + m.structure.n_members)
    assert analysis.path_bytes(m, 999) == pytest.approx(1000 * one)
