# SPDX-License-Identifier: MIT
"""The ParaView script ``examples/paraview/open_results.py`` renders trussfe's VTK output
under ``pvbatch``: a static ``.vtu`` warped and coloured by axial force, and a ``.pvd``
series.  Skipped where ParaView is not installed or cannot open a render window.

Source of the expected picture: both members of Lacy's triangular truss are in compression
(Lacy Table 3.2: -78.5429 N and -27.49 N), so the warped members are drawn in the blue half of
the symmetric blue-white-red map, over the undeformed model in grey.
"""
from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from trussfe.cli import main

ROOT = Path(__file__).resolve().parents[1]
SCRIPT = ROOT / "examples" / "paraview" / "open_results.py"
image = pytest.importorskip("matplotlib.image")

PVBATCH = shutil.which("pvbatch")
pytestmark = pytest.mark.skipif(PVBATCH is None, reason="ParaView (pvbatch) is not installed")


def _runner(tmp: Path) -> list[str]:
    """How to start pvbatch here: directly, or inside a virtual X server when the ParaView
    build needs a display and none is set.  Skip when neither can render."""
    probe = tmp / "probe.py"
    probe.write_text("from paraview import simple as pv\n"
                     "pv.Show(pv.Sphere())\n"
                     f"pv.SaveScreenshot({str(tmp / 'probe.png')!r}, ImageResolution=[64, 64])\n")
    candidates = [[PVBATCH]]
    if shutil.which("xvfb-run"):
        candidates.append(["xvfb-run", "-a", "-s", "-screen 0 1600x1200x24", PVBATCH])
    for cmd in candidates:
        try:
            r = subprocess.run([*cmd, str(probe)], capture_output=True, timeout=300)
        except (OSError, subprocess.TimeoutExpired):
            continue
        if r.returncode == 0 and (tmp / "probe.png").is_file():
            return cmd
    pytest.skip("pvbatch cannot open a render window on this machine")


@pytest.fixture(scope="module")
def pvbatch(tmp_path_factory):
    return _runner(tmp_path_factory.mktemp("pvprobe"))


def _render(pvbatch, target: Path, out: Path, *extra: str) -> np.ndarray:
    for _attempt in range(3):
        r = subprocess.run([*pvbatch, str(SCRIPT), str(target), "--png", str(out),
                            "--size", "640x480", *extra], capture_output=True, text=True,
                           timeout=600, env={**os.environ})
        # a virtual X server that is not ready makes ParaView abort while it creates its
        # render view, before the script has run: start it again (the machine, not the script)
        if r.returncode == 0 or "vtkPVRenderingCapabilitiesInformation" not in r.stderr:
            break
    assert r.returncode == 0, r.stderr[-2000:]
    assert out.is_file() and out.stat().st_size > 2000
    rgb = image.imread(str(out))[..., :3]
    assert rgb.shape == (480, 640, 3)
    return rgb


def test_static_vtu_warped_and_coloured_by_axial_force(pvbatch, tmp_path):
    vtu = tmp_path / "truss.vtu"
    assert main(["static", str(ROOT / "meshes" / "triangular_truss_static.toml"),
                 "--vtk", str(vtu)]) == 0
    rgb = _render(pvbatch, vtu, tmp_path / "truss.png")
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    blue = (b > 0.6) & (r < 0.6) & (b - r > 0.2)                 # compression members
    red = (r > 0.6) & (b < 0.5) & (r - b > 0.2)
    grey = (np.abs(r - g) < 0.03) & (np.abs(g - b) < 0.03) & (r > 0.6) & (r < 0.9)
    # the colour bar holds both halves of the map; the members only the blue one
    bar = np.zeros_like(blue)
    bar[:, int(0.8 * rgb.shape[1]):] = True
    assert (blue & ~bar).sum() > 300
    assert (red & ~bar).sum() < 0.05 * (blue & ~bar).sum()
    assert (grey & ~bar).sum() > 100                              # the undeformed model


def test_pvd_series_opens(pvbatch, tmp_path):
    out = tmp_path / "dome"
    assert main(["postcritical", str(ROOT / "meshes" / "postcritical_dome.toml"),
                 "--vtk", str(out)]) == 0
    series = out / "postcritical_dome_path.pvd"
    assert series.is_file()
    rgb = _render(pvbatch, series, tmp_path / "dome.png", "--step", "3")
    assert rgb.std() > 0.02
