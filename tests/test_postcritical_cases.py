"""The post-critical validation cases (validation/cases/postcritical_*.toml) pass: each
quantity's computed value meets its reference within the case's stated tolerance."""
import importlib
import tomllib

import numpy as np
import pytest

from trussfe._resources import data_dir

CASES = sorted((data_dir("validation") / "cases").glob("postcritical_*.toml"))
_cache = {}


def _run(spec):
    if spec not in _cache:
        mod, fn = spec.split(":")
        _cache[spec] = getattr(importlib.import_module(mod), fn)()
    return _cache[spec]


@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_case_quantities_within_tolerance(path):
    case = tomllib.loads(path.read_text())
    result = _run(case["case"]["python"])
    assert case["quantities"], "a case must check something"
    for q in case["quantities"]:
        value = result[q["path"]]
        ref = q["reference"]
        tol = q.get("atol", 0.0) + q.get("rtol", 0.0) * abs(ref)
        assert np.isfinite(value), q["name"]
        assert abs(value - ref) <= tol, f"{q['name']}: {value} vs {ref} (tolerance {tol})"
