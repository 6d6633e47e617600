# SPDX-License-Identifier: MIT
"""The allocator tuning (trussfe.allocator) is idempotent, yields to the environment, and is
made by the command line only — each check in a child process, so the test process's own
allocator is never changed."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _run(code: str, env: dict | None = None) -> str:
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=env, check=True, cwd=str(ROOT))
    return out.stdout.strip()


def test_idempotent():
    """A second call returns the first call's answer without touching the allocator again."""
    code = ("from trussfe.allocator import tune_allocator as t; a = t(); "
            "print(t() is a, a in (True, False))")
    assert _run(code) == "True True"


def test_environment_wins():
    """When the environment sets a threshold, trussfe leaves the allocator alone (False)."""
    code = "from trussfe.allocator import tune_allocator; print(tune_allocator())"
    assert _run(code, env={"MALLOC_MMAP_THRESHOLD_": "1048576", "PATH": ""}) == "False"


def test_library_import_leaves_the_allocator_alone():
    """Importing trussfe and running an analysis does not tune the allocator; the command
    line's entry point does."""
    code = ("import trussfe.allocator as a, trussfe, trussfe.fem; "
            "from trussfe.models import double_octahedral_chain; "
            "trussfe.fem.solve_static(double_octahedral_chain(3)); print(a._state)")
    assert _run(code) == "None"


_ARENAS = """
import ctypes, ctypes.util, os, sys, tempfile, threading
import numpy as np
if sys.argv[1] == "tuned":
    from trussfe.allocator import tune_allocator
    tune_allocator()
def work():
    for _ in range(20):
        a = np.ones(200_000); b = a * 2.0; del a, b
threads = [threading.Thread(target=work) for _ in range(3)]
for t in threads: t.start()
for t in threads: t.join()
libc = ctypes.CDLL(ctypes.util.find_library("c"))
libc.fopen.restype = ctypes.c_void_p
libc.fopen.argtypes = [ctypes.c_char_p, ctypes.c_char_p]
libc.malloc_info.argtypes = [ctypes.c_int, ctypes.c_void_p]
libc.fclose.argtypes = [ctypes.c_void_p]
path = os.path.join(tempfile.mkdtemp(), "info.xml")
f = libc.fopen(path.encode(), b"w"); libc.malloc_info(0, f); libc.fclose(f)
print(open(path).read().count("<heap nr="))
"""


def test_worker_threads_allocate_from_the_main_heap():
    """After the tuning, numpy arrays made in three threads come from one arena (glibc's
    malloc_info lists one heap); without it every thread gets an arena of its own."""
    import ctypes.util
    if not ctypes.util.find_library("c") or not hasattr(ctypes.CDLL(None), "malloc_info"):
        import pytest
        pytest.skip("not glibc")

    def heaps(mode):
        return int(subprocess.run([sys.executable, "-c", _ARENAS, mode], capture_output=True,
                                  text=True, check=True, cwd=str(ROOT)).stdout)
    assert heaps("tuned") == 1
    assert heaps("plain") > 1
