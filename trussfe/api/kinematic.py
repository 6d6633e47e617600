# SPDX-License-Identifier: MIT
"""Bar-and-joint mechanisms: :func:`mechanism` (rank analysis, Hortobágyi 1999 §2) and
:func:`trace` (finite-mechanism motion, Hortobágyi's algorithm)."""
from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from ..errors import InputError
from .model import ModelLike, as_structure
from .results import MechanismResult, TraceResult


def mechanism(model: ModelLike, *, tolerance: float | None = None) -> MechanismResult:
    """Rank analysis of the bar assembly (``trussfe mechanism``): ρ(B), internal
    infinitesimal mechanisms, rigid-body motions the supports leave free, states of
    self-stress, determinacy.

    Parameters
    ----------
    model : Structure, path or dict
    tolerance : float, optional
        Relative singular-value tolerance (default max(b, f)·1e3·eps).

    Returns
    -------
    MechanismResult
        ``rank``, ``mechanisms``, ``mechanism_shapes`` (mechanism, node, dim),
        ``self_stress`` (state, member), …
    """
    from ..kinematics.rank import structure_rank

    structure = as_structure(model)
    return MechanismResult(structure, structure_rank(structure, tolerance=tolerance))


def trace(model: ModelLike, *, drive: str | Sequence[str], step: float | Sequence[float],
          steps: int, branch: int = 0, tolerance: float = 1e-10,
          frozen: bool = False, progress: Callable[[int], None] | None = None) -> TraceResult:
    """Follow the motion of an inextensional bar-and-joint mechanism (``trussfe trace``),
    with its bifurcation and limit points.

    Parameters
    ----------
    model : Structure, path or dict
    drive : str or sequence of str
        Prescribed coordinates ``"NODE:AXIS"``, one per degree of freedom.
    step : float or sequence of float
        Increment of each drive coordinate per step, m (one value serves every drive).
    steps : int
        Number of steps.
    branch : int
        Branch taken at a bifurcation point (0 = prescribe the drive).
    tolerance : float
        Relative bar-length tolerance of the corrector.
    frozen : bool
        Keep B11 of the predicted state (the paper's iteration) instead of Newton's refresh.
    progress : callable, optional
        Called with the step number before every step (a progress bar; it may raise
        ``KeyboardInterrupt`` to stop the trace).

    Returns
    -------
    TraceResult
        ``position`` (state, node, dim), ``parameter`` and ``rank`` (state,), ``events``.
    """
    from ..kinematics.trace import trace_structure

    drives = [drive] if isinstance(drive, str) else list(drive)
    steps_ = [step] if np.isscalar(step) else list(step)
    if len(steps_) == 1 and len(drives) > 1:
        steps_ = steps_ * len(drives)
    if len(steps_) != len(drives):
        raise InputError("--step", f"give one --step per --drive ({len(drives)} drives, "
                                   f"{len(steps_)} steps)")
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or steps < 1:
        raise InputError("--steps", f"must be a positive integer, got {steps!r}")
    if branch < 0:
        raise InputError("--branch", f"must be 0 or more, got {branch}")
    structure = as_structure(model)
    r = trace_structure(structure, drives, steps_ if len(steps_) > 1 else steps_[0], steps,
                        branch=branch, tolerance=tolerance, newton=not frozen,
                        progress=progress)
    return TraceResult(structure, r, options={"drive": drives, "step": steps_,
                                              "steps": steps, "branch": branch})
