# SPDX-License-Identifier: MIT
"""The three shipped parameter studies (``examples/*.toml``) at small size, for the
validation report.

Each study file is read as shipped, made small (fewer grid values, samples or steps), and
its runs are made in this process with :func:`~trussfe.parametric.runner.run_one` — the
rows a Dask worker makes, which do not depend on where they run (tested).  Every check holds
a study's rows against the same analysis called directly through the API on a model written
by hand with the run's values, or against the physics the study is about.
"""
from __future__ import annotations

import math
import tempfile
import tomllib
from pathlib import Path

from .._resources import data_dir
from .design import design
from .runner import read_study, run_one
from .spec import Study

#: Edits that make each shipped study small: (old text, new text) pairs.
SMALL = {
    "chain_length.toml": (("to = 50", "to = 3"),),
    "slew_duration_payload.toml": (("from = 1.0, to = 6.0, step = 0.5", "values = [2.0, 6.0]"),
                                   ("from = 0.0, to = 20.0, step = 5.0", "values = [0.0, 20.0]"),
                                   ("steps = 200", "steps = 24")),
    "dome_imperfection.toml": (("samples = 200", "samples = 3"),),
}


def small_study(name: str, folder: Path) -> Study:
    """Shipped study ``name`` with its :data:`SMALL` edits, written into ``folder`` (its
    model and motion files named by absolute path) and read."""
    text = (data_dir("examples") / name).read_text(encoding="utf-8")
    text = text.replace('"../meshes/', f'"{data_dir("meshes").as_posix()}/')
    for old, new in SMALL[name]:
        if old not in text:
            raise ValueError(f"{name}: '{old}' is not in the shipped study")
        text = text.replace(old, new)
    path = Path(folder) / name
    path.write_text(text, encoding="utf-8")
    return read_study(path)


def _rows(study: Study) -> list[dict]:
    return [run_one(study, *run) for run in design(study)]


def _relative(a: float, b: float) -> float:
    """|a − b| / |b|; NaN when either is not a finite number, so that a missing or NaN
    value reaches the validation check as NaN (which fails) instead of vanishing in a
    comparison."""
    if not (math.isfinite(a) and math.isfinite(b)):
        return math.nan
    return abs(a - b) / max(abs(b), 1e-300)


def _largest(values) -> float:
    """The largest of ``values``, NaN if any is NaN (the builtin ``max`` drops a NaN that is
    not first)."""
    values = list(values)
    return math.nan if any(math.isnan(v) for v in values) else max(values, default=0.0)


def chain_length(folder: Path) -> dict:
    """Chains of 1–3 bays under Table 5.2's top load: the rows against ``modes`` and
    ``static`` of the catalogue chain, and the trend (longer: lower and softer)."""
    from .. import api
    from ..models import TABLE_LOAD, double_octahedral_chain

    rows = _rows(small_study("chain_length.toml", folder))
    f_errs, u_errs = [], []
    for row in rows:
        n = row["n_bays"]
        s = double_octahedral_chain(n, tip_load=TABLE_LOAD)
        f = float(api.modes(s, count=1).frequencies_hz[0])
        uz = api.static(s).to_dict()["nodes"][f"b{n}.N7"]["displacement"][2]
        f_errs.append(_relative(row["first_frequency"], f))
        u_errs.append(_relative(row["tip_deflection"], uz))
    f_err, u_err = _largest(f_errs), _largest(u_errs)
    freq = [r["first_frequency"] for r in rows]
    tip = [r["tip_deflection"] for r in rows]
    return {"runs_ok": sum(r["status"] == "ok" for r in rows), "frequency_vs_api": f_err,
            "deflection_vs_api": u_err,
            "frequency_not_falling": sum(not b < a for a, b in zip(freq, freq[1:])),
            "deflection_not_rising": sum(not b > a for a, b in zip(tip, tip[1:]))}


def slew_duration_payload(folder: Path) -> dict:
    """Slews of 2 and 6 s with 0 and 20 kg: the peak motor voltage against the motors'
    supply, and one run against ``simulate`` of the same model and motion."""
    from .. import api
    from ..rigid.motion_file import motion_from_spec

    study = small_study("slew_duration_payload.toml", folder)
    rows = _rows(study)
    volts = {(r["duration"], r["payload"]): r["peak_voltage"] for r in rows}
    force = {(r["duration"], r["payload"]): r["peak_M8_force"] for r in rows}
    meshes = data_dir("meshes")
    data = tomllib.loads((meshes / "double_octahedron_actuators.toml").read_text("utf-8"))
    supply = min(a["max_voltage"] for a in data["actuators"].values())
    data["masses"] = {n: 20.0 / 3.0 for n in ("N7", "N8", "N9")}
    s = api.model_from_dict(data)
    spec = tomllib.loads((meshes / "double_octahedron_tilt_rotation.toml").read_text("utf-8"))
    spec["motion"]["duration"] = 6.0
    motion = motion_from_spec(spec["motion"], s, meshes, steps=24)
    doc = api.simulate(s, motion=motion).to_dict()
    direct = max(a["max_motor_voltage"] for a in doc["actuators"].values())
    return {"runs_ok": sum(r["status"] == "ok" for r in rows),
            "voltage_vs_api": _relative(volts[6.0, 20.0], direct),
            "supply": supply,
            "over_supply_in_6s": sum(not v <= supply for (t, _), v in volts.items()
                                     if t == 6.0),
            "within_supply_in_2s": sum(not v > supply for (t, _), v in volts.items()
                                       if t == 2.0),
            "payload_raises_force": int(force[2.0, 20.0] > force[2.0, 0.0]
                                        and force[6.0, 20.0] > force[6.0, 0.0])}


def dome_imperfection(folder: Path) -> dict:
    """Three Monte Carlo draws of the dome's imperfection and member critical loads: the
    mechanism load against the first limit load of each draw, and the last draw against
    ``postcritical`` of the model with its values written in."""
    from .. import api

    rows = _rows(small_study("dome_imperfection.toml", folder))
    r = rows[-1]
    data = tomllib.loads((data_dir("meshes") / "postcritical_dome.toml").read_text("utf-8"))
    data["postcritical"]["imperfection"] = r["imperfection"]
    for m in ("A1", "A2", "A3", "A5", "A6"):
        data["failure"]["members"][m]["critical_load"] *= r[m]
    doc = api.postcritical(api.model_from_dict(data)).to_dict()
    mech = [e["load_factor"] for e in doc["events"] if e["kind"] == "mechanism"]
    return {"runs_ok": sum(x["status"] == "ok" for x in rows),
            "mechanism_load_vs_api": _relative(r["mechanism_load"], mech[0]),
            "mechanism_below_first_limit": sum(not x["mechanism_load"] >= x["first_limit_load"]
                                               for x in rows),
            "draws_outside_ranges": sum(not (0.0 <= x["imperfection"] <= 0.015)
                                        or not all(0.9 <= x[m] <= 1.1
                                                   for m in ("A1", "A2", "A3", "A5", "A6"))
                                        for x in rows)}


def shipped_studies() -> dict:
    """The three shipped studies at small size (the validation case ``studies-shipped``)."""
    with tempfile.TemporaryDirectory() as tmp:
        return {"chain": chain_length(Path(tmp)), "slew": slew_duration_payload(Path(tmp)),
                "dome": dome_imperfection(Path(tmp))}
