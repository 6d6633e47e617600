# SPDX-License-Identifier: MIT
"""Smooth differentiation of sampled histories (measured lengths, slew angles).

A cubic smoothing spline (:func:`scipy.interpolate.make_smoothing_spline`, which minimises
``Σ (y_i − f(t_i))² + λ ∫ f''² dt``) is fitted to the samples, λ chosen by generalised
cross-validation unless given; its derivatives are the rates.  Finite differences of measured
positions amplify noise by 1/dt and 1/dt²; the spline's cross-validated smoothing does not.

The cross-validation searches λ in ``(0, n)`` in the unit of ``t``, while the penalty
``∫ f''² dt`` grows as 1/h³ as the sample spacing h shrinks: for samples much closer than
10 ms that range holds only over-smoothed fits (rates off by tens of per cent), and below about
0.1 µs only singular systems.  Samples closer than :data:`FIT_SPACING` are therefore fitted in a
time unit in which the closest two are :data:`FIT_SPACING` apart, and the rates scaled back: a
record sampled at 1 MHz gets the rates of the same record sampled at 100 Hz, times 10⁴ (and 10⁸
for the second derivative).  Records sampled at 100 Hz or slower are fitted in seconds.
"""
from __future__ import annotations

import numpy as np
from scipy.interpolate import make_smoothing_spline

from ..errors import InputError

#: Closest sample spacing (s) fitted in seconds; closer samples are fitted in a finer unit.
FIT_SPACING = 1e-2

#: Largest magnitude of a rate accepted (m/s, m/s², rad/s, ...): no motion of a truss comes
#: near it, and beyond it the dynamic forces' squares overflow.
MAX_RATE = 1e100


def smooth_derivative(t: np.ndarray, y: np.ndarray, smoothing: float | None = None,
                      order: int = 1, item: str = "time") -> np.ndarray:
    """Derivative of a cubic smoothing spline through ``(t, y)``, columnwise.

    Parameters
    ----------
    t : ndarray, shape (nt,)
        Strictly increasing times, at least 5.
    y : ndarray, shape (nt, k)
        Samples.
    smoothing : float, optional
        λ of the smoothing spline (for ``t`` in seconds); ``None`` selects it by generalised
        cross-validation.
    order : int
        1 or 2: first or second derivative.
    item : str
        The times' item in the input, named when the rates cannot be computed.

    Returns
    -------
    ndarray, shape (nt, k)
        The derivative at the sample times, finite and at most :data:`MAX_RATE` in magnitude.

    Raises
    ------
    InputError
        Naming ``item``: the spline cannot be fitted through these times, or its rates are not
        finite or beyond :data:`MAX_RATE` (samples far too close for the change in ``y``).

    Examples
    --------
    Away from the ends (natural end conditions, f'' = 0, bend the first and last samples):

    >>> t = np.linspace(0.0, 1.0, 41)
    >>> d = smooth_derivative(t, np.sin(t)[:, None])
    >>> bool(np.max(np.abs(d[2:-2, 0] - np.cos(t[2:-2]))) < 2e-3)
    True

    A record sampled at 100 Hz and the same samples a million times closer: a million times the
    rate.

    >>> t = 0.01 * np.arange(41)
    >>> slow = smooth_derivative(t, np.sin(t)[:, None])
    >>> fast = smooth_derivative(t * 1e-6, np.sin(t)[:, None])
    >>> bool(np.allclose(fast * 1e-6, slow, rtol=1e-6, atol=0.0))
    True
    """
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    out = np.empty_like(y)
    closest = float(np.min(np.diff(t)))
    # (the tolerance keeps a record sampled at exactly 100 Hz, whose spacings round to either
    # side of 10 ms, in seconds)
    if closest < FIT_SPACING * (1.0 - 1e-9):
        scale = np.float64(FIT_SPACING) / closest      # inf-safe powers below
        tau = (t - t[0]) * scale
        # λ ∫ f''² dt in seconds is λ s³ ∫ f''² dτ in the finer unit τ = s t.
        lam = None if smoothing is None else smoothing * scale ** 3
    else:
        scale, tau, lam = 1.0, t, smoothing
    # Very sparse samples make the cross-validation meet an exact interpolation (a zero
    # denominator, an infinite score that the search passes over) and its squares overflow;
    # the rates are checked for finiteness below instead.
    with np.errstate(over="ignore", divide="ignore", invalid="ignore", under="ignore"):
        try:
            for j in range(y.shape[1]):     # one GCV choice of λ per member (few columns)
                out[:, j] = make_smoothing_spline(tau, y[:, j], lam=lam).derivative(order)(tau)
        except (ValueError, np.linalg.LinAlgError):
            raise InputError(item, f"no smoothing spline can be fitted through these samples "
                             f"(spacing from {closest:.3g} to {float(np.max(np.diff(t))):.3g} "
                             "s); resample the record more evenly") from None
        if scale != 1.0:
            out *= scale ** order
        finite = bool(np.all(np.isfinite(out)) and np.all(np.abs(out) <= MAX_RATE))
    if not finite:
        raise InputError(item, f"samples {closest:.3g} s apart give rates beyond any motion "
                         f"(magnitude above {MAX_RATE:g}); check the time unit")
    return out
