# SPDX-License-Identifier: MIT
"""Member failure laws, the data: Euler buckling, yield of the section, fracture at a strain.

The laws act on bar members (co-rotational truss elements) and are given in the model file's
``[failure]`` table (read by :mod:`trussfe.io.extension_tables`)::

    [failure.default]                 # every bar member
    buckling = "cap"                  # "none" | "cap" | "softening" | "remove"
    effective_length_factor = 1.0     # K in P_cr = π² E I / (K L)²
    yield = "none"                    # "none" | "cap" | "remove"  (uses yield_strength)
    fracture_strain = 0.05            # tensile strain at which the bar breaks (removed)

    [failure.members.M3]              # overrides for one member
    buckling = "softening"
    critical_load = 1200.0            # N, instead of the Euler formula
    residual = 0.3                    # softening: force kept, as a fraction of P_cr
    softening_strain = 0.002          # softening: extra shortening over which it drops

The force–strain laws are :func:`trussfe.nonlinear.failure.axial_law` (described in
:mod:`trussfe.nonlinear.failure`); this module holds what a model carries: the law and its
parameters for every member.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .sealed import sealed


BUCKLING = ("none", "cap", "softening", "remove")
YIELD = ("none", "cap", "remove")


@dataclass(frozen=True, eq=False)
class FailureLaws:
    """Failure-law data of every member, as read-only arrays of shape (member,).

    Attributes
    ----------
    buckling : ndarray of int
        Index into :data:`BUCKLING`.
    critical_load : ndarray
        Euler load P_cr > 0, N (``inf`` where no buckling law).
    residual, softening_strain : ndarray
        Softening-law parameters.
    yield_mode : ndarray of int
        Index into :data:`YIELD`.
    yield_force : ndarray
        ``A f_y``, N (``inf`` where no yield law).
    fracture_strain : ndarray
        Tensile fracture strain (``inf`` where none).

    Examples
    --------
    >>> laws = FailureLaws.none(2)
    >>> laws.buckling[0] = 1
    Traceback (most recent call last):
    ...
    ValueError: assignment destination is read-only
    """

    buckling: np.ndarray
    critical_load: np.ndarray
    residual: np.ndarray
    softening_strain: np.ndarray
    yield_mode: np.ndarray
    yield_force: np.ndarray
    fracture_strain: np.ndarray

    def __post_init__(self) -> None:
        m = np.shape(self.buckling)[0] if np.ndim(self.buckling) else 0
        for name in ("buckling", "yield_mode"):
            object.__setattr__(self, name, _frozen(getattr(self, name), np.int64, m))
        for name in ("critical_load", "residual", "softening_strain", "yield_force",
                     "fracture_strain"):
            object.__setattr__(self, name, _frozen(getattr(self, name), float, m))

    @classmethod
    def none(cls, m: int) -> "FailureLaws":
        """No failure law on any of ``m`` members (purely elastic bars)."""
        return cls(np.zeros(m, int), np.full(m, np.inf), np.ones(m), np.ones(m),
                   np.zeros(m, int), np.full(m, np.inf), np.full(m, np.inf))

    @property
    def n_members(self) -> int:
        """Number of members the laws describe."""
        return self.buckling.shape[0]

    @property
    def any(self) -> np.ndarray:
        """Members with at least one law, shape (member,)."""
        return ((self.buckling > 0) | (self.yield_mode > 0)
                | np.isfinite(self.fracture_strain))

    def subset(self, idx: np.ndarray) -> "FailureLaws":
        """Laws of the members ``idx`` (e.g. the members modelled as truss elements)."""
        return FailureLaws(self.buckling[idx], self.critical_load[idx], self.residual[idx],
                           self.softening_strain[idx], self.yield_mode[idx],
                           self.yield_force[idx], self.fracture_strain[idx])


_FIELDS = ("buckling", "critical_load", "residual", "softening_strain", "yield_mode",
           "yield_force", "fracture_strain")


def _frozen(a, dtype, m: int) -> np.ndarray:
    return sealed(np.array(a, dtype=dtype).reshape(m))
