# SPDX-License-Identifier: MIT
"""Global equilibrium of a static result, checked from the model's own data.

The applied loads are taken from the structure (nodal forces and moments, the weight of every
member at its midpoint, the weight of every nodal mass), not from the FE load vector, so that
a load or reaction lost in the discretisation (a hidden support, a dropped moment) shows.
Source: statics — the resultant force and the resultant moment about the origin of the loads
and reactions of a body at rest are zero.
"""
from __future__ import annotations

import numpy as np


def resultants(structure, reactions: np.ndarray, loads: np.ndarray | None = None,
               gravity: np.ndarray | None = None, self_weight: bool = True):
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
        w = (s.density * s.area * s.lengths())[:, None] * g[None, :]       # member weights
        mid = 0.5 * (X[s.connectivity[:, 0]] + X[s.connectivity[:, 1]])
        forces += [w, s.masses[:, None] * g[None, :]]
        points += [mid, X]
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
