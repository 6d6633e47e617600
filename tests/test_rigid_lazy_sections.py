# SPDX-License-Identifier: MIT
"""The section forces and stresses of a simulation are computed on first access
(SimulationResult.sections, .static_sections, .stresses, .static_stresses): they must be the
numbers of trussfe.rigid.sections.section_forces and section_stresses applied to the same
kinematics and nodal forces of the whole motion (Lacy eqs. 2.16-2.25), whatever the blocks of
steps and worker threads; the axial forces computed in simulate (buckling, midpoint force)
are the same numbers."""
from __future__ import annotations

import pickle

import numpy as np
import pytest

from trussfe import threads
from trussfe.mechanics.conventions import THESIS
from trussfe.rigid import simulate as simulate_module
from trussfe.rigid.motion import third_order_motion
from trussfe.rigid.sections import section_forces, section_stresses, section_tension
from trussfe.rigid.simulate import simulate
from trussfe.studies.lacy_rigid import double_octahedral_chain, double_octahedron


def _slew(steps: int):
    s = double_octahedron((1.2289, 1.1079, 1.1079), gravity=-9.81, top_load=46.0)
    m = third_order_motion(s, [1.2289, 1.1079, 1.1079], [1.1079, 1.2289, 1.2289], 2.0, steps)
    return s, m


def _reference(res):
    """Section forces and stresses of the whole motion at once, by the section functions."""
    s, o = res.structure, res.options
    fli = o["full_length_inertia"]
    sf = section_forces(s, res.kinematics, res.forces, res.bodies, o["n_sections"],
                        full_length_inertia=fli)
    ss = section_forces(s, res.kinematics, res.static_forces, res.bodies, o["n_sections"],
                        full_length_inertia=fli, at_rest=True)
    kw = dict(shear_factor=o["shear_factor"], convention=o["stress_form"])
    return sf, ss, section_stresses(s, sf, **kw), section_stresses(s, ss, **kw)


def _assert_same(res, ref):
    sf, ss, st, sts = ref
    for got, want in ((res.sections, sf), (res.static_sections, ss)):
        for name in ("position", "tension", "shear", "moment", "unit"):
            np.testing.assert_array_equal(getattr(got, name), getattr(want, name), err_msg=name)
    for got, want in ((res.stresses, st), (res.static_stresses, sts)):
        for name in ("axial", "shear", "bending", "s1", "s2"):
            np.testing.assert_array_equal(getattr(got, name), getattr(want, name), err_msg=name)


@pytest.mark.parametrize("n_sections", [1, 4, 7])
def test_lazy_sections_equal_the_section_functions_over_blocks(monkeypatch, n_sections):
    """The slew over 1,200 steps in blocks of 100 steps on 2 worker threads: nothing is
    computed before the first access, then the four outputs equal the section functions on
    the whole motion to the last bit; the axial forces of simulate (midpoint, buckling) are
    theirs."""
    monkeypatch.setattr(simulate_module, "CHUNK_ENTRIES", 100 * 18)
    s, m = _slew(1200)
    with threads.compute_threads(workers=2, blas=None):
        res = simulate(s, m, n_sections=n_sections)
        assert not res._sections.evaluated
        ref = _reference(res)
        _assert_same(res, ref)
    assert res._sections.evaluated
    assert res.sections.tension is res.section_tension
    np.testing.assert_array_equal(res.section_tension, ref[0].tension)
    mid = section_tension(s, res.kinematics, res.forces, res.bodies, 1)[:, :, 0]
    np.testing.assert_array_equal(res.midpoint_axial_force, mid)
    comp = np.maximum((-ref[0].tension).max(axis=(0, 2)), 0.0)
    np.testing.assert_array_equal(res.buckling.max_compression, comp)


def test_lazy_sections_of_a_chain_and_of_the_thesis_scheme():
    """A 3-bay chain bay by bay (blocked kinematics path) and the slew with Lacy's
    backward-difference scheme (one block): the same numbers as the section functions."""
    c = double_octahedral_chain(3, gravity=9.81, top_load=46.0)
    acts = [a.member for a in c.extensions["active_members"]]
    L0 = c.lengths()[acts]
    L1 = L0.copy()
    L1[0::3] += 0.02 * (-1.0) ** np.arange(3)
    res = simulate(c, third_order_motion(c, L0, L1, 2.0, 300), n_sections=3)
    _assert_same(res, _reference(res))
    s, m = _slew(200)
    res = simulate(s, m, conventions=THESIS, n_sections=7)
    _assert_same(res, _reference(res))


def test_pickled_result_carries_the_outputs():
    """A pickled result (e.g. sent between processes) carries the evaluated outputs."""
    s, m = _slew(150)
    res = simulate(s, m, n_sections=3)
    back = pickle.loads(pickle.dumps(res))
    assert back._sections.evaluated
    np.testing.assert_array_equal(back.stresses.von_mises, res.stresses.von_mises)
    np.testing.assert_array_equal(back.static_sections.moment, res.static_sections.moment)
