# SPDX-License-Identifier: MIT
"""Evidence and studies for :mod:`trussfe.response.transient` (validation suite, docs, tests).

* :func:`sdof_bar` / :func:`sdof_closed_form`: one active bar pushing a lumped mass along its
  axis with a cycloidal stroke — a single-DOF system ``m ü + k u = −m L̈(t)`` whose Duhamel
  integral has a closed form.
* :func:`triangle_slew`: Lacy's triangular truss (Base Simulation model, 10 kg at B, the
  thesis' third-order actuator motion over 1.2 m) for a slew time T.
* :func:`time_step_study`, :func:`subdivision_study`: convergence of the elastic member forces.
* :func:`validation_transient_triangle`: the quantities and figures of
  ``validation/cases/transient_triangle_slew_times.toml``.
"""
from __future__ import annotations

import itertools
import logging
import math
from pathlib import Path

import numpy as np

from ..model.sections import Material, Section
from ..model.structure import Structure, build_structure
from ..rigid.active import ActiveMember
from ..rigid.motion import Motion, third_order_motion
from .lacy_rigid import L2, L3MIN, triangular_truss
from ..response.transient import TransientResult, transient_response
from ..io.output import working_folder

log = logging.getLogger(__name__)

#: The Base Simulation stroke (Lacy section 3.3): the active member from 2.5 m to 3.7 m.
STROKE = 1.2

#: Slew times of the study (s).
SLEW_TIMES = (3.0, 1.0, 0.3)


# ---------------------------------------------------------------------- single DOF
def sdof_bar(length: float = 1.0, mass: float = 10.0, EA: float = 1.0e5) -> Structure:
    """A massless active bar from a fixed pin to a lumped mass that slides along x.

    The bar's axial stiffness ``k = EA/L`` and the mass ``m`` make the single-DOF system
    ``m ü + k u = −m L̈(t)`` when the bar's length follows ``L(t)`` (frozen matrices).

    Examples
    --------
    >>> s = sdof_bar()
    >>> s.n_members, s.masses.tolist()
    (1, [0.0, 10.0])
    """
    sec = Section("bar", area=1.0e-4, Iy=1.0e-9, Iz=1.0e-9, c=0.01)
    mat = Material("massless", E=EA / 1.0e-4, G=EA / 2.6e-4, density=0.0)
    s = build_structure([[0.0, 0.0], [length, 0.0]], [(0, 1)], section=sec, material=mat,
                        supports={0: "xy", 1: "y"}, masses={1: mass},
                        node_ids=["O", "P"], member_ids=["bar"], name="single-DOF active bar")
    # base and tube carry no mass, so their lengths change no force; the tube is half the bar,
    # so that a motion may shorten the bar (never below its tube) as well as lengthen it
    return s.with_extensions(active_members=[ActiveMember(
        member=0, base_mass=0.0, base_length=length, base_cg=0.0, base_inertia=0.0,
        tube_length=0.5 * length)])


def cycloidal_motion(structure: Structure, stroke: float, duration: float, dt: float,
                     t_end: float | None = None) -> Motion:
    """Cycloidal stroke of the first active member, ``L = L0 + d (τ − sin 2πτ / 2π)``,
    ``τ = t/T`` (zero rate and acceleration at both ends), held after T."""
    L0 = float(structure.lengths()[0])
    t_end = duration if t_end is None else t_end
    n = round(t_end / dt)
    t = dt * np.arange(n + 1)
    tau = np.clip(t / duration, 0.0, 1.0)
    w = 2 * np.pi / duration
    moving = t <= duration
    L = L0 + stroke * (tau - np.sin(2 * np.pi * tau) / (2 * np.pi))
    V = np.where(moving, stroke / duration * (1 - np.cos(w * t)), 0.0)
    A = np.where(moving, stroke * w / duration * np.sin(w * t), 0.0)
    return Motion(time=t, members=[0], length=L[:, None], velocity=V[:, None],
                  acceleration=A[:, None], source="cycloidal stroke")


def sdof_closed_form(t: np.ndarray, stroke: float, duration: float, mass: float,
                     stiffness: float) -> np.ndarray:
    """Bar force (tension positive) of the single-DOF system under the cycloidal stroke.

    With ``p0 = m d Ω²/(2π)``, ``Ω = 2π/T``, ``r = Ω/ω`` and ``u(0) = u̇(0) = 0`` the Duhamel
    integral of ``m ü + k u = −p0 sin Ωt`` is

    .. math:: u(t) = -\\frac{p_0/k}{1 - r^2}\\left(\\sin\\Omega t - r \\sin\\omega t\\right),
              \\quad 0 \\le t \\le T,

    then free vibration from ``u(T)``, ``u̇(T)``.  The force is ``N = k u``.

    Examples
    --------
    A slow stroke (T f1 = 1592) follows the quasi-static force ``−m L̈`` = −6.283 N at
    t = T/4 to within the residual vibration ``p0 r``:

    >>> N = sdof_closed_form(np.array([0.25]), 0.1, 1.0, 10.0, 1e9)
    >>> bool(abs(N[0] + 6.283) < 0.01)
    True
    """
    t = np.asarray(t, dtype=float)
    w = math.sqrt(stiffness / mass)
    W = 2 * math.pi / duration
    r = W / w
    p0 = mass * stroke * W * W / (2 * math.pi)
    amp = -(p0 / stiffness) / (1 - r * r)

    def u(x):
        return amp * (np.sin(W * x) - r * np.sin(w * x))

    def ud(x):
        return amp * (W * np.cos(W * x) - r * w * np.cos(w * x))

    uT, vT = u(duration), ud(duration)
    after = uT * np.cos(w * (t - duration)) + vT / w * np.sin(w * (t - duration))
    return stiffness * np.where(t <= duration, u(np.minimum(t, duration)), after)


def sdof_check(dt: float, *, duration: float = 0.2, stroke: float = 0.05, mass: float = 10.0,
               EA: float = 1.0e5, length: float = 1.0, t_end: float = 0.4,
               update: str = "frozen") -> dict:
    """Transient response of :func:`sdof_bar` against :func:`sdof_closed_form`.

    Returns
    -------
    dict
        ``max_error`` (max |N − N_exact| / max |N_exact|), ``peak``, ``peak_exact``,
        ``peak_qs`` (largest quasi-static force m·max L̈), ``T_f1`` (slew time × natural
        frequency) and ``energy_residual``.
    """
    s = sdof_bar(length, mass, EA)
    m = cycloidal_motion(s, stroke, duration, dt, t_end)
    r = transient_response(s, m, bar_model="truss", update=update)
    k = EA / length
    exact = sdof_closed_form(r.time, stroke, duration, mass, k)
    N = r.axial_force[:, 0]
    f1 = math.sqrt(k / mass) / (2 * math.pi)
    return {"max_error": float(np.max(np.abs(N - exact)) / np.max(np.abs(exact))),
            "peak": float(np.max(np.abs(N))), "peak_exact": float(np.max(np.abs(exact))),
            "peak_qs": float(np.max(np.abs(r.axial_force_qs[:, 0]))),
            "T_f1": duration * f1, "energy_residual": r.energy_residual(),
            "frequency_hz": float(r.frequencies_hz[0]), "frequency_exact_hz": f1}


# ---------------------------------------------------------------------- triangular truss
def triangle_slew(duration: float, dt: float = 5.0e-4, *, k: int | None = None,
                  update: str = "per-step", mass: float = 10.0, t_end: float | None = None,
                  damping=None) -> TransientResult:
    """The triangular truss (Lacy's Base Simulation model) slewing over 1.2 m in ``duration``.

    The motion is the thesis' third-order actuator model (:func:`third_order_motion`) sampled
    every ``dt`` from 0 to T inclusive (it has not quite settled at T: its rate there is
    about 0.1 % of the peak, so the motion is not held beyond T).
    """
    s = triangular_truss(mass=mass)
    steps = round(duration / dt)
    m = third_order_motion(s, [L3MIN + L2], [L3MIN + STROKE + L2], duration, steps,
                           include_end=True)
    return transient_response(s, m, dt=duration / steps, k=k, update=update, t_end=t_end,
                              damping=damping)


def double_octahedron_slew(duration: float, dt: float = 5.0e-4, *, angle: float = 10.0,
                           top_mass: float = 4.536, update: str = "per-step",
                           k: int | None = None) -> TransientResult:
    """Lacy's double-octahedral bay, standing under gravity with ``top_mass`` (kg) on each top
    node, tilting its top plane from 0 to ``angle`` degrees about n̂1 in ``duration`` s (the
    third-order profile of :mod:`trussfe.rigid.slew`, centroid height held)."""
    from .lacy_rigid import double_octahedron
    from ..rigid.slew import rotation_motion

    s = double_octahedron(top_masses=top_mass, gravity=9.81)
    steps = round(duration / dt)
    m = rotation_motion({"type": "rotation", "axis": "n1", "start": 0.0, "end": angle,
                         "duration": duration, "steps": steps}, s)
    return transient_response(s, m, update=update, k=k)


def departure_table(results: dict[float, TransientResult]) -> list[dict]:
    """One row per slew time and member: peaks and the largest departure of the elastic
    axial force from the quasi-static and rigid-body ones."""
    rows = []
    for T, r in results.items():
        f1 = float(r.frequencies_hz[0])
        for mid, d in r.departure().items():
            rows.append({"T": T, "T_f1": T * f1, "member": mid, **d})
    return rows


def time_step_study(duration: float = 0.3, dts=(2.0e-3, 1.0e-3, 5.0e-4, 2.5e-4),
                    member: int = 0, update: str = "per-step", k: int | None = None) -> dict:
    """Convergence of the elastic axial force history with the time step.

    The error of each run is its largest difference from the next finer run at the common
    sample times; Newmark's average-acceleration rule should give order 2.

    Returns
    -------
    dict
        ``dt``, ``error`` (N), ``order`` (log2 of successive error ratios), ``energy_residual``
        per dt.
    """
    runs = [triangle_slew(duration, dt, update=update, k=k) for dt in dts]
    errs = []
    for a, b in itertools.pairwise(runs):
        step = round(a.dt / b.dt)
        errs.append(float(np.max(np.abs(a.axial_force[:, member]
                                        - b.axial_force[::step, member]))))
    ratios = np.array(errs[:-1]) / np.array(errs[1:])
    dtr = np.array(dts[:-2]) / np.array(dts[1:-1])
    order = np.log(ratios) / np.log(dtr)
    return {"dt": list(dts[:-1]), "error": errs, "order": order.tolist(),
            "energy_residual": [r.energy_residual() for r in runs]}


def subdivision_study(duration: float = 0.3, dt: float = 5.0e-4, ks=(1, 2, 4, 8),
                      member: int = 0) -> dict:
    """Peak elastic axial force and midpoint moment of ``member`` with the sub-elements per
    member; differences from the finest."""
    runs = [triangle_slew(duration, dt, k=k) for k in ks]
    peakN = [float(np.max(np.abs(r.axial_force[:, member]))) for r in runs]
    peakM = [float(np.max(np.abs(r.moment[:, member]))) for r in runs]
    f1 = [float(r.frequencies_hz[0]) for r in runs]
    return {"k": list(ks), "peak_axial": peakN, "peak_moment": peakM, "f1_hz": f1,
            "axial_change": [abs(p - peakN[-1]) / peakN[-1] for p in peakN],
            "moment_change": [abs(p - peakM[-1]) / peakM[-1] for p in peakM]}


# ---------------------------------------------------------------------- figures
def history_figure(results: dict[float, TransientResult], path: Path, member: int = 0,
                   quantity: str = "axial_force") -> Path:
    """Time histories elastic vs quasi-static FE vs rigid-body, one panel per slew time."""
    from ..io.figures import subplots

    n = len(results)
    fig, axes = subplots(n, 1, figsize=(7.0, 2.4 * n), squeeze=False)
    label = {"axial_force": ("axial force", "N"), "moment": ("midpoint moment", "N·m")}
    for ax, (T, r) in zip(axes[:, 0], results.items()):
        dyn = getattr(r, quantity)[:, member]
        qs = getattr(r, f"{quantity}_qs")[:, member]
        rig = getattr(r, f"{quantity}_rigid")[:, member]
        ax.plot(r.time, rig, color="0.6", lw=3.0, label="rigid body (Lacy model)")
        ax.plot(r.time, qs, "k--", lw=1.2, label="FE quasi-static")
        ax.plot(r.time, dyn, color="tab:red", lw=1.0, label="FE elastic (Newmark)")
        ax.set_title(f"T = {T:g} s  (T·f1 = {T * r.frequencies_hz[0]:.1f})", fontsize=9)
        ax.set_ylabel(f"{label[quantity][0]}, {label[quantity][1]}", fontsize=8)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("time, s")
    axes[0, 0].legend(fontsize=7, loc="best")
    fig.suptitle(f"{r.structure.member_ids[member]}: elastic vs quasi-static vs rigid body",
                 fontsize=10)
    fig.tight_layout()
    path = Path(path)
    fig.savefig(path, dpi=110)
    return path


def energy_figure(r: TransientResult, path: Path) -> Path:
    """Energy terms and the balance residual of one run."""
    from ..io.figures import subplots

    e = r.energy
    fig, ax = subplots(figsize=(7.0, 3.2))
    e0 = e["kinetic"][0] + e["strain"][0]
    ax.plot(r.time, e["kinetic"], label="kinetic ½u̇ᵀMu̇")
    ax.plot(r.time, e["strain"] - e["strain"][0], label="strain ½uᵀKu − E₀")
    ax.plot(r.time, e["work"], label="work of driving loads")
    ax.plot(r.time, e["parametric"], label="parametric (changing K, M)")
    ax.plot(r.time, e["residual"], "k", lw=1.5, label="residual")
    ax.set_xlabel("time, s")
    ax.set_ylabel("energy, J")
    ax.set_title(f"energy balance, {r.options['update']} matrices, dt = {r.dt:g} s "
                 f"(E₀ = {e0:.3g} J)", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return Path(path)


# ---------------------------------------------------------------------- validation case
#: Time steps of the slew-time table: about 2 % of the first period at T = 0.3 s, coarser
#: for the gentler slow slews (the time-step study shows the peaks converged to < 1 %).
TABLE_DT = {3.0: 2.5e-4, 1.0: 1.25e-4, 0.3: 6.25e-5}


def slew_time_table(dts: dict[float, float] | None = None) -> dict[float, TransientResult]:
    """The triangular truss for T = 3, 1 and 0.3 s (:data:`TABLE_DT` time steps)."""
    dts = TABLE_DT if dts is None else dts
    return {T: triangle_slew(T, dt) for T, dt in dts.items()}


def validation_transient_triangle(figures: bool = True) -> dict:
    """Quantities of ``validation/cases/transient_triangle_slew_times.toml``.

    Paths: ``sdof.*`` (closed form), ``sdof_order``, ``convergence.order[0]``,
    ``energy.*``, ``slow.*`` (quasi-static limit), ``table.T0.3.follower.*`` and ``figures``.
    """
    out: dict = {}
    fine, coarse = sdof_check(dt=1.0e-4), sdof_check(dt=2.0e-4)
    out["sdof"] = {**fine, "peak_ratio": fine["peak"] / fine["peak_exact"]}
    out["sdof_order"] = math.log2(coarse["max_error"] / fine["max_error"])
    results = slew_time_table()
    table: dict = {}
    for T, r in results.items():
        table[f"T{T:g}"] = {**r.departure(), "T_f1": T * float(r.frequencies_hz[0]),
                            "dt": r.dt}
    out["table"] = table
    slow = results[SLEW_TIMES[0]]
    qs_rig = np.abs(slow.axial_force_qs - slow.axial_force_rigid).max(axis=0)
    peak = np.abs(slow.axial_force_rigid).max(axis=0)
    out["slow"] = {"follower_qs_vs_rigid": float(qs_rig[0] / peak[0]),
                   "active_qs_vs_rigid": float(qs_rig[1] / peak[1]),
                   "follower_relative": table[f"T{SLEW_TIMES[0]:g}"]["follower"]["relative"],
                   "active_relative": table[f"T{SLEW_TIMES[0]:g}"]["active"]["relative"],
                   "moment_qs_vs_rigid": float(np.abs(slow.moment_qs - slow.moment_rigid)
                                               [:, 0].max() / np.abs(slow.moment_rigid)
                                               [:, 0].max())}
    conv = time_step_study(0.3, dts=(2.5e-4, 1.25e-4, 6.25e-5))
    frozen = triangle_slew(0.3, 2.5e-4, update="frozen")
    res = conv["energy_residual"]
    out["energy"] = {"frozen": frozen.energy_residual(), "per_step": res[-1],
                     "per_step_order": math.log2(res[0] / res[1])}
    out["convergence"] = conv
    out["f1_hz"] = float(slow.frequencies_hz[0])
    if figures:
        folder = working_folder("trussfe_transient_")
        out["figures"] = {
            "transient_follower_axial": str(history_figure(
                results, folder / "follower_axial.png", 0)),
            "transient_active_axial": str(history_figure(
                results, folder / "active_axial.png", 1)),
            "transient_follower_moment": str(history_figure(
                results, folder / "follower_moment.png", 0, "moment")),
            "transient_energy": str(energy_figure(results[0.3], folder / "energy.png")),
        }
    return out
