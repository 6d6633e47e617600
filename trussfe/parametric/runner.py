# SPDX-License-Identifier: MIT
"""One run of a study: the model and motion with the run's parameter values, the analyses
through the public API (:data:`trussfe.api.ANALYSES`), and the outputs read from each
analysis' JSON document (``to_dict()``, docs/json.md).

:func:`run_one` is what a Dask worker executes.  A run that fails — a model the values make
invalid, an analysis that cannot be carried out, an output its result does not have — is a row
with ``status = "error"`` and the one-line reason, never an exception that stops the study.
"""
from __future__ import annotations

import contextlib
import copy
import logging
import math
import threading
import time
import tomllib
from typing import Any, Iterator

import numpy as np

from ..errors import InputError, TrussfeError, one_line
from ..api.numerics import failure_message
from ..api.result_paths import (PathError, get_value, get_values, numbers, reduce,
                                set_value)
from .spec import TEMPLATE, Study, _catalogue_function, parse_study, with_study_file



class StudyInputError(InputError):
    """A fault of the study itself found by its first run (an option value the analysis
    refuses, an output its result does not have): the study is refused."""


def _new_tables() -> tuple[str, ...]:
    from ..io.model_file import CORE_TABLES, EXTENSION_TABLES
    return tuple(CORE_TABLES) + tuple(EXTENSION_TABLES)


def _apply(data: dict, study: Study, values: dict, target: str, file_item: str) -> dict:
    out = copy.deepcopy(data)
    new = _new_tables() if target == "model" else ()
    for p in study.parameters:
        for k, (t, path) in enumerate(p.paths):
            if t != target:
                continue
            try:
                base = None
                if p.relative and p.bases[k] is None:
                    base = _run_base(data, path, p.name)
                set_value(out, path, p.written(values[p.name], k, base), new_tables=new)
            except PathError as err:
                raise InputError(f"parameters.{p.name}", f"path '{path}' is not in the "
                                 f"{file_item}: {err}") from None
    return out


def _run_base(data: dict, path: str, name: str) -> float:
    """The number at ``path`` in this run's model tables: the base of a ``relative``
    parameter whose model is a catalogue structure (no file to read it from beforehand).

    Raises
    ------
    PathError
        The model has no such path.
    InputError
        The path holds no number.
    """
    v = get_value(data, path)
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise InputError(f"parameters.{name}", f"relative: path '{path}' holds {v!r}, "
                                               "not a number")
    return v


def build_inputs(study: Study, values: dict) -> tuple[Any, dict]:
    """The structure and each analysis' options for one run's parameter ``values``.

    Returns
    -------
    structure : Structure
    options : dict
        Analysis name -> keyword options (a motion written by parameters as a ``Motion``).
    """
    from ..api import model_from_dict

    targets = {t for p in study.parameters for t, _ in p.paths}
    if study.catalogue is not None:
        args = dict(study.catalogue_args)
        for p in study.parameters:
            for k, (t, path) in enumerate(p.paths):
                if t == "catalogue":
                    args[path.split(".", 1)[1].strip()] = p.written(values[p.name], k)
        try:
            structure = _catalogue_function(study.catalogue)(**args)
        except TypeError as exc:
            raise InputError(f"catalogue {study.catalogue}", one_line(str(exc))) from None
        if "model" in targets:
            from ..io.model_writer import model_toml
            data = _apply(tomllib.loads(model_toml(structure)), study, values, "model",
                          "model")
            structure = model_from_dict(data)
    else:
        data = (_apply(study.model_data, study, values, "model", "model file")
                if "model" in targets else study.model_data)
        try:
            structure = model_from_dict(data, base_dir=study.model_file.parent)
        except InputError as err:
            raise err.with_file(study.model_file.name) from None
    options = {a: dict(o) for a, o in study.options.items()}
    if "motion" in targets:
        from ..rigid.motion_file import motion_from_spec
        mdata = _apply(study.motion_data, study, values, "motion", "motion file")
        for a, o in options.items():
            if o.get("motion") == str(study.motion_file):
                o["motion"] = motion_from_spec(mdata.get("motion"), structure,
                                               study.motion_file.parent,
                                               study.motion_file.name, steps=o.pop("steps", None))
    return structure, options


def _output_value(doc: dict, out, item: str, values: dict) -> float:

    path = TEMPLATE.sub(lambda m: str(values[m.group(1)]), out.path)
    try:
        found = get_values(doc, path, out.where)
        if out.reduce == "count":
            return float(len(found))
        return reduce(numbers(found), out.reduce)
    except PathError as err:
        raise StudyInputError(item, f"'{path}': {err}") from None


_QUIET_LOCK = threading.Lock()
_quiet_depth = 0
_saved_level = logging.NOTSET


@contextlib.contextmanager
def _library_warnings_held() -> Iterator[None]:
    """The library's log warnings (a motor over its voltage: in the results' flags too) are
    not printed while runs execute, by the workers or by the study's first run in the
    command's own process; the ``trussfe`` logger's level is restored when the last run of the
    process ends."""
    global _quiet_depth, _saved_level
    log = logging.getLogger("trussfe")
    with _QUIET_LOCK:
        if _quiet_depth == 0:
            _saved_level = log.level
            log.setLevel(logging.ERROR)
        _quiet_depth += 1
    try:
        yield
    finally:
        with _QUIET_LOCK:
            _quiet_depth -= 1
            if _quiet_depth == 0:
                log.setLevel(_saved_level)


def run_one(study: Study, run_id: int, grid_point: int, sample: int, values: dict, *,
            probe: bool = False) -> dict:
    """One row of the results table.

    Parameters
    ----------
    study : Study
    run_id, grid_point, sample : int
        The run's id (``grid_point × samples + sample``) and its place in the design.
    values : dict
        Parameter name -> value of this run.
    probe : bool
        The study's first run: an option value that an analysis refuses, or an output that its
        result does not have, raises :class:`StudyInputError` instead of making a failed row.

    Returns
    -------
    dict
        ``run_id``, ``grid_point``, ``sample``, every parameter, every output (NaN when the
        run failed), ``status`` (``"ok"`` or ``"error"``) and ``error`` (``None`` or the line).
    """
    from ..api import ANALYSES

    row = {"run_id": int(run_id), "grid_point": int(grid_point), "sample": int(sample),
           **values}
    outs = {o.name: math.nan for o in study.outputs}
    try:
        with _library_warnings_held(), \
                np.errstate(over="raise", divide="raise", invalid="raise", under="ignore"):
            structure, options = build_inputs(study, values)
            for a in study.analyses:
                try:
                    doc = ANALYSES[a](structure, **options[a]).to_dict()
                except InputError as err:
                    if probe and (err.item.startswith("--") or err.item == "motion"):
                        raise StudyInputError(f"study.options ({a})", str(err)) from None
                    raise
                for o in study.outputs:
                    if o.analysis == a:
                        try:
                            outs[o.name] = _output_value(doc, o, f"outputs.{o.name}", values)
                        except StudyInputError:
                            if probe:
                                raise
                            raise InputError(f"outputs.{o.name}",
                                             f"'{o.path}' is not in this run's result") from None
        status, error = "ok", None
    except StudyInputError:
        raise
    except TrussfeError as err:
        status, error = "error", one_line(str(err), 500)
    except (FloatingPointError, OverflowError, np.linalg.LinAlgError) as exc:
        # (the analyses raise their own as AnalysisError; this is what reading outputs does)
        status, error = "error", failure_message(exc)
    except MemoryError:
        status, error = "error", "out of memory"
    except RecursionError:
        status, error = "error", "the input nests too deeply"
    except Exception as exc:                  # an internal fault: a row, not a lost study
        status, error = "error", f"internal error ({type(exc).__name__}: " \
                                 f"{one_line(str(exc), 300)})"
    if status == "error":
        outs = {o.name: math.nan for o in study.outputs}
    return {**row, **outs, "status": status, "error": error}


def run_batch(study: Study, runs: list[tuple]) -> tuple[list[dict], float]:
    """Several runs in one task: their rows, and the seconds the worker spent on them.

    A study sends its runs to the workers in batches (:mod:`trussfe.parametric.engine`) so
    that the scheduler's cost per task is shared by several runs; each row is exactly
    :func:`run_one`'s, whatever the batch it ran in.
    """
    start = time.perf_counter()
    rows = [run_one(study, *run) for run in runs]
    return rows, time.perf_counter() - start


def read_study(path) -> Study:
    """Read and check a study file: its own tables (:func:`trussfe.parametric.spec.parse_study`),
    then the model (and motion) built with every parameter at a representative value.

    Raises
    ------
    InputError
        Naming the study file and the item at fault: an unknown key or table, a path that is
        not in the model, motion file or catalogue arguments, a bad distribution, an option the
        analysis does not have, an output without a path, a model that the parameters make
        invalid.
    """
    study = parse_study(path)
    try:
        _check_inputs(study)
    except InputError as err:
        # every refusal of a study names the study file, as parse_study's do
        raise with_study_file(err, study.source) from None
    return study


def _check_inputs(study: Study) -> None:
    """Build the model (and motion) with every parameter at a representative value, so that
    a path the files do not have, or a value their reader refuses, is found now."""
    names = [p.name for p in study.parameters]
    clash = {p.name for p in study.parameters} & {o.name for o in study.outputs}
    if clash:
        raise InputError(f"parameters.{sorted(clash)[0]}", "is also the name of an output")
    if len(set(names)) != len(names):
        raise InputError("[parameters]", "a parameter is named twice")
    values = {p.name: p.representative() for p in study.parameters}
    build_inputs(study, values)
