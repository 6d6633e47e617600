# SPDX-License-Identifier: MIT
"""Bar-and-joint mechanisms: :func:`mechanism` (rank analysis, Hortobágyi 1999 §2) and
:func:`trace` (finite-mechanism motion, Hortobágyi's algorithm)."""
from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from ..errors import InputError
from ..io.json_document import result_json
from .model import ModelLike, as_structure
from .options import (flag, nonneg_int, positive_int, progress_callback, real,
                      relative_tolerance)
from .numerics import numerics_checked
from .results import Result


#: Loosest bar-length tolerance of a trace (relative to the longest bar).
TRACE_TOLERANCE_LIMIT = 1e-4


@numerics_checked
def mechanism(model: ModelLike, *, tolerance: float | None = None,
              max_order: int = 64) -> MechanismResult:
    """Rank analysis of the bar assembly (``trussfe mechanism``): ρ(B), internal
    infinitesimal mechanisms, rigid-body motions the supports leave free, states of
    self-stress, determinacy, and the order of the infinitesimal mechanism (Hortobágyi 1999
    §7: compatible to which order of the successive compatibility equations).

    Parameters
    ----------
    model : Structure, path or dict
    tolerance : float, optional
        Relative singular-value tolerance (default 1e3·eps·max(max(b, f), X/l_min):
        the round-off of B and of its direction cosines, X the largest coordinate
        magnitude, l_min the shortest bar).
    max_order : int
        Highest order of the compatibility equations examined for the order (2 … 4096).

    Returns
    -------
    MechanismResult
        ``rank``, ``mechanisms``, ``mechanism_shapes`` (mechanism, node, dim),
        ``self_stress`` (state, member), ``order``, …
    """
    from ..kinematics.order import mechanism_order
    from ..kinematics.rank import structure_rank

    if isinstance(max_order, bool) or not isinstance(max_order, (int, np.integer)) \
            or not 2 <= max_order <= MAX_ORDER_LIMIT:
        raise InputError("--max-order", f"must be an integer from 2 to {MAX_ORDER_LIMIT}, "
                                        f"got {max_order!r}")
    tolerance = relative_tolerance("--tolerance", tolerance)
    structure = as_structure(model)
    rank = structure_rank(structure, tolerance=tolerance)
    order = mechanism_order(structure.coords, structure.connectivity,
                            ~structure.translation_supports, max_order=int(max_order),
                            rank=rank)
    return MechanismResult(structure, rank, order_analysis=order)


#: Largest ``max_order`` accepted: the work grows with its square.
MAX_ORDER_LIMIT = 4096


@numerics_checked
def trace(model: ModelLike, *, drive: str | Sequence[str], step: float | Sequence[float],
          steps: int, branch: int = 0, tolerance: float = 1e-10,
          frozen: bool = False, progress: Callable[[int, int], None] | None = None) -> TraceResult:
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
        Relative bar-length tolerance of the corrector (at most 1e-4).
    frozen : bool
        Keep B11 of the predicted state (the paper's iteration) instead of Newton's refresh.
    progress : callable, optional
        Called as ``progress(step, steps)`` before every step (a progress bar; it may raise
        ``KeyboardInterrupt`` to stop the trace).

    Returns
    -------
    TraceResult
        ``position`` (state, node, dim), ``parameter`` and ``rank`` (state,), ``events``.
    """
    from ..kinematics.trace import trace_structure

    if isinstance(drive, str):
        drives = [drive]
    elif isinstance(drive, (Sequence, np.ndarray)) and all(isinstance(d, str) for d in drive):
        drives = list(drive)
    else:
        raise InputError("--drive", f"expected NODE:AXIS (e.g. 3:y) or a list of them, "
                                    f"got {drive!r}")
    given = (np.ravel(step).tolist() if isinstance(step, np.ndarray) else list(step)
             if isinstance(step, Sequence) and not isinstance(step, str) else [step])
    steps_ = [real("--step", s, nonzero=True, optional=False) for s in given]
    if len(steps_) == 1 and len(drives) > 1:
        steps_ = steps_ * len(drives)
    if len(steps_) != len(drives):
        raise InputError("--step", f"give one --step per --drive ({len(drives)} drives, "
                                   f"{len(steps_)} steps)")
    steps = positive_int("--steps", steps, optional=False)
    branch = nonneg_int("--branch", branch)
    tolerance = relative_tolerance("--tolerance", tolerance, optional=False)
    if tolerance > TRACE_TOLERANCE_LIMIT:
        # the rank decisions along the trace are made at 100 × the bar-length tolerance: at
        # 1e-2 every singular value of a regular four-bar counts as zero
        raise InputError("--tolerance", f"{tolerance:g} is too loose a bar-length tolerance "
                         f"for a trace (at most {TRACE_TOLERANCE_LIMIT:g}: the rank of the "
                         "compatibility matrix is decided at 100 times it)")
    frozen = flag("--frozen", frozen)
    progress = progress_callback(progress)
    structure = as_structure(model)
    r = trace_structure(structure, drives, steps_ if len(steps_) > 1 else steps_[0], steps,
                        branch=branch, tolerance=tolerance, newton=not frozen,
                        progress=progress)
    return TraceResult(structure, r, options={"drive": drives, "step": steps_,
                                              "steps": steps, "branch": branch,
                                              "tolerance": tolerance, "frozen": frozen})


@numerics_checked
def topology(model: ModelLike) -> TopologyResult:
    """Graph description of the assembly (``trussfe topology``; Vlase et al. 2008 §2): the
    bar-only equivalent mechanism (plates triangulated, the ground closed, sliders as edges),
    its complete and reduced incidence matrices, spanning tree and cotree, fundamental cycle
    matrix ``B_f`` (Vlase eq. 2) and complete cycle matrix ``B_a``.

    Parameters
    ----------
    model : Structure, path or dict
        Fully fixed nodes are the ground; a node fixed in all directions but one is a slider
        (a node free in two directions of space is left free, ``planar_supports``); beams
        joined rigidly are a plate.

    Returns
    -------
    TopologyResult
        ``incidence`` (joint, edge), ``fundamental_cycles`` and ``complete_cycles``
        (cycle, edge), ``tree`` and ``cotree`` (edge ids), ``edge_ids``, ``joint_ids``.

    Raises
    ------
    InputError
        A model without members or without a fully fixed node, or a graph in several
        pieces.
    """
    from ..kinematics.model_graph import model_topology

    structure = as_structure(model)
    return TopologyResult(structure, model_topology(structure))


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
    order_analysis: Any = None

    @property
    def order(self) -> int | float | None:
        """Order of the infinitesimal mechanism (Hortobágyi 1999 §7): k when the successive
        compatibility equations are solvable to order k and not k + 1, ``math.inf`` for a
        finite mechanism, None when there is no mechanism or the order is undecided
        (:class:`trussfe.kinematics.order.MechanismOrder` in ``order_analysis`` says why)."""
        return None if self.order_analysis is None else self.order_analysis.order

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
            **result_json("mechanism", s.name),
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
        doc.update(_order_document(self.order_analysis))
        if r.self_stress_basis is not None:
            doc["self_stress_modes"] = [
                {s.member_ids[i]: float(v) for i, v in enumerate(r.self_stress_basis[:, k])
                 if abs(v) > 1e-12} for k in range(r.self_stress_states)]
        if any(s.is_beam):
            doc["note"] = "beams are analysed as pin-jointed bars"
        return doc


def _order_document(o) -> dict:
    """The ``order`` and ``order_analysis`` entries of the mechanism document (docs/json.md)."""
    if o is None:
        return {}
    order = None if o.order is None else "infinite" if o.order == math.inf else int(o.order)
    return {"order": order,
            "order_analysis": {"status": o.status, "checked": o.checked,
                               "max_order": o.max_order,
                               "obstruction": o.obstruction,
                               "obstruction_to_roundoff": o.above_roundoff,
                               "margin": o.margin, "note": o.note}}


@dataclass(frozen=True, eq=False, repr=False)
class TraceResult(Result):
    """A traced finite-mechanism motion (:func:`trussfe.trace`); ``solution`` is a
    :class:`trussfe.kinematics.trace.TraceResult`.  ``options`` holds the drive, step,
    steps, branch, tolerance and frozen of the JSON document."""

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
        return result_json("trace", s.name, drive=o.get("drive"), step=o.get("step"),
                           steps=o.get("steps"), branch=o.get("branch"),
                           tolerance=o.get("tolerance"), frozen=o.get("frozen"), path=path,
                           events=r.events)


@dataclass(frozen=True, eq=False, repr=False)
class TopologyResult(Result):
    """Graph of the equivalent bar-only mechanism (:func:`trussfe.topology`); ``solution``
    is a :class:`trussfe.kinematics.model_graph.ModelTopology`."""

    command: ClassVar[str] = "topology"

    @property
    def joint_ids(self) -> tuple[str, ...]:
        """Joints of the equivalent mechanism (rows of :attr:`incidence`): the model's
        nodes, then the virtual ground point of each slider."""
        return tuple(self.solution.node_ids)

    @property
    def edge_ids(self) -> tuple[str, ...]:
        """Edges (columns of every matrix): member ids, then the added plate, slider and
        ground edges."""
        return tuple(self.solution.edge_ids)

    @property
    def edge_kinds(self) -> tuple[str, ...]:
        """``"bar"``, ``"plate"``, ``"ground"`` or ``"slider"`` for every edge."""
        return tuple(str(k) for k in self.solution.assembly.kinds)

    @property
    def incidence(self) -> np.ndarray:
        """Complete incidence matrix ``A_a``, shape (joint, edge): +1 where the edge leaves
        the joint, −1 where it enters."""
        return self.solution.incidence.toarray()

    @property
    def reduced_incidence(self) -> np.ndarray:
        """``A``: ``A_a`` without the row of the reference joint (the tree's root)."""
        return self.solution.graph.reduced_incidence.toarray()

    @property
    def tree(self) -> tuple[str, ...]:
        """Edges of the spanning tree."""
        return tuple(self.solution.edge_ids[j] for j in self.solution.graph.tree)

    @property
    def cotree(self) -> tuple[str, ...]:
        """The links: edges not in the tree, one per fundamental cycle."""
        return tuple(self.solution.edge_ids[j] for j in self.solution.graph.links)

    @property
    def fundamental_cycles(self) -> np.ndarray:
        """``B_f`` (Vlase eq. 2), shape (link, edge)."""
        return self.solution.graph.cycle_matrix

    @property
    def complete_cycles(self) -> np.ndarray | None:
        """``B_a``, every simple cycle, shape (cycle, edge); ``None`` when the cycle space
        has more than 16 dimensions."""
        return self.solution.complete_cycles

    def _document(self) -> dict:
        t = self.solution
        eq = t.assembly
        ids = t.node_ids
        edges = []
        for j, ((a, b), kind) in enumerate(zip(eq.connectivity, eq.kinds)):
            edges.append({"id": t.edge_ids[j], "kind": str(kind), "nodes": [ids[a], ids[b]],
                          "length": float(np.linalg.norm(eq.coords[b] - eq.coords[a]))})
        g = t.graph
        Ba = t.complete_cycles
        return {
            **result_json("topology", self.structure.name),
            "counts": {"joints": len(ids), "edges": len(edges),
                       "tree_edges": int(g.tree.size), "links": int(g.links.size),
                       "cycles": None if Ba is None else int(Ba.shape[0])},
            "joints": list(ids),
            "ground": [ids[i] for i in eq.ground],
            "reference": ids[g.reference],
            "plates": t.plates,
            "planar_supports": t.planar_supports,
            "edges": edges,
            "incidence": self.incidence,
            "reduced_incidence": self.reduced_incidence,
            "tree": list(self.tree),
            "cotree": list(self.cotree),
            "fundamental_cycles": self.fundamental_cycles,
            "complete_cycles": Ba,
        }
