# SPDX-License-Identifier: MIT
"""Hortobágyi (1999) §7: higher-order infinitesimal mechanisms (Tarnai 1989), as dicts of numbers.

The paper's Fig. 9 is missing from the text; the assemblies are Tarnai-type chains of straight
bar pairs (:func:`trussfe.models.mechanisms.section7_chain`), whose order 2ⁿ − 1 follows from
a recursion (:func:`section7_recursion`) and is computed by the successive compatibility
equations (:func:`trussfe.kinematics.order.mechanism_order`) for the n within floating point.
The validation case ``validation/cases/mech_sec7_order.toml`` points at
:func:`hortobagyi_section7`.
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np

from ..kinematics.order import mechanism_order
from ..kinematics.rank import rank_analysis
from ..kinematics.trace import trace_mechanism
from ..mechanics.geometry import member_lengths
from ..models.mechanisms import CATALOGUE, section7_chain

#: The paper's chain: n = 14 pairs, order 2¹⁴ − 1.
PAPER_PAIRS = 14


def section7_recursion(n: int, lengths: list[tuple] | None = None,
                       first: Fraction = Fraction(1)) -> dict:
    """The order of the n-pair chain from its recursion, in exact rational arithmetic.

    If the middle joint X_j first moves across its pair at order v_j with coefficient c_j, the
    pair's far end X_{j+1} first moves along the pair's axis — across pair j + 1 — at order
    ``v_{j+1} = 2 v_j`` with ``c_{j+1} = −c_j² (a_j + b_j)/(2 a_j b_j)`` (the leading term of
    ``a − √(a² − y²) + b − √(b² − y²)``).  The last pair has both ends fixed, so its bars need
    ``|X_n(t) − X_n|² = 0``; the first term of that sum is ``c_n² t^(2 v_n)``, non-zero, so the
    compatibility equations fail first at order ``2 v_n``: the order is ``2 v_n − 1``.

    Parameters
    ----------
    n : int
        Number of straight pairs.
    lengths : list of (a_j, b_j), optional
        Bar lengths of every pair (default 1 each); numbers or fractions.
    first : Fraction
        c₁, the first-order motion of X₁ across pair 1.

    Returns
    -------
    dict
        ``valuations`` (v_1 … v_n), ``coefficients`` (c_1 … c_n, Fractions), ``order``
        (2 v_n − 1) and ``obstruction`` (the first non-zero term of the last pair's sum, c_n²,
        at order 2 v_n).

    Examples
    --------
    >>> r = section7_recursion(14)
    >>> r["order"] == 2 ** 14 - 1, r["valuations"][-1]
    (True, 8192)
    """
    ab = [(Fraction(1), Fraction(1))] * n if lengths is None else \
        [(Fraction(a), Fraction(b)) for a, b in lengths]
    v, c = [1], [Fraction(first)]
    for j in range(n - 1):
        a, b = ab[j]
        v.append(2 * v[-1])
        c.append(-c[-1] ** 2 * (a + b) / (2 * a * b))
    return {"valuations": v, "coefficients": c, "order": 2 * v[-1] - 1,
            "obstruction": c[-1] ** 2}


def circle_positions(entry, x1_y: np.ndarray) -> np.ndarray:
    """Positions of the chain with bar A_n–X_n removed for prescribed y of X₁, by successive
    circle intersections (an independent forward solution of the finite mechanism).

    X₁ is on the circle (A₁, a₁) at the given y; X_{j+1} is the intersection of the circles
    (X_j, b_j) and (A_{j+1}, a_{j+1}) — (X_{n+1}, b_n) for X_n, whose bar to A_n is removed —
    nearest the start state.  Returns the free joints X₁ … X_n, shape (state, n, 2).
    """
    x0 = entry.coords
    n = (x0.shape[0] - 1) // 2
    A = x0[n + 1:]
    L = member_lengths(x0, entry.bars)
    a = [L[2 * j] for j in range(n - 1)]          # A_j–X_j, j < n
    b = [L[2 * j + 1] for j in range(n - 1)] + [L[-1]]
    out = np.zeros((len(x1_y), n, 2))
    for k, y in enumerate(np.asarray(x1_y, float)):
        dy = y - A[0, 1]
        X = [A[0] + [np.sqrt(a[0] ** 2 - dy ** 2), dy]]
        for j in range(1, n):
            c, r = (A[j], a[j]) if j < n - 1 else (x0[n], b[n - 1])
            X.append(_intersect(X[-1], b[j - 1], c, r, x0[j]))
        out[k] = X
    return out


def _intersect(p: np.ndarray, rp: float, q: np.ndarray, rq: float, near: np.ndarray):
    """The intersection of circles (p, rp) and (q, rq) nearest ``near``."""
    w = q - p
    d = np.linalg.norm(w)
    along = (rp * rp - rq * rq + d * d) / (2 * d)
    h = np.sqrt(max(rp * rp - along * along, 0.0))
    u = w / d
    perp = np.array([-u[1], u[0]])
    cands = [p + along * u + h * perp, p + along * u - h * perp]
    return min(cands, key=lambda z: np.linalg.norm(z - near))


def hortobagyi_section7(max_pairs: int = 6, steps: int = 12) -> dict:
    """Orders of the section-7 chains, by computation and by recursion, and the finite
    mechanism left when a bar is removed.

    Returns
    -------
    dict
        ``chain_<n>`` for n = 1 … ``max_pairs``: ``order`` computed (−1 when undecided),
        ``recursion`` (2ⁿ − 1 by
        :func:`section7_recursion`), ``leading`` the computed coefficient of X_n's motion across
        its pair at order 2ⁿ⁻¹ and ``leading_recursion`` c_n; ``chain_14``: the recursion's
        order and the computed lower bound ``checked`` (status undecided: 16383 is beyond
        floating point); ``minus1``: the 14-pair chain without bar A₁₄–X₁₄ — its self-stress
        count, whether the order is infinite, and a traced motion (``rank_min``,
        ``rank_max``, ``misfit`` of the bar lengths, ``circle_error`` the largest distance from
        the circle-intersection positions, ``x1_y_end`` the drive's travel).
    """
    out: dict = {}
    for n in range(1, max_pairs + 1):
        e = section7_chain(n)
        o = mechanism_order(e.coords, e.bars, e.free, max_order=2 ** n + 1)
        rec = section7_recursion(n, first=Fraction(1))
        # X_n's coordinate across pair n: y for odd n (pair along x), x for even n
        col = (n - 1) * 2 + (0 if n % 2 == 0 else 1)
        lead = float(o.series[2 ** (n - 1) - 1, col]) if o.series.shape[0] >= 2 ** (n - 1) \
            else float("nan")
        out[f"chain_{n}"] = {"order": o.order if o.order is not None else -1,
                             "recursion": rec["order"], "leading": lead,
                             "leading_recursion": float(rec["coefficients"][-1]),
                             "obstruction": o.obstruction}
    e = CATALOGUE[f"mech_sec7_chain_{PAPER_PAIRS}"]
    o = mechanism_order(e.coords, e.bars, e.free)
    out["chain_14"] = {"recursion": section7_recursion(PAPER_PAIRS)["order"],
                       "checked": o.checked, "undecided": int(o.status == "undecided")}
    e = CATALOGUE[f"mech_sec7_chain_{PAPER_PAIRS}_minus1"]
    r = rank_analysis(e.coords, e.bars, e.free)
    o = mechanism_order(e.coords, e.bars, e.free, rank=r)
    t = trace_mechanism(e.coords, e.bars, e.free, [e.drive_index()], e.step, steps)
    ref = circle_positions(e, t.coords[:, 0, 1])
    n = PAPER_PAIRS
    L0 = member_lengths(e.coords, e.bars)
    out["minus1"] = {"mechanisms": r.mechanisms, "self_stress": r.self_stress_states,
                     "order_infinite": int(o.status == "finite"),
                     "rank_min": int(t.rank.min()), "rank_max": int(t.rank.max()),
                     "misfit": float(np.max(np.abs(member_lengths(t.coords, e.bars) - L0))),
                     "circle_error": float(np.max(np.abs(t.coords[:, :n] - ref))),
                     "x1_y_end": float(t.coords[-1, 0, 1] - e.coords[0, 1])}
    return out
