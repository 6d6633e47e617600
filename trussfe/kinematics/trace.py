# SPDX-License-Identifier: MIT
"""Continuation of a finite mechanism through bifurcations and limit points (Hortobágyi 1999).

:func:`trace_mechanism` strings single steps of :mod:`trussfe.kinematics.mechanism` (the
exact compatibility error, the corrector, the tangent of ``[B; cᵀ]``, the test function) into
a motion.  One step reads like the paper's procedure (sections 3–6):

1. **Set-up** (:func:`_set_up`, once): free coordinates, drives, the prescribed increment S,
   the bar lengths to keep, the step bounds and, for an over-constrained assembly, a set of
   independent rows of B for the determinant test.
2. **State at the step's start** (:meth:`_Trace.inspect_state`): B, its rank and null space
   (dense path); a rigid or locked assembly is refused, a mechanism unfolded into fewer degrees
   of freedom continues with one drive (section 6).
3. **Predictor** (eq. 4), one of three:

   * several drives (section 6): the prescribed increments in the null space, with the
     second-order unfolding prediction at a folded state
     (:meth:`_Trace.predict_prescribed`);
   * a rank drop at the step's start (section 4): the branch is chosen by pivoting the null
     space (:meth:`_Trace.predict_at_branch_point`);
   * a regular point (section 5): the oriented tangent of ``[B; cᵀ]`` and a step h in the
     coordinate of largest velocity, so limit points are passed
     (:meth:`_Trace.predict_along_tangent`).

4. **Bifurcation detection** on a regular path: a sign change of ``det [B; τᵀ]`` between two
   states (:meth:`_Trace.detect_sign_change`), optionally followed by **branch switching**
   (:meth:`_Trace.jump_to_branch`); a sharp minimum of the test function without a sign change
   is **located** by re-tracing the interval in sub-steps (:meth:`_Trace.locate_dip`).
5. **Corrector** (eq. 5–7) with **step-size control** (:meth:`_Trace.correct`): the step is
   halved when the corrector fails, down to a minimum step; the next step is at most twice the
   last (:meth:`_Trace.next_step_size`).
6. **Acceptance** (:meth:`_Trace.accept`): the new state, its tangent, and a limit point where
   the drive coordinate turns back.
7. **Result assembly** (:meth:`_Trace.result`).

Choices made here:

* The independent coordinate after the first step is the one with the largest velocity
  (section 5), so a node that reaches a limit point and turns back does not stall the motion.
* Bifurcations are found from the sign of ``det [B; τᵀ]`` (τ the oriented tangent), never from a
  determinant's value, which under- or overflows for a hundred coordinates; and from a rank drop
  of B (nullity above the number of drives) at a step's start.  They are not located to machine
  precision (Newton would then jump to another branch).
* Step halving stops at a minimum step ``max(|S|/1024, 10·sqrt(tolerance)·L)``: below it an
  infinitesimal (higher-order) mechanism would satisfy the tolerance and be crept along.
"""
from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Callable, NamedTuple

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp

from ..budget import count_text, require
from ..errors import AnalysisError, InputError, TrussfeError
from ..mechanics.geometry import member_lengths
from .compatibility import anchored_bar_count, compatibility_matrix
from .mechanism import (DENSE_LIMIT, DIVERGENCE_MESSAGE, StepResult, _augmented_tangent,
                        _check_double_crossing, _chord_corrector, _dense_null,
                        _lu_smallest_singular, _switch_branch, _test_function,
                        hortobagyi_step)

log = logging.getLogger(__name__)


@dataclass
class TraceResult:
    """A traced finite-mechanism path.

    Attributes
    ----------
    coords : ndarray, shape (steps + 1, n, dim)
        Joint positions at the start state and after every step.
    parameter : ndarray, shape (steps + 1,)
        Path parameter: accumulated independent-coordinate increments, m.
    rank : ndarray of int, shape (steps + 1,)
        ρ(B) at each state.
    iterations : ndarray of int, shape (steps,)
        Corrector iterations of each step.
    residual : ndarray, shape (steps + 1,)
        Largest bar-length misfit at each state, m.
    events : list of dict
        ``{"step": k, "kind": "bifurcation" | "limit_point", ...}``.
    independent : list of int
        Free-coordinate position of the independent coordinate of each step.
    """

    coords: np.ndarray
    parameter: np.ndarray
    rank: np.ndarray
    iterations: np.ndarray
    residual: np.ndarray
    events: list
    independent: list


# --------------------------------------------------------------------------- set-up
@dataclass(frozen=True)
class _Setup:
    """What stays fixed during a trace (the drives may still be reduced, see
    :meth:`_Trace.inspect_state`).

    Attributes
    ----------
    x0 : ndarray, shape (n, dim)
        Compatible start state.
    conn : ndarray of int, shape (b, 2)
    free : ndarray of bool, shape (n, dim)
    fidx : ndarray of int, shape (f,)
        Flat indices of the free coordinates (the columns of B).
    L : ndarray, shape (b,)
        Bar lengths to keep.
    Lmax : float
    names : list of str
        Coordinate names for events and messages.
    drives : list of int
        Flat indices of the prescribed coordinates.
    dcols : ndarray of int
        Their columns among the free coordinates.
    S : ndarray
        Prescribed increment of each drive per step, m.
    rtol : float
        Relative singular-value tolerance of the per-step rank.
    h_full, h_min : float
        Largest and smallest step in the independent coordinate, m (step-size control).
    dense : bool
        At most :data:`~trussfe.kinematics.mechanism.DENSE_LIMIT` free coordinates: rank and
        null space by dense SVD each step.
    square : bool
        ``b + drives = f``: ``[B; cᵀ]`` is square with the drives appended.
    rows : ndarray of int
        Independent rows of B for the determinant test (all rows unless over-constrained).
    anchored : int
        Bars whose two joints are fixed in every direction: zero rows of B that no motion
        changes (they hold a state of self-stress of their own).
    """

    x0: np.ndarray
    conn: np.ndarray
    free: np.ndarray
    fidx: np.ndarray
    L: np.ndarray
    Lmax: float
    names: list
    drives: list
    dcols: np.ndarray
    S: np.ndarray
    rtol: float
    h_full: float
    h_min: float
    dense: bool
    square: bool
    rows: np.ndarray
    anchored: int = 0

    @property
    def f(self) -> int:
        """Number of free coordinates."""
        return int(self.fidx.size)


def _set_up(coords, connectivity, free, drives, step, steps, tolerance, rank_tolerance,
            names) -> _Setup:
    """Check the input and derive the quantities that stay fixed along the trace.

    The minimum step ``max(|S|/1024, 10·sqrt(tolerance)·L)`` bounds the step halving: below
    it an infinitesimal mechanism would close within the bar-length tolerance (eq. 7).  For an
    over-constrained assembly (self-stress states) independent rows of B are chosen by
    column-pivoted QR of Bᵀ, so that ``[B; cᵀ]`` stays square for the determinant test.

    Raises
    ------
    InputError
        A drive that does not exist or is supported, a zero or non-finite step, ``steps < 1``.
    AnalysisError
        An over-constrained assembly beyond the dense limit.
    """
    x = np.array(coords, dtype=float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    free = np.asarray(free, dtype=bool).reshape(x.shape)
    n, dim = x.shape
    fidx = np.flatnonzero(free.ravel())
    f = fidx.size
    col_of = -np.ones(n * dim, dtype=np.int64)
    col_of[fidx] = np.arange(f)
    drives = [int(k) for k in np.atleast_1d(drives)]
    nd = len(drives)
    names = names or [f"{k // dim}:{'xyz'[k % dim]}" for k in range(n * dim)]
    for k in drives:
        if not 0 <= k < n * dim:
            raise InputError("drive", f"coordinate {k} does not exist")
        if col_of[k] < 0:
            raise InputError("drive", f"'{names[k]}' is a supported (fixed) coordinate; drive "
                                      "a free coordinate of a moving joint")
    dcols = col_of[drives]
    S = np.broadcast_to(np.asarray(step, dtype=float), (nd,)).astype(float)
    if not np.all(np.isfinite(S)) or np.any(S == 0):
        raise InputError("step", f"must be finite and non-zero, got {step}")
    if steps < 1:
        raise InputError("steps", f"must be at least 1, got {steps}")
    L = member_lengths(x, conn)
    Lmax = float(L.max())
    rtol = max(1e-8, 100 * tolerance) if rank_tolerance is None else float(rank_tolerance)
    h_full = float(np.max(np.abs(S)))
    h_min = max(h_full / 1024.0, 10.0 * np.sqrt(tolerance) * Lmax)
    dense = f <= DENSE_LIMIT
    square = conn.shape[0] + nd == f

    # Independent rows for the determinant test on over-constrained assemblies.
    rows = np.arange(conn.shape[0])
    if not square and nd == 1:
        if not dense:
            raise AnalysisError("trace", f"an assembly with self-stress states and {f} "
                                         f"coordinates is beyond the dense limit ({DENSE_LIMIT})")
        Bt = compatibility_matrix(x, conn, free).toarray().T
        _, rr, piv = sla.qr(Bt, mode="economic", pivoting=True)
        dg = np.abs(np.diag(rr))
        rows = np.sort(piv[: int(np.sum(dg > rtol * max(dg.max(), 1e-300)))])
    anchored = anchored_bar_count(conn, free)
    return _Setup(x0=x, conn=conn, free=free, fidx=fidx, L=L, Lmax=Lmax, names=names,
                  drives=drives, dcols=dcols, S=S, rtol=rtol, h_full=h_full, h_min=h_min,
                  dense=dense, square=square, rows=rows, anchored=anchored)


class _StartState(NamedTuple):
    """B at a step's start and, on the dense path, its rank and null space."""

    B: sp.csr_matrix
    rank: int | None
    N: np.ndarray | None
    nullity: int | None


# --------------------------------------------------------------------------- the trace
class _Trace:
    """The state of a trace between steps and the named steps of one continuation step.

    Parameters
    ----------
    setup : _Setup
    branch, tolerance, max_iterations, newton
        As in :func:`trace_mechanism`.

    Notes
    -----
    The path records (``path``, ``param``, ``ranks``, ``iters``, ``resid``, ``indeps``,
    ``events``) grow by one entry per accepted state; a branch switch adds the approximate
    bifurcation point as a state of its own.  ``prev_tau`` is the unit tangent of the last step
    (None before the first), ``prev_sign`` the sign of ``det [B; τᵀ]`` at the last state (0: no
    record), ``h`` the step in the independent coordinate.
    """

    def __init__(self, setup: _Setup, branch: int, tolerance: float, max_iterations: int,
                 newton: bool) -> None:
        self.su = setup
        self.branch = branch
        self.tolerance = tolerance
        self.max_iterations = max_iterations
        self.newton = newton
        # drives: reduced to one when the mechanism unfolds into fewer degrees of freedom
        self.drives, self.dcols, self.S = setup.drives, setup.dcols, setup.S
        self.nd = len(setup.drives)
        self.x = setup.x0
        self.path = [self.x.copy()]
        self.phi: dict[int, float] = {}                    # state index → test function
        self.param = [0.0]
        self.ranks: list[int] = []
        self.iters: list[int] = []
        self.resid = [0.0]
        self.indeps: list[int] = []
        self.events: list[dict] = []
        self.prev_tau: np.ndarray | None = None
        self.switched = False
        self.prev_sign = 0
        self.prev_drive_dir = None
        self.s_acc = 0.0
        self.h = setup.h_full

    def expand(self, dv: np.ndarray) -> np.ndarray:
        """Free-coordinate increments as an ``(n, dim)`` array (zeros at the supports)."""
        n, dim = self.x.shape
        out = np.zeros(n * dim)
        out[self.su.fidx] = dv
        return out.reshape(n, dim)

    def nullity_after(self, pred: np.ndarray) -> int:
        """Nullity of B a predicted step ``pred`` (free-coordinate increments) from the current
        state (dense): the freedoms that a step along the path keeps."""
        su = self.su
        B = compatibility_matrix(self.x + self.expand(pred), su.conn, su.free)
        return su.f - _dense_null(B, su.rtol)[0]

    # ----------------------------------------------------------------------- one step
    def step(self, k: int) -> None:
        """Advance the trace by step ``k`` (1-based): predict, detect, correct, accept."""
        item = f"trace: step {k}"
        start = self.inspect_state(k, item)
        chord = None
        if self.nd > 1:
            pred, indep, at_bifurcation = self.predict_prescribed(k, item, start)
        elif start.nullity is not None and start.nullity > 1:
            pred, indep = self.predict_at_branch_point(k, start)
            at_bifurcation = True
        else:
            pred, indep, chord = self.predict_along_tangent(k, item, start)
            at_bifurcation = False
        res = self.correct(item, pred, indep, chord)
        self.accept(k, res, indep, at_bifurcation)

    def inspect_state(self, k: int, item: str) -> _StartState:
        """B at the current state; its rank and null space on the dense path (ρ(B), section 3).

        Refuses a rigid assembly (nullity 0), more drives than degrees of freedom at the
        start, and fewer drives than degrees of freedom at a regular state: where B has full
        row rank (bars between fixed joints aside) the compatible states near x form a smooth
        manifold of dimension μ·j − ρ(B) (implicit-function theorem), so a nullity above the
        number of drives is a mechanism with more freedoms (or rigid-body motions the
        supports leave free), not a bifurcation point (section 4 needs a state of
        self-stress there).  When the motion has unfolded into a mechanism with fewer degrees of freedom
        than drives (section 6: after the prescribed increments a one-degree-of-freedom finite
        mechanism), the trace continues along the tangent with the drive of largest increment,
        which reports limit points.
        """
        su = self.su
        f = su.f
        B = compatibility_matrix(self.x, su.conn, su.free)
        rank = None
        N = None
        if su.dense:
            rank, N, _ = _dense_null(B, su.rtol)
        self.ranks.append(rank if rank is not None else f - self.nd)
        nullity = None if rank is None else f - rank
        if nullity == 0:
            raise AnalysisError(item if k > 1 else "trace",
                                "the assembly is rigid (rank of the compatibility matrix = "
                                f"{rank} = number of free coordinates): there is no mechanism "
                                "to trace" if k == 1 else "the assembly locks: no mechanism "
                                "left to follow")
        if nullity is not None and nullity < self.nd:
            if k == 1:
                raise InputError("drive", f"the assembly has {nullity} degree(s) of freedom "
                                          f"here but {self.nd} drives were given; prescribe at "
                                          f"most {nullity}")
            keep = int(np.argmax(np.abs(self.S)))
            self.drives, self.dcols, self.S = ([self.drives[keep]], self.dcols[[keep]],
                                               self.S[[keep]])
            self.nd = 1
            self.prev_drive_dir = None
        if nullity is not None and nullity > self.nd and rank == B.shape[0] - su.anchored:
            raise InputError("drive", f"the assembly has {nullity} degrees of freedom here (the "
                                      "compatibility matrix has full row rank: a regular state, "
                                      f"not a bifurcation point) but {self.nd} drive(s) were "
                                      f"given; prescribe {nullity} drives, or add supports to "
                                      "fix the joints and rigid-body motions that should not "
                                      "move")
        return _StartState(B, rank, N, nullity)

    # ----------------------------------------------------------------------- predictors
    def predict_prescribed(self, k: int, item: str, start: _StartState):
        """Predictor for several drives (Hortobágyi section 6, eq. 4 with d2 prescribed).

        The prediction is the null-space vector with the prescribed drive increments (the
        minimum-norm combination when the null space is larger than the number of drives).
        At a folded state (self-stress, fewer finite freedoms than drives, judged from B at the
        state *plus* the prescribed increments as in section 4) the coordinate of the largest
        prescribed increment is the independent one, the prescription is moved onto the
        nearest second-order unfolding direction and a second-order prediction starts the
        corrector; with more infinitesimal than finite freedoms only that coordinate is
        independent.

        Returns
        -------
        pred : ndarray, shape (f,)
        indep : ndarray of int
            Independent coordinates of the corrector.
        at_bifurcation : bool
        """
        su = self.su
        conn, names, fidx = su.conn, su.names, su.fidx
        rank, N, nullity = start.rank, start.N, start.nullity
        dcols, S, nd = self.dcols, self.S, self.nd
        if N is None:
            raise AnalysisError("trace", "several drives need the dense path "
                                         f"(at most {DENSE_LIMIT} coordinates)")
        a, *_ = np.linalg.lstsq(N[dcols], S, rcond=None)
        pred = N @ a
        if not np.allclose(pred[dcols], S, rtol=1e-6, atol=1e-12 * su.Lmax):
            raise AnalysisError(item, "the drives are not independent degrees of freedom "
                                      "of the mechanism; choose other drive coordinates")
        finite = nullity
        if nullity <= nd and conn.shape[0] > rank:
            finite = self.nullity_after(pred)
        if finite < nd and conn.shape[0] > rank:
            from .unfolding import project_to_cone, second_order_prediction
            p = int(dcols[int(np.argmax(np.abs(S)))])
            v = project_to_cone(self.x, conn, su.free, pred, p, rtol=su.rtol)
            pred = second_order_prediction(self.x, conn, su.free, v, p)
            indep = np.array([p])
            self.events.append({"step": k - 1, "kind": "bifurcation", "branches": int(nullity),
                                "unfolding": True, "independent": names[fidx[p]]})
            return pred, indep, True
        if nullity > nd and self.nullity_after(pred) <= nd:
            # more freedoms here than a step along the path keeps: a bifurcation.  (Where the
            # excess persists along the path — an infinitesimal mechanism elsewhere in the
            # assembly, a straight chain of two bars beside a four-bar — the state is a
            # regular one, and the least-squares corrector leaves that part where it is.)
            indep = dcols[[int(np.argmax(np.abs(S)))]]
            self.events.append({"step": k - 1, "kind": "bifurcation", "branches": int(nullity),
                                "independent": names[fidx[indep[0]]]})
            return pred, indep, True
        return pred, dcols, False

    def predict_at_branch_point(self, k: int, start: _StartState):
        """Predictor at a bifurcation point met at a step's start (rank drop; section 4).

        The candidate independent coordinates are found by pivoting the null space: the drive
        first, then the coordinates of largest pivot in the rest.  Branch ``branch`` prescribes
        its candidate with the other candidates kept at zero; on the first step the increment
        is S, later h along the tangent oriented like the last one.

        Returns
        -------
        pred : ndarray, shape (f,)
        indep : ndarray of int, shape (1,)
        """
        N, nullity = start.N, start.nullity
        dcols, branch = self.dcols, self.branch
        dv = N[dcols[0]]
        if np.linalg.norm(dv) > 1e-8:
            vh = dv / np.linalg.norm(dv)
            rest = N - np.outer(N @ vh, vh)
            _, _, piv = sla.qr(rest.T, mode="economic", pivoting=True)
            cands = [int(dcols[0])] + [int(c) for c in piv if c != dcols[0]][:nullity - 1]
        else:
            _, _, piv = sla.qr(N.T, mode="economic", pivoting=True)
            cands = [int(c) for c in piv[:nullity]]
        if branch >= len(cands):
            raise InputError("branch", f"the bifurcation at step {k} has {len(cands)} "
                                       f"branches (0..{len(cands) - 1}); got {branch}")
        p = int(cands[branch])
        e = np.zeros(nullity)
        e[branch] = 1.0
        a = np.linalg.solve(N[cands], e)
        tau = N @ a                                        # τ_p = 1, other candidates 0
        if self.prev_tau is None:
            pred = self.S[0] * tau                         # prescribed increment of p is S
        else:
            if tau @ self.prev_tau < 0:
                tau = -tau
            pred = self.h * tau / abs(tau[p])
        su = self.su
        if self.nullity_after(pred) <= self.nd:
            # the extra freedoms are gone a step along the branch: a bifurcation.  (Where
            # they persist — an infinitesimal mechanism elsewhere in the assembly, a straight
            # chain of two bars beside a four-bar — the state is a regular one.)
            self.events.append({"step": k - 1, "kind": "bifurcation",
                                "branches": int(nullity), "branch": int(branch),
                                "independent": su.names[su.fidx[p]]})
        return pred, np.array([p])

    def predict_along_tangent(self, k: int, item: str, start: _StartState):
        """Predictor at a regular point (Hortobágyi eq. 4, section 5), with the bifurcation
        tests of the state.

        The first step prescribes S in the drive coordinate; later steps go h forward along
        the oriented tangent in the coordinate of largest velocity.  A sign change of
        ``det [B; τᵀ]`` since the last state is a bifurcation (and, if asked, the trace jumps
        to the other branch); the test function of the state is recorded and a sharp minimum
        of it is located.

        Returns
        -------
        pred : ndarray, shape (f,)
        indep : ndarray of int, shape (1,)
        chord : tuple or None
            ``(lu, p)`` of ``[B; e_pᵀ]`` for the chord corrector (sparse path).
        """
        tau, sign, phi_lu, chord = self.tangent(item, start)
        switch = None
        if self.prev_tau is None:
            if abs(tau[self.dcols[0]]) <= 1e-8 * np.abs(tau).max():
                raise AnalysisError("drive", f"'{self.su.names[self.drives[0]]}' does not move "
                                             "in the mechanism at the start; choose another "
                                             "drive")
            p = int(self.dcols[0])
            pred = self.S[0] * tau / tau[p]
        else:
            switch = self.detect_sign_change(k, item, sign)
            if switch is not None:
                pred, p = self.jump_to_branch(switch)
                sign = 0
            else:
                p = int(np.argmax(np.abs(tau)))            # largest velocity (section 5)
                if chord is not None:
                    p = chord[1]
                pred = self.h * tau / abs(tau[p])          # forward along the oriented tangent
        self.prev_sign = sign
        if self.prev_tau is not None and switch is None:
            self.locate_dip(tau, phi_lu)
        return pred, np.array([p]), chord

    def tangent(self, item: str, start: _StartState):
        """Oriented tangent τ of the path and the sign of ``det [B; τᵀ]``.

        τ solves the augmented system ``[B; cᵀ] τ = e`` (sparse LU), c the last tangent (the
        signed drive direction on the first step).  Above the dense limit one factorisation of
        ``[B; e_pᵀ]``, p the coordinate of largest velocity of the last step, gives the tangent
        (τ_p = 1), the determinant sign (``det [B; τ̂ᵀ]`` has the sign of
        ``det [B; e_pᵀ]·τ̂_p``), the test function (``[B; e_pᵀ]`` is singular where B loses
        rank, and τ_p is the largest velocity, so not at limit points) and the chord corrector.
        Where the augmented matrix is singular the one-dimensional null space of B serves.

        Returns
        -------
        tau : ndarray, shape (f,)
        sign : int
        phi_lu : float or None
            Test function from the same factorisation (sparse path).
        chord : tuple or None
            ``(lu, p)`` for :func:`~trussfe.kinematics.mechanism._chord_corrector`.
        """
        su = self.su
        f = su.f
        B, N = start.B, start.N
        prev_tau = self.prev_tau
        c = prev_tau if prev_tau is not None else np.sign(self.S[0]) * np.eye(f)[self.dcols[0]]
        Br = B[su.rows] if su.rows.size != B.shape[0] else B
        chord = None
        phi_lu = None
        if not su.dense and su.square and prev_tau is not None and self.nd == 1:
            p0 = int(np.argmax(np.abs(prev_tau)))
            ep = np.zeros(f)
            ep[p0] = 1.0
            tau, sign, lu = _augmented_tangent(Br, ep, return_lu=True)
            if tau is not None:
                if tau @ prev_tau < 0:
                    tau = -tau
                sign *= int(np.sign(tau[p0]))
                phi_lu = sign * _lu_smallest_singular(lu)
                if abs(tau[p0]) >= 0.5 * np.abs(tau).max():
                    chord = (lu, p0)
        elif Br.shape[0] + 1 == f:
            tau, sign = _augmented_tangent(Br, c)
        else:
            tau, sign = None, 0
        if tau is None:
            if N is None or N.shape[1] != 1:
                msg = ("the drive coordinate does not move the mechanism at the start; "
                       "choose another drive" if prev_tau is None else DIVERGENCE_MESSAGE)
                raise AnalysisError(item, msg)
            tau = N[:, 0] * (1.0 if N[:, 0] @ c >= 0 else -1.0)
            sign = self.prev_sign
        return tau, sign, phi_lu, chord

    # ----------------------------------------------------------------------- bifurcations
    def detect_sign_change(self, k: int, item: str, sign: int):
        """Report a bifurcation where ``det [B; τᵀ]`` changed sign since the last state.

        At the first such bifurcation on the dense path, ``branch`` ≥ 1 asks to leave the
        traced path: :func:`~trussfe.kinematics.mechanism._switch_branch` approximates the
        bifurcation point and the other branch's tangent.

        Returns
        -------
        tuple or None
            ``(x_b, prediction, independent)`` of the other branch, or None to keep the path.
        """
        switch = None
        if self.prev_sign and sign and sign != self.prev_sign:
            ev = {"step": k - 1, "kind": "bifurcation",
                  "detected_by": "sign change of det [B; tangent]"}
            if self.branch > 0 and not self.switched and self.su.dense and len(self.path) > 1:
                su = self.su
                switch = _switch_branch(self.path[-2], self.x, su.conn, su.L, su.free,
                                        self.prev_tau, self.h, self.branch, self.tolerance,
                                        self.max_iterations)
                if switch is None:
                    raise AnalysisError(item, "could not leave the traced path at the "
                                              "bifurcation for another branch")
                self.switched = True
                ev["branch"] = int(self.branch)
            self.events.append(ev)
        return switch

    def jump_to_branch(self, switch):
        """Branch switching: record the approximate bifurcation point as a state and continue
        from it along the other branch.

        Returns
        -------
        pred : ndarray, shape (f,)
        p : int
            Independent coordinate of the other branch's first step.
        """
        x_b, pred, p = switch
        su = self.su
        self.path.append(x_b.copy())
        self.s_acc += float(np.max(np.abs((x_b - self.x)[su.free])))
        self.param.append(self.s_acc)
        self.iters.append(0)
        self.resid.append(0.0)
        self.indeps.append(p)
        self.ranks.append(_dense_null(compatibility_matrix(x_b, su.conn, su.free), su.rtol)[0])
        self.x = x_b
        return pred, p

    def locate_dip(self, tau: np.ndarray, phi_lu: float | None) -> None:
        """Record the test function (signed smallest singular value of ``[B; τ̂ᵀ]``) of the
        current state and, at a sharp minimum with no sign change, locate the bifurcations
        inside by re-tracing the interval in sub-steps (two crossed in one step cancel in the
        sign test)."""
        su = self.su
        j = len(self.path) - 1
        self.phi[j] = phi_lu if phi_lu is not None else _test_function(self.x, su.conn, su.free,
                                                                       tau, su.rows)
        _check_double_crossing(self.phi, j, self.path, su.conn, su.L, su.free, su.rows,
                               self.tolerance, self.max_iterations, self.events)

    # ----------------------------------------------------------------------- corrector
    def correct(self, item: str, pred: np.ndarray, indep: np.ndarray, chord) -> StepResult:
        """Close the predicted step (Hortobágyi eq. 5–7), halving it on failure.

        The chord corrector with the step's factorisation is tried first when there is one;
        otherwise, and on a retry, :func:`~trussfe.kinematics.mechanism.hortobagyi_step`.  The
        step is halved down to the minimum step; below it the motion is refused.

        Raises
        ------
        AnalysisError
            No compatible position within the minimum step.
        """
        su = self.su
        while True:
            res = None
            if chord is not None:
                res = _chord_corrector(self.x, su.conn, su.L, su.fidx, pred, chord[0], chord[1],
                                       self.tolerance * su.Lmax, self.max_iterations)
                chord = None                               # a retry uses Newton
            if res is None or not res.converged:
                res = hortobagyi_step(self.x, su.conn, su.L, su.free, indep, pred,
                                      tolerance=self.tolerance,
                                      max_iterations=self.max_iterations, newton=self.newton)
            if res.converged:
                return res
            scale = 0.5
            h_try = float(np.max(np.abs(pred[indep]))) * scale
            if h_try < su.h_min:
                raise AnalysisError(item, f"{DIVERGENCE_MESSAGE} (no compatible position "
                                          f"within a step of {h_try / scale:.3g} m after "
                                          "halving to the minimum step)")
            log.info("%s: corrector did not converge; halving the step to %.3g", item, h_try)
            pred = pred * scale

    def next_step_size(self, d: np.ndarray, indep: np.ndarray) -> None:
        """Step-size control: after a one-drive step the next step is at most twice the
        accepted one and never above the prescribed increment (a halved step grows back)."""
        if self.nd == 1:
            self.h = min(self.su.h_full, 2.0 * float(np.max(np.abs(d[indep]))))

    # ----------------------------------------------------------------------- acceptance
    def accept(self, k: int, res: StepResult, indep: np.ndarray, at_bifurcation: bool) -> None:
        """Take the corrected state: record it, set the next step and the new tangent, and
        report a limit point where the drive coordinate turns back (section 5)."""
        d = res.increments
        self.next_step_size(d, indep)
        self.x = self.x + self.expand(d)
        self.s_acc += float(np.max(np.abs(d[indep])))
        self.path.append(self.x.copy())
        self.param.append(self.s_acc)
        self.iters.append(res.iterations)
        self.resid.append(res.residual)
        self.indeps.append(int(indep[0]))
        norm = float(np.linalg.norm(d))
        self.prev_tau = d / norm
        if self.nd == 1:
            if at_bifurcation:
                self.prev_sign = 0                         # restart the determinant record
            self.detect_limit_point(k, d, norm)

    def detect_limit_point(self, k: int, d: np.ndarray, norm: float) -> None:
        """Report a limit point where the drive coordinate's increment changes sign."""
        dc = self.dcols[0]
        ddir = np.sign(d[dc]) if abs(d[dc]) > 1e-12 * norm else 0.0
        if self.prev_drive_dir and ddir and ddir != self.prev_drive_dir:
            self.events.append({"step": k - 1, "kind": "limit_point",
                                "coordinate": self.su.names[self.drives[0]]})
        if ddir:
            self.prev_drive_dir = ddir

    # ----------------------------------------------------------------------- result
    def result(self) -> TraceResult:
        """Assemble the :class:`TraceResult`, with ρ(B) at the last state."""
        su = self.su
        B = compatibility_matrix(self.x, su.conn, su.free)
        self.ranks.append(_dense_null(B, su.rtol)[0] if su.dense else su.f - self.nd)
        return TraceResult(coords=np.array(self.path), parameter=np.array(self.param),
                           rank=np.array(self.ranks, dtype=int),
                           iterations=np.array(self.iters, dtype=int),
                           residual=np.array(self.resid), events=self.events,
                           independent=self.indeps)


#: Memory per kept state and node of a trace (the coordinates and their JSON record).
BYTES_PER_STATE_NODE = 512


def trace_mechanism(coords: np.ndarray, connectivity: np.ndarray, free: np.ndarray,
                    drives: list[int], step: float | list[float], steps: int, *,
                    branch: int = 0, tolerance: float = 1e-10, max_iterations: int = 30,
                    newton: bool = True, rank_tolerance: float | None = None,
                    names: list[str] | None = None,
                    progress: Callable[[int, int], None] | None = None) -> TraceResult:
    """Follow the finite motion of a mechanism (Hortobágyi sections 3–6).

    Parameters
    ----------
    coords : ndarray, shape (n, dim)
        Compatible start state; its bar lengths are kept.
    connectivity : ndarray of int, shape (b, 2)
    free : ndarray of bool, shape (n, dim)
        Free coordinates.
    drives : list of int
        Flat coordinate indices (``node * dim + axis``) of the prescribed coordinates; one for a
        one-degree-of-freedom mechanism, several for section 6 (as many as degrees of freedom).
    step : float or list of float
        Prescribed increment of each drive coordinate per step, m.  After the first step of a
        one-drive trace the step length is kept in the coordinate of largest velocity
        (section 5), so limit points of the drive coordinate are passed.
    steps : int
        Number of steps.
    branch : int
        At a bifurcation point met at a step's start (rank drop, μ·j − ρ(B) above the number of
        drives), take branch ``branch``: the candidate independent coordinates are found by
        pivoting the null space; branch 0 prescribes the drive coordinate, branch k the k-th
        other candidate, the other candidates kept at zero in the prediction (section 4).
        At the first bifurcation found during the motion (sign change of det [B; τ]; dense
        path), ``branch`` ≥ 1 leaves the path for the other branch (odd: one way along it,
        even: the other way); 0 keeps the path.
    tolerance : float
        Relative bar-length tolerance of the corrector (eq. 7).
    max_iterations : int
    newton : bool
        Refresh B11 each iteration (default) or keep the paper's frozen B11.
    rank_tolerance : float, optional
        Relative singular-value tolerance of the per-step rank; default
        ``max(1e-8, 100·tolerance)`` — never tighter than the bar-length accuracy.
    names : list of str, optional
        Coordinate names ``"node:axis"`` for events and messages.
    progress : callable, optional
        Called as ``progress(step, steps)`` before every step (a progress bar; it may raise
        ``KeyboardInterrupt`` to stop the trace).

    Returns
    -------
    TraceResult

    Raises
    ------
    AnalysisError
        The assembly is rigid (no mechanism to trace), the drive does not move it, or a step
        cannot be closed even after halving to the minimum step (the message says
        "the prescribed increment leaves the motion region, or the assembly is not a finite
        mechanism").

    Notes
    -----
    Each step is :meth:`_Trace.step`: the state at the step's start, a predictor (eq. 4), the
    bifurcation tests, the corrector (eq. 5–7) with step-size control, and acceptance with the
    limit-point test; the module docstring lists them.

    Examples
    --------
    A four-bar linkage (ground 0–3, crank 0–1, coupler 1–2, rocker 2–3) driven by the x
    coordinate of joint 1; every bar keeps its length:

    >>> x = np.array([[0., 0.], [0., 1.], [2., 1.5], [2., 0.]])
    >>> conn = np.array([[0, 1], [1, 2], [2, 3]])
    >>> free = np.array([[0, 0], [1, 1], [1, 1], [0, 0]], bool)
    >>> r = trace_mechanism(x, conn, free, drives=[2], step=0.05, steps=4)
    >>> L0 = member_lengths(x, conn)
    >>> L4 = member_lengths(r.coords[-1], conn)
    >>> bool(np.allclose(L4, L0, rtol=1e-9)), round(float(r.coords[-1][1, 0]), 6)
    (True, 0.2)
    """
    setup = _set_up(coords, connectivity, free, drives, step, steps, tolerance, rank_tolerance,
                    names)
    # every state is kept (coordinates, and the per-state record of the JSON document)
    n = np.shape(coords)[0]
    # (an integer count beyond the largest float needs unbounded memory)
    states = float(steps) if steps < 1e300 else float("inf")
    require(states * (BYTES_PER_STATE_NODE * n + 2048), "--steps",
            f"a trace of {count_text(steps)} states of {n:,} nodes", "trace fewer steps")
    trace = _Trace(setup, branch, tolerance, max_iterations, newton)
    for k in range(1, steps + 1):
        if progress is not None:
            progress(k, steps)
        trace.step(k)
    return trace.result()


def trace_structure(structure, drive: str | list[str], step, steps: int, **kwargs) -> TraceResult:
    """:func:`trace_mechanism` for a :class:`~trussfe.model.Structure`.

    Parameters
    ----------
    drive : str or list of str
        ``"NODE:AXIS"`` (axis x, y or z), one per degree of freedom.
    """
    dim = structure.dim
    drives = []
    for dv in ([drive] if isinstance(drive, str) else list(drive)):
        node, sep, axis = str(dv).rpartition(":")
        if not sep or not node:
            raise InputError("--drive", f"expected NODE:AXIS (e.g. 3:y), got '{dv}'")
        axes = "xyz"[:dim]
        if axis not in axes:
            raise InputError("--drive", f"axis '{axis}' does not exist in a {dim}-D model; "
                                        f"use one of {', '.join(axes)}")
        try:
            i = structure.node_index(node)
        except KeyError:
            raise InputError("--drive", f"node '{node}' is not defined in the model") from None
        if structure.translation_supports[i, axes.index(axis)]:
            raise InputError("--drive", f"node '{node}' is fixed in {axis} by a support; "
                                        "drive a free coordinate of a moving joint")
        drives.append(i * dim + axes.index(axis))
    names = [f"{nid}:{ax}" for nid in structure.node_ids for ax in "xyz"[:dim]]
    try:
        return trace_mechanism(structure.coords, structure.connectivity,
                               ~structure.translation_supports, drives, step, steps,
                               names=names, **kwargs)
    except TrussfeError as err:
        raise _in_model_terms(err, structure.source) from None


#: Items of :func:`trace_mechanism`'s errors that are options of ``trussfe trace`` (and of
#: :func:`trussfe.trace`), spelt as the command line spells them.
_OPTION_ITEMS = {"drive": "--drive", "step": "--step", "steps": "--steps", "branch": "--branch"}


def _in_model_terms(err: TrussfeError, source: str) -> TrussfeError:
    """``err`` of :func:`trace_mechanism` as a user of a model file reads it: a bare option
    item spelt as the option, and the model file named first (its geometry is what the
    drive, the branch or a step could not be applied to).  Memory refusals of an option
    (``--steps``) are the option's alone and are left as they are."""
    if err.item.startswith("--"):
        return err
    item = _OPTION_ITEMS.get(err.item, err.item)
    if item != err.item:
        err = err.with_item(item)
    return err.in_file(source)
