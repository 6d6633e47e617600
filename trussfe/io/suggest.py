# SPDX-License-Identifier: MIT
"""The "did you mean" ending of a message about a name that is not defined: one wording for
every reader and command (model tables, load cases, analyses, options, study files)."""
from __future__ import annotations

import difflib

from ..model.ids import IdIndex

#: Most valid names a message lists; a larger set is summarised by its nearest few and a count.
MAX_LISTED = 8
#: Above this many names the nearest are found by sorted order, not by string similarity
#: (difflib on 300,000 ids takes seconds).
MAX_DIFFLIB = 2000


def suggest(word: str, choices) -> str:
    """The suggestion that ends a "not defined" message: the close match, all valid names
    of a short list, or the nearest few of a long one and how many there are."""
    if isinstance(choices, IdIndex):            # a mesh model: nodes are the point indices
        return f"; the mesh's nodes are 0 … {len(choices) - 1}"
    names = [str(c) for c in choices]
    word = str(word)
    pool = names if len(names) <= MAX_DIFFLIB else _neighbours(word, names, 50)
    close = difflib.get_close_matches(word, pool, n=1, cutoff=0.5)
    if close:
        return f"; did you mean '{close[0]}'?"
    if len(names) <= MAX_LISTED:
        return f"; valid: {', '.join(names)}"
    near = (difflib.get_close_matches(word, pool, n=5, cutoff=0.0) if len(names) <= MAX_DIFFLIB
            else _neighbours(word, names, 5))
    return f"; nearest: {', '.join(near)} (of {len(names):,} defined)"


def _neighbours(word: str, names: list[str], k: int) -> list[str]:
    """The ``k`` names nearest to ``word`` in sorted order (cheap for any number of names)."""
    import bisect

    ordered = sorted(names)
    i = bisect.bisect_left(ordered, word)
    lo = max(0, min(i - k // 2, len(ordered) - k))
    return ordered[lo:lo + k]
