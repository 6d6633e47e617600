# SPDX-License-Identifier: MIT
"""Reproductions of the published examples and closed-form checks, as plain dicts of numbers.

The validation cases ``validation/cases/mech_*.toml`` point at these functions
(``python = "trussfe.kinematics.reproductions:<name>"``) and compare entries of the returned
dict with published or analytic values; the tests call them directly.
"""
from __future__ import annotations

import numpy as np

from .compatibility import compatibility_matrix
from .mechanism import _jacobian, compatibility_error
from .rank import rank_analysis
from .topology import cycle_kinematics, equivalent_assembly
from .trace import trace_mechanism
from .velocity import bar_angular_velocity, mechanism_acceleration, mechanism_velocity

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
        bars = np.linalg.norm(xf[conn[:, 1]] - xf[conn[:, 0]], axis=1)
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


# --------------------------------------------------------------------------- four-bar
#: Crank-rocker four-bar (Grashof: 1 + 3.2 ≤ 2.6 + 3): ground 3, crank 1, coupler 3.2, rocker 2.6.
FOURBAR = {"ground": 3.0, "crank": 1.0, "coupler": 3.2, "rocker": 2.6}


def fourbar_position(theta: np.ndarray, a=1.0, b=3.2, c=2.6, d=3.0) -> tuple[np.ndarray, ...]:
    """Closed-form open-branch position of a four-bar: pin B and joint C for crank angle θ.

    Ground pivots A = (0, 0) and D = (d, 0); C is the intersection of the circles (B, b) and
    (D, c) on the left of B→D (above the ground for the open configuration).
    """
    th = np.asarray(theta, float)
    B = a * np.stack([np.cos(th), np.sin(th)], axis=-1)
    D = np.array([d, 0.0])
    w = D - B
    delta = np.linalg.norm(w, axis=-1)
    u = w / delta[..., None]
    along = (b * b - c * c + delta ** 2) / (2 * delta)
    h = np.sqrt(b * b - along ** 2)
    uperp = np.stack([-u[..., 1], u[..., 0]], axis=-1)
    C = B + along[..., None] * u + h[..., None] * uperp
    return B, C


def fourbar_rates(theta, omega=1.0, alpha=0.0, a=1.0, b=3.2, c=2.6, d=3.0) -> dict:
    """Closed-form angular velocities and accelerations of coupler (3) and rocker (4).

    Vector loop ``a e^{iθ2} + b e^{iθ3} − c e^{iθ4} − d = 0`` differentiated (Norton,
    *Design of Machinery*, eq. 6.18 and 7.12 in this notation).
    """
    B, C = fourbar_position(theta, a, b, c, d)
    t2 = np.asarray(theta, float)
    t3 = np.arctan2(C[..., 1] - B[..., 1], C[..., 0] - B[..., 0])
    t4 = np.arctan2(C[..., 1], C[..., 0] - d)
    w3 = a * omega * np.sin(t4 - t2) / (b * np.sin(t3 - t4))
    w4 = a * omega * np.sin(t2 - t3) / (c * np.sin(t4 - t3))
    A_ = c * np.sin(t4)
    B_ = b * np.sin(t3)
    C_ = (a * alpha * np.sin(t2) + a * omega ** 2 * np.cos(t2) + b * w3 ** 2 * np.cos(t3)
          - c * w4 ** 2 * np.cos(t4))
    D_ = c * np.cos(t4)
    E_ = b * np.cos(t3)
    F_ = (a * alpha * np.cos(t2) - a * omega ** 2 * np.sin(t2) - b * w3 ** 2 * np.sin(t3)
          + c * w4 ** 2 * np.sin(t4))
    a3 = (C_ * D_ - A_ * F_) / (A_ * E_ - B_ * D_)
    a4 = (C_ * E_ - B_ * F_) / (A_ * E_ - B_ * D_)
    vC = c * w4[..., None] * np.stack([-np.sin(t4), np.cos(t4)], axis=-1)
    aC = (c * a4[..., None] * np.stack([-np.sin(t4), np.cos(t4)], axis=-1)
          - c * (w4 ** 2)[..., None] * np.stack([np.cos(t4), np.sin(t4)], axis=-1))
    return {"omega3": w3, "omega4": w4, "alpha3": a3, "alpha4": a4, "vC": vC, "aC": aC}


def _fourbar_model(theta0: float):
    p = FOURBAR
    B, C = fourbar_position(theta0, p["crank"], p["coupler"], p["rocker"], p["ground"])
    x = np.array([[0.0, 0.0], B, C, [p["ground"], 0.0]])
    conn = np.array([[0, 1], [1, 2], [3, 2]])               # crank, coupler, rocker (D→C)
    free = np.array([[0, 0], [1, 1], [1, 1], [0, 0]], dtype=bool)
    return x, conn, free


def fourbar_closed_form(samples: int = 12, omega: float = 2.0, alpha: float = 0.5,
                        step: float = 0.02, steps: int = 330) -> dict:
    """A crank-rocker four-bar over a full crank turn against the closed form.

    Traces the bar assembly with :func:`trace_mechanism` (drive: crank pin y) and compares the
    joint C of every traced state with the closed-form position at the same crank angle; at
    ``samples`` crank angles compares ω, α of coupler and rocker and C's velocity and
    acceleration from the compatibility matrix and from the cycle equations (Vlase) with the
    closed form.

    Returns
    -------
    dict
        ``position_max_error`` (m), ``crank_turn`` (rad covered), ``velocity_max_error``,
        ``acceleration_max_error`` (compatibility method), ``cycle_velocity_max_error``,
        ``cycle_acceleration_max_error`` (cycle method), ``methods_max_difference`` and
        ``limit_points`` (events of the drive coordinate; the crank pin y turns back twice per
        turn), ``bar_length_misfit``.
    """
    p = FOURBAR
    a, b, c, d = p["crank"], p["coupler"], p["rocker"], p["ground"]
    x, conn, free = _fourbar_model(0.0)
    r = trace_mechanism(x, conn, free, drives=[3], step=step, steps=steps)
    th = np.unwrap(np.arctan2(r.coords[:, 1, 1], r.coords[:, 1, 0]))
    _, Cref = fourbar_position(th, a, b, c, d)
    L0 = np.linalg.norm(x[conn[:, 1]] - x[conn[:, 0]], axis=1)
    Ls = np.linalg.norm(r.coords[:, conn[:, 1]] - r.coords[:, conn[:, 0]], axis=2)
    out = {"position_max_error": float(np.max(np.abs(r.coords[:, 2] - Cref))),
           "crank_turn": float(th.max() - th.min()),
           "bar_length_misfit": float(np.max(np.abs(Ls - L0))),
           "limit_points": sum(e["kind"] == "limit_point" for e in r.events)}
    thetas = np.linspace(0.0, 2 * np.pi, samples, endpoint=False) + 0.1
    ref = fourbar_rates(thetas, omega, alpha, a, b, c, d)
    ev = ea = cv = ca = md = 0.0
    for k, t in enumerate(thetas):
        xs, _, _ = _fourbar_model(t)
        vB = a * omega * np.array([-np.sin(t), np.cos(t)])
        aB = a * alpha * np.array([-np.sin(t), np.cos(t)]) - a * omega ** 2 * np.array(
            [np.cos(t), np.sin(t)])
        v = mechanism_velocity(xs, conn, free, {2: vB[0], 3: vB[1]})
        acc = mechanism_acceleration(xs, conn, free, v, {2: aB[0], 3: aB[1]})
        w = bar_angular_velocity(xs, conn, v)
        ev = max(ev, abs(w[1] - ref["omega3"][k]), abs(w[2] - ref["omega4"][k]),
                 *np.abs(v[2] - ref["vC"][k]))
        ea = max(ea, *np.abs(acc[2] - ref["aC"][k]))
        eq = equivalent_assembly(xs, conn, ground=[0, 3])
        ck = cycle_kinematics(eq, drive_edge=0, omega=omega, alpha=alpha)
        cv = max(cv, abs(ck.omega[1] - ref["omega3"][k]), abs(ck.omega[2] - ref["omega4"][k]),
                 *np.abs(ck.velocity[2] - ref["vC"][k]))
        ca = max(ca, abs(ck.alpha[1] - ref["alpha3"][k]), abs(ck.alpha[2] - ref["alpha4"][k]),
                 *np.abs(ck.acceleration[2] - ref["aC"][k]))
        md = max(md, float(np.max(np.abs(ck.velocity[:4] - v))),
                 float(np.max(np.abs(ck.acceleration[:4] - acc))))
    out.update(velocity_max_error=float(ev), acceleration_max_error=float(ea),
               cycle_velocity_max_error=float(cv), cycle_acceleration_max_error=float(ca),
               methods_max_difference=float(md))
    return out


# --------------------------------------------------------------------------- slider-crank
SLIDER_CRANK = {"crank": 1.0, "rod": 3.0}


def slider_crank_closed_form(samples: int = 12, omega: float = 2.0, step: float = 0.02,
                             steps: int = 300) -> dict:
    """A slider-crank as a bar assembly (slider = joint on a roller) over a full crank turn.

    Closed form, crank r, rod l, slider on the x axis through the crank pivot:
    ``x = r cos θ + √(l² − r² sin²θ)``, ``v = ω dx/dθ``, ``a = ω² d²x/dθ²`` (uniform ω).
    Compatibility-matrix and cycle-equation (Vlase, slider edge of variable length) velocities
    and accelerations are compared with it at ``samples`` crank angles.
    """
    r_, l_ = SLIDER_CRANK["crank"], SLIDER_CRANK["rod"]

    def xs(t):
        s, c = np.sin(t), np.cos(t)
        S = np.sqrt(l_ ** 2 - r_ ** 2 * s ** 2)
        x = r_ * c + S
        dx = -r_ * s - r_ ** 2 * s * c / S
        ddx = -r_ * c - r_ ** 2 * (c * c - s * s) / S - r_ ** 4 * s * s * c * c / S ** 3
        return x, dx, ddx

    def model(t):
        x = np.array([[0.0, 0.0], [r_ * np.cos(t), r_ * np.sin(t)], [xs(t)[0], 0.0]])
        return x

    conn = np.array([[0, 1], [1, 2]])
    free = np.array([[0, 0], [1, 1], [1, 0]], dtype=bool)
    res = trace_mechanism(model(0.3), conn, free, drives=[3], step=step, steps=steps)
    th = np.unwrap(np.arctan2(res.coords[:, 1, 1], res.coords[:, 1, 0]))
    out = {"position_max_error": float(np.max(np.abs(res.coords[:, 2, 0] - xs(th)[0]))),
           "crank_turn": float(th.max() - th.min())}
    ev = ea = cv = ca = 0.0
    for t in np.linspace(0.0, 2 * np.pi, samples, endpoint=False) + 0.1:
        x = model(t)
        vB = r_ * omega * np.array([-np.sin(t), np.cos(t)])
        aB = -r_ * omega ** 2 * np.array([np.cos(t), np.sin(t)])
        v = mechanism_velocity(x, conn, free, {2: vB[0], 3: vB[1]})
        a = mechanism_acceleration(x, conn, free, v, {2: aB[0], 3: aB[1]})
        _, dx, ddx = xs(t)
        ev = max(ev, abs(v[2, 0] - omega * dx))
        ea = max(ea, abs(a[2, 0] - omega ** 2 * ddx))
        eq = equivalent_assembly(x, conn, ground=[0], sliders={2: np.array([1.0, 0.0])})
        ck = cycle_kinematics(eq, drive_edge=0, omega=omega)
        cv = max(cv, abs(ck.velocity[2, 0] - omega * dx), abs(ck.length_rate[2] - omega * dx))
        ca = max(ca, abs(ck.acceleration[2, 0] - omega ** 2 * ddx))
    out.update(velocity_max_error=float(ev), acceleration_max_error=float(ea),
               cycle_velocity_max_error=float(cv), cycle_acceleration_max_error=float(ca),
               slider_travel=float(res.coords[:, 2, 0].max() - res.coords[:, 2, 0].min()))
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
    from ..errors import AnalysisError
    from ..models.mechanisms import CATALOGUE
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
    L0 = np.linalg.norm(e.coords[e.bars[:, 1]] - e.coords[e.bars[:, 0]], axis=1)
    L = np.linalg.norm(t.coords[:, e.bars[:, 1]] - t.coords[:, e.bars[:, 0]], axis=2)
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
    from ..models.mechanisms import section6_foldable
    from .unfolding import tangent_cone
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
    import tempfile
    from pathlib import Path

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(len(results), 4, figsize=(14, 1.0 + 1.3 * len(results)), squeeze=False)
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
    path = Path(tempfile.mkdtemp(prefix="trussfe_sec6_")) / "section6_unfolding.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
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
    from ..errors import TrussfeError
    from ..models.mechanisms import section6_foldable
    from .unfolding import tangent_cone
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
        L0 = np.linalg.norm(e.coords[e.bars[:, 1]] - e.coords[e.bars[:, 0]], axis=1)
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
    from .unfolding import tangent_cone
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
