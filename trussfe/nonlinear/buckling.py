# SPDX-License-Identifier: MIT
"""Linear buckling of the co-rotational model and geometric imperfections from its modes.

The linear buckling problem about the linear static state under the reference load,

.. math:: (K + \\lambda K_g(N_0))\\,\\varphi = 0,

uses the tangent of the co-rotational elements at the reference geometry: ``K`` with zero
forces and ``Kg(N0)`` the change made by the linear axial forces ``N0``.  Its first load factor
is the one at which the nonlinear path of a perfect structure meets its first bifurcation
(up to the pre-buckling shortening).

It is the FE core's eigenproblem (:func:`trussfe.fem.buckling.solve_buckling`, ``K + λ K_g``
about the linear static state): the co-rotational tangent at the reference geometry is
``K + K_g(N)`` element by element, and the load factors agree to round-off
(tests/test_buckling_models_agree.py, tests/test_releases.py).  It is solved here on the
co-rotational model's own DOFs because its modes become the imperfect reference geometry of
that model (:func:`apply_imperfection`), including the points inside members.
"""
from __future__ import annotations

import numpy as np
from ..errors import AnalysisError
from ..linalg import SingularMatrixError, factor
from ..linalg.eigen import EigenNotConverged, buckling_pairs
from .model import NonlinearModel
from .path import UNSOLVABLE_START


def linear_buckling(model: NonlinearModel, count: int = 1):
    """Lowest positive linear buckling load factors and their modes.

    Parameters
    ----------
    model : NonlinearModel
    count : int

    Returns
    -------
    load_factors : ndarray, shape (count,)
        Ascending positive load factors λ.
    modes : ndarray, shape (dof, count)
        Mode shapes (all DOFs, zero on supports), scaled to a largest translation of 1.
    """
    free = np.flatnonzero(model.free)
    K = model.reference_tangent()[free][:, free]
    item = model.structure.source or model.structure.name
    lu = factor(K, "spd", singular="flag")
    # stiffnesses below the smallest normal number over the machine epsilon leave no
    # resolvable pivot: singular by magnitude (E or the section), not by a mechanism
    too_small = K.shape[0] > 0 and abs(K).max() < np.finfo(float).tiny / np.finfo(float).eps
    if lu.is_singular:
        raise AnalysisError(item, UNSOLVABLE_START if too_small else
                            "the structure is a mechanism: no linear buckling analysis")
    u0 = np.zeros(model.ndof)
    try:
        u0[free] = lu.solve(model.load[free])
    except SingularMatrixError:
        # the pivots passed but the solve overflowed: the same loss of magnitude
        raise AnalysisError(item, UNSOLVABLE_START) from None
    Nt, Nb = model.linear_axial_forces(u0)
    Kg = model.reference_tangent(Nt, Nb)[free][:, free] - K
    try:
        mu, vec = buckling_pairs(K, Kg, count, positive_only=True)
    except EigenNotConverged as err:
        raise AnalysisError(item, str(err)) from None
    if not mu.size:
        raise AnalysisError(model.structure.source or model.structure.name,
                            "no positive buckling load factor: the load puts no member in "
                            "compression")
    lam = 1.0 / mu
    modes = np.zeros((model.ndof, len(lam)))
    modes[free] = vec
    tr = model.n_points * model.dim
    modes /= np.abs(modes[:tr]).max(axis=0)
    return lam, modes


def apply_imperfection(model: NonlinearModel, shape: np.ndarray, amplitude: float) -> None:
    """Make the reference geometry imperfect: points moved by ``amplitude · shape``.

    The imperfect geometry is stress-free (an initially crooked member), as in a physical
    imperfection.  ``shape`` is a DOF vector (e.g. a buckling mode); its translations are scaled
    so that the largest point displacement (its length, whatever its direction) is
    ``amplitude`` (m).
    """
    tr = model.n_points * model.dim
    d = shape[:tr].reshape(-1, model.dim)
    model.X = model.X + amplitude * d / np.linalg.norm(d, axis=1).max()
    model.__dict__.pop("_t_len0", None)
