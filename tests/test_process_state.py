# SPDX-License-Identifier: MIT
"""Library code changes no process-wide state: analyses and plots run through
:mod:`trussfe.api` leave the environment, warning filters, floating-point error modes, print
options, logging, signal handlers, the recursion limit, matplotlib's backend (and pyplot
unimported) and the BLAS thread counts as they found them.

The run is a fresh interpreter, so what it sees before the analyses is the process as a
program using trussfe would have it (not as earlier tests left it), with trussfe's
dependencies already imported.  matplotlib is imported
first with the SVG backend selected, so that a library call selecting Agg would show.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from trussfe.cli import main

SCRIPT = r'''
import json, logging, os, signal, sys, warnings
from pathlib import Path

import matplotlib
import numpy as np
from threadpoolctl import threadpool_info

# the dependencies first: scipy adds warning filters of its own when imported
# (SpecialFunctionWarning "always", numpy's matrix-subclass warning ignored), which are not
# trussfe's doing; trussfe's own imports come after the first snapshot
import meshio, scipy.linalg, scipy.sparse, scipy.sparse.linalg, scipy.special, skfem  # noqa


def snapshot():
    return {
        "environ": dict(os.environ),
        "warnings": [repr(f) for f in warnings.filters],
        "geterr": np.geterr(),
        "printoptions": repr(np.get_printoptions()),
        "root_handlers": [repr(h) for h in logging.getLogger().handlers],
        "root_level": logging.getLogger().level,
        "trussfe_logger": [repr(h) for h in logging.getLogger("trussfe").handlers],
        "signals": {s.name: repr(signal.getsignal(s))
                    for s in (signal.SIGINT, signal.SIGTERM, signal.SIGCHLD)},
        "recursionlimit": sys.getrecursionlimit(),
        # the raw setting: get_backend() would resolve (and so import pyplot)
        "backend": dict.__getitem__(matplotlib.rcParams, "backend"),
        "pyplot": "matplotlib.pyplot" in sys.modules,
        "threads": {p["filepath"]: p["num_threads"] for p in threadpool_info()},
    }


before = snapshot()

from trussfe import api
from trussfe._resources import mesh_path
from trussfe.report_figures import render_shape
from trussfe.rigid.output import write_plots

out = Path(os.environ["TRUSSFE_STATE_OUT"])   # the test's own temporary folder
st = api.static(mesh_path("triangular_truss_static.toml"))
mo = api.modes(mesh_path("double_octahedron_equilibrium.toml"), count=3)
sim = api.simulate(mesh_path("triangular_truss_motion_active.toml"),
                   motion=mesh_path("triangular_truss_motion_3s.toml"), steps=8)
pngs = write_plots(out / "png", sim.solution)
shape = render_shape(out / "s.png", st.structure, st.displacement,
                     member_values=st.axial_force, backend="matplotlib", window=(200, 160))

after = snapshot()
# a library loaded during the run (MKL for PARDISO) has no "before" to compare with
after["threads"] = {k: v for k, v in after["threads"].items() if k in before["threads"]}
changed = sorted(k for k in before if before[k] != after[k])
print(json.dumps({"changed": changed, "before": {k: before[k] for k in changed},
                  "after": {k: after[k] for k in changed},
                  "pngs": [str(p) for p in pngs] + [str(shape)],
                  "frequencies": mo.frequencies_hz.tolist()}, default=str))
'''


def test_analyses_and_plots_leave_process_state_unchanged(tmp_path):
    """Static, modes, a short rigid-body simulation, its thesis-style figures and a
    member-coloured shape: nothing process-wide differs after them (and the figures exist)."""
    env = {k: v for k, v in os.environ.items() if k not in ("MPLBACKEND",
                                                             "TRUSSFE_PLOT_BACKEND")}
    env["MPLBACKEND"] = "svg"                       # a backend trussfe must not replace
    env["TRUSSFE_STATE_OUT"] = str(tmp_path)
    env["PYTHONPATH"] = os.pathsep.join([str(Path(__file__).resolve().parents[1]),
                                         env.get("PYTHONPATH", "")])
    run = subprocess.run([sys.executable, "-c", SCRIPT], env=env, capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    doc = json.loads(run.stdout.strip().splitlines()[-1])
    assert doc["changed"] == [], doc
    assert len(doc["pngs"]) >= 3
    for p in doc["pngs"]:
        assert Path(p).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert all(f > 0 for f in doc["frequencies"])


def test_command_line_restores_logging(capsys):
    """The command line logs to stderr for its own run only: the root and ``trussfe``
    loggers' handlers and levels are as before once :func:`trussfe.cli.main` returns."""
    import logging

    root, own = logging.getLogger(), logging.getLogger("trussfe")
    saved = root.handlers[:]
    root.handlers.clear()                   # as a program that has not configured logging
    try:
        before = (root.level, own.level, own.handlers[:])
        assert main(["-v", "static", str(_static_model())]) == 0
        assert root.handlers == [] and (root.level, own.level, own.handlers) == before
    finally:
        root.handlers[:] = saved


def _static_model() -> Path:
    from trussfe._resources import mesh_path

    return mesh_path("triangular_truss_static.toml")
