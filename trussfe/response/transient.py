# SPDX-License-Identifier: MIT
"""Transient elastic dynamics of a truss along a prescribed large motion.

Lacy's thesis computes the member forces of an adaptive truss as rigid bodies (chapter 2) and
names the flexible analysis as the step it could not take.  Here the elastic vibration is
superposed on the prescribed motion.

Formulation
-----------
The node positions are split into the rigid (kinematic) motion and a small elastic
displacement, ``x(t) = x_r(t) + u(t)``.  ``x_r`` follows from the active members' lengths
(:mod:`trussfe.rigid.kinematics`, exact compatibility equations); the active members are
locked at their instantaneous length in the FE model (their prescribed motion enters through
``x_r`` only).  Linearised about the moving configuration,

.. math::
   :label: transient-eom

   M(t)\\,\\ddot u + C(t)\\,\\dot u + K(t)\\,u = f(t) = f_g - M(t)\\,\\ddot x_r(t),

with ``K``, ``M`` the pinned-beam (or truss) FE stiffness and mass in the current geometry
(:mod:`trussfe.fem`), ``f_g`` gravity and nodal loads, and ``M ẍ_r`` the d'Alembert load of the
rigid acceleration field (:mod:`trussfe.response.transient_fe`; exact Newton–Euler loads for
the telescoping active members, Lacy eqs. 2.9–2.11, 4.20).  Terms of order ``u·Ω`` (Coriolis
and centrifugal coupling of the elastic field with the member rotation rate Ω), the geometric
stiffness of the member forces and the change of the interior DOFs' member axes within a step
are neglected: they are small while ``Ω`` is much less than the first natural circular
frequency (Ω reaches 9.4 rad/s, ``Ω/ω₁ = 0.09``, for the triangular truss at T = 0.3 s; a
few per cent at T = 1 s).

The **quasi-static** response ``u_qs = K⁻¹ f`` is the FE counterpart of the rigid-body member
forces: for a statically determinate truss its member forces equal the rigid-body ones
(checked in the tests).  The **dynamic** response starts from the quasi-static state at rest,
``u(0) = u_qs(0)``, ``u̇(0) = 0``.

Time integration
----------------
Newmark's average-acceleration rule (β = 1/4, γ = 1/2): unconditionally stable, second-order
accurate, no numerical damping.  With ``update="per-step"`` the matrices of step ``n + 1`` are
used in its equation (assembled for blocks of steps at once); with ``update="frozen"`` they
are those of the initial configuration (a linear time-invariant model; its loads still follow
the motion, expressed in the initial configuration).

Energy balance
--------------
With ``E = ½ u̇ᵀMu̇ + ½ uᵀKu``, equation :eq:`transient-eom` gives

.. math:: \\dot E = \\dot u^T f - \\dot u^T C \\dot u
          + \\tfrac12 \\dot u^T \\dot M \\dot u + \\tfrac12 u^T \\dot K u .

The average-acceleration rule satisfies the discrete form of it exactly when the matrices are
frozen, ``E_{n+1} − E_n = Δuᵀ (f_n + f_{n+1})/2 − Δt v̄ᵀ C v̄`` (v̄ the step's mean velocity), so
the residual ``E_n − E_0 − W_n + D_n`` is round-off.  When the matrices are updated, the last
two (parametric) terms exchange energy with the motion; they are accumulated by the trapezoidal
rule and the residual ``E_n − E_0 − W_n + D_n − P_n`` then vanishes as ``Δt² → 0``.
"""
from __future__ import annotations

import dataclasses
import logging
from dataclasses import dataclass, field

from typing import Callable

import numpy as np
import scipy.linalg as sla
import scipy.sparse.linalg as spla

from ..budget import along_motion_bytes, count_text, require
from ..errors import UNITS_ADVICE, AnalysisError, InputError, MechanismError, TrussfeError
from ..fem.discretisation import FEModel, discretise
from ..model.bar_models import BAR_MODELS
from ..fem.solver import factorise
from ..linalg import SingularMatrixError, factor
from ..mechanics.mass import mass_per_length
from ..mechanics.member_loads import deflection_shapes, rotation_shapes
from ..fem.static import section_forces as fe_section_forces
from ..model.structure import Structure
from ..mechanics.active_bodies import member_bodies
from ..rigid.kinematics import Kinematics
from ..rigid.motion import Motion
from ..rigid.simulate import simulate
from .along_motion import error_at_step
from ..mechanics.active_bodies import massless_active
from .transient_fe import assemble_block

log = logging.getLogger(__name__)

#: Newmark average acceleration.
BETA, GAMMA = 0.25, 0.5

#: Free-DOF count up to which the per-step systems are solved densely (batched inverses).
DENSE_LIMIT = 200

#: Bytes of dense per-step matrices kept for one block of steps.
BLOCK_BYTES = 64 << 20

#: Rigid-body sections per member; odd, so that the middle one is the midpoint.
RIGID_SECTIONS = 7

UPDATES = ("per-step", "frozen")


@dataclass
class TransientResult:
    """Result of :func:`transient_response`; arrays indexed (time, member) or (time, node).

    Attributes
    ----------
    time : ndarray, shape (nt,)
    structure : Structure
    motion : Motion
        The motion on the integration time grid.
    fe : FEModel
        Discretisation in the initial geometry (active members massless: their inertia is
        carried by :func:`~trussfe.fem.modal.active_member_mass` and the rigid-body loads).
    displacement, displacement_qs : ndarray, shape (nt, n, dim)
        Elastic node displacements, dynamic and quasi-static.
    axial_force, axial_force_qs, axial_force_rigid : ndarray, shape (nt, m)
        Axial force at the member midpoint (tension positive): dynamic FE, quasi-static FE,
        rigid-body model (:func:`trussfe.rigid.simulate`; for an active member the force at
        its cantilever connection, minus the actuator force, which is what its locked FE bar
        carries).
    moment, moment_qs, moment_rigid : ndarray, shape (nt, m)
        Bending-moment magnitude at the member midpoint, N·m (zero for truss bars and for the
        active members, which are loaded at their ends only in the FE model).
    energy : dict of ndarray (nt,)
        ``kinetic``, ``strain``, ``work`` (of the driving loads since t₀), ``dissipated``,
        ``parametric`` (exchanged through the changing matrices) and ``residual``
        = kinetic + strain − E₀ − work + dissipated − parametric.
    frequencies_hz : ndarray
        Lowest natural frequencies in the initial geometry.
    options : dict
    coords : ndarray, shape (nt, n, dim), optional
        Node positions of the rigid-body motion, about which the elastic displacements are
        measured.
    """

    time: np.ndarray
    structure: Structure
    motion: Motion
    fe: FEModel
    displacement: np.ndarray
    displacement_qs: np.ndarray
    axial_force: np.ndarray
    axial_force_qs: np.ndarray
    axial_force_rigid: np.ndarray
    moment: np.ndarray
    moment_qs: np.ndarray
    moment_rigid: np.ndarray
    energy: dict
    frequencies_hz: np.ndarray
    options: dict = field(default_factory=dict)
    coords: np.ndarray | None = None

    @property
    def dt(self) -> float:
        """Time step, s."""
        return float(self.time[1] - self.time[0])

    def energy_residual(self) -> float:
        """Largest |energy residual| relative to the largest total energy ½u̇ᵀMu̇ + ½uᵀKu."""
        e = self.energy
        scale = float(np.max(np.abs(e["kinetic"] + e["strain"])))
        return float(np.max(np.abs(e["residual"]))) / scale if scale > 0 else 0.0

    def departure(self) -> dict:
        """Largest departure of the elastic axial force from the quasi-static and the
        rigid-body ones, per member.

        Returns
        -------
        dict
            Member id → ``max_abs`` (max over time of |N − N_qs|, N), ``relative`` (that over
            max |N_qs|), ``max_abs_vs_rigid``, ``relative_vs_rigid``, ``peak`` (max |N|),
            ``peak_qs`` and ``peak_rigid`` and ``amplification`` = peak / peak_qs.
        """
        out = {}
        for j, mid in enumerate(self.structure.member_ids):
            n, q, r = (self.axial_force[:, j], self.axial_force_qs[:, j],
                       self.axial_force_rigid[:, j])
            dq = float(np.max(np.abs(n - q)))
            dr = float(np.max(np.abs(n - r)))
            pq, pr, pn = (float(np.max(np.abs(x))) for x in (q, r, n))
            out[mid] = {"max_abs": dq, "relative": dq / pq if pq else float("nan"),
                        "max_abs_vs_rigid": dr,
                        "relative_vs_rigid": dr / pr if pr else float("nan"),
                        "peak": pn, "peak_qs": pq, "peak_rigid": pr,
                        "amplification": pn / pq if pq else float("nan")}
        return out


# ---------------------------------------------------------------------- motion on the grid
def _quintic(t0, t1, y0, y1, tq):
    """C² quintic Hermite interpolation of (value, rate, second rate) on one interval each.

    ``y0``, ``y1``: tuples (value, rate, second rate) arrays (q, na) at the interval ends.
    """
    h = (t1 - t0)[:, None]
    s = ((tq - t0) / (t1 - t0))[:, None]
    # Hermite basis for value/rate/2nd-rate at s = 0 and s = 1, as polynomials in s.
    P = np.array([[1, 0, 0, -10, 15, -6], [0, 1, 0, -6, 8, -3], [0, 0, .5, -1.5, 1.5, -.5],
                  [0, 0, 0, 10, -15, 6], [0, 0, 0, -4, 7, -3], [0, 0, 0, .5, -1, .5]])
    w = [y0[0], h * y0[1], h * h * y0[2], y1[0], h * y1[1], h * h * y1[2]]
    powers = np.arange(6)
    out = []
    for d in range(3):
        c = P.copy()
        for _ in range(d):
            c = c[:, 1:] * np.arange(1, c.shape[1])
        sp_ = s ** powers[:c.shape[1]][None, :]                   # (q, deg)
        basis = sp_ @ c.T                                         # (q, 6)
        out.append(sum(basis[:, [k]] * w[k] for k in range(6)) / h ** d)
    return out


def motion_on_grid(motion: Motion, dt: float | None = None, t_end: float | None = None
                   ) -> Motion:
    """The motion sampled every ``dt`` from its first sample to ``t_end``.

    Between samples the lengths are interpolated by C² quintic Hermite polynomials through
    the sampled length, rate and second rate (exact for motions of degree ≤ 5).  After the
    last sample the active members are held at their final length, which requires a motion
    that ends at rest.

    Parameters
    ----------
    motion : Motion
    dt : float, optional
        Time step, s (default: the motion's own, which must then be uniform).
    t_end : float, optional
        Last time, s (default: the motion's last sample).

    Raises
    ------
    InputError
        ``dt`` not positive or longer than the motion, a non-uniform motion without ``dt``,
        a motion of one sample, or ``t_end`` past the end of a motion that does not end at
        rest.

    Examples
    --------
    >>> m = Motion([0.0, 1.0], [0], [[1.0], [2.0]], [[0.0], [0.0]], [[0.0], [0.0]])
    >>> g = motion_on_grid(m, 0.5)
    >>> g.time.tolist(), g.length[:, 0].tolist()
    ([0.0, 0.5, 1.0], [1.0, 1.5, 2.0])
    """
    t = motion.time
    item = f"{motion.source}: motion" if motion.source else "motion"
    if t.size < 2:
        raise InputError(item, "has a single sample; a transient analysis needs a motion "
                         "history (at least two samples)")
    span = float(t[-1] - t[0])
    if dt is None:
        steps = np.diff(t)
        if np.ptp(steps) > 1e-9 * steps.mean():
            raise InputError(item, "is not sampled uniformly; give a time step (--dt)")
        dt = float(steps.mean())
    if isinstance(dt, bool) or not isinstance(dt, (int, float, np.floating)) or not dt > 0 \
            or not np.isfinite(dt):
        raise InputError("dt", f"the time step must be a positive number of seconds, got {dt!r}")
    end = float(t[-1]) if t_end is None else float(t_end)
    if not end > t[0]:
        raise InputError("t_end", f"must lie after the motion's start ({t[0]:g} s), got {end:g}")
    if dt > end - t[0]:
        raise InputError("dt", f"{dt:g} s is longer than the analysed time ({end - t[0]:g} s);"
                         " the motion is too short for this step: give a smaller dt")
    n_float = np.floor((end - t[0]) / dt * (1 + 1e-12)) + 1
    # the FE response at every step dwarfs the motion itself: refuse what cannot fit
    require(along_motion_bytes(n_float, 0, motion.length.shape[1]),
            "--dt" if t_end is None else "--dt, --t-end",
            f"{count_text(n_float)} time steps of {dt:g} s", "give a longer time step")
    n = int(n_float)
    tq = t[0] + dt * np.arange(n)
    L, V, A = motion.length, motion.velocity, motion.acceleration
    if end > t[-1] * (1 + 1e-12) + 1e-12:
        scale = max(float(np.max(np.abs(V))), 1e-300)
        at_rest = (np.all(np.abs(V[-1]) <= 1e-3 * scale)
                   and np.all(np.abs(A[-1]) * span <= 1e-2 * scale))
        if not at_rest:
            raise InputError(item, f"ends at t = {t[-1]:g} s while still moving (rate "
                             f"{float(np.max(np.abs(V[-1]))):.3g} m/s) but the analysis runs to"
                             f" {end:g} s: give a longer motion or an earlier t_end")
        t = np.r_[t, end + dt]
        L = np.vstack([L, L[-1]])
        V = np.vstack([V, np.zeros_like(V[-1])])
        A = np.vstack([A, np.zeros_like(A[-1])])
    i = np.clip(np.searchsorted(t, tq, side="right") - 1, 0, t.size - 2)
    y, yd, ydd = _quintic(t[i], t[i + 1], (L[i], V[i], A[i]), (L[i + 1], V[i + 1], A[i + 1]), tq)
    return Motion(time=tq, members=motion.members, length=y, velocity=yd, acceleration=ydd,
                  source=motion.source)


# ---------------------------------------------------------------------- the analysis
def rayleigh(ratio: float, f1: float, f2: float) -> tuple[float, float]:
    """Rayleigh coefficients (α, β) of ``C = αM + βK`` giving the damping ratio ``ratio`` at
    the frequencies f1 and f2 (Hz).

    Examples
    --------
    >>> a, b = rayleigh(0.02, 10.0, 50.0)
    >>> w = 2 * np.pi * 10.0
    >>> round(a / (2 * w) + b * w / 2, 12)
    0.02
    """
    w1, w2 = 2 * np.pi * f1, 2 * np.pi * f2
    return 2 * ratio * w1 * w2 / (w1 + w2), 2 * ratio / (w1 + w2)


def _slice_kin(kin: Kinematics, sl: slice) -> Kinematics:
    names = ("time", "coords", "velocity", "acceleration", "length", "length_rate",
             "length_acc", "unit", "unit_rate", "unit_acc", "omega", "alpha")
    return dataclasses.replace(kin, **{k: getattr(kin, k)[sl] for k in names}, compat=None)


def _check_damping(damping):
    if damping is None:
        return 0.0, 0.0
    try:
        a, b = (float(x) for x in damping)
    except (TypeError, ValueError):
        raise InputError("damping", "expected Rayleigh coefficients (alpha, beta) of "
                         f"C = alpha M + beta K, got {damping!r}") from None
    if not (np.isfinite(a) and np.isfinite(b) and a >= 0 and b >= 0):
        raise InputError("damping", f"Rayleigh coefficients must be finite and not negative, "
                         f"got ({a}, {b})")
    return a, b


class _Dense:
    """Per-step matrices of a block as dense arrays (nb, nf, nf); batched inverses."""

    def __init__(self, block, free, alpha, beta, dt):
        self.K = block.dense("K", free)
        self.M = block.dense("M", free)
        self.C = alpha * self.M + beta * self.K
        S = self.M + GAMMA * dt * self.C + BETA * dt * dt * self.K
        self.S_inv = np.linalg.inv(S)

    def step(self, j, rhs):
        return self.S_inv[j] @ rhs

    def kmul(self, j, x):
        return self.K[j] @ x

    def cmul(self, j, x):
        return self.C[j] @ x

    def quad(self, A, x, y=None):
        """xᵀ A y per step, all steps: A (nb, nf, nf), x (nb, nf)."""
        y = x if y is None else y
        return np.einsum("si,sij,sj->s", x, A, y)

    def solve_K(self, F):
        return np.linalg.solve(self.K, F[..., None])[..., 0]


class _Sparse:
    """Per-step sparse matrices; one sparse LU of the Newmark matrix per step."""

    def __init__(self, block, free, alpha, beta, dt, frozen):
        self.K = block.sparse("K", free)
        self.M = block.sparse("M", free)
        self.C = [alpha * m + beta * k for k, m in zip(self.K, self.M)]
        n = 1 if frozen else len(self.K)
        # the Newmark matrix M + γΔt C + βΔt² K is symmetric positive definite
        self._lu = [factor(self.M[j] + GAMMA * dt * self.C[j] + BETA * dt * dt * self.K[j],
                           "spd") for j in range(n)]
        self.frozen = frozen

    def step(self, j, rhs):
        return self._lu[0 if self.frozen else j].solve(rhs, refine=False)

    def kmul(self, j, x):
        return self.K[j] @ x

    def cmul(self, j, x):
        return self.C[j] @ x

    def quad(self, A, x, y=None):
        y = x if y is None else y
        return np.array([xi @ (a @ yi) for a, xi, yi in zip(A, x, y)])

    def solve_K(self, F):
        return np.stack([factor(k, "spd").solve(f, refine=False) for k, f in zip(self.K, F)])


def _singular_step_error(block, single: FEModel, structure: Structure, k0: int,
                         time: np.ndarray) -> TrussfeError:
    """The error of a block of steps one of whose stiffness matrices is singular: the first
    such step, diagnosed on the single model (its ids, its mechanisms) and named with its
    time (:func:`~trussfe.response.along_motion.error_at_step`)."""
    item = structure.source or structure.name
    every = np.arange(single.n_dof)
    for j, K in enumerate(block.sparse("K", every)):
        try:
            factorise(K, single.free, fe=single, item=item)
        except MechanismError as err:
            return error_at_step(err, k0 + j, float(time[k0 + j]))
    return AnalysisError(item, "the stiffness matrix is singular at a step from "
                         f"t = {time[k0]:.6g} s on; {UNITS_ADVICE}")


def transient_response(structure: Structure, motion: Motion, *, bar_model: str = "pinned-beam",
                       k: int | None = None, dt: float | None = None,
                       t_end: float | None = None, damping: tuple[float, float] | None = None,
                       update: str = "per-step", mass: str = "consistent",
                       block: int | None = None,
                       progress: Callable[[int, int], None] | None = None) -> TransientResult:
    """Elastic vibration of a truss superposed on a prescribed motion of its active members.

    Parameters
    ----------
    structure : Structure
        Statically determinate pin-jointed truss with ``[active_members]``.
    motion : Motion
        Active-member histories (:mod:`trussfe.rigid.motion`).
    bar_model : {"pinned-beam", "truss"}
        FE model of the bars (docs/cli.md); pinned beams bend under their own distributed
        inertia and weight.
    k : int, optional
        Sub-elements per pinned-beam member (default 4).
    dt : float, optional
        Time step, s (default: the motion's sampling, which must be uniform); the motion is
        resampled by :func:`motion_on_grid` otherwise.
    t_end : float, optional
        End of the analysis, s (default the motion's end; later times hold the final lengths,
        for a motion that ends at rest: the residual vibration).
    damping : (alpha, beta), optional
        Rayleigh damping ``C = αM + βK`` (:func:`rayleigh`); default none.
    update : {"per-step", "frozen"}
        Matrices of the current geometry at every step, or of the initial geometry.
    mass : {"consistent", "lumped"}
        Member mass (the driving loads are exact only with the consistent mass).
    block : int, optional
        Steps assembled at once (default: as many as fit in about 64 MB).
    progress : callable, optional
        Called as ``progress(done, total)`` as the run advances (a progress bar).

    Returns
    -------
    TransientResult

    Raises
    ------
    InputError
        Bad ``dt``, ``t_end``, ``bar_model``, ``update``, ``k`` or ``damping``.
    AnalysisError
        A mechanism, a statically indeterminate truss, beams (the rigid-body comparison needs
        a pin-jointed truss), or a geometry that cannot be assembled.

    Notes
    -----
    See the module docstring: equation of motion :eq:`transient-eom`, Newmark average
    acceleration, energy balance.  Vectorised over members and over the steps of a block;
    the time loop itself costs one small solve per step.
    """
    if update not in UPDATES:
        raise InputError("update", f"unknown matrix update {update!r}; use one of "
                         + ", ".join(UPDATES))
    if bar_model not in BAR_MODELS:
        raise InputError("bar_model", f"unknown bar model {bar_model!r}; use one of "
                         + ", ".join(BAR_MODELS))
    alpha, beta = _check_damping(damping)
    if block is not None and not (isinstance(block, (int, np.integer)) and block >= 1):
        raise InputError("block", f"must be a positive number of steps, got {block!r}")
    dt_given = dt is not None
    grid = motion_on_grid(motion, dt, t_end)
    dt = float(grid.time[1] - grid.time[0])
    nt = grid.n_steps
    frozen = update == "frozen"

    # Rigid-body model: kinematics and the member forces of Lacy's model for comparison.
    rig = simulate(structure, grid, n_sections=RIGID_SECTIONS, actuators=False)
    kin = rig.kinematics
    bodies = member_bodies(structure)
    s0 = massless_active(structure)
    single = discretise(s0, bar_model=bar_model, subdivisions=k)
    free = single.free
    nf = free.size
    _dim, _n, m = structure.dim, structure.n_nodes, structure.n_members

    # Refuse a mechanism with the FE model's own diagnosis (names the moving nodes).
    first = assemble_block(structure, single, kin.coords[:1], _slice_kin(kin, slice(0, 1)),
                           bodies, bar_model=bar_model, subdivisions=k, mass=mass)
    K0 = first.sparse("K", np.arange(single.n_dof))[0]
    M0 = first.sparse("M", np.arange(single.n_dof))[0]
    try:
        factorise(K0, free, fe=single, item=structure.source or structure.name)
    except MechanismError as err:
        raise error_at_step(err, 0, float(grid.time[0])) from None
    freqs = _frequencies(K0, M0, free)

    dense = nf <= DENSE_LIMIT
    if block is None:
        block = max(1, min(nt, BLOCK_BYTES // max(1, 3 * 8 * nf * nf))) if dense else 64
    act_idx = np.flatnonzero(rig.bodies.active)

    U = np.zeros((nt, single.n_dof))
    Uq = np.zeros((nt, single.n_dof))
    N_dyn = np.zeros((nt, m))
    N_qs = np.zeros((nt, m))
    M_dyn = np.zeros((nt, m))
    M_qs = np.zeros((nt, m))
    ekin = np.zeros(nt)
    estr = np.zeros(nt)
    dwork = np.zeros(nt)
    ddiss = np.zeros(nt)
    dpar = np.zeros(nt)
    prev = None                     # (u, v, K, M, C, f) of the step before the block
    u = v = a = None
    for k0 in range(0, nt, block):
        k1 = min(nt, k0 + block)
        sl = slice(k0, k1)
        kb = _slice_kin(kin, sl)
        geom = (np.broadcast_to(kin.coords[:1], (k1 - k0,) + kin.coords.shape[1:])
                if frozen else kin.coords[sl])
        B = assemble_block(structure, single, np.ascontiguousarray(geom), kb, bodies,
                           bar_model=bar_model, subdivisions=k, mass=mass)
        try:
            ops = (_Dense(B, free, alpha, beta, dt) if dense
                   else _Sparse(B, free, alpha, beta, dt, frozen))
        except (SingularMatrixError, np.linalg.LinAlgError):
            # The massless degrees of freedom (those of the active members, whose inertia
            # enters as loads) carry only βΔt²K in M + γΔt C + βΔt²K: a short enough step
            # leaves them below the round-off of the massive ones.
            where = ("--dt" if dt_given else
                     f"{motion.source}: time step" if motion.source else "motion: time step")
            whose = "" if dt_given else " (the motion's own sampling)"
            raise AnalysisError(where, f"the time step {dt:.3g} s{whose} is too short for this "
                                "model: the Newmark matrix M + γΔt C + βΔt²K is singular to "
                                "round-off at its massless degrees of freedom; give a longer "
                                "time step (--dt)") from None
        F = B.f[:, free]
        nb = k1 - k0
        Ub = np.zeros((nb, nf))
        Vb = np.zeros((nb, nf))
        Ab = np.zeros((nb, nf))
        try:
            Uqb = ops.solve_K(F)
        except (SingularMatrixError, np.linalg.LinAlgError):
            raise _singular_step_error(B, single, structure, k0, grid.time) from None
        for j in range(nb):
            if u is None:           # quasi-static start at rest
                u = Uqb[0].copy()
                v = np.zeros(nf)
                a = np.zeros(nf)    # f − K u_qs = 0: no acceleration (M may be singular)
            else:
                up = u + dt * v + dt * dt * (0.5 - BETA) * a
                vp = v + dt * (1.0 - GAMMA) * a
                a = ops.step(j, F[j] - ops.kmul(j, up) - ops.cmul(j, vp))
                u = up + BETA * dt * dt * a
                v = vp + GAMMA * dt * a
            Ub[j], Vb[j], Ab[j] = u, v, a
        if not (np.all(np.isfinite(Ub)) and np.all(np.isfinite(Uqb))):
            raise AnalysisError(structure.source or structure.name,
                                f"the time integration produced non-finite values near "
                                f"t = {grid.time[k0]:.6g} s (singular stiffness or mass)")
        # Energies of the block and the increments from the step before it.
        ekin[sl] = 0.5 * ops.quad(ops.M, Vb)
        estr[sl] = 0.5 * ops.quad(ops.K, Ub)
        _increments(ops, dense, prev, Ub, Vb, F, dt, dwork, ddiss, dpar, k0)
        prev = (Ub[-1], Vb[-1], ops.K[-1], ops.M[-1], ops.C[-1], F[-1])
        # Member forces of the block (all steps at once on the batch model).
        U[sl][:, free] = Ub
        Uq[sl][:, free] = Uqb
        full_a = np.zeros((nb, single.n_dof))
        full_a[:, free] = Ab
        nd, md = _member_forces(B, U[sl], B.a_rigid + full_a, structure, nb)
        nq, mq = _member_forces(B, Uq[sl], B.a_rigid, structure, nb)
        N_dyn[sl], M_dyn[sl], N_qs[sl], M_qs[sl] = nd, md, nq, mq
        log.debug("transient: steps %d-%d of %d", k0, k1 - 1, nt)
        if progress is not None:
            progress(k1, nt)
    work = np.cumsum(dwork)
    diss = np.cumsum(ddiss)
    par = np.cumsum(dpar)
    e0 = ekin[0] + estr[0]
    energy = {"kinetic": ekin, "strain": estr, "work": work, "dissipated": diss,
              "parametric": par, "residual": ekin + estr - e0 - work + diss - par}

    N_rig = rig.midpoint_axial_force.copy()
    if act_idx.size:
        # The locked FE bar of an active member carries the force at the cantilever
        # connection: minus the actuator force (positive pushing the tube out).
        N_rig[:, act_idx] = -rig.actuator_force
    mid = (RIGID_SECTIONS - 1) // 2
    M_rig = rig.sections.moment_magnitude[:, :, mid].copy()
    M_rig[:, act_idx] = 0.0
    return TransientResult(
        time=grid.time, structure=structure, motion=grid, fe=single,
        displacement=_node_disp(single, U), displacement_qs=_node_disp(single, Uq),
        axial_force=N_dyn, axial_force_qs=N_qs, axial_force_rigid=N_rig,
        moment=M_dyn, moment_qs=M_qs, moment_rigid=M_rig, energy=energy,
        frequencies_hz=freqs,
        options={"bar_model": bar_model, "subdivisions": single.subdivisions, "dt": dt,
                 "update": update, "damping": (alpha, beta), "mass": mass,
                 "integrator": "Newmark average acceleration", "steps": nt},
        coords=kin.coords)


def _node_disp(fe: FEModel, U: np.ndarray) -> np.ndarray:
    """Node translations (nt, n, dim) from global DOF histories (nt, n_dof)."""
    return U[:, fe.node_dofs[:, :fe.ndim]]


def _increments(ops, dense, prev, Ub, Vb, F, dt, dwork, ddiss, dpar, k0):
    """Work, dissipation and parametric energy increments into the steps of a block.

    Step n gets the increment over [t_{n−1}, t_n] (trapezoidal rule; see the module docstring).
    """
    nb = Ub.shape[0]
    if prev is None:
        if nb == 1:
            return
        u0, v0, K0, M0, C0, f0 = Ub[0], Vb[0], ops.K[0], ops.M[0], ops.C[0], F[0]
        start = 1
    else:
        u0, v0, K0, M0, C0, f0 = prev
        start = 0
    Uprev = np.vstack([u0[None], Ub[start:-1]]) if nb - start > 0 else Ub[:0]
    Vprev = np.vstack([v0[None], Vb[start:-1]])
    Fprev = np.vstack([f0[None], F[start:-1]])
    Ucur, Vcur, Fcur = Ub[start:], Vb[start:], F[start:]
    if Ucur.shape[0] == 0:
        return
    du = Ucur - Uprev
    vbar = 0.5 * (Vcur + Vprev)
    sl = slice(k0 + start, k0 + nb)
    dwork[sl] = np.einsum("si,si->s", du, 0.5 * (Fcur + Fprev))
    if dense:
        Kc, Mc, Cc = ops.K[start:], ops.M[start:], ops.C[start:]
        Kp = np.concatenate([K0[None], ops.K[start:-1]]) if start == 0 else ops.K[:-1]
        Mp = np.concatenate([M0[None], ops.M[start:-1]]) if start == 0 else ops.M[:-1]
        Cp = np.concatenate([C0[None], ops.C[start:-1]]) if start == 0 else ops.C[:-1]
        q = ops.quad
        ddiss[sl] = dt * q(0.5 * (Cc + Cp), vbar)
        dK, dM = Kc - Kp, Mc - Mp
        dpar[sl] = 0.25 * (q(dM, Vcur) + q(dM, Vprev) + q(dK, Ucur) + q(dK, Uprev))
    else:
        Kl = ([K0] if start == 0 else []) + list(ops.K)
        Ml = ([M0] if start == 0 else []) + list(ops.M)
        Cl = ([C0] if start == 0 else []) + list(ops.C)
        for i in range(Ucur.shape[0]):
            Kp, Kc = Kl[i], Kl[i + 1]
            Mp, Mc = Ml[i], Ml[i + 1]
            Cm = 0.5 * (Cl[i] + Cl[i + 1])
            ddiss[k0 + start + i] = dt * vbar[i] @ (Cm @ vbar[i])
            dK, dM = Kc - Kp, Mc - Mp
            dpar[k0 + start + i] = 0.25 * (Vcur[i] @ (dM @ Vcur[i]) + Vprev[i] @ (dM @ Vprev[i])
                                           + Ucur[i] @ (dK @ Ucur[i])
                                           + Uprev[i] @ (dK @ Uprev[i]))


def _member_forces(B, U: np.ndarray, acc: np.ndarray, structure: Structure, nb: int):
    """Midpoint axial force and bending-moment magnitude (nb, m) from DOF histories.

    The section forces of the frame elements include their own distributed loads, weight and
    d'Alembert inertia ``−ρA (a_r + ü)`` (:meth:`FEModel.element_forces`).
    """
    fe = B.fe
    ub = np.zeros(fe.n_dof)
    ub[B.dof_map] = U
    ab = np.zeros(fe.n_dof)
    ab[B.dof_map] = acc
    grav = np.asarray(structure.gravity, dtype=float)
    f_local = []
    for g in fe.groups:
        if g.kind == "frame":
            fl = fe.local_mass(g) @ (g.T @ (-ab))
            if np.any(grav):
                fl = fl + fe.local_self_weight(g, grav)
            f_local.append(fl)
        else:                       # truss bars: loads lumped at the joints
            f_local.append(np.zeros(g.n_local))
    fel = fe.element_forces(ub, f_local)
    _x, F = fe_section_forces(fe, ub, fel)                    # (nb·m, kmax+1, ...)
    m = structure.n_members
    ksub = fe.member_subdivisions
    # Midpoint: the middle station (even k) or the mean of the two around it (odd k; a truss
    # bar's element force is constant, and its midpoint value follows from _bar_midpoints).
    lo = ksub // 2
    hi = (ksub + 1) // 2
    rows = np.arange(ksub.size)
    Fm = 0.5 * (F[rows, lo] + F[rows, hi])
    # A frame member with an odd k has its midpoint inside its middle element, where the
    # distributed loads make the moment vary (the mean of the end values would give 0 for k = 1
    # and 8/9 of a parabolic moment for k = 3): recover it by the equilibrium of the half
    # element.
    for g in fe.groups:
        if g.kind == "frame":
            _odd_midpoints(fe, g, fel, ab, grav, Fm)
        else:
            _bar_midpoints(fe, g, ab, Fm)
    N = Fm[:, 0].reshape(nb, m)
    if structure.dim == 2:
        Mm = np.abs(Fm[:, 5])
    else:
        Mm = np.hypot(Fm[:, 4], Fm[:, 5])
    return N, Mm.reshape(nb, m)


def _bar_midpoints(fe: FEModel, g, acc: np.ndarray, Fm: np.ndarray) -> None:
    """Midpoint axial force of the truss bars of group ``g``, corrected in place in ``Fm``.

    A bar (one element per member) carries the constant force ``N_e = EA Δu/L``, while its own
    axial load ``q(s) = ρA (g − a(s))·e``, with ``a`` linear between the end accelerations
    ``a_a``, ``a_b``, makes the force vary along it.  The consistent loads of the bar's ends are
    its exact end reactions, ``N(0) = N_e + ∫(1 − s/L) q``, so that
    ``N(L/2) = N(0) − ∫₀^{L/2} q = N_e − ρA L (a_b − a_a)·e / 24`` (the uniform weight drops
    out).  For a bar turning about one end at ω that is ``ρA ω² L²/24`` more tension than
    ``N_e``.
    """
    s = fe.structure
    mem = fe.element_member[g.elements]
    mu = mass_per_length(s.density, s.area)[mem]
    if not np.any(mu):
        return
    dim = fe.ndim
    a = acc[fe.node_dofs[:, :dim]]                                      # (node, dim)
    ends = s.connectivity[mem]
    e = fe.rotation[mem][:, 0, :dim]                                    # member axis
    da = np.einsum("ei,ei->e", a[ends[:, 1]] - a[ends[:, 0]], e)
    Fm[mem, 0] -= mu * fe.element_length[g.elements] * da / 24.0


#: Gauss–Legendre points and weights on [0, 1]; three points integrate the degree ≤ 4
#: integrands of :func:`_odd_midpoints` exactly.
_GAUSS_X, _GAUSS_WX = np.polynomial.legendre.leggauss(3)
_GAUSS_S, _GAUSS_W = 0.5 * (_GAUSS_X + 1.0), 0.5 * _GAUSS_WX


def _odd_midpoints(fe: FEModel, g, fel: np.ndarray, acc: np.ndarray, grav: np.ndarray,
                   Fm: np.ndarray) -> None:
    """Section forces at the midpoint of the frame members of group ``g`` whose number of
    elements is odd, written into ``Fm`` (member, 6).

    The midpoint lies at the middle of element ``j = k // 2``.  The equilibrium of the piece
    ``(x_m, x_1]`` of that element, with ``F_1, M_1`` the force and moment on the element at
    its end ``x_1``, gives the section force (what the end side exerts on the start side, as
    :func:`trussfe.fem.static.section_forces`)

    .. math:: F(x_m) = F_1 + \\int_{x_m}^{x_1} q, \\qquad
              M(x_m) = M_1 + (x_1 - x_m)\\, e_x \\times F_1
                       + \\int_{x_m}^{x_1} (\\xi - x_m)\\, e_x \\times q,

    where ``q = ρA (g − a)`` is the load of :meth:`FEModel.element_forces` here: gravity and
    the d'Alembert inertia of the acceleration ``a`` interpolated by the element's shape
    functions (linear axially, cubic transversely — Timoshenko's where the member has a shear
    area, :func:`~trussfe.mechanics.member_loads.deflection_shapes` — with the field v's
    rotation θz and w's −θy).  A Timoshenko element's mass also has rotary inertia, whose
    d'Alembert couple ``−ρI θ̈`` (θ̈ by the section-rotation shapes) adds its integral to
    ``M(x_m)``.

    Parameters
    ----------
    fe : FEModel
    g : _Group
        A frame group of ``fe``.
    fel : ndarray, shape (n_elements, 2, 6)
        :meth:`FEModel.element_forces` with those loads.
    acc : ndarray, shape (n_dof,)
        Acceleration (rigid plus elastic) on the global DOFs.
    grav : ndarray, shape (dim,)
    Fm : ndarray, shape (n_members, 6)
        Midpoint section forces, updated in place for the members concerned.
    """
    ksub = fe.member_subdivisions
    emem = fe.element_member[g.elements]
    local = g.elements - fe.member_elements[emem]              # element's place in its member
    pick = np.flatnonzero((ksub[emem] % 2 == 1) & (local == ksub[emem] // 2))
    if pick.size == 0:
        return
    dim = fe.ndim
    el = g.elements[pick]
    mem = emem[pick]
    comp = (g.G @ acc).reshape(g.elements.size, 2, g.ncomp)[pick]    # member axes
    h = fe.element_length[el]
    s = fe.structure
    mu = mass_per_length(s.density, s.area)[mem]
    g_loc = np.einsum("eij,j->ei", fe.rotation[mem], np.asarray(grav, dtype=float)[:dim]) \
        if np.any(grav) else np.zeros((el.size, dim))
    # the half element s ∈ [1/2, 1] of the element's own coordinate s = (ξ − x0)/h
    sq = 0.5 + 0.5 * _GAUSS_S
    wq = 0.5 * _GAUSS_W
    lin = np.stack([1.0 - sq, sq])                                      # (2, q)
    a0, a1 = comp[:, 0], comp[:, 1]
    # acceleration at the quadrature points, member axes: (el, q, dim)
    a_q = np.zeros((el.size, sq.size, dim))
    a_q[..., 0] = a0[:, None, 0] * lin[0] + a1[:, None, 0] * lin[1]
    # the rotation component and sign of each transverse field: v with θz = v′ (the last
    # component: [u, v, θz] in 2-D, [u, v, w, θx, θy, θz] in 3-D), w with θy = −w′
    slopes = {1: (1.0, g.ncomp - 1), 2: (-1.0, 4)}
    # a Timoshenko element's mass has rotary inertia ρI ψψᵀ too: a distributed couple
    # −ρI θ̈ about the field's axis, θ̈ interpolated by its section-rotation shapes
    couple = np.zeros((el.size, 2))                    # ∫ over the half: about z, about y
    for c in range(1, dim):
        sign, rc = slopes[c]
        phi = fe.shear_parameter("vw"[c - 1], el)
        dofs = (a0[:, c], sign * a0[:, rc], a1[:, c], sign * a1[:, rc])     # field's own
        # the element's own shape functions (Timoshenko where it has a shear area)
        N = deflection_shapes(sq[None, :], h[:, None], phi[:, None])      # (el, q, 4)
        a_q[..., c] = sum(d[:, None] * N[..., i] for i, d in enumerate(dofs))
        timo = phi > 0
        if np.any(timo):
            psi = rotation_shapes(sq[None, :], h[:, None], phi[:, None])
            spin = sum(d[:, None] * psi[..., i] for i, d in enumerate(dofs))   # φ̈ = sign θ̈
            I = (s.Iz if c == 1 else s.Iy)[mem]
            rho_i = np.where(timo, s.density[mem] * I, 0.0)
            couple[:, c - 1] = -sign * rho_i * (spin @ wq) * h
    q = mu[:, None, None] * (g_loc[:, None, :] - a_q)                  # (el, q, dim)
    Q = np.einsum("q,eqc->ec", wq, q) * h[:, None]
    arm = (sq - 0.5)[None, :] * h[:, None]                             # ξ − x_m
    MQ = np.einsum("q,eq,eqc->ec", wq, arm, q) * h[:, None]
    F1 = fel[el, 1]
    half = 0.5 * h
    out = F1.copy()
    out[:, :dim] += Q
    out[:, 5] += half * F1[:, 1] + MQ[:, 1] + couple[:, 0]
    if dim == 3:
        out[:, 4] += -half * F1[:, 2] - MQ[:, 2] + couple[:, 1]
    Fm[mem] = out


def _frequencies(K, M, free, count: int = 6) -> np.ndarray:
    """Lowest natural frequencies (Hz) of the free DOFs (dense; small models) or by
    shift-invert Lanczos."""
    Kf = K[free][:, free]
    Mf = M[free][:, free]
    nf = free.size
    if nf <= DENSE_LIMIT:
        # M φ = μ K φ with μ = 1/ω²: K is positive definite, M may be singular (massless
        # interior DOFs of the active members), whose modes have μ = 0 (infinite ω).
        mu = sla.eigh(Mf.toarray(), Kf.toarray(), eigvals_only=True)
    else:
        mu = spla.eigsh(Mf.tocsc(), k=min(count, nf - 2), M=Kf.tocsc(), which="LA",
                        return_eigenvectors=False)
    mu = np.sort(mu[mu > 0])[::-1][:count]
    return 1.0 / np.sqrt(mu) / (2 * np.pi)
