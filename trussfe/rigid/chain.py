# SPDX-License-Identifier: MIT
"""Multi-bay chains analysed bay by bay (Lacy chapter 6): the positions of ``simulate``'s
bay-by-bay method (:func:`chain_positions`) and the chapter's frames, rates and forces.

Lacy describes, but never implemented, the kinematics of a chain of double-octahedral bays in
bay-fixed frames: bay n's base plane is bay n−1's top plane, so each bay is solved alone in a
frame attached to its base and carried up the chain (eqs. 6.1–6.14):

.. math::

   x_i &= o_n + R_n p_i,                                                  \\\\
   v_i &= \\dot o_n + \\omega_n \\times R_n p_i + R_n \\dot p_i,               \\\\
   a_i &= \\ddot o_n + \\alpha_n \\times R_n p_i
          + \\omega_n \\times (\\omega_n \\times R_n p_i)
          + 2 \\omega_n \\times R_n \\dot p_i + R_n \\ddot p_i ,

with p, ṗ, p̈ the node position, velocity and acceleration of the bay alone (base fixed) and
o_n the centroid of bay n−1's top plane (eqs. 6.2, 6.6, 6.8, 6.13).  Here the frame's rotation
R_n, angular velocity ω_n and angular acceleration α_n are computed directly from the
Newtonian positions, velocities and accelerations of the three top-plane nodes of bay n−1 (a
rigid triangle: ``J ω = Σ r_i × (v_i − v_o)``, ``J = Σ (|r_i|² I − r_i r_iᵀ)``), not by
Lacy's sums of relative rotations.  Two of those need care: eq. 6.5, ``C^{bn/N} =
(C^{b2/N})^{n−1}``, holds only while every bay has the same configuration, and eq. 6.14 sums
relative angular accelerations, which omits the terms ``ω_{k−1} × ω_{k/k−1}`` (the derivative
of a relative angular velocity seen from a rotating frame); it is exact only when successive
bays turn about parallel axes.  :func:`thesis_angular_acceleration` evaluates eq. 6.14 so the
difference can be shown.

Bay-local kinematics (:func:`bay_kinematics`) use the forward-position solver and the
compatibility matrix of the bay: ``B ṗ = L̇``, ``B p̈ = L̈ − (|ṗ_b − ṗ_a|² − L̇²)/L``
(the bar-length condition differentiated twice), exact, batched over time steps.  The
positions of all bays and steps are found together (:func:`bay_positions`: continuation on
coarse steps, cubic Hermite guesses, chord Newton iterations).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AnalysisError
from ..kinematics.assembly import solve_positions
from ..mechanics.geometry import member_vectors, unit_vectors
from ..model.structure import Structure, build_structure
from .active import ActiveMember, active_members
from ..threads import contiguous_spans, parallel_map, worker_count
from ..vectors import cross

#: Bay template nodes: base N1–N3 (0–2), midplane N4–N6 (3–5), top N7–N9 (6–8).  The top
#: plane is the mirror image of the base in the midplane, N7 over N1, N9 over N2, N8 over N3,
#: so the next bay's base (N1, N2, N3) is this bay's (N7, N9, N8).
TOP_AS_NEXT_BASE = (6, 8, 7)


@dataclass
class BayFrames:
    """Frames attached to the base plane of every bay, arrays (nt, n_bays, ...).

    Attributes
    ----------
    origin, origin_velocity, origin_acceleration : ndarray, shape (nt, nb, 3)
        Base-plane centroid o_n and its rates.
    rotation : ndarray, shape (nt, nb, 3, 3)
        R_n: columns are the frame's unit vectors in Newtonian coordinates.
    omega, alpha : ndarray, shape (nt, nb, 3)
        Angular velocity and acceleration of the frame (Newtonian components).
    """

    origin: np.ndarray
    origin_velocity: np.ndarray
    origin_acceleration: np.ndarray
    rotation: np.ndarray
    omega: np.ndarray
    alpha: np.ndarray


@dataclass
class ChainKinematics:
    """Kinematics of the chain, nodes numbered as :func:`stack_bays`.

    Attributes
    ----------
    coords, velocity, acceleration : ndarray, shape (nt, n_nodes, 3)
    frames : BayFrames
    """

    coords: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    frames: BayFrames


def triangle_frame(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Origin and rotation of the frame of triangles ``x`` (..., 3 nodes, 3).

    Origin at the centroid (Lacy eq. 6.2), e1 along node 0 → 1, e3 normal (right-handed in the
    node order), e2 = e3 × e1.

    Examples
    --------
    >>> o, R = triangle_frame(np.array([[0., 0, 0], [1, 0, 0], [0, 1, 0]]))
    >>> np.round(o, 4).tolist(), np.allclose(R, np.eye(3))
    ([0.3333, 0.3333, 0.0], True)
    """
    # the centroid as numpy's mean adds it, (x0 + x1) + x2 over 3, without its reduction
    # machinery (a third of this function's time on a few hundred steps)
    o = (x[..., 0, :] + x[..., 1, :] + x[..., 2, :]) / 3.0
    u = x[..., 1, :] - x[..., 0, :]
    w = cross(u, x[..., 2, :] - x[..., 0, :])
    e1 = u / np.linalg.norm(u, axis=-1, keepdims=True)
    e3 = w / np.linalg.norm(w, axis=-1, keepdims=True)
    e2 = cross(e3, e1)
    return o, np.stack([e1, e2, e3], axis=-1)


def rigid_rates(x: np.ndarray, v: np.ndarray, a: np.ndarray) -> tuple[np.ndarray, ...]:
    """Centroid velocity/acceleration, angular velocity and acceleration of rigid triangles.

    Parameters
    ----------
    x, v, a : ndarray, shape (..., 3 nodes, 3)
        Node positions, velocities, accelerations of a rigid body.

    Returns
    -------
    vo, ao, omega, alpha : ndarray, shape (..., 3)

    Notes
    -----
    With r_i = x_i − o: ``Σ r_i × (v_i − v_o) = J ω`` and
    ``Σ r_i × (a_i − a_o − ω × (ω × r_i)) = J α``, ``J = Σ (|r_i|² I − r_i r_iᵀ)``, exact for a
    rigid motion of three non-collinear points.
    """
    o = x.mean(axis=-2, keepdims=True)
    r = x - o
    vo = v.mean(axis=-2)
    ao = a.mean(axis=-2)
    rr = np.einsum("...ik,...ik->...", r, r)
    J = rr[..., None, None] * np.eye(3) - np.einsum("...ij,...ik->...jk", r, r)
    h = cross(r, v - vo[..., None, :]).sum(axis=-2)
    omega = np.linalg.solve(J, h[..., None])[..., 0]
    cen = cross(omega[..., None, :], cross(omega[..., None, :], r))
    g = cross(r, a - ao[..., None, :] - cen).sum(axis=-2)
    alpha = np.linalg.solve(J, g[..., None])[..., 0]
    return vo, ao, omega, alpha


def bay_kinematics(bay: Structure, lengths: np.ndarray, rates: np.ndarray, accs: np.ndarray,
                   coords0: np.ndarray | None = None, item: str = "bay"
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Node positions, velocities, accelerations of one bay alone (base fixed), exact.

    Parameters
    ----------
    bay : Structure
        The bay (three supported base nodes, three active members).
    lengths, rates, accs : ndarray, shape (nt, n_active)
        Active lengths, L̇, L̈ (columns in the order of the bay's active members).
    coords0 : ndarray, optional
        Starting guess (default the bay's coordinates).

    Returns
    -------
    p, pd, pdd : ndarray, shape (nt, n_nodes, 3)

    Notes
    -----
    The positions of all steps are found at once by Newton's method from ``coords0``
    (:func:`_batched_positions`); if a step does not converge there, or lands more than a
    tenth of the bay's size away (another assembly branch), the steps are solved one after
    the other, each warm-started from the previous one.
    """
    L = _all_lengths(bay, lengths)
    x0 = bay.coords if coords0 is None else np.asarray(coords0, dtype=float)
    X, ok = _batched_positions(bay, L, x0)
    if not ok.all():
        X = _sequential_positions(bay, L, x0, item)
    return _bay_rates(bay, L, rates, accs, X, item)


def _all_lengths(bay: Structure, lengths: np.ndarray) -> np.ndarray:
    """Member lengths (nt, m): the bay's passive lengths and the given active ones."""
    from .kinematics import member_histories
    acts = np.array([a.member for a in active_members(bay)], dtype=np.int64)
    return member_histories(lengths, acts, bay.lengths(),
                            np.empty((lengths.shape[0], bay.n_members)))


def _sequential_positions(bay: Structure, L: np.ndarray, x0: np.ndarray, item: str
                          ) -> np.ndarray:
    """Warm-started forward position, one step after another (the robust fallback)."""
    conn, fixed = bay.connectivity, bay.translation_supports
    X = np.empty((L.shape[0],) + x0.shape)
    x = x0
    for k in range(L.shape[0]):
        x = solve_positions(x, conn, L[k], fixed, member_ids=bay.member_ids,
                            item=f"{item}: step {k}").coords
        X[k] = x
    return X


def _batched_positions(bay: Structure, L: np.ndarray, x0: np.ndarray, *,
                       tolerance: float = 1e-12, iterations: int = 30,
                       anchors: np.ndarray | None = None, owner: np.ndarray | None = None
                       ) -> tuple[np.ndarray, np.ndarray]:
    """Newton's method on the bar-length equations of every step at once, from ``x0``
    (one guess (n, 3) for all steps, or one per step (N, n, 3)).

    A chord iteration (:func:`~trussfe.rigid.kinematics.chord_newton`): the compatibility
    matrix is factorised at the guess and every :data:`REFACTOR_EVERY` iterations, at every
    step or, with ``anchors`` (step indices) and ``owner`` (the anchor of every step, indices
    into ``anchors``), at the anchors only, every step using its anchor's (close guesses of a
    smooth motion: the chord still contracts fast, for a fraction of the factorisations).
    Returns the positions and a per-step flag: converged, and within a tenth of the bay's
    size of ``x0``.
    """
    from .kinematics import _Pattern, chord_newton

    N = L.shape[0]
    pattern = _Pattern.of(bay)
    X = np.broadcast_to(x0, (N,) + x0.shape[-2:]).copy()      # one guess, or one per step
    if pattern.m != pattern.nfree or N == 0:
        return X, np.zeros(N, dtype=bool)
    return chord_newton(bay.connectivity, pattern, L, X, np.broadcast_to(x0, X.shape),
                        anchors, owner, refactor_every=REFACTOR_EVERY,
                        min_chunk_steps=PARALLEL_POSITION_MIN_STEPS, tolerance=tolerance,
                        iterations=iterations)


#: Steps per worker thread below which the bay positions' Newton solve is not split.
PARALLEL_POSITION_MIN_STEPS = 2000
#: Chord iterations between refactorisations of the bay positions' Newton solve.
REFACTOR_EVERY = 4
#: Steps per chord Jacobian of the bay positions' Newton solve over all steps.
ANCHOR_SPACING = 8

#: Steps of the coarse continuation that gives every bay-local Newton solve its guess: at
#: most COARSE_STEPS, about one per COARSE_SPACING steps of the motion.
COARSE_STEPS = 20
COARSE_SPACING = 50


def bay_positions(bay: Structure, L: np.ndarray, item: str = "bay",
                  rates: np.ndarray | None = None, time: np.ndarray | None = None
                  ) -> np.ndarray:
    """Node positions of the bay alone (base fixed) for member lengths ``L`` (nb, nt, m):
    ``nb`` independent histories of one bay, every bay and step solved together.

    The positions follow each history by continuation: Newton's method on a coarse subset
    of steps (:data:`COARSE_STEPS`, :data:`COARSE_SPACING`), each from the previous one (all
    histories at once), then
    on every step from the positions interpolated between those (:func:`_batched_positions`):
    cubic Hermite interpolation with the node velocities ``B ṗ = L̇`` at the coarse steps when
    the length ``rates`` (nb, nt, m) and the ``time`` (nt,) are given (a guess closer by
    orders of magnitude, so fewer Newton sweeps over all steps), else linear in the step.
    A history whose steps do not all converge near their guess is solved again one step after
    the other, warm-started (the robust fallback).

    Returns
    -------
    ndarray, shape (nb, nt, n_nodes, 3)
    """
    nb, nt, m = L.shape
    n = bay.n_nodes
    x0 = np.asarray(bay.coords, dtype=float)
    # about one coarse step per COARSE_SPACING steps, at most COARSE_STEPS of them
    n_coarse = min(COARSE_STEPS, nt, max(2, 1 + nt // COARSE_SPACING))
    idx = np.unique(np.linspace(0, nt - 1, n_coarse).round().astype(np.int64))
    coarse = np.empty((nb, idx.size, n, 3))
    ok = np.ones(nb, dtype=bool)
    x = x0
    hermite = rates is not None and time is not None and idx.size > 1
    for j, k in enumerate(idx):
        x, good = _batched_positions(bay, L[:, k], x)
        ok &= good
        coarse[:, j] = x
    if hermite:
        # the node velocities B ṗ = L̇ at every coarse step of every history, in one solve
        from .kinematics import _Pattern
        from .linalg import SingularStep
        pattern = _Pattern.of(bay)
        vel = np.zeros((nb * idx.size, n * 3))
        e, _ = unit_vectors(member_vectors(coarse.reshape(-1, n, 3), bay.connectivity))
        try:
            solver = pattern.solver(pattern.values(e))
            vel[:, pattern.free_flat] = solver.solve(
                rates[:, idx][..., pattern.loaded_cols].reshape(nb * idx.size, -1))
        except SingularStep:
            hermite = False
    if idx.size > 1:
        # interpolation between the coarse steps
        seg = np.clip(np.searchsorted(idx, np.arange(nt), side="right") - 1, 0, idx.size - 2)
        if hermite:
            t0, t1 = time[idx[seg]], time[idx[seg + 1]]
            h = (t1 - t0)[None, :, None, None]
            s = ((time - t0) / (t1 - t0))[None, :, None, None]
            v = vel.reshape(nb, idx.size, n, 3)
            guess = np.empty((nb, nt, n, 3))
            # the bays' histories are independent: worker threads take contiguous bays
            parallel_map(lambda ab: _hermite(coarse[ab[0]:ab[1]], v[ab[0]:ab[1]], seg, s, h,
                                             guess[ab[0]:ab[1]]),
                         contiguous_spans(nb, min(worker_count(), nb)))
        else:
            w = ((np.arange(nt) - idx[seg]) / (idx[seg + 1] - idx[seg]))[None, :, None, None]
            guess = coarse[:, seg] * (1.0 - w) + coarse[:, seg + 1] * w
    else:
        guess = coarse
    # the chord Jacobians: every ANCHOR_SPACING-th step of each history, the nearest for all
    at = np.unique(np.r_[np.arange(0, nt, ANCHOR_SPACING), nt - 1])
    near = np.searchsorted((at[1:] + at[:-1]) / 2.0, np.arange(nt))
    X, good = _batched_positions(
        bay, L.reshape(nb * nt, m), guess.reshape(nb * nt, n, 3),
        anchors=(np.arange(nb)[:, None] * nt + at).ravel(),
        owner=(np.arange(nb)[:, None] * at.size + near).ravel())
    X = X.reshape(nb, nt, n, 3)
    ok &= good.reshape(nb, nt).all(axis=1)
    for k in np.flatnonzero(~ok):
        X[k] = _sequential_positions(bay, L[k], x0, f"{item} {k + 1}" if nb > 1 else item)
    return X


def _hermite(x: np.ndarray, v: np.ndarray, seg: np.ndarray, s: np.ndarray, h: np.ndarray,
             out: np.ndarray | None = None) -> np.ndarray:
    """Cubic Hermite interpolant of positions ``x`` and velocities ``v`` (nb, nc, n, 3) at
    the coarse steps: every step between coarse steps ``seg`` and ``seg + 1`` at the fraction
    ``s`` of the interval ``h`` ((1, nt, 1, 1) each); ``out``: a contiguous (nb, nt, n, 3)
    array to write it into.

    The four terms h00 x0 + h10 h v0 + h01 x1 + h11 h v1 are added in that order into the
    first one's gathered array, with one scratch array (the interpolant has the size of
    all the positions)."""
    out = np.take(x, seg, axis=1, out=out)
    out *= ((2 * s - 3) * s * s + 1)
    term = np.take(v, seg, axis=1)
    term *= ((s - 2) * s + 1) * s * h
    out += term
    np.take(x, seg + 1, axis=1, out=term)
    term *= (3 - 2 * s) * s * s
    out += term
    np.take(v, seg + 1, axis=1, out=term)
    term *= (s - 1) * s * s * h
    out += term
    return out


def chain_positions(bay: Structure, lengths: np.ndarray,
                    next_base: tuple[int, int, int] = TOP_AS_NEXT_BASE,
                    rates: np.ndarray | None = None, time: np.ndarray | None = None
                    ) -> np.ndarray:
    """Node positions of a stacked chain, bay by bay in bay-fixed frames (Lacy eqs. 6.1–6.3).

    Every bay's positions in the frame of its base plane (:func:`bay_positions`, all bays
    and steps at once), then carried up the chain: ``x = o_n + R_n p`` with o_n, R_n the
    frame of the plane below (one pass over the bays, each vectorised over the steps).

    Parameters
    ----------
    bay : Structure
        The bay template (base nodes 0–2 supported, then six own nodes).
    lengths : ndarray, shape (nt, n_bays, n_active)
        Active lengths of every bay (the bay's active-member order).
    next_base : tuple of int
        Template nodes that are the next bay's base nodes 0, 1, 2.
    rates : ndarray, shape (nt, n_bays, n_active), optional
        The active lengths' rates, and
    time : ndarray, shape (nt,), optional
        the sample times: with both, the guesses of the position solve are cubic Hermite
        interpolants (:func:`bay_positions`).

    Returns
    -------
    ndarray, shape (nt, 3 + 6 n_bays, 3)
        In the numbering of :func:`stack_bays`.
    """
    nt, nb, _ = lengths.shape
    # every bay's history contiguous, (nb, nt, m): the position solve takes all bays' steps
    # as one run of nb·nt steps without a copy
    Lall = _all_lengths(bay, lengths.transpose(1, 0, 2).reshape(nb * nt, -1))
    Ldall = None
    if rates is not None:
        acts = np.array([a.member for a in active_members(bay)], dtype=np.int64)
        Ldall = np.zeros((nb, nt, bay.n_members))
        Ldall[:, :, acts] = rates.transpose(1, 0, 2)
    P = bay_positions(bay, Lall.reshape(nb, nt, -1), item="bay", rates=Ldall,
                      time=time)                                       # (nb, nt, 9, 3)
    o_b, R_b = triangle_frame(bay.coords[:3])
    X = np.empty((nt, 3 + 6 * nb, 3))
    X[:, :3] = bay.coords[:3]
    nxt = np.asarray(next_base) - 3

    def carry(span):
        """Up the chain for the steps ``a:b`` (every step is independent of the others)."""
        a, b = span
        base = X[a:b, :3]
        for k in range(nb):
            o, R = triangle_frame(base)                               # eqs. 6.2, 6.6
            own = X[a:b, 3 + 6 * k:9 + 6 * k]
            p = (P[k, a:b, 3:] - o_b) @ R_b           # own nodes in the template's frame
            np.matmul(p, R.transpose(0, 2, 1), out=own)               # R p, eq. 6.3
            own += o[:, None, :]
            base = own[:, nxt]
    parallel_map(carry, contiguous_spans(nt, min(worker_count(), max(1, nt // 100))))
    return X


def _bay_rates(bay: Structure, L: np.ndarray, rates: np.ndarray, accs: np.ndarray,
               X: np.ndarray, item) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Positions, velocities and accelerations from the positions ``X`` (every step at once):
    ``B ṗ = L̇``, ``B p̈ = L̈ − (|ṗ_b − ṗ_a|² − L̇²)/L``.  ``item`` names the analysis in
    messages (a string, or a function of the step index)."""
    acts = np.array([a.member for a in active_members(bay)], dtype=np.int64)
    nt = L.shape[0]
    conn = bay.connectivity
    free = ~bay.translation_supports
    m, n = conn.shape[0], bay.n_nodes
    Ld = np.zeros((nt, m))
    Ld[:, acts] = rates
    Ldd = np.zeros((nt, m))
    Ldd[:, acts] = accs
    e, _ = unit_vectors(member_vectors(X, conn))                  # (nt, m, 3)
    # Dense B on all coordinates, (nt, m, n*3), then the free columns.
    B = np.zeros((nt, m, n, 3))
    rows = np.arange(m)
    B[:, rows, conn[:, 1]] += e
    B[:, rows, conn[:, 0]] -= e
    cols = np.flatnonzero(free.ravel())
    Bf = B.reshape(nt, m, n * 3)[:, :, cols]
    if Bf.shape[1] != Bf.shape[2]:
        raise AnalysisError(item, "the bay is not statically determinate "
                            f"({m} members, {cols.size} free coordinates)")
    cond = np.linalg.cond(Bf)
    if np.any(cond > 1e12):
        k = int(np.argmax(cond > 1e12))
        raise AnalysisError(item(k) if callable(item) else f"{item}: step {k}",
                            "the bay passes a singular position")
    V = np.zeros((nt, n * 3))
    V[:, cols] = np.linalg.solve(Bf, Ld[..., None])[..., 0]
    V = V.reshape(nt, n, 3)
    vrel = member_vectors(V, conn)
    rhs = Ldd - (np.einsum("tmk,tmk->tm", vrel, vrel) - Ld ** 2) / L
    A = np.zeros((nt, n * 3))
    A[:, cols] = np.linalg.solve(Bf, rhs[..., None])[..., 0]
    return X, V, A.reshape(nt, n, 3)


def stack_bays(bay: Structure, n_bays: int) -> Structure:
    """A chain of ``n_bays`` copies of ``bay`` stacked top plane to base (Lacy Fig. 6.1).

    Nodes: the three base nodes, then six per bay (midplane N4–N6, top N7–N9) with ids
    ``N4.k`` … ``N9.k`` (k = 1…n); members ``<id>.k``; active members carry the bay's data.
    Each bay is placed with :func:`triangle_frame` of the previous top plane, so a bay that is
    not at a symmetric position stacks as its rigid copy.
    """
    if n_bays < 1:
        raise AnalysisError("n_bays", f"must be at least 1, got {n_bays}")
    x = bay.coords
    o_b, R_b = triangle_frame(x[:3])
    local = (x - o_b) @ R_b                                       # template in its base frame
    coords = [x[:3]]
    node_ids = list(bay.node_ids[:3])
    base_idx = np.array([0, 1, 2])
    conn, mids = [], []
    for k in range(1, n_bays + 1):
        o, R = triangle_frame(np.vstack(coords)[base_idx])
        new = o + local[3:] @ R.T
        start = sum(c.shape[0] for c in coords)
        coords.append(new)
        node_ids += [f"{nid}.{k}" for nid in bay.node_ids[3:]]
        idx = np.concatenate([base_idx, start + np.arange(6)])
        conn.append(idx[bay.connectivity])
        mids += [f"{mid}.{k}" for mid in bay.member_ids]
        base_idx = idx[list(TOP_AS_NEXT_BASE)]
    X = np.vstack(coords)
    s = build_structure(X, np.vstack(conn), section=bay.sections[0], material=bay.materials[0],
                        supports={i: "xyz" for i in range(3)}, node_ids=node_ids,
                        member_ids=mids, name=f"{n_bays}-bay chain of {bay.name}")
    m = bay.n_members
    return s.with_extensions(active_members=[
        ActiveMember(member=a.member + k * m, base_mass=a.base_mass, base_length=a.base_length,
                     base_cg=a.base_cg, base_inertia=a.base_inertia, tube_length=a.tube_length)
        for k in range(n_bays) for a in active_members(bay)])


def chain_kinematics(bay: Structure, lengths: np.ndarray, rates: np.ndarray,
                     accs: np.ndarray, next_base: tuple[int, int, int] = TOP_AS_NEXT_BASE
                     ) -> ChainKinematics:
    """Kinematics of a stacked chain, bay by bay in bay-fixed frames (Lacy eqs. 6.1–6.13).

    Parameters
    ----------
    bay : Structure
        The bay template (as passed to :func:`stack_bays`): base nodes 0–2 (supported), then
        the bay's six own nodes.
    lengths, rates, accs : ndarray, shape (nt, n_bays, n_active)
        Active lengths and rates of every bay (columns in the bay's active-member order).
    next_base : tuple of int
        Template nodes (among 3–8) that are the next bay's base nodes 0, 1, 2 (Lacy §6.2:
        N7, N9, N8 for the double-octahedral bay).

    Returns
    -------
    ChainKinematics
        Nodes in the numbering of :func:`stack_bays`.
    """
    nt, nb, _ = lengths.shape
    o_b, R_b = triangle_frame(bay.coords[:3])
    n = 3 + 6 * nb
    X = np.empty((nt, n, 3))
    V = np.empty((nt, n, 3))
    A = np.empty((nt, n, 3))
    X[:, :3] = bay.coords[:3]
    V[:, :3] = 0.0
    A[:, :3] = 0.0
    fr = {k: np.empty((nt, nb, 3)) for k in ("o", "vo", "ao", "w", "al")}
    rot = np.empty((nt, nb, 3, 3))
    base_idx = np.array([0, 1, 2])
    # Every bay alone, all bays and steps at once (they are independent problems of the same
    # bay, :func:`bay_positions`).
    Lall = _all_lengths(bay, lengths.transpose(1, 0, 2).reshape(nb * nt, -1)
                        ).reshape(nb, nt, -1)
    Xall = bay_positions(bay, Lall, item="bay")
    nn = bay.n_nodes
    P, Pd, Pdd = _bay_rates(bay, Lall.reshape(nb * nt, -1),
                            rates.transpose(1, 0, 2).reshape(nb * nt, -1),
                            accs.transpose(1, 0, 2).reshape(nb * nt, -1),
                            Xall.reshape(nb * nt, nn, 3),
                            item=lambda j: f"bay {j // nt + 1}: step {j % nt}")
    # Bay-local coordinates relative to the template's base frame, (nb, nt, n, 3).
    P = ((P - o_b) @ R_b).reshape(nb, nt, nn, 3)
    Pd = (Pd @ R_b).reshape(nb, nt, nn, 3)
    Pdd = (Pdd @ R_b).reshape(nb, nt, nn, 3)
    for k in range(nb):
        p, pd, pdd = P[k], Pd[k], Pdd[k]
        xb, vb, ab = X[:, base_idx], V[:, base_idx], A[:, base_idx]
        o, R = triangle_frame(xb)                                    # eqs. 6.2, 6.6
        vo, ao, w, al = rigid_rates(xb, vb, ab)                      # eqs. 6.8, 6.13
        r = np.einsum("tij,tnj->tni", R, p[:, 3:])                   # R p, (nt, 6, 3)
        rv = np.einsum("tij,tnj->tni", R, pd[:, 3:])
        ra = np.einsum("tij,tnj->tni", R, pdd[:, 3:])
        wn = w[:, None, :]
        sl = slice(3 + 6 * k, 9 + 6 * k)
        X[:, sl] = o[:, None, :] + r                                 # eq. 6.3
        V[:, sl] = vo[:, None, :] + cross(wn, r) + rv            # eq. 6.7
        A[:, sl] = (ao[:, None, :] + cross(al[:, None, :], r)    # eq. 6.11
                    + cross(wn, cross(wn, r)) + 2 * cross(wn, rv) + ra)
        fr["o"][:, k], fr["vo"][:, k], fr["ao"][:, k] = o, vo, ao
        fr["w"][:, k], fr["al"][:, k] = w, al
        rot[:, k] = R
        top = np.array([3 + 6 * k + j - 3 for j in next_base])
        base_idx = top
    frames = BayFrames(origin=fr["o"], origin_velocity=fr["vo"], origin_acceleration=fr["ao"],
                       rotation=rot, omega=fr["w"], alpha=fr["al"])
    return ChainKinematics(coords=X, velocity=V, acceleration=A, frames=frames)


def thesis_angular_acceleration(frames: BayFrames) -> np.ndarray:
    """Angular acceleration of every bay frame by Lacy's eq. 6.14 (sum of relative ones).

    The relative angular velocity of bay n's frame with respect to bay n−1's is
    ``ω_n − ω_{n−1}`` (eq. 6.9 is exact); its rate seen from frame n−1 is
    ``α_n − α_{n−1} − ω_{n−1} × (ω_n − ω_{n−1})``.  Summing these rates as eq. 6.14 does gives
    ``α_n − Σ_j ω_{j−1} × (ω_j − ω_{j−1})``: the returned array, (nt, nb, 3), differs from the
    true ``frames.alpha`` by that sum.

    The sum vanishes when every ω is parallel — identical bays tilting about one fixed axis,
    as in the chapter's own example (eq. 6.14 exact there to 5e-13) — and not otherwise: on a
    3-bay chain whose nine actuators move by different amounts (0.01–0.06 m in 2 s) eq. 6.14
    is off by 3.3 % of the peak angular acceleration for bay 3's frame and by 11.1 % for the
    chain's top plane (:func:`trussfe.studies.lacy_chain.equation_6_14`).
    """
    w, al = frames.omega, frames.alpha
    wprev = np.concatenate([np.zeros_like(w[:, :1]), w[:, :-1]], axis=1)
    alprev = np.concatenate([np.zeros_like(al[:, :1]), al[:, :-1]], axis=1)
    rel_rate = al - alprev - cross(wprev, w - wprev)
    return np.cumsum(rel_rate, axis=1)


def kinematics_from_nodes(structure: Structure, time: np.ndarray, X: np.ndarray, V: np.ndarray,
                          A: np.ndarray, length_rate: np.ndarray, length_acc: np.ndarray):
    """Member kinematics (unit vectors, their rates, ω, α) from node fields (nt, n, 3).

    The node fields may include moving supports (a bay's base inside a chain): ``ė = (v_b − v_a
    − L̇ e)/L``, ``ë = (a_b − a_a − L̈ e)/L − 2 L̇ ė / L``, ``ω = e × ė``, ``α = e × ë``.
    """
    from .kinematics import Kinematics

    conn = structure.connectivity
    e, L = unit_vectors(member_vectors(X, conn))
    vrel = member_vectors(V, conn)
    arel = member_vectors(A, conn)
    Ld, Ldd = length_rate[..., None], length_acc[..., None]
    ed = (vrel - Ld * e) / L[..., None]
    edd = (arel - Ldd * e) / L[..., None] - 2 * Ld * ed / L[..., None]
    return Kinematics(time=np.asarray(time, dtype=float), coords=X, velocity=V, acceleration=A,
                      length=L, length_rate=length_rate, length_acc=length_acc, unit=e,
                      unit_rate=ed, unit_acc=edd, omega=cross(e, ed), alpha=cross(e, edd),
                      scheme="exact")


@dataclass
class ChainForces:
    """Forces of a chain found bay by bay.

    Attributes
    ----------
    tension_end : ndarray, shape (nt, n_bays * 18)
        Axial force at each member's end node (positive in tension), chain member order.
    base_reactions : ndarray, shape (nt, n_bays, 3 nodes, 3)
        Reaction on the base nodes of every bay (the force its base plane receives).
    """

    tension_end: np.ndarray
    base_reactions: np.ndarray


def chain_forces(bay: Structure, time: np.ndarray, lengths: np.ndarray, rates: np.ndarray,
                 accs: np.ndarray, top_loads: np.ndarray | None = None) -> ChainForces:
    """Nodal forces of a chain by Lacy's bay-by-bay method (chapter 6): top bay first, each
    bay's base reactions applied, reversed, to the top plane of the bay below.

    The chain is stacked from ``bay`` (:func:`stack_bays`), its positions are found bay by
    bay (:func:`chain_positions`), and the forces by the rigid-body force model of the
    whole chain, whose equilibrium matrix is block triangular with one block per plane: the
    back substitution ``Bᵀ t = f`` runs from the top bay down and passes each bay's base
    reactions to the bay below — the recursion of §6.2, in O(n) per step, batched over the
    steps (the same code as ``simulate``).

    Parameters
    ----------
    bay : Structure
        Bay template (its gravity, sections and materials are used; its loads and masses
        are ignored).
    time : ndarray, shape (nt,)
    lengths, rates, accs : ndarray, shape (nt, n_bays, n_active)
    top_loads : ndarray, shape (3, 3), optional
        External forces on the top bay's N7, N8, N9, N.

    Returns
    -------
    ChainForces
    """
    from .forces import member_bodies, nodal_forces
    from .kinematics import compute_kinematics
    from .motion import Motion

    nt, nb, _ = lengths.shape
    m = bay.n_members
    chain = stack_bays(bay, nb).with_gravity(bay.gravity)
    chain = chain.variant(sections=tuple(bay.sections) * nb,
                          materials=tuple(bay.materials) * nb)
    if top_loads is not None:
        loads = np.array(chain.loads)
        loads[3 + 6 * (nb - 1) + np.arange(3, 6), :3] = top_loads      # N7, N8, N9 of bay nb
        chain = chain.with_loads(loads)
    acts = np.array([a.member for a in active_members(chain)], dtype=np.int64)
    motion = Motion(np.asarray(time, dtype=float), acts, lengths.reshape(nt, -1),
                    rates.reshape(nt, -1), accs.reshape(nt, -1), source="chain")
    kin = compute_kinematics(chain, motion, coords=chain_positions(bay, lengths))
    f = nodal_forces(chain, kin, member_bodies(chain))
    # Base reactions of every bay: the forces its base nodes exert on its members.
    conn = chain.connectivity
    bay_of = np.repeat(np.arange(nb), m)
    base = np.empty((nb, 3), dtype=np.int64)
    base[0] = [0, 1, 2]
    base[1:] = (3 + 6 * np.arange(nb - 1))[:, None] + np.asarray(TOP_AS_NEXT_BASE) - 3
    j, e, i = np.nonzero(conn[:, :, None] == base[bay_of][:, None, :])
    react = np.zeros((nt, nb * 3, 3))
    np.add.at(react, (slice(None), bay_of[j] * 3 + i), f.end_force[:, j, e])
    return ChainForces(tension_end=f.tension_end, base_reactions=react.reshape(nt, nb, 3, 3))
