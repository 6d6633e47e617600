# SPDX-License-Identifier: MIT
"""Measured motion histories from a CSV file (docs/actuators.md, *Measured motions*).

The file has one header row and one row per sample; lines starting with ``#`` are comments.
Columns::

    time, M7_8, M9_10.length, M9_10.velocity, M9_10.acceleration, ...

* ``time`` — seconds, strictly increasing;
* ``ID`` or ``ID.length`` — length of active member ``ID`` (m), required for every member
  listed;
* ``ID.velocity`` (m/s), ``ID.acceleration`` (m/s²) — optional.

Active members without a column keep their model length.  Missing rates are obtained by smooth
differentiation (:func:`~trussfe.rigid.smoothing.smooth_derivative`): a cubic smoothing spline (:func:`scipy.interpolate.make_smoothing_spline`,
which minimises ``Σ (y_i − f(t_i))² + λ ∫ f''² dt``) is fitted to the lengths, λ chosen by
generalised cross-validation unless given; its first and second derivatives are the velocity and the
acceleration (continuous, piecewise linear).  When a velocity column is given and the
acceleration is not, the acceleration is the derivative of a smoothing spline through the
velocity.  Finite differences of measured positions amplify noise by 1/dt and 1/dt²; the
spline's cross-validated smoothing does not.  The spline's natural end conditions (f'' = 0)
make the rates less accurate over the first and last few samples (about 2 % of a record
sampled as finely as the third-order move of the tests: 0.6 % of the peak velocity and 7 % of
the peak acceleration at the very ends, 0.04 % and 0.4 % inside).  At least five samples are
needed to differentiate.  Samples closer than 10 ms are fitted in a finer time unit (see
:mod:`trussfe.rigid.smoothing`); rates that are not finite or beyond any motion (closely spaced
samples of a large change) are refused naming the time column.
"""
from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

from ..budget import check_input_file
from ..errors import InputError
from ..model.structure import Structure
from .active import active_indices
from .motion import Motion
from .smoothing import smooth_derivative

_QUANTITIES = ("length", "velocity", "acceleration")


#: Largest magnitude of a value in a motion history: beyond it the smoothing splines'
#: squares overflow, and no length (m), rate or time (s) of a truss comes near it.
MAX_VALUE = 1e100


def _read_rows(path: Path) -> tuple[list[str], list[tuple[int, list[str]]]]:
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(str(path), "motion file not found") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(str(path), f"cannot read the motion file ({exc})") from None
    rows = []
    header = None
    for lineno, row in enumerate(csv.reader(text.splitlines()), start=1):
        if not row or not "".join(row).strip() or row[0].lstrip().startswith("#"):
            continue
        cells = [c.strip() for c in row]
        if header is None:
            header = cells
        else:
            rows.append((lineno, cells))
    if header is None:
        raise InputError(path.name, "empty motion file; expected a header row "
                         "'time, <active member id>, ...'")
    return header, rows


def read_motion_csv(path: str | Path, structure: Structure, *,
                    smoothing: float | None = None) -> Motion:
    """Read a measured motion of the active members from a CSV file.

    Parameters
    ----------
    path : path
        CSV file (format in the module docstring).
    structure : Structure
        The model; every member named in the header must be one of its active members.
    smoothing : float, optional
        λ of the smoothing splines used for missing velocities/accelerations (``None``:
        generalised cross-validation).

    Returns
    -------
    Motion
        Histories in the column order of the file.

    Raises
    ------
    InputError
        Naming the file and the line/column: missing ``time`` column, unknown or passive member,
        duplicated or unknown column, a member with rates but no length, a cell that is empty,
        not a number or NaN, a row with the wrong number of cells, time that does not increase
        strictly, fewer than five samples when rates must be computed.
    """
    path = Path(path)
    name = path.name
    check_input_file(str(path), "motion file")
    header, rows = _read_rows(path)
    if "time" not in header:
        raise InputError(f"{name}: header", "has no 'time' column")
    active = set(int(k) for k in active_indices(structure))
    columns: dict[int, dict[str, int]] = {}
    order: list[int] = []
    seen = set()
    for c, h in enumerate(header):
        if h in seen:
            raise InputError(f"{name}: column {c + 1}", f"'{h}' appears twice in the header")
        seen.add(h)
        if h == "time":
            continue
        mid, _, q = h.rpartition(".")
        if not mid or q not in _QUANTITIES:
            mid, q = h, "length"
        try:
            k = structure.member_index(mid)
        except KeyError:
            raise InputError(f"{name}: column {c + 1} '{h}'", f"'{mid}' is not a member of the "
                             "model; columns are time, ID, ID.velocity, ID.acceleration with "
                             "ID an active member") from None
        if k not in active:
            raise InputError(f"{name}: column {c + 1} '{h}'", f"'{mid}' is not an active member "
                             f"of the model (no [active_members.{mid}] table)")
        if k not in columns:
            columns[k] = {}
            order.append(k)
        columns[k][q] = c
    if not order:
        raise InputError(f"{name}: header", "names no active member; expected columns "
                         "time, <active member id>, ...")
    for k in order:
        if "length" not in columns[k]:
            mid = structure.member_ids[k]
            raise InputError(f"{name}: header", f"active member '{mid}' has rates but no "
                             f"length column ('{mid}' or '{mid}.length')")
    if not rows:
        raise InputError(name, "has a header but no samples")
    data = np.empty((len(rows), len(header)))
    for i, (lineno, cells) in enumerate(rows):
        if len(cells) != len(header):
            raise InputError(f"{name}: line {lineno}", f"has {len(cells)} cells, the header "
                             f"has {len(header)}")
        for c, cell in enumerate(cells):
            where = f"{name}: line {lineno}, column {c + 1} '{header[c]}'"
            if cell == "":
                raise InputError(where, "is empty; every sample needs every column")
            try:
                x = float(cell)
            except ValueError:
                raise InputError(where, f"'{cell}' is not a number") from None
            if not math.isfinite(x):
                raise InputError(where, f"is {cell}; values must be finite numbers")
            if abs(x) > MAX_VALUE:
                raise InputError(where, f"{cell} is beyond any length, rate or time in SI "
                                        "units (m, m/s, m/s², s); check the units")
            data[i, c] = x
    lines = [ln for ln, _ in rows]
    t = data[:, header.index("time")]
    bad = np.flatnonzero(np.diff(t) <= 0)
    if bad.size:
        i = int(bad[0]) + 1
        raise InputError(f"{name}: line {lines[i]}", f"time {t[i]:g} s does not increase "
                         f"(previous sample {t[i - 1]:g} s); time must increase strictly")
    L = data[:, [columns[k]["length"] for k in order]]
    if np.any(L <= 0):
        i, j = np.argwhere(L <= 0)[0]
        c = columns[order[j]]["length"]
        raise InputError(f"{name}: line {lines[i]}, column {c + 1} '{header[c]}'",
                         f"length {L[i, j]:g} m must be positive")
    need = any(q not in columns[k] for k in order for q in ("velocity", "acceleration"))
    if need and t.size < 5:
        raise InputError(name, f"has {t.size} samples; at least 5 are needed to compute missing "
                         "velocities or accelerations (or give ID.velocity and ID.acceleration)")
    v = np.empty_like(L)
    a = np.empty_like(L)
    tcol = header.index("time")
    titem = f"{name}: column {tcol + 1} 'time'"
    for j, k in enumerate(order):
        cols = columns[k]
        v[:, j] = data[:, cols["velocity"]] if "velocity" in cols else \
            smooth_derivative(t, L[:, [j]], smoothing, item=titem)[:, 0]
        if "acceleration" in cols:
            a[:, j] = data[:, cols["acceleration"]]
        elif "velocity" in cols:
            a[:, j] = smooth_derivative(t, v[:, [j]], smoothing, item=titem)[:, 0]
        else:
            a[:, j] = smooth_derivative(t, L[:, [j]], smoothing, order=2,
                                         item=titem)[:, 0]
    return Motion(time=t, members=np.array(order, dtype=np.int64), length=L, velocity=v,
                  acceleration=a, source=name)


def write_motion_csv(path: str | Path, motion: Motion, structure: Structure,
                     comment: str = "") -> None:
    """Write ``motion`` as a CSV file that :func:`read_motion_csv` reads back exactly.

    Columns ``time, ID, ID.velocity, ID.acceleration`` per active member, 17 significant
    digits; ``comment`` lines are written first with a leading ``#``.  The file is written to
    a temporary name and renamed (nothing half-written).
    """
    from ..io.output import atomic_path

    ids = [structure.member_ids[int(k)] for k in motion.members]
    head = ["time"] + [f"{i}{q}" for i in ids for q in ("", ".velocity", ".acceleration")]
    cols = [motion.time]
    for j in range(len(ids)):
        cols += [motion.length[:, j], motion.velocity[:, j], motion.acceleration[:, j]]
    data = np.column_stack(cols)
    lines = [f"# {c}" for c in comment.splitlines()] + [",".join(head)]
    lines += [",".join(f"{x:.17g}" for x in row) for row in data]
    with atomic_path(path) as tmp:
        Path(tmp).write_text("\n".join(lines) + "\n", encoding="utf-8")
