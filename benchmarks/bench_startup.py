# SPDX-License-Identifier: MIT
"""Start-up of the command line: ``trussfe static`` on the triangular truss against bare
``python -c "import numpy, scipy.sparse.linalg"``, in fresh processes measured alternately in
the same run (target: at most 1.5×, docs/performance.md); prints a table."""
from __future__ import annotations

import argparse
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "meshes" / "triangular_truss_static.toml"
COMMANDS = {
    "python -c 'import numpy, scipy.sparse.linalg'":
        [sys.executable, "-c", "import numpy, scipy.sparse.linalg"],
    "trussfe static triangular_truss_static.toml":
        [sys.executable, "-m", "trussfe", "static", str(MODEL)],
    "trussfe --version":
        [sys.executable, "-m", "trussfe", "--version"],
}


def _wall(cmd: list[str]) -> float:
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, cwd=ROOT)
    return time.perf_counter() - t0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=7, help="runs of each command (best shown)")
    args = ap.parse_args()
    best = dict.fromkeys(COMMANDS, float("inf"))
    for _ in range(args.repeat):           # alternate, so that machine load hits all alike
        for name, cmd in COMMANDS.items():
            best[name] = min(best[name], _wall(cmd))
    ref = best[next(iter(COMMANDS))]
    print(f"{'command':<48} {'best s':>8} {'× import':>9}")
    for name, t in best.items():
        print(f"{name:<48} {t:8.3f} {t / ref:9.2f}")


if __name__ == "__main__":
    main()
