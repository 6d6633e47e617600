# SPDX-License-Identifier: MIT
"""Settings of the post-critical analysis a model file may carry: the ``[postcritical]`` table.

::

    [postcritical]
    control = "arc-length"        # "load" | "displacement" | "arc-length"
    steps = 200
    step = 0.002                  # first increment (Δλ, Δu or Δs)
    max_step = 0.01               # largest increment the step control may grow to
    max_load_factor = 5.0
    monitor = "3:y"               # node:axis of the displacement plotted and controlled
    bar_model = "truss"           # "truss" | "pinned-beam"
    subdivisions = 8              # default: bar_models.DEFAULT_POSTCRITICAL_SUBDIVISIONS
    imperfection = 0.001          # m, amplitude of the first linear buckling mode
    branch = false                # follow the secondary branch at a bifurcation
    max_displacement = 0.5        # m, stop when the monitored displacement exceeds it

The analysis itself is :func:`trussfe.nonlinear.analysis.run_postcritical`; options given to
it override these settings.
"""
from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any

#: Path-following controls.
CONTROLS = ("load", "displacement", "arc-length")


@dataclass(frozen=True)
class PostcriticalSettings:
    """The ``[postcritical]`` table; ``None`` where the file does not set a value.

    Examples
    --------
    >>> PostcriticalSettings(control="load", steps=20).options()
    {'control': 'load', 'steps': 20}
    """

    control: str | None = None
    steps: int | None = None
    step: float | None = None
    max_step: float | None = None
    max_load_factor: float | None = None
    monitor: str | None = None
    bar_model: str | None = None
    subdivisions: int | None = None
    imperfection: float | None = None
    branch: bool | None = None
    max_displacement: float | None = None

    def options(self) -> dict[str, Any]:
        """The settings given, as keyword options of the analysis."""
        return {f.name: getattr(self, f.name) for f in fields(self)
                if getattr(self, f.name) is not None}


#: Type of each setting, for the reader.
SETTING_TYPES: dict[str, type] = {
    "control": str, "steps": int, "step": float, "max_load_factor": float, "monitor": str,
    "bar_model": str, "subdivisions": int, "imperfection": float, "branch": bool,
    "max_displacement": float, "max_step": float}
