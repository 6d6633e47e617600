# SPDX-License-Identifier: MIT
"""The runs of a study: the grid (every combination of the grid parameters, the last one
varying fastest) times ``samples`` Monte Carlo draws.

Run ``r`` is grid point ``r // samples``, draw ``r % samples``.  Its random values come from
``numpy.random.default_rng(SeedSequence(seed, spawn_key=(r,)))`` — the ``r``-th child of
``SeedSequence(seed).spawn`` — drawn in the order the parameters are written, so a run's
values depend on the seed and its id only: not on the number of workers, nor on the order in
which runs finish, nor on whether the study was interrupted and resumed.
"""
from __future__ import annotations

import itertools

import numpy as np

from .spec import Study


def run_rng(seed: int, run_id: int) -> np.random.Generator:
    """The random generator of one run."""
    return np.random.default_rng(np.random.SeedSequence(seed, spawn_key=(int(run_id),)))


def design(study: Study) -> list[tuple[int, int, int, dict]]:
    """Every run as ``(run_id, grid_point, sample, {parameter: value})``, by run id."""
    grid = study.grid
    points = list(itertools.product(*(p.values for p in grid))) if grid else [()]
    runs = []
    rid = 0
    for g, point in enumerate(points):
        fixed = dict(zip((p.name for p in grid), point))
        for s in range(study.samples):
            values = {}
            rng = run_rng(study.seed, rid) if study.random else None
            for p in study.parameters:          # file order: the order of the draws
                values[p.name] = fixed[p.name] if p.is_grid else p.draw(rng)
            runs.append((rid, g, s, values))
            rid += 1
    return runs
