# SPDX-License-Identifier: MIT
"""The validation suite from Python: :func:`validate` (``trussfe.validate``)."""
from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True, eq=False)
class ValidationResult:
    """Outcome of :func:`validate`.

    Attributes
    ----------
    cases : list of trussfe.validation.CaseResult
        One per case run, in the order run: ``case.id``, ``status`` (``pass``, ``fail``,
        ``error``), ``quantities`` (value, reference, errors, status of each).
    """

    cases: list

    @property
    def passed(self) -> bool:
        """True when every check holds: each value within its reference's tolerance, each
        documented deviation outside it and within its explained value's tolerance."""
        return all(r.passed for r in self.cases)

    @property
    def failed(self) -> list:
        """The cases that failed or could not be run."""
        return [r for r in self.cases if not r.passed]

    def write_report(self, directory: str | os.PathLike = "validation-report") -> Path:
        """Write ``report.md`` and ``report.html`` into ``directory``; returns the HTML
        page's path."""
        from .report import write_report
        return write_report(self.cases, directory)[1]

    def to_dict(self) -> dict:
        """Status and checked values of every case (``trussfe validate`` writes a report,
        not JSON; this is the same content as data)."""
        from ..io.output import plain

        def row(q) -> dict:
            d = {"name": q.quantity.name, "path": q.quantity.path, "value": q.value,
                 "reference": q.quantity.reference, "rel_error": q.rel_error,
                 "status": q.status, "source": q.quantity.source, "kind": q.quantity.kind,
                 "expect": q.quantity.expect}
            if q.quantity.expect == "differ":
                d.update(explained=q.quantity.explained,
                         explained_rel_error=q.explained_rel_error,
                         explained_source=q.quantity.explained_source,
                         explained_kind=q.quantity.explained_kind)
            return d

        cases = {}
        for r in self.cases:
            cases[r.case.id] = {"status": r.status, "error": r.error,
                                "quantities": [row(q) for q in r.quantities]}
        return plain({"command": "validate", "passed": self.passed, "cases": cases})

    def __repr__(self) -> str:
        return (f"<ValidationResult: {len(self.cases) - len(self.failed)}/{len(self.cases)} "
                "cases pass>")


def default_cases_dir() -> Path:
    """The built-in case folder (``validation/cases``)."""
    from .._resources import data_dir
    return data_dir("validation") / "cases"


def validate(cases: str | os.PathLike | None = None, *, case: Sequence[str] | None = None,
             progress: bool = False) -> ValidationResult:
    """Run the validation suite (``trussfe validate``): the thesis tables, analytic
    solutions and cross-checks between solvers.

    Parameters
    ----------
    cases : path, optional
        Folder of case files (default: the built-in ``validation/cases``).
    case : sequence of str, optional
        Run only these case ids.
    progress : bool
        Progress bar on stderr (the command shows one unless ``--no-progress``).

    Returns
    -------
    ValidationResult
        ``passed``, ``cases``, ``write_report(directory)``, ``to_dict()``.

    Raises
    ------
    InputError
        A malformed case file or an unknown case id.
    """
    from ..api.options import flag
    from ..errors import InputError
    from .cases import load_cases
    from .engine import run_cases

    if cases is not None and not isinstance(cases, (str, os.PathLike)):
        raise InputError("cases", f"expected a folder of case files, got "
                                  f"{type(cases).__name__}")
    if isinstance(case, str):
        case = [case]
    if case is not None and (not isinstance(case, Sequence)
                             or not all(isinstance(c, str) for c in case)):
        raise InputError("case", f"expected case ids (strings), got {case!r:.60}")
    progress = flag("progress", progress)
    folder = Path(cases) if cases is not None else default_cases_dir()
    selected = load_cases(folder, list(case) if case is not None else None)
    return ValidationResult(run_cases(selected, progress=progress))
