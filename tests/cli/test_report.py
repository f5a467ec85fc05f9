"""report.html of ``spindlesim run`` (issue 23, item 6 "One report to hand on"): one self-contained page
with the provenance, each analysis's key results and figures, failures and warnings.

The HTML is checked as text (every figure embedded as a data URI, no outside reference, provenance,
escaping of what comes from the deck) and in a real headless Chromium (tests/browser.py): the page
loads without console errors, every figure is decoded and displayed, the first screen is not blank,
it prints to PDF with each analysis on its own pages.  Without Chromium and chromedriver that test
skips, saying which is missing; .ci/run installs both on Debian.

SPINDLESIM_REPORT_ARTIFACTS=DIR keeps the screenshot and the PDFs in DIR to look at.
"""

from __future__ import annotations

import base64
import dataclasses
import hashlib
import html
import io
import logging
import os
import re
import stat
from importlib import resources
from pathlib import Path
from types import SimpleNamespace

import h5py
import pytest
from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.deck import DeckIssue, load_deck
from spindlesim.output.report import RunReport
from spindlesim.runs import run_info_for
from spindlesim.runs.status import file_mode
from tests.browser import Browser, find_browser

LINEAR_DECK = (resources.files("spindlesim.decks") / "spindle_linear.yaml").read_text()
TITLE = 'Spindle <script>alert("x")</script> & <b>co</b>'
IMG = re.compile(r'<img src="data:image/png;base64,([A-Za-z0-9+/=]+)"')


def _deck(folder: Path, analyses: str, text: str = LINEAR_DECK) -> Path:
    deck = folder / "deck.yaml"
    deck.write_text(re.sub(r"^title:.*$", f"title: '{TITLE}'", text, flags=re.M) + f"\nanalyses: [{analyses}]\n")
    return deck


@pytest.fixture(scope="module")
def run_ok(tmp_path_factory):
    """``spindlesim run`` of the linear-bearing spindle: static, modal, frf (a few seconds)."""
    folder = tmp_path_factory.mktemp("report")
    deck = _deck(folder, "static, modal, frf")
    res = CliRunner().invoke(main, ["run", str(deck), "-o", str(folder / "out")])
    assert res.exit_code == 0, res.output
    return SimpleNamespace(deck=deck, out=folder / "out", output=res.output,
                           html=(folder / "out" / "report.html").read_text(encoding="utf-8"))


def test_run_writes_one_self_contained_report(run_ok):
    page, out = run_ok.html, run_ok.out
    report = out / "report.html"
    assert str(report) in run_ok.output  # listed with the written files
    assert stat.S_IMODE(report.stat().st_mode) == file_mode() and not list(out.glob("*.tmp*"))
    # every figure of the run, embedded byte for byte, with a caption
    pngs = sorted(out.glob("*.png"))
    embedded = [base64.b64decode(s) for s in IMG.findall(page)]
    assert len(pngs) >= 4 and sorted(embedded) == sorted(p.read_bytes() for p in pngs)
    assert page.count("<figure>") == page.count("<figcaption>") == len(pngs)
    for p in pngs:
        assert f"({p.name})</figcaption>" in page
    # nothing from outside: no script, no style sheet, font or image by reference
    assert "<script" not in page and "<link rel=\"stylesheet\"" not in page and "@import" not in page
    assert "url(" not in page.split("</style>")[0]
    refs = re.findall(r'(?:src|href)="([^"]*)"', page)
    assert refs and all(r.startswith(("data:", "#")) for r in refs), [r[:40] for r in refs]
    # provenance: what the HDF5 files record
    for name in ("static", "frf"):  # the first and the last written: the range of times
        with h5py.File(out / f"{name}.h5") as f:
            attrs = {k: str(f.attrs[k]) for k in ("spindlesim_version", "deck_sha256", "command_line", "created_utc")}
        assert attrs["deck_sha256"] == hashlib.sha256(run_ok.deck.read_text().encode()).hexdigest()
        for key, value in attrs.items():
            assert html.escape(value) in page, key
    assert html.escape(str(run_ok.deck)) in page and "complete: 3 analyses finished" in page
    # the deck's title and text are escaped: the page has no element the deck wrote
    assert f"<h1>{html.escape(TITLE)}</h1>" in page and "<b>co</b>" not in page
    assert html.escape(run_ok.deck.read_text()) in page
    assert re.search(r"<details><summary>Deck text: .*</summary><pre class=\"deck\">", page)
    # each analysis: a section with the terminal's summary
    for name, words in (("static", "static stiffness at node"), ("modal", "frequency Hz"), ("frf", "peak")):
        section = page.split(f"<h2>{name} ")[1].split("</section>")[0]
        assert "Key results" in section and words in section, name


def test_failed_analyses_are_listed_with_their_error(tmp_path):
    """The run goes on after a failure; the report names each failed analysis and why; exit code 1."""
    singular = re.sub(r"K_N_m: \[\[.*\]\]", "K_N_m: [[0.0, 0.0], [0.0, 0.0]]", LINEAR_DECK)
    res = CliRunner().invoke(main, ["run", str(_deck(tmp_path, "static, modal", singular)), "-o", str(tmp_path / "o")])
    assert res.exit_code == 1, res.output
    page = (tmp_path / "o" / "report.html").read_text()
    assert "incomplete: 0 of 2 finished; 2 failed (static, modal)" in page
    failures = page.split('<section id="failures">')[1].split("</section>")[0]
    for name in ("static", "modal"):
        assert f"<strong>{name}</strong> failed: <span class=\"mono\">SingularRotorError: " in failures
    assert "<img" not in page


def test_an_interrupted_run_still_writes_its_report(tmp_path, monkeypatch):
    """Ctrl-C during an analysis: exit 130, the report lists what finished, what was interrupted, what not run."""
    import spindlesim.runs

    real = spindlesim.runs.perform_analysis

    def perform_analysis(name, *args, **kwargs):
        if name == "modal":
            raise KeyboardInterrupt
        return real(name, *args, **kwargs)

    monkeypatch.setattr(spindlesim.runs, "perform_analysis", perform_analysis)
    res = CliRunner().invoke(main, ["run", str(_deck(tmp_path, "static, modal, frf")), "-o", str(tmp_path / "o")])
    assert res.exit_code == 130, res.output
    page = (tmp_path / "o" / "report.html").read_text()
    assert "incomplete: 1 of 3 finished; 1 interrupted (modal); 1 not run (frf)" in page
    assert "<strong>modal</strong> interrupted: " in page and str(tmp_path / "o" / "report.html") in res.output


def test_no_report_option(tmp_path):
    res = CliRunner().invoke(main, ["run", str(_deck(tmp_path, "static")), "--no-report", "-o", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    assert (tmp_path / "o" / "static.h5").exists() and not (tmp_path / "o" / "report.html").exists()


def test_warnings_statuses_and_messages_are_collected_and_escaped(run_ok, tmp_path):
    """Deck plausibility warnings and warnings logged during the run (repeats counted, each attributed
    to the analysis running), a failure, an interruption and the analyses never started."""
    loaded = load_deck(run_ok.deck)
    loaded = dataclasses.replace(loaded, warnings=(
        DeckIssue(str(run_ok.deck), 3, 5, "bearings.0.C_Ns_m", "damping <too> high", "warning"),))
    names = ["static", "modal", "frf", "campbell"]
    with RunReport(loaded, run_info_for(loaded, "spindlesim run deck.yaml"), tmp_path, names) as report:
        for _ in range(2):
            logging.getLogger("spindlesim.runs.probe").warning("speed %s left out", "<0 rpm>")
        report.done("static", [run_ok.out / "static.h5", run_ok.out / "static_deflection.png"])
        logging.getLogger("spindlesim.runs.probe").warning("modal: one more")
        logging.getLogger("spindlesim.runs.probe").error("modal: worse")
        report.failed("modal", ValueError("K < 0 & <i>no</i>"))
        report.interrupted("frf")
    assert report._handler not in logging.getLogger("spindlesim").handlers
    logging.getLogger("spindlesim.runs.probe").warning("after the run: not collected")
    page = report.write().read_text()
    assert "incomplete: 1 of 4 finished; 1 failed (modal); 1 interrupted (frf); 1 not run (campbell)" in page
    warnings = page.split('<section id="warnings">')[1].split("</section>")[0]
    assert "damping &lt;too&gt; high" in warnings and "warning: damping" in warnings
    assert re.search(r"<td>static</td><td>spindlesim.runs.probe</td><td>speed &lt;0 rpm&gt; left out "
                     r"<span class=\"count\">\(2 times\)</span>", warnings)
    assert "<td>modal</td><td>spindlesim.runs.probe</td><td>modal: one more</td>" in warnings
    assert "<td><strong class=\"bad\">ERROR</strong> modal: worse</td>" in warnings
    assert "not collected" not in page
    assert "ValueError: K &lt; 0 &amp; &lt;i&gt;no&lt;/i&gt;" in page and "<i>no</i>" not in page
    assert "<td class=\"st bad\">interrupted</td>" in page and "<td class=\"st bad\">not run</td>" in page
    assert len(IMG.findall(page)) == 1  # the finished analysis's figure only


# ----------------------------------------------------------------------------------------------
# in a real browser

FIGURES_JS = """
return Array.from(document.images).map(img => {
  const r = img.getBoundingClientRect();
  return {complete: img.complete, width: img.naturalWidth, height: img.naturalHeight, shown_w: r.width,
          shown_h: r.height, visible: img.checkVisibility({checkOpacity: true, checkVisibilityCSS: true}),
          caption: img.parentElement.querySelector('figcaption').textContent};
});
"""
PAGE_JS = """
return {title: document.title, h1: document.querySelector('h1').textContent, scripts: document.scripts.length,
        resources: performance.getEntriesByType('resource').map(e => e.name),
        sections: document.querySelectorAll('section.analysis').length,
        deck_open: document.querySelector('#deck details').open};
"""


BROWSER, DRIVER, NO_BROWSER = find_browser()


def _pages(pdf: bytes) -> int:
    return len(re.findall(rb"/Type\s*/Page(?![s\w])", pdf))


def _keep(name: str, data: bytes, tmp_path: Path) -> None:
    folder = Path(os.environ.get("SPINDLESIM_REPORT_ARTIFACTS") or tmp_path)
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data)


@pytest.mark.slow  # about 3 s of browser start, load, screenshot and two prints
@pytest.mark.skipif(bool(NO_BROWSER), reason=NO_BROWSER)
def test_report_in_a_headless_browser(run_ok, tmp_path):
    from PIL import Image  # a dependency of matplotlib

    n_png = len(list(run_ok.out.glob("*.png")))
    broken = tmp_path / "broken.html"  # the checks below see a missing figure and a console error
    broken.write_text("<!DOCTYPE html><title>x</title><figure><img src=\"missing.png\" width=\"200\" height=\"200\">"
                      "<figcaption>Figure 1.</figcaption></figure><script>console.error('probe')</script>")
    with Browser(BROWSER, DRIVER, width=1280, height=1600) as b:
        b.open(broken)
        probe = b.console(), b.script(FIGURES_JS)
        b.open(run_ok.out / "report.html")
        console = b.console()
        figures = b.script(FIGURES_JS)
        page = b.script(PAGE_JS)
        shot = b.screenshot()
        a4, letter = b.pdf(21.0, 29.7), b.pdf(21.59, 27.94)
        console += b.console()
    assert {m["level"] for m in probe[0]} == {"SEVERE"} and len(probe[0]) == 2, probe[0]
    assert probe[1][0]["complete"] and probe[1][0]["width"] == 0  # a broken image: loaded, no pixels
    _keep("report_first_screen.png", shot, tmp_path)
    _keep("report_a4.pdf", a4, tmp_path)
    _keep("report_letter.pdf", letter, tmp_path)

    assert not [m for m in console if m["level"] in ("SEVERE", "WARNING")], console
    # every figure decoded at its own size and displayed, with its caption
    assert len(figures) == n_png
    for fig in figures:
        assert fig["complete"] and fig["width"] > 100 and fig["height"] > 100, fig
        assert fig["visible"] and fig["shown_w"] > 100 and fig["shown_h"] > 50, fig
        assert fig["caption"].startswith("Figure "), fig
    # the deck's title is text (its <script> never ran: there is no script), nothing was fetched
    assert page["h1"] == TITLE and page["title"].startswith(TITLE) and page["scripts"] == 0
    assert all(r.startswith("data:") for r in page["resources"]), page["resources"]
    assert page["sections"] == 3 and page["deck_open"] is False
    # the first screen: the whole viewport rendered, a dark title on white, the green status bar
    img = Image.open(io.BytesIO(shot)).convert("RGB")
    assert img.size[0] == 1280 and img.size[1] >= 1000
    top = img.crop((0, 0, img.size[0], 160))
    colours = top.getcolors(maxcolors=1 << 16) or []
    assert sum(n for n, c in colours if max(c) < 80) > 300, "no dark title text on the first screen"
    assert any(n > 50 and c[1] > 100 and c[0] < 60 and c[2] < 80 for n, c in colours), "no green status bar"
    white = sum(n for n, c in img.getcolors(maxcolors=1 << 20) if min(c) > 245)
    assert 0.3 < white / (img.size[0] * img.size[1]) < 0.98
    # printing: each analysis starts a page, then the deck (A4 and Letter)
    for pdf in (a4, letter):
        assert pdf.startswith(b"%PDF") and _pages(pdf) >= 1 + page["sections"] + 1
