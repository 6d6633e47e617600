# SPDX-License-Identifier: MIT
"""Elastic response of an adaptive truss along a prescribed large motion.

The rigid-body model (:mod:`trussfe.rigid`) gives the kinematics of every member along a
maneuver; this package loads the finite-element model (:mod:`trussfe.fem`) in the current
configuration with gravity and the d'Alembert inertial loads of that motion: quasi-statically
(member section forces compared with the rigid-body internal forces, member strains) and
dynamically (the elastic vibration superposed on the prescribed motion).
"""
import sys as _sys
import types as _types


class _CallablePackage(_types.ModuleType):
    """This package, callable as the analysis of the same name: ``trussfe.elastic(...)`` is
    :func:`trussfe.api.elastic`, while ``trussfe.elastic.<module>`` stays the package's."""

    def __call__(self, *args, **kwargs):
        from ..api import elastic as analysis
        return analysis(*args, **kwargs)

    @property
    def __signature__(self):
        """The analysis's signature (for ``inspect.signature`` and ``help``)."""
        import inspect

        from ..api import elastic as analysis
        return inspect.signature(analysis)


_sys.modules[__name__].__class__ = _CallablePackage
