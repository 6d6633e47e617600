# SPDX-License-Identifier: MIT
"""Gravity and d'Alembert inertial loads of a rigid-body motion, as finite-element loads.

Along a prescribed maneuver the rigid-body model (:mod:`trussfe.rigid`) knows every member's
motion: the start-node acceleration a_a, the unit vector e and its rates ė, ë, the angular
acceleration α = e × ë and the length L with its rates L̇, L̈.  Each member is loaded, in its
current configuration, with what its mass elements need to follow that motion (Lacy eqs.
2.9–2.11, 4.20, written as loads on the member; x is the distance from the start node):

* **tube** (the whole member if passive, the leadscrew tube of an active member on
  x ∈ [L − L_t, L]): a tube point at fixed distance u from the end node sits at x = L − u, so
  its acceleration ``a(x) = a_a + L̈ e + 2 L̇ ė + x ë`` is linear in x, and the distributed
  force per unit length is

  .. math:: q(x) = -\\mu\\,(a(x) - g) = q_0 + q_1 x, \\quad
            q_0 = -\\mu (a_a + \\ddot L e + 2 \\dot L \\dot e - g), \\quad q_1 = -\\mu \\ddot e,

  with μ = m_t / L_t (Lacy's ρA).  Its sections also rotate: the distributed couple
  ``c = −μ r² α`` with r² = I/A is the rotary inertia that makes Lacy's tube inertia
  ``m (I/A + L²/12)`` (Appendix A/C ``izz``; :meth:`MemberBodies.tube_inertia`) — the L²/12
  part comes from q itself.
* **active base** (Lacy section 4.7, eqs. 4.58–4.61): a rigid body of mass m_b with its centre
  of gravity at x = cg_b (acceleration a_a + cg_b ë) and inertia I_b about it, i.e. the point
  force ``F_b = −m_b (a_a + cg_b ë − g)`` and the couple ``C_b = −I_b α``.
* **lumped nodal masses and external loads**: ``P + M (g − a)`` at the nodes.

These are exactly the mass elements of :func:`trussfe.mechanics.active_bodies.member_bodies`, so the
loads' resultant on a member equals the rigid model's ``R`` and ``M_a`` (eq. 4.20).

**The active base on a line model** is applied on the base side of the cantilever connection,
at ``x_p = min(cg_b, x_c)`` with a transfer couple (:mod:`trussfe.mechanics.active_bodies`,
:func:`~trussfe.mechanics.active_bodies.base_load_point`): statically equivalent for the
member and identical for every section of the tube, which is where the rigid model reports
forces.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.structure import Structure
from ..mechanics.active_bodies import MemberBodies, base_load_point, member_bodies
from ..mechanics.member_loads import deflection_shapes, rotation_shapes
from ..rigid.kinematics import Kinematics, pad3

#: Three-point Gauss–Legendre rule on [−1, 1]: exact to degree 5 (load linear × cubic shape).
_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(3)


@dataclass
class MotionLoads:
    """Loads on every member and node, every step; vectors in global axes, 3 components.

    Attributes
    ----------
    length : ndarray, shape (nt, m)
        Member length L, m.
    unit : ndarray, shape (nt, m, 3)
        Member unit vector e (start → end node).
    tube_start : ndarray, shape (nt, m)
        x_c = L − L_t: the tube load acts on x ∈ [x_c, L] (0 for passive members).
    q0, q1 : ndarray, shape (nt, m, 3)
        Distributed force ``q(x) = q0 + q1 x`` on the tube, N/m and N/m².
    couple : ndarray, shape (nt, m, 3)
        Distributed couple on the tube, N·m/m.
    point_x : ndarray, shape (nt, m)
        Where the active base's resultant acts, m from the start node.
    point_force, point_couple : ndarray, shape (nt, m, 3)
        The base's force and couple there (zero for passive members).
    nodal : ndarray, shape (nt, n, 3)
        Nodal force P + M (g − a), N.
    """

    length: np.ndarray
    unit: np.ndarray
    tube_start: np.ndarray
    q0: np.ndarray
    q1: np.ndarray
    couple: np.ndarray
    point_x: np.ndarray
    point_force: np.ndarray
    point_couple: np.ndarray
    nodal: np.ndarray

    @property
    def n_steps(self) -> int:
        """Number of time steps."""
        return self.length.shape[0]

    def select(self, steps: slice | np.ndarray) -> "MotionLoads":
        """The loads of some time steps."""
        return MotionLoads(**{k: getattr(self, k)[steps] for k in self.__dataclass_fields__})

    def piece_resultant(self, a: np.ndarray, b: np.ndarray, about: np.ndarray
                        ) -> tuple[np.ndarray, np.ndarray]:
        """Resultant of the member loads on the piece a < x ≤ b (exact).

        Parameters
        ----------
        a, b : ndarray, shape (nt, m, k)
            Ends of the piece, m from the start node (a ≤ b).
        about : ndarray, shape (nt, m, k)
            Station about which the moment is taken.

        Returns
        -------
        force, moment : ndarray, shape (nt, m, k, 3)
            Total force and moment (about the point at ``about`` on the member axis).

        Notes
        -----
        With q linear, ∫q dx = q0 Δ₁ + q1 Δ₂/2 and ∫(x − p) e × q dx follow from the
        moments Δ_n = bⁿ − aⁿ of the clipped interval [max(a, x_c), b].
        """
        lo = np.maximum(a, self.tube_start[..., None])
        hi = np.maximum(b, lo)
        d1 = (hi - lo)[..., None]
        d2 = (hi ** 2 - lo ** 2)[..., None]
        d3 = (hi ** 3 - lo ** 3)[..., None]
        p = about[..., None]
        q0, q1 = self.q0[:, :, None], self.q1[:, :, None]
        e = self.unit[:, :, None]
        force = q0 * d1 + q1 * d2 / 2.0
        # ∫ (x − p) q dx  (a vector along the member's load), then e × it
        lever_q = q0 * (d2 / 2.0 - p * d1) + q1 * (d3 / 3.0 - p * d2 / 2.0)
        moment = np.cross(e, lever_q) + self.couple[:, :, None] * d1
        xp = self.point_x[..., None]
        inside = ((xp > a) & (xp <= b))[..., None]
        fp = self.point_force[:, :, None]
        force = force + np.where(inside, fp, 0.0)
        moment = moment + np.where(inside, np.cross((xp[..., None] - p) * e, fp)
                                   + self.point_couple[:, :, None], 0.0)
        return force, moment


def motion_loads(structure: Structure, kin: Kinematics, bodies: MemberBodies | None = None,
                 *, gravity: bool = True, loads: bool = True) -> MotionLoads:
    """Gravity and d'Alembert loads of the members and nodes along a motion (module notes).

    Parameters
    ----------
    structure : Structure
    kin : Kinematics
        Kinematics of the motion (``kin.at_rest()`` gives the static loads).
    bodies : MemberBodies, optional
        Mass elements (default :func:`trussfe.mechanics.active_bodies.member_bodies`, the
        rigid model's).
    gravity : bool
        Include gravity (``structure.gravity``).
    loads : bool
        Include the external nodal loads.

    Returns
    -------
    MotionLoads

    Examples
    --------
    A 2 m tube at rest under gravity carries its weight ρAL·g as a uniform load:

    >>> from trussfe.models import triangular_truss
    >>> from trussfe.rigid.kinematics import compute_kinematics
    >>> from trussfe.rigid.motion import rest_motion
    >>> s = triangular_truss(member_weight=True, active_members=True)
    >>> ld = motion_loads(s, compute_kinematics(s, rest_motion(s)).at_rest())
    >>> w = s.density[0] * s.area[0] * 9.81
    >>> bool(np.allclose(ld.q0[0, 0], [0.0, -w, 0.0]))
    True
    """
    bodies = member_bodies(structure) if bodies is None else bodies
    conn = structure.connectivity
    g = pad3(np.asarray(structure.gravity, dtype=float)) if gravity else np.zeros(3)
    e, ed, edd = kin.unit, kin.unit_rate, kin.unit_acc
    L = kin.length
    mu = (bodies.tube_mass / bodies.tube_length)[None, :, None]           # (1, m, 1)
    aa = kin.acceleration[:, conn[:, 0]]                                    # (t, m, 3)
    q0 = -mu * (aa + kin.length_acc[..., None] * e + 2.0 * kin.length_rate[..., None] * ed - g)
    q1 = -mu * edd
    couple = -(mu * bodies.tube_radius2[None, :, None]) * kin.alpha
    xc = L - bodies.tube_length[None, :]
    cg = np.broadcast_to(bodies.base_cg[None, :], L.shape)
    xp = base_load_point(bodies, L)
    mb = bodies.base_mass[None, :, None]
    fb = -mb * (aa + bodies.base_cg[None, :, None] * edd - g)
    cb = (-bodies.base_inertia_cg[None, :, None] * kin.alpha
          + np.cross((cg - xp)[..., None] * e, fb))
    n = structure.n_nodes
    nodal = structure.masses[None, :, None] * (g - kin.acceleration)
    if loads:
        nodal = nodal + pad3(structure.loads[:, :structure.dim])[None]
    nodal = np.broadcast_to(nodal, (kin.n_steps, n, 3)).copy()
    return MotionLoads(length=L.copy(), unit=e.copy(), tube_start=np.where(
        bodies.active[None, :], xc, 0.0), q0=q0, q1=q1, couple=couple, point_x=xp,
        point_force=fb, point_couple=cb, nodal=nodal)


def _end_components(f: np.ndarray, m: np.ndarray, s: np.ndarray, h: np.ndarray,
                    w: np.ndarray, phi: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    """Work-equivalent end components of forces f and couples m (member axes) at stations s.

    ``f``, ``m`` (..., p, 3) at p points of relative position ``s`` (..., p) with weights
    ``w`` (..., p); ``phi``: the shear parameters Φ of the v and w fields, each broadcastable
    to ``h`` (0: Euler–Bernoulli).  Returns (..., 2, 6): ``[Fx, Fy, Fz, Mx, My, Mz]`` at each
    element end, ``∫ f N_i + m ψ_i`` with the element's own shape functions
    (:func:`~trussfe.mechanics.member_loads.deflection_shapes`,
    :func:`~trussfe.mechanics.member_loads.rotation_shapes`).  Transverse fields: v with its
    section rotation θz, w with −θy (:mod:`trussfe.fem.discretisation`).
    """
    fw, mw = f * w[..., None], m * w[..., None]
    out = np.zeros(s.shape[:-1] + (2, 6))
    out[..., :, 0] = np.einsum("...p,...pa->...a", fw[..., 0], np.stack([1 - s, s], axis=-1))
    # v: DOFs (v0, θz0, v1, θz1); w: (w0, −θy0, w1, −θy1)
    for (force, couple, sign, cols), p in zip(((1, 2, 1.0, (1, 5)), (2, 1, -1.0, (2, 4))), phi):
        hp, pp = h[..., None], np.asarray(p, dtype=float)[..., None]
        dofs = (np.einsum("...p,...pa->...a", fw[..., force], deflection_shapes(s, hp, pp))
                + sign * np.einsum("...p,...pa->...a", mw[..., couple],
                                   rotation_shapes(s, hp, pp)))
        out[..., :, cols[0]] = dofs[..., [0, 2]]
        out[..., :, cols[1]] = sign * dofs[..., [1, 3]]
    return out


def element_load_components(ml: MotionLoads, element_x: np.ndarray, rotation: np.ndarray,
                            phi: tuple[np.ndarray, np.ndarray] = (0.0, 0.0)) -> np.ndarray:
    """Consistent (work-equivalent) element end loads of the member loads, member axes.

    Parameters
    ----------
    ml : MotionLoads
        Loads of nt steps on m members.
    element_x : ndarray, shape (m, k, 2)
        Stations of the ends of each member's k elements (equal subdivisions of every
        member, as :func:`trussfe.fem.discretise` makes them), per step: shape
        (nt, m, k, 2).
    rotation : ndarray, shape (nt, m, 3, 3)
        Member axes as rows (3-D; a planar member's z axis is the global z).
    phi : tuple of ndarray
        The elements' shear parameters Φ of the v and w fields
        (:meth:`~trussfe.fem.discretisation.FEModel.shear_parameter`), each broadcastable to
        (nt, m, k); 0 (default): Euler–Bernoulli elements.

    Returns
    -------
    ndarray, shape (nt, m, k, 2, 6)
        ``[Fx, Fy, Fz, Mx, My, Mz]`` at each element end: the consistent load of the element's
        transverse (cubic) and axial (linear) fields, integrated exactly — the distributed
        load with a three-point Gauss rule on the part of the element the tube covers, the
        base's force and couple at its point.
    """
    x0, x1 = element_x[..., 0], element_x[..., 1]              # (t, m, k)
    h = x1 - x0
    lo = np.clip(ml.tube_start[..., None], x0, x1)
    half = 0.5 * (x1 - lo)
    xg = lo[..., None] + half[..., None] * (_GAUSS_X + 1.0)     # (t, m, k, 3)
    wg = half[..., None] * _GAUSS_W
    R = rotation[:, :, None]                                   # (t, m, 1, 3, 3)
    q = (ml.q0[:, :, None, None] + ml.q1[:, :, None, None] * xg[..., None])   # (t,m,k,3,3)
    q_loc = np.einsum("tmkij,tmkpj->tmkpi", np.broadcast_to(R, q.shape[:3] + (3, 3)), q)
    c_loc = np.einsum("tmij,tmj->tmi", rotation, ml.couple)[:, :, None, None]
    c_loc = np.broadcast_to(c_loc, q_loc.shape)
    s = (xg - x0[..., None]) / h[..., None]
    phi = tuple(np.broadcast_to(p, h.shape) for p in phi)
    out = _end_components(q_loc, c_loc, s, h, wg, phi)
    # base point load: in the element holding x_p (the last one if x_p = L)
    k = element_x.shape[2]
    xp = ml.point_x
    j = np.clip(np.sum(x0 <= xp[..., None], axis=-1) - 1, 0, k - 1)     # (t, m)
    jj = j[..., None]
    hx0 = np.take_along_axis(x0, jj, axis=-1)[..., 0]
    hh = np.take_along_axis(h, jj, axis=-1)[..., 0]
    fp = np.einsum("tmij,tmj->tmi", rotation, ml.point_force)[:, :, None]
    cp = np.einsum("tmij,tmj->tmi", rotation, ml.point_couple)[:, :, None]
    sp_ = ((xp - hx0) / hh)[..., None]
    pt = _end_components(fp, cp, sp_, hh, np.ones_like(sp_),
                         tuple(np.take_along_axis(p, jj, axis=-1)[..., 0] for p in phi))
    t_idx, m_idx = np.indices(j.shape)
    out[t_idx, m_idx, j] += pt
    return out


def rotations3(rotation: np.ndarray) -> np.ndarray:
    """Member axes as 3 × 3 rotations (planar members: z axis = global z)."""
    d = rotation.shape[-1]
    if d == 3:
        return rotation
    R = np.zeros(rotation.shape[:-2] + (3, 3))
    R[..., :2, :2] = rotation
    R[..., 2, 2] = 1.0
    return R


def load_vectors(fe, ml: MotionLoads) -> tuple[np.ndarray, list[np.ndarray]]:
    """Global load vectors of every step on one discretisation (a fixed configuration).

    The loads of :func:`motion_loads` (global axes) are taken onto the members of ``fe`` in its
    own configuration: the stations and member axes of ``fe``, the loads' values of each step.
    This is the load of a linearised analysis about that configuration (e.g. transient
    dynamics); :func:`trussfe.response.along_motion.elastic_along_motion` instead moves the
    model with the motion.

    Parameters
    ----------
    fe : FEModel
        Pinned-beam (or all-frame) discretisation of the structure the loads belong to, every
        member subdivided alike.
    ml : MotionLoads
        Loads of nt steps.

    Returns
    -------
    f : ndarray, shape (nt, n_dof)
        Global load vectors (member loads, nodal forces P + M(g − a)).
    f_local : list of ndarray, one per element group, shape (nt, n_local)
        The element part in each group's local (field) space, for
        :meth:`FEModel.element_forces` (one step at a time).

    Raises
    ------
    InputError
        A discretisation with truss (axial-only) elements or unequal subdivisions.
    """
    from ..errors import InputError

    s = fe.structure
    nt, m, dim = ml.n_steps, s.n_members, s.dim
    k = int(fe.member_subdivisions[0]) if m else 1
    if np.any(fe.member_subdivisions != k) or any(g.kind != "frame" for g in fe.groups):
        raise InputError("--bar-model", "motion loads need the pinned-beam bar model "
                         "(every member a subdivided beam)")
    ex = np.broadcast_to(fe.element_x.reshape(1, m, k, 2), (nt, m, k, 2))
    R = np.broadcast_to(rotations3(fe.rotation)[None], (nt, m, 3, 3))
    every = np.arange(fe.n_elements)
    phi = tuple(fe.shear_parameter(f, every).reshape(1, m, k) for f in "vw")
    comp = element_load_components(ml, ex, R, phi).reshape(nt, m * k, 2, 6)
    f = np.zeros((nt, fe.n_dof))
    f_local = []
    for g in fe.groups:
        c = comp[:, g.elements]
        c = (c[..., [0, 1, 5]] if dim == 2 else c).reshape(nt, -1)
        f += (g.G.T @ c.T).T
        f_local.append((g.S @ c.T).T)
    np.add.at(f, (slice(None), fe.node_dofs[:, :dim]), ml.nodal[..., :dim])
    return f, f_local
