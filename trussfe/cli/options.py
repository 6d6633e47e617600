# SPDX-License-Identifier: MIT
"""Types of the command-line options: every value is checked when the line is parsed.

Each function below is an argparse ``type=``: it turns the text of one option into its value
or raises :class:`argparse.ArgumentTypeError` with what is wrong, which the parser prints as
``trussfe: error: --OPTION: <what is wrong>`` (exit status 2) before any model is read or any
analysis starts.  Output paths are checked the same way, so a run never computes for minutes
and then finds that it cannot write its result.
"""
from __future__ import annotations

import argparse
import math
import os
import stat
import tempfile
from pathlib import Path
from typing import Callable

from ..api.options import number_problem

#: Longest text an option value may have (a path or a number); longer is a pasting accident.
MAX_OPTION_CHARS = 4096


def _text(value: str) -> str:
    if len(value) > MAX_OPTION_CHARS:
        raise argparse.ArgumentTypeError(f"value of {len(value)} characters is too long")
    return value


def _show(value: str) -> str:
    """The value as typed, quoted, short and on one line."""
    v = value if len(value) <= 40 else value[:37] + "..."
    return repr(v)


def integer(lo: int | None = None, hi: int | None = None, what: str = "an integer"
            ) -> Callable[[str], int]:
    """An integer option in ``[lo, hi]`` (either bound may be open)."""

    def parse(value: str) -> int:
        _text(value)
        try:
            x = int(value)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected {what}, got {_show(value)}") from None
        if (lo is not None and x < lo) or (hi is not None and x > hi):
            rng = ("a positive integer" if (lo, hi) == (1, None) else "0 or more" if (lo, hi) == (
                0, None) else f"at least {lo}" if hi is None else f"at most {hi}" if lo is None
                   else f"from {lo} to {hi}")
            raise argparse.ArgumentTypeError(f"must be {rng}, got {x}")
        return x

    parse.__name__ = "integer"
    return parse


#: A count of things: 1, 2, 3, ...
positive_int = integer(1, what="a positive integer")
#: 0, 1, 2, ...
nonneg_int = integer(0, what="an integer (0 or more)")


def real(*, positive: bool = False, nonneg: bool = False, nonzero: bool = False,
         below: float | None = None, what: str = "a number") -> Callable[[str], float]:
    """A finite real option; ``positive``/``nonneg``/``nonzero`` and ``below`` restrict it."""

    def parse(value: str) -> float:
        _text(value)
        try:
            x = float(value)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected {what}, got {_show(value)}") from None
        problem = number_problem(x, positive=positive, nonneg=nonneg, nonzero=nonzero,
                                 below=below)
        if problem:
            # the value as typed: "got 1e400", not "got inf"
            shown = _show(value) if not math.isfinite(x) else value.strip()
            raise argparse.ArgumentTypeError(problem if x == 0.0 and nonzero
                                             else f"{problem}, got {shown}")
        return x

    parse.__name__ = "real"
    return parse


#: A length, time, step, factor that must be > 0.
positive_real = real(positive=True, what="a positive number")
#: A damping coefficient, amplitude or limit that may be 0.
nonneg_real = real(nonneg=True, what="a number (0 or more)")
#: Any finite number (a signed amplitude).
finite_real = real(what="a number")
#: A relative tolerance: 0 < tol < 1.
relative_tolerance = real(positive=True, below=1.0, what="a relative tolerance (0 < tol < 1)")
#: A signed, non-zero increment.
nonzero_real = real(nonzero=True, what="a non-zero number")


def _first_existing(path: Path) -> Path:
    """``path`` or its nearest ancestor that exists (missing folders are created on output)."""
    p = path
    while not os.path.lexists(p):
        if p.parent == p:
            break
        p = p.parent
    return p


def _probe_folder(folder: Path, value: str) -> None:
    """Create and remove a hidden file in ``folder``, where ``value`` (the path given) is to be
    written or its missing folders created: the only test a root user cannot fool."""
    try:
        fd, tmp = tempfile.mkstemp(prefix=".trussfe-probe.", dir=folder)
    except OSError as exc:
        where = "" if Path(value) in (folder, folder.resolve()) else f" (for '{value}')"
        raise argparse.ArgumentTypeError(f"cannot write in the folder '{folder}'{where}: "
                                         f"{exc.strerror or exc}") from None
    os.close(fd)
    os.unlink(tmp)


def _check_output(value: str, *, folder: bool) -> str:
    _text(value)
    if not value.strip():
        raise argparse.ArgumentTypeError("needs a path, got an empty string")
    if "\0" in value:
        raise argparse.ArgumentTypeError("the path contains a NUL character")
    path = Path(value)
    if os.path.lexists(path):
        try:
            st = os.stat(path)
        except OSError as exc:          # a dangling or looping symbolic link
            raise argparse.ArgumentTypeError(f"'{value}' cannot be used: "
                                             f"{exc.strerror or exc}") from None
        if folder and not stat.S_ISDIR(st.st_mode):
            raise argparse.ArgumentTypeError(f"'{value}' exists and is not a folder")
        if not folder and stat.S_ISDIR(st.st_mode):
            raise argparse.ArgumentTypeError(f"'{value}' is a folder; give a file name")
        if not folder and not stat.S_ISREG(st.st_mode):
            raise argparse.ArgumentTypeError(f"'{value}' is not a regular file (a device or "
                                             "pipe); give a file name")
    base = _first_existing(path.parent if not folder or not path.exists() else path)
    if not base.is_dir():
        raise argparse.ArgumentTypeError(f"'{base}' is not a folder, so '{value}' cannot be "
                                         "created")
    _probe_folder(base, value)
    return value


def output_file(value: str) -> str:
    """A file the run will write: not a folder, in a folder that exists or can be created and
    that accepts new files."""
    return _check_output(value, folder=False)


def output_dir(value: str) -> str:
    """A folder the run will write files into (created when missing)."""
    return _check_output(value, folder=True)


def input_file(value: str) -> str:
    """A file the run reads (model or motion): it must exist as a regular file."""
    _text(value)
    if not value.strip():
        raise argparse.ArgumentTypeError("needs a path, got an empty string")
    if "\0" in value:
        raise argparse.ArgumentTypeError("the path contains a NUL character")
    return value


def input_dir(value: str) -> str:
    """A folder the run reads."""
    _text(value)
    if not value.strip():
        raise argparse.ArgumentTypeError("needs a path, got an empty string")
    if not os.path.isdir(value):
        raise argparse.ArgumentTypeError(f"'{value}' is not a folder" if os.path.exists(value)
                                         else f"folder '{value}' not found")
    return value


#: Option destinations that name files or folders the run writes (for the checks that two
#: outputs, or an output and an input, are not the same file).
OUTPUT_OPTIONS = ("json", "vtk", "plot", "plots", "npz", "out", "png")
#: Option destinations that name files the run reads.
INPUT_OPTIONS = ("model", "motion", "cases", "results")


def check_paths(args: argparse.Namespace) -> str | None:
    """Return an error message when an output would overwrite an input or another output.

    Returns ``None`` when the paths are distinct.
    """
    def key(p: str) -> str:
        return os.path.realpath(p)

    seen: dict[str, str] = {}
    for name in INPUT_OPTIONS:
        v = getattr(args, name, None)
        if isinstance(v, str) and v:
            seen[key(v)] = "the model file" if name == "model" else f"--{name}"
    for name in OUTPUT_OPTIONS:
        v = getattr(args, name, None)
        if not isinstance(v, str) or not v:
            continue
        opt = f"--{name.replace('_', '-')}"
        k = key(v)
        if k in seen:
            return (f"{opt}: '{v}' is also {seen[k]}; writing it would overwrite it — "
                    "choose another name")
        seen[k] = opt
    return None
