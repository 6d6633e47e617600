"""Catalogue of hostile and careless inputs for every command (data for
``test_hostile_catalogue.py``).

Each case is ``(id, argv, expected status, words the error line holds)``; ``argv`` may hold the
placeholders below, which the test replaces by files it writes into a fresh folder:

``{m}`` a small 2-D two-bar truss (static, modes, buckling), ``{mech}`` a four-bar mechanism
(mechanism, trace), ``{act}`` the triangular truss with an active member and ``{mot}`` its
motion (simulate, elastic, transient, actuators), ``{bad}`` the model or motion a case writes
(``model`` / ``motion`` text of the case), ``{out}`` the output folder, ``{file}`` a plain
file in it, ``{fifo}`` a named pipe.

The catalogue is meant to grow: add a row for every input that once broke the contract.
"""
from __future__ import annotations

GOOD = """\
[model]
name = "two-bar"
dimension = 2

[materials.al]
E = 71.0e9
density = 2711.5

[sections.tube]
outer_diameter = 0.0254
inner_diameter = 0.022225

[nodes]
A = [-1.0, 0.0]
B = [0.0, 1.0]
C = [1.0, 0.0]

[members]
AB = { nodes = ["A", "B"], section = "tube", material = "al" }
BC = { nodes = ["B", "C"], section = "tube", material = "al" }

[supports]
A = ["x", "y"]
C = ["x", "y"]

[loads]
B = [0.0, -1000.0]
"""

MECH = """\
[model]
name = "fourbar"
dimension = 2

[materials.al]
E = 70.0e9
density = 2700.0

[sections.tube]
outer_diameter = 0.02
inner_diameter = 0.016

[nodes]
"1" = [0, 0]
"2" = [0.995004165278026, 0.0998334166468282]
"3" = [2.99230833478574, 2.59998862272246]
"4" = [3, 0]

[members]
b1 = { nodes = ["1", "2"], section = "tube", material = "al" }
b2 = { nodes = ["2", "3"], section = "tube", material = "al" }
b3 = { nodes = ["4", "3"], section = "tube", material = "al" }

[supports]
"1" = ["x", "y"]
"4" = ["x", "y"]
"""

ACT = """\
[model]
name = "triangular truss"
dimension = 2
gravity = [0.0, -9.81]

[materials.al]
E = 71.0e9
G = 26.2e9
density = 2711.5

[sections.tube]
outer_diameter = 0.0254
inner_diameter = 0.022225

[nodes]
O2 = [0.0, 0.0]
O1 = [2.0, 0.0]
B = [1.5625, 1.9515618744994994]

[members]
follower = { nodes = ["O1", "B"], section = "tube", material = "al" }
active = { nodes = ["O2", "B"], section = "tube", material = "al" }

[supports]
O2 = ["x", "y"]
O1 = ["x", "y"]

[masses]
B = 10.0

[active_members.active]
base_mass = 2.4
base_length = 2.1
base_cg = 1.05
tube_length = 2.0
min_length = 2.5
max_length = 4.1
"""

MOTION = """\
[motion]
type = "third-order"
duration = 3.0
steps = 6
start = { active = 2.5 }
end = { active = 3.7 }
"""

# ----------------------------------------------------------------------------- model files
#: (id, old, new): GOOD with ``old`` replaced by ``new``; every one must be refused (exit 2).
MODEL_EDITS = [
    ("E nan", "E = 71.0e9", "E = nan"),
    ("E inf", "E = 71.0e9", "E = inf"),
    ("E -inf", "E = 71.0e9", "E = -inf"),
    ("E string", "E = 71.0e9", 'E = "71e9"'),
    ("E bool", "E = 71.0e9", "E = true"),
    ("E array", "E = 71.0e9", "E = [71e9]"),
    ("E table", "E = 71.0e9", "E = { value = 71e9 }"),
    ("E date", "E = 71.0e9", "E = 1979-05-27"),
    ("E 1e-300 (overflowing displacements)", "E = 71.0e9", "E = 1e-300"),
    ("E zero", "E = 71.0e9", "E = 0"),
    ("E negative zero", "E = 71.0e9", "E = -0.0"),
    ("E negative", "E = 71.0e9", "E = -1"),
    ("E missing", "E = 71.0e9\n", ""),
    ("E twice", "E = 71.0e9", "E = 71.0e9\nE = 70e9"),
    ("density negative", "density = 2711.5", "density = -1"),
    ("density nan", "density = 2711.5", "density = nan"),
    ("density string", "density = 2711.5", 'density = "heavy"'),
    ("G zero", "density = 2711.5", "density = 2711.5\nG = 0"),
    ("yield negative", "density = 2711.5", "density = 2711.5\nyield_strength = -1"),
    ("material not a table", "[materials.al]\nE = 71.0e9\ndensity = 2711.5",
     "[materials]\nal = 3"),
    ("unknown material key", "density = 2711.5", "density = 2711.5\npoisson = 0.3"),
    ("outer diameter zero", "outer_diameter = 0.0254", "outer_diameter = 0"),
    ("outer diameter nan", "outer_diameter = 0.0254", "outer_diameter = nan"),
    ("outer diameter string", "outer_diameter = 0.0254", 'outer_diameter = "1in"'),
    ("inner > outer", "inner_diameter = 0.022225", "inner_diameter = 0.03"),
    ("inner negative", "inner_diameter = 0.022225", "inner_diameter = -0.01"),
    ("inner without outer", "outer_diameter = 0.0254\n", ""),
    ("area and diameter", "inner_diameter = 0.022225", "inner_diameter = 0.022225\narea = 1e-4"),
    ("area inf", "outer_diameter = 0.0254\ninner_diameter = 0.022225", "area = inf"),
    ("Iy negative", "outer_diameter = 0.0254\ninner_diameter = 0.022225",
     "area = 1e-4\nIy = -1e-8"),
    ("section not a table", "[sections.tube]\nouter_diameter = 0.0254\ninner_diameter = "
     "0.022225", "[sections]\ntube = 0.0254"),
    ("coordinate nan", "B = [0.0, 1.0]", "B = [0.0, nan]"),
    ("coordinate inf", "B = [0.0, 1.0]", "B = [0.0, inf]"),
    ("coordinate 1e308", "B = [0.0, 1.0]", "B = [1e308, -1e308]"),
    ("coordinate string", "B = [0.0, 1.0]", 'B = [0.0, "1"]'),
    ("coordinate bool", "B = [0.0, 1.0]", "B = [0.0, true]"),
    ("coordinate nested", "B = [0.0, 1.0]", "B = [[0.0, 1.0]]"),
    ("coordinates 3 in 2-D", "B = [0.0, 1.0]", "B = [0.0, 1.0, 0.0]"),
    ("coordinates 1", "B = [0.0, 1.0]", "B = [0.0]"),
    ("coordinates empty", "B = [0.0, 1.0]", "B = []"),
    ("coordinates table", "B = [0.0, 1.0]", "B = { x = 0.0, y = 1.0 }"),
    ("coordinates scalar", "B = [0.0, 1.0]", "B = 1.0"),
    ("node on top of node (joined)", "B = [0.0, 1.0]", "B = [-1.0, 0.0]"),
    ("no nodes", "A = [-1.0, 0.0]\nB = [0.0, 1.0]\nC = [1.0, 0.0]\n", ""),
    ("nodes not a table", "[nodes]\nA = [-1.0, 0.0]\nB = [0.0, 1.0]\nC = [1.0, 0.0]",
     "nodes = 3"),
    ("no members", "AB = { nodes = [\"A\", \"B\"], section = \"tube\", material = \"al\" }\n"
     "BC = { nodes = [\"B\", \"C\"], section = \"tube\", material = \"al\" }\n", ""),
    ("member one node", 'BC = { nodes = ["B", "C"]', 'BC = { nodes = ["B"]'),
    ("member three nodes", 'BC = { nodes = ["B", "C"]', 'BC = { nodes = ["B", "C", "A"]'),
    ("member nodes string", 'BC = { nodes = ["B", "C"]', 'BC = { nodes = "B C"'),
    ("member to itself", 'BC = { nodes = ["B", "C"]', 'BC = { nodes = ["B", "B"]'),
    ("member to missing node", 'BC = { nodes = ["B", "C"]', 'BC = { nodes = ["B", "Q"]'),
    ("member node integer", 'BC = { nodes = ["B", "C"]', 'BC = { nodes = ["B", 3]'),
    ("member node with newline", 'BC = { nodes = ["B", "C"]', 'BC = { nodes = ["B", "C\\nX"]'),
    ("member node with escape", 'BC = { nodes = ["B", "C"]',
     'BC = { nodes = ["B", "C\\u001b[31m"]'),
    ("member missing section", 'section = "tube", material = "al" }\nBC',
     'material = "al" }\nBC'),
    ("member unknown section", 'BC = { nodes = ["B", "C"], section = "tube"',
     'BC = { nodes = ["B", "C"], section = "pipe"'),
    ("member section integer", 'BC = { nodes = ["B", "C"], section = "tube"',
     'BC = { nodes = ["B", "C"], section = 7'),
    ("member unknown type", 'material = "al" }\nBC', 'material = "al", type = "rope" }\nBC'),
    ("member type integer", 'material = "al" }\nBC', 'material = "al", type = 1 }\nBC'),
    ("member releases on bar", 'material = "al" }\nBC',
     'material = "al", releases = ["start"] }\nBC'),
    ("member releases bad", 'material = "al" }\nBC',
     'material = "al", type = "beam", releases = ["middle"] }\nBC'),
    ("member orientation zero", 'material = "al" }\nBC',
     'material = "al", type = "beam", orientation = [0, 0, 0] }\nBC'),
    ("member orientation nan", 'material = "al" }\nBC',
     'material = "al", type = "beam", orientation = [0, nan, 1] }\nBC'),
    ("member unknown key", 'material = "al" }\nBC', 'material = "al", colour = "red" }\nBC'),
    ("member not a table", 'BC = { nodes = ["B", "C"], section = "tube", material = "al" }',
     'BC = ["B", "C"]'),
    ("duplicate member", 'BC = { nodes = ["B", "C"]', 'BC = { nodes = ["B", "A"]'),
    ("duplicate member reversed", 'BC = { nodes = ["B", "C"]', 'BC = { nodes = ["A", "B"]'),
    ("support unknown node", 'C = ["x", "y"]', 'D = ["x", "y"]'),
    ("support unknown dof", 'C = ["x", "y"]', 'C = ["x", "w"]'),
    ("support rotation in truss 2-D", 'C = ["x", "y"]', 'C = ["x", "y", "rx"]'),
    ("support integer", 'C = ["x", "y"]', "C = 1"),
    ("support bool list", 'C = ["x", "y"]', "C = [true]"),
    ("no supports (mechanism)", '[supports]\nA = ["x", "y"]\nC = ["x", "y"]\n', ""),
    ("one support (mechanism)", 'C = ["x", "y"]\n', ""),
    ("load unknown node", "B = [0.0, -1000.0]", "D = [0.0, -1000.0]"),
    ("load nan", "B = [0.0, -1000.0]", "B = [0.0, nan]"),
    ("load inf", "B = [0.0, -1000.0]", "B = [0.0, -inf]"),
    ("load string", "B = [0.0, -1000.0]", 'B = [0.0, "-1kN"]'),
    ("load 1 component", "B = [0.0, -1000.0]", "B = [-1000.0]"),
    ("load 4 components", "B = [0.0, -1000.0]", "B = [0.0, -1000.0, 0.0, 0.0]"),
    ("load scalar", "B = [0.0, -1000.0]", "B = -1000.0"),
    ("load 1e308", "B = [0.0, -1000.0]", "B = [1e308, -1e308]"),
    ("load integer beyond float", "B = [0.0, -1000.0]", "B = [0, -" + "9" * 400 + "]"),
    ("masses negative", "[loads]", "[masses]\nB = -1\n\n[loads]"),
    ("masses nan", "[loads]", "[masses]\nB = nan\n\n[loads]"),
    ("masses unknown node", "[loads]", "[masses]\nZ = 1\n\n[loads]"),
    ("dimension 4", "dimension = 2", "dimension = 4"),
    ("dimension 2.0", "dimension = 2", "dimension = 2.0"),
    ("dimension string", "dimension = 2", 'dimension = "2"'),
    ("dimension bool", "dimension = 2", "dimension = true"),
    ("name integer", 'name = "two-bar"', "name = 3"),
    ("gravity nan", 'name = "two-bar"', 'name = "two-bar"\ngravity = [0, nan]'),
    ("gravity wrong size", 'name = "two-bar"', 'name = "two-bar"\ngravity = [0, 0, -9.81]'),
    ("mesh integer", 'name = "two-bar"', 'name = "two-bar"\nmesh = 3'),
    ("mesh missing", 'name = "two-bar"', 'name = "two-bar"\nmesh = "nowhere.vtu"'),
    ("mesh is the folder", 'name = "two-bar"', 'name = "two-bar"\nmesh = "."'),
    ("mesh is a device", 'name = "two-bar"', 'name = "two-bar"\nmesh = "/dev/zero"'),
    ("mesh is text", 'name = "two-bar"', 'name = "two-bar"\nmesh = "notes.vtu"'),
    ("mesh is text (msh)", 'name = "two-bar"', 'name = "two-bar"\nmesh = "notes.msh"'),
    ("mesh unknown suffix", 'name = "two-bar"', 'name = "two-bar"\nmesh = "notes.txt"'),
    ("unknown table", "[supports]", "[suports]"),
    ("unknown key in model", 'name = "two-bar"', 'name = "two-bar"\nunits = "mm"'),
    ("model table missing", '[model]\nname = "two-bar"\ndimension = 2\n', ""),
    ("model not a table", '[model]\nname = "two-bar"\ndimension = 2\n', "model = 1\n"),
    ("malformed TOML bracket", "[nodes]", "[nodes"),
    ("malformed TOML string", 'name = "two-bar"', 'name = "two-bar'),
    ("malformed TOML duplicate table", "[supports]", "[loads]\n[supports]"),
    ("malformed TOML duplicate key", "A = [-1.0, 0.0]", "A = [-1.0, 0.0]\nA = [-1.0, 0.0]"),
    ("malformed TOML bare word", "E = 71.0e9", "E = seventy"),
    ("tab in key", "A = [-1.0, 0.0]", "\tA = [-1.0, 0.0]\n\x01"),
    ("deeply nested array", "B = [0.0, -1000.0]", "B = " + "[" * 5000 + "]" * 5000),
    ("deeply nested inline tables", "B = [0.0, -1000.0]",
     "B = " + "{a=" * 3000 + "1" + "}" * 3000),
    ("active member unknown", "[loads]", "[active_members.nope]\nmin_length = 1\n"
     "max_length = 2\n\n[loads]"),
    # load cases, springs, rotary inertia
    ("temperature without thermal_expansion", "[loads]\nB = [0.0, -1000.0]",
     '[load_cases.hot]\ntemperature = [ { members = ["AB"], delta_T = 40.0 } ]'),
    ("prescribed displacement on a free DOF", "[loads]\nB = [0.0, -1000.0]",
     "[load_cases.settle]\nprescribed = { B = { y = -0.005 } }"),
    ("prescribed unknown DOF", "[loads]\nB = [0.0, -1000.0]",
     "[load_cases.settle]\nprescribed = { A = { q = -0.005 } }"),
    ("spring on a fixed DOF", "[loads]", "[springs]\nA = { x = 1.0e6 }\n\n[loads]"),
    ("spring stiffness negative", "[loads]", "[springs]\nB = { x = -1.0e6 }\n\n[loads]"),
    ("spring stiffness nan", "[loads]", "[springs]\nB = { x = nan }\n\n[loads]"),
    ("spring on an unknown node", "[loads]", "[springs]\nQ = { x = 1.0e6 }\n\n[loads]"),
    ("rotational spring at a pin joint", "[loads]",
     "[springs]\nB = { rz = 1.0e3 }\n\n[loads]"),
    ("combination naming a missing case", "[loads]\nB = [0.0, -1000.0]",
     "[load_cases.a]\nloads = { B = [0.0, -1000.0] }\n\n[combinations]\nULS = { b = 1.5 }"),
    ("combination factor not a number", "[loads]\nB = [0.0, -1000.0]",
     '[load_cases.a]\nloads = { B = [0.0, -1000.0] }\n\n[combinations]\nULS = { a = "x" }'),
    ("combinations without cases", "[loads]", "[combinations]\nULS = { a = 1.5 }\n\n[loads]"),
    ("unknown key in a load case", "[loads]\nB = [0.0, -1000.0]",
     "[load_cases.a]\nload = { B = [0.0, -1000.0] }"),
    ("loads beside load cases", "[loads]",
     "[load_cases.a]\nloads = { B = [0.0, -1.0] }\n\n[loads]"),
    ("case gravity without a gravity vector", "[loads]\nB = [0.0, -1000.0]",
     "[load_cases.dead]\ngravity = true"),
    ("length error on an unknown member", "[loads]\nB = [0.0, -1000.0]",
     '[load_cases.fit]\nlength_error = [ { member = "XY", delta = 1e-3 } ]'),
    ("member load of a case on a missing member", "[loads]\nB = [0.0, -1000.0]",
     '[load_cases.p]\nmember_loads = [ { member = "XY", kind = "uniform", '
     'q = [0.0, -800.0] } ]'),
    ("top-level member loads beside load cases", "[loads]\nB = [0.0, -1000.0]",
     '[[member_loads]]\nmember = "AB"\nkind = "uniform"\nq = [0.0, -800.0]\n\n'
     '[load_cases.p]\nloads = { B = [0.0, -1.0] }'),
    ("rotary inertia negative", "[loads]", "[masses]\nB = { mass = 1.0, inertia = -1.0 }"
     "\n\n[loads]"),
]

#: Whole files: (id, bytes) — the model file is exactly this.
MODEL_FILES = [
    ("empty file", b""),
    ("only whitespace", b"  \n\t\n"),
    ("only a comment", b"# nothing\n"),
    ("binary zeros", b"\0" * 1000),
    ("random bytes", bytes(range(256)) * 8),
    ("PNG header", b"\x89PNG\r\n\x1a\n" + b"\0" * 64),
    ("gzip header", b"\x1f\x8b\x08\x00" + b"\0" * 64),
    ("UTF-16 text", GOOD.encode("utf-16")),
    ("Latin-1 text", GOOD.replace("two-bar", "zwei-st\u00e4be").encode("latin-1")),
    ("JSON instead of TOML", b'{"model": {"name": "x"}}'),
    ("YAML instead of TOML", b"model:\n  name: x\n"),
    ("CSV instead of TOML", b"time,active\n0,2.5\n1,2.6\n"),
    ("a very long line", b"x = \"" + b"a" * 300_000 + b"\"\n"),
    ("ten thousand tables", b"".join(b"[t%d]\n" % i for i in range(10_000))),
    ("NUL in a string", GOOD.replace('"two-bar"', '"two\\u0000bar"').encode() + b"\0"),
]

# ----------------------------------------------------------------------------- motion files
#: (id, old, new): MOTION with ``old`` replaced by ``new``; each refused by ``simulate``.
MOTION_EDITS = [
    ("first_sample string", "steps = 6", 'steps = 6\nfirst_sample = "abc"'),
    ("first_sample float", "steps = 6", "steps = 6\nfirst_sample = 1.5"),
    ("first_sample negative", "steps = 6", "steps = 6\nfirst_sample = -1"),
    ("first_sample huge", "steps = 6", "steps = 6\nfirst_sample = 10000000000000"),
    ("first_sample bool", "steps = 6", "steps = 6\nfirst_sample = true"),
    ("include_end string no", "steps = 6", 'steps = 6\ninclude_end = "no"'),
    ("include_end integer", "steps = 6", "steps = 6\ninclude_end = 1"),
    ("steps float", "steps = 6", "steps = 6.0"),
    ("steps 1e12 float", "steps = 6", "steps = 1e12"),
    ("steps 10^12", "steps = 6", "steps = 1000000000000"),
    ("steps zero", "steps = 6", "steps = 0"),
    ("steps negative", "steps = 6", "steps = -5"),
    ("steps string", "steps = 6", 'steps = "6"'),
    ("steps bool", "steps = 6", "steps = true"),
    ("duration zero", "duration = 3.0", "duration = 0"),
    ("duration negative", "duration = 3.0", "duration = -3"),
    ("duration nan", "duration = 3.0", "duration = nan"),
    ("duration inf", "duration = 3.0", "duration = inf"),
    ("duration string", "duration = 3.0", 'duration = "3 s"'),
    ("duration 1e-300", "duration = 3.0", "duration = 1e-300"),
    ("duration 1e300", "duration = 3.0", "duration = 1e300"),
    ("settling_constant 1e308", "steps = 6", "steps = 6\nsettling_constant = 1e308"),
    ("duration missing", "duration = 3.0\n", ""),
    ("start missing", "start = { active = 2.5 }\n", ""),
    ("start inf", "start = { active = 2.5 }", "start = { active = inf }"),
    ("start nan", "start = { active = 2.5 }", "start = { active = nan }"),
    ("start zero", "start = { active = 2.5 }", "start = { active = 0 }"),
    ("start string", "start = { active = 2.5 }", 'start = { active = "2.5" }'),
    ("start not a table", "start = { active = 2.5 }", "start = 2.5"),
    ("start unknown member", "start = { active = 2.5 }", "start = { passive = 2.5 }"),
    ("start negative", "start = { active = 2.5 }", "start = { active = -2.5 }"),
    ("end beyond max_length", "end = { active = 3.7 }", "end = { active = 40.0 }"),
    ("damping_ratio zero", "steps = 6", "steps = 6\ndamping_ratio = 0"),
    ("damping_ratio nan", "steps = 6", "steps = 6\ndamping_ratio = nan"),
    ("damping_ratio inf", "steps = 6", "steps = 6\ndamping_ratio = inf"),
    ("damping_ratio string", "steps = 6", 'steps = 6\ndamping_ratio = "high"'),
    ("unknown key", "steps = 6", "steps = 6\nspeed = 2"),
    ("unknown type", 'type = "third-order"', 'type = "fourth-order"'),
    ("type integer", 'type = "third-order"', "type = 3"),
    ("csv without file", 'type = "third-order"', 'type = "csv"'),
    ("csv file missing", 'type = "third-order"', 'type = "csv"\nfile = "nowhere.csv"'),
    ("rotation without nodes", 'type = "third-order"', 'type = "rotation"'),
    ("motion not a table", "[motion]\n", "motion = 3\n[other]\n"),
    ("no motion table", "[motion]", "[movement]"),
    ("malformed", "[motion]", "[motion"),
    ("deeply nested", "steps = 6", "steps = 6\nx = " + "[" * 5000 + "]" * 5000),
]

#: Whole motion files (name, bytes).  A .csv name is read as a CSV history.
MOTION_FILES = [
    ("empty toml", "m.toml", b""),
    ("binary toml", "m.toml", bytes(range(256))),
    ("empty csv", "m.csv", b""),
    ("csv header only", "m.csv", b"time,active\n"),
    ("csv text values", "m.csv", b"time,active\n0,a\n1,b\n2,c\n3,d\n4,e\n5,f\n"),
    ("csv nan", "m.csv", b"time,active\n0,2.5\n1,nan\n2,2.7\n3,2.8\n4,2.9\n5,3.0\n"),
    ("csv inf", "m.csv", b"time,active\n0,2.5\n1,inf\n2,2.7\n3,2.8\n4,2.9\n5,3.0\n"),
    ("csv time backwards", "m.csv", b"time,active\n0,2.5\n2,2.6\n1,2.7\n3,2.8\n4,2.9\n"),
    ("csv time repeated", "m.csv", b"time,active\n0,2.5\n0,2.6\n1,2.7\n2,2.8\n3,2.9\n"),
    ("csv unknown member", "m.csv", b"time,passive\n0,2.5\n1,2.6\n2,2.7\n3,2.8\n4,2.9\n"),
    ("csv ragged", "m.csv", b"time,active\n0,2.5\n1\n2,2.7,9\n3,2.8\n4,2.9\n"),
    ("csv binary", "m.csv", bytes(range(256))),
    ("csv 1e308 lengths", "m.csv",
     b"time,active\n0,1e308\n1,1e308\n2,1e308\n3,1e308\n4,1e308\n5,1e308\n"),
]

# ----------------------------------------------------------------------------- options
#: Bad values of numeric options: (id, value).
NOT_A_NUMBER = [("nan", "nan"), ("inf", "inf"), ("-inf", "-inf"), ("text", "abc"),
                ("empty", ""), ("space", " "), ("1e400", "1e400"), ("hex", "0x10"),
                ("comma decimal", "1,5"), ("unit suffix", "3m")]
NOT_AN_INT = [("float", "1.5"), ("exponent", "1e3"), ("text", "ten"), ("empty", ""),
              ("nan", "nan"), ("huge digits", "9" * 5000), ("unit suffix", "4x")]

#: (command argv prefix, option, bad values, words): each value must be refused (exit 2).
_STATIC = ["static", "{m}"]
_MODES = ["modes", "{m}"]
_BUCK = ["buckling", "{m}"]
_MECH = ["mechanism", "{mech}"]
_TRACE = ["trace", "{mech}", "--drive", "2:y", "--step", "0.01", "--steps", "2"]
_SIM = ["simulate", "{act}", "--motion", "{mot}"]
_ELA = ["elastic", "{act}", "--motion", "{mot}"]
_TRA = ["transient", "{act}", "--motion", "{mot}"]
_ACTS = ["actuators", "{act}", "--motion", "{mot}"]
_POST = ["postcritical", "{m}"]

OPTION_CASES = [
    (_STATIC, "--subdivisions", NOT_AN_INT + [("zero", "0"), ("negative", "-3")]),
    (_MODES, "--count", NOT_AN_INT + [("zero", "0"), ("negative", "-1")]),
    (_MODES, "--subdivisions", [("zero", "0"), ("float", "2.5")]),
    (_BUCK, "--count", [("zero", "0"), ("negative", "-2"), ("float", "1.5")]),
    (_BUCK, "--subdivisions", [("zero", "0"), ("text", "many")]),
    (_MECH, "--tolerance", NOT_A_NUMBER + [("zero", "0"), ("negative", "-1"), ("one", "1"),
                                          ("two", "2")]),
    (_TRACE, "--tolerance", NOT_A_NUMBER + [("zero", "0"), ("negative", "-1e-10"),
                                           ("one", "1")]),
    (_TRACE, "--branch", [("negative", "-1"), ("float", "0.5"), ("text", "left")]),
    (_SIM, "--steps", NOT_AN_INT + [("zero", "0"), ("negative", "-10")]),
    (_SIM, "--sections", [("zero", "0"), ("negative", "-7"), ("float", "3.5")]),
    (_ELA, "--sections", [("zero", "0")]),
    (_ELA, "--subdivisions", [("zero", "0")]),
    (_TRA, "--dt", NOT_A_NUMBER + [("zero", "0"), ("negative", "-0.01")]),
    (_TRA, "--t-end", [("nan", "nan"), ("zero", "0"), ("negative", "-1"), ("inf", "inf")]),
    (_TRA, "--vtk-every", [("zero", "0"), ("negative", "-1"), ("float", "0.5")]),
    (_TRA, "--subdivisions", [("zero", "0")]),
    (_ACTS, "--steps", [("zero", "0"), ("float", "2.5")]),
    (_POST, "--steps", [("zero", "0"), ("negative", "-5"), ("float", "1.5")]),
    (_POST, "--step", [("nan", "nan"), ("zero", "0"), ("negative", "-0.1"), ("inf", "inf")]),
    (_POST, "--max-load-factor", [("nan", "nan"), ("zero", "0"), ("negative", "-2")]),
    (_POST, "--max-displacement", [("nan", "nan"), ("zero", "0"), ("inf", "inf")]),
    (_POST, "--imperfection", [("nan", "nan"), ("negative", "-0.001"), ("inf", "inf")]),
    (_POST, "--subdivisions", [("zero", "0")]),
]

#: Whole argument lists that must be refused: (id, argv, words).
ARGV_CASES = [
    ("static case unknown", ["static", "{m}", "--case", "nope"], "--case"),
    ("static combination unknown", ["static", "{m}", "--combination", "ULS"], "--combination"),
    ("static case and all", ["static", "{m}", "--case", "default", "--all"], "--all"),
    ("buckling case unknown", ["buckling", "{m}", "--case", "nope"], "--case"),
    ("trace step nan", ["trace", "{mech}", "--drive", "2:y", "--step", "nan", "--steps", "2"],
     "--step"),
    ("trace step zero", ["trace", "{mech}", "--drive", "2:y", "--step", "0", "--steps", "2"],
     "--step"),
    ("trace steps zero", ["trace", "{mech}", "--drive", "2:y", "--step", "0.1", "--steps",
                          "0"], "--steps"),
    ("trace steps 10^12", ["trace", "{mech}", "--drive", "2:y", "--step", "1e-9", "--steps",
                           "1000000000000"], "--steps"),
    ("trace drive unknown node", ["trace", "{mech}", "--drive", "9:y", "--step", "0.1",
                                  "--steps", "2"], "--drive"),
    ("trace drive bad axis", ["trace", "{mech}", "--drive", "2:q", "--step", "0.1",
                              "--steps", "2"], "--drive"),
    ("trace drive no colon", ["trace", "{mech}", "--drive", "2y", "--step", "0.1",
                              "--steps", "2"], "--drive"),
    ("trace drive newline", ["trace", "{mech}", "--drive", "2\n:y", "--step", "0.1",
                             "--steps", "2"], "--drive"),
    ("trace drive supported", ["trace", "{mech}", "--drive", "1:x", "--step", "0.1",
                               "--steps", "2"], "--drive"),
    ("trace two steps one drive", ["trace", "{mech}", "--drive", "2:y", "--step", "0.1",
                                   "--step", "0.2", "--steps", "2"], "--step"),
    ("trace of a rigid truss", ["trace", "{m}", "--drive", "B:y", "--step", "0.1",
                                "--steps", "2"], "rigid"),
    ("static subdivisions 10^8", ["static", "{m}", "--bar-model", "pinned-beam",
                                  "--subdivisions", "100000000"], "--subdivisions"),
    ("modes subdivisions 10^9", ["modes", "{m}", "--bar-model", "pinned-beam",
                                 "--subdivisions", "1000000000"], "--subdivisions"),
    ("buckling subdivisions 10^9", ["buckling", "{m}", "--subdivisions", "1000000000"],
     "--subdivisions"),
    ("simulate steps 10^9", ["simulate", "{act}", "--motion", "{mot}", "--steps",
                             "1000000000"], "steps"),
    ("transient dt 1e-9", ["transient", "{act}", "--motion", "{mot}", "--dt", "1e-9"], "--dt"),
    ("transient dt 1e-300", ["transient", "{act}", "--motion", "{mot}", "--dt", "1e-300"],
     "--dt"),
    ("transient t-end 1e12", ["transient", "{act}", "--motion", "{mot}", "--t-end", "1e12"],
     "--t-end"),
    ("transient damping nan", ["transient", "{act}", "--motion", "{mot}", "--damping", "nan",
                               "0"], "--damping"),
    ("transient damping negative", ["transient", "{act}", "--motion", "{mot}", "--damping",
                                    "0", "-1"], "--damping"),
    ("transient no motion", ["transient", "{act}"], "--motion"),
    ("simulate steps without motion", ["simulate", "{act}", "--steps", "5"], "--steps"),
    ("simulate motion missing", ["simulate", "{act}", "--motion", "nowhere.toml"], "not found"),
    ("simulate motion is a folder", ["simulate", "{act}", "--motion", "{out}"], "folder"),
    ("simulate motion is a pipe", ["simulate", "{act}", "--motion", "{fifo}"], "pipe"),
    ("simulate motion is /dev/zero", ["simulate", "{act}", "--motion", "/dev/zero"], "device"),
    ("simulate motion empty path", ["simulate", "{act}", "--motion", ""], "--motion"),
    ("simulate motion is the model", ["simulate", "{act}", "--motion", "{act}"], "motion"),
    ("simulate motion without active members", ["simulate", "{m}", "--motion", "{mot}"],
     "active"),
    ("postcritical monitor bad", ["postcritical", "{m}", "--monitor", "B:q"], "NODE:AXIS"),
    ("postcritical monitor unknown", ["postcritical", "{m}", "--monitor", "Z:y"], "Z"),
    ("static unknown bar model", ["static", "{m}", "--bar-model", "rope"], "invalid choice"),
    ("static unknown solver", ["static", "{m}", "--solver", "magic"], "invalid choice"),
    ("modes unknown mass", ["modes", "{m}", "--mass", "heavy"], "invalid choice"),
    ("unknown command", ["analyse", "{m}"], "invalid choice"),
    ("no command", [], "required"),
    ("unknown option", ["static", "{m}", "--colour", "red"], "unrecognized"),
    ("option typo", ["static", "{m}", "--jsn", "x.json"], "unrecognized"),
    ("missing model", ["static"], "model"),
    ("two models", ["static", "{m}", "{m}"], "unrecognized"),
    ("model missing", ["static", "nowhere.toml"], "not found"),
    ("model empty path", ["static", ""], "empty"),
    ("model is a folder", ["static", "{out}"], "folder"),
    ("model is /dev/zero", ["static", "/dev/zero"], "device"),
    ("model is /dev/urandom", ["static", "/dev/urandom"], "device"),
    ("model is /dev/null", ["static", "/dev/null"], "device"),
    ("model is a named pipe", ["static", "{fifo}"], "named pipe"),
    ("model path with NUL", ["static", "a\0b.toml"], "NUL"),
    ("model path very long", ["static", "x" * 5000 + ".toml"], "too long"),
    ("model dangling link", ["static", "{link}"], "not found"),
    ("model is a looping link", ["static", "{loop}"], "loop"),
    ("validate empty cases folder", ["validate", "--cases", "{out}/empty", "--out",
                                     "{out}/r"], "--cases"),
    ("validate cases folder missing", ["validate", "--cases", "{out}/none", "--out",
                                       "{out}/r"], "--cases"),
    ("validate cases is a file", ["validate", "--cases", "{file}", "--out", "{out}/r"],
     "--cases"),
    ("validate unknown case", ["validate", "--case", "no-such-case", "--out", "{out}/r"],
     "no-such-case"),
    ("validate out is a file", ["validate", "--case", "x", "--out", "{file}"], "--out"),
    ("validate out empty", ["validate", "--out", ""], "--out"),
]

#: Output options of each command and whether they name a file or a folder.
OUTPUTS = [
    (_STATIC, "--json", "file"), (_STATIC, "--vtk", "file"),
    (_MODES, "--json", "file"), (_MODES, "--vtk", "dir"),
    (_BUCK, "--json", "file"), (_BUCK, "--vtk", "dir"),
    (_MECH, "--json", "file"), (_MECH, "--vtk", "dir"),
    (_TRACE, "--json", "file"), (_TRACE, "--vtk", "dir"), (_TRACE, "--plot", "file"),
    (_SIM, "--json", "file"), (_SIM, "--npz", "file"), (_SIM, "--vtk", "dir"),
    (_SIM, "--plots", "dir"),
    (_ELA, "--json", "file"), (_ELA, "--vtk", "dir"),
    (_TRA, "--json", "file"), (_TRA, "--plot", "file"), (_TRA, "--vtk", "dir"),
    (_ACTS, "--json", "file"),
    (_POST, "--json", "file"), (_POST, "--vtk", "dir"), (_POST, "--plot", "file"),
]

#: Bad output paths: (id, path template, kinds it applies to).
BAD_OUTPUT_PATHS = [
    ("empty", "", ("file", "dir")),
    ("blank", "   ", ("file", "dir")),
    ("existing folder", "{out}", ("file",)),
    ("existing file as folder", "{file}", ("dir",)),
    ("under a file", "{file}/x.out", ("file", "dir")),
    ("read-only file system", "/proc/trussfe-x.out", ("file", "dir")),
    ("device", "/dev/null", ("file",)),
    ("overwrites the model", "{model}", ("file",)),
]
