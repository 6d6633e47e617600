# SPDX-License-Identifier: MIT
"""Path following with member failure: load, displacement and arc-length control.

One function, :func:`follow_path`, follows the equilibrium path ``f_int(u) = λ f`` of a
:class:`~trussfe.nonlinear.model.NonlinearModel` under the reference load pattern ``f``:

* **load control** — Newton at prescribed λ (stops at a limit point);
* **displacement control** — one monitored displacement prescribed, λ unknown (passes load
  limit points, not displacement snap-back);
* **arc-length** (Crisfield's cylindrical constraint ``‖Δu‖ = Δs``) — passes limit points,
  snap-through and snap-back.

Along the path it

* counts the negative pivots of the tangent (:func:`trussfe.linalg.factor`, its inertia);
  a change brackets a critical point, located by bisection of the step and classified by its
  eigenvector φ: a **limit point** when ``φᵀf ≠ 0``, a **bifurcation** when ``φᵀf = 0``
  (optionally the path branches along φ);
* locates every member failure event (the step is cut so that the member's force equals the
  failure law's threshold to ``event_tolerance``), applies it (a removed member leaves the
  structure, which is re-equilibrated at the same λ; members overloaded by the redistribution
  fail in turn at that λ), and re-checks the rank of the compatibility matrix;
* when the assembly has become a mechanism, hands over to the finite-mechanism motion
  (:func:`~trussfe.nonlinear.mechanism.equilibrium_form`).
"""
from __future__ import annotations

import logging
from contextlib import contextmanager
from dataclasses import dataclass, field

from typing import Callable

import numpy as np
import scipy.sparse as sp

from ..errors import UNITS_ADVICE, AnalysisError, InputError, MechanismError
from ..linalg import SingularMatrixError, factor
from ..linalg.eigen import nearest_zero_mode
from ..mechanics.geometry import rotation_length as member_rotation_length
from ..model.postcritical import CONTROLS
from .failure import failure_margins
from .mechanism import MechanismMotion, equilibrium_form, mechanism_count
from .model import NonlinearModel

log = logging.getLogger(__name__)

_CAUSE = ("buckling", "yield", "fracture")
#: |φᵀf|/(|φ||f|) below which a critical point is a bifurcation (φ orthogonal to the load).
_BIFURCATION_RATIO = 1e-3
#: A load- or displacement-controlled step whose converged increment exceeds this multiple of
#: the tangent predictor has jumped to a remote equilibrium: it is cut.
_JUMP_FACTOR = 5.0
#: Newton iterations per step that the step-size control aims at.
_TARGET_ITERATIONS = 6.0
#: Largest growth of the step from one step to the next.
_MAX_GROWTH = 2.0
#: Default largest arc-length step, as a multiple of the first one.
_MAX_STEP_RATIO = 8.0
#: A located critical point's eigenvalue nearest zero, relative to the unloaded tangent's,
#: above which the tangent there is not singular (the inertia changed across a jump).
_SINGULAR_RATIO = 1e-3


@dataclass
class PathPoint:
    """One equilibrium state on the path.

    Attributes
    ----------
    load_factor : float
    u : ndarray, shape (dof,)
        Displacements (all DOFs of the model).
    forces : ndarray, shape (member,)
        Member axial forces, N (0 in removed members; NaN in the remaining bars at the
        points of the mechanism stage before its equilibrium form, where the bars move
        without being in equilibrium).
    alive : ndarray of bool, shape (member,)
    negative : int or None
        Negative eigenvalues of the tangent; None where unknown (a singular tangent, a
        factorisation that does not reveal the inertia, the mechanism stage).
    stage : str
        ``"equilibrium"`` or ``"mechanism"`` (rigid-bar motion after the hand-over, or the
        collapsed state that ends a path on which every member has failed).
    """

    load_factor: float
    u: np.ndarray
    forces: np.ndarray
    alive: np.ndarray
    negative: int | None = None
    stage: str = "equilibrium"


@dataclass
class Event:
    """An event on the path: a member failure, a critical point or the mechanism hand-over.

    Attributes
    ----------
    kind : str
        ``"buckling"``, ``"yield"``, ``"fracture"`` (a member reached its failure law's
        limit), ``"limit_point"``, ``"bifurcation"`` (a critical point: the number of negative
        eigenvalues of the tangent changed), ``"mechanism"`` (the failed structure became a
        mechanism and the path follows its motion), ``"equilibrium_form"`` (that motion
        reached an equilibrium) or ``"end"`` (the path stopped early; the reason is in
        ``detail``).
    load_factor : float
        λ at the event.
    member : int or None
        Index of the member that failed (failure events), else None.
    point : int
        Index of the path point at the event (``PathResult.path``), −1 when not recorded.
    force : float
        Failure events: the member's axial force at the event, N (fracture: its strain).
    threshold : float
        Failure events: the law's limit, N (fracture: strain).
    detail : str
        Text: the inertia change and load orthogonality of a critical point, the reason of an
        end.
    """

    kind: str
    load_factor: float
    member: int | None = None
    point: int = -1
    force: float = np.nan
    threshold: float = np.nan
    detail: str = ""

    def __post_init__(self):
        self.load_factor = float(self.load_factor)      # not a numpy scalar


@dataclass
class PathResult:
    """Result of :func:`follow_path`."""

    model: NonlinearModel
    path: list = field(default_factory=list)
    events: list = field(default_factory=list)
    termination: str = ""
    mechanism: MechanismMotion | None = None
    monitor: int = -1

    @property
    def load_factors(self) -> np.ndarray:
        """Load factor of every path point, shape (point,)."""
        return np.array([p.load_factor for p in self.path])

    def displacement(self, dof: int | None = None) -> np.ndarray:
        """Displacement of one DOF (default: the monitored one) along the path."""
        d = self.monitor if dof is None else dof
        return np.array([p.u[d] for p in self.path])


class _Stepper:
    """Predictor–corrector steps from a converged state (private to :func:`follow_path`)."""

    def __init__(self, model: NonlinearModel, control: str, monitor: int, tol: float,
                 max_iter: int):
        self.m = model
        self.control = control
        self.free = np.flatnonzero(model.free)
        #: length per radian of the free DOFs: 1 on translations, a length of the model on
        #: rotations (:func:`rotation_length`), so that displacement norms are lengths and
        #: residual norms forces in every consistent unit system
        self.w = np.ones(model.ndof)
        self.w[model.n_points * model.dim:] = rotation_length(model)
        self.w = self.w[self.free]
        self.f = model.load[self.free]
        self.fn = self.rnorm(self.f)
        #: constant dead load (gravity) under the scaled pattern λ f
        self.fd = model.dead[self.free]
        self.fdn = self.rnorm(self.fd)
        self.c = int(np.searchsorted(self.free, monitor)) if monitor >= 0 else -1
        self.tol = tol
        self.max_iter = max_iter
        self.lam_unit = 1.0
        self.size = float(np.ptp(model.X, axis=0).max())
        #: displacement control moves the monitored DOF the way the load first pushes it
        self.dsign = 1.0
        #: free DOFs up to which every Newton iteration refactorises the tangent
        self.full_newton_size = 2000

    @contextmanager
    def moving(self, sense: float):
        """Displacement steps of the monitored DOF in the sense ``sense`` (±1) inside the
        context, whatever the path's control (the steps that load control takes under
        displacement control)."""
        saved, self.dsign = self.dsign, sense
        try:
            yield
        finally:
            self.dsign = saved

    def dnorm(self, du) -> float:
        """Norm of a displacement vector of the free DOFs, rotations as lengths (m)."""
        return float(np.linalg.norm(self.w * du))

    def dot(self, a, b) -> float:
        """Inner product of two displacement vectors in the metric of :meth:`dnorm`."""
        return float((self.w * a) @ (self.w * b))

    def rnorm(self, r) -> float:
        """Norm of a force vector of the free DOFs, moments as forces (N)."""
        return float(np.linalg.norm(r / self.w))

    def scaled_tangent(self, K):
        """``S K S`` with ``S = 1/w``: the tangent in the DOFs of :meth:`dnorm` (its
        eigenvalues and eigenvectors do not depend on the units)."""
        if np.all(self.w == 1.0):
            return K
        S = sp.diags(1.0 / self.w)
        return (S @ K @ S).tocsr()

    def unloaded_eigenvalue(self) -> float:
        """|eigenvalue nearest zero| of the tangent of the unloaded structure (the scale of
        "singular" for the critical points), computed once."""
        if not hasattr(self, "_w0"):
            K0 = self.m.reference_tangent()[self.free][:, self.free]
            self._w0 = abs(nearest_zero_mode(self.scaled_tangent(K0))[0])
        return self._w0

    def full(self, uf):
        u = np.zeros(self.m.ndof)
        u[self.free] = uf
        return u

    def add(self, uf, duf):
        """Advance free DOFs by an increment (multiplicative for 3-D rotations)."""
        if self.m.additive:
            return uf + duf
        return self.m.add(self.full(uf), self.full(duf))[self.free]

    def eval(self, uf, tangent=True):
        res = self.m.evaluate(self.full(uf), tangent=tangent)
        K = res["tangent"][self.free][:, self.free] if tangent else None
        return res, res["internal"][self.free], K

    def step(self, uf0, lam0, fac0, ds, direction, du_prev, mode=None, fac_iter=None,
             refactor_ratio=0.5):
        """One step of size ``ds`` from a converged state: :meth:`predictor`, then
        :meth:`corrector`.

        ``fac0`` is the tangent factor at the start (predictor); ``fac_iter``, if given, a
        factor nearer the expected solution for the modified-Newton corrections, which
        refactorise when the residual falls by less than ``refactor_ratio``.  Under arc-length
        control ``direction`` is the sign of the load increment (or, in ``"branch"`` mode, the
        direction vector); without it the predictor continues ``du_prev``.  Returns
        ``(uf, lam, res, iterations, fresh factor or None)`` or None.
        """
        mode = mode or self.control
        pred = self.predictor(fac0, ds, direction, du_prev, mode)
        if pred is None:
            return None
        du, dlam, ut, mode = pred
        return self.corrector(uf0, lam0, fac0, du, dlam, ut, mode, fac_iter, refactor_ratio)

    def predictor(self, fac0, ds, direction, du_prev, mode):
        """Tangent predictor ``(Δu, Δλ, u_t, mode)`` of a step of size ``ds``, or None.

        ``u_t = K⁻¹ f`` is the tangent displacement per unit load factor.  Load control
        prescribes Δλ, displacement control the monitored Δu, arc-length ``‖Δu‖ = ds`` with the
        sign of Δλ given (``direction``) or continuing the previous increment ``du_prev``."""
        try:
            ut = fac0.solve(self.f)
        except SingularMatrixError:
            return None
        if mode == "load":
            dlam = ds
        elif mode == "displacement":
            if abs(ut[self.c]) < 1e-300:
                return None
            dlam = ds * self.dsign / ut[self.c]
        elif mode == "branch":
            return ds * direction, 0.0, ut, "arc-length"
        else:
            sign = 1.0
            if du_prev is not None:
                sign = 1.0 if self.dot(du_prev, ut) >= 0.0 else -1.0
            elif direction is not None:
                sign = float(direction)
            dlam = sign * ds / self.dnorm(ut)
        return dlam * ut, dlam, ut, mode

    def corrector(self, uf0, lam0, fac0, du, dlam, ut, mode, fac_iter=None,
                  refactor_ratio=0.5):
        """Newton corrections of a predicted increment ``(du, dlam)`` to equilibrium on the
        step's constraint (load: fixed λ; displacement: fixed monitored DOF; arc-length:
        Crisfield's cylinder ``‖Δu‖ = ‖du‖``).  Returns the :meth:`step` tuple or None."""
        f = self.f
        ds_arc = self.dnorm(du)
        # load and displacement control may converge to a remote equilibrium beyond a limit
        # point (a dynamic snap); such a step is refused (and cut) rather than followed
        jump = _JUMP_FACTOR * max(ds_arc, 1e-12 * self.size) if mode in ("load",
                                                                         "displacement") \
            else np.inf
        # full Newton on small systems; on large ones modified Newton: the tangent is
        # refactorised only when the residual stops falling fast (ratio > 0.5)
        modified = len(uf0) > self.full_newton_size
        fac, dt_fac, rprev, fresh = fac0, ut, np.inf, None
        if fac_iter is not None and modified:
            fac, dt_fac = fac_iter, fac_iter.solve(f, refine=False)
        uf = self.add(uf0, du)
        for it in range(1, (self.max_iter if refactor_ratio <= 0.5 else 2 * self.max_iter) + 1):
            lam = lam0 + dlam
            res, fint, K = self.eval(uf, tangent=not modified)
            R = fint - lam * f - self.fd
            scale = self.fn * max(abs(lam), self.lam_unit) + self.fdn
            if not np.all(np.isfinite(R)):
                return None
            rn = self.rnorm(R)
            if rn <= self.tol * scale:
                if self.dnorm(du) > jump:
                    return None
                return uf, lam, res, it, fresh
            try:
                if not modified or rn > refactor_ratio * rprev:
                    if K is None:
                        K = self.eval(uf)[2]
                    fac = _tangent_factor(K)
                    fresh = fac
                    dt_fac = fac.solve(f, refine=False)
                rprev = rn
                dr = -fac.solve(R, refine=False)
                dt = dt_fac
            except SingularMatrixError:
                return None
            if mode == "load":
                dl = 0.0
            elif mode == "displacement":
                dl = -dr[self.c] / dt[self.c]
            else:
                a = self.dot(dt, dt)
                w = du + dr
                b = 2.0 * self.dot(dt, w)
                cc = self.dot(w, w) - ds_arc ** 2
                disc = b * b - 4 * a * cc
                if disc < 0:
                    return None
                roots = ((-b + np.sqrt(disc)) / (2 * a), (-b - np.sqrt(disc)) / (2 * a))
                dl = max(roots, key=lambda r: self.dot(w + r * dt, du))
            corr = dr + dl * dt
            du = du + corr
            dlam += dl
            # the correction applies to the current iterate (rotations: composed with it)
            uf = uf0 + du if self.m.additive else self.add(uf, corr)
            # round-off floor of the residual: accept when the correction is negligible
            if self.dnorm(corr) <= 1e-13 * (self.dnorm(uf) + self.size):
                if self.dnorm(du) > jump:
                    return None
                return (uf, lam0 + dlam, self.m.evaluate(self.full(uf)), it, fresh)
        return None


def rotation_length(model: NonlinearModel) -> float:
    """The length (m) per radian in which the path following measures rotations.

    A displacement vector of a beam model holds lengths (m) and angles (rad), a residual
    forces (N) and moments (N·m): their plain norms change with the unit of length, and so
    would the arc length, the convergence test and the step control.  With rotations times
    this length (and moments divided by it) every norm is a length or a force, the same in
    every consistent unit system and for geometrically similar structures.  It is the median
    length of the members modelled as beams (every member when none is;
    :func:`trussfe.mechanics.geometry.rotation_length`), exactly — not rounded like :func:`trussfe.fem.solver.rotation_scale`, so that a scaled model follows
    the same path to round-off; 1 m members (most SI models) are measured as before.
    """
    s = model.structure
    beams = np.unique(model.b_member) if len(model.b_member) else np.arange(s.n_members)
    return member_rotation_length(s.lengths()[beams])


def _dead_load_state(st, max_cuts: int) -> np.ndarray:
    """The equilibrium under the dead load alone (λ = 0), where the path starts.

    The dead load is applied in one load-controlled increment when the structure answers it
    nearly linearly: the converged increment within :data:`_RAMP_LINEARITY` of the tangent's
    prediction, and the tangent halfway along it positive definite.  Otherwise — a large
    weight, a shallow arch — a load increment may converge to another form beyond a limit
    point (the von Mises truss under a weight above its limit load lands upside down), so
    the weight is applied by arc-length steps instead (:func:`_dead_load_ramp`), which stop
    at such a limit point: the structure cannot carry its own weight, an error."""
    ramp = _Stepper(st.m, "load", -1, st.tol, st.max_iter)
    ramp.f, ramp.fn = st.fd, st.fdn
    ramp.fd, ramp.fdn = np.zeros_like(st.fd), 0.0
    uf = np.zeros(st.free.size)
    try:
        fac = factor(ramp.eval(uf)[2], "symmetric")
        new = ramp.step(uf, 0.0, fac, 1.0, None, None, "load")
        if new is not None:
            predicted = ramp.dnorm(fac.solve(ramp.f))
            half = _inertia(_tangent_factor(ramp.eval(0.5 * new[0])[2]))
            if ramp.dnorm(new[0]) <= _RAMP_LINEARITY * predicted and half == 0:
                return new[0]
    except SingularMatrixError:
        pass
    return _dead_load_ramp(ramp, max_cuts)


#: The dead load in one increment when the increment converged within this factor of the
#: tangent's prediction (:func:`_dead_load_state`).
_RAMP_LINEARITY = 1.5


def _dead_load_ramp(ramp: _Stepper, max_cuts: int) -> np.ndarray:
    """The dead load ``t f_d`` followed from t = 0 to 1 by arc-length steps (a quarter of the
    linear response each at first), the last one cut to t = 1 by a load-controlled step on
    the branch it ended on.  A critical point on the way (the inertia of the tangent changes)
    or a load that turns back is a limit: there is no equilibrium under the whole weight on
    this branch."""
    s = ramp.m.structure

    def no_equilibrium(where: str) -> AnalysisError:
        return AnalysisError(s.source or s.name, "no equilibrium under the dead load "
                             f"(gravity) alone{where}: the structure cannot carry its own "
                             "weight")
    arc = _Stepper(ramp.m, "arc-length", -1, ramp.tol, ramp.max_iter)
    arc.f, arc.fn, arc.fd, arc.fdn = ramp.f, ramp.fn, ramp.fd, ramp.fdn
    uf, t = np.zeros(ramp.free.size), 0.0
    try:
        fac = _tangent_factor(arc.eval(uf)[2])
        ds = 0.25 * arc.dnorm(fac.solve(arc.f))
    except SingularMatrixError:
        raise no_equilibrium("") from None
    neg, du_prev, first = _inertia(fac), None, ds
    for _ in range(_RAMP_STEPS):
        new, checked, _ = _attempt(arc, uf, t, fac, ds, 1.0, du_prev, None, du_prev, neg,
                                   max_cuts, True)
        if new is None:
            raise no_equilibrium("")
        uf1, t1, _, its, fresh, dss = new
        try:
            fac1 = checked or fresh or _tangent_factor(arc.eval(uf1)[2])
        except SingularMatrixError:
            raise no_equilibrium(f" (a limit at {t:.3g} of it)") from None
        if _crossed(neg, _inertia(fac1)) or t1 <= t:
            # a limit inside the step: beyond the whole weight (the branch passes t = 1
            # before it) or before it, which shorter steps tell apart
            if dss > _RAMP_RESOLUTION * first:
                ds = 0.5 * dss
                continue
            raise no_equilibrium(f" (a limit at {t:.3g} of it)")
        if t1 >= 1.0:
            # the branch reaches the whole weight between t and t1: land on it
            land = ramp.step(uf, t, fac, 1.0 - t, None, None, "load")
            if land is None:
                raise no_equilibrium("")
            return land[0]
        du_prev, uf, t, fac = uf1 - uf, uf1, t1, fac1
        ds = _next_step(dss, its, 8.0 * first, "arc-length")
    raise no_equilibrium(f" (not reached in {_RAMP_STEPS} steps)")


#: Arc-length steps at most of :func:`_dead_load_ramp`.
_RAMP_STEPS = 200
#: Steps in a row shortened to stay short of a corner of several members' laws after which
#: the next step is taken over it (:func:`follow_path`).
_JUMP_CORNER_STEPS = 3
#: The ramp's steps are halved down to this fraction of the first one to locate a limit.
_RAMP_RESOLUTION = 1e-3


def _tangent_factor(K):
    """Factor of a tangent for the steps: ``P K Pᵀ = L D Lᵀ`` with diagonal pivots (which
    gives the inertia), else LU with partial pivoting (inertia unknown).

    Diagonal pivoting can break down — a pivot that vanishes although ``K`` is regular — on
    an indefinite tangent, and on the unsymmetric tangent of a 3-D beam under a moment of
    fixed direction (docs/postcritical.md, *Moments*): a cantilever rolled up by an end
    moment under arc-length control met one such pivot at every state near λ = 0.97 of
    ``M = 2πEI/L`` and the path stopped there.  Partial pivoting tells such a breakdown from
    a singular tangent, which it still refuses (:class:`SingularMatrixError`).  SuperLU's
    symmetric mode takes that LU itself (:func:`trussfe.linalg.factor`); the fallback here
    serves PARDISO's ``LDLᵀ`` of large tangents, which calls perturbed pivots singular.

    Parameters
    ----------
    K : scipy.sparse matrix
        The tangent on the free DOFs.

    Returns
    -------
    trussfe.linalg.Factor
    """
    try:
        return factor(K, "symmetric")
    except SingularMatrixError:
        return factor(K, "general")


def _inertia(fac) -> int | None:
    """Negative pivots of a factor (:attr:`trussfe.linalg.Factor.inertia`), or None when
    unknown (no factor, or a factorisation that had to pivot off the diagonal and did not
    count them)."""
    return None if fac is None or fac.inertia is None else int(fac.inertia)


def _crossed(neg0: int | None, neg1: int | None) -> bool:
    """A change of the inertia between two states (never claimed when either is unknown)."""
    return neg0 is not None and neg1 is not None and neg0 != neg1


def _next_step(ds: float, iterations: int, ds_max: float, control: str) -> float:
    """Step control: the next increment from the last one and the Newton iterations it took
    (aiming at :data:`_TARGET_ITERATIONS`), growing by at most :data:`_MAX_GROWTH` per step and
    never beyond ``ds_max``; displacement control keeps its step."""
    if control == "displacement":
        return ds
    nxt = float(np.clip(ds * np.sqrt(_TARGET_ITERATIONS / max(iterations, 1)),
                        0.25 * ds, _MAX_GROWTH * ds))
    return min(nxt, ds_max)


def _next_sign(sign: float, neg0: int | None, neg1: int | None, limit_point: bool,
               ut1: np.ndarray | None, du: np.ndarray, dot=np.dot) -> float:
    """Arc-length: the sign of the load increment of the next predictor.

    Between limit points the load factor is monotonic along the path, and at a limit point it
    turns back: the sign is kept, and flips where the step crossed a limit point (an odd
    change of the number of negative pivots at a critical point classified as a limit point;
    past a bifurcation the fundamental path goes on in the same sense).  Where the inertia is
    unknown the next predictor continues the last increment (the tangent ``ut1`` at the new
    state along the step ``du``)."""
    if neg0 is not None and neg1 is not None:
        return -sign if limit_point and (neg1 - neg0) % 2 == 1 else sign
    if ut1 is None:
        return sign
    return 1.0 if dot(ut1, du) >= 0.0 else -1.0


#: Why a path cannot start from a tangent whose pivots passed but whose solve is not finite.
UNSOLVABLE_START = ("the tangent stiffness of the unloaded structure is numerically singular: "
                    "the displacement under the reference loads is not finite (a stiffness "
                    "too small for floating-point numbers); check E and the section "
                    "properties in [materials] and [sections]")


#: Default first step of displacement and arc-length control, as a fraction of the size of
#: the structure (its largest extent).
DEFAULT_STEP_FRACTION = 1.0 / 1000.0


def default_step(control: str, steps: int, size: float, ut: np.ndarray, c: int,
                 max_load_factor: float | None, norm=np.linalg.norm) -> float:
    """The first increment when none is given, derived from the structure.

    * load control: ``max_load_factor / steps`` (1/steps without a maximum);
    * displacement and arc-length control: a step moves the structure
      :data:`DEFAULT_STEP_FRACTION` of its size ``L`` (the monitored displacement by ``L/1000``,
      or the displacement norm ``Δs = L/1000``) — a scale that does not depend on the size of
      the reference load, so that the default run reaches the first limit point of a
      snap-through structure whatever load pattern is given; with ``max_load_factor`` never
      more than a tenth of the linear response to it.

    ``ut`` is the linear displacement per unit load factor (free DOFs), ``c`` the monitored
    one's index in it, ``norm`` the displacement norm of the arc length
    (:meth:`_Stepper.dnorm`).
    """
    if control == "load":
        return (max_load_factor if max_load_factor is not None else 1.0) / steps
    linear = np.abs(ut[c]) if control == "displacement" else norm(ut)
    step = DEFAULT_STEP_FRACTION * size
    if max_load_factor is not None:
        step = min(step, max_load_factor * linear / 10.0)
    return float(step)


def _mech_free(model: NonlinearModel) -> np.ndarray:
    """Free joint coordinates for the rank check, shape (node, dim): joints still reached by a
    live member, or loaded (a loaded joint left without members is a mechanism).

    A coordinate on a spring is held like a support: the tangent has a zero-stiffness mode
    only where the bars leave one with no spring on it, and the rigid-bar motion of the
    hand-over treats the springs as rigid as it treats the bars."""
    s = model.structure
    n = s.n_nodes * s.dim
    sprung = (model.spring[:n] > 0).reshape(s.n_nodes, s.dim)
    return ~s.supports[:, : s.dim] & ~sprung & _touched(model)


def _touched(model):
    """Joint coordinates that take part in the assembly (member, support or load)."""
    s = model.structure
    t = np.zeros(s.n_nodes, dtype=bool)
    t[s.connectivity[model.alive].ravel()] = True
    return np.repeat(t[:, None], s.dim, axis=1) | s.supports[:, : s.dim] | (
        s.loads[:, : s.dim] != 0)


def follow_path(model: NonlinearModel, control: str = "arc-length", steps: int = 100,
                step: float | None = None, max_load_factor: float | None = None,
                monitor: int | None = None, branch: bool = False,
                tolerance: float = 1e-9, max_iterations: int = 30,
                event_tolerance: float = 1e-6, locate_critical: bool = True,
                handover: bool = True, max_cuts: int = 12,
                branch_step: float = 0.01,
                max_displacement: float | None = None,
                max_failures: int | None = None,
                max_step: float | None = None,
                progress: Callable[[int, int], None] | None = None) -> PathResult:
    """Follow the equilibrium path of a structure under ``λ f``.

    Parameters
    ----------
    model : NonlinearModel
    control : {"load", "displacement", "arc-length"}
    steps : int
        Number of converged steps (events add located points).
    step : float, optional
        First increment: Δλ (load control), Δu of the monitored DOF (displacement control) or
        the arc length Δs in displacement norm (arc-length).  Default: see
        :func:`default_step` (a step moves the structure 1/1000 of its size).
    max_load_factor : float, optional
        Stop at it: a step that would pass it lands on it (default: no limit for
        displacement and arc-length control, 1 for load control).
    monitor : int, optional
        Global DOF monitored (and prescribed under displacement control); default the
        translation with the largest reference load.
    branch : bool
        At a bifurcation, continue on the secondary branch along the critical eigenvector.
    tolerance : float
        Newton convergence: ``‖f_int − λf‖ ≤ tolerance · ‖f‖ · max(|λ|, λ₁)``.
    max_iterations : int
        Newton iterations per step before the step is cut.
    event_tolerance : float
        Failure events are located to ``|force/threshold − 1| ≤ event_tolerance``.
    locate_critical : bool
        Locate critical points by bisection (else report the bracketing step).
    handover : bool
        Hand over to the finite-mechanism motion when the bars left form a mechanism.
    max_cuts : int
        Halvings of a step that fails to converge before the path ends.
    branch_step : float
        First step on a secondary branch, as a fraction of the structure's size.
    max_displacement : float, optional
        Stop when the monitored displacement reaches this magnitude, m (a step that would
        pass it lands on it).
    max_failures : int, optional
        Stop after this many member failure events.
    max_step : float, optional
        Largest increment the step control may grow to (default 8 × the first one; the step
        grows by at most 2× per step).
    progress : callable, optional
        Called as ``progress(done, total)`` as the run advances (a progress bar).

    Returns
    -------
    PathResult

    Raises
    ------
    InputError
        No load pattern, unknown control, bad step or monitor.
    MechanismError
        The structure is a mechanism before any load is applied.
    AnalysisError
        The unloaded tangent passes its pivot test but its solve is not finite (a stiffness
        below what floating-point numbers resolve).
    """
    if control not in CONTROLS:
        raise InputError("--control", f"unknown control {control!r}; valid: "
                                      f"{', '.join(CONTROLS)}")
    if int(steps) < 1:
        raise InputError("--steps", f"must be at least 1, got {steps}")
    m = model
    s = m.structure
    free = np.flatnonzero(m.free)
    f = m.load[free]
    if np.linalg.norm(f) == 0.0:
        cases = ("; the post-critical analysis follows [loads], which a model with "
                 "[load_cases] has none of: give the case to follow as [loads] of a model "
                 "without [load_cases]" if "load_cases" in s.extensions else "")
        raise InputError(f"{s.source or s.name}: [loads]",
                         "no load pattern on a free degree of freedom: give the reference "
                         f"loads that the load factor λ scales{cases}")
    if monitor is None:
        fl = np.abs(m.load[: s.n_nodes * s.dim])
        # the most loaded translation; with moments only, the most loaded rotation
        monitor = int(np.argmax(fl)) if fl.max() > 0 else int(np.argmax(np.abs(m.load)))
    if not m.free[monitor]:
        raise InputError("--monitor", "the monitored displacement is a supported DOF")
    if step is not None and not (np.isfinite(step) and step > 0):
        raise InputError("step", f"must be a positive number, got {step}")
    if max_load_factor is None and control == "load":
        max_load_factor = 1.0
    st = _Stepper(m, control, monitor, tolerance, max_iterations)
    out = PathResult(model=m, monitor=monitor)

    uf = np.zeros(free.size)
    lam = 0.0
    if st.fdn > 0:
        uf = _dead_load_state(st, max_cuts)
    res, fint, K = st.eval(uf)
    try:
        fac = factor(K, "symmetric")
    except SingularMatrixError:
        nm, _ = mechanism_count(s.coords, s.connectivity, _mech_free(m))
        if nm == 0:
            # rigid by its geometry, singular by its numbers (a modulus of 1e-320 Pa)
            raise MechanismError(s.source or s.name, "the tangent stiffness of the unloaded "
                                 "structure is numerically singular although its geometry is "
                                 f"rigid; {UNITS_ADVICE}", mechanisms=0) from None
        raise MechanismError(s.source or s.name, f"the unloaded structure is a mechanism "
                             f"({nm} independent mechanism(s)); a post-critical analysis "
                             "needs a stiff start — see 'trussfe mechanism'",
                             mechanisms=nm) from None
    try:
        ut = fac.solve(f, refine=False)
    except SingularMatrixError:
        # the pivots are all of one (vanishing) magnitude, so the factor passed its relative
        # pivot test, yet the solve overflowed: no step can start from this tangent
        raise AnalysisError(s.source or s.name, UNSOLVABLE_START) from None
    if control == "displacement":
        if abs(st.w[st.c] * ut[st.c]) <= 1e-12 * np.abs(st.w * ut).max():
            raise InputError("--monitor", "the reference load does not move the monitored "
                                        "displacement: choose another for displacement control")
        st.dsign = float(np.sign(ut[st.c]))
    if step is None:
        step = default_step(control, steps, st.size, ut, st.c, max_load_factor, st.dnorm)
    st.lam_unit = abs(step / ut[st.c]) if control == "displacement" else (
        abs(step) if control == "load" else abs(step) / st.dnorm(ut))

    def record(uf_, lam_, res_, neg, stage="equilibrium"):
        out.path.append(PathPoint(lam_, st.full(uf_), m.member_axial_forces(res_),
                                  m.alive.copy(), neg, stage))
        return len(out.path) - 1

    record(uf, lam, res, _inertia(fac))
    ds = float(step)
    size = float(np.ptp(m.X, axis=0).max())
    ds_max = abs(ds) if control == "load" else _MAX_STEP_RATIO * abs(ds)
    if max_step is not None:
        if not (np.isfinite(max_step) and max_step > 0):
            raise InputError("max_step", f"must be a positive number, got {max_step}")
        ds_max = float(max_step)
    du_prev = None
    branch_dir = None
    neg = _inertia(fac)
    #: arc-length: the sign of the load increment of the next predictor
    sign = 1.0
    rejected = 0
    #: consecutive rejections of steps that crossed an inertia change, counted across the
    #: shortened steps accepted in between (a corner of a member's law: see below)
    corner_cuts = 0
    #: consecutive steps shortened to stay short of an inertia jump of two or more
    jump_cuts = 0
    k = 0
    while k < steps:
        if progress is not None:
            progress(k, steps)
        if max_load_factor is not None and lam >= max_load_factor * (1 - 1e-12):
            out.termination = f"reached the maximum load factor {max_load_factor:g}"
            break
        if max_failures is not None and sum(e.kind in _CAUSE for e in out.events) \
                >= max_failures:
            out.termination = f"reached {max_failures} member failure events"
            break
        # (to round-off: a path whose steps end on the limit stops there in every unit)
        if max_displacement is not None and abs(uf[st.c]) >= max_displacement * (1 - 1e-12):
            out.termination = f"reached the maximum displacement {max_displacement:g} m"
            break
        dss = ds
        if control == "load" and max_load_factor is not None:
            dss = min(ds, max_load_factor - lam)
        mode = "branch" if branch_dir is not None else None
        # arc-length steps are given the sign of their load increment (step control below);
        # a branch step its direction vector
        arc = control == "arc-length" and mode is None
        direction = branch_dir if mode == "branch" else (sign if arc else None)
        prev = None if arc else du_prev
        new, checked, jumped = _attempt(st, uf, lam, fac, dss, direction, prev, mode, du_prev,
                                        neg, max_cuts, arc,
                                        jump_ok=jump_cuts >= _JUMP_CORNER_STEPS)
        if new is not None:
            dss = new[-1]
            new = new[:-1]
        if control == "load" and (new is None or dss < 1e-4 * abs(step)):
            # the load step cannot be taken: a member event just ahead may soften the
            # structure so much that equilibrium at a larger load lies far away (a plastic
            # collapse); it is reached by displacement control and taken as this step
            ahead = _event_ahead(st, m, uf, lam, fac, res, ds, neg, max_cuts,
                                 event_tolerance)
            if ahead is not None:
                new, checked, dss = ahead[:5], None, ds
        # a load or monitored-displacement step cut to 1e-4 of the first: the path turns
        # back in the controlled quantity (a limit point, a snap-back) or collapses there;
        # steps creeping towards it would only pile up points
        if new is None or (control != "arc-length" and dss < 1e-4 * abs(step)):
            out.termination = _cannot_continue(control, lam, neg,
                                              _failed_at(out, s, lam, st.lam_unit))
            out.events.append(Event("end", lam, detail=out.termination))
            break
        uf1, lam1, res1, its, fac_new = new
        if control != "load" and mode != "branch":
            # a step past a stop lands on it instead, where that part of the path goes on
            # there (a load or monitored-displacement step to the limit converges)
            land = _land_on_stop(st, uf, lam, fac, uf1, lam1, max_load_factor,
                                 max_displacement)
            if land is not None:
                uf1, lam1, res1, its, fac_new = land
                checked = None
        n_events = len(out.events)
        # ---- member failure events inside the step: cut the step to the first one
        mg0 = m.margins(res)
        mg1 = m.margins(res1)
        crossed = (mg1 > event_tolerance) & (mg0 <= event_tolerance)
        if crossed.any():
            located = _locate_failure(st, m, uf, lam, fac, dss, direction, prev, mode,
                                      mg0, uf1, lam1, res1, fac_new, event_tolerance)
            uf1, lam1, res1, fac_new = located
            checked = None
        mg1 = m.margins(res1)
        hit = (mg1 >= -event_tolerance) & (mg0 < -event_tolerance)
        # ---- accept the step; the factor of the last Newton iteration (one tiny correction
        # away from the converged state) serves the next predictor and the inertia count
        try:
            fac1 = checked or (fac_new if fac_new is not None
                               else _tangent_factor(st.eval(uf1)[2]))
            neg1 = _inertia(fac1)
        except SingularMatrixError:
            fac1, neg1 = None, None
        if (control == "load" and fac1 is not None and _crossed(neg, neg1) and neg1 > neg
                and not hit.any()):
            # load control cannot pass a critical point: a limit point ends the path; on a
            # bifurcation the (now unstable) fundamental path is followed
            kind, detail, _, _ = _classify(st, uf1, neg, neg1)
            out.events.append(Event(kind, lam1, point=len(out.path), detail=detail
                                    + "; located within the last load step"))
            if kind == "limit_point":
                m.commit(res1)
                record(uf1, lam1, res1, neg1)
                out.termination = _cannot_continue(control, lam1, neg1)
                out.events.append(Event("end", lam1, detail=out.termination))
                break
        # an inertia change without a member event, on the fundamental path
        changed = (arc and fac1 is not None and _crossed(neg, neg1) and not hit.any()
                   and mode != "branch")
        corner = changed and corner_cuts >= max_cuts
        # A corner of several members' laws at once (members reaching a buckling cap together:
        # the inertia jumps by two or more without a singular state): every step over it was
        # rejected as crossing several critical points, and the steps accepted before it only
        # came closer; after _JUMP_CORNER_STEPS such steps one is taken over it, and the path
        # continues the motion there (the load sense from the new tangent along the step).
        jump_corner = changed and abs(neg1 - neg) > 1 and jump_cuts >= _JUMP_CORNER_STEPS
        jump_cuts = jump_cuts + 1 if jumped and not _crossed(neg, neg1) else 0
        if jump_corner:
            crit = None
        elif corner:
            # A corner of a member's law (the end of a softening branch): the tangent jumps
            # across zero stiffness without passing a singular state, so every step that
            # crosses it is rejected and each shortened step accepted before it comes closer
            # to it, never over it.  The step is taken over the corner instead; an odd change
            # of the inertia there turns the load factor back, as at a limit point.
            crit = None
            if (neg1 - neg) % 2 == 1:
                out.events.append(Event("limit_point", lam1, point=len(out.path),
                                        detail=f"negative eigenvalues {neg} -> {neg1} at a "
                                        "corner of a member's law (the tangent jumps; no "
                                        "singular state)"))
        elif (locate_critical and fac1 is not None and _crossed(neg, neg1) and not hit.any()
                and mode != "branch" and control != "load"):
            crit = _critical_point(st, m, out, uf, lam, fac, dss, direction, prev, mode,
                                   neg, neg1, record, branch,
                                   may_reject=rejected < max_cuts and arc)
            if crit == "reject":
                # the inertia changed across a jump, not at a singular tangent: a smaller step
                rejected += 1
                corner_cuts += 1
                ds = 0.5 * dss
                continue
        else:
            crit = None
            if fac1 is not None and _crossed(neg, neg1) and hit.any() and control != "load":
                # a failure event changed the inertia: the critical point is the event state
                kind, detail, _, _ = _classify(st, uf1, neg, neg1)
                out.events.append(Event(kind, lam1, point=len(out.path),
                                        detail=detail + "; at a member failure event"))
        # a shortened step accepted right after a rejection keeps the count of the corner
        corner_cuts = corner_cuts if rejected and not corner else 0
        rejected = 0
        branch_dir = None
        m.commit(res1)
        if crit is not None:
            # branch: restart from the bifurcation point along the critical eigenvector
            u2, lam2, res2, phi = crit
            du_prev = None
            uf, lam, res = u2, lam2, res2
            try:
                fac1 = factor(st.eval(uf)[2], "symmetric")
                neg1 = _inertia(fac1)
            except SingularMatrixError:
                # (a multiple critical point) the factor from before serves the predictor
                fac1 = fac
            branch_dir = phi if phi @ st.f >= 0 else -phi
            ds = max(dss, branch_step * size)
            ds_max = max(ds_max, 8.0 * ds)
            fac, neg = fac1, neg1
            k += 1
            continue
        if control == "arc-length" and fac1 is not None:
            limit = any(e.kind == "limit_point" for e in out.events[n_events:])
            if _crossed(neg, neg1) and len(out.events) == n_events:
                limit = _classify(st, uf1, neg, neg1)[0] == "limit_point"
            ut1 = fac1.solve(st.f)
            if mode == "branch":
                # the first step on a new branch: its load sense is the one it took
                sign = 1.0 if st.dot(ut1, uf1 - uf) >= 0.0 else -1.0
            elif _crossed(neg, neg1) and abs(neg1 - neg) > 1:
                # several eigenvalues crossed at once (members reaching their limits
                # together): parity says nothing of the load's sense; the motion continues
                # and the load follows the new tangent along it
                turn = _next_sign(sign, None, None, False, ut1, uf1 - uf, st.dot)
                if turn != sign:
                    where = ("at a corner of several members' laws (the tangent jumps; no "
                             "singular state)" if jump_corner else "with other critical points")
                    out.events.append(Event("limit_point", lam1, point=len(out.path),
                                            detail=f"negative eigenvalues {neg} -> {neg1} "
                                            f"{where}: the load turns back"))
                sign = turn
            else:
                sign = _next_sign(sign, neg, neg1, limit, ut1, uf1 - uf, st.dot)
        du_prev = uf1 - uf
        uf, lam, res = uf1, lam1, res1
        point = record(uf, lam, res, neg1)
        # a step cut short at a member event adds a located point, not a step
        k += 0 if crossed.any() else 1
        # ---- apply the failure events at this state
        if hit.any() and _apply_failures(st, m, out, hit, mg1, res, lam, point):
            uf_new, res_new, fac_new, reason = _reequilibrate(st, m, out, uf, lam, handover,
                                                              record)
            if reason:
                out.termination = reason
                break
            uf, res, fac1 = uf_new, res_new, fac_new
            neg1 = _inertia(fac1)
        if fac1 is None:
            out.termination = _cannot_continue(control, lam, neg,
                                              _failed_at(out, s, lam, st.lam_unit))
            out.events.append(Event("end", lam, detail=out.termination))
            break
        fac = fac1
        neg = neg1
        # under load control a step cut short at an event is followed by the step before it
        ds = _next_step(ds if control == "load" and crossed.any() else dss, its, ds_max,
                        control)
    else:
        # the last step may have reached a limit as the steps ran out
        if max_load_factor is not None and lam >= max_load_factor * (1 - 1e-12):
            out.termination = f"reached the maximum load factor {max_load_factor:g}"
        elif max_displacement is not None and abs(uf[st.c]) >= max_displacement * (1 - 1e-12):
            out.termination = f"reached the maximum displacement {max_displacement:g} m"
        else:
            out.termination = f"completed {steps} steps"
    if not out.termination:
        out.termination = f"completed {k} steps"
    log.info("path: %d points, %d events; %s", len(out.path), len(out.events),
             out.termination)
    return out


def _attempt(st, uf, lam, fac, dss, direction, prev, mode, du_prev, neg, max_cuts, arc,
             jump_ok=False):
    """Step control: one step of size ``dss``, halved until it converges and, under
    arc-length control, until it is acceptable — a step that turns back along the path
    (its increment against the last one) while the inertia did not change, or that crosses
    several critical points at once (unless ``jump_ok``: a corner of several members' laws,
    where the inertia jumps by more than one without a singular state), is rejected and
    halved.  (At the smallest step the result is taken as it is.)  Returns
    ``((uf, lam, res, its, fresh, dss), checked, jumps)`` — the :meth:`_Stepper.step`
    tuple with the step size taken, the factor made at the new state for the check (None
    when the step's own ``fresh`` factor serves) and the number of steps rejected for
    crossing several critical points — or ``(None, None, jumps)``.
    """
    jumps = 0
    for cut in range(max_cuts + 1):
        new = st.step(uf, lam, fac, dss, direction, prev, mode)
        if new is not None and arc and cut < max_cuts:
            try:
                f1 = new[4] if new[4] is not None else _tangent_factor(st.eval(new[0])[2])
            except SingularMatrixError:
                f1 = None
            neg1 = _inertia(f1)
            dl = new[1] - lam
            # without a critical point in the step neither the displacement increment nor
            # the load increment may turn against the path's direction
            turned = not _crossed(neg, neg1) and (
                (du_prev is not None and st.dot(new[0] - uf, du_prev) < 0.0)
                or (direction * dl < 0.0 and abs(dl) > 1e-9 * max(abs(lam), st.lam_unit)))
            several = (_crossed(neg, neg1) and abs(neg1 - neg) > 1 and cut < max_cuts // 2
                       and not jump_ok)
            jumps += several
            if not (turned or several):
                return new + (dss,), (f1 if new[4] is None else None), jumps
            new = None
        if new is not None:
            return new + (dss,), None, jumps
        dss *= 0.5
    return None, None, jumps


def _cannot_continue(control: str, lam: float, neg: int | None,
                     failed_here: list[str] | None = None) -> str:
    """The termination text of a path that cannot go on from the load factor ``lam``;
    ``failed_here``: the members whose failure events were applied at that state (under load
    control, a collapse: what they carried has nowhere to go at a larger load)."""
    why = "Newton iterations did not converge even with a step cut 4096 times"
    if control == "load" and failed_here:
        names = ", ".join(failed_here[:4]) + (", ..." if len(failed_here) > 4 else "")
        why = ("no equilibrium at a larger load factor: the structure collapses when "
               f"member(s) {names} reach their limit at this load factor; use --control "
               "displacement or arc-length to follow it further")
    elif control == "load" and neg:         # a count of negative eigenvalues, not unknown
        why = ("no equilibrium at a larger load factor: the tangent stiffness has "
               f"{neg} negative eigenvalue(s) (a limit point or unstable branch); use "
               "--control arc-length")
    elif control == "load":
        why = ("no equilibrium at a larger load factor (a limit point); use "
               "--control arc-length")
    elif control == "displacement":
        why = ("no step of the monitored displacement of more than 1e-4 of the first "
               "converges here: the monitored displacement may turn back (a snap-back); use "
               "--control arc-length")
    return f"path cannot be continued at load factor {lam:.6g}: {why}"


def _land_on_stop(st, uf, lam, fac, uf1, lam1, max_load_factor, max_displacement):
    """The step from ``(uf, lam)`` to exactly the stop that the step to ``(uf1, lam1)``
    passed — ``max_load_factor`` by a load step, ``max_displacement`` (of the monitored DOF)
    by a displacement step — as :meth:`_Stepper.step` returns it, or None (no stop passed,
    or the landing step does not converge)."""
    if max_load_factor is not None and lam < max_load_factor < lam1:
        return st.step(uf, lam, fac, max_load_factor - lam, None, None, "load")
    if max_displacement is not None and st.c >= 0 and abs(uf[st.c]) < max_displacement \
            < abs(uf1[st.c]):
        target = float(np.sign(uf1[st.c])) * max_displacement
        with st.moving(float(np.sign(target - uf[st.c]))):
            return st.step(uf, lam, fac, abs(target - uf[st.c]), None, None, "displacement")
    return None


def _failed_at(out: PathResult, s, lam: float, unit: float) -> list[str]:
    """Ids of the members whose failure events the path met at the load factor ``lam`` (to
    1e-5 of it, or of ``unit``: an event is located to the event tolerance of the member's
    force, and the path may have crept on by a step of round-off size since)."""
    near = 1e-5 * max(abs(lam), unit)
    return [s.member_ids[e.member] for e in out.events
            if e.kind in _CAUSE and e.member is not None and abs(e.load_factor - lam) <= near]


def _event_ahead(st, m, uf, lam, fac, res, ds, neg, max_cuts, tol):
    """Load control: the step that a load step ``ds`` from the converged state ``(uf, lam)``
    could not take, taken under displacement control of the monitored DOF instead.

    A load step that crosses a member event after which the structure is much softer (the
    last bars of a plastic mechanism reaching their yield force) converges only far beyond
    the event, or not at all, so the load step is cut without end short of it.  The event
    is an equilibrium state at a larger load factor all the same: a displacement step of the
    size the load step predicts for the monitored DOF crosses it, and
    :func:`_locate_failure` puts the first failing member on its threshold.  Without an
    event in it, the displacement step itself is taken when it raises the load factor (just
    past an event, the tangent of the state at the threshold still has the member's elastic
    stiffness; the step's own tangent has the softer one the next load steps need).

    Returns the :meth:`_Stepper.step` tuple of the state reached, or None when the load
    factor would not grow or a critical point (a limit point, where load control ends)
    lies in the step.
    """
    if st.c < 0:
        return None
    try:
        ut = fac.solve(st.f)
    except SingularMatrixError:
        return None
    if not abs(ut[st.c]) > 1e-12 * np.abs(ut).max():
        return None
    mg0 = m.margins(res)
    # (the way a growing load moves the monitored DOF)
    with st.moving(float(np.sign(ut[st.c]))):
        new, _, _ = _attempt(st, uf, lam, fac, abs(ds * ut[st.c]), None, None, "displacement",
                             None, neg, max_cuts, False)
        if new is None:
            return None
        uf1, lam1, res1, its, fac1, dsu = new
        if ((m.margins(res1) > tol) & (mg0 <= tol)).any():
            uf1, lam1, res1, fac1 = _locate_failure(st, m, uf, lam, fac, dsu, None, None,
                                                    "displacement", mg0, uf1, lam1, res1,
                                                    fac1, tol)
    if not lam1 > lam:
        return None
    try:
        fac1 = fac1 if fac1 is not None else _tangent_factor(st.eval(uf1)[2])
    except SingularMatrixError:
        return None
    if _crossed(neg, _inertia(fac1)):
        return None
    return uf1, float(lam1), res1, its, fac1


def _locate_failure(st, m, uf, lam, fac, dss, direction, du_prev, mode, mg0, uf1, lam1, res1,
                    fac1, tol):
    """Cut the step so that the first member to fail sits on its threshold.

    Root of ``g(θ) = max margin`` over the members that crossed within the step, θ the
    fraction of the step: secant steps through the last two iterates, kept inside the
    bracket (else an Illinois regula-falsi step); the state returned has ``|g| ≤ tol``.
    """
    mg1 = m.margins(res1)
    cand = (mg1 > tol) & (mg0 <= tol)
    g = lambda mg: float(np.max(mg[cand]))
    a, ga = 0.0, g(mg0)
    b, gb = 1.0, g(mg1)
    best = (uf1, lam1, res1, fac1)
    side = 0
    hist = [(a, ga), (b, gb)]
    near = fac1                      # latest factor near the event, for the corrections
    for _ in range(60):
        (c0, g0), (c1, g1) = hist[-2], hist[-1]
        c = c1 - g1 * (c1 - c0) / (g1 - g0) if g1 != g0 else 0.5 * (a + b)
        if len(hist) == 2:
            # first guess: the earliest of the members' own linear crossing estimates (the
            # maximum margin at θ = 1 is inflated by members that cross later in the step)
            with np.errstate(divide="ignore", invalid="ignore"):
                th = -mg0[cand] / (mg1[cand] - mg0[cand])
            c = float(np.nanmin(th)) if th.size else 0.5
        if not a < c < b:
            c = b - gb * (b - a) / (gb - ga) if gb != ga else 0.5 * (a + b)
        if not a < c < b:
            c = 0.5 * (a + b)
        new = st.step(uf, lam, fac, dss * c, direction, du_prev, mode, fac_iter=near,
                      refactor_ratio=0.9)
        if new is None:
            c = 0.5 * (a + b)
            new = st.step(uf, lam, fac, dss * c, direction, du_prev, mode)
            if new is None:
                break
        u2, l2, r2, _, f2 = new
        near = f2 if f2 is not None else near
        gc = g(m.margins(r2))
        hist.append((c, gc))
        log.debug("locate: theta %.12g margin %.3e", c, gc)
        if abs(gc) <= tol:
            return u2, l2, r2, f2
        if gc > 0:
            b, gb, best = c, gc, (u2, l2, r2, f2)
            if side == 1:
                ga *= 0.5
            side = 1
        else:
            a, ga = c, gc
            if side == -1:
                gb *= 0.5
            side = -1
        if b - a < 1e-14:
            break
    return best


def _critical_point(st, m, out, uf, lam, fac, dss, direction, du_prev, mode, neg0, neg1,
                    record, branch, may_reject=False):
    """Event location: bisect the step for the inertia change, record a limit point or a
    bifurcation.

    A critical point is reported only where the tangent is singular: the eigenvalue nearest
    zero at the located state is checked against the unloaded tangent's
    (:data:`_SINGULAR_RATIO`).  When it is not (the inertia changed across a jump of the
    corrector, not at a critical point) and ``may_reject``, nothing is recorded and
    ``"reject"`` returned, so that the step is retried smaller."""
    lo, hi = 0.0, 1.0
    state_hi = None
    for _ in range(40):
        if hi - lo < 1e-7:
            break
        mid = 0.5 * (lo + hi)
        new = st.step(uf, lam, fac, dss * mid, direction, du_prev, mode)
        if new is None:
            break
        try:
            fmid = new[4] if new[4] is not None else factor(st.eval(new[0])[2], "symmetric")
        except SingularMatrixError:
            state_hi = new
            break
        nmid = _inertia(fmid)
        if nmid is None:                 # unknown inertia: the bracket cannot be narrowed
            break
        if nmid == neg0:
            lo = mid
        else:
            hi, state_hi = mid, new
    if state_hi is None:
        new = st.step(uf, lam, fac, dss * hi, direction, du_prev, mode)
        state_hi = new
    if state_hi is None:
        return None
    u2, l2, r2 = state_hi[:3]
    kind, detail, phi, w = _classify(st, u2, neg0, neg1)
    if may_reject and abs(w) > _SINGULAR_RATIO * st.unloaded_eigenvalue():
        return "reject"
    p = record(u2, l2, r2, neg1)
    ev = Event(kind, l2, point=p, detail=detail)
    out.events.append(ev)
    if kind == "bifurcation" and branch:
        ev.detail += "; branch taken along the critical eigenvector"
        return u2, l2, r2, phi
    return None


def _classify(st, uf, neg0, neg1):
    """Limit point (the critical mode does work on the load) or bifurcation (it does not)."""
    w, phi = nearest_zero_mode(st.scaled_tangent(st.eval(uf)[2]))
    # φ of the scaled tangent (rotations as lengths) back to DOFs: ‖w φ‖ = 1
    phi = phi / st.w
    ratio = abs(phi @ st.f) / (st.rnorm(st.f) * st.dnorm(phi))
    kind = "limit_point" if ratio > _BIFURCATION_RATIO else "bifurcation"
    return kind, (f"negative eigenvalues {neg0} -> {neg1}; |phi.f|/(|phi||f|) = "
                  f"{ratio:.2e}"), phi, w


def _apply_failures(st, m, out, hit, mg, res, lam, point):
    """Record the failure events reached at this state and remove the failed members."""
    s = m.structure
    removed = []
    cause_idx, el_idx = np.nonzero(hit)
    laws = m.t_laws
    for c, e in zip(cause_idx, el_idx):
        mem = int(m.t_member[e])
        N = float(res["t_force"][e])
        if c == 0:
            thr = -laws.critical_load[e]
            remove = laws.buckling[e] == 3
        elif c == 1:
            thr = np.sign(res["t_buckling_force"][e]) * laws.yield_force[e]
            remove = laws.yield_mode[e] == 2
        else:
            thr = laws.fracture_strain[e]
            remove = True
        if c == 2:
            N_show = float(res["t_strain"][e])
        else:
            N_show = float(res["t_trial"][e]) if remove else N
        out.events.append(Event(_CAUSE[c], lam, mem, point, N_show, float(thr),
                                f"member {s.member_ids[mem]}"
                                + (" removed" if remove else " follows its law")))
        if remove:
            removed.append(mem)
        m.silenced[c, e] = True          # each kind of event is reported once per member
    for mem in removed:
        m.alive[mem] = False
    return removed


def _reequilibrate(st, m, out, uf, lam, handover, record):
    """After members were removed: rank check, equilibrium at the same λ, cascades."""
    s = m.structure
    for _ in range(len(m.alive) + 1):
        if not m.alive.any() and _mech_free(m).any():
            # (springs on every loaded coordinate still carry the load without members)
            return None, None, None, _collapse(st, m, out, uf, lam)
        conn = s.connectivity[m.alive]
        x = m.positions(st.full(uf))[: s.n_nodes]
        if not s.is_beam.any():
            nm, rank = mechanism_count(x, conn, _mech_free(m))
            if nm > 0:
                out.events.append(Event("mechanism", lam, None, len(out.path) - 1,
                                        detail=f"{nm} mechanism(s), rank {rank} "
                                               f"after {int((~m.alive).sum())} member(s) "
                                               "failed"))
                if not handover:
                    return None, None, None, (f"the structure became a mechanism at load "
                                              f"factor {lam:.6g}")
                form = _handover(st, m, out, x, conn, lam)
                if form is None:
                    return None, None, None, ("the structure became a mechanism at load factor "
                                              f"{lam:.6g}; " + out.mechanism.reason)
                # the form overloads members whose laws remove them: they fail there, and
                # what is left moves on (or collapses)
                uf = form
                continue
        new = _release(st, uf, lam)
        if new is None:
            last = out.events[-1].member
            who = s.member_ids[last] if last is not None else "?"
            reason = (f"path cannot be continued at load factor {lam:.6g}: no equilibrium "
                      f"after the failure of member {who} (the structure snaps: a dynamic "
                      "collapse that a static analysis cannot follow)")
            out.events.append(Event("end", lam, detail=reason))
            return None, None, None, reason
        uf, res, interrupted = new
        m.commit(res)
        mg = m.margins(res)
        over = mg >= (-1e-6 if interrupted else 1e-9)
        if not over.any():
            fac = factor(st.eval(uf)[2], "symmetric")
            record(uf, lam, res, _inertia(fac))
            return uf, res, fac, ""
        # cascade: the most overloaded member fails now, at the same load factor, with every
        # member as overloaded to the event tolerance (symmetric members reach their limits
        # together)
        worst = np.max(np.where(over, mg, -np.inf))
        hit = over & (mg >= worst - 1e-6)
        point = record(uf, lam, res, None)
        _apply_failures(st, m, out, hit, mg, res, lam, point)
        for ev in out.events[-int(hit.sum()):]:
            ev.detail += " (redistribution at the same load factor)"
    return None, None, None, "too many cascading failures"


def _collapse(st: _Stepper, m: NonlinearModel, out: PathResult, uf: np.ndarray,
              lam: float) -> str:
    """End the path where every member has failed: the structure has collapsed.

    No member is left to carry the load, so there is neither an equilibrium to re-establish
    nor a mechanism of bars to move.  The collapsed state closes the path — the displacements
    at the last failure, every member failed and carrying no force, stage ``"mechanism"`` (no
    stiffness is left) — so that the path's last point, like the VTK series, shows the
    failures; an ``"end"`` event gives the reason.

    Returns
    -------
    str
        The termination reason.
    """
    s = m.structure
    reason = (f"every member has failed at load factor {lam:.6g}: the structure has "
              "collapsed (no member is left to carry the load)")
    out.path.append(PathPoint(lam, st.full(uf), np.zeros(s.n_members), m.alive.copy(), None,
                              "mechanism"))
    out.events.append(Event("end", lam, None, len(out.path) - 1, detail=reason))
    return reason


def _release(st, uf0, lam, event_tolerance=1e-6, min_increment=1.0 / 4096):
    """Quasi-static release of the forces of removed members at constant λ.

    Just after a removal the structure is out of balance by ``r0 = f_int(u0) − λf`` (minus
    the removed members' forces).  The equilibrium of the reduced structure is followed from
    ``f_int(u) − λf = τ r0`` at τ = 1 (satisfied by ``u0``) to τ = 0 in load-controlled
    increments, so that the state found is the one the structure reaches by a slow release —
    not an arbitrary remote equilibrium that Newton from ``u0`` might jump to.  When another
    member reaches its failure limit during the release, the release stops there (located by
    bisection in τ to ``event_tolerance``) so that the member fails at its limit.

    Returns
    -------
    tuple or None
        ``(uf, res, interrupted)``, or ``None`` when no equilibrium exists for some τ (the
        structure snaps through: a dynamic collapse).
    """
    m = st.m
    res, fint, _ = st.eval(uf0, tangent=False)
    r0 = fint - lam * st.f - st.fd
    scale = st.fn * max(abs(lam), st.lam_unit)
    if st.rnorm(r0) <= st.tol * scale:
        return uf0, m.evaluate(st.full(uf0)), False
    mg_start = m.margins(res)

    modified = len(uf0) > st.full_newton_size
    held = {"fac": None}            # modified Newton on large models: factor kept across solves

    def solve(u, target):
        rprev = np.inf
        for _ in range(2 * st.max_iter if modified else st.max_iter):
            r, fi, K = st.eval(u, tangent=not modified)
            R = fi - lam * st.f - st.fd - target * r0
            rn = st.rnorm(R)
            if rn <= st.tol * scale:
                return u, r
            try:
                if not modified or held["fac"] is None or rn > 0.5 * rprev:
                    held["fac"] = factor(K if K is not None else st.eval(u)[2], "symmetric")
                u = st.add(u, -held["fac"].solve(R, refine=False))
            except SingularMatrixError:
                return None
            rprev = rn
            if not np.all(np.isfinite(u)):
                return None
        return None

    tau, dtau, uf = 1.0, 0.25, uf0
    while tau > 0.0:
        target = max(tau - dtau, 0.0)
        new = solve(uf.copy(), target)
        if new is None:
            dtau *= 0.5
            if dtau < min_increment:
                return None
            continue
        u, r = new
        mg = m.margins(r)
        crossed = (mg > event_tolerance) & (mg_start <= event_tolerance)
        if crossed.any():
            lo, hi, u_lo = tau, target, uf          # τ decreases from lo to hi
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                new = solve(u_lo.copy(), mid)
                if new is None:
                    break
                um, rm = new
                mgm = m.margins(rm)
                cm = (mgm > event_tolerance) & (mg_start <= event_tolerance)
                if cm.any():
                    hi, u, r = mid, um, rm
                else:
                    lo, u_lo = mid, um
                    if np.any((mgm >= -event_tolerance) & (mg_start < -event_tolerance)):
                        return um, rm, True
            return u, r, True
        uf, tau, res = u, target, r
        dtau = min(2.0 * dtau, 0.25)
    return uf, res, False


def _handover(st, m, out, x, conn, lam) -> np.ndarray | None:
    """Finite-mechanism motion of the remaining bars to the equilibrium form.

    The bar forces of the form are checked against the members' failure laws: a form that
    needs a member beyond its limit is no resting state.  Where every such member's law
    removes it, the members fail at the form (events, as in a redistribution) and the free
    displacements of the form are returned, for what is left to be analysed on from there;
    where a law keeps the member at its limit (``cap``), the motion ends there, saying so.
    Returns None otherwise (the form is the end of the path)."""
    s = m.structure
    load = lam * s.loads[:, : s.dim] + m.dead[: s.n_nodes * s.dim].reshape(s.n_nodes, s.dim)
    mot = equilibrium_form(x, conn, _mech_free(m), load)
    out.mechanism = mot
    X = s.coords
    forces_alive = m.alive.copy()
    for xp in mot.positions[1:]:
        u = np.zeros(m.ndof)
        u[: s.n_nodes * s.dim] = (xp - X).ravel()
        # the remaining bars' forces are known at the equilibrium form only: between it and
        # the hand-over the bars move as a mechanism, not in equilibrium (NaN, "no value");
        # removed members carry nothing
        forces = np.zeros(s.n_members)
        forces[forces_alive] = np.nan
        if mot.tensions is not None and xp is mot.positions[-1]:
            forces[forces_alive] = mot.tensions
        out.path.append(PathPoint(lam, u, forces, forces_alive.copy(), None, "mechanism"))
    over = _form_overloads(m, mot) if mot.converged and mot.tensions is not None else None
    if over is not None:
        hit, mg, res = over
        who = ", ".join(s.member_ids[int(m.t_member[e])] for e in np.flatnonzero(hit.any(0)))
        laws = m.t_laws
        removes = np.stack([laws.buckling == 3, laws.yield_mode == 2,
                            np.ones_like(laws.buckling, dtype=bool)])
        if np.all(removes[hit]):
            mot.converged, mot.stable = False, False
            mot.reason = (f"the equilibrium form needs member(s) {who} beyond their limits: "
                          "they fail there")
            out.events.append(Event("mechanism", lam, None, len(out.path) - 1,
                                    detail=mot.reason))
            _apply_failures(st, m, out, hit, mg, res, lam, len(out.path) - 1)
            for ev in out.events[-int(hit.sum()):]:
                ev.detail += " (at the equilibrium form of the mechanism)"
            u = np.zeros(m.ndof)
            u[: s.n_nodes * s.dim] = (mot.positions[-1] - X).ravel()
            return u[st.free]
        mot.converged, mot.stable = False, False
        mot.reason = (f"no equilibrium form within the members' limits: the form found needs "
                      f"member(s) {who} beyond the limits at which their laws hold them")
    out.events.append(Event("equilibrium_form" if mot.converged else "end", lam, None,
                            len(out.path) - 1, detail=mot.reason))
    return None


def _form_overloads(m: NonlinearModel, mot) -> tuple | None:
    """The failure events that the bar forces of a mechanism's equilibrium form reach:
    ``(hit, margins, res)`` as :func:`_apply_failures` takes them (the bars are rigid there:
    no strain, so no fracture), or None when every force is within its law."""
    N = np.zeros(m.structure.n_members)
    N[m.alive] = mot.tensions
    Ne = N[m.t_member]
    mg = failure_margins(m.t_laws, Ne, Ne, np.zeros_like(Ne))
    mg[:, ~m.alive[m.t_member]] = -np.inf
    hit = mg > 1e-6
    if not hit.any():
        return None
    return hit, mg, {"t_force": Ne, "t_buckling_force": Ne, "t_trial": Ne,
                     "t_strain": np.zeros_like(Ne)}
