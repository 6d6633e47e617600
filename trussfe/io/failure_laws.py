# SPDX-License-Identifier: MIT
"""Failure laws from the ``[failure]`` table's dicts: the data of :mod:`trussfe.model.failure`,
with each strut's Euler load from :func:`trussfe.mechanics.euler.euler_load` (Lacy eq. 2.26)."""
from __future__ import annotations

import numpy as np

from ..errors import InputError
from ..mechanics.euler import euler_load, weak_axis_inertia
from ..model.failure import _FIELDS, BUCKLING, YIELD, FailureLaws

__all__ = ["build_failure_laws"]


def build_failure_laws(structure, default: dict | None = None,
                       per_member: dict[int, dict] | None = None) -> FailureLaws:
    """Failure laws from a default law and per-member overrides (dicts as in the file).

    Parameters
    ----------
    structure : Structure
    default : dict, optional
        Keys of a ``[failure.default]`` table.
    per_member : dict, optional
        Member index → keys overriding the default for that member (see :func:`_merged`).
    """
    m = structure.n_members
    none = FailureLaws.none(m)
    arrays = {name: getattr(none, name).copy() for name in _FIELDS}
    default = default or {}
    per_member = per_member or {}
    L = structure.lengths()
    E, A = structure.E, structure.area
    Imin = weak_axis_inertia(structure.Iy, structure.Iz)
    fy = structure.yield_strength
    for i in range(m):   # input checking only: once per member, at read time
        law = _merged(default, per_member.get(i, {}))
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
            arrays["buckling"][i] = BUCKLING.index(bmode)
            arrays["critical_load"][i] = Pcr
            if bmode == "softening":
                r = law.get("residual", None)
                es = law.get("softening_strain", None)
                if r is None or es is None:
                    raise InputError(item, "buckling = \"softening\" needs residual and "
                                           "softening_strain")
                if not 0.0 <= r <= 1.0:
                    raise InputError(f"{item}.residual", f"must lie in [0, 1] (a fraction of "
                                                         f"P_cr), got {r}")
                arrays["residual"][i] = r
                arrays["softening_strain"][i] = es
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
            arrays["yield_mode"][i] = YIELD.index(ymode)
            arrays["yield_force"][i] = A[i] * f
        if "fracture_strain" in law:
            arrays["fracture_strain"][i] = law["fracture_strain"]
    return FailureLaws(**arrays)


#: default keys that a member's own key supersedes (they describe the law it replaces)
_SUPERSEDES = {"critical_load": ("effective_length_factor",),
               "effective_length_factor": ("critical_load",)}


def _merged(default: dict, own: dict) -> dict:
    """A member's law: the default with the member's keys overriding it.

    A member's key overrides the default's parameters of the law it replaces: its
    ``critical_load`` replaces the default's ``effective_length_factor`` (and vice versa), a
    buckling law other than ``"softening"`` drops the default's softening parameters,
    ``buckling = "none"`` the default's Euler load data and ``yield = "none"`` the default's
    ``yield_strength``.  What the member's own table gives is checked as given.

    Examples
    --------
    >>> _merged({"buckling": "cap", "effective_length_factor": 0.7},
    ...         {"buckling": "softening", "critical_load": 1200.0, "residual": 0.3,
    ...          "softening_strain": 0.002})
    {'buckling': 'softening', 'critical_load': 1200.0, 'residual': 0.3, 'softening_strain': 0.002}
    """
    law = dict(default)
    drop = set()
    for k in own:
        drop.update(_SUPERSEDES.get(k, ()))
    if "buckling" in own and own["buckling"] != "softening":
        drop.update(("residual", "softening_strain"))
    if own.get("buckling") == "none":
        drop.update(("critical_load", "effective_length_factor"))
    if own.get("yield") == "none":
        drop.add("yield_strength")
    for k in drop - set(own):
        law.pop(k, None)
    law.update(own)
    return law
