"""A member's ``[failure.members.X]`` keys override ``[failure.default]`` and the default's
parameters of the law they replace (docs/postcritical.md, *[failure] — member failure laws*).

Expected values: the Euler load π²EI/(KL)² of each bar and the documented parameters."""
import math
import re
import tomllib
from pathlib import Path

import pytest
from numpy.testing import assert_allclose

from trussfe.errors import InputError
from trussfe.io.extension_tables import parse_failure_table
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

A, E, I = 1e-4, 2e11, 1e-8
SEC = Section(name="s", area=A, Iy=I, Iz=I, J=2 * I, c=0.01)
MAT = Material(name="m", E=E, G=8e10, density=0.0, yield_strength=2.5e8)
DOC = Path(__file__).resolve().parents[1] / "docs" / "postcritical.md"


def _truss():
    """Joint 0 hung from three supports: M1, M3 at 45° (L = √2 m), M2 vertical (L = 1 m)."""
    return build_structure([[0.0, 0.0], [-1.0, 1.0], [0.0, 1.0], [1.0, 1.0]],
                           [(1, 0), (2, 0), (3, 0)], section=SEC, material=MAT,
                           supports={1: "xy", 2: "xy", 3: "xy"}, loads={0: [0.0, -1.0]},
                           member_ids=["M1", "M2", "M3"])


def _documented_table() -> dict:
    text = DOC.read_text(encoding="utf-8")
    block = re.search(r"```toml\n(\[failure\.default\].*?)```", text, re.S).group(1)
    return tomllib.loads(block)["failure"]


def test_documented_failure_table_is_accepted_as_described():
    """The docs' example: every bar buckles (cap) at its Euler load with K = 1 and breaks at
    ε = 0.05; M3 softens from its own critical_load 1200 N to 0.3 of it over 0.002 and yields
    (cap) at A·2.4e8 Pa."""
    laws = parse_failure_table(_documented_table(), _truss())
    assert list(laws.buckling) == [1, 1, 2]
    assert_allclose(laws.critical_load, [math.pi ** 2 * E * I / 2.0, math.pi ** 2 * E * I,
                                         1200.0], rtol=1e-14)
    assert laws.residual[2] == 0.3 and laws.softening_strain[2] == 0.002
    assert list(laws.yield_mode) == [0, 0, 1]
    assert_allclose(laws.yield_force[2], A * 2.4e8, rtol=1e-14)
    assert_allclose(laws.fracture_strain, [0.05] * 3)


@pytest.mark.parametrize("member, expected", [
    ({"buckling": "cap"}, (1, math.pi ** 2 * E * I / (0.7 ** 2 * 2.0), 0)),
    ({"buckling": "remove", "critical_load": 500.0}, (3, 500.0, 0)),
    ({"effective_length_factor": 2.0, "residual": 0.5},
     (2, math.pi ** 2 * E * I / (4.0 * 2.0), 0)),
    ({"buckling": "none", "yield": "none"}, (0, math.inf, 0)),
])
def test_member_law_replaces_the_defaults_parameters(member, expected):
    """Default: softening with K = 0.7, residual 0.2, softening_strain 1e-3, yield cap at
    3e8 Pa; member M1 (L = √2 m) overrides it."""
    default = {"buckling": "softening", "effective_length_factor": 0.7, "residual": 0.2,
               "softening_strain": 1e-3, "yield": "cap", "yield_strength": 3e8}
    if member.get("yield") != "none":
        member = {**member, "yield": "none"}
    laws = parse_failure_table({"default": default, "members": {"M1": member}}, _truss())
    mode, Pcr, ymode = expected
    assert laws.buckling[0] == mode
    assert_allclose(laws.critical_load[0], Pcr, rtol=1e-14)
    assert laws.yield_mode[0] == ymode
    if mode == 2:
        assert laws.residual[0] == member.get("residual", 0.2)
    # the other members keep the default
    assert laws.buckling[1] == 2 and laws.yield_mode[1] == 1
    assert_allclose(laws.critical_load[1], math.pi ** 2 * E * I / 0.49, rtol=1e-14)


@pytest.mark.parametrize("member, match", [
    ({"critical_load": 1.0, "effective_length_factor": 1.0}, "either critical_load"),
    ({"buckling": "cap", "residual": 0.3}, "belongs to buckling"),
    ({"yield": "none", "yield_strength": 1e8}, "without a yield law"),
])
def test_a_members_own_inconsistent_keys_are_still_refused(member, match):
    default = {"buckling": "softening", "effective_length_factor": 0.7, "residual": 0.2,
               "softening_strain": 1e-3}
    with pytest.raises(InputError, match=match) as err:
        parse_failure_table({"default": default, "members": {"M1": member}}, _truss())
    assert str(err.value).startswith("failure.members.M1")
