# SPDX-License-Identifier: MIT
"""The numbers of a parameter study held against independent computations: the statistics of
``study.json`` against pandas over ``results.parquet``, the grid ranges against their
documented ends (docs/studies.md), the random draws against scipy's distributions, and a
``relative`` parameter of a catalogue structure against the API called on the model by hand."""
from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("dask.distributed")
pd = pytest.importorskip("pandas")
pytest.importorskip("pyarrow")
stats = pytest.importorskip("scipy.stats")

import trussfe  # noqa: E402
from trussfe.cli import main  # noqa: E402
from trussfe.parametric import read_study  # noqa: E402
from trussfe.parametric.design import design  # noqa: E402
from trussfe.parametric.engine import StudyRun  # noqa: E402
from trussfe.parametric.runner import run_one  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TRIANGLE = ROOT / "meshes" / "triangular_truss_static.toml"

#: A grid × Monte Carlo study of the triangular truss in which a third of the draws make an
#: invalid tube (outer diameter 0.02 m below the bore 0.022225 m): failed rows.
MIXED = f"""
[study]
analysis = "static"
model = "{TRIANGLE.as_posix()}"
options = {{ bar_model = "truss" }}
samples = 7
seed = 3

[parameters]
"loads.B.1" = [-98.1, -196.2, -50.0]
"sections.tube.outer_diameter" = {{ distribution = "choice", values = [0.0254, 0.03, 0.02] }}
"materials.aluminium.E" = {{ distribution = "lognormal", mean = 24.99, sigma = 0.05 }}
"loads.B.0" = {{ distribution = "uniform", low = -5.0, high = 5.0 }}

[outputs]
N_follower = "members.follower.axial_force"
max_vm = {{ path = "members.*.max_von_mises", reduce = "max" }}
absmax_N = {{ path = "members.*.axial_force", reduce = "absmax" }}
mean_N = {{ path = "members.*.axial_force", reduce = "mean" }}
"""


def _write(folder: Path, text: str, name: str = "study.toml") -> Path:
    p = folder / name
    p.write_text(text, encoding="utf-8")
    return p


def _pandas_stats(x) -> dict:
    """docs/json.md, ``study``: count, mean, sample std, min, max, 5/50/95 % percentiles,
    computed by pandas (linear interpolation, ddof = 1)."""
    x = pd.Series(x, dtype=float)
    return {"count": int(x.size), "mean": x.mean(), "std": x.std(), "min": x.min(),
            "max": x.max(), "p05": x.quantile(0.05), "median": x.median(),
            "p95": x.quantile(0.95)}


def test_study_json_statistics_equal_pandas_over_the_stored_table(tmp_path):
    """Reference: pandas over results.parquet, keeping the rows with status "ok" and finite
    outputs (docs/json.md: "count (finite values over the runs that succeeded)"); the failed
    runs are counted apart and have NaN outputs (docs/studies.md)."""
    out = tmp_path / "out"
    status = main(["study", str(_write(tmp_path, MIXED)), "--out", str(out), "--workers", "1",
                   "--no-plots", "--no-progress"])
    assert status == 0
    df = pd.read_parquet(out / "results.parquet")
    doc = json.loads((out / "study.json").read_text())
    failed = df.status == "error"
    assert 0 < failed.sum() < len(df)                       # both kinds of run are present
    assert (doc["ok"], doc["error"], doc["stored"]) == ((~failed).sum(), failed.sum(), 21)
    assert df.loc[failed, ["N_follower", "max_vm", "absmax_N", "mean_N"]].isna().all().all()
    for name in ("N_follower", "max_vm", "absmax_N", "mean_N"):
        x = df.loc[~failed, name]
        ref = _pandas_stats(x[np.isfinite(x)])
        got = doc["outputs"][name]
        assert got["count"] == ref["count"]
        for key in ("mean", "std", "min", "max", "p05", "median", "p95"):
            assert got[key] == pytest.approx(ref[key], rel=1e-12, abs=0), (name, key)


@pytest.fixture
def summary_of(tmp_path):
    """The ``study.json`` statistics of the output N_follower for a table whose rows hold
    the given values and statuses (the other outputs equal)."""
    s = read_study(_write(tmp_path, MIXED))

    def summary(values: list[float], status: list[str]) -> dict:
        rows = [{"run_id": r[0], "grid_point": r[1], "sample": r[2], **r[3], "N_follower": v,
                 "max_vm": v, "absmax_N": v, "mean_N": v, "status": st,
                 "error": None if st == "ok" else "failed"}
                for r, v, st in zip(design(s), values, status)]
        run = StudyRun(study=s, table=pd.DataFrame(rows), wall_time=0.0, folder=None,
                       complete=True)
        return run.summary()["outputs"]["N_follower"]

    return summary


def test_the_statistics_leave_out_failed_runs_and_values_that_are_not_finite(summary_of):
    """Reference: pandas over the "ok" rows' finite values; a failed row's number (even one
    a part might hold) and a NaN or infinite output of a run that succeeded are not counted."""
    values = [1.0, 2.0, 1e9, math.nan, math.inf, 4.0, -2.5]
    status = ["ok", "ok", "error", "ok", "ok", "ok", "ok"]
    got = summary_of(values, status)
    ref = _pandas_stats([1.0, 2.0, 4.0, -2.5])
    assert got["count"] == 4
    for key in ("mean", "std", "min", "max", "p05", "median", "p95"):
        assert got[key] == pytest.approx(ref[key], rel=1e-12, abs=0), key


def test_the_sample_std_of_a_single_value_is_null_not_zero(summary_of):
    """Reference: pandas ``Series([x]).std()`` (ddof = 1) is NaN — one value has no sample
    standard deviation; study.json writes "no value" as null (docs/json.md).  trussfe wrote
    0.0, a spread of zero it never measured."""
    assert math.isnan(pd.Series([3.0]).std())
    got = summary_of([3.0, math.nan, 7.0], ["ok", "ok", "error"])
    assert got["count"] == 1 and got["mean"] == got["median"] == 3.0
    assert got["std"] is None


def _grid(tmp_path: Path, spec: str) -> tuple:
    text = MIXED.replace('"loads.B.1" = [-98.1, -196.2, -50.0]', f'"loads.B.1" = {spec}')
    return read_study(_write(tmp_path, text)).grid[0].values


@pytest.mark.parametrize("lo, hi, n", [(0.3, 0.9, 3), (0.1, 0.7, 7), (-0.9, -0.3, 4),
                                       (0, 10, 3)])
def test_a_count_range_runs_from_a_to_b_exactly(tmp_path, lo, hi, n):
    """docs/studies.md: ``{ from = a, to = b, count = n }`` is "n values evenly spaced from a to
    b"; reference ``numpy.linspace(a, b, n)``, whose ends are a and b exactly.  trussfe's last
    value was a + (b - a) = 0.9000000000000001 for a = 0.3, b = 0.9."""
    got = _grid(tmp_path, f"{{ from = {lo}, to = {hi}, count = {n} }}")
    ref = np.linspace(lo, hi, n)
    assert len(got) == n
    assert got[0] == ref[0] == lo and got[-1] == ref[-1] == hi
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-15 * max(abs(lo), abs(hi)))
    assert all(isinstance(v, float) for v in got)


@pytest.mark.parametrize("lo, hi, step, n", [(0.1, 0.3, 0.1, 3), (0.3, 0.1, -0.1, 3),
                                             (0.0, 0.9, 0.3, 4), (1, 7, 2, 4)])
def test_a_step_range_never_passes_b(tmp_path, lo, hi, step, n):
    """docs/studies.md: ``{ from = a, to = b, step = s }`` is "a, a + s, ... up to b": no value
    past b, although 0.1 + 2 × 0.1 = 0.30000000000000004 > 0.3 in floating point;
    each value is a + k s to rounding (reference: the exact a + k s)."""
    got = _grid(tmp_path, f"{{ from = {lo}, to = {hi}, step = {step} }}")
    assert len(got) == n and got[0] == lo
    assert all((v - hi) * step <= 0 for v in got)
    np.testing.assert_allclose(got, [lo + k * step for k in range(n)], rtol=1e-15, atol=1e-16)
    if all(isinstance(x, int) for x in (lo, hi, step)):
        assert all(isinstance(v, int) for v in got)


def test_draws_follow_their_distributions_by_kolmogorov_smirnov(tmp_path):
    """Reference: scipy.stats' uniform(low, high - low), norm(mean, std), lognorm(s = sigma,
    scale = exp(mean)) (numpy's lognormal: mean and sigma of the logarithm) and equal
    frequencies of a choice (chi-square), over 20,000 draws; uniform on [low, high)."""
    text = f"""
[study]
analysis = "static"
model = "{TRIANGLE.as_posix()}"
samples = 20000
seed = 11

[parameters]
a = {{ path = "loads.B.0", distribution = "uniform", low = -5.0, high = 3.0 }}
b = {{ path = "materials.aluminium.E", distribution = "normal", mean = 71.0e9, std = 2.0e9 }}
c = {{ path = "materials.aluminium.density", distribution = "lognormal", mean = 7.9, sigma = 0.3 }}
d = {{ path = "loads.B.1", distribution = "choice", values = [-1.0, -2.0, -3.0] }}

[outputs]
N = "members.follower.axial_force"
"""
    runs = design(read_study(_write(tmp_path, text)))
    col = {k: np.array([r[3][k] for r in runs]) for k in "abcd"}
    alpha = 1e-3
    assert stats.kstest(col["a"], stats.uniform(-5.0, 8.0).cdf).pvalue > alpha
    assert -5.0 <= col["a"].min() and col["a"].max() < 3.0
    assert stats.kstest(col["b"], stats.norm(71.0e9, 2.0e9).cdf).pvalue > alpha
    assert stats.kstest(col["c"], stats.lognorm(s=0.3, scale=np.exp(7.9)).cdf).pvalue > alpha
    _, counts = np.unique(col["d"], return_counts=True)
    assert len(counts) == 3 and stats.chisquare(counts).pvalue > alpha


CHAIN = """
[study]
analysis = "static"
catalogue = "double_octahedral_chain"

[catalogue]
tip_load = 44.498

[parameters]
n_bays = { path = "catalogue.n_bays", values = [1, 2] }
E = { path = "materials.aluminium.E", values = [0.5, 2.0], relative = true }

[outputs]
tip = "nodes.b{n_bays}.N7.displacement.2"
"""


def test_a_relative_parameter_of_a_catalogue_structure_scales_its_own_number(tmp_path):
    """docs/studies.md: ``relative = true`` writes the model's own number × the value.  A
    catalogue structure's model paths are parameters like a model file's, relative ones
    included, their base read from the model built for each run.  Reference: the
    API's static analysis of the catalogue model with E scaled by hand."""
    from trussfe.io.model_writer import model_toml
    from trussfe.models import double_octahedral_chain

    s = read_study(_write(tmp_path, CHAIN))
    for run in design(s):
        row = run_one(s, *run)
        assert row["status"] == "ok", row["error"]
        n, scale = run[3]["n_bays"], run[3]["E"]
        data = tomllib.loads(model_toml(double_octahedral_chain(n_bays=n, tip_load=44.498)))
        data["materials"]["aluminium"]["E"] *= scale
        direct = trussfe.static(trussfe.model_from_dict(data)).to_dict()
        assert row["tip"] == direct["nodes"][f"b{n}.N7"]["displacement"][2]


def test_a_relative_catalogue_path_that_holds_no_number_is_refused(tmp_path):
    """docs/studies.md: a study whose parameters make the model invalid is refused before any
    run, in one line naming the study file."""
    f = _write(tmp_path, CHAIN.replace("materials.aluminium.E", "model.name"))
    with pytest.raises(trussfe.InputError, match="study.toml: parameters.E: relative: path "
                                                 "'model.name' holds .*not a number"):
        read_study(f)


def test_reductions_treat_nulls_as_studies_md_says():
    """docs/studies.md: a JSON null is NaN; max, min, absmax, mean and sum leave NaN out (NaN
    only when every value is), first and last give the item as it is, count counts the
    items matched; a reduction over nothing is NaN (count: 0).  Reference: numpy's
    nan-aware reductions on the same values."""
    import math

    import numpy as np

    from trussfe.api.result_paths import reduce

    values = [math.nan, -4.0, 3.0, math.nan]
    a = np.array(values)
    assert reduce(values, "max") == np.nanmax(a) == 3.0
    assert reduce(values, "min") == np.nanmin(a) == -4.0
    assert reduce(values, "absmax") == 4.0
    assert reduce(values, "mean") == np.nanmean(a) == -0.5
    assert reduce(values, "sum") == np.nansum(a) == -1.0
    assert math.isnan(reduce(values, "first")) and math.isnan(reduce(values, "last"))
    assert reduce(values, "count") == 4.0
    assert math.isnan(reduce([math.nan, math.nan], "max"))
    assert math.isnan(reduce([], "mean")) and reduce([], "count") == 0.0
