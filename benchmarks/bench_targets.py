# SPDX-License-Identifier: MIT
"""Every performance target of docs/performance.md in one run, each against its reference
measured in the same run; prints the benchmarks' own tables, then one table of the targets.

The three benchmarks run one after the other, each in a process of its own, as they run alone
(each sets its threads before numpy loads: the rigid-body and modal benchmarks limit BLAS,
OpenMP and MKL to one thread, the static benchmark leaves PARDISO its threads):

- ``bench_static.py --repeat R --large --only "chain 10000 " 180x180 410x410``: the static
  chain of 10,000 bays and the 180 × 180 grid against OpenSeesPy, and the 10⁶-DOF grid;
- ``bench_modal.py --bays 10000 --grid 0``: the 10 lowest modes of the 10,000-bay chain
  against OpenSeesPy's ``-genBandArpack``;
- ``bench_rigid.py --repeat R``: the slew and the 100-bay chain against the dense-117 loop,
  and the time per bay and step of chains of 10, 100 and 1,000 bays.

Each benchmark writes its rows with ``--json``; the summary reads them.  A ratio is the
reference's time over trussfe's: the static and rigid-body ones the fastest of R runs of each
program (the dense loop the fastest of all its timings, made between the cases), the modal one
a single run of each.  Each row carries the check that the answers agree (residual
‖Ku − f‖/‖f‖ and the largest member-force difference to OpenSeesPy; eigen-residuals and
frequency difference; bay-by-bay against direct member forces).  Without OpenSeesPy the static
and modal ratios are shown as not measured.

Run from the source tree: ``PYTHONPATH=$PWD python benchmarks/bench_targets.py [--repeat R]``
(default 3).  It takes a few minutes and about 4 GB of memory (the 10⁶-DOF grid).
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent

#: Per bay and step, the 1,000-bay chain may take at most this many times the 100-bay chain's
#: time for the growth to count as linear in the number of bays (the pieces of 100 steps of
#: both; a shared machine's minutes differ by 10–20 %).
LINEAR_GROWTH = 1.25


def run(script: str, args: list[str], out: Path) -> dict:
    """Run one benchmark in a process of its own, its table printed as it comes; its rows."""
    cmd = [sys.executable, str(HERE / script), *args, "--json", str(out)]
    print(f"$ {' '.join(cmd[1:-2])}", flush=True)
    done = subprocess.run(cmd, check=False)
    if done.returncode != 0 or not out.exists():
        sys.exit(f"bench_targets: {script} failed (exit status {done.returncode})")
    print(flush=True)
    return json.loads(out.read_text())


def row(rows: list[dict], key: str, value: str) -> dict | None:
    """The row whose ``key`` is ``value``, or None."""
    return next((r for r in rows if r.get(key) == value), None)


def ratio_target(label: str, r: dict | None, need: float, check: str) -> tuple:
    """A target ratio: the row ``r`` (speed_up, total or wall, reference_s) against ``need``;
    a row of the targets' table."""
    if r is None or r.get("speed_up") is None:
        return (label, "–", "–", "–", f"≥ {need:g}×", "not measured", check)
    took = r.get("total", r.get("wall"))
    met = r["speed_up"] >= need
    return (label, f"{took:.3f} s", f"{r['reference_s']:.3f} s", f"{r['speed_up']:.2f}×",
            f"≥ {need:g}×", "met" if met else "not met", check)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3,
                    help="runs of each case in each benchmark, trussfe's and the "
                         "reference's; the fastest of each is shown (default 3)")
    a = ap.parse_args()
    rep = str(max(1, a.repeat))
    with tempfile.TemporaryDirectory() as tmp:
        st = run("bench_static.py", ["--repeat", rep, "--large", "--only", "chain 10000 ",
                                     "180x180", "410x410"], Path(tmp) / "static.json")
        mo = run("bench_modal.py", ["--bays", "10000", "--grid", "0"], Path(tmp) / "modal.json")
        rb = run("bench_rigid.py", ["--repeat", rep], Path(tmp) / "rigid.json")

    targets = []
    chain = row(st["rows"], "model", "chain 10000 bays")
    grid = row(st["rows"], "model", "grid 180x180")
    big = row(st["rows"], "model", "grid 410x410")

    def static_check(r: dict | None) -> str:
        if r is None or r.get("max_force_difference") is None:
            return f"residual {r['residual']:.1e}" if r else ""
        return (f"residual {r['residual']:.1e}; max |dN| {r['max_force_difference']:.1e} N "
                f"of {r['max_force']:.2e} N")
    targets.append(ratio_target("static chain, 10,000 bays", chain, 6.0, static_check(chain)))
    targets.append(ratio_target("static grid 180 × 180", grid, 6.0, static_check(grid)))
    if big is not None:
        targets.append((f"static grid of {big['dof']:,} DOF", f"{big['total']:.3f} s", "–",
                        "–", "≤ 8 s", "met" if big["total"] <= 8.0 else "not met",
                        f"residual {big['residual']:.1e}; peak {big['peak_mib']:.0f} MiB"))
    modes = row(mo["rows"], "model", "chain 10000")

    def modal_check(r: dict | None) -> str:
        if r is None:
            return ""
        text = f"eigen-residual {r['residual']:.1e}"
        if r.get("reference_residual") is not None:
            text += (f" (OpenSeesPy {r['reference_residual']:.1e}); "
                     f"max |df/f| {r['max_frequency_difference']:.1e}")
        if not r["resolved"]:
            # the chain's lowest modes are below what double precision resolves: neither
            # solver's modes can agree with the other's (docs/modal-buckling.md)
            text += "; not resolved in double precision"
        return text
    targets.append(ratio_target("10 modes, chain of 10,000 bays", modes, 5.5,
                                modal_check(modes)))
    slew = row(rb["rows"], "case", "double octahedron slew")
    targets.append(ratio_target("rigid slew, 10,000 steps", slew, 6.0,
                                "" if slew is None else
                                f"every output read: {slew['all_out_speed_up']:.1f}×"))
    c100 = next((r for r in rb["rows"] if r["case"] == "100-bay chain"
                 and r["method"] == "bay-by-bay"), None)
    agree = rb.get("agreement")
    targets.append(ratio_target(
        "rigid 100-bay chain × 1,000 steps", c100, 12.0,
        "" if c100 is None else
        f"every output read: {c100['all_out_speed_up']:.1f}×" + (
            "" if agree is None else
            f"; bay-by-bay vs direct forces {agree['relative_difference']:.1e}")))
    per = {r["bays"]: r["us_per_bay_step"] for r in rb["rows"]
           if r["case"].endswith("steps)") and r["method"] == "bay-by-bay"}
    if 100 in per and 1000 in per:
        growth = per[1000] / per[100]
        targets.append((
            "rigid chain time per bay and step, 10 → 1,000 bays",
            " / ".join(f"{per[b]:.1f}" for b in sorted(per)) + " µs", "–",
            f"{growth:.2f}× (1,000 / 100)", f"≤ {LINEAR_GROWTH:g}×",
            "met" if growth <= LINEAR_GROWTH else "not met", "pieces of 100 steps"))

    head = ("target", "trussfe", "reference", "ratio", "needed", "status", "agreement")
    width = [max(len(str(t[i])) for t in [head, *targets]) for i in range(len(head))]
    print("Targets, each against its reference in this run:")
    for t in [head, tuple("-" * w for w in width), *targets]:
        print("  ".join(str(v).ljust(w) for v, w in zip(t, width)).rstrip())
    met = sum(t[5] == "met" for t in targets)
    print(f"\nmet in this run: {met} of {len(targets)}")
    if st.get("blas"):
        print(st["blas"])


if __name__ == "__main__":
    main()
