# SPDX-License-Identifier: MIT
"""``report.md`` and a self-contained ``report.html`` (inline CSS, figures as base64 PNG)."""
from __future__ import annotations

import base64
import datetime as _dt
import html
import re
from pathlib import Path

from .._version import __version__
from ..io.output import atomic_dir
from .engine import CaseResult, QuantityResult

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,sans-serif;max-width:75em;margin:2em auto;
padding:0 1em;color:#222;line-height:1.4}
table{border-collapse:collapse;margin:.8em 0;font-size:.9em}
th,td{border:1px solid #ccc;padding:.25em .5em;text-align:right;vertical-align:top}
th{background:#f0f0f0} td.l,th.l{text-align:left}
.pass{color:#11691b;font-weight:600} .fail,.error{color:#b00020;font-weight:600}
.differs{color:#8a5a00;font-weight:600}
section.case{border-top:2px solid #ddd;margin-top:2em}
.notes{background:#fafafa;border-left:4px solid #ccd;padding:.3em 1em}
code{background:#f3f3f3;padding:0 .2em} img{max-width:100%}
"""

STATUS_TEXT = {"pass": "pass", "fail": "FAIL", "error": "ERROR",
               "differs": "differs as documented"}


def _fmt(x: float | None, digits: int = 6) -> str:
    if x is None:
        return "–"
    return f"{x:.{digits}g}"


def _tol(r: QuantityResult) -> str:
    q = r.quantity
    parts = []
    if q.rtol:
        parts.append(f"rtol {q.rtol:g}")
    if q.atol:
        parts.append(f"atol {q.atol:g}")
    return ", ".join(parts)


def _source(r: QuantityResult) -> str:
    """The source cell: a regression value says so; a documented deviation names the value
    its explanation predicts, where that comes from, and how close trussfe is to it."""
    q = r.quantity
    text = ("regression value (trussfe's own output): " if q.kind == "regression" else "") + \
        q.source + (f" — {q.note}" if q.note else "")
    if q.expect == "differ":
        tol = ", ".join(p for p in (f"rtol {q.explained_rtol:g}" if q.explained_rtol else "",
                                    f"atol {q.explained_atol:g}" if q.explained_atol else "") if p)
        text += (f" — explained: {_fmt(q.explained, 8)} "
                 f"({'regression value: ' if q.explained_kind == 'regression' else ''}"
                 f"{q.explained_source}), relative error {_fmt(r.explained_rel_error, 3)}, "
                 f"{tol}")
    return text


def _rows(res: CaseResult) -> list[list[str]]:
    rows = []
    for r in res.quantities:
        q = r.quantity
        rows.append([q.name, _fmt(q.thesis_matlab), _fmt(q.thesis_mscpal), _fmt(r.value, 8),
                     _fmt(q.reference, 8), _fmt(r.rel_error, 3), _tol(r),
                     STATUS_TEXT[r.status] + (f": {r.message}" if r.message else ""),
                     _source(r)])
    return rows


_HEAD = ["quantity", "thesis MATLAB", "thesis MSC/PAL", "trussfe", "reference",
         "relative error", "tolerance", "result", "source"]


#: The verdict of a case, as the summary groups them.
REPRODUCES = "reproduces the source"
DEVIATES = "reproduces, with documented deviations (explained)"
FAILS = "fails"


def verdict(res: CaseResult) -> str:
    """:data:`FAILS` when a check fails; :data:`DEVIATES` when it passes and some quantity
    is a documented deviation (which passes only while it matches its explanation);
    :data:`REPRODUCES` otherwise."""
    if not res.passed:
        return FAILS
    return DEVIATES if any(q.status == "differs" for q in res.quantities) else REPRODUCES


def _verdict_class(res: CaseResult) -> str:
    return {REPRODUCES: "pass", DEVIATES: "differs", FAILS: "fail"}[verdict(res)]


def _summary(results: list[CaseResult]) -> tuple[int, int, int, int, int]:
    v = [verdict(r) for r in results]
    qs = [q.quantity for r in results for q in r.quantities]
    n_dev = sum(q.expect == "differ" for q in qs)
    n_reg = sum(q.kind == "regression" for q in qs)
    return v.count(REPRODUCES), v.count(DEVIATES), v.count(FAILS), n_dev, n_reg


def _counts(results: list[CaseResult]) -> tuple[str, str]:
    """The summary line in two parts: the case counts, then the kinds of check."""
    n_rep, n_dev_cases, n_fail, n_dev, n_reg = _summary(results)
    return (f"{len(results)} cases: {n_rep + n_dev_cases} pass, {n_fail} fail",
            f" — {n_rep} reproduce their sources; {n_dev_cases} reproduce them with "
            f"documented deviations ({n_dev} quantities, each checked against its "
            f"explanation); {n_reg} regression values (references recorded from trussfe's "
            "own output).")


def _worst(res: CaseResult) -> str:
    """Worst relative error of the checks that reproduce their source (a documented
    deviation is meant to differ from it, and has its own column)."""
    errs = [q.rel_error for q in res.quantities
            if q.rel_error is not None and q.quantity.expect != "differ"]
    return _fmt(max(errs), 2) if errs else "–"


def _deviations(res: CaseResult) -> str:
    """How many documented deviations a case has, and the worst error against their
    explanations."""
    devs = [q for q in res.quantities if q.quantity.expect == "differ"]
    if not devs:
        return "–"
    errs = [q.explained_rel_error for q in devs if q.explained_rel_error is not None]
    return f"{len(devs)}" + (f" (within {_fmt(max(errs), 2)} of explained)" if errs else "")


# ------------------------------------------------------------------ markdown
def markdown_report(results: list[CaseResult], figure_paths: dict[tuple[str, str], str]) -> str:
    """The Markdown report (figures linked as files in ``figures/``)."""
    out = ["# trussfe validation report", "",
           f"trussfe {__version__}. {''.join(_counts(results))}", "",
           "| case | title | result | checks | worst relative error (reproduced checks) "
           "| documented deviations |",
           "|---|---|---|---|---|---|"]
    for r in results:
        out.append(f"| [{r.case.id}](#{_anchor(r.case.id)}) | {_md_cell(r.case.title)} | "
                   f"{verdict(r).upper() if verdict(r) == FAILS else verdict(r)} | "
                   f"{len(r.quantities)} | {_worst(r)} | {_deviations(r)} |")
    for r in results:
        out += ["", f"## {r.case.id}", "", f"**{r.case.title}** — {verdict(r)}", ""]
        if r.error:
            out += [f"Error: `{r.error}`", ""]
        if r.quantities:
            out.append("| " + " | ".join(_HEAD) + " |")
            out.append("|" + "---|" * len(_HEAD))
            out += ["| " + " | ".join(_md_cell(c) for c in row) + " |" for row in _rows(r)]
            out.append("")
        if r.case.notes.strip():
            out += [r.case.notes.strip(), ""]
        for name in r.figures:
            rel = figure_paths.get((r.case.id, name))
            if rel:
                out += [f"![{name}]({rel})", ""]
    return "\n".join(out) + "\n"


def _md_cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _anchor(text: str) -> str:
    return re.sub(r"[^a-z0-9._-]", "", text.lower().replace(" ", "-"))


# ------------------------------------------------------------------ html
def _inline(text: str) -> str:
    """Escape, then the inline Markdown of notes: `code`, **bold**, *em*, [text](url)."""
    t = html.escape(text, quote=False)
    t = re.sub(r"`([^`]+)`", r"<code>\1</code>", t)
    t = re.sub(r"\*\*([^*]+)\*\*", r"<strong>\1</strong>", t)
    t = re.sub(r"(?<![\w*])\*([^*\s][^*]*)\*(?!\w)", r"<em>\1</em>", t)
    t = re.sub(r"\[([^\]]+)\]\(([^)\s]+)\)", lambda m: f'<a href="{html.escape(m.group(2))}">'
               f"{m.group(1)}</a>", t)
    return t


def markdown_to_html(text: str) -> str:
    """The small Markdown subset used in case notes: paragraphs, ``-`` lists, ``#`` headings,
    and inline code, emphasis and links.

    Examples
    --------
    >>> markdown_to_html("Load **44.498 N**:\\n\\n- a `b`\\n- c")
    '<p>Load <strong>44.498 N</strong>:</p>\\n<ul><li>a <code>b</code></li><li>c</li></ul>'
    """
    blocks = re.split(r"\n\s*\n", text.strip())
    out = []
    for block in blocks:
        lines = block.splitlines()
        if all(re.match(r"\s*[-*] ", ln) or (i and ln.startswith("  "))
               for i, ln in enumerate(lines)):
            items: list[str] = []
            for ln in lines:
                if re.match(r"\s*[-*] ", ln):
                    items.append(re.sub(r"^\s*[-*] ", "", ln))
                else:
                    items[-1] += " " + ln.strip()
            out.append("<ul>" + "".join(f"<li>{_inline(i)}</li>" for i in items) + "</ul>")
        elif m := re.match(r"(#{1,4})\s+(.*)", block):
            level = min(len(m.group(1)) + 2, 6)
            out.append(f"<h{level}>{_inline(m.group(2))}</h{level}>")
        else:
            out.append("<p>" + _inline(" ".join(ln.strip() for ln in lines)) + "</p>")
    return "\n".join(out)


def html_report(results: list[CaseResult]) -> str:
    """One self-contained HTML page."""
    cases, kinds = _counts(results)
    e = html.escape
    parts = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
             "<title>trussfe validation report</title>", f"<style>{_CSS}</style></head><body>",
             "<h1>trussfe validation report</h1>",
             f"<p>trussfe {e(__version__)}. "
             f'<span id="summary-counts">{e(cases)}</span>{e(kinds)}</p>',
             '<table id="summary"><thead><tr><th class="l">case</th><th class="l">title</th>'
             '<th class="l">result</th><th>checks</th>'
             "<th>worst relative error (reproduced checks)</th>"
             '<th class="l">documented deviations</th></tr></thead><tbody>']
    for r in results:
        parts.append(f'<tr><td class="l"><a href="#{e(_anchor(r.case.id))}">{e(r.case.id)}</a>'
                     f'</td><td class="l">{e(r.case.title)}</td>'
                     f'<td class="l {_verdict_class(r)}">{e(verdict(r))}</td>'
                     f"<td>{len(r.quantities)}</td><td>{_worst(r)}</td>"
                     f'<td class="l">{e(_deviations(r))}</td></tr>')
    parts.append("</tbody></table>")
    for r in results:
        parts.append(f'<section class="case" id="{e(_anchor(r.case.id))}" '
                     f'data-status="{r.status}"><h2>{e(r.case.id)}</h2>'
                     f'<p><strong>{e(r.case.title)}</strong> — '
                     f'<span class="{_verdict_class(r)}">{e(verdict(r))}</span></p>')
        if r.error:
            parts.append(f'<p class="error">Error: {e(r.error)}</p>')
        if r.quantities:
            parts.append('<table class="quantities"><thead><tr>' + "".join(
                f'<th class="{"l" if i in (0, 7, 8) else ""}">{e(h)}</th>'
                for i, h in enumerate(_HEAD)) + "</tr></thead><tbody>")
            for row, qr in zip(_rows(r), r.quantities):
                cells = []
                for i, c in enumerate(row):
                    cls = "l" if i in (0, 8) else ""
                    if i == 7:
                        cls = f"l {qr.status}"
                    cells.append(f'<td class="{cls}">{e(c)}</td>')
                parts.append(f'<tr data-status="{qr.status}">' + "".join(cells) + "</tr>")
            parts.append("</tbody></table>")
        if r.case.notes.strip():
            parts.append(f'<div class="notes">{markdown_to_html(r.case.notes)}</div>')
        for name, png in r.figures.items():
            data = base64.b64encode(png).decode("ascii")
            parts.append(f'<figure><img alt="{e(name)}" src="data:image/png;base64,{data}">'
                         f"<figcaption>{e(name)}</figcaption></figure>")
        parts.append("</section>")
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"


def timings(results: list[CaseResult]) -> str:
    """When the suite ran and how long each case took.

    Kept out of ``report.md`` and ``report.html`` so that the reports are a function of the
    results alone: two runs of the same version give byte-identical reports (diffable
    against a reference), whatever the load of the machine.
    """
    lines = [f"# trussfe {__version__} validation run, "
             f"{_dt.datetime.now(_dt.timezone.utc):%Y-%m-%d %H:%M:%S} UTC",
             "# case, run time (s)"]
    lines += [f"{r.case.id}, {r.seconds:.3f}" for r in results]
    return "\n".join(lines) + "\n"


def write_report(results: list[CaseResult], out_dir: str | Path) -> tuple[Path, Path]:
    """Write ``out_dir/report.md``, ``out_dir/report.html``, ``out_dir/figures/`` and
    ``out_dir/timings.txt`` atomically; returns the two report paths."""
    out_dir = Path(out_dir)
    with atomic_dir(out_dir) as tmp:
        figure_paths: dict[tuple[str, str], str] = {}
        for r in results:
            for name, png in r.figures.items():
                safe = re.sub(r"[^A-Za-z0-9_.-]", "_", f"{r.case.id}-{name}")
                if not safe.endswith(".png"):
                    safe += ".png"
                (tmp / "figures").mkdir(exist_ok=True)
                (tmp / "figures" / safe).write_bytes(png)
                figure_paths[(r.case.id, name)] = f"figures/{safe}"
        (tmp / "report.md").write_text(markdown_report(results, figure_paths), encoding="utf-8")
        (tmp / "report.html").write_text(html_report(results), encoding="utf-8")
        (tmp / "timings.txt").write_text(timings(results), encoding="utf-8")
    return out_dir / "report.md", out_dir / "report.html"
