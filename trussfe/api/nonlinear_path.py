# SPDX-License-Identifier: MIT
"""Geometrically nonlinear analysis: :func:`postcritical`."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, ClassVar

import numpy as np

from ..errors import InputError
from .model import ModelLike, as_structure
from .options import choice, flag, positive_int, progress_callback, real
from .numerics import numerics_checked
from .results import Result


@numerics_checked
def postcritical(model: ModelLike, *, control: str | None = None, steps: int | None = None,
                 step: float | None = None, max_load_factor: float | None = None,
                 max_displacement: float | None = None, monitor: str | None = None,
                 bar_model: str | None = None, subdivisions: int | None = None,
                 imperfection: float | None = None,
                 branch: bool | None = None,
                 max_step: float | None = None,
                 progress: Callable[[int, int], None] | None = None) -> PostcriticalResult:
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

    progress : callable, optional
        Called as ``progress(done, total)`` during the run (a progress bar; the command line
        draws one on a terminal).

    Returns
    -------
    PostcriticalResult
        ``load_factors`` (point,), ``displacement`` (point, node, dim), ``axial_force``
        (point, member), ``events``, ``termination``.
    """
    from ..nonlinear.analysis import run_postcritical
    from ..model.bar_models import BAR_MODELS
    from ..nonlinear.path import CONTROLS

    if control is not None:
        choice("--control", control, CONTROLS)
    if bar_model is not None:
        choice("--bar-model", bar_model, BAR_MODELS)
    steps = positive_int("--steps", steps)
    subdivisions = positive_int("--subdivisions", subdivisions)
    step, max_load_factor, max_displacement, max_step = (
        real(f"--{name.replace('_', '-')}", v, positive=True)
        for name, v in (("step", step), ("max_load_factor", max_load_factor),
                        ("max_displacement", max_displacement), ("max_step", max_step)))
    imperfection = real("--imperfection", imperfection, nonneg=True)
    branch = flag("--branch", branch, optional=True)
    progress = progress_callback(progress)
    if monitor is not None and not isinstance(monitor, str):
        raise InputError("--monitor", f"expected NODE:AXIS (e.g. 3:y), got {monitor!r}")
    structure = as_structure(model)
    return PostcriticalResult(structure, run_postcritical(
        structure, control=control, steps=steps, step=step, max_load_factor=max_load_factor,
        max_displacement=max_displacement, monitor=monitor, bar_model=bar_model,
        subdivisions=subdivisions, imperfection=imperfection, branch=branch,
        max_step=max_step, progress=progress))


@dataclass(frozen=True, eq=False, repr=False)
class PostcriticalResult(Result):
    """Geometrically nonlinear path with member failure (:func:`trussfe.postcritical`);
    ``solution`` is a :class:`trussfe.nonlinear.path.PathResult` (its ``path`` points and
    ``events``)."""

    command: ClassVar[str] = "postcritical"

    @property
    def load_factors(self) -> np.ndarray:
        """Load factor λ of every path point, shape (point,)."""
        return self.solution.load_factors

    @property
    def displacement(self) -> np.ndarray:
        """Node translations of every path point, shape (point, node, dim), m."""
        s = self.structure
        n = s.n_nodes * s.dim
        return np.array([p.u[:n] for p in self.solution.path]).reshape(-1, s.n_nodes, s.dim)

    @property
    def axial_force(self) -> np.ndarray:
        """Member axial force of every path point, shape (point, member), N."""
        return np.array([p.forces for p in self.solution.path])

    @property
    def alive(self) -> np.ndarray:
        """False for a member removed by its failure law, shape (point, member)."""
        return np.array([p.alive for p in self.solution.path])

    @property
    def stage(self) -> tuple[str, ...]:
        """``"equilibrium"`` or ``"mechanism"`` (rigid-bar motion after the hand-over) per
        point."""
        return tuple(p.stage for p in self.solution.path)

    @property
    def monitor(self) -> tuple[str, str]:
        """The monitored displacement: (node id, axis)."""
        node, axis = divmod(self.solution.monitor, self.dim)
        return self.structure.node_ids[node], "xyz"[axis]

    @property
    def monitored_displacement(self) -> np.ndarray:
        """The monitored displacement of every path point, shape (point,), m."""
        return self.solution.displacement()

    @property
    def events(self) -> list:
        """Limit and bifurcation points, member buckling, yield, fracture, mechanism
        (:class:`trussfe.nonlinear.path.Event`)."""
        return self.solution.events

    @property
    def termination(self) -> str:
        """Why the path ended."""
        return self.solution.termination

    def _document(self) -> dict:
        from ..nonlinear.analysis import result_document
        return result_document(self.solution)
