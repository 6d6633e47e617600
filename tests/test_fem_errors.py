# SPDX-License-Identifier: MIT
"""Mechanisms and bad input in the finite-element core: one clear error, never a traceback
or a NaN.  Expected mechanism counts are from Maxwell's rule / the hand count of each model."""
from __future__ import annotations

import numpy as np
import pytest

from trussfe.errors import InputError, MechanismError
from trussfe.fem import discretise, solve_static
from trussfe.linalg.rank import DENSE_LIMIT
from trussfe.model.sections import Material, Section
from trussfe.model.structure import build_structure

AL = Material("al", E=7.0e10, G=2.6e10, density=2700.0)
TUBE = Section.tube("tube", 0.03, 0.025)


def test_four_bar_linkage_is_one_mechanism():
    """A pin-jointed square without a diagonal on two pinned supports: 4 free DOFs, 3 bars,
    so 1 mechanism in which both top nodes move."""
    s = build_structure([[0, 0], [1, 0], [1, 1], [0, 1]], [(0, 1), (1, 2), (2, 3), (3, 0)],
                        section=TUBE, material=AL, supports={0: "xy", 1: "xy"},
                        loads={2: [10.0, 0.0]}, node_ids=["A", "B", "C", "D"])
    with pytest.raises(MechanismError) as info:
        solve_static(s)
    err = info.value
    assert err.mechanisms == 1
    assert err.moving_nodes == ["C", "D"]
    assert "1 independent mechanism" in str(err) and "C, D" in str(err)
    assert "\n" not in str(err)


def test_unsupported_space_truss_has_six_rigid_body_motions():
    """A free tetrahedron: 12 DOFs, 6 bars, rank 6 → 6 rigid-body motions, all nodes move."""
    x = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    bars = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
    s = build_structure(x, bars, section=TUBE, material=AL, loads={3: [0, 0, -1.0]})
    with pytest.raises(MechanismError) as info:
        solve_static(s)
    assert info.value.mechanisms == 6
    assert info.value.moving_nodes == ["0", "1", "2", "3"]


def test_adding_the_diagonal_removes_the_mechanism():
    s = build_structure([[0, 0], [1, 0], [1, 1], [0, 1]],
                        [(0, 1), (1, 2), (2, 3), (3, 0), (0, 2)], section=TUBE, material=AL,
                        supports={0: "xy", 1: "xy"}, loads={2: [10.0, 0.0]})
    r = solve_static(s)
    assert np.all(np.isfinite(r.u)) and r.residual < 1e-12


def test_large_mechanism_uses_the_sparse_null_space():
    """A chain of pin-jointed squares without diagonals, larger than the dense limit:
    one sway mechanism per square."""
    n = DENSE_LIMIT // 4 + 10
    x = np.array([[i, j] for i in range(n + 1) for j in (0, 1)], float)
    bars = [(2 * i, 2 * i + 1) for i in range(n + 1)]
    bars += [(2 * i, 2 * i + 2) for i in range(n)] + [(2 * i + 1, 2 * i + 3) for i in range(n)]
    s = build_structure(x, bars, section=TUBE, material=AL, supports={0: "xy", 1: "xy"})
    with pytest.raises(MechanismError) as info:
        solve_static(s)
    assert info.value.mechanisms >= 12          # at most 12 computed, n exist
    assert "at least" in str(info.value)


def test_beam_section_without_second_moment_is_named():
    s = build_structure([[0, 0], [1, 0]], [(0, 1)], section=Section("flat", area=1e-4),
                        material=AL, supports={0: ["x", "y", "rz"]}, is_beam=True)
    with pytest.raises(InputError, match=r"sections\.flat: Iz is missing"):
        discretise(s)


def test_pinned_beam_needs_bending_properties_of_bars():
    s = build_structure([[0, 0], [1, 0]], [(0, 1)], section=Section("rod", area=1e-4),
                        material=AL, supports={0: "xy", 1: "xy"})
    discretise(s)                               # fine as a truss bar
    with pytest.raises(InputError, match="pinned-beam makes bars bend"):
        discretise(s, bar_model="pinned-beam")


def test_3d_beam_needs_torsion_constant():
    s = build_structure([[0, 0, 0], [1, 0, 0]], [(0, 1)],
                        section=Section("open", area=1e-4, Iy=1e-8, Iz=1e-8),
                        material=AL, is_beam=True)
    with pytest.raises(InputError, match=r"sections\.open: J is missing"):
        discretise(s)


def test_moment_on_a_pin_joint_is_rejected():
    s = build_structure([[0, 0], [1, 0], [0, 1]], [(0, 1), (2, 1)], section=TUBE, material=AL,
                        supports={0: "xy", 2: "xy"}, loads={1: [0.0, -5.0, 3.0]})
    with pytest.raises(InputError, match=r"loads\.1: a moment \(rz\)"):
        solve_static(s)


@pytest.mark.parametrize("option,value", [("bar_model", "cable"), ("subdivisions", 0),
                                          ("subdivisions", 1.5)])
def test_bad_options(option, value):
    s = build_structure([[0, 0], [1, 0]], [(0, 1)], section=TUBE, material=AL)
    with pytest.raises(InputError):
        discretise(s, **{option: value})


def test_orientation_along_the_member_is_rejected():
    s = build_structure([[0, 0, 0], [1, 0, 0]], [(0, 1)], section=TUBE, material=AL,
                        is_beam=True)
    s = s.with_member_data(orientation={0: [2.0, 0.0, 0.0]})
    with pytest.raises(InputError, match="orientation vector is parallel"):
        discretise(s)


def test_released_beam_spin_is_not_a_mechanism():
    """A 3-D beam released at both ends between pins would spin about its axis; its twist is
    taken as zero where the joint has no rotations, so the structure solves."""
    s = build_structure([[0, 0, 0], [2, 0, 0]], [(0, 1)], section=TUBE, material=AL,
                        is_beam=True, supports={0: "xyz", 1: "yz"}, gravity=[0, 0, -9.81])
    s = s.with_member_data(releases={0: [True, True]})
    r = solve_static(s)
    w = AL.density * TUBE.area * 9.81
    np.testing.assert_allclose(r.reactions[:, 2], [w, w], rtol=1e-10)   # wL/2 each, L = 2


def test_random_structures_give_a_result_or_one_error():
    """Random 2-D/3-D structures (random bars/beams, releases, supports, loads, gravity):
    either a finite result whose stiffness has no null space, or a MechanismError with at
    least one mechanism — never another exception, never a NaN."""
    from trussfe.errors import TrussfeError
    from trussfe.linalg import stiffness_null_space

    rng = np.random.default_rng(1)
    outcomes = {"ok": 0, "mechanism": 0}
    for _ in range(40):
        dim = int(rng.choice([2, 3]))
        n = int(rng.integers(2, 7))
        conn = rng.integers(0, n, (int(rng.integers(1, 12)), 2))
        conn = conn[conn[:, 0] != conn[:, 1]]
        if len(conn) == 0:
            continue
        names = ["x", "y", "rz"] if dim == 2 else ["x", "y", "z", "rx", "ry", "rz"]
        sup = {int(i): [d for d in names if rng.random() < 0.6]
               for i in rng.choice(n, int(rng.integers(1, n + 1)), replace=False)}
        s = build_structure(rng.uniform(-2, 2, (n, dim)), conn, section=TUBE, material=AL,
                            supports=sup, loads={0: rng.uniform(-10, 10, dim)},
                            gravity=[0.0] * (dim - 1) + [-9.81],
                            is_beam=rng.random(len(conn)) < 0.5)
        s = s.with_member_data(releases=rng.random((len(conn), 2)) < 0.3)
        for bar_model in ("truss", "pinned-beam"):
            try:
                r = solve_static(s, bar_model=bar_model, subdivisions=int(rng.integers(1, 4)))
            except MechanismError as err:
                assert err.mechanisms >= 1
                outcomes["mechanism"] += 1
                continue
            except TrussfeError as err:          # pragma: no cover - reported if it happens
                pytest.fail(f"unexpected error {err}")
            assert np.all(np.isfinite(r.u)) and np.all(np.isfinite(r.max_von_mises))
            fe = r.fe
            assert stiffness_null_space(fe.stiffness()[fe.free][:, fe.free]).shape[1] == 0
            outcomes["ok"] += 1
    assert outcomes["ok"] > 5 and outcomes["mechanism"] > 5


def test_beam_without_outer_fibre_distance_is_named():
    """The bending stress M c / I needs c: an explicit beam section without it is an input
    error naming the section, not a silently missing S2."""
    sec = Section("noc", area=1e-4, Iy=1e-8, Iz=1e-8, J=2e-8)
    s = build_structure([[0, 0], [1, 0]], [(0, 1)], section=sec, material=AL,
                        supports={0: ["x", "y", "rz"]}, loads={1: [0.0, -5.0, 0.0]},
                        is_beam=True)
    with pytest.raises(InputError, match=r"sections\.noc: c \(outer-fibre distance\)"):
        solve_static(s)
