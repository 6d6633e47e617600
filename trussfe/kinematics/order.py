# SPDX-License-Identifier: MIT
"""The order of an infinitesimal mechanism (Hortobágyi 1999 §7; Tarnai 1989; Connelly and
Servatius 1994): how many successive compatibility equations a first-order motion satisfies.

A motion of the joints ``x(t) = x₀ + Σ_{p≥1} tᵖ u_p`` keeps every bar length when, for bar i
from joint a to joint b (``d_p = u_pᵇ − u_pᵃ``, ``d₀ = x_b − x_a``, length l_i), every power of
t in ``|d₀ + Σ tᵖ d_p|² − l_i²`` vanishes.  The coefficient of ``tᵖ`` gives the order-p
compatibility equation

    Σ_{j=0..p} d_j·d_{p−j} = 0   ⇔   B u_p = r_p,   (r_p)_i = −(1/(2 l_i)) Σ_{j=1..p−1} d_j·d_{p−j},

with B the compatibility matrix (Hortobágyi eq. 2; ``B u₁ = 0`` at p = 1).  The equation of
order p is solvable exactly when r_p lies in the range of B, i.e. when it is orthogonal to every
state of self-stress ω (``ωᵀ r_p = 0``).  A *k-th order flex* solves the equations of orders
1…k with a non-trivial first-order motion u₁; the **order** of an infinitesimal mechanism is the
largest k for which one exists.  Conventions differ by one in the literature, so precisely:

* order k means: compatible to order k, not to order k + 1 — the bar-length changes of the
  best motion are of order ``t^(k+1)``;
* two collinear bars between two fixed joints (the middle joint's transverse motion) have
  order 1: first-order flexible, second-order rigid in the sense of Connelly and Servatius
  (1994); Tarnai's assemblies of n straight bar pairs have order 2ⁿ − 1
  (:func:`trussfe.models.mechanisms.section7_chain`);
* a finite mechanism is compatible to every order: order infinite (Gáspár and Tarnai 1994:
  finite mechanisms have no higher-order rigidity).

What is computed (:func:`mechanism_order`)
------------------------------------------
The rank analysis (:func:`trussfe.kinematics.rank.rank_analysis`, through
:func:`trussfe.linalg.matrix_rank`) gives m internal infinitesimal mechanisms and s states of
self-stress.  Then

* ``m = 0``: no mechanism, no order (status ``"rigid"``);
* ``s = 0``, ``m ≥ 1``: B has full row rank, every r_p lies in its range, every order is
  solvable — by the implicit-function theorem the assembly is a finite mechanism with m degrees
  of freedom: order infinite (``"finite"``).  The same holds when the only states of
  self-stress are bars between two joints fixed in every direction (zero rows of B, whose
  lengths no motion changes);
* ``m = 1``, ``s ≥ 1``: the series is built order by order from the mechanism shape u₁ with the
  minimum-norm solution u_p = B⁺ r_p; the first order p whose r_p is not in the range of B gives
  the order ``k = p − 1`` (``"infinitesimal"``).  With one mechanism the order does not depend on
  the choices made: any two solutions of order p differ by a null vector of B, i.e. by a
  multiple of u₁ (a reparametrisation ``t → t + c tᵖ``) or a rigid-body motion, and both
  transform a k-th order flex into a k-th order flex.  When no order up to ``max_order`` shows
  an obstruction above round-off the order is undecided (``"undecided"``, ``checked`` the
  orders solved): a finite computation cannot tell a finite mechanism with self-stress
  (Bricard's octahedron) from an infinitesimal one of a higher order, nor an obstruction
  below the round-off of the series from none;
* ``m ≥ 2``, ``s ≥ 1``: the order depends on the first-order motion chosen in the
  m-dimensional space and on the null-space parts chosen at every later order; it is not
  computed (``"several_mechanisms"``).  Remove mechanisms by supports to ask about one of them;
* more than :data:`DENSE_LIMIT` coordinates or bars with ``m = 1``, ``s ≥ 1``: not computed
  (``"too_large"``; the series uses a dense pseudo-inverse).

Tolerance
---------
The geometry is scaled by the longest bar L and u₁ by its largest entry, so every quantity is
dimensionless.  At order p two numbers decide whether r_p leaves the range of B (Ω an
orthonormal basis of the self-stress states, ``(s_p)_i = (1/(2 l_i)) Σ_j |d_j| |d_{p−j}|`` the
size of the terms summed):

* the relative obstruction ``η_p = ‖Ωᵀ r_p‖ / ‖|Ω|ᵀ s_p‖`` — the obstruction against the terms
  of the bars that carry self-stress — must exceed ``tolerance`` (:data:`ORDER_TOLERANCE`), and
* the obstruction must exceed the round-off bound ``c·ε_x·κ(B)·p·‖s_p‖`` (c =
  :data:`ROUNDOFF_FACTOR`, κ(B) the condition number on the range, ``ε_x = ε·max(1,
  max|x|/l_min)`` the accuracy of the member vectors computed from coordinates far from the
  origin): the coefficients of a series grow geometrically with p, and an error of ε_x times
  the largest term is all that floating point can tell from zero.

Entries of u_p (and of Ω) below the same round-off level of their largest entry are set to
zero: they are the smear of the solve over coordinates that do not move at that order, and their
products would otherwise pass for terms of the self-stressed bars.  An order at which the terms
of the self-stressed bars are non-zero but below the round-off bound, or whose obstruction
reaches :data:`SUSPECT` of the bound without exceeding it, may hide an obstruction; a missed one
would leave every later order's series wrong, so from such an order on nothing is decided and
the order is reported undecided, with the orders before it checked: an undecided answer rather
than a wrong one.  On Tarnai's chains (:func:`trussfe.models.mechanisms.section7_chain`) the
order 2ⁿ − 1 is found for n ≤ 6 (orders up to 63); n = 7 is undecided with 127 orders checked
(``max_order`` ≥ 128); on 300 chains with
random bar lengths and angles the order found was 2ⁿ − 1 or undecided.  "Checked" means no
obstruction above round-off: for n = 8 the leading coefficient of the last pair falls below
the round-off of the series and orders beyond 255 pass unobstructed.  The result carries η and
the ratio to the round-off bound at the obstruction, and the largest ratio among the solved
orders (the margin of the decision).  The rank itself is decided by the rank analysis's
relative tolerance.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..mechanics.geometry import member_lengths
from .compatibility import anchored_bar_count, compatibility_matrix
from .rank import RankResult, rank_analysis

#: Relative obstruction above which an order's equation counts as unsolvable.
ORDER_TOLERANCE = 1e-8
#: Default highest order examined.
MAX_ORDER = 64
#: Safety factor on the round-off bound ``ε·κ(B)·p·‖s_p‖`` of an order-p obstruction.
ROUNDOFF_FACTOR = 16.0
#: Fraction of the round-off bound above which an unsolved-looking order is suspect: an
#: obstruction may hide there, and no later order is trusted.
SUSPECT = 1e-2
#: Largest number of free coordinates or bars for which the series is computed (dense
#: pseudo-inverse); larger assemblies with one mechanism and self-stress are not decided.
DENSE_LIMIT = 1500

STATUSES = ("rigid", "finite", "infinitesimal", "undecided", "several_mechanisms",
            "too_large")


@dataclass
class MechanismOrder:
    """Outcome of :func:`mechanism_order`.

    Attributes
    ----------
    order : int, float or None
        k for an infinitesimal mechanism of order k, ``math.inf`` for a finite mechanism,
        None when there is no mechanism or the order is not decided (see ``status``).
    status : str
        One of :data:`STATUSES` (module notes).
    checked : int
        Highest order whose compatibility equation was solved with no obstruction above
        round-off (0 when no series was built).
    max_order : int
        Highest order that would have been examined.
    obstruction : float
        η of the first unsolvable order (``nan`` if none); of order one for a clear
        obstruction.
    above_roundoff : float
        That order's obstruction divided by its round-off bound (``nan`` if none).
    margin : float
        Largest ratio of obstruction to round-off bound among the solved orders (``nan`` if
        none was solved beyond the first): below one by construction, and the smaller, the
        clearer the decision.
    series : ndarray, shape (checked, f)
        Coefficients u₁ … u_checked over the free coordinates, m, for the parameter t that
        moves the largest coordinate of u₁ by the longest bar length L·t.
    note : str
        Why the order is not decided, when it is not.
    """

    order: int | float | None
    status: str
    checked: int
    max_order: int
    obstruction: float = float("nan")
    above_roundoff: float = float("nan")
    margin: float = float("nan")
    series: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    note: str = ""


def _series_terms(U: np.ndarray, conn: np.ndarray, fidx: np.ndarray, shape, p: int,
                  L: np.ndarray):
    """r_p and its size s_p from the stored coefficients ``U[0..p−2]`` = u₁…u_{p−1}.

    Vectorised over bars and over the pairs (j, p − j), j = 1 … p − 1 (Tarnai 1989: the
    order-p compatibility equation of every bar)."""
    n, dim = shape
    k = p - 1
    full = np.zeros((k, n * dim))
    full[:, fidx] = U[:k]
    full = full.reshape(k, n, dim)
    D = full[:, conn[:, 1]] - full[:, conn[:, 0]]          # (k, b, dim): d_1 … d_{p−1}
    dots = np.einsum("jbd,jbd->jb", D, D[::-1])            # d_j · d_{p−j}
    norms = np.linalg.norm(D, axis=2)
    size = np.einsum("jb,jb->b", norms, norms[::-1])
    return -dots.sum(axis=0) / (2.0 * L), size / (2.0 * L)


def mechanism_order(coords: np.ndarray, connectivity: np.ndarray, free: np.ndarray, *,
                    max_order: int = MAX_ORDER, tolerance: float = ORDER_TOLERANCE,
                    rank: RankResult | None = None,
                    rank_tolerance: float | None = None) -> MechanismOrder:
    """Order of the infinitesimal mechanism of a bar-and-joint assembly (module notes).

    Parameters
    ----------
    coords : ndarray, shape (n, dim)
    connectivity : ndarray of int, shape (b, 2)
    free : ndarray of bool, shape (n, dim)
    max_order : int
        Highest order examined (at least 2).
    tolerance : float
        Relative obstruction η above which an order is unsolvable.
    rank : RankResult, optional
        The rank analysis of the same state, when already computed.
    rank_tolerance : float, optional
        Relative singular-value tolerance of the rank analysis (when ``rank`` is not given).

    Returns
    -------
    MechanismOrder

    Examples
    --------
    Two collinear bars between fixed joints: the middle joint's transverse motion is a
    first-order mechanism, second-order rigid (Connelly and Servatius 1994) — order 1.

    >>> x = np.array([[0., 0.], [1., 0.], [2., 0.]])
    >>> free = np.array([[0, 0], [1, 1], [0, 0]], bool)
    >>> r = mechanism_order(x, np.array([[0, 1], [1, 2]]), free)
    >>> r.order, r.status
    (1, 'infinitesimal')

    Bent, the same chain is rigid; with the far joint on a roller along the chain it is a
    finite mechanism (no self-stress):

    >>> bars = np.array([[0, 1], [1, 2]])
    >>> mechanism_order(x + [[0, 0], [0, 0.1], [0, 0]], bars, free).status
    'rigid'
    >>> mechanism_order(x, bars, np.array([[0, 0], [1, 1], [1, 0]], bool)).order
    inf
    """
    x = np.asarray(coords, float)
    conn = np.asarray(connectivity, dtype=np.int64).reshape(-1, 2)
    free = np.asarray(free, bool).reshape(x.shape)
    max_order = int(max_order)
    if max_order < 2:
        raise ValueError(f"max_order must be at least 2, got {max_order}")
    if rank is None:
        rank = rank_analysis(x, conn, free, tolerance=rank_tolerance)
    m, s = rank.mechanisms, rank.self_stress_states
    f = rank.n_coordinates
    if m == 0:
        return MechanismOrder(None, "rigid", 0, max_order,
                              note="no internal infinitesimal mechanism")
    if s == 0:
        return MechanismOrder(math.inf, "finite", 0, max_order,
                              note="no state of self-stress: every order is solvable")
    # A bar whose two joints are fixed in every direction is a zero row of B and its own state
    # of self-stress; no motion changes its length (d_p = 0 at every order, so (r_p)_i = 0), and
    # it can never obstruct an order.  Without other states B has full row rank on the rest:
    # the implicit-function theorem applies as for s = 0 (a four-bar with its ground bar).
    anchored = anchored_bar_count(conn, free)
    if s == anchored:
        return MechanismOrder(math.inf, "finite", 0, max_order,
                              note=f"the only state(s) of self-stress are in the {anchored} "
                                   "bar(s) between fixed joints, which no motion stretches: "
                                   "every order is solvable")
    if m > 1:
        return MechanismOrder(None, "several_mechanisms", 0, max_order,
                              note=f"{m} infinitesimal mechanisms with {s} state(s) of "
                                   "self-stress: the order depends on the first-order motion "
                                   "chosen; add supports to leave one mechanism")
    if max(f, rank.n_bars) > DENSE_LIMIT:
        return MechanismOrder(None, "too_large", 0, max_order,
                              note=f"more than {DENSE_LIMIT} coordinates or bars")
    Lmax = float(member_lengths(x, conn).max())
    xs = x / Lmax                                           # dimensionless geometry
    Ls = member_lengths(xs, conn)
    B = compatibility_matrix(xs, conn, free).toarray()
    # one SVD; the rank decided by the rank analysis splits range and self-stress
    Uo, sv, Vt = np.linalg.svd(B, full_matrices=True)
    rho = rank.rank
    Bp = (Vt[:rho].T / sv[:rho]) @ Uo[:, :rho].T            # pseudo-inverse on the range
    Om = Uo[:, rho:]                                        # orthonormal self-stress basis
    kappa = float(sv[0] / sv[rho - 1]) if rho else 1.0
    # the geometry is known to the round-off of its coordinates: member vectors carry an error
    # of ε·max|x| against bars as short as the shortest, so straight pairs are straight only to
    # that accuracy
    eps = np.finfo(float).eps * max(1.0, float(np.abs(x).max()) / float(Ls.min() * Lmax))
    chop = ROUNDOFF_FACTOR * eps * kappa
    fidx = np.flatnonzero(free.ravel())
    u1 = rank.mechanism_basis[:, 0]
    u1 = u1 / u1[np.argmax(np.abs(u1))]                    # largest entry +1
    u1[np.abs(u1) <= chop] = 0.0
    Om = np.where(np.abs(Om) <= chop, 0.0, Om)              # bars outside the self-stress
    U = np.zeros((max_order, f))
    U[0] = u1
    margin = 0.0
    suspect = 0                 # first order whose obstruction may hide in round-off
    for p in range(2, max_order + 1):
        r, size = _series_terms(U, conn, fidx, x.shape, p, Ls)
        scale = float(np.linalg.norm(size))
        if not np.isfinite(scale) or scale > 1e250:
            return MechanismOrder(None, "undecided", p - 1, max_order, margin=margin,
                                  series=U[:p - 1] * Lmax,
                                  note=f"the series coefficients overflow at order {p}")
        obstruction = float(np.linalg.norm(Om.T @ r))
        local = float(np.linalg.norm(np.abs(Om).T @ size))
        eta = obstruction / local if local > 0 else 0.0
        noise = ROUNDOFF_FACTOR * eps * kappa * p * scale
        ratio = obstruction / noise
        if eta > tolerance and ratio > 1.0:
            if suspect:
                break
            return MechanismOrder(p - 1, "infinitesimal", p - 1, max_order, obstruction=eta,
                                  above_roundoff=ratio,
                                  margin=margin if p > 2 else float("nan"),
                                  series=U[:p - 1] * Lmax)
        if eta > tolerance and ratio > SUSPECT and not suspect:
            suspect = p
        if 0.0 < local <= noise and not suspect:
            suspect = p                 # the self-stressed bars' terms are below round-off
        margin = max(margin, ratio)
        u = Bp @ r
        # entries at round-off level of the largest one are zeros that the solve smeared:
        # left in, their products pass for terms of the self-stressed bars (module notes)
        u[np.abs(u) <= chop * np.abs(u).max(initial=0.0)] = 0.0
        U[p - 1] = u
    if suspect:
        # an obstruction missed at order `suspect` leaves every later order's series wrong
        return MechanismOrder(None, "undecided", suspect - 1, max_order, margin=margin,
                              series=U[:suspect - 1] * Lmax,
                              note=f"round-off hides whether order {suspect} is "
                                   "obstructed")
    return MechanismOrder(None, "undecided", max_order, max_order, margin=margin,
                          series=U * Lmax,
                          note=f"no obstruction above round-off up to order {max_order}: a "
                               "finite mechanism, an infinitesimal one of a higher order, or "
                               "one whose obstruction is below the round-off of the series")
