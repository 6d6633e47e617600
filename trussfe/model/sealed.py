# SPDX-License-Identifier: MIT
"""Read-only arrays that stay read-only: the arrays of a model.

``array.flags.writeable = False`` alone does not make an array immutable: an array that owns
its memory may be made writable again (``array.setflags(write=True)``), and a model computed
from it would then change under its kept results.  A read-only *view* of a read-only owner
cannot: numpy refuses to make a view writable while its base is not.
"""
from __future__ import annotations

import numpy as np


def sealed(a: np.ndarray) -> np.ndarray:
    """``a`` as a read-only view of a read-only array that owns its memory.

    An array already sealed is returned as it is (a model's arrays pass unchanged to its
    variants); an array that is a view of a writable one is copied first, so that no
    writable array shares its memory.

    Examples
    --------
    >>> a = sealed(np.arange(3.0))
    >>> a.setflags(write=True)
    Traceback (most recent call last):
    ...
    ValueError: cannot set WRITEABLE flag to True of this array
    >>> sealed(a) is a
    True
    """
    base = a.base
    if not a.flags.writeable and isinstance(base, np.ndarray) and not base.flags.writeable \
            and base.base is None:
        return a
    owner = a if base is None else a.copy()
    owner.flags.writeable = False
    view = owner.view()
    view.flags.writeable = False
    return view
