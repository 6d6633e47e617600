# SPDX-License-Identifier: MIT
"""``trussfe show MODEL [--png OUT] [--results JSON [--case NAME]]
[--color section|axial_force|utilisation] [--scale S] [--no-labels] [--size WxH]``: a picture of the model (docs/cli.md).

Members coloured by section or by a result of ``trussfe static --json`` (axial force,
utilisation), node and member ids, supports as symbols, loads as labelled arrows, and with
results the deformed shape over the undeformed model in grey.  pyvista draws off-screen where
an OpenGL library works, matplotlib where none does.
"""
from __future__ import annotations

import argparse
import contextlib
import logging
import os
import sys
import tempfile
from pathlib import Path
from typing import Iterator

from .. import api
from ..io.model_picture import COLOR_BY, DEFAULT_SIZE, PIXELS_PER_SIDE
from . import options as opt

log = logging.getLogger("trussfe")


def _size(value: str) -> tuple[int, int]:
    """``WIDTHxHEIGHT`` in pixels, each in ``PIXELS_PER_SIDE`` (200 to 8000)."""
    parts = value.lower().replace("×", "x").split("x")
    if len(parts) != 2:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT in pixels, got {value!r:.40}")
    px = opt.integer(*PIXELS_PER_SIDE, "a number of pixels")
    return px(parts[0].strip()), px(parts[1].strip())


def register(subparsers) -> None:
    """Add the ``show`` command."""
    p = subparsers.add_parser("show", help="draw the model (and its static results) to a PNG",
                              description="Draw the model to a PNG: members coloured by "
                              "section or by a result, node and member ids, supports, loads "
                              "and, from a results file, the deformed shape.")
    p.add_argument("model", type=opt.input_file, help="model file (TOML)")
    p.add_argument("--png", metavar="OUT", type=opt.output_file, default=None,
                   help="picture to write (default: MODEL's name with .png, in the current "
                   "folder)")
    p.add_argument("--results", metavar="JSON", type=opt.input_file, default=None,
                   help="results of this model written by 'trussfe static --json'")
    p.add_argument("--case", metavar="NAME", default=None,
                   help="the load case or combination to draw from results of several "
                   "('trussfe static --all --json'; required there)")
    p.add_argument("--color", choices=COLOR_BY, default=None,
                   help="what colours the members (default: axial_force with --results, "
                   "else section)")
    p.add_argument("--scale", type=opt.positive_real, default=None,
                   help="magnification of the displacements (default: the largest drawn at "
                   "a tenth of the model size)")
    p.add_argument("--no-labels", dest="labels", action="store_false", default=None,
                   help="no node and member ids (default: ids on models of up to 80 nodes "
                   "plus members)")
    p.add_argument("--size", type=_size, default=DEFAULT_SIZE, metavar="WxH",
                   help="picture size in pixels (default %dx%d)" % DEFAULT_SIZE)
    p.set_defaults(func=_run)


@contextlib.contextmanager
def _native_stderr_logged() -> Iterator[None]:
    """Collect what native libraries (VTK's OpenGL window probing) write to the process's
    stderr while the picture is drawn, and log it (visible with ``-v``): a successful run
    prints no warning lines."""
    try:
        sys.stderr.flush()
        saved = os.dup(2)
    except (OSError, ValueError):        # no real stderr (embedded): nothing to collect
        yield
        return
    with tempfile.TemporaryFile() as sink:
        os.dup2(sink.fileno(), 2)
        try:
            yield
        finally:
            with contextlib.suppress(OSError, ValueError):
                sys.stderr.flush()
            os.dup2(saved, 2)
            os.close(saved)
            sink.seek(0)
            for line in sink.read().decode("utf-8", "replace").splitlines():
                if line.strip():
                    log.info("renderer: %s", line.strip())


def _run(args: argparse.Namespace) -> int:
    out = args.png or Path(args.model).with_suffix(".png").name
    if args.png is None:
        opt.output_file(out)            # the default name is checked as --png would be
    model = api.read_model(args.model)
    with _native_stderr_logged():
        pic = api.show(model, out, results=args.results, case=args.case, color=args.color,
                       scale=args.scale, labels=args.labels, size=args.size)
    sys.stdout.write(f"trussfe show: {model.name}: wrote {out} ({pic.backend}, "
                     f"{pic.size[0]}x{pic.size[1]} px)\n")
    return 0
