# SPDX-License-Identifier: MIT
"""Lacy (1991) chapter 6: chains of double-octahedral bays, bay by bay against direct.

:func:`bay_by_bay_chains` runs ``simulate`` with ``method="direct"`` (the whole chain as one
truss) and ``method="bay-by-bay"`` (§6.1–6.2, :mod:`trussfe.rigid.bays`) on chains of 1, 3,
10 and 50 bays along the chapter's own example motion, and :func:`equation_6_14` shows where
the thesis' eq. 6.14 (the angular acceleration of bay n's frame as the sum of the bays'
relative angular accelerations) differs from the exact one, and why.  The validation case
``validation/cases/rigid_chain_bay_by_bay.toml`` points at both.
"""
from __future__ import annotations

import math

import numpy as np

from .. import api
from ..rigid.bays import bay_lengths, chain_layout
from ..rigid.chain import (chain_kinematics, rigid_rates, thesis_angular_acceleration,
                           triangle_frame)
from ..rigid.motion import third_order_response
from ..rigid.slew import rotation_motion
from .lacy_rigid import EQUILIBRIUM_LENGTH, double_octahedral_chain, double_octahedron

#: Lacy §6.1's example: "10 degree, 10 degree rotation on a single bay" about n̂1 and n̂2,
#: read as the rotation vector (10°, 10°, 0): a tilt of 14.142° about (n̂1 + n̂2)/√2.
BAY_TILT_DEG = math.degrees(math.hypot(math.radians(10.0), math.radians(10.0)))


def chapter_6_motion(chain, tilt_deg: float, steps: int = 40, duration: float = 4.0):
    """Lacy §6.1's example motion: the chain's top plane tilts by ``tilt_deg`` about
    (n̂1 + n̂2)/√2, split equally over its bays (``[motion] type = "rotation"``,
    ``split_over_bays``); the thesis' 3-bay example is ``tilt_deg = 3 BAY_TILT_DEG``."""
    return rotation_motion({"type": "rotation", "axis": [1.0, 1.0, 0.0], "start": 0.0,
                            "end": tilt_deg, "duration": duration,
                            "steps": steps, "include_end": True, "split_over_bays": True},
                           chain)


def _rel(a: np.ndarray, b: np.ndarray) -> float:
    """Largest difference relative to the largest magnitude of ``a``."""
    return float(np.abs(a - b).max() / np.abs(a).max())


def bay_by_bay_chains(n_bays=(1, 3, 10, 50), steps: int = 40) -> dict:
    """Direct against bay-by-bay ``simulate`` on chains of double-octahedral bays.

    Each chain stands under gravity with 46 N down on its top nodes; its top plane turns by
    Lacy's single-bay (10°, 10°) — 14.142° about (n̂1 + n̂2)/√2 — split equally over its bays
    (:func:`chapter_6_motion`), in 4 s.  (A turn of n × (10°, 10°), the thesis' per-bay
    example on every chain, coils a 50-bay chain through 707°, where the warm-started
    forward-position solve of the direct method loses the assembly between steps.)

    Returns
    -------
    dict
        Per chain ``"<n>"``: the largest differences, relative to each field's largest
        value, of node positions, velocities, accelerations, member forces (along the motion
        and at rest), reactions, von Mises stresses and actuator forces; and the tilt of the
        chain's top plane at the end (degrees).
    """
    out = {}
    for nb in n_bays:
        chain = double_octahedral_chain(nb, top_load=-46.0, gravity=9.81)
        motion = chapter_6_motion(chain, BAY_TILT_DEG, steps)
        d = api.simulate(chain, motion=motion, method="direct").solution
        b = api.simulate(chain, motion=motion, method="bay-by-bay").solution
        top = [chain.node_index(f"b{nb}.N{i}") for i in (7, 8, 9)]
        x = d.kinematics.coords[-1, top]
        normal = np.cross(x[1] - x[0], x[2] - x[0])
        out[str(nb)] = {
            "position": _rel(d.kinematics.coords, b.kinematics.coords),
            "velocity": _rel(d.kinematics.velocity, b.kinematics.velocity),
            "acceleration": _rel(d.kinematics.acceleration, b.kinematics.acceleration),
            "axial_force": _rel(d.forces.tension_end, b.forces.tension_end),
            "static_axial_force": _rel(d.static_forces.tension_end,
                                       b.static_forces.tension_end),
            "reaction": _rel(d.forces.reactions, b.forces.reactions),
            "von_mises": _rel(d.stresses.von_mises, b.stresses.von_mises),
            "actuator_force": _rel(d.actuator_force, b.actuator_force),
            "top_tilt_deg": math.degrees(math.acos(abs(normal[2]) / np.linalg.norm(normal))),
        }
    return out


#: Unequal motion of a 3-bay chain: each active member of each bay moves by its own amount
#: (m) with the third-order profile in 2 s, so the bays turn about different axes.
UNEQUAL_AMPLITUDES = np.array([[0.05, -0.03, 0.01], [-0.04, 0.02, 0.06], [0.03, 0.05, -0.05]])


def _frame_rates_by_differences(t: np.ndarray, R: np.ndarray) -> tuple[np.ndarray, ...]:
    """Angular velocity and acceleration of frames ``R`` (nt, nb, 3, 3) by central
    differences, independent of the rigid-body solution: ``[ω]× = Ṙ Rᵀ``, ``α = ω̇``."""
    Rd = np.gradient(R, t, axis=0, edge_order=2)
    W = Rd @ np.swapaxes(R, -1, -2)
    w = 0.5 * np.stack([W[..., 2, 1] - W[..., 1, 2], W[..., 0, 2] - W[..., 2, 0],
                        W[..., 1, 0] - W[..., 0, 1]], axis=-1)
    return w, np.gradient(w, t, axis=0, edge_order=2)


def equation_6_14(samples: int = 2001) -> dict:
    """Lacy's eq. 6.14 against the exact angular acceleration of the bay frames.

    Eq. 6.14 adds the relative angular accelerations of the bays,
    ``α_n = Σ_k α_{k/k−1}``.  The rate of a relative angular velocity seen from the moving
    frame k−1 is ``α_k − α_{k−1} − ω_{k−1} × (ω_k − ω_{k−1})`` (the Coriolis theorem for
    angular velocity), so the sum misses ``Σ_k ω_{k−1} × ω_k``: nothing when every bay
    turns about the same axis, as in the chapter's example (identical bays tilting about a
    fixed axis), but not when the bays turn about different axes.

    Returns
    -------
    dict
        ``equal_split``: the largest |α(6.14) − α| over the largest |α| of the three bay
        frames of a 3-bay chain along the chapter's example; ``unequal``: the same along
        :data:`UNEQUAL_AMPLITUDES`, for bay 3's frame (the first that can differ) and for
        the chain's top plane; ``unequal_by_differences``: the same deviations with ω and
        α of the frames from central differences of their rotation matrices (an
        independent route); ``transport_misfit``: largest |α − α(6.14) − Σ ω_{k−1} × ω_k|
        over the largest |α|.
    """
    bay = double_octahedron()
    chain3 = double_octahedral_chain(3)
    layout = chain_layout(chain3)
    ck = chain_kinematics(layout.template, *bay_lengths(chain3, layout, chapter_6_motion(
        chain3, 3 * BAY_TILT_DEG, steps=200)), next_base=layout.next_base)
    al = ck.frames.alpha
    equal = float(np.abs(thesis_angular_acceleration(ck.frames) - al).max() / np.abs(al).max())

    t = np.linspace(0.0, 2.0, samples)
    y, dy, ddy = third_order_response(t, 2.0)
    amp = UNEQUAL_AMPLITUDES
    ck = chain_kinematics(bay, EQUILIBRIUM_LENGTH + y[:, None, None] * amp,
                          dy[:, None, None] * amp, ddy[:, None, None] * amp)
    f = ck.frames
    # Frames of the three bases and of the chain's top plane: bay 3's N7, N9, N8, nodes
    # 3 + 6·2 + (6, 8, 7) − 3 of the stacked numbering.
    top = [3 + 6 * 2 + j - 3 for j in (6, 8, 7)]
    _, Rtop = triangle_frame(ck.coords[:, top])
    _, _, wtop, altop = rigid_rates(ck.coords[:, top], ck.velocity[:, top],
                                    ck.acceleration[:, top])
    w = np.concatenate([f.omega, wtop[:, None]], axis=1)
    al = np.concatenate([f.alpha, altop[:, None]], axis=1)
    R = np.concatenate([f.rotation, Rtop[:, None]], axis=1)

    def eq614(w, al):
        wprev = np.concatenate([np.zeros_like(w[:, :1]), w[:, :-1]], axis=1)
        alprev = np.concatenate([np.zeros_like(al[:, :1]), al[:, :-1]], axis=1)
        return np.cumsum(al - alprev - np.cross(wprev, w - wprev), axis=1)

    def dev(w, al, k):
        return float(np.linalg.norm(eq614(w, al)[:, k] - al[:, k], axis=1).max()
                     / np.linalg.norm(al[:, k], axis=1).max())

    wfd, alfd = _frame_rates_by_differences(t, R)
    inner = slice(5, -5)
    wprev = np.concatenate([np.zeros_like(w[:, :1]), w[:, :-1]], axis=1)
    transport = np.cumsum(np.cross(wprev, w), axis=1)
    return {
        "equal_split": equal,
        "unequal": {"bay3_frame": dev(w, al, 2), "top_plane": dev(w, al, 3)},
        "unequal_by_differences": {"bay3_frame": dev(wfd[inner], alfd[inner], 2),
                                   "top_plane": dev(wfd[inner], alfd[inner], 3)},
        "transport_misfit": float(np.abs(al - eq614(w, al) - transport).max()
                                  / np.abs(al).max()),
        "omega_by_differences": _rel(w[inner], wfd[inner]),
    }


def validation_chains() -> dict:
    """The validation case ``rigid-chain-bay-by-bay``: ``bays`` from
    :func:`bay_by_bay_chains`, ``eq_6_14`` from :func:`equation_6_14`."""
    return {"bays": bay_by_bay_chains(), "eq_6_14": equation_6_14()}
