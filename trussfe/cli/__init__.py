# SPDX-License-Identifier: MIT
"""Command line: ``trussfe COMMAND MODEL [options]`` (docs/cli.md).

Each command lives in a module ``trussfe/cli/cmd_<name>.py`` that defines
``register(subparsers)``; the parser it adds sets ``func`` to a callable taking the parsed
arguments and returning the exit status.  Modules are discovered, so adding a command touches
no other file.
"""
from __future__ import annotations

import argparse
import importlib
import logging
import os
import pkgutil
import sys
from collections.abc import Iterator
from contextlib import contextmanager

from .. import __version__
from ..errors import TrussfeError
from ..io.toml_text import compiled_parser
from ..threads import compute_threads


class _Parser(argparse.ArgumentParser):
    """argparse with the contract's one-line error format and exit status 2."""

    def error(self, message: str) -> None:  # pragma: no cover - exercised via CLI tests
        sys.stderr.write(f"trussfe: error: {message}\n")
        raise SystemExit(2)


def build_parser() -> argparse.ArgumentParser:
    """The ``trussfe`` argument parser with every discovered command."""
    parser = _Parser(prog="trussfe", description="Structural analysis of adaptive trusses "
                     "and bar-and-joint mechanisms.")
    parser.add_argument("--version", action="version", version=f"trussfe {__version__}")
    parser.add_argument("-v", "--verbose", action="store_true", help="log progress to stderr")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda i: i.name):
        if info.name.startswith("cmd_"):
            module = importlib.import_module(f"{__name__}.{info.name}")
            module.register(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Run the command line; returns the exit status."""
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        # the one place thread counts are set (trussfe.threads): workers from the
        # environment, one BLAS thread; large model files through the compiled TOML parser
        # (trussfe.io.toml_text); all of it, and the log output, only for this run
        with _run_logging(args.verbose), \
                compute_threads(workers=environment_workers(), blas=1), compiled_parser():
            return int(args.func(args) or 0)
    except TrussfeError as err:
        sys.stderr.write(f"trussfe: error: {err}\n")
        return err.exit_status
    except KeyboardInterrupt:
        sys.stderr.write("trussfe: error: interrupted\n")
        return 130
    except Exception as exc:  # an internal fault: one line, traceback only on request
        if os.environ.get("TRUSSFE_DEBUG"):
            raise
        sys.stderr.write(f"trussfe: error: internal error ({type(exc).__name__}: {exc}); "
                         "rerun with TRUSSFE_DEBUG=1 for a traceback\n")
        return 3


@contextmanager
def _run_logging(verbose: bool) -> Iterator[None]:
    """Log records to stderr as ``trussfe: message`` (INFO with ``--verbose``, else WARNING)
    for the duration of one run.

    As :func:`logging.basicConfig`, but undone at the end: a program that calls :func:`main`
    keeps its logging as it was.  A program that has configured logging (a root handler)
    keeps its own handlers and levels, as basicConfig would leave them.
    """
    root = logging.getLogger()
    if root.handlers:
        yield
        return
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(logging.Formatter("trussfe: %(message)s"))
    level = root.level
    root.addHandler(handler)
    root.setLevel(logging.INFO if verbose else logging.WARNING)
    try:
        yield
    finally:
        root.removeHandler(handler)
        root.setLevel(level)
        handler.close()


def environment_workers() -> int | None:
    """``TRUSSFE_THREADS`` (a positive integer) or None (the default count); anything else
    is ignored, as an unset variable."""
    env = os.environ.get("TRUSSFE_THREADS", "").strip()
    try:
        return max(1, int(env)) if env else None
    except ValueError:
        return None


def run() -> None:
    """Console-script entry point."""
    sys.exit(main())
