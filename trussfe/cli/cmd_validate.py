# SPDX-License-Identifier: MIT
"""``trussfe validate [--out DIR] [--case ID ...] [--cases DIR]``: run the validation suite
and write ``DIR/report.md`` and ``DIR/report.html``.

Exit status: 0 when every check holds (a documented deviation holds while it stays outside
its reference's tolerance and within its explained value's), 1 when a check misses or a case
cannot be run, 2 on bad input (a malformed case file, an unknown case id).
"""
from __future__ import annotations

import sys
from pathlib import Path

from ..validation.run import default_cases_dir, validate
from ..errors import InputError
from . import options as opt


def register(subparsers) -> None:
    """Add the ``validate`` command."""
    p = subparsers.add_parser(
        "validate", help="run the validation suite and write report.md / report.html",
        description="Run the validation cases (the thesis tables, analytic solutions, "
                    "cross-checks between solvers) and write a report.")
    p.add_argument("--out", default="validation-report", metavar="DIR", type=opt.output_dir,
                   help="report folder (default: ./validation-report)")
    p.add_argument("--case", action="append", metavar="ID", dest="cases_selected",
                   help="run only this case (repeatable)")
    p.add_argument("--cases", metavar="DIR", default=None, type=opt.input_dir,
                   help="folder of case files (default: the built-in validation/cases)")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.set_defaults(func=_main)


def _main(args) -> int:
    # The built-in cases' models are the suite's own, some odd on purpose (a folded mechanism
    # whose joint lies on a support): what the library notices about them is not news to the
    # user, whose result is the report; -v still shows it, and a folder of one's own cases
    # keeps its warnings.
    args.show_warnings = args.cases is not None
    run = validate(Path(args.cases) if args.cases else default_cases_dir(),
                       case=args.cases_selected,
                       progress=not args.no_progress and sys.stderr.isatty())
    if not run.cases:
        raise InputError("--cases", f"no validation case files (*.toml) in '{args.cases}'")
    page = run.write_report(args.out)
    results, failed = run.cases, run.failed
    for r in results:
        line = f"{r.status:5s}  {r.case.id}"
        if r.error:
            line += f"  ({r.error})"
        else:
            bad = [q for q in r.quantities if q.failed]
            if bad:
                line += "  (" + "; ".join(f"{q.quantity.name}: {q.message or 'rel. error '}"
                                          f"{'' if q.message else format(q.rel_error or 0, '.2e')}"
                                          for q in bad[:3]) + ")"
        print(line)
    print(f"{len(results) - len(failed)}/{len(results)} cases pass; report: {page}")
    sys.stdout.flush()
    return 1 if failed else 0
