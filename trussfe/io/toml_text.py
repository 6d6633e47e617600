# SPDX-License-Identifier: MIT
"""Parsing TOML text: :mod:`tomllib`, and on the command line a compiled parser for large
documents.

A model of a large lattice lists tens of thousands of loaded nodes; :mod:`tomllib`, written
in Python, takes about two seconds for the 32,761 load lines of a 180 × 180 space grid (0.9
MB), most of the whole static solve.  Inside :func:`compiled_parser` — which the ``trussfe``
command enters for every command (:mod:`trussfe.cli`) — documents of at least
:data:`FAST_MIN_BYTES` are parsed by ``rtoml`` (Rust) when it is installed: 0.16 s for the
same file, the same dictionary.  Whatever ``rtoml`` refuses goes to :mod:`tomllib`, which
either parses it or raises its usual error, so every document means what :mod:`tomllib` says
it means and errors read the same.  Library callers get :mod:`tomllib` unless they enter the
context themselves; small documents (every shipped model) never leave :mod:`tomllib`.
"""
from __future__ import annotations

import contextvars
import tomllib
from collections.abc import Iterator
from contextlib import contextmanager

#: Documents at least this long (characters) try the compiled parser first.
FAST_MIN_BYTES = 256 * 1024

TOMLDecodeError = tomllib.TOMLDecodeError

_COMPILED: contextvars.ContextVar[bool] = contextvars.ContextVar("trussfe_compiled_toml",
                                                                default=False)


@contextmanager
def compiled_parser() -> Iterator[None]:
    """Within the context, large documents try ``rtoml`` first (see the module notes)."""
    token = _COMPILED.set(True)
    try:
        yield
    finally:
        _COMPILED.reset(token)


def loads(text: str) -> dict:
    """Parse a TOML document (see the module notes on which parser runs).

    Raises
    ------
    tomllib.TOMLDecodeError
        Malformed TOML.

    Examples
    --------
    >>> loads('[model]\\nname = "bar"\\nloads = [1.0, -2.5]')
    {'model': {'name': 'bar', 'loads': [1.0, -2.5]}}
    """
    if _COMPILED.get() and len(text) >= FAST_MIN_BYTES:
        try:
            import rtoml
        except ImportError:
            rtoml = None
        if rtoml is not None:
            try:
                return rtoml.loads(text)
            except Exception:      # refused (or a parser fault): tomllib decides
                pass
    return tomllib.loads(text)
