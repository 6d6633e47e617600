# SPDX-License-Identifier: MIT
"""Floating-point failures in an analysis called from Python: one ``AnalysisError`` naming the
model and pointing at the units — never a ``RuntimeWarning`` and ``inf`` in the result
(docs/python.md) — with the caller's own numpy error settings left as they were."""
import warnings

import numpy as np
import pytest

import trussfe
from trussfe.errors import AnalysisError


def _prestrained(strain: float) -> dict:
    """A triangle on two pins whose base bar AB is given a stress-free strain: statically,
    N_AB = −EAε (the pins hold its length), the other bars carry nothing."""
    return {"model": {"dimension": 2, "name": "prestrained triangle"},
            "materials": {"st": {"E": 2.0e11}}, "sections": {"t": {"area": 1.0e-4}},
            "nodes": {"A": [0.0, 0.0], "B": [1.0, 0.0], "C": [0.5, 0.5]},
            "members": {"AB": {"nodes": ["A", "B"], "section": "t", "material": "st"},
                        "AC": {"nodes": ["A", "C"], "section": "t", "material": "st"},
                        "BC": {"nodes": ["B", "C"], "section": "t", "material": "st"}},
            "supports": {"A": ["x", "y"], "B": ["x", "y"]},
            "load_cases": {"pre": {"initial_strain": [{"member": "AB", "strain": strain}]}}}


def test_an_overflow_is_one_error_naming_the_model():
    """A strain of 1e300 gives an axial force of −2e307 N, whose stress overflows: the API
    raises one AnalysisError naming the model and the units, with no warning."""
    s = trussfe.model_from_dict(_prestrained(1e300))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(AnalysisError) as info:
            trussfe.static(s, case="pre")
    assert str(info.value).startswith("prestrained triangle: numerical failure (overflow")
    assert "check the units" in str(info.value)


def test_a_result_in_range_is_unchanged_and_the_callers_settings_kept():
    """The same model with ε = 1e-3: N_AB = −EAε = −20 kN (statics of a bar held between
    two pins), every other bar 0 N.  The caller's numpy error settings are the same after
    the call (the API raises errors only within it)."""
    before = np.geterr()
    r = trussfe.static(trussfe.model_from_dict(_prestrained(1e-3)), case="pre")
    assert np.geterr() == before
    assert r.axial_force[0] == pytest.approx(-2.0e11 * 1.0e-4 * 1e-3, rel=1e-12)
    assert np.allclose(r.axial_force[1:], 0.0, atol=1e-9)


def test_a_model_file_is_named_by_its_path(tmp_path):
    """From a model file the error names the file, as the command line does."""
    from trussfe.io.model_writer import write_model

    f = write_model(trussfe.model_from_dict(_prestrained(1e300)), tmp_path / "pre.toml")
    with pytest.raises(AnalysisError, match=rf"^{f}: numerical failure"):
        trussfe.static(str(f), case="pre")
