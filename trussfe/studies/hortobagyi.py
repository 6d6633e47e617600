# SPDX-License-Identifier: MIT
"""Hortobágyi (1999): the examples of sections 4, 6, 8 and 9, as plain dicts of numbers.

The validation cases ``validation/cases/mech_hortobagyi_section4.toml``,
``mech_constructions.toml`` and ``mech_sec6_unfolding.toml`` point at these functions
(``python = "trussfe.studies.hortobagyi:<name>"``) and compare entries of the returned dict
with the paper's values; the tests call them directly.  The assemblies come from the
catalogue :mod:`trussfe.models.mechanisms`.
"""
from __future__ import annotations

import numpy as np

from ..errors import AnalysisError, TrussfeError
from ..kinematics.compatibility import compatibility_matrix
from ..kinematics.mechanism import _jacobian, compatibility_error
from ..kinematics.rank import rank_analysis
from ..kinematics.trace import trace_mechanism
from ..kinematics.unfolding import tangent_cone
from ..mechanics.geometry import member_lengths
from ..models.mechanisms import CATALOGUE, section6_foldable
from ..io.output import working_folder

# --------------------------------------------------------------------------- Hortobágyi sec. 4
#: Hortobágyi section 4 assembly with l = 1: joints 1, 2 free; 3 at the origin and 4 at (l, 0)
#: fixed; bars b1 = 1–2, b2 = 3–1, b3 = 4–2.  Folded state: 1 at (l, 0) on top of 4, 2 at (2l, 0).
SECTION4_COORDS = np.array([[1.0, 0.0], [2.0, 0.0], [0.0, 0.0], [1.0, 0.0]])
SECTION4_BARS = np.array([[0, 1], [2, 0], [3, 1]])
SECTION4_FREE = np.array([[1, 1], [1, 1], [0, 0], [0, 0]], dtype=bool)


def _paper_iteration(independent: int, increment: float, *, newton: bool, tolerance: float,
                     max_iterations: int = 60) -> dict:
    """The section-4 iteration in the paper's sign convention (B_paper = −B, t_paper = −t).

    d1⁽¹⁾ = −B11⁻¹ B12 d2 with B at the folded state plus the prescribed increment (eq. 4),
    then d1 ← d1 − B11⁻¹ t⁽ⁿ⁾ (incremental eq. 6) until max|t| ≤ tolerance (eq. 7).
    """
    x, conn, free = SECTION4_COORDS, SECTION4_BARS, SECTION4_FREE
    L = np.ones(3)
    dep = [k for k in range(4) if k != independent]

    def full(d):
        return np.concatenate([d, np.zeros(4)]).reshape(4, 2)

    pred = np.zeros(4)
    pred[independent] = increment
    Bp = -compatibility_matrix(x + full(pred), conn, free).toarray()
    B11, B12 = Bp[:, dep], Bp[:, independent]
    B11inv = np.linalg.inv(B11)
    d = pred.copy()
    d[dep] = -B11inv @ B12 * increment
    iterates, errors = [d.copy()], []
    converged_at = None
    M = B11
    for n in range(1, max_iterations + 1):
        t = -compatibility_error(x, conn, L, full(d))
        errors.append(t)
        if np.max(np.abs(t)) <= tolerance:
            converged_at = n
            break
        if newton:
            M = -_jacobian(x + full(d), conn, L, free).toarray()[:, dep]
        d = d.copy()
        d[dep] -= np.linalg.solve(M, t)
        iterates.append(d.copy())
    # corrections made = error evaluations − 1 (the last one only confirms convergence)
    return {"B": Bp, "B11inv": B11inv, "B11invB12": B11inv @ B12, "iterates": iterates,
            "errors": errors, "corrections": None if converged_at is None else converged_at - 1,
            "d": d}


def _denominator(v: float) -> float | None:
    """The paper prints small numbers as l/q: return q (None for a zero up to round-off)."""
    return float(1.0 / v) if abs(v) > 1e-15 else None


def hortobagyi_section4(tolerance: float = 1e-14) -> dict:
    """Hortobágyi (1999) section 4: both paths from the folded state, l = 1.

    Returns
    -------
    dict
        ``rank_folded`` (2), ``rank_after`` (3 on each path), ``path1`` / ``path2`` with the
        paper's matrix entries, the first iterates (as ``l/value`` denominators, paper sign), the
        converged coordinates, the iteration counts with frozen and refreshed B11, and the
        coordinates after the paper's fifth iterate; ``trace`` with the same two paths followed
        by :func:`~trussfe.kinematics.trace.trace_mechanism` (branches 0 and 1).

    Notes
    -----
    Misprints found by recomputing: eq. (6) as printed has the linear prediction as its fixed
    point (the worked numbers use ``d1 ← d1 − B11⁻¹ t``); ``d1⁽²⁾ = −d1⁽¹⁾ + Δd1⁽¹⁾`` should read
    ``+d1⁽¹⁾``; the third entry of d1⁽²⁾ is −l/9.85, not l/9.85; t₂⁽²⁾ is l/78 835, not l/80 002
    (path 2's l/78 841 is the same number rounded differently); the final x2 = 2l − l/199.6 of
    path 1 is the unconverged fifth iterate — the converged value is 2l − l/199.499 (= l·(1 +
    √0.99)).
    """
    x, conn, free = SECTION4_COORDS, SECTION4_BARS, SECTION4_FREE
    out: dict = {}
    out["rank_folded"] = rank_analysis(x, conn, free).rank
    for name, indep, labels in (("path1", 1, ("11", "21", "22")), ("path2", 3, ("11", "12", "21"))):
        it = _paper_iteration(indep, -0.1, newton=False, tolerance=tolerance)
        nt = _paper_iteration(indep, -0.1, newton=True, tolerance=tolerance)
        dep = [k for k in range(4) if k != indep]
        d = nt["d"]
        xf = x.copy()
        xf[:2] += d.reshape(2, 2)
        p = {
            "B": {f"b{i + 1}_{c}": float(it["B"][i, j]) for i in range(3)
                  for j, c in enumerate(("11", "12", "21", "22"))},
            "B11inv": {f"r{i + 1}_c{j + 1}": float(it["B11inv"][i, j]) for i in range(3)
                       for j in range(3)},
            "B11invB12": [float(v) for v in it["B11invB12"]],
            "iterates": [{lab: _denominator(v) for lab, v in zip(labels, dd[dep])}
                         for dd in it["iterates"][:5]],
            "errors": [[_denominator(v) for v in t] for t in it["errors"][:5]],
            "iterations_frozen": it["corrections"],
            "iterations_newton": nt["corrections"],
            "x1": float(xf[0, 0]), "y1": float(xf[0, 1]),
            "x2": float(xf[1, 0]), "y2": float(xf[1, 1]),
            "rank_after": rank_analysis(xf, conn, free).rank,
        }
        fifth = it["iterates"][4] if len(it["iterates"]) > 4 else it["iterates"][-1]
        p["fifth_iterate_x2"] = float(x[1, 0] + fifth[2])
        bars = member_lengths(xf, conn)
        p["max_bar_misfit"] = float(np.max(np.abs(bars - 1.0)))
        out[name] = p
    tr = {}
    for br in (0, 1):
        r = trace_mechanism(x, conn, free, drives=[1], step=-0.1, steps=1, branch=br,
                            tolerance=tolerance)
        c = r.coords[-1]
        tr[f"branch{br}"] = {"x1": float(c[0, 0]), "y1": float(c[0, 1]), "x2": float(c[1, 0]),
                             "y2": float(c[1, 1]), "rank_start": int(r.rank[0]),
                             "rank_end": int(r.rank[-1]), "iterations": int(r.iterations[0]),
                             "events": [e["kind"] for e in r.events]}
    out["trace"] = tr
    return out


# --------------------------------------------------------------------------- sections 6, 8, 9
def hortobagyi_constructions() -> dict:
    """Rank counts and motion of the constructed assemblies of sections 6, 8, 9 and Bricard's
    octahedron (catalogue :mod:`trussfe.models.mechanisms`).

    Returns
    -------
    dict
        Per entry ``rank``, ``infinitesimal`` (μ·j − ρ(B)), ``self_stress``; for section 8 the
        ranks before and after a downward step and whether an upward step was refused; for
        section 9 the number of bifurcations detected while the crank passes 180°; for Bricard
        the bar-length misfit after 60 steps.
    """
    out: dict = {}
    for name in ("mech_sec6_foldable", "mech_sec6_foldable_minus1", "mech_sec6_foldable_minus3",
                 "mech_sec8_compound", "mech_sec9_space", "mech_bricard"):
        e = CATALOGUE[name]
        r = rank_analysis(e.coords, e.bars, e.free)
        out[name] = {"rank": r.rank, "infinitesimal": r.infinitesimal_motions,
                     "self_stress": r.self_stress_states, "joints": int(e.free.any(axis=1).sum()),
                     "bars": len(e.bars)}
    e = CATALOGUE["mech_sec8_compound"]
    t = trace_mechanism(e.coords, e.bars, e.free, [e.drive_index()], e.step, 20)
    out["mech_sec8_compound"].update(rank_after=int(t.rank[-1]),
                                     y_left_after=float(t.coords[-1, 4, 1]),
                                     y_right_after=float(t.coords[-1, 10, 1]))
    try:
        trace_mechanism(e.coords, e.bars, e.free, [e.drive_index()], -e.step, 20)
        refused = 0
    except AnalysisError:
        refused = 1
    out["mech_sec8_compound"]["upward_refused"] = refused
    e = CATALOGUE["mech_sec9_space"]
    t = trace_mechanism(e.coords, e.bars, e.free, [e.drive_index()], e.step, 30)
    ang = np.degrees(np.arctan2(t.coords[:, 0, 1], t.coords[:, 0, 0])) % 360
    out["mech_sec9_space"].update(
        bifurcations=sum(ev["kind"] == "bifurcation" for ev in t.events),
        crank_angle_start=float(ang[0]), crank_angle_end=float(ang[-1]))
    e = CATALOGUE["mech_bricard"]
    t = trace_mechanism(e.coords, e.bars, e.free, [e.drive_index()], e.step, 60)
    L0 = member_lengths(e.coords, e.bars)
    L = member_lengths(t.coords, e.bars)
    out["mech_bricard"].update(misfit=float(np.max(np.abs(L - L0))),
                               rank_min=int(t.rank.min()), rank_max=int(t.rank.max()))
    return out


# --------------------------------------------------------------------------- Hortobágyi sec. 6
def section6_unfolding_traces(remove: int = 0, *, step: float = 0.05, steps: int = 12):
    """The four unfolding shapes of the section-6 construction with bar ``remove + 1`` removed.

    For each inner joint Pi the unfolding direction (second-order tangent cone, see
    :mod:`trussfe.kinematics.unfolding`) nearest its vertical infinitesimal mechanism gives the
    four prescribed vertical increments (largest = ``step``); :func:`trace_mechanism` follows
    the motion from the folded state with those four drives (Hortobágyi section 6: "prescribe
    the vertical co-ordinate increments of the four inner nodes").

    Returns
    -------
    entry : MechanismEntry
    cone : TangentCone
    traces : list of (increments, TraceResult)
        One per inner joint, in joint order.
    """
    e = section6_foldable(remove)
    cone = tangent_cone(e.coords, e.bars, e.free)
    D = cone.directions                                    # rows: unit, free coords (x, y)...
    drives = [i * 2 + 1 for i in range(4)]                 # Pi:y, flat indices
    traces = []
    for i in range(4):
        line = int(np.argmax(np.abs(D[:, 2 * i + 1])))
        vy = D[line, 1::2]
        vy = vy * np.sign(vy[i])
        S = step * vy / np.abs(vy).max()
        traces.append((S, trace_mechanism(e.coords, e.bars, e.free, drives, S, steps)))
    return e, cone, traces


def _section6_figure(results: dict) -> dict:
    """Node trajectories of the four unfolding shapes (two rows: the two removed bars)."""

    from ..io.figures import subplots
    fig, axes = subplots(len(results), 4, figsize=(14, 1.0 + 1.3 * len(results)), squeeze=False)
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:red"]
    for row, (remove, (e, _cone, traces)) in enumerate(results.items()):
        for col, (S, t) in enumerate(traces):
            ax = axes[row, col]
            X = t.coords
            for a, b in e.bars:                            # folded and final states
                ax.plot(X[0, [a, b], 0], X[0, [a, b], 1], color="0.8", lw=3, zorder=1)
                ax.plot(X[-1, [a, b], 0], X[-1, [a, b], 1], color="0.25", lw=1.2, zorder=2)
            for j in range(4):
                ax.plot(X[:, j, 0], X[:, j, 1], ".-", ms=3, color=colours[j], lw=1,
                        label=f"P{j + 1}", zorder=3)
            ax.plot(X[0, 4:, 0], X[0, 4:, 1], "k^", ms=6, zorder=4)
            ax.set_aspect("equal")
            ax.set_title(f"bar {remove + 1} removed: direction nearest P{col + 1} up", fontsize=9)
            ax.tick_params(labelsize=7)
    axes[0, 0].legend(fontsize=7, loc="upper left")
    fig.suptitle("Hortobágyi section 6 (construction): four unfolding shapes from the folded "
                 "state (grey) — trajectories of P1–P4, final state dark", fontsize=10)
    fig.tight_layout()
    path = working_folder("trussfe_sec6_") / "section6_unfolding.png"
    fig.savefig(path, dpi=110)
    return {"section6_unfolding": str(path)}


def hortobagyi_section6(figures: bool = True) -> dict:
    """Section 6 (construction): rank counts, unfolding directions and the four traced shapes.

    Returns
    -------
    dict
        ``full``: rank, μ·j − ρ(B), self-stress states and real unfolding directions of the
        eight-bar assembly, and whether a trace is refused; per removed bar
        (``minus1``, ``minus3``): the same counts at the folded state, ``shapes`` (distinct
        traced shapes), ``rank_after`` (min and max of ρ(B) after the first step),
        ``misfit`` (largest bar-length error along all four traces, m),
        ``min_shape_distance`` (smallest distance between two final shapes, m) and
        ``figures``.
    """
    out: dict = {}
    e = section6_foldable()
    r = rank_analysis(e.coords, e.bars, e.free)
    cone = tangent_cone(e.coords, e.bars, e.free)
    try:
        trace_mechanism(e.coords, e.bars, e.free, [1, 3, 5, 7], [0.05, 0.02, 0.01, 0.005], 3)
        refused = 0
    except TrussfeError:
        refused = 1
    out["full"] = {"rank": r.rank, "infinitesimal": r.infinitesimal_motions,
                   "self_stress": r.self_stress_states, "unfolding_directions":
                   len(cone.directions), "trace_refused": refused}
    results = {}
    for remove in (0, 2):
        e, cone, traces = section6_unfolding_traces(remove)
        results[remove] = (e, cone, traces)
        r = rank_analysis(e.coords, e.bars, e.free)
        L0 = member_lengths(e.coords, e.bars)
        misfit = max(float(np.abs(np.linalg.norm(t.coords[:, e.bars[:, 1]]
                                                 - t.coords[:, e.bars[:, 0]], axis=2)
                                  - L0).max()) for _, t in traces)
        finals = np.array([t.coords[-1].ravel() for _, t in traces])
        dist = np.linalg.norm(finals[:, None] - finals[None], axis=2)
        dmin = float(dist[np.triu_indices(4, 1)].min())
        after = np.concatenate([t.rank[1:] for _, t in traces])
        out[f"minus{remove + 1}"] = {
            "rank": r.rank, "infinitesimal": r.infinitesimal_motions,
            "self_stress": r.self_stress_states, "unfolding_directions": len(cone.directions),
            "shapes": int(np.sum(dist[np.triu_indices(4, 1)] > 1e-3) == 6) * 4,
            "rank_after_min": int(after.min()), "rank_after_max": int(after.max()),
            "misfit": misfit, "min_shape_distance": dmin}
    if figures:
        out["figures"] = _section6_figure(results)
    return out


def section6_direction_counts(samples: int = 200, seed: int = 0, starts: int = 150) -> dict:
    """How many real unfolding directions folded assemblies of the section-6 graph have.

    Random folded states of the graph of :func:`trussfe.models.mechanisms.section6_foldable`
    (inner and ground joints at distinct half-integer positions in [0, 6]), each ground bar
    removed in turn; only states where the eight-bar assembly is second-order rigid (cannot
    move, as the text requires) and the reduced one has simple roots only are counted.

    Returns
    -------
    dict
        Number of real unfolding directions (lines; each with its mirror image) → number of
        (state, removed bar) pairs.  The text's "two unfolding shapes, symmetrical pairs of
        these are the other two" needs 2.
    """
    rng = np.random.default_rng(seed)
    bars = np.array([(0, 4), (1, 5), (2, 6), (3, 7), (0, 1), (1, 2), (2, 3), (3, 0)])
    free = np.zeros((8, 2), bool)
    free[:4] = True
    hist: dict = {}
    done = 0
    while done < samples:
        xs = rng.choice(np.arange(13) / 2.0, 8, replace=False)
        X = np.column_stack([xs, np.zeros(8)])
        if len(tangent_cone(X, bars, free, starts=20).directions):
            continue                                       # the full assembly must be rigid
        done += 1
        for k in range(4):
            c = tangent_cone(X, np.delete(bars, k, axis=0), free, starts=starts, seed=done)
            if c.simple.all():
                hist[len(c.directions)] = hist.get(len(c.directions), 0) + 1
    return dict(sorted(hist.items()))
