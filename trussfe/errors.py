# SPDX-License-Identifier: MIT
"""Exceptions with a one-line, user-facing message.

Every error a user can cause (bad input, an analysis that cannot be carried out) is raised as a
:class:`TrussfeError` subclass.  Its string form is ``"<item>: <what is wrong and what to do>"``;
the command line prints it as ``trussfe: error: <item>: ...`` and exits with status 2.
"""
from __future__ import annotations

#: Longest message printed; a longer one is cut (a huge id or value must not flood a terminal).
MAX_MESSAGE_CHARS = 2000


#: What a number out of range usually means (a modulus or length in another unit), for the
#: messages of overflows and of stiffnesses singular without a mechanism.
UNITS_ADVICE = ("check the units (SI: m, N, Pa, kg, s) and the magnitudes of loads, moduli, "
                "sections and lengths")


def one_line(text: str, limit: int = MAX_MESSAGE_CHARS) -> str:
    """``text`` with control characters escaped (``\\n``, ``\\t``, ``\\x1b``) and cut to
    ``limit`` characters, so that a message is always one line of a terminal's log.

    Examples
    --------
    >>> one_line("node 'A\\nB'")
    "node 'A\\\\nB'"
    """
    if text.isprintable() and len(text) <= limit:
        return text
    out = []
    for ch in text:
        if ch.isprintable():
            out.append(ch)
        else:
            esc = repr(ch)[1:-1]
            out.append(esc if esc != ch else f"\\u{ord(ch):04x}")
    s = "".join(out)
    if len(s) > limit:              # keep both ends: the item and what is wrong with it
        head = limit // 2
        tail = limit - head - 40
        s = f"{s[:head]} ... [{len(s) - head - tail} characters] ... {s[-tail:]}"
    return s


class TrussfeError(Exception):
    """Base class of every error that is reported to the user in one line.

    Parameters
    ----------
    item : str
        The file, table or item that is at fault, e.g. ``"model.toml: members.M3"``.
    message : str
        What is wrong and, where possible, what to do about it.
    """

    exit_status = 2

    def __init__(self, item: str, message: str):
        self.item = item
        self.message = message
        super().__init__(one_line(f"{item}: {message}" if item else message))

    def with_item(self, item: str) -> "TrussfeError":
        """Return a copy of the error (its type and attributes) naming ``item`` instead."""
        err = type(self).__new__(type(self))
        TrussfeError.__init__(err, item, self.message)
        for k, v in self.__dict__.items():
            if k not in ("item", "message", "args"):
                setattr(err, k, v)
        return err

    def with_file(self, filename: str) -> "TrussfeError":
        """Return a copy of the error whose item is prefixed with ``filename``."""
        return self.with_item(f"{filename}: {self.item}" if self.item else filename)

    def in_file(self, source: str | None) -> "TrussfeError":
        """:meth:`with_file` of ``source`` where there is one (a model read from a file), else
        the error itself."""
        return self.with_file(source) if source else self


class InputError(TrussfeError):
    """A model file, motion file or option that is malformed or inconsistent."""


class OutputError(TrussfeError):
    """A result file or folder that cannot be written (full disk, removed folder, ...)."""


class AnalysisError(TrussfeError):
    """An analysis that cannot be carried out on a valid model.

    Examples: a mechanism where a structure is required, lengths for which no assembly exists,
    an eigenproblem asked for more modes than there are degrees of freedom.
    """


class MechanismError(AnalysisError):
    """The structure is a mechanism where a stiff structure is required.

    Attributes
    ----------
    mechanisms : int
        Number of independent (infinitesimal) mechanisms found.
    moving_nodes : list of str
        Ids of the nodes that move in the mechanisms found.
    """

    def __init__(self, item: str, message: str, mechanisms: int = 0,
                 moving_nodes: list[str] | None = None):
        super().__init__(item, message)
        self.mechanisms = mechanisms
        self.moving_nodes = list(moving_nodes or [])
