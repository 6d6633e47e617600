# SPDX-License-Identifier: MIT
"""The linear buckling of the co-rotational model (trussfe.nonlinear.linear_buckling: its
tangent at the reference geometry) and of the FE core (trussfe.fem.buckling.solve_buckling:
K + λ K_g about the linear static state) are one eigenproblem: on trusses (2-D von Mises truss,
3-D dome) and on the dome's bars modelled as pinned beams their load factors agree to 1e-10.
Frames with every kind of end release: tests/test_releases.py."""
from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

from trussfe._resources import mesh_path
from trussfe.fem.buckling import solve_buckling
from trussfe.io.model_file import read_model
from trussfe.nonlinear import NonlinearModel, linear_buckling


# ``ask``: load factors asked of the FE core, which keeps the sign (the von Mises truss has
# one finite factor; the dome's smallest |λ| include negative ones)
@pytest.mark.parametrize("name, bar_model, count, ask", [
    ("postcritical_von_mises.toml", "truss", 1, 1),
    ("postcritical_dome.toml", "truss", 2, 6),
    ("postcritical_dome.toml", "pinned-beam", 2, 6),
])
def test_corotational_and_fe_core_linear_buckling_agree(name, bar_model, count, ask):
    s = read_model(mesh_path(name))
    core = solve_buckling(s, count=ask, bar_model=bar_model, subdivisions=4,
                          self_weight=False).load_factors
    core = np.sort(core[core > 0])[:count]
    corot = linear_buckling(NonlinearModel(s, bar_model=bar_model, subdivisions=4),
                            count=count)[0]
    assert len(core) == count
    assert_allclose(corot, core, rtol=1e-10)
