"""Progressive failure of a double-layer grid (the benchmark's lattice, small) and the rank
check behind it."""
import numpy as np
import pytest

from trussfe.nonlinear import NonlinearModel, follow_path
from trussfe.nonlinear.mechanism import mechanism_count
from trussfe.studies.postcritical import double_layer_grid


def test_grid_member_count():
    """2n(n−1) top + 2(n−1)(n−2) bottom chords + 4(n−1)² diagonals (9800 for n = 36)."""
    for n in (5, 36):
        s, laws = double_layer_grid(n)
        assert s.n_members == 2 * n * (n - 1) + 2 * (n - 1) * (n - 2) + 4 * (n - 1) ** 2
    assert s.n_members == 9800


@pytest.mark.parametrize("law", ["cap", "remove"])
def test_grid_progressive_failure_events_are_justified(law):
    """Every buckling event of the 5 × 5 grid is located where the bar force equals its own
    P_cr (tolerance 1e-6); with removal the rank is re-checked after each loss, and a
    mechanism (if reached) is reported with its load factor."""
    n = 5
    s, laws = double_layer_grid(n, law=law)
    m = NonlinearModel(s, laws=laws)
    r = follow_path(m, "arc-length", steps=400, max_failures=4, step=0.01,
                    monitor=m.dof((n // 2) * n + n // 2, 2))
    fails = [e for e in r.events if e.kind == "buckling"]
    assert len(fails) >= 4
    for e in fails:
        assert abs(e.force / e.threshold - 1.0) <= 1e-6
        assert e.threshold == pytest.approx(-laws.critical_load[e.member], rel=1e-12)
    lam = [e.load_factor for e in fails]
    assert lam == sorted(lam)                                 # the load does not drop
    if law == "remove":
        assert (~r.path[-1].alive).sum() == sum(1 for e in fails)
    else:
        # capped bars stay in and keep exactly −P_cr
        last = r.path[-1]
        for e in fails:
            if last.forces[e.member] < -laws.critical_load[e.member] * (1 - 1e-6):
                assert last.forces[e.member] == pytest.approx(-laws.critical_load[e.member])


def test_mechanism_count_of_known_assemblies():
    """Hortobágyi §2: mechanisms = μj − ρ(B). The intact grid is stiff (0); a bottom node
    without its four diagonals leaves 3 free motions of that node."""
    s, _ = double_layer_grid(5)
    free = ~s.supports[:, :3]
    assert mechanism_count(s.coords, s.connectivity, free)[0] == 0
    node = 5 * 5                                    # first bottom node
    keep = ~np.any(s.connectivity == node, axis=1)
    assert mechanism_count(s.coords, s.connectivity[keep], free)[0] == 3
