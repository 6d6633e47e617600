"""A refused size is written readably: a count of hundreds of digits (``--dt 1e-300``, a
300-digit ``--subdivisions``) appears in exponent notation in the one-line error, never digit
by digit."""
from __future__ import annotations

import re

import pytest

import trussfe
from trussfe._resources import mesh_path
from trussfe.cli import main
from trussfe.errors import InputError

MODEL = str(mesh_path("triangular_truss_motion_active.toml"))
MOTION = str(mesh_path("triangular_truss_motion_3s.toml"))
HUGE = "1" + "0" * 300


def _one_line(capsys) -> str:
    err = capsys.readouterr().err
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("trussfe: error: "), err
    return lines[0]


@pytest.mark.parametrize("n, text", [
    (0, "0"), (999, "999"), (2_940_000_001, "2,940,000,001"), (2.94e300, "2.94e+300"),
    (10 ** 15, "1e+15"), (10 ** 400, "about 1e+400"),
])
def test_count_text(n, text):
    from trussfe.budget import count_text
    assert count_text(n) == text


def test_transient_tiny_time_step_count_is_short(capsys):
    rc = main(["transient", MODEL, "--motion", MOTION, "--dt", "1e-300"])
    line = _one_line(capsys)
    assert rc == 2 and line.startswith("trussfe: error: --dt: ")
    assert re.search(r"\b2\.94e\+300 time steps of 1e-300 s\b", line), line
    steps_part = line.split(" time steps")[0]
    assert len(steps_part) < 40, line


def test_elastic_huge_subdivisions_count_is_short(capsys):
    rc = main(["elastic", MODEL, "--subdivisions", HUGE])
    line = _one_line(capsys)
    assert rc == 2 and "--subdivisions" in line
    assert "the FE response of 2e+300 elements" in line, line


def test_trace_huge_steps_count_is_short():
    """An integer beyond the range of floats is refused for its memory, not as a float
    overflow, and its count is written by its power of ten."""
    with pytest.raises(InputError) as info:
        trussfe.trace(mesh_path("mech_fourbar.toml"), drive="2:y", step=0.05,
                      steps=10 ** 400)
    assert info.value.item == "--steps"
    assert "a trace of about 1e+400 states" in str(info.value)
