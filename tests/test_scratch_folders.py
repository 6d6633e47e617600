"""A validation run leaves no working folders behind; a study called directly keeps its figures.

Studies hand their figures back as file paths; the validation engine reads them back into the
report at once.  Those folders are working files of the run and must not pile up in the
system's temporary folder (one validation run used to leave a dozen behind)."""
from __future__ import annotations

import tempfile

import pytest

from trussfe.cli.cmd_validate import default_cases_dir
from trussfe.io.output import scratch_files, working_folder
from trussfe.validation import load_cases
from trussfe.validation.engine import evaluate


@pytest.fixture
def own_tempdir(tmp_path, monkeypatch):
    """The system's temporary folder, for this test only, is an empty folder of its own."""
    folder = tmp_path / "tmp"
    folder.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(folder))
    return folder


def test_working_folder_goes_with_the_scratch_block(own_tempdir):
    with scratch_files():
        inner = working_folder("trussfe-test-")
        (inner / "figure.png").write_bytes(b"png")
        assert inner.is_dir() and own_tempdir in inner.parents
    assert not inner.exists()
    assert list(own_tempdir.iterdir()) == []


def test_working_folder_outside_a_scratch_block_is_kept(own_tempdir):
    """Called directly, a study's figure is the caller's result: its folder stays."""
    folder = working_folder("trussfe-test-")
    assert folder.is_dir() and folder.parent == own_tempdir


@pytest.mark.parametrize("case_id", ["postcritical_euler_column", "modal_closed_form"])
def test_a_case_with_study_figures_leaves_no_folder(own_tempdir, case_id):
    case = next(c for c in load_cases(default_cases_dir()) if c.id == case_id)
    result, figures = evaluate(case)
    assert figures, "the case shows figures"
    assert all(png[:8] == b"\x89PNG\r\n\x1a\n" for png in figures.values())
    assert list(own_tempdir.iterdir()) == []
