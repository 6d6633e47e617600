# SPDX-License-Identifier: MIT
"""Running validation cases: build the model, run the analysis, compare the quantities."""
from __future__ import annotations

import importlib
import logging
import math
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import InputError, TrussfeError
from ..api.result_paths import get_value
from ..io.output import scratch_files
from .cases import Case, Quantity, check_model_file

log = logging.getLogger(__name__)


def lookup(result: Any, path: str) -> Any:
    """The value at ``path`` in a nested dict/list result.

    Path syntax (:mod:`trussfe.api.result_paths`, shared with parameter studies):
    dot-separated keys, ``[i]`` list indices (``.i`` works too), keys with dots
    in double quotes.  A dict key that itself contains dots (a flat result such as
    ``{"table_5_2.M6_axial": ...}``) is matched without quotes: the longest run of path
    segments that is a key wins.

    Examples
    --------
    >>> lookup({"nodes": {"b1.N4": {"reaction": [1.0, 2.0]}}}, 'nodes."b1.N4".reaction[1]')
    2.0
    >>> lookup({"a": [[1, 2], [3, 4]]}, "a[1][-1]")
    4
    >>> lookup({"t.O2.0": 17.18}, "t.O2.0"), lookup({"r": [5, 6]}, "r.1")
    (17.18, 6)
    """
    return get_value(result, path)


@dataclass
class QuantityResult:
    """A quantity's outcome: ``status`` is ``pass``, ``fail``, ``differs`` (a documented
    deviation that holds: outside the reference's tolerance, within the explained value's)
    or ``error`` (no value).  A documented deviation that no longer holds is a ``fail``."""

    quantity: Quantity
    value: float | None = None
    abs_error: float | None = None
    rel_error: float | None = None
    explained_rel_error: float | None = None
    status: str = "error"
    message: str = ""

    @property
    def failed(self) -> bool:
        """True when the quantity counts against the suite."""
        return self.status in ("fail", "error")


@dataclass
class CaseResult:
    """A case's outcome."""

    case: Case
    quantities: list[QuantityResult] = field(default_factory=list)
    error: str = ""
    figures: dict[str, bytes] = field(default_factory=dict)    # name -> PNG
    seconds: float = 0.0

    @property
    def passed(self) -> bool:
        """No error and no quantity failed (a documented deviation fails when it no longer
        holds)."""
        return not self.error and not any(q.failed for q in self.quantities)

    @property
    def status(self) -> str:
        """``pass``, ``fail`` or ``error``."""
        if self.error:
            return "error"
        return "pass" if self.passed else "fail"


def _within(v: float, reference: float, rtol: float, atol: float) -> bool:
    return abs(v - reference) <= atol + rtol * abs(reference)


def compare(q: Quantity, value: Any) -> QuantityResult:
    """Compare one value with its reference: pass when ``|v − r| ≤ atol + rtol·|r|``.

    A documented deviation (``expect = "differ"``) passes (status ``differs``) only while it
    holds: outside the reference's tolerance and within ``explained``'s."""
    out = QuantityResult(quantity=q)
    if hasattr(value, "item") and getattr(value, "ndim", None) == 0:
        value = value.item()            # a numpy scalar
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        out.message = f"value at '{q.path}' is not a number: {value!r}"
        return out
    v = float(value)
    if not math.isfinite(v):
        out.message = f"value at '{q.path}' is not finite ({v})"
        return out
    out.value = v
    out.abs_error = abs(v - q.reference)
    out.rel_error = out.abs_error / abs(q.reference) if q.reference != 0 else None
    ok = _within(v, q.reference, q.rtol, q.atol)
    if q.expect != "differ":
        out.status = "pass" if ok else "fail"
        return out
    if q.explained is None:
        out.status = "fail"
        out.message = "documented deviation without an explained value"
        return out
    explained = float(q.explained)
    out.explained_rel_error = abs(v - explained) / abs(explained) if explained else None
    explained_ok = _within(v, explained, q.explained_rtol, q.explained_atol)
    out.status = "differs" if explained_ok and not ok else "fail"
    if ok:
        out.message = "documented deviation gone: the value is within the reference's tolerance"
    elif not explained_ok:
        out.message = (f"documented deviation not as explained: {v:.8g} is outside the "
                       f"tolerance of the explained value {explained:.8g}")
    return out


def _call_python(spec: str, options: dict) -> dict:
    module_name, _, func_name = spec.partition(":")
    try:
        module = importlib.import_module(module_name)
    except ImportError as exc:
        raise InputError("case.python", f"cannot import '{module_name}': {exc}") from None
    func = getattr(module, func_name, None)
    if not callable(func):
        raise InputError("case.python", f"'{module_name}' has no function '{func_name}'")
    return func(**options)


def _analyse(name: str):
    """The API function of an analysis, refusing options it does not take."""
    from .. import api

    func = api.ANALYSES.get(name)
    if func is None:
        from ..io.suggest import suggest as _suggest
        raise InputError("case.analysis", f"unknown analysis '{name}'"
                                          f"{_suggest(name, sorted(api.ANALYSES))}") from None

    def analyse(model: str, **options) -> dict:
        api.check_options(name, options)
        return func(model, **options).to_dict()
    return analyse


def _catalogue_model(case: Case, folder: Path) -> Path:
    """Build a catalogue structure and write it as a model file in ``folder``."""
    from .. import models
    from ..io.model_writer import write_model

    func = getattr(models, case.catalogue, None)
    if not callable(func):
        from ..io.suggest import suggest as _suggest
        raise InputError("case.catalogue", f"unknown catalogue model '{case.catalogue}'"
                                           f"{_suggest(case.catalogue, models.__all__)}")
    try:
        structure = func(**case.parameters)
    except TypeError as exc:
        raise InputError("case.parameters", str(exc)) from None
    return write_model(structure, folder / f"{case.id}.toml")


def evaluate(case: Case) -> tuple[dict, dict[str, bytes]]:
    """Run a case's analysis; returns (result dict, figures as PNG bytes).

    The files a case writes (its catalogue model, a study's figures) are working files, read
    back at once: they are written outside the command's output transaction."""
    with scratch_files():
        return _evaluate(case)


def _evaluate(case: Case) -> tuple[dict, dict[str, bytes]]:
    figures: dict[str, bytes] = {}
    if case.python:
        result = _call_python(case.python, case.options)
        if case.picture is not None and isinstance(result, dict) and not result.get("figures"):
            with tempfile.TemporaryDirectory(prefix="trussfe-case-") as tmp:
                figures["model"] = _model_picture(case.picture, Path(tmp))
    else:
        analyse = _analyse(case.analysis)
        with tempfile.TemporaryDirectory(prefix="trussfe-case-") as tmp:
            model = case.model if case.catalogue is None else _catalogue_model(case, Path(tmp))
            check_model_file(model, "case.model", model)
            result = analyse(str(model), **case.options)
            if case.plot and isinstance(result, dict):
                figures[case.plot] = _member_plot(model, result, case.plot)
            elif isinstance(result, dict) and not result.get("figures"):
                # a case without a figure of its own shows the model it analyses
                figures["model"] = _model_picture(model, Path(tmp))
    if not isinstance(result, dict):
        raise InputError("case", f"the analysis returned {type(result).__name__}, not a dict")
    for name, path in (result.get("figures", {}) or {}).items():
        try:
            figures[str(name)] = Path(path).read_bytes()
        except OSError as exc:
            raise InputError("case", f"figure '{name}' cannot be read: {exc}") from None
    return result, figures


def _model_picture(model: Path, folder: Path) -> bytes:
    """The model as ``trussfe show`` draws it (matplotlib: the same bytes on every run)."""
    from ..api.picture import show

    png = folder / "model.png"
    show(model, png, backend="matplotlib", size=(800, 600))
    return png.read_bytes()


def _member_plot(model: Path, result: dict, field_name: str) -> bytes:
    """The structure coloured by the member result ``field_name`` (e.g. axial_force)."""
    import numpy as np

    from ..io.model_file import read_model
    from .figures import member_field_png

    structure = read_model(model)
    members = result.get("members", {})
    values = np.full(structure.n_members, np.nan)
    for i, mid in enumerate(structure.member_ids):
        v = members.get(mid, {}).get(field_name)
        if isinstance(v, (int, float)):
            values[i] = v
        elif isinstance(v, list) and v and all(isinstance(x, (int, float)) for x in v):
            values[i] = v[-1]           # a history: its last value
    if not np.isfinite(values).any():
        raise InputError("case.plot", f"the result has no member field '{field_name}'")
    unit = {"axial_force": " (N)", "axial_stress": " (Pa)", "max_von_mises": " (Pa)"}
    return member_field_png(structure, values,
                            field_name.replace("_", " ") + unit.get(field_name, ""),
                            title=structure.name)


def run_case(case: Case) -> CaseResult:
    """Run one case.  Errors of the analysis are recorded in the result, never raised."""
    out = CaseResult(case=case)
    t0 = time.perf_counter()
    try:
        result, out.figures = evaluate(case)
    except TrussfeError as err:
        out.error = str(err)
    except Exception as exc:  # a fault in an analysis must not stop the suite
        log.exception("case %s", case.id)
        out.error = f"internal error: {type(exc).__name__}: {exc}"
    else:
        for q in case.quantities:
            try:
                value = lookup(result, q.path)
            except KeyError as exc:
                r = QuantityResult(quantity=q, message=f"path '{q.path}': {exc.args[0]}")
            else:
                r = compare(q, value)
            out.quantities.append(r)
    out.seconds = time.perf_counter() - t0
    return out


def run_cases(cases: list[Case], progress: bool = True) -> list[CaseResult]:
    """Run every case, with a progress bar on stderr."""
    try:
        from tqdm import tqdm
    except ImportError:  # pragma: no cover - tqdm is a dependency
        tqdm = None
    results = []
    bar = (tqdm(total=len(cases), desc="validate", unit="case", leave=False)
           if progress and tqdm is not None else None)
    for case in cases:
        if bar is not None:
            bar.set_postfix_str(case.id)
        results.append(run_case(case))
        if bar is not None:
            bar.update()
    if bar is not None:
        bar.close()
    return results
