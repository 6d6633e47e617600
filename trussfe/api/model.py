# SPDX-License-Identifier: MIT
"""Models for the Python API: read from a file or built from plain Python data.

:func:`model_from_dict` takes the same tables as a model file (``model``, ``materials``,
``sections``, ``nodes``, ``members``, ``supports``, ``loads``, ``masses``, ``groups`` and the
extension tables such as ``active_members``) and goes through the file reader's parser, so
every check and every error message is the file reader's.
"""
from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any, Union

import numpy as np

from ..errors import InputError
from ..io.model_file import parse_model, read_model
from ..model.structure import Structure

#: What every analysis accepts as its model: a structure, a model file or the tables as a dict.
ModelLike = Union[Structure, str, os.PathLike, Mapping]


def _plain(value: Any) -> Any:
    """TOML-like data from Python data: tuples and arrays become lists, numpy scalars numbers
    (the parser then checks values exactly as it checks a file's)."""
    if isinstance(value, Mapping):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return _plain(value.tolist())
    if isinstance(value, np.bool_):
        return bool(value)
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, np.floating):
        return float(value)
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    return value


def model_from_dict(data: Mapping, *, base_dir: str | os.PathLike = ".",
                    name: str | None = None) -> Structure:
    """Build a model from plain data laid out as a model file (docs/model-format.md).

    Parameters
    ----------
    data : mapping
        ``{"model": {"dimension": 2, ...}, "materials": {...}, "sections": {...},
        "nodes": {id: [x, y]}, "members": {id: {"nodes": [a, b], "section": ...,
        "material": ...}}, "supports": {id: ["x", "y"]}, "loads": {id: [fx, fy]}, ...}``.
        Tuples and numpy arrays are accepted where the file has lists.
    base_dir : path, optional
        Folder against which file references (``[model] mesh``) are resolved.
    name : str, optional
        Shorthand for ``data["model"]["name"]``.

    Returns
    -------
    Structure

    Raises
    ------
    InputError
        Naming the table and item at fault, with the message the file reader gives.

    Examples
    --------
    >>> s = model_from_dict({
    ...     "model": {"dimension": 2},
    ...     "materials": {"steel": {"E": 210e9}},
    ...     "sections": {"bar": {"area": 1e-4}},
    ...     "nodes": {"A": [0, 0], "B": [1, 0], "C": [0, 1]},
    ...     "members": {"AB": {"nodes": ["A", "B"], "section": "bar", "material": "steel"},
    ...                 "BC": {"nodes": ["B", "C"], "section": "bar", "material": "steel"}},
    ...     "supports": {"A": ["x", "y"], "C": ["x", "y"]},
    ...     "loads": {"B": [0, -1000]}})
    >>> s.n_nodes, s.n_members
    (3, 2)
    """
    if not isinstance(data, Mapping):
        raise InputError("model", f"expected a dict of tables, got {type(data).__name__}")
    raw = _plain(data)
    if name is not None:
        model = raw.get("model")
        raw["model"] = {**(model if isinstance(model, dict) else {}), "name": str(name)}
    try:
        return parse_model(raw, base_dir=Path(base_dir), source="")
    except RecursionError:
        raise InputError("model", "model nests too deeply") from None


def as_structure(model: ModelLike) -> Structure:
    """The :class:`Structure` of an analysis argument: a structure as is, a path read with
    :func:`~trussfe.io.model_file.read_model`, a dict built with :func:`model_from_dict`."""
    if isinstance(model, Structure):
        return model
    if isinstance(model, (str, os.PathLike)):
        return read_model(model)
    if isinstance(model, Mapping):
        return model_from_dict(model)
    raise TypeError(f"model must be a Structure, a model file path or a dict of tables, "
                    f"not {type(model).__name__}")


def refuse_unapplied(structure: Structure, command: str) -> Structure:
    """The structure, when it has none of the tables an analysis along a motion does not
    apply; an :class:`InputError` naming the model file, the table and the command otherwise.

    An analysis along a motion (``simulate``, ``actuators``, ``elastic``, ``transient``)
    applies the model's ``[loads]``, ``[model] gravity`` and ``[masses]``.  It refuses,
    rather than drops:

    * ``member_loads``: loads along members (static and buckling apply them);
    * ``[load_cases]``: a model with cases gives every action in a case and none in
      ``[loads]``, and the motion has no case to choose;
    * ``[springs]``: elastic supports, which the rigid-body model (the motion's positions and
      the member forces) and the response along the motion do not model.
    """
    source = structure.source or structure.name or "model"
    ext = structure.extensions
    if ext.get("member_loads"):
        raise InputError(f"{source}: member_loads", f"loads along members are applied by "
                         f"static and buckling only, not by {command}; apply them as nodal "
                         "loads")
    if ext.get("load_cases"):
        raise InputError(f"{source}: load_cases", f"{command} applies [loads] and [model] "
                         "gravity, not load cases: give the loads to apply as [loads] of a "
                         "model without [load_cases]")
    springs = ext.get("springs")
    if springs is not None and np.any(springs.stiffness > 0):
        raise InputError(f"{source}: springs", f"{command} models no elastic supports: the "
                         "structure moves on its [supports] alone; give the springs as "
                         "supports or remove them")
    return structure


def model_folder(structure: Structure) -> Path | None:
    """Folder of the file a structure was read from (``None`` if built in Python)."""
    return Path(structure.source).parent if structure.source else None


def resolve_beside(path: str | os.PathLike, structure: Structure) -> Path:
    """A relative file path that does not exist from the working directory is taken
    relative to the model file's folder (a motion file kept beside its model)."""
    p = Path(path)
    folder = model_folder(structure)
    if folder is not None and not p.is_file() and not p.is_absolute() \
            and (folder / p).is_file():
        return folder / p
    return p


__all__ = ["ModelLike", "as_structure", "model_from_dict", "read_model",
           "refuse_unapplied", "resolve_beside"]
