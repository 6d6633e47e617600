# SPDX-License-Identifier: MIT
"""Member failure laws: Euler buckling, yield of the section, fracture at a strain.

The laws act on bar members (co-rotational truss elements) and are given in the model file's
``[failure]`` table; :mod:`trussfe.model.failure` shows its format and holds the data.

Force–strain laws (``ε`` engineering strain, ``ε_p`` plastic strain, ``N_e = EA(ε − ε_p)``):

* buckling ``cap``: ``N = max(N_e, −P_cr)`` — the elastic strut after buckling carries P_cr
  while it shortens (the elastica is flat to first order at the bifurcation);
  ``softening``: beyond ``ε_cr = −P_cr/EA`` the compression drops linearly to ``residual·P_cr``
  over ``softening_strain`` and stays there; ``remove``: the bar is removed when ``N_e``
  reaches ``−P_cr``.  The buckling laws are elastic (path independent): an unloading strut
  retraces the curve, as an elastic strut does.
* yield ``cap``: elastic–perfectly plastic with a committed plastic strain; ``remove``: removed
  when ``|N| = A f_y``.  With a yield ``cap`` below the Euler load (``A f_y < P_cr``) the strut
  yields in compression before it can buckle, and its elastic force ``N_e`` never reaches
  ``−P_cr`` afterwards: its buckling law never acts (:func:`buckling_acts`).
* fracture: removed when ``ε`` reaches ``fracture_strain``.
"""
from __future__ import annotations

import numpy as np

from ..io.failure_laws import build_failure_laws
from ..model.failure import BUCKLING, YIELD, FailureLaws

__all__ = ["BUCKLING", "YIELD", "FailureLaws", "axial_law", "buckling_acts",
           "build_failure_laws", "failure_margins"]


def buckling_acts(laws: FailureLaws) -> np.ndarray:
    """Elements whose buckling law can act, shape (element,).

    A yield ``cap`` keeps ``|N_e| = |EA(ε − ε_p)| ≤ A f_y`` along the path, so a strut whose
    yield force is below its Euler load yields in compression and never reaches ``−P_cr``:
    its buckling law is pre-empted, however large the step that crosses both limits.
    """
    return (laws.buckling > 0) & ~((laws.yield_mode == 1)
                                   & (laws.yield_force < laws.critical_load))


def axial_law(laws: FailureLaws, EA: np.ndarray, strain: np.ndarray,
              plastic: np.ndarray):
    """Axial force and its strain derivative under the failure laws (vectorised).

    Parameters
    ----------
    laws : FailureLaws
        Laws of the elements (one per element, shape (element,)).
    EA : ndarray, shape (element,)
    strain, plastic : ndarray, shape (element,)
        Total engineering strain and committed plastic strain.

    Returns
    -------
    N, dNde : ndarray, shape (element,)
    trial : ndarray, shape (element,)
        Elastic trial force ``EA (ε − ε_p)``.
    N_buckling : ndarray, shape (element,)
        Force after the buckling law alone (before the yield cap).

    Examples
    --------
    >>> laws = FailureLaws(buckling=[1, 1, 1], critical_load=[10.0] * 3, residual=[1.0] * 3,
    ...                    softening_strain=[1.0] * 3, yield_mode=[0] * 3,
    ...                    yield_force=[np.inf] * 3, fracture_strain=[np.inf] * 3)
    >>> N, k, _, _ = axial_law(laws, np.full(3, 1000.), np.array([-0.02, -0.005, 0.01]),
    ...                        np.zeros(3))
    >>> N, k
    (array([-10.,  -5.,  10.]), array([   0., 1000., 1000.]))
    """
    trial = EA * (strain - plastic)
    N = trial.copy()
    k = EA.copy()
    Pcr = laws.critical_load
    acts = buckling_acts(laws)
    cap = acts & (laws.buckling == 1) & (trial < -Pcr)
    N[cap] = -Pcr[cap]
    k[cap] = 0.0
    soft = acts & (laws.buckling == 2) & (trial < -Pcr)
    if soft.any():
        es = laws.softening_strain[soft]
        over = (-Pcr[soft] - trial[soft]) / EA[soft]              # extra shortening >= 0
        frac = np.minimum(over / es, 1.0)
        r = laws.residual[soft]
        N[soft] = -Pcr[soft] * (1.0 - (1.0 - r) * frac)
        # dN/dε: compression falls as ε decreases, so the slope is negative on the ramp
        k[soft] = np.where(over < es, -Pcr[soft] * (1.0 - r) / es, 0.0)
    Nb = N.copy()
    Ny = laws.yield_force
    yl = (laws.yield_mode == 1) & (np.abs(N) > Ny)
    N[yl] = np.sign(N[yl]) * Ny[yl]
    k[yl] = 0.0
    return N, k, trial, Nb


def failure_margins(laws: FailureLaws, trial: np.ndarray, N_buckling: np.ndarray,
                    strain: np.ndarray):
    """Distance of each element from each failure event (≥ 0: reached).

    Returns
    -------
    ndarray, shape (3, element)
        Rows: buckling ``−N_e/P_cr − 1``, yield ``|N_b|/(A f_y) − 1``, fracture
        ``ε/ε_f − 1``; ``−inf`` where the law is absent or cannot act
        (:func:`buckling_acts`).
    """
    out = np.full((3, trial.shape[0]), -np.inf)
    b = buckling_acts(laws)
    out[0, b] = -trial[b] / laws.critical_load[b] - 1.0
    y = laws.yield_mode > 0
    out[1, y] = np.abs(N_buckling[y]) / laws.yield_force[y] - 1.0
    f = np.isfinite(laws.fracture_strain)
    out[2, f] = strain[f] / laws.fracture_strain[f] - 1.0
    return out
