# SPDX-License-Identifier: MIT
"""The study file (docs/studies.md): read, checked and turned into a :class:`Study`.

A study names one analysis (or several, of the same model), the model (a model file or a
structure of the catalogue :mod:`trussfe.models`), the analysis options, the parameters —
grid values and random distributions written at dotted paths into the model file, its motion
file or the catalogue's arguments — and the outputs, dotted paths into the analysis' JSON
document (docs/json.md) with an optional reduction.  Everything that can be checked without
running an analysis is checked here, so a bad study is refused before any run starts.
"""
from __future__ import annotations

import hashlib
import inspect
import json
import math
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..budget import check_input_file, require
from ..errors import InputError
from ..io.regular_file import read_regular_file, read_toml_file
from ..api.result_paths import REDUCTIONS, PathError, tokens

#: Distributions of a Monte Carlo parameter and the numbers each needs.
DISTRIBUTIONS = {"uniform": ("low", "high"), "normal": ("mean", "std"),
                 "lognormal": ("mean", "sigma"), "choice": ("values",)}

_STUDY_KEYS = ("name", "analysis", "model", "catalogue", "options", "samples", "seed")
_PARAM_KEYS = ("values", "from", "to", "step", "count", "distribution", "low", "high", "mean",
               "std", "sigma", "path", "paths", "factor", "relative")
_OUTPUT_KEYS = ("path", "reduce", "where", "analysis")
#: Largest number of runs a study may have (a typing accident beyond that, not a study).
MAX_RUNS = 10_000_000
#: Memory a study holds per run in the command's process: its entry in the list of runs
#: (measured 0.4 KiB with one parameter) and its row of the results table, read back whole.
BYTES_PER_RUN = 1024


@dataclass(frozen=True)
class Parameter:
    """One column of the design: grid ``values`` or a ``distribution`` with its ``args``.

    ``paths`` are ``(target, path)`` pairs, ``target`` one of ``"model"``, ``"motion"``,
    ``"catalogue"``; the value written at each is ``factor × value`` (``base × factor ×
    value`` when ``relative``, ``base`` the value the path holds in the file).  A model path
    of a catalogue structure has no file: its base is ``None`` here and is read, run by run,
    from the model the structure's arguments build (``written``'s ``base``).
    """

    name: str
    paths: tuple[tuple[str, str], ...]
    values: tuple | None = None
    distribution: str | None = None
    args: dict = field(default_factory=dict)
    factor: float = 1.0
    relative: bool = False
    bases: tuple = ()

    @property
    def is_grid(self) -> bool:
        return self.values is not None

    def representative(self) -> Any:
        """A value inside the parameter's range, used to check the model it makes."""
        if self.values is not None:
            return self.values[0]
        a = self.args
        return {"uniform": lambda: 0.5 * (a["low"] + a["high"]), "normal": lambda: a["mean"],
                "lognormal": lambda: math.exp(a["mean"]),
                "choice": lambda: a["values"][0]}[self.distribution]()

    def draw(self, rng) -> Any:
        """One draw from the distribution with the generator ``rng``."""
        a = self.args
        if self.distribution == "uniform":
            return float(rng.uniform(a["low"], a["high"]))
        if self.distribution == "normal":
            return float(rng.normal(a["mean"], a["std"]))
        if self.distribution == "lognormal":
            return float(rng.lognormal(a["mean"], a["sigma"]))
        values = a["values"]
        return values[int(rng.integers(len(values)))]

    def written(self, value: Any, k: int, base: Any = None) -> Any:
        """What is written at ``paths[k]`` for the column value ``value``.

        Parameters
        ----------
        value : Any
            The run's value of the parameter (its column).
        k : int
            Which of ``paths``.
        base : float, optional
            With ``relative``: the value the path holds in this run's model, used where the
            study file gives no file to read it from (``bases[k]`` is ``None``).
        """
        if self.relative:
            b = self.bases[k] if self.bases[k] is not None else base
            return b * self.factor * value
        if self.factor != 1.0:
            return self.factor * value
        return value


@dataclass(frozen=True)
class Output:
    """One output column: ``path`` into the JSON document of ``analysis``."""

    name: str
    analysis: str
    path: str
    reduce: str | None = None
    where: dict | None = None


@dataclass(frozen=True)
class Study:
    """A checked study file (:func:`trussfe.parametric.runner.read_study`)."""

    file: Path
    source: str                        # the study file as named (for error lines)
    name: str
    analyses: tuple[str, ...]
    options: dict                      # analysis -> its options (motion resolved to a path)
    model_file: Path | None
    model_data: dict | None            # the model file's tables (None for a catalogue model)
    catalogue: str | None
    catalogue_args: dict
    motion_file: Path | None           # the TOML motion file the parameters write into
    motion_data: dict | None
    parameters: tuple[Parameter, ...]
    outputs: tuple[Output, ...]
    samples: int
    seed: int

    @property
    def grid(self) -> tuple[Parameter, ...]:
        return tuple(p for p in self.parameters if p.is_grid)

    @property
    def random(self) -> tuple[Parameter, ...]:
        return tuple(p for p in self.parameters if not p.is_grid)

    @property
    def n_grid(self) -> int:
        return math.prod(len(p.values) for p in self.grid)

    @property
    def n_runs(self) -> int:
        return self.n_grid * self.samples

    def fingerprint(self) -> str:
        """A digest of everything that decides the results: the study file and the model and
        motion files it reads (a resumed study must be the same study)."""
        h = hashlib.sha256()
        for f, what in ((self.file, "study file"), (self.model_file, "model file"),
                        (self.motion_file, "motion file")):
            if f is not None:
                # read again, so checked again: the file may have been replaced since
                h.update(read_regular_file(f, what))
        h.update(json.dumps([self.catalogue, self.catalogue_args], default=str).encode())
        return h.hexdigest()


def _err(item: str, message: str) -> InputError:
    return InputError(item, message)


def parse_study(path: str | Path) -> Study:
    """Read a study file and check it against itself and the catalogue (the model and motion
    files are built with the parameters by :func:`trussfe.parametric.runner.read_study`).

    Raises
    ------
    InputError
        Naming the study file and the item at fault: an unknown key or table, a bad
        distribution, an option the analysis does not have, an output without a path (what
        needs the model or motion file is checked by ``read_study``).
    """
    path = Path(path)
    data = read_toml_file(path, "study file")
    try:
        return _parse(data, path)
    except InputError as err:
        raise with_study_file(err, str(path)) from None


def with_study_file(err: InputError, source: str) -> InputError:
    """``err`` naming the study file ``source`` first, as every refusal of a study does
    (unchanged when it names it already: the file cannot be read, or is not TOML)."""
    if err.item == source or err.item.startswith(f"{source}: "):
        return err
    return err.with_file(source)


def _parse(data: dict, path: Path) -> Study:
    from ..io.suggest import suggest as _suggest

    for key in data:
        if key not in ("study", "catalogue", "parameters", "outputs"):
            raise _err(f"[{key}]", "unknown table"
                       f"{_suggest(key, ('study', 'catalogue', 'parameters', 'outputs'))}")
    head = data.get("study")
    if not isinstance(head, dict):
        raise _err("[study]", "is required: name the analysis and the model")
    for key in head:
        if key not in _STUDY_KEYS:
            raise _err(f"study.{key}", f"unknown key{_suggest(key, _STUDY_KEYS)}")
    base = path.parent
    analyses = _analyses(head.get("analysis"))
    options = _options(head.get("options", {}), analyses, base)

    model_file = model_data = catalogue = None
    catalogue_args: dict = {}
    if ("model" in head) == ("catalogue" in head):
        raise _err("study.model", "give either model (a model file) or catalogue (a "
                                  "structure of trussfe.models)")
    if "model" in head:
        if not isinstance(head["model"], str):
            raise _err("study.model", f"expected a file name, got {head['model']!r}")
        model_file = (base / head["model"]).resolve()
        model_data = read_toml_file(model_file, "model file")
        if "catalogue" in data:
            raise _err("[catalogue]", "arguments of a catalogue structure need "
                                      "study.catalogue")
    else:
        catalogue = head["catalogue"]
        catalogue_args = _catalogue_args(catalogue, data.get("catalogue", {}))

    motion_file, motion_data = _motion(options)
    samples, seed = _count(head, "samples", 1, 1), _count(head, "seed", 0, 0)
    # from the counts alone, before any grid is built: a typing accident such as
    # count = 1000000000000 must be refused at once, not after filling the memory
    n_runs = samples * _grid_size(data.get("parameters", {}))
    if n_runs > MAX_RUNS:
        raise _err("study", f"{n_runs} runs is more than {MAX_RUNS}")
    require(n_runs * BYTES_PER_RUN, "study", f"the list and table of {n_runs} runs",
            "make fewer runs (grid values or samples)")
    params = _parameters(data.get("parameters", {}), model_data, motion_data, catalogue,
                         catalogue_args, motion_file)
    if any(not p.is_grid for p in params):
        if "samples" not in head:
            raise _err("study.samples", "a parameter has a distribution: give the number of "
                                        "Monte Carlo draws, samples = N")
    elif samples != 1:
        raise _err("study.samples", "no parameter has a distribution: every sample would be "
                                    "the same run")
    outputs = _outputs(data.get("outputs"), analyses, [p.name for p in params])
    name = head.get("name", path.stem)
    if not isinstance(name, str):
        raise _err("study.name", f"expected a string, got {name!r}")
    study = Study(file=path.resolve(), source=str(path), name=name, analyses=analyses,
                  options=options, model_file=model_file, model_data=model_data, catalogue=catalogue,
                  catalogue_args=catalogue_args, motion_file=motion_file,
                  motion_data=motion_data, parameters=params, outputs=outputs,
                  samples=samples, seed=seed)
    if study.n_runs > MAX_RUNS:
        raise _err("study", f"{study.n_runs} runs is more than {MAX_RUNS}")
    return study


def _count(head: dict, key: str, default: int, low: int) -> int:
    v = head.get(key, default)
    if isinstance(v, bool) or not isinstance(v, int) or v < low:
        raise _err(f"study.{key}", f"must be an integer ≥ {low}, got {v!r}")
    return v


def _analyses(value) -> tuple[str, ...]:
    from ..api import ANALYSES
    from ..io.suggest import suggest as _suggest

    if value is None:
        raise _err("study.analysis", f"is required: one of {', '.join(ANALYSES)}")
    names = [value] if isinstance(value, str) else value
    if not isinstance(names, list) or not names or not all(isinstance(a, str) for a in names):
        raise _err("study.analysis", f"expected an analysis name or a list of them, "
                                     f"got {value!r}")
    for a in names:
        if a not in ANALYSES:
            raise _err("study.analysis", f"unknown analysis '{a}'{_suggest(a, list(ANALYSES))}")
    if len(set(names)) != len(names):
        raise _err("study.analysis", "an analysis is named twice")
    return tuple(names)


def _options(raw, analyses: tuple[str, ...], base: Path) -> dict:
    """Options per analysis, checked against the API's keyword options."""
    from ..api import check_options

    if not isinstance(raw, dict):
        raise _err("study.options", f"expected a table of options, got {raw!r}")
    if len(analyses) == 1:
        per = {analyses[0]: raw}
    else:
        for key in raw:
            if key not in analyses:
                raise _err(f"study.options.{key}", "with several analyses, options are "
                           f"tables named by the analysis: {', '.join(analyses)}")
        per = {a: raw.get(a, {}) for a in analyses}
    out = {}
    for a, opts in per.items():
        item = "study.options" + (f".{a}" if len(analyses) > 1 else "")
        if not isinstance(opts, dict):
            raise _err(item, f"expected a table of options, got {opts!r}")
        if "progress" in opts:
            raise _err(f"{item}.progress", "the study shows its own progress")
        try:
            check_options(a, opts)
        except InputError as err:
            raise _err(item, err.message) from None
        opts = dict(opts)
        motion = opts.get("motion")
        if isinstance(motion, str):
            opts["motion"] = str(_motion_path(motion, base))
        out[a] = opts
    return out


def _motion_path(motion: str, base: Path) -> Path:
    """The motion file of an analysis' options, checked to be a regular file before any
    run reads it.

    It is named relative to the study file's folder; a file that is not there but is found
    from the working folder is taken from there, as the analysis alone would.
    """
    beside = base / motion
    path = beside if os.path.lexists(beside) or not os.path.lexists(motion) else Path(motion)
    check_input_file(str(path), "motion file")
    return path.resolve()


def _motion(options: dict) -> tuple[Path | None, dict | None]:
    files = {o["motion"] for o in options.values() if isinstance(o.get("motion"), str)}
    if len(files) != 1:
        return None, None
    f = Path(next(iter(files)))
    if f.suffix.lower() != ".toml" or not f.is_file():
        return f, None
    return f, read_toml_file(f, "motion file")


def _catalogue_function(name):
    import trussfe.models as catalogue
    from ..io.suggest import suggest as _suggest

    names = [n for n in catalogue.__all__ if n[0].islower()]
    if not isinstance(name, str) or name not in names:
        raise _err("study.catalogue", f"unknown structure {name!r}{_suggest(name, names)}")
    return getattr(catalogue, name)


def _catalogue_args(name, raw) -> dict:
    fn = _catalogue_function(name)
    if not isinstance(raw, dict):
        raise _err("[catalogue]", "expected a table of arguments")
    known = [p.name for p in inspect.signature(fn).parameters.values()]
    from ..io.suggest import suggest as _suggest
    for key in raw:
        if key not in known:
            raise _err(f"catalogue.{key}", f"'{name}' has no argument '{key}'"
                                           f"{_suggest(key, known)}")
    return dict(raw)


def _number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _parameters(raw, model_data, motion_data, catalogue, catalogue_args, motion_file
                ) -> tuple[Parameter, ...]:
    if not isinstance(raw, dict):
        raise _err("[parameters]", "expected a table: path = values")
    out = []
    for name, spec in raw.items():
        item = f"parameters.{name}"
        if isinstance(spec, list):
            spec = {"values": spec}
        if not isinstance(spec, dict):
            raise _err(item, "expected a list of values or a table (values, or a "
                             "distribution)")
        for key in spec:
            if key not in _PARAM_KEYS:
                from ..io.suggest import suggest as _suggest
                raise _err(f"{item}.{key}", f"unknown key{_suggest(key, _PARAM_KEYS)}")
        paths = _param_paths(name, spec, item)
        targets = []
        for p in paths:
            try:
                first = tokens(p)[0]
            except PathError as err:
                raise _err(item, f"path '{p}': {err}") from None
            if first == "motion":
                if motion_data is None:
                    raise _err(item, f"path '{p}' writes into the motion file: give the "
                                     "analysis a TOML motion file (options.motion)"
                               if motion_file is None or motion_file.suffix.lower() == ".toml"
                               else f"path '{p}': a CSV motion history has no parameters")
                targets.append(("motion", p))
            elif first == "catalogue":
                if catalogue is None:
                    raise _err(item, f"path '{p}' needs a catalogue structure "
                                     "(study.catalogue)")
                if len(tokens(p)) != 2:
                    raise _err(item, f"path '{p}': expected catalogue.ARGUMENT")
                _catalogue_args(catalogue, {tokens(p)[1]: None})
                targets.append(("catalogue", p))
            else:
                targets.append(("model", p))
        factor = spec.get("factor", 1.0)
        if not _number(factor):
            raise _err(f"{item}.factor", f"expected a number, got {factor!r}")
        relative = spec.get("relative", False)
        if not isinstance(relative, bool):
            raise _err(f"{item}.relative", f"expected true or false, got {relative!r}")
        values, dist, args = _values(spec, item)
        numeric = dist not in (None, "choice") or all(_number(v) for v in (
            values if values is not None else args["values"]))
        if (factor != 1.0 or relative) and not numeric:
            raise _err(item, "factor and relative need numeric values")
        bases = ()
        if relative:
            # a catalogue structure's model exists only once its arguments are known (they
            # may be parameters too): its values are read run by run (runner._apply)
            bases = tuple(None if t == "model" and model_data is None else
                          _base_value(t, p, model_data, motion_data, catalogue,
                                      catalogue_args, item) for t, p in targets)
        out.append(Parameter(name=name, paths=tuple(targets), values=values, distribution=dist,
                             args=args, factor=float(factor), relative=relative, bases=bases))
    return tuple(out)


def _param_paths(name: str, spec: dict, item: str) -> tuple[str, ...]:
    if "path" in spec and "paths" in spec:
        raise _err(item, "give path or paths, not both")
    if "paths" in spec:
        paths = spec["paths"]
        if not isinstance(paths, list) or not paths or not all(isinstance(p, str)
                                                                for p in paths):
            raise _err(f"{item}.paths", "expected a list of dotted paths")
        return tuple(paths)
    p = spec.get("path", name)
    if not isinstance(p, str):
        raise _err(f"{item}.path", f"expected a dotted path, got {p!r}")
    return (p,)


def _values(spec: dict, item: str) -> tuple[tuple | None, str | None, dict]:
    # beside a distribution, values are its argument (a choice's), not a grid
    grid_keys = ("from",) if "distribution" in spec else ("values", "from")
    kinds = [k for k in (*grid_keys, "distribution") if k in spec]
    if len(kinds) != 1:
        raise _err(item, "give one of: values = [...], from/to with step or count, "
                         "or distribution = " + " | ".join(DISTRIBUTIONS))
    kind = kinds[0]
    if kind == "values":
        values = spec["values"]
        if not isinstance(values, list) or not values:
            raise _err(f"{item}.values", "expected a non-empty list of values")
        _same_kind(values, f"{item}.values")
        return tuple(values), None, {}
    if kind == "from":
        return _range(spec, item), None, {}
    dist = spec["distribution"]
    if dist not in DISTRIBUTIONS:
        from ..io.suggest import suggest as _suggest
        raise _err(f"{item}.distribution", f"unknown distribution {dist!r}"
                                           f"{_suggest(str(dist), list(DISTRIBUTIONS))}")
    needs = DISTRIBUTIONS[dist]
    for key in ("low", "high", "mean", "std", "sigma", "values"):
        if key in spec and key not in needs:
            raise _err(f"{item}.{key}", f"a {dist} distribution takes {', '.join(needs)}")
    args = {}
    for key in needs:
        if key not in spec:
            raise _err(f"{item}.{key}", f"a {dist} distribution needs {', '.join(needs)}")
        args[key] = spec[key]
    if dist == "choice":
        v = args["values"]
        if not isinstance(v, list) or not v:
            raise _err(f"{item}.values", "expected a non-empty list of values")
        _same_kind(v, f"{item}.values")
        return None, dist, {"values": tuple(v)}
    for key, x in args.items():
        if not _number(x):
            raise _err(f"{item}.{key}", f"expected a finite number, got {x!r}")
        args[key] = float(x)
    if dist == "uniform" and not args["low"] < args["high"]:
        raise _err(item, f"uniform needs low < high, got {args['low']} and {args['high']}")
    for key in ("std", "sigma"):
        if key in args and not args[key] > 0:
            raise _err(f"{item}.{key}", f"must be positive, got {args[key]}")
    return None, dist, args


def _same_kind(values: list, item: str) -> None:
    if all(_number(v) for v in values):
        return
    if all(isinstance(v, str) for v in values) or all(isinstance(v, bool) for v in values):
        return
    raise _err(item, "values must be all finite numbers, all strings or all booleans")


def _grid_size(raw) -> int:
    """The number of grid points of the ``[parameters]`` table, from the lists' lengths and
    the ranges' counts and steps, without building any range.

    A parameter that is not a well-formed grid counts as one value: its error is reported
    when the parameter is read.
    """
    if not isinstance(raw, dict):
        return 1
    size = 1
    for name, spec in raw.items():
        if isinstance(spec, list):
            size *= max(len(spec), 1)
        elif isinstance(spec, dict) and "distribution" not in spec:
            if "values" in spec and "from" not in spec:
                values = spec["values"]
                size *= len(values) if isinstance(values, list) and values else 1
            elif "from" in spec and "values" not in spec:
                size *= _range_count(spec, f"parameters.{name}")
    return size


def _range_count(spec: dict, item: str) -> int:
    """The number of values of a ``from``/``to`` range, checked from its numbers alone.

    Raises
    ------
    InputError
        For bounds that are not finite numbers (or whose difference is not), a missing or
        doubled ``step``/``count``, a step that does not lead from ``from`` to ``to``, and a
        range of more values than a study may have runs.
    """
    lo, hi = spec.get("from"), spec.get("to")
    if not (_number(lo) and _number(hi)):
        raise _err(item, "from and to must be finite numbers")
    if not math.isfinite(hi - lo):      # the values between would overflow to inf or nan
        raise _err(item, f"from {lo} to {hi} spans more than the range of floating-point "
                         "numbers")
    if ("step" in spec) == ("count" in spec):
        raise _err(item, "from/to needs step or count (one of them)")
    if "count" in spec:
        n = spec["count"]
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise _err(f"{item}.count", f"must be a positive integer, got {n!r}")
        if n > MAX_RUNS:
            raise _err(f"{item}.count", f"{n} values is more than the {MAX_RUNS} runs a "
                                        "study may have")
        return n
    step = spec["step"]
    if not _number(step) or step == 0 or (hi - lo) / step < 0:
        raise _err(f"{item}.step", f"must be a number leading from {lo} to {hi}, got {step!r}")
    ratio = (hi - lo) / step
    if not ratio < MAX_RUNS:            # also inf: (to - from) / step overflows for a tiny step
        raise _err(f"{item}.step", f"gives more than the {MAX_RUNS} values a study may have "
                                   "runs")
    return int(math.floor(ratio + 1e-9)) + 1


def _range(spec: dict, item: str) -> tuple:
    """The grid values of a ``from``/``to`` range (docs/studies.md).

    ``count = n`` gives n values evenly spaced from ``from`` to ``to``, both ends exact;
    ``step = s`` gives ``from``, ``from + s``, ... up to ``to`` and never past it.

    Notes
    -----
    ``from + (to - from)`` is not always ``to`` in floating point (0.3 + 0.6 is
    0.9000000000000001), and ``from + k × step`` can land just past ``to`` (0.1 + 2 × 0.1 is
    0.30000000000000004): a value past ``to`` by rounding can be outside what the model
    accepts, so such a last value is ``to`` itself, as ``numpy.linspace`` gives its end point.
    """
    n = _range_count(spec, item)
    lo, hi = spec["from"], spec["to"]
    if "count" in spec:
        if n == 1:
            return (lo,)
        return tuple(lo + (hi - lo) * k / (n - 1) for k in range(n - 1)) + (float(hi),)
    step = spec["step"]
    vals = [lo + k * step for k in range(n)]
    if all(isinstance(x, int) for x in (lo, hi, step)):
        vals = [int(v) for v in vals]
    elif (vals[-1] - hi) * step > 0:        # past ``to`` by rounding only (_range_count)
        vals[-1] = hi
    return tuple(vals)


def _base_value(target, path, model_data, motion_data, catalogue, catalogue_args, item):
    from ..api.result_paths import get_value
    if target == "catalogue":
        arg = tokens(path)[1]
        if arg in catalogue_args:
            v = catalogue_args[arg]
        else:
            p = inspect.signature(_catalogue_function(catalogue)).parameters[arg]
            v = p.default
    else:
        try:
            v = get_value(model_data if target == "model" else motion_data, path)
        except PathError as err:
            raise _err(item, f"relative: path '{path}': {err}") from None
    if not _number(v):
        raise _err(item, f"relative: path '{path}' holds {v!r}, not a number")
    return v


#: A parameter's value in an output path: ``nodes.b{n_bays}.N7``.
TEMPLATE = re.compile(r"\{([^{}]+)\}")


def _outputs(raw, analyses: tuple[str, ...], params: list[str]) -> tuple[Output, ...]:
    if not isinstance(raw, dict) or not raw:
        raise _err("[outputs]", "is required: name = dotted path into the analysis' JSON "
                                "result")
    out = []
    for name, spec in raw.items():
        item = f"outputs.{name}"
        if isinstance(spec, str):
            spec = {"path": spec}
        if not isinstance(spec, dict):
            raise _err(item, "expected a dotted path or a table {path, reduce}")
        for key in spec:
            if key not in _OUTPUT_KEYS:
                from ..io.suggest import suggest as _suggest
                raise _err(f"{item}.{key}", f"unknown key{_suggest(key, _OUTPUT_KEYS)}")
        path = spec.get("path")
        if not isinstance(path, str):
            raise _err(f"{item}.path", "is required: a dotted path into the JSON result")
        try:
            toks = tokens(path)
        except PathError as err:
            raise _err(f"{item}.path", str(err)) from None
        for field_ in TEMPLATE.findall(path):
            if field_ not in params:
                raise _err(f"{item}.path", f"'{{{field_}}}' is not a parameter")
        analysis = spec.get("analysis")
        if analysis is None:
            if len(analyses) > 1:
                if not isinstance(toks[0], str) or toks[0] not in analyses:
                    raise _err(f"{item}.path", "with several analyses, an output path "
                               f"starts with the analysis: {', '.join(analyses)}")
                analysis = toks[0]
                path = path.strip()[len(analysis):].lstrip(".")
            else:
                analysis = analyses[0]
        elif analysis not in analyses:
            raise _err(f"{item}.analysis", f"'{analysis}' is not one of the study's analyses")
        how = spec.get("reduce")
        if how is not None and how not in REDUCTIONS:
            raise _err(f"{item}.reduce", f"unknown reduction {how!r}; valid: "
                                         f"{', '.join(REDUCTIONS)}")
        where = spec.get("where")
        if where is not None and (not isinstance(where, dict) or "*" not in toks):
            raise _err(f"{item}.where", "expected a table key = value, with a '*' in the path")
        if name in ("run_id", "grid_point", "sample", "status", "error"):
            raise _err(item, f"'{name}' is a column of every study; choose another name")
        out.append(Output(name=name, analysis=analysis, path=path, reduce=how, where=where))
    return tuple(out)
