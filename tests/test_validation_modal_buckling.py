# SPDX-License-Identifier: MIT
"""The modal and buckling validation cases hold: every quantity of
``validation/cases/{modal,buckling}_*.toml`` is computed and compared with its reference and
tolerance exactly as the case file states (the references and their sources are in the files)."""
from __future__ import annotations

import importlib
import tomllib
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
CASES = sorted((ROOT / "validation" / "cases").glob("modal_*.toml")) + \
    sorted((ROOT / "validation" / "cases").glob("buckling_*.toml"))


def _compute(case: dict, path) -> dict:
    c = case["case"]
    if "python" in c:
        mod, fn = c["python"].split(":")
        return getattr(importlib.import_module(mod), fn)()
    from trussfe import api
    return api.ANALYSES[c["analysis"]]((path.parent / c["model"]).resolve(),
                                       **c.get("options", {})).to_dict()


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_case(path):
    case = tomllib.loads(path.read_text())
    assert case["case"]["id"] == path.stem
    values = _compute(case, path)
    for q in case["quantities"]:
        got = values[q["path"]]
        ref = q["reference"]
        tol = q.get("atol", 0.0) + q.get("rtol", 0.0) * abs(ref)
        assert np.isfinite(got) and abs(got - ref) <= tol, (q["name"], got, ref, tol)
