# SPDX-License-Identifier: MIT
"""Member loads on the finite-element discretisation: the global load vector and the
fixed-end forces that member-force recovery subtracts.

A member load (:mod:`trussfe.model.member_loads`) is cut over the sub-elements of its member:
a distributed load goes to every sub-element its span covers, with its intensity at the ends
of the covered part (a sub-element covered in part takes the load on that part only), a
point load to the one sub-element containing it (anywhere along it, not only at its nodes).
On each sub-element its equivalent end loads are the fixed-end forces of
:mod:`trussfe.mechanics.member_loads` — Timoshenko (or Euler–Bernoulli) shape functions on
the bending fields of frames, P1 on the axial and twist fields and on every field of a
pin-ended bar (whose transverse load goes to its end joints as the reactions of a simply
supported bar).  They are written in the field DOFs of the element groups, the space of
:meth:`~trussfe.fem.discretisation.FEModel.element_forces`, so that

* the global load vector is ``f = Σ Tᵀ f_local`` and
* the end forces of every sub-element are ``Sᵀ (K_local T u − f_local)``: the fixed-end
  forces subtracted, so end forces and the section forces at every station are exact.

Use per load case: ``v = member_load_vector(fe, loads)``; add ``v.global_vector`` to the
case's load vector, and pass ``v.local`` (added to the self-weight's
:meth:`~trussfe.fem.discretisation.FEModel.element_self_weight_local` when the case has
gravity) to ``element_forces``.  :func:`trussfe.fem.static.solve_static` does both.
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..budget import require
from ..errors import InputError
from ..mechanics.member_loads import (AT_STATION, linear_load_bending, linear_load_p1,
                                      part_load_bending, part_load_p1, point_load_bending,
                                      point_load_p1, section_forces_along, span_integrals)
from ..model.member_loads import MemberLoad, load_arrays
from .discretisation import FEModel


@dataclass
class MemberLoadVectors:
    """Member loads on a discretisation (see the module notes).

    Attributes
    ----------
    global_vector : ndarray, shape (n_dof,)
        Equivalent nodal loads.
    local : list of ndarray
        Per element group of the model (``fe.groups``), the fixed-end forces in its field
        DOFs.
    q1, q2, F, C : ndarray, shape (l, 3)
        The loads in member axes (2-D: zero z components, couples about z only).
    member : ndarray of int, shape (l,)
    point : ndarray of bool, shape (l,)
    at : ndarray, shape (l,)
        Position of point loads, m from the start node.
    span : ndarray, shape (l, 2)
        Span of distributed loads, m from the start node (``q1`` acts at its start, ``q2``
        at its end).
    element_axial : ndarray, shape (n_elements,)
        Per element, its length-average axial force minus the mean of its two end values
        (:func:`element_axial_correction`).
    """

    global_vector: np.ndarray
    local: list
    member: np.ndarray
    point: np.ndarray
    q1: np.ndarray
    q2: np.ndarray
    at: np.ndarray
    F: np.ndarray
    C: np.ndarray
    element_axial: np.ndarray
    span: np.ndarray


def local_member_loads(fe: FEModel, loads: Sequence[MemberLoad]):
    """The loads in member axes, padded to 3 components: ``(member, point, q1, q2, a, F, C,
    span)`` with ``a`` and ``span`` in m from the start node."""
    s = fe.structure
    dim = s.dim
    try:
        arr = load_arrays(loads, dim)
    except ValueError as exc:
        raise InputError("member_loads", str(exc)) from None
    mem = arr.member
    R = fe.rotation[mem] if mem.size else np.zeros((0, dim, dim))

    def to_local(v):
        return np.where(arr.local[:, None], v, np.einsum("lij,lj->li", R, v))

    pad = lambda v: np.concatenate([v, np.zeros((v.shape[0], 3 - dim))], axis=1)
    q1, q2, F = (pad(to_local(v)) for v in (arr.q1, arr.q2, arr.F))
    C = arr.C.copy()
    if dim == 3:
        C = np.where(arr.local[:, None], C, np.einsum("lij,lj->li", R, C))
    L = fe.structure.lengths()[mem] if mem.size else np.zeros(0)
    return mem, arr.point, q1, q2, arr.at * L, F, C, arr.span * L[:, None]


def member_load_vector(fe: FEModel, loads: Sequence[MemberLoad]) -> MemberLoadVectors:
    """Equivalent nodal loads and fixed-end forces of member loads on a discretisation.

    Parameters
    ----------
    fe : FEModel
    loads : sequence of MemberLoad
        E.g. ``structure.extensions["member_loads"]`` or the member loads of one load case.

    Returns
    -------
    MemberLoadVectors

    Raises
    ------
    InputError
        A couple about the axis of a member that has no torsion field.
    """
    s = fe.structure
    mem, point, q1, q2, a, F, C, span = local_member_loads(fe, loads)
    L = s.lengths()
    k = fe.member_subdivisions
    first = fe.member_elements[:-1]
    # (load, element) pairs: distributed loads on every element their span covers (in
    # part, or over a length of round-off: dropped), point loads on the element holding them
    dist = np.flatnonzero(~point)
    reps = k[mem[dist]]
    d_load = np.repeat(dist, reps)
    d_el = first[mem[d_load]] + (np.arange(d_load.size)
                                 - np.repeat(np.cumsum(reps) - reps, reps))
    c, d = span[d_load, 0], span[d_load, 1]
    lo = np.maximum(fe.element_x[d_el, 0], c)
    hi = np.minimum(fe.element_x[d_el, 1], d)
    keep = hi - lo > AT_STATION * L[mem[d_load]]
    d_load, d_el, lo, hi, c, d = (v[keep] for v in (d_load, d_el, lo, hi, c, d))
    pts = np.flatnonzero(point)
    kp = k[mem[pts]]
    h_m = L[mem[pts]] / kp
    # a point load on an inner station goes to the element that ends there, so that the
    # station's section force (the start of the next element) is the one just after the
    # load, as in the statics of loaded_member_stations
    r = a[pts] / h_m
    on_station = np.abs(r - np.round(r)) <= AT_STATION * kp
    j = np.where(on_station, np.round(r) - 1, np.floor(r)).astype(np.int64)
    j = np.clip(j, 0, kp - 1)
    p_el = first[mem[pts]] + j
    xi = np.clip((a[pts] - fe.element_x[p_el, 0]) / fe.element_length[p_el], 0.0, 1.0)
    twistless = ~fe.twist_member[mem[pts]] & (np.abs(C[pts, 0]) > 0)
    if s.dim == 3 and np.any(twistless):
        i = int(mem[pts][np.flatnonzero(twistless)[0]])
        raise InputError(f"member_loads (member {s.member_ids[i]})",
                         "a couple about the member axis needs a beam with torsion (a bar "
                         "carries none)").in_file(s.source)
    spinning = fe.end_rotations.spinning[mem[pts]] & (np.abs(C[pts, 0]) > 0)
    if np.any(spinning):
        i = int(mem[pts][np.flatnonzero(spinning)[0]])
        raise InputError(f"member_loads (member {s.member_ids[i]})",
                         "a couple about the member axis, but the member is free to twist at "
                         "both ends (torsion released there, or joints that do not hold its "
                         "rotation about its axis): nothing resists it; keep the torsion at "
                         "one end or remove the couple").in_file(s.source)
    # intensities at the ends of the covered part of each loaded element
    x0 = fe.element_x[d_el, 0]
    he = fe.element_length[d_el]
    width = (d - c)[:, None]
    dq = (q2 - q1)[d_load]
    qa = q1[d_load] + dq * ((lo - c)[:, None] / width)
    qb = q1[d_load] + dq * ((hi - c)[:, None] / width)
    # the covered part as fractions of the element; whole elements take the closed forms
    xi0, xi1 = (lo - x0) / he, (hi - x0) / he
    whole = (lo == x0) & (hi == fe.element_x[d_el, 1])
    group_of = np.full(fe.n_elements, -1, dtype=np.int64)
    pos_in = np.zeros(fe.n_elements, dtype=np.int64)
    for gi, g in enumerate(fe.groups):
        group_of[g.elements] = gi
        pos_in[g.elements] = np.arange(g.elements.size)
    local = [np.zeros(g.n_local) for g in fe.groups]
    f = np.zeros(fe.n_dof)
    # component of the load and of the couple on each field (w: the couple about y does
    # work on θy = −w', hence the sign); the twist field θ takes the torque as its load
    # (the couple about x does work on θ itself), not as a couple on a slope
    comp = {"u": (0, None, 0.0), "v": (1, 2, 1.0), "w": (2, 1, -1.0), "theta": (None, None, 0.0)}
    for gi, g in enumerate(fe.groups):
        dsel = group_of[d_el] == gi
        psel = group_of[p_el] == gi
        if not (dsel.any() or psel.any()):
            continue
        out = local[gi]
        for fld in g.fields:
            qc, cc, sign = comp[fld.name]
            edofs = fld.basis.element_dofs                         # (nbfun, n_el_group)
            parts = []
            de, pe = d_el[dsel], p_el[psel]
            wh = whole[dsel]
            x0_, x1_ = xi0[dsel], xi1[dsel]
            hd, hp = fe.element_length[de], fe.element_length[pe]
            qa_c = qa[dsel, qc] if qc is not None else np.zeros(de.size)
            qb_c = qb[dsel, qc] if qc is not None else np.zeros(de.size)
            P = (F[pts][psel, qc] if qc is not None else
                 C[pts][psel, 0] if fld.name == "theta" else np.zeros(pe.size))
            Cc = sign * C[pts][psel, cc] if cc is not None else np.zeros(pe.size)
            if fld.hermite:
                phi_d = fe.shear_parameter(fld.name, de)
                phi_p = fe.shear_parameter(fld.name, pe)
                parts = [(de[wh], linear_load_bending(hd[wh], phi_d[wh], qa_c[wh],
                                                      qb_c[wh])),
                         (de[~wh], part_load_bending(hd[~wh], phi_d[~wh], x0_[~wh],
                                                     x1_[~wh], qa_c[~wh], qb_c[~wh])),
                         (pe, point_load_bending(xi[psel], hp, phi_p, P, Cc))]
            else:
                parts = [(de[wh], linear_load_p1(hd[wh], qa_c[wh], qb_c[wh])),
                         (de[~wh], part_load_p1(hd[~wh], x0_[~wh], x1_[~wh], qa_c[~wh],
                                                qb_c[~wh])),
                         (pe, point_load_p1(xi[psel], hp, P, Cc))]
            for els, vals in parts:
                if els.size:
                    rows = fld.offset + edofs[:, pos_in[els]].T            # (el, nbfun)
                    np.add.at(out, rows.ravel(), vals.ravel())
        f += g.T.T @ out
    correction = element_axial_correction(fe.n_elements, d_el, he, qa[:, 0], qb[:, 0],
                                          p_el, xi, F[pts, 0], xi0, xi1)
    return MemberLoadVectors(global_vector=f, local=local, member=mem, point=point, q1=q1,
                             q2=q2, at=a, F=F, C=C, element_axial=correction, span=span)


def element_axial_correction(n_elements: int, d_el: np.ndarray, h: np.ndarray,
                             qa: np.ndarray, qb: np.ndarray, p_el: np.ndarray,
                             xi: np.ndarray, P: np.ndarray, xi0: np.ndarray | None = None,
                             xi1: np.ndarray | None = None) -> np.ndarray:
    r"""Per element, the length-average of its axial force minus the mean of its two end
    values, from the axial loads along it.

    A linear buckling analysis takes one axial force per element
    (:meth:`~trussfe.fem.discretisation.FEModel.geometric_stiffness`); the bar's string
    stiffness ``∫ N dx / h² · [[1, −1], [−1, 1]]`` is exact with the average of N over the
    element, which is the mean of the end values only where N is linear.  With
    ``N(x) = N(0) − Q(x)`` (``Q`` the axial load on ``[0, x]``), a load varying linearly from
    ``q_a`` to ``q_b`` over the element adds ``h (q_b − q_a)/12``, and a point force ``P`` at
    ``ξ h`` adds ``P (ξ − 1/2)`` (``−P/2`` at the element's start: it acts on all of it).
    In general a load adds ``(1/h) ∫ q(s) (s − h/2) ds``: on the part ``[ξ₀ h, ξ₁ h]`` of
    length ``ℓ`` and centre ``m``, ``ℓ (ℓ/h) (q_b − q_a)/12 + (m/h − 1/2) ℓ (q_a + q_b)/2``.

    Parameters
    ----------
    n_elements : int
    d_el, h, qa, qb : ndarray, shape (d,)
        Element, its length and the axial intensities at the ends of the loaded part, for
        every (distributed load, element) pair.
    p_el, xi, P : ndarray, shape (p,)
        Element, relative position in it and axial force of every point load.
    xi0, xi1 : ndarray, shape (d,), optional
        The loaded part of the element (default the whole element).

    Returns
    -------
    ndarray, shape (n_elements,)

    Examples
    --------
    A point force of 1000 N at 0.3 of an element: the average is 0.2 × 1000 N below the
    mean of the ends.

    >>> element_axial_correction(1, np.zeros(0, int), np.zeros(0), np.zeros(0), np.zeros(0),
    ...                          np.array([0]), np.array([0.3]), np.array([1000.0])).tolist()
    [-200.0]
    """
    out = np.zeros(n_elements)
    if xi0 is None:
        np.add.at(out, d_el, h * (qb - qa) / 12.0)
    else:
        ell = (xi1 - xi0) * h
        # the second term vanishes on a whole element (ξ₀ + ξ₁ = 1)
        np.add.at(out, d_el, ell * (xi1 - xi0) * (qb - qa) / 12.0
                  + (0.5 * (xi0 + xi1) - 0.5) * ell * (qa + qb) / 2.0)
    np.add.at(out, p_el, P * (xi - 0.5))
    return out


def midpoint_axial_correction(v: MemberLoadVectors, lengths: np.ndarray,
                               n_members: int) -> np.ndarray:
    r"""``N(L/2) − (N(0) + N(L))/2`` of every member from its loads along it.

    The axial force at the midpoint is reported (``StaticResult.axial_force``); the mean of
    the two end values is that only where N is linear along the member.  With
    ``Q(x) = ∫₀ˣ q_x + Σ_{a<x} F_x`` the load on ``[0, x]`` (member axes),
    ``N(x) = N(0) − Q(x)``, so the midpoint value is the mean of the ends plus
    ``Q(L)/2 − Q(L/2)``: ``L(q₂ − q₁)/8`` for a load varying linearly from ``q₁`` to ``q₂``
    (zero for a uniform one) over the whole member, ``Q(L)/2 − Q(L/2)`` of its span
    otherwise (:func:`~trussfe.mechanics.member_loads.span_integrals`), ``F/2`` for a point
    force beyond the midpoint and ``−F/2`` before it.  A point force at the midpoint itself
    adds nothing: N jumps there and the mean of its two sides is reported.  Loads not among
    ``v`` (a truss bar's self-weight, lumped at its joints) do not enter its end values
    either, and need no correction.

    Parameters
    ----------
    v : MemberLoadVectors
        The member loads (member axes, point positions in m).
    lengths : ndarray, shape (m,)
        Member lengths.
    n_members : int

    Returns
    -------
    ndarray, shape (m,)
        The correction, N; zero for members without an axial member load.

    Examples
    --------
    A member of 4 m under an axial point load of 1000 N at 1.2 m: the mean of the ends is
    off by ``−F/2`` at the midpoint.

    >>> v = MemberLoadVectors(np.zeros(0), [], np.array([0]), np.array([True]),
    ...                       np.zeros((1, 3)), np.zeros((1, 3)), np.array([1.2]),
    ...                       np.array([[1000.0, 0.0, 0.0]]), np.zeros((1, 3)), np.zeros(1),
    ...                       np.array([[0.0, 4.0]]))
    >>> midpoint_axial_correction(v, np.array([4.0]), 1).tolist()
    [-500.0]
    """
    L = np.asarray(lengths, dtype=float)
    out = np.zeros(n_members)
    dist = ~v.point
    md = v.member[dist]
    whole = (v.span[dist, 0] == 0.0) & (v.span[dist, 1] == L[md])
    Q, _ = span_integrals(np.stack([0.5 * L[md], L[md]], axis=1), v.span[dist, 0],
                          v.span[dist, 1], v.q1[dist], v.q2[dist])
    np.add.at(out, md, np.where(whole, L[md] * (v.q2[dist, 0] - v.q1[dist, 0]) / 8.0,
                                0.5 * Q[:, 1, 0] - Q[:, 0, 0]))
    mp = v.member[v.point]
    a, Lp = v.at[v.point], L[mp]
    tol = AT_STATION * Lp
    # share of each point force in Q(L/2): before the midpoint all of it, at it half
    share = np.where(a < 0.5 * Lp - tol, 1.0, np.where(a > 0.5 * Lp + tol, 0.0, 0.5))
    np.add.at(out, mp, v.F[v.point, 0] * (0.5 - share))
    return out


#: Bytes of the statics of :func:`loaded_member_stations` per load and station (measured:
#: 1,000 point loads on one bar, 2,000 stations with the zero-shear points, 340 MB).
STATICS_BYTES_PER_PAIR = 170


def loaded_member_stations(fe: FEModel, v: MemberLoadVectors, station_x: np.ndarray,
                           section_forces: np.ndarray
                           ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Section forces along the members that carry member loads, by statics from their start
    sections (:func:`trussfe.mechanics.member_loads.section_forces_along`).

    The stations are the member's finite-element stations, the positions of its point
    loads (where the shear force jumps and the moment peaks), the ends of its distributed
    loads' spans (where the shear force changes its slope) and the points between them
    where a distributed load makes a shear force vanish (where the moment it bends peaks), so
    that a pin-ended bar, which has no station inside, shows its simply supported moment
    under its loads too.

    Besides ``v`` a member carries a uniform load: the self-weight of a frame member (scaled
    by a combination's factor; none without gravity).  The statics takes it from the
    member's two end sections, which the finite elements give exactly: the uniform load
    that closes the balance of the forces between them.  (A truss bar's self-weight is
    lumped at its joints and does not enter its end sections.)

    Parameters
    ----------
    fe : FEModel
    v : MemberLoadVectors
    station_x, section_forces : ndarray
        ``StaticResult.station_x`` (m, s) and ``StaticResult.section_forces`` (m, s, 6).

    Returns
    -------
    members : ndarray of int, shape (r,)
        The loaded members, ascending.
    x : ndarray, shape (r, t)
        Their stations, m from the start node (NaN-padded).
    forces : ndarray, shape (r, t, 6)
        ``[N, Vy, Vz, T, My, Mz]`` at the stations (NaN-padded).
    """
    members, row = np.unique(v.member, return_inverse=True)
    L = fe.structure.lengths()[members]
    # the FE stations of each loaded member and the positions of its point loads, one row
    # per member: sorted (NaN last), a position that is already a station dropped
    dist = ~v.point
    prow = np.concatenate([row[v.point], row[dist], row[dist]])
    where = np.concatenate([v.at[v.point], v.span[dist, 0], v.span[dist, 1]])
    order = np.argsort(prow, kind="stable")
    count = np.bincount(prow, minlength=members.size)
    rank = np.arange(prow.size) - np.repeat(np.cumsum(count) - count, count)
    extra = np.full((members.size, int(count.max(initial=0))), np.nan)
    extra[prow[order], rank] = where[order]
    x = _distinct_stations([station_x[members], extra], L)
    start = section_forces[members, 0]
    loads = _with_uniform_rest(v, row, L, start, station_x[members], section_forces[members])
    # the statics take every load at every station of the rows: (loads × stations) arrays
    # (10,000 point loads on one bar would need 30 GB)
    pairs = float(loads[0].size) * x.shape[1] * 2
    try:
        require(pairs * STATICS_BYTES_PER_PAIR, "member_loads",
                f"the section forces of {v.member.size:,} member loads at up to "
                f"{x.shape[1]:,} stations of a member",
                "give a distributed load instead of many point loads")
    except InputError as err:
        raise err.in_file(fe.structure.source) from None
    F = section_forces_along(x, L, start, *loads)
    # where a distributed load makes a shear force vanish between two stations, the moment
    # it bends has its extreme there (the midspan of a bar under a uniform load): a station
    peaks = _zero_shear_positions(x, F, L, *loads[:4], loads[7], members.size)
    if peaks.shape[1]:
        x = _distinct_stations([x, peaks], L)
        F = section_forces_along(x, L, start, *loads)
    F[~np.isfinite(x)] = np.nan
    return members, x, F


def _with_uniform_rest(v: MemberLoadVectors, row: np.ndarray, L: np.ndarray,
                       start: np.ndarray, x_fe: np.ndarray, F_fe: np.ndarray) -> tuple:
    """The loads of ``v`` as ``(row, point, q1, q2, at, F, C, span)`` for
    :func:`~trussfe.mechanics.member_loads.section_forces_along`, with one uniform load per
    member row added: the load its elements carry besides ``v`` (self-weight), from the
    finite-element sections at its two ends, ``q = (S_v(L) − S(L)) / L`` on the forces, where
    ``S_v`` is the statics of ``v`` alone from the start section (a point load at the end
    node is behind the end section, as the element's end force has it)."""
    r = L.size
    last = np.isfinite(x_fe).sum(axis=1) - 1
    end = F_fe[np.arange(r), last]
    alone = section_forces_along(L[:, None], L, start, row, v.point, v.q1, v.q2, v.at, v.F,
                                 v.C, v.span)[:, 0]
    at_end = v.point & (np.abs(v.at - L[row]) <= AT_STATION * L[row])
    forces = alone[:, :3].copy()
    np.add.at(forces, row[at_end], -v.F[at_end])
    rest = (forces - end[:, :3]) / L[:, None]
    z = np.zeros((r, 3))
    return (np.concatenate([row, np.arange(r)]), np.concatenate([v.point, np.zeros(r, bool)]),
            np.concatenate([v.q1, rest]), np.concatenate([v.q2, rest]),
            np.concatenate([v.at, np.zeros(r)]), np.concatenate([v.F, z]),
            np.concatenate([v.C, z]),
            np.concatenate([v.span, np.stack([np.zeros(r), L], axis=1)]))


def _distinct_stations(parts: list[np.ndarray], L: np.ndarray) -> np.ndarray:
    """The positions of ``parts`` (each (r, ·), NaN-padded) per member row, sorted, a
    position within :data:`AT_STATION` of the member length of the one before dropped,
    NaN-padded to the longest row."""
    x = np.sort(np.concatenate(parts, axis=1), axis=1)
    same = np.abs(np.diff(x, axis=1)) <= AT_STATION * L[:, None]
    x[:, 1:][same] = np.nan
    x = np.sort(x, axis=1)
    return x[:, : int(np.isfinite(x).sum(axis=1).max(initial=0))]


def _zero_shear_positions(x: np.ndarray, F: np.ndarray, L: np.ndarray, row: np.ndarray,
                          point: np.ndarray, q1: np.ndarray, q2: np.ndarray,
                          span: np.ndarray, r: int) -> np.ndarray:
    r"""Positions strictly between consecutive stations where ``Vy`` or ``Vz`` is zero.

    Between stations (the point loads and the ends of the spans are stations) a member
    carries only the distributed loads whose span covers the interval,
    ``q(x) = q₁ + k (x − c)``, ``k = (q₂ − q₁)/(d − c)``, summed over them, so from a
    station ``xᵢ`` with shear ``Vᵢ`` (just beyond it) ``V(xᵢ + t) = Vᵢ − q(xᵢ) t − k t²/2``:
    its roots in ``(0, h)`` are where ``dM/dx = ∓V`` vanishes.  With loads in one plane (or
    of one shape in both) these are where the resultant moment, and so the bending stress,
    is largest.

    Returns
    -------
    ndarray, shape (r, p)
        The positions per member row, NaN-padded (``p`` may be 0).
    """
    dist = np.flatnonzero(~np.asarray(point, bool))
    x0, x1 = x[:, :-1], x[:, 1:]
    h = x1 - x0                                                        # (r, s − 1), NaN past
    # per interval, the intensity at its start and the slope of the loads covering it
    rd = row[dist]
    c0, d0 = span[dist, 0][:, None], span[dist, 1][:, None]
    tol = AT_STATION * L[rd][:, None]
    with np.errstate(invalid="ignore"):
        covers = (x0[rd] >= c0 - tol) & (x1[rd] <= d0 + tol)           # (dist, s − 1)
    slope = (q2[dist] - q1[dist]) / (d0 - c0)                          # (dist, 3)
    found = []
    for c in (1, 2):                                                   # Vy, Vz
        V = F[:, :-1, c]
        at_start = q1[dist, c][:, None] + slope[:, c][:, None] * (x0[rd] - c0)
        qi = np.zeros(x0.shape)
        k = np.zeros(x0.shape)
        np.add.at(qi, rd, np.where(covers, at_start, 0.0))
        np.add.at(k, rd, np.where(covers, slope[:, c][:, None], 0.0))
        with np.errstate(invalid="ignore", divide="ignore"):
            D = np.sqrt(np.maximum(qi * qi + 2.0 * k * V, 0.0))
            s = qi + np.where(qi < 0, -D, D)                           # no cancellation
            t1 = np.where(s != 0, 2.0 * V / s, np.nan)                 # the root near V/q
            t2 = np.where(k != 0, -s / k, np.nan)
            real = qi * qi + 2.0 * k * V >= 0
        for t in (t1, t2):
            inside = real & np.isfinite(t) & (t > AT_STATION * L[:, None]) \
                & (t < h - AT_STATION * L[:, None])
            found.append(np.where(inside, x0 + t, np.nan))
    peaks = np.sort(np.concatenate(found, axis=1), axis=1)
    return peaks[:, : int(np.isfinite(peaks).sum(axis=1).max(initial=0))]
