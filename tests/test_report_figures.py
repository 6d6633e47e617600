# SPDX-License-Identifier: MIT
"""Off-screen figures: both back ends write a PNG of the requested size that is not blank,
and the PNG shows the deformed structure where it should be (coloured pixels present)."""
from __future__ import annotations

import numpy as np
import pytest

from trussfe.fem.modal import solve_modes
from trussfe.studies.modal_buckling import double_octahedron
from trussfe.report_figures import plot_backend, render_modes, render_shape

plt = pytest.importorskip("matplotlib.pyplot")


def _img(path):
    return plt.imread(str(path))


@pytest.fixture(scope="module")
def bay_modes():
    s = double_octahedron()
    return s, solve_modes(s, count=2)


@pytest.mark.parametrize("backend", ["matplotlib", "pyvista"])
def test_render_modes(tmp_path, bay_modes, backend):
    if backend == "pyvista" and plot_backend() != "pyvista" \
            and not __import__("os").environ.get("TRUSSFE_PLOT_BACKEND"):
        pytest.skip("VTK cannot render off-screen on this machine")
    s, r = bay_modes
    p = render_modes(tmp_path / "m.png", s, r.node_shapes()[:, :, :3],
                     [f"mode {i + 1}" for i in range(2)], backend=backend,
                     window=(200, 150))
    img = _img(p)
    assert img.shape[0] == 150 and img.shape[1] == 400          # two panels side by side
    rgb = img[..., :3]
    assert rgb.std() > 0.01                                    # not blank
    # blue deformed members are drawn (tab:blue is (0.12, 0.47, 0.71))
    blue = (rgb[..., 2] > 0.5) & (rgb[..., 0] < 0.3)
    assert blue.sum() > 100
    assert [q.name for q in tmp_path.iterdir()] == ["m.png"]


def test_render_shape_coloured(tmp_path, bay_modes):
    s, r = bay_modes
    d = r.node_shapes()[0, :, :3]
    force = np.linspace(-1.0, 1.0, s.n_members)
    p = render_shape(tmp_path / "s.png", s, d, member_values=force, backend="matplotlib",
                     window=(300, 240))
    rgb = _img(p)[..., :3]
    assert rgb.shape[:2] == (240, 300)
    red = (rgb[..., 0] > 0.6) & (rgb[..., 2] < 0.4)            # tension end of coolwarm
    assert red.sum() > 20
