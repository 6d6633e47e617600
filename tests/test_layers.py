# SPDX-License-Identifier: MIT
"""The package's import layers (pyproject.toml, ``[tool.importlinter]``): no import runs
upwards and no two packages import each other; docs/architecture.md draws the layers.

import-linter runs in a subprocess: it configures logging with ``disable_existing_loggers``,
which would silence trussfe's loggers for the rest of the test session."""
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

LINT = ("import sys; from importlinter.cli import lint_imports; "
        "sys.exit(lint_imports(config_filename=sys.argv[1], no_cache=True))")


def _lint(config: Path) -> subprocess.CompletedProcess:
    pytest.importorskip("importlinter.cli")
    return subprocess.run([sys.executable, "-c", LINT, str(config)], capture_output=True,
                          text=True, cwd=ROOT)


def test_import_layers_hold():
    r = _lint(ROOT / "pyproject.toml")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "0 broken" in r.stdout


def test_a_contract_that_cannot_hold_is_reported_broken(tmp_path):
    """The check can fail: the layers turned upside down are reported broken."""
    cfg = tmp_path / "upside_down.toml"
    cfg.write_text('[tool.importlinter]\nroot_package = "trussfe"\n'
                   '[[tool.importlinter.contracts]]\nname = "upside down"\ntype = "layers"\n'
                   'layers = ["trussfe.model", "trussfe.api"]\n')
    r = _lint(cfg)
    assert r.returncode != 0 and "broken" in r.stdout, r.stdout + r.stderr
