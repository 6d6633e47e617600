# SPDX-License-Identifier: MIT
"""Command line: ``trussfe COMMAND MODEL [options]`` (docs/cli.md).

Each command lives in a module ``trussfe/cli/cmd_<name>.py`` that defines
``register(subparsers)``; the parser it adds sets ``func`` to a callable taking the parsed
arguments and returning the exit status.  Modules are discovered, so adding a command touches
no other file.
"""
from __future__ import annotations

import argparse
import contextlib
import importlib
import logging
import os
import pkgutil
import re
import signal
import sys
import threading
import warnings
from typing import Iterator

import numpy as np

from .._version import __version__
from ..allocator import tune_allocator
from ..api.numerics import failure_message
from ..errors import TrussfeError, one_line
from ..io.output import output_transaction
from ..io.toml_text import compiled_parser
from ..threads import compute_threads
from .options import INPUT_OPTIONS, check_paths



#: A word that is a negative number, as an option's value, not an option: argparse's own test
#: knows ``-3`` and ``-0.5`` only, and takes ``-1e-3`` (a signed ``trace --step``) or ``-inf``
#: for an unknown option ("expected one argument").  ``-inf`` and ``-nan`` reach the option's
#: type, which refuses them by name.
NEGATIVE_NUMBER = re.compile(r"^-(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?$|^-(?:inf|infinity|nan)$",
                             re.IGNORECASE)


class _Parser(argparse.ArgumentParser):
    """argparse with the contract's one-line error format and exit status 2."""

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = NEGATIVE_NUMBER

    def error(self, message: str) -> None:  # pragma: no cover - exercised via CLI tests
        # "argument --json: ..." -> "--json: ...": the option is the item at fault
        if message.startswith("argument "):
            message = message[len("argument "):]
        sys.stderr.write(f"trussfe: error: {one_line(message)}\n")
        raise SystemExit(2)


def command_names() -> list[str]:
    """The commands, one ``cmd_<name>`` module each (found without importing them)."""
    return sorted(i.name[4:] for i in pkgutil.iter_modules(__path__)
                  if i.name.startswith("cmd_"))


def _chosen_command(argv: list[str] | None, names: list[str]) -> str | None:
    """The command ``argv`` runs, when it names one: its first word that is not an option
    (the top-level options take no value)."""
    if argv is None:
        return None
    for word in argv:
        if word == "--version":
            return ""               # prints the version and stops: no command is needed
        if word == "--":
            return None
        if not word.startswith("-"):
            return word if word in names else None
    return None


def build_parser(argv: list[str] | None = None) -> argparse.ArgumentParser:
    """The ``trussfe`` argument parser.

    With ``argv`` naming a command, only that command's module is imported and fully
    registered (the others are bare names, which is all the parser needs from them): a
    command loads only the solver family it runs, which is most of the start-up time.
    Without it (or for ``--help``, a misspelt command, ...) every command is registered.
    """
    parser = _Parser(prog="trussfe", description="Structural analysis of adaptive trusses "
                     "and bar-and-joint mechanisms.")
    parser.add_argument("--version", action="version", version=f"trussfe {__version__}")
    parser.add_argument("-v", "--verbose", action="store_true", help="log progress to stderr")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    names = command_names()
    chosen = _chosen_command(argv, names)
    for name in names:
        if chosen is None or name == chosen:
            importlib.import_module(f"{__name__}.cmd_{name}").register(sub)
        else:
            sub.add_parser(name)
    return parser


@contextlib.contextmanager
def _numerics_checked() -> Iterator[list]:
    """Floating-point overflow, division by zero and invalid operations raise instead of
    printing a warning line; other library warnings are collected (logged with ``-v``).

    This is the command line's own setting for the duration of one run, restored after it;
    library code never changes warning filters.
    """
    with warnings.catch_warnings(record=True) as caught, \
            np.errstate(over="raise", divide="raise", invalid="raise", under="ignore"):
        warnings.simplefilter("always")
        for quiet in (DeprecationWarning, PendingDeprecationWarning, FutureWarning,
                      ImportWarning, ResourceWarning):
            warnings.simplefilter("ignore", quiet)
        warnings.simplefilter("error", RuntimeWarning)
        yield caught


@contextlib.contextmanager
def _interrupts_held() -> Iterator[None]:
    """Hold Ctrl-C back while the outputs are renamed into place (all or none)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def _error(item: str, message: str) -> None:
    sys.stderr.write("trussfe: error: " + one_line(f"{item}: {message}" if item else message)
                     + "\n")


def main(argv: list[str] | None = None) -> int:
    """Run the command line; returns the exit status.

    Exit status: 0 success, 1 a validation check failed, 2 bad input or an analysis that
    cannot be carried out (one line on stderr), 3 an internal fault, 130 interrupted (Ctrl-C).
    """
    tune_allocator()   # numpy temporaries reuse heap memory (trussfe.allocator): the command only
    try:
        words = sys.argv[1:] if argv is None else list(argv)
        parser = build_parser(words)
        args = parser.parse_args(words)
    except SystemExit as stop:      # --help, --version, or a bad option (message printed)
        return stop.code if isinstance(stop.code, int) else 2
    except KeyboardInterrupt:
        _error("", "interrupted")
        return 130
    clash = check_paths(args)
    if clash:
        _error("", clash)
        return 2
    # the run's own log handler on the "trussfe" logger (messages as "trussfe: ..." on the
    # stderr of this run), removed again afterwards: main() may run many times in a process
    # Without --verbose the warnings are held until the run ends and shown only when it
    # succeeds: a run that fails says so in one line, whatever it noticed on the way.
    log = logging.getLogger("trussfe")
    held = _HeldLines()
    handler = logging.StreamHandler(sys.stderr) if args.verbose else held
    handler.setFormatter(logging.Formatter("trussfe: %(message)s"))
    old_level = log.level
    log.setLevel(logging.INFO if args.verbose else logging.WARNING)
    log.addHandler(handler)
    status = 3
    try:
        status = _run_command(args)
        return status
    finally:
        log.removeHandler(handler)
        log.setLevel(old_level)
        if status not in FAILED and getattr(args, "show_warnings", True):
            held.write_to(sys.stderr)


#: Exit statuses of a run that did not complete (bad input, an internal fault, Ctrl-C, a
#: closed output pipe): its one error line stands alone.
FAILED = frozenset({2, 3, 130, 128 + signal.SIGPIPE})


class _HeldLines(logging.Handler):
    """A log handler that keeps the formatted lines of a run for :meth:`write_to`."""

    def __init__(self) -> None:
        super().__init__()
        self.lines: list[str] = []

    def emit(self, record: logging.LogRecord) -> None:
        self.lines.append(self.format(record))

    def write_to(self, stream) -> None:
        """Write the kept lines, each distinct one once (a model read twice in a run warns
        twice), and forget them."""
        with contextlib.suppress(OSError):
            for line in dict.fromkeys(self.lines):
                stream.write(line + "\n")
            stream.flush()
        self.lines.clear()


def _run_command(args: argparse.Namespace) -> int:
    """Run the parsed command inside one output transaction; map failures to exit codes."""
    where = getattr(args, "model", None) or ""
    try:
        # the one place thread counts are set (trussfe.threads): workers from the
        # environment, one BLAS thread; large model files through the compiled TOML parser
        # (trussfe.io.toml_text)
        with _numerics_checked() as caught, output_transaction() as tx, \
                compute_threads(workers=environment_workers(), blas=1), compiled_parser():
            for name in INPUT_OPTIONS:
                value = getattr(args, name, None)
                if isinstance(value, str) and value:
                    tx.read_from(value, "the model file" if name == "model" else f"--{name}")
            status = int(args.func(args) or 0)
            sys.stdout.flush()          # a closed pipe is found here, before the commit
            with _interrupts_held():
                tx.commit()
        for w in caught:
            logging.getLogger("trussfe").info("note: %s", one_line(str(w.message)))
        return status
    except TrussfeError as err:
        sys.stderr.write(f"trussfe: error: {one_line(str(err))}\n")
        return err.exit_status
    except KeyboardInterrupt:
        _error("", "interrupted; no output written")
        return 130
    except (FloatingPointError, OverflowError, RuntimeWarning, np.linalg.LinAlgError) as exc:
        _error(where, failure_message(exc))
        return 2
    except MemoryError:
        _error(where, "out of memory: the analysis needs more memory than this machine has; "
                      "use a coarser model or fewer steps")
        return 2
    except RecursionError:
        _error(where, "the input nests too deeply to be processed")
        return 2
    except BrokenPipeError:
        # the reader of stdout went away (`trussfe ... | head`): nothing left to tell it
        with contextlib.suppress(OSError):
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 128 + signal.SIGPIPE
    except OSError as exc:
        # the machine refused a file operation (permissions, a vanished folder, a full disk)
        _error(str(exc.filename or where), exc.strerror or str(exc))
        return 2
    except Exception as exc:  # an internal fault: one line, traceback only on request
        if os.environ.get("TRUSSFE_DEBUG"):
            raise
        _error("", f"internal error ({type(exc).__name__}: {one_line(str(exc), 300)}); "
                   "rerun with TRUSSFE_DEBUG=1 for a traceback")
        return 3


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
    try:
        status = main()
    except KeyboardInterrupt:       # Ctrl-C between two of main's own handlers
        _error("", "interrupted; no output written")
        status = 130
    if status == 130:
        _exit_interrupted()
    sys.exit(status)


def _exit_interrupted() -> None:
    """End an interrupted command with exit status 130, now.

    CPython remembers a Ctrl-C that arrived while it ran code compiled from a string (the
    methods dataclasses and named tuples write for themselves, as a module that is imported
    on first use defines them) even when the interrupt was handled, and then ends the
    process by SIGINT at exit instead of with the status given to ``sys.exit``.  The output
    transaction has already removed this run's files, so the buffered streams are flushed and
    the process ends without the interpreter's shutdown.
    """
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            stream.flush()
    os._exit(130)
