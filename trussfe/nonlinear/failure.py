# SPDX-License-Identifier: MIT
"""Member failure laws: Euler buckling, yield of the section, fracture at a strain.

The laws act on bar members (co-rotational truss elements) and are given in the model file's
``[failure]`` table (registered with :func:`trussfe.io.model_file.register_table`)::

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

Force–strain laws (``ε`` engineering strain, ``ε_p`` plastic strain, ``N_e = EA(ε − ε_p)``):

* buckling ``cap``: ``N = max(N_e, −P_cr)`` — the elastic strut after buckling carries P_cr
  while it shortens (the elastica is flat to first order at the bifurcation);
  ``softening``: beyond ``ε_cr = −P_cr/EA`` the compression drops linearly to ``residual·P_cr``
  over ``softening_strain`` and stays there; ``remove``: the bar is removed when ``N_e``
  reaches ``−P_cr``.  The buckling laws are elastic (path independent): an unloading strut
  retraces the curve, as an elastic strut does.
* yield ``cap``: elastic–perfectly plastic with a committed plastic strain; ``remove``: removed
  when ``|N| = A f_y``.
* fracture: removed when ``ε`` reaches ``fracture_strain``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError
from ..mechanics.euler import euler_load, weak_axis_inertia

BUCKLING = ("none", "cap", "softening", "remove")
YIELD = ("none", "cap", "remove")
_KEYS = ("buckling", "effective_length_factor", "critical_load", "residual",
         "softening_strain", "yield", "yield_strength", "fracture_strain")


@dataclass
class FailureLaws:
    """Failure-law data of every member, as arrays of shape (member,).

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
    """

    buckling: np.ndarray
    critical_load: np.ndarray
    residual: np.ndarray
    softening_strain: np.ndarray
    yield_mode: np.ndarray
    yield_force: np.ndarray
    fracture_strain: np.ndarray
    raw: dict = field(default_factory=dict)

    @classmethod
    def none(cls, m: int) -> "FailureLaws":
        """No failure law on any of ``m`` members (purely elastic bars)."""
        return cls(np.zeros(m, int), np.full(m, np.inf), np.ones(m), np.ones(m),
                   np.zeros(m, int), np.full(m, np.inf), np.full(m, np.inf))

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


def axial_law(laws: FailureLaws, EA: np.ndarray, strain: np.ndarray,
              plastic: np.ndarray):
    """Axial force and its strain derivative under the failure laws (vectorised).

    Parameters
    ----------
    laws : FailureLaws
        Laws of the elements (one per element, shape (element,)).
    EA : ndarray, shape (element,)
    strain, plastic : ndarray, shape (element,)
        Total engineering strain and committed plastic strain.

    Returns
    -------
    N, dNde : ndarray, shape (element,)
    trial : ndarray, shape (element,)
        Elastic trial force ``EA (ε − ε_p)``.
    N_buckling : ndarray, shape (element,)
        Force after the buckling law alone (before the yield cap).

    Examples
    --------
    >>> laws = FailureLaws.none(3)
    >>> laws.buckling[:] = 1; laws.critical_load[:] = 10.0
    >>> N, k, _, _ = axial_law(laws, np.full(3, 1000.), np.array([-0.02, -0.005, 0.01]),
    ...                        np.zeros(3))
    >>> N, k
    (array([-10.,  -5.,  10.]), array([   0., 1000., 1000.]))
    """
    trial = EA * (strain - plastic)
    N = trial.copy()
    k = EA.copy()
    Pcr = laws.critical_load
    cap = (laws.buckling == 1) & (trial < -Pcr)
    N[cap] = -Pcr[cap]
    k[cap] = 0.0
    soft = (laws.buckling == 2) & (trial < -Pcr)
    if soft.any():
        es = laws.softening_strain[soft]
        over = (-Pcr[soft] - trial[soft]) / EA[soft]              # extra shortening >= 0
        frac = np.minimum(over / es, 1.0)
        r = laws.residual[soft]
        N[soft] = -Pcr[soft] * (1.0 - (1.0 - r) * frac)
        # dN/dε: compression falls as ε decreases, so the slope is negative on the ramp
        k[soft] = np.where(over < es, -Pcr[soft] * (1.0 - r) / es, 0.0)
    Nb = N.copy()
    Ny = laws.yield_force
    yl = (laws.yield_mode == 1) & (np.abs(N) > Ny)
    N[yl] = np.sign(N[yl]) * Ny[yl]
    k[yl] = 0.0
    return N, k, trial, Nb


def failure_margins(laws: FailureLaws, trial: np.ndarray, N_buckling: np.ndarray,
                    strain: np.ndarray):
    """Distance of each element from each failure event (≥ 0: reached).

    Returns
    -------
    ndarray, shape (3, element)
        Rows: buckling ``−N_e/P_cr − 1``, yield ``|N_b|/(A f_y) − 1``, fracture
        ``ε/ε_f − 1``; ``−inf`` where the law is absent.
    """
    out = np.full((3, trial.shape[0]), -np.inf)
    b = laws.buckling > 0
    out[0, b] = -trial[b] / laws.critical_load[b] - 1.0
    y = laws.yield_mode > 0
    out[1, y] = np.abs(N_buckling[y]) / laws.yield_force[y] - 1.0
    f = np.isfinite(laws.fracture_strain)
    out[2, f] = strain[f] / laws.fracture_strain[f] - 1.0
    return out


# ------------------------------------------------------------------------------- reader
def _law(raw: Any, item: str) -> dict:
    if not isinstance(raw, dict):
        raise InputError(item, "expected a table of failure-law keys "
                               f"({', '.join(_KEYS)})")
    for k in raw:
        if k not in _KEYS:
            raise InputError(f"{item}.{k}", f"unknown key '{k}'; valid: {', '.join(_KEYS)}")
    out = dict(raw)
    for k in ("effective_length_factor", "critical_load", "residual", "softening_strain",
              "yield_strength", "fracture_strain"):
        if k in out:
            v = out[k]
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                raise InputError(f"{item}.{k}", f"expected a finite number, got {v!r}")
            out[k] = float(v)
    for k, allowed in (("buckling", BUCKLING), ("yield", YIELD)):
        if k in out and out[k] not in allowed:
            raise InputError(f"{item}.{k}", f"unknown law {out[k]!r}; valid: "
                                             f"{', '.join(allowed)}")
    return out


def parse_failure_table(raw: Any, structure, base_dir: Path | None = None) -> FailureLaws:
    """Read the ``[failure]`` table into :class:`FailureLaws` (checks every parameter).

    Raises
    ------
    InputError
        Unknown keys, unknown laws, non-positive parameters, parameters that the chosen law
        does not use (e.g. ``residual`` with ``buckling = "cap"``), a residual outside [0, 1],
        a buckling law on a section without a second moment of area, a yield law on a material
        without ``yield_strength``.
    """
    if not isinstance(raw, dict):
        raise InputError("[failure]", "expected a table with 'default' and/or 'members'")
    for k in raw:
        if k not in ("default", "members"):
            raise InputError(f"failure.{k}", "unknown key; valid: default, members")
    default = _law(raw.get("default", {}), "failure.default")
    members = raw.get("members", {})
    if not isinstance(members, dict):
        raise InputError("failure.members", "expected a table of member ids")
    per = {}
    for mid, law in members.items():
        if str(mid) not in structure.member_ids:
            raise InputError(f"failure.members.{mid}", f"member '{mid}' is not defined")
        per[structure.member_index(str(mid))] = _law(law, f"failure.members.{mid}")
    return build_failure_laws(structure, default, per)


def build_failure_laws(structure, default: dict | None = None,
                       per_member: dict[int, dict] | None = None) -> FailureLaws:
    """Failure laws from a default law and per-member overrides (dicts as in the file).

    Parameters
    ----------
    structure : Structure
    default : dict, optional
        Keys of a ``[failure.default]`` table.
    per_member : dict, optional
        Member index → keys overriding the default for that member.
    """
    m = structure.n_members
    laws = FailureLaws.none(m)
    default = default or {}
    per_member = per_member or {}
    L = structure.lengths()
    E, A = structure.E, structure.area
    Imin = weak_axis_inertia(structure.Iy, structure.Iz)
    fy = structure.yield_strength
    for i in range(m):   # input checking only: once per member, at read time
        law = {**default, **per_member.get(i, {})}
        if not law:
            continue
        item = (f"failure.members.{structure.member_ids[i]}" if i in per_member
                else "failure.default")
        mid = structure.member_ids[i]
        for k in ("effective_length_factor", "critical_load", "softening_strain",
                  "yield_strength", "fracture_strain"):
            if k in law and law[k] <= 0.0:
                raise InputError(f"{item}.{k}", f"must be positive, got {law[k]}")
        bmode = law.get("buckling", "none")
        if bmode != "softening":
            for k in ("residual", "softening_strain"):
                if k in law:
                    raise InputError(f"{item}.{k}", f"'{k}' belongs to buckling = "
                                                    f"\"softening\", not \"{bmode}\"")
        if bmode == "none":
            for k in ("effective_length_factor", "critical_load"):
                if k in law:
                    raise InputError(f"{item}.{k}", "given without a buckling law; set "
                                                    "buckling = \"cap\", \"softening\" or "
                                                    "\"remove\"")
        if bmode != "none":
            if "critical_load" in law:
                if "effective_length_factor" in law:
                    raise InputError(f"{item}.critical_load", "give either critical_load or "
                                                              "effective_length_factor")
                Pcr = law["critical_load"]
            else:
                if not np.isfinite(Imin[i]):
                    raise InputError(item, f"member {mid}: section "
                                           f"'{structure.sections[i].name}' has no second "
                                           "moment of area; give critical_load")
                K = law.get("effective_length_factor", 1.0)
                Pcr = float(euler_load(E[i], Imin[i], L[i], K))
            laws.buckling[i] = BUCKLING.index(bmode)
            laws.critical_load[i] = Pcr
            if bmode == "softening":
                r = law.get("residual", None)
                es = law.get("softening_strain", None)
                if r is None or es is None:
                    raise InputError(item, "buckling = \"softening\" needs residual and "
                                           "softening_strain")
                if not 0.0 <= r <= 1.0:
                    raise InputError(f"{item}.residual", f"must lie in [0, 1] (a fraction of "
                                                         f"P_cr), got {r}")
                laws.residual[i] = r
                laws.softening_strain[i] = es
        ymode = law.get("yield", "none")
        if ymode == "none" and "yield_strength" in law:
            raise InputError(f"{item}.yield_strength", "given without a yield law; set "
                                                       "yield = \"cap\" or \"remove\"")
        if ymode != "none":
            f = law.get("yield_strength", fy[i])
            if not np.isfinite(f):
                raise InputError(item, f"member {mid}: material "
                                       f"'{structure.materials[i].name}' has no "
                                       "yield_strength; give yield_strength")
            laws.yield_mode[i] = YIELD.index(ymode)
            laws.yield_force[i] = A[i] * f
        if "fracture_strain" in law:
            laws.fracture_strain[i] = law["fracture_strain"]
    laws.raw = {"default": default, "members": {structure.member_ids[k]: v
                                                for k, v in per_member.items()}}
    return laws
