# SPDX-License-Identifier: MIT
"""Locate the data shipped with trussfe: ``meshes/``, ``validation/`` and ``examples/``.

In a wheel they are installed under ``trussfe/_data``; in a source checkout (editable install)
they are the top-level folders of the repository.
"""
from __future__ import annotations

from pathlib import Path

_PKG = Path(__file__).resolve().parent


def data_dir(name: str) -> Path:
    """Directory of the shipped data set ``name`` ("meshes", "validation" or "examples").

    Raises
    ------
    FileNotFoundError
        If neither the installed nor the source-tree copy exists.
    """
    for candidate in (_PKG / "_data" / name, _PKG.parent / name):
        if candidate.is_dir():
            return candidate
    raise FileNotFoundError(f"trussfe data folder '{name}' not found")


def mesh_path(filename: str) -> Path:
    """Path of a shipped model file in ``meshes/``."""
    return data_dir("meshes") / filename
