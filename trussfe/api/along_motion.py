# SPDX-License-Identifier: MIT
"""Finite elements along a rigid-body motion: :func:`elastic` (quasi-static, step by step)
and :func:`transient` (linearised dynamics about the moving configuration)."""
from __future__ import annotations

from .model import ModelLike, as_structure
from .options import choice
from .results import ElasticResult, TransientResult
from .rigid_body import SCHEMES, load_motion_for

#: Bar models and matrix updates of :func:`transient`.
TRANSIENT_BAR_MODELS = ("pinned-beam", "truss")
UPDATES = ("per-step", "frozen")


def elastic(model: ModelLike, *, motion=None, steps: int | None = None,
            scheme: str = "exact", sections: int = 7,
            subdivisions: int | None = None) -> ElasticResult:
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
        Elements per member (default ``sections - 1``).

    Returns
    -------
    ElasticResult
        ``displacement`` (step, node, dim), ``axial_force`` and ``axial_force_rigid``
        (step, member), ``section_forces`` (step, member, station, 6), …
    """
    from ..elastic.along_motion import simulate_elastic

    choice("--scheme", scheme, SCHEMES)
    structure = as_structure(model)
    mot = load_motion_for(structure, motion, steps)
    sim, resp, cmp = simulate_elastic(structure, mot, scheme=scheme, n_sections=sections,
                                      subdivisions=subdivisions)
    return ElasticResult(structure, resp, rigid=sim, comparison=cmp)


def transient(model: ModelLike, *, motion, steps: int | None = None, dt: float | None = None,
              t_end: float | None = None, bar_model: str = "pinned-beam",
              subdivisions: int | None = None, update: str = "per-step",
              damping: tuple[float, float] | None = None) -> TransientResult:
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

    Returns
    -------
    TransientResult
        ``axial_force``, ``axial_force_quasi_static``, ``axial_force_rigid`` (step, member),
        ``displacement`` (step, node, dim), ``energy``, …
    """
    from ..elastic.transient import transient_response

    choice("--bar-model", bar_model, TRANSIENT_BAR_MODELS)
    choice("--update", update, UPDATES)
    structure = as_structure(model)
    mot = load_motion_for(structure, motion, steps, required=True)
    return TransientResult(structure, transient_response(
        structure, mot, bar_model=bar_model, k=subdivisions, dt=dt, t_end=t_end,
        damping=damping, update=update))
