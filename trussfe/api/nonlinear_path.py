# SPDX-License-Identifier: MIT
"""Geometrically nonlinear analysis: :func:`postcritical`."""
from __future__ import annotations

import math

from ..errors import InputError
from .model import ModelLike, as_structure
from .options import choice, positive_int
from .results import PostcriticalResult


def postcritical(model: ModelLike, *, control: str | None = None, steps: int | None = None,
                 step: float | None = None, max_load_factor: float | None = None,
                 max_displacement: float | None = None, monitor: str | None = None,
                 bar_model: str | None = None, subdivisions: int | None = None,
                 imperfection: float | None = None,
                 branch: bool | None = None,
                 max_step: float | None = None) -> PostcriticalResult:
    """Follow the equilibrium path of the model under its ``[loads]`` scaled by a load
    factor λ (``trussfe postcritical``): co-rotational elements, limit and bifurcation
    points, member buckling, yield and fracture (``[failure]``), the hand-over to mechanism
    motion.

    Every option left ``None`` takes the model's ``[postcritical]`` value, else the
    default (arc-length control, truss bars, 8 beam elements per beam member).

    Parameters
    ----------
    model : Structure, path or dict
    control : {"load", "displacement", "arc-length"}, optional
    steps : int, optional
        Number of steps.
    step : float, optional
        First increment: Δλ (load), Δu (displacement) or Δs (arc-length).
    max_load_factor, max_displacement : float, optional
        Stop when λ or the monitored displacement (m) exceeds this.
    monitor : str, optional
        ``"NODE:AXIS"``: the displacement plotted (prescribed under displacement control).
    bar_model : {"truss", "pinned-beam"}, optional
    subdivisions : int, optional
        Beam elements per beam member.
    imperfection : float, optional
        Amplitude (m) of the first buckling mode added to the geometry.
    branch : bool, optional
        At a bifurcation follow the secondary branch.
    max_step : float, optional
        Largest arc-length increment (the ``[postcritical]`` setting; no command-line
        option).

    Returns
    -------
    PostcriticalResult
        ``load_factors`` (point,), ``displacement`` (point, node, dim), ``axial_force``
        (point, member), ``events``, ``termination``.
    """
    from ..nonlinear.analysis import run_postcritical
    from ..nonlinear.model import BAR_MODELS
    from ..nonlinear.path import CONTROLS

    if control is not None:
        choice("--control", control, CONTROLS)
    if bar_model is not None:
        choice("--bar-model", bar_model, BAR_MODELS)
    positive_int("--steps", steps)
    positive_int("--subdivisions", subdivisions)
    for name, v in (("step", step), ("max_load_factor", max_load_factor),
                    ("max_displacement", max_displacement), ("max_step", max_step)):
        if v is not None and not (math.isfinite(v) and v > 0):
            raise InputError(f"--{name.replace('_', '-')}", f"must be positive, got {v}")
    if imperfection is not None and not (math.isfinite(imperfection) and imperfection >= 0):
        raise InputError("--imperfection", f"must not be negative, got {imperfection}")
    structure = as_structure(model)
    return PostcriticalResult(structure, run_postcritical(
        structure, control=control, steps=steps, step=step, max_load_factor=max_load_factor,
        max_displacement=max_displacement, monitor=monitor, bar_model=bar_model,
        subdivisions=subdivisions, imperfection=imperfection, branch=branch,
        max_step=max_step))
