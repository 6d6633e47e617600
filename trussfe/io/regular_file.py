# SPDX-License-Identifier: MIT
"""Reading an input file that must be a regular file of a bounded size.

:func:`trussfe.budget.check_input_file` refuses a folder, a device (``/dev/zero`` never
ends), a socket or a named pipe (which blocks its reader forever) and a file too large to
parse, from the path's status.  :func:`read_regular_file` makes the same checks and then
reads the file so that the checks still hold for what is read: the file is opened without
blocking, its descriptor is checked again (the path may have been replaced in between) and
no more than the largest accepted size is read.
"""
from __future__ import annotations

import os
import stat
import tomllib

from ..budget import MAX_INPUT_BYTES, check_input_file, format_bytes
from ..errors import InputError


def read_regular_file(path: str | os.PathLike, what: str = "file") -> bytes:
    """The bytes of ``path``, refused unless it is a regular file of an accepted size.

    Parameters
    ----------
    path : str or path-like
        The file; a symbolic link to a regular file is accepted.
    what : str
        What the file is, for the messages (``"study file"``, ``"case file"``).

    Returns
    -------
    bytes
        The file's contents.

    Raises
    ------
    InputError
        Naming the path: missing, unreadable, a folder, a device, socket or named pipe, or
        larger than :data:`trussfe.budget.MAX_INPUT_BYTES` or than the memory its parsed form
        would take.
    """
    name = os.fspath(path)
    check_input_file(name, what)
    # O_NONBLOCK: a named pipe put in the file's place after the check must not block open()
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
    try:
        fd = os.open(name, flags)
    except FileNotFoundError:
        raise InputError(name, f"{what} not found") from None
    except OSError as exc:
        raise InputError(name, f"cannot read {what}: {exc.strerror or exc}") from None
    with os.fdopen(fd, "rb") as f:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise InputError(name, f"is not a regular file; the {what} must be a regular file")
        try:
            # one byte more than accepted tells a file that grew after the check
            data = f.read(MAX_INPUT_BYTES + 1)
        except OSError as exc:
            raise InputError(name, f"cannot read {what}: {exc.strerror or exc}") from None
    if len(data) > MAX_INPUT_BYTES:
        raise InputError(name, f"is more than the {format_bytes(MAX_INPUT_BYTES)} a {what} "
                               "may have")
    return data


def read_toml_file(path: str | os.PathLike, what: str = "file") -> dict:
    """The tables of a TOML input file, read by :func:`read_regular_file`.

    Parameters
    ----------
    path : str or path-like
    what : str
        What the file is, for the messages (``"study file"``, ``"case file"``).

    Raises
    ------
    InputError
        Naming the path: not a regular file of an accepted size, not UTF-8, malformed TOML,
        or nested too deeply to parse.
    """
    name = os.fspath(path)
    try:
        return tomllib.loads(read_regular_file(name, what).decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise InputError(name, f"cannot read the {what}: {exc}") from None
    except tomllib.TOMLDecodeError as exc:
        raise InputError(name, f"malformed TOML: {exc}") from None
    except RecursionError:
        raise InputError(name, f"the {what} nests too deeply") from None
