# SPDX-License-Identifier: MIT
"""Hortobágyi (1999) §8, Fig. 11: over one period of the compound mechanism the end points of the
connecting bar travel their trajectories twice.

The assembly is the section-8 construction (:func:`trussfe.models.mechanisms.section8_compound`):
two Watt linkages joined by a horizontal bar between their coupler midpoints.  From the
symmetric state it moves downward only; traced on (Hortobágyi's algorithm, the fastest
coordinate independent after each limit point) the motion runs once round its loop and comes
back to the symmetric state from below, where it cannot go on upward: that is one period.
Each end point's path then covers its trajectory twice — a closed part is travelled round twice,
an arc to and fro — so every point of the trajectory, away from its self-crossing and its
turning points, is passed exactly twice.
"""
from __future__ import annotations

import numpy as np

from ..kinematics.trace import trace_mechanism
from ..mechanics.geometry import member_lengths
from ..models.mechanisms import CATALOGUE

#: Steps of 0.02 m from the symmetric state back to it (the trace stops there: no upward motion).
PERIOD_STEPS = 614
#: Connecting-bar end points (coupler midpoints M of the left and right linkage).
END_POINTS = {"left": 4, "right": 10}


def passes(path: np.ndarray, point: np.ndarray, radius: float) -> int:
    """Number of separate visits of ``path`` (shape (k, 2)) to the disc of ``radius`` about
    ``point``: the entries into it."""
    inside = np.linalg.norm(path - point, axis=1) < radius
    return int(np.sum(inside[1:] & ~inside[:-1]) + inside[0])


def trajectory_passes(path: np.ndarray, radius: float, every: int = 3) -> dict[int, int]:
    """How often the path passes each of its own points, sampled every ``every`` states.

    Points within 3·radius of the start (the trajectory's self-crossing at the symmetric state)
    or of a turning point of the path (where the motion reverses, the two passes merge into
    one visit) are left out.  Returns ``{number of passes: number of sampled points}``.
    """
    v = np.diff(path, axis=0)
    turns = [k + 1 for k in range(len(v) - 1) if v[k] @ v[k + 1] < 0]
    excluded = np.array([path[0]] + [path[k] for k in turns])
    counts: dict[int, int] = {}
    for s in range(every, len(path) - every, every):
        if np.min(np.linalg.norm(excluded - path[s], axis=1)) < 3 * radius:
            continue
        c = passes(path, path[s], radius)
        counts[c] = counts.get(c, 0) + 1
    return counts


def hortobagyi_section8_period(radius: float = 0.04) -> dict:
    """One period of the section-8 construction and the passes of the connecting bar's ends.

    Returns
    -------
    dict
        ``return_distance`` (m, the largest joint distance between the last state and the
        symmetric start state, against a step of 0.02 m), ``misfit`` (bar lengths along the
        period, m), ``limit_points``; per end point (``left``, ``right``) ``points`` sampled,
        ``twice`` (how many of them are passed exactly twice), ``other`` (passed another number
        of times) and ``mirror`` (m, the largest distance of the right end's trajectory from
        the mirror image of the left end's).
    """
    e = CATALOGUE["mech_sec8_compound"]
    t = trace_mechanism(e.coords, e.bars, e.free, [e.drive_index()], e.step, PERIOD_STEPS)
    x = t.coords
    out: dict = {
        "return_distance": float(np.max(np.linalg.norm(x[-1] - x[0], axis=1))),
        "misfit": float(np.max(np.abs(member_lengths(x, e.bars) - member_lengths(e.coords,
                                                                                  e.bars)))),
        "limit_points": sum(ev["kind"] == "limit_point" for ev in t.events)}
    for side, node in END_POINTS.items():
        c = trajectory_passes(x[:, node], radius)
        out[side] = {"points": sum(c.values()), "twice": c.get(2, 0),
                     "other": sum(v for k, v in c.items() if k != 2)}
    left = x[:, END_POINTS["left"]] * [-1.0, 1.0]
    right = x[:, END_POINTS["right"]]
    out["right"]["mirror"] = float(np.max(np.min(
        np.linalg.norm(right[:, None, :] - left[None, :, :], axis=2), axis=1)))
    return out
