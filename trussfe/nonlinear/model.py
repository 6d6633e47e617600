# SPDX-License-Identifier: MIT
"""The geometrically nonlinear model: DOF numbering, internal forces and tangent stiffness.

A :class:`NonlinearModel` turns a :class:`~trussfe.model.Structure` into co-rotational elements:

* every bar member (``--bar-model truss``) is one co-rotational truss element carrying the
  member's failure laws;
* with ``bar_model = "pinned-beam"`` a bar becomes ``subdivisions`` co-rotational beam
  elements whose end rotations are released (each member end owns a rotation DOF), so it can
  buckle by bending — the Euler column of the validation suite;
* a ``type = "beam"`` member (frame member) becomes ``subdivisions`` beam elements whose
  unreleased ends share the joint's rotation DOF.

Global DOF vector (``point`` = joints first, then the points inside subdivided members)::

    u = [translations (point, dim) row-major | rotations (rotation slot, 1 or 3)]

In 2-D a rotation slot holds one angle (updated additively).  In 3-D a slot is either

* **multiplicative** (the rule): it stores the total rotation vector ψ of the point
  (``R = exp(S(ψ))``, global components) while its three DOFs are *spin* components in the
  slot's basis ``Q`` (global axes at joints, member axes inside members); a state is advanced
  with :meth:`NonlinearModel.add`, which composes rotations
  (:func:`~trussfe.nonlinear.beam3d.compose`);
* **additive** (where a rotation component must be held): it stores ``φ = Qᵀψ`` and its DOFs
  are the increments of ``φ`` (``δw = Tₛ(ψ) Q δφ``), so that holding a component of ``φ`` is
  a holonomic constraint.  These are the start ends of members free to twist at both ends
  (the axial component of the start rotation vector is held, so the member cannot spin) and
  joints with some but not all rotations supported;
* **relative** (an additive slot of a member end whose twist — or, under a torsion release
  of an end rigid in bending, whose bending rotations — are the joint's): it stores the
  end's rotation relative to its joint's, ``R_end = R_joint exp(S(Qφ))``, with the
  components that are the joint's held at zero.

What a release frees is :mod:`trussfe.mechanics.releases`, the same definition as the linear
discretisation's: a released end transmits no bending moment, and torsion only where the
joint has rotational stiffness from a rigid beam end or a rotational support.
"""
from __future__ import annotations

import logging

import numpy as np

from ..budget import count_text, require
from ..errors import InputError
from ..mechanics.active_bodies import active_weight_joint_loads, member_bodies
from ..mechanics.mass import mass_per_length
from ..mechanics.geometry import member_lengths, member_vectors
from ..model.bar_models import BAR_MODELS, DEFAULT_POSTCRITICAL_SUBDIVISIONS
from ..model.structure import Structure
from ..mechanics.dof_numbering import member_end_rotations, number_dofs
from ..mechanics.releases import HELD, JOINT, OWN
from .beam3d import (beam3d_matrices, compose, expm_so3, reference_frames,
                     tangent_operator, tangent_operator_derivative)
from .elements import (beam2d_local, beam2d_matrices, truss_kinematics,
                       truss_matrices)
from .failure import FailureLaws, axial_law, failure_margins

log = logging.getLogger(__name__)

#: Peak memory of a post-critical path per co-rotational beam element, bytes, by dimension
#: (measured on the 2-D and 3-D Euler columns with 5,000 to 40,000 elements: about 12 KiB in
#: 2-D and 35 KiB in 3-D — element arrays, tangent assembly, factor, linear buckling mode and
#: the path).
BYTES_PER_BEAM_ELEMENT = {2: 16 * 1024, 3: 48 * 1024}


class NonlinearModel:
    """Co-rotational discretisation of a structure.

    Parameters
    ----------
    structure : Structure
    bar_model : {"truss", "pinned-beam"}
        How pin-jointed bars are modelled.
    subdivisions : int
        Beam elements per beam (or pinned-beam) member (default
        :data:`~trussfe.model.bar_models.DEFAULT_POSTCRITICAL_SUBDIVISIONS`).
    laws : FailureLaws, optional
        Failure laws per member (only bar members modelled as truss elements use them).
    subdivisions_item : str
        The option or model item that gave ``subdivisions``, named when it is refused.

    Raises
    ------
    InputError
        An unknown bar model, ``subdivisions`` below 1 or more beam elements than the free
        memory holds (:func:`trussfe.budget.require`), loads along members, shear areas.

    Attributes
    ----------
    X : ndarray, shape (point, dim)
        Reference positions of all points (joints first).
    free : ndarray of bool, shape (dof,)
    load : ndarray, shape (dof,)
        Reference load pattern ``f`` (``[loads]``), scaled by the load factor λ.
    alive : ndarray of bool, shape (member,)
        Members still in the structure (failed members are removed).
    plastic : ndarray, shape (truss element,)
        Committed plastic strain of each truss element.
    rdof : int
        DOFs per rotation slot (1 in 2-D, 3 in 3-D).
    slot_basis : ndarray, shape (slot, 3, 3)
        3-D only: the basis ``Q`` (columns) of each rotation slot's DOFs.
    slot_additive : ndarray of bool, shape (slot,)
        3-D only: slots parametrised additively by ``φ = Qᵀψ`` (see the module notes).
    """

    def __init__(self, structure: Structure, bar_model: str = "truss",
                 subdivisions: int = DEFAULT_POSTCRITICAL_SUBDIVISIONS,
                 laws: FailureLaws | None = None, subdivisions_item: str = "subdivisions"):
        if bar_model not in BAR_MODELS:
            raise InputError("--bar-model", f"unknown bar model {bar_model!r}; valid: "
                                            f"{', '.join(BAR_MODELS)}")
        if int(subdivisions) < 1:
            raise InputError(subdivisions_item, f"must be at least 1, got {subdivisions}")
        s = structure
        beam_members = s.is_beam | (bar_model == "pinned-beam")
        # refuse a discretisation that cannot fit in memory before any element array exists
        n_beam = int(np.count_nonzero(beam_members))
        n_el = n_beam * int(subdivisions)
        require(n_el * BYTES_PER_BEAM_ELEMENT[s.dim], subdivisions_item,
                f"{count_text(n_el)} co-rotational beam elements ({n_beam:,} beam members x "
                f"{count_text(subdivisions)} subdivisions)", "use fewer subdivisions")
        # the co-rotational elements are Euler–Bernoulli beams under nodal loads: refuse what
        # they would otherwise silently drop
        if s.extensions.get("member_loads"):
            raise InputError("member_loads", "loads along members are not applied by the "
                             "co-rotational (post-critical) analysis; apply them as nodal "
                             "loads at the joints")
        timo = (s.is_beam | (bar_model == "pinned-beam")) & (
            np.isfinite(s.shear_area_y) | np.isfinite(s.shear_area_z))
        if np.any(timo):
            i = int(np.flatnonzero(timo)[0])
            raise InputError(f"sections.{s.sections[i].name}", "the co-rotational "
                             "(post-critical) beams have no shear deformation: remove the "
                             "shear areas (Timoshenko) of this section for this analysis")
        self.structure = s
        self.dim = s.dim
        self.bar_model = bar_model
        self.rdof = 1 if s.dim == 2 else 3                 # DOFs per rotation slot
        self._set_laws(beam_members, laws)
        self._truss_elements(beam_members)
        self._number_points_and_slots(beam_members, int(subdivisions))
        self._beam_properties()
        held = self._element_dofs()
        self._supports(held)
        self._springs()
        self._loads()
        self.dead = self._dead_load()
        self.alive = np.ones(s.n_members, dtype=bool)
        self.plastic = np.zeros(len(self.t_member))
        #: (cause, truss element): events already reported (each is reported once)
        self.silenced = np.zeros((3, len(self.t_member)), dtype=bool)

    # ------------------------------------------------------------------ construction
    def _set_laws(self, beam_members: np.ndarray, laws: FailureLaws | None) -> None:
        """The members' failure laws; a buckling law only on bars modelled as truss elements."""
        s = self.structure
        laws = laws if laws is not None else FailureLaws.none(s.n_members)
        bad = np.flatnonzero(beam_members & (laws.buckling > 0))
        if bad.size:
            raise InputError(f"failure.members.{s.member_ids[int(bad[0])]}",
                             "a buckling law applies to bars modelled as truss elements; a "
                             "beam (or pinned-beam) member buckles through its own bending "
                             "stiffness — remove the buckling law or use --bar-model truss")
        self.laws = laws

    def _truss_elements(self, beam_members: np.ndarray) -> None:
        """One co-rotational truss element per bar member (``t_*`` attributes)."""
        s = self.structure
        t_mem = np.flatnonzero(~beam_members)
        self.t_member = t_mem
        self.t_conn = s.connectivity[t_mem]
        self.t_laws = self.laws.subset(t_mem)
        self.t_EA = (s.E * s.area)[t_mem]

    def _number_points_and_slots(self, beam_members: np.ndarray, k: int) -> None:
        """Points and rotation slots: ``k`` beam elements per beam member, the points inside
        members after the joints, and the rotation slot of every beam element end.

        The joints' translations (DOFs ``dim·node + axis``) and their rotation slots (joints
        with rotations, in node order) are numbered as the linear discretisation numbers them
        (:func:`~trussfe.mechanics.dof_numbering.number_dofs`).  The rest differs in order and
        in kind: every point's translations come before all rotations (points inside members
        follow the joints, translations in global axes), and a rotation slot holds the whole
        rotation of a member end or inner point (3 DOFs in 3-D, the components that are the
        joint's or held are fixed DOFs), where the linear model numbers only the owned
        components (member axes) — a co-rotational slot stores a finite rotation, which cannot
        be split into independent components.  Slots: joints first, then the member ends that
        own a rotation (all start ends, then all end ends), then the points inside members.
        """
        s = self.structure
        dim, n = s.dim, s.n_nodes
        conn = s.connectivity
        b_mem = np.flatnonzero(beam_members)
        nb = b_mem.size
        self._b_mem, self._k = b_mem, k
        # what each end rotation is, and which joints carry rotations numbered in which
        # order: the linear discretisation's definitions (mechanics.dof_numbering)
        axis = s.member_vectors() / s.lengths()[:, None]
        er = member_end_rotations(s, self.bar_model, axis)
        self.end_rotations = er
        rigid_end = er.shared & beam_members[:, None]
        self.rigid_end = rigid_end
        joint_slot = number_dofs(s, self.bar_model, k, er).joint_rotation_rank()
        nslot = int(er.joint_rotation.sum())
        # points inside each beam member: (nb, k-1)
        inner_pts = n + np.arange(nb * (k - 1)).reshape(nb, k - 1)
        t = (np.arange(1, k) / k)[None, :, None]
        Xa, Xb = s.coords[conn[b_mem, 0]], s.coords[conn[b_mem, 1]]
        X_inner = (Xa[:, None, :] * (1 - t) + Xb[:, None, :] * t).reshape(-1, dim)
        chain = np.concatenate([conn[b_mem, :1], inner_pts, conn[b_mem, 1:]], axis=1)
        slots = np.empty((nb, k + 1), dtype=np.int64)
        # start and end slots: the joint's when every end rotation is the joint's, else a
        # slot of the member end
        for col, end in ((0, 0), (k, 1)):
            rigid = rigid_end[b_mem, end]
            slots[rigid, col] = joint_slot[conn[b_mem[rigid], end]]
            nown = int((~rigid).sum())
            slots[~rigid, col] = nslot + np.arange(nown)
            nslot += nown
        slots[:, 1:k] = nslot + np.arange(nb * (k - 1)).reshape(nb, k - 1)
        nslot += nb * (k - 1)
        self._slots = slots
        self.b_member = np.repeat(b_mem, k)
        self.b_conn = np.stack([chain[:, :-1].ravel(), chain[:, 1:].ravel()], axis=1)
        self.b_slot = np.stack([slots[:, :-1].ravel(), slots[:, 1:].ravel()], axis=1)
        self.X = np.vstack([s.coords, X_inner]) if nb else s.coords.copy()
        self.n_points = self.X.shape[0]
        self.n_rot = nslot
        self.ndof = self.n_points * dim + nslot * self.rdof
        self.joint_slot = joint_slot

    def _beam_properties(self) -> None:
        """Stiffness properties of the beam elements (``b_EA``, ``b_EI``, …), checked."""
        s = self.structure
        nb = self._b_mem.size
        self.b_EA = (s.E * s.area)[self.b_member]
        Ib = s.Iz[self.b_member] if self.dim == 2 else s.Iy[self.b_member]
        props = [("second moment of area (Iy)", Ib)]
        if self.dim == 3:
            props += [("second moment of area (Iz)", s.Iz[self.b_member]),
                      ("torsion constant (J)", s.J[self.b_member]),
                      ("shear modulus (G)", s.G[self.b_member])]
        for what, v in props:
            if nb and not np.all(np.isfinite(v) & (v > 0)):
                i = int(self.b_member[np.flatnonzero(~(np.isfinite(v) & (v > 0)))[0]])
                raise InputError(f"members.{s.member_ids[i]}",
                                 f"the member is modelled as a beam but its {what} is "
                                 "missing or not positive")
        self.b_EI = s.E[self.b_member] * Ib
        if self.dim == 3:
            self.b_EIz = (s.E * s.Iz)[self.b_member]
            self.b_GJ = (s.G * s.J)[self.b_member]
            self.b_orientation = s.orientation[self.b_member]

    def _element_dofs(self) -> np.ndarray:
        """Global DOFs of every element (``t_dofs``, ``b_dofs``) and, in 3-D, how each slot is
        parametrised (``slot_basis``, ``slot_additive``, ``slot_parent``) from the member ends'
        releases.

        Returns
        -------
        ndarray of int
            3-D: the held rotation DOFs of member ends (components that are the joint's or
            held, :mod:`~trussfe.mechanics.releases`); empty otherwise.
        """
        s = self.structure
        dim, k = self.dim, self._k
        b_mem, slots = self._b_mem, self._slots
        nb = b_mem.size
        nslot = self.n_rot
        conn = s.connectivity
        er, rigid_end, joint_slot = self.end_rotations, self.rigid_end, self.joint_slot
        tdofs = lambda pts: (pts[:, :, None] * dim + np.arange(dim)).reshape(len(pts), 2 * dim)
        self.t_dofs = tdofs(self.t_conn)
        rot0 = self.n_points * dim
        #: 3-D slots parametrised additively by their rotation vector in the slot basis
        self.slot_additive = np.zeros(nslot, dtype=bool)
        #: 3-D slots whose rotation is relative to a joint's (``-1``: absolute); see _beam3d
        self.slot_parent = np.full(nslot, -1)
        held = np.zeros(0, dtype=np.int64)
        if nb and dim == 3:
            sdofs = lambda sl: rot0 + sl[:, None] * 3 + np.arange(3)
            bd = np.empty((len(self.b_conn), 18), dtype=np.int64)
            bd[:, 0:3], bd[:, 6:9] = tdofs(self.b_conn)[:, :3], tdofs(self.b_conn)[:, 3:]
            bd[:, 3:6] = sdofs(self.b_slot[:, 0])
            bd[:, 9:12] = sdofs(self.b_slot[:, 1])
            # spin bases: global axes at joints, the member's axes at its own points
            member_axes = reference_frames(s.coords, conn[b_mem], s.orientation[b_mem])
            Q = np.broadcast_to(np.eye(3), (nslot, 3, 3)).copy()
            owned = slots.copy()
            owned[rigid_end[b_mem, 0], 0] = -1
            owned[rigid_end[b_mem, 1], k] = -1
            has = owned >= 0
            Q[owned[has]] = np.repeat(member_axes, k + 1, axis=0).reshape(nb, k + 1, 3, 3)[has]
            self.slot_basis = Q
            # own end slots: components that are the joint's make the slot relative to the
            # joint's slot (those components of the relative rotation held at zero); held
            # components make it additive with them fixed
            held_list = []
            for col, end in ((0, 0), (k, 1)):
                own = ~rigid_end[b_mem, end]
                st = er.state[b_mem[own], end].copy()                 # (own end, 3)
                if self.bar_model == "pinned-beam" and end == 1:
                    # a pinned-beam bar has no torsion: its twist is held at its start only
                    st[~s.is_beam[b_mem[own]], 0] = OWN
                sl = slots[own, col]
                rel = np.any(st == JOINT, axis=1)
                self.slot_parent[sl[rel]] = joint_slot[conn[b_mem[own][rel], end]]
                fix = (st == JOINT) | (st == HELD)
                self.slot_additive[sl[fix.any(axis=1)]] = True
                e, c = np.nonzero(fix)
                held_list.append(rot0 + 3 * sl[e] + c)
            held = np.concatenate(held_list)
            # parent slot DOFs of every element end (own DOFs again, unused, where none);
            # only models with relative slots carry them
            if not np.any(self.slot_parent >= 0):
                bd = bd[:, :12]
            for end, (own_cols, cols) in enumerate(((slice(3, 6), slice(12, 15)),
                                                    (slice(9, 12), slice(15, 18)))):
                par = self.slot_parent[self.b_slot[:, end]]
                if bd.shape[1] == 18:
                    bd[:, cols] = np.where(par[:, None] >= 0, sdofs(np.maximum(par, 0)),
                                           bd[:, own_cols])
            self.b_dofs = bd
        elif nb:
            bd = np.empty((len(self.b_conn), 6), dtype=np.int64)
            bd[:, [0, 1, 3, 4]] = tdofs(self.b_conn)
            bd[:, 2] = self.n_points * dim + self.b_slot[:, 0]
            bd[:, 5] = self.n_points * dim + self.b_slot[:, 1]
            self.b_dofs = bd
        else:
            self.b_dofs = np.zeros((0, 6 if dim == 2 else 18), dtype=np.int64)
        return held

    def _supports(self, held: np.ndarray) -> None:
        """Free DOFs (``free``): supports, held rotation components, joints no member
        touches (fixed unless loaded, which is an error)."""
        s = self.structure
        dim, n = self.dim, s.n_nodes
        er, joint_slot = self.end_rotations, self.joint_slot
        free = np.ones(self.ndof, dtype=bool)
        free[: n * dim] = ~s.supports[:, :dim].ravel()
        if dim == 2:
            rz = er.joint_rotation_held[:, 0]
            free[self.n_points * dim + joint_slot[rz]] = False
        # joints that no member touches carry nothing: fixed, unless loaded
        touched = np.zeros(n, dtype=bool)
        touched[s.connectivity.ravel()] = True
        loose = np.flatnonzero(~touched)
        if loose.size:
            if np.any(s.loads[loose, :dim] != 0):
                i = int(loose[np.flatnonzero(np.any(s.loads[loose, :dim] != 0, axis=1))[0]])
                raise InputError(f"loads.{s.node_ids[i]}", "node is connected to no member")
            free[(loose[:, None] * dim + np.arange(dim)).ravel()] = False
        self.free = free
        if dim == 3:
            # a partly fixed joint rotation holds components of its rotation vector: additive
            rs = er.joint_rotation_held
            part = rs.any(axis=1) & ~rs.all(axis=1)
            self.slot_additive[joint_slot[part]] = True
            jn, comp = np.nonzero(rs)
            free[self.n_points * dim + 3 * joint_slot[jn] + comp] = False
            free[held] = False

    def _springs(self) -> None:
        """Elastic supports ``[springs]`` as a stiffness per DOF (``spring``, shape (dof,)).

        A spring is part of the structure in every analysis (docs/fem.md), so the path
        carries its force ``−k u`` too.  On a translation (global axis) that is exact at any
        displacement.  On a joint rotation it is a spring on the rotation: in 2-D on the
        angle; in 3-D on the components of the joint's total rotation vector ψ, energy
        ``½ Σ k_i ψ_i²``, which is the linear spring for small rotations (and exact for a
        rotation about one axis).  Such a 3-D joint slot is made additive (its DOFs are the
        increments of ψ, as for a partly supported joint), so the spring force is ``k ψ`` and
        its tangent ``diag(k)``.

        Raises
        ------
        InputError
            A spring on a rotation the joint does not have (no beam rigidly attached), as in
            the linear analyses.
        """
        s = self.structure
        dim, n = self.dim, s.n_nodes
        k = np.zeros(self.ndof)
        self.spring = k
        data = s.extensions.get("springs")
        if data is None:
            return
        values = np.asarray(data.stiffness, dtype=float)
        k[: n * dim] = values[:, :dim].ravel()
        rot = values[:, dim:]
        has = np.flatnonzero(np.any(rot != 0.0, axis=1))
        if not has.size:
            return
        lost = has[~self.end_rotations.joint_rotation[has]]
        if lost.size:
            raise InputError(f"springs.{s.node_ids[int(lost[0])]}",
                             "acts on a rotation, which this node does not have (a pin "
                             "joint: no beam is rigidly attached); remove it")
        slot = self.joint_slot[has]
        cols = self.n_points * dim + self.rdof * slot[:, None] + np.arange(self.rdof)
        k[cols] = rot[has]
        if dim == 3:
            self.slot_additive[slot] = True         # DOFs = increments of ψ (Q = I)

    def _loads(self) -> None:
        """Reference load pattern ``load`` (``[loads]``): forces on the joints' translations,
        moments on their rotation slots."""
        s = self.structure
        dim, n = self.dim, s.n_nodes
        joint_has_rot, joint_slot = self.end_rotations.joint_rotation, self.joint_slot
        f = np.zeros(self.ndof)
        f[: n * dim] = s.loads[:, :dim].ravel()
        moments = s.loads[:, dim:]
        if dim == 3 and np.any(moments != 0):
            # a moment of fixed direction: virtual work M·δw on the joint's spin
            bad = np.flatnonzero(np.any(moments != 0, axis=1) & ~joint_has_rot)
            if bad.size:
                raise InputError(f"loads.{s.node_ids[int(bad[0])]}",
                                 "a moment on a node that no rigid beam end connects to")
            has = np.flatnonzero(np.any(moments != 0, axis=1))
            f[self.n_points * dim + 3 * joint_slot[has][:, None] + np.arange(3)] = moments[has]
        elif np.any(moments != 0):
            bad = np.flatnonzero((moments[:, 0] != 0) & ~joint_has_rot)
            if bad.size:
                raise InputError(f"loads.{s.node_ids[int(bad[0])]}",
                                 "a moment on a node that no rigid beam end connects to")
            has = np.flatnonzero(moments[:, 0] != 0)
            f[self.n_points * dim + joint_slot[has]] = moments[has, 0]
        self.load = f

    # ------------------------------------------------------------------ helpers
    def _dead_load(self) -> np.ndarray:
        """Constant dead load of gravity (``[model] gravity``), shape (dof,): the weight of
        every element lumped half at each of its ends (truss elements: the member's ends;
        beam elements: their end points along the member), an active member's base and
        leadscrew tube at its joints as the static analysis of a bar has them
        (:func:`~trussfe.mechanics.active_bodies.active_weight_joint_loads`) or, on beam
        elements, shared between the ends of the elements that hold them by the lever rule
        (:func:`_active_shares`), and the weight of the nodal masses.  Zero without
        gravity."""
        s = self.structure
        d = self.dim
        out = np.zeros(self.ndof)
        g = np.asarray(s.gravity, dtype=float)
        if not np.any(g):
            return out
        conn = [self.t_conn]
        members = [self.t_member]
        if len(self.b_conn):
            conn.append(self.b_conn)
            members.append(self.b_member)
        conn, members = np.concatenate(conn), np.concatenate(members)
        # active members of beam elements: their bodies instead of ρA (below)
        acts = list(s.extensions.get("active_members", ()))
        on_beams = np.zeros(s.n_members, dtype=bool)
        on_beams[[a.member for a in acts]] = True
        on_beams[self.t_member] = False
        # every element of a uniform member: half its weight at each end
        L0 = (np.concatenate([self.t_len0, member_lengths(self.X, self.b_conn)])
              if len(self.b_conn) else self.t_len0)
        half = np.where(on_beams[members], 0.0,
                        0.5 * mass_per_length(s.density, s.area)[members] * L0)
        mass = np.bincount(conn.ravel(), np.repeat(half, 2), minlength=self.n_points)
        if np.any(on_beams):
            el = np.flatnonzero(on_beams[members])
            at_start, at_end = _active_shares(s, self.X, conn[el], members[el])
            mass += np.bincount(conn[el, 0], at_start, minlength=self.n_points)
            mass += np.bincount(conn[el, 1], at_end, minlength=self.n_points)
        mass[: s.n_nodes] += s.masses
        out[: self.n_points * d] = (mass[:, None] * g[None, :]).ravel()
        if acts:
            # an active truss element keeps its weight at its joints, the base's axial share
            # at the start joint and the tube's at the end joint (as static's bars)
            bars = np.zeros(s.n_members, dtype=bool)
            bars[self.t_member] = True
            out[: s.n_nodes * d] += active_weight_joint_loads(s, members=bars).ravel()
        return out

    def positions(self, u: np.ndarray) -> np.ndarray:
        """Current point positions, shape (point, dim)."""
        return self.X + u[: self.n_points * self.dim].reshape(-1, self.dim)

    @property
    def additive(self) -> bool:
        """True when states add (no 3-D rotation): ``add(u, du) == u + du``."""
        return self.dim == 2 or self.n_rot == 0

    def add(self, u: np.ndarray, du: np.ndarray) -> np.ndarray:
        """Advance the state ``u`` by the increment ``du`` (all DOFs).

        Translations (and 2-D rotations) add.  A 3-D rotation slot's increment is a spin
        ``δw = Q δφ`` (``Q`` the slot's basis), composed multiplicatively with the total
        rotation: ``exp(S(ψ')) = exp(S(δw)) exp(S(ψ))`` (Crisfield vol. 2 §16.4).
        """
        out = u + du
        if self.additive:
            return out
        t = self.n_points * self.dim
        psi = u[t:].reshape(-1, 3)
        mul = ~self.slot_additive
        spin = np.einsum("sij,sj->si", self.slot_basis[mul], du[t:].reshape(-1, 3)[mul])
        new = out[t:].reshape(-1, 3)                # additive slots: φ + δφ
        new[mul] = compose(psi[mul], spin)
        return out

    def rotation_vectors(self, u: np.ndarray) -> np.ndarray:
        """Total rotation vectors ψ of the 3-D rotation slots (global), shape (slot, 3)."""
        r = u[self.n_points * 3:].reshape(-1, 3)
        add = self.slot_additive
        psi = r.copy()
        psi[add] = np.einsum("sij,sj->si", self.slot_basis[add], r[add])
        return psi

    def joint_displacements(self, u: np.ndarray) -> np.ndarray:
        """Displacements of the structure's nodes, shape (node, dim)."""
        n = self.structure.n_nodes
        return u[: n * self.dim].reshape(n, self.dim)

    def dof(self, node: int, axis: int) -> int:
        """Global DOF number of translation ``axis`` of node ``node``."""
        return int(node) * self.dim + int(axis)

    # ------------------------------------------------------------------ evaluation
    def evaluate(self, u: np.ndarray, tangent: bool = True, plastic: np.ndarray | None = None):
        """Internal forces (and tangent) at the displacement ``u``.

        Parameters
        ----------
        u : ndarray, shape (dof,)
        tangent : bool
            Assemble the tangent stiffness too.
        plastic : ndarray, optional
            Plastic strains to use (default: the committed ones).

        Returns
        -------
        dict
            ``internal`` (dof,), ``tangent`` (sparse dof × dof or None), and per truss element
            ``t_force``, ``t_strain``, ``t_trial``, ``t_buckling_force``; per beam element
            ``b_force``, ``b_moment``.
        """
        x = self.positions(u)
        plastic = self.plastic if plastic is None else plastic
        out = {}
        fs, ks, ds = [], [], []
        # truss elements
        l, e, strain = truss_kinematics(x, self.t_conn, self.t_len0)
        N, dNde, trial, Nb = axial_law(self.t_laws, self.t_EA, strain, plastic)
        live_t = self.alive[self.t_member]
        N = np.where(live_t, N, 0.0)
        out.update(t_force=N, t_strain=strain, t_trial=trial, t_buckling_force=Nb,
                   t_length=l)
        idx = np.flatnonzero(live_t)
        if idx.size:
            f, k = truss_matrices(e[idx], l[idx], self.t_len0[idx], N[idx], dNde[idx],
                                  tangent)
            fs.append(f)
            ks.append(k)
            ds.append(self.t_dofs[idx])
        # beam elements
        if len(self.b_conn) and self.dim == 3:
            live_b = self.alive[self.b_member]
            fb, kb, Nbm, Mb = self._beam3d(x, self.rotation_vectors(u), tangent=tangent)
            out.update(b_force=np.where(live_b, Nbm, 0.0), b_moment=Mb * live_b[:, None, None])
            fs.append(fb[live_b])
            ks.append(kb[live_b] if tangent else None)
            ds.append(self.b_dofs[live_b])
        elif len(self.b_conn):
            rot = u[self.n_points * self.dim:][self.b_slot]
            lb, c, s_, L0, ul, th = beam2d_local(x, self.b_conn, rot, self.X)
            live_b = self.alive[self.b_member]
            fb, kb, Nbm, Mb = beam2d_matrices(lb, c, s_, L0, ul, th, self.b_EA, self.b_EI)
            out.update(b_force=np.where(live_b, Nbm, 0.0), b_moment=Mb * live_b[:, None])
            fs.append(fb[live_b])
            ks.append(kb[live_b])
            ds.append(self.b_dofs[live_b])
        F, K = _assemble_mixed(self.ndof, ds, fs, ks, tangent)
        F, K = self._add_springs(u, F, K)
        out["internal"] = F
        out["tangent"] = K
        return out

    def _add_springs(self, u: np.ndarray, F: np.ndarray, K):
        """Internal force and tangent with the springs' ``k u`` and ``diag(k)`` added (a
        3-D joint slot with a rotational spring stores ψ additively, see :meth:`_springs`)."""
        if not np.any(self.spring):
            return F, K
        import scipy.sparse as sp
        F = F + self.spring * u
        if K is not None:
            K = (K + sp.diags(self.spring, format="csr")).tocsr()
        return F, K

    def _beam3d(self, x, psi, tangent=True, N_override=None):
        """Element forces and tangents of the 3-D beams in the slot DOFs (DOF order of
        ``b_dofs``: translations and own slot of each end, then each end's parent slot)."""
        R = expm_so3(psi)                                            # (slot, 3, 3)
        rel = np.flatnonzero(self.slot_parent >= 0)
        if rel.size == 0:
            return self._beam3d_absolute(x, psi, R, tangent, N_override)
        par = self.slot_parent[rel]
        if rel.size:
            # a relative slot stores the rotation of the member end relative to its joint,
            # in the member's reference axes: R_end = R_joint exp(S(Q φ))
            R[rel] = R[par] @ R[rel]
        conn = self.b_conn
        R0 = reference_frames(self.X, conn, self.b_orientation)
        L0 = member_lengths(self.X, conn)
        f, k, N, M = beam3d_matrices(x, conn, R[self.b_slot[:, 0]], R[self.b_slot[:, 1]], R0,
                                     L0, self.b_EA, self.b_GJ, self.b_EI, self.b_EIz,
                                     N_override=N_override, tangent=tangent)
        # DOFs of the slots: spins δw = C δφ with C = Q (multiplicative slots), Tₛ(ψ) Q
        # (additive slots) or, for a relative slot, δw = C_joint δφ_joint + R_joint Tₛ(v) Q δφ
        # (v = Qφ); f_φ = Cᵀ f_w, k_φ = Cᵀ k C, plus the derivative of Cᵀ at fixed f_w on the
        # additive slots' diagonal blocks
        C_all = np.broadcast_to(np.eye(3), (self.n_rot, 3, 3)).copy() \
            if self.n_rot else np.zeros((0, 3, 3))
        C_all[:] = self.slot_basis
        add = self.slot_additive
        if add.any():
            C_all[add] = tangent_operator(psi[add]) @ self.slot_basis[add]
        C_par = C_all[par].copy() if rel.size else None
        if rel.size:
            C_all[rel] = R[par] @ C_all[rel]
        ne = len(conn)
        B = np.zeros((ne, 12, 18))
        B[:, 0:3, 0:3] = np.eye(3)
        B[:, 6:9, 6:9] = np.eye(3)
        extra = np.zeros((ne, 18, 18)) if k is not None else None
        for sl, end, pc in ((slice(3, 6), 0, slice(12, 15)), (slice(9, 12), 1, slice(15, 18))):
            slot = self.b_slot[:, end]
            B[:, sl, sl] = C_all[slot]
            p = self.slot_parent[slot]
            e_rel = np.flatnonzero(p >= 0)
            if e_rel.size:
                B[e_rel, sl, pc] = C_par[np.searchsorted(rel, slot[e_rel])]
            e_add = np.flatnonzero(add[slot])
            if k is not None and e_add.size:
                sa = slot[e_add]
                m = f[e_add, sl]
                rr = np.flatnonzero(self.slot_parent[sa] >= 0)
                if rr.size:                      # relative: the moment in the joint's frame
                    m = m.copy()
                    m[rr] = np.einsum("eji,ej->ei", R[self.slot_parent[sa[rr]]], m[rr])
                Q = self.slot_basis[sa]
                dT = tangent_operator_derivative(psi[sa], m)
                r = np.arange(sl.start, sl.stop)
                extra[e_add[:, None, None], r[None, :, None], r[None, None, :]] += \
                    np.transpose(Q, (0, 2, 1)) @ dT @ Q
        f = np.einsum("eji,ej->ei", B, f)
        if k is not None:
            k = np.transpose(B, (0, 2, 1)) @ k @ B + extra
        return f, k, N, M

    def _beam3d_absolute(self, x, psi, R, tangent, N_override):
        """:meth:`_beam3d` of a model without relative slots (12 DOFs per element)."""
        conn = self.b_conn
        R0 = reference_frames(self.X, conn, self.b_orientation)
        L0 = member_lengths(self.X, conn)
        f, k, N, M = beam3d_matrices(x, conn, R[self.b_slot[:, 0]], R[self.b_slot[:, 1]], R0,
                                     L0, self.b_EA, self.b_GJ, self.b_EI, self.b_EIz,
                                     N_override=N_override, tangent=tangent)
        for sl, end in ((slice(3, 6), 0), (slice(9, 12), 1)):
            slot = self.b_slot[:, end]
            C = self.slot_basis[slot].copy()                         # (el, 3, 3)
            add = self.slot_additive[slot]
            if add.any():
                C[add] = tangent_operator(psi[slot[add]]) @ C[add]
                if k is not None:
                    Q = self.slot_basis[slot[add]]
                    dT = tangent_operator_derivative(psi[slot[add]], f[add, sl])
                    extra = np.transpose(Q, (0, 2, 1)) @ dT @ Q
            f[:, sl] = np.einsum("eji,ej->ei", C, f[:, sl])
            if k is not None:
                k[:, sl, :] = np.einsum("eji,ejk->eik", C, k[:, sl, :])
                k[:, :, sl] = k[:, :, sl] @ C
                if add.any():
                    r = np.arange(sl.start, sl.stop)
                    k[np.flatnonzero(add)[:, None, None], r[None, :, None],
                      r[None, None, :]] += extra
        return f, k, N, M

    @property
    def t_len0(self) -> np.ndarray:
        """Reference lengths of the truss elements, shape (truss element,)."""
        if not hasattr(self, "_t_len0"):
            self._t_len0 = member_lengths(self.X, self.t_conn)
        return self._t_len0

    def margins(self, res: dict) -> np.ndarray:
        """Failure margins of the truss elements of live members, shape (3, truss element)."""
        mg = failure_margins(self.t_laws, res["t_trial"], res["t_buckling_force"],
                             res["t_strain"])
        mg[:, ~self.alive[self.t_member]] = -np.inf
        mg[self.silenced] = -np.inf
        return mg

    def commit(self, res: dict) -> None:
        """Commit the plastic strain of a converged state (yield ``cap`` law)."""
        y = (self.t_laws.yield_mode == 1) & self.alive[self.t_member]
        over = y & (np.abs(res["t_buckling_force"]) > self.t_laws.yield_force)
        if over.any():
            N = res["t_force"][over]
            self.plastic[over] = res["t_strain"][over] - N / self.t_EA[over]

    def member_axial_forces(self, res: dict) -> np.ndarray:
        """Axial force of every member (mean over its elements; 0 for failed members)."""
        m = self.structure.n_members
        out = np.zeros(m)
        out[self.t_member] = res["t_force"]
        if len(self.b_conn):
            cnt = np.bincount(self.b_member, minlength=m)
            sm = np.bincount(self.b_member, weights=res["b_force"], minlength=m)
            has = cnt > 0
            out[has] = sm[has] / cnt[has]
        return np.where(self.alive, out, 0.0)

    def reference_tangent(self, axial_force_t: np.ndarray | None = None,
                          axial_force_b: np.ndarray | None = None):
        """Tangent at the reference geometry with prescribed element axial forces.

        With zero forces this is the linear stiffness ``K``; the difference made by the
        forces is the geometric stiffness ``Kg(N)`` (linear in N).
        """
        x = self.X
        ds, fs, ks = [], [], []
        l, e, _ = truss_kinematics(x, self.t_conn, self.t_len0)
        Nt = np.zeros(len(l)) if axial_force_t is None else axial_force_t
        live_t = self.alive[self.t_member]
        f, k = truss_matrices(e[live_t], l[live_t], self.t_len0[live_t], Nt[live_t],
                              self.t_EA[live_t])
        ds.append(self.t_dofs[live_t]); fs.append(f); ks.append(k)
        if len(self.b_conn) and self.dim == 3:
            Nb = np.zeros(len(self.b_conn)) if axial_force_b is None else axial_force_b
            live_b = self.alive[self.b_member]
            fb, kb, _, _ = self._beam3d(x, np.zeros((self.n_rot, 3)), N_override=Nb)
            ds.append(self.b_dofs[live_b]); fs.append(fb[live_b]); ks.append(kb[live_b])
        elif len(self.b_conn):
            lb, c, s_, L0, ul, th = beam2d_local(x, self.b_conn, np.zeros_like(
                self.b_slot, dtype=float), self.X)
            Nb = np.zeros(len(lb)) if axial_force_b is None else axial_force_b
            live_b = self.alive[self.b_member]
            fb, kb, _, _ = beam2d_matrices(lb, c, s_, L0, ul, th, self.b_EA, self.b_EI,
                                           N_override=Nb)
            ds.append(self.b_dofs[live_b]); fs.append(fb[live_b]); ks.append(kb[live_b])
        F, K = _assemble_mixed(self.ndof, ds, fs, ks, True)
        # the springs belong to K (they cancel in Kg = tangent(N) − tangent(0))
        return self._add_springs(np.zeros(self.ndof), F, K)[1]

    def linear_axial_forces(self, u: np.ndarray):
        """Element axial forces of the linearised kinematics, ``EA/L0 · eᵀ(u_b − u_a)``."""
        d = self.dim
        U = u[: self.n_points * d].reshape(-1, d)
        e = member_vectors(self.X, self.t_conn) / self.t_len0[:, None]
        Nt = self.t_EA / self.t_len0 * np.einsum("ij,ij->i", e,
                                                 member_vectors(U, self.t_conn))
        Nb = None
        if len(self.b_conn):
            D = member_vectors(self.X, self.b_conn)
            L0 = np.linalg.norm(D, axis=1)
            Nb = self.b_EA / L0 * np.einsum("ij,ij->i", D / L0[:, None],
                                            member_vectors(U, self.b_conn))
        return Nt, Nb


def _assemble_mixed(ndof, ds, fs, ks, tangent):
    """One COO assembly of element groups with different DOF counts (truss and beam)."""
    import scipy.sparse as sp
    F = np.zeros(ndof)
    rows, cols, vals = [], [], []
    for d, f, k in zip(ds, fs, ks):
        if len(d) == 0:
            continue
        F += np.bincount(d.ravel(), weights=f.ravel(), minlength=ndof)
        if tangent:
            nd = d.shape[1]
            rows.append(np.repeat(d, nd, axis=1).ravel())
            cols.append(np.tile(d, (1, nd)).ravel())
            vals.append(k.ravel())
    if not tangent:
        return F, None
    if not rows:
        return F, sp.csr_matrix((ndof, ndof))
    K = sp.coo_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                      shape=(ndof, ndof)).tocsr()
    return F, K


def _active_shares(structure: Structure, X: np.ndarray, conn: np.ndarray,
                   members: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The masses of the active members' bodies at the start and end point of elements of
    active members.

    An active member is its base (``base_mass`` at ``base_cg`` from the start node) and its
    leadscrew tube (ρA over the last ``tube_length``; :mod:`trussfe.mechanics.active_bodies`).
    Each element ``[s₀, s₁]`` along its member takes the tube's part on it and the base if
    ``s₀ <= base_cg < s₁`` (the last element also at ``base_cg = L``), each split between its
    ends by the lever rule: a mass m at s gives ``m (s₁ − s)/h`` and ``m (s − s₀)/h``, which
    keeps the weight and its moment about any point.

    Parameters
    ----------
    structure : Structure
    X : ndarray, shape (point, dim)
        Point positions.
    conn : ndarray of int, shape (k, 2)
        End points of the elements.
    members : ndarray of int, shape (k,)
        Their (active) members.

    Returns
    -------
    at_start, at_end : ndarray, shape (k,)
        kg.
    """
    s = structure
    bodies = member_bodies(s)
    L = s.lengths()[members]
    e = s.unit_vectors()[members]
    start = s.coords[s.connectivity[members, 0]]
    # where each element starts and ends along its member
    s0 = np.einsum("ij,ij->i", X[conn[:, 0]] - start, e)
    s1 = np.einsum("ij,ij->i", X[conn[:, 1]] - start, e)
    lo = np.maximum(s0, L - bodies.tube_length[members])
    hi = np.minimum(s1, L)
    m_tube = mass_per_length(s.density, s.area)[members] * np.maximum(hi - lo, 0.0)
    x_tube = 0.5 * (lo + hi)
    # a centre of gravity off the member's ends still weighs: at the nearer end
    cg = np.clip(bodies.base_cg[members], 0.0, L)
    last = np.isclose(s1, L, rtol=1e-12, atol=0.0)
    holds = (s0 <= cg) & ((cg < s1) | (last & (cg <= s1)))
    m_base = np.where(holds, bodies.base_mass[members], 0.0)
    at_end = (m_tube * (x_tube - s0) + m_base * (cg - s0)) / (s1 - s0)
    return m_tube + m_base - at_end, at_end
