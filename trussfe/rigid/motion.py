# SPDX-License-Identifier: MIT
"""Prescribed motion of the active members: lengths, velocities, accelerations over time.

The thesis' actuator model (Lacy section 2.2, Appendix A) is a third-order system driven by a
step of size ``end - start``: a complex pole pair of damping ratio ζ = 0.8 and natural
frequency ωn chosen so that the response settles at 0.9 T, and a fast real pole at 2 ωn,

.. math:: \\frac{Y(s)}{U(s)} = \\frac{2\\omega_n^3}
          {(s^2 + 2\\zeta\\omega_n s + \\omega_n^2)(s + 2\\omega_n)} .

The text gives ts = 4/(ζ ωn); Appendix A codes ``wn = 6/(zeta*ts)``, and only the coded value
reproduces the published maximum velocity (1.2477 m/s for the Base Simulation; 4 gives
0.83 m/s), so ``settling_constant = 6`` is the default.  The response, its velocity and its
acceleration are evaluated exactly from the partial-fraction form of the step response (the
thesis' ``lsim`` of a constant input is exact too), not by differencing.

Motion files (TOML ``[motion]`` tables, CSV histories of :mod:`trussfe.rigid.motion_csv`,
top-plane rotations of :mod:`trussfe.rigid.slew`) are read by :mod:`trussfe.rigid.motion_file`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..budget import along_motion_bytes, count_text, require
from ..errors import InputError
from ..mechanics.conventions import PHYSICAL
from ..model.structure import Structure
from .active import active_members


@dataclass
class Motion:
    """Histories of the active members' lengths.

    Attributes
    ----------
    time : ndarray, shape (nt,)
        Strictly increasing sample times, s.
    members : ndarray of int, shape (na,)
        Member indices of the active members, in the column order of the histories.
    length, velocity, acceleration : ndarray, shape (nt, na)
        Member length (m), its rate (m/s) and second rate (m/s²).
    source : str
        Where the motion came from (file name or description), for messages.
    first_step : int
        Index of the first sample in the whole motion when this is a block of it, so that
        messages name the step of the whole motion.
    """

    time: np.ndarray
    members: np.ndarray
    length: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    source: str = ""
    first_step: int = 0

    def __post_init__(self) -> None:
        self.time = np.asarray(self.time, dtype=float).reshape(-1)
        self.members = np.asarray(self.members, dtype=np.int64).reshape(-1)
        shape = (self.time.size, self.members.size)
        for name in ("length", "velocity", "acceleration"):
            arr = np.asarray(getattr(self, name), dtype=float).reshape(shape)
            setattr(self, name, arr)
        check_motion(self)

    @property
    def n_steps(self) -> int:
        """Number of time samples."""
        return self.time.size


def check_motion(motion: Motion, item: str | None = None) -> None:
    """Raise :class:`InputError` for a non-monotonic time, NaN or non-positive lengths.

    Examples
    --------
    >>> Motion([0.0, 0.0], [0], [[1.0], [1.0]], [[0.0], [0.0]], [[0.0], [0.0]])
    Traceback (most recent call last):
    ...
    trussfe.errors.InputError: motion: time: must increase strictly; sample 1 (t = 0 s) does not
    """
    item = item or (f"{motion.source}: motion" if motion.source else "motion")
    t = motion.time
    if t.size == 0:
        raise InputError(item, "has no time samples")
    if not np.all(np.isfinite(t)):
        raise InputError(f"{item}: time", f"is NaN or infinite at sample "
                         f"{int(np.flatnonzero(~np.isfinite(t))[0])}")
    bad = np.flatnonzero(np.diff(t) <= 0)
    if bad.size:
        k = int(bad[0]) + 1
        raise InputError(f"{item}: time", f"must increase strictly; sample {k} "
                         f"(t = {t[k]:g} s) does not")
    for name in ("length", "velocity", "acceleration"):
        arr = getattr(motion, name)
        if not np.all(np.isfinite(arr)):
            i, j = np.argwhere(~np.isfinite(arr))[0]
            raise InputError(f"{item}: {name}", f"is missing or NaN at sample {int(i)} "
                             f"(t = {t[i]:g} s) for active member column {int(j)}")
    if np.any(motion.length <= 0):
        i, j = np.argwhere(motion.length <= 0)[0]
        raise InputError(f"{item}: length", f"must be positive; sample {int(i)} has "
                         f"{motion.length[i, j]:g} m")


def check_stroke(structure: Structure, motion: Motion) -> None:
    """Raise :class:`InputError` when ``motion`` drives an active member outside its stroke.

    The stroke limits are the ``min_length``/``max_length`` of ``[active_members]``
    (:class:`~trussfe.model.active.ActiveMember`); a member without them is checked only
    against its ``tube_length``, which it may not become shorter than.  A
    length within 1e-9 (relative) of a limit counts as on it, so a motion generated to end
    exactly at a limit is not refused for its last bit.

    Examples
    --------
    >>> from trussfe.models import triangular_truss
    >>> s = triangular_truss(active_members=True)          # stroke 2.5-4.1 m
    >>> check_stroke(s, Motion([0.0, 1.0], [1], [[2.5], [4.2]], [[0.0], [0.0]], [[0.0], [0.0]]))
    Traceback (most recent call last):
    ...
    trussfe.errors.InputError: motion: step 1 (t = 1 s): active member 'active' is 4.2 m long, \
beyond its stroke 2.5-4.1 m by 0.1 m ([active_members.active] min_length, max_length)
    """
    actives = {a.member: a for a in structure.extensions.get("active_members", ())}
    item = f"{motion.source}: motion" if motion.source else "motion"
    members = np.asarray(motion.members).tolist()
    # per motion column: stroke limits and the leadscrew tube, NaN where not given (a
    # comparison with NaN is false).  The tube lies between the member's end node and the
    # base: a member shorter than its tube would put the tube behind its start node (the
    # model file's tube_length is refused when longer than the member at rest, likewise).
    nan3 = (math.nan, math.nan, math.nan)
    limits = np.array([(a.min_length, a.max_length, a.tube_length)
                       if (a := actives.get(k)) is not None else nan3 for k in members],
                      dtype=float).reshape(-1, 3)
    lo_all, hi_all, tube_all = limits.T
    L = motion.length
    out = ((L < lo_all * (1.0 - STROKE_TOLERANCE)) | (L > hi_all * (1.0 + STROKE_TOLERANCE))
           | (L < tube_all * (1.0 - STROKE_TOLERANCE)))
    bad = np.argwhere(out)                   # by step, then by column: the first step out
    if bad.size:
        i, j = (int(v) for v in bad[0])
        k = members[j]
        lo, hi, tube = limits[j]
        name = structure.member_ids[k]
        length = motion.length[i, j]
        shown = f"{length:.6g}"
        if (length < lo <= float(shown)) or (float(shown) <= hi < length):
            shown = f"{length:.12g}"     # six digits would round it onto the limit it passes
        where = f"step {i} (t = {motion.time[i]:g} s): active member '{name}' is {shown} m long"
        if np.isfinite(tube) and length < tube * (1.0 - STROKE_TOLERANCE) \
                and not (np.isfinite(lo) and length < lo * (1.0 - STROKE_TOLERANCE)):
            raise InputError(item, f"{where}, shorter than its leadscrew tube ({tube:g} m, "
                             f"[active_members.{name}] tube_length)")
        short = length < lo * (1.0 - STROKE_TOLERANCE)
        side = "short of" if short else "beyond"
        by = (lo - length) if short else (length - hi)
        raise InputError(item, f"{where}, {side} its stroke {lo:g}-{hi:g} m by "
                         f"{by:.3g} m ([active_members.{name}] min_length, max_length)")


#: Relative slack of :func:`check_stroke` (round-off of lengths generated at a limit).
STROKE_TOLERANCE = 1e-9


def third_order_response(t: np.ndarray, duration: float, *, damping_ratio: float = 0.8,
                         settling_fraction: float = 0.9,
                         settling_constant: float = PHYSICAL.settling_constant,
                         real_root_factor: float = 2.0) -> tuple[np.ndarray, ...]:
    """Unit-step response of the thesis' third-order actuator model and its two derivatives.

    Parameters
    ----------
    t : ndarray
        Times, s (from the start of the move).
    duration : float
        Total motion time T, s; the settling time is ``settling_fraction * T``.
    damping_ratio, settling_fraction, settling_constant, real_root_factor : float
        ζ, ts/T, the constant c of ωn = c/(ζ ts) and the real pole as a multiple of ωn
        (Lacy section 2.2 and Appendix A: 0.8, 0.9, 6, 2; c is
        :attr:`~trussfe.mechanics.conventions.Conventions.settling_constant`).

    Returns
    -------
    y, dy, ddy : ndarray
        Response, velocity and acceleration for a unit step.

    Examples
    --------
    The Base Simulation: a 1.2 m stroke in 3 s, 50 samples 0.06 s apart; the largest sampled
    velocity is Lacy's 1.2477 m/s (section 3.7).

    >>> y, dy, ddy = third_order_response(np.arange(50) * 0.06, 3.0)
    >>> round(float(1.2 * dy.max()), 4)
    1.2477
    """
    t = np.asarray(t, dtype=float)
    z = damping_ratio
    if not (0.0 < z < 1.0):
        raise InputError("motion.damping_ratio", f"must lie in (0, 1), got {z}")
    wn = settling_constant / (z * settling_fraction * duration)
    # the residues below take wn³: refuse time scales no actuator has (and floats cannot hold)
    if not (1e-50 < wn < 1e50 and 1e-50 < real_root_factor * wn < 1e50):
        raise InputError("motion.duration", f"{duration:g} s with these settling parameters "
                         f"gives a natural frequency of {wn:g} rad/s, beyond any actuator; "
                         "check the units (duration in s)")
    wd = wn * math.sqrt(1.0 - z * z)
    poles = np.array([-z * wn + 1j * wd, -z * wn - 1j * wd, -real_root_factor * wn])
    gain = real_root_factor * wn ** 3            # num = den(4): unit static gain
    # Residues of Y(s) = gain / (s * den(s)) at the poles of den.
    res = np.array([gain / (p * np.prod([p - q for q in poles if q != p])) for p in poles])
    # a fast-decaying pole's term reaches zero, its exact limit, within the motion: that
    # underflow is not a numerical failure
    with np.errstate(under="ignore"):
        ex = np.exp(np.outer(t, poles))          # (time, pole)
        y = 1.0 + np.real(ex @ res)
        dy = np.real(ex @ (res * poles))
        ddy = np.real(ex @ (res * poles ** 2))
    return y, dy, ddy


def third_order_motion(structure: Structure, start: dict | np.ndarray, end: dict | np.ndarray,
                       duration: float, steps: int, *, first_sample: int = 0,
                       include_end: bool = False, **model: float) -> Motion:
    """Motion of every active member from its start to its end length (Lacy section 2.2).

    Parameters
    ----------
    structure : Structure
        Model with ``[active_members]``.
    start, end : dict or array
        Member id → length (m), or arrays in the order of the active members.
    duration : float
        Motion time T, s.
    steps : int
        Number of time steps; the step is ``dt = T / steps``.
    first_sample : int
        Index of the first sample: samples are at ``t_i = i dt`` for
        ``i = first_sample … first_sample + steps - 1`` (Appendix A: ``T = (0:dt:tt-dt)``, so 0),
        or up to ``steps`` inclusive when ``include_end``.
    **model
        Parameters of :func:`third_order_response`.
    """
    acts = active_members(structure)
    if not acts:
        raise InputError("motion", "the model has no [active_members]; nothing can move")
    if isinstance(steps, bool) or not (isinstance(steps, (int, np.integer)) and steps >= 1):
        raise InputError("motion.steps", f"must be a positive integer, got {steps!r}")
    if not (duration > 0 and math.isfinite(duration)):
        raise InputError("motion.duration", f"must be positive, got {duration!r}")
    if isinstance(first_sample, bool) or not isinstance(first_sample, (int, np.integer)) \
            or first_sample < 0:
        raise InputError("motion.first_sample", "must be an integer sample index (0 or more), "
                         f"got {first_sample!r}")
    if first_sample > 1_000_000_000:
        raise InputError("motion.first_sample", f"{first_sample} is beyond any motion; the "
                         "first sample is 0 or 1 (Lacy's Appendix A uses 0)")
    if not isinstance(include_end, (bool, np.bool_)):
        raise InputError("motion.include_end", f"must be true or false, got {include_end!r}")
    require(along_motion_bytes(steps, structure.n_nodes, structure.n_members),
            "motion.steps", f"a motion of {count_text(steps)} time steps",
            "use fewer steps (--steps)")
    members = np.array([a.member for a in acts])
    L0 = structure.lengths()[members]

    def vec(v, name):
        if isinstance(v, dict):
            out = L0.copy()
            for k, x in v.items():
                try:
                    j = list(members).index(structure.member_index(str(k)))
                except (KeyError, ValueError):
                    raise InputError(f"motion.{name}.{k}", f"'{k}' is not an active member of "
                                     "the model") from None
                out[j] = float(x)
            return out
        return np.broadcast_to(np.asarray(v, dtype=float), L0.shape).copy()

    a, b = vec(start, "start"), vec(end, "end")
    dt = duration / steps
    last = first_sample + steps + (1 if include_end else 0)
    t = np.arange(first_sample, last) * dt
    y, dy, ddy = third_order_response(t, duration, **model)
    d = b - a
    return Motion(time=t, members=members, length=a + np.outer(y, d),
                  velocity=np.outer(dy, d), acceleration=np.outer(ddy, d),
                  source="third-order motion")


def rest_motion(structure: Structure) -> Motion:
    """One time step at rest in the model's geometry (``simulate`` without ``--motion``)."""
    members = np.array([a.member for a in active_members(structure)], dtype=np.int64)
    L = structure.lengths()[members][None, :]
    z = np.zeros_like(L)
    return Motion(time=np.zeros(1), members=members, length=L, velocity=z, acceleration=z,
                  source="at rest")


def spec_int(spec: dict, key: str, item: str, default: int, lo: int = 0,
             hi: int = 1_000_000_000) -> int:
    """An integer entry of a motion table (``first_sample``, ``grid``), checked."""
    v = spec.get(key, default)
    if isinstance(v, bool) or not isinstance(v, int) or not lo <= v <= hi:
        raise InputError(f"{item}.{key}", f"must be an integer from {lo} to {hi:,}, got {v!r}")
    return int(v)


def spec_bool(spec: dict, key: str, item: str, default: bool = False) -> bool:
    """A true/false entry of a motion table (``include_end``): a string "no" is refused,
    not read as true."""
    v = spec.get(key, default)
    if not isinstance(v, bool):
        raise InputError(f"{item}.{key}", f"must be true or false, got {v!r}")
    return v


def spec_positive(spec: dict, key: str, item: str) -> float:
    """A positive finite number of a motion table (the response-model parameters)."""
    v = spec[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not (
            math.isfinite(float(v)) and v > 0):
        raise InputError(f"{item}.{key}", f"must be a positive number, got {v!r}")
    return float(v)
