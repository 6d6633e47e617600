# SPDX-License-Identifier: MIT
"""Lack of fit in the double-octahedral bay: the forces an actuator locks in when it is
commanded off the length its neighbours give it.

The bay of Lacy (1991), Appendix D, pinned at its base N1–N3, has 18 free DOFs and 21
members: it is statically indeterminate to degree 3.  Commanding the active member M7/8 δ
longer than the geometry gives it is a length error δ; the forces it sets up are computed two
independent ways:

* the displacement method of trussfe (``trussfe static`` with a ``length_error`` load case,
  the axial fixed-end force of :mod:`trussfe.mechanics.imposed_strain`);
* the force method: the states of self-stress ``S`` (null space of the equilibrium matrix,
  by SVD), and compatibility of the member elongations, ``Sᵀ (F N + e0) = 0`` with
  ``F = diag(L/EA)`` and ``e0`` the length errors, so ``N = −S (SᵀFS)⁻¹ Sᵀ e0``
  (Pellegrino & Calladine 1986, the force method for pin-jointed assemblies).
"""
from __future__ import annotations

import numpy as np

from ..api import static
from ..model.load_cases import LoadCase, LoadCases
from ..models import double_octahedron


def force_method_forces(structure, length_error: np.ndarray) -> tuple[np.ndarray, int]:
    """Member forces set up by length errors in a pin-jointed structure, by the force method.

    Parameters
    ----------
    structure : Structure
        Pin-jointed, without springs.
    length_error : ndarray, shape (m,)
        Stress-free length minus geometric length of each member, m.

    Returns
    -------
    N : ndarray, shape (m,)
        Axial forces, N, tension positive.
    states : int
        Number of independent states of self-stress (degree of statical indeterminacy).
    """
    s = structure
    dim = s.dim
    e = s.unit_vectors()
    n, m = s.n_nodes, s.n_members
    # equilibrium matrix: a tension N pulls the start node towards the end (+e N) and the end
    # node back (−e N); rows are the node translations, the supported ones removed
    Aeq = np.zeros((n, dim, m))
    idx = np.arange(m)
    Aeq[s.connectivity[:, 0], :, idx] += e
    Aeq[s.connectivity[:, 1], :, idx] -= e
    free = ~s.supports[:, :dim]
    Aeq = Aeq[free]
    _, sv, Vt = np.linalg.svd(Aeq)
    rank = int(np.sum(sv > sv.max() * max(Aeq.shape) * np.finfo(float).eps))
    S = Vt[rank:].T                                       # (m, states)
    F = s.lengths() / (s.E * s.area)
    x = np.linalg.solve(S.T @ (F[:, None] * S), -(S.T @ length_error))
    return S @ x, S.shape[1]


def _lack_of_fit(bay, delta: float) -> tuple[dict, np.ndarray, int]:
    """Both routes on one bay: (the static document, force-method forces, states)."""
    error = np.zeros(bay.n_members)
    error[bay.member_index("M7_8")] = delta
    case = LoadCase("lack_of_fit", np.zeros_like(bay.loads), length_error=error)
    model = bay.with_extensions(load_cases=LoadCases(cases=(case,)))
    doc = static(model, case="lack_of_fit").to_dict()
    N_force, states = force_method_forces(bay, error)
    return doc, N_force, states


def double_octahedron_lack_of_fit(delta: float = 1.0e-3, step: float = 1.0e-6) -> dict:
    """The bay with M7/8 commanded ``delta`` off its length, free and with its top held.

    As built (base N1–N3 pinned), the bay is statically determinate (18 members, 18 free
    DOFs): the command moves the top and locks in no force; the motion is the derivative of
    the bay's position with respect to the M7/8 length (the catalogue's forward-position
    solver, central differences of ``step``) times ``delta``.  With the top N7–N9 pinned as
    well (a bay built between two stiff plates) it is indeterminate to degree 9 and the
    command locks in forces.

    Returns
    -------
    dict
        ``free``: ``members.ID.axial_force`` (N), ``max_force`` (N), ``states``,
        ``displacement.ID`` and ``kinematic.ID`` (m, the two routes' motions of the top nodes),
        ``motion_agreement`` (their largest difference over the largest motion);
        ``held``: ``members.ID.axial_force`` (displacement method, N),
        ``force_method.ID`` (N), ``agreement`` (the largest difference over the largest
        force), ``states``.
    """
    bay = double_octahedron()
    doc, N_force, states = _lack_of_fit(bay, delta)
    forces = np.array([v["axial_force"] for v in doc["members"].values()])
    L0 = bay.lengths()[bay.member_index("M7_8")]
    rest = bay.lengths()[[bay.member_index("M9_10"), bay.member_index("M11_12")]]
    up = double_octahedron((L0 + step, *rest)).coords
    down = double_octahedron((L0 - step, *rest)).coords
    kinematic = (up - down) / (2.0 * step) * delta
    u = np.array([doc["nodes"][nid]["displacement"] for nid in bay.node_ids])
    top = ["N7", "N8", "N9"]
    free = {
        "members": doc["members"],
        "max_force": float(np.abs(forces).max()),
        "force_method_max": float(np.abs(N_force).max()) if N_force.size else 0.0,
        "states": states,
        "displacement": {nid: u[bay.node_index(nid)].tolist() for nid in top},
        "kinematic": {nid: kinematic[bay.node_index(nid)].tolist() for nid in top},
        "motion_agreement": float(np.abs(u - kinematic).max() / np.abs(kinematic).max()),
    }
    supports = np.array(bay.supports)
    supports[[bay.node_index(n) for n in top], :3] = True
    held_bay = bay.with_supports(supports)
    doc, N_force, states = _lack_of_fit(held_bay, delta)
    N = np.array([doc["members"][mid]["axial_force"] for mid in bay.member_ids])
    held = {
        "members": doc["members"],
        "force_method": {mid: float(N_force[j]) for j, mid in enumerate(bay.member_ids)},
        "agreement": float(np.abs(N - N_force).max() / np.abs(N_force).max()),
        "states": states,
    }
    return {"free": free, "held": held}
