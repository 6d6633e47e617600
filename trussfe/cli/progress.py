# SPDX-License-Identifier: MIT
"""The command line's progress bar for long runs.

The solvers report progress through a plain callback, ``progress(done, total)`` (the API's
``progress`` option); here that callback drives a tqdm bar on stderr — only when stderr is a
terminal, so that a log file or a pipe gets no carriage-return noise, and never mixed into the
one-line error contract (the bar is cleared, ``leave=False``, before an error line is written).
"""
from __future__ import annotations

import contextlib
import os
import sys
from typing import Callable, Iterator

#: The callback the API's long analyses accept: ``progress(done, total)``.
Progress = Callable[[int, int], None]


@contextlib.contextmanager
def progress_bar(desc: str, unit: str = "step", enabled: bool | None = None
                 ) -> Iterator[Progress | None]:
    """A callback that draws a tqdm bar named ``desc`` on stderr, or None off a terminal.

    The total may change between calls (a run with several phases reports each against its
    own total); the bar is closed however the run ends, Ctrl-C included.
    """
    if enabled is None:
        enabled = sys.stderr.isatty()
    if not enabled:
        yield None
        return
    from tqdm import tqdm

    try:                    # a terminal that reports no width (a bare pty): 80 columns
        width = os.get_terminal_size(sys.stderr.fileno()).columns or 80
    except (OSError, ValueError, AttributeError):
        width = 80
    with tqdm(total=None, desc=desc, unit=unit, leave=False, file=sys.stderr,
              mininterval=0.5, ncols=width) as bar:
        def tick(done: int, total: int) -> None:
            if bar.total != total:
                bar.reset(total=total)
            bar.update(done - bar.n)
        yield tick
