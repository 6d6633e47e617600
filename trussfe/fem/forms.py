# SPDX-License-Identifier: MIT
"""Weak forms of the member fields, written as scikit-fem forms.

Every member (or sub-element of a member) lives on its own local axis ``0 <= x <= h``.  The
fields on that axis are

=====  ==========================  ===========================
field  meaning                     element
=====  ==========================  ===========================
u      axial displacement          ``ElementLineP1``
v      deflection in local x–y     ``ElementLineHermite`` (θz = v')
w      deflection in local x–z     ``ElementLineHermite`` (θy = −w')
θ      twist about local x         ``ElementLineP1``
=====  ==========================  ===========================

Truss bars carry only ``u`` in stiffness; their transverse translations are ``ElementLineP1``
fields used by the mass and geometric-stiffness forms.

Coefficients are passed per element and quadrature point, arrays of shape
``(n_elements, n_quadrature_points)``, named as in the forms (``EA``, ``EI``, ``GJ``, ``rhoA``,
``N``, ``q``).
"""
from __future__ import annotations

from skfem import BilinearForm, LinearForm
from skfem.helpers import dd, grad


@BilinearForm
def axial_stiffness(u, v, w):
    r"""Axial (and torsional) stiffness :math:`\int EA\,u'\,v'\,dx`.

    Used with ``EA`` = E·A for the axial field and ``EA`` = G·J for the twist field.

    Examples
    --------
    One element of length 2 with EA = 1 gives 1/2 [[1, -1], [-1, 1]]:

    >>> import numpy as np
    >>> from skfem import MeshLine1, Basis, ElementLineP1, asm
    >>> basis = Basis(MeshLine1(np.array([[0.0, 2.0]]), np.array([[0], [1]])), ElementLineP1())
    >>> asm(axial_stiffness, basis, EA=np.ones((1, basis.X.shape[-1]))).toarray()
    array([[ 0.5, -0.5],
           [-0.5,  0.5]])
    """
    return w["EA"] * grad(u)[0] * grad(v)[0]


@BilinearForm
def bending_stiffness(u, v, w):
    r"""Euler–Bernoulli bending stiffness :math:`\int EI\,u''\,v''\,dx` (Hermite field)."""
    return w["EI"] * dd(u)[0, 0] * dd(v)[0, 0]


@BilinearForm
def mass(u, v, w):
    r"""Consistent mass :math:`\int \rho A\,u\,v\,dx` (``rhoA``; ρI_p, I_p = Iy + Iz, for the twist field)."""
    return w["rhoA"] * u * v


@BilinearForm
def geometric_stiffness(u, v, w):
    r"""Geometric stiffness :math:`\int N\,u'\,v'\,dx` of a transverse field.

    N is the axial force, positive in tension.  On a P1 field it gives N/h [[1, -1], [-1, 1]],
    i.e. the bar's N/L (I − e eᵀ); on a Hermite field the classical beam-column matrix.
    """
    return w["N"] * grad(u)[0] * grad(v)[0]


@LinearForm
def distributed_load(v, w):
    r"""Distributed load :math:`\int q\,v\,dx` (``q`` in N/m along the field's direction)."""
    return w["q"] * v
