# SPDX-License-Identifier: MIT
"""Top-plane rotations converted to active-member lengths (Lacy section 5.5; docs/actuators.md).

A slew such as Lacy's Slewing Experiment 1 (−10° → +10° about n̂1) prescribes the orientation
of a truss's top plane, not the lengths of its active members.  The lengths q (one per active
member) that realise a tilt θ about an axis a are the root of

.. math::

   r(q) = \\begin{bmatrix} n(q)\\cdot u_1 \\\\ n(q)\\cdot u_2 \\\\ c(q) \\end{bmatrix}
        - \\begin{bmatrix} 0 \\\\ 0 \\\\ c_0 \\end{bmatrix} = 0,

where n(q) is the unit normal of the top plane in the assembly of lengths q (the general
forward-position solver, :func:`trussfe.kinematics.solve_positions`), u_1, u_2 span the plane
normal to the target normal R_a(θ) n̂3 (angles are measured from the base normal n̂3, the
orientation of a bay's top plane at its equilibrium position), and c is the third condition a
pointing (gimbal) motion leaves free: by default the **height** of the top plane's centroid
along the base normal, kept at its rest value or at ``height`` (``hold = "height"``), or the
mean active length (``hold = "mean_length"``).  Newton's method on q uses the exact
sensitivity of the node positions to the active lengths, ``B(x) ∂x/∂q_j = e_j`` (the
compatibility matrix of the current assembly and the unit elongation of active member j), the
same equations that give the velocities.

On a chain of identical bays (``split_over_bays = true``, :func:`~trussfe.rigid.bays.chain_layout`)
the angle is that of the chain's top plane, and the motion is Lacy's own example of chapter
6: "a rotation of the top plane of a 3 bay truss [of] 30 degrees about n̂1 and 30 degrees about
n̂2" done as "a 10 degree, 10 degree rotation on a single bay" — every bay's active members
take the lengths q(θ/n) of the first bay alone turning by θ/n relative to its base, so each
bay has the same configuration relative to its base plane (the premise of eqs. 6.5 and 6.12).
Read as a rotation vector, Lacy's (30°, 30°) is a tilt of 42.43° about (n̂1 + n̂2)/√2, 14.14°
per bay.

The map θ ↦ q(θ) is solved on a grid of angles by continuation from the rest configuration
and interpolated by a quintic spline, whose first and second derivatives give
``q̇ = q'(θ) θ̇`` and ``q̈ = q''(θ) θ̇² + q'(θ) θ̈``.  The angle follows the thesis' third-order
actuator model in time (Lacy section 2.2, :func:`~trussfe.rigid.motion.third_order_response`),
a constant velocity between smooth ramps (:func:`constant_velocity_profile`, like Slewing
Experiment 1), or given samples.

Motion-file table::

    [motion]
    type = "rotation"
    axis = [1.0, 0.0, 0.0]        # or "n1", "n2"
    start = -10.0                 # degrees
    end = 10.0
    duration = 5.5                # s (third-order profile)
    steps = 200
    top_nodes = ["N7", "N8", "N9"]  # default: the three nodes highest along the base normal
    hold = "height"               # or "mean_length"
    height = 1.1218               # optional value held (default: the model's at rest)
    split_over_bays = false       # true: a chain's top-plane rotation, shared equally by
                                  # its n bays (Lacy ch. 6): each bay turns by angle/n
    profile = "third-order"       # or "constant-velocity" with ramp_time = 0.25 (s)
    # or a given profile instead of start/end/duration/steps:
    # time = [0.0, 0.1, ...]
    # angle = [-10.0, -9.9, ...]
"""
from __future__ import annotations

import logging
import math
from typing import Any

import numpy as np
from scipy.interpolate import make_interp_spline

from ..budget import along_motion_bytes, count_text, require
from ..errors import AnalysisError, InputError
from ..kinematics.assembly import solve_positions
from ..kinematics.compatibility import compatibility_matrix
from ..model.structure import Structure
from .active import active_indices
from .motion import Motion, spec_bool, spec_int, spec_positive, third_order_response
from .smoothing import smooth_derivative

log = logging.getLogger(__name__)

_KEYS = ("type", "axis", "start", "end", "duration", "steps", "top_nodes", "hold", "time",
         "angle", "grid", "height", "profile", "ramp_time", "damping_ratio",
         "settling_fraction", "settling_constant",
         "real_root_factor", "include_end", "first_sample", "split_over_bays")


def rotation_matrix(axis: np.ndarray, angle: float) -> np.ndarray:
    """Rotation by ``angle`` (rad) about the unit vector ``axis`` (Rodrigues' formula).

    Examples
    --------
    >>> np.round(rotation_matrix(np.array([1.0, 0, 0]), np.pi / 2) @ [0, 0, 1.0], 12)
    array([ 0., -1.,  0.])
    """
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * (K @ K)


def plane_normal(x: np.ndarray) -> np.ndarray:
    """Unit normal of the plane through three points ``x`` (3, 3), right-handed in their order."""
    n = np.cross(x[1] - x[0], x[2] - x[0])
    return n / np.linalg.norm(n)


class TopPlaneInverse:
    """Active lengths that give the top plane of a spatial truss a prescribed tilt.

    Parameters
    ----------
    structure : Structure
        Spatial truss at rest with exactly three active members (three conditions, three
        lengths), e.g. a double-octahedral bay.
    top_nodes : sequence of int
        The three nodes of the top plane.
    axis : ndarray, shape (3,)
        Rotation axis (in the base frame).
    hold : str
        Third condition: ``"height"`` or ``"mean_length"``.
    height : float, optional
        Value held (top centroid height, or mean active length), default its rest value.
    """

    def __init__(self, structure: Structure, top_nodes, axis, hold: str = "height",
                 height: float | None = None):
        if structure.dim != 3:
            raise InputError("motion.type", "a top-plane rotation needs a spatial (3-D) truss")
        self.s = structure
        self.active = active_indices(structure)
        if self.active.size != 3:
            raise InputError("motion", f"a top-plane rotation sets three conditions; the model "
                             f"has {self.active.size} active members (three are needed)")
        self.top = np.asarray(top_nodes, dtype=np.int64)
        self.axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
        self.hold = hold
        self.fixed = structure.translation_supports
        self.conn = structure.connectivity
        self.L = structure.lengths().copy()
        x0 = structure.coords
        # Angles are measured from the base normal n3 (the top plane of a bay at its
        # equilibrium position is parallel to the base); the model may rest at any tilt.
        self.up = np.array([0.0, 0.0, 1.0])
        self.n0 = self.up
        n_rest = plane_normal(x0[self.top])
        n_rest = n_rest if n_rest[2] > 0 else -n_rest
        self.rest_angle = math.atan2(self.axis @ np.cross(self.up, n_rest), self.up @ n_rest)
        self.c0 = self._third(x0, self.L[self.active]) if height is None else float(height)

    def _third(self, x: np.ndarray, q: np.ndarray) -> float:
        if self.hold == "height":
            return float(x[self.top].mean(axis=0) @ self.up)
        return float(np.mean(q))

    def _residual(self, x: np.ndarray, q: np.ndarray, u: np.ndarray) -> np.ndarray:
        n = plane_normal(x[self.top])
        n = n if n @ self.n0 > 0 else -n
        return np.array([n @ u[0], n @ u[1], self._third(x, q) - self.c0])

    def _forward(self, q: np.ndarray, x0: np.ndarray, item: str) -> np.ndarray:
        L = self.L.copy()
        L[self.active] = q
        return solve_positions(x0, self.conn, L, self.fixed, member_ids=self.s.member_ids,
                               item=item).coords

    def _sensitivity(self, x: np.ndarray) -> np.ndarray:
        """∂x/∂q, shape (3 active, n, 3): B(x) dx = e_j (Hortobágyi eq. 2)."""
        free = ~self.fixed
        B = compatibility_matrix(x, self.conn, free=free).toarray()
        rhs = np.zeros((self.conn.shape[0], self.active.size))
        rhs[self.active, np.arange(self.active.size)] = 1.0
        dx, *_ = np.linalg.lstsq(B, rhs, rcond=1e-12)
        out = np.zeros((self.active.size,) + x.shape)
        for j in range(self.active.size):
            full = np.zeros(x.shape)
            full[free] = dx[:, j]
            out[j] = full
        return out

    def solve(self, angle: float, q0: np.ndarray, x0: np.ndarray, *, tolerance: float = 1e-11,
              max_iterations: int = 30) -> tuple[np.ndarray, np.ndarray]:
        """Lengths q and node positions x for a tilt ``angle`` (rad), Newton from (q0, x0)."""
        target = rotation_matrix(self.axis, angle) @ self.n0
        # Orthonormal basis of the plane normal to the target normal.
        helper = np.eye(3)[np.argmin(np.abs(target))]
        u1 = np.cross(target, helper)
        u1 /= np.linalg.norm(u1)
        u = np.array([u1, np.cross(target, u1)])
        q, x = np.array(q0, dtype=float), np.array(x0, dtype=float)
        item = f"motion: top-plane rotation {math.degrees(angle):.6g} deg"
        for _ in range(max_iterations):
            x = self._forward(q, x, item)
            r = self._residual(x, q, u)
            if np.max(np.abs(r)) < tolerance:
                return q, x
            dxdq = self._sensitivity(x)
            h = 1e-6
            J = np.empty((3, 3))
            for j in range(3):
                dq = np.zeros(3)
                dq[j] = h
                J[:, j] = (self._residual(x + h * dxdq[j], q + dq, u)
                           - self._residual(x - h * dxdq[j], q - dq, u)) / (2 * h)
            if np.linalg.cond(J) > 1e12:
                raise AnalysisError(item, "the top-plane orientation does not determine the "
                                    "active lengths here (singular Jacobian)")
            step = np.linalg.solve(J, r)
            q = q - step
            if np.max(np.abs(step)) < 1e-14 * np.max(np.abs(q)):
                return q, self._forward(q, x, item)      # at round-off: stop
        raise AnalysisError(item, f"no active lengths reach this orientation (residual "
                            f"{np.max(np.abs(r)):.3g} after {max_iterations} iterations)")

    def lengths_along(self, angles: np.ndarray) -> np.ndarray:
        """Active lengths at increasing or decreasing ``angles`` (rad) by continuation from rest.

        Returns an array (len(angles), 3).
        """
        q = self.L[self.active].copy()
        x = self.s.coords.copy()
        # Walk from the rest orientation to the first angle in steps of at most 1 degree.
        a0, ar = float(angles[0]), self.rest_angle
        nwalk = max(2, int(math.ceil(abs(a0 - ar) / math.radians(1.0))) + 1)
        for a in np.linspace(ar, a0, nwalk):
            q, x = self.solve(a, q, x)
        out = np.empty((len(angles), 3))
        for k, a in enumerate(angles):
            q, x = self.solve(float(a), q, x)
            out[k] = q
        return out


def constant_velocity_profile(t: np.ndarray, duration: float, ramp: float
                              ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unit move at constant velocity between smooth ramps, with its two derivatives.

    The velocity rises as ``V (1 − cos(π t/τ))/2`` over the ramp time τ, stays at V and falls
    symmetrically, so that the move ends at 1 at ``t = duration``: ``V = 1/(T − τ)``.  It
    mimics Lacy's Slewing Experiment 1 (section 5.5.1: virtually constant velocity with
    acceleration spikes at both ends).

    Examples
    --------
    >>> y, dy, ddy = constant_velocity_profile(np.array([0.0, 2.0, 4.0]), 4.0, 0.5)
    >>> np.round(y, 12).tolist(), np.round(dy, 12).tolist()
    ([0.0, 0.5, 1.0], [0.0, 0.285714285714, 0.0])
    """
    t = np.clip(np.asarray(t, dtype=float), 0.0, duration)
    T, tau = duration, ramp
    V = 1.0 / (T - tau)
    w = math.pi / tau

    def up(s):                                         # ramp from rest, s in [0, τ]
        return (V * (s / 2 - np.sin(w * s) / (2 * w)), V * (1 - np.cos(w * s)) / 2,
                V * w * np.sin(w * s) / 2)

    y, dy, ddy = (np.empty_like(t) for _ in range(3))
    a = t < tau
    b = t > T - tau
    c = ~(a | b)
    y[a], dy[a], ddy[a] = up(t[a])
    y[c], dy[c], ddy[c] = V * (t[c] - tau / 2), V, 0.0
    yb, dyb, ddyb = up(T - t[b])
    y[b], dy[b], ddy[b] = 1.0 - yb, dyb, -ddyb
    return y, dy, ddy


def _axis(v: Any, item: str) -> np.ndarray:
    if isinstance(v, str):
        named = {"n1": [1.0, 0, 0], "n2": [0, 1.0, 0], "n3": [0, 0, 1.0]}
        if v not in named:
            raise InputError(item, f"unknown axis {v!r}; give 'n1', 'n2' or a 3-vector")
        return np.array(named[v])
    try:
        a = np.asarray(v, dtype=float).reshape(3)
    except (TypeError, ValueError):
        raise InputError(item, f"expected 'n1', 'n2' or a 3-vector, got {v!r}") from None
    if not np.all(np.isfinite(a)) or np.linalg.norm(a) == 0:
        raise InputError(item, "must be a finite, non-zero vector")
    return a


def _number(spec: dict, key: str, item: str, *, positive=False) -> float:
    if key not in spec:
        raise InputError(f"{item}.{key}", "is required")
    v = spec[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise InputError(f"{item}.{key}", f"expected a number, got {v!r}")
    if positive and v <= 0:
        raise InputError(f"{item}.{key}", f"must be positive, got {v!r}")
    return float(v)


#: Largest tilt of a top plane from its base normal (degrees; per bay for a rotation split
#: over the bays): beyond a half turn the orientations repeat, and the continuation from rest
#: would walk through every degree of the angle.
MAX_TILT_DEG = 180.0


def _tilt(value: float, key: str, item: str, n_bays: int) -> float:
    """``value`` (degrees) in radians, refused beyond :data:`MAX_TILT_DEG` per bay."""
    if abs(value) / n_bays > MAX_TILT_DEG:
        per = f" ({value / n_bays:g} degrees per bay of {n_bays})" if n_bays > 1 else ""
        raise InputError(f"{item}.{key}", f"{value:g} degrees{per} is more than a half turn; "
                         f"a top plane tilts by at most {MAX_TILT_DEG:g} degrees from its base "
                         "normal (angles are in degrees)")
    return math.radians(value)


def _steps_fit(n: int, structure: Structure, item: str) -> None:
    """Refuse a step count whose analysis cannot fit in memory (before sampling it)."""
    require(along_motion_bytes(n, structure.n_nodes, structure.n_members), f"{item}.steps",
            f"a motion of {count_text(n)} time steps", "use fewer steps (--steps)")


def rotation_motion(spec: dict, structure: Structure, *, steps: int | None = None) -> Motion:
    """Active-member motion realising a top-plane rotation (``[motion] type = "rotation"``).

    Parameters
    ----------
    spec : dict
        The ``[motion]`` table (module docstring).
    structure : Structure
        Spatial truss with three active members, at rest (angle 0).
    steps : int, optional
        Overrides ``spec["steps"]``.

    Returns
    -------
    Motion
        Lengths, velocities and accelerations of the three active members.

    Raises
    ------
    InputError
        Bad or missing keys, a model that is not a three-active spatial truss.
    AnalysisError
        An orientation that no assembly reaches.
    """
    item = "motion"
    if structure.dim != 3:
        raise InputError("motion.type", "a top-plane rotation needs a spatial (3-D) truss")
    for key in spec:
        if key not in _KEYS:
            raise InputError(f"{item}.{key}", f"unknown key; valid: {', '.join(_KEYS)}")
    axis = _axis(spec.get("axis", "n1"), f"{item}.axis")
    hold = spec.get("hold", "height")
    if hold not in ("height", "mean_length"):
        raise InputError(f"{item}.hold", f"must be \"height\" or \"mean_length\", got {hold!r}")
    split = spec_bool(spec, "split_over_bays", item)
    n_bays = 1
    chain = structure
    if split:
        from .bays import chain_layout
        if "top_nodes" in spec:
            raise InputError(f"{item}.top_nodes", "a rotation split over the bays turns each "
                             "bay's own top plane; top_nodes is not used with it")
        layout = chain_layout(structure)
        n_bays = layout.n_bays
        structure = layout.template
        top = [6, 7, 8]
    elif "top_nodes" in spec:
        names = spec["top_nodes"]
        if not isinstance(names, list) or len(names) != 3:
            raise InputError(f"{item}.top_nodes", "expected three node ids")
        try:
            top = [structure.node_index(str(n)) for n in names]
        except KeyError as exc:
            raise InputError(f"{item}.top_nodes", f"unknown node {exc}") from None
    else:
        top = list(np.argsort(structure.coords[:, -1])[-3:])
    if steps is not None and (isinstance(steps, bool) or not isinstance(steps, int)
                              or steps < 1):
        raise InputError("--steps", f"must be a positive integer, got {steps!r}")
    if "angle" in spec or "time" in spec:
        if steps is not None:
            raise InputError("--steps", "a rotation given by time and angle samples has its "
                             "own steps; --steps applies to start/end/duration rotations")
        try:
            t = np.asarray(spec["time"], dtype=float).reshape(-1)
            deg = np.asarray(spec["angle"], dtype=float).reshape(-1)
        except KeyError as exc:
            raise InputError(f"{item}.{exc.args[0]}", "a given profile needs both time and "
                             "angle") from None
        except (TypeError, ValueError):
            raise InputError(f"{item}.angle", "time and angle must be lists of numbers") \
                from None
        if t.size != deg.size or t.size < 5:
            raise InputError(f"{item}.angle", "time and angle need the same length, at least 5")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(deg))):
            raise InputError(f"{item}.angle", "time and angle must be finite")
        if np.any(np.diff(t) <= 0):
            raise InputError(f"{item}.time", "must increase strictly")
        _tilt(float(deg[np.argmax(np.abs(deg))]), "angle", item, n_bays)
        ang = np.radians(deg)
        dang = smooth_derivative(t, ang[:, None], item=f"{item}.time")[:, 0]
        ddang = smooth_derivative(t, ang[:, None], order=2, item=f"{item}.time")[:, 0]
    elif spec.get("profile", "third-order") == "constant-velocity":
        a0 = _tilt(_number(spec, "start", item), "start", item, n_bays)
        a1 = _tilt(_number(spec, "end", item), "end", item, n_bays)
        T = _number(spec, "duration", item, positive=True)
        ramp = _number(spec, "ramp_time", item, positive=True)
        if 2 * ramp > T:
            raise InputError(f"{item}.ramp_time", f"must be at most half the duration ({T / 2:g}"
                             " s)")
        n = steps if steps is not None else spec.get("steps", 50)
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise InputError(f"{item}.steps", f"must be a positive integer, got {n!r}")
        _steps_fit(n, chain, item)
        last = n + (1 if spec_bool(spec, "include_end", item) else 0)
        t = np.arange(last) * (T / n)
        y, dy, ddy = constant_velocity_profile(t, T, ramp)
        ang, dang, ddang = a0 + (a1 - a0) * y, (a1 - a0) * dy, (a1 - a0) * ddy
    else:
        if spec.get("profile", "third-order") != "third-order":
            raise InputError(f"{item}.profile", "must be \"third-order\" or "
                             f"\"constant-velocity\", got {spec['profile']!r}")
        a0 = _tilt(_number(spec, "start", item), "start", item, n_bays)
        a1 = _tilt(_number(spec, "end", item), "end", item, n_bays)
        T = _number(spec, "duration", item, positive=True)
        n = steps if steps is not None else spec.get("steps", 50)
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise InputError(f"{item}.steps", f"must be a positive integer, got {n!r}")
        _steps_fit(n, chain, item)
        opts = {k: spec_positive(spec, k, item) for k in (
            "damping_ratio", "settling_fraction", "settling_constant", "real_root_factor")
                if k in spec}
        first = spec_int(spec, "first_sample", item, 0)
        last = first + n + (1 if spec_bool(spec, "include_end", item) else 0)
        t = np.arange(first, last) * (T / n)
        y, dy, ddy = third_order_response(t, T, **opts)
        ang, dang, ddang = a0 + (a1 - a0) * y, (a1 - a0) * dy, (a1 - a0) * ddy
    held = None if "height" not in spec else _number(spec, "height", item, positive=True)
    ang, dang, ddang = ang / n_bays, dang / n_bays, ddang / n_bays
    inv = TopPlaneInverse(structure, top, axis, hold, held)
    # Grid over the swept range; the quintic spline of q(θ) is accurate to round-off for the
    # smooth inverse map of a bay well inside its workspace.
    lo, hi = float(ang.min()), float(ang.max())
    ngrid = spec_int(spec, "grid", item, 41, lo=6, hi=100_000)
    if hi - lo < 1e-12:
        q = np.repeat(inv.lengths_along(np.array([lo])), t.size, axis=0)
        dq = np.zeros_like(q)
        ddq = np.zeros_like(q)
    else:
        grid = np.linspace(lo, hi, ngrid)
        if abs(ang[0] - hi) < abs(ang[0] - lo):
            qg = inv.lengths_along(grid[::-1])[::-1]
        else:
            qg = inv.lengths_along(grid)
        spl = make_interp_spline(grid, qg, k=5)
        q = spl(ang)
        d1 = spl.derivative(1)(ang)
        d2 = spl.derivative(2)(ang)
        dq = d1 * dang[:, None]
        ddq = d2 * (dang ** 2)[:, None] + d1 * ddang[:, None]
    log.info("rotation motion: %d steps, active lengths %.6g … %.6g m", t.size, q.min(), q.max())
    if split:
        # Every bay's active members, bay after bay, take the first bay's lengths.
        return Motion(time=t, members=layout.members[:, layout.active].ravel(),
                      length=np.tile(q, n_bays), velocity=np.tile(dq, n_bays),
                      acceleration=np.tile(ddq, n_bays),
                      source=f"top-plane rotation about {np.round(axis, 6).tolist()} split "
                             f"over {n_bays} bays")
    return Motion(time=t, members=inv.active, length=q, velocity=dq, acceleration=ddq,
                  source=f"top-plane rotation about {np.round(axis, 6).tolist()}")
