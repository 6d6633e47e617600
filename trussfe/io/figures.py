# SPDX-License-Identifier: MIT
"""Off-screen matplotlib figures that touch no process-wide state.

Every plot trussfe writes starts here.  A :class:`matplotlib.figure.Figure` is made directly
and given its own Agg canvas, so nothing goes through pyplot: no backend is selected for the
process (a program that uses trussfe keeps its interactive backend), no figure enters
pyplot's global registry (nothing to close, nothing leaks when a plot fails half-way), and
the rendering is exactly the Agg rendering that PNG output always used.

matplotlib is imported inside the functions, so ``import trussfe`` and the command line
start without it.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:                                          # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["new_figure", "subplots"]


def new_figure(figsize: tuple[float, float] | None = None, dpi: float | None = None) -> Figure:
    """A figure with its own Agg canvas, registered nowhere.

    Parameters
    ----------
    figsize : (float, float), optional
        Width and height in inches (default: matplotlib's ``figure.figsize``).
    dpi : float, optional
        Dots per inch (default: matplotlib's ``figure.dpi``).

    Returns
    -------
    matplotlib.figure.Figure
        Save it with ``fig.savefig(...)``; it is freed with its last reference.

    Examples
    --------
    >>> fig = new_figure(figsize=(2.0, 1.5), dpi=50)
    >>> fig.get_size_inches().tolist(), type(fig.canvas).__name__
    ([2.0, 1.5], 'FigureCanvasAgg')
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=figsize, dpi=dpi)
    FigureCanvasAgg(fig)                                   # attaches itself as fig.canvas
    return fig


def subplots(nrows: int = 1, ncols: int = 1, *, figsize: tuple[float, float] | None = None,
             dpi: float | None = None, **kwargs: Any) -> tuple[Figure, Any]:
    """A :func:`new_figure` and a grid of axes, as :meth:`Figure.subplots` returns them.

    Parameters
    ----------
    nrows, ncols : int
        Rows and columns of axes.
    figsize, dpi
        As for :func:`new_figure`.
    **kwargs
        Passed to :meth:`matplotlib.figure.Figure.subplots` (``sharex``, ``squeeze``, ...).

    Returns
    -------
    (Figure, Axes or numpy.ndarray of Axes)

    Examples
    --------
    >>> fig, ax = subplots(2, 1, figsize=(3.0, 4.0), squeeze=False)
    >>> ax.shape
    (2, 1)
    """
    fig = new_figure(figsize=figsize, dpi=dpi)
    return fig, fig.subplots(nrows, ncols, **kwargs)
