# SPDX-License-Identifier: MIT
"""One call for the whole rigid-body dynamic force analysis along a motion.

:func:`simulate` runs kinematics → nodal forces → section forces → stresses → buckling →
actuator force (and, when ``[actuators]`` data exist, the actuator and motor model), for the
motion and for the same positions at rest (the "static" forces of Lacy's figures), and returns
a :class:`SimulationResult`.
"""
from __future__ import annotations

import inspect
import logging
import threading
from dataclasses import dataclass, field, replace
from typing import Callable

import numpy as np

from ..budget import along_motion_bytes, count_text, require
from ..errors import AnalysisError, InputError
from ..mechanics.conventions import PHYSICAL, Conventions
from ..mechanics.stress import round_sections
from ..model.structure import Structure
from .active import active_members
from .bays import METHODS, bay_by_bay_positions, chain_layout, chain_layout_or_none
from .buckling import BucklingCheck, buckling_check
from .forces import (MemberBodies, NodalForces, forces_from_tensions, member_bodies,
                     nodal_forces_with_static, pair_loads)
from .kinematics import (Kinematics, _Pattern, check_fixed_members, compute_kinematics,
                         solve_motion_positions)
from .linalg import SingularStep
from .motion import Motion, check_stroke, rest_motion
from .sections import (SectionForces, SectionStresses, section_forces, section_stresses,
                       section_tension)
from ..threads import block_steps, parallel_map

log = logging.getLogger(__name__)


@dataclass
class SimulationResult:
    """Everything :func:`simulate` computes; arrays indexed (time, member[, section]).

    Attributes
    ----------
    structure, motion, kinematics
        Inputs and kinematics.
    forces, static_forces : NodalForces
        Pin forces along the motion, and at rest in the same positions.
    section_tension : ndarray, shape (nt, m, k)
        Axial force at the sections along the motion (``sections.tension``), N.
    sections, static_sections : SectionForces
        Internal forces at the sections (computed on first access, see Notes).
    stresses, static_stresses : SectionStresses
        Their stresses (computed on first access).
    midpoint_axial_force : ndarray, shape (nt, m)
        Axial force at the middle of each member's tube.
    actuator_force, static_actuator_force : ndarray, shape (nt, na)
        Axial force of the active base on the leadscrew tube (positive pushing it out).
    cantilever_moment : ndarray, shape (nt, na)
        Bending moment magnitude at the cantilever connection, N·m.
    buckling : BucklingCheck
    actuators : dict
        Actuator and motor histories per active member id (empty without ``[actuators]``).
    options : dict
        Options used.

    Notes
    -----
    The section forces and stresses are closed-form functions of the kinematics and the
    nodal forces (Lacy eqs. 2.16–2.25): :func:`simulate` computes the axial forces, which the
    buckling check needs, and the first access to any of ``sections``, ``static_sections``,
    ``stresses``, ``static_stresses`` computes the shears, moments and stresses of the whole
    motion (in blocks of steps, in worker threads) and keeps them — the same numbers as
    computing them in :func:`simulate`, without writing four (nt, m, k[, 3]) histories that a
    caller may never read.
    """

    structure: Structure
    motion: Motion
    kinematics: Kinematics
    bodies: MemberBodies
    forces: NodalForces
    static_forces: NodalForces
    section_tension: np.ndarray
    midpoint_axial_force: np.ndarray
    actuator_force: np.ndarray
    static_actuator_force: np.ndarray
    cantilever_moment: np.ndarray
    buckling: BucklingCheck
    actuators: dict = field(default_factory=dict)
    options: dict = field(default_factory=dict)
    _sections: "_LazySections | None" = field(default=None, repr=False)

    @property
    def sections(self) -> SectionForces:
        """Internal forces at the sections along the motion (Lacy eqs. 2.16–2.18)."""
        return self._sections.get()[0]

    @property
    def static_sections(self) -> SectionForces:
        """Internal forces at the sections at rest in the same positions."""
        return self._sections.get()[1]

    @property
    def stresses(self) -> SectionStresses:
        """Stresses at the sections along the motion (Lacy eqs. 2.19–2.25)."""
        return self._sections.get()[2]

    @property
    def static_stresses(self) -> SectionStresses:
        """Stresses at the sections at rest in the same positions."""
        return self._sections.get()[3]

    @property
    def time(self) -> np.ndarray:
        """Sample times, s."""
        return self.motion.time

    def member_summary(self, member: int, section: int | None = None) -> dict:
        """Maxima of one member's von Mises stress over the motion.

        Parameters
        ----------
        member : int
        section : int, optional
            Restrict the motion-induced maximum to one section (Lacy reports the follower's at
            its midpoint); default all sections.

        Returns
        -------
        dict
            ``max_von_mises`` with its ``time``, ``step`` and ``section`` (distance from the
            end node); ``static_at_max`` (static stress at that instant and section);
            ``static_max``; ``motion_induced_max`` (largest dynamic − static) with its time,
            step and section.
        """
        vm = self.stresses.von_mises[:, member]
        vs = self.static_stresses.von_mises[:, member]
        i, j = np.unravel_index(int(np.argmax(vm)), vm.shape)
        d = vm - vs
        if section is not None:
            d = d[:, [section]]
        i2, j2 = np.unravel_index(int(np.argmax(d)), d.shape)
        j2 = section if section is not None else j2
        pos = self.sections.position[member]
        out = {
            "max_von_mises": float(vm[i, j]), "time": float(self.time[i]), "step": int(i),
            "section": float(pos[j]),
            "static_at_max": float(vs[i, j]), "static_max": float(vs.max()),
            "motion_induced_max": float(d.max()), "motion_induced_time": float(self.time[i2]),
            "motion_induced_step": int(i2), "motion_induced_section": float(pos[j2]),
        }
        # A section without an outer-fibre distance has no von Mises stress where it bends:
        # the member's maximum is then undefined (NaN, null in JSON), and so are the time,
        # step and section of it (argmax stops at the first NaN, which is no maximum).
        for value, keys in (("max_von_mises", ("time", "step", "section")),
                            ("motion_induced_max", ("motion_induced_time",
                                                    "motion_induced_step",
                                                    "motion_induced_section"))):
            if not np.isfinite(out[value]):
                out.update(dict.fromkeys(keys))
        return out


class _Counter:
    """Counts finished blocks for a ``progress(done, total)`` callback, from any thread."""

    def __init__(self, progress: Callable[[int, int], None], total: int):
        self.progress, self.total, self.done = progress, total, 0
        self.lock = threading.Lock()

    def tick(self) -> None:
        with self.lock:
            self.done += 1
            self.progress(self.done, self.total)


#: Peak bytes per time step, member and section of the section forces and stresses, of the
#: motion and at rest (measured 210–270 on the triangular truss and the double-octahedral bay,
#: results written as JSON and NPZ).
BYTES_PER_STEP_SECTION = 384


def sections_bytes(steps: float, n_members: int, n_sections: float) -> float:
    """Estimated memory of the section results of ``steps`` time steps (bytes)."""
    return float(steps) * n_members * float(n_sections) * BYTES_PER_STEP_SECTION


def simulate(structure: Structure, motion: Motion | None = None, *,
             conventions: Conventions = PHYSICAL, n_sections: int = 7,
             effective_length_factor: np.ndarray | float = 1.0, actuators: bool = True,
             progress: Callable[[int, int], None] | None = None,
             method: str = "auto") -> SimulationResult:
    """Rigid-body dynamic force analysis of a truss along a motion (Lacy chapters 2–4).

    Parameters
    ----------
    structure : Structure
        Statically determinate pin-jointed truss, with ``[active_members]`` if it moves.
    motion : Motion, optional
        Active-member histories; ``None`` analyses the model at rest (one step).
    conventions : Conventions
        :data:`~trussfe.mechanics.conventions.PHYSICAL` (default: exact kinematics, each
        piece's own section inertia, von Mises at S1 by eq. 2.24) or
        :data:`~trussfe.mechanics.conventions.THESIS` (Lacy's Appendix A: backward-difference
        rates, whole-length inertia), or any other combination.
    n_sections : int
        Sections per member (Lacy: 7 in the triangular truss).
    effective_length_factor : float or array (m,)
        K of the Euler load π² E I / (K l)² (eq. 2.26 with C = 1/K²; 1 as Lacy).
    actuators : bool
        Run the actuator and motor model when ``[actuators]`` data exist.
    progress : callable, optional
        Called as ``progress(done, total)``: over the steps while the positions are solved
        one after the other, then over the blocks of steps whose forces are computed (from
        worker threads, one call at a time).
    method : {"auto", "direct", "bay-by-bay"}
        How the positions are found.  ``"direct"``: Newton's method on the whole truss.
        ``"bay-by-bay"``: a chain of identical bays as Lacy's chapter 6 describes
        (:mod:`trussfe.rigid.bays`): each bay alone in the frame of its base plane, carried
        up the chain (eqs. 6.1–6.3); exact kinematics only.  ``"auto"`` (default):
        ``"bay-by-bay"`` for a chain of two or more identical bays with the exact scheme
        (:func:`~trussfe.rigid.bays.chain_layout`), else ``"direct"``; ``options["method"]``
        of the result says which one ran.  Velocities, accelerations and forces are the
        same block substitutions for both: the compatibility matrix of a chain is block
        triangular with one 9 × 9 block per plane, so ``B v = L̇`` runs up the chain and
        ``Bᵀ t = f`` down it, each bay's base reactions passed to the bay below (§6.2), in
        O(n) per step, batched over the steps.

    Returns
    -------
    SimulationResult

    Notes
    -----
    Long motions are evaluated in blocks of steps (``CHUNK_ENTRIES`` members × steps each),
    which worker threads take in parallel (:mod:`trussfe.threads`, ``TRUSSFE_THREADS``);
    the results do not depend on the number of threads.
    """
    if n_sections < 1 or int(n_sections) != n_sections:
        raise InputError("sections", f"need a positive integer number of sections (1 = the "
                         f"midpoint only), got {n_sections}")
    scheme = conventions.kinematics
    if method not in METHODS:
        raise InputError("--method", f"unknown method {method!r}; valid: {', '.join(METHODS)}")
    layout = None
    if method == "auto":
        # bay by bay for a chain of two or more identical bays (exact kinematics only)
        layout = chain_layout_or_none(structure) if scheme == "exact" else None
        method = "bay-by-bay" if layout is not None and layout.n_bays >= 2 else "direct"
    if method == "bay-by-bay" and scheme != "exact":
        raise InputError("--method", "bay-by-bay uses the exact kinematics of every bay; it "
                         "cannot be combined with --scheme thesis")
    if motion is None:
        motion = rest_motion(structure)
    acts = active_members(structure)
    act_idx = np.array([a.member for a in acts], dtype=np.int64)
    if set(motion.members.tolist()) - set(act_idx.tolist()):
        bad = sorted(set(motion.members.tolist()) - set(act_idx.tolist()))[0]
        raise InputError("motion", f"member '{structure.member_ids[bad]}' is not an active "
                         "member of the model (add it to [active_members])")
    # A motion beyond an actuator's stroke, or changing a member between two supports,
    # describes a truss that cannot be built (checked once here, for every method: the
    # positions of a chain's bays and the blocks of steps are not checked again).
    check_stroke(structure, motion)
    check_fixed_members(structure, motion)
    bodies = member_bodies(structure)
    opts = dict(n_sections=n_sections, full_length_inertia=conventions.full_length_inertia,
                shear_factor=conventions.shear_factor, stress_form=conventions.stress_form,
                round_section=round_sections(structure.sections))
    nt, m = motion.n_steps, structure.n_members
    require(along_motion_bytes(nt, structure.n_nodes, m), "motion",
            f"an analysis of {count_text(nt)} time steps", "use fewer steps (--steps) or a longer "
            "time step")
    require(along_motion_bytes(nt, structure.n_nodes, m) + sections_bytes(nt, m, n_sections),
            "--sections", f"{count_text(n_sections)} sections of {m:,} members at "
            f"{count_text(nt)} time steps",
            "use fewer sections")
    # blocks of equal size, as many as a multiple of the worker threads; every step is
    # computed the same in any block
    step = block_steps(nt, CHUNK_ENTRIES // max(m, 1))
    if method == "bay-by-bay":
        X = bay_by_bay_positions(structure, motion, layout or chain_layout(structure))
    elif nt > 1:
        X = solve_motion_positions(structure, motion, progress=progress)
    else:
        X = None
    if scheme == "exact" and nt > step:
        # Positions for the whole motion (warm starts link the steps), then the forces one
        # block of steps at a time: the exact kinematics are independent per step, and blocks
        # that fit in the processor cache are several times faster than whole-motion arrays
        # (the work is memory-bound).  With a direct (stacked-inverse) factorisation the
        # kinematics are solved for the whole motion at once — a solve costs a Python loop
        # over the diagonal blocks, which is paid once instead of once per block of steps —
        # and the blocks use slices of it.
        starts = range(0, nt, step)
        bar = _Counter(progress, len(starts)) if progress is not None else None
        pattern = _Pattern.of(structure)
        # A direct (stacked-inverse) pattern is cheapest with the kinematics of the whole
        # motion at once (its stacked inverses and block substitutions are split over the
        # steps between the worker threads inside), the rest in blocks of steps in the
        # threads; an anchored sparse pattern runs whole blocks of steps, kinematics included,
        # in the threads (measured on a shared 2-core machine with two threads: the slew
        # 0.32 s whole-motion against 0.34–0.43 s in blocks, the 100-bay chain 2.9–3.4 s
        # against 3.1–3.3 s).
        if pattern.direct:
            kin_all = compute_kinematics(structure, motion, scheme=scheme, coords=X)
            # Member loads block by block, the member tensions of all steps in one solve (a
            # loop over the diagonal blocks, paid once), then the rest block by block.
            kins = [_slice_kinematics(kin_all, k0, k0 + step) for k0 in starts]
            # The blocks are independent: worker threads (trussfe.threads) take them, each
            # writing its rows of the right-hand sides of all steps.
            rhs = np.empty((nt, pattern.free_flat.size, 2))
            loads = parallel_map(lambda j: pair_loads(structure, kins[j], bodies,
                                                      rhs[starts[j]:starts[j] + step])[0],
                                 range(len(kins)))
            tension = _solve_tensions(kin_all, rhs)
            del rhs

            def rest(j):
                kc, k0 = kins[j], j * step
                pair = forces_from_tensions(structure, kc, bodies, loads[j],
                                            tension[k0:k0 + step])
                out = _steps(structure, kc, bodies, act_idx, forces=pair, **opts)[1:]
                if bar is not None:
                    bar.tick()
                return out
            kin = kin_all
            kin.compat = None          # factorisations are not kept
            f, fs, sec_t, mid, act_force, act_static, cmoment = _assemble(
                rest, list(starts), nt, n_sections, first=1)
        else:
            def block(j):
                k0 = starts[j]
                out = _steps(structure, compute_kinematics(
                    structure, _slice_motion(motion, k0, min(nt, k0 + step)), scheme=scheme,
                    coords=X[k0:k0 + step]), bodies, act_idx, **opts)
                if bar is not None:
                    bar.tick()
                return out
            kin, f, fs, sec_t, mid, act_force, act_static, cmoment = _assemble(
                block, list(starts), nt, n_sections, first=0)
    else:
        step = nt
        kin, f, fs, sec_t, mid, act_force, act_static, cmoment = _steps(
            structure, compute_kinematics(structure, motion, scheme=scheme, coords=X),
            bodies, act_idx, **opts)
    buck = buckling_check(structure, sec_t, bodies.tube_length, effective_length_factor)
    lazy = _LazySections(structure, kin, f, fs, bodies, sec_t, step, opts)
    res = SimulationResult(structure=structure, motion=motion, kinematics=kin, bodies=bodies,
                           forces=f, static_forces=fs, section_tension=sec_t,
                           midpoint_axial_force=mid,
                           actuator_force=act_force, static_actuator_force=act_static,
                           cantilever_moment=cmoment, buckling=buck, _sections=lazy,
                           options={"scheme": scheme, "method": method,
                                    "n_sections": int(n_sections),
                                    "full_length_inertia": conventions.full_length_inertia,
                                    "shear_factor": conventions.shear_factor,
                                    "stress_form": conventions.stress_form})
    if actuators and "actuators" in structure.extensions and act_idx.size:
        res.actuators = _actuator_histories(structure, motion, res)
    return res


#: Members × steps per block of the blocked evaluation (about 4 MB per 3-vector array).
CHUNK_ENTRIES = 1 << 17


def _solve_tensions(kin: Kinematics, rhs: np.ndarray) -> np.ndarray:
    """``Bᵀ t = rhs`` (nt, n_free, r) with the kinematics' direct factorisation."""
    try:
        return kin.compat.solve(rhs, transpose=True)
    except SingularStep as s:                                  # pragma: no cover
        raise AnalysisError(f"step {s.step} (t = {kin.time[s.step]:.6g} s)",
                            "the truss is at a singular position (its equilibrium matrix is "
                            "rank deficient): the member forces are not determined there"
                            ) from None


def _steps(structure, kin, bodies, act_idx, *, n_sections, full_length_inertia,
           shear_factor, stress_form="combined", round_section=None, forces=None):
    """Forces, axial forces at the sections, midpoint axial force and actuator force for a
    block of steps of kinematics ``kin``; the static forces are those of the same positions
    at rest.  ``forces``: the (dynamic, static) nodal forces if already known.  (The shears,
    moments and stresses of the sections: :class:`_LazySections`.)"""
    f, fs = nodal_forces_with_static(structure, kin, bodies) if forces is None else forces
    tension = section_tension(structure, kin, f, bodies, n_sections)
    if n_sections == 1 or n_sections % 2:
        mid = tension[:, :, (tension.shape[2] - 1) // 2]
    else:
        mid = section_tension(structure, kin, f, bodies, 1)[:, :, 0]
    # The cantilever connection: the cut at u = L_tube of an active member, where the
    # piece is the whole leadscrew tube; its axial force is the actuator force.
    act_force, act_static, cmoment = _cantilever(structure, kin, f, fs, bodies, act_idx)
    kin.compat = None                  # factorisations of one block are not kept
    return kin, f, fs, tension, mid, act_force, act_static, cmoment


class _LazySections:
    """The section forces and stresses of a simulation, computed on first access.

    They are closed-form functions of the kinematics, the nodal forces and the axial forces
    at the sections already computed (Lacy eqs. 2.16–2.25): :meth:`get` evaluates them in
    the blocks of steps of :func:`simulate` (worker threads take the blocks; every step is
    computed as in any block) and keeps them.  Thread-safe; a pickled result carries the
    evaluated arrays.
    """

    def __init__(self, structure, kin, forces, static_forces, bodies, tension, step, opts):
        self._inputs = (structure, kin, forces, static_forces, bodies, tension, step, opts)
        self._value: tuple | None = None
        self._lock = threading.Lock()

    @property
    def evaluated(self) -> bool:
        """Whether the section forces and stresses have been computed."""
        return self._value is not None

    def get(self) -> tuple[SectionForces, SectionForces, SectionStresses, SectionStresses]:
        """(sections, static sections, stresses, static stresses)."""
        with self._lock:
            if self._value is None:
                self._value = _section_results(*self._inputs)
                self._inputs = None
            return self._value

    def __getstate__(self) -> dict:
        return {"value": self.get()}

    def __setstate__(self, state: dict) -> None:
        self._inputs, self._value, self._lock = None, state["value"], threading.Lock()


def _section_results(structure, kin, forces, static_forces, bodies, tension, step, opts):
    """Section forces and stresses, motion and rest, of the whole motion, in blocks of
    ``step`` steps (:class:`_LazySections`); the dynamic axial forces are ``tension``."""
    nt = kin.n_steps
    n_sections, fli = opts["n_sections"], opts["full_length_inertia"]
    stress = dict(shear_factor=opts["shear_factor"], convention=opts["stress_form"],
                  round_section=opts["round_section"])

    def block(k0):
        k1 = min(nt, k0 + step)
        whole = k0 == 0 and k1 == nt
        kc = kin if whole else _slice_kinematics(kin, k0, k1)
        fc = forces if whole else _slice_forces(forces, k0, k1)
        fsc = static_forces if whole else _slice_forces(static_forces, k0, k1)
        sf = section_forces(structure, kc, fc, bodies, n_sections, full_length_inertia=fli,
                            tension=tension[k0:k1])
        ss = section_forces(structure, kc, fsc, bodies, n_sections, full_length_inertia=fli,
                            at_rest=True)
        st = section_stresses(structure, sf, **stress)
        sts = section_stresses(structure, ss, **stress)
        return sf, ss, st, sts

    starts = list(range(0, nt, step))
    if len(starts) == 1:
        return block(0)
    outs: list = []
    lock = threading.Lock()

    def one(k0):
        part = block(k0)
        # the dynamic tension and the unit vectors are the whole-motion arrays already
        part = (replace(part[0], tension=None, unit=None), replace(part[1], unit=None),
                part[2], part[3])
        with lock:                    # the first block to finish allocates the whole arrays
            if not outs:
                outs.extend(_allocate(p, nt) for p in part)
        for o, p in zip(outs, part):
            _store(o, p, k0)
    parallel_map(one, starts)
    outs[0].tension = tension
    outs[0].unit = outs[1].unit = kin.unit
    return tuple(outs)


def _slice_forces(f: NodalForces, k0: int, k1: int) -> NodalForces:
    """Steps ``k0:k1`` of nodal forces (views)."""
    return NodalForces(end_force=f.end_force[k0:k1], tension_end=f.tension_end[k0:k1],
                       tension_start=f.tension_start[k0:k1], reactions=f.reactions[k0:k1])


def _slice_kinematics(kin: Kinematics, k0: int, k1: int) -> Kinematics:
    """Steps ``k0:k1`` of ``kin`` (views) with their factorisations."""
    values = {}
    for name in kin.__dataclass_fields__:
        v = getattr(kin, name)
        values[name] = v[k0:k1] if isinstance(v, np.ndarray) else v
    values["compat"] = None if kin.compat is None else kin.compat.subset(k0, k1)
    return Kinematics(**values)


def _slice_motion(motion: Motion, k0: int, k1: int) -> Motion:
    return Motion(time=motion.time[k0:k1], members=motion.members,
                  length=motion.length[k0:k1], velocity=motion.velocity[k0:k1],
                  acceleration=motion.acceleration[k0:k1], source=motion.source,
                  first_step=motion.first_step + k0)


def _assemble(fn: Callable[[int], tuple], starts: list, nt: int, n_sections: int,
              first: int) -> list:
    """Results of every block of steps ``fn(j)`` (a tuple of arrays and dataclasses of
    arrays, item ``first`` onwards of :func:`_steps`' tuple) written into whole-motion
    arrays as each block finishes, while its arrays are still in the processor cache (a
    block at a time in worker threads; the first block to finish allocates them).

    With an odd number of sections the midpoint axial force is not copied but the middle
    section's axial force (a view)."""
    mid_is_view = n_sections == 1 or n_sections % 2
    skip = {4 - first} if mid_is_view else set()
    outs: list = []
    lock = threading.Lock()

    def one(j):
        part = fn(j)
        with lock:                    # the first block to finish allocates the whole arrays
            if not outs:
                outs.extend(None if i in skip else _allocate(p, nt)
                            for i, p in enumerate(part))
        for i, (o, p) in enumerate(zip(outs, part)):
            if i not in skip:
                _store(o, p, starts[j])
    parallel_map(one, range(len(starts)))
    if mid_is_view:
        tension = outs[3 - first]
        outs[4 - first] = tension[:, :, (tension.shape[2] - 1) // 2]
    return outs


def _allocate(item, nt: int):
    """Empty whole-motion arrays shaped like one block's ``item`` (an array or a dataclass
    of arrays indexed by time first; section positions and factorisations are not), in its
    memory order (components first, :mod:`trussfe.vectors`, where the block's are)."""
    if isinstance(item, np.ndarray):
        return np.empty_like(item, shape=(nt,) + item.shape[1:])
    values = {}
    for name in item.__dataclass_fields__:
        v = getattr(item, name)
        if isinstance(v, np.ndarray) and name != "position":
            values[name] = np.empty_like(v, shape=(nt,) + v.shape[1:])
        else:
            values[name] = None if name == "compat" else v
    return type(item)(**values)


def _store(out, item, k0: int) -> None:
    """Write one block's ``item`` into the whole-motion ``out`` from step ``k0``."""
    if isinstance(item, np.ndarray):
        out[k0:k0 + item.shape[0]] = item
        return
    for name in item.__dataclass_fields__:
        v, o = getattr(item, name), getattr(out, name)
        if isinstance(v, np.ndarray) and isinstance(o, np.ndarray) and name != "position":
            o[k0:k0 + v.shape[0]] = v


def _cantilever(structure, kin, f, fs, bodies, act_idx):
    """Actuator force (dynamic and static) and cantilever moment of the active members."""
    nt = kin.n_steps
    if act_idx.size == 0:
        z = np.zeros((nt, 0))
        return z, z.copy(), z.copy()
    pos = bodies.tube_length[act_idx, None].copy()
    cf = section_forces(structure, kin, f, bodies, positions=pos, members=act_idx)
    cs = section_tension(structure, kin, fs, bodies, positions=pos, members=act_idx,
                         at_rest=True)
    # N·e = −T: positive when the base pushes the tube outward (Lacy ``actfor``).
    return -cf.tension[:, :, 0], -cs[:, :, 0], cf.moment_magnitude[:, :, 0]


def _actuator_histories(structure: Structure, motion: Motion, res: SimulationResult) -> dict:
    """Actuator and motor histories from :mod:`trussfe.rigid.actuator` (if installed)."""
    try:
        from .actuator import actuator_histories
    except ImportError:
        log.warning("actuator data present but the actuator model is not available; skipped")
        return {}
    # Every active member, in the order of the actuator forces: an active member the motion
    # does not name keeps its model length (docs/actuators.md, *Measured motions*), so its
    # actuator holds the load at rest (Ẋ = Ẍ = 0) and its motor still carries the holding
    # torque, current and voltage (Lacy section 2.9, eqs. 2.37/2.40/2.44) — as every
    # actuator does in an analysis at rest.
    acts = [a.member for a in active_members(structure)]
    moving = {int(k): j for j, k in enumerate(motion.members)}
    rates = [np.zeros((motion.n_steps, len(acts))) for _ in range(2)]
    for c, k in enumerate(acts):
        if k in moving:
            rates[0][:, c] = motion.velocity[:, moving[k]]
            rates[1][:, c] = motion.acceleration[:, moving[k]]
    every = Motion(time=motion.time, members=acts,
                   length=res.kinematics.length[:, acts], velocity=rates[0],
                   acceleration=rates[1], source=motion.source,
                   first_step=motion.first_step)
    kwargs = {}
    params = inspect.signature(actuator_histories).parameters
    if "static_force" in params:
        kwargs["static_force"] = res.static_actuator_force
    out = actuator_histories(structure, every, res.actuator_force, **kwargs)
    if not isinstance(out, dict):
        raise AnalysisError("actuators", "the actuator model returned no histories")
    return out
