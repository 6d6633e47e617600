# SPDX-License-Identifier: MIT
"""The validation suite engine: data-only cases, run and reported beside the published values.

A case is a TOML file (``validation/cases/*.toml``, see ``docs/validation.md``): a model (a
file, or an entry of :mod:`trussfe.models` with parameters), an analysis (a function of the
Python API, :mod:`trussfe.api`, or a ``python = "module:function"``), and quantities, each a
path into the result with a reference value, its source and a tolerance.  :func:`run_cases` evaluates
them; :func:`write_report` writes ``report.md`` and a self-contained ``report.html``.
"""

from .cases import Case, Quantity, load_case, load_cases
from .engine import CaseResult, QuantityResult, lookup, run_case, run_cases
from .report import write_report
from .run import ValidationResult, default_cases_dir, validate

__all__ = ["Case", "CaseResult", "Quantity", "QuantityResult", "load_case", "load_cases",
           "lookup", "run_case", "run_cases", "write_report", "ValidationResult",
           "default_cases_dir", "validate"]
