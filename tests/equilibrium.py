# SPDX-License-Identifier: MIT
"""Global equilibrium of a static result, checked from the model's own data.

The applied loads are taken from the structure (nodal forces and moments, the weight of every
member at its centre of gravity — an active member's base and leadscrew tube — and of every
nodal mass), not from the FE load vector, so that
a load or reaction lost in the discretisation (a hidden support, a dropped moment) shows.
Loads along members (``member_loads``) are replaced by their statically equivalent forces and
couples, computed here from the load data alone.
Source: statics — the resultant force and the resultant moment about the origin of the loads
and reactions of a body at rest are zero.
"""
from __future__ import annotations

import numpy as np


def member_load_resultants(structure, member_loads):
    """Forces, their points of application and couples (global axes) that are statically
    equivalent to the member loads: a linearly varying load ``q₁ → q₂`` over a member of
    length L from ``X_a`` along ``e`` is the force ``(q₁ + q₂)L/2`` with the moment
    ``X_a × F + e × (q₁L²/6 + q₂L²/3)`` about the origin (∫ s q(s) ds), written as the force
    at ``X_a`` plus that couple (on a span ``[c, d]`` of length ℓ: ``(q₁ + q₂)ℓ/2`` and
    ``c F + q₁ℓ²/6 + q₂ℓ²/3``); a point load is its force at ``X_a + aLe`` and its couple."""
    from trussfe.mechanics.geometry import local_axes
    s = structure
    dim = s.dim
    X = s.coords
    forces, points, couples = [], [], []
    if not member_loads:
        return forces, points, couples
    R = local_axes(s)
    L = s.lengths()
    e = s.unit_vectors()
    for ld in member_loads:
        i = ld.member
        Xa = X[s.connectivity[i, 0]]
        glob = (lambda v: np.asarray(v, float)) if ld.axes == "global" else \
            (lambda v: R[i].T @ np.asarray(v, float))
        if ld.kind == "point":
            if ld.force:
                forces.append(glob(ld.force)[None])
                points.append((Xa + ld.at * L[i] * e[i])[None])
            if ld.moment:
                c = np.asarray(ld.moment, float)
                c = c if dim == 2 else glob(c)
                couples.append(c[None])
            continue
        q1, q2 = glob(ld.q_start), glob(ld.q_end)
        c, d = ld.span[0] * L[i], ld.span[1] * L[i]               # the loaded part
        ell = d - c
        F = 0.5 * (q1 + q2) * ell
        first = c * F + q1 * ell ** 2 / 6 + q2 * ell ** 2 / 3      # ∫ s q(s) ds over [c, d]
        forces.append(F[None])
        points.append(Xa[None])
        if dim == 2:
            couples.append(np.array([[e[i, 0] * first[1] - e[i, 1] * first[0]]]))
        else:
            couples.append(np.cross(e[i], first)[None])
    return forces, points, couples


def member_masses(structure):
    """Mass and centre of gravity of every member: a uniform member ρAL at its midpoint; an
    active member its base (``base_mass`` at ``base_cg`` from the start node) and its
    leadscrew tube (ρA·tube_length centred tube_length/2 from the end node), from the model
    data by hand (docs/model-format.md, ``[active_members]``)."""
    s = structure
    X = s.coords
    a, b = X[s.connectivity[:, 0]], X[s.connectivity[:, 1]]
    L = s.lengths()
    mass = s.density * s.area * L
    cg = 0.5 * (a + b)
    for act in s.extensions.get("active_members", ()):
        j = act.member
        e = (b[j] - a[j]) / L[j]
        tube = s.density[j] * s.area[j] * act.tube_length
        mass[j] = act.base_mass + tube
        cg[j] = (act.base_mass * (a[j] + act.base_cg * e)
                 + tube * (b[j] - 0.5 * act.tube_length * e)) / mass[j]
    return mass, cg


def resultants(structure, reactions: np.ndarray, loads: np.ndarray | None = None,
               gravity: np.ndarray | None = None, self_weight: bool = True,
               member_loads=None):
    """Resultant force and moment about the origin of loads + reactions (+ self-weight).

    Returns ``(force, moment, force_scale, moment_scale)``; the scales are the sums of the
    magnitudes of the contributions (the moment scale at least the force scale times the
    largest distance from the origin), so a relative test does not depend on the units.
    """
    s = structure
    dim = s.dim
    P = s.loads if loads is None else np.asarray(loads, dtype=float)
    R = np.asarray(reactions, dtype=float)
    X = s.coords
    g = s.gravity if gravity is None else np.asarray(gravity, dtype=float)
    forces = [P[:, :dim], R[:, :dim]]
    points = [X, X]
    couples = [P[:, dim:], R[:, dim:]]
    if self_weight and np.any(g):
        mass, cg = member_masses(s)
        forces += [mass[:, None] * g[None, :], s.masses[:, None] * g[None, :]]
        points += [cg, X]
    ml = s.extensions.get("member_loads", ()) if member_loads is None else member_loads
    mf, mp, mc = member_load_resultants(s, ml)
    forces += mf
    points += mp
    couples += mc
    F = sum(f.sum(axis=0) for f in forces)
    fscale = sum(np.abs(f).sum() for f in forces)
    if dim == 2:
        mom = [x[:, 0] * f[:, 1] - x[:, 1] * f[:, 0] for x, f in zip(points, forces)]
        M = sum(mm.sum() for mm in mom) + sum(c[:, 0].sum() for c in couples)
        mscale = sum(np.abs(mm).sum() for mm in mom) + sum(np.abs(c).sum() for c in couples)
    else:
        mom = [np.cross(x, f) for x, f in zip(points, forces)]
        M = sum(mm.sum(axis=0) for mm in mom) + sum(c.sum(axis=0) for c in couples)
        mscale = sum(np.abs(mm).sum() for mm in mom) + sum(np.abs(c).sum() for c in couples)
    # the round-off of a moment about the origin is that of force × distance, even where the
    # forces pass through the origin and the moments themselves vanish
    mscale = max(mscale, fscale * float(np.abs(X).max(initial=0.0)))
    return np.atleast_1d(F), np.atleast_1d(M), fscale, mscale


def assert_global_equilibrium(result, rtol: float = 1e-8, force_scale: float = 0.0,
                              **kw) -> None:
    """Assert that a static result (anything with ``structure`` and ``reactions``, e.g.
    :class:`~trussfe.fem.static.StaticResult`) is in global equilibrium: forces and moments
    about the origin of loads, self-weight and reactions sum to zero to ``rtol`` of the
    magnitudes involved.

    ``force_scale`` is a lower bound of the force magnitudes for the relative test: the
    forces a case sets up without external load (an imposed strain, a moved support) leave
    reactions of round-off size only when the structure can take them up freely (a
    statically determinate one), and their round-off is that of the internal forces."""
    s = kw.pop("structure", None) or result.structure
    F, M, fs, ms = resultants(s, result.reactions, **kw)
    fs = max(fs, force_scale)
    ms = max(ms, force_scale * float(np.abs(s.coords).max(initial=0.0)))
    tiny = np.finfo(float).tiny
    assert np.all(np.abs(F) <= rtol * max(fs, tiny)), \
        f"force resultant {F} not zero (scale {fs:.3e})"
    assert np.all(np.abs(M) <= rtol * max(ms, tiny)), \
        f"moment resultant about the origin {M} not zero (scale {ms:.3e})"
