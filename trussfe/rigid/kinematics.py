# SPDX-License-Identifier: MIT
"""Kinematics of a truss along a prescribed motion of its active members.

At every time step (Lacy sections 2.3 and 4.4, done here for any topology):

1. **positions** from the member lengths by the general forward-position solver, warm-started
   from the previous step (:func:`trussfe.kinematics.solve_positions`);
2. **velocities** from the compatibility equations ``B v = dL/dt`` (active members prescribed,
   passive members zero);
3. **accelerations** from their time derivative, per member

   .. math:: e\\cdot(a_b - a_a) = \\ddot L - \\frac{\\lVert v_b - v_a\\rVert^2 - \\dot L^2}{L},

   i.e. ``B a = d2L/dt2 - (|v_rel|^2 - (dL/dt)^2)/L`` — exact, no finite differences;
4. each member's unit vector e, its rates ė = (v_rel − L̇ e)/L and
   ë = (a_rel − L̈ e − 2 L̇ ė)/L, angular velocity ω = e × ė and acceleration α = e × ë
   (a slender member has no spin about its own axis).

``scheme="thesis"`` reproduces Lacy's Appendix A instead: member angles at each step, angular
rates by backward differences (ω = α = 0 at the first step), node accelerations from the
rigid-member formulas (eqs. 2.3–2.8) walking from the supports along the members, and the
active members' own rates from the motion model.  Its results depend on the step size.

All vectors are stored in 3-D (the z component is zero for planar trusses), array axes
``(time, member or node, component)``.
"""
from __future__ import annotations

import logging
from collections import deque
from dataclasses import dataclass
from functools import cached_property

from typing import Callable

import numpy as np

from ..errors import AnalysisError
from ..kinematics.assembly import solve_positions
from ..kinematics.compatibility import compatibility_matrix
from ..linalg import factor
from ..mechanics.geometry import lengths, member_vectors, unit_vectors
from ..model.derived import kept, read_only
from ..model.structure import Structure
from ..threads import block_steps, contiguous_spans, parallel_map, worker_count
from .linalg import (ANCHOR_SPACING, BlockTriangularForm, CompatSolver, SingularStep,
                     block_triangular_form, is_direct)
from ..vectors import components_first, cross, dot, empty_vectors, is_components_first
from .motion import Motion

log = logging.getLogger(__name__)


@dataclass
class Kinematics:
    """Positions, velocities and accelerations along a motion.

    Attributes
    ----------
    time : ndarray, shape (nt,)
    coords : ndarray, shape (nt, n, dim)
        Node positions.
    velocity, acceleration : ndarray, shape (nt, n, 3)
        Node velocities and accelerations (z = 0 in 2-D).
    length, length_rate, length_acc : ndarray, shape (nt, m)
        Member length L, L̇, L̈.
    unit, unit_rate, unit_acc : ndarray, shape (nt, m, 3)
        Member unit vector e (start → end node), ė, ë.
    omega, alpha : ndarray, shape (nt, m, 3)
        Member angular velocity and acceleration.
    scheme : str
        ``"exact"`` or ``"thesis"``.
    """

    time: np.ndarray
    coords: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    length: np.ndarray
    length_rate: np.ndarray
    length_acc: np.ndarray
    unit: np.ndarray
    unit_rate: np.ndarray
    unit_acc: np.ndarray
    omega: np.ndarray
    alpha: np.ndarray
    scheme: str = "exact"
    #: Factorised compatibility matrices (free coordinates × loaded members) of every step,
    #: reused for velocities, accelerations and (transposed) member forces.
    compat: CompatSolver | None = None

    @property
    def n_steps(self) -> int:
        """Number of time steps."""
        return self.time.size

    def at_rest(self) -> "Kinematics":
        """The same positions with every rate and acceleration zero (the static case)."""
        z3 = np.zeros_like(self.velocity)
        zm = np.zeros_like(self.length)
        zu = np.zeros_like(self.unit)
        return Kinematics(self.time, self.coords, z3, z3.copy(), self.length, zm, zm.copy(),
                          self.unit, zu, zu.copy(), zu.copy(), zu.copy(), self.scheme,
                          self.compat)


def pad3(x: np.ndarray) -> np.ndarray:
    """Pad the last axis of a 2-D vector array to 3 components (stored components first
    when ``x``'s are, :mod:`trussfe.vectors`)."""
    if x.shape[-1] == 3:
        return x
    if is_components_first(x):
        out = empty_vectors(x.shape[:-1] + (3,))
        out[..., :x.shape[-1]] = x
        out[..., x.shape[-1]:] = 0.0
        return out
    return np.concatenate([x, np.zeros(x.shape[:-1] + (3 - x.shape[-1],))], axis=-1)


def _step_item(motion: Motion, k: int) -> str:
    """The item of an error at step ``k`` of ``motion``, naming the motion's source (its
    file) first where it has one, as :func:`~trussfe.rigid.motion.check_stroke` does."""
    where = f"{motion.source}: motion" if motion.source else "motion"
    return f"{where}: step {motion.first_step + k} (t = {motion.time[k]:.6g} s)"


def member_histories(driven: np.ndarray, members: np.ndarray, rest: np.ndarray | float,
                     out: np.ndarray) -> np.ndarray:
    """Every member's value at some steps written into ``out`` (steps, m) and returned: the
    driven ``members``' from ``driven`` (steps, len(members)), every other member's
    ``rest`` (its model length, or 0 for a length rate or acceleration)."""
    out[...] = rest
    out[:, members] = driven
    return out


#: Relative slack of :func:`check_fixed_members` (round-off of a length written to a file).
FIXED_LENGTH_TOLERANCE = 1e-9


def check_fixed_members(structure: Structure, motion: Motion) -> None:
    """Refuse a motion that changes the length of a member between two held nodes.

    A member whose two nodes are held in every direction takes no part in the assembly
    (:class:`_Pattern`: it constrains nothing), so the position solver never sees its
    length, and the member keeps the distance of its supports whatever the motion asks.  A
    motion that asks another length describes no assembly (Lacy section 2.3: the lengths
    fix the positions), and computing on would pair the supports' distance with the
    motion's length rate in the member's inertia loads (eqs. 2.3–2.5, 4.58–4.61).

    Raises
    ------
    AnalysisError
        Naming the first step and the member, when a driven member between held nodes
        departs from its supports' distance by more than :data:`FIXED_LENGTH_TOLERANCE`
        (relative).
    """
    pattern = _Pattern.of(structure)
    members = np.asarray(motion.members)
    grounded = np.flatnonzero(~pattern.loaded[members])
    if grounded.size == 0:
        return
    L0 = structure.lengths()[members[grounded]]
    off = np.abs(motion.length[:, grounded] - L0) > FIXED_LENGTH_TOLERANCE * L0
    if not off.any():
        return
    k, j = (int(i) for i in np.argwhere(off)[0])
    c = int(grounded[j])
    raise AnalysisError(_step_item(motion, k), f"active member "
                        f"'{structure.member_ids[int(members[c])]}' joins two supported "
                        f"nodes {L0[j]:.6g} m apart, but the motion asks "
                        f"{motion.length[k, c]:.6g} m: no assembly has that length (support "
                        "one of its nodes less, or leave it out of the motion)")


def _member_lengths(structure: Structure, motion: Motion) -> np.ndarray:
    """Member lengths at every step: passive members keep their model length, (nt, m)."""
    return member_histories(motion.length, motion.members, structure.lengths(),
                            np.empty((motion.n_steps, structure.n_members)))


def solve_motion_positions(structure: Structure, motion: Motion,
                           coords0: np.ndarray | None = None,
                           progress: Callable[[int, int], None] | None = None
                           ) -> np.ndarray:
    """Node positions at every step of the motion, warm-started step to step.

    Parameters
    ----------
    structure : Structure
    motion : Motion
    coords0 : ndarray, optional
        Starting guess for the first step (default: the model's coordinates).
    progress : callable, optional
        Called as ``progress(done, total)`` as the steps are solved one after the other.

    Returns
    -------
    ndarray, shape (nt, n, dim)

    Raises
    ------
    AnalysisError
        Naming the time step and the members when no assembly exists for the lengths, or when
        the assembly passes a singular position.
    """
    check_fixed_members(structure, motion)
    L = _member_lengths(structure, motion)
    x0 = np.array(structure.coords if coords0 is None else coords0, dtype=float)
    nt = motion.n_steps
    pattern = _Pattern.of(structure)
    if nt > BATCH_MIN_STEPS and pattern.m == pattern.nfree:
        # Follow the branch on a coarse subset of steps, then polish every step at once.
        idx = np.unique(np.linspace(0, nt - 1, COARSE_STEPS).round().astype(int))
        coarse = _sequential_positions(structure, motion, L, x0, idx, progress)
        guess = np.empty((nt,) + x0.shape)
        flat = coarse.reshape(idx.size, -1)
        for c in range(flat.shape[1]):          # interpolate each coordinate in time
            guess.reshape(nt, -1)[:, c] = np.interp(motion.time, motion.time[idx], flat[:, c])
        X, ok = _batched_newton(structure, pattern, L, guess)
        if ok.all():
            return X
        redo = np.flatnonzero(~ok)
        log.info("positions: %d of %d steps re-solved one by one", redo.size, nt)
        start = X[redo[0] - 1] if redo[0] > 0 else x0
        X[redo[0]:] = _sequential_positions(structure, motion, L, start,
                                            np.arange(redo[0], nt), progress)
        return X
    return _sequential_positions(structure, motion, L, x0, np.arange(nt), progress)


#: Motions longer than this are solved by coarse continuation + batched Newton.
BATCH_MIN_STEPS = 120
#: Steps of the coarse continuation.
COARSE_STEPS = 20


def _sequential_positions(structure, motion, L, x0, steps, progress) -> np.ndarray:
    """Warm-started forward position, one step after the other, at the given step indices."""
    fixed = structure.translation_supports
    # Members between two fixed nodes neither move nor constrain: leaving them out keeps the
    # Newton system square (sparse LU instead of least squares).
    keep = _Pattern.of(structure).loaded_idx
    conn = structure.connectivity[keep]
    ids = [structure.member_ids[i] for i in keep]
    x = x0
    out = np.empty((len(steps),) + x0.shape)
    for j, k in enumerate(steps):
        if progress is not None:
            progress(j, len(steps))
        try:
            r = solve_positions(x, conn, L[k, keep], fixed, member_ids=ids,
                                item=_step_item(motion, k))
        except AnalysisError as err:
            # Newton starts from the position of the step before (``x``): when that position
            # is singular, no step can leave it, and the step at fault is that one (a motion
            # that starts at a singular position fails at its step 0, not at step 1)
            before = steps[j - 1] if j > 0 else (steps[0] - 1 if steps[0] > 0 else None)
            if before is not None and _singular_at(x, conn, fixed):
                item, k = _step_item(motion, before), before
                what = ("the assembly is at a singular position (its compatibility matrix is "
                        "rank deficient there): no unique position follows it")
            else:
                item, what = err.item, err.message
            acts = ", ".join(f"'{structure.member_ids[i]}' = {motion.length[k, c]:.6g} m"
                             for c, i in enumerate(motion.members[:6]))
            if motion.members.size > 6:
                acts += f", … ({motion.members.size} active members)"
            raise AnalysisError(item, f"{what} (active lengths {acts})") from None
        x = r.coords
        out[j] = x
    return out


def _singular_at(x: np.ndarray, conn: np.ndarray, fixed: np.ndarray) -> bool:
    """Whether the compatibility matrix of the bars ``conn`` at positions ``x`` is singular
    (the square system of a statically determinate truss; the test of
    :func:`~trussfe.kinematics.assembly.solve_positions`' Newton step)."""
    B = compatibility_matrix(x, conn, ~np.asarray(fixed, dtype=bool))
    if B.shape[0] != B.shape[1]:
        return False
    return bool(factor(B, "general", singular="flag").is_singular)


#: Steps per chunk below which the batched Newton iteration is not split between threads.
PARALLEL_NEWTON_MIN_STEPS = 200


def _batched_newton(structure, pattern, L, X, tolerance=1e-12, iterations=30):
    """Chord (modified) Newton on the bar-length equations of every step of the whole truss
    at once, from the guesses ``X`` (:func:`chord_newton`).

    The Jacobian (the compatibility matrix) is factorised once at the interpolated guess and
    reused: the guess is close, so the iteration contracts fast, and one factorisation per
    step costs far less than one per iteration.  The chord Jacobian of a step is its nearest
    anchor's (every :data:`ANCHOR_SPACING`-th step of the motion, and the last).  Returns
    the positions and a per-step flag: converged and within a tenth of the truss size of its
    guess (so that no step has jumped to another assembly branch).
    """
    nt = X.shape[0]
    anchors = np.unique(np.r_[np.arange(0, nt, ANCHOR_SPACING), nt - 1])
    owner = np.searchsorted((anchors[1:] + anchors[:-1]) / 2.0, np.arange(nt))
    # anchored refinement (approximate solves) where B has no direct factorisation
    return chord_newton(structure.connectivity, pattern, L, X.copy(), X, anchors, owner,
                        min_chunk_steps=PARALLEL_NEWTON_MIN_STEPS, approximate=True,
                        tolerance=tolerance, iterations=iterations)


def chord_newton(conn: np.ndarray, pattern: "_Pattern", L: np.ndarray, X: np.ndarray,
                 guess: np.ndarray, anchors: np.ndarray | None = None,
                 owner: np.ndarray | None = None, *, refactor_every: int = 0,
                 min_chunk_steps: int = PARALLEL_NEWTON_MIN_STEPS, approximate: bool = False,
                 tolerance: float = 1e-12, iterations: int = 30
                 ) -> tuple[np.ndarray, np.ndarray]:
    """Chord Newton iteration on the bar-length equations ``|x_b − x_a| = L`` of every step
    at once (Hortobágyi eqs. 1–2), in place on the positions ``X`` (nt, n, dim).

    ``B Δx = L − |d|`` is solved for all steps together with B factorised at the start (and,
    with ``refactor_every`` = k > 0, at every k-th iteration) at the anchor steps:
    ``anchors`` (step indices) with ``owner`` (the anchor of every step, indices into
    ``anchors``), or every step its own anchor when ``anchors`` is None.  Stacked inverses
    (:class:`~trussfe.rigid.linalg.CompatSolver`) are factorised at the anchors of each chunk
    of steps and gathered once for its steps; a B without them is factorised at every step,
    its solves anchored refinements when ``approximate``.

    Long runs (``min_chunk_steps`` steps per worker thread and more) are split into
    contiguous chunks of steps between worker threads, in lockstep: one convergence test over
    all steps per iteration and the whole run's anchors, so that every step's arithmetic is
    that of the whole-run iteration and the positions do not depend on the number of threads
    (the same numbers, bit for bit).

    Returns
    -------
    X : ndarray
        The positions (the array passed in).
    ok : ndarray of bool, shape (nt,)
        Converged and within a tenth of the largest length of ``guess``
        (:func:`accepted_positions`); all False when a factorisation is singular or a step
        not finite.
    """
    nt = X.shape[0]
    scale = float(L.max()) if nt else 1.0
    Lk = L[:, pattern.loaded_cols]
    flat = X.reshape(nt, -1)
    failed = (X, np.zeros(nt, dtype=bool))
    spans = contiguous_spans(nt, min(worker_count(), nt // min_chunk_steps))
    direct = pattern.direct

    def values(steps):
        """B's values at the current positions of ``steps`` (the unit vectors' components)."""
        return pattern.values(unit_vectors(member_vectors(X[steps], conn))[0])

    def chunk_solver(ab):
        """The stacked inverses at the anchors of a chunk's steps, gathered once for every
        step (each anchor's inverse is the same in any subset of the anchors)."""
        a, b = ab
        if anchors is None:
            return pattern.solver(values(slice(a, b)))
        first, last = owner[a], owner[b - 1]
        part = pattern.solver(values(anchors[first:last + 1]))
        return part.gather(owner[a:b] - first)

    pending: list | None = None       # the last corrections, one per chunk, not yet added

    def advance(j):
        """A chunk's pending correction added to its positions (in its worker thread)."""
        a, b = spans[j]
        flat[a:b, pattern.free_cols] += pending[j]

    def residual(j):
        """The chunk's pending correction added, then the bar lengths of its steps, the
        misfit of the loaded bars and its largest magnitude."""
        a, b = spans[j]
        if pending is not None:
            advance(j)
        now = lengths(member_vectors(X[a:b], conn))
        r = now[:, pattern.loaded_cols] - Lk[a:b]
        return now, r, np.abs(r).max()

    def correction(j):
        """The chunk's chord-Newton correction and whether it is finite."""
        dx = local[j].solve(-parts[j])
        return dx, bool(np.all(np.isfinite(dx)))

    local = solver = None
    current = None                    # the bar lengths of the final positions, if known
    for it in range(iterations):
        parts = parallel_map(residual, range(len(spans)))
        pending = None
        if max(worst for _, _, worst in parts) <= tolerance * scale:
            current = [now for now, _, _ in parts]
            break
        parts = [r for _, r, _ in parts]
        if it == 0 or (refactor_every and it % refactor_every == 0):
            try:
                if direct:
                    local = parallel_map(chunk_solver, spans)
                else:
                    solver = pattern.solver(values(slice(None)))
            except SingularStep:
                return failed
        if local is None:
            dx = solver.solve(-np.concatenate(parts), approximate=approximate)
            if not np.all(np.isfinite(dx)):
                return failed
            pending = [dx[a:b] for a, b in spans]
        else:
            solved = parallel_map(correction, range(len(spans)))
            if not all(finite for _, finite in solved):
                return failed
            pending = [dx for dx, _ in solved]
        # the corrections are added by the chunks' next residual pass, in the worker threads
    if pending is not None:           # the iterations ran out: the last corrections still count
        parallel_map(advance, range(len(spans)))
    return X, accepted_positions(X, guess, L, conn, scale, spans, tolerance, current)


def accepted_positions(X: np.ndarray, guess: np.ndarray, L: np.ndarray, conn: np.ndarray,
                       scale: float, spans: list, tolerance: float = 1e-12,
                       current: list | None = None) -> np.ndarray:
    """Which steps of a batched position solve to accept: the bar lengths ``L`` (nt, m) met
    to ``tolerance · scale`` by the positions ``X`` (nt, n, 3), and no coordinate moved a
    tenth of ``scale`` or more from its ``guess`` (no jump to another assembly branch).  The
    chunks of steps ``spans`` ((start, stop) pairs covering every step) are tested in
    worker threads; ``current``: the bar lengths of ``X``, one array per chunk, if known.

    Returns
    -------
    ndarray of bool, shape (nt,)
    """
    def accept(j):
        a, b = spans[j]
        now = lengths(member_vectors(X[a:b], conn)) if current is None else current[j]
        res = np.abs(now - L[a:b]).max(axis=1)
        moved = np.abs(X[a:b] - guess[a:b]).reshape(b - a, -1).max(axis=1)
        return (res <= tolerance * scale) & (moved < 0.1 * scale)
    return np.concatenate(parallel_map(accept, range(len(spans))))


class _Pattern:
    """Sparsity pattern of B restricted to the free coordinates (same at every step).

    :meth:`of` keeps one with each model (every block of steps of an analysis asks for it).
    """

    @classmethod
    def of(cls, structure: Structure) -> _Pattern:
        """The pattern of ``structure``, made once and kept with it
        (:func:`~trussfe.model.derived.kept`; read-only arrays, shared)."""
        return kept(structure, "rigid compatibility pattern", cls)

    def __init__(self, structure: Structure):
        dim = structure.dim
        conn = structure.connectivity
        free = ~structure.translation_supports
        self.free_flat = np.flatnonzero(free.ravel())
        # the free coordinates as a slice when they are contiguous (supports numbered first):
        # updates of them are then plain strided operations, not gathers and scatters
        f = self.free_flat
        contiguous = f.size > 0 and f[-1] - f[0] + 1 == f.size
        self.free_cols = slice(int(f[0]), int(f[-1]) + 1) if contiguous else f
        full_to_free = -np.ones(structure.n_nodes * dim, dtype=np.int64)
        full_to_free[self.free_flat] = np.arange(self.free_flat.size)
        m = conn.shape[0]
        # (member, end, component) → column among the free coordinates, −1 when fixed.
        cols = full_to_free[(conn[:, :, None] * dim + np.arange(dim)).reshape(m, -1)]
        # Members with a free coordinate carry an unknown axial force; a member between two
        # fixed nodes takes no part in the kinematics or in the global equilibrium.
        self.loaded = np.any(cols >= 0, axis=1)
        self.loaded_idx = np.flatnonzero(self.loaded)
        # the loaded members as a slice when they are contiguous (every member, in a model
        # without bars between supports): their columns are then views, not copies
        li = self.loaded_idx
        self.loaded_cols = (slice(int(li[0]), int(li[-1]) + 1)
                            if li.size and li[-1] - li[0] + 1 == li.size else li)
        cols = cols[self.loaded]
        self.m, self.dim, self.nfree = self.loaded_idx.size, dim, self.free_flat.size
        keep = cols.ravel() >= 0
        self.keep = keep
        self.rows = np.repeat(np.arange(self.m), 2 * dim)[keep]
        self.cols = cols.ravel()[keep]

    @cached_property
    def form(self) -> BlockTriangularForm | None:
        """The pattern's block-triangular form
        (:func:`~trussfe.rigid.linalg.block_triangular_form`), found on first use and kept
        with the pattern (every factorisation of the model's compatibility matrices uses
        it)."""
        return read_only(block_triangular_form(self.rows, self.cols, self.m))

    @property
    def direct(self) -> bool:
        """Whether its solvers keep stacked inverses (:func:`~trussfe.rigid.linalg.is_direct`;
        from the kept form, so not kept itself)."""
        return is_direct(self.rows, self.cols, self.m, self.form)

    def solver(self, values: np.ndarray) -> CompatSolver:
        """The factorised compatibility matrices of the steps whose entries are ``values``
        (nt, nnz) (:meth:`values`).

        Raises
        ------
        SingularStep
            At the first singular step.
        """
        return CompatSolver(self.rows, self.cols, values, self.m, self.form)

    def values(self, unit: np.ndarray) -> np.ndarray:
        """Entries of B for unit vectors ``unit`` (nt, m, dim or 3) → (nt, nnz): ``−e`` at
        the start node's free coordinates, ``+e`` at the end node's (one gather of the
        unit vectors' components and a sign)."""
        nt, _, du = unit.shape
        src, sign = self._gather(du)
        vals = np.take(unit.reshape(nt, -1), src, axis=1)
        vals *= sign
        return vals

    def _gather(self, du: int) -> tuple[np.ndarray, np.ndarray]:
        """Flat component index into a (m, du) unit-vector array and sign of every entry."""
        cache = self.__dict__.setdefault("_gathers", {})
        if du not in cache:
            comp = np.arange(self.dim)
            src = np.broadcast_to(self.loaded_idx[:, None, None] * du + comp[None, None, :],
                                  (self.m, 2, self.dim)).ravel()[self.keep]
            sign = np.broadcast_to(np.array([-1.0, 1.0])[None, :, None],
                                   (self.m, 2, self.dim)).ravel()[self.keep]
            cache[du] = (src, sign)
        return cache[du]


def _solve_compat(structure: Structure, pattern: _Pattern, solver: CompatSolver,
                  rhs: np.ndarray) -> np.ndarray:
    """Solve B x = rhs (nt, m) for the free node coordinates; returns (nt, n, dim), its
    components stored first (:mod:`trussfe.vectors`)."""
    nt, n, dim = rhs.shape[0], structure.n_nodes, structure.dim
    try:
        free = solver.solve(rhs[:, pattern.loaded_cols])
    except SingularStep as s:
        raise AnalysisError(f"motion: step {s.step}", "the assembly is at a singular position "
                            "(its compatibility matrix is rank deficient): its velocities and "
                            "accelerations are not determined there; choose a motion that "
                            "avoids it") from None
    out = empty_vectors((nt, n, dim))

    def place(s):
        """The free coordinates of steps ``s`` in their places, the fixed ones zero."""
        flat = np.zeros((s.stop - s.start, n * dim))
        flat[:, pattern.free_cols] = free[s]
        out[s] = flat.reshape(-1, n, dim)
    _in_blocks(nt, n * dim, place)
    return out


def _factorise(pattern: _Pattern, values: np.ndarray, motion: Motion) -> CompatSolver:
    """Factorise the compatibility matrix of every step from its entries ``values``
    (:meth:`_Pattern.values`), or raise at the first singular step (once: velocities,
    accelerations and member forces all use this matrix or its transpose)."""
    try:
        return pattern.solver(values)
    except SingularStep as s:
        raise AnalysisError(_step_item(motion, s.step), "the assembly is at a singular "
                            "position (its compatibility matrix is rank deficient): its "
                            "velocities, accelerations and member forces are not determined "
                            "there; choose a motion that avoids it") from None


def _count_message(pattern: _Pattern) -> str:
    if pattern.m > pattern.nfree:
        return (f"the truss has {pattern.m} members but {pattern.nfree} free node coordinates: "
                "it is statically indeterminate, so its member forces cannot be found from "
                "rigid-body equilibrium; analyse it with the finite-element model "
                "(trussfe static)")
    return (f"the truss has {pattern.m} members but {pattern.nfree} free node coordinates: it is "
            "a mechanism (add members or supports)")


def compute_kinematics(structure: Structure, motion: Motion, *, scheme: str = "exact",
                       coords: np.ndarray | None = None,
                       progress: Callable[[int, int], None] | None = None) -> Kinematics:
    """Kinematics of the structure along the motion.

    Parameters
    ----------
    structure : Structure
        Pin-jointed, statically determinate truss (members = free node coordinates).
    motion : Motion
        Active member histories.
    scheme : {"exact", "thesis"}
        Exact compatibility equations, or Lacy's backward-difference scheme (Appendix A).
    coords : ndarray, optional
        Node positions (nt, n, dim) if already known.
    progress : callable, optional
        ``progress(done, total)`` while solving the positions.

    Returns
    -------
    Kinematics

    Raises
    ------
    AnalysisError
        A statically indeterminate truss or a mechanism, a motion for whose lengths no
        assembly exists, or a singular position (naming the step).  Positions given as
        ``coords`` are taken as they are: :func:`check_fixed_members` is the caller's
        (``simulate`` makes it once, before the positions, for every method).
    """
    if scheme not in ("exact", "thesis"):
        raise AnalysisError("scheme", f"unknown kinematics scheme {scheme!r}; use 'exact' or "
                            "'thesis'")
    pattern = _Pattern.of(structure)
    if pattern.m != pattern.nfree:
        raise AnalysisError(structure.source or structure.name, _count_message(pattern))
    X = (solve_motion_positions(structure, motion, progress=progress) if coords is None
         else coords)
    nt = X.shape[0]
    conn = structure.connectivity
    m = structure.n_members
    L = np.empty((nt, m))
    # the member vectors' histories with their components stored first (fast element-wise
    # arithmetic over them here and in every force computation, trussfe.vectors)
    e = empty_vectors((nt, m, X.shape[2]))

    vals = np.empty((nt, pattern.rows.size))        # the entries of B, every step
    # the length rates and accelerations (the active members' from the motion, zero for
    # the others), filled with the geometry in the worker threads
    Ld, Ldd = np.empty_like(L), np.empty_like(L)

    def geometry(s):
        e[s], L[s] = unit_vectors(member_vectors(components_first(X[s]), conn))
        vals[s] = pattern.values(e[s])
        member_histories(motion.velocity[s], motion.members, 0.0, Ld[s])
        member_histories(motion.acceleration[s], motion.members, 0.0, Ldd[s])
    _in_blocks(nt, m, geometry)
    solver = _factorise(pattern, vals, motion)
    vals = None                                      # not needed once factorised
    e3 = pad3(e)
    if scheme == "exact":
        V = _solve_compat(structure, pattern, solver, Ld)
        vrel = np.empty_like(e)
        rhs = np.empty_like(L)

        def relative_velocity(s):
            vrel[s] = member_vectors(V[s], conn)
            quad = (dot(vrel[s], vrel[s]) - Ld[s] ** 2) / L[s]
            rhs[s] = Ldd[s] - quad
        _in_blocks(nt, m, relative_velocity)
        A = _solve_compat(structure, pattern, solver, rhs)
        ed, edd, omega, alpha = (empty_vectors((nt, m, 3)) for _ in range(4))

        def rates(s):
            arel = member_vectors(A[s], conn)
            Ls, Lds = L[s][..., None], Ld[s][..., None]
            if e.shape[2] == 3:
                _rates_into(ed[s], edd[s], vrel[s], arel, e[s], Ls, Lds, Ldd[s][..., None])
            else:
                ed_s = pad3((vrel[s] - Lds * e[s]) / Ls)
                ed[s] = ed_s
                edd[s] = pad3((arel - Ldd[s][..., None] * e[s]) / Ls) - 2 * Lds * ed_s / Ls
            cross(e3[s], ed[s], out=omega[s])
            cross(e3[s], edd[s], out=alpha[s])
        _in_blocks(nt, m, rates)
        return Kinematics(motion.time, X, components_first(pad3(V)),
                          components_first(pad3(A)), L, Ld, Ldd, e3, ed, edd, omega, alpha,
                          "exact", solver)
    # Lacy Appendix A: angle rates by backward differences.
    omega = np.zeros((nt, structure.n_members, 3))
    if nt > 1:
        dt = np.diff(motion.time)[:, None, None]
        cr = cross(e3[:-1], e3[1:])
        sn = lengths(cr)
        cs = dot(e3[:-1], e3[1:])
        ang = np.arctan2(sn, cs)
        axis = np.divide(cr, sn[..., None], out=np.zeros_like(cr), where=sn[..., None] > 0)
        omega[1:] = axis * ang[..., None] / dt
    alpha = np.zeros_like(omega)
    if nt > 1:
        alpha[1:] = np.diff(omega, axis=0) / np.diff(motion.time)[:, None, None]
    ed = cross(omega, e3)
    edd = cross(alpha, e3) + cross(omega, ed)
    V, A = _walk_nodes(structure, motion, e3, ed, edd, L, Ld, Ldd)
    return Kinematics(motion.time, X, components_first(V), components_first(A), L, Ld, Ldd,
                      e3, ed, edd, omega, alpha, "thesis", solver)


def _rates_into(ed: np.ndarray, edd: np.ndarray, vrel: np.ndarray, arel: np.ndarray,
                e: np.ndarray, L: np.ndarray, Ld: np.ndarray, Ldd: np.ndarray) -> None:
    """ė = (v_rel − L̇ e)/L and ë = (a_rel − L̈ e)/L − 2 L̇ ė / L written into ``ed`` and
    ``edd`` (3-D members), operation for operation as the expressions read, without their
    temporaries (``arel`` is overwritten)."""
    np.multiply(Ld, e, out=ed)
    np.subtract(vrel, ed, out=ed)
    ed /= L
    np.multiply(Ldd, e, out=edd)
    np.subtract(arel, edd, out=edd)
    edd /= L
    np.multiply(2 * Ld, ed, out=arel)
    arel /= L
    edd -= arel


#: Members × steps per block of the element-wise kinematics (:func:`_in_blocks`).
BLOCK_ENTRIES = 1 << 17


def _in_blocks(nt: int, m: int, fn: Callable[[slice], None]) -> None:
    """``fn(steps)`` over blocks of at most :data:`BLOCK_ENTRIES` members × steps, of equal
    size for the worker threads (:func:`~trussfe.threads.block_steps`): element-wise work on
    the motion's arrays, each block written into whole-motion arrays while it is in the
    processor cache (every step computed as in any block)."""
    step = block_steps(nt, BLOCK_ENTRIES // max(m, 1))
    parallel_map(lambda k0: fn(slice(k0, min(nt, k0 + step))), range(0, nt, step))


def _walk_nodes(structure, motion, e, ed, edd, L, Ld, Ldd):
    """Node velocities and accelerations by rigid-member formulas walked from the supports.

    Each free node takes its motion from one member whose other node is already known
    (passive members first, as Lacy takes point B from the follower, eqs. 2.3–2.5):
    ``a_b = a_a + L̈ e + 2 L̇ ė + L ë``.
    """
    nt = e.shape[0]
    n = structure.n_nodes
    V = np.zeros((nt, n, 3))
    A = np.zeros((nt, n, 3))
    known = np.all(structure.translation_supports, axis=1)
    active = np.zeros(structure.n_members, dtype=bool)
    active[motion.members] = True
    conn = structure.connectivity
    queue = deque(np.flatnonzero(known))
    adj: dict[int, list[tuple[int, int, int]]] = {i: [] for i in range(n)}
    for k, (a, b) in enumerate(conn):
        adj[a].append((int(active[k]), k, +1))
        adj[b].append((int(active[k]), k, -1))
    while True:
        progressed = False
        for node in range(n):
            if known[node]:
                continue
            for _, k, sign in sorted(adj[node]):
                a, b = conn[k]
                other = a if sign == -1 else b
                if not known[other]:
                    continue
                # Motion of the far end relative to the near end of member k.
                rel_v = Ld[:, k, None] * e[:, k] + L[:, k, None] * ed[:, k]
                rel_a = (Ldd[:, k, None] * e[:, k] + 2 * Ld[:, k, None] * ed[:, k]
                         + L[:, k, None] * edd[:, k])
                s = 1.0 if sign == -1 else -1.0   # node is the end (b) or the start (a)
                V[:, node] = V[:, other] + s * rel_v
                A[:, node] = A[:, other] + s * rel_a
                known[node] = True
                progressed = True
                break
        if known.all() or not progressed:
            break
    del queue
    return V, A
