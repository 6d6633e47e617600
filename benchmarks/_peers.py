# SPDX-License-Identifier: MIT
"""What a peer solver runs on, printed beside its times.

OpenSeesPy's Linux wheel links the system's ``libblas.so.3``, so its sparse solvers (UMFPACK's
dense frontal matrices, the band solvers) run at the speed of whichever BLAS that name
resolves to.  On Debian it is the reference implementation (package ``libblas3``) unless an
optimised one is installed (``libopenblas0-pthread`` or ``libopenblas0-openmp``, which take
over the alternative).  The 180 × 180 space grid takes OpenSeesPy 20–26 s with the reference
BLAS and 6.5–8.7 s with OpenBLAS on the same machine in the same minutes: a speed-up against a
peer on the reference BLAS is three times too flattering, so the benchmarks say which one ran.
"""
from __future__ import annotations

from pathlib import Path


def loaded_blas() -> str:
    """The BLAS library mapped into this process under the name ``libblas.so.3``, resolved
    through its symbolic links, with what it is: ``"OpenBLAS (path)"``, ``"reference BLAS
    (path)"``, or ``"none loaded"`` (before the peer is imported, or elsewhere than Linux)."""
    try:
        maps = Path("/proc/self/maps").read_text().splitlines()
    except OSError:
        return "unknown (no /proc)"
    paths = sorted({line.split()[-1] for line in maps
                    if line.rstrip().endswith(".so.3") and "/libblas.so" in line})
    if not paths:
        return "none loaded"
    path = str(Path(paths[0]).resolve())
    kind = ("OpenBLAS" if "openblas" in path.lower() else
            "MKL" if "mkl" in path.lower() else
            "BLIS" if "blis" in path.lower() else "reference BLAS")
    return f"{kind} ({path})"


def blas_note(peer: str = "OpenSeesPy") -> str:
    """One line for a benchmark's footer naming the peer's BLAS, and the remedy when it is
    the slow reference implementation."""
    blas = loaded_blas()
    note = f"{peer}'s BLAS: {blas}"
    if blas.startswith("reference"):
        note += (" -- the unoptimised reference implementation makes the peer about 3x "
                 "slower on large sparse solves; install an optimised BLAS (Debian: "
                 "libopenblas0-pthread) for a fair reference")
    return note
