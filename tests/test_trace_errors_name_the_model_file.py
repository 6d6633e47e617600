"""``trussfe trace``: an error about the model's motion (a rigid assembly, a step that cannot
be closed, a branch or drive count the state does not have) names the model file first, in
one line, as the other commands' errors do; errors about an option alone name the option."""
from __future__ import annotations

import shutil

import pytest

import trussfe
from trussfe._resources import mesh_path
from trussfe.cli import main
from trussfe.errors import TrussfeError


@pytest.fixture
def models(tmp_path):
    """Copies of the shipped mechanism models under names of their own."""
    def copy(name):
        dst = tmp_path / f"my_{name}"
        shutil.copy(mesh_path(name), dst)
        return dst
    return copy


def _one_line(capsys) -> str:
    err = capsys.readouterr().err
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("trussfe: error: "), err
    assert "Traceback" not in err and "warning" not in err.lower()
    return lines[0]


@pytest.mark.parametrize("name, args, item, text", [
    ("mech_octahedron_rigid.toml", ["--drive", "3:x", "--step", "0.02", "--steps", "2"],
     "trace", "the assembly is rigid"),
    ("mech_sec8_compound.toml", ["--drive", "5:y", "--step", "0.5", "--steps", "5"],
     "trace: step 5", "leaves the motion region"),
    ("mech_sec8_compound.toml", ["--drive", "5:y", "--step", "-0.02", "--steps", "3",
                                 "--branch", "7"],
     "--branch", "has 2 branches"),
    ("mech_fourbar.toml", ["--drive", "2:y", "--drive", "3:y", "--step", "0.05", "--steps",
                           "3"],
     "--drive", "2 drives were given"),
], ids=["rigid", "step", "branch", "drives"])
def test_cli_error_names_the_model_file(models, capsys, name, args, item, text):
    path = models(name)
    rc = main(["trace", str(path)] + args)
    line = _one_line(capsys)
    assert rc == 2
    assert line.startswith(f"trussfe: error: {path}: {item}: "), line
    assert text in line


def test_api_error_item_starts_with_the_model_file(models):
    path = models("mech_octahedron_rigid.toml")
    with pytest.raises(TrussfeError) as info:
        trussfe.trace(path, drive="3:x", step=0.02, steps=2)
    assert info.value.item == f"{path}: trace"


def test_option_errors_keep_naming_the_option(models, capsys):
    """A drive that the option itself gets wrong (an axis the model does not have) is the
    option's error, as ``--case`` and ``--mass-from`` are elsewhere."""
    rc = main(["trace", str(models("mech_fourbar.toml")), "--drive", "2:z", "--step", "0.1",
               "--steps", "3"])
    assert rc == 2 and _one_line(capsys).startswith("trussfe: error: --drive: axis 'z'")


def test_model_built_in_code_is_named_by_nothing_more():
    """A model without a file: the item is the trace's own."""
    s = trussfe.read_model(mesh_path("mech_octahedron_rigid.toml")).variant(source="")
    with pytest.raises(TrussfeError) as info:
        trussfe.trace(s, drive="3:x", step=0.02, steps=2)
    assert info.value.item == "trace"
