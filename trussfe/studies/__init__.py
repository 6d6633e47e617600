# SPDX-License-Identifier: MIT
"""Computations that follow a source's own conventions: the thesis and paper reproductions.

The solver packages (:mod:`trussfe.rigid`, :mod:`trussfe.response`, :mod:`trussfe.fem`,
:mod:`trussfe.kinematics`, :mod:`trussfe.nonlinear`) compute what a structural engineer
expects; the modules here reproduce published numbers, and where a table needs the source's
own choices (finite-difference rates, whole-length inertia, a node order or load of its own)
they apply them explicitly on top of the catalogue structures of :mod:`trussfe.models`
(:mod:`~trussfe.studies.numbering`), and pass the thesis' computational choices to the solvers
as one frozen object, :data:`trussfe.mechanics.conventions.THESIS`.

Dependencies run one way: a study imports the catalogue and the solvers, never the reverse.

=========================================  =====================================================
:mod:`~trussfe.studies.lacy_rigid`         Lacy ch. 3 and 5: rigid-body model, Tables 3.2–5.4
:mod:`~trussfe.studies.lacy_newton_euler`  Lacy eq. 2.13 / Appendix A, the literal system
:mod:`~trussfe.studies.lacy_actuators`     Lacy sections 3.7, 5.5 and 5.7: gains, slews, motors
:mod:`~trussfe.studies.lacy_elastic`       Lacy sections 3.3, 5.5, Table 5.5: FE along motions
:mod:`~trussfe.studies.transient_slews`    elastic transient response along Lacy's slews
:mod:`~trussfe.studies.modal_buckling`     Lacy Table 3.3 / section 5.8 allowables, modal checks
:mod:`~trussfe.studies.hortobagyi`         Hortobágyi (1999) sections 4 and 6, constructions
:mod:`~trussfe.studies.vlase`              Vlase (2008): four-bar and slider-crank, closed form
:mod:`~trussfe.studies.postcritical`       post-critical checks against closed forms
:mod:`~trussfe.studies.numbering`          a source's node order and member orientation
=========================================  =====================================================

The validation cases (``validation/cases/*.toml``) name these functions in their ``python``
entries; each returns a plain dict of the quantities the case compares.
"""
