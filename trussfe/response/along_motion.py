# SPDX-License-Identifier: MIT
"""Quasi-static elastic response of the finite-element model along a rigid-body motion.

At every time step of a maneuver the finite-element model (:mod:`trussfe.fem`, pinned-beam
bar model: every bar a subdivided Hermite beam with both end moments released) is assembled
in the current configuration — the rigid-body positions ``kin.coords[step]`` — and loaded with
gravity and the d'Alembert loads of the motion (:mod:`trussfe.response.loads`).  Its linear
static solution gives displacements, reactions and member section forces.

**All steps in one solve.**  The steps are independent, so a block of steps is discretised
as *one* structure made of disjoint copies of the truss, one per step, each in its own
configuration; its stiffness is block diagonal and one sparse factorisation solves the whole
block (:func:`trussfe.fem.discretise` and :func:`trussfe.fem.solver.factorise` unchanged).

**Section forces at the rigid model's sections.**  The element end forces
``K_e u_e − f_e`` of Hermite/linear elements with exactly integrated consistent loads are exact
(the nodal solution of Euler–Bernoulli and bar elements is exact for any load).  A section
at x inside an element [x0, x1] is recovered by the equilibrium of the piece (x, x1]: with
F1, M1 the force and moment on the element at x1,

.. math:: N = -F_1 - \\int_x^{x_1} q, \\qquad
          M = -\\Big[M_1 + (x_1 - x)\\, e \\times F_1 + \\int_x^{x_1} (\\xi - x)\\, e \\times q
              + \\int_x^{x_1} c\\Big],

N and M being what the start side exerts on the end side (Lacy's sign, eqs. 2.16–2.18,
4.68–4.74: tension T = −N·e).  Recovery rather than extra nodes because the rigid sections of
an active member lie on its tube, at positions that move with the stroke; with
``subdivisions = n_sections − 1`` the sections of passive members are element ends and the
recovered pieces are empty.

For a statically determinate truss the member forces do not depend on the stiffness, so these
section forces must equal the rigid model's (:func:`compare_with_rigid`) — the dynamic
cross-check Lacy could not make because MSC/PAL lumps member weight at the nodes.
"""
from __future__ import annotations

import logging
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Callable

import numpy as np

from ..budget import along_motion_bytes, count_text, require
from ..errors import AnalysisError, InputError, MechanismError, TrussfeError
from ..fem.discretisation import FEModel, discretise
from ..fem.solver import factorise, solve_free
from ..linalg import SingularMatrixError
from ..mechanics.conventions import PHYSICAL, Conventions
from ..mechanics.geometry import from_end_node, stations
from ..model.structure import Structure
from ..mechanics.active_bodies import MemberBodies, member_bodies
from ..rigid.kinematics import Kinematics
from ..rigid.sections import SectionForces
from .loads import MotionLoads, element_load_components, motion_loads, rotations3

log = logging.getLogger(__name__)

#: Elements per solved block of steps (memory ~ a few tens of MB).
BLOCK_ELEMENTS = 40_000

#: Peak bytes per element of a solved block of steps (the stacked model, its factorisation and
#: element forces; measured about 4 KiB with 40 000 elements a block).
BYTES_PER_BLOCK_ELEMENT = 4096
#: Bytes kept per time step and element (station positions and forces) ...
BYTES_PER_STEP_ELEMENT = 256
#: ... and per time step and section (the FE section forces and their recovery; measured about
#: 300 beside the rigid model's on the triangular truss).
BYTES_PER_STEP_FE_SECTION = 256


def elastic_bytes(steps: float, n_members: int, subdivisions: float,
                  n_sections: float) -> tuple[float, float]:
    """Estimated memory of the FE response along a motion (bytes): the part that grows with the
    elements (``subdivisions`` per member) and the part that grows with the sections."""
    per_step = float(n_members) * float(subdivisions)
    block = min(float(steps) * per_step, max(float(BLOCK_ELEMENTS), per_step))
    elements = (block * BYTES_PER_BLOCK_ELEMENT
                + float(steps) * n_members * (float(subdivisions) + 1) * BYTES_PER_STEP_ELEMENT)
    sections = float(steps) * n_members * float(n_sections) * BYTES_PER_STEP_FE_SECTION
    return elements, sections


@dataclass
class ElasticResponse:
    """Finite-element response along a motion; arrays indexed (time, member/node, ...).

    Attributes
    ----------
    time : ndarray, shape (nt,)
    displacements : ndarray, shape (nt, n, dim)
        Node translations relative to the rigid-body position, m.
    reactions : ndarray, shape (nt, n, dim)
        Support reactions (zero on free coordinates), N.
    sections : SectionForces
        Section forces at the rigid model's sections (``position`` from the end node).
    station_x : ndarray, shape (nt, m, k + 1)
        FE stations (element ends) from the start node.
    station_forces : ndarray, shape (nt, m, k + 1, 6)
        Section forces ``[N, Vy, Vz, T, My, Mz]`` at the stations, member axes
        (:func:`trussfe.fem.static.section_forces` convention).
    midpoint_axial_force : ndarray, shape (nt, m)
        Axial force at the member midpoint, N (tension positive).
    strain : ndarray, shape (nt, m)
        Axial strain N/(EA) at the midpoint.
    subdivisions : int
    loads : MotionLoads
        The loads applied.
    options : dict
        ``gravity`` and ``loads`` flags used.
    """

    time: np.ndarray
    displacements: np.ndarray
    reactions: np.ndarray
    sections: SectionForces
    station_x: np.ndarray
    station_forces: np.ndarray
    midpoint_axial_force: np.ndarray
    strain: np.ndarray
    subdivisions: int
    loads: MotionLoads
    options: dict = field(default_factory=dict)


def copy_ids(ids, copies: int) -> list[str]:
    """Ids of the items of ``copies`` disjoint copies: ``ID@i`` for copy ``i``, or the ids
    themselves for one copy (a single step is named as the model names it)."""
    if copies == 1:
        return list(ids)
    return [f"{x}@{i}" for i in range(copies) for x in ids]


def step_item(item: str, step: int, time: float) -> str:
    """``item`` narrowed to one step of a motion: ``"m.toml: step 3 (t = 0.18 s)"``."""
    where = f"step {step} (t = {time:.6g} s)"
    return f"{item}: {where}" if item else where


def error_at_step(err: TrussfeError, step: int, time: float) -> TrussfeError:
    """A copy of ``err`` whose item names the step of the motion (:func:`step_item`)."""
    return err.with_item(step_item(err.item, step, time))


def _first_copy(names) -> int | None:
    """The lowest copy index among ids ``ID@i`` (and ``member ID@i``) of
    :func:`copy_ids`, or None when none is such an id."""
    found = []
    for name in names:
        _, sep, idx = str(name).rpartition("@")
        if sep and idx.isdigit():
            found.append(int(idx))
    return min(found, default=None)


def stacked_structure(structure: Structure, coords: np.ndarray) -> Structure:
    """Disjoint copies of a structure, copy i at positions ``coords[i]`` (one per step).

    Loads, masses and gravity are left out (the loads of a motion are applied separately);
    supports, sections, materials and member types are repeated.  Node ``j`` of copy ``i`` is
    node ``i n + j``, member ``k`` of copy ``i`` is member ``i m + k``; their ids are
    :func:`copy_ids`.
    """
    nt = coords.shape[0]
    n, dim = structure.n_nodes, structure.dim
    conn = (structure.connectivity[None] + n * np.arange(nt)[:, None, None]).reshape(-1, 2)
    return Structure(
        name=f"{structure.name} × {nt} steps", dim=dim,
        node_ids=copy_ids(structure.node_ids, nt),
        coords=coords.reshape(nt * n, dim),
        member_ids=copy_ids(structure.member_ids, nt),
        connectivity=conn, sections=list(structure.sections) * nt,
        materials=list(structure.materials) * nt,
        is_beam=np.tile(structure.is_beam, nt), releases=np.tile(structure.releases, (nt, 1)),
        torsion_releases=np.tile(structure.torsion_releases, (nt, 1)),
        bending_axis_releases=np.tile(structure.bending_axis_releases, (nt, 1, 1)),
        supports=np.tile(structure.supports, (nt, 1)),
        loads=np.zeros((nt * n, structure.ndof_node)), masses=np.zeros(nt * n),
        gravity=np.zeros(dim), orientation=np.tile(structure.orientation, (nt, 1)),
        source=structure.source)


def _solve_block(structure: Structure, coords: np.ndarray, ml: MotionLoads,
                 positions: np.ndarray, subdivisions: int, backend: str = "superlu"):
    """FE solve of one block of steps; returns displacements, reactions, section and
    station forces."""
    nt = coords.shape[0]
    n, m, dim = structure.n_nodes, structure.n_members, structure.dim
    big = stacked_structure(structure, coords)
    fe: FEModel = discretise(big, bar_model="pinned-beam", subdivisions=subdivisions)
    k = subdivisions
    if np.any(fe.member_subdivisions != k):
        raise AnalysisError(structure.source or structure.name,
                            "the elastic response needs every member subdivided alike")
    R = rotations3(fe.rotation).reshape(nt, m, 3, 3)
    ex = fe.element_x.reshape(nt, m, k, 2)
    every = np.arange(fe.n_elements)
    phi = tuple(fe.shear_parameter(f, every).reshape(nt, m, k) for f in "vw")
    comp = element_load_components(ml, ex, R, phi)                    # (t, m, k, 2, 6)
    comp_flat = comp.reshape(nt * m * k, 2, 6)
    f = np.zeros(fe.n_dof)
    f_local = []
    for g in fe.groups:
        if g.kind != "frame":
            raise AnalysisError(structure.source or structure.name,
                                "the pinned-beam discretisation left a truss element")
        c = comp_flat[g.elements]
        c = c[..., [0, 1, 5]] if dim == 2 else c                    # 2-D: Fx, Fy, Mz
        c = c.reshape(-1)
        f += g.G.T @ c
        f_local.append(g.S @ c)
    nodal = ml.nodal[..., :dim].reshape(nt * n, dim)
    np.add.at(f, fe.node_dofs[:, :dim], nodal)
    K = fe.stiffness()
    # SuperLU: on these block-diagonal systems it factorises faster than PARDISO (0.9 s
    # against 1.4 s for 221 steps of the double octahedron, 1e5 DOFs)
    fac = factorise(K, fe.free, fe=fe, item=structure.source or structure.name,
                    backend=backend)
    try:
        u = solve_free(fac, fe.free, f)
    except SingularMatrixError:                # a non-finite solution
        raise AnalysisError(structure.source or structure.name,
                            "non-finite displacements") from None
    r = np.where(fe.fixed, K @ u - f, 0.0)
    disp = fe.node_values(u)[:, :dim].reshape(nt, n, dim)
    react = fe.node_values(r)[:, :dim].reshape(nt, n, dim)
    fel = fe.element_forces(u, f_local).reshape(nt, m, k, 2, 6)      # member axes
    # stations: element starts, then the member end
    sx = np.concatenate([ex[..., 0], ex[..., -1:, 1]], axis=-1)       # (t, m, k+1)
    st = np.concatenate([-fel[:, :, :, 0], fel[:, :, -1:, 1]], axis=2)
    L = ml.length[..., None]
    # the FE stations count from the start node, the rigid model's sections from the end node
    sections = _recover_sections(ml, ex, fel, R,
                                 np.clip(from_end_node(positions[None], ml.length), 0.0, L))
    tube_mid = L - 0.5 * (L - ml.tube_start[..., None])
    mid = _recover_sections(ml, ex, fel, R, tube_mid)[0][..., 0]
    return disp, react, sections, sx, st, mid


def _singular_step_error(err: MechanismError, structure: Structure, kin: Kinematics, k0: int,
                         subdivisions: int) -> TrussfeError:
    """The error of a block of steps whose FE model is singular, in the user's terms: the
    first step at fault (by time), diagnosed alone so that its nodes carry the model's ids
    and the mechanisms counted are that step's, not the sum over the copies of the block.

    ``err`` itself when it names no copy (nothing to translate)."""
    first = _first_copy(err.moving_nodes)
    if first is None:
        return err
    k = k0 + first
    one = stacked_structure(structure, kin.coords[k:k + 1])
    try:
        fe = discretise(one, bar_model="pinned-beam", subdivisions=subdivisions)
        factorise(fe.stiffness(), fe.free, fe=fe, item=structure.source or structure.name)
    except MechanismError as alone:
        return error_at_step(alone, k, float(kin.time[k]))
    # singular only beside the other steps (round-off of the block's pivot test): name the
    # step and its moving nodes as the model names them
    moving = list(dict.fromkeys(str(x).rpartition("@")[0] for x in err.moving_nodes
                                if _first_copy([x]) == first))
    return error_at_step(MechanismError(
        err.item, "the stiffness matrix of the structure in this position is singular; "
        f"moving nodes: {', '.join(moving[:20])}{' ...' if len(moving) > 20 else ''}; add "
        "supports or members, or run 'trussfe mechanism' for the rank analysis",
        mechanisms=err.mechanisms, moving_nodes=moving), k, float(kin.time[k]))


def _recover_sections(ml: MotionLoads, ex: np.ndarray, fel: np.ndarray, R: np.ndarray,
                      x: np.ndarray):
    """Section forces at stations ``x`` (t, m, s) from the start node by the equilibrium of
    the piece between the section and the end of its element (module notes).

    Returns tension (t, m, s), shear and moment (t, m, s, 3) in global axes."""
    x0 = ex[..., 0]                                                      # (t, m, k)
    k = ex.shape[2]
    j = np.clip(np.sum(x0[:, :, None, :] <= x[..., None], axis=-1) - 1, 0, k - 1)
    x1 = np.take_along_axis(ex[..., 1], j, axis=-1)                      # (t, m, s)
    end = np.take_along_axis(fel[:, :, :, 1], j[..., None], axis=2)      # (t, m, s, 6)
    Rt = np.swapaxes(R, -1, -2)[:, :, None]                              # local → global
    F1 = np.einsum("tmsij,tmsj->tmsi", np.broadcast_to(Rt, end.shape[:3] + (3, 3)),
                   end[..., :3])
    M1 = np.einsum("tmsij,tmsj->tmsi", np.broadcast_to(Rt, end.shape[:3] + (3, 3)),
                   end[..., 3:])
    Q, MQ = ml.piece_resultant(x, x1, x)
    e = ml.unit[:, :, None]
    N = -F1 - Q
    M = -(M1 + np.cross((x1 - x)[..., None] * e, F1) + MQ)
    T = -np.einsum("tmsi,tmsi->tms", N, np.broadcast_to(e, N.shape))
    V = N + T[..., None] * e
    return T, V, M


def elastic_along_motion(structure: Structure, kin: Kinematics, *,
                         bodies: MemberBodies | None = None, subdivisions: int = 6,
                         positions: np.ndarray | None = None, n_sections: int = 7,
                         gravity: bool = True, loads: bool = True,
                         block_elements: int = BLOCK_ELEMENTS,
                         progress: Callable[[int, int], None] | None = None) -> ElasticResponse:
    """Quasi-static FE response at every step of a motion (module notes).

    Parameters
    ----------
    structure : Structure
        Pin-jointed truss (bars; modelled as pinned beams), with its active members.
    kin : Kinematics
        Rigid-body kinematics of the motion (``SimulationResult.kinematics``).
    bodies : MemberBodies, optional
        Mass elements (default :func:`trussfe.mechanics.active_bodies.member_bodies`).
    subdivisions : int
        Elements per member (≥ 1).  Any number gives the same section forces (they are
        exact); ``n_sections − 1`` puts the passive members' sections on element ends.
    positions : ndarray, shape (m, s), optional
        Section positions from the end node (default: ``n_sections`` equidistant points over
        each member's tube, as :func:`trussfe.rigid.sections.section_forces`).
    n_sections : int
        Used when ``positions`` is not given (1 = the tube midpoint).
    gravity, loads : bool
        Include gravity / the external nodal loads.
    block_elements : int
        Steps are solved in blocks of about this many elements.
    progress : callable, optional
        Called as ``progress(done, total)`` as the run advances (a progress bar).

    Returns
    -------
    ElasticResponse

    Raises
    ------
    InputError
        A beam member (the rigid-body loads are those of pin-jointed bars) or a bad option.
    MechanismError
        The truss is a mechanism in some configuration of the motion.
    """
    if int(subdivisions) != subdivisions or subdivisions < 1:
        raise InputError("subdivisions", f"must be a positive integer, got {subdivisions!r}")
    if np.any(structure.is_beam):
        i = int(np.flatnonzero(structure.is_beam)[0])
        raise InputError(f"members.{structure.member_ids[i]}", "the elastic response along a "
                         "motion handles pin-jointed bars (type = \"bar\") only")
    bodies = member_bodies(structure) if bodies is None else bodies
    if positions is None:
        if n_sections < 1 or int(n_sections) != n_sections:
            raise InputError("sections", f"need a positive integer, got {n_sections!r}")
        positions = stations(bodies.tube_length, int(n_sections))       # from the end node
    positions = np.asarray(positions, dtype=float)
    ml = motion_loads(structure, kin, bodies, gravity=gravity, loads=loads)
    nt, m = kin.n_steps, structure.n_members
    per_step = max(1, m * subdivisions)
    step = max(1, block_elements // per_step)
    parts = []
    for k0 in range(0, nt, step):
        k1 = min(nt, k0 + step)
        try:
            parts.append(_solve_block(structure, kin.coords[k0:k1], ml.select(slice(k0, k1)),
                                      positions, int(subdivisions)))
        except MechanismError as err:
            raise _singular_step_error(err, structure, kin, k0, int(subdivisions)) from None
        except TrussfeError as err:
            # a property of the model refused on the copies: the same refusal of one copy
            # names the members as the model does
            one = stacked_structure(structure, kin.coords[k0:k0 + 1])
            try:
                discretise(one, bar_model="pinned-beam", subdivisions=int(subdivisions))
            except TrussfeError as alone:
                raise alone from None
            raise err from None
        if progress is not None:
            progress(k1, nt)
    disp, react, secs, sx, st = ([p[i] for p in parts] for i in range(5))
    T = np.concatenate([s[0] for s in secs])
    V = np.concatenate([s[1] for s in secs])
    M = np.concatenate([s[2] for s in secs])
    sf = SectionForces(position=positions, tension=T, shear=V, moment=M, unit=kin.unit)
    # axial force at the middle of each member's tube (the rigid model's midpoint_axial_force)
    mid = np.concatenate([p[5] for p in parts])
    strain = mid / (structure.E * structure.area)[None]
    return ElasticResponse(time=kin.time, displacements=np.concatenate(disp),
                           reactions=np.concatenate(react), sections=sf,
                           station_x=np.concatenate(sx), station_forces=np.concatenate(st),
                           midpoint_axial_force=mid, strain=strain,
                           subdivisions=int(subdivisions), loads=ml,
                           options={"gravity": gravity, "loads": loads})


def compare_with_rigid(rigid_sections: SectionForces, response: ElasticResponse,
                       rigid_reactions: np.ndarray | None = None,
                       member_ids: Sequence[str] | None = None) -> dict:
    """Largest differences between the FE and rigid-body section forces over a motion.

    Each member's differences are scaled by that member's largest force (tension or shear,
    over all steps and sections) for the forces and by its largest moment for the moments,
    so that near-zero values do not blow the ratio up; a member whose forces are all zero
    (to 1e-12 of the largest in the structure) is scaled by the structure's largest, and the
    moment scale is never below 1e-6 of the largest force in the model times the member's
    length (a pin-jointed member's moments are round-off, not a quantity to divide by).

    Parameters
    ----------
    rigid_sections : SectionForces
        ``SimulationResult.sections`` of the same motion, at the same positions.
    response : ElasticResponse
    rigid_reactions : ndarray, shape (nt, n, dim), optional
        ``SimulationResult.forces.reactions`` (scaled by the largest reaction).
    member_ids : sequence of str, optional
        The members' ids, to name the worst member by its id as well as its index.

    Returns
    -------
    dict
        ``tension``, ``shear``, ``moment`` (and ``reactions``): largest scaled difference;
        ``max``: the largest of them; ``worst``: step, member (index) and section of the
        largest force difference, and ``member_id`` (None without ``member_ids``);
        ``steps``: number of steps compared.
    """
    rs, fs = rigid_sections, response.sections
    if rs.tension.shape != fs.tension.shape or not np.allclose(rs.position, fs.position):
        raise AnalysisError("sections", "the rigid and FE section forces are not at the same "
                            "steps and positions")
    nt, m, k = rs.tension.shape
    fmag = np.maximum(np.abs(rs.tension), np.linalg.norm(rs.shear, axis=-1))
    f_scale = fmag.max(axis=(0, 2))                                        # (m,)
    m_scale = np.linalg.norm(rs.moment, axis=-1).max(axis=(0, 2))
    f_big = max(f_scale.max(initial=0.0), 1e-300)
    f_scale = np.maximum(f_scale, 1e-12 * f_big)
    # moments: a floor from the largest force in the model times the member's length, so
    # that the round-off moments of a pin-jointed member (all zero but for the last digits)
    # are not divided by zero
    length = np.abs(np.asarray(rs.position, dtype=float)).max(axis=1)      # (m,) section span
    m_floor = _MOMENT_FLOOR * f_big * length
    m_scale = np.maximum(m_scale, np.maximum(m_floor, 1e-12 * max(m_scale.max(initial=0.0),
                                                                  1e-300)))
    dT = np.abs(fs.tension - rs.tension) / f_scale[None, :, None]
    dV = np.linalg.norm(fs.shear - rs.shear, axis=-1) / f_scale[None, :, None]
    dM = np.linalg.norm(fs.moment - rs.moment, axis=-1) / m_scale[None, :, None]
    out = {"tension": float(dT.max()), "shear": float(dV.max()), "moment": float(dM.max()),
           "steps": int(nt)}
    worst = np.unravel_index(int(np.argmax(np.maximum(dT, dV))), dT.shape)
    out["worst"] = {"step": int(worst[0]), "member": int(worst[1]),
                    "member_id": None if member_ids is None else member_ids[int(worst[1])],
                    "section": int(worst[2])}
    if rigid_reactions is not None:
        scale = max(np.abs(rigid_reactions).max(), 1e-300)
        out["reactions"] = float(np.abs(response.reactions - rigid_reactions).max() / scale)
    out["max"] = max(v for key, v in out.items() if key in ("tension", "shear", "moment",
                                                            "reactions"))
    return out


#: Moment scale floor of :func:`compare_with_rigid`, as a fraction of the largest force in the
#: model times the member's length: round-off moments (1e-16 of that) compare as 1e-10.
_MOMENT_FLOOR = 1e-6


def simulate_elastic(structure: Structure, motion=None, *,
                     conventions: Conventions = PHYSICAL, n_sections: int = 7,
                     subdivisions: int | None = None,
                     gravity: bool = True, loads: bool = True,
                     progress: Callable[[int, int], None] | None = None):
    """Rigid-body simulation and FE response along the same motion, compared.

    Parameters
    ----------
    structure : Structure
    motion : Motion, optional
        Active-member histories (``None``: the model at rest, one step).
    conventions : Conventions
        Of the rigid-body run (:func:`trussfe.rigid.simulate.simulate`), except that each
        piece's own length is always used in its section inertia: the whole-length inertia of
        Lacy's Appendix A is the inertia of no mass distribution, so no FE load matches it.
    n_sections : int
        Sections per member tube.
    subdivisions : int, optional
        Elements per member (default ``max(n_sections − 1, 2)``).
    gravity, loads : bool
        Passed to :func:`elastic_along_motion` (the rigid model always has both).
    progress : callable, optional
        ``progress(done, total)``, through the rigid-body run and then the FE response.

    Returns
    -------
    sim : SimulationResult
        The rigid-body result (physical section inertia).
    response : ElasticResponse
    comparison : dict
        :func:`compare_with_rigid` (only meaningful with gravity and loads).

    Raises
    ------
    InputError, AnalysisError, MechanismError
        From the rigid solver (a motion that leaves the assembly, a mechanism or an
        indeterminate truss) or the FE solve.
    """
    from ..rigid.simulate import sections_bytes, simulate

    k = subdivisions if subdivisions is not None else max(int(n_sections) - 1, 2)
    counts = (n_sections, k)
    if all(isinstance(c, (int, np.integer)) and not isinstance(c, bool) and c >= 1
           for c in counts):            # other values are refused by the analyses themselves
        # Before the rigid-body run: its results are kept beside the FE response.
        nt, m = (1 if motion is None else motion.n_steps), structure.n_members
        elements, sections = elastic_bytes(nt, m, k, n_sections)
        rigid = along_motion_bytes(nt, structure.n_nodes, m) + sections_bytes(nt, m, n_sections)
        item = ("--subdivisions" if subdivisions is not None and elements > sections
                else "--sections")
        require(rigid + elements + sections, item,
                f"the FE response of {count_text(m * k)} elements and "
                f"{count_text(m * n_sections)} sections at {count_text(nt)} time steps",
                "use fewer sections or subdivisions")
    sim = simulate(structure, motion, n_sections=n_sections, actuators=False,
                   conventions=replace(conventions, full_length_inertia=False),
                   progress=progress)
    resp = elastic_along_motion(structure, sim.kinematics, bodies=sim.bodies,
                                positions=sim.sections.position, subdivisions=k,
                                gravity=gravity, loads=loads, progress=progress)
    cmp = compare_with_rigid(sim.sections, resp, sim.forces.reactions,
                             member_ids=structure.member_ids)
    return sim, resp, cmp
