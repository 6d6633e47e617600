"""The command-line contract under failure: outputs as one transaction, concurrent writers,
memory bounds, special files, numerical overflow, messages, progress and Ctrl-C.

Most tests run ``trussfe.cli.main`` in-process; a real signal, a terminal and concurrent
processes need subprocesses (kept few: each costs an interpreter start).
"""
from __future__ import annotations

import errno
import fcntl
import json
import os
import pty
import select
import signal
import subprocess
import struct
import sys
import termios
import time
from pathlib import Path

import numpy as np
import pytest

import hostile_cases as hc
from trussfe.cli import main
from trussfe.io import output as output_mod
from trussfe.io.output import atomic_path, output_transaction, write_json

ROOT = Path(__file__).resolve().parents[1]
ENV = {**os.environ, "PYTHONPATH": str(ROOT)}


def _files(folder: Path) -> list[str]:
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


def _one_error_line(err: str) -> str:
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("trussfe: error: "), err
    return lines[0]


@pytest.fixture
def model(tmp_path):
    p = tmp_path / "m.toml"
    p.write_text(hc.GOOD)
    return p


# ----------------------------------------------------------------------------- transactions
def _disk_full(*args, **kwargs):
    raise OSError(errno.ENOSPC, "No space left on device")


def _fails_while_writing(path, *args):
    """A writer that fails half-way through its file (a full disk)."""
    with atomic_path(path) as tmp:
        tmp.write_text("half")
        _disk_full()


def test_failed_vtu_leaves_no_json(model, tmp_path, capsys, monkeypatch):
    """``--json`` is not kept when the ``--vtk`` written after it fails (one transaction)."""
    import trussfe.cli.cmd_static as cmd

    out = tmp_path / "out"
    monkeypatch.setattr(cmd, "write_json", _fails_while_writing)
    rc = main(["static", str(model), "--vtk", str(out / "r.vtu"), "--json",
               str(out / "r.json")])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2 and "No space left" in line
    assert not out.exists() or _files(out) == []      # neither file, no temporaries


def test_failed_plot_leaves_no_json(tmp_path, capsys, monkeypatch):
    """trace: a failing ``--plot`` (written before ``--json``) removes the ``--vtk`` folder's
    files too; the output folder made for them is removed again."""
    import trussfe.cli.cmd_trace as cmd

    mech = tmp_path / "mech.toml"
    mech.write_text(hc.MECH)
    out = tmp_path / "new" / "deeper"
    monkeypatch.setattr(cmd, "_plot", _fails_while_writing)
    rc = main(["trace", str(mech), "--drive", "2:y", "--step", "0.05", "--steps", "3",
               "--json", str(out / "t.json"), "--vtk", str(out / "vtk"),
               "--plot", str(out / "t.png")])
    _one_error_line(capsys.readouterr().err)
    assert rc == 2
    assert _files(tmp_path) == ["mech.toml"]


def test_interrupt_in_analysis_leaves_nothing(tmp_path, capsys, monkeypatch):
    """Ctrl-C during a trace: exit 130, one line, no partial output."""
    import trussfe.cli.cmd_trace as cmd
    import contextlib

    mech = tmp_path / "mech.toml"
    mech.write_text(hc.MECH)

    @contextlib.contextmanager
    def bar(steps):
        def tick(k, total):
            if k == 3:
                raise KeyboardInterrupt
        yield tick

    monkeypatch.setattr(cmd, "_progress_bar", bar)
    rc = main(["trace", str(mech), "--drive", "2:y", "--step", "0.01", "--steps", "50",
               "--json", str(tmp_path / "t.json"), "--vtk", str(tmp_path / "v")])
    err = capsys.readouterr().err
    assert rc == 130 and "interrupted" in _one_error_line(err)
    assert _files(tmp_path) == ["mech.toml"]


def test_transaction_commits_all_or_nothing(tmp_path):
    """Library level: renames wait for the end of the block; an exception removes all."""
    with pytest.raises(RuntimeError):
        with output_transaction():
            write_json(tmp_path / "a.json", {"x": 1})
            with atomic_path(tmp_path / "sub" / "b.txt") as tmp:
                tmp.write_text("b")
            assert not (tmp_path / "a.json").exists()    # not yet renamed
            raise RuntimeError("later failure")
    assert _files(tmp_path) == []
    with output_transaction():
        write_json(tmp_path / "a.json", {"x": 1})
        with output_mod.atomic_dir(tmp_path / "d") as d:
            (d / "f.txt").write_text("f")
    assert _files(tmp_path) == ["a.json", "d", "d/f.txt"]


def test_concurrent_writers_leave_one_complete_result(tmp_path):
    """Two ``static`` runs with different loads write the same --json and --vtk at once,
    twice over: the pair left is always from one run (the displacement in the JSON equals
    the one in the VTU), never a mix and never a temporary."""
    import meshio

    models = []
    for k, load in enumerate(("-1000.0", "-3000.0")):
        p = tmp_path / f"m{k}.toml"
        p.write_text(hc.GOOD.replace("-1000.0", load))
        models.append(p)
    out = tmp_path / "out"
    for _ in range(2):
        procs = [subprocess.Popen([sys.executable, "-m", "trussfe", "static", str(m),
                                   "--json", str(out / "r.json"), "--vtk", str(out / "r.vtu")],
                                  env=ENV, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
                 for m in models]
        for p in procs:
            assert p.wait(timeout=300) == 0, p.stderr.read()
        doc = json.loads((out / "r.json").read_text())
        uy_json = doc["nodes"]["B"]["displacement"][1]
        uy_vtu = meshio.read(out / "r.vtu").point_data["displacement"][1, 1]
        assert uy_json == pytest.approx(uy_vtu, rel=1e-12)
        assert _files(out) == ["r.json", "r.vtu"]


# ----------------------------------------------------------------------------- special files
def test_named_pipe_model_is_refused_without_blocking(tmp_path):
    """A FIFO as model file is refused at once (reading it would block forever)."""
    fifo = tmp_path / "m.toml"
    os.mkfifo(fifo)
    r = subprocess.run([sys.executable, "-m", "trussfe", "static", str(fifo)], env=ENV,
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2
    assert "named pipe" in _one_error_line(r.stderr)


# ----------------------------------------------------------------------------- numerics
@pytest.mark.parametrize("command", ["static", "buckling"])
@pytest.mark.parametrize("edit", [("B = [0.0, -1000.0]", "B = [0.0, -1e308]"),
                                  ("E = 71.0e9", "E = 1e-300")])
def test_overflow_is_refused_naming_units(command, edit, tmp_path, capsys):
    """A load of 1e308 N or E = 1e-300 Pa overflows: refused (exit 2) with the units hint,
    no warning line, no 'inf' printed and no JSON with nulls."""
    p = tmp_path / "m.toml"
    p.write_text(hc.GOOD.replace(*edit))
    rc = main([command, str(p), "--json", str(tmp_path / "r.json")])
    out, err = capsys.readouterr()
    line = _one_error_line(err)
    assert rc == 2 and "units" in line, line
    assert "inf" not in out and not (tmp_path / "r.json").exists()


def test_static_result_is_finite_and_in_equilibrium(model, tmp_path, capsys):
    """The good model through the same checked path: finite numbers, global equilibrium
    (sum of reactions + loads = 0), the load 1000 N carried by two bars at 45 degrees:
    N = -1000 / (2 sin 45°) = -707.1 N (statics of the symmetric two-bar truss)."""
    rc = main(["static", str(model), "--json", str(tmp_path / "r.json")])
    assert rc == 0 and capsys.readouterr().err == ""
    doc = json.loads((tmp_path / "r.json").read_text())
    R = np.array([doc["nodes"][n]["reaction"][:2] for n in ("A", "C")]).sum(axis=0)
    assert R + np.array([0.0, -1000.0]) == pytest.approx([0.0, 0.0], abs=1e-8)
    for mid in ("AB", "BC"):
        assert doc["members"][mid]["axial_force"] == pytest.approx(-1000 / np.sqrt(2), 1e-9)


# ----------------------------------------------------------------------------- messages
def test_suggestions_are_capped(tmp_path, capsys):
    """A bad reference in a model of 20,000 nodes names the nearest few and a count, not
    every id."""
    n = 20_000
    nodes = "\n".join(f"N{i} = [{i}.0, 0.0]" for i in range(n))
    members = "\n".join(f'M{i} = {{ nodes = ["N{i}", "N{i + 1}"], section = "tube", '
                        f'material = "al" }}' for i in range(n - 1))
    text = (hc.GOOD.split("[nodes]")[0] + "[nodes]\n" + nodes + "\n\n[members]\n" + members
            + '\n\n[supports]\nN0 = ["x", "y"]\n\n[loads]\nsupport_left = [0.0, 1.0]\n')
    p = tmp_path / "big.toml"
    p.write_text(text)
    assert main(["static", str(p)]) == 2
    line = _one_error_line(capsys.readouterr().err)
    assert "support_left" in line and "20,000 defined" in line and len(line) < 400, line


def test_node_id_with_newline_stays_on_one_line(tmp_path, capsys):
    p = tmp_path / "m.toml"
    p.write_text(hc.GOOD.replace('nodes = ["B", "C"]', 'nodes = ["B", "C\\nD"]'))
    assert main(["static", str(p)]) == 2
    line = _one_error_line(capsys.readouterr().err)
    assert "'C\\nD'" in line


def test_coincident_nodes_warned_in_one_line(tmp_path, capsys):
    """Two unjoined nodes at one place: one warning line naming both, the run goes on (here
    it then stops as a mechanism: the extra node is free)."""
    p = tmp_path / "m.toml"
    p.write_text(hc.GOOD.replace("C = [1.0, 0.0]\n", "C = [1.0, 0.0]\nD = [1.0, 0.0]\n")
                 .replace('C = ["x", "y"]', 'C = ["x", "y"]\nD = ["x", "y"]'))
    assert main(["static", str(p)]) == 0
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and err[0].startswith("trussfe: warning: "), err
    assert "'C' and 'D' coincide" in err[0]
    q = tmp_path / "ok.toml"
    q.write_text(hc.GOOD)
    assert main(["static", str(q)]) == 0
    assert capsys.readouterr().err == ""


def test_a_failed_run_says_only_its_error(tmp_path, capsys):
    """Coincident unjoined nodes make a mechanism: the run fails, and its stderr is the one
    error line (the warning met on the way is shown with --verbose, before it); a modal run
    of a mechanism succeeds with its zero-frequency count in its table and nothing on
    stderr."""
    p = tmp_path / "m.toml"
    p.write_text(hc.GOOD.replace("C = [1.0, 0.0]\n", "C = [1.0, 0.0]\nD = [1.0, 0.0]\n"))
    assert main(["static", str(p)]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and err[0].startswith("trussfe: error: ") and "mechanism" in err[0]
    assert main(["-v", "static", str(p)]) == 2
    err = capsys.readouterr().err
    assert "'C' and 'D' coincide" in err and err.splitlines()[-1].startswith("trussfe: error")
    mech = Path(__file__).resolve().parents[1] / "meshes" / "mech_fourbar.toml"
    assert main(["modes", str(mech)]) == 0
    out, err = capsys.readouterr()
    assert "zero-frequency mode(s)" in out and err == ""


# ----------------------------------------------------------------------------- progress
def test_trace_progress_only_on_a_terminal(tmp_path, capsys, monkeypatch):
    import trussfe.cli.cmd_trace as cmd

    mech = tmp_path / "mech.toml"
    mech.write_text(hc.MECH)
    monkeypatch.setattr(cmd, "PROGRESS_STEPS", 2)
    argv = ["trace", str(mech), "--drive", "2:y", "--step", "0.01", "--steps", "5"]
    assert main(argv) == 0
    assert capsys.readouterr().err == ""                 # not a terminal: no bar
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True, raising=False)
    assert main(argv) == 0
    assert "trace" in capsys.readouterr().err            # a terminal: the tqdm bar


def test_ctrl_c_on_a_terminal_stops_a_long_trace(tmp_path):
    """A real SIGINT to a trace of 10^5 steps showing its bar on a terminal: exit 130, the
    last line says it was interrupted, no output file."""
    mech = tmp_path / "mech.toml"
    mech.write_text(hc.MECH)
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 80, 0, 0))
    proc = subprocess.Popen([sys.executable, "-m", "trussfe", "trace", str(mech), "--drive",
                             "2:y", "--step", "1e-7", "--steps", "100000", "--json",
                             str(tmp_path / "t.json")], env=ENV, stdout=subprocess.DEVNULL,
                            stderr=slave, cwd=tmp_path)
    os.close(slave)
    seen = b""
    deadline = time.monotonic() + 240
    while b"step" not in seen and time.monotonic() < deadline and proc.poll() is None:
        if select.select([master], [], [], 1.0)[0]:
            try:
                seen += os.read(master, 4096)
            except OSError:
                break
    assert b"step" in seen, seen                         # the bar is drawing
    proc.send_signal(signal.SIGINT)
    rc = proc.wait(timeout=120)
    while True:
        try:
            if not select.select([master], [], [], 0.5)[0]:
                break
            chunk = os.read(master, 4096)
        except OSError:
            break
        if not chunk:
            break
        seen += chunk
    os.close(master)
    assert rc == 130, seen.decode(errors="replace")[-2000:]
    text = seen.decode(errors="replace")
    assert "Traceback" not in text
    assert text.rstrip().splitlines()[-1].endswith("trussfe: error: interrupted; no output "
                                                   "written")
    assert _files(tmp_path) == ["mech.toml"]


# ----------------------------------------------------------------------------- validate
def test_three_parallel_validate_runs_give_identical_reports(tmp_path):
    """Three ``trussfe validate`` processes at once into different folders: byte-identical
    report.md and report.html (run times go to timings.txt only)."""
    cases = ["--case", "rigid_triangle_static"]
    procs = [subprocess.Popen([sys.executable, "-m", "trussfe", "validate", *cases, "--out",
                               str(tmp_path / f"r{k}"), "--no-progress"], env=ENV,
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
             for k in range(3)]
    for p in procs:
        assert p.wait(timeout=600) == 0, p.stderr.read()
    for name in ("report.md", "report.html"):
        texts = {(tmp_path / f"r{k}" / name).read_bytes() for k in range(3)}
        assert len(texts) == 1, name
    assert (tmp_path / "r0" / "timings.txt").read_text().count("\n") == 3


def test_non_finite_result_is_refused_naming_the_quantity(model, tmp_path, capsys,
                                                          monkeypatch):
    """An infinite number reaching a JSON result (a Python float overflow numpy cannot see)
    is refused naming the quantity and the units; nothing is written."""
    import trussfe.cli.cmd_static as cmd

    real = cmd.write_json

    def overflowing(path, doc):
        doc["members"]["AB"]["axial_force"] = 1e308 * 10.0
        real(path, doc)

    monkeypatch.setattr(cmd, "write_json", overflowing)
    rc = main(["static", str(model), "--json", str(tmp_path / "r.json")])
    line = _one_error_line(capsys.readouterr().err)
    assert rc == 2 and "members.AB.axial_force" in line and "units" in line
    assert not (tmp_path / "r.json").exists()
