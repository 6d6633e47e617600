# SPDX-License-Identifier: MIT
"""``trussfe study`` and :func:`trussfe.study`: study files, runs on Dask, resume, a killed
worker, an external scheduler, the shipped studies (at small size)."""
from __future__ import annotations

import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
import tomllib
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("dask.distributed")
pd = pytest.importorskip("pandas")
pytest.importorskip("pyarrow")

import trussfe  # noqa: E402
from trussfe.cli import main  # noqa: E402
from trussfe.parametric import read_study  # noqa: E402
from trussfe.parametric.design import design, run_rng  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
MESHES = ROOT / "meshes"
EXAMPLES = ROOT / "examples"
ENV = {**os.environ, "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")}

#: Lacy (1991) Table 3.2: the follower's axial force under 98.1 N at B (statically
#: determinate, so independent of E and of the tube).
TABLE_3_2_FOLLOWER = -78.5429

TRIANGLE = f"""
[study]
name = "triangle sizing"
analysis = "static"
model = "{MESHES / 'triangular_truss_static.toml'}"
options = {{ bar_model = "truss" }}
samples = 3
seed = 7

[parameters]
"sections.tube.outer_diameter" = [0.0254, 0.03]
"loads.B.1" = [-98.1, -196.2]
"materials.aluminium.E" = {{ distribution = "normal", mean = 71.0e9, std = 2.0e9 }}

[outputs]
N_follower = "members.follower.axial_force"
uy_B = "nodes.B.displacement.1"
max_vm = {{ path = "members.*.max_von_mises", reduce = "max" }}
"""

#: 90 third-order slews of the double-octahedral bay, 150 steps each (~0.05 s on a free core):
#: a study long enough to be interrupted mid-way.
SLEW = f"""
[study]
name = "slew"
analysis = "simulate"
model = "{MESHES / 'double_octahedron_actuators.toml'}"
options = {{ motion = "{MESHES / 'double_octahedron_motion_slew.toml'}", steps = 150 }}

[parameters]
duration = {{ path = "motion.duration", from = 1.0, to = 6.0, count = 30 }}
payload = {{ paths = ["masses.N7", "masses.N8", "masses.N9"], values = [0.0, 10.0, 20.0], factor = 0.3333333333333333 }}

[outputs]
peak_voltage = {{ path = "actuators.*.max_motor_voltage", reduce = "max" }}
peak_force = {{ path = "actuators.M7_8.force", reduce = "absmax" }}
"""


def _write(tmp_path: Path, text: str, name: str = "study.toml") -> Path:
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


@pytest.fixture(scope="module")
def cluster():
    """One local Dask cluster of two single-threaded worker processes, shared by the tests
    that do not kill workers (starting a cluster takes seconds)."""
    from dask.distributed import LocalCluster
    from trussfe.parametric.engine import environment_kept
    with environment_kept():          # Dask's nanny writes its workers' variables into ours
        c = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                         dashboard_address=":0")
        yield c.scheduler_address
        c.close()


@pytest.fixture(scope="module")
def slew_table(tmp_path_factory, cluster):
    """The slew study run uninterrupted."""
    d = tmp_path_factory.mktemp("slew")
    f = _write(d, SLEW)
    return f, trussfe.study(f, out=d / "out", scheduler=cluster)


def _assert_same(a, b):
    pd.testing.assert_frame_equal(a.reset_index(drop=True), b.reset_index(drop=True))


# -- the study file --------------------------------------------------------------------------

@pytest.mark.parametrize("edit, fragment", [
    (('"loads.B.1"', '"loads.X.1"'), "parameters.loads.X.1: path 'loads.X.1'"),
    (('"sections.tube.outer_diameter"', '"sections.tub.outer_diameter"'),
     "did you mean 'tube'"),
    (('distribution = "normal"', 'distribution = "gauss"'), "unknown distribution 'gauss'"),
    (('std = 2.0e9', 'std = -2.0e9'), "must be positive"),
    (('bar_model = "truss"', 'bar_modl = "truss"'), "'static' has no option 'bar_modl'"),
    (('"members.follower.axial_force"', '"members.folower.axial_force"'),
     "outputs.N_follower: 'members.folower.axial_force'"),
    (('reduce = "max"', 'reduce = "maximum"'), "unknown reduction 'maximum'"),
    (('bar_model = "truss"', 'bar_model = "trus"'), "--bar-model"),
    (('analysis = "static"', 'analysis = "statics"'), "unknown analysis 'statics'"),
    (('samples = 3', 'samples = 0'), "study.samples"),
])
def test_a_bad_study_file_is_refused_in_one_line_before_any_run(tmp_path, capsys, edit,
                                                               fragment):
    text = TRIANGLE.replace(*edit)
    assert text != TRIANGLE
    f = _write(tmp_path, text)
    out = tmp_path / "out"
    status = main(["study", str(f), "--out", str(out), "--no-plots"])
    err = capsys.readouterr().err
    assert status == 2
    assert err.startswith("trussfe: error: ") and err.count("\n") == 1, err
    assert fragment in err, err
    assert not (out / "parts").exists()             # no run was stored: none started


def test_a_sampled_study_needs_samples_and_a_grid_study_refuses_them(tmp_path):
    with pytest.raises(trussfe.InputError, match="samples = N"):
        read_study(_write(tmp_path, TRIANGLE.replace("samples = 3\n", "")))
    grid_only = TRIANGLE.replace(
        '"materials.aluminium.E" = { distribution = "normal", mean = 71.0e9, std = 2.0e9 }',
        "")
    with pytest.raises(trussfe.InputError, match="every sample would be the same run"):
        read_study(_write(tmp_path, grid_only))


def test_draws_depend_on_the_seed_and_the_run_id_only(tmp_path):
    """Run r's draw is the r-th child of SeedSequence(seed): the same whatever the order
    in which runs are made, and different for another seed."""
    s = read_study(_write(tmp_path, TRIANGLE))
    runs = design(s)
    assert [r[0] for r in runs] == list(range(12))
    assert [(r[1], r[2]) for r in runs[:4]] == [(0, 0), (0, 1), (0, 2), (1, 0)]
    for rid, _, _, values in runs:
        child = np.random.SeedSequence(7).spawn(12)[rid]
        expect = np.random.default_rng(child).normal(71.0e9, 2.0e9)
        assert values["materials.aluminium.E"] == expect
        assert run_rng(7, rid).normal(71.0e9, 2.0e9) == expect
    other = read_study(_write(tmp_path, TRIANGLE.replace("seed = 7", "seed = 8")))
    assert design(other)[0][3]["materials.aluminium.E"] != runs[0][3]["materials.aluminium.E"]


EVERY_DISTRIBUTION = TRIANGLE.replace(
    '"materials.aluminium.E" = { distribution = "normal", mean = 71.0e9, std = 2.0e9 }',
    '"loads.B.0" = { distribution = "uniform", low = -5.0, high = 5.0 }\n'
    '"materials.aluminium.E" = { distribution = "normal", mean = 71.0e9, std = 2.0e9 }\n'
    '"materials.aluminium.density" = { distribution = "lognormal", mean = 7.9, sigma = 0.1 }\n'
    '"sections.tube.inner_diameter" = { distribution = "choice", '
    'values = [0.02, 0.022225] }').replace("samples = 3", "samples = 500")


def test_every_distribution_draws_from_its_run_generator(tmp_path):
    """uniform (low, high), normal (mean, std), lognormal (mean, sigma of log x) and choice
    (values), drawn in file order from the run's generator; over the 2,000 runs of the
    grid × Monte Carlo design the sample moments match the distributions' closed forms
    (within 5 standard errors): uniform mean (a+b)/2, normal mean μ, lognormal mean
    exp(μ + σ²/2), choice frequencies 1/2."""
    s = read_study(_write(tmp_path, EVERY_DISTRIBUTION))
    runs = design(s)
    assert len(runs) == 4 * 500 and {(r[1], r[2]) for r in runs} == {
        (g, k) for g in range(4) for k in range(500)}
    for rid, _, _, values in runs[:50]:
        rng = run_rng(7, rid)
        assert values["loads.B.0"] == rng.uniform(-5.0, 5.0)
        assert values["materials.aluminium.E"] == rng.normal(71.0e9, 2.0e9)
        assert values["materials.aluminium.density"] == rng.lognormal(7.9, 0.1)
        assert values["sections.tube.inner_diameter"] == [0.02, 0.022225][rng.integers(2)]
    col = {k: np.array([r[3][k] for r in runs]) for k in runs[0][3]}
    n = len(runs)
    assert abs(col["loads.B.0"].mean() - 0.0) < 5 * (10 / np.sqrt(12)) / np.sqrt(n)
    assert abs(col["materials.aluminium.E"].mean() - 71.0e9) < 5 * 2.0e9 / np.sqrt(n)
    mean_ln = np.exp(7.9 + 0.1 ** 2 / 2)
    sd_ln = mean_ln * np.sqrt(np.exp(0.1 ** 2) - 1)
    assert abs(col["materials.aluminium.density"].mean() - mean_ln) < 5 * sd_ln / np.sqrt(n)
    share = (col["sections.tube.inner_diameter"] == 0.02).mean()
    assert abs(share - 0.5) < 5 * 0.5 / np.sqrt(n)


def test_a_monte_carlo_plot_has_a_histogram_panel(tmp_path, monkeypatch):
    """Each output's figure: one panel per varying parameter, and for a Monte Carlo study a
    histogram of the output over the runs (the counts add up to the runs that gave it)."""
    from trussfe.parametric import engine, plots

    s = read_study(_write(tmp_path, TRIANGLE))
    rows = [{"run_id": r[0], "grid_point": r[1], "sample": r[2], **r[3], "N_follower": -1.0 - r[0],
             "uy_B": 1e-6 * r[0], "max_vm": 1e6 + r[0], "status": "ok", "error": None}
            for r in design(s)]
    figures = []
    real = plots.subplots

    def keep(*a, **k):
        fig, axes = real(*a, **k)
        figures.append(axes)
        return fig, axes

    monkeypatch.setattr(plots, "subplots", keep)
    run = engine.StudyRun(study=s, table=pd.DataFrame(rows), wall_time=1.0, folder=tmp_path,
                          complete=True)
    names = plots.write_plots(run, tmp_path)
    assert names == ["N_follower.png", "uy_B.png", "max_vm.png"]
    for axes in figures:
        visible = [ax for ax in axes.ravel() if ax.get_visible()]
        assert len(visible) == 3 + 1                 # three parameters vary, one histogram
        bars = visible[-1].patches
        assert bars and sum(b.get_height() for b in bars) == 12


# -- running ---------------------------------------------------------------------------------

def test_triangle_study_gives_table_3_2_forces_for_every_draw(tmp_path, cluster, capsys):
    """The follower force is Lacy's Table 3.2 value scaled by the load, for every sampled E
    and tube (statically determinate); the displacement scales as 1/(E A) exactly."""
    df = trussfe.study(_write(tmp_path, TRIANGLE), out=tmp_path / "out", scheduler=cluster,
                       progress=True)
    bar = capsys.readouterr().err
    assert "12/12" in bar and "run" in bar          # the progress bar: done of the total
    assert list(df.run_id) == list(range(12)) and (df.status == "ok").all()
    scale = df["loads.B.1"] / -98.1
    np.testing.assert_allclose(df.N_follower, TABLE_3_2_FOLLOWER * scale, rtol=1e-5)
    D = df["sections.tube.outer_diameter"]
    area = np.pi / 4 * (D ** 2 - 0.022225 ** 2)
    eau = df.uy_B * df["materials.aluminium.E"] * area / scale
    np.testing.assert_allclose(eau, eau.iloc[0], rtol=1e-9)
    # a run equals calling the API with the same model (an independent path to the value)
    r = df.iloc[5]
    direct = trussfe.static(trussfe.model_from_dict(_triangle_data(
        r["sections.tube.outer_diameter"], r["loads.B.1"], r["materials.aluminium.E"])))
    assert r.uy_B == direct.to_dict()["nodes"]["B"]["displacement"][1]
    doc = json.loads((tmp_path / "out" / "study.json").read_text())
    assert doc["runs"] == doc["ok"] == 12 and doc["error"] == 0
    assert doc["outputs"]["max_vm"]["max"] == df.max_vm.max()


def _triangle_data(D, load, E):
    data = tomllib.loads((MESHES / "triangular_truss_static.toml").read_text())
    data["sections"]["tube"]["outer_diameter"] = D
    data["loads"]["B"][1] = load
    data["materials"]["aluminium"]["E"] = E
    return data


def test_the_table_does_not_depend_on_the_number_of_workers(tmp_path, cluster):
    """... and a study with its own local cluster leaves this process' environment as it
    found it."""
    f = _write(tmp_path, TRIANGLE)
    env = dict(os.environ)
    ticks = []
    two = trussfe.study(f, scheduler=cluster, progress=lambda d, t: ticks.append((d, t)))
    assert ticks == [(k, 12) for k in range(1, 13)]
    one = trussfe.study(f, workers=1)
    _assert_same(one, two)
    assert dict(os.environ) == env


def test_batch_size_rule():
    """The batch rule of trussfe.parametric.engine.BatchSize: one run per task until a run
    has been timed, then about TASK_SECONDS of runs, at most an even share of the runs left
    between two tasks per worker, never less than one."""
    from trussfe.parametric.engine import TASK_SECONDS, BatchSize

    size = BatchSize(workers=2)
    assert size.next(1000) == 1 and size.next(0) == 0
    size.record(4, 4 * 0.01)                       # 10 ms per run
    assert size.next(1000) == int(TASK_SECONDS / 0.01)
    assert size.next(40) == 10                     # ceil(40 / (2 x 2))
    assert size.next(3) == 1
    size.record(1, 100.0)                          # slow runs: one per task
    assert size.next(1000) == 1


def test_the_table_does_not_depend_on_the_batches(tmp_path, cluster, monkeypatch):
    """The same study with one run per task and with every run batched: the same table
    (each row is its run's, whatever batch it travelled in), and fewer tasks."""
    from dask.distributed import Client

    from trussfe.parametric import engine

    f = _write(tmp_path, TRIANGLE)
    tasks = {}
    real_submit = Client.submit

    def counting(self, fn, *a, **k):
        tasks[engine.TASK_SECONDS] = tasks.get(engine.TASK_SECONDS, 0) + 1
        return real_submit(self, fn, *a, **k)

    monkeypatch.setattr(Client, "submit", counting)
    monkeypatch.setattr(engine, "TASK_SECONDS", 1e-12)        # one run per task
    single = trussfe.study(f, scheduler=cluster)
    monkeypatch.setattr(engine, "TASK_SECONDS", 1e12)         # as large as the rule allows
    batched = trussfe.study(f, scheduler=cluster)
    _assert_same(single, batched)
    assert tasks[1e-12] == 11                # 12 runs, the first in this process
    assert tasks[1e12] < tasks[1e-12]


def test_a_failed_run_is_a_row_not_a_failed_study(tmp_path, cluster):
    """A diameter smaller than the bore makes an invalid tube: that run fails, with the
    reader's one-line reason, the others are computed."""
    text = TRIANGLE.replace("[0.0254, 0.03]", "[0.0254, 0.02]")
    df = trussfe.study(_write(tmp_path, text), scheduler=cluster)
    bad = df["sections.tube.outer_diameter"] == 0.02
    assert (df.status[bad] == "error").all() and (df.status[~bad] == "ok").all()
    assert df.error[bad].str.startswith("triangular_truss_static.toml: sections.tube").all()
    assert df.N_follower[bad].isna().all() and df.error[~bad].isna().all()


def test_the_progress_bar_counts_failed_runs_and_the_time_left(tmp_path, cluster, capsys):
    text = TRIANGLE.replace("[0.0254, 0.03]", "[0.0254, 0.02]")
    df = trussfe.study(_write(tmp_path, text), scheduler=cluster, progress=True)
    bar = capsys.readouterr().err.replace("\r", "\n").splitlines()
    last = [line for line in bar if "12/12" in line][-1]
    assert f"failed={int((df.status == 'error').sum())}" in last      # 6 of 12 failed
    assert "<" in last and ("run/s" in last or "s/run" in last)      # elapsed<left, rate


def test_cli_writes_results_summary_and_plots(tmp_path, cluster):
    f = _write(tmp_path, TRIANGLE)
    out = tmp_path / "res"
    p = subprocess.run([sys.executable, "-m", "trussfe", "study", str(f), "--out", str(out),
                        "--scheduler", cluster, "--json", str(tmp_path / "s.json")],
                       capture_output=True, text=True, env=ENV, cwd=tmp_path, timeout=300)
    assert p.returncode == 0, p.stderr
    assert p.stderr == ""                      # no progress bar: stderr is not a terminal
    assert "12/12 runs, 12 ok, 0 failed" in p.stdout
    df = pd.read_parquet(out / "results.parquet")
    assert len(df) == 12 and list(df.columns)[:3] == ["run_id", "grid_point", "sample"]
    doc = json.loads((tmp_path / "s.json").read_text())
    assert doc == json.loads((out / "study.json").read_text())
    assert {f"{o}.png" for o in ("N_follower", "uy_B", "max_vm")} <= set(os.listdir(out))
    # a second run into the same folder is refused unless resumed
    assert main(["study", str(f), "--out", str(out)]) == 2


def test_study_command_does_not_slow_other_commands():
    """Dask, pandas and pyarrow are imported by the study command only."""
    code = ("import sys; from trussfe.cli import build_parser; build_parser(); "
            "import trussfe.parametric; "
            "print(sorted(m for m in ('dask', 'distributed', 'pandas', 'pyarrow') "
            "if m in sys.modules))")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=ENV,
                       timeout=120)
    assert p.returncode == 0, p.stderr
    assert p.stdout.strip() == "[]"


# -- nothing is lost -------------------------------------------------------------------------

def test_kill_and_resume_gives_the_uninterrupted_table(tmp_path, slew_table, cluster):
    """The command killed mid-study (SIGKILL, no clean-up) keeps the runs it stored;
    --resume runs only the missing ones and the table equals the uninterrupted one."""
    f, full = slew_table
    out = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-m", "trussfe", "study", str(f), "--out",
                             str(out), "--scheduler", cluster, "--no-plots"], env=ENV,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True)
    parts = out / "parts"
    deadline = time.monotonic() + 120
    try:
        while time.monotonic() < deadline and proc.poll() is None:
            if parts.is_dir() and len(list(parts.glob("*.parquet"))) >= 2:
                break
            time.sleep(0.05)
    finally:
        os.killpg(proc.pid, signal.SIGKILL)        # the command and its worker processes
        proc.wait()
    from trussfe.parametric.engine import PartStore
    stored = PartStore(out, read_study(f), resume=True).done()
    assert 0 < len(stored) < len(full), "the study was not interrupted mid-way"
    assert not (out / "results.parquet").exists()
    p = subprocess.run([sys.executable, "-m", "trussfe", "study", str(f), "--out", str(out),
                        "--scheduler", cluster, "--resume", "--no-plots"], capture_output=True,
                       text=True, env=ENV, timeout=300)
    assert p.returncode == 0, p.stderr
    _assert_same(pd.read_parquet(out / "results.parquet"), full)


def test_a_killed_worker_loses_no_row(tmp_path, slew_table, cluster):
    """A worker process killed mid-study: Dask runs its tasks on the other worker (and the
    cluster's nanny starts a new worker process)."""
    from dask.distributed import Client

    f, full = slew_table
    with Client(cluster) as client:
        pids = list(client.run(os.getpid).values())
    killed = []

    def kill_one():
        parts = tmp_path / "out" / "parts"
        end = time.monotonic() + 60
        while time.monotonic() < end:
            if parts.is_dir() and len(list(parts.glob("*.parquet"))) >= 2:
                os.kill(pids[0], signal.SIGKILL)
                # mid-study: the table is written when the last run has finished
                killed.append(not (tmp_path / "out" / "results.parquet").exists())
                return
            time.sleep(0.02)

    t = threading.Thread(target=kill_one)
    t.start()
    df = trussfe.study(f, out=tmp_path / "out", scheduler=cluster)
    t.join()
    with Client(cluster) as client:           # the nanny has started a new worker
        client.wait_for_workers(2, timeout=60)
    assert killed == [True], "no worker was killed mid-study"
    assert len(df) == len(full) and (df.status == "ok").all()
    _assert_same(df, full)


def _free_port() -> int | None:
    try:
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            return s.getsockname()[1]
    except OSError:
        return None


def test_a_separately_started_scheduler_gives_the_same_table(tmp_path, slew_table):
    f, full = slew_table
    port = _free_port()
    dask_cli = shutil.which("dask")
    if port is None or dask_cli is None:
        pytest.skip("no free local port or no dask command")
    addr = f"tcp://127.0.0.1:{port}"
    procs = [subprocess.Popen([dask_cli, "scheduler", "--host", "127.0.0.1", "--port",
                               str(port), "--no-dashboard"], env=ENV, start_new_session=True,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    try:
        procs.append(subprocess.Popen([dask_cli, "worker", addr, "--nworkers", "1",
                                       "--nthreads", "1", "--no-dashboard"], env=ENV,
                                      start_new_session=True, stdout=subprocess.DEVNULL,
                                      stderr=subprocess.DEVNULL))
        from dask.distributed import Client
        try:
            with Client(addr, timeout="30s") as c:
                c.wait_for_workers(1, timeout=60)
        except (OSError, TimeoutError) as exc:
            pytest.skip(f"the scheduler did not start: {exc}")
        df = trussfe.study(f, out=tmp_path / "out", scheduler=addr)
    finally:
        for p in procs:
            with_kill = p.poll() is None
            if with_kill:
                os.killpg(p.pid, signal.SIGTERM)
            p.wait(timeout=30)
    _assert_same(df, full)


def test_an_unreachable_scheduler_is_one_line(tmp_path, capsys, monkeypatch):
    from trussfe.parametric import engine
    monkeypatch.setattr(engine, "CONNECT_TIMEOUT", "2s")
    port = _free_port()
    if port is None:
        pytest.skip("no free local port")
    f = _write(tmp_path, TRIANGLE)
    status = main(["study", str(f), "--out", str(tmp_path / "o"), "--scheduler",
                   f"tcp://127.0.0.1:{port}"])
    err = capsys.readouterr().err
    assert status == 2 and err.startswith("trussfe: error: --scheduler: cannot reach"), err
    assert err.count("\n") == 1 and not (tmp_path / "o" / "parts").exists()


# -- the shipped studies (examples/), at small size ------------------------------------------

def _example(tmp_path: Path, name: str, *edits: tuple[str, str]) -> Path:
    text = (EXAMPLES / name).read_text(encoding="utf-8").replace('"../meshes/', f'"{MESHES}/')
    for old, new in edits:
        assert old in text, old
        text = text.replace(old, new)
    return _write(tmp_path, text, name)


def test_shipped_studies_read():
    for f in sorted(EXAMPLES.glob("*.toml")):
        assert read_study(f).n_runs > 1, f


def test_chain_length_study(tmp_path, cluster):
    """First frequency and tip deflection of 1-3 bays equal the API's modes and static of
    the catalogue chain under Lacy's Table 5.2 load; a longer chain is softer and lower."""
    from trussfe.models import TABLE_LOAD, double_octahedral_chain

    f = _example(tmp_path, "chain_length.toml", ("to = 50", "to = 3"))
    df = trussfe.study(f, scheduler=cluster)
    assert list(df.n_bays) == [1, 2, 3] and (df.status == "ok").all()
    s = double_octahedral_chain(2, tip_load=TABLE_LOAD)
    assert df.first_frequency[1] == trussfe.modes(s, count=1).frequencies_hz[0]
    uz = trussfe.static(s).to_dict()["nodes"]["b2.N7"]["displacement"][2]
    assert df.tip_deflection[1] == uz
    assert (np.diff(df.first_frequency) < 0).all() and (np.diff(df.tip_deflection) > 0).all()


def test_slew_study_feasible_region(tmp_path, cluster):
    """Peak motor voltage of the -5 deg to +5 deg tilt: above the motors' 25 V in 2 s, within
    it in 6 s, with or without payload; more payload, more force in M7/8; a run equals the
    API's simulate of the same model and motion."""
    from trussfe.rigid.motion_file import motion_from_spec

    f = _example(tmp_path, "slew_duration_payload.toml",
                 ("from = 1.0, to = 6.0, step = 0.5", "values = [2.0, 6.0]"),
                 ("from = 0.0, to = 20.0, step = 5.0", "values = [0.0, 20.0]"),
                 ("steps = 200", "steps = 24"))
    df = trussfe.study(f, scheduler=cluster)
    assert (df.status == "ok").all() and len(df) == 4
    v = df.set_index(["duration", "payload"]).peak_voltage
    assert v[2.0, 0.0] > 25.0 and v[2.0, 20.0] > 25.0
    assert v[6.0, 0.0] <= 25.0 and v[6.0, 20.0] <= 25.0
    F = df.set_index(["duration", "payload"]).peak_M8_force
    assert F[2.0, 20.0] > F[2.0, 0.0]
    data = tomllib.loads((MESHES / "double_octahedron_actuators.toml").read_text())
    data["masses"] = {n: 20.0 * 0.3333333333333333 for n in ("N7", "N8", "N9")}
    s = trussfe.model_from_dict(data)
    spec = tomllib.loads((MESHES / "double_octahedron_tilt_rotation.toml").read_text())
    spec["motion"]["duration"] = 6.0
    motion = motion_from_spec(spec["motion"], s, MESHES, steps=24)
    doc = trussfe.simulate(s, motion=motion).to_dict()
    assert v[6.0, 20.0] == max(a["max_motor_voltage"] for a in doc["actuators"].values())


def test_dome_imperfection_study(tmp_path, cluster):
    """Each Monte Carlo run equals the API's postcritical analysis of the model with the
    drawn imperfection and critical loads; the dome becomes a mechanism after its first
    failure, at a load no lower."""
    f = _example(tmp_path, "dome_imperfection.toml", ("samples = 200", "samples = 3"))
    df = trussfe.study(f, scheduler=cluster)
    assert len(df) == 3 and (df.status == "ok").all()
    assert (df.mechanism_load >= df.first_limit_load).all()
    assert (df.imperfection >= 0).all() and (df.imperfection <= 0.015).all()
    r = df.iloc[2]
    data = tomllib.loads((MESHES / "postcritical_dome.toml").read_text())
    data["postcritical"]["imperfection"] = r.imperfection
    for m in ("A1", "A2", "A3", "A5", "A6"):
        assert 0.9 <= r[m] <= 1.1
        data["failure"]["members"][m]["critical_load"] *= r[m]
    doc = trussfe.postcritical(trussfe.model_from_dict(data)).to_dict()
    mech = [e["load_factor"] for e in doc["events"] if e["kind"] == "mechanism"]
    assert r.mechanism_load == mech[0]
    assert r.max_load_factor == doc["max_load_factor"]


def test_ctrl_c_keeps_the_stored_runs_in_one_line(tmp_path):
    """Ctrl-C on a terminal (SIGINT to the whole process group, local workers included):
    exit 130, one line saying how many runs are stored, no traceback from any worker."""
    f = _write(tmp_path, SLEW)
    out = tmp_path / "out"

    def default_sigint():                   # as a shell in the foreground would start it
        os.setsid()
        signal.signal(signal.SIGINT, signal.SIG_DFL)

    proc = subprocess.Popen([sys.executable, "-m", "trussfe", "study", str(f), "--out",
                             str(out), "--workers", "1", "--no-plots"], env=ENV,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=default_sigint)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        if (out / "parts").is_dir() and len(list((out / "parts").glob("*.parquet"))) >= 2:
            break
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGINT)
    stdout, stderr = proc.communicate(timeout=120)
    assert proc.returncode == 130, stderr
    assert stderr.startswith("trussfe: error: interrupted; ") and stderr.count("\n") == 1, \
        stderr
    assert "--resume continues the study" in stderr and stdout == ""
    assert not (out / "results.parquet").exists()
