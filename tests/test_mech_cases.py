"""The validation cases validation/cases/mech_*.toml: every quantity's path resolves in the
dict its function returns and the value is within the stated tolerance
(|v − r| ≤ atol + rtol·|r|, the validation engine's rule)."""
import importlib
import re
import tomllib

import pytest

from trussfe._resources import data_dir

CASES = sorted(data_dir("validation").glob("cases/mech_*.toml"))
_TOKEN = re.compile(r'\.?(?:"([^"]*)"|([^.\[\]"]+)|\[(-?\d+)\])')


def _lookup(obj, path):
    pos = 0
    while pos < len(path):
        m = _TOKEN.match(path, pos)
        quoted, key, index = m.groups()
        obj = obj[int(index)] if index is not None else obj[quoted if quoted is not None
                                                            else key]
        pos = m.end()
    return obj


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_case(path):
    case = tomllib.loads(path.read_text())
    module, func = case["case"]["python"].split(":")
    result = getattr(importlib.import_module(module), func)()
    for q in case["quantities"]:
        v = float(_lookup(result, q["path"]))
        r = float(q["reference"])
        assert abs(v - r) <= q.get("atol", 0.0) + q.get("rtol", 0.0) * abs(r), q["name"]
