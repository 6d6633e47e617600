# SPDX-License-Identifier: MIT
"""``trussfe actuators MODEL [--motion MOTION]``: leadscrew and motor demands along a motion.

Runs the rigid-body force analysis (as ``simulate``) and summarises, for every actuator of the
``[actuators]`` table, the self-locking check (Lacy eq. 2.45), the gains (eq. 3.1 when the
gearhead gain is selected), and the peak force, motor speed, torque, current and voltage with
their times, with and without leadscrew friction, and the flags (e.g. a voltage above the
motor's maximum, Lacy section 5.7).
"""
from __future__ import annotations

import argparse

from .. import api
from ..io.output import write_json
from . import options as opt


def register(subparsers) -> None:
    """Add the ``actuators`` command."""
    p = subparsers.add_parser(
        "actuators", help="leadscrew and motor demands of the actuators along a motion",
        description="Self-locking check, gains, peak actuator force, motor speed, torque, "
        "current and voltage (with and without friction) of every [actuators] entry.")
    p.add_argument("model", type=opt.input_file, help="model file (TOML) with [active_members] and [actuators]")
    p.add_argument("--motion", type=opt.input_file, help="motion file: TOML [motion] spec or CSV history")
    p.add_argument("--steps", type=opt.positive_int, help="number of time steps of a generated motion")
    p.add_argument("--json", metavar="OUT", type=opt.output_file, help="write the summary as JSON")
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    doc = api.actuators(args.model, motion=args.motion, steps=args.steps).to_dict()
    if args.json:
        write_json(args.json, doc)
    for aid, a in doc["actuators"].items():
        v, tq = a["motor_voltage"], a["motor_torque"]
        head = (f"{aid}: G_ls {a['leadscrew_gain']:.5g} m/rad "
                f"({'self-locking' if a['self_locking'] else 'NOT self-locking'}, limit "
                f"{a['self_locking_limit']:.5g}), ")
        if a["gearhead_gain"] is None:
            # no gain given and none to select: the motion does not move this actuator
            print(f"{head}G_gh not selected; peak force {a['force']['value']:.5g} N at "
                  f"{a['force']['time']:.4g} s")
        else:
            print(f"{head}G_gh {a['gearhead_gain']:.5g}"
                  f"{' (selected, eq. 3.1)' if a['gearhead_gain_selected'] else ''}; peak "
                  f"force {a['force']['value']:.5g} N at {a['force']['time']:.4g} s, torque "
                  f"{tq['value']:.4g} N·m at "
                  f"{tq['time']:.4g} s, voltage {v['value']:.4g} V at {v['time']:.4g} s "
                  f"({a['motor_voltage_frictionless']['value']:.4g} V without friction)")
        for f in a["flags"]:
            print(f"  finding: {f}")
    return 0
