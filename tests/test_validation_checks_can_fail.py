# SPDX-License-Identifier: MIT
"""Validation checks that once could not fail, each shown failing when the value it checks is
perturbed (a monkeypatched function or a perturbed model).  Every test names the case and what
it perturbs."""
from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import pytest

from trussfe.validation import default_cases_dir, load_case, load_cases, lookup, run_case
from trussfe.validation.engine import compare

CASES = default_cases_dir()


def _case(case_id: str):
    return load_cases(CASES, [case_id])[0]


def _by_path(result, path: str):
    hits = [q for q in result.quantities if q.quantity.path == path]
    assert hits, f"{result.case.id}: no check on {path}"
    return hits


# ---------------------------------------------------------------- elastic_m6_strains
def test_elastic_m6_strains_superposition_check_fails_when_gravity_run_is_off(monkeypatch):
    """elastic_m6_strains: the strain history with gravity (ZeroedStrain.full) perturbed by
    0.1 %.  identity_check (gravity part = full − no_gravity) stays exactly 0; the
    superposition check, whose gravity history comes from runs of its own, fails."""
    from trussfe.response.strains import zeroed_strain as real
    from trussfe.studies import lacy_elastic

    def perturbed(*args, **kwargs):
        z = real(*args, **kwargs)
        full = z.full * 1.001
        grav = full - z.no_gravity
        return dataclasses.replace(z, full=full, gravity=grav,
                                   zeroed=z.no_gravity + (grav - z.gravity_equilibrium))

    monkeypatch.setattr(lacy_elastic, "zeroed_strain", perturbed)
    result = lacy_elastic.m6_strains()
    assert result["slew1"]["identity_check"] == 0.0          # blind to the perturbation
    case = _case("elastic_m6_strains")
    q = [q for q in case.quantities if q.path == "slew1.superposition_check"][0]
    r = compare(q, lookup(result, q.path))
    assert r.failed, r


# ---------------------------------------------------------------- FE against rigid, along motions
def _without_rotary_inertia(monkeypatch):
    """Drop the tubes' distributed rotary-inertia couple (ρ I α) from the FE loads."""
    import trussfe.response.along_motion as along

    real = along.motion_loads

    def loads(*args, **kwargs):
        ml = real(*args, **kwargs)
        return dataclasses.replace(ml, couple=0.0 * ml.couple)

    monkeypatch.setattr(along, "motion_loads", loads)


def test_elastic_triangle_base_simulation_fails_without_rotary_inertia(monkeypatch):
    """elastic_triangle_base_simulation: FE loads without the tubes' rotary inertia couple.
    The scaled differences (7e-7) passed the former 1e-6 bound; they fail 1e-9."""
    _without_rotary_inertia(monkeypatch)
    res = run_case(_case("elastic_triangle_base_simulation"))
    for path in ("exact.max", "exact.moment", "thesis.max"):
        (r,) = _by_path(res, path)
        assert r.failed and 1e-9 < r.value < 1e-6, (path, r.value)


def test_elastic_double_octahedron_slews_fail_without_rotary_inertia(monkeypatch):
    """elastic_double_octahedron_slews: FE loads without the tubes' rotary inertia couple.
    The scaled differences (4.4e-7, 6.8e-8) passed the former 1e-6 bound; they fail 1e-9."""
    _without_rotary_inertia(monkeypatch)
    res = run_case(_case("elastic_double_octahedron_slews"))
    for path in ("slew1.max", "slew1.reactions", "slew2.max", "slew2.reactions"):
        (r,) = _by_path(res, path)
        assert r.failed and 1e-9 < r.value < 1e-6, (path, r.value)


# ---------------------------------------------------------------- studies-shipped
@pytest.mark.parametrize("key, when, paths", [
    ("first_frequency", lambda row: row.get("n_bays") == 3,
     ("chain.frequency_vs_api", "chain.frequency_not_falling")),
    ("tip_deflection", lambda row: row.get("n_bays") == 2,
     ("chain.deflection_vs_api", "chain.deflection_not_rising")),
    ("peak_voltage", lambda row: row.get("duration") == 6.0 and row.get("payload") == 20.0,
     ("slew.voltage_vs_api", "slew.over_supply_in_6s")),
    ("peak_voltage", lambda row: row.get("duration") == 2.0 and row.get("payload") == 0.0,
     ("slew.within_supply_in_2s",)),
    ("mechanism_load", lambda row: "mechanism_load" in row,
     ("dome.mechanism_load_vs_api", "dome.mechanism_below_first_limit")),
])
def test_studies_shipped_fails_on_a_nan_row(monkeypatch, key, when, paths):
    """studies-shipped: a study row that succeeds but carries NaN for ``key``.  The builtin
    max and comparisons would drop the NaN and pass; the checks fail instead."""
    from trussfe.parametric import shipped

    real = shipped.run_one

    def run_one(*args, **kwargs):
        row = dict(real(*args, **kwargs))
        if key in row and when(row):
            row[key] = math.nan
        return row

    monkeypatch.setattr(shipped, "run_one", run_one)
    res = run_case(_case("studies-shipped"))
    assert not res.error, res.error
    for path in paths:
        (r,) = _by_path(res, path)
        assert r.failed, (path, r.value, r.status)


# ---------------------------------------------------------------- Table 3.2 on the FE model
TABLE_3_2_CASES = ("lacy-table-3-2", "lacy-table-3-2-appendix-b-model",
                   "lacy-table-3-2-pinned-beam")


def test_lacy_table_3_2_fails_with_node_b_rounded_to_appendix_b(tmp_path):
    """lacy-table-3-2: the model with node B at the 4 decimals printed in Appendix B,
    (1.5625, 1.9516).  O2's reaction moves by 2.2e-5 (inside the former 1e-4) and fails."""
    case = _case("lacy-table-3-2")
    text = Path(case.model).read_text(encoding="utf-8")
    exact = "B = [1.5624999999999998, 1.9515618744994994]"
    assert text.count(exact) == 1
    model = tmp_path / "rounded.toml"
    model.write_text(text.replace(exact, "B = [1.5625, 1.9516]"), encoding="utf-8")
    case_text = Path(case.file).read_text(encoding="utf-8").replace(
        'model = "../../meshes/triangular_truss_static.toml"', f'model = "{model.as_posix()}"')
    (tmp_path / "case.toml").write_text(case_text, encoding="utf-8")
    res = run_case(load_case(tmp_path / "case.toml"))
    for path in ("nodes.O2.reaction[0]", "nodes.O1.reaction[0]", "members.active.axial_force"):
        (r,) = _by_path(res, path)
        assert r.failed and r.rel_error < 1e-4, (path, r.rel_error)


@pytest.mark.parametrize("case_id", TABLE_3_2_CASES)
def test_lacy_table_3_2_cases_fail_on_a_2e_5_reaction(monkeypatch, case_id):
    """lacy-table-3-2*: O2's horizontal reaction of the static analysis scaled by 1 + 2.2e-5
    (what rounding node B does) fails; it passed the former rtol 1e-4."""
    from trussfe.validation import engine

    real = engine._analyse

    def analyse(name):
        run = real(name)

        def perturbed(model, **options):
            d = run(model, **options)
            d["nodes"]["O2"]["reaction"][0] *= 1.0 + 2.2e-5
            return d
        return perturbed

    monkeypatch.setattr(engine, "_analyse", analyse)
    res = run_case(_case(case_id))
    (r,) = _by_path(res, "nodes.O2.reaction[0]")
    assert r.failed and r.rel_error < 1e-4, r


# ---------------------------------------------------------------- recorded and printed values
def test_transient_triangle_f1_regression_fails_on_a_1e_4_shift():
    """transient_triangle_slew_times: the first frequency f1_hz shifted by 1e-4 (a 2e-4 mass
    change) fails; the former rtol 1e-3 let a 0.1 % shift through."""
    q = [q for q in _case("transient_triangle_slew_times").quantities if q.path == "f1_hz"][0]
    assert not compare(q, 16.95099871).failed
    assert compare(q, 16.95099871 * (1 + 1e-4)).failed
    assert compare(q, 16.95099871 * (1 - 1e-4)).failed


def test_hortobagyi_section4_fifth_iterate_fails_when_converged():
    """hortobagyi-section4: path1.fifth_iterate_x2 replaced by the converged x2.  The row
    against the printed 1.99499 (rtol 1e-5) accepts it; the documented deviation against the
    converged value fails it."""
    converged = 1.0 + math.sqrt(0.99)
    qs = [q for q in _case("hortobagyi-section4").quantities
          if q.path == "path1.fifth_iterate_x2"]
    printed = [q for q in qs if q.expect == "agree"]
    differ = [q for q in qs if q.expect == "differ"]
    assert len(printed) == 1 and len(differ) == 1
    assert not compare(printed[0], converged).failed                # cannot tell them apart
    assert compare(differ[0], converged).failed
    assert not compare(differ[0], 1.994991544).failed               # the fifth iterate
