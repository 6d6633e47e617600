# SPDX-License-Identifier: MIT
"""The keys every JSON result document starts with (docs/json.md, "Conventions")."""
from __future__ import annotations

from typing import Any

#: The unit system of every number in a result document.
UNITS = "SI"


def result_json(command: str, model: str, **items: Any) -> dict[str, Any]:
    """A result document: ``units``, ``command`` and ``model`` first, then ``items`` in order.

    Parameters
    ----------
    command : str
        The command (and Python function) that made the result: ``"static"``, ``"modes"``, ...
    model : str
        The ``[model] name`` of the model file (a study: its model file or catalogue entry).
    **items
        The command's own keys, in the order they are to be written.

    Returns
    -------
    dict
    """
    return {"units": UNITS, "command": command, "model": model, **items}
