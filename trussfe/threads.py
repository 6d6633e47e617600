# SPDX-License-Identifier: MIT
"""Worker threads for independent blocks of array work.

numpy releases the GIL inside its array loops and LAPACK calls, so blocks of time steps that
do not depend on each other (the force stage of a long motion, the stacked inverses of the
compatibility blocks) run in parallel in plain threads, with bit-identical results: every
block is computed exactly as it would be alone.  ``TRUSSFE_THREADS`` sets the number of
threads (1 turns this off); the default is the number of usable cores, at most 4.
"""
from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor
from typing import Callable, Iterable, TypeVar

T = TypeVar("T")
R = TypeVar("R")

#: Default upper limit on worker threads (the blocks are memory-bound beyond a few).
MAX_THREADS = 4


def worker_count() -> int:
    """Number of worker threads: ``TRUSSFE_THREADS`` if set, else the usable cores (≤ 4).

    Examples
    --------
    >>> worker_count() >= 1
    True
    """
    env = os.environ.get("TRUSSFE_THREADS", "").strip()
    if env:
        try:
            return max(1, int(env))
        except ValueError:
            pass
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:                                    # not Linux
        cores = os.cpu_count() or 1
    return max(1, min(MAX_THREADS, cores))


def parallel_map(fn: Callable[[T], R], items: Iterable[T]) -> list[R]:
    """``[fn(x) for x in items]`` on :func:`worker_count` threads, results in order.

    Examples
    --------
    >>> parallel_map(lambda x: x * x, range(5))
    [0, 1, 4, 9, 16]
    """
    items = list(items)
    n = min(worker_count(), len(items))
    if n <= 1:
        return [fn(x) for x in items]
    with ThreadPoolExecutor(max_workers=n) as pool:
        return list(pool.map(fn, items))
