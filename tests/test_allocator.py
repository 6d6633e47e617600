# SPDX-License-Identifier: MIT
"""The allocator tuning (trussfe.allocator) is safe to call and idempotent."""
from __future__ import annotations

import subprocess
import sys

from trussfe import allocator


def test_idempotent():
    """A second call returns the first call's answer without touching the allocator again."""
    first = allocator.tune_allocator()
    assert allocator.tune_allocator() is first


def test_environment_wins():
    """When the environment sets a threshold, trussfe leaves the allocator alone (False)."""
    code = "from trussfe.allocator import tune_allocator; print(tune_allocator())"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env={"MALLOC_MMAP_THRESHOLD_": "1048576", "PATH": ""}, check=True,
                         cwd=str(__import__("pathlib").Path(__file__).resolve().parents[1]))
    assert out.stdout.strip() == "False"
