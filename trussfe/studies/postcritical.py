# SPDX-License-Identifier: MIT
"""Validation studies of the post-critical analysis, each against an independent solution.

Every function returns a flat dict of numbers (and optionally ``figures``) for the validation
suite (``validation/cases/postcritical_*.toml``) and the tests:

* :func:`von_mises_truss` — the two-bar shallow truss against its closed form;
* :func:`euler_column` — the imperfect and the perfect pin-ended column against the elastica;
* :func:`lattice_progressive` — the lattice dome that loses bars until it is a mechanism;
* :func:`linear_buckling_agreement` — first linear buckling load factor against the Euler load,
  the nonlinear path's bifurcation and (when present) the FE core's eigen solution.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from .._resources import mesh_path
from ..io.model_file import read_model
from ..mechanics.euler import euler_load, member_euler_loads
from ..nonlinear.analysis import run_postcritical
from ..nonlinear.buckling import linear_buckling
from ..nonlinear.model import NonlinearModel
from ..nonlinear.path import follow_path
from ..io.output import working_folder


# ------------------------------------------------------------------------- closed forms
def von_mises_load(v: np.ndarray, a: float, h: float, EA: float) -> np.ndarray:
    """Apex load of the two-bar truss at the apex deflection ``v`` (downward positive).

    Notes
    -----
    With ``w = h − v``, ``ℓ = √(a² + w²)``, ``L = √(a² + h²)`` and the engineering-strain bar
    ``N = EA(ℓ − L)/L`` (the co-rotational truss), vertical equilibrium of the apex gives

    .. math:: P(v) = 2 EA\\, w \\left(\\frac{1}{\\ell} - \\frac{1}{L}\\right)

    Examples
    --------
    >>> float(von_mises_load(np.array([0.1]), 1.0, 0.1, 1e6)[0])   # flat: no load carried
    0.0
    """
    L = math.hypot(a, h)
    w = h - np.asarray(v, dtype=float)
    return 2.0 * EA * w * (1.0 / np.hypot(a, w) - 1.0 / L)


def von_mises_limit(a: float, h: float, EA: float) -> tuple[float, float]:
    """Limit load and apex deflection of the two-bar truss (``dP/dv = 0``).

    ``dP/dw = 2EA(a²/ℓ³ − 1/L) = 0`` gives ``ℓ³ = a² L``.

    >>> round(von_mises_limit(1.0, 0.1, 1e6)[0], 6)
    381.08719
    """
    L = math.hypot(a, h)
    lc = (a * a * L) ** (1.0 / 3.0)
    wc = math.sqrt(lc * lc - a * a)
    return float(von_mises_load(h - wc, a, h, EA)), h - wc


def elastica(load_ratio: float, length: float) -> tuple[float, float]:
    """Mid-span deflection and end shortening of the pin-ended inextensible elastica.

    Parameters
    ----------
    load_ratio : float
        ``P / P_E`` (> 1).
    length : float

    Notes
    -----
    With ``p = sin(α/2)`` (α the end slope) and the complete elliptic integrals ``K(p)``,
    ``E(p)``: ``P/P_E = (2K/π)²``, ``δ = pL/K``, end shortening ``L(2 − 2E/K)``
    (Timoshenko & Gere, *Theory of Elastic Stability*, §2.7).

    >>> d, s = elastica(1.0 + 1e-9, 1.0)
    >>> bool(d < 1e-3 and s < 1e-6)
    True
    """
    p = brentq(lambda p: (2.0 * ellipk(p * p) / math.pi) ** 2 - load_ratio, 1e-12,
               1.0 - 1e-12)
    K, E = ellipk(p * p), ellipe(p * p)
    return p * length / K, length * (2.0 - 2.0 * E / K)


def elastica_load_ratio(deflection_ratio: float) -> float:
    """``P/P_E`` of the elastica whose mid-span deflection is ``δ/L`` (inverse of δ = pL/K).

    ``p/K(p)`` rises monotonically to 0.401 at p = 0.8 (and peaks at about 0.4025), so
    ``δ/L`` up to 0.4 is inverted on that bracket.
    """
    p = brentq(lambda p: p / ellipk(p * p) - deflection_ratio, 1e-12, 0.8)
    return (2.0 * ellipk(p * p) / math.pi) ** 2


# ------------------------------------------------------------------------- studies
def _figure(result, name: str) -> dict:
    """The load–displacement plot of a path as a PNG in a temporary folder."""
    from ..nonlinear.plot import write_plot
    path = working_folder("trussfe_postcritical_") / f"{name}.png"
    write_plot(path, result)
    return {name: str(path)}


def von_mises_truss(steps: int = 400, step: float = 0.002, figures: bool = True) -> dict:
    """Two-bar shallow truss (``meshes/postcritical_von_mises.toml``) against the closed form.

    Returns the limit loads found on the path (located by the inertia change of the tangent),
    the closed-form limit load, and the largest deviation of the whole arc-length path
    (snap-through, unloading, negative branch, re-stiffening in tension) from ``P(v)``.
    """
    s = read_model(mesh_path("postcritical_von_mises.toml"))
    a = float(s.coords[2, 0])
    h = float(s.coords[1, 1])
    EA = float(s.E[0] * s.area[0])
    res = run_postcritical(s, steps=steps, step=step)
    lam = res.load_factors
    v = -res.displacement()
    P = von_mises_load(v, a, h, EA)
    Plim, vlim = von_mises_limit(a, h, EA)
    limits = [e for e in res.events if e.kind == "limit_point"]
    upper = max(limits, key=lambda e: e.load_factor)
    lower = min(limits, key=lambda e: e.load_factor)
    vu = -res.path[upper.point].u[res.monitor]
    return {
        "limit_load": float(upper.load_factor),
        "limit_load_closed_form": Plim,
        "limit_deflection": float(vu),
        "limit_deflection_closed_form": vlim,
        "lower_limit_load": float(lower.load_factor),
        "limit_points": len(limits),
        "path_max_error": float(np.abs(lam - P).max() / Plim),
        "path_points": len(lam),
        "final_deflection": float(v[-1]),
        **({"figures": _figure(res, "von_mises_path")} if figures else {}),
    }


def _imperfect_ratios(out: dict, d: np.ndarray, lam: np.ndarray) -> None:
    """Load ratio of the imperfect column at deflections 0.1, 0.2, 0.3 L (linear interpolation
    between path states; d grows monotonically here) beside the elastica's."""
    for target in (0.1, 0.2, 0.3):
        if d.max() < target:
            continue
        out[f"imperfect_load_ratio_at_{int(target * 10)}"] = float(np.interp(target, d, lam))
        out[f"elastica_load_ratio_at_{int(target * 10)}"] = elastica_load_ratio(target)


def _perfect_column(out: dict, perfect, pres, d: np.ndarray, ratio_ref: float,
                    extensible: float, upper: float) -> None:
    """The perfect column's bifurcation, linear buckling load and the largest deviation of its
    secondary branch from the elastica for 0.15 L < δ < ``upper``, as ratios to P_E."""
    bif = [e for e in pres.events if e.kind == "bifurcation"]
    out["bifurcation_load_ratio"] = float(bif[0].load_factor * ratio_ref) if bif else math.nan
    out["extensible_euler_ratio"] = extensible
    lf, _ = linear_buckling(perfect, count=1)
    out["linear_buckling_ratio"] = float(lf[0] * ratio_ref)
    lam = pres.load_factors * ratio_ref
    on = (d > 0.15) & (d < upper)
    if on.any():
        ref = np.array([elastica_load_ratio(x) for x in d[on]])
        out["branch_max_error"] = float(np.abs(lam[on] / ref - 1.0).max())
        out["branch_max_deflection"] = float(d.max())


def _column_figure(name: str, title: str, imperfect: tuple[np.ndarray, np.ndarray],
                   branch: tuple[np.ndarray, np.ndarray], upper: float) -> dict:
    """P/P_E against the mid-span deflection δ/L of the imperfect path and of the perfect
    column's secondary branch, with the elastica (Timoshenko & Gere §2.7), as a PNG in a
    temporary folder."""
    from ..io.figures import subplots
    from ..io.output import atomic_path

    fig, ax = subplots(figsize=(6.4, 4.6))
    x = np.linspace(1e-3, upper, 80)
    ax.plot(x, [elastica_load_ratio(v) for v in x], color="0.6", lw=3,
            label="elastica (Timoshenko & Gere)")
    ax.plot(*imperfect, ".-", ms=3, lw=1, label="imperfect column (L/1000)")
    ax.plot(*branch, "s", ms=3, mfc="none", label="perfect column, secondary branch")
    ax.set_xlim(0.0, upper * 1.05)
    ax.set_ylim(0.0, 1.6)
    ax.set_xlabel("mid-span deflection δ/L")
    ax.set_ylabel("load P/P_E")
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = working_folder("trussfe_postcritical_") / f"{name}.png"
    with atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=120, format="png")
    return {name: str(path)}


def euler_column(subdivisions: int = 16, figures: bool = True) -> dict:
    """Pin-ended column (``meshes/postcritical_euler_column.toml``) against the elastica.

    * imperfect column (L/1000 in the first mode): load ratio ``P/P_E`` at the points where the
      mid-span deflection is 0.1 L … 0.4 L, against the elastica at the same deflection;
    * perfect column with branching: the bifurcation load against the extensible-column value
      ``P_E (1 + P_E/EA)`` (the shortening before buckling raises it slightly), and the
      secondary branch against the elastica.
    """
    s = read_model(mesh_path("postcritical_euler_column.toml"))
    L = float(s.lengths()[0])
    Pe = float(euler_load(s.E[0], s.Iz[0], L))
    ratio_ref = -float(s.loads[1, 1]) / Pe              # reference load / P_E (= 1)
    out = {"reference_over_euler": ratio_ref}
    k = subdivisions
    res = run_postcritical(s, subdivisions=k, steps=200)
    m = res.model
    mid = m.dof(s.n_nodes + k // 2 - 1, 0)               # mid-span point, lateral
    d = np.abs(res.displacement(mid)) / L
    lam = res.load_factors * ratio_ref
    _imperfect_ratios(out, d, lam)
    # perfect column, branch at the bifurcation
    perfect = NonlinearModel(s, bar_model="pinned-beam", subdivisions=k)
    EA = float(s.E[0] * s.area[0])
    pres = follow_path(perfect, "arc-length", steps=60, max_load_factor=1.6, branch=True,
                       monitor=perfect.dof(1, 1))
    db = np.abs(pres.displacement(mid)) / L
    _perfect_column(out, perfect, pres, db, ratio_ref, 1.0 + Pe / EA, upper=0.4)
    if figures:
        out["figures"] = _column_figure("euler_column_paths", "pin-ended column (2-D)",
                                        (d, lam), (db, pres.load_factors * ratio_ref), 0.4)
    return out


def euler_column_3d(subdivisions: int = 16, figures: bool = True) -> dict:
    """The Euler column in 3-D (``meshes/postcritical_euler_column_3d.toml``): the 2-D study of
    :func:`euler_column` with 3-D co-rotational beams, the column's axis ``a = (1, 2, 2)/3``
    oblique to every global axis and its top guided along the axis by two long links.

    The section has the 2-D column's area and ``Iz`` but ``Iy = 2 Iz``, so that the column has
    one buckling plane (a tube's buckled shape could turn freely about the axis, a singular
    tangent all along the secondary branch); the deflection measured is the mid-span point's
    displacement perpendicular to the axis, ``|u − (u·a)a|``.
    """
    s = read_model(mesh_path("postcritical_euler_column_3d.toml"))
    L = float(s.lengths()[0])
    a = (s.coords[1] - s.coords[0]) / L
    Pe = float(member_euler_loads(s)[0])
    ratio_ref = float(-s.loads[1, :3] @ a) / Pe          # reference load / P_E (= 1)
    out = {"reference_over_euler": ratio_ref}
    k = subdivisions

    def lateral(res, m):
        mid = s.n_nodes + k // 2 - 1                      # the column is member 0
        u = np.array([p.u[m.dof(mid, 0): m.dof(mid, 0) + 3] for p in res.path])
        return np.linalg.norm(u - np.outer(u @ a, a), axis=1) / L

    res = run_postcritical(s, subdivisions=k, steps=200)
    d = lateral(res, res.model)
    lam = res.load_factors * ratio_ref
    _imperfect_ratios(out, d, lam)
    perfect = NonlinearModel(s, bar_model="truss", subdivisions=k)
    EA = float(s.E[0] * s.area[0])
    pres = follow_path(perfect, "arc-length", steps=80, max_load_factor=1.6, branch=True,
                       monitor=perfect.dof(1, 2))
    # up to δ = 0.35 L: δ/L(p) peaks at 0.4025, near which P(δ) is ill-conditioned
    db = lateral(pres, perfect)
    _perfect_column(out, perfect, pres, db, ratio_ref, 1.0 + Pe / EA, upper=0.35)
    if figures:
        out["figures"] = _column_figure("euler_column_3d_paths",
                                        "pin-ended column on an oblique axis (3-D)",
                                        (d, lam), (db, pres.load_factors * ratio_ref), 0.35)
    return out


def lattice_progressive(figures: bool = True) -> dict:
    """The lattice dome (``meshes/postcritical_dome.toml``) loses apex bars until it becomes a
    mechanism; checks that every event is justified and that the equilibrium form is the one
    the kinematics predicts.

    The four-bar loss leaves the apex hanging from two bars (A4, A6) whose far ends are held
    by the stiff ring: a pendulum about the axis through R4 and R6.  Under a vertical dead load
    its equilibrium form is the lowest point of the circle the apex can describe: the apex
    straight below that axis.
    """
    s = read_model(mesh_path("postcritical_dome.toml"))
    res = run_postcritical(s)
    out = {}
    fails = [e for e in res.events if e.kind in ("buckling", "yield", "fracture")]
    out["failures"] = len(fails)
    out["failures_by_redistribution"] = sum("redistribution" in e.detail for e in fails)
    # every event, on the path or during a redistribution at constant λ, is located where the
    # member force equals the failure law's limit
    out["event_force_error"] = float(max(abs(e.force / e.threshold - 1.0) for e in fails))
    mech = [e for e in res.events if e.kind == "mechanism"]
    out["mechanism_load_factor"] = float(mech[0].load_factor) if mech else math.nan
    out["first_failure_load_factor"] = float(fails[0].load_factor)
    mot = res.mechanism
    out["equilibrium_form_found"] = float(bool(mot and mot.converged))
    out["equilibrium_residual"] = float(mot.residual) if mot else math.nan
    out["equilibrium_stable"] = float(bool(mot and mot.stable))
    if mot and mot.converged:
        alive = res.path[-1].alive
        live_apex = [s.member_ids[i] for i in np.flatnonzero(alive) if
                     s.member_ids[i].startswith("A")]
        out["apex_bars_left"] = len(live_apex)
        x0, x1 = mot.positions[0], mot.positions[-1]
        apex = s.node_index("A")
        ends = [s.node_index(s.node_ids[s.connectivity[s.member_index(b)][1]])
                for b in live_apex]
        if len(ends) == 2:
            p, q = x0[ends[0]], x0[ends[1]]
            axis = (q - p) / np.linalg.norm(q - p)
            c = p + axis * ((x0[apex] - p) @ axis)
            r = np.linalg.norm(x0[apex] - c)
            down = np.array([0.0, 0.0, -1.0])
            down = down - axis * (down @ axis)
            expected = c + r * down / np.linalg.norm(down)
            out["apex_form_error"] = float(np.linalg.norm(x1[apex] - expected) / r)
            out["apex_form_z"] = float(x1[apex, 2])
            out["apex_form_z_expected"] = float(expected[2])
        t = mot.tensions
        idx = [list(np.flatnonzero(alive)).index(s.member_index(b)) for b in live_apex]
        out["apex_bars_in_tension"] = float(all(t[i] > 0 for i in idx))
    if figures:
        out["figures"] = _figure(res, "lattice_path")
    return out


def linear_buckling_agreement(subdivisions: int = 16) -> dict:
    """First linear buckling load factor of the Euler column: co-rotational tangent, Euler
    formula, and the FE core's eigen solver when it is installed (:func:`trussfe.api.buckling`).
    """
    s = read_model(mesh_path("postcritical_euler_column.toml"))
    L = float(s.lengths()[0])
    Pe = float(euler_load(s.E[0], s.Iz[0], L))
    P = -float(s.loads[1, 1])
    m = NonlinearModel(s, bar_model="pinned-beam", subdivisions=subdivisions)
    lf, _ = linear_buckling(m, count=2)
    out = {"load_factor": float(lf[0]), "euler_load_factor": Pe / P,
           "second_load_factor": float(lf[1]), "second_euler_load_factor": 4 * Pe / P}
    try:
        from ..api import buckling  # FE core eigen solver
        res = buckling(mesh_path("postcritical_euler_column.toml"), bar_model="pinned-beam",
                       subdivisions=subdivisions)
        out["fe_core_load_factor"] = float(res.load_factors[0])
        out["fe_core_relative_difference"] = abs(out["load_factor"] / out[
            "fe_core_load_factor"] - 1.0)
    except Exception:  # not installed yet: the comparison is skipped, not faked
        pass
    return out


# ------------------------------------------------------------------------- large lattice
def double_layer_grid(n: int, spacing: float = 1.0, depth: float = 0.7,
                      load: float = -1000.0, spread: float = 0.1, seed: int = 0,
                      law: str = "cap"):
    """Square-on-square double-layer grid with buckling laws on its chords.

    ``n × n`` top nodes (pinned along the perimeter, each loaded by ``load`` N vertically),
    ``(n−1)²`` bottom nodes offset by half a bay, top and bottom chords and four diagonals
    per bottom node: ``2n(n−1) + 2(n−1)(n−2) + 4(n−1)²`` bars (9800 for n = 36).  Every bar
    has a buckling law (``law``) with its Euler load scaled by a random factor in
    ``1 ± spread`` (seeded), so that members fail one at a time.

    Returns
    -------
    structure : Structure
    laws : FailureLaws
    """
    from ..model.sections import Material, Section
    from ..model.structure import build_structure
    from ..nonlinear.failure import BUCKLING, FailureLaws
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    top = np.stack([i.ravel() * spacing, j.ravel() * spacing, np.zeros(n * n)], axis=1)
    k, l = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="ij")
    bot = np.stack([(k.ravel() + 0.5) * spacing, (l.ravel() + 0.5) * spacing,
                    np.full((n - 1) ** 2, -depth)], axis=1)
    T = (i * n + j)                                        # top node numbers (n, n)
    Bn = n * n + (k * (n - 1) + l)                         # bottom node numbers (n-1, n-1)
    bars = [np.stack([T[:-1, :].ravel(), T[1:, :].ravel()], 1),
            np.stack([T[:, :-1].ravel(), T[:, 1:].ravel()], 1),
            np.stack([Bn[:-1, :].ravel(), Bn[1:, :].ravel()], 1),
            np.stack([Bn[:, :-1].ravel(), Bn[:, 1:].ravel()], 1)]
    for di in (0, 1):
        for dj in (0, 1):
            bars.append(np.stack([Bn.ravel(), T[di:n - 1 + di, dj:n - 1 + dj].ravel()], 1))
    conn = np.concatenate(bars)
    edge = (i == 0) | (j == 0) | (i == n - 1) | (j == n - 1)
    s = build_structure(np.vstack([top, bot]), conn,
                        section=Section.tube("tube", 0.04, 0.036),
                        material=Material(name="steel", E=2.1e11, G=8.1e10, density=7850.0,
                                          yield_strength=3.55e8),
                        name=f"double-layer grid {n}x{n}")
    supports = np.array(s.supports)
    supports[np.flatnonzero(edge.ravel()), :3] = True
    loads = np.array(s.loads)
    loads[np.flatnonzero(~edge.ravel()), 2] = load
    s = s.with_supports(supports).with_loads(loads)
    m = s.n_members
    rng = np.random.default_rng(seed)
    L = s.lengths()
    laws = dataclasses.replace(
        FailureLaws.none(m), buckling=np.full(m, BUCKLING.index(law)),
        critical_load=(euler_load(s.E, s.Iy, L) * (1.0 + spread * (2 * rng.random(m) - 1))))
    return s, laws
