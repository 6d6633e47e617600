# SPDX-License-Identifier: MIT
"""Bennett's spatial four-bar linkage as a bar-and-joint assembly.

The Bennett linkage (Bennett 1903) is the spatial 4R chain that moves with one degree of
freedom although Grübler's count gives −2: four links joined by four revolute joints whose
axes are skew, with opposite links equal, ``a₁ = a₃ = a``, ``a₂ = a₄ = b``, twist angles
``α₁ = α₃ = α``, ``α₂ = α₄ = β`` and ``a / sin α = b / sin β``.

**Geometry.**  Joint k's axis is the z axis of frame F_k; F_{k+1} = F_k T_k with
``T_k = Rot_z(θ_k) Trans_x(a_k) Rot_x(α_k)`` (Denavit–Hartenberg: turn about axis k, go
along the common normal, twist onto axis k+1), F₁ the global frame.  The loop closes,
``T₁ T₂ T₃ T₄ = I``, for every input angle θ₁ with (checked by the tests)

.. math::

   \\theta_2 = 2 \\arctan \\frac{K}{\\tan(\\theta_1/2)}, \\quad \\theta_3 = -\\theta_1,
   \\quad \\theta_4 = -\\theta_2, \\qquad
   K = \\frac{\\sin\\frac{\\beta + \\alpha}{2}}{\\sin\\frac{\\beta - \\alpha}{2}} .

**Bar model.**  Each revolute joint is two spherical joints on its axis, ``A_k`` (the origin
of F_k) and ``B_k = A_k + h z_k``, joined by an axis bar; each link k is rigid, the tetrahedron
of bars between A_k, B_k and A_{k+1}, B_{k+1}.  Nodes A1 B1 A2 B2 A3 B3 A4 B4 (ids "1"–"8");
20 bars: four axis bars and four per link.  Link 4 (axes 4 and 1) is the ground: its four
joints are fixed.  The twelve free coordinates of A2, B2, A3, B3 meet fourteen bars, which
leave one mechanism: the rotation of link 1 about axis 1.  Of the 20 − 11 = 9 states of
self-stress, three are Bennett's overconstraint and six the bars between fixed joints.

The default proportions: a = 1 m, α = 30°, β = 60° (so b = √3 m), h = 0.6 m, θ₁ = 100°.
"""
from __future__ import annotations

import math

import numpy as np

#: Default Bennett linkage: link lengths a (links 1, 3), twists α, β (degrees), axis-bar
#: length h (m), input angle θ₁ (degrees).
BENNETT = {"a": 1.0, "alpha": 30.0, "beta": 60.0, "h": 0.6, "theta1": 100.0}


def bennett_b(a: float = BENNETT["a"], alpha: float = BENNETT["alpha"],
              beta: float = BENNETT["beta"]) -> float:
    """Length of links 2 and 4 from Bennett's condition a / sin α = b / sin β."""
    return a * math.sin(math.radians(beta)) / math.sin(math.radians(alpha))


def bennett_angles(theta1: float, alpha: float = BENNETT["alpha"],
                   beta: float = BENNETT["beta"]) -> np.ndarray:
    """Joint angles (θ₁, θ₂, θ₃, θ₄), rad, of the closed loop for the input θ₁ (rad)."""
    al, be = math.radians(alpha), math.radians(beta)
    K = math.sin((be + al) / 2) / math.sin((be - al) / 2)
    t2 = 2 * math.atan(K / math.tan(theta1 / 2))
    return np.array([theta1, t2, -theta1, -t2])


def bennett_rate(theta1: float, alpha: float = BENNETT["alpha"],
                 beta: float = BENNETT["beta"]) -> float:
    """dθ₂/dθ₁ of the closed form (the derivative of :func:`bennett_angles`)."""
    al, be = math.radians(alpha), math.radians(beta)
    K = math.sin((be + al) / 2) / math.sin((be - al) / 2)
    c = 1.0 / math.tan(theta1 / 2)
    return -K / math.sin(theta1 / 2) ** 2 / (1 + K * K * c * c)


def dh(theta: float, a: float, alpha: float) -> np.ndarray:
    """Homogeneous transform ``Rot_z(θ) Trans_x(a) Rot_x(α)``."""
    c, s = math.cos(theta), math.sin(theta)
    ca, sa = math.cos(alpha), math.sin(alpha)
    return np.array([[c, -s * ca, s * sa, a * c], [s, c * ca, -c * sa, a * s],
                     [0.0, sa, ca, 0.0], [0.0, 0.0, 0.0, 1.0]])


def bennett_frames(theta1: float, a: float = BENNETT["a"], alpha: float = BENNETT["alpha"],
                   beta: float = BENNETT["beta"]) -> np.ndarray:
    """Frames F₁…F₄ and the closing product F₁ T₁ T₂ T₃ T₄ (should be I), (5, 4, 4)."""
    th = bennett_angles(theta1, alpha, beta)
    b = bennett_b(a, alpha, beta)
    lengths = (a, b, a, b)
    twists = [math.radians(t) for t in (alpha, beta, alpha, beta)]
    F = [np.eye(4)]
    for k in range(4):
        F.append(F[-1] @ dh(th[k], lengths[k], twists[k]))
    return np.array(F)


def bennett_linkage(theta1: float | None = None, a: float = BENNETT["a"],
                    alpha: float = BENNETT["alpha"], beta: float = BENNETT["beta"],
                    h: float = BENNETT["h"]) -> tuple[np.ndarray, np.ndarray, list[int]]:
    """Joints, bars and fixed joints of the bar model (module docstring).

    Parameters
    ----------
    theta1 : float, optional
        Input angle, rad (default ``BENNETT["theta1"]``).

    Returns
    -------
    coords : ndarray, shape (8, 3)
        A1 B1 A2 B2 A3 B3 A4 B4.
    bars : ndarray of int, shape (20, 2)
    fixed : list of int
        The ground link's joints A1 B1 A4 B4.
    """
    t1 = math.radians(BENNETT["theta1"]) if theta1 is None else theta1
    F = bennett_frames(t1, a, alpha, beta)[:4]
    A = F[:, :3, 3]
    Z = F[:, :3, 2]
    x = np.empty((8, 3))
    x[0::2] = A
    x[1::2] = A + h * Z
    bars = [(2 * k, 2 * k + 1) for k in range(4)]              # axis bars
    for k in range(4):                                         # link k: axis k → axis k+1
        i, j = 2 * k, 2 * ((k + 1) % 4)
        bars += [(i, j), (i, j + 1), (i + 1, j), (i + 1, j + 1)]
    return x, np.array(bars, dtype=np.int64), [0, 1, 6, 7]


def bennett_toml(theta1: float | None = None) -> str:
    """The default linkage as a trussfe model file (``meshes/mech_bennett.toml``)."""
    x, bars, fixed = bennett_linkage(theta1)
    p = BENNETT
    fmt = "{:.17g}".format
    lines = [
        "# Bennett's spatial four-bar linkage (1903) as a bar-and-joint assembly, built by",
        "# trussfe.models.bennett: links a = 1 m (1, 3) and b = sqrt(3) m (2, 4), twists",
        f"# {p['alpha']:g} and {p['beta']:g} deg (a / sin alpha = b / sin beta), input angle "
        f"theta1 = {p['theta1']:g} deg.",
        "# Each revolute joint k is two joints on its axis, A_k and B_k = A_k + 0.6 m z_k (ids",
        "# 2k-1, 2k), joined by an axis bar; each link is the tetrahedron of bars between its",
        "# two axes.  Link 4 (axes 4 and 1) is the ground.  One mechanism: link 1 turning",
        "# about axis 1 (joints 1-2).",
        "", "[model]", 'name = "mech_bennett"', "dimension = 3", "",
        "[materials.aluminium]", "E = 70.0e9", "G = 26.0e9", "density = 2700.0", "",
        "[sections.tube]", "outer_diameter = 0.02", "inner_diameter = 0.016", "", "[nodes]"]
    lines += [f'"{i + 1}" = [{", ".join(fmt(v) for v in xi)}]' for i, xi in enumerate(x)]
    lines += ["", "[members]"]
    lines += [f'b{k + 1} = {{ nodes = ["{i + 1}", "{j + 1}"], section = "tube", '
              'material = "aluminium" }' for k, (i, j) in enumerate(bars)]
    lines += ["", "[supports]"] + [f'"{i + 1}" = ["x", "y", "z"]' for i in fixed]
    return "\n".join(lines) + "\n"
