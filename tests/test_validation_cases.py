"""Every shipped validation case (``validation/cases/*.toml``) passes through the validation
engine, exactly as ``trussfe validate`` runs it: each quantity within its reference's
tolerance, and each documented deviation (``expect = "differ"``) outside the tolerance of its
stated source and within that of its explained value.  The references and their sources
(thesis tables, closed forms, other solvers; regression values marked as such) are in the
case files."""
import pytest

from trussfe.cli.cmd_validate import default_cases_dir
from trussfe.validation import load_cases, run_case

CASES = load_cases(default_cases_dir())


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_case_passes_through_the_engine(case):
    result = run_case(case)
    assert not result.error, result.error
    bad = [(q.quantity.name, q.value, q.quantity.reference, q.status, q.message)
           for q in result.quantities if q.failed]
    assert not bad, bad
    assert len(result.quantities) == len(case.quantities) > 0
    for q in result.quantities:
        # a documented deviation is reported as one, never as a plain pass
        assert q.status == ("differs" if q.quantity.expect == "differ" else "pass"), q
