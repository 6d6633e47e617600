# SPDX-License-Identifier: MIT
"""Reading validation case files (TOML) into :class:`Case` objects, with input checks."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..budget import check_input_file
from ..errors import InputError
from ..io.regular_file import read_toml_file
from ..io.suggest import suggest as _suggest

CASE_KEYS = ("id", "title", "model", "catalogue", "parameters", "analysis", "python",
             "options", "notes", "tags", "plot", "picture")
EXPLAINED_KEYS = ("explained", "explained_source", "explained_rtol", "explained_atol",
                  "explained_kind")
QUANTITY_KEYS = ("name", "path", "reference", "source", "kind", "thesis_matlab", "thesis_mscpal",
                 "rtol", "atol", "expect", "note") + EXPLAINED_KEYS
EXPECT = ("agree", "differ")
#: Where a reference comes from: ``independent`` (a source, a closed form, another solver) or
#: ``regression`` (a value recorded from trussfe's own output: it guards against change, it
#: does not validate).
KINDS = ("independent", "regression")


@dataclass
class Quantity:
    """One compared number of a case.

    Attributes
    ----------
    name : str
        What it is, for the report.
    path : str
        Where it is in the result dict, e.g. ``nodes.N1.reaction[0]``.
    reference : float
        The value compared against.
    source : str
        Where the reference comes from (table and column, formula, other solver).
    thesis_matlab, thesis_mscpal : float or None
        Printed values shown beside it.
    rtol, atol : float
        Pass when ``|value − reference| ≤ atol + rtol·|reference|``.
    kind : {"independent", "regression"}
        ``regression`` marks a reference recorded from trussfe's own output.
    expect : {"agree", "differ"}
        ``differ`` marks a documented deviation: the value must stay *outside* the tolerance
        of ``reference`` and *within* the tolerance of ``explained``.
    explained : float or None
        For a documented deviation: the value the explanation predicts.
    explained_source : str
        Where ``explained`` comes from (the explanation, as a formula or a source).
    explained_rtol, explained_atol : float
        Its tolerance, read as ``rtol``/``atol``.
    explained_kind : {"independent", "regression"}
        As ``kind``, for ``explained``.
    note : str
        Short remark shown in the table.
    """

    name: str
    path: str
    reference: float
    source: str = ""
    thesis_matlab: float | None = None
    thesis_mscpal: float | None = None
    rtol: float = 0.0
    atol: float = 0.0
    kind: str = "independent"
    expect: str = "agree"
    explained: float | None = None
    explained_source: str = ""
    explained_rtol: float = 0.0
    explained_atol: float = 0.0
    explained_kind: str = "independent"
    note: str = ""


@dataclass
class Case:
    """A validation case read from ``file``."""

    id: str
    title: str
    file: Path
    quantities: list[Quantity]
    model: Path | None = None
    catalogue: str | None = None
    parameters: dict[str, Any] = field(default_factory=dict)
    analysis: str | None = None
    python: str | None = None
    options: dict[str, Any] = field(default_factory=dict)
    notes: str = ""
    tags: list[str] = field(default_factory=list)
    plot: str | None = None
    #: A python case's model file drawn in the report when the case draws no figure.
    picture: Path | None = None


def _num(value: Any, item: str, *, nonneg: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(item, f"expected a number, got {value!r}")
    x = float(value)
    if not math.isfinite(x) or (nonneg and x < 0):
        raise InputError(item, f"expected a finite{' non-negative' if nonneg else ''} number, "
                               f"got {value!r}")
    return x


def _str(value: Any, item: str) -> str:
    if not isinstance(value, str):
        raise InputError(item, f"expected a string, got {value!r}")
    return value


def _quantity(raw: Any, item: str) -> Quantity:
    if not isinstance(raw, dict):
        raise InputError(item, "expected a table [[quantities]]")
    for key in raw:
        if key not in QUANTITY_KEYS:
            raise InputError(f"{item}.{key}", f"unknown key '{key}'{_suggest(key, QUANTITY_KEYS)}")
    for key in ("name", "path", "reference"):
        if key not in raw:
            raise InputError(item, f"missing '{key}'")
    q = Quantity(name=_str(raw["name"], f"{item}.name"), path=_str(raw["path"], f"{item}.path"),
                 reference=_num(raw["reference"], f"{item}.reference"),
                 source=_str(raw.get("source", ""), f"{item}.source"),
                 note=_str(raw.get("note", ""), f"{item}.note"))
    for key in ("thesis_matlab", "thesis_mscpal"):
        if key in raw:
            setattr(q, key, _num(raw[key], f"{item}.{key}"))
    if "rtol" not in raw and "atol" not in raw:
        raise InputError(item, "give a tolerance: rtol and/or atol")
    q.rtol = _num(raw.get("rtol", 0.0), f"{item}.rtol", nonneg=True)
    q.atol = _num(raw.get("atol", 0.0), f"{item}.atol", nonneg=True)
    q.expect = _str(raw.get("expect", "agree"), f"{item}.expect")
    if q.expect not in EXPECT:
        raise InputError(f"{item}.expect", f"must be 'agree' or 'differ'{_suggest(q.expect, EXPECT)}")
    for key in ("kind", "explained_kind"):
        value = _str(raw.get(key, "independent"), f"{item}.{key}")
        if value not in KINDS:
            raise InputError(f"{item}.{key}", f"must be 'independent' or 'regression'"
                                              f"{_suggest(value, KINDS)}")
        setattr(q, key, value)
    given = [k for k in EXPLAINED_KEYS if k in raw]
    if q.expect == "agree":
        if given:
            raise InputError(f"{item}.{given[0]}", "applies to a documented deviation "
                                                   "(expect = \"differ\") only")
        return q
    # A documented deviation asserts itself: it names the value its explanation predicts.
    for key in ("explained", "explained_source"):
        if key not in raw:
            raise InputError(item, f"a documented deviation (expect = \"differ\") needs "
                                   f"'{key}'")
    if "explained_rtol" not in raw and "explained_atol" not in raw:
        raise InputError(item, "give the explained value's tolerance: explained_rtol and/or "
                               "explained_atol")
    q.explained = _num(raw["explained"], f"{item}.explained")
    q.explained_source = _str(raw["explained_source"], f"{item}.explained_source")
    q.explained_rtol = _num(raw.get("explained_rtol", 0.0), f"{item}.explained_rtol", nonneg=True)
    q.explained_atol = _num(raw.get("explained_atol", 0.0), f"{item}.explained_atol", nonneg=True)
    return q


def analysis_names() -> tuple[str, ...]:
    """Analyses of the Python API that a case can run (``analysis = "static"`` …)."""
    from .. import api
    return tuple(sorted(api.ANALYSES))


def resolve_model_path(model: str, case_file: Path) -> Path:
    """A case's model file: relative to the case file, else to the folder holding
    ``validation/`` (so ``meshes/x.toml`` works from a checkout and an installed package)."""
    candidates = [case_file.parent / model, case_file.parent.parent.parent / model]
    for c in candidates:
        if c.is_file():
            return c.resolve()
    return candidates[0].resolve()      # reported as missing when the case runs


def check_model_file(path: str | Path, item: str, written: str | Path) -> None:
    """Refuse a case's model file unless it is a regular file of an accepted size (missing, a
    folder, a device or a named pipe), naming the case's ``item`` and the path as ``written``
    in the case file."""
    try:
        check_input_file(str(path), "model file")
    except InputError as err:
        raise InputError(item, f"'{written}': {err.message}") from None


def load_case(path: str | Path) -> Case:
    """Read one case file.

    Raises
    ------
    InputError
        Naming the file and the item at fault.
    """
    path = Path(path)
    # only a regular file (or a link to one) is read: a case "file" that is a device never
    # ends and a named pipe blocks its reader
    data = read_toml_file(path, "case file")
    try:
        return _parse(data, path)
    except InputError as err:
        raise err.with_file(str(path)) from None


def _parse(data: dict, path: Path) -> Case:
    for key in data:
        if key not in ("case", "quantities"):
            raise InputError(f"[{key}]", f"unknown table{_suggest(key, ('case', 'quantities'))}")
    raw = data.get("case")
    if not isinstance(raw, dict):
        raise InputError("[case]", "table is missing")
    for key in raw:
        if key not in CASE_KEYS:
            raise InputError(f"case.{key}", f"unknown key '{key}'{_suggest(key, CASE_KEYS)}")
    if "id" not in raw:
        raise InputError("case", "missing 'id'")
    case = Case(id=_str(raw["id"], "case.id"), title=_str(raw.get("title", raw["id"]), "case.title"),
                file=path, quantities=[], notes=_str(raw.get("notes", ""), "case.notes"))
    if "analysis" not in raw and "python" not in raw:
        raise InputError("case", "give 'analysis' (a trussfe command) or 'python' "
                                 "(\"module:function\")")
    if "python" in raw:
        # The function computes the result; an 'analysis' beside it only labels the case.
        case.python = _str(raw["python"], "case.python")
        if ":" not in case.python:
            raise InputError("case.python", "expected \"module:function\"")
        if "analysis" in raw:
            case.analysis = _str(raw["analysis"], "case.analysis")
        for key in ("model", "catalogue", "parameters", "plot"):
            if key in raw:
                raise InputError(f"case.{key}", f"'{key}' applies to an 'analysis' case; a "
                                                "python case builds its own model")
    else:
        case.analysis = _str(raw["analysis"], "case.analysis")
        names = analysis_names()
        if case.analysis not in names:
            raise InputError("case.analysis", f"unknown analysis '{case.analysis}'"
                                              f"{_suggest(case.analysis, names)}")
        if ("model" in raw) == ("catalogue" in raw):
            raise InputError("case", "an analysis case needs exactly one of 'model' (a file) "
                                     "or 'catalogue' (a trussfe.models function)")
    if "model" in raw:
        case.model = resolve_model_path(_str(raw["model"], "case.model"), path)
    if "catalogue" in raw:
        case.catalogue = _str(raw["catalogue"], "case.catalogue")
        from .. import models
        if case.catalogue not in models.__all__ or not callable(getattr(models, case.catalogue)):
            funcs = [n for n in models.__all__ if callable(getattr(models, n))]
            raise InputError("case.catalogue", f"unknown catalogue model '{case.catalogue}'"
                                               f"{_suggest(case.catalogue, funcs)}")
    for key in ("parameters", "options"):
        if key in raw:
            if not isinstance(raw[key], dict):
                raise InputError(f"case.{key}", "expected a table")
            setattr(case, key, dict(raw[key]))
    if case.analysis is not None and case.python is None:
        from .. import api
        api.check_options(case.analysis, case.options)
    if "parameters" in raw and case.catalogue is None:
        raise InputError("case.parameters", "parameters apply to a 'catalogue' model only")
    if "plot" in raw:
        case.plot = _str(raw["plot"], "case.plot")
    if "picture" in raw:
        if case.python is None:
            raise InputError("case.picture", "an analysis case shows its own model")
        case.picture = resolve_model_path(_str(raw["picture"], "case.picture"), path)
        check_model_file(case.picture, "case.picture", raw["picture"])
    tags = raw.get("tags", [])
    if not isinstance(tags, list) or not all(isinstance(t, str) for t in tags):
        raise InputError("case.tags", "expected a list of strings")
    case.tags = tags
    qs = data.get("quantities", [])
    if not isinstance(qs, list) or not qs:
        raise InputError("[[quantities]]", "a case needs at least one quantity")
    case.quantities = [_quantity(q, f"quantities[{i}]") for i, q in enumerate(qs)]
    return case


def load_cases(folder: str | Path, ids: list[str] | None = None) -> list[Case]:
    """All cases ``*.toml`` in ``folder`` (sorted by file name), or only those with ``ids``.

    Raises
    ------
    InputError
        For a bad case file, a duplicate id or an unknown requested id.
    """
    folder = Path(folder)
    if not folder.is_dir():
        raise InputError(str(folder), "validation case folder not found")
    cases = [load_case(p) for p in sorted(folder.glob("*.toml"))]
    seen: dict[str, Path] = {}
    for c in cases:
        if c.id in seen:
            raise InputError(str(c.file), f"case id '{c.id}' is also used by {seen[c.id]}")
        seen[c.id] = c.file
    if ids:
        missing = [i for i in ids if i not in seen]
        if missing:
            raise InputError("--case", f"unknown case '{missing[0]}'{_suggest(missing[0], seen)}")
        cases = [c for c in cases if c.id in ids]
    return cases
