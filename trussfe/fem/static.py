# SPDX-License-Identifier: MIT
"""Linear static analysis: ``K u = f`` on the free DOFs, then reactions, member forces and
stresses (Lacy eqs. 2.23–2.25, 4.75/4.76; see :mod:`trussfe.mechanics.stress`).

Sign conventions
----------------
* Displacements and reactions are in global axes; reactions are the forces (and moments) the
  supports exert on the structure, ``r = K u − f`` at the fixed DOFs.
* Section forces ``[N, Vy, Vz, T, My, Mz]`` at a station are in member axes and are the
  resultant exerted on the part of the member *before* the station by the part *after* it
  (force on the positive face): N is positive in tension.  ``end_forces`` are the section
  forces at the start (x = 0) and end (x = L) stations, so ``N`` is the same tension at both
  ends of an unloaded bar.
"""
from __future__ import annotations

import logging
import time
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from ..errors import AnalysisError, InputError
from ..io.json_document import result_json
from ..mechanics.active_bodies import active_weight_joint_loads, active_weight_loads
from ..mechanics.stress import station_stresses
from ..model.member_loads import MemberLoad
from ..model.structure import DOF_NAMES, Structure
from ..linalg import SingularMatrixError
from .discretisation import FEModel, discretise
from .member_loads import (MemberLoadVectors, loaded_member_stations, member_load_vector,
                           midpoint_axial_correction)
from .solver import factorise, factorise_truss, raise_mechanism, solve_free
from .truss_band import internal_forces

log = logging.getLogger(__name__)

SECTION_FORCE_NAMES = ("N", "Vy", "Vz", "T", "My", "Mz")

#: Largest relative residual ‖K u − f‖/‖f‖ accepted from the linear solve.  Measured: 1e-9 for
#: a 10,000-bay chain, 3e-8 for 100,000 bays, 1.6e-6 for the 10⁶-DOF space grid; a 300-bay
#: chain with one member removed (a mechanism whose pivots round-off keeps above every
#: backend's singularity test) gives 3e-3.
SOLVE_RESIDUAL_LIMIT = 1e-4


@dataclass
class StaticResult:
    """Result of :func:`solve_static`.

    Attributes
    ----------
    fe : FEModel
    u : ndarray, shape (n_dof,)
        Global displacement vector.
    f : ndarray, shape (n_dof,)
        Global load vector.
    displacements : ndarray, shape (n_nodes, ndof_node)
        Translations and rotations per node, global axes (0 for absent rotations).
    reactions : ndarray, shape (n_nodes, ndof_node)
        Support reactions (0 on free or absent DOFs).
    axial_force : ndarray, shape (m,)
        Axial force at the member midpoint, N, positive in tension.
    axial_stress, strain : ndarray, shape (m,)
        N/A and N/(EA) at the midpoint.
    end_forces : ndarray, shape (m, 2, 6)
        Section forces ``[N, Vy, Vz, T, My, Mz]`` at the start and end stations.
    station_x : ndarray, shape (m, kmax + 1)
        Station positions along each member (NaN-padded past its own k + 1 stations).
    section_forces : ndarray, shape (m, kmax + 1, 6)
        Section forces at the stations (NaN-padded).
    von_mises_s1, von_mises_s2 : ndarray, shape (m, kmax + 1)
        Von Mises stress at points S1 and S2 of each station (NaN-padded).
    max_von_mises : ndarray, shape (m,)
        Largest of S1 and S2 over the member's stations (and, for a member carrying member
        loads, the positions of its point loads).
    element_axial_force : ndarray, shape (n_elements,)
        Axial force of every element averaged along it (tension positive): the input of
        :meth:`FEModel.geometric_stiffness` for a linear buckling analysis.
    residual : float
        ‖K u − f‖ / ‖f‖ over the free DOFs.
    backend : str
        Linear-solver backend that factorised K_ff (:mod:`trussfe.linalg.factor`).
    member_loads : MemberLoadVectors or None
        The member loads applied (:mod:`trussfe.fem.member_loads`), None without any.
    loaded_stations : tuple or None
        ``(members, x, forces)`` of the members carrying member loads: the section forces at
        their finite-element stations and under their point loads
        (:func:`trussfe.fem.member_loads.loaded_member_stations`); None without any.
    timings : dict
        Wall-clock seconds of the steps: ``assemble`` (load vector and stiffness: the sparse
        K, or for a long truss the bars' blocks that go to band storage), ``factorise``,
        ``solve`` (with refinement and the residual), ``recover`` (forces and stresses).
    """

    fe: FEModel
    u: np.ndarray
    f: np.ndarray
    displacements: np.ndarray
    reactions: np.ndarray
    axial_force: np.ndarray
    axial_stress: np.ndarray
    strain: np.ndarray
    end_forces: np.ndarray
    station_x: np.ndarray
    section_forces: np.ndarray
    von_mises_s1: np.ndarray
    von_mises_s2: np.ndarray
    max_von_mises: np.ndarray
    element_axial_force: np.ndarray
    residual: float
    backend: str = ""
    member_loads: MemberLoadVectors | None = None
    loaded_stations: tuple | None = None
    timings: dict = field(default_factory=dict)

    @property
    def structure(self) -> Structure:
        """The analysed structure."""
        return self.fe.structure


def section_forces(fe: FEModel, u: np.ndarray, element_forces: np.ndarray | None = None,
                   overwrite: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """Section forces at every station of every member.

    ``element_forces`` (from :meth:`FEModel.element_forces`) is computed when not given;
    with ``overwrite`` the section forces of a model of one element per member are made in
    its place (no copy: 129 MB for the 1.3 million bars of a 10⁶-DOF grid).

    Returns
    -------
    station_x : ndarray, shape (m, kmax + 1)
    forces : ndarray, shape (m, kmax + 1, 6)
        NaN past a member's own ``k + 1`` stations.
    """
    fel = fe.element_forces(u) if element_forces is None else element_forces  # (el, 2, 6)
    m = fe.structure.n_members
    k = fe.member_subdivisions
    kmax = int(k.max()) if m else 1
    if kmax == 1 and fe.n_elements == m:
        # one element per member, in member order (a truss): the two stations are its ends
        F = fel if overwrite and element_forces is not None else fel.copy()
        F[:, 0] *= -1.0
        return fe.element_x.copy(), F
    x = np.full((m, kmax + 1), np.nan)
    F = np.full((m, kmax + 1, 6), np.nan)
    emem = fe.element_member
    j = np.arange(fe.n_elements) - fe.member_elements[emem]
    # station j (left end of element j): minus the force on the element's start
    x[emem, j] = fe.element_x[:, 0]
    F[emem, j] = -fel[:, 0]
    last = fe.member_elements[1:] - 1
    x[np.arange(m), k] = fe.element_x[last, 1]
    F[np.arange(m), k] = fel[last, 1]
    return x, F


def solve_static(structure: Structure, bar_model: str = "truss",
                 subdivisions: int | None = None, loads: np.ndarray | None = None,
                 self_weight: bool = True, fe: FEModel | None = None,
                 backend: str = "auto", member_loads: Sequence[MemberLoad] | None = None
                 ) -> StaticResult:
    """Linear static analysis of a structure.

    Parameters
    ----------
    structure : Structure
    bar_model : {"truss", "pinned-beam"}
    subdivisions : int, optional
        Sub-elements per frame member.
    loads : ndarray, shape (n_nodes, ndof_node), optional
        Nodal loads replacing ``structure.loads``.
    self_weight : bool
        Include gravity on members and nodal masses (``structure.gravity``).  A member weighs
        ρAL; an active member (``[active_members]``) its base and leadscrew tube instead
        (:func:`~trussfe.mechanics.active_bodies.active_weight_loads`, loads along it).
    fe : FEModel, optional
        A discretisation to reuse.
    backend : {"auto", "superlu", "pardiso"}
        Linear-solver backend (:mod:`trussfe.linalg.factor`).
    member_loads : sequence of MemberLoad, optional
        Loads along members (default ``structure.extensions["member_loads"]``; ``()`` for
        none): their equivalent nodal loads join the load vector and their fixed-end forces
        are subtracted in the recovery of the member forces (:mod:`trussfe.fem.member_loads`).

    Returns
    -------
    StaticResult

    Raises
    ------
    MechanismError
        The structure cannot carry load (singular stiffness, or a solve whose residual exceeds
        :data:`SOLVE_RESIDUAL_LIMIT`); the message gives the number of independent
        mechanisms and the moving nodes.

    Notes
    -----
    The load cases of a model (prescribed displacements, imposed strains, several right-hand
    sides on one factorisation) are solved by :func:`trussfe.fem.load_cases.solve_load_cases`
    through the same steps (:class:`LinearSystem`).

    Examples
    --------
    A bar of EA = 2e7 N pulled by 1 kN stretches by PL/EA = 5e-5 m:

    >>> from trussfe.model.structure import build_structure
    >>> from trussfe.model.sections import Section, Material
    >>> s = build_structure([[0.0, 0.0], [1.0, 0.0]], [(0, 1)],
    ...                     section=Section("a", area=1e-4), material=Material("s", 2e11, 8e10),
    ...                     supports={0: "xy", 1: "y"}, loads={1: [1000.0, 0.0]})
    >>> r = solve_static(s)
    >>> float(r.displacements[1, 0]), float(r.axial_force[0])
    (5e-05, 1000.0)
    """
    if fe is None:
        fe = discretise(structure, bar_model=bar_model, subdivisions=subdivisions)
    t0 = time.perf_counter()
    f = fe.load_vector(self_weight=self_weight, loads=loads)
    if member_loads is None:
        member_loads = structure.extensions.get("member_loads", ())
    if self_weight:
        # active members weigh their base and leadscrew tube, not ρAL
        joints, along = active_member_weight(fe)
        f = f + joints
        member_loads = tuple(member_loads) + along
    mlv = member_load_vector(fe, member_loads) if len(member_loads) else None
    if mlv is not None:
        f = f + mlv.global_vector
    system = LinearSystem(fe, backend, started=t0)
    u, residual = system.solve(f)
    # the loads the elements carry themselves are those applied: without self-weight none
    # but the member loads
    base = (fe.element_self_weight_local() if self_weight
            else [np.zeros(g.n_local) for g in fe.groups])
    if mlv is not None:
        base = [b + ml for b, ml in zip(base, mlv.local)]
    return system.recover(u, f, residual, base, member_loads=mlv)


def active_member_weight(fe: FEModel) -> tuple[np.ndarray, tuple[MemberLoad, ...]]:
    """What the weight of the active members' bases and leadscrew tubes adds to the uniform
    self-weight ρAL of a discretisation (:mod:`trussfe.mechanics.active_bodies`).

    An active member modelled as an axial-only bar keeps its weight at its joints, as every
    bar does: joint loads (:func:`~trussfe.mechanics.active_bodies.active_weight_joint_loads`),
    with the bar's axial force that of the actuator.  A frame member (a beam, or a bar of the
    ``pinned-beam`` model) carries it along its length, where it bends the member: loads along
    it (:func:`~trussfe.mechanics.active_bodies.active_weight_loads`).

    Returns
    -------
    joints : ndarray, shape (n_dof,)
        The joint loads, to add to the load vector.
    along : tuple of MemberLoad
        The loads along frame members, to apply as member loads.
    """
    s = fe.structure
    f = np.zeros(fe.n_dof)
    if not s.extensions.get("active_members") or not np.any(s.gravity):
        return f, ()
    f[fe.node_dofs[:, : s.dim]] += active_weight_joint_loads(s, members=~fe.is_frame)
    return f, active_weight_loads(s, members=fe.is_frame)


class LinearSystem:
    """The free-DOF stiffness of a discretisation, factorised once, and the recovery of
    displacements, reactions and section forces from it: the steps of a linear static
    analysis, shared by one load (:func:`solve_static`) and many load cases
    (:func:`trussfe.fem.load_cases.solve_load_cases`).

    Parameters
    ----------
    fe : FEModel
    backend : str
        Linear-solver backend (:mod:`trussfe.linalg.factor`).
    started : float, optional
        ``time.perf_counter()`` when the load vectors began to be assembled (the
        ``assemble`` timing counts from there).

    Raises
    ------
    MechanismError
        K_ff is singular.
    """

    def __init__(self, fe: FEModel, backend: str = "auto", started: float | None = None):
        self.fe = fe
        t0 = time.perf_counter() if started is None else started
        # a long truss of single bars: K_ff banded straight from the bars, K·u bar by bar
        truss = factorise_truss(fe, backend)
        if truss is not None:
            fac, seconds = truss
            self.K = None
            t2 = time.perf_counter()
            t1 = t2 - seconds["factorise"]   # band fill and factorisation after the blocks
        else:
            self.K = fe.stiffness(copy=False)    # read only here
            t1 = time.perf_counter()
            fac = factorise(self.K, fe.free, fe=fe, item=self.item, backend=backend)
            t2 = time.perf_counter()
        self.factor = fac
        self.timings = {"assemble": t1 - t0, "factorise": t2 - t1}

    @property
    def item(self) -> str:
        """What an error names: the model file or the model's name."""
        s = self.fe.structure
        return s.source or s.name

    def stiffness(self):
        """The global K (assembled on demand for a truss solved from its bars)."""
        return self.fe.stiffness(copy=False) if self.K is None else self.K

    def internal_forces(self, u: np.ndarray) -> np.ndarray:
        """K u for one displacement vector or a (n_dof, r) block of them."""
        return internal_forces(self.fe, u) if self.K is None else self.K @ u

    def solve(self, f: np.ndarray, u_prescribed: np.ndarray | None = None
              ) -> tuple[np.ndarray, np.ndarray | float]:
        """Displacements under loads ``f`` and displacements ``u_prescribed`` of the fixed
        DOFs: ``K_ff u_f = f_f − K_fp u_p``.

        Parameters
        ----------
        f : ndarray, shape (n_dof,) or (n_dof, r)
            Load vectors (``r`` right-hand sides solved together).
        u_prescribed : ndarray, same shape as ``f``, optional
            Prescribed displacements on the fixed DOFs (zero elsewhere); None: all zero.

        Returns
        -------
        u : ndarray, same shape as ``f``
        residual : float or ndarray of shape (r,)
            ‖K u − f‖ / ‖f − K u_p‖ over the free DOFs, per right-hand side.

        Raises
        ------
        MechanismError
            A mechanism hidden by round-off (non-finite solution, or residual above
            :data:`SOLVE_RESIDUAL_LIMIT`).
        """
        fe = self.fe
        t2 = time.perf_counter()
        rhs = f if u_prescribed is None else f - self.stiffness() @ u_prescribed
        try:
            u = solve_free(self.factor, fe.free, rhs)
        except SingularMatrixError:
            # a non-finite solution from a factor that passed its pivot test: a mechanism
            # hidden by round-off — say which
            raise_mechanism(self.stiffness(), fe, self.item)
        if u_prescribed is not None:
            u[fe.fixed] = u_prescribed[fe.fixed]
        r_all = self.internal_forces(u) - f
        if u.ndim == 1:
            nf = np.linalg.norm(rhs[fe.free])
            nr = np.linalg.norm(r_all[fe.free])
            residual = float(nr / nf) if nf > 0 else float(nr)
        else:
            nf = np.linalg.norm(rhs[fe.free], axis=0)
            nr = np.linalg.norm(r_all[fe.free], axis=0)
            residual = np.where(nf > 0, nr / np.where(nf > 0, nf, 1.0), nr)
        if not np.all(residual <= SOLVE_RESIDUAL_LIMIT):
            # the factorisation passed its pivot test but does not solve the system: a
            # mechanism hidden by round-off (or worse) — say which, never return such
            # displacements
            raise_mechanism(self.stiffness(), fe, self.item)
        if not np.all(np.isfinite(u)):
            raise AnalysisError(self.item, "the linear solve produced non-finite "
                                "displacements; the stiffness is too ill-conditioned to trust")
        self._reactions = np.where(fe.fixed[:, None] if r_all.ndim == 2 else fe.fixed,
                                   r_all, 0.0)
        self.timings["solve"] = time.perf_counter() - t2
        return u, residual

    def recover(self, u: np.ndarray, f: np.ndarray, residual: float,
                f_local: list[np.ndarray] | None = None,
                reactions: np.ndarray | None = None,
                member_loads: MemberLoadVectors | None = None) -> StaticResult:
        """Reactions, section forces and stresses of one displacement vector.

        Parameters
        ----------
        u, f : ndarray, shape (n_dof,)
            Displacements and the load vector they carry.
        residual : float
        f_local : list of ndarray, optional
            Loads carried by the elements, per group (:meth:`FEModel.element_forces`;
            default the frames' self-weight).
        reactions : ndarray, shape (n_dof,), optional
            Support reactions ``(K u − f)`` on the fixed DOFs; by default those of the last
            :meth:`solve` of a single right-hand side.  Spring forces ``−k u`` are added.
        member_loads : MemberLoadVectors, optional
            The member loads in ``f`` and ``f_local`` (:mod:`trussfe.fem.member_loads`), for
            the section forces along loaded members.
        """
        t3 = time.perf_counter()
        fe = self.fe
        s = fe.structure
        reac = self._reactions if reactions is None else reactions
        if fe.spring_stiffness is not None:
            # the force of an elastic support on the structure is a reaction
            reac = reac - fe.spring_stiffness * u
        fel = fe.element_forces(u, f_local)
        element_axial = 0.5 * (fel[:, 1, 0] - fel[:, 0, 0])
        if member_loads is not None:
            # the average along each element, which its geometric stiffness takes
            element_axial = element_axial + member_loads.element_axial
        x, F = section_forces(fe, u, fel, overwrite=True)       # fel is not used after this
        m = s.n_members
        k = fe.member_subdivisions
        # the two end sections (with one element per member, F holds exactly those)
        ends = F if F.shape[1] == 2 else np.stack([F[:, 0], F[np.arange(m), k]], axis=1)
        # midpoint axial force: N is linear along a member under uniform distributed load
        # (self-weight), so the mean of its end values; loads along members with a point
        # or a varying axial component make N non-linear, and statics corrects the mean
        N_mid = 0.5 * (ends[:, 0, 0] + ends[:, 1, 0])
        if member_loads is not None:
            N_mid = N_mid + midpoint_axial_correction(member_loads, s.lengths(), m)
        s1, s2 = _stresses(fe, F)
        # largest over the stations; fmax skips the NaN padding past a member's own stations
        max_vm = _largest_per_row(np.fmax(s1, s2))
        stations = None
        if member_loads is not None:
            # a loaded member's moment peaks between its finite-element stations (under a
            # point load; a pin-ended bar bends between its joints): its largest stress is
            # taken over the stations of its loads too
            stations = loaded_member_stations(fe, member_loads, x, F)
            max_vm = _with_loaded_stations(fe, stations, max_vm)
        result = StaticResult(
            fe=fe, u=u, f=f, displacements=fe.node_values(u), reactions=fe.node_values(reac),
            axial_force=N_mid, axial_stress=N_mid / s.area, strain=N_mid / (s.E * s.area),
            end_forces=ends, station_x=x, section_forces=F, von_mises_s1=s1,
            von_mises_s2=s2, max_von_mises=max_vm,
            element_axial_force=element_axial, residual=residual,
            backend=self.factor.backend, member_loads=member_loads, loaded_stations=stations)
        t4 = time.perf_counter()
        # wall-clock seconds: load vector and stiffness (sparse K, or the bars' blocks for
        # the band), factorisation (band fill included), solve with refinement and residual,
        # recovery
        result.timings = {**self.timings, "recover": t4 - t3}
        log.info("static solve: %d DOFs, residual %.2e", fe.n_dof, residual)
        return result


def _largest_per_row(a: np.ndarray) -> np.ndarray:
    """The largest value of each row of ``a`` (m, k), NaN skipped (all-NaN rows: NaN).

    ``numpy.fmax`` column by column, in the order of ``np.fmax.reduce(a, axis=1)`` and
    with the same values, without a reduction over the short station axis (0.6 ms against
    11 ms for the 260,000 members of two stations of a 180 × 180 space grid).
    """
    out = a[:, 0].copy()
    for j in range(1, a.shape[1]):          # over the few stations, not the members
        np.fmax(out, a[:, j], out=out)
    return out


def _with_loaded_stations(fe: FEModel, stations: tuple, max_vm: np.ndarray) -> np.ndarray:
    """``max_vm`` with each loaded member's von Mises stress at its load stations (Lacy eqs.
    2.24, 2.25) taken into its largest.

    Raises
    ------
    InputError
        A loaded member bends but its section has no outer-fibre distance ``c`` (or no second
        moment of area): its bending stress cannot be computed.
    """
    lm, lx, lF = stations
    if lm.size == 0:
        return max_vm
    s = fe.structure
    vm = station_stresses(s, lF, lm)
    unknown = np.isfinite(lx) & ~np.isfinite(vm.s2)
    if np.any(unknown):
        i = int(lm[np.flatnonzero(unknown.any(axis=1))[0]])
        raise InputError(f"sections.{s.sections[i].name}",
                         f"c (outer-fibre distance) or I is missing (member {s.member_ids[i]}, "
                         "which bends under its member loads); its bending stress needs them: "
                         "give c and I (or the tube's diameters)")
    out = max_vm.copy()
    out[lm] = np.fmax(out[lm], _largest_per_row(np.fmax(vm.s1, vm.s2)))
    return out


def _stresses(fe: FEModel, F: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Von Mises stress at S1 and S2 of every station (Lacy eqs. 2.24, 2.25)."""
    s = fe.structure
    if np.any(fe.is_frame):
        bad = fe.is_frame & ~(np.isfinite(s.c) & (s.c > 0))
        if np.any(bad):
            i = int(np.flatnonzero(bad)[0])
            raise InputError(f"sections.{s.sections[i].name}",
                             f"c (outer-fibre distance) is missing (member {s.member_ids[i]}); "
                             "the bending stress of a beam needs it: give c")
        vm = station_stresses(s, F)
        return vm.s1, vm.s2
    # truss bars only: section forces are axial, so von Mises is |N|/A at S1 and S2
    # (von_mises with V = M = 0), taken directly for large pin-jointed models
    s1 = np.abs(F[..., 0]) / s.area[:, None]
    return s1, s1.copy()


def reacting_nodes(fe: FEModel) -> np.ndarray:
    """(n, ndof_node) bool: the DOFs held by a support or a spring, where reactions arise."""
    s = fe.structure
    springs = s.extensions.get("springs")
    if springs is None:
        return s.supports
    return s.supports | (springs.stiffness > 0)


def static_json(result: StaticResult, command: str = "static") -> dict:
    """The ``static`` JSON document (docs/json.md, ``static``).

    ``nodes[id]``: ``displacement`` (translations), ``rotation`` (where the node has
    rotational DOFs), ``reaction`` (supported nodes: forces) and ``reaction_moment`` (where a
    rotation is supported).  ``members[id]``: ``axial_force``, ``axial_stress``, ``strain``,
    ``max_von_mises``, ``end_forces`` = ``{"start": {N, Vy, Vz, T, My, Mz}, "end": {...}}``
    (section forces, member axes, N tension positive); for a member carrying member loads,
    ``stations`` = ``{x, N, Vy, Vz, T, My, Mz}``: the section forces along it
    (:func:`trussfe.fem.member_loads.loaded_member_stations`).
    """
    fe = result.fe
    s = fe.structure
    dim = s.dim
    names = DOF_NAMES[dim]
    nodes = {}
    sup = reacting_nodes(fe)
    for i, nid in enumerate(s.node_ids):
        d = {"displacement": result.displacements[i, :dim].tolist()}
        if fe.has_rotation[i]:
            d["rotation"] = result.displacements[i, dim:].tolist()
        if sup[i, :dim].any():
            d["reaction"] = result.reactions[i, :dim].tolist()
        if fe.has_rotation[i] and sup[i, dim:].any():
            d["reaction_moment"] = result.reactions[i, dim:].tolist()
        nodes[nid] = d
    members = {}
    along = {}
    if result.loaded_stations is not None:
        for i, x, F in zip(*result.loaded_stations):
            ok = np.isfinite(x)
            along[int(i)] = {"x": x[ok].tolist(), **{
                n: F[ok, c].tolist() for c, n in enumerate(SECTION_FORCE_NAMES)}}
    for i, mid in enumerate(s.member_ids):
        members[mid] = {
            "axial_force": float(result.axial_force[i]),
            "axial_stress": float(result.axial_stress[i]),
            "strain": float(result.strain[i]),
            "max_von_mises": float(result.max_von_mises[i]),
            "end_forces": {
                end: dict(zip(SECTION_FORCE_NAMES, result.end_forces[i, e].tolist()))
                for e, end in enumerate(("start", "end"))},
        }
        if i in along:
            members[mid]["stations"] = along[i]
    return result_json(
        command, s.name,
        bar_model=fe.bar_model,
        subdivisions=fe.subdivisions,
        dof_names=list(names),
        n_dof=fe.n_dof,
        residual=result.residual,
        nodes=nodes,
        members=members,
    )
