# SPDX-License-Identifier: MIT
"""``trussfe.show``: a picture of a model and, optionally, of its static results
(``trussfe show``, docs/cli.md; the drawing is :mod:`trussfe.io.model_picture`)."""
from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from ..errors import InputError
from ..io.model_picture import (DEFAULT_SIZE, PIXELS_PER_SIDE, PictureResults, draw_model,
                                read_results, results_from_document)
from .model import ModelLike, as_structure
from .options import flag, is_integer, real
from .numerics import numerics_checked
from .results import Result


def _size(size) -> tuple[int, int]:
    """``(width, height)``: two integers in :data:`~trussfe.io.model_picture.PIXELS_PER_SIDE`,
    else an InputError."""
    lo, hi = PIXELS_PER_SIDE
    if (not isinstance(size, (tuple, list)) or len(size) != 2
            or not all(is_integer(v) and lo <= v <= hi for v in size)):
        raise InputError("--size", f"expected (width, height) in pixels, integers from {lo} "
                                   f"to {hi}, got {size!r}")
    return int(size[0]), int(size[1])


@dataclass(frozen=True)
class Picture:
    """A picture written by :func:`show`.

    Attributes
    ----------
    path : Path
        The PNG file.
    backend : str
        ``"pyvista"`` or ``"matplotlib"``, the renderer that drew it.
    size : (int, int)
        Width and height, pixels.
    """

    path: Path
    backend: str
    size: tuple[int, int]


@numerics_checked
def show(model: ModelLike, png: str | os.PathLike, *,
         results: str | os.PathLike | Mapping | Result | None = None,
         case: str | None = None, color: str | None = None, scale: float | None = None, labels: bool | None = None,
         backend: str | None = None, size: tuple[int, int] = DEFAULT_SIZE) -> Picture:
    """Draw a model to a PNG: members coloured by section or by a result, node and member
    ids, supports as symbols, loads as labelled arrows, the deformed shape from results.

    Parameters
    ----------
    model : Structure, path or mapping
        The model (as for every analysis).
    png : path
        The PNG to write.
    results : path, mapping or Result, optional
        Static results of this model: a ``trussfe static --json`` file, its document
        (``to_dict()``) or the :class:`~trussfe.api.linear.StaticResult` itself.
    case : str, optional
        The load case or combination to draw from results of several (``static --all``,
        where it is required); drawn in the title.
    color : {"section", "axial_force", "utilisation"}, optional
        What colours the members (default: axial force with results, else section).
        Utilisation is :func:`trussfe.io.model_picture.utilisation`.
    scale : float, optional
        Magnification of the displacements (default: the largest drawn at a tenth of the
        model size).
    labels : bool, optional
        Node and member ids (default: for models of up to 80 nodes plus members).
    backend : {"pyvista", "matplotlib"}, optional
        Default: pyvista where an OpenGL context can be made off-screen, else matplotlib.
    size : (int, int)
        Width and height in pixels.

    Returns
    -------
    Picture

    Examples
    --------
    >>> import trussfe, tempfile, pathlib
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "truss.png"
    >>> model = "meshes/triangular_truss_static.toml"
    >>> pic = trussfe.show(model, out, results=trussfe.static(model), backend="matplotlib")
    >>> pic.size, out.stat().st_size > 0
    ((1000, 800), True)
    """
    width, height = _size(size)
    scale = real("--scale", scale, positive=True)
    labels = flag("labels", labels, optional=True)
    structure = as_structure(model)
    if backend is not None and backend not in ("pyvista", "matplotlib"):
        raise InputError("backend", f"unknown backend '{backend}'; use pyvista or matplotlib")
    picture_results: PictureResults | None
    if case is not None and results is None:
        raise InputError("--case", "chooses a load case of the results: give --results too")
    if results is None:
        picture_results = None
    elif isinstance(results, Result):
        picture_results = results_from_document(results.to_dict(), structure, case=case)
    elif isinstance(results, Mapping):
        picture_results = results_from_document(dict(results), structure, case=case)
    else:
        picture_results = read_results(results, structure, case)
    used = draw_model(png, structure, results=picture_results, color=color, scale=scale,
                      labels=labels, backend=backend, size=(width, height))
    return Picture(path=Path(png), backend=used, size=(width, height))


__all__ = ["Picture", "show"]
