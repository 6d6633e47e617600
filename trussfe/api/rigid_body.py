# SPDX-License-Identifier: MIT
"""Rigid-body dynamic force analysis (Lacy): :func:`simulate` and :func:`actuators`."""
from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Callable, ClassVar

import numpy as np

from ..errors import InputError
from ..io.json_document import result_json
from ..model.structure import Structure
from .model import ModelLike, as_structure, refuse_unapplied, resolve_beside
from .options import choice, positive_int, progress_callback
from .numerics import numerics_checked
from .results import Result

#: Kinematics schemes: exact (:data:`~trussfe.mechanics.conventions.PHYSICAL`), or Lacy's
#: Appendix A (:data:`~trussfe.mechanics.conventions.THESIS`: backward differences and
#: whole-length section inertia).
SCHEMES = ("exact", "thesis")
#: Analysis methods: chosen from the model (bay by bay for a chain of two or more identical
#: bays, else direct), the whole truss at once, or Lacy's chapter 6 bay by bay
#: (:mod:`trussfe.rigid.bays`).
METHODS = ("auto", "direct", "bay-by-bay")


def load_motion_for(structure: Structure, motion, steps: int | None, *,
                    required: bool = False):
    """The :class:`~trussfe.rigid.motion.Motion` of a ``motion`` option: a motion object as
    is, a file path (TOML ``[motion]`` or CSV; a relative path not found from the working
    directory is taken beside the model file), or ``None`` (the model at rest)."""
    from ..rigid.motion import Motion
    from ..rigid.motion_file import load_motion

    steps = positive_int("--steps", steps)
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


def _simulate(model: ModelLike, motion, steps, scheme: str, sections: int,
              progress: Callable[[int, int], None] | None, method: str = "auto"):
    from ..mechanics.conventions import Conventions
    from ..rigid.simulate import simulate as run

    choice("--scheme", scheme, SCHEMES)
    choice("--method", method, METHODS)
    sections = positive_int("--sections", sections, optional=False)
    progress = progress_callback(progress)
    structure = refuse_unapplied(as_structure(model), "simulate")
    mot = load_motion_for(structure, motion, steps)
    return structure, run(structure, mot, conventions=Conventions.from_scheme(scheme),
                          n_sections=sections, progress=progress, method=method)


@numerics_checked
def simulate(model: ModelLike, *, motion=None, steps: int | None = None,
             scheme: str = "exact", sections: int = 7, method: str = "auto",
             progress: Callable[[int, int], None] | None = None) -> SimulateResult:
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
    method : {"auto", "direct", "bay-by-bay"}
        ``"direct"``: the positions by Newton's method on the whole truss.
        ``"bay-by-bay"``: a chain of identical bays analysed as Lacy's chapter 6 describes —
        each bay's positions in its base frame carried up the chain (eqs. 6.1–6.3); the
        velocities and accelerations then run up the chain and the forces down it, each
        bay's base reactions passed to the bay below (§6.2), in O(n) per step for both
        methods.  Both give the same results to round-off; ``"bay-by-bay"`` refuses a model
        that is not such a chain and ``scheme="thesis"``.  ``"auto"`` (default):
        ``"bay-by-bay"`` for a chain of two or more identical bays with the exact scheme,
        else ``"direct"``; the result's ``options["method"]`` says which one ran.
    progress : callable, optional
        Called as ``progress(done, total)`` during the run (a progress bar; the command line
        draws one on a terminal).

    Returns
    -------
    SimulateResult
        ``time`` (step,), ``position`` (step, node, dim), ``axial_force`` (step, member), …
    """
    structure, res = _simulate(model, motion, steps, scheme, sections, progress, method)
    return SimulateResult(structure, res)


@numerics_checked
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

    Raises
    ------
    InputError
        The model has no ``[actuators]`` table.
    """
    from ..rigid import actuator as _actuator  # noqa: F401  (registers [actuators])

    structure = refuse_unapplied(as_structure(model), "actuators")
    if not _actuator.actuators_of(structure):
        raise InputError(structure.source or structure.name or "model",
                         "the model has no [actuators] table: give the leadscrew and motor "
                         "data of the actuators to analyse (see docs/actuators.md)")
    structure, res = _simulate(structure, motion, steps, "exact", 7, None)
    return ActuatorsResult(structure, res)


@dataclass(frozen=True, eq=False, repr=False)
class SimulateResult(Result):
    """Rigid-body dynamic force analysis along a motion (:func:`trussfe.simulate`);
    ``solution`` is a :class:`trussfe.rigid.simulate.SimulationResult`."""

    command: ClassVar[str] = "simulate"

    @property
    def time(self) -> np.ndarray:
        """Time of every step, shape (step,), s."""
        return self.solution.time

    @property
    def position(self) -> np.ndarray:
        """Node positions, shape (step, node, dim), m."""
        return self.solution.kinematics.coords[..., :self.dim]

    @property
    def velocity(self) -> np.ndarray:
        """Node velocities, shape (step, node, dim), m/s."""
        return self.solution.kinematics.velocity[..., :self.dim]

    @property
    def acceleration(self) -> np.ndarray:
        """Node accelerations, shape (step, node, dim), m/s²."""
        return self.solution.kinematics.acceleration[..., :self.dim]

    @property
    def reaction(self) -> np.ndarray:
        """Support reactions, shape (step, node, dim), N (zero on free coordinates)."""
        return self.solution.forces.reactions[..., :self.dim]

    @property
    def axial_force(self) -> np.ndarray:
        """Axial force at the middle of each member's tube, shape (step, member), N."""
        return self.solution.midpoint_axial_force

    @property
    def station_axial_force(self) -> np.ndarray:
        """Axial force at the sections, shape (step, member, station), N (Lacy eq. 2.18)."""
        return self.solution.section_tension

    @property
    def von_mises(self) -> np.ndarray:
        """Von Mises stress at the sections, shape (step, member, station), Pa."""
        return self.solution.stresses.von_mises

    @property
    def max_von_mises(self) -> np.ndarray:
        """Largest von Mises stress over each member's sections, shape (step, member), Pa."""
        return self.solution.stresses.von_mises.max(axis=2)

    @property
    def actuator_ids(self) -> tuple[str, ...]:
        """Ids of the active members, in the order of every ``actuator`` axis."""
        from ..rigid.active import active_members
        return tuple(self.structure.member_ids[a.member] for a in active_members(self.structure))

    @property
    def actuator_force(self) -> np.ndarray:
        """Force of the active base on the leadscrew tube, shape (step, actuator), N."""
        return self.solution.actuator_force

    def _document(self) -> dict:
        from ..rigid.output import to_json
        return to_json(self.solution)


@dataclass(frozen=True, eq=False, repr=False)
class ActuatorsResult(Result):
    """Leadscrew and motor demands along a motion (:func:`trussfe.actuators`); ``solution``
    is the :class:`trussfe.rigid.simulate.SimulationResult` they come from."""

    command: ClassVar[str] = "actuators"

    #: Histories of every actuator, each an array of shape (step, actuator).
    QUANTITIES: ClassVar[tuple[str, ...]] = (
        "force", "motor_speed", "motor_torque", "motor_current", "motor_voltage",
        "motor_voltage_frictionless")

    @property
    def time(self) -> np.ndarray:
        """Time of every step, shape (step,), s."""
        return self.solution.time

    @property
    def actuator_ids(self) -> tuple[str, ...]:
        """Ids of the ``[actuators]`` entries with histories, in the order of every
        ``actuator`` axis."""
        from ..rigid.actuator import actuators_of
        return tuple(a.name for a in actuators_of(self.structure)
                     if a.name in self.solution.actuators)

    def history(self, quantity: str) -> np.ndarray:
        """One of :attr:`QUANTITIES` for every actuator, shape (step, actuator); NaN for the
        motor quantities of an actuator without a gearhead gain whose member the motion does
        not move (eq. 3.1 has no speed to select the gain from)."""
        if quantity not in self.QUANTITIES:
            from ..io.suggest import suggest
            raise InputError("quantity", f"unknown actuator quantity {quantity!r}"
                             f"{suggest(quantity, self.QUANTITIES)}")
        h = self.solution.actuators
        nan = np.full(self.time.size, np.nan)
        return np.stack([np.asarray(h[a].get(quantity, nan), dtype=float)
                         for a in self.actuator_ids],
                        axis=1) if self.actuator_ids else np.zeros((self.time.size, 0))

    @property
    def force(self) -> np.ndarray:
        """Actuator force, shape (step, actuator), N."""
        return self.history("force")

    @property
    def motor_torque(self) -> np.ndarray:
        """Motor torque, shape (step, actuator), N·m."""
        return self.history("motor_torque")

    @property
    def motor_voltage(self) -> np.ndarray:
        """Motor voltage, shape (step, actuator), V."""
        return self.history("motor_voltage")

    def _document(self) -> dict:
        from ..rigid.actuator import actuators_of

        res = self.solution
        t = res.time

        def peak(x: np.ndarray) -> dict:
            k = int(np.argmax(np.abs(x)))
            return {"value": float(x[k]), "time": float(t[k])}

        out = {}
        for act in actuators_of(self.structure):
            h = res.actuators.get(act.name)
            if h is None:
                continue
            # without a gearhead gain and a motion of its member there are no motor
            # histories: the gain and the motor peaks are null
            out[act.name] = {
                "self_locking": bool(act.self_locking),
                "self_locking_limit": act.self_locking_limit,
                "leadscrew_gain": act.leadscrew_gain,
                "gearhead_gain": (float(h["gearhead_gain"]) if "gearhead_gain" in h
                                  else None),
                "gearhead_gain_selected": bool(h["gearhead_gain_selected"]),
                "convention": act.convention,
                **{k: peak(np.asarray(h[k])) if k in h else None for k in self.QUANTITIES},
                "flags": list(h["flags"]),
            }
        return result_json("actuators", self.structure.name, actuators=out)
