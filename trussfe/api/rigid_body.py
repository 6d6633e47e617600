# SPDX-License-Identifier: MIT
"""Rigid-body dynamic force analysis (Lacy): :func:`simulate` and :func:`actuators`."""
from __future__ import annotations

import os

from ..errors import InputError
from ..model.structure import Structure
from .model import ModelLike, as_structure, resolve_beside
from .options import choice, positive_int
from .results import ActuatorsResult, SimulateResult

#: Kinematics schemes: exact, or Lacy's backward differences.
SCHEMES = ("exact", "thesis")


def load_motion_for(structure: Structure, motion, steps: int | None, *,
                    required: bool = False):
    """The :class:`~trussfe.rigid.motion.Motion` of a ``motion`` option: a motion object as
    is, a file path (TOML ``[motion]`` or CSV; a relative path not found from the working
    directory is taken beside the model file), or ``None`` (the model at rest)."""
    from ..rigid.motion import Motion, load_motion

    positive_int("--steps", steps)
    if motion is None:
        if required:
            raise InputError("motion", "the analysis needs a motion file")
        if steps is not None:
            raise InputError("--steps", "needs --motion (without a motion the model is at rest)")
        return None
    if isinstance(motion, Motion):
        if steps is not None:
            raise InputError("--steps", "applies to a motion file, not a Motion object")
        return motion
    if not isinstance(motion, (str, os.PathLike)):
        raise TypeError(f"motion must be a file path or a Motion, not {type(motion).__name__}")
    return load_motion(resolve_beside(motion, structure), structure, steps=steps)


def _simulate(model: ModelLike, motion, steps, scheme: str, sections: int, progress: bool):
    from ..rigid.simulate import simulate as run

    choice("--scheme", scheme, SCHEMES)
    structure = as_structure(model)
    mot = load_motion_for(structure, motion, steps)
    return structure, run(structure, mot, scheme=scheme, n_sections=sections,
                          progress=progress)


def simulate(model: ModelLike, *, motion=None, steps: int | None = None,
             scheme: str = "exact", sections: int = 7,
             progress: bool = False) -> SimulateResult:
    """Rigid-body dynamic force analysis along a motion of the active members
    (``trussfe simulate``; Lacy chapters 2–4).

    Parameters
    ----------
    model : Structure, path or dict
        A model with ``[active_members]`` when it moves.
    motion : path or Motion, optional
        Motion file (TOML ``[motion]`` spec or CSV history; a relative path not found from
        the working directory is taken beside the model file).  ``None``: the model at rest
        (one step).
    steps : int, optional
        Number of time steps of a generated motion.
    scheme : {"exact", "thesis"}
        Kinematics: exact, or Lacy's backward differences.
    sections : int
        Sections per member for the internal forces.
    progress : bool
        Progress bar on stderr.

    Returns
    -------
    SimulateResult
        ``time`` (step,), ``position`` (step, node, dim), ``axial_force`` (step, member), …
    """
    structure, res = _simulate(model, motion, steps, scheme, sections, progress)
    return SimulateResult(structure, res)


def actuators(model: ModelLike, *, motion=None, steps: int | None = None) -> ActuatorsResult:
    """Leadscrew and motor demands of every ``[actuators]`` entry along a motion
    (``trussfe actuators``): self-locking check (Lacy eq. 2.45), gains (eq. 3.1), peak force,
    motor speed, torque, current and voltage, with and without friction, and flags.

    Parameters
    ----------
    model : Structure, path or dict
        A model with ``[active_members]`` and ``[actuators]``.
    motion : path or Motion, optional
        As for :func:`simulate`.
    steps : int, optional
        Number of time steps of a generated motion.

    Returns
    -------
    ActuatorsResult
        ``force``, ``motor_torque``, ``motor_voltage`` (step, actuator), ``history(name)``.
    """
    from ..rigid import actuator as _actuator  # noqa: F401  (registers [actuators])

    structure, res = _simulate(model, motion, steps, "exact", 7, False)
    return ActuatorsResult(structure, res)
