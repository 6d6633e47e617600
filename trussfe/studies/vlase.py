# SPDX-License-Identifier: MIT
"""Closed-form linkages against the compatibility-matrix and cycle-equation kinematics (Vlase).

The four-bar and the slider-crank are traced as bar assemblies and their velocities and
accelerations computed twice — from the compatibility matrix (Hortobágyi eq. 2 differentiated)
and from the cycle (loop) equations of the equivalent assembly (Vlase 2008) — and compared
with the textbook closed forms.  The validation cases ``validation/cases/mech_fourbar.toml``
and ``mech_slider_crank.toml`` point at these functions
(``python = "trussfe.studies.vlase:<name>"``).
"""
from __future__ import annotations

import numpy as np

from ..kinematics.trace import trace_mechanism
from ..kinematics.topology import cycle_kinematics, equivalent_assembly
from ..kinematics.velocity import bar_angular_velocity, mechanism_acceleration, mechanism_velocity
from ..mechanics.geometry import member_lengths
from ..models.mechanisms import FOURBAR, fourbar_position

__all__ = ["FOURBAR", "SLIDER_CRANK", "fourbar_closed_form", "fourbar_position",
           "fourbar_rates", "slider_crank_closed_form"]


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
    L0 = member_lengths(x, conn)
    Ls = member_lengths(r.coords, conn)
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


# --------------------------------------------------------------------------- spatial cycles
def _compare(eq, x, conn, free, *, length_rates=None, length_accs=None, drive_v=None,
             drive_a=None):
    """Cycle-equation rates (:func:`~trussfe.kinematics.cycles.cycle_rates`) and the
    compatibility-matrix rates (``B v = L̇``, ``B a = L̈ − (|v_rel|² − L̇²)/L``) of one state."""
    from ..kinematics.cycles import cycle_rates

    b = conn.shape[0]
    ld = np.zeros(b)
    ldd = np.zeros(b)
    for j, v in (length_rates or {}).items():
        ld[j] = v
    for j, v in (length_accs or {}).items():
        ldd[j] = v
    dim = x.shape[1]
    pv = {i * dim + a: v for (i, a), v in (drive_v or {}).items()}
    pa = {i * dim + a: v for (i, a), v in (drive_a or {}).items()}
    v = mechanism_velocity(x, conn, free, pv, ld)
    a = mechanism_acceleration(x, conn, free, v, pa, ld, ldd)
    cr = cycle_rates(eq, length_rates=length_rates, length_accelerations=length_accs,
                     node_velocities=drive_v, node_accelerations=drive_a)
    n = x.shape[0]
    return cr, v, a, float(np.abs(cr.velocity[:n] - v).max()), \
        float(np.abs(cr.acceleration[:n] - a).max())


def spatial_cycles_octahedral_bay() -> dict:
    """Lacy's double-octahedral bay (three active members) by the cycle equations in space
    against the compatibility matrix, at the equilibrium position and at the first slewed
    position of Lacy §5.3.

    The three actuators extend at L̇ = (0.10, −0.05, 0.02) m/s with L̈ = (0.3, 0.1, −0.2)
    m/s² (arbitrary rates: both methods take the same).

    Returns
    -------
    dict
        Per position: ``velocity_difference`` (m/s), ``acceleration_difference`` (m/s²),
        ``velocity_scale`` and ``acceleration_scale`` (largest joint rate); and
        ``cycles``: the fundamental cycles s − r of the equivalent mechanism.
    """
    from ..kinematics.topology import equivalent_assembly
    from ..models.octahedral import slew_lengths
    from .lacy_rigid import double_octahedron

    out = {}
    for pos in ("equilibrium", "slew1"):
        s = double_octahedron(tuple(slew_lengths(pos)))
        x, conn = s.coords, s.connectivity
        free = ~s.translation_supports
        acts = [a.member for a in s.extensions["active_members"]]
        lr = dict(zip(acts, (0.10, -0.05, 0.02)))
        la = dict(zip(acts, (0.3, 0.1, -0.2)))
        eq = equivalent_assembly(x, conn, ground=list(np.flatnonzero(~free.any(axis=1))))
        _, v, a, dv, da = _compare(eq, x, conn, free, length_rates=lr, length_accs=la)
        out[pos] = {"velocity_difference": dv, "acceleration_difference": da,
                    "velocity_scale": float(np.abs(v).max()),
                    "acceleration_scale": float(np.abs(a).max())}
        out["cycles"] = int(eq.topology.cycle_matrix.shape[0])
    return out


def spatial_cycles_bennett(samples: int = 8, omega: float = 2.0, alpha: float = 0.5) -> dict:
    """Bennett's linkage (:mod:`trussfe.models.bennett`) by the cycle equations in space,
    against the compatibility matrix and the closed form, over a turn of the input link.

    Link 1 turns about axis 1 at θ̇₁ = ``omega`` with θ̈₁ = ``alpha``: the drive is the
    velocity and acceleration of joint A2 (both horizontal components).  Closed form: link
    2 turns at ω₂ = θ̇₁ z₁ + θ̇₂ z₂ with θ̇₂ = (dθ₂/dθ₁) θ̇₁ (:func:`~trussfe.models.bennett.
    bennett_rate`), so joint A3 moves at v_A2 + ω₂ × (A3 − A2), and each bar of link 2 turns
    at ω₂'s part normal to it.

    Returns
    -------
    dict
        ``closure`` (largest |T₁T₂T₃T₄ − I| over the samples), ``bar_length_misfit`` (m, the
        bars keep their lengths across the samples), ``velocity_difference``,
        ``acceleration_difference`` (cycle against compatibility, m/s, m/s²),
        ``closed_form_velocity_error`` (A3, m/s), ``closed_form_omega_error`` (link 2's
        bars, rad/s), ``velocity_scale``.
    """
    from ..kinematics.topology import equivalent_assembly
    from ..models.bennett import bennett_frames, bennett_linkage, bennett_rate

    out = {"closure": 0.0, "bar_length_misfit": 0.0, "velocity_difference": 0.0,
           "acceleration_difference": 0.0, "closed_form_velocity_error": 0.0,
           "closed_form_omega_error": 0.0, "velocity_scale": 0.0}
    L0 = None
    for t1 in np.linspace(0.0, 2 * np.pi, samples, endpoint=False) + 0.4:
        F = bennett_frames(t1)
        out["closure"] = max(out["closure"], float(np.abs(F[4] - np.eye(4)).max()))
        x, conn, fixed = bennett_linkage(t1)
        L = member_lengths(x, conn)
        L0 = L if L0 is None else L0
        out["bar_length_misfit"] = max(out["bar_length_misfit"], float(np.abs(L - L0).max()))
        free = np.ones_like(x, dtype=bool)
        free[fixed] = False
        z1 = np.array([0.0, 0.0, 1.0])
        r = x[2] - x[0]
        vA2 = omega * np.cross(z1, r)
        aA2 = alpha * np.cross(z1, r) + omega * np.cross(z1, vA2)
        dv = {(2, 0): vA2[0], (2, 1): vA2[1]}
        da = {(2, 0): aA2[0], (2, 1): aA2[1]}
        eq = equivalent_assembly(x, conn, ground=fixed)
        cr, v, a, ev, ea = _compare(eq, x, conn, free, drive_v=dv, drive_a=da)
        out["velocity_difference"] = max(out["velocity_difference"], ev)
        out["acceleration_difference"] = max(out["acceleration_difference"], ea)
        out["velocity_scale"] = max(out["velocity_scale"], float(np.abs(v).max()))
        z2 = F[1, :3, 2]
        w2 = omega * z1 + bennett_rate(t1) * omega * z2
        vA3 = vA2 + np.cross(w2, x[4] - x[2])
        out["closed_form_velocity_error"] = max(out["closed_form_velocity_error"],
                                                float(np.abs(cr.velocity[4] - vA3).max()))
        for j in range(8, 12):                      # the bars of link 2 (axis 2 → axis 3)
            e = x[conn[j, 1]] - x[conn[j, 0]]
            e /= np.linalg.norm(e)
            wn = w2 - (w2 @ e) * e
            out["closed_form_omega_error"] = max(out["closed_form_omega_error"],
                                                 float(np.abs(cr.omega[j] - wn).max()))
    return out


def validation_spatial_cycles() -> dict:
    """The validation case ``topology-cycles-3d``: :func:`spatial_cycles_octahedral_bay`
    and :func:`spatial_cycles_bennett`."""
    return {"bay": spatial_cycles_octahedral_bay(), "bennett": spatial_cycles_bennett()}
