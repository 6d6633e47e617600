# SPDX-License-Identifier: MIT
"""Finite elements along a rigid-body motion: :func:`elastic` (quasi-static, step by step)
and :func:`transient` (linearised dynamics about the moving configuration)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, ClassVar

import numpy as np

from ..io.json_document import result_json
from ..model.bar_models import BAR_MODELS
from .model import ModelLike, as_structure, refuse_unapplied
from .options import choice, positive_int, progress_callback, real
from .numerics import numerics_checked
from .results import Result
from .rigid_body import SCHEMES, load_motion_for

#: Matrix updates of :func:`transient`.
UPDATES = ("per-step", "frozen")


@numerics_checked
def elastic(model: ModelLike, *, motion=None, steps: int | None = None,
            scheme: str = "exact", sections: int = 7,
            subdivisions: int | None = None, progress: Callable[[int, int], None] | None = None) -> ElasticResult:
    """Pinned-beam FE model in the current configuration at every step of a motion, under
    gravity and the d'Alembert loads of the rigid-body motion (``trussfe elastic``),
    compared with the rigid-body model's internal forces.

    Parameters
    ----------
    model : Structure, path or dict
        With ``[active_members]`` if it moves.
    motion : path or Motion, optional
        Motion file (as for :func:`trussfe.simulate`); ``None``: the model at rest.
    steps : int, optional
        Number of time steps of a generated motion.
    scheme : {"exact", "thesis"}
        Kinematics of the rigid-body motion.
    sections : int
        Sections per member tube compared with the rigid model.
    subdivisions : int, optional
        Elements per member (default ``sections - 1``, at least 2).

    progress : callable, optional
        Called as ``progress(done, total)`` during the run (a progress bar; the command line
        draws one on a terminal).

    Returns
    -------
    ElasticResult
        ``displacement`` (step, node, dim), ``axial_force`` and ``axial_force_rigid``
        (step, member), ``section_forces`` (step, member, station, 6), …
    """
    from ..response.along_motion import simulate_elastic
    from ..mechanics.conventions import Conventions

    choice("--scheme", scheme, SCHEMES)
    sections = positive_int("--sections", sections, optional=False)
    subdivisions = positive_int("--subdivisions", subdivisions)
    progress = progress_callback(progress)
    structure = refuse_unapplied(as_structure(model), "elastic")
    mot = load_motion_for(structure, motion, steps)
    sim, resp, cmp = simulate_elastic(structure, mot, n_sections=sections,
                                      subdivisions=subdivisions,
                                      conventions=Conventions.from_scheme(scheme),
                                      progress=progress)
    return ElasticResult(structure, resp, rigid=sim, comparison=cmp)


@numerics_checked
def transient(model: ModelLike, *, motion, steps: int | None = None, dt: float | None = None,
              t_end: float | None = None, bar_model: str = "pinned-beam",
              subdivisions: int | None = None, update: str = "per-step",
              damping: tuple[float, float] | None = None,
              progress: Callable[[int, int], None] | None = None) -> TransientResult:
    """Elastic vibration superposed on a prescribed motion (``trussfe transient``):
    linearised FE dynamics about the moving configuration, Newmark average acceleration.

    Parameters
    ----------
    model : Structure, path or dict
        With ``[active_members]``.
    motion : path or Motion
        The prescribed motion (required).
    steps : int, optional
        Number of time steps of a generated motion.
    dt : float, optional
        Time step, s (default: the motion's sampling).
    t_end : float, optional
        End time, s (holds a motion that ended at rest).
    bar_model : {"pinned-beam", "truss"}
    subdivisions : int, optional
        Elements per pinned-beam member (default 4).
    update : {"per-step", "frozen"}
        Matrices of the current geometry at every step, or of the initial one.
    damping : (alpha, beta), optional
        Rayleigh damping C = alpha M + beta K.

    progress : callable, optional
        Called as ``progress(done, total)`` during the run (a progress bar; the command line
        draws one on a terminal).

    Returns
    -------
    TransientResult
        ``axial_force``, ``axial_force_quasi_static``, ``axial_force_rigid`` (step, member),
        ``displacement`` (step, node, dim), ``energy``, …
    """
    from ..response.transient import transient_response

    choice("--bar-model", bar_model, BAR_MODELS)
    choice("--update", update, UPDATES)
    subdivisions = positive_int("--subdivisions", subdivisions)
    dt = real("--dt", dt, positive=True)
    t_end = real("--t-end", t_end, positive=True)
    progress = progress_callback(progress)
    structure = refuse_unapplied(as_structure(model), "transient")
    mot = load_motion_for(structure, motion, steps, required=True)
    return TransientResult(structure, transient_response(
        structure, mot, bar_model=bar_model, k=subdivisions, dt=dt, t_end=t_end,
        damping=damping, update=update, progress=progress))


@dataclass(frozen=True, eq=False, repr=False)
class ElasticResult(Result):
    """Finite-element response along a rigid-body motion (:func:`trussfe.elastic`).

    ``solution`` is the :class:`trussfe.response.along_motion.ElasticResponse`; ``rigid`` the
    rigid-body :class:`~trussfe.rigid.simulate.SimulationResult` of the same motion and
    ``comparison`` the largest scaled FE − rigid differences
    (:func:`trussfe.response.along_motion.compare_with_rigid`).
    """

    command: ClassVar[str] = "elastic"
    rigid: Any = None
    comparison: dict | None = None

    @property
    def time(self) -> np.ndarray:
        """Time of every step, shape (step,), s."""
        return self.rigid.time

    @property
    def position(self) -> np.ndarray:
        """Node positions of the rigid-body motion, shape (step, node, dim), m."""
        return self.rigid.kinematics.coords[..., :self.dim]

    @property
    def displacement(self) -> np.ndarray:
        """Elastic displacements from the rigid-body positions, shape (step, node, dim), m."""
        return self.solution.displacements

    @property
    def reaction(self) -> np.ndarray:
        """Support reactions, shape (step, node, dim), N."""
        return self.solution.reactions

    @property
    def axial_force(self) -> np.ndarray:
        """FE axial force at the middle of each member's tube, shape (step, member), N."""
        return self.solution.midpoint_axial_force

    @property
    def axial_force_rigid(self) -> np.ndarray:
        """The rigid-body model's axial force there, shape (step, member), N."""
        return self.rigid.midpoint_axial_force

    @property
    def strain(self) -> np.ndarray:
        """Axial strain N/(EA) at the tube middle, shape (step, member)."""
        return self.solution.strain

    @property
    def section_forces(self) -> np.ndarray:
        """FE section forces at the stations, shape (step, member, station, 6): N, Vy, Vz,
        T, My, Mz in member axes."""
        return self.solution.station_forces

    @property
    def station_x(self) -> np.ndarray:
        """Station positions along each member, shape (step, member, station), m."""
        return self.solution.station_x

    def _document(self) -> dict:
        s = self.structure
        dim = s.dim
        sim, resp = self.rigid, self.solution
        members = {mid: {"axial_force": resp.midpoint_axial_force[:, i].tolist(),
                         "strain": resp.strain[:, i].tolist(),
                         "axial_force_rigid": sim.midpoint_axial_force[:, i].tolist()}
                   for i, mid in enumerate(s.member_ids)}
        nodes = {}
        for i, nid in enumerate(s.node_ids):
            d = {"displacement": resp.displacements[:, i].tolist()}
            if s.supports[i, :dim].any():
                d["reaction"] = resp.reactions[:, i].tolist()
            nodes[nid] = d
        return result_json("elastic", s.name, bar_model="pinned-beam",
                               subdivisions=resp.subdivisions, time=sim.time.tolist(),
                               members=members, nodes=nodes, comparison=self.comparison)


@dataclass(frozen=True, eq=False, repr=False)
class TransientResult(Result):
    """Elastic vibration superposed on a prescribed motion (:func:`trussfe.transient`);
    ``solution`` is a :class:`trussfe.response.transient.TransientResult`, whose attributes
    hold the same arrays with ``_qs`` for ``_quasi_static``."""

    command: ClassVar[str] = "transient"

    @property
    def time(self) -> np.ndarray:
        """Time of every step, shape (step,), s."""
        return self.solution.time

    @property
    def position(self) -> np.ndarray:
        """Node positions of the rigid-body motion, shape (step, node, dim), m."""
        return self.solution.coords

    @property
    def displacement(self) -> np.ndarray:
        """Elastic (dynamic) displacements, shape (step, node, dim), m."""
        return self.solution.displacement

    @property
    def displacement_quasi_static(self) -> np.ndarray:
        """Quasi-static FE displacements, shape (step, node, dim), m."""
        return self.solution.displacement_qs

    @property
    def axial_force(self) -> np.ndarray:
        """Dynamic FE axial force at the member middle, shape (step, member), N."""
        return self.solution.axial_force

    @property
    def axial_force_quasi_static(self) -> np.ndarray:
        """Quasi-static FE axial force, shape (step, member), N."""
        return self.solution.axial_force_qs

    @property
    def axial_force_rigid(self) -> np.ndarray:
        """Rigid-body model's axial force, shape (step, member), N."""
        return self.solution.axial_force_rigid

    @property
    def moment(self) -> np.ndarray:
        """Bending-moment magnitude at the member middle, shape (step, member), N·m."""
        return self.solution.moment

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Lowest natural frequencies in the initial geometry, shape (mode,), Hz."""
        return self.solution.frequencies_hz

    @property
    def energy(self) -> dict:
        """Energy histories, each shape (step,), J: ``kinetic``, ``strain``, ``work``,
        ``dissipated``, ``parametric``, ``residual``."""
        return self.solution.energy

    def _document(self) -> dict:
        res = self.solution
        s = self.structure
        members = {}
        for j, mid in enumerate(s.member_ids):
            members[mid] = {
                "axial_force": res.axial_force[:, j].tolist(),
                "axial_force_quasi_static": res.axial_force_qs[:, j].tolist(),
                "axial_force_rigid": res.axial_force_rigid[:, j].tolist(),
                "moment": res.moment[:, j].tolist(),
                "moment_quasi_static": res.moment_qs[:, j].tolist(),
                "moment_rigid": res.moment_rigid[:, j].tolist()}
        return {**result_json("transient", s.name),
                "time": res.time.tolist(), "members": members,
                "nodes": {nid: {"displacement": res.displacement[:, i].tolist()}
                          for i, nid in enumerate(s.node_ids)},
                "departure": res.departure(),
                "energy": {k: v.tolist() for k, v in res.energy.items()},
                "energy_residual": res.energy_residual(),
                "frequencies_hz": res.frequencies_hz.tolist(),
                "options": {k: (list(v) if isinstance(v, tuple) else v)
                            for k, v in res.options.items()}}
