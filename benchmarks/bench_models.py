# SPDX-License-Identifier: MIT
"""Time to build, write and read double-octahedral chains (model catalogue and model I/O).

Usage: ``python benchmarks/bench_models.py [--max-bays 100000]``.  "build slewed": every bay
at its own random active lengths in the prototype's stroke.  Prints a table; nothing is
asserted (speed targets are read off here, not enforced by tests).
"""
from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from trussfe.io.model_file import read_model  # noqa: E402
from trussfe.io.model_writer import write_model  # noqa: E402
from trussfe.models import double_octahedral_chain  # noqa: E402



def _best(fn, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--max-bays", type=int, default=100_000)
    ap.add_argument("--repeat", type=int, default=3, help="best of N runs")
    args = ap.parse_args()
    sizes = [n for n in (10, 100, 1_000, 10_000, 100_000) if n <= args.max_bays]
    print(f"{'bays':>8} {'members':>9} {'build s':>9} {'build slewed s':>15} {'write mesh s':>13} "
          f"{'read mesh s':>12} {'write TOML s':>13} {'read TOML s':>12}")
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        for n in sizes:
            t_build = _best(lambda: double_octahedral_chain(n), args.repeat)
            s = double_octahedral_chain(n)
            act = np.random.default_rng(0).uniform(1.1079, 1.2289, (n, 3))
            t_slew = _best(lambda: double_octahedral_chain(n, active_lengths=act), args.repeat)
            t_wm = _best(lambda: write_model(s, d / "m.toml", mesh="m.vtu"), args.repeat)
            t_rm = _best(lambda: read_model(d / "m.toml"), args.repeat)
            if n <= 1_000:   # TOML tables are for readable models; large ones use a mesh
                t_wt = _best(lambda: write_model(s, d / "t.toml"), args.repeat)
                t_rt = _best(lambda: read_model(d / "t.toml"), args.repeat)
                toml = f"{t_wt:13.4f} {t_rt:12.4f}"
            else:
                toml = f"{'–':>13} {'–':>12}"
            print(f"{n:8d} {s.n_members:9d} {t_build:9.4f} {t_slew:15.4f} {t_wm:13.4f} "
                  f"{t_rm:12.4f} {toml}",
                  flush=True)


if __name__ == "__main__":
    from trussfe.cli import environment_workers
    from trussfe.threads import compute_threads

    with compute_threads(workers=environment_workers(), blas=1):   # as the trussfe command
        main()
