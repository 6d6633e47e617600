# SPDX-License-Identifier: MIT
"""Result objects of the Python API.

Every analysis returns a :class:`Result`: numpy arrays with documented shapes, the node and
member ids that index their axes, the solver's own result object (``solution``) for anything
further, and :meth:`Result.to_dict`, the JSON document that ``trussfe COMMAND --json`` writes.

The same quantity has the same attribute name in every family (docs/python.md has the table):

=====================  =====================================================================
``displacement``       node translations, ``(node, dim)``, or ``(step, node, dim)`` along a
                       motion or a path
``reaction``           support reactions (forces), same layout, zero on free coordinates
``position``           node positions along a motion or path, ``(step, node, dim)``
``axial_force``        member axial force (N, tension positive): ``(member,)`` static,
                       ``(step, member)`` along a motion (at the middle of the member)
``section_forces``     ``(…, member, station, 6)``: N, Vy, Vz, T, My, Mz in member axes
``shapes``             mode shapes at the nodes, ``(mode, node, dim)``
``time``               ``(step,)``, s
=====================  =====================================================================

Arrays are views of the solver's arrays: copy one before changing it.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ..io.output import _jsonable as plain
from ..model.structure import Structure


@dataclass(frozen=True, eq=False)
class Result:
    """Base of every analysis result.

    Attributes
    ----------
    structure : Structure
        The analysed model.
    solution : object
        The solver's result (e.g. :class:`trussfe.fem.static.StaticResult`).
    """

    command: ClassVar[str] = ""
    structure: Structure
    solution: Any

    @property
    def node_ids(self) -> tuple[str, ...]:
        """Node ids, in the order of every ``node`` axis."""
        return tuple(self.structure.node_ids)

    @property
    def member_ids(self) -> tuple[str, ...]:
        """Member ids, in the order of every ``member`` axis."""
        return tuple(self.structure.member_ids)

    @property
    def dim(self) -> int:
        """Spatial dimension, 2 or 3."""
        return int(self.structure.dim)

    def _document(self) -> dict:          # pragma: no cover - every subclass defines it
        raise NotImplementedError

    def to_dict(self) -> dict:
        """The JSON document of ``trussfe COMMAND --json`` (plain lists, numbers, strings;
        non-finite numbers as ``None``)."""
        return plain(self._document())

    def __repr__(self) -> str:
        return (f"<{type(self).__name__} of '{self.structure.name}': "
                f"{self.structure.n_nodes} nodes, {self.structure.n_members} members>")


# --------------------------------------------------------------------------- linear FE
@dataclass(frozen=True, eq=False, repr=False)
class StaticResult(Result):
    """Linear static analysis (:func:`trussfe.static`); ``solution`` is a
    :class:`trussfe.fem.static.StaticResult`.  Global equilibrium holds: the reactions balance
    the applied loads and gravity."""

    command: ClassVar[str] = "static"

    @property
    def displacement(self) -> np.ndarray:
        """Node translations, shape (node, dim), m."""
        return self.solution.displacements[:, :self.dim]

    @property
    def rotation(self) -> np.ndarray:
        """Node rotations, shape (node, 1) in 2-D or (node, 3) in 3-D, rad (zero at nodes
        without rotational freedom)."""
        return self.solution.displacements[:, self.dim:]

    @property
    def reaction(self) -> np.ndarray:
        """Support reaction forces, shape (node, dim), N (zero where not supported)."""
        return self.solution.reactions[:, :self.dim]

    @property
    def reaction_moment(self) -> np.ndarray:
        """Support reaction moments, shape (node, 1 or 3), N·m."""
        return self.solution.reactions[:, self.dim:]

    @property
    def axial_force(self) -> np.ndarray:
        """Member axial force, shape (member,), N (tension positive)."""
        return self.solution.axial_force

    @property
    def axial_stress(self) -> np.ndarray:
        """Axial stress N/A, shape (member,), Pa."""
        return self.solution.axial_stress

    @property
    def strain(self) -> np.ndarray:
        """Axial strain N/(EA), shape (member,)."""
        return self.solution.strain

    @property
    def max_von_mises(self) -> np.ndarray:
        """Largest von Mises stress along each member, shape (member,), Pa."""
        return self.solution.max_von_mises

    @property
    def end_forces(self) -> np.ndarray:
        """Section forces at the member ends, shape (member, 2, 6): start and end;
        N, Vy, Vz, T, My, Mz in member axes."""
        return self.solution.end_forces

    @property
    def section_forces(self) -> np.ndarray:
        """Section forces at the stations, shape (member, station, 6)."""
        return self.solution.section_forces

    @property
    def station_x(self) -> np.ndarray:
        """Station positions along each member, shape (member, station), m."""
        return self.solution.station_x

    @property
    def residual(self) -> float:
        """Relative residual of the linear solve."""
        return float(self.solution.residual)

    def _document(self) -> dict:
        from ..fem.static import static_json
        return static_json(self.solution)


@dataclass(frozen=True, eq=False, repr=False)
class ModesResult(Result):
    """Modal analysis (:func:`trussfe.modes`); ``solution`` is a
    :class:`trussfe.fem.modal.ModalResult`."""

    command: ClassVar[str] = "modes"

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Natural frequencies, shape (mode,), Hz, ascending."""
        return self.solution.frequencies_hz

    @property
    def shapes(self) -> np.ndarray:
        """Mass-normalised mode shapes at the nodes, shape (mode, node, dim), m·kg^-½."""
        return self.solution.node_shapes()[:, :, :self.dim]

    @property
    def participation(self) -> np.ndarray:
        """Participation factors, shape (mode, dim)."""
        return self.solution.participation

    @property
    def effective_mass(self) -> np.ndarray:
        """Effective modal masses, shape (mode, dim), kg."""
        return self.solution.effective_mass

    @property
    def total_mass(self) -> np.ndarray:
        """Total mass per axis, shape (dim,), kg."""
        return self.solution.total_mass

    @property
    def kinds(self) -> tuple[str, ...]:
        """``"rigid"`` (zero frequency) or ``"elastic"`` per mode."""
        return tuple(self.solution.kinds)

    @property
    def rigid_modes(self) -> int:
        """Number of zero-frequency (rigid-body or mechanism) modes."""
        return int(self.solution.rigid_modes)

    def _document(self) -> dict:
        from ..fem.modal import modes_json
        return modes_json(self.solution)


@dataclass(frozen=True, eq=False, repr=False)
class BucklingResult(Result):
    """Linear buckling analysis (:func:`trussfe.buckling`); ``solution`` is a
    :class:`trussfe.fem.buckling.BucklingResult`."""

    command: ClassVar[str] = "buckling"

    @property
    def load_factors(self) -> np.ndarray:
        """Load factors, shape (mode,), ascending by magnitude (negative = reversed loads)."""
        return self.solution.load_factors

    @property
    def critical_load_factor(self) -> float:
        """Smallest positive load factor (``nan`` if none among the modes computed)."""
        return float(self.solution.critical_load_factor)

    @property
    def shapes(self) -> np.ndarray:
        """Buckling mode shapes at the nodes, shape (mode, node, dim), largest translation 1."""
        return self.solution.node_shapes()[:, :, :self.dim]

    @property
    def axial_force(self) -> np.ndarray:
        """Static member axial force under the reference loads, shape (member,), N."""
        return self.solution.static.axial_force

    @property
    def euler_load(self) -> np.ndarray:
        """Member Euler load (Lacy eq. 2.26, C = 1), shape (member,), N."""
        return self.solution.euler_load

    @property
    def buckling_utilisation(self) -> np.ndarray:
        """Compression over Euler load, shape (member,)."""
        return self.solution.utilisation

    def _document(self) -> dict:
        from ..fem.buckling import buckling_json
        return buckling_json(self.solution)


# --------------------------------------------------------------------------- rigid body
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
        return self.solution.sections.tension

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
        """One of :attr:`QUANTITIES` for every actuator, shape (step, actuator)."""
        if quantity not in self.QUANTITIES:
            raise KeyError(f"{quantity!r}; have {', '.join(self.QUANTITIES)}")
        h = self.solution.actuators
        return np.stack([np.asarray(h[a][quantity], dtype=float) for a in self.actuator_ids],
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
            out[act.name] = {
                "self_locking": bool(act.self_locking),
                "self_locking_limit": act.self_locking_limit,
                "leadscrew_gain": act.leadscrew_gain,
                "gearhead_gain": float(h["gearhead_gain"]),
                "gearhead_gain_selected": bool(h["gearhead_gain_selected"]),
                "convention": act.convention,
                **{k: peak(np.asarray(h[k])) for k in self.QUANTITIES},
                "flags": list(h["flags"]),
            }
        return {"units": "SI", "command": "actuators", "model": self.structure.name,
                "actuators": out}


# --------------------------------------------------------------------------- elastic
@dataclass(frozen=True, eq=False, repr=False)
class ElasticResult(Result):
    """Finite-element response along a rigid-body motion (:func:`trussfe.elastic`).

    ``solution`` is the :class:`trussfe.elastic.along_motion.ElasticResponse`; ``rigid`` the
    rigid-body :class:`~trussfe.rigid.simulate.SimulationResult` of the same motion and
    ``comparison`` the largest scaled FE − rigid differences
    (:func:`trussfe.elastic.along_motion.compare_with_rigid`).
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
        return {"units": "SI", "command": "elastic", "model": s.name,
                "bar_model": "pinned-beam", "subdivisions": resp.subdivisions,
                "time": sim.time.tolist(), "members": members, "nodes": nodes,
                "comparison": self.comparison}


@dataclass(frozen=True, eq=False, repr=False)
class TransientResult(Result):
    """Elastic vibration superposed on a prescribed motion (:func:`trussfe.transient`);
    ``solution`` is a :class:`trussfe.elastic.transient.TransientResult`, whose attributes
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
        return {"units": "SI", "command": "transient", "model": s.name,
                "time": res.time.tolist(), "members": members,
                "nodes": {nid: {"displacement": res.displacement[:, i].tolist()}
                          for i, nid in enumerate(s.node_ids)},
                "departure": res.departure(),
                "energy": {k: v.tolist() for k, v in res.energy.items()},
                "energy_residual": res.energy_residual(),
                "frequencies_hz": res.frequencies_hz.tolist(),
                "options": {k: (list(v) if isinstance(v, tuple) else v)
                            for k, v in res.options.items()}}


# --------------------------------------------------------------------------- mechanisms
def _free_to_nodes(free: np.ndarray, columns: np.ndarray) -> np.ndarray:
    """Columns over the free coordinates, shape (f, k), as node vectors (k, node, dim)."""
    n, dim = free.shape
    out = np.zeros((columns.shape[1], n * dim))
    out[:, np.flatnonzero(free.ravel())] = columns.T
    return out.reshape(-1, n, dim)


@dataclass(frozen=True, eq=False, repr=False)
class MechanismResult(Result):
    """Rank analysis of the bar assembly (:func:`trussfe.mechanism`); ``solution`` is a
    :class:`trussfe.kinematics.rank.RankResult`.  Beams are analysed as pin-jointed bars."""

    command: ClassVar[str] = "mechanism"

    @property
    def rank(self) -> int:
        """ρ(B), the rank of the compatibility matrix."""
        return int(self.solution.rank)

    @property
    def mechanisms(self) -> int:
        """Number of internal infinitesimal mechanisms."""
        return int(self.solution.mechanisms)

    @property
    def rigid_body_motions(self) -> int:
        """Rigid-body motions the supports leave free."""
        return int(self.solution.rigid_body_motions)

    @property
    def self_stress_states(self) -> int:
        """Number of independent states of self-stress."""
        return int(self.solution.self_stress_states)

    @property
    def mechanism_shapes(self) -> np.ndarray:
        """Orthonormal mechanism shapes, shape (mechanism, node, dim)."""
        return _free_to_nodes(self.solution.free, self.solution.mechanism_basis)

    @property
    def rigid_body_shapes(self) -> np.ndarray:
        """Rigid-body motions left free, shape (motion, node, dim)."""
        return _free_to_nodes(self.solution.free, self.solution.rigid_body_basis)

    @property
    def self_stress(self) -> np.ndarray | None:
        """Bar tensions of each state of self-stress, shape (state, member), unit norm
        (``None`` when the sparse rank path did not form them)."""
        b = self.solution.self_stress_basis
        return None if b is None else b.T

    def _document(self) -> dict:
        s = self.structure
        r = self.solution

        def shapes(vectors: np.ndarray) -> list:
            out = []
            for d in vectors:
                moving = np.flatnonzero(np.linalg.norm(d, axis=1) > 1e-12)
                out.append({s.node_ids[i]: d[i].tolist() for i in moving})
            return out

        doc = {
            "units": "SI", "command": "mechanism", "model": s.name,
            "rank": r.rank, "mechanisms": r.mechanisms,
            "rigid_body_motions": r.rigid_body_motions,
            "self_stress_states": r.self_stress_states,
            "coordinates": r.n_coordinates, "bars": r.n_bars,
            "infinitesimal_motions": r.infinitesimal_motions,
            "statically_determinate": r.statically_determinate,
            "kinematically_determinate": r.kinematically_determinate,
            "classification": r.classification,
            "tolerance": r.tolerance,
            "smallest_kept_singular_value": r.smallest_kept,
            "largest_dropped_singular_value": r.largest_dropped,
            "mechanism_modes": shapes(self.mechanism_shapes),
            "rigid_body_modes": shapes(self.rigid_body_shapes),
        }
        if r.self_stress_basis is not None:
            doc["self_stress_modes"] = [
                {s.member_ids[i]: float(v) for i, v in enumerate(r.self_stress_basis[:, k])
                 if abs(v) > 1e-12} for k in range(r.self_stress_states)]
        if any(s.is_beam):
            doc["note"] = "beams are analysed as pin-jointed bars"
        return doc


@dataclass(frozen=True, eq=False, repr=False)
class TraceResult(Result):
    """A traced finite-mechanism motion (:func:`trussfe.trace`); ``solution`` is a
    :class:`trussfe.kinematics.trace.TraceResult`.  ``options`` holds the drive, step,
    steps and branch of the JSON document."""

    command: ClassVar[str] = "trace"
    options: dict | None = None

    @property
    def parameter(self) -> np.ndarray:
        """Path parameter of every state, shape (state,), m."""
        return self.solution.parameter

    @property
    def position(self) -> np.ndarray:
        """Joint positions of every state, shape (state, node, dim), m."""
        return self.solution.coords

    @property
    def displacement(self) -> np.ndarray:
        """Motion from the start state, shape (state, node, dim), m."""
        return self.solution.coords - self.solution.coords[:1]

    @property
    def rank(self) -> np.ndarray:
        """ρ(B) of every state, shape (state,)."""
        return self.solution.rank

    @property
    def residual(self) -> np.ndarray:
        """Largest bar-length misfit of every state, shape (state,), m."""
        return self.solution.residual

    @property
    def events(self) -> list:
        """Bifurcation and limit points: ``{"step": k, "kind": ...}``."""
        return self.solution.events

    def _document(self) -> dict:
        s = self.structure
        r = self.solution
        path = []
        for k in range(r.coords.shape[0]):
            entry = {"parameter": float(r.parameter[k]),
                     "positions": {nid: r.coords[k, i].tolist()
                                   for i, nid in enumerate(s.node_ids)},
                     "rank": int(r.rank[k]), "residual": float(r.residual[k])}
            if k > 0:
                entry["iterations"] = int(r.iterations[k - 1])
            path.append(entry)
        o = self.options or {}
        return {"units": "SI", "command": "trace", "model": s.name, "drive": o.get("drive"),
                "step": o.get("step"), "steps": o.get("steps"), "branch": o.get("branch"),
                "path": path, "events": r.events}


# --------------------------------------------------------------------------- post-critical
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
