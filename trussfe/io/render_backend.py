# SPDX-License-Identifier: MIT
"""Which off-screen renderer works here: pyvista (VTK, OpenGL) or matplotlib (Agg).

pyvista renders off-screen when an OpenGL context can be created (EGL, OSMesa or X).  Whether
it can is probed once per process in a child process, so a missing or broken OpenGL library
can never crash or hang the caller; ``TRUSSFE_PLOT_BACKEND`` (``pyvista`` or ``matplotlib``)
overrides the probe.  Every picture trussfe renders (model pictures, report figures) asks here.
"""
from __future__ import annotations

import functools
import logging
import os
import subprocess
import sys

log = logging.getLogger(__name__)

__all__ = ["plot_backend"]

_PROBE = ("import pyvista as pv\n"
          "p = pv.Plotter(off_screen=True, window_size=(32, 32))\n"
          "p.add_mesh(pv.Line())\n"
          "img = p.screenshot(return_img=True)\n"
          "p.close()\n"
          "assert img.shape[:2] == (32, 32)\n")


@functools.lru_cache(maxsize=1)
def _vtk_can_render() -> bool:
    try:
        r = subprocess.run([sys.executable, "-c", _PROBE], capture_output=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return False
    if r.returncode != 0:
        log.info("pyvista cannot render off-screen here; using matplotlib (%s)",
                 r.stderr.decode(errors="replace").strip().splitlines()[-1:] or "")
    return r.returncode == 0


def plot_backend() -> str:
    """``"pyvista"`` when VTK can render off-screen here, else ``"matplotlib"``.

    ``TRUSSFE_PLOT_BACKEND`` (``pyvista`` or ``matplotlib``) overrides the probe.

    Returns
    -------
    str
    """
    forced = os.environ.get("TRUSSFE_PLOT_BACKEND", "").strip().lower()
    if forced in ("pyvista", "matplotlib"):
        return forced
    return "pyvista" if _vtk_can_render() else "matplotlib"
