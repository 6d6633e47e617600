# SPDX-License-Identifier: MIT
"""Large test structures for the benchmarks, built vectorised."""
from __future__ import annotations

import numpy as np

from trussfe.model.sections import Material, Section
from trussfe.model.structure import Structure

ALUMINIUM = Material("aluminium", E=71.0e9, G=26.2e9, density=2711.5)
TUBE = Section.tube("tube", 0.01905, 0.016)


def space_grid(nx: int, ny: int | None = None, spacing: float = 1.0, depth: float = 0.7071,
               load: float = -1000.0) -> Structure:
    """Square-on-square double-layer space grid (statically indeterminate).

    Top layer (nx+1)×(ny+1) nodes, bottom layer nx×ny nodes at the cell centres, ``depth``
    below; top chords, bottom chords between adjacent bottom nodes, and four diagonals from
    each bottom node to the corners of its cell.  The four corner top nodes are pinned (x, y, z)
    and every top node carries ``load`` in z.
    """
    ny = nx if ny is None else ny
    ix, iy = np.meshgrid(np.arange(nx + 1), np.arange(ny + 1), indexing="ij")
    top = np.column_stack([ix.ravel() * spacing, iy.ravel() * spacing,
                           np.zeros(ix.size)])
    bx, by = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    bot = np.column_stack([(bx.ravel() + 0.5) * spacing, (by.ravel() + 0.5) * spacing,
                           np.full(bx.size, -depth)])
    coords = np.vstack([top, bot])
    tid = lambda i, j: i * (ny + 1) + j  # noqa: E731
    bid = lambda i, j: (nx + 1) * (ny + 1) + i * ny + j  # noqa: E731
    members = []
    i, j = np.meshgrid(np.arange(nx), np.arange(ny + 1), indexing="ij")
    members.append(np.column_stack([tid(i, j).ravel(), tid(i + 1, j).ravel()]))
    i, j = np.meshgrid(np.arange(nx + 1), np.arange(ny), indexing="ij")
    members.append(np.column_stack([tid(i, j).ravel(), tid(i, j + 1).ravel()]))
    i, j = np.meshgrid(np.arange(nx - 1), np.arange(ny), indexing="ij")
    members.append(np.column_stack([bid(i, j).ravel(), bid(i + 1, j).ravel()]))
    i, j = np.meshgrid(np.arange(nx), np.arange(ny - 1), indexing="ij")
    members.append(np.column_stack([bid(i, j).ravel(), bid(i, j + 1).ravel()]))
    i, j = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    b = bid(i, j).ravel()
    for di, dj in ((0, 0), (1, 0), (0, 1), (1, 1)):
        members.append(np.column_stack([b, tid(i + di, j + dj).ravel()]))
    conn = np.vstack(members)
    n, m = coords.shape[0], conn.shape[0]
    supports = np.zeros((n, 6), dtype=bool)
    for c in (tid(0, 0), tid(nx, 0), tid(0, ny), tid(nx, ny)):
        supports[c, :3] = True
    # two in-plane restraints more would be enough; pin the four corners fully (indeterminate)
    loads = np.zeros((n, 6))
    loads[: top.shape[0], 2] = load
    return Structure(
        name=f"space grid {nx}x{ny}", dim=3, node_ids=[str(k) for k in range(n)],
        coords=coords, member_ids=[str(k) for k in range(m)], connectivity=conn,
        sections=[TUBE] * m, materials=[ALUMINIUM] * m, is_beam=np.zeros(m, bool),
        releases=np.zeros((m, 2), bool), supports=supports, loads=loads, masses=np.zeros(n),
        gravity=np.zeros(3))
