# SPDX-License-Identifier: MIT
"""Order of an infinitesimal mechanism (Hortobágyi 1999 §7, Tarnai 1989, Connelly and
Servatius 1994): the successive compatibility equations, Tarnai's chains of straight bar pairs
(order 2ⁿ − 1) and the finite mechanism left when a bar is removed."""
from fractions import Fraction

import numpy as np
import pytest

from trussfe.kinematics.order import mechanism_order
from trussfe.kinematics.rank import rank_analysis
from trussfe.kinematics.trace import trace_mechanism
from trussfe.mechanics.geometry import member_lengths
from trussfe.models.mechanisms import CATALOGUE, section7_chain
from trussfe.studies.hortobagyi_order import (circle_positions, hortobagyi_section7,
                                              section7_recursion)

TWO_BARS = (np.array([[0., 0.], [1., 0.], [2., 0.]]), np.array([[0, 1], [1, 2]]))
MIDDLE_FREE = np.array([[0, 0], [1, 1], [0, 0]], bool)


def _series_misfit(x0, bars, free, series, t):
    """Largest bar-length change of x(t) = x₀ + Σ tᵖ u_p (the truncated series)."""
    n, dim = x0.shape
    fidx = np.flatnonzero(free.ravel())
    d = np.zeros(n * dim)
    for p, u in enumerate(series, start=1):
        d[fidx] += t ** p * u
    return np.max(np.abs(member_lengths(x0 + d.reshape(n, dim), bars)
                         - member_lengths(x0, bars)))


def test_straight_two_bar_chain_is_first_order():
    """Connelly and Servatius (1994): two collinear bars between fixed joints have a first-order
    flex (the middle joint across the chain) and no second-order one — order 1; the bar
    lengths of the first-order motion change by t²/2 (Pythagoras: √(1 + t²) − 1)."""
    x, bars = TWO_BARS
    r = mechanism_order(x, bars, MIDDLE_FREE)
    assert (r.order, r.status, r.checked) == (1, "infinitesimal", 1)
    assert r.obstruction == pytest.approx(1.0)
    np.testing.assert_allclose(np.abs(r.series[0]), [0.0, 1.0], atol=1e-15)
    t = 1e-3
    assert _series_misfit(x, bars, MIDDLE_FREE, r.series, t) == pytest.approx(
        np.sqrt(1 + t * t) - 1, rel=1e-9)


def test_four_bar_is_a_finite_mechanism():
    """A four-bar linkage (Gruebler: one degree of freedom) has no self-stress: every order is
    solvable, the order is infinite."""
    e = CATALOGUE["mech_fourbar"]
    r = mechanism_order(e.coords, e.bars, e.free)
    assert r.order == float("inf") and r.status == "finite"


def test_rigid_and_several_mechanisms_have_no_order():
    """A convex octahedron (Cauchy: rigid) has no mechanism; Hortobágyi's section-8 assembly
    has two infinitesimal mechanisms and a self-stress: the order depends on the first-order
    motion, and is not computed."""
    e = CATALOGUE["mech_octahedron_rigid"]
    assert mechanism_order(e.coords, e.bars, e.free).status == "rigid"
    e = CATALOGUE["mech_sec8_compound"]
    r = mechanism_order(e.coords, e.bars, e.free)
    assert r.order is None and r.status == "several_mechanisms" and "2 infinitesimal" in r.note


def test_bricard_is_never_obstructed():
    """Bricard's flexible octahedron (one mechanism, one self-stress, a finite mechanism):
    no order up to 100 is obstructed, so the order stays undecided (≥ 100) — never a finite
    number; the solved orders stay far below the round-off bound."""
    e = CATALOGUE["mech_bricard"]
    r = mechanism_order(e.coords, e.bars, e.free, max_order=100)
    assert r.order is None and r.status == "undecided" and r.checked == 100
    assert r.margin < 0.1


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5, 6])
def test_chain_order_is_two_to_the_n_minus_one(n):
    """Tarnai's chain of n straight pairs: order 2ⁿ − 1 (construction in
    :func:`trussfe.models.mechanisms.section7_chain`), computed for n ≤ 6; the truncated
    series keeps every bar length to O(t^(2ⁿ)): halving t divides the misfit by 2^(2ⁿ)."""
    e = section7_chain(n)
    r = mechanism_order(e.coords, e.bars, e.free, max_order=2 ** n + 4)
    assert r.order == 2 ** n - 1 and r.status == "infinitesimal"
    assert r.obstruction > 0.5 and r.above_roundoff > 1
    if n <= 3:
        t = 0.05
        m1 = _series_misfit(e.coords, e.bars, e.free, r.series, t)
        m2 = _series_misfit(e.coords, e.bars, e.free, r.series, t / 2)
        assert np.log2(m1 / m2) == pytest.approx(2 ** n, abs=0.1)


def test_chain_order_independent_of_scale_and_orientation():
    """The order is a property of the geometry, not of its units or placement: a chain with
    unequal bars, scaled by 0.01 and rotated, still has order 2³ − 1 = 7."""
    e = section7_chain(3, lengths=[(1.0, 0.6), (0.8, 1.3), (1.1, 0.9)])
    th = 0.3717
    R = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
    x = 0.01 * e.coords @ R.T + [0.123, 4.56]
    r = mechanism_order(x, e.bars, np.ones_like(e.free) & e.free)
    assert r.order == 7


def test_random_chains_never_give_a_wrong_order():
    """Chains of 1–6 pairs with random bar lengths and random angles between consecutive pairs
    (any non-zero angle doubles the order of motion): the computed order is 2ⁿ − 1 or, when
    round-off hides the obstruction, undecided — never a wrong number."""
    rng = np.random.default_rng(1)
    decided = 0
    for _ in range(40):
        n = int(rng.integers(1, 7))
        ang = rng.uniform(0, 2 * np.pi)
        X, A = [np.zeros(2)], []
        for j in range(n):
            if j:
                ang += rng.choice([-1, 1]) * rng.uniform(0.3, np.pi - 0.3)
            u = np.array([np.cos(ang), np.sin(ang)])
            a, b = rng.uniform(0.4, 1.5, 2)
            A.append(X[j] - a * u)
            X.append(X[j] + b * u)
        x = np.array(X + A)
        bars = np.array([(n + 1 + j, j) for j in range(n)] + [(j, j + 1) for j in range(n)])
        free = np.zeros(x.shape, bool)
        free[:n] = True
        r = mechanism_order(x, bars, free, max_order=2 ** n + 2)
        assert r.order in (2 ** n - 1, None)
        decided += r.order is not None
    assert decided >= 30


def test_recursion_matches_the_computed_series():
    """The recursion v_{j+1} = 2 v_j, c_{j+1} = −c_j²(a_j + b_j)/(2 a_j b_j) (exact fractions)
    predicts the order *and* the leading coefficient of X_n's motion across its pair at order
    2ⁿ⁻¹, which the computed series reproduces, for unequal bars."""
    lengths = [(Fraction(1), Fraction(3, 5)), (Fraction(4, 5), Fraction(13, 10)),
               (Fraction(11, 10), Fraction(9, 10)), (Fraction(1), Fraction(1, 2))]
    for n in range(1, 5):
        e = section7_chain(n, lengths=lengths[:n])
        r = mechanism_order(e.coords, e.bars, e.free, max_order=2 ** n + 2)
        Lmax = max(max(p) for p in lengths[:n])             # u₁ moves X₁ by Lmax·t
        rec = section7_recursion(n, lengths[:n], first=Fraction(Lmax))
        assert r.order == rec["order"] == 2 ** n - 1
        col = 2 * (n - 1) + (0 if n % 2 == 0 else 1)
        v = rec["valuations"][-1]
        assert r.series[v - 1, col] == pytest.approx(float(rec["coefficients"][-1]), rel=1e-12)
        assert not np.any(r.series[:v - 1, col])            # no motion across it before


def test_recursion_gives_the_papers_order_for_fourteen_pairs():
    """Hortobágyi (1999) §7: the order of Fig. 9's mechanism is 2¹⁴ − 1.  The recursion for 14
    pairs: valuations 1, 2, 4, …, 8192 and a non-zero obstruction c₁₄² at order 16384."""
    rec = section7_recursion(14)
    assert rec["valuations"] == [2 ** j for j in range(14)]
    assert rec["order"] == 2 ** 14 - 1 == 16383
    assert rec["obstruction"] != 0
    # the computation confirms what floating point can: no obstruction up to order 64
    e = CATALOGUE["mech_sec7_chain_14"]
    r = mechanism_order(e.coords, e.bars, e.free)
    assert r.status == "undecided" and r.checked == 64


def test_removing_a_bar_leaves_a_finite_mechanism():
    """Hortobágyi §7: removing one bar gives a one-degree-of-freedom finite mechanism.  Without
    bar A₁₄–X₁₄: no self-stress (order infinite); traced over 12 steps the rank stays 27 (full
    row rank), every bar keeps its length and the joints follow the successive circle
    intersections (an independent forward solution) to 1e-9 m."""
    e = CATALOGUE["mech_sec7_chain_14_minus1"]
    r = rank_analysis(e.coords, e.bars, e.free)
    assert (r.mechanisms, r.self_stress_states) == (1, 0)
    assert mechanism_order(e.coords, e.bars, e.free, rank=r).order == float("inf")
    t = trace_mechanism(e.coords, e.bars, e.free, [e.drive_index()], e.step, 12)
    assert np.all(t.rank == 27)
    L0 = member_lengths(e.coords, e.bars)
    assert np.max(np.abs(member_lengths(t.coords, e.bars) - L0)) < 1e-9
    ref = circle_positions(e, t.coords[:, 0, 1])
    np.testing.assert_allclose(t.coords[:, :14], ref, atol=1e-9)
    assert t.coords[-1, 0, 1] > 0.5                          # X₁ really moved
    # each joint moves at twice the order of the previous one: X₃ far less than X₂
    dX = np.linalg.norm(t.coords[-1] - t.coords[0], axis=1)
    assert dX[0] > dX[1] > dX[2] > dX[3] > dX[4] > 0


def test_study_numbers():
    """The validation case's numbers (validation/cases/mech_sec7_order.toml)."""
    out = hortobagyi_section7(max_pairs=4, steps=4)
    for n in range(1, 5):
        assert out[f"chain_{n}"]["order"] == out[f"chain_{n}"]["recursion"] == 2 ** n - 1
    assert out["chain_14"]["recursion"] == 16383
    assert out["minus1"]["order_infinite"] == 1 and out["minus1"]["circle_error"] < 1e-9


def test_max_order_must_allow_a_second_order():
    x, bars = TWO_BARS
    with pytest.raises(ValueError, match="at least 2"):
        mechanism_order(x, bars, MIDDLE_FREE, max_order=1)


# ---------------------------------------------------------------- command line and API
def test_cli_json_is_to_dict(tmp_path, capsys):
    """``trussfe mechanism --max-order`` writes the ``order`` of docs/json.md, equal to the
    API's to_dict(); the second output line states it."""
    import json

    from trussfe import api
    from trussfe._resources import mesh_path
    from trussfe.cli import main
    out = tmp_path / "m.json"
    p = mesh_path("mech_sec7_chain_3.toml")
    assert main(["mechanism", str(p), "--max-order", "20", "--json", str(out)]) == 0
    assert "order: 7 (compatible to order 7, not 8)" in capsys.readouterr().out
    doc = json.loads(out.read_text())
    assert doc == api.mechanism(p, max_order=20).to_dict()
    assert doc["order"] == 7 and doc["order_analysis"]["status"] == "infinitesimal"
    assert doc["order_analysis"]["checked"] == 7 and doc["order_analysis"]["max_order"] == 20
    assert doc["order_analysis"]["obstruction"] == pytest.approx(1.0)


@pytest.mark.parametrize("name, order, status", [
    ("mech_fourbar", "infinite", "finite"),
    ("mech_sec7_chain_14_minus1", "infinite", "finite"),
    ("mech_octahedron_rigid", None, "rigid"),
    ("mech_sec8_compound", None, "several_mechanisms"),
    ("mech_sec7_chain_14", None, "undecided"),
    ("mech_sec7_chain_1", 1, "infinitesimal"),
])
def test_order_in_the_json_of_shipped_models(name, order, status):
    """The order on shipped models: a four-bar and the 14-pair chain without a bar are finite
    mechanisms; the 14-pair chain (order 16383) is beyond double precision."""
    from trussfe import api
    from trussfe._resources import mesh_path
    r = api.mechanism(mesh_path(f"{name}.toml"))
    doc = r.to_dict()
    assert doc["order"] == order and doc["order_analysis"]["status"] == status
    assert r.order == (float("inf") if order == "infinite" else order)


@pytest.mark.parametrize("value", [1, 0, 4097, 2.5, True, "8"])
def test_bad_max_order_is_refused(value, capsys):
    """--max-order outside 2 … 4096: InputError naming the option; exit status 2, one line."""
    from trussfe import api
    from trussfe._resources import mesh_path
    from trussfe.cli import main
    from trussfe.errors import InputError
    with pytest.raises(InputError, match="--max-order"):
        api.mechanism(mesh_path("mech_fourbar.toml"), max_order=value)
    if isinstance(value, int) and not isinstance(value, bool):
        rc = main(["mechanism", str(mesh_path("mech_fourbar.toml")), "--max-order", str(value)])
        err = capsys.readouterr().err
        assert rc == 2 and err.startswith("trussfe: error:") and "--max-order" in err
        assert err.count("\n") == 1
