# SPDX-License-Identifier: MIT
"""Motion files: a TOML ``[motion]`` table or a CSV history, read into a :class:`Motion`.

``type = "third-order"`` (default) is the thesis' actuator model
(:func:`~trussfe.rigid.motion.third_order_motion`), ``type = "csv"`` a measured history
(:mod:`trussfe.rigid.motion_csv`), ``type = "rotation"`` a top-plane rotation converted to
active lengths (:mod:`trussfe.rigid.slew`).  This module sits above all three, so none of
them imports another's reader.
"""
from __future__ import annotations

import math
import tomllib
from pathlib import Path
from typing import Any

from ..budget import check_input_file
from ..errors import InputError
from ..io.regular_file import read_regular_file
from ..model.structure import Structure
from .motion import Motion, spec_bool, spec_int, spec_positive, third_order_motion
from .motion_csv import read_motion_csv
from .slew import rotation_motion

_TOML_KEYS = ("type", "duration", "steps", "start", "end", "damping_ratio", "settling_fraction",
              "settling_constant", "real_root_factor", "first_sample", "include_end", "file")


def motion_from_spec(spec: dict, structure: Structure, base_dir: Path, source: str = "",
                     steps: int | None = None) -> Motion:
    """Build a :class:`Motion` from a parsed ``[motion]`` table."""
    item = f"{source}: motion" if source else "motion"
    if not isinstance(spec, dict):
        raise InputError(item, "expected a [motion] table")
    kind = spec.get("type", "third-order")
    if kind == "csv":
        if "file" not in spec:
            raise InputError(f"{item}.file", "a csv motion needs file = \"history.csv\"")
        _no_steps(steps, "a CSV motion history")
        return read_motion_csv(base_dir / str(spec["file"]), structure)
    if kind == "rotation":
        try:
            return rotation_motion(spec, structure, steps=steps)
        except InputError as err:
            # named by the file, as for the other motion types (the options' own items not)
            if not source or err.item.startswith((source, "--")):
                raise
            raise err.with_file(source) from None
    if kind != "third-order":
        raise InputError(f"{item}.type", f"unknown motion type {kind!r}; valid: "
                         "'third-order', 'csv', 'rotation'")
    for key in spec:
        if key not in _TOML_KEYS:
            raise InputError(f"{item}.{key}", f"unknown key; valid: {', '.join(_TOML_KEYS)}")
    for key in ("duration", "start", "end"):
        if key not in spec:
            raise InputError(f"{item}.{key}", "is required")
    n = steps if steps is not None else spec.get("steps", 50)
    opts: dict[str, Any] = {}
    for key in ("damping_ratio", "settling_fraction", "settling_constant", "real_root_factor"):
        if key in spec:
            opts[key] = spec_positive(spec, key, item)
    for key in ("start", "end"):
        v = spec[key]
        if not isinstance(v, dict):
            raise InputError(f"{item}.{key}", "expected a table member id = length (m)")
        for k, x in v.items():
            if isinstance(x, bool) or not isinstance(x, (int, float)) or not (
                    x > 0 and math.isfinite(x)):
                raise InputError(f"{item}.{key}.{k}", f"must be a positive length, got {x!r}")
    dur = spec["duration"]
    if isinstance(dur, bool) or not isinstance(dur, (int, float)):
        raise InputError(f"{item}.duration", f"expected a number of seconds, got {dur!r}")
    if not (math.isfinite(dur) and dur > 0):
        raise InputError(f"{item}.duration", f"must be a positive number of seconds, got {dur!r}")
    try:
        m = third_order_motion(structure, spec["start"], spec["end"], float(dur), n,
                               first_sample=spec_int(spec, "first_sample", item, 0),
                               include_end=spec_bool(spec, "include_end", item), **opts)
    except InputError as err:
        if not source or err.item.startswith((source, "--")):
            raise
        raise err.with_file(source) from None
    m.source = source or m.source
    return m


def _no_steps(steps: int | None, what: str) -> None:
    """Refuse a step count for a motion whose samples are given (nothing to generate)."""
    if steps is not None:
        raise InputError("--steps", f"{what} gives its own time samples; --steps sets the "
                         "number of steps of a generated motion only (third-order or "
                         "rotation start/end/duration)")


def load_motion(path: str | Path, structure: Structure, steps: int | None = None) -> Motion:
    """Read a motion file: TOML ``[motion]`` spec, or a CSV history (``.csv``).

    Parameters
    ----------
    path : path
        Motion file.
    structure : Structure
        The model the motion drives (active members must exist in it).
    steps : int, optional
        Overrides the number of steps of a generated (third-order) motion.

    Raises
    ------
    InputError
        Unreadable file, unknown keys or members, non-monotonic time, NaN values.
    """
    path = Path(path)
    # a folder, device or named pipe is refused before it is opened (a pipe would block)
    check_input_file(str(path), "motion file")
    if path.suffix.lower() == ".csv":
        _no_steps(steps, "a CSV motion history")
        return read_motion_csv(path, structure)
    try:
        # what is read is what was checked, and no more than an input file may hold
        data = tomllib.loads(read_regular_file(path, "motion file").decode("utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise InputError(path.name, f"not a valid TOML motion file ({exc})") from None
    except RecursionError:
        raise InputError(path.name, "arrays or tables nest too deeply") from None
    if "motion" not in data:
        raise InputError(path.name, "no [motion] table")
    return motion_from_spec(data["motion"], structure, path.parent, path.name, steps)
