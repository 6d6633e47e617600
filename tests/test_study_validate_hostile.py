# SPDX-License-Identifier: MIT
"""``trussfe study`` and ``trussfe validate`` under hostile input: every file they read must
be a regular file of an accepted size, a grid too large is refused from its counts, and every
refusal is one line naming the file.

Runs that would hang or fill the memory if a check were missing go through a subprocess with
a time limit and an address-space limit, so that a failure is a failed test, not a stuck or
exhausted machine.
"""
from __future__ import annotations

import os
import resource
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

from trussfe.budget import MAX_INPUT_BYTES
from trussfe.cli import main
from trussfe.errors import InputError
from trussfe.parametric import read_study
from trussfe.parametric.spec import MAX_RUNS
from trussfe.validation.cases import load_cases

ROOT = Path(__file__).resolve().parents[1]
MESHES = ROOT / "meshes"
ENV = {**os.environ, "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")}

#: Address space of a checked subprocess: room for Python, numpy and Dask, not for a device
#: read to its end.
LIMIT_BYTES = 3 << 30
#: Seconds a checked subprocess may take: a refusal takes about one.
LIMIT_SECONDS = 60

STATIC = """
[study]
analysis = "static"
model = "{model}"

[parameters]
{parameters}

[outputs]
N = "members.follower.axial_force"
"""

SIMULATE = """
[study]
analysis = "simulate"
model = "{model}"
options = {{ motion = "{motion}" }}

[parameters]
"masses.B" = [10.0]

[outputs]
vm = {{ path = "members.follower.max_von_mises", reduce = "max" }}
"""

DIAMETER = '"sections.tube.outer_diameter" = [0.0254, 0.03]'


def _limits() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (LIMIT_BYTES, LIMIT_BYTES))


def _trussfe(*args: str, cwd: Path) -> tuple[int, str, float]:
    """Exit status, stderr and seconds of ``python -m trussfe ARGS`` under the limits."""
    start = time.monotonic()
    try:
        p = subprocess.run([sys.executable, "-m", "trussfe", *args], cwd=cwd, env=ENV,
                           capture_output=True, text=True, timeout=LIMIT_SECONDS, check=False,
                           preexec_fn=_limits, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        pytest.fail(f"trussfe {' '.join(args)} did not end within {LIMIT_SECONDS} s")
    return p.returncode, p.stderr, time.monotonic() - start


def _assert_one_line(status: int, err: str, *fragments: str) -> None:
    assert status == 2, err
    assert err.startswith("trussfe: error: ") and err.count("\n") == 1, err
    for f in fragments:
        assert f in err, err


def _study(folder: Path, text: str, name: str = "study.toml") -> Path:
    p = folder / name
    p.write_text(text, encoding="utf-8")
    return p


def _static(folder: Path, parameters: str = DIAMETER,
            model: str | Path = MESHES / "triangular_truss_static.toml") -> Path:
    return _study(folder, STATIC.format(model=Path(model).as_posix(), parameters=parameters))


def _sparse(path: Path, size: int) -> Path:
    """A regular file of ``size`` bytes that takes no disk space."""
    with open(path, "wb") as f:
        f.truncate(size)
    return path


@pytest.fixture
def fifo(tmp_path: Path) -> Path:
    p = tmp_path / "pipe.toml"
    os.mkfifo(p)
    return p


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="needs /dev/zero")
@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom"])
def test_a_study_file_that_is_a_device_is_refused(tmp_path, device):
    """``trussfe study /dev/zero`` is one line, exit 2, before anything is read."""
    status, err, _ = _trussfe("study", device, "--out", str(tmp_path / "out"), cwd=tmp_path)
    _assert_one_line(status, err, f"{device}: is a device", "regular file")


def test_a_study_file_that_is_a_named_pipe_is_refused(tmp_path, fifo):
    """A named pipe as the study file is refused, not waited on."""
    status, err, _ = _trussfe("study", str(fifo), "--out", str(tmp_path / "out"), cwd=tmp_path)
    _assert_one_line(status, err, "is a named pipe", "the study file must be a regular file")


def test_a_study_file_larger_than_the_input_limit_is_refused(tmp_path):
    """A regular study file above the size every input file has is refused by its size."""
    big = _sparse(tmp_path / "big.toml", MAX_INPUT_BYTES + 1)
    status, err, _ = _trussfe("study", str(big), "--out", str(tmp_path / "out"), cwd=tmp_path)
    _assert_one_line(status, err, f"{big}: is 1.0 GiB", "a study file may have")


@pytest.mark.parametrize("kind", ["device", "pipe", "large"])
def test_a_model_file_of_a_study_must_be_a_regular_file_of_accepted_size(tmp_path, fifo,
                                                                          kind):
    """The study's model (``model = ...``) is refused when it is ``/dev/zero``, a named pipe
    or above the size limit, naming the study file and the model file."""
    model = {"device": Path("/dev/zero"), "pipe": fifo,
             "large": tmp_path / "huge.toml"}[kind]
    if kind == "large":
        _sparse(model, MAX_INPUT_BYTES + 1)
    if not model.exists():
        pytest.skip(f"needs {model}")
    f = _static(tmp_path, model=model)
    status, err, _ = _trussfe("study", str(f), "--out", str(tmp_path / "out"), cwd=tmp_path)
    _assert_one_line(status, err, f"trussfe: error: {f}: ", str(model))
    assert ("must be a regular file" if kind != "large" else "a model file may have") in err
    assert not (tmp_path / "out" / "parts").exists()


@pytest.mark.parametrize("kind", ["device", "pipe"])
def test_a_motion_file_of_a_study_must_be_a_regular_file(tmp_path, fifo, kind):
    """``options = { motion = ... }`` naming ``/dev/zero`` or a named pipe beside the study is
    refused before any run, naming the study file and the motion file."""
    motion = "/dev/zero" if kind == "device" else fifo.name
    if kind == "device" and not Path(motion).exists():
        pytest.skip("needs /dev/zero")
    f = _study(tmp_path, SIMULATE.format(
        model=(MESHES / "triangular_truss_motion_active.toml").as_posix(), motion=motion))
    status, err, _ = _trussfe("study", str(f), "--out", str(tmp_path / "out"), cwd=tmp_path)
    _assert_one_line(status, err, f"trussfe: error: {f}: ",
                     "the motion file must be a regular file")
    assert not (tmp_path / "out" / "parts").exists()


def test_a_motion_file_linked_beside_the_study_is_read(tmp_path):
    """A symbolic link to a regular motion file, named relative to the study file, is
    accepted and resolved to the file it points to."""
    target = MESHES / "triangular_truss_motion_3s.toml"
    (tmp_path / "linked.toml").symlink_to(target)
    f = _study(tmp_path, SIMULATE.format(
        model=(MESHES / "triangular_truss_motion_active.toml").as_posix(), motion="linked.toml"))
    study = read_study(f)
    assert study.motion_file == target.resolve()
    assert study.options["simulate"]["motion"] == str(target.resolve())


@pytest.mark.parametrize("parameters, fragment", [
    ('"sections.tube.outer_diameter" = { from = 0.024, to = 0.03, count = 1000000000000 }',
     f"outer_diameter.count: 1000000000000 values is more than the {MAX_RUNS} runs"),
    ('"sections.tube.outer_diameter" = { from = 0.024, to = 0.03, count = 100000000 }',
     f"outer_diameter.count: 100000000 values is more than the {MAX_RUNS} runs"),
    (('"sections.tube.outer_diameter" = { from = 0.024, to = 0.03, count = 5000000 }\n'
      '"materials.aluminium.E" = { from = 7.0e10, to = 7.2e10, count = 5000000 }'),
     f"study: 25000000000000 runs is more than {MAX_RUNS}"),
    ('"sections.tube.outer_diameter" = { from = 0.02, to = 0.03, step = 1e-300 }',
     "outer_diameter.step: gives more than"),
    ('"sections.tube.outer_diameter" = { from = -1.7e308, to = 1.7e308, step = 1e-300 }',
     "spans more than the range of floating-point numbers"),
])
def test_a_grid_of_too_many_runs_is_refused_from_its_counts(tmp_path, parameters, fragment):
    """The number of runs is checked from the ranges' counts and steps before any grid is
    built: one line within seconds, whatever the count."""
    f = _static(tmp_path, parameters)
    status, err, seconds = _trussfe("study", str(f), "--out", str(tmp_path / "out"),
                                    cwd=tmp_path)
    _assert_one_line(status, err, f"trussfe: error: {f}: ", fragment)
    assert seconds < 30, seconds


def test_a_parameter_named_as_an_output_is_refused_naming_the_study_file(tmp_path, capsys):
    """A parameter and an output of the same name: the line names the study file first, as
    every other study error does."""
    f = _static(tmp_path, parameters='N = { path = "materials.aluminium.E", values = [7e10] }')
    status = main(["study", str(f), "--out", str(tmp_path / "out"), "--no-progress"])
    err = capsys.readouterr().err
    _assert_one_line(status, err,
                     f"trussfe: error: {f}: parameters.N: is also the name of an output")
    with pytest.raises(InputError) as info:
        read_study(f)
    assert info.value.item == f"{f}: parameters.N"


def test_a_path_missing_from_the_model_names_the_study_file(tmp_path):
    """The errors found by building the model with the parameters name the study file, as
    docs/studies.md shows."""
    f = _static(tmp_path, parameters='"loads.X.1" = [1.0]')
    with pytest.raises(InputError, match=r"parameters\.loads\.X\.1: path 'loads\.X\.1'") as info:
        read_study(f)
    assert str(info.value).startswith(f"{f}: parameters.loads.X.1: ")


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="needs /dev/zero")
def test_a_case_file_linked_to_a_device_is_refused(tmp_path):
    """``validate --cases DIR`` with ``DIR/a.toml`` a link to ``/dev/zero``: one line, exit 2,
    nothing read."""
    cases = tmp_path / "cases"
    cases.mkdir()
    (cases / "a.toml").symlink_to("/dev/zero")
    status, err, _ = _trussfe("validate", "--cases", str(cases), "--out", str(tmp_path / "r"),
                              "--no-progress", cwd=tmp_path)
    _assert_one_line(status, err, f"{cases / 'a.toml'}: is a device",
                     "the case file must be a regular file")
    assert not (tmp_path / "r").exists()


def test_a_case_file_that_is_a_named_pipe_is_refused(tmp_path):
    """A named pipe among the case files is refused, not waited on."""
    cases = tmp_path / "cases"
    cases.mkdir()
    os.mkfifo(cases / "a.toml")
    status, err, _ = _trussfe("validate", "--cases", str(cases), "--out", str(tmp_path / "r"),
                              "--no-progress", cwd=tmp_path)
    _assert_one_line(status, err, "is a named pipe", "the case file must be a regular file")


def test_a_case_file_linked_to_a_regular_file_is_read(tmp_path):
    """A symbolic link to a regular case file is a case like any other."""
    target = tmp_path / "kept" / "case.toml"
    target.parent.mkdir()
    target.write_text('[case]\nid = "linked"\npython = "math:sqrt"\n\n[[quantities]]\n'
                      'name = "x"\npath = "x"\nreference = 1.0\nrtol = 0.1\n',
                      encoding="utf-8")
    cases = tmp_path / "cases"
    cases.mkdir()
    (cases / "linked.toml").symlink_to(target)
    [case] = load_cases(cases)
    assert case.id == "linked" and case.file == cases / "linked.toml"


@pytest.mark.parametrize("key", ["model", "picture"])
def test_a_case_model_that_is_a_named_pipe_is_named_as_such(tmp_path, key):
    """A case whose ``model`` (or ``picture``) is a named pipe is refused as one, not as a
    missing file, and is not waited on."""
    cases = tmp_path / "cases"
    cases.mkdir()
    os.mkfifo(tmp_path / "m.toml")
    head = '[case]\nid = "x"\ntitle = "x"\n'
    body = (f'analysis = "static"\nmodel = "{tmp_path / "m.toml"}"\n' if key == "model" else
            f'python = "math:sqrt"\npicture = "{tmp_path / "m.toml"}"\n')
    (cases / "x.toml").write_text(head + body + '\n[[quantities]]\nname = "x"\npath = "x"\n'
                                  'reference = 1.0\nrtol = 0.1\n', encoding="utf-8")
    if key == "picture":
        status, err, _ = _trussfe("validate", "--cases", str(cases), "--out",
                                  str(tmp_path / "r"), "--no-progress", cwd=tmp_path)
        _assert_one_line(status, err, "case.picture", "is a named pipe")
    else:
        # an analysis case's model is looked at when the case runs: the case ends in error
        from trussfe.validation.engine import run_case
        [case] = load_cases(cases)
        result = run_case(case)
        assert result.status == "error" and "case.model" in result.error
        assert "is a named pipe" in result.error and "not found" not in result.error


@pytest.fixture(scope="module")
def finished_study(tmp_path_factory) -> tuple[Path, Path]:
    """A static study of three runs, finished: (study file, results folder)."""
    folder = tmp_path_factory.mktemp("finished")
    f = _static(folder, '"sections.tube.outer_diameter" = [0.0254, 0.03, 0.035]')
    status = main(["study", str(f), "--out", str(folder / "out"), "--no-progress",
                   "--workers", "1"])
    assert status == 0
    assert len(list((folder / "out" / "parts").glob("*.parquet"))) >= 1
    return f, folder / "out"


def _resume_copy(finished_study, tmp_path: Path) -> tuple[Path, Path]:
    f, out = finished_study
    copy = tmp_path / "out"
    shutil.copytree(out, copy)
    return f, copy


def test_resuming_a_folder_whose_study_record_is_a_named_pipe_is_refused(finished_study,
                                                                         tmp_path):
    """``--resume`` reads the folder's ``study-id.json``: a named pipe in its place is named
    in one line, not waited on."""
    f, out = _resume_copy(finished_study, tmp_path)
    (out / "study-id.json").unlink()
    os.mkfifo(out / "study-id.json")
    status, err, _ = _trussfe("study", str(f), "--out", str(out), "--resume", "--no-progress",
                              cwd=tmp_path)
    _assert_one_line(status, err, f"{out / 'study-id.json'}: is a named pipe",
                     "the study record must be a regular file")


@pytest.mark.parametrize("kind", ["corrupt", "foreign", "pipe"])
def test_resuming_a_folder_with_a_part_that_is_not_the_studys_is_refused(
        finished_study, tmp_path, kind):
    """A part of the results that is not a Parquet table of the study's columns (damaged,
    another table, a named pipe) is named in one line, exit 2: never an internal error,
    never a blocked read."""
    f, out = _resume_copy(finished_study, tmp_path)
    part = out / "parts" / "extra.parquet"
    if kind == "corrupt":
        part.write_bytes(b"not a parquet table\n")
        fragment = "is not a Parquet table of the study's columns"
    elif kind == "foreign":
        import pyarrow as pa
        import pyarrow.parquet as pq
        pq.write_table(pa.table({"other": [1, 2]}), part)
        fragment = "is not a Parquet table of the study's columns"
    else:
        os.mkfifo(part)
        fragment = "is a named pipe"
    status, err, _ = _trussfe("study", str(f), "--out", str(out), "--resume", "--no-progress",
                              cwd=tmp_path)
    _assert_one_line(status, err, f"trussfe: error: {part}: {fragment}")


def test_resuming_a_finished_folder_reads_its_parts(finished_study, tmp_path):
    """The checks accept the parts a study wrote: resuming a finished study runs nothing
    and gives its three rows."""
    f, out = _resume_copy(finished_study, tmp_path)
    status, err, _ = _trussfe("study", str(f), "--out", str(out), "--resume", "--no-progress",
                              cwd=tmp_path)
    assert status == 0, err
    import pyarrow.parquet as pq
    assert pq.read_table(out / "results.parquet").num_rows == 3
