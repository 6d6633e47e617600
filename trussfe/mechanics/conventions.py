# SPDX-License-Identifier: MIT
"""The choices where a source's computation departs from the physical model, in one object.

The solvers compute what a structural engineer expects (:data:`PHYSICAL`).  Lacy's thesis
(Appendix A's MATLAB listing) makes a few other choices; its published tables reproduce only
with them, so the solvers accept them — all together, as one frozen :class:`Conventions` —
and the studies (:mod:`trussfe.studies`) pass :data:`THESIS`:

=============================  ==================================  ==============================
field                          physical (default)                  Lacy, Appendix A
=============================  ==================================  ==============================
``finite_difference_rates``    exact rates from the compatibility  backward differences of the
                               equations (Lacy eqs. 2.3–2.8        member angles, zero at the
                               differentiated)                     first step
``full_length_inertia``        each piece's own length in its      the whole tube length in every
                               section inertia                     piece's section inertia
``shear_factor``               3: von Mises at S1, eq. 2.24        the code uses 1; the
                                                                   reproductions use eq. 2.24
``settling_constant``          6: ωn = 6/(ζ ts), as coded          6 (the text's 4/(ζ ωn) gives
                                                                   0.83 m/s, not the published
                                                                   1.2477 m/s)
=============================  ==================================  ==============================

The settling constant is the one thesis value kept as the physical default too: the actuator
model is the thesis' own, and only the coded value matches its published response.
:data:`THESIS` holds the choices the thesis' published tables need; its per-axis stress form
is selected on its own (``Conventions(stress_form="lacy-per-axis")``, for the components of its
Fig. 5.12), since the tables' von Mises stresses reproduce with the combined form.

Which torque model describes an actuator (the signed, geared eqs. 2.36–2.44, or Appendix C's
magnitudes without the gearhead ratio on the leadscrew torque) is not a run-wide choice but
part of that actuator's data (``[actuators.ID] convention``, :mod:`trussfe.model.actuators`):
one model may hold actuators documented either way.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Conventions:
    """How the solvers compute where a source departs from the physical model.

    Attributes
    ----------
    finite_difference_rates : bool
        Member angular rates and accelerations by Lacy's backward differences (Appendix A)
        instead of the exact compatibility equations.
    full_length_inertia : bool
        Whole tube length in every piece's moment of inertia (Appendix A) instead of the
        piece's own length.
    shear_factor : float
        Factor k of τ² in S1 = √(σ² + k τ²) (eq. 2.24: 3, von Mises).
    settling_constant : float
        c in the actuator model's natural frequency ωn = c / (ζ ts) (Appendix A: 6).
    stress_form : {"combined", "lacy-per-axis"}
        The von Mises form of the rigid-body model's section stresses
        (:func:`trussfe.mechanics.stress.von_mises`'s ``convention``).

    Examples
    --------
    >>> THESIS.kinematics, PHYSICAL.kinematics
    ('thesis', 'exact')
    >>> Conventions.from_scheme("thesis") == THESIS
    True
    """

    finite_difference_rates: bool = False
    full_length_inertia: bool = False
    shear_factor: float = 3.0
    settling_constant: float = 6.0
    stress_form: str = "combined"

    @property
    def kinematics(self) -> str:
        """The kinematics scheme's name: ``"thesis"`` (finite differences) or ``"exact"``."""
        return "thesis" if self.finite_difference_rates else "exact"

    @classmethod
    def from_scheme(cls, scheme: str) -> "Conventions":
        """:data:`THESIS` for ``"thesis"``, :data:`PHYSICAL` for ``"exact"`` (the CLI's
        ``--scheme``)."""
        if scheme == "thesis":
            return THESIS
        if scheme == "exact":
            return PHYSICAL
        raise ValueError(f"unknown kinematics scheme {scheme!r}; use 'exact' or 'thesis'")


#: What a structural engineer expects: exact kinematics, each piece's own inertia, von Mises.
PHYSICAL = Conventions()
#: Lacy's Appendix A: backward-difference rates and whole-length section inertia.
THESIS = Conventions(finite_difference_rates=True, full_length_inertia=True)
