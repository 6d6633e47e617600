# SPDX-License-Identifier: MIT
"""Keep numpy's large temporaries on the heap instead of fresh memory pages.

glibc's ``malloc`` serves every block above its *mmap threshold* (128 KiB to start, raised
dynamically up to 32 MiB) with a new ``mmap`` and returns it to the system on ``free``.  A
vectorised solver makes many temporaries of a few MB (one vector of a 180k-DOF model is
1.4 MB), and each one then costs a page fault per 4 KiB page on first touch.  On virtual
machines a page fault is expensive: an ``axpy`` of 180k doubles with a temporary takes
2.4 ms here against 0.34 ms once the memory is reused — the arithmetic is the small part.

:func:`tune_allocator` raises the mmap threshold to 512 MiB and the trim threshold to 1 GiB
(``mallopt``; 32 MiB where glibc refuses more), so freed blocks stay in the heap and are
reused, and keeps worker threads on that heap (one arena, ``M_ARENA_MAX`` = 1): a thread's
own arena is a heap of at most 64 MiB that glibc maps afresh as it fills and unmaps as it
empties (measured on the 100-bay chain with two worker threads: 37,000–100,000 page faults
and 0.3–0.8 s of system time per analysis with arenas per thread, a few hundred to a few
thousand faults and 0.05 s with one).  Only the ``trussfe`` command calls it, at start-up
(:func:`trussfe.cli.main`); library code never changes the allocator.  A program using
trussfe as a library may call it itself, or set the same limits through the environment
before Python starts (``MALLOC_MMAP_THRESHOLD_=536870912 MALLOC_TRIM_THRESHOLD_=1073741824
MALLOC_ARENA_MAX=1``).  The price is that up to 1 GiB of freed memory stays with the process
until it exits.  It does nothing where the C library is not glibc, or when the environment
already sets either threshold (an environment's ``MALLOC_ARENA_MAX`` stands too).
"""
from __future__ import annotations

import ctypes
import ctypes.util
import logging
import os

log = logging.getLogger(__name__)

#: ``mallopt`` parameter numbers (glibc ``malloc.h``).
_M_TRIM_THRESHOLD = -1
_M_MMAP_THRESHOLD = -3
_M_ARENA_MAX = -8

#: Blocks up to this size are served from the heap.
MMAP_THRESHOLD = 512 * 2**20
#: Free memory at the top of the heap kept rather than returned to the system.
TRIM_THRESHOLD = 2**30

_state: bool | None = None


def tune_allocator() -> bool:
    """Raise glibc's mmap and trim thresholds once per process.

    Returns
    -------
    bool
        True when the thresholds are (now) raised, False where this does not apply (not
        glibc, or the environment sets them: then the environment's values stand).

    """
    global _state
    if _state is None:
        _state = _apply()
    return _state


def _apply() -> bool:
    if os.environ.get("MALLOC_MMAP_THRESHOLD_") or os.environ.get("MALLOC_TRIM_THRESHOLD_"):
        return False
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        mallopt = libc.mallopt
    except (OSError, AttributeError):    # not glibc (musl, macOS, Windows)
        return False
    mallopt.argtypes, mallopt.restype = [ctypes.c_int, ctypes.c_int], ctypes.c_int
    # glibc before 2.35 refuses mmap thresholds above 32 MiB: fall back on that
    for threshold in (MMAP_THRESHOLD, 32 * 2**20):
        if mallopt(_M_MMAP_THRESHOLD, threshold):
            break
    else:
        return False
    ok = bool(mallopt(_M_TRIM_THRESHOLD, TRIM_THRESHOLD))
    # Worker threads would otherwise allocate from arenas of their own, heaps of at most
    # 64 MiB that glibc maps and unmaps as they fill and empty — fresh pages again for every
    # block of steps; one arena keeps every thread on the main heap, whose freed memory the
    # thresholds above keep.
    if not os.environ.get("MALLOC_ARENA_MAX"):
        mallopt(_M_ARENA_MAX, 1)
    log.debug("allocator: mmap threshold %d, trim threshold %d (%s)", threshold,
              TRIM_THRESHOLD, "set" if ok else "refused")
    return ok
