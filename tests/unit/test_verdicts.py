"""Issue 35, item 4: a verdict at the top.  The verdicts of a run's results (API 684 margins, stability, the
thermal speed limit against the operating speed, the stable depth, a transient's steadiness) open report.html,
the banner names the ones not met, and a sweep's table carries each case's.  Issue 34, item 1: they are computed
from the results the runs hand back, never read back from the files."""

from __future__ import annotations

from pathlib import Path

import shutil

import numpy as np

from spindlesim.analysis.verdicts import BAD, OK, verdicts_of
from spindlesim.deck import parse_deck
from spindlesim.deck.describe import operating_range
from spindlesim.output.report import RunReport, render
from spindlesim.runs import perform_analysis, run_info_for
from spindlesim.runs.common import RunContext
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
    loaded = parse_deck(deck.read_text(), str(deck))
    ctx = RunContext(loaded)
    thermal = perform_analysis("thermal", ctx, out, {"plots": False})
    campbell = perform_analysis("campbell", ctx, out, {"plots": False, "speeds_rpm": np.linspace(0, 24000, 13)})
    assert thermal.analysis == "spindle_thermal" and campbell.analysis == "campbell"
    shutil.rmtree(out)  # the verdicts are the results', not the files'
    found = verdicts_of([("thermal", thermal.analysis, thermal.result), ("campbell", "campbell", campbell.result)],
                        operating_range(loaded.deck))
    limit = [v for v in found if v.topic == "Thermal speed limit"]
    assert len(limit) == 1 and limit[0].status == BAD
    assert "18,000 rpm is above it" in limit[0].text and "12,500" in limit[0].text
    assert any(v.topic == "Stability over speed" and v.status == OK for v in found)
    api = [v for v in found if v.topic == "API 684 separation margins"]
    assert len(api) == 1 and api[0].status in (OK, BAD)
    report = RunReport(loaded, run_info_for(loaded), out, ["thermal", "campbell"])
    report.done("thermal", [], thermal)
    report.done("campbell", [], campbell)
    page = render(report)
    assert page.index('id="verdicts"') < page.index('id="provenance"')
    assert "NOT MET: Thermal speed limit" in page
    assert 'href="#a0-thermal">Thermal speed limit</a>' in page


def test_a_cases_verdict_in_a_few_words():
    assert verdict_word({"verdicts": [{"topic": "Transient", "text": "NOT SETTLED: drifts", "status": "warn"}]}) \
        == "Transient: NOT SETTLED"
    assert verdict_word({"verdicts": [{"topic": "Stability over speed", "text": "stable", "status": "ok"}]}) == "ok"
    assert verdict_word({"status": "failed"}) == ""
