# SPDX-License-Identifier: MIT
"""Atomic output: results are written to a temporary file and renamed into place.

A failed analysis or a crash therefore never leaves a half-written file behind.  Inside an
:func:`output_transaction` (the command line opens one per run) the renames wait until the
whole run has succeeded: a run that writes ``--json``, ``--vtk`` and ``--plot`` leaves all
three or none, and two runs writing the same outputs at once leave the complete set of one of
them (the renames of a run happen under an exclusive lock on the folders they go to).
"""
from __future__ import annotations

import contextlib
import contextvars
import fcntl
import json
import math
import os
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterator

import numpy as np

from ..errors import OutputError


@dataclass
class OutputTransaction:
    """The outputs of one run: temporary files and folders waiting to be renamed into place.

    Attributes
    ----------
    pending : list of (Path, Path, bool)
        ``(temporary, final, is_folder)`` in the order they were written.
    created : list of Path
        Folders created for the outputs (removed again, when empty, on :meth:`abort`).
    """

    pending: list[tuple[Path, Path, bool]] = field(default_factory=list)
    created: list[Path] = field(default_factory=list)
    #: Files the run reads (resolved path → what it is, e.g. "the model file"), which no
    #: output may replace.
    inputs: dict[str, str] = field(default_factory=dict)
    done: bool = False
    #: Refuse JSON results holding a non-finite number (see :func:`write_json`).
    finite_only: bool = True

    def make_parents(self, folder: Path) -> None:
        """Create ``folder`` and its missing ancestors, remembering which were new."""
        missing = []
        p = folder
        while not p.exists():
            missing.append(p)
            if p.parent == p:
                break
            p = p.parent
        folder.mkdir(parents=True, exist_ok=True)
        self.created += [m for m in reversed(missing) if m not in self.created]

    def read_from(self, path: str | Path, what: str) -> None:
        """Record that the run reads ``path`` (described as ``what``): no output may replace
        it."""
        self.inputs[os.path.realpath(path)] = what

    def _check_destinations(self) -> None:
        """Refuse, before anything is renamed, an output file that another output of the run
        or one of its inputs already is — a name given twice, a file inside an output
        folder, the ``_stations`` file beside a ``.vtu``: only the set of files to be
        written shows every such pair."""
        folders = {os.path.realpath(tmp): final for tmp, final, is_dir in self.pending if is_dir}
        waiting = {os.path.realpath(tmp) for tmp, _, _ in self.pending}

        def destination(path: Path) -> Path:
            # a file written into an output folder's temporary twin ends up in the folder
            real = os.path.realpath(path)
            for tmp, final in folders.items():
                if real.startswith(tmp + os.sep):
                    return final / os.path.relpath(real, tmp)
            return path

        seen: dict[str, str] = {}
        for tmp, final, is_dir in self.pending:
            if is_dir:
                files = [destination(f) for f in sorted(tmp.rglob("*"))
                         if f.is_file() and os.path.realpath(f) not in waiting]
                source = f" (in the folder '{final}')"
            else:
                files = [destination(final)]
                source = "" if files[0] is final else f" (in the folder '{files[0].parent}')"
            for path in files:
                key = os.path.realpath(path)
                if key in self.inputs:
                    raise OutputError(str(path), f"is also {self.inputs[key]}; writing it "
                                      "would overwrite it — choose another name")
                if key in seen:
                    raise OutputError(str(path), "would be written twice by this run"
                                      f"{seen[key] or source} — choose another name")
                seen[key] = source

    def commit(self) -> None:
        """Rename every output into place (under a lock on each destination folder)."""
        if self.done:
            return
        self._check_destinations()
        folders = sorted({str(final.parent.resolve()) for _, final, _ in self.pending})
        with contextlib.ExitStack() as stack:
            for folder in folders:
                stack.enter_context(_folder_lock(folder))
            for tmp, final, is_dir in self.pending:
                try:
                    if is_dir:
                        _merge_dir(tmp, final)
                    else:
                        os.replace(tmp, final)
                except OSError as exc:
                    raise OutputError(str(final), f"cannot write: {exc.strerror or exc}"
                                      ) from None
        self.done = True
        self.pending.clear()

    def abort(self) -> None:
        """Remove every temporary output and the folders made for them."""
        for tmp, _, is_dir in self.pending:
            if is_dir:
                shutil.rmtree(tmp, ignore_errors=True)
            else:
                with contextlib.suppress(OSError):
                    tmp.unlink()
        self.pending.clear()
        for folder in reversed(self.created):
            with contextlib.suppress(OSError):
                folder.rmdir()          # only when empty: another run may have used it
        self.created.clear()
        self.done = True


_TRANSACTION: contextvars.ContextVar[OutputTransaction | None] = contextvars.ContextVar(
    "trussfe_output_transaction", default=None)
# The scratch folder of the innermost scratch_files() block, None outside one.
_SCRATCH: contextvars.ContextVar[Path | None] = contextvars.ContextVar("trussfe_scratch",
                                                                      default=None)


@contextlib.contextmanager
def output_transaction() -> Iterator[OutputTransaction]:
    """Collect the outputs written inside the block; rename them all at its end.

    On an exception (including ``KeyboardInterrupt``) every temporary output is removed and
    nothing is renamed.  :meth:`OutputTransaction.commit` may be called inside the block (the
    command line does, with Ctrl-C held back); otherwise it runs when the block ends.
    """
    tx = OutputTransaction()
    token = _TRANSACTION.set(tx)
    try:
        yield tx
        tx.commit()
    except BaseException:
        tx.abort()
        raise
    finally:
        if not tx.done:
            tx.abort()
        _TRANSACTION.reset(token)


@contextlib.contextmanager
def scratch_files() -> Iterator[None]:
    """Files written inside the block are the program's own working files (a validation case's
    temporary model file, a study's figure read back at once), not outputs of the run: they
    are written at once, outside any :func:`output_transaction` around the block, and the
    folders :func:`working_folder` makes inside the block are removed when it ends."""
    token = _TRANSACTION.set(None)
    with tempfile.TemporaryDirectory(prefix="trussfe-scratch-") as folder:
        scratch = _SCRATCH.set(Path(folder))
        try:
            yield
        finally:
            _SCRATCH.reset(scratch)
            _TRANSACTION.reset(token)


def working_folder(prefix: str) -> Path:
    """A new empty folder for files a study writes and hands back by path (its figures).

    Inside :func:`scratch_files` the folder lies in the block's scratch folder and goes with
    it (the validation report reads the figures back and embeds them); called directly, the
    files are the caller's result and the folder stays in the system's temporary folder.
    """
    parent = _SCRATCH.get()
    return Path(tempfile.mkdtemp(prefix=prefix, dir=None if parent is None else parent))


@contextlib.contextmanager
def _folder_lock(folder: str) -> Iterator[None]:
    """An exclusive advisory lock on a folder (``flock`` of its descriptor)."""
    fd = os.open(folder, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)            # closing releases the lock


def _merge_dir(tmp: Path, path: Path) -> None:
    path.mkdir(parents=True, exist_ok=True)
    for item in sorted(tmp.rglob("*")):
        if item.is_file():
            dest = path / item.relative_to(tmp)
            dest.parent.mkdir(parents=True, exist_ok=True)
            os.replace(item, dest)
    shutil.rmtree(tmp, ignore_errors=True)


def _parents(path: Path) -> None:
    tx = _TRANSACTION.get()
    try:
        if tx is not None:
            tx.make_parents(path.parent)
        else:
            path.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(str(path), f"cannot create folder '{path.parent}': "
                                     f"{exc.strerror or exc}") from None


@contextlib.contextmanager
def atomic_path(path: str | Path) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; rename it to ``path`` on success.

    Inside an :func:`output_transaction` the rename waits for the end of the transaction.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> with atomic_path(d / "a.txt") as tmp:
    ...     _ = tmp.write_text("ok")
    >>> (d / "a.txt").read_text()
    'ok'
    """
    path = Path(path)
    _parents(path)
    try:
        fd, name = tempfile.mkstemp(prefix=f".{path.name}.", suffix=path.suffix or ".tmp",
                                    dir=path.parent)
    except OSError as exc:
        raise OutputError(str(path), f"cannot write: {exc.strerror or exc}") from None
    os.close(fd)
    tmp: Path | None = Path(name)
    try:
        try:
            yield tmp
            # mkstemp creates the file 0600; give the result the permissions of a normal file
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(tmp, 0o666 & ~umask)
            tx = _TRANSACTION.get()
            if tx is not None:
                tx.pending.append((tmp, path, False))
                tmp = None
            else:
                os.replace(tmp, path)
        except OSError as exc:
            raise OutputError(str(path), f"cannot write: {exc.strerror or exc}") from None
    finally:
        if tmp is not None and tmp.exists():
            tmp.unlink()


@contextlib.contextmanager
def atomic_dir(path: str | Path) -> Iterator[Path]:
    """Yield a temporary directory; on success its files are moved into ``path``.

    Files already in ``path`` that the new output does not overwrite are kept.  Inside an
    :func:`output_transaction` the move waits for the end of the transaction.
    """
    path = Path(path)
    _parents(path)
    try:
        tmp: Path | None = Path(tempfile.mkdtemp(prefix=f".{path.name}.", dir=path.parent))
    except OSError as exc:
        raise OutputError(str(path), f"cannot write: {exc.strerror or exc}") from None
    try:
        try:
            yield tmp
            tx = _TRANSACTION.get()
            if tx is not None:
                tx.pending.append((tmp, path, True))
                tmp = None
            else:
                _merge_dir(tmp, path)
        except OSError as exc:
            raise OutputError(str(path), f"cannot write: {exc.strerror or exc}") from None
    finally:
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)


def plain(obj: Any) -> Any:
    """A JSON-ready copy of ``obj``: dicts (keys as str), lists, str, int, bool, ``None`` and
    finite floats; numpy arrays and scalars converted, tuples as lists, non-finite floats as
    ``None`` (JSON has no NaN and a reader should see "no value").

    The exact built-in types are tested first: a large document is mostly floats, lists and
    dicts, and ``math.isfinite`` on a float is much cheaper than a numpy call.
    """
    t = type(obj)
    if t is float:
        return obj if math.isfinite(obj) else None
    if t is dict:
        return {k if type(k) is str else str(k): plain(v) for k, v in obj.items()}
    if t is list or t is tuple:
        return [plain(v) for v in obj]
    if t is str or t is int or t is bool or obj is None:
        return obj
    if isinstance(obj, dict):
        return {str(k): plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [plain(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return plain(obj.tolist())
    if isinstance(obj, (np.floating, float)):
        x = float(obj)
        return x if math.isfinite(x) else None
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, np.bool_):
        return bool(obj)
    return obj


#: Result keys whose value may be infinite or undefined by definition: the buckling margin of a
#: member never in compression, the singular value bounds of a rank decision with nothing kept
#: or dropped.  Written as ``null``.
NON_FINITE_ALLOWED = frozenset({"margin", "largest_dropped_singular_value",
                                "smallest_kept_singular_value", "yield_strength"})


def first_non_finite(obj: Any, path: str = "") -> tuple[str, float] | None:
    """The first number in ``obj`` (nested dicts, lists, arrays) that is not finite, as
    ``(dotted path, value)``, skipping the keys of :data:`NON_FINITE_ALLOWED`; else ``None``.

    Examples
    --------
    >>> first_non_finite({"members": {"M1": {"axial_force": [1.0, float("inf")]}}})
    ('members.M1.axial_force[1]', inf)
    >>> first_non_finite({"buckling": {"margin": float("inf")}}) is None
    True
    """
    if isinstance(obj, dict):
        for k, v in obj.items():
            if str(k) in NON_FINITE_ALLOWED:
                continue
            hit = first_non_finite(v, f"{path}.{k}" if path else str(k))
            if hit:
                return hit
        return None
    if isinstance(obj, np.ndarray):
        if obj.dtype.kind in "fc":
            bad = np.flatnonzero(~np.isfinite(obj.ravel()))
            if bad.size:
                return f"{path}[{int(bad[0])}]", float(obj.ravel()[bad[0]].real)
        return None
    if isinstance(obj, (list, tuple)):
        for i, v in enumerate(obj):
            if isinstance(v, (float, np.floating)):
                if not np.isfinite(v):
                    return f"{path}[{i}]", float(v)
            elif isinstance(v, (dict, list, tuple, np.ndarray)):
                hit = first_non_finite(v, f"{path}[{i}]")
                if hit:
                    return hit
        return None
    if isinstance(obj, (float, np.floating)) and not np.isfinite(obj):
        return path, float(obj)
    return None


def write_json(path: str | Path, data: dict) -> None:
    """Write ``data`` as JSON atomically (numpy arrays and scalars converted).

    Non-finite floats become ``null``: JSON has no NaN and a reader should see "no value".
    Inside an :func:`output_transaction` (a command-line run) a non-finite number outside the
    keys of :data:`NON_FINITE_ALLOWED` is refused instead: it means an overflow, almost always
    from inputs in the wrong units.
    """
    tx = _TRANSACTION.get()
    if tx is not None and tx.finite_only:
        hit = first_non_finite(data)
        if hit:
            from ..errors import UNITS_ADVICE, AnalysisError
            raise AnalysisError(f"result {hit[0]}", f"is {hit[1]}, not a finite number: a "
                                f"value overflowed; {UNITS_ADVICE}")
    with atomic_path(path) as tmp:
        tmp.write_text(json.dumps(plain(data), indent=1, allow_nan=False))
