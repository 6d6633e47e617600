# SPDX-License-Identifier: MIT
"""trussfe — structural analysis of adaptive trusses and bar-and-joint mechanisms.

One :class:`Structure` is read by three solver families: kinematics and mechanisms
(:mod:`trussfe.kinematics`), the rigid-body dynamic force model (:mod:`trussfe.rigid`) and
finite elements (:mod:`trussfe.fem`).  The Python API (:mod:`trussfe.api`, docs/python.md)
has one function per analysis, available here::

    import trussfe
    model = trussfe.read_model("meshes/triangular_truss_static.toml")
    result = trussfe.static(model)          # result.axial_force, result.to_dict(), ...

``static``, ``modes``, ``buckling``, ``simulate``, ``actuators``, ``elastic``, ``transient``,
``mechanism``, ``trace``, ``topology``, ``postcritical``, ``read_model``,
``model_from_dict``, ``validate`` (:mod:`trussfe.validation`) and ``study``
(:mod:`trussfe.parametric`) are imported on first use, so that ``import trussfe`` stays light;
so is ``show``, which draws a model (and its static results) to a PNG.  A call that does not
match a function of :mod:`trussfe.api` (an unknown option, a model of the wrong type) raises
:class:`InputError` naming the argument (also a :class:`TypeError`).
"""
from ._version import __version__   # the one place the version is written (pyproject reads it)
from .errors import AnalysisError, InputError, MechanismError, TrussfeError
from .model.sections import Material, Section
from .model.structure import Structure, build_structure

#: Functions of the Python API, imported from :mod:`trussfe.api` on first use.
_API = ("static", "modes", "buckling", "simulate", "actuators", "elastic", "transient",
        "mechanism", "trace", "topology", "postcritical", "model_from_dict", "read_model",
        "show")

__all__ = ["AnalysisError", "InputError", "MechanismError", "TrussfeError", "Material",
           "Section", "Structure", "build_structure", "__version__", *_API, "validate",
           "study"]


def __getattr__(name: str):
    if name in _API:
        from . import api
        return getattr(api, name)
    if name == "validate":
        from .validation.run import validate
        return validate
    if name == "study":
        from .parametric import study
        return study
    raise AttributeError(f"module 'trussfe' has no attribute '{name}'")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
