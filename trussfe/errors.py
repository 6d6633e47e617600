# SPDX-License-Identifier: MIT
"""Exceptions with a one-line, user-facing message.

Every error a user can cause (bad input, an analysis that cannot be carried out) is raised as a
:class:`TrussfeError` subclass.  Its string form is ``"<item>: <what is wrong and what to do>"``;
the command line prints it as ``trussfe: error: <item>: ...`` and exits with status 2.
"""
from __future__ import annotations


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
        super().__init__(f"{item}: {message}" if item else message)

    def with_file(self, filename: str) -> "TrussfeError":
        """Return a copy of the error whose item is prefixed with ``filename``."""
        item = f"{filename}: {self.item}" if self.item else filename
        err = type(self).__new__(type(self))
        TrussfeError.__init__(err, item, self.message)
        for k, v in self.__dict__.items():
            if k not in ("item", "message", "args"):
                setattr(err, k, v)
        return err


class InputError(TrussfeError):
    """A model file, motion file or option that is malformed or inconsistent."""


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
