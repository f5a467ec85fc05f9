"""Issue 35, item 4: a verdict at the top.  The verdicts read from a run's files (API 684 margins, stability, the
thermal speed limit against the operating speed, the stable depth, a transient's steadiness) open report.html,
the banner names the ones not met, and a sweep's table carries each case's."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from spindlesim.cli import main
from spindlesim.deck import parse_deck
from spindlesim.output.report import RunReport, render
from spindlesim.output.verdicts import BAD, OK, operating_range, verdicts
from spindlesim.runs import run_info_for
from spindlesim.sweep.runner import verdict_word

ROOT = Path(__file__).parents[2]


def _hot_deck(tmp_path) -> Path:
    """The milling spindle with 30 um front preload: it runs away above 12,500-12,750 rpm, below its 18,000 rpm."""
    text = (ROOT / "decks" / "milling_spindle.yaml").read_text().replace("axial_um: 15.0", "axial_um: 30.0")
    text = text.replace("speeds_rpm: [4000, 8000, 12000, 16000, 20000, 24000]", "speeds_rpm: [12000, 16000]")
    text = text.replace("  warm_up: {steps:", "  # warm_up: {steps:")
    p = tmp_path / "hot.yaml"
    p.write_text(text)
    return p


def test_the_thermal_limit_below_the_operating_speed_is_not_met_and_opens_the_report(tmp_path):
    deck = _hot_deck(tmp_path)
    out = tmp_path / "o"
    for cmd in (["thermal"], ["campbell", "--speeds", "0:24000:13"]):
        res = CliRunner().invoke(main, [*cmd, str(deck), "-o", str(out), "-q"])
        assert res.exit_code == 0, res.output
    loaded = parse_deck(deck.read_text(), str(deck))
    paths = [out / "thermal.h5", out / "campbell.h5"]
    found = verdicts(paths, operating=operating_range(loaded.deck))
    thermal = [v for v in found if v.topic == "Thermal speed limit"]
    assert len(thermal) == 1 and thermal[0].status == BAD
    assert "18,000 rpm is above it" in thermal[0].text and "12,500" in thermal[0].text
    assert any(v.topic == "Stability over speed" and v.status == OK for v in found)
    api = [v for v in found if v.topic == "API 684 separation margins"]
    assert len(api) == 1 and api[0].status in (OK, BAD)
    report = RunReport(loaded, run_info_for(loaded), out, ["thermal", "campbell"])
    report.done("thermal", [out / "thermal.h5"])
    report.done("campbell", [out / "campbell.h5"])
    page = render(report)
    assert page.index('id="verdicts"') < page.index('id="provenance"')
    assert "NOT MET: Thermal speed limit" in page
    assert 'href="#a0-thermal">Thermal speed limit</a>' in page


def test_a_cases_verdict_in_a_few_words():
    assert verdict_word({"verdicts": [{"topic": "Transient", "text": "NOT SETTLED: drifts", "status": "warn"}]}) \
        == "Transient: NOT SETTLED"
    assert verdict_word({"verdicts": [{"topic": "Stability over speed", "text": "stable", "status": "ok"}]}) == "ok"
    assert verdict_word({"status": "failed"}) == ""
