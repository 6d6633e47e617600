# SPDX-License-Identifier: MIT
"""``trussfe study STUDY.toml [--out DIR] [--scheduler ADDRESS] [--workers N] [--resume]
[--json OUT] [--no-plots] [--no-progress]``: parameter sweeps and Monte Carlo over any
analysis, on Dask distributed (docs/studies.md).

Exit status: 0 when the study ran (failed runs are rows of the table, not a failed command),
2 for a bad study file (refused before any run starts) or a scheduler that cannot be reached,
130 when interrupted (the finished runs are kept: ``--resume`` continues).
"""
from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

from . import options as opt


def register(subparsers) -> None:
    """Add the ``study`` command."""
    p = subparsers.add_parser(
        "study", help="parameter sweeps and Monte Carlo over any analysis (Dask)",
        description="Run an analysis over a grid of parameter values and/or random draws, "
        "on a local Dask cluster or a running Dask scheduler; results as a Parquet table.")
    p.add_argument("study", type=opt.input_file, help="study file (TOML, docs/studies.md)")
    p.add_argument("--out", metavar="DIR", type=opt.output_dir, default=None,
                   help="results folder (default: STUDY-results in the current folder)")
    p.add_argument("--scheduler", metavar="ADDRESS", default=None,
                   help="address of a running Dask scheduler (default: a local cluster)")
    p.add_argument("--workers", metavar="N", type=opt.positive_int, default=None,
                   help="worker processes of the local cluster (default: one per core)")
    p.add_argument("--resume", action="store_true",
                   help="continue the study stored in --out: run only the missing runs")
    p.add_argument("--json", metavar="OUT", type=opt.output_file,
                   help="write the summary (study.json) here too")
    p.add_argument("--no-plots", action="store_true", help="write no PNG plots")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.set_defaults(func=_main)


def _fmt(x) -> str:
    return "-" if x is None or (isinstance(x, float) and not math.isfinite(x)) else f"{x:.6g}"


def _main(args: argparse.Namespace) -> int:
    from ..errors import InputError
    from ..parametric.engine import require_dask, run_study, write_results
    from ..parametric import read_study

    if args.scheduler is not None and args.workers is not None:
        raise InputError("--workers", "sets the local cluster's size; a scheduler given by "
                                      "--scheduler has its own workers")
    require_dask()
    spec = read_study(args.study)
    out = Path(args.out) if args.out else Path(f"{Path(args.study).stem}-results")
    run = run_study(spec, out, scheduler=args.scheduler, workers=args.workers,
                    resume=args.resume, progress=not args.no_progress and sys.stderr.isatty())
    if not run.complete:
        sys.stderr.write(f"trussfe: error: interrupted; {len(run.table)} of {spec.n_runs} runs "
                         f"are stored in {out / 'parts'}: --resume continues the study\n")
        return 130
    doc = write_results(run, out, plots=not args.no_plots, json_out=args.json)
    lines = [f"trussfe study: {spec.name} ({', '.join(spec.analyses)}): "
             f"{doc['stored']}/{doc['runs']} runs, {doc['ok']} ok, {doc['error']} failed, "
             f"{doc['wall_time_s']:.1f} s"]
    lines.append(f"{'output':>24}  {'runs':>6}  {'mean':>12}  {'min':>12}  {'max':>12}")
    for name, s in doc["outputs"].items():
        lines.append(f"{name[:24]:>24}  {s['count']:6d}  {_fmt(s.get('mean')):>12}  "
                     f"{_fmt(s.get('min')):>12}  {_fmt(s.get('max')):>12}")
    for e in doc["first_errors"][:3]:
        lines.append(f"run {e['run_id']}: {e['error']}")
    lines.append(f"results: {out / 'results.parquet'}")
    sys.stdout.write("\n".join(lines) + "\n")
    return 0
