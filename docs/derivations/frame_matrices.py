# SPDX-License-Identifier: MIT
"""Symbolic derivation of the 12×12 space-frame element matrices that
``trussfe.fem.forms`` assembles numerically.

Run ``python docs/derivations/frame_matrices.py`` to print them.  The DOF order is
``u1 v1 w1 θx1 θy1 θz1 u2 v2 w2 θx2 θy2 θz2`` in member axes, with θz = v' and θy = −w'
(right-hand rotations about the local axes).

Shape functions
---------------
* axial u and twist θ: linear, N = [1 − ξ, ξ], ξ = x/L;
* bending v (x–y plane): cubic Hermite H = [1 − 3ξ² + 2ξ³, L(ξ − 2ξ² + ξ³), 3ξ² − 2ξ³,
  L(−ξ² + ξ³)] on [v1, θz1, v2, θz2];
* bending w (x–z plane): the same H on [w1, −θy1, w2, −θy2].

Matrices (Euler–Bernoulli, no shear deformation, no rotary inertia)
-------------------------------------------------------------------
K  = ∫ EA N'ᵀN' + GJ N'ᵀN' + EIz H''ᵀH'' + EIy H''ᵀH'' dx
M  = ∫ ρA (NᵀN + HᵀH + HᵀH) + ρI_p NᵀN dx   (I_p = Iy + Iz)
Kg = ∫ N_axial (H'ᵀH' + H'ᵀH') dx
"""
from __future__ import annotations

import numpy as np
import sympy as sy

x, L = sy.symbols("x L", positive=True)
E, G, A, Iy, Iz, J, rho, Nax = sy.symbols("E G A I_y I_z J rho N", real=True)


def shape_functions():
    """Linear and Hermite shape functions on [0, L]."""
    xi = x / L
    lin = sy.Matrix([1 - xi, xi])
    herm = sy.Matrix([1 - 3 * xi**2 + 2 * xi**3, L * (xi - 2 * xi**2 + xi**3),
                      3 * xi**2 - 2 * xi**3, L * (-xi**2 + xi**3)])
    return lin, herm


def _place(target, block, dofs, signs=None):
    signs = signs or [1] * len(dofs)
    for a, (i, si) in enumerate(zip(dofs, signs)):
        for b, (j, sj) in enumerate(zip(dofs, signs)):
            target[i, j] += si * sj * block[a, b]


def derive():
    """Symbolic K, M, Kg (12×12 sympy matrices)."""
    lin, herm = shape_functions()

    def integ(expr):
        return expr.applyfunc(lambda e: sy.integrate(sy.expand(e), (x, 0, L)))

    d1 = lambda f: f.diff(x)           # noqa: E731
    d2 = lambda f: f.diff(x, 2)        # noqa: E731
    kl = integ(d1(lin) * d1(lin).T)
    kb = integ(d2(herm) * d2(herm).T)
    ml = integ(lin * lin.T)
    mb = integ(herm * herm.T)
    gb = integ(d1(herm) * d1(herm).T)
    K, M, Kg = (sy.zeros(12, 12) for _ in range(3))
    ax, tw = [0, 6], [3, 9]
    pv, pw, sw = [1, 5, 7, 11], [2, 4, 8, 10], [1, -1, 1, -1]
    _place(K, E * A * kl, ax)
    _place(K, G * J * kl, tw)
    _place(K, E * Iz * kb, pv)
    _place(K, E * Iy * kb, pw, sw)
    _place(M, rho * A * ml, ax)
    _place(M, rho * (Iy + Iz) * ml, tw)          # the polar moment of area turns
    _place(M, rho * A * mb, pv)
    _place(M, rho * A * mb, pw, sw)
    _place(Kg, Nax * gb, pv)
    _place(Kg, Nax * gb, pw, sw)
    return K, M, Kg


def numeric(values: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """K, M, Kg evaluated for ``values`` = {"L":…, "E":…, "G":…, "A":…, "Iy":…, "Iz":…,
    "J":…, "rho":…, "N":…}."""
    subs = {L: values["L"], E: values["E"], G: values["G"], A: values["A"],
            Iy: values["Iy"], Iz: values["Iz"], J: values["J"], rho: values["rho"],
            Nax: values["N"]}
    return tuple(np.array(m.subs(subs), dtype=float) for m in derive())


if __name__ == "__main__":
    for name, mat in zip(("K", "M", "Kg"), derive()):
        print(f"{name} =")
        sy.pprint(sy.simplify(mat), wrap_line=False)
