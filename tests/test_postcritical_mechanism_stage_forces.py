# SPDX-License-Identifier: MIT
"""Member forces along the mechanism stage of a post-critical path (the dome of
``meshes/postcritical_dome.toml``: four apex bars fail by buckling, the apex is left on two
bars and swings down to its hanging equilibrium form).

Between the hand-over and the equilibrium form the remaining bars move as a mechanism, not
in equilibrium, so their forces have no value (NaN, which ParaView shows as "no value");
removed bars carry nothing (0); at the equilibrium form the forces are the mechanism's
equilibrium tensions, and with the loads they are in equilibrium at every free joint
(statics of the deformed pin-jointed truss, computed here from the positions).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

import trussfe

MODEL = Path(__file__).resolve().parents[1] / "meshes" / "postcritical_dome.toml"


def test_forces_between_hand_over_and_equilibrium_form_have_no_value():
    r = trussfe.postcritical(MODEL)
    path = r.solution.path
    stages = [p.stage for p in path]
    mech = [i for i, st in enumerate(stages) if st == "mechanism"]
    assert mech and [e.kind for e in r.events][-1] == "equilibrium_form"
    for i in mech[:-1]:
        alive = path[i].alive
        assert np.all(np.isnan(r.axial_force[i, alive]))
        assert np.all(r.axial_force[i, ~alive] == 0.0)
    last = mech[-1]
    N = r.axial_force[last]
    assert np.all(np.isfinite(N))
    # joint equilibrium at the equilibrium form: Σ N e + λ P = 0 at every free DOF
    s = r.structure
    x = s.coords + r.displacement[last]
    a, b = s.connectivity.T
    e = (x[b] - x[a]) / np.linalg.norm(x[b] - x[a], axis=1)[:, None]
    f = np.zeros_like(x)
    np.add.at(f, a, N[:, None] * e)
    np.add.at(f, b, -N[:, None] * e)
    f += path[last].load_factor * s.loads[:, : s.dim]
    free = ~s.supports[:, : s.dim]
    assert np.abs(f[free]).max() <= 1e-6 * np.abs(N).max()
