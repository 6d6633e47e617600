# SPDX-License-Identifier: MIT
"""trussfe — structural analysis of adaptive trusses and bar-and-joint mechanisms.

One :class:`Structure` is read by three solver families: kinematics and mechanisms
(:mod:`trussfe.kinematics`), the rigid-body dynamic force model (:mod:`trussfe.rigid`) and
finite elements (:mod:`trussfe.fem`).
"""
from importlib.metadata import PackageNotFoundError, version as _version

try:
    __version__ = _version("trussfe")
except PackageNotFoundError:  # running from a source tree
    __version__ = "0.0.0+unknown"

from .errors import AnalysisError, InputError, MechanismError, TrussfeError  # noqa: E402
from .io.model_file import read_model  # noqa: E402
from .model.sections import Material, Section  # noqa: E402
from .model.structure import Structure, build_structure  # noqa: E402

__all__ = ["AnalysisError", "InputError", "MechanismError", "TrussfeError", "Material",
           "Section", "Structure", "build_structure", "read_model", "__version__"]
