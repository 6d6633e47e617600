# SPDX-License-Identifier: MIT
"""Running a study on Dask distributed, and its results folder.

The runs go to a Dask cluster: a local one (``LocalCluster``, one single-threaded worker
process per core by default) or a running scheduler given by its address, so the same study
goes from a laptop to a cluster unchanged.  The runs travel in batches (:class:`BatchSize`:
one run per task at first, then as many as take about :data:`TASK_SECONDS`), a few tasks per
worker queued at a time; a row does not depend on the batch it ran in.  Dask retries the tasks
of a worker that dies on another worker; the runs of a task whose workers died three times
(Dask's ``allowed-failures``) are failed rows.

Nothing is lost: rows are appended to ``DIR/parts/`` as runs finish (Parquet files, each
written under a temporary name and renamed), and ``resume`` runs only the ids that no part
holds.  ``DIR/study-id.json`` records a digest of the study, model and motion files: a folder
is resumed only by the study that made it.  At the end the parts become
``DIR/results.parquet`` (sorted by run id; the same table as an uninterrupted run), with
``DIR/study.json`` and the plots.
"""
from __future__ import annotations

import contextlib
import json
import logging
import math
import os
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterator

from ..budget import check_input_file
from ..errors import InputError
from ..io.regular_file import read_regular_file
from ..io.json_document import result_json
from .design import design
from .runner import run_batch, run_one
from .spec import Study

#: Rows are written to a new part at least this often (seconds) while runs finish.
FLUSH_SECONDS = 1.0
#: ... or when this many rows are waiting.
FLUSH_ROWS = 256
#: Seconds to wait for a scheduler given by address.
CONNECT_TIMEOUT = "10s"
#: A task (a batch of runs) is sized to take about this long on a worker, once the first
#: tasks have measured how long a run takes: long enough that the scheduler's and the
#: client's cost per task is a small share of it, short enough for a live progress bar.
TASK_SECONDS = 0.5
#: Tasks queued per worker: the scheduler always has the next task at hand for a worker
#: that finishes, and the runs not yet submitted can still be batched by the measured time.
TASKS_PER_WORKER = 3


def require_dask() -> None:
    """Dask, pandas and pyarrow are needed by the study command only (imported here, not at
    start-up): a clear error if they are missing."""
    missing = []
    for mod in ("dask.distributed", "pandas", "pyarrow.parquet"):
        try:
            __import__(mod)
        except ImportError:
            missing.append(mod.split(".")[0])
    if missing:
        raise InputError("study", f"needs {', '.join(missing)}: pip install "
                                  "'dask[distributed]' pandas pyarrow")


def schema(study: Study):
    """The Arrow schema of the results table: ``run_id``, ``grid_point``, ``sample``, the
    parameters, the outputs (float64, NaN where missing), ``status``, ``error``."""
    import pyarrow as pa

    fields = [pa.field("run_id", pa.int64()), pa.field("grid_point", pa.int64()),
              pa.field("sample", pa.int64())]
    for p in study.parameters:
        vals = p.values if p.is_grid else p.args.get("values")
        if vals is None:
            t = pa.float64()
        elif all(isinstance(v, bool) for v in vals):
            t = pa.bool_()
        elif all(isinstance(v, str) for v in vals):
            t = pa.string()
        elif all(isinstance(v, int) for v in vals) and p.factor == 1.0 and not p.relative:
            t = pa.int64()
        else:
            t = pa.float64()
        fields.append(pa.field(p.name, t))
    fields += [pa.field(o.name, pa.float64()) for o in study.outputs]
    fields += [pa.field("status", pa.string()), pa.field("error", pa.string())]
    return pa.schema(fields)


class PartStore:
    """``DIR/parts/*.parquet``: the rows of finished runs, appended part by part."""

    def __init__(self, folder: Path, study: Study, *, resume: bool):
        self.folder = Path(folder)
        self.parts = self.folder / "parts"
        self.schema = schema(study)
        ident = {"study": str(study.file), "fingerprint": study.fingerprint(),
                 "runs": study.n_runs}
        id_file = self.folder / "study-id.json"
        if self.parts.is_dir() and any(self.parts.glob("*.parquet")):
            if not resume:
                raise InputError(str(self.folder), "already holds runs of a study: give "
                                 "--resume to continue it, or another --out folder")
            old = _study_record(id_file)
            if old.get("fingerprint") != ident["fingerprint"]:
                raise InputError(str(self.folder), "holds runs of a different study (the "
                                 "study, model or motion file changed): resume it with the "
                                 "same files, or choose another --out folder")
        self._ident = ident
        self._opened = False
        self._count = 0

    def open(self) -> None:
        """Create the folder and record which study it holds (at the first rows)."""
        if self._opened:
            return
        self.parts.mkdir(parents=True, exist_ok=True)
        id_file = self.folder / "study-id.json"
        tmp = id_file.with_name(f".{id_file.name}.{os.getpid()}.tmp")
        tmp.write_text(json.dumps(self._ident, indent=1), encoding="utf-8")
        os.replace(tmp, id_file)
        self._opened = True

    def read(self):
        """Every stored row as a pandas DataFrame (duplicates of a run id dropped)."""
        import pyarrow as pa
        import pyarrow.parquet as pq

        files = sorted(self.parts.glob("*.parquet")) if self.parts.is_dir() else []
        tables = [_read_part(f, lambda f: pq.read_table(f).cast(self.schema)) for f in files]
        table = pa.concat_tables(tables) if tables else self.schema.empty_table()
        df = table.to_pandas()
        return df.drop_duplicates("run_id").sort_values("run_id").reset_index(drop=True)

    def done(self) -> set[int]:
        import pyarrow.parquet as pq
        ids: set[int] = set()
        if not self.parts.is_dir():
            return ids
        for f in self.parts.glob("*.parquet"):
            part = _read_part(f, lambda f: pq.read_table(f, columns=["run_id"]))
            ids.update(part.column(0).to_pylist())
        return ids

    def append(self, rows: list[dict]) -> None:
        """Write ``rows`` as one new part (temporary name, then rename: a part is whole or
        absent)."""
        if not rows:
            return
        import pyarrow as pa
        import pyarrow.parquet as pq

        self.open()
        self._count += 1
        name = f"part-{time.time_ns():020d}-{os.getpid()}-{self._count:06d}.parquet"
        tmp = self.parts / f".{name}.tmp"
        pq.write_table(pa.Table.from_pylist(rows, schema=self.schema), tmp)
        os.replace(tmp, self.parts / name)


def _study_record(id_file: Path) -> dict:
    """The record of the study a results folder holds (``study-id.json``); empty when it is
    missing or not a JSON object, which the fingerprint test then refuses as another study's.

    Raises
    ------
    InputError
        The record is not a regular file of an accepted size (a named pipe would block the
        resume, a device would never end).
    """
    if not id_file.exists() and not id_file.is_symlink():
        return {}
    try:
        old = json.loads(read_regular_file(id_file, "study record").decode("utf-8"))
    except (UnicodeDecodeError, ValueError):
        return {}
    return old if isinstance(old, dict) else {}


def _read_part(f: Path, read):
    """``read(f)`` of one stored part of a results folder, or a one-line error naming it.

    A part is written under a temporary name and renamed, so a part that is not a Parquet
    table of the study's columns was not written by a study run: it is named, never read
    past (a named pipe would block, a device never end).

    Raises
    ------
    InputError
        The part is not a regular file or not a readable table of the study's rows.
    """
    import pyarrow as pa

    check_input_file(str(f), "part of the study's results")
    try:
        return read(f)
    except (OSError, pa.ArrowException, ValueError, KeyError) as exc:
        if isinstance(exc, OSError) and exc.errno is not None:      # the system refused
            raise InputError(str(f), "cannot read this part of the study's results: "
                             f"{exc.strerror or exc}") from None
        # pyarrow's own errors (corrupt or foreign content): its message repeats the path
        raise InputError(str(f), "is not a Parquet table of the study's columns; "
                         "remove it to run its runs again, or choose another --out folder"
                         ) from None


@dataclass
class StudyRun:
    """A finished (or interrupted) study: the results table and its summary."""

    study: Study
    table: Any                   # pandas DataFrame
    wall_time: float
    folder: Path | None
    complete: bool

    def summary(self) -> dict:
        """The ``study.json`` document (docs/json.md, ``study``)."""
        import numpy as np

        df = self.table
        ok = df["status"] == "ok" if len(df) else df.get("status", [])
        outputs = {}
        for o in self.study.outputs:
            x = df.loc[ok, o.name].to_numpy(dtype=float) if len(df) else np.zeros(0)
            x = x[np.isfinite(x)]
            stats: dict[str, Any] = {"path": o.path, "analysis": o.analysis,
                                     "reduce": o.reduce, "count": int(x.size)}
            if x.size:
                q = np.percentile(x, [5, 50, 95])
                # the sample standard deviation (ddof = 1) of a single value has no value
                # (numpy gives nan, pandas NaN): null, as JSON writes "no value", never 0,
                # which would claim the output does not vary
                stats.update(mean=float(x.mean()), std=float(x.std(ddof=1)) if x.size > 1
                             else None, min=float(x.min()), max=float(x.max()),
                             p05=float(q[0]), median=float(q[1]), p95=float(q[2]))
            outputs[o.name] = stats
        params = {}
        for p in self.study.parameters:
            d: dict[str, Any] = {"paths": [path for _, path in p.paths]}
            if p.is_grid:
                d["values"] = list(p.values)
            else:
                d["distribution"] = p.distribution
                d.update({k: list(v) if isinstance(v, tuple) else v for k, v in p.args.items()})
            if p.factor != 1.0:
                d["factor"] = p.factor
            if p.relative:
                d["relative"] = True
            params[p.name] = d
        errors = df.loc[df["status"] == "error", ["run_id", "error"]] if len(df) else []
        n_err = int(len(errors))
        return {
            **result_json("study", str(self.study.model_file) if self.study.model_file
                              else f"catalogue:{self.study.catalogue}"),
            "study": self.study.name, "analysis": list(self.study.analyses),
            "runs": self.study.n_runs, "grid_points": self.study.n_grid,
            "samples": self.study.samples, "seed": self.study.seed,
            "complete": self.complete, "stored": int(len(df)),
            "ok": int(len(df) - n_err), "error": n_err,
            "wall_time_s": self.wall_time,
            "parameters": params, "outputs": outputs,
            "first_errors": [{"run_id": int(r), "error": e}
                             for r, e in errors.head(10).itertuples(index=False)] if n_err else [],
            "results": "results.parquet",
        }


def _client(scheduler: str | None, workers: int | None):
    """A Dask client: of a running scheduler, or of a new local cluster."""
    from dask.distributed import Client, LocalCluster

    if scheduler:
        try:
            return Client(scheduler, timeout=CONNECT_TIMEOUT), None
        except (OSError, TimeoutError, ValueError) as exc:
            raise InputError("--scheduler", f"cannot reach a Dask scheduler at "
                                            f"'{scheduler}' ({exc})") from None
    n = workers or os.cpu_count() or 1
    with worker_allocator(), _interrupts_ignored_by_workers():
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                               dashboard_address=":0", silence_logs=logging.ERROR)
    return Client(cluster), cluster


#: glibc thresholds of a local cluster's worker processes, set before they start (see
#: :mod:`trussfe.allocator`): numpy's temporaries of a few MB stay on the heap.  Dask's own
#: default trims the heap above 64 KiB, which also pins the mmap threshold at 128 KiB, so every
#: larger temporary is a fresh mapping and a page fault per page.
#: 32 MiB is the largest mmap threshold every glibc accepts from the environment.
WORKER_MALLOC = {"MALLOC_TRIM_THRESHOLD_": 2**30, "MALLOC_MMAP_THRESHOLD_": 32 * 2**20}


@contextlib.contextmanager
def _interrupts_ignored_by_workers() -> Iterator[None]:
    """Start worker processes that ignore SIGINT: Ctrl-C on a terminal goes to the whole
    process group, and the study's own process stops the workers (each would otherwise print
    a traceback).  A child started while SIGINT is ignored keeps ignoring it; this process's
    handler is restored as soon as the workers have started (from the main thread only)."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    old = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, old)


@contextlib.contextmanager
def environment_kept() -> Iterator[None]:
    """Restore ``os.environ`` at the end of the block: Dask's nanny writes its workers'
    variables (``OMP_NUM_THREADS=1``, the heap thresholds, ...) into the environment of the
    process that starts them, which a study must not leave behind in a program using it."""
    saved = dict(os.environ)
    try:
        yield
    finally:
        for key in [k for k in os.environ if k not in saved]:
            del os.environ[key]
        for key, value in saved.items():
            if os.environ.get(key) != value:
                os.environ[key] = value


@contextlib.contextmanager
def worker_allocator() -> Iterator[None]:
    """Dask's ``distributed.nanny.pre-spawn-environ`` with :data:`WORKER_MALLOC`, for the
    worker processes started inside the block (a variable set in the environment wins)."""
    import dask

    with dask.config.set({f"distributed.nanny.pre-spawn-environ.{k}": v
                          for k, v in WORKER_MALLOC.items()}):
        yield


def run_study(study: Study, folder: str | Path, *, scheduler: str | None = None,
              workers: int | None = None, resume: bool = False, progress=False,
              ) -> StudyRun:
    """Run the missing runs of ``study`` and gather ``folder``'s parts into the table.

    Parameters
    ----------
    study : Study
    folder : path
        Results folder (``parts/`` is appended to while runs finish).
    scheduler : str, optional
        Address of a running Dask scheduler (``tcp://host:8786``); default a local cluster.
    workers : int, optional
        Worker processes of the local cluster (default: one per core).
    resume : bool
        Continue a study whose folder holds runs already; without it such a folder is refused.
    progress : bool or callable
        True: a progress bar on stderr (runs done of the total, failed, the time left); a
        callable is called as ``progress(done, total)`` after every run.

    Returns
    -------
    StudyRun
        ``complete`` is False after an interruption (Ctrl-C); the table holds what finished.
    """
    require_dask()
    start = time.perf_counter()
    store = PartStore(Path(folder), study, resume=resume)
    done = store.done()
    runs = [r for r in design(study) if r[0] not in done]
    bar = _Progress(progress, study.n_runs, study.n_runs - len(runs), study.name)
    complete = False
    client = cluster = None
    kept = environment_kept()
    kept.__enter__()
    try:
        if scheduler and runs:
            # a scheduler that cannot be reached is found before any run
            client, cluster = _client(scheduler, workers)
        if runs and runs[0][0] == 0:
            # the first run in this process: a study whose options or outputs do not fit the
            # analysis is refused before any other run starts
            try:
                row = run_one(study, *runs[0], probe=True)
            except InputError as err:
                raise err.with_file(study.source) from None
            store.append([row])
            runs = runs[1:]
            bar.update(row["status"] != "ok")
        if runs:
            if client is None:
                client, cluster = _client(scheduler, workers)
            _dispatch(study, runs, store, client, bar)
        complete = True
    except KeyboardInterrupt:
        pass
    finally:
        bar.close()
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
        kept.__exit__(None, None, None)
    return StudyRun(study=study, table=store.read(), wall_time=time.perf_counter() - start,
                    folder=Path(folder), complete=complete)


class _Progress:
    """Runs done and failed: a tqdm bar on stderr (``progress=True``) with the count done of
    the total, the failed runs and the time left, or a ``progress(done, total)`` callback."""

    def __init__(self, progress, total: int, done: int, name: str):
        self.total, self.done, self.failed = total, done, 0
        self.callback = progress if callable(progress) else None
        self.bar = None
        if progress is True:
            from tqdm import tqdm
            self.bar = tqdm(total=total, initial=done, unit="run", file=sys.stderr,
                            dynamic_ncols=True, desc=name[:30], mininterval=0.5)

    def update(self, failed: bool) -> None:
        self.done += 1
        self.failed += bool(failed)
        if self.bar is not None:
            if self.failed:
                self.bar.set_postfix(failed=self.failed, refresh=False)
            self.bar.update(1)
        if self.callback is not None:
            self.callback(self.done, self.total)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


class BatchSize:
    """How many runs the next task gets.

    The first tasks take one run each; after that a batch is sized from the mean worker
    time per run measured so far to take about :data:`TASK_SECONDS`, and never more than an
    even share of the runs left between ``2 × workers`` tasks, so that the last tasks end
    together instead of one worker finishing a long batch alone.
    """

    def __init__(self, workers: int):
        self.workers = max(1, workers)
        self.runs = 0
        self.seconds = 0.0

    def record(self, runs: int, seconds: float) -> None:
        """A task of ``runs`` runs took ``seconds`` on its worker."""
        self.runs += runs
        self.seconds += max(seconds, 0.0)

    def next(self, remaining: int) -> int:
        """The size of the next batch when ``remaining`` runs are still to be submitted."""
        if remaining <= 0:
            return 0
        if self.runs == 0:
            return 1
        per_run = self.seconds / self.runs
        by_time = int(TASK_SECONDS / per_run) if per_run > 0 else remaining
        share = math.ceil(remaining / (2 * self.workers))
        return max(1, min(by_time, share, remaining))


def _workers(client) -> int:
    """Workers connected to the client's scheduler (at least 1: workers of a scheduler given
    by address may still be connecting)."""
    return max(1, len(client.scheduler_info().get("workers", {})))


def _lost_row(study: Study, run: tuple, exc: Exception) -> dict:
    """The row of a run whose worker processes died (Dask's ``KilledWorker``)."""
    return {"run_id": run[0], "grid_point": run[1], "sample": run[2], **run[3],
            **{o.name: math.nan for o in study.outputs}, "status": "error",
            "error": f"the worker processes running it died ({exc})"[:500]}


def _dispatch(study, runs, store, client, bar: _Progress) -> None:
    """Send ``runs`` to the cluster in batches (:class:`BatchSize`), a few tasks per worker
    queued at a time, and append the rows to ``store`` as tasks finish."""
    from collections import deque

    from dask.distributed import as_completed
    from distributed.scheduler import KilledWorker

    pending: list[dict] = []
    last = time.monotonic()
    queue = deque(runs)
    workers = _workers(client)
    size = BatchSize(workers)
    batches: dict[str, list] = {}
    try:
        [payload] = client.scatter([study], broadcast=True)
        finished = as_completed()

        def submit() -> None:
            batch = [queue.popleft() for _ in range(size.next(len(queue)))]
            fut = client.submit(run_batch, payload, batch, pure=False)
            batches[fut.key] = batch
            finished.add(fut)

        for _ in range(TASKS_PER_WORKER * workers):
            if queue:
                submit()
        for fut in finished:
            batch = batches.pop(fut.key)
            try:
                rows, seconds = fut.result()
                size.record(len(batch), seconds)
            except KilledWorker as exc:
                rows = [_lost_row(study, run, exc) for run in batch]
            fut.release()
            if queue:
                submit()
            for row in rows:
                pending.append(row)
                bar.update(row["status"] != "ok")
            if len(pending) >= FLUSH_ROWS or time.monotonic() - last >= FLUSH_SECONDS:
                store.append(pending)
                pending, last = [], time.monotonic()
    finally:
        store.append(pending)       # what finished is kept, also when interrupted


def write_results(run: StudyRun, folder: Path, *, plots: bool = True,
                  json_out: str | Path | None = None) -> dict:
    """``results.parquet``, ``study.json`` (and ``--json OUT``) and the plots in ``folder``,
    each written under a temporary name and renamed."""
    from ..io.output import atomic_path, write_json

    folder = Path(folder)
    with atomic_path(folder / "results.parquet") as tmp:
        run.table.to_parquet(tmp, index=False)
    doc = run.summary()
    if plots:
        from .plots import write_plots
        doc["plots"] = write_plots(run, folder)
    write_json(folder / "study.json", doc)
    if json_out is not None:
        write_json(json_out, doc)
    return doc


__all__ = ["PartStore", "StudyRun", "require_dask", "run_study", "schema", "worker_allocator",
           "write_results"]
