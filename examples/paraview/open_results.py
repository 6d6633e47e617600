# SPDX-License-Identifier: MIT
"""Open trussfe's VTK results in ParaView: members coloured by axial force, deformed shape.

Run it with ParaView's Python (it needs ``paraview.simple``, not trussfe)::

    pvpython open_results.py RESULTS [--png OUT] [--scale S] [--step K] [--size WxH]
    pvbatch  open_results.py RESULTS --png OUT          # off-screen, for scripts

or from the ParaView window (View > Python Shell > Run Script, after setting
``sys.argv``).  RESULTS is a ``.pvd`` series or a ``.vtu`` file written by a trussfe command
with ``--vtk`` (docs/vtk.md): ``trussfe static MODEL --vtk OUT.vtu``, the ``.pvd`` of
``postcritical``, ``simulate``, ``elastic``, ``transient``, ``modes``, ``buckling``, ``trace``.

What it shows
-------------
* the undeformed model as thin grey lines;
* the model warped by the point array ``displacement`` (Warp By Vector), magnified so that
  the largest displacement is drawn at a tenth of the model size unless ``--scale`` is given;
  a series whose points already move (``postcritical``, ``trace``, ``simulate``: written at
  the deformed positions) is drawn as written over its first step in grey, not warped again
  (``--warp yes|no`` overrides);
* the warped members coloured by the cell array ``axial_force`` (N, tension positive) with a
  blue–white–red map symmetric about zero and a colour bar; a file without axial forces
  (mode shapes) is coloured by the displacement magnitude instead.

A series opens at its last step (``--step K`` picks step K, 0-based); in the ParaView window
the time controls step through it.  With ``--png`` the view is saved and the script ends;
without it, ``pvpython`` opens an interactive window.
"""
from __future__ import annotations

import argparse
import math
import os
import sys

from paraview import simple as pv


def _arguments(argv: list[str]) -> argparse.Namespace:
    p = argparse.ArgumentParser(prog="open_results.py", description=__doc__.splitlines()[0])
    p.add_argument("results", help=".pvd series or .vtu file written by trussfe --vtk")
    p.add_argument("--png", help="save the view to this PNG and exit")
    p.add_argument("--scale", type=float, default=None,
                   help="displacement magnification (default: largest drawn at 1/10 of "
                   "the model size)")
    p.add_argument("--warp", choices=("auto", "yes", "no"), default="auto",
                   help="warp by 'displacement' (auto: unless the series' points move)")
    p.add_argument("--step", type=int, default=-1, help="time step of a series (default last)")
    p.add_argument("--size", default="1200x900", help="PNG size in pixels, WxH")
    return p.parse_args(argv)


def main(argv: list[str]) -> int:
    args = _arguments(argv)
    reader = pv.OpenDataFile(args.results)
    if reader is None:
        sys.stderr.write(f"open_results.py: error: {args.results}: ParaView cannot read it\n")
        return 2
    times = list(getattr(reader, "TimestepValues", None) or [])
    scene = pv.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    if times:
        scene.AnimationTime = times[args.step]
    reader.UpdatePipeline(times[args.step] if times else 0.0)

    info = reader.GetDataInformation()
    xmin, xmax, ymin, ymax, zmin, zmax = info.GetBounds()
    size = max(xmax - xmin, ymax - ymin, zmax - zmin) or 1.0
    points = reader.GetPointDataInformation()
    cells = reader.GetCellDataInformation()
    disp = points.GetArray("displacement")
    force = cells.GetArray("axial_force")
    # a series whose points move (postcritical, trace, simulate, ...) is written at the
    # deformed positions: warping it again would count the displacement twice
    first = None
    if times:
        first = pv.ForceTime(Input=reader)
        first.ForcedTime = times[0]
        first.IgnorePipelineTime = 1
        first.UpdatePipeline()
    moving = first is not None and any(
        not math.isclose(a, b, abs_tol=1e-9 * size)
        for a, b in zip(first.GetDataInformation().GetBounds(), info.GetBounds()))
    warp_it = disp is not None and (args.warp == "yes" or (args.warp == "auto" and not moving))

    view = pv.GetActiveViewOrCreate("RenderView")
    width, height = (int(v) for v in args.size.lower().split("x"))
    view.ViewSize = [width, height]
    view.Background = [1.0, 1.0, 1.0]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.OrientationAxesVisibility = 0

    under = pv.Show(first if moving else reader, view)     # the start in grey
    under.ColorArrayName = ["POINTS", ""]             # plain colour
    under.AmbientColor = under.DiffuseColor = [0.75, 0.75, 0.75]
    under.LineWidth = 1.5

    shown = reader
    title = os.path.basename(args.results)
    if warp_it:
        largest = disp.GetRange(-1)[1]                     # magnitude range
        scale = args.scale if args.scale is not None else (
            0.1 * size / largest if largest > 0 else 1.0)
        warp = pv.WarpByVector(Input=reader)
        warp.Vectors = ["POINTS", "displacement"]
        warp.ScaleFactor = scale
        shown = warp
        title += f"  (deformed x{scale:.3g})"
    elif moving:
        title += "  (positions as written; the start in grey)"
    display = pv.Show(shown, view)
    display.LineWidth = 4.0
    if force is not None:
        pv.ColorBy(display, ("CELLS", "axial_force"))
        lo, hi = force.GetRange(0)
        top = max(abs(lo), abs(hi)) or 1.0
        lut = pv.GetColorTransferFunction("axial_force")
        lut.ApplyPreset("Cool to Warm", True)
        lut.RescaleTransferFunction(-top, top)
        label = "axial force [N] (tension +)"
    elif disp is not None:
        pv.ColorBy(display, ("POINTS", "displacement", "Magnitude"))
        lut = pv.GetColorTransferFunction("displacement")
        label = "displacement [m]"
    else:
        lut, label = None, ""
    if lut is not None:
        display.SetScalarBarVisibility(view, True)
        bar = pv.GetScalarBar(lut, view)
        bar.Title = label
        bar.ComponentTitle = ""
        bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    if times:
        title += f"  step {args.step % len(times)} of {len(times)}, time {scene.AnimationTime:g}"
    text = pv.Text(Text=title)
    text_display = pv.Show(text, view)
    text_display.Color = [0.0, 0.0, 0.0]
    text_display.FontSize = 16
    text_display.WindowLocation = "Upper Center"

    view.ResetCamera()
    camera = view.GetActiveCamera()
    if math.isclose(zmin, zmax, abs_tol=1e-12 * size):      # a 2-D model: look along z
        view.CameraPosition = [(xmin + xmax) / 2, (ymin + ymax) / 2, 10 * size]
        view.CameraFocalPoint = [(xmin + xmax) / 2, (ymin + ymax) / 2, 0.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
    else:                                                     # 3-D: isometric
        camera.SetFocalPoint((xmin + xmax) / 2, (ymin + ymax) / 2, (zmin + zmax) / 2)
        camera.SetPosition((xmin + xmax) / 2 + size, (ymin + ymax) / 2 - size,
                           (zmin + zmax) / 2 + size)
        camera.SetViewUp(0.0, 0.0, 1.0)
    view.ResetCamera()
    pv.Render(view)
    if args.png:
        pv.SaveScreenshot(args.png, view, ImageResolution=[width, height])
        print(f"open_results.py: wrote {args.png}")
    else:
        pv.Interact(view)
    return 0


if __name__ == "__main__":
    # pvbatch tears its render window down after the script; leaving through SystemExit
    # instead of the script's end makes some OpenGL drivers abort there, so exit only on error
    status = main(sys.argv[1:])
    if status:
        sys.exit(status)
