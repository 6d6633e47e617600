# SPDX-License-Identifier: MIT
"""Worker threads for independent blocks of array work, and the one place thread counts are
set.

numpy releases the GIL inside its array loops and LAPACK calls, so blocks of time steps that
do not depend on each other (the force stage of a long motion, the stacked inverses of the
compatibility blocks) run in parallel in plain threads, with bit-identical results: every
block is computed exactly as it would be alone.

Thread counts are arguments, never set by library functions:

* :func:`parallel_map` takes ``workers``; without it, the count given to the enclosing
  :func:`compute_threads`, else the usable cores (at most :data:`MAX_THREADS`);
* :func:`compute_threads` is the boundary: the command line wraps every command in it (its
  ``TRUSSFE_THREADS`` sets the workers), and a program using trussfe as a library may do the
  same.  It also limits BLAS to ``blas`` threads (one by default), once, in the calling thread
  before any worker starts, and lifts the limit when the context ends — the BLAS libraries
  keep one process-wide count, which OpenBLAS lets only the thread that set it restore, so
  the limit cannot be applied inside functions that run in worker threads.  One BLAS thread
  is what the solvers want: the band routines work on blocks of ~17 × 17, where BLAS threads
  are 3–7x slower, the Lanczos vectors are level-1 BLAS, and trussfe's own workers take the
  independent blocks.
"""
from __future__ import annotations

import contextvars
import os
import threading
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from contextlib import contextmanager
from typing import Callable, Iterable, TypeVar

import numpy as np
from threadpoolctl import ThreadpoolController

T = TypeVar("T")
R = TypeVar("R")

#: Default upper limit on worker threads (the blocks are memory-bound beyond a few).
MAX_THREADS = 4

#: Worker count of the enclosing :func:`compute_threads` (None: the default).
_WORKERS: contextvars.ContextVar[int | None] = contextvars.ContextVar("trussfe_workers",
                                                                     default=None)
#: Threads of the enclosing :func:`compute_threads` and their number (None outside one, and
#: inside the calls its threads run).
_POOL: contextvars.ContextVar[tuple[ThreadPoolExecutor, int] | None] = contextvars.ContextVar(
    "trussfe_pool", default=None)


def default_worker_count() -> int:
    """The usable cores, at most :data:`MAX_THREADS`.

    Examples
    --------
    >>> 1 <= default_worker_count() <= MAX_THREADS
    True
    """
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:                                    # not Linux
        cores = os.cpu_count() or 1
    return max(1, min(MAX_THREADS, cores))


def worker_count(workers: int | None = None) -> int:
    """Number of worker threads: ``workers`` if given, else the enclosing
    :func:`compute_threads`'s, else :func:`default_worker_count`.

    Examples
    --------
    >>> worker_count(3)
    3
    >>> with compute_threads(workers=2, blas=None):
    ...     worker_count()
    2
    """
    if workers is None:
        workers = _WORKERS.get()
    return max(1, int(workers)) if workers is not None else default_worker_count()


def contiguous_spans(n: int, parts: int) -> list[tuple[int, int]]:
    """``parts`` contiguous ``(start, stop)`` ranges of nearly equal length covering
    ``range(n)`` (one range when ``parts`` < 2): the pieces of independent steps that worker
    threads take.

    Examples
    --------
    >>> contiguous_spans(10, 3)
    [(0, 3), (3, 6), (6, 10)]
    """
    cuts = np.linspace(0, n, max(parts, 1) + 1).astype(np.int64)
    return [(int(a), int(b)) for a, b in zip(cuts[:-1], cuts[1:])]


def block_steps(n: int, largest: int, workers: int | None = None) -> int:
    """Steps per block when ``n`` independent steps are cut into blocks of at most
    ``largest`` steps for the worker threads: as many blocks as a multiple of the threads, of
    nearly equal size, so that no thread is left with a long tail (10,000 steps in blocks of
    at most 7,281 on two threads: 2 × 5,000, not 7,281 + 2,719).

    Examples
    --------
    >>> block_steps(10_000, 7_281, workers=2), block_steps(10_000, 7_281, workers=1)
    (5000, 7281)
    """
    step = max(1, largest)
    workers = worker_count(workers)
    if workers > 1 and n > step:
        blocks = -(-n // step)
        blocks = -(-blocks // workers) * workers
        step = -(-n // blocks)
    return step


def parallel_map(fn: Callable[[T], R], items: Iterable[T],
                 workers: int | None = None) -> list[R]:
    """``[fn(x) for x in items]`` on :func:`worker_count` threads, results in order.

    Each call runs in a copy of the caller's context, so a nested :func:`parallel_map` sees
    the same worker count.  Inside :func:`compute_threads` the calls run on the calling
    thread and the context's threads, started once for the whole computation (starting
    threads for every map cost a quarter of a millisecond each time, a few per cent of an
    analysis that maps many small blocks), all taking the items from one queue; a
    :func:`parallel_map` nested in one of those calls starts threads of its own, so that it
    never waits for the threads it runs on.

    Examples
    --------
    >>> parallel_map(lambda x: x * x, range(5), workers=2)
    [0, 1, 4, 9, 16]
    """
    items = list(items)
    count = worker_count(workers)
    n = min(count, len(items))
    if n <= 1:
        return [fn(x) for x in items]
    contexts = [contextvars.copy_context() for _ in items]   # one per call: not shared
    shared = _POOL.get()
    if shared is not None and shared[1] == count:
        return _shared_map(shared[0], n, fn, items, contexts)
    with ThreadPoolExecutor(max_workers=n) as pool:
        return list(pool.map(lambda cx: cx[0].run(fn, cx[1]), zip(contexts, items)))


def _shared_map(pool: ThreadPoolExecutor, n: int, fn: Callable[[T], R], items: list,
                contexts: list) -> list[R]:
    """:func:`parallel_map` on the threads of :func:`compute_threads`: the calling thread and
    ``n − 1`` of the pool's take the items one after another from one queue (the caller
    works instead of waiting: one thread fewer to wake for every map, and never more
    threads computing than the workers); results in order.

    After a failure no further item is taken; the items taken before it finish, and the
    exception of the first failing item in the items' order is raised (every item before it
    was taken before it, so that is the same item whatever the timing) — or an interrupt
    (``KeyboardInterrupt``, ``SystemExit``) if one ended an item."""
    results: list = [None] * len(items)
    errors: list = [None] * len(items)
    queue = iter(range(len(items)))
    lock = threading.Lock()
    failed = threading.Event()

    def run() -> None:
        while True:
            with lock:
                i = None if failed.is_set() else next(queue, None)
            if i is None:
                return
            try:
                results[i] = contexts[i].run(_in_pool, fn, items[i])
            except BaseException as exc:                # re-raised in the caller below
                errors[i] = exc
                failed.set()
    helpers = [pool.submit(run) for _ in range(n - 1)]
    run()
    for h in helpers:
        h.result()
    raised = [exc for exc in errors if exc is not None]
    if raised:
        # an interrupt or exit first, else the first failing item's error
        raise next((exc for exc in raised if not isinstance(exc, Exception)), raised[0])
    return results


def _in_pool(fn: Callable[[T], R], x: T) -> R:
    """``fn(x)`` on a thread of the shared pool, in the call's own copy of the context, where
    the pool is not offered again (a nested map starts its own threads)."""
    _POOL.set(None)
    return fn(x)


@contextmanager
def compute_threads(workers: int | None = None, blas: int | None = 1) -> Iterator[None]:
    """Thread counts for the computations inside the context (see the module notes).

    Parameters
    ----------
    workers : int, optional
        Worker threads of :func:`parallel_map` (default: the usable cores, at most 4).
    blas : int or None
        Threads of the OpenBLAS (or BLIS) libraries of numpy and scipy; None leaves them
        alone.  MKL, loaded for PARDISO, keeps its own threads: PARDISO's factorisation is
        parallel at the level of the elimination tree, where threads pay.

    Examples
    --------
    >>> from threadpoolctl import threadpool_info
    >>> with compute_threads(blas=1):
    ...     {p["num_threads"] for p in threadpool_info() if p["internal_api"] == "openblas"}
    {1}
    """
    token = _WORKERS.set(workers)
    count = worker_count(workers)
    # the workers of every parallel_map inside, started on first use and ended with the
    # context (nothing outlives it)
    # (the thread that calls a map works too: count − 1 threads beside it)
    pool = ThreadPoolExecutor(max_workers=count - 1, thread_name_prefix="trussfe") \
        if count > 1 else None
    pool_token = _POOL.set(None if pool is None else (pool, count))
    try:
        if blas is None:
            yield
        else:
            # OpenBLAS and BLIS (what numpy and scipy ship with); MKL, which PARDISO loads,
            # keeps its own threads for its parallel factorisation
            libs = ThreadpoolController().select(internal_api=["openblas", "blis"])
            with libs.limit(limits=int(blas)):
                yield
    finally:
        _POOL.reset(pool_token)
        if pool is not None:
            pool.shutdown(wait=True)
        _WORKERS.reset(token)
