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
