"""Validation engine (trussfe.validation) and ``trussfe validate``: cases, report, exit status.

The report is checked by parsing the HTML with :mod:`html.parser`.
"""
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pytest

from trussfe.cli import main
from trussfe.cli.cmd_validate import default_cases_dir
from trussfe.errors import InputError
from trussfe.validation import load_case, load_cases, lookup, run_cases, write_report


class ReportParser(HTMLParser):
    """Collects the summary rows, per-case statuses, quantity rows and embedded images."""

    def __init__(self):
        super().__init__()
        self.summary_rows, self.sections, self.images, self.quantity_rows = [], {}, [], []
        self._in_summary = self._row = None
        self._cell = None
        self._stack = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self._stack.append(tag)
        if tag == "table" and a.get("id") == "summary":
            self._in_summary = True
        if tag == "section":
            self.sections[a["id"]] = a["data-status"]
        if tag == "tr":
            self._row = []
            if "data-status" in a:
                self.quantity_rows.append(a["data-status"])
        if tag in ("td", "th"):
            self._cell = ""
        if tag == "img":
            self.images.append(a["src"])

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._row is not None:
            self._row.append(self._cell.strip())
            self._cell = None
        if tag == "tr" and self._in_summary and self._row and "case" not in self._row[:1]:
            self.summary_rows.append(self._row)
        if tag == "table":
            self._in_summary = False

    def handle_data(self, data):
        if self._cell is not None:
            self._cell += data


def parse_report(path):
    p = ReportParser()
    p.feed(Path(path).read_text(encoding="utf-8"))
    return p


def test_lookup_paths():
    d = {"nodes": {"N1": {"reaction": [1.0, -2.0, 3.0]}, "b1.N4": {"x": [[5]]}},
         "t.a": {"b.c": 7}, "t": {"z": 8}}
    assert lookup(d, "t.a.b.c") == 7 and lookup(d, "t.z") == 8     # flat dotted keys
    assert lookup(d, "nodes.N1.reaction.2") == 3.0
    assert lookup(d, "nodes.N1.reaction[1]") == -2.0
    assert lookup(d, "nodes.N1.reaction[-1]") == 3.0
    assert lookup(d, 'nodes."b1.N4".x[0][0]') == 5
    for bad in ("nodes.N2.reaction[0]", "nodes.N1.reaction[3]", "nodes.N1[0]", "", "nodes..N1"):
        with pytest.raises(KeyError):
            lookup(d, bad)


def test_builtin_cases_pass_and_report(tmp_path):
    """The static thesis cases pass (Tables 3.2, 5.2–5.4 within 0.01 % / 0.02 %), and the HTML
    report lists each case with its status and quantity rows."""
    every = load_cases(default_cases_dir())          # every shipped case file reads
    # run the static thesis cases here; the other analyses' cases are run by their own tests
    cases = [c for c in every if c.file.name.startswith(("lacy_", "chain_"))]
    ids = {c.id for c in cases}
    assert {"lacy-table-3-2", "lacy-table-5-2", "lacy-table-5-3", "lacy-table-5-4"} <= ids
    results = run_cases(cases, progress=False)
    bad = [(r.case.id, r.error, [(q.quantity.name, q.value, q.message) for q in r.quantities
                                 if q.failed]) for r in results if not r.passed]
    assert not bad
    md, page = write_report(results, tmp_path / "out")
    rep = parse_report(page)
    assert [row[0] for row in rep.summary_rows] == [c.id for c in cases]
    from trussfe.validation.report import DEVIATES, REPRODUCES, verdict
    assert [row[2] for row in rep.summary_rows] == [verdict(r) for r in results]
    assert {row[2] for row in rep.summary_rows} <= {REPRODUCES, DEVIATES}
    # a documented deviation's error against the stated source is not the "worst error"
    for row, r in zip(rep.summary_rows, results):
        if verdict(r) == DEVIATES:
            assert "of explained" in row[5]
    assert set(rep.sections) == {c.id for c in cases}
    n_quantities = sum(len(c.quantities) for c in cases)
    assert len(rep.quantity_rows) == n_quantities
    # cases with `plot` get a figure of the structure coloured by the member result
    n_plots = sum(c.plot is not None for c in cases)
    n_figures = sum(len(r.figures) for r in results)     # plots + figures python cases return
    assert n_plots >= 4 and len(rep.images) == n_figures >= n_plots
    assert all(src.startswith("data:image/png;base64,iVBOR") for src in rep.images)
    assert len(list((tmp_path / "out" / "figures").glob("*.png"))) == n_figures
    # the documented deviations are shown as such (46.0 N: all 7 values 3.4 % high)
    stated = next(r for r in results if r.case.id == "lacy-table-5-2-stated-load")
    assert all(q.status == "differs" for q in stated.quantities)
    np.testing.assert_allclose([q.value / q.quantity.reference for q in stated.quantities],
                               46.0 / 44.498, rtol=2e-4)
    assert "lacy-table-3-2" in md.read_text()


def _write_case(folder, name, body):
    folder.mkdir(exist_ok=True)
    (folder / name).write_text(body, encoding="utf-8")


CASE_PY = '''[case]
id = "{id}"
title = "python case"
python = "test_validate:{func}"
options = {{ value = {value} }}
notes = """A note with **bold** and `code`.

- item one
- item two"""

[[quantities]]
name = "x"
path = "x"
reference = 2.0
source = "analytic"
rtol = 1e-9
'''


def numbers(value):
    """A python case function returning a number and a figure."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import tempfile
    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, value])
    path = Path(tempfile.mkdtemp()) / "line.png"
    fig.savefig(path)
    plt.close(fig)
    return {"x": value, "figures": {"line": str(path)}}


def broken(value):
    raise RuntimeError("boom")


def test_exit_status_and_figures(tmp_path):
    """0 when all pass; 1 when a value misses its tolerance or a case errors; figures are
    embedded as base64 PNG; notes rendered as HTML."""
    cases = tmp_path / "cases"
    _write_case(cases, "a.toml", CASE_PY.format(id="good", func="numbers", value=2.0))
    out = tmp_path / "rep"
    assert main(["validate", "--cases", str(cases), "--out", str(out), "--no-progress"]) == 0
    rep = parse_report(out / "report.html")
    assert rep.sections == {"good": "pass"}
    assert len(rep.images) == 1 and rep.images[0].startswith("data:image/png;base64,iVBOR")
    html = (out / "report.html").read_text()
    assert "<strong>bold</strong>" in html and "<li>item two</li>" in html
    assert (out / "figures").is_dir() and "](figures/" in (out / "report.md").read_text()

    _write_case(cases, "b.toml", CASE_PY.format(id="off", func="numbers", value=2.001))
    assert main(["validate", "--cases", str(cases), "--out", str(out), "--no-progress"]) == 1
    assert parse_report(out / "report.html").sections == {"good": "pass", "off": "fail"}

    _write_case(cases, "b.toml", CASE_PY.format(id="err", func="broken", value=2.0))
    assert main(["validate", "--cases", str(cases), "--out", str(out), "--no-progress"]) == 1
    assert parse_report(out / "report.html").sections["err"] == "error"
    # --case selects
    assert main(["validate", "--cases", str(cases), "--out", str(out), "--no-progress",
                 "--case", "good"]) == 0


@pytest.mark.parametrize("body,item", [
    ("[case\nid = 1", "malformed TOML"),
    ('[case]\nid = "a"\nanalysis = "static"\nmodel = "x.toml"\n', "at least one quantity"),
    ('[case]\nid = "a"\n[[quantities]]\nname="x"\npath="x"\nreference=1\nrtol=1e-3\n',
     "give 'analysis'"),
    ('[case]\nid = "a"\npython = "m:f"\nmodel = "m.toml"\n[[quantities]]\nname="x"\n'
     'path="x"\nreference=1\nrtol=1e-3\n', "python case builds its own model"),
    ('[case]\nid = "a"\npython = "m:f"\n[[quantities]]\nname="x"\npath="x"\nreference=1\n',
     "tolerance"),
    ('[case]\nid = "a"\npython = "m:f"\n[[quantities]]\nname="x"\npath="x"\nreference=1\n'
     'rtol=1e-3\nexpect="diff"\n', "did you mean 'differ'"),
    ('[case]\nid = "a"\npyton = "m:f"\n', "did you mean 'python'"),
    ('[cases]\nid = "a"\n', "did you mean 'case'"),
    ('[case]\nid = "a"\npython = "m:f"\nplot = "axial_force"\n[[quantities]]\nname="x"\n'
     'path="x"\nreference=1\nrtol=1e-3\n', "case.plot"),
])
def test_bad_case_files(tmp_path, body, item, capsys):
    """A malformed case file is bad input: InputError naming the file, exit status 2."""
    f = tmp_path / "cases" / "bad.toml"
    _write_case(tmp_path / "cases", "bad.toml", body)
    with pytest.raises(InputError, match=item):
        load_case(f)
    assert main(["validate", "--cases", str(tmp_path / "cases"), "--out",
                 str(tmp_path / "r"), "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("trussfe: error: ") and "bad.toml" in err
    assert not (tmp_path / "r").exists()          # nothing written


def test_unknown_case_id_and_analysis(tmp_path, capsys):
    assert main(["validate", "--case", "lacy-tabel-3-2", "--out", str(tmp_path / "r"),
                 "--no-progress"]) == 2
    assert "did you mean 'lacy-table-3-2'" in capsys.readouterr().err
    cases = tmp_path / "cases"
    _write_case(cases, "a.toml", '[case]\nid = "a"\nanalysis = "statik"\n'
                'catalogue = "two_bar"\n[[quantities]]\nname="x"\npath="x"\nreference=1\n'
                'rtol=1e-3\n')
    assert main(["validate", "--cases", str(cases), "--out", str(tmp_path / "r"),
                 "--no-progress"]) == 2
    assert "did you mean 'static'" in capsys.readouterr().err
    _write_case(cases, "a.toml", '[case]\nid = "a"\nanalysis = "static"\n'
                'catalogue = "to_bar"\n[[quantities]]\nname="x"\npath="x"\nreference=1\n'
                'rtol=1e-3\n')
    assert main(["validate", "--cases", str(cases), "--out", str(tmp_path / "r"),
                 "--no-progress"]) == 2
    assert "did you mean 'two_bar'" in capsys.readouterr().err


def test_catalogue_case_bad_parameters_is_a_case_error(tmp_path):
    """Parameters the catalogue function rejects make the case fail (status error, exit 1)."""
    cases = tmp_path / "cases"
    _write_case(cases, "a.toml", '[case]\nid = "a"\nanalysis = "static"\n'
                'catalogue = "double_octahedron"\nparameters = { active_lengths = [3.0, 3.0, '
                '3.0] }\n[[quantities]]\nname="x"\npath="x"\nreference=1\nrtol=1e-3\n')
    assert main(["validate", "--cases", str(cases), "--out", str(tmp_path / "r"),
                 "--no-progress"]) == 1
    rep = parse_report(tmp_path / "r" / "report.html")
    assert rep.sections == {"a": "error"}


from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

_CASE_KEYS = ["case", "quantities", "id", "title", "analysis", "python", "model", "catalogue",
              "parameters", "options", "notes", "tags", "plot", "name", "path", "reference",
              "source", "rtol", "atol", "expect", "static", "two_bar", "m:f", "differ"]
_values = st.recursive(
    st.one_of(st.integers(-2, 2), st.floats(), st.booleans(), st.sampled_from(_CASE_KEYS)),
    lambda inner: st.one_of(st.lists(inner, max_size=3),
                            st.dictionaries(st.sampled_from(_CASE_KEYS), inner, max_size=4)),
    max_leaves=15)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.dictionaries(st.sampled_from(_CASE_KEYS), _values, max_size=4))
def test_fuzz_case_reader(data):
    """Any TOML-shaped case document: a Case or an InputError, never another exception."""
    from trussfe.validation.cases import _parse

    try:
        case = _parse(data, Path("fuzz.toml"))
    except InputError as err:
        assert "\n" not in str(err)
    else:
        assert case.quantities and case.id


def test_compare_semantics():
    """|v − r| ≤ atol + rtol·|r|; a documented deviation passes only while it holds: outside
    the reference's tolerance and within the explained value's."""
    from trussfe.validation.cases import Quantity
    from trussfe.validation.engine import compare

    q = Quantity(name="q", path="x", reference=100.0, rtol=1e-3)
    assert compare(q, np.float64(100.1)).status == "pass"        # exactly at the bound
    assert compare(q, 100.2).status == "fail"
    assert compare(q, 100.2).rel_error == pytest.approx(2e-3)
    assert compare(q, float("nan")).status == "error"
    assert compare(q, "100").status == "error"
    assert compare(q, True).status == "error"
    z = Quantity(name="z", path="x", reference=0.0, atol=1e-9)
    r = compare(z, 5e-10)
    assert r.status == "pass" and r.rel_error is None
    d = Quantity(name="d", path="x", reference=100.0, rtol=1e-3, expect="differ",
                 explained=103.38, explained_source="x 46/44.498", explained_rtol=2e-4)
    held = compare(d, 103.39)
    assert held.status == "differs" and not held.failed
    assert held.explained_rel_error == pytest.approx(0.01 / 103.38)
    gone = compare(d, 100.05)                        # back within the stated source's tolerance
    assert gone.status == "fail" and "gone" in gone.message
    wrong = compare(d, 105.0)                        # deviates, but not as explained
    assert wrong.status == "fail" and "explained" in wrong.message
    bare = Quantity(name="b", path="x", reference=100.0, rtol=1e-3, expect="differ")
    assert compare(bare, 103.0).failed                # a deviation must say what explains it


@pytest.mark.parametrize("extra, message", [
    ('expect = "differ"', "needs 'explained'"),
    ('expect = "differ"\nexplained = 2.2', "needs 'explained_source'"),
    ('expect = "differ"\nexplained = 2.2\nexplained_source = "s"', "explained value's tolerance"),
    ('explained = 2.2', "applies to a documented deviation"),
    ('kind = "recorded"', "'independent' or 'regression'"),
])
def test_documented_deviation_needs_its_explanation(tmp_path, extra, message):
    """A case file's documented deviation must name its explained value, source and
    tolerance; the explained keys and an unknown kind are refused elsewhere."""
    body = CASE_PY.format(id="c", func="numbers", value=2.0) + extra + "\n"
    _write_case(tmp_path, "c.toml", body)
    with pytest.raises(InputError, match=message):
        load_case(tmp_path / "c.toml")


def test_command_runs_cases_that_write_working_files(tmp_path):
    """`trussfe validate` (inside its output transaction) runs a catalogue case, whose model
    file is written to a working folder and read back, and a study that writes its figure and
    reads it back; both pass against their references (Lacy Table 5.2 ×10 bays; Hortobágyi
    section 6), and the report holds the study's figure."""
    out = tmp_path / "r"
    assert main(["validate", "--case", "chain-10-bays-statics", "--case",
                 "hortobagyi-section6-unfolding", "--out", str(out), "--no-progress"]) == 0
    assert (out / "report.html").is_file()
    assert any(p.name.startswith("hortobagyi-section6-unfolding") for p in
               (out / "figures").iterdir())


def test_builtin_case_models_do_not_warn_the_user(tmp_path, capsys):
    """The built-in Hortobágyi section-4 case analyses a folded mechanism whose joint 1 lies
    on support 4 on purpose: `trussfe validate` prints its result and no warning about the
    suite's own model; -v shows it; a folder of one's own cases keeps its warnings."""
    assert main(["validate", "--case", "hortobagyi-section4", "--out", str(tmp_path / "a"),
                 "--no-progress"]) == 0
    out, err = capsys.readouterr()
    assert "1/1 cases pass" in out and err == ""
    assert main(["-v", "validate", "--case", "hortobagyi-section4", "--out",
                 str(tmp_path / "b"), "--no-progress"]) == 0
    assert "'1' and '4' coincide" in capsys.readouterr().err
    own = tmp_path / "own"
    own.mkdir()
    model = Path(__file__).resolve().parents[1] / "meshes" / "mech_hortobagyi_sec4.toml"
    (own / "rank.toml").write_text(
        f'[case]\nid = "rank"\ntitle = "rank"\nanalysis = "mechanism"\n'
        f'model = "{model.as_posix()}"\n\n[[quantities]]\nname = "rank"\npath = "rank"\n'
        'reference = 2\nsource = "Hortobágyi (1999) section 4"\nrtol = 0\n',
        encoding="utf-8")
    assert main(["validate", "--cases", str(own), "--out", str(tmp_path / "c"),
                 "--no-progress"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and "'1' and '4' coincide" in err[0]


def test_report_labels_regression_values_and_explanations(tmp_path):
    """The report marks references recorded from trussfe's own output as regression values,
    counts them, and shows each documented deviation's explained value and its source."""
    cases = load_cases(default_cases_dir(), ["hortobagyi-section4", "lacy-table-5-2-stated-load"])
    results = run_cases(cases, progress=False)
    assert all(r.passed for r in results)
    md, page = write_report(results, tmp_path / "out")
    text = md.read_text(encoding="utf-8")
    n_reg = sum(q.kind == "regression" for c in cases for q in c.quantities)
    n_dev = sum(q.expect == "differ" for c in cases for q in c.quantities)
    assert n_reg == 2 and n_dev == 8
    assert f"0 reproduce their sources; 2 reproduce them with documented deviations " \
           f"({n_dev} quantities, each checked against its explanation); " \
           f"{n_reg} regression values" in text
    assert text.count("regression value (trussfe's own output)") == n_reg
    assert text.count("explained: ") == n_dev and "× 46.0/44.498" in text
    assert text.count("differs as documented") == n_dev
    assert "regression values" in page.read_text(encoding="utf-8")


def test_a_case_without_a_figure_shows_its_model():
    """An analysis case with no figure of its own gets the picture of its model
    (``trussfe show``) in the report; one with figures keeps only its own."""
    cases = load_cases(default_cases_dir(), ["buckling_euler_column", "postcritical_von_mises"])
    plain, own = run_cases(cases, progress=False)
    assert list(plain.figures) == ["model"]
    assert plain.figures["model"].startswith(b"\x89PNG")
    assert own.figures and "model" not in own.figures


def test_a_python_case_names_the_model_it_pictures(tmp_path):
    """``picture = MODEL`` gives a study case that draws no figure the picture of its model;
    on an analysis case (which shows its own model) it is refused in one line."""
    from trussfe.errors import InputError
    case, = load_cases(default_cases_dir(), ["fourbar-closed-form"])
    assert case.picture is not None and case.picture.name == "mech_fourbar.toml"
    result, = run_cases([case], progress=False)
    assert list(result.figures) == ["model"]
    bad = tmp_path / "bad.toml"
    model = Path(__file__).resolve().parents[1] / "meshes" / "triangular_truss_static.toml"
    bad.write_text(f'[case]\nid = "x"\ntitle = "x"\nanalysis = "static"\n'
                   f'model = "{model}"\npicture = "{model}"\n')
    with pytest.raises(InputError, match="case.picture"):
        load_cases(tmp_path)
