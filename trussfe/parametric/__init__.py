# SPDX-License-Identifier: MIT
"""Parameter studies: sweeps and Monte Carlo over any analysis, run on Dask distributed
(``trussfe study``, :func:`study`; the file format in docs/studies.md).

A study file names an analysis of the API and a model, the parameters written at dotted paths
into the model file (or its motion file, or the arguments of a catalogue structure) and the
outputs read at dotted paths from the analysis' JSON document.  Every run calls the public API
(:data:`trussfe.api.ANALYSES`); the runs go to a Dask cluster; the results are a Parquet
table, one row per run.  Dask, pandas and pyarrow are imported when a study runs, never by
``import trussfe``.
"""
from __future__ import annotations

import os
import tempfile
from pathlib import Path

from .runner import read_study
from .spec import Study


def study(study_file: str | os.PathLike, *, out: str | os.PathLike | None = None,
          scheduler: str | None = None, workers: int | None = None, resume: bool = False,
          progress=False, plots: bool = False):
    """Run a study file and return its results table (``trussfe study``).

    Parameters
    ----------
    study_file : path
        The study (TOML, docs/studies.md).
    out : path, optional
        Results folder: ``results.parquet``, ``study.json``, ``parts/`` (and the plots with
        ``plots=True``).  Default: a temporary folder, removed afterwards.
    scheduler : str, optional
        Address of a running Dask scheduler; default a local cluster.
    workers : int, optional
        Worker processes of the local cluster (default one per core).
    resume : bool
        Continue the study stored in ``out``, running only the missing runs.
    progress : bool or callable
        True: a progress bar on stderr (runs done, failed, the time left); a callable is
        called as ``progress(done, total)`` after every run, as the analyses' ``progress``.
    plots : bool
        Write ``<output>.png`` into ``out``.

    Returns
    -------
    pandas.DataFrame
        One row per run, sorted by ``run_id``: ``run_id``, ``grid_point``, ``sample``, the
        parameters, the outputs, ``status`` (``"ok"``/``"error"``) and ``error``.

    Raises
    ------
    InputError
        A bad study file, refused before any run starts.
    """
    from .engine import run_study, write_results

    spec = read_study(study_file)
    if out is None:
        with tempfile.TemporaryDirectory(prefix="trussfe-study-") as tmp:
            run = run_study(spec, Path(tmp), scheduler=scheduler, workers=workers,
                            progress=progress)
            if not run.complete:
                raise KeyboardInterrupt("study interrupted")
            return run.table
    run = run_study(spec, Path(out), scheduler=scheduler, workers=workers, resume=resume,
                    progress=progress)
    write_results(run, Path(out), plots=plots)
    if not run.complete:
        raise KeyboardInterrupt("study interrupted; resume=True continues it")
    return run.table


__all__ = ["Study", "read_study", "study"]
