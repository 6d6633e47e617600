# SPDX-License-Identifier: MIT
"""Memory bounds: an analysis estimates what it needs from its sizes before allocating.

A mistyped option (``--subdivisions 100000000``, ``--dt 1e-9``, ``steps = 1e12``) would
otherwise grow the process until the operating system kills it, minutes later and without a
word.  :func:`require` compares an estimate with the memory the machine has free and raises
one :class:`~trussfe.errors.InputError` naming the option or item that drives the size.

The estimates are deliberately rough (within a factor of about two of the peak, measured on the
shipped models): they exist to stop requests that are orders of magnitude too large, not to
ration memory.
"""
from __future__ import annotations

import math
import os
import resource

from .errors import InputError

#: Largest model, motion or mesh file read (bytes).  The TOML reader holds the parsed document
#: as Python objects, about 20 times the text; 1 GiB of text is far beyond any lattice the
#: solvers can handle on one machine.
MAX_INPUT_BYTES = 1 << 30

#: Bytes of parsed Python objects per byte of TOML text (measured: 12–16 on large models).
PARSE_BYTES_PER_BYTE = 20


def available_memory() -> int:
    """Bytes the process may still allocate: the free memory of the machine
    (``MemAvailable``), bounded by the address-space limit (``ulimit -v``) when one is set."""
    avail = None
    try:
        with open("/proc/meminfo", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    avail = int(line.split()[1]) * 1024
                    break
    except (OSError, ValueError, IndexError):
        pass
    if avail is None:
        try:
            avail = os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
        except (OSError, ValueError, AttributeError):
            avail = 1 << 40          # unknown: do not refuse on a guess
    soft, _ = resource.getrlimit(resource.RLIMIT_AS)
    if soft not in (resource.RLIM_INFINITY, -1) and soft > 0:
        avail = min(avail, soft)
    return int(avail)


def format_bytes(n: float) -> str:
    """``1.5e9`` → ``'1.4 GiB'``; beyond 10⁶ PiB in exponent notation (``'2.6e+285 PiB'``).

    Examples
    --------
    >>> format_bytes(1.5e9), format_bytes(3e300)
    ('1.4 GiB', '2.66e+285 PiB')
    """
    if not math.isfinite(n):
        return "an unbounded amount"
    for unit in ("bytes", "KiB", "MiB", "GiB", "TiB", "PiB"):
        if abs(n) < 1024 or unit == "PiB":
            if unit == "bytes":
                return f"{n:.0f} {unit}"
            return f"{n:.1f} {unit}" if abs(n) < 1e6 else f"{n:.3g} {unit}"
        n /= 1024
    return f"{n:.1f} EiB"  # pragma: no cover


#: Counts at or above this are written in exponent notation by :func:`count_text`.
EXACT_COUNT_LIMIT = 10 ** 15


def count_text(n: float) -> str:
    """A count for a one-line message: exact with thousands separators while it is short,
    in exponent notation from :data:`EXACT_COUNT_LIMIT` on (a time step of 1e-300 s asks for
    a count of 300 digits, which a reader takes in as ``2.94e+300``, not digit by digit).

    Integers beyond the range of floating-point numbers are written by their power of ten.

    Examples
    --------
    >>> count_text(2940000001.0), count_text(2.94e300), count_text(10 ** 400)
    ('2,940,000,001', '2.94e+300', 'about 1e+400')
    """
    if abs(n) < EXACT_COUNT_LIMIT:
        return f"{int(n):,}"
    try:
        return f"{float(n):.3g}"
    except OverflowError:           # an int beyond the largest float
        return f"about 1e+{int(math.log10(abs(n)))}"


def require(nbytes: float, item: str, what: str, hint: str = "") -> None:
    """Raise when an analysis would need more memory than is available.

    Parameters
    ----------
    nbytes : float
        Estimated peak memory of the analysis, bytes (may be ``inf``).
    item : str
        The option or model item that drives the size, e.g. ``"--subdivisions"``.
    what : str
        What would be allocated, e.g. ``"12,000,000 beam elements"``.
    hint : str
        What to do instead (appended to the message).

    Raises
    ------
    InputError
        ``item: what needs about X of memory, Y is available; hint``.
    """
    avail = available_memory()
    if not (nbytes <= avail):           # also catches nan
        msg = (f"{what} would need about {format_bytes(nbytes)} of memory; "
               f"{format_bytes(avail)} is available")
        raise InputError(item, msg + (f"; {hint}" if hint else ""))


def check_input_file(path: str, what: str = "file") -> int:
    """Refuse an input file that is not a regular file or is too large; returns its size.

    A named pipe would block the reader forever and ``/dev/zero`` never ends, so only regular
    files are read.

    Raises
    ------
    InputError
        Naming the path: missing, a folder, a device or pipe, or larger than
        :data:`MAX_INPUT_BYTES` or than the memory its parsed form would take.
    """
    import stat

    if not str(path).strip() or "\0" in str(path):
        raise InputError(repr(str(path)), f"is not a usable {what} name")
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise InputError(str(path), f"{what} not found") from None
    except OSError as exc:
        raise InputError(str(path), f"cannot read {what}: {exc.strerror or exc}") from None
    if stat.S_ISDIR(st.st_mode):
        raise InputError(str(path), f"is a folder; give the {what} itself")
    if not stat.S_ISREG(st.st_mode):
        kind = ("a named pipe" if stat.S_ISFIFO(st.st_mode) else
                "a device" if stat.S_ISCHR(st.st_mode) or stat.S_ISBLK(st.st_mode) else
                "a socket" if stat.S_ISSOCK(st.st_mode) else "not a regular file")
        raise InputError(str(path), f"is {kind}; the {what} must be a regular file")
    if st.st_size > MAX_INPUT_BYTES:
        raise InputError(str(path), f"is {format_bytes(st.st_size)}, more than the "
                                    f"{format_bytes(MAX_INPUT_BYTES)} a {what} may have")
    require(st.st_size * PARSE_BYTES_PER_BYTE, str(path),
            f"reading this {format_bytes(st.st_size)} {what}")
    return int(st.st_size)


#: Peak bytes per time step and member of an analysis along a motion (``simulate``: positions,
#: velocities, accelerations, section forces and stresses at every step; measured 1.5–4 KiB on
#: the triangular truss and the double-octahedral bay).
BYTES_PER_STEP_MEMBER = 4096
#: ... and per time step and node.
BYTES_PER_STEP_NODE = 512


def along_motion_bytes(steps: float, n_nodes: int, n_members: int) -> float:
    """Estimated peak memory of an analysis of ``steps`` time steps along a motion."""
    return float(steps) * (BYTES_PER_STEP_MEMBER * n_members + BYTES_PER_STEP_NODE * n_nodes
                           + 64)
